#!/bin/bash
# cli/body.sh - horizontal body loads (a seismic coefficient: lambda
# times each block's weight).  The closed form of a single block of width
# b and height h on the ground, contact at its corners (depth 0): it
# slides at lambda = mu and tips about its toe at lambda = b / h (the
# load acts at the centroid, h / 2 up, against the weight's lever b / 2),
# so lambda = min(mu, b / h).  And a wall whose mechanisms' joint rates
# are small: the motion threshold never falls below the kinematic LP's
# precision (docs/method.md, "Tolerances"; tests/data/body-195.yaml).
# TAP output.
set -u
bin=$1
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# block B H MU: a single block B wide, H high, friction MU, under a body
# load along +x
block() {
	cat <<YAML
name: Single block under a body load
material: {friction: $3, unit_weight: 19620, thickness: 0.10}
blocks:
  - id: b
    vertices: [[0, 0], [$1, 0], [$1, $2], [0, $2]]
supports:
  - ground: {y: 0}
loads:
  - body: {direction: [1, 0]}
contacts: {depth: 0}
analysis: {samples: 3, seed: 1}
YAML
}
# lam B H MU: the run's lambda_min (its JSON summary's lambda.min), all
# 3 samples accepted
lam() {
	block "$1" "$2" "$3" >"$tmp/b.yaml"
	"$bin" run "$tmp/b.yaml" --threads 1 --json >"$tmp/b.json" 2>"$tmp/err"
	json_field "$tmp/b.json" 'd["lambda"]["min"] if d["accepted"] == 3 else "rejected"'
}
for c in "0.4 0.8 0.6 0.5 tips: b/h" "0.8 0.4 0.6 0.6 slides: mu" \
	 "0.4 0.8 0.4 0.4 slides: mu" "0.3 1.0 0.6 0.3 tips: b/h"; do
	read -r b h mu want why <<<"$c"
	got=$(lam "$b" "$h" "$mu")
	check "block ${b} x ${h} m, mu $mu, body load: lambda $got = min(mu, b/h) = $want (${why% *} ${why##* })" \
		near "$got" "$want" 1e-7
done

# tests/data/body-195.yaml, seed 1, sample 7 (its positions in
# body-195-seed1-s7.csv): the largest joint rate of its mechanism is 0.02,
# rates of 1e-10 are the kinematic LP's round-off; counted as motion
# they made LP-min infeasible (`numerical`).  Accepted, lambda_min
# 0.424958 (the SLP's lambda_max is 0.4249586: the onset state's load
# can only be below it).
"$bin" run tests/data/body-195.yaml --positions tests/data/body-195-seed1-s7.csv \
	--threads 1 --samples "$tmp/s7.csv" >/dev/null 2>"$tmp/err"
read -r st lmax lmin <<<"$(awk -F, 'NR == 2 { print $2, $3, $4 }' "$tmp/s7.csv")"
check "195-block body-loaded wall, sample 7: accepted ($st)" [ "$st" = accepted ]
check "... lambda_min $lmin: 0.424958, at most lambda_max $lmax" \
	awk -v a="$lmin" -v b="$lmax" 'BEGIN { exit !(a > 0.4249580 && a < 0.4249590 && a <= b + 1e-9) }'
tap_end
