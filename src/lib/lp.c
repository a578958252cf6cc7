/*
 * lp.c - the LP layer above the seam: solver instances, the generic
 * calls over a backend's table (lp_backend.h; today lp_glpk.c), and
 * what is written once for every backend - saved bases, the uniqueness
 * test and the tie-break of "one answer per sample" (docs/method.md,
 * docs/design.md "The LP layer").  See lp.h.
 *
 * Nothing here is thread-local or static: a solver's state is in its
 * instance, a thread's (the backend's environment) in the backend.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lp_backend.h"
#include "slipwall/status.h"
#include "slipwall/sys.h"

/* The backend of every solver (one today). */
static const struct lp_type *const backend = &lp_glpk;

void lp_config_default(struct lp_config *c)
{
	memset(c, 0, sizeof *c);
	c->fault_as = LP_FAILED;
}

struct lp_solver *lp_solver_new(const struct lp_config *c)
{
	struct lp_solver *s = backend->solver_new();
	s->type = backend;
	if (c)
		s->cfg = *c;
	else
		lp_config_default(&s->cfg);
	if (s->cfg.fault_every < 0)
		s->cfg.fault_every = 0;
	if (s->cfg.fault_as != LP_ERROR)
		s->cfg.fault_as = LP_FAILED;
	return s;
}

void lp_solver_free(struct lp_solver *s)
{
	if (s)
		s->type->solver_free(s);
}

void lp_solver_counters(const struct lp_solver *s, struct lp_counters *c)
{
	*c = s->count;
}

void lp_solver_stop_flag(struct lp_solver *s, const atomic_int *flag)
{
	s->stop = flag;
	s->interrupted = 0;
}

int lp_solver_interrupted(const struct lp_solver *s)
{
	return s->interrupted;
}

void lp_solver_progress(struct lp_solver *s, lp_progress_fn fn, void *ctx)
{
	s->progress = fn;
	s->progress_ctx = ctx;
}

const char *lp_solver_message(const struct lp_solver *s)
{
	return s->message;
}

void lp_solver_fault(struct lp_solver *s, long every, enum lp_status as)
{
	s->cfg.fault_every = every > 0 ? every : 0;
	s->cfg.fault_as = as == LP_ERROR ? LP_ERROR : LP_FAILED;
	s->fault_count = 0;
}

int lp_solver_iteration_limit(struct lp_solver *s, int limit)
{
	int was = s->cfg.iteration_limit;
	s->cfg.iteration_limit = limit > 0 ? limit : 0;
	return was;
}

void lp_thread_done(void)
{
	backend->thread_done();
}

double lp_feasibility_tol(enum lp_method m)
{
	return backend->feasibility_tol(m);
}

/* Problems: the backend's calls. */
struct lp *lp_new(struct lp_solver *s, int nrows, int ncols)
{
	return s->type->prob_new(s, nrows, ncols);
}

void lp_free(struct lp *p)
{
	if (!p)
		return;
	free(p->tb_obj);
	free(p->tb_fixed);
	free(p->tb_stat);
	free(p->tb_lb);
	free(p->tb_ub);
	p->s->type->prob_free(p);
}

#define T(p) ((p)->s->type)

struct lp_solver *lp_solver_of(const struct lp *p) { return p->s; }

int lp_alive(const struct lp *p) { return p && T(p)->alive(p); }
void lp_clear(struct lp *p) { T(p)->clear(p); }
void lp_set_maximize(struct lp *p, int maximize) { T(p)->set_maximize(p, maximize); }
void lp_set_shift_costs(struct lp *p, int on) { p->shift_costs = on; }
void lp_set_refactor(struct lp *p, int updates) { T(p)->set_refactor(p, updates); }
int lp_factor_updates(const struct lp *p) { return T(p)->factor_updates(p); }
void lp_set_obj(struct lp *p, int col, double c) { T(p)->set_obj(p, col, c); }

void lp_set_col_bounds(struct lp *p, int col, double lo, double hi)
{
	T(p)->set_col_bounds(p, col, lo, hi);
}

void lp_set_row_bounds(struct lp *p, int row, double lo, double hi)
{
	T(p)->set_row_bounds(p, row, lo, hi);
}

void lp_set_col(struct lp *p, int col, int n, const int *rows,
		const double *vals)
{
	T(p)->set_col(p, col, n, rows, vals);
}

void lp_set_row(struct lp *p, int row, int n, const int *cols,
		const double *vals)
{
	T(p)->set_row(p, row, n, cols, vals);
}

enum lp_status lp_solve(struct lp *p, enum lp_method m) { return T(p)->solve(p, m); }
void lp_reset_basis(struct lp *p) { T(p)->reset_basis(p); }
void lp_crash_basis(struct lp *p) { T(p)->crash_basis(p); }
double lp_obj(const struct lp *p) { return T(p)->obj(p); }
double lp_col(const struct lp *p, int col) { return T(p)->col(p, col); }
double lp_row(const struct lp *p, int row) { return T(p)->row(p, row); }
double lp_col_dual(const struct lp *p, int col) { return T(p)->col_dual(p, col); }
double lp_row_dual(const struct lp *p, int row) { return T(p)->row_dual(p, row); }
int lp_last_iterations(const struct lp *p) { return p->last_iters; }
int lp_col_basic(const struct lp *p, int col) { return T(p)->col_stat(p, col) == LP_BS; }
int lp_row_basic(const struct lp *p, int row) { return T(p)->row_stat(p, row) == LP_BS; }

int lp_get_col(const struct lp *p, int col, int *rows, double *vals)
{
	return T(p)->get_col(p, col, rows, vals);
}

int lp_solve_square(struct lp_solver *s, int n, int nnz, const int *ri,
		    const int *ci, const double *v, double *b)
{
	return s->type->solve_square(s, n, nnz, ri, ci, v, b);
}

void lp_set_binary(struct lp *p, int col) { T(p)->set_binary(p, col); }

enum lp_mip_status lp_solve_mip(struct lp *p, double time_limit, double *gap)
{
	return T(p)->solve_mip(p, time_limit, gap);
}

double lp_mip_col(const struct lp *p, int col) { return T(p)->mip_col(p, col); }
double lp_mip_row(const struct lp *p, int row) { return T(p)->mip_row(p, row); }

/* Bases, over the variables' statuses. */
void lp_set_basis(struct lp *p, const unsigned char *cols)
{
	if (!lp_alive(p))
		return;
	/* a non-basic status that does not fit the variable's bounds is
	 * taken as the one that does (NL for a fixed row is NS, for a free
	 * column NF) */
	for (int i = 0; i < p->nrows; i++)
		T(p)->set_row_stat(p, i, LP_NL);
	for (int j = 0; j < p->ncols; j++)
		T(p)->set_col_stat(p, j, cols[j] ? LP_BS : LP_NL);
}

void lp_basis_save(const struct lp *p, struct lp_basis *b)
{
	if (!lp_alive(p))	/* after LP_ERROR or LP_STOPPED: nothing to save */
		return;
	lp_basis_size(b, p->nrows + p->ncols);
	for (int i = 0; i < p->nrows; i++)
		b->stat[i] = (int)T(p)->row_stat(p, i);
	for (int j = 0; j < p->ncols; j++)
		b->stat[p->nrows + j] = (int)T(p)->col_stat(p, j);
}

int *lp_basis_size(struct lp_basis *b, int n)
{
	if (b->n != n) {
		free(b->stat);
		b->stat = sw_xmalloc(sizeof(int) * (size_t)(n + 1));
		b->n = n;
	}
	return b->stat;
}

void lp_basis_load(struct lp *p, const struct lp_basis *b)
{
	if (!lp_alive(p))
		return;
	if (b->n != p->nrows + p->ncols)
		return;
	for (int i = 0; i < p->nrows; i++)
		T(p)->set_row_stat(p, i, (enum lp_var_stat)b->stat[i]);
	for (int j = 0; j < p->ncols; j++)
		T(p)->set_col_stat(p, j, (enum lp_var_stat)b->stat[p->nrows + j]);
}

void lp_basis_copy(struct lp_basis *dst, const struct lp_basis *src)
{
	if (src->n <= 0) {
		lp_basis_free(dst);
		return;
	}
	memcpy(lp_basis_size(dst, src->n), src->stat,
	       sizeof(int) * (size_t)src->n);
}

unsigned long lp_basis_hash(const struct lp *p)
{
	if (!lp_alive(p))
		return 0;
	unsigned long long h = 1469598103934665603ULL;	/* FNV-1a */
	for (int i = 0; i < p->nrows; i++)
		h = (h ^ (unsigned)T(p)->row_stat(p, i)) * 1099511628211ULL;
	for (int j = 0; j < p->ncols; j++)
		h = (h ^ (unsigned)T(p)->col_stat(p, j)) * 1099511628211ULL;
	return (unsigned long)h;
}

void lp_basis_free(struct lp_basis *b)
{
	free(b->stat);
	b->stat = NULL;
	b->n = 0;
}

/*
 * Tie-break (docs/method.md, "One answer per sample").  The optimal face
 * of the LP just solved is, by complementary slackness with the dual
 * solution the solver holds, the set of feasible points at which every
 * non-basic variable with a non-zero reduced cost stays where it is (this
 * holds for any optimal dual solution, so the face does not depend on
 * which optimal basis the simplex reached).  A variable is "non-zero"
 * when |d| > tol.  When no non-basic variable has |d| <= tol the optimum
 * is unique and nothing is solved.  Otherwise those variables are fixed
 * (lower bound = upper bound), the objective becomes c2 (minimised),
 * and the primal simplex starts from the optimal basis, which stays
 * primal feasible.  Afterwards the bounds, the statuses of the fixed
 * variables, the objective and its sense are put back as they were; the
 * solution the solver stores (lp_col, lp_row) is the tie-break's.
 */
static int tb_nonzero(enum lp_var_stat stat, double d, double tol)
{
	return stat != LP_BS && stat != LP_NS && fabs(d) > tol;
}

static int tb_zero(enum lp_var_stat stat, double d, double tol)
{
	return stat != LP_BS && stat != LP_NS && !(fabs(d) > tol);
}

int lp_unique(const struct lp *p, double tol)
{
	for (int j = 0; j < p->ncols; j++) {
		enum lp_var_stat st = T(p)->col_stat(p, j);
		if (st != LP_BS && st != LP_NS &&
		    fabs(T(p)->col_dual(p, j)) <= tol)
			return 0;
	}
	for (int i = 0; i < p->nrows; i++) {
		enum lp_var_stat st = T(p)->row_stat(p, i);
		if (st != LP_BS && st != LP_NS &&
		    fabs(T(p)->row_dual(p, i)) <= tol)
			return 0;
	}
	return 1;
}

/* Where a non-basic variable of status st with bounds [lo, hi] and
 * value x stays: at the bound it is at, or (free) where it is. */
static double tb_value(enum lp_var_stat st, double lo, double hi, double x)
{
	if (st == LP_NF)
		return x;
	return st == LP_NU ? hi : lo;
}

/* The tie-breaks' objective: minimise c2 . x; the problem's own
 * coefficients saved in p->tb_obj, its sense returned, for
 * tb_objective_restore. */
static int tb_objective_set(struct lp *p, const double *c2)
{
	const struct lp_type *t = T(p);
	if (!p->tb_obj)
		p->tb_obj = sw_xmalloc(sizeof(double) * (size_t)(p->ncols + 1));
	int maximize = t->maximize(p);
	for (int j = 0; j < p->ncols; j++) {
		p->tb_obj[j] = t->obj_coef(p, j);
		t->set_obj(p, j, c2[j]);
	}
	t->set_maximize(p, 0);
	return maximize;
}

static void tb_objective_restore(struct lp *p, int maximize)
{
	const struct lp_type *t = T(p);
	for (int j = 0; j < p->ncols; j++)
		t->set_obj(p, j, p->tb_obj[j]);
	t->set_maximize(p, maximize);
}

enum lp_status lp_tiebreak(struct lp *p, const double *c2, double tol,
			   int *solved)
{
	*solved = 0;
	if (!lp_alive(p))
		return LP_ERROR;
	const struct lp_type *t = T(p);
	int n = p->nrows + p->ncols, tie = 0;
	for (int i = 0; i < p->nrows && !tie; i++)
		tie = tb_zero(t->row_stat(p, i), t->row_dual(p, i), tol);
	for (int j = 0; j < p->ncols && !tie; j++)
		tie = tb_zero(t->col_stat(p, j), t->col_dual(p, j), tol);
	if (!tie)
		return LP_OPTIMAL;
	if (!p->tb_fixed) {
		p->tb_fixed = sw_xmalloc(sizeof(int) * (size_t)(n + 1));
		p->tb_stat = sw_xmalloc(sizeof(int) * (size_t)(n + 1));
		p->tb_lb = sw_xmalloc(sizeof(double) * (size_t)(n + 1));
		p->tb_ub = sw_xmalloc(sizeof(double) * (size_t)(n + 1));
	}
	int nf = 0, maximize = tb_objective_set(p, c2);
	for (int i = 0; i < p->nrows; i++) {
		enum lp_var_stat st = t->row_stat(p, i);
		if (!tb_nonzero(st, t->row_dual(p, i), tol))
			continue;
		p->tb_fixed[nf] = i;
		p->tb_stat[nf] = (int)st;
		t->row_bounds(p, i, &p->tb_lb[nf], &p->tb_ub[nf]);
		double v = tb_value(st, p->tb_lb[nf], p->tb_ub[nf],
				    st == LP_NF ? t->row(p, i) : 0);
		t->set_row_bounds(p, i, v, v);
		nf++;
	}
	for (int j = 0; j < p->ncols; j++) {
		enum lp_var_stat st = t->col_stat(p, j);
		if (!tb_nonzero(st, t->col_dual(p, j), tol))
			continue;
		p->tb_fixed[nf] = p->nrows + j;
		p->tb_stat[nf] = (int)st;
		t->col_bounds(p, j, &p->tb_lb[nf], &p->tb_ub[nf]);
		double v = tb_value(st, p->tb_lb[nf], p->tb_ub[nf],
				    st == LP_NF ? t->col(p, j) : 0);
		t->set_col_bounds(p, j, v, v);
		nf++;
	}
	enum lp_status st = lp_solve(p, LP_PRIMAL);
	*solved = 1;
	if (!lp_alive(p))
		return st;
	/* put the problem back; the statuses first fixed by the tie-break
	 * are those of the primary optimum, still valid (a fixed variable
	 * never enters the basis) */
	for (int f = 0; f < nf; f++) {
		int k = p->tb_fixed[f];
		enum lp_var_stat s0 = (enum lp_var_stat)p->tb_stat[f];
		if (k < p->nrows) {
			t->set_row_bounds(p, k, p->tb_lb[f], p->tb_ub[f]);
			if (t->row_stat(p, k) != LP_BS)
				t->set_row_stat(p, k, s0);
		} else {
			k -= p->nrows;
			t->set_col_bounds(p, k, p->tb_lb[f], p->tb_ub[f]);
			if (t->col_stat(p, k) != LP_BS)
				t->set_col_stat(p, k, s0);
		}
	}
	tb_objective_restore(p, maximize);
	return st;
}

enum lp_status lp_tiebreak_floor(struct lp *p, const double *c2, int col,
				 double lo, int *solved)
{
	*solved = 0;
	if (!lp_alive(p))
		return LP_ERROR;
	const struct lp_type *t = T(p);
	double lo0, hi0;
	t->col_bounds(p, col, &lo0, &hi0);
	int maximize = tb_objective_set(p, c2);
	t->set_col_bounds(p, col, lo, hi0);
	enum lp_status st = lp_solve(p, LP_PRIMAL);
	*solved = 1;
	if (!lp_alive(p))
		return st;
	/* a lower bound relaxed: the basis stays primal feasible */
	t->set_col_bounds(p, col, lo0, hi0);
	tb_objective_restore(p, maximize);
	return st;
}
