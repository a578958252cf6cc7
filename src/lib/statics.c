/*
 * statics.c - assembly of the equilibrium operator; see statics.h for the
 * conventions.  Every entry of A is computed in statics_column(); the
 * kinematic rates are its transpose applied to velocities.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "statics.h"

void statics_init(struct statics *s, const struct wall *w)
{
	memset(s, 0, sizeof *s);
	s->w = w;
	s->nrows = 3 * w->nfree;
	s->ncols = 3 * w->nifaces;
	s->F = w->mean_weight;
	s->L = w->mean_size;
	double ref = 0;
	int nloaded = 0;
	for (int l = 0; l < w->nloads; l++) {
		if (w->loads[l].kind == LOAD_POINT) {
			ref += w->loads[l].magnitude;
			nloaded++;
		} else {
			ref += w->loads[l].magnitude * w->total_weight;
			nloaded += w->nfree;
		}
	}
	/* the mean reference live force per loaded block: every force is
	 * divided by it before a lever multiplies it, so that a moment is
	 * finite whenever the forces are (a load of 1e308 N at a lever of
	 * 2 m overflows; 2 at 2 does not) */
	double unit = ref > 0 ? ref / nloaded : s->F;
	s->S = s->F / unit;
	s->fL = sw_xcalloc((size_t)s->nrows + 1, sizeof(double));
	s->fD = sw_xcalloc((size_t)s->nrows + 1, sizeof(double));
	s->q = sw_xcalloc(4 * (size_t)w->nifaces + 1, sizeof(double));
	s->xi = sw_xcalloc(2 * (size_t)w->nifaces + 1, sizeof(double));

	/* f_L at lambda_scaled = 1 is S times the reference load, over F,
	 * that is the reference load over `unit` */
	for (int l = 0; l < w->nloads; l++) {
		const struct wall_load *ld = &w->loads[l];
		for (int k = 0; k < w->nblocks; k++) {
			const struct wall_block *b = &w->blocks[k];
			double f, px, py;
			/* finite: wall_finish checked the magnitude times the
			 * whole wall's weight */
			if (!wall_load_on(w, ld, k, &f, &px, &py))
				continue;
			f /= unit;
			double fx = f * ld->dir[0], fy = f * ld->dir[1];
			/* the lever over L: F * L overflows on a wall whose
			 * weights and sizes are large (1e290 N and 1e20 m) */
			double m = (px - b->cx) / s->L * fy -
				   (py - b->cy) / s->L * fx;
			s->fL[3 * b->eq] += fx;
			s->fL[3 * b->eq + 1] += fy;
			s->fL[3 * b->eq + 2] += m;
		}
	}
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *b = &w->blocks[k];
		if (!b->fixed)
			s->fD[3 * b->eq + 1] = -b->weight / s->F;
	}
	s->mu = sw_xcalloc((size_t)w->nifaces + 1, sizeof(double));
	struct sample_draw d;
	draw_init(&d, w);
	draw_mean(&d, w);
	statics_set_draw(s, &d);
	draw_free(&d);
}

void statics_free(struct statics *s)
{
	free(s->fL);
	free(s->fD);
	free(s->q);
	free(s->xi);
	free(s->mu);
	memset(s, 0, sizeof *s);
}

void statics_set_draw(struct statics *s, const struct sample_draw *d)
{
	const struct wall *w = s->w;
	for (int k = 0; k < w->nifaces; k++) {
		const struct wall_interface *it = &w->ifaces[k];
		s->mu[k] = d->mu[k];
		for (int e = 0; e < 2; e++) {
			double x = d->xi[2 * k + e];
			s->xi[2 * k + e] = x;
			s->q[4 * k + 2 * e] = it->p1[0] + x * (it->p2[0] - it->p1[0]);
			s->q[4 * k + 2 * e + 1] = it->p1[1] + x * (it->p2[1] - it->p1[1]);
		}
	}
}

int statics_column(const struct statics *s, int j, int *rows, double *vals)
{
	const struct wall *w = s->w;
	const struct wall_interface *it = &w->ifaces[j / 3];
	int kind = j % 3;
	const double *e = kind == 2 ? it->t : it->n;
	/* the shear's moment does not depend on where along the joint it
	 * acts; take p1 */
	const double *p = kind == 2 ? it->p1 : &s->q[4 * (j / 3) + 2 * kind];
	int n = 0;
	const int body[2] = {it->b, it->a};
	const double sign[2] = {1, -1};
	for (int side = 0; side < 2; side++) {
		const struct wall_block *B = &w->blocks[body[side]];
		if (B->fixed)
			continue;
		double m = (p[0] - B->cx) * e[1] - (p[1] - B->cy) * e[0];
		rows[n] = 3 * B->eq;
		vals[n++] = sign[side] * e[0];
		rows[n] = 3 * B->eq + 1;
		vals[n++] = sign[side] * e[1];
		rows[n] = 3 * B->eq + 2;
		vals[n++] = sign[side] * m / s->L;
	}
	return n;
}

int statics_edge_column(const struct statics *s, int k, int e, int sgn,
			int *rows, double *vals)
{
	int trows[6];
	double tvals[6];
	int n = statics_column(s, 3 * k + e, rows, vals);
	int tn = statics_column(s, 3 * k + 2, trows, tvals);
	double mu = s->mu[k];
	/* the shear's column has the normal's rows, in the same order */
	for (int i = 0; i < n && i < tn; i++)
		vals[i] += (sgn ? -mu : mu) * tvals[i];
	return n;
}

double statics_rate(const struct statics *s, int j, const double *v)
{
	int rows[6];
	double vals[6], r = 0;
	int n = statics_column(s, j, rows, vals);
	for (int i = 0; i < n; i++)
		r += vals[i] * v[rows[i]];
	return r;
}
