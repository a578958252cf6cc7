/*
 * override.h - changes to a wall file from the command line, for run,
 * compare, report and sweep (docs/run.md, "Overrides").
 *
 *   --friction MU | --friction BED,HEAD    material.friction
 *   --load-at X,Y                          loads.K.point.at
 *   --load-direction DX,DY                 loads.K.point|body.direction
 *   --set KEY=VALUE                        any key (dotted path)
 *
 * Each is applied to the wall file's YAML document before it is read
 * (wallfile_load_edited), so a run with overrides is the run of the
 * edited file, sample for sample.  --load-at and --load-direction
 * change the wall's only live load (K found from the unedited file); a
 * wall with several says to use --set.  (--depth stays the sampling
 * option it was: CLI_OPT_DEPTH.)
 *
 * Usage: OVERRIDE_OPTIONS(&ov) in the command's option table
 * (cli_opts.h), then
 * override_load() instead of cli_load_wall(); override_json(),
 * override_describe() and override_args() say what was changed;
 * override_free() at the end.
 */
#ifndef SLIPWALL_OVERRIDE_H
#define SLIPWALL_OVERRIDE_H

#include <stddef.h>
#include <stdio.h>
#include "cli_opts.h"
#include "slipwall/json.h"
#include "slipwall/wall.h"

enum override_kind { OVR_FRICTION, OVR_COV, OVR_LOAD_AT, OVR_LOAD_DIR,
		     OVR_SET };

struct override {
	enum override_kind kind;
	char *option;		/* "--friction" */
	char *arg;		/* as given: "0.4,0.5" */
	char *key;		/* the wall file's key (set by override_load
				 * for the load options) */
	char *value;		/* YAML text */
	char *label;		/* "--friction 0.4,0.5" */
};

struct overrides {
	struct override *o;
	int n;
};

/* Record the override option opt ("--friction", ...) with its value
 * v into dst (a struct overrides *): 0, or 2 after printing a usage
 * error (a value that is not what the option takes).  The
 * CLI_OPT_CALL of the four options. */
int override_add(const char *cmd, const char *opt, const char *v, void *dst);
#define OVERRIDE_OPTION(nm, ov)						\
	{ .name = (nm), .kind = CLI_OPT_CALL, .dst = (ov),		\
	  .call = override_add }
#define OVERRIDE_OPTIONS(ov)						\
	OVERRIDE_OPTION("--friction", ov),				\
	OVERRIDE_OPTION("--cov", ov),					\
	OVERRIDE_OPTION("--load-at", ov),				\
	OVERRIDE_OPTION("--load-direction", ov),			\
	OVERRIDE_OPTION("--set", ov)
/* Load the wall file with the overrides applied.  Returns 0, or the
 * exit status (2) after printing the message. */
int override_load(const char *cmd, const char *path, struct overrides *ov,
		  struct wall **w);
/* The start of a command with overrides: rc is what its parse_args
 * returned (0: go on; -1: --help was printed; else an exit status).
 * Then the wall at path with the overrides applied (override_load).
 * Returns 1 with *w to go on; else 0 with the exit status in *status,
 * the overrides freed. */
int override_begin(const char *cmd, int rc, const char *path,
		   struct overrides *ov, struct wall **w, int *status);
/* "overrides": [{"option", "value", "key", "yaml"}, ...] (an empty list
 * when there is none). */
void override_json(const struct overrides *ov, struct json *j);
/* "material.friction = 0.5 (--friction 0.5); ..." into buf; "" when
 * there is none. */
void override_describe(const struct overrides *ov, char *buf, size_t len);
/* The options again, each argument quoted for a POSIX shell when it
 * needs it, each preceded by a space, written to f. */
void override_args(const struct overrides *ov, FILE *f);
void override_free(struct overrides *ov);

#endif
