# differ.awk - compare two samples files by sample number (docs/method.md,
# "The SLP's answer"): the same status, and lambda_min within 1e-9
# relative (or of 1, below 1).  Usage: awk -F, -f tests/differ.awk A.csv B.csv
# Each differing sample goes to standard error; standard output gets
# their number, or "rows N" when B's rows are not A's.
# Used by tests/cli/invariance.sh and bench/invariance.sh.
NR == FNR { if (FNR > 1) { st[$1] = $2; lm[$1] = $4 } next }
FNR > 1 {
	rows++
	if (!($1 in st)) { bad++; next }
	if (st[$1] != $2) {
		bad++
		print "  sample " $1 ": " st[$1] " " lm[$1] " vs " $2 " " $4 > "/dev/stderr"
		next
	}
	if ($2 != "accepted") next
	d = lm[$1] - $4; if (d < 0) d = -d
	s = lm[$1] < 0 ? -lm[$1] : lm[$1]; if (s < 1) s = 1
	if (d > 1e-9 * s) { bad++; print "  sample " $1 ": " lm[$1] " vs " $4 > "/dev/stderr" }
}
END { print (rows == length(st) ? bad + 0 : "rows " rows) }
