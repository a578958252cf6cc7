#!/bin/bash
# tui/tui_report.sh - the workbench's report (R) after an edit, the
# defaults of save and report beside the opened wall, and Tab in a path
# prompt (issue 27).
#
# After `f` (friction 0.6 -> 0.65) and the run's end, R with its
# default writes DIR/report.md beside the opened wall file: it names
# DIR/wall.yaml, states the edited friction and the edit, says the run
# had ended (not "while sampling"), and gives a command; wall.yaml
# passes `slipwall check`, and the command, run, writes a report with
# the same p05 row.  The save prompt's default is beside the opened
# wall.  In the open prompt, Tab completes a unique prefix; with two
# candidates it completes their common prefix and a second Tab lists
# both above the prompt.
#
# Usage (from the source root): bash tests/tui/tui_report.sh /path/to/slipwall
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_report.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-report-$$" 200 30

msg_has() {	# RE: the message line (above the keys; two rows when long)
	screen w | tail -n 3 | tr '\n' ' ' | grep -qE -- "$1"
}
wait_msg() {	# RE SECONDS
	within "$2" msg_has "$1"
}

# a small copy of the single block in its own directory: 150 samples
mkdir -p "$tmp/walls" "$tmp/c"
sed 's/samples: 1000/samples: 150/' walls/single-block.yaml >"$tmp/walls/blk.yaml"
start w LANG=C.UTF-8 LC_ALL=C.UTF-8 -- "$tmp/walls/blk.yaml"
if ! wait_run w 1 done 60; then
	not_ok "the workbench samples the wall" "$(screen w)"
	tap_end
	exit
fi

T send-keys -t t:w f
if ! wait_run w 2 done 60; then
	not_ok "f starts run 2, which ends" "$(screen w)"
	tap_end
	exit
fi

# R: the default is beside the opened wall
T send-keys -t t:w R
if wait_for w "write report to directory: $tmp/walls/blk-[0-9-]*-2-report" 5; then
	ok "R's default directory is beside the opened wall ($tmp/walls)"
else
	not_ok "R's default directory beside the opened wall" "$(screen w | tail -n 3)"
fi
T send-keys -t t:w Enter
wait_msg 'report of [0-9]+ accepted samples|report: ' 60
rep=$(ls -d "$tmp"/walls/blk-*-2-report 2>/dev/null | head -n 1)
if msg_has 'report of [0-9]+ accepted samples' && [ -s "$rep/report.md" ]; then
	ok "R writes the report beside the wall"
else
	not_ok "R writes the report" "$(screen w | tail -n 3)" "$(ls -R "$tmp/walls")"
fi
md=$rep/report.md

if grep -q "^Written by slipwall .* from \`$rep/wall.yaml\`" "$md" &&
   grep -q "| wall sampled | .*friction bed 0.65, head 0.65 (fixed).*Edited from \`$tmp/walls/blk.yaml\`: friction bed 0.6 → 0.65" "$md" &&
   grep -q 'contact depth d = 0.25' "$md"; then
	ok "report.md names wall.yaml, the edited friction and the edit"
else
	not_ok "report.md states the wall sampled" "$(sed -n '1,4p;/## Run/,/## Figures/p' "$md")"
fi

if grep -q 'after the run ended' "$md" && ! grep -q 'while sampling' "$md"; then
	ok "report.md says the run had ended, not 'while sampling'"
else
	not_ok "report.md: the run's state" "$(grep -i 'workbench' "$md")"
fi

if "$bin" check "$rep/wall.yaml" >/dev/null 2>&1 &&
   "$bin" check "$rep/wall.yaml" 2>&1 | grep -q 'friction.*0.65'; then
	ok "wall.yaml beside the report loads (check) with friction 0.65"
else
	not_ok "wall.yaml loads" "$("$bin" check "$rep/wall.yaml" 2>&1 | head -n 5)"
fi

# the command: the indented line after "To reproduce it:"
cmd=$(awk '/To reproduce it:/ { f = 1; next } f && /^    slipwall / { sub(/^    /, ""); print; exit }' "$md")
case $cmd in
"slipwall report $rep/wall.yaml -n "*" --seed "*" --out $rep-rerun")
	ok "report.md gives the command: $cmd" ;;
*)
	not_ok "report.md gives the reproducing command" "$cmd" ;;
esac
row() {	# the model's row of Table 1
	grep '^| Numerical model |' "$1"
}
if [ -n "$cmd" ] && (eval "\"\$bin\" ${cmd#slipwall }") >/dev/null 2>&1 &&
   [ -n "$(row "$md")" ] && [ "$(row "$md")" = "$(row "$rep-rerun/report.md")" ]; then
	ok "the command reproduces the report's p05 row: $(row "$md")"
else
	not_ok "the command reproduces p05" "$(row "$md")" \
		"$(row "$rep-rerun/report.md" 2>&1)"
fi

# s: the default is beside the opened wall
T send-keys -t t:w s
if wait_for w "save wall as: $tmp/walls/blk-[0-9-]*-2\\.yaml" 5; then
	ok "the save prompt's default is beside the opened wall"
else
	not_ok "the save prompt's default beside the wall" "$(screen w | tail -n 3)"
fi
T send-keys -t t:w Escape
wait_msg cancelled 5

# Tab in the open prompt: a unique prefix, then two candidates
: >"$tmp/c/unique-name.yaml"
: >"$tmp/c/ab1.yaml"
: >"$tmp/c/ab2.yaml"
T send-keys -t t:w o
wait_for w 'open wall file:' 5
T send-keys -t t:w -l "$tmp/c/uni"
T send-keys -t t:w Tab
if wait_for w "open wall file: $tmp/c/unique-name\\.yaml *\$" 5; then
	ok "Tab completes a unique prefix in the open prompt"
else
	not_ok "Tab completes a unique prefix" "$(screen w | tail -n 3)"
fi
T send-keys -t t:w C-u
T send-keys -t t:w -l "$tmp/c/a"
T send-keys -t t:w Tab
if wait_for w "open wall file: $tmp/c/ab *\$" 5; then
	ok "Tab completes the longest common prefix (ab1, ab2: ab)"
else
	not_ok "Tab: the longest common prefix" "$(screen w | tail -n 3)"
fi
T send-keys -t t:w Tab
if wait_for w '^ab1\.yaml  ab2\.yaml' 5; then
	ok "a second Tab lists the candidates above the prompt"
else
	not_ok "a second Tab lists the candidates" "$(screen w | tail -n 4)"
fi
T send-keys -t t:w Escape
T send-keys -t t:w q
tap_end
