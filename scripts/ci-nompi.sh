#!/bin/sh
# ci-nompi.sh - the whole suite on a build without MPI (build-nompi/,
# meson -Dmpi=disabled), on a machine where Open MPI is installed: the
# program must build and pass every test as before, and its
# `nompi_cli` test checks that it refuses to be one of several ranks
# (docs/cluster.md).  Ends with "tests: N passed, M failed".
set -e
cd "$(dirname "$0")/.."
sh scripts/setup.sh --tests --packages
dir=build-nompi
[ -f "$dir/build.ninja" ] || meson setup "$dir" -Dmpi=disabled >/dev/null
meson compile -C "$dir" >/dev/null
set +e
meson test -C "$dir" --print-errorlogs --num-processes 2 > "$dir/test-output.txt" 2>&1
rc=$?
set -e
grep -E '^ *[0-9]+/[0-9]+ ' "$dir/test-output.txt"
if ! grep -qE '^ *[0-9]+/[0-9]+ ([^ ]+ / )?nompi_cli +OK' "$dir/test-output.txt"; then
	echo "ci-nompi: the nompi_cli test did not run and pass: is this build without MPI?"
	rc=1
fi
if grep -qE '^ *[0-9]+/[0-9]+ ([^ ]+ / )?mpi_cli ' "$dir/test-output.txt"; then
	echo "ci-nompi: mpi_cli ran: the build has MPI"
	rc=1
fi
. scripts/meson-counts.sh
[ "$rc" = 0 ] || meson_failures "$dir"
meson_counts "$dir/test-output.txt" "$rc"
echo "tests: $mpassed passed, $mfailed failed"
[ "$rc" = 0 ] && [ "$mfailed" = 0 ]
