/*
 * geom.c - convex polygons, overlap and contact detection.
 *
 * Contact detection is the only part with a cost worth a design: a wall of
 * 10,000 blocks has 40,000 edges, and comparing every pair would take
 * seconds.  Instead every edge (and, for overlaps, every block) is put into
 * the cells of a uniform grid that its bounding box covers; only items
 * that share a cell are compared, and a pair is examined only in the one
 * cell that holds the lower-left corner of the intersection of their boxes,
 * so no pair is found twice.  The cell size is the mean item size, grown
 * until the grid has no more cells than about four per item, so the cost
 * is linear for walls of similar-sized blocks (a long ground edge just
 * covers many cells).
 *
 * Tolerances are relative to the blocks involved (wall_block.size), never
 * to the whole wall: a support far away must not make a real overlap or a
 * gap pass.  Contacts are found between the corners of each polygon
 * (geom_prune), so a vertex in the middle of an edge changes nothing.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/geom.h"

/* The power of two nearest above the largest |v| of n numbers (1 for
 * none, zeros or non-finite ones).  Scaling by it is exact, so sums of
 * products of scaled numbers round exactly as the unscaled ones would,
 * but neither overflow nor underflow for polygons of 1e-150 or 1e100 m. */
static double pow2_scale(const double *v, int n, double sub0, double sub1)
{
	double m = 0;
	for (int i = 0; i < n; i++)
		m = fmax(m, fabs(v[i] - (i % 2 ? sub1 : sub0)));
	if (!(m > 0) || !isfinite(m))
		return 1;
	int e;
	frexp(m, &e);
	return ldexp(1, e);
}

double geom_area(const double *xy, int nv)
{
	/* relative to the first vertex: the shoelace of absolute
	 * coordinates sums products of the size of |x|^2 that cancel to
	 * the size of the area, and loses all of it far from the origin (a
	 * 0.4 x 0.8 m block at (-1e9, -1e9) came out 400 times too large) */
	double x0 = xy[0], y0 = xy[1], a = 0;
	double s = pow2_scale(xy, 2 * nv, x0, y0);
	for (int i = 0; i < nv; i++) {
		int j = (i + 1) % nv;
		a += ((xy[2 * i] - x0) / s) * ((xy[2 * j + 1] - y0) / s) -
		     ((xy[2 * j] - x0) / s) * ((xy[2 * i + 1] - y0) / s);
	}
	return a / 2 * s * s;
}

/* The largest side of the polygon's bounding box. */
static double extent_of(const double *xy, int nv)
{
	double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
	for (int i = 0; i < nv; i++) {
		x0 = fmin(x0, xy[2 * i]);
		x1 = fmax(x1, xy[2 * i]);
		y0 = fmin(y0, xy[2 * i + 1]);
		y1 = fmax(y1, xy[2 * i + 1]);
	}
	return fmax(x1 - x0, y1 - y0);
}

double geom_thinness(const double *xy, int nv)
{
	double extent = extent_of(xy, nv);
	double t = fabs(geom_area(xy, nv)) / (extent * extent);
	return isfinite(t) ? t : 0;
}

int geom_far_vertex(const double *xy, int nv)
{
	double extent = extent_of(xy, nv);
	double thick = fabs(geom_area(xy, nv)) / extent;
	if (!(thick > 0) || !isfinite(thick))
		return -1;	/* degenerate: geom_check_polygon says so */
	for (int i = 0; i < 2 * nv; i++)
		if (ldexp(fabs(xy[i]), -52) > GEOM_PRECISION_REL * thick)
			return i / 2;
	return -1;
}

void geom_centroid(const double *xy, int nv, double *cx, double *cy)
{
	/* relative to the first vertex, for accuracy far from the origin */
	double x0 = xy[0], y0 = xy[1], a = 0, sx = 0, sy = 0;
	double s = pow2_scale(xy, 2 * nv, x0, y0);
	for (int i = 0; i < nv; i++) {
		int j = (i + 1) % nv;
		double xi = (xy[2 * i] - x0) / s, yi = (xy[2 * i + 1] - y0) / s;
		double xj = (xy[2 * j] - x0) / s, yj = (xy[2 * j + 1] - y0) / s;
		double c = xi * yj - xj * yi;
		a += c;
		sx += (xi + xj) * c;
		sy += (yi + yj) * c;
	}
	*cx = x0 + sx / (3 * a) * s;
	*cy = y0 + sy / (3 * a) * s;
}

enum geom_shape geom_check_polygon(const double *xy, int nv, double tol)
{
	if (nv < 3)
		return GEOM_DEGENERATE;
	double perim = 0;
	for (int i = 0; i < nv; i++) {
		int j = (i + 1) % nv;
		double len = hypot(xy[2 * j] - xy[2 * i],
				   xy[2 * j + 1] - xy[2 * i + 1]);
		if (len <= tol)
			return GEOM_DEGENERATE;
		perim += len;
	}
	double area = geom_area(xy, nv);
	if (fabs(area) <= tol * perim)
		return GEOM_DEGENERATE;
	if (area < 0)
		return GEOM_CLOCKWISE;
	/* Convex and simple: every turn is a left turn (or straight) and the
	 * turns add up to one full revolution (a star has all left turns but
	 * winds twice). */
	double turn = 0;
	for (int i = 0; i < nv; i++) {
		const double *p = xy + 2 * i, *q = xy + 2 * ((i + 1) % nv),
			     *r = xy + 2 * ((i + 2) % nv);
		double ex = q[0] - p[0], ey = q[1] - p[1];
		double fx = r[0] - q[0], fy = r[1] - q[1];
		double cr = ex * fy - ey * fx, dt = ex * fx + ey * fy;
		if (cr < -tol * hypot(fx, fy))
			return GEOM_NONCONVEX;
		turn += atan2(cr, dt);
	}
	if (fabs(turn - 2 * M_PI) > 1e-6)
		return GEOM_NONCONVEX;
	return GEOM_OK;
}

int geom_prune(const double *xy, int nv, double tol, double *out)
{
	char *corner = sw_xmalloc((size_t)nv + 1);
	int start = -1, m = 0;
	for (int i = 0; i < nv; i++) {
		const double *p = xy + 2 * ((i + nv - 1) % nv), *q = xy + 2 * i,
			     *r = xy + 2 * ((i + 1) % nv);
		double ex = r[0] - p[0], ey = r[1] - p[1];
		double cr = ex * (q[1] - p[1]) - ey * (q[0] - p[0]);
		/* q's distance from the line p r, and q between p and r */
		double dt = ex * (q[0] - p[0]) + ey * (q[1] - p[1]);
		corner[i] = !(fabs(cr) <= tol * hypot(ex, ey) && dt > 0 &&
			      dt < ex * ex + ey * ey);
		if (!corner[i])
			continue;
		m++;
		if (start < 0 || q[1] < xy[2 * start + 1] ||
		    (q[1] == xy[2 * start + 1] && q[0] < xy[2 * start]))
			start = i;
	}
	if (m < 3) {		/* not a polygon to prune: keep it whole */
		memcpy(out, xy, sizeof(double) * 2 * (size_t)nv);
		free(corner);
		return nv;
	}
	m = 0;
	for (int k = 0; k < nv; k++) {
		int i = (start + k) % nv;
		if (!corner[i])
			continue;
		out[2 * m] = xy[2 * i];
		out[2 * m + 1] = xy[2 * i + 1];
		m++;
	}
	free(corner);
	return m;
}

const char *geom_shape_text(enum geom_shape s)
{
	switch (s) {
	case GEOM_OK: return "a convex polygon";
	case GEOM_DEGENERATE: return "degenerate (fewer than 3 distinct vertices or zero area)";
	case GEOM_CLOCKWISE: return "clockwise (vertices must run counter-clockwise)";
	case GEOM_NONCONVEX: return "not convex (or self-intersecting)";
	}
	return "?";
}

int geom_contains(const double *xy, int nv, double px, double py, double tol)
{
	for (int i = 0; i < nv; i++) {
		int j = (i + 1) % nv;
		double ex = xy[2 * j] - xy[2 * i], ey = xy[2 * j + 1] - xy[2 * i + 1];
		double cr = ex * (py - xy[2 * i + 1]) - ey * (px - xy[2 * i]);
		if (cr < -tol * hypot(ex, ey))
			return 0;
	}
	return 1;
}

/* Projection of polygon p on the axis (ax, ay). */
static void project(const double *p, int n, double ax, double ay,
		    double *lo, double *hi)
{
	*lo = INFINITY;
	*hi = -INFINITY;
	for (int i = 0; i < n; i++) {
		double s = p[2 * i] * ax + p[2 * i + 1] * ay;
		if (s < *lo)
			*lo = s;
		if (s > *hi)
			*hi = s;
	}
}

/* 1 if some edge normal of a separates a from b (up to tol). */
static int separated_by(const double *a, int na, const double *b, int nb,
			double tol)
{
	for (int i = 0; i < na; i++) {
		int j = (i + 1) % na;
		double ex = a[2 * j] - a[2 * i], ey = a[2 * j + 1] - a[2 * i + 1];
		double len = hypot(ex, ey);
		if (len == 0)
			continue;
		double ax = ey / len, ay = -ex / len;
		double alo, ahi, blo, bhi;
		project(a, na, ax, ay, &alo, &ahi);
		project(b, nb, ax, ay, &blo, &bhi);
		if (fmin(ahi, bhi) - fmax(alo, blo) <= tol)
			return 1;
	}
	return 0;
}

int geom_overlap(const double *a, int na, const double *b, int nb, double tol)
{
	return !separated_by(a, na, b, nb, tol) && !separated_by(b, nb, a, na, tol);
}

/* ---- the grid -------------------------------------------------------- */

struct box {
	double x0, y0, x1, y1;
};

/* Items in cells, compressed rows: the items of cell c are
 * item[start[c] .. start[c+1]-1]. */
struct grid {
	double ox, oy, hx, hy;	/* origin, cell width and height */
	int nx, ny;
	int *start, *item;
};

static void cell_range(const struct grid *g, const struct box *b, int *i0,
		       int *j0, int *i1, int *j1)
{
	*i0 = (int)floor((b->x0 - g->ox) / g->hx);
	*j0 = (int)floor((b->y0 - g->oy) / g->hy);
	*i1 = (int)floor((b->x1 - g->ox) / g->hx);
	*j1 = (int)floor((b->y1 - g->oy) / g->hy);
	if (*i0 < 0) *i0 = 0;
	if (*j0 < 0) *j0 = 0;
	if (*i1 >= g->nx) *i1 = g->nx - 1;
	if (*j1 >= g->ny) *j1 = g->ny - 1;
}

static void grid_build(struct grid *g, const struct box *bx, int n)
{
	double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
	double sx = 0, sy = 0;
	for (int k = 0; k < n; k++) {
		x0 = fmin(x0, bx[k].x0);
		y0 = fmin(y0, bx[k].y0);
		x1 = fmax(x1, bx[k].x1);
		y1 = fmax(y1, bx[k].y1);
		sx += bx[k].x1 - bx[k].x0;
		sy += bx[k].y1 - bx[k].y0;
	}
	double w = fmax(x1 - x0, 1e-300), hgt = fmax(y1 - y0, 1e-300);
	/* Cells as wide and as tall as the mean box, separately: square
	 * cells of the mean size put a stack of long thin slabs (a 1.6 MB
	 * file of 20,000 of them: 11 s; fuzzing, docs/reliability.md) into
	 * one cell, and pairs in a cell are quadratic. */
	double hx = n ? sx / n : w, hy = n ? sy / n : hgt;
	if (!(hx > 0))
		hx = fmax(hy, w);
	if (!(hy > 0))
		hy = fmax(hx, hgt);
	/* no more than about 4 cells per item */
	while ((w / hx + 1) * (hgt / hy + 1) > 4.0 * n + 16) {
		hx *= 1.5;
		hy *= 1.5;
	}
	g->ox = x0;
	g->oy = y0;
	g->hx = hx;
	g->hy = hy;
	g->nx = (int)(w / hx) + 1;
	g->ny = (int)(hgt / hy) + 1;
	int ncell = g->nx * g->ny;
	g->start = sw_xcalloc((size_t)ncell + 1, sizeof(int));
	/* count, prefix-sum, fill */
	for (int k = 0; k < n; k++) {
		int i0, j0, i1, j1;
		cell_range(g, &bx[k], &i0, &j0, &i1, &j1);
		for (int j = j0; j <= j1; j++)
			for (int i = i0; i <= i1; i++)
				g->start[j * g->nx + i + 1]++;
	}
	for (int c = 0; c < ncell; c++)
		g->start[c + 1] += g->start[c];
	g->item = sw_xmalloc(sizeof(int) * (size_t)(g->start[ncell] + 1));
	int *fill = sw_xmalloc(sizeof(int) * (size_t)ncell);
	memcpy(fill, g->start, sizeof(int) * (size_t)ncell);
	for (int k = 0; k < n; k++) {
		int i0, j0, i1, j1;
		cell_range(g, &bx[k], &i0, &j0, &i1, &j1);
		for (int j = j0; j <= j1; j++)
			for (int i = i0; i <= i1; i++)
				g->item[fill[j * g->nx + i]++] = k;
	}
	free(fill);
}

static void grid_free(struct grid *g)
{
	free(g->start);
	free(g->item);
}

/* Is cell (ci, cj) the one where the pair (a, b) is examined? */
static int home_cell(const struct grid *g, const struct box *a,
		     const struct box *b, int ci, int cj)
{
	struct box x = {fmax(a->x0, b->x0), fmax(a->y0, b->y0), 0, 0};
	x.x1 = x.x0;
	x.y1 = x.y0;
	int i0, j0, i1, j1;
	cell_range(g, &x, &i0, &j0, &i1, &j1);
	return i0 == ci && j0 == cj;
}

/* Call fn(a, b, ctx) once for every pair of items whose boxes intersect;
 * stops and returns fn's value when it is non-zero. */
static int grid_pairs(const struct box *bx, int n,
		      int (*fn)(int, int, void *), void *ctx)
{
	struct grid g;
	int ret = 0;
	if (n < 2)
		return 0;
	grid_build(&g, bx, n);
	for (int cj = 0; cj < g.ny && !ret; cj++) {
		for (int ci = 0; ci < g.nx && !ret; ci++) {
			int c = cj * g.nx + ci;
			for (int p = g.start[c]; p < g.start[c + 1] && !ret; p++) {
				for (int q = p + 1; q < g.start[c + 1] && !ret; q++) {
					const struct box *a = &bx[g.item[p]],
							 *b = &bx[g.item[q]];
					if (a->x0 > b->x1 || b->x0 > a->x1 ||
					    a->y0 > b->y1 || b->y0 > a->y1)
						continue;
					if (!home_cell(&g, a, b, ci, cj))
						continue;
					ret = fn(g.item[p], g.item[q], ctx);
				}
			}
		}
	}
	grid_free(&g);
	return ret;
}

/* ---- overlaps -------------------------------------------------------- */

struct overlap_ctx {
	const struct wall *w;
	double rel;		/* tolerance, relative to the smaller block */
	int i, j;
};

static int overlap_pair(int a, int b, void *vctx)
{
	struct overlap_ctx *c = vctx;
	const struct wall_block *A = &c->w->blocks[a], *B = &c->w->blocks[b];
	if (A->fixed && B->fixed)
		return 0;
	double tol = c->rel * fmin(A->size, B->size);
	if (!geom_overlap(A->xy, A->nv, B->xy, B->nv, tol))
		return 0;
	c->i = a < b ? a : b;
	c->j = a < b ? b : a;
	return 1;
}

static struct box poly_box(const double *xy, int nv, double pad)
{
	struct box b = {INFINITY, INFINITY, -INFINITY, -INFINITY};
	for (int i = 0; i < nv; i++) {
		b.x0 = fmin(b.x0, xy[2 * i]);
		b.y0 = fmin(b.y0, xy[2 * i + 1]);
		b.x1 = fmax(b.x1, xy[2 * i]);
		b.y1 = fmax(b.y1, xy[2 * i + 1]);
	}
	b.x0 -= pad;
	b.y0 -= pad;
	b.x1 += pad;
	b.y1 += pad;
	return b;
}

int geom_find_overlap(const struct wall *w, double rel, int *i, int *j)
{
	struct box *bx = sw_xmalloc(sizeof *bx * (size_t)(w->nblocks + 1));
	for (int k = 0; k < w->nblocks; k++)
		bx[k] = poly_box(w->blocks[k].xy, w->blocks[k].nv, 0);
	struct overlap_ctx c = {w, rel, -1, -1};
	int found = grid_pairs(bx, w->nblocks, overlap_pair, &c);
	free(bx);
	if (found) {
		*i = c.i;
		*j = c.j;
	}
	return found;
}

/* ---- contacts -------------------------------------------------------- */

struct edge {
	int body;
	double p[2], q[2];	/* p -> q counter-clockwise along the body */
	double t[2];		/* unit direction */
	double len;
	double tol;		/* the body's tolerance, m */
};

struct contact_ctx {
	const struct wall *w;
	const struct edge *e;
	struct wall_interface *out;
	int n, cap;
};

static int contact_pair(int ea, int eb, void *vctx)
{
	struct contact_ctx *c = vctx;
	const struct edge *A = &c->e[ea], *B = &c->e[eb];
	if (A->body == B->body)
		return 0;
	if (c->w->blocks[A->body].fixed && c->w->blocks[B->body].fixed)
		return 0;
	/* opposite directions: outward normals opposite */
	if (A->t[0] * B->t[0] + A->t[1] * B->t[1] > -1 + 1e-9)
		return 0;
	double tol = fmin(A->tol, B->tol);
	/* collinear: B's ends on A's line */
	double nx = A->t[1], ny = -A->t[0];	/* outward normal of A */
	double d1 = (B->p[0] - A->p[0]) * nx + (B->p[1] - A->p[1]) * ny;
	double d2 = (B->q[0] - A->p[0]) * nx + (B->q[1] - A->p[1]) * ny;
	if (fabs(d1) > tol || fabs(d2) > tol)
		return 0;
	/* overlap along A's direction */
	double s1 = (B->q[0] - A->p[0]) * A->t[0] + (B->q[1] - A->p[1]) * A->t[1];
	double s2 = (B->p[0] - A->p[0]) * A->t[0] + (B->p[1] - A->p[1]) * A->t[1];
	double lo = fmax(0, fmin(s1, s2)), hi = fmin(A->len, fmax(s1, s2));
	if (hi - lo <= tol)
		return 0;
	/* a = the lower-numbered body, n its outward normal */
	const struct edge *E = A->body < B->body ? A : B;
	const struct edge *F = E == A ? B : A;
	struct wall_interface it;
	memset(&it, 0, sizeof it);
	it.a = E->body;
	it.b = F->body;
	it.t[0] = E->t[0];
	it.t[1] = E->t[1];
	it.n[0] = E->t[1];
	it.n[1] = -E->t[0];
	/* the segment on E's line, in E's direction */
	double u1, u2;
	if (E == A) {
		u1 = lo;
		u2 = hi;
	} else {
		/* parameters along B (= E) of A's overlap interval */
		double a1 = (A->p[0] - B->p[0]) * B->t[0] + (A->p[1] - B->p[1]) * B->t[1];
		double a2 = (A->q[0] - B->p[0]) * B->t[0] + (A->q[1] - B->p[1]) * B->t[1];
		u1 = fmax(0, fmin(a1, a2));
		u2 = fmin(B->len, fmax(a1, a2));
	}
	for (int k = 0; k < 2; k++) {
		it.p1[k] = E->p[k] + u1 * E->t[k];
		it.p2[k] = E->p[k] + u2 * E->t[k];
	}
	it.len = u2 - u1;
	if (fabs(it.n[0]) < 1e-9)
		it.kind = JOINT_BED;
	else if (fabs(it.n[1]) < 1e-9)
		it.kind = JOINT_HEAD;
	else
		it.kind = JOINT_OTHER;
	if (c->n == c->cap) {
		c->cap = c->cap ? 2 * c->cap : 64;
		c->out = sw_xrealloc(c->out, sizeof *c->out * (size_t)c->cap);
	}
	c->out[c->n++] = it;
	return 0;
}

static int iface_cmp(const void *pa, const void *pb)
{
	const struct wall_interface *a = pa, *b = pb;
	if (a->a != b->a)
		return a->a < b->a ? -1 : 1;
	if (a->b != b->b)
		return a->b < b->b ? -1 : 1;
	double sa = a->p1[0] + a->p1[1], sb = b->p1[0] + b->p1[1];
	return (sa > sb) - (sa < sb);
}

int geom_contacts(const struct wall *w, double rel,
		  struct wall_interface **out)
{
	int ne = 0, maxnv = 0;
	for (int k = 0; k < w->nblocks; k++) {
		ne += w->blocks[k].nv;
		if (w->blocks[k].nv > maxnv)
			maxnv = w->blocks[k].nv;
	}
	struct edge *e = sw_xmalloc(sizeof *e * (size_t)(ne + 1));
	struct box *bx = sw_xmalloc(sizeof *bx * (size_t)(ne + 1));
	double *xy = sw_xmalloc(sizeof(double) * 2 * (size_t)(maxnv + 1));
	int m = 0;
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *B = &w->blocks[k];
		/* the corners only: a vertex in the middle of an edge would
		 * split one shared boundary into two interfaces */
		double tol = rel * B->size;
		int nv = geom_prune(B->xy, B->nv, GEOM_PRUNE_REL * B->size, xy);
		for (int i = 0; i < nv; i++) {
			int j = (i + 1) % nv;
			struct edge *E = &e[m];
			E->body = k;
			E->tol = tol;
			E->p[0] = xy[2 * i];
			E->p[1] = xy[2 * i + 1];
			E->q[0] = xy[2 * j];
			E->q[1] = xy[2 * j + 1];
			E->len = hypot(E->q[0] - E->p[0], E->q[1] - E->p[1]);
			if (E->len <= 0)
				continue;
			E->t[0] = (E->q[0] - E->p[0]) / E->len;
			E->t[1] = (E->q[1] - E->p[1]) / E->len;
			double seg[4] = {E->p[0], E->p[1], E->q[0], E->q[1]};
			bx[m] = poly_box(seg, 2, tol);
			m++;
		}
	}
	struct contact_ctx c = {w, e, NULL, 0, 0};
	grid_pairs(bx, m, contact_pair, &c);
	free(xy);
	free(e);
	free(bx);
	if (c.n > 1)
		qsort(c.out, (size_t)c.n, sizeof *c.out, iface_cmp);
	*out = c.out;
	return c.n;
}
