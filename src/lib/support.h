/*
 * support.h - a starting basis for the associative problems (LP-max, the
 * standing check, LP-min) built from how the wall stands: every free
 * block carried by three cone edges of the joints beneath it.  Private
 * to the library (sample_start.c).
 */
#ifndef SLIPWALL_SUPPORT_H
#define SLIPWALL_SUPPORT_H

#include "statics.h"

/* Mark in basic[0 .. 4m] the columns of the associative problems (in
 * sample_ws.h's layout: alpha and beta of point e of interface k at 4k + 2e
 * and 4k + 2e + 1, lambda at 4m) that form the support basis at the
 * contact points st holds: three per free block, lambda non-basic.
 * Returns the number of blocks whose three edges carry their load only
 * with a negative force (0: the basis is primal feasible at lambda = 0),
 * or -1 when some free block has no joint beneath it (basic[] is then
 * meaningless). */
int support_basis(const struct statics *st, unsigned char *basic);

#endif
