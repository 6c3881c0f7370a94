#!/usr/bin/env bash
# Renders every method of a glyphscope binary on a set of small shipped scenes, each
# overlay included, into a folder: PNGs, error images and statistics without timings.
# Two builds' folders compared with `diff -r` show whether a change moved any pixel or
# figure (the check behind "behaviour unchanged" refactors).
#   tools/render_snapshot.sh target/release/glyphscope DIR
# Needs jq (apt install jq), to drop the timings from the statistics.
set -euo pipefail
# shellcheck source=tools/methods.sh
. "$(dirname "$0")/methods.sh"
bin=$1
out=$2
mkdir -p "$out"
methods=$(glyphscope_methods "$bin" || true)
[ -n "$methods" ] || methods="reference bounds winding sdf-cells xor-stencil tessellation atlas"
scenes=(
    "hamburg|--text Hamburgefonstiv --size 16"
    "small|--text Hamburgefonstiv --size 7"
    "rotated|--text Rotated --size 40 --matrix 0.866,-0.5,0.5,0.866 --tilt 30"
    "latin|--font fonts/lmroman10-regular.otf --text Quixotic --size 24"
    "inter|--font fonts/Inter-roman.var.ttf --variation wght=900 --text Overlap --size 32"
    "bengali|--font fonts/Lohit-Bengali.ttf --text ক্ষ্ম --size 40"
    "edge|--text O --size 20000 --width 128 --height 128 --origin=-1500,9000"
)
for method in $methods; do
    overlays=$("$bin" render --text x --size 8 --method "$method" --param overlay=zz \
        --out /dev/null 2>&1 | sed -n 's/.*overlay must be none\(, \| or \)//p' \
        | sed 's/ or / /; s/,//g' || true)
    for scene in "${scenes[@]}"; do
        name=${scene%%|*}
        read -r -a args <<<"${scene#*|}"
        base="$out/$method-$name"
        # A peer refuses a view its API cannot draw (exit 2, one line): the line is the
        # snapshot.
        if ! "$bin" render "${args[@]}" --method "$method" --out "$base.png" \
            --stats "$base.json" --error-image "$base-error.png" 2>"$base.refused"; then
            continue
        fi
        rm "$base.refused"
        # Timings, how they were sampled and the adapter vary from run to run;
        # everything else must not.
        jq 'walk(if type == "object" then with_entries(select(.key
            | test("_ms|^adapter$|^gpu_clock$|^frames_per_submission$|^warmup_frames$") | not))
            else . end)' \
            "$base.json" >"$base.stats"
        rm "$base.json"
        for overlay in $overlays; do
            "$bin" render "${args[@]}" --method "$method" --param "overlay=$overlay" \
                --out "$base-$overlay.png"
        done
    done
done
