/*
 * tui_pace.c - the time left of a sampling run, for the statistics
 * pane (docs/workbench.md, "Time left").
 *
 * On a large wall a sample takes minutes, and a bound such as "each
 * worker takes at least as long as its oldest sample" only grows while
 * the first samples run ("> 53 s", "> 14:08", "> 35:10" when the run
 * takes five hours).  So the pane shows an estimate instead: the
 * a-priori time of a sample (mc_sample_seconds) counted as one sample
 * already taken, blended with the worker-seconds the finished samples
 * took:
 *
 *   s    = (e0 + (E T - A)) / (1 + d)     seconds of one sample
 *   left = max(0, (N - d) s - min(A, b s)) / min(T, N - d)
 *
 * e0 the a-priori seconds of a sample, E the seconds this run has
 * sampled, T the workers, A the sum of the ages of the b samples in
 * progress (mc_progress), d the samples finished, N the target.  E T - A
 * is the worker time spent on finished samples, so while no sample
 * ends s stays put, `left` falls as fast as the clock runs, and the
 * total E + left stays where it was: it moves only when a sample ends
 * (towards the measured time) or when the samples in progress have
 * outlived s (it was too low).
 */
#include <math.h>

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
	struct mc_progress pg;
	if (!tui_run_progress(t, &pg) || r->done >= r->target)
		return 0;
	double T = t->threads > 0 ? t->threads : 1;
	double E = tui_pace_sampled(t);
	double d = (double)r->done, N = (double)r->target;
	double e0 = mc_sample_seconds(t->w);
	double spent = E * T - pg.total;
	if (!(spent > 0))
		spent = 0;
	double s = (e0 + spent) / (1 + d);
	double work = (N - d) * s - fmin(pg.total, pg.busy * s);
	double par = fmin(T, N - d);
	*left = fmax(0, work) / (par > 0 ? par : 1);
	*total = E + *left;
	return r->done > 0 ? 2 : 1;
}
