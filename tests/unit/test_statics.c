/*
 * test_statics.c - the equilibrium operator and its transpose: known
 * entries, rigid motions give no joint motion, and a block resting on
 * the ground is in equilibrium with half its weight at each corner.
 */
#include <math.h>
#include <stdlib.h>

#include "statics.h"
#include "tap.h"
#include "walls.h"

int main(void)
{
	/* a block b x h on the ground */
	struct wall *w = tw_block(0.6);
	tw_finish(w);
	struct statics s;
	statics_init(&s, w);
	double W = w->total_weight, F = s.F, L = s.L;
	tap_near(F, W, 1e-15, "force scale = the mean block weight");
	tap_near(L, sqrt(0.32), 1e-15, "length scale = sqrt(mean area)");
	tap_near(s.S, W, 1e-15, "load-factor scale: F / (1 N)");
	/* N at both ends = W/2, T = 0: A x + f_D = 0 (scaled: W/2F = 0.5) */
	double x[3] = {0.5, 0.5, 0}, r[3] = {0};
	for (int j = 0; j < 3; j++) {
		int rows[6];
		double vals[6];
		int n = statics_column(&s, j, rows, vals);
		for (int i = 0; i < n; i++)
			r[rows[i]] += vals[i] * x[j];
	}
	int ok = 1;
	for (int i = 0; i < 3; i++)
		ok &= fabs(r[i] + s.fD[i]) < 1e-15;
	tap_ok(ok, "half the weight at each corner balances the block");
	/* the interface is a = block, b = ground, n pointing down: the ground
	 * pushes the block up, so N enters the block's row with -n_y = +1 */
	int rows[6];
	double vals[6];
	int n = statics_column(&s, 0, rows, vals);
	tap_ok(n == 3 && vals[1] == 1, "N on the block's y row: +1 (ground pushes up)");
	/* moment of N at the left corner (0, 0) about the centroid (0.2, 0.4):
	 * (p - c) x (0, 1) = -0.2, scaled by L */
	tap_near(vals[2] * L, -0.2, 1e-15, "moment arm of the left corner");
	/* f_L: 1 N at (0, 0.6): moment (0 - 0.2, 0.6 - 0.4) x (1, 0) = -0.2 */
	tap_near(s.fL[0] * F / s.S, 1, 1e-15, "live load x");
	tap_near(s.fL[2] * F * L / s.S, -0.2, 1e-15, "live load moment");
	/* overturning to the right: a clockwise rotation (omega < 0) about
	 * the right corner (0.4, 0), whose velocity is zero:
	 * u = omega (y0 - yc)... u - omega (0 - 0.4) = 0, v + omega (0.4 - 0.2) = 0 */
	double v[3];
	double om = -1;
	v[0] = om * (0 - 0.4);
	v[1] = -om * (0.4 - 0.2);
	v[2] = om * L;					/* scaled omega */
	struct sample_draw d;	/* the classical contact: xi = 0, 1 */
	draw_init(&d, w);
	draw_mean(&d, w);
	statics_set_draw(&s, &d);
	draw_free(&d);
	tap_near(statics_rate(&s, 1, v), 0, 1e-15, "hinging about q_b: no motion at q_b");
	tap_ok(statics_rate(&s, 0, v) > 0, "... and the left corner q_a lifts off (%.3g)", statics_rate(&s, 0, v));
	statics_free(&s);
	wall_free(w);

	/* a whole wall translating together: joints between blocks do not
	 * move, joints with the ground slide by the translation */
	w = tw_load_file("walls/ferris-tinloi-1.yaml");
	statics_init(&s, w);
	double *vv = calloc((size_t)s.nrows, sizeof(double));
	for (int i = 0; i < s.nrows; i += 3) {
		vv[i] = 1;
		vv[i + 1] = 0.5;
	}
	double inner = 0, ground = 0;
	for (int k = 0; k < w->nifaces; k++) {
		int fixed = w->blocks[w->ifaces[k].a].fixed || w->blocks[w->ifaces[k].b].fixed;
		for (int e = 0; e < 3; e++) {
			double rt = statics_rate(&s, 3 * k + e, vv);
			if (fixed)
				ground = fmax(ground, fabs(rt));
			else
				inner = fmax(inner, fabs(rt));
		}
	}
	tap_ok(inner < 1e-14, "rigid translation: no relative motion inside (%.3g)", inner);
	tap_near(ground, 1, 1e-14, "rigid translation: the ground joints slide by 1 (largest rate)");
	free(vv);
	statics_free(&s);
	wall_free(w);
	/* a load near the top of the doubles at a lever of metres (found by
	 * the fuzzer): the forces are divided by the mean reference load
	 * before the lever multiplies them, so the moment is finite and
	 * exact: 1.5e308 N at (0, 0.6) on a 0.4 x 8 block, centroid
	 * (0.2, 4), is 2 (scaled) with a moment -(0.6 - 4) / L x 2 */
	w = wall_new();
	tw_rect(w, "A", 0, 0, 0.4, 8);
	w->has_ground = 1;
	tw_point_load(w, 0, 0.6, 1, 0);
	tw_point_load(w, 0, 0.5, 1, 0);
	w->loads[0].magnitude = 1.5e308;
	w->loads[1].magnitude = 1.5e208;
	tw_finish(w);
	statics_init(&s, w);
	ok = 1;
	for (int i = 0; i < s.nrows; i++)
		ok &= isfinite(s.fL[i]);
	tap_ok(ok, "a load of 1.5e308 N at a lever of 3.4 m: f_L finite");
	tap_near(s.fL[0], 2, 1e-15, "... its force over the mean reference load: 2");
	tap_near(s.fL[2] * s.L, 3.4 * 2, 1e-14, "... its moment: 3.4 m x 2");
	statics_free(&s);
	wall_free(w);
	return tap_done();
}
