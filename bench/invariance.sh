#!/bin/bash
# invariance.sh - path invariance at scale (docs/method.md, "The SLP's
# answer"): for the default SLP and for --slp plain, every
# SLIPWALL_LP_START and 1 against 2 threads give the same status and
# lambda_min (to 1e-9 relative) on every sample of the demo and both
# Ferris & Tin-Loi walls, at three seeds.  The suite runs its demo part
# (tests/cli/invariance.sh); this is the long form, about an hour and a
# half on 2 cores with the defaults.
#
# Usage: bash bench/invariance.sh SLIPWALL [N] [SEEDS] [WALLS...]
#   N samples (default 2000), SEEDS comma-separated (default 1,2,3),
#   WALLS (default the demo and both Ferris & Tin-Loi walls);
#   INVARIANCE_SLPS (default "piece plain"): the SLPs, the outer loop;
#   INVARIANCE_ARGS: more options for every run (e.g. "--cov 0.2": random
#   friction, docs/method.md).
# Prints one line per comparison and every differing sample; exits 1 if
# any differ.
bin=${1:?usage: invariance.sh SLIPWALL [N] [SEEDS] [WALLS...]}
n=${2:-2000}
seeds=${3:-1,2,3}
shift 3 2>/dev/null
cd "$(dirname "$0")/.." || exit 1
walls=("$@")
[ ${#walls[@]} -gt 0 ] || walls=(walls/demo.yaml walls/ferris-tinloi-1.yaml walls/ferris-tinloi-2.yaml)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
rc=0
for slp in ${INVARIANCE_SLPS:-piece plain}; do
	for w in "${walls[@]}"; do
		for seed in ${seeds//,/ }; do
			SLIPWALL_LP_START=auto "$bin" run "$w" -n "$n" --seed "$seed" \
				--threads 2 --slp $slp $INVARIANCE_ARGS --samples "$tmp/ref.csv" >/dev/null 2>&1
			for st in slack-primal slack-dual crash canonical previous support threads-1; do
				# previous: on 1 thread, its history fixed
				if [ $st = threads-1 ] || [ $st = previous ]; then
					SLIPWALL_LP_START=${st/threads-1/auto} \
					"$bin" run "$w" -n "$n" --seed "$seed" --threads 1 \
						--slp $slp $INVARIANCE_ARGS --samples "$tmp/o.csv" >/dev/null 2>&1
				else
					SLIPWALL_LP_START=$st "$bin" run "$w" -n "$n" --seed "$seed" \
						--threads 2 --slp $slp $INVARIANCE_ARGS --samples "$tmp/o.csv" >/dev/null 2>&1
				fi
				d=$(awk -F, -f tests/differ.awk "$tmp/ref.csv" "$tmp/o.csv" 2>"$tmp/d")
				echo "$(basename "$w") seed $seed --slp $slp $st: $d of $n differ"
				cat "$tmp/d"
				[ "$d" = 0 ] || rc=1
			done
		done
	done
done
exit $rc
