/*
 * cmd_report.c - `slipwall report`: the paper's figures and a summary of
 * a run, written into a directory (docs/report.md is the user's page).
 *
 * The model's loads come from a fresh Monte Carlo run (mc.c, like `run`)
 * or from a samples file of `run --samples`.  A samples file keeps the
 * loads and the contact positions but not the mechanisms, so for Fig. 6
 * the file's positions are replayed through the pool (`run --positions`
 * does the same); the figures use the file's loads, and the summary says
 * whether the replay reproduced them.  The experimental loads come from
 * --tests FILE (one per line, '#' comments) or the wall's `tests:` key.
 * The single-solution values of Fig. 10 are computed here on this thread
 * (solve_run): standard and gilbert always, global only for walls of at
 * most GLOBAL_MAX_BLOCKS free blocks and within --time-limit seconds.
 * Then report_write() (report.c) draws everything.
 *
 * SIGINT, SIGTERM and SIGHUP (run.h's handlers, for the whole command)
 * stop it at once wherever it is (the pool is stopped, report_write is
 * cancelled between two files),
 * and the report directory is then as it was: report_write writes into
 * a directory beside it and puts it in place only when everything is
 * written.  The exit status is 1, "interrupted", as for `run`.
 */
#include <ctype.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"
#include "cli_opts.h"
#include "summary.h"
#include "slipwall/collapse.h"
#include "override.h"
#include "slipwall/mc.h"
#include "slipwall/outfile.h"
#include "slipwall/report.h"
#include "slipwall/run.h"
#include "slipwall/runlog.h"
#include "slipwall/solve.h"
#include "slipwall/stats.h"
#include "slipwall/sys.h"
#include "slipwall/tally.h"

#define CMD "report"
#define GLOBAL_MAX_BLOCKS 12	/* the mixed-integer program beyond is slow */
#define GLOBAL_TIME 10.0	/* default --time-limit, s */

struct report_args {
	const char *wall, *samples, *tests, *out;
	long n;
	int n_set;
	unsigned long seed;
	int seed_set;
	int threads;
	double depth;		/* < 0: the wall's */
	double time_limit;
	struct overrides ov;	/* --friction, --set, ... */
};

static void usage(FILE *f)
{
	fprintf(f,
		"usage: slipwall report WALL.yaml --out DIR [--samples FILE.csv]\n"
		"                       [--tests FILE] [-n N] [--seed S] [--threads T]\n"
		"                       [--depth D] [--time-limit S]\n"
		"\n"
		"Figures (SVG, PDF and PNG) and a Markdown summary of a Monte Carlo\n"
		"run: the paper's Figs. 6, 8, 9 and 10, the convergence of p05 and\n"
		"Table 1, written into DIR (created if missing).\n"
		"\n"
		"  --out DIR           where to write (required)\n"
		"  --samples FILE.csv  the loads of a samples file of 'run' (its\n"
		"                      contact positions are replayed for the mechanisms)\n"
		"  --tests FILE        experimental loads, one per line, '#' comments\n"
		"                      (default: the wall's tests: key)\n"
		"  -n N, --seed S, --threads T, --depth D   as for 'run'\n"
		"  --friction, --load-at, --load-direction, --set KEY=VALUE\n"
		"                       change the wall as for 'run'; the report\n"
		"                       lists them, its command line repeats them\n"
		"  --time-limit S      for the global method (walls of at most %d\n"
		"                      blocks), default %g s\n", GLOBAL_MAX_BLOCKS,
		GLOBAL_TIME);
}

static int parse_args(int argc, char **argv, struct report_args *a)
{
	memset(a, 0, sizeof *a);
	a->depth = -1;
	a->time_limit = GLOBAL_TIME;
	const struct cli_opt opts[] = {
		CLI_OPT_SAMPLING(a),
		CLI_OPT_DEPTH(a),
		OVERRIDE_OPTIONS(&a->ov),
		{ .name = "--time-limit", .kind = CLI_OPT_TIME,
		  .dst = &a->time_limit },
		CLI_OPT_FILE("--samples", a->samples),
		CLI_OPT_FILE("--tests", a->tests),
		CLI_OPT_DIR("--out", a->out),
	};
	static const struct cli_cmd cmd = {
		.name = CMD, .usage = usage,
		.no_wall = "which wall? (slipwall report WALL.yaml --out DIR)",
	};
	int rc = cli_opts_parse(&cmd, opts, sizeof opts / sizeof *opts, argc,
				argv, &a->wall);
	if (rc)
		return rc;
	if (!a->out)
		return cli_usage_error(CMD, "where to? (--out DIR)");
	if (a->samples && (a->n_set || a->seed_set || a->depth >= 0))
		return cli_usage_error(CMD, "--samples takes the loads from a "
				       "file: -n, --seed and --depth do not apply");
	return 0;
}


/* ---- the model's loads ------------------------------------------------- */

static void tick(void *ctx, const struct tally *t)
{
	const struct mc_config *cfg = ctx;
	fprintf(stderr, "\rreport: %ld/%ld samples\033[K", t->samples,
		cfg->n);
	fflush(stderr);
}

/* Run the pool to the end (run_all): the tally and, in sample order,
 * the accepted loads.  SW_EINTR when a signal stopped it. */
static enum sw_status run_pool(const struct mc_config *cfg, struct tally *t,
			       double **lam, long *nlam, char *err)
{
	int tty = isatty(STDERR_FILENO);
	enum sw_status st = run_all(cfg, t, lam, nlam, tty ? tick : NULL,
				    (void *)cfg, err);
	if (tty)
		fprintf(stderr, "\r\033[K");
	if (st == SW_EINTR)
		snprintf(err, SW_ERRLEN, "interrupted (%s): no report written",
			 strsignal(run_signal()));
	return st;
}

/* The single-solution values (this thread's GLPK): standard and
 * gilbert from the summary beside a samples file when it has them (sf
 * not NULL), else computed; each step said on stderr as it starts and
 * ends, since on a large wall one takes minutes. */
static void single_solutions(const struct wall *w, double tlim,
			     const struct summary_file *sf,
			     struct report_solution *sol, int *nsol)
{
	static const enum solve_method ms[3] = {SOLVE_STANDARD, SOLVE_GILBERT,
						SOLVE_GLOBAL};
	*nsol = 0;
	for (int i = 0; i < 3; i++) {
		struct report_solution *s = &sol[(*nsol)++];
		memset(s, 0, sizeof *s);
		s->method = solve_method_name(ms[i]);
		s->lambda = NAN;
		if (ms[i] == SOLVE_GLOBAL && w->nfree > GLOBAL_MAX_BLOCKS) {
			snprintf(s->note, sizeof s->note, "not run: %d blocks "
				 "(the mixed-integer program runs for walls of at "
				 "most %d)", w->nfree, GLOBAL_MAX_BLOCKS);
			continue;
		}
		int has = !sf ? 0 : ms[i] == SOLVE_STANDARD ? sf->has_standard :
			  ms[i] == SOLVE_GILBERT ? sf->has_gilbert : 0;
		if (has) {
			/* X.json holds the loads as printed (the tally's
			 * quantity: wall_quantity), report_solution lambda */
			struct wall_quantity q;
			wall_quantity(w, &q);
			s->ran = s->found = 1;
			s->lambda = (ms[i] == SOLVE_STANDARD ? sf->standard :
				     sf->gilbert) / q.scale;
			snprintf(s->note, sizeof s->note, "from %.120s",
				 sf->path);
			fprintf(stderr, "report: %s: %.6g, from %s (not "
				"recomputed)\n", s->method, q.scale * s->lambda,
				sf->path);
			continue;
		}
		struct solve_opts o;
		struct solve_result r;
		char err[SW_ERRLEN];
		solve_opts_default(&o, ms[i]);
		o.sample.lp = cli_lp;
		o.time_limit = tlim;
		s->ran = 1;
		fprintf(stderr, "report: %s: computing the single solution "
			"(%d blocks)%s...\n", s->method, w->nfree,
			ms[i] == SOLVE_GLOBAL ? ", within --time-limit" : "");
		double t0 = sys_now();
		enum sw_status sst = solve_run(w, &o, &r, err);
		fprintf(stderr, "report: %s: %s (%.1f s)\n", s->method,
			sst != SW_OK ? "failed" : isfinite(r.lambda) ? "done" :
			"no load", sys_now() - t0);
		if (sst != SW_OK) {
			snprintf(s->note, sizeof s->note, "%.159s", err);
		} else if (r.status == SAMPLE_ACCEPTED ||
			   (ms[i] == SOLVE_GILBERT && isfinite(r.lambda))) {
			s->found = isfinite(r.lambda);
			s->lambda = r.lambda;
			if (ms[i] == SOLVE_GILBERT)
				snprintf(s->note, sizeof s->note, "%s after %d "
					 "iterations%s", r.converged ? "converged" :
					 "NOT converged", r.iterations,
					 r.status == SAMPLE_ACCEPTED ? "" :
					 "; no onset-of-collapse mechanism");
			else if (ms[i] == SOLVE_GLOBAL)
				snprintf(s->note, sizeof s->note, "%s (%.1f s)",
					 r.proven ? "optimal, proven" :
					 "best found within the time limit, not "
					 "proven", r.seconds);
			else
				snprintf(s->note, sizeof s->note, "associative: "
					 "an upper value");
		} else {
			snprintf(s->note, sizeof s->note, "%s",
				 sample_status_text(r.status));
		}
		solve_result_free(&r);
	}
}

/* The command that reproduces the report, malloc'd: the paths are the
 * user's, of any length. */
static char *command_line(const struct report_args *a,
			  const struct mc_config *cfg)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&buf, &len);
	if (!f)
		return sw_xstrdup("slipwall report");
	fputs("slipwall report", f);
	cli_shell_arg(f, a->wall);
	if (a->samples) {
		fputs(" --samples", f);
		cli_shell_arg(f, a->samples);
	} else {
		fprintf(f, " -n %ld --seed %lu", cfg->n, cfg->seed);
		if (a->depth >= 0)
			fprintf(f, " --depth %.17g", a->depth);
	}
	override_args(&a->ov, f);
	if (a->tests) {
		fputs(" --tests", f);
		cli_shell_arg(f, a->tests);
	}
	fputs(" --out", f);
	cli_shell_arg(f, a->out);
	if (fclose(f) != 0 || !buf) {
		free(buf);
		return sw_xstrdup("slipwall report");
	}
	return buf;
}

/* What report_main computes and frees. */
struct report_data {
	double *tests, *lam, *replay;
	struct draw_table draws;	/* the file's, replayed */
	long ntests, nlam;
	struct tally t;
	struct mc_config cfg;
	char note[2048];
};

/* The loads of a samples file, and its positions replayed for the
 * mechanisms (into d->t); d->note says whether the replay gave the
 * file's loads.  Returns 0 or the exit status. */
static int model_of_file(const struct report_args *a, const struct wall *w,
			 struct report_data *d)
{
	char err[SW_ERRLEN], warn[SW_ERRLEN];
	long rows, nrep = 0;
	if (runlog_read_loads(a->samples, w, &d->lam, &d->nlam, NULL, err) !=
	    SW_OK ||
	    runlog_read_draws(a->samples, w, &d->draws, warn, err) != SW_OK) {
		cli_errorf("%s", err);
		return 2;
	}
	if (warn[0])
		cli_errorf("%s", warn);
	rows = d->draws.rows;
	if (rows < 1) {
		cli_errorf("%s: no samples", a->samples);
		return 2;
	}
	d->cfg.replay = &d->draws;
	d->cfg.n = rows;
	int status = cli_threads(CMD, w, a->threads, mc_ncpu(), d->cfg.n,
				 &d->cfg.threads);
	if (status)
		return status;
	d->cfg.opts.lp = cli_lp;	/* with cli_threads' memory limit */
	fprintf(stderr, "report: %ld loads from %s; replaying their "
		"contact positions to recover the mechanisms (the file "
		"holds none)...\n", d->nlam, cli_text(a->samples));
	enum sw_status pst = run_pool(&d->cfg, &d->t, &d->replay, &nrep, err);
	if (pst != SW_OK) {
		cli_errorf("slipwall report: %s", err);
		return sw_status_exit(pst);
	}
	long differ = nrep != d->nlam;
	for (long i = 0; i < nrep && i < d->nlam; i++)
		differ += d->replay[i] != d->lam[i];
	if (differ)
		snprintf(d->note, sizeof d->note, "**Warning:** replaying the "
			 "contact positions of `%s` on this wall did not "
			 "give the file's loads (%ld accepted, the file has "
			 "%ld; %ld differences): the mechanisms and counts "
			 "are those of the replay, the plotted loads those "
			 "of the file. Was the wall changed?", a->samples,
			 nrep, d->nlam, differ);
	else
		snprintf(d->note, sizeof d->note, "The loads are those of `%s`; "
			 "its contact positions were replayed to recover "
			 "the mechanisms, and gave the same loads.",
			 a->samples);
	return 0;
}

/* A fresh run.  Returns 0 or the exit status. */
static int model_of_run(const struct report_args *a, const struct wall *w,
			struct report_data *d)
{
	char err[SW_ERRLEN];
	d->cfg.n = a->n_set ? a->n : w->samples;
	if (a->seed_set)
		d->cfg.seed = a->seed;
	d->cfg.depth = a->depth;
	int status = cli_threads(CMD, w, a->threads, mc_ncpu(), d->cfg.n,
				 &d->cfg.threads);
	if (status)
		return status;
	d->cfg.opts.lp = cli_lp;	/* with cli_threads' memory limit */
	enum sw_status pst = run_pool(&d->cfg, &d->t, &d->lam, &d->nlam, err);
	if (pst != SW_OK) {
		cli_errorf("slipwall report: %s", err);
		return sw_status_exit(pst);
	}
	return 0;
}

/* With a samples file, what its JSON summary holds (the workbench
 * saves X.json beside X.csv): standard and gilbert, when they provably
 * belong to the wall reported on - the summary's wall_digest is the
 * digest of this wall as loaded and changed here (wall_digest: the
 * model the solutions depend on).  The same file is not enough: a wall
 * edited in place keeps its device and inode.  NULL: nothing to
 * reuse. */
static const struct summary_file *reusable(const struct report_args *a,
					   const struct wall *w,
					   struct summary_file *sfile)
{
	if (!a->samples || summary_beside(a->samples, sfile) != 0)
		return NULL;
	char digest[WALL_DIGEST_LEN];
	wall_digest(w, digest);
	if (!strcmp(sfile->wall_digest, digest))
		return sfile;
	fprintf(stderr, "report: %s was written for %s, a model this wall "
		"%s: its single solutions are recomputed\n", sfile->path,
		sfile->wall[0] ? sfile->wall : "another wall",
		sfile->wall_digest[0] ? "is not (the file or --friction, "
		"--set, ... changed it)" : "cannot be matched to (it has no "
		"wall_digest)");
	return NULL;
}

/* Where the tests come from, for the summary (malloc'd). */
static char *tests_source(const struct report_args *a)
{
	if (!a->tests)
		return sw_xstrdup("the wall's tests: key");
	const char *syn = cli_tests_synthetic(a->tests) ?
		" (**synthetic**: not measurements, the file's `# slipwall: synthetic` line says so)" : "";
	size_t len = strlen(a->tests) + strlen(syn) + 3;
	char *tsrc = sw_xmalloc(len);
	snprintf(tsrc, len, "`%s`%s", a->tests, syn);
	return tsrc;
}

/* The design load's probability of collapse and the overrides, after
 * the replay's note. */
static void add_notes(const struct report_args *a, const struct wall *w,
		      struct report_data *d)
{
	char *note = d->note;
	size_t len = sizeof d->note;
	if (w->design_load > 0) {
		double *sl = stats_sorted_copy(d->lam, (size_t)d->nlam);
		struct collapse cp;
		collapse_at(sl, (size_t)d->nlam, w->design_load, "design_load",
			    &cp);
		free(sl);
		size_t u = strlen(note);
		struct wall_quantity q;
		wall_quantity(w, &q);
		snprintf(note + u, len - u, "%sDesign load %.6g "
			 "(analysis.design_load): P(%s ≤ %.6g) = %.4g (%zu of "
			 "%zu accepted samples), 99 %% interval [%.4g, %.4g] (exact "
			 "binomial); see the fragility figure.", u ? " " : "",
			 cp.load, q.name, cp.load, cp.p, cp.k, cp.n, cp.lo,
			 cp.hi);
	}
	if (a->ov.n > 0) {
		char o[1024];
		size_t u = strlen(note);
		override_describe(&a->ov, o, sizeof o);
		snprintf(note + u, len - u, "%sThe wall file's values "
			 "were changed for this report: %s.", u ? " " : "", o);
	}
}

/* The single solutions, then every file of the report; the line that
 * says what was written.  Returns the exit status. */
static int write_report(const struct report_args *a, const struct wall *w,
			struct report_data *d)
{
	struct summary_file sfile;
	struct report_solution sol[3];
	int nsol;
	char err[SW_ERRLEN];
	single_solutions(w, a->time_limit, reusable(a, w, &sfile), sol, &nsol);
	char *cmdline = command_line(a, &d->cfg), *tsrc = tests_source(a);
	add_notes(a, w, d);
	const struct tally *t = &d->t;
	struct report_input in = {
		.w = w,
		.lam = d->lam,
		.nlam = d->nlam,
		.mech = t,
		.tests = d->tests,
		.ntests = d->ntests,
		.sol = sol,
		.nsol = nsol,
		.run = {
			.wall_path = a->wall,
			.version = sw_version(),
			.command = cmdline,
			.samples_file = a->samples,
			.tests_source = tsrc,
			.seed_known = !a->samples,
			.seed = d->cfg.seed,
			.requested = a->samples ? 0 : d->cfg.n,
			.threads = d->cfg.threads,
			.depth = a->samples ? NAN : a->depth >= 0 ? a->depth :
				 w->depth,
			.anywhere = w->anywhere,
			.has_counts = 1,
			.samples = t->samples,
			.accepted = t->accepted,
			.note = *d->note ? d->note : NULL,
		},
	};
	memcpy(in.run.rejected, t->rejected, sizeof t->rejected);
	struct report_opts ro;
	report_opts_default(&ro);
	ro.cancel = run_signal_flag();
	int status = 0;
	if (report_write(&in, a->out, &ro, err) != SW_OK) {
		cli_errorf("slipwall report: %s", err);
		status = 1;
	} else {
		printf("%s/report.md: %ld accepted loads of %ld samples, %ld "
		       "tests, %d mechanisms\n", cli_text(a->out), d->nlam,
		       t->samples, d->ntests, t->nmech);
		if (!d->ntests)
			printf("no experimental loads: the figures show the "
			       "model alone\n");
		else if (a->tests && cli_tests_synthetic(a->tests))
			printf("the experimental loads of %s are synthetic (not "
			       "measurements: the file's \"# slipwall: synthetic\" line says so)\n", a->tests);
	}
	free(cmdline);
	free(tsrc);
	return status;
}

/* --out before any sampling (the output policy, outfile.h): a
 * directory (a symbolic link to one is one) or one that can be made,
 * none of its report files an input.  0 or the exit status. */
static int check_out(const struct report_args *a)
{
	const char *in[4];
	int k = 0;
	in[k++] = a->wall;
	if (a->samples)
		in[k++] = a->samples;
	if (a->tests)
		in[k++] = a->tests;
	in[k] = NULL;
	char err[SW_ERRLEN];
	enum sw_status st = outfile_check_dir(a->out, report_files(0), in,
					      "the report", err);
	if (st != SW_OK)
		cli_errorf("slipwall report: %s", err);
	return sw_status_exit(st);
}

static int report_main(int argc, char **argv)
{
	struct report_args a;
	struct wall *w;
	int status = parse_args(argc, argv, &a);
	if (!override_begin(CMD, status, a.wall, &a.ov, &w, &status))
		return status;

	struct report_data d;
	memset(&d, 0, sizeof d);
	tally_init(&d.t, w);
	mc_config_default(&d.cfg, w);
	status = cli_check_depth(CMD, w, a.wall, a.depth);
	if (!status)
		status = check_out(&a);
	if (!status && !(status = cli_tests(a.tests, w, &d.tests, &d.ntests)))
		status = a.samples ? model_of_file(&a, w, &d) :
			 model_of_run(&a, w, &d);
	cli_memory_note(CMD);
	if (!status && d.nlam == 0) {
		cli_errorf("slipwall report: no accepted sample (%ld "
			"computed): nothing to plot", d.t.samples);
		status = 1;
	}
	if (!status)
		status = write_report(&a, w, &d);
	report_cleanup();
	tally_free(&d.t);
	free(d.lam);
	free(d.replay);
	draw_table_free(&d.draws);
	free(d.tests);
	wall_free(w);
	override_free(&a.ov);
	return status;
}

int cmd_report(int argc, char **argv)
{
	struct run_signals caught;
	run_signals_catch(&caught, 0);
	int rc = report_main(argc, argv);
	run_signals_restore(&caught);
	return rc;
}
