#!/bin/sh
# docs/library.md's table of a UI's labels: examples/ui_labels.rs run once per renderer
# and label count, each in a process of its own (so that each one's resident memory is
# its own), on the machine's default adapter (lavapipe here), then tabulated.
#
#   tools/ui-labels.sh                     # 10 30 100 200 500 2000 labels, 30 frames
#   LABELS="500 2000" FRAMES=60 tools/ui-labels.sh
#   UI_LABELS=/path/to/ui_labels tools/ui-labels.sh   # another build of the example
#
# A renderer that fails on a count prints its error in the row instead of figures.
set -eu
cd "$(dirname "$0")/.."
labels="${LABELS:-10 30 100 200 500 2000}"
frames="${FRAMES:-30}"
binary="${UI_LABELS:-}"
if [ -z "$binary" ]; then
    cargo build --release --quiet --example ui_labels
    binary=target/release/examples/ui_labels
fi
field() { sed -n "s/.*\"$1\": \([^,}]*\).*/\1/p" | tr -d '"'; }
echo "| labels | library still ms | library moving ms | glyphon still ms | glyphon moving ms | still ÷ glyphon | moving ÷ glyphon | library memory growth MB (held) | glyphon memory growth MB |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for n in $labels; do
    lib=$("$binary" --renderer library --labels "$n" --frames "$frames" 2>&1 | grep '^{' || true)
    gly=$("$binary" --renderer glyphon --labels "$n" --frames "$frames" 2>&1 | grep '^{' || true)
    if [ -z "$lib" ]; then
        error=$("$binary" --renderer library --labels "$n" --frames 1 2>&1 | grep -v XDG | tail -1 | cut -c1-120)
        echo "| $n | error: $error | | $(echo "$gly" | field still_ms) | $(echo "$gly" | field moving_ms) | | | | $(echo "$gly" | field resident_growth_mb) |"
        continue
    fi
    ls=$(echo "$lib" | field still_ms); lm=$(echo "$lib" | field moving_ms)
    gs=$(echo "$gly" | field still_ms); gm=$(echo "$gly" | field moving_ms)
    rs=$(echo "$ls $gs" | awk '{printf "%.2f", $1 / $2}')
    rm=$(echo "$lm $gm" | awk '{printf "%.2f", $1 / $2}')
    echo "| $n | $ls | $lm | $gs | $gm | $rs | $rm | $(echo "$lib" | field resident_growth_mb) ($(echo "$lib" | field held_mb)) | $(echo "$gly" | field resident_growth_mb) |"
done
echo
echo "Adapter: $(echo "$lib" | sed -n 's/.*"adapter": "\([^"]*\)".*/\1/p'). \`tools/ui-labels.sh\` (LABELS=\"$labels\" FRAMES=$frames), median wall ms per frame: prepare + render + submit + wait, 1920×1080 Rgba8UnormSrgb."
