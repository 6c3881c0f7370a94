#!/bin/sh
# What joining overlapping instances costs (docs/methods/winding.md, "Glyphs whose ink
# overlaps"): each scene drawn by a method at between=union and between=add, three runs
# each, the statistics averaged (prepare and GPU time) or as measured (the rest).
#   tools/between-cost.sh [METHOD] [GLYPHSCOPE]
# METHOD: winding (default) or sdf-cells; GLYPHSCOPE: the binary (target/release/glyphscope).
set -eu
method=${1:-winding}
bin=${2:-target/release/glyphscope}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
echo "| case | between | groups (instances, distinct) | max | edge MAE /255 | prepare ms | GPU bytes | curves per pixel, mean (max) | GPU ms |"
echo "|---|---|---|---|---|---|---|---|---|"
for case in page bengali arabic; do
    for between in add union; do
        for run in 1 2 3; do
            "$bin" render --case "$case" --method "$method" --param "between=$between" \
                --out "$dir/c.png" --error-image "$dir/e.png" --stats "$dir/s$run.json" >/dev/null
        done
        python3 - "$case" "$between" "$dir"/s1.json "$dir"/s2.json "$dir"/s3.json <<'PY'
import json, sys
case, between, *paths = sys.argv[1:]
runs = [json.load(open(p)) for p in paths]
d, e, j = runs[0], runs[0]["error"], runs[0]["ink_overlaps"]
mean = lambda key: sum(r[key] for r in runs) / len(runs)
c = d["curves_per_pixel"]
print(f"| `{case}` | {between} | {j['groups']} ({j['instances']}, {j['distinct']}) | "
      f"{e['max']:.4f} | {e['edge']['mae_255']:.3f} | {mean('cpu_prepare_ms'):.1f} | "
      f"{d['gpu_bytes']} | {c['mean']:.2f} ({c['max']}) | {mean('gpu_ms'):.2f} |")
PY
    done
done
