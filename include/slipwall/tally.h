/*
 * tally.h - what a run has found so far: counts by status, the accepted
 * loads (sorted, for running percentiles), and the distinct mechanisms
 * with their frequencies.
 *
 * A mechanism is identified by its joint-state string (sample_result.
 * joint: one char per interface); the tally keeps, for each distinct
 * one, its count, the smallest and largest load, and the velocities of
 * its first sample (to draw it).  Used by `run` (summary), the workbench
 * (live statistics, the mechanism browser) and `report` (Fig. 6).  One
 * thread at a time.
 *
 * The loads it keeps are those people read (wall_quantity): a sample's
 * lambda_min times the wall's scale, so the force in N of a point load
 * of any magnitude, or a seismic coefficient; every summary, percentile
 * and mechanism range taken from a tally is in that quantity.  The
 * samples file keeps lambda itself (docs/run.md, "Loads and units").
 */
#ifndef SLIPWALL_TALLY_H
#define SLIPWALL_TALLY_H

#include "slipwall/record.h"
#include "slipwall/sample.h"
#include "slipwall/stats.h"

struct tally_mech {
	char *joint;		/* owned, nifaces + 1 */
	double *vel;		/* owned, 3 * nblocks: of its first sample */
	long count;
	double lam_lo, lam_hi;
};

struct tally {
	int nifaces, nblocks;
	long samples;		/* popped so far */
	long accepted;
	long rejected[SAMPLE_STATUS_COUNT];	/* by status (ACCEPTED unused) */
	struct wall_quantity q;	/* what the loads are (wall_quantity) */
	struct stats_sorted lam;	/* accepted q.scale * lambda_min, sorted */
	/* the level of p05's interval in the summaries: 0.99, or under
	 * --until-ci the share of 1 - 0.99 its looks have left (run.c) */
	double ci_conf;
	double lam_sum;
	long iterations, lps;	/* sums over all samples */
	double compute_seconds;	/* sum of per-sample compute times */
	/* TALLY_NAMED rows of nblocks, or NULL before the first: the
	 * samples of each status of tally_named, by the block they name
	 * (record.unheld) */
	long *unheld;
	struct tally_mech *mech;/* distinct mechanisms, by first appearance */
	int nmech, capmech;
	int *hash;		/* private: open-addressing index into mech */
	int hashcap;
};

void tally_init(struct tally *t, const struct wall *w);
void tally_free(struct tally *t);
void tally_add(struct tally *t, const struct record *it);
/* The index in t->mech of mechanism joint (nifaces chars), or -1 when
 * the tally has not seen it: one hash of the string. */
int tally_find(const struct tally *t, const char *joint);
/* The rejections whose samples name a block (record.unheld), in the
 * order the summaries show them: no_equilibrium, nonpositive,
 * unstable, hanging. */
#define TALLY_NAMED 4
extern const enum sample_status tally_named[TALLY_NAMED];
/* The blocks that the samples of status st (one of tally_named) named
 * (record.unheld), most samples first (equal counts: in the wall's
 * order): up to max block indices into blocks[] and their counts into
 * counts[]; returns how many blocks were named at all (0 for another
 * status). */
int tally_unheld(const struct tally *t, enum sample_status st, int *blocks,
		 long *counts, int max);
/* What the blocks of tally_unheld are, for people: "cannot be held"
 * (no_equilibrium: at any load), "falls under any load" (nonpositive:
 * they stand only under a load against its direction), "stands only
 * under load" (unstable: they need the live load), "lowest hanging
 * block" (hanging: where the clamp the SLP lost begins), NULL for
 * another status. */
const char *tally_unheld_text(enum sample_status st);
/* The mechanisms sorted by count, most frequent first: fills idx with up
 * to max indices into t->mech; returns how many. */
int tally_top(const struct tally *t, int *idx, int max);
/* A count and the index it ranks (qsort has no context argument, so the
 * count travels with its index); tally_ranked sorts r (n entries) by
 * count, most first, equal counts by index (first appearance first: an
 * order that does not depend on the thread count), and copies up to max
 * of the indices into idx; returns how many.  tally_top's order, and
 * the families' (family.c). */
struct tally_rank {
	long count;
	int k;
};
int tally_ranked(struct tally_rank *r, int n, int *idx, int max);
/* Summary statistics of the accepted loads (stats_summarise_conf at
 * ci_conf). */
void tally_summary(const struct tally *t, struct stats_summary *s);

/* The keys every run summary shares (docs/run.md), into an open JSON
 * object: "samples", "accepted", "rejected" (an object by reason name),
 * "load" {quantity, unit, scale} (what the loads are: wall_quantity),
 * "lambda" {min, p05, p50, p95, max, mean, std} (of the loads, in
 * load.unit: scale times the LPs' lambda) and "p05_ci99" [lo, hi] (null
 * below 90 accepted samples). */
struct json;
void tally_json(const struct tally *t, struct json *j);
/* The last two of those, of any summary (compare's model and tests). */
void tally_summary_json(struct json *j, const struct stats_summary *s);
/* "load": {"quantity", "unit", "scale"} of q, into an open object. */
void tally_quantity_json(struct json *j, const struct wall_quantity *q);

#endif
