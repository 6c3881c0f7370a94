#!/usr/bin/env python3
"""The quick bench's ratios on two software GPUs, side by side, from the bench.json files
tools/software-gpus.sh writes (DIR/<adapter>-<run>/bench.json): per scene, view and
method at its default, each adapter's ratio with its span: the bench's own settled
ratio (frames interleaved with the baseline's, its 95 % interval; `*` where it did not
settle within the cap) when a run carries one, else the ratio of the medians; over
several runs, the median of the runs' ratios and the span from the lowest interval's
low to the highest's high. `differs` where the two adapters' spans do not overlap.

    python3 tools/software_gpus.py docs/bench/software-gpus > docs/bench/software-gpus/ratios.md
"""

import json
import pathlib
import statistics
import sys


def default_cases(run):
    """(scene, view, method) -> each default case of a run."""
    cases = {}
    for case in run["cases"]:
        # The baseline's cache size is its one parameter at its default.
        params = [p for p in case["params"] if p[0] != "cache_px_per_em"]
        if not params and case["frame_ms"] is not None and case["method"] != "reference":
            cases[(case["scene"], case["view"], case["method"])] = case
    return cases


def ratios(run, over):
    """(scene, view, method) -> (ratio, low, high, settled) over `over` in the same view
    of the same run: the bench's interval where it has one (`ratio_atlas`,
    `ratio_glyphon`), else the ratio of the two frames' medians."""
    cases = default_cases(run)
    out = {}
    for key, case in cases.items():
        scene, view, _ = key
        measured = case.get(f"ratio_{over}")
        if measured:
            out[key] = (measured["value"], measured["low"], measured["high"], measured["settled"])
            continue
        base = cases.get((scene, view, over))
        if base:
            value = case["frame_ms"] / base["frame_ms"]
            out[key] = (value, value, value, True)
    return out


def main(folder):
    runs = {}
    for path in sorted(pathlib.Path(folder).glob("*/bench.json")):
        adapter = path.parent.name.rsplit("-", 1)[0]
        runs.setdefault(adapter, []).append(json.loads(path.read_text()))
    if len(runs) != 2:
        sys.exit(f"{folder}: expected the runs of two adapters, found {sorted(runs)}")
    names = sorted(runs)
    # A heading, so that docs/bench.md can quote the table and tests/figures.rs check it.
    print("## The quick bench on two software GPUs\n")
    print("| scene | view | method | over | " + " | ".join(
        f"{runs[n][0]['adapter'].split(' (')[0]} ({len(runs[n])} run{'s' if len(runs[n]) > 1 else ''})" for n in names
    ) + " | |")
    print("|---|---|---|---|" + "---:|" * len(names) + "---|")
    keys = sorted({k for n in names for r in runs[n] for k in default_cases(r)})
    for scene, view, method in keys:
        for over in ("atlas", "glyphon"):
            if method == over:
                continue
            cells, spans = [], []
            for n in names:
                found = [
                    r[(scene, view, method)]
                    for r in (ratios(run, over) for run in runs[n])
                    if (scene, view, method) in r
                ]
                if not found:
                    break
                low = min(f[1] for f in found)
                high = max(f[2] for f in found)
                unsettled = "" if all(f[3] for f in found) else "*"
                spans.append((low, high))
                median = statistics.median(f[0] for f in found)
                cells.append(f"{median:.2f} ({low:.2f}–{high:.2f}){unsettled}")
            if len(cells) != len(names):
                continue
            (lo_a, hi_a), (lo_b, hi_b) = spans
            differs = "differs" if hi_a < lo_b or hi_b < lo_a else ""
            print(f"| {scene} | {view} | {method} | × {over} | " + " | ".join(cells) + f" | {differs} |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
