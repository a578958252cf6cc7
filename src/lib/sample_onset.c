/*
 * sample_onset.c - the associative and kinematic steps of a sample
 * (docs/method.md, "One sample"): step 2a, LP-max (the SLP's start and
 * the standard method's answer) and the standing check; step 3, the
 * mechanism complementary to the SLP's stress field (onset, from the
 * basis complementary to LP1's: kin_from_lp1) or to a given pattern
 * (sws_mechanism, sample_pattern); step 5, LP-min with the
 * mechanism's yield conditions at their limits, and the virtual-work
 * check; and the export of the scaled results into real units.  The
 * problems are sample_lp.c's, the tie-breaks sample_tie.c's, the
 * capacities the SLP's (sample_slp.c); sample.c's sample_run, finish
 * and entry points call these in order.
 *
 * Tolerances (scaled units, mean block weight = 1): a normal force counts
 * as positive above TOL_FORCE; a joint rate counts as motion above
 * TOL_MOTION times the largest rate of the mechanism, and above the
 * kinematic LP's precision (motion_threshold).  docs/method.md says why.
 */
#include <math.h>
#include <string.h>

#include "sample_ws.h"

#define TOL_FORCE 1e-7
#define TOL_MOTION 1e-9
#define TOL_LIMIT 1e-5
/* the virtual-work identity's residual beyond the work of the rates
 * that are not motion (sws_virtual_work) */
#define VW_TOL 1e-8

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

/* The SLP's start from P's field (an associative problem's): the field
 * into ws->x, its normal-force sums, the capacities, into ws->c. */
static void slp_start_from(struct sample_ws *ws, const struct lp *P)
{
	assoc_field(ws, P, ws->x);
	for (int k = 0; k < ws->m; k++)
		ws->c[k] = ws->x[3 * k] + ws->x[3 * k + 1];
}

/* A load factor's verdict, for LP-max's (step 2) and the SLP's
 * (sws_slp_load): at or below 0 (TOL_FORCE) the wall cannot carry its
 * own weight at these contact points, `nonpositive`. */
static enum sample_status load_verdict(double lam)
{
	return lam > TOL_FORCE ? SAMPLE_ACCEPTED : SAMPLE_NONPOSITIVE;
}

/* Step 2a: LP-max; leaves its stress field in ws->x and the SLP's
 * starting capacities in ws->c, and, if v is not NULL, the duals of its
 * equilibrium rows in v (the associative mechanism, before the
 * tie-break replaces them). */
enum sample_status sws_lp_max(struct sample_ws *ws, struct sample_result *r,
				 double *v)
{
	/* LP-max is degenerate: its optimal stress fields form a face, and
	 * the tie-break takes the one with the least sum r_j N_j, whatever
	 * vertex the simplex reached (the SLP's start).  One fixed path
	 * whatever the start option: its start is sws_role_start's, its
	 * method sws_lp_max_method's. */
	struct lp *P = ws->lp[AMAX];
	enum lp_status s = sws_solve(ws, AMAX, sws_lp_max_method(ws), r);
	/* A load factor <= 0 is re-checked by the primal simplex from the
	 * slack basis, as sws_solve() re-checks a "no": the dual simplex has
	 * returned "optimal" at lambda = 0 where the LP's optimum is
	 * positive (5 of 1,000 LP-max problems of Ferris & Tin-Loi wall 1
	 * from the slack basis). */
	if (s == LP_OPTIMAL && !(lp_obj(P) > TOL_FORCE)) {
		lp_reset_basis(P);
		s = sws_solve(ws, AMAX, LP_PRIMAL, r);
	}
	if (s != LP_OPTIMAL)
		return lp_to_sample(s);
	double lam = lp_obj(P);
	r->lambda_lpmax = lam;
	if (load_verdict(lam) != SAMPLE_ACCEPTED)
		return SAMPLE_NONPOSITIVE;
	for (int i = 0; v && i < ws->R; i++)
		v[i] = lp_row_dual(P, i);
	s = sws_assoc_tiebreak(ws, AMAX, r);
	if (s != LP_OPTIMAL)
		return SAMPLE_NUMERICAL;
	slp_start_from(ws, P);
	return SAMPLE_ACCEPTED;
}

/* The SLP's load factor, before step 3: at or below 0 (TOL_FORCE) the
 * non-associative stress state it converged to cannot carry the wall's
 * own weight at these contact points, where LP-max's associative one
 * could, and the sample is `nonpositive`, the reason LP-max gives for
 * the same load (step 2).  Without this, step 3 found a mechanism and
 * LP-min (min lambda >= 0, below lambda_max) was infeasible by
 * construction, so the sample was `numerical`: a running-bond wall of
 * 8 courses with `positions: anywhere`, seed 3, sample 2, whose SLP
 * converged at lambda_max = -0.0356 (docs/method.md, "Rejection
 * reasons"). */
enum sample_status sws_slp_load(const struct sample_result *r)
{
	return load_verdict(r->lambda_max);
}

/* The SLP's start below LP-max's optimum (sws_floor_tiebreak): its
 * stress field into ws->x and its capacities into ws->c. */
enum sample_status sws_lp_max_floor(struct sample_ws *ws,
				    struct sample_result *r)
{
	if (sws_floor_tiebreak(ws, r->lambda_lpmax, r) != LP_OPTIMAL)
		return SAMPLE_NUMERICAL;
	slp_start_from(ws, ws->lp[AMAX]);
	return SAMPLE_ACCEPTED;
}

/* Step 2a, after LP-max: can the wall stand under its own weight on
 * these contact points, is there an admissible field at lambda = 0?  The
 * admissible load factors form an interval that ends at LP-max's, so
 * this is a question of feasibility alone: the primal simplex's first
 * phase, from the canonical basis.  (LP-max's problem with lambda fixed
 * at 0, by the dual simplex from LP-max's optimum, gives the same answer
 * but walks lambda down through twice as many instructions.) */
enum sample_status sws_standing(struct sample_ws *ws,
				   struct sample_result *r)
{
	enum lp_status s = sws_solve(ws, STAND, LP_PRIMAL, r);
	if (s == LP_OPTIMAL)
		return SAMPLE_ACCEPTED;
	return s == LP_INFEASIBLE ? SAMPLE_UNSTABLE : SAMPLE_NUMERICAL;
}

void sws_kin_allow(struct sample_ws *ws, int k, unsigned bits)
{
	struct lp *K = ws->lp[KIN];
	ws->kfree[k] = (unsigned char)bits;
	lp_set_row_bounds(K, 3 * k, 0, bits & KIN_OPEN_A ? HUGE_VAL : 0);
	lp_set_row_bounds(K, 3 * k + 1, 0, bits & KIN_OPEN_B ? HUGE_VAL : 0);
	lp_set_col_bounds(K, KCOL_SP(ws, k), 0,
			  bits & KIN_SLIP_POS ? HUGE_VAL : 0);
	lp_set_col_bounds(K, KCOL_SM(ws, k), 0,
			  bits & KIN_SLIP_NEG ? HUGE_VAL : 0);
}

/* Does the mechanism open contact point e of interface k, slide
 * interface k (+1, -1; 0: no)?  A rate counts above the motion
 * threshold thr, and only where KIN's bounds let it move: a rate that
 * KIN holds at 0 is 0 by the LP's definition, and what it reads there is
 * the solver's slack on a fixed row or column (up to 2e-9 on a
 * 310-block wall, where the field carries 1.2 block weights: counted
 * as an opening, it made LP-min infeasible; docs/method.md,
 * "Body-loaded walls of real size"). */
static int opens(const struct sample_ws *ws, int k, int e, double thr)
{
	return ws->kfree[k] & (e ? KIN_OPEN_B : KIN_OPEN_A) &&
	       ws->dn[2 * k + e] > thr;
}

static int slides(const struct sample_ws *ws, int k, double thr)
{
	if (ws->kfree[k] & KIN_SLIP_POS && ws->dt[k] > thr)
		return 1;
	if (ws->kfree[k] & KIN_SLIP_NEG && ws->dt[k] < -thr)
		return -1;
	return 0;
}

/* Step 3's LP: of the mechanisms whose motions the bounds of KIN allow
 * (its opening rows, its slip columns), the one with the least joint
 * motion for unit work of the live load, by the simplex method meth
 * from the basis KIN holds.  Fills ws->v, ws->dn, ws->dt. */
static enum sample_status mechanism(struct sample_ws *ws,
				    enum lp_method meth,
				    struct sample_result *r)
{
	struct lp *K = ws->lp[KIN];
	enum lp_status s = sws_solve(ws, KIN, meth, r);
	if (s == LP_INFEASIBLE)
		return SAMPLE_NO_MECHANISM;
	if (s != LP_OPTIMAL)
		return SAMPLE_NUMERICAL;
	s = sws_kin_tiebreak(ws, r);
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

/* Step 3's LP from the basis KIN holds, by the dual simplex: after a
 * pattern's bounds (sample_pattern) or from the slack basis (sample.c's
 * re-check). */
enum sample_status sws_mechanism(struct sample_ws *ws,
				    struct sample_result *r)
{
	return mechanism(ws, LP_DUAL, r);
}

/* KIN's start at the SLP's end: the basis complementary to LP1's optimal
 * basis (docs/method.md and docs/performance.md, "The mechanism from
 * LP1's basis").  KIN is LP1's dual, transposed: its row j is the rate
 * (A^T v)_j of LP1's column j (the normal force or shear of one
 * contact), its row 3m is f_L . v = 1 against LP1's lambda column, and
 * its velocity columns stand for LP1's equilibrium rows.  So a column
 * basic in LP1 makes KIN's row of it non-basic (rate 0: the force is off
 * its bound), one non-basic in LP1 makes the row basic (the rate is free
 * to move), and an equilibrium row non-basic in LP1 (as they all are but
 * a degenerate one) makes its velocity basic.  A shear's rate is split,
 * s+ - s-: a shear non-basic at +mu c takes s- (T > 0 opposes slip < 0),
 * at -mu c s+, a fixed one (no capacity) the side its reduced cost asks
 * for.  The counts match (KIN has 3m + 1 rows: LP1's R basics leave
 * 3m + 1 of the R + 3m + 1 for KIN), and the basis matrix is LP1's basis
 * matrix transposed, up to the slips' unit columns: non-singular when
 * LP1's is.  Its basic solution is LP1's optimal dual, a mechanism
 * complementary to every optimal field of LP1, the SLP's field among
 * them (LP2 takes it from LP1's optimal face): so the start is primal
 * feasible for the bounds sws_onset reads off that field, up to the
 * force zero and round-off, and the primal simplex goes on from it to
 * the least motion.  On the paper's walls the answer is the same as from
 * any other start (KIN's tie-break) and only the pivots move; on walls
 * of hundreds of blocks the optimum is decided only to the simplex's
 * tolerances, and loads moved by up to 1.5e-5 of themselves
 * (docs/method.md, "The mechanism from LP1's basis").  Returns 0, and
 * leaves KIN's basis, if LP1's cannot be read (a dead problem). */
static int kin_from_lp1(struct sample_ws *ws)
{
	int m = ws->m, R = ws->R, nk = 3 * m + 1;
	struct lp_basis *b1 = &ws->lp1_end, *bk = &ws->kin_start;
	if (!lp_alive(ws->lp[LP1]))
		return 0;
	lp_basis_save(ws->lp[LP1], b1);
	const int *row1 = b1->stat, *col1 = b1->stat + R;
	int *row = lp_basis_size(bk, nk + R + 2 * m), *col = row + nk;
	for (int j = 0; j < nk; j++)
		row[j] = col1[j] == LP_BS ? LP_NL : LP_BS;
	for (int i = 0; i < R; i++)
		col[i] = row1[i] == LP_BS ? LP_NF : LP_BS;
	for (int k = 0; k < m; k++) {
		int j = 3 * k + 2, st = col1[j];
		row[j] = LP_NS;
		if (st == LP_NS)
			st = lp_col_dual(ws->lp[LP1], j) > 0 ? LP_NU : LP_NL;
		col[KCOL_SP(ws, k)] = st == LP_NL ? LP_BS : LP_NL;
		col[KCOL_SM(ws, k)] = st == LP_NU ? LP_BS : LP_NL;
	}
	lp_basis_load(ws->lp[KIN], bk);
	return 1;
}

/* Step 3: a mechanism complementary to the stress field ws->x with
 * capacities mu c.  Fills ws->v, ws->dn, ws->dt.  A normal force below
 * the force zero counts as 0: with SWS_ZERO_DYING, max(TOL_FORCE,
 * 100 tol), for an interface whose capacity is dying away decays
 * geometrically (by omega per iteration) and still carries ~ tol when
 * the SLP stops; with SWS_ZERO_STRICT, TOL_FORCE (sample.c's retry when
 * LP-min finds the first mechanism's fixings infeasible). */
enum sample_status sws_onset(struct sample_ws *ws,
			       const struct sample_opts *o,
			       enum sws_force_zero z, struct sample_result *r)
{
	double fzero = z == SWS_ZERO_STRICT ? TOL_FORCE :
		       fmax(TOL_FORCE, 100 * o->tol);
	int m = ws->m;
	for (int k = 0; k < m; k++) {
		unsigned bits = 0;
		if (!(ws->x[3 * k] > fzero))
			bits |= KIN_OPEN_A;
		if (!(ws->x[3 * k + 1] > fzero))
			bits |= KIN_OPEN_B;
		double cap = sws_capacity(ws, k);
		/* at the limit: GLPK leaves a basic shear up to ~1e-6
		 * (relative) inside its bound */
		double t = ws->x[3 * k + 2], tol = fzero + TOL_LIMIT * cap;
		if (cap <= fzero)
			bits |= KIN_SLIP_POS | KIN_SLIP_NEG;	/* no contact */
		else if (t >= cap - tol)
			bits |= KIN_SLIP_NEG;	/* T > 0 opposes slip < 0 */
		else if (t <= -cap + tol)
			bits |= KIN_SLIP_POS;
		sws_kin_allow(ws, k, bits);
	}
	return mechanism(ws, kin_from_lp1(ws) ? LP_PRIMAL : LP_DUAL, r);
}

/* A joint rate of the mechanism counts as motion above this: TOL_MOTION
 * times the largest rate, but never below the kinematic LP's precision
 * (the dual simplex's feasibility tolerance, lp_feasibility_tol), for a
 * rate the LP holds only to its feasibility tolerance is not told from
 * 0.  (The onset's kinematic LP is solved by the primal simplex from
 * LP1's complementary basis, kin_from_lp1, and GLPK's primal allows
 * 1e-8; a floor of 1e-8 failed two samples' virtual work, docs/
 * method.md, "Tolerances", and no status moved with the floor kept.)
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

/* LP-min's problem for the mechanism in ws->dn, ws->dt: LP-max's with the
 * yield conditions that the mechanism uses held at their limits. */
static void amin_fix(struct sample_ws *ws)
{
	int m = ws->m;
	double thr = motion_threshold(ws);
	struct lp *P = ws->lp[AMIN];
	amin_reset(ws);
	for (int k = 0; k < m; k++) {
		int sl = slides(ws, k, thr);
		for (int e = 0; e < 2; e++) {
			if (opens(ws, k, e, thr)) {	/* N = 0 */
				lp_set_col_bounds(P, ACOL_ALPHA(k, e), 0, 0);
				lp_set_col_bounds(P, ACOL_BETA(k, e), 0, 0);
			}
			if (sl > 0)	/* T = -mu (Na + Nb) */
				lp_set_col_bounds(P, ACOL_ALPHA(k, e), 0, 0);
			else if (sl < 0)	/* T = +mu (Na + Nb) */
				lp_set_col_bounds(P, ACOL_BETA(k, e), 0, 0);
		}
	}
}

/* LP-min's first solve alone (sample_ws.h). */
enum lp_status sws_lp_min_once(struct sample_ws *ws, struct sample_result *r)
{
	amin_fix(ws);
	return sws_counted(ws, AMIN, LP_DUAL, NULL, r);
}

/* Step 5: LP-min, by the simplex method method from the basis AMIN
 * holds.  Leaves the stress field in ws->x. */
enum sample_status sws_lp_min(struct sample_ws *ws, enum lp_method method,
				 struct sample_result *r, enum lp_status *lps)
{
	struct lp *P = ws->lp[AMIN];
	amin_fix(ws);
	enum lp_status s = sws_solve(ws, AMIN, method, r);
	if (lps)
		*lps = s;
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
	if (ws->forces && sws_assoc_tiebreak(ws, AMIN, r) != LP_OPTIMAL)
		return SAMPLE_NUMERICAL;
	assoc_field(ws, P, ws->x);
	return SAMPLE_ACCEPTED;
}

/* The virtual-work check of step 6 (docs/method.md, "One sample" and
 * "Tolerances"): lambda (f_L . v) = sum mu (Na + Nb) |dt| - f_D . v with
 * LP-min's forces and the mechanism's rates; returns the relative
 * residual, and in *allow the residual it may have.
 *
 * Equilibrium dotted with v gives lambda f_L . v + f_D . v =
 * -sum_k (Na dn_a + Nb dn_b + T dt) for any admissible field, to the LPs'
 * precision.  The check then writes the flow rule in: N dn = 0 where the
 * mechanism opens, T dt = -mu N |dt| where it slides.  LP-min holds
 * those exactly where the mechanism moves (opens(), slides()), so there
 * the substitution costs nothing; at the rates that do not count as
 * motion (below the motion threshold, or held at 0 by KIN) it costs
 * their work, |N dn| and |T dt + mu N |dt||, at most the threshold
 * times the forces.  That work is the wall's own (it grows with its
 * forces and joints: 1.5e-8 to 1.2e-7 of the load's work on a
 * 310-block wall, 1e-14 on the paper's walls), so it is added to the
 * allowance.  So is the LPs' precision: LP-min's field meets its
 * equilibrium rows and its friction rows only to the simplex's
 * feasibility tolerance eps (the primal's, 1e-8, the looser of the two
 * and the re-check's), and a residual eps in row i does work eps |v_i|
 * against the mechanism, eps (1 + mu_k) |dt_k| in interface k's
 * friction rows; on a 243-block facade at friction 1.0 that is 4.5e-8 of
 * the load's work, and two samples' residuals of 1.4e-8 were rejected
 * (docs/method.md, "Tolerances").  The allowance is VW_TOL for the rest:
 * an LP-min field off its bounds or out of equilibrium by more than the
 * LP's precision, a mechanism off its rows, still fail. */
double sws_virtual_work(const struct sample_ws *ws, double lam, double *allow)
{
	double fl = 0, fd = 0, diss = 0, still = 0, motion = 0;
	double thr = motion_threshold(ws);
	for (int i = 0; i < ws->R; i++) {
		fl += ws->st.fL[i] * ws->v[i];
		fd += ws->st.fD[i] * ws->v[i];
		motion += fabs(ws->v[i]);
	}
	for (int k = 0; k < ws->m; k++) {
		double N = ws->x[3 * k] + ws->x[3 * k + 1], T = ws->x[3 * k + 2];
		double dt = ws->dt[k];
		motion += (1 + ws->st.mu[k]) * fabs(dt);
		diss += ws->st.mu[k] * N * fabs(dt);
		for (int e = 0; e < 2; e++)
			if (!opens(ws, k, e, thr))
				still += fabs(ws->x[3 * k + e] * ws->dn[2 * k + e]);
		if (!slides(ws, k, thr))
			still += fabs(T * dt + ws->st.mu[k] * N * fabs(dt));
	}
	double lhs = lam * fl, rhs = diss - fd;
	double scale = fmax(fmax(fabs(lhs), fabs(rhs)), fmax(fabs(fd), 1e-300));
	*allow = VW_TOL + (still + lp_feasibility_tol(LP_PRIMAL) * motion) / scale;
	return fabs(lhs - rhs) / scale;
}

/* Scaled results of the workspace into real units in r. */
void sws_export(struct sample_ws *ws, struct sample_result *r)
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
		int oa = opens(ws, k, 0, thr), ob = opens(ws, k, 1, thr);
		int sl = slides(ws, k, thr) != 0;
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
