#!/bin/bash
# cluster.sh - the figures of docs/cluster.md, "Scaling": `slipwall run`
# as one process and under mpirun, measured on this machine.
#
#   bash bench/cluster.sh [SLIPWALL [MPIRUN]]    (from the source root;
#                                                 default build/slipwall, mpirun)
#
# Speed: for each wall of CLUSTER_WALLS (default walls/demo.yaml
# walls/ferris-tinloi-1.yaml), CLUSTER_N samples (300), seed 1, with
# --samples, every configuration below CLUSTER_REPEAT times (5),
# interleaved (one round runs each configuration once) so that a change
# of the machine's load hits them all alike.  For each: the median and
# the range of the JSON's elapsed_seconds (the sampling, without
# mpirun's start-up), samples/s and the speed-up of the median over one
# process with one thread; the median CPU time (user + system, every
# process of the job: mpirun and every rank) per sample, which contention
# does not change much; and "same": every run wrote the samples file of
# the first, byte for byte.
#
# First, what mpirun itself costs (start-up and end, in elapsed and CPU
# time): it is in the CPU figures of the mpirun configurations, not in
# their elapsed_seconds.
#
# On a shared machine the wall-clock figures measure the share of the
# CPUs this job got: Linux's autogroup scheduler divides the CPUs
# between the busy terminal sessions first, so with other sessions busy
# a job of 2 threads may get no more CPU than a job of 1.  The CPU time
# per sample, and the load average printed beside each table, say how
# far to trust them.
#
# Rank 0's share of the work: rank 0's main thread does all of the
# merging (receiving, writing the rows, the tally).  Its CPU time is read
# from /proc/PID/task/PID/schedstat (nanoseconds) every 20 ms while it
# runs; the cost per sample is the difference between a run of
# CLUSTER_MERGE_N samples and one of 10 samples, over the difference of
# samples (which takes out the start-up and the summary).  The same for
# one process's main thread (its consumer), for comparison.  Walls:
# walls/single-block.yaml (samples of ~0.1 ms: the merge at full speed)
# and walls/demo.yaml; with and without --samples.
#
# The load average is printed before and after every group of runs:
# other work on the machine shows in it, and in the figures.  Set
# CLUSTER_MERGE=0 to skip the second part.  As root, mpirun's consent is
# given in the environment (as in tests/cli/mpi.sh).
set -u
# --probe OUT CMD...: run CMD; unless this is a rank > 0 of an MPI job,
# write the CPU time (ns) of CMD's main thread, read every 20 ms until it
# exits, to OUT.  Builtins only in the loop: the probe costs next to
# nothing.
if [ "${1:-}" = --probe ]; then
	out=$2
	shift 2
	[ "${OMPI_COMM_WORLD_RANK:-0}" = 0 ] || exec "$@"
	"$@" &
	pid=$!
	fifo=$(mktemp -u)
	mkfifo "$fifo"
	exec 3<>"$fifo"
	rm -f "$fifo"
	last=0
	exec 4>&2 2>/dev/null	# (a file gone at exit is no error)
	while read -r v _ <"/proc/$pid/task/$pid/schedstat"; do
		last=$v
		read -r _ _ state _ <"/proc/$pid/stat"
		[ "$state" = Z ] && break	# exited: this was its last reading
		read -r -t 0.02 -u 3
	done
	exec 2>&4 4>&-
	wait "$pid"
	rc=$?
	echo "$last" >"$out"
	exit $rc
fi
self=$(cd "$(dirname "$0")" && pwd)/$(basename "$0")
cd "$(dirname "$0")/.." || exit 1
bin=${1:-build/slipwall}
mpirun=${2:-mpirun}
walls=${CLUSTER_WALLS:-walls/demo.yaml walls/ferris-tinloi-1.yaml}
N=${CLUSTER_N:-300}
R=${CLUSTER_REPEAT:-5}
MERGE=${CLUSTER_MERGE:-1}
if [ "$(id -u)" = 0 ]; then
	export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
export OMPI_MCA_btl_vader_single_copy_mechanism=none
mpi=("$mpirun" --oversubscribe --bind-to none)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

load() {
	cut -d' ' -f1-3 /proc/loadavg
}

echo "machine: $(nproc) CPUs, $(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -n 1)"
echo "kernel:  $(uname -r); Open MPI $("$mpirun" --version 2>/dev/null | sed -n 's/.*(Open MPI) //p' | head -n 1)"
echo "date:    $(date -u '+%Y-%m-%d %H:%M UTC')"
echo "binary:  $bin ($("$bin" --version 2>&1 | head -n 1)); this tree: $(git log -1 --format=%h 2>/dev/null || echo 'not a git checkout')$(git diff --quiet -- src include 2>/dev/null || echo ', with uncommitted changes in src/ include/')"
echo

# ---- speed -------------------------------------------------------------------
# configuration k: its label and its command (WALL, CSV appended)
labels=("1 process x 1 thread" "mpirun -n 1 x 1 thread" "mpirun -n 2 x 1 thread"
	"1 process x 2 threads" "mpirun -n 4 x 1 thread (oversubscribed)")
cmd() {	# cmd K WALL CSV
	local k=$1 wall=$2 csv=$3
	local args=(run "$wall" -n "$N" --seed 1 --json --samples "$csv")
	case $k in
	0) "$bin" "${args[@]}" --threads 1 ;;
	1) "${mpi[@]}" -n 1 "$bin" "${args[@]}" --threads 1 ;;
	2) "${mpi[@]}" -n 2 "$bin" "${args[@]}" --threads 1 ;;
	3) "$bin" "${args[@]}" --threads 2 ;;
	4) "${mpi[@]}" -n 4 "$bin" "${args[@]}" --threads 1 ;;
	esac
}
# child_cpu: user + system seconds of every process this shell has
# waited for so far (the bash builtin `times`, run in this shell: a
# subshell would count its own children only: so not $(child_cpu), it
# sets $cpu_now); mpirun waits for its ranks, so a job's CPU counts in
# full
child_cpu() {
	times >"$tmp/times"
	cpu_now=$(awk 'NR == 2 { t = 0; for (i = 1; i <= NF; i++) {
		split($i, a, "m"); sub("s", "", a[2]); t += a[1] * 60 + a[2] }
		print t }' "$tmp/times")
}
median_range() {	# numbers on stdin: "median min max"
	sort -g | awk '{ x[NR] = $1 } END {
		m = NR % 2 ? x[(NR + 1) / 2] : (x[NR / 2] + x[NR / 2 + 1]) / 2
		printf "%.2f %.2f %.2f\n", m, x[1], x[NR] }'
}
# what mpirun itself costs: 2 ranks, 2 samples of a one-block wall
for k in 1 2 3; do
	child_cpu
	c0=$cpu_now
	t0=$(date +%s%N)
	"${mpi[@]}" -n 2 "$bin" run walls/single-block.yaml -n 2 --threads 1 >/dev/null 2>&1
	t1=$(date +%s%N)
	child_cpu
	echo "mpirun -n 2, 2 samples of walls/single-block.yaml: $(awk -v a="$t0" -v b="$t1" \
		'BEGIN { printf "%.2f", (b - a) / 1e9 }') s elapsed, $(awk -v a="$c0" -v b="$cpu_now" \
		'BEGIN { printf "%.2f", b - a }') s of CPU (start-up and end)"
done
echo

for wall in $walls; do
	w=$(basename "$wall" .yaml)
	echo "== $w: $N samples, seed 1, median of $R runs (load before: $(load))"
	printf '| %-40s | %11s | %11s | %9s | %8s | %13s | %4s |\n' configuration "elapsed (s)" range \
		samples/s speed-up "CPU ms/sample" same
	for r in $(seq "$R"); do
		for k in "${!labels[@]}"; do
			child_cpu
			c0=$cpu_now
			cmd "$k" "$wall" "$tmp/$w.$k.$r.csv" >"$tmp/$w.$k.$r.json" 2>"$tmp/$w.$k.$r.err" ||
				echo "   (run $r of '${labels[$k]}' failed: $(head -c 200 "$tmp/$w.$k.$r.err"))"
			child_cpu
			awk -v a="$c0" -v b="$cpu_now" -v n="$N" 'BEGIN { print (b - a) * 1000 / n }' \
				>"$tmp/$w.$k.$r.cpu"
		done
	done
	base=
	for k in "${!labels[@]}"; do
		read -r med lo hi < <(for r in $(seq "$R"); do
			python3 -c 'import json,sys; print(json.load(open(sys.argv[1]))["elapsed_seconds"])' \
				"$tmp/$w.$k.$r.json" 2>/dev/null || echo nan
		done | median_range)
		read -r cpu _ < <(cat "$tmp/$w.$k".*.cpu | median_range)
		[ -z "$base" ] && base=$med
		same=yes
		for r in $(seq "$R"); do
			cmp -s "$tmp/$w.0.1.csv" "$tmp/$w.$k.$r.csv" || same=NO
		done
		printf '| %-40s | %11s | %11s | %9.1f | %8.2f | %13s | %4s |\n' "${labels[$k]}" "$med" "$lo-$hi" \
			"$(awk -v a="$N" -v b="$med" 'BEGIN { print a / b }')" \
			"$(awk -v a="$base" -v b="$med" 'BEGIN { print a / b }')" "$cpu" "$same"
	done
	echo "(load after: $(load))"
	echo
done

[ "$MERGE" = 0 ] && exit 0

# ---- rank 0's main thread --------------------------------------------------
# cpu_of MODE WALL N FILE: main-thread CPU (ns) of one process (MODE 1)
# or of rank 0 of 2 (MODE 2), 1 thread each; FILE: --samples or "-".
# The process is started by this script's --probe mode (below), which
# reads its main thread's CPU time until it exits.
cpu_of() {
	local mode=$1 wall=$2 n=$3 file=$4
	local args=(run "$wall" -n "$n" --seed 1 --threads 1)
	[ "$file" != - ] && args+=(--samples "$file")
	rm -f "$tmp/cpu"
	if [ "$mode" = 1 ]; then
		bash "$self" --probe "$tmp/cpu" "$bin" "${args[@]}" >/dev/null 2>&1
	else
		"${mpi[@]}" -n 2 bash "$self" --probe "$tmp/cpu" "$bin" "${args[@]}" >/dev/null 2>&1
	fi
	cat "$tmp/cpu" 2>/dev/null || echo nan
}
echo "== rank 0's main thread: CPU per sample (load before: $(load))"
printf '| %-28s | %-38s | %12s |\n' wall configuration "us/sample"
for spec in "walls/single-block.yaml ${CLUSTER_MERGE_N:-40000}" "walls/demo.yaml ${CLUSTER_MERGE_DEMO_N:-600}"; do
	read -r wall n <<<"$spec"
	for mode in 1 2; do
		for file in "$tmp/m.csv" -; do
			a=$(cpu_of $mode "$wall" 10 "$file")
			b=$(cpu_of $mode "$wall" "$n" "$file")
			what=$([ $mode = 1 ] && echo "one process" || echo "rank 0 of 2")
			what="$what, $([ "$file" = - ] && echo "no samples file" || echo "--samples")"
			printf '| %-28s | %-38s | %12.1f |\n' "$(basename "$wall") ($n)" "$what" \
				"$(awk -v a="$a" -v b="$b" -v n="$n" 'BEGIN { print (b - a) / 1000 / (n - 10) }')"
		done
	done
done
echo "(load after: $(load))"
