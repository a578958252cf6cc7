/*
 * compare_runs.h - `slipwall compare WALL --samples A.csv --against
 * B.csv`: two runs side by side (docs/run.md, "Two runs: --against").
 */
#ifndef SLIPWALL_CLI_COMPARE_RUNS_H
#define SLIPWALL_CLI_COMPARE_RUNS_H

#include <stddef.h>

#include "override.h"
#include "slipwall/stats.h"
#include "slipwall/wall.h"

/* What compare_runs needs of the command line: the wall's path (as
 * given), its overrides (printed), the two samples files and --json. */
struct compare_runs_args {
	const char *wall, *a, *b;
	const struct overrides *ov;
	int json;
};

/* Read the accepted loads of both files as runs of w (runlog_read_loads:
 * the header must have w's interfaces; the loads are λ times w's
 * wall_quantity scale), print each run's count, p05 with its 99 %
 * interval, p50 and p95, the differences B - A and the two-sample
 * Kolmogorov-Smirnov test, as text or JSON.  Returns the exit status:
 * 0; 1 when a file has no accepted sample (printed first); 2 for a bad
 * file (FILE:LINE:COLUMN: message on stderr, nothing on stdout). */
int compare_runs(const struct compare_runs_args *a, const struct wall *w);

/* p05's 99 % interval as compare prints it: "[lo, hi]", "none (n < 90)"
 * or "-" without samples (both forms of compare use it). */
void compare_fmt_ci(char *buf, size_t len, const struct stats_summary *s);

#endif
