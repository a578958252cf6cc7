/*
 * piece.h - the exact fixed point of the SLP's map on one affine piece
 * (private to the library; docs/method.md, "The SLP's answer").
 *
 * The SLP's map c -> N(c) evaluates LP1 and, unless LP1's optimum is
 * unique, LP2.  While the LP that gave the stress field keeps its
 * optimal basis, every non-basic variable sits at a bound that is an
 * affine function of c (a normal force, p or q at 0, a shear at
 * +-mu_k c_k, a closeness row at c_k, an equilibrium row at -f_D), so
 * the basic variables, and N(c), are affine in c: N(c) = A c + b on
 * that piece.  Its fixed point c* = (I - A)^-1 b is the solution of one
 * sparse square system in the basic variables and c together:
 *
 *     rows of the LP, the c-dependent bounds moved to the left,
 *     c_k - N_a,k - N_b,k = 0        for every interface k,
 *
 * solved by the LP solver's sparse LU (lp_solve_square).  An interface whose
 * closeness row holds no basic p_k, q_k has N_k = c_k for every c on the
 * piece: its c_k stays where it is (the plain iteration keeps it too),
 * since I - A is singular in that direction.
 */
#ifndef SLIPWALL_PIECE_H
#define SLIPWALL_PIECE_H

#include "lp.h"

/* The SLP problem X (LP1 or LP2, as sample_lp.c builds them: columns
 * N_a,k = 3k, N_b,k = 3k + 1, T_k = 3k + 2, lambda = 3m; LP2 also p_k =
 * 3m + 1 + k, q_k = 3m + 1 + m + k and the closeness rows R + k), just
 * solved at the capacities c, m interfaces, R equilibrium rows, mu the
 * interfaces' friction.  Writes the piece's fixed point into cstar and
 * returns 0; -1 if the piece has none (I - A singular) or GLPK failed. */
struct piece {
	int m, R;
	int closeness;		/* X is LP2 */
	const double *mu;	/* m: the interfaces' friction */
};

int piece_fixed_point(const struct lp *X, const struct piece *pc,
		      const double *c, double *cstar);

#endif
