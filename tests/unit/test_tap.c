/*
 * test_tap.c - the TAP helpers themselves (tap.h): tap_near prints its
 * name as a printf format with arguments, like tap_ok.  Before, it
 * printed the format ("standard: block %gx%g mu %g a %g").  tap_skip
 * skips where a developer runs the tests and fails in CI (CI=true or
 * SLIPWALL_TEST_TOOLS=required).  The checks write into a temporary
 * file, read it back, and then report on stdout.
 */
#include <stdlib.h>
#include <unistd.h>

#include "tap.h"

/* What tap_near prints for (got, want, fmt with one double) */
static void near_line(double got, double want, char *out, size_t len)
{
	FILE *f = tmpfile();
	int saved = dup(STDOUT_FILENO), n0 = tap_n, failed0 = tap_failed;
	tap_n = 0;
	fflush(stdout);
	dup2(fileno(f), STDOUT_FILENO);
	tap_near(got, want, 1e-12, "block %gx%g, %d %%", 0.4, 0.8, 7);
	fflush(stdout);
	dup2(saved, STDOUT_FILENO);
	close(saved);
	tap_n = n0;		/* the inner check is not this test's */
	tap_failed = failed0;
	rewind(f);
	size_t n = fread(out, 1, len - 1, f);
	out[n] = 0;
	fclose(f);
}

/* What tap_skip("x", "no y here") prints with CI and
 * SLIPWALL_TEST_TOOLS set as given (NULL: unset); its return in *ret */
static void skip_line(const char *ci, const char *tools, char *out,
		      size_t len, int *ret)
{
	FILE *f = tmpfile();
	int saved = dup(STDOUT_FILENO), n0 = tap_n, failed0 = tap_failed;
	char *ci0 = getenv("CI"), *tools0 = getenv("SLIPWALL_TEST_TOOLS");
	ci0 = ci0 ? strdup(ci0) : NULL;
	tools0 = tools0 ? strdup(tools0) : NULL;
	if (ci)
		setenv("CI", ci, 1);
	else
		unsetenv("CI");
	if (tools)
		setenv("SLIPWALL_TEST_TOOLS", tools, 1);
	else
		unsetenv("SLIPWALL_TEST_TOOLS");
	tap_n = 0;
	fflush(stdout);
	dup2(fileno(f), STDOUT_FILENO);
	*ret = tap_skip("x", "no y here");
	fflush(stdout);
	dup2(saved, STDOUT_FILENO);
	close(saved);
	tap_n = n0;
	tap_failed = failed0;
	if (ci0)
		setenv("CI", ci0, 1);
	else
		unsetenv("CI");
	if (tools0)
		setenv("SLIPWALL_TEST_TOOLS", tools0, 1);
	else
		unsetenv("SLIPWALL_TEST_TOOLS");
	free(ci0);
	free(tools0);
	rewind(f);
	size_t n = fread(out, 1, len - 1, f);
	out[n] = 0;
	fclose(f);
}

int main(void)
{
	char line[1024];

	near_line(1.0, 1.0, line, sizeof line);
	tap_ok(!strcmp(line, "ok 1 - block 0.4x0.8, 7 %\n"),
	       "tap_near formats its name: '%.*s'", (int)strcspn(line, "\n"),
	       line);
	near_line(2.0, 1.0, line, sizeof line);
	tap_ok(!strncmp(line, "not ok 1 - block 0.4x0.8, 7 %\n#   got 2,", 39),
	       "a failing tap_near: the formatted name, then got and want");
	int ret;
	skip_line(NULL, NULL, line, sizeof line, &ret);
	/* (the line itself is not in this check's name: its "# SKIP"
	 * would make the check a skip) */
	tap_ok(ret && !strcmp(line, "ok 1 - x # SKIP no y here\n"),
	       "tap_skip without CI: a skip, 'ok', the name, the directive");
	skip_line("true", NULL, line, sizeof line, &ret);
	tap_ok(!ret && !strncmp(line, "not ok 1 - x: skipped, no y here", 32),
	       "tap_skip with CI=true: a failure ('%.*s')",
	       (int)strcspn(line, "\n"), line);
	skip_line(NULL, "required", line, sizeof line, &ret);
	tap_ok(!ret && !strncmp(line, "not ok 1 - ", 11),
	       "tap_skip with SLIPWALL_TEST_TOOLS=required: a failure");
	skip_line("false", NULL, line, sizeof line, &ret);
	tap_ok(ret && strstr(line, "# SKIP"),
	       "tap_skip with CI=false: a skip, as without CI");
	return tap_done();
}
