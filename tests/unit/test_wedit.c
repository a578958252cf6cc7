/*
 * test_wedit.c - the edits of a wall without a terminal (wedit.h): the
 * copy finishes to the same wall, a skipped block is gone, a removed
 * block of the courses comes back with its id and its place, a new block
 * sits on the layout's grid, a layout change regenerates the courses and
 * brings the load back onto the wall, and the load's stations lie on the
 * outline: never on an edge that rests on the ground.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "slipwall/wedit.h"
#include "slipwall/layout.h"
#include "slipwall/wallfile.h"
#include "tap.h"

static struct wall *load(const char *path)
{
	char err[SW_ERRLEN];
	struct wall *w;
	if (wallfile_load(path, &w, err) != SW_OK) {
		tap_diag("%s", err);
		exit(1);
	}
	return w;
}

/* Finish c (taking it); NULL with a diagnostic when it does not. */
static struct wall *finish(struct wall *c)
{
	char err[SW_ERRLEN];
	if (!c)
		return NULL;
	if (wall_finish(c, err) != SW_OK) {
		tap_diag("%s", err);
		wall_free(c);
		return NULL;
	}
	return c;
}

static int on_outline(double x, double y)
{
	return (fabs(x) < 1e-9 || fabs(x - 0.4) < 1e-9) ? y > 0 && y <= 0.8
	       : fabs(y - 0.8) < 1e-9 && x >= 0 && x <= 0.4;
}

static void test_copy(const struct wall *w)
{
	char err[SW_ERRLEN];
	struct wall *c = finish(wedit_copy(w, NULL, -1, err));
	tap_ok(c && c->nblocks == w->nblocks && c->nifaces == w->nifaces &&
	       c->mu_bed == w->mu_bed && c->loads[0].at[1] == w->loads[0].at[1],
	       "a copy finishes to the same wall (%d blocks, %d interfaces)",
	       c ? c->nblocks : -1, c ? c->nifaces : -1);
	int bad = 0;
	for (int k = 0; c && k < c->nblocks; k++)
		bad += strcmp(c->blocks[k].id, w->blocks[k].id) != 0;
	tap_ok(c && !bad, "the copy keeps every block's id and order");
	wall_free(c);
}

static void test_block_at(const struct wall *w)
{
	int bad = 0;
	for (int k = 0; k < w->nblocks; k++)
		if (k != w->ground_block &&
		    wedit_block_at(w, w->blocks[k].cx, w->blocks[k].cy) != k)
			bad++;
	tap_ok(!bad, "each block's centroid finds that block (%d wrong)", bad);
	tap_ok(wedit_block_at(w, 0.3, -0.05) == -1,
	       "the generated ground is never a block under the cursor");
	tap_ok(wedit_block_at(w, 5, 5) == -1, "off the wall: no block");
}

/* Remove the block at the top left, then add it back at its place. */
static void test_remove_restore(const struct wall *w)
{
	char err[SW_ERRLEN], what[128];
	int k = wedit_block_at(w, 0.05, 1.15);
	tap_ok(k >= 0, "a block at the top course (%s)", k >= 0 ? w->blocks[k].id : "-");
	if (k < 0)
		return;
	struct wall *r = finish(wedit_copy(w, NULL, k, err));
	tap_ok(r && r->nblocks == w->nblocks - 1 && wedit_block_at(r, 0.05, 1.15) < 0,
	       "skip leaves that block out");
	if (!r)
		return;
	struct wall *b = finish(wedit_add_block(r, 0.05, 1.15, what, sizeof what, err));
	tap_ok(b && b->nblocks == w->nblocks && !strcmp(b->blocks[k].id, w->blocks[k].id),
	       "a block added there is the removed one, at index %d (%s)", k, what);
	char want[64];
	snprintf(want, sizeof want, "block %s restored", w->blocks[k].id);
	tap_ok(b && !strcmp(what, want) &&
	       b->blocks[k].cx == w->blocks[k].cx && b->blocks[k].cy == w->blocks[k].cy,
	       "in its place: %s", what);
	wall_free(b);
	wall_free(r);
}

static void test_new_block(const struct wall *w)
{
	char err[SW_ERRLEN], what[128];
	struct wall *b = finish(wedit_add_block(w, 0.25, 1.28, what, sizeof what, err));
	int k = b ? wedit_block_at(b, 0.3, 1.25) : -1;
	tap_ok(k >= 0 && b->nblocks == w->nblocks + 1 && !strcmp(b->blocks[k].id, "u1"),
	       "a block above the wall is a new one, u1 (%s)", what);
	/* the grid: half a block (0.1 m) across, a course (0.15 m) up */
	tap_ok(k >= 0 && fabs(b->blocks[k].xy[0] - 0.2) < 1e-12 &&
	       fabs(b->blocks[k].xy[1] - 1.2) < 1e-12 &&
	       fabs(b->blocks[k].xy[4] - 0.4) < 1e-12 &&
	       fabs(b->blocks[k].xy[5] - 1.35) < 1e-12,
	       "on the layout's grid: (0.2, 1.2) to (0.4, 1.35)");
	if (b) {
		struct wall *b2 = finish(wedit_add_block(b, 0.45, 1.28, what,
						       sizeof what, err));
		int k2 = b2 ? wedit_block_at(b2, 0.5, 1.25) : -1;
		tap_ok(k2 >= 0 && !strcmp(b2->blocks[k2].id, "u2"),
		       "the next one is u2 (%s)", what);
		wall_free(b2);
	}
	wall_free(b);
}

static void test_layout(const struct wall *w)
{
	char err[SW_ERRLEN];
	struct wall_layout lay = w->layout;
	struct wall_mark none = {0, 0};
	lay.courses = 3;
	struct wall *g = wall_new();
	g->layout = lay;
	int n = layout_generate(g, none, err) == SW_OK ? g->nblocks : -1;
	wall_free(g);
	struct wall *c = finish(wedit_layout(w, &lay, err));
	tap_ok(c && c->nblocks == n + 1,
	       "3 courses: the layout's %d blocks and the ground (%d)", n,
	       c ? c->nblocks : -1);
	/* the load was at y = 0.525, above the 0.45 m of three courses;
	 * wall_finish refuses a load off the wall */
	tap_ok(c && c->loads[0].at[1] <= 0.45 + 1e-9 &&
	       c->loads[0].at[1] > 0.3,
	       "the load moved onto the lower wall (%.3g, %.3g)",
	       c ? c->loads[0].at[0] : NAN, c ? c->loads[0].at[1] : NAN);
	wall_free(c);
}

/* Step the load until it stops; returns the steps taken. */
static int walk(const struct wall *w, int dx, int dy, double at[2], int *off)
{
	int n = 0;
	while (n < 100 && wedit_load_step(w, dx, dy, at)) {
		*off += !on_outline(at[0], at[1]);
		n++;
	}
	return n;
}

static void test_stations(const struct wall *s)
{
	double at[2] = {0, 0.6};
	int off = 0;
	int up = walk(s, 0, 1, at, &off);
	tap_ok(up >= 1 && fabs(at[1] - 0.8) < 1e-9,
	       "up: %d steps to the top (%.3g, %.3g)", up, at[0], at[1]);
	int down = walk(s, 0, -1, at, &off);
	tap_ok(down >= 1 && at[1] > 0,
	       "down: %d steps, never onto the edge on the ground (y %.3g)",
	       down, at[1]);
	at[0] = 0;
	int right = walk(s, 1, 0, at, &off);
	tap_ok(right >= 1 && fabs(at[0] - 0.4) < 1e-9,
	       "right: %d steps to the right face (%.3g)", right, at[0]);
	tap_ok(off == 0, "every station is on the outline (%d off)", off);
	double p[2] = {0.2, 0.79}, h[2] = {1, 0}, v[2] = {0, -1};
	int found = wedit_load_nearest(s, h, p);
	tap_ok(found && (fabs(p[0]) < 1e-9 || fabs(p[0] - 0.4) < 1e-9),
	       "a horizontal load goes to a side face (%.3g, %.3g)", p[0], p[1]);
	p[0] = 0.2;
	p[1] = 0.79;
	found = wedit_load_nearest(s, v, p);
	tap_ok(found && fabs(p[1] - 0.8) < 1e-9,
	       "a vertical one to the top (%.3g, %.3g)", p[0], p[1]);
}

static void test_cursor_turn(const struct wall *s)
{
	double bw, bh, x = 0.2, y = 0.4;
	wedit_block_size(s, &bw, &bh);
	for (int i = 0; i < 100; i++)
		wedit_cursor(s, &x, &y, 1, -1);
	tap_ok(fabs(x - (0.4 + bw)) < 1e-12 && fabs(y) < 1e-12,
	       "the cursor stops a block right of the wall, at its foot (%.3g, %.3g)",
	       x, y);
	double box[4];
	wedit_bounds(s, 1, box);
	tap_ok(box[0] == 0 && box[1] == 0 && box[2] == 0.4 && box[3] == 0.8,
	       "the free blocks' box (%g, %g) - (%g, %g)", box[0], box[1],
	       box[2], box[3]);
	double d[2] = {1, 0};
	wedit_turn(d, 1);
	tap_ok(fabs(d[0] - sqrt(0.5)) < 1e-12 && fabs(d[1] - sqrt(0.5)) < 1e-12,
	       "an eighth of a turn counter-clockwise");
	wedit_turn(d, -3);
	tap_ok(d[0] == 0 && d[1] == -1, "three back: straight down (%g, %g)",
	       d[0], d[1]);
}

/* ---- saving over the opened file keeps its comments (issue 23) ---- */

static char *slurp(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	char *buf = NULL;
	*len = 0;
	if (!f)
		return NULL;
	buf = malloc(1 << 20);
	*len = fread(buf, 1, (1 << 20) - 1, f);
	buf[*len] = 0;
	fclose(f);
	return buf;
}

/* How many lines of a are not lines of b (each line of b matches once). */
static int lines_lost(const char *a, const char *b)
{
	char *bb = strdup(b), *save = NULL;
	int lost = 0;
	char *ac = strdup(a);
	for (char *l = strtok_r(ac, "\n", &save); l; l = strtok_r(NULL, "\n", &save)) {
		size_t n = strlen(l);
		char *p = bb;
		while ((p = strstr(p, l)) &&
		       !((p == bb || p[-1] == '\n') && (p[n] == '\n' || !p[n])))
			p++;
		if (p)
			p[0] = '\x01';	/* used */
		else
			lost++;
	}
	free(ac);
	free(bb);
	return lost;
}

/* Save edited (taking it) over path, a copy of the demo; the text saved,
 * and the wall it loads to in *back. */
static char *save_over(struct wall *edited, const char *path,
		       struct wall **back)
{
	char err[SW_ERRLEN];
	size_t len;
	*back = NULL;
	if (!edited)
		return NULL;
	if (wallfile_save(edited, path, err) != SW_OK) {
		tap_diag("save: %s", err);
		wall_free(edited);
		return NULL;
	}
	wall_free(edited);
	if (wallfile_load(path, back, err) != SW_OK)
		tap_diag("the saved file: %s", err);
	return slurp(path, &len);
}

static void test_save_keeps_comments(void)
{
	char err[SW_ERRLEN], dir[] = "/tmp/slipwall-keep-XXXXXX", path[64];
	size_t olen;
	char *orig = slurp(SRCDIR "/walls/demo.yaml", &olen);
	if (!orig || !mkdtemp(dir)) {
		tap_ok(0, "keep comments: set up");
		return;
	}
	snprintf(path, sizeof path, "%s/demo.yaml", dir);
	int ncomments = 0;
	for (const char *p = orig; (p = strchr(p, '#')); p++)
		ncomments += p == orig || p[-1] == '\n';

	/* friction, as f or the prompt makes it: one line changes */
	FILE *f = fopen(path, "wb");
	fwrite(orig, 1, olen, f);
	fclose(f);
	struct wall *w = load(path), *back;
	struct wall *c = finish(wedit_copy(w, NULL, -1, err));
	c->mu_bed = c->mu_head = 0.85;
	char *text = save_over(c, path, &back);
	tap_ok(text && lines_lost(orig, text) == 1 && strstr(text, "\n  friction: 0.85\n"),
	       "friction 0.8 -> 0.85 saved over the demo: its %d comment lines "
	       "and every other line kept, 'friction: 0.85' in place", ncomments);
	tap_ok(back && back->mu_bed == 0.85 && back->mu_head == 0.85,
	       "the saved demo loads with friction 0.85");
	if (text && lines_lost(orig, text) != 1)
		tap_diag("saved:\n%s", text);
	wall_free(back);
	free(text);

	/* more edits over that file: a default that changes (positions),
	 * a block removed (omit), bed and head apart, fewer courses */
	wall_free(w);
	w = load(path);
	c = finish(wedit_copy(w, NULL, -1, err));
	c->anywhere = 1;
	c->depth = 0.3;
	c->mu_head = 0.5;
	text = save_over(c, path, &back);
	tap_ok(text && lines_lost(orig, text) == 2 &&
	       back && back->anywhere && back->depth == 0.3 &&
	       back->mu_bed == 0.85 && back->mu_head == 0.5,
	       "positions anywhere, depth 0.3, head 0.5: loads so, only the "
	       "friction and depth lines differ from the demo (positions added)");
	if (text && lines_lost(orig, text) != 2)
		tap_diag("saved:\n%s", text);
	free(text);
	wall_free(w);
	w = back;
	int k = wedit_block_at(w, 0.3, 1.1);
	c = finish(wedit_copy(w, NULL, k, err));
	text = save_over(c, path, &back);
	tap_ok(text && k >= 0 && lines_lost(orig, text) == 2 &&
	       strstr(text, "omit:") && back && back->nblocks == w->nblocks - 1,
	       "a block removed: 'omit:' added to the layout, every comment kept");
	if (text && lines_lost(orig, text) != 2)
		tap_diag("saved:\n%s", text);
	free(text);
	wall_free(w);
	wall_free(back);
	free(orig);

	/* a wall of explicit blocks: a block added is one line more, and
	 * taking it out again gives the file back byte for byte */
	orig = slurp(SRCDIR "/walls/two-block-stack.yaml", &olen);
	f = fopen(path, "wb");
	fwrite(orig, 1, olen, f);
	fclose(f);
	w = load(path);
	char what[96];
	c = finish(wedit_add_block(w, 0.6, 0.1, what, sizeof what, err));
	text = save_over(c, path, &back);
	int nl0 = 0, nl1 = 0;
	for (const char *p = orig; *p; p++)
		nl0 += *p == '\n';
	for (const char *p = text ? text : ""; *p; p++)
		nl1 += *p == '\n';
	tap_ok(text && lines_lost(orig, text) == 0 && nl1 == nl0 + 1 &&
	       back && back->nblocks == w->nblocks + 1,
	       "two-block-stack + a block: every line kept, one line more "
	       "(%d -> %d)", nl0, nl1);
	free(text);
	wall_free(w);
	w = back;
	int u = w ? wedit_block_at(w, 0.8, 0.1) : -1;
	c = u >= 0 ? finish(wedit_copy(w, NULL, u, err)) : NULL;
	text = save_over(c, path, &back);
	tap_ok(text && !strcmp(text, orig),
	       "and without it again: the file as it was, byte for byte");
	free(text);
	wall_free(w);
	wall_free(back);
	free(orig);
	unlink(path);
	rmdir(dir);
}

int main(void)
{
	struct wall *w = load(SRCDIR "/walls/demo.yaml");
	struct wall *s = load(SRCDIR "/walls/single-block.yaml");
	tap_ok(wedit_point_load(w) == 0, "demo's point load is load 0");
	test_copy(w);
	test_block_at(w);
	test_remove_restore(w);
	test_new_block(w);
	test_layout(w);
	test_stations(s);
	test_cursor_turn(s);
	test_save_keeps_comments();
	wall_free(w);
	wall_free(s);
	return tap_done();
}
