/*
 * undo.h - the undo and redo stacks of a wall being edited (the
 * workbench's u, U and Ctrl-R), and whether it differs from the wall
 * last loaded or saved (the * in the title).
 *
 * Walls are immutable once finished (wall.h), so an edit replaces the
 * current wall by a new one; the stacks keep deep copies (wall_copy) of
 * the walls replaced.  Every wall state has a version number: the
 * current one is u->version, and undo_modified() compares it with the
 * version last saved, so undoing back to the saved wall clears the mark.
 * At most `cap` steps are kept; the oldest go first.
 *
 * The caller owns the current wall; the stacks own their copies.
 */
#ifndef SLIPWALL_UNDO_H
#define SLIPWALL_UNDO_H

#include "slipwall/wall.h"

struct undo_entry {
	struct wall *w;		/* owned copy */
	long version;
};

struct undo {
	struct undo_entry *past, *future;	/* stacks: last = top */
	int npast, nfuture, cap;
	long version;		/* the current wall's */
	long next;		/* the next version number */
	long saved;		/* the version last loaded or saved */
};

/* Empty stacks keeping at most cap (>= 1) steps; the current wall is
 * version 0, unmodified. */
void undo_init(struct undo *u, int cap);
void undo_free(struct undo *u);
/* A wall opened from a file: empty stacks, unmodified. */
void undo_reset(struct undo *u);
/* cur (finished) is being replaced by an edited wall: keep a copy of cur
 * for undo, forget the redo stack, and give the new wall a version. */
void undo_edit(struct undo *u, const struct wall *cur);
/* The wall to go back to (a new copy, owned by the caller), keeping a
 * copy of cur for redo; NULL when there is nothing to undo. */
struct wall *undo_undo(struct undo *u, const struct wall *cur);
/* The same forwards. */
struct wall *undo_redo(struct undo *u, const struct wall *cur);
/* The current wall differs from the one last loaded or saved. */
int undo_modified(const struct undo *u);
/* The current wall has just been saved. */
void undo_saved(struct undo *u);

#endif
