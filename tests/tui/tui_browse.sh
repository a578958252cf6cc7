#!/bin/bash
# tui/tui_browse.sh - the workbench's sample browser (docs/workbench.md,
# "The sample browser"), in tmux: on a copy of the demo wall with 200
# samples, once run 1 is done, S shows the latest sample, "sample 200",
# its lambda_min in N as the run's samples file has it (row 199, the
# file's lambda_min times the unit, 1 N: the demo's point load), and
# contact points (x) on the wall sketch, which has none before.  Home
# and ] step to samples 1 and 2, each with its own row's load; = shows
# the pair of its mechanism, the least and the largest load, the two
# samples with the same mechanism number and their rows' loads; Esc
# closes the browser.  With random friction (v 0.2: run 2) the legend
# gives the shown sample's least and largest mu.  On walls/body-100.yaml
# (20 samples), = on a sample alone in its mechanism pairs its family.
#
# Usage (from the source root): bash tests/tui/tui_browse.sh SLIPWALL
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_browse.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-browse-$$" 100 30

sed -e 's/^  samples: .*/  samples: 200/' walls/demo.yaml >"$tmp/demo.yaml"
start b LANG=C LC_ALL=C -- "$tmp/demo.yaml"
if wait_run b 1 done 120; then
	ok "run 1 done"
else
	not_ok "run 1 done" "$(screen b)"
fi
csv=$(run_csv 1)

# The wall pane's rows (its label and legend left out), its columns.
wall_rows() {
	screen b | sed -n '3,27p' | cut -c1-55
}
# The browser's label: "N STATUS LOAD [K/M]" of "sample N: STATUS
# lam_min LOAD N, mechanism K/M"
shown() {
	screen b | sed -n '2p' | sed -n \
		's/^sample \([0-9]*\): \([a-z_]*\) lam_min \([0-9.e+-]*\) N\(, mechanism \([0-9]*\/[0-9]*\)\)\{0,1\}.*/\1 \2 \3 \5/p'
}
# The load of sample N (1 first) in the samples file, as the browser
# writes it (%.4g, in N: the demo's unit is 1 N)
csv_load() {
	awk -F, -v i="$(($1 - 1))" 'NR > 1 && $1 == i { printf "%.4g\n", $4 }' "$csv"
}

if [ "$(wall_rows | grep -c x)" -eq 0 ]; then
	ok "no contact marker on the wall before the browser"
else
	not_ok "no contact marker on the wall before the browser" "$(screen b)"
fi

T send-keys -t t:b S
wait_for b '^sample 200: ' 5
read -r s0 st lam mech <<<"$(shown)"
if [ "$s0" = 200 ] && [ -n "$lam" ] && [ "$lam" = "$(csv_load 200)" ]; then
	ok "S: sample 200, lambda_min $lam N as its row of the samples file"
else
	not_ok "S: sample 200, lambda_min $lam N as its row of the samples file" \
		"shown '$s0' '$st' '$lam'; file $(csv_load 200); $(screen b)"
fi
if [ "$(wall_rows | grep -o x | wc -l)" -ge 10 ] &&
   screen b | sed -n '28p' | grep -q '^x contact'; then
	ok "S: contact points (x) on the wall sketch"
else
	not_ok "S: contact points (x) on the wall sketch" "$(screen b)"
fi

T send-keys -t t:b Home
wait_for b '^sample 1: ' 5
read -r n1 st1 lam1 mech1 <<<"$(shown)"
T send-keys -t t:b ']'
wait_for b '^sample 2: ' 5
read -r n2 st2 lam2 mech2 <<<"$(shown)"
if [ "$n1" = 1 ] && [ "$n2" = 2 ] && [ "$lam1" = "$(csv_load 1)" ] &&
   [ "$lam2" = "$(csv_load 2)" ]; then
	ok "Home, ]: samples 1 and 2, each with its row's load ($lam1, $lam2 N)"
else
	not_ok "Home, ]: samples 1 and 2, each with its row's load" \
		"shown '$n1' '$lam1', '$n2' '$lam2'; file $(csv_load 1), $(csv_load 2)"
fi

T send-keys -t t:b '='
wait_for b '^pair: mechanism ' 5
msg=$(screen b | grep '^pair: ')
pa=$(printf '%s\n' "$msg" | sed -n 's/.*(sample \([0-9]*\)) \.\. .*/\1/p')
pb=$(printf '%s\n' "$msg" | sed -n 's/.*\.\. .*(sample \([0-9]*\)).*/\1/p')
# the least first, or the largest when sample 2 is the least; then
# the other one
wait_for b "^sample ($pa|$pb): " 5
read -r n1 st1 l1 m1 <<<"$(shown)"
other=$pa
[ "$n1" = "$pa" ] && other=$pb
T send-keys -t t:b '='
wait_for b "^sample $other: " 5
read -r n2 st2 l2 m2 <<<"$(shown)"
if [ "$n1" = "$pa" ]; then
	lo=$l1 hi=$l2
else
	lo=$l2 hi=$l1
fi
if [ -n "$pa" ] && [ -n "$pb" ] && [ "$pa" != "$pb" ] &&
   [ "$n2" = "$other" ] && [ -n "$m1" ] && [ "$m1" = "$m2" ] &&
   [ "$m1" = "$mech2" ] &&
   [ "$lo" = "$(csv_load "$pa")" ] && [ "$hi" = "$(csv_load "$pb")" ] &&
   awk -v a="$lo" -v b="$hi" -v c="$lam2" \
	'BEGIN { exit !(a + 0 <= c + 0 && c + 0 <= b + 0 && a + 0 < b + 0) }'; then
	ok "=: samples $pa and $pb, sample 2's mechanism $m1, loads $lo .. $hi N"
else
	not_ok "=: the pair of sample 2's mechanism" \
		"'$msg': shown '$n1' '$m1' '$l1', '$n2' '$m2' '$l2'; sample 2 '$mech2' '$lam2'"
fi

T send-keys -t t:b Escape
if wait_for b '^latest mechanism \(sample 200\)' 5 &&
   [ "$(wall_rows | grep -c x)" -eq 0 ]; then
	ok "Esc closes the browser"
else
	not_ok "Esc closes the browser" "$(screen b)"
fi
# random friction: the legend has the shown sample's least and largest mu
prompt b v 'friction cov \(0\.\.1, 0: fixed\)' 0.2
if wait_run b 2 done 120; then
	T send-keys -t t:b S
	wait_for b '^sample 200: ' 5
fi
if screen b | sed -n '28p' |
   grep -qE '^x contact  mu [0-9.]+\.\.[0-9.]+  joints [.shHo]+'; then
	ok "random friction: the sample's mu range in the legend"
else
	not_ok "random friction: the sample's mu range in the legend" "$(screen b)"
fi
T send-keys -t t:b q

# = on a wall of real size: walls/body-100.yaml (105 blocks), 20
# samples.  Nearly every sample has joint states of its own; on one
# that is the only one of its mechanism, = pairs its family instead
# (the same moving region): the least and the largest load of the
# family's samples.  Which sample that is, and its family, come from
# `run --replay` of run 1's samples file (its JSON's mechanisms: count
# 1, and the family number).
export SLIPWALL_RUNS=$tmp/runs-body
sed -e 's/^  samples: .*/  samples: 20/' walls/body-100.yaml >"$tmp/body.yaml"
start f LANG=C LC_ALL=C -- "$tmp/body.yaml"
if wait_run f 1 done 300; then
	ok "body-100: run 1 done"
else
	not_ok "body-100: run 1 done" "$(screen f)"
fi
bcsv=$(run_csv 1)
"$bin" run "$tmp/body.yaml" --replay "$bcsv" --threads 2 --json >"$tmp/body.json" 2>/dev/null
# "INDEX FAMILY LO_SAMPLE LO HI_SAMPLE HI": a sample (1 first) alone in
# its mechanism, its family, and that family's least and largest load
# (%.4g) with their samples (the earliest of equal loads)
read -r one fam plo llo phi lhi <<<"$(python3 - "$bcsv" "$tmp/body.json" <<'PY'
import csv, json, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if r["status"] == "accepted"]
d = json.load(open(sys.argv[2]))
lam = {int(r["sample"]): float(r["lambda_min"]) for r in rows}
for m in d["mechanisms"]:
    if m["count"] != 1:
        continue
    one = [i for i, x in lam.items() if x == m["lambda_lo"]]
    if len(one) != 1:
        continue
    # its family (0 first in the JSON, by frequency, as the workbench's
    # numbers are 1 first) and that family's least and largest loads
    f = d["families"][m["family"]]
    lo = min(i for i, x in lam.items() if x == f["lambda_lo"])
    hi = min(i for i, x in lam.items() if x == f["lambda_hi"])
    print(one[0] + 1, m["family"] + 1, lo + 1, "%.4g" % lam[lo], hi + 1, "%.4g" % lam[hi])
    break
PY
)"
T send-keys -t t:f S
wait_for f '^sample 20: ' 5
T send-keys -t t:f Home
wait_for f '^sample 1: ' 5
for ((i = 1; i < ${one:-1}; i++)); do
	T send-keys -t t:f ']'
	wait_for f "^sample $((i + 1)): " 5
done
T send-keys -t t:f '='
wait_for f '^pair: ' 5
msg=$(screen f | grep '^pair: ')
if [ -n "$one" ] && [ "$plo" != "$phi" ] &&
   printf '%s\n' "$msg" | grep -qE "^pair: family $fam/[0-9]+, lam_min $llo \(sample $plo\) \.\. $lhi \(sample $phi\); = alternates"; then
	ok "body-100, sample $one (alone in its mechanism): = pairs family $fam, samples $plo and $phi"
else
	not_ok "body-100: = on a sample alone in its mechanism pairs its family" \
		"'$msg'; expected family $fam, $llo (sample $plo) .. $lhi (sample $phi), from sample $one"
fi
T send-keys -t t:f q
tap_end
