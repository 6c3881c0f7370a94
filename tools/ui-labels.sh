#!/bin/sh
# docs/library.md's table of a UI's labels: examples/ui_labels.rs run per renderer and
# label count, each in a process of its own (so that each one's resident memory is its
# own), on the machine's default adapter (lavapipe here), then tabulated. The two
# renderers alternate for ROUNDS rounds: a shared machine's speed drifts by a tenth or
# more over seconds, and a ratio taken within each round (the library's median frame
# over glyphon's in the same round) does not carry that drift; the table gives each
# figure's median over the rounds and each ratio's median with its range.
#
#   tools/ui-labels.sh                     # 10 30 100 200 500 2000 labels, 100 frames, 3 rounds
#   LABELS="500 2000" FRAMES=60 ROUNDS=5 tools/ui-labels.sh
#   UI_LABELS=/path/to/ui_labels tools/ui-labels.sh   # another build of the example
#
# Beside wall time, each renderer's CPU time per moving frame (the whole process, every
# thread: on a software GPU the GPU's work too), which other processes move less.
#
# A renderer that fails on a count prints its error in the row instead of figures.
set -eu
cd "$(dirname "$0")/.."
labels="${LABELS:-10 30 100 200 500 2000}"
frames="${FRAMES:-100}"
rounds="${ROUNDS:-3}"
binary="${UI_LABELS:-}"
if [ -z "$binary" ]; then
    cargo build --release --quiet --example ui_labels
    binary=target/release/examples/ui_labels
fi
field() { sed -n "s/.*\"$1\": \([^,}]*\).*/\1/p" | tr -d '"'; }
# The median of the numbers on standard input, one a line.
median() { sort -g | awk '{v[NR] = $1} END {if (NR % 2) print v[(NR + 1) / 2]; else printf "%.2f\n", (v[NR / 2] + v[NR / 2 + 1]) / 2}'; }
# "median (least–most)" of the numbers on standard input.
spread() { sort -g | awk '{v[NR] = $1} END {if (NR == 0) {printf "n/a"; exit} m = (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2; printf "%.2f (%.2f–%.2f)", m, v[1], v[NR]}'; }
echo "| labels | library still ms | library moving ms | glyphon still ms | glyphon moving ms | still ÷ glyphon | moving ÷ glyphon | moving CPU ms, library / glyphon | moving CPU ÷ glyphon | library memory growth MB (held) | glyphon memory growth MB |"
echo "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
last=""
runs=$(mktemp)
trap 'rm -f "$runs"' EXIT
for n in $labels; do
    : >"$runs"
    failed=""
    r=0
    while [ "$r" -lt "$rounds" ]; do
        r=$((r + 1))
        lib=$("$binary" --renderer library --labels "$n" --frames "$frames" 2>&1 | grep '^{' || true)
        gly=$("$binary" --renderer glyphon --labels "$n" --frames "$frames" 2>&1 | grep '^{' || true)
        if [ -z "$lib" ]; then
            failed=$("$binary" --renderer library --labels "$n" --frames 1 2>&1 | grep -v XDG | tail -1 | cut -c1-120)
            failed="${failed:-the library gave no figures}"
            break
        fi
        # A ratio needs both sides: a glyphon that fails gives its error, not a division.
        if [ -z "$gly" ]; then
            failed="glyphon: $("$binary" --renderer glyphon --labels "$n" --frames 1 2>&1 | grep -v XDG | tail -1 | cut -c1-120)"
            break
        fi
        echo "$(echo "$lib" | field still_ms) $(echo "$lib" | field moving_ms) $(echo "$gly" | field still_ms) $(echo "$gly" | field moving_ms) $(echo "$lib" | field resident_growth_mb) $(echo "$lib" | field held_mb) $(echo "$gly" | field resident_growth_mb) $(echo "$lib" | field moving_cpu_ms) $(echo "$gly" | field moving_cpu_ms)" >>"$runs"
        last="$lib"
    done
    if [ -n "$failed" ]; then
        echo "| $n | error: $failed | | $(echo "$gly" | field still_ms) | $(echo "$gly" | field moving_ms) | | | | | | $(echo "$gly" | field resident_growth_mb) |"
        continue
    fi
    col() { awk -v c="$1" '{print $c}' "$runs" | median; }
    still_ratio=$(awk '{printf "%.4f\n", $1 / $3}' "$runs" | spread)
    moving_ratio=$(awk '{printf "%.4f\n", $2 / $4}' "$runs" | spread)
    # Where the CPU time is unknown (not Linux: "null"), no ratio rather than a division by 0.
    cpu_ratio=$(awk '($9 + 0) > 0 {printf "%.4f\n", $8 / $9}' "$runs" | spread)
    echo "| $n | $(col 1) | $(col 2) | $(col 3) | $(col 4) | $still_ratio | $moving_ratio | $(col 8) / $(col 9) | $cpu_ratio | $(col 5) ($(col 6)) | $(col 7) |"
done
echo
echo "Adapter: $(echo "$last" | sed -n 's/.*"adapter": "\([^"]*\)".*/\1/p'). \`tools/ui-labels.sh\` (LABELS=\"$labels\" FRAMES=$frames ROUNDS=$rounds), median wall ms per frame over each run's frames (prepare + render + submit + wait, 1920×1080 Rgba8UnormSrgb), then the median over the rounds; ratios within each round, their median (least–most). *Moving CPU*: the CPU time the whole process spent per moving frame, every thread (on a software GPU, the GPU's work too; a figure other processes move less than wall time)."
