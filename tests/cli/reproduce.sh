#!/bin/bash
# cli/reproduce.sh - report.md's command to reproduce the report runs in
# a POSIX shell as it is printed, whatever its arguments hold
# (docs/report.md).
#
# Usage (from the source root): bash tests/cli/reproduce.sh /path/to/slipwall
# Proves: for --set values with a newline, a quote, a tab and a
# backtick fence, and paths with spaces, the code block after "To
# reproduce it:" in report.md, run by sh with `slipwall` a function
# that records its arguments, gives back every argument byte for byte;
# run with the real binary it exits 0 and writes a report.md with the
# same lines, but for the file's own paths.  TAP output.

bin=${1:?usage: cli/reproduce.sh SLIPWALL}
bin=$(realpath "$bin")
cd "$(dirname "$0")/../.." || exit 1
. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/a dir"
cp walls/single-block.yaml "$tmp/a dir/block.yaml"
cd "$tmp" || exit 1

# block FILE: the command of report.md, as a shell would read it
block() {
	python3 - "$1" <<'PY'
import re, sys
md = open(sys.argv[1]).read()
i = md.index("To reproduce it:\n\n") + len("To reproduce it:\n\n")
rest = md[i:]
m = re.match(r"(`{3,})sh\n", rest)
if m:
    body = rest[m.end():]
    end = re.search(r"^" + m.group(1) + r"`*\n", body, re.M)
    sys.stdout.write(body[:end.start()])
else:
    sys.stdout.write(rest.split("\n", 1)[0][4:] + "\n")
PY
}

k=0
for value in $'name=Line one\nline two' "name=it's a \"wall\"" $'name=tab\there' \
	     $'name=a ```\n````\nend' $'name=\n\nblank lines\n'; do
	k=$((k + 1))
	"$bin" report "a dir/block.yaml" -n 10 --set "$value" --out "r $k" >/dev/null 2>"err$k"
	if [ ! -f "r $k/report.md" ]; then
		not_ok "value $k: report writes report.md" "$(cat "err$k")"
		continue
	fi
	block "r $k/report.md" >"cmd$k.sh"
	printf 'slipwall() { printf "%%s\\0" "$@" >args%s; }\n' "$k" | cat - "cmd$k.sh" >"fake$k.sh"
	sh "fake$k.sh" 2>/dev/null
	check "value $k: sh reads back every argument byte for byte" python3 -c '
import sys
got = open(sys.argv[1], "rb").read().split(b"\0")[:-1]
want = [b"report", b"a dir/block.yaml", b"-n", b"10", b"--seed", b"1", b"--set",
        sys.argv[2].encode(), b"--out", ("r " + sys.argv[3]).encode()]
sys.exit(got != want)' "args$k" "$value" "$k"
	cp "r $k/report.md" "old$k.md"
	printf 'slipwall() { "%s" "$@"; }\n' "$bin" | cat - "cmd$k.sh" >"real$k.sh"
	sh "real$k.sh" >/dev/null 2>&1
	rc=$?
	check "value $k: the command runs (exit 0) to the same report.md" \
		eval "[ $rc = 0 ] && cmp -s 'old$k.md' 'r $k/report.md'"
done
tap_end
