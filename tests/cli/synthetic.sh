#!/bin/bash
# cli/synthetic.sh - which loads files compare and report call synthetic
# (docs/run.md): those with the marker line "# slipwall: synthetic", and
# no others.
#
# Usage (from the source root): bash tests/cli/synthetic.sh /path/to/slipwall
# Proves: walls/demo-loads.txt (which has the marker) is labelled by
# compare (text and tests.synthetic in --json) and report (stdout and
# report.md); a file of real loads whose comment says "these are real
# measurements, not synthetic" is labelled by neither; the marker with
# other blanks counts; the marker words inside a longer comment do not.
# TAP output.

bin=${1:?usage: cli/synthetic.sh SLIPWALL}
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
demo=walls/demo.yaml
loads=$(grep -v '^#' walls/demo-loads.txt)

synthetic() {	# synthetic FILE: compare --json's tests.synthetic
	"$bin" compare $demo -n 20 --tests "$1" --json 2>/dev/null |
		python3 -c 'import json, sys; print(json.load(sys.stdin)["tests"]["synthetic"])'
}

check "walls/demo-loads.txt: synthetic (its marker line)" \
	[ "$(synthetic walls/demo-loads.txt)" = True ]
"$bin" compare $demo -n 20 --tests walls/demo-loads.txt >"$tmp/c.txt" 2>&1
check "... and compare's text says so" grep -q "(SYNTHETIC: " "$tmp/c.txt"

{ echo "# Collapse loads of the 33 tests of the demo wall's twin, N: these"
  echo "# are real measurements (2019), not synthetic ones."
  echo "$loads"; } >"$tmp/real.txt"
check "real loads whose comment says 'not synthetic': not synthetic" \
	[ "$(synthetic "$tmp/real.txt")" = False ]
"$bin" compare $demo -n 20 --tests "$tmp/real.txt" >"$tmp/r.txt" 2>&1
check "... and compare's text does not say SYNTHETIC" eval "! grep -qi synthetic '$tmp/r.txt'"
"$bin" report $demo -n 20 --tests "$tmp/real.txt" --out "$tmp/rep" >"$tmp/rep.out" 2>&1
check "... nor report (stdout, report.md)" \
	eval "! grep -qi synthetic '$tmp/rep.out' && ! grep -qi synthetic '$tmp/rep/report.md'"

{ printf '  #   slipwall:\tsynthetic  \r\n'; echo "$loads"; } >"$tmp/blanks.txt"
check "the marker with other blanks: synthetic" [ "$(synthetic "$tmp/blanks.txt")" = True ]
"$bin" report $demo -n 20 --tests "$tmp/blanks.txt" --out "$tmp/rep2" >"$tmp/rep2.out" 2>&1
check "... and report says so (stdout, report.md)" \
	eval "grep -q 'are synthetic' '$tmp/rep2.out' && grep -q '(\*\*synthetic\*\*' '$tmp/rep2/report.md'"
{ echo "# unlike the file marked '# slipwall: synthetic', these are real"; echo "$loads"; } >"$tmp/inside.txt"
check "the marker's words inside a longer comment: not synthetic" \
	[ "$(synthetic "$tmp/inside.txt")" = False ]
tap_end
