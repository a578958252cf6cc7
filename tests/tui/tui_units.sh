#!/bin/bash
# tui/tui_units.sh - the workbench prints the load people read (docs/
# run.md, "Loads and units"), in tmux: walls/single-block.yaml with its
# point load's magnitude 0.5 at depth 0 tips at P = W b / (2 a) =
# 209.28 N, and the statistics pane shows 209.3 (N) for the run's
# median and for the standard solution, never lambda = 418.56; under a
# body load of magnitude 0.5 the run history gives its p05 as the
# seismic coefficient b/h = 0.5; T on a finished run leaves its speed
# line's threads; c on a wall without a layout says so at once; n below
# the samples done says "30 done (5 asked)"; a run that ended with no
# sample accepted says so instead of waiting; a run whose samples are
# all no_equilibrium names the block that cannot be held, one whose
# samples are all hanging the lowest block that hangs, and one whose
# samples are all nonpositive the block that falls; samples
# finished behind a slow one (walls/facade.yaml) are counted as "M more
# done".
#
# Usage (from the source root): bash tests/tui/tui_units.sh SLIPWALL
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_units.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-units-$$" 140 40

sed -e 's/magnitude: 1}/magnitude: 0.5}/' -e 's/depth: 0.25/depth: 0/' \
	-e 's/^  samples: .*/  samples: 30/' walls/single-block.yaml >"$tmp/half.yaml"
start h LANG=C LC_ALL=C -- "$tmp/half.yaml"
if wait_run h 1 done 60; then
	ok "magnitude 0.5: run 1 done"
else
	not_ok "magnitude 0.5: run 1 done" "$(screen h)"
fi
wait_for h 'standard [0-9]' 30
if screen_has h 'p05 +209\.3 +p50 +209\.3' && screen_has h 'sd +[0-9.e+-]+ +\(N\)' &&
   screen_has h 'standard 209\.3' && ! screen_has h '418\.6'; then
	ok "magnitude 0.5: the pane shows the force, 209.3 N, not lambda"
else
	not_ok "magnitude 0.5: the pane shows the force, 209.3 N, not lambda" "$(screen h)"
fi

# T on a finished run sets the next run's threads: the speed line keeps
# the threads this run had (it said "on 3 threads" for a run on 2)
th=$(screen h | sed -n 's/.*speed .* on \([0-9]*\) thread.*/\1/p; s/.*speed .* s a sample, \([0-9]*\) thread.*/\1/p' | head -n 1)
prompt h T threads 7
if [ -n "$th" ] && wait_for h '7 threads from the next sampling' 5 &&
   screen_has h "speed .*(on $th thread|, $th thread)" && ! screen_has h 'speed .*7 threads'; then
	ok "T 7 on a finished run: the speed line keeps its $th thread(s)"
else
	not_ok "T 7 on a finished run: the speed line keeps its thread count ($th)" "$(screen h)"
fi

# the block is given by its vertices: c (courses) says at once that there
# is no layout to change, not after a prompt of "courses: 0"
T send-keys -t t:h c
if wait_for h 'this wall has no generated layout to change' 5 && ! screen_has h 'courses: '; then
	ok "c on a wall without a layout: said at once, no prompt"
else
	not_ok "c on a wall without a layout: said at once, no prompt" "$(screen h)"
fi

# n below the samples done: the run is done with more than were asked
prompt h n samples 5
if wait_for h 'samples +30 +done \(5 asked\)' 5; then
	ok "n 5 after 30 samples: 'samples 30 done (5 asked)', not '30 / 5'"
else
	not_ok "n 5 after 30 samples: 'samples 30 done (5 asked)'" "$(screen h)"
fi
# friction 0: every sample is rejected; the ended run does not read as
# one still waiting for samples
prompt h g friction 0
if wait_run h 2 done 30 && wait_for h 'no sample accepted \(the rejections' 5 &&
   screen_has h 'no mechanism: no sample accepted' && ! screen_has h 'waiting for'; then
	ok "friction 0, every sample rejected: the ended run says 'no sample accepted', waits for nothing"
else
	not_ok "friction 0: the ended run says 'no sample accepted'" "$(screen h)"
fi

# a body load on the same block (0.4 x 0.8 m, friction 0.6) at depth 0
# tips at a seismic coefficient of b/h = 0.5: the run history's row says
# so, as the statistics pane does (it said "(load factor)")
sed -E 's/^  - point: .*/  - body: {direction: [1, 0], magnitude: 0.5}/' "$tmp/half.yaml" >"$tmp/body.yaml"
start b LANG=C LC_ALL=C -- "$tmp/body.yaml"
wait_run b 1 done 60
T send-keys -t t:b H
wait_for b 'run history' 5
if screen_has b 'p05 0\.5 .*\(seismic coefficient\)' && ! screen_has b '\(load factor\)'; then
	ok "a body load: the run history gives p05 0.5 as a seismic coefficient"
else
	not_ok "a body load: the run history gives p05 0.5 as a seismic coefficient" "$(screen b)"
fi
# a body load's label has a row of its own above the wall: at 80 x 24
# walls/body-100.yaml is drawn coarse, and its label was drawn over the
# top course ("... on every block >.....")
start y LANG=C LC_ALL=C -- walls/body-100.yaml
T resize-window -t t:y -x 80 -y 24
if wait_for y 'body load' 10 && sleep 1 &&
   screen y | grep -E 'body load' | grep -qE 'on every block > +\|' &&
   screen y | grep -A1 -E 'body load' | tail -n 1 | grep -qE '^ +[.]'; then
	ok "a body load's label at 80 x 24: a row of its own, the top course below it"
else
	not_ok "a body load's label at 80 x 24: a row of its own" "$(screen y)"
fi
T send-keys -t t:y q

# pane_names WIN WALL REJECTED NAMED NOT TEXT: the workbench on WALL
# (in window WIN) ends its run, and its statistics pane shows REJECTED
# (the tally's line) and NAMED (the block named, docs/workbench.md;
# docs/method.md, "Which blocks cannot be held"), never NOT (a block
# that stands); one check, TEXT, and the window is left
pane_names() {
	start "$1" LANG=C LC_ALL=C -- "$2"
	if wait_run "$1" 1 done 60 && wait_for "$1" "$4" 5 &&
	   screen_has "$1" "$3" && ! screen_has "$1" "$5"; then
		ok "$6"
	else
		not_ok "$6" "$(screen "$1")"
	fi
	T send-keys -t "t:$1" q
}
# every sample no_equilibrium (tests/data/beyond-pier.yaml, a block
# whose centroid is beyond its pier): the block, not the pier
pane_names c tests/data/beyond-pier.yaml 'no_equilibrium 10' \
	'cannot be held: over \(10\)' 'held: pier' \
	"every sample no_equilibrium: the pane says 'cannot be held: over (10)'"
# every sample `hanging` (tests/data/stack-gap.yaml, a stack-bond wall
# with the middle block of its first course left out): the lowest block
# that hangs, c2b2 over the gap, not c3b2 that rests on it
pane_names g tests/data/stack-gap.yaml 'hanging 5' \
	'lowest hanging block: c2b2 \(5\)' 'c3b2 \(' \
	"every sample hanging: the pane says 'lowest hanging block: c2b2 (5)'"
# every sample `nonpositive` (tests/data/slope.yaml, a block on a slope
# steeper than its friction beside one on the flat): the block on the
# slope, never the one on the flat
pane_names s tests/data/slope.yaml 'nonpositive 4' \
	'falls under any load: slope \(4\)' 'flat \(' \
	"every sample nonpositive: the pane says 'falls under any load: slope (4)'"

# samples finished behind a slow one are shown in order, later: the
# samples line says how many more are done (walls/facade.yaml, seed 1:
# sample 2 takes several times as long as the others, and the line read
# "2 / 20" for seconds beside "left ~0 s")
start f LANG=C LC_ALL=C -- walls/facade.yaml
prompt f n samples 20
if wait_for f 'samples +[0-9]+ / 20 +running, [0-9]+ more done' 90; then
	ok "a slow sample holds the count back: 'samples K / 20 running, M more done'"
else
	not_ok "a slow sample holds the count back: 'K / 20 running, M more done'" "$(screen f)"
fi
# leave them before the directory of their runs is removed
for w in h b f; do
	T send-keys -t t:$w Escape
	T send-keys -t t:$w q
	within 10 gone "$(cat "$tmp/$w.pid")"
done
tap_end
