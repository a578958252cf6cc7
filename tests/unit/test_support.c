/*
 * test_support.c - the support basis (support.c): three edge columns
 * per free block, all of them on joints beneath it, with forces >= 0
 * at the classical contact; a basis GLPK takes as optimal for the
 * standing check without a pivot there, and one that needs a tenth of
 * the slack basis's pivots elsewhere (the `support` start, through the
 * sample workspace), and the default start's standing check.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/sample.h"
#include "statics.h"
#include "support.h"
#include "tap.h"
#include "walls.h"

/* Check the support basis of w at its classical contact: the count,
 * that every basic column is on a joint beneath its block, and that the
 * basic forces, solved from the columns the basis names, balance f_D
 * with every force >= 0. */
static void classical(struct wall *w, const char *what)
{
	struct statics st;
	statics_init(&st, w);
	int m = w->nifaces, R = st.nrows;
	struct sample_draw dr;	/* the classical contact */
	draw_init(&dr, w);
	draw_mean(&dr, w);
	statics_set_draw(&st, &dr);
	unsigned char *basic = calloc(4 * (size_t)m + 1, 1);
	int bad = support_basis(&st, basic);
	tap_ok(bad == 0, "%s: every block carried with forces >= 0 (%d not)", what, bad);
	int n = 0, below = 1;
	for (int c = 0; c < 4 * m; c++) {
		if (!basic[c])
			continue;
		n++;
		const struct wall_interface *it = &w->ifaces[c / 4];
		below &= fabs(it->n[1]) > 0.5;	/* a bed joint or the ground */
	}
	tap_ok(!basic[4 * m], "%s: lambda is not basic", what);
	tap_ok(n == R, "%s: %d basic columns, 3 per free block (%d)", what, n, R);
	tap_ok(below, "%s: every basic column on a bed joint", what);
	free(basic);
	draw_free(&dr);
	statics_free(&st);
}

/* Standing-check pivots over n samples of w from start (the canonical
 * sample the workspace solves when made included); depth 0: the
 * classical contact, else points up to depth 0.2 from the ends. */
static long standing_pivots(struct wall *w, enum sample_start start, int n,
			    int depth, int *accepted)
{
	struct sample_ws *ws = sample_ws_new_start(w, start);
	struct sample_opts o;
	struct sample_result r;
	sample_opts_default(&o);
	sample_result_init(&r, w);
	struct sample_draw dr;
	draw_init(&dr, w);
	draw_mean(&dr, w);
	double *xi = dr.xi;
	*accepted = 0;
	for (int i = 0; i < n; i++) {
		for (int k = 0; k < w->nifaces; k++) {
			xi[2 * k] = depth ? 0.2 * ((i * 7 + k * 3) % 11) / 10.0 : 0;
			xi[2 * k + 1] = depth ? 1 - 0.2 * ((i * 5 + k) % 13) / 12.0 : 1;
		}
		sample_run(ws, &dr, &o, &r);
		*accepted += r.status == SAMPLE_ACCEPTED;
	}
	struct sample_lp_stats s[SAMPLE_ROLE_COUNT];
	sample_ws_stats(ws, s);
	draw_free(&dr);
	sample_result_free(&r);
	sample_ws_free(ws);
	return s[1].iterations;	/* role 1: the standing check */
}

/* At the classical contact the support basis is optimal for the
 * standing check (no pivot); at other points it may leave a block
 * whose load falls outside its bed joint's contact points (carried by
 * friction in its head joints, which the basis does not use), but it
 * still takes far fewer pivots than the slack basis. */
static void standing(struct wall *w, const char *what)
{
	int acc;
	long p0 = standing_pivots(w, SAMPLE_START_SUPPORT, 5, 0, &acc);
	tap_ok(acc == 5 && p0 == 0, "%s, classical contact: the standing check "
	       "from the support basis: %ld pivots in 6 LPs (%d of 5 accepted)",
	       what, p0, acc);
	long p1 = standing_pivots(w, SAMPLE_START_SUPPORT, 10, 1, &acc);
	long p2 = standing_pivots(w, SAMPLE_START_SLACK_PRIMAL, 10, 1, &acc);
	tap_ok(10 * p1 <= p2 && acc == 10, "%s, depth 0.2: the standing check "
	       "from the support basis %ld pivots, from the slack basis %ld "
	       "(%d of 10 accepted)", what, p1, p2, acc);
	/* the default start takes it on every wall (sample_start.c,
	 * sws_role_start), where it took the canonical basis before */
	long pa = standing_pivots(w, SAMPLE_START_AUTO, 10, 1, &acc);
	long pc = standing_pivots(w, SAMPLE_START_CANONICAL, 10, 1, &acc);
	tap_ok(pa == p1 && pa < pc, "%s, depth 0.2: the standing check of "
	       "`auto` %ld pivots, the support basis's %ld, the canonical "
	       "basis's %ld", what, pa, p1, pc);
}

/* A wall with a block that rests on no joint (an opening without a
 * lintel) has no support basis; the standing check of `auto` then
 * starts from the canonical basis, as every other role does, and not
 * from the slack basis (sample_start.c, sws_start_bases). */
static void no_support(void)
{
	struct wall *w = tw_load_file("tests/data/opening-nolintel.yaml");
	int acc;
	long pa = standing_pivots(w, SAMPLE_START_AUTO, 4, 1, &acc);
	long pc = standing_pivots(w, SAMPLE_START_CANONICAL, 4, 1, &acc);
	long ps = standing_pivots(w, SAMPLE_START_SLACK_PRIMAL, 4, 1, &acc);
	tap_ok(pa == pc && pa < ps, "a wall with a block on no joint: "
	       "the standing check of `auto` %ld pivots, the canonical "
	       "basis's %ld, the slack basis's %ld", pa, pc, ps);
	wall_free(w);
}

int main(void)
{
	/* a block on the ground */
	struct wall *w = tw_block(0.6);
	tw_finish(w);
	classical(w, "a block on the ground");
	standing(w, "a block on the ground");
	wall_free(w);

	/* stack and running bond, 5 courses */
	for (int running = 0; running < 2; running++) {
		const char *what = running ? "running bond" : "stack bond";
		w = tw_layout(0.4, 0.2, 5, 2.0, running, 0, 0.6);
		tw_point_load(w, 0, 0.7, 1, 0);
		tw_finish(w);
		classical(w, what);
		standing(w, what);
		wall_free(w);
	}
	no_support();
	return tap_done();
}
