/*
 * sys.c - the monotonic clock and `mkdir -p`; see slipwall/sys.h.
 * Used by the library (the LP layer's time limit, the pool's speed, the
 * solve timer, the report's and the history's directories) and by both
 * front ends.
 */
#include <errno.h>
#include <pthread.h>
#include <limits.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "slipwall/sys.h"

double sys_now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

int sys_mkdir_p(const char *dir, char *failed, size_t failed_len)
{
	char p[PATH_MAX];
	if (!*dir || snprintf(p, sizeof p, "%s", dir) >= (int)sizeof p) {
		errno = *dir ? ENAMETOOLONG : ENOENT;
		if (failed && failed_len)
			snprintf(failed, failed_len, "%s", dir);
		return -1;
	}
	/* each prefix ending at a '/', then the whole path */
	for (char *s = p + 1;; s++) {
		if (*s != '/' && *s)
			continue;
		char c = *s;
		*s = 0;
		if (mkdir(p, 0777) && errno != EEXIST) {
			int e = errno;
			if (failed && failed_len)
				snprintf(failed, failed_len, "%s", p);
			errno = e;
			return -1;
		}
		*s = c;
		if (!c)
			break;
	}
	return 0;
}

void sys_block_signals(sigset_t *old)
{
	static const int faults[] = {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT};
	sigset_t all;
	sigfillset(&all);
	for (size_t k = 0; k < sizeof faults / sizeof *faults; k++)
		sigdelset(&all, faults[k]);
	pthread_sigmask(SIG_SETMASK, &all, old);
}
