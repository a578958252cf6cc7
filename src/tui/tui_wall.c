/*
 * tui_wall.c - the wall pane: the blocks drawn to fit, the supports, the
 * live load, and the mechanism on show (the latest accepted one, or, chosen
 * with m/M, the most frequent mechanism of one of the most frequent
 * mechanism families: docs/statistics.md, "Mechanism families").
 *
 * Drawing goes through a canvas of cells.  Block edges are mapped to the
 * nearest cell centres; an axis-parallel edge sets connection bits
 * (up/down/left/right) in the cells it crosses, so meeting edges become
 * the right box-drawing junction (ASCII: - | +); other edges are drawn
 * with / and \.  The cells between lines belong to the block whose
 * polygon holds the cell centre: moving blocks are filled, supports
 * hatched, and cells of no block that blocks wall in (a removed block,
 * an opening) crossed out, else the lines around them would draw a
 * block there.  Overlays come last: joint states on the interface lines,
 * one motion arrow per moving block (from u, v of its velocity), the
 * load arrow, the block cursor.  With the sample browser open
 * (tui_browse.c) the mechanism is the shown sample's, and its draw's
 * contact points are marked `x` on each interface: q = p1 + xi (p2 - p1)
 * for its xi_a and xi_b (draw.h).  Cells are about twice as tall as wide,
 * so x is scaled twice as much as y.
 *
 * The load moves between "stations" of the wall's outline: the library
 * finds them (wedit.h), tui_edit.c moves the load.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <curses.h>

#include "slipwall/geom.h"
#include "slipwall/wedit.h"
#include "tui.h"

enum { CU = 1, CD = 2, CL = 4, CR = 8 };

struct tui_canvas {
	int w, h;
	unsigned char *conn;	/* connection bits of line cells */
	int *owner;		/* block under the cell centre, or -1 */
	const char **glyph;	/* overlay, or NULL */
	int *attr;		/* attribute of the overlay or the fill */
	char *text;		/* storage of label glyphs (8 bytes each) */
	int ntext, captext;
};

struct tui_map {
	double x0, y1;		/* world point of canvas cell (c0, r0) */
	double sx, sy;		/* cells per metre */
	double c0, r0;
	int coarse;		/* a course is one row: no joint lines */
};

static double tui_wall_col(const struct tui_map *m, double x)
{
	return m->c0 + (x - m->x0) * m->sx;
}

static double tui_wall_row(const struct tui_map *m, double y)
{
	return m->r0 + (m->y1 - y) * m->sy;
}

static int tui_wall_in(const struct tui_canvas *cv, int c, int r)
{
	return c >= 0 && r >= 0 && c < cv->w && r < cv->h;
}

static void tui_wall_conn(struct tui_canvas *cv, int c, int r, int bits)
{
	if (tui_wall_in(cv, c, r))
		cv->conn[r * cv->w + c] |= (unsigned char)bits;
}

static void tui_wall_glyph(struct tui_canvas *cv, int c, int r,
			   const char *g, int attr)
{
	if (!tui_wall_in(cv, c, r))
		return;
	cv->glyph[r * cv->w + c] = g;
	cv->attr[r * cv->w + c] = attr;
}

/* A text overlay, one code point per cell. */
static void tui_wall_label(struct tui_canvas *cv, int c, int r, const char *s,
			   int attr)
{
	while (*s && cv->ntext < cv->captext) {
		char *g = cv->text + 8 * cv->ntext++;
		int k = 0;
		do
			g[k++] = *s++;
		while (k < 7 && ((unsigned char)*s & 0xc0) == 0x80);
		g[k] = 0;
		tui_wall_glyph(cv, c++, r, g, attr);
	}
}

/* The 8 directions, counter-clockwise from east (y up). */
static const char *const tui_arrow_u[8] = {"→", "↗", "↑", "↖", "←", "↙", "↓", "↘"};
static const char *const tui_arrow_a[8] = {">", "/", "^", "\\", "<", "/", "v", "\\"};
static const int tui_oct_dc[8] = {1, 1, 0, -1, -1, -1, 0, 1};
static const int tui_oct_dr[8] = {0, -1, -1, -1, 0, 1, 1, 1};

static int tui_wall_octant(double u, double v)
{
	double a = atan2(v, u);
	int k = (int)floor((a + M_PI / 8) / (M_PI / 4));
	return ((k % 8) + 8) % 8;
}

static const char *tui_wall_shaft(const struct tui *t, int k)
{
	if (k == 0 || k == 4)
		return t->utf8 ? "─" : "-";
	if (k == 2 || k == 6)
		return t->utf8 ? "│" : "|";
	if (k == 1 || k == 5)
		return t->utf8 ? "╱" : "/";
	return t->utf8 ? "╲" : "\\";
}

static const char *tui_wall_box(const struct tui *t, int bits)
{
	static const char *const u[16] = {
		" ", "│", "│", "│", "─", "┘", "┐", "┤",
		"─", "└", "┌", "├", "─", "┴", "┬", "┼",
	};
	if (!t->utf8) {
		if (bits == CU || bits == CD || bits == (CU | CD))
			return "|";
		if (bits == CL || bits == CR || bits == (CL | CR))
			return "-";
		return "+";
	}
	return u[bits & 15];
}

/* A segment between two cells: box bits when axis-parallel, else a
 * diagonal glyph along a Bresenham line. */
static void tui_wall_segment(const struct tui *t, struct tui_canvas *cv,
			     int c1, int r1, int c2, int r2)
{
	if (r1 == r2) {
		int a = c1 < c2 ? c1 : c2, b = c1 < c2 ? c2 : c1;
		for (int c = a; c <= b; c++)
			tui_wall_conn(cv, c, r1, (c > a ? CL : 0) | (c < b ? CR : 0) |
					 (a == b ? CL | CR : 0));
		return;
	}
	if (c1 == c2) {
		int a = r1 < r2 ? r1 : r2, b = r1 < r2 ? r2 : r1;
		for (int r = a; r <= b; r++)
			tui_wall_conn(cv, c1, r, (r > a ? CU : 0) | (r < b ? CD : 0));
		return;
	}
	const char *g = ((c2 > c1) == (r2 < r1)) ? (t->utf8 ? "╱" : "/")
						 : (t->utf8 ? "╲" : "\\");
	int dc = abs(c2 - c1), dr = -abs(r2 - r1);
	int sc = c1 < c2 ? 1 : -1, sr = r1 < r2 ? 1 : -1, e = dc + dr;
	for (int c = c1, r = r1;;) {
		if (!tui_wall_in(cv, c, r) || !cv->conn[r * cv->w + c])
			tui_wall_glyph(cv, c, r, g, 0);
		if (c == c2 && r == r2)
			break;
		int e2 = 2 * e;
		if (e2 >= dr) {
			e += dr;
			c += sc;
		}
		if (e2 <= dc) {
			e += dc;
			r += sr;
		}
	}
}

static int tui_wall_drawn(const struct wall *w, int k)
{
	return k != w->ground_block;
}

/* Fit the wall (every block but the generated ground, the ground line,
 * the point loads) into a canvas of cw x ch cells. */
static void tui_wall_fit(const struct wall *w, const double *cursor, int cw,
			 int ch, struct tui_map *m)
{
	double box[4];
	int vert = 0, nbody = 0;
	wedit_bounds(w, 0, box);
	double x0 = box[0], y0 = box[1], x1 = box[2], y1 = box[3];
	for (int l = 0; l < w->nloads; l++) {
		if (w->loads[l].kind == LOAD_POINT &&
		    fabs(w->loads[l].dir[1]) > 0.38)
			vert = 1;
		nbody += w->loads[l].kind == LOAD_BODY;
	}
	if (w->has_ground)
		y0 = fmin(y0, w->ground_y);
	if (cursor) {
		x0 = fmin(x0, cursor[0]);
		x1 = fmax(x1, cursor[0]);
		y0 = fmin(y0, cursor[1]);
		y1 = fmax(y1, cursor[1]);
	}
	/* Rows are scaled to whole rows per course, so that every course
	 * has a row of its own between its joint lines (the loaded one
	 * too): with the usual margins, else with the least ones; when
	 * even then a course gets fewer than two rows, the drawing is
	 * coarse: one row per course (or less), no joint lines.  Each
	 * body load's label has a row of its own above the wall
	 * (tui_wall_loads), in every try. */
	double bh = w->layout.present ? w->layout.block_h
				      : w->mean_size / sqrt(2);
	double mx = 4, top = 0, bottom = 0, aw = cw - 1 - 2 * mx, s = 0;
	double dx = fmax(x1 - x0, 1e-9), dy = fmax(y1 - y0, 1e-9);
	m->coarse = 0;
	for (int tries = 0; tries < 2; tries++) {
		top = fmax(tries == 0 ? (vert ? 4 : 1) : (vert ? 2 : 0),
			   nbody);
		bottom = tries == 0 ? (vert ? 4 : 2) : (vert ? 2 : 1);
		double ah = ch - 1 - top - bottom;
		s = fmin(ah / dy, aw / (2 * dx));
		double k = floor(s * bh + 1e-9);
		/* a wall too long for the aspect ratio: two rows a course
		 * if the height allows, narrower columns */
		if (k < 2 && floor(ah / dy * bh + 1e-9) >= 2)
			k = 2;
		if (k >= 2 && bh > 0) {
			s = k / bh;
			break;
		}
		if (tries == 1) {
			m->coarse = 1;
			if (bh > 0 && s * bh >= 1)
				s = 1 / bh;
		}
	}
	if (!(s > 0))
		s = 1;
	m->sy = s;
	m->sx = fmin(2 * s, aw / dx);
	m->x0 = x0;
	m->y1 = y1;
	m->c0 = mx + floor((aw - dx * m->sx) / 2);
	/* coarse: the centre of row top is the middle of the top course */
	m->r0 = m->coarse ? top - 0.5 : top;
}

/* The coarse drawing: a vertical bar wherever the block under the cells
 * changes along a row (the head joints); no bed joint lines. */
static void tui_wall_coarse(const struct tui *t, struct tui_canvas *cv,
			    int joints)
{
	for (int r = 0; r < cv->h; r++)
		for (int c = 0; c < cv->w; c++) {
			int a = c ? cv->owner[r * cv->w + c - 1] : -1;
			int b = cv->owner[r * cv->w + c];
			if (joints && a != b && a >= 0 && b >= 0)
				tui_wall_conn(cv, c, r, CU | CD);
			else if (!joints && b >= 0 && !t->w->blocks[b].fixed)
				tui_wall_glyph(cv, c, r, t->utf8 ? "\u00b7" : ".", 0);
		}
}

/* The map of the last drawing is t->wall_view, for the mouse. */
int tui_wall_point(const struct tui *t, int y, int x, double *wx,
		   double *wy)
{
	const struct tui_wall_view *m = &t->wall_view;
	if (!m->ok)
		return 0;
	double r = y - m->y, c = x - m->x;
	*wx = m->x0 + (c - m->c0) / m->sx;
	*wy = m->y1 - (r - m->r0) / m->sy;
	return 1;
}

static void tui_wall_fill(const struct wall *w, struct tui_canvas *cv,
			  const struct tui_map *m)
{
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *b = &w->blocks[k];
		if (!tui_wall_drawn(w, k))
			continue;
		double bx0 = INFINITY, by0 = INFINITY, bx1 = -INFINITY, by1 = -INFINITY;
		for (int i = 0; i < b->nv; i++) {
			bx0 = fmin(bx0, b->xy[2 * i]);
			bx1 = fmax(bx1, b->xy[2 * i]);
			by0 = fmin(by0, b->xy[2 * i + 1]);
			by1 = fmax(by1, b->xy[2 * i + 1]);
		}
		int ca = (int)floor(tui_wall_col(m, bx0)), cb = (int)ceil(tui_wall_col(m, bx1));
		int ra = (int)floor(tui_wall_row(m, by1)), rb = (int)ceil(tui_wall_row(m, by0));
		for (int r = ra < 0 ? 0 : ra; r <= rb && r < cv->h; r++)
			for (int c = ca < 0 ? 0 : ca; c <= cb && c < cv->w; c++) {
				double x = m->x0 + (c - m->c0) / m->sx;
				double y = m->y1 - (r - m->r0) / m->sy;
				if (geom_contains(b->xy, b->nv, x, y, 0))
					cv->owner[r * cv->w + c] = k;
			}
	}
}

/* Is the empty cell (c, r) walled in: a line or a block first met
 * in each of the four directions? */
static int tui_wall_enclosed(const struct tui_canvas *cv, int c, int r)
{
	static const int d[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
	for (int k = 0; k < 4; k++) {
		int x = c + d[k][0], y = r + d[k][1], hit = 0;
		for (; tui_wall_in(cv, x, y) && !hit; x += d[k][0], y += d[k][1]) {
			int i = y * cv->w + x;
			hit = cv->conn[i] || cv->owner[i] >= 0;
		}
		if (!hit)
			return 0;
	}
	return 1;
}

/* Holes: cells of no block walled in by blocks, where a block was
 * removed (x) or the wall has an opening.  Left empty, the lines of the
 * blocks around would draw one there; they are crossed out instead. */
static void tui_wall_holes(const struct tui *t, struct tui_canvas *cv)
{
	for (int r = 0; r < cv->h; r++)
		for (int c = 0; c < cv->w; c++) {
			int i = r * cv->w + c;
			if (cv->owner[i] < 0 && !cv->conn[i] && !cv->glyph[i] &&
			    tui_wall_enclosed(cv, c, r))
				tui_wall_glyph(cv, c, r, t->utf8 ? "╳" : "x", A_DIM);
		}
}

int tui_family_shown(const struct tui *t)
{
	struct family_set *fs = tui_run_families(t);
	if (t->mech_sel <= 0 || !fs || fs->nfam == 0)
		return -1;
	int *idx = malloc(sizeof(int) * (size_t)fs->nfam);
	int n = idx ? family_top(fs, idx, fs->nfam) : 0;
	int k = t->mech_sel - 1, f = k < n ? idx[k] : -1;
	free(idx);
	return f;
}

int tui_family_rank(const struct tui *t, const char *joint, int *n)
{
	struct family_set *fs = tui_run_families(t);
	*n = fs ? fs->nfam : 0;
	int f = tui_run_family_of(t, fs, joint);
	if (f < 0)
		return 0;
	int *idx = malloc(sizeof(int) * (size_t)fs->nfam);
	int nf = idx ? family_top(fs, idx, fs->nfam) : 0, k = 0;
	for (int i = 0; i < nf && !k; i++)
		if (idx[i] == f)
			k = i + 1;
	free(idx);
	return k;
}

int tui_wall_mechanism(const struct tui *t, const char **joint,
		       const double **vel, char *label, size_t len, int w)
{
	const struct tui_run *r = &t->run;
	const struct tally *ta = &r->tally;
	int f = tui_family_shown(t);
	if (f >= 0) {
		/* m/M's family (docs/statistics.md, "Mechanism families"),
		 * drawn by its most frequent mechanism */
		const struct family_set *fs = r->fams;
		const struct family *fa = &fs->fam[f];
		int mk;
		family_mechs(fs, ta, f, &mk, 1);
		const struct tally_mech *mm = &ta->mech[mk];
		*joint = mm->joint;
		*vel = mm->vel;
		char name[256];
		family_label(fs, fa, name, sizeof name);
		const char *what = strstr(name, ": ");
		/* the long form if it fits the pane, else shorter; the
		 * numbers whole */
		double pc = ta->accepted ? 100.0 * (double)fa->count /
					   (double)ta->accepted : 0.0;
		const char *unit = strcmp(tui_load_unit(t->w), "N") ? "" : " N";
		char pcs[32];
		tui_pct(pcs, sizeof pcs, pc / 100);
		for (int form = 0; form < 5; form++) {
			const char *nm = form == 0 ? name : form == 1 && what ?
					 what + 2 : "";
			snprintf(label, len,
				 "family %d/%d: %s%s (%s %.*g..%.*g%s)%s%s",
				 t->mech_sel, fs->nfam, pcs,
				 form < 3 ? " of accepted" : "", tui_lam(t),
				 form == 4 ? 3 : 4, fa->lam_lo, form == 4 ? 3 : 4,
				 fa->lam_hi, unit, *nm ? ", " : "", nm);
			if (tui_cols(label) <= w)
				break;
		}
		return 1;
	}
	if (r->latest_index >= 0) {
		*joint = r->latest_joint;
		*vel = r->latest_vel;
		snprintf(label, len, "latest mechanism (sample %ld), %d distinct",
			 r->latest_index + 1, ta->nmech);
		return 1;
	}
	snprintf(label, len, r->mc || ta->samples == 0 ? "no mechanism yet" :
		 "no mechanism: no sample accepted");
	return 0;
}

/* Joint states along the interface lines, arrows on moving blocks. */
static void tui_wall_mech(const struct tui *t, struct tui_canvas *cv,
			  const struct tui_map *m, const char *joint,
			  const double *vel, int *moving)
{
	const struct wall *w = t->w;
	int attr = t->colors ? COLOR_PAIR(1) : A_BOLD;

	for (int k = 0; k < w->nblocks; k++) {
		const double *v = vel + 3 * k;
		double speed = hypot(v[0], v[1]) + fabs(v[2]) * w->mean_size;
		moving[k] = !w->blocks[k].fixed && speed > 1e-3;
	}
	for (int i = 0; i < cv->w * cv->h; i++)
		if (cv->owner[i] >= 0 && moving[cv->owner[i]] && !cv->conn[i]) {
			cv->glyph[i] = t->utf8 ? "▒" : "#";
			cv->attr[i] = attr;
		}
	for (int i = 0; i < w->nifaces && !m->coarse; i++) {
		char s = joint[i];
		if (s == JOINT_CLOSED || s == 0)
			continue;
		const struct wall_interface *f = &w->ifaces[i];
		const char *g = (s == JOINT_SLIDES || s == JOINT_HINGE_SLIDES) ? "=" : ":";
		int c1 = (int)lround(tui_wall_col(m, f->p1[0]));
		int r1 = (int)lround(tui_wall_row(m, f->p1[1]));
		int c2 = (int)lround(tui_wall_col(m, f->p2[0]));
		int r2 = (int)lround(tui_wall_row(m, f->p2[1]));
		int n = abs(c2 - c1) > abs(r2 - r1) ? abs(c2 - c1) : abs(r2 - r1);
		/* leave the corners: they belong to more than one joint */
		for (int j = n > 2 ? 1 : 0; j <= (n > 2 ? n - 1 : n); j++) {
			int c = n ? c1 + (c2 - c1) * j / n : c1;
			int r = n ? r1 + (r2 - r1) * j / n : r1;
			tui_wall_glyph(cv, c, r, g, A_BOLD);
		}
		if (s == JOINT_HINGES || s == JOINT_HINGE_SLIDES)
			tui_wall_glyph(cv, (c1 + c2) / 2, (r1 + r2) / 2, "*", A_BOLD);
	}
	for (int k = 0; k < w->nblocks; k++) {
		if (!moving[k])
			continue;
		const double *v = vel + 3 * k;
		const struct wall_block *b = &w->blocks[k];
		int c = (int)lround(tui_wall_col(m, b->cx));
		int r = (int)lround(tui_wall_row(m, b->cy));
		const char *g;
		if (hypot(v[0], v[1]) < 0.2 * fabs(v[2]) * w->mean_size)
			g = v[2] > 0 ? (t->utf8 ? "↺" : "@") : (t->utf8 ? "↻" : "@");
		else {
			int o = tui_wall_octant(v[0], v[1]);
			g = t->utf8 ? tui_arrow_u[o] : tui_arrow_a[o];
		}
		tui_wall_glyph(cv, c, r, g, attr | A_BOLD);
	}
}

/* The shown sample's contact points, two on each interface. */
static void tui_wall_contacts(const struct tui *t, struct tui_canvas *cv,
			      const struct tui_map *m,
			      const struct tui_browse_sample *s)
{
	const struct wall *w = t->w;
	int attr = (t->colors ? COLOR_PAIR(2) : 0) | A_BOLD;
	for (int i = 0; i < w->nifaces; i++) {
		const struct wall_interface *f = &w->ifaces[i];
		for (int e = 0; e < 2; e++) {
			double xi = s->xi[2 * i + e];
			double qx = f->p1[0] + xi * (f->p2[0] - f->p1[0]);
			double qy = f->p1[1] + xi * (f->p2[1] - f->p1[1]);
			tui_wall_glyph(cv, (int)lround(tui_wall_col(m, qx)),
				       (int)lround(tui_wall_row(m, qy)), "x", attr);
		}
	}
}

/* The browser's picked joint (< >): its cells in reverse video, and a
 * diamond at its middle unless a mark is there already. */
static void tui_wall_pick(const struct tui *t, struct tui_canvas *cv,
			  const struct tui_map *m, int k)
{
	const struct wall_interface *f = &t->w->ifaces[k];
	int c1 = (int)lround(tui_wall_col(m, f->p1[0]));
	int r1 = (int)lround(tui_wall_row(m, f->p1[1]));
	int c2 = (int)lround(tui_wall_col(m, f->p2[0]));
	int r2 = (int)lround(tui_wall_row(m, f->p2[1]));
	int n = abs(c2 - c1) > abs(r2 - r1) ? abs(c2 - c1) : abs(r2 - r1);
	for (int j = 0; j <= n; j++) {
		int c = n ? c1 + (c2 - c1) * j / n : c1;
		int r = n ? r1 + (r2 - r1) * j / n : r1;
		if (!tui_wall_in(cv, c, r))
			continue;
		int i = r * cv->w + c;
		if (!cv->glyph[i] && !cv->conn[i])
			cv->glyph[i] = " ";
		cv->attr[i] |= A_REVERSE | A_BOLD;
	}
	int c = (c1 + c2) / 2, r = (r1 + r2) / 2;
	if (tui_wall_in(cv, c, r) && (!cv->glyph[r * cv->w + c] ||
				      !strcmp(cv->glyph[r * cv->w + c], " ")))
		cv->glyph[r * cv->w + c] = t->utf8 ? "◆" : "@";
}

/* The browser's label: the sample, its status, its load, its
 * mechanism's number (m/M's), in the longest form that fits. */
static void tui_wall_browse_label(const struct tui *t,
				  const struct tui_browse_sample *s,
				  char *label, size_t len, int w)
{
	char lam[48] = "", mech[96] = "";
	const char *unit = strcmp(tui_load_unit(t->w), "N") ? "" : " N";
	int n, k = 0, nf = 0, kf = 0;
	if (s->status == SAMPLE_ACCEPTED) {
		k = tui_browse_mech_rank(t, s->joint, &n);
		kf = tui_family_rank(t, s->joint, &nf);
	}
	for (int form = 0; form < 4; form++) {
		if (s->status == SAMPLE_ACCEPTED || isfinite(s->lam))
			snprintf(lam, sizeof lam, " %s%s %.*g%s", tui_lam(t),
				 form < 3 ? "_min" : "", form == 3 ? 3 : 4,
				 tui_load(t, s->lam), unit);
		if (k > 0 && kf > 0 && form == 0)
			snprintf(mech, sizeof mech, ", mechanism %d/%d, family "
				 "%d/%d", k, n, kf, nf);
		else if (k > 0)
			snprintf(mech, sizeof mech, form < 2 ? ", mechanism %d/%d"
				 : " mech %d/%d", k, n);
		snprintf(label, len, "sample %ld: %s%s%s", s->index + 1,
			 sample_status_name(s->status), lam, mech);
		if (tui_cols(label) <= w)
			break;
	}
}

/* The picked joint's state in the sample, in words ("" when closed or
 * the sample has no mechanism). */
static const char *tui_wall_state(int c)
{
	switch (c) {
	case JOINT_SLIDES: return " slides";
	case JOINT_HINGES: return " hinges";
	case JOINT_HINGE_SLIDES: return " hinges+slides";
	case JOINT_OPENS: return " opens";
	default: return "";
	}
}

/* The browser's legend: the picked joint (< >) and its friction in
 * the sample, else the joints' least and largest friction (random
 * friction); the contact marker; the joint states of the sample.  A
 * picked joint's part comes whole; what follows it only if it fits in
 * w columns. */
static void tui_wall_browse_legend(const struct tui *t,
				   const struct tui_browse_sample *s,
				   char *buf, size_t len, int w)
{
	const struct wall *wall = t->w;
	int n = 0, k = t->browse.pick - 1;
	if (k >= 0 && k < wall->nifaces) {
		const struct wall_interface *f = &wall->ifaces[k];
		n = snprintf(buf, len, "joint %d/%d %s|%s %s %s %.3g%s", k + 1,
			     wall->nifaces, wall->blocks[f->a].id,
			     wall->blocks[f->b].id, f->kind == JOINT_BED ? "bed"
			     : f->kind == JOINT_HEAD ? "head" : "other",
			     tui_mu(t), s->mu ? s->mu[k] : wall_iface_mu(wall, k),
			     s->status == SAMPLE_ACCEPTED
			     ? tui_wall_state(s->joint[k]) : "");
		if ((size_t)n >= len || tui_cols(buf) + 11 > w)
			return;
		n += snprintf(buf + n, len - (size_t)n, "  ");
	}
	n += snprintf(buf + n, len - (size_t)n, "x contact");
	if (s->mu && wall->nifaces > 0 && k < 0) {
		double lo = INFINITY, hi = -INFINITY;
		for (int i = 0; i < wall->nifaces; i++) {
			lo = fmin(lo, s->mu[i]);
			hi = fmax(hi, s->mu[i]);
		}
		n += snprintf(buf + n, len - (size_t)n, "  %s %.3g..%.3g",
			      tui_mu(t), lo, hi);
	}
	if (s->status == SAMPLE_ACCEPTED && (size_t)n < len)
		snprintf(buf + n, len - (size_t)n, "  joints %s", s->joint);
}

static void tui_wall_loads(const struct tui *t, struct tui_canvas *cv,
			   const struct tui_map *m)
{
	const struct wall *w = t->w;
	int attr = (t->colors ? COLOR_PAIR(2) : 0) | A_BOLD;
	int body = 0;	/* the body loads' labels, a row each (tui_wall_fit) */
	for (int l = 0; l < w->nloads; l++) {
		const struct wall_load *ld = &w->loads[l];
		int k = tui_wall_octant(ld->dir[0], ld->dir[1]);
		const char *head = t->utf8 ? tui_arrow_u[k] : tui_arrow_a[k];
		if (ld->kind == LOAD_BODY) {
			char buf[64];
			snprintf(buf, sizeof buf, "body load %s%s W on every block %s",
				 tui_lam(t), t->utf8 ? "·" : "*", head);
			tui_wall_label(cv, 0, body++, buf, attr);
			continue;
		}
		int pc = (int)lround(tui_wall_col(m, ld->at[0]));
		int pr = (int)lround(tui_wall_row(m, ld->at[1]));
		double e = 0.01 * w->mean_size;
		int push = 0;	/* the force points into a free block */
		for (int b = 0; b < w->nblocks && !push; b++)
			push = !w->blocks[b].fixed &&
			       geom_contains(w->blocks[b].xy, w->blocks[b].nv,
					     ld->at[0] + e * ld->dir[0],
					     ld->at[1] + e * ld->dir[1],
					     -1e-3 * e);
		int dc = tui_oct_dc[k], dr = tui_oct_dr[k];
		const char *shaft = tui_wall_shaft(t, k);
		tui_wall_glyph(cv, pc, pr, t->utf8 ? "●" : "o", attr);
		for (int j = 1; j <= 3; j++) {
			int s = push ? -j : j;
			int ishead = push ? j == 1 : j == 3;
			tui_wall_glyph(cv, pc + s * dc, pr + s * dr,
				       ishead ? head : shaft, attr);
		}
	}
}

void tui_wall_draw(struct tui *t, int y0, int x0, int h, int w)
{
	const struct wall *wall = t->w;
	struct tui_canvas cv;
	struct tui_map m;
	char label[256];
	const char *joint = NULL;
	const double *vel = NULL;

	struct tui_browse_sample bs;
	int browse = tui_browse_shown(t, &bs);
	int has = tui_wall_mechanism(t, &joint, &vel, label, sizeof label, w);
	if (browse) {
		tui_wall_browse_label(t, &bs, label, sizeof label, w);
		has = bs.status == SAMPLE_ACCEPTED;
		joint = bs.joint;
		vel = bs.vel;
	} else if (t->browse.open) {
		snprintf(label, sizeof label, "sample browser: no sample yet");
		has = 0;
	}
	if (t->cursor_mode) {
		int k = wedit_block_at(wall, t->cur_x, t->cur_y);
		snprintf(label, sizeof label, "cursor (%.3g, %.3g): %s  a add  x remove",
			 t->cur_x, t->cur_y,
			 k < 0 ? "no block" : wall->blocks[k].id);
	}
	attron(A_BOLD);
	tui_text(y0, x0, w, label);
	attroff(A_BOLD);

	cv.w = w;
	cv.h = h - 2;
	if (cv.h < 3)
		return;
	size_t n = (size_t)cv.w * (size_t)cv.h;
	cv.conn = calloc(n, 1);
	cv.owner = malloc(sizeof(int) * n);
	cv.glyph = calloc(n, sizeof *cv.glyph);
	cv.attr = calloc(n, sizeof(int));
	cv.captext = 2 * cv.w;
	cv.ntext = 0;
	cv.text = malloc(8 * (size_t)cv.captext);
	int *moving = calloc((size_t)wall->nblocks + 1, sizeof(int));
	if (!cv.conn || !cv.owner || !cv.glyph || !cv.attr || !cv.text || !moving)
		goto out;
	for (size_t i = 0; i < n; i++)
		cv.owner[i] = -1;

	double cur[2] = {t->cur_x, t->cur_y};
	tui_wall_fit(wall, t->cursor_mode ? cur : NULL, cv.w, cv.h, &m);
	t->wall_view = (struct tui_wall_view){
		.ok = 1, .y = y0 + 1, .x = x0, .x0 = m.x0, .y1 = m.y1,
		.sx = m.sx, .sy = m.sy, .c0 = m.c0, .r0 = m.r0};
	tui_wall_fill(wall, &cv, &m);
	double cmin = INFINITY, cmax = -INFINITY;
	/* coarse: head joints when a course has its row, else dots */
	if (m.coarse)
		tui_wall_coarse(t, &cv, m.sy * (wall->layout.present
					? wall->layout.block_h
					: wall->mean_size / sqrt(2)) >= 1 - 1e-9);
	for (int k = 0; k < wall->nblocks; k++) {
		const struct wall_block *b = &wall->blocks[k];
		if (!tui_wall_drawn(wall, k))
			continue;
		for (int i = 0; i < b->nv && m.coarse; i++) {
			cmin = fmin(cmin, lround(tui_wall_col(&m, b->xy[2 * i])));
			cmax = fmax(cmax, lround(tui_wall_col(&m, b->xy[2 * i])));
		}
		for (int i = 0; i < b->nv && !m.coarse; i++) {
			int j = (i + 1) % b->nv;
			int c1 = (int)lround(tui_wall_col(&m, b->xy[2 * i]));
			int r1 = (int)lround(tui_wall_row(&m, b->xy[2 * i + 1]));
			int c2 = (int)lround(tui_wall_col(&m, b->xy[2 * j]));
			int r2 = (int)lround(tui_wall_row(&m, b->xy[2 * j + 1]));
			tui_wall_segment(t, &cv, c1, r1, c2, r2);
			cmin = fmin(cmin, c1);
			cmax = fmax(cmax, c1);
		}
	}
	for (size_t i = 0; i < n; i++) {
		int k = cv.owner[i];
		if (k >= 0 && wall->blocks[k].fixed && !cv.conn[i])
			cv.glyph[i] = t->utf8 ? "░" : "/";
	}
	tui_wall_holes(t, &cv);
	if (wall->has_ground && isfinite(cmin) && m.coarse) {
		int gr = (int)ceil(tui_wall_row(&m, wall->ground_y));
		for (int c = (int)cmin - 3; c <= (int)cmax + 3; c++)
			tui_wall_glyph(&cv, c, gr, t->utf8 ? "░" : "/", 0);
	} else if (wall->has_ground && isfinite(cmin)) {
		int gr = (int)lround(tui_wall_row(&m, wall->ground_y));
		int a = (int)cmin - 3, b = (int)cmax + 3;
		tui_wall_segment(t, &cv, a, gr, b, gr);
		for (int c = a; c <= b; c++)
			tui_wall_glyph(&cv, c, gr + 1, t->utf8 ? "░" : "/", 0);
	}
	if (has && !t->cursor_mode)
		tui_wall_mech(t, &cv, &m, joint, vel, moving);
	if (browse)
		tui_wall_contacts(t, &cv, &m, &bs);
	if (browse && t->browse.pick > 0 && t->browse.pick <= wall->nifaces)
		tui_wall_pick(t, &cv, &m, t->browse.pick - 1);
	tui_wall_loads(t, &cv, &m);
	if (t->cursor_mode)
		tui_wall_glyph(&cv, (int)lround(tui_wall_col(&m, t->cur_x)),
			       (int)lround(tui_wall_row(&m, t->cur_y)), "X",
			       A_REVERSE | A_BOLD);

	for (int r = 0; r < cv.h; r++)
		for (int c = 0; c < cv.w; c++) {
			size_t i = (size_t)r * cv.w + c;
			const char *g = cv.glyph[i];
			if (!g && cv.conn[i])
				g = tui_wall_box(t, cv.conn[i]);
			if (!g)
				continue;
			if (cv.attr[i])
				attron(cv.attr[i]);
			mvaddstr(y0 + 1 + r, x0 + c, g);
			if (cv.attr[i])
				attroff(cv.attr[i]);
		}
	if (browse) {
		char legend[512];
		tui_wall_browse_legend(t, &bs, legend, sizeof legend, w);
		tui_text_cut(t, y0 + h - 1, x0, w, legend);
	} else {
		tui_text_cut(t, y0 + h - 1, x0, w,
			     t->utf8 ? "▒ moving  = slides  * hinge  : opens  ● load"
				     : "# moving  = slides  * hinge  : opens  o load");
	}
out:
	free(cv.conn);
	free(cv.owner);
	free(cv.glyph);
	free(cv.attr);
	free(cv.text);
	free(moving);
}
