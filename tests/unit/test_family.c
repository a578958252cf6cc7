/*
 * test_family.c - mechanism families (family.c): on a two-course wall
 * whose answers are known by hand, joint strings made from a chosen set
 * of blocks (every joint between the set and the rest slides) move
 * exactly that set, in the number of rigid bodies the closed joints
 * inside it leave; a joint that opens between two blocks at rest moves
 * nothing; families group a tally's mechanisms by moving set, count
 * them, and are named by their blocks.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/family.h"
#include "slipwall/record.h"
#include "slipwall/wallfile.h"
#include "tap.h"

/* Course 1: c1b1 [0, 0.2], c1b2 [0.2, 0.4], c1b3 [0.4, 0.6]; course 2
 * starts with a half block: c2b1 [0, 0.1], c2b2 [0.1, 0.3], c2b3
 * [0.3, 0.5], c2b4 [0.5, 0.6]. */
static const char yaml[] =
	"material: {friction: 0.6, unit_weight: 20000, thickness: 0.1}\n"
	"layout: {block: [0.2, 0.1], courses: 2, length: 0.6, "
	"bond: running, first_course: full}\n"
	"supports:\n  - ground: {y: 0}\n"
	"loads:\n  - body: {direction: [1, 0]}\n";

static int block(const struct wall *w, const char *id)
{
	for (int b = 0; b < w->nblocks; b++)
		if (!strcmp(w->blocks[b].id, id))
			return b;
	tap_ok(0, "block %s exists", id);
	exit(1);
}

/* The joint string in which the joints between the blocks of set (a
 * NULL-terminated list of ids) and every other body have state `edge`,
 * the joints inside the set `inner`, the rest closed. */
static char *joints(const struct wall *w, const char *const *set, char edge,
		    char inner)
{
	unsigned char *in = calloc((size_t)w->nblocks, 1);
	for (int i = 0; set[i]; i++)
		in[block(w, set[i])] = 1;
	char *j = malloc((size_t)w->nifaces + 1);
	for (int k = 0; k < w->nifaces; k++) {
		int a = in[w->ifaces[k].a], b = in[w->ifaces[k].b];
		j[k] = a != b ? edge : a ? inner : '.';
	}
	j[w->nifaces] = 0;
	free(in);
	return j;
}

/* Does the moving set of joint equal set, in nbodies bodies? */
static void check_moving(const struct wall *w, const char *joint,
			 const char *const *set, int nbodies, const char *what)
{
	unsigned char *mv = malloc((size_t)w->nblocks);
	int nb = -1, n = family_moving(w, joint, mv, &nb);
	int want = 0, same = 1;
	for (int b = 0; b < w->nblocks; b++) {
		int in = 0;
		for (int i = 0; set[i]; i++)
			in |= !strcmp(set[i], w->blocks[b].id);
		want += in;
		same &= in == mv[b];
	}
	tap_ok(same && n == want, "%s: the moving blocks are the set (%d)",
	       what, n);
	tap_ok(nb == nbodies, "%s: %d rigid bodies (%d)", what, nbodies, nb);
	free(mv);
}

static void add(struct tally *t, const struct wall *w, const char *joint,
		double lam)
{
	struct record r;
	record_init(&r, w);
	r.status = SAMPLE_ACCEPTED;
	r.lambda_min = lam;
	memcpy(r.joint, joint, (size_t)w->nifaces + 1);
	tally_add(t, &r);
	record_free(&r);
}

int main(void)
{
	char err[1024];
	struct wall *w = NULL;
	if (wallfile_parse(yaml, sizeof yaml - 1, "two-courses", &w, err)) {
		tap_ok(0, "the wall parses: %s", err);
		return tap_done();
	}
	tap_ok(w->nfree == 7, "7 free blocks (%d)", w->nfree);

	static const char *const none[] = {NULL};
	static const char *const corner[] = {"c2b4", NULL};
	static const char *const top[] = {"c2b1", "c2b2", "c2b3", "c2b4",
					  NULL};
	static const char *const end[] = {"c1b3", "c2b3", "c2b4", NULL};

	char *j = joints(w, none, 's', '.');
	check_moving(w, j, none, 0, "every joint closed");
	free(j);
	/* c1b1/c1b2 opens, both still on the ground */
	j = joints(w, none, 's', '.');
	for (int k = 0; k < w->nifaces; k++)
		if (w->ifaces[k].a == block(w, "c1b1") &&
		    w->ifaces[k].b == block(w, "c1b2"))
			j[k] = 'o';
	tap_ok(strchr(j, 'o') != NULL, "c1b1/c1b2 is a joint");
	check_moving(w, j, none, 0, "a joint opens between blocks at rest");
	free(j);
	j = joints(w, corner, 's', '.');
	check_moving(w, j, corner, 1, "c2b4 slides out");
	free(j);
	j = joints(w, top, 's', '.');
	check_moving(w, j, top, 1, "course 2 slides as one body");
	char *jt = joints(w, top, 's', 'o');
	check_moving(w, jt, top, 4, "course 2 slides, its head joints open");
	char *je = joints(w, end, 'h', '.');
	check_moving(w, je, end, 1, "the right end rotates as one body");

	/* the names */
	struct family_set fs;
	family_set_init(&fs, w);
	tap_ok(fs.nrows == 2, "2 courses (%d)", fs.nrows);
	unsigned char *mv = malloc((size_t)w->nblocks);
	char name[256];
	struct {
		const char *const *set;
		const char *name;
	} names[] = {
		{corner, "c2b4: 1 block in course 2 at the right end"},
		{top, "c2b1-c2b4: 4 blocks in course 2 across the wall"},
		{end, "c1b3 c2b3 c2b4: 3 blocks in courses 1-2 at the right "
		 "end"},
	};
	for (int i = 0; i < 3; i++) {
		char *ji = joints(w, names[i].set, 's', '.');
		family_moving(w, ji, mv, NULL);
		family_name(&fs, mv, name, sizeof name);
		tap_ok(!strcmp(name, names[i].name), "name \"%s\" (%s)",
		       names[i].name, name);
		free(ji);
	}
	/* how they come away: c2b4 slides on the bed joint under it (bed
	 * joint 1; its head joint slides too); the right end hinges */
	char mo[128];
	char *jc = joints(w, corner, 's', '.');
	family_moving(w, jc, mv, NULL);
	family_motion(&fs, jc, mv, mo, sizeof mo);
	tap_ok(!strcmp(mo, "slides on bed joint 1"), "c2b4: \"slides on bed "
	       "joint 1\" (%s)", mo);
	free(jc);
	jc = joints(w, end, 'h', '.');
	family_moving(w, jc, mv, NULL);
	family_motion(&fs, jc, mv, mo, sizeof mo);
	/* its edge: the ground, c1b2 twice (head joint, bed joint under
	 * c2b3), c2b2 */
	tap_ok(!strcmp(mo, "hinges at 4 joints"), "the right end: \"hinges "
	       "at 4 joints\" (%s)", mo);
	free(jc);
	jc = joints(w, top, 'H', '.');
	family_moving(w, jc, mv, NULL);
	family_motion(&fs, jc, mv, mo, sizeof mo);
	tap_ok(!strncmp(mo, "slides on bed joint 1, hinges at ", 33),
	       "course 2 hinging and sliding: \"slides on bed joint 1, hinges "
	       "at ...\" (%s)", mo);
	free(jc);
	char jn[64];
	family_joint_name(w, 0, jn, sizeof jn);
	tap_ok(strchr(jn, '/') != NULL, "joint 1 is named by its bodies (%s)",
	       jn);

	/* a tally's families: course 2 as one body (3 samples) and in
	 * four (1), the right end (2 samples) */
	struct tally t;
	tally_init(&t, w);
	add(&t, w, je, 0.5);
	add(&t, w, j, 0.30);
	add(&t, w, jt, 0.25);
	add(&t, w, j, 0.35);
	add(&t, w, je, 0.45);
	add(&t, w, j, 0.32);
	family_update(&fs, &t);
	tap_ok(t.nmech == 3 && fs.nfam == 2, "3 mechanisms, 2 families "
	       "(%d, %d)", t.nmech, fs.nfam);
	int top2[4], n = family_top(&fs, top2, 4);
	tap_ok(n == 2, "family_top gives both");
	const struct family *f0 = &fs.fam[top2[0]], *f1 = &fs.fam[top2[1]];
	tap_ok(f0->count == 4 && f0->nmoving == 4 && f0->nmech == 2,
	       "the most frequent: course 2, 4 samples of 2 mechanisms");
	tap_ok(f0->lam_lo == 0.25 && f0->lam_hi == 0.35, "its loads 0.25..0.35");
	tap_ok(f1->count == 2 && f1->nmoving == 3 && f1->lam_lo == 0.45 &&
	       f1->lam_hi == 0.5, "then the right end: 2 samples, 0.45..0.5");
	tap_ok(f1->first == 0, "families are numbered by first appearance");
	int mi[4], nm = family_mechs(&fs, &t, top2[0], mi, 4);
	tap_ok(nm == 2 && !strcmp(t.mech[mi[0]].joint, j) &&
	       !strcmp(t.mech[mi[1]].joint, jt), "its mechanisms, most "
	       "frequent first");
	/* a later sample of a new family: only it is classified again */
	add(&t, w, je, 0.4);
	family_update(&fs, &t);
	tap_ok(fs.fam[top2[1]].count == 3 && fs.fam[top2[1]].lam_lo == 0.4,
	       "an update recounts (3 samples, from 0.4)");

	tally_free(&t);
	family_set_free(&fs);
	free(mv);
	free(j);
	free(jt);
	free(je);
	wall_free(w);
	return tap_done();
}
