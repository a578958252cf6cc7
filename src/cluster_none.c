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

/* Started by a launcher among several processes? */
static int one_of_many(void)
{
	const char *size = getenv("OMPI_COMM_WORLD_SIZE");
	const char *rank = getenv("PMIX_RANK");
	return (size && atol(size) > 1) || (rank && strcmp(rank, "0"));
}

enum sw_status cluster_start(struct cluster **c, char *err)
{
	*c = NULL;
	if (one_of_many())
		return sw_fail(err, SW_EUSAGE, "started by mpirun, but this "
			       "slipwall was built without MPI (meson setup "
			       "-Dmpi=enabled, docs/cluster.md): every process "
			       "would compute the whole run");
	return SW_OK;
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

int cluster_agree(struct cluster *c, int rc, const struct mc_config *cfg)
{
	(void)c;
	(void)cfg;
	return rc;
}

int cluster_pop(struct cluster *c, struct mc_item *it, int wait_ms)
{
	(void)c;
	(void)it;
	(void)wait_ms;
	return -1;
}

enum sw_status cluster_status(const struct cluster *c, char *err)
{
	(void)c;
	(void)err;
	return SW_OK;
}

void cluster_stop(struct cluster *c, int sig)
{
	(void)c;
	(void)sig;
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
