#!/bin/sh
# The explorer as a web page.
#   tools/web.sh setup   adds the wasm32-unknown-unknown target and installs
#                        wasm-bindgen-cli at the version of the wasm-bindgen crate in
#                        Cargo.lock (once; about 3 minutes on 2 cores)
#   tools/web.sh build   compiles the crate for wasm32-unknown-unknown, binds it with
#                        wasm-bindgen and writes the page to target/web/
#   tools/web.sh serve   serves target/web/ on http://127.0.0.1:8000 for a person
set -eu
cd "$(dirname "$0")/.."
out=target/web
# Where `cargo install` puts wasm-bindgen, whether or not the shell's PATH has it yet.
PATH="${CARGO_HOME:-$HOME/.cargo}/bin:$PATH"
# The wasm-bindgen version the lockfile resolves, and the installed CLI's.
want=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/[^0-9.]/, ""); print; exit }' Cargo.lock)
have=$(wasm-bindgen --version 2>/dev/null | awk '{ print $2 }') || true
say() { echo "web.sh: $*"; }
fail() { echo "web.sh: error: $*" >&2; exit 2; }
case "${1:-}" in
setup)
    if [ -d "$(rustc --print sysroot)/lib/rustlib/wasm32-unknown-unknown" ]; then
        say "wasm32: the wasm32-unknown-unknown target is installed"
    else
        command -v rustup >/dev/null \
            || fail "no wasm32-unknown-unknown target and no rustup to add it: install Rust through https://rustup.rs"
        say "wasm32: adding the wasm32-unknown-unknown target, which the page compiles to"
        why=$(rustup target add wasm32-unknown-unknown 2>&1 >/dev/null) \
            || fail "rustup target add wasm32-unknown-unknown failed: $(echo "$why" | tail -n 1)"
    fi
    if [ "$have" = "$want" ]; then
        say "wasm-bindgen: wasm-bindgen-cli $want is installed"
    else
        say "wasm-bindgen: building wasm-bindgen-cli $want, Cargo.lock's version (have: ${have:-none}; about 3 minutes on 2 cores)"
        # Without --locked: with it, cargo fails on a pinned dependency the registry lacks.
        # The page needs the one binary, and it downloads nothing: no TLS stack (the test
        # runner's, for fetching browser drivers), 9% less to build.
        log=$(mktemp)
        cargo install --quiet wasm-bindgen-cli --version "$want" --bin wasm-bindgen \
            --no-default-features >"$log" 2>&1 \
            || fail "cargo could not build wasm-bindgen-cli (no network?), see $log: cargo install wasm-bindgen-cli --version $want"
    fi
    ;;
build)
    if [ "$have" != "$want" ]; then
        fail "wasm-bindgen-cli $want is needed (have: ${have:-none}): tools/web.sh setup"
    fi
    # The library as a cdylib, for the web only: the native build stays an rlib.
    cargo rustc -p glyphscope --lib --release --target wasm32-unknown-unknown --crate-type cdylib
    mkdir -p "$out"
    wasm-bindgen --target web --no-typescript --out-dir "$out" \
        "${CARGO_TARGET_DIR:-target}/wasm32-unknown-unknown/release/glyphscope.wasm"
    cp tools/web/index.html "$out/"
    echo "$out/index.html"
    ;;
serve)
    [ -f "$out/index.html" ] || fail "no page yet: tools/web.sh build"
    command -v python3 >/dev/null || fail "serving needs python3 (apt-get install python3)"
    echo "http://127.0.0.1:8000"
    exec python3 -m http.server 8000 --bind 127.0.0.1 --directory "$out"
    ;;
*)
    echo "usage: tools/web.sh setup | build | serve" >&2
    exit 2
    ;;
esac
