/*
 * tui.h - the workbench's internal map: one state struct, one file per
 * screen or pane, one UI thread.
 *
 * Who does what:
 *   tui.c        tui_main, the poll() loop, signals, the screen dispatcher
 *   tui_run.c    one sampling run: the mc pool, the samples CSV, the tally
 *   tui_solve.c  the one-shot thread that computes standard and gilbert
 *   tui_wall.c   the wall pane: sketch, mechanism, load, block cursor
 *   tui_hist.c   the histogram pane
 *   tui_stats.c  the statistics pane
 *   tui_edit.c   the main screen's keys: edits, the prompt line
 *   tui_file.c   save (YAML + JSON) and open
 *   tui_help.c   the help screen
 *   tui_history.c the run history: its rows, the H screen, what q prints
 *
 * Threads: only the UI thread (the one in tui_main) calls curses, reads
 * or writes `struct tui`.  The sampler's workers and the solve thread
 * never see it: they read a finished wall and publish through mc_pop()
 * and tui_solve_poll().
 */
#ifndef SLIPWALL_TUI_H
#define SLIPWALL_TUI_H

#include <limits.h>

#include <stdio.h>

#include "slipwall/history.h"
#include "slipwall/mc.h"
#include "slipwall/run.h"
#include "slipwall/runlog.h"
#include "slipwall/tally.h"
#include "slipwall/undo.h"
#include "slipwall/wall.h"

#define TUI_MIN_COLS 80
#define TUI_MIN_ROWS 24
#define TUI_UNDO_STEPS 100	/* edits that u can take back */
#define TUI_FRAME 0.1		/* seconds between redraws (10 Hz at most) */

/* One sampling run: one wall, one samples file, one tally, the
 * library's run (run.h) over them.  The pool may be replaced during a
 * run (pause/resume, a raised target): a new pool starts at sample
 * `done` (mc_config.first), so the file is the one `slipwall run`
 * writes with the same seed. */
struct tui_run {
	struct mc *mc;		/* NULL when paused or finished */
	struct mc_config cfg;
	struct run_source src;	/* the current pool */
	struct run core;	/* file, tally, write errors */
	long done;		/* samples taken: the next index */
	long target;		/* samples wanted */
	int paused;
	struct runlog *log;	/* NULL if the file could not be made */
	char csv[PATH_MAX];
	struct tally tally;
	char *latest_joint;	/* mechanism of the latest accepted sample */
	double *latest_vel;
	long latest_index;	/* -1: none yet */
	char what[96];		/* what this run changed (the history) */
	double active;		/* seconds spent sampling before t_start */
	double t_start;		/* when the current pool started */
};

struct tui;
struct tui_solve;

/* The screens behind the dispatcher in tui.c. */
enum tui_screen_id {
	TUI_SCREEN_MAIN,
	TUI_SCREEN_HELP,
	TUI_SCREEN_HISTORY,
	TUI_SCREEN_COUNT
};

/* key() answers one key and returns the screen to show next. */
struct tui_screen {
	void (*init)(struct tui *t);
	enum tui_screen_id (*key)(struct tui *t, int ch);
	void (*draw)(struct tui *t);
};

typedef void (*tui_prompt_done)(struct tui *t, const char *text);

struct tui {
	struct wall *w;		/* the wall being sampled (finished) */
	struct undo undo;	/* the walls before and after (u, U) */
	char next_what[96];	/* what the next run changes */
	struct tui_run run;
	int runno;		/* runs started in this session */
	char **files;		/* every file the session wrote, as */
	int nfiles;		/* "samples: PATH", "wall: PATH", ... */
	char session[24];	/* when the session started (the history) */
	struct history_row *hist;	/* this session's finished runs */
	int nhist;
	char hist_path[PATH_MAX];	/* the index file, or "" */
	double *prev_lam;	/* the previous run's accepted loads, sorted */
	size_t prev_n;
	int prev_run;
	int threads;
	long target;		/* samples per run; 0: the wall's analysis.samples */

	struct tui_solve *solve;/* standard/gilbert for this wall */
	int has_std, has_gil;	/* the values below are known */
	int solve_done;
	double solve_t0;	/* when the solve thread started */
	double lam_std, lam_gil;

	int utf8;		/* the locale's codeset is UTF-8 */
	int colors;		/* has_colors() */
	int rows, cols;
	enum tui_screen_id screen;

	/* the prompt line (owned by tui_edit.c) */
	int prompting;
	char plabel[64];
	char pbuf[PATH_MAX];
	int plen;
	tui_prompt_done pdone;

	char msg[2 * SW_ERRLEN];/* message line; msg_err: show as an error */
	int msg_err;

	int mech_sel;		/* 0: latest accepted; k: k-th most frequent */
	int cursor_mode;	/* arrows move the block cursor, not the load */
	double cur_x, cur_y;	/* block cursor, wall coordinates */

	int quit;
};

/* tui.c */
/* A file the session wrote (kind: "samples", "wall", ...), printed at q. */
void tui_note_file(struct tui *t, const char *kind, const char *path);
void tui_message(struct tui *t, int is_err, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
/* Replace the wall (t takes nw, finished) and restart sampling on it. */
void tui_set_wall(struct tui *t, struct wall *nw);
/* The pool a signal handler should stop (NULL: none). */
void tui_signal_watch(struct mc *m);
/* A terminating signal has arrived: start nothing new. */
int tui_signal_pending(void);
double tui_now(void);
/* Draw a UTF-8 or an ASCII string depending on the locale. */
void tui_put(struct tui *t, int y, int x, const char *utf8, const char *ascii);
/* Draw s at (y, x), at most w columns (UTF-8 aware: one column per code
 * point, which holds for the text this program writes). */
void tui_text(int y, int x, int w, const char *s);
/* Code point k of s (its end if shorter). */
const char *tui_skip(const char *s, int k);
/* Columns of a UTF-8 string (one per code point). */
int tui_cols(const char *s);
/* The symbols of the locale: "λ" or "lam", "μ" or "mu". */
const char *tui_lam(const struct tui *t);
const char *tui_mu(const struct tui *t);
/* The unit of λ: "N" (point loads) or "load factor" (a body load). */
const char *tui_load_unit(const struct wall *w);

/* tui_run.c */
void tui_run_start(struct tui *t);	/* new CSV, new tally, sample */
void tui_run_end(struct tui *t);	/* drain, close the CSV, free */
int tui_run_pump(struct tui *t, double budget);	/* pop what is ready */
void tui_run_pause(struct tui *t, int pause);
void tui_run_set_target(struct tui *t, long n);
double tui_run_rate(const struct tui *t);	/* samples per second */
/* The samples in progress (0 when no pool runs). */
int tui_run_progress(struct tui *t, struct mc_progress *p);
/* "12 s", "3:05", "1:02:03" (or "?"). */
void tui_duration(char *buf, size_t len, double s);
const char *tui_run_state(const struct tui *t);	/* "running", ... */

/* tui_solve.c: standard and gilbert on a private copy of the wall */
struct tui_solve *tui_solve_start(const struct wall *w);
/* 1 when finished (values filled; has_* say which exist), else 0. */
int tui_solve_poll(struct tui_solve *s, int *has_std, double *std,
		   int *has_gil, double *gil);
/* The values as text: 1 with both filled ("235.4", "n/a"), or 0 with
 * sv saying how long they have been computing ("computing... 12 s"). */
int tui_solve_text(const struct tui *t, char *sv, char *gv, size_t len);
/* The caller lets go: the thread frees everything when it ends. */
void tui_solve_abandon(struct tui_solve *s);

/* tui_wall.c */
void tui_wall_draw(struct tui *t, int y0, int x0, int h, int w);
/* Move the first point load to the next boundary station in direction
 * (dx, dy) (one of the arrow keys); 0 if there is none. */
int tui_wall_load_step(const struct wall *w, int dx, int dy, double at[2]);
/* Move at to the nearest boundary station of w, preferring faces that a
 * load of direction dir acts across; 0 if there is none. */
int tui_wall_load_nearest(const struct wall *w, const double dir[2],
			  double at[2]);
/* The mechanism shown: joint states and velocities, label; 0 if none. */
int tui_wall_mechanism(const struct tui *t, const char **joint,
		       const double **vel, char *label, size_t len, int w);
int tui_wall_block_at(const struct wall *w, double x, double y);
/* The wall point under screen cell (y, x) in the last drawing; 0 if
 * none has been drawn. */
int tui_wall_point(int y, int x, double *wx, double *wy);

/* tui_hist.c */
void tui_hist_draw(struct tui *t, int y0, int x0, int h, int w);

/* tui_stats.c */
/* Returns the rows it used. */
int tui_stats_draw(struct tui *t, int y0, int x0, int h, int w);

/* tui_edit.c: the main screen */
void tui_main_init(struct tui *t);
enum tui_screen_id tui_main_key(struct tui *t, int ch);
void tui_main_draw(struct tui *t);
void tui_prompt(struct tui *t, const char *label, const char *initial,
		tui_prompt_done done);
/* A copy of w to edit: unfinished, without the generated ground, marks
 * cleared.  regen (or NULL): a layout whose blocks replace the generated
 * ones (layout_generate; the other blocks are kept); skip: a block index
 * to leave out (-1: none).  NULL + err on failure. */
struct wall *tui_edit_copy(const struct wall *w,
			   const struct wall_layout *regen, int skip, char *err);
/* Finish nw and switch to it (the current wall goes on the undo stack;
 * `what` names the edit in the message and the history); on failure
 * show the message, free nw and keep the current wall.  Returns 0 on
 * success. */
int tui_edit_apply(struct tui *t, struct wall *nw, const char *what);

/* tui_file.c */
void tui_file_save(struct tui *t);	/* asks for a path */
void tui_file_open(struct tui *t);	/* asks for a path */
void tui_file_report(struct tui *t);	/* asks for a directory */
/* The directory and name of the next samples file. */
int tui_file_csv_path(struct tui *t, char *out, size_t len, char *err);

/* tui_history.c */
void tui_history_record(struct tui *t);	/* the current run ends */
void tui_history_lines(const struct tui *t, const struct history_row *h,
		       char *a, size_t alen, char *b, size_t blen);
void tui_history_print(const struct tui *t, FILE *f);
void tui_history_free(void);
void tui_history_init(struct tui *t);
enum tui_screen_id tui_history_key(struct tui *t, int ch);
void tui_history_draw(struct tui *t);
/* s in at most w columns, its middle cut ("/home/…/demo-1.csv"). */
void tui_abbrev(const struct tui *t, char *out, size_t len, const char *s,
		int w);

/* tui_help.c */
void tui_help_init(struct tui *t);
enum tui_screen_id tui_help_key(struct tui *t, int ch);
void tui_help_draw(struct tui *t);

#endif
