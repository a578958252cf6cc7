#!/bin/bash
# cli/units.sh - what every writer prints for a collapse load is the
# load people read (docs/run.md, "Loads and units"): the force in N of a
# point load of any magnitude, a seismic coefficient (no unit) for a
# body load, never the LPs' factor lambda under the name of a force.
#
# Usage (from the source root): bash tests/cli/units.sh /path/to/slipwall
# Proves: walls/single-block.yaml with its point load's magnitude 0.5
# or 2, at depth 0, tips at the closed form P = W b / (2 a) = 627.84 *
# 0.4 / (2 * 0.6) = 209.28 N in run (text, --json), its samples file
# (lambda_min times the magnitude), --at (in N), compare (against tests in N),
# report.md, sweep and solve; the same block under a body load of
# magnitude 1 or 2 tips at the seismic coefficient b / (2 h) = 0.5,
# printed without "N"; two point loads of magnitudes 1 and 2 print the
# load factor, no unit.  TAP output.

bin=${1:?usage: cli/units.sh SLIPWALL}
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

jget() {	# jget FILE EXPR: a value of a JSON file (j is the document)
	python3 -c 'import json, sys; j = json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$1" "$2"
}

for m in 0.5 2; do
	w=$tmp/m$m.yaml
	sed -e "s/magnitude: 1}/magnitude: $m}/" -e 's/depth: 0.25/depth: 0/' \
		walls/single-block.yaml >"$w"
	"$bin" run "$w" -n 10 --samples "$tmp/m$m.csv" >"$tmp/run.txt" 2>&1
	check "magnitude $m: run prints the force, 209.28 N" \
		eval "grep -q '^load  *min 209.28  p05 209.28' '$tmp/run.txt' && grep -q '^  *in N, the force' '$tmp/run.txt'"
	"$bin" run "$w" -n 10 --json --at 209.29 >"$tmp/run.json" 2>/dev/null
	check "magnitude $m: run --json: lambda.p05 = 209.28 in load.unit N" \
		eval "near \$(jget '$tmp/run.json' 'j[\"lambda\"][\"p05\"]') 209.28 1e-9 && [ \"\$(jget '$tmp/run.json' 'j[\"load\"][\"unit\"]')\" = N ]"
	check "magnitude $m: --at 209.29 N: every sample collapses" \
		eval "[ \"\$(jget '$tmp/run.json' 'j[\"collapse_probability\"][0][\"probability\"] == 1')\" = True ]"
	check "magnitude $m: the samples file keeps lambda: lambda_min x $m = 209.28" \
		python3 -c '
import csv, sys
r = [float(x["lambda_min"]) for x in csv.DictReader(open(sys.argv[1]))]
sys.exit(not (len(r) == 10 and all(abs(v * float(sys.argv[2]) - 209.28) < 1e-9 for v in r)))' "$tmp/m$m.csv" "$m"
	printf '# loads in N\n205\n209\n215\n' >"$tmp/t.txt"
	"$bin" compare "$w" -n 10 --tests "$tmp/t.txt" --json >"$tmp/cmp.json" 2>/dev/null
	check "magnitude $m: compare: the model's p50 is 209.28 N beside tests in N" \
		eval "near \$(jget '$tmp/cmp.json' 'j[\"model\"][\"lambda\"][\"p50\"]') 209.28 1e-9"
	"$bin" compare "$w" --samples "$tmp/m$m.csv" --tests "$tmp/t.txt" --json >"$tmp/cmp2.json" 2>/dev/null
	check "magnitude $m: compare --samples reads the force from the file's lambda" \
		eval "near \$(jget '$tmp/cmp2.json' 'j[\"model\"][\"lambda\"][\"p50\"]') 209.28 1e-9"
	"$bin" report "$w" -n 10 --tests "$tmp/t.txt" --out "$tmp/rep$m" >/dev/null 2>&1
	check "magnitude $m: report.md: the model's p05 and standard are 209.28 N" \
		eval "grep -q '^| Numerical model | 10 | 209.28 N' '$tmp/rep$m/report.md' && grep -q '^| standard | 209.28 N' '$tmp/rep$m/report.md'"
	"$bin" sweep "$w" --friction 0.6:0.7:0.1 -n 10 --json >"$tmp/sw.json" 2>/dev/null
	check "magnitude $m: sweep: p05 209.28 N at every value" \
		eval "[ \"\$(jget '$tmp/sw.json' 'all(abs(p[\"p05\"] - 209.28) < 1e-9 for p in j[\"points\"])')\" = True ]"
	"$bin" solve "$w" --method standard --json >"$tmp/so.json" 2>/dev/null
	check "magnitude $m: solve: load_newtons 209.28" \
		eval "near \$(jget '$tmp/so.json' 'j[\"load_newtons\"]') 209.28 1e-9"
done

for m in 1 2; do
	w=$tmp/b$m.yaml
	sed -e "s/- point: {at: \[0, 0.6\], direction: \[1, 0\], magnitude: 1}/- body: {direction: [1, 0], magnitude: $m}/" \
		-e 's/depth: 0.25/depth: 0/' walls/single-block.yaml >"$w"
	"$bin" run "$w" -n 10 >"$tmp/b.txt" 2>&1
	check "body load of magnitude $m: the seismic coefficient 0.5, no N" \
		eval "grep -q '^factor  *min 0.5  p05 0.5 ' '$tmp/b.txt' && grep -q '^  *in seismic coefficient, no unit' '$tmp/b.txt' && ! grep -q ' N' '$tmp/b.txt'"
	"$bin" run "$w" -n 10 --json >"$tmp/b.json" 2>/dev/null
	check "body load of magnitude $m: --json: p05 0.5, unit \"\"" \
		eval "near \$(jget '$tmp/b.json' 'j[\"lambda\"][\"p05\"]') 0.5 1e-9 && [ \"\$(jget '$tmp/b.json' 'repr(j[\"load\"][\"unit\"])')\" = \"''\" ]"
	"$bin" report "$w" -n 10 --out "$tmp/brep$m" >/dev/null 2>&1
	check "body load of magnitude $m: report.md: seismic coefficient, no N" \
		eval "grep -q '^Loads: seismic coefficient' '$tmp/brep$m/report.md' && ! grep -q '0.5 N' '$tmp/brep$m/report.md'"
done

# two point loads of magnitudes 1 and 2: no one force, lambda is a factor
sed -e 's/depth: 0.25/depth: 0/' \
	-e 's/^  - point: {at: \[0, 0.6\], direction: \[1, 0\], magnitude: 1}/&\n  - point: {at: [0, 0.3], direction: [1, 0], magnitude: 2}/' \
	walls/single-block.yaml >"$tmp/two.yaml"
"$bin" run "$tmp/two.yaml" -n 5 --json >"$tmp/two.json" 2>/dev/null
"$bin" run "$tmp/two.yaml" -n 5 >"$tmp/two.txt" 2>&1
check "point loads of magnitudes 1 and 2: a load factor, no unit, scale 1" \
	eval "[ \"\$(jget '$tmp/two.json' '(j[\"load\"][\"quantity\"], j[\"load\"][\"unit\"], j[\"load\"][\"scale\"])')\" = \"('load factor', '', 1)\" ] && grep -q '^  *in load factor lambda, no unit' '$tmp/two.txt'"
tap_end
