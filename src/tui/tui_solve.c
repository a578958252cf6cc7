/*
 * tui_solve.c - the single-solution values (standard, gilbert) of the
 * wall on screen, computed on a thread of their own ("sw-solve") so that
 * the UI never waits for an LP.
 *
 * At most one solve thread exists at a time.  tui_solve_wall() hands
 * over a new wall (a copy: the UI frees its own when the wall changes
 * again); if a thread is still solving an older wall, its stop flag is
 * set (solve_opts.stop: the LP in progress ends within about a second,
 * solve_run() returns SW_EINTR) and the new wall waits as `next`.
 * tui_solve_poll(), called by the event loop every tick, joins a thread
 * that has ended - at once, it has ended - and only then starts the
 * thread of the waiting wall.  Walls handed over while one waits replace
 * it: holding a key that edits solves the first wall (briefly) and the
 * last one, never the ones between, and never two at a time.
 *
 * The standard solution and gilbert's each make a workspace; the
 * second starts from the set-up (canonical bases) the first solved, and
 * the next wall's from the last one's while the shape stays the same
 * (solve_opts.setup; docs/design.md, "The shared set-up").
 *
 * The thread works on its copy of the wall and writes its values under
 * the mutex; everything else belongs to the UI thread.  It blocks every
 * signal, like the sampler's workers.  tui_solve_free() (quit) stops the
 * thread and joins it.
 */
#define _GNU_SOURCE	/* pthread_setname_np */
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/solve.h"
#include "tui.h"

struct tui_solve {
	pthread_mutex_t mu;
	pthread_t th;
	int running;		/* th exists and is not joined yet */
	atomic_int stop;	/* read by the thread's LPs */
	struct wall *w;		/* the thread's wall (its copy) */
	struct wall *next;	/* the wall to solve next, or NULL */
	/* the set-up of the last wall solved (solve_opts.setup): the
	 * next solve's starts while the wall keeps its shape; the
	 * thread's while it runs, threads never overlap */
	struct sample_setup *setup;
	/* under mu: written by the thread once, when it ends */
	int finished;
	int has_std, has_gil;
	double std, gil;
};

static int tui_solve_one(struct tui_solve *s, enum solve_method m,
			 double *lambda)
{
	struct solve_opts o;
	struct solve_result r;
	char err[SW_ERRLEN];
	int ok;

	memset(&r, 0, sizeof r);
	solve_opts_default(&o, m);
	o.sample.lp = tui_lp;
	o.stop = &s->stop;
	o.setup = &s->setup;
	ok = solve_run(s->w, &o, &r, err) == SW_OK &&
	     r.status == SAMPLE_ACCEPTED;
	if (ok)
		*lambda = r.lambda;
	solve_result_free(&r);
	return ok;
}

static void *tui_solve_thread(void *arg)
{
	struct tui_solve *s = arg;
	double std = 0, gil = 0;
#ifdef __linux__
	pthread_setname_np(pthread_self(), "sw-solve");
#endif
	int has_std = tui_solve_one(s, SOLVE_STANDARD, &std);
	int has_gil = !atomic_load(&s->stop) &&
		      tui_solve_one(s, SOLVE_GILBERT, &gil);

	pthread_mutex_lock(&s->mu);
	s->has_std = has_std;
	s->std = std;
	s->has_gil = has_gil;
	s->gil = gil;
	s->finished = 1;
	pthread_mutex_unlock(&s->mu);
	return NULL;
}

/* Start the thread on w (s takes it); no thread may be running.  On
 * failure the values are "n/a" at once. */
static int tui_solve_begin(struct tui_solve *s, struct wall *w)
{
	sigset_t old;

	s->w = w;
	s->finished = 0;
	s->has_std = s->has_gil = 0;
	atomic_store(&s->stop, 0);
	sys_block_signals(&old);
	int rc = pthread_create(&s->th, NULL, tui_solve_thread, s);
	pthread_sigmask(SIG_SETMASK, &old, NULL);
	if (rc != 0) {
		wall_free(s->w);
		s->w = NULL;
		return -1;
	}
	s->running = 1;
	return 0;
}

struct tui_solve *tui_solve_new(void)
{
	struct tui_solve *s = calloc(1, sizeof *s);
	if (!s)
		return NULL;
	pthread_mutex_init(&s->mu, NULL);
	atomic_init(&s->stop, 0);
	return s;
}

void tui_solve_wall(struct tui_solve *s, const struct wall *w)
{
	struct wall *c = wall_copy(w);
	if (!s->running) {
		tui_solve_begin(s, c);
		return;
	}
	atomic_store(&s->stop, 1);
	wall_free(s->next);
	s->next = c;
}

/* Join the thread if it has ended (it has, so this does not wait). */
static int tui_solve_reap(struct tui_solve *s)
{
	if (!s->running)
		return 1;
	pthread_mutex_lock(&s->mu);
	int fin = s->finished;
	pthread_mutex_unlock(&s->mu);
	if (!fin)
		return 0;
	pthread_join(s->th, NULL);
	s->running = 0;
	wall_free(s->w);
	s->w = NULL;
	return 1;
}

int tui_solve_poll(struct tui_solve *s, int *has_std, double *std,
		   int *has_gil, double *gil)
{
	if (!tui_solve_reap(s))
		return 0;
	if (s->next) {
		struct wall *n = s->next;
		s->next = NULL;
		if (tui_solve_begin(s, n) == 0)
			return 0;
	}
	*has_std = s->has_std;
	*std = s->std;
	*has_gil = s->has_gil;
	*gil = s->gil;
	return 1;
}

void tui_solve_free(struct tui_solve *s)
{
	if (!s)
		return;
	if (s->running) {
		atomic_store(&s->stop, 1);
		pthread_join(s->th, NULL);
	}
	wall_free(s->w);
	wall_free(s->next);
	sample_setup_free(s->setup);
	pthread_mutex_destroy(&s->mu);
	free(s);
}

int tui_solve_text(const struct tui *t, char *sv, char *gv, size_t len)
{
	char d[32];
	if (!t->solve_done) {
		tui_duration(d, sizeof d, sys_now() - t->solve_t0);
		snprintf(sv, len, "computing%s %s", t->utf8 ? "\u2026" : "...", d);
		gv[0] = 0;
		return 0;
	}
	snprintf(sv, len, t->has_std ? "%.4g" : "n/a", tui_load(t, t->lam_std));
	snprintf(gv, len, t->has_gil ? "%.4g" : "n/a", tui_load(t, t->lam_gil));
	return 1;
}
