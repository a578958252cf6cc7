/*
 * tui_help.c - the help screen: every key of the workbench, made from
 * the one key table (tui_keys.c; docs/workbench.md lists the same, and
 * tests/keys_doc.sh checks it does), then a few notes.  Sampling goes
 * on behind it; any key returns to the main screen, and j/k or the
 * arrows scroll when the terminal is shorter than the list.  Tab turns
 * to the second page, "what the numbers mean" (tui_meaning.c), and back.
 */
#include <stdio.h>

#include <curses.h>

#include "tui.h"

/* The help: a title, the keys (tui_keys_help: their table), then this. */
static const char *const tui_help_notes[] = {
	"Every edit starts a new run at once and can be undone; * in the title:",
	"the wall differs from the one opened or saved.  The samples of every",
	"run stay in their file.  Samples and the history (history.tsv) go to",
	"$SLIPWALL_RUNS (default ~/.local/share/slipwall/runs).",
	"Wall drawing: filled blocks move,",
	"arrows show their motion, = a sliding joint, : an opening joint,",
	"* a hinge; S G T on the histogram axis: standard, gilbert, tests;",
	"x crossed out: no block there (removed with x, or an opening);",
	"the outline under the bars: the previous run.  NO_COLOR=1: no colours.",
};

#define TUI_HELP_NOTES ((int)(sizeof tui_help_notes / sizeof *tui_help_notes))

/* The help's lines: the title, a blank, the keys, a blank, the notes;
 * on the second page the title, a blank and tui_meaning_line's. */
static int tui_help_count(const struct tui *t)
{
	char buf[160];
	int n = 0;
	if (t->help_page) {
		while (tui_meaning_line(t, n, buf, sizeof buf))
			n++;
		return 2 + n;
	}
	while (tui_keys_help(n, buf, sizeof buf))
		n++;
	return 2 + n + 1 + TUI_HELP_NOTES;
}

static void tui_help_line(const struct tui *t, int i, char *buf, size_t len)
{
	int nkeys = tui_help_count(t) - 3 - TUI_HELP_NOTES;
	buf[0] = 0;
	if (t->help_page) {
		if (i == 0)
			snprintf(buf, len, "slipwall workbench: what the numbers "
				 "mean (Tab: the keys)");
		else if (i >= 2)
			tui_meaning_line(t, i - 2, buf, len);
		return;
	}
	if (i == 0)
		snprintf(buf, len, "slipwall workbench: keys (Tab: what the "
			 "numbers mean)");
	else if (i >= 2 && i < 2 + nkeys)
		tui_keys_help(i - 2, buf, len);
	else if (i >= 3 + nkeys)
		snprintf(buf, len, "%s", tui_help_notes[i - 3 - nkeys]);
}

void tui_help_init(struct tui *t)
{
	t->help_top = 0;
	t->help_page = 0;
}

enum tui_screen_id tui_help_key(struct tui *t, int ch)
{
	int page = t->rows - 2;
	ch = tui_wheel(ch);	/* the mouse scrolls, never closes */
	if (ch == 0)
		return TUI_SCREEN_HELP;
	if (ch == '\t') {	/* the other page, from its top */
		t->help_page = !t->help_page;
		t->help_top = 0;
		return TUI_SCREEN_HELP;
	}
	if (ch == 'j' || ch == KEY_DOWN) {
		if (t->help_top + page < tui_help_count(t))
			t->help_top++;
		return TUI_SCREEN_HELP;
	}
	if (ch == 'k' || ch == KEY_UP) {
		if (t->help_top > 0)
			t->help_top--;
		return TUI_SCREEN_HELP;
	}
	return TUI_SCREEN_MAIN;	/* q too: it leaves the help, not the program */
}

void tui_help_draw(struct tui *t)
{
	char buf[160];
	int n = tui_help_count(t);
	for (int i = 0; i + t->help_top < n && i < t->rows - 1; i++) {
		tui_help_line(t, i + t->help_top, buf, sizeof buf);
		if (i + t->help_top == 0)
			attron(A_BOLD);
		tui_text(i, 1, t->cols - 2, buf);
		if (i + t->help_top == 0)
			attroff(A_BOLD);
	}
	attron(A_REVERSE);
	move(t->rows - 1, 0);
	for (int c = 0; c < t->cols; c++)
		addch(' ');
	tui_text(t->rows - 1, 0, t->cols,
		 t->help_page ? " any key: back to the workbench   j/k: scroll"
				"   Tab: the keys"
			      : " any key: back to the workbench   j/k: scroll"
				"   Tab: what the numbers mean");
	attroff(A_REVERSE);
}
