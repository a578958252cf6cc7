#!/bin/bash
# cli/outputs.sh - the one output policy (issue 23, "Nothing lost" and
# "Misleading output"; include/slipwall/outfile.h, docs/reliability.md
# "Outputs"), end to end on the real binary.
#
# Usage (from the source root): bash tests/cli/outputs.sh /path/to/slipwall
# Proves: sweep --csv never overwrites the wall (any spelling) and is
# written whole (a full disk leaves the old file); SIGTERM, SIGHUP and
# SIGINT in sweep's output phase (the process held there by a pipe that
# nobody drains) leave whole files and exit 1 with a message; a swept
# value off the wall keeps the values done; --json seeds above 2^63 are
# unsigned; the table escapes a wall's name; report and sweep check
# --out (and sweep --csv) before sampling; a symbolic link to a
# directory is a directory; report never overwrites an input in its
# directory; run --samples to a FIFO that nobody reads says so, and a
# signal during that wait ends it with a message; a signal
# while run or compare writes its JSON to a pipe nobody drains yet leaves
# it whole, with exit 1 and a message.
# Each of these fails on fa21007.  TAP output.

bin=${1:?usage: cli/outputs.sh SLIPWALL}
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh

tmp=$(mktemp -d)
pids=
trap 'for p in $pids; do kill -KILL $p 2>/dev/null; done; rm -rf "$tmp"' EXIT
block=walls/single-block.yaml
cp $block "$tmp/w.yaml"
sweep3="--friction 0.3:0.5:0.1 -n 5 --load-at 0,0.1 --threads 1"

# ---- sweep --csv never over an input -------------------------------------------
ln -s w.yaml "$tmp/sym.yaml"
ln "$tmp/w.yaml" "$tmp/hard.yaml"
for spell in "$tmp/w.yaml" "$tmp/./w.yaml" "$tmp/sym.yaml" "$tmp/hard.yaml"; do
	"$bin" sweep "$tmp/w.yaml" $sweep3 --csv "$spell" >"$tmp/o" 2>"$tmp/e"
	rc=$?
	if [ $rc = 2 ] && cmp -s $block "$tmp/w.yaml" && [ ! -s "$tmp/o" ] &&
	   grep -q "this is the input file" "$tmp/e"; then
		ok "sweep --csv ${spell#$tmp/}: refused before sampling, exit 2, the wall untouched"
	else
		not_ok "sweep --csv ${spell#$tmp/}: refused, the wall untouched" "exit $rc" \
			"$(head -c 300 "$tmp/e")" "$(head -n 2 "$tmp/w.yaml")"
		cp $block "$tmp/w.yaml"
	fi
done

# ---- sweep --csv written whole: a full disk leaves the old file -----------------
"$bin" sweep $block --friction 0.3:0.8:0.01 -n 3 --load-at 0,0.1 --threads 1 \
	--csv "$tmp/full.csv" >/dev/null 2>&1
cp "$tmp/full.csv" "$tmp/full.ref"
(trap '' XFSZ; ulimit -f 2; exec "$bin" sweep $block --friction 0.2:0.7:0.01 -n 3 \
	--load-at 0,0.1 --threads 1 --csv "$tmp/full.csv" >/dev/null 2>"$tmp/e")
rc=$?
if [ $rc = 1 ] && cmp -s "$tmp/full.csv" "$tmp/full.ref" &&
   ! ls "$tmp" | grep -q 'full\.csv\.' && grep -q "full.csv: cannot write: File too large" "$tmp/e"; then
	ok "sweep --csv on a full disk: exit 1, 'File too large', the old CSV byte for byte, no temporary file"
else
	not_ok "sweep --csv on a full disk leaves the old file" "exit $rc" "$(head -c 300 "$tmp/e")" \
		"$(wc -c <"$tmp/full.csv") bytes, was $(wc -c <"$tmp/full.ref"); $(ls "$tmp" | tr '\n' ' ')"
fi

# ---- streams are written, not replaced ---------------------------------------------
# --csv /dev/stdout into a file: the CSV after the table (opening the path
# anew truncated the file: fa21007 left the CSV alone, the table lost)
"$bin" sweep $block $sweep3 --csv /dev/stdout >"$tmp/both" 2>"$tmp/e"
rc=$?
if [ $rc = 0 ] && head -n 1 "$tmp/both" | grep -q '^Single block' &&
   [ "$(grep -c '^0\.[345]  ' "$tmp/both")" = 3 ] && [ "$(grep -c '^friction,samples' "$tmp/both")" = 1 ] &&
   [ "$(tail -n 1 "$tmp/both" | cut -d, -f1)" = 0.5 ]; then
	ok "sweep --csv /dev/stdout > FILE: the table, then the CSV, in FILE"
else
	not_ok "sweep --csv /dev/stdout > FILE keeps the table" "exit $rc" "$(head -n 3 "$tmp/both")"
fi
"$bin" sweep $block $sweep3 --csv /dev/null >/dev/null 2>"$tmp/e"
rc=$?
if [ $rc = 0 ] && [ -c /dev/null ]; then
	ok "sweep --csv /dev/null: exit 0, /dev/null still a device"
else
	not_ok "sweep --csv /dev/null" "exit $rc" "$(head -c 300 "$tmp/e")"
fi

# ---- a signal in sweep's output phase --------------------------------------------
# 1000 values of one sample: the table is 85 KB, more than a pipe holds.
# stdout is a FIFO; its first line read means every value is sampled and
# the output phase has begun; nothing more is read, so the sweep blocks
# writing the table, where the signal finds it; then the FIFO is drained.
set -m	# job control: a background job does not ignore SIGINT
for sig in TERM HUP INT; do
	rm -rf "$tmp/fifo" "$tmp/sig.csv" "$tmp/sigfig"
	mkfifo "$tmp/fifo"
	"$bin" sweep $block --friction 0.001:1:0.001 -n 1 --load-at 0,0.1 --threads 1 \
		--csv "$tmp/sig.csv" --out "$tmp/sigfig" >"$tmp/fifo" 2>"$tmp/sig.err" &
	pid=$!
	pids="$pids $pid"
	exec 3<"$tmp/fifo"
	read -r first <&3
	kill -$sig $pid
	cat <&3 >"$tmp/sig.out"
	exec 3<&-
	wait $pid
	rc=$?
	rows=$(grep -c '^0\.[0-9]* \|^1  ' "$tmp/sig.out")
	csv=$(awk -F, 'NF == 10 { n++ } END { print n + 0 }' "$tmp/sig.csv" 2>/dev/null)
	tmps=$(ls -a "$tmp" "$tmp/sigfig" 2>/dev/null | grep -c 'tmp$')
	if [ $rc = 1 ] && grep -q "^slipwall sweep: interrupted" "$tmp/sig.err" &&
	   [ "$rows" = 1000 ] && [ "$csv" = 1001 ] && [ "$tmps" = 0 ]; then
		ok "SIG$sig in sweep's output phase: exit 1, '$(grep '^slipwall sweep: interrupted' "$tmp/sig.err" | cut -c1-60)...', the table and the CSV whole (1000 values), no temporary file"
	else
		not_ok "SIG$sig in sweep's output phase: whole files, exit 1 with a message" \
			"exit $rc, $rows table rows, $csv CSV lines, $tmps temporary files" \
			"$(head -c 300 "$tmp/sig.err")"
	fi
done
set +m

# ---- a signal while run or compare writes its result -----------------------------
# stdout a pipe of 4 KiB that nobody reads until the process is blocked
# writing its JSON (20 KB for 100 samples of Ferris & Tin-Loi wall 2, its
# mechanisms; 4.7 KB for compare --fit-depth); one signal there, then the pipe is drained: the JSON is
# whole, and the exit is 1 with a message (it was the signal's default:
# killed, the JSON cut at 4,096 bytes, nothing on stderr)
cat >"$tmp/blocked.py" <<'PY'
import fcntl, json, os, signal, subprocess, sys, time
sig, cmd = getattr(signal, sys.argv[1]), sys.argv[2:]
r, w = os.pipe()
fcntl.fcntl(w, 1031, 4096)	# F_SETPIPE_SZ
p = subprocess.Popen(cmd, stdout=w, stderr=subprocess.PIPE)
os.close(w)
blocked, t0 = False, time.time()
while not blocked and p.poll() is None and time.time() - t0 < 240:
    try:
        blocked = 'pipe_w' in open('/proc/%d/wchan' % p.pid).read()
    except OSError:
        break
    time.sleep(0.02)
p.send_signal(sig)
time.sleep(0.5)
out = b''
while True:
    b = os.read(r, 65536)
    if not b:
        break
    out += b
rc, err = p.wait(), p.stderr.read().decode()
try:
    json.loads(out)
    whole = 'whole JSON'
except ValueError:
    whole = 'cut JSON'
print(blocked, rc, whole, err.strip().replace('\n', ' | '))
PY
ft2=walls/ferris-tinloi-2.yaml
for sig in SIGTERM SIGINT SIGHUP; do
	res=$(python3 "$tmp/blocked.py" $sig "$bin" run $ft2 -n 100 --threads 1 --json)
	check "$sig while run writes its JSON: whole, exit 1, 'interrupted ... while writing the summary' ($res)" \
		eval 'case "$res" in "True 1 whole JSON slipwall run: interrupted ("*") while writing the summary: the samples file and the summary are whole") true ;; *) false ;; esac'
done
# compare --fit-depth's JSON on the demo: 4.7 KB
printf '%s\n' 150 160 170 >"$tmp/demo-tests.txt"
res=$(python3 "$tmp/blocked.py" SIGTERM "$bin" compare walls/demo.yaml --tests "$tmp/demo-tests.txt" -n 20 --fit-depth --threads 1 --json)
check "SIGTERM while compare writes its JSON: whole, exit 1, 'interrupted ... while writing the result' ($res)" \
	eval 'case "$res" in "True 1 whole JSON slipwall compare: interrupted (Terminated) while writing the result: it is whole") true ;; *) false ;; esac'

# ---- a swept value off the wall keeps the values done ----------------------------
"$bin" sweep $block --load-at 0,0.1:0,5:5 -n 5 --threads 1 --csv "$tmp/off.csv" \
	>"$tmp/o" 2>"$tmp/e"
rc=$?
if [ $rc = 2 ] && grep -q "value 2 of 5 (--load-at 0,1.325)" "$tmp/e" &&
   grep -q "outside every block" "$tmp/e" && grep -q '^0  *0  *0.1 ' "$tmp/o" &&
   [ "$(wc -l <"$tmp/off.csv")" = 2 ]; then
	ok "a value off the wall: exit 2, 'value 2 of 5 (--load-at 0,1.325)' and why; the value before it printed and in the CSV"
else
	not_ok "a value off the wall keeps the values done" "exit $rc" "$(cat "$tmp/e")" "$(cat "$tmp/o")"
fi

# ---- --json seeds are unsigned --------------------------------------------------
"$bin" sweep $block $sweep3 --json --seed 18446744073709551615 >"$tmp/o" 2>/dev/null
if python3 -c 'import json,sys; sys.exit(json.load(open(sys.argv[1]))["seed"] != 2**64 - 1)' "$tmp/o"; then
	ok "sweep --json --seed 2^64-1: \"seed\": 18446744073709551615"
else
	not_ok "sweep --json seed 2^64-1 unsigned" "$(grep seed "$tmp/o")"
fi

# ---- the table escapes names ------------------------------------------------------
printf 'name: "evil\\e]0;title\\a\\e[2J\\nsecond line\\u009b"\n' >"$tmp/evil.yaml"
grep -v '^name:' $block >>"$tmp/evil.yaml"
"$bin" sweep "$tmp/evil.yaml" $sweep3 >"$tmp/o" 2>"$tmp/e"
rc=$?
if [ $rc = 0 ] && ! python3 -c '
import sys
d = open(sys.argv[1], "rb").read()
sys.exit(0 if any(x in d for x in (b"\x1b", b"\x07", b"\xc2\x9b", b"\nsecond")) else 1)' "$tmp/o" &&
   grep -q 'evil\\e\]0;title\\a' "$tmp/o"; then
	ok "sweep's table prints a name's ESC, BEL, newline and C1 as escapes"
else
	not_ok "sweep's table escapes control characters" "exit $rc" "$(head -n 1 "$tmp/o" | od -c | head -3)"
fi

# ---- --out and --csv checked before sampling -------------------------------------
# the marker of sampling done: report's single solutions (after its
# samples), sweep's table (after every value)
: >"$tmp/afile"
"$bin" report $block -n 5 --threads 1 --out "$tmp/afile/r" >"$tmp/o" 2>"$tmp/e"
rc=$?
if [ $rc = 1 ] && grep -q "afile/r: cannot create: Not a directory" "$tmp/e" &&
   ! grep -q "single solution" "$tmp/e"; then
	ok "report --out under a file: refused before sampling, exit 1"
else
	not_ok "report --out under a file: refused before sampling" "exit $rc" "$(head -c 400 "$tmp/e")"
fi
for out in "--out $tmp/afile" "--out $tmp/afile/d" "--csv $tmp"; do
	"$bin" sweep $block $sweep3 $out >"$tmp/o" 2>"$tmp/e"
	rc=$?
	if [ $rc = 1 ] && [ ! -s "$tmp/o" ] && grep -q "^slipwall sweep: .*cannot" "$tmp/e"; then
		ok "sweep ${out%% *} ${out##*/}: refused before sampling (no table), exit 1"
	else
		not_ok "sweep ${out%% *} ${out##*/}: refused before sampling" "exit $rc" \
			"$(head -c 300 "$tmp/e")" "$(head -n 2 "$tmp/o")"
	fi
done

# ---- a symbolic link to a directory is a directory ---------------------------------
mkdir "$tmp/real"
ln -s real "$tmp/link"
"$bin" report $block -n 5 --threads 1 --out "$tmp/link" >"$tmp/o" 2>"$tmp/e"
rc=$?
if [ $rc = 0 ] && [ -L "$tmp/link" ] && [ -s "$tmp/real/report.md" ] &&
   [ -z "$(ls -A "$tmp" | grep '^\.link\|^\.real')" ]; then
	ok "report --out LINK (a symbolic link to a directory): exit 0, the report in the directory, the link kept"
else
	not_ok "report --out a symbolic link to a directory" "exit $rc" "$(tail -n 2 "$tmp/e")"
fi
"$bin" sweep $block $sweep3 --out "$tmp/link" >/dev/null 2>"$tmp/e"
rc=$?
if [ $rc = 0 ] && [ -L "$tmp/link" ] && [ -s "$tmp/real/sweep.png" ]; then
	ok "sweep --out LINK: exit 0, the figure in the directory"
else
	not_ok "sweep --out a symbolic link to a directory" "exit $rc" "$(tail -n 2 "$tmp/e")"
fi

# ---- report never replaces an input in its directory -------------------------------
mkdir "$tmp/rep"
printf '300\n400\n' >"$tmp/rep/report.md"
cp "$tmp/rep/report.md" "$tmp/tests.ref"
"$bin" report $block -n 5 --threads 1 --tests "$tmp/rep/report.md" --out "$tmp/rep" \
	>"$tmp/o" 2>"$tmp/e"
rc=$?
if [ $rc = 2 ] && cmp -s "$tmp/rep/report.md" "$tmp/tests.ref" &&
   grep -q "this is the input file" "$tmp/e"; then
	ok "report --tests DIR/report.md --out DIR: refused, exit 2, the tests file untouched"
else
	not_ok "report --tests DIR/report.md --out DIR: the input untouched" "exit $rc" \
		"$(head -c 300 "$tmp/e")" "$(head -n 2 "$tmp/rep/report.md")"
fi

# ---- run --samples to a FIFO that nobody reads says so ------------------------------
mkfifo "$tmp/nobody"
"$bin" run $block -n 5 --threads 1 --samples "$tmp/nobody" >"$tmp/fo" 2>"$tmp/fe" &
pid=$!
pids="$pids $pid"
if within 20 grep -qs "nobody: waiting for a process to read this FIFO" "$tmp/fe"; then
	said=1
else
	said=0
fi
cat "$tmp/nobody" >"$tmp/fifo.csv"	# the reader: the run goes on
wait $pid
rc=$?
if [ $said = 1 ] && [ $rc = 0 ] && [ "$(wc -l <"$tmp/fifo.csv")" = 6 ] && [ -p "$tmp/nobody" ]; then
	ok "run --samples FIFO without a reader: 'waiting for a process to read this FIFO', then the 5 rows to the reader"
else
	not_ok "run --samples FIFO without a reader: said, not a silent block" "said $said, exit $rc" \
		"$(head -c 300 "$tmp/fe")"
fi
# ... and a signal during that wait ends it with a message, not in
# silence (it killed the process before)
set -m	# job control: a background job does not ignore SIGINT
for sig in TERM HUP INT; do
	# the last run's stderr said it too: gone, so that the wait below
	# is for this run's message, not for a file not yet truncated (a
	# signal before the handler would kill the process)
	rm -f "$tmp/fe"
	"$bin" run $block -n 5 --threads 1 --samples "$tmp/nobody" >"$tmp/fo" 2>"$tmp/fe" &
	pid=$!
	pids="$pids $pid"
	within 20 grep -qs "nobody: waiting for a process to read this FIFO" "$tmp/fe"
	kill -$sig $pid
	wait $pid
	rc=$?
	if [ $rc = 1 ] && grep -q "slipwall run: .*nobody: interrupted (.*) while waiting for a process to read this FIFO: nothing was written" "$tmp/fe" &&
	   [ -p "$tmp/nobody" ]; then
		ok "SIG$sig while run waits for the FIFO's reader: exit 1, 'interrupted while waiting', the FIFO left"
	else
		not_ok "SIG$sig while run waits for the FIFO's reader: a message" "exit $rc" \
			"$(head -c 300 "$tmp/fe")"
	fi
done
set +m
# ... but not one that was ignored when the run started (nohup): the
# wait blocks the signals it ends on, and an ignored SIGHUP, blocked,
# would stay pending and end it (the last run's stderr removed, as
# above: a SIGHUP before the subshell's trap would end it)
rm -f "$tmp/fe"
(trap '' HUP; exec "$bin" run $block -n 5 --threads 1 --samples "$tmp/nobody") \
	>"$tmp/fo" 2>"$tmp/fe" &
pid=$!
pids="$pids $pid"
within 20 grep -qs "nobody: waiting for a process to read this FIFO" "$tmp/fe"
kill -HUP $pid
sleep 0.5
kill -0 $pid 2>/dev/null && alive=1 || alive=0
# the reader (a run that ended has no writer to meet it: not waited for)
[ $alive = 1 ] && timeout 60 cat "$tmp/nobody" >"$tmp/fifo.csv"
wait $pid
rc=$?
if [ $alive = 1 ] && [ $rc = 0 ] && [ "$(wc -l <"$tmp/fifo.csv")" = 6 ]; then
	ok "an ignored SIGHUP (nohup) while run waits for the FIFO's reader: the wait goes on, then the 5 rows to the reader"
else
	not_ok "an ignored SIGHUP while run waits for the FIFO's reader is ignored" \
		"alive $alive, exit $rc" "$(head -c 300 "$tmp/fe")"
fi

tap_end
