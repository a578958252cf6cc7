/*
 * test_tally.c - the run tally: counts by status, the sorted accepted
 * loads, mechanisms found again by their joint string (through the hash
 * table, past several rehashes), the order of tally_top, the blocks
 * that no_equilibrium samples could not hold, and the summary on data
 * whose percentiles are known by hand.
 */
#include <stdlib.h>
#include <string.h>

#include "slipwall/tally.h"
#include "tap.h"

#define M 5		/* interfaces of the fake wall */
#define B 3		/* blocks */

static struct wall fake;	/* tally_init reads nifaces and nblocks only */

static void item(struct record *it, long i, enum sample_status st,
		 double lam, const char *joint, double v0)
{
	it->index = i;
	it->status = st;
	it->lambda_min = lam;
	it->lambda_max = lam + 1;
	it->iterations = 3;
	it->lps = 7;
	it->seconds = 0.5;
	memset(it->joint, 0, M + 1);
	if (joint)
		memcpy(it->joint, joint, M);
	for (int k = 0; k < 3 * B; k++)
		it->vel[k] = v0 + k;
}

static void test_counts(void)
{
	struct tally t;
	struct record it;
	tally_init(&t, &fake);
	record_init(&it, &fake);
	/* 6 accepted with three mechanisms (3 x A, 2 x B, 1 x C), 4 rejected */
	item(&it, 0, SAMPLE_ACCEPTED, 5.0, "s.h..", 100);
	tally_add(&t, &it);
	item(&it, 1, SAMPLE_NO_MECHANISM, NAN, NULL, 0);
	tally_add(&t, &it);
	item(&it, 2, SAMPLE_ACCEPTED, 2.0, ".s.o.", 200);
	tally_add(&t, &it);
	item(&it, 3, SAMPLE_ACCEPTED, 7.0, "s.h..", 300);
	tally_add(&t, &it);
	item(&it, 4, SAMPLE_NOT_CONVERGED, NAN, NULL, 0);
	tally_add(&t, &it);
	item(&it, 5, SAMPLE_ACCEPTED, 1.0, "....H", 400);
	tally_add(&t, &it);
	item(&it, 6, SAMPLE_NO_MECHANISM, NAN, NULL, 0);
	tally_add(&t, &it);
	item(&it, 7, SAMPLE_ACCEPTED, 3.0, ".s.o.", 500);
	tally_add(&t, &it);
	item(&it, 8, SAMPLE_UNSTABLE, NAN, NULL, 0);
	tally_add(&t, &it);
	item(&it, 9, SAMPLE_ACCEPTED, 4.0, "s.h..", 600);
	tally_add(&t, &it);

	tap_ok(t.samples == 10, "10 samples counted");
	tap_ok(t.accepted == 6, "6 accepted");
	tap_ok(t.rejected[SAMPLE_NO_MECHANISM] == 2 &&
	       t.rejected[SAMPLE_NOT_CONVERGED] == 1 &&
	       t.rejected[SAMPLE_UNSTABLE] == 1 &&
	       t.rejected[SAMPLE_NO_EQUILIBRIUM] == 0,
	       "rejections counted by reason (2 no_mechanism, 1 "
	       "not_converged, 1 unstable)");
	tap_ok(t.iterations == 30 && t.lps == 70, "iterations and LPs summed");
	tap_near(t.compute_seconds, 5.0, 1e-12, "compute seconds summed");
	tap_near(t.lam_sum, 22.0, 1e-12, "sum of the accepted loads");

	int sorted = t.lam.n == 6;
	static const double want[6] = {1, 2, 3, 4, 5, 7};
	for (size_t k = 0; sorted && k < 6; k++)
		sorted = t.lam.x[k] == want[k];
	tap_ok(sorted, "accepted loads kept sorted: 1 2 3 4 5 7");

	tap_ok(t.nmech == 3, "three distinct mechanisms (got %d)", t.nmech);
	tap_ok(t.nmech == 3 && !strcmp(t.mech[0].joint, "s.h..") &&
	       !strcmp(t.mech[1].joint, ".s.o.") &&
	       !strcmp(t.mech[2].joint, "....H"),
	       "mechanisms in order of first appearance");
	tap_ok(t.mech[0].count == 3 && t.mech[1].count == 2 &&
	       t.mech[2].count == 1, "mechanism counts 3, 2, 1");
	tap_ok(t.mech[0].lam_lo == 4.0 && t.mech[0].lam_hi == 7.0,
	       "load range of the first mechanism [4, 7]");
	tap_ok(t.mech[0].vel[0] == 100 && t.mech[0].vel[8] == 108 &&
	       t.mech[1].vel[0] == 200,
	       "velocities of each mechanism's first sample kept");

	int idx[8];
	int n = tally_top(&t, idx, 8);
	tap_ok(n == 3 && idx[0] == 0 && idx[1] == 1 && idx[2] == 2,
	       "tally_top: most frequent first");
	n = tally_top(&t, idx, 2);
	tap_ok(n == 2 && idx[0] == 0 && idx[1] == 1, "tally_top honours max");

	/* type 7 on {1,2,3,4,5,7}: p05 = 1 + 0.25 * 1 = 1.25,
	 * p50 = 3.5, p95 = 5 + 0.75 * 2 = 6.5 */
	struct stats_summary s;
	tally_summary(&t, &s);
	tap_ok(s.n == 6, "summary over the accepted loads only");
	tap_near(s.p05, 1.25, 1e-12, "summary p05 (type 7) = 1.25");
	tap_near(s.p50, 3.5, 1e-12, "summary p50 = 3.5");
	tap_near(s.p95, 6.5, 1e-12, "summary p95 = 6.5");
	tap_near(s.mean, 22.0 / 6, 1e-12, "summary mean = 22/6");
	tap_ok(!s.has_ci, "no 99 %% interval with 6 values");

	record_free(&it);
	tally_free(&t);
}

/* Ties in count: first appearance first, whatever the insertion pattern. */
static void test_top_ties(void)
{
	struct tally t;
	struct record it;
	tally_init(&t, &fake);
	record_init(&it, &fake);
	const char *seq[] = {"o....", ".o...", "..o..", ".o...", "o....",
			     "...o.", "..o..", "...o.", "...o."};
	for (int i = 0; i < 9; i++) {
		item(&it, i, SAMPLE_ACCEPTED, 1.0 + i, seq[i], 0);
		tally_add(&t, &it);
	}
	/* counts: o.... 2, .o... 2, ..o.. 2, ...o. 3 */
	int idx[4];
	int n = tally_top(&t, idx, 4);
	tap_ok(n == 4 && idx[0] == 3 && idx[1] == 0 && idx[2] == 1 &&
	       idx[3] == 2, "ties broken by first appearance (3, 0, 1, 2)");
	record_free(&it);
	tally_free(&t);
}

/* Many distinct mechanisms: every one found again after rehashing. */
static void test_many(void)
{
	struct tally t;
	struct record it;
	tally_init(&t, &fake);
	record_init(&it, &fake);
	static const char states[] = ".shHo";	/* 5^5 = 3125 strings */
	char j[M + 1] = {0};
	int nd = 3125;
	for (int round = 0; round < 3; round++) {
		for (int c = 0; c < nd; c++) {
			int v = c;
			for (int k = 0; k < M; k++) {
				j[k] = states[v % 5];
				v /= 5;
			}
			/* round 2 adds only every third string once more */
			if (round == 2 && c % 3)
				continue;
			item(&it, c, SAMPLE_ACCEPTED, c, j, 0);
			tally_add(&t, &it);
		}
	}
	tap_ok(t.nmech == nd, "3125 distinct joint strings, 3125 mechanisms "
	       "(got %d)", t.nmech);
	int ok = 1;
	for (int c = 0; c < t.nmech && ok; c++)
		ok = t.mech[c].count == (c % 3 ? 2 : 3) &&
		     t.mech[c].lam_lo == c && t.mech[c].lam_hi == c;
	tap_ok(ok, "each found again on later rounds (count 2 or 3)");
	int *idx = malloc(sizeof(int) * (size_t)nd);
	int n = tally_top(&t, idx, nd);
	ok = n == nd;
	for (int i = 1; i < n && ok; i++) {
		const struct tally_mech *a = &t.mech[idx[i - 1]];
		const struct tally_mech *b = &t.mech[idx[i]];
		ok = a->count > b->count ||
		     (a->count == b->count && idx[i - 1] < idx[i]);
	}
	tap_ok(ok && idx[0] == 0 && idx[1] == 3,
	       "tally_top sorted by count, then first appearance");
	free(idx);
	record_free(&it);
	tally_free(&t);
}

/* The no_equilibrium samples by the block each could not hold
 * (tally_unheld): most samples first, equal counts in the wall's order;
 * the unstable, the hanging and the nonpositive ones apart; a sample of
 * another status, or without a block (-1), names none. */
static void test_unheld(void)
{
	struct tally t;
	struct record it;
	tally_init(&t, &fake);
	record_init(&it, &fake);
	int b[B];
	long c[B];
	tap_ok(it.unheld == -1 &&
	       tally_unheld(&t, SAMPLE_NO_EQUILIBRIUM, b, c, B) == 0,
	       "a new record names no block; a new tally none");
	const int blocks[] = {2, 0, 2, 1, -1, 0, 2};
	for (int i = 0; i < 7; i++) {
		item(&it, i, SAMPLE_NO_EQUILIBRIUM, NAN, NULL, 0);
		it.unheld = blocks[i];
		tally_add(&t, &it);
	}
	item(&it, 7, SAMPLE_NO_MECHANISM, NAN, NULL, 0);
	it.unheld = 1;	/* not a no_equilibrium sample: not counted */
	tally_add(&t, &it);
	item(&it, 8, SAMPLE_UNSTABLE, NAN, NULL, 0);
	it.unheld = 1;	/* counted apart */
	tally_add(&t, &it);
	int n = tally_unheld(&t, SAMPLE_NO_EQUILIBRIUM, b, c, B);
	tap_ok(n == 3 && b[0] == 2 && c[0] == 3 && b[1] == 0 && c[1] == 2 &&
	       b[2] == 1 && c[2] == 1 && t.rejected[SAMPLE_NO_EQUILIBRIUM] == 7,
	       "unheld: block 2 in 3 samples, block 0 in 2, block 1 in 1 (the "
	       "other statuses' blocks not counted): %d (%d %ld, %d %ld)", n,
	       b[0], c[0], b[1], c[1]);
	n = tally_unheld(&t, SAMPLE_NO_EQUILIBRIUM, b, c, 1);
	tap_ok(n == 3 && b[0] == 2, "unheld with room for one: the most "
	       "named, and the count of all");
	n = tally_unheld(&t, SAMPLE_UNSTABLE, b, c, B);
	tap_ok(n == 1 && b[0] == 1 && c[0] == 1 &&
	       tally_unheld(&t, SAMPLE_NO_MECHANISM, b, c, B) == 0,
	       "the unstable sample's block counted apart; another status "
	       "has none");
	item(&it, 9, SAMPLE_NO_EQUILIBRIUM, NAN, NULL, 0);
	it.unheld = 1;
	tally_add(&t, &it);
	n = tally_unheld(&t, SAMPLE_NO_EQUILIBRIUM, b, c, B);
	tap_ok(n == 3 && b[1] == 0 && b[2] == 1 && c[1] == 2 && c[2] == 2,
	       "equal counts in the wall's order: block 0 before block 1");
	/* a hanging sample's block (the lowest that hangs) in a row of
	 * its own, the others' rows unchanged */
	item(&it, 10, SAMPLE_HANGING, NAN, NULL, 0);
	it.unheld = 0;
	tally_add(&t, &it);
	n = tally_unheld(&t, SAMPLE_HANGING, b, c, B);
	int ne = tally_unheld(&t, SAMPLE_NO_EQUILIBRIUM, b + 1, c + 1, B - 1);
	int nu = tally_unheld(&t, SAMPLE_UNSTABLE, b + 2, c + 2, B - 2);
	tap_ok(n == 1 && b[0] == 0 && c[0] == 1 && ne == 3 && nu == 1 &&
	       b[1] == 2 && c[1] == 3 && b[2] == 1 && c[2] == 1 &&
	       t.rejected[SAMPLE_HANGING] == 1,
	       "the hanging sample's block counted apart (%d: %d %ld), the "
	       "other rows unchanged", n, b[0], c[0]);
	/* and a nonpositive sample's (the block that falls under any load
	 * along the live load) likewise */
	item(&it, 11, SAMPLE_NONPOSITIVE, NAN, NULL, 0);
	it.unheld = 2;
	tally_add(&t, &it);
	n = tally_unheld(&t, SAMPLE_NONPOSITIVE, b, c, B);
	int nh = tally_unheld(&t, SAMPLE_HANGING, b + 1, c + 1, B - 1);
	ne = tally_unheld(&t, SAMPLE_NO_EQUILIBRIUM, b + 2, c + 2, B - 2);
	tap_ok(n == 1 && b[0] == 2 && c[0] == 1 && nh == 1 && b[1] == 0 &&
	       ne == 3 && b[2] == 2 && c[2] == 3 &&
	       t.rejected[SAMPLE_NONPOSITIVE] == 1,
	       "the nonpositive sample's block counted apart (%d: %d %ld), "
	       "the other rows unchanged", n, b[0], c[0]);
	int named = 0;
	for (int u = 0; u < TALLY_NAMED; u++)
		named += tally_unheld_text(tally_named[u]) != NULL;
	tap_ok(named == TALLY_NAMED &&
	       !tally_unheld_text(SAMPLE_NO_MECHANISM),
	       "each status of tally_named has its text, another none");
	record_free(&it);
	tally_free(&t);
}

int main(void)
{
	fake.nifaces = M;
	fake.nblocks = B;
	test_counts();
	test_top_ties();
	test_many();
	test_unheld();
	return tap_done();
}
