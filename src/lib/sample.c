/*
 * sample.c - one Monte Carlo sample (docs/method.md), the hot loop.
 *
 * Six LP problems per wall and thread, one per LP role, built once per
 * workspace on the workspace's own LP solver (lp.h).  Each sample
 * rewrites what its contact points change (the moment coefficients of
 * the normal-force columns and of the opening-rate rows) and resets
 * every bound and objective (refill; the `previous` start keeps the
 * bases) and starts every role from the
 * basis SLIPWALL_LP_START names (set_points); within a sample
 * only bounds change between two solves of a role, so each is a warm
 * start (presolve off).  Wherever an LP's optimum is not unique, the
 * sample takes the optimal solution with the least weighted sum of its
 * normal forces (or, for the kinematic LP, joint rates), the weights
 * hashed from the contact positions: "One answer per sample", so that
 * the result does not depend on the start (docs/method.md).  All
 * quantities are in the scaled units of statics.h; results are
 * converted at the end.
 *
 *   AMAX, STAND, AMIN  rows: equilibrium (3 per free block) only
 *               cols: the force at each contact point in the edge
 *               directions of its friction cone, F = alpha (n + mu t) +
 *               beta (n - mu t), alpha, beta >= 0 (so N = alpha + beta,
 *               T = mu (alpha - beta) summed over the two points):
 *               alpha_a, beta_a, alpha_b, beta_b per interface | lambda.
 *               No friction rows (they were two thirds of the rows), and
 *               every yield condition LP-min holds at its limit is a
 *               column bound: N_j = 0 is alpha_j = beta_j = 0, T = +mu N
 *               is beta = 0, T = -mu N is alpha = 0.
 *               AMAX: LP-max (max lambda).  STAND: lambda = 0 and no
 *               objective: can the wall stand under its own weight?
 *               AMIN: min lambda >= 0 with the mechanism's yield
 *               conditions held at their limits (LP-min).
 *   LP1, LP2    rows: equilibrium | LP2 only: 1 closeness row per
 *               interface, Na + Nb - p + q = c
 *               cols: Na, Nb, T | lambda | LP2 only: p, q per interface
 *               LP1: max lambda with |T| <= mu c (column bounds: a fixed
 *               capacity, no dilatancy).  LP2: min sum (p + q) over LP1's
 *               optimal face (LP1's columns with a non-zero reduced cost
 *               fixed where LP1 left them) - the optimal stress field
 *               closest in L1 to c.
 *   KIN         rows: one per column of A (opening rates at q_a, q_b,
 *               slip rate) | f_L . v = 1
 *               cols: block velocities | s+, s- per interface (slip =
 *               s+ - s-); min sum of opening rates + sum |slip|: the
 *               least joint motion.
 *
 * Tolerances (scaled units, mean block weight = 1): a normal force counts
 * as positive above TOL_FORCE; a joint rate counts as motion above
 * TOL_MOTION times the largest rate of the mechanism, and above the
 * kinematic LP's precision (motion_threshold).  docs/method.md says why.
 */
#include <gsl/gsl_linalg.h>
#include <limits.h>
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "lp.h"
#include "piece.h"
#include "sample_lp.h"
#include "slipwall/sample.h"
#include "statics.h"
#include "support.h"

#define TOL_FORCE 1e-7
#define TOL_MOTION 1e-9
#define VW_TOL 1e-8
#define TOL_LIMIT 1e-5
#define TOL_FACE 1e-9
/* a reduced cost at or below this may be zero: the optimum may not be
 * unique, and the tie-break LP runs (docs/method.md) */
#define TOL_TIE 1e-9
/* the SLP's acceleration (slp()): iterations on one affine piece before
 * Anderson's steps, and their memory */
#define SLP_SETTLE 2
#define SLP_MEMORY 4
/* ... and only once the residual max |N - c| is below this (scaled
 * units): earlier, the pieces still change along the way, and a step
 * that crosses them may reach another fixed point than the plain
 * iteration's (the demo wall, seed 1, 1,000 samples: 21 samples
 * without any bound, 9 at 1e-3, 5 at 2e-4; docs/method.md) */
#define SLP_ACCEL_FROM 2e-4
/* Anderson's steps of one sample at most; then the plain iteration
 * again from the start (a sample of the demo wall cycled for 1,000
 * iterations between accelerated and plain steps where the plain
 * iteration converges in 84; going on plainly from where it was, it
 * converged to another fixed point) */
#define SLP_TRIES 50
/* The default SLP (slp_piece_path, docs/method.md "The SLP's answer"):
 * the joints' classification must hold this many iterations before the
 * piece's fixed point is solved (measured: 2 keeps the plain iteration's
 * answer wherever it is not decided by round-off; 1 and 0 move 3.5 % and
 * 12 % of the demo's samples) */
#define SLP_PIECE_SETTLE 2
/* a normal force, a shear's distance to its capacity or N - c counts as
 * zero below this in the classification (scaled units, mean block
 * weight 1): far above the round-off of a converged field (1e-13) */
#define SLP_CLASS_TOL 1e-9
/* the fixed point c* is verified when max |N(c*) - c*| is below this:
 * round-off (measured 1e-15 to 3e-13) */
#define PIECE_VERIFY 1e-9
/* the default SLP's first phase: iterations with the step omega before
 * a wandering iteration starts again from LP-max's capacities with
 * omega / 2 (for twice as many), and so on.  Within one phase the
 * last-bit differences between two LP starts do not grow to a decision:
 * demo sample 1478 of seed 2 wandered for 300 iterations before they
 * did.  Measured (docs/method.md, "The SLP's answer", rule 6): every
 * start agrees on it and on every sample of the demo and both Ferris &
 * Tin-Loi walls at 2,000 samples and three seeds.  Of the demo's 6,000
 * samples (seeds 1-3) it changes 15: 9 not converged before are
 * accepted, 1 accepted before is not converged, 5 loads move (3 lower,
 * 2 higher); none of 2,000 of either Ferris & Tin-Loi wall (seed 1) */
#define SLP_PHASE 100
/* ... if its last residual max |N - c| is still above this, far from the
 * plain test's 1e-7: a slowly converging iteration goes on (demo sample
 * 723 of seed 1 is at 3.4e-7 after 100 iterations, and converges at
 * 101) */
#define SLP_WANDERING 1e-3
/* `auto` takes its large-wall starts above this many interfaces
 * (role_start) */
#define AUTO_LARGE_IFACES 1000
/* the weight of sum r_j N_j in LP2's objective (put_lp2_objective) */
#define TIE_LP2 1e-4

static const struct {
	const char *name, *text;
} status_info[] = {
#define SAMPLE_X(e, name, text) {name, text},
	SAMPLE_STATUS_TABLE(SAMPLE_X)
#undef SAMPLE_X
};

const char *sample_status_name(enum sample_status s)
{
	return (unsigned)s < SAMPLE_STATUS_COUNT ? status_info[s].name : "?";
}

const char *sample_status_text(enum sample_status s)
{
	return (unsigned)s < SAMPLE_STATUS_COUNT ? status_info[s].text : "?";
}

int sample_status_parse(const char *name)
{
	for (int s = 0; s < SAMPLE_STATUS_COUNT; s++)
		if (!strcmp(name, status_info[s].name))
			return s;
	return -1;
}

void sample_opts_default(struct sample_opts *o)
{
	o->omega = 0.5;
	/* Nearly every sample converges in some tens of iterations; a few
	 * (1 % of Ferris & Tin-Loi wall 1) take 200-900, while the normal
	 * force of an interface that is losing its contact creeps to zero
	 * along a tie of LP2's L1 objective (docs/method.md).  None of
	 * 2,400 samples of the published walls needed more than 874. */
	o->max_iter = 1000;
	o->tol = 1e-7;
	o->stabilise = 1;
	o->slp = SAMPLE_SLP_PIECE;
	o->piece_settle = SLP_PIECE_SETTLE;
	o->forces = 0;
}

void sample_result_init(struct sample_result *r, const struct wall *w)
{
	memset(r, 0, sizeof *r);
	r->nblocks = w->nblocks;
	r->nifaces = w->nifaces;
	size_t m = (size_t)w->nifaces;
	r->vel = sw_xcalloc(3 * (size_t)w->nblocks + 1, sizeof(double));
	r->joint = sw_xcalloc(m + 1, 1);
	r->dn = sw_xcalloc(2 * m + 1, sizeof(double));
	r->dt = sw_xcalloc(m + 1, sizeof(double));
	r->N = sw_xcalloc(2 * m + 1, sizeof(double));
	r->T = sw_xcalloc(m + 1, sizeof(double));
}

void sample_result_free(struct sample_result *r)
{
	free(r->vel);
	free(r->joint);
	free(r->dn);
	free(r->dt);
	free(r->N);
	free(r->T);
	memset(r, 0, sizeof *r);
}

/* The LP roles of a sample, one GLPK problem each (see the top). */
enum role { AMAX, STAND, AMIN, LP1, LP2, KIN, ROLES };
/* sample.h's roles are these, then each one's tie-break */
_Static_assert(SAMPLE_ROLE_COUNT == 2 * ROLES, "roles");

/* Anderson mixing of the SLP (slp()): the last few iterates of one
 * affine piece, and the least-squares step they give. */
struct slp_history {
	int len;		/* iterates held, <= SLP_MEMORY + 1 */
	double *c[SLP_MEMORY + 1], *f[SLP_MEMORY + 1];	/* c_i, N(c_i) - c_i */
};

struct sample_ws {
	const struct wall *w;
	struct statics st;
	int m, R;		/* interfaces, equilibrium rows */
	/* the workspace's LP solver, and one problem per LP role (see the
	 * top), so that between two solves of a role only bounds change and
	 * the solver keeps its basis */
	struct lp_solver *solver;
	struct lp *lp[ROLES];
	double *c;		/* m: SLP capacities (sum of normal forces) */
	double *cstar;		/* m: a piece's fixed point (slp) */
	double *fallback;	/* m: where a failed jump goes on (slp) */
	int slp_lp;		/* LP1 or LP2: where slp_map read the field */
	struct slp_history hist;	/* slp()'s Anderson memory */
	double *c0;		/* m: the SLP's start, for its restarts */
	double *x;		/* 3m: stress field of the last SLP LP */
	double *v;		/* R: velocities */
	double *dn, *dt;	/* 2m, m: joint rates */
	int *ind;		/* scratch */
	double *val;
	/* the tie-break weights of this sample ("One answer per sample"):
	 * r[2k + e] for contact point e of interface k, r[2m + k] for the
	 * slip of interface k; all in [1, 2), from the positions alone */
	double *r;
	double *c2;		/* a tie-break objective (scratch) */
	unsigned char *basic;	/* the support basis's columns (scratch) */
	enum sample_start start;	/* SLIPWALL_LP_START */
	int large;		/* `auto` takes its large-wall starts */
	int setup;		/* solving the canonical sample */
	int forces;		/* this sample reports its stress field */
	/* LPs by role, since the workspace was made (sample_ws_stats) */
	struct sample_lp_stats stats[SAMPLE_ROLE_COUNT];
	struct lp_basis canon[ROLES];	/* see set_points() */
	long memory_noted;	/* of the solver's memory errors */
};

/* The LP solvers' memory errors (sample_memory_errors): the one
 * process-wide tally, each workspace's added as its solver counts them
 * (note_memory), so that a front end that has a sample's result has
 * its errors too. */
static atomic_long memory_errors;

static void note_memory(struct sample_ws *ws)
{
	struct lp_counters c;
	lp_solver_counters(ws->solver, &c);
	if (c.memory_errors > ws->memory_noted) {
		atomic_fetch_add(&memory_errors,
				 c.memory_errors - ws->memory_noted);
		ws->memory_noted = c.memory_errors;
	}
}

/* Column indices. */
#define COL_LAMBDA(ws) (3 * (ws)->m)
/* associative problems: cone edges of point e (0: q_a, 1: q_b) */
#define ACOL_ALPHA(k, e) (4 * (k) + 2 * (e))
#define ACOL_BETA(k, e) (4 * (k) + 2 * (e) + 1)
#define ACOL_LAMBDA(ws) (4 * (ws)->m)
#define COL_P(ws, k) (3 * (ws)->m + 1 + (k))
#define COL_Q(ws, k) (3 * (ws)->m + 1 + (ws)->m + (k))
#define KCOL_SP(ws, k) ((ws)->R + (k))
#define KCOL_SM(ws, k) ((ws)->R + (ws)->m + (k))

/* Write column j of A into the associative and SLP problems (with the extra
 * rows each has) and row j into the kinematic problem. */
static void put_column(struct sample_ws *ws, int j)
{
	int rows[8], n;
	double vals[8];
	int k = j / 3, kind = j % 3;

	n = statics_column(&ws->st, j, rows, vals);
	/* kin: row j over the velocity columns, plus the slip split */
	int kn = n;
	int kcols[8];
	double kvals[8];
	memcpy(kcols, rows, sizeof(int) * (size_t)n);
	memcpy(kvals, vals, sizeof(double) * (size_t)n);
	if (kind == 2) {
		kcols[kn] = KCOL_SP(ws, k);
		kvals[kn++] = -1;
		kcols[kn] = KCOL_SM(ws, k);
		kvals[kn++] = 1;
	}
	lp_set_row(ws->lp[KIN], j, kn, kcols, kvals);

	/* AMAX, STAND, AMIN: the cone edges n +- mu t at this point */
	if (kind != 2) {
		for (int sgn = 0; sgn < 2; sgn++) {
			int er[6];
			double ev[6];
			int en = statics_edge_column(&ws->st, k, kind, sgn, er, ev);
			int col = sgn ? ACOL_BETA(k, kind) : ACOL_ALPHA(k, kind);
			for (int p = AMAX; p <= AMIN; p++)
				lp_set_col(ws->lp[p], col, en, er, ev);
		}
	}

	/* slp: closeness row for normal forces */
	int sn = n;
	if (kind != 2) {
		rows[sn] = ws->R + k;
		vals[sn++] = 1;
	}
	lp_set_col(ws->lp[LP1], j, n, rows, vals);	/* no closeness row */
	lp_set_col(ws->lp[LP2], j, sn, rows, vals);
}

/* The objective of the kinematic LP on the velocities: the sum of the
 * opening rates, i.e. the sum of the normal-force columns of A. */
static void put_kin_objective(struct sample_ws *ws)
{
	double *g = ws->val;
	memset(g, 0, sizeof(double) * (size_t)ws->R);
	for (int j = 0; j < 3 * ws->m; j++) {
		if (j % 3 == 2)
			continue;
		int rows[6];
		double vals[6];
		int n = statics_column(&ws->st, j, rows, vals);
		for (int i = 0; i < n; i++)
			g[rows[i]] += vals[i];
	}
	for (int i = 0; i < ws->R; i++)
		lp_set_obj(ws->lp[KIN], i, g[i]);
}

/* The rows, bounds and fixed columns of an associative problem (amax,
 * amin) or an SLP problem (lp1, lp2); the point-dependent columns are
 * written by put_column(). */
static void build_assoc(struct sample_ws *ws, struct lp *P)
{
	for (int i = 0; i < ws->R; i++)
		lp_set_row_bounds(P, i, -ws->st.fD[i], -ws->st.fD[i]);
	for (int j = 0; j < 4 * ws->m; j++)
		lp_set_col_bounds(P, j, 0, HUGE_VAL);
}

/* LP1 needs no closeness rows: without their free p, q columns its
 * optimum can be recognised as unique, and LP2 skipped. */
static void build_lp1(struct sample_ws *ws, struct lp *P)
{
	for (int i = 0; i < ws->R; i++)
		lp_set_row_bounds(P, i, -ws->st.fD[i], -ws->st.fD[i]);
	for (int j = 0; j < 3 * ws->m; j++)
		lp_set_col_bounds(P, j, j % 3 == 2 ? -HUGE_VAL : 0, HUGE_VAL);
}

static void build_slp(struct sample_ws *ws, struct lp *P)
{
	int m = ws->m, R = ws->R;
	for (int i = 0; i < R; i++)
		lp_set_row_bounds(P, i, -ws->st.fD[i], -ws->st.fD[i]);
	for (int j = 0; j < 3 * m; j++)
		lp_set_col_bounds(P, j, j % 3 == 2 ? -HUGE_VAL : 0, HUGE_VAL);
	for (int k = 0; k < m; k++) {
		lp_set_col_bounds(P, COL_P(ws, k), 0, HUGE_VAL);
		lp_set_col_bounds(P, COL_Q(ws, k), 0, HUGE_VAL);
	}
}

/* The part of the matrix that no contact point changes, written once
 * when the problems are built: LP2's closeness columns p and q, the
 * shears' columns and slip rows (a shear's moment does not depend on
 * where along the joint it acts), the live load's column and the
 * kinematic normalisation row f_L . v = 1. */
static void write_fixed(struct sample_ws *ws)
{
	int m = ws->m, R = ws->R;
	for (int k = 0; k < m; k++) {
		int row = R + k;
		double one = 1, mone = -1;
		lp_set_col(ws->lp[LP2], COL_P(ws, k), 1, &row, &mone);
		lp_set_col(ws->lp[LP2], COL_Q(ws, k), 1, &row, &one);
	}
	for (int k = 0; k < m; k++)
		put_column(ws, 3 * k + 2);
	int nl = 0;
	for (int i = 0; i < R; i++)
		if (ws->st.fL[i] != 0) {
			ws->ind[nl] = i;
			ws->val[nl++] = ws->st.fL[i];
		}
	for (int p = AMAX; p <= LP2; p++)
		lp_set_col(ws->lp[p], p <= AMIN ? ACOL_LAMBDA(ws) : COL_LAMBDA(ws),
			   nl, ws->ind, ws->val);
	lp_set_row(ws->lp[KIN], 3 * m, nl, ws->ind, ws->val);
}

/* Everything else, at the current contact points: every bound,
 * objective and sense, the normal-force columns and the opening-rate
 * rows (refill() writes them at every sample). */
static void write_points(struct sample_ws *ws)
{
	int m = ws->m, R = ws->R;
	for (int p = AMAX; p <= AMIN; p++)
		build_assoc(ws, ws->lp[p]);
	build_lp1(ws, ws->lp[LP1]);
	build_slp(ws, ws->lp[LP2]);
	for (int j = 0; j < 3 * m; j++)
		if (j % 3 != 2)
			put_column(ws, j);

	/* the objectives never change: max lambda (free) for LP-max and
	 * LP1, min lambda >= 0 for LP-min, min sum (p + q) for LP2 */
	lp_set_col_bounds(ws->lp[AMAX], ACOL_LAMBDA(ws), -HUGE_VAL, HUGE_VAL);
	lp_set_obj(ws->lp[AMAX], ACOL_LAMBDA(ws), 1);
	lp_set_maximize(ws->lp[AMAX], 1);
	lp_set_col_bounds(ws->lp[AMIN], ACOL_LAMBDA(ws), 0, HUGE_VAL);
	lp_set_obj(ws->lp[AMIN], ACOL_LAMBDA(ws), 1);
	lp_set_maximize(ws->lp[AMIN], 0);
	/* standing: is there an admissible field at lambda = 0?  No
	 * objective: the simplex stops at the first feasible basis (a
	 * minimum over the degenerate face costs hundreds of pivots) */
	lp_set_col_bounds(ws->lp[STAND], ACOL_LAMBDA(ws), 0, 0);
	lp_set_col_bounds(ws->lp[LP1], COL_LAMBDA(ws), -HUGE_VAL, HUGE_VAL);
	lp_set_obj(ws->lp[LP1], COL_LAMBDA(ws), 1);
	lp_set_maximize(ws->lp[LP1], 1);
	for (int k = 0; k < m; k++) {
		lp_set_obj(ws->lp[LP2], COL_P(ws, k), 1);
		lp_set_obj(ws->lp[LP2], COL_Q(ws, k), 1);
	}
	lp_set_maximize(ws->lp[LP2], 0);

	/* kin: the normalisation row = 1, velocities free, slips >= 0,
	 * slip rows = 0 */
	lp_set_row_bounds(ws->lp[KIN], 3 * m, 1, 1);
	for (int i = 0; i < R; i++)
		lp_set_col_bounds(ws->lp[KIN], i, -HUGE_VAL, HUGE_VAL);
	for (int k = 0; k < m; k++) {
		lp_set_col_bounds(ws->lp[KIN], KCOL_SP(ws, k), 0, HUGE_VAL);
		lp_set_col_bounds(ws->lp[KIN], KCOL_SM(ws, k), 0, HUGE_VAL);
		lp_set_obj(ws->lp[KIN], KCOL_SP(ws, k), 1);
		lp_set_obj(ws->lp[KIN], KCOL_SM(ws, k), 1);
		lp_set_row_bounds(ws->lp[KIN], 3 * k + 2, 0, 0);
	}
	lp_set_maximize(ws->lp[KIN], 0);
	put_kin_objective(ws);
}

/* The six problems, new.  The fixed part of the matrix is written first
 * and the points' part after it, as refill() will write it again: GLPK
 * puts the newest writes first in its row lists, so a problem rebuilt
 * after a GLPK error holds its matrix in the order of every other
 * sample's. */
static void build(struct sample_ws *ws)
{
	int m = ws->m, R = ws->R;
	for (int p = AMAX; p <= AMIN; p++)
		ws->lp[p] = lp_new(ws->solver, R, 4 * m + 1);
	ws->lp[LP1] = lp_new(ws->solver, R, 3 * m + 1);
	ws->lp[LP2] = lp_new(ws->solver, R + m, 3 * m + 1 + 2 * m);
	ws->lp[KIN] = lp_new(ws->solver, 3 * m + 1, R + 2 * m);
	write_fixed(ws);
	write_points(ws);
}

static void set_points(struct sample_ws *ws, const struct sample_draw *d);

/* Solve one sample at the classical contact (xi = 0, 1) from the freshly
 * built problems and keep the basis each role ended at: the start of
 * every later sample.  Deterministic: it depends on the wall only.  On
 * a large wall it skips the tie-breaks (tiebreak()): nothing of it is
 * reported. */
static void canonical_bases(struct sample_ws *ws)
{
	struct sample_opts o;
	struct sample_result r;
	sample_opts_default(&o);
	sample_result_init(&r, ws->w);
	struct sample_draw d;
	draw_init(&d, ws->w);
	draw_mean(&d, ws->w);	/* the classical contact, mean friction */
	ws->setup = 1;
	sample_run(ws, &d, &o, &r);
	ws->setup = 0;
	/* interrupted (sample_lp_config.stop): the problems are dead and the
	 * workspace is only fit to be freed; lp_basis_save skips them */
	for (int p = 0; p < ROLES; p++)
		lp_basis_save(ws->lp[p], &ws->canon[p]);
	draw_free(&d);
	sample_result_free(&r);
}

static struct sample_ws *ws_new(const struct wall *w,
				const struct sample_lp_config *c, int large)
{
	sw_init();	/* GSL's handler off before anderson_step can run */
	struct sample_ws *ws = sw_xcalloc(1, sizeof *ws);
	struct lp_config lc;
	lp_config_default(&lc);
	lc.fault_every = c->fault_every;
	lc.fault_as = c->fault_error ? LP_ERROR : LP_FAILED;
	lc.mem_limit_mb = c->mem_limit_mb;
	ws->solver = lp_solver_new(&lc);
	/* before the problems are written: a stop reaches them too */
	lp_solver_stop_flag(ws->solver, c->stop);
	lp_solver_progress(ws->solver, c->progress, c->progress_ctx);
	ws->w = w;
	ws->large = large;
	statics_init(&ws->st, w);
	ws->m = w->nifaces;
	ws->R = ws->st.nrows;
	size_t m = (size_t)ws->m, big = 3 * m + (size_t)ws->R + 16;
	ws->c = sw_xcalloc(m + 1, sizeof(double));
	ws->c0 = sw_xcalloc(m + 1, sizeof(double));
	ws->cstar = sw_xcalloc(m + 1, sizeof(double));
	ws->fallback = sw_xcalloc(m + 1, sizeof(double));
	for (int i = 0; i <= SLP_MEMORY; i++) {
		ws->hist.c[i] = sw_xcalloc(m + 1, sizeof(double));
		ws->hist.f[i] = sw_xcalloc(m + 1, sizeof(double));
	}
	ws->x = sw_xcalloc(3 * m + 1, sizeof(double));
	ws->v = sw_xcalloc((size_t)ws->R + 1, sizeof(double));
	ws->dn = sw_xcalloc(2 * m + 1, sizeof(double));
	ws->dt = sw_xcalloc(m + 1, sizeof(double));
	ws->ind = sw_xmalloc(sizeof(int) * big);
	ws->val = sw_xmalloc(sizeof(double) * big);
	ws->r = sw_xcalloc(3 * m + 1, sizeof(double));
	ws->c2 = sw_xcalloc(5 * m + (size_t)ws->R + 2, sizeof(double));
	ws->basic = sw_xcalloc(4 * m + 1, 1);
	ws->start = c->start;
	build(ws);
	canonical_bases(ws);
	return ws;
}

struct sample_ws *sample_ws_new_config(const struct wall *w,
				       const struct sample_lp_config *c)
{
	struct sample_lp_config d;
	if (!c) {
		sample_lp_config_default(&d);
		c = &d;
	}
	return ws_new(w, c, w->nifaces > AUTO_LARGE_IFACES);
}

struct sample_ws *sample_ws_new(const struct wall *w)
{
	return sample_ws_new_config(w, NULL);
}

struct sample_ws *sample_ws_new_start(const struct wall *w,
				      enum sample_start start)
{
	struct sample_lp_config c;
	sample_lp_config_default(&c);
	c.start = start;
	return sample_ws_new_config(w, &c);
}

struct sample_ws *sample_ws_new_auto_large(const struct wall *w)
{
	struct sample_lp_config c;
	sample_lp_config_default(&c);
	c.start = SAMPLE_START_AUTO;
	return ws_new(w, &c, 1);
}

void sample_ws_free(struct sample_ws *ws)
{
	if (!ws)
		return;
	for (int p = 0; p < ROLES; p++)
		lp_free(ws->lp[p]);
	statics_free(&ws->st);
	free(ws->c);
	free(ws->c0);
	free(ws->cstar);
	free(ws->fallback);
	for (int i = 0; i <= SLP_MEMORY; i++) {
		free(ws->hist.c[i]);
		free(ws->hist.f[i]);
	}
	free(ws->x);
	free(ws->v);
	free(ws->dn);
	free(ws->dt);
	free(ws->ind);
	free(ws->val);
	free(ws->r);
	free(ws->c2);
	free(ws->basic);
	for (int p = 0; p < ROLES; p++)
		lp_basis_free(&ws->canon[p]);
	note_memory(ws);
	lp_solver_free(ws->solver);
	free(ws);
}

void sample_ws_counters(const struct sample_ws *ws,
			struct sample_lp_counters *c)
{
	struct lp_counters lc;
	lp_solver_counters(ws->solver, &lc);
	c->solves = lc.solves;
	c->iterations = lc.iterations;
	c->held = lc.held;
	c->memory_errors = lc.memory_errors;
	c->seconds = lc.seconds;
}

int sample_ws_interrupted(const struct sample_ws *ws)
{
	return lp_solver_interrupted(ws->solver);
}

struct lp_solver *sample_ws_solver(struct sample_ws *ws)
{
	return ws->solver;
}

void sample_thread_done(void)
{
	lp_thread_done();
}

long sample_memory_errors(void)
{
	return atomic_load(&memory_errors);
}

/* Fresh problems, built at the current contact points (after a GLPK
 * error the old ones are dead). */
static void rebuild(struct sample_ws *ws)
{
	for (int p = 0; p < ROLES; p++)
		lp_free(ws->lp[p]);
	build(ws);
}

/* The same problems, written again at the current contact points: the
 * problems are built once per workspace (thread and wall).  lp_clear()
 * takes each back to what lp_new() left, the matrix kept (bounds,
 * objective, the standard basis, no factorization), and write_points()
 * writes every bound and objective again and of the matrix only what
 * the points change.  GLPK's row lists put the newest writes first, so
 * they are in the same order at every sample, and as build() left them:
 * a sample gives the same bits whatever the thread solved before
 * (test_sample solves samples in order and in reverse order on two
 * workspaces; the CSV is byte-identical whatever the thread count,
 * tests/cli/run.sh). */
static void refill(struct sample_ws *ws)
{
	for (int p = 0; p < ROLES; p++)
		if (!lp_alive(ws->lp[p])) {
			rebuild(ws);
			return;
		}
	for (int p = 0; p < ROLES; p++)
		lp_clear(ws->lp[p]);
	write_points(ws);
}


/* One LP of role `role` (or of its tie-break: role + ROLES), counted in
 * r and in the workspace's statistics; the problem is rebuilt after a
 * GLPK error. */
static enum lp_status counted(struct sample_ws *ws, int role, enum lp_method m,
			      const double *c2, struct sample_result *r)
{
	struct lp_counters c0, c1;
	lp_solver_counters(ws->solver, &c0);
	int solved = 1;
	struct lp *p = ws->lp[role % ROLES];
	enum lp_status s = c2 ? lp_tiebreak(p, c2, TOL_TIE, &solved)
			      : lp_solve(p, m);
	lp_solver_counters(ws->solver, &c1);
	struct sample_lp_stats *st = &ws->stats[role];
	st->lps += c1.solves - c0.solves;
	st->iterations += c1.iterations - c0.iterations;
	st->seconds += c1.seconds - c0.seconds;
	r->lps += solved;
	if (s == LP_ERROR)
		rebuild(ws);
	note_memory(ws);
	return s;
}

/* Count the LP and handle a dead environment.  A verdict of "infeasible"
 * or "unbounded" is not believed from a warm start: it is re-checked by the
 * primal simplex from the slack basis, a fixed path, whose verdict
 * stands.  (Measured on Ferris & Tin-Loi wall 2: LP-min, borderline
 * feasible where a dying normal force is held at 0, was "infeasible" by
 * the dual simplex from one start and optimal from the others.) */
static enum lp_status solve(struct sample_ws *ws, enum role role,
			    enum lp_method m, struct sample_result *r)
{
	enum lp_status s = counted(ws, role, m, NULL, r);
	if (s == LP_INFEASIBLE || s == LP_UNBOUNDED) {
		lp_reset_basis(ws->lp[role]);
		s = counted(ws, role, LP_PRIMAL, NULL, r);
	}
	return s;
}

/* The tie-break of role's optimum with the objective c2 (lp_tiebreak). */
static enum lp_status tiebreak(struct sample_ws *ws, enum role role,
			       const double *c2, struct sample_result *r)
{
	/* the canonical sample reports nothing: its bases need only be a
	 * function of the wall, which they are without the tie-breaks.  A
	 * large wall's canonical sample skips them (on a 10,000-block wall
	 * LP-max's is a global LP over the rest of the wall); a small
	 * wall's keeps them, for the better starts they give (Ferris &
	 * Tin-Loi wall 1: 550 pivots a sample, 585 without; on the
	 * 1,020-block wall the starts without them are the better ones:
	 * 20,481 pivots a sample, 21,868 with them) */
	if (ws->setup && ws->large)
		return LP_OPTIMAL;
	return counted(ws, role + ROLES, LP_PRIMAL, c2, r);
}

/* The names of the starts, in enum sample_start's order. */
static const char *const start_names[SAMPLE_START_COUNT] = {
	"slack-primal", "slack-dual", "crash", "canonical", "previous",
	"support", "auto",
};

const char *sample_start_name(enum sample_start s)
{
	return (unsigned)s < SAMPLE_START_COUNT ? start_names[s] : "?";
}

int sample_start_parse(const char *name)
{
	for (int s = 0; s < SAMPLE_START_COUNT; s++)
		if (!strcmp(name, start_names[s]))
			return s;
	return -1;
}

void sample_lp_config_default(struct sample_lp_config *c)
{
	memset(c, 0, sizeof *c);
	c->start = SAMPLE_START_DEFAULT;
}

int sample_lp_config_parse(struct sample_lp_config *c, const char *start,
			   const char *fault, const char *mem_mb, char *err)
{
	int rc = 0;
	if (start && *start) {
		int st = sample_start_parse(start);
		if (st >= 0)
			c->start = (enum sample_start)st;
		else
			rc = sw_fail(err, SW_EUSAGE, "SLIPWALL_LP_START='%s': "
				     "not a start; use auto, slack-primal, "
				     "slack-dual, crash, canonical, previous "
				     "or support", start);
	}
	if (fault && *fault) {	/* failed:N or error:N (or N: failed) */
		int error = 0;
		char *end;
		if (!strncmp(fault, "failed:", 7)) {
			fault += 7;
		} else if (!strncmp(fault, "error:", 6)) {
			error = 1;
			fault += 6;
		}
		long n = strtol(fault, &end, 10);
		if (*end || n <= 0) {
			if (!rc)
				rc = sw_fail(err, SW_EUSAGE, "SLIPWALL_LP_FAULT "
					     "must be failed:N or error:N, "
					     "N >= 1");
		} else {
			c->fault_every = n;
			c->fault_error = error;
		}
	}
	if (mem_mb && *mem_mb) {
		char *end;
		long n = strtol(mem_mb, &end, 10);
		if (*end || n <= 0 || n > INT_MAX) {
			if (!rc)
				rc = sw_fail(err, SW_EUSAGE, "SLIPWALL_GLPK_MEM_MB "
					     "must be a number of megabytes >= 1");
		} else {
			c->mem_limit_mb = (int)n;
		}
	}
	return rc ? -1 : 0;
}

/* A 64-bit mix of the bits of x and a salt (splitmix64's finaliser). */
static uint64_t bits_mix(double x, uint64_t salt)
{
	uint64_t z;
	x += 0.0;	/* -0 and +0 are one position */
	memcpy(&z, &x, sizeof z);
	z ^= salt * 0x9e3779b97f4a7c15ULL;
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return z ^ (z >> 31);
}

/* A uniform in [1, 2) from 64 bits (the top 53). */
static double unit_weight(uint64_t z)
{
	return 1 + (double)(z >> 11) * 0x1.0p-53;
}

/* The tie-break weights of the sample at positions xi: a hash of each
 * point's position and index (so a --positions replay has the same
 * weights, and the classical contact, where every xi is 0 or 1, still has
 * distinct ones); a slip's weight hashes both points of its interface. */
static void tie_weights(struct sample_ws *ws, const double *xi)
{
	int m = ws->m;
	for (int j = 0; j < 2 * m; j++)
		ws->r[j] = unit_weight(bits_mix(xi[j], (uint64_t)j + 1));
	for (int k = 0; k < m; k++)
		ws->r[2 * m + k] = unit_weight(bits_mix(xi[2 * k], 2 * (uint64_t)m + 1 + (uint64_t)k) ^
					       bits_mix(xi[2 * k + 1], 3 * (uint64_t)m + 1 + (uint64_t)k));
}

/* LP2's objective: min sum (p + q) + TIE_LP2 sum r_j N_j, the tie-break
 * (docs/method.md) folded into LP2's objective, so that LP2's optimum
 * is nearly always unique and no second LP runs (lp2_tiebreak is the
 * safety net).  The closeness term dominates: a move of the normal
 * forces changes sum r_j N_j by at most 2 per unit of sum |dN|, so the
 * weighted optimum is the lexicographic one unless the closeness changes
 * at less than 2e-4 of the rate of the forces, which a face of ties (rate
 * 0) is and an LP vertex almost never is.  Measured, against the exact
 * lexicographic answer (TIE_LP2 = 0 and a second LP whenever LP2 is not
 * unique): the same samples on the demo, Ferris & Tin-Loi 1 and 2, and
 * the same gilbert load of wall 2 from every start, for 25 % fewer
 * instructions.  1e-6 (the first value tried) is below GLPK's reduced
 * cost tolerance (1e-7) for weights closer than 0.1: ties it leaves
 * unresolved moved gilbert on wall 2 by 1e-4 from start to start. */
static void put_lp2_objective(struct sample_ws *ws)
{
	for (int k = 0; k < ws->m; k++)
		for (int e = 0; e < 2; e++)
			lp_set_obj(ws->lp[LP2], 3 * k + e, TIE_LP2 * ws->r[2 * k + e]);
}

/* `auto`: walls with more interfaces than this start LP2 from the slack
 * basis and solve LP-max by the primal simplex (from the canonical
 * basis, like every other role); smaller walls start every role from the
 * canonical bases, LP-max by the dual simplex.  Measured pivots per
 * sample (docs/performance.md): Ferris & Tin-Loi wall 2 (141
 * interfaces), LP-max 29 from the canonical basis by the dual simplex,
 * 59.5 by the primal, 407 from the slack basis by the primal; LP2 20.5
 * and 24.5 per solve (canonical, slack); the 1,020-block wall (2,956
 * interfaces), LP-max 20,744 (canonical, dual), 2,308 (canonical,
 * primal), 13,751 (slack, primal), the first LP2 of a sample 12,254 and
 * 3,884 (canonical, slack; the other roles: canonical fewer on both).
 * Large walls also start the standing check from the support basis
 * (support.c): 35.5 pivots, 2,092 from the canonical basis; and so the
 * associative problems of the canonical sample, solved when the
 * workspace is made (LP-max 3,322 pivots from the support basis, 13,751
 * from the slack basis).  AUTO_LARGE_IFACES is at the top of the file. */

/* Is this an `auto` workspace of a large wall (AUTO_LARGE_IFACES, or
 * sample_ws_new_auto_large)? */
static int auto_large(const struct sample_ws *ws)
{
	return ws->start == SAMPLE_START_AUTO && ws->large;
}

/* The start of role p's LPs in this workspace. */
static enum sample_start role_start(const struct sample_ws *ws, int p)
{
	/* The mechanism and LP-min take `auto`'s starts whatever the
	 * start asked for: one fixed path, a function of the wall alone,
	 * so that neither the mechanism nor a `numerical` verdict depends
	 * on the start.  Their optima are unique only to GLPK's tolerances
	 * on a few samples (a slip rate at the motion threshold, a
	 * virtual-work residual between 1e-8 and GLPK's 1e-7): measured on
	 * Ferris & Tin-Loi wall 2, seed 1, where 7 of 1,000 samples had
	 * another mechanism or status from another start (docs/method.md,
	 * "The SLP's answer").  The start option still drives LP-max, the
	 * standing check and the SLP's LP1 and LP2. */
	int fixed = p == KIN || p == AMIN;
	if (ws->start != SAMPLE_START_AUTO && !fixed)
		return ws->start;
	if (ws->large && p == LP2)
		return SAMPLE_START_SLACK_PRIMAL;
	/* the standing check from the support basis; so are the
	 * associative problems of the workspace's canonical sample, which
	 * has no canonical basis yet (they would start from the slack
	 * basis) */
	if (ws->large && (p == STAND || (ws->setup && p <= AMIN)))
		return SAMPLE_START_SUPPORT;
	return SAMPLE_START_CANONICAL;
}

/* Place the contact points and the tie-break weights, and choose every
 * problem's starting basis (SLIPWALL_LP_START).  With the tie-breaks a
 * sample is a function of its contact points alone, whatever the start
 * (tests/unit/test_start.c checks it); the start only decides how many
 * pivots it takes.  The default, `auto` (role_start), is a function of
 * the wall alone, so that the CSV is byte-identical whatever the thread
 * count, which `previous` (the basis the thread's last sample left)
 * cannot promise to the last bit.  For the same reason every start but
 * `previous` takes the problems back to a fresh state before it writes
 * the points (refill: no basis, no factorization kept from the last
 * sample). */
static void set_points(struct sample_ws *ws, const struct sample_draw *d)
{
	statics_set_draw(&ws->st, d);
	tie_weights(ws, d->xi);
	if (ws->start == SAMPLE_START_PREVIOUS) {
		for (int j = 0; j < 3 * ws->m; j++)
			put_column(ws, j);
		put_kin_objective(ws);
	} else {
		refill(ws);
	}
	put_lp2_objective(ws);
	int support = -1;	/* support_basis's verdict, once computed */
	for (int p = 0; p < ROLES; p++) {
		switch (role_start(ws, p)) {
		case SAMPLE_START_SUPPORT:
			if (p == LP1 || p == LP2 || p == KIN) {
				lp_reset_basis(ws->lp[p]);
				break;
			}
			if (support == -1)
				support = support_basis(&ws->st, ws->basic) >= 0;
			if (support)
				lp_set_basis(ws->lp[p], ws->basic);
			else
				lp_reset_basis(ws->lp[p]);
			break;
		case SAMPLE_START_SLACK_PRIMAL:
		case SAMPLE_START_SLACK_DUAL:
			lp_reset_basis(ws->lp[p]);
			break;
		case SAMPLE_START_CRASH:
			lp_crash_basis(ws->lp[p]);
			break;
		case SAMPLE_START_CANONICAL:
			lp_basis_load(ws->lp[p], &ws->canon[p]);
			break;
		default:
			break;
		}
	}
}

/* The tie-break of an associative problem (LP-max, LP-min): of its
 * optimal stress fields, the one with the least sum r_j N_j (N_j = alpha_j
 * + beta_j). */
static enum lp_status assoc_tiebreak(struct sample_ws *ws, enum role role,
				     struct sample_result *r)
{
	int m = ws->m;
	for (int k = 0; k < m; k++)
		for (int e = 0; e < 2; e++) {
			ws->c2[ACOL_ALPHA(k, e)] = ws->r[2 * k + e];
			ws->c2[ACOL_BETA(k, e)] = ws->r[2 * k + e];
		}
	ws->c2[ACOL_LAMBDA(ws)] = 0;
	return tiebreak(ws, role, ws->c2, r);
}

/* Release LP-min's fixings in amin: back to the plain associative
 * yield conditions. */
static void amin_reset(struct sample_ws *ws)
{
	for (int j = 0; j < 4 * ws->m; j++)
		lp_set_col_bounds(ws->lp[AMIN], j, 0, HUGE_VAL);
}

/* The stress field (N_a, N_b, T per interface, ws->x's layout) of the
 * cone-edge solution of an associative problem. */
static void assoc_field(const struct sample_ws *ws, const struct lp *P,
			double *x)
{
	for (int k = 0; k < ws->m; k++) {
		double mu = ws->st.mu[k], t = 0;
		for (int e = 0; e < 2; e++) {
			double a = lp_col(P, ACOL_ALPHA(k, e));
			double b = lp_col(P, ACOL_BETA(k, e));
			x[3 * k + e] = a + b;
			t += mu * (a - b);
		}
		x[3 * k + 2] = t;
	}
}

static enum sample_status lp_to_sample(enum lp_status s)
{
	switch (s) {
	case LP_OPTIMAL: return SAMPLE_ACCEPTED;
	case LP_INFEASIBLE: return SAMPLE_NO_EQUILIBRIUM;
	case LP_UNBOUNDED: return SAMPLE_UNBOUNDED;
	default: return SAMPLE_NUMERICAL;
	}
}

/* Step 2a: LP-max; leaves its stress field in ws->x and the SLP's
 * starting capacities in ws->c, and, if v is not NULL, the duals of its
 * equilibrium rows in v (the associative mechanism, before the
 * tie-break replaces them). */
static enum sample_status lp_max(struct sample_ws *ws, struct sample_result *r,
				 double *v)
{
	/* LP-max is degenerate: its optimal stress fields form a face, and
	 * the tie-break takes the one with the least sum r_j N_j, whatever
	 * vertex the simplex reached (the SLP's start).  The dual simplex
	 * from the start's basis, except for `slack-primal` and large walls
	 * under `auto` (role_start). */
	struct lp *P = ws->lp[AMAX];
	enum sample_start st = role_start(ws, AMAX);
	enum lp_method m = st == SAMPLE_START_SLACK_PRIMAL ||
			   st == SAMPLE_START_SUPPORT || auto_large(ws) ?
			   LP_PRIMAL : LP_DUAL;
	enum lp_status s = solve(ws, AMAX, m, r);
	/* A load factor <= 0 is re-checked by the primal simplex from the
	 * slack basis, as solve() re-checks a "no": the dual simplex has
	 * returned "optimal" at lambda = 0 where the LP's optimum is
	 * positive (5 of 1,000 LP-max problems of Ferris & Tin-Loi wall 1
	 * from the slack basis). */
	if (s == LP_OPTIMAL && !(lp_obj(P) > TOL_FORCE)) {
		lp_reset_basis(P);
		s = solve(ws, AMAX, LP_PRIMAL, r);
	}
	if (s != LP_OPTIMAL)
		return lp_to_sample(s);
	double lam = lp_obj(P);
	r->lambda_lpmax = lam;
	if (!(lam > TOL_FORCE))
		return SAMPLE_NONPOSITIVE;
	for (int i = 0; v && i < ws->R; i++)
		v[i] = lp_row_dual(P, i);
	s = assoc_tiebreak(ws, AMAX, r);
	if (s != LP_OPTIMAL)
		return SAMPLE_NUMERICAL;
	assoc_field(ws, P, ws->x);
	for (int k = 0; k < ws->m; k++)
		ws->c[k] = ws->x[3 * k] + ws->x[3 * k + 1];
	return SAMPLE_ACCEPTED;
}

/* Step 2a, after LP-max: can the wall stand under its own weight on
 * these contact points, is there an admissible field at lambda = 0?  The
 * admissible load factors form an interval that ends at LP-max's, so
 * this is a question of feasibility alone: the primal simplex's first
 * phase, from the canonical basis.  (LP-max's problem with lambda fixed
 * at 0, by the dual simplex from LP-max's optimum, gives the same answer
 * but walks lambda down through twice as many instructions.) */
static enum sample_status standing(struct sample_ws *ws,
				   struct sample_result *r)
{
	enum lp_status s = solve(ws, STAND, LP_PRIMAL, r);
	if (s == LP_OPTIMAL)
		return SAMPLE_ACCEPTED;
	return s == LP_INFEASIBLE ? SAMPLE_UNSTABLE : SAMPLE_NUMERICAL;
}

/* The shear capacity mu_k c_k of interface k in the SLP. */
static double capacity(const struct sample_ws *ws, int k)
{
	return ws->st.mu[k] * fmax(ws->c[k], 0);
}

/* LP2's feasible set: LP1's optimal face.  A column that is non-basic in
 * LP1's optimum with a non-zero reduced cost stays where LP1 left it, the
 * others keep LP1's bounds (complementary slackness: every optimal field
 * has those columns there, and every admissible field that has them
 * there is optimal).  LP1's own field lies on this face, so LP2 cannot be
 * infeasible; holding lambda >= lambda_LP1 exactly instead left no point
 * within GLPK's tolerances for 9 % of the samples of Ferris & Tin-Loi
 * wall 2, and any slack on lambda lets LP2 trade load for closeness
 * through columns that are far from optimal (docs/method.md). */
static void face_bounds(struct sample_ws *ws)
{
	struct lp *P = ws->lp[LP1], *Q = ws->lp[LP2];
	for (int j = 0; j <= 3 * ws->m; j++) {
		double lo = 0, hi = HUGE_VAL;	/* normal forces */
		if (j == COL_LAMBDA(ws)) {
			lo = -HUGE_VAL;
		} else if (j % 3 == 2) {
			hi = capacity(ws, j / 3);
			lo = -hi;
		}
		if (!lp_col_basic(P, j) && fabs(lp_col_dual(P, j)) > TOL_FACE)
			lo = hi = lp_col(P, j);
		lp_set_col_bounds(Q, j, lo, hi);
	}
	for (int k = 0; k < ws->m; k++)
		lp_set_row_bounds(Q, ws->R + k, ws->c[k], ws->c[k]);
}

/* LP2's tie-break, if its weighted optimum is still not unique: the
 * least sum r_j N_j on its optimal face. */
static enum lp_status lp2_tiebreak(struct sample_ws *ws, struct sample_result *r)
{
	int m = ws->m;
	memset(ws->c2, 0, sizeof(double) * (5 * (size_t)m + 1));
	for (int k = 0; k < m; k++)
		for (int e = 0; e < 2; e++)
			ws->c2[3 * k + e] = ws->r[2 * k + e];
	return tiebreak(ws, LP2, ws->c2, r);
}

/* Step 2b: the stabilised SLP from the capacities in ws->c.  Leaves the
 * converged stress field in ws->x and the load factor in r->lambda_max. */
/* One evaluation of the SLP's map at the capacities ws->c: LP1, and LP2
 * unless LP1's optimum is unique.  Leaves N(c)'s stress field in ws->x,
 * the load factor in *lam and max_k |N_k - c_k| in *diff. */
static enum sample_status slp_map(struct sample_ws *ws,
				  const struct sample_opts *o,
				  struct sample_result *r, double *lam,
				  double *diff)
{
	int m = ws->m;
	struct lp *P = ws->lp[LP1], *Q = ws->lp[LP2];
	for (int k = 0; k < m; k++)
		lp_set_col_bounds(P, 3 * k + 2, -capacity(ws, k), capacity(ws, k));
	/* LP1: the maximum load with fixed capacities (only bounds changed
	 * since the last LP1: a few dual simplex pivots) */
	enum lp_status s = solve(ws, LP1, LP_DUAL, r);
	if (s == LP_UNBOUNDED)
		return SAMPLE_UNBOUNDED;
	if (s == LP_INFEASIBLE)
		return SAMPLE_NOT_CONVERGED;
	if (s != LP_OPTIMAL)
		return SAMPLE_NUMERICAL;
	*lam = lp_obj(P);
	struct lp *X = P;	/* where the stress field is read */
	ws->slp_lp = LP1;
	/* LP2: of the optimal stress fields, the one whose normal forces
	 * are closest (L1) to c; skipped when LP1's optimal face is a single
	 * point.  Only bounds change between two LP2s, so the dual simplex
	 * from LP2's own last basis is short (the primal simplex from LP1's
	 * optimum walks the degenerate face for hundreds of pivots). */
	if (o->stabilise && !lp_unique(P, TOL_FACE)) {
		face_bounds(ws);
		s = solve(ws, LP2, LP_DUAL, r);
		if (s != LP_OPTIMAL)
			return SAMPLE_NUMERICAL;
		if (lp2_tiebreak(ws, r) != LP_OPTIMAL)
			return SAMPLE_NUMERICAL;
		/* on the face the load is LP1's but for the columns whose
		 * reduced costs count as zero (measured: 2e-9) */
		double lam2 = lp_col(Q, COL_LAMBDA(ws));
		if (!(fabs(lam2 - *lam) <= o->tol * fmax(1, fabs(*lam))))
			return SAMPLE_NUMERICAL;
		*lam = lam2;
		X = Q;
		ws->slp_lp = LP2;
	}
	*diff = 0;
	for (int j = 0; j < 3 * m; j++)
		ws->x[j] = lp_col(X, j);
	for (int k = 0; k < m; k++)
		*diff = fmax(*diff, fabs(ws->x[3 * k] + ws->x[3 * k + 1] - ws->c[k]));
	return SAMPLE_ACCEPTED;
}

/* The bases LP1 and LP2 ended at: while they stay, the SLP's map is one
 * affine piece. */
static unsigned long slp_piece(const struct sample_ws *ws)
{
	return lp_basis_hash(ws->lp[LP1]) * 31 + lp_basis_hash(ws->lp[LP2]);
}


/* The Anderson step (type II) from the iterates of h, the newest last:
 * gamma minimises |f_t - dF gamma| (dF's columns f_{i+1} - f_i; GSL's QR
 * least squares), and c <- c_t + omega f_t - (dC + omega dF) gamma.  On
 * an affine piece N(c) = P c + q this is GMRES on (I - P) c = q: exact
 * once the memory spans the residuals' Krylov space.  Returns 0 (and
 * leaves c alone) if the least-squares problem is degenerate or GSL
 * fails (an allocation: GSL's handler is off, sw_init, so it returns
 * NULL; a bad size: an error status). */
static int anderson_step(struct sample_ws *ws, const struct slp_history *h,
			 double omega, double *c)
{
	int m = ws->m, k = h->len - 1, t = h->len - 1;
	gsl_matrix *A = gsl_matrix_alloc((size_t)m, (size_t)k);
	gsl_vector *b = gsl_vector_alloc((size_t)m), *tau = gsl_vector_alloc((size_t)k);
	gsl_vector *g = gsl_vector_alloc((size_t)k), *res = gsl_vector_alloc((size_t)m);
	int ok = m > 0 && k > 0 && A && b && tau && g && res;
	for (int i = 0; ok && i < m; i++) {
		gsl_vector_set(b, (size_t)i, h->f[t][i]);
		for (int j = 0; j < k; j++)
			gsl_matrix_set(A, (size_t)i, (size_t)j, h->f[j + 1][i] - h->f[j][i]);
	}
	ok = ok && gsl_linalg_QR_decomp(A, tau) == 0;
	for (int j = 0; ok && j < k; j++)	/* a rank-deficient memory */
		ok = fabs(gsl_matrix_get(A, (size_t)j, (size_t)j)) > 1e-12;
	ok = ok && gsl_linalg_QR_lssolve(A, tau, b, g, res) == 0;
	for (int i = 0; ok && i < m; i++) {
		double v = h->c[t][i] + omega * h->f[t][i];
		for (int j = 0; j < k; j++) {
			double dc = h->c[j + 1][i] - h->c[j][i];
			double df = h->f[j + 1][i] - h->f[j][i];
			v -= (dc + omega * df) * gsl_vector_get(g, (size_t)j);
		}
		c[i] = v;
	}
	if (A)
		gsl_matrix_free(A);
	gsl_vector *vs[4] = {b, tau, g, res};
	for (int j = 0; j < 4; j++)
		if (vs[j])
			gsl_vector_free(vs[j]);
	return ok;
}

/* Add (c, N(c) - c) to h, dropping the oldest iterate when it is full. */
static void history_push(struct slp_history *h, const struct sample_ws *ws)
{
	int m = ws->m;
	if (h->len == SLP_MEMORY + 1) {
		double *c0 = h->c[0], *f0 = h->f[0];
		for (int i = 0; i < SLP_MEMORY; i++) {
			h->c[i] = h->c[i + 1];
			h->f[i] = h->f[i + 1];
		}
		h->c[SLP_MEMORY] = c0;
		h->f[SLP_MEMORY] = f0;
		h->len--;
	}
	for (int k = 0; k < m; k++) {
		h->c[h->len][k] = ws->c[k];
		h->f[h->len][k] = ws->x[3 * k] + ws->x[3 * k + 1] - ws->c[k];
	}
	h->len++;
}

static enum sample_status slp_piece_path(struct sample_ws *ws,
					const struct sample_opts *o,
					struct sample_result *r);

/* The SLP's plain step c <- c + omega (N(c) - c), N from the field ws->x. */
static void plain_step(struct sample_ws *ws, double omega)
{
	for (int k = 0; k < ws->m; k++) {
		double nk = ws->x[3 * k] + ws->x[3 * k + 1];
		ws->c[k] += omega * (nk - ws->c[k]);
	}
}

/* Step 2b: the stabilised SLP from the capacities in ws->c.  The plain
 * iteration is c <- c + omega (N(c) - c) (o->slp == SAMPLE_SLP_PLAIN);
 * SAMPLE_SLP_ANDERSON accelerates it, as below (the default,
 * SAMPLE_SLP_PIECE, is slp_piece_path's).  While LP1 and LP2 end at the same bases,
 * the map is one affine piece N(c) = P c + q, and the plain iteration
 * converges on it linearly (rate 1 - omega (1 - rho(P)), about 0.75 on
 * Ferris & Tin-Loi wall 1: 20-30 iterations for the last digits).  After
 * SLP_SETTLE iterations on one piece, the steps are Anderson's (memory
 * SLP_MEMORY, iterates of this piece only), once the residual is below
 * SLP_ACCEL_FROM; on an affine map they reach its fixed point in a few
 * steps.  A step that does not shrink the
 * residual max |N - c| is undone: the plain step from the last accepted
 * iterate is taken instead and the memory cleared.  (The landing point
 * itself is often on another piece - the limit lies on a boundary, where
 * a dying force reaches 0 - so "same piece" is not required of it.)
 * After SLP_TRIES accelerated steps without convergence, the plain
 * iteration starts again from LP-max's capacities (the iterations count
 * on).
 * docs/method.md has the measured agreement with the plain iteration.
 * Leaves the converged stress field in ws->x and the load factor in
 * r->lambda_max. */
static enum sample_status slp(struct sample_ws *ws,
			      const struct sample_opts *o,
			      struct sample_result *r)
{
	if (o->slp == SAMPLE_SLP_PIECE)
		return slp_piece_path(ws, o, r);
	int m = ws->m, settled = 0, trial = 0, tries = 0;
	double lam_prev = NAN, lam, diff, diff_prev = HUGE_VAL;
	unsigned long piece = 0;
	struct slp_history *h = &ws->hist;
	h->len = 0;
	int accel = o->slp == SAMPLE_SLP_ANDERSON;
	if (accel)	/* the start, for a plain restart */
		memcpy(ws->c0, ws->c, sizeof(double) * (size_t)m);
	for (int it = 1; it <= o->max_iter; it++) {
		r->iterations = it;
		if (accel && tries == SLP_TRIES) {
			/* no convergence within the accelerated steps: the
			 * plain iteration from the start, so that the sample
			 * reaches the plain iteration's fixed point */
			memcpy(ws->c, ws->c0, sizeof(double) * (size_t)m);
			accel = 0;
			trial = 0;
			lam_prev = NAN;
		}
		enum sample_status st = slp_map(ws, o, r, &lam, &diff);
		if (st != SAMPLE_ACCEPTED)
			return st;
		unsigned long pc = slp_piece(ws);
		if (trial && !(diff < diff_prev)) {
			/* undo the accelerated step: back to the last
			 * accepted iterate, then its plain step */
			memcpy(ws->c, h->c[h->len - 1], sizeof(double) * (size_t)m);
			for (int k = 0; k < m; k++)
				ws->c[k] += o->omega * h->f[h->len - 1][k];
			h->len = 0;
			settled = 0;
			trial = 0;
			continue;
		}
		r->lambda_max = lam;
		if (diff < o->tol && fabs(lam - lam_prev) < o->tol * fmax(1, fabs(lam))) {
			r->converged = 1;
			return SAMPLE_ACCEPTED;
		}
		lam_prev = lam;
		diff_prev = diff;
		if (pc != piece)
			h->len = 0;
		settled = pc == piece ? settled + 1 : 0;
		piece = pc;
		history_push(h, ws);
		trial = 0;
		if (accel && settled >= SLP_SETTLE && h->len >= 2 &&
		    diff < SLP_ACCEL_FROM &&
		    anderson_step(ws, h, o->omega, ws->c)) {
			trial = 1;
			tries++;
			continue;
		}
		plain_step(ws, o->omega);
	}
	return SAMPLE_NOT_CONVERGED;
}

/* A hash of the joints' classification at the SLP's field ws->x and
 * capacities ws->c: each contact point's normal force zero or not, each
 * shear at +mu c, at -mu c or inside, each interface's N_a + N_b above,
 * at or below c_k, all to SLP_CLASS_TOL.  Unlike the LP bases (the last
 * round's test), it is a function of the field alone, and the field is
 * the tie-broken LPs' unique answer: a degenerate vertex has several
 * optimal bases, and which one the simplex ends at depends on its start
 * (docs/method.md, "The SLP's answer"). */
static unsigned long slp_class(const struct sample_ws *ws)
{
	unsigned long h = 1469598103934665603UL;	/* FNV-1a */
	const double f0 = SLP_CLASS_TOL;
	for (int k = 0; k < ws->m; k++) {
		double na = ws->x[3 * k], nb = ws->x[3 * k + 1], t = ws->x[3 * k + 2];
		double cap = capacity(ws, k), d = na + nb - ws->c[k];
		int live = cap > f0;
		unsigned code = (unsigned)(na > f0) | (unsigned)(nb > f0) << 1 |
				(unsigned)(live && t >= cap - f0) << 2 |
				(unsigned)(live && t <= -cap + f0) << 3 |
				(unsigned)(d > f0) << 4 | (unsigned)(d < -f0) << 5;
		h = (h ^ code) * 1099511628211UL;
	}
	return h;
}

/* The fixed point of the affine piece the SLP's map is on at ws->c
 * (piece.c), into ws->cstar; 0, or -1 if it has none. */
static int piece_jump(struct sample_ws *ws)
{
	struct piece pc = {
		.m = ws->m, .R = ws->R, .closeness = ws->slp_lp == LP2,
		.mu = ws->st.mu,
	};
	if (piece_fixed_point(ws->lp[ws->slp_lp], &pc, ws->c, ws->cstar))
		return -1;
	for (int k = 0; k < ws->m; k++)
		if (!isfinite(ws->cstar[k]))
			return -1;
	return 0;
}

/* Step 2b, the default (SAMPLE_SLP_PIECE): the SLP's answer is the fixed
 * point of the piece the plain iteration settles on (docs/method.md,
 * "The SLP's answer").  Plain steps c <- c + omega (N(c) - c) until the
 * joints' classification (slp_class) has held for o->piece_settle
 * iterations; then c jumps to the exact fixed point c* of the current
 * affine piece (piece_jump; a negative capacity is 0), and the next
 * evaluation of the map verifies it: max |N(c*) - c*| <= PIECE_VERIFY,
 * round-off, means c* is a fixed point of the map itself, and the sample
 * is converged there.  Otherwise the iteration goes back to the iterate
 * before the jump and takes its plain step, and the classification is
 * counted afresh (going on from c* instead was measured: on the demo
 * wall, seed 1, 1,000 samples, 15.6 iterations a sample against 13.1,
 * one sample more not converged, and 5 of the 22 samples whose load
 * differs from the plain iteration's above it, against none).  A failed
 * jump thus leaves the plain path as it was; it is not tried again
 * while the classification stays the one it failed on (a cap of 40
 * jumps instead was spent by demo sample 1478, seed 2, while its
 * iteration wandered, and its end was left to the plain test, which
 * round-off decides: 385.433 N from one start, 387.914 N from another).
 * The plain test (residual and load below o->tol) still ends the
 * iteration if it comes first.  An iteration that has neither after
 * SLP_PHASE iterations is wandering, and over many non-contracting
 * steps the last-bit differences between LP starts grow until they
 * decide (sample 1478 again): it starts afresh from LP-max's capacities
 * (ws->c0) with half the step, for twice as many iterations, and so on
 * until o->max_iter; each phase is short enough for the differences to
 * stay below every decision.  Leaves the field in ws->x and
 * the load factor in r->lambda_max. */
static enum sample_status slp_piece_path(struct sample_ws *ws,
					const struct sample_opts *o,
					struct sample_result *r)
{
	int m = ws->m, settled = 0, jumped = 0, phase = 0;
	double lam_prev = NAN, lam, diff = HUGE_VAL, omega = o->omega;
	unsigned long cls = 0, failed = 0;
	memcpy(ws->c0, ws->c, sizeof(double) * (size_t)m);
	for (int it = 1; it <= o->max_iter; it++) {
		r->iterations = it;
		if (it - phase > SLP_PHASE * (o->omega / omega) &&
		    diff > SLP_WANDERING) {
			/* wandering: again from the start, damped twice as
			 * much, for twice as many iterations */
			phase = it - 1;
			omega /= 2;
			memcpy(ws->c, ws->c0, sizeof(double) * (size_t)m);
			settled = jumped = 0;
			cls = failed = 0;
			lam_prev = NAN;
		}
		enum sample_status st = slp_map(ws, o, r, &lam, &diff);
		if (st != SAMPLE_ACCEPTED)
			return st;
		r->lambda_max = lam;
		if (jumped && diff <= PIECE_VERIFY) {
			r->converged = 1;
			return SAMPLE_ACCEPTED;
		}
		if (jumped) {
			/* not a fixed point: back to the iterate before
			 * the jump, and its plain step (so a failed jump
			 * leaves the path as it was); no jump again while
			 * the classification stays the one it failed on */
			memcpy(ws->c, ws->fallback, sizeof(double) * (size_t)m);
			jumped = 0;
			settled = 0;
			failed = cls;
			continue;
		}
		if (diff < o->tol && fabs(lam - lam_prev) < o->tol * fmax(1, fabs(lam))) {
			r->converged = 1;
			return SAMPLE_ACCEPTED;
		}
		lam_prev = lam;
		unsigned long h = slp_class(ws);
		settled = h == cls ? settled + 1 : 0;
		cls = h;
		if (settled >= o->piece_settle && h != failed &&
		    piece_jump(ws) == 0) {
			/* the plain step, kept for a failed jump */
			plain_step(ws, omega);
			memcpy(ws->fallback, ws->c, sizeof(double) * (size_t)m);
			for (int k = 0; k < m; k++)
				ws->c[k] = fmax(ws->cstar[k], 0);
			jumped = 1;
			continue;
		}
		plain_step(ws, omega);
	}
	return SAMPLE_NOT_CONVERGED;
}

/* The kinematic LP's tie-break: of its least-motion mechanisms, the one
 * with the least weighted joint motion, sum r_j dn_j + sum r_k |dt_k|
 * (the opening rates in velocity space: the r-weighted sum of the
 * normal-force columns of A, as put_kin_objective). */
static enum lp_status kin_tiebreak(struct sample_ws *ws,
				   struct sample_result *r)
{
	int m = ws->m;
	double *g = ws->c2;
	memset(g, 0, sizeof(double) * ((size_t)ws->R + 2 * (size_t)m));
	for (int j = 0; j < 3 * m; j++) {
		if (j % 3 == 2)
			continue;
		int rows[6];
		double vals[6];
		int n = statics_column(&ws->st, j, rows, vals);
		double wj = ws->r[2 * (j / 3) + j % 3];
		for (int i = 0; i < n; i++)
			g[rows[i]] += wj * vals[i];
	}
	for (int k = 0; k < m; k++)
		g[KCOL_SP(ws, k)] = g[KCOL_SM(ws, k)] = ws->r[2 * m + k];
	return tiebreak(ws, KIN, g, r);
}

/* Step 3's LP: of the mechanisms whose motions the bounds of KIN allow
 * (its opening rows, its slip columns), the one with the least joint
 * motion for unit work of the live load.  Fills ws->v, ws->dn, ws->dt. */
static enum sample_status mechanism(struct sample_ws *ws,
				    struct sample_result *r)
{
	struct lp *K = ws->lp[KIN];
	enum lp_status s = solve(ws, KIN, LP_DUAL, r);
	if (s == LP_INFEASIBLE)
		return SAMPLE_NO_MECHANISM;
	if (s != LP_OPTIMAL)
		return SAMPLE_NUMERICAL;
	s = kin_tiebreak(ws, r);
	if (s != LP_OPTIMAL)
		return SAMPLE_NUMERICAL;
	for (int i = 0; i < ws->R; i++)
		ws->v[i] = lp_col(K, i);
	for (int k = 0; k < ws->m; k++) {
		ws->dn[2 * k] = lp_row(K, 3 * k);
		ws->dn[2 * k + 1] = lp_row(K, 3 * k + 1);
		ws->dt[k] = lp_col(K, KCOL_SP(ws, k)) - lp_col(K, KCOL_SM(ws, k));
	}
	return SAMPLE_ACCEPTED;
}

/* Step 3: a mechanism complementary to the stress field ws->x with
 * capacities mu c.  Fills ws->v, ws->dn, ws->dt. */
static enum sample_status onset(struct sample_ws *ws,
			       const struct sample_opts *o,
			       struct sample_result *r)
{
	/* a force below this is zero: an interface whose capacity is dying
	 * away decays geometrically (by omega per iteration) and still
	 * carries ~ tol when the SLP stops */
	double fzero = fmax(TOL_FORCE, 100 * o->tol);
	int m = ws->m;
	struct lp *K = ws->lp[KIN];
	for (int k = 0; k < m; k++) {
		for (int e = 0; e < 2; e++) {
			double nj = ws->x[3 * k + e];
			if (nj > fzero)
				lp_set_row_bounds(K, 3 * k + e, 0, 0);
			else
				lp_set_row_bounds(K, 3 * k + e, 0, HUGE_VAL);
		}
		double cap = capacity(ws, k);
		/* at the limit: GLPK leaves a basic shear up to ~1e-6
		 * (relative) inside its bound */
		double t = ws->x[3 * k + 2], tol = fzero + TOL_LIMIT * cap;
		double sp = 0, sm = 0;	/* upper bounds of s+, s- */
		if (cap <= fzero) {
			sp = sm = HUGE_VAL;	/* no contact: free to slide */
		} else if (t >= cap - tol) {
			sm = HUGE_VAL;	/* T > 0 opposes slip < 0 */
		} else if (t <= -cap + tol) {
			sp = HUGE_VAL;
		}
		lp_set_col_bounds(K, KCOL_SP(ws, k), 0, sp);
		lp_set_col_bounds(K, KCOL_SM(ws, k), 0, sm);
	}
	return mechanism(ws, r);
}

/* A joint rate of the mechanism counts as motion above this: TOL_MOTION
 * times the largest rate, but never below the kinematic LP's precision
 * (it is solved by the dual simplex: lp_feasibility_tol), for a rate
 * the LP holds only to its feasibility tolerance is not told from 0.
 * On a wall whose mechanism's rates are small (a body load over many
 * blocks, normalised to f_L . v = 1: largest rate 0.02 on a 195-block
 * wall) TOL_MOTION alone put the threshold at 2e-11, rates of 1e-10 at
 * GLPK's precision counted as motion, and LP-min, holding N = 0 and
 * T = -+mu N there, was infeasible (`numerical`; docs/method.md,
 * "Tolerances"). */
static double motion_threshold(const struct sample_ws *ws)
{
	double s = 0;
	for (int k = 0; k < ws->m; k++)
		s = fmax(s, fmax(fabs(ws->dt[k]),
				 fmax(fabs(ws->dn[2 * k]), fabs(ws->dn[2 * k + 1]))));
	return fmax(TOL_MOTION * s, lp_feasibility_tol(LP_DUAL));
}

/* Step 5: LP-min with the yield conditions that the mechanism uses held
 * at their limits, by the simplex method m from the basis AMIN holds.
 * Leaves the stress field in ws->x. */
static enum sample_status lp_min(struct sample_ws *ws, enum lp_method method,
				 struct sample_result *r)
{
	int m = ws->m;
	double thr = motion_threshold(ws);
	struct lp *P = ws->lp[AMIN];
	amin_reset(ws);
	for (int k = 0; k < m; k++) {
		for (int e = 0; e < 2; e++) {
			if (ws->dn[2 * k + e] > thr) {	/* N = 0 */
				lp_set_col_bounds(P, ACOL_ALPHA(k, e), 0, 0);
				lp_set_col_bounds(P, ACOL_BETA(k, e), 0, 0);
			}
			if (ws->dt[k] > thr)	/* T = -mu (Na + Nb) */
				lp_set_col_bounds(P, ACOL_ALPHA(k, e), 0, 0);
			else if (ws->dt[k] < -thr)	/* T = +mu (Na + Nb) */
				lp_set_col_bounds(P, ACOL_BETA(k, e), 0, 0);
		}
	}
	enum lp_status s = solve(ws, AMIN, method, r);
	if (s != LP_OPTIMAL)
		return SAMPLE_NUMERICAL;
	r->lambda_min = lp_obj(P);
	/* the reported stress field: of LP-min's optima, the tie-break's.
	 * Unreported (sample_opts.forces), any optimum will do: lambda_min
	 * is the optimum's value, and the virtual-work identity holds for
	 * every field LP-min admits (its bounds hold N = 0 where the
	 * mechanism opens and T = -+mu N where it slides), so neither
	 * depends on the vertex.  The tie-break is LP-min's second LP and,
	 * on the 1,020-block wall, a sample's costliest (9,300 pivots,
	 * docs/performance.md). */
	if (ws->forces && assoc_tiebreak(ws, AMIN, r) != LP_OPTIMAL)
		return SAMPLE_NUMERICAL;
	assoc_field(ws, P, ws->x);
	return SAMPLE_ACCEPTED;
}

/* lambda (f_L . v) = sum mu (Na + Nb) |dt| - f_D . v, relative residual. */
static double virtual_work(const struct sample_ws *ws, double lam)
{
	double fl = 0, fd = 0, diss = 0;
	for (int i = 0; i < ws->R; i++) {
		fl += ws->st.fL[i] * ws->v[i];
		fd += ws->st.fD[i] * ws->v[i];
	}
	for (int k = 0; k < ws->m; k++)
		diss += ws->st.mu[k] * (ws->x[3 * k] + ws->x[3 * k + 1]) *
			fabs(ws->dt[k]);
	double lhs = lam * fl, rhs = diss - fd;
	double scale = fmax(fabs(lhs), fmax(fabs(rhs), fabs(fd)));
	return fabs(lhs - rhs) / fmax(scale, 1e-300);
}

/* Scaled results of the workspace into real units in r. */
static void export(struct sample_ws *ws, struct sample_result *r)
{
	const struct wall *w = ws->w;
	double F = ws->st.F, L = ws->st.L, vmax = 0;
	memset(r->vel, 0, sizeof(double) * 3 * (size_t)w->nblocks);
	for (int b = 0; b < w->nblocks; b++) {
		int e = w->blocks[b].eq;
		if (e < 0)
			continue;
		r->vel[3 * b] = ws->v[3 * e];
		r->vel[3 * b + 1] = ws->v[3 * e + 1];
		r->vel[3 * b + 2] = ws->v[3 * e + 2] / L;
		vmax = fmax(vmax, hypot(ws->v[3 * e], ws->v[3 * e + 1]));
		vmax = fmax(vmax, fabs(ws->v[3 * e + 2]));
	}
	double thr = motion_threshold(ws);
	for (int i = 0; i < 3 * w->nblocks && vmax > 0; i++)
		r->vel[i] /= vmax;
	for (int k = 0; k < ws->m; k++) {
		int oa = ws->dn[2 * k] > thr, ob = ws->dn[2 * k + 1] > thr;
		int sl = fabs(ws->dt[k]) > thr;
		char c = JOINT_CLOSED;
		if (oa && ob)
			c = JOINT_OPENS;
		else if (oa || ob)
			c = sl ? JOINT_HINGE_SLIDES : JOINT_HINGES;
		else if (sl)
			c = JOINT_SLIDES;
		r->joint[k] = c;
		r->dn[2 * k] = vmax > 0 ? ws->dn[2 * k] / vmax : 0;
		r->dn[2 * k + 1] = vmax > 0 ? ws->dn[2 * k + 1] / vmax : 0;
		r->dt[k] = vmax > 0 ? ws->dt[k] / vmax : 0;
		r->N[2 * k] = ws->forces ? ws->x[3 * k] * F : NAN;
		r->N[2 * k + 1] = ws->forces ? ws->x[3 * k + 1] * F : NAN;
		r->T[k] = ws->forces ? ws->x[3 * k + 2] * F : NAN;
	}
	r->joint[ws->m] = 0;
}

/* A sample's result, reset, and its problems built for its draw d;
 * forces: it reports its stress field. */
static void begin(struct sample_ws *ws, const struct sample_draw *d,
		  int forces, struct sample_result *r)
{
	ws->forces = forces;
	r->status = SAMPLE_NUMERICAL;
	r->lambda_lpmax = r->lambda_max = r->lambda_min = NAN;
	r->iterations = 0;
	r->converged = 0;
	r->lps = 0;
	r->vw_residual = NAN;
	set_points(ws, d);
}

/* After step 3 found a mechanism (st accepted): LP-min, the virtual work
 * check and the export; loads to the user's units, the status into r. */
static void finish(struct sample_ws *ws, enum sample_status st,
		   struct sample_result *r)
{
	double S = ws->st.S;
	if (st == SAMPLE_ACCEPTED) {
		st = lp_min(ws, LP_DUAL, r);
		if (st == SAMPLE_ACCEPTED)
			r->vw_residual = virtual_work(ws, r->lambda_min);
		/* a residual above VW_TOL is the LP's precision (GLPK's
		 * bound tolerance is 1e-7) as often as a wrong answer: it is
		 * not believed from a warm start, but re-checked from the
		 * slack basis (the mechanism, then LP-min by the primal
		 * simplex), a fixed path (measured: 1.8e-7 from GLPK's crash
		 * basis, 3e-15 from the slack basis, on one sample of Ferris &
		 * Tin-Loi wall 2).  (Re-checking LP-min's failures the same
		 * way was measured and changes no status on Ferris & Tin-Loi
		 * wall 2, seed 1, 1,000 samples from any start: not done, so
		 * that an LP that fails costs its sample, test_faults.) */
		if (st == SAMPLE_ACCEPTED && !(r->vw_residual <= VW_TOL)) {
			lp_reset_basis(ws->lp[KIN]);
			lp_reset_basis(ws->lp[AMIN]);
			st = mechanism(ws, r);
			if (st == SAMPLE_ACCEPTED)
				st = lp_min(ws, LP_PRIMAL, r);
			if (st == SAMPLE_ACCEPTED)
				r->vw_residual = virtual_work(ws, r->lambda_min);
		}
		if (st == SAMPLE_ACCEPTED && !(r->vw_residual <= VW_TOL))
			st = SAMPLE_NUMERICAL;
	}
	if (st == SAMPLE_ACCEPTED)
		export(ws, r);
	r->lambda_lpmax *= S;
	r->lambda_max *= S;
	r->lambda_min *= S;
	r->status = st;
}

void sample_run(struct sample_ws *ws, const struct sample_draw *d,
		const struct sample_opts *o, struct sample_result *r)
{
	begin(ws, d, o->forces, r);
	enum sample_status st = lp_max(ws, r, NULL);
	if (st == SAMPLE_ACCEPTED)
		st = standing(ws, r);
	if (st == SAMPLE_ACCEPTED)
		st = slp(ws, o, r);
	if (st == SAMPLE_ACCEPTED)
		st = onset(ws, o, r);
	finish(ws, st, r);
}

enum sample_status sample_pattern(struct sample_ws *ws,
				  const struct sample_draw *d,
				  const unsigned char *open,
				  const unsigned char *slip,
				  struct sample_result *r)
{
	begin(ws, d, 1, r);
	struct lp *K = ws->lp[KIN];
	for (int k = 0; k < ws->m; k++) {
		for (int e = 0; e < 2; e++)
			lp_set_row_bounds(K, 3 * k + e, 0,
					  open[2 * k + e] ? HUGE_VAL : 0);
		lp_set_col_bounds(K, KCOL_SP(ws, k), 0,
				  slip[k] & SAMPLE_SLIP_POS ? HUGE_VAL : 0);
		lp_set_col_bounds(K, KCOL_SM(ws, k), 0,
				  slip[k] & SAMPLE_SLIP_NEG ? HUGE_VAL : 0);
	}
	finish(ws, mechanism(ws, r), r);
	return r->status;
}

const struct statics *sample_statics(const struct sample_ws *ws)
{
	return &ws->st;
}

void sample_export(struct sample_ws *ws, const double *v, const double *x,
		   struct sample_result *r)
{
	ws->forces = 1;
	memcpy(ws->v, v, sizeof(double) * (size_t)ws->R);
	memcpy(ws->x, x, sizeof(double) * 3 * (size_t)ws->m);
	for (int k = 0; k < ws->m; k++) {
		ws->dn[2 * k] = statics_rate(&ws->st, 3 * k, ws->v);
		ws->dn[2 * k + 1] = statics_rate(&ws->st, 3 * k + 1, ws->v);
		ws->dt[k] = statics_rate(&ws->st, 3 * k + 2, ws->v);
	}
	export(ws, r);
}

enum sample_status sample_standard(struct sample_ws *ws,
				   const struct sample_draw *d,
				   struct sample_result *r)
{
	r->lps = 0;
	r->lambda_lpmax = r->lambda_max = r->lambda_min = NAN;
	set_points(ws, d);
	/* the mechanism: the duals of LP-max's equilibrium rows, scaled so
	 * that f_L . v = 1; the stress field: LP-max's, by the tie-break */
	double *v = sw_xmalloc(sizeof(double) * ((size_t)ws->R + 1));
	enum sample_status st = lp_max(ws, r, v);
	if (st != SAMPLE_ACCEPTED) {
		r->lambda_lpmax *= ws->st.S;
		free(v);
		return r->status = st;
	}
	double fl = 0;
	for (int i = 0; i < ws->R; i++)
		fl += ws->st.fL[i] * v[i];
	for (int i = 0; i < ws->R && fl != 0; i++)
		v[i] /= fl;
	double *x = sw_xmalloc(sizeof(double) * (3 * (size_t)ws->m + 1));
	memcpy(x, ws->x, sizeof(double) * 3 * (size_t)ws->m);
	r->lambda_lpmax *= ws->st.S;
	st = standing(ws, r);
	if (st == SAMPLE_ACCEPTED) {
		sample_export(ws, v, x, r);
		r->lambda_max = r->lambda_min = r->lambda_lpmax;
	}
	free(v);
	free(x);
	return r->status = st;
}

static const char *const role_names[SAMPLE_ROLE_COUNT] = {
	"LP-max", "standing", "LP-min", "LP1", "LP2", "kinematic",
	"LP-max tie", "standing tie", "LP-min tie", "LP1 tie", "LP2 tie",
	"kinematic tie",
};

const char *sample_role_name(int role)
{
	return role >= 0 && role < SAMPLE_ROLE_COUNT ? role_names[role] : "?";
}

void sample_ws_stats(const struct sample_ws *ws,
		     struct sample_lp_stats out[SAMPLE_ROLE_COUNT])
{
	memcpy(out, ws->stats, sizeof ws->stats);
}
