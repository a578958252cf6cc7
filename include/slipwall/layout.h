/*
 * layout.h - generated walls: courses of rectangular blocks.
 *
 * Course 1 sits on y0 (the ground, or 0).  With running bond, courses
 * alternate between starting with a half block and a full block
 * (`first_half` says which course 1 does); a course that does not fill the
 * length ends with a cut block.  Stack bond: every course as course 1.
 * Block ids: "c<course>b<k>" (1-based, left to right).
 */
#ifndef SLIPWALL_LAYOUT_H
#define SLIPWALL_LAYOUT_H

#include "slipwall/wall.h"

/* Append the blocks of w->layout to w (before wall_finish).  Fails with
 * SW_EINPUT (and a message pointing at mark) on impossible sizes. */
enum sw_status layout_generate(struct wall *w, struct wall_mark mark,
			       char *err);

#endif
