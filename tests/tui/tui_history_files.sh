#!/bin/bash
# tui/tui_history_files.sh - the run history's index file when it is not
# a regular file (issue 23): history.tsv linked to /dev/zero (the H
# screen read it for ever, deaf to q, SIGHUP and SIGTERM), a FIFO (the
# first edit blocked opening it for writing), and a directory (the
# write failed, and its message was overwritten at once by the edit's).
# Each is refused with a message that stays on screen until the next
# key; q still quits, SIGTERM still ends the workbench.
#
# Usage (from the source root): bash tests/tui/tui_history_files.sh /path/to/slipwall
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_history_files.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-histfiles-$$" 100 30
# a workbench stuck in a read ignores SIGHUP from the server: kill it
trap 'for f in "$tmp"/*.pid; do [ -f "$f" ] && kill -KILL "$(cat "$f")" 2>/dev/null; done
      T kill-server >/dev/null 2>&1; rm -rf "$tmp"' EXIT

wall=walls/two-block-stack.yaml
pid_of() {
	cat "$tmp/$1.pid" 2>/dev/null
}

# ---- history.tsv -> /dev/zero ----------------------------------------------
mkdir -p "$tmp/zero" "$tmp/zero2"
ln -s /dev/zero "$tmp/zero/history.tsv"
ln -s /dev/zero "$tmp/zero2/history.tsv"
SLIPWALL_RUNS=$tmp/zero start z LANG=C.UTF-8 LC_ALL=C.UTF-8 -- $wall
wait_samples z 1 20
T send-keys -t t:z H
if wait_for z '^earlier sessions not shown: .*history\.tsv: not a regular file \(a device\)' 10; then
	ok "history.tsv -> /dev/zero: the H screen opens and says the index is not a regular file"
else
	not_ok "history.tsv -> /dev/zero: the H screen opens and says why" "$(screen z)"
fi
T send-keys -t t:z q	# back to the workbench
wait_for z '\| run 1 ' 5
T send-keys -t t:z q
if within 10 gone "$(pid_of z)"; then
	ok "history.tsv -> /dev/zero: q quits after the H screen"
else
	not_ok "history.tsv -> /dev/zero: q quits after the H screen" "$(screen z)"
fi
SLIPWALL_RUNS=$tmp/zero2 start z2 LANG=C.UTF-8 LC_ALL=C.UTF-8 -- $wall
wait_samples z2 1 20
T send-keys -t t:z2 H
sleep 1
kill -TERM "$(pid_of z2)"
if within 10 gone "$(pid_of z2)"; then
	ok "history.tsv -> /dev/zero: SIGTERM on the H screen ends the workbench"
else
	not_ok "history.tsv -> /dev/zero: SIGTERM on the H screen ends the workbench" "$(screen z2)"
fi

# ---- history.tsv a FIFO ----------------------------------------------------
mkdir -p "$tmp/fifo"
mkfifo "$tmp/fifo/history.tsv"
SLIPWALL_RUNS=$tmp/fifo start p LANG=C.UTF-8 LC_ALL=C.UTF-8 -- $wall
wait_samples p 1 20
T send-keys -t t:p f	# an edit: run 1 ends, its row is written
if wait_for p '\| run 2 ' 10; then
	ok "history.tsv a FIFO: the first edit does not block (run 2 starts)"
else
	not_ok "history.tsv a FIFO: the first edit does not block" "$(screen p)"
fi
if screen_has p 'run history: .*history\.tsv: not a regular file \(a FIFO\)'; then
	ok "history.tsv a FIFO: the workbench says it is not a regular file"
else
	not_ok "history.tsv a FIFO: the workbench says why" "$(screen p)"
fi
T send-keys -t t:p q
if within 10 gone "$(pid_of p)"; then
	ok "history.tsv a FIFO: q quits"
else
	not_ok "history.tsv a FIFO: q quits" "$(screen p)"
fi

# ---- history.tsv a directory: the message stays --------------------------
mkdir -p "$tmp/dir/history.tsv"
SLIPWALL_RUNS=$tmp/dir start d LANG=C.UTF-8 LC_ALL=C.UTF-8 -- $wall
wait_samples d 1 20
T send-keys -t t:d f
wait_for d '\| run 2 ' 10
sleep 1		# a few ticks of the new run: the screen is redrawn
if screen_has d 'run history: .*: not a regular file \(a directory\) \(not kept' &&
   screen_has d 'sampling again \(run 2\)'; then
	ok "history.tsv a directory: the failed write's message stays beside the edit's"
else
	not_ok "history.tsv a directory: the failed write's message stays beside the edit's" "$(screen d)"
fi
T send-keys -t t:d H
if wait_for d '^not kept: .*history\.tsv: not a regular file \(a directory\)' 5; then
	ok "history.tsv a directory: the H screen's title says why the history is not kept"
else
	not_ok "history.tsv a directory: the H screen's title says why" "$(screen d)"
fi
T send-keys -t t:d q
wait_for d '\| run 2 ' 5
if ! screen_has d 'run history: .*not a regular file'; then
	ok "history.tsv a directory: the message goes at the next key"
else
	not_ok "history.tsv a directory: the message goes at the next key" "$(screen d)"
fi
T send-keys -t t:d q
within 10 gone "$(pid_of d)"
if screen_has d '^history: not kept: .*history\.tsv: not a regular file'; then
	ok "history.tsv a directory: q prints why the history was not kept"
else
	not_ok "history.tsv a directory: q prints why the history was not kept" "$(screen d)"
fi

tap_end
