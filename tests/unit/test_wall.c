/*
 * test_wall.c - building and validating the model: weights, the ground,
 * which block a point load acts on, and the refusals of wall_finish.
 */
#include <string.h>

#include "slipwall/wall.h"
#include "tap.h"
#include "walls.h"

static void weights(void)
{
	struct wall *w = wall_new();
	tw_rect(w, "A", 0, 0, 0.2, 0.1);
	w->has_ground = 1;
	tw_point_load(w, 0, 0.05, 1, 0);
	tw_finish(w);
	/* 19620 N/m^3 x 0.02 m^2 x 0.10 m = 39.24 N */
	tap_near(w->blocks[0].weight, 39.24, 1e-12, "0.2 x 0.1 block weighs 39.24 N");
	tap_near(w->blocks[0].cx, 0.1, 1e-15, "centroid x 0.1");
	tap_near(w->blocks[0].cy, 0.05, 1e-15, "centroid y 0.05");
	tap_ok(w->nblocks == 2 && w->ground_block == 1 && w->blocks[1].fixed,
	       "the ground is a fixed block after the wall's blocks");
	tap_ok(w->nifaces == 1 && w->ifaces[0].kind == JOINT_BED &&
	       fabs(w->ifaces[0].len - 0.2) < 1e-15,
	       "one bed interface of length 0.2 with the ground");
	struct wall *c = wall_copy(w);
	tap_ok(c->nifaces == 1 && c->blocks[0].weight == w->blocks[0].weight &&
	       strcmp(c->blocks[0].id, "A") == 0 && c->blocks[0].xy != w->blocks[0].xy,
	       "wall_copy is deep and equal");
	wall_free(c);
	wall_free(w);
}

/* Two blocks side by side, a load on their shared face: it acts on the
 * block it pushes into. */
static void load_block(void)
{
	for (int dir = -1; dir <= 1; dir += 2) {
		struct wall *w = wall_new();
		tw_rect(w, "L", 0, 0, 0.2, 0.1);
		tw_rect(w, "R", 0.2, 0, 0.2, 0.1);
		w->has_ground = 1;
		tw_point_load(w, 0.2, 0.05, dir, 0);
		tw_point_load(w, 0.4, 0.05, 1, 0);	/* a pull on the end face */
		tw_finish(w);
		tap_ok(w->loads[0].block == (dir > 0 ? 1 : 0),
		       "load on the shared face pushing %s acts on %s",
		       dir > 0 ? "+x" : "-x", dir > 0 ? "R" : "L");
		tap_ok(w->loads[1].block == 1, "a pull on the free end face acts on R");
		wall_free(w);
	}
}

static void expect_error(struct wall *w, const char *what, const char *sub)
{
	char err[SW_ERRLEN] = "";
	enum sw_status st = wall_finish(w, err);
	tap_ok(st == SW_EINPUT && strstr(err, sub) != NULL, "%s: \"%s\"", what, err);
	wall_free(w);
}

static void refusals(void)
{
	struct wall *w = wall_new();
	w->has_ground = 1;
	expect_error(w, "empty wall", "has no blocks");

	w = wall_new();
	tw_rect(w, "A", 0, 0, 1, 1);
	w->has_ground = 1;
	expect_error(w, "no load", "no live load");

	w = wall_new();
	tw_rect(w, "A", 0, 0, 1, 1);
	tw_point_load(w, 0, 0.5, 1, 0);
	expect_error(w, "no support", "no support");

	w = wall_new();
	tw_rect(w, "A", 0, 0, 1, 1);
	tw_rect(w, "float", 3, 3, 1, 1);
	w->has_ground = 1;
	tw_point_load(w, 0, 0.5, 1, 0);
	expect_error(w, "a floating block", "'float' touches nothing");

	w = wall_new();
	tw_rect(w, "A", 0, 0, 1, 1);
	tw_rect(w, "B", 0.5, 0, 1, 1);
	w->has_ground = 1;
	tw_point_load(w, 0, 0.5, 1, 0);
	expect_error(w, "overlapping blocks", "overlaps");

	w = wall_new();
	tw_rect(w, "A", 0, 0, 1, 1);
	w->has_ground = 1;
	tw_point_load(w, 5, 0.5, 1, 0);
	expect_error(w, "load outside", "outside every block");

	/* live loads that cancel on every block: two at one point, and a
	 * pair that cancels in force but not in moment, which is a load */
	w = wall_new();
	tw_rect(w, "A", 0, 0, 1, 1);
	w->has_ground = 1;
	tw_point_load(w, 0.3, 0.5, 1, 0.2);
	tw_point_load(w, 0.3, 0.5, -1, -0.2);
	expect_error(w, "loads that cancel", "the live loads cancel");
	w = wall_new();
	tw_rect(w, "A", 0, 0, 1, 1);
	w->has_ground = 1;
	tw_point_load(w, 0, 0.2, 1, 0);
	tw_point_load(w, 1, 0.8, -1, 0);
	char err[SW_ERRLEN] = "";
	tap_ok(wall_finish(w, err) == SW_OK,
	       "a couple on one block is a load: \"%s\"", err);
	wall_free(w);
	/* ... and loads that cancel over the wall but not on each block */
	w = wall_new();
	tw_rect(w, "A", 0, 0, 1, 1);
	tw_rect(w, "B", 1, 0, 1, 1);
	w->has_ground = 1;
	tw_point_load(w, 0, 0.5, 1, 0);
	tw_point_load(w, 2, 0.5, -1, 0);
	err[0] = 0;
	tap_ok(wall_finish(w, err) == SW_OK,
	       "loads that cancel over the wall, not on each block: \"%s\"",
	       err);
	wall_free(w);

	w = wall_new();
	double cw[8] = {0, 0, 0, 1, 1, 1, 1, 0};
	struct wall_mark mk = {7, 5};
	wall_add_block(w, "cw", cw, 4, 0, mk);
	w->has_ground = 1;
	w->path = sw_xstrdup("x.yaml");
	tw_point_load(w, 0, 0.5, 1, 0);
	expect_error(w, "clockwise block, with its place in the file",
		     "x.yaml:7:5: block 'cw' is clockwise");

	w = wall_new();
	tw_rect(w, "A", 0, 0, 1, 1);
	tw_rect(w, "A", 0, 1, 1, 1);
	w->has_ground = 1;
	tw_point_load(w, 0, 0.5, 1, 0);
	expect_error(w, "duplicate ids", "'A' is used twice");
}

/* Blocks that hang (wall_hanging, wall_clamp_joints, wall_clamp_blocks):
 * a 3 x 3 stack of 0.3 x 0.15 m blocks with the middle one of the first
 * course left out (tests/data/stack-gap.yaml).  B22 rests on no joint;
 * B32 rests on B22 only, so no chain of joints carries it either; their
 * clamp is their four side joints.  With the gap filled nothing hangs. */
static void hanging(void)
{
	for (int filled = 0; filled < 2; filled++) {
		struct wall *w = wall_new();
		for (int c = 1; c <= 3; c++)
			for (int b = 1; b <= 3; b++) {
				if (c == 1 && b == 2 && !filled)
					continue;
				char id[8];
				snprintf(id, sizeof id, "B%d%d", c, b);
				tw_rect(w, id, 0.3 * (b - 1), 0.15 * (c - 1), 0.3, 0.15);
			}
		w->has_ground = 1;
		tw_point_load(w, 0, 0.075, 1, 0);
		tw_finish(w);
		int blk = -1, above = -1, k[64], n = wall_clamp_joints(w, k);
		int side = 1, hang = wall_hanging(w, &blk, &above);
		for (int i = 0; i < n; i++) {
			const struct wall_interface *f = &w->ifaces[k[i]];
			const char *a = w->blocks[f->a].id, *b = w->blocks[f->b].id;
			side &= fabs(f->n[1]) < 1e-12 &&
				(!strcmp(a, "B22") || !strcmp(b, "B22") ||
				 !strcmp(a, "B32") || !strcmp(b, "B32"));
		}
		/* the clamped blocks, marked over a mark already set on B11 */
		char mark[16] = {0}, want[16] = {0};
		int b11 = -1, fits = w->nblocks <= (int)sizeof mark;
		for (int b = 0; fits && b < w->nblocks; b++) {
			const char *id = w->blocks[b].id;
			b11 = !strcmp(id, "B11") ? b : b11;
			want[b] = !strcmp(id, "B11") ||
				  (!filled && (!strcmp(id, "B22") ||
					       !strcmp(id, "B32")));
		}
		if (b11 >= 0)
			mark[b11] = 1;
		int nmark = fits ? wall_clamp_blocks(w, mark) : -1;
		tap_ok(b11 >= 0 && nmark == (filled ? 0 : 2) &&
		       !memcmp(mark, want, sizeof mark),
		       "%s: the clamped blocks marked (%d), the mark set "
		       "before kept", filled ? "without the gap" : "over the gap",
		       nmark);
		if (filled) {
			tap_ok(hang == 0 && above == 0 && n == 0 &&
			       wall_clamp_joints(w, NULL) == 0,
			       "the stack without its gap: nothing hangs, no clamp");
		} else {
			tap_ok(hang == 1 && !strcmp(w->blocks[blk].id, "B22") &&
			       above == 1 && n == 4 && side &&
			       wall_clamp_joints(w, NULL) == 4,
			       "a stack over a gap: B22 rests on no joint, B32 "
			       "only on it; the clamp is the 4 side joints of "
			       "B22 and B32 (%d, %d above)", n, above);
			char text[160];
			tap_ok(wall_hanging_text(w, text, sizeof text) &&
			       !strcmp(text, "block B22 rests on no joint below "
				       "it, and 1 other block only on it"),
			       "its warning names both: %s", text);
		}
		wall_free(w);
	}
}

int main(void)
{
	weights();
	load_block();
	refusals();
	hanging();
	return tap_done();
}
