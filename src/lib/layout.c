/*
 * layout.c - generated walls: courses of rectangular blocks.
 *
 * Called by the wall-file reader (and by tests or the workbench) between
 * wall_new() and wall_finish(): it appends the blocks that w->layout
 * describes and owns nothing.  Course c (1-based) spans
 * y0 + (c-1) h .. y0 + c h.  A course is a row of full blocks, preceded by
 * a half block when it starts "half", and closed by a cut block when the
 * last full block would pass the wall's end.  With running bond the
 * courses alternate half/full starts; with stack bond every course is
 * like course 1.
 *
 * Every joint position is computed as x0 + u * w from its whole number of
 * half blocks u, never by summing widths, so the vertices of one course
 * and the next fall on exactly the same numbers where they should, and a
 * saved wall reloads bit for bit.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "slipwall/layout.h"

/* A few bytes of layout can ask for any number of blocks.  Refuse more
 * than ten times the largest wall the program is meant for (10,000
 * blocks, docs/reliability.md): a million-block layout took 8 s and
 * 700 MB just to check, and no LP of that size is solvable here.  The
 * fuzz build (scripts/fuzz.sh) lowers the limit to keep executions fast. */
#ifndef LAYOUT_MAX_BLOCKS
#define LAYOUT_MAX_BLOCKS 100000
#endif

/* a cut block narrower than this fraction of a block width is absorbed
 * (course_joints): 20 micrometres on a 0.20 m block, far below a
 * mason's cut and above the contact search's resolution; the layouts of
 * bench/scan.py, whose lengths are whole millimetres on blocks of at
 * most 0.6 m, never leave so small a cut */
#define LAYOUT_SLIVER 1e-4

/* Does course c (1-based) start with a half block? */
static int course_starts_half(const struct wall_layout *l, int c)
{
	if (l->bond == BOND_STACK)
		return l->first_half;
	return (c % 2 == 1) ? l->first_half : !l->first_half;
}

/* The joints of one course: x positions e[0] < e[1] < ... < e[n] relative
 * to x0 (e[0] = 0, e[n] = length).  Returns n, the number of blocks; fills
 * e only when it is not NULL. */
static int course_joints(const struct wall_layout *l, int half, double *e)
{
	/* a cut block narrower than LAYOUT_SLIVER of a block is no block: the
	 * block before it reaches the wall's end instead.  A length of
	 * 0.40000001 with blocks 0.20 wide made a cut block 1e-8 m wide,
	 * below the contact search's resolution: it rested on no joint and
	 * every sample was `no_equilibrium` (docs/wall-format.md) */
	double tol = fmax(1e-9 * fmax(l->block_w, l->length),
			  LAYOUT_SLIVER * l->block_w);
	int n = 0;
	if (e)
		e[0] = 0;
	for (long k = 0;; k++) {
		/* right edge of block k: (k + 1) full widths, less a half when
		 * the course starts with a half block */
		double x = ((double)k + (half ? 0.5 : 1.0)) * l->block_w;
		if (x >= l->length - tol)
			x = l->length;
		n++;
		if (e)
			e[n] = x;
		if (x == l->length)
			return n;
	}
}

enum sw_status layout_generate(struct wall *w, struct wall_mark mark,
			       char *err)
{
	const struct wall_layout *l = &w->layout;
	char where[SW_ERRLEN / 2];

	wall_where(w, mark, where, sizeof where);
	if (!(l->block_w > 0) || !isfinite(l->block_w) ||
	    !(l->block_h > 0) || !isfinite(l->block_h))
		return sw_fail(err, SW_EINPUT,
			       "%slayout block size must be two positive numbers (got %g x %g)",
			       where, l->block_w, l->block_h);
	if (l->courses < 1)
		return sw_fail(err, SW_EINPUT,
			       "%slayout must have at least 1 course (got %d)",
			       where, l->courses);
	if (!isfinite(l->length))
		return sw_fail(err, SW_EINPUT,
			       "%slayout length must be a finite number", where);
	if (!(l->length >= l->block_w / 2))
		return sw_fail(err, SW_EINPUT,
			       "%slayout length %g is shorter than half a block (%g)",
			       where, l->length, l->block_w / 2);
	if (!isfinite(l->x0) || !isfinite(l->y0))
		return sw_fail(err, SW_EINPUT,
			       "%slayout origin must be finite", where);
	/* a course has at most length / w + 2 blocks: a bound first (a
	 * course of 1e300 blocks is not counted one by one), then the
	 * count itself (a stack of blocks as wide as the wall is one block
	 * a course, where the bound said three) */
	double per_course = floor(l->length / l->block_w) + 2;
	double count = per_course * l->courses;
	if (per_course <= LAYOUT_MAX_BLOCKS) {
		/* course 1 and course 2 (odd and even courses differ in
		 * running bond only) */
		double n1 = course_joints(l, course_starts_half(l, 1), NULL);
		double n2 = course_joints(l, course_starts_half(l, 2), NULL);
		count = n1 * ((l->courses + 1) / 2) + n2 * (l->courses / 2);
	}
	if (per_course > LAYOUT_MAX_BLOCKS)
		return sw_fail(err, SW_EINPUT,
			       "%slayout would make more than %d blocks in one "
			       "course (length %g, block width %g), the most "
			       "it may make in all", where, LAYOUT_MAX_BLOCKS,
			       l->length, l->block_w);
	if (count > LAYOUT_MAX_BLOCKS)
		return sw_fail(err, SW_EINPUT,
			       "%slayout would make %.0f blocks (at most %d)",
			       where, count, LAYOUT_MAX_BLOCKS);

	double *e = sw_xmalloc(sizeof(double) * ((size_t)per_course + 2));
	for (int c = 1; c <= l->courses; c++) {
		int n = course_joints(l, course_starts_half(l, c), e);
		double ylo = l->y0 + (c - 1) * l->block_h;
		double yhi = l->y0 + c * l->block_h;
		for (int k = 0; k < n; k++) {
			double xlo = l->x0 + e[k], xhi = l->x0 + e[k + 1];
			double xy[8] = {xlo, ylo, xhi, ylo, xhi, yhi, xlo, yhi};
			char id[40];
			snprintf(id, sizeof id, "c%db%d", c, k + 1);
			wall_add_block(w, id, xy, 4, 0, mark);
		}
	}
	free(e);
	return SW_OK;
}
