/*
 * run.c - one Monte Carlo run: samples from a source, in index order,
 * to the samples file and the tally; --until-ci; the write-error and
 * signal policies.  See run.h; `run` (src/cli/cmd_run.c), `report`,
 * `compare` and the workbench (src/tui/tui_run.c) drive it.
 *
 * --until-ci looks at the data only at RUN_LOOK0 * 2^j accepted samples
 * (128, 256, 512, ...), look j at the level 1 - 0.01 / 2^(j+1), so that
 * the levels' shortfalls sum to at most 1 % however many looks are made
 * (Bonferroni): the interval reported at the stop, or at any other end,
 * covers p05 with probability >= 99 %.  Checking the 99 % interval after
 * every sample, as before, covered only about 98 % (issue 23;
 * docs/statistics.md, "Stopping when the interval is narrow enough").
 *
 * Signals: the handler reaches the source through run_src, the one
 * global of this file besides the signal itself; both are set by the
 * thread that caught the signals, before the handlers can see them.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "slipwall/run.h"

/* ---- the pool as a source --------------------------------------------- */

static int pool_pop(void *m, struct record *r, int wait_ms)
{
	return mc_pop(m, r, wait_ms);
}

static void pool_stop(void *m, int sig)
{
	(void)sig;
	mc_stop(m);
}

void run_source_pool(struct run_source *s, struct mc *m)
{
	s->ctx = m;
	s->pop = pool_pop;
	s->stop = pool_stop;
	s->status = NULL;
}

const char *run_stop_name(enum run_stop s)
{
	switch (s) {
	case RUN_SIGNAL:
		return "interrupted";
	case RUN_UNTIL_CI:
		return "until_ci";
	case RUN_WRITE:
		return "write_error";
	case RUN_LOST:
		return "rank_lost";
	default:
		return "complete";
	}
}

/* ---- the run ------------------------------------------------------------ */

void run_init(struct run *r, const struct wall *w, const struct run_source *src,
	      struct tally *t, struct runlog *log)
{
	memset(r, 0, sizeof *r);
	r->w = w;
	r->src = src;
	r->tally = t;
	r->log = log;
	r->stop = RUN_COMPLETE;
	r->source_status = SW_OK;
	record_init(&r->rec, w);
}

void run_free(struct run *r)
{
	record_free(&r->rec);
}

int run_p05(struct run *r, double *p05, double *lo, double *hi)
{
	const struct stats_sorted *lam = &r->tally->lam;
	struct run_ci *c = &r->ci;
	if (lam->n != c->n) {
		c->n = lam->n;
		c->ok = stats_quantile_ci_ranks(lam->n, 0.05, 0.99, &c->lo,
						&c->hi) == 0;
	}
	*p05 = stats_quantile_sorted(lam->x, lam->n, 0.05);
	if (!c->ok) {
		*lo = *hi = NAN;
		return 0;
	}
	*lo = lam->x[c->lo - 1];
	*hi = lam->x[c->hi - 1];
	return 1;
}

size_t run_look_n(int j)
{
	return (size_t)RUN_LOOK0 << j;
}

double run_look_conf(int j)
{
	return 1 - RUN_CI_ALPHA / ldexp(1, j + 1);
}

int run_until_ci_look(struct run *r, double w)
{
	const struct stats_sorted *lam = &r->tally->lam;
	if (r->looks >= RUN_LOOKS_MAX || lam->n != run_look_n(r->looks))
		return 0;
	/* the look spends its share: from now on the interval reported,
	 * here or at any later end, is at this look's level */
	double conf = run_look_conf(r->looks++);
	r->tally->ci_conf = conf;
	size_t lo, hi;
	if (stats_quantile_ci_ranks(lam->n, 0.05, conf, &lo, &hi) != 0)
		return 0;
	double p05 = stats_quantile_sorted(lam->x, lam->n, 0.05);
	return p05 > 0 && lam->x[hi - 1] - lam->x[lo - 1] < w * p05;
}

/* Stop the run for a reason of its own: the source stops handing out
 * samples, and those it still does are dropped. */
static void stop(struct run *r, enum run_stop reason)
{
	r->stop = reason;
	r->src->stop(r->src->ctx, 0);
}

int run_take(struct run *r, const struct record *rec)
{
	if (r->stop == RUN_UNTIL_CI || r->stop == RUN_WRITE)
		return -1;
	if (r->log && runlog_write(r->log, rec, r->werr) != SW_OK) {
		stop(r, RUN_WRITE);	/* the row is lost: count nothing more */
		return -1;
	}
	tally_add(r->tally, rec);
	if (r->each)
		r->each(r->each_ctx, rec);
	if (r->until_ci > 0 && rec->status == SAMPLE_ACCEPTED &&
	    run_until_ci_look(r, r->until_ci)) {
		stop(r, RUN_UNTIL_CI);
		return -1;
	}
	return 0;
}

int run_pump(struct run *r, int wait_ms)
{
	int got = r->src->pop(r->src->ctx, &r->rec, wait_ms);
	if (got > 0)
		run_take(r, &r->rec);
	return got;
}

void run_finish(struct run *r)
{
	const struct run_source *s = r->src;
	int sig = run_signal();
	r->source_status = s->status ? s->status(s->ctx, r->source_err) :
			   SW_OK;
	if (r->stop != RUN_COMPLETE)
		return;
	if (sig) {
		r->stop = RUN_SIGNAL;
		snprintf(r->why, sizeof r->why, "%s", strsignal(sig));
	} else if (r->source_status == SW_EINTR) {
		r->stop = RUN_SIGNAL;
		snprintf(r->why, sizeof r->why, "%s", r->source_err);
	} else if (r->source_status != SW_OK) {
		r->stop = RUN_LOST;
	}
}

void run_drain(struct run *r)
{
	while (run_pump(r, -1) >= 0)
		;
	run_finish(r);
}

/* ---- signals ------------------------------------------------------------ */

/* The source a signal stops and the signal caught.  Globals because a
 * signal handler has no other way to reach them. */
static const struct run_source *volatile run_src;
static volatile sig_atomic_t run_sig;

static void on_signal(int sig)
{
	const struct run_source *s = run_src;
	run_sig = sig;
	if (s)
		s->stop(s->ctx, sig);
}

static const int catch_sigs[3] = {SIGINT, SIGTERM, SIGHUP};

void run_signals_catch(struct run_signals *c, int oneshot)
{
	struct sigaction sa;
	run_sig = 0;
	run_src = NULL;
	memset(&sa, 0, sizeof sa);
	sa.sa_handler = on_signal;
	sigemptyset(&sa.sa_mask);
	sa.sa_flags = SA_RESTART | (oneshot ? SA_RESETHAND : 0);
	/* a signal ignored at start stays ignored (nohup, a background job
	 * of a shell without job control) */
	for (int k = 0; k < 3; k++) {
		sigaction(catch_sigs[k], NULL, &c->old[k]);
		c->on[k] = c->old[k].sa_handler != SIG_IGN;
		if (c->on[k])
			sigaction(catch_sigs[k], &sa, NULL);
	}
}

void run_signals_watch(const struct run_source *src)
{
	run_src = src;
	if (src && run_sig)
		src->stop(src->ctx, run_sig);
}

int run_signal(void)
{
	return run_sig;
}

const volatile sig_atomic_t *run_signal_flag(void)
{
	return &run_sig;
}

void run_signals_restore(struct run_signals *c)
{
	for (int k = 0; k < 3; k++)
		if (c->on[k])
			sigaction(catch_sigs[k], &c->old[k], NULL);
	run_src = NULL;
}

/* ---- a whole run without a file ----------------------------------------- */

struct loads {
	double *x;
	long n;
	double scale;	/* wall_quantity's */
};

static void keep_load(void *ctx, const struct record *r)
{
	struct loads *l = ctx;
	if (r->status == SAMPLE_ACCEPTED)
		l->x[l->n++] = l->scale * r->lambda_min;
}

enum sw_status run_all(const struct mc_config *cfg, struct tally *t,
		       double **lam, long *nlam,
		       void (*tick)(void *ctx, const struct tally *t),
		       void *ctx, char *err)
{
	struct mc *m = mc_start(cfg, err);
	if (!m)
		return SW_EANALYSIS;
	struct run_source src;
	struct run run;
	struct wall_quantity q;
	wall_quantity(cfg->w, &q);
	struct loads l = {NULL, 0, q.scale};
	run_source_pool(&src, m);
	run_init(&run, cfg->w, &src, t, NULL);
	if (lam) {
		l.x = sw_xmalloc(sizeof(double) * ((size_t)cfg->n + 1));
		run.each = keep_load;
		run.each_ctx = &l;
	}
	run_signals_watch(&src);
	while (run_pump(&run, tick ? 200 : -1) >= 0)
		if (tick)
			tick(ctx, t);
	run_signals_watch(NULL);
	run_free(&run);
	mc_free(m);
	if (lam) {
		*lam = l.x;
		*nlam = l.n;
	}
	if (run_signal())
		return sw_fail(err, SW_EINTR, "interrupted (%s)",
			       strsignal(run_signal()));
	return SW_OK;
}
