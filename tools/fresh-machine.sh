#!/bin/sh
# README's set-up, checked on a fresh machine: a minimal Debian 12 (debootstrap
# --variant=minbase) in a chroot under DIR, with this repository's HEAD cloned into it.
#
#   tools/fresh-machine.sh test [DIR]     rustup's minimal Rust 1.95 and nothing else (no
#                                         apt packages, no crate cache, no wasm-bindgen);
#                                         runs README's test command as root; its time
#   tools/fresh-machine.sh nonroot [DIR]  the same machine, the test command as a user
#                                         without sudo, then with sudo but no rights:
#                                         each must stop with one line and exit 2
#   tools/fresh-machine.sh window [DIR]   this working tree's explorer (target/release/
#                                         glyphscope, built here) with none of the
#                                         window's libraries (one line, exit 2), then with
#                                         README's X11 list and lavapipe: a screenshot
#                                         after 30 s, DIR/window.png
#
# Needs root, debootstrap and a network; `window` needs Xvfb, xwd and ImageMagick (apt-get
# install debootstrap xvfb x11-apps imagemagick). The host's extra CA certificates go into
# the chroot, for networks behind a proxy of their own.
set -eu
mode=${1:-}
root=${2:-/tmp/glyphscope-fresh}
repo=$(cd "$(dirname "$0")/.." && pwd)
case "$mode" in test | nonroot | window) ;; *)
    echo "usage: tools/fresh-machine.sh test|nonroot|window [DIR]" >&2
    exit 2
    ;;
esac
[ "$(id -u)" = 0 ] || { echo "error: a chroot needs root" >&2; exit 2; }
command -v debootstrap >/dev/null || { echo "error: apt-get install debootstrap" >&2; exit 2; }

in_root() { chroot "$root" env -i HOME=/root TERM=dumb \
    PATH=/root/.cargo/bin:/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin "$@"; }
unmount() {
    for m in tmp/.X11-unix dev sys proc; do umount -R "$root/$m" 2>/dev/null || true; done
}
trap unmount EXIT
trap 'exit 130' INT TERM HUP

echo "fresh-machine: Debian 12 minbase in $root"
# Only a folder this script made is removed, and only with nothing mounted in it.
marker="$root/.glyphscope-fresh-machine"
if [ -e "$root" ]; then
    [ -e "$marker" ] || { echo "error: $root exists and is not a chroot of this script's" >&2; exit 2; }
    unmount
    if grep -q " $root/" /proc/mounts; then
        echo "error: something is still mounted under $root" >&2
        exit 2
    fi
    rm -rf --one-file-system "$root"
fi
mkdir -p "$root"
touch "$marker"
debootstrap --variant=minbase bookworm "$root" http://deb.debian.org/debian >"$root-debootstrap.log" 2>&1
# What a Debian 12 installation has and debootstrap leaves out: the updates and security
# suites, and localhost (chromedriver reaches Chromium's DevTools by that name).
rm -f "$root/etc/apt/sources.list"
cat >"$root/etc/apt/sources.list.d/debian.sources" <<SOURCES
Types: deb
URIs: http://deb.debian.org/debian
Suites: bookworm bookworm-updates
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg

Types: deb
URIs: http://deb.debian.org/debian-security
Suites: bookworm-security
Components: main
Signed-By: /usr/share/keyrings/debian-archive-keyring.gpg
SOURCES
printf '127.0.0.1\tlocalhost\n::1\tlocalhost ip6-localhost ip6-loopback\n' >"$root/etc/hosts"
cp /etc/resolv.conf "$root/etc/"
mkdir -p "$root/usr/local/share/ca-certificates"
cp /usr/local/share/ca-certificates/*.crt "$root/usr/local/share/ca-certificates/" 2>/dev/null || true
mount -t proc proc "$root/proc"
# Slaves: unmounting them later must not reach the host's own /dev/pts or /dev/shm.
mount --rbind /sys "$root/sys"
mount --make-rslave "$root/sys"
mount --rbind /dev "$root/dev"
mount --make-rslave "$root/dev"
in_root sh -c 'apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq \
    --no-install-recommends ca-certificates curl git >/dev/null 2>&1 && update-ca-certificates >/dev/null'

if [ "$mode" = window ]; then
    app="$repo/target/release/glyphscope"
    [ -x "$app" ] || { echo "error: no $app: cargo build --release" >&2; exit 2; }
    cp "$app" "$root/usr/local/bin/"
    mkdir -p "$root/tmp/.X11-unix"
    mount --bind /tmp/.X11-unix "$root/tmp/.X11-unix"
    Xvfb :96 -screen 0 1280x860x24 >/dev/null 2>&1 &
    xvfb=$!
    trap 'kill $xvfb 2>/dev/null || true; unmount' EXIT
    sleep 2
    explorer() { in_root env DISPLAY=:96 XDG_RUNTIME_DIR=/tmp timeout "$1" glyphscope; }
    echo "fresh-machine: the explorer with none of its libraries:"
    code=0; explorer 30 || code=$?
    echo "fresh-machine: exit $code"
    [ "$code" = 2 ] || { echo "fresh-machine: FAILED: exit 2 expected" >&2; exit 1; }
    echo "fresh-machine: with README's X11 libraries and lavapipe:"
    in_root sh -c 'DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
        libx11-6 libx11-xcb1 libxcursor1 libxrandr2 libxi6 libxkbcommon-x11-0 \
        mesa-vulkan-drivers libvulkan1 >/dev/null 2>&1'
    explorer 40 &
    sleep 30
    DISPLAY=:96 xwd -root -silent | convert xwd:- "$root/window.png"
    code=0; wait $! || code=$?
    echo "fresh-machine: exit $code (124: still open after 40 s, as it should be); $root/window.png"
    [ "$code" = 124 ] || { echo "fresh-machine: FAILED: the explorer closed" >&2; exit 1; }
    exit 0
fi

echo "fresh-machine: rustup, Rust 1.95 (minimal profile); the clone of HEAD"
in_root sh -c 'curl -sSf https://static.rust-lang.org/rustup/dist/x86_64-unknown-linux-gnu/rustup-init \
    -o /tmp/rustup-init && chmod +x /tmp/rustup-init \
    && /tmp/rustup-init -y -q --profile minimal --default-toolchain 1.95.0 >/dev/null 2>&1'
git clone -q "$repo" "$root/root/glyphscope"

if [ "$mode" = nonroot ]; then
    # The user runs root's toolchain, read-only, on a clone of its own: it could build
    # there, so "built: no" means setup.sh stopped first.
    chmod 755 "$root/root"
    in_root useradd -m tester
    in_root chown -R tester /root/glyphscope
    as_tester() { in_root su tester -c "cd /root/glyphscope && RUSTUP_HOME=/root/.rustup \
        CARGO_HOME=/home/tester/.cargo PATH=/root/.cargo/bin:/usr/bin:/bin \
        tools/setup.sh && cargo test --release"; }
    for sudo in none no-rights; do
        if [ $sudo = no-rights ]; then
            in_root sh -c 'DEBIAN_FRONTEND=noninteractive apt-get install -y -qq sudo >/dev/null 2>&1'
        fi
        echo "fresh-machine: the test command as a user, sudo: $sudo"
        code=0; as_tester || code=$?
        built=no; [ -d "$root/root/glyphscope/target" ] && built=yes
        echo "fresh-machine: exit $code; built: $built"
        if [ "$code" != 2 ] || [ $built = yes ]; then
            echo "fresh-machine: FAILED: exit 2 before building expected" >&2
            exit 1
        fi
    done
    exit 0
fi

echo "fresh-machine: tools/setup.sh && cargo test --release"
start=$(date +%s)
code=0; in_root sh -c 'cd /root/glyphscope && tools/setup.sh && cargo test --release' \
    || code=$?
echo "fresh-machine: the test command: exit $code after $(( $(date +%s) - start )) s"
exit $code
