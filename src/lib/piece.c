/*
 * piece.c - the exact fixed point of the SLP's map on one affine piece.
 * See piece.h for the system; docs/method.md ("The SLP's answer") for
 * why the SLP's answer is defined by it.
 *
 * Unknowns: the basic variables of X (rows' auxiliaries and columns, in
 * the order met), then c_k for every interface that is not held.
 * Equations: X's rows (sum_j a_ij x_j = the row's value, a basic
 * auxiliary on the left as -aux_i), then c_k - N_a,k - N_b,k = 0 for
 * every interface not held.  A non-basic variable is at its bound:
 * a shear at s mu_k c_k (s its sign, s = 0 at a dead contact, where it
 * stays 0) goes to the left in c_k's column; every other one is a
 * constant on the right.  A closeness row's value c_k likewise.
 */
#include <math.h>
#include <stdlib.h>

#include "piece.h"
#include "slipwall/status.h"

struct system {
	int nnz, cap;
	int *ri, *ci;
	double *v;
};

static void put(struct system *s, int i, int j, double v)
{
	if (v == 0)
		return;
	if (s->nnz == s->cap) {
		s->cap = s->cap ? 2 * s->cap : 1024;
		s->ri = sw_xrealloc(s->ri, sizeof(int) * (size_t)s->cap);
		s->ci = sw_xrealloc(s->ci, sizeof(int) * (size_t)s->cap);
		s->v = sw_xrealloc(s->v, sizeof(double) * (size_t)s->cap);
	}
	s->ri[s->nnz] = i;
	s->ci[s->nnz] = j;
	s->v[s->nnz++] = v;
}

int piece_fixed_point(const struct lp *X, const struct piece *pc,
		      const double *c, double *cstar)
{
	int m = pc->m, R = pc->R;
	int nrows = R + (pc->closeness ? m : 0);
	int ncols = 3 * m + 1 + (pc->closeness ? 2 * m : 0);
	int *unk_col = sw_xmalloc(sizeof(int) * (size_t)ncols);
	int *unk_c = sw_xmalloc(sizeof(int) * (size_t)(m + 1));
	int *rows = sw_xmalloc(sizeof(int) * (size_t)(nrows + 1));
	double *vals = sw_xmalloc(sizeof(double) * (size_t)(nrows + 1));
	double *b = sw_xcalloc((size_t)(nrows + 2 * m + 1), sizeof(double));
	struct system s = {0};
	int rc = -1, n = 0;

	/* the unknowns: basic auxiliaries and columns, then the free c_k */
	int nbasic = 0;
	for (int i = 0; i < nrows; i++)
		nbasic += lp_row_basic(X, i);
	for (int j = 0; j < ncols; j++)
		unk_col[j] = lp_col_basic(X, j) ? nbasic++ : -1;
	if (nbasic != nrows)
		goto out;
	n = nrows;
	for (int k = 0; k < m; k++) {
		int held = pc->closeness && !lp_row_basic(X, R + k) &&
			   !lp_col_basic(X, 3 * m + 1 + k) &&
			   !lp_col_basic(X, 3 * m + 1 + m + k);
		unk_c[k] = held ? -1 : n++;
	}
	/* the rows' auxiliaries */
	int u = 0;
	for (int i = 0; i < nrows; i++) {
		if (lp_row_basic(X, i)) {
			put(&s, i, u++, -1);
		} else if (i >= R && unk_c[i - R] >= 0) {
			put(&s, i, unk_c[i - R], -1);
		} else {
			b[i] += lp_row(X, i);
		}
	}
	/* the columns */
	for (int j = 0; j < ncols; j++) {
		int nz = lp_get_col(X, j, rows, vals);
		int k = j < 3 * m ? j / 3 : -1, kind = j < 3 * m ? j % 3 : -1;
		if (unk_col[j] >= 0) {
			for (int t = 0; t < nz; t++)
				put(&s, rows[t], unk_col[j], vals[t]);
			if ((kind == 0 || kind == 1) && unk_c[k] >= 0)
				put(&s, unk_c[k], unk_col[j], -1);
			continue;
		}
		double x = lp_col(X, j);
		if (kind == 2 && unk_c[k] >= 0 && x != 0) {
			double sm = (x > 0 ? 1 : -1) * pc->mu[k];
			for (int t = 0; t < nz; t++)
				put(&s, rows[t], unk_c[k], vals[t] * sm);
			continue;
		}
		for (int t = 0; t < nz; t++)
			b[rows[t]] -= vals[t] * x;
		if ((kind == 0 || kind == 1) && unk_c[k] >= 0)
			b[unk_c[k]] += x;	/* c_k - N_a - N_b = 0 */
	}
	for (int k = 0; k < m; k++)
		if (unk_c[k] >= 0)
			put(&s, unk_c[k], unk_c[k], 1);
	if (lp_solve_square(lp_solver_of(X), n, s.nnz, s.ri, s.ci, s.v, b) != 0)
		goto out;
	for (int k = 0; k < m; k++)
		cstar[k] = unk_c[k] >= 0 ? b[unk_c[k]] : c[k];
	rc = 0;
out:
	free(unk_col);
	free(unk_c);
	free(rows);
	free(vals);
	free(b);
	free(s.ri);
	free(s.ci);
	free(s.v);
	return rc;
}
