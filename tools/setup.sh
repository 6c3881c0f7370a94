#!/bin/sh
# The first half of README's test command, `tools/setup.sh && cargo test --release`: sets
# up what a fresh Debian machine lacks for the tests, one line per step, each step
# skipped when what it gives is already there.
#
#   vulkan        a Vulkan driver for the GPU tests: the loader and lavapipe, Mesa's
#                 software Vulkan (apt: libvulkan1 mesa-vulkan-drivers), where none exists
#   chromium      headless Chromium and chromedriver for the web page's test, tests/web.rs
#                 (apt: chromium chromium-driver)
#   linker        a C toolchain for cargo to link with (apt: gcc libc6-dev), where missing
#   wasm32        the wasm32-unknown-unknown target (rustup)        } tools/web.sh setup
#   wasm-bindgen  wasm-bindgen-cli at Cargo.lock's version (cargo)  }
#   crates        every crate Cargo.lock names for this machine and the page (cargo fetch)
#
# The apt packages need root: as another user the script uses sudo and says so. Where
# neither works, or the network does not answer, it prints one line naming what is
# missing and the command that installs it, and exits 2 before building: the tests never
# pass by skipping what they could not set up.
set -eu
cd "$(dirname "$0")/.."

say() { echo "setup.sh: $*"; }
fail() { echo "setup.sh: error: $*" >&2; exit 2; }

command -v cargo >/dev/null || fail "no cargo on the PATH: install Rust (https://rustup.rs)"

# What apt has to install, and why.
packages=""
# A driver is a manifest in one of the loader's folders (a glob that matches nothing stays
# as written, and -e rejects it).
vulkan_driver() {
    for manifest in /usr/share/vulkan/icd.d/*.json /etc/vulkan/icd.d/*.json; do
        [ -e "$manifest" ] && return 0
    done
    return 1
}
# ldconfig lives in /usr/sbin, which a user's PATH leaves out.
if vulkan_driver && PATH="$PATH:/usr/sbin:/sbin" ldconfig -p 2>/dev/null \
    | grep -q 'libvulkan\.so\.1 '; then
    say "vulkan: a driver is installed"
else
    say "vulkan: no Vulkan driver: lavapipe, Mesa's software Vulkan, will render the GPU tests"
    packages="$packages libvulkan1 mesa-vulkan-drivers"
fi
if command -v chromium >/dev/null && command -v chromedriver >/dev/null; then
    say "chromium: chromium and chromedriver are installed"
else
    say "chromium: the web page's test drives headless Chromium through chromedriver"
    packages="$packages chromium chromium-driver"
fi
# cc finds the C library's start files only where its development package is installed.
if command -v cc >/dev/null && [ -e "$(cc -print-file-name=Scrt1.o)" ]; then
    say "linker: cc and the C library's files are installed"
else
    say "linker: cargo links through cc, with the C library's start files"
    packages="$packages gcc libc6-dev"
fi

if [ -n "$packages" ]; then
    install="apt-get install$packages"
    command -v apt-get >/dev/null || fail "no apt-get: install$packages with this system's package manager"
    if [ "$(id -u)" = 0 ]; then
        sudo=""
    elif command -v sudo >/dev/null && sudo -n true 2>/dev/null; then
        sudo="sudo"
        say "apt: not root: installing through sudo"
    elif command -v sudo >/dev/null && [ -t 0 ] \
        && say "apt: not root: installing through sudo, which asks for your password" \
        && sudo -v; then
        sudo="sudo"
    else
        fail "installing$packages needs root, and this user has no sudo rights: as root, $install"
    fi
    log=$(mktemp)
    say "apt: installing$packages (its output: $log)"
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get update -q >"$log" 2>&1 \
        || fail "apt-get update failed (no network?), see $log: $install"
    # shellcheck disable=SC2086 # one word per package
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends \
        $packages >>"$log" 2>&1 \
        || fail "apt-get install failed (no network?), see $log: $install"
fi

# The web page's tools live beside its build: one place says how they are installed.
sh tools/web.sh setup

# Every crate the build and the page's build need, fetched now, so that no network stops
# the build halfway with cargo's many lines.
host=$(rustc -vV | sed -n 's/^host: //p')
log=$(mktemp)
say "crates: fetching what Cargo.lock names for $host and the page's wasm32 (its output: $log)"
cargo fetch --target "$host" --target wasm32-unknown-unknown >"$log" 2>&1 \
    || fail "cargo fetch failed (no network?), see $log: cargo fetch"
