/*
 * sample_unheld.c - which blocks no contact force can hold, when LP-max
 * says that none holds them all, or none at a load in the live load's
 * direction, or the standing check that none holds them without the
 * live load (docs/method.md, "Which blocks cannot be held").
 *
 * LP-max is infeasible (`no_equilibrium`) when no stress field inside
 * the friction cones of the contact points balances the dead load at
 * any load factor.  That verdict names no block, and a user who must
 * mend the wall (or understand a rejected sample) needs one.  The
 * elastic problem below gives it: LP-max's equilibrium rows, each with
 * a help force s+ - s- that an outside hand could add,
 *
 *     min  sum_i (s+_i + s-_i)
 *     s.t. A_edges alpha + lambda f_L + s+ - s- = -f_D,
 *          alpha >= 0, lambda free, s+, s- >= 0,
 *
 * always feasible (alpha = 0, lambda = 0, s = -f_D).  After the standing
 * check's `unstable`, lambda is held at 0 instead: the blocks named then
 * need the live load to stand.  After LP-max's `nonpositive` (its
 * largest load factor is at or below 0), lambda >= 0: the blocks named
 * then stand only under a load against the live load's direction, and
 * fall under any load along it.  After the SLP's `nonpositive` (LP-max
 * held every block at a positive load, the SLP's fixed point is at or
 * below 0), the cones give way to LP1's columns at the SLP's last
 * capacities, N >= 0 and |T_k| <= mu_k c_k, with lambda >= 0: the
 * blocks named fall once friction does not dilate.  Its optimum is
 * the least help, in the operator's scaled units (forces over the mean
 * block weight, moments over that weight times the mean block size:
 * statics.h), that lets every block stand; the blocks whose rows take
 * help are the ones named.  An L1 objective makes the help sparse: a
 * block that overhangs takes it alone, and its neighbours stand.
 * Where several blocks could each take the least help (a lintel that
 * bears on an overhanging jamb may be held at either), the simplex's
 * vertex names one of them: the answer is a least set, not the only
 * one, and docs/method.md says so.
 *
 * The problem is built on the workspace's solver, solved by the primal
 * simplex from the basis of the help alone (s = -f_D: primal feasible)
 * and freed: it runs once, on a rejected sample or a `solve` that
 * failed, never on a sample's path, so no status or load moves with it.
 * Its cost is about an LP-max from a poor start: 0.5 s on walls/
 * body-300.yaml, 10 s on walls/body-1000.yaml (a sample there: 50 s),
 * where no block needs help; where many do, up to its pivot limit
 * (UNHELD_PIVOTS_PER_ROW) and a dual simplex after it.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sample_lp.h"
#include "sample_ws.h"

/* Help below this, in the scaled units (a fraction of the mean block
 * weight, or of its moment over the mean block size), is the
 * simplex's round-off, not a block that cannot be held: 100 times the
 * primal simplex's feasibility tolerance (lp_feasibility_tol, 1e-8). */
#define UNHELD_TOL 1e-6

/* The primal simplex from the help's basis usually ends within a few
 * pivots a row (8,608 for 1,959 rows on a 654-block wall with an
 * opening without a lintel), but on a sample of that wall it took 644 s.
 * So it may take at most this many pivots a row; a solve cut there goes
 * again by the dual simplex from the slack basis (the rows' auxiliary
 * variables basic, every column at 0), which is dual feasible here (no
 * column has a negative cost) and took 13,366-13,640 pivots, 7.5-8.5 s,
 * on that wall's samples (docs/method.md, "Which blocks cannot be
 * held"). */
#define UNHELD_PIVOTS_PER_ROW 10

struct unheld_entry {
	int block;
	double help;
};

static int by_help(const void *a, const void *b)
{
	const struct unheld_entry *x = a, *y = b;
	if (x->help != y->help)
		return x->help < y->help ? 1 : -1;
	return (x->block > y->block) - (x->block < y->block);
}

int sample_unheld_asks(const struct sample_result *r,
		       enum sample_unheld_load *load)
{
	switch (r->status) {
	case SAMPLE_NO_EQUILIBRIUM: *load = SAMPLE_UNHELD_ANY; return 1;
	case SAMPLE_UNSTABLE: *load = SAMPLE_UNHELD_AT_REST; return 1;
	case SAMPLE_NONPOSITIVE:
		/* LP-max's leaves no SLP load (NaN), the SLP's one at or
		 * below 0 */
		*load = isnan(r->lambda_max) ? SAMPLE_UNHELD_ALONG :
					       SAMPLE_UNHELD_FIXED;
		return 1;
	default: return 0;
	}
}

void sample_ws_unheld_limit(struct sample_ws *ws, int pivots)
{
	ws->unheld_limit = pivots > 0 ? pivots : 0;
}

int sample_unheld(struct sample_ws *ws, enum sample_unheld_load load,
		  int *blocks, int max)
{
	const struct wall *w = ws->w;
	int m = ws->m, R = ws->R;
	/* the contact forces' columns: LP-max's cone edges (4 an
	 * interface), or after the SLP's `nonpositive` its own N_a, N_b, T
	 * (3 an interface, the layout of LP1); then lambda, then the help */
	int fixed = load == SAMPLE_UNHELD_FIXED;
	int nf = fixed ? 3 * m : 4 * m, lam = nf;
	int nc = nf + 1 + 2 * R;
	struct lp *P = lp_new(ws->solver, R, nc);
	if (!P)
		return -1;
	sws_put_dead_load(ws, P);
	if (fixed) {
		/* LP1's columns at the SLP's last capacities ws->c: N >= 0,
		 * |T_k| <= mu_k c_k (sample_slp.c, lp1_solve) */
		for (int j = 0; j < 3 * m; j++) {
			int rows[6];
			double vals[6];
			int n = statics_column(&ws->st, j, rows, vals);
			double cap = sws_capacity(ws, j / 3);
			lp_set_col(P, j, n, rows, vals);
			if (j % 3 == 2)
				lp_set_col_bounds(P, j, -cap, cap);
			else
				lp_set_col_bounds(P, j, 0, HUGE_VAL);
		}
	} else {
		/* the cone edges of every contact point, as LP-max has them */
		for (int k = 0; k < m; k++)
			for (int e = 0; e < 2; e++)
				for (int sgn = 0; sgn < 2; sgn++) {
					int rows[6];
					double vals[6];
					int n = statics_edge_column(&ws->st, k, e,
								    sgn, rows,
								    vals);
					int col = sgn ? ACOL_BETA(k, e) :
							ACOL_ALPHA(k, e);
					lp_set_col(P, col, n, rows, vals);
					lp_set_col_bounds(P, col, 0, HUGE_VAL);
				}
	}
	int nl = sws_live_load(ws);
	lp_set_col(P, lam, nl, ws->ind, ws->val);
	lp_set_col_bounds(P, lam, load == SAMPLE_UNHELD_ANY ? -HUGE_VAL : 0,
			  load == SAMPLE_UNHELD_AT_REST ? 0 : HUGE_VAL);
	/* the help forces: columns nf + 1 + 2i (s+) and + 1 (s-) */
	for (int i = 0; i < R; i++)
		for (int s = 0; s < 2; s++) {
			int col = nf + 1 + 2 * i + s;
			double v = s ? -1 : 1;
			lp_set_col(P, col, 1, &i, &v);
			lp_set_col_bounds(P, col, 0, HUGE_VAL);
			lp_set_obj(P, col, 1);
		}
	lp_set_maximize(P, 0);
	/* start from the basis of the help alone, s = -f_D (s+ or s- basic
	 * in each row by the sign of its dead load): primal feasible, so
	 * the primal simplex goes straight to its second phase (not after
	 * the SLP's: its shears are non-basic at -mu c, and a first phase
	 * runs) */
	unsigned char *basic = sw_xcalloc((size_t)nc, 1);
	for (int i = 0; i < R; i++)
		basic[nf + 1 + 2 * i + (ws->st.fD[i] > 0)] = 1;
	lp_set_basis(P, basic);
	free(basic);
	/* at most UNHELD_PIVOTS_PER_ROW pivots a row from there; a solve
	 * cut at that limit (not one that failed otherwise: an injected
	 * fault, SLIPWALL_LP_FAULT, makes none) goes on by the dual simplex
	 * from the slack basis */
	int limit = ws->unheld_limit > 0 ? ws->unheld_limit :
					   UNHELD_PIVOTS_PER_ROW * R;
	int was = lp_solver_iteration_limit(ws->solver, limit);
	enum lp_status st = lp_solve(P, LP_PRIMAL);
	lp_solver_iteration_limit(ws->solver, was);
	if (st == LP_FAILED && lp_alive(P) && lp_last_iterations(P) >= limit) {
		lp_reset_basis(P);
		st = lp_solve(P, LP_DUAL);
	}
	if (st != LP_OPTIMAL) {
		lp_free(P);
		return -1;
	}

	struct unheld_entry *u = sw_xmalloc(sizeof *u * (size_t)(w->nfree + 1));
	int n = 0;
	for (int b = 0; b < w->nblocks; b++) {
		int q = w->blocks[b].eq;
		if (q < 0)
			continue;
		double h = 0;
		for (int r = 3 * q; r < 3 * q + 3; r++)
			h += lp_col(P, nf + 1 + 2 * r) +
			     lp_col(P, nf + 2 + 2 * r);
		if (h > UNHELD_TOL) {
			u[n].block = b;
			u[n++].help = h;
		}
	}
	lp_free(P);
	qsort(u, (size_t)n, sizeof *u, by_help);
	for (int i = 0; i < n && i < max; i++)
		blocks[i] = u[i].block;
	free(u);
	return n;
}
