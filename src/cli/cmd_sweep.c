/*
 * cmd_sweep.c - `slipwall sweep`: one Monte Carlo run per value of one
 * parameter, and how the collapse load moves with it (docs/run.md,
 * "Sweeps").
 *
 *   --friction A:B:STEP        material.friction = A, A + STEP, ..., B
 *   --depth A:B:STEP           the imperfection depth (as run --depth)
 *   --load-at X1,Y1:X2,Y2:N    the live load at N points from (X1, Y1) to
 *                              (X2, Y2)
 *
 * Every value is a run of the wall as `run` would make it with that one
 * override (override.c; --depth as run's --depth), with the same seed
 * and sample count: the contact positions of sample i are drawn from
 * (seed, i) alone (sample_positions), so every value sees the same
 * draws - common random numbers - and the curve moves with the
 * parameter, not with the noise.  Other overrides (--set ..., a
 * --friction without ':') apply to every value.
 *
 * Output: a table (value, accepted, p05 and its 99 % interval, p50, p95,
 * mechanisms, families), or --json; --csv FILE writes the table's rows;
 * --out DIR draws sweep.svg/.pdf/.png (report.c, report_write_sweep).
 * The output policy (outfile.h): --csv and --out are checked before the
 * first value; --csv is never the wall; a file gets each value's row in
 * FILE.tmp as the value finishes (nothing done is lost to a SIGKILL)
 * and is renamed whole at the end, a stream gets the rows after the
 * table; the signal handlers stay through the writing, which finishes
 * the table and the CSV and cancels the figure.  A value that stops the
 * sweep (a load point off the wall, a run that fails) keeps the values
 * done: they are printed and written, then the message.
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "cli_opts.h"
#include "override.h"
#include "slipwall/json.h"
#include "slipwall/mc.h"
#include "slipwall/outfile.h"
#include "slipwall/report.h"
#include "slipwall/stats.h"
#include "slipwall/run.h"
#include "slipwall/family.h"
#include "slipwall/tally.h"
#include "slipwall/text.h"

#define CMD "sweep"
#define MAX_VALUES 1000

enum sweep_param { SW_NONE, SW_FRICTION, SW_COV, SW_DEPTH, SW_LOAD_AT };

struct sweep_args {
	const char *wall, *csv, *out;
	long n;
	int n_set;
	unsigned long seed;
	int seed_set;
	int threads;
	int json;
	enum sweep_param param;
	const char *range;	/* as given */
	double *val;		/* the values (friction, depth; load-at: t) */
	double (*at)[2];	/* load-at: the points */
	int nval;		/* the values (after a stop: those done) */
	int asked;		/* the values of the range */
	struct overrides ov;	/* fixed for every value */
};

static void usage(FILE *f)
{
	fprintf(f,
		"usage: slipwall sweep WALL.yaml (--friction A:B:STEP | --depth A:B:STEP |\n"
		"                     --load-at X1,Y1:X2,Y2:N) [-n N] [--seed S]\n"
		"                     [--threads T] [--csv FILE] [--json] [--out DIR]\n"
		"                     [--set KEY=VALUE]... (and run's other overrides)\n"
		"\n"
		"One Monte Carlo run per value of one parameter, all with the same\n"
		"seed: sample i has the same contact draws at every value (common\n"
		"random numbers), so the curve shows the parameter's effect.\n"
		"\n"
		"  --friction A:B:STEP     friction of every joint from A to B\n"
		"  --cov A:B:STEP          friction's coefficient of variation per\n"
		"                          joint from A to B (0..1; random friction)\n"
		"  --depth A:B:STEP        imperfection depth from A to B (0..0.5)\n"
		"  --load-at X1,Y1:X2,Y2:N the live load at N points along a line\n"
		"  -n N                    samples per value (default: the wall's)\n"
		"  --seed S, --threads T   as for 'run'\n"
		"  --csv FILE              the table as CSV\n"
		"  --json                  the table as JSON\n"
		"  --out DIR               sweep.svg, sweep.pdf, sweep.png: p05 with its\n"
		"                          99 %% interval, p50 and p95 against the value\n"
		"  --friction MU, --load-at X,Y, --load-direction DX,DY, --set KEY=VALUE\n"
		"                          change the wall for every value, as for 'run'\n"
		"\n"
		"The table: value, accepted samples, p05 and its 99 %% interval, p50,\n"
		"p95, the number of distinct mechanisms and of their families\n"
		"(the sets of blocks that move).\n");
}

/* "a:b:c" into its three fields (in buf, len bytes); 0 on success. */
static int split3(const char *s, char *buf, size_t len, char **f)
{
	if (strlen(s) >= len)
		return -1;
	strcpy(buf, s);
	char *c1 = strchr(buf, ':'), *c2 = c1 ? strchr(c1 + 1, ':') : NULL;
	if (!c1 || !c2 || strchr(c2 + 1, ':'))
		return -1;
	*c1 = *c2 = 0;
	f[0] = buf;
	f[1] = c1 + 1;
	f[2] = c2 + 1;
	return 0;
}

/* A:B:STEP into the values A, A + STEP, ... up to B (B included when
 * it is within STEP/1000 of a step). */
static int parse_steps(const char *s, double lo_ok, double hi_ok,
		       double **out, int *nout)
{
	char buf[256], *f[3];
	double a, b, step;
	if (split3(s, buf, sizeof buf, f) || text_parse_double(f[0], &a) ||
	    text_parse_double(f[1], &b) ||
	    text_parse_double(f[2], &step) || !(step > 0) || b < a ||
	    a < lo_ok || b > hi_ok)
		return -1;
	double count = floor((b - a) / step + 1e-3) + 1;
	if (count > MAX_VALUES)
		return -1;
	int n = (int)count;
	*out = sw_xmalloc(sizeof(double) * (size_t)n);
	for (int i = 0; i < n; i++) {
		/* 12 digits: 0.4 + 2 * 0.1 is the 0.6 that `run --friction
		 * 0.6` reads, not 0.6000000000000001 */
		char t[32];
		double v = a + step * i;
		snprintf(t, sizeof t, "%.12g", v > b ? b : v);
		(*out)[i] = strtod(t, NULL);
	}
	*nout = n;
	return 0;
}

/* X1,Y1:X2,Y2:N */
static int parse_line(const char *s, struct sweep_args *a)
{
	char buf[256], *parts[3];
	double p[4];
	long n;
	if (split3(s, buf, sizeof buf, parts))
		return -1;
	for (int k = 0; k < 2; k++) {
		char *comma = strchr(parts[k], ',');
		if (!comma)
			return -1;
		*comma = 0;
		if (text_parse_double(parts[k], &p[2 * k]) ||
		    text_parse_double(comma + 1, &p[2 * k + 1]))
			return -1;
	}
	if (text_parse_long(parts[2], 2, MAX_VALUES, &n))
		return -1;
	a->nval = (int)n;
	a->val = sw_xmalloc(sizeof(double) * (size_t)n);
	a->at = sw_xmalloc(sizeof *a->at * (size_t)n);
	double len = hypot(p[2] - p[0], p[3] - p[1]);
	for (int i = 0; i < n; i++) {
		double t = (double)i / (double)(n - 1);
		a->at[i][0] = p[0] + t * (p[2] - p[0]);
		a->at[i][1] = p[1] + t * (p[3] - p[1]);
		a->val[i] = t * len;	/* distance from the first point */
	}
	return 0;
}

static int set_param(struct sweep_args *a, enum sweep_param p, const char *v)
{
	if (a->param != SW_NONE)
		return cli_usage_error(CMD, "one parameter per sweep (%s and %s)",
				       a->range, v);
	a->param = p;
	a->range = v;
	int bad = p == SW_FRICTION ? parse_steps(v, 0, INFINITY, &a->val,
						 &a->nval) :
		  p == SW_COV ? parse_steps(v, 0, WALL_COV_MAX, &a->val,
					    &a->nval) :
		  p == SW_DEPTH ? parse_steps(v, 0, 0.5, &a->val, &a->nval) :
		  parse_line(v, a);
	if (bad)
		return cli_usage_error(CMD, "%s: '%s' is not %s",
				       p == SW_FRICTION ? "--friction" :
				       p == SW_COV ? "--cov" :
				       p == SW_DEPTH ? "--depth" : "--load-at", v,
				       p == SW_FRICTION ? "A:B:STEP (0 <= A <= B, "
				       "STEP > 0, at most 1000 values)" :
				       p == SW_COV ? "A:B:STEP (0 <= A <= B <= "
				       "1, STEP > 0, at most 1000 values)" :
				       p == SW_DEPTH ? "A:B:STEP (0 <= A <= B <= "
				       "0.5, STEP > 0, at most 1000 values)" :
				       "X1,Y1:X2,Y2:N (N from 2 to 1000)");
	return 0;
}

/* --depth A:B:STEP: the parameter. */
static int opt_depth(const char *cmd, const char *name, const char *v,
		     void *dst)
{
	(void)cmd;
	(void)name;
	return set_param(dst, SW_DEPTH, v);
}

/* --friction, --cov and --load-at: the parameter when a range
 * (A:B:STEP, X1,Y1:X2,Y2:N), else a fixed override as for run (MU, COV,
 * X,Y). */
static int opt_range_or_fixed(const char *cmd, const char *name,
			      const char *v, void *dst)
{
	struct sweep_args *a = dst;
	if (!strchr(v, ':'))
		return override_add(cmd, name, v, &a->ov);
	return set_param(a, !strcmp(name, "--friction") ? SW_FRICTION :
			 !strcmp(name, "--cov") ? SW_COV : SW_LOAD_AT, v);
}

static int parse_args(int argc, char **argv, struct sweep_args *a)
{
	memset(a, 0, sizeof *a);
	const struct cli_opt opts[] = {
		CLI_OPT_SWITCH("--json", a->json),
		CLI_OPT_SAMPLING(a),
		{ .name = "--depth", .kind = CLI_OPT_CALL, .dst = a,
		  .call = opt_depth },
		{ .name = "--friction", .kind = CLI_OPT_CALL, .dst = a,
		  .call = opt_range_or_fixed },
		{ .name = "--cov", .kind = CLI_OPT_CALL, .dst = a,
		  .call = opt_range_or_fixed },
		{ .name = "--load-at", .kind = CLI_OPT_CALL, .dst = a,
		  .call = opt_range_or_fixed },
		OVERRIDE_OPTION("--load-direction", &a->ov),
		OVERRIDE_OPTION("--set", &a->ov),
		CLI_OPT_FILE("--csv", a->csv),
		CLI_OPT_DIR("--out", a->out),
	};
	static const struct cli_cmd cmd = {
		.name = CMD, .usage = usage,
		.no_wall = "which wall? (slipwall sweep WALL.yaml "
			   "--friction A:B:STEP)",
	};
	int rc = cli_opts_parse(&cmd, opts, sizeof opts / sizeof *opts, argc,
				argv, &a->wall);
	if (rc)
		return rc;
	if (a->param == SW_NONE)
		return cli_usage_error(CMD, "what to sweep? --friction A:B:STEP, "
				       "--cov A:B:STEP, --depth A:B:STEP or "
				       "--load-at X1,Y1:X2,Y2:N");
	a->asked = a->nval;
	return 0;
}

static void args_free(struct sweep_args *a)
{
	free(a->val);
	free(a->at);
	override_free(&a->ov);
}

/* ---- one value ---------------------------------------------------------- */

struct point {
	double value, at[2];
	long samples, accepted;
	struct stats_summary s;
	int mechanisms;
	int families;	/* docs/statistics.md, "Mechanism families" */
};

/* The wall for value k: the fixed overrides and the value's own. */
static int wall_for(const struct sweep_args *a, int k, struct wall **w)
{
	struct overrides ov = {0};
	char arg[128];
	int rc = 0;
	for (int i = 0; i < a->ov.n && !rc; i++)
		rc = override_add(CMD, a->ov.o[i].option, a->ov.o[i].arg, &ov);
	if (!rc && a->param != SW_DEPTH) {
		if (a->param == SW_FRICTION || a->param == SW_COV)
			snprintf(arg, sizeof arg, "%.17g", a->val[k]);
		else
			snprintf(arg, sizeof arg, "%.17g,%.17g", a->at[k][0],
				 a->at[k][1]);
		rc = override_add(CMD, a->param == SW_FRICTION ? "--friction" :
				  a->param == SW_COV ? "--cov" : "--load-at",
				  arg, &ov);
	}
	if (!rc)
		rc = override_load(CMD, a->wall, &ov, w);
	override_free(&ov);
	return rc;
}

/* The progress line of one value's run. */
struct sweep_tick {
	int k, nval;
	long n;
};

static void tick(void *ctx, const struct tally *t)
{
	const struct sweep_tick *st = ctx;
	fprintf(stderr, "\rsweep: value %d of %d, %ld/%ld samples\033[K",
		st->k + 1, st->nval, t->samples, st->n);
	fflush(stderr);
}

/* One value's run (run_all, no file) and what the sweep keeps of it. */
static enum sw_status run_value(const struct mc_config *cfg, struct point *p,
				int k, int nval, char *err)
{
	struct sweep_tick st = {k, nval, cfg->n};
	struct tally t;
	tally_init(&t, cfg->w);
	enum sw_status rc = run_all(cfg, &t, NULL, NULL,
				    isatty(STDERR_FILENO) ? tick : NULL, &st,
				    err);
	p->samples = t.samples;
	p->accepted = t.accepted;
	p->mechanisms = t.nmech;
	struct family_set fs;
	family_set_init(&fs, cfg->w);
	family_update(&fs, &t);
	p->families = fs.nfam;
	family_set_free(&fs);
	tally_summary(&t, &p->s);
	tally_free(&t);
	return rc;
}

/* ---- output --------------------------------------------------------------- */

static const char *param_name(enum sweep_param p)
{
	return p == SW_FRICTION ? "friction" : p == SW_COV ? "cov" :
	       p == SW_DEPTH ? "depth" : "load_at";
}

static void print_table(const struct sweep_args *a, const struct wall *w,
			const struct point *pt, unsigned long seed, long n)
{
	/* names, paths and override values are the user's: their control
	 * characters printed as escapes (cli_text) */
	printf("%s  [%s]\n", cli_text(w->name ? w->name : a->wall),
	       cli_text(a->wall));
	if (a->ov.n > 0) {
		char d[1024];
		override_describe(&a->ov, d, sizeof d);
		printf("overrides: %s\n", cli_text(d));
	}
	char count[64];
	if (a->nval < a->asked)
		snprintf(count, sizeof count, "%d of %d", a->nval, a->asked);
	else
		snprintf(count, sizeof count, "%d", a->nval);
	printf("sweep of %s %s: %s values, %ld samples each, seed %lu (the "
	       "same contact draws at every value)\n\n", param_name(a->param),
	       cli_text(a->range), count, n, seed);
	struct wall_quantity q;
	wall_quantity(w, &q);
	printf("loads: %s\n\n", q.what);
	if (a->param == SW_LOAD_AT)
		printf("%-10s %-10s %-10s", "distance", "x", "y");
	else
		printf("%-10s", param_name(a->param));
	printf(" %-9s %-11s %-25s %-11s %-11s %-10s %s\n", "accepted", "p05",
	       "99 % interval of p05", "p50", "p95", "mechanisms", "families");
	for (int k = 0; k < a->nval; k++) {
		const struct point *p = &pt[k];
		char ci[64];
		if (p->s.has_ci)
			snprintf(ci, sizeof ci, "[%.5g, %.5g]", p->s.p05_lo,
				 p->s.p05_hi);
		else
			snprintf(ci, sizeof ci, "- (n < 90)");
		if (a->param == SW_LOAD_AT)
			printf("%-10.4g %-10.4g %-10.4g", p->value, p->at[0],
			       p->at[1]);
		else
			printf("%-10.4g", p->value);
		/* a value with no accepted sample has no load: "-" */
		char q[3][32];
		const double v[3] = { p->s.p05, p->s.p50, p->s.p95 };
		for (int i = 0; i < 3; i++)
			text_num(q[i], sizeof q[i], v[i], 5);
		printf(" %-9ld %-11s %-25s %-11s %-11s %-10d %d\n",
		       p->accepted, q[0], ci, q[1], q[2], p->mechanisms,
		       p->families);
	}
}

static void print_json(const struct sweep_args *a, const struct wall *w,
		       const struct point *pt, unsigned long seed, long n)
{
	struct wall_quantity q;
	wall_quantity(w, &q);
	struct json j;
	json_init(&j, stdout, 1);
	json_object_begin(&j);
	json_key(&j, "wall");
	json_string(&j, a->wall);
	json_key(&j, "parameter");
	json_string(&j, param_name(a->param));
	json_key(&j, "range");
	json_string(&j, a->range);
	tally_quantity_json(&j, &q);
	override_json(&a->ov, &j);
	json_key(&j, "seed");
	json_uint(&j, seed);
	json_key(&j, "samples");
	json_int(&j, n);
	json_key(&j, "points");
	json_array_begin(&j);
	for (int k = 0; k < a->nval; k++) {
		const struct point *p = &pt[k];
		json_object_begin(&j);
		json_key(&j, "value");
		json_double(&j, p->value);
		if (a->param == SW_LOAD_AT) {
			json_key(&j, "at");
			json_array_begin(&j);
			json_double(&j, p->at[0]);
			json_double(&j, p->at[1]);
			json_array_end(&j);
		}
		json_key(&j, "samples");
		json_int(&j, p->samples);
		json_key(&j, "accepted");
		json_int(&j, p->accepted);
		json_key(&j, "p05");
		json_double(&j, p->s.p05);
		json_key(&j, "p05_ci99");
		if (p->s.has_ci) {
			json_array_begin(&j);
			json_double(&j, p->s.p05_lo);
			json_double(&j, p->s.p05_hi);
			json_array_end(&j);
		} else {
			json_null(&j);
		}
		json_key(&j, "p50");
		json_double(&j, p->s.p50);
		json_key(&j, "p95");
		json_double(&j, p->s.p95);
		json_key(&j, "mechanisms");
		json_int(&j, p->mechanisms);
		json_key(&j, "families");
		json_int(&j, p->families);
		json_object_end(&j);
	}
	json_array_end(&j);
	json_object_end(&j);
	json_end(&j);
}

/* --csv's header and one value's row (full precision). */
static void csv_header(FILE *f, const struct sweep_args *a)
{
	fprintf(f, "%s,%ssamples,accepted,p05,p05_lo,p05_hi,p50,p95,"
		"mechanisms,families\n", a->param == SW_LOAD_AT ? "distance" :
		param_name(a->param), a->param == SW_LOAD_AT ? "x,y," : "");
}

static void csv_row(FILE *f, const struct sweep_args *a,
		    const struct point *p)
{
	fprintf(f, "%.17g,", p->value);
	if (a->param == SW_LOAD_AT)
		fprintf(f, "%.17g,%.17g,", p->at[0], p->at[1]);
	fprintf(f, "%ld,%ld,%.17g,%.17g,%.17g,%.17g,%.17g,%d,%d\n",
		p->samples, p->accepted, p->s.p05, p->s.p05_lo, p->s.p05_hi,
		p->s.p50, p->s.p95, p->mechanisms, p->families);
}

/* --csv opened (outfile.h: never over the wall, a file into
 * FILE.tmp, a stream directly) and its header written.  0, or 1 after
 * the message. */
static int csv_open(const struct sweep_args *a, struct outfile *o)
{
	const char *in[] = {a->wall, NULL};
	char err[SW_ERRLEN];
	if (outfile_open(o, a->csv, in, OUTFILE_STREAM, "the CSV", err) !=
	    SW_OK) {
		cli_errorf("slipwall sweep: %s", err);
		return 1;
	}
	csv_header(o->f, a);
	return 0;
}

/* --csv closed: a file renamed over FILE (a full disk, or a row that
 * could not be written, leaves the old file).  0, or 1 after the
 * message. */
static int csv_commit(struct outfile *o)
{
	char err[SW_ERRLEN];
	if (outfile_commit(o, err) != SW_OK) {
		cli_errorf("slipwall sweep: %s", err);
		return 1;
	}
	return 0;
}

/* --csv FILE, a file: opened before the first value, so that each
 * value's row goes into FILE.tmp as the value finishes (flushed: a
 * SIGKILL, an out-of-memory kill or a lost machine leaves every value
 * done in FILE.tmp, the old FILE as it was), and renamed over FILE
 * when the sweep ends (csv_commit).  A stream (a FIFO, /dev/stdout) is
 * written after the table instead (write_csv), so that `--csv
 * /dev/stdout` keeps the CSV after it and a FIFO is not opened, and
 * waited on, before the sampling.  0 with o->f NULL for a stream or no
 * --csv, 0 with o open, or 1 after the message. */
static int csv_open_rows(const struct sweep_args *a, struct outfile *o)
{
	memset(o, 0, sizeof *o);
	if (!a->csv || outfile_is_stream(a->csv))
		return 0;
	if (csv_open(a, o))
		return 1;
	outfile_flush(o);
	return 0;
}

/* --csv into a stream, after the table: the values done. */
static int write_csv(const struct sweep_args *a, const struct point *pt)
{
	struct outfile o;
	if (csv_open(a, &o))
		return 1;
	for (int k = 0; k < a->nval; k++)
		csv_row(o.f, a, &pt[k]);
	return csv_commit(&o);
}

/* --out: the figure, its formats cancelled by a signal when cancel is
 * set (report.h). */
static int write_figure(const struct sweep_args *a, const struct wall *w,
			const struct point *pt, unsigned long seed, long n,
			int cancel)
{
	struct report_sweep_point *rp = sw_xmalloc(sizeof *rp *
						   (size_t)a->nval);
	for (int k = 0; k < a->nval; k++) {
		rp[k] = (struct report_sweep_point){
			pt[k].value, pt[k].accepted, pt[k].s.p05,
			pt[k].s.has_ci ? pt[k].s.p05_lo : NAN,
			pt[k].s.has_ci ? pt[k].s.p05_hi : NAN,
			pt[k].s.p50, pt[k].s.p95};
	}
	char xlabel[160], cap[512];
	if (a->param == SW_FRICTION)
		snprintf(xlabel, sizeof xlabel, "friction coefficient μ");
	else if (a->param == SW_COV)
		snprintf(xlabel, sizeof xlabel, "friction's coefficient of "
			 "variation");
	else if (a->param == SW_DEPTH)
		snprintf(xlabel, sizeof xlabel, "imperfection depth d");
	else
		snprintf(xlabel, sizeof xlabel, "load point: distance from "
			 "(%g, %g) towards (%g, %g), m", pt[0].at[0],
			 pt[0].at[1], pt[a->nval - 1].at[0],
			 pt[a->nval - 1].at[1]);
	snprintf(cap, sizeof cap, "%s: %ld samples per value, seed %lu, the "
		 "same contact draws at every value.", w->name ? w->name :
		 a->wall, n, seed);
	struct report_sweep rs = {w, xlabel, cap, sw_version(), rp,
				  a->nval};
	char err[SW_ERRLEN];
	struct report_opts ro;
	report_opts_default(&ro);
	ro.cancel = cancel ? run_signal_flag() : NULL;
	enum sw_status st = report_write_sweep(&rs, a->out, &ro, err);
	free(rp);
	report_cleanup();
	if (st != SW_OK) {
		cli_errorf("slipwall sweep: %s", err);
		return 1;
	}
	if (!a->json)
		printf("\n%s/sweep.svg, .pdf, .png: p05 with its 99 %% interval, "
		       "p50 and p95 against the %s\n", cli_text(a->out),
		       param_name(a->param));
	return 0;
}

/* ---- the command -------------------------------------------------------------- */

/* The outputs, before any sampling (the output policy, outfile.h):
 * --csv a file (written whole) or a stream, --out a directory or one
 * that can be made; neither the wall.  0 or the exit status. */
static int check_outputs(const struct sweep_args *a)
{
	const char *in[] = {a->wall, NULL};
	char err[SW_ERRLEN];
	enum sw_status st = SW_OK;
	if (a->csv)
		st = outfile_check(a->csv, in, OUTFILE_STREAM, "the CSV", err);
	if (st == SW_OK && a->out)
		st = outfile_check_dir(a->out, report_files(1), in,
				       "the figure", err);
	if (st != SW_OK)
		cli_errorf("slipwall sweep: %s", err);
	return sw_status_exit(st);
}

/* "value 4 of 5 (--load-at 0,1.325)", for the messages. */
static void value_name(const struct sweep_args *a, int k, char *buf,
		       size_t len)
{
	if (a->param == SW_LOAD_AT)
		snprintf(buf, len, "value %d of %d (--load-at %.6g,%.6g)", k + 1,
			 a->nval, a->at[k][0], a->at[k][1]);
	else
		snprintf(buf, len, "value %d of %d (--%s %.6g)", k + 1, a->nval,
			 param_name(a->param), a->val[k]);
}

/* Run the values in order until the last, a signal or a failure.
 * *done: the values finished (pt[0..*done)), *failed: those of them
 * without an accepted sample.  rows: --csv's file when it is open
 * (rows->f), which gets each value's row as it finishes
 * (csv_open_rows).  Returns 0, or the exit status of the
 * failure after its message: 2 when a value makes the wall invalid (a
 * load point off the wall), 1 when its run failed. */
static int sample_values(const struct sweep_args *a, unsigned long seed,
			 long n, struct point *pt, struct outfile *rows,
			 int *done, int *failed)
{
	char what[160], err[SW_ERRLEN];
	int rc = 0;
	*done = *failed = 0;
	for (int k = 0; k < a->nval; k++) {
		struct wall *w = NULL;
		memset(&pt[k], 0, sizeof pt[k]);
		pt[k].value = a->val[k];
		if (a->at) {
			pt[k].at[0] = a->at[k][0];
			pt[k].at[1] = a->at[k][1];
		}
		value_name(a, k, what, sizeof what);
		if ((rc = wall_for(a, k, &w))) {
			/* wall_for said why, FILE: what is wrong */
			cli_errorf("slipwall sweep: %s: the wall is invalid "
				   "there (above)", what);
			break;
		}
		struct mc_config cfg;
		mc_config_default(&cfg, w);
		cfg.opts.lp = cli_lp;
		cfg.n = n;
		cfg.seed = seed;
		cfg.threads = a->threads ? a->threads : mc_ncpu();
		cfg.depth = a->param == SW_DEPTH ? a->val[k] : -1;
		enum sw_status vs = run_value(&cfg, &pt[k], k, a->nval, err);
		wall_free(w);
		if (vs == SW_EINTR)
			break;
		if (vs != SW_OK) {
			cli_errorf("slipwall sweep: %s: %s", what, err);
			rc = 1;
			break;
		}
		*failed += pt[k].accepted == 0;
		++*done;
		if (rows->f) {
			/* a failed write shows at the commit */
			csv_row(rows->f, a, &pt[k]);
			outfile_flush(rows);
		}
	}
	if (isatty(STDERR_FILENO))
		fprintf(stderr, "\r\033[K");
	return rc;
}

/* The values done (a->nval of them): the table or the JSON, --csv (a
 * file whose rows are written, rows->f set, is renamed into place; a
 * stream is written now), the figure (cancelled between two formats by
 * a signal when cancel is set).  0, or 1 after the message. */
static int write_outputs(const struct sweep_args *a, const struct wall *base,
			 const struct point *pt, unsigned long seed, long n,
			 struct outfile *rows, int cancel)
{
	if (a->json)
		print_json(a, base, pt, seed, n);
	else
		print_table(a, base, pt, seed, n);
	fflush(stdout);
	int rc = 0;
	if (rows->f)
		rc = csv_commit(rows);
	else if (a->csv)
		rc = write_csv(a, pt);
	if (!rc && a->out)
		rc = write_figure(a, base, pt, seed, n, cancel);
	return rc;
}

int cmd_sweep(int argc, char **argv)
{
	struct sweep_args a;
	int rc = parse_args(argc, argv, &a);
	if (rc) {
		args_free(&a);
		return rc < 0 ? 0 : rc;
	}
	struct wall *base = NULL;
	if ((rc = override_load(CMD, a.wall, &a.ov, &base))) {
		args_free(&a);
		return rc;
	}
	if ((rc = cli_check_depth(CMD, base, a.wall,
				  a.param == SW_DEPTH ? 0 : -1)) ||
	    (rc = check_outputs(&a)))
		goto out;
	unsigned long seed = a.seed_set ? a.seed : base->seed;
	long n = a.n_set ? a.n : base->samples;
	struct point *pt = sw_xmalloc(sizeof *pt * (size_t)a.nval);
	int failed, done, nval = a.nval;
	/* SIGINT, SIGTERM, SIGHUP (run.h's one policy), to the end: during
	 * the sampling the value being run is dropped and the values done
	 * are written (the figure too); during the writing the table and
	 * the CSV are finished and the figure is not drawn (the formats
	 * drawn are whole).  Exit 1 either way, with a message. */
	struct outfile rows;
	if ((rc = csv_open_rows(&a, &rows))) {
		free(pt);
		goto out;
	}
	struct run_signals caught;
	run_signals_catch(&caught, 1);
	rc = sample_values(&a, seed, n, pt, &rows, &done, &failed);
	int intr = run_signal();
	a.nval = done;	/* the values done, each whole */
	if (a.out && done < 2 && done < nval) {
		fprintf(stderr, "slipwall sweep: no figure: fewer than two "
			"values were done\n");
		a.out = NULL;
	}
	/* nothing to write when the first value failed; an interrupted
	 * sweep says what it did, even nothing */
	int wrc = 0;
	if (done > 0 || intr)
		wrc = write_outputs(&a, base, pt, seed, n, &rows, !intr);
	else if (rows.f)
		outfile_abort(&rows);	/* no CSV, as the first value failed */
	int late = intr ? 0 : run_signal();
	run_signals_restore(&caught);
	if (rc && done > 0 && !wrc)
		fprintf(stderr, "slipwall sweep: the %d value%s before it %s "
			"written\n", done, done == 1 ? "" : "s",
			done == 1 ? "is" : "are");
	if (!rc)
		rc = wrc;
	if (!rc && failed) {
		fprintf(stderr, "slipwall sweep: %d value%s gave no accepted "
			"sample\n", failed, failed > 1 ? "s" : "");
		rc = 1;
	}
	if (intr) {
		fprintf(stderr, "slipwall sweep: interrupted (%s): the %d "
			"value%s done %s written\n", strsignal(intr), done,
			done == 1 ? "" : "s", done == 1 ? "is" : "are");
		rc = sw_status_exit(SW_EINTR);
	} else if (late) {
		fprintf(stderr, "slipwall sweep: interrupted (%s) while "
			"writing: every file written holds the %d values, "
			"whole\n", strsignal(late), done);
		rc = sw_status_exit(SW_EINTR);
	}
	free(pt);
out:
	wall_free(base);
	args_free(&a);
	return rc;
}
