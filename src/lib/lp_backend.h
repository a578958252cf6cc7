/*
 * lp_backend.h - the seam between the LP layer (lp.c) and a solver
 * behind it (lp_glpk.c): a const table of functions, as GSL's
 * gsl_multimin_fminimizer_type or a sqlite VFS (docs/design.md, "The LP
 * layer").  Only lp.c and the backends include it.
 *
 * A backend allocates its solver and its problems with the generic part
 * first (struct lp_solver, struct lp) and its own state after it; lp.c
 * reads and writes the generic part, the backend everything.  Indices
 * are 0-based and bounds are -HUGE_VAL / HUGE_VAL for "none", as in
 * lp.h.  The statuses of variables are enum lp_var_stat.
 */
#ifndef SLIPWALL_LP_BACKEND_H
#define SLIPWALL_LP_BACKEND_H

#include "lp.h"

/* What every solver instance holds, whatever its backend: lp.h's
 * settings, counters and the state a stop leaves. */
struct lp_solver {
	const struct lp_type *type;
	struct lp_config cfg;
	struct lp_counters count;
	const atomic_int *stop;		/* lp_solver_stop_flag */
	int interrupted;		/* a solve returned LP_STOPPED */
	lp_progress_fn progress;	/* lp_solver_progress */
	void *progress_ctx;
	long fault_count;		/* solves, for cfg.fault_every */
	char message[256];		/* the solver's last line of text */
};

/* What every problem holds: its solver, its size, and the tie-break's
 * record of what it changed (lp.c). */
struct lp {
	struct lp_solver *s;
	int nrows, ncols;
	int last_iters;
	/* lp_set_shift_costs: a dual simplex from a dual infeasible start
	 * shifts costs instead of bounding variables artificially */
	int shift_costs;
	double *tb_obj;		/* ncols: the objective */
	int *tb_fixed;		/* rows then columns it fixed (columns as
				 * nrows + j) */
	int *tb_stat;		/* their status */
	double *tb_lb, *tb_ub;	/* and their bounds */
};

struct lp_type {
	const char *name;
	/* an instance (zeroed generic part; lp.c fills it), and its end */
	struct lp_solver *(*solver_new)(void);
	void (*solver_free)(struct lp_solver *s);
	/* the calling thread will use no solver again (lp_thread_done) */
	void (*thread_done)(void);

	/* problems: lp.h's functions of the same names */
	struct lp *(*prob_new)(struct lp_solver *s, int nrows, int ncols);
	void (*prob_free)(struct lp *p);
	int (*alive)(const struct lp *p);
	void (*clear)(struct lp *p);
	void (*set_maximize)(struct lp *p, int maximize);
	void (*set_refactor)(struct lp *p, int updates);
	int (*factor_updates)(const struct lp *p);
	int (*maximize)(const struct lp *p);
	void (*set_obj)(struct lp *p, int col, double c);
	double (*obj_coef)(const struct lp *p, int col);
	void (*set_col_bounds)(struct lp *p, int col, double lo, double hi);
	void (*set_row_bounds)(struct lp *p, int row, double lo, double hi);
	void (*col_bounds)(const struct lp *p, int col, double *lo, double *hi);
	void (*row_bounds)(const struct lp *p, int row, double *lo, double *hi);
	void (*set_col)(struct lp *p, int col, int n, const int *rows,
			const double *vals);
	void (*set_row)(struct lp *p, int row, int n, const int *cols,
			const double *vals);
	int (*get_col)(const struct lp *p, int col, int *rows, double *vals);

	/* bases: the status of each variable (rows' auxiliary variables and
	 * columns); setting one the solver's way (a non-basic status that
	 * does not fit the bounds is the one that does) */
	enum lp_var_stat (*col_stat)(const struct lp *p, int col);
	enum lp_var_stat (*row_stat)(const struct lp *p, int row);
	void (*set_col_stat)(struct lp *p, int col, enum lp_var_stat st);
	void (*set_row_stat)(struct lp *p, int row, enum lp_var_stat st);
	void (*reset_basis)(struct lp *p);
	void (*crash_basis)(struct lp *p);

	enum lp_status (*solve)(struct lp *p, enum lp_method m);
	double (*obj)(const struct lp *p);
	double (*col)(const struct lp *p, int col);
	double (*row)(const struct lp *p, int row);
	double (*col_dual)(const struct lp *p, int col);
	double (*row_dual)(const struct lp *p, int row);
	double (*feasibility_tol)(enum lp_method m);
	int (*solve_square)(struct lp_solver *s, int n, int nnz,
			    const int *ri, const int *ci, const double *v,
			    double *b);

	void (*set_binary)(struct lp *p, int col);
	enum lp_mip_status (*solve_mip)(struct lp *p, double time_limit,
					double *gap);
	double (*mip_col)(const struct lp *p, int col);
	double (*mip_row)(const struct lp *p, int row);
};

/* The backends. */
extern const struct lp_type lp_glpk;

#endif
