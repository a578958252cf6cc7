/*
 * solve.c - standard, gilbert and global solutions; see solve.h.
 *
 * standard and gilbert are the sampler's own LPs at the classical contact
 * points (xi = 0 and 1), so they share every line of code with a sample.
 *
 * global is a mixed-integer program over statics and kinematics at
 * once, whose solution is read as a collapse pattern and checked by
 * exact LPs (global.c).  The LPs all belong to the sample workspace
 * (sample.h), which owns the LP solver: nothing here names it.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "global.h"
#include "slipwall/solve.h"
#include "slipwall/sys.h"
#include "statics.h"

static const char *method_names[] = {"standard", "gilbert", "global"};

void solve_opts_default(struct solve_opts *o, enum solve_method m)
{
	memset(o, 0, sizeof *o);
	o->method = m;
	o->time_limit = 60;
	sample_opts_default(&o->sample);
}

int solve_method_parse(const char *name)
{
	for (int i = 0; i < 3; i++)
		if (!strcmp(name, method_names[i]))
			return i;
	return -1;
}

const char *solve_method_name(enum solve_method m)
{
	return (unsigned)m < 3 ? method_names[m] : "?";
}

void solve_result_free(struct solve_result *r)
{
	sample_result_free(&r->mech);
}

/* A message for m's verdict, one that leaves no load factor: for
 * `nonpositive`, LP-max's load factor, or the SLP's where it reached
 * one (m->lambda_max not NaN). */
static enum sw_status failure(const struct sample_result *m, char *err)
{
	enum sample_status s = m->status;
	switch (s) {
	case SAMPLE_UNBOUNDED:
		return sw_fail(err, SW_EANALYSIS,
			       "the load factor is unbounded: the live load pushes against a support or a block that cannot move, so no mechanism can form");
	case SAMPLE_NO_EQUILIBRIUM:
		return sw_fail(err, SW_EANALYSIS,
			       "the wall cannot stand under its own weight: no contact forces hold the blocks in equilibrium, at any load");
	case SAMPLE_UNSTABLE:
		return sw_fail(err, SW_EANALYSIS,
			       "the wall cannot stand under its own weight");
	case SAMPLE_NONPOSITIVE:
		if (!isnan(m->lambda_max))
			return sw_fail(err, SW_EANALYSIS,
				       "the wall carries no positive live load "
				       "once friction does not dilate: the "
				       "sequential LP's load factor is %.6g "
				       "(the associative one is above 0)",
				       m->lambda_max);
		return sw_fail(err, SW_EANALYSIS,
			       "the wall carries no positive live load: its "
			       "largest load factor is %.6g, so it collapses "
			       "under any load in this direction (zero friction "
			       "does this, or a slope steeper than the "
			       "friction)", m->lambda_lpmax);
	case SAMPLE_HANGING:
		return sw_fail(err, SW_EANALYSIS,
			       "the sequential LP lost the clamp that holds "
			       "blocks which rest on no joint, or whose weight "
			       "acts beyond the contact points they rest on: "
			       "they hang on their neighbours' friction, whose "
			       "normal forces rigid blocks leave free, so the "
			       "wall has no non-associative answer "
			       "(docs/method.md, \"What the method cannot "
			       "answer\"); the standard value is the "
			       "associative one");
	default:
		return sw_fail(err, SW_EANALYSIS, "the solver failed (%s)",
			       sample_status_text(s));
	}
}

/* After `no_equilibrium`, `unstable` or `nonpositive` (r->mech's: the
 * standard solution's are LP-max's and the standing check's, gilbert's
 * `nonpositive` its SLP's; any other verdict names none): the blocks
 * that cannot be held into r, and their names after err's message
 * (docs/method.md, "Which blocks cannot be held"). */
static void name_unheld(const struct wall *w, struct sample_ws *ws,
			struct solve_result *r, char *err)
{
	enum sample_unheld_load load;
	if (!sample_unheld_asks(&r->mech, &load))
		return;
	int n = sample_unheld(ws, load, r->unheld, SOLVE_UNHELD);
	if (n <= 0)
		return;
	r->nunheld = n;
	size_t len = strlen(err);
	const int shown = 3;
	len += (size_t)snprintf(err + len, SW_ERRLEN - len,
				"; the least outside help that lets every "
				"block stand%s acts on block%s ",
				load == SAMPLE_UNHELD_AT_REST ?
				" without the live load" :
				load == SAMPLE_UNHELD_ALONG ?
				" under a load in this direction" :
				load == SAMPLE_UNHELD_FIXED ?
				" under a load in this direction (friction "
				"that does not dilate)" : "",
				n > 1 ? "s" : "");
	for (int i = 0; i < n && i < shown && len < SW_ERRLEN; i++)
		len += (size_t)snprintf(err + len, SW_ERRLEN - len, "%s%s",
					i == 0 ? "" : i + 1 == n ? " and " : ", ",
					w->blocks[r->unheld[i]].id);
	if (n > shown && len < SW_ERRLEN)
		snprintf(err + len, SW_ERRLEN - len, " and %d other%s",
			 n - shown, n - shown > 1 ? "s" : "");
}

/* sample_lp_config.progress: the caller's, in seconds and user's units */
struct progress {
	const struct solve_opts *o;
	double t0;
	double scale;		/* the program's units to the user's */
	const char *what;	/* the step being solved */
};
static void progress(void *ctx, double incumbent, double bound)
{
	struct progress *p = ctx;
	p->o->progress(p->o->progress_ctx, p->what, sys_now() - p->t0,
		       incumbent * p->scale, bound * p->scale);
}

enum sw_status solve_run(const struct wall *w, const struct solve_opts *o,
			 struct solve_result *r, char *err)
{
	double t0 = sys_now();
	struct progress prog = { o, t0, 1, "the standard solution (LP-max)" };
	memset(r, 0, sizeof *r);
	r->method = o->method;
	r->lambda = r->lambda_onset = r->gap = r->lower_bound = NAN;
	if (o->stop && atomic_load(o->stop)) {
		r->status = SAMPLE_NUMERICAL;
		return sw_fail(err, SW_EINTR, "the solve was stopped");
	}
	sample_result_init(&r->mech, w);
	struct sample_lp_config c = o->sample.lp;
	c.stop = o->stop;
	if (o->progress) {
		c.progress = progress;
		c.progress_ctx = &prog;
	}
	struct sample_ws *ws;
	if (o->setup && sample_setup_fits(*o->setup, w, &c)) {
		ws = sample_ws_new_setup(w, &c, *o->setup);
	} else {
		ws = sample_ws_new_config(w, &c);
		struct sample_setup *s = o->setup ? sample_ws_setup(ws) : NULL;
		if (s) {
			sample_setup_free(*o->setup);
			*o->setup = s;
		}
	}
	/* the classical contact, the wall's (mean) friction */
	struct sample_draw d;
	draw_init(&d, w);
	draw_mean(&d, w);
	enum sw_status ret = SW_OK;
	/* every method starts from the standard solution */
	enum sample_status s = sample_standard(ws, &d, &r->mech);
	r->status = s;
	if (s != SAMPLE_ACCEPTED) {
		ret = failure(&r->mech, err);
		name_unheld(w, ws, r, err);
		goto out;
	}
	double lam_std = r->mech.lambda_max;
	switch (o->method) {
	case SOLVE_STANDARD:
		r->lambda = lam_std;
		r->has_mechanism = 1;
		break;
	case SOLVE_GILBERT:
		prog.what = "the sequential LP and its onset check";
		sample_run(ws, &d, &o->sample, &r->mech);
		r->status = r->mech.status;
		r->iterations = r->mech.iterations;
		r->converged = r->mech.converged;
		r->lambda = r->mech.lambda_max;
		r->lambda_onset = r->mech.lambda_min;
		r->has_mechanism = r->mech.status == SAMPLE_ACCEPTED;
		if (r->status != SAMPLE_ACCEPTED &&
		    r->status != SAMPLE_NO_MECHANISM &&
		    r->status != SAMPLE_NOT_CONVERGED) {
			/* no load: the last LP1's is not an answer (the
			 * SLP's `nonpositive` has one, at or below 0: its
			 * blocks are named as sample_run named them) */
			ret = failure(&r->mech, err);
			name_unheld(w, ws, r, err);
			r->lambda = r->lambda_onset = NAN;
		}
		break;
	case SOLVE_GLOBAL:
		ret = global_solve(w, o, ws, &d, lam_std, r, err, &prog.what,
				   &prog.scale);
		break;
	}
out:
	if (o->stop && sample_ws_interrupted(ws)) {
		/* whatever was found is incomplete (solve.h) */
		r->status = SAMPLE_NUMERICAL;
		r->lambda = r->lambda_onset = NAN;
		r->has_mechanism = 0;
		ret = sw_fail(err, SW_EINTR, "the solve was stopped");
	}
	r->seconds = sys_now() - t0;
	draw_free(&d);
	/* and the LP solver's environment of this thread goes with the
	 * workspace: callers (the batch commands' main thread, the
	 * workbench's solve thread) never see the LP layer */
	sample_ws_free(ws);
	return ret;
}
