# tap.sh - the TAP helpers of the command-line tests (tests/cli/*.sh),
# sourced after the script has changed to the source root:
#   . tests/tap.sh
# ok TEXT; not_ok TEXT [DETAIL...] (each detail line becomes a TAP
# comment); check TEXT COMMAND... (ok when the command succeeds);
# tap_end (the plan line, and the status: 0 when nothing failed).
# n counts the tests, failed the failures.  And helpers for tests that
# wait: within SECONDS COMMAND... (the command, every 0.1 s, until it
# succeeds or SECONDS have passed); alive PID and gone PID; has_rows
# FILE K and wait_rows FILE K (a samples file's data rows).
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
