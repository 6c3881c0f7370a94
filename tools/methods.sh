# shellcheck shell=bash
# Sourced by the tools that run every method: the registry's method names, one a line,
# as a glyphscope binary's `render --help` lists them (so no script keeps a stale list).
#   glyphscope_methods BIN
glyphscope_methods() {
    "$1" render --help | sed -n 's/.*The method that draws it: //p' | tr ';' '\n' \
        | sed -n 's/^ *\([a-z-]*\):.*/\1/p'
}
