/*
 * cmd_compare.c - `slipwall compare`: the model's collapse loads against
 * experimental ones (docs/run.md; the statistics in docs/statistics.md).
 *
 * The experimental loads come from the wall's `tests:` key or from a
 * file of one load per line; the model's from a samples file of `run` or
 * from a fresh Monte Carlo run (no file written).  The comparison is the
 * two-sample Kolmogorov-Smirnov test (stats_ks2, x = model, y = tests,
 * exact p-values) and the paper's Table 1: the characteristic value
 * (p05) of each with its distribution-free 99 % interval.
 *
 * --fit-depth calibrates the one free parameter of the contact model,
 * the imperfection depth d: a run per d on a grid over [0, 0.5], then a
 * finer grid around the best, all with the same seed.  draw_make
 * draws the same uniforms for every d and scales them by d (common
 * random numbers), so the profile of the KS distance against d is
 * smooth rather than noisy.  The best d has the least KS distance (ties:
 * the larger two-sided p-value, then the smaller d).
 *
 * --against B.csv compares two runs instead, the --samples file (A) and
 * B: compare_runs.c.
 *
 * The model's runs are the library's (run_all, run.h).  SIGINT, SIGTERM
 * and SIGHUP stop them: the samples done (with --fit-depth, the depths
 * done) are compared and printed, and the exit status is 1.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "cli_opts.h"
#include "compare_runs.h"
#include "slipwall/collapse.h"
#include "override.h"
#include "slipwall/json.h"
#include "slipwall/run.h"
#include "slipwall/runlog.h"
#include "slipwall/stats.h"
#include "slipwall/tally.h"
#include "slipwall/text.h"

#define CMD "compare"
#define GRID_STEP 0.05		/* first pass: 0, 0.05, ..., 0.5 */
#define FINE_STEP 0.01		/* second pass: +-0.04 around the best */
#define FINE_HALF 4

struct compare_args {
	const char *wall, *tests, *samples, *against;
	long n;
	int n_set;
	unsigned long seed;
	int seed_set;
	int threads;
	double depth;		/* < 0: the wall's */
	int fit_depth;
	int json;
	struct overrides ov;	/* --friction, --set, ... */
};

/* One model run (a depth of the profile, or the only one). */
struct model {
	double depth;
	long samples, accepted;
	double *lam;		/* accepted loads (wall_quantity), n = accepted */
	struct stats_summary s;
	struct stats_ks ks;
	int ks_ok;
};

static void usage(FILE *f)
{
	fprintf(f,
		"usage: slipwall compare WALL.yaml [--tests FILE] [--samples FILE.csv]\n"
		"                        [-n N] [--seed S] [--threads T] [--depth D]\n"
		"                        [--fit-depth] [--json] [--friction MU|BED,HEAD]\n"
		"                        [--load-at X,Y] [--load-direction DX,DY]\n"
		"                        [--set KEY=VALUE]...\n"
		"       slipwall compare WALL.yaml --samples A.csv --against B.csv [--json]\n"
		"\n"
		"The model's collapse loads against experimental ones: two-sample\n"
		"Kolmogorov-Smirnov test (exact p-values) and the characteristic\n"
		"values (p05) with their 99 %% intervals, side by side.  With\n"
		"--against, two runs of the wall side by side instead.\n"
		"\n"
		"  --tests FILE        experimental loads, one per line, '#' comments\n"
		"                      (default: the wall's tests: key)\n"
		"  --samples FILE.csv  the model's loads from a samples file of 'run'\n"
		"                      (default: run the Monte Carlo analysis now)\n"
		"  -n N, --seed S, --threads T, --depth D   as for 'run'\n"
		"  --friction, --load-at, --load-direction, --set KEY=VALUE\n"
		"                      change the wall as for 'run'\n"
		"  --fit-depth         find the depth d in [0, 0.5] whose loads match\n"
		"                      the tests best (least KS distance)\n"
		"  --against B.csv     compare the --samples run (A) with the run of\n"
		"                      this samples file (B): p05, p50, p95, B - A,\n"
		"                      and the KS test (one-sided: B < A)\n"
		"  --json              print the result as JSON\n");
}

static int parse_args(int argc, char **argv, struct compare_args *a)
{
	memset(a, 0, sizeof *a);
	a->depth = -1;
	const struct cli_opt opts[] = {
		CLI_OPT_SWITCH("--json", a->json),
		CLI_OPT_SWITCH("--fit-depth", a->fit_depth),
		CLI_OPT_SAMPLING(a),
		CLI_OPT_DEPTH(a),
		OVERRIDE_OPTIONS(&a->ov),
		CLI_OPT_FILE("--tests", a->tests),
		CLI_OPT_FILE("--samples", a->samples),
		CLI_OPT_FILE("--against", a->against),
	};
	static const struct cli_cmd cmd = {
		.name = CMD, .usage = usage,
		.no_wall = "which wall? (slipwall compare WALL.yaml)",
	};
	int rc = cli_opts_parse(&cmd, opts, sizeof opts / sizeof *opts, argc,
				argv, &a->wall);
	if (rc)
		return rc;
	if (a->against && !a->samples)
		return cli_usage_error(CMD, "--against B.csv compares two "
				       "runs: give the first with --samples "
				       "A.csv");
	if (a->against && a->tests)
		return cli_usage_error(CMD, "--against compares two runs, "
				       "--tests a run with experimental "
				       "loads: give one of them");
	if (a->samples && (a->fit_depth || a->n_set || a->seed_set ||
			   a->threads || a->depth >= 0))
		return cli_usage_error(CMD, "--samples takes the model's loads "
				       "from a file: --fit-depth, -n, --seed, "
				       "--threads and --depth do not apply");
	if (a->fit_depth && a->depth >= 0)
		return cli_usage_error(CMD, "--fit-depth searches the depth: "
				       "--depth does not apply");
	return 0;
}

/* ---- the model's loads -------------------------------------------------- */

/* Run the pool to the end and keep the accepted loads (run_all, no
 * file).  SW_EINTR when a signal stopped it: md has the samples done. */
static enum sw_status run_model(const struct mc_config *cfg, struct model *md,
				char *err)
{
	struct tally t;
	tally_init(&t, cfg->w);
	enum sw_status st = run_all(cfg, &t, &md->lam, &md->accepted, NULL,
				    NULL, err);
	md->samples = t.samples;
	tally_free(&t);
	return st;
}

/* Statistics of a model run and its KS test against the tests. */
static void analyse(struct model *md, const double *tests, long ntests)
{
	stats_summarise(md->lam, (size_t)md->accepted, &md->s);
	md->ks_ok = md->accepted > 0 &&
		    stats_ks2(md->lam, (size_t)md->accepted, tests,
			      (size_t)ntests, &md->ks) == 0;
}

static int better(const struct model *a, const struct model *b)
{
	if (!a->ks_ok)
		return 0;
	if (!b->ks_ok)
		return 1;
	if (a->ks.d != b->ks.d)
		return a->ks.d < b->ks.d;
	if (a->ks.p_two_sided != b->ks.p_two_sided)
		return a->ks.p_two_sided > b->ks.p_two_sided;
	return a->depth < b->depth;
}

static int cmp_depth(const void *x, const void *y)
{
	const struct model *a = x, *b = y;
	return (a->depth > b->depth) - (a->depth < b->depth);
}

/* The depth profile: returns the profile (sorted by depth) in *prof,
 * its length, and the index of the best run. */
static enum sw_status fit_depth(struct mc_config *cfg, const double *tests,
				long ntests, struct model **prof, int *nprof,
				int *best, int verbose, char *err)
{
	int cap = 32, n = 0;
	struct model *p = sw_xcalloc((size_t)cap, sizeof *p);
	int coarse = (int)lround(0.5 / GRID_STEP);
	int b = -1;
	for (int pass = 0; pass < 2; pass++) {
		double lo = 0, step = GRID_STEP;
		int count = coarse + 1;
		if (pass == 1) {
			if (b < 0)
				break;
			lo = p[b].depth - FINE_HALF * FINE_STEP;
			step = FINE_STEP;
			count = 2 * FINE_HALF + 1;
		}
		for (int k = 0; k < count; k++) {
			/* on the 0.01 lattice exactly, so points are shared */
			double d = round((lo + k * step) * 100) / 100;
			if (d < 0 || d > 0.5)
				continue;
			int seen = 0;
			for (int i = 0; i < n; i++)
				seen |= fabs(p[i].depth - d) < 1e-9;
			if (seen)
				continue;
			if (n == cap) {
				cap *= 2;
				p = sw_xrealloc(p, sizeof *p * (size_t)cap);
			}
			struct model *md = &p[n];
			memset(md, 0, sizeof *md);
			md->depth = d;
			cfg->depth = d;
			enum sw_status st = run_model(cfg, md, err);
			if (st == SW_EINTR) {
				/* a signal: the depths done are the profile */
				free(md->lam);
				goto done;
			}
			if (st != SW_OK) {
				for (int i = 0; i <= n; i++)
					free(p[i].lam);
				free(p);
				return st;
			}
			analyse(md, tests, ntests);
			if (verbose) {
				fprintf(stderr, "\rfit-depth: d = %.2f done (%d)\033[K",
					d, n + 1);
				fflush(stderr);
			}
			n++;
			if (b < 0 || better(md, &p[b]))
				b = n - 1;
		}
	}
done:
	if (verbose)
		fprintf(stderr, "\r\033[K");
	double bd = b >= 0 ? p[b].depth : NAN;
	qsort(p, (size_t)n, sizeof *p, cmp_depth);
	*best = -1;
	for (int i = 0; i < n; i++)
		if (p[i].depth == bd)
			*best = i;
	*prof = p;
	*nprof = n;
	return SW_OK;
}

/* ---- output ------------------------------------------------------------- */

/* One row of the table: the model's value and the tests', "-" where a
 * side has none (no accepted sample; a standard deviation of one value). */
static void print_row(const char *name, double model, double tests)
{
	char a[32], b[32];
	printf("%-24s %-26s %s\n", name, text_num(a, sizeof a, model, 6),
	       text_num(b, sizeof b, tests, 6));
}

static void print_table(const struct model *md, const struct stats_summary *ts,
			long ntests)
{
	const struct stats_summary *ms = &md->s;
	char a[64], b[64];
	printf("%-24s %-26s %s\n", "", "model", "tests");
	snprintf(a, sizeof a, "%ld", md->accepted);
	printf("%-24s %-26s %ld\n", "values", a, ntests);
	print_row("min", ms->min, ts->min);
	print_row("p05 (characteristic)", ms->p05, ts->p05);
	compare_fmt_ci(a, sizeof a, ms);
	compare_fmt_ci(b, sizeof b, ts);
	printf("%-24s %-26s %s\n", "  99 % interval", a, b);
	print_row("p50", ms->p50, ts->p50);
	print_row("p95", ms->p95, ts->p95);
	print_row("max", ms->max, ts->max);
	print_row("mean", ms->mean, ts->mean);
	print_row("std", ms->std, ts->std);
	if (!ms->has_ci || !ts->has_ci)
		printf("(no interval: needs at least 90 values)\n");
}

static void print_ks(const struct model *md)
{
	if (!md->ks_ok) {
		printf("\nno Kolmogorov-Smirnov test: the model has no accepted "
		       "sample\n");
		return;
	}
	const struct stats_ks *k = &md->ks;
	printf("\nKolmogorov-Smirnov, two samples (x = model, y = tests), %s "
	       "p-values:\n", k->exact ? "exact" : "asymptotic");
	printf("  D  = %.6g   (D+ = %.6g, D- = %.6g)\n", k->d, k->d_plus,
	       k->d_minus);
	printf("  p two-sided  %-12.6g H1: the distributions differ\n",
	       k->p_two_sided);
	printf("  p greater    %-12.6g H1: model CDF above the tests' "
	       "(model < tests)\n", k->p_greater);
	printf("  p less       %-12.6g H1: model CDF below the tests' "
	       "(model > tests)\n", k->p_less);
}

static void json_ks(struct json *j, const struct model *md)
{
	if (!md->ks_ok) {
		json_null(j);
		return;
	}
	json_object_begin(j);
	json_key(j, "statistic");
	json_double(j, md->ks.d);
	json_key(j, "d_plus");
	json_double(j, md->ks.d_plus);
	json_key(j, "d_minus");
	json_double(j, md->ks.d_minus);
	json_key(j, "p_two_sided");
	json_double(j, md->ks.p_two_sided);
	json_key(j, "p_less");
	json_double(j, md->ks.p_less);
	json_key(j, "p_greater");
	json_double(j, md->ks.p_greater);
	json_key(j, "exact");
	json_bool(j, md->ks.exact);
	json_object_end(j);
}

/* ---- the command -------------------------------------------------------- */

/* What cmd_compare computes and frees. */
struct compare_data {
	double *tests;
	long ntests;
	struct mc_config cfg;
	struct model *prof, one, *md;	/* md: the run compared */
	int nprof, best;
	struct stats_summary ts;	/* of the tests */
};

/* The tests, and the options that need the wall.  Returns 0 or the
 * exit status (message printed). */
static int setup(const struct compare_args *a, const struct wall *w,
		 struct compare_data *d)
{
	if (cli_tests(a->tests, w, &d->tests, &d->ntests))
		return 2;
	if (d->ntests == 0)
		/* w->tests is NULL when the file has no tests: key, an
		 * empty array when its list of loads is empty */
		return cli_usage_error(CMD, "no experimental loads: %s%s%s",
				       a->tests ? a->tests : a->wall,
				       a->tests ? " holds no load" :
				       w->tests ? ": its tests: loads list "
				       "is empty" : " has no tests: key",
				       a->tests ? "" : "; give --tests FILE");
	if (a->fit_depth && w->anywhere)
		return cli_usage_error(CMD, "--fit-depth: %s draws its contact "
				       "points anywhere (contacts.positions): "
				       "there is no depth to fit", a->wall);
	if (cli_check_depth(CMD, w, a->wall, a->depth))
		return 2;
	struct mc_config *cfg = &d->cfg;
	mc_config_default(cfg, w);
	if (a->n_set)
		cfg->n = a->n;
	if (a->seed_set)
		cfg->seed = a->seed;
	cfg->depth = a->depth;
	if (cfg->n < 1)
		return cli_usage_error(CMD, "no samples to compute (-n)");
	int rc = cli_threads(CMD, w, a->threads, mc_ncpu(), cfg->n,
			     &cfg->threads);
	cfg->opts.lp = cli_lp;	/* with cli_threads' memory limit */
	return rc;
}

/* The model's loads: from the samples file, the depth profile or one
 * run; d->md the run compared.  Returns 0 or the exit status; *intr is
 * set when a signal stopped the sampling (what was done is compared). */
static int model(const struct compare_args *a, const struct wall *w,
		 struct compare_data *d, int *intr)
{
	char err[SW_ERRLEN], warn[SW_ERRLEN];
	d->md = &d->one;
	if (a->samples) {
		long n;
		if (runlog_read_loads(a->samples, w, &d->one.lam, &n, warn,
				      err) != SW_OK) {
			cli_errorf("%s", err);
			return 2;
		}
		if (warn[0])
			cli_errorf("%s", warn);
		d->one.samples = d->one.accepted = n;
		d->one.depth = NAN;
		analyse(&d->one, d->tests, d->ntests);
	} else if (a->fit_depth) {
		if (fit_depth(&d->cfg, d->tests, d->ntests, &d->prof, &d->nprof,
			      &d->best, isatty(STDERR_FILENO), err) != SW_OK) {
			cli_errorf("slipwall compare: %s", err);
			return 1;
		}
		*intr = run_signal() != 0;
		if (d->best < 0) {
			cli_errorf("slipwall compare: no depth gave an "
				"accepted sample%s", *intr ? " before the signal" :
				": the analysis failed");
			return *intr ? sw_status_exit(SW_EINTR) : 1;
		}
		d->md = &d->prof[d->best];
	} else {
		enum sw_status st = run_model(&d->cfg, &d->one, err);
		if (st != SW_OK && st != SW_EINTR) {
			cli_errorf("slipwall compare: %s", err);
			return 1;
		}
		*intr = st == SW_EINTR;
		d->one.depth = d->cfg.depth < 0 ? w->depth : d->cfg.depth;
		analyse(&d->one, d->tests, d->ntests);
	}
	return 0;
}

static void json_profile(struct json *j, const struct compare_data *d)
{
	json_key(j, "fit_depth");
	json_object_begin(j);
	json_key_double(j, "best_depth", d->md->depth);
	json_key(j, "profile");
	json_array_begin(j);
	for (int i = 0; i < d->nprof; i++) {
		const struct model *p = &d->prof[i];
		json_object_begin(j);
		json_key_double(j, "depth", p->depth);
		json_key_int(j, "samples", p->samples);
		json_key_int(j, "accepted", p->accepted);
		json_key_double(j, "p05", p->s.p05);
		json_key_double(j, "ks_statistic", p->ks_ok ? p->ks.d : NAN);
		json_key_double(j, "p_two_sided", p->ks_ok ? p->ks.p_two_sided : NAN);
		json_object_end(j);
	}
	json_array_end(j);
	json_object_end(j);
}

static void print_json(const struct compare_args *a, const struct wall *w,
		       const struct compare_data *d)
{
	const struct model *md = d->md;
	struct json j;
	json_init(&j, stdout, 1);
	json_object_begin(&j);
	json_key(&j, "wall");
	json_string(&j, a->wall);
	override_json(&a->ov, &j);
	struct wall_quantity q;
	wall_quantity(w, &q);
	tally_quantity_json(&j, &q);
	json_key(&j, "model");
	json_object_begin(&j);
	json_key(&j, "source");
	json_string(&j, a->samples ? a->samples : "run");
	if (!a->samples) {
		json_key(&j, "seed");
		json_uint(&j, d->cfg.seed);
		json_key(&j, "depth");
		if (w->anywhere)
			json_null(&j);
		else
			json_double(&j, md->depth);
		json_key(&j, "samples");
		json_int(&j, md->samples);
	}
	json_key(&j, "accepted");
	json_int(&j, md->accepted);
	tally_summary_json(&j, &md->s);
	json_object_end(&j);
	json_key(&j, "tests");
	json_object_begin(&j);
	json_key(&j, "source");
	json_string(&j, a->tests ? a->tests : "wall");
	json_key(&j, "synthetic");
	json_bool(&j, a->tests && cli_tests_synthetic(a->tests));
	json_key(&j, "n");
	json_int(&j, d->ntests);
	tally_summary_json(&j, &d->ts);
	json_object_end(&j);
	json_key(&j, "ks");
	json_ks(&j, md);
	if (a->fit_depth)
		json_profile(&j, d);
	json_object_end(&j);
	json_end(&j);
}

static void print_profile(const struct compare_data *d)
{
	printf("%-7s %-10s %-12s %-10s %s\n", "depth", "accepted", "p05",
	       "KS D", "p two-sided");
	for (int i = 0; i < d->nprof; i++) {
		const struct model *p = &d->prof[i];
		printf("%-7.2f %5.1f %%    %-12.6g %-10.4g %-11.4g%s\n",
		       p->depth, p->samples ? 100.0 * (double)p->accepted /
		       (double)p->samples : 0.0, p->s.p05,
		       p->ks_ok ? p->ks.d : NAN,
		       p->ks_ok ? p->ks.p_two_sided : NAN,
		       i == d->best ? "  <- best" : "");
	}
	printf("best depth %.2f: KS distance %.4g, p = %.4g (two-sided)\n\n",
	       d->md->depth, d->md->ks.d, d->md->ks.p_two_sided);
}

static void print_text(const struct compare_args *a, const struct wall *w,
		       const struct compare_data *d)
{
	const struct model *md = d->md;
	struct wall_quantity q;
	wall_quantity(w, &q);
	printf("%s  [%s]\n", cli_text(w->name ? w->name : a->wall),
	       cli_text(a->wall));
	if (a->ov.n > 0) {
		char o[1024];
		override_describe(&a->ov, o, sizeof o);
		printf("overrides: %s\n", cli_text(o));
	}
	if (a->samples)
		printf("model: %ld accepted loads from %s\n", md->accepted,
		       cli_text(a->samples));
	else
		printf("model: %ld of %ld samples accepted (seed %lu, %s "
		       "%.4g)\n", md->accepted, md->samples, d->cfg.seed,
		       a->fit_depth ? "best depth" : "depth", md->depth);
	printf("tests: %ld loads from %s%s\nloads: %s\n\n", d->ntests,
	       a->tests ? cli_text(a->tests) : "the wall's tests: key",
	       a->tests && cli_tests_synthetic(a->tests) ?
	       " (SYNTHETIC: not measurements, the file's \"# slipwall: synthetic\" line says so)" : "",
	       q.what);
	if (a->fit_depth)
		print_profile(d);
	print_table(md, &d->ts, d->ntests);
	if (w->design_load > 0 && md->accepted > 0) {
		double *sl = stats_sorted_copy(md->lam, (size_t)md->accepted);
		struct collapse cp;
		collapse_at(sl, (size_t)md->accepted, w->design_load,
			    "design_load", &cp);
		free(sl);
		collapse_print(stdout, "\nmodel: ", q.name, &cp);
	}
	print_ks(md);
}

/* Compare, then print.  Returns the exit status. */
static int compare(const struct compare_args *a, const struct wall *w,
		   struct compare_data *d)
{
	int intr = 0, status = setup(a, w, d);
	if (!status)
		status = model(a, w, d, &intr);
	if (status)
		return status;
	stats_summarise(d->tests, (size_t)d->ntests, &d->ts);
	if (a->json)
		print_json(a, w, d);
	else
		print_text(a, w, d);
	cli_memory_note(CMD);
	if (intr) {
		cli_errorf("slipwall compare: interrupted (%s): the %s",
			   strsignal(run_signal()), a->fit_depth ?
			   "depths done were compared" :
			   "samples done were compared");
		return sw_status_exit(SW_EINTR);
	}
	if (run_signal()) {
		/* caught while the result was written: it is whole */
		fflush(stdout);
		cli_errorf("slipwall compare: interrupted (%s) while writing "
			   "the result: it is whole", strsignal(run_signal()));
		return sw_status_exit(SW_EINTR);
	}
	if (d->md->accepted == 0) {
		cli_errorf("slipwall compare: no model sample was accepted: "
			"the analysis failed");
		status = 1;
	}
	return status;
}

int cmd_compare(int argc, char **argv)
{
	struct compare_args a;
	struct wall *w;
	int status = parse_args(argc, argv, &a);
	if (!override_begin(CMD, status, a.wall, &a.ov, &w, &status))
		return status;
	if (a.samples && a.ov.n > 0) {
		/* the loads are the file's, as they were computed: an override
		 * reaches only the wall's tests and design load */
		char o[1024];
		override_describe(&a.ov, o, sizeof o);
		cli_errorf("slipwall %s: warning: the loads of %s%s%s are read "
			   "as they were computed: the overrides (%s) do not "
			   "change them, only the wall's tests and design load",
			   CMD, a.samples, a.against ? " and " : "",
			   a.against ? a.against : "", o);
	}
	if (a.against) {
		const struct compare_runs_args ra = {
			.wall = a.wall, .a = a.samples, .b = a.against,
			.ov = &a.ov, .json = a.json,
		};
		status = compare_runs(&ra, w);
		wall_free(w);
		override_free(&a.ov);
		return status;
	}
	struct compare_data d;
	memset(&d, 0, sizeof d);
	d.best = -1;
	struct run_signals caught;
	run_signals_catch(&caught, 1);
	status = compare(&a, w, &d);
	run_signals_restore(&caught);
	for (int i = 0; i < d.nprof; i++)
		free(d.prof[i].lam);
	free(d.prof);
	free(d.one.lam);
	free(d.tests);
	wall_free(w);
	override_free(&a.ov);
	return status;
}
