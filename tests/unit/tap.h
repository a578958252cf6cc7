/*
 * tap.h - a tiny TAP producer for the unit tests (meson protocol 'tap').
 * Each check prints "ok N - name" or "not ok N - name" with the numbers
 * that differed; tap_done() prints the plan and returns the exit status.
 */
#ifndef SLIPWALL_TAP_H
#define SLIPWALL_TAP_H

#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int tap_n, tap_failed;

static inline int tap_ok(int cond, const char *fmt, ...)
{
	va_list ap;
	tap_n++;
	printf("%s %d - ", cond ? "ok" : "not ok", tap_n);
	va_start(ap, fmt);
	vprintf(fmt, ap);
	va_end(ap);
	printf("\n");
	if (!cond)
		tap_failed++;
	fflush(stdout);
	return cond;
}

/* |got - want| <= rel * max(1, |want|); the name is a printf format
 * with its arguments, like tap_ok's (it was printed as "%s" of the
 * format before, so "block %gx%g" showed the % signs) */
static inline int tap_near(double got, double want, double rel,
			   const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
static inline int tap_near(double got, double want, double rel,
			   const char *fmt, ...)
{
	char name[512];
	va_list ap;
	double tol = rel * (fabs(want) > 1 ? fabs(want) : 1);
	int c = fabs(got - want) <= tol;
	va_start(ap, fmt);
	vsnprintf(name, sizeof name, fmt, ap);
	va_end(ap);
	tap_ok(c, "%s", name);
	if (!c)
		printf("#   got %.17g, want %.17g (tol %.3g)\n", got, want, tol);
	return c;
}

/* A check that cannot run here, for REASON: "ok N - WHAT # SKIP REASON"
 * where a developer runs the tests, and a failure where every check must
 * run: in CI (CI=true) and under scripts/test.sh, which sets
 * SLIPWALL_TEST_TOOLS=required (the rule of tests/tap.sh's skip_one). */
static inline int tap_skip(const char *what, const char *reason)
{
	const char *ci = getenv("CI"), *tools = getenv("SLIPWALL_TEST_TOOLS");
	if ((ci && !strcmp(ci, "true")) || (tools && !strcmp(tools, "required")))
		return tap_ok(0, "%s: skipped, %s (every check must run: CI=true "
			      "or SLIPWALL_TEST_TOOLS=required)", what, reason);
	return tap_ok(1, "%s # SKIP %s", what, reason);
}

static inline void tap_diag(const char *fmt, ...)
{
	va_list ap;
	printf("# ");
	va_start(ap, fmt);
	vprintf(fmt, ap);
	va_end(ap);
	printf("\n");
}

static inline int tap_done(void)
{
	printf("1..%d\n", tap_n);
	return tap_failed ? 1 : 0;
}

#endif
