/*
 * cluster.c - `slipwall run` over the ranks of an MPI job; see cluster.h
 * and docs/cluster.md.  Compiled only when meson finds MPI; without it
 * cluster_none.c stands in.
 *
 * Who computes what.  Sample i depends only on (seed, i), so the job
 * splits the indices: rank r's pool (mc.c, with its own threads, GLPK
 * only in them) computes i = r, r + P, r + 2P, ... and hands them to its
 * main thread in that order.  Rank 0's main thread also merges: it takes
 * sample i from its own pool when i mod P = 0, else from the queue of
 * rank i mod P, strictly in index order, and `run` writes and counts
 * them as they come.  The samples file is therefore the one a single
 * process writes, byte for byte, each row written as soon as every
 * earlier row is in.
 *
 * Protocol: point to point on MPI_COMM_WORLD, from the main threads only
 * (MPI_THREAD_FUNNELED).  Rank r > 0 sends rank 0
 *   ITEM   one sample, packed (record_pack: its fixed part, xi, vel,
 *          joint), in its index order;
 *   BEAT   nothing else sent for a second: alive;
 *   DONE   {samples sent, why: share done / stopped / signal, signal},
 *          the last message.
 * Rank 0 sends rank r
 *   CREDIT {samples of r merged so far}: r sends at most `window`
 *          samples beyond it, so rank 0 holds at most that many per rank
 *          (one ring each: 128 samples, fewer for large walls, about
 *          1 MiB), whatever the speeds of the ranks;
 *   STOP   stop computing (--until-ci, a signal, the end of the stream);
 *   BEAT   as above.
 * MPI keeps the order of the messages from one rank to another, so r's
 * samples arrive in index order and its DONE after its last sample.
 * Rank 0 sends with MPI_Isend and never waits for a send: one request
 * per kind and rank, a new CREDIT or BEAT waits until the last one has
 * gone, and requests still pending at the end are freed (their buffers
 * live until after MPI_Finalize).
 *
 * Ending.  The stream ends at n, or at the first index whose rank ended
 * without it (stopped).  Before it says so, rank 0 tells every rank
 * still working to STOP and receives (and drops) what they still send
 * until each one's DONE: no sample is in flight at MPI_Finalize.  After
 * a stop the ranks still send the samples they had finished, so the
 * file gets every sample finished in order, as with one process.  Only
 * after a signal is there a deadline: mpirun, on SIGINT or SIGTERM or
 * when a rank dies, sends every rank SIGTERM and SIGKILL a second
 * later, so rank 0 ends the stream with what has arrived within
 * GRACE_SECONDS of the signal, gives up on the ranks that have not said
 * DONE by then (lost, see below) and prints its summary in time.
 *
 * Faults.  Nothing blocks once the samples flow: both sides poll
 * (MPI_Iprobe, MPI_Test) and sleep 1 ms at a time, and the timeouts
 * below are checked every 0.1 s.  Even a sample's receive is polled: a
 * message longer than the transport's first fragment comes in pieces
 * that its sender must push, and a sender that froze half way would
 * hold an MPI_Recv for ever (receive_item).  A rank that has sent nothing, not
 * even a BEAT, for the timeout (60 s; SLIPWALL_MPI_TIMEOUT seconds)
 * while it still owes samples is lost: the stream ends there, `run`
 * prints what was done and a message naming the rank, and cluster_end
 * calls MPI_Abort (MPI_Finalize would wait for the lost rank).  The
 * other ranks give up on a silent rank 0 the same way.  A rank that
 * dies is usually noticed sooner by mpirun, which then ends the job
 * (SIGTERM, SIGKILL a second later); the samples file holds complete
 * rows either way, since runlog.c writes each one with a single
 * write(2).  A loop that was itself stopped for a while (SIGSTOP)
 * forgives the silence it caused.  Not covered by the timeout: the
 * set-up (cluster_agree's collectives wait for every rank to have read
 * its files, however long that takes) and MPI_Finalize; a rank that
 * dies there is still ended by mpirun.  SLIPWALL_MPI_FAULT=stop:K
 * freezes rank 1 half way through sending its K-th sample, for
 * tests/cli/mpi.sh.
 */
#define _GNU_SOURCE	/* sched_getaffinity, CPU_COUNT */
#include <fcntl.h>
#include <math.h>
#include <mpi.h>
#include <sched.h>
#include <signal.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cluster.h"
#include "slipwall/run.h"
#include "slipwall/sys.h"

#define WINDOW 128		/* samples a rank may be ahead of the merge, */
#define WINDOW_BYTES (1L << 20)	/* or fewer: at most this much per rank, */
#define WINDOW_MIN 16		/* but at least this many */
#define BEAT_SECONDS 1.0	/* silence after which a BEAT is sent */
#define HOUSEKEEPING 0.1	/* seconds between beats/timeouts checks */
#define TIMEOUT_SECONDS 60.0	/* default silence that loses a rank */
#define GRACE_SECONDS 0.5	/* after a signal: mpirun kills after 1 s */

enum tag { TAG_ITEM = 1, TAG_BEAT, TAG_DONE, TAG_CREDIT, TAG_STOP };
enum done_why { DONE_SHARE, DONE_STOPPED, DONE_SIGNAL };

/* Rank 0's view of another rank. */
struct peer {
	unsigned char *ring;	/* window packed samples, in index order */
	long head, queued;	/* ring */
	long taken;		/* its samples merged (or dropped) */
	long credited;		/* the last CREDIT sent */
	int done, why, sig;	/* its DONE */
	long sent;		/* samples it says it sent */
	double heard, told;	/* last message from it / to it */
	MPI_Request rq_credit, rq_stop, rq_beat;
	long credit_buf;	/* the CREDIT in flight */
};

struct cluster {
	int rank, size, local;
	double timeout;
	struct mc *pool;	/* this rank's share */
	const struct wall *w;
	long n;			/* samples of the run */
	size_t item_size;	/* bytes of one packed sample */
	long window;		/* samples a rank may be ahead (same on all) */
	unsigned char *buf;	/* one packed sample */
	atomic_int stop;	/* cluster_stop was called */
	volatile sig_atomic_t stop_sig;
	double last_loop;	/* for forgiving our own stalls */
	double last_house;
	char fault[SW_ERRLEN];	/* a rank lost: MPI_Abort at the end */
	int lost;
	long fault_stop;	/* SLIPWALL_MPI_FAULT=stop:K (tests) */
	/* rank 0 */
	struct peer *peer;	/* size entries, [0] unused */
	long next;		/* the next index of the stream */
	int stop_sent, ended;
	double grace_until;	/* after a signal: the stream's deadline */
	int cut_rank;		/* the rank whose end cut the stream, or -1 */
	/* ranks > 0 */
	MPI_Request rq_item, rq_beat, rq_done;
	long done_buf[3];
};

static void nap(void)
{
	struct timespec t = {0, 1000000L};
	nanosleep(&t, NULL);
}

/* ---- starting ----------------------------------------------------------- */

static int under_mpirun(void)
{
	return getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMIX_RANK");
}

/* SLIPWALL_MPI_FAULT=stop:K, for tests/cli/mpi.sh: rank 1 stops itself
 * (SIGSTOP) just after it starts to send its K-th sample, leaving that
 * message half sent - a node that freezes or a link that breaks in the
 * middle of a message, which no signal sent from outside can aim at. */
static long env_fault_stop(void)
{
	const char *s = getenv("SLIPWALL_MPI_FAULT");
	char *end;
	if (!s || strncmp(s, "stop:", 5))
		return 0;
	long k = strtol(s + 5, &end, 10);
	return *end || k < 1 ? 0 : k;
}

static double env_timeout(void)
{
	const char *s = getenv("SLIPWALL_MPI_TIMEOUT");
	char *end;
	double v = s ? strtod(s, &end) : 0;
	if (!s || *end || !(v > 0) || v > 86400)
		return TIMEOUT_SECONDS;
	return v;
}

/* The ranks on this node. */
static int local_ranks(void)
{
	MPI_Comm node;
	int n = 1;
	if (MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0,
				MPI_INFO_NULL, &node) == MPI_SUCCESS) {
		MPI_Comm_size(node, &n);
		MPI_Comm_free(&node);
	}
	return n > 0 ? n : 1;
}

enum sw_status cluster_start(struct cluster **cp, char *err)
{
	*cp = NULL;
	if (!under_mpirun())
		return SW_OK;
	int provided = 0;
	if (MPI_Init_thread(NULL, NULL, MPI_THREAD_FUNNELED, &provided) !=
	    MPI_SUCCESS)
		return sw_fail(err, SW_EIO, "MPI_Init_thread failed");
	if (provided < MPI_THREAD_FUNNELED) {
		MPI_Finalize();
		return sw_fail(err, SW_EIO, "this MPI library offers no "
			       "MPI_THREAD_FUNNELED support");
	}
	/* errors come back as return codes: a dead peer must not abort
	 * the rank that is writing the samples file */
	MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
	struct cluster *c = sw_xcalloc(1, sizeof *c);
	MPI_Comm_rank(MPI_COMM_WORLD, &c->rank);
	MPI_Comm_size(MPI_COMM_WORLD, &c->size);
	c->local = local_ranks();
	c->timeout = env_timeout();
	c->fault_stop = c->rank == 1 ? env_fault_stop() : 0;
	c->cut_rank = -1;
	c->grace_until = INFINITY;
	c->rq_item = c->rq_beat = c->rq_done = MPI_REQUEST_NULL;
	atomic_init(&c->stop, 0);
	if (c->rank > 0) {
		/* only rank 0 prints results */
		int fd = open("/dev/null", O_WRONLY | O_CLOEXEC);
		if (fd >= 0) {
			fflush(stdout);
			dup2(fd, STDOUT_FILENO);
			close(fd);
		}
	}
	*cp = c;
	return SW_OK;
}

int cluster_rank(const struct cluster *c)
{
	return c ? c->rank : 0;
}

int cluster_size(const struct cluster *c)
{
	return c ? c->size : 1;
}

int cluster_threads(const struct cluster *c)
{
	long ncpu = sysconf(_SC_NPROCESSORS_ONLN);
	long share = (ncpu > 0 ? ncpu : 1) / (c ? c->local : 1);
	cpu_set_t set;
	CPU_ZERO(&set);
	if (sched_getaffinity(0, sizeof set, &set) == 0 &&
	    CPU_COUNT(&set) < share)
		share = CPU_COUNT(&set);
	return share > 0 ? (int)share : 1;
}

enum sw_status cluster_open(struct cluster *c, const struct mc_config *cfg,
			    char *err)
{
	struct mc_config share = *cfg;
	share.first = c->rank;
	share.stride = c->size;
	c->w = cfg->w;
	c->n = cfg->n;
	c->item_size = record_wire_size(c->w);
	c->buf = sw_xcalloc(1, c->item_size);
	c->window = WINDOW_BYTES / (long)c->item_size;
	c->window = c->window > WINDOW ? WINDOW : c->window < WINDOW_MIN ?
		    WINDOW_MIN : c->window;
	if (c->rank == 0) {
		c->peer = sw_xcalloc((size_t)c->size, sizeof *c->peer);
		double t = sys_now();
		for (int r = 1; r < c->size; r++) {
			struct peer *p = &c->peer[r];
			p->ring = sw_xcalloc((size_t)c->window, c->item_size);
			p->heard = p->told = t;
			p->rq_credit = p->rq_stop = p->rq_beat = MPI_REQUEST_NULL;
		}
	}
	c->last_loop = c->last_house = sys_now();
	c->pool = mc_start(&share, err);
	return c->pool ? SW_OK : SW_EIO;
}

/* ---- agreeing on the set-up ------------------------------------------- */

static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
	const unsigned char *b = p;
	for (size_t k = 0; k < n; k++)
		h = (h ^ b[k]) * 1099511628211ULL;
	return h;
}

/* A fingerprint of everything the samples depend on: the model as
 * loaded, n, the seed, the depth and the replayed positions. */
static uint64_t fingerprint(const struct mc_config *cfg)
{
	const struct wall *w = cfg->w;
	uint64_t h = 14695981039346656037ULL;
	double depth = cfg->depth < 0 ? w->depth : cfg->depth;
	h = fnv(h, &cfg->n, sizeof cfg->n);
	h = fnv(h, &cfg->seed, sizeof cfg->seed);
	h = fnv(h, &depth, sizeof depth);
	h = fnv(h, &w->anywhere, sizeof w->anywhere);
	h = fnv(h, &w->nblocks, sizeof w->nblocks);
	h = fnv(h, &w->nifaces, sizeof w->nifaces);
	for (int b = 0; b < w->nblocks; b++) {
		const struct wall_block *bl = &w->blocks[b];
		h = fnv(h, bl->xy, sizeof(double) * 2 * (size_t)bl->nv);
		h = fnv(h, &bl->weight, sizeof bl->weight);
		h = fnv(h, &bl->fixed, sizeof bl->fixed);
	}
	for (int k = 0; k < w->nifaces; k++) {
		double mu = wall_iface_mu(w, k);
		h = fnv(h, &mu, sizeof mu);
	}
	h = fnv(h, &w->mu_cov, sizeof w->mu_cov);
	for (int l = 0; l < w->nloads; l++) {
		const struct wall_load *ld = &w->loads[l];
		h = fnv(h, ld->at, sizeof ld->at);
		h = fnv(h, ld->dir, sizeof ld->dir);
		h = fnv(h, &ld->magnitude, sizeof ld->magnitude);
		h = fnv(h, &ld->kind, sizeof ld->kind);
	}
	int replay = cfg->replay != NULL;
	h = fnv(h, &replay, sizeof replay);
	if (replay) {
		h = fnv(h, cfg->replay->xi, sizeof(double) * 2 *
			(size_t)w->nifaces * (size_t)cfg->n);
		if (cfg->replay->mu)
			h = fnv(h, cfg->replay->mu, sizeof(double) *
				(size_t)w->nifaces * (size_t)cfg->n);
	}
	return h;
}

/* The worst status over the ranks, and the first rank that had it. */
static int worst(int rc, int *who)
{
	int in[2] = {rc, 0}, out[2] = {rc, 0};
	MPI_Comm_rank(MPI_COMM_WORLD, &in[1]);
	MPI_Allreduce(in, out, 1, MPI_2INT, MPI_MAXLOC, MPI_COMM_WORLD);
	*who = out[1];
	return out[0];
}

int cluster_agree(struct cluster *c, int rc, const struct mc_config *cfg,
		  int *root_rc)
{
	*root_rc = rc;
	if (!c)
		return rc;
	MPI_Bcast(root_rc, 1, MPI_INT, 0, MPI_COMM_WORLD);
	int who, all = worst(rc, &who);
	if (all > 0) {
		if (rc <= 0 && c->rank == 0)
			fprintf(stderr, "slipwall run: rank %d could not set up "
				"the run (that rank says why)\n", who);
		return all;
	}
	/* all <= 0: every rank ready (0) or with nothing to do (-1, as
	 * after --help); a mixture means the ranks were given different
	 * options (mpirun's MPMD syntax), and a rank with nothing to do has
	 * no config to compare */
	int least = -worst(-rc, &who);
	if (all < 0)
		return -1;
	if (least < 0) {
		if (c->rank == 0)
			fprintf(stderr, "slipwall run: some ranks were given "
				"--help and others a run: every rank must be "
				"given the same options\n");
		return 2;
	}
	unsigned long long mine = fingerprint(cfg), root = mine;
	MPI_Bcast(&root, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
	all = worst(mine != root ? 2 : 0, &who);
	if (all && c->rank == 0)
		fprintf(stderr, "slipwall run: rank %d set up another run than "
			"rank 0 (the wall file, -n, --seed, --depth or "
			"--positions differ): every rank must be given the "
			"same options and read the same files\n", who);
	return all;
}

/* ---- sending without waiting -------------------------------------------- */

/* Is the request done (or none)?  A failed send counts as done: the
 * silence of its peer is what decides. */
static int sent(MPI_Request *rq)
{
	int flag = 1;
	if (*rq != MPI_REQUEST_NULL &&
	    MPI_Test(rq, &flag, MPI_STATUS_IGNORE) != MPI_SUCCESS)
		flag = 1;
	return flag;
}

/* Post a small message unless the last one of its kind is pending. */
static int post(void *buf, int count, MPI_Datatype type, int to, int tag,
		MPI_Request *rq)
{
	if (!sent(rq))
		return 0;
	if (MPI_Isend(buf, count, type, to, tag, MPI_COMM_WORLD, rq) !=
	    MPI_SUCCESS)
		*rq = MPI_REQUEST_NULL;
	return 1;
}

/* Give up on a pending request: MPI completes it on its own; the
 * buffer lives until cluster_end. */
static void drop(MPI_Request *rq)
{
	if (*rq != MPI_REQUEST_NULL && !sent(rq))
		MPI_Request_free(rq);
	*rq = MPI_REQUEST_NULL;
}

/* Was this loop itself stopped for a while (SIGSTOP, a swapped-out
 * node)?  Then the silence of the others is ours: forgive it. */
static int stalled(struct cluster *c, double t)
{
	int s = t - c->last_loop > 2 * BEAT_SECONDS;
	c->last_loop = t;
	return s;
}

/* A rank is lost (or rank 0, seen from another rank): the first
 * message is kept for cluster_status / cluster_serve. */
static void lose(struct cluster *c, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
static void lose(struct cluster *c, const char *fmt, ...)
{
	if (c->lost)
		return;
	c->lost = 1;
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(c->fault, sizeof c->fault, fmt, ap);
	va_end(ap);
}

/* ---- rank 0: receiving and merging ------------------------------------- */

static void credit(struct cluster *c, int r)
{
	struct peer *p = &c->peer[r];
	if (p->done || p->taken - p->credited < c->window / 2)
		return;
	if (!sent(&p->rq_credit))
		return;
	p->credit_buf = p->taken;
	if (post(&p->credit_buf, 1, MPI_LONG, r, TAG_CREDIT, &p->rq_credit)) {
		p->credited = p->taken;
		p->told = sys_now();
	}
}

static void housekeeping(struct cluster *c, double t);
static void stop_all(struct cluster *c);

/* After a signal, mpirun may kill us within a second: from the first
 * look at a stop, the stream ends with what has come by GRACE_SECONDS;
 * and the other ranks are told to stop. */
static void notice_stop(struct cluster *c)
{
	if (!atomic_load(&c->stop) || c->stop_sent)
		return;
	if (c->stop_sig)
		c->grace_until = sys_now() + GRACE_SECONDS;
	stop_all(c);
}

/* Receive rank r's sample (probed) into slot; 0, or -1 when r is lost.
 * Not MPI_Recv: a message longer than the transport's first fragment
 * (by default 32 KB on shared memory, 64 KB over TCP: a large wall's
 * sample) comes in pieces that its sender must push, and a sender that
 * freezes half way (a stopped process, a broken link) would block
 * MPI_Recv for ever.  So the receive is polled, with beats to the
 * others and the same timeout as silence; a pending receive left behind
 * is ended by MPI_Abort. */
static int receive_item(struct cluster *c, int r, void *slot, int count)
{
	struct peer *p = &c->peer[r];
	MPI_Request rq;
	if (MPI_Irecv(slot, count, MPI_BYTE, r, TAG_ITEM, MPI_COMM_WORLD,
		      &rq) != MPI_SUCCESS) {
		lose(c, "rank %d: its sample could not be received", r);
		return -1;
	}
	for (;;) {
		int flag = 0;
		if (MPI_Test(&rq, &flag, MPI_STATUS_IGNORE) != MPI_SUCCESS) {
			lose(c, "rank %d: its sample could not be received", r);
			return -1;
		}
		if (flag)
			return 0;
		double t = sys_now();
		notice_stop(c);
		if (stalled(c, t))	/* our own stall: forgive it */
			for (int q = 1; q < c->size; q++)
				c->peer[q].heard = t;
		if (t - p->heard > c->timeout)
			lose(c, "rank %d sent part of a sample and then nothing "
			     "for %.0f s: it died or hangs", r, t - p->heard);
		else if (t > c->grace_until)
			lose(c, "rank %d did not finish sending a sample within "
			     "%.1f s of the signal", r, GRACE_SECONDS);
		housekeeping(c, t);	/* beats to the others, their silence */
		if (c->lost)
			return -1;
		nap();
	}
}

/* Receive one message from rank r (already probed). */
static void receive(struct cluster *c, const MPI_Status *st, double t)
{
	int r = st->MPI_SOURCE, count = 0;
	struct peer *p = &c->peer[r];
	p->heard = t;
	MPI_Get_count(st, MPI_BYTE, &count);
	if (st->MPI_TAG == TAG_ITEM && count == (int)c->item_size &&
	    !p->done && p->queued < c->window) {
		unsigned char *slot = p->ring + c->item_size *
			(size_t)((p->head + p->queued) % c->window);
		if (receive_item(c, r, slot, count))
			return;	/* r is lost */
		p->queued++;
		if (c->ended) {	/* the stream is over: drop it */
			p->head = (p->head + p->queued) % c->window;
			p->taken += p->queued;
			p->queued = 0;
			credit(c, r);
		}
		return;
	}
	if (st->MPI_TAG == TAG_DONE && count == (int)sizeof(long[3])) {
		long d[3];
		MPI_Recv(d, 3, MPI_LONG, r, TAG_DONE, MPI_COMM_WORLD,
			 MPI_STATUS_IGNORE);
		p->done = 1;
		p->sent = d[0];
		p->why = (int)d[1];
		p->sig = (int)d[2];
		return;
	}
	if (st->MPI_TAG == TAG_BEAT && count == 0) {
		MPI_Recv(NULL, 0, MPI_BYTE, r, TAG_BEAT, MPI_COMM_WORLD,
			 MPI_STATUS_IGNORE);
		return;
	}
	/* not the protocol: take it off the queue and give up on r */
	unsigned char *junk = sw_xmalloc((size_t)count + 1);
	MPI_Recv(junk, count, MPI_BYTE, r, st->MPI_TAG, MPI_COMM_WORLD,
		 MPI_STATUS_IGNORE);
	free(junk);
	lose(c, "rank %d sent a message out of the protocol (tag %d, %d "
	     "bytes)", r, st->MPI_TAG, count);
}

/* Beats to the ranks still working, and their silence. */
static void housekeeping(struct cluster *c, double t)
{
	int forgive = stalled(c, t);
	if (t - c->last_house < HOUSEKEEPING)
		return;
	c->last_house = t;
	for (int r = 1; r < c->size; r++) {
		struct peer *p = &c->peer[r];
		if (p->done)
			continue;
		if (forgive)
			p->heard = t;
		credit(c, r);
		if (t - p->told >= BEAT_SECONDS &&
		    post(NULL, 0, MPI_BYTE, r, TAG_BEAT, &p->rq_beat))
			p->told = t;
		if (t - p->heard > c->timeout)
			lose(c, "rank %d sent nothing for %.0f s while it still "
			     "owed samples: it died or hangs", r, t - p->heard);
	}
}

/* Receive whatever has arrived, then keep house. */
static void progress(struct cluster *c)
{
	double t = sys_now();
	for (;;) {
		int flag = 0;
		MPI_Status st;
		if (MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD,
			       &flag, &st) != MPI_SUCCESS || !flag)
			break;
		if (st.MPI_SOURCE <= 0 || st.MPI_SOURCE >= c->size)
			break;
		receive(c, &st, t);
		if (c->lost)
			return;
	}
	housekeeping(c, t);
}

/* Tell every rank still working to stop, once; stop our own pool. */
static void stop_all(struct cluster *c)
{
	if (c->stop_sent)
		return;
	c->stop_sent = 1;
	mc_stop(c->pool);
	for (int r = 1; r < c->size; r++) {
		struct peer *p = &c->peer[r];
		if (!p->done)
			post(NULL, 0, MPI_BYTE, r, TAG_STOP, &p->rq_stop);
	}
}

/* The next sample of the stream from where it is: 1, 0 (not yet), -1
 * (the stream ends here).  wait_ms: how long to wait for our own pool. */
static int take(struct cluster *c, struct record *it, int wait_ms)
{
	if (c->next >= c->n)
		return -1;
	int r = (int)(c->next % c->size);
	if (r == 0) {
		int got = mc_pop(c->pool, it, wait_ms);
		if (got == 1)
			c->next++;
		if (got == 0 && sys_now() >= c->grace_until)
			got = -1;	/* our own workers are too slow */
		return got;
	}
	struct peer *p = &c->peer[r];
	if (p->queued == 0) {
		if (!p->done && sys_now() < c->grace_until)
			return 0;
		c->cut_rank = r;
		return -1;
	}
	record_unpack(it, c->w, p->ring + c->item_size * (size_t)p->head);
	p->head = (p->head + 1) % c->window;
	p->queued--;
	p->taken++;
	credit(c, r);
	if (it->index != c->next) {
		lose(c, "rank %d sent sample %ld where %ld was due", r,
		     it->index, c->next);
		return -1;
	}
	c->next++;
	return 1;
}

/* The stream is over: stop the others, drop what they still send, and
 * wait for every DONE (or until a rank is lost). */
static void finish(struct cluster *c)
{
	c->ended = 1;
	if (c->next < c->n)
		stop_all(c);	/* (at n, every rank ends on its own) */
	for (int r = 1; r < c->size; r++) {
		struct peer *p = &c->peer[r];
		p->taken += p->queued;
		p->queued = 0;
		credit(c, r);
	}
	for (;;) {
		progress(c);
		int left = 0;
		for (int r = 1; r < c->size; r++)
			left += !c->peer[r].done;
		if (!left || c->lost)
			return;
		if (sys_now() > c->grace_until) {
			for (int r = 1; r < c->size; r++)
				if (!c->peer[r].done)
					lose(c, "rank %d did not stop within "
					     "%.1f s of the signal", r,
					     GRACE_SECONDS);
			return;
		}
		nap();
	}
}

static int cluster_pop(void *cp, struct record *it, int wait_ms)
{
	struct cluster *c = cp;
	if (c->ended)
		return -1;
	double until = wait_ms < 0 ? INFINITY : sys_now() + 1e-3 * wait_ms;
	for (;;) {
		notice_stop(c);
		progress(c);
		int got = c->lost ? -1 : take(c, it, 0);
		if (got == 0 && (int)(c->next % c->size) == 0)
			got = take(c, it, 1);	/* wait a little for our pool */
		else if (got == 0)
			nap();
		if (got == 1)
			return 1;
		if (got < 0) {
			if (!c->lost)
				finish(c);
			c->ended = 1;
			return -1;
		}
		if (sys_now() >= until)
			return 0;
	}
}

static enum sw_status cluster_status(void *cp, char *err)
{
	const struct cluster *c = cp;
	if (c->lost)
		return sw_fail(err, SW_EIO, "%s", c->fault);
	if (c->cut_rank < 0 || atomic_load(&c->stop))
		return SW_OK;
	const struct peer *p = &c->peer[c->cut_rank];
	if (p->why == DONE_SIGNAL)
		return sw_fail(err, SW_EINTR, "rank %d: %s", c->cut_rank,
			       strsignal(p->sig));
	return sw_fail(err, SW_EIO, "rank %d stopped after %ld of its samples",
		       c->cut_rank, p->sent);
}

static void cluster_stop(void *cp, int sig)
{
	struct cluster *c = cp;
	if (sig && !c->stop_sig)
		c->stop_sig = sig;
	atomic_store(&c->stop, 1);
	if (c->pool)
		mc_stop(c->pool);
}

void cluster_source(struct cluster *c, struct run_source *s)
{
	s->ctx = c;
	s->pop = cluster_pop;
	s->stop = cluster_stop;
	s->status = cluster_status;
}

/* ---- ranks > 0: computing and sending ----------------------------------- */

/* Wait for a send to go, at most the timeout; 0 when it went. */
static int wait_sent(struct cluster *c, MPI_Request *rq)
{
	double t0 = sys_now();
	while (!sent(rq)) {
		double t = sys_now();
		if (stalled(c, t))
			t0 = t;
		if (t - t0 > c->timeout) {
			lose(c, "rank %d: rank 0 took no message for %.0f s: "
			     "it died or hangs", c->rank, t - t0);
			return -1;
		}
		nap();
	}
	return 0;
}

/* Read what rank 0 sent: credits, beats, a stop. */
static void listen(struct cluster *c, long *credit_got, double *heard)
{
	for (;;) {
		int flag = 0, count = 0;
		MPI_Status st;
		if (MPI_Iprobe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &st) !=
		    MPI_SUCCESS || !flag)
			return;
		*heard = sys_now();
		MPI_Get_count(&st, MPI_BYTE, &count);
		if (st.MPI_TAG == TAG_CREDIT && count == (int)sizeof(long)) {
			long v;
			MPI_Recv(&v, 1, MPI_LONG, 0, TAG_CREDIT, MPI_COMM_WORLD,
				 MPI_STATUS_IGNORE);
			if (v > *credit_got)
				*credit_got = v;
			continue;
		}
		unsigned char *junk = sw_xmalloc((size_t)count + 1);
		MPI_Recv(junk, count, MPI_BYTE, 0, st.MPI_TAG, MPI_COMM_WORLD,
			 MPI_STATUS_IGNORE);
		free(junk);
		if (st.MPI_TAG == TAG_STOP) {
			atomic_store(&c->stop, 1);
			mc_stop(c->pool);
		}
	}
}

enum sw_status cluster_serve(struct cluster *c, char *err)
{
	struct record it;
	record_init(&it, c->w);
	long nsent = 0, credit_got = 0;
	double heard = sys_now(), told = heard;
	int got = 0;
	while (!c->lost) {
		listen(c, &credit_got, &heard);
		double t = sys_now();
		if (stalled(c, t))
			heard = t;
		if (t - heard > c->timeout) {
			lose(c, "rank %d: rank 0 sent nothing for %.0f s: it "
			     "died or hangs", c->rank, t - heard);
			break;
		}
		if (nsent - credit_got < c->window) {
			got = mc_pop(c->pool, &it, 5);
			if (got < 0)
				break;
			if (got == 1) {
				record_pack(&it, c->w, c->buf);
				MPI_Isend(c->buf, (int)c->item_size, MPI_BYTE, 0,
					  TAG_ITEM, MPI_COMM_WORLD, &c->rq_item);
				if (nsent + 1 == c->fault_stop)
					raise(SIGSTOP);
				if (wait_sent(c, &c->rq_item))
					break;
				nsent++;
				told = sys_now();
			}
		} else {
			nap();
		}
		if (sys_now() - told >= BEAT_SECONDS &&
		    post(NULL, 0, MPI_BYTE, 0, TAG_BEAT, &c->rq_beat))
			told = sys_now();
	}
	record_free(&it);
	if (c->lost)
		return sw_fail(err, SW_EIO, "%s", c->fault);
	int sig = c->stop_sig;
	c->done_buf[0] = nsent;
	c->done_buf[1] = sig ? DONE_SIGNAL : atomic_load(&c->stop) ?
			 DONE_STOPPED : DONE_SHARE;
	c->done_buf[2] = sig;
	wait_sent(c, &c->rq_beat);
	MPI_Isend(c->done_buf, 3, MPI_LONG, 0, TAG_DONE, MPI_COMM_WORLD,
		  &c->rq_done);
	if (wait_sent(c, &c->rq_done))
		return sw_fail(err, SW_EIO, "%s", c->fault);
	return sig ? SW_EINTR : SW_OK;
}

/* ---- the end ---------------------------------------------------------- */

void cluster_close(struct cluster *c)
{
	if (!c)
		return;
	mc_free(c->pool);
	c->pool = NULL;
}

int cluster_end(struct cluster *c, int rc)
{
	if (!c)
		return rc;
	cluster_close(c);
	fflush(stdout);
	fflush(stderr);
	if (c->lost)
		MPI_Abort(MPI_COMM_WORLD, rc ? rc : 1);
	if (c->peer)
		for (int r = 1; r < c->size; r++) {
			drop(&c->peer[r].rq_credit);
			drop(&c->peer[r].rq_stop);
			drop(&c->peer[r].rq_beat);
		}
	drop(&c->rq_item);
	drop(&c->rq_beat);
	drop(&c->rq_done);
	MPI_Finalize();
	if (c->peer)
		for (int r = 1; r < c->size; r++)
			free(c->peer[r].ring);
	free(c->peer);
	free(c->buf);
	free(c);
	return rc;
}
