/*
 * geom.h - plane geometry of convex polygons and contact detection.
 *
 * Polygons are arrays of 2*nv doubles (x0,y0,x1,y1,...).  Knows nothing of
 * YAML or LPs.  Tolerances of single polygons are absolute lengths;
 * the wall-wide searches take them relative to each block's size.
 */
#ifndef SLIPWALL_GEOM_H
#define SLIPWALL_GEOM_H

#include "slipwall/wall.h"

/* Signed area (> 0 for counter-clockwise). */
double geom_area(const double *xy, int nv);
/* Centroid of a polygon of non-zero area. */
void geom_centroid(const double *xy, int nv, double *cx, double *cy);

/* The precision a polygon's coordinates must carry (docs/wall-format.md,
 * "Coordinates far from the origin"): a double near x is exact to its
 * spacing, at most |x| 2^-52, so a vertex at x holds the polygon's
 * dimensions to |x| 2^-52 over its thickness (its area over its largest
 * extent).  That must be at most GEOM_PRECISION_REL: 100 times below the
 * tolerance of contacts and overlaps (1e-6 of a block's size), so every
 * joint found is the one the coordinates mean, and the weights, lever
 * arms and loads are exact to about 1e-8.  Returns the index of the
 * first vertex farther from the origin than that allows, or -1 (also
 * for a polygon of no area, which geom_check_polygon refuses). */
#define GEOM_PRECISION_REL 1e-8
int geom_far_vertex(const double *xy, int nv);
/* The polygon's thickness (its area over its largest extent, as
 * geom_far_vertex reads it) over that extent: 0 for no area. */
double geom_thinness(const double *xy, int nv);

enum geom_shape {
	GEOM_OK,
	GEOM_DEGENERATE,	/* zero area, repeated vertex */
	GEOM_CLOCKWISE,
	GEOM_NONCONVEX,		/* includes self-intersecting */
};
/* Is the polygon a convex counter-clockwise polygon?  Collinear
 * consecutive vertices are allowed (a block may carry a vertex where a
 * neighbour's corner meets its edge). */
enum geom_shape geom_check_polygon(const double *xy, int nv, double tol);
const char *geom_shape_text(enum geom_shape s);

/* The corners of a convex CCW polygon: its vertices without those that
 * lie on the segment between their neighbours (within tol), starting at
 * the lowest (then leftmost) corner, so that the same shape gives the
 * same list whatever redundant vertices it carries and wherever its list
 * starts.  out has room for 2*nv numbers; returns the count (nv, with
 * the polygon copied as it is, when fewer than 3 corners remain). */
int geom_prune(const double *xy, int nv, double tol, double *out);
/* The tolerance of geom_prune relative to the polygon's size. */
#define GEOM_PRUNE_REL 1e-9

/* 1 if (px,py) lies in the closed convex CCW polygon (within tol). */
int geom_contains(const double *xy, int nv, double px, double py, double tol);
/* 1 if the interiors of two convex polygons overlap by more than tol
 * (separating-axis test). */
int geom_overlap(const double *a, int na, const double *b, int nb, double tol);

/* Find a pair of blocks of w whose interiors overlap by more than rel
 * times the size of the smaller of the two (wall_block.size; grid over
 * bounding boxes, near-linear).  Returns 1 and sets *i < *j, or 0 when
 * no two blocks overlap. */
int geom_find_overlap(const struct wall *w, double rel, int *i, int *j);

/* Find every interface between the blocks of w (shared boundary segments
 * of collinear edges with opposite outward normals, overlap longer than
 * the tolerance rel times the smaller block's size).  Edges run between
 * corners (geom_prune), so one shared boundary of two bodies is one
 * interface whatever vertices lie along it.  Supports never touch
 * supports.  Uses a uniform grid over edge
 * bounding boxes, so the cost is linear in the number of edges for walls
 * of similar-sized blocks.  Fills a, b, p1, p2, len, t, n, kind; mu is
 * set from w->mu_bed / w->mu_head by kind (mu_bed for JOINT_OTHER).
 * Returns the count; *out is malloc'd (NULL when 0). */
int geom_contacts(const struct wall *w, double rel,
		  struct wall_interface **out);

#endif
