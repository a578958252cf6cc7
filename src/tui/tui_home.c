/*
 * tui_home.c - the main screen: its keys and its layout (title, wall
 * pane, statistics, histogram, message and status lines).
 *
 * Keys go through the workbench's one key table (tui_keys.c: key ->
 * handler, and the screen it opens), and the status line shows the
 * labels it gives the mode on show.  While the prompt line is open the
 * prompt's keys of the table work, and any other is typed into the
 * prompt (tui_prompt.c).  Any other key says on the message line that it
 * does nothing (docs/workbench.md, "Keys").
 */
#include <stdio.h>
#include <string.h>

#include <curses.h>

#include "tui.h"

void tui_home_init(struct tui *t)
{
	(void)t;
}

/* A key's name for a message: the character itself when printable
 * (keyname gives "^Z" for controls, "KEY_F(5)" for function keys). */
static const char *tui_home_keyname(int ch)
{
	static char buf[32];
	if (ch == ' ')
		return "space";
	const char *n = keyname(ch);
	snprintf(buf, sizeof buf, "%s", n ? n : "?");
	if (ch >= 128 && ch < 256)	/* a byte of a wide character */
		snprintf(buf, sizeof buf, "0x%02x", ch);
	return buf;
}

enum tui_screen_id tui_home_key(struct tui *t, int ch)
{
	if (t->confirm_key)	/* y or no (tui_confirm.c) */
		return tui_confirm_answer(t, ch);
	const struct tui_key *k = tui_keys_find(t->prompting, ch);
	if (!k) {
		if (t->prompting)
			tui_prompt_type(t, ch);	/* a character of the text */
		else if (ch != KEY_RESIZE && ch != KEY_MOUSE)
			tui_message(t, 0, "key %s does nothing here: ? lists the keys",
				    tui_home_keyname(ch));
		return TUI_SCREEN_MAIN;
	}
	if (tui_confirm_ask(t, k, ch))
		return TUI_SCREEN_MAIN;
	if (k->fn)
		k->fn(t, ch);
	return k->next;
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
	char rest[192], name[256], nm[256], file[PATH_MAX + 8], fr[64];
	snprintf(rest, sizeof rest, "%s | %s%s | %s | run %d %s",
		 undo_modified(&t->undo) ? " *" : "",
		 tui_friction(t, fr, sizeof fr, w->mu_bed, w->mu_head,
			      w->mu_cov), t->lock[0] ? " locks" : "", dtext,
		 t->runno, tui_run_state(t));
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

/* The status line: the keys that work now, as many as fit (their
 * labels in tui_keys.c's table). */
static void tui_home_keybar(struct tui *t)
{
	char buf[512];
	tui_keys_bar(t->prompting ? TUI_KEYS_PROMPT :
		     t->cursor_mode ? TUI_KEYS_CURSOR :
		     t->present ? TUI_KEYS_PRESENT :
		     t->browse.open ? TUI_KEYS_BROWSE : TUI_KEYS_MAIN,
		     t->cols, buf, sizeof buf);
	tui_bar(t, t->rows - 1, buf);
}

void tui_home_draw(struct tui *t)
{
	int R = t->rows, C = t->cols;
	tui_home_title(t);

	int top = 1, bottom = R - 2;	/* panes: rows top .. bottom-1 */
	if (t->present)		/* no statistics pane (tui_present.c) */
		tui_present_draw(t, top, bottom);
	int lw = C * 55 / 100;
	int rx = lw + 1, rw = C - rx;
	if (!t->present) {
		tui_wall_draw(t, top, 0, bottom - top, lw);
		for (int y = top; y < bottom; y++)
			tui_put(t, y, lw, "│", "|");
		int sh = tui_stats_draw(t, top, rx, bottom - top - 8, rw) + 1;
		tui_hist_draw(t, top + sh, rx, bottom - top - sh, rw);
	}

	if (t->prompting)
		tui_prompt_draw(t, R - 2);
	else if (t->msg[0])
		tui_home_message(t);
	if (t->note[0])
		tui_home_note(t);
	tui_home_keybar(t);
}
