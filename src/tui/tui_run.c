/*
 * tui_run.c - one sampling run of the workbench: the worker pool, the
 * samples CSV and the tally, driven from the UI thread.
 *
 * A run starts when a wall is loaded or edited, or on reset: a new
 * samples file (streamed from the first sample, one complete row per
 * write), a fresh tally, and a pool of t->threads workers for indices
 * 0 .. target-1 with the wall's seed, exactly as `slipwall run` would.
 *
 * Pause stops the pool (mc_stop), pops what the workers had finished or
 * were computing (mc_pop waits for those), and frees it: `done` samples,
 * contiguous, are in the file.  Resume, or a target raised after the
 * pool has ended, starts a new pool on a replay table of the positions
 * of (seed, done + i), in chunks of bounded memory, and adds `done` to
 * the indices it returns: the file stays the one `run` writes.
 *
 * tui_run_end() is called before the wall changes and at exit: it
 * drains the pool the same way, so every computed sample has its row,
 * and closes the file (which stays on disk).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/runlog.h"
#include "tui.h"

/* Replay chunks: at most this many samples (the table is built on the
 * UI thread, a few microseconds a row) and this many doubles (16 MB). */
#define TUI_RUN_CHUNK 4096L
#define TUI_RUN_TABLE_MAX (2L << 20)

static void tui_run_free_pool(struct tui *t)
{
	struct tui_run *r = &t->run;
	if (!r->mc)
		return;
	tui_signal_watch(NULL);
	mc_free(r->mc);
	r->mc = NULL;
	free(r->table);
	r->table = NULL;
	r->active += sys_now() - r->t_start;
}

/* One popped sample: to the file, to the tally. */
static void tui_run_take(struct tui *t)
{
	struct tui_run *r = &t->run;
	const struct wall *w = t->w;
	char err[SW_ERRLEN];

	r->item.index += r->base;
	if (r->log && runlog_write(r->log, &r->item, err) != SW_OK) {
		tui_message(t, 1, "samples file: %s (no more rows written)", err);
		runlog_close(r->log, err);
		r->log = NULL;
	}
	tally_add(&r->tally, &r->item);
	if (r->item.status == SAMPLE_ACCEPTED) {
		memcpy(r->latest_joint, r->item.joint, (size_t)w->nifaces + 1);
		memcpy(r->latest_vel, r->item.vel,
		       sizeof(double) * 3 * (size_t)w->nblocks);
		r->latest_index = r->item.index;
	}
	r->done++;
}

/* Stop the pool and take every sample it finished in order (those in
 * progress are abandoned: mc_stop). */
static void tui_run_drain(struct tui *t)
{
	struct tui_run *r = &t->run;
	if (!r->mc)
		return;
	mc_stop(r->mc);
	while (mc_pop(r->mc, &r->item, -1) == 1)
		tui_run_take(t);
	tui_run_free_pool(t);
}

/* Start a pool for the next samples, if any are wanted. */
static void tui_run_spawn(struct tui *t)
{
	struct tui_run *r = &t->run;
	const struct wall *w = t->w;
	char err[SW_ERRLEN];

	if (r->mc || r->paused || r->done >= r->target || tui_signal_pending())
		return;
	mc_config_default(&r->cfg, w);
	r->cfg.threads = t->threads;
	r->base = r->done;
	if (r->done == 0) {
		r->cfg.n = r->target;
	} else {
		long row = 2L * w->nifaces;
		long n = r->target - r->done;
		long cap = TUI_RUN_TABLE_MAX / (row > 0 ? row : 1);
		if (cap > TUI_RUN_CHUNK)
			cap = TUI_RUN_CHUNK;
		if (n > cap)
			n = cap > 0 ? cap : 1;
		r->table = malloc(sizeof(double) * (size_t)(n * row + 1));
		if (!r->table) {
			tui_message(t, 1, "out of memory for the replay table");
			r->paused = 1;
			return;
		}
		for (long i = 0; i < n; i++)
			mc_positions(w, r->cfg.seed,
				     (unsigned long)(r->done + i), -1,
				     r->table + i * row);
		r->cfg.n = n;
		r->cfg.positions = r->table;
	}
	r->mc = mc_start(&r->cfg, err);
	if (!r->mc) {
		free(r->table);
		r->table = NULL;
		tui_message(t, 1, "cannot start the sampler: %s", err);
		r->paused = 1;
		return;
	}
	r->t_start = sys_now();
	tui_signal_watch(r->mc);
}

void tui_run_start(struct tui *t)
{
	struct tui_run *r = &t->run;
	const struct wall *w = t->w;
	char err[SW_ERRLEN];

	memset(r, 0, sizeof *r);
	r->target = t->target > 0 ? t->target : (w->samples > 0 ? w->samples : 1000);
	r->latest_index = -1;
	r->latest_joint = calloc((size_t)w->nifaces + 1, 1);
	r->latest_vel = calloc(3 * (size_t)w->nblocks + 1, sizeof(double));
	tally_init(&r->tally, w);
	mc_item_init(&r->item, w);
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
	} else {
		r->csv[0] = 0;
	}
	tui_run_spawn(t);
}

void tui_run_end(struct tui *t)
{
	struct tui_run *r = &t->run;
	char err[SW_ERRLEN];

	if (!r->latest_joint)
		return;		/* never started */
	tui_run_drain(t);
	if (r->log && runlog_close(r->log, err) != SW_OK)
		tui_message(t, 1, "samples file: %s", err);
	r->log = NULL;
	tui_history_record(t);
	tally_free(&r->tally);
	mc_item_free(&r->item);
	free(r->latest_joint);
	free(r->latest_vel);
	r->latest_joint = NULL;
	r->latest_vel = NULL;
}

int tui_run_pump(struct tui *t, double budget)
{
	struct tui_run *r = &t->run;
	double t0 = sys_now();
	int n = 0;

	while (r->mc) {
		int got = mc_pop(r->mc, &r->item, 0);
		if (got == 0)
			break;
		if (got < 0) {
			/* the pool is through its indices: next chunk */
			tui_run_free_pool(t);
			tui_run_spawn(t);
			continue;
		}
		tui_run_take(t);
		n++;
		if (r->done >= r->target) {
			tui_run_drain(t);
			break;
		}
		if ((n & 63) == 0 && sys_now() - t0 > budget)
			return -1;
	}
	return n;
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
	if (r->done >= r->target)
		return "done";
	return r->paused ? "paused" : "stopped";
}
