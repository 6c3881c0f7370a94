#!/usr/bin/env python3
"""The quick bench's ratios on two software GPUs, side by side, from the bench.json files
tools/software-gpus.sh writes (DIR/<adapter>-<run>/bench.json): per scene, view and
method at its default, the median ratio over the runs of each adapter with its spread
(fastest–slowest run), and `differs` where the two adapters' spreads do not overlap.

    python3 tools/software_gpus.py docs/bench/software-gpus > docs/bench/software-gpus/ratios.md
"""

import json
import pathlib
import statistics
import sys


def default_frames(run):
    """(scene, view, method) -> GPU + CPU ms per frame of each default case of a run."""
    times = {}
    for case in run["cases"]:
        # The baseline's cache size is its one parameter at its default.
        params = [p for p in case["params"] if p[0] != "cache_px_per_em"]
        if not params and case["frame_ms"] is not None and case["method"] != "reference":
            times[(case["scene"], case["view"], case["method"])] = case["frame_ms"]
    return times


def ratios(run, over):
    """(scene, view, method) -> time over `over`'s in the same view of the same run."""
    times = default_frames(run)
    out = {}
    for (scene, view, method), ms in times.items():
        base = times.get((scene, view, over))
        if base:
            out[(scene, view, method)] = ms / base
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
        f"{runs[n][0]['adapter'].split(' (')[0]} ({len(runs[n])} runs)" for n in names
    ) + " | |")
    print("|---|---|---|---|" + "---:|" * len(names) + "---|")
    keys = sorted({k for n in names for r in runs[n] for k in default_frames(r)})
    for scene, view, method in keys:
        for over in ("atlas", "glyphon"):
            if method == over:
                continue
            cells, spans = [], []
            for n in names:
                values = [
                    r[(scene, view, method)]
                    for r in (ratios(run, over) for run in runs[n])
                    if (scene, view, method) in r
                ]
                if not values:
                    break
                spans.append((min(values), max(values)))
                cells.append(
                    f"{statistics.median(values):.2f} ({min(values):.2f}–{max(values):.2f})"
                )
            if len(cells) != len(names):
                continue
            (lo_a, hi_a), (lo_b, hi_b) = spans
            differs = "differs" if hi_a < lo_b or hi_b < lo_a else ""
            print(f"| {scene} | {view} | {method} | × {over} | " + " | ".join(cells) + f" | {differs} |")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    main(sys.argv[1])
