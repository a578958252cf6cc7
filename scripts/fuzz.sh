#!/bin/sh
# fuzz.sh - build the libFuzzer harness (fuzz/fuzz_wallfile.c) into
# build-fuzz/ with clang and -fsanitize=fuzzer,address,undefined, and run
# it for SECONDS (default 60) on one process, niced.
#
#   sh scripts/fuzz.sh [SECONDS]          CI runs 60; long runs: 3600 and more
#
# The seed corpus is walls/*.yaml and tests/bad/*.yaml (but the alias
# bomb: its descendants cost a second each); what the fuzzer
# learns is kept in build-fuzz/corpus/ (so a second run goes on from
# there).  A finding is written to build-fuzz/artifacts/ and the script
# exits non-zero; turn it into a regression test (docs/reliability.md).
# Environment: FUZZ_DIR (build-fuzz), FUZZ_ARGS (extra libFuzzer flags),
# FUZZ_TIMEOUT (seconds per input, default 20).  Each run appends one line
# to build-fuzz/history (date, seconds, executions, exit, corpus units)
# for the totals of docs/reliability.md.
# A timeout is wall-clock time, and a niced process on a busy machine can
# be starved for that long: a timeout's input is run once more alone (not
# niced); it is a finding only if it is slow there too (over a quarter of
# the timeout).
# Ends with "tests: 1 passed, 0 failed" or "tests: 0 passed, 1 failed".
set -e
cd "$(dirname "$0")/.."
secs=${1:-60}
dir=${FUZZ_DIR:-build-fuzz}
timeout=${FUZZ_TIMEOUT:-20}

sh scripts/setup.sh --packages	# meson and the libraries
if ! command -v clang >/dev/null 2>&1 ||
   ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
	echo "fuzz: installing clang" >&2
	export DEBIAN_FRONTEND=noninteractive
	apt-get update -qq
	apt-get install -y -qq clang libclang-rt-dev >/dev/null
fi
# the library is instrumented for coverage (fuzzer-no-link); layouts are
# limited to 400 blocks here (src/lib/layout.c) to keep executions fast
reconf=
[ -f "$dir/build.ninja" ] && reconf=--reconfigure
CC=clang meson setup $reconf "$dir" -Dfuzz=true -Db_sanitize=address,undefined \
	-Db_lundef=false -Dbuildtype=debugoptimized \
	-Dc_args="['-fsanitize=fuzzer-no-link', '-DLAYOUT_MAX_BLOCKS=400']" >/dev/null
meson compile -C "$dir" fuzz_wallfile >/dev/null

mkdir -p "$dir/corpus" "$dir/artifacts" "$dir/seeds"
for f in walls/*.yaml tests/bad/*.yaml; do
	if [ "$(wc -c <"$f")" -le 4096 ]; then cp "$f" "$dir/seeds/"; fi
done
# -rss_limit_mb: the loader is bounded (16 MiB files, 2e6 nodes);
# -max_len: small walls fit in 4 KiB, and short inputs keep exec/s high
# (the size limits have their own tests);
# -timeout: one input (parse + one sample of <= 8 blocks) takes ms; the
# slowest units of the corpus take about a second.
# one process (no -jobs): the machine is shared; niced.
set +e
t0=$(date +%s)
ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} \
UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
nice -n 19 "$dir/fuzz/fuzz_wallfile" -max_total_time="$secs" \
	-rss_limit_mb=2048 -max_len=4096 -timeout="$timeout" \
	-print_final_stats=1 -artifact_prefix="$dir/artifacts/" \
	${FUZZ_ARGS:-} \
	"$dir/corpus" "$dir/seeds" > "$dir/fuzz.log" 2>&1
rc=$?
took=$(( $(date +%s) - t0 ))
tail -n 25 "$dir/fuzz.log"
execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/fuzz.log" | tail -n 1)
units=$(ls "$dir/corpus" | wc -l)
echo "fuzz: ${execs:-?} executions in $took s (of $secs), exit $rc, corpus $units units"
# a timeout: slow alone too, or a starved process?
if [ "$rc" != 0 ] && grep -q '^SUMMARY: libFuzzer: timeout' "$dir/fuzz.log"; then
	unit=$(sed -n "s|.*Test unit written to \(.*timeout-[0-9a-f]*\).*|\1|p" "$dir/fuzz.log" | tail -n 1)
	t0=$(date +%s%N)
	ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} \
	UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
	"$dir/fuzz/fuzz_wallfile" -timeout="$timeout" -rss_limit_mb=2048 "$unit" \
		> "$dir/timeout-rerun.log" 2>&1
	rrc=$?
	ms=$(( ($(date +%s%N) - t0) / 1000000 ))
	if [ -f "$unit" ] && [ "$rrc" = 0 ] && [ "$ms" -lt $((timeout * 250)) ]; then
		mkdir -p "$dir/starved"
		mv "$unit" "$dir/starved/"
		echo "fuzz: the timeout's input takes $ms ms alone: the niced fuzzer was starved, not a finding (kept in $dir/starved/)"
		rc=0
	else
		echo "fuzz: the timeout's input takes $ms ms alone (exit $rrc): a finding"
	fi
fi
echo "$(date -u +%Y-%m-%dT%H:%M:%SZ) secs=$took execs=${execs:-0} exit=$rc units=$units" >> "$dir/history"
set -e
if [ "$rc" = 0 ]; then
	echo "tests: 1 passed, 0 failed"
else
	ls "$dir/artifacts" >&2
	echo "tests: 0 passed, 1 failed"
	exit 1
fi
