/*
 * wedit.h - the computations behind the workbench's edits of a wall: an
 * editable copy, a layout changed, a block put back or added, the load
 * moved along the wall's outline.  No terminal: the workbench (src/tui/
 * tui_edit.c) calls these and applies what they return.
 *
 * A finished wall is read-only (wall.h), so an edit is a new wall:
 * wedit_copy() gives an unfinished copy, the caller changes it, and
 * wall_finish() (which may refuse it: a block left hanging, a load off
 * the wall) makes it usable.  Every function here that returns a wall
 * returns such an unfinished copy, owned by the caller; w is never
 * changed.
 *
 * Generated blocks are the layout's ("c<course>b<k>", layout.h); a
 * layout edit regenerates them and keeps every other block.
 *
 * Load stations: points spread along the parts of the free blocks' edges
 * that touch no other body (the wall's outline), about one per mean
 * block size, each with its edge's outward normal.  The arrow keys move
 * a point load from station to station.
 */
#ifndef SLIPWALL_WEDIT_H
#define SLIPWALL_WEDIT_H

#include <stddef.h>

#include "slipwall/wall.h"

/* An unfinished copy of finished w: without the generated ground (which
 * wall_finish adds again), marks cleared.  regen (or NULL): a layout
 * whose blocks replace the generated ones; skip: a block index to leave
 * out (-1: none).  NULL + err when regen cannot be generated. */
struct wall *wedit_copy(const struct wall *w, const struct wall_layout *regen,
		       int skip, char *err);

/* A copy of w with layout lay (w must have one): the courses generated
 * again, and each point load that is then off the wall (fewer courses,
 * a shorter wall) moved to the nearest station of the new outline.
 * NULL + err on failure. */
struct wall *wedit_layout(const struct wall *w, const struct wall_layout *lay,
			 char *err);

/* A copy of w with a block added under (x, y): the layout's block there
 * if w lacks it (removed earlier; it comes back with its id, in its
 * place among the courses), else a new block "u<k>" of the layout's
 * size on its grid (half a block across, a course up).  what (len
 * bytes) names the edit ("block c3b2 restored").  NULL + err on
 * failure. */
struct wall *wedit_add_block(const struct wall *w, double x, double y,
			    char *what, size_t len, char *err);

/* The index of w's first point load, or -1. */
int wedit_point_load(const struct wall *w);
/* The block (not the generated ground) that holds (x, y), or -1. */
int wedit_block_at(const struct wall *w, double x, double y);
/* A block's width and height: the layout's, else from the mean size. */
void wedit_block_size(const struct wall *w, double *bw, double *bh);

/* The bounding box {x0, y0, x1, y1} of w's blocks but the generated
 * ground (free_only: of its free blocks); infinite when there is none. */
void wedit_bounds(const struct wall *w, int free_only, double box[4]);
/* Move (x, y) by dx half blocks across and dy blocks up, kept within a
 * block's size of the free blocks' bounding box (above it, not below
 * the lowest). */
void wedit_cursor(const struct wall *w, double *x, double *y, int dx, int dy);
/* Turn dir by sense eighths of a turn (+1 counter-clockwise), from the
 * nearest eighth; components below 1e-12 become 0. */
void wedit_turn(double dir[2], int sense);

/* Move at to the next station in direction (dx, dy) (an arrow key: one
 * of them 0, the other +-1); 0 (at unchanged) if there is none. */
int wedit_load_step(const struct wall *w, int dx, int dy, double at[2]);
/* Move at to the nearest station, preferring faces that a load of
 * direction dir acts across; 0 if the wall has none. */
int wedit_load_nearest(const struct wall *w, const double dir[2], double at[2]);

#endif
