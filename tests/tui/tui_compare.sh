#!/bin/bash
# tui/tui_compare.sh - what-if studies in the workbench, in tmux: each
# run keeps its wall beside its samples file (X.yaml beside X.csv, a
# wall `check` loads); after an edit the p05 line says the previous
# run's p05 and the change in %, and the histogram labels the previous
# run's outline; in H two marked runs show Δp05, Δp50, Δp95 and a KS
# line whose D is the one `slipwall compare WALL --samples A --against
# B` prints; `o` on a row reopens that run's wall (its friction in the
# title), the unsaved edit's too; after a load moved far the histogram's
# axis spans the current run and the outline is clipped.
#
# Usage (from the source root): bash tests/tui/tui_compare.sh /path/to/slipwall
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_compare.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-compare-$$" 100 36


sed -e 's/^  samples: .*/  samples: 200/' walls/demo.yaml >"$tmp/demo.yaml"
start w LANG=C.UTF-8 LC_ALL=C.UTF-8 -- "$tmp/demo.yaml"
wait_run w 1 done 60
T send-keys -t t:w f
if wait_run w 2 done 60 && title w | grep -q 'μ 0\.85/0\.85'; then
	ok "an edit (f): run 2 done at μ 0.85"
else
	not_ok "an edit (f): run 2 done at μ 0.85" "$(screen w)"
fi

# 1. each run's wall beside its samples file
c1=$(run_csv 1)
c2=$(run_csv 2)
y1=${c1%.csv}.yaml
y2=${c2%.csv}.yaml
if [ -f "$y1" ] && [ -f "$y2" ] && "$bin" check "$y1" >/dev/null 2>&1 &&
   grep -q '^  friction: 0\.8$' "$y1" && grep -q '^  friction: 0\.85$' "$y2"; then
	ok "each run keeps its wall beside its samples file (μ 0.8, 0.85)"
else
	not_ok "each run keeps its wall beside its samples file" \
		"$(ls "$SLIPWALL_RUNS")" "$(grep friction "$y1" "$y2" 2>&1)"
fi

# 4. the p05 line against the previous run, the outline labelled
p1=$(csv_p05 "$c1")
p2=$(csv_p05 "$c2")
want=$(awk -v a="$p1" -v b="$p2" 'BEGIN { r = 100 * (b - a) / a
	m = r < 0 ? -r : r; s = r > 0 ? "+" : r < 0 ? "−" : ""
	printf "%s%.*f %%", s, (m >= 10 || m == 0) ? 0 : 1, m }')
if screen_has w "p05 $p2 \\(run 1: $p1, $want\\)"; then
	ok "the p05 line: p05 $p2 (run 1: $p1, $want)"
else
	not_ok "the p05 line: p05 $p2 (run 1: $p1, $want)" "$(screen w)"
fi
if screen_has w 'histogram \([0-9]+( accepted)?; ═ run 1' &&
   screen w | sed -n '16,32p' | grep -q '═'; then
	ok "the histogram labels and draws the previous run's outline (═)"
else
	not_ok "the histogram labels and draws the previous run's outline" "$(screen w)"
fi

# 2. H: mark both runs, compare
T send-keys -t t:w H
wait_for w '^ run history: 2 runs this session' 5
T send-keys -t t:w Space
wait_for w 'mark another with Space' 5
T send-keys -t t:w k Space
cli=$("$bin" compare "$tmp/demo.yaml" --samples "$c1" --against "$c2")
d=$(printf '%s\n' "$cli" | awk '$1 == "D" { printf "%.4g\n", $3 }')
if wait_for w '^KS B vs A: D [0-9.]+  p [0-9.<]+ ?[0-9.]* %  p B < A ' 10 &&
   screen_has w "^KS B vs A: D $d " &&
   screen_has w '^Δp05 [−+]?[0-9.]+ \([−+]?[0-9.]+ %\)  Δp50 .*  Δp95 ' &&
   screen_has w '^compare: A run 1 \(μ 0\.8/0\.8\)  B run 2 \(μ 0\.85/0\.85\)' &&
   screen_has w "p05 A $p1 B $p2"; then
	ok "H: two marked runs: Δp05, Δp50, Δp95, KS D $d (as slipwall compare)"
else
	not_ok "H: two marked runs compared (KS D $d)" "$(screen w)" "$cli"
fi
if screen_has w '^ A 1 ' && screen_has w '^>B 2 '; then
	ok "H: the marked rows say A and B"
else
	not_ok "H: the marked rows say A and B" "$(screen w)"
fi

# 3. reopen run 1's wall (the cursor is on it), then the unsaved edit's
T send-keys -t t:w o
if wait_for w 'reopened run 1.s wall' 5 && wait_run w 3 '[a-z]+' 5 &&
   title w | grep -q 'μ 0\.8/0\.8'; then
	ok "o in H reopens run 1's wall: μ 0.8 in the title, run 3"
else
	not_ok "o in H reopens run 1's wall" "$(screen w)"
fi
wait_run w 3 done 60
# run 3's files are named by the wall it came from (demo-STAMP-3.csv),
# not by run 1's file name and a second stamp
c3=$(run_csv 3)
if [ -n "$c3" ] && basename "$c3" | grep -qE '^demo-[0-9]{8}-[0-9]{6}-3(\.[0-9]+)?\.csv$'; then
	ok "the reopened wall's run is named demo-STAMP-3.csv ($(basename "$c3"))"
else
	not_ok "the reopened wall's run is named demo-STAMP-3.csv" "$c3"
fi
T send-keys -t t:w H
wait_for w '^ run history: 3 runs this session' 5
T send-keys -t t:w k Enter
if wait_for w 'reopened run 2.s wall' 5 && title w | grep -q 'μ 0\.85/0\.85'; then
	ok "Enter reopens the unsaved edit's wall (run 2): μ 0.85"
else
	not_ok "Enter reopens the unsaved edit's wall (run 2)" "$(screen w)"
fi

# a run without a wall file: H says so and stays
wait_run w 4 done 60
rm -f "$y1"
T send-keys -t t:w H
wait_for w '^ run history: 4 runs this session' 5
T send-keys -t t:w k k k o
if wait_for w 'run 1: .*no wall kept for this run' 5 &&
   screen_has w '^ run history'; then
	ok "a run whose wall file is gone: H says so and stays open"
else
	not_ok "a run whose wall file is gone" "$(screen w)"
fi
T send-keys -t t:w Escape
wait_for w 'samples  ' 5

# the axis follows the current run: the load moved low on the end face
# (loads of about 35..90 N after 80..500 N) spans it alone, and the
# title says how much of the previous run's outline is off the axis
prompt w P 'dx,dy\]' '0.6,0.0875'
wait_run w 5 done 60
lo=$(screen w | grep -A1 -E '│─+' | tail -n 1 | sed 's/^.*│\([0-9.]*\).*/\1/')
min=$(screen w | sed -n 's/.*λ min  *\([0-9.]*\) .*/\1/p')
if screen_has w 'histogram \([0-9]+( accepted)?; ═ run 4: [0-9.]+ % off ▸\)' &&
   [ -n "$lo" ] && [ "$lo" = "$min" ]; then
	ok "a moved load: the axis starts at the run's λ min ($min), run 4's outline clipped"
else
	not_ok "a moved load: the axis follows the current run (axis $lo, min $min)" "$(screen w)"
fi
T send-keys -t t:w q
wait_for w '^history: ' 10
tap_end
