# tui_lib.sh - the helpers of the workbench tests (tests/tui/tui*.sh),
# sourced after tests/tap.sh, with $bin set:
#   tui_setup NAME COLS ROWS     skip without tmux (skip_all: a failure
#                                in CI); $tmp, $SLIPWALL_RUNS, the server
#   tui_server NAME [COLS ROWS]  a private tmux server (tmux -L NAME -f
#                                /dev/null), session t; 1 if it cannot start
#   prompt WIN KEY LABEL TEXT    KEY opens the prompt LABEL: TEXT replaces
#                                its value and Enter accepts
#   T ARGS...                    tmux on that server
#   start WIN ENV... -- ARGS...  the workbench in window WIN ($tmp/WIN.pid)
#   screen WIN, screen_has WIN RE, wait_for WIN RE SECONDS
#   last_has WIN RE, wait_last WIN RE SECONDS  (the status line)
#   title WIN                    the title line
#   samples WIN, median WIN, p05 WIN, runno WIN   numbers of the panes
#   samples_reach WIN N, wait_samples WIN N SECONDS
#   wait_run WIN RUN STATE SECONDS  (the title says "run RUN STATE")
#   csv_complete FILE            rows 0..n-1 with the header's columns
#   run_csv RUN                  the samples file of run RUN
#   frame_at WIN COLS ROWS       a whole frame drawn for COLS x ROWS
#   printed_csv WIN              the samples file a workbench printed
#                                on exit ("samples: PATH")
tui_sock=
T() {
	tmux -L "$tui_sock" "$@"
}
tui_server() {
	tui_sock=$1
	T -f /dev/null new-session -d -s t -n idle -x "${2:-100}" -y "${3:-30}" \
		"sleep 600" || return 1
	T set-option -g remain-on-exit on >/dev/null
	trap 'T kill-server >/dev/null 2>&1; rm -rf "$tmp"' EXIT
}
tui_setup() {
	command -v tmux >/dev/null 2>&1 || skip_all "tmux is not installed"
	tmp=$(mktemp -d)
	export SLIPWALL_RUNS=$tmp/runs
	tui_server "$1" "$2" "$3" || {
		rm -rf "$tmp"
		skip_all "cannot start a tmux server"
	}
}
prompt() {
	T send-keys -t "t:$1" "$2"
	wait_for "$1" "$3:" 5
	T send-keys -t "t:$1" C-u
	T send-keys -t "t:$1" -l -- "$4"	# "--": a value may start with "-"
	T send-keys -t "t:$1" Enter
}
# A window per workbench, started through a shell that leaves its pid.
# remain-on-exit keeps the pane (and what the program printed) after exit.
start() {	# NAME ENV... -- ARGS...
	local name=$1
	shift
	local envs=()
	while [ "$1" != "--" ]; do
		envs+=("$1")
		shift
	done
	shift
	T new-window -d -t t -n "$name" \
		"echo \$\$ > '$tmp/$name.pid'; exec env ${envs[*]} SLIPWALL_RUNS='$SLIPWALL_RUNS' '$bin' $*"
}
screen() {
	T capture-pane -p -t "t:$1"
}
screen_has() {
	screen "$1" | grep -qE -- "$2"
}
# wait_for WINDOW REGEX SECONDS
wait_for() {
	within "$3" screen_has "$1" "$2"
}
title() {
	screen "$1" | head -n 1
}
samples() {
	screen "$1" | samples_of
}
# ... of a screen on stdin (one capture read for several values)
samples_of() {
	sed -n 's/.*samples  *\([0-9][0-9]*\) \/ .*/\1/p' | head -n 1
}
median() {
	screen "$1" | sed -n 's/.* p50  *\([0-9.e+-][0-9.e+-]*\).*/\1/p' | head -n 1
}
p05() {
	screen "$1" | sed -n 's/.* p05  *\([0-9.e+-][0-9.e+-]*\).*/\1/p' | head -n 1
}
runno() {
	screen "$1" | sed -n 's/.* run \([0-9][0-9]*\) .*/\1/p' | head -n 1
}
samples_reach() {
	local s
	s=$(samples "$1")
	[ -n "$s" ] && [ "$s" -ge "$2" ]
}
# wait_samples WINDOW MIN SECONDS: until the count reaches MIN
wait_samples() {
	within "$3" samples_reach "$1" "$2"
}
wait_run() {
	within "$4" screen_has "$1" "\\| run $2 $3( \\||$)"
}
last_has() {
	screen "$1" | tail -n 1 | grep -qE -- "$2"
}
# wait_last WINDOW REGEX SECONDS: the status line (last row) matches
wait_last() {
	within "$3" last_has "$1" "$2"
}
csv_complete() {	# every row has the header's column count; samples 0..n-1
	awk -F, 'NR == 1 { n = NF; next }
		 NF != n || $1 != NR - 2 { bad = 1 }
		 END { exit bad || NR < 1 }' "$1"
}
# (a session that started in the same second as another one of the same
# wall has <...>-RUN.1.csv: src/tui/tui_file.c)
run_csv() {
	ls "$SLIPWALL_RUNS"/*-"$1".csv "$SLIPWALL_RUNS"/*-"$1".[0-9]*.csv \
		2>/dev/null | head -n 1
}
# frame_at WIN COLS ROWS: one capture that is a frame the workbench drew
# for COLS x ROWS: ROWS lines, the title whole up to the run's state (a
# frame drawn for a wider terminal, which tmux cuts at the new width,
# ends elsewhere) and the status line last.  Waiting for "q quit" on
# the last line alone passed on the cut old frame before the redraw.
frame_at() {
	local s
	s=$(screen "$1")
	[ "$(printf '%s\n' "$s" | wc -l)" -eq "$3" ] &&
		printf '%s\n' "$s" | head -n 1 |
		grep -qE '^ slipwall \|.*\| run [0-9]+ [a-z]+( \| [^|]*)? *$' &&
		printf '%s\n' "$s" | tail -n 1 | grep -q 'q quit'
}
printed_csv() {
	screen "$1" | sed -n 's/^samples: \(.*\.csv\) *$/\1/p' | head -n 1
}
# csv_p05 FILE: p05 of a samples file as the workbench prints it (%.4g):
# GSL's type 7 quantile of the sorted accepted lambda_min (for a point
# load of 1 N, as the demo's, lambda_min is the load in N); "-" without
# an accepted sample
csv_p05() {
	awk -F, 'NR > 1 && $2 == "accepted" { print $4 }' "$1" | sort -g |
		awk '{ x[n++] = $1 }
		     END { if (!n) { print "-"; exit }
			   h = (n - 1) * 0.05; i = int(h); d = h - i
			   v = x[i]; if (i + 1 < n) v = (1 - d) * x[i] + d * x[i + 1]
			   printf "%.4g\n", v }'
}
