/*
 * nowinch.c - run a program with SIGWINCH blocked: nowinch PROGRAM ARGS...
 *
 * tests/tui/tui.sh starts the workbench through it to lose every resize
 * signal for certain (the blocked mask survives exec; ncurses installs
 * its handler, which never runs).  A shell cannot block a signal, and
 * ignoring it is not enough: ncurses replaces SIG_IGN with its handler.
 * Built by meson, so the test takes no interpreter from the PATH (it
 * was the first python3 there: a pyenv shim in the failing CI run).
 */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

int main(int argc, char **argv)
{
	sigset_t set;

	if (argc < 2) {
		fprintf(stderr, "usage: nowinch PROGRAM [ARGS...]\n");
		return 2;
	}
	sigemptyset(&set);
	sigaddset(&set, SIGWINCH);
	if (sigprocmask(SIG_BLOCK, &set, NULL) != 0) {
		perror("nowinch: sigprocmask");
		return 1;
	}
	execv(argv[1], argv + 1);
	fprintf(stderr, "nowinch: %s: %s\n", argv[1], strerror(errno));
	return 127;
}
