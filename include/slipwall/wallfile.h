/*
 * wallfile.h - wall files in YAML (docs/wall-format.md).
 *
 * Reading uses libyaml's document API, with checks libyaml does not make:
 * duplicate keys, unknown keys, types, finite numbers, alias expansion
 * limits, a size limit.  Every error is "FILE:LINE:COLUMN: message" and
 * SW_EINPUT.  The returned wall is finished (wall_finish has run).
 */
#ifndef SLIPWALL_WALLFILE_H
#define SLIPWALL_WALLFILE_H

#include <stddef.h>
#include "slipwall/wall.h"

#define WALLFILE_MAX_BYTES (16u << 20)	/* refuse larger files */
#define WALLFILE_MAX_NODES 2000000	/* refuse documents with more nodes */

enum sw_status wallfile_load(const char *path, struct wall **out, char *err);
/* The same from memory; name is used in messages. */
enum sw_status wallfile_parse(const char *buf, size_t len, const char *name,
			      struct wall **out, char *err);
/* One change to a wall file, made to its YAML document before the
 * document is read, exactly as editing the file would make it.  key is
 * a dotted path: material.friction, loads.0.point.at (list items count
 * from 0); mappings missing on the way are created, the last key is
 * added or its value replaced.  value is YAML text: a scalar, or a flow
 * list or mapping ("[0, 0.5]", "{bed: 0.6, head: 0.5}").  label names
 * the change in messages: an error in the value reads "LABEL: message"
 * (the checks of wall_finish have no place to point at for it). */
struct wallfile_edit {
	const char *key;
	const char *value;
	const char *label;
};
/* wallfile_load with the edits applied in order (edits may be NULL when
 * nedits is 0). */
enum sw_status wallfile_load_edited(const char *path,
				    const struct wallfile_edit *edits,
				    int nedits, struct wall **out, char *err);
/* Write w as YAML that loads again to the same model: material, its
 * layout or every free block as explicit vertices, supports, loads,
 * contacts, analysis, tests.  When w->path names a wall file, its text
 * is kept (comments, formatting) and only the values that differ are
 * changed in it, if the result loads to w; else the whole file is
 * written under that file's top comments (docs/wall-format.md,
 * "Saving").  Written whole (outfile: PATH.tmp, flushed, renamed over
 * PATH); PATH must be a regular file or a new one. */
enum sw_status wallfile_save(const struct wall *w, const char *path,
			     char *err);

#endif
