/*
 * test_binom.c - the binomial tails and the Clopper-Pearson interval
 * (stats_binom_ge/_le, stats_binomial_ci; `run --at`, the design load)
 * against an independent computation, and GSL's error handler (issue 23:
 * gsl_cdf_beta_Pinv, used before, aborted the program for k = 1 at 28
 * values of n from 231 and for k = 2 at 2,556 values of n up to 5,000).
 *
 * The independent computation: the binomial tails summed term by term in
 * long double from the end term, whose logarithm is a sum of logs of
 * ratios (min(k, n-k) <= 1000) or lgammal's (beyond), every later term
 * by the ratio of successive terms - no continued fraction, no Loader
 * term, no bisection over doubles.  An end e of the interval is right
 * when the defining equation changes sign across it: P(B >= k | lo) =
 * (1-conf)/2 has the independent tail below the target at lo - d and
 * above it at lo + d (the mirror for hi), d = DELTA * min(e, 1-e) plus
 * two ulps; DELTA is 1e-9 up to n = 10^5 and 1e-7 beyond (the long double
 * lgammal of 10^9 carries 1e-9 of error).  Swept over every k of every
 * n <= 200, k = 1 and 2 for every n <= 5,000 (the region GSL failed in),
 * and k in {0, 1, 2, 3, n/20, n/2, random, n-3 .. n} for 300 values of n
 * up to 10^9; with the symmetry lo(k, n) = 1 - hi(n-k, n) and the
 * monotonicity in k and n.
 */
#include <gsl/gsl_errno.h>
#include <gsl/gsl_rng.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include "slipwall/sample.h"
#include "slipwall/stats.h"
#include "slipwall/status.h"
#include "tap.h"
#include "walls.h"

/* log C(n, k) in long double. */
static long double log_choose(size_t k, size_t n)
{
	size_t m = k < n - k ? k : n - k;
	if (m <= 1000) {
		long double s = 0;
		for (size_t i = 0; i < m; i++)
			s += logl((long double)(n - i) / (long double)(i + 1));
		return s;
	}
	return lgammal((long double)n + 1) - lgammal((long double)k + 1) -
	       lgammal((long double)(n - k) + 1);
}

/* P(B >= k) (upper) or P(B <= k), B ~ Bin(n, p), summed from the term
 * of k outwards until the terms stop mattering. */
static long double tail_ld(size_t k, size_t n, long double p, int upper)
{
	if (upper && k == 0)
		return 1;
	if (!upper && k >= n)
		return 1;
	if (p <= 0)
		return upper ? 0 : 1;
	if (p >= 1)
		return upper ? 1 : 0;
	long double q = 1 - p, r = p / q;
	long double t = expl(log_choose(k, n) + (long double)k * logl(p) +
			     (long double)(n - k) * log1pl(-p));
	long double s = 0, mode = (long double)(n + 1) * p;
	size_t j = k;
	for (;;) {
		s += t;
		if (upper) {
			if (j == n)
				break;
			t *= (long double)(n - j) / (long double)(j + 1) * r;
			j++;
			if (j > mode && t < s * 1e-22L)
				break;
		} else {
			if (j == 0)
				break;
			t *= (long double)j / (long double)(n - j + 1) / r;
			j--;
			if (j < mode && t < s * 1e-22L)
				break;
		}
	}
	return s;
}

struct sweep {
	long cases, bad;
	double conf;
};

/* One (k, n): the ends bracket the roots of their defining equations,
 * and lie on the right sides of k/n. */
static void check_ci(struct sweep *sw, size_t k, size_t n)
{
	double lo, hi, a = (1 - sw->conf) / 2;
	stats_binomial_ci(k, n, sw->conf, &lo, &hi);
	double ph = (double)k / (double)n;
	double delta = n <= 100000 ? 1e-9 : 1e-7;
	int ok = lo >= 0 && hi <= 1 && lo <= ph && ph <= hi &&
		 (k > 0 || lo == 0) && (k < n || hi == 1);
	if (ok && k > 0) {
		double d = delta * fmin(lo, 1 - lo) + 2 * DBL_EPSILON * lo;
		ok = tail_ld(k, n, lo - d, 1) < a && tail_ld(k, n, lo + d, 1) > a;
	}
	if (ok && k < n) {
		double d = delta * fmin(hi, 1 - hi) + 2 * DBL_EPSILON * hi;
		ok = tail_ld(k, n, hi - d, 0) > a && tail_ld(k, n, hi + d, 0) < a;
	}
	sw->cases++;
	if (!ok && sw->bad++ < 5)
		tap_diag("%zu of %zu at %g: [%.17g, %.17g]: P(B >= k | lo) = "
			 "%.6Lg, P(B <= k | hi) = %.6Lg", k, n, sw->conf, lo,
			 hi, k ? tail_ld(k, n, lo, 1) : 0.0L,
			 k < n ? tail_ld(k, n, hi, 0) : 0.0L);
}

static void test_sweep(void)
{
	struct sweep sw = {0, 0, 0.99};
	for (size_t n = 1; n <= 200; n++)
		for (size_t k = 0; k <= n; k++)
			check_ci(&sw, k, n);
	tap_ok(sw.bad == 0, "every k of every n <= 200: the ends solve "
	       "P(B >= k | lo) = P(B <= k | hi) = 0.005 (%ld cases, %ld wrong)",
	       sw.cases, sw.bad);

	sw.cases = sw.bad = 0;
	for (size_t n = 201; n <= 5000; n++) {
		check_ci(&sw, 1, n);
		check_ci(&sw, 2, n);
	}
	tap_ok(sw.bad == 0, "k = 1 and 2 for every n from 201 to 5,000 "
	       "(%ld cases, %ld wrong)", sw.cases, sw.bad);

	gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
	gsl_rng_set(g, 23);
	sw.cases = sw.bad = 0;
	for (int i = 0; i <= 300; i++) {
		/* 300 values from 200 to 10^9, geometrically, jittered */
		double base = 200 * pow(5e6, i / 300.0);
		size_t n = i == 300 ? 1000000000 :
			   (size_t)(base * (1 + 0.05 * gsl_rng_uniform(g)));
		size_t ks[] = {0, 1, 2, 3, n / 20, n / 2,
			       (size_t)(gsl_rng_uniform(g) * (double)n),
			       n - 3, n - 2, n - 1, n};
		for (size_t j = 0; j < sizeof ks / sizeof *ks; j++)
			check_ci(&sw, ks[j], n);
	}
	tap_ok(sw.bad == 0, "k in {0, 1, 2, 3, n/20, n/2, random, n-3 .. n} "
	       "for 301 n up to 10^9 (%ld cases, %ld wrong)", sw.cases, sw.bad);

	sw.cases = sw.bad = 0;
	sw.conf = 0.95;
	for (size_t n = 1; n <= 1000000000; n = n * 7 + 3)
		for (size_t k = 0; k <= n; k += n / 7 + 1)
			check_ci(&sw, k, n);
	tap_ok(sw.bad == 0, "at 95 %% too (%ld cases, %ld wrong)", sw.cases,
	       sw.bad);
	gsl_rng_free(g);
}

/* lo(k, n) = 1 - hi(n-k, n); lo and hi grow with k and fall with n. */
static void test_shape(void)
{
	long bad = 0;
	for (size_t n = 1; n <= 300; n++) {
		double plo = -1, phi = -1;
		for (size_t k = 0; k <= n; k++) {
			double lo, hi, lo2, hi2, lo3, hi3;
			stats_binomial_ci(k, n, 0.99, &lo, &hi);
			stats_binomial_ci(n - k, n, 0.99, &lo2, &hi2);
			stats_binomial_ci(k, n + 1, 0.99, &lo3, &hi3);
			if (fabs(lo - (1 - hi2)) > 2 * DBL_EPSILON ||
			    (k > 0 && !(lo > plo)) || !(hi > phi) ||
			    (k > 0 && !(lo3 < lo)) || !(hi3 < hi) ||
			    (k == 0 && lo3 != 0))
				bad++;
			plo = lo;
			phi = hi;
		}
	}
	size_t big[] = {1000000, 999999937, 1000000000};
	for (size_t i = 0; i < 3; i++) {
		double plo = -1, phi = -1;
		for (size_t k = 0; k <= 5; k++) {
			double lo, hi;
			stats_binomial_ci(k, big[i], 0.99, &lo, &hi);
			if ((k > 0 && !(lo > plo)) || !(hi > phi))
				bad++;
			plo = lo;
			phi = hi;
		}
	}
	tap_ok(bad == 0, "symmetry lo(k, n) = 1 - hi(n-k, n); monotone in k "
	       "and n (%ld wrong)", bad);
}

/* The tails themselves: against the sums, small and large n. */
static void test_tails(void)
{
	static const size_t cases[][2] = {{0, 10}, {3, 10}, {10, 10},
					  {50, 1000}, {70, 1000}, {30, 1000},
					  {5000, 100000}, {5600, 100000},
					  {1, 1000000000}, {49990000, 1000000000}};
	static const double ps[] = {0.3, 0.3, 0.9, 0.05, 0.05, 0.05, 0.05,
				    0.05, 1e-9, 0.05};
	double worst = 0;
	for (size_t i = 0; i < sizeof ps / sizeof *ps; i++) {
		size_t k = cases[i][0], n = cases[i][1];
		double ge = stats_binom_ge(k, n, ps[i]);
		double le = stats_binom_le(k, n, ps[i]);
		long double wge = tail_ld(k, n, ps[i], 1);
		long double wle = tail_ld(k, n, ps[i], 0);
		worst = fmax(worst, (double)fabsl(ge / wge - 1));
		worst = fmax(worst, (double)fabsl(le / wle - 1));
	}
	tap_ok(worst < 1e-8, "P(B >= k) and P(B <= k) against the summed pmf "
	       "up to n = 10^9 (worst relative error %.2g)", worst);
	tap_ok(stats_binom_ge(0, 5, 0.5) == 1 && stats_binom_ge(6, 5, 0.5) == 0 &&
	       stats_binom_le(5, 5, 0.5) == 1 && stats_binom_le(2, 5, 0) == 1 &&
	       stats_binom_ge(2, 5, 1) == 1 && isnan(stats_binom_ge(1, 5, 2)),
	       "tails: the ends, p = 0 and 1, a bad p");
}

/* In a child: turn what must turn GSL's handler off, then raise a GSL
 * error.  The default handler would abort the child. */
static int child_survives(int how)
{
	pid_t pid = fork();
	if (pid == 0) {
		if (how == 0) {
			sw_init();
		} else {
			struct wall *w = tw_block(0.4);
			tw_finish(w);
			struct sample_ws *ws = sample_ws_new(w);
			sample_ws_free(ws);
			wall_free(w);
		}
		gsl_error("probe", __FILE__, __LINE__, GSL_EDOM);
		_exit(0);
	}
	int st;
	if (pid < 0 || waitpid(pid, &st, 0) != pid)
		return 0;
	return WIFEXITED(st) && WEXITSTATUS(st) == 0;
}

static void test_handler_off(void)
{
	tap_ok(child_survives(0), "after sw_init a GSL error returns: GSL's "
	       "default handler (print and abort) is off");
	tap_ok(child_survives(1), "after sample_ws_new too (the library's own "
	       "defensive sw_init, for a user that forgot it)");
}

int main(void)
{
	test_handler_off();
	test_tails();
	test_shape();
	test_sweep();
	return tap_done();
}
