#!/bin/bash
# tui/tui_screen.sh - what the workbench's screen tells, in tmux: at
# 80x24 on the demo wall the whole wall with the loaded course and the
# load arrow on a row of their own, every number whole (the pane against
# the JSON of `slipwall run` with the same seed and count), the unit of
# lambda (N, load factor), the title's numbers, a saved path whole;
# NO_COLOR gives no colour escapes; a left click selects a block, a right
# click moves the load; on a large wall (minutes a sample), within 10 s
# of opening, the a-priori estimate of a sample's time before any sample
# finished ("first    about N min a sample"), the samples in progress
# with their age and an estimate of the time left, and standard/gilbert
# "computing... N s"; and `slipwall run`'s progress line says the first
# samples are running, how long, and the a-priori estimate, then the
# speed as the summary words it ("s a sample").
#
# Usage (from the source root): bash tests/tui/tui_screen.sh /path/to/slipwall
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_screen.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-screen-$$" 100 30

# --- 80x24 on the demo wall: the loaded course, the load, whole numbers ---
start d LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/demo.yaml
T resize-window -t t:d -x 80 -y 24
wait_samples d 1 20
# a run of 100 samples from sample 0, the one `slipwall run -n 100` makes
T send-keys -t t:d n C-u 100 Enter r
if wait_run d 2 done 60 && [ "$(screen d | wc -l)" -eq 24 ] && [ "$(screen d | head -n 1 | wc -m)" -le 81 ]; then
	ok "80x24: a run of 100 samples"
else
	not_ok "80x24: a run of 100 samples" "$(screen d)"
fi
pane=$(screen d | sed 's/\(.*\)│.*/\1/')	# the wall pane
load_row=$(printf '%s\n' "$pane" | grep '●')
left_of_load=${load_row%%●*}
if [ -n "$load_row" ] && printf '%s\n' "$load_row" | grep -q '●──→' &&
   printf '%s\n' "$left_of_load" | grep -q '│' &&
   ! printf '%s\n' "$left_of_load" | grep -q '[─┼├┤┬┴]'; then
	ok "80x24: the load and its arrow on a row of the loaded course, not on a joint line"
else
	not_ok "80x24: the load on a row of the loaded course" "$pane"
fi
if printf '%s\n' "$pane" | grep -q '┌' && printf '%s\n' "$pane" | grep -q '░░░'; then
	ok "80x24: the whole wall, top to ground"
else
	not_ok "80x24: the whole wall, top to ground" "$pane"
fi
"$bin" run walls/demo.yaml -n 100 --json >"$tmp/demo.json" 2>/dev/null
want=$(python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
l = j["lambda"]
f = lambda v: "%.4g" % v
print(" ".join(f(l[k]) for k in ("min", "max", "p05", "p50", "p95", "mean", "std")),
      f(j["p05_ci99"][0]), f(j["p05_ci99"][1]))' "$tmp/demo.json")
stats=$(screen d | sed -n 's/.*│//p')
got=$(printf '%s\n' "$stats" | awk '
	/min .* max / { mn = $3; mx = $5 }
	/ p05 .* p50 / { p05 = $2; p50 = $4 }
	/ p95 .* mean / { p95 = $2; mean = $4 }
	/^ *sd / { sd = $2 }
	/99 % interval \[/ { gsub(/[][,]/, " "); lo = $4; hi = $5 }
	END { print mn, mx, p05, p50, p95, mean, sd, lo, hi }')
if [ -n "$want" ] && [ "$got" = "$want" ]; then
	ok "80x24: every number whole, as in the JSON of slipwall run -n 100 ($got)"
else
	not_ok "80x24: every number whole, as in the JSON of slipwall run -n 100" "pane: $got" "json: $want" "$stats"
fi
if screen d | tail -n 1 | grep -q ' q quit' && [ "$(screen d | head -n 1 | wc -m)" -le 81 ] &&
   screen d | head -n 1 | grep -q 'run 2 done'; then
	ok "80x24: the title keeps its numbers and state"
else
	not_ok "80x24: the title keeps its numbers and state" "$(screen d | head -n 1)"
fi
if screen_has d '   sd  [0-9.e+-]+ +\(N\)' && screen_has d 'standard [0-9.]+  gilbert [0-9.]+'; then
	ok "80x24: the unit of lambda, N for a point load"
else
	not_ok "80x24: the unit of lambda, N for a point load" "$(screen d)"
fi
start ft LANG=C LC_ALL=C -- walls/ferris-tinloi-1.yaml
wait_samples ft 1 20
if screen_has ft 'sd  [0-9.e+-]+ +\(seismic coefficient\)'; then
	ok "a body load: the loads are a seismic coefficient"
else
	not_ok "a body load: the loads are a seismic coefficient" "$(screen ft)"
fi
T send-keys -t t:ft q
mkdir -p "$tmp/a/long/directory/name/to/see/the/path/is/not/cut"
prompt d s 'save wall as' "$tmp/a/long/directory/name/to/see/the/path/is/not/cut/saved-at-80x24.yaml"
if wait_for d 'saved ' 5 &&
   screen d | tr -d '\n' | grep -q "saved $tmp/a/long/directory/name/to/see/the/path/is/not/cut/saved-at-80x24.yaml"; then
	ok "80x24: the saved path is shown whole (wrapped)"
else
	not_ok "80x24: the saved path is shown whole" "$(screen d)"
fi
T send-keys -t t:d q
wait_for d '^history: ' 10

# --- NO_COLOR: no colour escapes; with colours, some ---
colour_sgr() {	# a colour parameter in an SGR sequence of the pane
	T capture-pane -e -p -t "t:$1" |
		grep -qE $'\e\\[([0-9]+;)*(3[0-8]|4[0-8]|9[0-7]|10[0-7])(;[0-9]+)*m'
}
start c LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/demo.yaml
start nc LANG=C.UTF-8 LC_ALL=C.UTF-8 NO_COLOR=1 -- walls/demo.yaml
wait_samples c 5 20
wait_samples nc 5 20
T send-keys -t t:c m
T send-keys -t t:nc m
wait_for c '^family 1/' 5
wait_for nc '^family 1/' 5
if colour_sgr c; then
	ok "without NO_COLOR the pane has colour escapes"
else
	not_ok "without NO_COLOR the pane has colour escapes" "$(T capture-pane -e -p -t t:c | cat -v | head -5)"
fi
if ! colour_sgr nc && T capture-pane -e -p -t t:nc | grep -q $'\e\\[[0-9;]*7m'; then
	ok "NO_COLOR=1: no colour escapes (reverse video for the bars)"
else
	not_ok "NO_COLOR=1: no colour escapes" "$(T capture-pane -e -p -t t:nc | cat -v | grep -E '\^\[\[([0-9]+;)*(3|4|9)[0-9]' | head -5)"
fi
T send-keys -t t:c q
T send-keys -t t:nc q

# --- the mouse: a left click selects a block, a right click moves the load ---
click() {	# WINDOW BUTTON(0 left, 2 right) COL ROW (0-based): X10 press, release
	local b=$2 x=$3 y=$4
	T send-keys -t "t:$1" -l "$(printf '\033[M%b%b%b\033[M%b%b%b' \
		"\\x$(printf %x $((32 + b)))" "\\x$(printf %x $((33 + x)))" "\\x$(printf %x $((33 + y)))" \
		"\\x$(printf %x 35)" "\\x$(printf %x $((33 + x)))" "\\x$(printf %x $((33 + y)))")"
}
start ms LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/demo.yaml
wait_samples ms 1 20
# the top-left block: the cell right below and right of the wall's corner
LC_ALL=C.UTF-8
top=$(screen ms | grep -n '┌' | head -n 1 | cut -d: -f1)
line=$(screen ms | sed -n "${top}p")
pre=${line%%┌*}
cx=$((${#pre} + 2))
cy=$top	# the row below, 0-based
click ms 0 "$cx" "$cy"
if wait_for ms 'block c[0-9]+b1 selected' 5 && wait_for ms '^cursor \(.*\): c[0-9]+b1 ' 5; then
	ok "a left click selects the block under it ($(screen ms | sed -n 's/^block \(c[0-9]*b1\) selected.*/\1/p'))"
else
	not_ok "a left click selects the block under it (cell $cx,$cy)" "$(screen ms)"
fi
T send-keys -t t:ms Tab
r0=$(runno ms)
click ms 2 "$cx" "$cy"
if wait_for ms 'load at \(|load now (pulls|pushes|acts)' 5 && [ "$(runno ms)" -eq $((r0 + 1)) ]; then
	ok "a right click moves the load there (a new run)"
else
	not_ok "a right click moves the load there" "$(screen ms)"
fi
T send-keys -t t:ms q

# --- a large wall: honest progress ---
start big LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/large.yaml
if wait_for big 'working  [0-9]+ samples?, oldest [0-9]+ s' 10 && wait_for big 'left     (about |~)[0-9:]+( s)? of ~?[0-9:]+( s)?' 10; then
	ok "large wall: samples in progress, their age, the time left, within 10 s"
else
	not_ok "large wall: samples in progress, their age, the time left, within 10 s" "$(screen big)"
fi
# the a-priori estimate (mc_sample_seconds), while no sample has finished
if wait_for big 'first +about [0-9]+ (s|min|h)( a sample| \(estimate\))' 10 &&
   screen_has big 'samples +0 / '; then
	ok "large wall: the first sample's estimate on screen before any sample finished"
else
	not_ok "large wall: the first sample's estimate on screen before any sample finished" "$(screen big)"
fi
age() {
	screen big | sed -n 's/.*working .*oldest \([0-9][0-9]*\) s.*/\1/p'
}
a1=$(age)
within 5 eval '[ "$(age)" != "$a1" ]'
a2=$(age)
if [ -n "$a1" ] && [ -n "$a2" ] && [ "$a2" -gt "$a1" ]; then
	ok "the age of the samples in progress ticks ($a1 s -> $a2 s)"
else
	not_ok "the age of the samples in progress ticks ($a1 -> $a2)" "$(screen big)"
fi
if screen_has big 'standard, gilbert: computing… [0-9]+ s' ||
   screen_has big 'standard ([0-9][0-9.e+-]*|n/a)  gilbert ([0-9]|n/a)'; then
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

# --- run's progress line on the same wall (a terminal on stderr) ---
T new-window -d -t t -n rp "echo \$\$ > '$tmp/rp.pid'; exec '$bin' run walls/large.yaml -n 4 --threads 1"
if wait_for rp '^0/4  first samples running for 0:0[1-9], left > 0:0[1-9]' 10; then
	ok "slipwall run on the large wall: the first samples running, their time, left > it"
else
	not_ok "slipwall run on the large wall: the first samples running" "$(screen rp)"
fi
if screen_has rp '^0/4  first samples running .*\(estimate: about [0-9]+ (s|min|h) a sample\)'; then
	ok "slipwall run on the large wall: the first progress line has the estimate"
else
	not_ok "slipwall run on the large wall: the first progress line has the estimate" "$(screen rp)"
fi
# once a sample has finished, the speed in the summary's words (a sample
# of this wall takes seconds: "s a sample", not "s/sample" or "/s")
if wait_for rp '^[1-4]/4  accepted [0-4]  rejected [0-4]  [0-9.]+ s a sample  .*left ' 90; then
	ok "slipwall run on the large wall: the speed in seconds a sample, as the summary says it"
else
	not_ok "slipwall run on the large wall: the speed in seconds a sample" "$(screen rp)"
fi
kill -INT "$(cat "$tmp/rp.pid")" 2>/dev/null

tap_end
