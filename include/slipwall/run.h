/*
 * run.h - one Monte Carlo run, the same for `run`, `report`, `compare`
 * and the workbench: samples taken in index order from a source, each
 * written to the samples file and then counted in the tally, until the
 * source ends or the run stops.
 *
 * A source is anything that hands out struct record in index order
 * behind struct run_source: this process's pool (run_source_pool, mc.h)
 * or, on rank 0 of an MPI job, the merge of every rank's pool (src/cli/
 * cluster.c provides it).  A pool may start at any index (mc_config's
 * first): a run resumed at sample k is a pool whose first is k.
 *
 * Call order, one thread (the consumer):
 *   run_init          the wall, the tally and the samples file (or NULL)
 *   run_pump ...      until it returns -1 (the source has ended)
 *   run_finish        why the run ended (struct run.stop)
 *
 * Stops.  --until-ci (until_ci > 0): the run looks at its accepted loads
 * at RUN_LOOK0 * 2^j of them (128, 256, 512, ...), look j with p05's
 * interval at the level 1 - 0.01 / 2^(j+1) (run_look_conf), and stops
 * at the first look whose interval is narrower than until_ci times p05;
 * samples the source still hands out are dropped, so the result does not
 * depend on the thread count or the timing.  Each look sets the tally's
 * ci_conf, so the summary's interval, at the stop or at any other end,
 * is at the level of the last look made: the shares 0.01 / 2^(j+1) sum
 * to at most 0.01, and the interval reported covers p05 with probability
 * at least 99 % (Bonferroni; docs/statistics.md).
 *
 * Write errors (one policy): a row that cannot be written stops the
 * run (RUN_WRITE, the message in .werr): that sample and every later
 * one are dropped, so the tally never counts a sample the file does not
 * hold.  Front ends say so: `run` prints the summary of the samples in
 * the file and exits 1; the workbench shows the error and pauses.
 *
 * Signals (one policy): run_signals_catch catches SIGINT, SIGTERM and
 * SIGHUP (a signal ignored at start stays ignored); the handler records
 * the signal and stops the watched source (async-signal-safe).  The
 * samples finished in order are still taken, written and counted (the
 * file holds complete rows only), then run_finish says RUN_SIGNAL and
 * the front end writes the summary of what was done and exits 1
 * ("interrupted").  One set of handlers per process at a time: the
 * handler reaches the source through a global of run.c.
 */
#ifndef SLIPWALL_RUN_H
#define SLIPWALL_RUN_H

#include <signal.h>

#include "slipwall/mc.h"
#include "slipwall/record.h"
#include "slipwall/runlog.h"
#include "slipwall/tally.h"

/* Where the samples come from.  pop: as mc_pop (1 a sample, 0 nothing
 * within wait_ms, -1 the end).  stop: stop handing out samples; sig is
 * the signal that asked, 0 for any other reason; async-signal-safe.
 * status (NULL: always SW_OK): after pop returned -1, whether the source
 * was cut short by something outside this process: SW_EINTR (a signal
 * on another rank) or SW_EIO (a rank lost), with a message. */
struct run_source {
	void *ctx;
	int (*pop)(void *ctx, struct record *r, int wait_ms);
	void (*stop)(void *ctx, int sig);
	enum sw_status (*status)(void *ctx, char *err);
};
/* The source of a pool started with mc_start. */
void run_source_pool(struct run_source *s, struct mc *m);

/* Why a run ended; the names are those of `run --json`'s "stopped". */
enum run_stop {
	RUN_COMPLETE,	/* the source ended on its own */
	RUN_SIGNAL,	/* a signal, here or on another rank */
	RUN_UNTIL_CI,	/* --until-ci */
	RUN_WRITE,	/* a row could not be written */
	RUN_LOST	/* the source failed (an MPI rank lost) */
};
const char *run_stop_name(enum run_stop s);

/* --until-ci's looks: the first at RUN_LOOK0 accepted samples, then at
 * every doubling (at most RUN_LOOKS_MAX of them: 128 * 2^40), look j at
 * the level 1 - RUN_CI_ALPHA / 2^(j+1). */
#define RUN_LOOK0 128
#define RUN_LOOKS_MAX 40
#define RUN_CI_ALPHA 0.01
size_t run_look_n(int j);
double run_look_conf(int j);

/* The 99 % interval of p05 kept from sample to sample (the progress
 * line): its ranks depend on the number of accepted samples only. */
struct run_ci {
	size_t n;
	int ok;
	size_t lo, hi;
};

struct run {
	const struct wall *w;
	const struct run_source *src;
	struct tally *tally;	/* the caller's, tally_init'ed */
	struct runlog *log;	/* the caller's, or NULL: no file */
	double until_ci;	/* 0: off */
	/* called after each sample is counted (or NULL) */
	void (*each)(void *ctx, const struct record *r);
	void *each_ctx;
	enum run_stop stop;
	char werr[SW_ERRLEN];	/* RUN_WRITE: the error */
	/* run_finish: the source's status and message, and why a
	 * RUN_SIGNAL (the signal here, or the source's message) */
	enum sw_status source_status;
	char source_err[SW_ERRLEN];
	char why[SW_ERRLEN];
	struct run_ci ci;
	int looks;		/* --until-ci: the looks made */
	struct record rec;	/* the pop buffer */
};

void run_init(struct run *r, const struct wall *w, const struct run_source *src,
	      struct tally *t, struct runlog *log);
void run_free(struct run *r);
/* Take one sample from the source, waiting at most wait_ms (< 0: until
 * one comes): 1 when one was taken (or dropped after a stop), 0 on
 * timeout, -1 when the source has ended. */
int run_pump(struct run *r, int wait_ms);
/* Take every sample left, then run_finish (a pool after mc_stop, a run
 * at its end). */
void run_drain(struct run *r);
/* Write and count one sample (run_pump does it for popped ones): 0, or
 * -1 when the run has stopped (a write error, --until-ci reached). */
int run_take(struct run *r, const struct record *rec);
/* After run_pump returned -1: settle .stop (a signal caught, the
 * source's status), .source_status and .why. */
void run_finish(struct run *r);

/* --until-ci's rule, after an accepted sample is counted: if the count
 * is the next look's, make it (the tally's ci_conf becomes its level)
 * and return whether p05's interval at that level is narrower than w
 * times p05 (then the run must stop); 0 when no look is due. */
int run_until_ci_look(struct run *r, double w);

/* p05 of the accepted samples so far and its 99 % interval; returns 0
 * (lo and hi NaN) when there are too few samples for an interval. */
int run_p05(struct run *r, double *p05, double *lo, double *hi);

/* A whole run of a pool without a samples file (`report`, `compare`):
 * start the pool for cfg, take every sample into t and, when lam is not
 * NULL, the accepted loads in index order into *lam (malloc'd, *nlam of
 * them; in the tally's quantity: lambda_min times wall_quantity's
 * scale).  tick (or NULL) is called at least every 0.2 s while it runs
 * (a progress line).  A signal caught by run_signals_catch stops it:
 * the samples done are in t and *lam, and it returns SW_EINTR with
 * "interrupted (SIGNAL)" in err.  SW_EANALYSIS when the pool cannot
 * start (err says why). */
enum sw_status run_all(const struct mc_config *cfg, struct tally *t,
		       double **lam, long *nlam,
		       void (*tick)(void *ctx, const struct tally *t),
		       void *ctx, char *err);

/* Signals: catch SIGINT, SIGTERM, SIGHUP (oneshot: SA_RESETHAND, a
 * second signal kills at once); watch names the source a signal stops
 * (NULL: none; a signal already caught stops it at once); run_signal
 * is the signal caught since run_signals_catch, or 0;
 * run_signal_flag is the same as a flag for a cancel pointer
 * (report_opts.cancel). */
struct run_signals {
	struct sigaction old[3];
	int on[3];
};
void run_signals_catch(struct run_signals *s, int oneshot);
void run_signals_watch(const struct run_source *src);
int run_signal(void);
const volatile sig_atomic_t *run_signal_flag(void);
void run_signals_restore(struct run_signals *s);

#endif
