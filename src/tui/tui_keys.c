/*
 * tui_keys.c - the workbench's keys, in one table (tui_keys): for each
 * key its codes, its name and what it does as the help screen shows
 * them, its label and place on the status line in each mode (the main
 * screen, the block cursor, the prompt line), and its handler or the
 * screen it opens.  The main screen dispatches through the table
 * (tui_home.c), the status line (tui_keys_bar) and the help screen
 * (tui_keys_help, tui_help.c) are made from it, as tmux makes its
 * list-keys from its key bindings, and tests/keys_doc.sh checks that
 * docs/workbench.md, "Keys", names every key of it and no other.
 *
 * The handlers of the main screen's own keys (quit, pause, reset, the
 * sample target, the mechanism on show, the block cursor, the mouse,
 * redraw) are here; the edits of the wall are tui_edit.c's, the files
 * tui_io.c's, the prompt line's tui_prompt.c's.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <curses.h>

#include "slipwall/text.h"
#include "slipwall/wedit.h"
#include "tui.h"

static void tui_keys_quit(struct tui *t, int ch)
{
	(void)ch;
	t->quit = 1;
}

static void tui_keys_pause(struct tui *t, int ch)
{
	(void)ch;
	tui_run_pause(t, !t->run.paused);
	tui_message(t, 0, "%s at %ld sample%s",
		    t->run.paused ? "paused" : "resumed", t->run.done,
		    tui_s(t->run.done));
}

static void tui_keys_reset(struct tui *t, int ch)
{
	(void)ch;
	tui_run_end(t);
	tui_run_start(t);
	tui_message(t, 0, "reset: sampling again (run %d)", t->runno);
}

static void tui_keys_target_typed(struct tui *t, const char *text)
{
	long n;
	if (text_parse_long(text, 1, 1000000000L, &n)) {
		tui_message(t, 1, "sample target: a whole number from 1 to 1e9");
		return;
	}
	tui_run_set_target(t, n);
	tui_message(t, 0, "sample target %ld", n);
}

static void tui_keys_target(struct tui *t, int ch)
{
	char buf[32];
	(void)ch;
	snprintf(buf, sizeof buf, "%ld", t->run.target);
	tui_prompt(t, "sample target", buf, tui_keys_target_typed);
}

/* m, M: the next or the previous mechanism family on show (0: the
 * latest mechanism). */
static void tui_keys_mech(struct tui *t, int ch)
{
	const struct family_set *fs = tui_run_families(t);
	int nfam = fs ? fs->nfam : 0;
	t->mech_sel = (t->mech_sel + (ch == 'm' ? 1 : nfam)) % (nfam + 1);
}

/* The block cursor is within a block's size of the wall. */
static int tui_keys_cursor_near(struct tui *t)
{
	if (!isfinite(t->cur_x) || !isfinite(t->cur_y))
		return 0;
	double x = t->cur_x, y = t->cur_y;
	wedit_cursor(t->w, &t->cur_x, &t->cur_y, 0, 0);
	return x == t->cur_x && y == t->cur_y;
}

/* Arrows and hjkl: the block cursor (half a block across, a block up
 * or down) or the load (to the next station of the outline). */
static void tui_keys_arrow(struct tui *t, int ch)
{
	int dx = ch == KEY_RIGHT || ch == 'l' ? 1 : ch == KEY_LEFT || ch == 'h' ? -1 : 0;
	int dy = ch == KEY_UP || ch == 'k' ? 1 : ch == KEY_DOWN || ch == 'j' ? -1 : 0;
	if (t->cursor_mode)
		wedit_cursor(t->w, &t->cur_x, &t->cur_y, dx, dy);
	else
		tui_edit_load_step(t, dx, dy);
}

static void tui_keys_tab(struct tui *t, int ch)
{
	const struct wall *w = t->w;
	(void)ch;
	t->cursor_mode = !t->cursor_mode;
	/* the cursor stays where it was; placed on a block the first time
	 * (and when the wall changed so that it is far off) */
	if (t->cursor_mode && !tui_keys_cursor_near(t)) {
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
 * block cursor goes there; with the sample browser open, the joint
 * nearest it: tui_browse.c), the right one moves the load to the nearest
 * place of the outline (an edit, as the arrows make). */
static void tui_keys_mouse(struct tui *t, int ch)
{
	MEVENT ev;
	double x, y;
	(void)ch;
	if (getmouse(&ev) != OK || !tui_wall_point(t, ev.y, ev.x, &x, &y) ||
	    ev.x >= t->cols * 55 / 100)
		return;
	if ((ev.bstate & (BUTTON1_PRESSED | BUTTON1_CLICKED)) &&
	    t->browse.open) {
		tui_browse_pick_at(t, x, y);	/* the joint there */
	} else if (ev.bstate & (BUTTON1_PRESSED | BUTTON1_CLICKED)) {
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

static void tui_keys_redraw(struct tui *t, int ch)
{
	(void)t;
	(void)ch;
	clearok(curscr, TRUE);
}

static void tui_keys_save(struct tui *t, int ch)
{
	(void)ch;
	tui_io_save(t);
}

static void tui_keys_open(struct tui *t, int ch)
{
	(void)ch;
	tui_io_open(t);
}

static void tui_keys_report(struct tui *t, int ch)
{
	(void)ch;
	tui_io_report(t);
}


#define BAR(m, text, at) .bar[TUI_KEYS_##m] = {text, at}

/* A row without a name is a line of the help: blank (help NULL) or a
 * heading.  Names are key names separated by ", " (the same action) or
 * " / " (the opposite one): tests/keys_doc.sh reads them from here. */
static const struct tui_key tui_keys[] = {
	{.ch = {'?', KEY_F(1)}, .name = "?, F1", .next = TUI_SCREEN_HELP,
	 .help = "this help (Tab: what the numbers mean; any other key\n"
		 "returns)",
	 BAR(MAIN, "? help", 2), BAR(CURSOR, "? help", 6),
	 BAR(BROWSE, "? help", 7), BAR(PRESENT, "? help", 4)},
	{.ch = {'q', 'Q'}, .name = "q, Q", .fn = tui_keys_quit,
	 .help = "quit: print the history and every file written",
	 BAR(MAIN, "q quit", 1), BAR(CURSOR, "q quit", 7),
	 BAR(BROWSE, "q quit", 6), BAR(PRESENT, "q quit", 5)},
	{.ch = {' ', 'p'}, .name = "space, p", .fn = tui_keys_pause,
	 .help = "pause / resume sampling (resume continues the same run)",
	 BAR(MAIN, "spc pause", 3)},
	{.ch = {'r'}, .name = "r", .fn = tui_keys_reset,
	 .help = "reset: a new run on the same wall"},
	{.ch = {'n'}, .name = "n", .fn = tui_keys_target,
	 .help = "sample target (prompt)"},
	{.ch = {'T'}, .name = "T", .fn = tui_knobs_key_threads,
	 .help = "worker threads (prompt; the same samples, faster or slower)"},
	{.ch = {'G'}, .name = "G", .fn = tui_knobs_key_design,
	 .help = "design load (prompt; 0: none): the pane shows P(lambda <= it)"},
	{.ch = {'m', 'M'}, .name = "m / M", .fn = tui_keys_mech,
	 .help = "next / previous mechanism family (the same moving\n"
		 "blocks): the latest mechanism, then by frequency",
	 BAR(MAIN, "m mech", 11)},
	{.ch = {'H'}, .name = "H", .next = TUI_SCREEN_HISTORY,
	 .help = "run history: one row per run of the session; Space marks\n"
		 "two to compare, o reopens a run's wall (Esc returns)",
	 BAR(MAIN, "H history", 5)},
	{.ch = {'S', 27}, .name = "S, Esc", .fn = tui_browse_key_toggle,
	 .help = "sample browser on / off: one sample's load, mechanism,\n"
		 "contact points (x on the wall) and histogram bin",
	 BAR(BROWSE, "S/Esc close", 1)},
	{.ch = {'[', ']'}, .name = "[ / ]", .fn = tui_browse_key_step,
	 .help = "sample browser: previous / next sample",
	 BAR(BROWSE, "[/] step", 2), BAR(PRESENT, "[/] step", 3)},
	{.ch = {KEY_HOME, KEY_END}, .name = "Home / End",
	 .fn = tui_browse_key_step,
	 .help = "sample browser: first / latest sample kept",
	 BAR(BROWSE, "Home/End", 3)},
	{.ch = {'='}, .name = "=", .fn = tui_pair_key,
	 .help = "sample browser: the same mechanism's least and largest\n"
		 "load, one then the other (the same family's where the\n"
		 "sample is the only one of its mechanism)",
	 BAR(BROWSE, "= pair", 4)},
	{.ch = {'<', '>'}, .name = "< / >", .fn = tui_browse_key_joint,
	 .help = "sample browser: previous / next joint, marked on the wall;\n"
		 "the legend gives its friction in the sample shown",
	 BAR(BROWSE, "</> joint", 5)},
	{.ch = {KEY_F(5), 'V'}, .name = "F5, V", .fn = tui_present_key_toggle,
	 .help = "presentation mode on / off: wall, histogram, the sample's\n"
		 "load and p05 in large digits, auto-play",
	 BAR(PRESENT, "F5/V back", 1)},
	{.ch = {'A'}, .name = "A", .fn = tui_present_key_play,
	 .help = "presentation mode: pause / resume auto-play",
	 BAR(PRESENT, "A auto-play", 2)},
	{.help = NULL},

	{.ch = {'u'}, .name = "u", .fn = tui_edit_key_undo,
	 .help = "undo the last edit of the wall (100 steps)",
	 BAR(MAIN, "u undo", 4), BAR(CURSOR, "u undo", 5)},
	{.ch = {'U', 18}, .name = "U, Ctrl-R", .fn = tui_edit_key_undo,
	 .help = "redo"},
	{.ch = {'f', 'F'}, .name = "f / F", .fn = tui_edit_key_friction,
	 .help = "friction of bed and head joints +0.05 / -0.05",
	 BAR(MAIN, "f/F mu", 6)},
	{.ch = {'g'}, .name = "g", .fn = tui_edit_key_prompt,
	 .help = "friction, typed: bed or bed,head"},
	{.ch = {'v'}, .name = "v", .fn = tui_edit_key_prompt,
	 .help = "friction's cov per joint, typed (0: fixed; > 0: random)"},
	{.ch = {'e', 'E'}, .name = "e / E", .fn = tui_edit_key_depth,
	 .help = "contact depth +0.05 / -0.05 (0 .. 0.5)",
	 BAR(MAIN, "e/E depth", 7)},
	{.ch = {'i'}, .name = "i", .fn = tui_edit_key_depth,
	 .help = "contact points: depth <-> anywhere"},
	{.ch = {KEY_UP, KEY_DOWN, KEY_LEFT, KEY_RIGHT, 'h', 'j', 'k', 'l'},
	 .name = "arrows, hjkl", .fn = tui_keys_arrow,
	 .help = "move the load along the wall's outline (h left, j down,\n"
		 "k up, l right; in block cursor mode: move the cursor)",
	 BAR(MAIN, "arrows load", 8), BAR(CURSOR, "arrows/hjkl cursor", 2)},
	{.ch = {'d', 'D'}, .name = "d / D", .fn = tui_edit_key_turn,
	 .help = "turn the load 45 degrees counter-clockwise / clockwise"},
	{.ch = {'P'}, .name = "P", .fn = tui_edit_key_prompt,
	 .help = "load position and direction, typed: x,y or x,y,dx,dy"},
	{.ch = {'c'}, .name = "c", .fn = tui_edit_key_prompt,
	 .help = "courses (prompt)"},
	{.ch = {'L'}, .name = "L", .fn = tui_edit_key_prompt,
	 .help = "blocks per course (prompt; length = that many widths)"},
	{.ch = {'w'}, .name = "w", .fn = tui_edit_key_prompt,
	 .help = "block width,height (prompt)"},
	{.ch = {'b'}, .name = "b", .fn = tui_edit_key_bond,
	 .help = "bond: running <-> stack"},
	{.ch = {'B'}, .name = "B", .fn = tui_edit_key_bond,
	 .help = "first course: half <-> full block"},
	{.ch = {'\t'}, .name = "Tab", .fn = tui_keys_tab,
	 .help = "block cursor on/off (arrows then move the cursor)",
	 BAR(CURSOR, "Tab load mode", 1)},
	{.ch = {'a'}, .name = "a", .fn = tui_edit_key_block,
	 .help = "add a block at the cursor (a removed block of the\n"
		 "courses comes back with its id)",
	 BAR(CURSOR, "a add", 3)},
	{.ch = {'x', KEY_DC}, .name = "x, Delete", .fn = tui_edit_key_block,
	 .help = "remove the block under the cursor",
	 BAR(CURSOR, "x remove", 4)},
	{.help = NULL},

	{.ch = {'s'}, .name = "s", .fn = tui_keys_save,
	 .help = "save the wall (YAML) and a summary (JSON)",
	 BAR(MAIN, "s save", 9)},
	{.ch = {'R'}, .name = "R", .fn = tui_keys_report,
	 .help = "write the report of this run (figures, report.md)"},
	{.ch = {'o'}, .name = "o", .fn = tui_keys_open,
	 .help = "open another wall file", BAR(MAIN, "o open", 10)},
	{.ch = {12}, .name = "Ctrl-L", .fn = tui_keys_redraw,
	 .help = "redraw"},
	{.ch = {KEY_MOUSE}, .name = "mouse", .fn = tui_keys_mouse,
	 .help = "left click: select the block under it (block cursor; in\n"
		 "the sample browser: pick the nearest joint); right click:\n"
		 "move the load to the nearest face there"},
	{.help = NULL},

	{.help = "In a prompt:"},
	{.ch = {'\n', '\r', KEY_ENTER}, .name = "Enter", .prompt = 1,
	 .fn = tui_prompt_accept, .help = "accept",
	 BAR(PROMPT, "Enter accept", 1)},
	{.ch = {27, 7}, .name = "Esc, Ctrl-G", .prompt = 1,
	 .fn = tui_prompt_cancel, .help = "cancel",
	 BAR(PROMPT, "Esc cancel", 2)},
	{.ch = {KEY_BACKSPACE, 127, 8}, .name = "Backspace", .prompt = 1,
	 .fn = tui_prompt_erase, .help = "delete the last character"},
	{.ch = {21}, .name = "Ctrl-U", .prompt = 1, .fn = tui_prompt_clear,
	 .help = "clear", BAR(PROMPT, "Ctrl-U clear", 3)},
	{.ch = {'\t'}, .name = "Tab", .prompt = 1, .fn = tui_prompt_complete,
	 .help = "complete a file name (save, report, open);\n"
		 "again: list the names it could be"},
};

#define TUI_NKEYS ((int)(sizeof tui_keys / sizeof *tui_keys))

const struct tui_key *tui_keys_find(int prompt, int ch)
{
	for (int i = 0; i < TUI_NKEYS; i++) {
		const struct tui_key *k = &tui_keys[i];
		if (!k->name || k->prompt != prompt)
			continue;
		for (int j = 0; k->ch[j]; j++)
			if (k->ch[j] == ch)
				return k;
	}
	return NULL;
}

void tui_keys_bar(enum tui_keys_mode mode, int cols, char *buf, size_t len)
{
	int n = 0;
	buf[0] = 0;
	for (int at = 1;; at++) {
		const char *text = NULL;
		for (int i = 0; i < TUI_NKEYS && !text; i++)
			if (tui_keys[i].bar[mode].at == at)
				text = tui_keys[i].bar[mode].text;
		if (!text)
			break;
		int k = (int)strlen(text);
		if (n + 1 + k > cols - 1 || (size_t)(n + 1 + k) >= len)
			break;
		n += snprintf(buf + n, len - (size_t)n, " %s", text);
	}
}

int tui_keys_help(int line, char *buf, size_t len)
{
	for (int i = 0; i < TUI_NKEYS; i++) {
		const struct tui_key *k = &tui_keys[i];
		const char *s = k->help ? k->help : "";
		for (int part = 0;; part++) {
			const char *nl = strchr(s, '\n');
			int w = nl ? (int)(nl - s) : (int)strlen(s);
			if (line-- == 0) {
				if (!k->name)
					snprintf(buf, len, "%.*s", w, s);
				else
					snprintf(buf, len, "  %-*s %.*s",
						 TUI_KEYS_NAME_W, part ? "" : k->name,
						 w, s);
				return 1;
			}
			if (!nl)
				break;
			s = nl + 1;
		}
	}
	return 0;
}
