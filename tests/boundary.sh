#!/bin/bash
# boundary.sh - the walls between the three rooms (docs/design.md) stand.
#
#   src/lib/  libslipwall: computes; the only room that includes the LP
#             solver (and only its backend, lp_glpk.c), GSL, libyaml,
#             cairo
#   src/tui/  the workbench: the only room that includes curses
#   src/cli/  main and the batch commands: the only room with MPI
#
# Each rule is a pattern of #include lines (or of dependencies in a
# room's meson.build, or of words such as getenv) and the places where
# it may appear; a match
# anywhere else is a crossing, printed as FILE:LINE: text.  The rules are
# then proven able to fail: for each one, a copy of the tree gets one
# crossing planted in it, and the rule must find it.
#
# Usage (from the source root): bash tests/boundary.sh
# TAP output.
cd "$(dirname "$0")/.." || exit 1
. tests/tap.sh

# The library's files that may still read the environment (the rest take
# their configuration as arguments, docs/design.md): none since the
# workbench resolves the runs directory itself (history.c took
# SLIPWALL_RUNS, XDG_DATA_HOME and HOME); a file put here is allowed.
getenv_allowed=()
getenv_ok=-
if [ ${#getenv_allowed[@]} -gt 0 ]; then
	getenv_ok=$(printf '|%s' "${getenv_allowed[@]}")
	getenv_ok="^(${getenv_ok:1})\$"
	getenv_ok=${getenv_ok//./\\.}
fi

# RULE: name | files it looks at (find -path patterns, relative to the
# tree) | the files of those where the pattern is allowed (an extended
# regex on the path, or "-" for none) | the pattern (extended regex on
# lines)
rules=(
	"curses outside src/tui/|src/*|^src/tui/|^[[:space:]]*#[[:space:]]*include[[:space:]]*<(n?cursesw?/|n?cursesw?\.h|panel\.h|term\.h)"
	"MPI outside src/cli/|src/* include/*|^src/cli/|^[[:space:]]*#[[:space:]]*include[[:space:]]*<mpi\.h>"
	"GLPK outside the LP layer's backend (src/lib/lp_glpk.c)|src/* include/*|^src/lib/lp_glpk\.c$|^[[:space:]]*#[[:space:]]*include[[:space:]]*<glpk\.h>"
	"the LP layer's header outside src/lib/|src/* include/*|^src/lib/|^[[:space:]]*#[[:space:]]*include[[:space:]]*\"(\.\./)*(lib/)?lp\.h\""
	"the library's private headers (statics.h, support.h, piece.h, global.h, sample_lp.h, sample_ws.h) outside src/lib/|src/* include/*|^src/lib/|^[[:space:]]*#[[:space:]]*include[[:space:]]*\"(\.\./)*(lib/)?(statics|support|piece|global|sample_lp|sample_ws)\.h\""
	"GSL, libyaml, cairo outside src/lib/|src/* include/*|^src/lib/|^[[:space:]]*#[[:space:]]*include[[:space:]]*<(gsl/|yaml\.h|cairo|fontconfig/)"
	"src/tui/ including src/cli/|src/tui/*|-|^[[:space:]]*#[[:space:]]*include[[:space:]]*\"(\.\./)*(cli/)?(cli|override|summary|cluster)\.h\""
	"the library including a front end|src/lib/* include/*|-|^[[:space:]]*#[[:space:]]*include[[:space:]]*\"(\.\./)*((cli|tui)/)?(cli|override|summary|cluster|tui|workbench)\.h\""
	"src/cli/ past the workbench's door (workbench.h)|src/cli/*|-|^[[:space:]]*#[[:space:]]*include[[:space:]]*\"(\.\./)*(tui/)?tui\.h\""
	"a room's meson.build naming another room's dependencies|src/lib/meson.build src/tui/meson.build src/cli/meson.build|-|@meson"
	"source files outside the three rooms|src/*|-|@loose"
	"thread-local state outside the LP backend (src/lib/lp_glpk.c)|src/* include/*|^src/lib/lp_glpk\.c$|(_Thread_local|__thread|thread_local)"
	"getenv in the library (allowed: ${getenv_allowed[*]:-none})|src/lib/* include/*|$getenv_ok|(^|[^[:alnum:]_])(secure_)?getenv[[:space:]]*\("
	"the LP layer in the pool (mc.c) or solve.c|src/lib/mc.c src/lib/solve.c|-|^[[:space:]]*#[[:space:]]*include[[:space:]]*\"(lp|lp_backend|sample_lp|sample_ws)\.h\""
	"the LP backend table (lp_backend.h) outside the LP layer (lp.c, lp_glpk.c)|src/* include/*|^src/lib/lp(_glpk)?\.c$|^[[:space:]]*#[[:space:]]*include[[:space:]]*\"(\.\./)*(lib/)?lp_backend\.h\""
	"the engine reading friction from the wall, not from the sample's draw (docs/method.md)|src/lib/sample*.c src/lib/sample*.h src/lib/statics.* src/lib/support.* src/lib/global.* src/lib/solve.c src/lib/piece.* src/lib/lp*.c src/lib/lp*.h src/lib/mc.c src/lib/record.c|-|(wall_iface_mu|mu_bed|mu_head|mu_cov)"
	"a sample workspace's inside (sample_ws.h) outside the sample's files (src/lib/sample*.c)|src/* include/*|^src/lib/sample(_[a-z]+)?\.c$|^[[:space:]]*#[[:space:]]*include[[:space:]]*\"(\.\./)*(lib/)?sample_ws\.h\""
)

# crossings TREE RULE: print the crossings of RULE in TREE (empty: none)
crossings() {
	local tree=$1 rule=$2
	local name scope allowed pat
	IFS='|' read -r name scope allowed pat <<<"$rule"
	(
		cd "$tree" || exit 1
		if [ "$pat" = "@loose" ]; then
			find src -maxdepth 1 -type f \( -name '*.c' -o -name '*.h' \)
			exit 0
		fi
		if [ "$pat" = "@meson" ]; then
			# the dependencies each room may name
			grep -HnE 'curses_dep|mpi_dep' src/lib/meson.build
			grep -HnE 'mpi_dep|glpk_dep|gsl_dep|yaml_dep|cairo_dep' src/tui/meson.build
			grep -HnE 'curses_dep|glpk_dep|gsl_dep|yaml_dep|cairo_dep' src/cli/meson.build
			exit 0
		fi
		local files=() p f
		set -f	# the scope's patterns are find's, not the shell's
		for p in $scope; do
			while IFS= read -r f; do files+=("$f"); done < <(
				find . -path "./$p" -type f \( -name '*.c' -o -name '*.h' \) |
					sed 's|^\./||' | sort)
		done
		for f in "${files[@]}"; do
			if [ "$allowed" != "-" ] && [[ $f =~ $allowed ]]; then
				continue
			fi
			grep -HnE "$pat" "$f"
		done
		exit 0
	)
}

# 1. the tree as it is: no crossing
for rule in "${rules[@]}"; do
	name=${rule%%|*}
	out=$(crossings . "$rule")
	if [ -z "$out" ]; then
		ok "no $name"
	else
		mapfile -t lines <<<"$out"
		not_ok "no $name" "${lines[@]}"
	fi
done

# 2. each rule finds a crossing planted on purpose
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
plant() {	# RULE-INDEX: the file and line that cross rule i
	case $1 in
	0) echo "src/lib/planted.c|#include <curses.h>" ;;
	1) echo "src/tui/planted.c|#include <mpi.h>" ;;
	2) echo "src/lib/sample_planted.c|#include <glpk.h>" ;;
	3) echo "src/cli/planted.c|#include \"lp.h\"" ;;
	4) echo "src/tui/planted.c|# include \"piece.h\"" ;;
	5) echo "src/cli/planted.c|#include <gsl/gsl_rng.h>" ;;
	6) echo "src/tui/planted.c|#include \"cli.h\"" ;;
	7) echo "include/slipwall/planted.h|#include \"tui.h\"" ;;
	8) echo "src/cli/planted.c|#include \"tui.h\"" ;;
	9) echo "src/tui/meson.build|  dependencies : [slipwall_dep, curses_dep, mpi_dep])" ;;
	10) echo "src/planted.c|int planted;" ;;
	11) echo "src/lib/mc.c|static _Thread_local int planted;" ;;
	12) echo "src/lib/sample.c|	const char *e = getenv(\"SLIPWALL_LP_START\");" ;;
	13) echo "src/lib/solve.c|#include \"lp.h\"" ;;
	14) echo "src/lib/sample.c|#include \"lp_backend.h\"" ;;
	15) echo "src/lib/statics.c|static double planted(const struct wall *w) { return w->mu_bed; }" ;;
	16) echo "src/lib/global.c|#include \"sample_ws.h\"" ;;
	esac
}
for i in "${!rules[@]}"; do
	rule=${rules[$i]}
	name=${rule%%|*}
	rm -rf "${tmp:?}/tree" && mkdir "$tmp/tree"
	cp -r src include "$tmp/tree/"
	IFS='|' read -r file line <<<"$(plant "$i")"
	printf '%s\n' "$line" >>"$tmp/tree/$file"
	out=$(crossings "$tmp/tree" "$rule")
	if grep -qF "${file}" <<<"$out"; then
		ok "planted crossing found: $name ($file: $line)"
	else
		not_ok "planted crossing found: $name ($file: $line)" "found: $out"
	fi
done
tap_end
