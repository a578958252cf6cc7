/*
 * cli_opts.c - the one option parser of the batch commands; see
 * cli_opts.h.  One loop over argv: each argument is help, an option of
 * the command's table (its value checked and stored by its kind) or
 * the wall file.
 */
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cli_opts.h"
#include "slipwall/text.h"

/* If arg names the option (its name or its alias), the name as given
 * and its value: "NAME=VALUE", or "NAME" and the next argument
 * (advancing *i; *value NULL when there is none).  A flag matches only
 * by itself.  0 if arg is not this option. */
static int opt_match(const struct cli_opt *o, int argc, char **argv, int *i,
		     const char **value)
{
	const char *names[2] = {o->name, o->alias}, *a = argv[*i];
	for (int k = 0; k < 2 && names[k]; k++) {
		size_t len = strlen(names[k]);
		if (strncmp(a, names[k], len))
			continue;
		if (o->kind == CLI_OPT_FLAG) {
			if (a[len])
				continue;
			*value = NULL;
			return 1;
		}
		if (a[len] == '=') {
			*value = a + len + 1;
			return 1;
		}
		if (a[len])
			continue;
		*value = *i + 1 < argc ? argv[++*i] : NULL;
		return 1;
	}
	return 0;
}

/* Check the value v of option o and store it: 0, or 2 after the
 * message. */
static int opt_store(const char *cmd, const struct cli_opt *o, const char *v)
{
	long l;
	double d;
	switch (o->kind) {
	case CLI_OPT_FLAG:
		*(int *)o->dst = 1;
		break;
	case CLI_OPT_LONG:
	case CLI_OPT_INT:
		if (text_parse_long(v, (long)o->lo, (long)o->hi, &l))
			return cli_usage_error(cmd, "%s: '%s' is not %s",
					       o->name, v, o->what);
		if (o->kind == CLI_OPT_LONG)
			*(long *)o->dst = l;
		else
			*(int *)o->dst = (int)l;
		break;
	case CLI_OPT_DOUBLE:
		if (text_parse_double(v, &d) ||
		    (o->above ? !(d > o->lo) : d < o->lo) || d > o->hi)
			return cli_usage_error(cmd, "%s: '%s' is not %s",
					       o->name, v, o->what);
		*(double *)o->dst = d;
		break;
	case CLI_OPT_SEED:
		if (cli_parse_seed(v, o->dst))
			return cli_usage_error(cmd, "%s: '%s' is not a whole "
					       "number from 0 to %llu (2^64-1)",
					       o->name, v, WALL_SEED_MAX);
		break;
	case CLI_OPT_TIME:
		if (cli_parse_time_limit(v, o->dst))
			return cli_usage_error(cmd, "%s: '%s' is not a number "
					       "of seconds > 0 and <= %g",
					       o->name, v, CLI_TIME_LIMIT_MAX);
		break;
	case CLI_OPT_STRING:
		if (!*v)
			return cli_usage_error(cmd, "%s: empty %s", o->name,
					       o->what);
		*(const char **)o->dst = v;
		break;
	case CLI_OPT_CALL:
		return o->call(cmd, o->name, v, o->dst);
	}
	if (o->given)
		*o->given = 1;
	return 0;
}

/* "unknown option 's'", or the command's own words for it. */
static int unknown(const struct cli_cmd *c, const char *s)
{
	return cli_usage_error(c->name, c->unknown ? c->unknown :
			       "unknown option '%s'", s);
}

/* An argument that is not in the table: 2 after the message, or 0 when
 * it is the wall file (counted in *nwall). */
static int not_an_option(const struct cli_cmd *c, const char *s, int options,
			 const char **wall, int *nwall)
{
	if (options && s[0] == '-' && s[1])
		return unknown(c, s);
	if (*nwall && !c->posix)
		return cli_usage_error(c->name, "one wall file only ('%s' and "
				       "'%s')", *wall, s);
	if (!*nwall)
		*wall = s;
	++*nwall;
	return 0;
}

int cli_opts_parse(const struct cli_cmd *c, const struct cli_opt *opts,
		   int n, int argc, char **argv, const char **wall)
{
	int nwall = 0, options = 1, rc;
	*wall = NULL;
	for (int i = 1; i < argc; i++) {
		const char *s = argv[i], *v = NULL;
		if (options && (!strcmp(s, "--help") || !strcmp(s, "-h"))) {
			c->usage(stdout);
			return -1;
		}
		if (options && c->posix && !strcmp(s, "--")) {
			options = 0;
			continue;
		}
		int k = 0;
		while (options && k < n && !opt_match(&opts[k], argc, argv, &i,
						      &v))
			k++;
		if (!options || k == n)
			rc = not_an_option(c, s, options, wall, &nwall);
		else if (!v && opts[k].kind != CLI_OPT_FLAG)
			rc = c->posix ? unknown(c, s) :
			     cli_usage_error(c->name, "%s needs a value", s);
		else
			rc = opt_store(c->name, &opts[k], v);
		if (rc)
			return rc;
	}
	if (nwall != 1)
		return cli_usage_error(c->name, "%s", c->no_wall);
	return 0;
}
