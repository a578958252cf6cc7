/*
 * tui_home.c - the main screen: its keys and its layout (title, wall
 * pane, statistics, histogram, message and status lines).
 *
 * Keys go through one table (tui_home_keys: key -> handler, and the
 * screen it opens); the edits of the wall are tui_edit.c's handlers,
 * the files tui_io.c's, the rest (pause, reset, the sample target, the
 * mechanism on show, the block cursor, the mouse) are here.  While the
 * prompt line is open every key goes to it (tui_prompt.c).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <curses.h>

#include "slipwall/text.h"
#include "slipwall/wedit.h"
#include "tui.h"

static void tui_home_quit(struct tui *t, int ch)
{
	(void)ch;
	t->quit = 1;
}

static void tui_home_pause(struct tui *t, int ch)
{
	(void)ch;
	tui_run_pause(t, !t->run.paused);
	tui_message(t, 0, "%s at %ld samples",
		    t->run.paused ? "paused" : "resumed", t->run.done);
}

static void tui_home_reset(struct tui *t, int ch)
{
	(void)ch;
	tui_run_end(t);
	tui_run_start(t);
	tui_message(t, 0, "reset: sampling again (run %d)", t->runno);
}

static void tui_home_target_typed(struct tui *t, const char *text)
{
	long n;
	if (text_parse_long(text, 1, 1000000000L, &n)) {
		tui_message(t, 1, "sample target: a whole number from 1 to 1e9");
		return;
	}
	tui_run_set_target(t, n);
	tui_message(t, 0, "sample target %ld", n);
}

static void tui_home_target(struct tui *t, int ch)
{
	char buf[32];
	(void)ch;
	snprintf(buf, sizeof buf, "%ld", t->run.target);
	tui_prompt(t, "sample target", buf, tui_home_target_typed);
}

/* m, M: the next or the previous mechanism on show (0: the latest). */
static void tui_home_mech(struct tui *t, int ch)
{
	int nmech = t->run.tally.nmech;
	t->mech_sel = (t->mech_sel + (ch == 'm' ? 1 : nmech)) % (nmech + 1);
}

/* The block cursor is within a block's size of the wall. */
static int tui_home_cursor_near(struct tui *t)
{
	if (!isfinite(t->cur_x) || !isfinite(t->cur_y))
		return 0;
	double x = t->cur_x, y = t->cur_y;
	wedit_cursor(t->w, &t->cur_x, &t->cur_y, 0, 0);
	return x == t->cur_x && y == t->cur_y;
}

/* Arrows and hjkl: the block cursor (half a block across, a block up
 * or down) or the load (to the next station of the outline). */
static void tui_home_arrow(struct tui *t, int ch)
{
	int dx = ch == KEY_RIGHT || ch == 'l' ? 1 : ch == KEY_LEFT || ch == 'h' ? -1 : 0;
	int dy = ch == KEY_UP || ch == 'k' ? 1 : ch == KEY_DOWN || ch == 'j' ? -1 : 0;
	if (t->cursor_mode)
		wedit_cursor(t->w, &t->cur_x, &t->cur_y, dx, dy);
	else
		tui_edit_load_step(t, dx, dy);
}

static void tui_home_tab(struct tui *t, int ch)
{
	const struct wall *w = t->w;
	(void)ch;
	t->cursor_mode = !t->cursor_mode;
	/* the cursor stays where it was; placed on a block the first time
	 * (and when the wall changed so that it is far off) */
	if (t->cursor_mode && !tui_home_cursor_near(t)) {
		for (int k = 0; k < w->nblocks; k++)
			if (!w->blocks[k].fixed) {
				t->cur_x = w->blocks[k].cx;
				t->cur_y = w->blocks[k].cy;
				break;
			}
	}
	tui_message(t, 0, t->cursor_mode ? "block cursor: arrows move it, a adds, x removes, Tab back"
					 : "arrows move the load");
}

/* A click on the wall: the left button selects the block under it (the
 * block cursor goes there), the right one moves the load to the nearest
 * place of the outline (an edit, as the arrows make). */
static void tui_home_mouse(struct tui *t, int ch)
{
	MEVENT ev;
	double x, y;
	(void)ch;
	if (getmouse(&ev) != OK || !tui_wall_point(ev.y, ev.x, &x, &y) ||
	    ev.x >= t->cols * 55 / 100)
		return;
	if (ev.bstate & (BUTTON1_PRESSED | BUTTON1_CLICKED)) {
		int k = wedit_block_at(t->w, x, y);
		if (k < 0) {
			tui_message(t, 0, "no block there");
			return;
		}
		t->cursor_mode = 1;
		t->cur_x = t->w->blocks[k].cx;
		t->cur_y = t->w->blocks[k].cy;
		tui_message(t, 0, "block %s selected: a add, x remove, Tab back",
			    t->w->blocks[k].id);
	} else if (ev.bstate & (BUTTON3_PRESSED | BUTTON3_CLICKED)) {
		tui_edit_load_to(t, x, y);
	}
}

static void tui_home_redraw(struct tui *t, int ch)
{
	(void)t;
	(void)ch;
	clearok(curscr, TRUE);
}

static void tui_home_save(struct tui *t, int ch)
{
	(void)ch;
	tui_io_save(t);
}

static void tui_home_open(struct tui *t, int ch)
{
	(void)ch;
	tui_io_open(t);
}

static void tui_home_report(struct tui *t, int ch)
{
	(void)ch;
	tui_io_report(t);
}

/* The keys of the main screen: a handler, or a screen to open. */
static const struct tui_home_key {
	int ch;
	void (*fn)(struct tui *t, int ch);
	enum tui_screen_id next;
} tui_home_keys[] = {
	{'q', tui_home_quit, TUI_SCREEN_MAIN},
	{'Q', tui_home_quit, TUI_SCREEN_MAIN},
	{'?', NULL, TUI_SCREEN_HELP},
	{'H', NULL, TUI_SCREEN_HISTORY},
	{' ', tui_home_pause, TUI_SCREEN_MAIN},
	{'p', tui_home_pause, TUI_SCREEN_MAIN},
	{'r', tui_home_reset, TUI_SCREEN_MAIN},
	{'n', tui_home_target, TUI_SCREEN_MAIN},
	{'m', tui_home_mech, TUI_SCREEN_MAIN},
	{'M', tui_home_mech, TUI_SCREEN_MAIN},
	{'f', tui_edit_key_friction, TUI_SCREEN_MAIN},
	{'F', tui_edit_key_friction, TUI_SCREEN_MAIN},
	{'g', tui_edit_key_prompt, TUI_SCREEN_MAIN},
	{'e', tui_edit_key_depth, TUI_SCREEN_MAIN},
	{'E', tui_edit_key_depth, TUI_SCREEN_MAIN},
	{'i', tui_edit_key_depth, TUI_SCREEN_MAIN},
	{'u', tui_edit_key_undo, TUI_SCREEN_MAIN},
	{'U', tui_edit_key_undo, TUI_SCREEN_MAIN},
	{18, tui_edit_key_undo, TUI_SCREEN_MAIN},	/* Ctrl-R */
	{KEY_UP, tui_home_arrow, TUI_SCREEN_MAIN},
	{KEY_DOWN, tui_home_arrow, TUI_SCREEN_MAIN},
	{KEY_LEFT, tui_home_arrow, TUI_SCREEN_MAIN},
	{KEY_RIGHT, tui_home_arrow, TUI_SCREEN_MAIN},
	{'h', tui_home_arrow, TUI_SCREEN_MAIN},
	{'j', tui_home_arrow, TUI_SCREEN_MAIN},
	{'k', tui_home_arrow, TUI_SCREEN_MAIN},
	{'l', tui_home_arrow, TUI_SCREEN_MAIN},
	{'d', tui_edit_key_turn, TUI_SCREEN_MAIN},
	{'D', tui_edit_key_turn, TUI_SCREEN_MAIN},
	{'P', tui_edit_key_prompt, TUI_SCREEN_MAIN},
	{'c', tui_edit_key_prompt, TUI_SCREEN_MAIN},
	{'L', tui_edit_key_prompt, TUI_SCREEN_MAIN},
	{'w', tui_edit_key_prompt, TUI_SCREEN_MAIN},
	{'b', tui_edit_key_bond, TUI_SCREEN_MAIN},
	{'B', tui_edit_key_bond, TUI_SCREEN_MAIN},
	{'\t', tui_home_tab, TUI_SCREEN_MAIN},
	{'a', tui_edit_key_block, TUI_SCREEN_MAIN},
	{'x', tui_edit_key_block, TUI_SCREEN_MAIN},
	{KEY_DC, tui_edit_key_block, TUI_SCREEN_MAIN},
	{'s', tui_home_save, TUI_SCREEN_MAIN},
	{'o', tui_home_open, TUI_SCREEN_MAIN},
	{'R', tui_home_report, TUI_SCREEN_MAIN},
	{KEY_MOUSE, tui_home_mouse, TUI_SCREEN_MAIN},
	{12, tui_home_redraw, TUI_SCREEN_MAIN},	/* Ctrl-L */
};

void tui_home_init(struct tui *t)
{
	(void)t;
}

enum tui_screen_id tui_home_key(struct tui *t, int ch)
{
	if (t->prompting) {
		tui_prompt_key(t, ch);
		return TUI_SCREEN_MAIN;
	}
	for (size_t i = 0; i < sizeof tui_home_keys / sizeof *tui_home_keys; i++) {
		const struct tui_home_key *k = &tui_home_keys[i];
		if (k->ch != ch)
			continue;
		if (k->fn)
			k->fn(t, ch);
		return k->next;
	}
	return TUI_SCREEN_MAIN;
}

/* The title: the numbers always; the name's middle cut to fit, the
 * samples file only when there is room (H shows it). */
static void tui_home_title(struct tui *t)
{
	const struct wall *w = t->w;
	char buf[PATH_MAX + 512];
	const char *csv = strrchr(t->run.csv, '/');
	csv = csv ? csv + 1 : t->run.csv;
	char dtext[32];
	if (w->anywhere)
		snprintf(dtext, sizeof dtext, "points anywhere");
	else
		snprintf(dtext, sizeof dtext, "depth %.3g", w->depth);
	char rest[160], name[256], nm[256], file[PATH_MAX + 8];
	snprintf(rest, sizeof rest, "%s | %s %.3g/%.3g | %s | run %d %s",
		 undo_modified(&t->undo) ? " *" : "", tui_mu(t), w->mu_bed,
		 w->mu_head, dtext, t->runno, tui_run_state(t));
	snprintf(name, sizeof name, "%s",
		 w->name ? w->name : (w->path ? w->path : "wall"));
	snprintf(file, sizeof file, " | %s", csv[0] ? csv : "(no samples file)");
	int room = t->cols - 12 - tui_cols(rest);	/* " slipwall | " */
	if ((int)(tui_cols(name) + tui_cols(file)) > room)
		file[0] = 0;
	tui_abbrev(t, nm, sizeof nm, name, room);
	snprintf(buf, sizeof buf, " slipwall | %s%s%s", nm, rest, file);
	tui_bar(t, 0, buf);
}

/* The message line; a message longer than the line (paths) takes the
 * row above too, and the middle of the rest is cut. */
static void tui_home_message(struct tui *t)
{
	int R = t->rows, C = t->cols;
	int attr = t->msg_err ? (t->colors ? COLOR_PAIR(5) : A_BOLD) : 0;
	if (attr)
		attron(attr);
	if (tui_cols(t->msg) > C) {
		char rest[sizeof t->msg + 8];
		const char *s = tui_skip(t->msg, C);
		move(R - 3, 0);
		clrtoeol();
		tui_text(R - 3, 0, C, t->msg);
		tui_abbrev(t, rest, sizeof rest, s, C);
		tui_text(R - 2, 0, C, rest);
	} else {
		tui_text(R - 2, 0, C, t->msg);
	}
	if (attr)
		attroff(attr);
}

/* The note (tui_note): an error above the message line, until a key. */
static void tui_home_note(struct tui *t)
{
	char buf[sizeof t->note + 8];
	int attr = t->colors ? COLOR_PAIR(5) : A_BOLD;
	tui_abbrev(t, buf, sizeof buf, t->note, t->cols);
	attron(attr);
	move(t->rows - 3, 0);
	clrtoeol();
	tui_text(t->rows - 3, 0, t->cols, buf);
	attroff(attr);
}

/* The status line: the keys that work now, as many as fit. */
static void tui_home_keybar(struct tui *t)
{
	static const char *const kprompt[] = {"Enter accept", "Esc cancel",
					      "Ctrl-U clear", NULL};
	static const char *const kcursor[] = {
		"Tab load mode", "arrows/hjkl cursor", "a add", "x remove",
		"u undo", "? help", "q quit", NULL};
	static const char *const kmain[] = {
		"q quit", "? help", "spc pause", "u undo", "H history",
		"f/F mu", "e/E depth", "arrows load", "s save", "o open",
		"m mech", NULL};
	const char *const *keys = t->prompting ? kprompt
				  : t->cursor_mode ? kcursor : kmain;
	char buf[512];
	int len = 0;
	buf[0] = 0;
	for (int i = 0; keys[i]; i++) {
		int k = (int)strlen(keys[i]);
		if (len + 1 + k > t->cols - 1)
			break;
		len += snprintf(buf + len, sizeof buf - (size_t)len, " %s", keys[i]);
	}
	tui_bar(t, t->rows - 1, buf);
}

void tui_home_draw(struct tui *t)
{
	int R = t->rows, C = t->cols;
	tui_home_title(t);

	int top = 1, bottom = R - 2;	/* panes: rows top .. bottom-1 */
	int lw = C * 55 / 100;
	int rx = lw + 1, rw = C - rx;
	tui_wall_draw(t, top, 0, bottom - top, lw);
	for (int y = top; y < bottom; y++)
		tui_put(t, y, lw, "│", "|");
	int sh = tui_stats_draw(t, top, rx, bottom - top - 5, rw) + 1;
	tui_hist_draw(t, top + sh, rx, bottom - top - sh, rw);

	if (t->prompting)
		tui_prompt_draw(t, R - 2);
	else if (t->msg[0])
		tui_home_message(t);
	if (t->note[0])
		tui_home_note(t);
	tui_home_keybar(t);
}
