/*
 * sample_lp.h - the LP solver a sample workspace owns (sample_lp.c), for
 * the library's other LP users on the same workspace: the global
 * method's mixed-integer program (global.c).  Private to src/lib/; the
 * workspace's inside is sample_ws.h's, private to the sample's files.
 */
#ifndef SLIPWALL_SAMPLE_LP_H
#define SLIPWALL_SAMPLE_LP_H

#include "lp.h"
#include "slipwall/sample.h"

struct lp_solver *sample_ws_solver(struct sample_ws *ws);
/* For tests: sample_unheld's pivot limit for its primal simplex, after
 * which it goes on by the dual simplex from the slack basis
 * (sample_unheld.c); 0 restores the default, 10 pivots a row. */
void sample_ws_unheld_limit(struct sample_ws *ws, int pivots);

#endif
