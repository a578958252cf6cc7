# tap.sh - the TAP helpers of the command-line tests (tests/cli/*.sh),
# sourced after the script has changed to the source root:
#   . tests/tap.sh
# ok TEXT; not_ok TEXT [DETAIL...] (each detail line becomes a TAP
# comment); check TEXT COMMAND... (ok when the command succeeds);
# tap_end (the plan line, and the status: 0 when nothing failed).
# n counts the tests, failed the failures.  And helpers for tests that
# wait: within SECONDS COMMAND... (the command, every 0.1 s, until it
# succeeds or SECONDS have passed); alive PID and gone PID; has_rows
# FILE K and wait_rows FILE K (a samples file's data rows); json_field
# FILE EXPR and near VALUE TARGET REL, for the JSON and numeric checks;
# asan_no_leaks, for a run under a tracer or a launcher.
# python3 is the system's; skip_all and skip_one (below).
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
	local line
	for line in "$@"; do
		printf '%s\n' "$line" | sed 's/^/#   /'
	done
}
check() {
	local name=$1
	shift
	if "$@"; then ok "$name"; else not_ok "$name"; fi
}
tap_end() {
	echo "1..$n"
	[ "$failed" -eq 0 ]
}
# asan_no_leaks: the ASAN_OPTIONS of a run under strace or mpirun, the
# environment's with LeakSanitizer off: it cannot run under ptrace (a
# fatal error), and Open MPI's ranks do not free everything at
# MPI_Finalize, from plugins unloaded by then (no stack to suppress them
# by).  Memory errors are still checked there, and every other run of
# the sanitizer job (scripts/ci-sanitize.sh) still checks leaks.
asan_no_leaks() {
	echo "${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
}
# within SECONDS COMMAND...: 0 as soon as COMMAND succeeds, 1 when it
# has not within SECONDS (it is tried every 0.1 s)
within() {
	local end=$((SECONDS + $1))
	shift
	until "$@"; do
		[ "$SECONDS" -le "$end" ] || return 1
		sleep 0.1
	done
}
# alive PID: running (a zombie that its parent has not reaped yet has
# exited)
alive() {
	local st
	st=$(ps -o stat= -p "$1" 2>/dev/null) || return 1
	case $st in Z*) return 1 ;; esac
	return 0
}
gone() {
	! alive "$1"
}
# has_rows FILE K: FILE exists and has at least K data rows (lines
# after its header)
has_rows() {
	[ -f "$1" ] && [ "$(wc -l <"$1")" -gt "$2" ]
}
# wait_rows FILE K: until FILE has K data rows (at most 60 s)
wait_rows() {
	within 60 has_rows "$1" "$2"
}
# json_field FILE EXPR: the python expression EXPR on the JSON object d
# read from FILE (nothing, and a failure, if FILE is not JSON)
json_field() {
	python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))' "$1" "$2" 2>/dev/null
}
# one_load [--its FIRST ALL] [--le LE] [--in LO HI] FILE...: each
# samples file holds one accepted sample and all have one lambda_min (to
# 1e-9); --its: the first file's iterations above FIRST and every
# file's above ALL; --le: 0 < lambda_min <= lambda_max (1 + LE); --in:
# LO < lambda_min < HI.  Prints each file's row as a TAP comment.
one_load() {
	python3 - "$@" <<'PY'
import csv, sys
a = sys.argv[1:]
its = le = rng = None
while a and a[0].startswith("--"):
    if a[0] == "--its":
        its, a = (int(a[1]), int(a[2])), a[3:]
    elif a[0] == "--le":
        le, a = float(a[1]), a[2:]
    elif a[0] == "--in":
        rng, a = (float(a[1]), float(a[2])), a[3:]
    else:
        sys.exit("one_load: unknown option " + a[0])
rows = [list(csv.DictReader(open(f))) for f in a]
if not a or not all(len(r) == 1 for r in rows):
    sys.exit(1)
rows = [r[0] for r in rows]
for f, r in zip(a, rows):
    print("#  ", f.rsplit("/", 1)[-1], r["status"], r["lambda_max"], r["lambda_min"], r["iterations"])
if not all(r["status"] == "accepted" for r in rows):
    sys.exit(1)
lam = [float(r["lambda_min"]) for r in rows]
ok = all(abs(l - lam[0]) <= 1e-9 * abs(lam[0]) for l in lam)
if its:
    ok = ok and int(rows[0]["iterations"]) > its[0] and \
        all(int(r["iterations"]) > its[1] for r in rows)
if le is not None:
    ok = ok and all(0 < l <= float(r["lambda_max"]) * (1 + le) for l, r in zip(lam, rows))
if rng:
    ok = ok and rng[0] < lam[0] < rng[1]
sys.exit(0 if ok else 1)
PY
}
# near VALUE TARGET REL: |VALUE - TARGET| <= REL |TARGET| (false when
# VALUE is not a number)
near() {
	python3 -c 'import sys; a, b, r = map(float, sys.argv[1:]); sys.exit(not abs(a - b) <= r * abs(b))' "$1" "$2" "$3" 2>/dev/null
}
# python3 (the JSON and arithmetic checks): the system's interpreter by
# its absolute path, the one scripts/setup.sh installs, not the first
# python3 on PATH.  A pyenv shim there is a bash script that runs
# pyenv's own scripts for a second or more before the Python it chose,
# which moved the timing of every check behind it (issue 23); where
# /usr/bin/python3 is missing, the one on PATH.
if [ -x /usr/bin/python3 ]; then
	python3() {
		/usr/bin/python3 "$@"
	}
fi
# A test that cannot run for a missing tool (tmux, mpirun) skips where a
# developer runs it, and fails where the tools must be there: in CI
# (CI=true) and under scripts/test.sh, which installs them and sets
# SLIPWALL_TEST_TOOLS=required.  tools_required: 0 there.
# skip_all REASON: the whole script ("1..0 # SKIP REASON", or one
# failure), and exit.  skip_one TEXT REASON: one test.
tools_required() {
	[ "${CI:-}" = true ] || [ "${SLIPWALL_TEST_TOOLS:-}" = required ]
}
skip_all() {
	if tools_required; then
		echo "not ok 1 - $1 (the tools must be there: CI=true or SLIPWALL_TEST_TOOLS=required)"
		echo "1..1"
		exit 1
	fi
	echo "1..0 # SKIP $1"
	exit 0
}
skip_one() {
	if tools_required; then
		not_ok "$1: $2 (the tools must be there: CI=true or SLIPWALL_TEST_TOOLS=required)"
	else
		ok "$1 # SKIP $2"
	fi
}
