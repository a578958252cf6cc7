#!/bin/bash
# same-outputs.sh - do two builds of slipwall write the same files?
#
#   bash scripts/same-outputs.sh OLD_SLIPWALL NEW_SLIPWALL
#
# For reshaping the code without changing what it computes (issue 15):
# `check`, `run`, `compare` and `report` on the bundled walls with fixed
# seeds, by each binary, in directories of the same name (outputs name
# their files); every file compared byte for byte, after dropping the
# lines that carry a clock (elapsed_seconds, samples_per_second,
# seconds, the report's timing line) and the version string.  Prints
# one line per command and "same-outputs: N same, M different"; exits 1
# if any differ.  Run from the source root; about a minute.
old=$(realpath "${1:?usage: same-outputs.sh OLD NEW}")
new=$(realpath "${2:?usage: same-outputs.sh OLD NEW}")
cd "$(dirname "$0")/.." || exit 2
root=$PWD
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
walls="demo ferris-tinloi-1 ferris-tinloi-2 single-block two-block-stack clamp-pull"
cmds=()
for w in $walls large; do
	cmds+=("check $root/walls/$w.yaml" "check --json $root/walls/$w.yaml")
done
for w in $walls; do
	cmds+=("run $root/walls/$w.yaml -n 120 --seed 11 --threads 2 --samples run.csv --json")
done
cmds+=("run $root/walls/demo.yaml -n 60 --seed 5 --threads 1 --samples run.csv --until-ci 0.5"
       "run $root/walls/demo.yaml -n 40 --seed 2 --samples run.csv --at 150 --friction 0.7 --json"
       "compare $root/walls/demo.yaml --tests $root/walls/demo-loads.txt -n 150 --seed 4 --json"
       "compare $root/walls/ferris-tinloi-1.yaml --tests $root/walls/demo-loads.txt -n 100 --seed 9"
       "report $root/walls/demo.yaml --out rep -n 120 --seed 6 --tests $root/walls/demo-loads.txt"
       "report $root/walls/two-block-stack.yaml --out rep -n 60 --seed 1")
# lines with a clock or the version in them
clock='elapsed|per_second|seconds|"version"|[0-9.]+ s\b|samples/s|took|Generated|generated'
same=0 diff=0
for c in "${cmds[@]}"; do
	for b in old new; do
		mkdir -p "$tmp/$b" && rm -rf "${tmp:?}/$b/"*
		bin=$old; [ $b = new ] && bin=$new
		# shellcheck disable=SC2086
		(cd "$tmp/$b" && "$bin" $c >stdout 2>stderr; echo "exit $?" >>stdout)
		find "$tmp/$b" -type f \( -name '*.png' -o -name '*.pdf' \) -delete
		find "$tmp/$b" -type f | while read -r f; do
			grep -avE "$clock" "$f" >"$f.k"; mv "$f.k" "$f"
		done
	done
	if diff -r "$tmp/old" "$tmp/new" >"$tmp/d"; then
		same=$((same + 1)); echo "same       $c"
	else
		diff=$((diff + 1)); echo "DIFFERENT  $c"; head -n 8 "$tmp/d" | sed 's/^/    /'
	fi
done
echo "same-outputs: $same same, $diff different"
[ "$diff" -eq 0 ]
