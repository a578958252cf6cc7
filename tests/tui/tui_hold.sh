#!/bin/bash
# tui/tui_hold.sh - a key held down on a large wall: 40 presses of f
# (friction up) within 2 s on walls/large.yaml, where one solve of
# standard and gilbert runs for minutes.  Each press is an edit: a new
# wall, a new run, a new solve.  Afterwards at most one solve thread
# ("sw-solve") is alive and no thread but the main one, the sampler's
# workers ("sw-mc", at most one per processor) and that one; the
# process holds under 400 MB (VmRSS); every press was applied (the
# title's friction is 0.6 + 40 x 0.05 = 2.6); and q ends the process
# within 2 s (the solve and the samples in progress are stopped, not
# waited for).
#
# Threads are counted by name in /proc/PID/task/*/comm (Linux; skipped
# elsewhere).
#
# Usage (from the source root): bash tests/tui/tui_hold.sh /path/to/slipwall
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_hold.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
if [ ! -d /proc/self/task ]; then
	echo "1..0 # SKIP no /proc/PID/task here"
	exit 0
fi
tui_setup "slipwall-hold-$$" 100 30

# threads PID: one line per thread other than the main one, its name
threads() {
	local d
	for d in /proc/"$1"/task/*; do
		[ "${d##*/}" = "$1" ] && continue
		cat "$d/comm" 2>/dev/null
	done
}
# rss PID: resident memory in kB
rss() {
	awk '/^VmRSS:/ { print $2 }' /proc/"$1"/status 2>/dev/null
}
# snapshot PID: the threads into $list, and 0 when none of them still
# has the name a new thread inherits (the program's, "slipwall"): each
# names itself (sw-mc, sw-solve) once it runs, and under load a thread
# made a moment ago has not run yet (seen 3 times in 20 runs beside two
# busy loops: "others: 2 slipwall", the workers of a run a press had
# just started).  The presses are still being taken then, threads come
# and go: the checks below look at one snapshot.
snapshot() {
	list=$(threads "$1")
	! printf '%s\n' "$list" | grep -qx "$(printf '%.15s' "${bin##*/}")"
}
# check_threads PID WHEN: the thread assertions, with what was seen (a
# thread that never names itself is still seen: after 5 s of snapshots
# with one, the last is checked)
check_threads() {
	local list solve mc other ncpu
	within 5 snapshot "$1"
	solve=$(printf '%s\n' "$list" | grep -cx 'sw-solve')
	mc=$(printf '%s\n' "$list" | grep -cx 'sw-mc')
	other=$(printf '%s\n' "$list" | grep -cvx -e 'sw-solve' -e 'sw-mc' -e '')
	ncpu=$(getconf _NPROCESSORS_ONLN)
	if [ "$solve" -le 1 ] && [ "$other" -eq 0 ]; then
		ok "$2: at most one solve thread ($solve), no other ($mc sw-mc)"
	else
		not_ok "$2: at most one solve thread" \
			"solve threads: $solve, sw-mc: $mc, others: $other" \
			"$(printf '%s\n' "$list" | sort | uniq -c)"
	fi
	if [ "$mc" -le "$ncpu" ]; then
		ok "$2: at most one sampler worker a processor ($mc of $ncpu)"
	else
		not_ok "$2: at most one sampler worker a processor" \
			"sw-mc: $mc, processors: $ncpu"
	fi
}

start w LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/large.yaml
if ! wait_for w 'μ 0\.6/0\.6 ' 60; then
	not_ok "the workbench opens walls/large.yaml" "$(screen w)"
	tap_end
	exit
fi
pid=$(cat "$tmp/w.pid")
ok "the workbench opens walls/large.yaml (pid $pid)"

# hold f: 40 presses, about 20 a second (a key's auto-repeat)
for i in $(seq 40); do
	T send-keys -t t:w f
	sleep 0.04
done
check_threads "$pid" "right after 40 presses"
max=$(rss "$pid")

if wait_for w 'μ 2\.6/2\.6 ' 60; then
	ok "every press was applied (μ 2.6)"
else
	not_ok "every press was applied (μ 2.6)" "$(title w)"
fi
sleep 2
check_threads "$pid" "2 s later"
now=$(rss "$pid")
[ "${now:-0}" -gt "${max:-0}" ] && max=$now
if ldd "$bin" 2>/dev/null | grep -qE 'lib(a|t)san'; then
	# the sanitizers' shadow memory and quarantine (256 MB of freed
	# blocks held back) are not the program's: the bound is checked in
	# the plain builds (the suite and the no-MPI suite of CI)
	ok "memory under 400 MB # SKIP a sanitizer build ($((${max:-0} / 1024)) MB)"
elif [ -n "$max" ] && [ "$max" -lt 409600 ]; then
	ok "memory under 400 MB ($((max / 1024)) MB)"
else
	not_ok "memory under 400 MB" "VmRSS: ${max:-?} kB"
fi

T send-keys -t t:w q
if within 2 gone "$pid"; then
	ok "q ends the process within 2 s"
else
	not_ok "q ends the process within 2 s" "$(screen w | tail -n 3)"
	kill "$pid" 2>/dev/null
fi
# the 40 edits' runs ended before their first sample (one takes minutes
# on this wall): they found nothing and leave no row of 0 samples (no
# row at all: no history file; tests/tui/tui_history.sh checks rows)
hist=$SLIPWALL_RUNS/history.tsv
[ -e "$hist" ] || printf 'samples\n' >"$hist"
zero=$(awk -F'\t' 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "samples") c = i; next }
		  c && $c == 0 { z++ } END { print z + 0 }' "$hist" 2>/dev/null)
if [ "${zero:-x}" = 0 ]; then
	ok "no history row for a run that found nothing ($(($(wc -l <"$hist" 2>/dev/null || echo 1) - 1)) rows)"
else
	not_ok "no history row for a run that found nothing" "rows with 0 samples: ${zero:-?}" "$(head -c 300 "$hist" 2>/dev/null)"
fi
tap_end
