#!/bin/sh
# test.sh - set up (scripts/setup.sh), run the whole test suite, and end
# with the line "tests: N passed, M failed".
set -e
cd "$(dirname "$0")/.."
sh scripts/setup.sh
set +e
meson test -C build --print-errorlogs --num-processes 2 > build/test-output.txt 2>&1
rc=$?
set -e
cat build/test-output.txt
passed=$(sed -n 's/^Ok: *\([0-9]*\).*/\1/p' build/test-output.txt | tail -n 1)
failed=$(sed -n 's/^Fail: *\([0-9]*\).*/\1/p' build/test-output.txt | tail -n 1)
timeout=$(sed -n 's/^Timeout: *\([0-9]*\).*/\1/p' build/test-output.txt | tail -n 1)
passed=${passed:-0}
failed=$(( ${failed:-0} + ${timeout:-0} ))
if [ "$rc" != 0 ] && [ "$failed" = 0 ]; then failed=1; fi
echo "tests: $passed passed, $failed failed"
[ "$rc" = 0 ]
