/*
 * sample_slp.c - step 2b of a sample: the stabilised SLP (docs/method.md,
 * "One sample" and "The SLP's answer"), from its start (sws_slp: LP-max's
 * field over its optimal face if the map holds it, else the field below
 * the optimum of sws_lp_max_floor; docs/method.md, "The SLP's start")
 * to a stress field in x and the load factor lambda_max.  Its map is
 * LP1 and LP2 (sample_lp.c builds them; LP2's tie-break is
 * sample_tie.c's); the iteration is plain,
 * Anderson-accelerated, or (the default) the piece path, whose jump to
 * an affine piece's fixed point is piece.c's, in up to four attempts
 * on a large wall (slp_attempts).  sws_capacity is also
 * sample_onset.c's (the onset check reads the shears against it).
 */
#include <gsl/gsl_linalg.h>
#include <math.h>
#include <string.h>

#include "piece.h"
#include "sample_ws.h"

#define TOL_FACE 1e-9
/* the SLP's acceleration (sws_slp()): iterations on one affine piece
 * before Anderson's steps (their memory, SLP_MEMORY, is sample_ws.h's) */
#define SLP_SETTLE 2
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
/* a normal force, a shear's distance to its capacity or N - c counts as
 * zero below this in the classification (scaled units, mean block
 * weight 1): far above the round-off of a converged field (1e-13) */
#define SLP_CLASS_TOL 1e-9
/* ... but once the residual max |N - c| is below this (scaled units),
 * the classification leaves out each interface's side of its capacity
 * (N_a + N_b above, at or below c_k).  On the way to a fixed point every
 * N_k - c_k goes to 0, and on a wall of hundreds of interfaces they
 * cross SLP_CLASS_TOL one by one: the classification changed at nearly
 * every iteration, the jump never came, and the plain iteration ran its
 * tail down to o->tol (tests/data/body-195.yaml, seed 1: no jump in 20
 * samples, 73.3 iterations a sample).  The side says which of LP2's p_k
 * and q_k is basic, and swapping them leaves the piece's map of N as it
 * is, and where that basis holds is what the verification reads.  The
 * bound is SLP_ACCEL_FROM's, for its reason: earlier the pieces still
 * change, and leaving the side out from the start moved 5 of 2,000
 * samples of Ferris & Tin-Loi wall 1 and 29 of wall 2 (seed 1), nearly
 * all up; below it, none (docs/method.md, "The SLP's answer", rule 2) */
#define SLP_CLASS_SIDE 2e-4
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
 * 2 higher); none of 2,000 of either Ferris & Tin-Loi wall (seed 1).
 * It is the first of the default SLP's attempts (slp_attempts) */
#define SLP_PHASE 100
/* ... if its last residual max |N - c| is still above this, far from the
 * plain test's 1e-7: a slowly converging iteration goes on (demo sample
 * 723 of seed 1 is at 3.4e-7 after 100 iterations, and converges at
 * 101) */
/* ... and, on a wall of more than SLP_PHASE interfaces (on a smaller
 * one in its second attempt only), only if it is not contracting: its
 * residual has not fallen to SLP_CONTRACT of what it was
 * SLP_CONTRACT_SPAN plain iterations before (a rate of 0.933 an
 * iteration).  Until it stops contracting, the phase goes on.  On such
 * a wall the early iterations cross many pieces before the iteration
 * contracts, and a phase of 100 can end in the middle of a steady
 * descent: walls/body-1000.yaml, seed 1, sample 0, falls from 2.0e-2
 * at iteration 71 to 1.15e-3 at 100, was restarted, and converged at
 * iteration 401 at half the step (docs/method.md, "The SLP's answer",
 * rule 6) */
#define SLP_CONTRACT 0.25
#define SLP_CONTRACT_SPAN 20
/* ... nor, on any wall, while it is leaving a piece: its joints'
 * classification has held for SLP_CONTRACT_SPAN plain iterations, and
 * for SLP_CONTRACT_SPAN after it last did.  On one affine piece whose
 * fixed point is not the map's (its jump failed), the iterates move away
 * from that point, at a steady rate, until they leave the piece: the
 * residual grows all the way out, so it reads as wandering, but the way
 * out is the way to the answer.  A 6-course wall beside a half-height
 * pier (tests/data/pier-half-seed1-s4.csv) held one piece from
 * iteration 72 to 104, its residual growing 1 % an iteration, and
 * converged at 134 once the phase was not cut at 100; each smaller step
 * drifted the same way more slowly, and it was `not_converged`
 * (docs/method.md, "The SLP's answer", rule 6) */
#define SLP_WANDERING 1e-3
/* Rule 7's long phase, one phase never cut from the slack bases, is
 * tried on walls that are not large (at most SWS_LARGE_IFACES
 * interfaces, sample_ws.h): on those of at most SLP_PHASE as the third
 * attempt, on larger ones after rule 8's root searches (a second
 * attempt's phase of m iterations comes first there; slp_round).  A
 * squat running-bond wall that slides at lambda = mu on
 * every bed joint at once drifts at a constant residual (one bed
 * joint's normal force passing to its neighbour, 0.004 block weights an
 * iteration) for 576 iterations before its fixed point, past the
 * second attempt's 445 (tests/data/squat-mu062.yaml, seed 1, sample
 * 6; docs/method.md, "A drift at lambda = mu, and LP2 said
 * infeasible").  On a large wall an iteration costs about a second
 * (walls/body-1000.yaml), and 1,000 more would be a quarter of an hour
 * a sample. */
/* the third attempt's root search (rule 8): bisection steps along the
 * segment between a phase end's two iterates (to 2^-40 of its length),
 * then piece jumps from the root, at most this many */
#define ROOT_BISECT 40
#define ROOT_JUMPS 8

/* LP2's feasible set: LP1's optimal face.  A column that is non-basic in
 * LP1's optimum with a non-zero reduced cost stays where LP1 left it, the
 * others keep LP1's bounds (complementary slackness: every optimal field
 * has those columns there, and every admissible field that has them
 * there is optimal).  LP1's own field lies on this face, so LP2 cannot be
 * infeasible; holding lambda >= lambda_LP1 exactly instead left no point
 * within GLPK's tolerances for 9 % of the samples of Ferris & Tin-Loi
 * wall 2, and any slack on lambda lets LP2 trade load for closeness
 * through columns that are far from optimal (docs/method.md). */
static int face_fixed(const struct lp *P, int j)
{
	return !lp_col_basic(P, j) && fabs(lp_col_dual(P, j)) > TOL_FACE;
}

static void face_bounds(struct sample_ws *ws)
{
	struct lp *P = ws->lp[LP1], *Q = ws->lp[LP2];
	for (int j = 0; j <= 3 * ws->m; j++) {
		double lo = 0, hi = HUGE_VAL;	/* normal forces */
		if (j == COL_LAMBDA(ws)) {
			lo = -HUGE_VAL;
		} else if (j % 3 == 2) {
			hi = sws_capacity(ws, j / 3);
			lo = -hi;
		}
		if (face_fixed(P, j))
			lo = hi = lp_col(P, j);
		lp_set_col_bounds(Q, j, lo, hi);
	}
	for (int k = 0; k < ws->m; k++)
		lp_set_row_bounds(Q, ws->R + k, ws->c[k], ws->c[k]);
}

/* The most that LP2's load can differ from LP1's on the face of
 * face_bounds: each column that is non-basic in LP1's optimum with a
 * reduced cost that counts as zero (at most TOL_FACE) is free in LP2,
 * and moving it by dx moves the load by at most TOL_FACE |dx|.  The
 * measure is the wall's: on the facade (629 interfaces, forces up to
 * tens of block weights) these columns move by 300 to 760 scaled units
 * in all between LP1's field and LP2's, so the load may fall by up to
 * 8e-7 there, where a fixed tolerance of 1e-7 rejected a sample
 * (docs/method.md, "Tolerances": LP2's load). */
static double face_drop(const struct sample_ws *ws)
{
	const struct lp *P = ws->lp[LP1], *Q = ws->lp[LP2];
	double moved = 0;
	for (int j = 0; j < 3 * ws->m; j++)
		if (!lp_col_basic(P, j) && !face_fixed(P, j))
			moved += fabs(lp_col(Q, j) - lp_col(P, j));
	return TOL_FACE * moved;
}

/* LP2's start on a path's first evaluation: LP1's optimal basis, and
 * for each closeness row N_k - p_k + q_k = c_k the one of p_k and q_k
 * that carries LP1's N_k - c_k.  LP1's field lies on the face that
 * face_bounds wrote (its non-basic columns at the values they are fixed
 * at, or within the bounds they keep), so this basis is primal
 * feasible, and non-singular (each row's p_k or q_k is its own).  Its
 * rows and LP1's columns come first in LP2, in LP1's order
 * (sample_lp.c). */
static void lp2_from_lp1(struct sample_ws *ws)
{
	const struct lp *P = ws->lp[LP1];
	int m = ws->m, R = ws->R;
	struct lp_basis *b1 = &ws->lp1_end, *b2 = &ws->lp2_face;
	lp_basis_save(P, b1);
	int *row = lp_basis_size(b2, (R + m) + (3 * m + 1 + 2 * m));
	int *col = row + R + m;
	memcpy(row, b1->stat, sizeof(int) * (size_t)R);
	for (int k = 0; k < m; k++)
		row[R + k] = LP_NS;
	memcpy(col, b1->stat + R, sizeof(int) * (size_t)(3 * m + 1));
	for (int k = 0; k < m; k++) {
		int up = lp_col(P, 3 * k) + lp_col(P, 3 * k + 1) >= ws->c[k];
		col[COL_P(ws, k)] = up ? LP_BS : LP_NL;
		col[COL_Q(ws, k)] = up ? LP_NL : LP_BS;
	}
	lp_basis_load(ws->lp[LP2], b2);
}

/* LP1: the maximum load with the shear capacities fixed at ws->c
 * (only bounds change between two LP1s: a few dual simplex pivots). */
static enum lp_status lp1_solve(struct sample_ws *ws, struct sample_result *r)
{
	struct lp *P = ws->lp[LP1];
	for (int k = 0; k < ws->m; k++)
		lp_set_col_bounds(P, 3 * k + 2, -sws_capacity(ws, k), sws_capacity(ws, k));
	return sws_solve(ws, LP1, LP_DUAL, r);
}

/* One evaluation of the SLP's map at the capacities ws->c: LP1, and LP2
 * unless LP1's optimum is unique.  Leaves N(c)'s stress field in ws->x,
 * the load factor in *lam and max_k |N_k - c_k| in *diff.  *failed is 1
 * when it stopped on a solver failure (an LP without a verdict), not on
 * an LP's verdict or a check.  fresh: the first evaluation of a path,
 * where LP2's last basis is another sample's or another path's (see
 * below). */
static enum sample_status slp_map(struct sample_ws *ws,
				  const struct sample_opts *o,
				  struct sample_result *r, double *lam,
				  double *diff, int *failed, int fresh)
{
	int m = ws->m;
	struct lp *P = ws->lp[LP1], *Q = ws->lp[LP2];
	*failed = 0;
	enum lp_status s = lp1_solve(ws, r);
	/* infeasible and unbounded are verdicts (sws_solve's fixed path) */
	if (s == LP_UNBOUNDED)
		return SAMPLE_UNBOUNDED;
	if (s == LP_INFEASIBLE)
		return SAMPLE_NOT_CONVERGED;
	if (s != LP_OPTIMAL) {
		*failed = 1;
		return SAMPLE_NUMERICAL;
	}
	*lam = lp_obj(P);
	struct lp *X = P;	/* where the stress field is read */
	ws->slp_lp = LP1;
	/* LP2: of the optimal stress fields, the one whose normal forces
	 * are closest (L1) to c; skipped when LP1's optimal face is a single
	 * point.  Only bounds change between two LP2s of a path, so the
	 * dual simplex from LP2's own last basis is short (median 14
	 * pivots on tests/data/body-195.yaml; the primal simplex from
	 * LP1's optimum walks the degenerate face for more).  A path's
	 * first LP2 is the exception: its last basis is another sample's
	 * (or the end of another path), and the dual simplex from it took
	 * 1,130-1,340 pivots there, as many as from the slack basis; the
	 * primal simplex from LP1's optimum (lp2_from_lp1) takes fewer,
	 * and every LP2 after it too.  On walls of more than 1,000
	 * interfaces only under a body load (ws->lp2_primal): there LP2
	 * starts from the slack basis (sws_role_start), and on
	 * walls/large.yaml, pulled at one block (two SLP iterations a
	 * sample), the primal simplex took 16,955 pivots against the
	 * dual's 4,089, while on walls/body-1000.yaml it took fewer
	 * (docs/performance.md, "A path's first LP2").  The tie-break
	 * (sws_lp2_tiebreak) makes LP2's field the same from any start. */
	if (o->stabilise && !lp_unique(P, TOL_FACE)) {
		face_bounds(ws);
		fresh = fresh && ws->lp2_primal;
		if (fresh)
			lp2_from_lp1(ws);
		s = sws_solve(ws, LP2, fresh ? LP_PRIMAL : LP_DUAL, r);
		/* LP1's optimal field lies on the face, to the simplex's
		 * tolerance, so "infeasible" here is the simplex's, not the
		 * face's: a path of a squat running-bond wall that slides at
		 * lambda = mu on every bed joint at once, where LP1's field
		 * was outside a shear bound by 9e-10 and the dual simplex
		 * from LP2's last basis and the primal from the slack basis
		 * both found no feasible point (tests/data/squat-mu062.yaml,
		 * seed 1, sample 6, at iteration 402; squat-mu037.yaml's
		 * sample 1 ended `numerical` the same way; docs/method.md,
		 * "A drift at lambda = mu, and LP2 said infeasible").  Once
		 * more from that field, as a path's first LP2 starts on a
		 * large wall (lp2_from_lp1): a primal feasible basis.  The
		 * tie-break makes the answer the face's, not the
		 * start's.  What moves: a path that ended `numerical` here,
		 * and a piece jump whose verifying LP2 the simplex called
		 * infeasible, which failed and is now verified as any other
		 * (rule 4), so that round-off no longer fails it. */
		if (s == LP_INFEASIBLE && !fresh) {
			/* sws_solve's re-check from the slack basis has
			 * said "infeasible" already: not again */
			lp2_from_lp1(ws);
			s = sws_counted(ws, LP2, LP_PRIMAL, NULL, r);
		}
		if (s != LP_OPTIMAL) {
			*failed = s != LP_UNBOUNDED && s != LP_INFEASIBLE;
			return SAMPLE_NUMERICAL;
		}
		if (sws_lp2_tiebreak(ws, r) != LP_OPTIMAL) {
			*failed = 1;
			return SAMPLE_NUMERICAL;
		}
		/* on the face the load is LP1's but for the columns whose
		 * reduced costs count as zero: they may move it by up to
		 * TOL_FACE a unit moved (face_drop) */
		double lam2 = lp_col(Q, COL_LAMBDA(ws));
		double off = fabs(lam2 - *lam), tol = o->tol * fmax(1, fabs(*lam));
		if (!(off <= tol) && !(off <= tol + face_drop(ws)))
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

enum sample_status sws_slp_first_lp1(struct sample_ws *ws,
				     const struct sample_opts *o,
				     struct sample_result *r)
{
	struct sample_opts lp1 = *o;
	double lam, diff;
	int failed;
	lp1.stabilise = 0;
	enum sample_status st = slp_map(ws, &lp1, r, &lam, &diff, &failed, 1);
	r->iterations = 1;
	if (st == SAMPLE_ACCEPTED)	/* lam is set only then */
		r->lambda_max = lam;
	return st;
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

static enum sample_status slp_attempts(struct sample_ws *ws,
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

/* The end of an SLP path (slp_from, slp_piece_path) with status st:
 * where st is `not_converged` from an evaluation of the map, its LP1
 * had no equilibrium (slp_map), and the capacities it failed at are
 * kept for slp_clamp_lost; an end at the iteration limit clears that.
 * The root searches' evaluations (slp_cycle_root) are not the path's
 * and leave it as the last path left it. */
static enum sample_status path_end(struct sample_ws *ws,
				   enum sample_status st, int limit)
{
	ws->slp_lost = !limit && st == SAMPLE_NOT_CONVERGED;
	if (ws->slp_lost)
		memcpy(ws->clost, ws->c, sizeof(double) * (size_t)ws->m);
	return st;
}

/* LP1 and LP2 from the slack basis, which no start option touches, for
 * a path on which the last-bit differences of two starts' LP values
 * would grow to a decision.  An LP's values are the same to the last bit
 * when its simplex takes the same pivots, as it does from the same
 * basis, unfactorised, and the same bounds: the capacities ws->c0
 * (LP-max's), bit for bit the same from every start wherever measured
 * (docs/method.md, "Rules 7-9 on small walls"). */
static void slp_slack_bases(struct sample_ws *ws)
{
	lp_reset_basis(ws->lp[LP1]);
	lp_reset_basis(ws->lp[LP2]);
}

/* Step 2b from the start in ws->c (sws_slp chooses it): the stabilised
 * SLP.  The plain
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
static enum sample_status slp_from(struct sample_ws *ws,
				   const struct sample_opts *o,
				   struct sample_result *r)
{
	if (o->slp == SAMPLE_SLP_PIECE)
		return slp_attempts(ws, o, r);
	int m = ws->m, settled = 0, trial = 0, tries = 0;
	double lam_prev = NAN, lam, diff, diff_prev = HUGE_VAL;
	unsigned long piece = 0;
	struct slp_history *h = &ws->hist;
	h->len = 0;
	int accel = o->slp == SAMPLE_SLP_ANDERSON;
	/* the start, for a plain restart and for slp_clamp_lost */
	memcpy(ws->c0, ws->c, sizeof(double) * (size_t)m);
	/* from the slack bases, as rule 7's long phase (slp_again): the
	 * plain iteration has no phases, and where it wanders its answer is
	 * where round-off lets it first meet its tolerance (the demo, seed
	 * 1, 2,000 samples: 3 differed between `auto` and `crash`, by
	 * 61-125 %; docs/method.md, "The plain iteration's start") */
	slp_slack_bases(ws);
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
		int lp_failed;
		enum sample_status st = slp_map(ws, o, r, &lam, &diff,
						&lp_failed, it == 1);
		if (st != SAMPLE_ACCEPTED)
			return path_end(ws, st, 0);
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
	return path_end(ws, SAMPLE_NOT_CONVERGED, 1);
}

/* The SLP's start (docs/method.md, "The SLP's start").  First the map
 * at LP-max's tie-broken field over its optimal face: where it holds
 * that field (N = c to PIECE_VERIFY), the associative optimum is an
 * onset state of the non-associative problem, and the sample's SLP
 * answer (a rocking wall, the demo's samples at its standard load).
 * Otherwise the SLP starts from the floor's field
 * (sws_lp_max_floor): the face, read off the reduced costs of the basis
 * LP-max ended at, is not a function of the sample where the optimum
 * is ill-conditioned (demo sample 299 at friction cov 0.2, seed 2: two
 * starts' fields 0.19 block weights apart in a capacity, for optima
 * 2.6e-9 apart).  The canonical sample starts from the face's field:
 * its path is fixed, and it has no canonical basis yet.  So does a wall
 * of more than SLP_PHASE interfaces: there, from the floor's start,
 * the SLP's LP1 and LP2 (which follow the start option) part from start
 * to start (the facade at friction 0.8, seed 7, sample 0: 0.3100433
 * from `auto`, 0.3093318 from `slack-primal`; one load from the face's
 * start), and walls/body-300.yaml's sample 18 of seed 1 becomes
 * `numerical` (docs/method.md, "The SLP's start", rule 5). */
static enum sample_status slp_solve(struct sample_ws *ws,
				    const struct sample_opts *o,
				    struct sample_result *r)
{
	if (ws->setup || ws->m > SLP_PHASE)
		return slp_from(ws, o, r);
	double lam, diff;
	int lp_failed;
	enum sample_status st = slp_map(ws, o, r, &lam, &diff, &lp_failed,
					1);
	if (st == SAMPLE_ACCEPTED && diff <= PIECE_VERIFY) {
		r->iterations = 1;
		r->lambda_max = lam;
		r->converged = 1;
		return SAMPLE_ACCEPTED;
	}
	if (lp_failed)
		return st;
	st = sws_lp_max_floor(ws, r);
	if (st != SAMPLE_ACCEPTED)
		return st;
	st = slp_from(ws, o, r);
	r->iterations++;
	return st;
}

/* The blocks that overhang on this sample's contact points: a free
 * block whose weight acts outside the span, in x, of the contact points
 * it rests on (those of its interfaces whose normal has an upward
 * component into it: wall_iface_rests, as the hanging test), by more
 * than 1e-9 of the wall's length scale.  A running-bond block at the
 * edge of an opening, half over the void, has its centroid on the edge
 * of its bearing: at depth 0 the contact point is there, at any other
 * depth the contact points fall short of it, and the block is held
 * against tipping into the opening only by its neighbours - the
 * friction and the contact of its side joints and of the joints above
 * it, the clamp of a block that hangs (docs/method.md, "Blocks that
 * overhang an opening").  Marks in blk[] each such block, and in give[]
 * each joint of each such block but those it rests on; returns how many
 * joints were marked. */
static int slp_overhang(const struct sample_ws *ws, char *blk, char *give)
{
	const struct wall *w = ws->w;
	int nb = w->nblocks, n = 0;
	double *lo = sw_xmalloc(sizeof(double) * 2 * (size_t)nb), *hi = lo + nb;
	wall_rest_span(w, ws->st.q, lo, hi);
	double tol = 1e-9 * ws->st.L;
	for (int b = 0; b < nb; b++) {
		double cx = w->blocks[b].cx;
		/* a block that rests on nothing hangs (wall_clamp_blocks) */
		if (!w->blocks[b].fixed && hi[b] >= lo[b] &&
		    (cx < lo[b] - tol || cx > hi[b] + tol))
			blk[b] = 1;
	}
	free(lo);
	for (int k = 0; k < ws->m; k++) {
		const struct wall_interface *f = &w->ifaces[k];
		int up = wall_iface_rests(f);
		int ends[2] = {f->a, f->b};
		for (int e = 0; e < 2 && !give[k]; e++)
			if (ends[e] < nb && ends[e] != up && blk[ends[e]]) {
				give[k] = 1;
				n++;
			}
	}
	return n;
}

/* LP1's verdict "has an equilibrium": optimal, or unbounded (any load
 * factor).  Not its negation: a failed or stopped LP has no verdict. */
static int lp1_stands(enum lp_status s)
{
	return s == LP_OPTIMAL || s == LP_UNBOUNDED;
}

/* LP1 at the capacities the path failed at (ws->clost), with each
 * joint that give[] marks (want 1) or does not mark (want 0) given back
 * at least its capacity at the SLP's start (ws->c0, LP-max's field or
 * the floor's, where LP1 has an equilibrium): its status, so that
 * "has an equilibrium" (optimal or unbounded) and "has none"
 * (infeasible) are each the LP's own verdict, and a failed or stopped
 * LP is neither. */
static enum lp_status lp1_given_back(struct sample_ws *ws, const char *give,
				     int want, struct sample_result *r)
{
	memcpy(ws->c, ws->clost, sizeof(double) * (size_t)ws->m);
	for (int k = 0; k < ws->m; k++)
		if (!give[k] == !want)
			ws->c[k] = fmax(ws->c[k], ws->c0[k]);
	return lp1_solve(ws, r);
}

/* LP1 at the capacities the path failed at (ws->clost), at zero load,
 * with the blocks that blk[] marks weightless (their equilibrium rows'
 * dead load 0): its status.  Only bounds change, and they are put back
 * as write_points (sample_lp.c) writes them at every sample: each row
 * at its dead load (sws_put_dead_load), the load factor free. */
static enum lp_status lp1_weightless(struct sample_ws *ws, const char *blk,
				     struct sample_result *r)
{
	const struct wall *w = ws->w;
	struct lp *P = ws->lp[LP1];
	for (int b = 0; b < w->nblocks; b++) {
		if (!blk[b] || w->blocks[b].fixed)
			continue;
		int row = 3 * w->blocks[b].eq;	/* its three rows */
		for (int i = row; i < row + 3; i++)
			lp_set_row_bounds(P, i, 0, 0);
	}
	lp_set_col_bounds(P, COL_LAMBDA(ws), 0, 0);
	memcpy(ws->c, ws->clost, sizeof(double) * (size_t)ws->m);
	enum lp_status s = lp1_solve(ws, r);
	sws_put_dead_load(ws, P);
	lp_set_col_bounds(P, COL_LAMBDA(ws), -HUGE_VAL, HUGE_VAL);
	return s;
}

/* The lowest of the blocks that blk[] marks, the one a `hanging`
 * sample names (docs/method.md, "Which blocks cannot be held"): the
 * least centroid height, then the least x, each to 1e-9 of the wall's
 * length scale (blocks of one course tie in height), then the wall's
 * order; -1 if none is marked.  How many are marked into *n. */
static int slp_lowest(const struct sample_ws *ws, const char *blk, int *n)
{
	const struct wall *w = ws->w;
	double tol = 1e-9 * ws->st.L;
	int low = -1;
	*n = 0;
	for (int b = 0; b < w->nblocks; b++) {
		if (!blk[b])
			continue;
		++*n;
		const struct wall_block *p = &w->blocks[b];
		const struct wall_block *q = low < 0 ? NULL : &w->blocks[low];
		if (!q || p->cy < q->cy - tol ||
		    (p->cy <= q->cy + tol && p->cx < q->cx - tol))
			low = b;
	}
	return low;
}

/* A sample that the SLP leaves not converged because its last path
 * ended on an LP1 without equilibrium (path_end): is a clamp what it
 * lost?  The clamped blocks are those that no chain of joints carries
 * to a support from below (wall_clamp_blocks; docs/method.md, "What the
 * method cannot answer: blocks that hang on friction") and those that
 * overhang their bearing on this sample's contact points
 * (slp_overhang); the clamped joints are the side joints of the first
 * (wall_clamp_joints) and the joints of the second but those they rest
 * on.  Where there are any, LP1 at the capacities the path failed at
 * answers three questions, each a way the clamp can be what was lost
 * (docs/method.md, "The clamp's loss: sufficient, necessary, its
 * weight"):
 *   sufficient: with the clamped joints alone given back their start
 *     capacities, LP1 has an equilibrium again;
 *   necessary: with every other joint given back its start capacity,
 *     and the clamped joints left where the path failed, LP1 still has
 *     none (the clamp's thrust runs through the wall, so the path can
 *     lose a joint far from the opening as well);
 *   its weight: with the clamped blocks weightless, the wall stands at
 *     zero load (the path lost, far from the opening, a joint of the
 *     thrust that carries their weight, and not the clamped joints).
 * Any makes the sample `hanging` (the lowest clamped block into
 * ws->hang_blk, slp_lowest); otherwise it stays `not_converged`.
 * Each is a verdict of feasibility (an LP that fails is none), and
 * "infeasible" is sws_solve's fixed path: the status does not depend on
 * the start. */
static enum sample_status slp_clamp_lost(struct sample_ws *ws,
					 struct sample_result *r)
{
	const struct wall *w = ws->w;
	char *give = sw_xcalloc((size_t)ws->m + 1, 1);
	char *blk = sw_xcalloc((size_t)w->nblocks + 1, 1);
	int n = slp_overhang(ws, blk, give);
	for (int i = 0; i < ws->nclamp; i++) {
		n += !give[ws->clamp_k[i]];
		give[ws->clamp_k[i]] = 1;
	}
	for (int b = 0; b < w->nblocks; b++)
		blk[b] |= ws->clamp_blk[b];
	/* each question asked only after the last was answered no */
	enum lp_status s = n > 0 ? lp1_given_back(ws, give, 1, r) : LP_FAILED;
	int hanging = lp1_stands(s);
	if (s == LP_INFEASIBLE) {
		s = lp1_given_back(ws, give, 0, r);
		hanging = s == LP_INFEASIBLE;
		if (lp1_stands(s)) {
			s = lp1_weightless(ws, blk, r);
			hanging = lp1_stands(s);
		}
	}
	if (hanging)
		ws->hang_blk = slp_lowest(ws, blk, &ws->nhang);
	free(blk);
	free(give);
	return hanging ? SAMPLE_HANGING : SAMPLE_NOT_CONVERGED;
}

enum sample_status sws_slp(struct sample_ws *ws,
			      const struct sample_opts *o,
			      struct sample_result *r)
{
	ws->slp_lost = 0;
	ws->hang_blk = -1;
	ws->nhang = 0;
	enum sample_status st = slp_solve(ws, o, r);
	if (st == SAMPLE_NOT_CONVERGED && ws->slp_lost)
		st = slp_clamp_lost(ws, r);
	return st;
}

/* A hash of the joints' classification at the SLP's field ws->x and
 * capacities ws->c: each contact point's normal force zero or not, each
 * shear at +mu c, at -mu c or inside, all to SLP_CLASS_TOL, and while
 * the residual diff = max |N - c| is at least SLP_CLASS_SIDE, each
 * interface's N_a + N_b above, at or below c_k.  Unlike the LP bases
 * (the last round's test), it is a function of the field alone, and the
 * field is the tie-broken LPs' unique answer: a degenerate vertex has
 * several optimal bases, and which one the simplex ends at depends on
 * its start (docs/method.md, "The SLP's answer"). */
static unsigned long slp_class(const struct sample_ws *ws, double diff)
{
	unsigned long h = 1469598103934665603UL;	/* FNV-1a */
	const double f0 = SLP_CLASS_TOL;
	/* bits 0-3 the points and the shear, 4-5 the side */
	unsigned mask = diff < SLP_CLASS_SIDE ? 0xfu : 0x3fu;
	for (int k = 0; k < ws->m; k++) {
		double na = ws->x[3 * k], nb = ws->x[3 * k + 1], t = ws->x[3 * k + 2];
		double cap = sws_capacity(ws, k), d = na + nb - ws->c[k];
		int live = cap > f0;
		unsigned code = (unsigned)(na > f0) | (unsigned)(nb > f0) << 1 |
				(unsigned)(live && t >= cap - f0) << 2 |
				(unsigned)(live && t <= -cap + f0) << 3 |
				(unsigned)(d > f0) << 4 | (unsigned)(d < -f0) << 5;
		h = (h ^ (code & mask)) * 1099511628211UL;
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

/* The phase ends' storage (struct slp_ends): the ring's iterate i,
 * capacities and normal-force sums, and phase end e's two iterates'
 * capacities (s = 0: the last of the phase, s = 1: the one it is
 * searched against). */
static double *ring_c(const struct sample_ws *ws, int i)
{
	return ws->ends.buf + (size_t)i * (size_t)ws->m;
}

static double *ring_n(const struct sample_ws *ws, int i)
{
	return ring_c(ws, SLP_RING + i);
}

static double *end_c(const struct sample_ws *ws, int e, int s)
{
	return ring_c(ws, 2 * SLP_RING + 2 * e + s);
}

/* An iterate of the plain path and its map, into the ring. */
static void ends_push(struct sample_ws *ws)
{
	if (!ws->ends.on)
		return;
	int i = ws->ends.pushed++ % SLP_RING;
	double *c = ring_c(ws, i), *n = ring_n(ws, i);
	for (int k = 0; k < ws->m; k++) {
		c[k] = ws->c[k];
		n[k] = ws->x[3 * k] + ws->x[3 * k + 1];
	}
}

/* A phase ended without converging: keep its last iterate, and of the
 * ring's others the one whose map is farthest from it (max norm of the
 * normal-force sums; in a cycle across a steep piece, an iterate on its
 * other side), with the interface where that norm is reached and its
 * residual N - c at both.  The ring starts again for the next phase. */
static void ends_mark(struct sample_ws *ws)
{
	struct slp_ends *E = &ws->ends;
	int m = ws->m, p = E->pushed;
	E->pushed = 0;
	if (!E->on || E->n >= SLP_ENDS || p < 2)
		return;
	int i = (p - 1) % SLP_RING, j = -1, K = -1;
	const double *ni = ring_n(ws, i);
	double far = 0;
	for (int b = 2; b <= SLP_RING && b <= p; b++) {
		int q = (p - b) % SLP_RING;
		const double *nq = ring_n(ws, q);
		for (int k = 0; k < m; k++)
			if (fabs(ni[k] - nq[k]) > far) {
				far = fabs(ni[k] - nq[k]);
				j = q;
				K = k;
			}
	}
	if (j < 0)
		return;
	int e = E->n++;
	E->K[e] = K;
	E->f[e][0] = ni[K] - ring_c(ws, i)[K];
	E->f[e][1] = ring_n(ws, j)[K] - ring_c(ws, j)[K];
	memcpy(end_c(ws, e, 0), ring_c(ws, i), sizeof(double) * (size_t)m);
	memcpy(end_c(ws, e, 1), ring_c(ws, j), sizeof(double) * (size_t)m);
}

/* Step 2b, the default (SAMPLE_SLP_PIECE): the SLP's answer is the fixed
 * point of the piece the plain iteration settles on (docs/method.md,
 * "The SLP's answer").  Plain steps c <- c + omega (N(c) - c) until the
 * joints' classification (slp_class) has held for o->piece_settle
 * iterations; then c jumps to the exact fixed point c* of the current
 * affine piece (piece_jump; a negative capacity is 0), and the next
 * evaluation of the map verifies it: max |N(c*) - c*| <= PIECE_VERIFY,
 * round-off, means c* is a fixed point of the map itself, and the sample
 * is converged there.  Otherwise (also when the map has no value at c*:
 * an LP of it infeasible or unbounded, or LP2's load off LP1's; a solver
 * failure still ends the sample) the iteration goes back to the iterate
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
 * stay below every decision.  On a wall of more than SLP_PHASE
 * interfaces a phase whose residual is still contracting (SLP_CONTRACT)
 * is not cut until it stops, and on any wall a phase that is leaving a
 * piece it has held (escape) is not cut until SLP_CONTRACT_SPAN
 * iterations after it has left.  Leaves the field in ws->x and the load
 * factor in r->lambda_max.  The first phase is first_phase iterations
 * long (slp_attempts). */
static enum sample_status slp_piece_path(struct sample_ws *ws,
					const struct sample_opts *o,
					struct sample_result *r,
					double first_phase, int contract)
{
	int m = ws->m, settled = 0, jumped = 0, phase = 0, escape = 0;
	double lam_prev = NAN, lam, diff = HUGE_VAL, omega = o->omega;
	unsigned long cls = 0, failed = 0;
	/* the residuals of the phase's plain iterates, the last
	 * SLP_CONTRACT_SPAN + 1 of them (the newest at (np - 1) % ...) */
	double res[SLP_CONTRACT_SPAN + 1];
	int np = 0;
	memcpy(ws->c0, ws->c, sizeof(double) * (size_t)m);
	for (int it = 1; it <= o->max_iter; it++) {
		r->iterations = it;
		int contracting = contract && np > SLP_CONTRACT_SPAN &&
				  diff <= SLP_CONTRACT *
					  res[np % (SLP_CONTRACT_SPAN + 1)];
		if (it - phase > first_phase * (o->omega / omega) &&
		    diff > SLP_WANDERING && !contracting && it > escape) {
			/* wandering: again from the start, damped twice as
			 * much, for twice as many iterations */
			ends_mark(ws);
			phase = it - 1;
			omega /= 2;
			memcpy(ws->c, ws->c0, sizeof(double) * (size_t)m);
			settled = jumped = 0;
			cls = failed = 0;
			lam_prev = NAN;
			np = 0;
		}
		int lp_failed;
		enum sample_status st = slp_map(ws, o, r, &lam, &diff,
						&lp_failed, it == 1);
		if (st != SAMPLE_ACCEPTED && (!jumped || lp_failed))
			return path_end(ws, st, 0);
		if (st == SAMPLE_ACCEPTED)
			r->lambda_max = lam;
		if (st == SAMPLE_ACCEPTED && !jumped)
			ends_push(ws);
		if (jumped && st == SAMPLE_ACCEPTED && diff <= PIECE_VERIFY) {
			r->converged = 1;
			return SAMPLE_ACCEPTED;
		}
		if (jumped) {
			/* not a fixed point, or the map has no value at c*
			 * (an LP of it infeasible or unbounded there, or
			 * LP2 off LP1's load: c* is off the plain path, and
			 * its verdicts are not the sample's): back to the
			 * iterate before the jump, and its plain step (so a
			 * failed jump leaves the path as it was); no jump
			 * again while the classification stays the one it
			 * failed on */
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
		res[np++ % (SLP_CONTRACT_SPAN + 1)] = diff;
		unsigned long h = slp_class(ws, diff);
		settled = h == cls ? settled + 1 : 0;
		cls = h;
		if (settled >= SLP_CONTRACT_SPAN)	/* leaving a piece */
			escape = it + SLP_CONTRACT_SPAN;
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
	ends_mark(ws);
	return path_end(ws, SAMPLE_NOT_CONVERGED, 1);
}

/* Rule 8's root search at phase end e (docs/method.md, "The SLP's
 * answer"): at the interface K whose normal-force sum differs most
 * between the end's two iterates (ends_mark), if its residual N_K - c_K
 * changes sign between them, bisection along the segment for the point
 * where it is 0, and
 * from there piece jumps, each verified as rule 4's.  Every evaluation
 * of the map counts in *evals.  A solver failure ends the sample
 * (`numerical`, as anywhere); anything else that does not verify leaves
 * it not converged. */
static enum sample_status slp_cycle_root(struct sample_ws *ws,
					 const struct sample_opts *o,
					 struct sample_result *r, int e,
					 int *evals)
{
	int m = ws->m, K = ws->ends.K[e], lp_failed;
	const double *ci = end_c(ws, e, 0), *cj = end_c(ws, e, 1);
	double fi = ws->ends.f[e][0], fj = ws->ends.f[e][1], lam, diff;
	if (!((fi > 0 && fj < 0) || (fi < 0 && fj > 0)))
		return SAMPLE_NOT_CONVERGED;	/* no root between them */
	double lo = 0, hi = 1;
	enum sample_status st;
	for (int b = 0; b < ROOT_BISECT; b++) {
		double t = 0.5 * (lo + hi);
		for (int k = 0; k < m; k++)
			ws->c[k] = ci[k] + t * (cj[k] - ci[k]);
		st = slp_map(ws, o, r, &lam, &diff, &lp_failed, 0);
		(*evals)++;
		if (st != SAMPLE_ACCEPTED)
			return lp_failed ? st : SAMPLE_NOT_CONVERGED;
		double fk = ws->x[3 * K] + ws->x[3 * K + 1] - ws->c[K];
		if ((fk > 0) == (fi > 0))
			lo = t;
		else
			hi = t;
	}
	for (int jmp = 0; jmp < ROOT_JUMPS; jmp++) {
		if (piece_jump(ws))
			return SAMPLE_NOT_CONVERGED;
		for (int k = 0; k < m; k++)
			ws->c[k] = fmax(ws->cstar[k], 0);
		st = slp_map(ws, o, r, &lam, &diff, &lp_failed, 0);
		(*evals)++;
		if (st != SAMPLE_ACCEPTED)
			return lp_failed ? st : SAMPLE_NOT_CONVERGED;
		if (diff <= PIECE_VERIFY) {
			r->lambda_max = lam;
			r->converged = 1;
			return SAMPLE_ACCEPTED;
		}
	}
	return SAMPLE_NOT_CONVERGED;
}

/* Back to the SLP's start for another attempt: LP-max's capacities
 * (ws->c0, which slp_piece_path keeps) and LP1's and LP2's bases as
 * slp_attempts saved them before the first. */
static void slp_restart(struct sample_ws *ws)
{
	memcpy(ws->c, ws->c0, sizeof(double) * (size_t)ws->m);
	lp_basis_load(ws->lp[LP1], &ws->slp_start[0]);
	lp_basis_load(ws->lp[LP2], &ws->slp_start[1]);
}

/* Another attempt from the SLP's start (slp_restart): the piece path
 * with the contracting test on and the first phase given; the
 * iterations of the attempts before it count on in r->iterations.
 * slack: from the slack bases (slp_slack_bases), not from the bases the
 * start option gave them (rule 7's long phase on a small wall).  A
 * phase never cut follows a piece it leaves for hundreds of iterations,
 * and on such a piece the last-bit differences of two LP starts' values
 * grow about tenfold in ten (the demo's sample 1269 of seed 3: 125.229 N
 * from five starts, 346.648 N from `crash`). */
static enum sample_status slp_again(struct sample_ws *ws,
				    const struct sample_opts *o,
				    struct sample_result *r,
				    double first_phase, int slack)
{
	int its = r->iterations;
	slp_restart(ws);
	if (slack)
		slp_slack_bases(ws);
	enum sample_status st = slp_piece_path(ws, o, r, first_phase, 1);
	r->iterations += its;
	return st;
}

/* The default SLP's attempts with o's step (docs/method.md, "The SLP's
 * answer", rules 6, 7 and 8), each from LP-max's capacities (ws->c0) and
 * LP1's and LP2's saved start bases, until one converges or gives a
 * verdict; each runs only where those before it end not converged.  On
 * a wall of at most SLP_PHASE interfaces the first two are rule 6's:
 * the phases alone, then once more with a contracting phase going on
 * (a 7-course wall beside a pier, tests/data/leftpier-seed1-s32.csv,
 * was cut at iteration 100 while its residual halved every iteration;
 * the test in the first attempt would move 2 of the demo's 6,000
 * accepted samples up, to the plain iteration's higher fixed points);
 * the third is rule 7's long phase, one phase never cut (the demo at
 * friction cov 0.3, tests/data/demo-cov03-seed1-s380.csv: its residual
 * grew slowly at a fixed load until a piece held, past each phase's
 * end; 39 such samples at seeds 1-9, all accepted now).  On a larger
 * wall the contracting test is on in both, and the second
 * attempt's first phase is one iteration per interface (rule 7): there
 * the plain iteration can drift through many pieces with its residual
 * above SLP_WANDERING all the way (150 iterations at omega 0.5 on a
 * 105-block wall of friction 1.0) before it contracts, and each
 * 100-iteration phase restarts it before it is through, with a smaller
 * step that makes the way longer; that wall's 3 samples of 20 (seed 1)
 * that the first left not converged are accepted, each at the plain
 * iteration's load.  Where these leave the sample not converged, the
 * last (rule 8) is a root search at each phase end they passed
 * (slp_cycle_root): a cycle across a steep, thin piece of the map (the
 * facade's sample 2 of seed 1: dN/dc about -530 over 0.005 block
 * weights), or a spiral around a fixed point, brackets the fixed point
 * between two of its iterates, and the zero between them of the
 * residual that differs most lands on the piece that the plain steps
 * jump over.  On a larger wall that is not large (SWS_LARGE_IFACES)
 * the long phase comes after them.  The iterations of all count in
 * r->iterations. */
static enum sample_status slp_round(struct sample_ws *ws,
				    const struct sample_opts *o,
				    struct sample_result *r)
{
	int m = ws->m, small = m <= SLP_PHASE;
	struct slp_ends *E = &ws->ends;
	E->on = 1;
	E->n = E->pushed = 0;
	enum sample_status st = slp_piece_path(ws, o, r, SLP_PHASE, !small);
	if (st == SAMPLE_NOT_CONVERGED)
		st = slp_again(ws, o, r, small ? SLP_PHASE : m, 0);
	/* one phase, never cut, from the slack bases */
	if (st == SAMPLE_NOT_CONVERGED && small)
		st = slp_again(ws, o, r, o->max_iter, 1);
	E->on = 0;
	if (st != SAMPLE_NOT_CONVERGED)
		return st;
	/* rule 8: the phase ends' root searches, in the order the
	 * attempts reached them */
	int its = r->iterations, evals = 0;
	for (int e = 0; e < E->n && st == SAMPLE_NOT_CONVERGED; e++)
		st = slp_cycle_root(ws, o, r, e, &evals);
	r->iterations = its + evals;
	/* the long phase on a larger wall that is not large, after the
	 * root searches, so that every sample they accept keeps its answer
	 * and its cost */
	if (st == SAMPLE_NOT_CONVERGED && !small && m <= SWS_LARGE_IFACES)
		st = slp_again(ws, o, r, o->max_iter, 1);
	return st;
}

/* The default SLP: slp_round's three attempts, and where they leave the
 * sample not converged, the fourth (rule 9): the three again, from the
 * same start, with half the step.  A sample that an earlier attempt
 * accepts keeps its answer.  The smaller step is what the phases of
 * rule 6 give a wandering iteration, but there each phase is cut short
 * and the second attempt's long first phase and the root searches run
 * at the full step: a 290-block bay with two windows at friction 0.65
 * (tests/data/bay-2w-mu065.yaml, seed 11, sample 17) cycles at omega
 * 0.5 and its root searches land between two pieces whose fixed points
 * lie in each other's domain; at 0.25 the third attempt accepts it, at
 * the load the `support` start's first round reaches.  Rules 8 and 9
 * were a large wall's until 2 December 2026: with random friction
 * (cov 0.3) the demo wall left 0.5 % of its samples not converged
 * after rule 6's two attempts (docs/method.md, rule 9). */
static enum sample_status slp_attempts(struct sample_ws *ws,
				       const struct sample_opts *o,
				       struct sample_result *r)
{
	int m = ws->m;
	/* the second attempt starts where the first did: the capacities,
	 * and LP1's and LP2's bases (those the start option gave them), so
	 * that it is the path a sample would take with its first phase m */
	lp_basis_save(ws->lp[LP1], &ws->slp_start[0]);
	lp_basis_save(ws->lp[LP2], &ws->slp_start[1]);
	struct slp_ends *E = &ws->ends;
	if (!E->buf)
		E->buf = sw_xmalloc(sizeof(double) * (size_t)m *
				    (2 * SLP_RING + 2 * SLP_ENDS));
	enum sample_status st = slp_round(ws, o, r);
	if (st != SAMPLE_NOT_CONVERGED)
		return st;
	/* the fourth attempt: the three again, from the same start, with
	 * half the step */
	int its = r->iterations;
	struct sample_opts half = *o;
	half.omega = o->omega / 2;
	slp_restart(ws);
	st = slp_round(ws, &half, r);
	r->iterations += its;
	return st;
}
