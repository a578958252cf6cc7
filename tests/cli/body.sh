#!/bin/bash
# cli/body.sh - horizontal body loads (a seismic coefficient: lambda
# times each block's weight).  The closed form of a single block of width
# b and height h on the ground, contact at its corners (depth 0): it
# slides at lambda = mu and tips about its toe at lambda = b / h (the
# load acts at the centroid, h / 2 up, against the weight's lever b / 2),
# so lambda = min(mu, b / h).  And a wall whose mechanisms' joint rates
# are small: the motion threshold never falls below the kinematic LP's
# precision (docs/method.md, "Tolerances"; tests/data/body-195.yaml).
# TAP output.
set -u
bin=$1
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# stack B MU DX DY H1 [H2 ...]: blocks B wide and H1, H2, ... high, one
# on another from the ground up (contact at their corners), friction MU,
# under a body load along (DX, DY)
stack() {
	local b=$1 mu=$2 dx=$3 dy=$4 y=0 i=1 top
	shift 4
	cat <<YAML
name: Blocks on the ground under a body load
material: {friction: $mu, unit_weight: 19620, thickness: 0.10}
blocks:
YAML
	for h in "$@"; do
		top=$(awk -v y="$y" -v h="$h" 'BEGIN { print y + h }')
		printf '  - id: b%d\n    vertices: [[0, %s], [%s, %s], [%s, %s], [0, %s]]\n' \
			"$i" "$y" "$b" "$y" "$b" "$top" "$top"
		y=$top
		i=$((i + 1))
	done
	cat <<YAML
supports:
  - ground: {y: 0}
loads:
  - body: {direction: [$dx, $dy]}
contacts: {depth: 0}
analysis: {samples: 3, seed: 1}
YAML
}
# lam B MU DX DY H1 [H2 ...]: that wall's lambda_min (its run's JSON
# summary's lambda.min), all 3 samples accepted
lam() {
	stack "$@" >"$tmp/b.yaml"
	"$bin" run "$tmp/b.yaml" --threads 1 --json >"$tmp/b.json" 2>"$tmp/err"
	json_field "$tmp/b.json" 'd["lambda"]["min"] if d["accepted"] == 3 else "rejected"'
}
for c in "0.4 0.8 0.6 0.5 tips: b/h" "0.8 0.4 0.6 0.6 slides: mu" \
	 "0.4 0.8 0.4 0.4 slides: mu" "0.3 1.0 0.6 0.3 tips: b/h"; do
	read -r b h mu want why <<<"$c"
	got=$(lam "$b" "$mu" 1 0 "$h")
	check "block ${b} x ${h} m, mu $mu, body load: lambda $got = min(mu, b/h) = $want (${why% *} ${why##* })" \
		near "$got" "$want" 1e-7
done

# An inclined body load, direction (dx, dy) normalised to (cos t, sin t)
# (docs/wall-format.md): lambda W along it on each block.  A stack of
# blocks of width b on the ground, contact at the corners, heights h_i:
# sliding on the ground (or on any bed joint, every block above it
# moving) at lambda cos t = mu (1 - lambda sin t), so lambda = mu /
# (cos t + mu sin t); the blocks from the top down to block i tipping
# about the toe of the joint below them, whose centroid is H/2 above it
# (H their height), at lambda (H/2 cos t + b/2 sin t) = b/2, so
# lambda = b / (H cos t + b sin t) (no tipping where that is <= 0); and
# lambda is the least of them.  The load along -x is the mirror image.
for c in "0.4 0.6 1 -0.3 0.8" "0.4 0.6 2 -0.6 0.8" "0.8 0.6 1 0.2 0.4" \
	 "0.8 0.6 1 -0.5 0.4" "0.8 0.6 -1 0.2 0.4" "0.4 0.6 -1 0.3 0.8" \
	 "0.3 0.8 1 0.4 0.9" "0.4 0.7 1 0 0.3 0.5" "0.4 0.4 1 0 0.3 0.5" \
	 "0.4 0.7 1 -0.2 0.5 0.3" "0.6 0.5 1 0.25 0.3 0.3"; do
	read -ra args <<<"$c"
	got=$(lam "${args[@]}")
	want=$(python3 - "${args[@]}" <<'PY'
import math, sys
b, mu, dx, dy, *hs = map(float, sys.argv[1:])
n = math.hypot(dx, dy)
co, si = abs(dx) / n, dy / n
cands = [mu / (co + mu * si)]
for i in range(len(hs)):
    den = sum(hs[i:]) * co + b * si
    if den > 0:
        cands.append(b / den)
print(min(cands))
PY
)
	read -r b mu dx dy hs <<<"$c"
	what="blocks ${hs// / and } m high, $b m wide, mu $mu"
	check "$what, body load along ($dx, $dy): lambda $got = $want" \
		near "$got" "$want" 1e-9
done

# tests/data/body-195.yaml, seed 1, sample 7 (its positions in
# body-195-seed1-s7.csv): the largest joint rate of its mechanism is 0.02,
# rates of 1e-10 are the kinematic LP's round-off; counted as motion
# they made LP-min infeasible (`numerical`).  Accepted, lambda_min
# 0.424958 (the SLP's lambda_max is 0.4249586: the onset state's load
# can only be below it).
"$bin" run tests/data/body-195.yaml --positions tests/data/body-195-seed1-s7.csv \
	--threads 1 --samples "$tmp/s7.csv" >/dev/null 2>"$tmp/err"
read -r st lmax lmin <<<"$(awk -F, 'NR == 2 { print $2, $3, $4 }' "$tmp/s7.csv")"
check "195-block body-loaded wall, sample 7: accepted ($st)" [ "$st" = accepted ]
check "... lambda_min $lmin: 0.424958, at most lambda_max $lmax" \
	awk -v a="$lmin" -v b="$lmax" 'BEGIN { exit !(a > 0.4249580 && a < 0.4249590 && a <= b + 1e-9) }'

# A wall against a side support as high as itself (a panel built
# against a pier), pushed into it by the body load: no block can move
# along the load without moving into the support or lifting against the
# load's direction, so the load factor has no bound and every sample is
# `unbounded`, a physical verdict.  LP-max's dual simplex ended by
# proving its dual infeasible, which GLPK leaves undecided between
# unbounded and infeasible, and that was read as a solver failure:
# every sample `numerical` (docs/method.md, "Rejection reasons").
# Pushed the other way, off the support, the same wall is answered.
# pier_wall NAME COURSES LENGTH DIR: running bond of 0.2 x 0.1 m blocks,
# friction 0.6, beside a pier 0.3 m wide and 0.3 m high on its right,
# the body load along (DIR, 0)
pier_wall() {
	cat <<YAML
name: $1
material: {friction: 0.6, unit_weight: 20000, thickness: 0.10}
layout: {block: [0.2, 0.1], courses: $2, length: $3, bond: running, first_course: half}
supports:
  - ground: {y: 0}
  - vertices: [[$3, 0], [$(awk -v l="$3" 'BEGIN { print l + 0.3 }'), 0], [$(awk -v l="$3" 'BEGIN { print l + 0.3 }'), 0.3], [$3, 0.3]]
loads:
  - body: {direction: [$4, 0]}
contacts: {depth: 0.25}
analysis: {samples: 10, seed: 1}
YAML
}
pier_wall "A panel against a pier" 3 0.6 1 >"$tmp/into.yaml"
"$bin" run "$tmp/into.yaml" --threads 1 --json >"$tmp/into.json" 2>"$tmp/into.err"
rc=$?
got=$(json_field "$tmp/into.json" 'd["rejected"]["unbounded"]')
check "panel pushed into a pier as high as itself: 10 of 10 samples unbounded ($got), exit 1 ($rc)" \
	eval '[ "$got" = 10 ] && [ $rc = 1 ]'
pier_wall "A panel against a pier" 3 0.6 -1 >"$tmp/off.yaml"
"$bin" run "$tmp/off.yaml" --threads 1 --json >"$tmp/off.json" 2>/dev/null
got=$(json_field "$tmp/off.json" 'd["accepted"]')
check "the same panel pushed off the pier: 10 of 10 samples accepted ($got)" [ "$got" = 10 ]
"$bin" solve "$tmp/into.yaml" --method standard >/dev/null 2>"$tmp/solve.err"
check "solve --method standard on it: says the load is unbounded" \
	grep -q "unbounded" "$tmp/solve.err"

# A wall whose SLP converges below 0: 8 courses, 1.6 m, `positions:
# anywhere`, seed 3, sample 2 (its draw: tests/data/anywhere-8c-seed3-s2.csv).
# LP-max's associative field carries the wall (lambda > 0), but the
# SLP's non-associative fixed point (verified, residual 2e-13) is at
# lambda_max = -0.0356: at these contact points the wall cannot carry its
# own weight once friction does not dilate.  That is `nonpositive`, the
# reason LP-max gives for the same load; it was `numerical`, because
# LP-min (min lambda >= 0 below lambda_max) was infeasible by
# construction (docs/method.md, "Rejection reasons").
cat >"$tmp/anywhere.yaml" <<'YAML'
name: Running bond, contact points anywhere
material: {friction: 0.6, unit_weight: 20000, thickness: 0.10}
layout: {block: [0.2, 0.1], courses: 8, length: 1.6, bond: running, first_course: half}
supports:
  - ground: {y: 0}
loads:
  - body: {direction: [1, 0]}
contacts: {positions: anywhere}
YAML
"$bin" run "$tmp/anywhere.yaml" --replay tests/data/anywhere-8c-seed3-s2.csv \
	--threads 1 --samples "$tmp/any.csv" >/dev/null 2>&1
read -r st lmax <<<"$(awk -F, 'NR == 2 { print $2, $3 }' "$tmp/any.csv")"
check "contact points anywhere, seed 3, sample 2: nonpositive ($st), lambda_max $lmax = -0.0356" \
	awk -v s="$st" -v l="$lmax" 'BEGIN { exit !(s == "nonpositive" && l > -0.03557 && l < -0.03555) }'
# Which block falls: the least help that lets every block stand with
# the SLP's capacities (friction that does not dilate) acts on c7b9, the
# half block at the right end of course 7 (x 1.5-1.6).  Its one bed
# joint (interface 150, from x = 1.6 towards 1.5) has its two contact
# points drawn within 0.0003 m of each other, both left of its centroid
# (x = 1.55): its weight acts beyond the point it rests on, and only its
# neighbours' friction holds it (docs/method.md, "Which blocks cannot be
# held").  The test reads the positions from the draw.
"$bin" run "$tmp/anywhere.yaml" --replay tests/data/anywhere-8c-seed3-s2.csv \
	--threads 1 >"$tmp/any.out" 2>&1
read -r xa xb <<<"$(awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) { if ($i == "xa_150") a = i; if ($i == "xb_150") b = i } }
	NR == 2 { print $a, $b }' "$tmp/any.csv")"
check "the same sample names c7b9, whose bed joint's points ($xa, $xb of the joint from x = 1.6) lie left of its centroid" \
	awk -v a="$xa" -v b="$xb" -v named="$(grep -c 'falls under any load: block c7b9 (1)' "$tmp/any.out")" \
	'BEGIN { exit !(named == 1 && 1.6 - 0.1 * a < 1.55 && 1.6 - 0.1 * b < 1.55) }'

# The same verdict from `solve --method gilbert`, at the classical
# contact (tests/data/nolintel-s45w9.yaml: an opening without a lintel,
# course 8's blocks over it on no joint below).  LP-max carries the wall
# at a positive load; the SLP's fixed point is below 0.  The message
# gives the SLP's load factor, not LP-max's, and names a block that
# rests on no joint (found here from `check --json`: no bed joint has it
# above), which falls once friction does not dilate.
"$bin" solve tests/data/nolintel-s45w9.yaml --method standard --json \
	>"$tmp/nl-std.json" 2>/dev/null
"$bin" solve tests/data/nolintel-s45w9.yaml --method gilbert --json \
	>"$tmp/nl.json" 2>/dev/null
rc=$?
"$bin" check tests/data/nolintel-s45w9.yaml --json >"$tmp/nl-check.json" 2>/dev/null
check "solve gilbert on an opening without a lintel: exit 1 ($rc), nonpositive, the SLP's load factor below 0 in the message, LP-max's above 0, a block on no joint named" \
	python3 - "$tmp/nl.json" "$tmp/nl-std.json" "$tmp/nl-check.json" "$rc" <<'PY'
import json, re, sys
g, s, c = (json.load(open(f)) for f in sys.argv[1:4])
lam = float(re.search(r"sequential LP's load factor is (\S+) ", g['error']).group(1))
carried = {f['b'] for f in c['interfaces'] if f['kind'] == 'bed'}
named = g['unheld_blocks']
print('#', g['status'], lam, s['load_factor'], named, file=sys.stderr)
sys.exit(not (sys.argv[4] == '1' and g['status'] == 'nonpositive' and
              lam < 0 and s['load_factor'] > 0 and named and
              all(b not in carried for b in named)))
PY

# Friction that associative friction turns into a lock (docs/method.md,
# "What the method cannot answer"): a 0.1 m block on the ground beside a
# support, the load away from the support.  It tips at lambda = b/h = 1;
# with bed x head friction >= 1 the associative LP-max has no bound (the
# support's push buys more ground friction than it costs), so every
# sample is `unbounded`.  Every command that loads such a wall warns,
# and one whose joints cannot lock does not.
# corner BED HEAD: the block and its support, friction {bed, head}
corner() {
	cat <<YAML
name: A block beside a support
material: {friction: {bed: $1, head: $2}, unit_weight: 20000, thickness: 0.10}
blocks:
  - id: a
    vertices: [[0.5, 0], [0.6, 0], [0.6, 0.1], [0.5, 0.1]]
supports:
  - ground: {y: 0}
  - vertices: [[0.3, 0], [0.5, 0], [0.5, 0.1], [0.3, 0.1]]
loads:
  - body: {direction: [1, 0]}
contacts: {depth: 0}
analysis: {samples: 3, seed: 1}
YAML
}
for c in "1.5 1.5 yes" "2.0 0.5 yes" "2.0 0.45 no" "0.6 0.6 no"; do
	read -r bed head want <<<"$c"
	corner "$bed" "$head" >"$tmp/corner.yaml"
	"$bin" check "$tmp/corner.yaml" >/dev/null 2>"$tmp/check.err"
	"$bin" run "$tmp/corner.yaml" --threads 1 --json >"$tmp/corner-$bed-$head.json" 2>"$tmp/run.err"
	got=no
	grep -q "warning: .*friction [0-9.]* and [0-9.]* on two joints of block a that meet at (0.5, 0)" "$tmp/check.err" &&
		grep -q "warning: .*associative friction locks them" "$tmp/run.err" && got=yes
	[ -s "$tmp/check.err" ] && [ $got = no ] && got="other: $(head -c 200 "$tmp/check.err")"
	check "friction bed $bed x head $head at a right angle: warning $got (want $want)" [ "$got" = "$want" ]
done
# --json carries the same warning (the loop's runs)
got=$(json_field "$tmp/corner-1.5-1.5.json" 'len(d["warnings"]) == 1 and "associative friction locks them" in d["warnings"][0] and "block a that meet at (0.5, 0)" in d["warnings"][0]')
got2=$(json_field "$tmp/corner-0.6-0.6.json" 'd["warnings"] == []')
check "run --json: warnings has the lock at friction 1.5 ($got), is empty at 0.6 ($got2)" [ "$got $got2" = "True True" ]
# solve's `unbounded` names the lock, not a support, as its reason
corner 1.5 1.5 >"$tmp/corner.yaml"
"$bin" solve "$tmp/corner.yaml" --method standard >/dev/null 2>"$tmp/solve.err"
check "solve --method standard at friction 1.5: unbounded, and says the lock makes it so, not the wall" \
	grep -q "unbounded: friction 1.5 and 1.5 on two joints of block a that meet at (0.5, 0) lock .*not the wall's answer" "$tmp/solve.err"
# What the warning is about (the loop's runs): at friction 1.5 the
# block, which tips at lambda = 1, is `unbounded`; at 0.6 it slides at
# lambda = mu
got=$(json_field "$tmp/corner-1.5-1.5.json" 'd["rejected"]["unbounded"]')
check "friction 1.5: the block that tips at lambda = 1 is unbounded on 3 of 3 samples ($got): the limit the warning names" [ "$got" = 3 ]
got=$(json_field "$tmp/corner-0.6-0.6.json" 'd["lambda"]["min"] if d["accepted"] == 3 else "rejected"')
check "friction 0.6: the same block slides at lambda = mu = 0.6 ($got)" near "$got" 0.6 1e-7
# A wall that must leave a piece before it converges (docs/method.md,
# "The SLP's answer", rule 6, "a phase leaving a piece goes on"): a
# 6-course, 1.0 m running-bond wall beside a pier half its height,
# friction 0.6, seed 1, sample 4 (its draw: tests/data/pier-half-seed1-
# s4.csv).  Its iteration sits on one piece of the map for about 35
# iterations, its load just below mu (the upper courses sliding over the
# pier), while its residual grows 1 % an iteration away from a fixed
# point that is not the map's; it leaves that piece at iteration 104 and
# converges to a rocking-and-sliding state at 0.5994.  The phase of 100
# iterations cut it just before it left, each smaller step drifted the
# same way more slowly, and the sample was `not_converged` from every
# start.  It is accepted now, at `--slp plain`'s load, from three starts.
pier_wall "Running bond beside a pier half its height" 6 1.0 1 >"$tmp/pier.yaml"
# plain_answer NAME WALL REPLAY LO HI: the replayed sample from the LP
# starts auto, slack-primal, crash and support, and by `--slp plain`: all
# five accepted, one lambda_min to 1e-9, and LO < lambda_min < HI
plain_answer() {
	local s
	for s in auto slack-primal crash support; do
		SLIPWALL_LP_START=$s "$bin" run "$2" --replay "$3" \
			--threads 1 --samples "$tmp/$1-$s.csv" >/dev/null 2>&1
	done
	"$bin" run "$2" --replay "$3" --slp plain --threads 1 \
		--samples "$tmp/$1-plain.csv" >/dev/null 2>&1
	one_load --in "$4" "$5" "$tmp/$1"-plain.csv "$tmp/$1"-auto.csv \
		"$tmp/$1"-slack-primal.csv "$tmp/$1"-crash.csv \
		"$tmp/$1"-support.csv
}
check "beside a half-height pier, seed 1, sample 4: accepted from the starts auto, slack-primal, crash, support at --slp plain's lambda_min to 1e-9, below mu" \
	plain_answer pier "$tmp/pier.yaml" tests/data/pier-half-seed1-s4.csv 0.59 0.5999

# A phase cut in the middle of a steady contraction (docs/method.md, "The
# SLP's answer", rule 6, "a second attempt on small walls"): a 7-course,
# 0.6 m running-bond wall beside a pier 0.3 m high on its left, bed
# friction 0.9, head 0.3, depth 0.4, the body load away from the pier;
# seed 1, sample 32 (tests/data/leftpier-seed1-s32.csv).  At iteration
# 100 its residual is 2.0e-3 and halving every iteration, as the plain
# iteration's does until it converges at 113; the phase's end restarted
# it, its smaller steps never settled, and it was `not_converged` from
# every start.  Its second attempt, whose contracting phase goes on (as
# on a large wall), accepts it at `--slp plain`'s load.
cat >"$tmp/leftpier.yaml" <<'YAML'
name: Running bond beside a pier on its left
material: {friction: {bed: 0.9, head: 0.3}, unit_weight: 20000, thickness: 0.10}
layout: {block: [0.2, 0.1], courses: 7, length: 0.6, bond: running, first_course: full}
supports:
  - ground: {y: 0}
  - vertices: [[-0.3, 0], [0, 0], [0, 0.3], [-0.3, 0.3]]
loads:
  - body: {direction: [1, 0]}
contacts: {depth: 0.4}
YAML
check "beside a pier on its left, seed 1, sample 32: accepted from the starts auto, slack-primal, crash, support at --slp plain's lambda_min to 1e-9" \
	plain_answer leftpier "$tmp/leftpier.yaml" tests/data/leftpier-seed1-s32.csv 0.43 0.44
# The long phase on a small wall (docs/method.md, "The SLP's answer",
# rules 7-9 on small walls): the demo wall with random friction (cov
# 0.3), seed 1, sample 380 (tests/data/demo-cov03-seed1-s380.csv, its
# contact points and friction).  From iteration 50 its residual grows
# slowly (2.9e-2 to 3.9e-2 by iteration 115) at a load that no longer
# changes, its classification changing now and then; each phase of rule
# 6 cut it before a piece held, and both attempts left it
# `not_converged` after 2,001 iterations.  The long phase, never cut,
# reaches a piece whose jump verifies at its iteration 117, at `--slp
# plain`'s load.
check "the demo at friction cov 0.3, seed 1, sample 380: accepted from the starts auto, slack-primal, crash, support at --slp plain's lambda_min to 1e-9" \
	plain_answer demo380 walls/demo.yaml tests/data/demo-cov03-seed1-s380.csv 117 118
# The long phase from the slack bases (docs/method.md, "The SLP's
# answer", rules 7-9 on small walls): the demo wall, seed 3, sample 1269
# (tests/data/demo-seed3-s1269.csv), whose first two attempts leave it
# `not_converged`.  From iteration 20 of the long phase its path is on a
# piece whose jump failed, and leaves it slowly; on that piece the
# last-bit differences between two LP starts grow about tenfold in ten
# iterations.  When the long phase started from the bases the start
# option gave, `crash` left the piece at about iteration 140 for
# 346.648 N and every other start at 290 for 125.229 N, `--slp plain`'s
# load.  From the slack bases every start takes one path.
check "the demo, seed 3, sample 1269: accepted from the starts auto, slack-primal, crash, support at --slp plain's lambda_min to 1e-9" \
	plain_answer demo1269 walls/demo.yaml tests/data/demo-seed3-s1269.csv 125 126
# Blocks that hang on friction (docs/method.md, "What the method cannot
# answer: blocks that hang on friction"): a sample whose SLP ends because
# LP1 has no equilibrium, on a wall with blocks that no joint carries
# from below, and whose LP1 has one again once the side joints of those
# blocks get back their capacities at the SLP's start, is `hanging`,
# not `not_converged`.  tests/data/stack-gap.yaml (a 3 x 3 stack-bond
# wall, the middle block of its first course left out): every sample.
# Its running-bond twin has no hanging block: no sample is `hanging`.
"$bin" run tests/data/stack-gap.yaml -n 5 --threads 1 --json \
	--samples "$tmp/gap.csv" >"$tmp/gap.json" 2>/dev/null
check "a block over a gap (stack bond): 5 of 5 samples hanging, in the summary and the samples file" \
	[ "$(json_field "$tmp/gap.json" '(d["rejected"]["hanging"], d["rejected"]["not_converged"], d["accepted"])')" = "(5, 0, 0)" -a \
	  "$(cut -d, -f2 "$tmp/gap.csv" | sed 1d | sort | uniq -c | tr -s ' ')" = " 5 hanging" ]
# Each names the lowest block that hangs (docs/method.md, "Which blocks
# cannot be held"): c2b2, the block over the gap, not c3b2, which rests
# on it; in the summary and its JSON.
"$bin" run tests/data/stack-gap.yaml -n 5 --threads 1 >"$tmp/gap.txt" 2>/dev/null
check "a block over a gap: each hanging sample names c2b2, the lowest block that hangs (summary, JSON)" \
	[ "$(grep -cx '    lowest hanging block: block c2b2 (5)' "$tmp/gap.txt")" = 1 -a \
	  "$(json_field "$tmp/gap.json" 'd["unheld"]["hanging"]')" = "[{'block': 'c2b2', 'count': 5}]" ]
sed 's/bond: stack/bond: running/' tests/data/stack-gap.yaml >"$tmp/gap-running.yaml"
"$bin" run "$tmp/gap-running.yaml" -n 5 --threads 1 --json >"$tmp/gapr.json" 2>/dev/null
check "the same gap in running bond: nothing hangs, 5 of 5 accepted" \
	[ "$(json_field "$tmp/gapr.json" '(d["accepted"], d["rejected"]["hanging"])')" = "(5, 0)" ]
# An opening without a lintel (tests/data/opening-nolintel.yaml, 220
# blocks): some samples keep the clamp and are accepted, the others are
# `hanging`; nothing else, and the same statuses and loads from three
# starts (the verdict is LP1's feasibility, by sws_solve's fixed path).
# clamp_starts WALL NAME [BLOCK...]: 12 samples of WALL from the starts
# auto, slack-primal and support; true when each is accepted or hanging,
# some of each, and the three runs agree on every status and load; with
# BLOCKs, each hanging sample of the first run names one of them (its
# JSON's unheld.hanging).
clamp_starts() {
	local wall=$1 name=$2
	shift 2
	for s in auto slack-primal support; do
		SLIPWALL_LP_START=$s "$bin" run "$wall" -n 12 --threads 2 --json \
			--samples "$tmp/$name-$s.csv" >"$tmp/$name-$s.json" 2>/dev/null
	done
	python3 - "$tmp/$name" "$@" <<'PY'
import csv, json, sys
pre, blocks = sys.argv[1], set(sys.argv[2:])
runs = [[(r["status"], r["lambda_min"]) for r in csv.DictReader(open(pre + "-" + s + ".csv"))]
        for s in ("auto", "slack-primal", "support")]
st = [s for s, _ in runs[0]]
named = json.load(open(pre + "-auto.json"))["unheld"]["hanging"]
print("# statuses:", " ".join(st))
print("# hanging samples name:", " ".join("%s (%d)" % (u["block"], u["count"]) for u in named))
sys.exit(not (len(st) == 12 and set(st) == {"accepted", "hanging"}
              and all(r == runs[0] for r in runs)
              and (not blocks or ({u["block"] for u in named} <= blocks and
                                  sum(u["count"] for u in named) == st.count("hanging")))))
PY
}
check "an opening without a lintel: 12 samples accepted or hanging (some of each), the same statuses and loads from auto, slack-primal and support" \
	clamp_starts tests/data/opening-nolintel.yaml open
# Blocks that overhang an opening (docs/method.md, "Blocks that overhang
# an opening"): tests/data/opening-overhang.yaml has a lintel, but jamb
# blocks half over the void, their weight beyond the contact points they
# rest on at depth 0.45; the samples whose SLP drops the clamp that
# holds them were `not_converged` (3 of 12 at seed 1) and are `hanging`,
# the same statuses and loads from three starts, and each names one of
# the jamb blocks half over the void (c6b2, c8b2, c7b5: the wall file).
check "jamb blocks over an opening with a lintel, depth 0.45: 12 samples accepted or hanging (some of each, none not_converged), the same statuses and loads from auto, slack-primal and support, each hanging sample naming a jamb block half over the void" \
	clamp_starts tests/data/opening-overhang.yaml over c6b2 c8b2 c7b5
# replay_starts WALL DRAWS NAME N: replays the N samples of DRAWS on
# WALL from the starts auto and slack-primal; true when every one is
# `hanging` in both runs.
replay_starts() {
	for s in auto slack-primal; do
		SLIPWALL_LP_START=$s "$bin" run "$1" --replay "$2" --threads 2 \
			--samples "$tmp/$3-$s.csv" >/dev/null 2>&1
	done
	want=$(yes hanging | head -n "$4" | tr '\n' ' ')
	for s in auto slack-primal; do
		got=$(cut -d, -f2 "$tmp/$3-$s.csv" | sed 1d | tr '\n' ' ')
		echo "# $s: $got"
		[ "$got" = "$want" ] || return 1
	done
}
# The clamp's thrust (docs/method.md, "The clamp's loss: sufficient,
# necessary, its weight"): on tests/data/opening-thrust.yaml (an opening
# without a lintel) the SLP of samples 0 and 8 of seed 1 loses, with the
# clamp of the blocks over the opening, a joint on the way of its thrust
# at the wall's end; the clamp's side joints alone do not restore LP1's
# equilibrium, but every other joint given back does not either.  They
# were `not_converged`; they are `hanging`, from two starts.
check "an opening without a lintel, the clamp lost with a joint of its thrust: samples 0 and 8 of seed 1 hanging, from auto and slack-primal" \
	replay_starts tests/data/opening-thrust.yaml \
		tests/data/opening-thrust-seed1-s0s8.csv thrust 2
# The thrust's abutment: on tests/data/opening-abutment.yaml the SLP of
# sample 4 of seed 1 loses the head joint of the top course's end block
# and none of the clamp's joints; with the blocks over the opening
# weightless the wall stands at zero load.  It was `not_converged`; it
# is `hanging`, from two starts.
check "an opening without a lintel, the thrust lost at its abutment: sample 4 of seed 1 hanging, from auto and slack-primal" \
	replay_starts tests/data/opening-abutment.yaml \
		tests/data/opening-abutment-seed1-s4.csv abut 1

# Which blocks cannot be held (docs/method.md): sample 1 of seed 1 of
# tests/data/lintel-jamb.yaml is `no_equilibrium` because jamb block
# c13b3 overhangs its bearing under the lintel.  `run` names it, in text
# and JSON, and the name is checked against the wall itself: given whole
# contact (xi 0 and 1) at c13b3's bed joint (found in `check --json` by
# its bodies) the draw has an equilibrium, and at a joint of another
# block (the first interface) it still has none.
"$bin" run tests/data/lintel-jamb.yaml --replay tests/data/lintel-jamb-seed1-s1.csv \
	--threads 2 >"$tmp/lj.txt" 2>/dev/null
"$bin" run tests/data/lintel-jamb.yaml --replay tests/data/lintel-jamb-seed1-s1.csv \
	--threads 2 --json >"$tmp/lj.json" 2>/dev/null
"$bin" check tests/data/lintel-jamb.yaml --json >"$tmp/lj-check.json" 2>/dev/null
python3 - "$tmp" <<'PY'
import csv, json, sys
tmp = sys.argv[1]
ifaces = json.load(open(tmp + "/lj-check.json"))["interfaces"]
bed = [k for k, f in enumerate(ifaces)
       if f["kind"] == "bed" and f["b"] == "c13b3"]
rows = list(csv.reader(open("tests/data/lintel-jamb-seed1-s1.csv")))
head = rows[0]
for name, k in (("bed", bed[0] if bed else 0), ("other", 0)):
    r = list(rows[1])
    r[head.index("xa_%d" % (k + 1))] = "0"
    r[head.index("xb_%d" % (k + 1))] = "1"
    csv.writer(open("%s/lj-%s.csv" % (tmp, name), "w"),
               lineterminator="\n").writerows([head, r])
sys.exit(len(bed) != 1)
PY
made=$?
for v in bed other; do
	"$bin" run tests/data/lintel-jamb.yaml --replay "$tmp/lj-$v.csv" --threads 1 \
		--samples "$tmp/lj-$v-out.csv" >/dev/null 2>&1
done
j=$(python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(d["rejected"]["no_equilibrium"], " ".join(u["block"] + ":" + str(u["count"]) for u in d["unheld"]["no_equilibrium"]), len(d["unheld"]["unstable"]))' "$tmp/lj.json")
bed=$(sed -n 2p "$tmp/lj-bed-out.csv" | cut -d, -f2)
other=$(sed -n 2p "$tmp/lj-other-out.csv" | cut -d, -f2)
echo "# json: $j; c13b3's bed joint whole: $bed; the first joint whole: $other"
[ "$made" = 0 ] && grep -qx '    cannot be held: block c13b3 (1)' "$tmp/lj.txt" \
	&& [ "$j" = "1 c13b3:1 0" ] && [ "$bed" = accepted ] && [ "$other" = no_equilibrium ]
check "a jamb that overhangs under a lintel: no_equilibrium names block c13b3, in text and JSON; its bed joint given whole contact restores equilibrium, another block's does not" \
	test $? = 0
# A block beyond its pier held up by the live load itself (tests/data/
# beyond-pier.yaml with an upward load on its far end): an equilibrium
# at some load, none at rest, so every sample is `unstable`, and `run`
# names the block that needs the load, never the pier.
sed 's/^  - point: .*/  - point: {at: [0.7, 0.3], direction: [0, 1], magnitude: 1}/' \
	tests/data/beyond-pier.yaml >"$tmp/held-up.yaml"
# named_run NAME WALL STATUS LINE BLOCK: 4 samples of WALL, in text and
# in JSON ($tmp/NAME.txt, .json); true when all 4 are STATUS, the text
# has the line LINE, and the JSON's `unheld` names BLOCK on all 4 under
# STATUS and nothing under each other verdict that names blocks.
named_run() {
	"$bin" run "$2" -n 4 --threads 2 >"$tmp/$1.txt" 2>/dev/null
	"$bin" run "$2" -n 4 --threads 2 --json >"$tmp/$1.json" 2>/dev/null
	grep -qx "    $4" "$tmp/$1.txt" || return 1
	python3 - "$tmp/$1.json" "$3" "$5" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
st, blk = sys.argv[2], sys.argv[3]
want = {k: [] for k in ("no_equilibrium", "nonpositive", "unstable",
                        "hanging")}
want[st] = [{"block": blk, "count": 4}]
print("# json: rejected %s %s, unheld %s" % (st, d["rejected"][st],
                                             d["unheld"]))
sys.exit(not (d["rejected"][st] == 4 and d["unheld"] == want))
PY
}
check "a block held up by its own load: 4 unstable, 'stands only under load: block over (4)' in text and JSON" \
	named_run held-up "$tmp/held-up.yaml" unstable \
	'stands only under load: block over (4)' over
# and `solve` names it too, with what it needs
"$bin" solve "$tmp/held-up.yaml" --method standard --json >"$tmp/held-up-solve.json" 2>/dev/null
check "solve on the block held up by its own load: unstable, 'over' named, 'without the live load'" \
	python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); sys.exit(not (d["status"] == "unstable" and d["unheld_blocks"] == ["over"] and d["error"].endswith("stand without the live load acts on block over")))' "$tmp/held-up-solve.json"
# A block on a slope steeper than its friction beside one on the flat
# (tests/data/slope.yaml): LP-max's largest load factor is below 0 on
# every sample, and `run` names the block that falls under any load in
# the load's direction, never the one that stands
check "a block on a slope steeper than its friction: 4 nonpositive, 'falls under any load: block slope (4)' in text and JSON" \
	named_run slope tests/data/slope.yaml nonpositive \
	'falls under any load: block slope (4)' slope
# The same block alone at friction 0.9: it stands, and slides down the
# slope at (mu - t) / (1 + mu t) = 0.0581395 under the load along +x,
# up it at (mu + t) / (1 - mu t) = 6.07143 along -x; at depth 0.25 its
# contact points move along its joint, and a sliding block's load does
# not move with them: every sample has it, to 1e-9 (tests/unit/
# test_solve.c has the single solutions, tipping among them)
sed -e '/id: flat/d' -e 's/friction: 0.6/friction: 0.9/' tests/data/slope.yaml \
	>"$tmp/slope-down.yaml"
sed 's/direction: \[1, 0\]/direction: [-1, 0]/' "$tmp/slope-down.yaml" \
	>"$tmp/slope-up.yaml"
# slides_at WALL MU T UP: 6 samples of WALL, each accepted at the closed
# form (UP 0: down the slope; 1: up it) to 1e-9, its one joint sliding
# in every sample (the JSON's one mechanism, "s")
slides_at() {
	"$bin" run "$1" -n 6 --threads 2 --samples "$1.csv" --json \
		>"$1.json" 2>/dev/null || return 1
	python3 - "$1" "$2" "$3" "$4" <<'PY'
import csv, json, sys
wall, mu, t, up = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), \
    sys.argv[4] == "1"
want = (mu + t) / (1 - mu * t) if up else (mu - t) / (1 + mu * t)
rows = list(csv.DictReader(open(wall + ".csv")))
got = [(r["status"], float(r["lambda_min"] or "nan")) for r in rows]
mech = [(m["joints"], m["count"])
        for m in json.load(open(wall + ".json"))["mechanisms"]]
print("# %s: want %.15g, got %s, mechanisms %s"
      % (wall.rsplit("/", 1)[-1], want, got, mech))
sys.exit(not (len(rows) == 6 and mech == [("s", 6)] and
              all(st == "accepted" and abs(v - want) <= 1e-9 * max(1, want)
                  for st, v in got)))
PY
}
check "a block on a slope, friction 0.9 > tan 0.8: every sample slides down it at (mu - t)/(1 + mu t) = 0.0581395" \
	slides_at "$tmp/slope-down.yaml" 0.9 0.8 0
check "... and up it, the load reversed, at (mu + t)/(1 - mu t) = 6.07143" \
	slides_at "$tmp/slope-up.yaml" 0.9 0.8 1
# and `report`'s table has a row for it (its first two samples, seed 1)
"$bin" report tests/data/lintel-jamb.yaml -n 2 --seed 1 --threads 2 \
	--out "$tmp/lj-report" >/dev/null 2>&1
check "report: a row 'cannot be held (no_equilibrium) | block c13b3 in 1 sample'" \
	grep -qx '| cannot be held (no_equilibrium) | block c13b3 in 1 sample |' "$tmp/lj-report/report.md"
# and one for a hanging sample: tests/data/opening-overhang.yaml's first
# three samples (seed 1), the third hanging with jamb block c6b2 (a
# report needs an accepted sample: stack-gap.yaml has none)
"$bin" report tests/data/opening-overhang.yaml -n 3 --seed 1 --threads 2 \
	--out "$tmp/over-report" >/dev/null 2>&1
check "report: a row 'lowest hanging block (hanging) | block c6b2 in 1 sample'" \
	grep -qx '| lowest hanging block (hanging) | block c6b2 in 1 sample |' "$tmp/over-report/report.md"

# The piece jump on a wall of hundreds of interfaces (docs/method.md,
# "The SLP's answer", rule 2): below a residual of 2e-4 the joints'
# classification leaves out each interface's side of its capacity, which
# on tests/data/body-195.yaml (543 interfaces) changed at nearly every
# iteration as the residuals N_k - c_k crossed 1e-9 one by one, so no
# jump came and `--slp piece` ran as many iterations as `--slp plain`
# (73 a sample).  Now every sample jumps to its piece's fixed point, at
# the plain iteration's load.
for v in piece plain; do
	"$bin" run tests/data/body-195.yaml -n 4 --seed 1 --threads 2 --slp $v \
		--samples "$tmp/b195-$v.csv" >/dev/null 2>&1
done
python3 - "$tmp"/b195-piece.csv "$tmp"/b195-plain.csv <<'PY'
import csv, sys
piece, plain = ([r for r in csv.DictReader(open(f))] for f in sys.argv[1:])
for a, b in zip(piece, plain):
    print("#   sample", a["sample"], a["status"], a["lambda_min"], a["iterations"],
          "iterations; plain", b["status"], b["lambda_min"], b["iterations"])
sys.exit(not (len(piece) == len(plain) == 4 and all(
    a["status"] == b["status"] == "accepted"
    and abs(float(a["lambda_min"]) - float(b["lambda_min"])) <= 1e-9 * float(b["lambda_min"])
    and int(a["iterations"]) + 10 < int(b["iterations"])
    for a, b in zip(piece, plain))))
PY
check "body-195, 4 samples: the piece path jumps (10 or more iterations fewer than --slp plain on each) and keeps --slp plain's lambda_min to 1e-9" \
	[ $? = 0 ]

tap_end
