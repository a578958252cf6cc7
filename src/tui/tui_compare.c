/*
 * tui_compare.c - what-if studies (docs/workbench.md, "The run history
 * (`H`)" and "Runs, pause and the files"): each run's wall kept beside
 * its samples file, two runs of H compared, a run's wall reopened, and
 * the characteristic value said against the previous run's.
 *
 * The wall of a run: when a run starts, its wall is written with
 * wallfile_save as X.yaml beside its samples file X.csv, so a history
 * row (which names X.csv) leads to the wall it sampled, an unsaved edit
 * included.  Rows of runs made before this existed have no wall file:
 * they are read as runs of the current wall, and H says so.
 *
 * Two runs compared: A is the upper row of H (the earlier run), B the
 * lower; each run's accepted loads are read from its samples file as a
 * run of its own wall (runlog_read_loads: λ_min times its
 * wall_quantity's scale), the live run's from its tally.  Shown: both
 * histograms on one axis (B as bars, A as the outline the main screen
 * draws for the previous run), Δp05, Δp50, Δp95 (B - A, and in % of A)
 * and the two-sample Kolmogorov-Smirnov test with x = B and y = A, as
 * `slipwall compare WALL --samples A.csv --against B.csv` prints them
 * (src/cli/compare_runs.c): "p B < A" is the test whose alternative is
 * that B's loads tend to be smaller.  The loads are read once per pair
 * (the KS test is O(n m), exact up to n m = 1e7), on the UI thread.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sys/stat.h>

#include <curses.h>

#include "slipwall/runlog.h"
#include "slipwall/stats.h"
#include "slipwall/text.h"
#include "slipwall/wallfile.h"
#include "tui.h"

/* "−32 %" (a minus sign in UTF-8), "+5.1 %", "0 %". */
static void tui_compare_rel(const struct tui *t, char *buf, size_t len,
			    double a, double b)
{
	if (!(a != 0) || !isfinite(a) || !isfinite(b)) {
		snprintf(buf, len, "-");
		return;
	}
	double r = 100 * (b - a) / a;
	const char *sign = r > 0 ? "+" : r < 0 ? (t->utf8 ? "−" : "-") : "";
	double m = fabs(r);
	snprintf(buf, len, "%s%.*f %%", sign, m >= 10 || m == 0 ? 0 : 1, m);
}

int tui_compare_p05(const struct tui *t, double p05, int w, char *out,
		    size_t len)
{
	char rel[32];
	if (!t->prev_n || isnan(t->prev_p05))
		return 0;
	tui_compare_rel(t, rel, sizeof rel, t->prev_p05, p05);
	for (int prec = 4; prec >= 2; prec--) {
		static const char *const fmt[] = {
			"characteristic value (p05) %.*g (run %d: %.*g, %s)",
			"p05 %.*g (run %d: %.*g, %s)",
		};
		for (int k = 0; k < 2; k++) {
			if (isnan(p05))
				snprintf(out, len, "%s - (run %d: %.*g)",
					 k ? "p05" : "characteristic value (p05)",
					 t->prev_run, prec, t->prev_p05);
			else
				snprintf(out, len, fmt[k], prec, p05,
					 t->prev_run, prec, t->prev_p05, rel);
			if (tui_cols(out) <= w)
				return 1;
		}
	}
	return 1;	/* cut by the pane, as any line */
}

/* ---- two runs of H ---- */

static int tui_compare_cmpd(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

void tui_compare_free(struct tui *t)
{
	struct tui_cmp *c = &t->cmp;
	free(c->la);
	free(c->lb);
	memset(c, 0, sizeof *c);
	c->a = c->b = -1;
}

/* The loads of row h: the live run's tally (live), else its samples
 * file read as a run of its wall file (or of the current wall, with a
 * note, when it has none).  0 and err on failure. */
static int tui_compare_read(struct tui *t, const struct history_row *h,
			    int live, double **x, long *n, char *err,
			    size_t errlen, char *note, size_t notelen)
{
	char path[PATH_MAX], e[SW_ERRLEN], warn[SW_ERRLEN];
	struct wall *w = NULL;
	struct stat st;
	if (live) {
		const struct stats_sorted *s = &t->run.tally.lam;
		*x = malloc(sizeof(double) * (s->n + 1));
		if (!*x) {
			snprintf(err, errlen, "out of memory");
			return 0;
		}
		memcpy(*x, s->x, sizeof(double) * s->n);
		*n = (long)s->n;
		return 1;
	}
	if (!h->file[0]) {
		snprintf(err, errlen, "run %d has no samples file", h->run);
		return 0;
	}
	if (tui_file_run_wall_path(h->file, path, sizeof path) &&
	    stat(path, &st) == 0) {
		if (wallfile_load(path, &w, e) != SW_OK) {
			snprintf(err, errlen, "%s", e);
			return 0;
		}
	} else if (!note[0]) {
		snprintf(note, notelen, "run %d has no wall file: read as runs "
			 "of the current wall", h->run);
	}
	enum sw_status st2 = runlog_read_loads(h->file, w ? w : t->w, x, n,
					       warn, e);
	wall_free(w);
	if (st2 != SW_OK) {
		snprintf(err, errlen, "%s", e);
		return 0;
	}
	qsort(*x, (size_t)*n, sizeof **x, tui_compare_cmpd);
	return 1;
}

void tui_compare_update(struct tui *t, const struct history_row *const *h,
			int n)
{
	struct tui_cmp *c = &t->cmp;
	int a = t->hist_mark[0], b = t->hist_mark[1];
	if (a > b) {
		int k = a;
		a = b;
		b = k;
	}
	if (a < 0 || b >= n) {
		tui_compare_free(t);
		return;
	}
	if (c->a == a && c->b == b)
		return;
	tui_compare_free(t);
	c->a = a;
	c->b = b;
	int live = t->run.latest_joint != NULL;
	if (!tui_compare_read(t, h[a], live && a == n - 1, &c->la, &c->na,
			      c->err, sizeof c->err, c->note, sizeof c->note) ||
	    !tui_compare_read(t, h[b], live && b == n - 1, &c->lb, &c->nb,
			      c->err, sizeof c->err, c->note, sizeof c->note))
		return;
	/* x = B, y = A: p_greater is "B < A" (compare_runs.c) */
	c->ks_ok = c->na > 0 && c->nb > 0 &&
		   stats_ks2(c->lb, (size_t)c->nb, c->la, (size_t)c->na,
			     &c->ks) == 0;
}

/* "Δp05 +2.94 (+8.3 %)" */
static int tui_compare_delta(const struct tui *t, char *buf, size_t len,
			     const char *name, double a, double b)
{
	char rel[32];
	tui_compare_rel(t, rel, sizeof rel, a, b);
	if (isnan(a) || isnan(b))
		return snprintf(buf, len, "%s%s -", t->utf8 ? "Δ" : "d", name);
	const char *sign = b > a ? "+" : b < a ? (t->utf8 ? "−" : "-") : "";
	return snprintf(buf, len, "%s%s %s%.4g (%s)", t->utf8 ? "Δ" : "d",
			name, sign, fabs(b - a), rel);
}

/* Both runs on one axis: B as bars, A as the outline. */
static void tui_compare_hist(struct tui *t, int y0, int rows, int w)
{
	struct tui_cmp *c = &t->cmp;
	double lo = fmin(c->la[0], c->lb[0]);
	double hi = fmax(c->la[c->na - 1], c->lb[c->nb - 1]);
	if (!(hi > lo)) {
		double d = fabs(lo) > 0 ? 0.05 * fabs(lo) : 0.5;
		lo -= d;
		hi += d;
	}
	int nb = w;
	double fa = c->na > 1 ? stats_fd_width(c->la, (size_t)c->na) : 0;
	double fb = c->nb > 1 ? stats_fd_width(c->lb, (size_t)c->nb) : 0;
	double fd = fa > 0 && fb > 0 ? fmin(fa, fb) : fa > 0 ? fa : fb;
	if (fd > 0 && isfinite(fd))
		nb = (int)ceil((hi - lo) / fd);
	if (nb < 8)
		nb = 8;
	if (nb > w)
		nb = w;
	int cpb = w / nb;
	nb = w / cpb;
	double width = (hi - lo) / nb;
	size_t *ca = calloc((size_t)nb, sizeof *ca);
	size_t *cb = calloc((size_t)nb, sizeof *cb);
	if (!ca || !cb) {
		free(ca);
		free(cb);
		return;
	}
	double maxf = 0;
	for (long i = 0; i < c->na; i++)
		ca[stats_bin(c->la[i], lo, width, nb)]++;
	for (long i = 0; i < c->nb; i++)
		cb[stats_bin(c->lb[i], lo, width, nb)]++;
	for (int k = 0; k < nb; k++)
		maxf = fmax(maxf, fmax((double)ca[k] / (double)c->na,
				       (double)cb[k] / (double)c->nb));
	static const char *const u[8] = {"▁", "▂", "▃", "▄", "▅", "▆", "▇", "█"};
	int battr = t->colors ? COLOR_PAIR(3) : 0;
	int pattr = (t->colors ? COLOR_PAIR(7) : 0) | A_BOLD;
	for (int col = 0; col < nb * cpb && maxf > 0; col++) {
		int e = (int)ceil((double)cb[col / cpb] / (double)c->nb / maxf *
				  rows * 8);
		if (battr)
			attron(battr);
		for (int r = 0; r < rows; r++) {
			int k = e - 8 * r;
			if (k <= 0)
				break;
			const char *g = t->utf8 ? u[k >= 8 ? 7 : k - 1] :
					k >= 8 ? "#" : k >= 4 ? "+" : ".";
			mvaddstr(y0 + rows - 1 - r, col, g);
		}
		if (battr)
			attroff(battr);
		int ea = (int)ceil((double)ca[col / cpb] / (double)c->na / maxf *
				   rows * 8);
		if (ea > 0) {
			attron(pattr);
			mvaddstr(y0 + rows - 1 - (ea - 1) / 8, col,
				 t->utf8 ? "═" : "=");
			attroff(pattr);
		}
	}
	for (int col = 0; col < nb * cpb; col++)
		tui_put(t, y0 + rows, col, "─", "-");
	char l[32], r[32];
	snprintf(l, sizeof l, "%.4g", lo);
	snprintf(r, sizeof r, "%.4g", hi);
	tui_text(y0 + rows + 1, 0, w, l);
	tui_text(y0 + rows + 1, nb * cpb - (int)strlen(r), (int)strlen(r), r);
	free(ca);
	free(cb);
}

void tui_compare_draw(struct tui *t, const struct history_row *const *h,
		      int y0, int hr)
{
	struct tui_cmp *c = &t->cmp;
	int C = t->cols;
	char buf[512], pa[32], pb[32];
	if (c->a < 0)
		return;
	const struct history_row *A = h[c->a], *B = h[c->b];
	attron(A_BOLD);
	char fa[64], fb[64];
	snprintf(buf, sizeof buf, "compare: A run %d (%s)  B run %d (%s)",
		 A->run, tui_friction(t, fa, sizeof fa, A->mu_bed, A->mu_head,
				      A->mu_cov),
		 B->run, tui_friction(t, fb, sizeof fb, B->mu_bed, B->mu_head,
				      B->mu_cov));
	tui_text_cut(t, y0, 0, C, buf);
	attroff(A_BOLD);
	if (c->err[0]) {
		tui_text(y0 + 1, 0, C, c->err);
		return;
	}
	if (c->na == 0 || c->nb == 0) {
		tui_text(y0 + 1, 0, C, "a run has no accepted sample: nothing "
			 "to compare");
		return;
	}
	struct stats_summary sa, sb;
	stats_summarise(c->la, (size_t)c->na, &sa);
	stats_summarise(c->lb, (size_t)c->nb, &sb);
	int rows = hr - 6 - (c->note[0] ? 1 : 0);
	int y = y0 + 1;
	if (rows >= 1) {
		tui_compare_hist(t, y, rows, C);
		y += rows + 2;
	}
	snprintf(buf, sizeof buf, "bars B (%ld accepted), %s A (%ld): p05 A %s "
		 "B %s", c->nb, t->utf8 ? "═" : "=", c->na,
		 text_num(pa, sizeof pa, sa.p05, 4),
		 text_num(pb, sizeof pb, sb.p05, 4));
	tui_text_cut(t, y++, 0, C, buf);
	int n = tui_compare_delta(t, buf, sizeof buf, "p05", sa.p05, sb.p05);
	n += snprintf(buf + n, sizeof buf - (size_t)n, "  ");
	n += tui_compare_delta(t, buf + n, sizeof buf - (size_t)n, "p50",
			       sa.p50, sb.p50);
	n += snprintf(buf + n, sizeof buf - (size_t)n, "  ");
	tui_compare_delta(t, buf + n, sizeof buf - (size_t)n, "p95", sa.p95,
			  sb.p95);
	tui_text_cut(t, y++, 0, C, buf);
	if (c->ks_ok) {
		char d[32], p2[32], pg[32];
		tui_pct(p2, sizeof p2, c->ks.p_two_sided);
		tui_pct(pg, sizeof pg, c->ks.p_greater);
		snprintf(buf, sizeof buf, "KS B vs A: D %s  p %s  p B < A %s%s",
			 text_num(d, sizeof d, c->ks.d, 4), p2, pg,
			 c->ks.exact ? "" : " (asymptotic)");
	} else {
		snprintf(buf, sizeof buf, "KS B vs A: -");
	}
	tui_text_cut(t, y++, 0, C, buf);
	if (c->note[0])
		tui_text_cut(t, y++, 0, C, c->note);
}

/* ---- reopen ---- */

int tui_compare_reopen(struct tui *t, const struct history_row *h)
{
	char path[PATH_MAX], err[SW_ERRLEN];
	struct wall *nw;
	struct stat st;
	t->hist_msg[0] = 0;
	if (!h->file[0] || !tui_file_run_wall_path(h->file, path, sizeof path)) {
		snprintf(t->hist_msg, sizeof t->hist_msg, "run %d has no "
			 "samples file, so no wall kept", h->run);
		return 0;
	}
	if (stat(path, &st) != 0) {
		snprintf(t->hist_msg, sizeof t->hist_msg, "run %d: %s: %s",
			 h->run, path, errno == ENOENT ? "no wall kept for "
			 "this run" : strerror(errno));
		return 0;
	}
	if (!S_ISREG(st.st_mode)) {
		snprintf(t->hist_msg, sizeof t->hist_msg, "run %d: %s: not a "
			 "regular file", h->run, path);
		return 0;
	}
	if (wallfile_load(path, &nw, err) != SW_OK) {
		snprintf(t->hist_msg, sizeof t->hist_msg, "%s", err);
		return 0;
	}
	/* h may be a row of t->hist, which the run's end below moves */
	int run = h->run;
	char which[64] = "";
	if (strcmp(h->session, t->session))
		snprintf(which, sizeof which, " of %.24s", h->session);
	undo_reset(&t->undo);
	snprintf(t->next_what, sizeof t->next_what, "reopened run %d%s", run,
		 which);
	tui_edit_set_wall(t, nw);
	tui_message(t, 0, "reopened run %d%s's wall (%s): sampling (run %d)",
		    run, which, path, t->runno);
	return 1;
}
