/*
 * test_sys.c - the monotonic clock and mkdir -p (slipwall/sys.h).
 */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "slipwall/sys.h"
#include "tap.h"

static int is_dir(const char *p)
{
	struct stat st;
	return stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}

static void test_now(void)
{
	double t0 = sys_now();
	struct timespec nap = {0, 20000000L};	/* 20 ms */
	nanosleep(&nap, NULL);
	double t1 = sys_now();
	/* a sleep of 20 ms is at least 20 ms on the monotonic clock (no
	 * upper bound: the machine may be busy) */
	tap_ok(t1 - t0 >= 0.02 - 1e-6, "sys_now: a 20 ms sleep is >= 20 ms "
	       "(%.4f s)", t1 - t0);
}

static void test_mkdir_p(void)
{
	char tmpl[] = "/tmp/test_sys.XXXXXX";
	if (!mkdtemp(tmpl)) {
		tap_ok(0, "mkdtemp: %s", strerror(errno));
		return;
	}
	char p[PATH_MAX], q[PATH_MAX], failed[PATH_MAX];
	snprintf(p, sizeof p, "%s/a/b/c", tmpl);
	tap_ok(sys_mkdir_p(p, failed, sizeof failed) == 0 && is_dir(p),
	       "sys_mkdir_p makes a/b/c and its parents");
	tap_ok(sys_mkdir_p(p, NULL, 0) == 0,
	       "sys_mkdir_p of a directory that exists is fine");
	snprintf(q, sizeof q, "%s/a/b/c/", tmpl);
	tap_ok(sys_mkdir_p(q, NULL, 0) == 0, "a trailing slash is fine");
	/* under a file: the first component that cannot be made */
	snprintf(q, sizeof q, "%s/file", tmpl);
	FILE *f = fopen(q, "w");
	if (f)
		fclose(f);
	snprintf(p, sizeof p, "%s/file/x/y", tmpl);
	errno = 0;
	int rc = sys_mkdir_p(p, failed, sizeof failed);
	char want[PATH_MAX];
	snprintf(want, sizeof want, "%s/file/x", tmpl);
	tap_ok(rc == -1 && errno == ENOTDIR && !strcmp(failed, want),
	       "under a file: -1, ENOTDIR, and the path that failed is "
	       "file/x (got %s)", failed);
	tap_ok(sys_mkdir_p("", failed, sizeof failed) == -1 &&
		       errno == ENOENT, "an empty path: -1, ENOENT");
	char *big = malloc(PATH_MAX + 10);
	memset(big, 'a', PATH_MAX + 9);
	big[PATH_MAX + 9] = 0;
	tap_ok(sys_mkdir_p(big, NULL, 0) == -1 && errno == ENAMETOOLONG,
	       "a path of PATH_MAX bytes or more: -1, ENAMETOOLONG");
	free(big);
	char cmd[PATH_MAX + 16];
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", tmpl);
	if (system(cmd) != 0)
		printf("# could not remove %s\n", tmpl);
}

int main(void)
{
	test_now();
	test_mkdir_p();
	return tap_done();
}
