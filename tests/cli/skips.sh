#!/bin/bash
# cli/skips.sh - a test that cannot run for a missing tool skips where a
# developer runs it and fails where the tools must be there: CI=true, or
# SLIPWALL_TEST_TOOLS=required (scripts/test.sh sets it after installing
# them).  tests/tap.sh's skip_all, as tui_lib.sh's tui_setup, tui.sh and
# cli/mpi.sh use it (issue 23: a skipped tmux test passed in CI).
#
# Usage (from the source root): bash tests/cli/skips.sh SLIPWALL
# The tmux tests run with a PATH that has every command of /usr/bin and
# /bin but tmux; mpi.sh gets "missing" (meson's word for a build with
# MPI and no mpirun).  TAP output.

bin=${1:?usage: cli/skips.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/bin"
for f in /usr/bin/* /bin/*; do
	name=${f##*/}
	[ "$name" = tmux ] || [ -e "$tmp/bin/$name" ] || ln -s "$f" "$tmp/bin/$name"
done

# run MODE SCRIPT ARGS...: the script without tmux on the PATH; MODE
# dev (neither variable), ci (CI=true) or tools (SLIPWALL_TEST_TOOLS);
# its output in $tmp/out, its status in $rc
run() {
	local mode=$1
	shift
	local envs=(-u CI -u SLIPWALL_TEST_TOOLS PATH="$tmp/bin")
	case $mode in
	ci) envs+=(CI=true) ;;
	tools) envs+=(SLIPWALL_TEST_TOOLS=required) ;;
	esac
	env "${envs[@]}" bash "$@" >"$tmp/out" 2>&1
	rc=$?
}
skipped() {	# the plan says skip, status 0
	[ "$rc" = 0 ] && grep -q '^1\.\.0 # SKIP' "$tmp/out"
}
failed() {	# a not ok line, status not 0
	[ "$rc" != 0 ] && grep -q '^not ok' "$tmp/out" && ! grep -q '# SKIP' "$tmp/out"
}

for t in tui/tui.sh tui/tui_edit.sh; do
	run dev "tests/$t" "$bin"
	if skipped; then ok "$t without tmux: skipped"; else not_ok "$t without tmux: skipped (exit $rc)" "$(cat "$tmp/out")"; fi
	run ci "tests/$t" "$bin"
	if failed; then ok "$t without tmux, CI=true: a failure"; else not_ok "$t without tmux, CI=true: a failure (exit $rc)" "$(cat "$tmp/out")"; fi
	run tools "tests/$t" "$bin"
	if failed; then ok "$t without tmux, SLIPWALL_TEST_TOOLS=required: a failure"; else not_ok "$t without tmux, SLIPWALL_TEST_TOOLS=required: a failure (exit $rc)" "$(cat "$tmp/out")"; fi
done
run dev tests/cli/mpi.sh "$bin" missing
if skipped; then ok "mpi.sh without mpirun: skipped"; else not_ok "mpi.sh without mpirun: skipped (exit $rc)" "$(cat "$tmp/out")"; fi
run ci tests/cli/mpi.sh "$bin" missing
if failed; then ok "mpi.sh without mpirun, CI=true: a failure"; else not_ok "mpi.sh without mpirun, CI=true: a failure (exit $rc)" "$(cat "$tmp/out")"; fi
tap_end
