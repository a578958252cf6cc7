/*
 * sample_tie.c - "One answer per sample" (docs/method.md): wherever an
 * LP's optimum is not unique, the sample takes the optimal solution with
 * the least weighted sum of its normal forces (or, for the kinematic LP,
 * joint rates), the weights hashed from the contact positions
 * (sws_tie_weights, into the workspace's r), so that the result does not
 * depend on the start.  LP2's tie-break is folded into its objective
 * (sws_put_lp2_objective); the others are a second LP over the role's
 * optimal face (lp_tiebreak, solved and counted by sample_lp.c's
 * sws_counted).  Called from sample_start.c (weights, LP2's objective),
 * sample_slp.c (LP2) and sample_onset.c (LP-max, LP-min, the mechanism).
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "sample_ws.h"

/* the weight of sum r_j N_j in LP2's objective (sws_put_lp2_objective) */
#define TIE_LP2 1e-4

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
void sws_tie_weights(struct sample_ws *ws, const double *xi)
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
 * is nearly always unique and no second LP runs (sws_lp2_tiebreak is the
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
void sws_put_lp2_objective(struct sample_ws *ws)
{
	for (int k = 0; k < ws->m; k++)
		for (int e = 0; e < 2; e++)
			lp_set_obj(ws->lp[LP2], 3 * k + e, TIE_LP2 * ws->r[2 * k + e]);
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
	return sws_counted(ws, role + ROLES, LP_PRIMAL, c2, r);
}

/* An associative problem's tie-break objective, sum r_j N_j (N_j =
 * alpha_j + beta_j), into ws->c2. */
static void assoc_objective(struct sample_ws *ws)
{
	for (int k = 0; k < ws->m; k++)
		for (int e = 0; e < 2; e++) {
			ws->c2[ACOL_ALPHA(k, e)] = ws->r[2 * k + e];
			ws->c2[ACOL_BETA(k, e)] = ws->r[2 * k + e];
		}
	ws->c2[ACOL_LAMBDA(ws)] = 0;
}

/* The tie-break of an associative problem (LP-max, LP-min): of its
 * optimal stress fields, the one with the least sum r_j N_j. */
enum lp_status sws_assoc_tiebreak(struct sample_ws *ws, enum role role,
				     struct sample_result *r)
{
	assoc_objective(ws);
	return tiebreak(ws, role, ws->c2, r);
}

/* LP-max's floor (docs/method.md, "The SLP's start"): the load the
 * floor's tie-break holds, the optimum lam less one to two steps of a
 * grid of 2^-TIE_FLOOR_BITS of lam's binary order, so 1e-6 to 2e-6 of
 * lam below it.  The optimum is known only to the simplex's tolerances
 * (3e-10 of it between the dual and the primal simplex on the demo).
 * LP-max runs on one fixed path whatever the start (sample_start.c), so
 * the optimum is the same from every start; the grid keeps the floor
 * from following its last digits all the same. */
#define TIE_FLOOR_BITS 20

static double lpmax_floor(double lam)
{
	double g = ldexp(1, ilogb(lam) - TIE_FLOOR_BITS);
	return (floor(lam / g) - 1) * g;
}

/* The floor's tie-break: of the stress fields that carry at least
 * LP-max's floor (its optimum lam, unscaled), the one with the least
 * sum r_j N_j, by the primal simplex from the basis LP-max's face
 * tie-break ended at (primal feasible: it carries lam).  LP-max and its
 * tie-break run on one fixed path whatever the start (sample_start.c),
 * so the bound and the basis, and with them the field, are the
 * sample's (docs/method.md, "The SLP's start").  From the canonical
 * basis instead: twice the pivots, the same answers. */
enum lp_status sws_floor_tiebreak(struct sample_ws *ws, double lam,
				  struct sample_result *r)
{
	assoc_objective(ws);
	return sws_counted_floor(ws, AMAX + ROLES, ws->c2, ACOL_LAMBDA(ws),
				 lpmax_floor(lam), r);
}

/* LP2's tie-break, if its weighted optimum is still not unique: the
 * least sum r_j N_j on its optimal face. */
enum lp_status sws_lp2_tiebreak(struct sample_ws *ws, struct sample_result *r)
{
	int m = ws->m;
	memset(ws->c2, 0, sizeof(double) * (5 * (size_t)m + 1));
	for (int k = 0; k < m; k++)
		for (int e = 0; e < 2; e++)
			ws->c2[3 * k + e] = ws->r[2 * k + e];
	return tiebreak(ws, LP2, ws->c2, r);
}

/* The kinematic LP's tie-break: of its least-motion mechanisms, the one
 * with the least weighted joint motion, sum r_j dn_j + sum r_k |dt_k|
 * (the opening rates in velocity space: the r-weighted sum of the
 * normal-force columns of A, as sws_put_kin_objective). */
enum lp_status sws_kin_tiebreak(struct sample_ws *ws,
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
