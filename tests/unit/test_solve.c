/*
 * test_solve.c - the single-solution methods: closed forms for a block
 * and a two-block stack (every method must agree where the collapse
 * involves one joint; a block on a slope, sliding or tipping, down it
 * and up it; a trapezoid that tips about its area's centroid), the
 * published Ferris & Tin-Loi values, and on random small walls the
 * global method's load (an onset of collapse checked by exact LPs) and
 * bound (below every onset load found otherwise).  And the stop flag: a
 * solve stopped returns SW_EINTR.
 */
#include <gsl/gsl_rng.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "lp.h"
#include "sample_lp.h"
#include "slipwall/mc.h"
#include "slipwall/solve.h"
#include "tap.h"
#include "walls.h"

static double run_limit(const struct wall *w, enum solve_method m,
			double time_limit, struct solve_result *r)
{
	struct solve_opts o;
	char err[SW_ERRLEN];
	solve_opts_default(&o, m);
	o.time_limit = time_limit;
	if (solve_run(w, &o, r, err) != SW_OK) {
		tap_diag("solve %s: %s", solve_method_name(m), err);
		return NAN;
	}
	return r->lambda;
}

/* Generous: "optimality proven" must not depend on the machine's speed
 * (a sanitizer build is several times slower); the walls that use it
 * take well under a second. */
static double run(const struct wall *w, enum solve_method m,
		  struct solve_result *r)
{
	return run_limit(w, m, 300, r);
}

/* Every method on w: its load want to 1e-9, and the states of joints
 * k[0..n-1] (n at most 7; state[i] each) in the mechanism of the
 * methods that give one (the standard method's associative mechanism is
 * not the onset's).  what names the case. */
static void every_method(const struct wall *w, double want, int n,
			 const int *k, const char *state, const char *what)
{
	for (int m = 0; m < 3; m++) {
		struct solve_result r;
		double lam = run(w, (enum solve_method)m, &r);
		tap_near(lam, want, 1e-9, "%s, %s: %.10g (want %.10g)", what,
			 solve_method_name((enum solve_method)m), lam, want);
		if (m != SOLVE_STANDARD && r.has_mechanism) {
			char got[8] = "";
			int ok = 1;
			for (int i = 0; i < n; i++) {
				got[i] = r.mech.joint[k[i]];
				ok = ok && got[i] == state[i];
			}
			tap_ok(ok, "... and its joints '%s' (want '%.*s')", got,
			       n, state);
		}
		solve_result_free(&r);
	}
}

/* ... on a wall of one joint (joint 0) */
static void one_joint(const struct wall *w, double want, char joint,
		      const char *what)
{
	every_method(w, want, 1, (const int[]){0}, &joint, what);
}

/* Two blocks, bottom b1 x h1 and top b2 x h2 (flush left), under a point
 * load pushing +x on the left face at height a.  Candidate collapses:
 *  load on the top block (a > h1):
 *    top slides:          P = mu W2
 *    top overturns:       P (a - h1) = W2 b2 / 2        about (b2, h1)
 *    stack slides:        P = mu (W1 + W2)
 *    stack overturns:     P a = W1 b1/2 + W2 (b1 - b2/2) about (b1, 0)
 *  load on the bottom block (a < h1): the stack cases only.
 * The collapse load is the least of them (each is a kinematically
 * admissible single-joint mechanism, and the statically admissible field
 * reaching it exists for these shapes). */
struct stack {
	double b1, h1, b2, h2, mu, a;
	char top_joint, ground_joint;	/* expected states (ground, top) */
};

static void stacks(void)
{
	static const struct stack cases[] = {
		/* top slides: wide, low top block, load on it */
		{0.6, 0.2, 0.6, 0.2, 0.4, 0.3, JOINT_SLIDES, JOINT_CLOSED},
		/* top overturns: tall slender top block */
		{0.6, 0.2, 0.15, 0.6, 0.7, 0.75, JOINT_HINGES, JOINT_CLOSED},
		/* stack slides: load on the bottom block */
		{0.6, 0.2, 0.6, 0.4, 0.3, 0.1, JOINT_CLOSED, JOINT_SLIDES},
		/* stack overturns: tall narrow stack, rough joints, load
		 * near the top of the bottom block */
		{0.2, 0.5, 0.2, 0.5, 0.9, 0.45, JOINT_CLOSED, JOINT_HINGES},
	};
	for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
		const struct stack *s = &cases[c];
		struct wall *w = wall_new();
		tw_rect(w, "bottom", 0, 0, s->b1, s->h1);
		tw_rect(w, "top", 0, s->h1, s->b2, s->h2);
		w->has_ground = 1;
		w->mu_bed = w->mu_head = s->mu;
		tw_point_load(w, 0, s->a, 1, 0);
		tw_finish(w);
		double W1 = w->blocks[0].weight, W2 = w->blocks[1].weight;
		double want = fmin(s->mu * (W1 + W2),
				   (W1 * s->b1 / 2 + W2 * (s->b1 - s->b2 / 2)) / s->a);
		if (s->a > s->h1)
			want = fmin(want, fmin(s->mu * W2,
					       W2 * s->b2 / (2 * (s->a - s->h1))));
		/* interface order: (bottom, top) then (bottom, ground) */
		int kg = -1, kt = -1;
		for (int k = 0; k < w->nifaces; k++) {
			if (w->blocks[w->ifaces[k].b].fixed ||
			    w->blocks[w->ifaces[k].a].fixed)
				kg = k;
			else
				kt = k;
		}
		char what[32];
		snprintf(what, sizeof what, "stack case %zu", c);
		every_method(w, want, 2, (const int[]){kg, kt},
			     (const char[]){s->ground_joint, s->top_joint},
			     what);
		wall_free(w);
	}
}

static void published(void)
{
	struct solve_result r;
	struct wall *w1 = tw_load_file("walls/ferris-tinloi-1.yaml");
	struct wall *w2 = tw_load_file("walls/ferris-tinloi-2.yaml");
	double s1 = run(w1, SOLVE_STANDARD, &r);
	solve_result_free(&r);
	double s2 = run(w2, SOLVE_STANDARD, &r);
	solve_result_free(&r);
	tap_ok(fabs(s1 - 0.6429) <= 1e-4, "wall 1 standard %.6f = 0.6429", s1);
	tap_ok(fabs(s2 - 0.5800) <= 1e-4, "wall 2 standard %.6f = 0.5800", s2);
	double g2 = run(w2, SOLVE_GILBERT, &r);
	tap_ok(r.converged, "wall 2 gilbert converged in %d iterations",
	       r.iterations);
	tap_ok(g2 >= 0.555 && g2 <= 0.580,
	       "wall 2 gilbert %.6f in [0.555, 0.580] (Gilbert et al. 2006)", g2);
	solve_result_free(&r);
	wall_free(w1);
	wall_free(w2);
}

/* The global method on 100 random small walls at depth 0.  Whatever the
 * time limit: its load is an onset of collapse checked by exact LPs (a
 * mechanism, virtual work to 1e-8), and its bound is below every onset
 * load found otherwise (gilbert's onset load, the depth-0 sample's
 * lambda_min); when proven, the load itself is below them.  The walls of
 * one course (3 blocks) are proven, with the generous limit.  A joint
 * that could slip both ways at once once let the program "prove" lambda
 * = 0 on 82 % of these walls; the load check turns such a solution into
 * a failure, so those walls would count as unsolved. */
static void global_walls(void)
{
	gsl_rng *g = gsl_rng_alloc(gsl_rng_mt19937);
	gsl_rng_set(g, 7);
	int found = 0, small = 0, small_proven = 0, bad = 0, bad_bound = 0;
	int bad_check = 0;
	struct sample_opts so;
	sample_opts_default(&so);
	for (int c = 0; c < 100; c++) {
		double bw = 0.15 + 0.3 * gsl_rng_uniform(g);
		double bh = bw * (0.25 + 0.75 * gsl_rng_uniform(g));
		int courses = 1 + (int)gsl_rng_uniform_int(g, 3);
		double mu = 0.3 + 0.6 * gsl_rng_uniform(g);
		struct wall *w = tw_layout(bw, bh, courses, 2 * bw, 1, 1, mu);
		if (gsl_rng_uniform(g) < 0.5)
			tw_body_load(w);
		else
			tw_point_load(w, 0, courses * bh * (0.1 + 0.8 * gsl_rng_uniform(g)), 1, 0);
		w->depth = 0;
		tw_finish(w);
		struct solve_result rg, rb;
		int one_course = w->nfree <= 3;
		double glob = run_limit(w, SOLVE_GLOBAL, one_course ? 300 : 0.5,
					&rg);
		run(w, SOLVE_GILBERT, &rb);
		double gil = rb.status == SAMPLE_ACCEPTED ? rb.lambda_onset : NAN;
		struct sample_ws *ws = sample_ws_new(w);
		struct sample_result r;
		sample_result_init(&r, w);
		struct sample_draw dr;
		draw_init(&dr, w);
		draw_mean(&dr, w);
		draw_make(&dr, w, 3, (unsigned long)c, 0);
		sample_run(ws, &dr, &so, &r);
		double smp = r.status == SAMPLE_ACCEPTED ? r.lambda_min : NAN;
		double tol = 1e-6 * fmax(1, fabs(gil));
		small += one_course;
		if (isfinite(glob)) {
			found++;
			small_proven += one_course && rg.proven;
			if (!(rg.has_mechanism && rg.mech.vw_residual <= 1e-8 &&
			      glob > 0))
				bad_check++, tap_diag("case %d: global %.9g not "
						      "checked (virtual work %.3g)",
						      c, glob, rg.mech.vw_residual);
			if (rg.proven && (glob > gil + tol || glob > smp + tol))
				bad++, tap_diag("case %d: proven global %.9g > "
						"gilbert %.9g or sample %.9g", c,
						glob, gil, smp);
		}
		if (rg.lower_bound > gil + tol || rg.lower_bound > smp + tol)
			bad_bound++, tap_diag("case %d: bound %.9g > gilbert %.9g "
					      "or sample %.9g", c, rg.lower_bound,
					      gil, smp);
		draw_free(&dr);
		sample_result_free(&r);
		sample_ws_free(ws);
		solve_result_free(&rg);
		solve_result_free(&rb);
		wall_free(w);
	}
	gsl_rng_free(g);
	tap_diag("global: a load on %d of 100 walls; %d of %d one-course "
		 "walls proven", found, small_proven, small);
	/* how many of the larger walls find a load in 0.5 s depends on
	 * the machine: only the one-course walls are counted on */
	tap_ok(bad_check == 0 && found >= small, "every global load is a "
	       "checked onset of collapse, positive (%d not), on %d of 100 "
	       "walls (>= the %d one-course walls)", bad_check, found, small);
	tap_ok(bad_bound == 0, "the global bound is below gilbert's onset "
	       "load and the depth-0 sample's (%d violations)", bad_bound);
	tap_ok(bad == 0, "a proven global load is below them too (%d "
	       "violations)", bad);
	tap_ok(small > 20 && small_proven == small, "one-course walls (3 "
	       "blocks): optimality proven on %d of %d", small_proven, small);
}

/* A wall that cannot carry a finite load, one that cannot stand, and
 * one that stands but carries no load. */
static void failures(void)
{
	char err[SW_ERRLEN];
	struct solve_opts o;
	struct solve_result r;
	solve_opts_default(&o, SOLVE_STANDARD);
	/* a block boxed in by a support on its right, pushed into it */
	struct wall *w = wall_new();
	tw_rect(w, "A", 0, 0, 0.4, 0.4);
	double wall_xy[8] = {0.4, 0, 0.6, 0, 0.6, 0.4, 0.4, 0.4};
	struct wall_mark mk = {0, 0};
	wall_add_block(w, "abutment", wall_xy, 4, 1, mk);
	w->has_ground = 1;
	tw_point_load(w, 0, 0.1, 1, 0);
	tw_finish(w);
	enum sw_status st = solve_run(w, &o, &r, err);
	tap_ok(st == SW_EANALYSIS && strstr(err, "unbounded"),
	       "a load pushing into a support: %s", err);
	solve_result_free(&r);
	wall_free(w);
	/* a block overhanging the ground edge: its centroid is beyond the
	 * only support, so no stress field carries its weight */
	w = wall_new();
	tw_rect(w, "base", 0, 0, 0.2, 0.2);
	tw_rect(w, "cantilever", 0.1, 0.2, 0.6, 0.1);
	w->has_ground = 1;
	tw_point_load(w, 0.1, 0.25, 1, 0);
	tw_finish(w);
	st = solve_run(w, &o, &r, err);
	tap_ok(st == SW_EANALYSIS && strstr(err, "cannot stand"),
	       "a wall that cannot stand under its own weight: %s", err);
	solve_result_free(&r);
	wall_free(w);
	/* a block on frictionless ground stands, and slides under any push:
	 * its collapse load is 0 (it was told it could not stand) */
	w = wall_new();
	tw_rect(w, "A", 0, 0, 0.4, 0.4);
	w->has_ground = 1;
	w->mu_bed = w->mu_head = 0;
	tw_point_load(w, 0, 0.2, 1, 0);
	tw_finish(w);
	st = solve_run(w, &o, &r, err);
	tap_ok(st == SW_EANALYSIS && strstr(err, "largest load factor is 0,") &&
	       !strstr(err, "cannot stand"),
	       "zero friction: collapses under any push: %s", err);
	solve_result_free(&r);
	wall_free(w);
}

/* The index of block id in w, or -1. */
static int block_of(const struct wall *w, const char *id)
{
	for (int b = 0; b < w->nblocks; b++)
		if (!strcmp(w->blocks[b].id, id))
			return b;
	return -1;
}

/* Two piers on the ground, 0.2 m wide at x = 0 and x = 1.0, 0.6 m
 * high, and on each an end block of 0.4 x 0.2 m reaching over_l (over_r)
 * past its pier's outer edge: its centroid is over its bearing when
 * over < 0.2, beyond it (held by nothing: the pier's top is its only
 * joint) when over > 0.2.  The blocks named in `fixed` are supports. */
static struct wall *piers(double over_l, double over_r, const char *fixed)
{
	struct wall *w = wall_new();
	struct wall_mark mk = {0, 0};
	tw_rect(w, "pier_l", 0, 0, 0.2, 0.6);
	tw_rect(w, "pier_r", 1.0, 0, 0.2, 0.6);
	double l[8] = {-over_l, 0.6, 0.4 - over_l, 0.6, 0.4 - over_l, 0.8,
		       -over_l, 0.8};
	double r[8] = {0.8 + over_r, 0.6, 1.2 + over_r, 0.6, 1.2 + over_r, 0.8,
		       0.8 + over_r, 0.8};
	wall_add_block(w, "end_l", l, 4, fixed && strstr(fixed, "end_l"), mk);
	wall_add_block(w, "end_r", r, 4, fixed && strstr(fixed, "end_r"), mk);
	w->has_ground = 1;
	tw_point_load(w, 0, 0.3, 1, 0);
	tw_finish(w);
	return w;
}

/* A wall's workspace, its classical draw (the interface ends, the mean
 * friction) and a result, as solve_run makes them: unheld() solves on
 * it directly. */
struct classical {
	struct sample_ws *ws;
	struct sample_draw d;
	struct sample_result r;
};

static void classical_open(struct classical *c, const struct wall *w)
{
	c->ws = sample_ws_new(w);
	draw_init(&c->d, w);
	draw_mean(&c->d, w);
	sample_result_init(&c->r, w);
}

static void classical_close(struct classical *c)
{
	sample_result_free(&c->r);
	draw_free(&c->d);
	sample_ws_free(c->ws);
}

/* `no_equilibrium` names the blocks that cannot be held (sample_unheld,
 * docs/method.md "Which blocks cannot be held"): an elastic LP-max
 * whose help acts on exactly the blocks that overhang their bearing, a
 * wall that stands gets none, and holding the named block (making it a
 * support) gives the wall back an equilibrium; `unstable` names the
 * block that needs the live load. */
static void unheld(void)
{
	char err[SW_ERRLEN];
	struct solve_opts o;
	struct solve_result r;
	solve_opts_default(&o, SOLVE_STANDARD);
	/* end_r overhangs: it spans 1.05-1.45 m, its centroid at 1.25 m
	 * beyond its bearing 1.05-1.2 m; end_l's centroid is over its pier */
	struct wall *w = piers(0, 0.25, NULL);
	enum sw_status st = solve_run(w, &o, &r, err);
	tap_ok(st == SW_EANALYSIS && r.status == SAMPLE_NO_EQUILIBRIUM &&
	       r.nunheld == 1 && r.unheld[0] == block_of(w, "end_r") &&
	       strstr(err, "acts on block end_r") &&
	       !strstr(err, "end_l"),
	       "one end block overhangs its pier: it alone is named: %s", err);
	solve_result_free(&r);
	wall_free(w);
	/* both overhang: both named, the one further out first (end_l's
	 * centroid is 0.1 m past its pier, end_r's 0.05 m: it needs twice
	 * the moment) */
	w = piers(0.3, 0.25, NULL);
	st = solve_run(w, &o, &r, err);
	tap_ok(st == SW_EANALYSIS && r.nunheld == 2 &&
	       r.unheld[0] == block_of(w, "end_l") &&
	       r.unheld[1] == block_of(w, "end_r") &&
	       strstr(err, "acts on blocks end_l and end_r"),
	       "both end blocks overhang: both named, the further first: %s",
	       err);
	solve_result_free(&r);
	/* the same least help when the primal simplex is cut at its pivot
	 * limit and the dual simplex from the slack basis goes on: one LP
	 * more, the same blocks in the same order */
	struct classical c;
	classical_open(&c, w);
	enum sample_status ss = sample_standard(c.ws, &c.d, &c.r);
	struct lp_counters c0, c1, c2;
	int b1[4], b2[4];
	lp_solver_counters(sample_ws_solver(c.ws), &c0);
	int n1 = sample_unheld(c.ws, SAMPLE_UNHELD_ANY, b1, 4);
	lp_solver_counters(sample_ws_solver(c.ws), &c1);
	sample_ws_unheld_limit(c.ws, 1);
	int n2 = sample_unheld(c.ws, SAMPLE_UNHELD_ANY, b2, 4);
	lp_solver_counters(sample_ws_solver(c.ws), &c2);
	sample_ws_unheld_limit(c.ws, 0);
	tap_ok(ss == SAMPLE_NO_EQUILIBRIUM && n1 == 2 && n2 == 2 &&
	       b1[0] == b2[0] && b1[1] == b2[1] &&
	       c1.solves - c0.solves == 1 && c2.solves - c1.solves == 2,
	       "the primal cut after 1 pivot: the dual simplex names the "
	       "same %d blocks (%d), in %ld LPs (%ld uncut)", n2, n1,
	       c2.solves - c1.solves, c1.solves - c0.solves);
	classical_close(&c);
	wall_free(w);
	/* hold end_r (a support) and only end_l is left to name */
	w = piers(0.3, 0.25, "end_r");
	st = solve_run(w, &o, &r, err);
	tap_ok(st == SW_EANALYSIS && r.nunheld == 1 &&
	       r.unheld[0] == block_of(w, "end_l"),
	       "the right end held: only the left one named: %s", err);
	solve_result_free(&r);
	wall_free(w);
	/* hold both: the wall has an equilibrium (its load, which pushes
	 * the left pier under a support, is unbounded) */
	w = piers(0.3, 0.25, "end_l end_r");
	st = solve_run(w, &o, &r, err);
	tap_ok(r.status == SAMPLE_UNBOUNDED && r.nunheld == 0,
	       "both ends held: an equilibrium, nothing named (%s)",
	       st == SW_OK ? "ok" : err);
	solve_result_free(&r);
	wall_free(w);
	/* let neither overhang: the wall stands */
	w = piers(0.1, 0.1, NULL);
	st = solve_run(w, &o, &r, err);
	tap_ok(st == SW_OK && r.status == SAMPLE_ACCEPTED && r.nunheld == 0,
	       "centroids over their piers: the wall stands, nothing named "
	       "(%s)", st == SW_OK ? "ok" : err);
	solve_result_free(&r);
	wall_free(w);
	/* on a wall that stands, the elastic LP needs no help */
	w = piers(0.1, 0.1, NULL);
	classical_open(&c, w);
	ss = sample_standard(c.ws, &c.d, &c.r);
	int b[4];
	tap_ok(ss == SAMPLE_ACCEPTED && sample_unheld(c.ws, 0, b, 4) == 0 &&
	       sample_unheld(c.ws, 1, b, 4) == 0,
	       "sample_unheld on a wall that stands: 0 blocks, at any load "
	       "and at rest");
	/* and after an SLP that ends above 0, its capacities hold every
	 * block at a load along the live load's (the question asked after
	 * the SLP's `nonpositive`; tests/cli/body.sh has one that names a
	 * block) */
	struct sample_opts so;
	sample_opts_default(&so);
	sample_run(c.ws, &c.d, &so, &c.r);
	int nf = sample_unheld(c.ws, SAMPLE_UNHELD_FIXED, b, 4);
	tap_ok(c.r.status == SAMPLE_ACCEPTED && c.r.lambda_max > 0 && nf == 0,
	       "sample_unheld with the SLP's capacities on a wall that "
	       "stands (%s, lambda_max %g): %d blocks",
	       sample_status_name(c.r.status), c.r.lambda_max, nf);
	classical_close(&c);
	wall_free(w);

	/* a block beyond its pier held up by the live load itself (an
	 * upward point load on its far end): LP-max has an equilibrium at
	 * some load, the standing check none at rest, so the sample is
	 * `unstable`, and sample_run names the block that needs the load;
	 * at any load (at_rest 0) nothing needs help */
	w = wall_new();
	struct wall_mark mk = {0, 0};
	tw_rect(w, "pier", 0, 0, 0.4, 0.2);
	double ov[8] = {0.3, 0.2, 0.7, 0.2, 0.7, 0.4, 0.3, 0.4};
	wall_add_block(w, "over", ov, 4, 0, mk);
	w->has_ground = 1;
	tw_point_load(w, 0.7, 0.3, 0, 1);
	tw_finish(w);
	classical_open(&c, w);
	sample_run(c.ws, &c.d, &so, &c.r);
	int n0 = sample_unheld(c.ws, 0, b, 4);
	tap_ok(c.r.status == SAMPLE_UNSTABLE && c.r.nunheld == 1 &&
	       c.r.unheld == block_of(w, "over") && n0 == 0,
	       "held up by its own load: unstable (%s), 'over' needs the load "
	       "(%d, %d blocks), nothing at some load (%d)",
	       sample_status_name(c.r.status), c.r.unheld, c.r.nunheld, n0);
	classical_close(&c);
	wall_free(w);
}

/* Units must not matter: Ferris & Tin-Loi wall 1 built at 1e-3 and 1e3
 * times its size has the same load factors (body load); a block pushed
 * at a point collapses at a load that scales exactly as its weight. */
static void scale(void)
{
	double ref[2] = {NAN, NAN};
	const double f[3] = {1, 1e-3, 1e3};
	for (int i = 0; i < 3; i++) {
		struct wall *w = tw_layout(0.4 * f[i], 0.175 * f[i], 6, 2.0 * f[i],
					   1, 1, 0.65);
		tw_body_load(w);
		tw_finish(w);
		struct solve_result r;
		double s = run(w, SOLVE_STANDARD, &r);
		solve_result_free(&r);
		double g = run(w, SOLVE_GILBERT, &r);
		solve_result_free(&r);
		if (i == 0) {
			ref[0] = s;
			ref[1] = g;
			wall_free(w);
			continue;
		}
		tap_near(s, ref[0], 1e-6, "standard load factor at scale 1e-3 / 1e3");
		tap_near(g, ref[1], 1e-6, "gilbert load factor at scale 1e-3 / 1e3");
		wall_free(w);
	}
	double ratio = NAN;
	for (int i = 0; i < 3; i++) {
		struct wall *w = wall_new();
		tw_rect(w, "A", 0, 0, 0.4 * f[i], 0.8 * f[i]);
		w->has_ground = 1;
		tw_point_load(w, 0, 0.6 * f[i], 1, 0);
		tw_finish(w);
		struct solve_result r;
		double p = run(w, SOLVE_GILBERT, &r) / w->total_weight;
		solve_result_free(&r);
		if (i == 0)
			ratio = p;
		else
			tap_near(p, ratio, 1e-9, "point load / weight independent of the scale");
		wall_free(w);
	}
}

/* The stop flag (solve_opts.stop): set before, nothing is solved; set
 * during a long LP of walls/large.yaml (from the progress hook, which
 * runs only after half a second of one LP), the solve ends with
 * SW_EINTR instead of running for minutes. */
static void stop_flag_set(void *ctx, const char *what, double seconds,
			  double incumbent, double bound)
{
	(void)what;
	(void)seconds;
	(void)incumbent;
	(void)bound;
	atomic_store((atomic_int *)ctx, 1);
}

static void stops(void)
{
	char err[SW_ERRLEN];
	struct solve_opts o;
	struct solve_result r;
	atomic_int stop;
	struct wall *w = tw_load_file("walls/ferris-tinloi-1.yaml");

	solve_opts_default(&o, SOLVE_STANDARD);
	atomic_init(&stop, 0);
	o.stop = &stop;
	enum sw_status st = solve_run(w, &o, &r, err);
	tap_ok(st == SW_OK && r.status == SAMPLE_ACCEPTED,
	       "a stop flag left at 0 changes nothing (%.6g)", r.lambda);
	solve_result_free(&r);
	atomic_store(&stop, 1);
	st = solve_run(w, &o, &r, err);
	tap_ok(st == SW_EINTR && r.status == SAMPLE_NUMERICAL && isnan(r.lambda),
	       "a stop flag set before: SW_EINTR, no load (%s)", err);
	solve_result_free(&r);
	wall_free(w);

	struct wall *big = tw_load_file("walls/large.yaml");
	solve_opts_default(&o, SOLVE_GILBERT);
	atomic_store(&stop, 0);
	o.stop = &stop;
	o.progress = stop_flag_set;
	o.progress_ctx = &stop;
	st = solve_run(big, &o, &r, err);
	tap_ok(st == SW_EINTR && r.status == SAMPLE_NUMERICAL,
	       "large.yaml, stopped during its first long LP: SW_EINTR (%s)",
	       err);
	solve_result_free(&r);
	wall_free(big);
}

/* A block on an inclined face (a fixed wedge whose face falls along +x
 * at tan theta = t), len along the face and h thick, under a horizontal
 * body load along +x (down the slope) or -x (up it).  It slides where
 * the load's component along the face overcomes friction on the normal
 * force:
 *     down:  lambda = (mu - t) / (1 + mu t)
 *     up:    lambda = (mu + t) / (1 - mu t)     (mu t < 1)
 * and tips about the base corner it leans over where the resultant of
 * weight and load passes it: lambda = -rx / ry about the lower corner
 * (down), rx / ry about the upper one (up), with (rx, ry) the centroid
 * from that corner (no tipping where that is negative).  The collapse
 * load is the least of them, for every method. */
struct incline {
	double mu, t;
	int up;
	double len, h;	/* the block: along the face, out of it */
};

static void inclines(void)
{
	static const struct incline cases[] = {
		{0.9, 0.8, 0, 0.4, 0.1}, {0.9, 0.8, 1, 0.4, 0.1},
		{0.7, 0.3, 0, 0.4, 0.1}, {0.7, 0.3, 1, 0.4, 0.1},
		{0.45, 0.4, 0, 0.4, 0.1},
		/* a slender block: it tips down the slope first */
		{0.9, 0.1, 0, 0.1, 0.4},
	};
	for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
		const struct incline *q = &cases[c];
		double th = atan(q->t), L = 1.0;
		double ux = cos(th), uy = -sin(th);	/* down the face */
		double nx = sin(th), ny = cos(th);	/* out of it */
		double a = 0.3, len = q->len, h = q->h;
		double p0x = a * ux, p0y = L * q->t + a * uy;
		double xy[8] = {p0x, p0y, p0x + len * ux, p0y + len * uy,
				p0x + len * ux + h * nx, p0y + len * uy + h * ny,
				p0x + h * nx, p0y + h * ny};
		double wedge[6] = {0, 0, L, 0, 0, L * q->t};
		struct wall_mark mk = {0, 0};
		struct wall *w = wall_new();
		wall_add_block(w, "block", xy, 4, 0, mk);
		wall_add_block(w, "wedge", wedge, 3, 1, mk);
		w->mu_bed = w->mu_head = q->mu;
		tw_body_load_x(w, q->up ? -1 : 1);
		tw_finish(w);
		double gx = 0, gy = 0;
		for (int i = 0; i < 4; i++) {
			gx += xy[2 * i] / 4;
			gy += xy[2 * i + 1] / 4;
		}
		double slide, rx, ry, tip;
		if (q->up) {
			slide = (q->mu + q->t) / (1 - q->mu * q->t);
			rx = gx - xy[0];	/* from the upper corner */
			ry = gy - xy[1];
			tip = rx / ry;
		} else {
			slide = (q->mu - q->t) / (1 + q->mu * q->t);
			rx = gx - xy[2];	/* from the lower corner */
			ry = gy - xy[3];
			tip = -rx / ry;
		}
		int slides = tip <= 0 || slide < tip;
		char what[96];
		snprintf(what, sizeof what, "a block on a slope, tan %g, "
			 "friction %g, load %s it", q->t, q->mu,
			 q->up ? "up" : "down");
		one_joint(w, slides ? slide : tip,
			  slides ? JOINT_SLIDES : JOINT_HINGES, what);
		wall_free(w);
	}
}

/* A trapezoid on the ground, (0, 0) (0.6, 0) (0.2, 0.6) (0, 0.6), under
 * a horizontal body load, friction 2 (it tips before it slides): the
 * weight and the load act at its area's centroid (13/60, 1/4), not at
 * the mean of its vertices (0.2, 0.3), so it tips about its left corner
 * at lambda = x_c / y_c = 13/15 under the load along -x (0.667 at the
 * vertices' mean) and about its right one at (0.6 - x_c) / y_c = 23/15
 * along +x, every method, its joint hinging. */
static void trapezoid(void)
{
	static const double xy[8] = {0, 0, 0.6, 0, 0.2, 0.6, 0, 0.6};
	for (int up = 0; up < 2; up++) {
		struct wall_mark mk = {0, 0};
		struct wall *w = wall_new();
		wall_add_block(w, "trapezoid", xy, 4, 0, mk);
		w->has_ground = 1;
		w->mu_bed = w->mu_head = 2;
		tw_body_load_x(w, up ? -1 : 1);
		tw_finish(w);
		one_joint(w, up ? 13.0 / 15 : 23.0 / 15, JOINT_HINGES,
			  up ? "a trapezoid, the load along -x" :
			       "a trapezoid, the load along +x");
		wall_free(w);
	}
}

int main(void)
{
	stops();
	scale();
	stacks();
	inclines();
	trapezoid();
	published();
	global_walls();
	failures();
	unheld();
	lp_thread_done();
	return tap_done();
}
