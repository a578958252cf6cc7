/*
 * tui_pair.c - the sample browser's pair (=, docs/workbench.md, "The
 * sample browser"): among the kept accepted samples with the shown
 * one's joint states (the same mechanism), the ones of the least and of
 * the largest load; = shows one, then the other, and the message line
 * names both.  Why one mechanism holds at loads far apart is in the two
 * samples' contact points.
 *
 * Where the shown sample is the only one kept of its mechanism, as
 * nearly every sample of a wall of real size is (each has joint states
 * of its own), the pair is of its family instead: the same moving
 * blocks (docs/statistics.md, "Mechanism families").
 *
 * It reads the browser's kept samples (tui_browse.c), the run's
 * families (tui_run.c) and their ranks (tui_wall.c), and none of those
 * calls it: its own file keeps the three free of a circle.
 */
#include <string.h>

#include "tui.h"

/* Of the kept accepted samples that match s (its mechanism, or its
 * family f when f >= 0), the least load's (*lo) and the largest's (*hi),
 * the earlier sample on a tie. */
static void tui_pair_range(const struct tui *t,
			   const struct tui_browse_sample *s, int f,
			   long *lo, long *hi, double *llo, double *lhi)
{
	const struct family_set *fs = f >= 0 ? tui_run_families(t) : NULL;
	struct tui_browse_sample o;
	*lo = *hi = s->index;
	*llo = *lhi = s->lam;
	for (long j = tui_browse_first(t); j >= 0 && j < t->browse.next; j++) {
		if (!tui_browse_sample_at(t, j, &o) || o.status != SAMPLE_ACCEPTED)
			continue;
		if (f >= 0 ? tui_run_family_of(t, fs, o.joint) != f
			   : strcmp(o.joint, s->joint) != 0)
			continue;
		if (o.lam < *llo || (o.lam == *llo && j < *lo)) {
			*llo = o.lam;
			*lo = j;
		}
		if (o.lam > *lhi || (o.lam == *lhi && j < *hi)) {
			*lhi = o.lam;
			*hi = j;
		}
	}
}

void tui_pair_key(struct tui *t, int ch)
{
	struct tui_browse_sample s;
	(void)ch;
	if (!t->browse.open)
		tui_browse_key_toggle(t, 'S');
	if (!tui_browse_shown(t, &s))
		return;
	long shown = s.index, first = tui_browse_first(t), i;
	/* the mechanism: the shown sample's, else the latest accepted one */
	for (i = shown; i >= first; i--)
		if (tui_browse_sample_at(t, i, &s) && s.status == SAMPLE_ACCEPTED)
			break;
	if (i < first) {
		tui_message(t, 1, "pair: no accepted sample kept");
		return;
	}
	long lo, hi;
	double llo, lhi;
	int f = -1, n, k;
	tui_pair_range(t, &s, -1, &lo, &hi, &llo, &lhi);
	if (lo == hi &&
	    (f = tui_run_family_of(t, tui_run_families(t), s.joint)) >= 0) {
		tui_pair_range(t, &s, f, &lo, &hi, &llo, &lhi);
		k = tui_family_rank(t, s.joint, &n);
	} else {
		f = -1;
		k = tui_browse_mech_rank(t, s.joint, &n);
	}
	t->browse.at = shown == lo ? hi : lo;
	const char *unit = strcmp(tui_load_unit(t->w), "N") ? "" : " N";
	if (lo == hi)
		tui_message(t, 0, "pair: sample %ld is the only one kept of its "
			    "mechanism and of its family", lo + 1);
	else
		tui_message(t, 0, "pair: %s %d/%d, %s_min %.4g%s (sample "
			    "%ld) .. %.4g%s (sample %ld); = alternates",
			    f >= 0 ? "family" : "mechanism", k, n,
			    tui_lam(t), tui_load(t, llo), unit, lo + 1,
			    tui_load(t, lhi), unit, hi + 1);
}
