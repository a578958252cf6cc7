#!/bin/bash
# cli/report_samples.sh - `report --samples FILE.csv`: what it reuses and
# what it recomputes, said on stderr (docs/report.md).
#
# Usage (from the source root): bash tests/cli/report_samples.sh SLIPWALL
# Proves: with the workbench's summary X.json beside X.csv (same wall
# model: its wall_digest), the report takes standard and gilbert from it
# (values no solver gives, so a recomputation would show) and says so on
# stderr; without it, it says it computes them, and its values are
# solve's; a copy of the wall file is the same model and reused; a wall
# changed by an override, a summary without wall_digest, and the wall
# file edited in place (same device and inode, its load moved) are not
# reused, with the reason, and report.md has the edited wall's value; the replay of the contact positions is announced with
# the count of loads.  TAP output.

bin=${1:?usage: cli/report_samples.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp walls/demo.yaml "$tmp/X.yaml"
cd "$tmp" || exit 1
"$bin" run X.yaml -n 12 --samples X.csv >/dev/null 2>&1

"$bin" report X.yaml --samples X.csv --out r1 >/dev/null 2>r1.err
rc=$?
check "without a summary: exit 0" [ $rc = 0 ]
check "the replay is announced, with the count of loads" \
	grep -q "^report: 12 loads from X.csv; replaying their contact positions" r1.err
check "standard and gilbert: 'computing' then 'done' on stderr" \
	eval 'grep -q "^report: standard: computing" r1.err && grep -q "^report: standard: done" r1.err &&
	      grep -q "^report: gilbert: computing" r1.err && grep -q "^report: gilbert: done" r1.err'
"$bin" solve X.yaml --method standard --json >std.json 2>/dev/null
check "the computed standard value is solve's" python3 -c '
import json, re, sys
want = json.load(open("std.json"))["load_factor"]
m = re.search(r"^\| standard \| ([0-9.e+-]+) ", open("r1/report.md").read(), re.M)
sys.exit(not (m and abs(float(m.group(1)) - want) <= 1e-4 * want))'

# the workbench's summary beside the samples file, with the digest of
# the wall it was written for (check --json gives it)
digest() {
	"$bin" check "$1" --json | python3 -c 'import json, sys; print(json.load(sys.stdin)["wall_digest"])'
}
summary() {	# summary DIGEST: X.json for X.csv
	printf '{\n  "wall": "X.yaml",\n  "wall_digest": "%s",\n  "samples_file": "X.csv",\n  "standard": 1234.5,\n  "gilbert": 987.25\n}\n' "$1" >X.json
}
summary "$(digest X.yaml)"
"$bin" report X.yaml --samples X.csv --out r2 >/dev/null 2>r2.err
check "with X.json: standard and gilbert taken from it, not recomputed" \
	eval 'grep -q "^report: standard: 1234.5, from X.json (not recomputed)" r2.err &&
	      grep -q "^report: gilbert: 987.25, from X.json (not recomputed)" r2.err &&
	      ! grep -q "computing" r2.err &&
	      grep -q "^| standard | 1234.5 N | from X.json |" r2/report.md &&
	      grep -q "^| gilbert | 987.25 N | from X.json |" r2/report.md'
cp X.yaml Y.yaml
"$bin" report Y.yaml --samples X.csv --out r3 >/dev/null 2>r3.err
check "a copy of the wall (the same model): reused" \
	grep -q "^report: standard: 1234.5, from X.json (not recomputed)" r3.err
"$bin" report X.yaml --samples X.csv --friction 0.5 --out r4 >/dev/null 2>r4.err
check "a wall changed by an override: not reused, and said" \
	eval 'grep -q "X.json was written for X.yaml, a model this wall is not" r4.err && grep -q "^report: gilbert: computing" r4.err'
summary ""
"$bin" report X.yaml --samples X.csv --out r6 >/dev/null 2>r6.err
check "a summary without wall_digest: not reused, and said" \
	eval 'grep -q "cannot be matched to (it has no wall_digest)" r6.err && grep -q "^report: standard: computing" r6.err'
# the wall edited in place (same device and inode): its load moved down
summary "$(digest X.yaml)"
python3 - X.yaml <<'PY'
import re, sys
t = open(sys.argv[1]).read()
t2 = re.sub(r"(point: \{at: \[[^,]+, )([0-9.]+)\]", lambda m: m.group(1) + repr(float(m.group(2)) / 2) + "]", t, count=1)
assert t2 != t
open(sys.argv[1], "r+").write(t2)
PY
"$bin" report X.yaml --samples X.csv --out r7 >/dev/null 2>r7.err
"$bin" solve X.yaml --method standard --json >std7.json 2>/dev/null
check "the wall edited in place: recomputed, report.md has the edited wall's standard" python3 -c '
import json, re, sys
want = json.load(open("std7.json"))["load_newtons"]
md = open("r7/report.md").read()
m = re.search(r"^\| standard \| ([0-9.e+-]+) N \| ", md, re.M)
err = open("r7.err").read()
sys.exit(not (m and abs(float(m.group(1)) - want) <= 1e-4 * want and "1234.5" not in md
              and "a model this wall is not" in err))'
printf '{\n  "wall": "X.yaml",\n  "samples_file": "other.csv",\n  "standard": 1234.5\n}\n' >X.json
"$bin" report X.yaml --samples X.csv --out r5 >/dev/null 2>r5.err
check "a summary of another samples file: ignored" grep -q "^report: standard: computing" r5.err
tap_end
