#!/bin/bash
# cli/friction.sh - friction as a random variable per joint
# (docs/method.md, "Friction as a random variable"): a sample's draw
# holds each joint's friction, lognormal with the file's mean and cov.
#  - A flat block pulled at its base slides at P = mu W (it cannot tip:
#    b / (2a) = 4 >> mu): every accepted sample's load is its own joint's
#    drawn mu times W, and over 4,000 samples the load's mean is within
#    2 % of mu W and its coefficient of variation within 0.18..0.22.
#  - The draw is the sample's: the same with 1 and 2 threads and from
#    another LP start; replayed from the samples file (its mu_k columns);
#    cov 0 is fixed friction, byte for byte.
#  - --friction sets the mean and keeps the cov; --cov and sweep --cov.
#  - A bad cov is refused at its FILE:LINE:COLUMN, exit status 2.
# TAP output.
set -u
bin=$1
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# flat COV: a block 1.0 m wide and 0.25 m high (W = 500 N) on the
# ground, pulled at mid-height of its left face
flat() {
	cat <<YAML
name: flat block, random friction
material:
  friction: {bed: 0.6, head: 0.6, cov: $1}
  unit_weight: 20000
  thickness: 0.1
blocks:
  - id: A
    vertices: [[0, 0], [1.0, 0], [1.0, 0.25], [0, 0.25]]
supports:
  - ground: {y: 0}
loads:
  - point: {at: [0, 0.125], direction: [1, 0], magnitude: 1}
contacts: {depth: 0.25}
analysis: {samples: 4000, seed: 1}
YAML
}
flat 0.2 >"$tmp/flat.yaml"
"$bin" run "$tmp/flat.yaml" --threads 2 --samples "$tmp/flat.csv" \
	--json >"$tmp/flat.json" 2>"$tmp/err"
# the per-sample closed form, then the distribution
out=$(python3 - "$tmp/flat.csv" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
W = 500.0
lam = [float(r["lambda_min"]) for r in rows if r["status"] == "accepted"]
bad = sum(1 for r in rows if r["status"] == "accepted" and
          abs(float(r["lambda_min"]) - float(r["mu_1"]) * W) >
          1e-9 * float(r["mu_1"]) * W)
mean = statistics.mean(lam)
print(len(rows), len(lam), bad, mean / (0.6 * W), statistics.stdev(lam) / mean)
PY
)
read -r nrows nacc nbad ratio cv <<<"${out:-x x x x x}"
check "4,000 samples, all accepted ($nacc of $nrows)" \
	test "$nrows" = 4000 -a "$nacc" = 4000
check "each sample slides at its own mu W (to 1e-9; $nbad differ)" \
	test "$nbad" = 0
check "mean load within 2 % of mu W (ratio $ratio)" near "$ratio" 1 0.02
check "coefficient of variation of the load 0.18..0.22 ($cv)" \
	python3 -c "import sys; sys.exit(not 0.18 <= $cv <= 0.22)"
check "run --json states the friction's cov" \
	test "$(json_field "$tmp/flat.json" 'd["friction"]["cov"]')" = 0.2

# the draw is the sample's: threads, LP start, replay
"$bin" run walls/demo.yaml -n 40 --seed 3 --cov 0.2 --threads 1 \
	--samples "$tmp/t1.csv" >/dev/null 2>&1
"$bin" run walls/demo.yaml -n 40 --seed 3 --cov 0.2 --threads 2 \
	--samples "$tmp/t2.csv" >/dev/null 2>&1
check "demo, cov 0.2: 1 and 2 threads write the same samples file" \
	cmp -s "$tmp/t1.csv" "$tmp/t2.csv"
check "... whose rows carry each joint's mu (mu_1 .. mu_66)" \
	bash -c "head -1 '$tmp/t1.csv' | grep -q ',mu_1,.*,mu_66\$'"
SLIPWALL_LP_START=slack-dual "$bin" run walls/demo.yaml -n 40 --seed 3 \
	--cov 0.2 --threads 2 --samples "$tmp/t3.csv" >/dev/null 2>&1
check "... and from the slack-dual LP start: status and lambda_min to 1e-9" \
	python3 - "$tmp/t1.csv" "$tmp/t3.csv" <<'PY'
import csv, sys
a = list(csv.DictReader(open(sys.argv[1])))
b = list(csv.DictReader(open(sys.argv[2])))
def same(x, y):
    if x["status"] != y["status"]:
        return False
    if x["status"] != "accepted":
        return True
    p, q = float(x["lambda_min"]), float(y["lambda_min"])
    return abs(p - q) <= 1e-9 * max(1, abs(p))
sys.exit(not (len(a) == 40 and len(a) == len(b) and all(map(same, a, b))))
PY
"$bin" run walls/demo.yaml --cov 0.2 --replay "$tmp/t1.csv" \
	--threads 2 --samples "$tmp/r.csv" >/dev/null 2>&1
check "a replay of the samples file (positions and friction) recomputes it" \
	cmp -s "$tmp/t1.csv" "$tmp/r.csv"
"$bin" run walls/demo.yaml -n 5 --seed 3 --samples "$tmp/fixed.csv" \
	>/dev/null 2>&1
"$bin" run walls/demo.yaml --cov 0.2 --positions "$tmp/fixed.csv" \
	>"$tmp/out" 2>"$tmp/err"
st=$?
check "a file without frictions is refused for a random-friction wall (exit $st)" \
	bash -c "[ $st = 2 ] && grep -q 'fixed.csv:1:1: .*no friction columns' '$tmp/err'"
"$bin" run walls/demo.yaml -n 5 --seed 3 --cov 0 --samples "$tmp/cov0.csv" \
	>/dev/null 2>&1
check "cov 0 is fixed friction: the same samples file, byte for byte" \
	cmp -s "$tmp/fixed.csv" "$tmp/cov0.csv"
check "cov 0: the positions are those of the random-friction run" \
	bash -c "cut -d, -f6-137 '$tmp/cov0.csv' | head -6 | tail -5 > '$tmp/p0'; cut -d, -f6-137 '$tmp/t1.csv' | head -6 | tail -5 > '$tmp/p1'; cmp -s '$tmp/p0' '$tmp/p1'"

# --friction sets the mean, the cov stays
"$bin" run "$tmp/flat.yaml" -n 2000 --friction 0.4 --threads 2 \
	--samples "$tmp/f4.csv" --json >"$tmp/f4.json" 2>/dev/null
m=$(python3 -c "
import csv, statistics, sys
mu = [float(r['mu_1']) for r in csv.DictReader(open('$tmp/f4.csv'))]
print(statistics.mean(mu), statistics.stdev(mu) / statistics.mean(mu))" 2>/dev/null)
read -r mmean mcv <<<"${m:-x x}"
check "--friction 0.4 on a cov 0.2 wall: mean mu $mmean (0.4 +- 2 %), cov $mcv" \
	bash -c "python3 -c 'import sys; sys.exit(not (abs($mmean / 0.4 - 1) <= 0.02 and 0.18 <= $mcv <= 0.22))'"
# --set material.friction.cov on a file that writes friction as one number
"$bin" run walls/single-block.yaml -n 3 --set material.friction.cov=0.1 \
	--samples "$tmp/s.csv" >/dev/null 2>&1
check "--set material.friction.cov=0.1 where friction is one number" \
	bash -c "head -1 '$tmp/s.csv' | grep -q ',mu_1\$'"
# sweep --cov
"$bin" sweep "$tmp/flat.yaml" --cov 0:0.2:0.1 -n 400 --json \
	>"$tmp/sw.json" 2>"$tmp/err"
check "sweep --cov 0:0.2:0.1: three values, the spread grows with the cov" \
	test "$(json_field "$tmp/sw.json" 'len(d["points"]) == 3 and d["points"][0]["p05"] > d["points"][2]["p05"]')" = True

# a bad cov
for bad in "-0.1" "1.5" "x"; do
	flat "$bad" >"$tmp/bad.yaml"
	"$bin" check "$tmp/bad.yaml" >"$tmp/out" 2>"$tmp/err"
	st=$?
	check "cov: $bad refused at its place, exit 2 ($(head -c 120 "$tmp/err"))" \
		bash -c "[ $st = 2 ] && grep -q '^$tmp/bad.yaml:3:[0-9]*: friction' '$tmp/err'"
done
tap_end
