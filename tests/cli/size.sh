#!/bin/bash
# cli/size.sh - size: a 10,000-block wall works in bounded memory; absurd
# inputs are refused with a message, quickly (docs/reliability.md).
#
# Usage (from the source root): bash tests/cli/size.sh /path/to/slipwall
# Proves: a generated wall of 10,050 blocks and the same wall written out
# as 10,050 explicit polygons (1 MB of YAML) load and are checked, the
# JSON listing every block and interface; a sample of it runs for a
# minute (SLIPWALL_SIZE_SECONDS) and one SIGINT stops it within 10 s
# although GLPK is inside an LP that needs more than 25 minutes
# (docs/reliability.md), leaving a valid samples file and valid JSON;
# each stays under 1 GB of memory (max RSS measured).  Refused with a message: a file over 16 MiB
# through a pipe (no size to look at first), a document of more than
# 2,000,000 nodes without aliases, a layout of more than 100,000 blocks.
# Needs python3 (it measures the memory: getrusage of the children).
# TAP.

bin=${1:?usage: cli/size.sh SLIPWALL}
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
limit_mb=1024

# measure OUT ERR COMMAND...: run it; sets rc, secs, rss_mb (max RSS)
measure() {
	local out=$1 err=$2
	shift 2
	read -r rc secs rss_mb < <(python3 - "$out" "$err" "$@" <<'EOF'
import resource, subprocess, sys, time
out, err, cmd = sys.argv[1], sys.argv[2], sys.argv[3:]
t0 = time.monotonic()
with open(out, "wb") as o, open(err, "wb") as e:
    r = subprocess.run(cmd, stdout=o, stderr=e, stdin=subprocess.DEVNULL)
t = time.monotonic() - t0
rss = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
print(r.returncode, "%.1f" % t, "%.0f" % rss)
EOF
)
}

# ---- a 10,000-block wall ---------------------------------------------------
# 100 courses of 0.20 x 0.10 m blocks, 20 m long, running bond: half
# courses hold 101 blocks (a half, 99 full, a half), full courses 100:
# 50 * 101 + 50 * 100 = 10,050 blocks
cp tests/wall-10050.yaml "$tmp/big.yaml"
measure "$tmp/big.json" "$tmp/big.err" "$bin" check "$tmp/big.yaml" --json
counts=$(python3 -c 'import json,sys; d=json.load(open(sys.argv[1]))
print(len(d["blocks"]), sum(1 for b in d["blocks"] if not b["fixed"]), len(d["interfaces"]))' "$tmp/big.json" 2>/dev/null)
read -r nb nfree nif <<<"$counts"
if [ "$rc" = 0 ] && [ "$nfree" = 10050 ] && [ "$nif" -gt 20000 ] && [ "$rss_mb" -lt $limit_mb ]; then
	ok "a 10,050-block layout: check --json lists $nfree free blocks and $nif interfaces (${secs} s, max RSS ${rss_mb} MB < $limit_mb MB)"
else
	not_ok "a 10,050-block layout is checked" "exit $rc, blocks '$counts', ${secs} s, ${rss_mb} MB" \
		"$(head -c 300 "$tmp/big.err")"
fi

# the same wall as explicit polygons: 1 MB of YAML through the reader
python3 - "$tmp/big.json" "$tmp/explicit.yaml" <<'EOF'
import json, sys
d = json.load(open(sys.argv[1]))
with open(sys.argv[2], "w") as f:
    f.write("name: 10,050 explicit blocks\n")
    f.write("material: {friction: 0.6, unit_weight: 19620, thickness: 0.10}\n")
    f.write("blocks:\n")
    for b in d["blocks"]:
        if b["fixed"]:
            continue
        v = ", ".join("[%r, %r]" % (x, y) for x, y in b["vertices"])
        f.write("  - {id: %s, vertices: [%s]}\n" % (b["id"], v))
    f.write("supports:\n  - ground: {y: 0}\n")
    f.write("loads:\n  - point: {at: [20.0, 4.95], direction: [1, 0]}\n")
EOF
measure "$tmp/ex.out" "$tmp/ex.err" "$bin" check "$tmp/explicit.yaml"
size=$(wc -c <"$tmp/explicit.yaml")
if [ "$rc" = 0 ] && grep -q '10050 free' "$tmp/ex.out" && [ "$rss_mb" -lt $limit_mb ]; then
	ok "the same wall as 10,050 explicit polygons ($((size / 1024)) KiB of YAML) loads and is checked (${secs} s, ${rss_mb} MB)"
else
	not_ok "10,050 explicit polygons are checked" "exit $rc, ${secs} s, ${rss_mb} MB" \
		"$(head -c 300 "$tmp/ex.err")" "$(head -n 3 "$tmp/ex.out")"
fi

# one sample: GLPK needs more than 25 minutes for the first LP of this
# size (docs/reliability.md), too long for CI.  Sample it for a minute,
# watching the memory (the high-water mark of /proc/PID/status), then
# stop it with one SIGINT: the solve running inside GLPK must notice
# (src/lib/lp_glpk.c, "Interruption") and the program end by itself within 10 s,
# exit 1 ("interrupted"), with valid JSON and a samples file of its
# header and complete rows only.
secs_run=${SLIPWALL_SIZE_SECONDS:-60}
set -m	# job control: a background job does not ignore SIGINT
"$bin" run "$tmp/big.yaml" -n 1 --threads 1 --json --samples "$tmp/big.csv" \
	>"$tmp/run.json" 2>"$tmp/run.err" &
pid=$!
hwm=0
for _ in $(seq "$secs_run"); do
	sleep 1
	kill -0 $pid 2>/dev/null || break
	h=$(sed -n 's/^VmHWM:[[:space:]]*\([0-9]*\) kB/\1/p' /proc/$pid/status 2>/dev/null)
	[ -n "$h" ] && [ "$h" -gt "$hwm" ] && hwm=$h
done
finished=1
stopped_in=
if kill -0 $pid 2>/dev/null; then
	finished=0
	kill -INT $pid
	t0=$(date +%s)
	if within 10 gone $pid; then
		stopped_in=$(( $(date +%s) - t0 ))
	else
		kill -KILL $pid 2>/dev/null
	fi
fi
wait $pid 2>/dev/null
rc=$?
set +m
hwm_mb=$((hwm / 1024))
rows=$(($(wc -l <"$tmp/big.csv") - 1))
hdr=$(awk -F, 'NR == 1 { print NF }' "$tmp/big.csv")
bad=$(awk -F, -v c="$hdr" 'NF != c { b++ } END { print b + 0 }' "$tmp/big.csv")
json_ok=$(python3 -c 'import json, sys; d = json.load(open(sys.argv[1])); print(1 if d["samples"] == d["accepted"] + sum(d["rejected"].values()) and d["stopped"] != "complete" else 0)' "$tmp/run.json" 2>/dev/null)
if [ "$hdr" = $((5 + 2 * nif)) ] && [ "$bad" = 0 ] && [ "$hwm_mb" -lt $limit_mb ] &&
   [ "$json_ok" = 1 ]; then
	if [ $finished = 1 ]; then
		ok "one sample of the 10,050-block wall: exit $rc, $rows complete row(s), max RSS ${hwm_mb} MB < $limit_mb MB"
	elif [ -n "$stopped_in" ] && [ "$rc" = 1 ] && grep -q 'interrupted' "$tmp/run.err"; then
		ok "a sample of the 10,050-block wall for ${secs_run} s: max RSS ${hwm_mb} MB < $limit_mb MB; one SIGINT stopped it inside GLPK in ${stopped_in} s (exit 1, valid JSON), the samples file a complete header of $hdr columns and $rows rows"
	else
		not_ok "one SIGINT stops the 10,050-block wall's sample within 10 s" \
			"exit $rc, stopped in '${stopped_in:-never}' s" "$(head -c 300 "$tmp/run.err")"
	fi
else
	not_ok "a sample of the 10,050-block wall in bounded memory" \
		"exit $rc, header $hdr columns (want $((5 + 2 * nif))), $bad bad lines, max RSS ${hwm_mb} MB, JSON ok '$json_ok'" \
		"$(head -c 300 "$tmp/run.err")"
fi

# over 16 MiB through a pipe: no size to look at first; read and refused
measure "$tmp/p.out" "$tmp/p.err" sh -c \
	"{ cat '$tmp/big.yaml'; head -c 17000000 /dev/zero | tr '\\0' '#'; } | '$bin' check /dev/stdin"
if [ "$rc" = 2 ] && grep -q '/dev/stdin: file is larger than 16777216 bytes' "$tmp/p.err" &&
   [ "$rss_mb" -lt 512 ]; then
	ok "17 MB through a pipe: 'file is larger than 16777216 bytes', exit 2 (${secs} s, ${rss_mb} MB)"
else
	not_ok "17 MB through a pipe is refused" "exit $rc, ${secs} s, ${rss_mb} MB" "$(head -c 300 "$tmp/p.err")"
fi

# 2,100,000 numbers, no alias: too many nodes, refused before the
# document is built
python3 -c 'import sys
sys.stdout.write("tests:\n  loads: [" + "1," * 2100000 + "1]\n")' >"$tmp/nodes.yaml"
measure "$tmp/nodes.out" "$tmp/nodes.err" "$bin" check "$tmp/nodes.yaml"
# (14 MB here; 372 MB under AddressSanitizer, whose quarantine keeps
# freed memory)
if [ "$rc" = 2 ] && grep -q 'nodes.yaml:2:.*more than 2000000 nodes' "$tmp/nodes.err" &&
   [ "$rss_mb" -lt 512 ]; then
	ok "2.1 million list items: 'more than 2000000 nodes' at LINE:COL, exit 2 (${secs} s, ${rss_mb} MB)"
else
	not_ok "2.1 million nodes are refused" "exit $rc, ${secs} s, ${rss_mb} MB" "$(head -c 300 "$tmp/nodes.err")"
fi

# 20,000 long thin slabs stacked (1.6 MB): contact detection must stay
# near-linear (square grid cells of the mean size put them all in one
# cell: 11.5 s before src/lib/geom.c's grid got separate cell width and
# height, 0.6 s after)
python3 -c 'import sys
w = sys.stdout.write
w("material: {friction: 0.6, unit_weight: 19620, thickness: 0.1}\nblocks:\n")
for i in range(20000):
    y0, y1 = i * 0.005, (i + 1) * 0.005
    w("  - {vertices: [[0, %r], [100, %r], [100, %r], [0, %r]]}\n" % (y0, y0, y1, y1))
w("supports: [{ground: {y: 0}}]\nloads: [{point: {at: [100, 0.0025], direction: [1, 0]}}]\n")' >"$tmp/slabs.yaml"
measure "$tmp/s.out" "$tmp/s.err" "$bin" check "$tmp/slabs.yaml"
if [ "$rc" = 0 ] && grep -q '20000 free' "$tmp/s.out" && [ "${secs%.*}" -lt 5 ]; then
	ok "20,000 stacked slabs 100 m long: checked in ${secs} s (< 5 s: no quadratic contact search)"
else
	not_ok "20,000 stacked slabs are checked in < 5 s" "exit $rc, ${secs} s, ${rss_mb} MB" "$(head -c 300 "$tmp/s.err")"
fi

# a layout of a million blocks from 150 bytes
cat >"$tmp/million.yaml" <<'EOF'
material: {friction: 0.6, unit_weight: 19620, thickness: 0.1}
layout: {block: [0.2, 0.1], courses: 1000, length: 200}
supports: [{ground: {y: 0}}]
loads: [{point: {at: [200, 0.05], direction: [1, 0]}}]
EOF
measure "$tmp/m.out" "$tmp/m.err" "$bin" check "$tmp/million.yaml"
if [ "$rc" = 2 ] && grep -q 'million.yaml:2:9: layout would make 1000500 blocks (at most 100000)' "$tmp/m.err" &&
   [ "$rss_mb" -lt 100 ]; then
	ok "a layout of a million blocks: refused at 2:9 (at most 100000), ${secs} s"
else
	not_ok "a layout of a million blocks is refused" "exit $rc, ${secs} s, ${rss_mb} MB" "$(head -c 300 "$tmp/m.err")"
fi

tap_end
