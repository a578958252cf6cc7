#!/bin/bash
# cli/check.sh - `slipwall check` and `slipwall solve` through the real
# binary: counts and loads someone could get wrong, exit statuses.
set -u
bin=$1
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh
# ok_if STATUS TEXT: ok when STATUS is 0
ok_if() { if [ "$1" = 0 ]; then ok "$2"; else not_ok "$2"; fi; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# The demo wall by hand: 8 courses of 0.20 x 0.15 m blocks in a 0.60 m
# wall, half-start courses [0.1 0.2 0.2 0.1] (4 blocks) and full ones
# [0.2 0.2 0.2] (3): 4*4 + 4*3 = 28 blocks.  Head joints 4*3 + 4*2 = 20;
# between two courses the joints at every 0.1 m split the bed into 6
# segments, 7 pairs = 42; 4 blocks on the ground.  66 interfaces.
"$bin" check --json walls/demo.yaml > "$tmp/demo.json"
ok_if $? "check --json demo wall exits 0"
python3 - "$tmp/demo.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
free = [b for b in d["blocks"] if not b["fixed"]]
assert len(free) == 28, len(free)
assert len(d["interfaces"]) == 66, len(d["interfaces"])
head = [i for i in d["interfaces"] if i["kind"] == "head"]
assert len(head) == 20, len(head)
# weight of a full block: 19620 * 0.2 * 0.15 * 0.1 = 58.86 N; 20 of them
# (3 in each full course, 2 in each half-start one)
w = [b["weight"] for b in free if abs(b["area"] - 0.03) < 1e-12]
assert all(abs(x - 58.86) < 1e-9 for x in w) and len(w) == 20, (len(w), w[:3])
assert d["loads"][0]["type"] == "point" and d["loads"][0]["block"] == "c4b3", d["loads"][0]
PY
ok_if $? "demo wall: 28 blocks, 66 interfaces (20 head), 58.86 N blocks, load on c4b3"

# every bundled wall loads, geometry and all (docs/walls.md)
for w in walls/*.yaml; do
	if "$bin" check "$w" > /dev/null 2> "$tmp/err"; then
		ok "check $w exits 0"
	else
		not_ok "check $w exits 0" "$(head -c 400 "$tmp/err")"
	fi
done

"$bin" check walls/ferris-tinloi-1.yaml > "$tmp/ft1.txt"
grep -q "33 free" "$tmp/ft1.txt"
ok_if $? "check text: Ferris & Tin-Loi wall 1 has 33 free blocks"

"$bin" check --help > /dev/null
ok_if $? "check --help exits 0"
"$bin" check > /dev/null 2>&1
[ $? = 2 ]
ok_if $? "check without a file exits 2"
"$bin" check walls/demo.yaml --frobnicate > /dev/null 2>&1
[ $? = 2 ]
ok_if $? "check with an unknown option exits 2"
"$bin" --help | grep -q "commands:"
ok_if $? "slipwall --help lists the commands"

# single block 0.4 x 0.8 pushed at height 0.6: overturns at
# P = W b / (2 a) = W / 3 (b/2a = 0.333 < mu = 0.6)
"$bin" check --json walls/single-block.yaml > "$tmp/sb.json"
for m in standard gilbert global; do
	"$bin" solve walls/single-block.yaml --method $m --json > "$tmp/$m.json"
	ok_if $? "solve --method $m exits 0"
	python3 - "$tmp/sb.json" "$tmp/$m.json" <<'PY'
import json, sys
w = json.load(open(sys.argv[1])); r = json.load(open(sys.argv[2]))
W = w["total_weight"]
b = 0.4; a = w["loads"][0]["at"][1]; mu = w["material"]["friction"]["bed"]
want = W * min(mu, b / (2 * a))
assert abs(r["load_factor"] - want) <= 1e-9 * want, (r["load_factor"], want)
assert r["mechanism"]["blocks"][0]["moving"]
PY
	ok_if $? "solve --method $m: single block at W b/(2a)"
done
"$bin" solve walls/single-block.yaml --method magic > /dev/null 2>&1
[ $? = 2 ]
ok_if $? "solve with an unknown method exits 2"
# check and solve keep their own words (src/cli/cli_opts.c, posix mode)
"$bin" solve walls/single-block.yaml --method 2> "$tmp/err"
[ $? = 2 ] && grep -qF "unknown option or missing value: '--method'" "$tmp/err"
ok_if $? "solve --method without a value: exit 2, 'unknown option or missing value'"
"$bin" solve -m standard -- walls/single-block.yaml > "$tmp/m.txt" 2>&1
[ $? = 0 ] && grep -q "standard" "$tmp/m.txt"
ok_if $? "solve -m standard -- WALL: '--' ends the options, -m is --method"
"$bin" check walls/single-block.yaml walls/demo.yaml --json 2> "$tmp/err"
[ $? = 2 ] && grep -qF "expected one wall file" "$tmp/err"
ok_if $? "check with two walls: exit 2, 'expected one wall file'"

# a load pushing a block into an abutment: no finite collapse load
cat > "$tmp/boxed.yaml" <<'Y'
blocks:
  - vertices: [[0, 0], [0.4, 0], [0.4, 0.4], [0, 0.4]]
supports:
  - ground: {y: 0}
  - vertices: [[0.4, 0], [0.6, 0], [0.6, 0.6], [0.4, 0.6]]
loads:
  - point: {at: [0, 0.1], direction: [1, 0]}
Y
"$bin" solve "$tmp/boxed.yaml" --method standard > /dev/null 2> "$tmp/err"
rc=$?
[ $rc = 1 ] && grep -q "unbounded" "$tmp/err"
ok_if $? "a load pushing into a support: exit 1 and says unbounded ($(cat "$tmp/err"))"

# A block that rests on no joint (wall_hanging): tests/data/stack-gap.yaml,
# a stack-bond wall with the middle block of its first course left out;
# its warning on stderr and in --json's warnings names the block over
# the gap and counts the one that rests on it.  The same wall in running
# bond has no such block (each block over the gap rests half on a
# neighbour of the missing one): no such warning, but those blocks
# overhang what they rest on (wall_overhang_text: the centroid of c2b2
# at x = 0.3 m, the edge of its joint on c1b1), and that is said.
sed 's/bond: stack/bond: running/' tests/data/stack-gap.yaml >"$tmp/running.yaml"
"$bin" check tests/data/stack-gap.yaml --json >"$tmp/stack.json" 2>"$tmp/stack.err"
python3 - "$tmp/stack.json" "$tmp/stack.err" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
w = [x for x in d["warnings"] if "rests on no joint" in x]
err = open(sys.argv[2]).read()
sys.exit(not (len(w) == 1 and w[0].startswith("block c2b2 rests on no joint below it, and 1 other block only on it:")
              and "warning: " in err and w[0] in err))
PY
ok_if $? "stack bond, a block of the first course left out: c2b2 hangs and c3b2 on it, warned on stderr and in --json"
"$bin" check "$tmp/running.yaml" --json >"$tmp/running.json" 2>"$tmp/running.err"
python3 - "$tmp/running.json" "$tmp/running.err" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
w = d["warnings"]
err = open(sys.argv[2]).read()
sys.exit(not (len(w) == 1 and w[0].startswith(
    "block c2b2 overhangs what it rests on (its centroid, at x = 0.3 m, is at the edge of the joints below it), and 1 other block likewise:")
    and "rests on no joint" not in err and w[0] in err))
PY
ok_if $? "running bond, the same block left out: nothing hangs; c2b2 and one other overhang their bearing, warned on stderr and in --json"
# jamb blocks half over an opening with a lintel (tests/data/
# opening-overhang.yaml: c6b2, c8b2 and c7b5); walls/facade.yaml's
# toothed jambs overhang nothing
"$bin" check tests/data/opening-overhang.yaml --json >"$tmp/over.json" 2>/dev/null
"$bin" check walls/facade.yaml --json >"$tmp/facade.json" 2>/dev/null
python3 - "$tmp/over.json" "$tmp/facade.json" <<'PY'
import json, sys
w = json.load(open(sys.argv[1]))["warnings"]
f = json.load(open(sys.argv[2]))["warnings"]
sys.exit(not (len(w) == 1 and w[0].startswith("block c6b2 overhangs what it rests on (its centroid, at x = 0.45 m, is at the edge of the joints below it), and 2 other blocks likewise:")
              and "Blocks that overhang an opening" in w[0] and f == []))
PY
ok_if $? "an opening's jambs in running bond: 3 blocks overhang their bearing (warned); the facade's toothed jambs: no warning"

tap_end
