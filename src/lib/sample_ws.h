/*
 * sample_ws.h - the inside of a sample workspace (struct sample_ws), for
 * the files that do one sample's jobs: sample.c (the workspace, begin,
 * finish, the entry points), sample_lp.c (the LPs' formulation),
 * sample_start.c (the starts), sample_tie.c (the tie-breaks),
 * sample_slp.c (the SLP) and sample_onset.c (LP-max, standing, the
 * mechanism, LP-min, the export); docs/method.md, "One sample".  Private
 * to those files (tests/boundary.sh); the rest of the library reaches a
 * workspace through slipwall/sample.h and sample_lp.h.  It holds what
 * they share: the roles, the column layout, the workspace, and the
 * functions one of them calls in another (prefix sws_).
 *
 * The roles (enum role), one LP problem each:
 *
 *   AMAX, STAND, AMIN  rows: equilibrium (3 per free block) only
 *               cols: the force at each contact point in the edge
 *               directions of its friction cone, F = alpha (n + mu t) +
 *               beta (n - mu t), alpha, beta >= 0 (so N = alpha + beta,
 *               T = mu (alpha - beta) summed over the two points):
 *               alpha_a, beta_a, alpha_b, beta_b per interface | lambda.
 *               No friction rows (they were two thirds of the rows), and
 *               every yield condition LP-min holds at its limit is a
 *               column bound: N_j = 0 is alpha_j = beta_j = 0, T = +mu N
 *               is beta = 0, T = -mu N is alpha = 0.
 *               AMAX: LP-max (max lambda).  STAND: lambda = 0 and no
 *               objective: can the wall stand under its own weight?
 *               AMIN: min lambda >= 0 with the mechanism's yield
 *               conditions held at their limits (LP-min).
 *   LP1, LP2    rows: equilibrium | LP2 only: 1 closeness row per
 *               interface, Na + Nb - p + q = c
 *               cols: Na, Nb, T | lambda | LP2 only: p, q per interface
 *               LP1: max lambda with |T| <= mu c (column bounds: a fixed
 *               capacity, no dilatancy).  LP2: min sum (p + q) over LP1's
 *               optimal face (LP1's columns with a non-zero reduced cost
 *               fixed where LP1 left them) - the optimal stress field
 *               closest in L1 to c.
 *   KIN         rows: one per column of A (opening rates at q_a, q_b,
 *               slip rate) | f_L . v = 1
 *               cols: block velocities | s+, s- per interface (slip =
 *               s+ - s-); min sum of opening rates + sum |slip|: the
 *               least joint motion.
 */
#ifndef SLIPWALL_SAMPLE_WS_H
#define SLIPWALL_SAMPLE_WS_H

#include <math.h>

#include "lp.h"
#include "slipwall/sample.h"
#include "statics.h"

/* the SLP's acceleration (sws_slp()): the memory of Anderson's steps,
 * iterates of one affine piece (the iterations before them: SLP_SETTLE,
 * sample_slp.c) */
#define SLP_MEMORY 4

/* The LP roles of a sample, one GLPK problem each (see the top). */
enum role { AMAX, STAND, AMIN, LP1, LP2, KIN, ROLES };
/* sample.h's roles are these, then each one's tie-break */
_Static_assert(SAMPLE_ROLE_COUNT == 2 * ROLES, "roles");

/* Anderson mixing of the SLP (sws_slp()): the last few iterates of one
 * affine piece, and the least-squares step they give. */
struct slp_history {
	int len;		/* iterates held, <= SLP_MEMORY + 1 */
	double *c[SLP_MEMORY + 1], *f[SLP_MEMORY + 1];	/* c_i, N(c_i) - c_i */
};

/* The default SLP's phase ends (sample_slp.c, slp_cycle_root;
 * docs/method.md, "The SLP's answer", rule 8): the last SLP_RING
 * iterates of the path (capacities c and their maps' normal-force sums
 * N), and at the end of each phase that did not converge, the two of
 * them between which the third attempt's root search runs. */
#define SLP_RING 16
#define SLP_ENDS 8
struct slp_ends {
	double *buf;	/* (2 SLP_RING + 2 SLP_ENDS) m doubles (11 MB on
			 * tests/wall-10050.yaml's 29,851 interfaces);
			 * NULL until a large wall's first SLP needs it */
	int on;		/* record (the first two attempts, m > SLP_PHASE) */
	int pushed;	/* iterates in the ring since the phase began */
	int n;		/* phase ends held */
	int K[SLP_ENDS];	/* each end's interface, and its residual */
	double f[SLP_ENDS][2];	/* N_K - c_K at the end's two iterates */
};

struct sample_ws {
	const struct wall *w;
	struct statics st;
	int m, R;		/* interfaces, equilibrium rows */
	/* the side joints of blocks that hang (wall_clamp_joints), and
	 * those blocks, 1 each (wall_clamp_blocks) */
	int nclamp, *clamp_k;
	char *clamp_blk;
	/* the SLP's last path ended on an LP1 without equilibrium, at
	 * the capacities clost (m) */
	int slp_lost;
	double *clost;
	/* after a `hanging` verdict (slp_clamp_lost): the lowest of the
	 * blocks that hang, and how many hang; else -1 and 0 */
	int hang_blk, nhang;
	/* sample_unheld's primal pivot limit (sample_ws_unheld_limit; 0:
	 * its default) */
	int unheld_limit;
	/* the workspace's LP solver, and one problem per LP role (see the
	 * top), so that between two solves of a role only bounds change and
	 * the solver keeps its basis */
	struct lp_solver *solver;
	struct lp *lp[ROLES];
	double *c;		/* m: SLP capacities (sum of normal forces) */
	double *cstar;		/* m: a piece's fixed point (sws_slp) */
	double *fallback;	/* m: where a failed jump goes on (sws_slp) */
	int slp_lp;		/* LP1 or LP2: where slp_map read the field */
	struct slp_history hist;	/* sws_slp()'s Anderson memory */
	double *c0;		/* m: the SLP's start, for its restarts */
	struct lp_basis slp_start[2];	/* LP1's, LP2's bases there */
	/* LP1's optimal basis, and LP2's start made of it (lp2_from_lp1)
	 * and KIN's (sample_onset.c, kin_from_lp1) */
	struct lp_basis lp1_end, lp2_face, kin_start;
	struct slp_ends ends;		/* the phase ends, for rule 8 */
	double *x;		/* 3m: stress field of the last SLP LP */
	double *v;		/* R: velocities */
	double *dn, *dt;	/* 2m, m: joint rates */
	int *ind;		/* scratch */
	double *val;
	/* the tie-break weights of this sample ("One answer per sample"):
	 * r[2k + e] for contact point e of interface k, r[2m + k] for the
	 * slip of interface k; all in [1, 2), from the positions alone */
	double *r;
	double *c2;		/* a tie-break objective (scratch) */
	unsigned char *basic;	/* the support basis's columns (scratch) */
	/* m: which of interface k's rates in dn, dt may be motion (KIN_*):
	 * what KIN's bounds let it do (sws_kin_allow), for a rate KIN
	 * holds at 0 is 0 whatever round-off it reads; all of them for
	 * rates not from KIN (sample_export) */
	unsigned char *kfree;
	enum sample_start start;	/* SLIPWALL_LP_START */
	int large;		/* `auto` takes its large-wall starts */
	/* a path's first LP2 by the primal simplex from LP1's optimum
	 * (sample_slp.c, lp2_from_lp1): not large, or a body load */
	int lp2_primal;
	int setup;		/* solving the canonical sample */
	int setups;		/* canonical samples solved (0 or 1) */
	int forces;		/* this sample reports its stress field */
	/* LPs by role, since the workspace was made (sample_ws_stats) */
	struct sample_lp_stats stats[SAMPLE_ROLE_COUNT];
	struct lp_basis canon[ROLES];	/* see sws_start_bases() */
	long memory_noted;	/* of the solver's memory errors */
};

/* Column indices. */
#define COL_LAMBDA(ws) (3 * (ws)->m)
/* associative problems: cone edges of point e (0: q_a, 1: q_b) */
#define ACOL_ALPHA(k, e) (4 * (k) + 2 * (e))
#define ACOL_BETA(k, e) (4 * (k) + 2 * (e) + 1)
#define ACOL_LAMBDA(ws) (4 * (ws)->m)
#define COL_P(ws, k) (3 * (ws)->m + 1 + (k))
#define COL_Q(ws, k) (3 * (ws)->m + 1 + (ws)->m + (k))
#define KCOL_SP(ws, k) ((ws)->R + (k))
#define KCOL_SM(ws, k) ((ws)->R + (ws)->m + (k))

/* The shear capacity mu_k c_k of interface k in the SLP. */
static inline double sws_capacity(const struct sample_ws *ws, int k)
{
	return ws->st.mu[k] * fmax(ws->c[k], 0);
}

/* A wall of more than this many interfaces is large: `auto` takes its
 * large-wall starts and set-up there (sample.c, setup_large;
 * sample_start.c), and the SLP's last attempt, the long phase, is not
 * tried (sample_slp.c, slp_round), where an iteration costs about a
 * second (walls/body-1000.yaml, 2,956 interfaces). */
#define SWS_LARGE_IFACES 1000

/* What the kinematic LP may do at an interface (sample_ws.kfree). */
#define KIN_OPEN_A 1u	/* point q_a may open */
#define KIN_OPEN_B 2u	/* point q_b may open */
#define KIN_SLIP_POS 4u	/* slip > 0 allowed */
#define KIN_SLIP_NEG 8u	/* slip < 0 allowed */

/* sample_lp.c: the LPs' formulation, every solve, and the memory errors
 * they meet */
void sws_note_memory(struct sample_ws *ws);
void sws_put_column(struct sample_ws *ws, int j);
void sws_put_dead_load(struct sample_ws *ws, struct lp *P);
int sws_live_load(struct sample_ws *ws);
void sws_put_kin_objective(struct sample_ws *ws);
void sws_build(struct sample_ws *ws);
void sws_refill(struct sample_ws *ws);
enum lp_status sws_counted(struct sample_ws *ws, int role, enum lp_method m,
			   const double *c2, struct sample_result *r);
enum lp_status sws_counted_floor(struct sample_ws *ws, int role,
				 const double *c2, int col, double lo,
				 struct sample_result *r);
enum lp_status sws_solve(struct sample_ws *ws, enum role role,
			 enum lp_method m, struct sample_result *r);

/* sample_start.c: the starts */
enum sample_start sws_role_start(const struct sample_ws *ws, int p);
enum lp_method sws_lp_max_method(const struct sample_ws *ws);
void sws_start_bases(struct sample_ws *ws);

/* sample_tie.c: the tie-break weights and the tie-breaks */
void sws_tie_weights(struct sample_ws *ws, const double *xi);
void sws_put_lp2_objective(struct sample_ws *ws);
enum lp_status sws_assoc_tiebreak(struct sample_ws *ws, enum role role,
				  struct sample_result *r);
enum lp_status sws_lp2_tiebreak(struct sample_ws *ws, struct sample_result *r);
enum lp_status sws_floor_tiebreak(struct sample_ws *ws, double lam,
				  struct sample_result *r);
enum sample_status sws_lp_max_floor(struct sample_ws *ws,
				    struct sample_result *r);
enum lp_status sws_kin_tiebreak(struct sample_ws *ws, struct sample_result *r);

/* sample_onset.c: KIN's bounds at interface k (KIN_* bits) */
void sws_kin_allow(struct sample_ws *ws, int k, unsigned bits);

/* sample_slp.c: step 2b, the SLP */
enum sample_status sws_slp(struct sample_ws *ws, const struct sample_opts *o,
			   struct sample_result *r);
/* sample_slp.c: the SLP's first evaluation by LP1 alone, at the
 * capacities of LP-max's field: its field into ws->x, its load into
 * r->lambda_max (a large wall's set-up: sample.c, setup_large) */
enum sample_status sws_slp_first_lp1(struct sample_ws *ws,
				     const struct sample_opts *o,
				     struct sample_result *r);

/* sample_onset.c: LP-max, standing, the mechanism, onset, LP-min, the
 * virtual work, the export */
enum sample_status sws_lp_max(struct sample_ws *ws, struct sample_result *r,
			      double *v);
enum sample_status sws_slp_load(const struct sample_result *r);
enum sample_status sws_standing(struct sample_ws *ws, struct sample_result *r);
enum sample_status sws_mechanism(struct sample_ws *ws, struct sample_result *r);
/* the force zero of the onset check: the first (a dying contact's force
 * is zero) and the strict one of its retry after LP-min (docs/method.md,
 * "One sample", step 5) */
enum sws_force_zero { SWS_ZERO_DYING, SWS_ZERO_STRICT };
enum sample_status sws_onset(struct sample_ws *ws, const struct sample_opts *o,
			     enum sws_force_zero z, struct sample_result *r);
/* LP-min's first solve alone, the dual simplex from the basis AMIN holds,
 * without sws_solve's re-check of a "no" (a large wall's set-up, which
 * wants LP-min's basis and no verdict: sample.c, setup_large) */
enum lp_status sws_lp_min_once(struct sample_ws *ws, struct sample_result *r);
/* LP-min; its LP's verdict also in *lps (may be NULL) */
enum sample_status sws_lp_min(struct sample_ws *ws, enum lp_method method,
			      struct sample_result *r, enum lp_status *lps);
double sws_virtual_work(const struct sample_ws *ws, double lam, double *allow);
void sws_export(struct sample_ws *ws, struct sample_result *r);

#endif
