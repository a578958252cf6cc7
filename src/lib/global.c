/*
 * global.c - the global method's mixed-integer program (solve.c, solve.h):
 * built on the LP solver of the sample workspace it checks its pattern
 * with (sample_lp.h).
 *
 * global is a mixed-integer program over statics and kinematics at once
 * (Ferris & Tin-Loi 2001 posed it as an MPEC; here complementarity is
 * encoded with binaries).  In scaled units (statics.h):
 *
 *   min lambda
 *   A x + lambda f_L = -f_D                        equilibrium
 *   |T_k| <= mu_k (Na + Nb),  N >= 0                yield
 *   dn_j = (A^T v)_j in [0, z_j]                   opening only if z_j
 *   N_j <= M (1 - z_j)                             ... and then N_j = 0
 *   dt_k = (A^T v)_T = s+ - s-,  s+- in [0, y+-]   slip only if y+-
 *   mu (Na + Nb) + T <= 2 mu M (1 - y+)            s+ > 0: T = -mu (Na+Nb)
 *   mu (Na + Nb) - T <= 2 mu M (1 - y-)            s- > 0: T = +mu (Na+Nb)
 *   y+ + y- <= 1                                   one way at a time
 *   sum dn + sum (s+ + s-) = 1                     a mechanism (normalised)
 *   f_L . v >= eps                                 driven by the live load
 *
 * With the total joint motion normalised to 1, every rate is at most 1,
 * so the kinematic big-M is exactly 1.  The static big-M is the largest
 * total normal force of any statically admissible field with
 * 0 <= lambda <= lambda_standard (one LP); every onset-of-collapse load
 * is at most the standard one, so no solution is cut off.  When that LP
 * is unbounded (self-stress can grow without limit) a fallback bound is
 * used and the result says the bounds were not derived.
 *
 * Without "one way at a time" a joint with N = T = 0 could slip both ways
 * at once, s+ = s- = 1/2: one unit of "motion" in which nothing moves.
 * The live load's work then came from slips of ~3e-7 at joints whose
 * binaries GLPK takes as 0 (its integrality tolerance is 1e-5), and the
 * program "proved" lambda = 0 for 164 of the 200 small walls of
 * tests/unit/test_solve.c and for Ferris & Tin-Loi wall 1.  So the program's
 * own numbers are not taken as the answer: its solution is read as a
 * collapse pattern only - which points open, which joints slip and which
 * way (where its binaries allow it and its rates are motion, not noise)
 * - and sample_pattern finds, by exact LPs, the least-motion mechanism
 * within that pattern with unit work of the live load, and the
 * least load that keeps it (LP-min): a true onset-of-collapse load, with
 * its mechanism and forces.  The
 * program's optimum is reported beside it as the lower bound it would be
 * in exact arithmetic; optimality is claimed only where the two agree.
 * A pattern that admits no exact mechanism is a failure, not a number.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "global.h"
#include "sample_lp.h"
#include "statics.h"

#define GLOBAL_EPS_WORK 1e-6
/* the verified load and the program's bound agree: optimality holds */
#define GLOBAL_AGREE 1e-6
/* a rate of the program's mechanism (total motion 1) that is motion: far
 * above the ~3e-7 that GLPK's integrality tolerance lets through */
#define GLOBAL_MOTION 1e-6

/* Column indices of the global problem. */
struct glayout {
	int m, R;
	int lam, v, sp, sm, z, yp, ym, ncols;
	int eq, fr, kn0, kn1, ks, ksp, ksm, one, cn, cp, cm, norm, work, nrows;
};

static void glayout(struct glayout *g, int m, int R)
{
	g->m = m;
	g->R = R;
	g->lam = 3 * m;
	g->v = g->lam + 1;
	g->sp = g->v + R;
	g->sm = g->sp + m;
	g->z = g->sm + m;
	g->yp = g->z + 2 * m;
	g->ym = g->yp + m;
	g->ncols = g->ym + m;
	g->eq = 0;
	g->fr = R;		/* 2 per interface */
	g->kn0 = g->fr + 2 * m;	/* A_j^T v >= 0, 2 per interface */
	g->kn1 = g->kn0 + 2 * m;	/* A_j^T v - z_j <= 0 */
	g->ks = g->kn1 + 2 * m;	/* A_T^T v - s+ + s- = 0 */
	g->ksp = g->ks + m;	/* s+ - y+ <= 0 */
	g->ksm = g->ksp + m;	/* s- - y- <= 0 */
	g->one = g->ksm + m;	/* y+ + y- <= 1 */
	g->cn = g->one + m;	/* N_j + M z_j <= M, 2 per interface */
	g->cp = g->cn + 2 * m;	/* mu(Na+Nb) + T + Mf y+ <= Mf */
	g->cm = g->cp + m;	/* mu(Na+Nb) - T + Mf y- <= Mf */
	g->norm = g->cm + m;
	g->work = g->norm + 1;
	g->nrows = g->work + 1;
}

/* The largest total normal force over the admissible fields with
 * 0 <= lambda <= lam_hi; HUGE_VAL when unbounded. */
static double max_total_normal(struct lp_solver *solver,
			       const struct statics *st, double lam_hi)
{
	const struct wall *w = st->w;
	int m = w->nifaces, R = st->nrows;
	struct lp *P = lp_new(solver, R + 2 * m, 3 * m + 1);
	int rows[10];
	double vals[10];
	for (int i = 0; i < R; i++)
		lp_set_row_bounds(P, i, -st->fD[i], -st->fD[i]);
	for (int j = 0; j < 3 * m; j++) {
		int k = j / 3, n = statics_column(st, j, rows, vals);
		double mu = st->mu[k];
		if (j % 3 == 2) {
			rows[n] = R + 2 * k;
			vals[n++] = 1;
			rows[n] = R + 2 * k + 1;
			vals[n++] = -1;
			lp_set_col_bounds(P, j, -HUGE_VAL, HUGE_VAL);
		} else {
			rows[n] = R + 2 * k;
			vals[n++] = -mu;
			rows[n] = R + 2 * k + 1;
			vals[n++] = -mu;
			lp_set_col_bounds(P, j, 0, HUGE_VAL);
			lp_set_obj(P, j, 1);
		}
		lp_set_col(P, j, n, rows, vals);
	}
	for (int r = 0; r < 2 * m; r++)
		lp_set_row_bounds(P, R + r, -HUGE_VAL, 0);
	int nl = 0;
	for (int i = 0; i < R; i++)
		nl += st->fL[i] != 0;
	int *lr = sw_xmalloc(sizeof(int) * (size_t)(nl + 1));
	double *lv = sw_xmalloc(sizeof(double) * (size_t)(nl + 1));
	nl = 0;
	for (int i = 0; i < R; i++)
		if (st->fL[i] != 0) {
			lr[nl] = i;
			lv[nl++] = st->fL[i];
		}
	lp_set_col(P, 3 * m, nl, lr, lv);
	lp_set_col_bounds(P, 3 * m, 0, lam_hi);
	free(lr);
	free(lv);
	lp_set_maximize(P, 1);
	enum lp_status s = lp_solve(P, LP_PRIMAL);
	double M = s == LP_OPTIMAL ? lp_obj(P) : HUGE_VAL;
	lp_free(P);
	return M;
}

/* The global program's x columns: equilibrium, yield and the
 * complementarity rows (bounds M on the normal forces, mumax M on the
 * shear), and the bounds of the equilibrium and friction rows. */
static void global_statics(struct lp *P, const struct glayout *gp,
			   const struct wall *w, const struct statics *st,
			   double M, double mumax)
{
	const struct glayout g = *gp;
	int m = w->nifaces, rows[16];
	double vals[16];
	for (int j = 0; j < 3 * m; j++) {
		int k = j / 3, e = j % 3, n = statics_column(st, j, rows, vals);
		double mu = st->mu[k];
		if (e == 2) {
			rows[n] = g.fr + 2 * k; vals[n++] = 1;
			rows[n] = g.fr + 2 * k + 1; vals[n++] = -1;
			rows[n] = g.cp + k; vals[n++] = 1;
			rows[n] = g.cm + k; vals[n++] = -1;
			lp_set_col_bounds(P, j, -mumax * M, mumax * M);
		} else {
			rows[n] = g.fr + 2 * k; vals[n++] = -mu;
			rows[n] = g.fr + 2 * k + 1; vals[n++] = -mu;
			rows[n] = g.cn + 2 * k + e; vals[n++] = 1;
			rows[n] = g.cp + k; vals[n++] = mu;
			rows[n] = g.cm + k; vals[n++] = mu;
			lp_set_col_bounds(P, j, 0, M);
		}
		lp_set_col(P, j, n, rows, vals);
	}
	for (int i = 0; i < st->nrows; i++)
		lp_set_row_bounds(P, g.eq + i, -st->fD[i], -st->fD[i]);
	for (int q = 0; q < 2 * m; q++)
		lp_set_row_bounds(P, g.fr + q, -HUGE_VAL, 0);
}

/* The load factor's column, bounded by the standard solution. */
static void global_lambda(struct lp *P, const struct glayout *g,
			  const struct statics *st, double lam_hi)
{
	int R = st->nrows;
	int n = 0;
	int *lr = sw_xmalloc(sizeof(int) * (size_t)(R + 1));
	double *lv = sw_xmalloc(sizeof(double) * (size_t)(R + 1));
	for (int i = 0; i < R; i++)
		if (st->fL[i] != 0) {
			lr[n] = i;
			lv[n++] = st->fL[i];
		}
	lp_set_col(P, g->lam, n, lr, lv);
	lp_set_col_bounds(P, g->lam, 0, lam_hi * (1 + 1e-9) + 1e-12);
	lp_set_obj(P, g->lam, 1);
	free(lr);
	free(lv);
}

/* The velocity columns: the entries of A^T in the kinematic rows, plus
 * the normalisation (sum of the normal-force columns) and the work. */
static void global_velocities(struct lp *P, const struct glayout *g,
			      const struct statics *st, int m)
{
	int R = st->nrows, rows[16];
	double vals[16];
	int *cnt = sw_xcalloc((size_t)R + 1, sizeof(int));
	int cap = 8 * m + 8;
	int **vr = sw_xcalloc((size_t)R + 1, sizeof(int *));
	double **vv = sw_xcalloc((size_t)R + 1, sizeof(double *));
	double *norm = sw_xcalloc((size_t)R + 1, sizeof(double));
	for (int i = 0; i < R; i++) {
		vr[i] = sw_xmalloc(sizeof(int) * (size_t)(cap + 4));
		vv[i] = sw_xmalloc(sizeof(double) * (size_t)(cap + 4));
	}
	for (int j = 0; j < 3 * m; j++) {
		int k = j / 3, e = j % 3, n = statics_column(st, j, rows, vals);
		for (int t = 0; t < n; t++) {
			int i = rows[t];
			if (cnt[i] + 3 > cap)
				continue;	/* cannot happen: <= 3 per column */
			if (e == 2) {
				vr[i][cnt[i]] = g->ks + k;
				vv[i][cnt[i]++] = vals[t];
			} else {
				vr[i][cnt[i]] = g->kn0 + 2 * k + e;
				vv[i][cnt[i]++] = vals[t];
				vr[i][cnt[i]] = g->kn1 + 2 * k + e;
				vv[i][cnt[i]++] = vals[t];
				norm[i] += vals[t];
			}
		}
	}
	for (int i = 0; i < R; i++) {
		if (norm[i] != 0) {
			vr[i][cnt[i]] = g->norm;
			vv[i][cnt[i]++] = norm[i];
		}
		if (st->fL[i] != 0) {
			vr[i][cnt[i]] = g->work;
			vv[i][cnt[i]++] = st->fL[i];
		}
		lp_set_col(P, g->v + i, cnt[i], vr[i], vv[i]);
		lp_set_col_bounds(P, g->v + i, -HUGE_VAL, HUGE_VAL);
		free(vr[i]);
		free(vv[i]);
	}
	free(vr);
	free(vv);
	free(cnt);
	free(norm);
}

/* The slip and opening columns, their binaries and their rows; the
 * normalisation and the work rows. */
static void global_binaries(struct lp *P, const struct glayout *gp, int m,
			    double M, double Mf)
{
	const struct glayout g = *gp;
	int rows[4];
	double vals[4];
	for (int k = 0; k < m; k++) {
		/* slips */
		rows[0] = g.ks + k; vals[0] = -1;
		rows[1] = g.ksp + k; vals[1] = 1;
		rows[2] = g.norm; vals[2] = 1;
		lp_set_col(P, g.sp + k, 3, rows, vals);
		lp_set_col_bounds(P, g.sp + k, 0, 1);
		rows[0] = g.ks + k; vals[0] = 1;
		rows[1] = g.ksm + k; vals[1] = 1;
		lp_set_col(P, g.sm + k, 3, rows, vals);
		lp_set_col_bounds(P, g.sm + k, 0, 1);
		/* slip binaries */
		rows[0] = g.ksp + k; vals[0] = -1;
		rows[1] = g.cp + k; vals[1] = Mf;
		rows[2] = g.one + k; vals[2] = 1;
		lp_set_col(P, g.yp + k, 3, rows, vals);
		lp_set_binary(P, g.yp + k);
		rows[0] = g.ksm + k; vals[0] = -1;
		rows[1] = g.cm + k; vals[1] = Mf;
		lp_set_col(P, g.ym + k, 3, rows, vals);
		lp_set_binary(P, g.ym + k);
		/* opening binaries */
		for (int e = 0; e < 2; e++) {
			rows[0] = g.kn1 + 2 * k + e; vals[0] = -1;
			rows[1] = g.cn + 2 * k + e; vals[1] = M;
			lp_set_col(P, g.z + 2 * k + e, 2, rows, vals);
			lp_set_binary(P, g.z + 2 * k + e);
			lp_set_row_bounds(P, g.kn0 + 2 * k + e, 0, HUGE_VAL);
			lp_set_row_bounds(P, g.kn1 + 2 * k + e, -HUGE_VAL, 0);
			lp_set_row_bounds(P, g.cn + 2 * k + e, -HUGE_VAL, M);
		}
		lp_set_row_bounds(P, g.ks + k, 0, 0);
		lp_set_row_bounds(P, g.ksp + k, -HUGE_VAL, 0);
		lp_set_row_bounds(P, g.ksm + k, -HUGE_VAL, 0);
		lp_set_row_bounds(P, g.one + k, -HUGE_VAL, 1);
		lp_set_row_bounds(P, g.cp + k, -HUGE_VAL, Mf);
		lp_set_row_bounds(P, g.cm + k, -HUGE_VAL, Mf);
	}
	lp_set_row_bounds(P, g.norm, 1, 1);
	lp_set_row_bounds(P, g.work, GLOBAL_EPS_WORK, HUGE_VAL);
	lp_set_maximize(P, 0);
}

/* What the program found: its pattern checked by exact LPs (see the
 * top) into r; SW_OK, or SW_EANALYSIS with the message. */
static enum sw_status global_result(struct lp *P, const struct glayout *gp,
				    enum lp_mip_status ms, double gap,
				    struct sample_ws *ws,
				    const struct sample_draw *d,
				    double lam_std, struct solve_result *r,
				    double time_limit, char *err)
{
	const struct glayout g = *gp;
	const struct statics *st = sample_statics(ws);
	int m = g.m;
	enum sw_status ret = SW_OK;
	if (ms == LP_MIP_OPTIMAL || ms == LP_MIP_FEASIBLE) {
		/* the pattern, checked by exact LPs (see the top) */
		double lam_mip = lp_mip_col(P, g.lam) * st->S;
		unsigned char *open = sw_xcalloc(2 * (size_t)m + 1, 1);
		unsigned char *slip = sw_xcalloc((size_t)m + 1, 1);
		/* the motions its mechanism makes, where its binaries allow
		 * them (a binary only permits: a pattern wider than the
		 * mechanism could hold other mechanisms, without an onset
		 * state) */
		for (int j = 0; j < 2 * m; j++)
			open[j] = lp_mip_col(P, g.z + j) > 0.5 &&
				  lp_mip_row(P, g.kn0 + j) > GLOBAL_MOTION;
		for (int k = 0; k < m; k++)
			slip[k] = (lp_mip_col(P, g.yp + k) > 0.5 &&
				   lp_mip_col(P, g.sp + k) > GLOBAL_MOTION ?
				   SAMPLE_SLIP_POS : 0) |
				  (lp_mip_col(P, g.ym + k) > 0.5 &&
				   lp_mip_col(P, g.sm + k) > GLOBAL_MOTION ?
				   SAMPLE_SLIP_NEG : 0);
		/* GLPK's gap: |incumbent - best bound| / |incumbent| */
		r->mip_optimal = ms == LP_MIP_OPTIMAL;
		r->lower_bound = ms == LP_MIP_OPTIMAL ? lam_mip
			: lam_mip - (isfinite(gap) ? gap : 1) * fabs(lam_mip);
		enum sample_status s = sample_pattern(ws, d, open, slip,
						      &r->mech);
		free(open);
		free(slip);
		r->status = s;
		if (s == SAMPLE_ACCEPTED) {
			r->lambda = r->mech.lambda_min;
			r->has_mechanism = 1;
			r->gap = (r->lambda - r->lower_bound) /
				 fmax(fabs(r->lambda), 1e-300);
			r->proven = ms == LP_MIP_OPTIMAL && r->bounds_derived &&
				    r->lambda - r->lower_bound <=
				    GLOBAL_AGREE * fmax(fabs(r->lambda), lam_std);
			if (r->proven)
				r->gap = 0;
		} else {
			ret = sw_fail(err, SW_EANALYSIS,
				      "the mixed-integer program's solution "
				      "(load factor %.6g) is not an onset of "
				      "collapse once checked by exact LPs (%s): "
				      "it leans on GLPK's tolerances; no global "
				      "minimum", lam_mip,
				      s == SAMPLE_NO_MECHANISM ?
				      "no mechanism uses only its motions" :
				      sample_status_text(s));
		}
	} else if (ms == LP_MIP_NOFEASIBLE) {
		r->status = SAMPLE_NO_MECHANISM;
		ret = sw_fail(err, SW_EANALYSIS,
			      "no onset-of-collapse state exists (the mixed-integer program is infeasible)");
	} else {
		r->status = SAMPLE_NUMERICAL;
		ret = sw_fail(err, SW_EANALYSIS,
			      "the mixed-integer solver found no solution within %g s",
			      time_limit);
	}
	return ret;
}

enum sw_status global_solve(const struct wall *w, const struct solve_opts *o,
			    struct sample_ws *ws, const struct sample_draw *d,
			    double lam_std, struct solve_result *r, char *err,
			    const char **what, double *scale)
{
	const struct statics *st = sample_statics(ws);
	int m = w->nifaces, R = st->nrows;
	struct glayout g;
	glayout(&g, m, R);
	double lam_hi = lam_std / st->S;	/* scaled */
	double M = max_total_normal(sample_ws_solver(ws), st, lam_hi * (1 + 1e-9) + 1e-12);
	r->bounds_derived = isfinite(M);
	if (!r->bounds_derived)
		M = 1e3 * w->nfree;	/* mean block weight = 1 */
	M = M * (1 + 1e-6) + 1e-9;
	double mumax = 0;
	for (int k = 0; k < m; k++)
		mumax = fmax(mumax, st->mu[k]);
	double Mf = 2 * mumax * M + 1e-9;

	struct lp *P = lp_new(sample_ws_solver(ws), g.nrows, g.ncols);
	global_statics(P, &g, w, st, M, mumax);
	global_lambda(P, &g, st, lam_hi);
	global_velocities(P, &g, st, m);
	global_binaries(P, &g, m, M, Mf);

	double gap = NAN;
	*scale = st->S;	/* the program's objective is lambda */
	*what = "the mixed-integer program";
	enum lp_mip_status ms = lp_solve_mip(P, o->time_limit, &gap);
	*scale = 1;
	*what = "the exact LPs of its pattern";
	enum sw_status ret = global_result(P, &g, ms, gap, ws, d, lam_std, r,
					   o->time_limit, err);
	lp_free(P);
	return ret;
}

