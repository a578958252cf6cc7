/*
 * cluster_none.c - cluster.h for a build without MPI (meson found none,
 * or -Dmpi=disabled): there is never a job, so `run` works alone.  Only
 * cluster_start, cluster_rank, cluster_size, cluster_agree,
 * cluster_close and cluster_end are called (with no job); the rest exist
 * for the linker.
 *
 * One refusal: a process started by mpirun among several would each
 * compute the whole run and write the same samples file at once, so it
 * stops with a message instead.
 */
#include <stdlib.h>
#include <string.h>

#include "cluster.h"
#include "slipwall/run.h"

/* Started by a launcher among several processes?  Open MPI's mpirun
 * says OMPI_COMM_WORLD_SIZE, MPICH's mpiexec (and srun --mpi=pmi2)
 * PMI_SIZE: every process knows.  A PMIx launcher alone says only
 * PMIX_RANK: rank 0 cannot tell, the others refuse and the launcher
 * ends the job.  *told: every process knows, so rank 0 says why. */
static int one_of_many(int *told)
{
	const char *size = getenv("OMPI_COMM_WORLD_SIZE");
	const char *pmi = getenv("PMI_SIZE");
	const char *rank = getenv("PMIX_RANK");
	*told = (size && atol(size) > 1) || (pmi && atol(pmi) > 1);
	return *told || (rank && strcmp(rank, "0"));
}

/* The launcher's rank of this process, or NULL. */
static const char *launcher_rank(void)
{
	const char *r = getenv("OMPI_COMM_WORLD_RANK");
	if (!r)
		r = getenv("PMI_RANK");
	if (!r)
		r = getenv("PMIX_RANK");
	return r;
}

enum sw_status cluster_start(struct cluster **c, char *err)
{
	*c = NULL;
	int told;
	if (!one_of_many(&told))
		return SW_OK;
	/* every process refuses; rank 0 says why, when it knows (err
	 * empty: quiet) */
	const char *rank = launcher_rank();
	if (told && rank && strcmp(rank, "0"))
		return sw_fail(err, SW_EUSAGE, "%s", "");
	return sw_fail(err, SW_EUSAGE, "started by mpirun, but this "
		       "slipwall was built without MPI (meson setup "
		       "-Dmpi=enabled, docs/cluster.md): every process "
		       "would compute the whole run");
}

int cluster_rank(const struct cluster *c)
{
	(void)c;
	return 0;
}

int cluster_size(const struct cluster *c)
{
	(void)c;
	return 1;
}

int cluster_threads(const struct cluster *c)
{
	(void)c;
	return 1;
}

enum sw_status cluster_open(struct cluster *c, const struct mc_config *cfg,
			    char *err)
{
	(void)c;
	(void)cfg;
	return sw_fail(err, SW_EUSAGE, "built without MPI");
}

int cluster_agree(struct cluster *c, int rc, const struct mc_config *cfg,
		  int *root_rc)
{
	(void)c;
	(void)cfg;
	*root_rc = rc;
	return rc;
}

/* Never called: there is no job to be a source of. */
static int none_pop(void *c, struct record *it, int wait_ms)
{
	(void)c;
	(void)it;
	(void)wait_ms;
	return -1;
}

static void none_stop(void *c, int sig)
{
	(void)c;
	(void)sig;
}

void cluster_source(struct cluster *c, struct run_source *s)
{
	s->ctx = c;
	s->pop = none_pop;
	s->stop = none_stop;
	s->status = NULL;
}

enum sw_status cluster_serve(struct cluster *c, char *err)
{
	(void)c;
	return sw_fail(err, SW_EUSAGE, "built without MPI");
}

void cluster_close(struct cluster *c)
{
	(void)c;
}

int cluster_end(struct cluster *c, int rc)
{
	(void)c;
	return rc;
}
