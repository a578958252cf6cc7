/*
 * cmd_solve.c - `slipwall solve WALL --method standard|gilbert|global`:
 * one solution on the classical contact, with its mechanism.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "cli.h"
#include "cli_opts.h"
#include "slipwall/json.h"
#include "slipwall/solve.h"
#include "slipwall/tally.h"

static const char *method_text[] = {
	"standard (associative limit analysis)",
	"gilbert (stabilised sequential LP, Gilbert, Casapulla & Ahmed 2006)",
	"global (mixed-integer program, global minimum of the non-associative problem)",
};

static const char *joint_text(char c)
{
	switch (c) {
	case JOINT_SLIDES: return "slides";
	case JOINT_HINGES: return "hinges";
	case JOINT_HINGE_SLIDES: return "hinges and slides";
	case JOINT_OPENS: return "opens";
	default: return "closed";
	}
}

/* The load people read for a load factor (wall_quantity): the force
 * in N, or NaN when the wall's loads give no force. */
static double newtons(const struct wall *w, double lambda)
{
	struct wall_quantity q;
	wall_quantity(w, &q);
	return *q.unit ? q.scale * lambda : NAN;
}

static int moving(const struct sample_result *m, int b)
{
	return fabs(m->vel[3 * b]) + fabs(m->vel[3 * b + 1]) +
		       fabs(m->vel[3 * b + 2]) > 1e-6;
}

/* The JSON of a solve.  error: NULL when the solve gave a load (the key
 * is null), else why there is none (the message stderr has too): a
 * script reads `status` and `error` from the same object either way
 * (docs/run.md, "solve --json"). */
static void print_json(const struct wall *w, const struct solve_result *r,
		       const char *error)
{
	struct json j;
	json_init(&j, stdout, 1);
	json_object_begin(&j);
	json_key(&j, "method");
	json_string(&j, solve_method_name(r->method));
	json_key(&j, "status");
	json_string(&j, sample_status_name(r->status));
	json_key(&j, "error");
	if (error)
		json_string(&j, error);
	else
		json_null(&j);
	cli_json_warnings(&j, w);
	json_key(&j, "load_factor");
	json_double(&j, r->lambda);
	json_key(&j, "load_newtons");
	json_double(&j, newtons(w, r->lambda));
	/* what `run --json` gives its loads in (wall_quantity): a body-loaded
	 * wall's seismic coefficient is scale * lambda, and no unit */
	struct wall_quantity q;
	wall_quantity(w, &q);
	tally_quantity_json(&j, &q);
	json_key(&j, "load_value");
	json_double(&j, q.scale * r->lambda);
	if (r->method == SOLVE_GILBERT) {
		/* which of the two loads is the method's answer */
		json_key(&j, "result");
		json_string(&j, "load_factor");
		json_key(&j, "iterations");
		json_int(&j, r->iterations);
		json_key(&j, "converged");
		json_bool(&j, r->converged);
		json_key(&j, "onset_load_factor");
		json_double(&j, r->lambda_onset);
	}
	if (r->method == SOLVE_GLOBAL) {
		json_key(&j, "proven_optimal");
		json_bool(&j, r->proven);
		json_key(&j, "lower_bound");
		json_double(&j, r->lower_bound);
		json_key(&j, "bounds_derived");
		json_bool(&j, r->bounds_derived);
		json_key(&j, "gap");
		json_double(&j, r->gap);
	}
	json_key(&j, "seconds");
	json_double(&j, r->seconds);
	/* no_equilibrium, unstable, nonpositive: the blocks the least
	 * outside help acts on (docs/run.md, "solve --json"), the first
	 * SOLVE_UNHELD of them */
	json_key(&j, "unheld_blocks");
	if (!r->nunheld) {
		json_null(&j);
	} else {
		json_array_begin(&j);
		for (int i = 0; i < r->nunheld && i < SOLVE_UNHELD; i++)
			json_string(&j, w->blocks[r->unheld[i]].id);
		json_array_end(&j);
	}
	json_key(&j, "unheld_count");
	json_int(&j, r->nunheld);
	json_key(&j, "mechanism");
	if (!r->has_mechanism) {
		json_null(&j);
	} else {
		json_object_begin(&j);
		json_key(&j, "blocks");
		json_array_begin(&j);
		for (int b = 0; b < w->nblocks; b++) {
			if (w->blocks[b].fixed)
				continue;
			json_object_begin(&j);
			json_key(&j, "id");
			json_string(&j, w->blocks[b].id);
			json_key(&j, "u");
			json_double(&j, r->mech.vel[3 * b]);
			json_key(&j, "v");
			json_double(&j, r->mech.vel[3 * b + 1]);
			json_key(&j, "omega");
			json_double(&j, r->mech.vel[3 * b + 2]);
			json_key(&j, "moving");
			json_bool(&j, moving(&r->mech, b));
			json_object_end(&j);
		}
		json_array_end(&j);
		json_key(&j, "joints");
		json_string(&j, r->mech.joint);
		json_object_end(&j);
	}
	json_object_end(&j);
	json_end(&j);
}

/* Under associative flow a joint that slides also lifts: both points
 * open by mu |dt| (an opening beyond it is a separation), so the joint
 * string says `o` where the joint slides.  Say so in words. */
static int assoc_slide(const struct wall *w, const struct sample_result *m,
		       int k)
{
	double mu = wall_iface_mu(w, k), dt = fabs(m->dt[k]);
	if (m->joint[k] != JOINT_OPENS || !(dt > 1e-6))
		return 0;
	for (int e = 0; e < 2; e++)
		if (fabs(m->dn[2 * k + e] - mu * dt) > 1e-6 * fmax(1, mu * dt))
			return 0;
	return 1;
}

static void print_text(const struct wall *w, const struct solve_result *r)
{
	struct wall_quantity q;
	wall_quantity(w, &q);
	printf("method:      %s\n", method_text[r->method]);
	printf("load factor: %.6g", r->lambda);
	if (*q.unit)
		printf("  (%s %.6g N)", q.name, q.scale * r->lambda);
	else if (q.scale != 1)
		printf("  (%s %.6g)", q.name, q.scale * r->lambda);
	printf("\n");
	if (r->method == SOLVE_GILBERT) {
		printf("             the result: the load of the converged "
		       "sequential LP\n");
		printf("iterations:  %d (%s)\n", r->iterations,
		       r->converged ? "converged" : "NOT converged");
		if (r->status == SAMPLE_ACCEPTED)
			printf("onset check: mechanism found; the least load that "
			       "keeps it is %.6g\n"
			       "             (a check of the mechanism, not the "
			       "result; a Monte Carlo sample\n"
			       "             reports this load as its lambda_min)\n",
			       r->lambda_onset);
		else
			printf("onset check: %s\n", sample_status_text(r->status));
	}
	if (r->method == SOLVE_GLOBAL) {
		printf("checked:     mechanism and load by exact LPs; the "
		       "program's bound %.6g\n", r->lower_bound);
		if (r->proven)
			printf("optimality:  proven (gap 0)\n");
		else
			printf("optimality:  NOT proven (%s; gap %.3g)\n",
			       !r->bounds_derived ? "big-M bounds are a fallback"
			       : !r->mip_optimal ? "time limit"
			       : "the program's optimum is below the exact load:"
				 " the LP solver's tolerances", r->gap);
	}
	printf("time:        %.3f s\n", r->seconds);
	if (!r->has_mechanism)
		return;
	int nmov = 0, count[128] = {0};
	for (int b = 0; b < w->nblocks; b++)
		nmov += !w->blocks[b].fixed && moving(&r->mech, b);
	for (int k = 0; k < w->nifaces; k++)
		count[(unsigned char)r->mech.joint[k] & 127]++;
	printf("mechanism:   %d of %d blocks move; joints: %d slide, %d hinge, %d hinge and slide, %d open\n",
	       nmov, w->nfree, count[JOINT_SLIDES], count[JOINT_HINGES],
	       count[JOINT_HINGE_SLIDES], count[JOINT_OPENS]);
	printf("\n%-10s %10s %10s %10s   (velocities, largest = 1)\n", "block",
	       "u", "v", "omega*L");
	for (int b = 0; b < w->nblocks; b++)
		if (!w->blocks[b].fixed && moving(&r->mech, b))
			printf("%-10s %10.4f %10.4f %10.4f\n", cli_text(w->blocks[b].id),
			       r->mech.vel[3 * b], r->mech.vel[3 * b + 1],
			       r->mech.vel[3 * b + 2] * w->mean_size);
	printf("\n%-5s %-10s %-10s %s\n", "#", "a", "b", "joint");
	for (int k = 0; k < w->nifaces; k++)
		if (r->mech.joint[k] != JOINT_CLOSED)
			printf("%-5d %-10s %-10s %s\n", k + 1,
			       cli_text(w->blocks[w->ifaces[k].a].id),
			       cli_text(w->blocks[w->ifaces[k].b].id),
			       r->method == SOLVE_STANDARD &&
			       assoc_slide(w, &r->mech, k) ?
			       "slides and lifts (opens by mu |slip|: "
			       "associative flow)" :
			       joint_text(r->mech.joint[k]));
}

/* The mixed-integer program has four binaries per interface (two of
 * slip, two of opening).  Measured: walls of up to GLOBAL_PROVEN_BLOCKS
 * free blocks (report.c runs global up to the same size) are proven
 * within seconds; the 36-block demo wall and Ferris & Tin-Loi wall 1
 * (33 blocks) find no solution in 60 s.  So say it before the wait, not
 * after it; and the best bound while it works (solve_progress). */
#define GLOBAL_PROVEN_BLOCKS 12

static void global_forecast(const char *path, const struct wall *w,
			    double tlim)
{
	if (w->nfree <= GLOBAL_PROVEN_BLOCKS)
		return;
	fprintf(stderr, "slipwall solve: %s has %d free blocks and %d "
		"interfaces (%d binary variables): most likely beyond what the "
		"mixed-integer program can prove within %g s (it proves walls "
		"of up to about %d blocks in seconds; the bundled 33- and "
		"36-block walls find no solution in 60 s).  It runs until the "
		"time limit, then prints the best load it found, not proven, "
		"or says it found none.\n", path, w->nfree, w->nifaces,
		4 * w->nifaces, tlim, GLOBAL_PROVEN_BLOCKS);
	fflush(stderr);
}

/* Progress on stderr (solve_opts.progress).  On a terminal one line,
 * rewritten in place about once a second: what is being solved, the
 * elapsed time and, in global's mixed-integer program, the incumbent and
 * the best bound.  Elsewhere (a log, a pipe) only the bound lines, at
 * most one a second: a long simplex says nothing there. */
struct solve_progress {
	const char *path, *method;
	int tty;
	int shown;		/* a line is on the terminal */
	double last;		/* seconds of the last line */
};

static void solve_progress(void *ctx, const char *what, double seconds,
			   double incumbent, double bound)
{
	struct solve_progress *p = ctx;
	int mip = isfinite(bound);
	if ((!p->tty && !mip) || (p->shown && seconds - p->last < 1))
		return;
	p->last = seconds;
	p->shown = 1;
	fprintf(stderr, "%sslipwall solve: %s: %s: solving %s, %.0f s",
		p->tty ? "\r" : "", p->method, p->path, what, seconds);
	if (mip) {
		fprintf(stderr, ", best bound %.6g", bound);
		if (isfinite(incumbent))
			fprintf(stderr, ", incumbent %.6g", incumbent);
		else
			fprintf(stderr, ", no incumbent yet");
	}
	fprintf(stderr, p->tty ? "\033[K" : "\n");
	fflush(stderr);
}

static void usage(FILE *f)
{
	fprintf(f,
		"usage: slipwall solve WALL.yaml --method standard|gilbert|global\n"
		"                     [--time-limit SECONDS] [--json]\n"
		"\n"
		"One solution on the classical contact (points at the interface ends):\n"
		"  standard  associative limit analysis (an upper value, may be unsafe)\n"
		"  gilbert   the stabilised sequential LP started from the standard\n"
		"            solution; its result is the converged load (the load\n"
		"            factor); the onset check's least load keeping the\n"
		"            mechanism is printed too, as a check\n"
		"  global    the global minimum of the non-associative problem by a\n"
		"            mixed-integer program (small walls); its collapse pattern\n"
		"            is checked and its load found by exact LPs; says the\n"
		"            program's bound and whether optimality was proven; says\n"
		"            first when the wall is larger than it can prove within\n"
		"            the time limit\n"
		"On a terminal, stderr shows what is being solved and the elapsed\n"
		"time; global prints its best bound there about once a second.\n"
		"Prints the load factor (and the load in N for a point load) and the\n"
		"mechanism.  Exit status 1 when there is no finite collapse load.\n");
}

/* --method NAME into an int (enum solve_method). */
static int opt_method(const char *cmd, const char *name, const char *v,
		      void *dst)
{
	(void)name;
	if ((*(int *)dst = solve_method_parse(v)) < 0)
		return cli_usage_error(cmd, "unknown method '%s' (standard, "
				       "gilbert or global)", v);
	return 0;
}

int cmd_solve(int argc, char **argv)
{
	int json = 0, method = -1;
	double tlim = 60;
	const char *path;
	const struct cli_opt opts[] = {
		CLI_OPT_SWITCH("--json", json),
		{ .name = "--method", .alias = "-m", .kind = CLI_OPT_CALL,
		  .dst = &method, .call = opt_method },
		{ .name = "--time-limit", .kind = CLI_OPT_TIME, .dst = &tlim },
	};
	static const struct cli_cmd cmd = {
		.name = "solve", .usage = usage, .posix = 1,
		.no_wall = "expected one wall file",
		.unknown = "unknown option or missing value: '%s'",
	};
	int rc = cli_opts_parse(&cmd, opts, sizeof opts / sizeof *opts, argc,
				argv, &path);
	if (rc)
		return rc < 0 ? 0 : rc;
	if (method < 0)
		return cli_usage_error("solve",
				       "--method is required (standard, gilbert or global)");
	struct wall *w;
	if ((rc = cli_load_wall(path, &w)))
		return rc;
	if (method == SOLVE_GLOBAL)
		global_forecast(path, w, tlim);
	struct solve_opts o;
	solve_opts_default(&o, (enum solve_method)method);
	o.sample.lp = cli_lp;
	o.time_limit = tlim;
	struct solve_progress prog = {
		path, solve_method_name(o.method), isatty(2), 0, 0,
	};
	o.progress = solve_progress;
	o.progress_ctx = &prog;
	struct solve_result r;
	char err[SW_ERRLEN];
	enum sw_status st = solve_run(w, &o, &r, err);
	if (prog.tty && prog.shown)
		fputs("\r\033[K", stderr);	/* the line goes */
	if (st != SW_OK) {
		char lock[512], why[SW_ERRLEN + 512];
		if (r.status == SAMPLE_UNBOUNDED &&
		    wall_friction_lock_text(w, lock, sizeof lock))
			/* not a support: the lock (docs/method.md, "What the
			 * method cannot answer") */
			snprintf(why, sizeof why, "the load factor is "
				 "unbounded: %s lock under associative "
				 "friction, so this is not the wall's answer: "
				 "it may rock or slide at a finite load", lock);
		else
			snprintf(why, sizeof why, "%s", err);
		cli_errorf("%s: %s", path, why);
		/* a verdict on the wall (unbounded, cannot stand, ...) is an
		 * answer a script reads too */
		if (json && st == SW_EANALYSIS)
			print_json(w, &r, why);
		rc = sw_status_exit(st);
	} else {
		if (json)
			print_json(w, &r, NULL);
		else
			print_text(w, &r);
		if (method == SOLVE_GILBERT && !r.converged) {
			fprintf(stderr, "%s: the sequential LP did not converge in %d iterations\n",
				cli_text(path), r.iterations);
			rc = 1;
		}
	}
	solve_result_free(&r);
	wall_free(w);
	return rc;
}
