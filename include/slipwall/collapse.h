/*
 * collapse.h - the probability of collapse at a load, for the batch
 * commands' summaries (`run --at LOAD`, a wall's analysis.design_load;
 * docs/run.md, "The probability of collapse at a load").
 *
 * P(collapse load <= LOAD) is estimated by the share of the accepted
 * samples whose collapse load, m * lambda_min in the loads' own unit
 * (docs/run.md, "Loads and units"), is at most LOAD (rejected samples have no
 * load: the probability is conditional on acceptance), with the exact
 * binomial (Clopper-Pearson) 99 % interval, stats_binomial_ci.
 */
#ifndef SLIPWALL_COLLAPSE_H
#define SLIPWALL_COLLAPSE_H

#include <stddef.h>
#include <stdio.h>
#include "slipwall/json.h"

struct collapse {
	double load;
	const char *source;	/* "at" (--at) or "design_load" */
	size_t k, n;		/* collapsed of accepted */
	double p, lo, hi;	/* k/n and its 99 % interval (NaN: n = 0) */
};

/* From the accepted loads, sorted. */
void collapse_at(const double *sorted, size_t n, double load,
		 const char *source, struct collapse *c);
/* "collapse     P(collapse load <= L) = p (k of n accepted), 99 % interval
 * [lo, hi] (exact binomial; --at)" with the given label width; name is
 * the loads' quantity (wall_quantity's: "collapse load", "seismic
 * coefficient" or "load factor"), in which L is given. */
void collapse_print(FILE *f, const char *label, const char *name,
		    const struct collapse *c);
/* {"load", "source", "collapsed", "accepted", "probability", "ci99"} */
void collapse_json(struct json *j, const struct collapse *c);

#endif
