/*
 * report_fig.h - what the report's figures and its Markdown summary
 * share (private to src/lib/): the context computed once from the
 * input (struct rctx, report.c), the list of figures, and the writer of
 * report.md (report_md.c).  The figures are drawn with the kit of
 * plot.h.
 */
#ifndef SLIPWALL_REPORT_FIG_H
#define SLIPWALL_REPORT_FIG_H

#include <stddef.h>

#include "plot.h"
#include "slipwall/family.h"
#include "slipwall/report.h"
#include "slipwall/stats.h"

#define MAX_PANELS 6		/* mechanisms drawn at the most (Fig. 6) */

/* ---- what every figure reads --------------------------------------------- */

struct rctx {
	const struct report_input *in;
	const struct wall *w;
	char axis[96];		/* the load axis label */
	const char *unit;	/* " N" or "" */
	/* in->sol with each lambda times wall_quantity's scale: the
	 * loads printed and drawn */
	struct report_solution *sol;
	double *lam;		/* model loads, sorted */
	size_t n;
	double *tst;		/* tests, sorted, or NULL */
	size_t m;
	struct stats_summary ms, ts;
	double mmu, msd, tmu, tsd;	/* normal fits */
	struct stats_ks ks;
	int ks_ok;
	double bw;		/* KDE bandwidth */
	/* common classes of Figs. 8 and 10 */
	double blo, bw_class;
	int nb;
	double *fm, *ft;	/* relative frequencies per class */
	/* the load range of the distribution plots */
	double x0, x1;
	/* the mechanisms (Fig. 6): the most frequent families (docs/
	 * statistics.md, "Mechanism families"), each drawn by its most
	 * frequent mechanism top[i] */
	struct family_set fams;	/* of in->mech (fams.w NULL: none) */
	int topfam[MAX_PANELS], top[MAX_PANELS], ntop;
	double wx0, wx1, wy0, wy1;	/* the drawn extent, m */
	double wsize;			/* the blocks' larger extent, m */
	/* the convergence curve */
	int nconv;
	double *cn, *cp, *clo, *chi;	/* n, p05, 99 % band (NaN: none) */
	/* report_write_sweep: the sweep (the fields above are unused) */
	const struct report_sweep *sweep;
};

/* A figure as report.md lists it: report.c's table says which exist and
 * which were drawn, so that report_md.c needs nothing of report.c. */
struct md_figure {
	const char *name, *title;
	int drawn;
};

/* Write DIR/report.md for c and its nfig figures, whole or not at all
 * (outfile).  SW_OK or SW_EIO with a message in err. */
enum sw_status report_md_write(const struct rctx *c,
			       const struct md_figure *fig, int nfig,
			       const char *dir, const struct report_opts *o,
			       char *err);

#endif
