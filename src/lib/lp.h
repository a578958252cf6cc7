/*
 * lp.h - a thin layer over GLPK; the only module that includes glpk.h.
 *
 * Indices are 0-based here (GLPK's are 1-based).  Bounds use -HUGE_VAL /
 * HUGE_VAL for "none".  A problem keeps its basis between solves, so
 * changing bounds, objective or a column and solving again is a warm
 * start (presolve is always off).
 *
 * Threads: Debian's GLPK keeps one environment per thread.  A problem is
 * created, solved and freed on one thread; every thread that uses this
 * module calls lp_thread_done() before it exits.  The first call on a
 * thread installs hooks so that GLPK never prints (its text is kept, the
 * last line readable with lp_last_message) and never aborts: a GLPK error
 * jumps back into lp_solve(), which frees the thread's environment and
 * returns LP_ERROR.  After LP_ERROR every problem of that thread is dead:
 * lp_free() it (safe) and build new ones.
 */
#ifndef SLIPWALL_LP_H
#define SLIPWALL_LP_H

#include <stdatomic.h>

enum lp_status {
	LP_OPTIMAL,
	LP_INFEASIBLE,	/* no primal feasible point */
	LP_UNBOUNDED,	/* feasible, objective unbounded */
	LP_FAILED,	/* the simplex gave up (singular basis, limit) */
	LP_ERROR,	/* GLPK reported an internal error; problems dead */
	LP_STOPPED,	/* interrupted by the thread's stop flag; the
			 * thread's problems are dead (as after LP_ERROR) */
};

enum lp_method { LP_PRIMAL, LP_DUAL };

/* How far a basic variable of an optimal solution by the simplex method
 * m may lie outside its bounds (absolute at a bound of 0): GLPK's tol_bnd
 * as lp.c sets it, 1e-9 for the dual simplex and 1e-8 for the primal
 * (the tie-breaks).  A value this small is not told from 0. */
double lp_feasibility_tol(enum lp_method m);

struct lp;

struct lp *lp_new(int nrows, int ncols);
void lp_free(struct lp *p);
/* Is the problem usable (not dead after LP_ERROR or LP_STOPPED)? */
int lp_alive(const struct lp *p);
/* Back to what lp_new() left, the matrix kept: every row fixed at 0,
 * every column free, objective 0 and minimised, the standard basis and
 * no factorization (one reached by updates differs in the last bits
 * from one computed afresh).  For a caller that writes the problem
 * again and wants no trace of past solves (src/lib/sample.c, refill). */
void lp_clear(struct lp *p);

void lp_set_maximize(struct lp *p, int maximize);
void lp_set_obj(struct lp *p, int col, double c);
void lp_set_col_bounds(struct lp *p, int col, double lo, double hi);
void lp_set_row_bounds(struct lp *p, int row, double lo, double hi);
/* Replace column col: n non-zeros at rows[] with vals[]. */
void lp_set_col(struct lp *p, int col, int n, const int *rows,
		const double *vals);
/* Replace row row: n non-zeros at cols[] with vals[]. */
void lp_set_row(struct lp *p, int row, int n, const int *cols,
		const double *vals);

/* Solve from the current basis.  If the simplex fails (singular basis,
 * iteration limit) it is retried once from an advanced basis.  A dual
 * simplex solve after bound changes only first tries the basis of the
 * last solve as it is (src/lib/lp.c, "Held bases"). */
enum lp_status lp_solve(struct lp *p, enum lp_method m);
/* Forget the basis (next solve starts from the standard basis). */
void lp_reset_basis(struct lp *p);
/* Start from GLPK's advanced (crash) basis: deterministic, built from
 * the matrix alone, and usually far fewer pivots from optimal than the
 * standard (all-slack) basis. */
void lp_crash_basis(struct lp *p);
/* Start from the basis whose basic columns are those with cols[j] != 0:
 * every row non-basic (its auxiliary variable at its bound), every other
 * column non-basic at its bound (or 0 if free).  The caller makes it a
 * basis (as many basic columns as rows, non-singular); a singular one
 * is GLPK's to repair (lp_solve). */
void lp_set_basis(struct lp *p, const unsigned char *cols);

/* A saved basis (row and column statuses), to warm-start a problem that
 * alternates between objectives from the basis each objective last
 * ended at.  A fresh basis is empty: lp_basis_load does nothing. */
struct lp_basis {
	int n;			/* 0: nothing saved */
	int *stat;		/* rows then columns */
};
void lp_basis_save(const struct lp *p, struct lp_basis *b);
void lp_basis_load(struct lp *p, const struct lp_basis *b);
void lp_basis_free(struct lp_basis *b);
/* A hash of the current basis (every row's and column's status): two
 * solves that end with the same hash almost surely ended at the same
 * basis. */
unsigned long lp_basis_hash(const struct lp *p);

double lp_obj(const struct lp *p);
double lp_col(const struct lp *p, int col);
double lp_row(const struct lp *p, int row);
double lp_col_dual(const struct lp *p, int col);	/* reduced cost */
double lp_row_dual(const struct lp *p, int row);
/* 1 if the column is basic in the current solution. */
int lp_col_basic(const struct lp *p, int col);
/* 1 if the row's auxiliary variable is basic in the current solution. */
int lp_row_basic(const struct lp *p, int row);
/* Column col of the matrix: its non-zeros into rows[] and vals[] (room
 * for every row), their number returned. */
int lp_get_col(const struct lp *p, int col, int *rows, double *vals);
/* Solve the square sparse system M y = b of order n, M given by nnz
 * triplets (rows ri[], columns ci[], values v[]; 0-based, a repeated
 * position adds up), by GLPK's sparse LU of the basis matrix of a
 * throw-away problem (glp_factorize, glp_ftran).  b is replaced by y.
 * Returns 0, or -1 if M is singular or too ill-conditioned for GLPK's
 * LU (GLP_ESING, GLP_ECOND), or after a GLPK error (out of memory: the
 * thread's problems are then dead, as after LP_ERROR). */
int lp_solve_square(int n, int nnz, const int *ri, const int *ci,
		    const double *v, double *b);
/* 1 if the optimum is unique as far as the reduced costs tell: no
 * non-basic variable (except fixed ones) has a zero reduced cost. */
int lp_unique(const struct lp *p, double tol);
/* The tie-break of docs/method.md, "One answer per sample", right after
 * an LP_OPTIMAL solve of p: if some non-basic variable has a reduced cost
 * |d| <= tol, the optimum may not be unique, and p is solved again over
 * its optimal face (every non-basic variable with |d| > tol held where it
 * is) with the objective "minimise c2 . x" (c2: one coefficient per
 * column), by the primal simplex from the optimal basis.  The problem's
 * bounds, objective and sense are then restored; the values lp_col and
 * lp_row read are the tie-break's.  *solved: 1 if that LP was solved (it
 * counts as a solve), 0 if the optimum was unique.  Returns LP_OPTIMAL,
 * or the failed tie-break's status (LP_ERROR, LP_STOPPED: as lp_solve). */
enum lp_status lp_tiebreak(struct lp *p, const double *c2, double tol,
			   int *solved);
/* Simplex iterations of the last solve. */
int lp_last_iterations(const struct lp *p);

/* Counters of this thread since start: solves, simplex iterations, and
 * solves answered by the basis GLPK held, without the simplex (src/lib/lp.c,
 * "Held bases"). */
void lp_thread_counters(long *solves, long *iterations, long *held);
/* Seconds this thread spent inside lp_solve (GLPK's simplex), by the
 * monotonic clock, since start (for the benchmark). */
double lp_thread_seconds(void);
void lp_thread_done(void);
/* lp_thread_done() if the thread holds no problem (every lp_new freed). */
void lp_thread_idle(void);
/* Interruption: while *flag is non-zero, lp_solve on this thread returns
 * LP_STOPPED at once, and a solve already running stops within about a
 * second (src/lib/lp.c, "Interruption").  NULL: never.  Also clears the
 * thread's interrupted mark. */
void lp_thread_stop_flag(const atomic_int *flag);
/* Progress: fn(ctx, incumbent, bound) is called on this thread every
 * half second during a long simplex of lp_solve (both NAN), and about
 * once a second during lp_solve_mip (the incumbent's objective, NAN
 * before one is found, and the best bound of the open nodes).  fn must
 * not call this module.  NULL: never. */
typedef void (*lp_progress_fn)(void *ctx, double incumbent, double bound);
void lp_thread_progress(lp_progress_fn fn, void *ctx);
/* Did an lp_solve of this thread return LP_STOPPED since the flag was
 * set?  The sample it belonged to is incomplete: discard it. */
int lp_thread_interrupted(void);
const char *lp_last_message(void);

/* Fault injection, for tests: from now on every `every`-th lp_solve()
 * of each thread (counted per thread, from 0 again for the calling
 * thread) returns `as` - LP_FAILED at once,
 * or LP_ERROR by raising a GLPK error inside the solve, so the recovery
 * above runs for real.  every = 0 turns it off.  Call it before the
 * threads that solve start.  Without a call, the environment variable
 * SLIPWALL_LP_FAULT=failed:N or error:N does the same (read once). */
void lp_fault_set(long every, enum lp_status as);
/* For tests: GLPK's simplex iteration limit for this thread's solves
 * (0: the default, 50,000 + 50 (rows + columns)).  A solve that reaches
 * it is retried once from an advanced basis, then LP_FAILED: the path of
 * GLPK's own GLP_EITLIM, provoked for real rather than injected. */
void lp_thread_iteration_limit(int limit);

/* Memory: the limit of GLPK's allocator on each thread, in MB (GLPK's
 * glp_mem_limit; at least 1), for the threads' environments created
 * from now on; call it before the threads start.  The environment
 * variable SLIPWALL_GLPK_MEM_MB (for tests) overrides it.  Running out
 * (of the limit or of malloc) inside any call of this module is a GLPK
 * error: the thread's problems die and the next lp_solve returns
 * LP_ERROR (src/lib/lp.c, "Out of memory").  lp_mem_limit: the limit in
 * force (0: none); lp_memory_errors: how many GLPK errors, over all
 * threads since start, were out of memory. */
void lp_mem_limit_set(double mb);
int lp_mem_limit(void);
long lp_memory_errors(void);

/* Mixed-integer: mark a column binary; solve with branch and cut. */
void lp_set_binary(struct lp *p, int col);
enum lp_mip_status { LP_MIP_OPTIMAL, LP_MIP_FEASIBLE, LP_MIP_NOFEASIBLE,
		     LP_MIP_FAILED };
/* time_limit in seconds; *gap gets the relative MIP gap at the end.
 * Values are read with lp_mip_col and lp_mip_row. */
enum lp_mip_status lp_solve_mip(struct lp *p, double time_limit, double *gap);
double lp_mip_col(const struct lp *p, int col);
double lp_mip_row(const struct lp *p, int row);

#endif
