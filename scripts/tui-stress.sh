#!/bin/sh
# tui-stress.sh - the workbench tests (tmux) many times in a row beside
# two busy loops, as on a loaded CI machine (issue 23: they must pass 20
# runs in a row).
#
#   sh scripts/tui-stress.sh [RUNS [BUILDDIR]]     (default 20, build)
#
# Starts two `while :; do :; done` shells, then RUNS times
# `meson test -C BUILDDIR --no-rebuild --num-processes 2` on the tmux
# tests (tui tui_edit tui_history tui_screen tui_design tui_hold), each
# run's log kept under BUILDDIR/meson-logs/tui-stress-K.txt; a failed
# run's failing subtests are printed.  Stops the loops it started (by
# their pids) and ends with "tui-stress: P of N runs passed", status 0
# when all passed.  Build first (meson compile -C BUILDDIR).
runs=${1:-20}
dir=${2:-build}
cd "$(dirname "$0")/.." || exit 2
tests="tui tui_edit tui_history tui_screen tui_design tui_hold"
[ -f "$dir/build.ninja" ] || { echo "tui-stress: no build in $dir" >&2; exit 2; }

sh -c 'while :; do :; done' &
busy1=$!
sh -c 'while :; do :; done' &
busy2=$!
trap 'kill "$busy1" "$busy2" 2>/dev/null' EXIT
trap 'exit 1' INT TERM HUP

passed=0
k=1
while [ "$k" -le "$runs" ]; do
	start=$(date +%s)
	# shellcheck disable=SC2086
	if meson test -C "$dir" --no-rebuild --num-processes 2 \
		--logbase "tui-stress-$k" $tests >"$dir/meson-logs/tui-stress-$k.out" 2>&1; then
		passed=$((passed + 1))
		echo "tui-stress: run $k passed ($(( $(date +%s) - start )) s)"
	else
		echo "tui-stress: run $k FAILED ($(( $(date +%s) - start )) s):"
		grep -E '^not ok|(FAIL|TIMEOUT|ERROR) ' "$dir/meson-logs/tui-stress-$k.txt" \
			"$dir/meson-logs/tui-stress-$k.out" 2>/dev/null | sed 's/^/    /'
	fi
	k=$((k + 1))
done
echo "tui-stress: $passed of $runs runs passed"
[ "$passed" = "$runs" ]
