#!/bin/bash
# cli_mpi.sh - `mpirun -n P slipwall run` (docs/cluster.md) end to end.
#
# Usage (from the source root): bash tests/cli_mpi.sh SLIPWALL MPIRUN
# Proves: with 2 ranks (1 and 2 threads each; oversubscribed on a small
# machine) the samples file is byte-identical to a single process's with
# one thread and the JSON equal apart from timing, thread and rank keys,
# on two walls and seeds, with N odd and N smaller than the rank count,
# and 20001 fast samples on 3 ranks (rank 0's flow control at work);
# --until-ci stops at the same sample; --positions replays under mpirun;
# rank 0 alone prints the summary; a usage error is printed once; ranks
# that set up different runs are refused (exit 2).  Faults: a rank
# killed by SIGKILL mid-run, and SIGINT to mpirun, leave complete rows
# that are a prefix of the single process's file, and mpirun returns
# within a bounded time; SIGINT to rank 0 alone ends the job cleanly with
# the summary of those rows; a rank that stops answering (SIGSTOP) is given
# up after SLIPWALL_MPI_TIMEOUT seconds with a message naming it and a
# summary of what was done.  TAP output.  Needs python3.

bin=${1:?usage: cli_mpi.sh SLIPWALL MPIRUN}
mpirun=${2:?usage: cli_mpi.sh SLIPWALL MPIRUN}
cd "$(dirname "$0")/.." || exit 1

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
	for line in "$@"; do
		printf '#   %s\n' "$line"
	done
}
check() {	# check NAME COMMAND...: ok when the command succeeds
	local name=$1
	shift
	if "$@"; then ok "$name"; else not_ok "$name"; fi
}
# complete FILE: every line has the header's number of fields, the file
# ends with a newline and the rows are samples 0..k-1
complete() {
	awk -F, 'NR == 1 { c = NF } NF != c || (NR > 1 && $1 != NR - 2) { bad++ }
		END { exit bad > 0 }' "$1" &&
		[ "$(tail -c 1 "$1" | od -An -c | tr -d ' ')" = '\n' ]
}
rows() {	# data rows of a samples file
	echo $(($(wc -l <"$1") - 1))
}

tmp=$(mktemp -d)
mpipid=
cleanup() {
	# only what this script started: a stopped rank dies with its mpirun
	[ -n "$mpipid" ] && stop_mpirun "$mpipid"
	rm -rf "$tmp"
}
trap cleanup EXIT
demo=walls/demo.yaml
ft=walls/ferris-tinloi-1.yaml

# mpirun as root needs its consent; more ranks than cores is the point
# here; the shared-memory transport's single-copy mode needs ptrace
# rights that containers often lack (and these messages are small)
if [ "$(id -u)" = 0 ]; then
	export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
export OMPI_MCA_btl_vader_single_copy_mechanism=none
# "${mpi[@]}" -n P "$bin" ARGS: not a function, so that $! of a
# background job is mpirun itself (env execs it).  Under AddressSanitizer
# (scripts/ci-sanitize.sh) the ranks check memory errors but not leaks:
# Open MPI does not free everything at MPI_Finalize, from plugins it has
# unloaded by then (no stack to suppress them by); the single-process
# runs here and in the other tests still check leaks.
mpi=(env "ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
	"$mpirun" --oversubscribe --bind-to none)
strip='import json,sys
d=json.load(open(sys.argv[1]))
for k in ("elapsed_seconds","samples_per_second","threads","ranks","samples_file"):
    d.pop(k,None)
print(json.dumps(d,sort_keys=True))'
same_json() {	# same_json A B: equal apart from timing, threads, ranks, file
	local a b
	a=$(python3 -c "$strip" "$1" 2>&1)
	b=$(python3 -c "$strip" "$2" 2>&1)
	[ -n "$a" ] && [ "$a" = "$b" ] && case $a in *'"samples"'*) ;; *) false ;; esac
}

# ---- the same samples as one process ---------------------------------------
# compare NAME WALL SEED N THREADS [RANKS]: one process with 1 thread
# against RANKS (2) ranks with THREADS threads each
compare() {
	local name=$1 wall=$2 seed=$3 nn=$4 th=$5 np=${6:-2}
	"$bin" run "$wall" -n "$nn" --seed "$seed" --threads 1 --json \
		--samples "$tmp/$name.1.csv" >"$tmp/$name.1.json" 2>"$tmp/$name.1.err"
	local rc1=$?
	"${mpi[@]}" -n "$np" "$bin" run "$wall" -n "$nn" --seed "$seed" --threads "$th" --json \
		--samples "$tmp/$name.2.csv" >"$tmp/$name.2.json" 2>"$tmp/$name.2.err"
	local rc2=$?
	local what="$wall -n $nn --seed $seed, $np ranks x $th thread(s)"
	if [ $rc1 -eq 0 ] && [ $rc2 -eq 0 ] && [ "$(rows "$tmp/$name.2.csv")" = "$nn" ] &&
		cmp -s "$tmp/$name.1.csv" "$tmp/$name.2.csv"; then
		ok "$what: exit 0, $nn rows, the samples file byte-identical to one process's"
	else
		not_ok "$what: the samples file byte-identical" "exit $rc1 / $rc2" \
			"$(head -c 300 "$tmp/$name.2.err")" \
			"$(diff "$tmp/$name.1.csv" "$tmp/$name.2.csv" 2>&1 | head -4 | cut -c1-160)"
	fi
	if same_json "$tmp/$name.1.json" "$tmp/$name.2.json"; then
		ok "$what: the JSON equal apart from timing, threads, ranks and the file name"
	else
		not_ok "$what: the JSON equal" "$(head -c 300 "$tmp/$name.2.json")"
	fi
}
compare ft1 $ft 7 60 1
compare ft2 $ft 7 60 2
compare demo1 $demo 3 101 1	# N odd: rank 0 computes one more
compare demo2 $demo 11 45 2
# fast samples, many per rank: rank 0's flow control (at most 128 samples
# of a rank waiting in its queue) is exercised thousands of times
compare sb walls/single-block.yaml 9 20001 1 3

check "the JSON of 2 ranks says ranks 2 and threads per rank" \
	python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(not (d["ranks"]==2 and d["threads"]==2))' "$tmp/ft2.2.json"

# N smaller than the rank count: rank 2 has nothing to compute
"${mpi[@]}" -n 3 "$bin" run $demo -n 2 --seed 3 --threads 1 --samples "$tmp/n2.csv" --json \
	>"$tmp/n2.json" 2>"$tmp/n2.err"
rc=$?
check "-n 2 on 3 ranks: exit 0, the first 2 rows of one process's file" \
	eval '[ $rc -eq 0 ] && cmp -s "$tmp/n2.csv" <(head -n 3 "$tmp/demo1.1.csv")'

# rank 0 alone prints: one summary on stdout
"${mpi[@]}" -n 2 "$bin" run $demo -n 20 --seed 3 --threads 1 >"$tmp/txt.out" 2>"$tmp/txt.err"
rc=$?
cnt=$(grep -c '^samples ' "$tmp/txt.out")
check "text summary printed once, by rank 0: 'samples 20 of 20 (..., 2 ranks x 1 thread)'" \
	eval '[ $rc -eq 0 ] && [ "$cnt" = 1 ] && grep -q "samples      20 of 20 (seed 3, depth 0.25, 2 ranks x 1 thread)" "$tmp/txt.out"'

# ---- --until-ci and --positions ----------------------------------------------
"$bin" run $ft -n 3000 --seed 5 --until-ci 0.03 --threads 1 --json \
	--samples "$tmp/u1.csv" >"$tmp/u1.json" 2>/dev/null
"${mpi[@]}" -n 2 "$bin" run $ft -n 3000 --seed 5 --until-ci 0.03 --threads 2 --json \
	--samples "$tmp/u2.csv" >"$tmp/u2.json" 2>"$tmp/u2.err"
rc=$?
if [ $rc -eq 0 ] && cmp -s "$tmp/u1.csv" "$tmp/u2.csv" &&
	same_json "$tmp/u1.json" "$tmp/u2.json" &&
	python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(not (d["stopped"]=="until_ci" and 90 < d["samples"] < 3000))' "$tmp/u2.json"; then
	ok "--until-ci 0.03: 2 ranks stop at the same sample as one process ($(rows "$tmp/u2.csv") of 3000), same file and JSON"
else
	not_ok "--until-ci: the same stop as one process" "exit $rc: $(head -c 200 "$tmp/u2.err")" \
		"rows $(rows "$tmp/u1.csv") / $(rows "$tmp/u2.csv")"
fi

"${mpi[@]}" -n 2 "$bin" run $ft --positions "$tmp/ft1.1.csv" --threads 1 --samples "$tmp/rp.csv" \
	>/dev/null 2>"$tmp/rp.err"
rc=$?
check "--positions under mpirun: the replay is the same file again" \
	eval '[ $rc -eq 0 ] && cmp -s "$tmp/ft1.1.csv" "$tmp/rp.csv"'

# ---- set-up errors -----------------------------------------------------------
"${mpi[@]}" -n 2 "$bin" run $demo -n 0 >"$tmp/bad.out" 2>"$tmp/bad.err"
rc=$?
cnt=$(grep -c "is not a sample count" "$tmp/bad.err")
check "a usage error under mpirun: exit 2, the message once (rank 0's)" \
	eval '[ $rc -eq 2 ] && [ "$cnt" = 1 ] && [ ! -s "$tmp/bad.out" ]'
# two ranks that set up different runs (MPMD: -n 10 and -n 11)
"${mpi[@]}" -n 1 "$bin" run $demo -n 10 --threads 1 \
	--samples "$tmp/dif.csv" : -n 1 "$bin" run $demo -n 11 --threads 1 \
	--samples "$tmp/dif.csv" >"$tmp/dif.out" 2>"$tmp/dif.err"
rc=$?
check "ranks that set up different runs (-n 10 and -n 11): exit 2, 'rank 1 set up another run'" \
	eval '[ $rc -eq 2 ] && grep -q "rank 1 set up another run than rank 0" "$tmp/dif.err" &&
	[ "$(rows "$tmp/dif.csv")" = 0 ]'

# ---- faults ------------------------------------------------------------------
# wait_rows FILE K: wait (at most 60 s) until FILE has K data rows
wait_rows() {
	local i
	for i in $(seq 600); do
		[ -f "$1" ] && [ "$(wc -l <"$1")" -gt "$2" ] && return 0
		sleep 0.1
	done
	return 1
}
# rank_pid MPIRUN_PID RANK: the process of that rank (a child of mpirun)
rank_pid() {
	local d
	for d in /proc/[0-9]*; do
		[ "$(awk '{print $4}' "$d/stat" 2>/dev/null)" = "$1" ] || continue
		if tr '\0' '\n' <"$d/environ" 2>/dev/null |
			grep -qx "OMPI_COMM_WORLD_RANK=$2"; then
			echo "${d#/proc/}"
			return 0
		fi
	done
	return 1
}
# stop_mpirun PID: SIGTERM (mpirun then ends its ranks), SIGKILL 5 s later
stop_mpirun() {
	local i
	kill -TERM "$1" 2>/dev/null
	for i in $(seq 50); do
		kill -0 "$1" 2>/dev/null || break
		sleep 0.1
	done
	kill -9 "$1" 2>/dev/null
	wait "$1" 2>/dev/null
}
# wait_gone PID SECONDS: wait for mpirun; its exit status, or 124 if it
# is still running after SECONDS (then it is stopped)
wait_gone() {
	local i
	for i in $(seq $(($2 * 10))); do
		kill -0 "$1" 2>/dev/null || break
		sleep 0.1
	done
	if kill -0 "$1" 2>/dev/null; then
		stop_mpirun "$1"
		return 124
	fi
	wait "$1"
}
# prefix FILE SEED: FILE's rows are those of one process with that seed
prefix() {
	local k
	k=$(rows "$1")
	[ "$k" -gt 0 ] || return 1
	"$bin" run $demo -n "$k" --seed "$2" --threads 2 \
		--samples "$tmp/ref$2.csv" >/dev/null 2>&1 &&
		cmp -s "$1" "$tmp/ref$2.csv"
}

set -m	# job control: a background job does not ignore SIGINT

# a rank killed by SIGKILL: mpirun ends the job
"${mpi[@]}" -n 2 "$bin" run $demo -n 5000 --seed 21 --threads 1 --samples "$tmp/k.csv" --json \
	>"$tmp/k.json" 2>"$tmp/k.err" &
mpipid=$!
wait_rows "$tmp/k.csv" 20
r1=$(rank_pid $mpipid 1)
t0=$(date +%s)
[ -n "$r1" ] && kill -9 "$r1"
wait_gone $mpipid 60
rc=$?
mpipid=
dt=$(($(date +%s) - t0))
check "SIGKILL of rank 1 (pid ${r1:-none}): mpirun returns in $dt s (at most 30), exit $rc (not 0)" \
	eval '[ -n "$r1" ] && [ $rc -ne 0 ] && [ $rc -ne 124 ] && [ $dt -le 30 ]'
check "SIGKILL of rank 1: $(rows "$tmp/k.csv") rows, every line complete, samples 0..k-1" \
	complete "$tmp/k.csv"
check "SIGKILL of rank 1: the rows are one process's first rows, byte for byte" \
	prefix "$tmp/k.csv" 21

# SIGINT to mpirun: it stops every rank (SIGTERM, SIGKILL 1 s later)
"${mpi[@]}" -n 2 "$bin" run $demo -n 5000 --seed 22 --threads 1 --samples "$tmp/i.csv" --json \
	>"$tmp/i.json" 2>"$tmp/i.err" &
mpipid=$!
wait_rows "$tmp/i.csv" 20
t0=$(date +%s)
kill -INT $mpipid
wait_gone $mpipid 60
rc=$?
mpipid=
dt=$(($(date +%s) - t0))
k=$(rows "$tmp/i.csv")
check "SIGINT to mpirun: it returns in $dt s (at most 30), exit $rc (not 0)" \
	eval '[ $rc -ne 0 ] && [ $rc -ne 124 ] && [ $dt -le 30 ]'
check "SIGINT to mpirun: $k rows, every line complete, samples 0..k-1" \
	complete "$tmp/i.csv"
check "SIGINT to mpirun: the rows are one process's first rows, byte for byte" \
	prefix "$tmp/i.csv" 22
# rank 0 has a second before SIGKILL: when it got to its last message
# (printed after the summary), the summary counts exactly the rows of
# the file
if grep -q "interrupted" "$tmp/i.err"; then
	jn=$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(d["samples"] if d["stopped"]=="interrupted" else -1)' "$tmp/i.json" 2>&1)
	check "SIGINT to mpirun: rank 0's summary says interrupted after the $k samples of the file" \
		eval '[ "$jn" = "$k" ] && grep -q "interrupted (.*) after $k of 5000 samples" "$tmp/i.err"'
else
	ok "SIGINT to mpirun: rank 0 was killed before its summary (allowed; the file is checked above)"
fi

# SIGINT to rank 0 alone: it stops the others and ends cleanly
"${mpi[@]}" -n 2 "$bin" run $demo -n 5000 --seed 24 --threads 1 --samples "$tmp/r0.csv" --json \
	>"$tmp/r0.json" 2>"$tmp/r0.err" &
mpipid=$!
wait_rows "$tmp/r0.csv" 20
r0=$(rank_pid $mpipid 0)
[ -n "$r0" ] && kill -INT "$r0"
wait_gone $mpipid 60
rc=$?
mpipid=
k=$(rows "$tmp/r0.csv")
jn=$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(d["samples"] if d["stopped"]=="interrupted" else -1)' "$tmp/r0.json" 2>&1)
check "SIGINT to rank 0 (pid ${r0:-none}): exit $rc (1), 'interrupted (Interrupt) after $k of 5000' and a JSON summary of the same $k samples" \
	eval '[ -n "$r0" ] && [ $rc -eq 1 ] && [ "$jn" = "$k" ] && grep -q "interrupted (Interrupt) after $k of 5000 samples" "$tmp/r0.err"'
check "SIGINT to rank 0: $k complete rows, one process's first rows" \
	eval 'complete "$tmp/r0.csv" && prefix "$tmp/r0.csv" 24'

# a rank that stops answering: given up after the timeout
SLIPWALL_MPI_TIMEOUT=3 "${mpi[@]}" -n 2 -x SLIPWALL_MPI_TIMEOUT "$bin" run $demo -n 5000 --seed 23 --threads 1 \
	--samples "$tmp/s.csv" --json >"$tmp/s.json" 2>"$tmp/s.err" &
mpipid=$!
wait_rows "$tmp/s.csv" 20
r1=$(rank_pid $mpipid 1)
t0=$(date +%s)
[ -n "$r1" ] && kill -STOP "$r1"
wait_gone $mpipid 60
rc=$?
mpipid=
dt=$(($(date +%s) - t0))
k=$(rows "$tmp/s.csv")
check "rank 1 stopped (SIGSTOP), SLIPWALL_MPI_TIMEOUT=3: mpirun returns in $dt s (3 to 30), exit $rc (not 0)" \
	eval '[ -n "$r1" ] && [ $rc -ne 0 ] && [ $rc -ne 124 ] && [ $dt -ge 3 ] && [ $dt -le 30 ]'
check "the silent rank: 'rank 1 sent nothing for 3 s' and 'stopped after $k of 5000 samples' on stderr" \
	grep -q "rank 1 sent nothing for 3 s.*stopped after $k of 5000 samples" "$tmp/s.err"
check "the silent rank: JSON stopped rank_lost, $k samples, as many as rows" \
	python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(not (d["stopped"]=="rank_lost" and d["samples"]==int(sys.argv[2])))' "$tmp/s.json" "$k"
check "the silent rank: $k complete rows, one process's first rows" \
	eval 'complete "$tmp/s.csv" && prefix "$tmp/s.csv" 23'
set +m

echo "1..$n"
[ $failed -eq 0 ]
