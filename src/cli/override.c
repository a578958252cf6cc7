/* override.c - changes to a wall file from the command line; see
 * override.h. */
#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "override.h"
#include "slipwall/text.h"
#include "slipwall/wallfile.h"

static char *dup_printf(const char *fmt, ...)
	__attribute__((format(printf, 1, 2)));

static char *dup_printf(const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	int n = vsnprintf(NULL, 0, fmt, ap);
	va_end(ap);
	char *s = sw_xmalloc((size_t)n + 1);
	va_start(ap, fmt);
	vsnprintf(s, (size_t)n + 1, fmt, ap);
	va_end(ap);
	return s;
}

/* Split "a,b" into exactly n numbers (n <= 2); their texts in part[]
 * (into buf).  0 on success. */
static int split_numbers(const char *v, int n, char *buf, size_t len,
			 char **part)
{
	if (strlen(v) >= len)
		return -1;
	strcpy(buf, v);
	int k = 0;
	char *s = buf;
	for (;;) {
		char *comma = strchr(s, ',');
		if (comma)
			*comma = 0;
		double d;
		if (k >= n || text_parse_double(s, &d))
			return -1;
		part[k++] = s;
		if (!comma)
			break;
		s = comma + 1;
	}
	return k == n ? 0 : -1;
}

/* --friction's value: MU (bed and head both) or BED,HEAD, their texts
 * in *bed and *head (into buf).  0, or -1 if it is neither. */
static int friction_parts(const char *v, char *buf, size_t len, char **bed,
			  char **head)
{
	char *part[2];
	if (!split_numbers(v, 1, buf, len, part)) {
		*bed = *head = part[0];
		return 0;
	}
	if (!split_numbers(v, 2, buf, len, part)) {
		*bed = part[0];
		*head = part[1];
		return 0;
	}
	return -1;
}

int override_add(const char *cmd, const char *opt, const char *v, void *dst)
{
	struct overrides *ov = dst;
	enum override_kind kind = !strcmp(opt, "--friction") ? OVR_FRICTION :
				  !strcmp(opt, "--cov") ? OVR_COV :
				  !strcmp(opt, "--load-at") ? OVR_LOAD_AT :
				  !strcmp(opt, "--load-direction") ?
				  OVR_LOAD_DIR : OVR_SET;
	char buf[256], *part[2];
	char *key = NULL, *value = NULL;
	switch (kind) {
	case OVR_FRICTION: {
		char *bed, *head;
		if (friction_parts(v, buf, sizeof buf, &bed, &head))
			return cli_usage_error(cmd, "--friction: '%s' is neither "
					       "MU nor BED,HEAD (numbers)", v);
		value = bed == head ? dup_printf("%s", bed) :
			dup_printf("{bed: %s, head: %s}", bed, head);
		key = dup_printf("material.friction");
		break;
	}
	case OVR_COV:
		if (split_numbers(v, 1, buf, sizeof buf, part))
			return cli_usage_error(cmd, "--cov: '%s' is not a "
					       "number", v);
		key = dup_printf("material.friction.cov");
		value = dup_printf("%s", part[0]);
		break;
	case OVR_LOAD_AT:
	case OVR_LOAD_DIR:
		if (split_numbers(v, 2, buf, sizeof buf, part))
			return cli_usage_error(cmd, "%s: '%s' is not two numbers "
					       "%s", opt, v, kind == OVR_LOAD_AT ?
					       "X,Y" : "DX,DY");
		value = dup_printf("[%s, %s]", part[0], part[1]);
		break;
	case OVR_SET: {
		const char *eq = strchr(v, '=');
		size_t kl = eq ? (size_t)(eq - v) : 0;
		int good = eq && kl > 0 && eq[1] && v[0] != '.' &&
			   v[kl - 1] != '.';
		for (size_t k = 0; good && k < kl; k++)
			if (!isalnum((unsigned char)v[k]) && v[k] != '_' &&
			    !(v[k] == '.' && v[k + 1] != '.'))
				good = 0;
		if (!good)
			return cli_usage_error(cmd, "--set: '%s' is not KEY=VALUE "
					       "(KEY a dotted path such as "
					       "material.unit_weight)", v);
		key = dup_printf("%.*s", (int)kl, v);
		value = dup_printf("%s", eq + 1);
		break;
	}
	}
	ov->o = sw_xrealloc(ov->o, sizeof *ov->o * (size_t)(ov->n + 1));
	struct override *x = &ov->o[ov->n++];
	x->kind = kind;
	x->option = dup_printf("%s", opt);
	x->arg = dup_printf("%s", v);
	x->key = key;
	x->value = value;
	x->label = dup_printf("%s %s", opt, v);
	return 0;
}

/* Friction's edits when it is random (docs/wall-format.md, "Friction as
 * a random variable"): --friction sets the mean and keeps the file's
 * cov; --cov and --set material.friction.cov set the cov and keep the
 * mean, also where the file writes friction as one number.  Each such
 * edit becomes the whole mapping material.friction = {bed, head, cov},
 * from the file's values and the edits before it, in order.  Without a
 * cov anywhere, --friction's edit is left as it is. */
static int sets_cov(const struct override *x)
{
	return x->kind == OVR_COV ||
	       (x->kind == OVR_SET && !strcmp(x->key, "material.friction.cov"));
}

static void resolve_friction(const struct wall *w, struct overrides *ov)
{
	int need = w->mu_cov > 0;
	for (int k = 0; k < ov->n; k++)
		need |= sets_cov(&ov->o[k]);
	if (!need)
		return;
	char bed[64], head[64], cov[64];
	snprintf(bed, sizeof bed, "%.17g", w->mu_bed);
	snprintf(head, sizeof head, "%.17g", w->mu_head);
	snprintf(cov, sizeof cov, "%.17g", w->mu_cov);
	for (int k = 0; k < ov->n; k++) {
		struct override *x = &ov->o[k];
		char buf[256], *b, *h;
		if (x->kind == OVR_FRICTION) {
			if (!friction_parts(x->arg, buf, sizeof buf, &b, &h)) {
				snprintf(bed, sizeof bed, "%s", b);
				snprintf(head, sizeof head, "%s", h);
			}
		} else if (sets_cov(x)) {
			snprintf(cov, sizeof cov, "%.60s", x->value);
		} else {
			continue;
		}
		free(x->key);
		free(x->value);
		x->key = dup_printf("material.friction");
		x->value = dup_printf("{bed: %s, head: %s, cov: %s}", bed, head,
				      cov);
	}
}

/* The keys of --load-at and --load-direction: the wall's only load. */
static int resolve_loads(const char *cmd, const char *path,
			 const struct wall *w, struct overrides *ov)
{
	int rc = 0;
	for (int k = 0; k < ov->n && !rc; k++) {
		struct override *x = &ov->o[k];
		if (x->kind != OVR_LOAD_AT && x->kind != OVR_LOAD_DIR)
			continue;
		if (w->nloads != 1) {
			rc = cli_usage_error(cmd, "%s: %s has %d live loads; say "
					     "which with --set loads.K.point.%s="
					     "[X, Y] (K from 0)", x->option,
					     path, w->nloads,
					     x->kind == OVR_LOAD_AT ? "at" :
					     "direction");
		} else if (w->loads[0].kind == LOAD_BODY &&
			   x->kind == OVR_LOAD_AT) {
			rc = cli_usage_error(cmd, "--load-at: the load of %s is a "
					     "body load, which acts at every "
					     "block's centroid", path);
		} else {
			free(x->key);
			x->key = dup_printf("loads.0.%s.%s",
					    w->loads[0].kind == LOAD_BODY ?
					    "body" : "point",
					    x->kind == OVR_LOAD_AT ? "at" :
					    "direction");
		}
	}
	return rc;
}

int override_load(const char *cmd, const char *path, struct overrides *ov,
		  struct wall **w)
{
	*w = NULL;
	if (ov->n == 0)
		return cli_load_wall(path, w);
	/* the file as it is, read once, when an override's key or value
	 * depends on it: the live load's kind, the friction's cov */
	int need = 0;
	for (int k = 0; k < ov->n; k++)
		need |= ov->o[k].kind != OVR_SET || sets_cov(&ov->o[k]);
	if (need) {
		struct wall *plain = NULL;
		int rc = cli_load_wall_quiet(path, &plain);
		if (!rc)
			rc = resolve_loads(cmd, path, plain, ov);
		if (!rc)
			resolve_friction(plain, ov);
		wall_free(plain);
		if (rc)
			return rc;
	}
	struct wallfile_edit *e = sw_xmalloc(sizeof *e * (size_t)ov->n);
	for (int k = 0; k < ov->n; k++)
		e[k] = (struct wallfile_edit){ov->o[k].key, ov->o[k].value,
					      ov->o[k].label};
	char err[SW_ERRLEN];
	enum sw_status st = wallfile_load_edited(path, e, ov->n, w, err);
	free(e);
	if (st != SW_OK) {
		/* a message about the file ("FILE: ..." or "FILE:LINE:COL:
		 * ...") may be about an override, and a place in the file
		 * may hold a value that an override replaced (--set
		 * blocks.0.vertices.0=[0,-1]: "FILE:3:5: block 'a' reaches
		 * below the ground"): say which overrides the wall had */
		size_t pl = strlen(path);
		if (!strncmp(err, path, pl) && err[pl] == ':') {
			char d[1024];
			override_describe(ov, d, sizeof d);
			/* cleaned: a --set value may hold control
			 * characters, and the message quotes it */
			fprintf(stderr, "%s\n  (in %s as changed by: %s)\n",
				cli_text(err), cli_text(path), cli_text(d));
		} else {
			cli_errorf("%s", err);
		}
		return sw_status_exit(st);
	}
	cli_warn_wall(*w);
	return 0;
}

int override_begin(const char *cmd, int rc, const char *path,
		   struct overrides *ov, struct wall **w, int *status)
{
	*w = NULL;
	if (!rc)
		rc = override_load(cmd, path, ov, w);
	if (!rc)
		return 1;
	override_free(ov);
	*status = rc < 0 ? 0 : rc;
	return 0;
}

void override_json(const struct overrides *ov, struct json *j)
{
	json_key(j, "overrides");
	json_array_begin(j);
	for (int k = 0; k < ov->n; k++) {
		const struct override *x = &ov->o[k];
		json_object_begin(j);
		json_key_string(j, "option", x->option);
		json_key_string(j, "value", x->arg);
		json_key_string(j, "key", x->key);
		json_key_string(j, "yaml", x->value);
		json_object_end(j);
	}
	json_array_end(j);
}

void override_describe(const struct overrides *ov, char *buf, size_t len)
{
	size_t u = 0;
	buf[0] = 0;
	for (int k = 0; k < ov->n && u < len; k++) {
		const struct override *x = &ov->o[k];
		int m = snprintf(buf + u, len - u, "%s%s = %s (%s)",
				 k ? "; " : "", x->key, x->value, x->label);
		if (m < 0)
			break;
		u += (size_t)m;
	}
}

void override_args(const struct overrides *ov, FILE *f)
{
	for (int k = 0; k < ov->n; k++) {
		cli_shell_arg(f, ov->o[k].option);
		cli_shell_arg(f, ov->o[k].arg);
	}
}

void override_free(struct overrides *ov)
{
	for (int k = 0; k < ov->n; k++) {
		free(ov->o[k].option);
		free(ov->o[k].arg);
		free(ov->o[k].key);
		free(ov->o[k].value);
		free(ov->o[k].label);
	}
	free(ov->o);
	ov->o = NULL;
	ov->n = 0;
}
