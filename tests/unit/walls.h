/*
 * walls.h - small walls built in code for the engine tests: a block, a
 * stack, a generated layout.  Each returns a finished wall or aborts.
 */
#ifndef SLIPWALL_TEST_WALLS_H
#define SLIPWALL_TEST_WALLS_H

#include <gsl/gsl_rng.h>
#include <stdio.h>
#include <stdlib.h>

#include "slipwall/layout.h"
#include "slipwall/wall.h"
#include "slipwall/wallfile.h"

static inline void tw_finish(struct wall *w)
{
	char err[SW_ERRLEN];
	if (wall_finish(w, err) != SW_OK) {
		fprintf(stderr, "test wall: %s\n", err);
		abort();
	}
}

static inline void tw_rect(struct wall *w, const char *id, double x0,
			   double y0, double bw, double bh)
{
	double xy[8] = {x0, y0, x0 + bw, y0, x0 + bw, y0 + bh, x0, y0 + bh};
	struct wall_mark mk = {0, 0};
	wall_add_block(w, id, xy, 4, 0, mk);
}

static inline void tw_point_load(struct wall *w, double x, double y,
				 double dx, double dy)
{
	struct wall_load ld = {0};
	ld.kind = LOAD_POINT;
	ld.at[0] = x;
	ld.at[1] = y;
	ld.dir[0] = dx;
	ld.dir[1] = dy;
	ld.magnitude = 1;
	wall_add_load(w, &ld);
}

/* The closed-form block: 0.4 m wide, 0.8 m high, on the ground, a
 * horizontal point load of 1 N on its left face at height y (not
 * finished). */
static inline struct wall *tw_block(double y)
{
	struct wall *w = wall_new();
	tw_rect(w, "A", 0, 0, 0.4, 0.8);
	w->has_ground = 1;
	tw_point_load(w, 0, y, 1, 0);
	return w;
}

/* A horizontal body load of magnitude 1 along dx (+1 or -1). */
static inline void tw_body_load_x(struct wall *w, double dx)
{
	struct wall_load ld = {0};
	ld.kind = LOAD_BODY;
	ld.dir[0] = dx;
	ld.magnitude = 1;
	wall_add_load(w, &ld);
}

static inline void tw_body_load(struct wall *w)
{
	tw_body_load_x(w, 1);
}

/* A generated running or stack bond wall on the ground (not finished). */
static inline struct wall *tw_layout(double bw, double bh, int courses,
				     double length, int running, int half,
				     double mu)
{
	struct wall *w = wall_new();
	char err[SW_ERRLEN];
	struct wall_mark mk = {0, 0};
	w->layout.present = 1;
	w->layout.block_w = bw;
	w->layout.block_h = bh;
	w->layout.courses = courses;
	w->layout.length = length;
	w->layout.bond = running ? BOND_RUNNING : BOND_STACK;
	w->layout.first_half = half;
	w->has_ground = 1;
	w->mu_bed = w->mu_head = mu;
	if (layout_generate(w, mk, err) != SW_OK) {
		fprintf(stderr, "test layout: %s\n", err);
		abort();
	}
	return w;
}

/* A random small wall drawn from g (finished): 1-4 courses of 2-4
 * blocks, running or stack bond, friction 0.3-0.9, a body load or a
 * point load on the left face, depth 0-0.5. */
static inline struct wall *tw_random(gsl_rng *g)
{
	double bw = 0.1 + 0.4 * gsl_rng_uniform(g);
	double bh = bw * (0.2 + 0.8 * gsl_rng_uniform(g));
	int courses = 1 + (int)gsl_rng_uniform_int(g, 4);
	int nb = 2 + (int)gsl_rng_uniform_int(g, 3);
	double mu = 0.3 + 0.6 * gsl_rng_uniform(g);
	int running = (int)gsl_rng_uniform_int(g, 2);
	struct wall *w = tw_layout(bw, bh, courses, nb * bw, running, 1, mu);
	if (gsl_rng_uniform(g) < 0.5)
		tw_body_load(w);
	else
		tw_point_load(w, 0, courses * bh * (0.05 + 0.9 * gsl_rng_uniform(g)), 1, 0);
	w->depth = 0.5 * gsl_rng_uniform(g);
	tw_finish(w);
	return w;
}

static inline struct wall *tw_load_file(const char *path)
{
	struct wall *w;
	char err[SW_ERRLEN];
	if (wallfile_load(path, &w, err) != SW_OK) {
		fprintf(stderr, "%s\n", err);
		abort();
	}
	return w;
}

#endif
