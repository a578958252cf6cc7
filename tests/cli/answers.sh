#!/bin/bash
# cli/answers.sh - the "silently wrong answers" of issue 16 through the
# real binary (docs/reliability.md, "Silently wrong answers"): seeds in
# one range written exactly, time limits bounded, a split edge giving
# one interface, friction exact up to its bound, a samples file checked
# against its wall (tests/bad/ holds the walls refused at load time:
# overflows, reserved names, overlaps, friction).  Expected values
# come from the program's own outputs or from closed forms, never from a
# recorded run.
set -u
bin=$1
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
# status_is WANT TEXT COMMAND...: ok when COMMAND exits with WANT (its
# stderr is kept in $tmp/err)
status_is() {
	local want=$1 text=$2 rc
	shift 2
	"$@" >"$tmp/out" 2>"$tmp/err" </dev/null
	rc=$?
	if [ "$rc" = "$want" ]; then
		ok "$text"
	else
		not_ok "$text" "exit $rc, not $want" "$(head -c 600 "$tmp/err")"
	fi
}
# a copy of the single-block wall with another analysis.seed
with_seed() {
	sed "s/^  seed: 1\$/  seed: $1/" walls/single-block.yaml
}

# ---- seeds: one range, 0 .. 2^64-1, written exactly ------------------
max=18446744073709551615
big=9223372036854775813		# 2^63 + 5
with_seed $max >"$tmp/max.yaml"
with_seed $big >"$tmp/big.yaml"
"$bin" check --json "$tmp/max.yaml" >"$tmp/max.json"
"$bin" run "$tmp/big.yaml" -n 3 --json >"$tmp/big.json"
python3 - "$tmp/max.json" "$tmp/big.json" "$max" "$big" <<'PY'
import json, sys
c = json.load(open(sys.argv[1])); r = json.load(open(sys.argv[2]))
assert c["analysis"]["seed"] == int(sys.argv[3]), c["analysis"]["seed"]
assert r["seed"] == int(sys.argv[4]), r["seed"]
PY
check "a wall seed of 2^64-1 and of 2^63+5 is written exactly in JSON" test $? = 0
"$bin" run "$tmp/big.yaml" -n 4 --samples "$tmp/wall-seed.csv" >/dev/null 2>&1
"$bin" run walls/single-block.yaml -n 4 --seed $big \
	--samples "$tmp/cli-seed.csv" >/dev/null 2>"$tmp/err"
check "--seed 2^63+5 gives the samples of a wall seed 2^63+5" \
	cmp -s "$tmp/wall-seed.csv" "$tmp/cli-seed.csv"
"$bin" run walls/single-block.yaml -n 4 --seed $max >/dev/null 2>&1
check "--seed 2^64-1 is accepted" test $? = 0
for s in 18446744073709551616 -1 0x10 " 5" 1e3 ""; do
	status_is 2 "--seed '$s' is refused (exit 2)" \
		"$bin" run walls/single-block.yaml -n 1 --seed "$s"
done
"$bin" report "$tmp/big.yaml" -n 5 --out "$tmp/rep" >/dev/null 2>&1
cmd=$(sed -n 's/^    slipwall report //p' "$tmp/rep/report.md" | head -n 1)
case $cmd in
*"--seed $big "*) ok "report: the command to reproduce carries seed 2^63+5" ;;
*) not_ok "report: the command to reproduce carries seed 2^63+5" "$cmd" ;;
esac
eval "set -- $cmd"
"$bin" report "$@" >/dev/null 2>"$tmp/err"
check "report: the command to reproduce runs (exit 0)" test $? = 0

# ---- --time-limit: GLPK counts int milliseconds ----------------------
for t in 2147484 1e7 1e300 0 -1; do
	status_is 2 "solve --time-limit $t is refused (exit 2)" \
		"$bin" solve walls/single-block.yaml --method global --time-limit $t
	grep -q -- "--time-limit" "$tmp/err" ||
		not_ok "solve --time-limit $t: the message names the option"
done
status_is 2 "report --time-limit 2147484 is refused (exit 2)" \
	"$bin" report walls/single-block.yaml -n 2 --time-limit 2147484 \
	--out "$tmp/rep2"
# the largest limit still solves: tipping about the toe, P = W b / (2 a)
"$bin" solve walls/single-block.yaml --method global --time-limit 1e6 \
	--json >"$tmp/g.json"
python3 - "$tmp/g.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
W = 19620 * 0.4 * 0.8 * 0.1
assert abs(r["load_factor"] - W * 0.4 / (2 * 0.6)) < 1e-6 * W, r["load_factor"]
PY
check "solve --time-limit 1e6 (the bound) still finds P = W b / 2a" test $? = 0

# ---- a vertex in the middle of an edge changes nothing ---------------
# Two stacked blocks, and the same two with vertices in the middle of
# the shared bed (one on each block, at different places, and one list
# starting at such a vertex) and of the bottom block's bed on the
# ground; then a block on a slope of 1:2 with a vertex on its sloping
# edge.  The interfaces (check --json) and the samples (byte for byte)
# must be the same.
plain() {
	cat <<YAML
material: {friction: 0.6, unit_weight: 19620, thickness: 0.1}
blocks:
  - {id: bottom, vertices: $1}
  - {id: top, vertices: $2}
supports:
  - ground: {y: 0}
loads:
  - body: {direction: [1, 0]}
analysis: {samples: 40, seed: 11}
YAML
}
plain "[[0, 0], [0.4, 0], [0.4, 0.2], [0, 0.2]]" \
	"[[0, 0.2], [0.4, 0.2], [0.4, 0.4], [0, 0.4]]" >"$tmp/stack.yaml"
plain "[[0, 0], [0.25, 0], [0.4, 0], [0.4, 0.2], [0.3, 0.2], [0, 0.2]]" \
	"[[0.1, 0.2], [0.4, 0.2], [0.4, 0.4], [0, 0.4], [0, 0.2]]" \
	>"$tmp/stack-split.yaml"
slope() {
	cat <<YAML
material: {friction: 0.6, unit_weight: 19620, thickness: 0.1}
blocks:
  - {id: block, vertices: $1}
supports:
  - {id: slope, vertices: [[0, 0], [1, 0], [1, 0.5]]}
loads:
  - point: {at: [0.5, 0.45], direction: [-1, 0]}
analysis: {samples: 40, seed: 11}
YAML
}
slope "[[0.2, 0.1], [0.8, 0.4], [0.6, 0.8]]" >"$tmp/slope.yaml"
slope "[[0.2, 0.1], [0.3, 0.15], [0.8, 0.4], [0.6, 0.8]]" \
	>"$tmp/slope-split.yaml"
for w in stack slope; do
	"$bin" check --json "$tmp/$w.yaml" >"$tmp/$w.json" 2>"$tmp/err" &&
	"$bin" check --json "$tmp/$w-split.yaml" >"$tmp/$w-split.json" \
		2>>"$tmp/err"
	python3 - "$tmp/$w.json" "$tmp/$w-split.json" <<'PY'
import json, sys
a = json.load(open(sys.argv[1])); b = json.load(open(sys.argv[2]))
assert a["interfaces"] == b["interfaces"], (a["interfaces"], b["interfaces"])
key = lambda d: [(x["id"], x["centroid"], x["area"], x["weight"])
                 for x in d["blocks"]]
assert key(a) == key(b), (key(a), key(b))
assert a["total_weight"] == b["total_weight"]
PY
	check "$w: a vertex in the middle of an edge gives the same interfaces, centroids and weights" test $? = 0
	"$bin" run "$tmp/$w.yaml" --samples "$tmp/$w.csv" >/dev/null 2>&1
	"$bin" run "$tmp/$w-split.yaml" --samples "$tmp/$w-split.csv" \
		>/dev/null 2>&1
	if [ "$(wc -l <"$tmp/$w.csv")" -eq 41 ] &&
		cmp -s "$tmp/$w.csv" "$tmp/$w-split.csv"; then
		ok "$w: ... and the same 40 samples, byte for byte"
	else
		not_ok "$w: ... and the same 40 samples, byte for byte" \
			"$(head -c 300 "$tmp/$w.csv")" \
			"$(head -c 300 "$tmp/$w-split.csv")"
	fi
done

# ---- friction: refused above 1000, exact up to it --------------------
# (tests/bad/friction-*.yaml: the refusal.)  On Ferris & Tin-Loi wall 1
# friction 100 already forbids sliding, so at 1000 (the bound) every
# sample must be accepted with the load of friction 100; before the
# bound existed, 1e5 gave "numerical" samples and wrong loads.
for mu in 100 1000; do
	sed "s/^  friction: 0.65\$/  friction: $mu/" walls/ferris-tinloi-1.yaml \
		>"$tmp/ft-$mu.yaml"
	"$bin" run "$tmp/ft-$mu.yaml" -n 8 --seed 3 --samples "$tmp/ft-$mu.csv" \
		>/dev/null 2>"$tmp/err"
done
python3 - "$tmp/ft-100.csv" "$tmp/ft-1000.csv" <<'PY'
import csv, sys
a = list(csv.DictReader(open(sys.argv[1])))
b = list(csv.DictReader(open(sys.argv[2])))
assert len(a) == len(b) == 8, (len(a), len(b))
for x, y in zip(a, b):
    assert x["status"] == y["status"] == "accepted", (x["status"], y["status"])
    la, lb = float(x["lambda_min"]), float(y["lambda_min"])
    assert abs(la - lb) <= 1e-6 * abs(la), (la, lb)
PY
check "friction 1000 (the bound): every sample accepted, with the loads of friction 100" test $? = 0
sed "s/^  friction: 0.65\$/  friction: 1000.001/" walls/ferris-tinloi-1.yaml \
	>"$tmp/ft-over.yaml"
status_is 2 "friction 1000.001 is refused (exit 2)" "$bin" run "$tmp/ft-over.yaml" -n 1
grep -q "ft-over.yaml:14:13: .*to forbid sliding use friction: 1000" "$tmp/err"
check "... at FILE:LINE:COL, saying what to do instead" test $? = 0

# ---- a samples file belongs to its wall ------------------------------
# run on the two-block stack (2 interfaces) and on the single block (1):
# compare and report take each file with its own wall only
printf '300\n320\n' >"$tmp/tests.txt"
"$bin" run walls/two-block-stack.yaml -n 6 --samples "$tmp/two.csv" >/dev/null 2>&1
"$bin" run walls/single-block.yaml -n 6 --samples "$tmp/one.csv" >/dev/null 2>&1
status_is 0 "compare --samples with the file's own wall: exit 0" \
	"$bin" compare walls/single-block.yaml --samples "$tmp/one.csv" \
	--tests "$tmp/tests.txt"
for pair in "single-block two" "two-block-stack one"; do
	set -- $pair
	status_is 2 "compare --samples: a file of another wall ($2 -> $1) is refused" \
		"$bin" compare walls/$1.yaml --samples "$tmp/$2.csv" \
		--tests "$tmp/tests.txt"
	grep -q "^$tmp/$2.csv:1:[0-9]*: .*another wall" "$tmp/err"
	check "... with FILE:LINE:COL and 'another wall'" test $? = 0
	status_is 2 "report --samples: a file of another wall ($2 -> $1) is refused" \
		"$bin" report walls/$1.yaml --samples "$tmp/$2.csv" \
		--out "$tmp/rep-$2"
done

# ---- the least load that keeps the mechanism is at most the SLP's ---
# (docs/method.md, "One sample", step 5).  LP-min's optimum was above
# lambda_max on 43 % of Ferris & Tin-Loi wall 1's samples, by round-off,
# and on samples 508 and 524 of seed 1 by 8.5e-10 and 3.0e-10 of the
# load (tests/data/ftl1-seed1-s508s524.csv: their draws).
# min_le_max FILE N: true when FILE has N accepted samples, each with
# lambda_min <= lambda_max
min_le_max() {
	python3 - "$1" "$2" <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["status"] == "accepted"]
above = [r["sample"] for r in rows if float(r["lambda_min"]) > float(r["lambda_max"])]
print("# %d accepted, lambda_min above lambda_max on %d: %s" % (len(rows), len(above), " ".join(above[:10])))
sys.exit(not (len(rows) == int(sys.argv[2]) and not above))
PY
}
"$bin" run walls/ferris-tinloi-1.yaml --replay tests/data/ftl1-seed1-s508s524.csv \
	--threads 1 --samples "$tmp/ft508.csv" >/dev/null 2>&1
check "Ferris & Tin-Loi 1, samples 508 and 524 of seed 1: lambda_min <= lambda_max" \
	min_le_max "$tmp/ft508.csv" 2
"$bin" run walls/ferris-tinloi-1.yaml -n 300 --seed 1 --threads 2 \
	--samples "$tmp/ft300.csv" >/dev/null 2>&1
check "Ferris & Tin-Loi 1, 300 samples of seed 1: lambda_min <= lambda_max on every one" \
	min_le_max "$tmp/ft300.csv" 300

# ---- large and small numbers: exact, or refused at the input --------
# (tests/bad/*-overflow.yaml, *-underflow.yaml: the refusals.)  The
# single block (0.4 x 0.8 of its unit, pulled at 0.6) at other scales:
# 1e20 m with a unit weight of 1e250 N/m^3 (weight 3.2e290 N: its moment
# overflowed, "collapses under any load"), 1e-150 m (the centroid
# underflowed to a corner: the block slid at mu W instead of tipping)
# and 1e140 m at 1e-200 N/m^3 (the centroid overflowed).  solve must
# find the tipping load W b / (2 a) = W / 3 and run accept every sample
# below it, with finite statistics.
for case in "1e20 1e250" "1e-150 19620" "1e140 1e-200"; do
	set -- $case
	python3 - "$1" "$2" >"$tmp/scaled.yaml" <<'PY'
import sys
s, g = float(sys.argv[1]), sys.argv[2]
print(f"""material: {{friction: 0.6, unit_weight: {g}, thickness: 0.1}}
blocks:
  - vertices: [[0, 0], [{0.4 * s!r}, 0], [{0.4 * s!r}, {0.8 * s!r}], [0, {0.8 * s!r}]]
supports:
  - ground: {{y: 0}}
loads:
  - point: {{at: [0, {0.6 * s!r}], direction: [1, 0]}}""")
PY
	"$bin" solve "$tmp/scaled.yaml" --method standard --json \
		>"$tmp/scaled.json" 2>"$tmp/err"
	"$bin" run "$tmp/scaled.yaml" -n 5 --json >"$tmp/scaled-run.json" \
		2>>"$tmp/err"
	python3 - "$tmp/scaled.json" "$tmp/scaled-run.json" "$1" "$2" <<'PY'
import json, math, sys
r = json.load(open(sys.argv[1])); m = json.load(open(sys.argv[2]))
s, g = float(sys.argv[3]), float(sys.argv[4])
P = g * 0.1 * (0.4 * s) * (0.8 * s) / 3     # W b / (2 a), b / 2a = 1/3
assert abs(r["load_factor"] / P - 1) < 1e-9, (r["load_factor"], P)
lam = m["lambda"]
assert m["accepted"] == 5, m
assert all(math.isfinite(lam[k]) for k in ("min", "max", "mean", "std")), lam
assert 0 < lam["min"] <= lam["max"] <= P * (1 + 1e-9), (lam, P)
PY
	check "block of $1 m, unit weight $2: solve finds W b / 2a, run accepts 5 samples below it" \
		test $? = 0
done

tap_end
