#!/usr/bin/env bash
# The quick bench on two software GPUs, lavapipe (Mesa's llvmpipe) and SwiftShader
# (Chromium's Vulkan driver, which Debian's chromium package installs), RUNS times each
# (default 1: each ratio is settled within its run and carries its interval), taking
# turns, then the table of their ratios side by side that docs/bench.md quotes. A ratio
# that moves between the two by more than its intervals belongs to an implementation,
# not to the method. SETTLE_CAP (default 10 s) bounds each case's sampling.
#   tools/software-gpus.sh [RUNS]
set -euo pipefail
runs=${1:-1}
cap=${SETTLE_CAP:-10}
out=docs/bench/software-gpus
cargo build --release
bin=target/release/glyphscope
rm -rf "$out"
for k in $(seq 1 "$runs"); do
    for adapter in llvmpipe swiftshader; do
        echo "run $k of $runs on $adapter" >&2
        "$bin" bench --quick --settle-cap "$cap" --scenes page,tiny,rotated --adapter "$adapter" \
            --methods winding,sdf-cells,xor-stencil,tessellation,atlas,glyphon \
            --out "$out/$adapter-$k" >/dev/null
        # The tables and the JSON are what the comparison reads; the plots are the
        # bench's usual ones, kept out of the repository.
        rm -f "$out/$adapter-$k"/*.svg
    done
done
python3 tools/software_gpus.py "$out" >"$out/ratios.md"
echo "$out/ratios.md"
