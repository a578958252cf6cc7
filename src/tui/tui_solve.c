/*
 * tui_solve.c - the single-solution values (standard, gilbert) of the
 * wall on screen, computed once per wall on a one-shot thread so that the
 * UI never waits for an LP.
 *
 * The thread works on its own copy of the wall; solve_run() keeps the LP
 * solver's text off the screen and frees its environment of the thread
 * when it returns.  It blocks every signal, like the sampler's workers.
 *
 * Ownership: the UI either collects the result (tui_solve_poll) and later
 * abandons the job, or abandons it early (a new wall, quit).  Whichever
 * of "the thread has finished" and "the UI has let go" happens last frees
 * the job, so the UI never joins, never waits.
 */
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/solve.h"
#include "tui.h"

struct tui_solve {
	pthread_mutex_t mu;
	struct wall *w;		/* private copy */
	int finished, abandoned;
	int has_std, has_gil;
	double std, gil;
};

static void tui_solve_free(struct tui_solve *s)
{
	pthread_mutex_destroy(&s->mu);
	wall_free(s->w);
	free(s);
}

static int tui_solve_one(const struct wall *w, enum solve_method m,
			 double *lambda)
{
	struct solve_opts o;
	struct solve_result r;
	char err[SW_ERRLEN];
	int ok;

	memset(&r, 0, sizeof r);
	solve_opts_default(&o, m);
	ok = solve_run(w, &o, &r, err) == SW_OK &&
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
	int has_std = tui_solve_one(s->w, SOLVE_STANDARD, &std);
	int has_gil = tui_solve_one(s->w, SOLVE_GILBERT, &gil);

	pthread_mutex_lock(&s->mu);
	s->has_std = has_std;
	s->std = std;
	s->has_gil = has_gil;
	s->gil = gil;
	s->finished = 1;
	int gone = s->abandoned;
	pthread_mutex_unlock(&s->mu);
	if (gone)
		tui_solve_free(s);
	return NULL;
}

struct tui_solve *tui_solve_start(const struct wall *w)
{
	struct tui_solve *s = calloc(1, sizeof *s);
	pthread_attr_t attr;
	pthread_t th;
	sigset_t all, old;

	if (!s)
		return NULL;
	pthread_mutex_init(&s->mu, NULL);
	s->w = wall_copy(w);
	pthread_attr_init(&attr);
	pthread_attr_setdetachstate(&attr, PTHREAD_CREATE_DETACHED);
	sigfillset(&all);
	pthread_sigmask(SIG_SETMASK, &all, &old);
	int rc = pthread_create(&th, &attr, tui_solve_thread, s);
	pthread_sigmask(SIG_SETMASK, &old, NULL);
	pthread_attr_destroy(&attr);
	if (rc != 0) {
		tui_solve_free(s);
		return NULL;
	}
	return s;
}

int tui_solve_poll(struct tui_solve *s, int *has_std, double *std,
		   int *has_gil, double *gil)
{
	pthread_mutex_lock(&s->mu);
	int fin = s->finished;
	if (fin) {
		*has_std = s->has_std;
		*std = s->std;
		*has_gil = s->has_gil;
		*gil = s->gil;
	}
	pthread_mutex_unlock(&s->mu);
	return fin;
}

void tui_solve_abandon(struct tui_solve *s)
{
	if (!s)
		return;
	pthread_mutex_lock(&s->mu);
	s->abandoned = 1;
	int fin = s->finished;
	pthread_mutex_unlock(&s->mu);
	if (fin)
		tui_solve_free(s);
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
	snprintf(sv, len, t->has_std ? "%.4g" : "n/a", t->lam_std);
	snprintf(gv, len, t->has_gil ? "%.4g" : "n/a", t->lam_gil);
	return 1;
}
