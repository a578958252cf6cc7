/*
 * tui_fatal.c - however the workbench ends, the terminal is given back
 * and the reason is printed on the real stderr (issue 23).
 *
 * While curses owns the terminal, stderr goes to a temporary file:
 * nothing a library prints (an allocation failure, GLPK) may write over
 * the screen.  A normal end (q, a signal of tui_signal.c) leaves curses
 * with endwin() and tui_fatal_end copies the file to the real stderr.
 * An end that does not come back - abort() (sw_xmalloc out of memory, a
 * GLPK error outside a solve, a failed assertion), SIGSEGV, SIGBUS,
 * SIGFPE, SIGILL on any thread (the workers leave these unblocked,
 * sys_block_signals), every other signal whose default is to end the
 * process (SIGQUIT from Ctrl-\, SIGXFSZ past `ulimit -f`, SIGXCPU,
 * SIGUSR1, ...; not one that was ignored when the program started, and
 * not SIGKILL, which cannot be caught), or exit() from anywhere - used
 * to leave the
 * terminal raw, on the alternate screen, and the message in $TMPDIR.
 * Now a handler for those signals, and an atexit hook, do what endwin
 * would, with async-signal-safe calls only:
 *   - write the terminal's own strings to leave curses (rmcup, cnorm,
 *     sgr0, rmkx and, the mouse being on, the xterm mouse off), worked
 *     out by tputs when curses starts;
 *   - put back the terminal modes saved before curses (tcsetattr);
 *   - copy the temporary file to the real stderr, remove it, and say
 *     "slipwall: the workbench ended: SIGNAL (the terminal was
 *     restored)";
 * then the signal's default action goes on (a core dump, exit 128+N):
 * the end is still a crash to the shell, but a readable one.
 * A leaf: it calls nothing of the room.
 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <termios.h>
#include <unistd.h>

#include <curses.h>
#include <term.h>

#include "tui.h"

/* The signals that would end the workbench without its own handler
 * (SIGINT, SIGTERM, SIGHUP are tui_signal.c's), with their names. */
#define TF_NSIGS 15
static const struct {
	int sig;
	const char *name;
} tf_sigs[TF_NSIGS] = {
	{SIGABRT, "SIGABRT (aborted)"},
	{SIGSEGV, "SIGSEGV (segmentation fault)"},
	{SIGBUS, "SIGBUS (bus error)"},
	{SIGFPE, "SIGFPE (arithmetic exception)"},
	{SIGILL, "SIGILL (illegal instruction)"},
	{SIGQUIT, "SIGQUIT (quit)"},
	{SIGTRAP, "SIGTRAP (trap)"},
	{SIGSYS, "SIGSYS (bad system call)"},
	{SIGXCPU, "SIGXCPU (CPU time limit exceeded)"},
	{SIGXFSZ, "SIGXFSZ (file size limit exceeded)"},
	{SIGUSR1, "SIGUSR1"},
	{SIGUSR2, "SIGUSR2"},
	{SIGALRM, "SIGALRM (alarm clock)"},
	{SIGVTALRM, "SIGVTALRM (virtual alarm clock)"},
	{SIGPROF, "SIGPROF (profiling timer expired)"},
};

/* Everything the handler reads, set before it is installed. */
static struct {
	int armed;		/* curses owns the terminal */
	int have_modes;
	struct termios modes;	/* before curses */
	int saved_err;		/* the real stderr, or -1 */
	char path[PATH_MAX];	/* the temporary stderr */
	char leave[256];	/* the strings that leave curses */
	size_t nleave;
	struct sigaction old[TF_NSIGS];
	int caught[TF_NSIGS];
} tf = {.saved_err = -1};

static void tf_write(int fd, const char *s, size_t n)
{
	while (n > 0) {
		ssize_t w = write(fd, s, n);
		if (w < 0 && errno == EINTR)
			continue;
		if (w <= 0)
			return;
		s += w;
		n -= (size_t)w;
	}
}

static void tf_puts(int fd, const char *s)
{
	tf_write(fd, s, strlen(s));
}

/* The temporary stderr to the real one, then remove it; stderr is the
 * real one again.  Async-signal-safe. */
static void tf_stderr_back(void)
{
	char buf[4096];
	ssize_t n;
	if (tf.saved_err < 0)
		return;
	int fd = open(tf.path, O_RDONLY);
	if (fd >= 0) {
		while ((n = read(fd, buf, sizeof buf)) > 0)
			tf_write(tf.saved_err, buf, (size_t)n);
		close(fd);
	}
	unlink(tf.path);
	dup2(tf.saved_err, STDERR_FILENO);
	close(tf.saved_err);
	tf.saved_err = -1;
}

/* What endwin would do, async-signal-safe: the strings, the modes. */
static void tf_terminal_back(void)
{
	tf_write(STDOUT_FILENO, tf.leave, tf.nleave);
	if (tf.have_modes)
		tcsetattr(STDIN_FILENO, TCSANOW, &tf.modes);
}

static void tf_on_fatal(int sig)
{
	const char *name = "a fatal signal";
	for (int k = 0; k < TF_NSIGS; k++)
		if (tf_sigs[k].sig == sig)
			name = tf_sigs[k].name;
	if (tf.armed) {
		tf.armed = 0;
		tf_terminal_back();
		tf_stderr_back();
		tf_puts(STDERR_FILENO, "slipwall: the workbench ended: ");
		tf_puts(STDERR_FILENO, name);
		tf_puts(STDERR_FILENO, " (the terminal was restored)\n");
	}
	/* the default action: SA_RESETHAND put it back, SA_NODEFER lets
	 * it through at once */
	raise(sig);
}

/* exit() while curses owns the terminal (a library that gives up). */
static void tf_at_exit(void)
{
	if (!tf.armed)
		return;
	tf.armed = 0;
	tf_terminal_back();
	tf_stderr_back();
	tf_puts(STDERR_FILENO, "slipwall: the workbench ended: exit() "
		"(the terminal was restored)\n");
}

int tui_fatal_begin(void)
{
	tf.have_modes = tcgetattr(STDIN_FILENO, &tf.modes) == 0;
	const char *dir = getenv("TMPDIR");
	snprintf(tf.path, sizeof tf.path, "%s/slipwall-stderr-XXXXXX",
		 dir && dir[0] ? dir : "/tmp");
	int fd = mkstemp(tf.path);
	if (fd < 0)
		return -1;
	fflush(stderr);
	int saved = dup(STDERR_FILENO);
	if (saved < 0 || dup2(fd, STDERR_FILENO) < 0) {
		if (saved >= 0)
			close(saved);
		close(fd);
		unlink(tf.path);
		return -1;
	}
	close(fd);
	tf.saved_err = saved;
	return 0;
}

static int tf_collect(int c)
{
	if (tf.nleave < sizeof tf.leave)
		tf.leave[tf.nleave++] = (char)c;
	return c;
}

static void tf_leave_cap(const char *cap)
{
	char *s = tigetstr(cap);
	if (s && s != (char *)-1)
		tputs(s, 1, tf_collect);
}

void tui_fatal_arm(int mouse)
{
	static int hooked;
	tf.nleave = 0;
	tf_leave_cap("sgr0");
	tf_leave_cap("rmkx");
	tf_leave_cap("cnorm");
	if (mouse) {
		char *km = tigetstr("kmous");
		if (km && km != (char *)-1 && km[0])
			for (const char *s = "\033[?1000l"; *s; s++)
				tf_collect(*s);
	}
	tf_leave_cap("rmcup");
	struct sigaction sa;
	memset(&sa, 0, sizeof sa);
	sa.sa_handler = tf_on_fatal;
	sigemptyset(&sa.sa_mask);
	sa.sa_flags = SA_RESETHAND | SA_NODEFER;
	for (int k = 0; k < TF_NSIGS; k++) {
		/* a signal ignored at start stays ignored (nohup) */
		tf.caught[k] = sigaction(tf_sigs[k].sig, NULL, &tf.old[k]) == 0 &&
			       tf.old[k].sa_handler != SIG_IGN &&
			       sigaction(tf_sigs[k].sig, &sa, NULL) == 0;
	}
	if (!hooked)
		hooked = atexit(tf_at_exit) == 0;
	tf.armed = 1;
}

void tui_fatal_end(void)
{
	if (tf.armed) {
		tf.armed = 0;
		for (int k = 0; k < TF_NSIGS; k++)
			if (tf.caught[k])
				sigaction(tf_sigs[k].sig, &tf.old[k], NULL);
	}
	fflush(stderr);
	tf_stderr_back();
}
