#!/bin/bash
# tui/tui_present.sh - the classroom (docs/workbench.md, "What the
# numbers mean", "Presentation mode"), in tmux at 80 x 24 on a copy of
# the demo wall with 200 samples:
# - the help's second page (? then Tab): the lambda_min and p05 lines,
#   and every rejection reason's text, read from sample.h's
#   SAMPLE_STATUS_TABLE here too, so a new reason is checked without an
#   edit of this test;
# - presentation mode (V): the statistics pane gone, p05 (read from the
#   statistics pane before) in large digits, row by row as the font
#   draws it (with `█` in UTF-8, `#` in ASCII); auto-play advances the
#   shown sample within 5 s; A pauses it (the number stays 3.5 s) and
#   resumes it; after Esc (the browser closed) A opens it and plays on;
#   V again brings the statistics back;
# - m lights the bins of its mechanism family's samples in the histogram: red
#   bars with colours (capture-pane -e), reverse video with NO_COLOR;
#   none before m, none again back at the latest mechanism (M).
#
# Usage (from the source root): bash tests/tui/tui_present.sh SLIPWALL
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_present.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-present-$$" 80 24

sed -e 's/^  samples: .*/  samples: 200/' walls/demo.yaml >"$tmp/demo.yaml"
start u LANG=C.UTF-8 LC_ALL=C.UTF-8 -- "$tmp/demo.yaml"
start a LANG=C LC_ALL=C NO_COLOR=1 -- "$tmp/demo.yaml"
for w in u a; do
	if wait_run "$w" 1 done 120; then
		ok "$w: run 1 done"
	else
		not_ok "$w: run 1 done" "$(screen "$w")"
	fi
done

# --- the help's second page
T send-keys -t t:u '?'
wait_for u '^ slipwall workbench: keys \(Tab: what the numbers mean\)' 5
T send-keys -t t:u Tab
if wait_for u '^ slipwall workbench: what the numbers mean' 5 &&
   screen_has u '^ λ_min +one sample.s collapse load' &&
   screen_has u '^ p05 +the characteristic value' &&
   screen_has u '99 % interval' && screen_has u 'standard +one solution' &&
   screen_has u 'gilbert +the same contact points' &&
   screen_has u '\. closed +s slides +h hinges' && last_has u 'Tab: the keys'; then
	ok "help, Tab: what the numbers mean (lambda_min, p05, standard, gilbert, letters)"
else
	not_ok "help, Tab: what the numbers mean" "$(screen u)"
fi
# every reason's text, scrolling down (the page is longer than 24 rows)
seen=$(screen u)
for i in 1 2 3 4 5 6 7 8 9 10 11 12; do
	T send-keys -t t:u j
	sleep 0.1
	seen+=$'\n'$(screen u)
done
texts=$(sed -n '/define SAMPLE_STATUS_TABLE/,/^$/p' include/slipwall/sample.h |
	tr -d '\\\n\t' | grep -o 'X([A-Z_]*, *"[a-z_]*", *"[^"]*")' |
	sed 's/.*"\([a-z_]*\)", *"\([^"]*\)")/\1|\2/' | grep -v '^accepted|')
missing=
while IFS='|' read -r name text; do
	printf '%s\n' "$seen" | grep -qF "$name" || missing+=" $name"
	printf '%s\n' "$seen" | grep -qF "$text" || missing+=" '$text'"
done <<<"$texts"
if [ "$(printf '%s\n' "$texts" | wc -l)" -ge 7 ] && [ -z "$missing" ]; then
	ok "help's second page: all $(printf '%s\n' "$texts" | wc -l) rejection reasons and their texts"
else
	not_ok "help's second page: every rejection reason" "missing:$missing; $seen"
fi
T send-keys -t t:u Tab
wait_for u '^ slipwall workbench: keys' 5
T send-keys -t t:u Escape
wait_for u 'samples +200 / 200' 5

# --- presentation mode
# big WIN TEXT ROW COL: TEXT in large digits, rows ROW.. from column COL
# (1 first), as tui_present.c's font draws it at a cell width of 2 or 1
font() {	# the rows of one character
	case $1 in
	0) echo '###|# #|# #|# #|###' ;; 1) echo ' # |## | # | # |###' ;;
	2) echo '###|  #|###|#  |###' ;; 3) echo '###|  #| ##|  #|###' ;;
	4) echo '# #|# #|###|  #|  #' ;; 5) echo '###|#  |###|  #|###' ;;
	6) echo '###|#  |###|# #|###' ;; 7) echo '###|  #|  #|  #|  #' ;;
	8) echo '###|# #|###|# #|###' ;; 9) echo '###|# #|###|  #|###' ;;
	.) echo '   |   |   |   | # ' ;; -) echo '   |   |###|   |   ' ;;
	+) echo '   | # |###| # |   ' ;; e) echo '   |###|# #|## |###' ;;
	esac
}
big_row() {	# TEXT ROW SX BLOCK: row ROW (1..5) of TEXT
	local s=$1 r=$2 sx=$3 out= i g c k
	for ((i = 0; i < ${#s}; i++)); do
		g=$(font "${s:i:1}" | cut -d'|' -f"$r")
		[ "$i" -gt 0 ] && for ((k = 0; k < sx; k++)); do out+=' '; done
		for ((c = 0; c < 3; c++)); do
			for ((k = 0; k < sx; k++)); do out+=${g:c:1}; done
		done
	done
	printf '%s\n' "$out" | sed "s/ *\$//; s/#/$4/g"
}
big_shown() {	# WIN TEXT BLOCK: TEXT's five rows, one under the other
	local scr sx r row ok
	scr=$(screen "$1")
	for sx in 2 1; do
		ok=1
		for r in 1 2 3 4 5; do
			row=$(big_row "$2" "$r" "$sx" "$3")
			printf '%s\n' "$scr" | sed -n "$((r + 2))p" | grep -qF -- "$row" ||
				ok=0
		done
		[ "$ok" = 1 ] && return 0
	done
	return 1
}
shown_no() {	# the sample whose load is in large digits
	screen "$1" | sed -n '2s/.*_min of sample \([0-9]*\) .*/\1/p'
}

for w in u a; do
	p=$(p05 "$w")
	block='█'
	[ "$w" = a ] && block='#'
	T send-keys -t "t:$w" V
	if wait_for "$w" 'p05 of 200 accepted \(N\)' 5 &&
	   ! screen_has "$w" 'samples +200 / 200' &&
	   ! screen_has "$w" 'characteristic value' &&
	   screen_has "$w" '_min histogram' &&
	   within 3 big_shown "$w" "$p" "$block"; then
		ok "$w: V: no statistics pane, p05 $p in large digits ($block)"
	else
		not_ok "$w: V: no statistics pane, p05 $p in large digits" \
			"$(screen "$w"); expected rows: $(for r in 1 2 3 4 5; do big_row "$p" "$r" 2 "$block"; done)"
	fi
done

n0=$(shown_no u)
changed() {
	local n
	n=$(shown_no u)
	[ -n "$n" ] && [ "$n" != "$n0" ]
}
if [ -n "$n0" ] && within 5 changed; then
	ok "auto-play: sample $n0, then $(shown_no u) within 5 s"
else
	not_ok "auto-play advances within 5 s" "'$n0' '$(shown_no u)': $(screen u)"
fi
T send-keys -t t:u A
wait_for u 'auto-play paused' 5
n1=$(shown_no u)
sleep 3.5
n2=$(shown_no u)
if [ -n "$n1" ] && [ "$n1" = "$n2" ]; then
	ok "A pauses auto-play: sample $n1 stays"
else
	not_ok "A pauses auto-play" "'$n1' then '$n2'"
fi
T send-keys -t t:u A
n0=$n2
if wait_for u 'auto-play resumed' 5 && within 5 changed; then
	ok "A resumes auto-play: sample $n2, then $(shown_no u)"
else
	not_ok "A resumes auto-play" "'$n2' '$(shown_no u)': $(screen u)"
fi
# Esc closes the browser: the latest accepted sample's load; A opens it
# and plays on
T send-keys -t t:u Escape
wait_for u 'latest mechanism \(sample' 5
n0=$(shown_no u)
T send-keys -t t:u A
if wait_for u 'auto-play resumed' 5 && wait_for u '^sample [0-9]+: ' 5 &&
   within 5 changed; then
	ok "Esc, then A: the browser again, auto-play on (sample $n0, then $(shown_no u))"
else
	not_ok "Esc, then A: the browser again, auto-play on" "'$n0': $(screen u)"
fi
for w in u a; do
	T send-keys -t "t:$w" V
	if wait_for "$w" 'samples +200 / 200' 5 && screen_has "$w" 'characteristic value'; then
		ok "$w: V again: the statistics pane back"
	else
		not_ok "$w: V again: the statistics pane back" "$(screen "$w")"
	fi
	T send-keys -t "t:$w" S	# the browser (opened by V) closed
	wait_for "$w" '^latest mechanism' 5
done

# --- m lights its samples' bins: rows 2..21 hold the panes
lit_u() {	# red bars (the load's colour) in the panes
	T capture-pane -e -p -t t:u | sed -n '2,21p' |
		grep -oE $'\e\\[([0-9]+;)*31m[▁▂▃▄▅▆▇█]' | wc -l
}
lit_a() {	# reverse video in the panes (NO_COLOR)
	T capture-pane -e -p -t t:a | sed -n '2,21p' |
		grep -oE $'\e\\[([0-9]+;)*7m' | wc -l
}
for w in u a; do
	b0=$(lit_$w)
	T send-keys -t "t:$w" m
	wait_for "$w" '^family 1/' 5
	sleep 0.3
	b1=$(lit_$w)
	T send-keys -t "t:$w" M
	wait_for "$w" '^latest mechanism' 5
	sleep 0.3
	b2=$(lit_$w)
	if [ "$b0" -eq 0 ] && [ "$b1" -gt 0 ] && [ "$b2" -eq 0 ]; then
		ok "$w: m lights family 1's bins ($b1 lit), M back: none"
	else
		not_ok "$w: m lights family 1's bins" "before $b0, m $b1, M $b2"
	fi
done
T send-keys -t t:u q
T send-keys -t t:a q
tap_end
