/*
 * wall.c - the wall model: building, deriving, validating, copying.
 *
 * The readers (wallfile.c, layout.c) and the tests add blocks and loads;
 * wall_finish() then derives everything the solvers read and refuses
 * models that are geometrically impossible, pointing at the offending
 * item of the file.  Tolerances are relative to the blocks involved (a
 * block's size: its largest extent), never to the whole wall, whose span
 * a far support can make as large as it likes.  Every derived number
 * (extent, area, centroid, weight, their sums, the reference load) is
 * checked finite, so that an overflow is a message naming the input and
 * not a NaN in the results.
 */
#include <float.h>
#include <stdint.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/geom.h"
#include "slipwall/wall.h"

struct wall *wall_new(void)
{
	struct wall *w = sw_xcalloc(1, sizeof *w);
	w->mu_bed = w->mu_head = 0.6;
	w->unit_weight = 19620;
	w->thickness = 0.10;
	w->depth = 0.25;
	w->samples = 1000;
	w->seed = 1;
	w->ground_block = -1;
	return w;
}

void wall_free(struct wall *w)
{
	if (!w)
		return;
	for (int i = 0; i < w->nblocks; i++) {
		free(w->blocks[i].id);
		free(w->blocks[i].xy);
	}
	free(w->blocks);
	free(w->loads);
	free(w->ifaces);
	free(w->tests);
	free(w->name);
	free(w->path);
	free(w);
}

int wall_add_block(struct wall *w, const char *id, const double *xy, int nv,
		   int fixed, struct wall_mark mark)
{
	if (w->nblocks == w->capblocks) {
		w->capblocks = w->capblocks ? 2 * w->capblocks : 16;
		w->blocks = sw_xrealloc(w->blocks,
					sizeof *w->blocks * (size_t)w->capblocks);
	}
	struct wall_block *b = &w->blocks[w->nblocks];
	memset(b, 0, sizeof *b);
	if (id) {
		b->id = sw_xstrdup(id);
	} else {
		char buf[32];
		snprintf(buf, sizeof buf, "%s%d", fixed ? "s" : "b", w->nblocks + 1);
		b->id = sw_xstrdup(buf);
	}
	b->nv = nv;
	b->xy = sw_xmalloc(sizeof(double) * 2 * (size_t)nv);
	memcpy(b->xy, xy, sizeof(double) * 2 * (size_t)nv);
	b->fixed = fixed;
	b->mark = mark;
	b->eq = -1;
	return w->nblocks++;
}

void wall_add_load(struct wall *w, const struct wall_load *ld)
{
	if (w->nloads == w->caploads) {
		w->caploads = w->caploads ? 2 * w->caploads : 4;
		w->loads = sw_xrealloc(w->loads,
				       sizeof *w->loads * (size_t)w->caploads);
	}
	w->loads[w->nloads++] = *ld;
}

void wall_where(const struct wall *w, struct wall_mark m, char *buf,
		size_t len)
{
	const char *p = w && w->path ? w->path : "<wall>";
	if (m.line > 0)
		snprintf(buf, len, "%s:%d:%d: ", p, m.line, m.col);
	else
		snprintf(buf, len, "%s: ", p);
}

#define WHERE(m) (wall_where(w, (m), where, sizeof where), where)

void wall_quantity(const struct wall *w, struct wall_quantity *q)
{
	int point = 0, body = 0, same = 1;
	double m = 1;
	for (int i = 0; i < w->nloads; i++) {
		const struct wall_load *ld = &w->loads[i];
		if (point + body == 0)
			m = ld->magnitude;
		else if (ld->magnitude != m)
			same = 0;
		if (ld->kind == LOAD_POINT)
			point++;
		else
			body++;
	}
	if (point && !body && same) {
		*q = (struct wall_quantity){m, "collapse load", "N",
			"collapse load (N)", point > 1 ?
			"N, the force of each point load (its magnitude "
			"times the load factor lambda)" :
			"N, the force of the point load (its magnitude "
			"times the load factor lambda)"};
	} else if (body && !point && same) {
		*q = (struct wall_quantity){m, "seismic coefficient", "",
			"seismic coefficient (body force / weight)",
			"seismic coefficient, no unit (the body load's force "
			"on each block over its weight: magnitude times "
			"lambda)"};
	} else {
		*q = (struct wall_quantity){1, "load factor", "",
			"load factor λ (× the reference loads)",
			"load factor lambda, no unit (it multiplies every "
			"load's magnitude)"};
	}
}

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
	const unsigned char *b = p;
	for (size_t k = 0; k < n; k++)
		h = (h ^ b[k]) * 1099511628211ULL;
	return h;
}

double wall_iface_mu(const struct wall *w, int k)
{
	return w->ifaces[k].kind == JOINT_HEAD ? w->mu_head : w->mu_bed;
}

/* Interface f's endpoint e (0: p1, 1: p2). */
static const double *iface_end(const struct wall_interface *f, int e)
{
	return e ? f->p2 : f->p1;
}

static int same_point(const double *p, const double *q)
{
	double tol = 1e-9 * fmax(1, fmax(fabs(p[0]), fabs(p[1])));
	return fabs(p[0] - q[0]) <= tol && fabs(p[1] - q[1]) <= tol;
}

/* Each block's interfaces, as lists over one array: block b's are
 * (*list)[start[b] .. start[b + 1]), in interface order.  Returns start
 * (nblocks + 1 entries); both are the caller's to free. */
static int *block_ifaces(const struct wall *w, int **list)
{
	int nb = w->nblocks, m = w->nifaces;
	int *start = sw_xcalloc((size_t)nb + 1, sizeof *start);
	*list = sw_xmalloc(sizeof **list * (size_t)(2 * m + 1));
	for (int k = 0; k < m; k++) {
		start[w->ifaces[k].a + 1]++;
		start[w->ifaces[k].b + 1]++;
	}
	for (int b = 0; b < nb; b++)
		start[b + 1] += start[b];
	int *fill = sw_xmalloc(sizeof *fill * (size_t)(nb + 1));
	memcpy(fill, start, sizeof *fill * (size_t)(nb + 1));
	for (int k = 0; k < m; k++) {
		(*list)[fill[w->ifaces[k].a]++] = k;
		(*list)[fill[w->ifaces[k].b]++] = k;
	}
	free(fill);
	return start;
}

/* The cone test at a shared point: forces F_i in the cone about n_i
 * (half-angle atan mu_i) and F_j = -F_i in the cone about n_j exist iff
 * the angle between n_i and -n_j is at most atan mu_i + atan mu_j (a
 * hair more, so that mu = 1 at a right angle, the edge, counts: there
 * the corner's pair of forces already exists). */
int wall_friction_lock(const struct wall *w, int *blk, int *ki, int *kj,
		       double pt[2])
{
	int nb = w->nblocks, *list, *start = block_ifaces(w, &list);
	int found = 0;
	for (int b = 0; b < nb && !found; b++) {
		if (w->blocks[b].fixed)
			continue;
		for (int x = start[b]; x < start[b + 1] && !found; x++)
			for (int y = x + 1; y < start[b + 1] && !found; y++) {
				const struct wall_interface
					*f = &w->ifaces[list[x]],
					*g = &w->ifaces[list[y]];
				/* the normals of the forces on b, into b */
				double sf = f->b == b ? 1 : -1, sg = g->b == b ? 1 : -1;
				double c = -(sf * f->n[0] * sg * g->n[0] +
					     sf * f->n[1] * sg * g->n[1]);
				double ang = acos(fmax(-1, fmin(1, c)));
				double cone = atan(wall_iface_mu(w, list[x])) +
					      atan(wall_iface_mu(w, list[y]));
				if (ang > cone + 1e-9)
					continue;
				for (int e = 0; e < 4 && !found; e++)
					if (same_point(iface_end(f, e / 2),
						       iface_end(g, e % 2))) {
						found = 1;
						*blk = b;
						*ki = list[x];
						*kj = list[y];
						pt[0] = iface_end(f, e / 2)[0];
						pt[1] = iface_end(f, e / 2)[1];
					}
			}
	}
	free(start);
	free(list);
	return found;
}

int wall_friction_lock_text(const struct wall *w, char *buf, size_t len)
{
	int b, i, j;
	double pt[2];
	if (!wall_friction_lock(w, &b, &i, &j, pt))
		return 0;
	snprintf(buf, len, "friction %g and %g on two joints of block %s "
		 "that meet at (%g, %g)", wall_iface_mu(w, i),
		 wall_iface_mu(w, j), w->blocks[b].id, pt[0], pt[1]);
	return 1;
}

/* 1 for each free block that hangs, in a new array.  A block rests on
 * joint k when the compressive normal force of k on it has an upward
 * component: sin 1e-9 of the vertical, so that a head joint, vertical
 * to round-off, does not count.  chain = 0: the blocks that rest on no
 * joint (wall_hanging); chain = 1: also those that rest only on hanging
 * blocks, so that no chain of joints carries them to a support from
 * below (wall_clamp_joints, wall_clamp_blocks, and wall_hanging's
 * count of them; tests/data/stack-gap.yaml: c3b2 on c2b2). */
int wall_iface_rests(const struct wall_interface *f)
{
	/* n points from a into b: the force on b is along n, on a along -n */
	return f->n[1] > 1e-9 ? f->b : f->n[1] < -1e-9 ? f->a : -1;
}

static char *hanging_marks(const struct wall *w, int chain)
{
	int nb = w->nblocks;
	char *hang = sw_xcalloc((size_t)nb + 1, 1);
	for (int b = 0; b < nb; b++)
		hang[b] = !w->blocks[b].fixed;
	for (int more = 1; more;) {
		more = 0;
		for (int k = 0; k < w->nifaces; k++) {
			const struct wall_interface *f = &w->ifaces[k];
			int up = wall_iface_rests(f);
			int down = up == f->b ? f->a : f->b;
			if (up >= 0 && hang[up] && !(chain && hang[down])) {
				hang[up] = 0;
				more = 1;
			}
		}
	}
	return hang;
}

int wall_hanging(const struct wall *w, int *blk, int *above)
{
	char *hang = hanging_marks(w, 0), *chain = hanging_marks(w, 1);
	int n = 0, na = 0;
	for (int b = 0; b < w->nblocks; b++) {
		if (hang[b] && !n++)
			*blk = b;
		na += chain[b] && !hang[b];
	}
	free(hang);
	free(chain);
	if (above)
		*above = na;
	return n;
}

int wall_clamp_blocks(const struct wall *w, char *mark)
{
	char *hang = hanging_marks(w, 1);
	int n = 0;
	for (int b = 0; b < w->nblocks; b++)
		if (hang[b]) {
			mark[b] = 1;
			n++;
		}
	free(hang);
	return n;
}

int wall_clamp_joints(const struct wall *w, int *k)
{
	char *hang = hanging_marks(w, 1);
	int n = 0;
	for (int i = 0; i < w->nifaces; i++) {
		const struct wall_interface *f = &w->ifaces[i];
		if ((hang[f->a] || hang[f->b]) && fabs(f->n[1]) <= 1e-9) {
			if (k)
				k[n] = i;
			n++;
		}
	}
	free(hang);
	return n;
}

void wall_rest_span(const struct wall *w, const double *q, double *lo,
		    double *hi)
{
	for (int b = 0; b < w->nblocks; b++) {
		lo[b] = HUGE_VAL;
		hi[b] = -HUGE_VAL;
	}
	for (int k = 0; k < w->nifaces; k++) {
		const struct wall_interface *f = &w->ifaces[k];
		int up = wall_iface_rests(f);
		if (up < 0 || up >= w->nblocks)	/* a support */
			continue;
		double x1 = q ? q[4 * k] : f->p1[0];
		double x2 = q ? q[4 * k + 2] : f->p2[0];
		lo[up] = fmin(lo[up], fmin(x1, x2));
		hi[up] = fmax(hi[up], fmax(x1, x2));
	}
}

int wall_overhang_text(const struct wall *w, char *buf, size_t len)
{
	int nb = w->nblocks, n = 0, first = -1;
	double *lo = sw_xmalloc(sizeof(double) * 2 * (size_t)nb);
	double *hi = lo + nb;
	wall_rest_span(w, NULL, lo, hi);
	for (int b = 0; b < nb; b++) {
		const struct wall_block *bl = &w->blocks[b];
		double tol = 1e-9 * bl->size;
		if (bl->fixed || !(hi[b] >= lo[b]) ||
		    (bl->cx > lo[b] + tol && bl->cx < hi[b] - tol))
			continue;
		if (!n++)
			first = b;
	}
	if (n) {
		const struct wall_block *bl = &w->blocks[first];
		char more[64] = "";
		if (n > 1)
			snprintf(more, sizeof more, ", and %d other block%s "
				 "likewise", n - 1, n > 2 ? "s" : "");
		double tol = 1e-9 * bl->size;
		int at = fabs(bl->cx - lo[first]) <= tol ||
			 fabs(bl->cx - hi[first]) <= tol;
		snprintf(buf, len, "block %s overhangs what it rests on (its "
			 "centroid, at x = %.6g m, is %s the edge of the joints "
			 "below it)%s", bl->id, bl->cx, at ? "at" : "beyond",
			 more);
	}
	free(lo);
	return n > 0;
}

int wall_hanging_text(const struct wall *w, char *buf, size_t len)
{
	int b, above, n = wall_hanging(w, &b, &above);
	if (!n)
		return 0;
	char more[64] = "";
	if (above)
		snprintf(more, sizeof more, ", and %d other block%s only on %s",
			 above, above > 1 ? "s" : "", n > 1 ? "them" : "it");
	if (n == 1)
		snprintf(buf, len, "block %s rests on no joint below it%s",
			 w->blocks[b].id, more);
	else
		snprintf(buf, len, "block %s and %d other%s rest on no joint "
			 "below them%s", w->blocks[b].id, n - 1,
			 n > 2 ? "s" : "", more);
	return 1;
}

void wall_digest(const struct wall *w, char *out)
{
	uint64_t h = 14695981039346656037ULL;
	h = fnv(h, &w->nblocks, sizeof w->nblocks);
	for (int b = 0; b < w->nblocks; b++) {
		const struct wall_block *bl = &w->blocks[b];
		h = fnv(h, &bl->nv, sizeof bl->nv);
		h = fnv(h, bl->xy, sizeof(double) * 2 * (size_t)bl->nv);
		h = fnv(h, &bl->weight, sizeof bl->weight);
		h = fnv(h, &bl->fixed, sizeof bl->fixed);
	}
	h = fnv(h, &w->nifaces, sizeof w->nifaces);
	for (int k = 0; k < w->nifaces; k++) {
		const struct wall_interface *f = &w->ifaces[k];
		int ab[2] = {f->a, f->b};
		h = fnv(h, ab, sizeof ab);
		h = fnv(h, f->p1, sizeof f->p1);
		h = fnv(h, f->p2, sizeof f->p2);
		double mu = wall_iface_mu(w, k);
		h = fnv(h, &mu, sizeof mu);
	}
	if (w->mu_cov > 0)	/* only then: digests of fixed friction stay */
		h = fnv(h, &w->mu_cov, sizeof w->mu_cov);
	h = fnv(h, &w->nloads, sizeof w->nloads);
	for (int l = 0; l < w->nloads; l++) {
		const struct wall_load *ld = &w->loads[l];
		int kind = ld->kind;
		h = fnv(h, &kind, sizeof kind);
		h = fnv(h, ld->at, sizeof ld->at);
		h = fnv(h, ld->dir, sizeof ld->dir);
		h = fnv(h, &ld->magnitude, sizeof ld->magnitude);
	}
	snprintf(out, WALL_DIGEST_LEN, "fnv1a64:%016llx", (unsigned long long)h);
}

const char wall_far_text[] = "is too far from the origin for the size of "
	"its polygon: doubles there are more than 1e-8 of the polygon's "
	"thickness apart (docs/wall-format.md, \"Coordinates far from the "
	"origin\"): move the wall nearer the origin";

const char *wall_thin_text(const double *xy, int nv, char *buf, size_t len)
{
	double t = geom_thinness(xy, nv);
	/* some coordinate of a polygon of extent E is at least E/2 from 0,
	 * wherever it lies: its spacing E 2^-53 against 1e-8 of t E */
	if (!(t > 0) || ldexp(1, -53) <= GEOM_PRECISION_REL * t)
		return NULL;
	snprintf(buf, len, "is too thin: %g of its length thick, where "
		 "doubles need %.2g wherever it is (docs/wall-format.md, "
		 "\"Coordinates far from the origin\")", t,
		 ldexp(1, -53) / GEOM_PRECISION_REL);
	return buf;
}

/* Why geom_check_polygon found the polygon degenerate, in words a
 * person can act on (wall_finish): a repeated vertex (the first repeated
 * at the end, as CAD exports write a closed outline), fewer than three
 * vertices, all on one line, or no area for vertices out of order (a
 * rectangle with two corners swapped crosses itself). */
static const char *degenerate_text(const double *xy, int nv, double tol,
				   char *buf, size_t len)
{
	if (nv < 3) {
		snprintf(buf, len, "has %d vertices: a polygon needs 3 or "
			 "more", nv);
		return buf;
	}
	for (int i = 0; i < nv; i++) {
		int j = (i + 1) % nv;
		if (hypot(xy[2 * j] - xy[2 * i], xy[2 * j + 1] - xy[2 * i + 1]) >
		    tol)
			continue;
		if (j == 0)
			snprintf(buf, len, "closed by repeating its first "
				 "vertex at the end (vertex %d): leave the "
				 "repeat out, the polygon closes by itself", nv);
		else
			snprintf(buf, len, "degenerate: vertices %d and %d "
				 "are the same point", i + 1, j + 1);
		return buf;
	}
	/* the largest distance of a vertex from the line of the first edge */
	double ex = xy[2] - xy[0], ey = xy[3] - xy[1], off = 0;
	for (int i = 2; i < nv; i++)
		off = fmax(off, fabs(ex * (xy[2 * i + 1] - xy[1]) -
				     ey * (xy[2 * i] - xy[0])) / hypot(ex, ey));
	snprintf(buf, len, off <= tol ? "degenerate: its vertices lie on one "
		 "line (no area)" : "self-intersecting: its area is zero "
		 "(vertices out of order? they must run around the polygon, "
		 "counter-clockwise)");
	return buf;
}

int wall_id_reserved(const char *id)
{
	return !strcmp(id, "ground");
}

/* The mark of a material value, or the block's when it was not given. */
static struct wall_mark mark_or(struct wall_mark m, struct wall_mark other)
{
	return m.line > 0 ? m : other;
}

/* The block that a point load at p in direction d acts on: the one that
 * contains p; on a shared boundary, the one the force pushes into, else
 * the one it pulls out of. */
static int load_block(const struct wall *w, const double *p, const double *d,
		      double rel)
{
	int first = -1;
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *b = &w->blocks[k];
		double tol = rel * b->size;
		if (!geom_contains(b->xy, b->nv, p[0], p[1], tol))
			continue;
		if (first < 0)
			first = k;
		double eps = 1e3 * tol;
		if (geom_contains(b->xy, b->nv, p[0] + eps * d[0],
				  p[1] + eps * d[1], -tol))
			return k;
	}
	if (first < 0)
		return -1;
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *b = &w->blocks[k];
		double tol = rel * b->size, eps = 1e3 * tol;
		if (geom_contains(b->xy, b->nv, p[0], p[1], tol) &&
		    geom_contains(b->xy, b->nv, p[0] - eps * d[0],
				  p[1] - eps * d[1], -tol))
			return k;
	}
	return first;
}

/* Every free block must reach a support through interfaces. */
static int first_unsupported(const struct wall *w)
{
	int n = w->nblocks, *adj, *adj_start = block_ifaces(w, &adj);
	/* block i's neighbour across interface adj[p] */
	for (int i = 0; i < n; i++)
		for (int p = adj_start[i]; p < adj_start[i + 1]; p++) {
			const struct wall_interface *f = &w->ifaces[adj[p]];
			adj[p] = f->a == i ? f->b : f->a;
		}
	char *seen = sw_xcalloc((size_t)n + 1, 1);
	int *queue = sw_xmalloc(sizeof(int) * (size_t)(n + 1));
	int head = 0, tail = 0;
	for (int i = 0; i < n; i++)
		if (w->blocks[i].fixed) {
			seen[i] = 1;
			queue[tail++] = i;
		}
	while (head < tail) {
		int i = queue[head++];
		for (int p = adj_start[i]; p < adj_start[i + 1]; p++)
			if (!seen[adj[p]]) {
				seen[adj[p]] = 1;
				queue[tail++] = adj[p];
			}
	}
	int bad = -1;
	for (int i = 0; i < n && bad < 0; i++)
		if (!seen[i])
			bad = i;
	free(adj_start);
	free(adj);
	free(queue);
	free(seen);
	return bad;
}

static const struct wall *id_wall;	/* qsort has no context argument */

static int id_cmp(const void *pa, const void *pb)
{
	int a = *(const int *)pa, b = *(const int *)pb;
	int c = strcmp(id_wall->blocks[a].id, id_wall->blocks[b].id);
	return c ? c : (a > b) - (a < b);
}

/* The later of two blocks that share an id, or -1.  Sorting, so that a
 * 10,000-block wall is not a hundred million comparisons.  (Not
 * thread-safe: walls are finished on one thread.) */
static int duplicate_id(const struct wall *w)
{
	int *ix = sw_xmalloc(sizeof(int) * (size_t)(w->nblocks + 1)), dup = -1;
	for (int k = 0; k < w->nblocks; k++)
		ix[k] = k;
	id_wall = w;
	qsort(ix, (size_t)w->nblocks, sizeof *ix, id_cmp);
	for (int k = 1; k < w->nblocks && dup < 0; k++)
		if (!strcmp(w->blocks[ix[k - 1]].id, w->blocks[ix[k]].id))
			dup = ix[k];
	free(ix);
	return dup;
}

/* What wall_finish finds in its first pass: the wall's extent (for the
 * ground) and the most vertices of a block. */
struct extent {
	double x0, y0, x1, y1, span;
	int maxnv;
};

/* wall_finish: every vertex finite, the extents, the friction. */
static enum sw_status finish_extent(struct wall *w, struct extent *e,
				    char *err)
{
	char where[SW_ERRLEN / 2];
	struct wall_mark none = {0, 0};
	/* the extent of the wall (for the ground) and of each block (for
	 * its tolerances) */
	double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
	int nfree = 0, maxnv = 0;
	for (int k = 0; k < w->nblocks; k++) {
		struct wall_block *b = &w->blocks[k];
		double bx0 = INFINITY, by0 = INFINITY, bx1 = -INFINITY,
		       by1 = -INFINITY;
		for (int i = 0; i < b->nv; i++) {
			if (!isfinite(b->xy[2 * i]) || !isfinite(b->xy[2 * i + 1]))
				return sw_fail(err, SW_EINPUT,
					       "%sblock '%s' has a vertex that is not a finite number",
					       WHERE(b->mark), b->id);
			bx0 = fmin(bx0, b->xy[2 * i]);
			by0 = fmin(by0, b->xy[2 * i + 1]);
			bx1 = fmax(bx1, b->xy[2 * i]);
			by1 = fmax(by1, b->xy[2 * i + 1]);
		}
		b->size = fmax(bx1 - bx0, by1 - by0);
		if (!isfinite(b->size))
			return sw_fail(err, SW_EINPUT,
				       "%s%s '%s' is too large: its coordinates "
				       "span more than a double can hold",
				       WHERE(b->mark),
				       b->fixed ? "support" : "block", b->id);
		if (wall_id_reserved(b->id))
			return sw_fail(err, SW_EINPUT,
				       "%s'%s' is a reserved name (the program's "
				       "own foundation support): give this %s "
				       "another id", WHERE(b->mark), b->id,
				       b->fixed ? "support" : "block");
		x0 = fmin(x0, bx0);
		y0 = fmin(y0, by0);
		x1 = fmax(x1, bx1);
		y1 = fmax(y1, by1);
		nfree += !b->fixed;
		if (b->nv > maxnv)
			maxnv = b->nv;
	}
	if (nfree == 0)
		return sw_fail(err, SW_EINPUT, "%sthe wall has no blocks",
			       WHERE(none));
	double span = fmax(x1 - x0, y1 - y0);
	*e = (struct extent){x0, y0, x1, y1, span, maxnv};
	if (!isfinite(span) || !isfinite(1.2 * span + fmax(fabs(x0), fabs(x1))))
		return sw_fail(err, SW_EINPUT,
			       "%sthe wall is too large: its coordinates span "
			       "more than a double can hold", WHERE(none));
	for (int f = 0; f < 2; f++) {
		double mu = f ? w->mu_head : w->mu_bed;
		if (mu > WALL_FRICTION_MAX)
			return sw_fail(err, SW_EINPUT,
				       "%sfriction %.*g is above %g: larger "
				       "coefficients change nothing physically "
				       "and are beyond the accuracy of the LPs; "
				       "to forbid sliding use friction: %g",
				       WHERE(w->friction_mark[f]),
				       /* 1000.0000000000001 is not "1000" */
				       mu < 2 * WALL_FRICTION_MAX ? 17 : 6, mu,
				       WALL_FRICTION_MAX, WALL_FRICTION_MAX);
	}
	return SW_OK;
}

/* Each polygon: convex, counter-clockwise; ids unique.  Area and
 * centroid of its corners alone (geom_prune), so that a vertex in the
 * middle of an edge does not change them by a rounding. */
static enum sw_status finish_polygons(struct wall *w, const struct extent *e,
				      char *err)
{
	char where[SW_ERRLEN / 2];
	double *corners = sw_xmalloc(sizeof(double) * 2 * (size_t)(e->maxnv + 1));
	for (int k = 0; k < w->nblocks; k++) {
		struct wall_block *b = &w->blocks[k];
		double tol = GEOM_PRUNE_REL * b->size;
		if (!isfinite(geom_area(b->xy, b->nv))) {
			free(corners);
			return sw_fail(err, SW_EINPUT,
				       "%s%s '%s' is too large: its area "
				       "overflows a double", WHERE(b->mark),
				       b->fixed ? "support" : "block", b->id);
		}
		int far = geom_far_vertex(b->xy, b->nv);
		char thin[200];
		if (far >= 0 && wall_thin_text(b->xy, b->nv, thin, sizeof thin)) {
			free(corners);
			return sw_fail(err, SW_EINPUT, "%s%s '%s' %s",
				       WHERE(b->mark), b->fixed ? "support" :
				       "block", b->id, thin);
		}
		if (far >= 0) {
			free(corners);
			return sw_fail(err, SW_EINPUT, "%s%s '%s': vertex %d "
				       "%s", WHERE(b->mark), b->fixed ?
				       "support" : "block", b->id, far + 1,
				       wall_far_text);
		}
		enum geom_shape s = geom_check_polygon(b->xy, b->nv, tol);
		if (s != GEOM_OK) {
			char why[200];
			free(corners);
			return sw_fail(err, SW_EINPUT, "%s%s '%s' is %s",
				       WHERE(b->mark),
				       b->fixed ? "support" : "block", b->id,
				       s == GEOM_DEGENERATE ?
				       degenerate_text(b->xy, b->nv, tol, why,
						       sizeof why) :
				       geom_shape_text(s));
		}
		int nc = geom_prune(b->xy, b->nv, tol, corners);
		b->area = geom_area(corners, nc);
		geom_centroid(corners, nc, &b->cx, &b->cy);
		if (!isfinite(b->area) || !isfinite(b->cx) || !isfinite(b->cy) ||
		    !isnormal(b->area)) {
			free(corners);
			return sw_fail(err, SW_EINPUT,
				       "%s%s '%s' is too %s: its area (%g m^2) "
				       "is beyond the normal doubles (%g to "
				       "%g): use other units", WHERE(b->mark),
				       b->fixed ? "support" : "block", b->id,
				       isnormal(b->area) ? "large" : "small",
				       b->area, DBL_MIN, DBL_MAX);
		}
	}
	free(corners);
	int dup = duplicate_id(w);
	if (dup >= 0)
		return sw_fail(err, SW_EINPUT, "%sblock id '%s' is used twice",
			       WHERE(w->blocks[dup].mark), w->blocks[dup].id);
	return SW_OK;
}

/* The ground: a fixed slab under the whole wall. */
static enum sw_status finish_ground(struct wall *w, const struct extent *e,
				    char *err)
{
	char where[SW_ERRLEN / 2];
	if (!w->has_ground)
		return SW_OK;
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *b = &w->blocks[k];
		double tol = GEOM_PRUNE_REL * b->size;
		for (int i = 0; i < b->nv && !b->fixed; i++)
			if (b->xy[2 * i + 1] < w->ground_y - tol)
				return sw_fail(err, SW_EINPUT,
					       "%sblock '%s' reaches below the ground (y = %g)",
					       WHERE(b->mark), b->id,
					       w->ground_y);
	}
	double pad = 0.1 * e->span, depth = 0.1 * e->span;
	if (!isfinite(w->ground_y - depth))
		return sw_fail(err, SW_EINPUT,
			       "%sthe ground at y = %g is too far down: "
			       "its slab overflows a double",
			       WHERE(w->ground_mark), w->ground_y);
	double g[8] = {e->x0 - pad, w->ground_y - depth,
		       e->x1 + pad, w->ground_y - depth,
		       e->x1 + pad, w->ground_y,
		       e->x0 - pad, w->ground_y};
	w->ground_block = wall_add_block(w, "ground", g, 4, 1,
					 w->ground_mark);
	struct wall_block *gb = &w->blocks[w->ground_block];
	gb->size = fmax(e->x1 - e->x0 + 2 * pad, depth);
	gb->area = geom_area(g, 4);
	geom_centroid(g, 4, &gb->cx, &gb->cy);
	return SW_OK;
}

/* No two blocks overlap. */
static enum sw_status finish_overlap(struct wall *w, char *err)
{
	char where[SW_ERRLEN / 2];
	int oi, oj;
	if (geom_find_overlap(w, 1e-6, &oi, &oj)) {
		const struct wall_block *b = &w->blocks[oj];
		if (w->blocks[oj].fixed && !w->blocks[oi].fixed)
			b = &w->blocks[oi];
		return sw_fail(err, SW_EINPUT, "%sblock '%s' overlaps '%s'",
			       WHERE(b->mark), b->id,
			       w->blocks[b == &w->blocks[oi] ? oj : oi].id);
	}
	return SW_OK;
}

/* Weights and equation numbers. */
static enum sw_status finish_weights(struct wall *w, char *err)
{
	char where[SW_ERRLEN / 2];
	struct wall_mark none = {0, 0};
	w->nfree = 0;
	w->total_weight = 0;
	double area_sum = 0;
	for (int k = 0; k < w->nblocks; k++) {
		struct wall_block *b = &w->blocks[k];
		if (b->fixed) {
			b->weight = 0;
			b->eq = -1;
			continue;
		}
		b->weight = w->unit_weight * b->area * w->thickness;
		b->eq = w->nfree++;
		w->total_weight += b->weight;
		area_sum += b->area;
		if (isfinite(b->weight) && !isnormal(b->weight))
			return sw_fail(err, SW_EINPUT,
				       "%sthe weight of block '%s' (%g N) is "
				       "below the normal doubles (%g): use "
				       "larger units or values",
				       WHERE(mark_or(w->unit_weight_mark,
						     b->mark)),
				       b->id, b->weight, DBL_MIN);
		if (!isfinite(b->weight) || !isfinite(w->total_weight) ||
		    !isfinite(area_sum))
			return sw_fail(err, SW_EINPUT,
				       "%sthe weight of %s overflows a double "
				       "(unit_weight %g N/m^3 x area %g m^2 x "
				       "thickness %g m): use smaller units or "
				       "values", WHERE(mark_or(w->unit_weight_mark,
							      b->mark)),
				       isfinite(b->weight) ? "the blocks"
							   : "a block",
				       w->unit_weight, b->area, w->thickness);
	}
	w->mean_weight = w->total_weight / w->nfree;
	w->mean_size = sqrt(area_sum / w->nfree);
	if (!(w->mean_weight > 0))
		return sw_fail(err, SW_EINPUT,
			       "%sthe blocks weigh nothing (unit weight %g N/m^3, thickness %g m)",
			       WHERE(none), w->unit_weight, w->thickness);
	return SW_OK;
}

/* The interfaces (tolerance relative to the blocks involved); every
 * block rests on a support. */
static enum sw_status finish_supports(struct wall *w, char *err)
{
	char where[SW_ERRLEN / 2];
	struct wall_mark none = {0, 0};
	free(w->ifaces);
	w->nifaces = geom_contacts(w, 1e-6, &w->ifaces);
	int nsupports = 0;
	for (int k = 0; k < w->nblocks; k++)
		nsupports += w->blocks[k].fixed;
	if (nsupports == 0)
		return sw_fail(err, SW_EINPUT,
			       "%sthe wall has no support (add `supports: [{ground: {y: 0}}]`)",
			       WHERE(none));
	int bad = first_unsupported(w);
	if (bad >= 0) {
		const struct wall_block *b = &w->blocks[bad];
		int touches = 0;
		for (int k = 0; k < w->nifaces && !touches; k++)
			touches = w->ifaces[k].a == bad || w->ifaces[k].b == bad;
		return sw_fail(err, SW_EINPUT, "%sblock '%s' %s",
			       WHERE(b->mark), b->id,
			       touches ? "does not rest on any support (through the blocks it touches)"
				       : "touches nothing");
	}
	return SW_OK;
}

/* Live loads that cancel on every block: zero force and zero moment on
 * each, to round-off of the loads on it.  The load factor then appears
 * in no equation, and every LP that maximises it is unbounded, which
 * the solvers read as a load path into a support ("the live load
 * pushes against a support ...", not what happens).  Two point loads
 * at one point in opposite directions are the plain case; loads that
 * cancel over the wall but not on each block are a load like any other
 * (docs/wall-format.md). */
int wall_load_on(const struct wall *w, const struct wall_load *ld, int k,
		 double *f, double *px, double *py)
{
	const struct wall_block *b = &w->blocks[k];
	if (b->fixed || (ld->kind == LOAD_POINT && ld->block != k))
		return 0;
	if (ld->kind == LOAD_POINT) {
		*f = ld->magnitude;
		*px = ld->at[0];
		*py = ld->at[1];
	} else {
		*f = ld->magnitude * b->weight;
		*px = b->cx;
		*py = b->cy;
	}
	return 1;
}

static enum sw_status loads_cancel(const struct wall *w, char *err)
{
	char where[SW_ERRLEN / 2];
	if (w->nloads < 2)
		return SW_OK;
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *b = &w->blocks[k];
		double fx = 0, fy = 0, m = 0, fa = 0, ma = 0;
		if (b->fixed)
			continue;
		for (int l = 0; l < w->nloads; l++) {
			const struct wall_load *ld = &w->loads[l];
			double f, px, py;
			if (!wall_load_on(w, ld, k, &f, &px, &py))
				continue;
			double gx = f * ld->dir[0], gy = f * ld->dir[1];
			double mk = (px - b->cx) * gy - (py - b->cy) * gx;
			fx += gx;
			fy += gy;
			m += mk;
			fa += f;
			ma += fabs(mk) + f * (fabs(px - b->cx) + fabs(py - b->cy));
		}
		if (fabs(fx) > 1e-12 * fa || fabs(fy) > 1e-12 * fa ||
		    fabs(m) > 1e-12 * ma)
			return SW_OK;	/* a block the live load moves */
	}
	const struct wall_load *last = &w->loads[w->nloads - 1];
	return sw_fail(err, SW_EINPUT,
		       "%sthe live loads cancel: on every block their forces "
		       "and moments sum to zero, so no load factor moves the "
		       "wall (remove a load or change its direction)",
		       WHERE(last->mark));
}

/* The loads: directions, magnitudes, the blocks they act on, and the
 * reference live load against the weights. */
static enum sw_status finish_loads(struct wall *w, char *err)
{
	char where[SW_ERRLEN / 2];
	enum sw_status st;
	struct wall_mark none = {0, 0};
	if (w->nloads == 0)
		return sw_fail(err, SW_EINPUT,
			       "%sthe wall has no live load (add a `loads` entry)",
			       WHERE(none));
	for (int l = 0; l < w->nloads; l++) {
		struct wall_load *ld = &w->loads[l];
		double dn = hypot(ld->dir[0], ld->dir[1]);
		if (!(dn > 0) || !isfinite(dn))
			return sw_fail(err, SW_EINPUT,
				       "%sload direction must be a non-zero vector",
				       WHERE(ld->mark));
		/* a saved (already unit) direction must load back bit for bit */
		if (fabs(dn - 1) > 4 * DBL_EPSILON) {
			ld->dir[0] /= dn;
			ld->dir[1] /= dn;
		}
		if (!(ld->magnitude > 0) || !isfinite(ld->magnitude))
			return sw_fail(err, SW_EINPUT,
				       "%sload magnitude must be > 0",
				       WHERE(ld->mark));
		if (ld->kind != LOAD_POINT) {
			ld->block = -1;
			continue;
		}
		ld->block = load_block(w, ld->at, ld->dir, GEOM_PRUNE_REL);
		if (ld->block < 0)
			return sw_fail(err, SW_EINPUT,
				       "%sload point (%g, %g) is outside every block",
				       WHERE(ld->mark), ld->at[0], ld->at[1]);
		if (w->blocks[ld->block].fixed)
			return sw_fail(err, SW_EINPUT,
				       "%sload point (%g, %g) is on support '%s', which cannot move",
				       WHERE(ld->mark), ld->at[0], ld->at[1],
				       w->blocks[ld->block].id);
	}
	if ((st = loads_cancel(w, err)) != SW_OK)
		return st;
	/* the reference live load, summed (the body loads scale the total
	 * weight): finite, or every load factor is a NaN */
	double live = 0;
	for (int l = 0; l < w->nloads; l++) {
		const struct wall_load *ld = &w->loads[l];
		live += ld->kind == LOAD_POINT ? ld->magnitude
					       : ld->magnitude * w->total_weight;
		if (!isfinite(live))
			return sw_fail(err, SW_EINPUT,
				       "%sthe live load overflows a double "
				       "(magnitude %g%s): use a smaller "
				       "magnitude", WHERE(ld->mark),
				       ld->magnitude,
				       ld->kind == LOAD_POINT ? ""
					       : " x the weight of the wall");
	}
	/* the LPs scale the live load to the weights: their ratio must be
	 * a normal double both ways */
	if (!isnormal(live / w->mean_weight) ||
	    !isnormal(w->mean_weight / live))
		return sw_fail(err, SW_EINPUT,
			       "%sthe live load (%g N at load factor 1) and "
			       "the weights (%g N a block) are too far apart "
			       "for a double: use a magnitude nearer the "
			       "weights", WHERE(w->loads[0].mark), live,
			       w->mean_weight);
	return SW_OK;
}

enum sw_status wall_finish(struct wall *w, char *err)
{
	if (w->finished)
		return SW_OK;
	struct extent e = {0};
	enum sw_status st;
	if ((st = finish_extent(w, &e, err)) != SW_OK ||
	    (st = finish_polygons(w, &e, err)) != SW_OK ||
	    (st = finish_ground(w, &e, err)) != SW_OK ||
	    (st = finish_overlap(w, err)) != SW_OK ||
	    (st = finish_weights(w, err)) != SW_OK ||
	    (st = finish_supports(w, err)) != SW_OK ||
	    (st = finish_loads(w, err)) != SW_OK)
		return st;
	w->finished = 1;
	return SW_OK;
}

struct wall *wall_copy(const struct wall *w)
{
	struct wall *c = sw_xmalloc(sizeof *c);
	*c = *w;
	c->name = w->name ? sw_xstrdup(w->name) : NULL;
	c->path = w->path ? sw_xstrdup(w->path) : NULL;
	c->capblocks = w->nblocks;
	c->blocks = sw_xmalloc(sizeof *c->blocks * (size_t)(w->nblocks + 1));
	for (int k = 0; k < w->nblocks; k++) {
		c->blocks[k] = w->blocks[k];
		c->blocks[k].id = sw_xstrdup(w->blocks[k].id);
		c->blocks[k].xy = sw_xmalloc(sizeof(double) * 2 * (size_t)w->blocks[k].nv);
		memcpy(c->blocks[k].xy, w->blocks[k].xy,
		       sizeof(double) * 2 * (size_t)w->blocks[k].nv);
	}
	c->caploads = w->nloads;
	c->loads = sw_xmalloc(sizeof *c->loads * (size_t)(w->nloads + 1));
	if (w->nloads)
		memcpy(c->loads, w->loads, sizeof *c->loads * (size_t)w->nloads);
	c->tests = sw_xmalloc(sizeof(double) * (size_t)(w->ntests + 1));
	if (w->ntests)
		memcpy(c->tests, w->tests, sizeof(double) * (size_t)w->ntests);
	c->ifaces = sw_xmalloc(sizeof *c->ifaces * (size_t)(w->nifaces + 1));
	if (w->nifaces)
		memcpy(c->ifaces, w->ifaces, sizeof *c->ifaces * (size_t)w->nifaces);
	return c;
}
