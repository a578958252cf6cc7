/*
 * fuzz_wallfile.c - libFuzzer harness for the wall loader and the model
 * builder (docs/reliability.md).
 *
 * Each input is a wall file.  wallfile_parse() must either refuse it with
 * SW_EINPUT and a "NAME:LINE:COLUMN: message" (or "NAME: message") in
 * the error buffer, or return a finished wall.  On a wall, the harness
 * touches everything derived from it: a deep copy, the equilibrium
 * operator at random contact points (every column and its transpose,
 * all finite), and, for small walls (FUZZ_MAX_BLOCKS), a sampling
 * workspace - which solves one whole sample at the classical contact
 * (xi = 0, 1), six GLPK problems - and the standard (associative)
 * solution at the wall's own depth.  GLPK must never print and never
 * abort; any crash, sanitizer report, leak or malformed message is a
 * finding.  The limits keep it at a few thousand executions a second:
 * a sample of a small wall costs ~20 ms under the sanitizers, parsing a
 * few KiB well under 1 ms.
 *
 * Built by scripts/fuzz.sh (clang, -fsanitize=fuzzer,address,undefined)
 * with meson -Dfuzz=true; the seed corpus is the wall files of walls/
 * and tests/bad/.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/draw.h"
#include "slipwall/sample.h"
#include "statics.h"
#include "slipwall/wallfile.h"

/* Walls with more blocks are only loaded and assembled, not solved:
 * keeps the harness at hundreds of executions per second. */
#ifndef FUZZ_MAX_BLOCKS
#define FUZZ_MAX_BLOCKS 8
#endif

static void check_message(const char *err)
{
	/* "fuzz.yaml:L:C: text" or "fuzz.yaml: text", never empty */
	if (strncmp(err, "fuzz.yaml:", 10) != 0 || strlen(err) < 12) {
		fprintf(stderr, "fuzz: malformed error message '%s'\n", err);
		abort();
	}
}

static void touch_statics(const struct wall *w)
{
	struct statics s;
	struct sample_draw d;	/* sample 0's: its points and friction */
	draw_init(&d, w);
	draw_make(&d, w, 1, 0, -1);
	double *v = calloc((size_t)3 * (size_t)w->nfree + 1, sizeof(double));
	statics_init(&s, w);
	statics_set_draw(&s, &d);
	for (int k = 0; k < w->nifaces; k++)	/* a drawn friction is finite */
		if (!(s.mu[k] >= 0) || !(s.mu[k] <= WALL_FRICTION_MAX))
			abort();
	/* a finished wall gives a finite operator: GLPK refuses (aborts on)
	 * non-finite coefficients outside a solve */
	if (!(s.F > 0) || !isfinite(s.F) || !(s.L > 0) || !isfinite(s.L) ||
	    !(s.S > 0) || !isfinite(s.S))
		abort();
	for (int i = 0; i < s.nrows; i++) {
		if (!isfinite(s.fL[i]) || !isfinite(s.fD[i]))
			abort();
		v[i] = 1.0 / (i + 1);
	}
	for (int j = 0; j < s.ncols; j++) {
		int rows[6];
		double vals[6];
		int n = statics_column(&s, j, rows, vals);
		if (n < 0 || n > 6)
			abort();
		for (int i = 0; i < n; i++)
			if (rows[i] < 0 || rows[i] >= s.nrows ||
			    !isfinite(vals[i]))
				abort();
		(void)statics_rate(&s, j, v);
	}
	statics_free(&s);
	free(v);
	draw_free(&d);
}

static void touch_sample(const struct wall *w)
{
	struct sample_result r;
	struct sample_draw d;
	draw_init(&d, w);
	/* sample_ws_new solves one sample at the classical contact */
	struct sample_ws *ws = sample_ws_new(w);
	sample_result_init(&r, w);
	draw_make(&d, w, 7, 3, -1);
	enum sample_status st = sample_standard(ws, &d, &r);
	if ((unsigned)st >= SAMPLE_STATUS_COUNT)
		abort();
	if (st == SAMPLE_ACCEPTED && !(r.lambda_min > 0))
		abort();
	sample_result_free(&r);
	sample_ws_free(ws);
	draw_free(&d);
}

int LLVMFuzzerTestOneInput(const unsigned char *data, size_t size)
{
	char err[SW_ERRLEN];
	struct wall *w;

	err[0] = '\0';
	enum sw_status st = wallfile_parse((const char *)data, size,
					   "fuzz.yaml", &w, err);
	if (st != SW_OK) {
		if (st != SW_EINPUT || w)
			abort();
		check_message(err);
		return 0;
	}
	if (!w || !w->finished || w->nfree < 1)
		abort();
	struct wall *c = wall_copy(w);
	wall_free(c);
	touch_statics(w);
	if (w->nblocks <= FUZZ_MAX_BLOCKS)
		touch_sample(w);
	wall_free(w);
	return 0;
}
