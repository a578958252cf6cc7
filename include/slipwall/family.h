/*
 * family.h - mechanism families (docs/statistics.md, "Mechanism
 * families"): the mechanisms of a run grouped by the set of blocks that
 * move, so that a person recognises them on a wall of any size.
 *
 * A mechanism is a joint-state string (sample.h, one char per
 * interface).  Its moving set is the set of free blocks that are not
 * joined to a support by a chain of closed ('.') joints: the blocks at
 * rest form, with the supports, the connected components that contain a
 * support; every other block moves.  The rigid bodies of a mechanism are
 * the connected components of its moving blocks under closed joints.
 * Two mechanisms are of one family when they move the same region: the
 * same set, for sets of at most FAMILY_SMALL blocks; the same outline
 * for larger ones (the lowest and the highest course, the leftmost and
 * rightmost moving block of each, and which ends of the wall every
 * course reaches).  On a wall of hundreds of blocks the sets of one
 * collapse region differ by a block here and there (walls/body-1000.yaml:
 * 407-409 blocks, every sample a set of its own).  Both keys are
 * functions of the mechanism alone (not of the other samples, the thread
 * count or the order in which samples arrive).
 *
 * A family is named by its outline or its blocks (family_label): "c4b3
 * c5b4: 2 blocks in courses 4-5 at the right end", "c1b24-c1b26 to
 * c40b10-c40b25: 407-409 blocks in courses 1-40 at the right end".
 * Courses are the rows of the wall's free
 * blocks by the height of their lowest point (a layout's c<course>b<k>
 * course for a layout wall).  Joints are named by their two bodies
 * (family_joint_name: "c3b4/c4b4").
 *
 * A family_set follows a tally: the tally's mechanisms only ever grow
 * (by first appearance), so family_update classifies the new ones and
 * recounts.  Nothing here is shared between threads; the wall must stay
 * alive and unchanged while the set is used.
 */
#ifndef SLIPWALL_FAMILY_H
#define SLIPWALL_FAMILY_H

#include <stddef.h>

#include "slipwall/tally.h"
#include "slipwall/wall.h"

/* The moving set of mechanism joint (nifaces chars): moving[b] = 1 for
 * a free block that moves, 0 otherwise (nblocks entries).  Returns the
 * number of moving blocks; *nbodies (may be NULL) gets the number of
 * rigid bodies they form. */
int family_moving(const struct wall *w, const char *joint,
		  unsigned char *moving, int *nbodies);

/* A moving set of at most this many blocks is its family's key; a
 * larger one's outline is (family.c; docs/statistics.md, "Mechanism
 * families") */
#define FAMILY_SMALL 3

/* A large moving set's outline (its family's key): its lowest and
 * highest course (1-based), the leftmost and rightmost moving block of
 * each (lo[0], hi[0]: the lowest), and whether every course it spans
 * reaches the wall's left and right end. */
struct family_outline {
	int rlo, rhi, lo[2], hi[2], left, right;
};

struct family {
	/* owned, nblocks: the blocks that move in every mechanism of the
	 * family (its core; a small family's moving set) */
	unsigned char *moving;
	int nmoving;		/* the core's blocks */
	int nmin, nmax;		/* the fewest and most moving blocks of a
				 * mechanism of it */
	unsigned long long key;	/* a hash of the key (FNV-1a), to find it */
	struct family_outline outline;	/* a large family's key */
	long count;		/* accepted samples */
	double lam_lo, lam_hi;	/* their loads' range (the tally's quantity) */
	int nmech;		/* distinct mechanisms in it */
	int first;		/* its first mechanism (index into t->mech) */
};

struct family_set {
	const struct wall *w;
	int *row;		/* nblocks: a free block's course, 1-based */
	int nrows;
	struct family *fam;	/* by first appearance */
	int nfam, capfam;
	int *of;		/* of[k]: the family of the tally's mechanism k */
	int nseen, capseen;	/* mechanisms classified so far */
};

void family_set_init(struct family_set *fs, const struct wall *w);
void family_set_free(struct family_set *fs);
/* Classify the tally's mechanisms not seen yet and recount every
 * family's samples and load range from the tally. */
void family_update(struct family_set *fs, const struct tally *t);
/* The families sorted by count, most frequent first (ties: first
 * appearance first): up to max indices into fs->fam; returns how many. */
int family_top(const struct family_set *fs, int *idx, int max);
/* The mechanisms of family f, most frequent first (ties: first
 * appearance): up to max indices into t->mech; returns how many. */
int family_mechs(const struct family_set *fs, const struct tally *t, int f,
		 int *idx, int max);

/* The name for people of one moving set, by its blocks (see above),
 * into buf. */
void family_name(const struct family_set *fs, const unsigned char *moving,
		 char *buf, size_t len);
/* A family's name: its outline (or its blocks, when small) and the range
 * of its mechanisms' counts, "c1b24-c1b26 to c40b10-c40b25: 407-409
 * blocks in courses 1-40 at the right end". */
void family_label(const struct family_set *fs, const struct family *f,
		  char *buf, size_t len);
/* How mechanism joint (moving set mv) comes away from the blocks at
 * rest, by the joints on the set's edge: "slides on bed joints 3-4,
 * hinges at 2 joints".  Bed joint k lies between courses k and k + 1
 * (0: on a support).  "opens" when no edge joint slides or hinges. */
void family_motion(const struct family_set *fs, const char *joint,
		   const unsigned char *mv, char *buf, size_t len);
/* Interface k's two bodies, "a/b" by id, into buf. */
void family_joint_name(const struct wall *w, int k, char *buf, size_t len);
/* The moving joints of mechanism joint, 1-based as in the samples file,
 * each with its bodies: "3s(c1b2/c2b2) 7h(c2b1/c2b2)", cut short with
 * " ..." to fit len. */
void family_fmt_joints(const struct wall *w, const char *joint, char *buf,
		       size_t len);

#endif
