/*
 * tui_draw.c - the leaf of the workbench: the text helpers every screen
 * and pane draws with (UTF-8 or ASCII, cut to a width, control
 * characters cleaned), the message line, the list of files written, the
 * clock.  It calls nothing else of the room, so any file may call it.
 */
#include <stdarg.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <curses.h>

#include "slipwall/text.h"
#include "tui.h"

void tui_message(struct tui *t, int is_err, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(t->msg, sizeof t->msg, fmt, ap);
	va_end(ap);
	t->msg_err = is_err;
}

void tui_note(struct tui *t, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(t->note, sizeof t->note, fmt, ap);
	va_end(ap);
}

void tui_note_file(struct tui *t, const char *kind, const char *path)
{
	char *line;
	for (int k = 0; k < t->nfiles; k++) {
		const char *c = strchr(t->files[k], ':');
		if (c && !strncmp(t->files[k], kind, (size_t)(c - t->files[k])) &&
		    !strcmp(c + 2, path))
			return;	/* written again: listed once */
	}
	size_t len = strlen(kind) + strlen(path) + 3;
	line = malloc(len);
	if (!line)
		return;
	snprintf(line, len, "%s: %s", kind, path);
	char **v = realloc(t->files, sizeof *v * (size_t)(t->nfiles + 1));
	if (!v) {
		free(line);
		return;
	}
	t->files = v;
	t->files[t->nfiles++] = line;
}

void tui_put(struct tui *t, int y, int x, const char *utf8, const char *ascii)
{
	mvaddstr(y, x, t->utf8 ? utf8 : ascii);
}

void tui_text(int y, int x, int w, const char *s)
{
	/* names and paths come from files: a control character would move
	 * the cursor or reach the terminal (curses passes ESC through) */
	if (!text_is_clean(s)) {
		char *c = text_clean(s);
		tui_text(y, x, w, c);
		free(c);
		return;
	}
	int cols = 0;
	size_t n = 0;
	while (s[n]) {
		if (((unsigned char)s[n] & 0xc0) != 0x80) {
			if (cols == w)
				break;
			cols++;
		}
		n++;
	}
	if (n)
		mvaddnstr(y, x, s, (int)n);
}

const char *tui_dots(const struct tui *t)
{
	return t->utf8 ? "\u2026" : "~";
}

void tui_text_cut(const struct tui *t, int y, int x, int w, const char *s)
{
	if (!text_is_clean(s)) {	/* measured as drawn (tui_text) */
		char *c = text_clean(s);
		tui_text_cut(t, y, x, w, c);
		free(c);
		return;
	}
	if (w < 2 || tui_cols(s) <= w) {
		tui_text(y, x, w, s);
		return;
	}
	tui_text(y, x, w - 1, s);
	tui_text(y, x + w - 1, 1, tui_dots(t));
}

int tui_cols(const char *s)
{
	int n = 0;
	for (; *s; s++)
		n += ((unsigned char)*s & 0xc0) != 0x80;
	return n;
}

const char *tui_skip(const char *s, int k)
{
	for (; *s; s++)
		if (((unsigned char)*s & 0xc0) != 0x80 && k-- == 0)
			break;
	return s;
}

void tui_abbrev(const struct tui *t, char *out, size_t len, const char *s, int w)
{
	int n = tui_cols(s);
	if (w < 0)
		w = 0;
	if (n <= w) {
		snprintf(out, len, "%s", s);
		return;
	}
	if (w < 5) {
		snprintf(out, len, "%.*s", (int)(tui_skip(s, w) - s), s);
		return;
	}
	/* keep more of the end: a path's file name */
	const char *dots = tui_dots(t);
	int keep = w - 1, head = keep / 3, tail = keep - head;
	snprintf(out, len, "%.*s%s%s", (int)(tui_skip(s, head) - s), s, dots,
		 tui_skip(s, n - tail));
}

/* A full-width bar in the title colours (reverse video without). */
void tui_bar(struct tui *t, int y, const char *text)
{
	int attr = t->colors ? COLOR_PAIR(6) : A_REVERSE;
	attron(attr);
	move(y, 0);
	for (int c = 0; c < t->cols; c++)
		addch(' ');
	tui_text(y, 0, t->cols, text);
	attroff(attr);
}

const char *tui_lam(const struct tui *t)
{
	return t->utf8 ? "\u03bb" : "lam";
}

const char *tui_mu(const struct tui *t)
{
	return t->utf8 ? "\u03bc" : "mu";
}

const char *tui_friction(const struct tui *t, char *buf, size_t len,
			 double bed, double head, double cov)
{
	char c[32] = "";
	if (cov > 0)	/* random friction: the means and the cov */
		snprintf(c, sizeof c, " cov %.3g", cov);
	snprintf(buf, len, "%s %.3g/%.3g%s", tui_mu(t), bed, head, c);
	return buf;
}

const char *tui_s(long n)
{
	return n == 1 ? "" : "s";
}

/* Whole percents from 1 to 99.5, a tenth below and above, a hundredth
 * below 0.1 %: 1 of 1,000 is "0.1 %", never "0 %" (docs/workbench.md). */
void tui_pct(char *buf, size_t len, double p)
{
	double pc = 100 * p;
	if (isnan(p))
		snprintf(buf, len, "-");
	else if (pc <= 0)
		snprintf(buf, len, "0 %%");
	else if (pc >= 100)
		snprintf(buf, len, "100 %%");
	else if (pc < 0.01)
		snprintf(buf, len, "< 0.01 %%");
	else if (pc < 0.1)
		snprintf(buf, len, "%.2f %%", pc);
	else if (pc >= 99.95)
		snprintf(buf, len, "> 99.9 %%");
	else if (pc < 1 || pc >= 99.5)
		snprintf(buf, len, "%.1f %%", pc);
	else
		snprintf(buf, len, "%.0f %%", pc);
}

const char *tui_load_unit(const struct wall *w)
{
	struct wall_quantity q;
	wall_quantity(w, &q);
	return *q.unit ? q.unit : q.name;
}

double tui_load(const struct tui *t, double lambda)
{
	struct wall_quantity q;
	wall_quantity(t->w, &q);
	return q.scale * lambda;
}
