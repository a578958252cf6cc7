/*
 * stats.c - statistics of the accepted collapse loads.
 *
 * Called by the Monte Carlo driver (running percentiles), the report and
 * the workbench screens, and by `slipwall compare` (KS against tests).
 * Plain arrays of doubles in, numbers out; nothing here knows of walls,
 * solvers, threads or the terminal, and nothing is kept between calls
 * (no static state: every function is safe to call from any thread).
 *
 * What GSL does, GSL does: sorting (gsl_sort), mean and standard
 * deviation (gsl_stats_mean, gsl_stats_sd), type-7 quantiles
 * (gsl_stats_quantile_from_sorted_data) and the normal density
 * (gsl_ran_ugaussian_pdf) - none of which can fail.
 * What no Debian library provides is written here by hand:
 *   - the binomial tails and the Clopper-Pearson interval, for every n
 *     up to 2^53 (GSL's fail to converge, below);
 *   - the shortest order-statistic confidence interval for a quantile;
 *   - the Gaussian kernel density estimate reflected at zero;
 *   - the exact two-sample Kolmogorov-Smirnov p-value conditional on the
 *     pooled sample, with ties (Nikiforov 1994, Applied Statistics
 *     algorithm AS 288), and its asymptotic fallback.
 * docs/statistics.md gives the definitions and the conventions.
 *
 * Memory: scratch copies come from sw_xmalloc (which aborts on
 * exhaustion) and are freed before returning; the only memory handed to
 * the caller is stats_hist.count and stats_sorted.x.
 */
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_randist.h>
#include <gsl/gsl_sort.h>
#include <gsl/gsl_statistics_double.h>

#include "slipwall/stats.h"
#include "slipwall/status.h"

/* Confidence of the interval of the characteristic value (docs/statistics.md). */
#define STATS_P05_CONF 0.99
/* Largest n*m for the exact KS lattice count (O(n m) time). */
#define STATS_KS_EXACT_MAX 10000000.0
/* Default bin cap of stats_histogram when max_bins <= 0. */
#define STATS_HIST_DEFAULT_MAX 1000
#define STATS_PI 3.14159265358979323846

/* KDE: kernels further than this many bandwidths away are dropped
 * (phi(8.5) / phi(0) < 2e-16). */
#define STATS_KDE_CUT 8.5

void stats_sort(double *x, size_t n)
{
	if (n > 1)
		gsl_sort(x, 1, n);
}

double *stats_sorted_copy(const double *x, size_t n)
{
	double *s = sw_xmalloc(sizeof(double) * (n ? n : 1));
	memcpy(s, x, sizeof(double) * n);
	stats_sort(s, n);
	return s;
}

int stats_bin(double x, double lo, double width, int nbins)
{
	double k = floor((x - lo) / width);
	return k < 0 ? 0 : k >= nbins ? nbins - 1 : (int)k;
}

/* ---- quantiles -------------------------------------------------------- */

double stats_quantile_sorted(const double *x, size_t n, double p)
{
	if (n == 0 || isnan(p))
		return NAN;
	if (p <= 0)
		return x[0];
	if (p >= 1)
		return x[n - 1];
	/* GSL's definition is Hyndman-Fan type 7:
	 * h = (n - 1) p, x[floor h] + (h - floor h)(x[floor h + 1] - ...). */
	return gsl_stats_quantile_from_sorted_data(x, 1, n, p);
}

/* P(B <= k) and P(B > k), B ~ Bin(n, p): stats_binom_le / _ge below. */
static double binom_le(size_t k, double p, size_t n)
{
	return stats_binom_le(k, n, p);
}

static double binom_gt(size_t k, double p, size_t n)
{
	return stats_binom_ge(k + 1, n, p);
}

double stats_quantile_ci_coverage(size_t n, double p, size_t lo, size_t hi)
{
	if (n == 0 || n > STATS_BINOM_MAX_N || lo < 1 || hi <= lo || hi > n ||
	    !(p > 0 && p < 1))
		return NAN;
	/* P(lo <= B <= hi - 1): difference of the two lower tails, or of
	 * the two upper tails when lo lies in the upper half, so that the
	 * smaller tail is subtracted and its digits are not lost. */
	double below = binom_le(lo - 1, p, n);
	if (below < 0.5)
		return binom_le(hi - 1, p, n) - below;
	return binom_gt(lo - 1, p, n) - binom_gt(hi - 1, p, n);
}

/*
 * Written here: the shortest distribution-free interval (X(lo), X(hi))
 * for the p-quantile (David & Nagaraja, Order Statistics, 3rd ed., 7.1).
 * B, the number of observations below xi_p, is Bin(n, p); the interval
 * covers xi_p exactly when lo <= B <= hi - 1.  For every lo the least hi
 * reaching conf is found; it never decreases as lo grows (the coverage
 * falls with lo), so one forward walk of both ends visits each rank at
 * most once.  Among the shortest intervals the one whose B-range
 * [lo, hi - 1] is centred nearest n p wins; then the larger coverage.
 */
int stats_quantile_ci_ranks(size_t n, double p, double conf, size_t *lo,
			    size_t *hi)
{
	if (n < 2 || n > STATS_BINOM_MAX_N || !(p > 0 && p < 1) ||
	    !(conf > 0 && conf < 1))
		return -1;
	if (!(stats_quantile_ci_coverage(n, p, 1, n) >= conf))
		return -1;

	double np2 = 2 * (double)n * p;
	size_t best_lo = 0, best_hi = 0;
	double best_off = 0, best_cov = 0;
	size_t h = 2;
	for (size_t l = 1; l < n; l++) {
		/* Even hi = n falls short: so will every larger l. */
		if (!(stats_quantile_ci_coverage(n, p, l, n) >= conf))
			break;
		if (h <= l)
			h = l + 1;
		double cov = stats_quantile_ci_coverage(n, p, l, h);
		while (!(cov >= conf))
			cov = stats_quantile_ci_coverage(n, p, l, ++h);
		double off = fabs((double)(l + h - 1) - np2);
		int better = best_lo == 0 || h - l < best_hi - best_lo ||
			     (h - l == best_hi - best_lo &&
			      (off < best_off ||
			       (off == best_off && cov > best_cov)));
		if (better) {
			best_lo = l;
			best_hi = h;
			best_off = off;
			best_cov = cov;
		}
	}
	if (best_lo == 0)
		return -1;
	*lo = best_lo;
	*hi = best_hi;
	return 0;
}

/* ---- summary ---------------------------------------------------------- */

/* The sample standard deviation about `mean`.  GSL's, unless the values
 * are near either end of the doubles (a wall in odd units: loads of
 * 1e-306 or 1e200), where the squared deviations underflow to 0 or
 * overflow: there the deviations are squared scaled by the largest
 * |x|. */
static double sd_m(const double *x, size_t n, double mean)
{
	double sc = 0;
	for (size_t i = 0; i < n; i++)
		sc = fmax(sc, fabs(x[i]));
	if (!(sc > 0) || (sc > 1e-100 && sc < 1e100))
		return gsl_stats_sd_m(x, 1, n, mean);
	double q = 0;
	for (size_t i = 0; i < n; i++) {
		double d = x[i] / sc - mean / sc;
		q += d * d;
	}
	return sc * sqrt(q / (double)(n - 1));
}

void stats_summarise(const double *x, size_t n, struct stats_summary *s)
{
	stats_summarise_conf(x, n, STATS_P05_CONF, s);
}

void stats_summarise_conf(const double *x, size_t n, double conf,
			  struct stats_summary *s)
{
	s->n = n;
	s->ci_conf = conf;
	s->min = s->p05 = s->p50 = s->p95 = s->max = NAN;
	s->mean = s->std = NAN;
	s->has_ci = 0;
	s->p05_lo = s->p05_hi = NAN;
	if (n == 0)
		return;

	double *v = stats_sorted_copy(x, n);
	s->min = v[0];
	s->max = v[n - 1];
	s->p05 = stats_quantile_sorted(v, n, 0.05);
	s->p50 = stats_quantile_sorted(v, n, 0.50);
	s->p95 = stats_quantile_sorted(v, n, 0.95);
	s->mean = gsl_stats_mean(v, 1, n);
	if (n >= 2)
		s->std = sd_m(v, n, s->mean);
	size_t lo, hi;
	if (stats_quantile_ci_ranks(n, 0.05, conf, &lo, &hi) == 0) {
		s->has_ci = 1;
		s->p05_lo = v[lo - 1];
		s->p05_hi = v[hi - 1];
	}
	free(v);
}

/* ---- histogram -------------------------------------------------------- */

double stats_fd_width(const double *sorted, size_t n)
{
	if (n < 2)
		return 1;
	double cbrt_n = cbrt((double)n);
	double iqr = stats_quantile_sorted(sorted, n, 0.75) -
		     stats_quantile_sorted(sorted, n, 0.25);
	if (iqr > 0)
		return 2 * iqr / cbrt_n;
	/* Scott (1979): 3.49 sd n^(-1/3). */
	double sd = sd_m(sorted, n, gsl_stats_mean(sorted, 1, n));
	if (sd > 0 && isfinite(sd))
		return 3.49 * sd / cbrt_n;
	return 1;
}

void stats_histogram(const double *sorted, size_t n, double width,
		     int max_bins, struct stats_hist *h)
{
	if (max_bins <= 0)
		max_bins = STATS_HIST_DEFAULT_MAX;
	if (!(width > 0) || !isfinite(width))
		width = stats_fd_width(sorted, n);
	if (n == 0) {
		h->lo = 0;
		h->width = width;
		h->nbins = 0;
		h->count = NULL;
		return;
	}

	double range = sorted[n - 1] - sorted[0];
	double lo = sorted[0];
	int nbins;
	if (range <= 0) {
		/* One value: one bin centred on it. */
		lo -= width / 2;
		nbins = 1;
	} else {
		/* The last bin is closed, so a range of exactly k widths
		 * needs k bins, not k + 1. */
		double nb = ceil(range / width);
		if (nb < 1)
			nb = 1;
		if (nb > max_bins) {
			width = range / max_bins;
			nb = max_bins;
		}
		nbins = (int)nb;
	}
	h->lo = lo;
	h->width = width;
	h->nbins = nbins;
	h->count = sw_xcalloc((size_t)nbins, sizeof *h->count);
	for (size_t i = 0; i < n; i++) {
		h->count[stats_bin(sorted[i], lo, width, nbins)]++;
	}
}

void stats_hist_free(struct stats_hist *h)
{
	free(h->count);
	h->count = NULL;
	h->nbins = 0;
}

/* ---- kernel density --------------------------------------------------- */

/* Silverman's rule on sorted data; the fallbacks are those of R's bw.nrd0
 * (a zero IQR uses sd, a zero sd uses |x_1|, then 1). */
static double silverman_sorted(const double *v, size_t n)
{
	double sd = n >= 2 ? sd_m(v, n, gsl_stats_mean(v, 1, n)) : 0;
	double iqr = stats_quantile_sorted(v, n, 0.75) -
		     stats_quantile_sorted(v, n, 0.25);
	double a = fmin(sd, iqr / 1.34);
	if (!(a > 0))
		a = sd;
	if (!(a > 0))
		a = fabs(v[0]);
	if (!(a > 0))
		a = 1;
	return 0.9 * a * pow((double)n, -0.2);
}

double stats_kde_bandwidth(const double *x, size_t n)
{
	if (n == 0)
		return NAN;
	double *v = stats_sorted_copy(x, n);
	double h = silverman_sorted(v, n);
	free(v);
	return h;
}

/* First index of sorted v[0..n-1] with v[i] >= t. */
static size_t lower_bound(const double *v, size_t n, double t)
{
	size_t a = 0, b = n;
	while (a < b) {
		size_t c = a + (b - a) / 2;
		if (v[c] < t)
			a = c + 1;
		else
			b = c;
	}
	return a;
}

/* Sum of phi((c - v[i]) / h) over the v[i] within STATS_KDE_CUT h of c. */
static double kernel_sum(const double *v, size_t n, double c, double h)
{
	double r = STATS_KDE_CUT * h, sum = 0;
	for (size_t i = lower_bound(v, n, c - r); i < n && v[i] <= c + r; i++)
		sum += gsl_ran_ugaussian_pdf((c - v[i]) / h);
	return sum;
}

/*
 * Written here: f(t) = 1/(n h) sum phi((t - x_i)/h), and with reflection
 * at 0 (Silverman 1986, 2.10) f(t) = 1/(n h) sum [phi((t - x_i)/h) +
 * phi((t + x_i)/h)] for t >= 0, 0 below: the mass the plain kernels put
 * below zero is folded back, so f integrates to 1 over [0, inf) when all
 * x_i >= 0.  phi((t + x_i)/h) = phi((-t - x_i)/h) is a kernel centred on
 * -t, which lets both sums use the same sorted window search.
 */
void stats_kde(const double *x, size_t n, double bw, int reflect_at_zero,
	       const double *g, size_t ng, double *out)
{
	if (n == 0) {
		for (size_t k = 0; k < ng; k++)
			out[k] = NAN;
		return;
	}
	double *v = stats_sorted_copy(x, n);
	double h = bw > 0 && isfinite(bw) ? bw : silverman_sorted(v, n);
	double scale = 1 / ((double)n * h);
	for (size_t k = 0; k < ng; k++) {
		double t = g[k];
		if (reflect_at_zero && t < 0) {
			out[k] = 0;
			continue;
		}
		double sum = kernel_sum(v, n, t, h);
		if (reflect_at_zero)
			sum += kernel_sum(v, n, -t, h);
		out[k] = scale * sum;
	}
	free(v);
}

void stats_normal_fit(const double *x, size_t n, double *mu, double *sigma)
{
	*mu = n ? gsl_stats_mean(x, 1, n) : NAN;
	*sigma = n >= 2 ? sd_m(x, n, *mu) : NAN;
}

/* ---- two-sample Kolmogorov-Smirnov ------------------------------------ */

/* One observation of the pooled sample and the sample it came from. */
struct ks_obs {
	double v;
	int from_x;
};

static int ks_obs_cmp(const void *a, const void *b)
{
	double u = ((const struct ks_obs *)a)->v;
	double w = ((const struct ks_obs *)b)->v;
	return (u > w) - (u < w);
}

/* Kolmogorov's limiting distribution, P(K > t) (two-sided).  For small t
 * the theta-function form converges fast, for large t the alternating
 * series (Marsaglia, Tsang & Wang 2003 use the same split). */
static double kolmogorov_q(double t)
{
	if (t <= 0)
		return 1;
	if (t < 1) {
		double s = 0, a = STATS_PI * STATS_PI / (8 * t * t);
		for (int k = 1; k <= 9; k += 2)
			s += exp(-(double)(k * k) * a);
		return 1 - sqrt(2 * STATS_PI) / t * s;
	}
	double s = 0;
	for (int k = 1; k <= 100; k++) {
		double term = exp(-2.0 * k * k * t * t);
		s += (k % 2 ? term : -term);
		if (term < 1e-17)
			break;
	}
	double q = 2 * s;
	return q < 0 ? 0 : q > 1 ? 1 : q;
}

/*
 * Written here, because no Debian-packaged library provides it: the exact
 * null distribution of the two-sample KS statistics conditional on the
 * pooled sample, with ties (Nikiforov 1994, "Algorithm AS 288: Exact
 * two-sample Kolmogorov-Smirnov test for arbitrary distributions",
 * Applied Statistics 43(1):265-270; R >= 4.3 psmirnov(exact = TRUE, obs =)
 * computes the same).  Under H0 all C(n+m, n) ways to label the sorted
 * pooled sample x or y are equally likely.  A labelling is a lattice path
 * from (0,0) to (n,m); after i x's and j y's, n m (F_x - F_y) =
 * i m - j n.  The ECDFs only exist at the end of a tied group, so the
 * path is checked only where i + j ends one.  p = P(D >= d) is the share
 * of paths that reach the boundary at some checked point.
 *
 * Everything is integer: the observed statistics are kept as K = n m d,
 * so "reaches d" is an exact integer comparison (R compares doubles with
 * a 1e-7 / (n m) allowance to the same effect).  The DP carries, for
 * each (i, j), the probability that a uniformly chosen path to (i, j)
 * has already hit the boundary:
 *   w(i,j) = 1 at a checked boundary point, else
 *   w(i,j) = i/(i+j) w(i-1,j) + j/(i+j) w(i,j-1)
 * (the last step of a uniform path to (i,j) comes from (i-1,j) with
 * probability C(i+j-1,i-1)/C(i+j,i) = i/(i+j)).  All values stay in
 * [0,1], so n and m in the thousands neither overflow nor underflow, and
 * small p-values keep their relative accuracy (the upper tail is summed
 * directly, not found as 1 - lower).  Three alternatives, three rows.
 */
static void ks_exact(size_t n, size_t m, const unsigned char *ends,
		     int64_t k2, int64_t kp, int64_t km, double *p2,
		     double *pp, double *pm)
{
	double *w2 = sw_xmalloc((m + 1) * sizeof *w2);
	double *wp = sw_xmalloc((m + 1) * sizeof *wp);
	double *wm = sw_xmalloc((m + 1) * sizeof *wm);
	int64_t N = (int64_t)n, M = (int64_t)m;

	for (size_t i = 0; i <= n; i++) {
		for (size_t j = 0; j <= m; j++) {
			double a2, ap, am;
			if (i == 0 && j == 0) {
				a2 = ap = am = 0;
			} else {
				double s = (double)(i + j);
				double fi = (double)i / s, fj = (double)j / s;
				/* w[j] still holds row i-1, w[j-1] row i */
				a2 = ap = am = 0;
				if (i > 0) {
					a2 += fi * w2[j];
					ap += fi * wp[j];
					am += fi * wm[j];
				}
				if (j > 0) {
					a2 += fj * w2[j - 1];
					ap += fj * wp[j - 1];
					am += fj * wm[j - 1];
				}
				if (ends[i + j]) {
					int64_t diff = (int64_t)i * M -
						       (int64_t)j * N;
					if (diff >= k2 || -diff >= k2)
						a2 = 1;
					if (diff >= kp)
						ap = 1;
					if (-diff >= km)
						am = 1;
				}
			}
			w2[j] = a2;
			wp[j] = ap;
			wm[j] = am;
		}
	}
	*p2 = fmin(1, w2[m]);
	*pp = fmin(1, wp[m]);
	*pm = fmin(1, wm[m]);
	free(w2);
	free(wp);
	free(wm);
}

int stats_ks2(const double *x, size_t n, const double *y, size_t m,
	      struct stats_ks *out)
{
	if (n == 0 || m == 0)
		return -1;
	for (size_t i = 0; i < n; i++)
		if (isnan(x[i]))
			return -1;
	for (size_t j = 0; j < m; j++)
		if (isnan(y[j]))
			return -1;

	size_t total = n + m;
	struct ks_obs *z = sw_xmalloc(total * sizeof *z);
	for (size_t i = 0; i < n; i++)
		z[i] = (struct ks_obs){x[i], 1};
	for (size_t j = 0; j < m; j++)
		z[n + j] = (struct ks_obs){y[j], 0};
	qsort(z, total, sizeof *z, ks_obs_cmp);

	/* ends[k]: the first k pooled values end a tied group (k = 1..N). */
	unsigned char *ends = sw_xcalloc(total + 1, 1);
	int64_t kp = 0, km = 0, N = (int64_t)n, M = (int64_t)m;
	size_t i = 0, j = 0;
	for (size_t k = 0; k < total; k++) {
		if (z[k].from_x)
			i++;
		else
			j++;
		if (k + 1 == total || z[k + 1].v != z[k].v) {
			ends[k + 1] = 1;
			int64_t diff = (int64_t)i * M - (int64_t)j * N;
			if (diff > kp)
				kp = diff;
			if (-diff > km)
				km = -diff;
		}
	}
	free(z);

	double nm = (double)n * (double)m;
	int64_t k2 = kp > km ? kp : km;
	out->d_plus = (double)kp / nm;
	out->d_minus = (double)km / nm;
	out->d = (double)k2 / nm;

	if (nm <= STATS_KS_EXACT_MAX) {
		ks_exact(n, m, ends, k2, kp, km, &out->p_two_sided,
			 &out->p_greater, &out->p_less);
		out->exact = 1;
	} else {
		/* Large samples: Smirnov's limits (continuous data; with
		 * ties they are conservative). */
		double en = nm / (double)total;
		out->p_two_sided = kolmogorov_q(sqrt(en) * out->d);
		out->p_greater = exp(-2 * en * out->d_plus * out->d_plus);
		out->p_less = exp(-2 * en * out->d_minus * out->d_minus);
		out->exact = 0;
	}
	free(ends);
	return 0;
}

/* ---- running sorted array --------------------------------------------- */

void stats_sorted_insert(struct stats_sorted *s, double v)
{
	if (s->n == s->cap) {
		s->cap = s->cap ? 2 * s->cap : 64;
		s->x = sw_xrealloc(s->x, s->cap * sizeof *s->x);
	}
	/* After any equal values already present (stable). */
	size_t a = 0, b = s->n;
	while (a < b) {
		size_t c = a + (b - a) / 2;
		if (s->x[c] <= v)
			a = c + 1;
		else
			b = c;
	}
	memmove(s->x + a + 1, s->x + a, (s->n - a) * sizeof *s->x);
	s->x[a] = v;
	s->n++;
}

void stats_sorted_free(struct stats_sorted *s)
{
	free(s->x);
	s->x = NULL;
	s->n = s->cap = 0;
}

/* ---- probability of collapse at a load ----------------------------------- */

size_t stats_count_le(const double *sorted, size_t n, double v)
{
	size_t lo = 0, hi = n;	/* the first index with x > v */
	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;
		if (sorted[mid] <= v)
			lo = mid + 1;
		else
			hi = mid;
	}
	return lo;
}

/*
 * Written here: the binomial tails and the Clopper-Pearson interval.
 * GSL's gsl_cdf_beta_Pinv, which the interval used before, fails to
 * converge for k = 1 at 28 values of n from 231 and for k = 2 at 2,556
 * values of n up to 5,000 (issue 23), and its binomial tails go through
 * a continued fraction capped at 512 terms; neither returns a status.
 *
 * P(B >= k) = I_p(k, n-k+1) and P(B <= k) = I_(1-p)(n-k, k+1), I the
 * regularised incomplete beta.  Each is the binomial probability of its
 * end term times the continued fraction of I (Numerical Recipes, 3rd
 * ed., 6.4, modified Lentz), taken only on the side where it converges
 * fast (the small tail; the large one is 1 - the other): for the upper
 * tail x^a (1-x)^b / (a B(a,b)) = P(B = k) (1 - p).  The term itself is
 * Loader's saddle-point form (C. Loader, "Fast and accurate computation
 * of binomial probabilities", 2000; R's dbinom_raw): Stirling's error
 * and the deviance bd0 keep its relative accuracy near 1e-14 for every
 * n up to 2^53, where exp(lgamma(n+1) - ...) loses half its digits at
 * n = 1e9.  The fraction needs O(sqrt(n)) terms at worst (about 30,000
 * at n = 1e9, k = n/2); it is cut at STATS_CF_MAXIT(a, b) and reports
 * NaN if it has not converged by then, which the sweep of the unit test
 * never saw.
 */
#define STATS_LN_SQRT_2PI 0.918938533204672741780329736406

/* Stirling's error ln n! - (n + 1/2) ln n + n - ln sqrt(2 pi), n >= 1. */
static double stirlerr(double n)
{
	const double s0 = 1.0 / 12, s1 = 1.0 / 360, s2 = 1.0 / 1260,
		     s3 = 1.0 / 1680, s4 = 1.0 / 1188;
	if (n <= 15)
		return lgamma(n + 1) - (n + 0.5) * log(n) + n -
		       STATS_LN_SQRT_2PI;
	double nn = n * n;
	if (n > 500)
		return (s0 - s1 / nn) / n;
	if (n > 80)
		return (s0 - (s1 - s2 / nn) / nn) / n;
	if (n > 35)
		return (s0 - (s1 - (s2 - s3 / nn) / nn) / nn) / n;
	return (s0 - (s1 - (s2 - (s3 - s4 / nn) / nn) / nn) / nn) / n;
}

/* The deviance x ln(x / np) + np - x, without cancellation near x = np. */
static double bd0(double x, double np)
{
	if (fabs(x - np) < 0.1 * (x + np)) {
		double v = (x - np) / (x + np), s = (x - np) * v;
		double ej = 2 * x * v;
		v *= v;
		for (int j = 1; j < 1000; j++) {
			ej *= v;
			double s1 = s + ej / (2 * j + 1);
			if (s1 == s)
				return s1;
			s = s1;
		}
		return s;
	}
	return x * log(x / np) + np - x;
}

/* P(B = k), B ~ Bin(n, p), q = 1 - p; 0 <= k <= n, 0 < p < 1. */
static double binom_pmf(double k, double n, double p, double q)
{
	if (k == 0)
		return exp(p < 0.1 ? -bd0(n, n * q) - n * p : n * log(q));
	if (k == n)
		return exp(q < 0.1 ? -bd0(n, n * p) - n * q : n * log(p));
	double lc = stirlerr(n) - stirlerr(k) - stirlerr(n - k) -
		    bd0(k, n * p) - bd0(n - k, n * q);
	double lf = 2 * STATS_LN_SQRT_2PI + log(k) + log1p(-k / n);
	return exp(lc - 0.5 * lf);
}

#define STATS_CF_MAXIT(a, b) (1000 + 20 * (long)sqrt(fmax(a, b)))

/* The continued fraction of I_x(a, b) (NR betacf), without the factor
 * x^a (1-x)^b / (a B(a, b)); NaN if it does not converge. */
static double beta_cf(double a, double b, double x)
{
	const double tiny = 1e-300, eps = 1e-16;
	double qab = a + b, qap = a + 1, qam = a - 1;
	double c = 1, d = 1 - qab * x / qap;
	if (fabs(d) < tiny)
		d = tiny;
	d = 1 / d;
	double h = d;
	long maxit = STATS_CF_MAXIT(a, b);
	for (long m = 1; m <= maxit; m++) {
		double dm = (double)m, m2 = 2 * dm;
		double aa = dm * (b - dm) * x / ((qam + m2) * (a + m2));
		d = 1 + aa * d;
		if (fabs(d) < tiny)
			d = tiny;
		c = 1 + aa / c;
		if (fabs(c) < tiny)
			c = tiny;
		d = 1 / d;
		h *= d * c;
		aa = -(a + dm) * (qab + dm) * x / ((a + m2) * (qap + m2));
		d = 1 + aa * d;
		if (fabs(d) < tiny)
			d = tiny;
		c = 1 + aa / c;
		if (fabs(c) < tiny)
			c = tiny;
		d = 1 / d;
		double del = d * c;
		h *= del;
		if (fabs(del - 1) < eps)
			return h;
	}
	return NAN;
}

/* The small-tail forms: P(B >= k) for p < (k+1)/(n+3) (1 <= k <= n) and
 * P(B <= k) for 1 - p < (n-k+1)/(n+3) (0 <= k < n). */
static double upper_cf(double k, double n, double p)
{
	return binom_pmf(k, n, p, 1 - p) * (1 - p) * beta_cf(k, n - k + 1, p);
}

static double lower_cf(double k, double n, double p)
{
	return binom_pmf(k, n, p, 1 - p) * p * beta_cf(n - k, k + 1, 1 - p);
}

double stats_binom_ge(size_t k, size_t n, double p)
{
	if (n > STATS_BINOM_MAX_N || !(p >= 0 && p <= 1))
		return NAN;
	if (k == 0)
		return 1;
	if (k > n)
		return 0;
	if (p == 0 || p == 1)
		return p;
	double dk = (double)k, dn = (double)n;
	if (p < (dk + 1) / (dn + 3))
		return upper_cf(dk, dn, p);
	return 1 - lower_cf(dk - 1, dn, p);
}

double stats_binom_le(size_t k, size_t n, double p)
{
	if (n > STATS_BINOM_MAX_N || !(p >= 0 && p <= 1))
		return NAN;
	if (k >= n)
		return 1;
	if (p == 0 || p == 1)
		return 1 - p;
	double dk = (double)k, dn = (double)n;
	if (1 - p < (dn - dk + 1) / (dn + 3))
		return lower_cf(dk, dn, p);
	return 1 - upper_cf(dk + 1, dn, p);
}

/* The p in [0, 1] where tail(p) - target changes sign, tail increasing
 * (up) or decreasing in p: bisection over the doubles themselves (their
 * bit patterns are ordered like their values), at most 64 steps to the
 * neighbouring pair, whatever the scale (p_lo is 5e-12 for k = 1 of
 * n = 1e9).  NaN if a tail is NaN. */
static double tail_root(size_t k, size_t n, double target, int up)
{
	double one = 1;
	uint64_t a = 0, b;
	memcpy(&b, &one, sizeof b);
	while (b - a > 1) {
		uint64_t m = a + (b - a) / 2;
		double x;
		memcpy(&x, &m, sizeof x);
		double f = up ? stats_binom_ge(k, n, x) : stats_binom_le(k, n, x);
		if (isnan(f))
			return NAN;
		if ((f < target) == (up != 0))
			a = m;
		else
			b = m;
	}
	double xa, xb;
	memcpy(&xa, &a, sizeof xa);
	memcpy(&xb, &b, sizeof xb);
	/* the end of {p : tail(p) >= target}, the set the interval is */
	return up ? xb : xa;
}

void stats_binomial_ci(size_t k, size_t n, double conf, double *lo,
		       double *hi)
{
	if (n < 1 || k > n || n > STATS_BINOM_MAX_N ||
	    !(conf > 0 && conf < 1)) {
		*lo = *hi = NAN;
		return;
	}
	double a = (1 - conf) / 2;
	*lo = k == 0 ? 0 : tail_root(k, n, a, 1);
	*hi = k == n ? 1 : tail_root(k, n, a, 0);
}

double stats_dkw_eps(size_t n, double conf)
{
	if (n < 1 || !(conf > 0 && conf < 1))
		return NAN;
	return sqrt(log(2 / (1 - conf)) / (2 * (double)n));
}
