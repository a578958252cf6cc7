/*
 * tui_history.c - the run history: one row per run of the session (what
 * the run changed, the friction, the contacts, the load, the counts, the
 * characteristic value with its 99 % interval, p50, p95, the samples
 * file), the H screen that shows it with the rows of earlier sessions
 * above, and the text that q prints.
 *
 * A run's row is made when the run ends (tui_run_end: an edit, a reset,
 * an open, quit or a signal) and appended to the index file beside the
 * samples files (history.h), so it survives quitting; the run in
 * progress is shown live, from its tally.  When the run ends, its
 * accepted loads are kept as "the previous run" that the histogram pane
 * outlines over the current one, with its p05 (tui_compare_p05).
 *
 * In H a row is selected (j/k); Space marks up to two rows, whose runs
 * tui_compare.c compares in the lower half of the screen, and o or
 * Enter reopens the selected run's wall (tui_compare_reopen).  Rows are
 * numbered in the order shown: earlier sessions, this session, the live
 * run (tui_history_rows); marks are reset each time H opens.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <curses.h>

#include "slipwall/stats.h"
#include "tui.h"

#define TUI_HISTORY_OLD 200	/* rows of earlier sessions read */

/* The row of the current run, from its tally. */
static void tui_history_row(const struct tui *t, struct history_row *h)
{
	const struct tui_run *r = &t->run;
	const struct wall *w = t->w;
	struct stats_summary s;

	memset(h, 0, sizeof *h);
	snprintf(h->session, sizeof h->session, "%s", t->session);
	h->run = t->runno;
	snprintf(h->wall, sizeof h->wall, "%s",
		 w->name ? w->name : (w->path ? w->path : "wall"));
	snprintf(h->what, sizeof h->what, "%s", r->what);
	h->mu_bed = w->mu_bed;
	h->mu_head = w->mu_head;
	h->mu_cov = w->mu_cov;
	h->depth = w->depth;
	h->anywhere = w->anywhere;
	h->load = -1;
	if (w->nloads > 0) {
		const struct wall_load *ld = &w->loads[0];
		h->load = ld->kind == LOAD_POINT ? 0 : 1;
		memcpy(h->at, ld->at, sizeof h->at);
		memcpy(h->dir, ld->dir, sizeof h->dir);
	}
	h->samples = r->tally.samples;
	h->accepted = r->tally.accepted;
	tally_summary(&r->tally, &s);
	h->p05 = s.p05;
	h->p05_lo = s.has_ci ? s.p05_lo : NAN;
	h->p05_hi = s.has_ci ? s.p05_hi : NAN;
	h->p50 = s.p50;
	h->p95 = s.p95;
	snprintf(h->file, sizeof h->file, "%s", r->csv);
}

void tui_history_record(struct tui *t)
{
	struct tui_run *r = &t->run;
	char err[SW_ERRLEN];
	struct history_row h;

	/* a run that ended before its first sample (the next edit came
	 * first: a held key) found nothing: no row */
	if (r->tally.samples == 0)
		return;
	tui_history_row(t, &h);
	struct history_row *v = realloc(t->hist, sizeof *v * (size_t)(t->nhist + 1));
	if (v) {
		t->hist = v;
		t->hist[t->nhist++] = h;
	}
	if (t->hist_path[0] && history_append(t->hist_path, &h, err) != SW_OK) {
		/* the edit that ended the run writes its own message at
		 * once: a note stays until the next key (issue 23) */
		tui_note(t, "run history: %s (not kept after quitting)", err);
		snprintf(t->hist_err, sizeof t->hist_err, "%s", err);
		t->hist_path[0] = 0;
	}
	/* the previous run, for the histogram's outline */
	if (r->tally.lam.n > 0) {
		double *x = malloc(sizeof(double) * r->tally.lam.n);
		if (x) {
			memcpy(x, r->tally.lam.x, sizeof(double) * r->tally.lam.n);
			free(t->prev_lam);
			t->prev_lam = x;
			t->prev_n = r->tally.lam.n;
			t->prev_run = t->runno;
			t->prev_p05 = h.p05;
		}
	}
}

static const char *tui_history_num(char *buf, size_t len, double v)
{
	if (isnan(v))
		snprintf(buf, len, "-");
	else
		snprintf(buf, len, "%.4g", v);
	return buf;
}

/* The two lines of a row: a (what changed and the wall's parameters) and
 * b (the numbers).  Numbers are never cut; `what` is. */
void tui_history_lines(const struct tui *t, const struct history_row *h,
		       char *a, size_t alen, char *b, size_t blen)
{
	char d[32], ld[64], p[32], lo[32], hi[32], m[32], q[32], fr[64];
	if (h->anywhere)
		snprintf(d, sizeof d, "anywhere");
	else
		snprintf(d, sizeof d, "depth %.3g", h->depth);
	if (h->load == 0)
		snprintf(ld, sizeof ld, "point load at %.3g,%.3g dir %.2g,%.2g",
			 h->at[0], h->at[1], h->dir[0], h->dir[1]);
	else if (h->load == 1)
		snprintf(ld, sizeof ld, "body load dir %.2g,%.2g", h->dir[0],
			 h->dir[1]);
	else
		snprintf(ld, sizeof ld, "no load");
	snprintf(a, alen, "%s  %s  %s",
		 tui_friction(t, fr, sizeof fr, h->mu_bed, h->mu_head,
			      h->mu_cov), d, ld);
	tui_history_num(lo, sizeof lo, h->p05_lo);
	tui_history_num(hi, sizeof hi, h->p05_hi);
	snprintf(b, blen, "n %ld  acc %ld  p05 %s [%s, %s]  p50 %s  p95 %s %s",
		 h->samples, h->accepted, tui_history_num(p, sizeof p, h->p05),
		 lo, hi, tui_history_num(m, sizeof m, h->p50),
		 tui_history_num(q, sizeof q, h->p95),
		 h->load == 1 ? "(seismic coefficient)" : "N");
}

void tui_history_print(const struct tui *t, FILE *f)
{
	char a[256], b[256];
	if (t->nhist == 0)
		return;
	fprintf(f, "run history (%d run%s):\n", t->nhist, tui_s(t->nhist));
	for (int i = 0; i < t->nhist; i++) {
		const struct history_row *h = &t->hist[i];
		tui_history_lines(t, h, a, sizeof a, b, sizeof b);
		fprintf(f, "%3d %s\n    %s\n    %s\n    samples: %s\n", h->run,
			h->what, a, b, h->file[0] ? h->file : "(none)");
	}
}

/* ---- the H screen ---- */

/* Its state is t's: hist_top, hist_old, hist_nold, hist_rerr. */

void tui_history_init(struct tui *t)
{
	char err[SW_ERRLEN];
	struct history_row *all = NULL;
	int n = 0;
	tui_history_free(t);
	t->hist_top = -1;	/* at the bottom */
	t->hist_rerr[0] = 0;
	t->hist_cur = -1;	/* the last row */
	t->hist_mark[0] = t->hist_mark[1] = -1;
	t->hist_msg[0] = 0;
	if (!t->hist_path[0])
		return;
	if (history_read(t->hist_path, TUI_HISTORY_OLD, &all, &n, err) != SW_OK) {
		snprintf(t->hist_rerr, sizeof t->hist_rerr,
			 "earlier sessions not shown: %s", err);
		return;
	}
	/* this session's rows are in t->hist */
	int k = 0;
	for (int i = 0; i < n; i++)
		if (strcmp(all[i].session, t->session))
			all[k++] = all[i];
	t->hist_old = all;
	t->hist_nold = k;
}

void tui_history_free(struct tui *t)
{
	free(t->hist_old);
	t->hist_old = NULL;
	t->hist_nold = 0;
	tui_compare_free(t);
}

/* The mouse wheel as a key: KEY_DOWN (wheel down), KEY_UP (up), 0 for
 * another mouse event, which leaves the screen open. */
int tui_wheel(int ch)
{
	MEVENT ev;
	if (ch != KEY_MOUSE)
		return ch;
	if (getmouse(&ev) != OK)
		return 0;
	if (ev.bstate & BUTTON4_PRESSED)
		return KEY_UP;
	if (ev.bstate & BUTTON5_PRESSED)
		return KEY_DOWN;
	return 0;
}

/* H's rows in order (earlier sessions, this session, the live run in
 * live): a malloc'd array of n pointers, NULL when there are none. */
static const struct history_row **tui_history_rows(const struct tui *t,
						   struct history_row *live,
						   int *n)
{
	int running = t->run.latest_joint != NULL;
	*n = t->hist_nold + t->nhist + running;
	const struct history_row **v = malloc(sizeof *v * (size_t)(*n + 1));
	if (!v) {
		*n = 0;
		return NULL;
	}
	int k = 0;
	for (int i = 0; i < t->hist_nold; i++)
		v[k++] = &t->hist_old[i];
	for (int i = 0; i < t->nhist; i++)
		v[k++] = &t->hist[i];
	if (running) {
		tui_history_row(t, live);
		v[k++] = live;
	}
	return v;
}

/* Space: mark the selected row, or unmark it; a third mark replaces
 * the older one. */
static void tui_history_mark(struct tui *t, int row)
{
	int *m = t->hist_mark;
	if (m[0] == row || m[1] == row) {
		if (m[0] == row)
			m[0] = m[1];
		m[1] = -1;
		return;
	}
	if (m[0] < 0)
		m[0] = row;
	else if (m[1] < 0)
		m[1] = row;
	else {
		m[0] = m[1];
		m[1] = row;
	}
}

enum tui_screen_id tui_history_key(struct tui *t, int ch)
{
	struct history_row live;
	int n;
	ch = tui_wheel(ch);	/* the mouse scrolls, never closes */
	if (ch == 0)
		return TUI_SCREEN_HISTORY;
	const struct history_row **rows = tui_history_rows(t, &live, &n);
	enum tui_screen_id next = TUI_SCREEN_HISTORY;
	int cur = t->hist_cur < 0 || t->hist_cur >= n ? n - 1 : t->hist_cur;
	t->hist_msg[0] = 0;
	if (ch == 'j' || ch == KEY_DOWN) {
		if (cur < n - 1)
			cur++;
	} else if (ch == 'k' || ch == KEY_UP) {
		if (cur > 0)
			cur--;
	} else if (ch == ' ') {
		if (cur >= 0)
			tui_history_mark(t, cur);
	} else if (ch == 'o' || ch == '\n' || ch == '\r' || ch == KEY_ENTER) {
		if (cur >= 0 && tui_compare_reopen(t, rows[cur]))
			next = TUI_SCREEN_MAIN;
	} else {
		next = TUI_SCREEN_MAIN;
	}
	t->hist_cur = cur;
	free(rows);
	return next;
}

/* One run: three lines (what changed and the file; the wall's
 * parameters; the numbers). */
static int tui_history_draw_row(const struct tui *t, int y, int y1,
				const struct history_row *h, int live, int old,
				int sel, int mark)
{
	char a[256], b[256], head[PATH_MAX + 256], file[PATH_MAX];
	const char *base = strrchr(h->file, '/');
	base = base ? base + 1 : h->file;
	tui_history_lines(t, h, a, sizeof a, b, sizeof b);
	int n = snprintf(head, sizeof head, "%s%s%s%3d", live ? ">" : " ",
			 old ? h->session : "", old ? " " : "", h->run);
	if (mark)	/* the marked rows: A or B in place of the number's
			 * first column (runs up to 99 keep theirs) */
		head[n - 3] = mark;
	int room = t->cols - 2 - n - 2;
	int fw = (int)strlen(base);
	if (fw > room / 2)
		fw = room / 2;
	tui_abbrev(t, file, sizeof file, base[0] ? base : "(no samples file)", fw);
	int ww = room - (int)strlen(file) - 2;
	if (ww < 0)
		ww = 0;
	char what[128];
	snprintf(what, sizeof what, "%s%s", h->what, live ? " (this run)" : "");
	char wc[128];
	tui_abbrev(t, wc, sizeof wc, what, ww);
	snprintf(head + n, sizeof head - (size_t)n, " %-*s  %s", ww, wc, file);
	if (y >= 1 && y < y1) {
		int attr = (live ? A_BOLD : 0) | (sel ? A_REVERSE : 0);
		if (attr)
			attron(attr);
		tui_text_cut(t, y, 0, t->cols, head);
		if (attr)
			attroff(attr);
	}
	if (y + 1 >= 1 && y + 1 < y1)
		tui_text_cut(t, y + 1, 5, t->cols - 5, a);
	if (y + 2 >= 1 && y + 2 < y1)
		tui_text_cut(t, y + 2, 5, t->cols - 5, b);
	return 3;
}

/* The mark of row i: 'A' (the upper marked row), 'B', '*' (one
 * marked), or 0. */
static int tui_history_mark_of(const struct tui *t, int i)
{
	int a = t->hist_mark[0], b = t->hist_mark[1];
	if (i != a && i != b)
		return 0;
	if (a < 0 || b < 0)
		return '*';
	return i == (a < b ? a : b) ? 'A' : 'B';
}

void tui_history_draw(struct tui *t)
{
	char buf[PATH_MAX + 128];
	struct history_row live;
	int R = t->rows, C = t->cols;
	int running = t->run.latest_joint != NULL;
	int nrows;
	const struct history_row **rows = tui_history_rows(t, &live, &nrows);
	if (t->hist_cur < 0 || t->hist_cur >= nrows)
		t->hist_cur = nrows - 1;
	for (int k = 0; k < 2; k++)
		if (t->hist_mark[k] >= nrows)
			t->hist_mark[k] = -1;
	if (rows)
		tui_compare_update(t, rows, nrows);
	/* two marked rows: their comparison takes the lower rows */
	int cmp_h = t->cmp.a >= 0 ? (R - 3) / 2 : 0;
	if (cmp_h > 16)
		cmp_h = 16;

	int body = R - 3 - cmp_h;	/* rows 1 .. R-3-cmp_h */
	int head = (t->hist_nold ? 1 : 0) + (t->hist_rerr[0] ? 1 : 0) +
		   (t->hist_err[0] ? 1 : 0);
	int lines = 3 * nrows + head;
	int maxtop = lines > body ? lines - body : 0;
	/* the selected row in sight */
	int cy = head + 3 * t->hist_cur;
	if (t->hist_top < 0 || t->hist_top > maxtop)
		t->hist_top = maxtop;
	if (cy + 3 > t->hist_top + body)
		t->hist_top = cy + 3 - body;
	if (cy < t->hist_top)
		t->hist_top = cy > head ? cy : 0;

	snprintf(buf, sizeof buf, " run history: %d run%s this session%s%s",
		 t->nhist + running, tui_s(t->nhist + running),
		 t->hist_path[0] ? "; index " :
		 t->hist_err[0] ? " (not kept: the line below says why)" :
		 " (not kept: no index file)", t->hist_path);
	attron(A_REVERSE);
	move(0, 0);
	for (int c = 0; c < C; c++)
		addch(' ');
	char ab[PATH_MAX + 128];
	tui_abbrev(t, ab, sizeof ab, buf, C);
	tui_text(0, 0, C, ab);
	attroff(A_REVERSE);

	int y = 1 - t->hist_top, y1 = R - 2 - cmp_h;
	/* why the index was not written or read, above the rows */
	const char *why[] = {t->hist_err, t->hist_rerr};
	for (int i = 0; i < 2; i++) {
		if (!why[i][0])
			continue;
		snprintf(buf, sizeof buf, "%s%s", i ? "" : "not kept: ", why[i]);
		if (y >= 1 && y < y1)
			tui_text_cut(t, y, 0, C, buf);
		y++;
	}
	if (t->hist_nold) {
		if (y >= 1 && y < y1)
			tui_text(y, 0, C, "earlier sessions (session, run):");
		y++;
	}
	for (int i = 0; i < nrows; i++)
		y += tui_history_draw_row(t, y, y1, rows[i],
					  running && i == nrows - 1,
					  i < t->hist_nold, i == t->hist_cur,
					  tui_history_mark_of(t, i));
	if (cmp_h)
		tui_compare_draw(t, rows, R - 2 - cmp_h, cmp_h);
	free(rows);

	if (t->hist_msg[0]) {
		int attr = t->colors ? COLOR_PAIR(5) : A_BOLD;
		attron(attr);
		tui_text(R - 2, 0, C, t->hist_msg);
		attroff(attr);
	} else if (t->hist_mark[0] >= 0 && t->hist_mark[1] < 0) {
		tui_text(R - 2, 0, C, "1 run marked (*): mark another with "
			 "Space to compare them");
	} else if (!cmp_h) {
		tui_text(R - 2, 0, C, "p05 [99 % interval of p05], p50, p95: "
			 "the accepted loads of the run");
	}
	attron(A_REVERSE);
	move(R - 1, 0);
	for (int c = 0; c < C; c++)
		addch(' ');
	tui_text(R - 1, 0, C, " Esc back  j/k select  Space mark two to "
		 "compare  o/Enter reopen the run's wall");
	attroff(A_REVERSE);
}
