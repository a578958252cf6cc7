/*
 * tui_knobs.c - settings that change no sample: the number of worker
 * threads (T) and the design load (G).
 *
 * A sample depends on the seed and its index only (docs/method.md), so
 * the thread count changes how fast the run goes, never what it finds:
 * a running pool is drained (the samples in progress are abandoned, as
 * a pause does) and a new one of the new size continues at the next
 * index, in the same samples file.
 *
 * The design load is analysis.design_load of the wall file: the
 * statistics pane then shows P(λ ≤ design) (tui_stats.c), and s saves
 * it.  It is written into the wall in place: no worker and no solve
 * reads it (the sampler reads the wall's blocks, loads and friction;
 * the solve thread has its own copy), so the run goes on.
 */
#include <stdio.h>

#include "slipwall/text.h"
#include "tui.h"

#define TUI_MAX_THREADS 256

static void tui_knobs_threads_typed(struct tui *t, const char *text)
{
	long n;
	if (text_parse_long(text, 1, TUI_MAX_THREADS, &n)) {
		tui_message(t, 1, "threads: a whole number from 1 to %d",
			    TUI_MAX_THREADS);
		return;
	}
	t->threads = (int)n;
	if (t->run.mc) {	/* a new pool of n workers, at the next index */
		tui_run_pause(t, 1);
		tui_run_pause(t, 0);
		tui_message(t, 0, "sampling on %d thread%s from sample %ld "
			    "(same samples)", t->threads, tui_s(t->threads),
			    t->run.done);
	} else {
		tui_message(t, 0, "%d thread%s from the next sampling",
			    t->threads, tui_s(t->threads));
	}
}

void tui_knobs_key_threads(struct tui *t, int ch)
{
	char buf[16];
	(void)ch;
	snprintf(buf, sizeof buf, "%d", t->threads);
	tui_prompt(t, "threads", buf, tui_knobs_threads_typed);
}

static void tui_knobs_design_typed(struct tui *t, const char *text)
{
	double v;
	if (text_parse_double(text, &v) || !(v >= 0) || v > 1e300) {
		tui_message(t, 1, "design load: a number >= 0 (%s; 0: none)",
			    tui_load_unit(t->w));
		return;
	}
	t->w->design_load = v;
	if (v > 0)
		tui_message(t, 0, "design load %g (%s): the pane shows P(%s <= design)",
			    v, tui_load_unit(t->w), tui_lam(t));
	else
		tui_message(t, 0, "no design load");
}

void tui_knobs_key_design(struct tui *t, int ch)
{
	char buf[32], label[64];
	(void)ch;
	snprintf(buf, sizeof buf, "%.6g", t->w->design_load);
	snprintf(label, sizeof label, "design load (%s; 0: none)",
		 tui_load_unit(t->w));
	tui_prompt(t, label, buf, tui_knobs_design_typed);
}
