#!/bin/sh
# setup.sh - install what is missing (Debian 12, as root), configure and
# build slipwall in ./build, and install it (meson install: the program
# on the PATH, `man slipwall`, the bundled walls).  Safe to run again: it
# only does what is not done yet, and says what it does.
#
#   setup.sh            what building and running need
#   setup.sh --tests    also what the tests need (tmux, valgrind, Open MPI
#                       for the MPI build and its test, ps); scripts/test.sh
#   setup.sh --packages install the packages only, build nothing (the
#                       scripts that build elsewhere: fuzz.sh, ci-nompi.sh)
set -e
cd "$(dirname "$0")/.."
tests=0
packages_only=0
for a in "$@"; do
	case $a in
	--tests) tests=1 ;;
	--packages) packages_only=1 ;;
	*) echo "usage: sh scripts/setup.sh [--tests] [--packages]" >&2; exit 2 ;;
	esac
done

# building and running: the compiler, meson, the libraries, man
pkgs="build-essential meson ninja-build pkg-config libglpk-dev libgsl-dev libyaml-dev libncurses-dev libcairo2-dev man-db"
if [ "$tests" = 1 ]; then
	# the workbench test drives tmux; the tests look at processes with
	# ps (not in a minimal Debian image), read JSON with python3 and
	# the order of system calls with strace
	pkgs="$pkgs tmux procps python3 valgrind strace"
	# mpirun -n P slipwall run (docs/cluster.md): Open MPI, found by
	# meson -Dmpi=auto, and its test
	pkgs="$pkgs libopenmpi-dev openmpi-bin"
fi
missing=""
for p in $pkgs; do
	dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing="$missing $p"
done
if [ -n "$missing" ]; then
	echo "setup: installing$missing"
	export DEBIAN_FRONTEND=noninteractive
	apt-get update -q
	apt-get install -y $missing
else
	echo "setup: packages already installed"
fi
[ "$packages_only" = 1 ] && exit 0

if [ ! -f build/build.ninja ]; then
	echo "setup: configuring ./build (meson setup build)"
	meson setup build
elif [ -n "$missing" ]; then
	# new libraries (Open MPI) are found only by a new configuration
	echo "setup: reconfiguring ./build for the new packages"
	meson setup --reconfigure build
fi
echo "setup: building (meson compile -C build)"
meson compile -C build
if [ "$(id -u)" = 0 ]; then
	echo "setup: installing slipwall, its manual page and walls (meson install -C build)"
	meson install -C build --quiet
	echo "setup: done: $(command -v slipwall || echo 'slipwall not on the PATH')"
else
	echo "setup: done (not root: run 'meson install -C build' as root to put slipwall on the PATH, or use ./build/slipwall)"
fi
