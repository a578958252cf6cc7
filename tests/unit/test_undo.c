/*
 * test_undo.c - the undo/redo stacks of an edited wall: each undo gives
 * back the wall before the edit, redo the one after, a new edit forgets
 * the redo stack, the oldest steps go beyond the cap, and the modified
 * mark follows the version (it goes when undone back to the saved wall).
 */
#include <stdlib.h>

#include "slipwall/undo.h"
#include "slipwall/wall.h"
#include "tap.h"

/* A finished one-block wall on the ground with friction mu. */
static struct wall *slab(double mu)
{
	char err[SW_ERRLEN];
	struct wall *w = wall_new();
	struct wall_mark m = {0, 0};
	double xy[8] = {0, 0, 1, 0, 1, 0.5, 0, 0.5};
	struct wall_load ld = {0};
	w->path = sw_xstrdup("slab.yaml");
	w->mu_bed = w->mu_head = mu;
	w->has_ground = 1;
	wall_add_block(w, "s", xy, 4, 0, m);
	ld.kind = LOAD_POINT;
	ld.at[0] = 0;
	ld.at[1] = 0.25;
	ld.dir[0] = 1;
	ld.magnitude = 1;
	wall_add_load(w, &ld);
	if (wall_finish(w, err) != SW_OK) {
		tap_diag("%s", err);
		exit(1);
	}
	return w;
}

/* Apply an edit: the new wall replaces cur. */
static struct wall *edit(struct undo *u, struct wall *cur, double mu)
{
	undo_edit(u, cur);
	wall_free(cur);
	return slab(mu);
}

int main(void)
{
	struct undo u;
	undo_init(&u, 60);
	struct wall *cur = slab(0);

	tap_ok(!undo_modified(&u), "a loaded wall is not modified");
	tap_ok(undo_undo(&u, cur) == NULL, "nothing to undo at first");
	for (int i = 1; i <= 70; i++)
		cur = edit(&u, cur, i);
	tap_ok(undo_modified(&u), "an edited wall is modified");
	tap_ok(u.npast == 60, "the stack keeps the last 60 steps (%d)", u.npast);

	int good = 1;
	for (int i = 69; i >= 10; i--) {
		struct wall *p = undo_undo(&u, cur);
		if (!p || p->mu_bed != i || !p->finished) {
			good = 0;
			break;
		}
		wall_free(cur);
		cur = p;
	}
	tap_ok(good, "60 undos give back mu 69 .. 10, finished walls");
	tap_ok(undo_undo(&u, cur) == NULL, "then nothing more to undo");

	struct wall *n = undo_redo(&u, cur);
	tap_ok(n && n->mu_bed == 11, "redo gives mu 11 back");
	wall_free(cur);
	cur = n;
	cur = edit(&u, cur, 100);
	tap_ok(undo_redo(&u, cur) == NULL, "an edit forgets the redo stack");
	n = undo_undo(&u, cur);
	tap_ok(n && n->mu_bed == 11, "undo after the edit: mu 11");
	wall_free(cur);
	cur = n;

	/* the mark: saved at mu 11; an edit sets it, undo clears it */
	undo_saved(&u);
	tap_ok(!undo_modified(&u), "saved: not modified");
	cur = edit(&u, cur, 12);
	tap_ok(undo_modified(&u), "edited after the save: modified");
	n = undo_undo(&u, cur);
	wall_free(cur);
	cur = n;
	tap_ok(cur->mu_bed == 11 && !undo_modified(&u),
	       "undone back to the saved wall: not modified");
	n = undo_redo(&u, cur);
	wall_free(cur);
	cur = n;
	tap_ok(cur->mu_bed == 12 && undo_modified(&u), "redone: modified again");

	undo_reset(&u);
	tap_ok(!undo_modified(&u) && u.npast == 0 && u.nfuture == 0,
	       "a wall opened: empty stacks, not modified");
	wall_free(cur);
	undo_free(&u);
	return tap_done();
}
