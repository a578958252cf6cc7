/*
 * sample.h - one Monte Carlo sample (docs/method.md, "One sample"), and
 * the pieces the single-solution methods reuse.
 *
 * A `struct sample_ws` holds six LPs of one wall, one per role (src/lib/
 * sample_ws.h): LP-max, the standing check and LP-min (the associative
 * problem), LP1 and LP2 (the SLP's fixed-capacity problem and its
 * stabilisation), and the kinematic LP of the onset check.  Each sample
 * starts every role from the basis its start option names (`previous`
 * keeps the last sample's bases); within a sample every re-solve of a
 * role is a warm start.  It owns its LP solver, which belongs to one
 * thread (the solver's rule): create, use and free the workspace on the
 * same thread.  The wall it reads must stay alive and unchanged.
 *
 * Units: sample_result carries real units (load factor as the user reads
 * it: N for a point load of magnitude 1, a coefficient for a body load;
 * forces in N; velocities and joint rates normalised so that the largest
 * block speed or rotation rate is 1).
 */
#ifndef SLIPWALL_SAMPLE_H
#define SLIPWALL_SAMPLE_H

#include <stdatomic.h>

#include "slipwall/draw.h"
#include "slipwall/wall.h"

/* X(enum, name in files, text for people) */
#define SAMPLE_STATUS_TABLE(X)                                                  \
	X(SAMPLE_ACCEPTED, "accepted", "accepted")                              \
	X(SAMPLE_NO_EQUILIBRIUM, "no_equilibrium",                              \
	  "no equilibrium on these contact points")                             \
	X(SAMPLE_UNBOUNDED, "unbounded", "load unbounded")                      \
	X(SAMPLE_NONPOSITIVE, "nonpositive", "maximum load factor <= 0")        \
	X(SAMPLE_UNSTABLE, "unstable", "cannot stand under its own weight")     \
	X(SAMPLE_NOT_CONVERGED, "not_converged", "SLP not converged")           \
	X(SAMPLE_HANGING, "hanging", "blocks hang on friction (clamp lost)")   \
	X(SAMPLE_NO_MECHANISM, "no_mechanism", "no mechanism at the SLP load")  \
	X(SAMPLE_NUMERICAL, "numerical", "numerical failure")

enum sample_status {
#define SAMPLE_X(e, name, text) e,
	SAMPLE_STATUS_TABLE(SAMPLE_X)
#undef SAMPLE_X
	SAMPLE_STATUS_COUNT
};
const char *sample_status_name(enum sample_status s);	/* "no_mechanism" */
const char *sample_status_text(enum sample_status s);	/* for people */
/* The status of a name, or -1. */
int sample_status_parse(const char *name);

/* Where every LP of a sample starts (SLIPWALL_LP_START, docs/method.md):
 * the slack basis with LP-max by the primal or the dual simplex, the LP
 * solver's crash basis, the canonical bases (each role's optimal basis at the
 * classical contact, a function of the wall alone), the basis the
 * workspace's previous sample left, the support basis of the sample's
 * own contact points for LP-max, the standing check and LP-min (each
 * block carried by its bed joints; the other roles from the slack
 * basis), or (`auto`, the default) the start
 * measured fastest for each role and size of wall, a function of the
 * wall alone.  A sample's result does not depend on it (the tie-breaks
 * of "one answer per sample"); its cost does. */
enum sample_start {
	SAMPLE_START_SLACK_PRIMAL,
	SAMPLE_START_SLACK_DUAL,
	SAMPLE_START_CRASH,
	SAMPLE_START_CANONICAL,
	SAMPLE_START_PREVIOUS,
	SAMPLE_START_SUPPORT,
	SAMPLE_START_AUTO,	/* by role and wall size (docs/method.md) */
	SAMPLE_START_COUNT
};
#define SAMPLE_START_DEFAULT SAMPLE_START_AUTO
const char *sample_start_name(enum sample_start s);
/* The start of a name ("slack-primal", ...), or -1. */
int sample_start_parse(const char *name);

/* The LP solver a workspace owns: its start, and the settings the front
 * ends pass from the environment (SLIPWALL_LP_START, docs/method.md; the
 * test variables of fault injection and of the solver's memory limit,
 * src/cli/main.c): the library reads no environment. */
struct sample_lp_config {
	enum sample_start start;	/* default SAMPLE_START_DEFAULT */
	/* for tests: every fault_every-th LP of the workspace fails (0:
	 * never), as the solver's internal error if fault_error (the
	 * problems die and are rebuilt) or else as a failure */
	long fault_every;
	int fault_error;
	/* the limit of the LP solver's allocator on the workspace's
	 * thread, in MB (0: none; the first workspace of a thread sets
	 * it): running out fails the sample (numerical), not the process */
	int mem_limit_mb;
	/* while *stop is non-zero the LPs stop: a sample in progress is
	 * abandoned (sample_ws_interrupted) within about a second, even
	 * inside a long LP.  NULL: never. */
	const atomic_int *stop;
	/* progress of a long LP: progress(progress_ctx, incumbent, bound)
	 * every half second of a long simplex (both NAN) and about once a
	 * second of a mixed-integer program (its incumbent's objective and
	 * best bound, NAN where none); it must not call the library.
	 * NULL: never. */
	void (*progress)(void *ctx, double incumbent, double bound);
	void *progress_ctx;
};
void sample_lp_config_default(struct sample_lp_config *c);
/* The test variables' values (NULL or "": not set) into c: start names
 * a start (sample_start_parse), fault is failed:N or error:N, mem_mb a
 * number of MB >= 1.  Returns 0, or -1 with the message of the first
 * value that is not one (that value leaves c as it was). */
int sample_lp_config_parse(struct sample_lp_config *c, const char *start,
			   const char *fault, const char *mem_mb,
			   char *err);

/* The SLP's iteration (docs/method.md, "The SLP's answer"): PLAIN,
 * c <- c + omega (N(c) - c) until it converges; ANDERSON, the last
 * round's default, accelerated by Anderson's steps while the LP bases
 * stay the same; PIECE, the default and the definition of a sample's
 * answer: plain steps until the joints' classification has held for
 * piece_settle iterations, then the exact fixed point of that affine
 * piece, verified by one more evaluation of the map. */
enum sample_slp { SAMPLE_SLP_PLAIN, SAMPLE_SLP_ANDERSON, SAMPLE_SLP_PIECE };

struct sample_opts {
	double omega;		/* SLP relaxation, default 0.5 */
	int max_iter;		/* SLP iteration limit, default 1000 */
	double tol;		/* convergence, relative to the mean block
				 * weight, default 1e-7 */
	int stabilise;		/* the L1-closest optimal stress field (1) */
	enum sample_slp slp;	/* how the SLP iterates (default PIECE) */
	int piece_settle;	/* PIECE: iterations the joints'
				 * classification must hold before its
				 * piece's fixed point is solved (default 2;
				 * 0: a Newton step at every iteration) */
	int forces;		/* fill sample_result.N and .T (default 0:
				 * no front end reports them, and their
				 * tie-break is a sample's costliest LP on
				 * large walls) */
	struct sample_lp_config lp;	/* the workspaces' LP solvers
					 * (mc.c, solve.c make them) */
};
void sample_opts_default(struct sample_opts *o);

/* Joint states in sample_result.joint (one char per interface). */
#define JOINT_CLOSED '.'	/* no relative motion */
#define JOINT_SLIDES 's'	/* slides, both points in contact */
#define JOINT_HINGES 'h'	/* one point opens: rotation about the other */
#define JOINT_HINGE_SLIDES 'H'	/* hinges and slides */
#define JOINT_OPENS 'o'		/* both points open: separates */

struct sample_result {
	enum sample_status status;
	double lambda_lpmax;	/* LP-max (associative, these points) */
	double lambda_max;	/* the converged SLP load factor */
	double lambda_min;	/* the onset-of-collapse load: the result */
	int iterations;		/* SLP iterations */
	int converged;
	int lps;		/* LPs solved for this sample */
	double vw_residual;	/* relative virtual-work residual */
	/* `no_equilibrium`, `unstable` or `nonpositive`
	 * (sample_run, sample_pattern): the block that most needs the least
	 * outside help (sample_unheld), or -1, and how many blocks need
	 * some (0: not found); `hanging`
	 * (sample_run): the lowest of the blocks that hang (docs/method.md,
	 * "Which blocks cannot be held"), and how many hang */
	int unheld, nunheld;
	/* mechanism (accepted samples) */
	int nblocks, nifaces;
	double *vel;		/* 3 * nblocks: u, v, omega (supports 0) */
	char *joint;		/* nifaces + 1: JOINT_* chars, NUL-terminated */
	double *dn;		/* 2 * nifaces: opening rates at q_a, q_b */
	double *dt;		/* nifaces: slip rates */
	/* stress field at lambda_min, N (with sample_opts.forces; NaN
	 * otherwise) */
	double *N;		/* 2 * nifaces */
	double *T;		/* nifaces */
};
void sample_result_init(struct sample_result *r, const struct wall *w);
void sample_result_free(struct sample_result *r);


struct sample_ws;
/* A workspace whose LP solver is set up by c (NULL: the defaults);
 * _start: from the given start (the path-invariance test). */
struct sample_ws *sample_ws_new(const struct wall *w);
struct sample_ws *sample_ws_new_config(const struct wall *w,
				       const struct sample_lp_config *c);
struct sample_ws *sample_ws_new_start(const struct wall *w,
				      enum sample_start start);
/* (For tests) a workspace with the `auto` start as it is on walls of
 * more than 1,000 interfaces, whatever the size of w. */
struct sample_ws *sample_ws_new_auto_large(const struct wall *w);
void sample_ws_free(struct sample_ws *ws);

/* The set-up of a wall (docs/design.md, "The shared set-up"): every
 * role's canonical basis (the basis it ended at on the canonical sample,
 * which a workspace solves when it is made: 23 s on walls/large.yaml),
 * as plain data, row and column statuses, so that another thread's
 * workspace of the same wall can start from it without solving the
 * canonical sample again.  A function of the wall's shape and the start
 * option alone: a workspace made from it takes exactly the bases it
 * would have solved for (the sampler's workers share one, mc.c).  The
 * workbench also gives it to the next wall of the same shape after an
 * edit (same blocks, supports and interfaces; friction, depth, loads
 * may differ): there it is only a start, which a sample's answer does
 * not depend on (docs/method.md, "One answer per sample").  Immutable
 * once made: any number of threads may read one. */
struct sample_setup;
/* The workspace's set-up (a new copy), or NULL if its canonical sample
 * was interrupted (sample_lp_config.stop). */
struct sample_setup *sample_ws_setup(const struct sample_ws *ws);
struct sample_setup *sample_setup_copy(const struct sample_setup *s);
void sample_setup_free(struct sample_setup *s);
/* Can a workspace of w with the configuration c (NULL: the defaults)
 * start from s?  The same shape (blocks, supports, interfaces and their
 * bodies) and the same start option; 0 for a NULL s. */
int sample_setup_fits(const struct sample_setup *s, const struct wall *w,
		      const struct sample_lp_config *c);
/* sample_ws_new_config, but the canonical bases are s's when s fits w
 * and c (no canonical sample is solved); otherwise as
 * sample_ws_new_config. */
struct sample_ws *sample_ws_new_setup(const struct wall *w,
				      const struct sample_lp_config *c,
				      const struct sample_setup *s);


/* Steps 2-6 of docs/method.md ("One sample") for the draw d (contact
 * points, friction).  Fills r (which must have been sample_result_init'ed
 * for the same wall). */
void sample_run(struct sample_ws *ws, const struct sample_draw *d,
		const struct sample_opts *o, struct sample_result *r);

/* A collapse pattern's onset-of-collapse load, for the draw d (for the
 * global method, whose mixed-integer program proposes the pattern):
 * open[2k + e] != 0 where contact point e of interface k may open, slip[k]
 * the directions (SAMPLE_SLIP_POS: towards +t, SAMPLE_SLIP_NEG) in which
 * joint k may slip.  Step 3's LP with these permissions instead of a
 * stress field's (the least joint motion for unit work of the live
 * load), then step 5 and the virtual work check, by exact LPs: r as after
 * sample_run (lambda_min, the mechanism, the forces).  Returns r->status:
 * NO_MECHANISM when no mechanism uses only these motions, NUMERICAL when
 * no admissible field keeps the one found (LP-min infeasible: a block
 * pushed high overturns before it can slide). */
enum { SAMPLE_SLIP_POS = 1, SAMPLE_SLIP_NEG = 2 };
enum sample_status sample_pattern(struct sample_ws *ws,
				  const struct sample_draw *d,
				  const unsigned char *open,
				  const unsigned char *slip,
				  struct sample_result *r);

/* The associative (standard) limit analysis for the draw d: maximum
 * load factor and its mechanism (the LP dual).  Returns the status
 * (ACCEPTED when an optimum was found). */
enum sample_status sample_standard(struct sample_ws *ws,
				   const struct sample_draw *d,
				   struct sample_result *r);

/* The load factors at which sample_unheld asks the blocks to stand,
 * by the verdict that asks (docs/method.md, "Which blocks cannot be
 * held"). */
enum sample_unheld_load {
	SAMPLE_UNHELD_ANY,	/* any load factor: `no_equilibrium` */
	SAMPLE_UNHELD_AT_REST,	/* 0, no live load: `unstable` */
	SAMPLE_UNHELD_ALONG,	/* 0 or more: LP-max's `nonpositive` */
	SAMPLE_UNHELD_FIXED,	/* 0 or more, with the SLP's friction
				 * capacities fixed: the SLP's
				 * `nonpositive` */
};

/* Whether r's verdict asks which blocks cannot be held, and if so at
 * which load factors (into *load): `no_equilibrium` at any, `unstable`
 * at 0, `nonpositive` at 0 or more, LP-max's (r->lambda_max NaN) with
 * the cones, the SLP's (its fixed point's load at or below 0) with the
 * SLP's capacities, SAMPLE_UNHELD_FIXED; every other verdict asks
 * nothing (returns 0). */
int sample_unheld_asks(const struct sample_result *r,
		       enum sample_unheld_load *load);

/* Which blocks no contact force can hold at the draw the workspace
 * last solved, at the load factors `load` allows (after `no_equilibrium`
 * at any; after `unstable` at 0: the blocks that need the live load to
 * stand; after LP-max's `nonpositive` at 0 or more: the blocks that
 * need a load against the live load's direction; after the SLP's, the
 * same with each joint's shear bounded by its friction times the SLP's
 * last capacity, friction that does not dilate): the blocks on which
 * the least outside help that lets every block stand acts, by an
 * elastic LP-max.  Writes up to max of them (indices into w->blocks),
 * the most helped first, into blocks[]; returns how many there are in
 * all (0: the draw has an equilibrium there), or -1 if the LP failed or
 * was stopped. */
int sample_unheld(struct sample_ws *ws, enum sample_unheld_load load,
		  int *blocks, int max);

/* What the LPs of a workspace cost, by role, since it was made (its
 * canonical sample included): the six LP roles of docs/method.md (LP-max,
 * standing, LP-min, LP1, LP2, kinematic), then each one's tie-break.  A
 * solve that the LP layer answers from the basis it held counts as an LP
 * of no iterations. */
#define SAMPLE_ROLE_COUNT 12
struct sample_lp_stats {
	long lps, iterations;
	double seconds;		/* inside lp_solve, monotonic clock */
};
const char *sample_role_name(int role);
void sample_ws_stats(const struct sample_ws *ws,
		     struct sample_lp_stats out[SAMPLE_ROLE_COUNT]);

/* What the workspace's LP solver did since it was made: LPs solved,
 * simplex iterations, LPs answered by the basis the solver held, LPs
 * started from artificial bounds or from shifted costs (docs/method.md,
 * "Warm starts and held bases"), seconds inside the solver, internal
 * errors that were the solver running out of memory, and whether it
 * solved its canonical sample (setups). */
struct sample_lp_counters {
	long solves, iterations, held, art, shift, memory_errors;
	double seconds;
	int setups;	/* canonical samples solved: 0 (made from a
			 * sample_setup) or 1 */
};
void sample_ws_counters(const struct sample_ws *ws,
			struct sample_lp_counters *c);
/* Did an LP of the workspace stop (sample_lp_config.stop) since it was
 * made?  The sample it belonged to is incomplete: discard it. */
int sample_ws_interrupted(const struct sample_ws *ws);
/* A thread that used workspaces is done with them: the LP solver's
 * per-thread environment goes (call it before the thread exits). */
void sample_thread_done(void);
/* Internal errors of workspaces' LP solvers that were running out of
 * memory, over the process: those of a sample are counted before
 * sample_run (or the other sample functions) returns. */
long sample_memory_errors(void);

/* The statics of the workspace (scales, operator), for the global
 * method which builds its own problem on the same operator. */
struct statics;
const struct statics *sample_statics(const struct sample_ws *ws);
/* Fill the mechanism and forces of r from scaled block velocities v
 * (3 per free block) and a scaled stress field x (3 per interface): the
 * joint rates come from A^T v. */
void sample_export(struct sample_ws *ws, const double *v, const double *x,
		   struct sample_result *r);

#endif
