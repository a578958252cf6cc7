/*
 * stats.h - statistics of the accepted collapse loads.
 *
 * Knows nothing of walls or solvers: arrays of doubles in, numbers out.
 * GSL provides sorting, moments and quantiles; what no well-kept library
 * provides (the exact two-sample Kolmogorov-Smirnov p-value with ties,
 * the reflected Gaussian KDE, the order-statistic interval, binomial
 * tails and the Clopper-Pearson interval that converge for every n) is
 * written here by hand, each with a comment that says so and cites the
 * method.  Nothing here calls a GSL function that can fail.
 *
 * Percentile definition everywhere: Hyndman & Fan type 7 (linear
 * interpolation between order statistics, R's default and
 * gsl_stats_quantile_from_sorted_data).
 */
#ifndef SLIPWALL_STATS_H
#define SLIPWALL_STATS_H

#include <stddef.h>

/* Quantile p in [0,1] of sorted data x[0..n-1] (type 7).  p outside
 * [0,1] is clamped; n == 0 or p NaN gives NaN. */
double stats_quantile_sorted(const double *x, size_t n, double p);

/* Distribution-free confidence interval for the p-quantile from order
 * statistics (binomial): the 1-based ranks lo < hi with
 * P(X(lo) <= xi_p <= X(hi)) >= conf and hi - lo least; among equally
 * short ones the B-range [lo, hi-1] centred nearest n*p, then the larger
 * coverage.  Returns 0 and fills lo, hi; returns -1 when n is too small
 * for that confidence (even (1, n) falls short: for p = 0.05 and
 * conf = 0.99 that is n < 90) or p, conf are not in (0,1). */
int stats_quantile_ci_ranks(size_t n, double p, double conf, size_t *lo,
			    size_t *hi);
/* Exact coverage P(X(lo) <= xi_p <= X(hi)) = P(lo <= B < hi),
 * B ~ Binomial(n, p) (continuous data).  NaN unless 1 <= lo < hi <= n
 * and 0 < p < 1. */
double stats_quantile_ci_coverage(size_t n, double p, size_t lo, size_t hi);

/* Binomial tails of B ~ Bin(n, p), n <= STATS_BINOM_MAX_N (2^53, where
 * counts stop being exact doubles), p in [0, 1]: P(B >= k) and
 * P(B <= k), the small one of the two to a relative accuracy near
 * 1e-13 (written here: Loader's binomial term times the continued
 * fraction of the incomplete beta; docs/statistics.md).  NaN for bad
 * arguments, or if the fraction does not converge (never seen). */
#define STATS_BINOM_MAX_N 9007199254740992.0
double stats_binom_ge(size_t k, size_t n, double p);
double stats_binom_le(size_t k, size_t n, double p);

/* The probability of collapse at a load (`run --at`, fragility):
 * stats_count_le is the number of sorted x[0..n-1] that are <= v;
 * stats_binomial_ci the exact (Clopper-Pearson) interval of a binomial
 * proportion, k of n (1 <= n <= 2^53, k <= n), at confidence conf in
 * (0,1): lo = Beta^-1((1-conf)/2; k, n-k+1) (0 when k = 0), hi =
 * Beta^-1((1+conf)/2; k+1, n-k) (1 when k = n), so P(B >= k | lo) =
 * P(B <= k | hi) = (1-conf)/2; found by bisection on the tails above to
 * the nearest double (the ends of {p : tail >= (1-conf)/2}); NaNs for
 * bad arguments.  stats_dkw_eps: the half-width of the
 * Dvoretzky-Kiefer-Wolfowitz band, sqrt(ln(2/(1-conf)) / (2n)) (Massart's
 * constant): the true CDF lies within the empirical CDF +- eps at every
 * load at once with probability >= conf. */
size_t stats_count_le(const double *sorted, size_t n, double v);
void stats_binomial_ci(size_t k, size_t n, double conf, double *lo,
		       double *hi);
double stats_dkw_eps(size_t n, double conf);

struct stats_summary {
	size_t n;
	double min, p05, p50, p95, max;
	double mean, std;	/* std: sample standard deviation (n - 1) */
	int has_ci;		/* the interval of p05 exists */
	double p05_lo, p05_hi;	/* its ends (order statistics) */
	double ci_conf;		/* its level: 0.99 but under --until-ci */
};
/* Summary of x[0..n-1] (any order; not modified).  n == 0 gives n = 0 and
 * NaN everywhere; n == 1 gives std = NaN.  The interval of p05 is at
 * 99 %; has_ci needs n >= 90; without it p05_lo and p05_hi are NaN.
 * stats_summarise_conf: the interval at level conf instead (--until-ci's
 * split level, run.h; has_ci needs more samples the higher it is). */
void stats_summarise(const double *x, size_t n, struct stats_summary *s);
void stats_summarise_conf(const double *x, size_t n, double conf,
			  struct stats_summary *s);

/* Sort x[0..n-1] in place, ascending (gsl_sort). */
void stats_sort(double *x, size_t n);
/* A sorted copy of x[0..n-1], malloc'd (never NULL, n may be 0). */
double *stats_sorted_copy(const double *x, size_t n);
/* The bin of x among nbins bins [lo + k width, lo + (k+1) width):
 * floor((x - lo) / width), clamped to 0 .. nbins - 1 (values below lo
 * fall in the first bin, the top value in the last). */
int stats_bin(double x, double lo, double width, int nbins);

/* Freedman-Diaconis bin width 2 IQR n^(-1/3) of sorted x; falls back to
 * Scott's rule, then to 1, when the IQR or the spread is zero. */
double stats_fd_width(const double *sorted, size_t n);

struct stats_hist {
	double lo, width;	/* bin k covers [lo + k w, lo + (k+1) w) */
	int nbins;
	size_t *count;		/* owned, nbins */
};
/* Histogram of sorted x with the given width (<= 0: Freedman-Diaconis),
 * at most max_bins bins (the width grows to fit; max_bins <= 0 means
 * 1000).  lo is the minimum (constant data: one bin centred on it); the
 * last bin is closed, so every value is counted.  n == 0 gives nbins = 0
 * and count NULL.  Free with stats_hist_free. */
void stats_histogram(const double *sorted, size_t n, double width,
		     int max_bins, struct stats_hist *h);
void stats_hist_free(struct stats_hist *h);

/* Gaussian kernel density estimate of x at the points g[0..ng-1].
 * bw <= 0: Silverman's rule 0.9 min(sd, IQR/1.34) n^(-1/5).  When
 * reflect_at_zero, the kernel is reflected at 0 (density 0 below 0 and
 * integrating to 1 over [0, inf)); loads are >= 0. */
void stats_kde(const double *x, size_t n, double bw, int reflect_at_zero,
	       const double *g, size_t ng, double *out);
double stats_kde_bandwidth(const double *x, size_t n);

/* Best-fit normal: mean and sample standard deviation (NaN for n < 2). */
void stats_normal_fit(const double *x, size_t n, double *mu, double *sigma);

/* Two-sample Kolmogorov-Smirnov test of x (n) against y (m), exact
 * p-values conditional on the pooled sample, ties handled (Nikiforov
 * 1994, AS 288; the lattice-path count checks the boundary only at the
 * ends of tied groups).  Alternatives as in R's ks.test(x, y):
 *   "less":    the CDF of x lies below that of y (x tends to be larger),
 *              statistic d_minus = max (F_y - F_x);
 *   "greater": the CDF of x lies above that of y, d_plus = max (F_x - F_y).
 * All three p-values are reported; which one answers the paper's
 * "numerical model < experimental test" hypothesis (x = model) is
 * documented in docs/statistics.md (in short: "model < tests" is the
 * alternative of p_greater and the null hypothesis of p_less). */
struct stats_ks {
	double d, d_plus, d_minus;
	double p_two_sided, p_less, p_greater;
	int exact;		/* 0 when n*m too large: asymptotic */
};
/* Returns 0, or -1 (out untouched) when a sample is empty or holds NaN.
 * Exact when n*m <= 1e7 (O(n m) time, O(m) memory). */
int stats_ks2(const double *x, size_t n, const double *y, size_t m,
	      struct stats_ks *out);

/* A growing sorted array for running percentiles (insertion, O(n)).
 * Start from {0}; equal values go after those already present. */
struct stats_sorted {
	double *x;
	size_t n, cap;
};
void stats_sorted_insert(struct stats_sorted *s, double v);
void stats_sorted_free(struct stats_sorted *s);

#endif
