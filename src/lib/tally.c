/*
 * tally.c - what a run has found so far; see tally.h.
 *
 * The consumer of the Monte Carlo pool (the `run` command, the
 * workbench's UI thread) feeds every popped sample to tally_add().  The
 * accepted loads go into a sorted array (running percentiles), the
 * mechanisms into an array in order of first appearance.  A mechanism is
 * found again by its joint-state string through an open-addressing hash
 * table of indices into that array (FNV-1a, linear probing, kept at most
 * half full), so a run of 10^5 samples on a wall with thousands of
 * interfaces costs one hash of the string per sample, not a scan of every
 * mechanism seen.  Nothing here is shared between threads.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/json.h"
#include "slipwall/tally.h"

void tally_init(struct tally *t, const struct wall *w)
{
	memset(t, 0, sizeof *t);
	t->nifaces = w->nifaces;
	t->nblocks = w->nblocks;
	wall_quantity(w, &t->q);
	t->ci_conf = 0.99;
}

void tally_free(struct tally *t)
{
	for (int k = 0; k < t->nmech; k++) {
		free(t->mech[k].joint);
		free(t->mech[k].vel);
	}
	free(t->mech);
	free(t->hash);
	free(t->unheld);
	stats_sorted_free(&t->lam);
	memset(t, 0, sizeof *t);
}

static uint64_t fnv1a(const char *s, size_t n)
{
	uint64_t h = 1469598103934665603ull;
	for (size_t i = 0; i < n; i++) {
		h ^= (unsigned char)s[i];
		h *= 1099511628211ull;
	}
	return h;
}

/* Rebuild the index with room for twice the mechanisms (power of two). */
static void rehash(struct tally *t)
{
	int cap = t->hashcap ? 2 * t->hashcap : 64;
	int *h = sw_xmalloc(sizeof(int) * (size_t)cap);
	for (int i = 0; i < cap; i++)
		h[i] = -1;
	for (int k = 0; k < t->nmech; k++) {
		uint64_t s = fnv1a(t->mech[k].joint, (size_t)t->nifaces);
		int i = (int)(s & (uint64_t)(cap - 1));
		while (h[i] >= 0)
			i = (i + 1) & (cap - 1);
		h[i] = k;
	}
	free(t->hash);
	t->hash = h;
	t->hashcap = cap;
}

/* The index of mechanism `joint` in t->mech, or -1 with *slot the free
 * slot of the index where it would go (t->hashcap > 0). */
static int probe(const struct tally *t, const char *joint, int *slot)
{
	size_t len = (size_t)t->nifaces;
	uint64_t s = fnv1a(joint, len);
	int i = (int)(s & (uint64_t)(t->hashcap - 1));
	while (t->hash[i] >= 0) {
		int k = t->hash[i];
		if (!memcmp(t->mech[k].joint, joint, len))
			return k;
		i = (i + 1) & (t->hashcap - 1);
	}
	*slot = i;
	return -1;
}

/* The index of mechanism `joint` in t->mech, adding it if new. */
static int find_or_add(struct tally *t, const char *joint, const double *vel,
		       double lam)
{
	size_t len = (size_t)t->nifaces;
	if (2 * (t->nmech + 1) > t->hashcap)
		rehash(t);
	int i, k = probe(t, joint, &i);
	if (k >= 0)
		return k;
	if (t->nmech == t->capmech) {
		t->capmech = t->capmech ? 2 * t->capmech : 16;
		t->mech = sw_xrealloc(t->mech, sizeof *t->mech * (size_t)t->capmech);
	}
	struct tally_mech *m = &t->mech[t->nmech];
	m->joint = sw_xmalloc(len + 1);
	memcpy(m->joint, joint, len);
	m->joint[len] = 0;
	m->vel = sw_xmalloc(sizeof(double) * (3 * (size_t)t->nblocks + 1));
	memcpy(m->vel, vel, sizeof(double) * 3 * (size_t)t->nblocks);
	m->count = 0;
	m->lam_lo = m->lam_hi = lam;
	t->hash[i] = t->nmech;
	return t->nmech++;
}

int tally_find(const struct tally *t, const char *joint)
{
	int slot;
	return t->hashcap == 0 ? -1 : probe(t, joint, &slot);
}

const enum sample_status tally_named[TALLY_NAMED] = {
	SAMPLE_NO_EQUILIBRIUM, SAMPLE_NONPOSITIVE, SAMPLE_UNSTABLE,
	SAMPLE_HANGING,
};

/* The row of t->unheld that a status counts in, or -1. */
static int unheld_row(enum sample_status st)
{
	for (int u = 0; u < TALLY_NAMED; u++)
		if (tally_named[u] == st)
			return u;
	return -1;
}

void tally_add(struct tally *t, const struct record *it)
{
	t->samples++;
	t->iterations += it->iterations;
	t->lps += it->lps;
	t->compute_seconds += it->seconds;
	if (it->status != SAMPLE_ACCEPTED) {
		if ((unsigned)it->status < SAMPLE_STATUS_COUNT)
			t->rejected[it->status]++;
		else
			t->rejected[SAMPLE_NUMERICAL]++;
		int u = unheld_row(it->status);
		if (u >= 0 && it->unheld >= 0 && it->unheld < t->nblocks) {
			if (!t->unheld)
				t->unheld = sw_xcalloc(TALLY_NAMED *
						       (size_t)t->nblocks,
						       sizeof *t->unheld);
			t->unheld[u * t->nblocks + it->unheld]++;
		}
		return;
	}
	double lam = t->q.scale * it->lambda_min;
	t->accepted++;
	stats_sorted_insert(&t->lam, lam);
	t->lam_sum += lam;
	/* find_or_add may move t->mech: index it afterwards */
	int k = find_or_add(t, it->joint, it->vel, lam);
	struct tally_mech *m = &t->mech[k];
	m->count++;
	if (lam < m->lam_lo)
		m->lam_lo = lam;
	if (lam > m->lam_hi)
		m->lam_hi = lam;
}

static int by_count(const void *a, const void *b)
{
	const struct tally_rank *ra = a, *rb = b;
	if (ra->count != rb->count)
		return ra->count > rb->count ? -1 : 1;
	/* equal counts: first appearance first (a stable order that does
	 * not depend on the thread count) */
	return (ra->k > rb->k) - (ra->k < rb->k);
}

const char *tally_unheld_text(enum sample_status st)
{
	return st == SAMPLE_NO_EQUILIBRIUM ? "cannot be held" :
	       st == SAMPLE_NONPOSITIVE ? "falls under any load" :
	       st == SAMPLE_UNSTABLE ? "stands only under load" :
	       st == SAMPLE_HANGING ? "lowest hanging block" : NULL;
}

int tally_unheld(const struct tally *t, enum sample_status st, int *blocks,
		 long *counts, int max)
{
	int u = unheld_row(st);
	if (!t->unheld || u < 0)
		return 0;
	const long *row = t->unheld + (size_t)u * (size_t)t->nblocks;
	struct tally_rank *r = sw_xmalloc(sizeof *r * (size_t)t->nblocks);
	int n = 0;
	for (int b = 0; b < t->nblocks; b++)
		if (row[b]) {
			r[n].count = row[b];
			r[n++].k = b;
		}
	int m = tally_ranked(r, n, blocks, max);
	for (int i = 0; i < m; i++)
		counts[i] = row[blocks[i]];
	free(r);
	return n;
}

int tally_ranked(struct tally_rank *r, int n, int *idx, int max)
{
	qsort(r, (size_t)n, sizeof *r, by_count);
	int m = n < max ? n : max;
	for (int i = 0; i < m; i++)
		idx[i] = r[i].k;
	return m < 0 ? 0 : m;
}

int tally_top(const struct tally *t, int *idx, int max)
{
	if (max <= 0 || t->nmech == 0)
		return 0;
	struct tally_rank *r = sw_xmalloc(sizeof *r * (size_t)t->nmech);
	for (int k = 0; k < t->nmech; k++) {
		r[k].count = t->mech[k].count;
		r[k].k = k;
	}
	int n = tally_ranked(r, t->nmech, idx, max);
	free(r);
	return n;
}

void tally_summary(const struct tally *t, struct stats_summary *s)
{
	stats_summarise_conf(t->lam.x, t->lam.n,
			     t->ci_conf > 0 ? t->ci_conf : 0.99, s);
}

void tally_json(const struct tally *t, struct json *j)
{
	struct stats_summary s;
	tally_summary(t, &s);
	json_key(j, "samples");
	json_int(j, t->samples);
	json_key(j, "accepted");
	json_int(j, t->accepted);
	json_key(j, "rejected");
	json_object_begin(j);
	for (int k = 0; k < SAMPLE_STATUS_COUNT; k++) {
		if (k == SAMPLE_ACCEPTED)
			continue;
		json_key(j, sample_status_name(k));
		json_int(j, t->rejected[k]);
	}
	json_object_end(j);
	tally_quantity_json(j, &t->q);
	tally_summary_json(j, &s);
}

void tally_quantity_json(struct json *j, const struct wall_quantity *q)
{
	json_key(j, "load");
	json_object_begin(j);
	json_key_string(j, "quantity", q->name);
	json_key_string(j, "unit", q->unit);
	json_key_double(j, "scale", q->scale);
	json_object_end(j);
}

void tally_summary_json(struct json *j, const struct stats_summary *s)
{
	json_key(j, "lambda");
	json_object_begin(j);
	const char *names[7] = {"min", "p05", "p50", "p95", "max", "mean", "std"};
	const double vals[7] = {s->min, s->p05, s->p50, s->p95, s->max,
				s->mean, s->std};
	for (int k = 0; k < 7; k++) {
		json_key(j, names[k]);
		json_double(j, vals[k]);
	}
	json_object_end(j);
	json_key(j, "p05_ci99");
	if (s->has_ci) {
		json_array_begin(j);
		json_double(j, s->p05_lo);
		json_double(j, s->p05_hi);
		json_array_end(j);
	} else {
		json_null(j);
	}
}
