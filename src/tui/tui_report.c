/*
 * tui_report.c - what the workbench's report (R) says about the run
 * beyond what `slipwall report` says (issue 27), and where the save
 * (s) and the report go by default.
 *
 * A report of the workbench is of the wall on screen, which edits may
 * have made unlike any file.  So R saves that wall beside the report
 * (DIR/wall.yaml, wallfile_save), names it as the report's wall file,
 * describes it in words (friction with its coefficient of variation
 * when random, the contacts, the load, the layout, and what differs
 * from the file it came from: that file is read again and compared),
 * and gives the command that reproduces the report's loads from it:
 *
 *   slipwall report DIR/wall.yaml -n N --seed S --out DIR-rerun
 *
 * N is the samples the run has computed (its samples file holds them,
 * in index order: the batch run with the same seed computes the same
 * ones, docs/run.md), so the p05 of the rerun is the report's.  The
 * threads are left out: the results do not depend on them.
 *
 * Defaults: a wall opened from a file has its save and its report
 * beside that file (its directory), named after the run's samples
 * file; a wall from no file (the built-in demo) keeps them in the runs
 * directory beside the samples.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "slipwall/wallfile.h"
#include "tui.h"

/* The directory of the opened wall file into out ("." for a bare name);
 * -1 when the wall came from no file or the path does not fit. */
static int tui_report_wall_dir(const struct tui *t, char *out, size_t len)
{
	const char *p = t->w->path;
	if (!p || !p[0])
		return -1;
	const char *slash = strrchr(p, '/');
	int n;
	if (!slash)
		n = snprintf(out, len, ".");
	else if (slash == p)
		n = snprintf(out, len, "/");
	else
		n = snprintf(out, len, "%.*s", (int)(slash - p), p);
	return n < 0 || (size_t)n >= len ? -1 : 0;
}

int tui_report_default(const struct tui *t, const char *suffix, char *out,
		       size_t len)
{
	char dir[PATH_MAX], stem[PATH_MAX];
	if (tui_report_wall_dir(t, dir, sizeof dir))
		return -1;
	if (t->run.csv[0]) {
		const char *b = strrchr(t->run.csv, '/');
		snprintf(stem, sizeof stem, "%s", b ? b + 1 : t->run.csv);
		char *dot = strrchr(stem, '.');
		if (dot && !strcmp(dot, ".csv"))
			*dot = 0;
	} else {
		char s[128];
		tui_file_stem(t->w, s, sizeof s);
		snprintf(stem, sizeof stem, "%s-edited", s);
	}
	int n = snprintf(out, len, "%s%s%s%s", strcmp(dir, "/") ? dir : "",
			 "/", stem, suffix);
	return n < 0 || (size_t)n >= len ? -1 : 0;
}

/* s as one word of a POSIX shell: as it is when it has only harmless
 * characters, else in single quotes ('\'' for a quote). */
static void tui_report_shell_arg(FILE *f, const char *s)
{
	fputc(' ', f);
	if (s[0] && strspn(s, "abcdefghijklmnopqrstuvwxyz"
			   "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_./+-=:,@%")
		    == strlen(s)) {
		fputs(s, f);
		return;
	}
	fputc('\'', f);
	for (; *s; s++)
		if (*s == '\'')
			fputs("'\\''", f);
		else
			fputc(*s, f);
	fputc('\'', f);
}

char *tui_report_command(const struct tui *t, const char *wallpath,
			 const char *dir)
{
	char *buf = NULL, out[PATH_MAX + 16];
	size_t len = 0;
	FILE *f = open_memstream(&buf, &len);
	if (!f)
		return NULL;
	snprintf(out, sizeof out, "%s", dir);
	for (size_t k = strlen(out); k > 1 && out[k - 1] == '/'; k--)
		out[k - 1] = 0;
	if (strlen(out) + 7 < sizeof out)
		strcat(out, "-rerun");
	fputs("slipwall report", f);
	tui_report_shell_arg(f, wallpath);
	fprintf(f, " -n %ld --seed %lu --out", t->run.tally.samples,
		t->run.cfg.seed);
	tui_report_shell_arg(f, out);
	if (fclose(f) != 0) {
		free(buf);
		return NULL;
	}
	return buf;
}

/* The first load in words. */
static void tui_report_load(FILE *f, const struct wall *w)
{
	if (w->nloads < 1) {
		fputs("no load", f);
		return;
	}
	const struct wall_load *l = &w->loads[0];
	if (l->kind == LOAD_POINT)
		fprintf(f, "point load %g N at (%g, %g) m, direction (%.4g, %.4g)",
			l->magnitude, l->at[0], l->at[1], l->dir[0], l->dir[1]);
	else
		fprintf(f, "body load %g × weight, direction (%.4g, %.4g)",
			l->magnitude, l->dir[0], l->dir[1]);
	if (w->nloads > 1)
		fprintf(f, " (and %d more)", w->nloads - 1);
}

/* The layout in words. */
static void tui_report_layout(FILE *f, const struct wall *w)
{
	int nfixed = 0;
	for (int i = 0; i < w->nblocks; i++)
		nfixed += w->blocks[i].fixed;
	if (w->layout.present)
		fprintf(f, "%d courses of %g × %g m blocks, %s bond, "
			"length %g m; ", w->layout.courses, w->layout.block_w,
			w->layout.block_h, w->layout.bond == BOND_STACK ?
			"stack" : "running", w->layout.length);
	fprintf(f, "%d blocks (%d support%s)", w->nblocks, nfixed,
		nfixed == 1 ? "" : "s");
}

/* Two walls' blocks are the same (ids and vertices). */
static int tui_report_same_blocks(const struct wall *a, const struct wall *b)
{
	if (a->nblocks != b->nblocks)
		return 0;
	for (int i = 0; i < a->nblocks; i++) {
		const struct wall_block *p = &a->blocks[i], *q = &b->blocks[i];
		if (p->nv != q->nv || p->fixed != q->fixed ||
		    strcmp(p->id, q->id) ||
		    memcmp(p->xy, q->xy, sizeof(double) * 2 * (size_t)p->nv))
			return 0;
	}
	return 1;
}

static int tui_report_same_load(const struct wall *a, const struct wall *b)
{
	if (a->nloads != b->nloads)
		return 0;
	for (int i = 0; i < a->nloads; i++) {
		const struct wall_load *p = &a->loads[i], *q = &b->loads[i];
		if (p->kind != q->kind || p->magnitude != q->magnitude ||
		    p->dir[0] != q->dir[0] || p->dir[1] != q->dir[1] ||
		    (p->kind == LOAD_POINT &&
		     (p->at[0] != q->at[0] || p->at[1] != q->at[1])))
			return 0;
	}
	return 1;
}

/* What differs between the file's wall o and the wall sampled w. */
static void tui_report_changes(FILE *f, const struct wall *o,
			       const struct wall *w)
{
	int any = 0;
	if (o->mu_bed != w->mu_bed || o->mu_head != w->mu_head)
		fprintf(f, "%sfriction bed %g → %g, head %g → %g",
			any++ ? "; " : "", o->mu_bed, w->mu_bed, o->mu_head,
			w->mu_head);
	if (o->mu_cov != w->mu_cov)
		fprintf(f, "%scoefficient of variation of friction %g → %g",
			any++ ? "; " : "", o->mu_cov, w->mu_cov);
	if (o->anywhere != w->anywhere || o->depth != w->depth) {
		fprintf(f, "%scontacts ", any++ ? "; " : "");
		if (o->anywhere)
			fputs("anywhere", f);
		else
			fprintf(f, "depth %g", o->depth);
		fputs(" → ", f);
		if (w->anywhere)
			fputs("anywhere", f);
		else
			fprintf(f, "depth %g", w->depth);
	}
	if (!tui_report_same_load(o, w)) {
		fprintf(f, "%sload: ", any++ ? "; " : "");
		tui_report_load(f, o);
		fputs(" → ", f);
		tui_report_load(f, w);
	}
	if (!tui_report_same_blocks(o, w)) {
		fprintf(f, "%slayout: ", any++ ? "; " : "");
		tui_report_layout(f, o);
		fputs(" → ", f);
		tui_report_layout(f, w);
	}
	if (!any)
		fputs("other settings", f);
}

char *tui_report_describe(const struct tui *t, const char *wallpath)
{
	const struct wall *w = t->w;
	char *buf = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&buf, &len);
	if (!f)
		return NULL;
	fprintf(f, "saved beside this report as `%s`: friction bed %g, head %g",
		wallpath, w->mu_bed, w->mu_head);
	if (w->mu_cov > 0)
		fprintf(f, " (random: lognormal, coefficient of variation %g)",
			w->mu_cov);
	else
		fputs(" (fixed)", f);
	if (w->anywhere)
		fputs("; contact points anywhere", f);
	else
		fprintf(f, "; contact depth d = %g", w->depth);
	fputs("; ", f);
	tui_report_load(f, w);
	fputs("; ", f);
	tui_report_layout(f, w);
	if (w->path) {
		/* the file it came from, read again to name the edits */
		struct wall *o = NULL;
		char err[SW_ERRLEN], d0[WALL_DIGEST_LEN], d1[WALL_DIGEST_LEN];
		struct stat st;	/* a FIFO there now would block the UI */
		if (stat(w->path, &st) != 0 || !S_ISREG(st.st_mode) ||
		    wallfile_load(w->path, &o, err) != SW_OK) {
			fprintf(f, ". From `%s` (not readable now: the edits "
				"are not listed)", w->path);
		} else {
			wall_digest(o, d0);
			wall_digest(w, d1);
			if (!strcmp(d0, d1))
				fprintf(f, ". The wall of `%s`, not edited",
					w->path);
			else {
				fprintf(f, ". Edited from `%s`: ", w->path);
				tui_report_changes(f, o, w);
			}
			wall_free(o);
		}
	} else {
		fputs(". The built-in demonstration wall", f);
	}
	fputc('.', f);
	if (fclose(f) != 0) {
		free(buf);
		return NULL;
	}
	/* a | would end the table's cell */
	for (char *p = buf; *p; p++)
		if (*p == '|')
			*p = '/';
	return buf;
}
