#!/bin/bash
# cli/mpi.sh - `mpirun -n P slipwall run` (docs/cluster.md) end to end.
#
# Usage (from the source root): bash tests/cli/mpi.sh SLIPWALL MPIRUN
# Proves: with 2 ranks (1 and 2 threads each; oversubscribed on a small
# machine) the samples file is byte-identical to a single process's and
# the JSON the same text apart from the timing keys (elapsed_seconds,
# samples_per_second) and the added "ranks", on two walls and seeds, with
# N odd and N smaller than the rank count, and 20001 fast samples on 3
# ranks (rank 0's flow control at work); the default threads per rank;
# --until-ci stops at the same sample; --positions replays under mpirun;
# random friction's draws cross the wire and replay;
# rank 0 alone prints the summary; a usage error and an error in the wall
# file are printed once, a rank's own set-up error by that rank; ranks
# that set up different runs (or --help on one only) are refused (exit
# 2).  Faults: SIGKILL of rank 1 and of rank 0 mid-run, SIGINT and
# SIGTERM to mpirun, SIGINT to rank 0 alone and SIGTERM to rank 1 alone
# leave complete rows that are a prefix of the single process's file, in
# a bounded time, with the message that says what happened; a rank that
# stops answering (SIGSTOP of rank 1, of rank 0), or that stops half way
# through sending a sample (SLIPWALL_MPI_FAULT=stop:K, src/cli/cluster.c), is
# given up after SLIPWALL_MPI_TIMEOUT seconds with a message naming it
# and (rank 0 alive) a summary of what was done.  TAP output.  Needs
# python3.
#
# With MPIRUN "none" (a build without MPI): a process started by a
# launcher among several refuses (exit 2), only launcher rank 0 says why,
# and one started alone (mpirun -n 1) runs.  With MPIRUN "missing" (a
# build with MPI where meson found no mpirun): skipped, and a failure in
# CI (tests/tap.sh's skip_all).

bin=${1:?usage: cli/mpi.sh SLIPWALL MPIRUN}
mpirun=${2:?usage: cli/mpi.sh SLIPWALL MPIRUN}
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh
[ "$mpirun" = missing ] &&
	skip_all "the build has MPI but mpirun is not installed (Debian: openmpi-bin)"
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

# ---- a build without MPI ----------------------------------------------------
# The environment Open MPI's mpirun gives its processes is enough here:
# such a build never talks to the launcher.
if [ "$mpirun" = none ]; then
	OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=0 "$bin" run $demo -n 3 \
		--samples "$tmp/no0.csv" >"$tmp/no0.out" 2>"$tmp/no0.err"
	rc0=$?
	OMPI_COMM_WORLD_SIZE=2 OMPI_COMM_WORLD_RANK=1 "$bin" run $demo -n 3 \
		--samples "$tmp/no1.csv" >"$tmp/no1.out" 2>"$tmp/no1.err"
	rc1=$?
	check "without MPI, rank 0 of 2: exit 2, 'built without MPI', no samples file" \
		eval '[ $rc0 -eq 2 ] && grep -q "built without MPI" "$tmp/no0.err" && [ ! -e "$tmp/no0.csv" ] && [ ! -s "$tmp/no0.out" ]'
	check "without MPI, rank 1 of 2: exit 2 and quiet (rank 0 says it once)" \
		eval '[ $rc1 -eq 2 ] && [ ! -s "$tmp/no1.err" ] && [ ! -e "$tmp/no1.csv" ]'
	PMI_SIZE=4 PMI_RANK=0 "$bin" run $demo -n 3 >/dev/null 2>"$tmp/no2.err"
	rc=$?
	check "without MPI, MPICH's PMI_SIZE=4: exit 2, 'built without MPI'" \
		eval '[ $rc -eq 2 ] && grep -q "built without MPI" "$tmp/no2.err"'
	OMPI_COMM_WORLD_SIZE=1 OMPI_COMM_WORLD_RANK=0 "$bin" run $demo -n 3 --json \
		>"$tmp/no3.json" 2>"$tmp/no3.err"
	rc=$?
	check "without MPI, mpirun -n 1: runs alone (exit 0, 3 samples, no 'ranks')" \
		python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(not (int(sys.argv[2])==0 and d["samples"]==3 and "ranks" not in d))' "$tmp/no3.json" $rc
	echo "1..$n"
	[ $failed -eq 0 ]
	exit
fi

# mpirun as root needs its consent; more ranks than cores is the point
# here; the shared-memory transport's single-copy mode needs ptrace
# rights that containers often lack (and these messages are small)
if [ "$(id -u)" = 0 ]; then
	export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
fi
export OMPI_MCA_btl_vader_single_copy_mechanism=none
# "${mpi[@]}" -n P "$bin" ARGS: not a function, so that $! of a
# background job is mpirun itself (env execs it).  Under AddressSanitizer
# (scripts/ci-sanitize.sh) the ranks check memory errors but not leaks
# (tests/tap.sh, asan_no_leaks); the single-process runs here and in the
# other tests still check leaks.
mpi=(env "ASAN_OPTIONS=$(asan_no_leaks)"
	"$mpirun" --oversubscribe --bind-to none)
# same_json ONE MPI P: the JSON of mpirun -n P is the same text, byte
# for byte, as one process's apart from the lines of the timing keys
# (elapsed_seconds, samples_per_second), and adds one line "ranks": P
# (one process has none); both runs give the same --threads and
# --samples (the JSON names them)
same='import json,re,sys
timing = re.compile(r"\s*\"(elapsed_seconds|samples_per_second)\": ")
ranks = re.compile(r"\s*\"ranks\": ")
a = [l for l in open(sys.argv[1]) if not timing.match(l)]
b = [l for l in open(sys.argv[2]) if not timing.match(l)]
rb = [l for l in b if ranks.match(l)]
b = [l for l in b if not ranks.match(l)]
ok = (not any(ranks.match(l) for l in a) and len(rb) == 1 and
      json.loads("{" + rb[0].strip().rstrip(",") + "}")["ranks"] == int(sys.argv[3]))
d = json.load(open(sys.argv[2]))
sys.exit(not (ok and a == b and "samples" in d and len(a) > 20))'
same_json() {
	python3 -c "$same" "$@" 2>/dev/null
}

# ---- the same samples as one process ---------------------------------------
# compare NAME WALL SEED N THREADS [RANKS]: one process against RANKS (2)
# ranks, THREADS threads each, the same samples file name
compare() {
	local name=$1 wall=$2 seed=$3 nn=$4 th=$5 np=${6:-2}
	local csv=$tmp/$name.csv
	"$bin" run "$wall" -n "$nn" --seed "$seed" --threads "$th" --json \
		--samples "$csv" >"$tmp/$name.1.json" 2>"$tmp/$name.1.err"
	local rc1=$?
	mv "$csv" "$tmp/$name.1.csv"
	"${mpi[@]}" -n "$np" "$bin" run "$wall" -n "$nn" --seed "$seed" --threads "$th" --json \
		--samples "$csv" >"$tmp/$name.2.json" 2>"$tmp/$name.2.err"
	local rc2=$?
	mv "$csv" "$tmp/$name.2.csv"
	local what="$wall -n $nn --seed $seed, $np ranks x $th thread(s)"
	if [ $rc1 -eq 0 ] && [ $rc2 -eq 0 ] && [ "$(rows "$tmp/$name.2.csv")" = "$nn" ] &&
		cmp -s "$tmp/$name.1.csv" "$tmp/$name.2.csv"; then
		ok "$what: exit 0, $nn rows, the samples file byte-identical to one process's"
	else
		not_ok "$what: the samples file byte-identical" "exit $rc1 / $rc2" \
			"$(head -c 300 "$tmp/$name.2.err")" \
			"$(diff "$tmp/$name.1.csv" "$tmp/$name.2.csv" 2>&1 | head -4 | cut -c1-160)"
	fi
	if same_json "$tmp/$name.1.json" "$tmp/$name.2.json" "$np"; then
		ok "$what: the JSON the same apart from elapsed_seconds, samples_per_second and \"ranks\": $np"
	else
		not_ok "$what: the JSON the same" \
			"$(diff "$tmp/$name.1.json" "$tmp/$name.2.json" | head -8)"
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

# threads per rank by default: the node's CPUs shared by its ranks, at
# most the CPUs a rank may run on (not bound here: --bind-to none; but a
# container may allow fewer than the machine has)
"${mpi[@]}" -n 2 "$bin" run $demo -n 4 --seed 3 --json >"$tmp/th.json" 2>"$tmp/th.err"
rc=$?
cpus=$(getconf _NPROCESSORS_ONLN)
want=$((cpus / 2 < $(nproc) ? cpus / 2 : $(nproc)))
want=$((want > 0 ? want : 1))
check "no --threads, 2 ranks on a node of $cpus CPUs ($(nproc) allowed): $want thread(s) each" \
	python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(not (int(sys.argv[2])==0 and d["threads"]==int(sys.argv[3])))' "$tmp/th.json" $rc $want

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
"$bin" run $ft -n 3000 --seed 5 --until-ci 0.03 --threads 2 --json \
	--samples "$tmp/u.csv" >"$tmp/u1.json" 2>/dev/null
mv "$tmp/u.csv" "$tmp/u1.csv"
"${mpi[@]}" -n 2 "$bin" run $ft -n 3000 --seed 5 --until-ci 0.03 --threads 2 --json \
	--samples "$tmp/u.csv" >"$tmp/u2.json" 2>"$tmp/u2.err"
rc=$?
mv "$tmp/u.csv" "$tmp/u2.csv"
if [ $rc -eq 0 ] && cmp -s "$tmp/u1.csv" "$tmp/u2.csv" &&
	same_json "$tmp/u1.json" "$tmp/u2.json" 2 &&
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

# random friction (docs/method.md): the draw crosses the wire whole
"$bin" run $ft -n 30 --seed 4 --cov 0.2 --threads 2 --samples "$tmp/mu1.csv" \
	>/dev/null 2>&1
"${mpi[@]}" -n 2 "$bin" run $ft -n 30 --seed 4 --cov 0.2 --threads 1 \
	--samples "$tmp/mu2.csv" >/dev/null 2>"$tmp/mu2.err"
rc=$?
"${mpi[@]}" -n 2 "$bin" run $ft --cov 0.2 --replay "$tmp/mu1.csv" --threads 1 \
	--samples "$tmp/mu3.csv" >/dev/null 2>>"$tmp/mu2.err"
rc3=$?
check "random friction, cov 0.2: 2 ranks write one process's file (mu_k columns), and replay it" \
	eval '[ $rc -eq 0 ] && [ $rc3 -eq 0 ] && head -1 "$tmp/mu1.csv" | grep -q ",mu_1," && cmp -s "$tmp/mu1.csv" "$tmp/mu2.csv" && cmp -s "$tmp/mu1.csv" "$tmp/mu3.csv"'

# ---- set-up errors -----------------------------------------------------------
"${mpi[@]}" -n 2 "$bin" run $demo -n 0 >"$tmp/bad.out" 2>"$tmp/bad.err"
rc=$?
cnt=$(grep -c "is not a sample count" "$tmp/bad.err")
check "a usage error under mpirun: exit 2, the message once (rank 0's)" \
	eval '[ $rc -eq 2 ] && [ "$cnt" = 1 ] && [ ! -s "$tmp/bad.out" ]'
# an error in the wall file: every rank finds it, rank 0 alone says it
bw=tests/bad/block-unknown-key.yaml
"${mpi[@]}" -n 3 "$bin" run $bw -n 5 >"$tmp/bw.out" 2>"$tmp/bw.err"
rc=$?
cnt=$(grep -c "^$bw:4:42: unknown key 'fixed'" "$tmp/bw.err")
check "an error in the wall file on 3 ranks: exit 2, '$bw:4:42: ...' once" \
	eval '[ $rc -eq 2 ] && [ "$cnt" = 1 ] && [ ! -s "$tmp/bw.out" ]'
# one rank's own set-up fails (its copy of the wall is missing): that
# rank says why, rank 0 says which rank
"${mpi[@]}" -n 1 "$bin" run $demo -n 5 --threads 1 --samples "$tmp/own.csv" : \
	-n 1 "$bin" run "$tmp/missing.yaml" -n 5 --threads 1 --samples "$tmp/own.csv" \
	>"$tmp/own.out" 2>"$tmp/own.err"
rc=$?
check "rank 1 alone cannot read its wall: exit 2, its own message and 'rank 1 could not set up the run'" \
	eval '[ $rc -eq 2 ] && [ "$(grep -c "missing.yaml: cannot read" "$tmp/own.err")" = 1 ] &&
	grep -q "rank 1 could not set up the run" "$tmp/own.err"'
# --help on one rank only: the others' run has no partner (this crashed:
# the set-up fingerprint of a rank that had none)
"${mpi[@]}" -n 1 "$bin" run $demo -n 5 --threads 1 : -n 1 "$bin" run --help \
	>"$tmp/hm.out" 2>"$tmp/hm.err"
rc=$?
check "--help on rank 1 only: exit 2, 'every rank must be given the same options', no crash" \
	eval '[ $rc -eq 2 ] && grep -q "every rank must be given the same options" "$tmp/hm.err" &&
	! grep -qi "signal\|segmentation" "$tmp/hm.err"'
# two ranks that set up different runs (MPMD: -n 10 and -n 11)
"${mpi[@]}" -n 1 "$bin" run $demo -n 10 --threads 1 \
	--samples "$tmp/dif.csv" : -n 1 "$bin" run $demo -n 11 --threads 1 \
	--samples "$tmp/dif.csv" >"$tmp/dif.out" 2>"$tmp/dif.err"
rc=$?
check "ranks that set up different runs (-n 10 and -n 11): exit 2, 'rank 1 set up another run'" \
	eval '[ $rc -eq 2 ] && grep -q "rank 1 set up another run than rank 0" "$tmp/dif.err" &&
	[ "$(rows "$tmp/dif.csv")" = 0 ]'

# ---- faults ------------------------------------------------------------------
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
	kill -TERM "$1" 2>/dev/null
	within 5 gone "$1" || kill -9 "$1" 2>/dev/null
	wait "$1" 2>/dev/null
}
# wait_gone PID SECONDS: wait for mpirun; its exit status, or 124 if it
# is still running after SECONDS (then it is stopped)
wait_gone() {
	if ! within "$2" gone "$1"; then
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

# start NAME SEED [ROWS [ENV=VALUE...]]: a 5000-sample run of the demo
# wall on 2 ranks in the background ($mpipid; $tmp/NAME.csv, .json,
# .err), once ROWS (20) rows are in
start() {
	local name=$1 seed=$2 k=${3:-20}
	shift 2
	shift
	env "$@" "${mpi[@]}" -n 2 -x SLIPWALL_MPI_TIMEOUT -x SLIPWALL_MPI_FAULT \
		"$bin" run $demo -n 5000 --seed "$seed" --threads 1 \
		--samples "$tmp/$name.csv" --json >"$tmp/$name.json" 2>"$tmp/$name.err" &
	mpipid=$!
	wait_rows "$tmp/$name.csv" "$k"
}
# json_says FILE STOPPED K: rank 0's JSON summary says STOPPED after K
# samples
json_says() {
	python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); sys.exit(not (d["stopped"]==sys.argv[2] and d["samples"]==int(sys.argv[3])))' "$@" 2>/dev/null
}
export SLIPWALL_MPI_TIMEOUT=60 SLIPWALL_MPI_FAULT=

# a rank killed by SIGKILL: mpirun ends the job (SIGTERM to the others)
for r in 1 0; do
	start k$r 21
	pid=$(rank_pid $mpipid $r)
	t0=$(date +%s)
	[ -n "$pid" ] && kill -9 "$pid"
	wait_gone $mpipid 60
	rc=$?
	mpipid=
	dt=$(($(date +%s) - t0))
	check "SIGKILL of rank $r (pid ${pid:-none}): mpirun returns in $dt s (at most 30), exit $rc (not 0)" \
		eval '[ -n "$pid" ] && [ $rc -ne 0 ] && [ $rc -ne 124 ] && [ $dt -le 30 ]'
	check "SIGKILL of rank $r: $(rows "$tmp/k$r.csv") rows, every line complete, samples 0..k-1, one process's first rows" \
		eval 'complete "$tmp/k$r.csv" && prefix "$tmp/k$r.csv" 21'
done
check "SIGKILL of rank 1: mpirun says 'process rank 1 ... exited on signal 9'" \
	grep -q "process rank 1 .*exited on signal 9" "$tmp/k1.err"
# rank_summary NAME WHAT: when rank 0 got to its last message (printed
# after the summary) within mpirun's second, the summary counts exactly
# the rows of the file
# (check's eval sees the caller's locals, but its own $1 and $name)
rank_summary() {
	local rs_name=$1 rs_k
	rs_k=$(rows "$tmp/$1.csv")
	if grep -q "interrupted" "$tmp/$1.err"; then
		check "$2: rank 0's summary says interrupted (Terminated) after the $rs_k samples of the file" \
			eval 'json_says "$tmp/$rs_name.json" interrupted $rs_k &&
			grep -q "interrupted (Terminated) after $rs_k of 5000 samples" "$tmp/$rs_name.err"'
	else
		n=$((n + 1))
		echo "ok $n - $2: rank 0's summary # SKIP rank 0 was killed before it (mpirun's second was not enough on this machine)"
	fi
}
rank_summary k1 "SIGKILL of rank 1"

# SIGINT or SIGTERM to mpirun: it stops every rank (SIGTERM, SIGKILL 1 s
# later)
for sig in INT TERM; do
	start m$sig 22
	t0=$(date +%s)
	kill -$sig $mpipid
	wait_gone $mpipid 60
	rc=$?
	mpipid=
	dt=$(($(date +%s) - t0))
	k=$(rows "$tmp/m$sig.csv")
	check "SIG$sig to mpirun: it returns in $dt s (at most 30), exit $rc (not 0)" \
		eval '[ $rc -ne 0 ] && [ $rc -ne 124 ] && [ $dt -le 30 ]'
	check "SIG$sig to mpirun: $k rows, every line complete, samples 0..k-1, one process's first rows" \
		eval 'complete "$tmp/m$sig.csv" && prefix "$tmp/m$sig.csv" 22'
	rank_summary m$sig "SIG$sig to mpirun"
done

# signal_rank NAME SEED RANK SIGNAL WHY: a run, and SIGNAL to rank RANK
# alone: exit 1, "interrupted (WHY) after k of 5000 samples", the JSON of
# the same k samples, k complete rows that are one process's first
signal_rank() {
	local sr_name=$1 sr_seed=$2 sr_rank=$3 sr_sig=$4 sr_why=$5
	start "$sr_name" "$sr_seed"
	pid=$(rank_pid $mpipid "$sr_rank")
	[ -n "$pid" ] && kill -"$sr_sig" "$pid"
	wait_gone $mpipid 60
	rc=$?
	mpipid=
	k=$(rows "$tmp/$sr_name.csv")
	check "SIG$sr_sig to rank $sr_rank (pid ${pid:-none}): exit $rc (1), 'interrupted ($sr_why) after $k of 5000' and the JSON of the same $k samples" \
		eval '[ -n "$pid" ] && [ $rc -eq 1 ] && json_says "$tmp/$sr_name.json" interrupted $k &&
		grep -qF "interrupted ($sr_why) after $k of 5000 samples" "$tmp/$sr_name.err"'
	check "SIG$sr_sig to rank $sr_rank: $k complete rows, one process's first rows" \
		eval 'complete "$tmp/$sr_name.csv" && prefix "$tmp/$sr_name.csv" $sr_seed'
}
# SIGINT to rank 0 alone: it stops the others and ends cleanly
signal_rank r0 24 0 INT Interrupt
# SIGTERM to rank 1 alone: rank 0 ends the stream at rank 1's first
# missing sample and says so
signal_rank r1 25 1 TERM "rank 1: Terminated"

# a rank that stops answering: given up after the timeout
# ms: the monotonic-enough clock in milliseconds
ms() {
	echo $(($(date +%s%N) / 1000000))
}
# silent NAME SEED WHAT MIN MESSAGE: after start, WHAT was done at $t0
# (ms); mpirun must return MIN (ms) to 30 s later, MESSAGE on stderr
silent() {
	local sl_name=$1 sl_seed=$2 what=$3 sl_min=$4 msg=$5 sl_dt
	wait_gone $mpipid 60
	rc=$?
	mpipid=
	sl_dt=$(($(ms) - t0))
	k=$(rows "$tmp/$sl_name.csv")
	check "$what, SLIPWALL_MPI_TIMEOUT=3: mpirun returns in $sl_dt ms ($sl_min to 30000), exit $rc (not 0)" \
		eval '[ $rc -ne 0 ] && [ $rc -ne 124 ] && [ $sl_dt -ge $sl_min ] && [ $sl_dt -le 30000 ]'
	check "$what: '$msg' on stderr" \
		grep -q "$msg" "$tmp/$sl_name.err"
	check "$what: $k complete rows, one process's first rows" \
		eval 'complete "$tmp/$sl_name.csv" && prefix "$tmp/$sl_name.csv" $sl_seed'
}
# the timeout runs from the last message heard before the stop: from
# rank 1 a sample every few tens of ms, from rank 0 a credit or a beat
# about every second (MIN leaves room for a loaded machine)
start s1 23 60 SLIPWALL_MPI_TIMEOUT=3
pid=$(rank_pid $mpipid 1)
t0=$(ms)
[ -n "$pid" ] && kill -STOP "$pid"
silent s1 23 "rank 1 stopped (SIGSTOP, pid ${pid:-none})" 2000 \
	"rank 1 sent nothing for 3 s.*stopped after [0-9]* of 5000 samples"
check "rank 1 stopped: JSON stopped rank_lost, as many samples as rows" \
	json_says "$tmp/s1.json" rank_lost "$(rows "$tmp/s1.csv")"

start s0 26 60 SLIPWALL_MPI_TIMEOUT=3
pid=$(rank_pid $mpipid 0)
t0=$(ms)
[ -n "$pid" ] && kill -STOP "$pid"
silent s0 26 "rank 0 stopped (SIGSTOP, pid ${pid:-none})" 1000 \
	"rank 1: rank 0 \(sent nothing\|took no message\) for 3 s: it died or hangs"

# a rank that stops half way through sending a sample: rank 1 stops
# itself after starting to send its 10th.  The small transport limits
# make a demo wall's sample (2.4 KB) travel in pieces, as a large wall's
# does at the default limits (above 32 KB here, 64 KB over TCP): rank 0
# used to wait in MPI_Recv for the rest for ever.  The clock starts
# before that sample is sent.
start h 27 0 SLIPWALL_MPI_TIMEOUT=3 SLIPWALL_MPI_FAULT=stop:10 OMPI_MCA_btl=self,vader \
	OMPI_MCA_btl_vader_eager_limit=1024 OMPI_MCA_btl_vader_rndv_eager_limit=1024 \
	OMPI_MCA_btl_vader_max_send_size=1024
t0=$(ms)
silent h 27 "rank 1 stopped half way through sending a sample" 2900 \
	"rank 1 sent part of a sample and then nothing for 3 s.*stopped after [0-9]* of 5000 samples"
check "half a sample: JSON stopped rank_lost, as many samples as rows" \
	json_says "$tmp/h.json" rank_lost "$(rows "$tmp/h.csv")"
set +m

tap_end
