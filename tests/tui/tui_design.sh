#!/bin/bash
# tui/tui_design.sh - the workbench's probability of collapse at the
# wall's design load, in tmux: a copy of the demo wall with
# analysis.design_load (the median of a short batch run, so that the
# count is neither 0 nor all) shows "P(λ <= design L) p, k of n" and its
# 99 % interval in the statistics pane once run 1 is done; k and n are
# the run's own samples file's counts (accepted rows with lambda_min <= L,
# accepted rows), p is k/n as a percentage (never in scientific
# notation: src/tui/tui_draw.c, tui_pct), and the interval holds p.  The demo wall
# itself (no design load) has no such line.
#
# Usage (from the source root): bash tests/tui/tui_design.sh SLIPWALL
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_design.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-design-$$" 140 40

load=$("$bin" run walls/demo.yaml -n 40 --json 2>/dev/null |
	python3 -c 'import json, sys; print("%.6g" % json.load(sys.stdin)["lambda"]["p50"])')
sed -e 's/^  samples: .*/  samples: 200/' -e "s/^  seed: .*/&\n  design_load: $load/" \
	walls/demo.yaml >"$tmp/dl.yaml"
grep -q "^  design_load: $load\$" "$tmp/dl.yaml" || echo "# could not add the design load ($load)"

start w LANG=C.UTF-8 LC_ALL=C.UTF-8 -- "$tmp/dl.yaml"
if wait_run w 1 done 120; then
	ok "the wall with a design load: run 1 done"
else
	not_ok "the wall with a design load: run 1 done" "$(screen w)"
fi
line=$(screen w | grep -o 'P(λ <= design [^,]*, [0-9]* of [0-9]*')
ci=$(screen w | grep -o '99 % interval \[[^]]*\] (binomial)')
f=$(run_csv 1)
if python3 -c '
import csv, sys
line, ci, path, load = sys.argv[1:5]
head, counts = line.split(", ")
k, n = (int(x) for x in counts.split(" of "))
shown_load, p = head[len("P(λ <= design "):].split(") ")
rows = [r for r in csv.DictReader(open(path)) if r["status"] == "accepted"]
want_k = sum(float(r["lambda_min"]) <= float(load) for r in rows)
def pct(p):	# tui_pct
    pc = 100 * p
    if pc <= 0: return "0 %"
    if pc >= 100: return "100 %"
    if pc < 0.01: return "< 0.01 %"
    if pc < 0.1: return "%.2f %%" % pc
    if pc >= 99.95: return "> 99.9 %"
    if pc < 1 or pc >= 99.5: return "%.1f %%" % pc
    return "%.0f %%" % pc
def num(s):	# a shown percentage, its sign of bound dropped
    return float(s.strip("<> %"))
lo, hi = (num(x) for x in ci[ci.index("[") + 1:ci.index("]")].split(", "))
ok = (n == len(rows) > 0 and k == want_k and 0 < k < n
      and shown_load == "%.4g" % float(load) and p == pct(k / n)
      and lo - 0.5 <= 100 * k / n <= hi + 0.5)
if not ok:
    print("# shown %s / %s; the file: %d of %d at %s" % (line, ci, want_k, len(rows), load))
sys.exit(not ok)' "$line" "$ci" "$f" "$load"; then
	ok "P(λ <= design load) is the samples file's count, with its 99 % interval"
else
	not_ok "P(λ <= design load) is the samples file's count, with its 99 % interval" "$(screen w)"
fi

start d LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/demo.yaml
if wait_samples d 1 30 && ! screen_has d 'design'; then
	ok "the demo wall (no design load): no such line"
else
	not_ok "the demo wall (no design load): no such line" "$(screen d)"
fi
tap_end
