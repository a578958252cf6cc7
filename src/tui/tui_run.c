/*
 * tui_run.c - one sampling run of the workbench: the library's run
 * (run.h: the samples CSV, the tally, the write-error policy) on a
 * worker pool, driven from the UI thread.
 *
 * A run starts when a wall is loaded or edited, or on reset: a new
 * samples file (streamed from the first sample, one complete row per
 * write), a fresh tally, and a pool of t->threads workers for indices
 * 0 .. target-1 with the wall's seed, exactly as `slipwall run` would.
 *
 * Pause stops the pool (mc_stop), takes what the workers had finished
 * in order (the one in progress is abandoned) and frees it: `done`
 * samples, contiguous, are in the file.  Resume, or a target raised
 * after the pool has ended, starts a new pool at sample `done` (mc's
 * first): the file stays the one `run` writes.
 *
 * A row that cannot be written stops the run (run.h): the screen says
 * so, the run pauses for good ("write error"), and reset (r) starts a
 * new one; no sample is counted without its row.
 *
 * The set-up (every worker's canonical sample: docs/design.md, "The
 * shared set-up") is solved once by a pool; its bases (mc_setup) are
 * kept in t->setup when the pool is freed and given to the next pool,
 * which starts from them, without solving its own, when the wall has
 * the same shape: after a pause, and after an edit that keeps the
 * blocks and interfaces (friction, depth, a load, cov).  A sample's
 * answer does not depend on its start (docs/method.md, "One answer per
 * sample"), only its cost.
 *
 * tui_run_end() is called before the wall changes and at exit: it
 * drains the pool the same way, so every computed sample has its row,
 * and closes the file (which stays on disk); then t->run_ended (the
 * run history's row, set by tui_main) sees the whole tally before it
 * is freed.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/runlog.h"
#include "tui.h"

static void tui_run_free_pool(struct tui *t)
{
	struct tui_run *r = &t->run;
	if (!r->mc)
		return;
	tui_signal_watch(NULL);
	/* the pool's set-up, for the next pool (after a pause, or an edit
	 * that keeps the wall's shape); the pool reads t->setup until
	 * mc_free */
	struct sample_setup *s = mc_setup(r->mc);
	struct mc_progress pg;
	mc_progress(r->mc, &pg);
	r->worked += pg.worked;
	mc_free(r->mc);
	r->mc = NULL;
	if (s) {
		sample_setup_free(t->setup);
		t->setup = s;
	}
	r->active += sys_now() - r->t_start;
}

/* After each sample the run counted: the latest mechanism, the sample
 * browser's copy (tui_browse.c), the count. */
static void tui_run_each(void *ctx, const struct record *rec)
{
	struct tui *t = ctx;
	struct tui_run *r = &t->run;
	const struct wall *w = t->w;
	if (rec->status == SAMPLE_ACCEPTED) {
		memcpy(r->latest_joint, rec->joint, (size_t)w->nifaces + 1);
		memcpy(r->latest_vel, rec->vel,
		       sizeof(double) * 3 * (size_t)w->nblocks);
		r->latest_index = rec->index;
	}
	tui_browse_push(t, rec);
	r->done++;
}

/* A write error stopped the run: say so, and sample no more. */
static void tui_run_failed(struct tui *t)
{
	struct tui_run *r = &t->run;
	tui_message(t, 1, "samples file: %s: sampling stopped (r starts a "
		    "new run)", r->core.werr);
	r->paused = 1;
}

/* Stop the pool and take every sample it finished in order (those in
 * progress are abandoned: mc_stop). */
static void tui_run_drain(struct tui *t)
{
	struct tui_run *r = &t->run;
	if (!r->mc)
		return;
	mc_stop(r->mc);
	run_drain(&r->core);
	tui_run_free_pool(t);
	if (r->core.stop == RUN_WRITE)
		tui_run_failed(t);
}

/* Start a pool for the next samples, if any are wanted. */
static void tui_run_spawn(struct tui *t)
{
	struct tui_run *r = &t->run;
	char err[SW_ERRLEN];

	if (r->mc || r->paused || r->done >= r->target ||
	    r->core.stop == RUN_WRITE || tui_signal_pending())
		return;
	r->cfg.threads = t->threads;
	r->cfg.first = r->done;		/* resume where the file ends */
	r->cfg.n = r->target;
	/* the last pool's set-up: used when this wall has its shape
	 * (mc.c, sample_setup_fits), else the pool solves its own */
	r->cfg.setup = t->setup;
	r->mc = mc_start(&r->cfg, err);
	if (!r->mc) {
		tui_message(t, 1, "cannot start the sampler: %s", err);
		r->paused = 1;
		return;
	}
	run_source_pool(&r->src, r->mc);
	r->t_start = sys_now();
	tui_signal_watch(r->mc);
}

void tui_run_start(struct tui *t)
{
	struct tui_run *r = &t->run;
	const struct wall *w = t->w;
	char err[SW_ERRLEN];

	memset(r, 0, sizeof *r);
	r->apriori = tui_pace_apriori(t);
	r->target = t->target > 0 ? t->target : (w->samples > 0 ? w->samples : 1000);
	r->latest_index = -1;
	r->latest_joint = calloc((size_t)w->nifaces + 1, 1);
	r->latest_vel = calloc(3 * (size_t)w->nblocks + 1, sizeof(double));
	tally_init(&r->tally, w);
	r->fams = sw_xmalloc(sizeof *r->fams);
	family_set_init(r->fams, w);
	tui_browse_reset(t);
	mc_config_default(&r->cfg, w);
	r->cfg.opts.lp = tui_lp;
	t->runno++;
	snprintf(r->what, sizeof r->what, "%s", t->next_what[0] ? t->next_what : "reset");
	t->next_what[0] = 0;
	if (tui_file_csv_path(t, r->csv, sizeof r->csv, err) == 0) {
		const char *keep[] = {w->path, NULL};
		if (runlog_create(&r->log, r->csv, w, keep, err) != SW_OK)
			tui_message(t, 1, "%s", err);
	} else {
		tui_message(t, 1, "%s", err);
	}
	if (r->log) {
		tui_note_file(t, "samples", r->csv);
		tui_file_save_run_wall(t);	/* X.yaml beside X.csv */
	} else {
		r->csv[0] = 0;
	}
	run_init(&r->core, w, &r->src, &r->tally, r->log);
	r->core.each = tui_run_each;
	r->core.each_ctx = t;
	tui_run_spawn(t);
}

struct family_set *tui_run_families(const struct tui *t)
{
	struct family_set *fs = t->run.fams;
	if (fs)
		family_update(fs, &t->run.tally);
	return fs;
}

int tui_run_family_of(const struct tui *t, const struct family_set *fs,
		      const char *joint)
{
	int m = fs ? tally_find(&t->run.tally, joint) : -1;
	return m >= 0 && m < fs->nseen ? fs->of[m] : -1;
}

void tui_run_end(struct tui *t)
{
	struct tui_run *r = &t->run;
	char err[SW_ERRLEN];

	if (!r->latest_joint)
		return;		/* never started */
	tui_run_drain(t);
	/* measured, while its wall is t->w: its worker seconds a sample
	 * seed the next run's a-priori figure (tui_pace_apriori) */
	if (r->done > 0 && r->worked > 0) {
		t->pace_s = r->worked / (double)r->done;
		t->pace_apriori = r->apriori;
		snprintf(t->pace_path, sizeof t->pace_path, "%s",
			 t->w->path ? t->w->path : "");
	}
	if (r->log && runlog_close(r->log, err) != SW_OK)
		tui_message(t, 1, "samples file: %s", err);
	r->log = NULL;
	if (t->run_ended)
		t->run_ended(t);	/* the history's row (tui_main) */
	run_free(&r->core);
	tally_free(&r->tally);
	family_set_free(r->fams);
	free(r->fams);
	r->fams = NULL;
	tui_browse_free(t);
	free(r->latest_joint);
	free(r->latest_vel);
	r->latest_joint = NULL;
	r->latest_vel = NULL;
}

/* Pops what is ready, for at most budget seconds.  Returns -1 when it
 * stopped with more ready (come back at once), else whether the screen
 * changed: a sample counted, or the pool ended (the target reached, a
 * write error).  The end alone counts too: a write error on a row that
 * comes by itself, after the last frame, with the solve thread done, is
 * otherwise never drawn (seen in CI: the screen said "running" for
 * 90 s). */
int tui_run_pump(struct tui *t, double budget)
{
	struct tui_run *r = &t->run;
	double t0 = sys_now();
	int changed = 0;
	long n = 0;

	while (r->mc) {
		int got = run_pump(&r->core, 0);
		if (got == 0)
			break;
		changed = 1;	/* a sample, or the end of the pool */
		if (r->core.stop == RUN_WRITE) {
			tui_run_drain(t);	/* says so */
			break;
		}
		if (got < 0) {
			/* the pool is through its indices (a target raised
			 * meanwhile: a new one) */
			tui_run_free_pool(t);
			tui_run_spawn(t);
			continue;
		}
		if (r->done >= r->target) {
			tui_run_drain(t);
			break;
		}
		if ((++n & 63) == 0 && sys_now() - t0 > budget)
			return -1;
	}
	return changed;
}

void tui_run_pause(struct tui *t, int pause)
{
	struct tui_run *r = &t->run;
	if (pause) {
		r->paused = 1;
		tui_run_drain(t);
	} else {
		r->paused = 0;
		tui_run_spawn(t);
	}
}

void tui_run_set_target(struct tui *t, long n)
{
	struct tui_run *r = &t->run;
	t->target = n;
	r->target = n;
	if (r->done >= n)
		tui_run_drain(t);
	else
		tui_run_spawn(t);
}

int tui_run_progress(struct tui *t, struct mc_progress *p)
{
	memset(p, 0, sizeof *p);
	if (!t->run.mc)
		return 0;
	mc_progress(t->run.mc, p);
	return 1;
}

void tui_duration(char *buf, size_t len, double s)
{
	if (!isfinite(s) || s < 0) {
		snprintf(buf, len, "?");
		return;
	}
	long v = (long)(s + 0.5);
	if (v < 60)
		snprintf(buf, len, "%ld s", v);
	else if (v < 3600)
		snprintf(buf, len, "%ld:%02ld", v / 60, v % 60);
	else
		snprintf(buf, len, "%ld:%02ld:%02ld", v / 3600, v / 60 % 60, v % 60);
}

double tui_run_rate(const struct tui *t)
{
	const struct tui_run *r = &t->run;
	double s = r->active + (r->mc ? sys_now() - r->t_start : 0);
	return s > 0 ? (double)r->done / s : NAN;
}

const char *tui_run_state(const struct tui *t)
{
	const struct tui_run *r = &t->run;
	if (r->mc)
		return "running";
	if (r->core.stop == RUN_WRITE)
		return "write error";
	if (r->done >= r->target)
		return "done";
	return r->paused ? "paused" : "stopped";
}
