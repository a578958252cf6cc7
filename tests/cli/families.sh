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
# Python) have its family's key (the set itself, up to 3 blocks; else
# its outline: lowest and highest course, the end blocks of each, which
# wall ends it reaches), two families never have the same key, a
# family's `blocks` are those that all its mechanisms move, and its name
# counts their fewest to most blocks; each family's load range is its
# mechanisms'; each
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
# courses: the free blocks' lowest points, equal within 1e-6 m here
free = [b for b in chk["blocks"] if not b["fixed"]]
ymin = {b["id"]: min(v[1] for v in b["vertices"]) for b in free}
xmin = {b["id"]: min(v[0] for v in b["vertices"]) for b in free}
levels = sorted({round(y, 6) for y in ymin.values()})
row = {i: levels.index(round(y, 6)) + 1 for i, y in ymin.items()}
def key(s):
    # at most 3 blocks: the set; more: its outline (lowest and highest
    # course, the leftmost and rightmost moving block of each, whether
    # every course it spans reaches the wall's left / right end)
    if len(s) <= 3:
        return ("set", s)
    rows = sorted({row[b] for b in s})
    def ends(r, among):
        bs = sorted((b for b in among if row[b] == r), key=lambda b: xmin[b])
        return bs[0], bs[-1]
    left = all(ends(r, ids_free)[0] in s for r in rows)
    right = all(ends(r, ids_free)[1] in s for r in rows)
    return ("outline", rows[0], ends(rows[0], s), rows[-1], ends(rows[-1], s), left, right)
ids_free = [b["id"] for b in free]
errs = []
fams, mechs = run["families"], run["mechanisms"]
if sum(x["count"] for x in fams) != run["accepted"]:
    errs.append("family counts do not add up to accepted")
keys = [key(moving(mechs[fa["mechanisms"][0]]["joints"])) for fa in fams]
if len(set(keys)) != len(fams):
    errs.append("two families with the same key")
seen = set()
for i, fa in enumerate(fams):
    ms = [mechs[k] for k in fa["mechanisms"]]
    seen |= set(fa["mechanisms"])
    if sum(m["count"] for m in ms) != fa["count"]:
        errs.append("family %d: its mechanisms' counts" % i)
    if min(m["lambda_lo"] for m in ms) != fa["lambda_lo"] or \
       max(m["lambda_hi"] for m in ms) != fa["lambda_hi"]:
        errs.append("family %d: load range" % i)
    sets = [moving(m["joints"]) for m in ms]
    if frozenset.intersection(*sets) != frozenset(fa["blocks"]):
        errs.append("family %d: its blocks are not those every mechanism moves" % i)
    lo, hi = min(map(len, sets)), max(map(len, sets))
    if (": %d block" % lo if lo == hi else ": %d-%d blocks" % (lo, hi)) not in fa["name"]:
        errs.append("family %d: its name does not count %d-%d blocks" % (i, lo, hi))
    for m, st in zip(ms, sets):
        if key(st) != keys[i]:
            errs.append("family %d: a mechanism moves another region" % i)
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
"$bin" run walls/demo.yaml -n 200 --seed 1 --threads 1 >"$tmp/run.txt" 2>"$tmp/err"
# two of the demo's regions are reached by mechanisms that move different
# counts of blocks (19-20 and 11-12 blocks at seed 1): one family each
check "demo: a family of mechanisms with different counts of moving blocks" \
	grep -Eq '^ +[0-9]+ .*: [0-9]+-[0-9]+ blocks in courses' "$tmp/run.txt"
# ... and it slides out between its neighbours: on the bed joints under
# c4b3 (3), between c4b3 and c5b3 (4) and above c5b4 (5)
"$bin" run walls/demo.yaml -n 200 --seed 1 --threads 1 >"$tmp/run.txt" 2>"$tmp/err"
line=$(grep -m1 'the most frequent (' "$tmp/run.txt")
check "demo: the most frequent family's mechanism slides on bed joints 3-5" \
	eval "printf '%s\\n' \"\$line\" | grep -Eq '^ +1 mechanism; the most frequent \\([0-9]+, 1 body\\) slides on bed joints 3-5: '"
tap_end
