/*
 * test_tap.c - the TAP helpers themselves (tap.h): tap_near prints its
 * name as a printf format with arguments, like tap_ok.  Before, it
 * printed the format ("standard: block %gx%g mu %g a %g").  The checks
 * write into a temporary file, read it back, and then report on stdout.
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
	return tap_done();
}
