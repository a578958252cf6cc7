# meson-counts.sh - sourced by the scripts that run `meson test`
# (test.sh, ci-nompi.sh, ci-sanitize.sh).
# meson_counts LOG RC: from meson test's output LOG and its exit status
# RC, set mpassed (Ok) and mfailed (Fail + Timeout; at least 1 when RC
# is not 0, so a run that failed without a count is not a pass).  In CI
# (CI=true) and under scripts/test.sh (SLIPWALL_TEST_TOOLS=required)
# every test must run: a test that meson reports skipped (a TAP plan
# "1..0 # SKIP", or exit status 77) is a failure too, and is named.
# (tests/tap.sh's skip_all and tap.h's tap_skip already fail there;
# this catches a skip that goes around them.)
meson_counts() {
	mpassed=$(sed -n 's/^Ok: *\([0-9]*\).*/\1/p' "$1" | tail -n 1)
	mfailed=$(sed -n 's/^Fail: *\([0-9]*\).*/\1/p' "$1" | tail -n 1)
	_t=$(sed -n 's/^Timeout: *\([0-9]*\).*/\1/p' "$1" | tail -n 1)
	_s=$(sed -n 's/^Skipped: *\([0-9]*\).*/\1/p' "$1" | tail -n 1)
	mpassed=${mpassed:-0}
	mfailed=$(( ${mfailed:-0} + ${_t:-0} ))
	if [ "${_s:-0}" != 0 ] && { [ "${CI:-}" = true ] ||
		[ "${SLIPWALL_TEST_TOOLS:-}" = required ]; }; then
		grep -E '^ *[0-9]+/[0-9]+ .* SKIP ' "$1" |
			sed 's/^/--- skipped, a failure here (CI=true or SLIPWALL_TEST_TOOLS=required): /'
		mfailed=$(( mfailed + _s ))
	fi
	if [ "$2" != 0 ] && [ "$mfailed" = 0 ]; then mfailed=1; fi
}

# meson_failures DIR: what failed, from DIR's meson test logs (the TAP
# tests' stdout is not in meson's --print-errorlogs output): for every
# test whose result is not a pass, its name and result, its "not ok"
# lines with their comments, and the last lines of its stderr.
meson_failures() {
	for _log in "$1"/meson-logs/testlog*.txt; do
		[ -f "$_log" ] || continue
		awk '
		function flush() {
			if (name != "" && bad) {
				printf "--- failed: %s (%s)\n", name, result
				printf "%s", notok
				if (nerr > 0) {
					print "    stderr, last lines:"
					for (i = (nerr > 10 ? nerr - 9 : 1); i <= nerr; i++)
						print "    " err[i]
				}
			}
			name = ""; bad = 0; notok = ""; nerr = 0; sect = ""; keep = 0
		}
		/^=+ [0-9]+\/[0-9]+ =+$/ || /^=+$/ { flush(); next }
		/^test: / { name = $2; next }
		/^result: / {
			result = substr($0, index($0, $2))
			bad = (result != "exit status 0" && result != "passed")
			next
		}
		/^-+ stdout -+$/ { sect = "out"; next }
		/^-+ stderr -+$/ { sect = "err"; next }
		sect == "out" && /^not ok/ { notok = notok "    " $0 "\n"; keep = 30; next }
		sect == "out" && /^#/ && keep > 0 { notok = notok "    " $0 "\n"; keep--; next }
		sect == "out" { keep = 0; next }
		sect == "err" { err[++nerr] = $0; next }
		END { flush() }
		' "$_log"
	done
}
