#!/bin/bash
# tui/tui_edit.sh - the workbench's edits as a user makes them, in tmux:
# undo and redo (u, U, Ctrl-R) give back the wall and its samples (the
# same seed: the same lambda_min column, the same p05), 52 steps deep;
# the modified mark * comes with an edit and goes with undo or a save;
# hjkl move the block cursor like the arrows and never edit; Tab keeps
# the cursor; a removed block of the courses comes back with its id and
# layout edits work after it; a save keeps the layout (layout: with
# omit: for a removed block) and the opened file's comments; a wall
# with a block over a gap says so when it opens.
#
# Usage (from the source root): bash tests/tui/tui_edit.sh /path/to/slipwall
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_edit.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-edit-$$" 100 30

# lambda_min of every sample (accepted or not) of run $1's file
lam_column() {
	cut -d, -f1-4 "$(run_csv "$1")"
}
mu_is() {	# WINDOW MU: the title shows that friction
	title "$1" | grep -qF "μ $2/$2 "
}
# (the name, or after a layout edit the file's name: it has no name
# then, docs/workbench.md, "Edits"), then " * |" when modified
marked() {
	title "$1" | grep -qE ' \* \| '
}

start w LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/clamp-pull.yaml
wait_samples w 1 20
# 30 samples a run: r starts run 2 with that target from sample 0
T send-keys -t t:w n C-u 30 Enter r
if wait_run w 2 done 60; then
	ok "a run of 30 samples"
else
	not_ok "a run of 30 samples" "$(screen w)"
fi
pa=$(p05 w)
if ! marked w; then ok "no modified mark on the opened wall"; else not_ok "no modified mark on the opened wall" "$(title w)"; fi

T send-keys -t t:w f
if wait_run w 3 done 60 && mu_is w 0.65 && marked w && ! title w | grep -q locks; then
	ok "f: friction 0.65, the title marked modified"
else
	not_ok "f: friction 0.65, the title marked modified" "$(title w)"
fi

T send-keys -t t:w u
if wait_run w 4 done 60 && mu_is w 0.6 && ! marked w; then
	ok "u: back to friction 0.6, no modified mark"
else
	not_ok "u: back to friction 0.6, no modified mark" "$(title w)"
fi
pb=$(p05 w)
if [ -n "$pa" ] && [ "$pa" = "$pb" ]; then
	ok "u: the same p05 as before the edit ($pa)"
else
	not_ok "u: the same p05 as before the edit ($pa, $pb)" "$(screen w)"
fi
if [ "$(lam_column 2 | wc -l)" -eq 31 ] && [ "$(lam_column 2)" = "$(lam_column 4)" ]; then
	ok "u: the same 30 samples as before the edit (samples files of runs 2 and 4)"
else
	not_ok "u: the same 30 samples as before the edit" "$(diff <(lam_column 2) <(lam_column 4) | head)"
fi
if [ "$(lam_column 3)" != "$(lam_column 2)" ]; then
	ok "the edited wall's samples differ (runs 2 and 3)"
else
	not_ok "the edited wall's samples differ (runs 2 and 3)"
fi

T send-keys -t t:w U
if wait_run w 5 done 60 && mu_is w 0.65 && marked w; then
	ok "U redoes: friction 0.65, marked"
else
	not_ok "U redoes: friction 0.65, marked" "$(title w)"
fi
T send-keys -t t:w u C-r
if wait_run w 7 '[a-z]+' 60 && mu_is w 0.65; then
	ok "u then Ctrl-R: friction 0.65 again"
else
	not_ok "u then Ctrl-R: friction 0.65 again" "$(title w)"
fi

# 51 more edits (friction 0.65 -> 3.2), then 52 undos back to 0.6
keys=()
for i in $(seq 51); do keys+=(f); done
T send-keys -t t:w "${keys[@]}"
if within 120 mu_is w 3.2; then
	ok "51 edits: friction 3.2"
else
	not_ok "51 edits: friction 3.2" "$(title w)"
fi
# friction 3.2 on bed and head joints locks them under associative
# friction (docs/workbench.md, "Friction that locks"): the title marks
# it and the last edit's message says which joints, as `check` does
if title w | grep -qF "μ 3.2/3.2 locks |" &&
   wait_for w 'warning: friction 3.2 and 3.2 on two joints of block c[0-9]*b[0-9]* that meet at' 10; then
	ok "friction 3.2: the title says locks, the message which joints"
else
	not_ok "friction 3.2: the title says locks, the message which joints" "$(screen w)"
fi
keys=()
for i in $(seq 52); do keys+=(u); done
T send-keys -t t:w "${keys[@]}"
if within 120 mu_is w 0.6 && wait_for w 'undone: .*0 more to undo' 10 && ! marked w &&
   ! title w | grep -q locks; then
	ok "52 undos: friction 0.6, nothing more to undo, not marked, no lock"
else
	not_ok "52 undos: friction 0.6, nothing more to undo, not marked, no lock" "$(screen w)"
fi

# --- the block cursor: hjkl move it, Tab keeps it ---
cursor() {
	screen w | sed -n 's/^\(cursor ([^)]*)\).*/\1/p' | head -n 1
}
r0=$(runno w)
T send-keys -t t:w Tab
wait_for w '^cursor \(' 5
c0=$(cursor)
T send-keys -t t:w l l k
within 5 eval '[ "$(cursor)" != "$c0" ]'
c1=$(cursor)
T send-keys -t t:w h h j
within 5 eval '[ "$(cursor)" = "$c0" ]'
c2=$(cursor)
if [ -n "$c0" ] && [ "$c1" != "$c0" ] && [ "$c2" = "$c0" ] && [ "$(runno w)" = "$r0" ]; then
	ok "hjkl move the block cursor and back, no new run ($c0 -> $c1 -> $c2)"
else
	not_ok "hjkl move the block cursor and back, no new run ($c0 -> $c1 -> $c2, run $r0 -> $(runno w))" "$(screen w)"
fi
T send-keys -t t:w Right Tab
wait_for w '^latest mechanism|^no mechanism|^mechanism|^family' 5
T send-keys -t t:w Tab
wait_for w '^cursor \(' 5
c3=$(cursor)
T send-keys -t t:w Left
within 5 eval '[ "$(cursor)" = "$c0" ]'
if [ "$c3" != "$c0" ] && [ "$(cursor)" = "$c0" ]; then
	ok "Tab off and on keeps the cursor where it was ($c3)"
else
	not_ok "Tab off and on keeps the cursor ($c0, $c3, $(cursor))" "$(screen w)"
fi

# --- remove a block, add it back, then layout edits ---
id=$(screen w | sed -n 's/^cursor ([^)]*): \([a-z0-9]*\) .*/\1/p' | head -n 1)
T send-keys -t t:w x
if [ -n "$id" ] && wait_for w "block $id removed: sampling again" 10 && marked w; then
	ok "x removes block $id"
else
	not_ok "x removes block $id" "$(screen w)"
fi
T send-keys -t t:w a
if wait_for w "block $id restored: sampling again" 10 && wait_for w "^cursor \(.*\): $id " 5; then
	ok "a at the same place restores block $id with its id"
else
	not_ok "a restores block $id with its id" "$(screen w)"
fi
T send-keys -t t:w b
if wait_for w "stack bond: sampling again" 10; then
	ok "b (a layout edit) works after remove and add"
else
	not_ok "b (a layout edit) works after remove and add" "$(screen w)"
fi
T send-keys -t t:w B
if wait_for w "first course starts full: sampling again" 10; then
	ok "B toggles the first course (h no longer does)"
else
	not_ok "B toggles the first course" "$(screen w)"
fi

# --- a save takes the mark away ---
prompt w s 'save wall as' "$tmp/saved.yaml"
if wait_for w "saved .*saved\.yaml" 10 && ! marked w; then
	ok "s saves and the modified mark goes"
else
	not_ok "s saves and the modified mark goes" "$(screen w)"
fi
T send-keys -t t:w f
if within 10 marked w; then
	ok "an edit after the save marks the title again"
else
	not_ok "an edit after the save marks the title again" "$(title w)"
fi

# --- a save keeps the layout, the removed block and short numbers ---
id2=$(screen w | sed -n 's/^cursor ([^)]*): \([a-z0-9]*\) .*/\1/p' | head -n 1)
T send-keys -t t:w x
wait_for w "block $id2 removed: sampling again" 10
prompt w s 'save wall as' "$tmp/saved2.yaml"
wait_for w "saved .*saved2\.yaml" 10
if [ -n "$id2" ] && grep -q '^layout:' "$tmp/saved2.yaml" &&
   grep -q "^  omit: \[\"$id2\"\]" "$tmp/saved2.yaml" &&
   ! grep -q '"c[0-9]*b[0-9]*", vertices' "$tmp/saved2.yaml" &&
   grep -qE '^  friction: (0\.65|\{bed: 0\.65, head: 0\.65\})$' "$tmp/saved2.yaml" &&
   grep -q '^# A clamp pull-out' "$tmp/saved2.yaml"; then
	ok "s writes layout: with omit: [$id2], the edited friction, the file's comments"
else
	not_ok "s writes layout: with omit: [$id2], the edited friction, the file's comments" "$(cat "$tmp/saved2.yaml")"
fi
nb() {	# free blocks of a wall, from check --json
	"$bin" check --json "$1" | python3 -c '
import json, sys
print(sum(1 for b in json.load(sys.stdin)["blocks"] if not b["fixed"]))'
}
n1=$(nb "$tmp/saved.yaml")
n2=$(nb "$tmp/saved2.yaml")
if [ -n "$n1" ] && [ "$n2" -eq $((n1 - 1)) ]; then
	ok "the wall saved after x has one block fewer ($n1 -> $n2)"
else
	not_ok "the wall saved after x has one block fewer ($n1 -> $n2)"
fi
T send-keys -t t:w o
wait_for w 'open wall file:' 5
T send-keys -t t:w -l "$tmp/saved2.yaml"
T send-keys -t t:w Enter
wait_for w "opened .*saved2\.yaml" 10
T send-keys -t t:w b
if wait_for w "(running|stack) bond: sampling again" 10; then
	ok "a layout edit works on the reopened wall"
else
	not_ok "a layout edit works on the reopened wall" "$(screen w)"
fi

# --- v: friction random per joint (docs/method.md), its cov in the title,
# each sample's friction in the run's samples file, undo back to fixed
cov_shown() { title w | grep -qF 'cov 0.2 |'; }
cov_gone() { ! title w | grep -qF ' cov '; }
r0=$(runno w)
prompt w v 'friction cov' 0.2
if within 10 cov_shown; then
	ok "v 0.2: the title shows the friction's cov"
else
	not_ok "v 0.2: the title shows the friction's cov" "$(title w)"
fi
r1=$((r0 + 1))
wait_samples w 1 30
if head -n 1 "$(run_csv "$r1")" 2>/dev/null | grep -q ',mu_1,'; then
	ok "... and run $r1's samples file has each joint's mu"
else
	not_ok "... and run $r1's samples file has each joint's mu" "$(head -c 300 "$(run_csv "$r1")")"
fi
T send-keys -t t:w u
if within 10 cov_gone; then
	ok "u: fixed friction again, no cov in the title"
else
	not_ok "u: fixed friction again, no cov in the title" "$(title w)"
fi
# run r1 has ended (the undo): its history row keeps the cov, on the H
# screen and in history.tsv (its last column, mu_cov)
T send-keys -t t:w H
if wait_for w "/[0-9.]+ cov 0\.2  depth" 5; then
	ok "H: run $r1's row shows the friction's cov"
else
	not_ok "H: run $r1's row shows the friction's cov" "$(screen w)"
fi
T send-keys -t t:w Escape
if awk -F'\t' -v r="$r1" '$2 == r && $NF == "0.20000000000000001" { found = 1 } END { exit !found }' \
	"$SLIPWALL_RUNS/history.tsv"; then
	ok "history.tsv: run $r1's row ends with its mu_cov, 0.2"
else
	not_ok "history.tsv: run $r1's row ends with its mu_cov, 0.2" "$(tail -n 3 "$SLIPWALL_RUNS/history.tsv")"
fi

# a value that changes nothing starts no run: a negative cov is refused,
# the same friction typed again is already the wall's
runof() { title w | sed -n 's/.*| run \([0-9][0-9]*\).*/\1/p'; }
wait_for w '^samples +[0-9]+ / ' 5 || wait_for w 'samples +[0-9]+ / ' 5
r0=$(runof)
prompt w v 'friction cov' -0.2
if [ -n "$r0" ] && wait_for w "friction cov: type a number from 0 to 1" 5 && [ "$(runof)" = "$r0" ]; then
	ok "v -0.2: refused, no new run (run $r0)"
else
	not_ok "v -0.2: refused, no new run (run $r0 -> $(runof))" "$(screen w)"
fi
mu=$(title w | sed -n 's/.*μ \([0-9.]*\).*/\1/p; s/.*mu \([0-9.]*\).*/\1/p' | head -n 1)
prompt w g 'friction' "$mu"
if [ -n "$mu" ] && wait_for w "friction is already bed $mu" 5 && [ "$(runof)" = "$r0" ]; then
	ok "g $mu (the wall's friction): 'already', no new run"
else
	not_ok "g $mu (the wall's friction): 'already', no new run ($r0 -> $(runof))" "$(screen w)" "$(title w)"
fi

T send-keys -t t:w q
wait_for w '^samples: ' 10

# a wall with a block over a gap, as `x` leaves a stack-bond wall: the
# opening's message says which block hangs, as `check` does
# (docs/workbench.md, "Blocks that hang")
start h LANG=C.UTF-8 LC_ALL=C.UTF-8 -- tests/data/stack-gap.yaml
if wait_for h 'warning: block c2b2 rests on no joint below it, and 1 other block only on it: samples may' 20; then
	ok "a block over a gap: the opening's message says it hangs"
else
	not_ok "a block over a gap: the opening's message says it hangs" "$(screen h)"
fi
T send-keys -t t:h q
wait_for h '^samples: ' 10
# jamb blocks half over an opening (tests/data/opening-overhang.yaml):
# the opening's message says they overhang
start o LANG=C.UTF-8 LC_ALL=C.UTF-8 -- tests/data/opening-overhang.yaml
if wait_for o 'warning: block c6b2 overhangs what it rests on' 20; then
	ok "jamb blocks half over an opening: the opening's message says they overhang"
else
	not_ok "jamb blocks half over an opening: the opening's message says they overhang" "$(screen o)"
fi
T send-keys -t t:o q
wait_for o '^samples: ' 10
# both kinds (tests/data/opening-no-lintel.yaml): the message names the
# hanging blocks and the overhanging ones, as `check` warns of each
start b LANG=C.UTF-8 LC_ALL=C.UTF-8 -- tests/data/opening-no-lintel.yaml
if wait_for b 'warning: block c10b2 and 2 others rest on no joint below them' 20 &&
   screen b | tr -d '\n' | grep -q 'only on them; block c6b2 overhangs what it rests on'; then
	ok "blocks over an opening without a lintel, and jamb blocks half over it: the message says both"
else
	not_ok "blocks over an opening without a lintel, and jamb blocks half over it: the message says both" "$(screen b)"
fi
T send-keys -t t:b q
wait_for b '^samples: ' 10
tap_end
