/*
 * tui_pace.c - the time left of a sampling run, for the statistics
 * pane (docs/workbench.md, "Time left"): the run's figures handed to
 * the library's estimate (mc_pace_left; src/lib/mc.c, "Time left", says
 * how it is made and why it is an estimate rather than a bound).
 */
#include <string.h>

#include "slipwall/mc.h"
#include "tui.h"

double tui_pace_sampled(const struct tui *t)
{
	const struct tui_run *r = &t->run;
	return r->active + (r->mc ? sys_now() - r->t_start : 0);
}

double tui_pace_apriori(const struct tui *t)
{
	double e = mc_sample_seconds(t->w);
	const char *path = t->w->path ? t->w->path : "";
	/* an edit of the same wall file: the last run's measured worker
	 * seconds a sample, scaled by the a-priori figures of the two
	 * walls (a friction or depth edit keeps it; a layout edit scales it
	 * as its interfaces do).  On walls/large.yaml the a-priori figure,
	 * fitted to walls of its size under a body load, is 12 times its
	 * measured one (docs/workbench.md, "Time left"); another wall's
	 * file keeps the a-priori figure alone */
	if (t->pace_s > 0 && t->pace_apriori > 0 && !strcmp(path, t->pace_path))
		e = t->pace_s * (e / t->pace_apriori);
	return e;
}

int tui_pace_left(struct tui *t, double *left, double *total, double *per)
{
	const struct tui_run *r = &t->run;
	struct mc_pace in = {
		.threads = t->threads,
		.worked = r->worked,
		.done = (double)r->done,
		.target = (double)r->target,
		.apriori = r->apriori,
	};
	if (!tui_run_progress(t, &in.now))
		return 0;
	int how = mc_pace_left(&in, left, per);
	*total = tui_pace_sampled(t) + *left;
	return how;
}
