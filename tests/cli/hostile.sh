#!/bin/bash
# cli/hostile.sh - what a careful but unlucky user does to the files
# (issue 16, "data loss and corruption" and "limits and the terminal").
#
# Usage (from the source root): bash tests/cli/hostile.sh /path/to/slipwall
# Proves: report takes paths of any length (no fixed buffer); --samples
# never destroys an input, however its path is spelled, and a second run
# on the same samples file is refused (exit 2); a SIGKILL in the middle
# of a row write larger than a page leaves a cut last row that every
# reader drops with a warning; SIGTERM during report leaves the report
# directory complete or as it was; the readers of --positions, --tests
# and compare --samples are bounded (/dev/zero, a file too large);
# an old samples file is replaced by a header already on the disk
# (fsync before rename, seen by strace); -n 1 --threads 1000 starts one
# worker and a --threads the memory cannot hold is refused; control
# characters in names and invalid UTF-8 in paths never reach the
# terminal, report.md or the JSON raw; a closed samples pipe is a clear
# error; an empty tests: list and hexadecimal tests are told apart.  TAP output.  Needs python3 and strace.

bin=${1:?usage: cli/hostile.sh SLIPWALL}
case $bin in /*) ;; *) bin=$PWD/$bin ;; esac
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh

tmp=$(mktemp -d)
pids=
trap 'for p in $pids; do kill -KILL $p 2>/dev/null; done; rm -rf "$tmp"' EXIT
demo=walls/demo.yaml
two=walls/two-block-stack.yaml

# ---- report: paths of any length -------------------------------------------
# The command line of report.md was built in a 2 KB stack buffer: a
# longer path overflowed it (a crash).  Paths of 2.5 KB here.
long="$tmp"
for _ in 1 2 3 4 5 6 7 8 9 10 11 12; do
	long="$long/$(printf 'd%.0s' $(seq 200))"
done
mkdir -p "$long"
cp $two "$long/wall.yaml"
"$bin" report "$long/wall.yaml" -n 30 --threads 1 --out "$long/out" \
	>"$tmp/long.out" 2>"$tmp/long.err"
rc=$?
if [ $rc -eq 0 ] && grep -qF -- "--out $long/out" "$long/out/report.md"; then
	ok "report with ${#long}-byte paths: exit 0, report.md has the whole command"
else
	not_ok "report with ${#long}-byte paths" "exit $rc" "$(head -c 300 "$tmp/long.err")"
fi

# ---- --samples never destroys an input --------------------------------------
cp $two "$tmp/w.yaml"
cp $two "$tmp/w.orig"
ln -s w.yaml "$tmp/sym.yaml"
ln "$tmp/w.yaml" "$tmp/hard.yaml"
for spelling in "$tmp/w.yaml" "$tmp/./w.yaml" "$tmp/sym.yaml" "$tmp/hard.yaml"; do
	"$bin" run "$tmp/w.yaml" -n 5 --threads 1 --samples "$spelling" \
		>/dev/null 2>"$tmp/e"
	rc=$?
	if [ $rc -eq 2 ] && cmp -s "$tmp/w.yaml" "$tmp/w.orig" &&
	   grep -q "the samples would overwrite it" "$tmp/e"; then
		ok "run W --samples ${spelling#"$tmp/"}: refused, exit 2, the wall untouched"
	else
		not_ok "run W --samples ${spelling#"$tmp/"} must not destroy the wall" \
			"exit $rc" "$(head -c 300 "$tmp/e")"
	fi
done
"$bin" run $two -n 30 --threads 1 --samples "$tmp/p.csv" >/dev/null 2>&1
cp "$tmp/p.csv" "$tmp/p.orig"
(cd "$tmp" && "$bin" run "$OLDPWD/$two" --positions p.csv --samples ./p.csv \
	>/dev/null 2>"$tmp/e")
rc=$?
if [ $rc -eq 2 ] && cmp -s "$tmp/p.csv" "$tmp/p.orig"; then
	ok "run --positions p.csv --samples ./p.csv: refused, exit 2, the positions untouched"
else
	not_ok "--samples ./p.csv must not destroy --positions p.csv" "exit $rc" \
		"$(head -c 300 "$tmp/e")"
fi

# ---- an old samples file is replaced by a header on the disk -----------------
# A run over an old samples file writes its header to FILE.tmp and
# renames it over FILE (the old rows stay whole until then).  The header
# must be on the disk (fsync) before the rename: otherwise a machine
# that crashes just after it leaves an empty file where the old rows
# were.  strace shows the order of the calls.
if ! command -v strace >/dev/null 2>&1; then
	skip_one "the samples file's header is synced before it replaces the old file" "no strace"
else
	"$bin" run $two -n 3 --threads 1 --samples "$tmp/old.csv" >/dev/null 2>&1
	# no leak check under ptrace (tests/tap.sh, asan_no_leaks) in this
	# one run, whose question is the order of two calls
	ASAN_OPTIONS=$(asan_no_leaks) \
		strace -f -e trace=openat,fsync,rename -o "$tmp/strace" \
		"$bin" run $two -n 3 --threads 1 --samples "$tmp/old.csv" >/dev/null 2>&1
	rc=$?
	# the fd of old.csv.tmp, then fsync(that fd) before the rename
	order=$(awk -v f="$tmp/old.csv.tmp" '
		index($0, "openat(") && index($0, "\"" f "\"") && / = [0-9]+$/ { fd = $NF }
		fd != "" && $0 ~ "fsync\\(" fd "\\)" && !renamed { synced = 1 }
		index($0, "rename(\"" f "\"") { renamed = 1; print (synced ? "synced" : "not-synced") }
		' "$tmp/strace")
	if [ $rc -eq 0 ] && [ "$order" = synced ] && [ ! -e "$tmp/old.csv.tmp" ] &&
	   [ "$(wc -l <"$tmp/old.csv")" -eq 4 ]; then
		ok "an old samples file is replaced by a header synced to the disk first (fsync, then rename)"
	else
		not_ok "the samples file's header is synced before it replaces the old file" \
			"exit $rc, order '$order'" "$(grep -E 'old.csv|fsync|rename' "$tmp/strace" | head -c 600)"
	fi
fi

# ---- one writer per samples file ---------------------------------------------
"$bin" run $demo -n 1000000 --threads 1 --seed 1 --samples "$tmp/shared.csv" \
	>/dev/null 2>&1 &
first=$!
pids="$pids $first"
wait_rows "$tmp/shared.csv" 2
"$bin" run $demo -n 50 --threads 1 --seed 2 --samples "$tmp/shared.csv" \
	>/dev/null 2>"$tmp/e"
rc=$?
kill -TERM $first 2>/dev/null
wait $first 2>/dev/null
# the file: the first run's rows only, 0, 1, 2, ... each complete
seq_ok=$(awk -F, -v c="$(awk -F, 'NR == 1 { print NF; exit }' "$tmp/shared.csv")" \
	'NR > 1 { if ($1 != NR - 2 || NF != c) bad++ } END { print bad + 0 }' "$tmp/shared.csv")
if [ $rc -eq 2 ] && grep -q "another process is writing" "$tmp/e" && [ "$seq_ok" = 0 ]; then
	ok "a second run on the same samples file: exit 2, 'another process is writing'; the first run's rows intact"
else
	not_ok "a second run on the same samples file is refused" "exit $rc, $seq_ok bad rows" \
		"$(head -c 300 "$tmp/e")"
fi

# ---- SIGKILL in the middle of a row larger than a page -----------------------
# A 1020-block wall without friction: every sample is rejected after one
# LP (fast), and each row holds 2 x 2,956 positions: over 100 KB.  The
# rows go through a FIFO to a reader that, after a few rows, stops
# reading where a row ends and the pipe is empty: the next row fills the
# pipe (64 KB) and the run blocks inside that row's write(2), where the
# SIGKILL finds it.  Then the reader drains the pipe.
sed 's/friction: 0.6/friction: 0/' walls/large.yaml >"$tmp/f0.yaml"
mkfifo "$tmp/fifo"
python3 - "$tmp/fifo" "$tmp/cut.csv" "$tmp/paused" "$tmp/go" <<'EOF' &
import array, fcntl, os, sys, termios, time
fifo, path, paused, go = sys.argv[1:]
fd = os.open(fifo, os.O_RDONLY)
lines, waited = 0, False
with open(path, "wb") as out:
    while True:
        b = os.read(fd, 65536)
        if not b:
            break
        out.write(b)
        out.flush()
        lines += b.count(b"\n")
        avail = array.array("i", [0])
        fcntl.ioctl(fd, termios.FIONREAD, avail)
        if not waited and lines >= 3 and b.endswith(b"\n") and avail[0] == 0:
            waited = True
            open(paused, "w").close()
            while not os.path.exists(go):
                time.sleep(0.05)
EOF
job=$!
pids="$pids $job"
"$bin" run "$tmp/f0.yaml" -n 1000 --threads 1 --samples "$tmp/fifo" \
	>/dev/null 2>&1 &
writer=$!
pids="$pids $writer"
in_pipe_write() {	# PID: blocked writing to a pipe (as the kernel says)
	grep -q pipe_write "/proc/$1/wchan" 2>/dev/null
}
within 120 test -e "$tmp/paused"
# a kernel that hides wchan: a few seconds are enough for a sample
if grep -q '^0$' "/proc/$writer/wchan" 2>/dev/null; then sleep 5; else
	within 30 in_pipe_write $writer; fi
kill -KILL $writer 2>/dev/null
wait $writer 2>/dev/null
touch "$tmp/go"
wait $job 2>/dev/null
rowlen=$(awk 'NR == 2 { print length($0); exit }' "$tmp/cut.csv")
last=$(tail -c 1 "$tmp/cut.csv" | od -An -c | tr -d ' ')
whole=$(($(wc -l <"$tmp/cut.csv") - 1))
if [ "${rowlen:-0}" -gt 65536 ] && [ "$last" != '\n' ] && [ "$whole" -ge 1 ]; then
	ok "SIGKILL during a ${rowlen}-byte row write: $whole whole row(s), then a cut row"
else
	not_ok "SIGKILL cuts a row in the middle" "row length ${rowlen:-?}, last byte '$last', $whole rows"
fi
"$bin" run "$tmp/f0.yaml" --positions "$tmp/cut.csv" --threads 1 --json \
	>"$tmp/cut.json" 2>"$tmp/e"
got=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["samples"])' "$tmp/cut.json" 2>/dev/null)
if grep -q "cut.csv:$((whole + 2)): warning: the last row is incomplete" "$tmp/e" &&
   [ "$got" = "$whole" ]; then
	ok "--positions replays the $whole whole rows and drops the cut one with a warning"
else
	not_ok "--positions reads a file with a cut row" "samples '$got' of $whole" "$(head -c 300 "$tmp/e")"
fi
printf '0.5\n0.6\n' >"$tmp/t.txt"
"$bin" compare "$tmp/f0.yaml" --samples "$tmp/cut.csv" --tests "$tmp/t.txt" \
	>/dev/null 2>"$tmp/e"
if grep -q "warning: the last row is incomplete" "$tmp/e" && ! grep -q "fields, the header" "$tmp/e"; then
	ok "compare --samples drops the cut row with a warning"
else
	not_ok "compare --samples reads a file with a cut row" "$(head -c 300 "$tmp/e")"
fi
# SIGKILLs at random moments on a regular file: whatever the moment,
# the file holds whole rows, then at most one cut row
bad=
for k in 1 2 3; do
	"$bin" run "$tmp/f0.yaml" -n 1000 --threads 1 --samples "$tmp/k$k.csv" \
		>/dev/null 2>&1 &
	p=$!
	sleep "$(python3 -c 'import random; print(round(random.uniform(0.5, 2.5), 2))')"
	kill -KILL $p 2>/dev/null
	wait $p 2>/dev/null
	c=$(awk -F, 'NR == 1 { print NF; exit }' "$tmp/k$k.csv")
	nb=$(awk -F, -v c="$c" 'NF != c { b++ } END { print b + 0 }' "$tmp/k$k.csv")
	lastnl=$(tail -c 1 "$tmp/k$k.csv" | od -An -c | tr -d ' ')
	if [ "$nb" -gt 1 ] || { [ "$nb" = 1 ] && [ "$lastnl" = '\n' ]; }; then
		bad="$bad k$k"
	fi
done
if [ -z "$bad" ]; then ok "three SIGKILLs on a regular file: whole rows and at most a cut last one"; else
	not_ok "SIGKILL leaves whole rows" "$bad"; fi
# the same for compare and report on a file of the demo wall whose last
# row is cut by hand
"$bin" run $demo -n 40 --threads 1 --samples "$tmp/d.csv" >/dev/null 2>&1
head -c $(($(wc -c <"$tmp/d.csv") - 20)) "$tmp/d.csv" >"$tmp/dcut.csv"
"$bin" report $demo --samples "$tmp/dcut.csv" --threads 1 --out "$tmp/dcut" \
	>/dev/null 2>"$tmp/e"
rc=$?
if [ $rc -eq 0 ] && grep -q "dcut.csv:41: warning: the last row is incomplete" "$tmp/e"; then
	ok "report --samples drops a cut last row with a warning, exit 0"
else
	not_ok "report --samples with a cut last row" "exit $rc" "$(head -c 300 "$tmp/e")"
fi
"$bin" compare $demo --samples "$tmp/dcut.csv" --tests "$tmp/t.txt" --json \
	>"$tmp/c.json" 2>"$tmp/e"
rc=$?
if [ $rc -eq 0 ] && grep -q "warning: the last row" "$tmp/e"; then
	ok "compare --samples drops it too, exit 0"
else
	not_ok "compare --samples with a cut last row" "exit $rc" "$(head -c 300 "$tmp/e")"
fi

# ---- SIGTERM during report: complete or absent ---------------------------------
"$bin" run $demo -n 100 --threads 2 --samples "$tmp/r.csv" >/dev/null 2>&1
start=$(date +%s.%N)
"$bin" report $demo --samples "$tmp/r.csv" --threads 2 --out "$tmp/rfull" >/dev/null 2>&1
full=$(python3 -c "import sys; print(float(sys.argv[2]) - float(sys.argv[1]))" "$start" "$(date +%s.%N)")
nfiles=$(ls "$tmp/rfull" | wc -l)
# an older report in one of the directories: it must stay whole
"$bin" report $demo --samples "$tmp/r.csv" --threads 2 --out "$tmp/rold" >/dev/null 2>&1
cp "$tmp/rold/report.md" "$tmp/rold.md"
half=
for frac in 0.2 0.5 0.7 0.85 0.95; do
	for d in rnew rold; do
		[ $d = rold ] && [ $frac = 0.2 ] && continue
		[ $d = rnew ] && rm -rf "$tmp/rnew"
		"$bin" report $demo --samples "$tmp/r.csv" --threads 2 --out "$tmp/$d" \
			>/dev/null 2>&1 &
		p=$!
		sleep "$(python3 -c "print($full * $frac)")"
		kill -TERM $p 2>/dev/null
		wait $p
		rc=$?
		nf=$(ls "$tmp/$d" 2>/dev/null | wc -l)
		hidden=$(ls -A "$tmp" | grep -c "^\.$d\.")
		# 143: the signal's default action, after the report was put
		# in place and its handler gone (a sanitizer build's exit, its
		# leak check, takes a tenth of the run): complete, as exit 0
		if [ $d = rnew ]; then
			{ [ $rc = 1 ] && [ ! -e "$tmp/rnew" ]; } ||
			{ { [ $rc = 0 ] || [ $rc = 143 ]; } && [ "$nf" = "$nfiles" ]; } || half="$half $d@$frac:exit$rc:$nf-files"
		else
			{ [ $rc = 1 ] && cmp -s "$tmp/rold/report.md" "$tmp/rold.md" && [ "$nf" = "$nfiles" ]; } ||
			{ { [ $rc = 0 ] || [ $rc = 143 ]; } && [ "$nf" = "$nfiles" ]; } || half="$half $d@$frac:exit$rc:$nf-files"
		fi
		[ "$hidden" = 0 ] || half="$half $d@$frac:staging-left"
		[ $d = rold ] && { [ $rc = 0 ] || [ $rc = 143 ]; } && cp "$tmp/rold/report.md" "$tmp/rold.md"
		ls "$tmp/$d" 2>/dev/null | grep -q '\.tmp$' && half="$half $d@$frac:tmp-left"
	done
done
if [ -z "$half" ]; then
	ok "SIGTERM at 10..95 % of a report (${full%.??????} s): the directory complete ($nfiles files), absent or the old one"
else
	not_ok "SIGTERM during report leaves a complete report or none" "$half"
fi

# ---- readers are bounded ----------------------------------------------------------
bounded() {	# NAME PATTERN COMMAND...: exit 2 within 20 s, PATTERN in stderr
	local name=$1 pat=$2
	shift 2
	(ulimit -t 20; "$@" >/dev/null 2>"$tmp/e")
	local rc=$?
	if [ $rc -eq 2 ] && grep -q -- "$pat" "$tmp/e"; then
		ok "$name: exit 2, '$(head -n 1 "$tmp/e" | cut -c 1-90)'"
	else
		not_ok "$name is refused" "exit $rc" "$(head -c 300 "$tmp/e")"
	fi
}
bounded "--positions /dev/zero" "/dev/zero:1:1: a NUL byte" \
	"$bin" run $demo --positions /dev/zero
bounded "--tests /dev/zero" "/dev/zero:1:1: a NUL byte" \
	"$bin" compare $demo --tests /dev/zero
bounded "compare --samples /dev/zero" "/dev/zero:1:1: a NUL byte" \
	"$bin" compare $demo --samples /dev/zero --tests "$tmp/t.txt"
head -c 20000000 /dev/zero | tr '\0' '1' >"$tmp/oneline"
bounded "--positions: 20 MB without a line end" "oneline:1:1: a line longer than" \
	"$bin" run $demo --positions "$tmp/oneline"
head -n 1 "$tmp/d.csv" >"$tmp/longrow.csv"
cat "$tmp/oneline" >>"$tmp/longrow.csv"
bounded "compare --samples: a 20 MB row" "longrow.csv:2:1: a line longer than" \
	"$bin" compare $demo --samples "$tmp/longrow.csv" --tests "$tmp/t.txt"
yes 1.5 | head -n 6000000 >"$tmp/many.txt"
bounded "--tests: 18 MB of loads" "more than 16 MiB" \
	"$bin" compare $demo --tests "$tmp/many.txt"

# ---- threads ------------------------------------------------------------------------
start=$(date +%s)
"$bin" run $demo -n 1 --threads 1000 --json >"$tmp/t1.json" 2>"$tmp/e"
rc=$?
secs=$(($(date +%s) - start))
th=$(python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["threads"])' "$tmp/t1.json" 2>/dev/null)
if [ $rc -eq 0 ] && [ "$th" = 1 ] && [ $secs -le 10 ]; then
	ok "-n 1 --threads 1000: one worker (${secs} s)"
else
	not_ok "-n 1 --threads 1000 starts one worker" "exit $rc, threads '$th', ${secs} s"
fi
cp tests/wall-10050.yaml "$tmp/big.yaml"
bounded "--threads 1024 on a 10,050-block wall (hundreds of GB)" "use at most" \
	"$bin" run "$tmp/big.yaml" -n 5000 --threads 1024

# ---- control characters and invalid UTF-8 --------------------------------------
sed 's/^name: Two stacked blocks/name: "evil\\e]0;title\\a\\e[2J\\nsecond line\\x9b"/; s/id: top/id: "to\\np\\e[31m"/' \
	$two >"$tmp/evil.yaml"
raw() {	# FILE: has an ESC, a BEL, a C1 CSI or a name's newline, raw
	python3 -c '
import sys
d = open(sys.argv[1], "rb").read()
sys.exit(0 if any(x in d for x in (b"\x1b", b"\x07", b"\xc2\x9b",
                                   b"\nsecond line", b"to\np")) else 1)' "$1"
}
"$bin" check "$tmp/evil.yaml" >"$tmp/o1" 2>&1
"$bin" run "$tmp/evil.yaml" -n 10 --threads 1 >"$tmp/o2" 2>&1
"$bin" solve "$tmp/evil.yaml" --method standard >"$tmp/o3" 2>&1
"$bin" report "$tmp/evil.yaml" -n 20 --threads 1 --out "$tmp/evilr" >"$tmp/o4" 2>&1
found=
for f in o1 o2 o3 o4 evilr/report.md; do
	raw "$tmp/$f" && found="$found $f"
done
grep -q 'evil\\e\]0;title\\a\\e\[2J\\nsecond line\\x9b' "$tmp/o1" || found="$found (check: no escaped name)"
grep -q '^# slipwall report: evil\\e' "$tmp/evilr/report.md" || found="$found (report.md: no escaped name)"
if [ -z "$found" ]; then
	ok "control characters in a name and an id are escaped: check, run, solve, report and report.md"
else
	not_ok "control characters escaped on output" "raw in:$found"
fi
"$bin" check "$tmp/evil.yaml" --json >"$tmp/e.json"
if python3 -c '
import json, sys
d = json.load(open(sys.argv[1], encoding="utf-8"))
assert d["name"] == "evil\x1b]0;title\x07\x1b[2J\nsecond line\x9b", d["name"]
assert "to\np\x1b[31m" in [b["id"] for b in d["blocks"]]
raw = open(sys.argv[1], "rb").read()
assert b"\x1b" not in raw and b"\x07" not in raw and b"\xc2\x9b" not in raw
' "$tmp/e.json" 2>"$tmp/e"; then
	ok "check --json: the name and id round-trip, escaped (no raw control byte)"
else
	not_ok "check --json escapes control characters" "$(tail -n 2 "$tmp/e")"
fi
bad=$(printf 'w\xff\xfe.yaml')
cp $two "$tmp/$bad"
"$bin" run "$tmp/$bad" -n 5 --threads 1 --json >"$tmp/u.json" 2>/dev/null
if python3 -c '
import json, sys
d = json.loads(open(sys.argv[1], "rb").read().decode("utf-8"))
assert d["wall"].endswith("w\ufffd\ufffd.yaml"), d["wall"]' "$tmp/u.json" 2>"$tmp/e"; then
	ok "an invalid-UTF-8 path makes valid JSON (U+FFFD)"
else
	not_ok "an invalid-UTF-8 path makes valid JSON" "$(tail -n 2 "$tmp/e")"
fi

# ---- smaller ----------------------------------------------------------------------
"$bin" run $demo -n 2000 --threads 1 --samples /dev/stdout 2>"$tmp/e" | head -n 1 >/dev/null
rc=${PIPESTATUS[0]}
if [ "$rc" = 1 ] && grep -q "/dev/stdout: cannot write: Broken pipe" "$tmp/e"; then
	ok "--samples /dev/stdout | head -1: exit 1, 'cannot write: Broken pipe'"
else
	not_ok "a closed samples pipe is reported" "exit $rc" "$(head -c 300 "$tmp/e")"
fi
# a stdout that closed before the end: never "Success" for the reason
"$bin" sweep $demo --friction 0.4:0.8:0.1 -n 20 --threads 1 --json --csv "$tmp/cl.csv" \
	2>"$tmp/e" | true
rc=${PIPESTATUS[0]}
check "sweep --json --csv F | true: exit 1, the reason is not 'Success' ($(head -c 120 "$tmp/e"))" \
	eval '[ "$rc" = 1 ] && grep -q "^slipwall: standard output: " "$tmp/e" && ! grep -q "Success" "$tmp/e"'
{ cat $two; printf 'tests:\n  loads: []\n'; } >"$tmp/empty-tests.yaml"
"$bin" compare "$tmp/empty-tests.yaml" >/dev/null 2>"$tmp/e"
rc=$?
if [ $rc -eq 2 ] && grep -q "tests: loads list is empty" "$tmp/e"; then
	ok "tests: {loads: []}: 'its tests: loads list is empty', exit 2"
else
	not_ok "an empty tests: list is told apart" "exit $rc" "$(head -c 300 "$tmp/e")"
fi
printf '0x1p-1\n' >"$tmp/hex.txt"
bounded "--tests with a hexadecimal load" "hex.txt:1:1: a load must be a number, in decimal" \
	"$bin" compare $demo --tests "$tmp/hex.txt"

tap_end
