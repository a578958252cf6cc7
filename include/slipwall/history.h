/*
 * history.h - the run history of the workbench: one row per run (what
 * changed, the friction, the contacts, the load, the counts, the
 * characteristic value with its interval, the median, p95, the samples
 * file), kept in a small index file beside the samples files so that it
 * survives quitting.
 *
 * The index is a tab-separated text file, `history.tsv` in the runs
 * directory: a header line naming the columns, then one line per run,
 * appended with one write(2) to a file opened O_APPEND, so that two
 * workbenches sharing the directory never interleave a line.  Numbers
 * are written with %.17g (NaN as "nan"), text with its tabs and line
 * breaks turned into spaces.  Readers skip lines they cannot parse
 * (a line cut by a crash, an older format).  The index is used only
 * when it is a regular file (opened O_NONBLOCK; a FIFO, a device or a
 * directory is an error), and a reader reads at most its last 4 MiB.
 */
#ifndef SLIPWALL_HISTORY_H
#define SLIPWALL_HISTORY_H

#include <limits.h>
#include <stddef.h>

#include <limits.h>

#include "slipwall/status.h"

struct history_row {
	char session[24];	/* when the session started, YYYYmmdd-HHMMSS */
	int run;		/* the run's number in its session */
	char wall[128];		/* the wall's name */
	char what[96];		/* what the run changed */
	double mu_bed, mu_head;
	double mu_cov;		/* friction's cov, 0: not random */
	double depth;
	int anywhere;		/* contacts.positions: anywhere */
	int load;		/* 0 point, 1 body, -1 none: the first load */
	double at[2], dir[2];	/* its point (point loads) and direction */
	long samples, accepted;
	double p05, p05_lo, p05_hi, p50, p95;	/* NaN: not known */
	char file[PATH_MAX];	/* the samples file */
};

/* Make the runs directory dir when it is missing (the front end says
 * where it is: the workbench's tui_file_runs_dir); -1 and err when it
 * cannot be made. */
int history_runs_make(const char *dir, char *err);
/* The index file in dir. */
int history_index_path(const char *dir, char *out, size_t len);
/* Append one row (the header first when the file is new or empty). */
enum sw_status history_append(const char *path, const struct history_row *r,
			      char *err);
/* Read the last max rows (all when max <= 0) of the last 4 MiB of the
 * file into *rows (malloc'd, the caller frees); a missing file is 0
 * rows, one that is not a regular file an error. */
enum sw_status history_read(const char *path, int max,
			    struct history_row **rows, int *n, char *err);

#endif
