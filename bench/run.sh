#!/bin/bash
# run.sh - the sampling benchmark on the bundled walls (docs/performance.md).
#
# Usage: bash bench/run.sh BENCH_EXE      (or: meson compile -C build bench)
# Environment: BENCH_THREADS (default "1,2"), BENCH_N_SMALL (samples for
# the demo and Ferris & Tin-Loi walls, default 400), BENCH_N_LARGE
# (samples for the 1020-block wall, default 6), BENCH_N_BODY (samples
# of the body-loaded walls of issue 25: tests/data/body-195.yaml, and
# walls/body-1000.yaml at a tenth of it, at least 2; default 20; 0
# leaves them out: body-1000 takes minutes).
bench=${1:?usage: run.sh BENCH_EXE}
cd "$(dirname "$0")/.." || exit 1
threads=${BENCH_THREADS:-1,2}

echo "machine: $(nproc) CPUs, $(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)"
echo "kernel:  $(uname -sr); GLPK $(dpkg-query -W -f '${Version}' libglpk40 2>/dev/null || echo '?')"
echo "load:    $(cut -d' ' -f1-3 /proc/loadavg) (1, 5, 15 min; other work skews the figures)"
echo "date:    $(date -u '+%Y-%m-%d %H:%M UTC')"
echo
rc=0
"$bench" walls/demo.yaml -n "${BENCH_N_SMALL:-400}" --threads "$threads" || rc=1
"$bench" walls/ferris-tinloi-1.yaml -n "${BENCH_N_SMALL:-400}" --threads "$threads" || rc=1
"$bench" walls/large.yaml -n "${BENCH_N_LARGE:-6}" --threads "$threads" || rc=1
# issue 25's figures: body-195's samples/s on two threads, body-1000's
# seconds to its first sample ("first s")
nbody=${BENCH_N_BODY:-20}
if [ "$nbody" -gt 0 ]; then
	"$bench" tests/data/body-195.yaml -n "$nbody" --threads "$threads" || rc=1
	n1000=$((nbody / 10 > 2 ? nbody / 10 : 2))
	"$bench" walls/body-1000.yaml -n "$n1000" --threads "$threads" || rc=1
fi
exit $rc
