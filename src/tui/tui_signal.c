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
 *
 * Ctrl-Z (SIGTSTP) suspends as in other curses programs, but not from
 * the handler (curses is not async-signal-safe): the handler, installed
 * before curses starts so that ncurses leaves SIGTSTP alone, sets a
 * flag; the loop (tui.c) sees it, ends curses and calls
 * tui_signal_stop, which raises SIGTSTP with its default action: the
 * whole process stops, the sampler's threads with it (docs/workbench.md,
 * "Signals, threads, the terminal").  On SIGCONT (fg) it returns, and
 * the loop restores the screen and draws it again.
 */
#include <signal.h>
#include <string.h>

#include "tui.h"

/* Set by the signal handler, read by the loop. */
static volatile sig_atomic_t tui_signalled;
/* Ctrl-Z has arrived: the loop suspends. */
static volatile sig_atomic_t tui_tstp;
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

static void tui_on_tstp(int sig)
{
	(void)sig;
	tui_tstp = 1;
}

static int tui_signal_tstp_handler(void)
{
	struct sigaction sa;
	memset(&sa, 0, sizeof sa);
	sa.sa_handler = tui_on_tstp;
	sigemptyset(&sa.sa_mask);
	return sigaction(SIGTSTP, &sa, NULL);
}

int tui_signal_suspend_pending(void)
{
	return tui_tstp != 0;
}

/* Stop the process as SIGTSTP's default action does; returns after
 * SIGCONT (at once when the process group has no job control: a
 * terminal-made stop is then discarded). */
void tui_signal_stop(void)
{
	sigset_t set;
	tui_tstp = 0;
	signal(SIGTSTP, SIG_DFL);
	sigemptyset(&set);
	sigaddset(&set, SIGTSTP);
	sigprocmask(SIG_UNBLOCK, &set, NULL);
	raise(SIGTSTP);
	tui_signal_tstp_handler();
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
	    sigaction(SIGHUP, &sa, NULL) || tui_signal_tstp_handler())
		return -1;
	signal(SIGPIPE, SIG_IGN);
	return 0;
}
