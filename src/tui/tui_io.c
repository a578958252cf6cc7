/*
 * tui_io.c - the main screen's keys that read and write files: save (s),
 * open (o), report (R).  Each asks for a path on the prompt line.
 *
 * Save asks for the wall's path (default: beside the opened wall file,
 * tui_report.c; else the samples file's with .yaml) and writes the wall with wallfile_save (PATH.tmp then rename)
 * and a JSON summary of the run beside it (.json, same way), after
 * checking both against the output policy (outfile.h: not the samples
 * file being streamed, not a FIFO, a device or a directory).  Open asks
 * for a path; a file that does not load leaves the current wall and
 * shows the reader's FILE:LINE:COLUMN message.  Report writes what
 * `slipwall report` writes, for the current run, and the wall sampled
 * beside it (DIR/wall.yaml) with its description and the command that
 * reproduces it (tui_report.c).
 */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "slipwall/json.h"
#include "slipwall/outfile.h"
#include "slipwall/stats.h"
#include "slipwall/report.h"
#include "slipwall/wallfile.h"
#include "tui.h"

static void tui_io_json(struct tui *t, FILE *f, const char *wallpath)
{
	const struct tally *ta = &t->run.tally;
	const struct wall *w = t->w;
	struct stats_summary s;
	struct json j;

	tally_summary(ta, &s);
	json_init(&j, f, 1);
	json_object_begin(&j);
	json_key(&j, "wall");
	json_string(&j, wallpath);
	json_key(&j, "source");
	if (w->path)
		json_string(&j, w->path);
	else
		json_null(&j);
	char digest[WALL_DIGEST_LEN];
	wall_digest(w, digest);
	json_key_string(&j, "wall_digest", digest);
	json_key(&j, "samples_file");
	if (t->run.csv[0])
		json_string(&j, t->run.csv);
	else
		json_null(&j);
	json_key(&j, "seed");
	json_uint(&j, w->seed);
	json_key(&j, "threads");
	json_int(&j, t->threads);
	json_key(&j, "target");
	json_int(&j, t->run.target);
	tally_json(ta, &j);
	json_key(&j, "samples_per_second");
	json_double(&j, tui_run_rate(t));
	json_key(&j, "mechanisms");
	json_int(&j, ta->nmech);
	json_key(&j, "standard");
	if (t->solve_done && t->has_std)
		json_double(&j, tui_load(t, t->lam_std));
	else
		json_null(&j);
	json_key(&j, "gilbert");
	if (t->solve_done && t->has_gil)
		json_double(&j, tui_load(t, t->lam_gil));
	else
		json_null(&j);
	if (w->ntests > 0) {
		struct stats_ks ks;
		json_key(&j, "ks");
		if (ta->lam.n > 0 &&
		    stats_ks2(ta->lam.x, ta->lam.n, w->tests, (size_t)w->ntests,
			      &ks) == 0) {
			json_object_begin(&j);
			json_key(&j, "statistic");
			json_double(&j, ks.d);
			json_key(&j, "p_two_sided");
			json_double(&j, ks.p_two_sided);
			json_key(&j, "p_less");
			json_double(&j, ks.p_less);
			json_key(&j, "p_greater");
			json_double(&j, ks.p_greater);
			json_object_end(&j);
		} else {
			json_null(&j);
		}
	}
	json_object_end(&j);
	json_end(&j);
}

/* Write the summary whole or not at all (outfile: PATH.tmp, then
 * renamed), never over an input. */
static int tui_io_summary(struct tui *t, const char *path,
			  const char *wallpath, const char *const *inputs,
			  char *err)
{
	struct outfile out;
	if (outfile_open(&out, path, inputs, 0, "the summary", err) != SW_OK)
		return -1;
	tui_io_json(t, out.f, wallpath);
	return outfile_commit(&out, err) == SW_OK ? 0 : -1;
}

/* The summary's path beside the wall's: PATH without .yaml, plus
 * .json.  0, or -1 when it is too long. */
static int tui_io_json_path(const char *path, char *json, size_t len)
{
	snprintf(json, len, "%s", path);
	char *dot = strrchr(json, '.');
	char *slash = strrchr(json, '/');
	if (dot && (!slash || dot > slash) &&
	    (!strcmp(dot, ".yaml") || !strcmp(dot, ".yml")))
		*dot = 0;
	if (strlen(json) + 6 > len)
		return -1;
	strcat(json, ".json");
	return 0;
}

static void tui_io_save_to(struct tui *t, const char *path)
{
	char err[SW_ERRLEN], json[PATH_MAX];
	if (!path[0]) {
		tui_message(t, 1, "save: no path given");
		return;
	}
	if (tui_io_json_path(path, json, sizeof json)) {
		tui_message(t, 1, "save: path too long");
		return;
	}
	/* the output policy (outfile.h): neither file may be the samples
	 * file being streamed, nor a FIFO, a device or a directory; both
	 * are checked before either is written */
	const char *inputs[] = {t->run.csv[0] ? t->run.csv : NULL, NULL};
	if (outfile_check(path, inputs, 0, "the wall", err) != SW_OK ||
	    outfile_check(json, inputs, 0, "the summary", err) != SW_OK) {
		tui_message(t, 1, "save: %s: nothing saved", err);
		return;
	}
	/* analysis.samples follows the target the user set */
	struct wall *c = wall_copy(t->w);
	c->samples = t->run.target > 0x7fffffffL ? 0x7fffffff : (int)t->run.target;
	enum sw_status st = wallfile_save(c, path, err);
	wall_free(c);
	if (st != SW_OK) {
		tui_message(t, 1, "save: %s", err);
		return;
	}
	if (tui_io_summary(t, json, path, inputs, err)) {
		tui_message(t, 1, "saved %s; summary: %s", path, err);
		return;
	}
	undo_saved(&t->undo);
	tui_note_file(t, "wall", path);
	tui_note_file(t, "summary", json);
	tui_message(t, 0, "saved %s and %s; samples: %s", path, json,
		    t->run.csv[0] ? t->run.csv : "(none)");
}

void tui_io_save(struct tui *t)
{
	char def[PATH_MAX];
	/* beside the opened wall file (tui_report.c), else the samples */
	if (tui_report_default(t, ".yaml", def, sizeof def) == 0)
		;
	else if (t->run.csv[0]) {
		snprintf(def, sizeof def, "%s", t->run.csv);
		char *dot = strrchr(def, '.');
		if (dot && !strcmp(dot, ".csv"))
			*dot = 0;
		if (strlen(def) + 6 < sizeof def)
			strcat(def, ".yaml");
	} else {
		char stem[128];
		tui_file_stem(t->w, stem, sizeof stem);
		snprintf(def, sizeof def, "%s-edited.yaml", stem);
	}
	tui_prompt(t, "save wall as", def, tui_io_save_to);
}

static void tui_io_open_path(struct tui *t, const char *path)
{
	char err[SW_ERRLEN];
	struct wall *nw;
	if (!path[0]) {
		tui_message(t, 1, "open: no path given");
		return;
	}
	/* stat first: opening a FIFO or a terminal for reading would
	 * block the UI thread (a FIFO until a writer comes) */
	struct stat st;
	if (stat(path, &st) != 0) {
		tui_message(t, 1, "open: %s: %s", path, strerror(errno));
		return;
	}
	if (!S_ISREG(st.st_mode)) {
		tui_message(t, 1, "open: %s: not a regular file (%s)", path,
			    S_ISDIR(st.st_mode) ? "a directory" :
			    S_ISFIFO(st.st_mode) ? "a FIFO" :
			    S_ISCHR(st.st_mode) ? "a device" : "not a file");
		return;
	}
	if (wallfile_load(path, &nw, err) != SW_OK) {
		tui_message(t, 1, "%s", err);
		return;
	}
	undo_reset(&t->undo);
	snprintf(t->next_what, sizeof t->next_what, "opened %s", path);
	tui_edit_set_wall(t, nw);
	tui_message(t, 0, "opened %s: sampling (run %d)", path, t->runno);
	tui_edit_lock_message(t);
}

void tui_io_open(struct tui *t)
{
	tui_prompt(t, "open wall file", "", tui_io_open_path);
}

/* R: the figures and summary of `slipwall report` for the current run,
 * written by the library (report_write) from the run's samples file (its
 * accepted loads in sample order) and tally (its mechanisms). */
static void tui_io_report_to(struct tui *t, const char *dir)
{
	char err[SW_ERRLEN];
	double *lam = NULL;
	long n = 0;
	if (!dir[0]) {
		tui_message(t, 1, "report: no directory given");
		return;
	}
	/* the output policy (outfile.h): a directory or one that can be
	 * made, none of its files the samples file or the wall */
	const char *inputs[] = {t->run.csv[0] ? t->run.csv : NULL, t->w->path,
				NULL};
	if (!inputs[0])
		inputs[0] = t->w->path, inputs[1] = NULL;
	if (outfile_check_dir(dir, report_files(0), inputs, "the report",
			      err) != SW_OK) {
		tui_message(t, 1, "report: %s", err);
		return;
	}
	/* the wall sampled is saved beside the report (tui_report.c) */
	char wallpath[PATH_MAX];
	if ((size_t)snprintf(wallpath, sizeof wallpath, "%s%swall.yaml", dir,
			     dir[strlen(dir) - 1] == '/' ? "" : "/") >=
	    sizeof wallpath) {
		tui_message(t, 1, "report: path too long");
		return;
	}
	struct stat dst;	/* a new directory has no wall.yaml yet */
	if (stat(dir, &dst) == 0 &&
	    outfile_check(wallpath, inputs, 0, "the wall", err) != SW_OK) {
		tui_message(t, 1, "report: %s", err);
		return;
	}
	if (!t->run.csv[0] ||
	    runlog_read_loads(t->run.csv, t->w, &lam, &n, NULL, err) != SW_OK) {
		tui_message(t, 1, "report: %s", t->run.csv[0] ? err : "no samples file");
		return;
	}
	if (n < 1) {
		free(lam);
		tui_message(t, 1, "report: no accepted sample yet");
		return;
	}
	struct report_solution sol[2];
	memset(sol, 0, sizeof sol);
	sol[0].method = "standard";
	sol[0].ran = sol[0].found = t->has_std;
	sol[0].lambda = t->lam_std;
	sol[1].method = "gilbert";
	sol[1].ran = sol[1].found = t->has_gil;
	sol[1].lambda = t->lam_gil;
	for (int i = 0; i < 2; i++)
		if (!sol[i].ran)
			snprintf(sol[i].note, sizeof sol[i].note,
				 "not computed yet");
	struct report_input in;
	memset(&in, 0, sizeof in);
	in.w = t->w;
	in.lam = lam;
	in.nlam = n;
	in.mech = &t->run.tally;
	in.tests = t->w->ntests ? t->w->tests : NULL;
	in.ntests = t->w->ntests;
	in.sol = sol;
	in.nsol = 2;
	in.run.wall_path = wallpath;
	in.run.version = sw_version();
	in.run.samples_file = t->run.csv;
	in.run.seed_known = 1;
	in.run.seed = t->run.cfg.seed;
	in.run.requested = t->run.target;
	in.run.threads = t->threads;
	in.run.depth = t->w->depth;
	in.run.anywhere = t->w->anywhere;
	in.run.has_counts = 1;
	in.run.samples = t->run.tally.samples;
	in.run.accepted = t->run.tally.accepted;
	memcpy(in.run.rejected, t->run.tally.rejected, sizeof in.run.rejected);
	/* "while sampling" only while it samples (issue 27) */
	char note[256];
	const char *state = tui_run_state(t);
	if (!strcmp(state, "running"))
		snprintf(note, sizeof note, "Written from the workbench (key R) "
			 "while sampling: %ld of the run's %ld samples computed.",
			 t->run.tally.samples, t->run.target);
	else if (!strcmp(state, "done"))
		snprintf(note, sizeof note, "Written from the workbench (key R) "
			 "after the run ended: all its %ld samples computed.",
			 t->run.tally.samples);
	else
		snprintf(note, sizeof note, "Written from the workbench (key R) "
			 "while the run was %s: %ld of its %ld samples computed.",
			 state, t->run.tally.samples, t->run.target);
	in.run.note = note;
	char *cmd = tui_report_command(t, wallpath, dir);
	char *desc = tui_report_describe(t, wallpath);
	in.run.command = cmd;
	in.run.wall_desc = desc;
	enum sw_status st = report_write(&in, dir, NULL, err);
	free(lam);
	free(cmd);
	free(desc);
	if (st == SW_OK) {
		/* the wall as sampled: its analysis.samples and seed those of
		 * the run, so that `slipwall run` alone repeats it too */
		struct wall *c = wall_copy(t->w);
		c->samples = t->run.tally.samples > 0x7fffffffL ? 0x7fffffff :
			     (int)t->run.tally.samples;
		c->seed = t->run.cfg.seed;
		st = wallfile_save(c, wallpath, err);
		wall_free(c);
	}
	if (st != SW_OK)
		tui_message(t, 1, "report: %s", err);
	else
	{
		char md[PATH_MAX + 16];
		snprintf(md, sizeof md, "%s/report.md", dir);
		tui_note_file(t, "report", md);
		tui_note_file(t, "wall", wallpath);
		tui_message(t, 0, "report of %ld accepted samples in %s; the wall "
			    "in %s", n, md, wallpath);
	}
}

void tui_io_report(struct tui *t)
{
	char def[PATH_MAX];
	if (!t->run.csv[0]) {
		tui_message(t, 1, "report: no samples file");
		return;
	}
	/* beside the opened wall file (tui_report.c), else the samples */
	if (tui_report_default(t, "-report", def, sizeof def) != 0) {
		snprintf(def, sizeof def, "%s", t->run.csv);
		char *dot = strrchr(def, '.');
		if (dot && !strcmp(dot, ".csv"))
			*dot = 0;
		if (strlen(def) + 8 < sizeof def)
			strcat(def, "-report");
	}
	tui_prompt(t, "write report to directory", def, tui_io_report_to);
}
