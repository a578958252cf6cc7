/*
 * tui_confirm.c - a key that would throw away more than a minute of
 * sampling asks first (docs/workbench.md, "Asking before"): an edit of
 * the wall (its run ends and a new one starts), r, o, and q.  The
 * question is on the message line; y goes on, any other key keeps the
 * run (and does nothing else).
 *
 * The minute is the run's sampling time (its pools' lifetimes:
 * tui_pace_sampled), not the session's.  SLIPWALL_CONFIRM_SECONDS sets
 * another threshold (the tests use a few seconds; 0 asks always, a
 * negative value never).
 */
#include <curses.h>
#include <stdlib.h>

#include "tui.h"

#define TUI_CONFIRM_SECONDS 60.0

static double tui_confirm_threshold(void)
{
	const char *e = getenv("SLIPWALL_CONFIRM_SECONDS");
	char *end;
	if (e && *e) {
		double v = strtod(e, &end);
		if (*end == 0)
			return v;
	}
	return TUI_CONFIRM_SECONDS;
}

/* Whether key k (code ch) ends the current run. */
static int tui_confirm_discards(const struct tui *t, const struct tui_key *k,
				int ch)
{
	if (k->prompt)
		return 0;
	switch (ch) {
	case 'q': case 'Q': case 'r': case 'o':
		return 1;
	case KEY_UP: case KEY_DOWN: case KEY_LEFT: case KEY_RIGHT:
	case 'h': case 'j': case 'k': case 'l':
		return !t->cursor_mode;		/* they move the load */
	}
	/* a and x edit only in the block cursor mode; outside it they
	 * say "Tab first" and end nothing */
	if (k->fn == tui_edit_key_block)
		return t->cursor_mode;
	return k->fn == tui_edit_key_undo || k->fn == tui_edit_key_friction ||
	       k->fn == tui_edit_key_depth || k->fn == tui_edit_key_turn ||
	       k->fn == tui_edit_key_bond || k->fn == tui_edit_key_prompt;
}

int tui_confirm_ask(struct tui *t, const struct tui_key *k, int ch)
{
	double limit = tui_confirm_threshold();
	double s = tui_pace_sampled(t);
	char d[32];
	if (limit < 0 || s <= limit || !tui_confirm_discards(t, k, ch))
		return 0;
	t->confirm_key = k;
	t->confirm_ch = ch;
	tui_duration(d, sizeof d, s);
	if (ch == 'q' || ch == 'Q')
		tui_message(t, 0, "quit and end %s of sampling? y yes, any "
			    "other key no", d);
	else
		tui_message(t, 0, "end %s of sampling (a new run)? y yes, any "
			    "other key no", d);
	return 1;
}

enum tui_screen_id tui_confirm_answer(struct tui *t, int ch)
{
	const struct tui_key *k = t->confirm_key;
	if (ch == KEY_RESIZE || ch == KEY_MOUSE)
		return TUI_SCREEN_MAIN;		/* not an answer */
	t->confirm_key = NULL;
	if (ch != 'y' && ch != 'Y') {
		tui_message(t, 0, "kept the run");
		return TUI_SCREEN_MAIN;
	}
	tui_message(t, 0, "%s", "");
	if (k->fn)
		k->fn(t, t->confirm_ch);
	return k->next;
}
