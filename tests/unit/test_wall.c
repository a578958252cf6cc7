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

int main(void)
{
	weights();
	load_block();
	refusals();
	return tap_done();
}
