/*
 * tui_pace.c - the time left of a sampling run, for the statistics
 * pane (docs/workbench.md, "Time left").
 *
 * On a large wall a sample takes minutes, and a bound such as "each
 * worker takes at least as long as its oldest sample" only grows while
 * the first samples run ("> 53 s", "> 14:08", "> 35:10" when the run
 * takes five hours).  So the pane shows an estimate instead: the
 * a-priori time of a sample (mc_sample_seconds) counted as w samples
 * already taken, blended with the worker-seconds the finished samples
 * took:
 *
 *   w    = max(0, 1 - d / P),  P = min(T, N)
 *   s    = (w e0 + (E T - A)) / (w + d)   seconds of one sample
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
 *
 * Why w fades: e0 was fitted to a worker's first sample with its
 * workspace's set-up on a loaded machine (mc.c), which on
 * walls/large.yaml is 10 to 40 times a later sample.  Counted as one
 * sample for the whole run it kept the total several times too long
 * for the first hundreds of samples (by docs/performance.md's figures,
 * a 23 s set-up and 9.2 s a sample on an idle core: about 4 times the
 * true total after 75 s on two threads, the bound of
 * tests/tui/tui_pace_large.sh being 3); once every worker
 * has finished a sample (d >= P), the measured time, set-ups included,
 * is the better figure, and it only falls as they are amortised.
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
	double P = fmin(T, N);
	double w = d < P ? 1 - d / P : 0;
	double s = (w * e0 + spent) / (w + d);
	double work = (N - d) * s - fmin(pg.total, pg.busy * s);
	double par = fmin(T, N - d);
	*left = fmax(0, work) / (par > 0 ? par : 1);
	*total = E + *left;
	return r->done > 0 ? 2 : 1;
}
