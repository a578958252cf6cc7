/*
 * mc.c - the worker pool and the in-order reorder window; see mc.h.
 *
 * Shared state is guarded by one mutex: the next index to hand out, the
 * next index the consumer expects, and a ring of `window` slots in which
 * sample i lives at i % window until it is popped.  Counters and slots
 * are ordinals k within the pool's share (first + k * stride is the
 * sample's index), so a pool that computes one MPI rank's share works
 * exactly like one that computes every sample.  A worker never runs
 * more than `window` samples ahead of the consumer, so a slot is free
 * when its sample arrives.  The stop flag is a C11 atomic so that a
 * signal handler may set it; waits are timed (100 ms) so that a stop is
 * noticed without a signal-unsafe broadcast.
 *
 * Random input: sample i's draw (draw.h: its contact points and
 * friction) is made from (seed, i) alone by draw_make, or read from a
 * replayed samples file's table, in the worker that computes it.
 *
 * Estimate (mc_sample_seconds).  A sample's time grows with the wall
 * faster than linearly: the LPs have rows and columns in proportion to
 * the interfaces, and on the large wall their pivots too (docs/
 * performance.md: about 600 pivots a sample on Ferris & Tin-Loi wall 1,
 * 43,000 on walls/large.yaml).  EST_SECONDS and EST_POWER are fitted to
 * `slipwall run WALL -n N --threads 1`'s elapsed time per sample on
 * this project's (loaded, shared) build machine: see the constants.
 * It is a guide to tell seconds from minutes, not a promise.
 *
 * The set-up (docs/design.md, "The shared set-up").  Every worker's
 * workspace starts its samples from the canonical bases, which cost one
 * sample's LPs at the classical contact, or on a wall of more than 1,000
 * interfaces the part of them its samples use (2.5 s on walls/large.yaml,
 * 7.4 s on walls/body-1000.yaml: docs/performance.md, "A large wall's
 * set-up" and "The set-up's LP-min cut").  The
 * pool solves them once: the worker that takes id 0 makes its
 * workspace, which solves them, and publishes them as plain data
 * (sample_ws_setup: row and column statuses; GLPK's state is the
 * thread's own) under the mutex; the others wait for it (timed waits, so
 * that a stop is noticed) and make theirs from it (sample_ws_new_setup),
 * which are then the workspaces they would have made themselves: the
 * bases are a function of the wall alone, and the CSV stays the same
 * whatever the thread count.  A set-up given in the config that fits
 * the wall (the workbench's previous wall after an edit, or the same
 * wall after a pause) is used by every worker and none is solved.
 *
 * The workers are named "sw-mc" (pthread_setname_np, on Linux), so that
 * a test or a person can count them (/proc/PID/task/TID/comm, top -H).
 *
 * Time left (mc_pace_left; the workbench's statistics pane, docs/
 * workbench.md, "Time left").  On a large wall a sample takes minutes,
 * and a bound such as "each worker takes at least as long as its oldest
 * sample" only grows while the first samples run ("> 53 s", "> 14:08",
 * "> 35:10" when the run takes five hours).  So the estimate is the
 * a-priori time of a sample (mc_sample_seconds) counted as w samples
 * already taken, blended with the worker-seconds the finished samples
 * took:
 *
 *   w    = max(0, 1 - d / P),  P = min(T, N)
 *   s    = (w e0 + W) / (w + d)   seconds of one sample
 *   left = max(0, (N - d) s - min(A, b s)) / min(T, N - d)
 *
 * e0 the a-priori seconds of a sample, T the workers, A the sum of the
 * ages of the b samples in progress, N the target, d the samples
 * finished: those popped and those that wait in the window for an
 * earlier one (mc_progress's `ahead`), and W the worker seconds those d
 * samples took, each from when its worker took it (its workspace's
 * set-up included in a worker's first) to when it finished
 * (mc_progress's `worked` and `worked_ahead`, and mc_pace's `worked`
 * for the pools of a run before a pause).  So while no sample ends s
 * stays put, `left` falls as fast as the clock runs, and the total
 * (the seconds sampled + left) stays where it was: it moves only when
 * a sample ends (towards the measured time) or when the samples in
 * progress have outlived s (it was too low).  d counts the samples
 * that wait: a worker that finished its first sample before worker 0's
 * (whose first includes the set-up) has its time in W, and with d = 0
 * it was added to e0 as if the two were one sample; the total then
 * grew, before any sample was popped, from 16,930 s to 22,248 s on
 * walls/large.yaml (28 November 2026, tests/tui/tui_pace_large.sh).
 * W was E T - A until 2 December 2026 (E the seconds the run has
 * sampled): that counts a worker's idle time as time spent on finished
 * samples - waiting for room in the window behind a slow sample, idle
 * once the last samples are handed out, or a sample a pause abandoned -
 * and each idle second made s longer (tests/unit/test_mc.c: 9 samples
 * of 10 finished in 100 s on 2 workers, one idle for the last 35 s:
 * 17.8 s a sample, where they took 13.9).
 *
 * A sample in progress counts as at most s above (min(A, b s)): past s
 * it has outlived the estimate, and what it still needs is not known.
 * While samples remain to be started that only holds `left` where it
 * is (the total grows: the estimate was low).  Once every sample left
 * is in progress, `left` is 0, and a large wall's samples differ by ten
 * times and more (docs/performance.md: 100 to 1,500 SLP iterations a
 * sample on walls/body-1000.yaml), so a run's last sample could read
 * "left ~0 s" for minutes.  mc_pace_left says so instead (3).
 *
 * Why w fades: e0 was fitted to a worker's first sample with its
 * workspace's set-up on a loaded machine (above), which on
 * walls/large.yaml is 10 to 40 times a later sample.  Counted as one
 * sample for the whole run it kept the total several times too long
 * for the first hundreds of samples (by docs/performance.md's figures,
 * a 23 s set-up and 9.2 s a sample on an idle core: about 4 times the
 * true total after 75 s on two threads, the bound of
 * tests/tui/tui_pace_large.sh being 3); once every worker has finished
 * a sample (d >= P), the measured time, set-ups included, is the better
 * figure, and it only falls as they are amortised.
 */
#define _GNU_SOURCE	/* pthread_setname_np */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "slipwall/mc.h"
#include "slipwall/sys.h"

/* Estimate: seconds of one sample at 100 interfaces, and the power of
 * the interfaces.  Measured on 23 November 2026 (`run -n 20`, or -n 1
 * for the large wall, one thread, elapsed time per sample with the
 * workspace's set-up, a 2-core machine at a load average of about 10):
 * demo (66 interfaces) 0.14 s, Ferris & Tin-Loi wall 1 (83) 0.12 s,
 * wall 2 (141) 0.23 s, walls/large.yaml (2,956) 382 s.  The line through
 * wall 2 and the large wall in log-log: power 2.44, 0.099 s at 100.
 * The small walls are above it (fixed costs), where nothing is said
 * anyway (under a second); an idle machine is two or three times
 * faster. */
#define EST_SECONDS 0.1
#define EST_POWER 2.4

struct slot {
	int full;
	double worked;	/* its worker seconds (mc_progress) */
	struct record item;
};

struct mc {
	struct mc_config cfg;
	pthread_t *th;
	int nth, started;
	pthread_mutex_t mu;
	pthread_cond_t cv_space, cv_ready;
	long count;		/* samples in this pool's share */
	long next_index, next_out, window;	/* ordinals in the share */
	int running;
	struct slot *ring;
	atomic_int stop;
	int pipe[2];
	struct mc_counters counters;
	/* per worker: when its current sample started (its workspace
	 * setup counts in its first one), 0 when idle; for mc_progress */
	double *since;
	/* the worker seconds of the samples mc_pop has given */
	double worked;
	int nextid;
	/* the set-up every worker starts from (see the top): 0 while
	 * worker 0 solves it, 1 when setup is there, -1 if it was
	 * interrupted (the workers end) */
	pthread_cond_t cv_setup;
	int setup_state;
	struct sample_setup *setup;
};

void mc_config_default(struct mc_config *c, const struct wall *w)
{
	memset(c, 0, sizeof *c);
	c->w = w;
	c->seed = w->seed;
	c->n = w->samples;
	c->first = 0;
	c->stride = 1;
	c->threads = 1;
	c->depth = -1;
	sample_opts_default(&c->opts);
}

static void notify(struct mc *m)
{
	char b = 1;
	/* non-blocking: a full pipe already says "look" */
	ssize_t r = write(m->pipe[1], &b, 1);
	(void)r;
}

static void deadline(struct timespec *ts, int ms)
{
	clock_gettime(CLOCK_REALTIME, ts);
	ts->tv_sec += ms / 1000;
	ts->tv_nsec += (long)(ms % 1000) * 1000000L;
	if (ts->tv_nsec >= 1000000000L) {
		ts->tv_sec++;
		ts->tv_nsec -= 1000000000L;
	}
}

/* Worker id's workspace, from the pool's set-up (see the top): worker
 * 0 solves it if the config gave none that fits, the others wait for
 * it.  NULL when the set-up was interrupted (a stop). */
static struct sample_ws *worker_ws(struct mc *m, int id,
				   const struct sample_lp_config *lpc)
{
	const struct wall *w = m->cfg.w;
	pthread_mutex_lock(&m->mu);
	if (m->setup_state == 0 && id == 0) {
		pthread_mutex_unlock(&m->mu);
		struct sample_ws *ws = sample_ws_new_config(w, lpc);
		struct sample_setup *s = sample_ws_setup(ws);
		pthread_mutex_lock(&m->mu);
		m->setup = s;
		m->setup_state = s ? 1 : -1;
		pthread_cond_broadcast(&m->cv_setup);
		pthread_mutex_unlock(&m->mu);
		return ws;
	}
	while (m->setup_state == 0 && !atomic_load(&m->stop)) {
		struct timespec ts;
		deadline(&ts, 100);
		pthread_cond_timedwait(&m->cv_setup, &m->mu, &ts);
	}
	int ready = m->setup_state == 1;
	pthread_mutex_unlock(&m->mu);
	/* published: immutable until mc_free, which joins the workers */
	return ready ? sample_ws_new_setup(w, lpc, m->setup) : NULL;
}

static void *worker(void *arg)
{
	struct mc *m = arg;
	const struct wall *w = m->cfg.w;
#ifdef __linux__
	pthread_setname_np(pthread_self(), "sw-mc");
#endif
	pthread_mutex_lock(&m->mu);
	int id = m->nextid++;
	m->since[id] = sys_now();
	pthread_mutex_unlock(&m->mu);
	/* a stop reaches the LPs too: a sample in progress is abandoned
	 * (on a large wall one LP can take minutes) */
	struct sample_lp_config lpc = m->cfg.opts.lp;
	lpc.stop = &m->stop;
	struct sample_ws *ws = worker_ws(m, id, &lpc);
	struct sample_result r;
	struct record it;
	sample_result_init(&r, w);
	record_init(&it, w);

	while (ws) {
		pthread_mutex_lock(&m->mu);
		while (!atomic_load(&m->stop) && m->next_index < m->count &&
		       m->next_index >= m->next_out + m->window) {
			struct timespec ts;
			deadline(&ts, 100);
			pthread_cond_timedwait(&m->cv_space, &m->mu, &ts);
		}
		if (atomic_load(&m->stop) || m->next_index >= m->count) {
			pthread_mutex_unlock(&m->mu);
			break;
		}
		long k = m->next_index++;
		if (m->since[id] == 0)
			m->since[id] = sys_now();
		pthread_mutex_unlock(&m->mu);
		long i = m->cfg.first + k * m->cfg.stride;

		if (m->cfg.replay)
			draw_from_table(&it.draw, w, m->cfg.replay, i);
		else
			draw_make(&it.draw, w, m->cfg.seed, (unsigned long)i,
				  m->cfg.depth);
		double t0 = sys_now();
		sample_run(ws, &it.draw, &m->cfg.opts, &r);
		if (sample_ws_interrupted(ws))
			break;	/* incomplete: never reported (mc_pop ends
				 * at its index once the workers are gone) */
		record_set(&it, i, &r, sys_now() - t0, w);

		pthread_mutex_lock(&m->mu);
		struct slot *s = &m->ring[k % m->window];
		record_copy(&s->item, &it, w);
		s->full = 1;
		s->worked = sys_now() - m->since[id];
		m->since[id] = 0;
		if (k == m->next_out) {
			pthread_cond_broadcast(&m->cv_ready);
			notify(m);
		}
		pthread_mutex_unlock(&m->mu);
	}

	struct sample_lp_counters lc;
	memset(&lc, 0, sizeof lc);
	if (ws)
		sample_ws_counters(ws, &lc);
	sample_result_free(&r);
	record_free(&it);
	sample_ws_free(ws);
	sample_thread_done();
	pthread_mutex_lock(&m->mu);
	m->counters.solves += lc.solves;
	m->counters.iterations += lc.iterations;
	m->counters.held += lc.held;
	m->counters.art += lc.art;
	m->counters.shift += lc.shift;
	m->counters.lp_seconds += lc.seconds;
	m->counters.setups += lc.setups;
	m->since[id] = 0;
	m->running--;
	pthread_cond_broadcast(&m->cv_ready);
	notify(m);
	pthread_mutex_unlock(&m->mu);
	return NULL;
}

struct mc *mc_start(const struct mc_config *c, char *err)
{
	sw_init();	/* before any worker can reach GSL */
	if (c->threads < 1 || c->threads > 1024) {
		sw_fail(err, SW_EUSAGE, "threads must be between 1 and 1024");
		return NULL;
	}
	if (c->first < 0 || c->stride < 0) {
		sw_fail(err, SW_EUSAGE, "a pool's share needs first >= 0 and "
			"stride >= 0");
		return NULL;
	}
	struct mc *m = sw_xcalloc(1, sizeof *m);
	m->cfg = *c;
	if (m->cfg.stride == 0)
		m->cfg.stride = 1;
	m->count = c->n > c->first ? (c->n - c->first - 1) / m->cfg.stride + 1
				   : 0;
	/* never more workers than samples to compute */
	m->nth = m->count > 0 && m->count < c->threads ? (int)m->count :
		 c->threads;
	m->window = 64 + 16L * m->nth;
	m->ring = sw_xcalloc((size_t)m->window, sizeof *m->ring);
	for (long k = 0; k < m->window; k++)
		record_init(&m->ring[k].item, c->w);
	pthread_mutex_init(&m->mu, NULL);
	pthread_cond_init(&m->cv_space, NULL);
	pthread_cond_init(&m->cv_ready, NULL);
	pthread_cond_init(&m->cv_setup, NULL);
	if (sample_setup_fits(c->setup, c->w, &c->opts.lp)) {
		m->setup = sample_setup_copy(c->setup);
		m->setup_state = 1;
	}
	atomic_init(&m->stop, 0);
	if (pipe(m->pipe) != 0) {
		sw_fail(err, SW_EIO, "cannot create a pipe: %s", strerror(errno));
		m->pipe[0] = m->pipe[1] = -1;
		mc_free(m);
		return NULL;
	}
	for (int k = 0; k < 2; k++) {
		fcntl(m->pipe[k], F_SETFL, fcntl(m->pipe[k], F_GETFL) | O_NONBLOCK);
		fcntl(m->pipe[k], F_SETFD, FD_CLOEXEC);
	}
	m->th = sw_xcalloc((size_t)m->nth, sizeof *m->th);
	m->since = sw_xcalloc((size_t)m->nth, sizeof *m->since);

	/* workers inherit a full signal mask but for the faults: signals
	 * go to the caller */
	sigset_t old;
	sys_block_signals(&old);
	m->running = 0;
	for (int k = 0; k < m->nth; k++) {
		pthread_mutex_lock(&m->mu);
		m->running++;
		pthread_mutex_unlock(&m->mu);
		if (pthread_create(&m->th[k], NULL, worker, m) != 0) {
			pthread_mutex_lock(&m->mu);
			m->running--;
			pthread_mutex_unlock(&m->mu);
			break;
		}
		m->started++;
	}
	pthread_sigmask(SIG_SETMASK, &old, NULL);
	if (m->started == 0) {
		sw_fail(err, SW_EIO, "cannot start a worker thread");
		mc_free(m);
		return NULL;
	}
	return m;
}

void mc_progress(struct mc *m, struct mc_progress *p)
{
	double t = sys_now();
	memset(p, 0, sizeof *p);
	pthread_mutex_lock(&m->mu);
	for (int k = 0; k < m->nth; k++) {
		if (m->since[k] == 0)
			continue;
		double age = t - m->since[k];
		p->busy++;
		p->total += age;
		if (age > p->oldest)
			p->oldest = age;
	}
	p->worked = m->worked;
	for (long k = m->next_out; k < m->next_index; k++) {
		const struct slot *s = &m->ring[k % m->window];
		p->ahead += s->full;
		if (s->full)
			p->worked_ahead += s->worked;
	}
	pthread_mutex_unlock(&m->mu);
}

int mc_pace_left(const struct mc_pace *in, double *left, double *per)
{
	const struct mc_progress *pg = &in->now;
	double T = in->threads > 0 ? in->threads : 1;
	double N = in->target, d = in->done + (double)pg->ahead;
	*left = 0;
	*per = 0;
	if (!(d < N))
		return 0;
	double spent = in->worked + pg->worked + pg->worked_ahead;
	double P = fmin(T, N);
	double w = d < P ? 1 - d / P : 0;
	double s = (w * in->apriori + spent) / (w + d);
	double work = (N - d) * s - fmin(pg->total, pg->busy * s);
	double par = fmin(T, N - d);
	*left = fmax(0, work) / (par > 0 ? par : 1);
	*per = s;
	if (pg->busy > 0 && N - d <= pg->busy && pg->oldest > s)
		return 3;
	return d > 0 ? 2 : 1;
}

int mc_pop(struct mc *m, struct record *it, int wait_ms)
{
	char buf[64];
	while (read(m->pipe[0], buf, sizeof buf) > 0)
		;
	pthread_mutex_lock(&m->mu);
	struct timespec ts;
	if (wait_ms > 0)
		deadline(&ts, wait_ms);
	for (;;) {
		if (m->next_out >= m->count) {
			pthread_mutex_unlock(&m->mu);
			return -1;
		}
		struct slot *s = &m->ring[m->next_out % m->window];
		if (s->full) {
			record_copy(it, &s->item, m->cfg.w);
			s->full = 0;
			m->worked += s->worked;
			m->next_out++;
			pthread_cond_broadcast(&m->cv_space);
			pthread_mutex_unlock(&m->mu);
			return 1;
		}
		/* nothing will come: the sample was never handed out (stop)
		 * or no worker is left */
		if (m->running == 0 ||
		    (atomic_load(&m->stop) && m->next_out >= m->next_index)) {
			pthread_mutex_unlock(&m->mu);
			return -1;
		}
		if (wait_ms == 0) {
			pthread_mutex_unlock(&m->mu);
			return 0;
		}
		if (wait_ms < 0) {
			struct timespec t2;
			deadline(&t2, 100);
			pthread_cond_timedwait(&m->cv_ready, &m->mu, &t2);
		} else if (pthread_cond_timedwait(&m->cv_ready, &m->mu, &ts) ==
			   ETIMEDOUT) {
			int full = m->ring[m->next_out % m->window].full;
			if (!full) {
				pthread_mutex_unlock(&m->mu);
				return 0;
			}
		}
	}
}

int mc_wake_fd(const struct mc *m)
{
	return m->pipe[0];
}

void mc_stop(struct mc *m)
{
	atomic_store(&m->stop, 1);
}

void mc_counters(const struct mc *m, struct mc_counters *c)
{
	pthread_mutex_lock((pthread_mutex_t *)&m->mu);
	*c = m->counters;
	pthread_mutex_unlock((pthread_mutex_t *)&m->mu);
}

struct sample_setup *mc_setup(struct mc *m)
{
	pthread_mutex_lock(&m->mu);
	struct sample_setup *s = m->setup_state == 1 ?
				 sample_setup_copy(m->setup) : NULL;
	pthread_mutex_unlock(&m->mu);
	return s;
}

void mc_wait(struct mc *m)
{
	pthread_mutex_lock(&m->mu);
	while (m->running > 0) {
		struct timespec ts;
		deadline(&ts, 100);
		pthread_cond_timedwait(&m->cv_ready, &m->mu, &ts);
	}
	pthread_mutex_unlock(&m->mu);
}

void mc_free(struct mc *m)
{
	if (!m)
		return;
	mc_stop(m);
	pthread_mutex_lock(&m->mu);
	pthread_cond_broadcast(&m->cv_space);
	pthread_mutex_unlock(&m->mu);
	for (int k = 0; k < m->started; k++)
		pthread_join(m->th[k], NULL);
	for (long k = 0; k < m->window; k++)
		record_free(&m->ring[k].item);
	free(m->ring);
	free(m->th);
	free(m->since);
	if (m->pipe[0] >= 0)
		close(m->pipe[0]);
	if (m->pipe[1] >= 0)
		close(m->pipe[1]);
	pthread_mutex_destroy(&m->mu);
	pthread_cond_destroy(&m->cv_space);
	pthread_cond_destroy(&m->cv_ready);
	pthread_cond_destroy(&m->cv_setup);
	sample_setup_free(m->setup);
	free(m);
}

double mc_sample_seconds(const struct wall *w)
{
	double n = w->nifaces > 1 ? (double)w->nifaces : 1;
	return EST_SECONDS * pow(n / 100.0, EST_POWER);
}

void mc_about(char *buf, size_t len, double s)
{
	if (!(s >= 1))
		snprintf(buf, len, "under a second");
	else if (s < 59.5)
		snprintf(buf, len, "about %.0f s", s);
	else if (s < 5970)	/* under 99.5 min */
		snprintf(buf, len, "about %.0f min", s / 60);
	else
		snprintf(buf, len, "about %.0f h", s / 3600);
}

int mc_ncpu(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);
	return n > 0 ? (int)n : 1;
}

long mc_memory_errors(void)
{
	return sample_memory_errors();
}
