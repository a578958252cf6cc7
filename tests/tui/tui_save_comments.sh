#!/bin/bash
# tui/tui_save_comments.sh - a wall saved over the file the workbench
# opened keeps that file's comments (issue 23): open a copy of
# walls/demo.yaml, raise the friction with f, save over the copy with s;
# the file keeps every comment line and every other line, its friction
# line reads 0.85, and slipwall check loads it.
#
# Usage (from the source root): bash tests/tui/tui_save_comments.sh /path/to/slipwall
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_save_comments.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-savecomments-$$" 100 30

cp walls/demo.yaml "$tmp/demo.yaml"
start w LANG=C.UTF-8 LC_ALL=C.UTF-8 -- "$tmp/demo.yaml"
wait_samples w 1 20
T send-keys -t t:w f
wait_for w 'μ 0.85/0.85' 10
prompt w s "save wall as" "$tmp/demo.yaml"
if wait_for w "saved $tmp/demo.yaml" 10; then
	ok "the edited wall is saved over its file"
else
	not_ok "the edited wall is saved over its file" "$(screen w)"
fi
T send-keys -t t:w q
n_old=$(grep -c '^#' walls/demo.yaml)
n_new=$(grep -c '^#' "$tmp/demo.yaml")
if [ "$n_new" = "$n_old" ] && grep -qxF -f <(grep '^#' walls/demo.yaml) "$tmp/demo.yaml" &&
   [ "$(grep -vxF -f <(grep '^#' walls/demo.yaml) "$tmp/demo.yaml" | grep -c '^#')" = 0 ]; then
	ok "all $n_old comment lines of the demo are still there"
else
	not_ok "all $n_old comment lines of the demo are still there" "$n_new comment lines" "$(cat "$tmp/demo.yaml")"
fi
changed=$(diff walls/demo.yaml "$tmp/demo.yaml" | grep '^[<>]')
if [ "$changed" = "$(printf '<   friction: 0.8\n>   friction: 0.85')" ]; then
	ok "only the friction line changed (0.8 -> 0.85)"
else
	not_ok "only the friction line changed" "$changed"
fi
"$bin" check "$tmp/demo.yaml" --json >"$tmp/check.json" 2>&1
if tr -d ' \n' <"$tmp/check.json" | grep -q '"friction":{"bed":0.85,"head":0.85}'; then
	ok "the saved file loads with friction 0.85"
else
	not_ok "the saved file loads with friction 0.85" "$(head -20 "$tmp/check.json")"
fi

tap_end
