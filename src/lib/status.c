/* status.c - the status table, error formatting, checked allocation,
 * the library's process set-up (sw_init: GSL's handler, malloc's
 * thresholds).  (Files written whole:
 * outfile.c.) */
#include <errno.h>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <gsl/gsl_errno.h>

#include "slipwall/status.h"

/* GSL's default error handler prints and aborts: inside a run that is a
 * crash for a bad number (issue 23).  It is process-global, so it is
 * turned off once, before any thread can call GSL, and every GSL call
 * of the library checks its own result (docs/reliability.md, "GSL"). */
static pthread_once_t sw_init_once = PTHREAD_ONCE_INIT;

/* Freed memory stays in the process.  GLPK builds its working copy of
 * an LP at every glp_simplex call and frees it after (a few MB on a
 * wall of hundreds of interfaces, an SLP solves two LPs an iteration),
 * and glibc's malloc gives large freed blocks back to the kernel as it
 * goes (munmap, or a trim of a worker's heap), so the next call faults
 * them in again; with two workers the faults also contend for the
 * process's memory map.  On tests/data/body-195.yaml that was 8 % of
 * the CPU in the kernel and both workers slower: fixed thresholds make
 * `run -n 40 --threads 2` 15-20 % faster, and the small walls'
 * samples take what they took (docs/performance.md, "Freed memory kept
 * in the process").  A process then holds each worker's largest
 * working set until it exits, which it would fault in again at its
 * next LP anyway.  The mmap threshold is glibc's largest dynamic one
 * (32 MiB on 64-bit), the trim threshold four times that. */
static void keep_freed_memory(void)
{
#ifdef __GLIBC__
	mallopt(M_MMAP_THRESHOLD, 32 << 20);
	mallopt(M_TRIM_THRESHOLD, 128 << 20);
#endif
}

static void sw_init_process(void)
{
	gsl_set_error_handler_off();
	keep_freed_memory();
}

void sw_init(void)
{
	pthread_once(&sw_init_once, sw_init_process);
}

/* The exit status of each code (the table's text names the code for a
 * reader of status.h). */
static const int status_exit[] = {
#define SW_X(name, code, text) code,
	SW_STATUS_TABLE(SW_X)
#undef SW_X
};

int sw_status_exit(enum sw_status st)
{
	if ((unsigned)st >= SW_STATUS_COUNT)
		return 1;
	return status_exit[st];
}

enum sw_status sw_fail(char *err, enum sw_status st, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(err, SW_ERRLEN, fmt, ap);
	va_end(ap);
	return st;
}

static void oom(size_t n)
{
	fprintf(stderr, "slipwall: out of memory (%zu bytes)\n", n);
	abort();
}

void *sw_xmalloc(size_t n)
{
	void *p = malloc(n ? n : 1);
	if (!p)
		oom(n);
	return p;
}

void *sw_xcalloc(size_t n, size_t size)
{
	void *p = calloc(n ? n : 1, size ? size : 1);
	if (!p)
		oom(n * size);
	return p;
}

void *sw_xrealloc(void *p, size_t n)
{
	void *q = realloc(p, n ? n : 1);
	if (!q)
		oom(n);
	return q;
}

char *sw_xstrdup(const char *s)
{
	size_t n = strlen(s) + 1;
	char *d = sw_xmalloc(n);
	memcpy(d, s, n);
	return d;
}

const char *sw_version(void)
{
	return SLIPWALL_VERSION;
}
