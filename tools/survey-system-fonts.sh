#!/bin/sh
# The survey of fonts no developer of glyphscope chose (docs/survey.md, "Fonts nobody
# here chose"): six fonts from Debian's packages (fonts-dejavu-core and -extra,
# fonts-noto-mono, fonts-urw-base35) — a serif and a math font of DejaVu's (TrueType
# quadratics), Noto Sans Mono, and three of URW's base 35 (CFF cubics: a serif, a
# geometric sans and a script) — at 12, 24 and 48 px/em,
# still and turned, through the three methods the project was built around at their
# defaults. It exits 1 where a claim breaks, as `survey` does.
#
#   tools/survey-system-fonts.sh OUT        # writes OUT/survey.md and the rest
#   METHODS=sdf-cells,winding tools/survey-system-fonts.sh OUT
set -eu
out="${1:?usage: tools/survey-system-fonts.sh OUT}"
# OUT as the caller meant it, before the script moves to the repository.
mkdir -p "$out"
out="$(cd "$out" && pwd)"
cd "$(dirname "$0")/.."
methods="${METHODS:-sdf-cells,tessellation,xor-stencil}"
fonts="$(mktemp -d)"
trap 'rm -rf "$fonts"' EXIT
for f in \
    /usr/share/fonts/truetype/dejavu/DejaVuSerif.ttf \
    /usr/share/fonts/truetype/dejavu/DejaVuMathTeXGyre.ttf \
    /usr/share/fonts/truetype/noto/NotoSansMono-Regular.ttf \
    /usr/share/fonts/opentype/urw-base35/C059-Roman.otf \
    /usr/share/fonts/opentype/urw-base35/URWGothic-Book.otf \
    /usr/share/fonts/opentype/urw-base35/Z003-MediumItalic.otf; do
    if [ ! -f "$f" ]; then
        echo "error: $f is not installed (apt install fonts-dejavu-core fonts-dejavu-extra fonts-noto-mono fonts-urw-base35)" >&2
        exit 2
    fi
    ln -s "$f" "$fonts/"
done
cargo run --release --quiet -- survey --fonts "$fonts" --sizes 12,24,48 --methods "$methods" --out "$out"
