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
 * outline under the bars: the top of each of its bins, on the same axis
 * (which spans both runs) and the same scale of relative frequency, so
 * that a what-if is read at a glance.
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

void tui_hist_draw(struct tui *t, int y0, int x0, int h, int w)
{
	const struct stats_sorted *s = &t->run.tally.lam;
	const struct wall *wall = t->w;
	struct tui_mark mk[64];
	int nmk = 0, nfar = 0;
	const char *far[2];
	char buf[256];
	size_t n = s->n;

	const double *px = t->prev_lam;
	size_t pn = t->prev_n;
	if (pn) {
		snprintf(buf, sizeof buf, "%s_min histogram (%zu accepted; %s run %d)",
			 tui_lam(t), n, t->utf8 ? "─" : "_", t->prev_run);
		if (tui_cols(buf) > w)
			snprintf(buf, sizeof buf, "%s_min histogram (%zu; %s run %d)",
				 tui_lam(t), n, t->utf8 ? "─" : "_", t->prev_run);
	} else
		snprintf(buf, sizeof buf, "%s_min histogram (%zu accepted)",
			 tui_lam(t), n);
	attron(A_BOLD);
	tui_text(y0, x0, w, buf);
	attroff(A_BOLD);
	int rows = h - 4;
	if (rows < 1 || w < 10)
		return;

	double lo = INFINITY, hi = -INFINITY;
	if (n) {
		lo = s->x[0];
		hi = s->x[n - 1];
	}
	if (n && pn) {
		lo = fmin(lo, px[0]);
		hi = fmax(hi, px[pn - 1]);
	}
	for (int i = 0; i < wall->ntests && nmk < 60; i++)
		mk[nmk++] = (struct tui_mark){wall->tests[i], "T"};
	for (int i = 0; i < nmk; i++) {
		lo = fmin(lo, mk[i].v);
		hi = fmax(hi, mk[i].v);
	}
	/* the single-solution values: on the axis unless far beyond */
	struct tui_mark one[2];
	int none = 0;
	if (t->has_gil)
		one[none++] = (struct tui_mark){t->lam_gil, "G"};
	if (t->has_std)
		one[none++] = (struct tui_mark){t->lam_std, "S"};
	double span = isfinite(hi - lo) ? hi - lo : 0;
	for (int i = 0; i < none; i++) {
		if (n && span > 0 && one[i].v > hi + 0.5 * span) {
			far[nfar++] = one[i].g;
			continue;
		}
		mk[nmk++] = one[i];
		lo = fmin(lo, one[i].v);
		hi = fmax(hi, one[i].v);
	}
	if (!isfinite(lo)) {
		tui_text(y0 + 1, x0, w, "waiting for accepted samples...");
		return;
	}
	if (!(hi > lo)) {
		double d = fabs(lo) > 0 ? 0.05 * fabs(lo) : 0.5;
		lo -= d;
		hi += d;
	}

	int nb = w;
	if (n >= 2) {
		double fd = stats_fd_width(s->x, n);
		if (fd > 0 && isfinite(fd))
			nb = (int)ceil((hi - lo) / fd);
	}
	if (nb < 8)
		nb = 8;
	if (nb > w)
		nb = w;
	int cpb = w / nb;
	nb = w / cpb;
	int cols = nb * cpb;
	double width = (hi - lo) / nb;

	size_t *count = calloc((size_t)nb, sizeof *count);
	size_t *pcount = calloc((size_t)nb, sizeof *pcount);
	if (!count || !pcount) {
		free(count);
		free(pcount);
		return;
	}
	size_t maxc = 0;
	for (size_t i = 0; i < n; i++) {
		int b = stats_bin(s->x[i], lo, width, nb);
		if (++count[b] > maxc)
			maxc = count[b];
	}
	/* both runs on one scale of relative frequency */
	double maxf = n ? (double)maxc / (double)n : 0;
	if (n)
		for (size_t i = 0; i < pn; i++) {
			pcount[stats_bin(px[i], lo, width, nb)]++;
		}
	for (int b = 0; b < nb && pn; b++)
		maxf = fmax(maxf, (double)pcount[b] / (double)pn);
	int pattr = t->colors ? COLOR_PAIR(4) : A_DIM;
	attron(pattr);
	for (int c = 0; c < cols && maxf > 0 && pn; c++) {
		double f = (double)pcount[c / cpb] / (double)pn;
		int e = (int)ceil(f / maxf * rows * 8);
		if (e <= 0)
			continue;
		int top = (e - 1) / 8;	/* its top row, from the bottom */
		mvaddstr(y0 + rows - top, x0 + c, t->utf8 ? "─" : "_");
	}
	attroff(pattr);
	int attr = t->colors ? COLOR_PAIR(3) : 0;
	if (attr)
		attron(attr);
	for (int c = 0; c < cols && maxc; c++) {
		size_t cnt = count[c / cpb];
		int e = (int)ceil((double)cnt / (double)n / maxf * rows * 8);
		for (int r = 0; r < rows; r++) {
			const char *g = tui_hist_level(t, e - 8 * r);
			if (g)
				mvaddstr(y0 + rows - r, x0 + c, g);
		}
	}
	if (attr)
		attroff(attr);
	free(count);
	free(pcount);

	int ya = y0 + rows + 1;
	for (int c = 0; c < cols; c++)
		tui_put(t, ya, x0 + c, "─", "-");
	attr = (t->colors ? COLOR_PAIR(4) : 0) | A_BOLD;
	attron(attr);
	for (int i = 0; i < nmk; i++) {
		int c = (int)lround((mk[i].v - lo) / (hi - lo) * (cols - 1));
		mvaddstr(ya, x0 + c, mk[i].g);
	}
	for (int i = 0; i < nfar; i++) {
		mvaddstr(ya, x0 + cols - 2 - 2 * i, far[i]);
		mvaddstr(ya, x0 + cols - 1 - 2 * i, ">");
	}
	attroff(attr);

	char l[32], m[32], r[32];
	snprintf(l, sizeof l, "%.4g", lo);
	snprintf(m, sizeof m, "%.4g", 0.5 * (lo + hi));
	snprintf(r, sizeof r, "%.4g", hi);
	tui_text(ya + 1, x0, w, l);
	int mc = (cols - (int)strlen(m)) / 2;
	if (mc > (int)strlen(l))
		tui_text(ya + 1, x0 + mc, w - mc, m);
	int rc = cols - (int)strlen(r);
	if (rc > mc + (int)strlen(m))
		tui_text(ya + 1, x0 + rc, w - rc, r);

	char sv[32], gv[32];
	int len;
	if (tui_solve_text(t, sv, gv, sizeof sv))
		len = snprintf(buf, sizeof buf, "S standard %s  G gilbert %s", sv, gv);
	else
		len = snprintf(buf, sizeof buf, "S G: %s", sv);
	if (wall->ntests && len > 0 && (size_t)len < sizeof buf)
		snprintf(buf + len, sizeof buf - (size_t)len, "  T tests (%d)",
			 wall->ntests);
	tui_text(ya + 2, x0, w, buf);
}
