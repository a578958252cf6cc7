#!/bin/bash
# cli_tui_screen.sh - what the workbench's screen tells, in tmux: on a
# large wall (minutes a sample) the samples in progress with their age
# and an estimate of the time left, and standard/gilbert "computing...
# N s", within 10 s of opening.
#
# Usage (from the source root): bash tests/cli_tui_screen.sh /path/to/slipwall
# TAP output; skips when tmux is missing.

bin=${1:?usage: cli_tui_screen.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/.." || exit 1

if ! command -v tmux >/dev/null 2>&1; then
	echo "1..0 # SKIP tmux is not installed"
	exit 0
fi
. tests/tap.sh
. tests/tui_lib.sh

tmp=$(mktemp -d)
export SLIPWALL_RUNS=$tmp/runs
tui_server "slipwall-screen-$$" 100 30 || {
	echo "1..0 # SKIP cannot start a tmux server"
	exit 0
}

# --- a large wall: honest progress ---
start big LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/large.yaml
if wait_for big 'working  [0-9]+ in progress (for|, oldest) [0-9]+ s; left [>~] ?[0-9:]+( s)?' 10; then
	ok "large wall: samples in progress, their age, the time left, within 10 s"
else
	not_ok "large wall: samples in progress, their age, the time left, within 10 s" "$(screen big)"
fi
a1=$(screen big | sed -n 's/.*working .* \([0-9][0-9]*\) s; left.*/\1/p')
within 5 eval '[ "$(screen big | sed -n "s/.*working .* \([0-9][0-9]*\) s; left.*/\1/p")" != "$a1" ]'
a2=$(screen big | sed -n 's/.*working .* \([0-9][0-9]*\) s; left.*/\1/p')
if [ -n "$a1" ] && [ -n "$a2" ] && [ "$a2" -gt "$a1" ]; then
	ok "the age of the samples in progress ticks ($a1 s -> $a2 s)"
else
	not_ok "the age of the samples in progress ticks ($a1 -> $a2)" "$(screen big)"
fi
if screen_has big 'standard, gilbert: computing… [0-9]+ s' ||
   screen_has big 'standard [0-9.e+-]+|standard n/a'; then
	ok "standard and gilbert: computing… N s (or their values)"
else
	not_ok "standard and gilbert: computing… N s" "$(screen big)"
fi
pid=$(cat "$tmp/big.pid")
T send-keys -t t:big q
if within 10 gone "$pid"; then
	ok "q leaves a large wall within 10 s"
else
	not_ok "q leaves a large wall within 10 s" "$(screen big)"
fi

tap_end
