/*
 * runlog.h - the samples file: one CSV row per sample, streamed.
 *
 * Format (SPEC section 4): a header line
 *   sample,status,lambda_max,lambda_min,iterations,xa_1,xb_1,...,xa_m,xb_m
 * then one row per sample in index order (0-based sample numbers), with
 * status "accepted" or the rejection reason (sample_status_name), loads
 * with 17 significant digits (empty when not computed), and the contact
 * positions in the interface order of `check --json`.
 *
 * Nothing is lost: every row is written with a single write(2) of the
 * whole line, so a process killed at any moment leaves only complete
 * rows (a row is never split between two writes).
 */
#ifndef SLIPWALL_RUNLOG_H
#define SLIPWALL_RUNLOG_H

#include "slipwall/mc.h"
#include "slipwall/wall.h"

struct runlog;

/* Create (truncate) path and write the header.  NULL + err on failure. */
struct runlog *runlog_open(const char *path, const struct wall *w, char *err);
/* Append one sample's row.  SW_EIO + err on a write error (disk full). */
enum sw_status runlog_write(struct runlog *l, const struct mc_item *it,
			    char *err);
/* Close; SW_EIO if anything failed to reach the file. */
enum sw_status runlog_close(struct runlog *l, char *err);
const char *runlog_path(const struct runlog *l);

/* Read the contact positions of a samples file (for --positions):
 * *rows rows of 2 * w->nifaces numbers, malloc'd into *xi.  Errors are
 * "FILE:LINE:COLUMN: message", SW_EINPUT; a file whose header has
 * another number of interfaces than w is refused (another wall's). */
enum sw_status runlog_read_positions(const char *path, const struct wall *w,
				     double **xi, long *rows, char *err);
/* Read the accepted lambda_min column of a samples file of wall w (for
 * report and compare); refused like runlog_read_positions when its
 * header does not have w's interfaces. */
enum sw_status runlog_read_loads(const char *path, const struct wall *w,
				 double **lam, long *n, char *err);

#endif
