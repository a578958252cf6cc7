/*
 * draw.c - a sample's random stream and its draw; see draw.h.
 *
 * Random streams: sample i of a run with seed s draws from its own
 * xoshiro256** generator, whose 256-bit state splitmix64 expands from
 * the sample's 64-bit seed mix(mix(s) ^ i).  Every step is a bijection of
 * 64 bits, so two samples of one run never share a stream (GSL's
 * mt19937, used before, kept 32 bits of that seed: a million samples
 * held about 116 identical pairs).  The generator is written here, not
 * taken from GSL, for that seeding: GSL's generators take an unsigned
 * long seed and expand it their own way.
 *
 * Friction (docs/method.md, "Friction as a random variable"): a
 * lognormal of mean mu and coefficient of variation v has log-mean
 * ln mu - s^2 / 2 and log-deviation s, s^2 = ln(1 + v^2); it is drawn by
 * inversion (GSL's normal quantile) so that one uniform makes one
 * friction, and a sample's frictions come after all its positions.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_cdf.h>

#include "slipwall/draw.h"
#include "slipwall/sys.h"

/* splitmix64's finaliser: a bijection of 64 bits */
static uint64_t mix(uint64_t z)
{
	z += 0x9e3779b97f4a7c15ULL;
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return z ^ (z >> 31);
}

void draw_rng_seed(struct draw_rng *r, unsigned long seed, unsigned long index)
{
	uint64_t x = mix(mix((uint64_t)seed) ^ (uint64_t)index);
	/* splitmix64 expands the sample seed into the state: its outputs
	 * mix(x), mix(x + g), ... (each a bijection of x, so the state is
	 * never all zero) */
	for (int k = 0; k < 4; k++) {
		r->s[k] = mix(x);
		x += 0x9e3779b97f4a7c15ULL;
	}
}

static uint64_t rotl(uint64_t x, int k)
{
	return (x << k) | (x >> (64 - k));
}

uint64_t draw_rng_next(struct draw_rng *r)
{
	uint64_t *s = r->s;
	uint64_t out = rotl(s[1] * 5, 7) * 9, t = s[1] << 17;
	s[2] ^= s[0];
	s[3] ^= s[1];
	s[1] ^= s[2];
	s[0] ^= s[3];
	s[2] ^= t;
	s[3] = rotl(s[3], 45);
	return out;
}

double draw_rng_uniform(struct draw_rng *r)
{
	return (double)(draw_rng_next(r) >> 11) * 0x1.0p-53;
}

/* A uniform in (0, 1), never 0: the normal quantile's argument */
static double open_uniform(struct draw_rng *r)
{
	return ((double)(draw_rng_next(r) >> 11) + 0.5) * 0x1.0p-53;
}

void draw_init(struct sample_draw *d, const struct wall *w)
{
	size_t m = (size_t)w->nifaces;
	d->nifaces = w->nifaces;
	d->xi = sw_xcalloc(2 * m + 1, sizeof(double));
	d->mu = sw_xcalloc(m + 1, sizeof(double));
}

void draw_free(struct sample_draw *d)
{
	free(d->xi);
	free(d->mu);
	memset(d, 0, sizeof *d);
}

void draw_copy(struct sample_draw *dst, const struct sample_draw *src)
{
	size_t m = (size_t)src->nifaces;
	memcpy(dst->xi, src->xi, sizeof(double) * 2 * m);
	memcpy(dst->mu, src->mu, sizeof(double) * m);
}

void draw_mean(struct sample_draw *d, const struct wall *w)
{
	for (int k = 0; k < w->nifaces; k++) {
		d->xi[2 * k] = 0;
		d->xi[2 * k + 1] = 1;
		d->mu[k] = wall_iface_mu(w, k);
	}
}

double draw_lognormal(double mean, double cov, double u)
{
	double s2 = log1p(cov * cov);
	return mean * exp(sqrt(s2) * gsl_cdf_ugaussian_Pinv(u) - s2 / 2);
}

void draw_make(struct sample_draw *d, const struct wall *w,
	       unsigned long seed, unsigned long index, double depth)
{
	struct draw_rng r;
	draw_rng_seed(&r, seed, index);
	if (depth < 0)
		depth = w->depth;
	for (int k = 0; k < w->nifaces; k++) {
		/* two uniforms per interface, always drawn, so that the
		 * positions are continuous in the depth (common random
		 * numbers for --fit-depth) */
		double u1 = draw_rng_uniform(&r), u2 = draw_rng_uniform(&r);
		if (w->anywhere) {
			d->xi[2 * k] = fmin(u1, u2);
			d->xi[2 * k + 1] = fmax(u1, u2);
		} else {
			d->xi[2 * k] = depth * u1;
			d->xi[2 * k + 1] = 1 - depth * u2;
		}
	}
	for (int k = 0; k < w->nifaces; k++)
		d->mu[k] = w->mu_cov > 0 ?
			   fmin(draw_lognormal(wall_iface_mu(w, k), w->mu_cov,
					       open_uniform(&r)),
				WALL_FRICTION_MAX) :
			   wall_iface_mu(w, k);
}

void draw_table_free(struct draw_table *t)
{
	free(t->xi);
	free(t->mu);
	memset(t, 0, sizeof *t);
}

void draw_from_table(struct sample_draw *d, const struct wall *w,
		     const struct draw_table *t, long i)
{
	size_t m = (size_t)w->nifaces;
	memcpy(d->xi, t->xi + 2 * m * (size_t)i, sizeof(double) * 2 * m);
	for (int k = 0; k < w->nifaces; k++)
		d->mu[k] = t->mu ? t->mu[m * (size_t)i + (size_t)k] :
			   wall_iface_mu(w, k);
}
