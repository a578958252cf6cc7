/*
 * test_wallfile.c - reading and writing wall files: values, defaults,
 * marks, the bundled walls, hostile input, and save -> load round trips.
 * (The catalogue of malformed files is tests/bad/, run by
 * tests/cli/bad_walls.sh through the real binary.)
 */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "slipwall/wallfile.h"
#include "tap.h"

#ifndef SRCDIR
#define SRCDIR "."
#endif

static struct wall *parse(const char *text, char *err)
{
	struct wall *w = NULL;
	err[0] = '\0';
	if (wallfile_parse(text, strlen(text), "t.yaml", &w, err) != SW_OK)
		return NULL;
	return w;
}

static int find(const struct wall *w, const char *id)
{
	for (int k = 0; k < w->nblocks; k++)
		if (!strcmp(w->blocks[k].id, id))
			return k;
	return -1;
}

/* Does text fail with a message that starts with where and holds what? */
static void fails(const char *text, const char *where, const char *what,
		  const char *name)
{
	char err[SW_ERRLEN];
	struct wall *w = parse(text, err);
	int ok = !w && !strncmp(err, where, strlen(where)) && strstr(err, what);
	tap_ok(ok, "%s", name);
	if (!ok)
		tap_diag("want '%s...%s', got '%s'", where, what, err);
	wall_free(w);
}

static const char *small =
	"material: {friction: 0.6, unit_weight: 19620, thickness: 0.1}\n"
	"blocks:\n"
	"  - id: a\n"
	"    vertices: [[0, 0], [0.2, 0], [0.2, 0.1], [0, 0.1]]\n"
	"  - vertices: [[0.2, 0], [0.4, 0], [0.4, 0.1], [0.2, 0.1]]\n"
	"supports:\n"
	"  - ground: {y: 0}\n"
	"loads:\n"
	"  - point: {at: [0.4, 0.05], direction: [3, 4], magnitude: 2.5}\n"
	"  - body: {direction: [-1, 0]}\n";

static void test_values(void)
{
	char err[SW_ERRLEN];
	struct wall *w = parse(small, err);
	tap_ok(w != NULL, "a small wall parses");
	if (!w) {
		tap_diag("%s", err);
		return;
	}
	tap_ok(w->nblocks == 3 && w->nfree == 2,
	       "2 blocks + the ground (got %d, %d free)", w->nblocks, w->nfree);
	tap_ok(!strcmp(w->blocks[0].id, "a"), "the explicit id is kept");
	tap_ok(strcmp(w->blocks[1].id, "a") && w->blocks[1].id[0] != '\0',
	       "a block without id gets one ('%s')", w->blocks[1].id);
	tap_ok(w->blocks[0].mark.line == 3 && w->blocks[0].mark.col == 5,
	       "block a is marked at 3:5 (got %d:%d)", w->blocks[0].mark.line,
	       w->blocks[0].mark.col);
	tap_ok(w->blocks[1].mark.line == 5 && w->blocks[1].mark.col == 5,
	       "the second block is marked at 5:5");
	tap_ok(w->has_ground && w->ground_y == 0 && w->ground_block == 2,
	       "the ground support is the last block");
	tap_near(w->blocks[0].weight, 39.24, 1e-12,
		 "a 0.2 x 0.1 block of 19620 N/m^3, 0.1 m thick weighs 39.24 N");
	tap_near(w->blocks[1].cx, 0.3, 1e-12, "centroid x of the second block");
	tap_near(w->blocks[1].cy, 0.05, 1e-12, "centroid y of the second block");
	tap_ok(w->nloads == 2, "two loads");
	const struct wall_load *p = &w->loads[0], *b = &w->loads[1];
	tap_ok(p->kind == LOAD_POINT && p->at[0] == 0.4 && p->at[1] == 0.05,
	       "point load at (0.4, 0.05)");
	tap_near(p->dir[0], 0.6, 1e-15, "direction [3, 4] normalised: x = 0.6");
	tap_near(p->dir[1], 0.8, 1e-15, "direction [3, 4] normalised: y = 0.8");
	tap_ok(p->magnitude == 2.5, "magnitude 2.5");
	/* pushed into block 'a' at its right face? no: (0.4, 0.05) is on the
	 * right face of the second block, and [3, 4] points out of it. */
	tap_ok(p->block == 1, "the point load acts on the block that holds it (got %d)",
	       p->block);
	tap_ok(p->mark.line == 9 && p->mark.col == 17,
	       "the point load is marked at its 'at' (9:17, got %d:%d)",
	       p->mark.line, p->mark.col);
	tap_ok(b->kind == LOAD_BODY && b->dir[0] == -1 && b->dir[1] == 0 &&
		       b->magnitude == 1,
	       "body load [-1, 0], magnitude defaults to 1");
	tap_ok(!strcmp(w->path, "t.yaml") && w->name == NULL,
	       "path is the file name; no name");
	wall_free(w);
}

static void test_defaults(void)
{
	char err[SW_ERRLEN];
	struct wall *w = parse(
		"layout: {block: [0.2, 0.1], courses: 2, length: 0.4}\n"
		"supports: [{ground: {y: 0.5}}]\n"
		"loads: [{body: {direction: [1, 0]}}]\n", err);
	tap_ok(w != NULL, "a minimal wall parses");
	if (!w) {
		tap_diag("%s", err);
		return;
	}
	tap_ok(w->mu_bed == 0.6 && w->mu_head == 0.6, "friction defaults to 0.6");
	tap_ok(w->unit_weight == 19620, "unit weight defaults to 19620 N/m^3");
	tap_ok(w->thickness == 0.1, "thickness defaults to 0.10 m");
	tap_ok(w->depth == 0.25 && !w->anywhere, "contacts default to depth 0.25");
	tap_ok(w->samples == 1000 && w->seed == 1, "1000 samples, seed 1");
	tap_ok(w->ntests == 0, "no tests");
	tap_ok(w->layout.present && w->layout.bond == BOND_RUNNING &&
		       w->layout.first_half,
	       "layout: running bond, half first course by default");
	tap_ok(w->blocks[0].xy[1] == 0.5,
	       "without origin the layout stands on the ground (y = 0.5)");
	tap_ok(w->nfree == 5, "0.4 m of 0.2 blocks: 3 + 2 blocks (got %d)",
	       w->nfree);
	wall_free(w);
	/* a direction only points: one whose length overflows a double is
	 * still [1, 1] (it was "must be a non-zero vector") */
	w = parse("layout: {block: [0.2, 0.1], courses: 2, length: 0.4}\n"
		  "supports: [{ground: {y: 0}}]\n"
		  "loads: [{body: {direction: [1.7e308, 1.7e308]}}]\n", err);
	tap_ok(w && fabs(w->loads[0].dir[0] - M_SQRT1_2) < 1e-15 &&
	       fabs(w->loads[0].dir[1] - M_SQRT1_2) < 1e-15,
	       "direction [1.7e308, 1.7e308] is the unit vector along [1, 1]");
	if (!w)
		tap_diag("%s", err);
	wall_free(w);
}

static void test_settings(void)
{
	char err[SW_ERRLEN];
	struct wall *w = parse(
		"name: \"Test: wall\"\n"
		"material:\n"
		"  friction: {bed: 0.7, head: 0.45}\n"
		"  unit_weight: 2.2e4\n"
		"  thickness: 0.25\n"
		"layout:\n"
		"  block: [0.4, 0.2]\n"
		"  courses: 3\n"
		"  length: 1.2\n"
		"  bond: stack\n"
		"  first_course: full\n"
		"  origin: [1, 0]\n"
		"supports:\n"
		"  - ground: {y: 0}\n"
		"  - id: pier\n"
		"    vertices: [[0.6, 0], [1, 0], [1, 0.6], [0.6, 0.6]]\n"
		"loads:\n"
		"  - point: {at: [2.2, 0.5], direction: [1, 0]}\n"
		"contacts: {depth: 0.1, positions: anywhere}\n"
		"analysis: {samples: 50, seed: 18446744073709551615}\n"
		"tests:\n"
		"  loads: [312, 298.5, 341]\n", err);
	tap_ok(w != NULL, "a wall with every section parses");
	if (!w) {
		tap_diag("%s", err);
		return;
	}
	tap_ok(w->name && !strcmp(w->name, "Test: wall"), "name");
	tap_ok(w->mu_bed == 0.7 && w->mu_head == 0.45,
	       "friction {bed: 0.7, head: 0.45}");
	tap_ok(w->unit_weight == 22000 && w->thickness == 0.25,
	       "unit weight 2.2e4, thickness 0.25");
	tap_ok(w->layout.bond == BOND_STACK && !w->layout.first_half &&
		       w->layout.x0 == 1,
	       "stack bond, full first course, origin x 1");
	tap_ok(w->nfree == 9, "3 courses of 3 blocks (got %d)", w->nfree);
	int pier = find(w, "pier");
	tap_ok(pier >= 0 && w->blocks[pier].fixed && w->blocks[pier].weight == 0,
	       "the 'vertices' support is a fixed block 'pier'");
	tap_ok(w->depth == 0.1 && w->anywhere, "depth 0.1, positions anywhere");
	tap_ok(w->samples == 50 && w->seed == 18446744073709551615UL,
	       "samples 50, seed 2^64 - 1");
	tap_ok(w->ntests == 3 && w->tests[0] == 312 && w->tests[1] == 298.5 &&
		       w->tests[2] == 341,
	       "tests loads [312, 298.5, 341]");
	/* head joints: 2 in each of 3 courses, and the pier against the
	 * first block of each course: 9, all with the head friction */
	int nhead = 0, nbed = 0, headmu = 1, bedmu = 1;
	for (int k = 0; k < w->nifaces; k++) {
		if (w->ifaces[k].kind == JOINT_HEAD) {
			nhead++;
			headmu &= wall_iface_mu(w, k) == 0.45;
		} else if (w->ifaces[k].kind == JOINT_BED) {
			nbed++;
			bedmu &= wall_iface_mu(w, k) == 0.7;
		}
	}
	tap_ok(nhead == 9 && headmu,
	       "9 head joints (6 in the courses, 3 on the pier), mu 0.45 (got %d)",
	       nhead);
	/* bed joints: 3 on the ground, 3 + 3 between the stacked courses */
	tap_ok(nbed == 9 && bedmu, "9 bed joints, mu 0.7 (got %d)", nbed);
	wall_free(w);
}

static void test_errors(void)
{
	fails("material: {friction: 0.6}\nmaterial: {friction: 0.6}\n",
	      "t.yaml:2:1: ", "duplicate key 'material'", "duplicate top-level key");
	fails("material: {friction: \"0.6\"}\n", "t.yaml:1:22: ",
	      "not a quoted string", "a quoted number is a string");
	fails("material: {friction: 0.6x}\n", "t.yaml:1:22: ", "'0.6x'",
	      "0.6x is not a number");
	fails("material: {friction: .NaN}\n", "t.yaml:1:22: ", "finite",
	      ".NaN is refused");
	fails("material: {friction: -.inf}\n", "t.yaml:1:22: ", "finite",
	      "-.inf is refused");
	fails("material: {frction: 0.6}\n", "t.yaml:1:12: ",
	      "unknown key 'frction' in material", "a misspelt key");
	fails("contacts: {depth: 0.51}\n", "t.yaml:1:19: ", "between 0 and 0.5",
	      "depth 0.51");
	fails("analysis: {samples: 10.0}\n", "t.yaml:1:21: ", "integer",
	      "samples must be an integer literal");
	fails("a: [1\n", "t.yaml:2:1: ", "did not find expected",
	      "a syntax error is located");
	fails("", "t.yaml:1:1: ", "empty", "an empty file");
	fails("# only a comment\n", "t.yaml:1:1: ", "empty", "a file of comments");
	fails("- 1\n", "t.yaml:1:1: ", "must be a mapping", "a list at the top");
	fails("blocks: &a [*a]\n", "t.yaml:1:9: ", "a block must be a mapping",
	      "a recursive alias terminates");
	fails("loads: [{point: {at: [0, 0], direction: [0, 0]}}]\n",
	      "t.yaml:1:41: ", "non-zero", "a zero direction");
}

/* Hostile input: must fail fast, not hang. */
static void test_hostile(void)
{
	char err[SW_ERRLEN];
	static const char nul[] = "name: a\0b\n";
	struct wall *w0 = NULL;
	tap_ok(wallfile_parse(nul, sizeof nul - 1, "t.yaml", &w0, err) == SW_EINPUT &&
		       !strncmp(err, "t.yaml:1:8: ", 12),
	       "a NUL byte is refused where it is (%s)", err);
	size_t n = 1000000;
	char *deep = malloc(2 * n + 16);
	memcpy(deep, "name: ", 6);
	memset(deep + 6, '[', n);
	memset(deep + 6 + n, ']', n);
	deep[6 + 2 * n] = '\n';
	clock_t t0 = clock();
	struct wall *w = NULL;
	enum sw_status st = wallfile_parse(deep, 2 * n + 7, "t.yaml", &w, err);
	double secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
	tap_ok(st == SW_EINPUT && strstr(err, "nested deeper than 64"),
	       "a million nested lists are refused (%s)", err);
	tap_ok(secs < 1, "... at once (%.3f s)", secs);
	free(deep);

	/* billion laughs: 9 levels of 10 references */
	char buf[4096];
	size_t len = 0;
	len += (size_t)snprintf(buf + len, sizeof buf - len,
				"tests:\n  loads: &l0 [1, 1, 1, 1, 1, 1, 1, 1, 1, 1]\n");
	for (int i = 1; i <= 9; i++)
		len += (size_t)snprintf(buf + len, sizeof buf - len,
					"x%d: &l%d [*l%d, *l%d, *l%d, *l%d, *l%d, *l%d, *l%d, *l%d, *l%d, *l%d]\n",
					i, i, i - 1, i - 1, i - 1, i - 1, i - 1,
					i - 1, i - 1, i - 1, i - 1, i - 1);
	t0 = clock();
	st = wallfile_parse(buf, len, "t.yaml", &w, err);
	secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
	/* libyaml shares aliased nodes instead of copying them, so this
	 * loads at once; the walk then refuses the unknown key x1 */
	tap_ok(st == SW_EINPUT && w == NULL, "billion laughs is refused (%s)", err);
	tap_ok(secs < 1, "... at once (%.3f s)", secs);

	/* a valid-looking bomb: 1000 references to a block of 1000
	 * vertices would be 3 million nodes */
	size_t cap = 200000;
	char *bomb = malloc(cap);
	len = (size_t)snprintf(bomb, cap, "blocks: [&b {id: a, vertices: [");
	for (int i = 0; i < 1000; i++)
		len += (size_t)snprintf(bomb + len, cap - len, "%s[%d, 0]",
					i ? ", " : "", i);
	len += (size_t)snprintf(bomb + len, cap - len, "]}");
	for (int i = 0; i < 1000; i++)
		len += (size_t)snprintf(bomb + len, cap - len, ", *b");
	len += (size_t)snprintf(bomb + len, cap - len, "]\n");
	t0 = clock();
	st = wallfile_parse(bomb, len, "t.yaml", &w, err);
	secs = (double)(clock() - t0) / CLOCKS_PER_SEC;
	tap_ok(st == SW_EINPUT && strstr(err, "more than 2000000 nodes"),
	       "an alias bomb of blocks hits the node limit (%s)", err);
	tap_ok(secs < 2, "... quickly (%.3f s)", secs);
	free(bomb);
}

static void test_files(void)
{
	char err[SW_ERRLEN], path[512];
	static const struct {
		const char *file;
		int nfree, nifaces;
	} walls[] = {
		/* counted by hand: see tests/unit/test_layout.c and the files */
		{"walls/ferris-tinloi-1.yaml", 33, 83},
		{"walls/ferris-tinloi-2.yaml", 55, 141},
		{"walls/single-block.yaml", 1, 1},
		{"walls/two-block-stack.yaml", 2, 2},
		{"walls/demo.yaml", 28, 66},
		{"walls/large.yaml", 1020, -1},
	};
	for (size_t k = 0; k < sizeof walls / sizeof walls[0]; k++) {
		struct wall *w = NULL;
		snprintf(path, sizeof path, "%s/%s", SRCDIR, walls[k].file);
		enum sw_status st = wallfile_load(path, &w, err);
		tap_ok(st == SW_OK && w->nfree == walls[k].nfree &&
			       (walls[k].nifaces < 0 || w->nifaces == walls[k].nifaces),
		       "%s: %d blocks%s", walls[k].file, walls[k].nfree,
		       walls[k].nifaces < 0 ? "" : " and their interfaces");
		if (st != SW_OK)
			tap_diag("%s", err);
		else if (w->nfree != walls[k].nfree ||
			 (walls[k].nifaces >= 0 && w->nifaces != walls[k].nifaces))
			tap_diag("got %d blocks, %d interfaces", w->nfree,
				 w->nifaces);
		if (k == 0 && w)
			tap_ok(w->mu_bed == 0.65 && w->mu_head == 0.65 &&
				       w->loads[0].kind == LOAD_BODY,
			       "Ferris & Tin-Loi: mu 0.65, body load");
		wall_free(w);
	}

	struct wall *w = (struct wall *)1;
	enum sw_status st = wallfile_load("/nonexistent/wall.yaml", &w, err);
	tap_ok(st == SW_EINPUT && w == NULL &&
		       !strcmp(err, "/nonexistent/wall.yaml: cannot read: No such file or directory"),
	       "a missing file: '%s'", err);

	/* a file over the size limit is refused before it is read */
	char big[] = "/tmp/slipwall-big-XXXXXX";
	int fd = mkstemp(big);
	if (fd >= 0 && ftruncate(fd, (off_t)WALLFILE_MAX_BYTES + 1) == 0) {
		st = wallfile_load(big, &w, err);
		tap_ok(st == SW_EINPUT && strstr(err, "larger than"),
		       "a file over 16 MiB is refused (%s)", err);
	} else {
		tap_ok(0, "cannot make a big file: %s", strerror(errno));
	}
	if (fd >= 0) {
		close(fd);
		unlink(big);
	}
}

static int same_wall(const struct wall *a, const struct wall *b)
{
	if (a->nblocks != b->nblocks || a->nloads != b->nloads ||
	    a->ntests != b->ntests || a->nifaces != b->nifaces)
		return 0;
	for (int k = 0; k < a->nblocks; k++) {
		const struct wall_block *x = &a->blocks[k], *y = &b->blocks[k];
		if (strcmp(x->id, y->id) || x->nv != y->nv || x->fixed != y->fixed)
			return 0;
		if (k != a->ground_block &&
		    memcmp(x->xy, y->xy, sizeof(double) * 2 * (size_t)x->nv))
			return 0;
	}
	for (int l = 0; l < a->nloads; l++) {
		const struct wall_load *x = &a->loads[l], *y = &b->loads[l];
		/* wall_finish normalises the direction again on loading,
		 * which may move it by an ulp */
		if (x->kind != y->kind || x->magnitude != y->magnitude ||
		    fabs(x->dir[0] - y->dir[0]) > 1e-15 ||
		    fabs(x->dir[1] - y->dir[1]) > 1e-15 ||
		    x->block != y->block ||
		    (x->kind == LOAD_POINT &&
		     (x->at[0] != y->at[0] || x->at[1] != y->at[1])))
			return 0;
	}
	for (int t = 0; t < a->ntests; t++)
		if (a->tests[t] != b->tests[t])
			return 0;
	return a->mu_bed == b->mu_bed && a->mu_head == b->mu_head &&
	       a->mu_cov == b->mu_cov && a->unit_weight == b->unit_weight &&
	       a->thickness == b->thickness && a->depth == b->depth &&
	       a->anywhere == b->anywhere && a->samples == b->samples &&
	       a->seed == b->seed && a->has_ground == b->has_ground &&
	       a->ground_y == b->ground_y &&
	       ((!a->name && !b->name) ||
		(a->name && b->name && !strcmp(a->name, b->name)));
}

static void round_trip(const char *text, const char *what)
{
	char err[SW_ERRLEN], path[] = "/tmp/slipwall-save-XXXXXX";
	struct wall *a = parse(text, err), *b = NULL;
	int fd = mkstemp(path);
	if (!a || fd < 0) {
		tap_ok(0, "%s: parse (%s)", what, err);
		return;
	}
	close(fd);
	enum sw_status st = wallfile_save(a, path, err);
	tap_ok(st == SW_OK, "%s: saved", what);
	if (st != SW_OK)
		tap_diag("%s", err);
	st = wallfile_load(path, &b, err);
	tap_ok(st == SW_OK, "%s: the saved file loads", what);
	if (st != SW_OK)
		tap_diag("%s", err);
	tap_ok(b && same_wall(a, b),
	       "%s: same blocks (vertices bit for bit), ids, loads, settings",
	       what);
	char tmp[64];
	snprintf(tmp, sizeof tmp, "%s.tmp", path);
	tap_ok(access(tmp, F_OK) != 0, "%s: no temporary file left", what);
	unlink(path);
	wall_free(a);
	wall_free(b);
}

static void test_save(void)
{
	round_trip(small, "two blocks");
	round_trip("name: \"quote \\\" backslash \\\\ tab \\t colon: \\u00e9\"\n"
		   "material: {friction: {bed: 0.7, head: 0.3}, unit_weight: 21000.5, thickness: 0.123456789}\n"
		   "layout: {block: [0.4, 0.175], courses: 6, length: 2.0}\n"
		   "supports:\n"
		   "  - ground: {y: 0}\n"
		   "  - {id: pier, vertices: [[2, 0], [2.3, 0], [2.3, 0.6], [2, 0.6]]}\n"
		   "loads:\n"
		   "  - point: {at: [0.1, 1.0], direction: [1, 0.3], magnitude: 7}\n"
		   "  - body: {direction: [1, 0], magnitude: 0.5}\n"
		   "contacts: {depth: 0.1, positions: anywhere}\n"
		   "analysis: {samples: 77, seed: 12345678901234}\n"
		   "tests: {loads: [0.1, 312, 1e-3]}\n",
		   "a layout wall with every section");
	/* the largest seed (WALL_SEED_MAX) saves and loads exactly */
	round_trip("material: {friction: 0.6}\n"
		   "blocks: [{vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}]\n"
		   "supports: [{ground: {y: 0}}]\n"
		   "loads: [{point: {at: [0, 0.5], direction: [1, 0]}}]\n"
		   "analysis: {seed: 18446744073709551615}\n",
		   "seed 2^64 - 1");
	/* random friction: its cov saves and loads exactly */
	round_trip("material: {friction: {bed: 0.65, head: 0.5, cov: 0.215}}\n"
		   "blocks: [{vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}]\n"
		   "supports: [{ground: {y: 0}}]\n"
		   "loads: [{point: {at: [0, 0.5], direction: [1, 0]}}]\n",
		   "random friction (cov)");

	char err[SW_ERRLEN];
	struct wall *w = parse(small, err);
	if (w) {
		enum sw_status st = wallfile_save(w, "/nonexistent/dir/w.yaml", err);
		tap_ok(st == SW_EIO && strstr(err, "/nonexistent/dir/w.yaml.tmp: cannot write"),
		       "saving into a missing directory fails with SW_EIO (%s)",
		       err);
	}
	wall_free(w);
}

/* Save w to a temporary file and load it back; NULL (and a diagnostic)
 * when the saved file does not load. */
static struct wall *save_load(const struct wall *w, const char *what)
{
	char err[SW_ERRLEN], path[] = "/tmp/slipwall-save-XXXXXX";
	struct wall *b = NULL;
	int fd = mkstemp(path);
	if (fd < 0)
		return NULL;
	close(fd);
	if (wallfile_save(w, path, err) != SW_OK ||
	    wallfile_load(path, &b, err) != SW_OK) {
		tap_diag("%s: %s", what, err);
		b = NULL;
	}
	unlink(path);
	return b;
}

/* Append code point c to s as UTF-8. */
static size_t put_utf8(char *s, size_t k, long c)
{
	if (c < 0x80) {
		s[k++] = (char)c;
	} else if (c < 0x800) {
		s[k++] = (char)(0xc0 | c >> 6);
		s[k++] = (char)(0x80 | (c & 0x3f));
	} else if (c < 0x10000) {
		s[k++] = (char)(0xe0 | c >> 12);
		s[k++] = (char)(0x80 | (c >> 6 & 0x3f));
		s[k++] = (char)(0x80 | (c & 0x3f));
	} else {
		s[k++] = (char)(0xf0 | c >> 18);
		s[k++] = (char)(0x80 | (c >> 12 & 0x3f));
		s[k++] = (char)(0x80 | (c >> 6 & 0x3f));
		s[k++] = (char)(0x80 | (c & 0x3f));
	}
	return k;
}

/* Ids and names with the characters YAML folds (NEL U+0085, U+2028,
 * U+2029, line breaks, tabs) or refuses (C0, DEL, C1, U+FFFE) or reads
 * specially (a BOM, quotes, backslashes, ': ', ' #', leading and
 * trailing spaces) survive a save and a load byte for byte, and two ids
 * that differ only there stay two ids (issue 23). */
static void test_save_odd_strings(void)
{
	static const long odd[] = {
		0x85, 0x2028, 0x2029, 0xfeff, 0x0a, 0x0d, 0x09, 0x01, 0x1b,
		0x7f, 0x80, 0x9f, 0xa0, 0xfffe, 0xffff, '"', '\\', ':', '#',
		' ', '\'', '&', '*', '!', '{', '[', ',', 'a', 'Z', '0', 0xe9,
		0x3bb, 0x1f9f1, 0x10ffff, 0xfffd};
	char err[SW_ERRLEN];
	struct wall *w = parse(small, err);
	if (!w) {
		tap_ok(0, "odd strings: parse (%s)", err);
		return;
	}
	/* the case of the issue: "a<NEL>b" and "a b" */
	free(w->blocks[0].id);
	free(w->blocks[1].id);
	w->blocks[0].id = sw_xstrdup("a\xc2\x85" "b");
	w->blocks[1].id = sw_xstrdup("a b");
	struct wall *b = save_load(w, "NEL");
	tap_ok(b && !strcmp(b->blocks[0].id, "a\xc2\x85" "b") &&
	       !strcmp(b->blocks[1].id, "a b"),
	       "ids 'a<U+0085>b' and 'a b' survive a save and a load, distinct");
	wall_free(b);

	unsigned long x = 88172645463325252UL;	/* xorshift64 */
	int bad = 0, rounds = 200;
	for (int r = 0; r < rounds; r++) {
		char s[3][64];
		for (int j = 0; j < 3; j++) {
			size_t k = 0;
			int len = 1 + r % 7 + j;
			for (int i = 0; i < len; i++) {
				x ^= x << 13;
				x ^= x >> 7;
				x ^= x << 17;
				k = put_utf8(s[j], k,
					     odd[x % (sizeof odd / sizeof *odd)]);
			}
			s[j][k] = 0;
		}
		if (!strcmp(s[0], s[1]))
			strcat(s[1], "1");
		free(w->blocks[0].id);
		free(w->blocks[1].id);
		free(w->name);
		w->blocks[0].id = sw_xstrdup(s[0]);
		w->blocks[1].id = sw_xstrdup(s[1]);
		w->name = sw_xstrdup(s[2]);
		b = save_load(w, "odd strings");
		if (!b || strcmp(b->blocks[0].id, s[0]) ||
		    strcmp(b->blocks[1].id, s[1]) || !b->name ||
		    strcmp(b->name, s[2]))
			bad++;
		wall_free(b);
	}
	tap_ok(bad == 0, "%d walls with random ids and names of odd "
	       "characters: each saved file loads to the same strings (%d "
	       "did not)", rounds, bad);
	wall_free(w);
}

/* A generated wall stays generated: layout, the blocks left out (omit)
 * and the blocks of its own, in the same order; numbers in the fewest
 * digits that read back bit for bit. */
static void test_save_layout(void)
{
	char err[SW_ERRLEN], path[] = "/tmp/slipwall-save-XXXXXX", text[8192];
	const char *src =
		"material: {friction: 0.7, unit_weight: 19620, thickness: 0.1}\n"
		"layout: {block: [0.2, 0.1], courses: 4, length: 0.8, first_course: full,\n"
		"         omit: [c4b2, c4b3]}\n"
		"blocks:\n"
		"  - {id: cap, vertices: [[0, 0.4], [0.2, 0.4], [0.2, 0.5], [0, 0.5]]}\n"
		"supports: [{ground: {y: 0}}]\n"
		"loads: [{point: {at: [0.8, 0.15], direction: [1, 0]}}]\n"
		"tests: {loads: [0.30000000000000004, 312]}\n";
	struct wall *a = parse(src, err), *b = NULL;
	int fd = mkstemp(path);
	if (!a || fd < 0) {
		tap_ok(0, "layout save: parse (%s)", err);
		return;
	}
	close(fd);
	tap_ok(a->nblocks > 0 && strcmp(a->blocks[0].id, "c1b1") == 0,
	       "omit leaves the other blocks of the layout");
	int has = 0;
	for (int k = 0; k < a->nblocks; k++)
		has |= !strcmp(a->blocks[k].id, "c4b2") || !strcmp(a->blocks[k].id, "c4b3");
	tap_ok(!has, "omit leaves out c4b2 and c4b3");
	tap_ok(wallfile_save(a, path, err) == SW_OK, "layout save: saved");
	FILE *f = fopen(path, "r");
	size_t n = f ? fread(text, 1, sizeof text - 1, f) : 0;
	text[n] = 0;
	if (f)
		fclose(f);
	tap_ok(strstr(text, "layout:\n") && strstr(text, "omit: [\"c4b2\", \"c4b3\"]") &&
	       strstr(text, "\"cap\"") && !strstr(text, "\"c1b1\""),
	       "written as its layout, the blocks left out and its own block");
	tap_ok(strstr(text, "friction: {bed: 0.7, head: 0.7}") &&
	       strstr(text, "block: [0.2, 0.1]") &&
	       strstr(text, "0.30000000000000004, 312"),
	       "the shortest decimals: 0.7, 0.2, and 17 digits where needed");
	tap_ok(wallfile_load(path, &b, err) == SW_OK && same_wall(a, b),
	       "it loads to the same wall, blocks in the same order");
	if (!b)
		tap_diag("%s\n%s", err, text);
	wall_free(b);
	b = NULL;

	/* a block of the courses moved to the end: not the layout's order,
	 * so every block explicit (the model stays the same) */
	struct wall *c = parse(
		"material: {friction: 0.7, unit_weight: 19620, thickness: 0.1}\n"
		"layout: {block: [0.2, 0.1], courses: 2, length: 0.8, omit: [c1b1]}\n"
		"blocks:\n"
		"  - {id: c1b1, vertices: [[0, 0], [0.1, 0], [0.1, 0.1], [0, 0.1]]}\n"
		"supports: [{ground: {y: 0}}]\n"
		"loads: [{point: {at: [0.8, 0.15], direction: [1, 0]}}]\n", err);
	tap_ok(c && wallfile_save(c, path, err) == SW_OK, "reordered: saved");
	f = fopen(path, "r");
	n = f ? fread(text, 1, sizeof text - 1, f) : 0;
	text[n] = 0;
	if (f)
		fclose(f);
	tap_ok(!strstr(text, "layout:") && strstr(text, "\"c1b1\""),
	       "reordered blocks: written explicit");
	tap_ok(wallfile_load(path, &b, err) == SW_OK && same_wall(c, b),
	       "reordered: loads to the same wall");
	wall_free(b);
	wall_free(c);
	wall_free(a);
	unlink(path);

	a = parse("material: {friction: 0.6, unit_weight: 1, thickness: 1}\n"
		  "layout: {block: [1, 1], courses: 1, length: 2,\n"
		  "         omit: [c1b9]}\n"
		  "supports: [{ground: {y: 0}}]\n"
		  "loads: [{body: {direction: [1, 0]}}]\n", err);
	tap_ok(!a && strstr(err, ":3:17: layout omit: the layout has no block 'c1b9'"),
	       "omit of a block the layout has not: FILE:LINE:COLUMN (%s)", err);
	wall_free(a);
}

int main(void)
{
	test_values();
	test_defaults();
	test_settings();
	test_errors();
	test_hostile();
	test_files();
	test_save();
	test_save_layout();
	test_save_odd_strings();
	return tap_done();
}
