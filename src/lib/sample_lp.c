/*
 * sample_lp.c - the LPs of a sample workspace (docs/method.md, "One
 * sample"): their formulation (the roles and the column layout are in
 * sample_ws.h), built once per workspace on its own LP solver (lp.h),
 * written again at each sample (sws_refill; docs/method.md, "One answer
 * per sample" says why every sample must see the same problems), and
 * every solve of them, counted by role in the workspace's statistics
 * and re-checked where a warm start's verdict is not believed.  The
 * contact points' part of the matrix is written by sws_put_column, also
 * from sample_start.c's sws_set_points; the tie-breaks (sample_tie.c)
 * solve through sws_counted.  sample_lp.h gives the solver to the
 * library's other LP users (global.c).
 */
#include <math.h>
#include <stdatomic.h>
#include <string.h>

#include "sample_lp.h"
#include "sample_ws.h"

/* a reduced cost at or below this may be zero: the optimum may not be
 * unique, and the tie-break LP runs (docs/method.md) */
#define TOL_TIE 1e-9

/* Write column j of A into the associative and SLP problems (with the extra
 * rows each has) and row j into the kinematic problem. */
void sws_put_column(struct sample_ws *ws, int j)
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
void sws_put_kin_objective(struct sample_ws *ws)
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

/* The live load's column, f_L's non-zeros, into ws->ind and ws->val
 * (R entries each); returns their count. */
int sws_live_load(struct sample_ws *ws)
{
	int nl = 0;
	for (int i = 0; i < ws->R; i++)
		if (ws->st.fL[i] != 0) {
			ws->ind[nl] = i;
			ws->val[nl++] = ws->st.fL[i];
		}
	return nl;
}

/* Each equilibrium row of P at its dead load: A x + lambda f_L = -f_D
 * (docs/method.md, "The operator").  Every problem's rows are
 * written by it, and so are LP1's put back after lp1_weightless
 * (sample_slp.c) took a weight away. */
void sws_put_dead_load(struct sample_ws *ws, struct lp *P)
{
	for (int i = 0; i < ws->R; i++)
		lp_set_row_bounds(P, i, -ws->st.fD[i], -ws->st.fD[i]);
}

/* The rows, bounds and fixed columns of an associative problem (amax,
 * amin) or an SLP problem (lp1, lp2); the point-dependent columns are
 * written by sws_put_column(). */
static void build_assoc(struct sample_ws *ws, struct lp *P)
{
	sws_put_dead_load(ws, P);
	for (int j = 0; j < 4 * ws->m; j++)
		lp_set_col_bounds(P, j, 0, HUGE_VAL);
}

/* LP1 needs no closeness rows: without their free p, q columns its
 * optimum can be recognised as unique, and LP2 skipped. */
static void build_lp1(struct sample_ws *ws, struct lp *P)
{
	sws_put_dead_load(ws, P);
	for (int j = 0; j < 3 * ws->m; j++)
		lp_set_col_bounds(P, j, j % 3 == 2 ? -HUGE_VAL : 0, HUGE_VAL);
}

static void build_slp(struct sample_ws *ws, struct lp *P)
{
	int m = ws->m;
	sws_put_dead_load(ws, P);
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
		sws_put_column(ws, 3 * k + 2);
	int nl = sws_live_load(ws);
	for (int p = AMAX; p <= LP2; p++)
		lp_set_col(ws->lp[p], p <= AMIN ? ACOL_LAMBDA(ws) : COL_LAMBDA(ws),
			   nl, ws->ind, ws->val);
	lp_set_row(ws->lp[KIN], 3 * m, nl, ws->ind, ws->val);
}

/* Everything else, at the current contact points: every bound,
 * objective and sense, the normal-force columns and the opening-rate
 * rows (sws_refill() writes them at every sample). */
static void write_points(struct sample_ws *ws)
{
	int m = ws->m, R = ws->R;
	for (int p = AMAX; p <= AMIN; p++)
		build_assoc(ws, ws->lp[p]);
	build_lp1(ws, ws->lp[LP1]);
	build_slp(ws, ws->lp[LP2]);
	for (int j = 0; j < 3 * m; j++)
		if (j % 3 != 2)
			sws_put_column(ws, j);

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
	sws_put_kin_objective(ws);
}

/* LP-min's dual infeasible starts by shifted costs above this many
 * interfaces (sws_build) */
#define AMIN_SHIFT_IFACES 100
/* on walls of at most REFACTOR_IFACES interfaces, each problem's basis
 * factorization is computed afresh once its updates have added
 * REFACTOR_UPDATES factors, not GLPK's 100 (sws_build) */
#define REFACTOR_IFACES 400
#define REFACTOR_UPDATES 40

/* The six problems, new.  The fixed part of the matrix is written first
 * and the points' part after it, as sws_refill() will write it again: GLPK
 * puts the newest writes first in its row lists, so a problem rebuilt
 * after a GLPK error holds its matrix in the order of every other
 * sample's. */
void sws_build(struct sample_ws *ws)
{
	int m = ws->m, R = ws->R;
	for (int p = AMAX; p <= AMIN; p++)
		ws->lp[p] = lp_new(ws->solver, R, 4 * m + 1);
	ws->lp[LP1] = lp_new(ws->solver, R, 3 * m + 1);
	ws->lp[LP2] = lp_new(ws->solver, R + m, 3 * m + 1 + 2 * m);
	ws->lp[KIN] = lp_new(ws->solver, 3 * m + 1, R + 2 * m);
	/* the SLP's re-solves: one objective, bounds moved (the capacities,
	 * LP2's face), and a start dual infeasible in a few columns that
	 * the face freed.  Shifted costs there, artificial bounds elsewhere
	 * (lp.h; docs/performance.md, "Shifted costs").  LP-min takes them
	 * on walls of more than AMIN_SHIFT_IFACES interfaces: from its
	 * canonical basis, under the mechanism's fixings, 100.0 pivots an
	 * LP against 189.3 on tests/data/body-195.yaml, 18.6 against 29.9
	 * on Ferris & Tin-Loi wall 2; on the demo (66 interfaces) 187.4
	 * against 89.9 (docs/method.md, "LP-min by shifted costs on walls
	 * of more than 100 interfaces"; docs/performance.md, "The standing
	 * check from the support basis, and LP-min by shifted costs") */
	lp_set_shift_costs(ws->lp[LP1], 1);
	lp_set_shift_costs(ws->lp[LP2], 1);
	lp_set_shift_costs(ws->lp[AMIN], m > AMIN_SHIFT_IFACES);
	/* the factorization's updates (lp.h, lp_set_refactor).  A sample's
	 * LPs are re-solves of a few pivots each, and the updates pile up
	 * across them: at 40 instead of 100, 14 % fewer instructions a
	 * sample on Ferris & Tin-Loi wall 1, 21 % on the demo, 14 % on wall
	 * 2, and 2-5 % less time on walls/body-100.yaml (286 interfaces)
	 * and 2 % on a 415-interface wall.  On larger walls a factorization
	 * costs more than the updates it saves: 3-8 % more time at 486 and
	 * 543 interfaces (tests/data/body-195.yaml), and walls/
	 * body-1000.yaml's set-up, whose solves from the slack basis take
	 * thousands of pivots, 58 % more (docs/performance.md, "The
	 * factorization's updates") */
	if (m <= REFACTOR_IFACES)
		for (int p = 0; p < ROLES; p++)
			lp_set_refactor(ws->lp[p], REFACTOR_UPDATES);
	write_fixed(ws);
	write_points(ws);
}

struct lp_solver *sample_ws_solver(struct sample_ws *ws)
{
	return ws->solver;
}

/* Fresh problems, built at the current contact points (after a GLPK
 * error the old ones are dead). */
static void rebuild(struct sample_ws *ws)
{
	for (int p = 0; p < ROLES; p++)
		lp_free(ws->lp[p]);
	sws_build(ws);
}

/* The same problems, written again at the current contact points: the
 * problems are built once per workspace (thread and wall).  lp_clear()
 * takes each back to what lp_new() left, the matrix kept (bounds,
 * objective, the standard basis, no factorization), and write_points()
 * writes every bound and objective again and of the matrix only what
 * the points change.  GLPK's row lists put the newest writes first, so
 * they are in the same order at every sample, and as sws_build() left them:
 * a sample gives the same bits whatever the thread solved before
 * (test_sample solves samples in order and in reverse order on two
 * workspaces; the CSV is byte-identical whatever the thread count,
 * tests/cli/run.sh). */
void sws_refill(struct sample_ws *ws)
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
static enum lp_status counted_end(struct sample_ws *ws, int role,
				  const struct lp_counters *c0, int solved,
				  enum lp_status s, struct sample_result *r)
{
	struct lp_counters c1;
	lp_solver_counters(ws->solver, &c1);
	struct sample_lp_stats *st = &ws->stats[role];
	st->lps += c1.solves - c0->solves;
	st->iterations += c1.iterations - c0->iterations;
	st->seconds += c1.seconds - c0->seconds;
	r->lps += solved;
	if (s == LP_ERROR)
		rebuild(ws);
	sws_note_memory(ws);
	return s;
}

enum lp_status sws_counted(struct sample_ws *ws, int role, enum lp_method m,
			      const double *c2, struct sample_result *r)
{
	struct lp_counters c0;
	lp_solver_counters(ws->solver, &c0);
	int solved = 1;
	struct lp *p = ws->lp[role % ROLES];
	enum lp_status s = c2 ? lp_tiebreak(p, c2, TOL_TIE, &solved)
			      : lp_solve(p, m);
	return counted_end(ws, role, &c0, solved, s, r);
}

/* The tie-break below an optimum (lp_tiebreak_floor: column col at
 * least lo), counted as sws_counted counts. */
enum lp_status sws_counted_floor(struct sample_ws *ws, int role,
				 const double *c2, int col, double lo,
				 struct sample_result *r)
{
	struct lp_counters c0;
	lp_solver_counters(ws->solver, &c0);
	int solved = 1;
	enum lp_status s = lp_tiebreak_floor(ws->lp[role % ROLES], c2, col,
					     lo, &solved);
	return counted_end(ws, role, &c0, solved, s, r);
}

/* Count the LP and handle a dead environment.  A verdict of "infeasible"
 * or "unbounded" is not believed from a warm start: it is re-checked by the
 * primal simplex from the slack basis, a fixed path, whose verdict
 * stands.  (Measured on Ferris & Tin-Loi wall 2: LP-min, borderline
 * feasible where a dying normal force is held at 0, was "infeasible" by
 * the dual simplex from one start and optimal from the others.) */
enum lp_status sws_solve(struct sample_ws *ws, enum role role,
			    enum lp_method m, struct sample_result *r)
{
	enum lp_status s = sws_counted(ws, role, m, NULL, r);
	if (s == LP_INFEASIBLE || s == LP_UNBOUNDED) {
		lp_reset_basis(ws->lp[role]);
		s = sws_counted(ws, role, LP_PRIMAL, NULL, r);
	}
	return s;
}

/* The LP solvers' memory errors (sample_memory_errors): the one
 * process-wide tally, each workspace's added as its solver counts them
 * (sws_note_memory), so that a front end that has a sample's result has
 * its errors too. */
static atomic_long memory_errors;

void sws_note_memory(struct sample_ws *ws)
{
	struct lp_counters c;
	lp_solver_counters(ws->solver, &c);
	if (c.memory_errors > ws->memory_noted) {
		atomic_fetch_add(&memory_errors,
				 c.memory_errors - ws->memory_noted);
		ws->memory_noted = c.memory_errors;
	}
}

long sample_memory_errors(void)
{
	return atomic_load(&memory_errors);
}
