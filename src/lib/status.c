/* status.c - the status table, error formatting, checked allocation,
 * the library's process set-up (sw_init).  (Files written whole:
 * outfile.c.) */
#include <errno.h>
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

static void sw_init_process(void)
{
	gsl_set_error_handler_off();
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
