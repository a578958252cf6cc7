#!/bin/sh
# test.sh - set up (scripts/setup.sh --tests: the packages the tests
# need too), run the whole test suite, and end
# with the line "tests: N passed, M failed".
set -e
cd "$(dirname "$0")/.."
sh scripts/setup.sh --tests
# the tools are installed now: a test that skips for want of one (tmux,
# mpirun) fails (tests/tap.sh's skip_all and skip_one)
export SLIPWALL_TEST_TOOLS=required
set +e
meson test -C build --print-errorlogs --num-processes 2 > build/test-output.txt 2>&1
rc=$?
set -e
cat build/test-output.txt
. scripts/meson-counts.sh
[ "$rc" = 0 ] || meson_failures build
meson_counts build/test-output.txt "$rc"
echo "tests: $mpassed passed, $mfailed failed"
[ "$rc" = 0 ] && [ "$mfailed" = 0 ]
