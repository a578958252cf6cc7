/*
 * tui_stats.c - the running statistics pane: counts, rejections by
 * reason, speed (samples per second, or seconds per sample when they
 * are slow, with the samples in progress and the time left), the
 * percentiles of the accepted λ_min and their unit, the characteristic
 * value (5 % percentile) with its distribution-free 99 % interval, the
 * probability of collapse at the wall's design load (analysis.design_load:
 * the share of accepted samples with λ_min at most it, with its exact
 * binomial 99 % interval, as `run` prints it), the single-solution values, and the KS test against the wall's
 * experimental loads.
 *
 * Every line fits the pane: a line of numbers that does not fit with
 * four significant digits is written with three, then two, so that no
 * number is cut.  The pane takes the rows it needs and returns how many
 * (the histogram gets the rest).
 *
 * Everything is computed from the tally at draw time (at most 10 times a
 * second): tally_summary is linear in the accepted count, the exact KS
 * test is O(n m) with m the (few) tests.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include <curses.h>

#include "slipwall/collapse.h"
#include "slipwall/mc.h"
#include "slipwall/stats.h"
#include "slipwall/text.h"
#include "tui.h"

/* opt: the level of the lines written now (0: always shown; the
 * highest levels go first when the pane is short: tui_stats_draw);
 * keep: the highest level shown; dry: count the lines of each level
 * in n[] instead of drawing. */
struct tui_lines {
	int y, end, x0, w;
	int opt, keep, dry;
	int n[4];
	const char *dots;	/* the mark of a cut line (tui_dots) */
};

/* A line longer than the pane is cut at a word boundary (a space in its
 * right half), not in the middle of a word, and ends in the mark of a
 * cut ("sd 0.0076 (seismic…"). */
static void tui_stats_text(struct tui_lines *p, const char *line)
{
	char buf[512];
	if (p->opt > p->keep)
		return;
	if (p->dry) {
		p->n[p->opt]++;
		return;
	}
	if (p->y >= p->end)
		return;
	if (tui_cols(line) > p->w && p->w >= 2) {
		int w = p->w - 1;	/* and the mark */
		const char *cut = tui_skip(line, w);
		const char *sp = cut;
		while (sp > line && *sp != ' ')
			sp--;
		if (*cut == ' ' || tui_cols(line) - tui_cols(sp) > w / 2)
			cut = *cut == ' ' ? cut : sp;
		while (cut > line && cut[-1] == ' ')
			cut--;
		snprintf(buf, sizeof buf, "%.*s%s", (int)(cut - line), line,
			 p->dots);
		line = buf;
	}
	tui_text(p->y++, p->x0, p->w, line);
}

/* A line with up to four numbers (fmt has one %s for each, in order;
 * pad: the width the first one is padded to, 0 for none), with the
 * most significant digits that fit; those whose bit is set in probs are
 * probabilities, shown as percentages (tui_pct). */
static void tui_stats_probs(struct tui_lines *p, const char *fmt, int pad,
			    int nv, const double *v, unsigned probs)
{
	char line[256], s[4][32];
	for (int prec = 4; prec >= 2; prec--) {
		for (int i = 0; i < 4; i++)
			if (probs & (1u << i))	/* a probability: a percentage */
				tui_pct(s[i], sizeof s[i], i < nv ? v[i] : NAN);
			else
				text_num(s[i], sizeof s[i],
					 i < nv ? v[i] : NAN, prec);
		if (pad > 0) {
			char tmp[32];
			snprintf(tmp, sizeof tmp, "%-*s", pad, s[0]);
			memcpy(s[0], tmp, sizeof tmp);
		}
		snprintf(line, sizeof line, fmt, s[0], s[1], s[2], s[3]);
		if (tui_cols(line) <= p->w)
			break;
	}
	tui_stats_text(p, line);
}

static void tui_stats_nums(struct tui_lines *p, const char *fmt, int pad,
			   int nv, const double *v)
{
	tui_stats_probs(p, fmt, pad, nv, v, 0);
}

/* Speed: samples per second, or seconds per sample when they are slow;
 * samples in progress with their age and the time left when one takes
 * more than a second (a large wall: minutes a sample). */
static void tui_stats_speed(struct tui *t, struct tui_lines *p)
{
	const struct tally *ta = &t->run.tally;
	const struct wall *wall = t->w;
	int w = p->w;
	char line[512], a[32], b[32];
	double rate = tui_run_rate(t);
	struct mc_progress pg;
	tui_run_progress(t, &pg);
	double v[4];
	/* the threads the run's last pool had: T sets the next pool's */
	int th = t->run.cfg.threads > 0 ? t->run.cfg.threads : t->threads;
	if (ta->samples > 0 && rate < 1) {
		v[0] = 1 / rate;
		snprintf(line, sizeof line, "speed    %%s s a sample, %d thread%s",
			 th, tui_s(th));
		tui_stats_nums(p, line, 0, 1, v);
	} else if (ta->samples > 0 || pg.oldest < 1) {
		text_num(a, sizeof a, rate, rate >= 1e4 ? 6 : 4);
		snprintf(line, sizeof line, "speed    %s /s on %d thread%s", a,
			 th, tui_s(th));
		tui_stats_text(p, line);
	} else {
		tui_stats_text(p, "speed    none finished yet");
	}
	/* a wall whose first sample will be slow says so from the start,
	 * with the a-priori estimate (rough: src/lib/mc.c, "Estimate") */
	double est = t->run.apriori;
	int measured = est != mc_sample_seconds(wall);
	if (ta->samples == 0 && est >= 1) {
		p->opt = 3;
		mc_about(a, sizeof a, est);
		if (measured)
			snprintf(line, sizeof line, "first    %s a sample (as "
				 "the last run of this wall)", a);
		else
			snprintf(line, sizeof line, "first    %s a sample (a "
				 "wall of %d interfaces; rough)", a,
				 wall->nifaces);
		if (tui_cols(line) > w)
			snprintf(line, sizeof line, "first    %s (%s)", a,
				 measured ? "as the last run" : "estimate");
		tui_stats_text(p, line);
		p->opt = 0;
	}
	double left, total, per;
	int how = tui_pace_left(t, &left, &total, &per);
	if (pg.busy > 0 && (pg.oldest >= 1 || (how && total >= 10 &&
						 (ta->samples == 0 || rate < 2)))) {
		tui_duration(a, sizeof a, pg.oldest);
		snprintf(line, sizeof line, "working  %d sample%s, oldest %s",
			 pg.busy, pg.busy == 1 ? "" : "s", a);
		p->opt = 2;
		tui_stats_text(p, line);
		p->opt = 0;
		if (how == 3) {
			/* the last samples, one past the estimate of a
			 * sample: what it still needs is not known (a run's
			 * last slow sample read "left ~0 s" for minutes) */
			tui_duration(b, sizeof b, per);
			snprintf(line, sizeof line, "left     unknown: the oldest "
				 "has run past a sample's ~%s", b);
			if (tui_cols(line) > w)
				snprintf(line, sizeof line, "left     unknown (a "
					 "slow sample)");
			tui_stats_text(p, line);
		} else if (how) {
			/* an estimate, never a bound that only grows
			 * (tui_pace.c) */
			char c[32];
			tui_duration(b, sizeof b, left);
			tui_duration(c, sizeof c, total);
			snprintf(line, sizeof line, "left     %s%s of %s%s",
				 how == 1 ? "about " : "~", b, how == 1 ? "" : "~", c);
			if (tui_cols(line) + 11 <= w)
				strcat(line, how == 2 ? " (estimate)" : measured ?
				       " (last run)" : " (a priori)");
			tui_stats_text(p, line);
		}
	}
}

/* Under the rejections: the blocks that the samples of status st (one
 * of tally_named) named, the three named most often (docs/
 * workbench.md), when the tally is of this wall's blocks. */
static void tui_stats_unheld(struct tui *t, struct tui_lines *p,
			     enum sample_status st)
{
	const struct tally *ta = &t->run.tally;
	int b[3];
	long c[3];
	int n = ta->nblocks == t->w->nblocks ? tally_unheld(ta, st, b, c, 3)
					     : 0;
	if (n <= 0)
		return;
	char line[512];
	int len = snprintf(line, sizeof line, "%s:", tally_unheld_text(st));
	for (int i = 0; i < n && i < 3 && len < (int)sizeof line; i++)
		len += snprintf(line + len, sizeof line - (size_t)len,
				"%s %s (%ld)", i ? "," : "", t->w->blocks[b[i]].id,
				c[i]);
	if (n > 3 && len < (int)sizeof line)
		snprintf(line + len, sizeof line - (size_t)len, ", %d more",
			 n - 3);
	tui_stats_text(p, line);
}

/* Accepted, and the rejections by reason, wrapped. */
static void tui_stats_counts(struct tui *t, struct tui_lines *p)
{
	const struct tally *ta = &t->run.tally;
	int w = p->w;
	char line[512];
	snprintf(line, sizeof line, "accepted %ld (%.1f %%)", ta->accepted,
		 ta->samples ? 100.0 * (double)ta->accepted / (double)ta->samples
			     : 0.0);
	tui_stats_text(p, line);

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
		if (len + il > w && p->y < p->end - 1) {
			tui_stats_text(p, line);
			len = snprintf(line, sizeof line, "        ");
			memmove(item, item + 2, strlen(item + 2) + 1);
			il -= 2;
		}
		if (len + il < (int)sizeof line)
			len += snprintf(line + len, sizeof line - (size_t)len, "%s", item);
	}
	tui_stats_text(p, line);
	for (int u = 0; u < TALLY_NAMED; u++)
		tui_stats_unheld(t, p, tally_named[u]);
}

/* The loads: order statistics, the characteristic value and its
 * interval, the probability of collapse at the design load. */
static void tui_stats_loads(struct tui *t, struct tui_lines *p,
			    const struct stats_summary *s)
{
	const struct tally *ta = &t->run.tally;
	const struct wall *wall = t->w;
	char line[512];
	double v[4];
	const char *lam = tui_lam(t);
	int ind = t->utf8 ? 1 : 3;	/* columns of lam */
	snprintf(line, sizeof line, "%s min  %%s max  %%s", lam);
	v[0] = s->min;
	v[1] = s->max;
	tui_stats_nums(p, line, 10, 2, v);
	snprintf(line, sizeof line, "%*s p05  %%s p50  %%s", ind, "");
	v[0] = s->p05;
	v[1] = s->p50;
	tui_stats_nums(p, line, 10, 2, v);
	snprintf(line, sizeof line, "%*s p95  %%s mean %%s", ind, "");
	v[0] = s->p95;
	v[1] = s->mean;
	p->opt = 1;
	tui_stats_nums(p, line, 10, 2, v);
	snprintf(line, sizeof line, "%*s  sd  %%s (%s)", ind, "",
		 tui_load_unit(wall));
	v[0] = s->std;
	p->opt = 2;
	tui_stats_nums(p, line, 10, 1, v);
	p->opt = 0;
	v[0] = s->p05;
	if (tui_compare_p05(t, s->p05, p->w, line, sizeof line))
		tui_stats_text(p, line);	/* and the previous run's */
	else
		tui_stats_nums(p, "characteristic value (p05) %s", 0, 1, v);
	p->opt = 1;
	if (s->has_ci) {
		v[0] = s->p05_lo;
		v[1] = s->p05_hi;
		tui_stats_nums(p, "  99 %% interval [%s, %s]", 0, 2, v);
	} else {
		tui_stats_text(p, "  99 % interval: needs 90 accepted");
	}
	p->opt = 0;
	if (wall->design_load > 0) {
		struct collapse c;
		collapse_at(ta->lam.x, ta->lam.n, wall->design_load,
			    "design_load", &c);
		/* k and n exactly: they are counts */
		snprintf(line, sizeof line, "P(%s <= design %%s) %%s, %zu of %zu",
			 lam, c.k, c.n);
		/* the counts go when even two digits do not fit with them
		 * (a line cut at "601 of" says something else) */
		char l2[512], a2[32], b2[32];
		text_num(a2, sizeof a2, c.load, 2);
		tui_pct(b2, sizeof b2, c.p);
		snprintf(l2, sizeof l2, line, a2, b2);
		if (tui_cols(l2) > p->w)
			snprintf(line, sizeof line, "P(%s <= design %%s) %%s", lam);
		v[0] = c.load;
		v[1] = c.p;
		tui_stats_probs(p, line, 0, 2, v, 2);
		if (c.n > 0) {
			v[0] = c.lo;
			v[1] = c.hi;
			p->opt = 2;
			tui_stats_probs(p, "  99 %% interval [%s, %s] (binomial)",
					0, 2, v, 3);
			p->opt = 0;
		}
	}

}

/* The single-solution values, the KS test against the tests, the
 * mechanisms. */
static void tui_stats_tail(struct tui *t, struct tui_lines *p)
{
	const struct tally *ta = &t->run.tally;
	const struct wall *wall = t->w;
	char line[512];
	double v[4];
	char sv[32], gv[32];
	if (tui_solve_text(t, sv, gv, sizeof sv)) {
		v[0] = t->has_std ? tui_load(t, t->lam_std) : NAN;
		v[1] = t->has_gil ? tui_load(t, t->lam_gil) : NAN;
		snprintf(line, sizeof line, "standard %s  gilbert %s",
			 t->has_std ? "%s" : "n/a%.0s", t->has_gil ? "%s" : "n/a%.0s");
		tui_stats_nums(p, line, 0, 2, v);
	} else {
		snprintf(line, sizeof line, "standard, gilbert: %s", sv);
		tui_stats_text(p, line);
	}

	if (wall->ntests > 0) {
		struct stats_ks ks;
		if (ta->lam.n > 0 &&
		    stats_ks2(ta->lam.x, ta->lam.n, wall->tests,
			      (size_t)wall->ntests, &ks) == 0) {
			snprintf(line, sizeof line,
				 "KS vs %d test%s: D %%s p %%s, model<tests p %%s",
				 wall->ntests, tui_s(wall->ntests));
			v[0] = ks.d;
			v[1] = ks.p_two_sided;
			v[2] = ks.p_greater;
			tui_stats_probs(p, line, 0, 3, v, 6);
		} else {
			snprintf(line, sizeof line, "KS vs %d test%s: -",
				 wall->ntests, tui_s(wall->ntests));
			tui_stats_text(p, line);
		}
	}
	const struct family_set *fs = tui_run_families(t);
	int nf = fs ? fs->nfam : 0;
	if (ta->nmech > 0)
		snprintf(line, sizeof line, "%d mechanism%s in %d famil%s; m/M "
			 "shows them", ta->nmech, tui_s(ta->nmech), nf,
			 nf == 1 ? "y" : "ies");
	else
		snprintf(line, sizeof line, "no mechanism yet");
	p->opt = 3;
	tui_stats_text(p, line);
	p->opt = 0;
}

int tui_stats_draw(struct tui *t, int y0, int x0, int h, int w)
{
	const struct tally *ta = &t->run.tally;
	struct stats_summary s;
	struct tui_lines p = {y0, y0 + h, x0, w, 0, 3, 1, {0}, tui_dots(t)};
	char line[512];

	tally_summary(ta, &s);
	/* samples finished behind one still running are shown in order,
	 * later: say how many (walls/facade.yaml read "2 / 20" for 10 s with
	 * 17 more finished, and "left ~0 s") */
	struct mc_progress pg;
	long ahead = tui_run_progress(t, &pg) ? pg.ahead : 0;
	/* twice: first the lines of each level counted, then drawn with
	 * the levels that fit (the lowest-priority ones dropped first) */
	for (int pass = 0; pass < 2; pass++) {
		if (ta->samples > t->run.target)	/* n lowered below it */
			snprintf(line, sizeof line, "samples  %ld  %s (%ld "
				 "asked)", ta->samples, tui_run_state(t),
				 t->run.target);
		else
			snprintf(line, sizeof line, "samples  %ld / %ld  %s",
				 ta->samples, t->run.target, tui_run_state(t));
		if (ahead > 0) {
			size_t u = strlen(line);
			snprintf(line + u, sizeof line - u, ", %ld more done",
				 ahead);
		}
		tui_stats_text(&p, line);
		tui_stats_speed(t, &p);
		tui_stats_counts(t, &p);
		tui_stats_loads(t, &p, &s);
		tui_stats_tail(t, &p);
		if (pass == 0) {
			int used = 0;
			p.keep = -1;
			for (int l = 0; l < 4; l++) {
				used += p.n[l];
				if (used > h && l > 0)
					break;
				p.keep = l;
			}
			p.dry = 0;
		}
	}
	return p.y - y0;
}
