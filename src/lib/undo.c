/*
 * undo.c - the undo and redo stacks of an edited wall (undo.h).
 */
#include <stdlib.h>
#include <string.h>

#include "slipwall/undo.h"

void undo_init(struct undo *u, int cap)
{
	memset(u, 0, sizeof *u);
	u->cap = cap < 1 ? 1 : cap;
	u->past = sw_xcalloc((size_t)u->cap, sizeof *u->past);
	u->future = sw_xcalloc((size_t)u->cap, sizeof *u->future);
	u->next = 1;
}

static void undo_clear(struct undo_entry *e, int *n)
{
	for (int i = 0; i < *n; i++)
		wall_free(e[i].w);
	*n = 0;
}

void undo_free(struct undo *u)
{
	undo_clear(u->past, &u->npast);
	undo_clear(u->future, &u->nfuture);
	free(u->past);
	free(u->future);
	memset(u, 0, sizeof *u);
}

void undo_reset(struct undo *u)
{
	undo_clear(u->past, &u->npast);
	undo_clear(u->future, &u->nfuture);
	u->version = u->next++;
	u->saved = u->version;
}

/* Push onto a full-or-not stack: the oldest entry goes when full. */
static void undo_push(struct undo *u, struct undo_entry *stack, int *n,
		      struct wall *w, long version)
{
	if (*n == u->cap) {
		wall_free(stack[0].w);
		memmove(stack, stack + 1, sizeof *stack * (size_t)(u->cap - 1));
		(*n)--;
	}
	stack[*n].w = w;
	stack[*n].version = version;
	(*n)++;
}

void undo_edit(struct undo *u, const struct wall *cur)
{
	undo_push(u, u->past, &u->npast, wall_copy(cur), u->version);
	undo_clear(u->future, &u->nfuture);
	u->version = u->next++;
}

/* Move the top of `from` to the caller, cur onto `to`. */
static struct wall *undo_step(struct undo *u, struct undo_entry *from,
			      int *nfrom, struct undo_entry *to, int *nto,
			      const struct wall *cur)
{
	if (*nfrom == 0)
		return NULL;
	struct undo_entry e = from[--(*nfrom)];
	undo_push(u, to, nto, wall_copy(cur), u->version);
	u->version = e.version;
	return e.w;
}

struct wall *undo_undo(struct undo *u, const struct wall *cur)
{
	return undo_step(u, u->past, &u->npast, u->future, &u->nfuture, cur);
}

struct wall *undo_redo(struct undo *u, const struct wall *cur)
{
	return undo_step(u, u->future, &u->nfuture, u->past, &u->npast, cur);
}

int undo_modified(const struct undo *u)
{
	return u->version != u->saved;
}

void undo_saved(struct undo *u)
{
	u->saved = u->version;
}
