/*
 * test_start.c - "One answer per sample" (docs/method.md): a sample is a
 * function of its contact positions alone, whatever the LP solver's path.
 * Every sample is solved by nine workspaces whose LPs start from
 * different bases (SLIPWALL_LP_START's values, which drive the standing
 * check and the SLP's LP1 and LP2, LP-max and LP-min keeping `auto`'s
 * path and the mechanism starting from LP1's complementary basis: the
 * default `auto`, the
 * slack basis by the primal and by the dual simplex, GLPK's crash basis,
 * the canonical bases, the previous sample's bases, the support basis;
 * `auto` as it starts walls of more than 1,000 interfaces (whose set-up
 * stops after the SLP's first LP1: setup_roles); and `auto`
 * from the set-up of another wall of the same shape, the workbench's
 * start after an edit: the wall with its friction scaled by 0.7,
 * docs/design.md "The shared set-up"), and must
 * give the same status, the same lambda_min (1e-9 relative) and the
 * same mechanism (the joint classification of every interface).  The
 * last two also move LP-max: the large walls' path solves it by the
 * primal simplex, and the edited wall's canonical basis is another.
 * Without the tie-breaks, changing
 * only LP-max's start moved 47-88 % of the demo wall's samples.
 *
 * Walls: the demo, Ferris & Tin-Loi 1 and 2 (depth 0.25, the walls'
 * own seeds), and 200 random small walls, one sample each.  Then
 * walls/body-1000.yaml's set-up alone: its LP-min cut at one pivot per
 * interface (large_setup_cut).
 */
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/mc.h"
#include "slipwall/sample.h"
#include "tap.h"
#include "walls.h"

/* the starts, the default first: ws[s] starts from start_of[s]; the
 * last two are `auto` as it starts a wall of more than 1,000 interfaces
 * (sample_ws_new_auto_large) and `auto` from an edited wall's set-up
 * (sample_ws_new_setup) */
#define NSTART (SAMPLE_START_COUNT + 2)
#define AUTO_LARGE (NSTART - 2)
#define EDITED (NSTART - 1)
static const enum sample_start start_of[NSTART - 2] = {
	SAMPLE_START_DEFAULT, SAMPLE_START_SLACK_PRIMAL, SAMPLE_START_SLACK_DUAL,
	SAMPLE_START_CRASH, SAMPLE_START_CANONICAL, SAMPLE_START_PREVIOUS,
	SAMPLE_START_SUPPORT,
};

static const char *start_name(int s)
{
	return s == AUTO_LARGE ? "auto (large walls)" :
	       s == EDITED ? "auto (an edited wall's set-up)" :
	       sample_start_name(start_of[s]);
}

struct tally {
	long samples, accepted, status, lambda, mechanism;
};

/* Sample `index` of w by every start; differences against the first
 * start (the default, canonical) are counted in t. */
static void one(struct sample_ws **ws, const struct wall *w,
		unsigned long seed, unsigned long index, struct tally *t,
		const char *what)
{
	const struct sample_opts *o = NULL;
	struct sample_opts opts;
	sample_opts_default(&opts);
	o = &opts;
	struct sample_draw dr;
	draw_init(&dr, w);
	draw_mean(&dr, w);
	draw_make(&dr, w, seed, index, -1);
	struct sample_result ref, r;
	sample_result_init(&ref, w);
	sample_result_init(&r, w);
	sample_run(ws[0], &dr, o, &ref);
	t->samples++;
	t->accepted += ref.status == SAMPLE_ACCEPTED;
	for (int s = 1; s < NSTART; s++) {
		sample_run(ws[s], &dr, o, &r);
		if (r.status != ref.status) {
			t->status++;
			tap_diag("%s sample %lu: %s by %s, %s by %s", what, index,
				 sample_status_name(ref.status),
				 sample_start_name(SAMPLE_START_DEFAULT),
				 sample_status_name(r.status),
				 start_name(s));
			continue;
		}
		if (ref.status != SAMPLE_ACCEPTED)
			continue;
		if (!(fabs(r.lambda_min - ref.lambda_min) <=
		      1e-9 * fmax(1, fabs(ref.lambda_min)))) {
			t->lambda++;
			tap_diag("%s sample %lu: lambda_min %.12g by %s, %.12g by %s",
				 what, index, ref.lambda_min,
				 sample_start_name(SAMPLE_START_DEFAULT),
				 r.lambda_min, start_name(s));
		}
		if (strcmp(r.joint, ref.joint)) {
			t->mechanism++;
			tap_diag("%s sample %lu: mechanism %s by %s, %s by %s", what,
				 index, ref.joint,
				 sample_start_name(SAMPLE_START_DEFAULT), r.joint,
				 start_name(s));
		}
	}
	sample_result_free(&ref);
	sample_result_free(&r);
	draw_free(&dr);
}

/* workspaces opened from an edited wall's set-up, and those that used
 * it (solved no canonical sample) */
static long edited_opened, edited_used;

/* The workspaces of w, the default start first. */
static void open_all(struct sample_ws **ws, const struct wall *w)
{
	for (int s = 0; s < AUTO_LARGE; s++)
		ws[s] = sample_ws_new_start(w, start_of[s]);
	ws[AUTO_LARGE] = sample_ws_new_auto_large(w);
	/* the workbench after a friction edit: the previous wall's
	 * canonical bases, a start of the right shape that is not this
	 * wall's */
	struct wall *e = wall_copy(w);
	e->mu_bed *= 0.7;
	e->mu_head *= 0.7;
	struct sample_ws *we = sample_ws_new(e);
	struct sample_setup *su = sample_ws_setup(we);
	sample_ws_free(we);
	ws[EDITED] = sample_ws_new_setup(w, NULL, su);
	struct sample_lp_counters c;
	sample_ws_counters(ws[EDITED], &c);
	edited_opened++;
	edited_used += sample_setup_fits(su, w, NULL) && c.setups == 0;
	sample_setup_free(su);
	wall_free(e);
}

static void close_all(struct sample_ws **ws)
{
	for (int s = 0; s < NSTART; s++)
		sample_ws_free(ws[s]);
}

static void report(const char *what, const struct tally *t)
{
	tap_ok(t->status == 0, "%s: %ld samples (%ld accepted), same status "
	       "from every start (%ld differ)", what, t->samples, t->accepted,
	       t->status);
	tap_ok(t->lambda == 0, "%s: same lambda_min (1e-9) from every start "
	       "(%ld differ)", what, t->lambda);
	tap_ok(t->mechanism == 0, "%s: same mechanism from every start "
	       "(%ld differ)", what, t->mechanism);
}

/* The role named name (sample_role_name), or -1. */
static int role_index(const char *name)
{
	for (int p = 0; p < SAMPLE_ROLE_COUNT; p++)
		if (!strcmp(sample_role_name(p), name))
			return p;
	return -1;
}

/* What each set-up solved, before any sample (sample.c,
 * canonical_bases): a small wall's the whole canonical sample, its
 * SLP's LP2 and its LP-min among them; a large wall's LP-max, the
 * standing check, the SLP's first LP1 and at most one LP-min at its
 * mechanism (setup_large), and every sample of
 * `auto (large walls)` must still give the default start's answer
 * (one()). */
static void setup_roles(struct sample_ws **ws, const char *path)
{
	struct sample_lp_stats dflt[SAMPLE_ROLE_COUNT], big[SAMPLE_ROLE_COUNT];
	sample_ws_stats(ws[0], dflt);
	sample_ws_stats(ws[AUTO_LARGE], big);
	int lp1 = role_index("LP1"), lp2 = role_index("LP2"),
	    amin = role_index("LP-min"), kin = role_index("kinematic"),
	    amax = role_index("LP-max");
	if (lp1 < 0 || lp2 < 0 || amin < 0 || kin < 0 || amax < 0) {
		tap_ok(0, "%s: a role's name is not sample_role_name's", path);
		return;
	}
	tap_ok(dflt[lp2].lps > 0 && dflt[amin].lps > 0 && dflt[kin].lps > 0,
	       "%s: the set-up solves the canonical sample (%ld LP2, %ld "
	       "LP-min, %ld kinematic)", path, dflt[lp2].lps, dflt[amin].lps,
	       dflt[kin].lps);
	tap_ok(big[amax].lps == 1 && big[lp1].lps == 1 && big[lp2].lps == 0 &&
	       big[amin].lps <= 1 && big[kin].lps <= 1,
	       "%s: a large wall's set-up: its first LP1, no SLP path, at "
	       "most one LP-min (%ld LP-max, %ld LP1, %ld LP2, %ld LP-min, "
	       "%ld kinematic)", path,
	       big[amax].lps, big[lp1].lps, big[lp2].lps, big[amin].lps,
	       big[kin].lps);
}

/* The single-solution methods at the classical contact: standard (its
 * load factor; its mechanism, LP-max's dual, is one of several when
 * LP-max is primal degenerate) and gilbert (the SLP from the standard
 * field: lambda_max, lambda_min, mechanism). */
static void classical(struct sample_ws **ws, const struct wall *w,
		      const char *path)
{
	struct sample_opts o;
	sample_opts_default(&o);
	struct sample_draw dr;	/* the classical contact */
	draw_init(&dr, w);
	draw_mean(&dr, w);
	struct sample_result r;
	sample_result_init(&r, w);
	double std[NSTART], gmax[NSTART],
	       gmin[NSTART];
	char *mech[NSTART];
	int st_ok = 1, g_ok = 1, m_ok = 1;
	for (int s = 0; s < NSTART; s++) {
		sample_standard(ws[s], &dr, &r);
		std[s] = r.lambda_max;
		sample_run(ws[s], &dr, &o, &r);
		gmax[s] = r.lambda_max;
		gmin[s] = r.lambda_min;
		mech[s] = strdup(r.status == SAMPLE_ACCEPTED ? r.joint : "-");
		double tol = 1e-9 * fmax(1, fabs(std[0]));
		st_ok &= fabs(std[s] - std[0]) <= tol;
		/* gilbert's load is the SLP's, converged to its tolerance
		 * (1e-7): the same to 1e-6; its onset load is an LP's */
		g_ok &= fabs(gmax[s] - gmax[0]) <= 1e-6 * fmax(1, fabs(gmax[0])) &&
			fabs(gmin[s] - gmin[0]) <= 1e-9 * fmax(1, fabs(gmin[0]));
		m_ok &= !strcmp(mech[s], mech[0]);
		if (s)
			tap_diag("%s: %s: standard %.12g, gilbert %.12g / %.12g",
				 path, start_name(s), std[s],
				 gmax[s], gmin[s]);
	}
	tap_ok(st_ok, "%s: standard %.9g from every start", path, std[0]);
	tap_ok(g_ok, "%s: gilbert %.9g (1e-6; onset %.9g, 1e-9) from every start", path,
	       gmax[0], gmin[0]);
	tap_ok(m_ok, "%s: gilbert's mechanism from every start", path);
	for (int s = 0; s < NSTART; s++)
		free(mech[s]);
	sample_result_free(&r);
	draw_free(&dr);
}

static void wall_file(const char *path, long n)
{
	struct wall *w = tw_load_file(path);
	struct sample_ws *ws[NSTART];
	struct tally t = {0};
	open_all(ws, w);
	setup_roles(ws, path);
	classical(ws, w, path);
	for (long i = 0; i < n; i++)
		one(ws, w, w->seed, (unsigned long)i, &t, path);
	close_all(ws);
	report(path, &t);
	tap_ok(t.accepted >= n * 9 / 10, "%s: most samples accepted "
	       "(%ld of %ld)", path, t.accepted, n);
	wall_free(w);
}

/* A large wall's set-up tries LP-min, for a start basis only, with at
 * most one pivot per interface (sample.c, setup_large): on
 * walls/body-1000.yaml that solve took 14,282 pivots to prove the LP
 * infeasible (docs/performance.md, "The set-up's LP-min cut").  About
 * 8 s: the set-up alone, no sample. */
static void large_setup_cut(void)
{
	const char *path = "walls/body-1000.yaml";
	struct wall *w = tw_load_file(path);
	struct sample_ws *ws = sample_ws_new(w);
	struct sample_lp_stats st[SAMPLE_ROLE_COUNT];
	sample_ws_stats(ws, st);
	int amin = role_index("LP-min"), lp1 = role_index("LP1");
	tap_ok(amin >= 0 && lp1 >= 0 && st[lp1].lps == 1 &&
	       st[amin].lps == 1 && st[amin].iterations > 0 &&
	       st[amin].iterations <= w->nifaces,
	       "%s: the set-up's LP-min takes at most one pivot per interface "
	       "(%ld pivots, %d interfaces)", path,
	       amin >= 0 ? st[amin].iterations : -1L, w->nifaces);
	sample_ws_free(ws);
	wall_free(w);
}

/* 200 random small walls (as test_sample's properties), one sample
 * each. */
static void random_walls(void)
{
	gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
	gsl_rng_set(g, 2026);
	struct tally t = {0};
	for (int c = 0; c < 200; c++) {
		struct wall *w = tw_random(g);
		struct sample_ws *ws[NSTART];
		open_all(ws, w);
		one(ws, w, 7, (unsigned long)c, &t, "random wall");
		close_all(ws);
		wall_free(w);
	}
	gsl_rng_free(g);
	report("200 random walls", &t);
	tap_ok(t.accepted >= 150, "200 random walls: most accepted (%ld)",
	       t.accepted);
}

int main(void)
{
	wall_file("walls/demo.yaml", 100);
	wall_file("walls/ferris-tinloi-1.yaml", 100);
	wall_file("walls/ferris-tinloi-2.yaml", 60);
	random_walls();
	large_setup_cut();
	tap_ok(edited_opened > 0 && edited_used == edited_opened,
	       "every workspace opened from an edited wall's set-up started "
	       "from it (%ld of %ld)", edited_used, edited_opened);
	return tap_done();
}
