/*
 * record.h - one sample's record: what a run keeps of a sample and
 * carries from the worker that computed it to the consumer (the pool's
 * reorder window, an MPI rank's messages to rank 0, the tally, the CSV
 * writer).  Declared here only; every copy goes through record_copy or
 * the wire functions below.
 *
 * struct sample_result (sample.h) is the solver's full answer (forces,
 * joint rates, ...) in the worker's workspace; record_set keeps of it
 * what the run needs.  The arrays are owned by the record: record_init
 * sizes them for a wall, and a record is only ever copied into another
 * record of the same wall.
 */
#ifndef SLIPWALL_RECORD_H
#define SLIPWALL_RECORD_H

#include <stddef.h>

#include "slipwall/sample.h"
#include "slipwall/wall.h"

struct record {
	/* the fixed part, up to draw: plain data without padding, sent as
	 * bytes between the ranks of an MPI job (the same binary on every
	 * rank: RECORD_FIXED bytes) */
	long index;		/* the sample's index in the run */
	enum sample_status status;
	int iterations, lps;	/* SLP iterations, LPs solved */
	/* a status of tally_named (`no_equilibrium`, `nonpositive`,
	 * `unstable`, `hanging`): the block the sample
	 * names (sample_result.unheld), else -1; also no padding before
	 * the doubles */
	int unheld;
	double lambda_lpmax, lambda_max, lambda_min;
	double vw_residual;
	double seconds;		/* compute time of this sample */
	/* the arrays */
	struct sample_draw draw;	/* contact points and friction */
	char *joint;		/* nifaces + 1 (mechanism, accepted only) */
	double *vel;		/* 3 * nblocks (accepted only) */
};

void record_init(struct record *r, const struct wall *w);
void record_free(struct record *r);
/* dst = src, arrays included; both made by record_init for w. */
void record_copy(struct record *dst, const struct record *src,
		 const struct wall *w);
/* The record of sample `index` of draw r->draw (already there) from
 * the solver's result res, computed in `seconds`: the joint states and
 * velocities of an accepted sample, zeros otherwise. */
void record_set(struct record *r, long index, const struct sample_result *res,
		double seconds, const struct wall *w);

#define RECORD_FIXED offsetof(struct record, draw)

/* The wire form: record_wire_size(w) bytes, the fixed part then the
 * draw's xi and mu, vel and joint. */
size_t record_wire_size(const struct wall *w);
void record_pack(const struct record *r, const struct wall *w,
		 unsigned char *buf);
void record_unpack(struct record *r, const struct wall *w,
		   const unsigned char *buf);

#endif
