/*
 * status.h - the one table of status codes and their messages.
 *
 * Every function of the library that can fail returns an `enum sw_status`
 * and, when it fails, fills a caller-owned message buffer of SW_ERRLEN
 * bytes (never NULL).  Input errors are formatted as
 * "FILE:LINE:COLUMN: what is wrong".  The exit status of the program
 * follows from the code (sw_status_exit).
 */
#ifndef SLIPWALL_STATUS_H
#define SLIPWALL_STATUS_H

#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>

#define SW_ERRLEN 512

/* X(name, exit status, short text) */
#define SW_STATUS_TABLE(X)                                   \
	X(SW_OK, 0, "ok")                                    \
	X(SW_EINPUT, 2, "bad input")                         \
	X(SW_EUSAGE, 2, "bad usage")                         \
	X(SW_EANALYSIS, 1, "analysis failure")               \
	X(SW_ENOMEM, 1, "out of memory")                     \
	X(SW_EIO, 1, "input/output error")                   \
	X(SW_EINTR, 1, "interrupted")

enum sw_status {
#define SW_X(name, code, text) name,
	SW_STATUS_TABLE(SW_X)
#undef SW_X
	SW_STATUS_COUNT
};

/* Exit status of the program for a status (0, 1 or 2). */
int sw_status_exit(enum sw_status st);

/* Format into err (SW_ERRLEN bytes) and return st: `return sw_fail(...)`. */
enum sw_status sw_fail(char *err, enum sw_status st, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));

/* Allocation that never returns NULL for n > 0: prints and aborts on
 * exhaustion (the only sane reaction inside a numerical kernel). */
void *sw_xmalloc(size_t n);
void *sw_xcalloc(size_t n, size_t size);
void *sw_xrealloc(void *p, size_t n);
char *sw_xstrdup(const char *s);

/* The library's set-up for the whole process: GSL's error handler off
 * (GSL functions return their errors; the library checks each one),
 * and malloc's thresholds fixed so that the LPs' freed working memory
 * stays in the process (status.c, keep_freed_memory).
 * Idempotent and thread-safe.  Each front end calls it first (main); the
 * entry points that reach GSL code that can fail (mc_start,
 * sample_ws_new) call it too, so a library user or a unit test that
 * forgets it is safe. */
void sw_init(void);

/* The program's version ("0.1.0"), from meson.build. */
const char *sw_version(void);

#endif
