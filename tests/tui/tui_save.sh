#!/bin/bash
# tui/tui_save.sh - where the workbench's save (s) and report (R) may
# write: the output policy (include/slipwall/outfile.h, issue 23).
# A save onto the run's own samples file, a FIFO or a device node is
# refused with a message and the file stays what it was (each replaced
# it on fa21007: the samples by YAML, the FIFO and the device by a
# regular file); R into a path under a file is refused at once; a
# plain save still writes the wall and its summary.
#
# Usage (from the source root): bash tests/tui/tui_save.sh /path/to/slipwall
# TAP output; skips when tmux is missing.

bin=${1:?usage: tui/tui_save.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
. tests/tui/tui_lib.sh
tui_setup "slipwall-save-$$" 220 30

save_as() {	# PATH: through the s prompt
	prompt w s 'save wall as' "$1"
}
msg_has() {	# RE: the message line (above the keys; two rows when long)
	screen w | tail -n 3 | tr '\n' ' ' | grep -qE -- "$1"
}
wait_msg() {	# RE SECONDS
	within "$2" msg_has "$1"
}
msg() {
	screen w | tail -n 3 | head -n 2
}

start w LANG=C.UTF-8 LC_ALL=C.UTF-8 -- walls/single-block.yaml
if ! wait_samples w 2 30; then
	not_ok "the workbench samples" "$(screen w)"
	tap_end
	exit
fi
csv=$(run_csv 1)

# the samples file being streamed
save_as "$csv"
if wait_msg 'nothing saved' 5 && msg_has 'input file' &&
   head -n 1 "$csv" | grep -q '^sample,status,' && csv_complete "$csv"; then
	ok "save onto the run's own samples file: refused ('...input file...nothing saved'), the samples intact"
else
	not_ok "save onto the run's samples file: refused, the samples intact" \
		"$(msg)" "$(head -c 120 "$csv")"
fi

# a FIFO
mkfifo "$tmp/f.yaml"
save_as "$tmp/f.yaml"
if wait_msg 'nothing saved' 5 && msg_has 'a FIFO' && [ -p "$tmp/f.yaml" ] &&
   [ ! -e "$tmp/f.json" ]; then
	ok "save onto a FIFO: refused ('a FIFO'), still a FIFO, no summary"
else
	not_ok "save onto a FIFO: refused, still a FIFO" "$(msg)" \
		"$(ls -l "$tmp" | grep ' f\.')"
fi

# a device node (made here: mknod needs root)
if mknod "$tmp/null.yaml" c 1 3 2>/dev/null; then
	save_as "$tmp/null.yaml"
	if wait_msg 'nothing saved' 5 && msg_has 'character device' &&
	   [ -c "$tmp/null.yaml" ]; then
		ok "save onto a device node: refused ('a character device'), still a device"
	else
		not_ok "save onto a device node: refused, still a device" \
			"$(msg)" "$(ls -l "$tmp/null.yaml")"
	fi
else
	ok "save onto a device node # SKIP mknod needs root"
fi

# the summary beside the wall is checked before the wall is written
mkdir "$tmp/s.json"
save_as "$tmp/s.yaml"
if wait_msg 's\.json: cannot write: Is a directory: nothing saved' 5 && [ ! -e "$tmp/s.yaml" ]; then
	ok "a directory where the summary goes: refused before the wall is written"
else
	not_ok "the summary's path checked before the wall is written" "$(msg)" \
		"$(ls "$tmp")"
fi

# R into a path under a file
: >"$tmp/afile"
prompt w R 'write report to directory' "$tmp/afile/r"
if wait_msg 'report: .*afile/r: cannot create: Not a directory' 5; then
	ok "R under a file: 'cannot create: Not a directory'"
else
	not_ok "R under a file: a clear refusal" "$(msg)"
fi

# and a plain save still writes both
save_as "$tmp/ok.yaml"
if wait_msg 'saved .*ok\.yaml' 5 && "$bin" check "$tmp/ok.yaml" >/dev/null 2>&1 &&
   [ -s "$tmp/ok.json" ]; then
	ok "a plain save: the wall (which check accepts) and its summary"
else
	not_ok "a plain save writes the wall and the summary" "$(msg)"
fi

T send-keys -t t:w q
tap_end
