/*
 * solve.h - the single-solution methods (docs/method.md, "Single-solution
 * methods"), all on the classical contact (points at the interface ends,
 * d = 0):
 *
 *   standard  associative limit analysis: max lambda with each contact
 *             point n >= 0, |t| <= mu n.  An upper value (may be unsafe).
 *   gilbert   the stabilised sequential LP of Gilbert, Casapulla & Ahmed
 *             (2006) started from the standard solution, then the onset
 *             check of the sampler: the same code as one sample.
 *   global    the global minimum of the non-associative problem, a
 *             mixed-integer program (complementarity by binaries, big-M
 *             bounds derived by LP), within a time limit; its collapse
 *             pattern is then checked, and its load found, by exact LPs.
 *
 * The result's load factor is in the user's units (N for a point load of
 * 1 N).  Runs on the calling thread; solve_run() frees the LP solver's
 * environment of that thread when it returns.
 *
 * Interruption: with o->stop set, another thread may store a non-zero
 * value there to end the solve early (the workbench does, when the wall
 * it solves is replaced).  An LP in progress stops within about a second
 * and no new one starts; solve_run() then returns SW_EINTR ("interrupted")
 * and r->status is SAMPLE_NUMERICAL: the result means nothing.  Building
 * the operator of a large wall is not interrupted (a few seconds at most
 * for a thousand blocks).  global's mixed-integer search is not either:
 * it has its own time limit.
 */
#ifndef SLIPWALL_SOLVE_H
#define SLIPWALL_SOLVE_H

#include <stdatomic.h>

#include "slipwall/sample.h"
#include "slipwall/wall.h"

enum solve_method { SOLVE_STANDARD, SOLVE_GILBERT, SOLVE_GLOBAL };

struct solve_opts {
	enum solve_method method;
	double time_limit;	/* global: seconds (default 60) */
	struct sample_opts sample;
	/* Progress, on the calling thread: about once a second during a
	 * long LP, and during global's mixed-integer program with its
	 * incumbent and best bound (user's units; NAN when there is none).
	 * what: the step being solved ("the standard solution (LP-max)",
	 * ...); seconds since solve_run began.  NULL: none. */
	void (*progress)(void *ctx, const char *what, double seconds,
			 double incumbent, double bound);
	void *progress_ctx;
	/* Non-zero *stop ends the solve (SW_EINTR; see above).  NULL:
	 * never (the default). */
	const atomic_int *stop;
	/* The set-up to start from (the workbench's solve thread, across
	 * its solves and edits; docs/design.md, "The shared set-up"): when
	 * *setup fits the wall (sample_setup_fits) the workspace starts
	 * from it and solves no canonical sample; otherwise it solves its
	 * own, which replaces *setup (the old one freed).  The caller owns
	 * *setup.  NULL: none (the default; the batch commands). */
	struct sample_setup **setup;
};
void solve_opts_default(struct solve_opts *o, enum solve_method m);
/* "standard" -> SOLVE_STANDARD; -1 for an unknown name. */
int solve_method_parse(const char *name);
const char *solve_method_name(enum solve_method m);

#define SOLVE_UNHELD 16

struct solve_result {
	enum solve_method method;
	enum sample_status status;	/* ACCEPTED when lambda was found */
	double lambda;			/* the method's load factor */
	/* gilbert */
	int iterations, converged;
	double lambda_onset;		/* LP-min after the onset check */
	/* global: lambda is the onset load of the program's collapse
	 * pattern, found by exact LPs (src/lib/solve.c says why) */
	double lower_bound;		/* the program's bound on the minimum */
	int mip_optimal;		/* the program proved its own optimum */
	int proven;			/* optimal, bounds derived, and lambda
					 * agrees with lower_bound */
	int bounds_derived;		/* big-M from LPs, not a fallback */
	double gap;			/* (lambda - lower_bound) / lambda */
	double seconds;
	/* `no_equilibrium`, `unstable`, `nonpositive`: the blocks that
	 * cannot be held (sample_unheld, at the load factors each allows),
	 * the first SOLVE_UNHELD of them, and how many in all (0 when not
	 * computed or none) */
	int nunheld;
	int unheld[SOLVE_UNHELD];
	/* the mechanism (when found) */
	int has_mechanism;
	struct sample_result mech;
};

/* Solve; SW_OK when the method ran (r->status says what it found),
 * SW_EANALYSIS with a message when it could not give a load, SW_EINTR
 * when *o->stop ended it. */
enum sw_status solve_run(const struct wall *w, const struct solve_opts *o,
			 struct solve_result *r, char *err);
void solve_result_free(struct solve_result *r);

#endif
