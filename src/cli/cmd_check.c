/*
 * cmd_check.c - `slipwall check WALL [--json]`: validate a wall and print
 * the model (blocks, interfaces, loads, weights).  The --json form fixes
 * the order of blocks and interfaces that every other output uses.
 */
#include <stdio.h>
#include <string.h>

#include "cli.h"
#include "cli_opts.h"
#include "slipwall/json.h"

static const char *kind_name(enum joint_kind k)
{
	return k == JOINT_BED ? "bed" : k == JOINT_HEAD ? "head" : "other";
}

static void point(struct json *j, const double *p)
{
	json_array_begin(j);
	json_double(j, p[0]);
	json_double(j, p[1]);
	json_array_end(j);
}

/* "key": [x, y] */
static void key_point(struct json *j, const char *key, const double *p)
{
	json_key(j, key);
	point(j, p);
}

static void print_json(const struct wall *w)
{
	struct json j;
	json_init(&j, stdout, 1);
	json_object_begin(&j);
	json_key(&j, "wall");
	json_string(&j, w->path);
	json_key(&j, "name");
	if (w->name)
		json_string(&j, w->name);
	else
		json_null(&j);
	cli_json_warnings(&j, w);
	json_key(&j, "material");
	json_object_begin(&j);
	json_key(&j, "friction");
	json_object_begin(&j);
	json_key(&j, "bed");
	json_double(&j, w->mu_bed);
	json_key(&j, "head");
	json_double(&j, w->mu_head);
	if (w->mu_cov > 0) {	/* random friction: bed and head are means */
		json_key(&j, "cov");
		json_double(&j, w->mu_cov);
	}
	json_object_end(&j);
	json_key(&j, "unit_weight");
	json_double(&j, w->unit_weight);
	json_key(&j, "thickness");
	json_double(&j, w->thickness);
	json_object_end(&j);
	json_key(&j, "total_weight");
	json_double(&j, w->total_weight);
	char digest[WALL_DIGEST_LEN];
	wall_digest(w, digest);
	json_key_string(&j, "wall_digest", digest);
	json_key(&j, "blocks");
	json_array_begin(&j);
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *b = &w->blocks[k];
		json_object_begin(&j);
		json_key(&j, "id");
		json_string(&j, b->id);
		json_key(&j, "vertices");
		json_array_begin(&j);
		for (int i = 0; i < b->nv; i++)
			point(&j, b->xy + 2 * i);
		json_array_end(&j);
		json_key(&j, "centroid");
		double c[2] = {b->cx, b->cy};
		point(&j, c);
		json_key(&j, "area");
		json_double(&j, b->area);
		json_key(&j, "weight");
		json_double(&j, b->weight);
		json_key(&j, "fixed");
		json_bool(&j, b->fixed);
		json_object_end(&j);
	}
	json_array_end(&j);
	json_key(&j, "interfaces");
	json_array_begin(&j);
	for (int k = 0; k < w->nifaces; k++) {
		const struct wall_interface *it = &w->ifaces[k];
		json_object_begin(&j);
		json_key(&j, "a");
		json_string(&j, w->blocks[it->a].id);
		json_key(&j, "b");
		json_string(&j, w->blocks[it->b].id);
		key_point(&j, "p1", it->p1);
		key_point(&j, "p2", it->p2);
		key_point(&j, "normal", it->n);
		json_key(&j, "length");
		json_double(&j, it->len);
		json_key(&j, "mu");
		json_double(&j, wall_iface_mu(w, k));
		json_key(&j, "kind");
		json_string(&j, kind_name(it->kind));
		json_object_end(&j);
	}
	json_array_end(&j);
	json_key(&j, "loads");
	json_array_begin(&j);
	for (int l = 0; l < w->nloads; l++) {
		const struct wall_load *ld = &w->loads[l];
		json_object_begin(&j);
		json_key(&j, "type");
		json_string(&j, ld->kind == LOAD_POINT ? "point" : "body");
		if (ld->kind == LOAD_POINT) {
			key_point(&j, "at", ld->at);
			json_key(&j, "block");
			json_string(&j, w->blocks[ld->block].id);
		}
		key_point(&j, "direction", ld->dir);
		json_key(&j, "magnitude");
		json_double(&j, ld->magnitude);
		json_object_end(&j);
	}
	json_array_end(&j);
	json_key(&j, "contacts");
	json_object_begin(&j);
	json_key(&j, "positions");
	json_string(&j, w->anywhere ? "anywhere" : "depth");
	json_key(&j, "depth");
	json_double(&j, w->depth);
	json_object_end(&j);
	json_key(&j, "analysis");
	json_object_begin(&j);
	json_key(&j, "samples");
	json_int(&j, w->samples);
	json_key(&j, "seed");
	json_uint(&j, w->seed);
	json_object_end(&j);
	json_key(&j, "tests");
	json_array_begin(&j);
	for (int t = 0; t < w->ntests; t++)
		json_double(&j, w->tests[t]);
	json_array_end(&j);
	json_object_end(&j);
	json_end(&j);
}

static void print_text(const struct wall *w)
{
	int nbed = 0, nhead = 0, nsup = 0, nfixed = 0;
	for (int k = 0; k < w->nifaces; k++) {
		const struct wall_interface *it = &w->ifaces[k];
		if (w->blocks[it->a].fixed || w->blocks[it->b].fixed)
			nsup++;
		else if (it->kind == JOINT_HEAD)
			nhead++;
		else
			nbed++;
	}
	for (int k = 0; k < w->nblocks; k++)
		nfixed += w->blocks[k].fixed;
	printf("wall:       %s%s%s%s\n", w->name ? cli_text(w->name) :
	       "(unnamed)", w->path ? " (" : "", w->path ? cli_text(w->path) :
	       "", w->path ? ")" : "");
	if (w->mu_cov > 0)
		printf("material:   friction bed %g, head %g (means; each joint's "
		       "random, lognormal, cov %g); unit weight %g N/m^3; "
		       "thickness %g m\n", w->mu_bed, w->mu_head, w->mu_cov,
		       w->unit_weight, w->thickness);
	else
		printf("material:   friction bed %g, head %g; unit weight %g N/m^3; thickness %g m\n",
		       w->mu_bed, w->mu_head, w->unit_weight, w->thickness);
	printf("blocks:     %d free, %d support%s; total weight %.6g N (mean block %.6g N)\n",
	       w->nfree, nfixed, nfixed == 1 ? "" : "s", w->total_weight,
	       w->mean_weight);
	printf("interfaces: %d (%d between blocks on bed joints or other, %d head joints, %d on supports)\n",
	       w->nifaces, nbed, nhead, nsup);
	for (int l = 0; l < w->nloads; l++) {
		const struct wall_load *ld = &w->loads[l];
		if (ld->kind == LOAD_POINT)
			printf("load:       point at (%g, %g) on block %s, direction (%g, %g), reference %g N\n",
			       ld->at[0], ld->at[1],
			       cli_text(w->blocks[ld->block].id),
			       ld->dir[0], ld->dir[1], ld->magnitude);
		else
			printf("load:       body load %g x weight, direction (%g, %g)\n",
			       ld->magnitude, ld->dir[0], ld->dir[1]);
	}
	if (w->anywhere)
		printf("contacts:   two points anywhere on each interface\n");
	else
		printf("contacts:   imperfection depth %g\n", w->depth);
	printf("analysis:   %d samples, seed %lu\n", w->samples, w->seed);
	if (w->ntests)
		printf("tests:      %d experimental loads\n", w->ntests);
	printf("\n%-10s %10s %10s %10s %12s\n", "block", "x_c (m)", "y_c (m)",
	       "area (m2)", "weight (N)");
	for (int k = 0; k < w->nblocks; k++) {
		const struct wall_block *b = &w->blocks[k];
		char wt[32];
		if (b->fixed)
			snprintf(wt, sizeof wt, "support");
		else
			snprintf(wt, sizeof wt, "%.5g", b->weight);
		printf("%-10s %10.4f %10.4f %10.5f %12s\n", cli_text(b->id),
		       b->cx, b->cy,
		       b->area, wt);
	}
	printf("\n%-5s %-10s %-10s %-21s %-21s %6s %s\n", "#", "a", "b",
	       "p1", "p2", "mu", "kind");
	for (int k = 0; k < w->nifaces; k++) {
		const struct wall_interface *it = &w->ifaces[k];
		char p1[32], p2[32];
		snprintf(p1, sizeof p1, "(%.4g, %.4g)", it->p1[0], it->p1[1]);
		snprintf(p2, sizeof p2, "(%.4g, %.4g)", it->p2[0], it->p2[1]);
		printf("%-5d %-10s %-10s %-21s %-21s %6.3g %s\n", k + 1,
		       cli_text(w->blocks[it->a].id),
		       cli_text(w->blocks[it->b].id), p1, p2,
		       wall_iface_mu(w, k), kind_name(it->kind));
	}
}

static void usage(FILE *f)
{
	fprintf(f,
		"usage: slipwall check WALL.yaml [--json]\n"
		"\n"
		"Validate a wall file and print the model: blocks (centroid, area,\n"
		"weight), interfaces (bodies, segment, friction, bed/head), loads.\n"
		"Errors are reported as FILE:LINE:COLUMN: message, exit status 2.\n"
		"\n"
		"  --json    machine-readable; its block and interface order is the\n"
		"            one of every other output (samples files, mechanisms)\n");
}

int cmd_check(int argc, char **argv)
{
	int json = 0;
	const char *path;
	const struct cli_opt opts[] = {
		CLI_OPT_SWITCH("--json", json),
	};
	static const struct cli_cmd cmd = {
		.name = "check", .usage = usage, .posix = 1,
		.no_wall = "expected one wall file",
	};
	int rc = cli_opts_parse(&cmd, opts, 1, argc, argv, &path);
	if (rc)
		return rc < 0 ? 0 : rc;
	struct wall *w;
	if ((rc = cli_load_wall(path, &w)))
		return rc;
	if (json)
		print_json(w);
	else
		print_text(w);
	wall_free(w);
	return 0;
}
