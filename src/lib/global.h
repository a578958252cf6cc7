/*
 * global.h - the global method's mixed-integer program (global.c), for
 * solve.c.  Private to src/lib/.
 */
#ifndef SLIPWALL_GLOBAL_H
#define SLIPWALL_GLOBAL_H

#include "slipwall/sample.h"
#include "slipwall/solve.h"

/* The global solution of w for the draw d (the classical contact, the
 * mean friction), lam_std its standard load factor: the program on ws's LP solver, its
 * pattern checked by exact LPs on ws (global.c, top), into r; SW_OK, or
 * SW_EANALYSIS with the message.  *what and *scale follow its steps
 * (the progress hook's words and the program's units to the user's). */
enum sw_status global_solve(const struct wall *w, const struct solve_opts *o,
			    struct sample_ws *ws, const struct sample_draw *d,
			    double lam_std, struct solve_result *r, char *err,
			    const char **what, double *scale);

#endif
