#!/usr/bin/env bash
# The workspace's crates: for each, the unique crates `cargo tree -e normal` lists (the
# crate itself included) and its lines of Rust; glyphon's tree in the same lockfile
# beside them, the library people compare the text crate with. docs/architecture.md's
# figures come from here.
#   tools/crates.sh
set -euo pipefail
cd "$(dirname "$0")/.."
unique() {
    cargo tree --offline -e normal --prefix none -p "$@" 2>/dev/null |
        sed 's/ (\*)//; s/ (proc-macro)//' | sort -u | wc -l
}
lines() {
    find "$1" -name '*.rs' -not -path '*/target/*' -print0 | xargs -0 cat | wc -l
}
echo "| crate | unique crates in its tree | lines of Rust |"
echo "|---|---:|---:|"
for crate in core gpu text; do
    echo "| glyphscope-$crate | $(unique "glyphscope-$crate") | $(lines "crates/$crate/src") |"
done
echo "| glyphscope (default: explorer and every peer) | $(unique glyphscope) | $(lines src) |"
echo "| glyphscope, explorer without peers (\`--no-default-features --features app\`) | $(unique glyphscope --no-default-features --features app) | |"
echo "| glyphscope, command line without peers (\`--no-default-features\`) | $(unique glyphscope --no-default-features) | |"
echo "| glyphon (peer, for comparison) | $(unique glyphon) | — |"
