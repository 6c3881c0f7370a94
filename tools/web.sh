#!/bin/sh
# The explorer as a web page.
#   tools/web.sh setup   adds the wasm32-unknown-unknown target and installs
#                        wasm-bindgen-cli at the version of the wasm-bindgen crate in
#                        Cargo.lock (once; about 5 minutes on 2 cores)
#   tools/web.sh build   compiles the crate for wasm32-unknown-unknown, binds it with
#                        wasm-bindgen and writes the page to target/web/
#   tools/web.sh serve   serves target/web/ on http://127.0.0.1:8000 for a person
set -eu
cd "$(dirname "$0")/.."
out=target/web
# The wasm-bindgen version the lockfile resolves, and the installed CLI's.
want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/[^0-9.]/, ""); print; exit }' Cargo.lock)
have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }') || true
case "${1:-}" in
setup)
    rustup target list --installed | grep -qx wasm32-unknown-unknown \
        || rustup target add wasm32-unknown-unknown
    # Without --locked: with it, cargo fails on a pinned dependency the registry lacks.
    [ "$have" = "$want" ] || cargo install --quiet wasm-bindgen-cli --version "$want"
    ;;
build)
    if [ "$have" != "$want" ]; then
        echo "error: wasm-bindgen-cli $want is needed (have: ${have:-none}): tools/web.sh setup" >&2
        exit 2
    fi
    # The library as a cdylib, for the web only: the native build stays an rlib.
    cargo rustc --lib --release --target wasm32-unknown-unknown --crate-type cdylib
    mkdir -p "$out"
    wasm-bindgen --target web --no-typescript --out-dir "$out" \
        "${CARGO_TARGET_DIR:-target}/wasm32-unknown-unknown/release/glyphscope.wasm"
    cp tools/web/index.html "$out/"
    echo "$out/index.html"
    ;;
serve)
    [ -f "$out/index.html" ] || { echo "error: no page yet: tools/web.sh build" >&2; exit 2; }
    command -v python3 >/dev/null || { echo "error: serving needs python3 (apt-get install python3)" >&2; exit 2; }
    echo "http://127.0.0.1:8000"
    exec python3 -m http.server 8000 --bind 127.0.0.1 --directory "$out"
    ;;
*)
    echo "usage: tools/web.sh setup | build | serve" >&2
    exit 2
    ;;
esac
