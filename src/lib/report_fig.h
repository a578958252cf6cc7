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
	/* the mechanisms (Fig. 6) */
	int top[MAX_PANELS], ntop;
	double wx0, wx1, wy0, wy1;	/* the drawn extent, m */
	double wsize;			/* the blocks' larger extent, m */
	/* the convergence curve */
	int nconv;
	double *cn, *cp, *clo, *chi;	/* n, p05, 99 % band (NaN: none) */
	/* report_write_sweep: the sweep (the fields above are unused) */
	const struct report_sweep *sweep;
};

/* A figure: its file name, its title, how to draw it and how high. */
struct figdef {
	const char *name;	/* file name without extension */
	const char *title;	/* for report.md and the PDF metadata */
	void (*draw)(struct fig *, const struct rctx *);
	double (*height)(const struct rctx *);
};

/* The figures in the order of report.md; report_nfigures of them. */
extern const struct figdef report_figures[];
extern const int report_nfigures;
/* Is figure i drawn for c (the mechanisms need some)? */
int report_figure_wanted(const struct rctx *c, int i);

/* Write DIR/report.md for c, whole or not at all (outfile).  SW_OK or
 * SW_EIO with a message in err. */
enum sw_status report_md_write(const struct rctx *c, const char *dir,
			       const struct report_opts *o, char *err);

#endif
