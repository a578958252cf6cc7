/*
 * runlog.h - the samples file: one CSV row per sample, streamed.
 *
 * Format (docs/run.md, "The samples file"): a header line
 *   sample,status,lambda_max,lambda_min,iterations,xa_1,xb_1,...,xa_m,xb_m
 * then one row per sample in index order (0-based sample numbers), with
 * status "accepted" or the rejection reason (sample_status_name), loads
 * with 17 significant digits (empty when not computed), and the contact
 * positions in the interface order of `check --json`.
 *
 * Nothing is lost: every row is written with a single write(2) of the
 * whole line.  A kill (SIGKILL) can still stop the kernel in the middle
 * of a write larger than a page, leaving the beginning of the last row
 * without its '\n': every reader below recognises that row, drops it
 * and says so in a warning.  Every other row is whole.
 *
 * Outputs never destroy inputs: runlog_create refuses a path that is
 * one of the inputs (the same file however it is spelled) and locks
 * the file (flock), so that a second process writing the same samples
 * file is refused instead of mixing its rows with the first one's.
 *
 * Readers are bounded: a line longer than its header allows (or than
 * 16 MiB for the header), more than 10^9 rows, or contact positions of
 * more than 8 GiB are refused with a message, as is a NUL byte.
 */
#ifndef SLIPWALL_RUNLOG_H
#define SLIPWALL_RUNLOG_H

#include "slipwall/draw.h"
#include "slipwall/record.h"
#include "slipwall/wall.h"

struct runlog;

/* Create path, or truncate it, and write the header; *l gets the log.
 * keep (NULL or NULL-terminated) names the input files of the run: a
 * path that is one of them, however spelled (device and inode), is
 * refused with SW_EINPUT, and so is a regular file that another process
 * holds open through runlog_create (an exclusive flock, held until
 * runlog_close).  SW_EIO when the file cannot be created.  A FIFO or a
 * character device is written to, not replaced; a FIFO that no process
 * reads is waited for, said on stderr first (outfile.h). */
enum sw_status runlog_create(struct runlog **l, const char *path,
			     const struct wall *w, const char *const *keep,
			     char *err);
/* Append one sample's row.  SW_EIO + err on a write error (disk full). */
enum sw_status runlog_write(struct runlog *l, const struct record *it,
			    char *err);
/* Close; SW_EIO if anything failed to reach the file. */
enum sw_status runlog_close(struct runlog *l, char *err);
const char *runlog_path(const struct runlog *l);

/* Read the draws of a samples file (for --positions): t->rows rows of
 * 2 * w->nifaces contact positions into t->xi and, when the file has
 * mu_k columns (random friction), of w->nifaces frictions into t->mu
 * (else NULL); malloc'd, draw_table_free frees them.  Errors are
 * "FILE:LINE:COLUMN: message", SW_EINPUT; a file whose header has
 * another number of interfaces than w is refused (another wall's), and
 * so is a file without frictions for a wall whose friction is random.
 * warn (SW_ERRLEN bytes, or NULL) gets "" or the warning of a cut last
 * row, which was dropped. */
enum sw_status runlog_read_draws(const char *path, const struct wall *w,
				 struct draw_table *t, char *warn, char *err);
/* Read the accepted loads of a samples file of wall w (for report and
 * compare): its lambda_min column times wall_quantity's scale, the
 * quantity people read (the force in N of a point load); refused like runlog_read_draws when its
 * header does not have w's interfaces, and at an accepted row whose
 * lambda_max is not a number or is below its lambda_min by more than
 * 1e-6 of itself; warn as above. */
enum sw_status runlog_read_loads(const char *path, const struct wall *w,
				 double **lam, long *n, char *warn, char *err);

#endif
