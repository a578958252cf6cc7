/*
 * draw.h - a sample's random input: where each joint's two contact
 * points are, and each joint's friction coefficient.
 *
 * Sample i of a run with seed s is a function of (s, i) alone: its own
 * random stream (struct draw_rng) makes its draw (draw_make), so that a
 * sample's answer does not depend on the thread or MPI rank that
 * computed it.  A draw is carried whole: by the record (record.h), the
 * samples file (runlog.h: its xi and, with random friction, mu columns),
 * the MPI wire and the replay of a samples file (struct draw_table).
 * The engine (sample.h) reads the contact points and the friction of a
 * sample from its draw, never from the wall.
 *
 * docs/method.md ("The random contact", "Friction as a random
 * variable") has the distributions; docs/statistics.md what they do to
 * the collapse load's.
 */
#ifndef SLIPWALL_DRAW_H
#define SLIPWALL_DRAW_H

#include <stdint.h>

#include "slipwall/wall.h"

/* One sample's random stream: xoshiro256** (Blackman & Vigna), its state
 * expanded by splitmix64 from the sample's full 64-bit seed, itself a
 * bijective mix of (run seed, index).  Distinct indices of one run give
 * distinct streams (their first outputs already differ). */
struct draw_rng {
	uint64_t s[4];
};
void draw_rng_seed(struct draw_rng *r, unsigned long seed,
		   unsigned long index);
uint64_t draw_rng_next(struct draw_rng *r);
/* A uniform double in [0, 1), 53 random bits. */
double draw_rng_uniform(struct draw_rng *r);

struct sample_draw {
	int nifaces;
	double *xi;	/* 2 * nifaces: xi_a, xi_b of each interface, the
			 * contact points as fractions of its length */
	double *mu;	/* nifaces: each interface's friction coefficient */
};

/* A draw sized for w (only w->nifaces is read: a record of a wall
 * known by its sizes has one), zero-filled: draw_mean, draw_make or
 * draw_from_table fill it. */
void draw_init(struct sample_draw *d, const struct wall *w);
void draw_free(struct sample_draw *d);
/* dst = src; both made by draw_init for the same wall. */
void draw_copy(struct sample_draw *dst, const struct sample_draw *src);
/* The classical contact and every interface at its mean friction
 * (wall_iface_mu): the draw of a single-solution method. */
void draw_mean(struct sample_draw *d, const struct wall *w);

/* The draw of sample `index` of a run with `seed`: depends on (seed,
 * index) only, drawn from that sample's stream.  First the positions,
 * two uniforms u1, u2 per interface in interface order: with depth d (<
 * 0: the wall's), xi_a = d u1 and xi_b = 1 - d u2; with
 * contacts.positions: anywhere, the sorted pair (u1, u2).  The same two
 * uniforms are drawn per interface whatever d (common random numbers).
 * Then, only when the wall's friction has a coefficient of variation
 * (w->mu_cov > 0), one uniform per interface, in interface order, for
 * its friction: lognormal with mean wall_iface_mu and that coefficient
 * of variation.  So the positions of a sample are the same whatever the
 * friction's spread, and a wall without one draws exactly what it drew
 * before friction could be random. */
void draw_make(struct sample_draw *d, const struct wall *w,
	       unsigned long seed, unsigned long index, double depth);

/* The lognormal friction of mean `mean` and coefficient of variation
 * `cov` (> 0) at the uniform u in (0, 1): mean exp(s z - s^2 / 2), z the
 * standard normal quantile of u, s^2 = ln(1 + cov^2). */
double draw_lognormal(double mean, double cov, double u);

/* Draws read back from a samples file, to replay them: rows of 2 *
 * nifaces positions, and rows of nifaces frictions or NULL when the
 * file has none (then each sample's friction is the wall's mean). */
struct draw_table {
	long rows;
	double *xi;
	double *mu;
};
void draw_table_free(struct draw_table *t);
/* Row i of t into d (made by draw_init for w). */
void draw_from_table(struct sample_draw *d, const struct wall *w,
		     const struct draw_table *t, long i);

#endif
