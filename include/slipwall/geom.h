/*
 * geom.h - plane geometry of convex polygons and contact detection.
 *
 * Polygons are arrays of 2*nv doubles (x0,y0,x1,y1,...).  Knows nothing of
 * YAML or LPs.  Tolerances are absolute lengths; callers pass one scaled
 * to the block size.
 */
#ifndef SLIPWALL_GEOM_H
#define SLIPWALL_GEOM_H

#include "slipwall/wall.h"

/* Signed area (> 0 for counter-clockwise). */
double geom_area(const double *xy, int nv);
/* Centroid of a polygon of non-zero area. */
void geom_centroid(const double *xy, int nv, double *cx, double *cy);

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

/* 1 if (px,py) lies in the closed convex CCW polygon (within tol). */
int geom_contains(const double *xy, int nv, double px, double py, double tol);
/* 1 if the interiors of two convex polygons overlap by more than tol
 * (separating-axis test). */
int geom_overlap(const double *a, int na, const double *b, int nb, double tol);

/* Find a pair of blocks of w whose interiors overlap by more than tol
 * (grid over bounding boxes, near-linear).  Returns 1 and sets *i < *j,
 * or 0 when no two blocks overlap. */
int geom_find_overlap(const struct wall *w, double tol, int *i, int *j);

/* Find every interface between the blocks of w (shared boundary segments
 * of collinear edges with opposite outward normals, overlap longer than
 * tol).  Supports never touch supports.  Uses a uniform grid over edge
 * bounding boxes, so the cost is linear in the number of edges for walls
 * of similar-sized blocks.  Fills a, b, p1, p2, len, t, n, kind; mu is
 * set from w->mu_bed / w->mu_head by kind (mu_bed for JOINT_OTHER).
 * Returns the count; *out is malloc'd (NULL when 0). */
int geom_contacts(const struct wall *w, double tol,
		  struct wall_interface **out);

#endif
