/*
 * tui_browse.c - the sample browser: the run's samples one at a time,
 * each with its number, status, λ_min, mechanism and draw (where each
 * joint's two contact points were, and its friction when friction is
 * random: docs/method.md, "The random contact"), shown by the wall pane
 * (tui_wall.c: the contact points on the sketch) and the histogram
 * (tui_hist.c: the sample's bin lit).
 *
 * What is kept: every sample of the run as it is counted (tui_run.c
 * calls tui_browse_push in index order, on the UI thread), its λ_min,
 * status, joint states, velocities and draw, in a ring of `cap` slots:
 * sample i in slot i % cap, so the latest `cap` samples are there.  cap
 * is 100,000 samples, fewer on a large wall: the ring takes at most
 * 64 MiB (docs/workbench.md, "The sample browser").  Keeping them in
 * memory rather than reading rows back from the samples file keeps the
 * browser working when the file could not be made or was cut by a
 * write error, and costs no parsing of a file being written.
 *
 * The mechanism view (m/M, browser closed) lights the bins of the kept
 * samples of the family on show (tui_hist.c reads them through
 * tui_browse_sample_at).
 *
 * The joint picked (< >): one interface of the wall, 1 first as the
 * samples file's xa_k, xb_k and mu_k columns count them; the wall pane
 * marks it on the sketch and its legend gives the shown sample's
 * friction μ there (tui_wall.c), so that a joint can be pointed at and
 * its draw read (docs/workbench.md, "The sample browser").  It stays
 * picked across runs while the wall has that many joints.
 *
 * The pair (=) is tui_pair.c's.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <curses.h>

#include "slipwall/stats.h"
#include "tui.h"

#define TUI_BROWSE_MAX 100000L		/* samples kept at most */
#define TUI_BROWSE_BYTES (64L << 20)	/* memory of the ring at most */

void tui_browse_free(struct tui *t)
{
	struct tui_browse *b = &t->browse;
	free(b->lam);
	free(b->status);
	free(b->joint);
	free(b->xi);
	free(b->mu);
	free(b->vel);
	b->lam = b->xi = b->mu = b->vel = NULL;
	b->status = NULL;
	b->joint = NULL;
	b->cap = 0;
	b->next = 0;
}

static int tui_browse_alloc(struct tui_browse *b, long cap)
{
	size_t n = (size_t)cap, f = (size_t)b->nifaces;
	b->lam = malloc(n * sizeof(double));
	b->status = malloc(n);
	b->joint = malloc(n * (f + 1));
	b->xi = malloc(n * 2 * f * sizeof(double) + 1);
	b->mu = b->has_mu ? malloc(n * f * sizeof(double) + 1) : NULL;
	b->vel = malloc(n * 3 * (size_t)b->nblocks * sizeof(double) + 1);
	b->cap = cap;
	return b->lam && b->status && b->joint && b->xi && b->vel &&
	       (b->mu || !b->has_mu);
}

void tui_browse_reset(struct tui *t)
{
	struct tui_browse *b = &t->browse;
	const struct wall *w = t->w;

	tui_browse_free(t);
	b->nifaces = w->nifaces;
	b->nblocks = w->nblocks;
	b->has_mu = w->mu_cov > 0;
	b->at = LONG_MAX;	/* the latest, until a key chooses one */
	if (b->pick > w->nifaces)
		b->pick = 0;
	size_t per = sizeof(double) + 1 + (size_t)w->nifaces + 1 +
		     (2 + (b->has_mu ? 1 : 0)) * sizeof(double) * (size_t)w->nifaces +
		     3 * sizeof(double) * (size_t)w->nblocks;
	long cap = (long)(TUI_BROWSE_BYTES / per);
	if (cap > TUI_BROWSE_MAX)
		cap = TUI_BROWSE_MAX;
	if (cap < 1)
		cap = 1;
	/* short of memory: fewer samples, down to none */
	while (cap > 0 && !tui_browse_alloc(b, cap)) {
		tui_browse_free(t);
		cap /= 4;
	}
}

void tui_browse_push(struct tui *t, const struct record *rec)
{
	struct tui_browse *b = &t->browse;
	if (b->cap <= 0 || rec->index != b->next)
		return;	/* samples come in order; anything else is kept out */
	size_t s = (size_t)(rec->index % b->cap), f = (size_t)b->nifaces;
	b->lam[s] = rec->lambda_min;
	b->status[s] = (signed char)rec->status;
	memcpy(b->joint + s * (f + 1), rec->joint, f + 1);
	memcpy(b->xi + s * 2 * f, rec->draw.xi, 2 * f * sizeof(double));
	if (b->mu)
		memcpy(b->mu + s * f, rec->draw.mu, f * sizeof(double));
	memcpy(b->vel + s * 3 * (size_t)b->nblocks, rec->vel,
	       3 * (size_t)b->nblocks * sizeof(double));
	b->next++;
}

long tui_browse_first(const struct tui *t)
{
	const struct tui_browse *b = &t->browse;
	if (b->cap <= 0 || b->next == 0)
		return -1;
	return b->next > b->cap ? b->next - b->cap : 0;
}

/* The sample i, kept (tui_browse_first .. next - 1). */
static void tui_browse_get(const struct tui *t, long i,
			   struct tui_browse_sample *s)
{
	const struct tui_browse *b = &t->browse;
	size_t k = (size_t)(i % b->cap), f = (size_t)b->nifaces;
	s->index = i;
	s->status = b->status[k];
	s->lam = b->lam[k];
	s->joint = b->joint + k * (f + 1);
	s->xi = b->xi + k * 2 * f;
	s->mu = b->mu ? b->mu + k * f : NULL;
	s->vel = b->vel + k * 3 * (size_t)b->nblocks;
}

/* The index on show: b->at within the kept ones. */
static long tui_browse_index(const struct tui *t)
{
	const struct tui_browse *b = &t->browse;
	long first = tui_browse_first(t);
	if (first < 0)
		return -1;
	if (b->at < first)
		return first;
	return b->at > b->next - 1 ? b->next - 1 : b->at;
}

int tui_browse_shown(const struct tui *t, struct tui_browse_sample *s)
{
	long i = tui_browse_index(t);
	if (!t->browse.open || i < 0)
		return 0;
	tui_browse_get(t, i, s);
	return 1;
}

void tui_browse_key_toggle(struct tui *t, int ch)
{
	struct tui_browse *b = &t->browse;
	if (b->open || ch == 27) {
		b->open = 0;
		return;
	}
	b->open = 1;
	b->at = b->next > 0 ? b->next - 1 : LONG_MAX;
	if (b->cap <= 0)
		tui_message(t, 1, "sample browser: no memory to keep samples");
	else
		tui_message(t, 0, "sample browser: [ ] step, Home End, = pair, < > joint, "
			    "S or Esc closes");
}

void tui_browse_key_step(struct tui *t, int ch)
{
	struct tui_browse *b = &t->browse;
	long first = tui_browse_first(t);
	if (!b->open) {
		tui_browse_key_toggle(t, 'S');
		if (ch == '[' || ch == ']')
			return;	/* opened on the latest */
	}
	if (first < 0)
		return;
	long i = tui_browse_index(t);
	if (ch == '[')
		i = i > first ? i - 1 : first;
	else if (ch == ']')
		i = i < b->next - 1 ? i + 1 : b->next - 1;
	else if (ch == KEY_HOME)
		i = first;
	else
		i = b->next - 1;
	b->at = i;
}

/* The mechanism's place among the most frequent ones (m/M's number):
 * 1 .. *n, or 0 when the tally does not have it. */
int tui_browse_mech_rank(const struct tui *t, const char *joint, int *n)
{
	const struct tally *ta = &t->run.tally;
	int k = 0;
	*n = ta->nmech;
	if (ta->nmech <= 0)
		return 0;
	int *idx = malloc(sizeof(int) * (size_t)ta->nmech);
	int m = idx ? tally_top(ta, idx, ta->nmech) : 0;
	for (int j = 0; j < m && !k; j++)
		if (strcmp(ta->mech[idx[j]].joint, joint) == 0)
			k = j + 1;
	free(idx);
	return k;
}

void tui_browse_key_joint(struct tui *t, int ch)
{
	struct tui_browse *b = &t->browse;
	int n = t->w->nifaces;
	if (!b->open)
		tui_browse_key_toggle(t, 'S');
	if (n <= 0) {
		tui_message(t, 1, "joint: the wall has no joints");
		return;
	}
	/* from none: > the first joint, < the last; around at the ends */
	if (ch == '>')
		b->pick = b->pick >= n ? 1 : b->pick + 1;
	else
		b->pick = b->pick <= 1 ? n : b->pick - 1;
}

void tui_browse_pick_at(struct tui *t, double x, double y)
{
	const struct wall *w = t->w;
	double best = INFINITY;
	int k = -1;
	for (int i = 0; i < w->nifaces; i++) {
		const struct wall_interface *f = &w->ifaces[i];
		double dx = f->p2[0] - f->p1[0], dy = f->p2[1] - f->p1[1];
		double l2 = dx * dx + dy * dy, u = 0;
		if (l2 > 0)
			u = fmin(1, fmax(0, ((x - f->p1[0]) * dx +
					     (y - f->p1[1]) * dy) / l2));
		double d = hypot(x - f->p1[0] - u * dx, y - f->p1[1] - u * dy);
		if (d < best) {
			best = d;
			k = i;
		}
	}
	if (k < 0)
		return;
	t->browse.pick = k + 1;
}

int tui_browse_sample_at(const struct tui *t, long i,
			 struct tui_browse_sample *s)
{
	long first = tui_browse_first(t);
	if (first < 0 || i < first || i >= t->browse.next)
		return 0;
	tui_browse_get(t, i, s);
	return 1;
}
