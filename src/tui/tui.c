/*
 * tui.c - the workbench: tui_main, the terminal, the event loop and the
 * dispatcher of screens (main, help, history).
 *
 * One thread (this one) owns the terminal.  It sleeps in poll() on stdin
 * and on the sampler's wake pipe (mc_wake_fd) for at most 100 ms, then
 * reads every pending key, pops every sample that is ready (tui_run_pump:
 * written to the samples CSV and tallied), looks whether the solve
 * thread has finished, and redraws if anything changed and the last
 * frame is at least TUI_FRAME old: at most 10 frames a second, a key
 * answered within 100 ms.
 *
 * Signals (tui_signal.c): SIGINT, SIGTERM and SIGHUP end the loop the
 * way q does; Ctrl-Z suspends (tui_suspend).  Quitting never waits for a computation: the pool is
 * stopped and drained (tui_run_end), the solve thread stopped and
 * joined (tui_solve_free); their LPs see the stop within a second.
 */
#include <errno.h>
#include <langinfo.h>
#include <locale.h>
#include <math.h>
#include <poll.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <time.h>
#include <unistd.h>

#include <curses.h>

#include "slipwall/text.h"
#include "slipwall/wallfile.h"
#include "tui.h"
#include "workbench.h"

static const struct tui_screen tui_screens[TUI_SCREEN_COUNT] = {
	[TUI_SCREEN_MAIN] = {tui_home_init, tui_home_key, tui_home_draw},
	[TUI_SCREEN_HELP] = {tui_help_init, tui_help_key, tui_help_draw},
	[TUI_SCREEN_HISTORY] = {tui_history_init, tui_history_key,
				tui_history_draw},
};

static void tui_switch_screen(struct tui *t, enum tui_screen_id id)
{
	t->screen = id;
	tui_screens[id].init(t);
}

/* Below the least size the screen shows none of the workbench. */
static int tui_small(const struct tui *t)
{
	return t->rows < TUI_MIN_ROWS || t->cols < TUI_MIN_COLS;
}

static void tui_key(struct tui *t, int ch)
{
	/* too small a terminal: q quits (its question, after a long run,
	 * is drawn on the small screen, and the next key answers it), from
	 * whatever screen; any other key would edit a wall or end a run
	 * that nobody sees, and waits for a larger terminal instead */
	if (tui_small(t) && !t->confirm_key) {
		if (ch != 'q' && ch != 'Q') {
			t->small_keys = 1;
			return;
		}
		if (t->prompting)	/* a prompt nobody sees: dropped */
			tui_prompt_cancel(t, 27);
		if (t->screen != TUI_SCREEN_MAIN)
			tui_switch_screen(t, TUI_SCREEN_MAIN);
	}
	t->note[0] = 0;		/* seen: the key was the answer */
	enum tui_screen_id next = tui_screens[t->screen].key(t, ch);
	if (next != t->screen)
		tui_switch_screen(t, next);
}

static void tui_draw(struct tui *t)
{
	getmaxyx(stdscr, t->rows, t->cols);
	erase();
	if (tui_small(t)) {
		char buf[128];
		snprintf(buf, sizeof buf,
			 "terminal too small: %dx%d, the workbench needs %dx%d",
			 t->cols, t->rows, TUI_MIN_COLS, TUI_MIN_ROWS);
		mvaddnstr(0, 0, buf, t->cols);
		mvaddnstr(t->rows > 1 ? 1 : 0, 0, "(sampling goes on; q quits)",
			  t->cols);
		/* q's question, or why the other keys did nothing */
		const char *why = t->confirm_key ? t->msg : t->small_keys ?
			"(other keys wait for a larger terminal)" : "";
		if (t->rows > 2)
			mvaddnstr(2, 0, why, t->cols);
	} else {
		t->small_keys = 0;
		tui_screens[t->screen].draw(t);
	}
	refresh();
}

static void tui_colors(struct tui *t)
{
	/* NO_COLOR (no-color.org): set and not empty, no colours at all;
	 * bold and reverse video stay */
	const char *nc = getenv("NO_COLOR");
	t->colors = has_colors() && !(nc && nc[0]);
	if (!t->colors)
		return;
	start_color();
	use_default_colors();
	init_pair(1, COLOR_BLACK, COLOR_YELLOW);	/* moving blocks */
	init_pair(2, COLOR_RED, -1);			/* the load */
	init_pair(3, COLOR_CYAN, -1);			/* histogram bars */
	init_pair(4, COLOR_MAGENTA, -1);		/* markers */
	init_pair(5, COLOR_WHITE, COLOR_RED);		/* errors */
	init_pair(6, COLOR_BLACK, COLOR_CYAN);		/* title, status */
	init_pair(7, COLOR_YELLOW, -1);			/* previous run */
}

/* curses on the terminal, set up; NULL if it cannot start. */
static SCREEN *tui_terminal(struct tui *t)
{
	SCREEN *scr = newterm(NULL, stdout, stdin);
	if (!scr)
		return NULL;
	cbreak();
	noecho();
	nonl();
	keypad(stdscr, TRUE);
	nodelay(stdscr, TRUE);
	curs_set(0);
	set_escdelay(25);
	tui_colors(t);
	/* a left click selects a block, a right click moves the load; the
	 * wheel scrolls the help and the history */
	mousemask(BUTTON1_PRESSED | BUTTON1_CLICKED | BUTTON3_PRESSED |
		  BUTTON3_CLICKED | BUTTON4_PRESSED | BUTTON5_PRESSED, NULL);
	mouseinterval(0);
	getmaxyx(stdscr, t->rows, t->cols);
	return scr;
}

/* The session's state for wall w (t takes it): undo, history, the
 * first run and its solve. */
static void tui_session(struct tui *t, struct wall *w, const char *path)
{
	char err[SW_ERRLEN], dir[PATH_MAX];
	time_t now = time(NULL);
	struct tm tm;

	t->w = w;
	tui_edit_lock(t);
	undo_init(&t->undo, TUI_UNDO_STEPS);
	snprintf(t->next_what, sizeof t->next_what, "opened %s",
		 w->path ? w->path : path);
	t->cur_x = t->cur_y = NAN;	/* placed on a block by Tab */
	localtime_r(&now, &tm);
	strftime(t->session, sizeof t->session, "%Y%m%d-%H%M%S", &tm);
	if (tui_file_runs_dir(dir, sizeof dir, err) != 0 ||
	    history_index_path(dir, t->hist_path, sizeof t->hist_path))
		t->hist_path[0] = 0;
	tui_message(t, 0, "%s: sampling on %d thread%s", w->path ? w->path : path,
		    t->threads, tui_s(t->threads));
	tui_edit_lock_message(t);
	tui_run_start(t);
	t->solve = tui_solve_new();
	if (t->solve)
		tui_solve_wall(t->solve, w);
	t->solve_t0 = sys_now();
	tui_switch_screen(t, TUI_SCREEN_MAIN);
}

/* A resize that comes between newterm()'s size query and the moment
 * ncurses installs its SIGWINCH handler is lost (the signal's default is
 * to be ignored), and the screen is then drawn for the old size: seen in
 * CI, a pane resized to 80x24 as the workbench started under load, drawn
 * at 100x30 until the next resize.  So every turn the loop asks the
 * terminal its size (one ioctl) and resizes when curses disagrees;
 * returns whether it did. */
static int tui_size_check(struct tui *t)
{
	struct winsize ws;
	if (ioctl(STDOUT_FILENO, TIOCGWINSZ, &ws) != 0 || ws.ws_row == 0 ||
	    ws.ws_col == 0 || !is_term_resized(ws.ws_row, ws.ws_col))
		return 0;
	resizeterm(ws.ws_row, ws.ws_col);
	clearok(curscr, TRUE);	/* what is on the terminal is unknown */
	getmaxyx(stdscr, t->rows, t->cols);
	return 1;
}

/* One turn of the loop after poll(): keys, samples, the solve thread;
 * returns whether the screen changed. */
static int tui_tick(struct tui *t, int *more)
{
	int ch, dirty = tui_size_check(t);
	while (!t->quit && (ch = getch()) != ERR) {
		dirty = 1;
		if (ch == KEY_RESIZE)
			getmaxyx(stdscr, t->rows, t->cols);
		else
			tui_key(t, ch);
	}
	/* pop for at most 50 ms, then come back for the keys */
	int n = tui_run_pump(t, 0.05);
	*more = n < 0;
	if (n != 0)
		dirty = 1;
	if (tui_present_tick(t))	/* auto-play's step */
		dirty = 1;
	if (t->solve && !t->solve_done &&
	    tui_solve_poll(t->solve, &t->has_std, &t->lam_std, &t->has_gil,
			   &t->lam_gil)) {
		t->solve_done = 1;
		dirty = 1;
	}
	return dirty;
}

/* Ctrl-Z: the terminal back to the shell, the process stopped
 * (tui_signal_stop); after fg the screen drawn again from scratch. */
static void tui_suspend(struct tui *t)
{
	double t0 = sys_now();
	endwin();
	tui_signal_stop();
	/* the clocks of the speed and of the solve leave out the stop */
	t->run.t_start += sys_now() - t0;
	t->solve_t0 += sys_now() - t0;
	refresh();		/* back in curses mode */
	tui_size_check(t);	/* resized while stopped */
	clearok(curscr, TRUE);
	tui_message(t, 0, "back after Ctrl-Z (the sampling stopped with the program)");
}

static void tui_loop(struct tui *t)
{
	double last_draw = -1;
	int dirty = 1, more = 0;
	while (!t->quit && !tui_signal_pending()) {
		struct pollfd pf[2];
		pf[0].fd = STDIN_FILENO;
		pf[0].events = POLLIN;
		pf[1].fd = t->run.mc ? mc_wake_fd(t->run.mc) : -1;
		pf[1].events = POLLIN;
		int timeout = 100;
		if (more)
			timeout = 0;
		else if (dirty) {
			double left = last_draw + TUI_FRAME - sys_now();
			timeout = left <= 0 ? 0 : (int)(left * 1000) + 1;
		}
		if (poll(pf, 2, timeout) < 0 && errno != EINTR)
			break;
		if (tui_signal_pending())
			break;
		if (tui_signal_suspend_pending()) {
			tui_suspend(t);
			dirty = 1;
			last_draw = -1;
		}
		if (tui_tick(t, &more))
			dirty = 1;
		/* the clocks of slow samples and of the solve thread tick */
		if ((t->run.mc || (t->solve && !t->solve_done)) &&
		    sys_now() - last_draw >= 1)
			dirty = 1;
		if (dirty && sys_now() - last_draw >= TUI_FRAME) {
			tui_draw(t);
			last_draw = sys_now();
			dirty = 0;
		}
	}
}

/* After the terminal is back: the history and the files of the session
 * on stdout, everything freed. */
static void tui_finish(struct tui *t)
{
	tui_history_print(t, stdout);
	if (t->nfiles)
		printf("files written:\n");
	for (int k = 0; k < t->nfiles; k++) {
		printf("%s\n", t->files[k]);
		free(t->files[k]);
	}
	free(t->files);
	if (t->hist_path[0] && t->nhist)
		printf("history: %s\n", t->hist_path);
	else if (t->hist_err[0])
		printf("history: not kept: %s\n", t->hist_err);
	fflush(stdout);
	free(t->hist);
	free(t->prev_lam);
	tui_history_free(t);
	undo_free(&t->undo);
	wall_free(t->w);
}

struct sample_lp_config tui_lp = { .start = SAMPLE_START_DEFAULT };

int tui_main(const char *path, const struct sample_lp_config *lp)
{
	tui_lp = *lp;
	struct tui tt, *t = &tt;
	char err[SW_ERRLEN];
	struct wall *w;

	memset(t, 0, sizeof *t);
	if (wallfile_load(path, &w, err) != SW_OK) {
		char *c = text_clean(err);	/* the path may hold controls */
		fprintf(stderr, "%s\n", c);
		free(c);
		return 2;
	}
	if (!isatty(STDIN_FILENO) || !isatty(STDOUT_FILENO)) {
		fprintf(stderr, "slipwall: the workbench needs a terminal "
				"(use 'slipwall run' for batch work)\n");
		wall_free(w);
		return 2;
	}
	setlocale(LC_ALL, "");
	t->utf8 = !strcmp(nl_langinfo(CODESET), "UTF-8");
	t->threads = mc_ncpu();
	t->run_ended = tui_history_record;	/* tui_run.c: a run's row */
	if (tui_signal_install()) {
		fprintf(stderr, "slipwall: cannot install signal handlers\n");
		wall_free(w);
		return 1;
	}
	tui_fatal_begin();	/* stderr to a file; the terminal's modes */
	SCREEN *scr = tui_terminal(t);
	if (!scr) {
		tui_fatal_end();
		fprintf(stderr, "slipwall: cannot start the terminal (TERM=%s)\n",
			getenv("TERM") ? getenv("TERM") : "");
		wall_free(w);
		return 2;
	}
	tui_fatal_arm(1);	/* from here any end restores the terminal */
	tui_session(t, w, path);
	tui_loop(t);
	tui_run_end(t);
	tui_solve_free(t->solve);
	sample_setup_free(t->setup);
	t->setup = NULL;
	endwin();
	delscreen(scr);
	tui_fatal_end();	/* what was written to stderr, to stderr */
	tui_finish(t);
	return 0;
}
