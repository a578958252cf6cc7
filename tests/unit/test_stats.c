/*
 * test_stats.c - percentiles, order-statistic intervals, histogram, KDE,
 * normal fit and the exact two-sample Kolmogorov-Smirnov test.
 *
 * Every expected number says where it came from.  "Enumerated" means: all
 * C(n+m, n) labellings of the pooled sample listed with Python's
 * itertools.combinations, the statistic of each computed with
 * fractions.Fraction, and the share with D >= d_obs counted exactly (the
 * script is in docs/statistics.md, appendix).  "Exact integers" means the
 * binomial sums done in Python with math.comb, scaled by 20^n.
 */
#include <math.h>
#include <stdlib.h>
#include <time.h>

#include <gsl/gsl_rng.h>
#include <gsl/gsl_sort.h>

#include "slipwall/stats.h"
#include "tap.h"

#define N_OF(a) (sizeof(a) / sizeof(a)[0])

static void test_quantiles(void)
{
	/* Type 7: h = (n-1) p; {1,2,3,4,10}, p = 0.05: h = 0.2,
	 * 1 + 0.2 (2 - 1) = 1.2.  p = 0.95: h = 3.8, 4 + 0.8 (10 - 4) = 8.8.
	 * (R: quantile(c(1,2,3,4,10), c(.05,.5,.95)) = 1.2 3 8.8.) */
	const double x[] = {1, 2, 3, 4, 10};
	tap_near(stats_quantile_sorted(x, 5, 0.05), 1.2, 1e-14,
		 "type-7 quantile p=0.05 of {1,2,3,4,10} is 1.2");
	tap_near(stats_quantile_sorted(x, 5, 0.5), 3, 1e-14,
		 "type-7 median of {1,2,3,4,10} is 3");
	tap_near(stats_quantile_sorted(x, 5, 0.95), 8.8, 1e-14,
		 "type-7 quantile p=0.95 of {1,2,3,4,10} is 8.8");
	tap_ok(stats_quantile_sorted(x, 5, 0) == 1 &&
		       stats_quantile_sorted(x, 5, 1) == 10,
	       "quantiles 0 and 1 are the min and the max");
	const double one[] = {7};
	tap_ok(stats_quantile_sorted(one, 1, 0.05) == 7,
	       "quantile of a single value is that value");
}

static void test_ci_ranks(void)
{
	size_t lo = 0, hi = 0;

	/* P(X(1) <= xi_.05 <= X(n)) = 1 - 0.95^n - 0.05^n: 0.98959 at
	 * n = 89, 0.99011 at n = 90 (exact integers), so no 99 % interval
	 * exists below n = 90. */
	tap_ok(stats_quantile_ci_ranks(89, 0.05, 0.99, &lo, &hi) == -1,
	       "p05 99%% interval: none at n = 89");
	tap_near(stats_quantile_ci_coverage(89, 0.05, 1, 89),
		 0.9895911950424642, 1e-12,
		 "coverage of (1, 89) at n = 89 is 1 - .95^89 - .05^89");
	tap_near(stats_quantile_ci_coverage(90, 0.05, 1, 90),
		 0.990111635290341, 1e-12,
		 "coverage of (1, 90) at n = 90 is 1 - .95^90 - .05^90");

	/* n = 90: the shortest interval is (1, 15) with coverage
	 * 0.9900723127325582; (2, 15) gives 0.94323, (1, 14) 0.98996
	 * (exact integers, every lo < hi tried). */
	int r = stats_quantile_ci_ranks(90, 0.05, 0.99, &lo, &hi);
	tap_ok(r == 0 && lo == 1 && hi == 15,
	       "p05 99%% interval at n = 90 is ranks (1, 15) (got %d: %zu, %zu)",
	       r, lo, hi);
	tap_near(stats_quantile_ci_coverage(90, 0.05, 1, 15),
		 0.9900723127325582, 1e-12, "coverage of (1, 15) at n = 90");
	tap_ok(stats_quantile_ci_coverage(90, 0.05, 2, 15) < 0.99 &&
		       stats_quantile_ci_coverage(90, 0.05, 1, 14) < 0.99,
	       "n = 90: shrinking either end drops coverage below 0.99");

	/* n = 200: (3, 19), coverage 0.9918401478421455 (exact integers). */
	r = stats_quantile_ci_ranks(200, 0.05, 0.99, &lo, &hi);
	tap_ok(r == 0 && lo == 3 && hi == 19,
	       "p05 99%% interval at n = 200 is (3, 19) (got %zu, %zu)", lo,
	       hi);

	/* n = 1000: (33, 69), coverage 0.9912312374375453; (34, 69)
	 * 0.9889706674506489, (33, 68) 0.9889322487246814 (exact
	 * integers). */
	r = stats_quantile_ci_ranks(1000, 0.05, 0.99, &lo, &hi);
	tap_ok(r == 0 && lo == 33 && hi == 69,
	       "p05 99%% interval at n = 1000 is (33, 69) (got %zu, %zu)", lo,
	       hi);
	double c = stats_quantile_ci_coverage(1000, 0.05, 33, 69);
	tap_near(c, 0.9912312374375453, 1e-12,
		 "coverage of (33, 69) at n = 1000");
	tap_ok(stats_quantile_ci_coverage(1000, 0.05, 34, 69) < 0.99 &&
		       stats_quantile_ci_coverage(1000, 0.05, 33, 68) < 0.99,
	       "n = 1000: shrinking either end drops coverage below 0.99");

	/* Tie-break: the median of n = 20 at 95 % has three intervals of
	 * width 9, (5,14), (6,15), (7,16); (6,15) is the one centred on
	 * n p = 10 (B in [6, 14]), coverage 0.9586105346679688 = 1 -
	 * 2 P(B <= 5) (exact integers; the classical table value). */
	r = stats_quantile_ci_ranks(20, 0.5, 0.95, &lo, &hi);
	tap_ok(r == 0 && lo == 6 && hi == 15,
	       "median 95%% interval at n = 20 is the symmetric (6, 15) (got %zu, %zu)",
	       lo, hi);
	tap_near(stats_quantile_ci_coverage(20, 0.5, 6, 15),
		 0.9586105346679688, 1e-12, "coverage of (6, 15), n = 20");
	tap_ok(isnan(stats_quantile_ci_coverage(20, 0.5, 6, 21)) &&
		       isnan(stats_quantile_ci_coverage(20, 0.5, 6, 6)),
	       "coverage of impossible ranks is NaN");

	/* Coverage by simulation: 2000 samples of 200 uniforms; the true
	 * 0.05 quantile is 0.05.  Exact coverage is 0.99184, the binomial
	 * sd of the hit rate 0.002, so >= 0.985 fails only if the interval
	 * is wrong (fixed seed: the outcome is reproducible). */
	gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
	gsl_rng_set(rng, 20240611);
	double u[200];
	int hit = 0, reps = 2000;
	stats_quantile_ci_ranks(200, 0.05, 0.99, &lo, &hi);
	for (int k = 0; k < reps; k++) {
		for (int i = 0; i < 200; i++)
			u[i] = gsl_rng_uniform(rng);
		gsl_sort(u, 1, 200);
		hit += u[lo - 1] <= 0.05 && 0.05 <= u[hi - 1];
	}
	gsl_rng_free(rng);
	tap_ok((double)hit / reps >= 0.985,
	       "simulated coverage of the n = 200 interval %.4f >= 0.985",
	       (double)hit / reps);
}

static void test_summary(void)
{
	struct stats_summary s;
	double x[100];
	/* 100, 99, ..., 1: unsorted input, values equal to their ranks. */
	for (int i = 0; i < 100; i++)
		x[i] = 100 - i;
	stats_summarise(x, 100, &s);
	/* p05: h = 99 * .05 = 4.95, 5 + .95 = 5.95; p95: h = 94.05, 95.05;
	 * mean 50.5, sd sqrt(100 * 101 / 12) = 29.011491975882016;
	 * 99 % interval for n = 100: ranks (1, 13), coverage 0.99262
	 * (exact integers). */
	tap_ok(s.n == 100 && s.min == 1 && s.max == 100,
	       "summary: n, min, max");
	tap_near(s.p05, 5.95, 1e-13, "summary p05 of 1..100 is 5.95");
	tap_near(s.p50, 50.5, 1e-13, "summary p50 of 1..100 is 50.5");
	tap_near(s.p95, 95.05, 1e-13, "summary p95 of 1..100 is 95.05");
	tap_near(s.mean, 50.5, 1e-13, "summary mean of 1..100");
	tap_near(s.std, 29.011491975882016, 1e-13,
		 "summary sample sd of 1..100 is sqrt(n(n+1)/12)");
	tap_ok(s.has_ci && s.p05_lo == 1 && s.p05_hi == 13,
	       "summary p05 99%% interval of 1..100 is [X(1), X(13)] = [1, 13]");
	tap_ok(x[0] == 100 && x[99] == 1, "summary leaves its input alone");

	/* loads near the top of the doubles (a wall in odd units): the
	 * squares of the deviations overflow, the sd must not */
	double huge[100];
	for (int i = 0; i < 100; i++)
		huge[i] = 1e306 * x[i];
	struct stats_summary sb;
	stats_summarise(huge, 100, &sb);
	tap_near(sb.std, 1e306 * 29.011491975882016, 1e-12,
		 "summary sd of 1e306 x (1..100) is 1e306 x sqrt(n(n+1)/12)");
	tap_near(sb.mean, 1e306 * 50.5, 1e-13, "... and the mean is finite");
	/* ... and near the bottom (a load of 1.5e308 N on blocks of kN:
	 * load factors of 1e-306, whose squared deviations underflow to 0) */
	double tiny[100];
	for (int i = 0; i < 100; i++)
		tiny[i] = 1e-306 * x[i];
	stats_summarise(tiny, 100, &sb);
	tap_near(sb.std / 1e-306, 29.011491975882016, 1e-12,
		 "summary sd of 1e-306 x (1..100) is 1e-306 x sqrt(n(n+1)/12)");

	stats_summarise(x, 89, &s);
	tap_ok(!s.has_ci && isnan(s.p05_lo) && isnan(s.p05_hi),
	       "summary of 89 values has no p05 interval");
	stats_summarise(x, 0, &s);
	tap_ok(s.n == 0 && isnan(s.mean) && isnan(s.p05) && isnan(s.min) &&
		       !s.has_ci,
	       "summary of nothing is NaN");
	stats_summarise(x, 1, &s);
	tap_ok(s.mean == 100 && s.p05 == 100 && isnan(s.std),
	       "summary of one value: sd undefined (NaN)");

	/* Large n: the interval search is linear in n p, not quadratic. */
	size_t big = 200000;
	double *y = malloc(big * sizeof *y);
	for (size_t i = 0; i < big; i++)
		y[i] = (double)((i * 7919) % big);
	clock_t t0 = clock();
	stats_summarise(y, big, &s);
	double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
	tap_ok(s.has_ci && s.p05_lo < s.p05 && s.p05 < s.p05_hi &&
		       secs < 2.0,
	       "summary of %zu values brackets p05 (%.3f s)", big, secs);
	free(y);
}

static void test_histogram(void)
{
	/* FD: IQR of {1..5} (type 7) = 4 - 2 = 2, 2 * 2 / 5^(1/3) =
	 * 2.339214190570293.  {1,1,1,1,5}: IQR 0, Scott 3.49 sd n^(-1/3)
	 * with sd = sqrt(3.2): 3.6509880769450316.  Constant data: 1. */
	const double a[] = {1, 2, 3, 4, 5};
	const double b[] = {1, 1, 1, 1, 5};
	const double c[] = {4, 4, 4};
	tap_near(stats_fd_width(a, 5), 2.339214190570293, 1e-13,
		 "FD width of {1..5} is 4 / 5^(1/3)");
	tap_near(stats_fd_width(b, 5), 3.6509880769450316, 1e-13,
		 "FD falls back to Scott when the IQR is 0");
	tap_ok(stats_fd_width(c, 3) == 1, "FD width of constant data is 1");

	/* Width 1 on {0, .5, 1, 1.5, 2}: bins [0,1) and [1,2] (the last
	 * closed, so 2 joins it instead of opening a third bin): 2, 3. */
	const double d[] = {0, 0.5, 1, 1.5, 2};
	struct stats_hist h;
	stats_histogram(d, 5, 1, 100, &h);
	tap_ok(h.nbins == 2 && h.lo == 0 && h.width == 1 && h.count[0] == 2 &&
		       h.count[1] == 3,
	       "histogram width 1: counts 2, 3 with the max in the closed last bin");
	stats_hist_free(&h);

	/* Width 0.1 would make 20 bins; max_bins 4 widens to 0.5:
	 * [0,.5) [.5,1) [1,1.5) [1.5,2]: 1, 1, 1, 2. */
	stats_histogram(d, 5, 0.1, 4, &h);
	tap_ok(h.nbins == 4 && fabs(h.width - 0.5) < 1e-15 &&
		       h.count[0] == 1 && h.count[1] == 1 && h.count[2] == 1 &&
		       h.count[3] == 2,
	       "histogram capped at 4 bins: width 0.5, counts 1, 1, 1, 2");
	stats_hist_free(&h);

	/* FD width on many values: every value lands in some bin. */
	size_t n = 5000;
	double *x = malloc(n * sizeof *x);
	gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
	gsl_rng_set(rng, 7);
	for (size_t i = 0; i < n; i++)
		x[i] = 3 + gsl_rng_uniform(rng) * gsl_rng_uniform(rng);
	gsl_rng_free(rng);
	gsl_sort(x, 1, n);
	stats_histogram(x, n, 0, 50, &h);
	size_t sum = 0;
	for (int k = 0; k < h.nbins; k++)
		sum += h.count[k];
	tap_ok(sum == n && h.nbins >= 1 && h.nbins <= 50 &&
		       h.lo + h.nbins * h.width >= x[n - 1] - 1e-12,
	       "FD histogram of %zu values: counts sum to n, %d bins cover the range",
	       n, h.nbins);
	stats_hist_free(&h);
	free(x);

	stats_histogram(c, 3, 0, 10, &h);
	tap_ok(h.nbins == 1 && h.count[0] == 3 && h.lo < 4 &&
		       4 < h.lo + h.width,
	       "histogram of constant data: one bin around the value");
	stats_hist_free(&h);
}

/* Simpson's rule for f sampled at nseg + 1 points (nseg even), step dx. */
static double simpson(const double *f, size_t nseg, double dx)
{
	double s = f[0] + f[nseg];
	for (size_t i = 1; i < nseg; i++)
		s += (i % 2 ? 4 : 2) * f[i];
	return s * dx / 3;
}

static void test_kde(void)
{
	/* Silverman on {1..5}: sd = sqrt(2.5) = 1.5811, IQR/1.34 = 1.4925,
	 * 0.9 * 1.4925 * 5^(-1/5) = 0.9735846228506357.  Constant {2,2,2}:
	 * R's bw.nrd0 fallback |x_1| = 2: 0.9 * 2 * 3^(-1/5) =
	 * 1.4449348111684153. */
	const double a[] = {5, 3, 1, 2, 4};
	const double c[] = {2, 2, 2};
	tap_near(stats_kde_bandwidth(a, 5), 0.9735846228506357, 1e-13,
		 "Silverman bandwidth of {1..5}");
	tap_near(stats_kde_bandwidth(c, 3), 1.4449348111684153, 1e-13,
		 "bandwidth of constant data falls back to |x|");

	/* One point at 0, h = 1: plain f(0) = phi(0) = 0.3989422804014327;
	 * reflected f(0) = 2 phi(0), f(1) = 2 phi(1) = 0.48394144903828673,
	 * f(-0.5) = 0.  Two points {1, 3}, h = 2, at 2: (phi(.5) +
	 * phi(-.5)) / (2 * 2) = 0.17603266338214976. */
	const double zero[] = {0}, two[] = {1, 3};
	const double g[] = {-0.5, 0, 1, 2};
	double f[4], fr[4], f2[4];
	stats_kde(zero, 1, 1, 0, g, 4, f);
	stats_kde(zero, 1, 1, 1, g, 4, fr);
	stats_kde(two, 2, 2, 0, g, 4, f2);
	tap_near(f[1], 0.3989422804014327, 1e-14, "KDE of {0} at 0, h = 1");
	tap_near(fr[1], 0.7978845608028654, 1e-14,
		 "reflected KDE of {0} at 0 doubles");
	tap_near(fr[2], 0.48394144903828673, 1e-14,
		 "reflected KDE of {0} at 1 is 2 phi(1)");
	tap_ok(fr[0] == 0 && f[0] > 0, "reflected KDE is 0 below 0");
	tap_near(f2[3], 0.17603266338214976, 1e-14, "KDE of {1,3} at 2, h = 2");

	/* Integrals, Simpson on 40000 segments: a sample piled near 0. */
	const double x[] = {0.02, 0.05, 0.1, 0.15, 0.3, 0.5, 0.04, 0.08,
			    0.01, 0.2};
	size_t n = N_OF(x), nseg = 40000;
	double h = stats_kde_bandwidth(x, n);
	double *gr = malloc((nseg + 1) * sizeof *gr);
	double *fv = malloc((nseg + 1) * sizeof *fv);

	double b = 0.5 + 12 * h, dx = b / (double)nseg;
	for (size_t i = 0; i <= nseg; i++)
		gr[i] = (double)i * dx;
	stats_kde(x, n, 0, 1, gr, nseg + 1, fv);
	double with = simpson(fv, nseg, dx);
	stats_kde(x, n, 0, 0, gr, nseg + 1, fv);
	double without = simpson(fv, nseg, dx);
	tap_near(with, 1, 1e-3, "reflected KDE integrates to 1 over [0, inf)");
	tap_ok(without < 0.9,
	       "unreflected KDE of the same sample loses mass below 0 (%.3f)",
	       without);

	double a0 = 0.01 - 12 * h;
	dx = (b - a0) / (double)nseg;
	for (size_t i = 0; i <= nseg; i++)
		gr[i] = a0 + (double)i * dx;
	stats_kde(x, n, 0, 0, gr, nseg + 1, fv);
	tap_near(simpson(fv, nseg, dx), 1, 1e-6,
		 "unreflected KDE integrates to 1 over R");
	free(gr);
	free(fv);
}

static void test_normal_fit(void)
{
	/* {2,4,4,4,5,5,7,9}: mean 5, sum of squares 32, sample sd
	 * sqrt(32/7) = 2.138089935299395 (the population sd would be 2). */
	const double x[] = {2, 4, 4, 4, 5, 5, 7, 9};
	double mu, sigma;
	stats_normal_fit(x, 8, &mu, &sigma);
	tap_near(mu, 5, 1e-14, "normal fit mean");
	tap_near(sigma, 2.138089935299395, 1e-14,
		 "normal fit sd uses n - 1");
}

/* Check all six numbers of a KS result. */
static void ks_case(const char *name, const double *x, size_t n,
		    const double *y, size_t m, double d, double dp, double dm,
		    double p2, double pg, double pl)
{
	struct stats_ks k;
	int r = stats_ks2(x, n, y, m, &k);
	tap_ok(r == 0 && k.exact, "KS %s: exact", name);
	tap_ok(fabs(k.d - d) < 1e-14 && fabs(k.d_plus - dp) < 1e-14 &&
		       fabs(k.d_minus - dm) < 1e-14,
	       "KS %s: d %.6g, d+ %.6g, d- %.6g (got %.6g %.6g %.6g)", name,
	       d, dp, dm, k.d, k.d_plus, k.d_minus);
	char t[3][96];
	snprintf(t[0], sizeof t[0], "KS %s: two-sided p", name);
	snprintf(t[1], sizeof t[1], "KS %s: p greater", name);
	snprintf(t[2], sizeof t[2], "KS %s: p less", name);
	tap_near(k.p_two_sided, p2, 1e-13, "%s", t[0]);
	tap_near(k.p_greater, pg, 1e-13, "%s", t[1]);
	tap_near(k.p_less, pl, 1e-13, "%s", t[2]);
}

static void test_ks_small(void)
{
	/* No ties, complete separation: d = d+ = 1, d- = 0.  Of the
	 * C(6,3) = 20 arrangements, xxxyyy and yyyxxx reach |D| = 1:
	 * p = 2/20 = 0.1; only xxxyyy reaches D+ = 1: 1/20; D- >= 0
	 * always: 1.  (R: ks.test(1:3, 4:6)$p.value = 0.1.) */
	const double x1[] = {1, 2, 3}, y1[] = {4, 5, 6};
	ks_case("{1,2,3} vs {4,5,6}", x1, 3, y1, 3, 1, 1, 0, 0.1, 0.05, 1);

	/* No ties, interleaved: d = d+ = d- = 1/4, the least possible;
	 * enumerated: p = 1, greater 26/35, less 26/35. */
	const double x2[] = {1, 3, 5, 7}, y2[] = {2, 4, 6};
	ks_case("interleaved 4/3", x2, 4, y2, 3, 0.25, 0.25, 0.25, 1,
		26.0 / 35, 26.0 / 35);

	/* No ties, 5 vs 6: d = d+ = 7/15, d- = 0; enumerated over
	 * C(11,5) = 462: p = 73/154, greater 5/21, less 1. */
	const double x3[] = {0.1, 0.4, 0.5, 0.9, 1.3};
	const double y3[] = {0.2, 0.6, 1.0, 1.1, 1.4, 1.5};
	ks_case("5 vs 6 no ties", x3, 5, y3, 6, 7.0 / 15, 7.0 / 15, 0,
		73.0 / 154, 5.0 / 21, 1);

	/* Ties across the samples (the value 2 in both, 3 in both):
	 * d = d+ = 11/20 (after the 2s: F_x = 3/4, F_y = 1/5), d- = 0;
	 * enumerated over C(9,4) = 126: p = 13/63, greater 1/6, less 1.
	 * Checking the boundary at every lattice point instead of at
	 * group ends would give 3/7 and 3/14. */
	const double x4[] = {1, 2, 2, 3}, y4[] = {2, 3, 3, 4, 5};
	ks_case("ties across", x4, 4, y4, 5, 0.55, 0.55, 0, 13.0 / 63,
		1.0 / 6, 1);

	/* Heavy ties: {1,1,2,2,2} vs {1,2,3,3}: d = d+ = 1/2, d- = 0;
	 * enumerated: p = 2/7, greater 5/21, less 1. */
	const double x5[] = {1, 1, 2, 2, 2}, y5[] = {1, 2, 3, 3};
	ks_case("heavy ties", x5, 5, y5, 4, 0.5, 0.5, 0, 2.0 / 7, 5.0 / 21,
		1);

	/* Ties, x larger (the "less" side): {3,4,4,6} vs {1,2,2,4,5}:
	 * d = d- = 3/5, d+ = 0; enumerated: p = 1/6, greater 1, less
	 * 5/42 (every lattice point: 2/7 and 1/7). */
	const double x6[] = {3, 4, 4, 6}, y6[] = {1, 2, 2, 4, 5};
	ks_case("ties, x larger", x6, 4, y6, 5, 0.6, 0, 0.6, 1.0 / 6, 1,
		5.0 / 42);

	/* Swapping the samples swaps d+ with d- and greater with less. */
	struct stats_ks k;
	stats_ks2(y4, 5, x4, 4, &k);
	tap_ok(fabs(k.d_minus - 0.55) < 1e-14 && k.d_plus == 0 &&
		       fabs(k.p_less - 1.0 / 6) < 1e-13 && k.p_greater == 1 &&
		       fabs(k.p_two_sided - 13.0 / 63) < 1e-13,
	       "KS swap: ks(y, x) mirrors ks(x, y)");

	/* Tiny p-values keep their digits: 1..50 against 51..100, only one
	 * of the C(100,50) arrangements reaches D+ = 1, p greater =
	 * 1/C(100,50) = 9.911653021418339e-30, two-sided twice that
	 * (Python math.comb).  1 - P(inside) would round to 0. */
	double lo50[50], hi50[50];
	for (int i = 0; i < 50; i++) {
		lo50[i] = i + 1;
		hi50[i] = i + 51;
	}
	stats_ks2(lo50, 50, hi50, 50, &k);
	tap_ok(fabs(k.p_greater / 9.911653021418339e-30 - 1) < 1e-10 &&
		       fabs(k.p_two_sided / 1.9823306042836678e-29 - 1) <
			       1e-10,
	       "KS 1..50 vs 51..100: p greater = 1/C(100,50) = %.6g",
	       k.p_greater);

	/* All values equal: d = 0, every p = 1. */
	const double e1[] = {1, 1}, e2[] = {1, 1, 1};
	stats_ks2(e1, 2, e2, 3, &k);
	tap_ok(k.d == 0 && k.p_two_sided == 1 && k.p_greater == 1 &&
		       k.p_less == 1,
	       "KS of identical constants: d = 0, p = 1");
	tap_ok(stats_ks2(e1, 0, e2, 3, &k) == -1, "KS of an empty sample fails");
}

static void test_ks_large(void)
{
	/* n = m = 3000 (n m = 9e6, still exact): x = 0..2999,
	 * y = x + 99.5, so D+ = 100/3000 and D- = 0.  Without ties and
	 * n = m the law is closed (Gnedenko & Korolyuk 1951):
	 * P(D+ >= k/n) = C(2n, n-k) / C(2n, n) = 0.035671790338095866,
	 * P(D >= k/n) = 2 sum_j (-1)^(j-1) C(2n, n-jk) / C(2n, n) =
	 * 0.07134036622341668 (Python math.comb, exact). */
	size_t n = 3000;
	double *x = malloc(4000 * sizeof *x), *y = malloc(4000 * sizeof *y);
	for (size_t i = 0; i < n; i++) {
		x[i] = (double)i;
		y[i] = (double)i + 99.5;
	}
	struct stats_ks k;
	clock_t t0 = clock();
	stats_ks2(x, n, y, n, &k);
	double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
	tap_ok(k.exact && fabs(k.d_plus - 100.0 / 3000) < 1e-15,
	       "KS 3000 x 3000 is exact, d+ = 1/30 (%.2f s)", secs);
	tap_near(k.p_greater, 0.035671790338095866, 1e-10,
		 "KS 3000 x 3000: p greater = C(6000,2900)/C(6000,3000)");
	tap_near(k.p_two_sided, 0.07134036622341668, 1e-10,
		 "KS 3000 x 3000: two-sided p (Gnedenko-Korolyuk)");
	tap_ok(k.p_less == 1, "KS 3000 x 3000: p less = 1");

	/* n = m = 4000 (1.6e7 > 1e7): asymptotic.  Shift 99.5 gives
	 * d = 1/40, n m/(n+m) = 2000, t = sqrt(2000)/40 = 1.118:
	 * one-sided exp(-2 * 2000 / 1600) = exp(-2.5) = 0.0820849986238988,
	 * two-sided 2 sum (-1)^(j-1) exp(-2 j^2 t^2) = 0.1640791977266521.
	 * Shift 39.5: t = 0.4472 (the theta-series branch), two-sided
	 * 0.9882610776435246 (both series agree in Python to 1e-16). */
	n = 4000;
	for (size_t i = 0; i < n; i++) {
		x[i] = (double)i;
		y[i] = (double)i + 99.5;
	}
	stats_ks2(x, n, y, n, &k);
	tap_ok(!k.exact, "KS 4000 x 4000 switches to the asymptotic law");
	tap_near(k.p_greater, 0.0820849986238988, 1e-12,
		 "KS asymptotic one-sided p = exp(-2.5)");
	tap_near(k.p_two_sided, 0.1640791977266521, 1e-12,
		 "KS asymptotic two-sided p at t = 1.118");
	for (size_t i = 0; i < n; i++)
		y[i] = (double)i + 39.5;
	stats_ks2(x, n, y, n, &k);
	tap_near(k.p_two_sided, 0.9882610776435246, 1e-12,
		 "KS asymptotic two-sided p at t = 0.447");
	free(x);
	free(y);
}

static void test_sorted_insert(void)
{
	struct stats_sorted s = {0};
	gsl_rng *rng = gsl_rng_alloc(gsl_rng_mt19937);
	gsl_rng_set(rng, 3);
	int ok = 1;
	for (int i = 0; i < 1000; i++)
		stats_sorted_insert(&s, (double)gsl_rng_uniform_int(rng, 50));
	gsl_rng_free(rng);
	for (size_t i = 1; i < s.n; i++)
		ok &= s.x[i - 1] <= s.x[i];
	tap_ok(s.n == 1000 && ok, "sorted insert: 1000 values, in order");
	stats_sorted_insert(&s, -1);
	stats_sorted_insert(&s, 1e9);
	tap_ok(s.x[0] == -1 && s.x[s.n - 1] == 1e9 && s.n == 1002,
	       "sorted insert at both ends");
	stats_sorted_free(&s);
	tap_ok(s.x == NULL && s.n == 0, "sorted free resets");
}

static int cmp_dbl(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

/* P(B >= k), B ~ Binomial(n, p), by summing the pmf (lgamma): an
 * independent check of the beta quantiles. */
static double binom_upper(size_t k, size_t n, double p)
{
	double sum = 0;
	for (size_t j = k; j <= n; j++)
		sum += exp(lgamma((double)n + 1) - lgamma((double)j + 1) -
			   lgamma((double)(n - j) + 1) + (double)j * log(p) +
			   (double)(n - j) * log1p(-p));
	return sum;
}

static void test_collapse_probability(void)
{
	double x[] = {1, 2, 2, 2, 3, 5};
	tap_ok(stats_count_le(x, 6, 0.5) == 0 && stats_count_le(x, 6, 2) == 4 &&
	       stats_count_le(x, 6, 2.5) == 4 && stats_count_le(x, 6, 5) == 6 &&
	       stats_count_le(x, 6, 9) == 6, "count_le with ties and ends");

	/* Clopper-Pearson: each end leaves 0.5 % in its tail */
	static const size_t cases[][2] = {{1, 10}, {7, 40}, {50, 200},
					  {199, 200}, {3, 1000}};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		size_t k = cases[i][0], n = cases[i][1];
		double lo, hi;
		stats_binomial_ci(k, n, 0.99, &lo, &hi);
		tap_ok(lo < (double)k / (double)n && (double)k / (double)n < hi &&
		       fabs(binom_upper(k, n, lo) - 0.005) < 1e-7 &&
		       fabs((1 - binom_upper(k + 1, n, hi)) - 0.005) < 1e-7,
		       "binomial 99 %% interval of %zu of %zu: [%g, %g], tails "
		       "0.005 (by summing the pmf)", k, n, lo, hi);
	}
	double lo, hi;
	stats_binomial_ci(0, 50, 0.99, &lo, &hi);
	tap_near(hi, 1 - pow(0.005, 1.0 / 50), 1e-9,
		 "0 of 50: [0, 1 - 0.005^(1/50)]");
	tap_ok(lo == 0, "0 of 50: the low end is 0");
	stats_binomial_ci(50, 50, 0.99, &lo, &hi);
	tap_ok(hi == 1 && fabs(lo - pow(0.005, 1.0 / 50)) < 1e-9,
	       "50 of 50: [0.005^(1/50), 1]");
	stats_binomial_ci(3, 2, 0.99, &lo, &hi);
	tap_ok(isnan(lo) && isnan(hi), "k > n: NaN");

	/* DKW: over many uniform samples the true CDF (F(u) = u) stays in
	 * the band in at least 99 % of them; a band 0.7 times as wide
	 * misses often, so the band is not vacuous */
	size_t n = 40, reps = 4000, in = 0, in_narrow = 0;
	double eps = stats_dkw_eps(n, 0.99), u[40];
	tap_near(eps, sqrt(log(200.0) / 80), 1e-12, "DKW eps(40, 0.99)");
	unsigned long long st = 12345;
	for (size_t r = 0; r < reps; r++) {
		for (size_t i = 0; i < n; i++) {
			st = st * 6364136223846793005ULL + 1442695040888963407ULL;
			u[i] = (double)(st >> 11) / 9007199254740992.0;
		}
		qsort(u, n, sizeof u[0], cmp_dbl);
		double d = 0;
		for (size_t i = 0; i < n; i++)
			d = fmax(d, fmax(fabs((double)(i + 1) / (double)n - u[i]),
					 fabs((double)i / (double)n - u[i])));
		in += d <= eps;
		in_narrow += d <= 0.7 * eps;
	}
	tap_ok((double)in / (double)reps >= 0.99,
	       "DKW band holds the true CDF in %zu of %zu samples (>= 99 %%)",
	       in, reps);
	tap_ok((double)in_narrow / (double)reps < 0.98,
	       "a band 0.7 times as wide holds it in only %zu", in_narrow);
}

/* stats_bin: the one binning of the histogram, the report's classes and
 * the workbench's histogram; stats_sorted_copy. */
static void test_bin_and_sort(void)
{
	/* bins [0,1) [1,2) [2,3] of width 1 from 0: 0.999 is in bin 0, 1 in
	 * bin 1 (half-open), 3 in the closed last bin, -0.5 below lo in
	 * the first, 7 beyond the top in the last, 2.5 in bin 2 */
	tap_ok(stats_bin(0.999, 0, 1, 3) == 0 && stats_bin(1, 0, 1, 3) == 1,
	       "stats_bin: bins are half-open [lo + k w, lo + (k+1) w)");
	tap_ok(stats_bin(3, 0, 1, 3) == 2 && stats_bin(7, 0, 1, 3) == 2,
	       "stats_bin: the top value and beyond fall in the last bin");
	tap_ok(stats_bin(-0.5, 0, 1, 3) == 0,
	       "stats_bin: a value below lo falls in the first bin");
	/* lo = 10, width 0.25: 10.6 is 2.4 widths up: bin 2 */
	tap_ok(stats_bin(10.6, 10, 0.25, 8) == 2 &&
		       stats_bin(1e300, 10, 0.25, 8) == 7,
	       "stats_bin: 10.6 from 10 by 0.25 is bin 2; 1e300 the last (8)");
	const double x[] = {3, -1, 2.5, 0, 2.5};
	double *s = stats_sorted_copy(x, N_OF(x));
	tap_ok(s[0] == -1 && s[1] == 0 && s[2] == 2.5 && s[3] == 2.5 &&
		       s[4] == 3 && x[0] == 3 && x[1] == -1,
	       "stats_sorted_copy: {3,-1,2.5,0,2.5} -> {-1,0,2.5,2.5,3}, "
	       "the input untouched");
	free(s);
	s = stats_sorted_copy(x, 0);
	tap_ok(s != NULL, "stats_sorted_copy of nothing is a valid pointer");
	free(s);
}

int main(void)
{
	test_bin_and_sort();
	test_collapse_probability();
	test_quantiles();
	test_ci_ranks();
	test_summary();
	test_histogram();
	test_kde();
	test_normal_fit();
	test_ks_small();
	test_ks_large();
	test_sorted_insert();
	return tap_done();
}
