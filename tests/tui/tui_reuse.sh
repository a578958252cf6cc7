#!/bin/bash
# tui/tui_reuse.sh - `report --samples X.csv` reuses the workbench's
# single solutions from X.json only for the model they were computed on
# (docs/report.md), in tmux: the workbench on walls/single-block.yaml
# (depth 0, its load's magnitude 2) saves X.yaml and X.json beside its
# samples X.csv; X.json's wall_digest is check --json's of X.yaml, its
# standard is the force, 209.28 N, and report takes it from there into
# report.md as 209.28 N; then X.yaml is edited in place (the same device and inode:
# its load moved from 0.6 m to 0.3 m up, where the block slides first,
# at mu W = 376.704 N) and report recomputes: report.md's standard is
# 376.7 N (%.5g), not the saved 209.28 N.
#
# Usage (from the source root): bash tests/tui/tui_reuse.sh SLIPWALL
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_reuse.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-reuse-$$" 140 40

sed -e 's/depth: 0.25/depth: 0/' -e 's/^  samples: .*/  samples: 30/' \
	-e 's/magnitude: 1}/magnitude: 2}/' walls/single-block.yaml >"$tmp/block.yaml"
start w LANG=C LC_ALL=C -- "$tmp/block.yaml"
if wait_run w 1 done 60 && wait_for w 'standard 209' 30; then
	ok "run 1 and the single solutions done"
else
	not_ok "run 1 and the single solutions done" "$(screen w)"
fi
csv=$(run_csv 1)
x=${csv%.csv}
# saved beside the samples file (the prompt's default is beside the
# opened wall: docs/workbench.md), so that X.json is found from X.csv
prompt w s 'save wall as' "$x.yaml"
if wait_for w "saved " 5 && [ -s "$x.json" ] && [ -s "$x.yaml" ]; then
	ok "s writes X.yaml and X.json beside X.csv"
else
	not_ok "s writes X.yaml and X.json beside X.csv" "$(screen w)" "$(ls "$SLIPWALL_RUNS")"
fi
T send-keys -t t:w q
digest=$("$bin" check "$x.yaml" --json 2>/dev/null |
	python3 -c 'import json, sys; print(json.load(sys.stdin)["wall_digest"])')
if grep -q "^  \"wall_digest\": \"$digest\",\$" "$x.json"; then
	ok "X.json's wall_digest is the saved wall's ($digest)"
else
	not_ok "X.json's wall_digest is the saved wall's ($digest)" "$(cat "$x.json")"
fi
"$bin" report "$x.yaml" --samples "$csv" --out "$tmp/r1" >/dev/null 2>"$tmp/r1.err"
check "report --samples: standard taken from X.json, 209.28 N" \
	eval 'grep -q "^  \"standard\": 209.28" "$x.json" &&
	      grep -q "^report: standard: 209.28, from .*json (not recomputed)" "$tmp/r1.err" &&
	      grep -q "^| standard | 209.28 N | from " "$tmp/r1/report.md"'

# edit in place: the same inode, the load lower
python3 - "$x.yaml" <<'PY'
import re, sys
t = open(sys.argv[1]).read()
t2 = re.sub(r"at: \[0, 0\.6\]", "at: [0, 0.3]", t)
assert t2 != t
with open(sys.argv[1], "r+") as f:
    f.write(t2)
    f.truncate()
PY
"$bin" report "$x.yaml" --samples "$csv" --out "$tmp/r2" >/dev/null 2>"$tmp/r2.err"
if grep -q "^| standard | 376.7 N |" "$tmp/r2/report.md" &&
   ! grep -q "209.28 N | from" "$tmp/r2/report.md" &&
   grep -q "^report: standard: computing" "$tmp/r2.err"; then
	ok "X.yaml edited in place: standard recomputed, 376.7 N"
else
	not_ok "X.yaml edited in place: standard recomputed, 376.7 N" "$(cat "$tmp/r2.err")" "$(grep '^| ' "$tmp/r2/report.md")"
fi
tap_end
