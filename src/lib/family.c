/*
 * family.c - mechanism families; see family.h and docs/statistics.md
 * ("Mechanism families").
 *
 * The moving set is found by union-find over the bodies: every closed
 * joint joins its two bodies, and every support is joined to the first
 * support, so a free block is at rest exactly when it ends in the
 * supports' component.  This is O(nifaces + nblocks) per mechanism, and
 * a family_set classifies each distinct mechanism of a tally once
 * (family_update only looks at the mechanisms added since its last
 * call).  Families are found again by their key (family.h: the moving
 * set up to FAMILY_SMALL blocks, its outline above): a linear search
 * over the families that compares a hash of the key before the key
 * itself; there are far fewer families than mechanisms (measured in
 * docs/statistics.md).
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/family.h"
#include "slipwall/sample.h"

static int uf_find(int *par, int x)
{
	while (par[x] != x) {
		par[x] = par[par[x]];
		x = par[x];
	}
	return x;
}

static void uf_join(int *par, int a, int b)
{
	a = uf_find(par, a);
	b = uf_find(par, b);
	if (a != b)
		par[a < b ? b : a] = a < b ? a : b;
}

int family_moving(const struct wall *w, const char *joint,
		  unsigned char *moving, int *nbodies)
{
	int nb = w->nblocks;
	int *par = sw_xmalloc(sizeof(int) * ((size_t)nb + 1));
	for (int b = 0; b < nb; b++)
		par[b] = b;
	int sup = -1;
	for (int b = 0; b < nb; b++) {
		if (!w->blocks[b].fixed)
			continue;
		if (sup < 0)
			sup = b;
		else
			uf_join(par, sup, b);
	}
	for (int k = 0; k < w->nifaces; k++)
		if (joint[k] == JOINT_CLOSED)
			uf_join(par, w->ifaces[k].a, w->ifaces[k].b);
	int rest = sup >= 0 ? uf_find(par, sup) : -1;
	int n = 0, bodies = 0;
	for (int b = 0; b < nb; b++) {
		int r = uf_find(par, b);
		moving[b] = !w->blocks[b].fixed && r != rest;
		if (moving[b]) {
			n++;
			/* a component's root is its smallest block (uf_join),
			 * and a moving one has no support: count roots */
			if (r == b)
				bodies++;
		}
	}
	free(par);
	if (nbodies)
		*nbodies = bodies;
	return n;
}

static double block_min(const struct wall_block *b, int c)
{
	double m = b->xy[c];
	for (int i = 1; i < b->nv; i++)
		if (b->xy[2 * i + c] < m)
			m = b->xy[2 * i + c];
	return m;
}

static int by_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* Courses: the distinct heights of the free blocks' lowest points, equal
 * within a thousandth of the mean block size. */
static void find_rows(struct family_set *fs)
{
	const struct wall *w = fs->w;
	int nb = w->nblocks, n = 0;
	double *y = sw_xmalloc(sizeof(double) * ((size_t)nb + 1));
	for (int b = 0; b < nb; b++)
		if (!w->blocks[b].fixed)
			y[n++] = block_min(&w->blocks[b], 1);
	qsort(y, (size_t)n, sizeof *y, by_double);
	double tol = 1e-3 * (w->mean_size > 0 ? w->mean_size : 1);
	int m = 0;
	for (int i = 0; i < n; i++)
		if (m == 0 || y[i] - y[m - 1] > tol)
			y[m++] = y[i];
	fs->nrows = m;
	for (int b = 0; b < nb; b++) {
		fs->row[b] = 0;
		if (w->blocks[b].fixed)
			continue;
		double yb = block_min(&w->blocks[b], 1);
		for (int r = 0; r < m; r++)
			if (yb - y[r] <= tol) {
				fs->row[b] = r + 1;
				break;
			}
	}
	free(y);
}

void family_set_init(struct family_set *fs, const struct wall *w)
{
	memset(fs, 0, sizeof *fs);
	fs->w = w;
	fs->row = sw_xmalloc(sizeof(int) * ((size_t)w->nblocks + 1));
	find_rows(fs);
}

void family_set_free(struct family_set *fs)
{
	for (int f = 0; f < fs->nfam; f++)
		free(fs->fam[f].moving);
	free(fs->fam);
	free(fs->of);
	free(fs->row);
	memset(fs, 0, sizeof *fs);
}

static unsigned long long fnv1a(const unsigned char *s, size_t n)
{
	unsigned long long h = 1469598103934665603ull;
	for (size_t i = 0; i < n; i++) {
		h ^= s[i];
		h *= 1099511628211ull;
	}
	return h;
}

/* The outline of a moving set of more than FAMILY_SMALL blocks
 * (family.h): what its name says, but for the count. */

static void row_span(const struct family_set *fs, const unsigned char *mv,
		     int r, int *lo, int *hi, int *left, int *right);

static void outline_of(const struct family_set *fs, const unsigned char *mv,
		       struct family_outline *o)
{
	const struct wall *w = fs->w;
	memset(o, 0, sizeof *o);
	for (int b = 0; b < w->nblocks; b++) {
		if (!mv[b])
			continue;
		if (o->rlo == 0 || fs->row[b] < o->rlo)
			o->rlo = fs->row[b];
		if (fs->row[b] > o->rhi)
			o->rhi = fs->row[b];
	}
	o->left = o->right = 1;
	for (int r = o->rlo; r <= o->rhi; r++) {
		int lo, hi, l, rt;
		row_span(fs, mv, r, &lo, &hi, &l, &rt);
		if (lo < 0)
			continue;	/* a course the set skips */
		o->left = o->left && l;
		o->right = o->right && rt;
	}
	int l, rt;
	row_span(fs, mv, o->rlo, &o->lo[0], &o->hi[0], &l, &rt);
	row_span(fs, mv, o->rhi, &o->lo[1], &o->hi[1], &l, &rt);
}

/* The family of moving set mv (n blocks), adding it (first mechanism k)
 * if new: of the same set, for at most FAMILY_SMALL blocks; of the same
 * outline, for more (family.h).  A member's set narrows the family's
 * core (the blocks that move in every member) and widens its range of
 * counts. */
static int find_or_add(struct family_set *fs, unsigned char *mv, int n,
		       int k)
{
	size_t nb = (size_t)fs->w->nblocks;
	struct family_outline o;
	unsigned long long key;
	if (n > FAMILY_SMALL) {
		outline_of(fs, mv, &o);
		key = fnv1a((const unsigned char *)&o, sizeof o);
	} else {
		key = fnv1a(mv, nb);
	}
	for (int f = 0; f < fs->nfam; f++) {
		struct family *fa = &fs->fam[f];
		if (fa->key != key || (fa->nmax > FAMILY_SMALL) !=
		    (n > FAMILY_SMALL))
			continue;
		if (n > FAMILY_SMALL) {
			if (memcmp(&o, &fa->outline, sizeof o))
				continue;
		} else if (memcmp(fa->moving, mv, nb)) {
			continue;
		}
		fa->nmoving = 0;
		for (size_t b = 0; b < nb; b++)
			fa->nmoving += fa->moving[b] = fa->moving[b] && mv[b];
		fa->nmin = n < fa->nmin ? n : fa->nmin;
		fa->nmax = n > fa->nmax ? n : fa->nmax;
		return f;
	}
	if (fs->nfam == fs->capfam) {
		fs->capfam = fs->capfam ? 2 * fs->capfam : 8;
		fs->fam = sw_xrealloc(fs->fam, sizeof *fs->fam *
				      (size_t)fs->capfam);
	}
	struct family *f = &fs->fam[fs->nfam];
	memset(f, 0, sizeof *f);
	f->moving = sw_xmalloc(nb + 1);
	memcpy(f->moving, mv, nb);
	f->nmoving = f->nmin = f->nmax = n;
	if (n > FAMILY_SMALL)
		f->outline = o;
	f->key = key;
	f->first = k;
	return fs->nfam++;
}

void family_update(struct family_set *fs, const struct tally *t)
{
	if (t->nmech > fs->capseen) {
		fs->capseen = t->nmech + 64;
		fs->of = sw_xrealloc(fs->of, sizeof(int) * (size_t)fs->capseen);
	}
	if (fs->nseen < t->nmech) {
		unsigned char *mv = sw_xmalloc((size_t)fs->w->nblocks + 1);
		for (int k = fs->nseen; k < t->nmech; k++) {
			int n = family_moving(fs->w, t->mech[k].joint, mv, NULL);
			fs->of[k] = find_or_add(fs, mv, n, k);
		}
		free(mv);
		fs->nseen = t->nmech;
	}
	for (int f = 0; f < fs->nfam; f++) {
		fs->fam[f].count = 0;
		fs->fam[f].nmech = 0;
	}
	for (int k = 0; k < fs->nseen; k++) {
		const struct tally_mech *m = &t->mech[k];
		struct family *f = &fs->fam[fs->of[k]];
		if (f->nmech == 0 || m->lam_lo < f->lam_lo)
			f->lam_lo = m->lam_lo;
		if (f->nmech == 0 || m->lam_hi > f->lam_hi)
			f->lam_hi = m->lam_hi;
		f->count += m->count;
		f->nmech++;
	}
}

int family_top(const struct family_set *fs, int *idx, int max)
{
	if (max <= 0 || fs->nfam == 0)
		return 0;
	struct tally_rank *r = sw_xmalloc(sizeof *r * (size_t)fs->nfam);
	for (int f = 0; f < fs->nfam; f++) {
		r[f].count = fs->fam[f].count;
		r[f].k = f;	/* families are numbered by first appearance */
	}
	int n = tally_ranked(r, fs->nfam, idx, max);
	free(r);
	return n;
}

int family_mechs(const struct family_set *fs, const struct tally *t, int f,
		 int *idx, int max)
{
	if (max <= 0 || fs->nseen == 0)
		return 0;
	struct tally_rank *r = sw_xmalloc(sizeof *r * (size_t)fs->nseen);
	int n = 0;
	for (int k = 0; k < fs->nseen; k++)
		if (fs->of[k] == f) {
			r[n].count = t->mech[k].count;
			r[n++].k = k;
		}
	n = tally_ranked(r, n, idx, max);
	free(r);
	return n;
}

/* Append a formatted string to buf (len bytes, *used of them used);
 * silently cut at the end. */
static void put(char *buf, size_t len, size_t *used, const char *fmt, ...)
{
	if (*used + 1 >= len)
		return;
	va_list ap;
	va_start(ap, fmt);
	int n = vsnprintf(buf + *used, len - *used, fmt, ap);
	va_end(ap);
	if (n < 0)
		return;
	*used += (size_t)n < len - *used ? (size_t)n : len - *used - 1;
}

/* The leftmost and rightmost moving blocks of course r, and whether the
 * free blocks at the course's two ends move. */
static void row_span(const struct family_set *fs, const unsigned char *mv,
		     int r, int *lo, int *hi, int *left, int *right)
{
	const struct wall *w = fs->w;
	int flo = -1, fhi = -1;
	double xflo = 0, xfhi = 0, xlo = 0, xhi = 0;
	*lo = *hi = -1;
	for (int b = 0; b < w->nblocks; b++) {
		if (fs->row[b] != r)
			continue;
		double x = block_min(&w->blocks[b], 0);
		if (flo < 0 || x < xflo) {
			flo = b;
			xflo = x;
		}
		if (fhi < 0 || x > xfhi) {
			fhi = b;
			xfhi = x;
		}
		if (!mv[b])
			continue;
		if (*lo < 0 || x < xlo) {
			*lo = b;
			xlo = x;
		}
		if (*hi < 0 || x > xhi) {
			*hi = b;
			xhi = x;
		}
	}
	*left = flo >= 0 && mv[flo];
	*right = fhi >= 0 && mv[fhi];
}

/* The name of moving set mv, with its count as nmin-nmax blocks; by
 * its blocks' ids when small (the set itself is the family's key) */
static void name_of(const struct family_set *fs, const unsigned char *mv,
		    const struct family_outline *out, int nmin, int nmax, int small,
		    char *buf, size_t len)
{
	const struct wall *w = fs->w;
	size_t used = 0;
	buf[0] = 0;
	if (nmax == 0) {
		put(buf, len, &used, "no block moves");
		return;
	}
	struct family_outline o;
	if (out)
		o = *out;
	else
		outline_of(fs, mv, &o);
	int rlo = o.rlo, rhi = o.rhi;
	if (small) {
		int any = 0;
		for (int b = 0; b < w->nblocks; b++)
			if (mv[b]) {
				put(buf, len, &used, "%s%s", any ? " " : "",
				    w->blocks[b].id);
				any = 1;
			}
	} else {
		for (int e = 0; e < (rhi > rlo ? 2 : 1); e++) {
			put(buf, len, &used, "%s%s", e ? " to " : "",
			    w->blocks[o.lo[e]].id);
			if (o.hi[e] != o.lo[e])
				put(buf, len, &used, "-%s", w->blocks[o.hi[e]].id);
		}
	}
	put(buf, len, &used, ": %d", nmin);
	if (nmax > nmin)
		put(buf, len, &used, "-%d", nmax);
	put(buf, len, &used, " block%s in course%s %d", nmax > 1 ? "s" : "",
	    rhi > rlo ? "s" : "", rlo);
	if (rhi > rlo)
		put(buf, len, &used, "-%d", rhi);
	if (o.left && o.right)
		put(buf, len, &used, " across the wall");
	else if (o.left)
		put(buf, len, &used, " at the left end");
	else if (o.right)
		put(buf, len, &used, " at the right end");
}

void family_name(const struct family_set *fs, const unsigned char *mv,
		 char *buf, size_t len)
{
	int n = 0;
	for (int b = 0; b < fs->w->nblocks; b++)
		n += mv[b] != 0;
	name_of(fs, mv, NULL, n, n, n <= FAMILY_SMALL, buf, len);
}

void family_label(const struct family_set *fs, const struct family *f,
		  char *buf, size_t len)
{
	int small = f->nmax <= FAMILY_SMALL;
	name_of(fs, f->moving, small ? NULL : &f->outline, f->nmin, f->nmax,
		small, buf, len);
}

void family_motion(const struct family_set *fs, const char *joint,
		   const unsigned char *mv, char *buf, size_t len)
{
	const struct wall *w = fs->w;
	unsigned char *bed = sw_xcalloc((size_t)fs->nrows + 2, 1);
	int nh = 0, nbed = 0;
	for (int k = 0; k < w->nifaces; k++) {
		const struct wall_interface *f = &w->ifaces[k];
		char c = joint[k];
		if (c == JOINT_CLOSED || mv[f->a] == mv[f->b])
			continue;	/* not on the edge */
		if (c == JOINT_HINGES || c == JOINT_HINGE_SLIDES)
			nh++;
		if ((c == JOINT_SLIDES || c == JOINT_HINGE_SLIDES) &&
		    f->kind == JOINT_BED) {
			/* the lower body's course: the joint's number */
			int lo = w->blocks[f->a].cy < w->blocks[f->b].cy ?
				 f->a : f->b;
			int r = w->blocks[lo].fixed ? 0 : fs->row[lo];
			if (r >= 0 && r <= fs->nrows && !bed[r]) {
				bed[r] = 1;
				nbed++;
			}
		}
	}
	size_t used = 0;
	buf[0] = 0;
	if (nbed > 0) {
		put(buf, len, &used, "slides on bed joint%s ", nbed > 1 ? "s" :
		    "");
		int any = 0;
		for (int r = 0; r <= fs->nrows; r++) {
			if (!bed[r] || (r > 0 && bed[r - 1]))
				continue;	/* not the start of a range */
			int e = r;
			while (e + 1 <= fs->nrows && bed[e + 1])
				e++;
			put(buf, len, &used, e > r ? "%s%d-%d" : "%s%d",
			    any ? ", " : "", r, e);
			any = 1;
		}
	}
	if (nh > 0)
		put(buf, len, &used, "%shinges at %d joint%s", nbed ? ", " : "",
		    nh, nh > 1 ? "s" : "");
	if (nbed == 0 && nh == 0)
		put(buf, len, &used, "opens");
	free(bed);
}

void family_joint_name(const struct wall *w, int k, char *buf, size_t len)
{
	const struct wall_interface *f = &w->ifaces[k];
	snprintf(buf, len, "%s/%s", w->blocks[f->a].id, w->blocks[f->b].id);
}

void family_fmt_joints(const struct wall *w, const char *joint, char *buf,
		       size_t len)
{
	size_t used = 0;
	int any = 0;
	buf[0] = 0;
	for (int k = 0; k < w->nifaces && joint[k]; k++) {
		if (joint[k] == JOINT_CLOSED)
			continue;
		char nm[160], tmp[200];
		family_joint_name(w, k, nm, sizeof nm);
		int n = snprintf(tmp, sizeof tmp, "%s%d%c(%s)", any ? " " : "",
				 k + 1, joint[k], nm);
		if (n < 0 || used + (size_t)n + 4 >= len) {
			if (used + 5 <= len)
				snprintf(buf + used, len - used, " ...");
			return;
		}
		memcpy(buf + used, tmp, (size_t)n + 1);
		used += (size_t)n;
		any = 1;
	}
	if (!any)
		snprintf(buf, len, "(no joint moves)");
}
