#!/bin/bash
# cli/override.sh - --friction, --load-at, --load-direction and --set on
# run, compare and report (docs/run.md, "Overrides").
#
# Usage (from the source root): bash tests/cli/override.sh /path/to/slipwall
# Proves: a run with overrides writes the same samples file, byte for
# byte, as the run of a copy of the wall file edited by hand (sed on the
# file's text), for each kind of override and for them all at once;
# the JSON summaries of run and compare list every override; the
# report's "to reproduce" line repeats them and its summary lists them;
# a bad value exits 2 with a message naming the option; the load options
# refuse a body load's point and walls with several loads.  TAP output.

bin=${1:?usage: cli/override.sh SLIPWALL}
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
block=walls/single-block.yaml
stack=walls/two-block-stack.yaml

# same NAME WALL SEDSCRIPT OPTIONS...: the run with OPTIONS on WALL and
# the run of WALL edited by SEDSCRIPT give the same samples file (and
# the edit did change the file, and the samples differ from the plain
# run's: the override had an effect)
same() {
	local name=$1 wall=$2 script=$3
	shift 3
	sed -e "$script" "$wall" >"$tmp/edited.yaml"
	"$bin" run "$wall" -n 40 --threads 2 --samples "$tmp/ovr.csv" "$@" \
		>/dev/null 2>"$tmp/ovr.err"
	local r1=$?
	"$bin" run "$tmp/edited.yaml" -n 40 --threads 1 \
		--samples "$tmp/edit.csv" >/dev/null 2>&1
	local r2=$?
	"$bin" run "$wall" -n 40 --threads 1 --samples "$tmp/plain.csv" \
		>/dev/null 2>&1
	if [ $r1 = 0 ] && [ $r2 = 0 ] && ! cmp -s "$wall" "$tmp/edited.yaml" &&
	   cmp -s "$tmp/ovr.csv" "$tmp/edit.csv" &&
	   ! cmp -s "$tmp/ovr.csv" "$tmp/plain.csv"; then
		ok "$name: the same samples as the edited file"
	else
		not_ok "$name: the same samples as the edited file" \
			"exit $r1 / $r2" "$(cat "$tmp/ovr.err")" \
			"$(diff "$tmp/ovr.csv" "$tmp/edit.csv" | head -n 4)"
	fi
}

same "--friction 0.45" $block 's/^  friction: 0.6$/  friction: 0.45/' \
	--friction 0.45
same "--friction 0.3,0.5 (bed, head)" $stack \
	's/^  friction: 0.6$/  friction: {bed: 0.3, head: 0.5}/' --friction 0.3,0.5
same "--set material.friction.bed=0.3 on a file with one friction (head keeps 0.6)" $stack \
	's/^  friction: 0.6$/  friction: {bed: 0.3, head: 0.6}/' --set material.friction.bed=0.3
same "--load-at 0,0.1" $block 's/at: \[0, 0.6\]/at: [0, 0.1]/' --load-at 0,0.1
same "--load-direction 1,0.5 (a point load)" $block \
	's/direction: \[1, 0\], magnitude/direction: [1, 0.5], magnitude/' \
	--load-direction 1,0.5
same "--load-direction 1,-0.2 (a body load)" $stack \
	's/direction: \[1, 0\]/direction: [1, -0.2]/' --load-direction 1,-0.2
same "--set material.unit_weight=20000" $block \
	's/unit_weight: 19620/unit_weight: 20000/' --set material.unit_weight=20000
same "--set analysis.seed=3" $block 's/seed: 1$/seed: 3/' --set analysis.seed=3
same "--set contacts.depth=0.1" $block 's/depth: 0.25/depth: 0.1/' \
	--set contacts.depth=0.1
same "--set loads.0.point.at=[0.1,0.4] (a flow list)" $block \
	's/at: \[0, 0.6\]/at: [0.1, 0.4]/' '--set=loads.0.point.at=[0.1,0.4]'
same "all at once" $block \
	's/^  friction: 0.6$/  friction: 0.5/; s/at: \[0, 0.6\]/at: [0, 0.2]/; s/unit_weight: 19620/unit_weight: 18000/; s/seed: 1$/seed: 5/' \
	--friction 0.5 --load-at 0,0.2 --set material.unit_weight=18000 --set analysis.seed=5

# a key the file does not have: added, as writing it in would
cat >"$tmp/nomat.yaml" <<'Y'
blocks:
  - vertices: [[0, 0], [0.4, 0], [0.4, 0.8], [0, 0.8]]
supports:
  - ground: {y: 0}
loads:
  - point: {at: [0, 0.1], direction: [1, 0]}
Y
{ cat "$tmp/nomat.yaml"; printf 'material:\n  friction: 0.3\n'; } >"$tmp/withmat.yaml"
"$bin" run "$tmp/nomat.yaml" -n 20 --friction 0.3 --samples "$tmp/a.csv" >/dev/null 2>&1
"$bin" run "$tmp/withmat.yaml" -n 20 --samples "$tmp/b.csv" >/dev/null 2>&1
check "--friction on a file without material: as if the key were written in" \
	cmp -s "$tmp/a.csv" "$tmp/b.csv"

# ---- the JSON summaries ------------------------------------------------------------
"$bin" run $block -n 5 --friction 0.3,0.4 --load-at 0,0.2 --set analysis.seed=2 \
	--json >"$tmp/run.json" 2>/dev/null
check "run --json lists every override (option, value, key, yaml) and uses the seed" \
	python3 -c '
import json, sys
d = json.load(open(sys.argv[1]))
o = d["overrides"]
want = [("--friction", "0.3,0.4", "material.friction", "{bed: 0.3, head: 0.4}"),
        ("--load-at", "0,0.2", "loads.0.point.at", "[0, 0.2]"),
        ("--set", "analysis.seed=2", "analysis.seed", "2")]
got = [(x["option"], x["value"], x["key"], x["yaml"]) for x in o]
sys.exit(not (got == want and d["seed"] == 2))' "$tmp/run.json"
"$bin" run $block -n 5 --json >"$tmp/run0.json" 2>/dev/null
check "run --json without overrides: an empty list" \
	python3 -c 'import json,sys; sys.exit(json.load(open(sys.argv[1]))["overrides"] != [])' "$tmp/run0.json"
"$bin" compare $block -n 20 --tests walls/demo-loads.txt --friction 0.4 --json \
	>"$tmp/cmp.json" 2>/dev/null
check "compare --json lists the override" \
	python3 -c 'import json,sys; o=json.load(open(sys.argv[1]))["overrides"]; sys.exit(not (len(o)==1 and o[0]["key"]=="material.friction" and o[0]["yaml"]=="0.4"))' "$tmp/cmp.json"

# ---- the report ------------------------------------------------------------------------
"$bin" report $block -n 20 --friction 0.4 --set 'name=Block, mu 0.4' \
	--out "$tmp/rep" >/dev/null 2>&1
line=$(grep -A2 'To reproduce' "$tmp/rep/report.md" | grep 'slipwall report')
check "the report's command line repeats the overrides" \
	eval "echo \"\$line\" | grep -qF -- \"--friction 0.4 --set 'name=Block, mu 0.4'\""
check "the report's summary lists them" \
	grep -qF 'material.friction = 0.4 (--friction 0.4)' "$tmp/rep/report.md"
# the line runs again (slipwall: the binary under test) to the same summary
slipwall() { "$bin" "$@"; }
eval "${line/--out*/--out \"\$tmp/rep2\"}" >/dev/null 2>&1
check "the report's command line runs again, to the same load statistics" \
	eval '[ -f "$tmp/rep2/report.md" ] && diff <(grep "^| Numerical model" "$tmp/rep/report.md") <(grep "^| Numerical model" "$tmp/rep2/report.md") >/dev/null && grep -q "^| Numerical model | 20 " "$tmp/rep/report.md"'

# ---- bad values: exit 2, a message naming the option -----------------------------------
bad() {		# DESCRIPTION PATTERN ARGS...
	local what=$1 pat=$2
	shift 2
	"$bin" "$@" >"$tmp/bad.out" 2>"$tmp/bad.err"
	local rc=$?
	if [ $rc = 2 ] && grep -qE -- "$pat" "$tmp/bad.err" && [ ! -s "$tmp/bad.out" ]; then
		ok "$what: exit 2"
	else
		not_ok "$what: exit 2" "exit $rc" "$(cat "$tmp/bad.err")"
	fi
}
bad "--friction abc" "--friction: 'abc'" run $block --friction abc
bad "--friction 0.4,0.5,0.6" "--friction" run $block --friction 0.4,0.5,0.6
bad "--friction -1 (the reader's range check, named)" "^--friction -1: friction must be >= 0" run $block --friction -1
bad "--friction 0x1 (not a decimal, as in the wall file)" "--friction: '0x1' is neither MU nor BED,HEAD \(numbers\)" run $block --friction 0x1
bad "--load-at 1" "--load-at: '1'" run $block --load-at 1
bad "--load-at outside every block" "--load-at 5,5\\)" run $block --load-at 5,5
bad "--load-at on a body load" "body load" run $stack --load-at 0,0.1
# a value's control characters are shown escaped, never sent to the
# terminal (an escape sequence could clear it or retitle the window)
"$bin" run $block -n 2 --set "$(printf 'name="a\033[2J"')" >/dev/null 2>"$tmp/esc.err"
rc=$?
check "--set with an escape character: exit 2, shown as \\e, no raw escape on stderr" \
	eval '[ $rc = 2 ] && grep -qF "a\e[2J" "$tmp/esc.err" && ! grep -q "$(printf "\033")" "$tmp/esc.err"'
"$bin" run $block -n 2 --set "$(printf 'material.frict=1\nx')" >/dev/null 2>"$tmp/nl.err"
check "--set with a newline in its value: one line of message, the newline shown as \\n" \
	eval '[ "$(wc -l <"$tmp/nl.err")" = 1 ] && grep -qF "frict=1\nx" "$tmp/nl.err"'
# an error at a place in the file whose value an override replaced says
# which overrides the wall had
bad "--set a vertex below the ground: the file's place, then the override" \
	"^  \(in walls/single-block.yaml as changed by: blocks.0.vertices.0 = \[0,-1\]" \
	run $block --set 'blocks.0.vertices.0=[0,-1]'
bad "--load-direction 0,0" "^--load-direction 0,0: direction must be a non-zero" run $block --load-direction 0,0
bad "--set without =" "--set: 'material.friction'" run $block --set material.friction
bad "--set an unknown key" "^--set material.frict=1: unknown key 'frict' in material" run $block --set material.frict=1
bad "--set a list item out of range" "not an item of a list of 1" run $block --set 'loads.2.point.at=[0,0]'
bad "--set a key inside a number" "^--set material.unit_weight.x=1: 'x' is inside a single value" run $block --set material.unit_weight.x=1
bad "--set a key inside one friction's bed" "^--set material.friction.bed.x=1: 'x' is inside a single value" run $block --set material.friction.bed.x=1
bad "--set material.friction.bed=-1 on one friction (the reader's range check)" "^--set material.friction.bed=-1: friction .bed. must be >= 0" run $block --set material.friction.bed=-1
bad "--set a value that is not YAML" "not a YAML value" run $block --set 'material.friction=[1'
bad "--set analysis.samples=0 (range)" "^--set analysis.samples=0: samples" run $block --set analysis.samples=0
bad "--friction without a value" "needs a value" run $block --friction
bad "compare --friction abc" "--friction: 'abc'" compare $block --tests walls/demo-loads.txt --friction abc
bad "report --set x=1" "unknown key 'x'" report $block --out "$tmp/r3" --set x=1

# ---- every YAML the program parses has the file's limits (issue 23) ------
# A --set value went to libyaml without the wall file's depth limit
# (60,000 '[' took 12-40 s) and its aliases were copied out (a value of
# 7 alias levels expanded to about 2 GB, 8 levels exhausted memory).
# Now the value passes the same depth check as a file, and an alias
# stays a shared node: the schema's message comes at once.  The memory
# limit is a guard for the old code, not an assertion of time.
deep=$(printf '%60000s' '' | tr ' ' '[')
bad "--set 60,000 nested brackets: the file's depth limit" \
	"^--set material\.friction=\[+\.\.\.: not a YAML value: 1:65: nested deeper than 64 levels" \
	run $block --set "material.friction=$deep"
bomb7='[&a [0,0,0,0,0,0,0,0,0,0]'
prev=a
for l in b c d e f g h; do
	bomb7="$bomb7, &$l [$(printf "*$prev,%.0s" 1 2 3 4 5 6 7 8 9)*$prev]"
	prev=$l
done
bomb7="$bomb7]"
bomb8="${bomb7%]}, &i [$(printf '*h,%.0s' 1 2 3 4 5 6 7 8 9)*h]]"
# AddressSanitizer reserves terabytes of address space: no ulimit -v there
vlimit="ulimit -v 1048576;"
grep -q __asan_init "$bin" 2>/dev/null && vlimit=
for b in 7 8; do
	v=bomb$b
	(eval "$vlimit"; ulimit -t 120
	 exec "$bin" run $block -n 1 --set "tests.loads=${!v}") \
		>"$tmp/bomb.out" 2>"$tmp/bomb.err"
	rc=$?
	if [ $rc = 2 ] && grep -q ": a test load must be a number, not a list" "$tmp/bomb.err"; then
		ok "--set a value of $b alias levels ($(printf %s "${!v}" | wc -c) bytes): exit 2 with the schema's message, nothing expanded"
	else
		not_ok "--set a value of $b alias levels: exit 2 with the schema's message" \
			"exit $rc" "$(tail -c 300 "$tmp/bomb.err")"
	fi
done
"$bin" run $block -n 5 --threads 1 --set 'material.friction={bed: &m 0.7, head: *m}' \
	--json >"$tmp/alias.json" 2>"$tmp/alias.err"
rc=$?
if [ $rc = 0 ] && grep -q '"accepted": 5' "$tmp/alias.json"; then
	ok "--set a value with an alias still works"
else
	not_ok "--set a value with an alias still works" "exit $rc" "$(cat "$tmp/alias.err")"
fi

tap_end
