#!/bin/bash
# check_whole.sh - every `check` of the test scripts tests its whole
# condition.
#
# tests/tap.sh's `check TEXT COMMAND...` runs COMMAND as its arguments.
# A line such as
#
#     check "the summary and the JSON agree" grep -q X out && [ "$j" = Y ]
#
# runs only `grep -q X out` inside check: the shell applies `&&` to
# check's own status, so a wrong "$j" fails nothing, and the test cannot
# fail for the half it names.  The same holds for `||`, a pipe (check's
# "ok" line would be piped) and `;`.  Four checks were written so, found
# on 3 December 2026 (tests/cli/body.sh, tests/cli/run.sh); a condition
# of several commands is computed first and checked as `test $? = 0`,
# or given to `eval` in one quoted word.
#
# The scan: each check statement of tests/**/*.sh (continuation lines
# joined) must have no `&&`, `||`, `|` or `;` outside quotes and before
# a comment.  Then the scan is proven able to fail: on planted lines of
# each kind it must report every one, and on the allowed forms none.
#
# Usage (from the source root): bash tests/check_whole.sh
# TAP output.
cd "$(dirname "$0")/.." || exit 1
. tests/tap.sh

# scan FILE...: "FILE:LINE: OPERATORS" for each check with an operator
# outside its quotes
scan() {
	python3 - "$@" <<'PY'
import re, sys

def operators(s):
    """The shell's list and pipe operators of s outside quotes, up to a
    comment."""
    ops, q, i = [], None, 0
    while i < len(s):
        c = s[i]
        if q:
            if c == '\\' and q == '"':
                i += 2
                continue
            if c == q:
                q = None
        elif c in '\'"':
            q = c
        elif c == '\\':
            i += 2
            continue
        elif s.startswith('&&', i) or s.startswith('||', i):
            ops.append(s[i:i + 2])
            i += 2
            continue
        elif c in '|;':
            ops.append(c)
        elif c == '#' and (i == 0 or s[i - 1] in ' \t'):
            break
        i += 1
    return ops

for f in sys.argv[1:]:
    lines = open(f).read().split('\n')
    i = 0
    while i < len(lines):
        first, stmt = i, lines[i]
        while stmt.endswith('\\') and i + 1 < len(lines):
            i += 1
            stmt = stmt[:-1] + ' ' + lines[i]
        s = stmt.strip()
        if re.match(r'check\s', s):
            ops = operators(s)
            if ops:
                print('%s:%d: %s' % (f, first + 1, ' '.join(ops)))
        i += 1
PY
}

mapfile -t scripts < <(find tests -name '*.sh' ! -path tests/check_whole.sh | sort)
found=$(scan "${scripts[@]}")
if [ ${#scripts[@]} -gt 30 ] && [ -z "$found" ]; then
	ok "no check of the ${#scripts[@]} test scripts has an operator outside its command"
else
	not_ok "every check tests its whole condition (${#scripts[@]} scripts)" \
		"$found"
fi

# the scan can fail: each planted form is found, on its own line
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/bad.sh" <<'SH'
check "and" grep -q x f && [ "$j" = y ]
check "continued" grep -q x f \
	&& [ "$j" = y ]
check "or" test -s f || true
check "pipe" cat f | grep -q x
check "list" true; false
SH
cat >"$tmp/good.sh" <<'SH'
check "computed first" test $? = 0
check "eval" eval '[ "$rc" = 1 ] && grep -q "a && b" f'
check "quoted operators" grep -q 'a | b; c && d || e' f
check "double-quoted" grep -q "x && y" f # a comment; with && in it
check "escaped" echo a\;b
SH
got=$(scan "$tmp/bad.sh" | sed 's/^[^:]*://')
want=$'1: &&\n2: &&\n4: ||\n5: |\n6: ;'
if [ "$got" = "$want" ]; then
	ok "the scan finds each planted &&, ||, | and ; (a continued line by its first line)"
else
	not_ok "the scan finds each planted operator" "got: $got" "want: $want"
fi
got=$(scan "$tmp/good.sh")
check "the scan passes quoted operators, eval's one word, a comment and 'test \$? = 0'" \
	test -z "$got"

tap_end
