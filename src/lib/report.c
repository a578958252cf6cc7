/*
 * report.c - the paper's figures (cairo); see report.h for what is
 * written and docs/report.md for how to read it.  The plotting kit
 * (axes, text, colours, the SVG text layer) is plot.c; report.md is
 * written by report_md.c.
 *
 * Who calls it: the `report` and `sweep` commands.  Flow: report_write()
 * computes everything once into a `struct rctx` (report_fig.h: sorted
 * loads, summaries, KS test, fits, the common classes, the plot
 * ranges), then for each figure and each format opens a cairo surface,
 * calls the figure's draw function and closes it, all in a staging
 * directory published at the end.  The draw functions only read the
 * rctx: the three formats are the same drawing.
 *
 * Drawing is in points (1/72 in): a figure is 480 pt wide (about 170 mm,
 * an A4 text width) with 10-12 pt text, so it reads in print at its
 * natural size and on a projector; PNGs are rendered at 2.5 px per
 * point.  Colours are the Okabe-Ito palette (safe for the common colour
 * vision deficiencies): the model in vermillion and the tests in black,
 * as in the paper, the single-solution methods in blue, bluish green and
 * reddish purple, intervals in orange.
 */
#include <cairo.h>
#include <cairo-pdf.h>
#include <cairo-svg.h>
#include <dirent.h>
#include <errno.h>
#include <limits.h>
#include <fontconfig/fontconfig.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <gsl/gsl_cdf.h>

#include "report_fig.h"
#include "slipwall/report.h"
#include "slipwall/sys.h"
#include "slipwall/stats.h"
#include "slipwall/text.h"

#define NGRID 400		/* points of a density curve */
#define NCONV 400		/* checkpoints of the convergence curve */


void report_load_unit(const struct wall *w, char *axis, size_t len,
		      const char **unit)
{
	struct wall_quantity q;
	wall_quantity(w, &q);
	snprintf(axis, len, "%s", q.axis);
	*unit = *q.unit ? " N" : "";
}

/* Relative frequencies of sorted x in nb classes [lo + k w, lo + (k+1) w),
 * the last one closed. */
static void class_freq(const double *x, size_t n, double lo, double w, int nb,
		       double *f)
{
	for (int k = 0; k < nb; k++)
		f[k] = 0;
	for (size_t i = 0; i < n; i++)
		f[stats_bin(x[i], lo, w, nb)] += 1.0 / (double)n;
}

static void convergence(struct rctx *c)
{
	const double *lam = c->in->lam;
	size_t n = c->n;
	int K = n < NCONV ? (int)n : NCONV;
	c->nconv = K;
	c->cn = sw_xmalloc(sizeof(double) * (size_t)K);
	c->cp = sw_xmalloc(sizeof(double) * (size_t)K);
	c->clo = sw_xmalloc(sizeof(double) * (size_t)K);
	c->chi = sw_xmalloc(sizeof(double) * (size_t)K);
	/* a sorted prefix grown by merging each new chunk */
	double *s = sw_xmalloc(sizeof(double) * n), *tmp =
		sw_xmalloc(sizeof(double) * n);
	size_t have = 0;
	for (int k = 0; k < K; k++) {
		size_t upto = (size_t)llround((double)(k + 1) * (double)n /
					      (double)K);
		size_t add = upto - have;
		memcpy(tmp, lam + have, sizeof(double) * add);
		stats_sort(tmp, add);
		/* merge s[0..have) and tmp[0..add) from the top */
		size_t i = have, j = add, o = upto;
		while (j > 0) {
			if (i > 0 && s[i - 1] > tmp[j - 1])
				s[--o] = s[--i];
			else
				s[--o] = tmp[--j];
		}
		have = upto;
		size_t lo, hi;
		c->cn[k] = (double)have;
		c->cp[k] = stats_quantile_sorted(s, have, 0.05);
		if (stats_quantile_ci_ranks(have, 0.05, 0.99, &lo, &hi) == 0) {
			c->clo[k] = s[lo - 1];
			c->chi[k] = s[hi - 1];
		} else {
			c->clo[k] = c->chi[k] = NAN;
		}
	}
	free(s);
	free(tmp);
}

/* The drawn extent of Fig. 6, m: the blocks, a margin for the moved
 * outlines (0.35 mean block size, see draw_mech_panel) and the load
 * arrows (LOAD_ARROW of the wall's size). */
#define LOAD_ARROW 0.2
static void wall_extent(struct rctx *c)
{
	const struct wall *w = c->w;
	c->wx0 = c->wy0 = HUGE_VAL;
	c->wx1 = c->wy1 = -HUGE_VAL;
	for (int b = 0; b < w->nblocks; b++)
		for (int i = 0; i < w->blocks[b].nv; i++) {
			double x = w->blocks[b].xy[2 * i];
			double y = w->blocks[b].xy[2 * i + 1];
			c->wx0 = fmin(c->wx0, x);
			c->wx1 = fmax(c->wx1, x);
			c->wy0 = fmin(c->wy0, y);
			c->wy1 = fmax(c->wy1, y);
		}
	c->wsize = fmax(c->wx1 - c->wx0, c->wy1 - c->wy0);
	double L = LOAD_ARROW * c->wsize;
	for (int i = 0; i < w->nloads; i++) {
		const struct wall_load *ld = &w->loads[i];
		if (ld->kind != LOAD_POINT)
			continue;
		for (int sgn = -1; sgn <= 1; sgn += 2) {
			double x = ld->at[0] + sgn * L * ld->dir[0];
			double y = ld->at[1] + sgn * L * ld->dir[1];
			c->wx0 = fmin(c->wx0, x);
			c->wx1 = fmax(c->wx1, x);
			c->wy0 = fmin(c->wy0, y);
			c->wy1 = fmax(c->wy1, y);
		}
	}
	double m = 0.4 * w->mean_size;
	c->wx0 -= m;
	c->wx1 += m;
	c->wy1 += m;
}

static void rctx_free(struct rctx *c)
{
	if (c->fams.w)
		family_set_free(&c->fams);
	free(c->sol);
	free(c->lam);
	free(c->tst);
	free(c->fm);
	free(c->ft);
	free(c->cn);
	free(c->cp);
	free(c->clo);
	free(c->chi);
}

/* The spread to give an axis over data in [lo, hi]: hi - lo, unless the
 * data are (to round-off) one value - a sliding block gives the same
 * load in every sample - when a range of 20 % of the value is shown.  A
 * range of 1e-13 at 204 N would make tick steps smaller than one ulp. */
static double data_span(double lo, double hi)
{
	double span = hi - lo;
	if (!(span > 1e-9 * fmax(fabs(lo), fabs(hi))))
		span = fmax(fabs(hi) * 0.2, 1e-9);
	return span;
}

static enum sw_status rctx_init(struct rctx *c, const struct report_input *in,
				const struct report_opts *o, char *err)
{
	memset(c, 0, sizeof *c);
	c->in = in;
	c->w = in->w;
	if (!in->w || !in->w->finished)
		return sw_fail(err, SW_EINPUT, "report: no finished wall");
	if (!in->lam || in->nlam < 1)
		return sw_fail(err, SW_EINPUT, "report: no accepted sample: "
			       "nothing to plot");
	for (long i = 0; i < in->nlam; i++)
		if (!isfinite(in->lam[i]))
			return sw_fail(err, SW_EINPUT, "report: accepted load %ld "
				       "is not a number", i + 1);
	for (long i = 0; i < in->ntests; i++)
		if (!isfinite(in->tests[i]))
			return sw_fail(err, SW_EINPUT, "report: test load %ld is "
				       "not a number", i + 1);
	report_load_unit(in->w, c->axis, sizeof c->axis, &c->unit);
	struct wall_quantity q;
	wall_quantity(in->w, &q);
	c->sol = sw_xcalloc((size_t)in->nsol + 1, sizeof *c->sol);
	for (int i = 0; i < in->nsol; i++) {
		c->sol[i] = in->sol[i];
		c->sol[i].lambda *= q.scale;
	}
	c->n = (size_t)in->nlam;
	c->lam = stats_sorted_copy(in->lam, c->n);
	stats_summarise(c->lam, c->n, &c->ms);
	stats_normal_fit(c->lam, c->n, &c->mmu, &c->msd);
	c->bw = stats_kde_bandwidth(c->lam, c->n);
	c->tmu = c->tsd = NAN;
	if (in->tests && in->ntests > 0) {
		c->m = (size_t)in->ntests;
		c->tst = stats_sorted_copy(in->tests, c->m);
		stats_summarise(c->tst, c->m, &c->ts);
		stats_normal_fit(c->tst, c->m, &c->tmu, &c->tsd);
		c->ks_ok = stats_ks2(c->lam, c->n, c->tst, c->m, &c->ks) == 0;
	}

	/* the load range: both samples, with a margin, never below 0 */
	double lo = c->lam[0], hi = c->lam[c->n - 1];
	if (c->m) {
		lo = fmin(lo, c->tst[0]);
		hi = fmax(hi, c->tst[c->m - 1]);
	}
	double span = data_span(lo, hi);
	/* the KDE tails need about 3 bandwidths */
	double marg = fmax(0.12 * span, isfinite(c->bw) ? 3 * c->bw : 0);
	c->x0 = fmax(0, lo - marg);
	c->x1 = hi + marg;

	/* the classes: Freedman-Diaconis width of the tests (the coarser
	 * sample) or of the model, aligned on the lowest value */
	double bw = c->m >= 2 ? stats_fd_width(c->tst, c->m) :
		    stats_fd_width(c->lam, c->n);
	if (!(bw > 0))
		bw = span / 10;
	if ((hi - lo) / bw > 200)
		bw = (hi - lo) / 200;
	c->nb = (int)ceil((hi - lo) / bw);
	if (c->nb < 1)
		c->nb = 1;
	c->blo = hi > lo ? lo : lo - bw / 2;
	c->bw_class = bw;
	c->fm = sw_xcalloc((size_t)c->nb, sizeof(double));
	class_freq(c->lam, c->n, c->blo, bw, c->nb, c->fm);
	if (c->m) {
		c->ft = sw_xcalloc((size_t)c->nb, sizeof(double));
		class_freq(c->tst, c->m, c->blo, bw, c->nb, c->ft);
	}

	convergence(c);
	wall_extent(c);
	if (in->mech && in->mech->nmech > 0) {
		int max = o->max_mechanisms;
		if (max < 1)
			max = 1;
		if (max > MAX_PANELS)
			max = MAX_PANELS;
		family_set_init(&c->fams, c->w);
		family_update(&c->fams, in->mech);
		c->ntop = family_top(&c->fams, c->topfam, max);
		for (int i = 0; i < c->ntop; i++)
			family_mechs(&c->fams, in->mech, c->topfam[i],
				     &c->top[i], 1);
	}
	return SW_OK;
}

/* Class heights h[k] over the classes of c as a step outline (filled
 * when alpha > 0). */
static void steps(cairo_t *cr, const struct axes *a, const struct rctx *c,
		  const double *h, double scale, struct rgb col, double alpha,
		  double lw)
{
	double y0 = plot_y(a, 0);
	cairo_move_to(cr, plot_x(a, c->blo), y0);
	for (int k = 0; k < c->nb; k++) {
		double xl = c->blo + k * c->bw_class, xr = xl + c->bw_class;
		cairo_line_to(cr, plot_x(a, xl), plot_y(a, h[k] * scale));
		cairo_line_to(cr, plot_x(a, xr), plot_y(a, h[k] * scale));
	}
	cairo_line_to(cr, plot_x(a, c->blo + c->nb * c->bw_class), y0);
	if (alpha > 0) {
		plot_rgb(cr, col, alpha);
		cairo_fill_preserve(cr);
	}
	cairo_set_dash(cr, NULL, 0, 0);
	plot_rgb(cr, col, 1);
	cairo_set_line_width(cr, lw);
	cairo_stroke(cr);
}

/* ---- Fig. 8 (left): relative frequencies -------------------------------- */

static void draw_frequencies(struct fig *f, const struct rctx *c)
{
	cairo_t *cr = f->cr;
	struct axes a = plot_box(2);
	a.x0 = c->x0;
	a.x1 = c->x1;
	a.y0 = 0;
	a.y1 = 1.12 * fmax(plot_max(c->fm, c->nb), c->ft ? plot_max(c->ft, c->nb) : 0);
	if (!(a.y1 > 0))
		a.y1 = 1;
	plot_white(f);
	plot_clip(cr, &a);
	steps(cr, &a, c, c->fm, 1, C_MODEL, 0.35, 1.6);
	if (c->ft)
		steps(cr, &a, c, c->ft, 1, C_TESTS, 0, 1.6);
	cairo_restore(cr);
	plot_axes(f, &a, c->axis, "relative frequency",
		  c->m ? "Relative frequencies: model and tests" :
		  "Relative frequencies: model (no tests)", 0);
	char lm[96], lt[96];
	snprintf(lm, sizeof lm, "model (%zu samples)", c->n);
	snprintf(lt, sizeof lt, "tests (%zu)", c->m);
	struct lg_item it[2] = {{LG_BAR, C_MODEL, lm}, {LG_THIN, C_TESTS, lt}};
	plot_legend(f, &a, it, c->m ? 2 : 1, c->ms.p50 > (c->x0 + c->x1) / 2);
	double y = PLOT_H + 6;
	char s[256];
	snprintf(s, sizeof s, "Classes of width %.4g%s from %.5g%s (%d classes, "
		 "Freedman-Diaconis width of the %s).", c->bw_class, c->unit,
		 c->blo, c->unit, c->nb, c->m >= 2 ? "tests" : "model");
	plot_caption(f, y, s);
	/* a standard deviation of one value is shown as "-" */
	char sm[32] = "-", st[32] = "-";
	if (isfinite(c->ms.std))
		snprintf(sm, sizeof sm, "%.4g%s", c->ms.std, c->unit);
	if (isfinite(c->ts.std))
		snprintf(st, sizeof st, "%.4g%s", c->ts.std, c->unit);
	snprintf(s, sizeof s, "Model: mean %.5g%s, std %s.", c->ms.mean,
		 c->unit, sm);
	if (c->m)
		snprintf(s + strlen(s), sizeof s - strlen(s),
			 "  Tests: mean %.5g%s, std %s.", c->ts.mean, c->unit,
			 st);
	plot_caption(f, y + 13, s);
}

/* ---- Fig. 8 (centre, right): KDE and normals ------------------------------ */

static double normal_pdf(double x, double mu, double sd)
{
	double z = (x - mu) / sd;
	return exp(-0.5 * z * z) / (sd * sqrt(2 * M_PI));
}

/* A legend's "WHO, normal (mean, sd)"; with no spread (one value, or
 * every value equal) no normal is drawn, and the legend says why. */
static void normal_label(char *buf, size_t len, const char *who, double mu,
			 double sd)
{
	if (sd > 0)
		snprintf(buf, len, "%s, normal (%.4g, %.3g)", who, mu, sd);
	else
		snprintf(buf, len, "%s, no normal (%s)", who,
			 isfinite(sd) ? "every value equal" : "one value");
}

static void density_grid(const struct rctx *c, double x0, double x1, double *g,
			 double *kde, double *nm, double *nt)
{
	for (int i = 0; i < NGRID; i++)
		g[i] = x0 + (x1 - x0) * i / (NGRID - 1);
	stats_kde(c->lam, c->n, c->bw, 1, g, NGRID, kde);
	for (int i = 0; i < NGRID; i++) {
		nm[i] = c->msd > 0 ? normal_pdf(g[i], c->mmu, c->msd) : NAN;
		nt[i] = c->tsd > 0 ? normal_pdf(g[i], c->tmu, c->tsd) : NAN;
	}
}

/* The model's KDE, and the tests' normal fit (tests) or else the
 * model's, on the grid g. */
static void density_curves(cairo_t *cr, const struct axes *a,
			   const double *g, const double *kde,
			   const double *nm, const double *nt, int tests)
{
	plot_style(cr, LG_LINE, C_MODEL);
	plot_curve(cr, a, g, kde, NGRID);
	if (tests) {
		plot_style(cr, LG_LINE, C_TESTS);
		plot_curve(cr, a, g, nt, NGRID);
	} else {
		plot_style(cr, LG_DASH, C_MODEL);
		plot_curve(cr, a, g, nm, NGRID);
	}
}

static void draw_densities(struct fig *f, const struct rctx *c)
{
	cairo_t *cr = f->cr;
	plot_white(f);
	double g[NGRID], kde[NGRID], nm[NGRID], nt[NGRID];
	density_grid(c, c->x0, c->x1, g, kde, nm, nt);
	int tests = c->m >= 2 && c->tsd > 0;

	/* top: the KDE of the model and the normal of the tests */
	struct axes a = plot_box(0);
	a.x0 = c->x0;
	a.x1 = c->x1;
	a.y0 = 0;
	a.y1 = 1.12 * fmax(plot_max(kde, NGRID), fmax(tests ? plot_max(nt, NGRID) : 0,
						     plot_max(nm, NGRID)));
	if (!(a.y1 > 0))
		a.y1 = 1;
	plot_clip(cr, &a);
	density_curves(cr, &a, g, kde, nm, nt, tests);
	cairo_set_dash(cr, NULL, 0, 0);
	cairo_restore(cr);
	char yl[64];
	/* per N, or of no unit like the coefficient it is of */
	snprintf(yl, sizeof yl, "probability density%s",
		 *c->unit ? " (1/N)" : "");
	plot_axes(f, &a, c->axis, yl, tests ?
		  "Model KDE and best-fit normal of the tests" :
		  "Model KDE and its best-fit normal (no tests)", 0);
	char l1[96], l2[96];
	snprintf(l1, sizeof l1, "model, Gaussian KDE (h = %.3g)", c->bw);
	if (tests)
		normal_label(l2, sizeof l2, "tests", c->tmu, c->tsd);
	else
		normal_label(l2, sizeof l2, "model", c->mmu, c->msd);
	struct lg_item it[2] = {{LG_LINE, C_MODEL, l1},
				{tests ? LG_LINE : LG_DASH,
				 tests ? C_TESTS : C_MODEL, l2}};
	plot_legend(f, &a, it, 2, c->ms.p50 > (c->x0 + c->x1) / 2);

	/* bottom: both normals grouped in the tests' number of classes */
	struct axes b = plot_box(0);
	b.y += PLOT_H;
	int k = tests ? (int)c->m : c->nb;
	if (k < 2)
		k = 2;
	double w = (c->x1 - c->x0) / k;
	double *pm = sw_xmalloc(sizeof(double) * (size_t)k);
	double *pt = sw_xmalloc(sizeof(double) * (size_t)k);
	for (int i = 0; i < k; i++) {
		double l = c->x0 + i * w, r = l + w;
		pm[i] = c->msd > 0 ? gsl_cdf_gaussian_P(r - c->mmu, c->msd) -
			gsl_cdf_gaussian_P(l - c->mmu, c->msd) : NAN;
		pt[i] = tests ? gsl_cdf_gaussian_P(r - c->tmu, c->tsd) -
			gsl_cdf_gaussian_P(l - c->tmu, c->tsd) : NAN;
	}
	b.x0 = c->x0;
	b.x1 = c->x1;
	b.y0 = 0;
	b.y1 = 1.15 * fmax(plot_max(pm, k), plot_max(pt, k));
	if (!(b.y1 > 0))
		b.y1 = 1;
	plot_clip(cr, &b);
	for (int pass = 0; pass < (tests ? 2 : 1); pass++) {
		const double *p = pass ? pt : pm;
		double off = tests ? (pass ? 0.5 : 0.08) : 0.08;
		double bwid = tests ? 0.42 : 0.84;
		for (int i = 0; i < k; i++) {
			if (!isfinite(p[i]))
				continue;
			double l = c->x0 + (i + off) * w;
			cairo_rectangle(cr, plot_x(&b, l), plot_y(&b, p[i]),
					plot_x(&b, l + bwid * w) - plot_x(&b, l),
					plot_y(&b, 0) - plot_y(&b, p[i]));
		}
		plot_rgb(cr, pass ? C_TESTS : C_MODEL, pass ? 0.75 : 0.6);
		cairo_fill(cr);
	}
	cairo_restore(cr);
	char title[128];
	snprintf(title, sizeof title, "Best-fit normals in %d classes%s",
		 k, tests ? " (the number of tests)" : "");
	plot_axes(f, &b, c->axis, "probability per class", title, 0);
	char l3[96], l4[96];
	normal_label(l3, sizeof l3, "model", c->mmu, c->msd);
	normal_label(l4, sizeof l4, "tests", c->tmu, c->tsd);
	struct lg_item it2[2] = {{LG_BAR, C_MODEL, l3}, {LG_BAR, C_TESTS, l4}};
	plot_legend(f, &b, it2, tests ? 2 : 1, c->ms.p50 > (c->x0 + c->x1) / 2);
	free(pm);
	free(pt);
}

/* ---- Fig. 9: relative cumulative frequencies ------------------------------ */

static void ecdf(cairo_t *cr, const struct axes *a, const double *x, size_t n)
{
	cairo_move_to(cr, plot_x(a, a->x0), plot_y(a, 0));
	for (size_t i = 0; i < n; i++) {
		cairo_line_to(cr, plot_x(a, x[i]), plot_y(a, (double)i / (double)n));
		while (i + 1 < n && x[i + 1] == x[i])
			i++;
		cairo_line_to(cr, plot_x(a, x[i]), plot_y(a, (double)(i + 1) /
						    (double)n));
	}
	cairo_line_to(cr, plot_x(a, a->x1), plot_y(a, 1));
	cairo_stroke(cr);
}

static void draw_cumulative(struct fig *f, const struct rctx *c)
{
	cairo_t *cr = f->cr;
	plot_white(f);
	struct axes a = plot_box(4);
	a.x0 = c->x0;
	a.x1 = c->x1;
	a.y0 = 0;
	a.y1 = 1.04;
	plot_clip(cr, &a);
	plot_style(cr, LG_LINE, C_MODEL);
	cairo_set_line_width(cr, 2);
	ecdf(cr, &a, c->lam, c->n);
	if (c->m) {
		plot_style(cr, LG_THIN, C_TESTS);
		cairo_set_line_width(cr, 1.4);
		ecdf(cr, &a, c->tst, c->m);
	}
	cairo_restore(cr);
	plot_axes(f, &a, c->axis, "relative cumulative frequency",
		  c->m ? "Relative cumulative frequencies: model and tests" :
		  "Relative cumulative frequencies: model (no tests)", 0);
	char lm[96], lt[96];
	snprintf(lm, sizeof lm, "model (%zu)", c->n);
	snprintf(lt, sizeof lt, "tests (%zu)", c->m);
	struct lg_item it[2] = {{LG_LINE, C_MODEL, lm}, {LG_THIN, C_TESTS, lt}};
	plot_legend(f, &a, it, c->m ? 2 : 1, 1);
	double y = PLOT_H + 6;
	char s[256];
	if (c->ks_ok) {
		snprintf(s, sizeof s, "Two-sample Kolmogorov-Smirnov test, x = "
			 "model, y = tests, %s p-values:", c->ks.exact ? "exact" :
			 "asymptotic");
		plot_caption(f, y, s);
		snprintf(s, sizeof s, "D = %.4g (D+ = %.4g, D- = %.4g); "
			 "p two-sided = %.4g (H1: they differ)", c->ks.d,
			 c->ks.d_plus, c->ks.d_minus, c->ks.p_two_sided);
		plot_caption(f, y + 13, s);
		snprintf(s, sizeof s, "p greater = %.4g (H1: model < tests)",
			 c->ks.p_greater);
		plot_caption(f, y + 26, s);
		snprintf(s, sizeof s, "p less = %.4g (H0: model <= tests; "
			 "the paper's 0.994 is this one)", c->ks.p_less);
		plot_caption(f, y + 39, s);
	} else {
		plot_caption(f, y, "No Kolmogorov-Smirnov test: the wall has no "
			     "experimental loads.");
	}
}

/* ---- the fragility curve ---------------------------------------------------- */

/* The empirical CDF of the model's loads is the estimated probability of
 * collapse at each load; the Dvoretzky-Kiefer-Wolfowitz band F +- eps
 * (clipped to [0, 1]) holds the true curve at every load at once with
 * probability >= 99 %.  A wall's design load is marked with its exact
 * binomial interval. */
static void dkw_edge(cairo_t *cr, const struct axes *a, const double *x,
		     size_t n, double eps, int upper)
{
	double f0 = upper ? fmin(1, eps) : 0;
	cairo_line_to(cr, plot_x(a, a->x0), plot_y(a, f0));
	for (size_t i = 0; i < n; i++) {
		double before = (double)i / (double)n;
		while (i + 1 < n && x[i + 1] == x[i])
			i++;
		double after = (double)(i + 1) / (double)n;
		before = upper ? fmin(1, before + eps) : fmax(0, before - eps);
		after = upper ? fmin(1, after + eps) : fmax(0, after - eps);
		cairo_line_to(cr, plot_x(a, x[i]), plot_y(a, before));
		cairo_line_to(cr, plot_x(a, x[i]), plot_y(a, after));
	}
	cairo_line_to(cr, plot_x(a, a->x1), plot_y(a, upper ? 1 : fmax(0, 1 - eps)));
}

static void draw_fragility(struct fig *f, const struct rctx *c)
{
	cairo_t *cr = f->cr;
	double eps = stats_dkw_eps(c->n, 0.99);
	double dl = c->w->design_load;
	plot_white(f);
	struct axes a = plot_box(3);
	a.x0 = c->x0;
	a.x1 = c->x1;
	a.y0 = 0;
	a.y1 = 1.04;
	plot_clip(cr, &a);
	/* the band: the upper edge left to right, the lower edge back */
	cairo_new_path(cr);
	dkw_edge(cr, &a, c->lam, c->n, eps, 1);
	cairo_path_t *up = cairo_copy_path(cr);
	cairo_new_path(cr);
	dkw_edge(cr, &a, c->lam, c->n, eps, 0);
	cairo_path_t *down = cairo_copy_path(cr);
	cairo_new_path(cr);
	cairo_append_path(cr, up);
	for (int i = down->num_data - 2; i >= 0; ) {
		/* walk the lower edge backwards: every element is a
		 * move/line of one point (2 data each) */
		cairo_path_data_t *d = &down->data[i];
		cairo_line_to(cr, d[1].point.x, d[1].point.y);
		i -= 2;
	}
	cairo_close_path(cr);
	plot_rgb(cr, C_ORANGE, 0.35);
	cairo_fill(cr);
	cairo_path_destroy(up);
	cairo_path_destroy(down);
	plot_style(cr, LG_LINE, C_MODEL);
	cairo_set_line_width(cr, 2);
	ecdf(cr, &a, c->lam, c->n);
	double p = NAN, lo = NAN, hi = NAN;
	if (dl > 0) {
		size_t k = stats_count_le(c->lam, c->n, dl);
		p = (double)k / (double)c->n;
		stats_binomial_ci(k, c->n, 0.99, &lo, &hi);
		plot_style(cr, LG_DASH, C_BLUE);
		cairo_move_to(cr, plot_x(&a, dl), plot_y(&a, 0));
		cairo_line_to(cr, plot_x(&a, dl), plot_y(&a, 1.04));
		cairo_stroke(cr);
		cairo_set_dash(cr, NULL, 0, 0);
		cairo_set_line_width(cr, 3);
		cairo_move_to(cr, plot_x(&a, dl), plot_y(&a, lo));
		cairo_line_to(cr, plot_x(&a, dl), plot_y(&a, hi));
		cairo_stroke(cr);
	}
	cairo_restore(cr);
	struct wall_quantity q;
	wall_quantity(c->w, &q);
	char title[96];
	snprintf(title, sizeof title, "Fragility: P(%s <= %s)", q.name,
		 *q.unit ? "load" : "value");
	plot_axes(f, &a, c->axis, "probability of collapse", title, 0);
	char lm[96], lb[96], ld[96];
	snprintf(lm, sizeof lm, "model: empirical CDF (%zu)", c->n);
	snprintf(lb, sizeof lb, "99 %% simultaneous band (DKW)");
	snprintf(ld, sizeof ld, "design load, 99 %% interval");
	struct lg_item it[3] = {{LG_LINE, C_MODEL, lm}, {LG_BAND, C_ORANGE, lb},
				{LG_DASH, C_BLUE, ld}};
	plot_legend(f, &a, it, dl > 0 ? 3 : 2, LG_BOTTOM);
	double y = PLOT_H + 6;
	char s[256];
	snprintf(s, sizeof s, "The share of the %zu accepted samples whose "
		 "collapse load is at most the load.", c->n);
	plot_caption(f, y, s);
	snprintf(s, sizeof s, "Band: +-%.4g (Dvoretzky-Kiefer-Wolfowitz): "
		 "the true curve lies in it at every load, at 99 %%.", eps);
	plot_caption(f, y + 13, s);
	if (dl > 0)
		snprintf(s, sizeof s, "Design load %.5g%s: P = %.4g, 99 %% "
			 "interval [%.4g, %.4g] (exact binomial).", dl, c->unit,
			 p, lo, hi);
	else
		snprintf(s, sizeof s, "No design load (analysis.design_load) "
			 "in the wall file.");
	plot_caption(f, y + 26, s);
}

/* ---- Fig. 10: the model against the single solutions ---------------------- */

static const struct rgb *method_colour(const char *m)
{
	if (!strcmp(m, "standard"))
		return &C_BLUE;
	if (!strcmp(m, "gilbert"))
		return &C_GREEN;
	return &C_PURPLE;
}

/* Coincident lines stay visible: standard solid, gilbert dashed, global
 * dotted, drawn in that order. */
static void method_dash(cairo_t *cr, const char *m)
{
	static const double dash[] = {7, 5}, dot[] = {2, 4};
	if (!strcmp(m, "gilbert"))
		cairo_set_dash(cr, dash, 2, 0);
	else if (!strcmp(m, "global"))
		cairo_set_dash(cr, dot, 2, 0);
	else
		cairo_set_dash(cr, NULL, 0, 0);
}

/* Fig. 10: the labels of the single solutions' lines, above the plot,
 * staggered when close. */
static void single_labels(struct fig *f, const struct rctx *c,
			  const struct axes *pa)
{
	const struct report_input *in = c->in;
	const struct axes a = *pa;
	double lastx = -1e9;
	int row = 0;
	for (int i = 0; i < in->nsol; i++) {
		const struct report_solution *s = &c->sol[i];
		if (!s->found || !isfinite(s->lambda))
			continue;
		double x = fmin(fmax(plot_x(&a, s->lambda), a.x + 1), a.x + a.w - 1);
		row = fabs(x - lastx) < 120 ? row + 1 : 0;
		lastx = x;
		plot_rgb(f->cr, *method_colour(s->method), 1);
		double ax = x > a.x + a.w - 100 ? 1 : x < a.x + 100 ? 0 : 0.5;
		plot_text(f, x, a.y - 3 - 12 * (row % 2), 9.5, 1, ax, 1, 0,
			  "%s %.5g%s", s->method, s->lambda, c->unit);
	}
}

/* Fig. 10's legend; tests: the tests' normal fit is drawn. */
static void single_legend(struct fig *f, const struct rctx *c,
			  const struct axes *a, int tests)
{
	struct lg_item it[6];
	int n = 0;
	char l1[64], l2[64], l3[96];
	it[n++] = (struct lg_item){LG_THIN, C_MODEL, "model frequencies"};
	if (c->ft)
		it[n++] = (struct lg_item){LG_THIN, C_TESTS, "test frequencies"};
	snprintf(l1, sizeof l1, "model KDE");
	it[n++] = (struct lg_item){LG_LINE, C_MODEL, l1};
	snprintf(l2, sizeof l2, tests ? "tests, normal fit" : "model, normal fit");
	it[n++] = (struct lg_item){tests ? LG_LINE : LG_DASH,
				   tests ? C_TESTS : C_MODEL, l2};
	snprintf(l3, sizeof l3, "model p05%s", c->ms.has_ci ?
		 " and its 99 % interval" : "");
	it[n++] = (struct lg_item){c->ms.has_ci ? LG_BAND : LG_DASH, C_ORANGE, l3};
	if (c->m && c->ts.has_ci)
		it[n++] = (struct lg_item){LG_BAND, C_GREY,
					   "tests p05, 99 % interval"};
	plot_legend(f, a, it, n, c->ms.p50 > (a->x0 + a->x1) / 2);

}

/* Fig. 10's captions: the two p05 and the solutions not shown. */
static void single_captions(struct fig *f, const struct rctx *c)
{
	const struct report_input *in = c->in;
	double y = plot_height(3) - 13 * 3;
	char s[256];
	if (c->ms.has_ci)
		snprintf(s, sizeof s, "Model p05 = %.5g%s, 99 %% interval "
			 "[%.5g, %.5g]%s (%zu accepted samples).", c->ms.p05,
			 c->unit, c->ms.p05_lo, c->ms.p05_hi, c->unit, c->n);
	else
		snprintf(s, sizeof s, "Model p05 = %.5g%s, no 99 %% interval "
			 "(needs at least 90 samples, has %zu).", c->ms.p05,
			 c->unit, c->n);
	plot_caption(f, y, s);
	if (c->m && c->ts.has_ci)
		snprintf(s, sizeof s, "Tests p05 = %.5g%s, 99 %% interval "
			 "[%.5g, %.5g]%s (%zu tests).", c->ts.p05, c->unit,
			 c->ts.p05_lo, c->ts.p05_hi, c->unit, c->m);
	else if (c->m)
		snprintf(s, sizeof s, "Tests p05 = %.5g%s, no distribution-free "
			 "99 %% interval (needs 90 tests, has %zu).", c->ts.p05,
			 c->unit, c->m);
	else
		snprintf(s, sizeof s, "No experimental loads: the model alone.");
	plot_caption(f, y + 13, s);
	s[0] = 0;
	for (int i = 0; i < in->nsol; i++) {
		const struct report_solution *so = &c->sol[i];
		if (so->found && isfinite(so->lambda))
			continue;
		snprintf(s + strlen(s), sizeof s - strlen(s), "%s%s: %s",
			 *s ? "; " : "Not shown: ", so->method,
			 so->ran ? (*so->note ? so->note : "no load") :
			 (*so->note ? so->note : "not run"));
	}
	if (*s)
		plot_caption(f, y + 26, s);
}

static void draw_single(struct fig *f, const struct rctx *c)
{
	cairo_t *cr = f->cr;
	const struct report_input *in = c->in;
	plot_white(f);
	struct axes a = plot_box(3);
	a.y += 14;	/* room for the line labels */
	a.h -= 14;
	double lo = c->x0, hi = c->x1;
	for (int i = 0; i < in->nsol; i++)
		if (c->sol[i].found && isfinite(c->sol[i].lambda)) {
			lo = fmin(lo, c->sol[i].lambda);
			hi = fmax(hi, c->sol[i].lambda);
		}
	double span = hi - lo;
	a.x0 = fmax(0, lo - (lo < c->x0 ? 0.05 * span : 0));
	a.x1 = hi + (hi > c->x1 ? 0.08 * span : 0);
	double g[NGRID], kde[NGRID], nm[NGRID], nt[NGRID];
	density_grid(c, a.x0, a.x1, g, kde, nm, nt);
	int tests = c->m >= 2 && c->tsd > 0;
	double scale = 1 / c->bw_class;	/* relative frequency -> density */
	a.y0 = 0;
	a.y1 = 1.12 * fmax(fmax(plot_max(kde, NGRID), plot_max(c->fm, c->nb) * scale),
			   fmax(tests ? plot_max(nt, NGRID) : plot_max(nm, NGRID),
				c->ft ? plot_max(c->ft, c->nb) * scale : 0));
	if (!(a.y1 > 0))
		a.y1 = 1;

	plot_clip(cr, &a);
	/* the 99 % interval of the characteristic values */
	if (c->m && c->ts.has_ci) {
		plot_rgb(cr, C_GREY, 0.25);
		cairo_rectangle(cr, plot_x(&a, c->ts.p05_lo), a.y,
				plot_x(&a, c->ts.p05_hi) - plot_x(&a, c->ts.p05_lo),
				a.h);
		cairo_fill(cr);
	}
	if (c->ms.has_ci) {
		plot_rgb(cr, C_ORANGE, 0.35);
		cairo_rectangle(cr, plot_x(&a, c->ms.p05_lo), a.y,
				fmax(plot_x(&a, c->ms.p05_hi) -
				     plot_x(&a, c->ms.p05_lo), 1), a.h);
		cairo_fill(cr);
	}
	steps(cr, &a, c, c->fm, scale, C_MODEL, 0, 0.8);
	if (c->ft)
		steps(cr, &a, c, c->ft, scale, C_TESTS, 0, 0.8);
	density_curves(cr, &a, g, kde, nm, nt, tests);
	/* p05 */
	plot_style(cr, LG_DASH, C_ORANGE);
	cairo_set_line_width(cr, 1.6);
	cairo_move_to(cr, plot_x(&a, c->ms.p05), a.y);
	cairo_line_to(cr, plot_x(&a, c->ms.p05), a.y + a.h);
	cairo_stroke(cr);
	/* the single solutions */
	for (int i = 0; i < in->nsol; i++) {
		const struct report_solution *s = &c->sol[i];
		if (!s->found || !isfinite(s->lambda))
			continue;
		plot_style(cr, LG_LINE, *method_colour(s->method));
		cairo_set_line_width(cr, 2.2);
		method_dash(cr, s->method);
		double x = plot_x(&a, s->lambda);
		x = fmin(fmax(x, a.x + 1), a.x + a.w - 1);
		cairo_move_to(cr, x, a.y);
		cairo_line_to(cr, x, a.y + a.h);
		cairo_stroke(cr);
	}
	cairo_set_dash(cr, NULL, 0, 0);
	cairo_restore(cr);
	char yl[64];
	/* per N, or of no unit like the coefficient it is of */
	snprintf(yl, sizeof yl, "probability density%s",
		 *c->unit ? " (1/N)" : "");
	plot_axes(f, &a, c->axis, yl, NULL, 0);
	plot_text(f, a.x, 16, 12, 1, 0, 1, 0, "%s",
		  "The model against the single-solution methods");
	single_labels(f, c, &a);
	single_legend(f, c, &a, tests);
	single_captions(f, c);
}

/* ---- the convergence of p05 ------------------------------------------------ */

static void draw_convergence(struct fig *f, const struct rctx *c)
{
	cairo_t *cr = f->cr;
	plot_white(f);
	struct axes a = plot_box(2);
	a.x0 = 0;
	a.x1 = (double)c->n;
	if (a.x1 < 1)
		a.x1 = 1;
	double lo = HUGE_VAL, hi = -HUGE_VAL;
	int first = c->nconv > 10 ? c->nconv / 20 : 0;	/* skip the start */
	for (int k = first; k < c->nconv; k++) {
		lo = fmin(lo, isfinite(c->clo[k]) ? c->clo[k] : c->cp[k]);
		hi = fmax(hi, isfinite(c->chi[k]) ? c->chi[k] : c->cp[k]);
	}
	double span = data_span(lo, hi);
	a.y0 = fmax(0, lo - 0.1 * span);
	a.y1 = hi + 0.1 * span;
	plot_clip(cr, &a);
	/* the band */
	int started = 0;
	for (int k = 0; k < c->nconv; k++) {
		if (!isfinite(c->clo[k]))
			continue;
		double x = plot_x(&a, c->cn[k]), y = plot_y(&a, c->chi[k]);
		if (!started)
			cairo_move_to(cr, x, y);
		else
			cairo_line_to(cr, x, y);
		started = 1;
	}
	for (int k = c->nconv - 1; k >= 0 && started; k--)
		if (isfinite(c->clo[k]))
			cairo_line_to(cr, plot_x(&a, c->cn[k]), plot_y(&a, c->clo[k]));
	if (started) {
		cairo_close_path(cr);
		plot_rgb(cr, C_ORANGE, 0.35);
		cairo_fill(cr);
	}
	/* the final value */
	plot_style(cr, LG_DASH, C_GREY);
	cairo_move_to(cr, a.x, plot_y(&a, c->ms.p05));
	cairo_line_to(cr, a.x + a.w, plot_y(&a, c->ms.p05));
	cairo_stroke(cr);
	plot_style(cr, LG_LINE, C_MODEL);
	cairo_set_line_width(cr, 1.8);
	plot_curve(cr, &a, c->cn, c->cp, c->nconv);
	cairo_restore(cr);
	plot_axes(f, &a, "accepted samples", c->axis,
		  "Convergence of the characteristic value (p05)", 1);
	struct lg_item it[2] = {{LG_LINE, C_MODEL, "running p05"},
				{LG_BAND, C_ORANGE, "99 % interval (from 90 samples)"}};
	plot_legend(f, &a, it, 2, LG_BOTTOM);
	double y = PLOT_H + 6;
	char s[256];
	if (c->ms.has_ci)
		snprintf(s, sizeof s, "Final p05 = %.5g%s, 99 %% interval [%.5g, "
			 "%.5g]%s (n = %zu; width %.3g %% of p05).",
			 c->ms.p05, c->unit, c->ms.p05_lo, c->ms.p05_hi, c->unit,
			 c->n, 100 * (c->ms.p05_hi - c->ms.p05_lo) / c->ms.p05);
	else
		snprintf(s, sizeof s, "Final p05 = %.5g%s after %zu accepted "
			 "samples (no interval below 90).", c->ms.p05, c->unit,
			 c->n);
	plot_caption(f, y, s);
	plot_caption(f, y + 13, "Distribution-free interval from order statistics "
		     "(docs/statistics.md).");
}

/* ---- Fig. 6: the mechanisms ------------------------------------------------ */

#define MECH_LEGEND 40.0

static void mech_layout(const struct rctx *c, int *cols, int *rows,
			double *pw, double *ph)
{
	int n = c->ntop;
	*cols = n <= 1 ? 1 : 2;
	*rows = (n + *cols - 1) / *cols;
	*pw = FIG_W / *cols;
	double ww = c->wx1 - c->wx0, wh = c->wy1 - c->wy0;
	double aspect = ww > 0 ? wh / ww : 1;
	if (aspect > 1.6)
		aspect = 1.6;
	if (aspect < 0.25)
		aspect = 0.25;
	*ph = (*pw - 24) * aspect + 54;
}

static double mech_height(const struct rctx *c)
{
	int cols, rows;
	double pw, ph;
	mech_layout(c, &cols, &rows, &pw, &ph);
	return 28 + rows * ph + MECH_LEGEND;
}

static struct rgb joint_colour(char j)
{
	switch (j) {
	case JOINT_SLIDES:
		return C_VERMILLION;
	case JOINT_HINGES:
		return C_ORANGE;
	case JOINT_HINGE_SLIDES:
		return C_PURPLE;
	default:
		return C_BLUE;
	}
}

static void joint_style(cairo_t *cr, char j)
{
	static const double dash[] = {3, 2};
	plot_rgb(cr, joint_colour(j), 1);
	cairo_set_line_width(cr, 2.6);
	if (j == JOINT_OPENS)
		cairo_set_dash(cr, dash, 2, 0);
	else
		cairo_set_dash(cr, NULL, 0, 0);
}

static void arrow(cairo_t *cr, double x0, double y0, double x1, double y1,
		  double head)
{
	double dx = x1 - x0, dy = y1 - y0, l = hypot(dx, dy);
	if (l < 1e-9)
		return;
	dx /= l;
	dy /= l;
	cairo_move_to(cr, x0, y0);
	cairo_line_to(cr, x1, y1);
	cairo_stroke(cr);
	cairo_move_to(cr, x1, y1);
	cairo_line_to(cr, x1 - head * dx - 0.45 * head * dy,
		      y1 - head * dy + 0.45 * head * dx);
	cairo_line_to(cr, x1 - head * dx + 0.45 * head * dy,
		      y1 - head * dy - 0.45 * head * dx);
	cairo_close_path(cr);
	cairo_fill(cr);
}

/* A mechanism panel's live loads as arrows; the wall's point (x, y)
 * is drawn at (ox + (x - wx0) s, oy + (wy1 - y) s). */
static void panel_loads(cairo_t *cr, const struct rctx *c, double ox,
			double oy, double s)
{
	const struct wall *w = c->w;
#define MX(x) (ox + ((x) - c->wx0) * s)
#define MY(y) (oy + (c->wy1 - (y)) * s)
	for (int i = 0; i < w->nloads; i++) {
		const struct wall_load *ld = &w->loads[i];
		if (ld->kind != LOAD_POINT)
			continue;
		double L = LOAD_ARROW * c->wsize * s;
		double x1 = MX(ld->at[0]), y1 = MY(ld->at[1]);
		double x0 = x1 - L * ld->dir[0], y0 = y1 + L * ld->dir[1];
		/* a pull is drawn from the point outwards */
		int pull = 0;
		for (int b = 0; b < w->nblocks; b++)
			if (b == ld->block && ld->at[0] * ld->dir[0] +
			    ld->at[1] * ld->dir[1] >= w->blocks[b].cx *
			    ld->dir[0] + w->blocks[b].cy * ld->dir[1])
				pull = 1;
		plot_rgb(cr, C_BLACK, 1);
		cairo_set_line_width(cr, 1.6);
		if (pull)
			arrow(cr, x1, y1, x1 + L * ld->dir[0], y1 - L * ld->dir[1], 7);
		else
			arrow(cr, x0, y0, x1, y1, 7);
	}
#undef MX
#undef MY
}

/* A mechanism panel's texts: its family's rank, share and blocks, its
 * range of loads, and the mechanism drawn (the family's most frequent). */
static void panel_caption(struct fig *f, const struct rctx *c, int rank,
			  const struct tally_mech *mk, double px, double py,
			  double ph)
{
	const struct tally *t = c->in->mech;
	const struct family *fa = &c->fams.fam[c->topfam[rank]];
	double pct = 100.0 * (double)fa->count / (double)(t->accepted ?
							  t->accepted : 1);
	char name[256];
	family_label(&c->fams, fa, name, sizeof name);
	plot_rgb(f->cr, C_BLACK, 1);
	plot_text(f, px + 12, py + 4, 10.5, 1, 0, 0, 0,
		  "#%d: %.1f %% (%ld of %ld), %d mechanism%s", rank + 1, pct,
		  fa->count, t->accepted, fa->nmech, fa->nmech > 1 ? "s" : "");
	char lo[32], hi[32];
	snprintf(lo, sizeof lo, "%.5g", fa->lam_lo);
	snprintf(hi, sizeof hi, "%.5g", fa->lam_hi);
	if (!strcmp(lo, hi))
		plot_text(f, px + 12, py + ph - 28, 9.5, 0, 0, 0, 0,
			  "λ = %.5g%s", fa->lam_lo, c->unit);
	else
		plot_text(f, px + 12, py + ph - 28, 9.5, 0, 0, 0, 0,
			  "λ from %.5g to %.5g%s", fa->lam_lo, fa->lam_hi,
			  c->unit);
	/* the blocks are drawn: the words after the ids fit a panel */
	const char *what = strstr(name, ": ");
	plot_text(f, px + 12, py + ph - 14, 9, 0, 0, 0, 0, "%s",
		  what ? what + 2 : name);
	(void)mk;
}

static void draw_mech_panel(struct fig *f, const struct rctx *c, int rank,
			    const struct tally_mech *mk, double px, double py,
			    double pw, double ph)
{
	cairo_t *cr = f->cr;
	const struct wall *w = c->w;
	const struct tally *t = c->in->mech;
	double ww = c->wx1 - c->wx0, wh = c->wy1 - c->wy0;
	double bx = px + 12, by = py + 22, bw = pw - 24, bh = ph - 54;
	double s = fmin(bw / ww, bh / wh);
	double ox = bx + (bw - s * ww) / 2, oy = by + (bh - s * wh) / 2;
#define MX(x) (ox + ((x) - c->wx0) * s)
#define MY(y) (oy + (c->wy1 - (y)) * s)
	/* motion scale: the largest vertex displacement is 0.35 mean size */
	double dmax = 0, vmax = 0;
	for (int b = 0; b < w->nblocks; b++) {
		const struct wall_block *bl = &w->blocks[b];
		const double *v = mk->vel + 3 * b;
		vmax = fmax(vmax, hypot(v[0], v[1]));
		for (int i = 0; i < bl->nv; i++) {
			double x = bl->xy[2 * i] - bl->cx, y = bl->xy[2 * i + 1] - bl->cy;
			dmax = fmax(dmax, hypot(v[0] - v[2] * y, v[1] + v[2] * x));
		}
	}
	double ds = dmax > 0 ? 0.35 * w->mean_size / dmax : 0;
	for (int b = 0; b < w->nblocks; b++) {
		const struct wall_block *bl = &w->blocks[b];
		const double *v = mk->vel + 3 * b;
		double sp = 0;
		for (int i = 0; i < bl->nv; i++) {
			double x = bl->xy[2 * i] - bl->cx, y = bl->xy[2 * i + 1] - bl->cy;
			sp = fmax(sp, hypot(v[0] - v[2] * y, v[1] + v[2] * x));
		}
		cairo_new_path(cr);
		for (int i = 0; i < bl->nv; i++)
			cairo_line_to(cr, MX(bl->xy[2 * i]), MY(bl->xy[2 * i + 1]));
		cairo_close_path(cr);
		if (bl->fixed)
			cairo_set_source_rgb(cr, 0.82, 0.82, 0.82);
		else if (dmax > 0 && sp > 1e-6 * dmax)
			plot_rgb(cr, C_SKY, 0.35 + 0.5 * sp / dmax);
		else
			cairo_set_source_rgb(cr, 1, 1, 1);
		cairo_fill_preserve(cr);
		cairo_set_source_rgb(cr, 0.3, 0.3, 0.3);
		cairo_set_line_width(cr, 0.6);
		cairo_set_dash(cr, NULL, 0, 0);
		cairo_stroke(cr);
	}
	/* the moved outlines and the motion arrows */
	for (int b = 0; b < w->nblocks && ds > 0; b++) {
		const struct wall_block *bl = &w->blocks[b];
		const double *v = mk->vel + 3 * b;
		if (bl->fixed || (hypot(v[0], v[1]) < 1e-6 && fabs(v[2]) < 1e-6))
			continue;
		static const double dash[] = {2, 1.5};
		cairo_new_path(cr);
		for (int i = 0; i < bl->nv; i++) {
			double x = bl->xy[2 * i], y = bl->xy[2 * i + 1];
			double dx = v[0] - v[2] * (y - bl->cy);
			double dy = v[1] + v[2] * (x - bl->cx);
			cairo_line_to(cr, MX(x + ds * dx), MY(y + ds * dy));
		}
		cairo_close_path(cr);
		plot_rgb(cr, C_BLUE, 0.8);
		cairo_set_line_width(cr, 0.6);
		cairo_set_dash(cr, dash, 2, 0);
		cairo_stroke(cr);
		cairo_set_dash(cr, NULL, 0, 0);
		if (vmax > 0 && hypot(v[0], v[1]) > 0.05 * vmax) {
			double al = 0.8 * w->mean_size / vmax;
			plot_rgb(cr, C_BLUE, 1);
			cairo_set_line_width(cr, 1.2);
			arrow(cr, MX(bl->cx), MY(bl->cy), MX(bl->cx + al * v[0]),
			      MY(bl->cy + al * v[1]), 5);
		}
	}
	/* the joints that move */
	for (int k = 0; k < w->nifaces && k < t->nifaces; k++) {
		char j = mk->joint[k];
		if (j == JOINT_CLOSED)
			continue;
		const struct wall_interface *in = &w->ifaces[k];
		joint_style(cr, j);
		cairo_move_to(cr, MX(in->p1[0]), MY(in->p1[1]));
		cairo_line_to(cr, MX(in->p2[0]), MY(in->p2[1]));
		cairo_stroke(cr);
	}
	cairo_set_dash(cr, NULL, 0, 0);
	panel_loads(cr, c, ox, oy, s);
#undef MX
#undef MY
	panel_caption(f, c, rank, mk, px, py, ph);
}

static void draw_mechanisms(struct fig *f, const struct rctx *c)
{
	plot_white(f);
	int cols, rows;
	double pw, ph;
	mech_layout(c, &cols, &rows, &pw, &ph);
	const struct tally *t = c->in->mech;
	plot_text(f, 14, 6, 11.5, 1, 0, 0, 0, "Mechanism families "
		  "(%d of %d distinct in %ld accepted samples)", c->fams.nfam,
		  t->nmech, t->accepted);
	for (int i = 0; i < c->ntop; i++) {
		double px = (i % cols) * pw, py = 28 + (i / cols) * ph;
		draw_mech_panel(f, c, i, &t->mech[c->top[i]], px, py, pw, ph);
	}
	/* the legend */
	cairo_t *cr = f->cr;
	double y = 28 + rows * ph + 10;
	static const char js[] = {JOINT_SLIDES, JOINT_HINGES, JOINT_HINGE_SLIDES,
				  JOINT_OPENS};
	static const char *jt[] = {"slides", "hinges", "hinges and slides",
				   "opens"};
	double x = 14;
	for (int i = 0; i < 4; i++) {
		joint_style(cr, js[i]);
		cairo_move_to(cr, x, y + 5);
		cairo_line_to(cr, x + 18, y + 5);
		cairo_stroke(cr);
		cairo_set_dash(cr, NULL, 0, 0);
		plot_rgb(cr, C_BLACK, 1);
		plot_text(f, x + 22, y + 5, 9.5, 0, 0, 0.5, 0, "%s", jt[i]);
		x += i == 2 ? 130 : 80;
	}
	plot_rgb(cr, C_SKY, 0.7);
	cairo_rectangle(cr, 14, y + 15, 18, 9);
	cairo_fill(cr);
	plot_rgb(cr, C_BLACK, 1);
	plot_text(f, 36, y + 19.5, 9.5, 0, 0, 0.5, 0, "%s",
		  "moving block (darker: faster); dashed: its motion; "
		  "arrow: its velocity");
}

/* ---- rendering -------------------------------------------------------------- */


static double h_freq(const struct rctx *c)
{
	(void)c;
	return plot_height(2);
}

static double h_dens(const struct rctx *c)
{
	(void)c;
	return 2 * PLOT_H;
}

static double h_three(const struct rctx *c)
{
	(void)c;
	return plot_height(3);
}

static double h_four(const struct rctx *c)
{
	(void)c;
	return plot_height(4);
}

/* A figure: its file name, its title, how to draw it and how high. */
struct figdef {
	const char *name;	/* file name without extension */
	const char *title;	/* for report.md and the PDF metadata */
	void (*draw)(struct fig *, const struct rctx *);
	double (*height)(const struct rctx *);
};

/* The figures in the order of report.md; report_nfigures of them. */
static const struct figdef report_figures[] = {
	{"frequencies", "Relative frequencies (the paper's Fig. 8, left)",
	 draw_frequencies, h_freq},
	{"densities", "Model KDE against the tests' normal, and both normals "
	 "grouped in classes (Fig. 8, centre and right)", draw_densities, h_dens},
	{"cumulative", "Relative cumulative frequencies and the "
	 "Kolmogorov-Smirnov test (Fig. 9)", draw_cumulative, h_four},
	{"single-solutions", "The model against the single-solution methods "
	 "(Fig. 10)", draw_single, h_three},
	{"mechanisms", "The most frequent mechanism families (Fig. 6)", draw_mechanisms,
	 mech_height},
	{"convergence", "Convergence of the characteristic value", 
	 draw_convergence, h_freq},
	{"fragility", "Fragility: the probability of collapse at a load, with "
	 "its 99 % simultaneous band", draw_fragility, h_three},
};
static const int report_nfigures = sizeof report_figures / sizeof report_figures[0];

const char *const *report_files(int sweep)
{
	static const char *const sweep_files[] = {"sweep.svg", "sweep.pdf",
						  "sweep.png", NULL};
	static char names[sizeof report_figures / sizeof report_figures[0]]
			 [3][64];
	static const char *files[sizeof names / sizeof names[0] * 3 + 2];
	static const char *const ext[] = {"svg", "pdf", "png"};
	if (sweep)
		return sweep_files;
	if (!files[0]) {
		int n = 0;
		for (int i = 0; i < report_nfigures; i++)
			for (int k = 0; k < 3; k++) {
				snprintf(names[i][k], sizeof names[i][k], "%s.%s",
					 report_figures[i].name, ext[k]);
				files[n++] = names[i][k];
			}
		files[n] = "report.md";
	}
	return files;
}

/* Is figure i drawn for c (the mechanisms need some)? */
static int report_figure_wanted(const struct rctx *c, int i)
{
	return strcmp(report_figures[i].name, "mechanisms") || c->ntop > 0;
}

/* Draw figure d into dir; messages name the file in shown (the
 * report's directory: dir is its staging directory). */
static enum sw_status render(const struct figdef *d, const struct rctx *c,
			     const char *dir, const char *shown, int format,
			     const struct report_opts *o, char *err)
{
	/* The figure is drawn into PATH.tmp and renamed over PATH when it
	 * is whole: a full disk or a kill leaves the old figure or none,
	 * never half of one. */
	char final[4096], path[4096 + 4];
	const char *ext = format == REPORT_SVG ? "svg" :
			  format == REPORT_PDF ? "pdf" : "png";
	if ((size_t)snprintf(final, sizeof final, "%s/%s.%s", dir, d->name,
			     ext) >= sizeof final)
		return sw_fail(err, SW_EIO, "%s: path too long", dir);
	snprintf(path, sizeof path, "%s.tmp", final);
	char named[4096];
	snprintf(named, sizeof named, "%s/%s.%s", shown, d->name, ext);
	struct fig f = {0};
	f.w = FIG_W;
	f.h = d->height(c);
	cairo_surface_t *s;
	if (format == REPORT_SVG) {
		s = cairo_svg_surface_create(path, f.w, f.h);
	} else if (format == REPORT_PDF) {
		s = cairo_pdf_surface_create(path, f.w, f.h);
		if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS) {
			char creator[128];
			snprintf(creator, sizeof creator, "slipwall %s",
				 c->in->run.version ? c->in->run.version : "");
			cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_TITLE,
						       d->title);
			cairo_pdf_surface_set_metadata(s,
						       CAIRO_PDF_METADATA_CREATOR,
						       creator);
		}
	} else {
		s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32,
					       (int)ceil(f.w * o->png_scale),
					       (int)ceil(f.h * o->png_scale));
	}
	if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS) {
		enum sw_status st = sw_fail(err, SW_EIO, "%s: %s", named,
			cairo_status_to_string(cairo_surface_status(s)));
		cairo_surface_destroy(s);
		unlink(path);
		return st;
	}
	f.cr = cairo_create(s);
	if (format == REPORT_PNG)
		cairo_scale(f.cr, o->png_scale, o->png_scale);
	cairo_set_line_join(f.cr, CAIRO_LINE_JOIN_ROUND);
	d->draw(&f, c);
	cairo_status_t cs = cairo_status(f.cr);
	cairo_destroy(f.cr);
	if (format == REPORT_PNG && cs == CAIRO_STATUS_SUCCESS)
		cs = cairo_surface_write_to_png(s, path);
	cairo_surface_finish(s);
	if (cs == CAIRO_STATUS_SUCCESS)
		cs = cairo_surface_status(s);
	cairo_surface_destroy(s);
	enum sw_status st = SW_OK;
	if (cs != CAIRO_STATUS_SUCCESS)
		st = sw_fail(err, SW_EIO, "%s: %s", named,
			     cairo_status_to_string(cs));
	else if (format == REPORT_SVG)
		st = plot_svg_text_layer(path, named, &f, err);
	if (st == SW_OK && rename(path, final) != 0)
		st = sw_fail(err, SW_EIO, "%s: cannot write: %s", named,
			     strerror(errno));
	if (st != SW_OK)
		unlink(path);
	plot_labels_clear(&f);
	return st;
}

/* ---- the entry point ---------------------------------------------------------- */

void report_opts_default(struct report_opts *o)
{
	o->formats = REPORT_ALL;
	o->max_mechanisms = MAX_PANELS;
	o->png_scale = 2.5;
	o->cancel = NULL;
}

static enum sw_status make_dir(const char *dir, char *err)
{
	char failed[PATH_MAX];
	if (strlen(dir) >= PATH_MAX)
		return sw_fail(err, SW_EIO, "%s: path too long", dir);
	if (sys_mkdir_p(dir, failed, sizeof failed))
		return sw_fail(err, SW_EIO, "%s: cannot create: %s", failed,
			       strerror(errno));
	struct stat st;
	if (stat(dir, &st) || !S_ISDIR(st.st_mode))
		return sw_fail(err, SW_EIO, "%s: not a directory", dir);
	return SW_OK;
}

/* The staging directory of a report: where it is and what it holds. */
struct stage {
	char *dir;		/* ".NAME.XXXXXX" beside the report's dir */
	char *final;		/* the report's dir */
	char **names;		/* files written into it */
	int n;
};

static char *path_join(const char *dir, const char *name)
{
	size_t n = strlen(dir) + strlen(name) + 2;
	char *p = sw_xmalloc(n);
	snprintf(p, n, "%s/%s", dir, name);
	return p;
}

static enum sw_status stage_open(struct stage *s, const char *dir, char *err)
{
	memset(s, 0, sizeof *s);
	/* a symbolic link to a directory is that directory: the report is
	 * staged beside the directory it names and renamed into it (the
	 * link stays a link) */
	struct stat ls, ds;
	char *real = lstat(dir, &ls) == 0 && S_ISLNK(ls.st_mode) &&
		     stat(dir, &ds) == 0 && S_ISDIR(ds.st_mode) ?
		     realpath(dir, NULL) : NULL;
	if (real)
		dir = real;
	size_t len = strlen(dir);
	while (len > 1 && dir[len - 1] == '/')
		len--;
	char *d = sw_xmalloc(len + 1);
	memcpy(d, dir, len);
	d[len] = 0;
	free(real);
	char *slash = strrchr(d, '/');
	const char *base = slash ? slash + 1 : d;
	char *parent = slash ? (slash == d ? sw_xstrdup("/") :
				strndup(d, (size_t)(slash - d))) :
		       sw_xstrdup(".");
	if (!parent)
		abort();
	enum sw_status st = SW_OK;
	size_t n = strlen(parent) + strlen(base) + 16;
	s->dir = sw_xmalloc(n);
	snprintf(s->dir, n, "%s/.%s.XXXXXX", parent, base);
	char *tmpl = sw_xstrdup(s->dir);
	if (!mkdtemp(s->dir)) {
		/* a missing parent is created, as the directory itself was */
		int e = errno;
		if (e == ENOENT && (st = make_dir(parent, err)) == SW_OK) {
			memcpy(s->dir, tmpl, strlen(tmpl) + 1);
			if (!mkdtemp(s->dir))
				e = errno;
			else
				e = 0;
		}
		if (st == SW_OK && e)
			st = sw_fail(err, SW_EIO, "%s: cannot create: %s", d,
				     strerror(e));
		if (st != SW_OK) {
			free(s->dir);
			s->dir = NULL;
		}
	}
	free(tmpl);
	free(parent);
	if (st != SW_OK) {
		free(d);
		return st;
	}
	s->final = d;
	return SW_OK;
}

/* Remove the staging directory and everything in it (the temporary
 * files of a figure cut short included). */
static void stage_remove(struct stage *s)
{
	DIR *d = opendir(s->dir);
	if (d) {
		struct dirent *e;
		while ((e = readdir(d))) {
			if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, ".."))
				continue;
			char *p = path_join(s->dir, e->d_name);
			unlink(p);
			free(p);
		}
		closedir(d);
	}
	rmdir(s->dir);
}

static void stage_free(struct stage *s)
{
	for (int i = 0; i < s->n; i++)
		free(s->names[i]);
	free(s->names);
	free(s->dir);
	free(s->final);
}

static void stage_add(struct stage *s, const char *name)
{
	s->names = sw_xrealloc(s->names, sizeof *s->names * (size_t)(s->n + 1));
	s->names[s->n++] = sw_xstrdup(name);
}

static int stage_has(const struct stage *s, const char *name)
{
	for (int i = 0; i < s->n; i++)
		if (!strcmp(s->names[i], name))
			return 1;
	return 0;
}

/* Make the staged report the report: one rename when the directory is
 * new; else the figures of an older report that this one lacks are
 * removed, the figures renamed in, and report.md last. */
static enum sw_status stage_publish(struct stage *s, char *err)
{
	if (rename(s->dir, s->final) == 0)
		return SW_OK;
	if (errno != EEXIST && errno != ENOTEMPTY)
		return sw_fail(err, SW_EIO, "%s: cannot create: %s", s->final,
			       strerror(errno));
	struct stat st;
	if (stat(s->final, &st) != 0 || !S_ISDIR(st.st_mode))
		return sw_fail(err, SW_EIO, "%s: not a directory", s->final);
	static const char *const ext[] = {"svg", "pdf", "png"};
	for (int i = 0; i < report_nfigures; i++)
		for (int k = 0; k < 3; k++) {
			char name[128];
			snprintf(name, sizeof name, "%s.%s", report_figures[i].name,
				 ext[k]);
			if (stage_has(s, name))
				continue;
			char *p = path_join(s->final, name);
			unlink(p);
			free(p);
		}
	for (int pass = 0; pass < 2; pass++)
		for (int i = 0; i < s->n; i++) {
			if ((pass == 0) == !strcmp(s->names[i], "report.md"))
				continue;
			char *from = path_join(s->dir, s->names[i]);
			char *to = path_join(s->final, s->names[i]);
			int rc = rename(from, to);
			int e = errno;
			free(from);
			free(to);
			if (rc != 0)
				return sw_fail(err, SW_EIO, "%s/%s: cannot "
					       "write: %s", s->final,
					       s->names[i], strerror(e));
		}
	rmdir(s->dir);
	return SW_OK;
}

static int cancelled(const struct report_opts *o)
{
	return o->cancel && *o->cancel;
}

enum sw_status report_write(const struct report_input *in, const char *dir,
			    const struct report_opts *o, char *err)
{
	struct report_opts def;
	if (!o) {
		report_opts_default(&def);
		o = &def;
	}
	if (!(o->png_scale > 0) || o->png_scale > 20)
		return sw_fail(err, SW_EINPUT, "report: PNG scale %g out of range",
			       o->png_scale);
	struct rctx c;
	enum sw_status st = rctx_init(&c, in, o, err);
	if (st != SW_OK) {
		rctx_free(&c);
		return st;
	}
	struct stage s;
	st = stage_open(&s, dir, err);
	if (st != SW_OK) {
		rctx_free(&c);
		return st;
	}
	static const char *const ext[] = {"svg", "pdf", "png"};
	for (int i = 0; i < report_nfigures && st == SW_OK; i++) {
		if (!report_figure_wanted(&c, i))
			continue;
		for (int fmt = REPORT_SVG, k = 0; fmt <= REPORT_PNG &&
		     st == SW_OK; fmt <<= 1, k++) {
			if (!(o->formats & fmt))
				continue;
			if (cancelled(o)) {
				st = sw_fail(err, SW_EINTR, "%s: interrupted: "
					     "nothing written", dir);
				break;
			}
			st = render(&report_figures[i], &c, s.dir, s.final, fmt, o,
				    err);
			if (st == SW_OK) {
				char name[128];
				snprintf(name, sizeof name, "%s.%s",
					 report_figures[i].name, ext[k]);
				stage_add(&s, name);
			}
		}
	}
	if (st == SW_OK && cancelled(o))
		st = sw_fail(err, SW_EINTR, "%s: interrupted: nothing written",
			     dir);
	struct md_figure fig[sizeof report_figures / sizeof report_figures[0]];
	for (int i = 0; i < report_nfigures; i++)
		fig[i] = (struct md_figure){report_figures[i].name,
					    report_figures[i].title,
					    report_figure_wanted(&c, i)};
	if (st == SW_OK && (st = report_md_write(&c, fig, report_nfigures,
						 s.dir, o, err)) == SW_OK)
		stage_add(&s, "report.md");
	if (st == SW_OK)
		st = stage_publish(&s, err);
	if (st != SW_OK)
		stage_remove(&s);
	stage_free(&s);
	rctx_free(&c);
	return st;
}

/* ---- a sweep (`slipwall sweep`) ------------------------------------------ */

static void draw_sweep(struct fig *f, const struct rctx *c)
{
	const struct report_sweep *s = c->sweep;
	cairo_t *cr = f->cr;
	int n = s->n;
	double *x = sw_xmalloc(sizeof(double) * (size_t)n * 6);
	double *p05 = x + n, *lo = x + 2 * n, *hi = x + 3 * n, *p50 = x + 4 * n,
	       *p95 = x + 5 * n;
	double ymax = 0;
	for (int i = 0; i < n; i++) {
		x[i] = s->pt[i].value;
		p05[i] = s->pt[i].p05;
		lo[i] = s->pt[i].p05_lo;
		hi[i] = s->pt[i].p05_hi;
		p50[i] = s->pt[i].p50;
		p95[i] = s->pt[i].p95;
	}
	ymax = fmax(plot_max(p95, n), plot_max(hi, n));
	plot_white(f);
	struct axes a = plot_box(1);
	a.x0 = x[0];
	a.x1 = x[n - 1];
	if (!(a.x1 > a.x0)) {
		a.x0 -= 0.5;
		a.x1 += 0.5;
	}
	a.y0 = 0;
	a.y1 = ymax > 0 ? ymax * 1.08 : 1;
	plot_axes(f, &a, s->xlabel, c->axis, "Collapse load against the "
		  "parameter", 0);
	plot_clip(cr, &a);
	/* the band of p05, in runs of values that have one */
	for (int i = 0; i < n;) {
		if (!isfinite(lo[i]) || !isfinite(hi[i])) {
			i++;
			continue;
		}
		int j = i;
		while (j + 1 < n && isfinite(lo[j + 1]) && isfinite(hi[j + 1]))
			j++;
		if (j == i) {
			plot_rgb(cr, C_ORANGE, 0.8);
			cairo_set_line_width(cr, 4);
			cairo_move_to(cr, plot_x(&a, x[i]), plot_y(&a, lo[i]));
			cairo_line_to(cr, plot_x(&a, x[i]), plot_y(&a, hi[i]));
			cairo_stroke(cr);
		} else {
			cairo_move_to(cr, plot_x(&a, x[i]), plot_y(&a, lo[i]));
			for (int k = i + 1; k <= j; k++)
				cairo_line_to(cr, plot_x(&a, x[k]), plot_y(&a, lo[k]));
			for (int k = j; k >= i; k--)
				cairo_line_to(cr, plot_x(&a, x[k]), plot_y(&a, hi[k]));
			cairo_close_path(cr);
			plot_rgb(cr, C_ORANGE, 0.35);
			cairo_fill(cr);
		}
		i = j + 1;
	}
	plot_style(cr, LG_DASH, C_BLACK);
	plot_curve(cr, &a, x, p95, n);
	plot_style(cr, LG_THIN, C_BLACK);
	plot_curve(cr, &a, x, p50, n);
	plot_style(cr, LG_LINE, C_VERMILLION);
	plot_curve(cr, &a, x, p05, n);
	cairo_set_dash(cr, NULL, 0, 0);
	for (int i = 0; i < n; i++) {
		if (!isfinite(p05[i]))
			continue;
		cairo_arc(cr, plot_x(&a, x[i]), plot_y(&a, p05[i]), 2.6, 0,
			  2 * M_PI);
		cairo_fill(cr);
	}
	cairo_restore(cr);
	struct lg_item it[4] = {
		{LG_LINE, C_VERMILLION, "p05 (characteristic value)"},
		{LG_BAND, C_ORANGE, "99 % interval of p05"},
		{LG_THIN, C_BLACK, "p50"},
		{LG_DASH, C_BLACK, "p95"},
	};
	/* the legend on the side where the curves are low */
	plot_legend(f, &a, it, 4, p95[0] < p95[n - 1] || !isfinite(p95[0]) ?
		    LG_LEFT : 0);
	if (s->caption)
		plot_caption(f, PLOT_H + 6, s->caption);
	free(x);
}

static double h_sweep(const struct rctx *c)
{
	(void)c;
	return plot_height(1);
}

enum sw_status report_write_sweep(const struct report_sweep *s,
				  const char *dir, const struct report_opts *o,
				  char *err)
{
	static const struct figdef fig = {"sweep", "Collapse load against "
					  "the parameter (slipwall sweep)",
					  draw_sweep, h_sweep};
	struct report_opts def;
	if (!o) {
		report_opts_default(&def);
		o = &def;
	}
	if (s->n < 1)
		return sw_fail(err, SW_EINPUT, "sweep: no values to draw");
	enum sw_status st = make_dir(dir, err);
	if (st != SW_OK)
		return st;
	struct report_input in;
	memset(&in, 0, sizeof in);
	in.w = s->w;
	in.run.version = s->version;
	struct rctx c;
	memset(&c, 0, sizeof c);
	c.in = &in;
	c.w = s->w;
	c.sweep = s;
	report_load_unit(s->w, c.axis, sizeof c.axis, &c.unit);
	/* a cancel stops between two formats: the figures drawn are whole,
	 * the one being drawn is finished first */
	for (int fmt = REPORT_SVG, k = 0; fmt <= REPORT_PNG && st == SW_OK;
	     fmt <<= 1, k++) {
		if (!(o->formats & fmt))
			continue;
		if (cancelled(o))
			st = sw_fail(err, SW_EINTR, "%s/%s: interrupted: not "
				     "written", dir, report_files(1)[k]);
		else
			st = render(&fig, &c, dir, dir, fmt, o, err);
	}
	return st;
}

void report_cleanup(void)
{
	cairo_debug_reset_static_data();
	FcFini();
}
