/*
 * wedit.c - the computations behind the workbench's edits; see wedit.h.
 *
 * Moved here from the workbench's curses files (issue 15) so that they
 * can be tested without a terminal: the copy of an edited wall, the
 * layout edits, restoring a removed block, the block cursor's grid and
 * the load stations of the outline.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/wedit.h"
#include "slipwall/geom.h"
#include "slipwall/layout.h"

static int wedit_generated(const char *id)
{
	int c, k, n = 0;
	return id && sscanf(id, "c%db%d%n", &c, &k, &n) == 2 && id[n] == 0;
}

/* Course and place of a generated id ("c<course>b<k>"), as one number
 * that sorts like the layout's order; -1 for other ids. */
static long wedit_order(const char *id)
{
	int c, k, n = 0;
	if (!id || sscanf(id, "c%db%d%n", &c, &k, &n) != 2 || id[n])
		return -1;
	return (long)c * 1000000L + k;
}

struct wall *wedit_copy(const struct wall *w, const struct wall_layout *regen,
		       int skip, char *err)
{
	struct wall_mark none = {0, 0};
	struct wall *c = wall_new();

	c->name = w->name ? sw_xstrdup(w->name) : NULL;
	c->path = w->path ? sw_xstrdup(w->path) : NULL;
	c->mu_bed = w->mu_bed;
	c->mu_head = w->mu_head;
	c->mu_cov = w->mu_cov;
	c->unit_weight = w->unit_weight;
	c->thickness = w->thickness;
	c->layout = regen ? *regen : w->layout;
	c->has_ground = w->has_ground;
	c->ground_y = w->ground_y;
	c->depth = w->depth;
	c->anywhere = w->anywhere;
	c->samples = w->samples;
	c->seed = w->seed;
	if (w->ntests) {
		c->tests = sw_xmalloc(sizeof(double) * (size_t)w->ntests);
		memcpy(c->tests, w->tests, sizeof(double) * (size_t)w->ntests);
		c->ntests = w->ntests;
	}
	if (regen && layout_generate(c, none, err) != SW_OK) {
		wall_free(c);
		return NULL;
	}
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *b = &w->blocks[k];
		if (k == w->ground_block || k == skip)
			continue;
		if (regen && !b->fixed && wedit_generated(b->id))
			continue;
		wall_add_block(c, b->id, b->xy, b->nv, b->fixed, none);
	}
	for (int l = 0; l < w->nloads; l++) {
		struct wall_load ld = w->loads[l];
		ld.mark = none;
		wall_add_load(c, &ld);
	}
	return c;
}

int wedit_point_load(const struct wall *w)
{
	for (int l = 0; l < w->nloads; l++)
		if (w->loads[l].kind == LOAD_POINT)
			return l;
	return -1;
}

int wedit_block_at(const struct wall *w, double x, double y)
{
	double tol = 1e-6 * w->mean_size;
	for (int k = 0; k < w->nblocks; k++)
		if (k != w->ground_block &&
		    geom_contains(w->blocks[k].xy, w->blocks[k].nv, x, y, tol))
			return k;
	return -1;
}

void wedit_block_size(const struct wall *w, double *bw, double *bh)
{
	if (w->layout.present) {
		*bw = w->layout.block_w;
		*bh = w->layout.block_h;
	} else {
		*bw = 2 * w->mean_size / sqrt(2);
		*bh = w->mean_size / sqrt(2);
	}
}

/* ---- the load stations ---- */

/* A growing list of stations, 4 numbers each: x, y, outward normal. */
struct wedit_st {
	double *v;
	int n, cap;
};

static void wedit_st_add(struct wedit_st *s, double x, double y, double nx,
			double ny)
{
	if (s->n == s->cap) {
		s->cap = s->cap ? 2 * s->cap : 64;
		s->v = sw_xrealloc(s->v, sizeof(double) * 4 * (size_t)s->cap);
	}
	double *p = s->v + 4 * s->n++;
	p[0] = x;
	p[1] = y;
	p[2] = nx;
	p[3] = ny;
}

/* The pieces of [0, L] along block k's edge from p in direction t that
 * no interface of k covers, spread with stations (iv: room for one
 * interval per interface). */
static void wedit_edge(const struct wall *w, int k, const double p[2],
		      const double t[2], double L, double (*iv)[2],
		      struct wedit_st *st)
{
	double tol = 1e-6 * w->mean_size;
	int ni = 0;
	for (int f = 0; f < w->nifaces; f++) {
		const struct wall_interface *fi = &w->ifaces[f];
		if (fi->a != k && fi->b != k)
			continue;
		double d1 = fabs((fi->p1[0] - p[0]) * t[1] - (fi->p1[1] - p[1]) * t[0]);
		double d2 = fabs((fi->p2[0] - p[0]) * t[1] - (fi->p2[1] - p[1]) * t[0]);
		if (d1 > 1e3 * tol || d2 > 1e3 * tol)
			continue;
		double s1 = (fi->p1[0] - p[0]) * t[0] + (fi->p1[1] - p[1]) * t[1];
		double s2 = (fi->p2[0] - p[0]) * t[0] + (fi->p2[1] - p[1]) * t[1];
		iv[ni][0] = fmin(s1, s2);
		iv[ni][1] = fmax(s1, s2);
		ni++;
	}
	/* walk [0, L] and take the uncovered pieces */
	double s = 0;
	while (s < L - tol) {
		double next = L;
		int moved = 0;
		for (int q = 0; q < ni; q++)
			if (iv[q][0] <= s + tol && iv[q][1] > s + tol) {
				s = iv[q][1];
				moved = 1;
			}
		if (moved)
			continue;
		for (int q = 0; q < ni; q++)
			if (iv[q][0] > s + tol && iv[q][0] < next)
				next = iv[q][0];
		double len = next - s;
		int cnt = (int)floor(len / w->mean_size + 0.5);
		if (cnt < 1)
			cnt = 1;
		for (int c = 0; c < cnt; c++) {
			double u = s + len * (c + 0.5) / cnt;
			wedit_st_add(st, p[0] + t[0] * u, p[1] + t[1] * u, t[1],
				    -t[0]);
		}
		s = next;
	}
}

/* The stations of w (see wedit.h); returns how many, *out to free. */
static int wedit_stations(const struct wall *w, double **out)
{
	double tol = 1e-6 * w->mean_size;
	struct wedit_st st = {NULL, 0, 0};
	double (*iv)[2] = sw_xmalloc(sizeof *iv * (size_t)(w->nifaces + 1));
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *b = &w->blocks[k];
		if (b->fixed)
			continue;
		for (int i = 0; i < b->nv; i++) {
			int j = (i + 1) % b->nv;
			double p[2] = {b->xy[2 * i], b->xy[2 * i + 1]};
			double L = hypot(b->xy[2 * j] - p[0],
					 b->xy[2 * j + 1] - p[1]);
			if (L <= tol)
				continue;
			double t[2] = {(b->xy[2 * j] - p[0]) / L,
				       (b->xy[2 * j + 1] - p[1]) / L};
			wedit_edge(w, k, p, t, L, iv, &st);
		}
	}
	free(iv);
	*out = st.v;
	return st.n;
}

/* The station with the least score(station, at, ctx) below INFINITY
 * goes to at; 0 if there is none. */
typedef double (*wedit_score)(const double *st, const double at[2],
			      const void *ctx);

static int wedit_station(const struct wall *w, double at[2], wedit_score score,
			 const void *ctx)
{
	double *st, best = INFINITY;
	int n = wedit_stations(w, &st), bi = -1;
	for (int i = 0; i < n; i++) {
		double d = score(st + 4 * i, at, ctx);
		if (d < best) {
			best = d;
			bi = i;
		}
	}
	if (bi >= 0) {
		at[0] = st[4 * bi];
		at[1] = st[4 * bi + 1];
	}
	free(st);
	return bi >= 0;
}

/* Along the arrow (dx, dy), with a penalty across it. */
struct wedit_arrow {
	int dx, dy;
	double tol;
};

static double wedit_step_score(const double *st, const double at[2],
			       const void *ctx)
{
	const struct wedit_arrow *a = ctx;
	double ex = st[0] - at[0], ey = st[1] - at[1];
	double along = ex * a->dx + ey * a->dy;
	double perp = fabs(ex * a->dy - ey * a->dx);
	return along <= a->tol ? INFINITY : along + 3 * perp;
}

int wedit_load_step(const struct wall *w, int dx, int dy, double at[2])
{
	struct wedit_arrow a = {dx, dy, 1e-6 * w->mean_size};
	return wedit_station(w, at, wedit_step_score, &a);
}

/* The distance, plus a block's size on faces the load does not act
 * across (normal across dir). */
struct wedit_near {
	const double *dir;
	double size;
};

static double wedit_near_score(const double *st, const double at[2],
			       const void *ctx)
{
	const struct wedit_near *c = ctx;
	return hypot(st[0] - at[0], st[1] - at[1]) +
	       c->size * (1 - fabs(st[2] * c->dir[0] + st[3] * c->dir[1]));
}

int wedit_load_nearest(const struct wall *w, const double dir[2], double at[2])
{
	struct wedit_near c = {dir, w->mean_size};
	return wedit_station(w, at, wedit_near_score, &c);
}

void wedit_bounds(const struct wall *w, int free_only, double box[4])
{
	box[0] = box[1] = INFINITY;
	box[2] = box[3] = -INFINITY;
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *b = &w->blocks[k];
		if (k == w->ground_block || (free_only && b->fixed))
			continue;
		for (int i = 0; i < b->nv; i++) {
			box[0] = fmin(box[0], b->xy[2 * i]);
			box[2] = fmax(box[2], b->xy[2 * i]);
			box[1] = fmin(box[1], b->xy[2 * i + 1]);
			box[3] = fmax(box[3], b->xy[2 * i + 1]);
		}
	}
}

/* ---- layout edits ---- */

/* After a layout change a point load may be off the wall: move each such
 * load to the nearest station of the new outline.  The outline comes
 * from a copy finished with a body load in place of the point loads. */
static void wedit_snap_loads(struct wall *nw)
{
	char err[SW_ERRLEN];
	struct wall *c = wall_copy(nw);
	struct wall_load body;
	memset(&body, 0, sizeof body);
	body.kind = LOAD_BODY;
	body.dir[0] = 1;
	body.magnitude = 1;
	c->nloads = 0;
	wall_add_load(c, &body);
	if (wall_finish(c, err) == SW_OK) {
		for (int l = 0; l < nw->nloads; l++) {
			struct wall_load *ld = &nw->loads[l];
			int k = wedit_block_at(c, ld->at[0], ld->at[1]);
			if (ld->kind == LOAD_POINT && (k < 0 || c->blocks[k].fixed))
				wedit_load_nearest(c, ld->dir, ld->at);
		}
	}
	wall_free(c);
}

struct wall *wedit_layout(const struct wall *w, const struct wall_layout *lay,
			 char *err)
{
	struct wall *nw = wedit_copy(w, lay, -1, err);
	if (nw)
		wedit_snap_loads(nw);
	return nw;
}

/* The last block of (unfinished) nw, a block of the courses put back,
 * moves to its place in the layout's order, before the blocks that are
 * not the layout's: a saved wall keeps its layout (wallfile_save). */
static void wedit_to_course(struct wall *nw)
{
	int last = nw->nblocks - 1;
	long o = wedit_order(nw->blocks[last].id);
	int at = 0;
	while (at < last) {
		long q = wedit_order(nw->blocks[at].id);
		if (q < 0 || q > o)
			break;
		at++;
	}
	struct wall_block b = nw->blocks[last];
	memmove(nw->blocks + at + 1, nw->blocks + at,
		sizeof *nw->blocks * (size_t)(last - at));
	nw->blocks[at] = b;
}

/* The block of w's layout under (x, y) that w does not have (one removed
 * from the courses), as the last block of a wall holding the layout's
 * blocks; NULL when there is none. */
static struct wall *wedit_missing(const struct wall *w, double x, double y)
{
	char err[SW_ERRLEN];
	struct wall_mark none = {0, 0};
	if (!w->layout.present || !isfinite(x) || !isfinite(y))
		return NULL;
	struct wall *g = wall_new();
	g->layout = w->layout;
	if (layout_generate(g, none, err) != SW_OK) {
		wall_free(g);
		return NULL;
	}
	double tol = 1e-6 * fmax(w->layout.block_w, w->layout.block_h);
	for (int k = 0; k < g->nblocks; k++) {
		const struct wall_block *b = &g->blocks[k];
		int have = 0;
		for (int j = 0; j < w->nblocks && !have; j++)
			have = !strcmp(w->blocks[j].id, b->id);
		if (have || !geom_contains(b->xy, b->nv, x, y, tol))
			continue;
		/* move it to the end */
		struct wall_block tmp = g->blocks[k];
		g->blocks[k] = g->blocks[g->nblocks - 1];
		g->blocks[g->nblocks - 1] = tmp;
		return g;
	}
	wall_free(g);
	return NULL;
}

/* A block of the courses that w lacks, under (x, y), put back. */
static struct wall *wedit_restore(const struct wall *w, const struct wall *lay,
				 char *what, size_t len, char *err)
{
	struct wall_mark none = {0, 0};
	const struct wall_block *b = &lay->blocks[lay->nblocks - 1];
	struct wall *nw = wedit_copy(w, NULL, -1, err);
	if (!nw)
		return NULL;
	wall_add_block(nw, b->id, b->xy, b->nv, 0, none);
	wedit_to_course(nw);
	snprintf(what, len, "block %s restored", b->id);
	return nw;
}

struct wall *wedit_add_block(const struct wall *w, double x, double y,
			    char *what, size_t len, char *err)
{
	struct wall_mark none = {0, 0};
	struct wall *lay = wedit_missing(w, x, y);
	if (lay) {
		struct wall *nw = wedit_restore(w, lay, what, len, err);
		wall_free(lay);
		return nw;
	}
	double bw, bh;
	wedit_block_size(w, &bw, &bh);
	double gx = w->layout.present ? w->layout.x0 : 0;
	double gy = w->layout.present ? w->layout.y0
				      : (w->has_ground ? w->ground_y : 0);
	double x0 = gx + floor((x - gx) / (bw / 2) + 1e-9) * (bw / 2);
	double y0 = gy + floor((y - gy) / bh + 1e-9) * bh;
	double xy[8] = {x0, y0, x0 + bw, y0, x0 + bw, y0 + bh, x0, y0 + bh};
	char id[32];
	for (int k = 1;; k++) {
		int used = 0;
		snprintf(id, sizeof id, "u%d", k);
		for (int b = 0; b < w->nblocks && !used; b++)
			used = !strcmp(w->blocks[b].id, id);
		if (!used)
			break;
	}
	struct wall *nw = wedit_copy(w, NULL, -1, err);
	if (!nw)
		return NULL;
	wall_add_block(nw, id, xy, 4, 0, none);
	snprintf(what, len, "block %s added at (%.3g, %.3g)", id, x0, y0);
	return nw;
}

/* ---- the block cursor, the load's direction ---- */

void wedit_cursor(const struct wall *w, double *x, double *y, int dx, int dy)
{
	double bw, bh, box[4];
	wedit_block_size(w, &bw, &bh);
	wedit_bounds(w, 1, box);
	*x = fmin(box[2] + bw, fmax(box[0] - bw, *x + dx * bw / 2));
	*y = fmin(box[3] + bh, fmax(box[1], *y + dy * bh));
}

void wedit_turn(double dir[2], int sense)
{
	double a = atan2(dir[1], dir[0]);
	a = (round(a / (M_PI / 4)) + sense) * (M_PI / 4);
	dir[0] = cos(a);
	dir[1] = sin(a);
	for (int i = 0; i < 2; i++)
		if (fabs(dir[i]) < 1e-12)
			dir[i] = 0;
}
