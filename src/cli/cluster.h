/*
 * cluster.h - `slipwall run` over the ranks of an MPI job (Open MPI):
 * `mpirun -n P slipwall run WALL ...` computes the same samples as one
 * process, split over the ranks.  docs/cluster.md is the user's page;
 * src/cli/cluster.c explains the protocol.  Only cmd_run.c calls this.
 *
 * Built with MPI (meson -Dmpi, src/cli/cluster.c), MPI is initialised only
 * when the process was started by mpirun (OMPI_COMM_WORLD_SIZE or
 * PMIX_RANK in the environment); otherwise there is no job (NULL) and
 * `run` works alone, exactly as without MPI.  Built without it
 * (src/cli/cluster_none.c) there is never a job, and a process started by
 * mpirun among several refuses to run (each would compute everything).
 *
 * Call order, every rank, from the main thread only:
 *   cluster_start     first: MPI_Init if started by mpirun
 *   cluster_open      start this rank's pool on its share of the indices
 *   cluster_agree     the set-up outcome of the whole job (collective)
 *   rank 0:           cluster_source: run_pump until -1, run_finish
 *   other ranks:      cluster_serve (cluster_source: the signal's stop)
 *   cluster_close     join the pool (before the wall is freed)
 *   cluster_end       MPI_Finalize (MPI_Abort after a lost rank); frees
 * The source's stop may be called at any time, from a signal handler too.
 * On rank > 0, cluster_start sends stdout to /dev/null: only rank 0
 * prints results.
 */
#ifndef SLIPWALL_CLUSTER_H
#define SLIPWALL_CLUSTER_H

#include "slipwall/mc.h"
#include "slipwall/record.h"

struct cluster;

/* *c gets the job, or NULL when this process is not one rank of an MPI
 * job.  SW_OK, or an error (err filled) when MPI cannot start, or when
 * started by mpirun without MPI support. */
enum sw_status cluster_start(struct cluster **c, char *err);
/* This process's rank (0 without a job) and the number of ranks (1). */
int cluster_rank(const struct cluster *c);
int cluster_size(const struct cluster *c);
/* The default number of worker threads of a rank: the CPUs it is bound
 * to, at most the node's CPUs divided by its ranks on the node. */
int cluster_threads(const struct cluster *c);

/* Start this rank's pool on its share of cfg (indices rank, rank + P,
 * ...).  The wall and the positions of cfg must outlive the pool
 * (until cluster_close). */
enum sw_status cluster_open(struct cluster *c, const struct mc_config *cfg,
			    char *err);
/* Every rank passes the exit status of its own set-up (0: ready, -1:
 * nothing to do, as after --help) and, when ready, its config; returns
 * the job's: the worst status of any rank (a rank that failed printed
 * why, or should: see *root_rc; rank 0 says which one), -1 when every
 * rank has nothing to do, or 2 when a rank set up a different run than
 * rank 0 (another wall file, -n, --seed, --depth or --positions; or
 * --help on some ranks only).  *root_rc gets rank 0's own status: a rank
 * > 0 that kept its set-up messages to itself (they are the same on
 * every rank) prints them when its status is > 0 and rank 0's is not.
 * Without a job, returns rc (and *root_rc = rc).  Collective. */
int cluster_agree(struct cluster *c, int rc, const struct mc_config *cfg,
		  int *root_rc);

/* The job as a source of samples (run.h), on every rank:
 *   pop     rank 0: the next sample of the whole job in index order, as
 *           mc_pop (1 a sample, 0 nothing within wait_ms, -1 the end);
 *           after -1, every other rank has finished
 *   stop    the pool stops after its current samples, and rank 0 tells
 *           the other ranks; sig: the signal that asked (0: --until-ci,
 *           a write error); async-signal-safe; every rank
 *   status  why the stream ended, after pop returned -1: SW_OK (every
 *           sample, or a stop asked on this rank), SW_EINTR (another
 *           rank was interrupted by a signal: err names the rank and the
 *           signal) or SW_EIO (a rank was lost or broke the protocol: err
 *           says which) */
struct run_source;
void cluster_source(struct cluster *c, struct run_source *s);

/* Ranks > 0: compute the share and send it to rank 0 until done or
 * stopped.  SW_OK; SW_EINTR after a signal on this rank (rank 0 reports
 * it); SW_EIO with err when rank 0 went silent. */
enum sw_status cluster_serve(struct cluster *c, char *err);

/* Stop and join this rank's pool: before the wall and the config it
 * reads are freed.  NULL: nothing. */
void cluster_close(struct cluster *c);

/* End the job and free it: MPI_Finalize, or MPI_Abort(rc) when a rank
 * was lost (it would wait for that rank).  Returns rc.  NULL: rc. */
int cluster_end(struct cluster *c, int rc);

#endif
