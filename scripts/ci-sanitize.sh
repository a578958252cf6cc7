#!/bin/sh
# ci-sanitize.sh - the test suite under the sanitizers (docs/reliability.md).
#
#   sh scripts/ci-sanitize.sh [asan|tsan]...     (default: both)
#
# asan: every test (unit, command line, workbench) but the real-size
#       walls (tests/cli/realwalls.sh, minutes even unsanitized) built with
#       -Db_sanitize=address,undefined in build-asan/; leaks are errors
#       (LeakSanitizer), except those listed in scripts/sanitizers/lsan.supp.
# tsan: the threaded tests - the sampler's pool (test_mc), `run` with 1
#       and 2 threads (cli_run, cli_faults), the workbench with its solver
#       thread (cli_tui) - built with -Db_sanitize=thread
#       in build-tsan/; scripts/sanitizers/tsan.supp says what is
#       suppressed and why.
# Environment: ASAN_DIR, TSAN_DIR (build directories).  Prints each
# suite's meson summary and ends with "tests: N passed, M failed".
set -e
cd "$(dirname "$0")/.."
sh scripts/setup.sh --tests >/dev/null	# the packages (and the plain build)
jobs=${*:-asan tsan}
supp=$(pwd)/scripts/sanitizers
passed=0
failed=0

# reports DIR PREFIX: sanitizer reports written by any process (the
# command-line tests send the program's stderr to files or /dev/null, so
# every report also goes to DIR/PREFIX.PID): each one is a failure
reports() {
	n=0
	for r in "$1/$2".*; do
		[ -e "$r" ] || continue
		n=$((n + 1))
		echo "--- $r"
		if [ $n -le 5 ]; then	# the first ones whole, then the gist
			head -n 40 "$r"
		else
			grep -m 1 -E '^SUMMARY|runtime error' "$r"
		fi
	done
	failed=$(( failed + n ))
	echo "$2: $n sanitizer report(s) from the programs the tests ran"
}

. scripts/meson-counts.sh
# count NAME LOG RC: add meson's Ok / Fail / Timeout counts of LOG
count() {
	meson_counts "$2" "$3"
	passed=$(( passed + mpassed ))
	failed=$(( failed + mfailed ))
	echo "$1: $mpassed passed, $mfailed failed"
}

for job in $jobs; do
	case $job in
	asan)
		dir=${ASAN_DIR:-build-asan}
		[ -f "$dir/build.ninja" ] ||
			meson setup "$dir" -Db_sanitize=address,undefined >/dev/null
		meson compile -C "$dir" >/dev/null
		rm -f "$dir"/san-report.*
		log=$(pwd)/$dir/san-report
		set +e
		SLIPWALL_SIZE_SECONDS=20 SLIPWALL_INVARIANCE_SAMPLES=300 SLIPWALL_PACE_LARGE_CAP=900 \
		ASAN_OPTIONS=detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=1:log_path=$log \
		LSAN_OPTIONS=suppressions=$supp/lsan.supp:print_suppressions=0 \
		UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1:log_path=$log \
		meson test -C "$dir" --print-errorlogs --num-processes 2 \
			--timeout-multiplier 3 --no-suite realwalls \
			>"$dir/test-output.txt" 2>&1
		rc=$?
		set -e
		tail -n 12 "$dir/test-output.txt"
		count asan "$dir/test-output.txt" $rc
		[ "$rc" = 0 ] || meson_failures "$dir"
		reports "$dir" san-report
		;;
	tsan)
		dir=${TSAN_DIR:-build-tsan}
		[ -f "$dir/build.ninja" ] ||
			meson setup "$dir" -Db_sanitize=thread >/dev/null
		meson compile -C "$dir" >/dev/null
		# TSan needs a memory layout some kernels' address randomisation
		# breaks ("unexpected memory mapping"): run without it if we can
		wrap=
		if setarch "$(uname -m)" -R true 2>/dev/null; then
			wrap="--wrapper=setarch $(uname -m) -R"
		fi
		rm -f "$dir"/san-report.*
		log=$(pwd)/$dir/san-report
		set +e
		TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1:suppressions=$supp/tsan.supp:log_path=$log \
		meson test -C "$dir" --print-errorlogs --num-processes 2 \
			--timeout-multiplier 4 ${wrap:+"$wrap"} mc run faults_cli tui \
			>"$dir/test-output.txt" 2>&1
		rc=$?
		set -e
		tail -n 12 "$dir/test-output.txt"
		count tsan "$dir/test-output.txt" $rc
		[ "$rc" = 0 ] || meson_failures "$dir"
		reports "$dir" san-report
		;;
	*)
		echo "ci-sanitize: unknown job '$job' (asan, tsan)" >&2
		exit 2
		;;
	esac
done
echo "tests: $passed passed, $failed failed"
[ "$failed" = 0 ]
