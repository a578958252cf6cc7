# meson-counts.sh - sourced by the scripts that run `meson test`
# (test.sh, ci-nompi.sh, ci-sanitize.sh).
# meson_counts LOG RC: from meson test's output LOG and its exit status
# RC, set mpassed (Ok) and mfailed (Fail + Timeout; at least 1 when RC
# is not 0, so a run that failed without a count is not a pass).
meson_counts() {
	mpassed=$(sed -n 's/^Ok: *\([0-9]*\).*/\1/p' "$1" | tail -n 1)
	mfailed=$(sed -n 's/^Fail: *\([0-9]*\).*/\1/p' "$1" | tail -n 1)
	_t=$(sed -n 's/^Timeout: *\([0-9]*\).*/\1/p' "$1" | tail -n 1)
	mpassed=${mpassed:-0}
	mfailed=$(( ${mfailed:-0} + ${_t:-0} ))
	if [ "$2" != 0 ] && [ "$mfailed" = 0 ]; then mfailed=1; fi
}
