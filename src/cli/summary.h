/*
 * summary.h - what `report --samples FILE.csv` can reuse from the JSON
 * summary beside a samples file (the workbench's save writes X.yaml,
 * X.json beside X.csv; docs/workbench.md).
 *
 * Only the top-level keys this needs are read, from the pretty-printed
 * JSON that json.c writes (one key per line, two spaces in): "wall",
 * "wall_digest", "samples_file", "standard", "gilbert".  Anything else in the file is
 * ignored; a file that is not there or not of that shape gives nothing.
 */
#ifndef SLIPWALL_SUMMARY_H
#define SLIPWALL_SUMMARY_H

#include <stddef.h>

struct summary_file {
	char path[4096];	/* the JSON read */
	char wall[4096];	/* its "wall" ("" if none) */
	char samples_file[4096];	/* its "samples_file" ("" if none) */
	char wall_digest[64];	/* its "wall_digest" (wall_digest; "" if
				 * none) */
	int has_standard, has_gilbert;
	double standard, gilbert;
};

/* The JSON beside csv (X.csv -> X.json): 0 and *s filled when it exists
 * and names csv as its samples file (the same path, or the same file);
 * -1 otherwise. */
int summary_beside(const char *csv, struct summary_file *s);

#endif
