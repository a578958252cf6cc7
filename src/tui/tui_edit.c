/*
 * tui_edit.c - the main screen: its layout (title, wall pane, statistics,
 * histogram, message and status lines), its keys, the prompt line, and
 * the edits of the wall.
 *
 * The wall of a running sampler is read-only (wall.h), so every edit
 * builds a new wall: tui_edit_copy() rebuilds an unfinished copy from
 * the current one (without the generated ground, which wall_finish adds
 * again; with the layout's courses generated again for layout edits),
 * the key changes the copy, and tui_edit_apply() finishes it and hands
 * it to tui_set_wall(), which ends the current run (its samples file
 * stays) and starts a new one.  A copy that does not finish (a removed
 * block leaves another hanging, a load off the wall) is thrown away with
 * its message on the message line; the current wall stays.
 *
 * tui_edit_apply() also pushes the wall it replaces on the undo stack
 * (src/lib/undo.c): u and U switch back and forth the same way, as new runs
 * of the same seed.  No key changes the wall without a prompt or a way
 * back.
 *
 * Layout edits regenerate every block whose id is a generated one
 * ("c<course>b<k>"); other blocks (from the file's `blocks`, or added
 * here, "u<k>") are kept as they are.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <curses.h>

#include "slipwall/text.h"
#include "slipwall/geom.h"
#include "slipwall/layout.h"
#include "tui.h"

#define TUI_STEP_MU 0.05
#define TUI_STEP_DEPTH 0.05

static int tui_edit_generated(const char *id)
{
	int c, k, n = 0;
	return id && sscanf(id, "c%db%d%n", &c, &k, &n) == 2 && id[n] == 0;
}

struct wall *tui_edit_copy(const struct wall *w, const struct wall_layout *regen,
			   int skip, char *err)
{
	struct wall_mark none = {0, 0};
	struct wall *c = wall_new();

	c->name = w->name ? sw_xstrdup(w->name) : NULL;
	c->path = w->path ? sw_xstrdup(w->path) : NULL;
	c->mu_bed = w->mu_bed;
	c->mu_head = w->mu_head;
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
		if (regen && !b->fixed && tui_edit_generated(b->id))
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

int tui_edit_apply(struct tui *t, struct wall *nw, const char *what)
{
	char err[SW_ERRLEN];
	if (wall_finish(nw, err) != SW_OK) {
		tui_message(t, 1, "not applied: %s", err);
		wall_free(nw);
		return -1;
	}
	undo_edit(&t->undo, t->w);
	snprintf(t->next_what, sizeof t->next_what, "%s", what);
	tui_set_wall(t, nw);
	return 0;
}

/* u and U (Ctrl-R): back to the wall before the last edit, or forward
 * again; a new run on it, with the same seed, so the same samples. */
static void tui_edit_undo(struct tui *t, int redo)
{
	struct wall *p = redo ? undo_redo(&t->undo, t->w)
			      : undo_undo(&t->undo, t->w);
	if (!p) {
		tui_message(t, 0, "nothing to %s", redo ? "redo" : "undo");
		return;
	}
	snprintf(t->next_what, sizeof t->next_what, "%s", redo ? "redo" : "undo");
	tui_set_wall(t, p);
	tui_message(t, 0, "%s: sampling again (run %d; %d more to undo, %d to redo)",
		    redo ? "redone" : "undone", t->runno, t->undo.npast,
		    t->undo.nfuture);
}

/* Copy, let the caller change, apply; with a message on success. */
static struct wall *tui_edit_begin(struct tui *t)
{
	char err[SW_ERRLEN];
	struct wall *nw = tui_edit_copy(t->w, NULL, -1, err);
	if (!nw)
		tui_message(t, 1, "%s", err);
	return nw;
}

static void tui_edit_done(struct tui *t, struct wall *nw, const char *what)
{
	if (tui_edit_apply(t, nw, what) == 0)
		tui_message(t, 0, "%s: sampling again (run %d)", what, t->runno);
}

static int tui_edit_point_load(const struct wall *w)
{
	for (int l = 0; l < w->nloads; l++)
		if (w->loads[l].kind == LOAD_POINT)
			return l;
	return -1;
}

/* ---- the prompt line ---- */

void tui_prompt(struct tui *t, const char *label, const char *initial,
		tui_prompt_done done)
{
	t->prompting = 1;
	snprintf(t->plabel, sizeof t->plabel, "%s", label);
	snprintf(t->pbuf, sizeof t->pbuf, "%s", initial ? initial : "");
	t->plen = (int)strlen(t->pbuf);
	t->pdone = done;
}

static void tui_prompt_key(struct tui *t, int ch)
{
	if (ch == '\n' || ch == '\r' || ch == KEY_ENTER) {
		char text[sizeof t->pbuf];
		memcpy(text, t->pbuf, sizeof text);
		t->prompting = 0;
		t->pdone(t, text);
	} else if (ch == 27 || ch == 7) {	/* Esc, Ctrl-G */
		t->prompting = 0;
		tui_message(t, 0, "cancelled");
	} else if (ch == KEY_BACKSPACE || ch == 127 || ch == 8) {
		/* remove one UTF-8 character */
		while (t->plen > 0 &&
		       ((unsigned char)t->pbuf[--t->plen] & 0xc0) == 0x80)
			;
		t->pbuf[t->plen] = 0;
	} else if (ch == 21) {			/* Ctrl-U */
		t->plen = 0;
		t->pbuf[0] = 0;
	} else if (ch >= 32 && ch < 256 && ch != 127 &&
		   t->plen < (int)sizeof t->pbuf - 1) {
		t->pbuf[t->plen++] = (char)ch;
		t->pbuf[t->plen] = 0;
	}
}

/* Parse "a" or "a,b" (also spaces); returns how many numbers. */
static int tui_edit_numbers(const char *s, double *v, int max)
{
	int n = 0;
	char *end;
	while (*s && n < max) {
		while (*s == ' ' || *s == ',' || *s == '\t')
			s++;
		if (!*s)
			break;
		v[n] = strtod(s, &end);
		if (end == s || !isfinite(v[n]))
			return -1;
		n++;
		s = end;
	}
	while (*s == ' ' || *s == ',')
		s++;
	return *s ? -1 : n;
}

/* ---- edits ---- */

static void tui_edit_friction(struct tui *t, double bed, double head)
{
	char what[128];
	if (bed < 0 || head < 0) {
		tui_message(t, 1, "friction must be >= 0");
		return;
	}
	struct wall *nw = tui_edit_begin(t);
	if (!nw)
		return;
	nw->mu_bed = bed;
	nw->mu_head = head;
	snprintf(what, sizeof what, "friction bed %.3g, head %.3g", bed, head);
	tui_edit_done(t, nw, what);
}

static void tui_edit_friction_typed(struct tui *t, const char *text)
{
	double v[2];
	int n = tui_edit_numbers(text, v, 2);
	if (n < 1) {
		tui_message(t, 1, "friction: type 'bed' or 'bed,head' (numbers >= 0)");
		return;
	}
	tui_edit_friction(t, v[0], n == 2 ? v[1] : v[0]);
}

static void tui_edit_depth(struct tui *t, double d, int anywhere)
{
	char what[128];
	d = fmin(0.5, fmax(0, d));
	struct wall *nw = tui_edit_begin(t);
	if (!nw)
		return;
	nw->depth = round(d * 1e6) / 1e6;
	nw->anywhere = anywhere;
	if (anywhere)
		snprintf(what, sizeof what, "contact points anywhere");
	else
		snprintf(what, sizeof what, "contact depth %.3g", nw->depth);
	tui_edit_done(t, nw, what);
}

static void tui_edit_load_at(struct tui *t, const double at[2],
			     const double *dir)
{
	char what[128];
	int l = tui_edit_point_load(t->w);
	if (l < 0) {
		tui_message(t, 1, "this wall has no point load to move");
		return;
	}
	struct wall *nw = tui_edit_begin(t);
	if (!nw)
		return;
	nw->loads[l].at[0] = at[0];
	nw->loads[l].at[1] = at[1];
	if (dir) {
		nw->loads[l].dir[0] = dir[0];
		nw->loads[l].dir[1] = dir[1];
	}
	snprintf(what, sizeof what, "load at (%.4g, %.4g) direction (%.3g, %.3g)",
		 at[0], at[1], nw->loads[l].dir[0], nw->loads[l].dir[1]);
	tui_edit_done(t, nw, what);
}

static void tui_edit_load_typed(struct tui *t, const char *text)
{
	double v[4];
	int n = tui_edit_numbers(text, v, 4);
	if (n != 2 && n != 4) {
		tui_message(t, 1, "load: type 'x,y' or 'x,y,dx,dy'");
		return;
	}
	tui_edit_load_at(t, v, n == 4 ? v + 2 : NULL);
}

static void tui_edit_load_step(struct tui *t, int dx, int dy)
{
	int l = tui_edit_point_load(t->w);
	if (l < 0) {
		tui_message(t, 1, "this wall has no point load to move");
		return;
	}
	double at[2] = {t->w->loads[l].at[0], t->w->loads[l].at[1]};
	if (!tui_wall_load_step(t->w, dx, dy, at)) {
		tui_message(t, 0, "no place for the load further that way");
		return;
	}
	tui_edit_load_at(t, at, NULL);
}

static void tui_edit_load_turn(struct tui *t, int sense)
{
	int l = tui_edit_point_load(t->w);
	if (l < 0)
		l = 0;		/* a body load turns too */
	struct wall *nw = tui_edit_begin(t);
	if (!nw)
		return;
	struct wall_load *ld = &nw->loads[l];
	double a = atan2(ld->dir[1], ld->dir[0]);
	a = (round(a / (M_PI / 4)) + sense) * (M_PI / 4);
	ld->dir[0] = cos(a);
	ld->dir[1] = sin(a);
	for (int i = 0; i < 2; i++)
		if (fabs(ld->dir[i]) < 1e-12)
			ld->dir[i] = 0;
	char what[96];
	snprintf(what, sizeof what, "load direction (%.3g, %.3g)", ld->dir[0],
		 ld->dir[1]);
	tui_edit_done(t, nw, what);
}

/* After a layout change a point load may be off the wall (fewer courses,
 * a shorter wall): move each such load to the nearest station of the new
 * outline.  The outline comes from a copy finished with a body load in
 * place of the point loads. */
static void tui_edit_snap_loads(struct wall *nw)
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
			int k = tui_wall_block_at(c, ld->at[0], ld->at[1]);
			if (ld->kind == LOAD_POINT && (k < 0 || c->blocks[k].fixed))
				tui_wall_load_nearest(c, ld->dir, ld->at);
		}
	}
	wall_free(c);
}

static void tui_edit_layout(struct tui *t, const struct wall_layout *lay,
			    const char *what)
{
	char err[SW_ERRLEN];
	if (!t->w->layout.present) {
		tui_message(t, 1, "this wall has no generated layout to change");
		return;
	}
	struct wall *nw = tui_edit_copy(t->w, lay, -1, err);
	if (!nw) {
		tui_message(t, 1, "not applied: %s", err);
		return;
	}
	tui_edit_snap_loads(nw);
	tui_edit_done(t, nw, what);
}

static void tui_edit_courses_typed(struct tui *t, const char *text)
{
	long n;
	struct wall_layout lay = t->w->layout;
	if (text_parse_long(text, 1, 100000, &n)) {
		tui_message(t, 1, "courses: a whole number from 1 to 100000");
		return;
	}
	lay.courses = (int)n;
	tui_edit_layout(t, &lay, "courses changed");
}

static void tui_edit_per_course_typed(struct tui *t, const char *text)
{
	double v[1];
	struct wall_layout lay = t->w->layout;
	if (tui_edit_numbers(text, v, 1) != 1 || !(v[0] >= 0.5) || v[0] > 1e5) {
		tui_message(t, 1, "blocks per course: a number >= 0.5 (the length is that many block widths)");
		return;
	}
	lay.length = v[0] * lay.block_w;
	tui_edit_layout(t, &lay, "wall length changed");
}

static void tui_edit_block_typed(struct tui *t, const char *text)
{
	double v[2];
	struct wall_layout lay = t->w->layout;
	if (tui_edit_numbers(text, v, 2) != 2 || !(v[0] > 0) || !(v[1] > 0)) {
		tui_message(t, 1, "block size: type 'width,height' in m (both > 0)");
		return;
	}
	lay.block_w = v[0];
	lay.block_h = v[1];
	tui_edit_layout(t, &lay, "block size changed");
}

static void tui_edit_target_typed(struct tui *t, const char *text)
{
	long n;
	if (text_parse_long(text, 1, 1000000000L, &n)) {
		tui_message(t, 1, "sample target: a whole number from 1 to 1e9");
		return;
	}
	tui_run_set_target(t, n);
	tui_message(t, 0, "sample target %ld", n);
}

static void tui_edit_block_size(const struct wall *w, double *bw, double *bh)
{
	if (w->layout.present) {
		*bw = w->layout.block_w;
		*bh = w->layout.block_h;
	} else {
		*bw = 2 * w->mean_size / sqrt(2);
		*bh = w->mean_size / sqrt(2);
	}
}

/* Course and place of a generated id ("c<course>b<k>"), as one
 * number that sorts like the layout's order; -1 for other ids. */
static long tui_edit_order(const char *id)
{
	int c, k, n = 0;
	if (!id || sscanf(id, "c%db%d%n", &c, &k, &n) != 2 || id[n])
		return -1;
	return (long)c * 1000000L + k;
}

/* The last block of (unfinished) nw, a block of the courses put back,
 * moves to its place in the layout's order, before the blocks that are
 * not the layout's: a saved wall keeps its layout (wallfile_save). */
static void tui_edit_to_course(struct wall *nw)
{
	int last = nw->nblocks - 1;
	long o = tui_edit_order(nw->blocks[last].id);
	int at = 0;
	while (at < last) {
		long q = tui_edit_order(nw->blocks[at].id);
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
static struct wall *tui_edit_missing(const struct wall *w, double x, double y)
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

static void tui_edit_add_block(struct tui *t)
{
	double bw, bh;
	const struct wall *w = t->w;
	tui_edit_block_size(w, &bw, &bh);
	double gx = w->layout.present ? w->layout.x0 : 0;
	double gy = w->layout.present ? w->layout.y0 : (w->has_ground ? w->ground_y : 0);
	double x = gx + floor((t->cur_x - gx) / (bw / 2) + 1e-9) * (bw / 2);
	double y = gy + floor((t->cur_y - gy) / bh + 1e-9) * bh;
	double xy[8] = {x, y, x + bw, y, x + bw, y + bh, x, y + bh};
	char id[32];
	struct wall *lay = tui_edit_missing(w, t->cur_x, t->cur_y);
	if (lay) {
		/* a block of the courses, removed: it comes back as it was */
		const struct wall_block *b = &lay->blocks[lay->nblocks - 1];
		struct wall *nw = tui_edit_begin(t);
		char what[128];
		if (nw) {
			struct wall_mark none = {0, 0};
			wall_add_block(nw, b->id, b->xy, b->nv, 0, none);
			tui_edit_to_course(nw);
			snprintf(what, sizeof what, "block %s restored", b->id);
			tui_edit_done(t, nw, what);
		}
		wall_free(lay);
		return;
	}
	for (int k = 1;; k++) {
		int used = 0;
		snprintf(id, sizeof id, "u%d", k);
		for (int b = 0; b < w->nblocks && !used; b++)
			used = !strcmp(w->blocks[b].id, id);
		if (!used)
			break;
	}
	struct wall *nw = tui_edit_begin(t);
	if (!nw)
		return;
	struct wall_mark none = {0, 0};
	wall_add_block(nw, id, xy, 4, 0, none);
	char what[128];
	snprintf(what, sizeof what, "block %s added at (%.3g, %.3g)", id, x, y);
	tui_edit_done(t, nw, what);
}

static void tui_edit_remove_block(struct tui *t)
{
	char err[SW_ERRLEN], what[128];
	int k = tui_wall_block_at(t->w, t->cur_x, t->cur_y);
	if (k < 0 || t->w->blocks[k].fixed) {
		tui_message(t, 1, "no block under the cursor");
		return;
	}
	snprintf(what, sizeof what, "block %s removed", t->w->blocks[k].id);
	struct wall *nw = tui_edit_copy(t->w, NULL, k, err);
	if (!nw) {
		tui_message(t, 1, "%s", err);
		return;
	}
	tui_edit_done(t, nw, what);
}

static void tui_edit_cursor(struct tui *t, int dx, int dy);

/* The block cursor is within a block's size of the wall. */
static int tui_edit_cursor_near(struct tui *t)
{
	if (!isfinite(t->cur_x) || !isfinite(t->cur_y))
		return 0;
	double x = t->cur_x, y = t->cur_y;
	tui_edit_cursor(t, 0, 0);
	return x == t->cur_x && y == t->cur_y;
}

/* Move the block cursor by half a block across, a block up or down; it
 * stays within a block's size of the wall. */
static void tui_edit_cursor(struct tui *t, int dx, int dy)
{
	const struct wall *w = t->w;
	double bw, bh;
	double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
	tui_edit_block_size(w, &bw, &bh);
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *b = &w->blocks[k];
		if (b->fixed)
			continue;
		for (int i = 0; i < b->nv; i++) {
			x0 = fmin(x0, b->xy[2 * i]);
			x1 = fmax(x1, b->xy[2 * i]);
			y0 = fmin(y0, b->xy[2 * i + 1]);
			y1 = fmax(y1, b->xy[2 * i + 1]);
		}
	}
	t->cur_x = fmin(x1 + bw, fmax(x0 - bw, t->cur_x + dx * bw / 2));
	t->cur_y = fmin(y1 + bh, fmax(y0, t->cur_y + dy * bh));
}

/* A click on the wall: the left button selects the block under it (the
 * block cursor goes there), the right one moves the load to the nearest
 * place of the outline (an edit, as the arrows make). */
static void tui_edit_mouse(struct tui *t)
{
	MEVENT ev;
	double x, y;
	if (getmouse(&ev) != OK || !tui_wall_point(ev.y, ev.x, &x, &y) ||
	    ev.x >= t->cols * 55 / 100)
		return;
	if (ev.bstate & (BUTTON1_PRESSED | BUTTON1_CLICKED)) {
		int k = tui_wall_block_at(t->w, x, y);
		if (k < 0) {
			tui_message(t, 0, "no block there");
			return;
		}
		t->cursor_mode = 1;
		t->cur_x = t->w->blocks[k].cx;
		t->cur_y = t->w->blocks[k].cy;
		tui_message(t, 0, "block %s selected: a add, x remove, Tab back",
			    t->w->blocks[k].id);
	} else if (ev.bstate & (BUTTON3_PRESSED | BUTTON3_CLICKED)) {
		int l = tui_edit_point_load(t->w);
		if (l < 0) {
			tui_message(t, 1, "this wall has no point load to move");
			return;
		}
		double at[2] = {x, y};
		if (tui_wall_load_nearest(t->w, t->w->loads[l].dir, at))
			tui_edit_load_at(t, at, NULL);
	}
}

/* ---- the main screen ---- */

void tui_main_init(struct tui *t)
{
	(void)t;
}

enum tui_screen_id tui_main_key(struct tui *t, int ch)
{
	char buf[128];
	const struct wall *w = t->w;
	int nmech = t->run.tally.nmech;

	if (t->prompting) {
		tui_prompt_key(t, ch);
		return TUI_SCREEN_MAIN;
	}
	switch (ch) {
	case 'q':
	case 'Q':
		t->quit = 1;
		break;
	case '?':
		return TUI_SCREEN_HELP;
	case 'H':
		return TUI_SCREEN_HISTORY;
	case ' ':
	case 'p':
		tui_run_pause(t, !t->run.paused);
		tui_message(t, 0, "%s at %ld samples",
			    t->run.paused ? "paused" : "resumed", t->run.done);
		break;
	case 'r':
		tui_run_end(t);
		tui_run_start(t);
		tui_message(t, 0, "reset: sampling again (run %d)", t->runno);
		break;
	case 'n':
		snprintf(buf, sizeof buf, "%ld", t->run.target);
		tui_prompt(t, "sample target", buf, tui_edit_target_typed);
		break;
	case 'm':
		t->mech_sel = (t->mech_sel + 1) % (nmech + 1);
		break;
	case 'M':
		t->mech_sel = (t->mech_sel + nmech) % (nmech + 1);
		break;
	case 'f':
	case 'F': {
		double s = ch == 'f' ? TUI_STEP_MU : -TUI_STEP_MU;
		tui_edit_friction(t, fmax(0, round((w->mu_bed + s) * 1e6) / 1e6),
				  fmax(0, round((w->mu_head + s) * 1e6) / 1e6));
		break;
	}
	case 'g':
		snprintf(buf, sizeof buf, "%.4g,%.4g", w->mu_bed, w->mu_head);
		tui_prompt(t, "friction bed,head", buf, tui_edit_friction_typed);
		break;
	case 'e':
		tui_edit_depth(t, w->depth + TUI_STEP_DEPTH, 0);
		break;
	case 'E':
		tui_edit_depth(t, w->depth - TUI_STEP_DEPTH, 0);
		break;
	case 'i':
		tui_edit_depth(t, w->depth, !w->anywhere);
		break;
	case 'u':
		tui_edit_undo(t, 0);
		break;
	case 'U':
	case 18:	/* Ctrl-R */
		tui_edit_undo(t, 1);
		break;
	case KEY_UP:
	case KEY_DOWN:
	case KEY_LEFT:
	case KEY_RIGHT:
	case 'h':
	case 'j':
	case 'k':
	case 'l': {
		int dx = ch == KEY_RIGHT || ch == 'l' ? 1 : ch == KEY_LEFT || ch == 'h' ? -1 : 0;
		int dy = ch == KEY_UP || ch == 'k' ? 1 : ch == KEY_DOWN || ch == 'j' ? -1 : 0;
		if (t->cursor_mode)
			tui_edit_cursor(t, dx, dy);
		else
			tui_edit_load_step(t, dx, dy);
		break;
	}
	case 'd':
		tui_edit_load_turn(t, 1);
		break;
	case 'D':
		tui_edit_load_turn(t, -1);
		break;
	case 'P': {
		int l = tui_edit_point_load(w);
		if (l < 0) {
			tui_message(t, 1, "this wall has no point load");
			break;
		}
		snprintf(buf, sizeof buf, "%.4g,%.4g,%.3g,%.3g", w->loads[l].at[0],
			 w->loads[l].at[1], w->loads[l].dir[0], w->loads[l].dir[1]);
		tui_prompt(t, "load x,y[,dx,dy]", buf, tui_edit_load_typed);
		break;
	}
	case 'c':
		snprintf(buf, sizeof buf, "%d", w->layout.courses);
		tui_prompt(t, "courses", buf, tui_edit_courses_typed);
		break;
	case 'L':
		snprintf(buf, sizeof buf, "%.4g",
			 w->layout.block_w > 0 ? w->layout.length / w->layout.block_w : 0);
		tui_prompt(t, "blocks per course", buf, tui_edit_per_course_typed);
		break;
	case 'w':
		snprintf(buf, sizeof buf, "%.4g,%.4g", w->layout.block_w,
			 w->layout.block_h);
		tui_prompt(t, "block width,height (m)", buf, tui_edit_block_typed);
		break;
	case 'b': {
		struct wall_layout lay = w->layout;
		lay.bond = lay.bond == BOND_RUNNING ? BOND_STACK : BOND_RUNNING;
		tui_edit_layout(t, &lay, lay.bond == BOND_RUNNING ? "running bond"
								  : "stack bond");
		break;
	}
	case 'B': {
		struct wall_layout lay = w->layout;
		lay.first_half = !lay.first_half;
		tui_edit_layout(t, &lay, lay.first_half ? "first course starts half"
							: "first course starts full");
		break;
	}
	case '\t':
		t->cursor_mode = !t->cursor_mode;
		/* the cursor stays where it was; placed on a block the first
		 * time (and when the wall changed so that it is far off) */
		if (t->cursor_mode && !tui_edit_cursor_near(t)) {
			for (int k = 0; k < w->nblocks; k++)
				if (!w->blocks[k].fixed) {
					t->cur_x = w->blocks[k].cx;
					t->cur_y = w->blocks[k].cy;
					break;
				}
		}
		tui_message(t, 0, t->cursor_mode ? "block cursor: arrows move it, a adds, x removes, Tab back"
						 : "arrows move the load");
		break;
	case 'a':
		if (!t->cursor_mode)
			tui_message(t, 1, "Tab first: the block cursor");
		else
			tui_edit_add_block(t);
		break;
	case 'x':
	case KEY_DC:
		if (!t->cursor_mode)
			tui_message(t, 1, "Tab first: the block cursor");
		else
			tui_edit_remove_block(t);
		break;
	case 's':
		tui_file_save(t);
		break;
	case 'o':
		tui_file_open(t);
		break;
	case 'R':
		tui_file_report(t);
		break;
	case KEY_MOUSE:
		tui_edit_mouse(t);
		break;
	case 12:	/* Ctrl-L */
		clearok(curscr, TRUE);
		break;
	default:
		break;
	}
	return TUI_SCREEN_MAIN;
}

static void tui_main_bar(struct tui *t, int y, const char *text)
{
	int attr = t->colors ? COLOR_PAIR(6) : A_REVERSE;
	attron(attr);
	move(y, 0);
	for (int c = 0; c < t->cols; c++)
		addch(' ');
	tui_text(y, 0, t->cols, text);
	attroff(attr);
}

void tui_main_draw(struct tui *t)
{
	const struct wall *w = t->w;
	char buf[PATH_MAX + 512];
	int R = t->rows, C = t->cols;
	const char *csv = strrchr(t->run.csv, '/');
	csv = csv ? csv + 1 : t->run.csv;

	char dtext[32];
	if (w->anywhere)
		snprintf(dtext, sizeof dtext, "points anywhere");
	else
		snprintf(dtext, sizeof dtext, "depth %.3g", w->depth);
	/* the title: the numbers always; the name's middle cut to fit,
	 * the samples file only when there is room (H shows it) */
	char rest[160], name[256], nm[256], file[PATH_MAX + 8];
	snprintf(rest, sizeof rest, "%s | %s %.3g/%.3g | %s | run %d %s",
		 undo_modified(&t->undo) ? " *" : "", tui_mu(t), w->mu_bed,
		 w->mu_head, dtext, t->runno, tui_run_state(t));
	snprintf(name, sizeof name, "%s",
		 w->name ? w->name : (w->path ? w->path : "wall"));
	snprintf(file, sizeof file, " | %s", csv[0] ? csv : "(no samples file)");
	int room = C - 12 - tui_cols(rest);	/* " slipwall | " */
	if ((int)(tui_cols(name) + tui_cols(file)) > room)
		file[0] = 0;
	tui_abbrev(t, nm, sizeof nm, name, room);
	snprintf(buf, sizeof buf, " slipwall | %s%s%s", nm, rest, file);
	tui_main_bar(t, 0, buf);

	int top = 1, bottom = R - 2;	/* panes: rows top .. bottom-1 */
	int lw = C * 55 / 100;
	int rx = lw + 1, rw = C - rx;
	int sh = 12;
	tui_wall_draw(t, top, 0, bottom - top, lw);
	for (int y = top; y < bottom; y++)
		tui_put(t, y, lw, "│", "|");
	sh = tui_stats_draw(t, top, rx, bottom - top - 5, rw) + 1;
	tui_hist_draw(t, top + sh, rx, bottom - top - sh, rw);

	if (t->prompting) {
		/* the end of a long text stays in view */
		const char *p = t->pbuf;
		int room = C - 3 - (int)strlen(t->plabel) - 2;
		while ((int)strlen(p) > room && *p)
			p++;
		snprintf(buf, sizeof buf, "%s: %s", t->plabel, p);
		attron(A_BOLD);
		tui_text(R - 2, 0, C - 1, buf);
		attroff(A_BOLD);
		int len = (int)strlen(buf);
		if (len < C - 1) {
			attron(A_REVERSE);
			mvaddch(R - 2, len, ' ');
			attroff(A_REVERSE);
		}
	} else if (t->msg[0]) {
		/* a message longer than the line (paths) takes the row
		 * above too, and the middle of the rest is cut */
		int attr = t->msg_err ? (t->colors ? COLOR_PAIR(5) : A_BOLD) : 0;
		if (attr)
			attron(attr);
		if (tui_cols(t->msg) > C) {
			char rest[sizeof t->msg + 8];
			const char *s = tui_skip(t->msg, C);
			move(R - 3, 0);
			clrtoeol();
			tui_text(R - 3, 0, C, t->msg);
			tui_abbrev(t, rest, sizeof rest, s, C);
			tui_text(R - 2, 0, C, rest);
		} else {
			tui_text(R - 2, 0, C, t->msg);
		}
		if (attr)
			attroff(attr);
	}
	/* the keys that work now, as many as fit */
	static const char *const kprompt[] = {"Enter accept", "Esc cancel",
					      "Ctrl-U clear", NULL};
	static const char *const kcursor[] = {
		"Tab load mode", "arrows/hjkl cursor", "a add", "x remove",
		"u undo", "? help", "q quit", NULL};
	static const char *const kmain[] = {
		"q quit", "? help", "spc pause", "u undo", "H history",
		"f/F mu", "e/E depth", "arrows load", "s save", "o open",
		"m mech", NULL};
	const char *const *keys = t->prompting ? kprompt
				  : t->cursor_mode ? kcursor : kmain;
	int len = 0;
	buf[0] = 0;
	for (int i = 0; keys[i]; i++) {
		int k = (int)strlen(keys[i]);
		if (len + 1 + k > C - 1)
			break;
		len += snprintf(buf + len, sizeof buf - (size_t)len, " %s", keys[i]);
	}
	tui_main_bar(t, R - 1, buf);
}
