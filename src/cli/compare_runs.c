/*
 * compare_runs.c - two runs side by side: `slipwall compare WALL
 * --samples A.csv --against B.csv` (docs/run.md, "Two runs: --against";
 * the statistics in docs/statistics.md).
 *
 * What-if studies: A is a run of the wall, B a run of the same wall
 * with something changed (the friction, the load's point, an edited
 * copy of the file with the same interfaces).  Both samples files are
 * read as runs of WALL (runlog_read_loads): the header must have WALL's
 * interfaces, and each accepted λ_min is multiplied by WALL's
 * wall_quantity scale, so both are in the quantity WALL prints.
 *
 * Printed: each run's accepted count, p05 with its 99 % interval, p50
 * and p95 (stats_summarise, as `run` prints them); the differences
 * B - A of p05, p50 and p95, absolute in the load's unit and relative to
 * A in %; and the two-sample Kolmogorov-Smirnov test with x = B and
 * y = A (stats_ks2), so that its "greater" alternative (x's CDF above
 * y's) is "B < A": B's loads tend to be smaller.  That mirrors the
 * model-against-tests comparison of cmd_compare.c, whose x is the model.
 *
 * Called by cmd_compare after the wall (with its overrides) is loaded;
 * it owns the two arrays of loads it reads.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cli.h"
#include "compare_runs.h"
#include "slipwall/json.h"
#include "slipwall/runlog.h"
#include "slipwall/stats.h"
#include "slipwall/tally.h"

/* One run: its file's accepted loads and their summary. */
struct one_run {
	const char *path;
	double *lam;		/* in the wall's quantity, n = accepted */
	long accepted;
	struct stats_summary s;
};

/* Read a samples file; 0 or 2 after printing its error. */
static int read_run(const char *path, const struct wall *w,
		    struct one_run *r)
{
	char err[SW_ERRLEN], warn[SW_ERRLEN];
	r->path = path;
	if (runlog_read_loads(path, w, &r->lam, &r->accepted, warn, err) !=
	    SW_OK) {
		cli_errorf("%s", err);
		return 2;
	}
	if (warn[0])
		cli_errorf("%s", warn);
	stats_summarise(r->lam, (size_t)r->accepted, &r->s);
	return 0;
}

/* B - A in % of A: NaN when A is 0 or either is missing. */
static double rel_pct(double a, double b)
{
	return a != 0 && isfinite(a) && isfinite(b) ? 100 * (b - a) / a : NAN;
}

/* ---- text ---------------------------------------------------------------- */

void compare_fmt_ci(char *buf, size_t len, const struct stats_summary *s)
{
	if (s->has_ci)
		snprintf(buf, len, "[%.6g, %.6g]", s->p05_lo, s->p05_hi);
	else if (s->n > 0)
		snprintf(buf, len, "none (n < 90)");
	else
		snprintf(buf, len, "-");
}

static void fmt_diff(char *buf, size_t len, double a, double b,
		     const char *unit)
{
	double r = rel_pct(a, b);
	if (!isfinite(a) || !isfinite(b))
		snprintf(buf, len, "-");
	else if (isfinite(r))
		snprintf(buf, len, "%+.6g%s%s (%+.4g %%)", b - a, *unit ? " " :
			 "", unit, r);
	else
		snprintf(buf, len, "%+.6g%s%s", b - a, *unit ? " " : "", unit);
}

static void row(const char *name, double a, double b, const char *unit)
{
	char d[96];
	fmt_diff(d, sizeof d, a, b, unit);
	printf("%-24s %-26.6g %-26.6g %s\n", name, a, b, d);
}

static void print_text(const struct compare_runs_args *a,
		       const struct wall *w, const struct wall_quantity *q,
		       const struct one_run *ra, const struct one_run *rb,
		       const struct stats_ks *ks, int ks_ok)
{
	printf("%s  [%s]\n", cli_text(w->name ? w->name : a->wall),
	       cli_text(a->wall));
	if (a->ov->n > 0) {
		char o[1024];
		override_describe(a->ov, o, sizeof o);
		printf("overrides: %s\n", cli_text(o));
	}
	printf("A: %ld accepted loads from %s\n", ra->accepted,
	       cli_text(ra->path));
	printf("B: %ld accepted loads from %s\n", rb->accepted,
	       cli_text(rb->path));
	printf("loads: %s\n\n", q->what);

	char ca[64], cb[64];
	printf("%-24s %-26s %-26s %s\n", "", "A", "B", "B - A");
	snprintf(ca, sizeof ca, "%ld", ra->accepted);
	snprintf(cb, sizeof cb, "%ld", rb->accepted);
	printf("%-24s %-26s %-26s %+ld\n", "accepted", ca, cb,
	       rb->accepted - ra->accepted);
	row("p05 (characteristic)", ra->s.p05, rb->s.p05, q->unit);
	compare_fmt_ci(ca, sizeof ca, &ra->s);
	compare_fmt_ci(cb, sizeof cb, &rb->s);
	printf("%-24s %-26s %s\n", "  99 % interval", ca, cb);
	row("p50", ra->s.p50, rb->s.p50, q->unit);
	row("p95", ra->s.p95, rb->s.p95, q->unit);
	if (!ra->s.has_ci || !rb->s.has_ci)
		printf("(no interval: needs at least 90 values)\n");

	if (!ks_ok) {
		printf("\nno Kolmogorov-Smirnov test: a run has no accepted "
		       "sample\n");
		return;
	}
	printf("\nKolmogorov-Smirnov, two samples (x = B, y = A), %s "
	       "p-values:\n", ks->exact ? "exact" : "asymptotic");
	printf("  D  = %.6g   (D+ = max(F_B - F_A) = %.6g, D- = max(F_A - "
	       "F_B) = %.6g)\n", ks->d, ks->d_plus, ks->d_minus);
	printf("  p two-sided  %-12.6g H1: the distributions differ\n",
	       ks->p_two_sided);
	printf("  p B < A      %-12.6g H1: B's CDF above A's (B's loads "
	       "tend to be smaller)\n", ks->p_greater);
	printf("  p B > A      %-12.6g H1: B's CDF below A's (B's loads "
	       "tend to be larger)\n", ks->p_less);
}

/* ---- JSON ---------------------------------------------------------------- */

static void json_run(struct json *j, const char *key, const struct one_run *r)
{
	json_key(j, key);
	json_object_begin(j);
	json_key_string(j, "source", r->path);
	json_key_int(j, "accepted", r->accepted);
	tally_summary_json(j, &r->s);
	json_object_end(j);
}

static void json_diff(struct json *j, const char *key, double a, double b)
{
	json_key(j, key);
	json_object_begin(j);
	json_key_double(j, "absolute", b - a);
	json_key_double(j, "relative_percent", rel_pct(a, b));
	json_object_end(j);
}

static void print_json(const struct compare_runs_args *a,
		       const struct wall_quantity *q,
		       const struct one_run *ra, const struct one_run *rb,
		       const struct stats_ks *ks, int ks_ok)
{
	struct json j;
	json_init(&j, stdout, 1);
	json_object_begin(&j);
	json_key_string(&j, "wall", a->wall);
	override_json(a->ov, &j);
	tally_quantity_json(&j, q);
	json_run(&j, "a", ra);
	json_run(&j, "b", rb);
	json_key(&j, "difference");
	json_object_begin(&j);
	json_key_string(&j, "of", "b - a");
	json_key_int(&j, "accepted", rb->accepted - ra->accepted);
	json_diff(&j, "p05", ra->s.p05, rb->s.p05);
	json_diff(&j, "p50", ra->s.p50, rb->s.p50);
	json_diff(&j, "p95", ra->s.p95, rb->s.p95);
	json_object_end(&j);
	json_key(&j, "ks");
	if (!ks_ok) {
		json_null(&j);
	} else {
		json_object_begin(&j);
		json_key_string(&j, "x", "b");
		json_key_string(&j, "y", "a");
		json_key_double(&j, "statistic", ks->d);
		json_key_double(&j, "d_plus", ks->d_plus);
		json_key_double(&j, "d_minus", ks->d_minus);
		json_key_double(&j, "p_two_sided", ks->p_two_sided);
		json_key_double(&j, "p_b_less", ks->p_greater);
		json_key_double(&j, "p_b_greater", ks->p_less);
		json_key(&j, "exact");
		json_bool(&j, ks->exact);
		json_object_end(&j);
	}
	json_object_end(&j);
	json_end(&j);
}

/* ---- the comparison ------------------------------------------------------ */

int compare_runs(const struct compare_runs_args *a, const struct wall *w)
{
	struct one_run ra = {0}, rb = {0};
	int status = read_run(a->a, w, &ra);
	if (!status)
		status = read_run(a->b, w, &rb);
	if (status) {
		free(ra.lam);
		return status;
	}
	struct wall_quantity q;
	wall_quantity(w, &q);
	struct stats_ks ks;
	/* x = B, y = A: p_greater is "B < A" (header comment) */
	int ks_ok = ra.accepted > 0 && rb.accepted > 0 &&
		    stats_ks2(rb.lam, (size_t)rb.accepted, ra.lam,
			      (size_t)ra.accepted, &ks) == 0;
	if (a->json)
		print_json(a, &q, &ra, &rb, &ks, ks_ok);
	else
		print_text(a, w, &q, &ra, &rb, &ks, ks_ok);
	for (int k = 0; k < 2; k++) {
		const struct one_run *r = k ? &rb : &ra;
		if (r->accepted == 0) {
			cli_errorf("slipwall compare: %s has no accepted "
				   "sample", r->path);
			status = 1;
		}
	}
	free(ra.lam);
	free(rb.lam);
	return status;
}
