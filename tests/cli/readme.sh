#!/bin/bash
# cli/readme.sh - README's example commands, literally, as a new user
# runs them after README's first line.
#
# Usage (from the source root): bash tests/cli/readme.sh SLIPWALL
#   [mpi|none|nompirun]
# Extracts every line of the sh block under README's "## Use" heading and
# runs it with bash in a scratch directory that sees the checkout's
# walls/ and docs/ (the commands write demo.csv, demo-report/, ...):
# `slipwall` on the PATH is SLIPWALL, the binary under test (README's
# first line installs it; CI's own clone runs scripts/test.sh, which
# does).  Each must exit 0.  A line that opens the workbench (`slipwall`
# or `slipwall WALL.yaml`) runs in a private tmux server until its status
# line shows, then gets 'q' and must exit 0.  The mpirun line runs when
# the build has MPI (second argument `mpi`; `none`: a build without MPI,
# skipped; `nompirun`: MPI but no mpirun, a failure in CI).  A line that
# cannot run for a missing tool skips, and fails in CI (tests/tap.sh's
# skip_one).  Also: README's first line
# installs `slipwall` into a directory on the PATH and the manual page
# (meson install --dry-run of this build), and the bundled loads file is
# labelled synthetic.  TAP output.

bin=${1:?usage: cli/readme.sh SLIPWALL [mpi|none|nompirun]}
mpi=${2:-none}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1
root=$PWD
. tests/tap.sh

tmp=$(mktemp -d)
sock=slipwall-readme-$$
trap 'for s in $(seq 1 "$wb_n"); do tmux -L "$sock-$s" kill-server >/dev/null 2>&1; done; rm -rf "$tmp"' EXIT
mkdir -p "$tmp/bin" "$tmp/work"
ln -s "$bin" "$tmp/bin/slipwall"
ln -s "$root/walls" "$tmp/work/walls"
ln -s "$root/docs" "$tmp/work/docs"
export PATH="$tmp/bin:$PATH" SLIPWALL_RUNS="$tmp/runs" MANPAGER=cat PAGER=cat
# The mpirun line runs as written: nothing here lets mpirun run as root
# or put more ranks than cores (OMPI_ALLOW_RUN_AS_ROOT and an
# oversubscribe setting were exported here, so README's line passed in
# CI, as root, and failed for its readers); nor may the caller's
# environment.
unset OMPI_ALLOW_RUN_AS_ROOT OMPI_ALLOW_RUN_AS_ROOT_CONFIRM \
	OMPI_MCA_rmaps_base_oversubscribe

# the lines of the first ```sh block after "## Use"
awk '/^## Use/ {use = 1} use && /^```sh/ {inb = 1; next} inb && /^```/ {exit} inb' \
	README.md >"$tmp/lines"
count=$(grep -c . "$tmp/lines")
check "README's Use block has example commands ($count)" [ "$count" -ge 10 ]

# workbench LINE: run it in tmux; wait for the status line; q; status 0.
# Each line gets a server of its own: a new session on the socket of a
# server that kill-server has just told to go can reach that server as
# it exits ("server exited unexpectedly", seen once in CI).
wb_n=0
workbench() {
	wb_n=$((wb_n + 1))
	local s="$sock-$wb_n"
	tmux -L "$s" -f /dev/null new-session -d -s w -x 100 -y 30 \
		"cd '$tmp/work' && { $1; } 2>'$tmp/wb.out'; echo \$? >'$tmp/wb.rc'; sleep 60" ||
		return 1
	within 30 eval "tmux -L '$s' capture-pane -p -t w | grep -q 'q quit'" || {
		tmux -L "$s" capture-pane -p -t w
		tmux -L "$s" kill-server
		return 1
	}
	tmux -L "$s" send-keys -t w q
	within 30 test -s "$tmp/wb.rc"
	local rc
	rc=$(cat "$tmp/wb.rc" 2>/dev/null)
	tmux -L "$s" kill-server >/dev/null 2>&1
	rm -f "$tmp/wb.rc"
	[ "$rc" = 0 ]
}

while IFS= read -r line; do
	cmd=${line%%#*}
	cmd=$(echo "$cmd" | sed 's/[[:space:]]*$//')
	[ -n "$cmd" ] || continue
	set -- $cmd
	if [ "$1" = slipwall ] && { [ $# = 1 ] || { [ $# = 2 ] && [ "${2%.yaml}" != "$2" ]; }; }; then
		if ! command -v tmux >/dev/null 2>&1; then
			skip_one "$cmd" "tmux is not installed"
			continue
		fi
		if workbench "$cmd"; then ok "$cmd"; else not_ok "$cmd" "$(cat "$tmp/wb.out" 2>/dev/null)"; fi
		continue
	fi
	if [ "$1" = mpirun ] && [ "$mpi" = none ]; then
		ok "$cmd # SKIP the build has no MPI"
		continue
	fi
	if [ "$1" = mpirun ] && [ "$mpi" != mpi ]; then
		skip_one "$cmd" "the build has MPI but mpirun is not installed"
		continue
	fi
	if [ "$1" = man ] && ! command -v man >/dev/null 2>&1; then
		skip_one "$cmd" "man is not installed"
		continue
	fi
	# under AddressSanitizer the MPI ranks check memory errors but not
	# leaks (tests/tap.sh, asan_no_leaks)
	asan=${ASAN_OPTIONS:-}
	[ "$1" = mpirun ] && asan=$(asan_no_leaks)
	(cd "$tmp/work" && ASAN_OPTIONS=$asan bash -c "$line") >"$tmp/out" 2>"$tmp/err" </dev/null
	rc=$?
	if [ $rc = 0 ]; then
		ok "$cmd"
	else
		not_ok "$cmd: exit $rc" "$(tail -n 5 "$tmp/err")"
	fi
	if [ "$1" = man ]; then
		check "man ./docs/slipwall.1 shows the manual" grep -q 'sweep' "$tmp/out"
	fi
	case $cmd in
	*--tests*demo-loads.txt*)
		check "'$2' says the loads are synthetic" \
			eval "grep -qi synthetic '$tmp/out' || grep -rqi synthetic '$tmp'/work/*-report/report.md 2>/dev/null"
		;;
	esac
done <"$tmp/lines"

# a line that needs more than README's first line says what: the mpirun
# line names the set-up that installs Open MPI
check "README's mpirun line says it needs sh scripts/setup.sh --tests, and runs as root" \
	eval 'grep "^mpirun " "$tmp/lines" | grep -q -- "--allow-run-as-root.*# needs Open MPI: run sh scripts/setup.sh --tests first"'
check "walls/demo-loads.txt says it is synthetic" grep -qi '^#.*synthetic' walls/demo-loads.txt

# README's first line: setup.sh ends with meson install: slipwall goes
# to a directory on a root's PATH, the manual page to man1
builddir=$(dirname "$bin")
if command -v meson >/dev/null 2>&1 && [ -f "$builddir/build.ninja" ]; then
	meson install -C "$builddir" --dry-run --no-rebuild >"$tmp/install" 2>&1
	bindir=$(sed -n 's|^Installing \(.*/\)\{0,1\}slipwall to \(.*\)$|\2|p' "$tmp/install" | head -n 1)
	check "setup.sh installs slipwall into a PATH directory ($bindir) and its manual page" \
		eval 'grep -q "meson install -C build --quiet" scripts/setup.sh &&
		      case "$bindir" in /usr/local/bin|/usr/bin) true ;; *) false ;; esac &&
		      grep -q "slipwall.1 to .*/man1" "$tmp/install"'
else
	skip_one "meson install --dry-run" "no meson or no build directory"
fi
check "setup.sh without --tests installs neither valgrind nor Open MPI nor tmux" \
	eval 'sed -n "/^pkgs=\"build-essential/p" scripts/setup.sh | grep -vqE "valgrind|openmpi|tmux"'
# (docs/method.md and docs/performance.md are the lead's: not checked)
check "no user-facing text cites SPEC (a file the repository does not ship)" \
	eval '! grep -n "SPEC" docs/slipwall.1 README.md docs/run.md docs/wall-format.md docs/statistics.md docs/report.md docs/workbench.md docs/cluster.md docs/reliability.md && ! grep -rn "\"[^\"]*SPEC" src'
tap_end
