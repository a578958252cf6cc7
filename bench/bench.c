/*
 * bench.c - the sampling benchmark (issue 4; figures in
 * docs/performance.md).
 *
 *   bench WALL.yaml [-n N] [--threads 1,2] [--seed S]
 *
 * For each thread count, runs N samples of the wall through the real
 * worker pool (mc.c, the code path of `slipwall run`, without the CSV)
 * and prints one line: samples per second, the seconds to the first
 * sample (the pool's set-up included: issue 25's first-sample figure),
 * acceptance, LPs per sample,
 * the share of them answered by the basis GLPK held (no simplex:
 * lp_glpk.c, "Held bases"), the share whose dual simplex started from
 * artificial bounds (lp_glpk.c, "Artificial bounds"), simplex
 * iterations per LP, microseconds per LP, the share of the
 * workers' time spent inside GLPK's simplex (lp_solve, timed by lp.c per
 * thread), and the p05 so that a speed change that changes the results
 * is noticed.  The last line gives the peak resident memory of the
 * process (getrusage), which covers the largest run.
 *
 * Two shares are printed: "glpk/sample" is the time inside lp_solve over
 * the time inside sample_run (the solver's own overhead: building,
 * convergence tests, the onset check's bookkeeping); "glpk/wall" is the
 * time inside lp_solve over threads x elapsed time (everything else too:
 * the pool, the reorder window, drawing positions, the consumer).
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>

#include "slipwall/mc.h"
#include "slipwall/sample.h"
#include "slipwall/stats.h"
#include "slipwall/tally.h"
#include "slipwall/wallfile.h"

static double now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* The LP solvers' settings: SLIPWALL_LP_START (and the test variables)
 * from the environment, as the program reads them (src/cli/cli.c). */
static struct sample_lp_config lpc;

static int usage(void)
{
	fprintf(stderr, "usage: bench WALL.yaml [-n N] [--threads 1,2,...] "
		"[--seed S] [--roles]\n");
	return 2;
}

static int bench_one(const struct wall *w, long n, unsigned long seed,
		     int threads)
{
	char err[SW_ERRLEN];
	struct mc_config cfg;
	mc_config_default(&cfg, w);
	cfg.n = n;
	cfg.seed = seed;
	cfg.threads = threads;
	cfg.opts.lp = lpc;
	double t0 = now();
	struct mc *m = mc_start(&cfg, err);
	if (!m) {
		fprintf(stderr, "bench: %s\n", err);
		return 1;
	}
	struct tally t;
	struct record it;
	tally_init(&t, w);
	record_init(&it, w);
	double first = -1;	/* the first sample (the set-up included) */
	while (mc_pop(m, &it, -1) > 0) {
		if (first < 0)
			first = now() - t0;
		tally_add(&t, &it);
	}
	double elapsed = now() - t0;
	mc_wait(m);
	struct mc_counters c;
	mc_counters(m, &c);
	mc_free(m);
	record_free(&it);

	struct stats_summary s;
	tally_summary(&t, &s);
	double ns = (double)t.samples;
	printf("%-8d %9.2f %8.2f %7.1f%% %9.1f %6.1f%% %6.1f%% %6.1f%% %10.1f %9.1f %7.1f%% %7.1f%% %12.6g\n",
	       threads, ns / elapsed, first, 100.0 * (double)t.accepted / ns,
	       (double)c.solves / ns,
	       c.solves ? 100.0 * (double)c.held / (double)c.solves : 0.0,
	       c.solves ? 100.0 * (double)c.art / (double)c.solves : 0.0,
	       c.solves ? 100.0 * (double)c.shift / (double)c.solves : 0.0,
	       c.solves ? (double)c.iterations / (double)c.solves : 0.0,
	       c.solves ? 1e6 * c.lp_seconds / (double)c.solves : 0.0,
	       t.compute_seconds > 0 ? 100.0 * c.lp_seconds /
	       t.compute_seconds : 0.0,
	       100.0 * c.lp_seconds / (elapsed * threads), s.p05);
	fflush(stdout);
	tally_free(&t);
	return 0;
}

/* --roles: the workspace's set-up (its canonical sample) by role, then
 * the cost of each LP role per sample, one thread. */
static int bench_roles(const struct wall *w, long n, unsigned long seed)
{
	double t_setup = now();
	struct sample_ws *ws = sample_ws_new_config(w, &lpc);
	t_setup = now() - t_setup;
	struct sample_lp_stats before[SAMPLE_ROLE_COUNT], after[SAMPLE_ROLE_COUNT];
	sample_ws_stats(ws, before);
	printf("set-up (the canonical sample): %.3f s\n", t_setup);
	printf("%-14s %9s %10s %10s\n", "role", "LPs", "iters/LP", "s");
	for (int k = 0; k < SAMPLE_ROLE_COUNT; k++)
		if (before[k].lps > 0)
			printf("%-14s %9ld %10.1f %10.3f\n", sample_role_name(k),
			       before[k].lps, (double)before[k].iterations /
			       (double)before[k].lps, before[k].seconds);
	struct sample_opts o;
	sample_opts_default(&o);
	struct sample_result r;
	sample_result_init(&r, w);
	struct sample_draw dr;
	draw_init(&dr, w);
	long accepted = 0, iters = 0;
	double t0 = now();
	for (long i = 0; i < n; i++) {
		draw_make(&dr, w, seed, (unsigned long)i, -1);
		sample_run(ws, &dr, &o, &r);
		accepted += r.status == SAMPLE_ACCEPTED;
		iters += r.iterations;
	}
	double elapsed = now() - t0;
	sample_ws_stats(ws, after);
	double lp_total = 0;
	for (int k = 0; k < SAMPLE_ROLE_COUNT; k++)
		lp_total += after[k].seconds - before[k].seconds;
	printf("start %s: %.2f samples/s (%.3f ms a sample), %ld of %ld "
	       "accepted, %.1f SLP iterations a sample, %.1f %% of the time "
	       "inside the LP solver\n", sample_start_name(lpc.start),
	       (double)n / elapsed, 1e3 * elapsed / (double)n, accepted, n,
	       (double)iters / (double)n, 100 * lp_total / elapsed);
	printf("%-14s %9s %10s %10s %8s\n", "role", "LPs/smp", "iters/LP",
	       "us/LP", "share");
	for (int k = 0; k < SAMPLE_ROLE_COUNT; k++) {
		double lps = (double)(after[k].lps - before[k].lps);
		double it = (double)(after[k].iterations - before[k].iterations);
		double sec = after[k].seconds - before[k].seconds;
		if (lps == 0)
			continue;
		printf("%-14s %9.2f %10.1f %10.1f %7.1f%%\n", sample_role_name(k),
		       lps / (double)n, it / lps, 1e6 * sec / lps,
		       lp_total > 0 ? 100 * sec / lp_total : 0.0);
	}
	draw_free(&dr);
	sample_result_free(&r);
	sample_ws_free(ws);
	return 0;
}

int main(int argc, char **argv)
{
	const char *path = NULL;
	long n = 200;
	unsigned long seed = 1;
	int threads[16] = {1, 2}, nthreads = 2, roles = 0;
	char err[SW_ERRLEN];
	sample_lp_config_default(&lpc);
	if (sample_lp_config_parse(&lpc, getenv("SLIPWALL_LP_START"),
				   getenv("SLIPWALL_LP_FAULT"),
				   getenv("SLIPWALL_GLPK_MEM_MB"), err)) {
		fprintf(stderr, "bench: %s\n", err);
		return 2;
	}
	for (int i = 1; i < argc; i++) {
		if (!strcmp(argv[i], "--roles")) {
			roles = 1;
		} else if (!strcmp(argv[i], "-n") && i + 1 < argc) {
			n = strtol(argv[++i], NULL, 10);
		} else if (!strcmp(argv[i], "--seed") && i + 1 < argc) {
			seed = strtoul(argv[++i], NULL, 10);
		} else if (!strcmp(argv[i], "--threads") && i + 1 < argc) {
			char *s = argv[++i];
			nthreads = 0;
			while (*s && nthreads < 16) {
				threads[nthreads++] = (int)strtol(s, &s, 10);
				if (*s == ',')
					s++;
				else if (*s)
					return usage();
			}
		} else if (argv[i][0] == '-' || path) {
			return usage();
		} else {
			path = argv[i];
		}
	}
	if (!path || n < 1 || nthreads < 1)
		return usage();
	for (int k = 0; k < nthreads; k++)
		if (threads[k] < 1)
			return usage();

	struct wall *w;
	if (wallfile_load(path, &w, err) != SW_OK) {
		fprintf(stderr, "%s\n", err);
		return 2;
	}
	printf("%s: %d blocks (%d free), %d interfaces; %ld samples, seed %lu\n",
	       path, w->nblocks, w->nfree, w->nifaces, n, seed);
	if (roles) {
		int rc = bench_roles(w, n, seed);
		wall_free(w);
		return rc;
	}
	printf("%-8s %9s %8s %8s %9s %7s %7s %7s %10s %9s %8s %8s %12s\n", "threads",
	       "samples/s", "first s", "accept", "LPs/smp", "held", "art", "shift", "iters/LP", "us/LP",
	       "glpk/smp", "glpk/wall", "p05");
	int rc = 0;
	for (int k = 0; k < nthreads && !rc; k++)
		rc = bench_one(w, n, seed, threads[k]);
	struct rusage ru;
	getrusage(RUSAGE_SELF, &ru);
	printf("peak resident memory %.1f MB\n\n", (double)ru.ru_maxrss / 1024.0);
	wall_free(w);
	return rc;
}
