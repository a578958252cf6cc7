/*
 * support.c - the support basis of the associative problems.
 *
 * A dry wall stands by passing each block's weight, and what rests on
 * it, down through its bed joints.  This builds that as a simplex basis
 * of LP-max's problem (sample_lp.c: rows = the equilibrium of the free
 * blocks, 3 each; columns = the two edges n + mu t, n - mu t of the
 * friction cone at each contact point, and lambda):
 *
 *   - the free blocks are taken from the top down (centroid height);
 *   - a block's supports are the joints whose normal is within 60
 *     degrees of vertical and whose other body is lower in that order
 *     or a support: its bed joints, the ground;
 *   - of the edge columns of its supports, the block takes the three
 *     that carry its load (its weight, its dead load, and the forces of
 *     the blocks above that rest on it, already known) with forces >= 0
 *     and the least shear in its joints (better()): a 3 x 3 system per
 *     triple, by Cramer's rule;
 *   - those forces then load the blocks beneath.
 *
 * Every column of a block's triple acts on that block and on blocks
 * later in the order, so the basis matrix is block triangular with
 * non-singular 3 x 3 diagonal blocks: it is a basis, whatever the
 * forces.  Where every block finds a triple with forces >= 0 it is
 * primal feasible at lambda = 0: the standing check needs no pivot, and
 * the primal simplex starts LP-max in its second phase, where a load
 * that moves a few blocks needs pivots near them only (the slack basis
 * needs about one pivot per row first).  It is a function of the wall
 * and the contact points alone, so a sample started from it is as
 * history-free as any other start (docs/method.md, "Starts").
 *
 * Written here because no library builds a basis from a structure's
 * load paths: GLPK's crash (glp_adv_basis) sees only the matrix.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/status.h"
#include "support.h"

/* a triple whose determinant is below this times the product of its
 * columns' lengths is singular */
#define SUPPORT_SINGULAR 1e-9
/* candidate edge columns of one block at most (4 per joint beneath) */
#define SUPPORT_MAXCAND 32

struct order_ctx {
	const struct wall *w;
	int b;
};

static int higher_first(const void *pa, const void *pb)
{
	const struct order_ctx *a = pa, *b = pb;
	double ya = a->w->blocks[a->b].cy, yb = b->w->blocks[b->b].cy;
	if (ya != yb)
		return ya > yb ? -1 : 1;
	return (a->b > b->b) - (a->b < b->b);
}

static double dot3(const double *a, const double *b)
{
	return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void cross3(const double *a, const double *b, double *c)
{
	c[0] = a[1] * b[2] - a[2] * b[1];
	c[1] = a[2] * b[0] - a[0] * b[2];
	c[2] = a[0] * b[1] - a[1] * b[0];
}

/* y with y0 c0 + y1 c1 + y2 c2 = rhs; 0 if the columns are (nearly)
 * dependent. */
static int solve3(const double c[3][3], const double *rhs, double *y)
{
	double x12[3], b2[3], c1b[3];
	cross3(c[1], c[2], x12);
	double det = dot3(c[0], x12);
	double scale = sqrt(dot3(c[0], c[0]) * dot3(c[1], c[1]) *
			    dot3(c[2], c[2]));
	if (!(fabs(det) > SUPPORT_SINGULAR * scale))
		return 0;
	cross3(rhs, c[2], b2);
	cross3(c[1], rhs, c1b);
	y[0] = dot3(rhs, x12) / det;
	y[1] = dot3(c[0], b2) / det;
	y[2] = dot3(c[0], c1b) / det;
	return 1;
}

/* A triple of edge columns and the forces with which it carries a
 * block's load. */
struct pick {
	double least;	/* the least of the three forces */
	double shear;	/* sum over its joints of |the joint's net shear| */
	double y[3];
	int t[3];	/* the columns, as indices among the candidates */
};

/* The shear the triple p puts into its joints, summed over the joints
 * by magnitude: the two edges of a point shear by +-mu N, so a triple
 * can carry a vertical load without shearing a joint (the pair at one
 * point, or three points of one joint), or by shearing two joints in
 * opposite directions, which pushes the blocks beneath sideways (and
 * those beneath them) for nothing. */
static double net_shear(const struct statics *st, const int *col,
			const struct pick *p)
{
	double total = 0;
	for (int s = 0; s < 3; s++) {
		int k = col[p->t[s]] / 4, first = 1;
		for (int u = 0; u < s; u++)
			first &= col[p->t[u]] / 4 != k;
		if (!first)
			continue;	/* this joint was summed */
		double net = 0;
		for (int u = s; u < 3; u++)
			if (col[p->t[u]] / 4 == k)
				net += (col[p->t[u]] % 2 ? -1 : 1) *
				       st->mu[k] * p->y[u];
		total += fabs(net);
	}
	return total;
}

/* Is p a better triple than q?  One that carries the load with forces
 * >= 0 (to tol) over one that does not; of two that do, the one that
 * shears its joints less, then the one with the larger least force (the
 * further from a degenerate vertex); of two that do not, the one with
 * the larger least force. */
static int better(const struct pick *p, const struct pick *q, double tol)
{
	int pf = p->least >= -tol, qf = q->least >= -tol;
	if (pf != qf)
		return pf;
	if (pf && fabs(p->shear - q->shear) > tol)
		return p->shear < q->shear;
	return p->least > q->least;
}

/* The body under interface k's block U (the one it rests on), or -1 if
 * the joint is not beneath U; *up is U. */
static int beneath(const struct wall_interface *it, int *up)
{
	if (it->n[1] > 0.5) {		/* n points up, from a into b */
		*up = it->b;
		return it->a;
	}
	if (it->n[1] < -0.5) {
		*up = it->a;
		return it->b;
	}
	return -1;
}

int support_basis(const struct statics *st, unsigned char *basic)
{
	const struct wall *w = st->w;
	int m = w->nifaces, nb = w->nblocks, R = st->nrows, bad = 0;
	struct order_ctx *ord = sw_xmalloc(sizeof *ord * (size_t)(nb + 1));
	int *pos = sw_xmalloc(sizeof(int) * (size_t)(nb + 1));
	int *first = sw_xcalloc((size_t)nb + 2, sizeof(int));
	int *cur = sw_xmalloc(sizeof(int) * (size_t)(nb + 1));
	int *list = sw_xmalloc(sizeof(int) * (size_t)(m + 1));
	double *rhs = sw_xmalloc(sizeof(double) * (size_t)(R + 1));
	memset(basic, 0, 4 * (size_t)m + 1);
	int nf = 0;
	for (int b = 0; b < nb; b++)
		if (!w->blocks[b].fixed)
			ord[nf++] = (struct order_ctx){w, b};
	qsort(ord, (size_t)nf, sizeof *ord, higher_first);
	for (int b = 0; b < nb; b++)
		pos[b] = w->blocks[b].fixed ? nb : -1;
	for (int i = 0; i < nf; i++)
		pos[ord[i].b] = i;
	/* the joints beneath each block, in interface order */
	for (int k = 0; k < m; k++) {
		int up, lo = beneath(&w->ifaces[k], &up);
		if (lo >= 0 && !w->blocks[up].fixed && pos[lo] > pos[up])
			first[up + 1]++;
	}
	for (int b = 0; b < nb; b++)
		first[b + 1] += first[b];
	memcpy(cur, first, sizeof(int) * (size_t)nb);
	for (int k = 0; k < m; k++) {
		int up, lo = beneath(&w->ifaces[k], &up);
		if (lo >= 0 && !w->blocks[up].fixed && pos[lo] > pos[up])
			list[cur[up]++] = k;
	}
	for (int i = 0; i < R; i++)
		rhs[i] = -st->fD[i];

	for (int i = 0; i < nf && bad >= 0; i++) {
		int b = ord[i].b, q = w->blocks[b].eq;
		double c[SUPPORT_MAXCAND][3];
		int col[SUPPORT_MAXCAND], nc = 0;
		for (int l = first[b]; l < first[b + 1]; l++)
			for (int e = 0; e < 2; e++)
				for (int sgn = 0; sgn < 2 && nc < SUPPORT_MAXCAND; sgn++) {
					int rows[6], k = list[l];
					double vals[6];
					int n = statics_edge_column(st, k, e, sgn, rows, vals);
					c[nc][0] = c[nc][1] = c[nc][2] = 0;
					for (int r = 0; r < n; r++)
						if (rows[r] / 3 == q)
							c[nc][rows[r] % 3] = vals[r];
					col[nc++] = 4 * k + 2 * e + sgn;
				}
		double size = fabs(rhs[3 * q]) + fabs(rhs[3 * q + 1]) +
			      fabs(rhs[3 * q + 2]), tol = 1e-12 * (1 + size);
		struct pick best = {-HUGE_VAL, HUGE_VAL, {0, 0, 0}, {-1, -1, -1}};
		for (int t0 = 0; t0 < nc; t0++)
			for (int t1 = t0 + 1; t1 < nc; t1++)
				for (int t2 = t1 + 1; t2 < nc; t2++) {
					struct pick p = {0, 0, {0, 0, 0}, {t0, t1, t2}};
					double cc[3][3];
					for (int s = 0; s < 3; s++)
						memcpy(cc[s], c[p.t[s]], sizeof cc[s]);
					if (!solve3(cc, &rhs[3 * q], p.y))
						continue;
					p.least = fmin(p.y[0], fmin(p.y[1], p.y[2]));
					p.shear = net_shear(st, col, &p);
					if (better(&p, &best, tol))
						best = p;
				}
		if (best.t[0] < 0) {	/* nothing beneath it: no basis */
			bad = -1;
			break;
		}
		if (best.least < -tol)
			bad++;
		int tb[3] = {best.t[0], best.t[1], best.t[2]};
		double *yb = best.y;
		/* the chosen forces load the bodies beneath */
		for (int s = 0; s < 3; s++) {
			int cl = col[tb[s]], rows[6];
			double vals[6];
			basic[cl] = 1;
			int n = statics_edge_column(st, cl / 4, cl % 4 / 2, cl % 2,
						    rows, vals);
			for (int r = 0; r < n; r++)
				if (rows[r] / 3 != q)
					rhs[rows[r]] -= vals[r] * yb[s];
		}
	}
	free(ord);
	free(pos);
	free(first);
	free(cur);
	free(list);
	free(rhs);
	return bad;
}
