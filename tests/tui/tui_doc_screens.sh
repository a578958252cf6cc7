#!/bin/bash
# tui/tui_doc_screens.sh - docs/workbench.md's screen excerpts are what
# the workbench draws (issue 27: "Keep its screens from drifting").
# Each excerpt follows a marker `<!-- screen NAME [lines A-B] -->`; this
# test makes every NAME's screen in tmux as the documentation's text
# says it was made, captures it, and compares (tests/tui/doc_screens.py:
# rates, thread counts, times, directories and file time stamps are
# masked).  The screens:
#   demo-100x30      a copy of the demo with samples: 300, done; f (run 2,
#                    done); m
#   demo-80x24       the same, the window made 80x24
#   history-100x36   the same at 100x36, H
#   compare-100x36   then Space, k, Space (runs 2 and 1 compared)
#   quit             then Esc, q: what q prints
#   browser-100x30   LANG=C, the demo with 200 samples, done; S
#   present-80x24    the demo with 200 samples, done; V, A (paused), End
#   joint-80x24      then V, Esc, v 0.2 (run 2, done), S, > six times
#   ferris-80x24     LANG=C, Ferris & Tin-Loi wall 1 with 150 samples, done
#   large-80x24      walls/large.yaml, once a sample has run 3 s
# Every whole screen in the documentation (a block that starts with the
# title line or the history's) must have a marker.  The comparison is
# then shown able to fail: on a copy of the documentation with one
# character of an excerpt changed it must fail and name that excerpt.
#
# SLIPWALL_DOC_SCREENS=update writes the captures into docs/workbench.md
# instead (then check the diff, and the prose around each excerpt).
#
# Usage (from the source root): bash tests/tui/tui_doc_screens.sh SLIPWALL
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_doc_screens.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-docscreens-$$" 100 30
doc=docs/workbench.md
caps=$tmp/caps
mkdir -p "$caps"

# size WIN COLS ROWS: the window resized; waits for a frame drawn for it
size() {
	T resize-window -t "t:$1" -x "$2" -y "$3"
	within 10 frame_at "$1" "$2" "$3"
}
# cap WIN NAME: the screen, once two captures 0.3 s apart agree (the
# once-a-second tick has drawn what the keys did)
cap() {
	local a b i
	for i in $(seq 1 20); do
		sleep 0.3
		a=$(screen "$1")
		sleep 0.3
		b=$(screen "$1")
		[ "$a" = "$b" ] && break
	done
	printf '%s\n' "$b" >"$caps/$2"
}

# the demo, 300 samples, then f and m; then H, the comparison, q
sed -e 's/^  samples: .*/  samples: 300/' walls/demo.yaml >"$tmp/demo.yaml"
SLIPWALL_RUNS=$tmp/runs start d LANG=C.UTF-8 LC_ALL=C.UTF-8 -- "$tmp/demo.yaml"
size d 100 30
wait_run d 1 done 120
T send-keys -t t:d f
wait_run d 2 done 120
T send-keys -t t:d m
wait_for d '^mechanism 1/' 5
cap d demo-100x30
size d 80 24
cap d demo-80x24
size d 100 36
T send-keys -t t:d H
wait_for d '^ run history: ' 5
cap d history-100x36
T send-keys -t t:d Space k Space
wait_for d '^compare: ' 10
cap d compare-100x36
T send-keys -t t:d Escape
wait_for d ' run 2 done' 5
T send-keys -t t:d q
wait_for d '^history: ' 10
# what q printed, from its first line (the pane's history included)
T capture-pane -p -S - -t t:d | sed -n '/^run history (/,/^history: /p' \
	>"$caps/quit"

# the browser, LANG=C
sed -e 's/^  samples: .*/  samples: 200/' walls/demo.yaml >"$tmp/demo200.yaml"
SLIPWALL_RUNS=$tmp/runs-b start b LANG=C LC_ALL=C -- "$tmp/demo200.yaml"
size b 100 30
wait_run b 1 done 120
T send-keys -t t:b S
wait_for b '^sample 200: ' 5
cap b browser-100x30
T send-keys -t t:b q

# the presentation mode, then a joint's friction
SLIPWALL_RUNS=$tmp/runs-p start p LANG=C.UTF-8 LC_ALL=C.UTF-8 -- "$tmp/demo200.yaml"
size p 80 24
wait_run p 1 done 120
T send-keys -t t:p V
wait_for p 'λ_min of sample' 5
T send-keys -t t:p A End
wait_for p 'λ_min of sample 200 ' 5
cap p present-80x24
T send-keys -t t:p V
within 5 last_has p 'q quit'
T send-keys -t t:p Escape
prompt p v 'friction cov \(0\.\.1, 0: fixed\)' 0.2
wait_run p 2 done 120
T send-keys -t t:p S
wait_for p '^sample 200: ' 5
T send-keys -t t:p '>' '>' '>' '>' '>' '>'
wait_for p '^joint 6/' 5
cap p joint-80x24
T send-keys -t t:p q

# Ferris & Tin-Loi wall 1, LANG=C
sed -e 's/^  samples: .*/  samples: 150/' walls/ferris-tinloi-1.yaml >"$tmp/ft1.yaml"
SLIPWALL_RUNS=$tmp/runs-f start f LANG=C LC_ALL=C -- "$tmp/ft1.yaml"
size f 80 24
wait_run f 1 done 180
cap f ferris-80x24
T send-keys -t t:f q

# the large wall, its first seconds
SLIPWALL_RUNS=$tmp/runs-l start l LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/large.yaml
size l 80 24
wait_for l 'oldest ([3-9]|[0-9][0-9]) s' 60
cap l large-80x24
T send-keys -t t:l q

if [ "${SLIPWALL_DOC_SCREENS:-}" = update ]; then
	# the test's directory as a reader's (only the file names count)
	sed -i "s|$tmp/|/tmp/w/|g" "$caps"/*
	python3 tests/tui/doc_screens.py update "$doc" "$caps"
	ok "docs/workbench.md's excerpts written from the captures"
	tap_end
	exit
fi

if out=$(python3 tests/tui/doc_screens.py unmarked "$doc"); then
	ok "every whole screen in $doc has a screen marker"
else
	not_ok "every whole screen in $doc has a screen marker" "$out"
fi
for name in demo-100x30 demo-80x24 history-100x36 compare-100x36 \
	quit browser-100x30 present-80x24 joint-80x24 ferris-80x24 \
	large-80x24; do
	if grep -q "^<!-- screen $name[ >]" "$doc" &&
	   out=$(python3 tests/tui/doc_screens.py check "$doc" "$caps" "$name"); then
		ok "$name: the excerpt is the screen"
	else
		not_ok "$name: the excerpt is the screen" "$out"
	fi
done

# the check can fail: one character of an excerpt changed in a copy
line=$(grep -n '^<!-- screen demo-80x24' "$doc" | cut -d: -f1)
sed "$((line + 3))s/mechanism/mechanisn/; $((line + 3))s/samples /sampels /" \
	"$doc" >"$tmp/changed.md"
if ! cmp -s "$doc" "$tmp/changed.md" &&
   ! out=$(python3 tests/tui/doc_screens.py check "$tmp/changed.md" "$caps") &&
   printf '%s\n' "$out" | grep -q '^differ demo-80x24 ' &&
   ! printf '%s\n' "$out" | grep -q '^differ demo-100x30 '; then
	ok "a changed excerpt fails, named (demo-80x24)"
else
	not_ok "a changed excerpt fails, named (demo-80x24)" "$out"
fi
tap_end
