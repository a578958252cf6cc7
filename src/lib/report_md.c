/*
 * report_md.c - report.md, the Markdown summary of a report: the
 * characteristic values (the paper's Table 1), the Kolmogorov-Smirnov
 * test, the single solutions, the run's settings and the list of
 * figures.  Called by report_write (report.c) with the context it
 * computed (report_fig.h); written whole or not at all, as the figures.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "report_fig.h"
#include "slipwall/outfile.h"
#include "slipwall/sample.h"
#include "slipwall/text.h"

static void md_num(FILE *o, double v, const char *unit)
{
	if (isfinite(v))
		fprintf(o, "%.5g%s", v, unit);
	else
		fprintf(o, "—");
}

static void md_ci(FILE *o, const struct stats_summary *s, const char *unit)
{
	if (s->has_ci)
		fprintf(o, "[%.5g, %.5g]%s", s->p05_lo, s->p05_hi, unit);
	else
		fprintf(o, "none (n = %zu < 90)", s->n);
}

/* A copy of s for report.md (text_clean); NULL stays NULL. */
static char *md_clean(const char *s)
{
	return s ? text_clean(s) : NULL;
}

/* A row of the table of characteristic values. */
static void md_row(FILE *f, const char *what, size_t n,
		   const struct stats_summary *s, const char *u)
{
	fprintf(f, "| %s | %zu | ", what, n);
	md_num(f, s->p05, u);
	fprintf(f, " | ");
	md_ci(f, s, u);
	fprintf(f, " | ");
	md_num(f, s->mean, u);
	fprintf(f, " | ");
	md_num(f, s->std, u);
	fprintf(f, " |\n");
}

/* The names and paths of a report as they may be printed: no control
 * character (a newline would end a table row, an ESC reach a
 * terminal).  NULL where the input has none. */
struct md_text {
	char *name, *wall_path, *command, *samples_file, *tests_source, *note;
	char *wall_desc;
};

/* Is every line of s clean (text_is_clean), newlines apart? */
static int clean_lines(const char *s)
{
	char *copy = sw_xstrdup(s), *save = NULL;
	int ok = 1;
	for (char *l = strtok_r(copy, "\n", &save); l && ok;
	     l = strtok_r(NULL, "\n", &save))
		ok = text_is_clean(l);
	free(copy);
	return ok;
}

/* The command to reproduce the report, as a code block that a POSIX
 * shell runs as it is: indented when it is one line; fenced when an
 * argument spans lines (a --set value with a newline, quoted by the
 * caller: cli_shell_arg), the fence longer than any run of backticks in
 * it.  A command with other control characters (the caller did not
 * quote them) is written escaped, one line, for people only. */
static void md_command(FILE *f, const char *cmd)
{
	if (!strchr(cmd, '\n') || !clean_lines(cmd)) {
		char *clean = text_clean(cmd);
		fprintf(f, " To reproduce it:\n\n    %s\n\n", clean);
		free(clean);
		return;
	}
	int run = 0, longest = 0;
	for (const char *p = cmd; *p; p++) {
		run = *p == '`' ? run + 1 : 0;
		if (run > longest)
			longest = run;
	}
	int fence = longest < 3 ? 3 : longest + 1;
	fputs(" To reproduce it:\n\n", f);
	for (int k = 0; k < fence; k++)
		fputc('`', f);
	fprintf(f, "sh\n%s\n", cmd);
	for (int k = 0; k < fence; k++)
		fputc('`', f);
	fputs("\n\n", f);
}

static void md_values(FILE *f, const struct rctx *c)
{
	fprintf(f, "## Characteristic values (the paper's Table 1)\n\n");
	fprintf(f, "| | values | 5 %% percentile (p05) | 99 %% confidence "
		"interval of p05 | mean | std |\n|---|---:|---:|---|---:|---:|\n");
	md_row(f, "Numerical model", c->n, &c->ms, c->unit);
	if (c->m)
		md_row(f, "Experimental tests", c->m, &c->ts, c->unit);
	fprintf(f, "\nPercentiles are of type 7; the interval is "
		"distribution-free (order statistics, coverage ≥ 99 %%) and "
		"exists from 90 values on (docs/statistics.md).\n");
	if (!c->m)
		fprintf(f, "\n**No experimental loads** (the wall has no `tests:` "
			"key and no `--tests` file was given): the figures show "
			"the model alone, and there is no Kolmogorov-Smirnov "
			"test.\n");
}

static void md_ks(FILE *f, const struct rctx *c)
{
	if (c->ks_ok) {
		fprintf(f, "\n## Model against tests: two-sample "
			"Kolmogorov–Smirnov\n\n");
		fprintf(f, "x = model (%zu), y = tests (%zu), %s p-values.\n\n",
			c->n, c->m, c->ks.exact ? "exact" : "asymptotic");
		fprintf(f, "| statistic | value | p | hypotheses |\n"
			"|---|---:|---:|---|\n");
		fprintf(f, "| D | %.4g | %.4g | H1: the distributions differ |\n",
			c->ks.d, c->ks.p_two_sided);
		fprintf(f, "| D+ = max(F_model − F_tests) | %.4g | %.4g | "
			"`p_greater`, H1: model < tests |\n", c->ks.d_plus,
			c->ks.p_greater);
		fprintf(f, "| D− = max(F_tests − F_model) | %.4g | %.4g | "
			"`p_less`, H0: model ≤ tests (the paper's 0.994) |\n",
			c->ks.d_minus, c->ks.p_less);
	}
}

static void md_single(FILE *f, const struct rctx *c)
{
	const struct report_input *in = c->in;
	fprintf(f, "\n## Single-solution methods (classical contact, d = 0)\n\n");
	if (in->nsol == 0)
		fprintf(f, "None computed.\n");
	else
		fprintf(f, "| method | load | note |\n|---|---:|---|\n");
	for (int i = 0; i < in->nsol; i++) {
		const struct report_solution *s = &c->sol[i];
		fprintf(f, "| %s | ", s->method);
		if (s->found)
			md_num(f, s->lambda, c->unit);
		else
			fprintf(f, "—");
		fprintf(f, " | %s |\n", *s->note ? s->note :
			s->ran ? "" : "not run");
	}
}

/* A row of the run's table: the blocks that the samples of status st
 * (one of tally_named) named, the three named most often (docs/
 * method.md, "Which blocks cannot be held"); none when no sample named
 * one. */
static void md_unheld(FILE *f, const struct rctx *c, enum sample_status st)
{
	const struct report_input *in = c->in;
	int b[3];
	long n3[3];
	int n = in->mech && in->mech->nblocks == c->w->nblocks ?
		tally_unheld(in->mech, st, b, n3, 3) : 0;
	if (n <= 0)
		return;
	fprintf(f, "| %s (%s) | ", tally_unheld_text(st),
		sample_status_name(st));
	for (int i = 0; i < n && i < 3; i++)
		fprintf(f, "%sblock %s in %ld sample%s", i ? ", " : "",
			c->w->blocks[b[i]].id, n3[i], n3[i] > 1 ? "s" : "");
	if (n > 3)
		fprintf(f, ", and %d other block%s", n - 3, n > 4 ? "s" : "");
	fprintf(f, " |\n");
}

static void md_run(FILE *f, const struct rctx *c, const struct md_text *t)
{
	const struct report_input *in = c->in;
	const struct report_run *r = &in->run;
	fprintf(f, "\n## Run\n\n| setting | value |\n|---|---|\n");
	fprintf(f, "| wall file | `%s` |\n", t->wall_path ? t->wall_path : "?");
	if (t->wall_desc)
		fprintf(f, "| wall sampled | %s |\n", t->wall_desc);
	fprintf(f, "| slipwall version | %s |\n", r->version ? r->version : "?");
	if (t->samples_file)
		fprintf(f, "| loads read from | `%s` |\n", t->samples_file);
	if (r->seed_known)
		fprintf(f, "| seed | %lu |\n", r->seed);
	else
		fprintf(f, "| seed | not recorded in the samples file |\n");
	if (r->requested > 0)
		fprintf(f, "| samples requested | %ld |\n", r->requested);
	if (r->threads > 0)
		fprintf(f, "| threads | %d (the results do not depend on it) |\n",
			r->threads);
	if (c->w->mu_cov > 0)	/* random friction (fixed: the wall file's) */
		fprintf(f, "| friction | random per joint and sample: lognormal, "
			"mean bed %g, head %g, coefficient of variation %g |\n",
			c->w->mu_bed, c->w->mu_head, c->w->mu_cov);
	if (r->anywhere)
		fprintf(f, "| contact points | anywhere (sorted pair of U(0, 1)) |\n");
	else if (isfinite(r->depth))
		fprintf(f, "| contact depth d | %g |\n", r->depth);
	if (r->has_counts) {
		fprintf(f, "| samples computed | %ld |\n", r->samples);
		fprintf(f, "| accepted | %ld (%.1f %%) |\n", r->accepted,
			r->samples ? 100.0 * (double)r->accepted /
			(double)r->samples : 0.0);
		long rej = r->samples - r->accepted;
		fprintf(f, "| rejected | %ld |\n", rej);
		for (int k = 0; k < SAMPLE_STATUS_COUNT; k++)
			if (k != SAMPLE_ACCEPTED && r->rejected[k])
				fprintf(f, "| rejected: %s | %ld |\n",
					sample_status_text(k), r->rejected[k]);
	}
	for (int u = 0; u < TALLY_NAMED; u++)
		md_unheld(f, c, tally_named[u]);
	fprintf(f, "| accepted loads plotted | %zu |\n", c->n);
	if (in->mech)
		fprintf(f, "| distinct mechanisms | %d |\n", in->mech->nmech);
	if (in->mech && c->fams.w)
		fprintf(f, "| mechanism families (same moving region) | %d |\n",
			c->fams.nfam);
	if (c->m)
		fprintf(f, "| experimental loads | %zu, from %s |\n", c->m,
			t->tests_source ? t->tests_source : "?");
	if (t->note)
		fprintf(f, "\n%s\n", t->note);
}

/* The most frequent families (those of Fig. 6), each with its blocks
 * and its most frequent mechanism's moving joints, named by their
 * blocks (docs/statistics.md, "Mechanism families"). */
static void md_families(FILE *f, const struct rctx *c)
{
	const struct tally *t = c->in->mech;
	if (!t || !c->fams.w || c->ntop == 0)
		return;
	fprintf(f, "\n## Mechanism families\n\n"
		"Mechanisms grouped by the region that moves "
		"(docs/statistics.md), the most frequent first; %d famil%s of "
		"%d distinct mechanisms in %ld accepted samples.\n\n"
		"| # | share | samples | load%s%s%s | moving blocks | mechanisms "
		"| the most frequent one: how it comes away; its moving joints "
		"|\n"
		"|---|---|---|---|---|---|---|\n", c->fams.nfam,
		c->fams.nfam == 1 ? "y" : "ies", t->nmech, t->accepted,
		*c->unit ? " (" : "", *c->unit ? c->unit + (*c->unit == ' ') :
		"", *c->unit ? ")" : "");
	for (int i = 0; i < c->ntop; i++) {
		const struct family *fa = &c->fams.fam[c->topfam[i]];
		char name[256], j[400], how[160];
		const char *joint = t->mech[c->top[i]].joint;
		family_label(&c->fams, fa, name, sizeof name);
		/* how the mechanism itself comes away: its own moving set
		 * (a large family's core is narrower) */
		unsigned char *mv = sw_xmalloc((size_t)c->w->nblocks + 1);
		family_moving(c->w, joint, mv, NULL);
		family_motion(&c->fams, joint, mv, how, sizeof how);
		free(mv);
		family_fmt_joints(c->w, joint, j, sizeof j);
		char *nm = md_clean(name), *jm = md_clean(j);
		fprintf(f, "| %d | %.1f %% | %ld | %.5g to %.5g | %s | %d | %s; "
			"%s |\n", i + 1, 100.0 * (double)fa->count /
			(double)(t->accepted ? t->accepted : 1), fa->count,
			fa->lam_lo, fa->lam_hi, nm ? nm : "", fa->nmech, how,
			jm ? jm : "");
		free(nm);
		free(jm);
	}
}

static void md_figures(FILE *f, const struct md_figure *fig, int nfig,
		       const struct report_opts *o)
{
	fprintf(f, "\n## Figures\n\n");
	for (int i = 0; i < nfig; i++) {
		if (!fig[i].drawn) {
			fprintf(f, "### %s\n\nNot drawn: no mechanisms were "
				"recorded for these loads.\n\n", fig[i].title);
			continue;
		}
		fprintf(f, "### %s\n\n", fig[i].title);
		if (o->formats & REPORT_PNG)
			fprintf(f, "![%s](%s.png)\n\n", fig[i].name,
				fig[i].name);
		int any = 0;
		if (o->formats & REPORT_SVG)
			fprintf(f, "%s[SVG](%s.svg)", any++ ? " · " : "",
				fig[i].name);
		if (o->formats & REPORT_PDF)
			fprintf(f, "%s[PDF](%s.pdf)", any++ ? " · " : "",
				fig[i].name);
		if (any)
			fprintf(f, "\n\n");
	}
}

enum sw_status report_md_write(const struct rctx *c,
			       const struct md_figure *fig, int nfig,
			       const char *dir, const struct report_opts *o,
			       char *err)
{
	const struct report_run *r = &c->in->run;
	char path[4096];
	snprintf(path, sizeof path, "%s/report.md", dir);
	struct outfile out;
	enum sw_status st = outfile_open(&out, path, NULL, 0, "report.md",
					 err);
	if (st != SW_OK)
		return st;
	FILE *f = out.f;
	struct md_text t = {
		md_clean(c->w->name), md_clean(r->wall_path),
		NULL, md_clean(r->samples_file),
		md_clean(r->tests_source), md_clean(r->note),
		md_clean(r->wall_desc),
	};
	fprintf(f, "# slipwall report: %s\n\n", t.name ? t.name :
		(t.wall_path ? t.wall_path : "wall"));
	fprintf(f, "Written by slipwall %s from `%s`.", r->version ? r->version :
		"(unknown version)", t.wall_path ? t.wall_path : "?");
	if (r->command)
		md_command(f, r->command);
	else
		fprintf(f, "\n\n");
	fprintf(f, "Loads: %s.\n\n", c->axis);
	md_values(f, c);
	md_ks(f, c);
	md_single(f, c);
	md_run(f, c, &t);
	md_families(f, c);
	md_figures(f, fig, nfig, o);
	free(t.name);
	free(t.wall_path);
	free(t.command);
	free(t.samples_file);
	free(t.tests_source);
	free(t.note);
	free(t.wall_desc);
	return outfile_commit(&out, err);
}
