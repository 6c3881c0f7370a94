#!/bin/sh
# What drawing a quad per word costs against a quad per glyph (docs/methods/winding.md,
# "A quad per word"): `winding` at quads=glyph and quads=word, and glyphon, on the page
# and `tiny`, ROUNDS renders each (default 5) taking turns, so that the machine's drift
# falls on all three alike, on lavapipe (the adapter `llvmpipe`) and on SwiftShader
# (where installed). GPU ms:
# the median of the renders' `gpu_ms` (fastest–slowest in brackets); × glyphon: the
# median of each round's ratio to glyphon's render in the same round (least–most); the
# rest as measured.
#   tools/quads-cost.sh [GLYPHSCOPE]
# GLYPHSCOPE: the binary (default target/release/glyphscope).
set -eu
bin=${1:-target/release/glyphscope}
rounds=${ROUNDS:-5}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
echo "| device | case | drawn | GPU ms | × glyphon | curves per pixel, mean (max) | GPU bytes | prepare ms | max | edge MAE /255 |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for adapter in llvmpipe swiftshader; do
    if ! "$bin" render --case tiny --method winding --adapter "$adapter" --out "$dir/c.png" >/dev/null 2>&1; then
        echo "| $adapter | — | — | not found | | | | | | |"
        continue
    fi
    for scene in tiny page; do
        round=1
        while [ "$round" -le "$rounds" ]; do
            # Each round starts with the next of the three, so that none always runs first.
            case $((round % 3)) in
                0) order="glyph word glyphon" ;;
                1) order="word glyphon glyph" ;;
                *) order="glyphon glyph word" ;;
            esac
            for drawn in $order; do
                if [ "$drawn" = glyphon ]; then set -- --method glyphon; else set -- --method winding --param "quads=$drawn"; fi
                "$bin" render --case "$scene" "$@" --adapter "$adapter" --out "$dir/c.png" \
                    --stats "$dir/$drawn-$round.json" >/dev/null
            done
            round=$((round + 1))
        done
        python3 - "$adapter" "$scene" "$dir" "$rounds" <<'PY'
import json, statistics, sys
adapter, case, folder, rounds = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4])
load = lambda drawn: [json.load(open(f"{folder}/{drawn}-{r}.json")) for r in range(1, rounds + 1)]
glyphon = [r["gpu_ms"] for r in load("glyphon")]
for drawn in ["glyph", "word"]:
    runs = load(drawn)
    ms = [r["gpu_ms"] for r in runs]
    ratios = [m / g for m, g in zip(ms, glyphon)]
    d, c = runs[0], runs[0]["curves_per_pixel"]
    prepare = statistics.median(r["cpu_prepare_ms"] for r in runs)
    print(f"| {adapter} | `{case}` | quads={drawn} | {statistics.median(ms):.2f} ({min(ms):.2f}–{max(ms):.2f}) | "
          f"{statistics.median(ratios):.2f} ({min(ratios):.2f}–{max(ratios):.2f}) | "
          f"{c['mean']:.2f} ({c['max']}) | {d['gpu_bytes']} | {prepare:.0f} | "
          f"{d['error']['max']:.4f} | {d['error']['edge']['mae_255']:.3f} |")
print(f"| {adapter} | `{case}` | glyphon | {statistics.median(glyphon):.2f} ({min(glyphon):.2f}–{max(glyphon):.2f}) | 1 | | | | | |")
PY
    done
done
