/*
 * test_report.c - report_write: every figure in every format is written
 * and valid (PDF and PNG magic, PNG size from its IHDR, SVG closed and
 * carrying its text layer), and the numbers printed on the figures and
 * in report.md are the right ones.  The expected numbers are computed
 * here independently of stats.c: type-7 percentiles, moments, the 99 %
 * order-statistic interval by trying every pair of ranks, and the
 * Kolmogorov-Smirnov p-values by enumerating every labelling of a small
 * pooled sample.  Also: a run without tests, body-load units, and the
 * errors (no loads, a NaN, a directory that cannot be made).
 *
 * XML well-formedness of the SVGs is checked by tests/cli/report.sh
 * (python3's parser) on a real run.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "slipwall/report.h"
#include "slipwall/tally.h"
#include "slipwall/wallfile.h"
#include "tap.h"

static const char *figs[] = {"frequencies", "densities", "cumulative",
			     "single-solutions", "mechanisms", "convergence",
			     "fragility"};
#define NFIGS 7

/* ---- reading files back ---------------------------------------------------- */

static char *slurp(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return NULL;
	fseek(f, 0, SEEK_END);
	long n = ftell(f);
	fseek(f, 0, SEEK_SET);
	char *b = malloc((size_t)n + 1);
	size_t got = fread(b, 1, (size_t)n, f);
	fclose(f);
	b[got] = 0;
	if (len)
		*len = got;
	return b;
}

/* The text of the <text> elements of an SVG, unescaped, one per entry. */
struct texts {
	char **s;
	int n;
};

static void texts_read(const char *path, struct texts *t)
{
	t->s = NULL;
	t->n = 0;
	char *b = slurp(path, NULL);
	if (!b)
		return;
	for (char *p = b; (p = strstr(p, "<text")); ) {
		char *gt = strchr(p, '>'), *end = gt ? strstr(gt, "</text>") : NULL;
		if (!end)
			break;
		size_t n = (size_t)(end - gt - 1);
		char *s = malloc(n + 1), *o = s;
		for (const char *q = gt + 1; q < end; q++) {
			if (!strncmp(q, "&lt;", 4))
				*o++ = '<', q += 3;
			else if (!strncmp(q, "&gt;", 4))
				*o++ = '>', q += 3;
			else if (!strncmp(q, "&amp;", 5))
				*o++ = '&', q += 4;
			else if (!strncmp(q, "&quot;", 6))
				*o++ = '"', q += 5;
			else
				*o++ = *q;
		}
		*o = 0;
		t->s = realloc(t->s, sizeof(char *) * (size_t)(t->n + 1));
		t->s[t->n++] = s;
		p = end;
	}
	free(b);
}

static void texts_free(struct texts *t)
{
	for (int i = 0; i < t->n; i++)
		free(t->s[i]);
	free(t->s);
}

/* The first label that starts with prefix, or NULL. */
static const char *label(const struct texts *t, const char *prefix)
{
	for (int i = 0; i < t->n; i++)
		if (!strncmp(t->s[i], prefix, strlen(prefix)))
			return t->s[i];
	return NULL;
}

static const char *label_has(const struct texts *t, const char *sub)
{
	for (int i = 0; i < t->n; i++)
		if (strstr(t->s[i], sub))
			return t->s[i];
	return NULL;
}

/* A number printed with `sig` significant digits is within half a unit
 * of its last digit of the true value. */
static int close_sig(double got, double want, int sig, const char *what)
{
	double tol = want == 0 ? 1e-12 :
		     0.5 * pow(10, floor(log10(fabs(want))) - sig + 1) *
		     (1 + 1e-9) + 1e-300;
	int ok = fabs(got - want) <= tol;
	tap_ok(ok, "%s: printed %.10g, computed %.10g", what, got, want);
	return ok;
}

static void check_files(const char *dir, const char *tag, int mech)
{
	char p[512];
	for (int i = 0; i < NFIGS; i++) {
		int want = mech || strcmp(figs[i], "mechanisms");
		size_t len;
		snprintf(p, sizeof p, "%s/%s.pdf", dir, figs[i]);
		char *b = slurp(p, &len);
		if (!want) {
			tap_ok(!b, "%s: no %s without mechanisms", tag, figs[i]);
			free(b);
			continue;
		}
		tap_ok(b && len > 1000 && !memcmp(b, "%PDF-", 5) &&
		       strstr(b + len - 1024 > b ? b + len - 1024 : b, "%%EOF"),
		       "%s: %s.pdf starts with %%PDF- and ends with %%%%EOF (%zu "
		       "bytes)", tag, figs[i], b ? len : 0);
		free(b);
		snprintf(p, sizeof p, "%s/%s.png", dir, figs[i]);
		b = slurp(p, &len);
		static const unsigned char magic[8] = {0x89, 'P', 'N', 'G', '\r',
						       '\n', 0x1a, '\n'};
		unsigned wpx = 0, hpx = 0;
		if (b && len > 24) {
			const unsigned char *u = (const unsigned char *)b;
			wpx = (unsigned)u[16] << 24 | (unsigned)u[17] << 16 |
			      (unsigned)u[18] << 8 | u[19];
			hpx = (unsigned)u[20] << 24 | (unsigned)u[21] << 16 |
			      (unsigned)u[22] << 8 | u[23];
		}
		tap_ok(b && len > 24 && !memcmp(b, magic, 8) &&
		       !memcmp(b + 12, "IHDR", 4) && wpx == 1200 && hpx >= 600 &&
		       hpx <= 6000, "%s: %s.png magic, IHDR %ux%u (480 pt at "
		       "2.5 px/pt)", tag, figs[i], wpx, hpx);
		free(b);
		snprintf(p, sizeof p, "%s/%s.svg", dir, figs[i]);
		b = slurp(p, &len);
		tap_ok(b && !strncmp(b, "<?xml", 5) && strstr(b, "<svg") &&
		       strstr(b, "id=\"slipwall-text\"") &&
		       !strcmp(b + len - 7, "</svg>\n"),
		       "%s: %s.svg is an SVG with its text layer", tag, figs[i]);
		free(b);
	}
}

/* ---- independent statistics ------------------------------------------------- */

static int cmpd(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return (x > y) - (x < y);
}

static double q7(const double *s, size_t n, double p)
{
	double h = (double)(n - 1) * p;
	size_t i = (size_t)floor(h);
	return i + 1 < n ? s[i] + (h - (double)i) * (s[i + 1] - s[i]) : s[i];
}

static double mean_of(const double *x, size_t n)
{
	double m = 0;
	for (size_t i = 0; i < n; i++)
		m += x[i];
	return m / (double)n;
}

static double sd_of(const double *x, size_t n)
{
	double m = mean_of(x, n), s = 0;
	for (size_t i = 0; i < n; i++)
		s += (x[i] - m) * (x[i] - m);
	return sqrt(s / (double)(n - 1));
}

static double binom_pmf(size_t n, size_t k, double p)
{
	return exp(lgamma((double)n + 1) - lgamma((double)k + 1) -
		   lgamma((double)(n - k) + 1) + (double)k * log(p) +
		   (double)(n - k) * log1p(-p));
}

/* docs/statistics.md: every pair lo < hi with P(lo <= B < hi) >= 0.99;
 * least hi - lo, then least |lo + hi - 1 - 2np|, then most coverage. */
static int ci_ranks(size_t n, size_t *blo, size_t *bhi)
{
	double p = 0.05, best_c = 0, best_off = 0;
	long best_w = -1;
	for (size_t lo = 1; lo < n; lo++)
		for (size_t hi = lo + 1; hi <= n; hi++) {
			double c = 0;
			for (size_t k = lo; k < hi; k++)
				c += binom_pmf(n, k, p);
			if (c < 0.99)
				continue;
			long w = (long)(hi - lo);
			double off = fabs((double)(lo + hi - 1) - 2 * (double)n * p);
			if (best_w < 0 || w < best_w ||
			    (w == best_w && (off < best_off - 1e-12 ||
			     (fabs(off - best_off) <= 1e-12 && c > best_c)))) {
				best_w = w;
				best_off = off;
				best_c = c;
				*blo = lo;
				*bhi = hi;
			}
			break;	/* larger hi only widens */
		}
	return best_w >= 0;
}

/* D+, D- of x (model) against y (tests), ECDFs at every pooled value. */
static void ks_stats(const double *x, size_t n, const double *y, size_t m,
		     double *dp, double *dm)
{
	*dp = *dm = 0;
	for (size_t k = 0; k < n + m; k++) {
		double v = k < n ? x[k] : y[k - n];
		size_t cx = 0, cy = 0;
		for (size_t i = 0; i < n; i++)
			cx += x[i] <= v;
		for (size_t j = 0; j < m; j++)
			cy += y[j] <= v;
		double d = (double)cx / (double)n - (double)cy / (double)m;
		*dp = fmax(*dp, d);
		*dm = fmax(*dm, -d);
	}
}

/* Exact p-values: the share of the C(n+m, m) labellings of the pooled
 * values whose statistic reaches the observed one. */
static void ks_enumerate(const double *x, size_t n, const double *y, size_t m,
			 double *p2, double *pg, double *pl)
{
	size_t N = n + m;
	double *z = malloc(sizeof(double) * N), xx[32], yy[32];
	memcpy(z, x, sizeof(double) * n);
	memcpy(z + n, y, sizeof(double) * m);
	double dp0, dm0;
	ks_stats(x, n, y, m, &dp0, &dm0);
	double d0 = fmax(dp0, dm0), eps = 1e-9;
	long tot = 0, c2 = 0, cg = 0, cl = 0;
	for (unsigned long mask = 0; mask < (1ul << N); mask++) {
		if ((size_t)__builtin_popcountl(mask) != m)
			continue;
		size_t a = 0, b = 0;
		for (size_t k = 0; k < N; k++)
			if (mask >> k & 1)
				yy[b++] = z[k];
			else
				xx[a++] = z[k];
		double dp, dm;
		ks_stats(xx, n, yy, m, &dp, &dm);
		tot++;
		c2 += fmax(dp, dm) >= d0 - eps;
		cg += dp >= dp0 - eps;
		cl += dm >= dm0 - eps;
	}
	*p2 = (double)c2 / (double)tot;
	*pg = (double)cg / (double)tot;
	*pl = (double)cl / (double)tot;
	free(z);
}

/* ---- the fixtures --------------------------------------------------------------- */

static struct wall *load_demo(void)
{
	struct wall *w;
	char err[SW_ERRLEN];
	if (wallfile_load(SRCDIR "/walls/demo.yaml", &w, err) != SW_OK) {
		tap_ok(0, "load demo wall: %s", err);
		exit(tap_done());
	}
	return w;
}

/* A tally of n accepted samples spread over three made-up mechanisms in
 * the proportions 1/2, 3/10, 1/5 (samples in that order), plus two
 * rejections.  Mechanism k moves one free block, every joint around it
 * in state "sho"[k], so the three are three families (Fig. 6 draws
 * families: docs/statistics.md). */
static void fake_tally(struct tally *t, const struct wall *w, const double *lam,
		       long n)
{
	struct record it;
	record_init(&it, w);
	tally_init(t, w);
	int freeb[3], nf = 0;
	for (int b = 0; b < w->nblocks && nf < 3; b++)
		if (!w->blocks[b].fixed)
			freeb[nf++] = b;
	for (long i = 0; i < n + 2; i++) {
		int k = i < n / 2 ? 0 : i < n / 2 + 3 * n / 10 ? 1 : 2;
		memset(it.joint, JOINT_CLOSED, (size_t)w->nifaces);
		it.joint[w->nifaces] = 0;
		memset(it.vel, 0, sizeof(double) * 3 * (size_t)w->nblocks);
		for (int f = 0; f < w->nifaces; f++)
			if (w->ifaces[f].a == freeb[k] ||
			    w->ifaces[f].b == freeb[k])
				it.joint[f] = "sho"[k];
		it.vel[3 * freeb[k]] = 1;
		it.vel[3 * freeb[k] + 2] = 0.3 * k;
		it.index = i;
		it.status = i < n ? SAMPLE_ACCEPTED : SAMPLE_NO_MECHANISM;
		it.lambda_min = i < n ? lam[i] : NAN;
		tally_add(t, &it);
	}
	record_free(&it);
}

static void rm_dir(const char *dir)
{
	char p[512];
	for (int i = 0; i < NFIGS; i++) {
		static const char *ext[3] = {"svg", "pdf", "png"};
		for (int e = 0; e < 3; e++) {
			snprintf(p, sizeof p, "%s/%s.%s", dir, figs[i], ext[e]);
			unlink(p);
		}
	}
	snprintf(p, sizeof p, "%s/report.md", dir);
	unlink(p);
	rmdir(dir);
}

static void base_input(struct report_input *in, const struct wall *w)
{
	memset(in, 0, sizeof *in);
	in->w = w;
	in->run.wall_path = "walls/demo.yaml";
	in->run.version = "9.9.9-test";
	in->run.command = "slipwall report walls/demo.yaml -n 202 --out X";
	in->run.seed_known = 1;
	in->run.seed = 42;
	in->run.requested = 202;
	in->run.threads = 3;
	in->run.depth = 0.25;
}

/* ---- the tests ------------------------------------------------------------------ */

#define NA 200
#define MA 10

static void test_full(const char *root)
{
	struct wall *w = load_demo();
	double lam[NA], tests[MA], s[NA], ts[MA];
	for (int i = 0; i < NA; i++)	/* ties on a 0.5 N grid */
		lam[i] = round(2 * (200 + 60 * sin(i * 1.7) + (i % 7) * 3)) / 2;
	for (int j = 0; j < MA; j++)
		tests[j] = 230 + 9 * j - (j % 3) * 4;
	struct tally t;
	fake_tally(&t, w, lam, NA);
	struct report_solution sol[3] = {
		{"standard", 1, 1, 301.25, "associative"},
		{"gilbert", 1, 1, 180.5, "converged"},
		{"global", 0, 0, NAN, "not run: too many blocks"},
	};
	struct report_input in;
	base_input(&in, w);
	in.lam = lam;
	in.nlam = NA;
	in.mech = &t;
	in.tests = tests;
	in.ntests = MA;
	in.sol = sol;
	in.nsol = 3;
	in.run.tests_source = "a list in the test";
	in.run.has_counts = 1;
	in.run.samples = t.samples;
	in.run.accepted = t.accepted;
	memcpy(in.run.rejected, t.rejected, sizeof t.rejected);

	char dir[512], err[SW_ERRLEN], p[600];
	snprintf(dir, sizeof dir, "%s/full/sub", root);	/* two levels made */
	enum sw_status st = report_write(&in, dir, NULL, err);
	tap_ok(st == SW_OK, "report_write with tests and mechanisms: %s",
	       st == SW_OK ? "ok" : err);
	check_files(dir, "full", 1);

	memcpy(s, lam, sizeof s);
	memcpy(ts, tests, sizeof ts);
	qsort(s, NA, sizeof(double), cmpd);
	qsort(ts, MA, sizeof(double), cmpd);
	double p05 = q7(s, NA, 0.05);
	size_t lo = 1, hi = 1;
	int has = ci_ranks(NA, &lo, &hi);
	tap_ok(has, "n = %d has a 99 %% interval (ranks %zu, %zu)", NA, lo, hi);

	/* Fig. 10: the characteristic value, its interval, the lines */
	struct texts tx;
	snprintf(p, sizeof p, "%s/single-solutions.svg", dir);
	texts_read(p, &tx);
	const char *l = label(&tx, "Model p05 = ");
	double a = NAN, b = NAN, c = NAN;
	tap_ok(l && sscanf(l, "Model p05 = %lf N, 99 %% interval [%lf, %lf] N",
			   &a, &b, &c) == 3, "Fig. 10 caption: '%s'", l ? l : "");
	close_sig(a, p05, 5, "Fig. 10 p05");
	close_sig(b, s[lo - 1], 5, "Fig. 10 interval, low end");
	close_sig(c, s[hi - 1], 5, "Fig. 10 interval, high end");
	l = label(&tx, "standard ");
	tap_ok(l && sscanf(l, "standard %lf N", &a) == 1 && a == 301.25,
	       "Fig. 10 line label '%s'", l ? l : "");
	l = label(&tx, "gilbert ");
	tap_ok(l && sscanf(l, "gilbert %lf N", &a) == 1 && a == 180.5,
	       "Fig. 10 line label '%s'", l ? l : "");
	tap_ok(!label(&tx, "global ") && label_has(&tx, "global: not run"),
	       "Fig. 10: global not drawn, and says why");
	l = label(&tx, "Tests p05 = ");
	tap_ok(l && sscanf(l, "Tests p05 = %lf", &a) == 1, "Fig. 10 tests "
	       "caption '%s'", l ? l : "");
	close_sig(a, q7(ts, MA, 0.05), 5, "Fig. 10 tests p05");
	tap_ok(l && strstr(l, "no distribution-free"), "10 tests: no interval");
	texts_free(&tx);

	/* Fig. 9: the KS statistic */
	snprintf(p, sizeof p, "%s/cumulative.svg", dir);
	texts_read(p, &tx);
	double dp, dm;
	ks_stats(lam, NA, tests, MA, &dp, &dm);
	l = label(&tx, "D = ");
	double d = NAN;
	tap_ok(l && sscanf(l, "D = %lf (D+ = %lf, D- = %lf)", &d, &a, &b) == 3,
	       "Fig. 9 caption '%s'", l ? l : "");
	close_sig(d, fmax(dp, dm), 4, "Fig. 9 D");
	close_sig(a, dp, 4, "Fig. 9 D+");
	close_sig(b, dm, 4, "Fig. 9 D-");
	tap_ok(label(&tx, "tests (10)") && label(&tx, "model (200)"),
	       "Fig. 9 legend counts");
	texts_free(&tx);

	/* Fig. 8: moments and the tests' normal */
	snprintf(p, sizeof p, "%s/frequencies.svg", dir);
	texts_read(p, &tx);
	l = label(&tx, "Model: mean ");
	tap_ok(l && sscanf(l, "Model: mean %lf N, std %lf N", &a, &b) == 2,
	       "Fig. 8 caption '%s'", l ? l : "");
	close_sig(a, mean_of(lam, NA), 5, "Fig. 8 model mean");
	close_sig(b, sd_of(lam, NA), 4, "Fig. 8 model std");
	texts_free(&tx);
	snprintf(p, sizeof p, "%s/densities.svg", dir);
	texts_read(p, &tx);
	l = label(&tx, "tests, normal (");
	tap_ok(l && sscanf(l, "tests, normal (%lf, %lf)", &a, &b) == 2,
	       "Fig. 8 centre legend '%s'", l ? l : "");
	close_sig(a, mean_of(tests, MA), 4, "Fig. 8 tests mean");
	close_sig(b, sd_of(tests, MA), 3, "Fig. 8 tests std");
	tap_ok(label(&tx, "Best-fit normals in 10 classes") != NULL,
	       "Fig. 8 right: grouped in the tests' number of classes");
	texts_free(&tx);

	/* convergence */
	snprintf(p, sizeof p, "%s/convergence.svg", dir);
	texts_read(p, &tx);
	l = label(&tx, "Final p05 = ");
	tap_ok(l && sscanf(l, "Final p05 = %lf N, 99 %% interval [%lf, %lf]",
			   &a, &b, &c) == 3, "convergence caption '%s'",
	       l ? l : "");
	close_sig(a, p05, 5, "convergence: final p05");
	close_sig(b, s[lo - 1], 5, "convergence: low end");
	texts_free(&tx);

	/* Fig. 6: the frequencies of the mechanisms */
	snprintf(p, sizeof p, "%s/mechanisms.svg", dir);
	texts_read(p, &tx);
	tap_ok(label(&tx, "#1: 50.0 % (100 of 200)") &&
	       label(&tx, "#2: 30.0 % (60 of 200)") &&
	       label(&tx, "#3: 20.0 % (40 of 200)") && !label(&tx, "#4"),
	       "Fig. 6: three panels with their frequencies");
	tap_ok(label_has(&tx, "3 distinct in 200 accepted") != NULL,
	       "Fig. 6 title counts");
	texts_free(&tx);

	/* report.md: Table 1, the settings, the links */
	snprintf(p, sizeof p, "%s/report.md", dir);
	char *md = slurp(p, NULL);
	tap_ok(md != NULL, "report.md written");
	const char *row = md ? strstr(md, "| Numerical model | 200 | ") : NULL;
	tap_ok(row && sscanf(row, "| Numerical model | 200 | %lf N | [%lf, %lf]",
			     &a, &b, &c) == 3, "Table 1 model row");
	close_sig(a, p05, 5, "Table 1 p05");
	close_sig(b, s[lo - 1], 5, "Table 1 interval low");
	close_sig(c, s[hi - 1], 5, "Table 1 interval high");
	row = md ? strstr(md, "| Experimental tests | 10 | ") : NULL;
	tap_ok(row && sscanf(row, "| Experimental tests | 10 | %lf N", &a) == 1 &&
	       strstr(row, "none (n = 10 < 90)"), "Table 1 tests row");
	close_sig(a, q7(ts, MA, 0.05), 5, "Table 1 tests p05");
	tap_ok(md && strstr(md, "9.9.9-test") && strstr(md, "| seed | 42 |") &&
	       strstr(md, "| threads | 3") && strstr(md, "| contact depth d | 0.25 |") &&
	       strstr(md, "| samples computed | 202 |") &&
	       strstr(md, "| rejected: no mechanism at the SLP load | 2 |") &&
	       strstr(md, "slipwall report walls/demo.yaml -n 202 --out X"),
	       "report.md: version, seed, threads, depth, counts, command");
	int links = 1;
	for (int i = 0; i < NFIGS && md; i++) {
		char lk[3][96];
		snprintf(lk[0], sizeof lk[0], "](%s.png)", figs[i]);
		snprintf(lk[1], sizeof lk[1], "](%s.svg)", figs[i]);
		snprintf(lk[2], sizeof lk[2], "](%s.pdf)", figs[i]);
		for (int e = 0; e < 3; e++)
			links &= strstr(md, lk[e]) != NULL;
	}
	tap_ok(md && links, "report.md links every figure in every format");
	free(md);
	rm_dir(dir);
	snprintf(p, sizeof p, "%s/full", root);
	rmdir(p);
	tally_free(&t);
	wall_free(w);
}

/* Small samples: the KS p-values against a full enumeration, and no
 * interval below 90 values. */
static void test_ks_exact(const char *root)
{
	struct wall *w = load_demo();
	double lam[12] = {101, 97, 120, 88, 110, 97, 131, 105, 94, 140, 115, 99};
	double tests[5] = {118, 97, 150, 85, 133};	/* 97 tied with the model */
	struct report_input in;
	base_input(&in, w);
	in.lam = lam;
	in.nlam = 12;
	in.tests = tests;
	in.ntests = 5;
	char dir[512], err[SW_ERRLEN], p[600];
	snprintf(dir, sizeof dir, "%s/ks", root);
	enum sw_status st = report_write(&in, dir, NULL, err);
	tap_ok(st == SW_OK, "report_write, 12 against 5, no tally: %s",
	       st == SW_OK ? "ok" : err);
	check_files(dir, "ks", 0);
	double p2, pg, pl, a = NAN, b = NAN, c = NAN;
	ks_enumerate(lam, 12, tests, 5, &p2, &pg, &pl);
	tap_ok(p2 < 1 && pg < 1 && pl < 1, "the data make all three p < 1: "
	       "two-sided %.6g, greater %.6g, less %.6g", p2, pg, pl);
	struct texts tx;
	snprintf(p, sizeof p, "%s/cumulative.svg", dir);
	texts_read(p, &tx);
	const char *l = label(&tx, "D = ");
	const char *q = l ? strstr(l, "p two-sided = ") : NULL;
	tap_ok(q && sscanf(q, "p two-sided = %lf", &a) == 1, "Fig. 9 two-sided");
	close_sig(a, p2, 4, "KS p two-sided (enumerated)");
	l = label(&tx, "p greater = ");
	tap_ok(l && sscanf(l, "p greater = %lf", &b) == 1, "Fig. 9 greater");
	close_sig(b, pg, 4, "KS p greater (enumerated)");
	l = label(&tx, "p less = ");
	tap_ok(l && sscanf(l, "p less = %lf", &c) == 1, "Fig. 9 less");
	close_sig(c, pl, 4, "KS p less (enumerated)");
	texts_free(&tx);
	snprintf(p, sizeof p, "%s/single-solutions.svg", dir);
	texts_read(p, &tx);
	l = label(&tx, "Model p05 = ");
	tap_ok(l && strstr(l, "no 99 % interval"), "12 samples: no interval "
	       "('%s')", l ? l : "");
	texts_free(&tx);
	snprintf(p, sizeof p, "%s/report.md", dir);
	char *md = slurp(p, NULL);
	tap_ok(md && strstr(md, "Not drawn: no mechanisms"),
	       "report.md says why Fig. 6 is missing");
	free(md);
	rm_dir(dir);
	wall_free(w);
}

static void test_no_tests(const char *root)
{
	struct wall *w = load_demo();
	double lam[100];
	for (int i = 0; i < 100; i++)
		lam[i] = 50 + (i * 37 % 100) * 0.5;
	struct report_input in;
	base_input(&in, w);
	in.lam = lam;
	in.nlam = 100;
	char dir[512], err[SW_ERRLEN], p[600];
	snprintf(dir, sizeof dir, "%s/model", root);
	struct report_opts o;
	report_opts_default(&o);
	o.formats = REPORT_SVG;
	enum sw_status st = report_write(&in, dir, &o, err);
	tap_ok(st == SW_OK, "report_write without tests, SVG only: %s",
	       st == SW_OK ? "ok" : err);
	snprintf(p, sizeof p, "%s/frequencies.pdf", dir);
	tap_ok(access(p, F_OK) != 0, "no PDF when only SVG is asked for");
	snprintf(p, sizeof p, "%s/cumulative.svg", dir);
	struct texts tx;
	texts_read(p, &tx);
	tap_ok(label(&tx, "No Kolmogorov-Smirnov test") && !label(&tx, "tests ("),
	       "Fig. 9 without tests: model only, says so");
	texts_free(&tx);
	snprintf(p, sizeof p, "%s/report.md", dir);
	char *md = slurp(p, NULL);
	tap_ok(md && strstr(md, "**No experimental loads**") &&
	       !strstr(md, "| Experimental tests |") && !strstr(md, ".png)"),
	       "report.md: no tests row, says so, no PNG links");
	free(md);
	rm_dir(dir);
	wall_free(w);
}

static void test_units_and_errors(const char *root)
{
	struct wall *w;
	char err[SW_ERRLEN], axis[96];
	const char *unit;
	if (wallfile_load(SRCDIR "/walls/ferris-tinloi-1.yaml", &w, err) == SW_OK) {
		report_load_unit(w, axis, sizeof axis, &unit);
		tap_ok(strstr(axis, "seismic coefficient") && !strstr(axis, "(N)") &&
		       !*unit, "body load: a seismic coefficient, no unit ('%s')",
		       axis);
		wall_free(w);
	} else {
		tap_ok(0, "load ferris-tinloi-1: %s", err);
	}
	w = load_demo();
	report_load_unit(w, axis, sizeof axis, &unit);
	tap_ok(!strcmp(axis, "collapse load (N)") && !strcmp(unit, " N"),
	       "point load of 1 N: newtons ('%s')", axis);

	struct report_input in;
	base_input(&in, w);
	char dir[512];
	snprintf(dir, sizeof dir, "%s/err", root);
	tap_ok(report_write(&in, dir, NULL, err) == SW_EINPUT &&
	       strstr(err, "no accepted"), "no loads: SW_EINPUT (%s)", err);
	double bad[3] = {1, NAN, 2};
	in.lam = bad;
	in.nlam = 3;
	tap_ok(report_write(&in, dir, NULL, err) == SW_EINPUT &&
	       strstr(err, "load 2"), "a NaN load: SW_EINPUT (%s)", err);
	rmdir(dir);
	double good[3] = {1, 2, 3};
	in.lam = good;
	char file[512];
	snprintf(file, sizeof file, "%s/plain-file", root);
	FILE *f = fopen(file, "w");
	fclose(f);
	snprintf(dir, sizeof dir, "%s/plain-file/sub", root);
	tap_ok(report_write(&in, dir, NULL, err) == SW_EIO &&
	       strstr(err, "plain-file"), "a file in the way: SW_EIO (%s)", err);
	unlink(file);
	wall_free(w);
}

int main(void)
{
	char root[] = "/tmp/slipwall-test-report-XXXXXX";
	if (!mkdtemp(root)) {
		perror("mkdtemp");
		return 1;
	}
	test_full(root);
	test_ks_exact(root);
	test_no_tests(root);
	test_units_and_errors(root);
	tap_ok(rmdir(root) == 0, "every file written was accounted for");
	report_cleanup();
	return tap_done();
}
