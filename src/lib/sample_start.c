/*
 * sample_start.c - where a sample's LPs start (docs/method.md, "One
 * answer per sample"; docs/performance.md has the measured pivots): the
 * names of the starts and the parser of the LP configuration
 * (SLIPWALL_LP_START, the fault and memory test variables), `auto`'s
 * choice per role and wall size (sws_role_start), and sws_start_bases,
 * which loads every role's starting basis once sample.c has written a
 * sample's draw into the problems (the support basis: support.c; the
 * canonical bases, which a workspace solves once when it is made:
 * sample.c).  Nothing here calls up into sample.c.
 */
#include <limits.h>
#include <stdlib.h>
#include <string.h>

#include "sample_ws.h"
#include "support.h"

/* The names of the starts, in enum sample_start's order. */
static const char *const start_names[SAMPLE_START_COUNT] = {
	"slack-primal", "slack-dual", "crash", "canonical", "previous",
	"support", "auto",
};

const char *sample_start_name(enum sample_start s)
{
	return (unsigned)s < SAMPLE_START_COUNT ? start_names[s] : "?";
}

int sample_start_parse(const char *name)
{
	for (int s = 0; s < SAMPLE_START_COUNT; s++)
		if (!strcmp(name, start_names[s]))
			return s;
	return -1;
}

void sample_lp_config_default(struct sample_lp_config *c)
{
	memset(c, 0, sizeof *c);
	c->start = SAMPLE_START_DEFAULT;
}

int sample_lp_config_parse(struct sample_lp_config *c, const char *start,
			   const char *fault, const char *mem_mb, char *err)
{
	int rc = 0;
	if (start && *start) {
		int st = sample_start_parse(start);
		if (st >= 0)
			c->start = (enum sample_start)st;
		else
			rc = sw_fail(err, SW_EUSAGE, "SLIPWALL_LP_START='%s': "
				     "not a start; use auto, slack-primal, "
				     "slack-dual, crash, canonical, previous "
				     "or support", start);
	}
	if (fault && *fault) {	/* failed:N or error:N (or N: failed) */
		int error = 0;
		char *end;
		if (!strncmp(fault, "failed:", 7)) {
			fault += 7;
		} else if (!strncmp(fault, "error:", 6)) {
			error = 1;
			fault += 6;
		}
		long n = strtol(fault, &end, 10);
		if (*end || n <= 0) {
			if (!rc)
				rc = sw_fail(err, SW_EUSAGE, "SLIPWALL_LP_FAULT "
					     "must be failed:N or error:N, "
					     "N >= 1");
		} else {
			c->fault_every = n;
			c->fault_error = error;
		}
	}
	if (mem_mb && *mem_mb) {
		char *end;
		long n = strtol(mem_mb, &end, 10);
		if (*end || n <= 0 || n > INT_MAX) {
			if (!rc)
				rc = sw_fail(err, SW_EUSAGE, "SLIPWALL_GLPK_MEM_MB "
					     "must be a number of megabytes >= 1");
		} else {
			c->mem_limit_mb = (int)n;
		}
	}
	return rc ? -1 : 0;
}

/* `auto`: walls with more interfaces than this start LP2 from the slack
 * basis and solve LP-max by the primal simplex (from the canonical
 * basis, like every other role); smaller walls start every role from the
 * canonical bases, LP-max by the dual simplex.  Measured pivots per
 * sample (docs/performance.md): Ferris & Tin-Loi wall 2 (141
 * interfaces), LP-max 29 from the canonical basis by the dual simplex,
 * 59.5 by the primal, 407 from the slack basis by the primal; LP2 20.5
 * and 24.5 per solve (canonical, slack); the 1,020-block wall (2,956
 * interfaces), LP-max 20,744 (canonical, dual), 2,308 (canonical,
 * primal), 13,751 (slack, primal), the first LP2 of a sample 12,254 and
 * 3,884 (canonical, slack; the other roles: canonical fewer on both).
 * Every wall starts the standing check from the support basis
 * (support.c): on the 1,020-block wall 35.5 pivots, 2,092 from the
 * canonical basis (on walls of at most 1,000 interfaces since 29
 * November 2026: below); large walls also start the canonical
 * sample's LP-max from it, solved when the workspace is made (3,322
 * pivots from the support basis, 13,751 from the slack basis).
 * SWS_LARGE_IFACES is in sample_ws.h.
 * On walls of at most that many interfaces, and on larger ones under
 * a body load, LP2's start, whichever it is, is loaded and then
 * replaced: each path of the SLP starts its first LP2 from LP1's
 * optimum (sample_slp.c, lp2_from_lp1), which on the 195-block
 * body-loaded wall took fewer pivots than any start, and on the
 * 1,020-block one fewer than the slack basis (docs/performance.md, "A
 * path's first LP2"). */

/* The start of role p's LPs in this workspace. */
enum sample_start sws_role_start(const struct sample_ws *ws, int p)
{
	/* LP-max, the mechanism and LP-min take `auto`'s starts whatever
	 * the start asked for: one fixed path, a function of the wall
	 * alone, so that neither the SLP's start, the mechanism nor a
	 * `numerical` verdict depends on the start.  Their optima are
	 * unique only to GLPK's tolerances on a few samples (a slip rate at
	 * the motion threshold, a virtual-work residual between 1e-8 and
	 * GLPK's 1e-7): measured on Ferris & Tin-Loi wall 2, seed 1, where
	 * 7 of 1,000 samples had another mechanism or status from another
	 * start (docs/method.md, "The SLP's answer").  LP-max's optimal
	 * face, read off its reduced costs, and its optimum's last digits
	 * depend on the vertex the simplex ends at: the demo, seed 1,
	 * sample 1628 was `not_converged` from `previous` only, and on
	 * walls of 600+ interfaces the two simplex methods' optima part by
	 * up to 8e-7 of themselves (docs/method.md, "The SLP's start").
	 * The start option still drives the standing check and the SLP's
	 * LP1 and LP2, where most of a sample's pivots are.  The onset's
	 * mechanism then starts from the basis complementary to LP1's last
	 * (sample_onset.c, kin_from_lp1), which the start option reaches
	 * only through LP1's optimum: the same status and lambda_min from
	 * every start and thread count on 2,000 samples of each of the
	 * three walls at three seeds (docs/method.md, "LP-max, the
	 * mechanism and LP-min on one fixed path"); KIN's start here is
	 * the patterns' (sample_pattern). */
	int fixed = p == AMAX || p == KIN || p == AMIN;
	if (ws->start != SAMPLE_START_AUTO && !fixed)
		return ws->start;
	if (ws->large && p == LP2)
		return SAMPLE_START_SLACK_PRIMAL;
	/* the standing check from the support basis on every wall: it is
	 * primal feasible at lambda = 0 wherever each block finds its
	 * support triple, so the check needs no pivot, where from the
	 * canonical basis it took 14.9 pivots on Ferris & Tin-Loi wall 1
	 * and 178.5 on tests/data/body-195.yaml (docs/performance.md, "The
	 * standing check from the support basis, and LP-min by shifted
	 * costs"); its answer is a verdict, feasible or not, and no field,
	 * so the start cannot move a sample.  A large wall's canonical
	 * sample starts LP-max from it too: it has no canonical basis yet
	 * (it would start from the slack basis); its LP-min, where it runs
	 * one, starts from LP-max's optimum (sample.c, setup_large) */
	if (p == STAND || (ws->large && ws->setup && p == AMAX))
		return SAMPLE_START_SUPPORT;
	return SAMPLE_START_CANONICAL;
}

/* LP-max's simplex method, the other half of its one fixed path (its
 * start is sws_role_start's): the dual simplex from the canonical basis,
 * the primal on large walls, where the dual takes 20,744 pivots from
 * the canonical basis against the primal's 2,308 (the comment above). */
enum lp_method sws_lp_max_method(const struct sample_ws *ws)
{
	return ws->large ? LP_PRIMAL : LP_DUAL;
}

/* Choose every problem's starting basis (the start option): with the
 * tie-breaks a sample is a function of its draw alone, whatever the
 * start (tests/unit/test_start.c checks it); the start only decides how
 * many pivots it takes.  The default, `auto` (sws_role_start), is a
 * function of the wall alone.  Called after the sample's draw was
 * written into the problems (sample.c, set_points). */
void sws_start_bases(struct sample_ws *ws)
{
	int support = -1;	/* support_basis's verdict, once computed */
	for (int p = 0; p < ROLES; p++) {
		switch (sws_role_start(ws, p)) {
		case SAMPLE_START_SUPPORT:
			if (p == LP1 || p == LP2 || p == KIN) {
				lp_reset_basis(ws->lp[p]);
				break;
			}
			if (support == -1)
				support = support_basis(&ws->st, ws->basic) >= 0;
			/* a wall with a block that rests on no joint (an
			 * opening without a lintel) has no support basis:
			 * the canonical basis then, where there is one (on
			 * tests/data/opening-nolintel.yaml, seed 1, the
			 * standing check took 327.2 pivots an LP from it and
			 * 1,199.3 from the slack basis), and the slack basis
			 * in the set-up */
			if (support)
				lp_set_basis(ws->lp[p], ws->basic);
			else if (ws->canon[p].n)
				lp_basis_load(ws->lp[p], &ws->canon[p]);
			else
				lp_reset_basis(ws->lp[p]);
			break;
		case SAMPLE_START_SLACK_PRIMAL:
		case SAMPLE_START_SLACK_DUAL:
			lp_reset_basis(ws->lp[p]);
			break;
		case SAMPLE_START_CRASH:
			lp_crash_basis(ws->lp[p]);
			break;
		case SAMPLE_START_CANONICAL:
			lp_basis_load(ws->lp[p], &ws->canon[p]);
			break;
		default:
			break;
		}
	}
}
