/*
 * lp.c - the GLPK layer: hooks, warm starts, statuses.  See lp.h.
 *
 * GLPK reports internal errors by calling the error hook and then
 * abort()ing unless the hook does not return.  We longjmp out of the hook
 * back into the lp_solve() that was running, free the thread's GLPK
 * environment (the only documented recovery) and bump a per-thread
 * generation number; a problem built in an older generation is dead and
 * is never touched again by GLPK calls.
 *
 * Out of memory.  GLPK's allocator reports a failed malloc, or a total
 * above glp_mem_limit, by the same error path.  So it is not only the
 * solves that run under a jump target: every entry point here whose
 * GLPK calls allocate (lp_new, lp_set_col, lp_set_row, the basis
 * resets, lp_set_binary) sets one too (GUARD below) and recovers the
 * same way: the thread's problems are dead, the setters on a dead
 * problem do nothing, and its next lp_solve returns LP_ERROR - the
 * sample is "numerical", and sample.c's rebuild either succeeds or
 * leaves dead problems again (each sample then fails the same way; the
 * run goes on and says why: lp_memory_errors).  Each thread's GLPK
 * environment gets the limit of lp_mem_limit_set (or the test variable
 * SLIPWALL_GLPK_MEM_MB), again after every recovery, so that GLPK runs
 * out inside its own accounting before the kernel's overcommit kills
 * the process.
 *
 * Fault injection (lp_fault_set, or SLIPWALL_LP_FAULT in the environment)
 * makes every n-th lp_solve of a thread fail, to test that a failed LP
 * costs one sample and nothing else (tests/unit/test_faults.c,
 * tests/cli/faults.sh).  An injected LP_ERROR goes through GLPK's own
 * error path (glp_error, the hook, the longjmp), not around it.
 *
 * Held bases.  Most LPs of the SLP are re-solves after a few bounds
 * changed, and most of them end where they started: on Ferris & Tin-Loi
 * wall 1, 92 % of LP1's and 71 % of LP2's dual simplex calls make no
 * pivot.  Such a call still costs glp_simplex its whole set-up (a
 * working copy of the problem, reduced costs, pricing weights; about
 * as much as three pivots).  So while GLPK holds a problem's optimal
 * basis and only bounds have changed since (p->held), a dual simplex
 * solve first evaluates that basis (glp_warm_up: one FTRAN, one BTRAN,
 * with the factorisation GLPK kept) and accepts it when no basic value
 * is outside its bounds by more than half of GLPK's tol_bnd and no
 * reduced cost has the wrong sign by more than half of 0.97 tol_dj, the
 * margins below which GLPK's dual simplex (spy_dual) neither pivots nor
 * flips a bound.  It is the basis glp_simplex would have returned, so the
 * same vertex; the values agree to round-off (they are computed by
 * another routine).  Anything else goes to glp_simplex, from the same
 * basis.
 *
 * Interruption (lp_thread_stop_flag): GLPK's simplex has no callback,
 * and one LP of a very large wall runs for minutes, so a stop request
 * (Ctrl-C, a new edit in the workbench) could not reach a worker inside
 * it.  The simplex runs with messages on but delayed (out_dly): GLPK
 * prints nothing during the first tenth of a second of a solve, then a
 * progress line every tenth - to the terminal hook, which looks
 * at the thread's stop flag and, if it is set, leaves the solve by the
 * same longjmp and recovery as an error.  Only whether a sample is
 * abandoned depends on the clock, never a value: an interrupted sample
 * is discarded, not reported (lp_thread_interrupted).  Those lines
 * call the thread's progress hook (lp_thread_progress) every half second,
 * and so does the branch-and-cut callback, about once a second.
 */
#include <glpk.h>
#include <limits.h>
#include <math.h>
#include <pthread.h>
#include <setjmp.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "lp.h"
#include "slipwall/status.h"
#include "slipwall/sys.h"

struct lp {
	glp_prob *P;
	int nrows, ncols;
	unsigned generation;
	int last_iters;
	/* GLPK holds the optimal basis of this problem's last solve and
	 * its factorisation, and only bounds changed since ("Held bases") */
	int held;
	int *ind;		/* scratch, 1-based */
	double *val;
	/* lp_tiebreak's record of what it changed, to restore it */
	double *tb_obj;		/* ncols: the objective */
	int *tb_fixed;		/* rows then columns it fixed (1-based,
				 * columns as nrows + j) */
	int *tb_type, *tb_stat;	/* their type and status */
	double *tb_lb, *tb_ub;	/* and their bounds */
};

static _Thread_local int tl_hooked;
static _Thread_local long tl_live;	/* problems alive on the thread */
static _Thread_local unsigned tl_generation;
static _Thread_local jmp_buf tl_jump;
static _Thread_local int tl_in_call;
static _Thread_local char tl_message[256];
static _Thread_local long tl_solves, tl_iterations, tl_held;
static _Thread_local double tl_seconds;
static _Thread_local const atomic_int *tl_stop;	/* lp_thread_stop_flag */
static _Thread_local int tl_in_simplex;	/* inside lp_solve's simplex */
static _Thread_local int tl_interrupted;
static _Thread_local int tl_it_lim;	/* lp_thread_iteration_limit */
static _Thread_local int tl_out_of_memory;	/* GLPK said so (term_hook) */

static int stop_requested(void)
{
	return tl_stop && atomic_load(tl_stop);
}

/* Fault injection: set once (lp_fault_set before any thread solves, or
 * the environment at the first solve), then only read. */
static pthread_once_t fault_once = PTHREAD_ONCE_INIT;
static long fault_every;		/* 0: off */
static enum lp_status fault_as;		/* LP_FAILED or LP_ERROR */
static _Thread_local long tl_fault_count;

static _Thread_local double tl_gap;
static _Thread_local lp_progress_fn tl_progress;	/* lp_thread_progress */
static _Thread_local void *tl_progress_ctx;
static _Thread_local double tl_progress_last;

/* The thread's progress hook, with the branch-and-cut's incumbent and
 * best bound (NAN: none, or a simplex) */
static void progress(double incumbent, double bound)
{
	if (tl_progress)
		tl_progress(tl_progress_ctx, incumbent, bound);
}

/* Branch-and-cut callback: remember the gap between the incumbent and
 * the best bound whenever either changes. */
static void mip_callback(glp_tree *T, void *info)
{
	(void)info;
	int r = glp_ios_reason(T);
	if (r == GLP_IBINGO || r == GLP_ISELECT || r == GLP_IBRANCH)
		tl_gap = glp_ios_mip_gap(T);
	/* and, about once a second, the progress hook */
	if (!tl_progress || r != GLP_ISELECT || sys_now() - tl_progress_last < 1)
		return;
	tl_progress_last = sys_now();
	glp_prob *P = glp_ios_get_prob(T);
	int best = glp_ios_best_node(T);
	progress(glp_mip_status(P) == GLP_FEAS ? glp_mip_obj_val(P) : NAN,
		 best ? glp_ios_node_bound(T, best) : NAN);
}

/* GLPK's text goes here instead of the terminal; the last line is kept. */
static int term_hook(void *info, const char *s)
{
	(void)info;
	if (tl_in_simplex && stop_requested())
		longjmp(tl_jump, 2);	/* see "Interruption" above */
	/* every half second of a long solve (the lines come every tenth) */
	if (tl_in_simplex && tl_progress && sys_now() - tl_progress_last >= 0.5) {
		tl_progress_last = sys_now();
		progress(NAN, NAN);
	}
	/* GLPK's allocator's words (env/alloc.c); the error's last line is
	 * "Error detected in file ...", so the mark is kept apart */
	if (strstr(s, "memory allocation") || strstr(s, "no memory available"))
		tl_out_of_memory = 1;
	size_t n = strlen(s);
	if (n >= sizeof tl_message)
		n = sizeof tl_message - 1;
	if (n > 0) {
		memcpy(tl_message, s, n);
		tl_message[n] = 0;
		if (tl_message[n - 1] == '\n')
			tl_message[n - 1] = 0;
	}
	return 1;	/* suppress GLPK's own output */
}

static void error_hook(void *info)
{
	(void)info;
	if (tl_in_call)
		longjmp(tl_jump, 1);
	/* An error outside any guarded call (a bad argument to an unguarded
	 * setter) is a bug in this program: say so and stop, as GLPK would
	 * have. */
	fprintf(stderr, "slipwall: GLPK error outside a solve: %s\n",
		tl_message);
	abort();
}

/* Out of memory (see the top): the limit in MB for every thread's
 * environment (0: none), set before the threads start; and how many
 * GLPK errors were memory errors, over all threads. */
static pthread_once_t mem_once = PTHREAD_ONCE_INIT;
static int mem_limit_mb;
static atomic_long mem_errors;

static void mem_from_env(void)
{
	const char *s = getenv("SLIPWALL_GLPK_MEM_MB");	/* for tests */
	char *end;
	if (!s || !*s)
		return;
	long n = strtol(s, &end, 10);
	if (*end || n <= 0 || n > INT_MAX) {
		fprintf(stderr, "slipwall: SLIPWALL_GLPK_MEM_MB must be a "
			"number of megabytes >= 1\n");
		return;
	}
	mem_limit_mb = (int)n;
}

void lp_mem_limit_set(double mb)
{
	pthread_once(&mem_once, mem_from_env);
	if (getenv("SLIPWALL_GLPK_MEM_MB"))
		return;		/* the test's limit wins */
	mem_limit_mb = !(mb >= 1) ? 1 : mb >= INT_MAX ? INT_MAX : (int)mb;
}

int lp_mem_limit(void)
{
	pthread_once(&mem_once, mem_from_env);
	return mem_limit_mb;
}

long lp_memory_errors(void)
{
	return atomic_load(&mem_errors);
}

static void hook(void)
{
	if (tl_hooked)
		return;
	glp_term_out(GLP_ON);
	glp_term_hook(term_hook, NULL);
	glp_error_hook(error_hook, NULL);
	int mb = lp_mem_limit();
	if (mb > 0)
		glp_mem_limit(mb);
	tl_hooked = 1;
}

/* After a hook's longjmp: GLPK's environment is mid-call, the only way
 * back is to free it; every problem of the thread is dead. */
static void recover(void)
{
	tl_in_call = 0;
	tl_in_simplex = 0;
	if (tl_out_of_memory)
		atomic_fetch_add(&mem_errors, 1);
	tl_out_of_memory = 0;
	glp_free_env();
	tl_hooked = 0;
	tl_generation++;
	hook();
}

/* Run `body` (GLPK calls that may allocate) on a live problem under a
 * jump target: a GLPK error there kills the thread's problems (see the
 * top) instead of aborting. */
#define GUARD(p, body)                                                   \
	do {                                                             \
		if (!alive(p))                                           \
			return;                                          \
		if (setjmp(tl_jump)) {                                   \
			recover();                                       \
			return;                                          \
		}                                                        \
		tl_in_call = 1;                                          \
		body;                                                    \
		tl_in_call = 0;                                          \
	} while (0)

static int alive(const struct lp *p)
{
	return p->P && p->generation == tl_generation;
}

struct lp *lp_new(int nrows, int ncols)
{
	hook();
	struct lp *p = sw_xcalloc(1, sizeof *p);
	tl_live++;
	p->nrows = nrows;
	p->ncols = ncols;
	int n = (nrows > ncols ? nrows : ncols) + 1;
	p->ind = sw_xmalloc(sizeof(int) * (size_t)(n + 1));
	p->val = sw_xmalloc(sizeof(double) * (size_t)(n + 1));
	if (stop_requested()) {	/* a dead problem (stopped_writing) */
		tl_interrupted = 1;
		return p;
	}
	if (setjmp(tl_jump)) {	/* out of memory: a dead problem (top) */
		recover();
		p->P = NULL;
		return p;
	}
	tl_in_call = 1;
	p->generation = tl_generation;
	p->P = glp_create_prob();
	if (nrows > 0)
		glp_add_rows(p->P, nrows);
	if (ncols > 0)
		glp_add_cols(p->P, ncols);
	for (int i = 1; i <= nrows; i++)
		glp_set_row_bnds(p->P, i, GLP_FX, 0, 0);
	for (int j = 1; j <= ncols; j++)
		glp_set_col_bnds(p->P, j, GLP_FR, 0, 0);
	tl_in_call = 0;
	return p;
}

void lp_free(struct lp *p)
{
	if (!p)
		return;
	tl_live--;
	if (alive(p))
		glp_delete_prob(p->P);
	free(p->ind);
	free(p->val);
	free(p->tb_obj);
	free(p->tb_fixed);
	free(p->tb_type);
	free(p->tb_stat);
	free(p->tb_lb);
	free(p->tb_ub);
	free(p);
}

int lp_alive(const struct lp *p)
{
	return p && alive(p);
}

void lp_clear(struct lp *p)
{
	p->held = 0;
	if (!alive(p))
		return;
	glp_prob *P = p->P;
	/* drop the factorization: GLPK keeps it while no variable enters
	 * or leaves the basis, and one reached by updates differs in the
	 * last bits from one computed afresh; taking row 1 out of the
	 * basis and back in is a change in any basis */
	if (p->nrows > 0) {
		glp_set_row_stat(P, 1, GLP_NL);
		glp_set_row_stat(P, 1, GLP_BS);
	}
	for (int i = 1; i <= p->nrows; i++)
		glp_set_row_bnds(P, i, GLP_FX, 0, 0);
	for (int j = 1; j <= p->ncols; j++) {
		glp_set_col_bnds(P, j, GLP_FR, 0, 0);
		glp_set_obj_coef(P, j, 0);
	}
	glp_set_obj_dir(P, GLP_MIN);
	glp_std_basis(P);
}

void lp_set_maximize(struct lp *p, int maximize)
{
	p->held = 0;
	if (!alive(p))	/* dead after an error (top): the next solve says so */
		return;
	glp_set_obj_dir(p->P, maximize ? GLP_MAX : GLP_MIN);
}

void lp_set_obj(struct lp *p, int col, double c)
{
	p->held = 0;
	if (!alive(p))
		return;
	glp_set_obj_coef(p->P, col + 1, c);
}

static int bound_type(double lo, double hi)
{
	int l = isfinite(lo), h = isfinite(hi);
	if (l && h)
		return lo == hi ? GLP_FX : GLP_DB;
	if (l)
		return GLP_LO;
	if (h)
		return GLP_UP;
	return GLP_FR;
}

void lp_set_col_bounds(struct lp *p, int col, double lo, double hi)
{
	if (!alive(p))
		return;
	glp_set_col_bnds(p->P, col + 1, bound_type(lo, hi),
			 isfinite(lo) ? lo : 0, isfinite(hi) ? hi : 0);
}

void lp_set_row_bounds(struct lp *p, int row, double lo, double hi)
{
	if (!alive(p))
		return;
	glp_set_row_bnds(p->P, row + 1, bound_type(lo, hi),
			 isfinite(lo) ? lo : 0, isfinite(hi) ? hi : 0);
}

/* A stop request (lp_thread_stop_flag) while a problem is being written
 * kills it, as an error would: writing the problems of a large wall
 * takes most of a second (6 problems of 9,000 columns on
 * walls/large.yaml), and the workbench waits for its workers to stop at
 * every edit.  The next solve of the problem reports the interruption. */
static int stopped_writing(struct lp *p)
{
	if (!stop_requested())
		return 0;
	if (alive(p))
		glp_delete_prob(p->P);
	p->P = NULL;
	tl_interrupted = 1;
	return 1;
}

void lp_set_col(struct lp *p, int col, int n, const int *rows,
		const double *vals)
{
	p->held = 0;
	if (stopped_writing(p))
		return;
	for (int i = 0; i < n; i++) {
		p->ind[i + 1] = rows[i] + 1;
		p->val[i + 1] = vals[i];
	}
	GUARD(p, glp_set_mat_col(p->P, col + 1, n, p->ind, p->val));
}

void lp_set_row(struct lp *p, int row, int n, const int *cols,
		const double *vals)
{
	p->held = 0;
	if (stopped_writing(p))
		return;
	for (int i = 0; i < n; i++) {
		p->ind[i + 1] = cols[i] + 1;
		p->val[i + 1] = vals[i];
	}
	GUARD(p, glp_set_mat_row(p->P, row + 1, n, p->ind, p->val));
}

void lp_reset_basis(struct lp *p)
{
	p->held = 0;
	GUARD(p, glp_std_basis(p->P));
}

void lp_crash_basis(struct lp *p)
{
	p->held = 0;
	GUARD(p, glp_adv_basis(p->P, 0));
}

void lp_set_basis(struct lp *p, const unsigned char *cols)
{
	if (!alive(p))
		return;
	p->held = 0;
	/* GLPK takes a non-basic status that does not fit the variable's
	 * type as the one that does (NL for a fixed row is NS, for a free
	 * column NF) */
	for (int i = 1; i <= p->nrows; i++)
		glp_set_row_stat(p->P, i, GLP_NL);
	for (int j = 1; j <= p->ncols; j++)
		glp_set_col_stat(p->P, j, cols[j - 1] ? GLP_BS : GLP_NL);
}

static enum lp_status map_status(glp_prob *P)
{
	switch (glp_get_status(P)) {
	case GLP_OPT:
		return LP_OPTIMAL;
	case GLP_NOFEAS:
		return LP_INFEASIBLE;
	case GLP_UNBND:
		return LP_UNBOUNDED;
	default:
		/* GLP_INFEAS / GLP_FEAS / GLP_UNDEF after a clean return:
		 * look at the primal and dual statuses */
		if (glp_get_prim_stat(P) == GLP_NOFEAS)
			return LP_INFEASIBLE;
		if (glp_get_dual_stat(P) == GLP_NOFEAS &&
		    glp_get_prim_stat(P) == GLP_FEAS)
			return LP_UNBOUNDED;
		return LP_FAILED;
	}
}

/* The simplex's tolerances (glp_smcp: tol_bnd, tol_dj; GLPK's defaults
 * are 1e-7) and the share of them within which a held basis is taken as
 * it is ("Held bases").  1e-9 since the fourth round: with GLPK's 1e-7
 * an optimum is only optimal to about that, relative, and the SLP's
 * answer is sensitive to it.  Measured on Ferris & Tin-Loi wall 2, seed
 * 1, sample 691: LP1's maximum load at the same capacities was
 * 0.523379238758734 from one start and 0.523379264669792 (5e-8 more)
 * from the others, and the iterations settled on different pieces
 * (accepted from one start, `numerical` from the others).  At 1e-9 every
 * start gives 0.52337926466979, and the wall's 1,000 samples have the
 * same status and load from every start (4 rejected at 1e-7, 1 at 1e-9:
 * 501, 701 and 737 had virtual-work residuals of 4e-8 to 8e-8, the
 * LPs' precision); the speed is the same (docs/method.md). */
#define GLPK_TOL_BND 1e-9
#define GLPK_TOL_DJ 1e-9
/* ... but the primal simplex (the tie-breaks, which start from an optimal
 * basis, and the fixed-path re-check of an "infeasible" verdict) keeps
 * 1e-8: at 1e-9 its Harris ratio test stalls on degenerate vertices.
 * Measured on the demo wall, seed 1, 200 samples: LP-max's tie-break
 * took 702 pivots an LP at 1e-9 (samples 27 and 103 about 1 s each) and
 * 26 at 1e-8; at 1e-8 the 1,000 samples of seed 1 of the demo and both
 * Ferris & Tin-Loi walls have the same status, loads and iterations as
 * at 1e-9 (docs/performance.md, "Fourth round") */
#define GLPK_TOL_PRIMAL 1e-8
#define HELD_TOL_PRIMAL (0.5 * GLPK_TOL_BND)
#define HELD_TOL_DUAL (0.5 * 0.97 * GLPK_TOL_DJ)

double lp_feasibility_tol(enum lp_method m)
{
	return m == LP_DUAL ? GLPK_TOL_BND : GLPK_TOL_PRIMAL;
}

/* Is a basic value v inside the bounds of a variable of GLPK type t? */
static int held_primal_ok(int t, double lb, double ub, double v)
{
	if ((t == GLP_LO || t == GLP_DB || t == GLP_FX) &&
	    v < lb - HELD_TOL_PRIMAL)
		return 0;
	if ((t == GLP_UP || t == GLP_DB || t == GLP_FX) &&
	    v > ub + HELD_TOL_PRIMAL)
		return 0;
	return 1;
}

/* Has the reduced cost d (of a minimisation) of a non-basic variable
 * with status st the sign its status needs? */
static int held_dual_ok(int st, double d)
{
	switch (st) {
	case GLP_NL: return d >= -HELD_TOL_DUAL;
	case GLP_NU: return d <= HELD_TOL_DUAL;
	case GLP_NF: return fabs(d) <= HELD_TOL_DUAL;
	default: return 1;	/* GLP_NS: fixed, never enters */
	}
}

/* The held basis of p, evaluated under the current bounds: is it
 * optimal?  If so GLPK now holds its solution, as after glp_simplex. */
static int held_optimal(struct lp *p)
{
	glp_prob *P = p->P;
	if (glp_warm_up(P) != 0)
		return 0;
	double dir = glp_get_obj_dir(P) == GLP_MIN ? 1 : -1;
	for (int i = 1; i <= p->nrows; i++) {
		int st = glp_get_row_stat(P, i);
		if (st == GLP_BS ? !held_primal_ok(glp_get_row_type(P, i),
						   glp_get_row_lb(P, i),
						   glp_get_row_ub(P, i),
						   glp_get_row_prim(P, i))
				 : !held_dual_ok(st, dir * glp_get_row_dual(P, i)))
			return 0;
	}
	for (int j = 1; j <= p->ncols; j++) {
		int st = glp_get_col_stat(P, j);
		if (st == GLP_BS ? !held_primal_ok(glp_get_col_type(P, j),
						   glp_get_col_lb(P, j),
						   glp_get_col_ub(P, j),
						   glp_get_col_prim(P, j))
				 : !held_dual_ok(st, dir * glp_get_col_dual(P, j)))
			return 0;
	}
	return 1;
}

/* SLIPWALL_LP_FAULT=failed:N or error:N (see lp.h). */
static void fault_from_env(void)
{
	const char *s = getenv("SLIPWALL_LP_FAULT");
	char *end;
	if (!s || !*s)
		return;
	enum lp_status as = LP_FAILED;
	if (!strncmp(s, "failed:", 7)) {
		s += 7;
	} else if (!strncmp(s, "error:", 6)) {
		as = LP_ERROR;
		s += 6;
	}
	long n = strtol(s, &end, 10);
	if (*end || n <= 0) {
		fprintf(stderr, "slipwall: SLIPWALL_LP_FAULT must be failed:N or error:N, N >= 1\n");
		return;
	}
	fault_every = n;
	fault_as = as;
}

void lp_fault_set(long every, enum lp_status as)
{
	pthread_once(&fault_once, fault_from_env);
	fault_every = every > 0 ? every : 0;
	fault_as = as == LP_ERROR ? LP_ERROR : LP_FAILED;
	tl_fault_count = 0;
}

/* Is this solve of this thread one that must fail? */
static int fault_now(void)
{
	pthread_once(&fault_once, fault_from_env);
	return fault_every > 0 && ++tl_fault_count % fault_every == 0;
}

enum lp_status lp_solve(struct lp *p, enum lp_method m)
{
	if (stop_requested()) {	/* before anything else: no rebuilding */
		tl_interrupted = 1;
		return LP_STOPPED;
	}
	if (!alive(p))
		return LP_ERROR;
	int fault = fault_now();
	if (fault && fault_as == LP_FAILED) {
		tl_solves++;
		p->last_iters = 0;
		return LP_FAILED;
	}
	glp_smcp parm;
	glp_init_smcp(&parm);
	/* messages on, but none before a tenth of a second, then one every
	 * tenth: the terminal hook's chance to see a stop request */
	parm.msg_lev = GLP_MSG_ON;
	parm.out_dly = 100;
	parm.out_frq = 100;
	parm.presolve = GLP_OFF;
	parm.tol_bnd = lp_feasibility_tol(m);
	parm.tol_dj = m == LP_DUAL ? GLPK_TOL_DJ : GLPK_TOL_PRIMAL;
	parm.meth = m == LP_DUAL ? GLP_DUALP : GLP_PRIMAL;
	parm.it_lim = tl_it_lim > 0 ? tl_it_lim :
		      50000 + 50 * (p->nrows + p->ncols);
	/* no time limit: a result must not depend on the machine's speed
	 * or load; the iteration limit above is the (deterministic) bound */
	enum lp_status st;
	int jumped = setjmp(tl_jump);
	if (jumped) {
		/* a hook jumped here (an error, or a stop request): GLPK's
		 * environment is mid-solve, the only way back is to free it */
		recover();
		if (jumped == 2) {
			tl_interrupted = 1;
			return LP_STOPPED;
		}
		return LP_ERROR;
	}
	tl_in_call = 1;
	if (fault)	/* an injected error, through GLPK's error path */
		glp_error("slipwall: injected fault (SLIPWALL_LP_FAULT)\n");
	double t0 = sys_now();
	int held = p->held && m == LP_DUAL;
	p->held = 0;
	if (held && held_optimal(p)) {
		tl_in_call = 0;
		tl_seconds += sys_now() - t0;
		p->last_iters = 0;
		p->held = 1;
		tl_solves++;
		tl_held++;
		return LP_OPTIMAL;
	}
	tl_in_simplex = 1;
	int it0 = glp_get_it_cnt(p->P);
	int rc = glp_simplex(p->P, &parm);
	if (rc == GLP_EBADB || rc == GLP_ESING || rc == GLP_ECOND ||
	    rc == GLP_EFAIL || rc == GLP_EITLIM) {
		glp_adv_basis(p->P, 0);
		parm.meth = GLP_DUALP;
		rc = glp_simplex(p->P, &parm);
	}
	tl_in_call = 0;
	tl_in_simplex = 0;
	tl_seconds += sys_now() - t0;
	p->last_iters = glp_get_it_cnt(p->P) - it0;
	tl_solves++;
	tl_iterations += p->last_iters;
	if (rc == GLP_ENOPFS)
		return LP_INFEASIBLE;
	if (rc == GLP_ENODFS)
		return LP_UNBOUNDED;
	if (rc != 0)
		return LP_FAILED;
	st = map_status(p->P);
	p->held = st == LP_OPTIMAL;
	return st;
}

/*
 * Tie-break (docs/method.md, "One answer per sample").  The optimal face
 * of the LP just solved is, by complementary slackness with the dual
 * solution GLPK holds, the set of feasible points at which every
 * non-basic variable with a non-zero reduced cost stays where it is (this
 * holds for any optimal dual solution, so the face does not depend on
 * which optimal basis the simplex reached).  A variable is "non-zero"
 * when |d| > tol.  When no non-basic variable has |d| <= tol the optimum
 * is unique and nothing is solved.  Otherwise those variables are fixed
 * (their bounds, as GLPK types), the objective becomes c2 (minimised),
 * and the primal simplex starts from the optimal basis, which stays
 * primal feasible.  Afterwards the bounds, the statuses of the fixed
 * variables, the objective and its sense are put back as they were; the
 * solution GLPK stores (lp_col, lp_row) is the tie-break's.
 */
static int tb_nonzero(int stat, double d, double tol)
{
	return stat != GLP_BS && stat != GLP_NS && fabs(d) > tol;
}

static int tb_zero(int stat, double d, double tol)
{
	return stat != GLP_BS && stat != GLP_NS && !(fabs(d) > tol);
}

enum lp_status lp_tiebreak(struct lp *p, const double *c2, double tol,
			   int *solved)
{
	*solved = 0;
	if (!alive(p))
		return LP_ERROR;
	glp_prob *P = p->P;
	int n = p->nrows + p->ncols, tie = 0;
	for (int i = 1; i <= p->nrows && !tie; i++)
		tie = tb_zero(glp_get_row_stat(P, i), glp_get_row_dual(P, i), tol);
	for (int j = 1; j <= p->ncols && !tie; j++)
		tie = tb_zero(glp_get_col_stat(P, j), glp_get_col_dual(P, j), tol);
	if (!tie)
		return LP_OPTIMAL;
	if (!p->tb_obj) {
		p->tb_obj = sw_xmalloc(sizeof(double) * (size_t)(p->ncols + 1));
		p->tb_fixed = sw_xmalloc(sizeof(int) * (size_t)(n + 1));
		p->tb_type = sw_xmalloc(sizeof(int) * (size_t)(n + 1));
		p->tb_stat = sw_xmalloc(sizeof(int) * (size_t)(n + 1));
		p->tb_lb = sw_xmalloc(sizeof(double) * (size_t)(n + 1));
		p->tb_ub = sw_xmalloc(sizeof(double) * (size_t)(n + 1));
	}
	int nf = 0, dir = glp_get_obj_dir(P);
	for (int i = 1; i <= p->nrows; i++) {
		int st = glp_get_row_stat(P, i);
		if (!tb_nonzero(st, glp_get_row_dual(P, i), tol))
			continue;
		p->tb_fixed[nf] = i;
		p->tb_type[nf] = glp_get_row_type(P, i);
		p->tb_stat[nf] = st;
		p->tb_lb[nf] = glp_get_row_lb(P, i);
		p->tb_ub[nf] = glp_get_row_ub(P, i);
		double v = st == GLP_NU ? p->tb_ub[nf] : p->tb_lb[nf];
		if (st == GLP_NF)
			v = glp_get_row_prim(P, i);
		glp_set_row_bnds(P, i, GLP_FX, v, v);
		nf++;
	}
	for (int j = 1; j <= p->ncols; j++) {
		int st = glp_get_col_stat(P, j);
		p->tb_obj[j - 1] = glp_get_obj_coef(P, j);
		glp_set_obj_coef(P, j, c2[j - 1]);
		if (!tb_nonzero(st, glp_get_col_dual(P, j), tol))
			continue;
		p->tb_fixed[nf] = p->nrows + j;
		p->tb_type[nf] = glp_get_col_type(P, j);
		p->tb_stat[nf] = st;
		p->tb_lb[nf] = glp_get_col_lb(P, j);
		p->tb_ub[nf] = glp_get_col_ub(P, j);
		double v = st == GLP_NU ? p->tb_ub[nf] : p->tb_lb[nf];
		if (st == GLP_NF)
			v = glp_get_col_prim(P, j);
		glp_set_col_bnds(P, j, GLP_FX, v, v);
		nf++;
	}
	glp_set_obj_dir(P, GLP_MIN);
	p->held = 0;
	enum lp_status st = lp_solve(p, LP_PRIMAL);
	*solved = 1;
	if (!alive(p))
		return st;
	/* put the problem back; the statuses first fixed by the tie-break
	 * are those of the primary optimum, still valid (a fixed variable
	 * never enters the basis) */
	for (int f = 0; f < nf; f++) {
		int k = p->tb_fixed[f];
		if (k <= p->nrows) {
			glp_set_row_bnds(P, k, p->tb_type[f], p->tb_lb[f], p->tb_ub[f]);
			if (glp_get_row_stat(P, k) != GLP_BS)
				glp_set_row_stat(P, k, p->tb_stat[f]);
		} else {
			k -= p->nrows;
			glp_set_col_bnds(P, k, p->tb_type[f], p->tb_lb[f], p->tb_ub[f]);
			if (glp_get_col_stat(P, k) != GLP_BS)
				glp_set_col_stat(P, k, p->tb_stat[f]);
		}
	}
	for (int j = 1; j <= p->ncols; j++)
		glp_set_obj_coef(P, j, p->tb_obj[j - 1]);
	glp_set_obj_dir(P, dir);
	p->held = 0;
	return st;
}

void lp_thread_iteration_limit(int limit)
{
	tl_it_lim = limit > 0 ? limit : 0;
}

void lp_basis_save(const struct lp *p, struct lp_basis *b)
{
	if (!alive(p))	/* after LP_ERROR or LP_STOPPED: nothing to save */
		return;
	int n = p->nrows + p->ncols;
	if (b->n != n) {
		free(b->stat);
		b->stat = sw_xmalloc(sizeof(int) * (size_t)(n + 1));
		b->n = n;
	}
	for (int i = 0; i < p->nrows; i++)
		b->stat[i] = glp_get_row_stat(p->P, i + 1);
	for (int j = 0; j < p->ncols; j++)
		b->stat[p->nrows + j] = glp_get_col_stat(p->P, j + 1);
}

void lp_basis_load(struct lp *p, const struct lp_basis *b)
{
	if (!alive(p))
		return;
	if (b->n != p->nrows + p->ncols)
		return;
	p->held = 0;
	for (int i = 0; i < p->nrows; i++)
		glp_set_row_stat(p->P, i + 1, b->stat[i]);
	for (int j = 0; j < p->ncols; j++)
		glp_set_col_stat(p->P, j + 1, b->stat[p->nrows + j]);
}

unsigned long lp_basis_hash(const struct lp *p)
{
	if (!alive(p))
		return 0;
	unsigned long long h = 1469598103934665603ULL;	/* FNV-1a */
	for (int i = 1; i <= p->nrows; i++)
		h = (h ^ (unsigned)glp_get_row_stat(p->P, i)) * 1099511628211ULL;
	for (int j = 1; j <= p->ncols; j++)
		h = (h ^ (unsigned)glp_get_col_stat(p->P, j)) * 1099511628211ULL;
	return (unsigned long)h;
}

void lp_basis_free(struct lp_basis *b)
{
	free(b->stat);
	b->stat = NULL;
	b->n = 0;
}

double lp_obj(const struct lp *p) { return glp_get_obj_val(p->P); }
double lp_col(const struct lp *p, int col) { return glp_get_col_prim(p->P, col + 1); }
double lp_row(const struct lp *p, int row) { return glp_get_row_prim(p->P, row + 1); }
double lp_col_dual(const struct lp *p, int col) { return glp_get_col_dual(p->P, col + 1); }
double lp_row_dual(const struct lp *p, int row) { return glp_get_row_dual(p->P, row + 1); }
int lp_last_iterations(const struct lp *p) { return p->last_iters; }

int lp_col_basic(const struct lp *p, int col)
{
	return glp_get_col_stat(p->P, col + 1) == GLP_BS;
}

int lp_row_basic(const struct lp *p, int row)
{
	return glp_get_row_stat(p->P, row + 1) == GLP_BS;
}

int lp_get_col(const struct lp *p, int col, int *rows, double *vals)
{
	int n = glp_get_mat_col(p->P, col + 1, p->ind, p->val);
	for (int t = 0; t < n; t++) {
		rows[t] = p->ind[t + 1] - 1;
		vals[t] = p->val[t + 1];
	}
	return n;
}

/* lp_solve_square's triplets, sorted by column then row (qsort) */
struct triplet {
	int i, j;
	double v;
};

static int triplet_cmp(const void *a, const void *b)
{
	const struct triplet *x = a, *y = b;
	if (x->j != y->j)
		return x->j < y->j ? -1 : 1;
	return x->i < y->i ? -1 : x->i > y->i;
}

/* The system as a problem whose basis is every column: GLPK's basis
 * matrix is the columns of (I | -A) of the basic variables, here -M, in
 * the order of the basis header, so y_j = -(B^-1 b) at the header's
 * position of column j. */
int lp_solve_square(int n, int nnz, const int *ri, const int *ci,
		    const double *v, double *b)
{
	hook();
	if (n <= 0)
		return n == 0 ? 0 : -1;
	struct triplet *t = sw_xmalloc(sizeof *t * (size_t)(nnz + 1));
	int *ia = sw_xmalloc(sizeof(int) * (size_t)(nnz + 1));
	int *ja = sw_xmalloc(sizeof(int) * (size_t)(nnz + 1));
	double *ar = sw_xmalloc(sizeof(double) * (size_t)(nnz + 1));
	double *x = sw_xmalloc(sizeof(double) * (size_t)(n + 1));
	for (int e = 0; e < nnz; e++)
		t[e] = (struct triplet){ri[e], ci[e], v[e]};
	qsort(t, (size_t)nnz, sizeof *t, triplet_cmp);
	int ne = 0;
	for (int e = 0; e < nnz; e++) {
		if (ne > 0 && ia[ne] == t[e].i + 1 && ja[ne] == t[e].j + 1) {
			ar[ne] += t[e].v;
			continue;
		}
		ne++;
		ia[ne] = t[e].i + 1;
		ja[ne] = t[e].j + 1;
		ar[ne] = t[e].v;
	}
	volatile int rc = -1;
	glp_prob *P;
	if (setjmp(tl_jump)) {	/* out of memory: the thread's problems die */
		recover();
		goto out;
	}
	tl_in_call = 1;
	P = glp_create_prob();
	glp_add_rows(P, n);
	glp_add_cols(P, n);
	glp_load_matrix(P, ne, ia, ja, ar);
	for (int i = 1; i <= n; i++) {
		glp_set_row_bnds(P, i, GLP_FX, 0, 0);
		glp_set_row_stat(P, i, GLP_NS);
		glp_set_col_stat(P, i, GLP_BS);
	}
	if (glp_factorize(P) == 0) {
		for (int i = 0; i < n; i++)
			x[i + 1] = b[i];
		glp_ftran(P, x);
		for (int i = 1; i <= n; i++) {
			int h = glp_get_bhead(P, i);	/* n + j: column j */
			b[h - n - 1] = -x[i];
		}
		rc = 0;
		for (int i = 0; i < n; i++)
			if (!isfinite(b[i]))
				rc = -1;
	}
	glp_delete_prob(P);
	tl_in_call = 0;
out:
	free(t);
	free(ia);
	free(ja);
	free(ar);
	free(x);
	return rc;
}

int lp_unique(const struct lp *p, double tol)
{
	for (int j = 1; j <= p->ncols; j++) {
		int st = glp_get_col_stat(p->P, j);
		if (st == GLP_BS || st == GLP_NS)
			continue;
		if (fabs(glp_get_col_dual(p->P, j)) <= tol)
			return 0;
	}
	for (int i = 1; i <= p->nrows; i++) {
		int st = glp_get_row_stat(p->P, i);
		if (st == GLP_BS || st == GLP_NS)
			continue;
		if (fabs(glp_get_row_dual(p->P, i)) <= tol)
			return 0;
	}
	return 1;
}

void lp_thread_counters(long *solves, long *iterations, long *held)
{
	*solves = tl_solves;
	*iterations = tl_iterations;
	*held = tl_held;
}

double lp_thread_seconds(void)
{
	return tl_seconds;
}

void lp_thread_done(void)
{
	glp_free_env();
	tl_hooked = 0;
	tl_generation++;
}

void lp_thread_idle(void)
{
	if (tl_live == 0 && tl_hooked)
		lp_thread_done();
}

void lp_thread_stop_flag(const atomic_int *flag)
{
	tl_stop = flag;
	tl_interrupted = 0;
}

void lp_thread_progress(lp_progress_fn fn, void *ctx)
{
	tl_progress = fn;
	tl_progress_ctx = ctx;
}

int lp_thread_interrupted(void)
{
	return tl_interrupted;
}

const char *lp_last_message(void)
{
	return tl_message;
}

void lp_set_binary(struct lp *p, int col)
{
	GUARD(p, glp_set_col_kind(p->P, col + 1, GLP_BV));
}

enum lp_mip_status lp_solve_mip(struct lp *p, double time_limit, double *gap)
{
	if (!alive(p))
		return LP_MIP_FAILED;
	if (setjmp(tl_jump)) {
		recover();
		return LP_MIP_FAILED;
	}
	tl_in_call = 1;
	glp_smcp sp;
	glp_init_smcp(&sp);
	sp.msg_lev = GLP_MSG_OFF;
	sp.presolve = GLP_OFF;
	int rc = glp_simplex(p->P, &sp);
	if (rc != 0 || glp_get_status(p->P) != GLP_OPT) {
		tl_in_call = 0;
		if (glp_get_status(p->P) == GLP_NOFEAS)
			return LP_MIP_NOFEASIBLE;
		return LP_MIP_FAILED;
	}
	glp_iocp ip;
	glp_init_iocp(&ip);
	ip.msg_lev = GLP_MSG_OFF;
	/* milliseconds in an int: clamped here, whatever the caller checked */
	ip.tm_lim = !(time_limit > 0) ? 1 :
		    time_limit >= INT_MAX / 1000.0 ? INT_MAX : (int)(time_limit * 1000);
	ip.br_tech = GLP_BR_PCH;
	ip.bt_tech = GLP_BT_BLB;
	ip.gmi_cuts = GLP_ON;
	ip.mir_cuts = GLP_ON;
	ip.cov_cuts = GLP_ON;
	ip.clq_cuts = GLP_ON;
	ip.cb_func = mip_callback;
	tl_gap = NAN;
	tl_progress_last = sys_now();
	rc = glp_intopt(p->P, &ip);
	tl_in_call = 0;
	int st = glp_mip_status(p->P);
	/* the relative gap between the incumbent and the best bound */
	*gap = NAN;
	if (st == GLP_OPT) {
		*gap = 0;
		return LP_MIP_OPTIMAL;
	}
	if (st == GLP_FEAS) {
		*gap = tl_gap;	/* last gap the callback saw */
		return LP_MIP_FEASIBLE;
	}
	if (st == GLP_NOFEAS)
		return LP_MIP_NOFEASIBLE;
	(void)rc;
	return LP_MIP_FAILED;
}

double lp_mip_col(const struct lp *p, int col) { return glp_mip_col_val(p->P, col + 1); }
double lp_mip_row(const struct lp *p, int row) { return glp_mip_row_val(p->P, row + 1); }
