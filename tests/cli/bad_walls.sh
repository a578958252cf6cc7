#!/bin/bash
# cli/bad_walls.sh - every malformed wall in tests/bad/ is refused cleanly.
#
# Usage (from the source root): bash tests/cli/bad_walls.sh /path/to/slipwall
# Each tests/bad/*.yaml starts with "# expect: LINE:COL: substring".  For
# each file, `slipwall check FILE` must exit with status 2, print
# "FILE:LINE:COL:" and the substring on stderr, and neither crash nor trip
# a sanitizer.  TAP output.

bin=${1:?usage: cli/bad_walls.sh SLIPWALL}
cd "$(dirname "$0")/../.." || exit 1

. tests/tap.sh

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

files=(tests/bad/*.yaml)
echo "1..$((${#files[@]} + 2))"

for f in "${files[@]}"; do
	expect=$(head -n 1 "$f")
	expect=${expect#'# expect: '}
	loc=${expect%%: *}
	sub=${expect#*: }
	timeout 60 "$bin" check "$f" >"$tmp/out" 2>"$tmp/err" </dev/null
	rc=$?
	err=$(head -c 2000 "$tmp/err")
	if [ "$rc" -ne 2 ]; then
		not_ok "$f: exit status 2" "got $rc" "stderr: $err"
	elif ! grep -qF -- "$f:$loc:" "$tmp/err"; then
		not_ok "$f: reported at $loc" "stderr: $err"
	elif ! grep -qF -- "$sub" "$tmp/err"; then
		not_ok "$f: message contains '$sub'" "stderr: $err"
	elif grep -qE 'Sanitizer|core dumped|runtime error' "$tmp/err"; then
		not_ok "$f: no sanitizer report" "stderr: $err"
	else
		ok "$f: $loc: $sub"
	fi
done

# a file that does not exist
"$bin" check tests/bad/no-such-file.yaml >"$tmp/out" 2>"$tmp/err" </dev/null
rc=$?
if [ "$rc" -eq 2 ] && grep -qF 'tests/bad/no-such-file.yaml: cannot read' "$tmp/err"; then
	ok "missing file: exit 2, 'cannot read'"
else
	not_ok "missing file: exit 2, 'cannot read'" "got $rc" "stderr: $(head -c 500 "$tmp/err")"
fi

# a directory instead of a file
"$bin" check tests/bad >"$tmp/out" 2>"$tmp/err" </dev/null
rc=$?
if [ "$rc" -eq 2 ] && grep -qF 'tests/bad: cannot read' "$tmp/err"; then
	ok "directory: exit 2, 'cannot read'"
else
	not_ok "directory: exit 2, 'cannot read'" "got $rc" "stderr: $(head -c 500 "$tmp/err")"
fi

[ "$failed" -eq 0 ]
