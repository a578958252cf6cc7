/*
 * cli_opts.h - the one option parser of the batch commands.
 *
 * Each command (cmd_*.c) declares its options as a table of struct
 * cli_opt, each naming where its value goes and what range it takes, and
 * hands it with its struct cli_cmd to cli_opts_parse(), which walks argv
 * once.  The syntax is the one of every command:
 *
 *   --name VALUE | --name=VALUE   (VALUE is the next argument whatever
 *                                  it looks like, "-n -1" included)
 *   --flag                        (no value; "--flag=x" is unknown)
 *   -h | --help                   the usage on stdout
 *   WALL.yaml                     the one argument that is no option
 *                                 ("-" is a file name)
 *
 * Options are checked as they come, left to right, and the first bad one
 * is the message; the same option given twice keeps the last value,
 * except for the CLI_OPT_CALL ones, which decide (the overrides add up).
 * The messages are the commands' own (tests/cli check them):
 *   slipwall CMD: -n: '0' is not a sample count (1 to 10^9)
 *   slipwall CMD: --samples: empty file name
 *   slipwall CMD: --seed needs a value
 *   slipwall CMD: unknown option '--bogus'
 *   slipwall CMD: one wall file only ('a.yaml' and 'b.yaml')
 *   slipwall CMD: which wall? (slipwall CMD WALL.yaml)
 * each followed by "Try 'slipwall CMD --help'." (cli_usage_error).
 */
#ifndef SLIPWALL_CLI_OPTS_H
#define SLIPWALL_CLI_OPTS_H

#include <stdio.h>

enum cli_opt_kind {
	CLI_OPT_FLAG,		/* no value: int, set to 1 */
	CLI_OPT_LONG,		/* a whole number in [lo, hi]: long */
	CLI_OPT_INT,		/* a whole number in [lo, hi]: int */
	CLI_OPT_DOUBLE,		/* a number in [lo, hi]: double (lo itself
				 * refused with .above) */
	CLI_OPT_SEED,		/* a seed (cli_parse_seed): unsigned long */
	CLI_OPT_TIME,		/* a time limit (cli_parse_time_limit): double */
	CLI_OPT_STRING,		/* a non-empty text: const char * (into argv) */
	CLI_OPT_CALL,		/* .call decides, and stores into .dst */
};

struct cli_opt {
	const char *name;	/* "--seed", "-n" */
	const char *alias;	/* a second name ("-m" for "--method"), or NULL */
	enum cli_opt_kind kind;
	void *dst;		/* where the value goes (see the kinds) */
	int *given;		/* raised when the option is given, or NULL */
	double lo, hi;		/* the range of LONG, INT and DOUBLE */
	int above;		/* DOUBLE: lo excluded (v > lo) */
	/* the message's end: "NAME: 'VALUE' is not WHAT" for the numbers,
	 * "NAME: empty WHAT" for a string */
	const char *what;
	/* CALL: returns 0, or an exit status after printing the usage
	 * error (cli_usage_error(cmd, ...)); name is the option as
	 * declared */
	int (*call)(const char *cmd, const char *name, const char *value,
		    void *dst);
};

/* How a command takes its options and its wall file. */
struct cli_cmd {
	const char *name;	/* "run" */
	void (*usage)(FILE *f);
	/* the message when no wall file is given */
	const char *no_wall;
	/* check and solve, which used getopt: "--" ends the options, an
	 * unknown option or a missing value is .unknown ("%s" the
	 * argument), and a wall count other than one is no_wall, said
	 * after every option was read */
	int posix;
	const char *unknown;	/* NULL: "unknown option '%s'" */
};

/* The options run, compare, report and sweep share; a names the
 * command's argument struct, with fields n, n_set, seed, seed_set,
 * threads (and depth for CLI_OPT_DEPTH). */
#define CLI_OPT_SAMPLING(a)						\
	{ .name = "-n", .kind = CLI_OPT_LONG, .dst = &(a)->n,		\
	  .given = &(a)->n_set, .lo = 1, .hi = 1000000000L,		\
	  .what = "a sample count (1 to 10^9)" },			\
	{ .name = "--seed", .kind = CLI_OPT_SEED, .dst = &(a)->seed,	\
	  .given = &(a)->seed_set },					\
	{ .name = "--threads", .kind = CLI_OPT_INT, .dst = &(a)->threads, \
	  .lo = 1, .hi = 1024, .what = "a thread count (1 to 1024)" }
#define CLI_OPT_DEPTH(a)						\
	{ .name = "--depth", .kind = CLI_OPT_DOUBLE, .dst = &(a)->depth,	\
	  .lo = 0, .hi = 0.5, .what = "a depth between 0 and 0.5" }
#define CLI_OPT_FILE(nm, field)						\
	{ .name = (nm), .kind = CLI_OPT_STRING, .dst = &(field),	\
	  .what = "file name" }
#define CLI_OPT_DIR(nm, field)						\
	{ .name = (nm), .kind = CLI_OPT_STRING, .dst = &(field),	\
	  .what = "directory name" }
#define CLI_OPT_SWITCH(nm, field)					\
	{ .name = (nm), .kind = CLI_OPT_FLAG, .dst = &(field) }

/* Parse argv[1..argc-1] (argv[0] is the command's name) against the n
 * options of opts.  Returns 0 with *wall set; -1 after printing the
 * usage for -h or --help (the command then exits 0); or 2 after
 * printing a usage error.  Values are stored as they are read, so on
 * an error some may be set (CALL ones may own memory to free). */
int cli_opts_parse(const struct cli_cmd *c, const struct cli_opt *opts,
		   int n, int argc, char **argv, const char **wall);

#endif
