/*
 * tui_pace.c - the time left of a sampling run, for the statistics
 * pane (docs/workbench.md, "Time left"): the run's figures handed to
 * the library's estimate (mc_pace_left; src/lib/mc.c, "Time left", says
 * how it is made and why it is an estimate rather than a bound).
 */
#include "slipwall/mc.h"
#include "tui.h"

double tui_pace_sampled(const struct tui *t)
{
	const struct tui_run *r = &t->run;
	return r->active + (r->mc ? sys_now() - r->t_start : 0);
}

int tui_pace_left(struct tui *t, double *left, double *total)
{
	const struct tui_run *r = &t->run;
	struct mc_pace in = {
		.threads = t->threads,
		.sampled = tui_pace_sampled(t),
		.done = (double)r->done,
		.target = (double)r->target,
		.apriori = mc_sample_seconds(t->w),
	};
	if (!tui_run_progress(t, &in.now))
		return 0;
	int how = mc_pace_left(&in, left);
	*total = in.sampled + *left;
	return how;
}
