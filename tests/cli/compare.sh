#!/bin/bash
# cli/compare.sh - `slipwall compare` end to end.
#
# Usage (from the source root): bash tests/cli/compare.sh /path/to/slipwall
# Proves: the KS statistic and the three exact p-values on small samples
# with ties equal a brute-force permutation count in exact rational
# arithmetic (python3 fractions, all C(9,4) splits of the pooled data);
# the wall's tests: key and a tests file give the same result; bad input
# and missing tests exit 2 with FILE:LINE:COL; --fit-depth finds the depth
# that made the "tests" (model loads at d = 0.3 with another seed);
# --against: two demo runs (friction 0.6, 0.8) give Δp05, Δp50, Δp95 and
# the KS D that python computes from the CSVs (type 7 percentiles), and
# the run's own p05 of `run --json`; a run against itself D = 0, p = 1;
# --against without --samples, with --tests, or of another wall exit 2.
# TAP output.

bin=${1:?usage: cli/compare.sh SLIPWALL}
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
demo=walls/demo.yaml
# the hand-made samples files below have one interface: the single block's
one=walls/single-block.yaml

# ---- KS against a brute-force permutation test --------------------------------
# model x = {1, 2, 2, 3, 5} (two rejected rows are skipped),
# tests y = {2, 3, 3, 4}: ties inside and across the samples
cat >"$tmp/model.csv" <<'EOF'
sample,status,lambda_max,lambda_min,iterations,xa_1,xb_1
0,accepted,9,1,3,0.1,0.9
1,no_mechanism,9,,3,0.1,0.9
2,accepted,9,2,3,0.1,0.9
3,accepted,9,2,3,0.1,0.9
4,not_converged,,,200,0.1,0.9
5,accepted,9,3,3,0.1,0.9
6,accepted,9,5,3,0.1,0.9
EOF
printf '# experimental loads, N\n2\n3   # two equal loads\n\n  3\n4\n' >"$tmp/tests.txt"
"$bin" compare $one --samples "$tmp/model.csv" --tests "$tmp/tests.txt" \
	--json >"$tmp/ks.json" 2>"$tmp/ks.err"
rc=$?
check "compare --samples --tests --json: exit 0" [ $rc -eq 0 ]
res=$(python3 - "$tmp/ks.json" <<'EOF'
import json, sys
from fractions import Fraction as F
from itertools import combinations
from math import comb
x = [1, 2, 2, 3, 5]
y = [2, 3, 3, 4]
def stats(x, y):
    pts = sorted(set(x + y))
    dp = dm = F(0)
    for t in pts:
        fx = F(sum(v <= t for v in x), len(x))
        fy = F(sum(v <= t for v in y), len(y))
        dp = max(dp, fx - fy)
        dm = max(dm, fy - fx)
    return max(dp, dm), dp, dm
d0, dp0, dm0 = stats(x, y)
z = x + y
cnt = [0, 0, 0]
for idx in combinations(range(len(z)), len(y)):
    yy = [z[i] for i in idx]
    xx = [z[i] for i in range(len(z)) if i not in idx]
    d, dp, dm = stats(xx, yy)
    cnt[0] += d >= d0
    cnt[1] += dp >= dp0
    cnt[2] += dm >= dm0
tot = comb(len(z), len(y))
want = {"statistic": d0, "d_plus": dp0, "d_minus": dm0,
        "p_two_sided": F(cnt[0], tot), "p_greater": F(cnt[1], tot),
        "p_less": F(cnt[2], tot)}
ks = json.load(open(sys.argv[1]))["ks"]
bad = [f"{k}: got {ks[k]!r}, want {float(v)!r} ({v})" for k, v in want.items()
       if abs(ks[k] - float(v)) > 1e-12]
print("; ".join(bad) or "ok " + ", ".join(f"{k} {v}" for k, v in want.items()))
EOF
)
if [ "${res%% *}" = ok ]; then
	ok "KS on x = {1,2,2,3,5}, y = {2,3,3,4} equals the brute-force permutation test: ${res#ok }"
else
	not_ok "KS equals the brute-force permutation test" "$res"
fi
check "model = 5 accepted loads of the file, tests = 4 loads of the file" \
	python3 -c 'import json,sys; d=json.load(open(sys.argv[1]))
sys.exit(not (d["model"]["accepted"]==5 and d["tests"]["n"]==4 and d["tests"]["lambda"]["p50"]==3 and d["tests"]["p05_ci99"] is None))' "$tmp/ks.json"

# one test load: its standard deviation is "-", never "nan"
printf '3\n' >"$tmp/one-test.txt"
"$bin" compare $one --samples "$tmp/model.csv" --tests "$tmp/one-test.txt" \
	>"$tmp/one-test.out" 2>/dev/null
grep -Eq '^std +[0-9.]+ +-$' "$tmp/one-test.out" && ! grep -qi nan "$tmp/one-test.out"
check "compare with one test load: its std is '-' and no 'nan' is printed" test $? = 0
# no accepted model sample (friction 0): the model's column is "-"
printf '100\n120\n' >"$tmp/two-tests.txt"
"$bin" compare $one --friction 0 -n 3 --tests "$tmp/two-tests.txt" \
	>"$tmp/none.out" 2>/dev/null
grep -Eq '^p05 \(characteristic\) +- +101$' "$tmp/none.out" && ! grep -qiw nan "$tmp/none.out"
check "compare with no accepted model sample: '-' in the model's column, no 'nan'" test $? = 0

# the same loads from the wall's tests: key
{ cat $one; printf 'tests:\n  loads: [2, 3, 3, 4]\n'; } >"$tmp/withtests.yaml"
"$bin" compare "$tmp/withtests.yaml" --samples "$tmp/model.csv" --json \
	>"$tmp/ks2.json" 2>/dev/null
check "the wall's tests: key gives the same KS result as the file" \
	python3 -c 'import json,sys; a=json.load(open(sys.argv[1]))["ks"]; b=json.load(open(sys.argv[2]))["ks"]; sys.exit(a!=b)' \
	"$tmp/ks.json" "$tmp/ks2.json"

"$bin" compare $one --samples "$tmp/model.csv" --tests "$tmp/tests.txt" \
	>"$tmp/ks.txt" 2>&1
ok_txt=1
for s in "p05 (characteristic)" "99 % interval" "no interval: needs at least 90 values" \
	"Kolmogorov-Smirnov" "p two-sided" "p greater" "p less"; do
	grep -qF "$s" "$tmp/ks.txt" || ok_txt=0
done
check "Table 1 for people: p05 side by side, 'no interval' under 90 values, the KS p-values" \
	[ $ok_txt = 1 ]
# a byte-order mark at the start of either file (a spreadsheet's UTF-8)
# is read past: the same KS result
printf '\357\273\277' | cat - "$tmp/tests.txt" >"$tmp/tests-bom.txt"
printf '\357\273\277' | cat - "$tmp/model.csv" >"$tmp/model-bom.csv"
"$bin" compare $one --samples "$tmp/model-bom.csv" --tests "$tmp/tests-bom.txt" \
	--json >"$tmp/ksb.json" 2>"$tmp/ksb.err"
check "a byte-order mark before the tests file and the samples file: read, the same KS result" \
	python3 -c 'import json,sys; sys.exit(json.load(open(sys.argv[1]))["ks"] != json.load(open(sys.argv[2]))["ks"])' \
	"$tmp/ks.json" "$tmp/ksb.json"
check "compare --samples without overrides: no warning" \
	eval '! grep -q "warning" "$tmp/ks.err"'

# an override cannot change loads read from a file: it says so, and the
# result is the file's (the same KS result as without it)
"$bin" compare $one --samples "$tmp/model.csv" --tests "$tmp/tests.txt" \
	--friction 0.3 --json >"$tmp/ksf.json" 2>"$tmp/ksf.err"
rc=$?
check "compare --samples --friction: exit 0, a warning that the file's loads do not change, the same KS result" \
	eval '[ $rc = 0 ] && grep -q "^slipwall compare: warning: the loads of .*model.csv are read as they were computed: the overrides (material.friction = 0.3" "$tmp/ksf.err" &&
	python3 -c "import json,sys; sys.exit(json.load(open(sys.argv[1]))[\"ks\"] != json.load(open(sys.argv[2]))[\"ks\"])" "$tmp/ks.json" "$tmp/ksf.json"'

# ---- --against: two runs of the demo wall, friction 0.6 (A) and 0.8 (B) ----
"$bin" run $demo -n 200 --seed 5 --friction 0.6 --samples "$tmp/fa.csv" --json \
	>"$tmp/fa.json" 2>/dev/null
"$bin" run $demo -n 200 --seed 5 --friction 0.8 --samples "$tmp/fb.csv" --json \
	>"$tmp/fb.json" 2>/dev/null
"$bin" compare $demo --samples "$tmp/fa.csv" --against "$tmp/fb.csv" --json \
	>"$tmp/ab.json" 2>"$tmp/ab.err"
rc=$?
check "compare --samples A --against B --json: exit 0" [ $rc -eq 0 ]
res=$(python3 - "$tmp/ab.json" "$tmp/fa.csv" "$tmp/fb.csv" "$tmp/fa.json" \
	"$tmp/fb.json" <<'EOF'
import csv, json, math, sys
d = json.load(open(sys.argv[1]))
scale = d["load"]["scale"]
def loads(path):
    with open(path) as f:
        return sorted(scale * float(r["lambda_min"]) for r in csv.DictReader(f)
                      if r["status"] == "accepted")
def q7(x, p):	# Hyndman & Fan type 7 (docs/statistics.md)
    h = (len(x) - 1) * p
    lo = math.floor(h)
    return x[lo] + (h - lo) * (x[min(lo + 1, len(x) - 1)] - x[lo])
def ks(x, y):	# two-sample D = sup |F_x - F_y| over the pooled values
    import bisect
    return max(abs(bisect.bisect_right(x, t) / len(x) -
                   bisect.bisect_right(y, t) / len(y)) for t in x + y)
a, b = loads(sys.argv[2]), loads(sys.argv[3])
ra, rb = json.load(open(sys.argv[4])), json.load(open(sys.argv[5]))
errs = []
def near(what, got, want, tol=1e-12):
    if got is None or abs(got - want) > tol * max(1, abs(want)):
        errs.append(f"{what}: got {got!r}, want {want!r}")
near("a.accepted", d["a"]["accepted"], len(a))
near("b.accepted", d["b"]["accepted"], len(b))
for k, p in (("p05", .05), ("p50", .5), ("p95", .95)):
    want = q7(b, p) - q7(a, p)
    near(f"difference.{k}.absolute (python)", d["difference"][k]["absolute"], want)
    near(f"difference.{k}.relative_percent", d["difference"][k]["relative_percent"],
         100 * want / q7(a, p))
    near(f"difference.{k} (run --json)", d["difference"][k]["absolute"],
         rb["lambda"][k] - ra["lambda"][k])
near("a.p05_ci99 (run --json)", d["a"]["p05_ci99"][0], ra["p05_ci99"][0])
near("b.p05_ci99 (run --json)", d["b"]["p05_ci99"][1], rb["p05_ci99"][1])
near("ks.statistic", d["ks"]["statistic"], ks(a, b))
if not d["ks"]["exact"]: errs.append("ks not exact")
if not d["difference"]["p05"]["absolute"] > 0: errs.append("more friction, no larger p05?")
if not d["ks"]["p_b_greater"] < 1e-6: errs.append("p(B > A) not small")
print("; ".join(errs) or "ok %.6g %.6g %.4f" % (d["difference"]["p05"]["absolute"],
      q7(b, .05) - q7(a, .05), ks(a, b)))
EOF
)
if [ "${res%% *}" = ok ]; then
	set -- $res
	ok "--against: Δp05 = $2 = p05(B) - p05(A) from the CSVs ($3) and from run --json; Δp50, Δp95, % too; KS D = $4 as python computes it"
else
	not_ok "--against: the differences and KS D equal python's on the CSVs" "$res"
fi
"$bin" compare $demo --samples "$tmp/fa.csv" --against "$tmp/fa.csv" --json \
	>"$tmp/aa.json" 2>/dev/null
check "a run against itself: D = 0, p = 1 (two-sided and both one-sided), differences 0" \
	python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); k=d["ks"]
sys.exit(not (k["statistic"]==0 and k["p_two_sided"]==1 and k["p_b_less"]==1 and k["p_b_greater"]==1 and d["difference"]["p05"]["absolute"]==0))' "$tmp/aa.json"
"$bin" compare $demo --samples "$tmp/fa.csv" --against "$tmp/fb.csv" \
	>"$tmp/ab.txt" 2>&1
ok_txt=1
for s in "p05 (characteristic)" "99 % interval" "B - A" " N (+" \
	"x = B, y = A" "p B < A" "p B > A" "p two-sided"; do
	grep -qF "$s" "$tmp/ab.txt" || ok_txt=0
done
check "--against for people: A, B and B - A side by side, the unit, the KS direction" \
	[ $ok_txt = 1 ]

# ---- bad input --------------------------------------------------------------------
bad() {	# bad DESCRIPTION SUBSTRING ARGS...
	local what=$1 sub=$2
	shift 2
	timeout 120 "$bin" compare "$@" >"$tmp/out" 2>"$tmp/err" </dev/null
	local rc=$?
	if [ $rc -eq 2 ] && grep -qF -- "$sub" "$tmp/err"; then
		ok "refused with exit 2: $what"
	else
		not_ok "refused with exit 2: $what" "exit $rc" \
			"stderr: $(head -c 300 "$tmp/err")"
	fi
}
bad "no tests anywhere" "no experimental loads" $demo -n 5
printf '# empty\n\n' >"$tmp/empty.txt"
bad "a tests file without loads" "holds no load" $demo --tests "$tmp/empty.txt"
printf '100\n  12x\n' >"$tmp/junk.txt"
bad "a word in the tests file (FILE:LINE:COL)" "junk.txt:2:3: a load must be a number" \
	$demo --tests "$tmp/junk.txt"
printf '100\n100 200\n' >"$tmp/two.txt"
bad "two loads on a line" "two.txt:2:5: one load per line" $demo --tests "$tmp/two.txt"
printf '100\n-3\n' >"$tmp/neg.txt"
bad "a negative load" "neg.txt:2:1: a collapse load must be > 0" $demo --tests "$tmp/neg.txt"
printf '100\n0\n' >"$tmp/zero.txt"
bad "a load of 0 (refused in the wall file's tests: loads too)" \
	"zero.txt:2:1: a collapse load must be > 0" $demo --tests "$tmp/zero.txt"
bad "a missing tests file" "cannot open" $demo --tests "$tmp/nope.txt"
bad "--samples with --fit-depth" "do not apply" $demo --tests "$tmp/tests.txt" \
	--samples "$tmp/model.csv" --fit-depth
bad "unknown option" "unknown option" $demo --frobnicate
printf 'sample,status\n' >"$tmp/bad.csv"
bad "a --samples file that is not one" "bad.csv:1:" $demo --tests "$tmp/tests.txt" \
	--samples "$tmp/bad.csv"
# accepted rows whose loads cannot be (slipwall writes lambda_min <= lambda_max)
printf 'sample,status,lambda_max,lambda_min,iterations,xa_1,xb_1\n0,accepted,9,1,3,0.1,0.9\n1,accepted,2,3,3,0.1,0.9\n' \
	>"$tmp/swap.csv"
bad "lambda_min above lambda_max (FILE:LINE:COL)" \
	"swap.csv:3:14: lambda_min is above lambda_max" $one --tests "$tmp/tests.txt" \
	--samples "$tmp/swap.csv"
printf 'sample,status,lambda_max,lambda_min,iterations,xa_1,xb_1\n0,accepted,,1,3,0.1,0.9\n' \
	>"$tmp/nomax.csv"
bad "an accepted row without lambda_max (FILE:LINE:COL)" \
	"nomax.csv:2:12: an accepted sample needs a lambda_max" $one --tests "$tmp/tests.txt" \
	--samples "$tmp/nomax.csv"

bad "--against without --samples" "give the first with --samples" $demo \
	--against "$tmp/fa.csv"
bad "--against with --tests" "give one of them" $demo --samples "$tmp/fa.csv" \
	--against "$tmp/fb.csv" --tests "$tmp/tests.txt"
bad "--against a samples file of another wall (FILE:LINE:COL)" \
	"model.csv:1:48: the file has the contact positions of 1 interfaces" \
	$demo --samples "$tmp/fa.csv" --against "$tmp/model.csv"

# ---- --fit-depth recovers the depth of the "tests" ------------------------------
# tests: 60 model loads of the single block at d = 0.3, seed 99
"$bin" run walls/single-block.yaml -n 60 --seed 99 --depth 0.3 \
	--samples "$tmp/sb.csv" >/dev/null 2>&1
awk -F, 'NR > 1 && $2 == "accepted" { print $4 }' "$tmp/sb.csv" >"$tmp/sb.txt"
"$bin" compare walls/single-block.yaml --tests "$tmp/sb.txt" -n 200 \
	--fit-depth --json >"$tmp/fit.json" 2>"$tmp/fit.err"
rc=$?
res=$(python3 - "$tmp/fit.json" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
f = d["fit_depth"]
prof = f["profile"]
deps = [p["depth"] for p in prof]
errs = []
if deps != sorted(deps): errs.append("profile not sorted by depth")
for g in [round(0.05 * k, 2) for k in range(11)]:
    if not any(abs(g - x) < 1e-9 for x in deps): errs.append(f"grid point {g} missing")
best = min(prof, key=lambda p: (p["ks_statistic"], -p["p_two_sided"], p["depth"]))
if best["depth"] != f["best_depth"]: errs.append(f"best {f['best_depth']} is not the least KS distance ({best['depth']})")
if not abs(f["best_depth"] - 0.3) <= 0.05: errs.append(f"best depth {f['best_depth']}, want 0.3 +- 0.05")
if d["ks"]["statistic"] != best["ks_statistic"]: errs.append("ks is not that of the best depth")
if d["model"]["depth"] != f["best_depth"]: errs.append("model depth")
print("; ".join(errs) or f"ok {f['best_depth']} {best['ks_statistic']:.3f} {len(prof)}")
EOF
)
if [ $rc -eq 0 ] && [ "${res%% *}" = ok ]; then
	set -- $res
	ok "--fit-depth: best d = $2 (tests made at 0.3), KS D = $3, $4 depths, the least D wins"
else
	not_ok "--fit-depth recovers d = 0.3" "exit $rc: $res" "$(head -c 200 "$tmp/fit.err")"
fi

tap_end
