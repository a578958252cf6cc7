/*
 * test_run.c - the library's run (run.c) and the sample record
 * (record.c): samples from a scripted source are written and counted in
 * order; a write error stops the run before the sample it could not
 * write is counted and drops every later one; --until-ci stops at the
 * first look (128 * 2^j accepted) whose interval at the look's level is
 * narrow enough, found here by brute force, and the interval it reports
 * covers p05 at least 99 % of the time (3,000 simulated runs); a signal stops the watched source and the samples
 * finished after it are still counted; a pool resumed at sample k
 * (mc first) gives the samples k.. of the whole run; a record survives
 * the wire (pack, unpack) field for field.
 */
#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include "slipwall/run.h"
#include "slipwall/stats.h"
#include "slipwall/wallfile.h"
#include "tap.h"

#define M 2		/* interfaces of the fake wall */
#define B 1		/* blocks */

static struct wall fake;	/* record, tally and runlog read the sizes */

/* A scripted source: n samples, index i with load lam(i); every
 * `rejected`-th is rejected.  stop() counts and keeps the signal. */
struct script {
	long n, next, rejected;
	int stops, sig;
	int stopped;
};

static double lam_of(long i)
{
	/* a spread of loads that is not sorted by index */
	return 100 + (double)((i * 37) % 101);
}

static int script_pop(void *ctx, struct record *r, int wait_ms)
{
	struct script *s = ctx;
	(void)wait_ms;
	if (s->next >= s->n)
		return -1;
	long i = s->next++;
	r->index = i;
	r->status = s->rejected && i % s->rejected == 0 ?
		    SAMPLE_NO_MECHANISM : SAMPLE_ACCEPTED;
	r->lambda_max = r->lambda_min = lam_of(i);
	r->iterations = 2;
	r->lps = 5;
	for (int k = 0; k < 2 * M; k++)
		r->draw.xi[k] = 0.1 * (double)k;
	memset(r->joint, JOINT_CLOSED, M);
	r->joint[0] = JOINT_SLIDES;
	return 1;
}

static void script_stop(void *ctx, int sig)
{
	struct script *s = ctx;
	s->stops++;
	if (sig)
		s->sig = sig;
}

static void source_of(struct run_source *src, struct script *s)
{
	src->ctx = s;
	src->pop = script_pop;
	src->stop = script_stop;
	src->status = NULL;
}

static long lines_of(const char *path)
{
	FILE *f = fopen(path, "r");
	long n = 0;
	int c;
	if (!f)
		return -1;
	while ((c = fgetc(f)) != EOF)
		n += c == '\n';
	fclose(f);
	return n;
}

static void test_in_order(void)
{
	char err[SW_ERRLEN], path[] = "/tmp/test_run.XXXXXX";
	int fd = mkstemp(path);
	close(fd);
	struct script s = {.n = 30, .rejected = 4};
	struct run_source src;
	struct runlog *log;
	struct tally t;
	struct run r;
	source_of(&src, &s);
	runlog_create(&log, path, &fake, NULL, err);
	tally_init(&t, &fake);
	run_init(&r, &fake, &src, &t, log);
	while (run_pump(&r, -1) >= 0)
		;
	run_finish(&r);
	tap_ok(runlog_close(log, err) == SW_OK, "the samples file closes");
	tap_ok(r.stop == RUN_COMPLETE, "a source that ends: complete (%s)",
	       run_stop_name(r.stop));
	tap_ok(t.samples == 30 && t.accepted == 22,
	       "30 samples counted, 22 accepted (every 4th rejected): %ld, %ld",
	       t.samples, t.accepted);
	tap_ok(lines_of(path) == 31, "the file: a header and 30 rows (%ld)",
	       lines_of(path));
	tap_ok(s.stops == 0, "nobody stopped the source");
	run_free(&r);
	tally_free(&t);
	unlink(path);
}

static void test_write_error(void)
{
	char err[SW_ERRLEN];
	struct script s = {.n = 10};
	struct run_source src;
	struct runlog *log = NULL;
	struct tally t;
	struct run r;
	char path[] = "/tmp/test_run.XXXXXX";
	int fd = mkstemp(path);
	close(fd);
	source_of(&src, &s);
	runlog_create(&log, path, &fake, NULL, err);
	/* a full disk: the file may not grow beyond its header (the
	 * write fails with EFBIG, SIGXFSZ ignored) */
	struct rlimit old, full;
	struct stat st;
	stat(path, &st);
	getrlimit(RLIMIT_FSIZE, &old);
	full = old;
	full.rlim_cur = (rlim_t)st.st_size;
	signal(SIGXFSZ, SIG_IGN);
	setrlimit(RLIMIT_FSIZE, &full);
	tally_init(&t, &fake);
	run_init(&r, &fake, &src, &t, log);
	while (run_pump(&r, -1) >= 0)
		;
	run_finish(&r);
	setrlimit(RLIMIT_FSIZE, &old);
	runlog_close(log, err);
	tap_ok(r.stop == RUN_WRITE, "a row that cannot be written stops the "
	       "run (%s)", run_stop_name(r.stop));
	tap_ok(t.samples == 0, "no sample counted without its row (%ld)",
	       t.samples);
	tap_ok(s.stops == 1 && s.sig == 0, "the source told to stop once, not "
	       "by a signal (%d)", s.stops);
	tap_ok(strstr(r.werr, path) != NULL, "the error names the file: %s",
	       r.werr);
	tap_ok(lines_of(path) == 1, "the file holds its header only (%ld "
	       "lines)", lines_of(path));
	run_free(&r);
	tally_free(&t);
	unlink(path);
}

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* The first count of accepted samples, among the looks 128, 256, 512,
 * ... of docs/statistics.md, at which p05's interval at the look's level
 * 1 - 0.01 / 2^(j+1) is narrower than w times p05, by brute force (or
 * -1). */
static long until_ci_count(long n, double w)
{
	double *x = malloc(sizeof(double) * (size_t)n);
	long found = -1;
	for (long k = 1; k <= n; k++)
		x[k - 1] = lam_of(k - 1);
	for (int j = 0; 128L << j <= n && found < 0; j++) {
		long k = 128L << j;
		double *y = malloc(sizeof(double) * (size_t)k);
		memcpy(y, x, sizeof(double) * (size_t)k);
		qsort(y, (size_t)k, sizeof(double), cmp_double);
		size_t lo, hi;
		double p05 = stats_quantile_sorted(y, (size_t)k, 0.05);
		double conf = 1 - 0.01 / pow(2, j + 1);
		if (stats_quantile_ci_ranks((size_t)k, 0.05, conf, &lo, &hi) ==
		    0 && y[hi - 1] - y[lo - 1] < w * p05)
			found = k;
		free(y);
	}
	free(x);
	return found;
}

static void test_until_ci(void)
{
	struct script s = {.n = 600};
	struct run_source src;
	struct tally t;
	struct run r;
	source_of(&src, &s);
	tally_init(&t, &fake);
	run_init(&r, &fake, &src, &t, NULL);
	r.until_ci = 0.1;
	while (run_pump(&r, -1) >= 0)
		;
	run_finish(&r);
	long want = until_ci_count(600, 0.1);
	tap_ok(want > 90 && want < 600, "the brute force finds a stop beyond "
	       "the first interval (%ld)",
	       want);
	tap_ok(r.stop == RUN_UNTIL_CI, "--until-ci stops the run (%s)",
	       run_stop_name(r.stop));
	tap_ok(t.samples == want, "at the first narrow enough count: %ld, "
	       "want %ld", t.samples, want);
	tap_ok(s.next == 600, "the samples handed out after it are dropped "
	       "(%ld popped)", s.next);
	run_free(&r);
	tally_free(&t);
}

/*
 * The promise of --until-ci (issue 23): the interval of p05 that a run
 * stopped by it reports covers the true p05 with probability >= 99 %.
 * R replications, each an endless stream of independent normal(100, 20)
 * loads (the order-statistic interval is distribution-free, so any
 * continuous law will do; this one gives p05 = 100 - 1.6449 * 20 and a
 * relative width like a real wall's) fed to run_take with --until-ci
 * 0.15 until the run stops (or 2^15 samples); the interval is the
 * tally's summary, as `run` prints it.  The coverage must be at least
 * 99 % less one standard error of a 99 % coverage.  The rule that
 * checked the 99 % interval after every sample covered 98.2 % here.
 * The bias of p05 at the stop is printed, not tested: the stop still
 * favours samples whose p05 came out high (docs/statistics.md).
 */
static void test_until_ci_coverage(void)
{
	const int R = 3000;
	const long nmax = 1L << 15;
	const double xi = 100 - 1.6448536269514722 * 20;
	gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
	gsl_rng_set(g, 2023);
	struct script sc = {.n = 0};
	struct run_source src;
	source_of(&src, &sc);
	int cover = 0, stopped = 0;
	double bias = 0, bias2 = 0, nsum = 0;
	for (int i = 0; i < R; i++) {
		struct tally t;
		struct run r;
		tally_init(&t, &fake);
		run_init(&r, &fake, &src, &t, NULL);
		r.until_ci = 0.15;
		struct record *rec = &r.rec;
		for (long k = 0; k < nmax; k++) {
			rec->index = k;
			rec->status = SAMPLE_ACCEPTED;
			rec->lambda_max = rec->lambda_min =
				100 + 20 * gsl_ran_gaussian(g, 1);
			memset(rec->joint, JOINT_CLOSED, M);
			if (run_take(&r, rec) < 0)
				break;
		}
		stopped += r.stop == RUN_UNTIL_CI;
		struct stats_summary s;
		tally_summary(&t, &s);
		cover += s.has_ci && s.p05_lo <= xi && xi <= s.p05_hi;
		double e = s.p05 / xi - 1;
		bias += e;
		bias2 += e * e;
		nsum += (double)s.n;
		run_free(&r);
		tally_free(&t);
	}
	gsl_rng_free(g);
	double cov = (double)cover / R, se = sqrt(0.99 * 0.01 / R);
	double mb = bias / R, sb = sqrt((bias2 / R - mb * mb) / R);
	tap_ok(stopped == R, "--until-ci 0.15 stops all %d runs (%d)", R,
	       stopped);
	tap_ok(cov >= 0.99 - se, "the interval it reports covers p05 in "
	       "%.2f %% of %d runs: at least 99 %% - one standard error "
	       "(%.2f %%)", 100 * cov, R, 100 * se);
	tap_diag("p05 at the stop: %+.3f %% +- %.3f %% from the true p05, "
		 "%.0f accepted samples on average", 100 * mb, 100 * sb,
		 nsum / R);
}

static void test_signal(void)
{
	struct script s = {.n = 8};
	struct run_source src;
	struct run_signals caught;
	struct tally t;
	struct run r;
	source_of(&src, &s);
	tally_init(&t, &fake);
	run_init(&r, &fake, &src, &t, NULL);
	run_signals_catch(&caught, 1);
	run_signals_watch(&src);
	run_pump(&r, -1);
	raise(SIGINT);
	tap_ok(s.sig == SIGINT && run_signal() == SIGINT,
	       "a signal stops the watched source (sig %d)", s.sig);
	while (run_pump(&r, -1) >= 0)
		;
	run_finish(&r);
	run_signals_restore(&caught);
	tap_ok(r.stop == RUN_SIGNAL && strstr(r.why, "nterrupt"),
	       "the run says: %s (%s)", run_stop_name(r.stop), r.why);
	tap_ok(t.samples == 8, "the samples finished after it are still "
	       "counted (%ld)", t.samples);
	run_free(&r);
	tally_free(&t);
}

static void test_resume(void)
{
	char err[SW_ERRLEN];
	struct wall *w;
	if (wallfile_load(SRCDIR "/walls/single-block.yaml", &w, err) != SW_OK) {
		tap_ok(0, "load: %s", err);
		return;
	}
	struct mc_config cfg;
	mc_config_default(&cfg, w);
	cfg.n = 9;
	cfg.first = 5;
	cfg.threads = 2;
	struct mc *m = mc_start(&cfg, err);
	struct record rec;
	record_init(&rec, w);
	struct sample_draw d;
	draw_init(&d, w);
	draw_mean(&d, w);
	long want = 5, bad = 0;
	while (m && mc_pop(m, &rec, -1) > 0) {
		draw_make(&d, w, cfg.seed, (unsigned long)want, -1);
		bad += rec.index != want ||
		       memcmp(d.xi, rec.draw.xi, sizeof(double) * 2 *
			      (size_t)w->nifaces) != 0;
		want++;
	}
	tap_ok(m && want == 9 && bad == 0, "a pool resumed at 5 gives "
	       "samples 5..8 of the run, at their positions (%ld, %ld bad)",
	       want, bad);
	mc_free(m);
	draw_free(&d);
	record_free(&rec);
	wall_free(w);
}

static void test_wire(void)
{
	struct record a, b;
	record_init(&a, &fake);
	record_init(&b, &fake);
	a.index = 123456789012L;
	a.status = SAMPLE_UNSTABLE;
	a.iterations = 7;
	a.lps = 11;
	a.lambda_lpmax = 3.5;
	a.lambda_max = -0.0;
	a.lambda_min = 1e-300;
	a.vw_residual = 2e-9;
	a.seconds = 0.25;
	for (int k = 0; k < 2 * M; k++)
		a.draw.xi[k] = 1.0 / (k + 3);
	for (int k = 0; k < M; k++)
		a.draw.mu[k] = 0.5 + 1.0 / (k + 7);
	for (int k = 0; k < 3 * B; k++)
		a.vel[k] = -k - 0.5;
	memcpy(a.joint, "sh", M + 1);
	size_t n = record_wire_size(&fake);
	unsigned char *buf = malloc(n);
	record_pack(&a, &fake, buf);
	record_unpack(&b, &fake, buf);
	tap_ok(n == RECORD_FIXED + sizeof(double) * (3 * M + 3 * B) + M + 1,
	       "the wire size: the fixed part and the arrays (%zu)", n);
	tap_ok(b.index == a.index && b.status == a.status &&
	       b.iterations == 7 && b.lps == 11 && b.lambda_lpmax == 3.5 &&
	       b.lambda_min == 1e-300 && b.vw_residual == 2e-9 &&
	       b.seconds == 0.25 && signbit(b.lambda_max),
	       "the fixed part survives the wire");
	tap_ok(!memcmp(a.draw.xi, b.draw.xi, sizeof(double) * 2 * M) &&
	       !memcmp(a.draw.mu, b.draw.mu, sizeof(double) * M) &&
	       !memcmp(a.vel, b.vel, sizeof(double) * 3 * B) &&
	       !strcmp(b.joint, "sh"), "the draw (xi, mu), vel and joint "
	       "survive the wire");
	free(buf);
	record_free(&a);
	record_free(&b);
}

int main(void)
{
	fake.nifaces = M;
	fake.nblocks = B;
	test_in_order();
	test_write_error();
	test_until_ci();
	test_until_ci_coverage();
	test_signal();
	test_resume();
	test_wire();
	return tap_done();
}
