/*
 * wall.h - the wall model: blocks, supports, interfaces, loads.
 *
 * A `struct wall` is what every other module reads.  It is built in two
 * steps: blocks, loads and settings are added (by the YAML reader in
 * wallfile.c, by the layout generator, or by hand in tests), then
 * wall_finish() computes the derived geometry (area, centroid, weight of
 * each block), makes the ground support, finds the interfaces and the
 * block of every point load, and validates the whole.  After
 * wall_finish() the model is read-only; nothing in it changes while a
 * solver runs, so any number of threads may read one wall at once.
 *
 * Supports are blocks with fixed = 1: they have no equations and no
 * velocity.  A `ground` support becomes a fixed rectangle under the wall.
 * Interfaces are ordered by (min(a,b), max(a,b), position along the
 * joint); this order is the one of `check --json` and of every output.
 */
#ifndef SLIPWALL_WALL_H
#define SLIPWALL_WALL_H

#include <limits.h>

#include "slipwall/status.h"

enum joint_kind { JOINT_BED, JOINT_HEAD, JOINT_OTHER };
enum load_kind { LOAD_POINT, LOAD_BODY };
enum bond_kind { BOND_RUNNING, BOND_STACK };

/* Where a value came from in the wall file (line, col 1-based; 0 = none). */
struct wall_mark {
	int line, col;
};

struct wall_block {
	char *id;		/* owned; "b12" style when the file gives none */
	int nv;			/* number of vertices (>= 3) */
	double *xy;		/* owned, 2*nv, counter-clockwise */
	int fixed;		/* 1 for a support */
	struct wall_mark mark;	/* where the block was declared */
	/* derived by wall_finish(): */
	double size;		/* m, largest extent (its tolerances' scale) */
	double area;		/* m^2 */
	double cx, cy;		/* centroid, m */
	double weight;		/* N (0 for a support) */
	int eq;			/* index among free blocks, -1 for a support */
};

struct wall_interface {
	int a, b;		/* bodies; n points from a into b */
	double p1[2], p2[2];	/* shared segment, p1 -> p2 along t */
	double len;		/* |p2 - p1| */
	double t[2], n[2];	/* unit tangent and normal (n = a -> b) */
	enum joint_kind kind;	/* bed (horizontal), head (vertical), other */
};

struct wall_load {
	enum load_kind kind;
	double at[2];		/* point loads: where */
	double dir[2];		/* unit direction (normalised by wall_finish) */
	double magnitude;	/* point: reference force in N; body: factor */
	int block;		/* point loads: derived by wall_finish() */
	struct wall_mark mark;
};

struct wall_layout {
	int present;		/* 0: no generated part */
	double block_w, block_h;/* full block, m */
	int courses;
	double length;		/* wall length, m */
	enum bond_kind bond;
	int first_half;		/* course 1 starts with a half block */
	double x0, y0;		/* lower-left corner (default 0, ground y) */
};

struct wall {
	char *name;		/* owned, may be NULL */
	char *path;		/* owned, file it came from (for messages) */
	double mu_bed, mu_head;	/* friction of bed and head joints: the mean
				 * when it is random */
	double mu_cov;		/* friction's coefficient of variation per
				 * joint and sample; 0: fixed (draw.h) */
	double unit_weight;	/* gamma, N/m^3 */
	double thickness;	/* out-of-plane t, m */
	/* where friction (bed, head) and unit_weight were given, for the
	 * messages of wall_finish (0: not given) */
	struct wall_mark friction_mark[2], unit_weight_mark;
	struct wall_layout layout;
	int has_ground;
	double ground_y;
	struct wall_mark ground_mark;
	int ground_block;	/* derived: index of the ground block, or -1 */

	struct wall_block *blocks;	/* supports included */
	int nblocks, capblocks;
	struct wall_load *loads;
	int nloads, caploads;

	double depth;		/* contacts.depth, 0..0.5 */
	int anywhere;		/* contacts.positions: anywhere */
	int samples;		/* analysis.samples */
	unsigned long seed;	/* analysis.seed, 0..WALL_SEED_MAX */
	double design_load;	/* analysis.design_load (the load factor's
				 * unit, N for a 1 N point load); 0: none */
	double *tests;		/* experimental collapse loads, N; owned */
	int ntests;

	/* derived by wall_finish(): */
	struct wall_interface *ifaces;
	int nifaces;
	int nfree;		/* number of free blocks */
	double total_weight;	/* N, free blocks */
	double mean_weight;	/* N, free blocks (force scale) */
	double mean_size;	/* m, sqrt(mean free block area) (length scale) */
	int finished;
};

/* The one range of seeds: the wall file, the command line (--seed), the
 * JSON outputs (an exact integer) and the report all take and write every
 * seed from 0 to 2^64 - 1. */
#define WALL_SEED_MAX 18446744073709551615ULL
_Static_assert(ULONG_MAX >= WALL_SEED_MAX,
	       "a seed is an unsigned long of 64 bits");

/* The largest friction coefficient a wall may have.  Larger ones are
 * beyond the accuracy of the LPs (measured: Ferris & Tin-Loi wall 1 has
 * "numerical" samples from 1e5) and change nothing physically: at 1000 a
 * joint slides only within 0.06 degrees of the direction of its contact
 * force.  docs/wall-format.md. */
#define WALL_FRICTION_MAX 1000.0
/* friction.cov: at most this (a coefficient of variation of 100 %; a
 * joint's drawn friction is then capped at WALL_FRICTION_MAX) */
#define WALL_COV_MAX 1.0

/* Ids the program gives bodies of its own ("ground", the foundation of
 * `supports: [{ground: ...}]`): a block or support may not take one.
 * Returns 1 for a reserved id. */
int wall_id_reserved(const char *id);

/* A new empty wall with the defaults of docs/wall-format.md. */
struct wall *wall_new(void);
void wall_free(struct wall *w);

/* Add a block (xy: 2*nv numbers, copied).  id may be NULL.  Returns the
 * block index. */
int wall_add_block(struct wall *w, const char *id, const double *xy, int nv,
		   int fixed, struct wall_mark mark);
/* Add a load (copied). */
void wall_add_load(struct wall *w, const struct wall_load *ld);

/* The force of live load ld on block k at load factor 1 (N; a body
 * load's is its factor times the block's weight) and the point where it
 * acts (a body load: the centroid).  Returns 0, and leaves the outputs
 * alone, when it does not act on k: a support, or a point load's other
 * blocks.  Its direction is ld->dir.  Reads what wall_finish derives
 * (the point load's block, the weights). */
int wall_load_on(const struct wall *w, const struct wall_load *ld, int k,
		 double *f, double *px, double *py);

/* Compute what is derived and validate.  On failure fills err with
 * "FILE:LINE:COLUMN: message" (the mark of the offending item) and
 * returns SW_EINPUT.  Must be called once, after all adds. */
enum sw_status wall_finish(struct wall *w, char *err);

/* A deep copy of a finished or unfinished wall (for editing). */
struct wall *wall_copy(const struct wall *w);

/* A digest of the mechanical model of a finished wall: every block's
 * vertices, weight and whether it is a support, every interface's
 * bodies, segment and friction, every load's kind, point, direction
 * and magnitude - all that a solution on the classical contact (solve,
 * report's single solutions) depends on; not the contact depth, seed or
 * sample count.  FNV-1a 64 over the doubles' bytes, written as
 * "fnv1a64:" and 16 hex digits into out (WALL_DIGEST_LEN bytes).  Two
 * walls with the same digest are the same model (up to a collision);
 * an edit that moves a load or changes a friction changes it. */
#define WALL_DIGEST_LEN 32
void wall_digest(const struct wall *w, char *out);

/* The friction coefficient of interface k: the material's (mu_head for a
 * head joint, mu_bed for any other), its mean when friction is random.
 * A sample's own friction is in its draw (draw.h). */
double wall_iface_mu(const struct wall *w, int k);

/* Two joints of one free block that meet at a point where associative
 * friction can lock them: the friction cones of their contact forces
 * at that point hold a pair of opposite forces, so a force of any size
 * pushed into the corner is carried by friction alone (for joints at a
 * right angle: mu_i mu_j >= 1).  LP-max, the associative problem every
 * sample starts from, can then be unbounded or far above the
 * non-associative collapse load (docs/method.md, "What the method
 * cannot answer").  Returns 1 and the first such pair (interfaces *ki,
 * *kj, block *blk, the point pt), 0 if there is none.  The friction is
 * wall_iface_mu's. */
int wall_friction_lock(const struct wall *w, int *blk, int *ki, int *kj,
		       double pt[2]);
/* The same, for people: "friction A and B on two joints of block ID
 * that meet at (X, Y)" into buf; 0 (buf untouched) when w's joints
 * cannot lock.  The command line's warnings and the workbench's title
 * and messages say it. */
int wall_friction_lock_text(const struct wall *w, char *buf, size_t len);

/* Free blocks that rest on no joint: no interface of theirs can push
 * them up (the normal of each points into them horizontally or from
 * above), so their weight hangs on the friction of side joints, held
 * by a clamp: a course over an opening without a lintel.  The SLP's
 * fixed capacities can lose that clamp, and such a wall's samples may
 * be rejected as `hanging` (docs/method.md, "What the method cannot
 * answer").  Returns how many there are and the first in *blk; into
 * *above, when not NULL, how many other blocks rest only on such blocks
 * (or on those), so that no chain of joints carries them to a support
 * from below either (tests/data/stack-gap.yaml: c3b2 on c2b2). */
int wall_hanging(const struct wall *w, int *blk, int *above);
/* The body that rests on interface f: the one its normal points up into
 * (an upward component beyond 1e-9), or -1 for a vertical joint.  The
 * hanging and overhang tests' one notion of "rests on". */
int wall_iface_rests(const struct wall_interface *f);
/* The span in x of what each block rests on (the interfaces
 * wall_iface_rests gives it): of the contact points q (4 numbers an
 * interface, q_a's x and y then q_b's, as a sample's statics has them)
 * or, when q is NULL, of the joints' ends.  lo[b] = HUGE_VAL and hi[b] =
 * -HUGE_VAL for a block that rests on nothing; lo and hi have room for
 * w->nblocks. */
void wall_rest_span(const struct wall *w, const double *q, double *lo,
		    double *hi);
/* The clamp of those blocks: the side joints (normal horizontal) of
 * every block that no chain of joints carries to a support from below
 * (those blocks, and any that rests only on them), into k when not NULL
 * (room for w->nifaces), and how many.  A sample whose SLP loses them
 * is rejected as `hanging` (docs/method.md, "What the method cannot
 * answer: blocks that hang on friction"). */
int wall_clamp_joints(const struct wall *w, int *k);
/* Those blocks: mark[b] = 1 for each block that no chain of joints
 * carries to a support from below (mark has room for w->nblocks; the
 * other entries are left as they are); how many. */
int wall_clamp_blocks(const struct wall *w, char *mark);
/* The same, for people: "block ID rests on no joint below it" (or
 * "block ID and N others rest on no joint below them"), followed by ",
 * and M other blocks only on it (them)" when blocks rest on those, into
 * buf; 0 (buf untouched) when none hangs. */
int wall_hanging_text(const struct wall *w, char *buf, size_t len);
/* Blocks that overhang the joints they rest on: a free block that rests
 * on joints (an interface whose normal has an upward component into
 * it) and whose centroid lies at or beyond the edge, in x, of their
 * span (to 1e-9 of the block's size) - a running-bond block half over
 * an opening.  At a contact depth above 0 its weight acts beyond its
 * contact points, and it is held by its neighbours' clamp, which the
 * SLP can lose: such samples are rejected as `hanging` (docs/method.md,
 * "Blocks that overhang an opening").  For people: "block ID overhangs
 * what it rests on (its centroid, at x = X m, is at the edge of the
 * joints below it)" ("beyond" the edge), with ", and N other blocks
 * likewise" when there are more, into buf; 0 (buf untouched) when none
 * does. */
int wall_overhang_text(const struct wall *w, char *buf, size_t len);

/* The end of the message of a vertex too far from the origin for its
 * polygon (geom_far_vertex): "... vertex K " wall_far_text. */
extern const char wall_far_text[];
/* A polygon so thin for its length that geom_far_vertex refuses it at
 * any position (no move helps): "is too thin: ..." into buf, or NULL. */
const char *wall_thin_text(const double *xy, int nv, char *buf, size_t len);

/* What a collapse load factor is for people (docs/run.md, "Loads and
 * units").  The LPs' lambda multiplies the reference load: each load's
 * magnitude m times its direction (a point load: m N at its point; a
 * body load: m times each block's weight).  Every writer prints
 * scale * lambda with the unit and name below, never lambda itself:
 *   point loads, all of one magnitude m:  the force, m lambda, in N
 *                                         ("collapse load");
 *   body loads, all of one magnitude m:   m lambda, no unit ("seismic
 *                                         coefficient": the horizontal
 *                                         force over the weight);
 *   anything else (magnitudes that differ, point and body loads
 *   together, no load):                   lambda, no unit ("load
 *                                         factor", times the reference
 *                                         loads).
 * Experimental loads (tests), --at and analysis.design_load are given
 * in this quantity too. */
struct wall_quantity {
	double scale;		/* printed value = scale * lambda (> 0) */
	const char *name;	/* "collapse load", "seismic coefficient",
				 * "load factor" */
	const char *unit;	/* "N", or "" for a coefficient */
	const char *axis;	/* an axis label: name and unit */
	const char *what;	/* one line: what the value is */
};
void wall_quantity(const struct wall *w, struct wall_quantity *q);

/* "FILE:LINE:COLUMN: " prefix for mark m (or "FILE: " without mark). */
void wall_where(const struct wall *w, struct wall_mark m, char *buf,
		size_t len);

#endif
