/*
 * test_lp.c - the LP layer's held bases (src/lib/lp_glpk.c): after bound
 * changes, a dual simplex solve takes the basis GLPK holds as it is when
 * it is still optimal, and only then; and a solver instance's state (its
 * counters, its stop flag) is its own.  On a 2 x 2 LP whose every answer
 * is known in closed form:
 *
 *   max x + y   s.t.   x + 2y <= b1,   3x + y <= b2,   x, y >= 0
 *
 * At (b1, b2) = (4, 6) both rows bind: x = (2 b2 - b1)/5, y = (3 b1 -
 * b2)/5, the optimum is x + y = (2 b1 + b2)/5 while both are >= 0.  For
 * b1 > 3 b2 row 1 is slack and the optimum is x = 0, y = b2.
 */
#include <assert.h>
#include <math.h>
#include <stdatomic.h>

#include "lp.h"
#include "tap.h"

static struct lp_solver *S;

static long held_count(void)
{
	struct lp_counters c;
	lp_solver_counters(S, &c);
	return c.held;
}

static struct lp *two_by_two(double b1, double b2)
{
	struct lp *p = lp_new(S, 2, 2);
	int cols[2] = {0, 1};
	double r1[2] = {1, 2}, r2[2] = {3, 1};
	lp_set_row(p, 0, 2, cols, r1);
	lp_set_row(p, 1, 2, cols, r2);
	lp_set_row_bounds(p, 0, -HUGE_VAL, b1);
	lp_set_row_bounds(p, 1, -HUGE_VAL, b2);
	lp_set_col_bounds(p, 0, 0, HUGE_VAL);
	lp_set_col_bounds(p, 1, 0, HUGE_VAL);
	lp_set_obj(p, 0, 1);
	lp_set_obj(p, 1, 1);
	lp_set_maximize(p, 1);
	return p;
}

static struct lp_counters counters(void)
{
	struct lp_counters c;
	lp_solver_counters(S, &c);
	return c;
}

/* A problem of one row, max x + y s.t. a x + b y <= r, x, y >= 0,
 * solved with x held at 0 (y basic, x's reduced cost asks it up), then
 * x freed: a start that is dual infeasible where GLPK cannot flip a
 * bound, which lp_glpk.c starts from x on an artificial upper bound. */
static struct lp *one_row(double a, double b, double r)
{
	struct lp *p = lp_new(S, 1, 2);
	int cols[2] = {0, 1};
	double row[2] = {a, b};
	lp_set_row(p, 0, 2, cols, row);
	lp_set_row_bounds(p, 0, -HUGE_VAL, r);
	lp_set_col_bounds(p, 0, 0, 0);
	lp_set_col_bounds(p, 1, 0, HUGE_VAL);
	lp_set_obj(p, 0, 1);
	lp_set_obj(p, 1, 1);
	lp_set_maximize(p, 1);
	return p;
}

/* Artificial bounds (lp_glpk.c, "Artificial bounds"): the answer is the
 * problem's own whether the artificial bound is redundant, holds the
 * optimum (the solve goes on without it), or stands for an unbounded
 * direction. */
static void artificial_bounds(void)
{
	/* x + 2y <= 4 with 3x + y <= 6 of two_by_two: x freed after y = 2 */
	struct lp *p = two_by_two(4, 6);
	lp_set_col_bounds(p, 0, 0, 0);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL && fabs(lp_obj(p) - 2) < 1e-12,
	       "x held at 0: y = 2");
	struct lp_counters c0 = counters();
	lp_set_col_bounds(p, 0, 0, HUGE_VAL);
	enum lp_status st = lp_solve(p, LP_DUAL);
	struct lp_counters c1 = counters();
	tap_ok(st == LP_OPTIMAL && c1.art == c0.art + 1 &&
	       c1.art_again == c0.art_again,
	       "x freed: from an artificial bound, which the optimum leaves");
	tap_near(lp_col(p, 0), 1.6, 1e-12, "x = (2 b2 - b1)/5 = 1.6");
	tap_near(lp_col(p, 1), 1.2, 1e-12, "y = (3 b1 - b2)/5 = 1.2");
	/* the bound put back: x may now go beyond the artificial one */
	lp_set_row_bounds(p, 0, -HUGE_VAL, 4e4);
	lp_set_row_bounds(p, 1, -HUGE_VAL, 6e4);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL, "rows scaled by 1e4: optimal");
	tap_near(lp_obj(p), 2.8e4, 1e-8, "x's own bound is back: 2.8e4");
	lp_free(p);

	/* 1e-4 x + 2 y <= 4: the optimum x = 4e4 lies beyond the artificial
	 * bound (1e3 times the right-hand side 4), which holds the first
	 * optimum at x = 4e3; the solve goes on without it */
	p = one_row(1e-4, 2, 4);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL, "x held at 0: y = 2");
	c0 = counters();
	lp_set_col_bounds(p, 0, 0, HUGE_VAL);
	st = lp_solve(p, LP_DUAL);
	c1 = counters();
	tap_ok(st == LP_OPTIMAL && c1.art == c0.art + 1 &&
	       c1.art_again == c0.art_again + 1,
	       "x freed: the artificial bound holds the optimum, so again without");
	tap_near(lp_obj(p), 4e4, 1e-6, "optimum x = 4e4, y = 0");
	lp_free(p);

	/* -x + y <= 1: x unbounded above; from the artificial bound the
	 * optimum holds x on it, and without it the problem is unbounded */
	p = one_row(-1, 1, 1);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL, "x held at 0: y = 1");
	c0 = counters();
	lp_set_col_bounds(p, 0, 0, HUGE_VAL);
	st = lp_solve(p, LP_DUAL);
	c1 = counters();
	tap_ok(st == LP_UNBOUNDED && c1.art_again == c0.art_again + 1,
	       "x freed along an unbounded ray: unbounded, not the artificial optimum");
	lp_free(p);
}

/* Shifted costs (lp_glpk.c, "Dual infeasible starts by shifted costs"):
 * the same starts as artificial_bounds's, on a problem that asks for
 * them, give the problem's own answers (the shifted optimum lies at
 * x = 0, y = 2; the primal simplex takes it from there), an infeasible
 * problem stays infeasible, and an unbounded one unbounded. */
static void shifted_costs(void)
{
	struct lp *p = two_by_two(4, 6);
	lp_set_shift_costs(p, 1);
	lp_set_col_bounds(p, 0, 0, 0);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL && fabs(lp_obj(p) - 2) < 1e-12,
	       "shifted costs: x held at 0: y = 2");
	struct lp_counters c0 = counters();
	lp_set_col_bounds(p, 0, 0, HUGE_VAL);
	enum lp_status st = lp_solve(p, LP_DUAL);
	struct lp_counters c1 = counters();
	tap_ok(st == LP_OPTIMAL && c1.shift == c0.shift + 1 && c1.art == c0.art,
	       "x freed: from a shifted cost, no artificial bound");
	tap_near(lp_col(p, 0), 1.6, 1e-12, "x = 1.6 with the own costs");
	tap_near(lp_col(p, 1), 1.2, 1e-12, "y = 1.2");
	tap_near(lp_obj(p), 2.8, 1e-12, "the own objective: x + y = 2.8");
	lp_free(p);

	/* 1e-4 x + 2 y <= 4: x = 4e4, where an artificial bound would have
	 * held it at 4e3 */
	p = one_row(1e-4, 2, 4);
	lp_set_shift_costs(p, 1);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL, "shifted costs: x held at 0: y = 2");
	lp_set_col_bounds(p, 0, 0, HUGE_VAL);
	c0 = counters();
	st = lp_solve(p, LP_DUAL);
	c1 = counters();
	tap_ok(st == LP_OPTIMAL && c1.shift == c0.shift + 1,
	       "x freed: from a shifted cost");
	tap_near(lp_obj(p), 4e4, 1e-6, "optimum x = 4e4, y = 0");
	lp_free(p);

	/* -x + y <= 1: x unbounded above */
	p = one_row(-1, 1, 1);
	lp_set_shift_costs(p, 1);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL, "shifted costs: x held at 0: y = 1");
	lp_set_col_bounds(p, 0, 0, HUGE_VAL);
	c0 = counters();
	st = lp_solve(p, LP_DUAL);
	c1 = counters();
	tap_ok(st == LP_UNBOUNDED && c1.shift == c0.shift + 1,
	       "x freed along an unbounded ray: unbounded");
	lp_free(p);

	/* 1e-4 x + 2 y <= 4 with y >= 3 once x is freed: no feasible point,
	 * found by the dual simplex on the shifted costs */
	p = one_row(1e-4, 2, 4);
	lp_set_shift_costs(p, 1);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL, "shifted costs: x held at 0: y = 2");
	lp_set_col_bounds(p, 0, 0, HUGE_VAL);
	lp_set_col_bounds(p, 1, 3, HUGE_VAL);
	c0 = counters();
	st = lp_solve(p, LP_DUAL);
	c1 = counters();
	tap_ok(st == LP_INFEASIBLE && c1.shift == c0.shift + 1,
	       "y >= 3 with 2 y <= 4: infeasible");
	lp_free(p);
}

/* A dense LP: max sum (1 + j/100) x_j s.t. sum_j a_ij x_j <= 1 + i/10,
 * x >= 0, with every a_ij in [1, 2); n <= DENSE_MAX. */
enum { DENSE_MAX = 64 };
static struct lp *dense(int n)
{
	assert(n <= DENSE_MAX);
	struct lp *p = lp_new(S, n, n);
	int cols[DENSE_MAX];
	double v[DENSE_MAX];
	for (int i = 0; i < n; i++) {
		for (int j = 0; j < n; j++) {
			cols[j] = j;
			v[j] = 1 + (double)((7 * i + 13 * j + i * j) % 11) / 10;
		}
		lp_set_row(p, i, n, cols, v);
		lp_set_row_bounds(p, i, -HUGE_VAL, 1 + i / 10.0);
	}
	for (int j = 0; j < n; j++) {
		lp_set_col_bounds(p, j, 0, HUGE_VAL);
		lp_set_obj(p, j, 1 + j / 100.0);
	}
	lp_set_maximize(p, 1);
	return p;
}

/* lp_set_refactor: the factorization is computed afresh once its
 * updates have added that many factors, across solves (on a dense LP
 * every update adds one), and the optimum is the same. */
static void refactor(void)
{
	enum { N = 30 };
	struct lp *a = dense(N), *b = dense(N);
	lp_set_refactor(b, 3);
	int most_a = 0, most_b = 0, ok = 1;
	for (int k = 0; k < 6; k++) {
		if (k > 0)	/* re-solves after bounds moved */
			for (int i = k; i < N; i += 3) {
				lp_set_row_bounds(a, i, -HUGE_VAL, 2 + (i + k) % 5 / 7.0);
				lp_set_row_bounds(b, i, -HUGE_VAL, 2 + (i + k) % 5 / 7.0);
			}
		enum lp_method m = k == 0 ? LP_PRIMAL : LP_DUAL;
		ok = ok && lp_solve(a, m) == LP_OPTIMAL &&
		     lp_solve(b, m) == LP_OPTIMAL &&
		     fabs(lp_obj(a) - lp_obj(b)) <= 1e-12 * fabs(lp_obj(a));
		most_a = lp_factor_updates(a) > most_a ? lp_factor_updates(a) : most_a;
		most_b = lp_factor_updates(b) > most_b ? lp_factor_updates(b) : most_b;
	}
	tap_ok(ok, "six solves of a dense 30 x 30 LP: the same optimum with "
		   "the factorization afresh after 3 updates as with the default");
	tap_ok(most_a > 3 && most_b <= 3,
	       "updates held: at most 3 when set (%d), more by default (%d)",
	       most_b, most_a);
	lp_free(a);
	lp_free(b);
}

int main(void)
{
	S = lp_solver_new(NULL);
	struct lp *p = two_by_two(4, 6);
	long h0 = held_count();
	enum lp_status st = lp_solve(p, LP_DUAL);
	tap_ok(st == LP_OPTIMAL && held_count() == h0 &&
	       lp_last_iterations(p) > 0,
	       "first solve: the simplex (%d pivots), no held basis yet",
	       lp_last_iterations(p));
	tap_near(lp_obj(p), 2.8, 1e-12, "optimum (8 + 6)/5 = 2.8");

	/* a small change of b1: the same basis stays optimal */
	lp_set_row_bounds(p, 0, -HUGE_VAL, 4.2);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL && held_count() == h0 + 1 &&
	       lp_last_iterations(p) == 0,
	       "b1 = 4.2: answered by the held basis, no pivot");
	tap_near(lp_col(p, 0), (12 - 4.2) / 5, 1e-14, "x = (2 b2 - b1)/5");
	tap_near(lp_col(p, 1), (12.6 - 6) / 5, 1e-14, "y = (3 b1 - b2)/5");
	tap_near(lp_obj(p), (8.4 + 6) / 5, 1e-14, "objective (2 b1 + b2)/5");
	tap_near(lp_row_dual(p, 0), 0.4, 1e-14, "dual of row 1 = 2/5");

	/* b1 far away: that basis gives x < 0, the simplex must move */
	lp_set_row_bounds(p, 0, -HUGE_VAL, 20);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL && held_count() == h0 + 1 &&
	       lp_last_iterations(p) > 0,
	       "b1 = 20: the held basis is infeasible, the simplex pivots");
	tap_near(lp_obj(p), 6, 1e-12, "optimum x = 0, y = b2 = 6");
	tap_near(lp_col(p, 0), 0, 1e-12, "x = 0");

	/* an objective change is not a bound change: never held */
	lp_set_obj(p, 0, 1.5);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL && held_count() == h0 + 1,
	       "new objective coefficient: solved by the simplex");
	tap_near(lp_obj(p), 6, 1e-12, "max 1.5 x + y is still 6 at (0, 6)");

	/* the primal simplex never takes the held path */
	lp_set_row_bounds(p, 0, -HUGE_VAL, 21);
	tap_ok(lp_solve(p, LP_PRIMAL) == LP_OPTIMAL && held_count() == h0 + 1,
	       "primal simplex after a bound change: not held");

	/* y <= 5 cuts the held vertex (0, 6) off */
	lp_set_col_bounds(p, 1, 0, 5);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL && held_count() == h0 + 1,
	       "y <= 5: the held vertex (0, 6) is cut off, the simplex");
	tap_near(lp_obj(p), 1.5 / 3 + 5, 1e-12,
		 "optimum y = 5, 3x + y = 6: x = 1/3, 1.5 x + y = 5.5");

	/* y's bound removed: y, non-basic at 5, drops to its lower bound 0
	 * (GLPK's status for a new bound type); that basis is primal
	 * feasible (x = 2) but y's reduced cost 1 - 1.5/3 > 0 says raise y:
	 * not optimal, whatever the primal values say */
	lp_set_col_bounds(p, 1, 0, HUGE_VAL);
	tap_ok(lp_solve(p, LP_DUAL) == LP_OPTIMAL && held_count() == h0 + 1,
	       "y free again: primal feasible but dual infeasible, the simplex");
	tap_near(lp_obj(p), 6, 1e-12, "optimum back at (0, 6), not 3 at (2, 0)");
	lp_free(p);

	artificial_bounds();
	shifted_costs();
	refactor();

	/* a stop request while problems are written (the workbench stops
	 * its workers at every edit): a problem written or made after it is
	 * dead at once, not half-written: once the stop is withdrawn its
	 * solve fails (LP_ERROR), where a whole problem would solve */
	atomic_int stop = 0;
	lp_solver_stop_flag(S, &stop);
	int col_rows[1] = {0};
	double col_vals[1] = {1};
	p = lp_new(S, 1, 2);
	lp_set_col(p, 0, 1, col_rows, col_vals);
	lp_set_col(p, 1, 1, col_rows, col_vals);
	tap_ok(lp_solve(p, LP_PRIMAL) == LP_OPTIMAL,
	       "written whole before any stop: solved");
	lp_free(p);
	p = lp_new(S, 1, 2);
	lp_set_col(p, 0, 1, col_rows, col_vals);
	atomic_store(&stop, 1);
	lp_set_col(p, 1, 1, col_rows, col_vals);
	tap_ok(lp_solve(p, LP_PRIMAL) == LP_STOPPED && lp_solver_interrupted(S),
	       "stopped while its columns were written: the solve says so");
	atomic_store(&stop, 0);
	tap_ok(lp_solve(p, LP_PRIMAL) == LP_ERROR,
	       "... and the problem is dead, not half-written");
	lp_free(p);
	atomic_store(&stop, 1);
	p = lp_new(S, 1, 2);
	atomic_store(&stop, 0);
	tap_ok(lp_solve(p, LP_PRIMAL) == LP_ERROR,
	       "made after the stop: dead");
	lp_free(p);

	/* two solvers on one thread: the stop flag and the counters are
	 * each one's own */
	struct lp_solver *S2 = lp_solver_new(NULL);
	atomic_store(&stop, 1);
	struct lp_counters c0, c1, d1;
	lp_solver_counters(S2, &c0);
	struct lp *q = lp_new(S2, 1, 2);
	lp_set_col(q, 0, 1, col_rows, col_vals);
	lp_set_col(q, 1, 1, col_rows, col_vals);
	tap_ok(lp_solve(q, LP_PRIMAL) == LP_OPTIMAL && !lp_solver_interrupted(S2),
	       "a second solver: the first one's stop flag is not its own");
	lp_solver_counters(S2, &c1);
	lp_solver_counters(S, &d1);
	tap_ok(c1.solves == c0.solves + 1 && d1.solves > c1.solves,
	       "... and its counters neither (%ld solves, the first %ld)",
	       c1.solves, d1.solves);
	lp_free(q);
	lp_solver_free(S2);
	lp_solver_stop_flag(S, NULL);
	lp_solver_free(S);

	lp_thread_done();
	return tap_done();
}
