#!/bin/sh
# ci-valgrind.sh - valgrind memcheck on the batch commands
# (docs/reliability.md), with the plain build (build/, scripts/setup.sh).
#
#   sh scripts/ci-valgrind.sh          [SLIPWALL_BIN=path/to/slipwall]
#
# Each command runs under memcheck with --leak-check=full; any memory
# error or a definite leak fails it (--error-exitcode), and so does the
# command's own exit status if it is not the expected one.  TAP lines,
# then "tests: N passed, M failed".
set -e
cd "$(dirname "$0")/.."
# SLIPWALL_BIN: another build's binary (default: build/, set up here)
bin=${SLIPWALL_BIN:-}
if [ -z "$bin" ]; then
	sh scripts/setup.sh --tests >/dev/null
	bin=./build/slipwall
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

n=0
failed=0
# memcheck LOG [--track-origins=yes] ARGS...: the program under memcheck.
# Without --track-origins (a third faster; it changes no verdict, only
# the report): a failing command is run again with it.  A command that
# hangs is killed after 10 minutes (exit 124: a failure).
memcheck() {
	local log=$1 origins=
	shift
	case $1 in --track-origins=*) origins=$1; shift ;; esac
	timeout -k 10 600 valgrind -q --error-exitcode=99 --leak-check=full \
		--errors-for-leak-kinds=definite --show-leak-kinds=definite \
		$origins --log-file="$log" "$bin" "$@"
}
# vg EXPECTED-EXIT DESCRIPTION ARGS...
vg() {
	want=$1
	what=$2
	shift 2
	n=$((n + 1))
	set +e
	memcheck "$tmp/vg.$n" "$@" >"$tmp/out.$n" 2>"$tmp/err.$n" </dev/null
	rc=$?
	set -e
	if [ "$rc" = "$want" ] && [ ! -s "$tmp/vg.$n" ]; then
		echo "ok $n - valgrind: $what (exit $rc, no errors, no leaks)"
	else
		failed=$((failed + 1))
		echo "not ok $n - valgrind: $what (exit $rc, want $want)"
		# again with the origins of uninitialised values, for the report
		memcheck "$tmp/vg.$n" --track-origins=yes "$@" \
			>/dev/null 2>&1 </dev/null || true
		sed 's/^/#   /' "$tmp/vg.$n" | head -n 60
		sed 's/^/#   stderr: /' "$tmp/err.$n" | head -n 10
	fi
}

vg 0 "check demo" check walls/demo.yaml
vg 0 "check --json ferris-tinloi-1" check walls/ferris-tinloi-1.yaml --json
vg 2 "check a malformed wall" check tests/bad/geom-overlap.yaml
vg 2 "check an alias bomb" check tests/bad/alias-bomb.yaml
vg 0 "solve --method standard demo" solve walls/demo.yaml --method standard --json
vg 0 "solve --method gilbert demo" solve walls/demo.yaml --method gilbert --json
vg 0 "solve --method global two-block stack" solve walls/two-block-stack.yaml --method global --json
vg 0 "solve --method global single block" solve walls/single-block.yaml --method global
vg 0 "run -n 20 --threads 2 demo" run walls/demo.yaml -n 20 --threads 2 \
	--samples "$tmp/demo.csv" --json
vg 0 "run --positions (replay of 20 rows)" run walls/demo.yaml \
	--positions "$tmp/demo.csv" --samples "$tmp/replay.csv"
vg 0 "run -n 10 ferris-tinloi-1" run walls/ferris-tinloi-1.yaml -n 10
printf '0.5\n0.55\n0.6\n0.62\n' >"$tmp/tests.txt"
vg 0 "compare --json ferris-tinloi-1 against 4 loads" compare \
	walls/ferris-tinloi-1.yaml --tests "$tmp/tests.txt" -n 10 --json
vg 0 "compare --samples (the demo run's file)" compare walls/demo.yaml \
	--samples "$tmp/demo.csv" --tests "$tmp/tests.txt"
vg 0 "report of the demo run (figures with cairo)" report walls/demo.yaml \
	--samples "$tmp/demo.csv" --tests "$tmp/tests.txt" --out "$tmp/report"
vg 1 "run -n 5 --samples /dev/full" run walls/demo.yaml -n 5 --samples /dev/full
# GLPK errors inside the solves (src/lib/lp_glpk.c): the recovery frees everything
# (every 400th LP: a demo sample solves 60-80 LPs, so some samples fail
# and the others are accepted)
export SLIPWALL_LP_FAULT=error:400
vg 0 "run -n 10 --threads 2 with every 400th LP a GLPK error" \
	run walls/demo.yaml -n 10 --threads 2 --json
unset SLIPWALL_LP_FAULT
# issue 16: a cut last row, an output over an input, control characters,
# a report with its signal handler and staging directory
head -c $(($(wc -c <"$tmp/demo.csv") - 10)) "$tmp/demo.csv" >"$tmp/cut.csv"
vg 0 "run --positions of a file with a cut last row" run walls/demo.yaml \
	--positions "$tmp/cut.csv" --threads 1
cp walls/two-block-stack.yaml "$tmp/w.yaml"
vg 2 "run --samples over its own wall (refused)" run "$tmp/w.yaml" -n 2 \
	--samples "$tmp/./w.yaml"
sed 's/^name: .*/name: "a\\e[2Jb\\a\\nc"/' walls/two-block-stack.yaml >"$tmp/evil.yaml"
vg 0 "check of a wall named with control characters" check "$tmp/evil.yaml"
vg 0 "report of a wall named with control characters" report "$tmp/evil.yaml" \
	-n 10 --threads 1 --out "$tmp/evil-report"
echo "1..$n"
echo "tests: $((n - failed)) passed, $failed failed"
[ "$failed" = 0 ]
