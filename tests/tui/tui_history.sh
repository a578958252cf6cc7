#!/bin/bash
# tui/tui_history.sh - the workbench's run history, in tmux: after two
# edits the H screen has three runs with their friction and their p05
# (each checked against the run's own samples file: the 5 % quantile,
# type 7, of its accepted lambda_min), the histogram outlines the
# previous run, q prints the history and every file written (samples,
# the saved wall and its summary, the report), and the index file
# beside the samples files keeps the rows for the next session.
#
# Usage (from the source root): bash tests/tui/tui_history.sh /path/to/slipwall
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_history.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-history-$$" 100 40

# the H screen's three lines of run N: "mu p05" (mu bed)
hist_row() {
	screen w | awk -v r="$1" '
		$0 ~ "^[ >] *" r " " { found = 1; k = 0; next }
		found && k == 0 { k = 1; split($0, a, " "); mu = a[2]; next }
		found && k == 1 { for (i = 1; i <= NF; i++) if ($i == "p05") p = $(i + 1)
				  print mu, p; exit }'
}

start w LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/clamp-pull.yaml
wait_samples w 1 20
# run 1 ends at its count; the two edits' runs have 40 samples each
T send-keys -t t:w n C-u 40 Enter
wait_for w 'run 1 done' 60
T send-keys -t t:w f
wait_run w 2 done 60
T send-keys -t t:w e
if wait_run w 3 done 60; then
	ok "two edits: runs 2 and 3 done"
else
	not_ok "two edits: runs 2 and 3 done" "$(screen w)"
fi
if screen_has w "histogram \([0-9]+ accepted; ═ run 2\)"; then
	ok "the histogram outlines the previous run (run 2)"
else
	not_ok "the histogram outlines the previous run" "$(screen w)"
fi

T send-keys -t t:w H
wait_for w '^ run history: 3 runs this session' 5
want_mu=(0.6 0.65 0.65)
for r in 1 2 3; do
	row=$(hist_row $r)
	mu=${row% *}
	p=${row#* }
	f=$(run_csv $r)
	want=$(csv_p05 "$f")
	if [ "$mu" = "${want_mu[$((r - 1))]}/${want_mu[$((r - 1))]}" ] && [ -n "$p" ] && [ "$p" = "$want" ]; then
		ok "history row of run $r: μ $mu, p05 $p (its samples file: $want)"
	else
		not_ok "history row of run $r: μ $mu, p05 $p (its samples file: $want)" "$(screen w)"
	fi
done
if screen_has w '^> +3 contact depth 0\.3 \(this run\)' && screen_has w '^ +2 friction bed 0\.65, head 0\.65 '; then
	ok "each row says what the run changed"
else
	not_ok "each row says what the run changed" "$(screen w)"
fi
T send-keys -t t:w Escape
wait_for w 'samples  ' 5

# files: a saved wall (and its summary), a report
prompt w s 'save wall as' "$tmp/saved.yaml"
wait_for w "saved .*saved\.yaml" 10
prompt w R 'write report to directory' "$tmp/rep"
wait_for w 'report of [0-9]+ accepted samples' 30

T send-keys -t t:w q
if wait_for w '^history: ' 10; then
	out=$(T capture-pane -p -S -200 -t t:w)
	if printf '%s\n' "$out" | grep -q '^run history (3 runs):' &&
	   printf '%s\n' "$out" | grep -q "^wall: $tmp/saved.yaml\$" &&
	   printf '%s\n' "$out" | grep -q "^summary: $tmp/saved.json\$" &&
	   printf '%s\n' "$out" | grep -q "^report: $tmp/rep/report.md\$" &&
	   [ "$(printf '%s\n' "$out" | grep -c "^samples: $SLIPWALL_RUNS/clamp-pull-.*\.csv\$")" -eq 3 ]; then
		ok "q prints the history and every file written"
	else
		not_ok "q prints the history and every file written" "$out"
	fi
else
	not_ok "q prints the history" "$(screen w)"
fi
idx=$SLIPWALL_RUNS/history.tsv
if [ "$(grep -c "$SLIPWALL_RUNS/clamp-pull-" "$idx")" -eq 3 ]; then
	ok "the index file has the three runs"
else
	not_ok "the index file has the three runs" "$(cat "$idx")"
fi

# a new session shows them as earlier sessions
start v LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/clamp-pull.yaml
wait_samples v 1 20
T send-keys -t t:v H
if wait_for v '^earlier sessions' 5 && [ "$(screen v | grep -cE '^ [0-9]{8}-[0-9]{6} +[123] ')" -eq 3 ]; then
	ok "the next session shows the three runs of the first"
else
	not_ok "the next session shows the three runs of the first" "$(screen v)"
fi
T send-keys -t t:v Escape q
wait_for v '^history: ' 10
tap_end
