/*
 * test_layout.c - the layout generator: block counts, joint positions,
 * cut blocks, ids, rejections; and, through wall_finish, the weights and
 * the interfaces of the Ferris & Tin-Loi walls, counted by hand.
 */
#include <stdlib.h>
#include <string.h>

#include "slipwall/geom.h"
#include "slipwall/layout.h"
#include "slipwall/wall.h"
#include "tap.h"

static struct wall *make(double bw, double bh, int courses, double length,
			 enum bond_kind bond, int first_half)
{
	struct wall *w = wall_new();
	w->path = sw_xstrdup("test.yaml");
	w->layout.present = 1;
	w->layout.block_w = bw;
	w->layout.block_h = bh;
	w->layout.courses = courses;
	w->layout.length = length;
	w->layout.bond = bond;
	w->layout.first_half = first_half;
	return w;
}

static struct wall_mark mark(int line, int col)
{
	struct wall_mark m = {line, col};
	return m;
}

static double width(const struct wall_block *b)
{
	return b->xy[2] - b->xy[0];
}

static int find(const struct wall *w, const char *id)
{
	for (int k = 0; k < w->nblocks; k++)
		if (!strcmp(w->blocks[k].id, id))
			return k;
	return -1;
}

/* Blocks in course c: ids "c<c>b...". */
static int count_course(const struct wall *w, int c)
{
	char pre[16];
	int n = 0;
	snprintf(pre, sizeof pre, "c%db", c);
	for (int k = 0; k < w->nblocks; k++)
		n += !strncmp(w->blocks[k].id, pre, strlen(pre));
	return n;
}

static void test_cut_course(void)
{
	char err[SW_ERRLEN];
	enum sw_status st;
	/* length 0.80 of 0.20 blocks, half start: 0.1 + 3 * 0.2 + 0.1 */
	struct wall *w = make(0.2, 0.1, 2, 0.8, BOND_RUNNING, 1);
	tap_ok(layout_generate(w, mark(3, 9), err) == SW_OK, "0.80 wall generates");
	tap_ok(count_course(w, 1) == 5, "half course of 0.80 holds 5 blocks (got %d)",
	       count_course(w, 1));
	tap_ok(count_course(w, 2) == 4, "full course of 0.80 holds 4 blocks (got %d)",
	       count_course(w, 2));
	static const double want[5] = {0.1, 0.2, 0.2, 0.2, 0.1};
	for (int k = 0; k < 5; k++) {
		char id[16], name[64];
		snprintf(id, sizeof id, "c1b%d", k + 1);
		snprintf(name, sizeof name, "c1b%d is %.1f wide", k + 1, want[k]);
		int i = find(w, id);
		tap_near(i >= 0 ? width(&w->blocks[i]) : -1, want[k], 1e-12, "%s", name);
	}
	int i = find(w, "c1b1");
	tap_ok(i == 0, "c1b1 is the first block");
	/* counter-clockwise from the lower-left corner */
	static const double ll[8] = {0, 0, 0.1, 0, 0.1, 0.1, 0, 0.1};
	int same = i >= 0 && w->blocks[i].nv == 4;
	for (int k = 0; same && k < 8; k++)
		same = fabs(w->blocks[i].xy[k] - ll[k]) < 1e-15;
	tap_ok(same, "c1b1 = (0,0) (0.1,0) (0.1,0.1) (0,0.1), counter-clockwise");
	tap_ok(geom_area(w->blocks[0].xy, 4) > 0, "c1b1 has positive signed area");
	i = find(w, "c2b4");
	tap_ok(i >= 0 && fabs(w->blocks[i].xy[0] - 0.6) < 1e-12 &&
		       fabs(w->blocks[i].xy[2] - 0.8) < 1e-12 &&
		       fabs(w->blocks[i].xy[1] - 0.1) < 1e-12 &&
		       fabs(w->blocks[i].xy[5] - 0.2) < 1e-12,
	       "c2b4 spans x 0.6..0.8, y 0.1..0.2");
	tap_ok(w->blocks[0].mark.line == 3 && w->blocks[0].mark.col == 9 &&
		       w->blocks[0].fixed == 0,
	       "generated blocks carry the layout's mark and are free");
	wall_free(w);

	/* length 0.50, full start: 0.2 + 0.2 + a cut 0.1; course 2 half:
	 * 0.1 + 0.2 + 0.2 */
	w = make(0.2, 0.1, 2, 0.5, BOND_RUNNING, 0);
	layout_generate(w, mark(0, 0), err);
	tap_ok(w->nblocks == 6, "0.50 wall of 2 courses: 3 + 3 blocks (got %d)",
	       w->nblocks);
	i = find(w, "c1b3");
	tap_near(i >= 0 ? width(&w->blocks[i]) : -1, 0.1, 1e-12,
		 "full-start course ends with a 0.1 cut block");
	i = find(w, "c2b1");
	tap_near(i >= 0 ? width(&w->blocks[i]) : -1, 0.1, 1e-12,
		 "course 2 starts with a half block");
	i = find(w, "c2b3");
	tap_near(i >= 0 ? width(&w->blocks[i]) : -1, 0.2, 1e-12,
		 "course 2 ends with a full block (0.1 + 0.2 + 0.2 = 0.5)");
	wall_free(w);

	/* length exactly half a block: one half block per course, whatever
	 * the start */
	w = make(0.4, 0.1, 2, 0.2, BOND_RUNNING, 1);
	st = layout_generate(w, mark(0, 0), err);
	tap_ok(st == SW_OK && w->nblocks == 2,
	       "length = half a block: one block per course (got %d)", w->nblocks);
	tap_near(width(&w->blocks[1]), 0.2, 1e-12,
		 "the full-start course is one 0.2 cut block");
	wall_free(w);

	/* a cut narrower than 1e-4 of a block is no block: length
	 * 0.40000001 with 0.2 blocks is 0.40 (it made a 1e-8 m block that
	 * no joint carried); a cut of 1e-4 m (5e-4 of a block) stays (the
	 * half-start course 0.1 + 0.2 + 0.1001, the full one 0.2 + 0.2 +
	 * 1e-4) */
	w = make(0.2, 0.1, 2, 0.40000001, BOND_RUNNING, 1);
	st = layout_generate(w, mark(0, 0), err);
	tap_ok(st == SW_OK && w->nblocks == 5,
	       "length 0.40000001: 3 + 2 blocks, no sliver (got %d)", w->nblocks);
	i = find(w, "c2b2");
	tap_near(i >= 0 ? width(&w->blocks[i]) : -1, 0.20000001, 1e-12,
		 "the last block reaches the wall's end");
	wall_free(w);
	w = make(0.2, 0.1, 2, 0.4001, BOND_RUNNING, 1);
	st = layout_generate(w, mark(0, 0), err);
	tap_ok(st == SW_OK && w->nblocks == 6,
	       "length 0.4001: 3 + 3 blocks (got %d)", w->nblocks);
	i = find(w, "c2b3");
	tap_near(i >= 0 ? width(&w->blocks[i]) : -1, 1e-4, 1e-12,
		 "the full-start course ends with a 1e-4 m cut block");
	wall_free(w);
}

static void test_ferris_counts(void)
{
	char err[SW_ERRLEN];
	/* Ferris & Tin-Loi wall 1: 0.40 blocks, length 2.0, half start.
	 * Half courses: 0.2 + 4 * 0.4 + 0.2 = 6 blocks; full courses 5.
	 * 6 courses: 3 * 6 + 3 * 5 = 33. */
	struct wall *w = make(0.4, 0.175, 6, 2.0, BOND_RUNNING, 1);
	layout_generate(w, mark(1, 1), err);
	tap_ok(w->nblocks == 33, "Ferris & Tin-Loi wall 1 has 33 blocks (got %d)",
	       w->nblocks);
	tap_ok(count_course(w, 1) == 6 && count_course(w, 2) == 5 &&
		       count_course(w, 6) == 5,
	       "courses of 6 and 5 blocks alternate, course 1 has 6");
	int i = find(w, "c1b2");
	tap_near(i >= 0 ? w->blocks[i].xy[0] : -1, 0.2, 1e-12,
		 "first full block of course 1 starts at x = 0.2 (half offset)");
	i = find(w, "c6b1");
	tap_near(i >= 0 ? w->blocks[i].xy[1] : -1, 5 * 0.175, 1e-12,
		 "course 6 sits at y = 5 * 0.175 = 0.875");
	tap_near(i >= 0 ? w->blocks[i].xy[5] : -1, 1.05, 1e-12,
		 "the wall is 6 * 0.175 = 1.05 m high");
	wall_free(w);

	/* wall 2, 10 courses: 5 * 6 + 5 * 5 = 55 */
	w = make(0.4, 0.175, 10, 2.0, BOND_RUNNING, 1);
	layout_generate(w, mark(1, 1), err);
	tap_ok(w->nblocks == 55, "Ferris & Tin-Loi wall 2 has 55 blocks (got %d)",
	       w->nblocks);
	wall_free(w);
}

static void test_stack(void)
{
	char err[SW_ERRLEN];
	/* stack bond, full start: 5 blocks of 0.2 in 1.0, every course */
	struct wall *w = make(0.2, 0.1, 3, 1.0, BOND_STACK, 0);
	layout_generate(w, mark(0, 0), err);
	tap_ok(w->nblocks == 15, "stack bond 3 x 5 = 15 blocks (got %d)",
	       w->nblocks);
	int a = find(w, "c1b3"), b = find(w, "c3b3");
	tap_ok(a >= 0 && b >= 0 && w->blocks[a].xy[0] == w->blocks[b].xy[0] &&
		       w->blocks[a].xy[2] == w->blocks[b].xy[2],
	       "stack bond: head joints line up exactly");
	wall_free(w);
	/* the limit counts the blocks, not a bound on them: a column of
	 * 40,000 blocks as wide as the wall is 40,000 blocks (the bound,
	 * length / width + 2 a course, said 120,000 and refused it) */
	w = make(0.2, 0.1, 40000, 0.2, BOND_STACK, 0);
	tap_ok(layout_generate(w, mark(0, 0), err) == SW_OK &&
	       w->nblocks == 40000, "a stack of 40,000 blocks: made (%d)",
	       w->nblocks);
	wall_free(w);
	/* stack bond, half start: 0.1 + 4 * 0.2 + 0.1 = 6 per course */
	w = make(0.2, 0.1, 3, 1.0, BOND_STACK, 1);
	layout_generate(w, mark(0, 0), err);
	tap_ok(w->nblocks == 18, "stack bond with half start: 3 x 6 = 18 (got %d)",
	       w->nblocks);
	wall_free(w);
}

static void test_origin(void)
{
	char err[SW_ERRLEN];
	struct wall *w = make(0.2, 0.1, 2, 0.4, BOND_RUNNING, 1);
	w->layout.x0 = 1.5;
	w->layout.y0 = -2;
	layout_generate(w, mark(0, 0), err);
	tap_ok(w->blocks[0].xy[0] == 1.5 && w->blocks[0].xy[1] == -2,
	       "origin moves the lower-left corner to (1.5, -2)");
	int i = find(w, "c2b2");
	tap_near(i >= 0 ? w->blocks[i].xy[2] : -1, 1.9, 1e-12,
		 "the wall ends at x0 + length = 1.9");
	wall_free(w);
}

static void test_reject(void)
{
	static const struct {
		double bw, bh;
		int courses;
		double length;
		const char *msg;
	} bad[] = {
		{0, 0.1, 2, 1, "block size"},
		{0.2, -0.1, 2, 1, "block size"},
		{NAN, 0.1, 2, 1, "block size"},
		{0.2, 0.1, 0, 1, "at least 1 course"},
		{0.2, 0.1, 2, 0.09, "shorter than half a block"},
		{0.2, 0.1, 2, INFINITY, "length must be a finite number"},
		{0.001, 0.1, 1000, 10, "would make 10000500 blocks"},
		{1e-300, 0.1, 2, 10, "more than 100000 blocks in one course"},
	};
	for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
		char err[SW_ERRLEN] = "";
		struct wall *w = make(bad[k].bw, bad[k].bh, bad[k].courses,
				      bad[k].length, BOND_RUNNING, 1);
		enum sw_status st = layout_generate(w, mark(4, 3), err);
		tap_ok(st == SW_EINPUT && w->nblocks == 0 &&
			       !strncmp(err, "test.yaml:4:3: ", 15) &&
			       strstr(err, bad[k].msg),
		       "rejects case %zu with '%s' at the mark", k, bad[k].msg);
		if (st != SW_EINPUT || !strstr(err, bad[k].msg))
			tap_diag("got %d: %s", st, err);
		wall_free(w);
	}
}

/* The derived quantities need wall_finish (wall.c and geom.c). */
static void test_finished(void)
{
	char err[SW_ERRLEN];
	struct wall_load body = {.kind = LOAD_BODY, .dir = {1, 0},
				 .magnitude = 1, .block = -1};

	/* demo-like wall: 0.2 x 0.1 blocks, gamma 19620, t 0.1:
	 * W = 19620 * 0.02 * 0.1 = 39.24 N; half blocks 19.62 N */
	struct wall *w = make(0.2, 0.1, 2, 0.8, BOND_RUNNING, 1);
	w->has_ground = 1;
	layout_generate(w, mark(0, 0), err);
	wall_add_load(w, &body);
	enum sw_status st = wall_finish(w, err);
	tap_ok(st == SW_OK, "0.80 wall finishes");
	if (st != SW_OK)
		tap_diag("%s", err);
	int i = find(w, "c1b2");
	tap_near(i >= 0 ? w->blocks[i].weight : 0, 39.24, 1e-12,
		 "a 0.2 x 0.1 block weighs 19620 * 0.02 * 0.1 = 39.24 N");
	i = find(w, "c1b1");
	tap_near(i >= 0 ? w->blocks[i].weight : 0, 19.62, 1e-12,
		 "the half block weighs 19.62 N");
	tap_near(i >= 0 ? w->blocks[i].cx : 0, 0.05, 1e-12, "half block centroid x = 0.05");
	tap_near(i >= 0 ? w->blocks[i].cy : 0, 0.05, 1e-12, "half block centroid y = 0.05");
	i = find(w, "c2b4");
	tap_near(i >= 0 ? w->blocks[i].cx : 0, 0.7, 1e-12, "c2b4 centroid x = 0.7");
	tap_near(i >= 0 ? w->blocks[i].cy : 0, 0.15, 1e-12, "c2b4 centroid y = 0.15");
	tap_near(w->total_weight, 19620 * 0.8 * 0.2 * 0.1, 1e-12,
		 "total weight = gamma * 0.8 * 0.2 * t = 313.92 N");
	wall_free(w);

	/* Ferris & Tin-Loi wall 1, interfaces counted by hand:
	 *  - head joints: blocks in the course - 1: three courses of 6
	 *    blocks (5 each) and three of 5 (4 each): 15 + 12 = 27;
	 *  - bed joints between courses: joints of a half course at
	 *    0.2 0.6 1.0 1.4 1.8, of a full course at 0.4 0.8 1.2 1.6; merged
	 *    they cut 0..2.0 into 10 pieces, each one overlapping pair, so
	 *    10 per course boundary and 5 boundaries: 50;
	 *  - ground: the 6 blocks of course 1.
	 * Total 27 + 50 + 6 = 83 (56 bed, 27 head). */
	w = make(0.4, 0.175, 6, 2.0, BOND_RUNNING, 1);
	w->has_ground = 1;
	w->mu_bed = w->mu_head = 0.65;
	w->unit_weight = 20000;
	w->thickness = 1;
	layout_generate(w, mark(0, 0), err);
	wall_add_load(w, &body);
	st = wall_finish(w, err);
	tap_ok(st == SW_OK, "Ferris & Tin-Loi wall 1 finishes");
	if (st != SW_OK)
		tap_diag("%s", err);
	int nbed = 0, nhead = 0, nground = 0;
	for (int k = 0; k < w->nifaces; k++) {
		nbed += w->ifaces[k].kind == JOINT_BED;
		nhead += w->ifaces[k].kind == JOINT_HEAD;
		nground += w->ifaces[k].a == w->ground_block ||
			   w->ifaces[k].b == w->ground_block;
	}
	tap_ok(w->nifaces == 83, "wall 1 has 83 interfaces (got %d)", w->nifaces);
	tap_ok(nbed == 56, "wall 1 has 56 bed joints (got %d)", nbed);
	tap_ok(nhead == 27, "wall 1 has 27 head joints (got %d)", nhead);
	tap_ok(nground == 6, "wall 1 has 6 ground contacts (got %d)", nground);
	tap_ok(w->nfree == 33, "wall 1 has 33 free blocks (got %d)", w->nfree);
	/* 2.0 x 1.05 m, 20000 N/m^3, 1 m: 42000 N */
	tap_near(w->total_weight, 42000, 1e-12, "wall 1 weighs 2.0 * 1.05 * 20000 = 42000 N");
	wall_free(w);

	/* wall 2 (10 courses): head 5 * 5 + 5 * 4 = 45, bed 9 * 10 = 90,
	 * ground 6: 141 */
	w = make(0.4, 0.175, 10, 2.0, BOND_RUNNING, 1);
	w->has_ground = 1;
	layout_generate(w, mark(0, 0), err);
	wall_add_load(w, &body);
	st = wall_finish(w, err);
	tap_ok(st == SW_OK && w->nifaces == 141,
	       "wall 2 has 45 + 90 + 6 = 141 interfaces (got %d)", w->nifaces);
	wall_free(w);
}

int main(void)
{
	test_cut_course();
	test_ferris_counts();
	test_stack();
	test_origin();
	test_reject();
	test_finished();
	return tap_done();
}
