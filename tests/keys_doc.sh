#!/bin/bash
# keys_doc.sh - docs/workbench.md names every key of the workbench and
# no other.
#
# The workbench's keys are one table (src/tui/tui_keys.c; the help
# screen and the status line are made from it).  Each row's .name is
# what the help shows, key names separated by ", " (the same action) or
# " / " (the opposite one): "f / F", "U, Ctrl-R", "arrows, hjkl".  The
# documentation's table (docs/workbench.md, "## Keys") names its keys
# in its first column, each in backticks.  The two sets must be equal:
# a key of the program that the documentation leaves out, or a key the
# documentation names that the program does not have, fails.  Then the
# check is proven able to fail: on a copy of the documentation with one
# key's row removed, and on one with a row of a key that does not
# exist, it must fail and name that key.
#
# Usage (from the source root): bash tests/keys_doc.sh
# TAP output.
cd "$(dirname "$0")/.." || exit 1
. tests/tap.sh

table=src/tui/tui_keys.c
doc=docs/workbench.md

# table_keys FILE: the key names of the table's rows, one a line
table_keys() {
	awk '{
		while (match($0, /\.name = "[^"]*"/)) {
			print substr($0, RSTART + 9, RLENGTH - 10)
			$0 = substr($0, RSTART + RLENGTH)
		}
	}' "$1" | sed 's/, /\n/g; s| / |\n|g' | sort -u
}

# doc_keys FILE: the keys the first column of the table in its "## Keys"
# section names (in backticks), one a line
doc_keys() {
	awk '/^## Keys$/ { on = 1; next } /^## / { on = 0 } on' "$1" |
		grep '^| ' | grep -v '^| key |' | awk -F'|' '{ print $2 }' |
		grep -o '`[^`]*`' | tr -d '`' | sort -u
}

# keys_check DOC: the differences, printed ("not in the documentation:
# K", "not a key of the workbench: K"); 0 when there are none
keys_check() {
	local prog docs
	prog=$(table_keys "$table")
	docs=$(doc_keys "$1")
	comm -23 <(printf '%s\n' "$prog") <(printf '%s\n' "$docs") |
		sed 's/^/not in the documentation: /'
	comm -13 <(printf '%s\n' "$prog") <(printf '%s\n' "$docs") |
		sed 's/^/not a key of the workbench: /'
	[ "$(printf '%s\n' "$prog")" = "$(printf '%s\n' "$docs")" ]
}

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# the extraction finds the table (an awk that finds nothing would make
# an empty documentation pass)
nk=$(table_keys "$table" | wc -l)
nd=$(doc_keys "$doc" | wc -l)
for k in q space Ctrl-R arrows hjkl Tab Delete mouse Enter Backspace; do
	table_keys "$table" | grep -qxF -- "$k" || missing_t="$missing_t $k"
done
if [ "$nk" -ge 40 ] && [ -z "$missing_t" ]; then
	ok "the key table names $nk keys"
else
	not_ok "the key table names $nk keys" "missing:$missing_t"
fi
check "the documentation's key table names $nd keys" [ "$nd" -ge 40 ]

if out=$(keys_check "$doc"); then
	ok "$doc names every key of $table and no other"
else
	not_ok "$doc names every key of $table and no other" "$out"
fi

# proof: a key's row removed (R, the report) ...
grep -v '^| `R` |' "$doc" >"$tmp/no-R.md"
if ! cmp -s "$doc" "$tmp/no-R.md" && ! out=$(keys_check "$tmp/no-R.md") &&
	grep -qxF 'not in the documentation: R' <<<"$out"; then
	ok "the check fails when the documentation leaves out R"
else
	not_ok "the check fails when the documentation leaves out R" "$out"
fi
# ... and a key that does not exist (Z)
sed 's/^| `o` |/| `Z` | nothing |\n&/' "$doc" >"$tmp/with-Z.md"
if ! cmp -s "$doc" "$tmp/with-Z.md" && ! out=$(keys_check "$tmp/with-Z.md") &&
	grep -qxF 'not a key of the workbench: Z' <<<"$out"; then
	ok "the check fails when the documentation names a key Z that is not"
else
	not_ok "the check fails when the documentation names a key Z that is not" "$out"
fi

tap_end
