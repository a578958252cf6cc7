#!/bin/bash
# tui/tui_joint_mu.sh - the sample browser's joints and their friction
# (docs/workbench.md, "The sample browser"), in tmux at 80x24: on a copy
# of the demo wall with random friction (cov 0.2) and 200 samples, once
# run 1 is done, S opens the browser on sample 200 and > picks joint 1;
# > then steps through every joint of the wall, and each time the
# legend line reads "joint K/N ... μ MU" with MU the samples file's
# mu_K of row 199 (as %.3g), and the sketch has the pick's marker (◆).
# Then Home shows sample 1 and the same joint with row 0's mu_K, ]
# sample 2 with row 1's, and < goes back one joint.  With fixed friction
# (v 0: run 2) the picked joint shows the wall's μ, 0.8.
#
# Usage (from the source root): bash tests/tui/tui_joint_mu.sh SLIPWALL
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_joint_mu.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-jointmu-$$" 80 24

sed -e 's/^  samples: .*/  samples: 200/' \
    -e 's/^  friction: 0\.8$/  friction: {bed: 0.8, head: 0.8, cov: 0.2}/' \
    walls/demo.yaml >"$tmp/demo.yaml"
grep -q 'cov: 0.2' "$tmp/demo.yaml" || not_ok "the demo's friction line is 0.8"
start j LANG=C.UTF-8 LC_ALL=C.UTF-8 -- "$tmp/demo.yaml"
if wait_run j 1 done 120; then
	ok "run 1 done"
else
	not_ok "run 1 done" "$(screen j)"
fi
csv=$(run_csv 1)

# the legend's picked joint: "K N MU" of "joint K/N A|B KIND μ MU ..."
picked() {
	screen j | sed -n 's/^joint \([0-9]*\)\/\([0-9]*\) [^ ]* [a-z]* μ \([0-9.e+-]*\).*/\1 \2 \3/p' |
		head -n 1
}
# csv_mu ROW K: mu_K of data row ROW (the sample column), as %.3g
csv_mu() {
	awk -F, -v row="$1" -v col="mu_$2" '
		NR == 1 { for (i = 1; i <= NF; i++) if ($i == col) c = i; next }
		$1 == row && c { printf "%.3g\n", $c }' "$csv"
}
nif=$(head -n 1 "$csv" | tr , '\n' | grep -c '^mu_')

T send-keys -t t:j S
wait_for j '^sample 200: ' 5
T send-keys -t t:j '>'
if wait_for j '^joint 1/' 5 && screen j | sed -n '3,21p' | grep -q '◆'; then
	ok "S, >: joint 1 picked, marked on the sketch"
else
	not_ok "S, >: joint 1 picked, marked on the sketch" "$(screen j)"
fi

# every joint of sample 200 against row 199 of the samples file
bad=
for k in $(seq 1 "$nif"); do
	[ "$k" = 1 ] || T send-keys -t t:j '>'
	wait_for j "^joint $k/" 5
	read -r kk nn mu <<<"$(picked)"
	want=$(csv_mu 199 "$k")
	if [ "$kk" != "$k" ] || [ "$nn" != "$nif" ] || [ -z "$want" ] ||
	   [ "$mu" != "$want" ]; then
		bad="$bad joint $k: shown '$kk/$nn' '$mu', file mu_$k '$want';"
	fi
done
if [ "$nif" -gt 10 ] && [ -z "$bad" ]; then
	ok "sample 200: the $nif joints' μ on screen are the file's mu_k"
else
	not_ok "sample 200: the $nif joints' μ on screen are the file's mu_k" \
		"$bad $(screen j)"
fi

# > after the last joint goes round to the first; < back to the last
T send-keys -t t:j '>'
wait_for j '^joint 1/' 5
T send-keys -t t:j '<' '<' '<'
if wait_for j "^joint $((nif - 2))/" 5; then
	ok "> goes round, < steps back (joint $((nif - 2)))"
else
	not_ok "> goes round, < steps back" "$(screen j)"
fi

# the same joint in other samples: Home (sample 1), ] (sample 2)
k=$((nif - 2))
T send-keys -t t:j Home
wait_for j '^sample 1: ' 5
read -r k1 n1 mu1 <<<"$(picked)"
T send-keys -t t:j ']'
wait_for j '^sample 2: ' 5
read -r k2 n2 mu2 <<<"$(picked)"
if [ "$k1" = "$k" ] && [ "$k2" = "$k" ] && [ "$mu1" = "$(csv_mu 0 "$k")" ] &&
   [ "$mu2" = "$(csv_mu 1 "$k")" ] && [ "$mu1" != "$mu2" ]; then
	ok "joint $k in samples 1 and 2: μ $mu1, $mu2 as rows 0 and 1"
else
	not_ok "joint $k in samples 1 and 2 as rows 0 and 1" \
		"shown '$k1' '$mu1', '$k2' '$mu2'; file $(csv_mu 0 "$k"), $(csv_mu 1 "$k")"
fi

# fixed friction: the wall's μ
prompt j v 'friction cov \(0\.\.1, 0: fixed\)' 0
wait_run j 2 done 120
read -r kf nf muf <<<"$(picked)"
if [ "$kf" = "$k" ] && [ "$muf" = 0.8 ] &&
   screen j | grep -q '^ S/Esc close .*</> joint'; then
	ok "fixed friction: joint $k shows the wall's μ 0.8; the status line has </> joint"
else
	not_ok "fixed friction: the picked joint shows μ 0.8" "$(screen j)"
fi
T send-keys -t t:j q
tap_end
