/*
 * tui_stats.c - the running statistics pane: counts, rejections by
 * reason, speed, the percentiles of the accepted λ_min, the
 * characteristic value (5 % percentile) with its distribution-free 99 %
 * interval, and the KS test against the wall's experimental loads.
 *
 * Everything is computed from the tally at draw time (at most 10 times a
 * second): tally_summary is linear in the accepted count, the exact KS
 * test is O(n m) with m the (few) tests.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <curses.h>

#include "slipwall/stats.h"
#include "tui/tui.h"

static const char *tui_stats_num(char *buf, size_t len, double v)
{
	if (isnan(v))
		snprintf(buf, len, "-");
	else
		snprintf(buf, len, "%.4g", v);
	return buf;
}

void tui_stats_draw(struct tui *t, int y0, int x0, int h, int w)
{
	const struct tally *ta = &t->run.tally;
	const struct wall *wall = t->w;
	struct stats_summary s;
	char line[512], a[32], b[32], c[32];
	int y = y0, end = y0 + h;

	tally_summary(ta, &s);
	snprintf(line, sizeof line, "samples  %ld / %ld  %s", ta->samples,
		 t->run.target, tui_run_state(t));
	if (y < end)
		tui_text(y++, x0, w, line);
	/* Speed: samples per second, or seconds per sample when they are
	 * slow; samples in progress with their age and the time left when
	 * one takes more than a second (a large wall: minutes a sample). */
	double rate = tui_run_rate(t);
	struct mc_progress pg;
	tui_run_progress(t, &pg);
	if (ta->samples > 0 && rate < 1)
		snprintf(line, sizeof line, "speed    %.3g s per sample on %d threads",
			 1 / rate, t->threads);
	else if (ta->samples > 0 || pg.oldest < 1)
		snprintf(line, sizeof line, "speed    %s /s on %d threads",
			 tui_stats_num(a, sizeof a, rate), t->threads);
	else
		snprintf(line, sizeof line, "speed    no sample finished yet, %d threads",
			 t->threads);
	if (y < end)
		tui_text(y++, x0, w, line);
	if (pg.busy > 0 && pg.oldest >= 1) {
		long left = t->run.target - ta->samples;
		tui_duration(a, sizeof a, pg.oldest);
		if (ta->samples > 0) {
			tui_duration(b, sizeof b, (double)left / rate);
			snprintf(line, sizeof line, "working  %d in progress, oldest %s; left ~%s",
				 pg.busy, a, b);
		} else {
			/* nothing finished: every worker is on its first
			 * sample, so each takes at least `oldest` */
			long rounds = (left + t->threads - 1) / t->threads;
			tui_duration(b, sizeof b, (double)rounds * pg.oldest);
			snprintf(line, sizeof line, "working  %d in progress for %s; left > %s",
				 pg.busy, a, b);
		}
		if (y < end)
			tui_text(y++, x0, w, line);
	}
	snprintf(line, sizeof line, "accepted %ld (%.1f %%)", ta->accepted,
		 ta->samples ? 100.0 * (double)ta->accepted / (double)ta->samples
			     : 0.0);
	if (y < end)
		tui_text(y++, x0, w, line);

	/* rejections by reason, wrapped */
	long rej = ta->samples - ta->accepted;
	int len = snprintf(line, sizeof line, "rejected %ld", rej);
	const char *sep = ": ";
	for (int k = 0; k < SAMPLE_STATUS_COUNT; k++) {
		if (k == SAMPLE_ACCEPTED || ta->rejected[k] == 0)
			continue;
		char item[64];
		int il = snprintf(item, sizeof item, "%s%s %ld", sep,
				  sample_status_name(k), ta->rejected[k]);
		sep = ", ";
		if (len + il > w && y < end - 1) {
			tui_text(y++, x0, w, line);
			len = snprintf(line, sizeof line, "        ");
			memmove(item, item + 2, strlen(item + 2) + 1);
			il -= 2;
		}
		if (len + il < (int)sizeof line)
			len += snprintf(line + len, sizeof line - (size_t)len, "%s", item);
	}
	if (y < end)
		tui_text(y++, x0, w, line);

	const char *lam = tui_lam(t);
	int ind = t->utf8 ? 1 : 3;	/* columns of lam */
	snprintf(line, sizeof line, "%s min  %-9s p05  %s", lam,
		 tui_stats_num(a, sizeof a, s.min), tui_stats_num(b, sizeof b, s.p05));
	if (y < end)
		tui_text(y++, x0, w, line);
	snprintf(line, sizeof line, "%*s p50  %-9s p95  %s", ind, "",
		 tui_stats_num(a, sizeof a, s.p50), tui_stats_num(b, sizeof b, s.p95));
	if (y < end)
		tui_text(y++, x0, w, line);
	snprintf(line, sizeof line, "%*s max  %-9s mean %s  sd %s", ind, "",
		 tui_stats_num(a, sizeof a, s.max), tui_stats_num(b, sizeof b, s.mean),
		 tui_stats_num(c, sizeof c, s.std));
	if (y < end)
		tui_text(y++, x0, w, line);
	snprintf(line, sizeof line, "characteristic value (p05) %s",
		 tui_stats_num(a, sizeof a, s.p05));
	if (y < end)
		tui_text(y++, x0, w, line);
	if (s.has_ci)
		snprintf(line, sizeof line, "  99 %% interval [%s, %s]",
			 tui_stats_num(b, sizeof b, s.p05_lo),
			 tui_stats_num(c, sizeof c, s.p05_hi));
	else
		snprintf(line, sizeof line, "  99 %% interval: needs 90 accepted");
	if (y < end)
		tui_text(y++, x0, w, line);

	char sv[32], gv[32];
	if (tui_solve_text(t, sv, gv, sizeof sv))
		snprintf(line, sizeof line, "standard %s  gilbert %s", sv, gv);
	else
		snprintf(line, sizeof line, "standard, gilbert: %s", sv);
	if (y < end)
		tui_text(y++, x0, w, line);

	if (wall->ntests > 0) {
		struct stats_ks ks;
		if (ta->lam.n > 0 &&
		    stats_ks2(ta->lam.x, ta->lam.n, wall->tests,
			      (size_t)wall->ntests, &ks) == 0)
			snprintf(line, sizeof line,
				 "KS vs %d tests: D %.3f p %.3g, model<tests p %.3g",
				 wall->ntests, ks.d, ks.p_two_sided, ks.p_greater);
		else
			snprintf(line, sizeof line, "KS vs %d tests: -", wall->ntests);
		if (y < end)
			tui_text(y++, x0, w, line);
	}
	snprintf(line, sizeof line, "%d mechanisms; m/M shows them", ta->nmech);
	if (y < end)
		tui_text(y++, x0, w, line);
}
