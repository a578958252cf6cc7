/*
 * tui_signal.c - the workbench's terminating signals (SIGINT, SIGTERM,
 * SIGHUP): the handler sets a flag and stops the current pool (mc_stop
 * is async-signal-safe); the event loop (tui.c) sees the flag, drains
 * the samples finished in order into the CSV, closes it, restores the
 * terminal and returns 0.
 *
 * The handlers are installed before curses starts, so ncurses keeps its
 * hands off them; SIGWINCH stays with ncurses, which turns it into
 * KEY_RESIZE.  Workers block every signal (mc_start, tui_solve.c), so
 * the handler always runs on the UI thread and the pool pointer it reads
 * is never being freed under it.  A leaf: it calls nothing of the room.
 */
#include <signal.h>
#include <string.h>

#include "tui.h"

/* Set by the signal handler, read by the loop. */
static volatile sig_atomic_t tui_signalled;
/* The pool the handler stops; written only by the UI thread, which is
 * also the only thread the handler can interrupt. */
static struct mc *volatile tui_signal_mc;

static void tui_on_signal(int sig)
{
	struct mc *m = tui_signal_mc;
	tui_signalled = sig;
	if (m)
		mc_stop(m);
}

void tui_signal_watch(struct mc *m)
{
	tui_signal_mc = m;
}

int tui_signal_pending(void)
{
	return tui_signalled != 0;
}

int tui_signal_install(void)
{
	struct sigaction sa;
	memset(&sa, 0, sizeof sa);
	sa.sa_handler = tui_on_signal;
	sigemptyset(&sa.sa_mask);
	/* no SA_RESTART: poll() returns EINTR and the loop looks */
	if (sigaction(SIGINT, &sa, NULL) || sigaction(SIGTERM, &sa, NULL) ||
	    sigaction(SIGHUP, &sa, NULL))
		return -1;
	signal(SIGPIPE, SIG_IGN);
	return 0;
}
