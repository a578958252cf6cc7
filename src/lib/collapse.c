/* collapse.c - the probability of collapse at a load; see collapse.h. */
#include <math.h>

#include "slipwall/collapse.h"
#include "slipwall/stats.h"

void collapse_at(const double *sorted, size_t n, double load,
		 const char *source, struct collapse *c)
{
	c->load = load;
	c->source = source;
	c->n = n;
	c->k = n ? stats_count_le(sorted, n, load) : 0;
	c->p = n ? (double)c->k / (double)n : NAN;
	if (n)
		stats_binomial_ci(c->k, n, 0.99, &c->lo, &c->hi);
	else
		c->lo = c->hi = NAN;
}

void collapse_print(FILE *f, const char *label, const char *name,
		    const struct collapse *c)
{
	const char *why = c->source[0] == 'a' ? "--at" : "the wall's design load";
	if (c->n == 0) {
		fprintf(f, "%sP(%s <= %.6g): no accepted sample (%s)\n",
			label, name, c->load, why);
		return;
	}
	fprintf(f, "%sP(%s <= %.6g) = %.4g (%zu of %zu accepted), "
		"99 %% interval [%.4g, %.4g] (exact binomial; %s)\n", label,
		name, c->load, c->p, c->k, c->n, c->lo, c->hi, why);
}

void collapse_json(struct json *j, const struct collapse *c)
{
	json_object_begin(j);
	json_key(j, "load");
	json_double(j, c->load);
	json_key(j, "source");
	json_string(j, c->source);
	json_key(j, "collapsed");
	json_int(j, (long long)c->k);
	json_key(j, "accepted");
	json_int(j, (long long)c->n);
	json_key(j, "probability");
	json_double(j, c->p);
	json_key(j, "ci99");
	json_array_begin(j);
	json_double(j, c->lo);
	json_double(j, c->hi);
	json_array_end(j);
	json_object_end(j);
}
