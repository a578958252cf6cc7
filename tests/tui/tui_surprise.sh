#!/bin/bash
# tui/tui_surprise.sh - the workbench's surprises removed (issue 27,
# "Surprises to remove"), driven in tmux as a person would:
#   - a key that does nothing says so on the message line;
#   - the mouse wheel scrolls the history screen H and does not close it;
#   - F1 opens the help, as ? does;
#   - Ctrl-Z in a shell stops the workbench (the shell shows the stopped
#     job) and fg brings its screen back, sampling on;
#   - texts: "1 run this session", the rarest mechanism of 300 samples
#     never "0 %", no probability in scientific notation;
#   - h on the demo's pull on the right face says that the load now
#     pushes on the left face;
#   - a block removed from inside the wall is crossed out, not drawn as
#     a block.
#
# Usage (from the source root): bash tests/tui/tui_surprise.sh SLIPWALL
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_surprise.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-surprise-$$" 100 30

# the message line (the row above the status line)
message() {
	screen "$1" | tail -n 2 | head -n 1
}

# A key of no use: a word on the message line, the wall unchanged.
start w LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/demo.yaml
wait_samples w 1 30
T send-keys -t t:w z
if wait_for w 'key z does nothing here: \? lists the keys' 5 &&
   title w | grep -q '| run 1 running'; then
	ok "z: 'key z does nothing here: ? lists the keys', no new run"
else
	not_ok "z: 'key z does nothing here: ? lists the keys', no new run" "$(screen w)"
fi
T send-keys -t t:w C-e
if wait_for w 'key \^E does nothing here' 5; then
	ok "Ctrl-E: named ^E"
else
	not_ok "Ctrl-E: named ^E" "$(message w)"
fi

# The wheel in H: X10 mouse sequences (button 64 up, 65 down at column
# 10, row 10) scroll; the screen stays open.  Before, any mouse event
# closed it.
T send-keys -t t:w H
wait_for w '^ run history:' 5
T send-keys -t t:w -l $'\e[Ma++'
T send-keys -t t:w -l $'\e[M`++'
sleep 0.5
if screen_has w '^ run history:'; then
	ok "the mouse wheel leaves H open"
else
	not_ok "the mouse wheel leaves H open" "$(screen w)"
fi
T send-keys -t t:w q
if wait_for w '^ slipwall \|' 5; then
	ok "a key leaves H"
else
	not_ok "a key leaves H" "$(screen w)"
fi

# F1 is help, as ? is; any key returns.
T send-keys -t t:w F1
if wait_for w '^ slipwall workbench: keys' 5 && screen_has w '\?, F1 +this help'; then
	ok "F1 opens the help (which names F1)"
else
	not_ok "F1 opens the help (which names F1)" "$(screen w)"
fi
T send-keys -t t:w Escape
if wait_for w '^ slipwall \|' 5; then
	ok "a key leaves the help"
else
	not_ok "a key leaves the help" "$(screen w)"
fi

# Ctrl-Z from a shell with job control: the shell says the job stopped;
# fg brings the screen back and sampling goes on.
T new-window -d -t t -n sh "env -i PATH=/usr/bin:/bin HOME=$tmp TERM=\$TERM PS1='$ ' bash --norc --noprofile -i"
wait_for sh '\$ ' 10
T send-keys -t t:sh -l "cd $PWD && LANG=C.UTF-8 LC_ALL=C.UTF-8 SLIPWALL_RUNS=$SLIPWALL_RUNS $bin walls/demo.yaml"
T send-keys -t t:sh Enter
wait_samples sh 1 30
T send-keys -t t:sh C-z
if wait_for sh '^\[1\]\+ +Stopped ' 10 && ! screen_has sh '^ slipwall \|'; then
	ok "Ctrl-Z: the shell shows the stopped job"
else
	not_ok "Ctrl-Z: the shell shows the stopped job" "$(screen sh)"
fi
T send-keys -t t:sh fg Enter
if wait_for sh '^ slipwall \| Demo wall' 10 &&
   wait_for sh 'back after Ctrl-Z' 5; then
	ok "fg: the screen is back (the title line, 'back after Ctrl-Z')"
else
	not_ok "fg: the screen is back" "$(screen sh)"
fi
s1=$(samples sh)
sleep 1.5
s2=$(samples sh)
if [ -n "$s1" ] && [ -n "$s2" ] && { [ "$s2" -gt "$s1" ] || title sh | grep -q 'run 1 done'; }; then
	ok "fg: sampling goes on ($s1, then $s2)"
else
	not_ok "fg: sampling goes on" "$s1 then $s2" "$(screen sh)"
fi
T send-keys -t t:sh q
if wait_for sh '^run history \(1 run\):' 10; then
	ok "q after fg: the workbench ends and prints its history"
else
	not_ok "q after fg: the workbench ends and prints its history" "$(screen sh)"
fi

# One run: "1 run", not "1 runs".
T send-keys -t t:w H
if wait_for w '^ run history: 1 run this session' 5; then
	ok "H: '1 run this session'"
else
	not_ok "H: '1 run this session'" "$(screen w | head -n 1)"
fi
T send-keys -t t:w q
wait_for w '^ slipwall \|' 5
# 300 samples: the rarest mechanism family (M from the latest) is a share of
# 300, at least 0.3 %: never "0 %"; nothing in scientific notation
T send-keys -t t:w n C-u 300 Enter r
wait_run w 2 done 120
T send-keys -t t:w M
sleep 0.5
label=$(screen w | sed -n 2p)
if printf '%s\n' "$label" |
	grep -qE 'family ([0-9]+)/\1: ([1-9][0-9]*|0\.[1-9]|[0-9]+\.[0-9]) % ' &&
   ! screen w | grep -qE '[0-9]e[-+][0-9]'; then
	ok "the rarest of 300 is not '0 %' (${label%%(*}); no scientific notation"
else
	not_ok "the rarest of 300 is not '0 %'; no scientific notation" "$(screen w)"
fi

# h on the demo's pull on the right face goes round to the left face,
# where the same direction pushes: said so.
T send-keys -t t:w h
if wait_for w 'load now pushes on the left face \(was: pulls on the right face\)' 5; then
	ok "h: 'load now pushes on the left face (was: pulls on the right face)'"
else
	not_ok "h: the message says the load now pushes on the left face" "$(message w)"
fi
T send-keys -t t:w l
if wait_for w 'load now pulls on the right face \(was: pushes on the left face\)' 5; then
	ok "l: back to a pull on the right face, said so"
else
	not_ok "l: back to a pull on the right face, said so" "$(message w)"
fi

# A block removed from inside the wall (course 2, the third block):
# crossed out, not drawn as a block between its neighbours' lines.
wall_pane() {	# the panes' rows (╳ is the wall pane's only)
	screen "$1" | sed -n '3,24p'
}
if ! wall_pane w | grep -q '╳'; then
	ok "the whole wall: nothing crossed out"
else
	not_ok "the whole wall: nothing crossed out" "$(wall_pane w)"
fi
T send-keys -t t:w Tab
wait_for w 'cursor \(' 5
T send-keys -t t:w Up Right Right Right
wait_for w 'cursor \(0\.35, 0\.225\): c2b2' 5
T send-keys -t t:w x
wait_for w 'block c2b2 removed' 5
T send-keys -t t:w Tab
sleep 0.5
if wall_pane w | grep -qE '│╳+│'; then
	ok "x: the removed block's place is crossed out between its neighbours"
else
	not_ok "x: the removed block's place is crossed out" "$(wall_pane w)"
fi
T send-keys -t t:w u
if wait_for w 'undone' 5 && ! wall_pane w | grep -q '╳'; then
	ok "u: the block is back, nothing crossed out"
else
	not_ok "u: the block is back, nothing crossed out" "$(wall_pane w)"
fi

# w ends (its files written before the server and $tmp go)
T send-keys -t t:w q
wait_for w "^run history" 10
tap_end
