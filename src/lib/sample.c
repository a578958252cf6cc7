/*
 * sample.c - one Monte Carlo sample (docs/method.md), the hot loop.
 *
 * Six LP problems per wall and thread, one per LP role, built once per
 * workspace on the workspace's own LP solver (lp.h).  Each sample
 * rewrites what its contact points change (the moment coefficients of
 * the normal-force columns and of the opening-rate rows) and resets
 * every bound and objective (sws_refill; the `previous` start keeps the
 * bases) and starts every role from the basis its start option names
 * (set_points); within a sample only bounds change between two
 * solves of a role, so each is a warm start (presolve off).  Wherever an LP's optimum is not unique, the
 * sample takes the optimal solution with the least weighted sum of its
 * normal forces (or, for the kinematic LP, joint rates), the weights
 * hashed from the contact positions: "One answer per sample", so that
 * the result does not depend on the start (docs/method.md).  All
 * quantities are in the scaled units of statics.h; results are
 * converted at the end.
 *
 * The work is split by job, a file each.  This file holds the workspace
 * (new, free, counters), the statuses, options and results, a sample's
 * begin (set_points writes its draw into the problems) and finish, the
 * canonical bases and the set-up that shares them (struct sample_setup:
 * docs/design.md, "The shared set-up"), the public entry points (sample_run, sample_pattern,
 * sample_standard, sample_export), and the roles' names; the others, each
 * below the ones that call it (none calls up into this file):
 *
 *   sample_ws.h      the workspace (struct sample_ws), the roles, the
 *                    column layout: what the files below share
 *   sample_lp.c      the LPs' formulation: build, write, refill, and
 *                    every solve, counted by role (and its memory errors)
 *   sample_start.c   the starts (the start option): each role's basis
 *   sample_tie.c     the tie-break weights and the tie-breaks ("One
 *                    answer per sample")
 *   sample_slp.c     step 2b: the SLP (plain, Anderson, piece path)
 *   sample_onset.c   steps 2a, 3 and 5: LP-max, standing, the mechanism,
 *                    onset, LP-min, virtual work, the export
 *   sample_unheld.c  after `no_equilibrium`, `unstable` or
 *                    `nonpositive`: which blocks cannot be held (an
 *                    elastic LP-max, or LP1 after the SLP's; on no
 *                    sample's path)
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "sample_ws.h"

/* The default SLP (slp_piece_path, docs/method.md "The SLP's answer"):
 * the joints' classification must hold this many iterations before the
 * piece's fixed point is solved (measured: 2 keeps the plain iteration's
 * answer wherever it is not decided by round-off; 1 and 0 move 3.5 % and
 * 12 % of the demo's samples) */
#define SLP_PIECE_SETTLE 2

static const struct {
	const char *name, *text;
} status_info[] = {
#define SAMPLE_X(e, name, text) {name, text},
	SAMPLE_STATUS_TABLE(SAMPLE_X)
#undef SAMPLE_X
};

const char *sample_status_name(enum sample_status s)
{
	return (unsigned)s < SAMPLE_STATUS_COUNT ? status_info[s].name : "?";
}

const char *sample_status_text(enum sample_status s)
{
	return (unsigned)s < SAMPLE_STATUS_COUNT ? status_info[s].text : "?";
}

int sample_status_parse(const char *name)
{
	for (int s = 0; s < SAMPLE_STATUS_COUNT; s++)
		if (!strcmp(name, status_info[s].name))
			return s;
	return -1;
}

void sample_opts_default(struct sample_opts *o)
{
	o->omega = 0.5;
	/* Nearly every sample converges in some tens of iterations; a few
	 * (1 % of Ferris & Tin-Loi wall 1) take 200-900, while the normal
	 * force of an interface that is losing its contact creeps to zero
	 * along a tie of LP2's L1 objective (docs/method.md).  None of
	 * 2,400 samples of the published walls needed more than 874. */
	o->max_iter = 1000;
	o->tol = 1e-7;
	o->stabilise = 1;
	o->slp = SAMPLE_SLP_PIECE;
	o->piece_settle = SLP_PIECE_SETTLE;
	o->forces = 0;
}

void sample_result_init(struct sample_result *r, const struct wall *w)
{
	memset(r, 0, sizeof *r);
	r->unheld = -1;
	r->nblocks = w->nblocks;
	r->nifaces = w->nifaces;
	size_t m = (size_t)w->nifaces;
	r->vel = sw_xcalloc(3 * (size_t)w->nblocks + 1, sizeof(double));
	r->joint = sw_xcalloc(m + 1, 1);
	r->dn = sw_xcalloc(2 * m + 1, sizeof(double));
	r->dt = sw_xcalloc(m + 1, sizeof(double));
	r->N = sw_xcalloc(2 * m + 1, sizeof(double));
	r->T = sw_xcalloc(m + 1, sizeof(double));
}

void sample_result_free(struct sample_result *r)
{
	free(r->vel);
	free(r->joint);
	free(r->dn);
	free(r->dt);
	free(r->N);
	free(r->T);
	memset(r, 0, sizeof *r);
}

/* Write a sample's draw into its problems: the contact points and the
 * frictions (statics_set_draw), the tie-break weights, then every
 * problem's starting basis (sws_start_bases, the start option).  With the tie-breaks a
 * sample is a function of its contact points alone, whatever the start
 * (tests/unit/test_start.c checks it); the start only decides how many
 * pivots it takes.  The default, `auto` (sws_role_start), is a function of
 * the wall alone, so that the CSV is byte-identical whatever the thread
 * count, which `previous` (the basis the thread's last sample left)
 * cannot promise to the last bit.  For the same reason every start but
 * `previous` takes the problems back to a fresh state before it writes
 * the points (sws_refill: no basis, no factorization kept from the last
 * sample). */
static void set_points(struct sample_ws *ws, const struct sample_draw *d)
{
	statics_set_draw(&ws->st, d);
	sws_tie_weights(ws, d->xi);
	if (ws->start == SAMPLE_START_PREVIOUS) {
		for (int j = 0; j < 3 * ws->m; j++)
			sws_put_column(ws, j);
		sws_put_kin_objective(ws);
	} else {
		sws_refill(ws);
	}
	sws_put_lp2_objective(ws);
	sws_start_bases(ws);
}

/* A sample's result, reset, and its problems built for its draw d;
 * forces: it reports its stress field. */
static void begin(struct sample_ws *ws, const struct sample_draw *d,
		  int forces, struct sample_result *r)
{
	ws->forces = forces;
	r->status = SAMPLE_NUMERICAL;
	r->lambda_lpmax = r->lambda_max = r->lambda_min = NAN;
	r->iterations = 0;
	r->converged = 0;
	r->lps = 0;
	r->vw_residual = NAN;
	set_points(ws, d);
}

/* A sample's first steps (docs/method.md, "One sample"): its problems
 * for the draw d, LP-max and the standing check. */
static enum sample_status first_steps(struct sample_ws *ws,
				      const struct sample_draw *d,
				      const struct sample_opts *o,
				      struct sample_result *r)
{
	begin(ws, d, o->forces, r);
	enum sample_status st = sws_lp_max(ws, r, NULL);
	if (st == SAMPLE_ACCEPTED)
		st = sws_standing(ws, r);
	return st;
}

/* A large wall's canonical sample (SWS_LARGE_IFACES), as far as its
 * samples use its bases: LP-max (without its tie-break, sample_tie.c),
 * the standing check and the SLP's first LP1, at LP-max's capacities.
 * Its SLP path, mechanism and LP-min were 14 of the 19 s of
 * walls/body-1000.yaml's set-up.  A sample's LP2 starts from the slack
 * basis there, or under a body load from its own LP1's optimum
 * (sws_role_start, lp2_from_lp1), and its mechanism from LP1's
 * complementary basis (kin_from_lp1); and LP1's basis at the path's end
 * saved the samples no more than LP1's first basis does
 * (docs/performance.md, "A large wall's set-up").
 * LP-min's start: its optimum for the mechanism of LP1's field, found by
 * one dual simplex solve from LP-max's optimum, where that solve has one
 * within one pivot per interface (walls/large.yaml, 415 of 2,956
 * pivots; pulled at one block: every sample's mechanism is
 * that one, and its LP-min then takes 378 pivots, against 10,150 from
 * LP-max's basis); otherwise LP-max's optimum itself (walls/
 * body-1000.yaml, whose first LP1 is far from an onset state: from it
 * LP-min took 6,654-8,289 pivots a sample, from the basis of the whole
 * canonical sample's LP-min 7,864-8,131; the set-up's solve, uncut,
 * took 14,282 pivots, 4.6 s, to prove LP-min infeasible there, and is
 * cut at 2,956 now, 1.8 s: docs/performance.md, "The set-up's LP-min
 * cut"). */
static void setup_large(struct sample_ws *ws, const struct sample_draw *d,
			const struct sample_opts *o, struct sample_result *r)
{
	enum sample_status st = first_steps(ws, d, o, r);
	if (st == SAMPLE_ACCEPTED)
		st = sws_slp_first_lp1(ws, o, r);
	if (st == SAMPLE_ACCEPTED)
		st = sws_onset(ws, o, SWS_ZERO_DYING, r);
	struct lp_basis amax = {0};
	lp_basis_save(ws->lp[AMAX], &amax);
	lp_basis_load(ws->lp[AMIN], &amax);
	/* at most one pivot per interface for LP-min's start (above) */
	int was = lp_solver_iteration_limit(ws->solver, ws->m);
	enum lp_status min = st == SAMPLE_ACCEPTED ? sws_lp_min_once(ws, r)
						   : LP_FAILED;
	lp_solver_iteration_limit(ws->solver, was);
	if (min != LP_OPTIMAL)
		lp_basis_load(ws->lp[AMIN], &amax);
	lp_basis_free(&amax);
}

/* The canonical sample (xi = 0, 1, mean friction), solved from the
 * freshly built problems; each role keeps the basis it ended at: the
 * start of every later sample (sws_start_bases).  Deterministic: it
 * depends on the wall only, and nothing of it is reported.  A small wall
 * solves the whole sample, a large one what its samples use
 * (setup_large). */
static void canonical_bases(struct sample_ws *ws)
{
	struct sample_opts o;
	struct sample_result r;
	sample_opts_default(&o);
	sample_result_init(&r, ws->w);
	struct sample_draw d;
	draw_init(&d, ws->w);
	draw_mean(&d, ws->w);	/* the classical contact, mean friction */
	ws->setup = 1;
	if (ws->large)
		setup_large(ws, &d, &o, &r);
	else
		sample_run(ws, &d, &o, &r);
	ws->setup = 0;
	/* interrupted (sample_lp_config.stop): the problems are dead and the
	 * workspace is only fit to be freed; lp_basis_save skips them */
	for (int p = 0; p < ROLES; p++)
		lp_basis_save(ws->lp[p], &ws->canon[p]);
	draw_free(&d);
	sample_result_free(&r);
}

/* The set-up of a wall (slipwall/sample.h): the canonical bases as
 * plain data, with what they were solved for. */
struct sample_setup {
	unsigned long shape;	/* setup_shape() */
	enum sample_start start;
	int large;
	struct lp_basis canon[ROLES];
};

/* A hash of what decides the LPs' rows and columns: the blocks (which
 * are supports), the interfaces and the bodies each one joins.  Two
 * walls with the same hash have problems of the same shape, whose bases
 * are interchangeable as starts. */
static unsigned long setup_shape(const struct wall *w)
{
	unsigned long long h = 1469598103934665603ULL;	/* FNV-1a */
#define MIX(x) (h = (h ^ (unsigned long long)(unsigned)(x)) * 1099511628211ULL)
	MIX(w->nblocks);
	MIX(w->nifaces);
	for (int i = 0; i < w->nblocks; i++)
		MIX(w->blocks[i].fixed);
	for (int k = 0; k < w->nifaces; k++) {
		MIX(w->ifaces[k].a);
		MIX(w->ifaces[k].b);
	}
#undef MIX
	return (unsigned long)h;
}

static int large_wall(const struct wall *w)
{
	return w->nifaces > SWS_LARGE_IFACES;
}

/* A set-up holding copies of the bases canon[ROLES]. */
static struct sample_setup *setup_new(unsigned long shape,
				      enum sample_start start, int large,
				      const struct lp_basis *canon)
{
	struct sample_setup *s = sw_xcalloc(1, sizeof *s);
	s->shape = shape;
	s->start = start;
	s->large = large;
	for (int p = 0; p < ROLES; p++)
		lp_basis_copy(&s->canon[p], &canon[p]);
	return s;
}

struct sample_setup *sample_ws_setup(const struct sample_ws *ws)
{
	if (lp_solver_interrupted(ws->solver))
		return NULL;	/* the canonical sample may be incomplete */
	return setup_new(setup_shape(ws->w), ws->start, ws->large, ws->canon);
}

struct sample_setup *sample_setup_copy(const struct sample_setup *s)
{
	return s ? setup_new(s->shape, s->start, s->large, s->canon) : NULL;
}

void sample_setup_free(struct sample_setup *s)
{
	if (!s)
		return;
	for (int p = 0; p < ROLES; p++)
		lp_basis_free(&s->canon[p]);
	free(s);
}

static int setup_fits(const struct sample_setup *s, const struct wall *w,
		      enum sample_start start, int large)
{
	return s && s->shape == setup_shape(w) && s->start == start &&
	       s->large == large;
}

int sample_setup_fits(const struct sample_setup *s, const struct wall *w,
		      const struct sample_lp_config *c)
{
	return setup_fits(s, w, c ? c->start : SAMPLE_START_DEFAULT,
			  large_wall(w));
}

/* A workspace of w; its canonical bases are those of s when s fits,
 * else solved here (canonical_bases). */
static struct sample_ws *ws_new(const struct wall *w,
				const struct sample_lp_config *c, int large,
				const struct sample_setup *s)
{
	sw_init();	/* GSL's handler off before anderson_step can run */
	struct sample_ws *ws = sw_xcalloc(1, sizeof *ws);
	struct lp_config lc;
	lp_config_default(&lc);
	lc.fault_every = c->fault_every;
	lc.fault_as = c->fault_error ? LP_ERROR : LP_FAILED;
	lc.mem_limit_mb = c->mem_limit_mb;
	ws->solver = lp_solver_new(&lc);
	/* before the problems are written: a stop reaches them too */
	lp_solver_stop_flag(ws->solver, c->stop);
	lp_solver_progress(ws->solver, c->progress, c->progress_ctx);
	ws->w = w;
	ws->large = large;
	ws->lp2_primal = !large;
	for (int l = 0; l < w->nloads; l++)
		ws->lp2_primal |= w->loads[l].kind == LOAD_BODY;
	statics_init(&ws->st, w);
	ws->m = w->nifaces;
	ws->R = ws->st.nrows;
	ws->clamp_k = sw_xmalloc(sizeof(int) * ((size_t)ws->m + 1));
	ws->nclamp = wall_clamp_joints(w, ws->clamp_k);
	ws->clamp_blk = sw_xcalloc((size_t)w->nblocks + 1, 1);
	wall_clamp_blocks(w, ws->clamp_blk);
	size_t m = (size_t)ws->m, big = 3 * m + (size_t)ws->R + 16;
	ws->c = sw_xcalloc(m + 1, sizeof(double));
	ws->c0 = sw_xcalloc(m + 1, sizeof(double));
	ws->clost = sw_xcalloc(m + 1, sizeof(double));
	ws->hang_blk = -1;
	ws->cstar = sw_xcalloc(m + 1, sizeof(double));
	ws->fallback = sw_xcalloc(m + 1, sizeof(double));
	for (int i = 0; i <= SLP_MEMORY; i++) {
		ws->hist.c[i] = sw_xcalloc(m + 1, sizeof(double));
		ws->hist.f[i] = sw_xcalloc(m + 1, sizeof(double));
	}
	ws->x = sw_xcalloc(3 * m + 1, sizeof(double));
	ws->v = sw_xcalloc((size_t)ws->R + 1, sizeof(double));
	ws->dn = sw_xcalloc(2 * m + 1, sizeof(double));
	ws->dt = sw_xcalloc(m + 1, sizeof(double));
	ws->ind = sw_xmalloc(sizeof(int) * big);
	ws->val = sw_xmalloc(sizeof(double) * big);
	ws->r = sw_xcalloc(3 * m + 1, sizeof(double));
	ws->c2 = sw_xcalloc(5 * m + (size_t)ws->R + 2, sizeof(double));
	ws->basic = sw_xcalloc(4 * m + 1, 1);
	ws->kfree = sw_xcalloc((size_t)m + 1, 1);
	ws->start = c->start;
	sws_build(ws);
	if (setup_fits(s, w, ws->start, large)) {
		/* a basis of another length (none should be) is not
		 * loaded: lp_basis_load */
		for (int p = 0; p < ROLES; p++)
			lp_basis_copy(&ws->canon[p], &s->canon[p]);
	} else {
		canonical_bases(ws);
		ws->setups = 1;
	}
	return ws;
}

struct sample_ws *sample_ws_new_config(const struct wall *w,
				       const struct sample_lp_config *c)
{
	struct sample_lp_config d;
	if (!c) {
		sample_lp_config_default(&d);
		c = &d;
	}
	return ws_new(w, c, large_wall(w), NULL);
}

struct sample_ws *sample_ws_new_setup(const struct wall *w,
				      const struct sample_lp_config *c,
				      const struct sample_setup *s)
{
	struct sample_lp_config d;
	if (!c) {
		sample_lp_config_default(&d);
		c = &d;
	}
	return ws_new(w, c, large_wall(w), s);
}

struct sample_ws *sample_ws_new(const struct wall *w)
{
	return sample_ws_new_config(w, NULL);
}

struct sample_ws *sample_ws_new_start(const struct wall *w,
				      enum sample_start start)
{
	struct sample_lp_config c;
	sample_lp_config_default(&c);
	c.start = start;
	return sample_ws_new_config(w, &c);
}

struct sample_ws *sample_ws_new_auto_large(const struct wall *w)
{
	struct sample_lp_config c;
	sample_lp_config_default(&c);
	c.start = SAMPLE_START_AUTO;
	return ws_new(w, &c, 1, NULL);
}

void sample_ws_free(struct sample_ws *ws)
{
	if (!ws)
		return;
	for (int p = 0; p < ROLES; p++)
		lp_free(ws->lp[p]);
	statics_free(&ws->st);
	free(ws->c);
	free(ws->c0);
	free(ws->clamp_k);
	free(ws->clamp_blk);
	free(ws->clost);
	lp_basis_free(&ws->slp_start[0]);
	lp_basis_free(&ws->slp_start[1]);
	lp_basis_free(&ws->lp1_end);
	lp_basis_free(&ws->lp2_face);
	lp_basis_free(&ws->kin_start);
	free(ws->cstar);
	free(ws->fallback);
	free(ws->ends.buf);
	for (int i = 0; i <= SLP_MEMORY; i++) {
		free(ws->hist.c[i]);
		free(ws->hist.f[i]);
	}
	free(ws->x);
	free(ws->v);
	free(ws->dn);
	free(ws->dt);
	free(ws->ind);
	free(ws->val);
	free(ws->r);
	free(ws->c2);
	free(ws->basic);
	free(ws->kfree);
	for (int p = 0; p < ROLES; p++)
		lp_basis_free(&ws->canon[p]);
	sws_note_memory(ws);
	lp_solver_free(ws->solver);
	free(ws);
}

void sample_ws_counters(const struct sample_ws *ws,
			struct sample_lp_counters *c)
{
	struct lp_counters lc;
	lp_solver_counters(ws->solver, &lc);
	c->solves = lc.solves;
	c->iterations = lc.iterations;
	c->held = lc.held;
	c->art = lc.art;
	c->shift = lc.shift;
	c->memory_errors = lc.memory_errors;
	c->seconds = lc.seconds;
	c->setups = ws->setups;
}

int sample_ws_interrupted(const struct sample_ws *ws)
{
	return lp_solver_interrupted(ws->solver);
}

void sample_thread_done(void)
{
	lp_thread_done();
}

/* After step 3 found a mechanism (st accepted): LP-min and the virtual
 * work check; the status.  *amin, unless amin is NULL: LP-min's first
 * verdict (LP_OPTIMAL if it did not run). */
static enum sample_status check(struct sample_ws *ws, enum sample_status st,
				struct sample_result *r, enum lp_status *amin)
{
	double allow = 0;
	if (amin)
		*amin = LP_OPTIMAL;
	if (st == SAMPLE_ACCEPTED) {
		st = sws_lp_min(ws, LP_DUAL, r, amin);
		if (st == SAMPLE_ACCEPTED)
			r->vw_residual = sws_virtual_work(ws, r->lambda_min, &allow);
		/* a residual above VW_TOL is the LP's precision (GLPK's
		 * bound tolerance is 1e-7) as often as a wrong answer: it is
		 * not believed from a warm start, but re-checked from the
		 * slack basis (the mechanism, then LP-min by the primal
		 * simplex), a fixed path (measured: 1.8e-7 from GLPK's crash
		 * basis, 3e-15 from the slack basis, on one sample of Ferris &
		 * Tin-Loi wall 2).  (Re-checking LP-min's failures the same
		 * way was measured and changes no status on Ferris & Tin-Loi
		 * wall 2, seed 1, 1,000 samples from any start: not done, so
		 * that an LP that fails costs its sample, test_faults.) */
		if (st == SAMPLE_ACCEPTED && !(r->vw_residual <= allow)) {
			lp_reset_basis(ws->lp[KIN]);
			lp_reset_basis(ws->lp[AMIN]);
			st = sws_mechanism(ws, r);
			if (st == SAMPLE_ACCEPTED)
				st = sws_lp_min(ws, LP_PRIMAL, r, NULL);
			if (st == SAMPLE_ACCEPTED)
				r->vw_residual = sws_virtual_work(ws, r->lambda_min, &allow);
		}
		if (st == SAMPLE_ACCEPTED && !(r->vw_residual <= allow))
			st = SAMPLE_NUMERICAL;
	}
	return st;
}

/* The export of an accepted sample; loads to the user's units, the
 * status into r. */
static void finish(struct sample_ws *ws, enum sample_status st,
		   struct sample_result *r)
{
	double S = ws->st.S;
	if (st == SAMPLE_ACCEPTED)
		sws_export(ws, r);
	r->lambda_lpmax *= S;
	r->lambda_max *= S;
	r->lambda_min *= S;
	r->status = st;
	/* which blocks cannot be held (at any load, without the live load,
	 * or at any load along it): one more LP, on these rejected samples
	 * only (docs/method.md, "Which blocks cannot be held").  A
	 * `nonpositive` is LP-max's (lambda_max not reached, NaN) or the
	 * SLP's; after the SLP's, LP-max held every block at a positive
	 * load, and the blocks are asked with the SLP's capacities, friction
	 * that does not dilate (ws->c is still the SLP's last). */
	r->unheld = -1;
	r->nunheld = 0;
	enum sample_unheld_load load;
	if (sample_unheld_asks(r, &load)) {
		int b, n = sample_unheld(ws, load, &b, 1);
		if (n > 0) {
			r->unheld = b;
			r->nunheld = n;
		}
		r->lps++;
	}
	/* the blocks that hang, from the verdict's own test (sws_slp): no
	 * LP more */
	if (st == SAMPLE_HANGING && ws->hang_blk >= 0) {
		r->unheld = ws->hang_blk;
		r->nunheld = ws->nhang;
	}
}

void sample_run(struct sample_ws *ws, const struct sample_draw *d,
		const struct sample_opts *o, struct sample_result *r)
{
	enum sample_status st = first_steps(ws, d, o, r);
	if (st == SAMPLE_ACCEPTED)
		st = sws_slp(ws, o, r);
	if (st == SAMPLE_ACCEPTED)
		st = sws_slp_load(r);
	enum lp_status amin = LP_OPTIMAL;
	if (st == SAMPLE_ACCEPTED)
		st = check(ws, sws_onset(ws, o, SWS_ZERO_DYING, r), r, &amin);
	/* LP-min infeasible: the mechanism opened a point whose normal
	 * force, below the first force zero, equilibrium needs (Ferris &
	 * Tin-Loi wall 2, seed 1, sample 291: 1.7e-6 block weights; docs/
	 * method.md, "One sample", step 5).  Once more with the strict force
	 * zero; only an accepted sample replaces the first verdict. */
	if (st == SAMPLE_NUMERICAL && amin == LP_INFEASIBLE) {
		st = check(ws, sws_onset(ws, o, SWS_ZERO_STRICT, r), r, &amin);
		if (st != SAMPLE_ACCEPTED) {
			st = SAMPLE_NUMERICAL;
			r->lambda_min = r->vw_residual = NAN;
		}
	}
	/* The SLP's field at lambda_max is an onset state of this
	 * mechanism, one of the fields LP-min minimises over, to the SLP's
	 * tolerance (its residual N - c up to o->tol): LP-min's optimum,
	 * the sample's answer, can be above lambda_max only by that.  It
	 * was on 43 % of the samples of Ferris & Tin-Loi wall 1 (seed 1,
	 * 1,000 samples), by 2e-16 to 7e-15 of the load, and on samples 508
	 * and 524 by 8.5e-10 and 3.0e-10.  A minimum above the maximum reads
	 * as a wrong answer; lambda_max, known to that tolerance, is raised
	 * to lambda_min, which is LP-min's own value and stays a function of
	 * the sample (docs/method.md, "One sample", step 5). */
	if (st == SAMPLE_ACCEPTED && r->lambda_min > r->lambda_max)
		r->lambda_max = r->lambda_min;
	finish(ws, st, r);
}

enum sample_status sample_pattern(struct sample_ws *ws,
				  const struct sample_draw *d,
				  const unsigned char *open,
				  const unsigned char *slip,
				  struct sample_result *r)
{
	begin(ws, d, 1, r);
	for (int k = 0; k < ws->m; k++)
		sws_kin_allow(ws, k, (open[2 * k] ? KIN_OPEN_A : 0) |
				     (open[2 * k + 1] ? KIN_OPEN_B : 0) |
				     (slip[k] & SAMPLE_SLIP_POS ? KIN_SLIP_POS : 0) |
				     (slip[k] & SAMPLE_SLIP_NEG ? KIN_SLIP_NEG : 0));
	finish(ws, check(ws, sws_mechanism(ws, r), r, NULL), r);
	return r->status;
}

const struct statics *sample_statics(const struct sample_ws *ws)
{
	return &ws->st;
}

void sample_export(struct sample_ws *ws, const double *v, const double *x,
		   struct sample_result *r)
{
	ws->forces = 1;
	memcpy(ws->v, v, sizeof(double) * (size_t)ws->R);
	memcpy(ws->x, x, sizeof(double) * 3 * (size_t)ws->m);
	/* rates of v itself, every one free (not a KIN answer) */
	memset(ws->kfree, KIN_OPEN_A | KIN_OPEN_B | KIN_SLIP_POS | KIN_SLIP_NEG,
	       (size_t)ws->m);
	for (int k = 0; k < ws->m; k++) {
		ws->dn[2 * k] = statics_rate(&ws->st, 3 * k, ws->v);
		ws->dn[2 * k + 1] = statics_rate(&ws->st, 3 * k + 1, ws->v);
		ws->dt[k] = statics_rate(&ws->st, 3 * k + 2, ws->v);
	}
	sws_export(ws, r);
}

enum sample_status sample_standard(struct sample_ws *ws,
				   const struct sample_draw *d,
				   struct sample_result *r)
{
	r->lps = 0;
	r->lambda_lpmax = r->lambda_max = r->lambda_min = NAN;
	set_points(ws, d);
	/* the mechanism: the duals of LP-max's equilibrium rows, scaled so
	 * that f_L . v = 1; the stress field: LP-max's, by the tie-break */
	double *v = sw_xmalloc(sizeof(double) * ((size_t)ws->R + 1));
	enum sample_status st = sws_lp_max(ws, r, v);
	if (st != SAMPLE_ACCEPTED) {
		r->lambda_lpmax *= ws->st.S;
		free(v);
		return r->status = st;
	}
	double fl = 0;
	for (int i = 0; i < ws->R; i++)
		fl += ws->st.fL[i] * v[i];
	for (int i = 0; i < ws->R && fl != 0; i++)
		v[i] /= fl;
	double *x = sw_xmalloc(sizeof(double) * (3 * (size_t)ws->m + 1));
	memcpy(x, ws->x, sizeof(double) * 3 * (size_t)ws->m);
	r->lambda_lpmax *= ws->st.S;
	st = sws_standing(ws, r);
	if (st == SAMPLE_ACCEPTED) {
		sample_export(ws, v, x, r);
		r->lambda_max = r->lambda_min = r->lambda_lpmax;
	}
	free(v);
	free(x);
	return r->status = st;
}

static const char *const role_names[SAMPLE_ROLE_COUNT] = {
	"LP-max", "standing", "LP-min", "LP1", "LP2", "kinematic",
	"LP-max tie", "standing tie", "LP-min tie", "LP1 tie", "LP2 tie",
	"kinematic tie",
};

const char *sample_role_name(int role)
{
	return role >= 0 && role < SAMPLE_ROLE_COUNT ? role_names[role] : "?";
}

void sample_ws_stats(const struct sample_ws *ws,
		     struct sample_lp_stats out[SAMPLE_ROLE_COUNT])
{
	memcpy(out, ws->stats, sizeof ws->stats);
}
