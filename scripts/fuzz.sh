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
# Environment: FUZZ_DIR (build-fuzz), FUZZ_ARGS (extra libFuzzer flags).
# Ends with "tests: 1 passed, 0 failed" or "tests: 0 passed, 1 failed".
set -e
cd "$(dirname "$0")/.."
secs=${1:-60}
dir=${FUZZ_DIR:-build-fuzz}

if ! command -v clang >/dev/null 2>&1 ||
   ! ls /usr/lib/llvm-*/lib/clang/*/lib/linux/libclang_rt.fuzzer-x86_64.a >/dev/null 2>&1; then
	echo "fuzz: installing clang" >&2
	export DEBIAN_FRONTEND=noninteractive
	apt-get update -qq
	apt-get install -y -qq clang libclang-rt-dev >/dev/null
fi
# the library is instrumented for coverage (fuzzer-no-link); layouts are
# limited to 400 blocks here (src/layout.c) to keep executions fast
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
# -timeout: one input (parse + one sample of <= 40 blocks) takes ms.
# one process (no -jobs): the machine is shared; niced.
set +e
ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1} \
UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
nice -n 19 "$dir/fuzz/fuzz_wallfile" -max_total_time="$secs" \
	-rss_limit_mb=2048 -max_len=4096 -timeout=20 \
	-print_final_stats=1 -artifact_prefix="$dir/artifacts/" \
	${FUZZ_ARGS:-} \
	"$dir/corpus" "$dir/seeds" > "$dir/fuzz.log" 2>&1
rc=$?
set -e
tail -n 25 "$dir/fuzz.log"
execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$dir/fuzz.log" | tail -n 1)
echo "fuzz: ${execs:-?} executions in ${secs} s, exit $rc"
if [ "$rc" = 0 ]; then
	echo "tests: 1 passed, 0 failed"
else
	ls "$dir/artifacts" >&2
	echo "tests: 0 passed, 1 failed"
	exit 1
fi
