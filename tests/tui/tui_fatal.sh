#!/bin/bash
# tui/tui_fatal.sh - however the workbench ends, the terminal is given
# back and the reason is printed (issue 23).  Before, a fatal end (GSL's
# default handler aborting, out of memory, a GLPK error outside a solve,
# a fault) left the terminal in curses' modes - no echo, no line editing,
# the alternate screen - and the message in $TMPDIR/slipwall-stderr-*,
# which nobody reads.
#
# In a private tmux server the workbench runs from a shell that, once it
# has ended, records the terminal's modes (stty -a).  The workbench is
# sent SIGABRT (what abort() raises), then in other windows SIGSEGV and
# Ctrl-\ (SIGQUIT, typed): each time its stderr says "the workbench ended: SIGNAL (the
# terminal was restored)", the shell after it finds echo and canonical
# input back on, the pane is off the alternate screen, and no temporary
# stderr file is left.  A wall whose design load is the least of 240
# loads (the count at which GSL's beta quantile failed, k = 1) runs to
# its end and shows "1 of 240".
#
# Usage (from the source root): bash tests/tui/tui_fatal.sh SLIPWALL
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_fatal.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-fatal-$$" 100 30

# fatal WINDOW SIGNAL
fatal() {
	local w=$1 sig=$2
	mkdir -p "$tmp/$w.tmp"
	T new-window -d -t t -n "$w" "sh -c 'echo \$\$ > $tmp/$w.pid; exec env TMPDIR=$tmp/$w.tmp SLIPWALL_RUNS=$SLIPWALL_RUNS LANG=C.UTF-8 $bin walls/demo.yaml 2>$tmp/$w.err'; stty -a > $tmp/$w.stty; echo ended > $tmp/$w.done; sleep 600"
	if ! wait_samples "$w" 1 60; then
		not_ok "$sig: the workbench started" "$(screen "$w")"
		return
	fi
	if [ "$sig" = SIGQUIT ]; then
		T send-keys -t "t:$w" 'C-\'	# what a person types
	else
		kill -"$sig" "$(cat "$tmp/$w.pid")"
	fi
	if ! within 20 test -s "$tmp/$w.done"; then
		not_ok "$sig: the workbench ended" "$(screen "$w")"
		return
	fi
	check "$sig: the reason on stderr" \
		grep -q "^slipwall: the workbench ended: $sig .*(the terminal was restored)" "$tmp/$w.err"
	check "$sig: echo and canonical input are back on" \
		eval "grep -qw icanon '$tmp/$w.stty' && grep -qw echo '$tmp/$w.stty' && ! grep -qw -- -icanon '$tmp/$w.stty'"
	check "$sig: off the alternate screen (the workbench's screen is gone)" \
		eval "! screen_has $w 'q quit'"
	check "$sig: no temporary stderr file left" \
		eval "[ -z \"\$(ls -A '$tmp/$w.tmp')\" ]"
}
fatal a SIGABRT
fatal s SIGSEGV
fatal q SIGQUIT

# ---- the design load at k = 1 of 240 ----------------------------------------
min=$("$bin" run walls/demo.yaml -n 240 --json 2>/dev/null |
	python3 -c 'import json, sys; print(repr(json.load(sys.stdin)["lambda"]["min"]))')
sed -e 's/^  samples: .*/  samples: 240/' -e "s/^  seed: .*/&\n  design_load: $min/" \
	walls/demo.yaml >"$tmp/k1.yaml"
grep -q "^  design_load: $min\$" "$tmp/k1.yaml" || echo "# could not add the design load ($min)"
start d LANG=C.UTF-8 LC_ALL=C.UTF-8 -- "$tmp/k1.yaml"
if wait_run d 1 done 120 && screen_has d 'P\(λ <= design [^,]*, 1 of 240'; then
	ok "a design load at the least of 240 loads: run 1 done, 1 of 240"
else
	not_ok "a design load at the least of 240 loads: run 1 done, 1 of 240" "$(screen d)"
fi
tap_end
