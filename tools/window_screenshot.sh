#!/bin/sh
# The explorer's real window under Xvfb (software X server) on whatever Vulkan driver is
# present (lavapipe on a machine without a GPU), photographed after it has settled:
#
#     tools/window_screenshot.sh [OUT.png] [SECONDS]
#
# Needs Xvfb, xwd and ImageMagick (apt-get install xvfb x11-apps imagemagick). Settings are
# kept in a throwaway home so the picture shows the defaults, not the last session.
set -eu
out=${1:-screenshots/window-side-by-side.png}
wait_s=${2:-40}
display=:97
home=$(mktemp -d)
cargo build --release --quiet
Xvfb $display -screen 0 1280x860x24 >/dev/null 2>&1 &
xvfb=$!
trap 'kill $app $xvfb 2>/dev/null; rm -rf "$home"' EXIT
sleep 2
DISPLAY=$display HOME=$home XDG_DATA_HOME=$home XDG_CONFIG_HOME=$home \
    XDG_RUNTIME_DIR=$home WINIT_UNIX_BACKEND=x11 target/release/glyphscope &
app=$!
sleep "$wait_s"
DISPLAY=$display xwd -root -silent | convert xwd:- "$out"
echo "wrote $out"
