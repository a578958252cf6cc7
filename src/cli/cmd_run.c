/*
 * cmd_run.c - `slipwall run`: the Monte Carlo analysis from the command
 * line (docs/method.md, "One sample"; docs/run.md is the user's page).
 *
 * The run itself is the library's (run.h): the worker pool (mc.c)
 * computes the samples; this thread takes them in index order through
 * run_pump, which writes each one's row to the samples file and counts
 * it, stops for --until-ci, on a write error or a signal (run.h says
 * the policies); here, when stderr is a terminal, a progress line is
 * redrawn at most ten times a second, and at the end the summary is
 * printed, for people or as JSON.  The signal handlers are one-shot: a
 * second Ctrl-C kills at once, the samples file still holds complete
 * rows only.  The progress line refreshes p05's interval at most once a
 * second beyond 20000 accepted samples (finding its ranks costs O(n)).
 *
 * Under mpirun (an MPI build, docs/cluster.md) every rank sets up the
 * same run and computes its share of the samples (cluster.c); rank 0
 * takes the merged stream (cluster_source) instead of its own pool and
 * does all of the above; the other ranks only send.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"
#include "cli_opts.h"
#include "cluster.h"
#include "slipwall/collapse.h"
#include "slipwall/family.h"
#include "override.h"
#include "slipwall/json.h"
#include "slipwall/mc.h"
#include "slipwall/run.h"
#include "slipwall/runlog.h"
#include "slipwall/sample.h"
#include "slipwall/stats.h"
#include "slipwall/sys.h"
#include "slipwall/tally.h"

#define CMD "run"
#define TOP_MECHANISMS 8	/* in the summary for people */

struct run_args {
	const char *wall;
	const char *samples;	/* --samples: the CSV to write */
	const char *positions;	/* --positions: a CSV to replay */
	long n;			/* 0: the wall's analysis.samples */
	int n_set;
	unsigned long seed;
	int seed_set;
	int threads;		/* 0: the number of CPUs */
	double depth;		/* < 0: the wall's */
	double until_ci;	/* 0: off */
	int json;
	int slp;		/* --slp: enum sample_slp */
	struct overrides ov;	/* --friction, --set, ... */
	double at;		/* --at LOAD; < 0: none */
};

static void usage(FILE *f)
{
	fprintf(f,
		"usage: slipwall run WALL.yaml [-n N] [--seed S] [--threads T]\n"
		"                    [--samples FILE.csv] [--replay FILE.csv]\n"
		"                    [--depth D] [--until-ci W] [--at LOAD] [--json]\n"
		"                    [--friction MU|BED,HEAD] [--load-at X,Y]\n"
		"                    [--load-direction DX,DY] [--set KEY=VALUE]...\n"
		"                    [--slp plain|anderson|piece]\n"
		"\n"
		"Monte Carlo analysis (docs/method.md): N samples of the collapse\n"
		"load with random contact points, their statistics and mechanisms.\n"
		"\n"
		"  -n N                 samples (default: the wall's analysis.samples)\n"
		"  --seed S             random seed (default: the wall's analysis.seed)\n"
		"  --threads T          worker threads (default: the number of CPUs);\n"
		"                       the results do not depend on it\n"
		"  --samples FILE.csv   write one row per sample, as it is computed\n"
		"  --replay FILE.csv    replay the draws (contact positions, and\n"
		"                       friction when random) of a samples file\n"
		"  --positions FILE.csv the same (its first name)\n"
		"  --depth D            imperfection depth, 0..0.5 (default: the wall's)\n"
		"  --friction MU | --friction BED,HEAD     friction of every joint, or\n"
		"                       of the bed and head joints\n"
		"                       (the means when friction is random)\n"
		"  --cov COV            friction random per joint and sample:\n"
		"                       lognormal, this coefficient of variation\n"		"  --load-at X,Y        where the wall's live load acts\n"
		"  --load-direction DX,DY   its direction\n"
		"  --set KEY=VALUE      any key of the wall file (material.unit_weight=\n"
		"                       20000, analysis.seed=3, loads.0.point.at=[0,1]);\n"
		"                       each override changes the wall as editing its\n"
		"                       file would, and the summary lists them\n"
		"  --at LOAD            the probability of collapse at LOAD (in N for\n"
		"                       point loads, whatever their magnitude),\n"
		"                       P(collapse load <= LOAD) among the accepted samples,\n"
		"                       with its exact 99 %% interval (a wall's\n"
		"                       analysis.design_load is always reported)\n"
		"  --until-ci W         stop when the 99 %% interval of p05 is narrower\n"
		"                       than W times p05 (at most N samples; looked at\n"
		"                       128, 256, 512, ... accepted samples, each look\n"
		"                       at a higher level so that the rule keeps 99 %%)\n"
		"  --slp plain          the SLP's plain iteration to its tolerance,\n"
		"                       for comparison; --slp anderson, the last\n"
		"                       round's accelerated default; the default,\n"
		"                       --slp piece, solves the fixed point of the\n"
		"                       piece the iteration settles on exactly\n"
		"                       (docs/method.md)\n"
		"  --json               print the summary as JSON\n"
		"\n"
		"Ctrl-C stops cleanly: the summary of the samples done, exit status 1.\n");
}

/* --slp plain|anderson|piece into an int (enum sample_slp). */
static int parse_slp(const char *cmd, const char *name, const char *v,
		     void *dst)
{
	if (!strcmp(v, "plain"))
		*(int *)dst = SAMPLE_SLP_PLAIN;
	else if (!strcmp(v, "anderson"))
		*(int *)dst = SAMPLE_SLP_ANDERSON;
	else if (!strcmp(v, "piece"))
		*(int *)dst = SAMPLE_SLP_PIECE;
	else
		return cli_usage_error(cmd, "%s: '%s' is not plain, anderson or piece",
				       name, v);
	return 0;
}

static int parse_args(int argc, char **argv, struct run_args *a)
{
	memset(a, 0, sizeof *a);
	a->depth = -1;
	a->slp = SAMPLE_SLP_PIECE;
	a->at = -1;
	const struct cli_opt opts[] = {
		CLI_OPT_SWITCH("--json", a->json),
		CLI_OPT_SAMPLING(a),
		CLI_OPT_DEPTH(a),
		OVERRIDE_OPTIONS(&a->ov),
		CLI_OPT_FILE("--samples", a->samples),
		CLI_OPT_FILE("--positions", a->positions),
		/* the same: it replays the whole draw (draw.h) */
		CLI_OPT_FILE("--replay", a->positions),
		{ .name = "--slp", .kind = CLI_OPT_CALL, .dst = &a->slp,
		  .call = parse_slp },
		{ .name = "--at", .kind = CLI_OPT_DOUBLE, .dst = &a->at,
		  .lo = 0, .hi = INFINITY, .what = "a load >= 0" },
		{ .name = "--until-ci", .kind = CLI_OPT_DOUBLE,
		  .dst = &a->until_ci, .lo = 0, .above = 1, .hi = INFINITY,
		  .what = "a relative width > 0" },
	};
	static const struct cli_cmd cmd = {
		.name = CMD, .usage = usage,
		.no_wall = "which wall? (slipwall run WALL.yaml)",
	};
	int rc = cli_opts_parse(&cmd, opts, sizeof opts / sizeof *opts, argc,
				argv, &a->wall);
	if (rc)
		return rc;
	if (a->positions && (a->seed_set || a->depth >= 0))
		return cli_usage_error(CMD, "--positions replays the contact "
				       "positions of a file: --seed and --depth "
				       "do not apply");
	return 0;
}

/* ---- the progress line ------------------------------------------------ */

static void fmt_duration(char *buf, size_t len, double s)
{
	if (!isfinite(s) || s < 0) {
		snprintf(buf, len, "?");
		return;
	}
	long t = (long)(s + 0.5);
	if (t >= 3600)
		snprintf(buf, len, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
	else
		snprintf(buf, len, "%ld:%02ld", t / 60, t % 60);
}

/* What the progress line shows of the interval, refreshed sparingly. */
struct progress_ci {
	double when;		/* elapsed time of the last refresh */
	int has;
	double p05, lo, hi;
};

static void progress(struct run *run, struct progress_ci *pc, long n,
		     double elapsed, double est)
{
	const struct tally *t = run->tally;
	double rate = elapsed > 0 ? (double)t->samples / elapsed : 0;
	char left[32], p05s[96] = "";
	fmt_duration(left, sizeof left, rate > 0 ? (double)(n - t->samples) /
		     rate : NAN);
	if (t->lam.n > 0 && (t->lam.n <= 20000 || elapsed - pc->when >= 1)) {
		pc->has = run_p05(run, &pc->p05, &pc->lo, &pc->hi);
		pc->when = elapsed;
	}
	if (t->lam.n > 0) {
		if (pc->has)
			snprintf(p05s, sizeof p05s, "  p05 %.4g [%.4g, %.4g]",
				 pc->p05, pc->lo, pc->hi);
		else
			snprintf(p05s, sizeof p05s, "  p05 %.4g", pc->p05);
	}
	/* slow samples (a large wall): seconds per sample, and before the
	 * first one how long it has been running */
	char speed[64];
	if (t->samples == 0 && (elapsed >= 1 || est >= 1)) {
		/* est: mc_sample_seconds, a rough a-priori time, said from
		 * the first line on a wall whose samples will be slow */
		char about[64] = "", a[32];
		if (est >= 1) {
			mc_about(a, sizeof a, est);
			snprintf(about, sizeof about, "  (estimate: %s a "
				 "sample)", a);
		}
		fmt_duration(speed, sizeof speed, elapsed);
		fprintf(stderr, "\r0/%ld  first samples running for %s, "
			"left > %s%s\033[K", n, speed, speed, about);
		fflush(stderr);
		return;
	}
	if (rate > 0 && rate < 1)
		snprintf(speed, sizeof speed, "%.3g s a sample", 1 / rate);
	else
		snprintf(speed, sizeof speed, "%.1f samples/s", rate);
	fprintf(stderr, "\r%ld/%ld  accepted %ld  rejected %ld  %s%s  "
		"left %s\033[K", t->samples, n, t->accepted,
		t->samples - t->accepted, speed, p05s, left);
	fflush(stderr);
}

/* ---- the summary -------------------------------------------------------- */

struct run_info {
	const struct run_args *a;
	const struct wall *w;
	const struct mc_config *cfg;
	long requested;
	enum run_stop stop;
	double elapsed;
	int ranks;		/* of an MPI job; 0: no job */
};

static double depth_used(const struct run_info *r)
{
	return r->cfg->depth < 0 ? r->w->depth : r->cfg->depth;
}

/* The families (docs/statistics.md, "Mechanism families"), each with
 * its most frequent mechanism, then the most frequent mechanisms, each
 * joint named by its number (the samples file's xa_k) and its bodies. */
static void print_families(const struct wall *w, const struct tally *t)
{
	const char *unit = *t->q.unit ? "load" : "factor";
	struct family_set fs;
	family_set_init(&fs, w);
	family_update(&fs, t);
	int idx[TOP_MECHANISMS];
	int nf = family_top(&fs, idx, TOP_MECHANISMS);
	printf("families     %d (mechanisms with the same moving region); "
	       "%s:\n", fs.nfam, fs.nfam > nf ? "the most frequent" :
	       "by frequency");
	for (int i = 0; i < nf; i++) {
		const struct family *f = &fs.fam[idx[i]];
		char name[256], j[160];
		family_label(&fs, f, name, sizeof name);
		printf("  %7ld %5.1f %%  %s %.4g..%.4g  %s\n", f->count,
		       100.0 * (double)f->count / (double)t->accepted, unit,
		       f->lam_lo, f->lam_hi, cli_text(name));
		int mk;
		family_mechs(&fs, t, idx[i], &mk, 1);
		const struct tally_mech *m = &t->mech[mk];
		int nbodies;
		char how[160];
		unsigned char *mv = sw_xmalloc((size_t)w->nblocks + 1);
		family_moving(w, m->joint, mv, &nbodies);
		family_motion(&fs, m->joint, mv, how, sizeof how);
		free(mv);
		family_fmt_joints(w, m->joint, j, sizeof j);
		printf("                  %d mechanism%s; the most frequent (%ld, "
		       "%d bod%s) %s: %s\n", f->nmech, f->nmech > 1 ? "s" : "",
		       m->count, nbodies, nbodies == 1 ? "y" : "ies", how,
		       cli_text(j));
	}
	int nt = tally_top(t, idx, TOP_MECHANISMS);
	printf("mechanisms   %d distinct; %s:\n", t->nmech,
	       t->nmech > nt ? "the most frequent" : "by frequency");
	int *rank = sw_xmalloc(sizeof(int) * ((size_t)fs.nfam + 1));
	int *fi = sw_xmalloc(sizeof(int) * ((size_t)fs.nfam + 1));
	int n = family_top(&fs, fi, fs.nfam);
	for (int i = 0; i < n; i++)
		rank[fi[i]] = i + 1;
	for (int i = 0; i < nt; i++) {
		const struct tally_mech *m = &t->mech[idx[i]];
		char j[120];
		family_fmt_joints(w, m->joint, j, sizeof j);
		printf("  %7ld %5.1f %%  %s %.4g..%.4g  family %d  joints %s\n",
		       m->count, 100.0 * (double)m->count / (double)t->accepted,
		       unit, m->lam_lo, m->lam_hi, rank[fs.of[idx[i]]],
		       cli_text(j));
	}
	free(rank);
	free(fi);
	printf("             (joint k(a/b) as in the samples file's xa_k, "
	       "between bodies a and b:\n"
	       "              s slides, h hinges, H hinges and slides, "
	       "o opens)\n");
	family_set_free(&fs);
}

/* Under the counts of tally_named's statuses: the blocks their
 * samples named (tally_unheld), the three named most often. */
static void print_unheld(const struct wall *w, const struct tally *t,
			 enum sample_status st)
{
	int b[3];
	long c[3];
	int n = tally_unheld(t, st, b, c, 3);
	if (n <= 0)
		return;
	printf("    %s: ", tally_unheld_text(st));
	for (int i = 0; i < n && i < 3; i++)
		printf("%sblock %s (%ld)", i ? ", " : "", w->blocks[b[i]].id,
		       c[i]);
	if (n > 3)
		printf(", and %d other block%s", n - 3, n > 4 ? "s" : "");
	printf("\n");
}

static void print_text(const struct run_info *r, const struct tally *t)
{
	struct stats_summary s;
	tally_summary(t, &s);
	const struct wall *w = r->w;

	if (w->name)
		printf("%s  [%s]\n", cli_text(w->name), cli_text(r->a->wall));
	else
		printf("%s\n", cli_text(r->a->wall));
	printf("samples      %ld of %ld (", t->samples, r->requested);
	if (r->a->positions)
		printf("positions of %s", cli_text(r->a->positions));
	else if (w->anywhere)
		printf("seed %lu, positions anywhere", r->cfg->seed);
	else
		printf("seed %lu, depth %g", r->cfg->seed, depth_used(r));
	if (r->ranks)
		printf(", %d rank%s x", r->ranks, r->ranks > 1 ? "s" : "");
	printf("%s%d thread%s)\n", r->ranks ? " " : ", ", r->cfg->threads,
	       r->cfg->threads > 1 ? "s" : "");
	if (w->mu_cov > 0)
		printf("friction     random per joint and sample: lognormal, "
		       "mean bed %g, head %g, cov %g\n", w->mu_bed, w->mu_head,
		       w->mu_cov);
	if (r->a->ov.n > 0) {
		char d[1024];
		override_describe(&r->a->ov, d, sizeof d);
		printf("overrides    %s\n", d);
	}
	printf("accepted     %ld (%.1f %%)\n", t->accepted,
	       t->samples ? 100.0 * (double)t->accepted / (double)t->samples : 0.0);
	printf("rejected     %ld\n", t->samples - t->accepted);
	for (int k = 0; k < SAMPLE_STATUS_COUNT; k++) {
		if (k != SAMPLE_ACCEPTED && t->rejected[k])
			printf("  %-40s %ld\n", sample_status_text(k),
			       t->rejected[k]);
		print_unheld(w, t, (enum sample_status)k);
	}
	if (s.n > 0) {
		printf("%-12s min %.6g  p05 %.6g  p50 %.6g  p95 %.6g  "
		       "max %.6g\n", *t->q.unit ? "load" : "factor", s.min,
		       s.p05, s.p50, s.p95, s.max);
		/* the sample standard deviation needs two values */
		if (isfinite(s.std))
			printf("             mean %.6g  std %.6g\n", s.mean,
			       s.std);
		else
			printf("             mean %.6g  std - (one value)\n",
			       s.mean);
		printf("             in %s\n", t->q.what);
		if (s.has_ci && s.ci_conf != 0.99)
			printf("p05          %.6g, 99 %% interval [%.6g, %.6g] "
			       "(characteristic value; --until-ci: the %.6g %% "
			       "interval of its last look, the looks' levels "
			       "add up to 99 %%)\n", s.p05, s.p05_lo, s.p05_hi,
			       100 * s.ci_conf);
		else if (s.has_ci)
			printf("p05          %.6g, 99 %% interval [%.6g, %.6g] "
			       "(characteristic value)\n", s.p05, s.p05_lo,
			       s.p05_hi);
		else
			printf("p05          %.6g, no interval: needs at least "
			       "90 accepted samples\n", s.p05);
	}
	struct collapse c;
	if (r->a->at >= 0) {
		collapse_at(t->lam.x, t->lam.n, r->a->at, "at", &c);
		collapse_print(stdout, "collapse     ", t->q.name, &c);
	}
	if (w->design_load > 0) {
		collapse_at(t->lam.x, t->lam.n, w->design_load, "design_load",
			    &c);
		collapse_print(stdout, "collapse     ", t->q.name, &c);
	}
	if (t->samples > 0)
		printf("work         %.1f SLP iterations, %.1f LPs per sample\n",
		       (double)t->iterations / (double)t->samples,
		       (double)t->lps / (double)t->samples);
	/* seconds a sample where samples are slower than one a second (a
	 * wall of a thousand blocks: "0.0 samples/s" said nothing), as the
	 * workbench's speed line does */
	double rate = r->elapsed > 0 ? (double)t->samples / r->elapsed : 0.0;
	if (t->samples > 0 && rate < 1)
		printf("speed        %.1f s a sample (%.2f s)\n",
		       r->elapsed / (double)t->samples, r->elapsed);
	else
		printf("speed        %.1f samples/s (%.2f s)\n", rate,
		       r->elapsed);
	if (t->nmech > 0)
		print_families(w, t);
	if (r->a->samples)
		printf("samples file %s\n", cli_text(r->a->samples));
}

/* "families" and "mechanisms" (docs/run.md): every family, most
 * frequent first, with its blocks and the positions of its mechanisms
 * in "mechanisms"; every mechanism with its family's position. */
static void families_json(const struct wall *w, const struct tally *t,
			  struct json *j)
{
	struct family_set fs;
	family_set_init(&fs, w);
	family_update(&fs, t);
	int *fi = sw_xmalloc(sizeof(int) * ((size_t)fs.nfam + 1));
	int *frank = sw_xmalloc(sizeof(int) * ((size_t)fs.nfam + 1));
	int nf = family_top(&fs, fi, fs.nfam);
	for (int i = 0; i < nf; i++)
		frank[fi[i]] = i;
	int *idx = sw_xmalloc(sizeof(int) * ((size_t)t->nmech + 1));
	int *mrank = sw_xmalloc(sizeof(int) * ((size_t)t->nmech + 1));
	int nt = tally_top(t, idx, t->nmech);
	for (int i = 0; i < nt; i++)
		mrank[idx[i]] = i;
	json_key(j, "families");
	json_array_begin(j);
	for (int i = 0; i < nf; i++) {
		const struct family *f = &fs.fam[fi[i]];
		char name[256];
		family_label(&fs, f, name, sizeof name);
		json_object_begin(j);
		json_key_string(j, "name", name);
		json_key(j, "blocks");
		json_array_begin(j);
		for (int b = 0; b < w->nblocks; b++)
			if (f->moving[b])
				json_string(j, w->blocks[b].id);
		json_array_end(j);
		json_key(j, "count");
		json_int(j, f->count);
		json_key(j, "lambda_lo");
		json_double(j, f->lam_lo);
		json_key(j, "lambda_hi");
		json_double(j, f->lam_hi);
		json_key(j, "mechanisms");
		json_array_begin(j);
		int *mk = sw_xmalloc(sizeof(int) * ((size_t)f->nmech + 1));
		int nm = family_mechs(&fs, t, fi[i], mk, f->nmech);
		for (int k = 0; k < nm; k++)
			json_int(j, mrank[mk[k]]);
		free(mk);
		json_array_end(j);
		json_object_end(j);
	}
	json_array_end(j);
	json_key(j, "mechanisms");
	json_array_begin(j);
	for (int i = 0; i < nt; i++) {
		const struct tally_mech *m = &t->mech[idx[i]];
		json_object_begin(j);
		json_key(j, "joints");
		json_string(j, m->joint);
		json_key(j, "count");
		json_int(j, m->count);
		json_key(j, "lambda_lo");
		json_double(j, m->lam_lo);
		json_key(j, "lambda_hi");
		json_double(j, m->lam_hi);
		json_key(j, "family");
		json_int(j, frank[fs.of[idx[i]]]);
		json_object_end(j);
	}
	json_array_end(j);
	free(idx);
	free(mrank);
	free(fi);
	free(frank);
	family_set_free(&fs);
}

static void print_json(const struct run_info *r, const struct tally *t)
{
	struct stats_summary s;
	tally_summary(t, &s);
	struct json j;
	json_init(&j, stdout, 1);
	json_object_begin(&j);
	json_key(&j, "wall");
	json_string(&j, r->a->wall);
	json_key(&j, "name");
	if (r->w->name)
		json_string(&j, r->w->name);
	else
		json_null(&j);
	cli_json_warnings(&j, r->w);
	json_key(&j, "positions");
	json_string(&j, r->a->positions ? "replay" :
		    r->w->anywhere ? "anywhere" : "depth");
	json_key(&j, "seed");
	json_uint(&j, r->cfg->seed);
	json_key(&j, "depth");
	if (r->a->positions || r->w->anywhere)
		json_null(&j);
	else
		json_double(&j, depth_used(r));
	if (r->w->mu_cov > 0) {	/* random friction (absent: fixed) */
		json_key(&j, "friction");
		json_object_begin(&j);
		json_key(&j, "bed");
		json_double(&j, r->w->mu_bed);
		json_key(&j, "head");
		json_double(&j, r->w->mu_head);
		json_key(&j, "cov");
		json_double(&j, r->w->mu_cov);
		json_object_end(&j);
	}
	override_json(&r->a->ov, &j);
	json_key(&j, "threads");
	json_int(&j, r->cfg->threads);
	if (r->ranks) {
		json_key(&j, "ranks");
		json_int(&j, r->ranks);
	}
	json_key(&j, "requested");
	json_int(&j, r->requested);
	json_key(&j, "stopped");
	json_string(&j, run_stop_name(r->stop));
	tally_json(t, &j);
	/* the blocks the samples of tally_named's statuses named
	 * (docs/run.md), most samples first */
	json_key(&j, "unheld");
	json_object_begin(&j);
	int *ub = sw_xmalloc(sizeof *ub * ((size_t)t->nblocks + 1));
	long *uc = sw_xmalloc(sizeof *uc * ((size_t)t->nblocks + 1));
	for (int s = 0; s < TALLY_NAMED; s++) {
		json_key(&j, sample_status_name(tally_named[s]));
		json_array_begin(&j);
		int nb = tally_unheld(t, tally_named[s], ub, uc, t->nblocks);
		for (int i = 0; i < nb; i++) {
			json_object_begin(&j);
			json_key_string(&j, "block", r->w->blocks[ub[i]].id);
			json_key(&j, "count");
			json_int(&j, uc[i]);
			json_object_end(&j);
		}
		json_array_end(&j);
	}
	free(ub);
	free(uc);
	json_object_end(&j);
	json_key(&j, "p05_ci_level");	/* the level of p05_ci99's ends */
	json_double(&j, t->ci_conf);
	json_key(&j, "design_load");
	if (r->w->design_load > 0)
		json_double(&j, r->w->design_load);
	else
		json_null(&j);
	json_key(&j, "collapse_probability");
	json_array_begin(&j);
	struct collapse c;
	if (r->a->at >= 0) {
		collapse_at(t->lam.x, t->lam.n, r->a->at, "at", &c);
		collapse_json(&j, &c);
	}
	if (r->w->design_load > 0) {
		collapse_at(t->lam.x, t->lam.n, r->w->design_load,
			    "design_load", &c);
		collapse_json(&j, &c);
	}
	json_array_end(&j);
	json_key(&j, "iterations_per_sample");
	json_double(&j, t->samples ? (double)t->iterations / (double)t->samples : NAN);
	json_key(&j, "lps_per_sample");
	json_double(&j, t->samples ? (double)t->lps / (double)t->samples : NAN);
	families_json(r->w, t, &j);
	json_key(&j, "samples_file");
	if (r->a->samples)
		json_string(&j, r->a->samples);
	else
		json_null(&j);
	/* where every LP started (SLIPWALL_LP_START): not the results,
	 * which are the same from every start, but their cost */
	json_key(&j, "lp_start");
	json_string(&j, sample_start_name(cli_lp.start));
	/* timing: the only fields that change from run to run */
	json_key(&j, "elapsed_seconds");
	json_double(&j, r->elapsed);
	json_key(&j, "samples_per_second");
	json_double(&j, r->elapsed > 0 ? (double)t->samples / r->elapsed : NAN);
	json_object_end(&j);
	json_end(&j);
}

/* ---- the command -------------------------------------------------------- */

/* Everything `run` sets up before it samples. */
struct run_setup {
	struct run_args a;
	struct wall *w;
	struct mc_config cfg;
	struct draw_table replay;	/* --positions */
	struct runlog *log;	/* --samples, rank 0 only */
};

static void setup_free(struct run_setup *s)
{
	char err[SW_ERRLEN];
	runlog_close(s->log, err);
	draw_table_free(&s->replay);
	wall_free(s->w);
	override_free(&s->a.ov);
	memset(s, 0, sizeof *s);
}

/* On ranks > 0 of a job, the set-up's messages (a usage error, an
 * error in the wall file) go to a temporary file instead of stderr:
 * every rank reads the same options and files, so rank 0's messages
 * say it once.  A rank that fails where rank 0 did not (its own copy of
 * a file) prints its messages after all (held_release). */
struct held {
	int saved;		/* stderr, or -1: nothing held */
	FILE *tmp;
};

static void held_start(struct held *h, const struct cluster *cl)
{
	h->saved = -1;
	h->tmp = NULL;
	if (cluster_rank(cl) == 0 || !(h->tmp = tmpfile()))
		return;
	fflush(stderr);
	h->saved = dup(STDERR_FILENO);
	if (h->saved < 0 || dup2(fileno(h->tmp), STDERR_FILENO) < 0) {
		if (h->saved >= 0)
			close(h->saved);
		h->saved = -1;
	}
}

/* Give stderr back; print what was held when show is set. */
static void held_release(struct held *h, int show)
{
	if (h->saved >= 0) {
		fflush(stderr);
		dup2(h->saved, STDERR_FILENO);
		close(h->saved);
		if (show) {
			char buf[4096];
			size_t n;
			rewind(h->tmp);
			while ((n = fread(buf, 1, sizeof buf, h->tmp)) > 0)
				fwrite(buf, 1, n, stderr);
			fflush(stderr);
		}
	}
	if (h->tmp)
		fclose(h->tmp);
	h->saved = -1;
	h->tmp = NULL;
}

/* Parse the options, load the wall and fill the config (every rank of a
 * job does the same); the samples file is created by rank 0 only.
 * Returns 0, -1 when there is nothing to do (--help) or the exit
 * status, with a message printed. */
static int setup(int argc, char **argv, const struct cluster *cl,
		 struct run_setup *s)
{
	struct run_args *a = &s->a;
	memset(s, 0, sizeof *s);
	int rc = parse_args(argc, argv, a);
	if (rc)
		return rc;
	if ((rc = override_load(CMD, a->wall, &a->ov, &s->w)))
		return rc;
	struct wall *w = s->w;
	if (cli_check_depth(CMD, w, a->wall, a->depth))
		return 2;

	char err[SW_ERRLEN];
	struct mc_config *cfg = &s->cfg;
	mc_config_default(cfg, w);
	cfg->opts.slp = (enum sample_slp)a->slp;
	if (a->positions) {
		char warn[SW_ERRLEN];
		if (runlog_read_draws(a->positions, w, &s->replay, warn,
				      err) != SW_OK) {
			cli_errorf("%s", err);
			return 2;
		}
		if (warn[0])
			cli_errorf("%s", warn);
		long rows = s->replay.rows;
		if (a->n_set && a->n > rows)
			return cli_usage_error(CMD, "-n %ld: %s holds %ld "
					       "samples", a->n, a->positions, rows);
		cfg->replay = &s->replay;
		cfg->n = a->n_set ? a->n : rows;
	} else {
		cfg->n = a->n_set ? a->n : w->samples;
	}
	if (cfg->n < 1)
		return cli_usage_error(CMD, "no samples to compute (-n)");
	if (a->seed_set)
		cfg->seed = a->seed;
	cfg->depth = a->depth;
	if ((rc = cli_threads(CMD, w, a->threads, cl ? cluster_threads(cl) :
			      mc_ncpu(), cfg->n, &cfg->threads)))
		return rc;
	cfg->opts.lp = cli_lp;	/* with cli_threads' memory limit */

	if (a->samples && cluster_rank(cl) == 0) {
		const char *keep[] = {a->wall, a->positions, NULL};
		enum sw_status st = runlog_create(&s->log, a->samples, w, keep,
						  err);
		if (st != SW_OK) {
			cli_errorf("slipwall run: %s", err);
			return sw_status_exit(st);
		}
	}
	return 0;
}

/* What went wrong, on stderr; the exit status. */
static int report_end(const struct run *run, enum sw_status cst,
		      const char *cerr, long n)
{
	const struct tally *t = run->tally;
	enum sw_status sst = run->source_status;
	int status = 0;
	if (run->stop == RUN_WRITE) {
		cli_errorf("slipwall run: %s", run->werr);
		status = 1;
	} else if (cst != SW_OK) {
		cli_errorf("slipwall run: %s", cerr);
		status = 1;
	}
	if (run->stop == RUN_SIGNAL) {
		cli_errorf("slipwall run: interrupted (%s) after %ld of %ld "
			"samples", run->why, t->samples, n);
		status = sw_status_exit(SW_EINTR);
	}
	if (run->stop == RUN_LOST) {
		cli_errorf("slipwall run: %s: stopped after %ld of %ld "
			"samples", run->source_err, t->samples, n);
		status = 1;
	} else if (sst != SW_OK && sst != SW_EINTR) {
		cli_errorf("slipwall run: %s", run->source_err);
		status = 1;
	}
	cli_memory_note(CMD);
	if (t->accepted == 0 && t->samples > 0) {
		cli_errorf("slipwall run: no sample was accepted: the "
			"analysis failed (see the rejections above)");
		status = 1;
	}
	return status;
}

/* Rank 0 (or the only process): take the samples in order, write and
 * count them (run.c), print the summary.  Returns the exit status. */
static int sample(struct run_setup *s, const struct run_source *src,
		  const struct cluster *cl, double t0)
{
	const struct mc_config *cfg = &s->cfg;
	struct run_signals caught;
	run_signals_catch(&caught, 1);
	run_signals_watch(src);

	int tty = isatty(STDERR_FILENO);
	struct tally t;
	struct run run;
	struct progress_ci pci = {0};
	tally_init(&t, s->w);
	run_init(&run, s->w, src, &t, s->log);
	run.until_ci = s->a.until_ci;
	double last_draw = 0, est = mc_sample_seconds(s->w);
	while (run_pump(&run, tty ? 100 : -1) >= 0) {
		if (tty && sys_now() - last_draw >= 0.1) {
			last_draw = sys_now();
			progress(&run, &pci, cfg->n, last_draw - t0, est);
		}
	}
	double elapsed = sys_now() - t0;
	if (tty)
		fprintf(stderr, "\r\033[K");
	run_finish(&run);
	/* the signals stay caught while the summary is written (a reader
	 * slow to take it blocks the writing): the first one now only marks,
	 * the summary is finished, and the exit says so; after a signal
	 * that stopped the sampling, a second one kills (run.h's policy) */
	run_signals_watch(NULL);

	char err[SW_ERRLEN];
	enum sw_status cst = runlog_close(s->log, err);
	s->log = NULL;

	struct run_info info = {&s->a, s->w, cfg, cfg->n, run.stop, elapsed,
				cl ? cluster_size(cl) : 0};
	if (s->a.json)
		print_json(&info, &t);
	else
		print_text(&info, &t);
	fflush(stdout);
	int late = run.stop == RUN_SIGNAL ? 0 : run_signal();
	run_signals_restore(&caught);

	int status = report_end(&run, cst, err, cfg->n);
	if (late) {
		cli_errorf("slipwall run: interrupted (%s) while writing the "
			   "summary: the samples file and the summary are "
			   "whole", strsignal(late));
		status = sw_status_exit(SW_EINTR);
	}
	run_free(&run);
	tally_free(&t);
	return status;
}

/* A rank > 0 of a job: compute and send.  Rank 0 reports a signal. */
static int serve(struct cluster *cl, const struct run_source *src)
{
	char err[SW_ERRLEN];
	struct run_signals caught;
	run_signals_catch(&caught, 1);
	run_signals_watch(src);
	enum sw_status st = cluster_serve(cl, err);
	run_signals_restore(&caught);
	if (st != SW_OK && st != SW_EINTR)
		cli_errorf("slipwall run: %s", err);
	return sw_status_exit(st);
}

/* Set up, start the pool (this rank's share in a job), agree with the
 * other ranks, then sample or serve. */
static int run_job(struct cluster *cl, int argc, char **argv)
{
	struct run_setup s;
	char err[SW_ERRLEN];
	struct mc *pool = NULL;
	struct held held;
	held_start(&held, cl);
	int rc = setup(argc, argv, cl, &s);
	double t0 = sys_now();
	if (rc == 0 && cl && cluster_open(cl, &s.cfg, err) != SW_OK) {
		cli_errorf("slipwall run: %s", err);
		rc = 1;
	} else if (rc == 0 && !cl && !(pool = mc_start(&s.cfg, err))) {
		cli_errorf("slipwall run: %s", err);
		rc = 1;
	}
	int root_rc;
	int mine = rc;
	rc = cluster_agree(cl, rc, rc == 0 ? &s.cfg : NULL, &root_rc);
	held_release(&held, mine > 0 && root_rc <= 0);
	if (rc == 0) {
		struct run_source src;
		if (cl)
			cluster_source(cl, &src);
		else
			run_source_pool(&src, pool);
		rc = cluster_rank(cl) > 0 ? serve(cl, &src) :
		     sample(&s, &src, cl, t0);
	}
	mc_free(pool);
	cluster_close(cl);	/* its workers read the wall */
	setup_free(&s);
	return rc < 0 ? 0 : rc;
}

int cmd_run(int argc, char **argv)
{
	struct cluster *cl;
	char err[SW_ERRLEN];
	enum sw_status st = cluster_start(&cl, err);
	if (st != SW_OK) {
		if (err[0])	/* (empty: another process says it) */
			cli_errorf("slipwall run: %s", err);
		return sw_status_exit(st);
	}
	return cluster_end(cl, run_job(cl, argc, argv));
}
