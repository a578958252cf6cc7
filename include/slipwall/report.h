/*
 * report.h - the paper's figures and a Markdown summary of a run.
 *
 * report_write() takes everything a run has produced (the accepted loads
 * in sample order, the distinct mechanisms, the experimental loads, the
 * single-solution values and the settings) and writes into a directory:
 *
 *   frequencies.{svg,pdf,png}      relative frequencies, model vs tests
 *                                  (the paper's Fig. 8, left)
 *   densities.*                    KDE of the model vs the best-fit normal
 *                                  of the tests; both normals grouped in
 *                                  the tests' number of classes (Fig. 8,
 *                                  centre and right)
 *   cumulative.*                   relative cumulative frequencies with
 *                                  the Kolmogorov-Smirnov result (Fig. 9)
 *   single-solutions.*             frequencies, KDE, normal fit, the 99 %
 *                                  interval of p05 and the single-solution
 *                                  values as vertical lines (Fig. 10)
 *   mechanisms.*                   the wall with its most frequent
 *                                  mechanisms (Fig. 6)
 *   convergence.*                  the running p05 and its 99 % band
 *                                  against the number of accepted samples
 *   report.md                      Table 1, the KS test, the settings and
 *                                  the version, links to the figures
 *
 * Without experimental loads the test-dependent curves are left out (the
 * figures are drawn for the model alone) and report.md says so.  Without
 * a tally the mechanism figure is not written.  Each figure is drawn by
 * one function onto a cairo context, once per surface (SVG, PDF, PNG).
 * cairo writes SVG text as glyph outlines; so that the numbers in an SVG
 * can be searched, copied and checked, report.c appends every label it
 * drew as a transparent <text> element (a text layer, like an OCR layer
 * in a scanned PDF) with the same position and size.
 *
 * No terminal code: the `report` command and the workbench both call
 * report_write() on the thread they run on.  Nothing here uses the LP solver.
 */
#ifndef SLIPWALL_REPORT_H
#define SLIPWALL_REPORT_H

#include <signal.h>

#include "slipwall/sample.h"
#include "slipwall/status.h"
#include "slipwall/tally.h"
#include "slipwall/wall.h"

/* One single-solution value for Fig. 10 and the summary. */
struct report_solution {
	const char *method;	/* "standard", "gilbert", "global" */
	int ran;		/* 0: not run (note says why) */
	int found;		/* 1: lambda is the method's load factor */
	double lambda;		/* the method's load factor lambda (report_write
				 * prints wall_quantity's scale times it) */
	char note[160];		/* for people: "not converged", "gap 3 %" */
};

/* How the loads were obtained: everything needed to reproduce them. */
struct report_run {
	const char *wall_path;	/* the wall file as given */
	const char *version;	/* the slipwall version (the caller's) */
	const char *command;	/* the command line, or NULL */
	const char *samples_file;	/* loads read from this CSV, or NULL */
	const char *tests_source;	/* where the tests came from, or NULL */
	int seed_known;		/* 0 when the loads came from a file */
	unsigned long seed;
	long requested;		/* samples asked for */
	int threads;
	double depth;		/* contact depth used (ignored if anywhere) */
	int anywhere;		/* contacts.positions: anywhere */
	int has_counts;		/* samples, accepted, rejected are known */
	long samples, accepted;
	long rejected[SAMPLE_STATUS_COUNT];	/* by status */
	const char *note;	/* one more line for the summary, or NULL */
	/* the wall sampled in words (the workbench: its friction,
	 * contacts, load, layout and what was edited since the file it
	 * came from), a row of the run's table; NULL: no row */
	const char *wall_desc;
};

struct report_input {
	const struct wall *w;	/* finished */
	const double *lam;	/* accepted loads in sample order: lambda_min
				 * times wall_quantity's scale, as a tally,
				 * run_all and runlog_read_loads give them */
	long nlam;		/* >= 1 */
	const struct tally *mech;	/* mechanisms, or NULL */
	const double *tests;	/* experimental collapse loads (in the same
				 * quantity: N for a point load), or NULL */
	long ntests;
	const struct report_solution *sol;
	int nsol;
	struct report_run run;
};

/* Formats, for report_opts.formats. */
#define REPORT_SVG 1
#define REPORT_PDF 2
#define REPORT_PNG 4
#define REPORT_ALL (REPORT_SVG | REPORT_PDF | REPORT_PNG)

struct report_opts {
	int formats;		/* REPORT_* bits (default all) */
	int max_mechanisms;	/* panels of Fig. 6, 1..6 (default 6) */
	double png_scale;	/* pixels per point (default 2.5) */
	/* NULL, or a flag a signal handler raises: report_write stops
	 * between two files, removes what it wrote and returns SW_EINTR */
	const volatile sig_atomic_t *cancel;
};
void report_opts_default(struct report_opts *o);

/* Write the figures and report.md into dir (created if missing; files
 * in it are overwritten).  o may be NULL for the defaults.  Returns
 * SW_OK; SW_EINPUT for unusable input (no loads, NaN loads), SW_EIO with
 * the file and the reason when something cannot be written, SW_EINTR
 * when o->cancel was raised.
 *
 * Complete or absent: everything is written into a new directory beside
 * dir (".NAME.XXXXXX" in its parent), which becomes dir by one rename
 * when dir does not exist; when it does, the files are renamed into it
 * one by one (each rename is atomic, and the figures of an earlier
 * report that this one does not draw are removed), so a reader sees the
 * old report, or the new one, never a report.md beside figures of
 * another run.  On a failure or a cancel the new directory is removed;
 * a SIGKILL can leave it behind (hidden), never a half-written dir. */
enum sw_status report_write(const struct report_input *in, const char *dir,
			    const struct report_opts *o, char *err);

/* A sweep (`slipwall sweep`): the load statistics at each value of one
 * parameter.  p05_lo/p05_hi are NaN where there is no interval. */
struct report_sweep_point {
	double value;
	long accepted;
	double p05, p05_lo, p05_hi, p50, p95;
};
struct report_sweep {
	const struct wall *w;	/* for the load axis */
	const char *xlabel;	/* the parameter, with its unit */
	const char *caption;	/* one line under the plot, or NULL */
	const char *version;	/* the slipwall version (PDF metadata) */
	const struct report_sweep_point *pt;	/* by increasing value */
	int n;			/* >= 1 */
};
/* Draw sweep.svg, sweep.pdf and sweep.png (o->formats) into dir
 * (created if missing): p05 with its 99 % band, p50 and p95 against
 * the value, in the style of the report's figures.  Errors as for
 * report_write; o->cancel stops it between two formats (SW_EINTR): the
 * formats drawn before are whole, the others not written. */
enum sw_status report_write_sweep(const struct report_sweep *s,
				  const char *dir, const struct report_opts *o,
				  char *err);

/* The files report_write (sweep 0) or report_write_sweep (sweep 1)
 * writes into its directory, or removes there (an older report's
 * figures): "frequencies.svg", ..., "report.md"; NULL-terminated.  For
 * the output policy's check of the directory (outfile_check_dir). */
const char *const *report_files(int sweep);

/* Free the process-wide caches of cairo and fontconfig (fonts, glyphs),
 * so that a leak checker sees a clean exit.  Call once, at exit, when
 * no thread is drawing; report_write() works again afterwards. */
void report_cleanup(void);

/* The axis label of the loads of this wall into axis (len bytes):
 * wall_quantity's ("collapse load (N)" for point loads of one
 * magnitude, a seismic coefficient or a load factor, no unit,
 * otherwise); *unit is what to print after a value (" N" or ""). */
void report_load_unit(const struct wall *w, char *axis, size_t len,
		      const char **unit);

#endif
