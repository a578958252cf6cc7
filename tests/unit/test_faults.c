/*
 * test_faults.c - faults cost what they must and nothing more
 * (docs/reliability.md).
 *
 * LP solver: with lp_solver_fault() the n-th LP of a sample fails, for every n
 * (every LP role of the five steps), both as LP_FAILED and as a real GLPK
 * error (glp_error, the hook, the longjmp): the sample is a `numerical`
 * rejection, the workspace recovers, and the same sample solved again
 * gives the clean result bit for bit.  A real singular basis and a basis
 * with the wrong number of basic variables (GLPK's GLP_ESING and
 * GLP_EBADB, not injected) are recovered by lp_solve's retry; GLPK's
 * iteration limit, reached for real, fails the LP and the sample.
 *
 * Scale: the same samples of a wall built at 1e-3 and 1e3 times its size
 * give the same results (body load: the same load factors to 1e-6; point
 * load: the same load per unit weight).
 *
 * Saving (wallfile_save, temporary file + rename): a save that fails -
 * a file size limit standing in for a full disk, a directory in the way,
 * a missing directory - reports the path and leaves the old file byte
 * for byte and no temporary file; a process killed at random instants
 * while saving leaves the old wall or the new one, never a mixture.
 */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "lp.h"
#include "sample_lp.h"
#include "slipwall/mc.h"
#include "slipwall/sample.h"
#include "slipwall/wallfile.h"
#include "tap.h"
#include "walls.h"

/* ---- GLPK faults ------------------------------------------------------- */

/* the solver of the LPs made here (the samples' are their workspaces') */
static struct lp_solver *S;

static void test_lp_error(void)
{
	/* max x + y, x + y <= 1 */
	struct lp *p = lp_new(S, 1, 2);
	int cols[2] = {0, 1};
	double one[2] = {1, 1};
	lp_set_row(p, 0, 2, cols, one);
	lp_set_row_bounds(p, 0, -HUGE_VAL, 1);
	lp_set_col_bounds(p, 0, 0, HUGE_VAL);
	lp_set_col_bounds(p, 1, 0, HUGE_VAL);
	lp_set_obj(p, 0, 1);
	lp_set_obj(p, 1, 1);
	lp_set_maximize(p, 1);

	lp_solver_fault(S, 1, LP_ERROR);
	enum lp_status s = lp_solve(p, LP_PRIMAL);
	tap_ok(s == LP_ERROR, "an injected GLPK error returns LP_ERROR (got %d)",
	       s);
	tap_ok(strstr(lp_solver_message(S), "Error detected") != NULL,
	       "GLPK's own error text is kept, not printed: '%s'",
	       lp_solver_message(S));
	tap_ok(lp_solve(p, LP_PRIMAL) == LP_ERROR,
	       "a problem of the dead environment stays dead");
	lp_free(p);	/* safe after LP_ERROR */
	lp_solver_fault(S, 0, LP_FAILED);

	p = lp_new(S, 1, 2);
	lp_set_row(p, 0, 2, cols, one);
	lp_set_row_bounds(p, 0, -HUGE_VAL, 1);
	lp_set_col_bounds(p, 0, 0, HUGE_VAL);
	lp_set_col_bounds(p, 1, 0, HUGE_VAL);
	lp_set_obj(p, 0, 1);
	lp_set_obj(p, 1, 1);
	lp_set_maximize(p, 1);
	s = lp_solve(p, LP_PRIMAL);
	tap_ok(s == LP_OPTIMAL && lp_obj(p) == 1,
	       "a new problem after the error solves (status %d, obj %g)", s,
	       lp_obj(p));
	lp_solver_fault(S, 2, LP_FAILED);
	tap_ok(lp_solve(p, LP_PRIMAL) == LP_OPTIMAL &&
	       lp_solve(p, LP_PRIMAL) == LP_FAILED &&
	       lp_solve(p, LP_PRIMAL) == LP_OPTIMAL,
	       "failed:2 fails every second solve, and the problem lives on");
	lp_solver_fault(S, 0, LP_FAILED);
	lp_free(p);
}

/* A singular starting basis, for real: two identical columns both basic.
 * GLPK cannot factorize it (glp_simplex returns GLP_ESING); lp_solve
 * must retry from the advanced basis and find the optimum.  The status
 * codes of a basis are GLPK's, so they are read from a solved problem
 * (this file does not include glpk.h). */
static void test_lp_singular(void)
{
	/* max x + y, x + y <= 1, 2x + 2y <= 3: columns x and y are equal */
	struct lp *p = lp_new(S, 2, 2);
	int cols[2] = {0, 1};
	double one[2] = {1, 1}, two[2] = {2, 2};
	lp_set_row(p, 0, 2, cols, one);
	lp_set_row(p, 1, 2, cols, two);
	lp_set_row_bounds(p, 0, -HUGE_VAL, 1);
	lp_set_row_bounds(p, 1, -HUGE_VAL, 3);
	for (int j = 0; j < 2; j++) {
		lp_set_col_bounds(p, j, 0, HUGE_VAL);
		lp_set_obj(p, j, 1);
	}
	lp_set_maximize(p, 1);
	enum lp_status s = lp_solve(p, LP_PRIMAL);
	struct lp_basis b = {0, NULL};
	lp_basis_save(p, &b);
	/* one column basic, the other at its lower bound; row 0 at its
	 * upper bound, row 1 basic */
	int jb = lp_col_basic(p, 0) ? 0 : 1;
	if (!tap_ok(s == LP_OPTIMAL && lp_obj(p) == 1 && b.n == 4 &&
		    lp_col_basic(p, jb) && !lp_col_basic(p, 1 - jb),
		    "the reference problem solves (status %d, obj %g)", s,
		    lp_obj(p))) {
		lp_basis_free(&b);
		lp_free(p);
		return;
	}
	int bs = b.stat[2 + jb], nu = b.stat[0];

	/* both columns basic, both rows at their upper bounds: singular */
	b.stat[0] = nu;
	b.stat[1] = nu;
	b.stat[2] = bs;
	b.stat[3] = bs;
	lp_basis_load(p, &b);
	int loaded = lp_col_basic(p, 0) && lp_col_basic(p, 1);
	s = lp_solve(p, LP_PRIMAL);
	tap_ok(loaded && s == LP_OPTIMAL && fabs(lp_obj(p) - 1) < 1e-12,
	       "a singular starting basis (two equal columns basic): the "
	       "retry from the advanced basis solves it (loaded %d, status "
	       "%d, obj %g)", loaded, s, lp_obj(p));

	/* three basic variables for two rows: an invalid basis */
	b.stat[0] = bs;
	b.stat[1] = nu;
	b.stat[2] = bs;
	b.stat[3] = bs;
	lp_basis_load(p, &b);
	s = lp_solve(p, LP_DUAL);
	tap_ok(s == LP_OPTIMAL && fabs(lp_obj(p) - 1) < 1e-12,
	       "a basis with 3 basic variables for 2 rows: the retry solves "
	       "it (status %d, obj %g)", s, lp_obj(p));
	lp_basis_free(&b);
	lp_free(p);
}

/* One sample of a wall (seed 1, index `index`) in its own workspace: the
 * clean result r0, and r for the runs under a fault. */
struct one_sample {
	struct sample_opts o;
	struct sample_result r0, r;
	struct sample_draw dr;
	struct sample_ws *ws;
};

static void one_sample_init(struct one_sample *x, const struct wall *w,
			    unsigned long index)
{
	sample_opts_default(&x->o);
	sample_result_init(&x->r0, w);
	sample_result_init(&x->r, w);
	draw_init(&x->dr, w);
	draw_mean(&x->dr, w);
	draw_make(&x->dr, w, 1, index, -1);
	x->ws = sample_ws_new(w);
	sample_run(x->ws, &x->dr, &x->o, &x->r0);
}

/* x->r again, and is it the clean sample bit for bit? */
static int one_sample_clean(struct one_sample *x)
{
	sample_run(x->ws, &x->dr, &x->o, &x->r);
	return x->r.status == SAMPLE_ACCEPTED &&
	       x->r.lambda_min == x->r0.lambda_min &&
	       x->r.lambda_max == x->r0.lambda_max &&
	       x->r.iterations == x->r0.iterations &&
	       !strcmp(x->r.joint, x->r0.joint);
}

static void one_sample_free(struct one_sample *x)
{
	sample_ws_free(x->ws);
	sample_result_free(&x->r0);
	sample_result_free(&x->r);
	draw_free(&x->dr);
}

/* The n-th LP of one sample fails, for every n: numerical, then the
 * clean sample again, bit for bit. */
static void test_sample_faults(const struct wall *w, enum lp_status as)
{
	const char *kind = as == LP_ERROR ? "GLPK error" : "LP failure";
	struct one_sample x;
	one_sample_init(&x, w, 0);
	int lps = x.r0.lps;
	if (tap_ok(x.r0.status == SAMPLE_ACCEPTED && lps > 5,
		   "%s: the clean sample is accepted (%d LPs)", kind, lps)) {
		int numerical = 0, recovered = 0;
		for (int n = 1; n <= lps; n++) {
			lp_solver_fault(sample_ws_solver(x.ws), n, as);
			sample_run(x.ws, &x.dr, &x.o, &x.r);
			numerical += x.r.status == SAMPLE_NUMERICAL;
			lp_solver_fault(sample_ws_solver(x.ws), 0, LP_FAILED);
			recovered += one_sample_clean(&x);
		}
		tap_ok(numerical == lps,
		       "%s in LP n of the sample, n = 1..%d (every step): a "
		       "'numerical' rejection each time (%d)", kind, lps,
		       numerical);
		tap_ok(recovered == lps,
		       "%s: the same workspace then gives the clean sample "
		       "bit for bit (%d of %d)", kind, recovered, lps);
	}
	one_sample_free(&x);
}

/* GLPK's iteration limit, reached for real (lp_solver_iteration_limit):
 * an LP that needs more pivots than the limit is LP_FAILED after that
 * many (a limit the caller set is final: no retry from another basis,
 * lp.h), the same problem then solves with the default limit; a sample
 * whose LPs hit it is a `numerical` rejection, and the same workspace
 * then gives the clean sample bit for bit. */
static void test_iteration_limit(const struct wall *w)
{
	/* max sum x_j, x_j + x_{j+1} <= 1 (a path of 12 columns): the
	 * primal simplex from the slack basis needs several pivots */
	enum { N = 12 };
	struct lp *p = lp_new(S, N - 1, N);
	for (int i = 0; i < N - 1; i++) {
		int cols[2] = {i, i + 1};
		double one[2] = {1, 1};
		lp_set_row(p, i, 2, cols, one);
		lp_set_row_bounds(p, i, -HUGE_VAL, 1);
	}
	for (int j = 0; j < N; j++) {
		lp_set_col_bounds(p, j, 0, HUGE_VAL);
		lp_set_obj(p, j, 1);
	}
	lp_set_maximize(p, 1);
	int was = lp_solver_iteration_limit(S, 1);
	enum lp_status s1 = lp_solve(p, LP_PRIMAL);
	int it1 = lp_last_iterations(p);
	int one = lp_solver_iteration_limit(S, was);
	lp_reset_basis(p);
	enum lp_status s2 = lp_solve(p, LP_PRIMAL);
	tap_ok(was == 0 && one == 1 && s1 == LP_FAILED && it1 == 1 &&
	       s2 == LP_OPTIMAL && lp_obj(p) == N / 2 &&
	       lp_last_iterations(p) > 1,
	       "an iteration limit of 1 on an LP of %d pivots: LP_FAILED "
	       "(status %d) after %d pivot(s) (no retry); without it: optimal, "
	       "%g", lp_last_iterations(p), s1, it1, lp_obj(p));
	lp_free(p);

	struct one_sample x;
	one_sample_init(&x, w, 3);
	lp_solver_iteration_limit(sample_ws_solver(x.ws), 2);
	sample_run(x.ws, &x.dr, &x.o, &x.r);
	enum sample_status limited = x.r.status;
	lp_solver_iteration_limit(sample_ws_solver(x.ws), 0);
	int clean = one_sample_clean(&x);
	tap_ok(x.r0.status == SAMPLE_ACCEPTED && limited == SAMPLE_NUMERICAL &&
	       clean,
	       "a sample whose LPs reach an iteration limit of 2: '%s'; "
	       "then the clean sample bit for bit (%s, lambda_min %.9g)",
	       sample_status_name(limited), sample_status_name(x.r.status),
	       x.r.lambda_min);
	one_sample_free(&x);
}

/* ---- scale -------------------------------------------------------------- */

/* Units must not matter to a sample either (tests/unit/test_solve.c proves it
 * for the single solutions): the same samples (contact points are
 * fractions of each interface) of a wall built at 1e-3 and 1e3 times its
 * size have the same status and mechanism, and, under a body load, the
 * same load factors to 1e-6; under a point load the load divided by the
 * weight is the same. */
#define SCALE_SAMPLES 12
static void sample_at_scale(double f, int point, struct sample_result *rs)
{
	struct wall *w = tw_layout(0.4 * f, 0.175 * f, 6, 2.0 * f, 1, 1, 0.65);
	if (point)
		tw_point_load(w, 2.0 * f, 0.175 * f * 5.5, 1, 0);
	else
		tw_body_load(w);
	tw_finish(w);
	struct sample_opts o;
	sample_opts_default(&o);
	struct sample_draw dr;
	draw_init(&dr, w);
	draw_mean(&dr, w);
	struct sample_ws *ws = sample_ws_new(w);
	for (int k = 0; k < SCALE_SAMPLES; k++) {
		sample_result_init(&rs[k], w);
		draw_make(&dr, w, 5, (unsigned long)k, -1);
		sample_run(ws, &dr, &o, &rs[k]);
		if (point) {	/* the load per unit weight */
			rs[k].lambda_min /= w->total_weight;
			rs[k].lambda_max /= w->total_weight;
		}
	}
	sample_ws_free(ws);
	draw_free(&dr);
	wall_free(w);
}

static void test_sample_scale(void)
{
	const double f[2] = {1e-3, 1e3};
	for (int point = 0; point < 2; point++) {
		struct sample_result r1[SCALE_SAMPLES], rf[SCALE_SAMPLES];
		sample_at_scale(1, point, r1);
		int accepted = 0;
		for (int k = 0; k < SCALE_SAMPLES; k++)
			accepted += r1[k].status == SAMPLE_ACCEPTED;
		for (int i = 0; i < 2; i++) {
			sample_at_scale(f[i], point, rf);
			int same = 0;
			double worst = 0;
			for (int k = 0; k < SCALE_SAMPLES; k++) {
				int ok = rf[k].status == r1[k].status;
				if (ok && r1[k].status == SAMPLE_ACCEPTED) {
					double a = fabs(rf[k].lambda_min / r1[k].lambda_min - 1);
					double b = fabs(rf[k].lambda_max / r1[k].lambda_max - 1);
					if (a > worst) worst = a;
					if (b > worst) worst = b;
					ok = a <= 1e-6 && b <= 1e-6 &&
					     !strcmp(rf[k].joint, r1[k].joint);
				}
				same += ok;
				sample_result_free(&rf[k]);
			}
			tap_ok(accepted > 0 && same == SCALE_SAMPLES,
			       "%s load, wall scaled by %g: %d of %d samples with "
			       "the same status and mechanism (%d accepted), load%s "
			       "within %.1e relative (<= 1e-6)",
			       point ? "point" : "body", f[i], same,
			       SCALE_SAMPLES, accepted,
			       point ? " / weight" : " factors", worst);
		}
		for (int k = 0; k < SCALE_SAMPLES; k++)
			sample_result_free(&r1[k]);
	}
}

/* ---- saving ------------------------------------------------------------ */

static char *slurp(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return NULL;
	size_t cap = 1 << 16, n = 0;
	char *b = malloc(cap);
	size_t got;
	while ((got = fread(b + n, 1, cap - n, f)) > 0) {
		n += got;
		if (n == cap)
			b = realloc(b, cap *= 2);
	}
	fclose(f);
	*len = n;
	return b;
}

static int same_file(const char *a, const char *b)
{
	size_t la = 0, lb = 0;
	char *x = slurp(a, &la), *y = slurp(b, &lb);
	int same = x && y && la == lb && !memcmp(x, y, la);
	free(x);
	free(y);
	return same;
}

static int exists(const char *path)
{
	struct stat st;
	return stat(path, &st) == 0;
}

static void test_save(const struct wall *a, const struct wall *b)
{
	char dir[] = "/tmp/slipwall-faults-XXXXXX", path[256], tmp[512];
	char refa[256], refb[256], err[SW_ERRLEN];
	if (!mkdtemp(dir)) {
		tap_ok(0, "mkdtemp: %s", strerror(errno));
		return;
	}
	snprintf(path, sizeof path, "%s/wall.yaml", dir);
	snprintf(tmp, sizeof tmp, "%s.tmp", path);
	snprintf(refa, sizeof refa, "%s/a.yaml", dir);
	snprintf(refb, sizeof refb, "%s/b.yaml", dir);
	tap_ok(wallfile_save(a, refa, err) == SW_OK &&
	       wallfile_save(b, refb, err) == SW_OK &&
	       wallfile_save(a, path, err) == SW_OK && same_file(path, refa) &&
	       !exists(tmp),
	       "a save writes the file and leaves no temporary file");

	/* a full disk: a file size limit (half of b's file) makes write(2)
	 * fail with EFBIG */
	struct stat sb;
	rlim_t half = stat(refb, &sb) == 0 ? (rlim_t)sb.st_size / 2 : 512;
	pid_t pid = fork();
	if (pid == 0) {
		struct rlimit rl = {half, half};
		signal(SIGXFSZ, SIG_IGN);
		setrlimit(RLIMIT_FSIZE, &rl);
		enum sw_status st = wallfile_save(b, path, err);
		_exit(st == SW_EIO && strstr(err, path) ? 0 : 1);
	}
	int status;
	waitpid(pid, &status, 0);
	tap_ok(WIFEXITED(status) && WEXITSTATUS(status) == 0,
	       "a save that runs out of space fails with SW_EIO naming the "
	       "file");
	tap_ok(same_file(path, refa) && !exists(tmp),
	       "... and leaves the old file byte for byte, no temporary file");

	/* a directory where the temporary file goes */
	mkdir(tmp, 0700);
	enum sw_status st = wallfile_save(b, path, err);
	tap_ok(st == SW_EIO && strstr(err, "cannot write") &&
	       same_file(path, refa),
	       "the temporary file cannot be created: SW_EIO, old file "
	       "intact (%s)", err);
	rmdir(tmp);

	/* a directory where the file goes: the rename fails */
	char dpath[256];
	snprintf(dpath, sizeof dpath, "%s/adir", dir);
	mkdir(dpath, 0700);
	st = wallfile_save(b, dpath, err);
	snprintf(tmp, sizeof tmp, "%s.tmp", dpath);
	tap_ok(st == SW_EIO && strstr(err, dpath) && !exists(tmp),
	       "the rename fails (a directory in the way): SW_EIO, the "
	       "temporary file removed (%s)", err);
	rmdir(dpath);

	char npath[256];
	snprintf(npath, sizeof npath, "%s/no/such/dir/wall.yaml", dir);
	st = wallfile_save(b, npath, err);
	tap_ok(st == SW_EIO && strstr(err, "No such file"),
	       "a missing directory: SW_EIO and why (%s)", err);

	/* SIGKILL at random instants while saving a, b, a, b, ...: the file
	 * is always one of the two, whole */
	snprintf(tmp, sizeof tmp, "%s.tmp", path);
	int whole = 0, rounds = 30;
	srand(7);
	for (int i = 0; i < rounds; i++) {
		pid = fork();
		if (pid == 0) {
			for (int k = 0;; k++)
				wallfile_save(k % 2 ? a : b, path, err);
		}
		struct timespec d = {0, (rand() % 20000) * 1000L};
		nanosleep(&d, NULL);
		kill(pid, SIGKILL);
		waitpid(pid, &status, 0);
		whole += same_file(path, refa) || same_file(path, refb);
		unlink(tmp);	/* a kill between create and rename leaves it */
	}
	tap_ok(whole == rounds,
	       "SIGKILL during saves, %d times: the file is always a whole "
	       "wall, old or new (%d)", rounds, whole);

	struct wall *back;
	st = wallfile_load(path, &back, err);
	tap_ok(st == SW_OK, "the file left by the last kill loads%s%s",
	       st == SW_OK ? "" : ": ", st == SW_OK ? "" : err);
	wall_free(back);
	unlink(path);
	unlink(refa);
	unlink(refb);
	rmdir(dir);
}

int main(void)
{
	struct wall *demo = tw_load_file(SRCDIR "/walls/demo.yaml");
	struct wall *ft = tw_load_file(SRCDIR "/walls/ferris-tinloi-1.yaml");

	S = lp_solver_new(NULL);
	test_lp_error();
	test_lp_singular();
	test_sample_faults(ft, LP_ERROR);
	test_sample_faults(demo, LP_FAILED);
	test_iteration_limit(ft);
	test_sample_scale();
	test_save(demo, ft);

	wall_free(demo);
	wall_free(ft);
	lp_solver_free(S);
	lp_thread_done();
	return tap_done();
}
