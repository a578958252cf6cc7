/*
 * statics.h - the equilibrium operator A and its transpose.
 *
 * For a wall and a choice of contact points (two per interface, at
 * parameters xi_a < xi_b along p1 -> p2), the equilibrium of the free
 * blocks reads
 *
 *     A x + lambda f_L + f_D = 0,     x = (N_a1, N_b1, T_1, ..., T_m),
 *
 * with 3 rows per free block (force x, force y, moment about the
 * centroid) and 3 columns per interface k: column 3k is the normal force
 * at q_a, 3k+1 at q_b, 3k+2 the shear.  A force e at p that body a
 * exerts on body b enters b's rows as (e_x, e_y, (p - c_b) x e) and a's
 * rows with the opposite sign.  The compatibility operator is A^T: for a
 * vector v of block velocities (u, v, omega per free block), (A^T v)_j is
 * the opening rate n . Delta(q) of column j's point, or the slip rate
 * t . Delta of the interface.  Both come from statics_column(), so statics
 * and kinematics cannot disagree.
 *
 * Scaling: the operator is in scaled units so that walls in N and kN,
 * in mm and km, give LPs of the same conditioning.  Forces are divided
 * by F = the mean free-block weight, lengths by L = the mean block size,
 * and the load factor by S (lambda = S * lambda_scaled, S = F / the mean
 * reference live force per loaded block).  The rows are then O(1).
 */
#ifndef SLIPWALL_STATICS_H
#define SLIPWALL_STATICS_H

#include "slipwall/draw.h"
#include "slipwall/wall.h"

struct statics {
	const struct wall *w;	/* borrowed, finished */
	int nrows;		/* 3 * nfree */
	int ncols;		/* 3 * nifaces */
	double F, L, S;		/* force, length and load-factor scales */
	double *fL, *fD;	/* nrows each, scaled: live and dead loads */
	double *q;		/* 4 * nifaces: q_a (x, y), q_b (x, y) */
	double *xi;		/* 2 * nifaces: xi_a, xi_b */
	double *mu;		/* nifaces: each interface's friction */
};

void statics_init(struct statics *s, const struct wall *w);
void statics_free(struct statics *s);

/* A sample's draw: its contact points (xi[2k], xi[2k+1] for interface
 * k) and its friction (mu[k]).  statics_init sets the classical contact
 * and the wall's mean friction (draw_mean). */
void statics_set_draw(struct statics *s, const struct sample_draw *d);

/* The non-zeros of column j of A (scaled): at most 6; rows are 0-based
 * equation numbers.  Returns the count. */
int statics_column(const struct statics *s, int j, int *rows, double *vals);

/* The column of the edge n + mu t (sgn 0) or n - mu t (sgn 1) of the
 * friction cone at point e (0: q_a, 1: q_b) of interface k: the normal
 * force's column plus +-mu times the shear's (the same rows).  At most
 * 6 non-zeros; returns the count. */
int statics_edge_column(const struct statics *s, int k, int e, int sgn,
			int *rows, double *vals);

/* (A^T v)_j for scaled velocities v (nrows entries). */
double statics_rate(const struct statics *s, int j, const double *v);

#endif
