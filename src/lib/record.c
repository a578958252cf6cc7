/*
 * record.c - one sample's record; see record.h.  The pool (mc.c) makes
 * records with record_set and moves them with record_copy; the MPI run
 * (src/cli/cluster.c) packs them for the wire.
 */
#include <stdlib.h>
#include <string.h>

#include "slipwall/record.h"

/* the fixed part has no padding: every byte sent is a field's */
_Static_assert(RECORD_FIXED == sizeof(long) + 4 * sizeof(int) +
	       5 * sizeof(double), "struct record: padding in the fixed part");

/* the draw's numbers: xi, then mu */
static size_t nxi(const struct wall *w)
{
	return 2 * (size_t)w->nifaces;
}

static size_t nmu(const struct wall *w)
{
	return (size_t)w->nifaces;
}

static size_t nvel(const struct wall *w)
{
	return 3 * (size_t)w->nblocks;
}

void record_init(struct record *r, const struct wall *w)
{
	memset(r, 0, sizeof *r);
	r->unheld = -1;
	draw_init(&r->draw, w);
	r->joint = sw_xcalloc((size_t)w->nifaces + 1, 1);
	r->vel = sw_xcalloc(nvel(w) + 1, sizeof(double));
}

void record_free(struct record *r)
{
	draw_free(&r->draw);
	free(r->joint);
	free(r->vel);
	memset(r, 0, sizeof *r);
}

void record_copy(struct record *dst, const struct record *src,
		 const struct wall *w)
{
	memcpy(dst, src, RECORD_FIXED);
	draw_copy(&dst->draw, &src->draw);
	memcpy(dst->vel, src->vel, sizeof(double) * nvel(w));
	memcpy(dst->joint, src->joint, (size_t)w->nifaces + 1);
}

void record_set(struct record *r, long index, const struct sample_result *res,
		double seconds, const struct wall *w)
{
	r->index = index;
	r->status = res->status;
	r->iterations = res->iterations;
	r->lps = res->lps;
	r->unheld = res->unheld;	/* -1 but after tally_named's statuses */
	r->lambda_lpmax = res->lambda_lpmax;
	r->lambda_max = res->lambda_max;
	r->lambda_min = res->lambda_min;
	r->vw_residual = res->vw_residual;
	r->seconds = seconds;
	if (res->status == SAMPLE_ACCEPTED) {
		memcpy(r->joint, res->joint, (size_t)w->nifaces + 1);
		memcpy(r->vel, res->vel, sizeof(double) * nvel(w));
	} else {
		memset(r->joint, 0, (size_t)w->nifaces + 1);
		memset(r->vel, 0, sizeof(double) * nvel(w));
	}
}

size_t record_wire_size(const struct wall *w)
{
	return RECORD_FIXED + sizeof(double) * (nxi(w) + nmu(w) + nvel(w)) +
	       (size_t)w->nifaces + 1;
}

void record_pack(const struct record *r, const struct wall *w,
		 unsigned char *b)
{
	size_t sx = sizeof(double) * nxi(w), sv = sizeof(double) * nvel(w);
	memcpy(b, r, RECORD_FIXED);
	b += RECORD_FIXED;
	memcpy(b, r->draw.xi, sx);
	memcpy(b + sx, r->draw.mu, sizeof(double) * nmu(w));
	b += sizeof(double) * nmu(w);
	memcpy(b + sx, r->vel, sv);
	memcpy(b + sx + sv, r->joint, (size_t)w->nifaces + 1);
}

void record_unpack(struct record *r, const struct wall *w,
		   const unsigned char *b)
{
	size_t sx = sizeof(double) * nxi(w), sv = sizeof(double) * nvel(w);
	memcpy(r, b, RECORD_FIXED);
	b += RECORD_FIXED;
	memcpy(r->draw.xi, b, sx);
	memcpy(r->draw.mu, b + sx, sizeof(double) * nmu(w));
	b += sizeof(double) * nmu(w);
	memcpy(r->vel, b + sx, sv);
	memcpy(r->joint, b + sx + sv, (size_t)w->nifaces + 1);
	r->joint[w->nifaces] = 0;
}
