/*
 * tui_help.c - the help screen: every key of the workbench, from one
 * table (docs/workbench.md lists the same).  Sampling goes on behind it;
 * any key returns to the main screen, and j/k or the arrows scroll when
 * the terminal is shorter than the list.
 */
#include <curses.h>

#include "tui.h"

static const char *const tui_help_lines[] = {
	"slipwall workbench: keys",
	"",
	"  ?            this help (any key returns)",
	"  q            quit: print the history and every file written",
	"  space, p     pause / resume sampling (resume continues the same run)",
	"  r            reset: a new run on the same wall",
	"  n            sample target (prompt)",
	"  m / M        next / previous mechanism: latest, then by frequency",
	"  H            run history: one row per run of the session (any key returns)",
	"",
	"  u            undo the last edit of the wall (100 steps)",
	"  U, Ctrl-R    redo",
	"  f / F        friction of bed and head joints +0.05 / -0.05",
	"  g            friction, typed: bed or bed,head",
	"  e / E        contact depth +0.05 / -0.05 (0 .. 0.5)",
	"  i            contact points: depth <-> anywhere",
	"  arrows, hjkl move the load along the wall's outline (h left, j down,",
	"               k up, l right; in block cursor mode: move the cursor)",
	"  d / D        turn the load 45 degrees counter-clockwise / clockwise",
	"  P            load position and direction, typed: x,y or x,y,dx,dy",
	"  c            courses (prompt)",
	"  L            blocks per course (prompt; length = that many widths)",
	"  w            block width,height (prompt)",
	"  b            bond: running <-> stack",
	"  B            first course: half <-> full block",
	"  Tab          block cursor on/off (arrows then move the cursor)",
	"  a / x        add a block at / remove the block under the cursor",
	"               (a removed block of the courses comes back with its id)",
	"",
	"  s            save the wall (YAML) and a summary (JSON)",
	"  R            write the report of this run (figures, report.md)",
	"  o            open another wall file",
	"  Ctrl-L       redraw",
	"  mouse        left click: select the block under it (block cursor);",
	"               right click: move the load to the nearest face there",
	"",
	"Every edit starts a new run at once and can be undone; * in the title:",
	"the wall differs from the one opened or saved.  The samples of every",
	"run stay in their file.  In a prompt: Enter accepts, Esc cancels,",
	"Ctrl-U clears.  Samples and the history (history.tsv) go to",
	"$SLIPWALL_RUNS (default ~/.local/share/slipwall/runs).",
	"Wall drawing: filled blocks move,",
	"arrows show their motion, = a sliding joint, : an opening joint,",
	"* a hinge; S G T on the histogram axis: standard, gilbert, tests;",
	"the outline under the bars: the previous run.  NO_COLOR=1: no colours.",
};

#define TUI_HELP_N ((int)(sizeof tui_help_lines / sizeof *tui_help_lines))

static int tui_help_top;

void tui_help_init(struct tui *t)
{
	(void)t;
	tui_help_top = 0;
}

enum tui_screen_id tui_help_key(struct tui *t, int ch)
{
	int page = t->rows - 2;
	if (ch == 'j' || ch == KEY_DOWN) {
		if (tui_help_top + page < TUI_HELP_N)
			tui_help_top++;
		return TUI_SCREEN_HELP;
	}
	if (ch == 'k' || ch == KEY_UP) {
		if (tui_help_top > 0)
			tui_help_top--;
		return TUI_SCREEN_HELP;
	}
	return TUI_SCREEN_MAIN;	/* q too: it leaves the help, not the program */
}

void tui_help_draw(struct tui *t)
{
	for (int i = 0; i + tui_help_top < TUI_HELP_N && i < t->rows - 1; i++) {
		if (i + tui_help_top == 0)
			attron(A_BOLD);
		tui_text(i, 1, t->cols - 2, tui_help_lines[i + tui_help_top]);
		if (i + tui_help_top == 0)
			attroff(A_BOLD);
	}
	attron(A_REVERSE);
	move(t->rows - 1, 0);
	for (int c = 0; c < t->cols; c++)
		addch(' ');
	tui_text(t->rows - 1, 0, t->cols,
		 " any key: back to the workbench   j/k: scroll");
	attroff(A_REVERSE);
}
