/*
 * tui_present.c - the presentation mode (F5 or V), for a projector at
 * about 80 x 24 with large fonts (docs/workbench.md, "Presentation
 * mode"): the statistics pane hidden; the wall pane at the top left, the
 * shown sample's λ_min and the run's p05 in large digits at the top
 * right, the histogram across the whole width below; auto-play steps the
 * sample browser (tui_browse.c) one sample every TUI_PRESENT_STEP
 * seconds, A pauses and resumes it.
 *
 * The large digits are a font of 5 rows by 3 columns drawn with a block
 * (`█`, `#` when the locale is not UTF-8, as the rest of the workbench
 * falls back to ASCII); a character the font lacks is a blank.  The
 * sample shown is the browser's when it is open (auto-play opens it),
 * else the latest accepted sample the browser keeps.
 *
 * Auto-play is driven by tui_present_tick, called once a turn of the UI
 * loop (tui.c): the loop turns at least every 100 ms, so a step is late
 * by at most that.  At the latest sample it starts again at the first
 * one kept.
 */
#include <stdio.h>
#include <string.h>

#include <curses.h>

#include "slipwall/stats.h"
#include "slipwall/sys.h"
#include "tui.h"

#define TUI_PRESENT_STEP 1.5	/* seconds a sample is on show */
#define TUI_BIG_H 5		/* rows of a large digit */
#define TUI_BIG_W 3		/* its columns; one blank between two */

/* The font: for each character, TUI_BIG_H rows of TUI_BIG_W cells, '#'
 * for a block. */
static const struct {
	char c;
	const char *rows[TUI_BIG_H];
} tui_big_font[] = {
	{'0', {"###", "# #", "# #", "# #", "###"}},
	{'1', {" # ", "## ", " # ", " # ", "###"}},
	{'2', {"###", "  #", "###", "#  ", "###"}},
	{'3', {"###", "  #", " ##", "  #", "###"}},
	{'4', {"# #", "# #", "###", "  #", "  #"}},
	{'5', {"###", "#  ", "###", "  #", "###"}},
	{'6', {"###", "#  ", "###", "# #", "###"}},
	{'7', {"###", "  #", "  #", "  #", "  #"}},
	{'8', {"###", "# #", "###", "# #", "###"}},
	{'9', {"###", "# #", "###", "  #", "###"}},
	{'.', {"   ", "   ", "   ", "   ", " # "}},
	{'-', {"   ", "   ", "###", "   ", "   "}},
	{'+', {"   ", " # ", "###", " # ", "   "}},
	{'e', {"   ", "###", "# #", "## ", "###"}},
};

#define TUI_BIG_NFONT ((int)(sizeof tui_big_font / sizeof *tui_big_font))

/* Row r of character c in the font ("   " if it has none). */
static const char *tui_big_row(char c, int r)
{
	for (int i = 0; i < TUI_BIG_NFONT; i++)
		if (tui_big_font[i].c == c)
			return tui_big_font[i].rows[r];
	return "   ";
}

/* The size of the large digits: each cell of the font sx columns by
 * sy rows (a terminal's cell is about twice as tall as wide, so sx is
 * up to twice sy). */
struct tui_big {
	int sx, sy;
};

/* The columns s takes in large digits. */
static int tui_big_cols(const char *s, struct tui_big z)
{
	int n = (int)strlen(s);
	return n ? n * (TUI_BIG_W + 1) * z.sx - z.sx : 0;
}

/* s in large digits, its top left at (y, x), at most w columns. */
static void tui_big_draw(const struct tui *t, int y, int x, int w,
			 const char *s, struct tui_big z, int attr)
{
	const char *block = t->utf8 ? "█" : "#";
	if (attr)
		attron(attr);
	for (int r = 0; r < TUI_BIG_H * z.sy; r++)
		for (int i = 0; s[i]; i++) {
			const char *g = tui_big_row(s[i], r / z.sy);
			for (int c = 0; c < TUI_BIG_W * z.sx; c++) {
				int cx = i * (TUI_BIG_W + 1) * z.sx + c;
				if (cx < w && g[c / z.sx] == '#')
					mvaddstr(y + r, x + cx, block);
			}
		}
	if (attr)
		attroff(attr);
}

/* The sample whose load is shown: the browser's, else the latest
 * accepted one kept; 0 when there is none. */
static int tui_present_sample(const struct tui *t, struct tui_browse_sample *s)
{
	if (t->browse.open)
		return tui_browse_shown(t, s);
	long first = tui_browse_first(t);
	for (long i = t->browse.next - 1; first >= 0 && i >= first; i--) {
		if (tui_browse_sample_at(t, i, s) &&
		    s->status == SAMPLE_ACCEPTED)
			return 1;
	}
	return 0;
}

void tui_present_key_toggle(struct tui *t, int ch)
{
	(void)ch;
	t->present = !t->present;
	if (t->present) {
		if (!t->browse.open)
			tui_browse_key_toggle(t, 'S');
		t->present_play = 1;
		t->present_next = sys_now() + TUI_PRESENT_STEP;
		tui_message(t, 0, "presentation: A pauses auto-play, [ ] step, "
			    "F5 or V back");
	} else {
		t->present_play = 0;
		tui_message(t, 0, "presentation off");
	}
}

void tui_present_key_play(struct tui *t, int ch)
{
	(void)ch;
	if (!t->present) {
		tui_message(t, 0, "auto-play is part of the presentation mode: "
			    "F5 or V");
		return;
	}
	/* playing with the browser closed (S, Esc): it opens, play goes on */
	t->present_play = !t->present_play || !t->browse.open;
	t->present_next = sys_now() + TUI_PRESENT_STEP;
	if (t->present_play && !t->browse.open)
		tui_browse_key_toggle(t, 'S');
	tui_message(t, 0, "auto-play %s", t->present_play ? "resumed" : "paused");
}

int tui_present_tick(struct tui *t)
{
	if (!t->present || !t->present_play || sys_now() < t->present_next)
		return 0;
	t->present_next = sys_now() + TUI_PRESENT_STEP;
	long first = tui_browse_first(t);
	if (!t->browse.open || first < 0)
		return 0;
	struct tui_browse_sample s;
	if (tui_browse_shown(t, &s) && s.index >= t->browse.next - 1)
		tui_browse_key_step(t, KEY_HOME);	/* again from the first */
	else
		tui_browse_key_step(t, ']');
	return 1;
}

/* The number's text: 4 significant digits, 3 if they do not fit. */
static void tui_present_format(char *num, size_t len, double v, int w,
			       struct tui_big z)
{
	snprintf(num, len, "%.4g", v);
	if (tui_big_cols(num, z) > w)
		snprintf(num, len, "%.3g", v);
}

/* One number in large digits under its label, at (y, x), w columns. */
static void tui_present_number(struct tui *t, int y, int x, int w,
			       const char *label, const char *num,
			       struct tui_big z, int attr)
{
	attron(A_BOLD);
	tui_text_cut(t, y, x, w, label);
	attroff(A_BOLD);
	tui_big_draw(t, y + 1, x, w, num, z, attr);
}

/* The large numbers side by side in rows y .. y + h - 1: the sample's
 * load at the left, p05 at the right, each in half of the w columns. */
static void tui_present_numbers(struct tui *t, int y, int w, int h)
{
	char label[128], num[2][32] = {"", ""};
	const char *unit = tui_load_unit(t->w);
	struct tui_browse_sample s;
	struct stats_summary sum;
	int has_s = tui_present_sample(t, &s);
	int acc = has_s && s.status == SAMPLE_ACCEPTED;
	int has_p = t->run.tally.lam.n > 0;
	if (has_p)
		tally_summary(&t->run.tally, &sum);
	int hw = w / 2 - 1;
	/* as large as the rows and both numbers' columns allow */
	struct tui_big z = {1, 1};
	z.sy = (h - 1) / TUI_BIG_H > 1 ? (h - 1) / TUI_BIG_H : 1;
	for (z.sx = 2 * z.sy; z.sx > 1; z.sx--) {
		tui_present_format(num[0], sizeof num[0], acc ? tui_load(t, s.lam)
							      : 0, hw, z);
		tui_present_format(num[1], sizeof num[1], has_p ? sum.p05 : 0,
				   hw, z);
		if (tui_big_cols(num[0], z) <= hw && tui_big_cols(num[1], z) <= hw)
			break;
	}
	tui_present_format(num[0], sizeof num[0], acc ? tui_load(t, s.lam) : 0,
			   hw, z);
	tui_present_format(num[1], sizeof num[1], has_p ? sum.p05 : 0, hw, z);

	if (acc) {
		snprintf(label, sizeof label, "%s_min of sample %ld (%s)",
			 tui_lam(t), s.index + 1, unit);
		tui_present_number(t, y, 1, hw, label, num[0], z,
				   t->colors ? COLOR_PAIR(2) | A_BOLD : A_BOLD);
	} else if (has_s) {
		snprintf(label, sizeof label, "sample %ld: %s", s.index + 1,
			 sample_status_text(s.status));
		tui_text_cut(t, y, 1, hw, label);
	} else {
		tui_text(y, 1, hw, "no sample yet");
	}
	int x = w - hw;
	if (has_p) {
		snprintf(label, sizeof label, "p05 of %ld accepted (%s)",
			 t->run.tally.accepted, unit);
		tui_present_number(t, y, x, hw, label, num[1], z,
				   t->colors ? COLOR_PAIR(3) | A_BOLD : A_BOLD);
	} else {
		tui_text_cut(t, y, x, hw, "p05: no accepted sample yet");
	}
}

void tui_present_draw(struct tui *t, int top, int bottom)
{
	int R = t->rows, C = t->cols;
	/* the numbers' band: a label and the digits, a fifth of the rows
	 * on a tall screen; then the wall and the histogram side by side */
	int sy = R >= 40 ? 2 : 1;
	int nh = 1 + TUI_BIG_H * sy;
	tui_present_numbers(t, top, C, nh);
	for (int x = 0; x < C; x++)
		tui_put(t, top + nh, x, "─", "-");
	int y = top + nh + 1, h = bottom - y;
	int lw = C / 2;
	tui_wall_draw(t, y, 0, h, lw);
	for (int r = y; r < bottom; r++)
		tui_put(t, r, lw, "│", "|");
	tui_hist_draw(t, y, lw + 2, h, C - lw - 2);
}
