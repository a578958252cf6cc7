#!/bin/bash
# cli_faults.sh - faults during the batch commands lose nothing
# (docs/reliability.md).
#
# Usage (from the source root): bash tests/cli_faults.sh /path/to/slipwall
# Proves: GLPK failures and GLPK errors (SLIPWALL_LP_FAULT, src/lp.c) are
# `numerical` rejections, counted in the JSON, the run goes on, and every
# accepted sample is the one a clean run computes; `solve` reports a
# numerical failure with exit 1; a samples file that cannot be created,
# /dev/full, or a disk that fills up mid-run (a file size limit) give a
# clear error, exit 1, and no half row; stdout on a full disk is an error;
# SIGHUP stops a run like SIGINT and SIGTERM (tests/cli_run.sh has those
# two and SIGKILL); a second SIGINT kills at once and leaves complete
# rows; SIGKILL leaves no JSON or a valid one.  TAP output.  Needs python3.

bin=${1:?usage: cli_faults.sh SLIPWALL}
cd "$(dirname "$0")/.." || exit 1

n=0
failed=0
ok() {
	n=$((n + 1))
	echo "ok $n - $1"
}
not_ok() {
	n=$((n + 1))
	failed=$((failed + 1))
	echo "not ok $n - $1"
	shift
	for line in "$@"; do
		printf '#   %s\n' "$line"
	done
}
check() {	# check NAME COMMAND...: ok when the command succeeds
	local name=$1
	shift
	if "$@"; then ok "$name"; else not_ok "$name"; fi
}
# complete FILE: every line has the header's number of fields and the
# file ends with a newline
complete() {
	awk -F, 'NR == 1 { c = NF } NF != c { bad++ } END { exit bad > 0 }' "$1" &&
		[ "$(tail -c 1 "$1" | od -An -c | tr -d ' ')" = '\n' ]
}
# json_field FILE EXPR: python expression on the JSON object d
json_field() {
	python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$1" "$2" 2>/dev/null
}
sanitizer_clean() {
	! grep -qE 'Sanitizer|runtime error|core dumped' "$1"
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
demo=walls/demo.yaml
ft=walls/ferris-tinloi-1.yaml

# ---- GLPK faults: numerical rejections, the run goes on --------------------
"$bin" run $demo -n 20 --threads 1 --samples "$tmp/clean.csv" >/dev/null 2>&1
for spec in error:40 failed:40; do
	SLIPWALL_LP_FAULT=$spec "$bin" run $demo -n 20 --threads 1 --json \
		--samples "$tmp/f.csv" >"$tmp/f.json" 2>"$tmp/f.err"
	rc=$?
	num=$(json_field "$tmp/f.json" 'd["rejected"]["numerical"]')
	acc=$(json_field "$tmp/f.json" 'd["accepted"]')
	rows=$(awk -F, 'NR > 1 && $2 == "numerical"' "$tmp/f.csv" | wc -l)
	if [ $rc -eq 0 ] && [ -n "$num" ] && [ "$num" -gt 0 ] && [ "$num" = "$rows" ] &&
	   [ "$acc" -gt 0 ] && [ "$(json_field "$tmp/f.json" 'd["samples"]')" = 20 ]; then
		ok "SLIPWALL_LP_FAULT=$spec: exit 0, 20 samples, $num numerical rejections counted in the JSON and the file, $acc accepted"
	else
		not_ok "SLIPWALL_LP_FAULT=$spec: numerical rejections, the run goes on" \
			"exit $rc, numerical $num (file $rows), accepted $acc" "$(head -c 300 "$tmp/f.err")"
	fi
	# every row but the numerical ones is the clean run's row
	check "SLIPWALL_LP_FAULT=$spec: every other sample is the clean run's, bit for bit" \
		python3 -c 'import sys
a = open(sys.argv[1]).read().splitlines()
b = open(sys.argv[2]).read().splitlines()
ok = len(a) == len(b) == 21 and a[0] == b[0]
for x, y in zip(a[1:], b[1:]):
    xs, ys = x.split(","), y.split(",")
    if ys[1] == "numerical":
        ok = ok and xs[5:] == ys[5:]   # the same contact points
    else:
        ok = ok and x == y
sys.exit(not ok)' "$tmp/clean.csv" "$tmp/f.csv"
done

# two threads: each has its own GLPK environment; nothing lost, and the
# samples that survive are those of a clean run (any thread count)
"$bin" run $ft -n 40 --threads 1 --samples "$tmp/ftclean.csv" >/dev/null 2>&1
SLIPWALL_LP_FAULT=error:400 "$bin" run $ft -n 40 --threads 2 --json \
	--samples "$tmp/f2.csv" >"$tmp/f2.json" 2>"$tmp/f2.err"
rc=$?
num=$(json_field "$tmp/f2.json" 'd["rejected"]["numerical"]')
acc=$(json_field "$tmp/f2.json" 'd["accepted"]')
rows=$(awk -F, 'NR > 1 && $2 == "numerical"' "$tmp/f2.csv" | wc -l)
if [ $rc -eq 0 ] && [ -n "$num" ] && [ "$num" -gt 0 ] && [ "$num" = "$rows" ] &&
   [ "$acc" -gt 0 ] && [ "$(($(wc -l <"$tmp/f2.csv") - 1))" = 40 ] && complete "$tmp/f2.csv"; then
	ok "GLPK errors on 2 threads: 40 complete rows, $num numerical (counted), $acc accepted"
else
	not_ok "GLPK errors on 2 threads" "exit $rc, numerical $num (file $rows), accepted $acc" "$(head -c 300 "$tmp/f2.err")"
fi
check "GLPK errors on 2 threads: every other sample is the clean 1-thread run's" \
	python3 -c 'import sys
a = open(sys.argv[1]).read().splitlines()
b = open(sys.argv[2]).read().splitlines()
ok = len(a) == len(b) == 41
for x, y in zip(a[1:], b[1:]):
    ok = ok and (x == y or (y.split(",")[1] == "numerical" and x.split(",")[5:] == y.split(",")[5:]))
sys.exit(not ok)' "$tmp/ftclean.csv" "$tmp/f2.csv"

for method in standard gilbert global; do
	wall=$demo
	[ $method = global ] && wall=walls/two-block-stack.yaml
	SLIPWALL_LP_FAULT=error:1 "$bin" solve $wall --method $method \
		>"$tmp/s.out" 2>"$tmp/s.err"
	rc=$?
	if [ $rc -eq 1 ] && grep -q 'numerical' "$tmp/s.err" && sanitizer_clean "$tmp/s.err"; then
		ok "solve --method $method with every LP failing: exit 1, 'numerical failure'"
	else
		not_ok "solve --method $method: a GLPK error is a numerical failure" \
			"exit $rc" "$(head -c 300 "$tmp/s.err")"
	fi
done

# ---- the samples file: cannot create, full disk ----------------------------
"$bin" run $demo -n 5 --samples "$tmp/no/such/dir/s.csv" >/dev/null 2>"$tmp/e"
rc=$?
if [ $rc -eq 1 ] && grep -qF "$tmp/no/such/dir/s.csv: cannot create: No such file or directory" "$tmp/e" &&
   [ ! -e "$tmp/no" ]; then
	ok "--samples in a missing directory: exit 1, 'cannot create: No such file or directory'"
else
	not_ok "--samples in a missing directory" "exit $rc" "$(head -c 300 "$tmp/e")"
fi

mkdir "$tmp/adir"
"$bin" run $demo -n 5 --samples "$tmp/adir" >/dev/null 2>"$tmp/e"
rc=$?
if [ $rc -eq 1 ] && grep -qF "$tmp/adir: cannot create: Is a directory" "$tmp/e"; then
	ok "--samples naming a directory: exit 1, 'Is a directory'"
else
	not_ok "--samples naming a directory" "exit $rc" "$(head -c 300 "$tmp/e")"
fi

"$bin" run $demo -n 5 --samples /dev/full >/dev/null 2>"$tmp/e"
rc=$?
if [ $rc -eq 1 ] && grep -qF '/dev/full: cannot write: No space left on device' "$tmp/e"; then
	ok "--samples /dev/full: exit 1, 'No space left on device'"
else
	not_ok "--samples /dev/full" "exit $rc" "$(head -c 300 "$tmp/e")"
fi

# the disk fills up mid-run: a 20 KiB file size limit (SIGXFSZ ignored,
# so write(2) is short, then fails with EFBIG - as on a full disk)
(trap '' XFSZ; ulimit -f 20; exec "$bin" run $demo -n 200 --threads 1 --json \
	--samples "$tmp/lim.csv" >"$tmp/lim.json" 2>"$tmp/lim.err")
rc=$?
jn=$(json_field "$tmp/lim.json" 'd["samples"] if d["stopped"] == "write_error" else -1')
rows=$(($(wc -l <"$tmp/lim.csv") - 1))
if [ $rc -eq 1 ] && grep -qF "$tmp/lim.csv: cannot write: File too large" "$tmp/lim.err" &&
   [ -n "$jn" ] && [ "$jn" -gt 0 ]; then
	ok "the disk fills mid-run: exit 1, 'cannot write: File too large', a JSON summary of $jn samples"
else
	not_ok "the disk fills mid-run: a clear error" "exit $rc, json samples $jn" "$(head -c 300 "$tmp/lim.err")"
fi
# the rows counted are the rows in the file, all complete: no half row
if complete "$tmp/lim.csv" && [ "$rows" = "$jn" ]; then
	ok "the disk fills mid-run: the file holds the $jn counted rows, all complete"
else
	not_ok "the disk fills mid-run: no half row (src/runlog.c flush_row: truncate a short row)" \
		"$rows newline-terminated rows, JSON counts $jn" \
		"last bytes: $(tail -c 40 "$tmp/lim.csv" | tr '\n' '|')"
fi

# ---- stdout on a full disk ---------------------------------------------------
for cmd in "check $demo --json" "solve $demo --method standard --json" "run $demo -n 3 --json"; do
	"$bin" $cmd >/dev/full 2>"$tmp/e"
	rc=$?
	if [ $rc -ne 0 ] && grep -q 'No space left on device' "$tmp/e"; then
		ok "${cmd%% *} --json > /dev/full: exit $rc, 'No space left on device'"
	else
		not_ok "${cmd%% *} --json > /dev/full: an error, not exit 0 (src/main.c: check fflush/ferror of stdout)" \
			"exit $rc" "$(head -c 300 "$tmp/e")"
	fi
done

# ---- signals -------------------------------------------------------------------
cols=$(awk -F, 'NR == 1 { print NF; exit }' "$tmp/clean.csv")
set -m	# job control: a background job does not ignore SIGINT
"$bin" run $ft -n 100000 --threads 2 --samples "$tmp/HUP.csv" --json \
	>"$tmp/HUP.json" 2>"$tmp/HUP.err" &
pid=$!
sleep 1.5
kill -HUP $pid
wait $pid
rc=$?
rows=$(($(wc -l <"$tmp/HUP.csv") - 1))
jn=$(json_field "$tmp/HUP.json" 'd["samples"] if d["stopped"] == "interrupted" else -1')
if [ $rc -eq 1 ] && [ "$jn" = "$rows" ] && [ "$rows" -gt 0 ] && complete "$tmp/HUP.csv"; then
	ok "SIGHUP: exit 1, a JSON summary of the same $rows samples as the file, every row complete"
else
	not_ok "SIGHUP: a summary of what was done" "exit $rc, rows $rows, json $jn" "$(head -c 200 "$tmp/HUP.err")"
fi

# a second SIGINT kills at once (one-shot handler): complete rows still
"$bin" run $ft -n 100000 --threads 2 --samples "$tmp/INT2.csv" --json \
	>"$tmp/INT2.json" 2>"$tmp/INT2.err" &
pid=$!
sleep 1.5
kill -INT $pid
kill -INT $pid
wait $pid
rc=$?
if { [ $rc -eq 1 ] || [ $rc -eq 130 ]; } && complete "$tmp/INT2.csv" &&
   { [ ! -s "$tmp/INT2.json" ] || json_field "$tmp/INT2.json" 'd["samples"]' >/dev/null; }; then
	ok "two SIGINTs at once: exit $rc, every row complete, JSON valid or none"
else
	not_ok "two SIGINTs at once" "exit $rc" "$(head -c 200 "$tmp/INT2.err")"
fi
set +m

# SIGKILL: no JSON (it is written at the end) or a valid one, complete rows
for delay in 0.2 1.0; do
	"$bin" run $ft -n 100000 --threads 2 --samples "$tmp/K.csv" --json \
		>"$tmp/K.json" 2>/dev/null &
	pid=$!
	sleep $delay
	kill -KILL $pid
	wait $pid 2>/dev/null
	if { [ ! -s "$tmp/K.json" ] || json_field "$tmp/K.json" 'd["samples"]' >/dev/null; } &&
	   { [ ! -s "$tmp/K.csv" ] || complete "$tmp/K.csv"; }; then
		ok "SIGKILL after $delay s: JSON none or valid, every row complete"
	else
		not_ok "SIGKILL after $delay s" "json: $(head -c 100 "$tmp/K.json")"
	fi
done

echo "1..$n"
[ "$failed" -eq 0 ]
