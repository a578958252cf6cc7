/*
 * lp.h - the LP layer: problems, bases, solves and the tie-break, over
 * an LP solver instance (docs/design.md, "The LP layer").
 *
 * A solver (struct lp_solver) is made with its settings (struct
 * lp_config: fault injection, a memory limit, an iteration limit) and
 * holds its counters, its stop flag and progress hook, and its last
 * message; every problem belongs to one solver.  Behind it is a backend
 * (lp_backend.h; today lp_glpk.c, the only file that names the solver
 * library).  The tie-break of "one answer per sample" and the saved
 * bases are written here once, over the generic calls (lp.c).
 *
 * Indices are 0-based.  Bounds use -HUGE_VAL / HUGE_VAL for "none".  A
 * problem keeps its basis between solves, so changing bounds, objective
 * or a column and solving again is a warm start (presolve is always
 * off).
 *
 * Threads: a solver and its problems are used on one thread.  The
 * backend's environment is the thread's: every thread that used a
 * solver calls lp_thread_done() before it exits (freeing the last solver
 * of a thread that holds no problem does it too).  An internal error of
 * the solver, or running out of memory, never aborts: the solve (or the
 * setter) returns, the thread's problems are dead (lp_alive), and the
 * next lp_solve of each returns LP_ERROR; lp_free() them (safe) and
 * build new ones.
 */
#ifndef SLIPWALL_LP_H
#define SLIPWALL_LP_H

#include <stdatomic.h>

enum lp_status {
	LP_OPTIMAL,
	LP_INFEASIBLE,	/* no primal feasible point */
	LP_UNBOUNDED,	/* feasible, objective unbounded */
	LP_FAILED,	/* the simplex gave up (singular basis, limit) */
	LP_ERROR,	/* the solver reported an internal error; problems
			 * dead */
	LP_STOPPED,	/* interrupted by the thread's stop flag; the
			 * thread's problems are dead (as after LP_ERROR) */
};

enum lp_method { LP_PRIMAL, LP_DUAL };

/* The status of a variable (a row's auxiliary variable or a column) in
 * a basis: basic, non-basic at its lower bound, at its upper bound,
 * free (at 0), fixed. */
enum lp_var_stat { LP_BS = 1, LP_NL, LP_NU, LP_NF, LP_NS };

/* How far a basic variable of an optimal solution by the simplex method
 * m may lie outside its bounds (absolute at a bound of 0): the solver's
 * feasibility tolerance as the backend sets it (lp_glpk.c: 1e-9 for the
 * dual simplex and 1e-8 for the primal, the tie-breaks).  A value this
 * small is not told from 0. */
double lp_feasibility_tol(enum lp_method m);

/* A solver's settings, passed by the front ends (the test variables
 * SLIPWALL_LP_FAULT, SLIPWALL_GLPK_MEM_MB: src/cli/, src/tui/, bench/). */
struct lp_config {
	/* Fault injection, for tests: every fault_every-th lp_solve of the
	 * solver (0: never) returns fault_as - LP_FAILED at once, or
	 * LP_ERROR by raising an error inside the solver's solve, so the
	 * recovery above runs for real. */
	long fault_every;
	enum lp_status fault_as;
	/* The limit of the solver's allocator on the thread, in MB (0:
	 * none): running out inside any call of this module is an internal
	 * error (problems dead, LP_ERROR; lp_glpk.c, "Out of memory").
	 * The first solver of a thread sets it for the thread. */
	int mem_limit_mb;
	/* The simplex's iteration limit (0: the default, 50,000 + 50
	 * (rows + columns)).  A solve that reaches the default is retried
	 * from an advanced basis and then from the slack basis, as any
	 * start the simplex cannot leave; one that reaches a limit set
	 * here is LP_FAILED at once: the caller wanted no more pivots
	 * (tests; a large wall's set-up, sample.c setup_large). */
	int iteration_limit;
};
void lp_config_default(struct lp_config *c);

struct lp_solver;
struct lp_solver *lp_solver_new(const struct lp_config *c);
/* Frees the solver, after its problems (lp_free); lp_thread_done() too
 * if the thread then holds no problem. */
void lp_solver_free(struct lp_solver *s);

/* What a solver did since it was made: solves, simplex iterations,
 * solves answered by the basis the solver held, without the simplex
 * (lp_glpk.c, "Held bases"), seconds inside lp_solve (monotonic clock),
 * and internal errors that were the solver running out of memory. */
struct lp_counters {
	long solves, iterations, held, memory_errors;
	/* dual simplex solves started from artificial bounds (lp_glpk.c),
	 * and those of them that went on without */
	long art, art_again;
	/* ... and from shifted costs (lp_set_shift_costs) */
	long shift;
	double seconds;
};
void lp_solver_counters(const struct lp_solver *s, struct lp_counters *c);
/* Interruption: while *flag is non-zero, lp_solve returns LP_STOPPED at
 * once, a solve already running stops within about a second, and a
 * problem being written dies (lp_glpk.c, "Interruption").  NULL: never.
 * Also clears the interrupted mark. */
void lp_solver_stop_flag(struct lp_solver *s, const atomic_int *flag);
/* Did an lp_solve of this solver return LP_STOPPED since the flag was
 * set?  The sample it belonged to is incomplete: discard it. */
int lp_solver_interrupted(const struct lp_solver *s);
/* Progress: fn(ctx, incumbent, bound) is called every half second
 * during a long simplex of lp_solve (both NAN), and about once a second
 * during lp_solve_mip (the incumbent's objective, NAN before one is
 * found, and the best bound of the open nodes).  fn must not call this
 * module.  NULL: never. */
typedef void (*lp_progress_fn)(void *ctx, double incumbent, double bound);
void lp_solver_progress(struct lp_solver *s, lp_progress_fn fn, void *ctx);
/* The solver's last line of text (an error's, for one). */
const char *lp_solver_message(const struct lp_solver *s);
/* For tests: change the fault injection of a made solver (its fault
 * count starts again from 0). */
void lp_solver_fault(struct lp_solver *s, long every, enum lp_status as);
/* Set the simplex's iteration limit of a made solver (lp_config's
 * iteration_limit; 0: the default); returns the limit it had. */
int lp_solver_iteration_limit(struct lp_solver *s, int limit);
/* The calling thread is done with LP solvers (see the top). */
void lp_thread_done(void);

struct lp;

struct lp *lp_new(struct lp_solver *s, int nrows, int ncols);
void lp_free(struct lp *p);
/* The solver p belongs to. */
struct lp_solver *lp_solver_of(const struct lp *p);
/* Is the problem usable (not dead after LP_ERROR or LP_STOPPED)? */
int lp_alive(const struct lp *p);
/* Back to what lp_new() left, the matrix kept: every row fixed at 0,
 * every column free, objective 0 and minimised, the standard basis and
 * no factorization (one reached by updates differs in the last bits
 * from one computed afresh).  For a caller that writes the problem
 * again and wants no trace of past solves (src/lib/sample_lp.c, sws_refill). */
void lp_clear(struct lp *p);

/* How the dual simplex starts from a basis that is dual feasible but for
 * a few non-basic columns whose reduced cost asks them off their bound
 * toward a side without one (lp_glpk.c, "Dual infeasible starts by
 * shifted costs"): off (the default), they get artificial bounds; on,
 * their costs are shifted until the dual simplex ends, and the primal
 * simplex finishes from there.  For re-solves of one objective after
 * bounds moved (the SLP's LP1 and LP2). */
void lp_set_shift_costs(struct lp *p, int on);
/* The basis factorization is computed afresh once it has taken
 * `updates` updates that each add a factor to it (a pivot's update
 * adds one unless nothing is left to eliminate); 0 is the solver's own
 * rule.  Each factor is work for every later FTRAN and BTRAN, and a
 * factorization afresh costs as much as some of them: which is cheaper
 * depends on the problem's size and how many pivots its solves take
 * (lp_glpk.c, glpk_set_refactor). */
void lp_set_refactor(struct lp *p, int updates);
/* The updates that the factorization the solver holds has had since it
 * was computed (0 when it holds none); for tests (test_lp). */
int lp_factor_updates(const struct lp *p);
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
 * iteration limit) it is retried from an advanced basis, and then from
 * the slack basis by the primal simplex.  A dual
 * simplex solve after bound changes only first tries the basis of the
 * last solve as it is (src/lib/lp_glpk.c, "Held bases"). */
enum lp_status lp_solve(struct lp *p, enum lp_method m);
/* Forget the basis (next solve starts from the standard basis). */
void lp_reset_basis(struct lp *p);
/* Start from the solver's advanced (crash) basis: deterministic, built from
 * the matrix alone, and usually far fewer pivots from optimal than the
 * standard (all-slack) basis. */
void lp_crash_basis(struct lp *p);
/* Start from the basis whose basic columns are those with cols[j] != 0:
 * every row non-basic (its auxiliary variable at its bound), every other
 * column non-basic at its bound (or 0 if free).  The caller makes it a
 * basis (as many basic columns as rows, non-singular); a singular one
 * is the solver's to repair (lp_solve). */
void lp_set_basis(struct lp *p, const unsigned char *cols);

/* A saved basis (row and column statuses), to warm-start a problem that
 * alternates between objectives from the basis each objective last
 * ended at.  A fresh basis is empty: lp_basis_load does nothing. */
struct lp_basis {
	int n;			/* 0: nothing saved */
	int *stat;		/* rows then columns */
};
void lp_basis_save(const struct lp *p, struct lp_basis *b);
/* b sized for n statuses (rows then columns), to be written by the
 * caller: a basis built for another problem (its statuses are undefined
 * when the size changed); returns b->stat */
int *lp_basis_size(struct lp_basis *b, int n);
void lp_basis_load(struct lp *p, const struct lp_basis *b);
void lp_basis_free(struct lp_basis *b);
/* dst becomes a copy of src (plain data: another thread's problem of
 * the same shape may load it) */
void lp_basis_copy(struct lp_basis *dst, const struct lp_basis *src);
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
 * position adds up), by the solver's sparse LU (of the basis matrix of
 * a throw-away problem).  b is replaced by y.  Returns 0, or -1 if M is
 * singular or too ill-conditioned for the LU, or after an internal
 * error (out of memory: the thread's problems are then dead, as after
 * LP_ERROR). */
int lp_solve_square(struct lp_solver *s, int n, int nnz, const int *ri,
		    const int *ci, const double *v, double *b);
/* 1 if the optimum is unique as far as the reduced costs tell: no
 * non-basic variable (except fixed ones) has a zero reduced cost. */
int lp_unique(const struct lp *p, double tol);
/* The tie-break of "one answer per sample" (docs/method.md; lp.c), right
 * after an LP_OPTIMAL solve of p: if some non-basic variable has a
 * reduced cost |d| <= tol, the optimum may not be unique, and p is
 * solved again over its optimal face (every non-basic variable with
 * |d| > tol held where it is) with the objective "minimise c2 . x" (c2:
 * one coefficient per column), by the primal simplex from the optimal
 * basis.  The problem's bounds, objective and sense are then restored;
 * the values lp_col and lp_row read are the tie-break's.  *solved: 1 if
 * that LP was solved (it counts as a solve), 0 if the optimum was
 * unique.  Returns LP_OPTIMAL, or the failed tie-break's status
 * (LP_ERROR, LP_STOPPED: as lp_solve). */
enum lp_status lp_tiebreak(struct lp *p, const double *c2, double tol,
			   int *solved);
/* The tie-break below an optimum (docs/method.md, "The SLP's start":
 * LP-max's floor): minimise c2 . x over the feasible points whose
 * column col is at least lo, by the primal simplex from the basis the
 * problem holds (the caller chooses it); then col's bounds, the
 * objective and its sense are put back, and the solution the solver
 * stores is the tie-break's.  Unlike lp_tiebreak it does not read the
 * reduced costs of an optimum, so its answer does not depend on which
 * optimal basis, or how near the optimum, the first solve ended. */
enum lp_status lp_tiebreak_floor(struct lp *p, const double *c2, int col,
				 double lo, int *solved);
/* Simplex iterations of the last solve. */
int lp_last_iterations(const struct lp *p);

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
