#!/bin/bash
# cli/families.sh - mechanism families in run's summary (docs/
# statistics.md, "Mechanism families"; docs/run.md).
#
# Usage (from the source root): bash tests/cli/families.sh /path/to/slipwall
# Proves, on walls/demo.yaml (200 samples, seed 1) and walls/ferris-
# tinloi-1.yaml (100 samples), from the JSON summary and the wall's
# `check --json`, recomputed here independently of family.c: the
# families' counts add up to the accepted samples, and their mechanisms'
# counts to each family's; every mechanism's moving blocks (the free
# blocks not joined to a support by closed joints, by a union-find in
# Python) are exactly its family's `blocks`, and two families never have
# the same blocks; each family's load range is its mechanisms'; each
# mechanism's `family` points back to it.  The text summary lists the
# same families, with the count and name of the JSON's first one, and
# names every joint by its two blocks.  The families do not depend on
# the thread count.  The demo's most frequent family is the end block of
# course 4 and the half block above it, sliding out on bed joints 3-5
# (the wall file's comment).  TAP output.

bin=${1:?usage: cli/families.sh SLIPWALL}
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

verify() {	# verify CHECK.json RUN.json: the independent recount
	python3 - "$1" "$2" <<'PY'
import json, sys
chk = json.load(open(sys.argv[1])); run = json.load(open(sys.argv[2]))
ids = [b["id"] for b in chk["blocks"]]
fixed = {b["id"] for b in chk["blocks"] if b["fixed"]} | {"ground"}
ifs = chk["interfaces"]
def moving(joint):
    par = {b: b for b in ids + ["ground"]}
    def f(x):
        while par[x] != x:
            x = par[x]
        return x
    for k, c in enumerate(joint):
        if c == ".":
            par[f(ifs[k]["a"])] = f(ifs[k]["b"])
    for s in fixed:
        if s in par:
            par[f(s)] = f("ground")
    g = f("ground")
    return frozenset(b for b in ids if b not in fixed and f(b) != g)
errs = []
fams, mechs = run["families"], run["mechanisms"]
if sum(x["count"] for x in fams) != run["accepted"]:
    errs.append("family counts do not add up to accepted")
if len({frozenset(x["blocks"]) for x in fams}) != len(fams):
    errs.append("two families with the same blocks")
seen = set()
for i, fa in enumerate(fams):
    ms = [mechs[k] for k in fa["mechanisms"]]
    seen |= set(fa["mechanisms"])
    if sum(m["count"] for m in ms) != fa["count"]:
        errs.append("family %d: its mechanisms' counts" % i)
    if min(m["lambda_lo"] for m in ms) != fa["lambda_lo"] or \
       max(m["lambda_hi"] for m in ms) != fa["lambda_hi"]:
        errs.append("family %d: load range" % i)
    for m in ms:
        if moving(m["joints"]) != frozenset(fa["blocks"]):
            errs.append("family %d: a mechanism moves other blocks" % i)
        if m["family"] != i:
            errs.append("family %d: a mechanism points elsewhere" % i)
    if i and fa["count"] > fams[i - 1]["count"]:
        errs.append("not most frequent first")
if seen != set(range(len(mechs))):
    errs.append("a mechanism in no family or in two")
print("; ".join(errs) if errs else "%d families of %d mechanisms, %d accepted" % (len(fams), len(mechs), run["accepted"]))
sys.exit(1 if errs else 0)
PY
}

for wall in demo ferris-tinloi-1; do
	ns=200
	[ $wall = demo ] || ns=100
	"$bin" check walls/$wall.yaml --json >"$tmp/check.json" 2>"$tmp/err"
	"$bin" run walls/$wall.yaml -n $ns --seed 1 --threads 1 --json \
		>"$tmp/run.json" 2>"$tmp/err"
	res=$(verify "$tmp/check.json" "$tmp/run.json")
	check "$wall: every family's mechanisms move its blocks, counts add up ($res)" \
		eval "verify '$tmp/check.json' '$tmp/run.json' >/dev/null"
	"$bin" run walls/$wall.yaml -n $ns --seed 1 --threads 2 --json \
		>"$tmp/run2.json" 2>"$tmp/err"
	check "$wall: the same families with 2 threads" \
		python3 -c 'import json, sys; a, b = (json.load(open(f)) for f in sys.argv[1:]); sys.exit(a["families"] != b["families"] or a["mechanisms"] != b["mechanisms"])' "$tmp/run.json" "$tmp/run2.json"
	"$bin" run walls/$wall.yaml -n $ns --seed 1 --threads 1 >"$tmp/run.txt" 2>"$tmp/err"
	want=$(json_field "$tmp/run.json" '"families     %d " % len(d["families"])')
	check "$wall: the text summary counts the families ($want)" \
		grep -q "^$want" "$tmp/run.txt"
	first=$(json_field "$tmp/run.json" '"%7d" % d["families"][0]["count"] + " .*  " + d["families"][0]["name"]')
	check "$wall: its first family is the JSON's (count, name)" \
		grep -q -- "^  $first\$" "$tmp/run.txt"
	check "$wall: joints are named by their blocks, 29s(c3b3/c4b3) style" \
		grep -Eq 'joints [0-9]+[shHo]\([^/ ]+/[^/ ]+\)' "$tmp/run.txt"
done
# the demo's most frequent family, by hand (walls/demo.yaml's comment:
# the end block of course 4 pulled out with the half block above it)
"$bin" run walls/demo.yaml -n 200 --seed 1 --threads 1 --json >"$tmp/run.json" 2>"$tmp/err"
check "demo: the most frequent family is c4b3 and c5b4" \
	eval "[ \"\$(json_field '$tmp/run.json' 'sorted(d[\"families\"][0][\"blocks\"])')\" = \"['c4b3', 'c5b4']\" ]"
# ... and it slides out between its neighbours: on the bed joints under
# c4b3 (3), between c4b3 and c5b3 (4) and above c5b4 (5)
"$bin" run walls/demo.yaml -n 200 --seed 1 --threads 1 >"$tmp/run.txt" 2>"$tmp/err"
line=$(grep -m1 'the most frequent (' "$tmp/run.txt")
check "demo: the most frequent family's mechanism slides on bed joints 3-5" \
	eval "printf '%s\\n' \"\$line\" | grep -Eq '^ +1 mechanism; the most frequent \\([0-9]+, 1 body\\) slides on bed joints 3-5: '"
tap_end
