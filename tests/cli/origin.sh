#!/bin/bash
# cli/origin.sh - walls far from the origin (docs/wall-format.md,
# "Coordinates far from the origin"): areas, centroids and weights are
# computed relative to each polygon, so moving a wall changes nothing
# but the rounding of its coordinates; a wall so far out that doubles
# cannot hold its blocks' dimensions to 1e-8 is refused at the vertex.
#
# Usage (from the source root): bash tests/cli/origin.sh /path/to/slipwall
# Proves: walls/single-block.yaml moved to (-1e9, -1e9) is refused, exit
# 2, FILE:LINE:COLUMN at its first vertex; moved to (1e7, 1e7) it
# weighs 627.84 N to 1e-8 (check --json) and tips at 209.28 N to 1e-7 at depth
# 0; moved to UTM-like (5e5, 4.4e6) it tips at 209.28 N to 1e-9; a
# two-block stack under a point load, moved there, gives every sample's
# lambda_min of the unmoved stack to 1e-8.  TAP output.

bin=${1:?usage: cli/origin.sh SLIPWALL}
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# move_wall SRC DX DY OUT: the wall moved by (DX, DY): vertices, load points
# and the ground
move_wall() {
	python3 - "$@" <<'PY'
import re, sys
src, dx, dy, out = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), sys.argv[4]
t = open(src).read()
t = re.sub(r"((?:vertices: \[|at: |, ))\[(-?[0-9.e+-]+), (-?[0-9.e+-]+)\]",
           lambda m: "%s[%r, %r]" % (m.group(1), float(m.group(2)) + dx, float(m.group(3)) + dy), t)
t = re.sub(r"ground: \{y: ([0-9.e+-]+)\}", lambda m: "ground: {y: %r}" % (float(m.group(1)) + dy), t)
open(out, "w").write(t)
PY
}
p05() {	# p05 FILE.json
	python3 -c 'import json, sys; print(json.load(open(sys.argv[1]))["lambda"]["p05"])' "$1"
}

sed 's/depth: 0.25/depth: 0/' walls/single-block.yaml >"$tmp/block.yaml"

move_wall "$tmp/block.yaml" -1e9 -1e9 "$tmp/far.yaml"
line=$(grep -n 'vertices:' "$tmp/far.yaml" | cut -d: -f1)
col=$(grep 'vertices:' "$tmp/far.yaml" | awk '{print index($0, "[[") + 1}')
"$bin" run "$tmp/far.yaml" -n 5 >"$tmp/far.out" 2>"$tmp/far.err"
rc=$?
check "(-1e9, -1e9): refused, exit 2, at the first vertex ($line:$col)" \
	eval "[ $rc -eq 2 ] && grep -q '^$tmp/far.yaml:$line:$col: vertex 1 is too far from the origin' '$tmp/far.err' && [ ! -s '$tmp/far.out' ]"

move_wall "$tmp/block.yaml" 1e7 1e7 "$tmp/e7.yaml"
"$bin" check "$tmp/e7.yaml" --json >"$tmp/e7.check" 2>&1
check "(1e7, 1e7): the block weighs 627.84 N (to 1e-8)" \
	python3 -c 'import json, sys; b = [b for b in json.load(open(sys.argv[1]))["blocks"] if b["id"] == "block"][0]; sys.exit(not abs(b["weight"] - 627.84) < 1e-8 * 627.84)' "$tmp/e7.check"
"$bin" run "$tmp/e7.yaml" -n 5 --json >"$tmp/e7.json" 2>/dev/null
check "(1e7, 1e7): it tips at 209.28 N (to 1e-7)" near "$(p05 "$tmp/e7.json")" 209.28 1e-7

move_wall "$tmp/block.yaml" 5e5 4.4e6 "$tmp/utm.yaml"
"$bin" run "$tmp/utm.yaml" -n 5 --json >"$tmp/utm.json" 2>/dev/null
check "(5e5, 4.4e6): it tips at 209.28 N (to 1e-9)" near "$(p05 "$tmp/utm.json")" 209.28 1e-9

sed 's/- body: {direction: \[1, 0\]}/- point: {at: [0, 0.3], direction: [1, 0]}/' \
	walls/two-block-stack.yaml >"$tmp/stack.yaml"
move_wall "$tmp/stack.yaml" 5e5 4.4e6 "$tmp/stack-utm.yaml"
"$bin" run "$tmp/stack.yaml" -n 100 --samples "$tmp/a.csv" >/dev/null 2>&1
"$bin" run "$tmp/stack-utm.yaml" -n 100 --samples "$tmp/b.csv" >/dev/null 2>&1
check "a two-block stack moved to (5e5, 4.4e6): every sample's lambda_min to 1e-8" python3 -c '
import csv, sys
a = list(csv.DictReader(open(sys.argv[1])))
b = list(csv.DictReader(open(sys.argv[2])))
ok = len(a) == len(b) == 100 and all(x["status"] == y["status"] for x, y in zip(a, b))
ok = ok and sum(x["status"] == "accepted" for x in a) > 50
ok = ok and all(abs(float(x["lambda_min"]) - float(y["lambda_min"])) <= 1e-8 * float(x["lambda_min"])
                for x, y in zip(a, b) if x["status"] == "accepted")
sys.exit(not ok)' "$tmp/a.csv" "$tmp/b.csv"
tap_end
