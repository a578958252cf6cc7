#!/bin/bash
# cli/sweep.sh - `slipwall sweep` end to end (docs/run.md, "Sweeps").
#
# Usage (from the source root): bash tests/cli/sweep.sh /path/to/slipwall
# Proves: a sweep over friction of a single block on the ground pulled
# sideways low down (at 0.1 m: tipping would need P >= W, more than
# mu W for mu <= 0.8) gives p05 = p50 = p95 = mu W at every value, W
# the block's weight from check --json; every point of a sweep is the
# run of the wall with that value (the same seed: the same contact
# draws), so it gives the same statistics as `run --depth D` / `run
# --friction MU` / `run --load-at X,Y`; --csv, --json and --out write
# what they say; bad ranges exit 2; a signal writes the values done.
# TAP output.

bin=${1:?usage: cli/sweep.sh SLIPWALL}
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
block=walls/single-block.yaml

"$bin" check $block --json >"$tmp/check.json"
"$bin" sweep $block --friction 0.3:0.8:0.1 -n 30 --load-at 0,0.1 --json \
	>"$tmp/mu.json" 2>"$tmp/mu.err"
rc=$?
check "sweep --friction: exit 0" [ $rc = 0 ]
check "sweep --friction 0.3:0.8:0.1 on a sliding block: p05 = p50 = p95 = mu W at all 6 values" \
	python3 -c '
import json, sys
w = [b["weight"] for b in json.load(open(sys.argv[1]))["blocks"] if not b["fixed"]]
d = json.load(open(sys.argv[2]))
pts = d["points"]
mus = [0.3, 0.4, 0.5, 0.6, 0.7, 0.8]
ok = len(w) == 1 and len(pts) == len(mus)
for p, mu in zip(pts, mus):
    want = mu * w[0]
    ok = ok and abs(p["value"] - mu) < 1e-12 and p["accepted"] == 30
    for k in ("p05", "p50", "p95"):
        ok = ok and abs(p[k] - want) <= 1e-7 * want
    if not ok:
        print("# mu", mu, "want", want, "got", p)
        break
sys.exit(not ok)' "$tmp/check.json" "$tmp/mu.json"

# every point is the run with that value (common random numbers)
same_as_run() {		# NAME INDEX SWEEPJSON RUN-ARGS...
	local name=$1 idx=$2 sj=$3
	shift 3
	"$bin" run "$@" --json >"$tmp/run.json" 2>/dev/null
	check "$name" python3 -c '
import json, sys
p = json.load(open(sys.argv[1]))["points"][int(sys.argv[3])]
r = json.load(open(sys.argv[2]))
lam = r["lambda"]
ok = p["accepted"] == r["accepted"] and p["mechanisms"] == len(r["mechanisms"])
ok = ok and p["families"] == len(r["families"]) and 1 <= p["families"] <= p["mechanisms"]
ok = ok and all(p[k] == lam[k] for k in ("p05", "p50", "p95"))
if not ok: print("#", p, lam)
sys.exit(not ok)' "$tmp/$sj" "$tmp/run.json" "$idx"
}
"$bin" sweep $block --depth 0.1:0.3:0.1 -n 40 --seed 4 --json >"$tmp/depth.json" 2>/dev/null
same_as_run "sweep --depth: the value 0.2 is run --depth 0.2 (same seed, same draws)" 1 depth.json \
	$block -n 40 --seed 4 --depth 0.2
"$bin" sweep walls/demo.yaml --friction 0.4:0.6:0.1 -n 30 --json >"$tmp/demo.json" 2>/dev/null
same_as_run "sweep --friction on the demo wall: 0.6 is run --friction 0.6" 2 demo.json \
	walls/demo.yaml -n 30 --friction 0.6
"$bin" sweep $block --load-at 0,0.1:0,0.7:4 -n 30 --set analysis.seed=7 \
	--json >"$tmp/at.json" 2>/dev/null
same_as_run "sweep --load-at along a line: the third point (0, 0.5) is run --load-at 0,0.5" 2 at.json \
	$block -n 30 --load-at 0,0.5 --set analysis.seed=7
check "sweep --load-at: 4 points from (0, 0.1) to (0, 0.7), distances 0..0.6" \
	python3 -c '
import json, sys
p = json.load(open(sys.argv[1]))["points"]
ok = len(p) == 4 and p[0]["at"] == [0, 0.1] and abs(p[3]["at"][1] - 0.7) < 1e-12
ok = ok and abs(p[3]["value"] - 0.6) < 1e-12
sys.exit(not ok)' "$tmp/at.json"
# the draws are common: with the load higher, no sample's load rises
# (the same contacts, a longer lever), so the percentiles fall in order
check "sweep --load-at: p05 falls as the load point rises" python3 -c '
import json, sys
p = json.load(open(sys.argv[1]))["points"]
sys.exit(not all(p[i]["p05"] >= p[i + 1]["p05"] for i in range(len(p) - 1)))' "$tmp/at.json"

# ---- the table, --csv, --out --------------------------------------------------
"$bin" sweep $block --friction 0.4:0.6:0.1 -n 100 --load-at 0,0.1 \
	--csv "$tmp/s.csv" --out "$tmp/fig" >"$tmp/table.txt" 2>&1
rc=$?
check "the table: a row per value with accepted, p05, its interval, p50, p95, mechanisms, families" \
	eval '[ $rc = 0 ] && grep -qE "^friction +accepted +p05 +99 % interval of p05 +p50 +p95 +mechanisms +families" "$tmp/table.txt" &&
	      [ "$(grep -cE "^0\.[456] +100 " "$tmp/table.txt")" = 3 ]'
check "--csv: the header and 3 rows" \
	eval '[ "$(head -n 1 "$tmp/s.csv")" = "friction,samples,accepted,p05,p05_lo,p05_hi,p50,p95,mechanisms,families" ] && [ "$(wc -l <"$tmp/s.csv")" = 4 ]'
check "--out: sweep.svg, sweep.pdf, sweep.png, the SVG labelled" \
	eval '[ -s "$tmp/fig/sweep.svg" ] && [ -s "$tmp/fig/sweep.pdf" ] && [ -s "$tmp/fig/sweep.png" ] && grep -q "99 % interval of p05" "$tmp/fig/sweep.svg" && grep -q "friction coefficient" "$tmp/fig/sweep.svg"'

# ---- bad input ----------------------------------------------------------------------
bad() {		# DESCRIPTION ARGS...
	local what=$1
	shift
	"$bin" sweep "$@" >"$tmp/bad.out" 2>"$tmp/bad.err"
	local rc=$?
	if [ $rc = 2 ] && [ -s "$tmp/bad.err" ]; then
		ok "$what: exit 2"
	else
		not_ok "$what: exit 2" "exit $rc" "$(cat "$tmp/bad.err")"
	fi
}
bad "no parameter" $block -n 5
bad "two parameters" $block --friction 0.4:0.6:0.1 --depth 0:0.2:0.1
bad "--friction B < A" $block --friction 0.8:0.4:0.1
bad "--friction a zero step" $block --friction 0.4:0.8:0
bad "--friction 2 fields" $block --friction 0.4:0.8
bad "--depth beyond 0.5" $block --depth 0:0.6:0.1
bad "--load-at N = 1" $block --load-at 0,0.1:0,0.7:1
bad "--load-at a point outside the block" $block --load-at 0,0.1:0,5:3 -n 5
bad "--friction more than 1000 values" $block --friction 0:1:0.0001
# a signal during a sweep (run.h's one policy): the value being run is
# dropped, the values done are written whole (JSON and CSV agree, each
# point has every sample), exit 1 with "interrupted"
"$bin" sweep walls/demo.yaml --friction 0.3:1:0.1 -n 400 --threads 1 --json \
	--csv "$tmp/sig.csv" >"$tmp/sig.json" 2>"$tmp/sig.err" &
pid=$!
sleep 4
kill -TERM "$pid"
wait "$pid"
rc=$?
res=$(python3 -c '
import csv, json, sys
d = json.load(open(sys.argv[1]))
rows = list(csv.DictReader(open(sys.argv[2])))
pts = d["points"]
ok = len(pts) < 8 and len(rows) == len(pts) and all(p["samples"] == 400 for p in pts) \
     and all(int(r["samples"]) == 400 for r in rows)
print("%d of 8 values written" % len(pts))
sys.exit(not ok)' "$tmp/sig.json" "$tmp/sig.csv" 2>&1)
if [ $? -eq 0 ] && [ $rc -eq 1 ] && grep -q "^slipwall sweep: interrupted (Terminated)" "$tmp/sig.err"; then
	ok "SIGTERM during a sweep: exit 1, the values done written whole ($res)"
else
	not_ok "SIGTERM during a sweep: exit 1, the values done written whole" "exit $rc" "$res" "$(cat "$tmp/sig.err")"
fi

# nothing done is lost to a SIGKILL: with --csv FILE each value's row
# goes into FILE.tmp as the value finishes (the old FILE untouched until
# the rename at the end), so a kill leaves every value done, each row as
# the sweep of that value alone writes it
printf 'old,csv\n' >"$tmp/kill.csv"
"$bin" sweep walls/demo.yaml --friction 0.3:1:0.1 -n 100 --threads 1 \
	--csv "$tmp/kill.csv" >/dev/null 2>"$tmp/kill.err" &
pid=$!
for _ in $(seq 600); do
	[ -f "$tmp/kill.csv.tmp" ] && [ "$(wc -l <"$tmp/kill.csv.tmp")" -ge 2 ] && break
	sleep 0.1
done
kill -KILL "$pid" 2>/dev/null
wait "$pid" 2>/dev/null
"$bin" sweep walls/demo.yaml --friction 0.3:0.3:0.1 -n 100 --threads 1 \
	--csv "$tmp/one.csv" >/dev/null 2>&1
if [ "$(cat "$tmp/kill.csv")" = "old,csv" ] && [ -f "$tmp/kill.csv.tmp" ] &&
   rows=$(($(wc -l <"$tmp/kill.csv.tmp") - 1)) && [ "$rows" -ge 1 ] &&
   [ "$rows" -lt 8 ] &&
   [ "$(head -n 2 "$tmp/kill.csv.tmp")" = "$(cat "$tmp/one.csv")" ]; then
	ok "SIGKILL during a sweep: the $rows value(s) done in FILE.tmp, the first row as its own sweep's, the old FILE as it was"
else
	not_ok "SIGKILL during a sweep leaves the values done in FILE.tmp" \
		"$(cat "$tmp/kill.csv")" "$(cat "$tmp/kill.csv.tmp" 2>&1)" \
		"$(cat "$tmp/one.csv")"
fi

# a value with no accepted sample (friction 0: nonpositive) has no load:
# the table shows "-", never "nan"; the CSV keeps nan (docs/run.md)
"$bin" sweep $block --friction 0:0.6:0.3 -n 2 --csv "$tmp/zero.csv" \
	>"$tmp/zero.out" 2>/dev/null
grep -Eq '^0 +0 +- +- \(n < 90\) +- +- +0 +0$' "$tmp/zero.out" \
	&& ! grep -qiw nan "$tmp/zero.out" && grep -q '^0,2,0,nan,' "$tmp/zero.csv"
check "a value with no accepted sample: '-' for p05, p50 and p95 in the table, nan in the CSV" \
	test $? = 0

tap_end
