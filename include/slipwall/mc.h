/*
 * mc.h - the Monte Carlo sampler: a pool of worker threads, results in
 * sample order.
 *
 * Sample i's draw, its contact points and friction, depends only on
 * (seed, i) (draw_make, draw.h; or a replayed table), and each worker
 * computes whole samples with its own workspace and LP solver, so the
 * results do not depend on the number of threads.
 * Workers take indices from a shared counter and put finished samples
 * into a reorder window; the consumer (one thread: the `run` command, or
 * the workbench's UI thread) takes them out strictly in index order with
 * mc_pop().  A pool may compute a share of the indices only (first,
 * first + stride, ...: one MPI rank's, src/cli/cluster.c; or, with
 * first = k and stride 1, a run resumed at sample k); "in order" is then
 * the order of that share.  Samples are struct record (record.h).  Workers wait when they are more than
 * the window ahead of the consumer, so memory stays bounded.
 *
 * Signals: mc_start() blocks every asynchronous signal in the workers
 * (they inherit a full mask), so SIGINT, SIGTERM, SIGHUP and SIGWINCH go
 * to the thread that started the pool.  The wall and the config must
 * outlive the pool.
 */
#ifndef SLIPWALL_MC_H
#define SLIPWALL_MC_H

#include <stdint.h>

#include "slipwall/draw.h"
#include "slipwall/record.h"
#include "slipwall/sample.h"
#include "slipwall/wall.h"

struct mc_config {
	const struct wall *w;	/* finished; read by every worker */
	unsigned long seed;
	long n;			/* samples of the run (indices 0..n-1) */
	/* this pool's share: indices first, first + stride, ... < n (an MPI
	 * rank's, or a resumed run's; 0 and 1 = every index; stride 0 counts
	 * as 1) */
	long first, stride;
	int threads;		/* >= 1 */
	double depth;		/* < 0: the wall's contacts.depth */
	struct sample_opts opts;
	/* replay: n rows of draws (or NULL to draw them) */
	const struct draw_table *replay;
	/* the set-up to start every worker from, when it fits the wall
	 * (sample_setup_fits); NULL or another shape: the pool solves it
	 * once, in one worker, and the others start from it (mc_setup).
	 * Read until mc_free. */
	const struct sample_setup *setup;
};
void mc_config_default(struct mc_config *c, const struct wall *w);

struct mc;

/* Start the workers.  Returns NULL and fills err on failure. */
struct mc *mc_start(const struct mc_config *c, char *err);

/* Take the next sample in index order into *it (copied).  Waits at most
 * wait_ms milliseconds (< 0: forever).  Returns 1 with a sample, 0 on
 * timeout, -1 when no more samples will come (all n done, or stopped and
 * the finished ones in order all taken). */
int mc_pop(struct mc *m, struct record *it, int wait_ms);

/* A file descriptor that becomes readable when a sample may be ready
 * (one byte per notification; mc_pop drains it).  For poll() loops. */
int mc_wake_fd(const struct mc *m);

/* The samples being computed now, for progress displays (one lock):
 * how many, the seconds the oldest has taken so far (a worker's first
 * sample includes the setup of its workspace), and the sum of their
 * ages; how many samples have finished that mc_pop has not given yet
 * (they wait for an earlier one, still in progress); and the worker
 * seconds that the samples given took, and those that wait. */
struct mc_progress {
	int busy;
	double oldest, total;
	long ahead;
	double worked, worked_ahead;
};
void mc_progress(struct mc *m, struct mc_progress *p);

/* The time left of a run (see mc.c, "Time left"): its workers, the
 * worker seconds of the samples its earlier pools gave (a run paused
 * and resumed has one pool a stretch), the samples popped and its
 * target, the a-priori seconds of a sample (mc_sample_seconds), and the
 * progress of its pool now.  Writes the seconds left and the estimate
 * of one sample's worker seconds (*per); returns 0 when the run is
 * done, 1 when the estimate is the a-priori one alone (no sample
 * finished), 2 when it comes from measured samples, 3 when every sample
 * left is in progress and one has already run longer than *per: how
 * long it will still take is not known (*left is 0). */
struct mc_pace {
	double threads, worked, done, target, apriori;
	struct mc_progress now;
};
int mc_pace_left(const struct mc_pace *in, double *left, double *per);

/* A rough a-priori time of one sample of w on one core, in seconds,
 * before any sample has run (to say, on opening a large wall, that its
 * first sample will be slow): a power law in the number of interfaces,
 * fitted to measured times (src/lib/mc.c, "Estimate").  Rough: within a
 * factor of about three on a loaded machine; increasing in the
 * interfaces.  mc_about writes it for people: "under a second",
 * "about 40 s", "about 5 min", "about 2 h". */
double mc_sample_seconds(const struct wall *w);
void mc_about(char *buf, size_t len, double seconds);

/* Ask the workers to stop: each abandons the sample it is computing
 * (within about a second, even inside a long LP: sample_lp_config.stop)
 * and takes no other.  Samples already finished in order can still be
 * popped; an abandoned one is never reported, so the popped samples are
 * always a prefix of the run.  Async-signal-safe. */
void mc_stop(struct mc *m);

/* Join the workers and free everything.  Stops first if needed. */
void mc_free(struct mc *m);

/* Worker-side counters, for the benchmark: LP solves, simplex
 * iterations, solves answered by the held basis, solves started from
 * artificial bounds and from shifted costs (sample_ws_counters),
 * summed over the workers that have exited, and the seconds they spent
 * inside the LP solver (approximate). */
struct mc_counters {
	long solves, iterations, held, art, shift;
	double lp_seconds;	/* inside the LP solver, summed over workers */
	int setups;		/* canonical samples solved: 1, or 0 when
				 * config.setup fitted (docs/design.md,
				 * "The shared set-up") */
};
void mc_counters(const struct mc *m, struct mc_counters *c);
/* The pool's set-up (a copy for the caller to free: sample_setup_free),
 * once it is there (config.setup, or the one its worker 0 solved);
 * NULL before, or if it was interrupted.  For the next pool of a wall of
 * the same shape (the workbench, tui_run.c). */
struct sample_setup *mc_setup(struct mc *m);
/* Wait until every worker has exited: after mc_pop returned -1 (or
 * after mc_stop), so that mc_counters covers every worker. */
void mc_wait(struct mc *m);

/* Number of online processors (>= 1): the default thread count. */
int mc_ncpu(void);

/* How many LPs, over all workspaces freed since start (the workers'
 * among them), ran out of memory (each fails its sample, not the
 * process): sample_memory_errors.  The limit of the LP solver's
 * allocator on each worker is config.opts.lp.mem_limit_mb (the batch
 * commands share half the memory out between the workers,
 * cli_threads). */
long mc_memory_errors(void);

#endif
