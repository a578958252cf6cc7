/*
 * wallkeep.h - private to src/lib: keeping a wall file's comments and
 * formatting when a changed wall is saved over it (wallkeep.c).  It
 * parses YAML with the one limited parser of wallfile.c, which the
 * caller passes (so wallkeep.c needs nothing of wallfile.c).
 */
#ifndef SLIPWALL_WALLKEEP_H
#define SLIPWALL_WALLKEEP_H

#include <stddef.h>

#include <yaml.h>

/* A YAML parser with the limits of a wall file (size, nesting depth,
 * node count, one document): buf into *doc, which the caller deletes;
 * -1 and a "NAME:LINE:COLUMN: what" message in err (SW_ERRLEN) on any
 * error, *doc then empty.  wallfile.c's wallfile_yaml_load. */
typedef int (*wallkeep_yaml_fn)(const char *buf, size_t len,
				const char *name, yaml_document_t *doc,
				char *err);

/* orig is a wall file whose model wallfile_save writes as the text old;
 * the changed model is written as the text new.  The text of orig with
 * the values that differ between old and new replaced (or added) in
 * place: malloc'd, its length in *len; NULL when the change cannot be
 * made in place (a list that grew or shrank, a key that went, a value
 * over several lines).  parse reads the three texts.  The caller
 * checks that the result loads to the new model (wallfile_save does). */
char *wallkeep_patch(const char *orig, size_t olen, const char *old,
		     size_t oldlen, const char *new, size_t newlen,
		     size_t *len, wallkeep_yaml_fn parse);

/* The comment lines (and blank lines) at the top of text: their
 * length. */
size_t wallkeep_header(const char *text, size_t len);

#endif
