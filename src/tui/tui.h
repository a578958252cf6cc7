/*
 * tui.h - the workbench's internal map: one state struct, one file per
 * screen or pane, one UI thread.
 *
 * Who does what, from the top of the calls down (a file calls only
 * files below it; tui_draw.c, tui_signal.c and tui_fatal.c call none):
 *   tui.c        tui_main: the terminal, the poll() loop, the screens
 *   tui_home.c   the main screen: its layout, its keys through tui_keys.c
 *   tui_help.c   the help screen, made from tui_keys.c's table
 *   tui_meaning.c its second page: what the numbers mean
 *   tui_keys.c   the one key table (dispatch, status line, help) and the
 *                main screen's own keys
 *   tui_confirm.c the question before a key ends a long run (y/n)
 *   tui_knobs.c  T (worker threads) and G (the design load)
 *   tui_history.c the run history: its rows, the H screen, what q prints
 *                (tui_run.c reaches it only through t->run_ended)
 *   tui_compare.c two runs of H compared, a run's wall kept and reopened,
 *                p05 against the previous run
 *   tui_pair.c   the sample browser's = (the pair of a mechanism, or of
 *                a family): it reads the browser, the run and the panes
 *   tui_io.c     the keys that read and write files: save, open, report
 *   tui_edit.c   the edits of the wall (through src/lib/wedit.c), undo
 *   tui_wall.c   the wall pane: sketch, mechanism, load, block cursor
 *   tui_stats.c  the statistics pane
 *   tui_hist.c   the histogram pane
 *   tui_pace.c   the time left of a run (an estimate)
 *   tui_solve.c  the one solve thread: standard and gilbert of the wall
 *   tui_run.c    one sampling run: the mc pool, the samples CSV, the tally
 *   tui_browse.c the sample browser: the run's samples kept (tui_run.c
 *                pushes them), the one on show, its keys
 *   tui_present.c the presentation mode: large digits, auto-play (it
 *                steps the browser)
 *   tui_file.c   where the samples files go, and their names
 *   tui_prompt.c the prompt line
 *   tui_signal.c SIGINT, SIGTERM, SIGHUP; Ctrl-Z (SIGTSTP)
 *   tui_fatal.c  any other end (abort, a fault, exit): the terminal back,
 *                the reason on stderr
 *   tui_draw.c   text helpers, the message line, the clock
 *
 * Threads: only the UI thread (the one in tui_main) calls curses, reads
 * or writes `struct tui`.  The sampler's workers and the solve thread
 * never see it: they read a finished wall (the solve thread its own
 * copy) and publish through mc_pop() and tui_solve_poll().
 */
#ifndef SLIPWALL_TUI_H
#define SLIPWALL_TUI_H

#include <limits.h>

#include <stdio.h>

#include "slipwall/history.h"
#include "slipwall/mc.h"
#include "slipwall/record.h"
#include "slipwall/run.h"
#include "slipwall/runlog.h"
#include "slipwall/sample.h"
#include "slipwall/stats.h"
#include "slipwall/sys.h"
#include "slipwall/family.h"
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
	/* the tally's mechanism families (docs/statistics.md): a cache,
	 * brought up to date where it is read (tui_run_families) */
	struct family_set *fams;
	char *latest_joint;	/* mechanism of the latest accepted sample */
	double *latest_vel;
	long latest_index;	/* -1: none yet */
	char what[96];		/* what this run changed (the history) */
	double active;		/* seconds spent sampling before t_start */
	double worked;		/* worker seconds of the samples given
				 * before t_start (mc_progress) */
	double t_start;		/* when the current pool started */
	double apriori;		/* tui_pace_apriori of its wall at its start */
};

/* The sample browser (tui_browse.c): the run's latest samples, kept in
 * a ring (sample i in slot i % cap), and the one on show. */
struct tui_browse {
	int open;
	long at;		/* the sample shown (its index) */
	long cap;		/* slots; 0: none could be kept */
	long next;		/* the index of the next sample pushed */
	int nifaces, nblocks, has_mu;
	int pick;		/* the joint picked with < > (1 first), 0: none */
	double *lam;		/* cap: lambda_min (not scaled) */
	signed char *status;	/* cap: enum sample_status */
	char *joint;		/* cap * (nifaces + 1) */
	double *xi;		/* cap * 2 * nifaces */
	double *mu;		/* cap * nifaces, or NULL (fixed friction) */
	double *vel;		/* cap * 3 * nblocks */
};

/* A kept sample, as tui_browse_shown gives it (pointers into the ring,
 * valid until the next sample is pushed). */
struct tui_browse_sample {
	long index;
	int status;
	double lam;		/* lambda_min, not scaled (tui_load scales) */
	const char *joint;
	const double *xi, *mu, *vel;	/* mu NULL: fixed friction */
};

/* Two runs of H compared (tui_compare.c): A the upper row (the earlier
 * run), B the lower; their loads read from their samples files. */
struct tui_cmp {
	int a, b;		/* H's row numbers; -1: not read */
	double *la, *lb;	/* accepted loads, sorted (malloc'd) */
	long na, nb;
	int ks_ok;		/* ks holds the test of B (x) against A (y) */
	struct stats_ks ks;
	char err[SW_ERRLEN + 64];	/* why they could not be read */
	char note[SW_ERRLEN];	/* read, with a caveat */
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

/* Where the wall pane drew the wall last (tui_wall.c), for the mouse:
 * screen cell (y + r, x + c) is the wall point (x0 + (c - c0) / sx,
 * y1 - (r - r0) / sy). */
struct tui_wall_view {
	int ok;			/* 0: nothing drawn yet */
	int y, x;		/* the screen cell of canvas cell (0, 0) */
	double x0, y1, sx, sy, c0, r0;
};

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
	double prev_p05;	/* the previous run's p05 (tui_compare_p05) */
	int threads;
	long target;		/* samples per run; 0: the wall's analysis.samples */
	/* the last run that took a sample: its worker seconds a sample,
	 * the a-priori figure of its wall and that wall's file, which seed
	 * the next run's a-priori figure (tui_pace_apriori) */
	double pace_s, pace_apriori;
	char pace_path[PATH_MAX];
	/* called when a run ends, its file closed and its tally whole
	 * (tui_main sets tui_history_record): tui_run.c calls nothing above
	 * it */
	void (*run_ended)(struct tui *t);

	struct tui_solve *solve;/* the solve thread (standard, gilbert) */
	/* the last pool's set-up (mc_setup): the next pool's starts while
	 * the wall keeps its shape (tui_run.c; docs/design.md, "The shared
	 * set-up") */
	struct sample_setup *setup;
	/* why the wall's joints lock under associative friction
	 * (wall_friction_lock; tui_edit_lock), or "" */
	char lock[192];
	/* which blocks rest on no joint (wall_hanging) and which overhang
	 * what they rest on (wall_overhang_text); tui_edit_lock; or "" */
	char hang[640];
	int has_std, has_gil;	/* the values below are known */
	int solve_done;
	double solve_t0;	/* when the solve thread started */
	double lam_std, lam_gil;

	int utf8;		/* the locale's codeset is UTF-8 */
	int colors;		/* has_colors() */
	int rows, cols;
	enum tui_screen_id screen;

	/* the prompt line (owned by tui_prompt.c) */
	int prompting;
	char plabel[64];
	char pbuf[PATH_MAX];
	int plen;
	tui_prompt_done pdone;
	/* Tab in the prompt (tui_complete.c): the text after the last Tab,
	 * and the candidates listed above the prompt while it is still
	 * that text */
	char pcomp[PATH_MAX];
	char pcands[1024];
	int pcands_on;

	char msg[2 * SW_ERRLEN];/* message line; msg_err: show as an error */
	int msg_err;
	/* an error that must not be lost under the next message (the run
	 * history could not be written): shown above the message line
	 * until the next key (tui_note) */
	char note[2 * SW_ERRLEN];
	char hist_err[SW_ERRLEN];	/* why the history is not kept */

	/* the screens' own state: what each screen or pane keeps between
	 * frames is here, not in its file (tui_signal.c and tui_fatal.c keep
	 * theirs in statics: their signal handlers have no argument) */
	int help_top;		/* help: lines scrolled away */
	int hist_top;		/* H: lines scrolled away; -1: at the bottom */
	struct history_row *hist_old;	/* H: rows of earlier sessions */
	int hist_nold;
	char hist_rerr[SW_ERRLEN + 64];	/* H: why they could not be read */
	int hist_cur;		/* H: the selected row; -1: the last */
	int hist_mark[2];	/* H: the marked rows, -1: none */
	char hist_msg[PATH_MAX + SW_ERRLEN];	/* H: why a wall was not reopened */
	struct tui_cmp cmp;	/* H: the two marked runs compared */
	struct tui_wall_view wall_view;	/* the wall pane's last drawing */

	struct tui_browse browse;	/* the sample browser (S) */
	int mech_sel;		/* 0: latest accepted; k: k-th most frequent */
	int cursor_mode;	/* arrows move the block cursor, not the load */
	double cur_x, cur_y;	/* block cursor, wall coordinates */

	int help_page;		/* help: 0 the keys, 1 what the numbers mean */
	int present;		/* the presentation mode (tui_present.c) */
	int present_play;	/* its auto-play steps the browser */
	double present_next;	/* when auto-play steps next (sys_now) */
	/* a key that throws away more than a minute of sampling waits
	 * for y (tui_confirm.c); NULL: none waits */
	const struct tui_key *confirm_key;
	int confirm_ch;
	/* a key other than q came while the terminal was too small (tui.c:
	 * it waits for a larger one, and the small screen says so) */
	int small_keys;

	int quit;
};

/* tui_draw.c: the leaf */
void tui_message(struct tui *t, int is_err, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
/* An error shown above the message line until the next key. */
void tui_note(struct tui *t, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* A file the session wrote (kind: "samples", "wall", ...), printed at q. */
void tui_note_file(struct tui *t, const char *kind, const char *path);
/* Draw a UTF-8 or an ASCII string depending on the locale. */
void tui_put(struct tui *t, int y, int x, const char *utf8, const char *ascii);
/* Draw s at (y, x), at most w columns (UTF-8 aware: one column per code
 * point, which holds for the text this program writes). */
void tui_text(int y, int x, int w, const char *s);
/* tui_text, but a string longer than w columns ends in the locale's
 * "…" (or "~") in its last column, so that a cut shows. */
void tui_text_cut(const struct tui *t, int y, int x, int w, const char *s);
/* The locale's mark of a cut: "…" or "~". */
const char *tui_dots(const struct tui *t);
/* Code point k of s (its end if shorter). */
const char *tui_skip(const char *s, int k);
/* Columns of a UTF-8 string (one per code point). */
int tui_cols(const char *s);
/* s in at most w columns, its middle cut ("/home/…/demo-1.csv"). */
void tui_abbrev(const struct tui *t, char *out, size_t len, const char *s,
		int w);
/* Row y as a full-width bar (title and status lines). */
void tui_bar(struct tui *t, int y, const char *text);
/* The symbols of the locale: "λ" or "lam", "μ" or "mu". */
const char *tui_lam(const struct tui *t);
const char *tui_mu(const struct tui *t);
/* "μ BED/HEAD", and " cov C" when the friction is random (C > 0): the
 * friction as the home line, the history and compare show it; buf. */
const char *tui_friction(const struct tui *t, char *buf, size_t len,
			 double bed, double head, double cov);
/* "s" unless n is 1: "%d run%s", n, tui_s(n). */
const char *tui_s(long n);
/* A probability as a percentage, "0.1 %", "98 %", "< 0.01 %" ("-": NaN). */
void tui_pct(char *buf, size_t len, double p);
/* The unit of the loads shown (wall_quantity): "N" (point loads of one
 * magnitude), else what they are ("seismic coefficient", "load factor"). */
const char *tui_load_unit(const struct wall *w);
/* A single solution's load factor as the run's loads are shown (the
 * tally's quantity: wall_quantity's scale times lambda). */
double tui_load(const struct tui *t, double lambda);

/* tui_fatal.c: tui_fatal_begin before curses starts (stderr to a
 * temporary file, the terminal's modes saved; -1: stderr unchanged),
 * tui_fatal_arm once it has (mouse: the mouse is on): from then on an
 * abort, a fault or exit() restores the terminal, prints the temporary
 * file and the reason on the real stderr, and dies as it would have;
 * tui_fatal_end after endwin: the handlers off, the file printed. */
int tui_fatal_begin(void);
void tui_fatal_arm(int mouse);
void tui_fatal_end(void);

/* The mouse wheel as KEY_UP / KEY_DOWN, another mouse event as 0, any
 * other key as itself (tui_history.c; the help and H scroll with it). */
int tui_wheel(int ch);

/* tui_signal.c */
int tui_signal_install(void);	/* before curses starts; -1 on failure */
/* The pool a signal handler should stop (NULL: none). */
void tui_signal_watch(struct mc *m);
/* A terminating signal has arrived: start nothing new. */
int tui_signal_pending(void);
/* Ctrl-Z has arrived: end curses, then tui_signal_stop. */
int tui_signal_suspend_pending(void);
/* Stop the process (SIGTSTP's default); returns when it continues. */
void tui_signal_stop(void);

/* tui_prompt.c */
void tui_prompt(struct tui *t, const char *label, const char *initial,
		tui_prompt_done done);
/* The prompt's keys (tui_keys.c's table), while t->prompting: */
void tui_prompt_accept(struct tui *t, int ch);	/* Enter */
void tui_prompt_cancel(struct tui *t, int ch);	/* Esc, Ctrl-G */
void tui_prompt_erase(struct tui *t, int ch);	/* Backspace */
void tui_prompt_clear(struct tui *t, int ch);	/* Ctrl-U */
void tui_prompt_type(struct tui *t, int ch);	/* any other: typed */
void tui_prompt_draw(struct tui *t, int y);
/* tui_complete.c: Tab, file names completed (save, report, open) */
void tui_prompt_complete(struct tui *t, int ch);

/* tui_file.c */
/* The runs directory: $SLIPWALL_RUNS, else $XDG_DATA_HOME/slipwall/runs
 * (an absolute $XDG_DATA_HOME), else ~/.local/share/slipwall/runs; made
 * when missing.  -1 and err when there is no such place or it cannot be
 * made. */
int tui_file_runs_dir(char *out, size_t len, char *err);
/* The wall's short name: file name without directory and .yaml. */
void tui_file_stem(const struct wall *w, char *out, size_t len);
/* The directory and name of the next samples file. */
int tui_file_csv_path(struct tui *t, char *out, size_t len, char *err);
/* Save the run's wall beside its samples file (X.csv: X.yaml) when it
 * starts; a failure is said and the run goes on. */
void tui_file_save_run_wall(struct tui *t);
/* The wall file beside a samples file; 0 when csv is not "X.csv". */
int tui_file_run_wall_path(const char *csv, char *out, size_t len);

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

/* tui_solve.c: standard and gilbert of the wall, on one thread */
struct tui_solve *tui_solve_new(void);
/* Solve w (copied) next: a solve still running is stopped, and w's
 * starts when it has ended (walls handed over meanwhile replace w). */
void tui_solve_wall(struct tui_solve *s, const struct wall *w);
/* Every tick: 1 when the latest wall's values are known (has_* say
 * which exist), else 0; starts the waiting wall's thread. */
int tui_solve_poll(struct tui_solve *s, int *has_std, double *std,
		   int *has_gil, double *gil);
/* The values as text: 1 with both filled ("235.4", "n/a"), or 0 with
 * sv saying how long they have been computing ("computing... 12 s"). */
int tui_solve_text(const struct tui *t, char *sv, char *gv, size_t len);
/* Stop the thread, join it (quick once stopped), free; NULL is fine. */
void tui_solve_free(struct tui_solve *s);

/* tui_wall.c */
void tui_wall_draw(struct tui *t, int y0, int x0, int h, int w);
/* The run's mechanism families, up to date with its tally (NULL: no
 * run). */
struct family_set *tui_run_families(const struct tui *t);
/* The family in fs (tui_run_families') of mechanism joint, or -1 when
 * the tally does not have it (or fs is NULL). */
int tui_run_family_of(const struct tui *t, const struct family_set *fs,
		      const char *joint);
/* The family of mechanism joint: its place among the most frequent
 * families (m/M's number), 1 .. *n, or 0 when the tally does not have
 * it. */
int tui_family_rank(const struct tui *t, const char *joint, int *n);
/* m/M's family on show (0: none, the latest mechanism): its index in
 * tui_run_families, or -1. */
int tui_family_shown(const struct tui *t);
/* The mechanism shown: joint states and velocities, label; 0 if none. */
int tui_wall_mechanism(const struct tui *t, const char **joint,
		       const double **vel, char *label, size_t len, int w);
/* The wall point under screen cell (y, x) in the last drawing; 0 if
 * none has been drawn. */
int tui_wall_point(const struct tui *t, int y, int x, double *wx,
		   double *wy);

/* tui_hist.c */
void tui_hist_draw(struct tui *t, int y0, int x0, int h, int w);

/* tui_browse.c */
/* A new run on t->w: the ring made anew (the browser stays open). */
void tui_browse_reset(struct tui *t);
void tui_browse_free(struct tui *t);
/* After each sample of the run (tui_run.c), in index order. */
void tui_browse_push(struct tui *t, const struct record *rec);
/* The sample on show: 1 with it, 0 when the browser is closed or keeps
 * no sample yet. */
int tui_browse_shown(const struct tui *t, struct tui_browse_sample *s);
/* The mechanism's place among the most frequent ones (m/M's number),
 * 1 .. *n (the tally's count), or 0 when the tally does not have it. */
int tui_browse_mech_rank(const struct tui *t, const char *joint, int *n);
/* The oldest kept sample's index (-1: none). */
long tui_browse_first(const struct tui *t);
/* Sample i, kept (tui_browse_first .. browse.next - 1): 1, else 0. */
int tui_browse_sample_at(const struct tui *t, long i,
			 struct tui_browse_sample *s);
/* The browser's keys (tui_keys.c's table): */
void tui_browse_key_toggle(struct tui *t, int ch);	/* S, Esc */
void tui_browse_key_step(struct tui *t, int ch);	/* [ ] Home End */
void tui_browse_key_joint(struct tui *t, int ch);	/* < > */
/* The pair of the shown sample's mechanism, or family (tui_pair.c): = */
void tui_pair_key(struct tui *t, int ch);
/* A click on the wall with the browser open: the joint nearest the
 * point (wall coordinates) is picked. */
void tui_browse_pick_at(struct tui *t, double x, double y);

/* tui_present.c: the presentation mode */
/* The main screen's panes in presentation mode, rows top .. bottom-1. */
void tui_present_draw(struct tui *t, int top, int bottom);
/* Each turn of the UI loop: auto-play's step; 1 when it stepped. */
int tui_present_tick(struct tui *t);
void tui_present_key_toggle(struct tui *t, int ch);	/* F5, V */
void tui_present_key_play(struct tui *t, int ch);	/* A */

/* tui_stats.c */
/* Returns the rows it used. */
int tui_stats_draw(struct tui *t, int y0, int x0, int h, int w);

/* tui_edit.c: the edits; the tui_edit_key_* are the main screen's
 * handlers of their keys (tui_home.c's table) */
/* Replace the wall (t takes nw, finished): a new run, a new solve. */
void tui_edit_set_wall(struct tui *t, struct wall *nw);
void tui_edit_lock(struct tui *t);
void tui_edit_lock_message(struct tui *t);
void tui_edit_key_undo(struct tui *t, int ch);		/* u, U, Ctrl-R */
void tui_edit_key_friction(struct tui *t, int ch);	/* f, F */
void tui_edit_key_depth(struct tui *t, int ch);		/* e, E, i */
void tui_edit_key_turn(struct tui *t, int ch);		/* d, D */
void tui_edit_key_bond(struct tui *t, int ch);		/* b, B */
void tui_edit_key_prompt(struct tui *t, int ch);	/* g, v, P, c, L, w */
void tui_edit_key_block(struct tui *t, int ch);		/* a, x, Delete */
/* The point load to the next station in direction (dx, dy). */
void tui_edit_load_step(struct tui *t, int dx, int dy);
/* The point load to the station nearest (x, y) (a right click). */
void tui_edit_load_to(struct tui *t, double x, double y);

/* tui_io.c: each asks for a path on the prompt line */
void tui_io_save(struct tui *t);	/* s: the wall and a summary */
void tui_io_open(struct tui *t);	/* o: another wall */
void tui_io_report(struct tui *t);	/* R: a directory */

/* tui_report.c: what R says beyond `slipwall report`, and the defaults
 * of s and R beside the opened wall file */
/* DIR/STEM+suffix: DIR the opened wall file's directory, STEM the
 * samples file's name without .csv (or WALL-edited); -1 when the wall
 * came from no file. */
int tui_report_default(const struct tui *t, const char *suffix, char *out,
		       size_t len);
/* The command that reproduces the run's loads from wallpath into
 * DIR-rerun (malloc'd; NULL when out of memory). */
char *tui_report_command(const struct tui *t, const char *wallpath,
			 const char *dir);
/* The wall sampled in words, for report.md (malloc'd; NULL when out of
 * memory). */
char *tui_report_describe(const struct tui *t, const char *wallpath);

/* tui_keys.c: the workbench's keys, one table: the main screen's
 * dispatch, the status line and the help are made from it */
enum tui_keys_mode {
	TUI_KEYS_MAIN,		/* the main screen */
	TUI_KEYS_CURSOR,	/* the main screen in block cursor mode */
	TUI_KEYS_PROMPT,	/* the prompt line */
	TUI_KEYS_BROWSE,	/* the main screen with the sample browser */
	TUI_KEYS_PRESENT,	/* the presentation mode */
	TUI_KEYS_MODES
};
#define TUI_KEYS_NAME_W 12	/* the help's column of names */
struct tui_key {
	int ch[9];		/* the codes bound to it, 0 after the last */
	const char *name;	/* as the help shows it: "f / F" */
	const char *help;	/* what it does; "\n" starts a new line */
	struct {
		const char *text;	/* "f/F mu" */
		int at;			/* its place, 1 first; 0: not shown */
	} bar[TUI_KEYS_MODES];	/* on the status line, in each mode */
	void (*fn)(struct tui *t, int ch);	/* NULL: only a screen */
	enum tui_screen_id next;	/* the screen to show next */
	int prompt;		/* a key of the prompt line */
};
/* The key bound to ch on the main screen or (prompt) the prompt line;
 * NULL if none. */
const struct tui_key *tui_keys_find(int prompt, int ch);
/* The status line of the mode: the labels in their order, as many as
 * fit in cols - 1. */
void tui_keys_bar(enum tui_keys_mode mode, int cols, char *buf, size_t len);
/* Line `line` of the keys' part of the help; 0 past the last. */
int tui_keys_help(int line, char *buf, size_t len);

/* tui_pace.c: the time left of a run (docs/workbench.md, "Time
 * left").  0: nothing to say; 1: *left and *total from the a-priori
 * estimate alone (no sample finished); 2: from the measured rate; 3:
 * every sample left is in progress, and one has outlived *per, the
 * estimate of one sample: the time left is not known (mc_pace_left). */
int tui_pace_left(struct tui *t, double *left, double *total, double *per);
/* Seconds the current run has sampled (its pools' lifetimes). */
double tui_pace_sampled(const struct tui *t);
/* The a-priori seconds of a sample of the wall: mc_sample_seconds, or
 * after an edit of the same wall file the last run's measured figure
 * (tui_pace.c). */
double tui_pace_apriori(const struct tui *t);
/* The keys of tui_knobs.c (tui_keys.c's table): */
void tui_knobs_key_threads(struct tui *t, int ch);	/* T */
void tui_knobs_key_design(struct tui *t, int ch);	/* G */

/* tui_confirm.c: keys that throw away more than a minute of sampling
 * (edits, r, o, q) ask first.  tui_confirm_ask: 1 when k waits for the
 * answer (asked on the message line); tui_confirm_answer: the next key
 * answers (y: k runs). */
int tui_confirm_ask(struct tui *t, const struct tui_key *k, int ch);
enum tui_screen_id tui_confirm_answer(struct tui *t, int ch);

/* tui_home.c: the main screen */
void tui_home_init(struct tui *t);
enum tui_screen_id tui_home_key(struct tui *t, int ch);
void tui_home_draw(struct tui *t);

/* tui_history.c */
void tui_history_record(struct tui *t);	/* the current run ends */
void tui_history_lines(const struct tui *t, const struct history_row *h,
		       char *a, size_t alen, char *b, size_t blen);
void tui_history_print(const struct tui *t, FILE *f);
void tui_history_free(struct tui *t);	/* the H screen's rows */
void tui_history_init(struct tui *t);
enum tui_screen_id tui_history_key(struct tui *t, int ch);
void tui_history_draw(struct tui *t);
/* tui_meaning.c: line `line` of the help's second page ("what the
 * numbers mean"); 0 past the last. */
int tui_meaning_line(const struct tui *t, int line, char *buf, size_t len);

/* tui_compare.c */
/* The characteristic value's line with the previous run's, in at most
 * w columns: "p05 80.7 (run 1: 118.2, −32 %)"; 0 with no previous
 * run (the caller writes its own line). */
int tui_compare_p05(const struct tui *t, double p05, int w, char *out,
		    size_t len);
/* Read the marked rows' loads when the pair changed (h: H's rows in
 * order, n of them). */
void tui_compare_update(struct tui *t, const struct history_row *const *h,
			int n);
void tui_compare_free(struct tui *t);
/* The comparison of the two marked rows in rows y0 .. y0 + h - 1. */
void tui_compare_draw(struct tui *t, const struct history_row *const *h,
		      int y0, int h_rows);
/* Reopen row h's wall (H's o, Enter); 0 and t->hist_msg on failure. */
int tui_compare_reopen(struct tui *t, const struct history_row *h);

/* tui_help.c */
void tui_help_init(struct tui *t);
enum tui_screen_id tui_help_key(struct tui *t, int ch);
void tui_help_draw(struct tui *t);

/* The LP solvers' settings (tui_main's lp): every pool and solve of the
 * workbench copies them into its options. */
extern struct sample_lp_config tui_lp;

#endif
