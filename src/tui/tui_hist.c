/*
 * tui_hist.c - the live histogram of the accepted λ_min, with the
 * single-solution values (S standard, G gilbert) and the experimental
 * loads (T) marked on its axis.
 *
 * The bin width is Freedman-Diaconis (stats_fd_width), rounded so that
 * every bin is a whole number of columns; bars are drawn in eighths of a
 * row with ▁▂▃▄▅▆▇█, or with . + # when the locale is not UTF-8.  The
 * axis spans the data and the markers; a standard or gilbert value far
 * beyond the data (standard is an upper value, often several times
 * larger) would squash the bars, so it is then shown as "S>" or "G>" at
 * the right end, its value in the legend.
 *
 * The previous run of the session (before the last edit) is drawn as an
 * outline over the bars: the top of each of its bins as ═ (= in ASCII),
 * in its own colour (yellow), on the same axis and the same scale of
 * relative frequency, so that a what-if is read at a glance; the title
 * labels it ("═ run 2").  The axis follows the current run
 * (docs/workbench.md, "The histogram"): it spans both runs while that
 * span is at most 3 times the current run's own (its range, or 10 % of
 * its middle when narrower), so that a small change shows both whole;
 * past that (a moved load that halves the loads) it spans the current
 * run alone, the outline is clipped to it (the previous run's loads
 * off the axis are left out, not piled into the end bins) and the
 * title says which share of the previous run is off the axis and on
 * which side ("run 2: 80 % off ▸").
 *
 * With the sample browser open (tui_browse.c), the bin of the shown
 * sample's load is lit (the load's colour, or reverse video); with it
 * closed and a mechanism family of the tally on show (m/M), the bins of
 * that family's kept samples are lit the same way (tui_hist_lit_family).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <curses.h>

#include "slipwall/stats.h"
#include "tui.h"

struct tui_mark {
	double v;
	const char *g;
};

static const char *tui_hist_level(const struct tui *t, int eighths)
{
	static const char *const u[8] = {"▁", "▂", "▃", "▄", "▅", "▆", "▇", "█"};
	if (eighths <= 0)
		return NULL;
	if (eighths >= 8)
		return t->utf8 ? u[7] : "#";
	if (t->utf8)
		return u[eighths - 1];
	return eighths >= 4 ? "+" : ".";
}

/* The axis: lo .. hi over the data of both runs and the markers; the
 * single-solution values far beyond the data go in far[]. */
struct tui_hist_axis {
	double lo, hi;
	struct tui_mark mk[64];
	int nmk;
	const char *far[2];
	int nfar;
	int clip;		/* the previous run clipped to the axis */
};

static void tui_hist_title(struct tui *t, int y0, int x0, int w, size_t n,
			   const char *off)
{
	char buf[256];
	if (t->prev_n) {
		snprintf(buf, sizeof buf, "%s_min histogram (%zu accepted; %s run %d%s)",
			 tui_lam(t), n, t->utf8 ? "═" : "=", t->prev_run, off);
		if (tui_cols(buf) > w)
			snprintf(buf, sizeof buf, "%s_min histogram (%zu; %s run %d%s)",
				 tui_lam(t), n, t->utf8 ? "═" : "=", t->prev_run, off);
	} else
		snprintf(buf, sizeof buf, "%s_min histogram (%zu accepted)",
			 tui_lam(t), n);
	attron(A_BOLD);
	tui_text_cut(t, y0, x0, w, buf);
	attroff(A_BOLD);
}

/* The axis of the histogram; 0 when there is nothing to draw yet. */
static int tui_hist_range(const struct tui *t, struct tui_hist_axis *a)
{
	const struct stats_sorted *s = &t->run.tally.lam;
	const struct wall *wall = t->w;
	const double *px = t->prev_lam;
	size_t n = s->n, pn = t->prev_n;
	double lo = INFINITY, hi = -INFINITY;

	a->nmk = a->nfar = 0;
	a->clip = 0;
	if (n) {
		lo = s->x[0];
		hi = s->x[n - 1];
	}
	if (n && pn) {	/* both runs, unless that squeezes this one */
		double ulo = fmin(lo, px[0]), uhi = fmax(hi, px[pn - 1]);
		double own = fmax(hi - lo, 0.1 * fabs(0.5 * (lo + hi)));
		if (uhi - ulo <= 3 * own) {
			lo = ulo;
			hi = uhi;
		} else {
			a->clip = 1;
		}
	}
	for (int i = 0; i < wall->ntests && a->nmk < 60; i++)
		a->mk[a->nmk++] = (struct tui_mark){wall->tests[i], "T"};
	for (int i = 0; i < a->nmk; i++) {
		lo = fmin(lo, a->mk[i].v);
		hi = fmax(hi, a->mk[i].v);
	}
	/* the single-solution values: on the axis unless far beyond */
	struct tui_mark one[2];
	int none = 0;
	if (t->has_gil)
		one[none++] = (struct tui_mark){tui_load(t, t->lam_gil), "G"};
	if (t->has_std)
		one[none++] = (struct tui_mark){tui_load(t, t->lam_std), "S"};
	double span = isfinite(hi - lo) ? hi - lo : 0;
	for (int i = 0; i < none; i++) {
		if (n && span > 0 && one[i].v > hi + 0.5 * span) {
			a->far[a->nfar++] = one[i].g;
			continue;
		}
		a->mk[a->nmk++] = one[i];
		lo = fmin(lo, one[i].v);
		hi = fmax(hi, one[i].v);
	}
	if (!isfinite(lo))
		return 0;
	if (!(hi > lo)) {
		double d = fabs(lo) > 0 ? 0.05 * fabs(lo) : 0.5;
		lo -= d;
		hi += d;
	}
	a->lo = lo;
	a->hi = hi;
	return 1;
}

/* How many of the n values x fall in each of nb bins of width from lo
 * (the ends clamped); returns the largest count. */
static size_t tui_hist_bin(const double *x, size_t n, double lo, double width,
			   size_t *count, int nb)
{
	size_t maxc = 0;
	for (size_t i = 0; i < n; i++) {
		int b = stats_bin(x[i], lo, width, nb);
		if (++count[b] > maxc)
			maxc = count[b];
	}
	return maxc;
}

/* The previous run's outline, then this run's bars, in rows rows above
 * y0 + rows + 1; nb bins of cpb columns each, the bins lit[b] lit. */
static void tui_hist_paint(struct tui *t, int y0, int x0, int rows, int nb,
			   int cpb, const size_t *count, const size_t *pcount,
			   size_t maxc, const unsigned char *lit)
{
	size_t n = t->run.tally.lam.n, pn = t->prev_n;
	int cols = nb * cpb;
	/* both runs on one scale of relative frequency */
	double maxf = n ? (double)maxc / (double)n : 0;
	for (int b = 0; b < nb && pn; b++)
		maxf = fmax(maxf, (double)pcount[b] / (double)pn);
	int battr = t->colors ? COLOR_PAIR(3) : 0;
	int lattr = (t->colors ? COLOR_PAIR(2) : A_REVERSE) | A_BOLD;
	for (int c = 0; c < cols && maxc; c++) {
		size_t cnt = count[c / cpb];
		int e = (int)ceil((double)cnt / (double)n / maxf * rows * 8);
		int attr = lit[c / cpb] ? lattr : battr;
		if (attr)
			attron(attr);
		for (int r = 0; r < rows; r++) {
			const char *g = tui_hist_level(t, e - 8 * r);
			if (g)
				mvaddstr(y0 + rows - r, x0 + c, g);
		}
		if (attr)
			attroff(attr);
	}
	/* over the bars, so that it is seen where they are higher */
	int pattr = (t->colors ? COLOR_PAIR(7) : 0) | A_BOLD;
	attron(pattr);
	for (int c = 0; c < cols && maxf > 0 && pn; c++) {
		double f = (double)pcount[c / cpb] / (double)pn;
		int e = (int)ceil(f / maxf * rows * 8);
		if (e <= 0)
			continue;
		int top = (e - 1) / 8;	/* its top row, from the bottom */
		mvaddstr(y0 + rows - top, x0 + c, t->utf8 ? "═" : "=");
	}
	attroff(pattr);
}

/* m/M's lit bins: the kept samples (tui_browse.c) of the family on show,
 * each found by its mechanism in the tally (one hash of its joint
 * states). */
static void tui_hist_lit_family(const struct tui *t, double lo, double width,
				int nb, unsigned char *lit)
{
	const struct family_set *fs = tui_run_families(t);
	int f = tui_family_shown(t);
	if (!fs || f < 0)
		return;
	struct tui_browse_sample s;
	long first = tui_browse_first(t);
	for (long i = first; first >= 0 && i < t->browse.next; i++) {
		if (!tui_browse_sample_at(t, i, &s) ||
		    s.status != SAMPLE_ACCEPTED)
			continue;
		if (tui_run_family_of(t, fs, s.joint) == f)
			lit[stats_bin(tui_load(t, s.lam), lo, width, nb)] = 1;
	}
}

/* The bins (Freedman-Diaconis, whole columns each) and the bars;
 * returns the columns used, or -1. */
static int tui_hist_bars(struct tui *t, int y0, int x0, int rows, int w,
			 const struct tui_hist_axis *a)
{
	const struct stats_sorted *s = &t->run.tally.lam;
	size_t n = s->n;
	int nb = w;
	if (n >= 2) {
		double fd = stats_fd_width(s->x, n);
		if (fd > 0 && isfinite(fd))
			nb = (int)ceil((a->hi - a->lo) / fd);
	}
	if (nb < 8)
		nb = 8;
	if (nb > w)
		nb = w;
	int cpb = w / nb;
	nb = w / cpb;
	double width = (a->hi - a->lo) / nb;

	size_t *count = calloc((size_t)nb, sizeof *count);
	size_t *pcount = calloc((size_t)nb, sizeof *pcount);
	unsigned char *lit = calloc((size_t)nb, 1);
	if (!count || !pcount || !lit) {
		free(count);
		free(pcount);
		free(lit);
		return -1;
	}
	size_t maxc = tui_hist_bin(s->x, n, a->lo, width, count, nb);
	for (size_t i = 0; n && i < t->prev_n; i++) {
		double v = t->prev_lam[i];
		if (!a->clip || (v >= a->lo && v <= a->hi))	/* clipped */
			pcount[stats_bin(v, a->lo, width, nb)]++;
	}
	struct tui_browse_sample bs;
	const char *joint;
	const double *vel;
	char label[256];
	if (tui_browse_shown(t, &bs) && bs.status == SAMPLE_ACCEPTED)
		lit[stats_bin(tui_load(t, bs.lam), a->lo, width, nb)] = 1;
	else if (!t->browse.open && t->mech_sel > 0 &&
		 tui_wall_mechanism(t, &joint, &vel, label, sizeof label, 0))
		tui_hist_lit_family(t, a->lo, width, nb, lit);
	tui_hist_paint(t, y0, x0, rows, nb, cpb, count, pcount, maxc, lit);
	free(count);
	free(pcount);
	free(lit);
	return nb * cpb;
}

/* The axis line at row ya with its markers, the numbers under it. */
static void tui_hist_axis(struct tui *t, int ya, int x0, int w, int cols,
			  const struct tui_hist_axis *a)
{
	for (int c = 0; c < cols; c++)
		tui_put(t, ya, x0 + c, "─", "-");
	int attr = (t->colors ? COLOR_PAIR(4) : 0) | A_BOLD;
	attron(attr);
	for (int i = 0; i < a->nmk; i++) {
		int c = (int)lround((a->mk[i].v - a->lo) / (a->hi - a->lo) *
				    (cols - 1));
		mvaddstr(ya, x0 + c, a->mk[i].g);
	}
	for (int i = 0; i < a->nfar; i++) {
		mvaddstr(ya, x0 + cols - 2 - 2 * i, a->far[i]);
		mvaddstr(ya, x0 + cols - 1 - 2 * i, ">");
	}
	attroff(attr);

	char l[32], m[32], r[32];
	snprintf(l, sizeof l, "%.4g", a->lo);
	snprintf(m, sizeof m, "%.4g", 0.5 * (a->lo + a->hi));
	snprintf(r, sizeof r, "%.4g", a->hi);
	tui_text(ya + 1, x0, w, l);
	int mc = (cols - (int)strlen(m)) / 2;
	if (mc > (int)strlen(l))
		tui_text(ya + 1, x0 + mc, w - mc, m);
	int rc = cols - (int)strlen(r);
	if (rc > mc + (int)strlen(m))
		tui_text(ya + 1, x0 + rc, w - rc, r);
}

void tui_hist_draw(struct tui *t, int y0, int x0, int h, int w)
{
	const struct wall *wall = t->w;
	struct tui_hist_axis a;
	a.lo = a.hi = 0;
	a.clip = 0;
	char buf[256];

	int have = tui_hist_range(t, &a);
	char off[64] = "";
	if (have && a.clip) {	/* the share of the previous run off the axis */
		size_t below = 0, above = 0;	/* sorted: from each end */
		while (below < t->prev_n && t->prev_lam[below] < a.lo)
			below++;
		while (above < t->prev_n - below &&
		       t->prev_lam[t->prev_n - 1 - above] > a.hi)
			above++;
		char pct[32];
		tui_pct(pct, sizeof pct, (double)(below + above) / (double)t->prev_n);
		snprintf(off, sizeof off, ": %s off %s", pct,
			 above >= below ? (t->utf8 ? "▸" : ">") :
			 (t->utf8 ? "◂" : "<"));
	}
	tui_hist_title(t, y0, x0, w, t->run.tally.lam.n, off);
	int rows = h - 4;
	if (rows < 1 || w < 10)
		return;
	if (!have) {
		/* a run that has ended waits for nothing */
		tui_text(y0 + 1, x0, w, t->run.mc ? "waiting for accepted "
			 "samples..." : t->run.tally.samples > 0 ?
			 "no sample accepted (the rejections are counted "
			 "on the right)" : "no samples");
		return;
	}
	int cols = tui_hist_bars(t, y0, x0, rows, w, &a);
	if (cols < 0)
		return;
	int ya = y0 + rows + 1;
	tui_hist_axis(t, ya, x0, w, cols, &a);

	char sv[32], gv[32];
	int len;
	if (tui_solve_text(t, sv, gv, sizeof sv))
		len = snprintf(buf, sizeof buf, "S standard %s  G gilbert %s", sv, gv);
	else
		len = snprintf(buf, sizeof buf, "S G: %s", sv);
	if (wall->ntests && len > 0 && (size_t)len < sizeof buf)
		snprintf(buf + len, sizeof buf - (size_t)len, "  T tests (%d)",
			 wall->ntests);
	tui_text_cut(t, ya + 2, x0, w, buf);
}
