/*
 * slipwall.h - the map of libslipwall: every module, its header, and
 * what it promises.  Including this one header gives the whole public
 * library; a front end may include the module headers one by one.
 *
 * Data flows one way: wall file -> model -> operator -> LPs -> samples
 * -> statistics -> files and figures.  Nothing here draws on a terminal
 * or knows of MPI; errors come back as `enum sw_status` with a message
 * "FILE:LINE:COLUMN: what is wrong" (or "what: why") in a caller's
 * buffer of SW_ERRLEN bytes.
 *
 * Private to the library (src/lib/): lp.h, the LP layer (its one
 * backend, lp_glpk.c, the only file that names the LP solver library);
 * statics.h, the equilibrium operator; and
 * support.h, the support basis (a starting basis built from how the
 * wall stands, for sample_start.c).
 */
#ifndef SLIPWALL_SLIPWALL_H
#define SLIPWALL_SLIPWALL_H

/* status    the status codes, their messages and exit codes; sw_fail,
 *           the version; allocation that never returns NULL */
#include "slipwall/status.h"
/* sys       the monotonic clock and mkdir -p, one copy each */
#include "slipwall/sys.h"
/* outfile   the one output policy: never an input, files written whole
 *           (PATH.tmp + rename), streams written directly, directories
 *           checked before any work */
#include "slipwall/outfile.h"
/* text      lines read with a bound; names and messages made safe to
 *           print; whole-string number parsing */
#include "slipwall/text.h"
/* json      a streaming JSON writer (no DOM) */
#include "slipwall/json.h"
/* wall      the model: blocks, supports, interfaces, loads; finished
 *           once (contacts found, checked), then read-only */
#include "slipwall/wall.h"
/* geom      convex polygons, contact detection between blocks */
#include "slipwall/geom.h"
/* layout    generated walls: courses of rectangular blocks */
#include "slipwall/layout.h"
/* wallfile  YAML wall files in and out, every error with its line and
 *           column; saves that keep the author's layout */
#include "slipwall/wallfile.h"
/* sample    one Monte Carlo sample (docs/method.md): its LPs, one
 *           answer per set of contact points whatever the solver's path */
#include "slipwall/sample.h"
/* solve     the single-solution methods: standard, gilbert, global */
#include "slipwall/solve.h"
/* record    one sample's record: the pool's, the MPI wire's, the tally's
 *           and the samples file's, declared once */
#include "slipwall/record.h"
/* mc        the sampler: a pool of worker threads, results in sample
 *           order, the same for any thread count */
#include "slipwall/mc.h"
/* tally     what a run has found so far: counts by status, the loads,
 *           the distinct mechanisms */
#include "slipwall/tally.h"
/* runlog    the samples file: one CSV row a sample, streamed, read back */
#include "slipwall/runlog.h"
/* run       one run: a source of samples in order to the samples file and
 *           the tally; --until-ci; the write-error and signal policies */
#include "slipwall/run.h"
/* stats     statistics of the loads: quantiles with intervals, the
 *           histogram, the KDE, the exact two-sample KS test */
#include "slipwall/stats.h"
/* collapse  the probability of collapse at a load */
#include "slipwall/collapse.h"
/* report    the paper's figures (cairo) and the Markdown summary */
#include "slipwall/report.h"
/* wedit     the edits of a wall: an editable copy, layout changes, a
 *           block put back or added, the load's stations on the outline */
#include "slipwall/wedit.h"
/* undo      the undo and redo stacks of a wall being edited */
#include "slipwall/undo.h"
/* history   the run history of the workbench (history.tsv) */
#include "slipwall/history.h"

#endif
