/*
 * test_geom.c - polygons and contact detection, with counts done by hand.
 */
#include <math.h>
#include <stdlib.h>
#include <time.h>

#include "slipwall/geom.h"
#include "tap.h"
#include "walls.h"

static void polygons(void)
{
	double sq[8] = {0, 0, 1, 0, 1, 1, 0, 1};
	double tri[6] = {0, 0, 2, 0, 0, 1};
	double cx, cy;
	tap_near(geom_area(sq, 4), 1, 1e-15, "unit square area 1");
	tap_near(geom_area(tri, 3), 1, 1e-15, "triangle (0,0) (2,0) (0,1): area 1");
	geom_centroid(tri, 3, &cx, &cy);
	tap_near(cx, 2.0 / 3, 1e-15, "triangle centroid x = 2/3");
	tap_near(cy, 1.0 / 3, 1e-15, "triangle centroid y = 1/3");
	/* far from the origin the centroid must not lose digits */
	double far[8] = {1e6, 1e6, 1e6 + 0.2, 1e6, 1e6 + 0.2, 1e6 + 0.1, 1e6, 1e6 + 0.1};
	geom_centroid(far, 4, &cx, &cy);
	tap_near(cx - 1e6, 0.1, 1e-9, "centroid 1e6 m from the origin: x");
	tap_near(cy - 1e6, 0.05, 1e-9, "centroid 1e6 m from the origin: y");

	/* nor underflow or overflow for polygons of 1e-150 and 1e140 m */
	for (int k = 0; k < 2; k++) {
		double f = k ? 1e140 : 1e-150, t[6] = {0, 0, 2 * f, 0, 0, f};
		geom_centroid(t, 3, &cx, &cy);
		tap_ok(fabs(geom_area(t, 3) / (f * f) - 1) < 1e-15 &&
		       fabs(cx / f - 2.0 / 3) < 1e-15 &&
		       fabs(cy / f - 1.0 / 3) < 1e-15,
		       "the triangle at %g times its size: area and centroid "
		       "scale", f);
	}

	double cw[8] = {0, 0, 0, 1, 1, 1, 1, 0};
	double lshape[12] = {0, 0, 2, 0, 2, 1, 1, 1, 1, 2, 0, 2};
	double bowtie[8] = {0, 0, 1, 1, 1, 0, 0, 1};
	/* {5/2} star, counter-clockwise: 90, 234, 18, 162, 306 degrees */
	double star[10] = {0, 1, -0.588, -0.809, 0.951, 0.309, -0.951, 0.309, 0.588, -0.809};
	double colin[10] = {0, 0, 0.5, 0, 1, 0, 1, 1, 0, 1};
	double rep[10] = {0, 0, 1, 0, 1, 0, 1, 1, 0, 1};
	tap_ok(geom_check_polygon(sq, 4, 1e-12) == GEOM_OK, "square is OK");
	tap_ok(geom_check_polygon(cw, 4, 1e-12) == GEOM_CLOCKWISE, "clockwise square");
	tap_ok(geom_check_polygon(lshape, 6, 1e-12) == GEOM_NONCONVEX, "L shape is not convex");
	tap_ok(geom_check_polygon(bowtie, 4, 1e-12) == GEOM_DEGENERATE, "bow-tie: zero signed area");
	tap_ok(geom_check_polygon(star, 5, 1e-12) == GEOM_NONCONVEX, "pentagram: all left turns but winds twice");
	tap_ok(geom_check_polygon(colin, 5, 1e-12) == GEOM_OK, "a vertex on an edge is allowed");
	tap_ok(geom_check_polygon(rep, 5, 1e-12) == GEOM_DEGENERATE, "repeated vertex");

	tap_ok(geom_contains(sq, 4, 0.5, 0.5, 1e-12), "centre inside");
	tap_ok(geom_contains(sq, 4, 1, 0.5, 1e-12), "edge point inside (closed)");
	tap_ok(!geom_contains(sq, 4, 1.01, 0.5, 1e-12), "outside");
	double right[8] = {1, 0, 2, 0, 2, 1, 1, 1};
	double over[8] = {0.9, 0, 2, 0, 2, 1, 0.9, 1};
	tap_ok(!geom_overlap(sq, 4, right, 4, 1e-9), "squares sharing an edge do not overlap");
	tap_ok(geom_overlap(sq, 4, over, 4, 1e-9), "squares overlapping by 0.1 overlap");
}

/* geom_prune: the corners of a polygon, whatever vertices lie on its
 * edges and wherever its list starts. */
static void corners(void)
{
	/* the unit square with a vertex in the middle of two edges, its list
	 * starting at one of them, and two consecutive ones on the top */
	double split[16] = {0.5, 0, 1, 0, 1, 0.3, 1, 1, 0.75, 1, 0.25, 1,
			    0, 1, 0, 0};
	double want[8] = {0, 0, 1, 0, 1, 1, 0, 1};
	double out[16];
	int n = geom_prune(split, 8, 1e-12, out);
	int same = n == 4;
	for (int i = 0; same && i < 8; i++)
		same = out[i] == want[i];
	tap_ok(same, "a square with 4 vertices on its edges: its 4 corners, "
	       "from the lower left (got %d)", n);
	/* a vertex off the line by more than the tolerance is a corner */
	double bent[10] = {0, 0, 0.5, -1e-6, 1, 0, 1, 1, 0, 1};
	tap_ok(geom_prune(bent, 5, 1e-9, out) == 5 &&
	       geom_prune(bent, 5, 1e-5, out) == 4,
	       "a vertex 1e-6 off the edge: a corner at tolerance 1e-9, not "
	       "at 1e-5");
	tap_ok(geom_area(out, 4) == 1, "... and the pruned square's area is 1");
}

/* Ferris & Tin-Loi wall 1, by hand: 33 blocks.  Head joints: three
 * courses of 6 blocks (5 joints each) and three of 5 (4 each) = 27.  Bed
 * joints between two courses: the vertical joints of a half-start course
 * are at x = 0.2, 0.6, 1.0, 1.4, 1.8 and of a full course at 0.4, 0.8,
 * 1.2, 1.6, so the shared boundary splits into 10 segments; 5 course
 * pairs give 50.  The ground carries the 6 blocks of course 1.  In all
 * 27 + 50 + 6 = 83. */
static void ferris_tinloi_contacts(void)
{
	struct wall *w = tw_load_file("walls/ferris-tinloi-1.yaml");
	int head = 0, bed = 0, ground = 0;
	double bedlen = 0;
	for (int k = 0; k < w->nifaces; k++) {
		const struct wall_interface *it = &w->ifaces[k];
		if (w->blocks[it->a].fixed || w->blocks[it->b].fixed)
			ground++;
		else if (it->kind == JOINT_HEAD)
			head++;
		else if (it->kind == JOINT_BED) {
			bed++;
			bedlen += it->len;
		}
	}
	tap_ok(w->nfree == 33, "wall 1: 33 blocks (%d)", w->nfree);
	tap_ok(head == 27, "wall 1: 27 head joints (%d)", head);
	tap_ok(bed == 50, "wall 1: 50 bed joints (%d)", bed);
	tap_ok(ground == 6, "wall 1: 6 contacts with the ground (%d)", ground);
	tap_near(bedlen, 5 * 2.0, 1e-12, "bed joints cover 5 x 2.0 m");
	/* every interface: unit normal opposite the outward normal of b,
	 * pointing from a into b */
	int ok = 1;
	for (int k = 0; k < w->nifaces; k++) {
		const struct wall_interface *it = &w->ifaces[k];
		const struct wall_block *a = &w->blocks[it->a];
		double mx = (it->p1[0] + it->p2[0]) / 2, my = (it->p1[1] + it->p2[1]) / 2;
		ok &= (mx - a->cx) * it->n[0] + (my - a->cy) * it->n[1] > 0;
		ok &= fabs(hypot(it->n[0], it->n[1]) - 1) < 1e-12;
		ok &= fabs(it->t[0] * it->n[0] + it->t[1] * it->n[1]) < 1e-12;
	}
	tap_ok(ok, "normals point from a into b, unit, normal to t");
	wall_free(w);
}

/* A 100 x 100 stack-bond wall: 10,000 blocks.  Interfaces: 99 head joints
 * in each of 100 courses, 99 x 100 bed joints, 100 on the ground:
 * 19,900.  The time is printed, not asserted. */
static void large(void)
{
	struct wall *w = tw_layout(0.2, 0.1, 100, 20.0, 0, 0, 0.6);
	tw_point_load(w, 0, 5, 1, 0);
	clock_t t0 = clock();
	tw_finish(w);
	double s = (double)(clock() - t0) / CLOCKS_PER_SEC;
	tap_ok(w->nfree == 10000, "10,000 blocks (%d)", w->nfree);
	tap_ok(w->nifaces == 19900, "19,900 interfaces (%d)", w->nifaces);
	tap_diag("wall_finish of 10,000 blocks: %.3f s", s);
	wall_free(w);
}

/* Far from the origin: the area is taken relative to the polygon (the
 * shoelace of absolute coordinates gave a 0.4 x 0.8 m block at
 * (-1e9, -1e9) an area 400 times too large), and geom_far_vertex says
 * where the coordinates cannot hold the polygon to GEOM_PRECISION_REL. */
static void far_from_origin(void)
{
	static const double at[][2] = {{1e7, 1e7}, {5e5, 4.4e6}, {-1e9, -1e9}};
	for (int k = 0; k < 3; k++) {
		double x = at[k][0], y = at[k][1];
		double r[8] = {x, y, x + 0.5, y, x + 0.5, y + 0.25, x, y + 0.25};
		/* the edges as the doubles hold them: 0.5 and 0.25 are
		 * exact sums, so the area is exactly 0.125 */
		tap_ok(fabs(geom_area(r, 4) - 0.125) < 1e-15, "a 0.5 x 0.25 "
		       "rectangle at (%g, %g): area 0.125", x, y);
		tap_ok(geom_far_vertex(r, 4) == (k == 2 ? 0 : -1),
		       "at (%g, %g): %s", x, y, k == 2 ? "its first vertex is "
		       "too far for 1e-8 of 0.25 m" : "precise enough");
	}
	/* the bound: |x| 2^-52 against 1e-8 of the thickness (0.25 m) */
	double edge = ldexp(GEOM_PRECISION_REL * 0.25, 52);
	double in = ldexp(1, (int)floor(log2(edge))), out = 2 * in;
	double a[8] = {in, 0, in + 0.5, 0, in + 0.5, 0.25, in, 0.25};
	double b[8] = {0, out, 0.5, out, 0.5, out + 0.25, 0, out + 0.25};
	tap_ok(geom_far_vertex(a, 4) == -1 && geom_far_vertex(b, 4) == 0,
	       "x = %g passes, y = %g does not (edge %g)", in, out, edge);
}

int main(void)
{
	far_from_origin();
	polygons();
	corners();
	ferris_tinloi_contacts();
	large();
	return tap_done();
}
