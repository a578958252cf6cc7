#!/bin/sh
# setup.sh - install what is missing (Debian 12, as root), configure and
# build slipwall in ./build.  Safe to run again: it only does what is
# not done yet.  `setup.sh --packages`: install only (the scripts that
# build elsewhere: scripts/fuzz.sh).
set -e
cd "$(dirname "$0")/.."
pkgs="build-essential meson ninja-build pkg-config libglpk-dev libgsl-dev libyaml-dev libncurses-dev libcairo2-dev tmux python3 valgrind"
# the tests look at processes with ps (not in a minimal Debian image)
pkgs="$pkgs procps"
# mpirun -n P slipwall run (docs/cluster.md): Open MPI, found by meson -Dmpi=auto
pkgs="$pkgs libopenmpi-dev openmpi-bin"
missing=""
for p in $pkgs; do
	dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
	echo "setup: installing$missing" >&2
	export DEBIAN_FRONTEND=noninteractive
	apt-get update -qq
	apt-get install -y -qq $missing >/dev/null
fi
[ "${1:-}" = --packages ] && exit 0
[ -f build/build.ninja ] || meson setup build >/dev/null
meson compile -C build >/dev/null
