#!/bin/bash
# cli/report.sh - `slipwall report` end to end.
#
# Usage (from the source root): bash tests/cli/report.sh /path/to/slipwall
# Proves: a small run of the demo wall writes every figure in every
# format; every SVG is well-formed XML (python3's parser) whose text
# layer carries the numbers; the p05 and the 99 % interval in report.md
# and on Fig. 10 are those `run --json` prints for the same seed; a
# samples file is read back (and its positions replayed: same loads);
# usage errors exit 2.  TAP output.

bin=${1:?usage: cli/report.sh SLIPWALL}
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
demo=walls/demo.yaml
figs="frequencies densities cumulative single-solutions mechanisms convergence"

printf '# made-up loads, N\n150\n171 # a comment\n\n133\n190\n162\n' >"$tmp/tests.txt"

# ---- a fresh run -----------------------------------------------------------------
out=$("$bin" report $demo -n 100 --seed 3 --threads 2 --tests "$tmp/tests.txt" \
	--out "$tmp/r1" 2>"$tmp/err"); rc=$?
check "report exits 0" test $rc -eq 0
check "it says where the report is" grep -q "r1/report.md: 100 accepted" <<<"$out"
missing=""
for f in $figs; do
	for e in svg pdf png; do
		test -s "$tmp/r1/$f.$e" || missing="$missing $f.$e"
	done
done
if [ -z "$missing" ]; then ok "every figure in every format"; else
	not_ok "every figure in every format" "missing:$missing"; fi

if python3 - "$tmp/r1" $figs >"$tmp/xml" 2>&1 <<'EOF'
import sys, xml.dom.minidom
d = sys.argv[1]
for f in sys.argv[2:]:
    doc = xml.dom.minidom.parse(f"{d}/{f}.svg")
    assert doc.documentElement.tagName == "svg", f
    texts = [t for t in doc.getElementsByTagName("text")]
    assert len(texts) > 10, (f, len(texts))
EOF
then ok "every SVG parses as XML, with a text layer"; else
	not_ok "every SVG parses as XML, with a text layer" "$(cat "$tmp/xml")"; fi

# the same seed through `run --json`: p05 and its interval
"$bin" run $demo -n 100 --seed 3 --threads 1 --json >"$tmp/run.json"
read -r p05 lo hi < <(python3 -c '
import json, sys
j = json.load(open(sys.argv[1]))
print("%.5g %.5g %.5g" % (j["lambda"]["p05"], j["p05_ci99"][0], j["p05_ci99"][1]))' "$tmp/run.json")
check "Table 1 has run's p05 and interval ($p05 [$lo, $hi])" \
	grep -q "| Numerical model | 100 | $p05 N | \[$lo, $hi\] N |" "$tmp/r1/report.md"
check "Fig. 10 prints them too" grep -q \
	">Model p05 = $p05 N, 99 % interval \[$lo, $hi\] N" "$tmp/r1/single-solutions.svg"
std=$("$bin" solve $demo --method standard --json | python3 -c '
import json, sys; print("%.5g" % json.load(sys.stdin)["load_factor"])')
check "Fig. 10 draws the standard solution ($std N)" \
	grep -q ">standard $std N<" "$tmp/r1/single-solutions.svg"
check "global is not run on 28 blocks, and the report says so" \
	grep -q "| global | — | not run: 28 blocks" "$tmp/r1/report.md"
check "the tests file is used (5 loads)" \
	grep -q "| Experimental tests | 5 |" "$tmp/r1/report.md"
check "the command to reproduce it" grep -q \
	"slipwall report walls/demo.yaml -n 100 --seed 3 --tests $tmp/tests.txt --out $tmp/r1" \
	"$tmp/r1/report.md"
check "the version" grep -q "slipwall $("$bin" --version | cut -d' ' -f2)" \
	"$tmp/r1/report.md"

# ---- from a samples file -----------------------------------------------------------
"$bin" run $demo -n 40 --seed 5 --threads 2 --samples "$tmp/s.csv" >/dev/null
"$bin" run $demo -n 40 --seed 5 --threads 2 --json >"$tmp/run40.json"
"$bin" report $demo --samples "$tmp/s.csv" --threads 2 --out "$tmp/r2" >/dev/null 2>"$tmp/err2"
rc=$?
check "report --samples exits 0" test $rc -eq 0
check "the replay gave the file's loads" grep -q "gave the same loads" "$tmp/r2/report.md"
check "without tests: said in report.md" grep -q "No experimental loads" "$tmp/r2/report.md"
nm=$(python3 -c 'import json,sys; print(len(json.load(open(sys.argv[1]))["mechanisms"]))' "$tmp/run40.json")
check "Fig. 6 counts the mechanisms run found ($nm)" \
	grep -q "of $nm distinct in 40 accepted samples)" "$tmp/r2/mechanisms.svg"
check "the seed is not claimed" grep -q "not recorded in the samples file" "$tmp/r2/report.md"

# ---- usage -------------------------------------------------------------------------
"$bin" report $demo >/dev/null 2>&1
check "no --out: exit 2" test $? -eq 2
"$bin" report $demo --samples "$tmp/s.csv" -n 5 --out "$tmp/r3" >/dev/null 2>&1
check "--samples with -n: exit 2" test $? -eq 2
printf '12\nabc\n' >"$tmp/bad.txt"
"$bin" report $demo -n 5 --tests "$tmp/bad.txt" --out "$tmp/r3" >/dev/null 2>"$tmp/err3"
rc=$?
check "a bad tests file: exit 2 with FILE:LINE:COL" \
	bash -c "test $rc -eq 2 && grep -q 'bad.txt:2:1:' '$tmp/err3'"
"$bin" compare $demo -n 5 --tests "$tmp/bad.txt" >/dev/null 2>"$tmp/err4"
check "the same tests file, the same message from compare (one reader)" \
	cmp -s "$tmp/err3" "$tmp/err4"
"$bin" report walls/nope.yaml --out "$tmp/r3" >/dev/null 2>&1
check "a missing wall: exit 2" test $? -eq 2
"$bin" report --help | grep -q "usage: slipwall report"
check "--help" test $? -eq 0

# A slab that slides at mu W in every sample: all loads are equal to
# round-off.  Axis ranges of 1e-13 once made tick steps below one ulp
# and the drawing never ended.
cat >"$tmp/slab.yaml" <<'Y'
material: {friction: 0.6, unit_weight: 19620, thickness: 0.10}
blocks:
  - vertices: [[0, 0], [0.8, 0], [0.8, 0.2], [0, 0.2]]
supports:
  - ground: {y: 0}
loads:
  - point: {at: [0, 0.1], direction: [1, 0]}
Y
timeout 120 "$bin" report "$tmp/slab.yaml" -n 300 --out "$tmp/slab" >/dev/null 2>&1
check "equal loads (a sliding slab): the report is written" \
	bash -c "test -s '$tmp/slab/report.md' && test -s '$tmp/slab/convergence.png'"

# One accepted sample: no spread, so no normal is drawn and no figure or
# table prints "nan" (the legends once said "normal (113.8, nan)")
"$bin" report walls/single-block.yaml -n 1 --out "$tmp/one" >/dev/null 2>&1
grep -q ">model, no normal (one value)<" "$tmp/one/densities.svg" \
	&& ! grep -qiw nan "$tmp/one"/*.svg "$tmp/one/report.md"
check "one accepted sample: 'no normal (one value)' in the densities' legend, no 'nan' in any figure or the report" \
	test $? = 0

tap_end
