/*
 * tui_edit.c - the edits of the wall, key by key: friction, contact
 * depth, the load (moved, turned, typed), the layout (courses, length,
 * block size, bond), blocks added and removed, undo and redo.  The main
 * screen (tui_home.c) maps its keys to the tui_edit_key_* functions.
 *
 * The wall of a running sampler is read-only (wall.h), so every edit
 * builds a new wall: the library (wedit.h) makes an unfinished copy of
 * the current one, the key changes it, and tui_edit_apply() finishes it
 * and hands it to tui_edit_set_wall(), which ends the current run (its
 * samples file stays), starts a new one and hands the wall to the solve
 * thread (tui_solve.c).  A copy that does not finish (a removed block
 * leaves another hanging, a load off the wall) is thrown away with its
 * message on the message line; the current wall stays.
 *
 * tui_edit_apply() also pushes the wall it replaces on the undo stack
 * (src/lib/undo.c): u and U switch back and forth the same way, as new
 * runs of the same seed.  No key changes the wall without a prompt or a
 * way back.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/text.h"
#include "slipwall/wedit.h"
#include "tui.h"

#define TUI_STEP_MU 0.05
#define TUI_STEP_DEPTH 0.05

/* t->lock for t->w: the two joints that associative friction locks
 * (wall_friction_lock_text, the command line's words), or "".  The
 * title marks such a wall (tui_home_title), and the message
 * of the edit or the opening that made it says why (docs/workbench.md,
 * "Friction that locks").  And t->hang: the blocks that rest on no
 * joint (wall_hanging_text) and those that overhang what they rest on
 * (wall_overhang_text), either or both, or "": the message says that
 * too, as `check` warns of each (docs/workbench.md, "Blocks that
 * hang"). */
void tui_edit_lock(struct tui *t)
{
	char joints[sizeof t->lock - 96];
	char hang[(sizeof t->hang - 64) / 2], over[sizeof hang];
	t->lock[0] = t->hang[0] = 0;
	if (!t->w)
		return;
	if (wall_friction_lock_text(t->w, joints, sizeof joints))
		snprintf(t->lock, sizeof t->lock, "%s lock under associative "
			 "friction: loads may be the lock's, not the wall's "
			 "(docs/method.md)", joints);
	int h = wall_hanging_text(t->w, hang, sizeof hang);
	int o = wall_overhang_text(t->w, over, sizeof over);
	if (h || o)
		snprintf(t->hang, sizeof t->hang, "%s%s%s: samples may be "
			 "rejected as hanging (docs/method.md)", h ? hang : "",
			 h && o ? "; " : "", o ? over : "");
}

/* The message line as it is, with the lock's and the hanging blocks'
 * warnings first when the wall has them; shown as an error, so that it
 * stands out. */
void tui_edit_lock_message(struct tui *t)
{
	if (!t->lock[0] && !t->hang[0])
		return;
	char m[sizeof t->msg];
	snprintf(m, sizeof m, "%s", t->msg);
	tui_message(t, 1, "warning: %s%s%s | %s", t->lock,
		    t->lock[0] && t->hang[0] ? "; " : "", t->hang, m);
}

void tui_edit_set_wall(struct tui *t, struct wall *nw)
{
	tui_run_end(t);
	wall_free(t->w);
	t->w = nw;
	tui_edit_lock(t);
	t->has_std = t->has_gil = t->solve_done = 0;
	t->mech_sel = 0;
	tui_run_start(t);
	if (t->solve)
		tui_solve_wall(t->solve, nw);
	t->solve_t0 = sys_now();
}

/* Finish nw and switch to it (the current wall goes on the undo stack;
 * `what` names the edit in the message and the history); on failure
 * show the message, free nw and keep the current wall. */
static int tui_edit_apply(struct tui *t, struct wall *nw, const char *what)
{
	char err[SW_ERRLEN];
	if (wall_finish(nw, err) != SW_OK) {
		tui_message(t, 1, "not applied: %s", err);
		wall_free(nw);
		return -1;
	}
	undo_edit(&t->undo, t->w);
	snprintf(t->next_what, sizeof t->next_what, "%.*s",
		 (int)sizeof t->next_what - 1, what);	/* cut to fit */
	tui_edit_set_wall(t, nw);
	return 0;
}

/* u and U (Ctrl-R): back to the wall before the last edit, or forward
 * again; a new run on it, with the same seed, so the same samples. */
void tui_edit_key_undo(struct tui *t, int ch)
{
	int redo = ch != 'u';
	struct wall *p = redo ? undo_redo(&t->undo, t->w)
			      : undo_undo(&t->undo, t->w);
	if (!p) {
		tui_message(t, 0, "nothing to %s", redo ? "redo" : "undo");
		return;
	}
	snprintf(t->next_what, sizeof t->next_what, "%s", redo ? "redo" : "undo");
	tui_edit_set_wall(t, p);
	tui_message(t, 0, "%s: sampling again (run %d; %d more to undo, %d to redo)",
		    redo ? "redone" : "undone", t->runno, t->undo.npast,
		    t->undo.nfuture);
	tui_edit_lock_message(t);
}

/* Copy, let the caller change, apply; with a message on success. */
static struct wall *tui_edit_begin(struct tui *t)
{
	char err[SW_ERRLEN];
	struct wall *nw = wedit_copy(t->w, NULL, -1, err);
	if (!nw)
		tui_message(t, 1, "%s", err);
	return nw;
}

static void tui_edit_done(struct tui *t, struct wall *nw, const char *what)
{
	if (tui_edit_apply(t, nw, what) == 0) {
		tui_message(t, 0, "%s: sampling again (run %d)", what, t->runno);
		tui_edit_lock_message(t);
	}
}

/* Parse "a" or "a,b" (also spaces); returns how many numbers, each a
 * decimal as in the wall file (text_parse_double), or -1. */
static int tui_edit_numbers(const char *s, double *v, int max)
{
	int n = 0;
	for (;;) {
		s += strspn(s, " ,\t");
		if (!*s)
			return n;
		size_t len = strcspn(s, " ,\t");
		char tok[64];
		if (n == max || len >= sizeof tok)
			return -1;
		memcpy(tok, s, len);
		tok[len] = 0;
		if (text_parse_double(tok, &v[n]))
			return -1;
		n++;
		s += len;
	}
}

/* ---- friction, depth ---- */

static void tui_edit_friction(struct tui *t, double bed, double head)
{
	char what[128];
	if (bed < 0 || head < 0) {
		tui_message(t, 1, "friction must be >= 0");
		return;
	}
	if (bed == t->w->mu_bed && head == t->w->mu_head) {
		/* F at 0, or the same value typed: no new run of the same
		 * wall */
		tui_message(t, 0, "friction is already bed %.3g, head %.3g",
			    bed, head);
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

/* f and F: both frictions a step up or down. */
void tui_edit_key_friction(struct tui *t, int ch)
{
	const struct wall *w = t->w;
	double s = ch == 'f' ? TUI_STEP_MU : -TUI_STEP_MU;
	tui_edit_friction(t, fmax(0, round((w->mu_bed + s) * 1e6) / 1e6),
			  fmax(0, round((w->mu_head + s) * 1e6) / 1e6));
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

/* v's prompt: the friction's coefficient of variation per joint and
 * sample (docs/method.md, "Friction as a random variable"); 0 is fixed
 * friction. */
static void tui_edit_cov_typed(struct tui *t, const char *text)
{
	double v[1];
	if (tui_edit_numbers(text, v, 1) != 1 || !(v[0] >= 0) ||
	    !(v[0] <= WALL_COV_MAX)) {
		tui_message(t, 1, "friction cov: type a number from 0 to 1 "
			    "(0: fixed friction)");
		return;
	}
	if (v[0] == t->w->mu_cov) {
		tui_message(t, 0, "friction cov is already %.3g", v[0]);
		return;
	}
	struct wall *nw = tui_edit_begin(t);
	if (!nw)
		return;
	nw->mu_cov = v[0];
	char what[128];
	if (v[0] > 0)
		snprintf(what, sizeof what, "friction random, cov %.3g", v[0]);
	else
		snprintf(what, sizeof what, "friction fixed (cov 0)");
	tui_edit_done(t, nw, what);
}

static void tui_edit_depth(struct tui *t, double d, int anywhere)
{
	char what[128];
	d = round(fmin(0.5, fmax(0, d)) * 1e6) / 1e6;
	if (d == t->w->depth && anywhere == t->w->anywhere) {
		/* e at 0.5, E at 0: no new run of the same wall */
		tui_message(t, 0, "contact depth is already %.3g (0 to 0.5)", d);
		return;
	}
	struct wall *nw = tui_edit_begin(t);
	if (!nw)
		return;
	nw->depth = d;
	nw->anywhere = anywhere;
	if (anywhere)
		snprintf(what, sizeof what, "contact points anywhere");
	else
		snprintf(what, sizeof what, "contact depth %.3g", nw->depth);
	tui_edit_done(t, nw, what);
}

/* e and E: the depth a step up or down; i: points anywhere or not. */
void tui_edit_key_depth(struct tui *t, int ch)
{
	const struct wall *w = t->w;
	if (ch == 'i')
		tui_edit_depth(t, w->depth, !w->anywhere);
	else
		tui_edit_depth(t, w->depth + (ch == 'e' ? TUI_STEP_DEPTH
						      : -TUI_STEP_DEPTH), 0);
}

/* ---- the load ---- */

/* Where load l of w acts, in words: "pulls on the right face", "pushes
 * on the top face".  The face is the side of the point with no block
 * (probed a hundredth of a block away); the load pulls when it points
 * away from the wall, pushes when it points into it. */
static void tui_edit_load_face(const struct wall *w, int l, char *buf,
			       size_t len)
{
	static const char *const side[4] = {"right", "left", "top", "bottom"};
	static const double n[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
	const struct wall_load *ld = &w->loads[l];
	double e = 0.01 * w->mean_size;
	int face = -1, nfaces = 0;
	for (int k = 0; k < 4; k++) {
		int out = wedit_block_at(w, ld->at[0] + e * n[k][0],
					 ld->at[1] + e * n[k][1]);
		int in = wedit_block_at(w, ld->at[0] - e * n[k][0],
					ld->at[1] - e * n[k][1]);
		if ((out < 0 || w->blocks[out].fixed) && in >= 0 &&
		    !w->blocks[in].fixed) {
			face = k;
			nfaces++;
		}
	}
	double d = face < 0 ? 0 : ld->dir[0] * n[face][0] + ld->dir[1] * n[face][1];
	const char *acts = d > 1e-9 ? "pulls on" : d < -1e-9 ? "pushes on" : "acts along";
	if (face < 0 || nfaces > 1)	/* a corner, a sloped face */
		snprintf(buf, len, "%s the wall",
			 face < 0 ? "acts on" : "acts at a corner of");
	else
		snprintf(buf, len, "%s the %s face", acts, side[face]);
}

/* The message after an edit of the load: the face it acts on and
 * whether it pulls or pushes, when that changed (h on the right face
 * can carry a pull round to a push on the left: docs/workbench.md,
 * "Edits"). */
static void tui_edit_load_done(struct tui *t, struct wall *nw, int l,
			       const char *what)
{
	char was[64], now[64];
	tui_edit_load_face(t->w, l, was, sizeof was);
	if (tui_edit_apply(t, nw, what) != 0)
		return;
	tui_edit_load_face(t->w, l, now, sizeof now);	/* finished: nw */
	if (strcmp(was, now))
		tui_message(t, 0, "load now %s (was: %s): sampling again (run %d)",
			    now, was, t->runno);
	else
		tui_message(t, 0, "%s: sampling again (run %d)", what, t->runno);
}

static void tui_edit_load_at(struct tui *t, const double at[2],
			     const double *dir)
{
	char what[128];
	int l = wedit_point_load(t->w);
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
	tui_edit_load_done(t, nw, l, what);
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

void tui_edit_load_step(struct tui *t, int dx, int dy)
{
	int l = wedit_point_load(t->w);
	if (l < 0) {
		tui_message(t, 1, "this wall has no point load to move");
		return;
	}
	double at[2] = {t->w->loads[l].at[0], t->w->loads[l].at[1]};
	if (!wedit_load_step(t->w, dx, dy, at)) {
		tui_message(t, 0, "no place for the load further that way");
		return;
	}
	tui_edit_load_at(t, at, NULL);
}

void tui_edit_load_to(struct tui *t, double x, double y)
{
	int l = wedit_point_load(t->w);
	if (l < 0) {
		tui_message(t, 1, "this wall has no point load to move");
		return;
	}
	double at[2] = {x, y};
	if (wedit_load_nearest(t->w, t->w->loads[l].dir, at))
		tui_edit_load_at(t, at, NULL);
}

/* d and D: the load turns an eighth counter-clockwise or clockwise. */
void tui_edit_key_turn(struct tui *t, int ch)
{
	int l = wedit_point_load(t->w);
	if (l < 0)
		l = 0;		/* a body load turns too */
	struct wall *nw = tui_edit_begin(t);
	if (!nw)
		return;
	struct wall_load *ld = &nw->loads[l];
	wedit_turn(ld->dir, ch == 'd' ? 1 : -1);
	char what[96];
	snprintf(what, sizeof what, "load direction (%.3g, %.3g)", ld->dir[0],
		 ld->dir[1]);
	tui_edit_load_done(t, nw, l, what);
}

/* ---- the layout ---- */

/* A layout edit moves a point load that acted on an end face of the
 * courses to the same place of the new end face: the same course, the
 * same height within it (wedit_layout alone keeps the old x: inside a
 * longer wall, or snapped elsewhere on a shorter one).  And the wall's
 * name goes: it often states the old geometry ("pulled at course 4");
 * the title then shows the file's name (docs/workbench.md, "Editing"). */
static void tui_edit_layout_follow(const struct wall *w, struct wall *nw)
{
	const struct wall_layout *o = &w->layout, *n = &nw->layout;
	double tol = 1e-6 * fmax(o->block_w, o->block_h);
	for (int l = 0; l < w->nloads && l < nw->nloads; l++) {
		const struct wall_load *ld = &w->loads[l];
		if (ld->kind != LOAD_POINT || nw->loads[l].kind != LOAD_POINT)
			continue;
		double x;
		if (fabs(ld->at[0] - (o->x0 + o->length)) < tol)
			x = n->x0 + n->length;		/* the right end */
		else if (fabs(ld->at[0] - o->x0) < tol)
			x = n->x0;			/* the left end */
		else
			continue;
		double c = (ld->at[1] - o->y0) / o->block_h;	/* course */
		if (!(c > 0) || c >= n->courses)
			continue;
		nw->loads[l].at[0] = x;
		nw->loads[l].at[1] = n->y0 + c * n->block_h;
	}
	free(nw->name);
	nw->name = NULL;
}

static void tui_edit_layout(struct tui *t, const struct wall_layout *lay,
			    const char *what)
{
	char err[SW_ERRLEN];
	if (!t->w->layout.present) {
		tui_message(t, 1, "this wall has no generated layout to change");
		return;
	}
	struct wall *nw = wedit_layout(t->w, lay, err);
	if (!nw) {
		tui_message(t, 1, "not applied: %s", err);
		return;
	}
	tui_edit_layout_follow(t->w, nw);
	tui_edit_done(t, nw, what);
}

/* b: running or stack bond; B: the first course starts half or full. */
void tui_edit_key_bond(struct tui *t, int ch)
{
	struct wall_layout lay = t->w->layout;
	if (ch == 'b') {
		lay.bond = lay.bond == BOND_RUNNING ? BOND_STACK : BOND_RUNNING;
		tui_edit_layout(t, &lay, lay.bond == BOND_RUNNING ? "running bond"
								  : "stack bond");
	} else {
		lay.first_half = !lay.first_half;
		tui_edit_layout(t, &lay, lay.first_half ? "first course starts half"
							: "first course starts full");
	}
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
	/* the same blocks per course (to the half block): a length kept
	 * in metres would end the courses in slivers */
	double per = lay.block_w > 0 ? round(2 * lay.length / lay.block_w) / 2 : 0;
	if (per >= 0.5)
		lay.length = per * v[0];
	lay.block_w = v[0];
	lay.block_h = v[1];
	tui_edit_layout(t, &lay, "block size changed");
}

/* g, P, c, L, w: the value typed on the prompt line, from its current
 * one. */
void tui_edit_key_prompt(struct tui *t, int ch)
{
	const struct wall *w = t->w;
	char buf[128];
	int l;
	if ((ch == 'c' || ch == 'L' || ch == 'w') && !w->layout.present) {
		/* say it before the prompt, as b and B do */
		tui_message(t, 1, "this wall has no generated layout to change");
		return;
	}
	switch (ch) {
	case 'g':
		snprintf(buf, sizeof buf, "%.4g,%.4g", w->mu_bed, w->mu_head);
		tui_prompt(t, "friction bed,head", buf, tui_edit_friction_typed);
		break;
	case 'v':
		snprintf(buf, sizeof buf, "%.4g", w->mu_cov);
		tui_prompt(t, "friction cov (0..1, 0: fixed)", buf,
			   tui_edit_cov_typed);
		break;
	case 'P':
		l = wedit_point_load(w);
		if (l < 0) {
			tui_message(t, 1, "this wall has no point load");
			break;
		}
		snprintf(buf, sizeof buf, "%.4g,%.4g,%.3g,%.3g", w->loads[l].at[0],
			 w->loads[l].at[1], w->loads[l].dir[0], w->loads[l].dir[1]);
		tui_prompt(t, "load x,y[,dx,dy]", buf, tui_edit_load_typed);
		break;
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
	}
}

/* ---- blocks ---- */

static void tui_edit_add_block(struct tui *t)
{
	char err[SW_ERRLEN], what[128];
	struct wall *nw = wedit_add_block(t->w, t->cur_x, t->cur_y, what,
					  sizeof what, err);
	if (!nw) {
		tui_message(t, 1, "%s", err);
		return;
	}
	tui_edit_done(t, nw, what);
}

static void tui_edit_remove_block(struct tui *t)
{
	char err[SW_ERRLEN], what[128];
	int k = wedit_block_at(t->w, t->cur_x, t->cur_y);
	if (k < 0 || t->w->blocks[k].fixed) {
		tui_message(t, 1, "no block under the cursor");
		return;
	}
	snprintf(what, sizeof what, "block %s removed", t->w->blocks[k].id);
	struct wall *nw = wedit_copy(t->w, NULL, k, err);
	if (!nw) {
		tui_message(t, 1, "%s", err);
		return;
	}
	tui_edit_done(t, nw, what);
}

/* a: a block added under the block cursor; x, Delete: removed. */
void tui_edit_key_block(struct tui *t, int ch)
{
	if (!t->cursor_mode)
		tui_message(t, 1, "Tab first: the block cursor");
	else if (ch == 'a')
		tui_edit_add_block(t);
	else
		tui_edit_remove_block(t);
}
