/*
 * cli.h - the batch commands and what they share.
 *
 * Each command lives in its own file (cmd_check.c -> cmd_check, ...),
 * takes the arguments after its name (argv[0] is the command name) and
 * returns the process exit status: 0 success, 1 analysis failure, 2 bad
 * input or usage (sw_status_exit).  Messages go to stderr; results to
 * stdout.  No command touches curses.
 */
#ifndef SLIPWALL_CLI_H
#define SLIPWALL_CLI_H

#include <stdio.h>
#include "slipwall/sample.h"
#include "slipwall/text.h"
#include "slipwall/wall.h"

int cmd_check(int argc, char **argv);
int cmd_solve(int argc, char **argv);
int cmd_run(int argc, char **argv);
int cmd_compare(int argc, char **argv);
int cmd_report(int argc, char **argv);
int cmd_sweep(int argc, char **argv);

/* Load and finish a wall file; on failure print the message to stderr
 * and return the exit status (2), else 0. */
int cli_load_wall(const char *path, struct wall **w);
/* The same without cli_warn_wall (a file that overrides will change) */
int cli_load_wall_quiet(const char *path, struct wall **w);
/* Warn on stderr when two joints of a block can lock each other with
 * associative friction (wall_friction_lock): the answers are then not
 * the wall's; and when blocks rest on no joint (wall_hanging): samples
 * may then end not converged.  Called by every load of a wall file. */
void cli_warn_wall(const struct wall *w);
/* The same warnings for --json: the key "warnings", an array of
 * strings (empty when there are none). */
struct json;
void cli_json_warnings(struct json *j, const struct wall *w);
/* After sampling: if the LP solver ran out of memory (each time a
 * sample was rejected as numerical), say so and what to do. */
void cli_memory_note(const char *cmd);
/* --depth D (D >= 0: given) of a wall whose contact points are drawn
 * anywhere (contacts.positions): a usage error, returns 2; else 0. */
int cli_check_depth(const char *cmd, const struct wall *w, const char *path,
		    double depth);
/* The bundled demo wall: from the build tree when the program runs from
 * it, else the installed copy.  Never NULL (may not exist). */
const char *cli_demo_wall(void);
/* s as it may be printed (text_clean): s itself when it is clean, else
 * a cleaned copy that lives until eight more calls have been made - for
 * printf arguments: printf("%s", cli_text(w->name)).  NULL stays NULL. */
const char *cli_text(const char *s);
/* Print a message and a newline to stderr, its control characters and
 * invalid UTF-8 escaped (text_clean): messages carry paths and names. */
void cli_errorf(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
/* Print "slipwall CMD: message" and a hint to stderr; returns 2. */
int cli_usage_error(const char *cmd, const char *fmt, ...)
	__attribute__((format(printf, 2, 3)));
/* A seed: decimal digits only, 0 to WALL_SEED_MAX (the range of the wall
 * file's analysis.seed); 0 on success. */
int cli_parse_seed(const char *s, unsigned long *out);
/* --time-limit of solve and report: seconds, > 0 and at most
 * CLI_TIME_LIMIT_MAX (GLPK counts its limit in int milliseconds, which
 * end at 2^31-1 ms = 24.8 days); 0 on success. */
#define CLI_TIME_LIMIT_MAX 1e6
int cli_parse_time_limit(const char *s, double *out);
/* Experimental collapse loads (compare --tests, report --tests): one
 * load >= 0 per line, '#' starts a comment, blank lines are skipped.
 * *out (malloc'd) and *nout on SW_OK; else SW_EINPUT and a message
 * "FILE:LINE:COLUMN: what is wrong" in err. */
enum sw_status cli_read_tests(const char *path, double **out, long *nout,
			      char *err);
/* The experimental loads of compare and report: FILE (--tests) when
 * given, else the wall's tests: key (none: *ntests = 0).  Returns 0, or
 * 2 after printing the file's error. */
int cli_tests(const char *file, const struct wall *w, double **tests,
	      long *ntests);
/* Does a loads file call its loads synthetic: has it the marker line
 * "# slipwall: synthetic" (docs/run.md)?  Then compare and report say
 * so.  Words in other comments ("not synthetic", "the synthetic tests
 * are elsewhere") do not count. */
int cli_tests_synthetic(const char *path);
/* Write " s" to f, single-quoted for a POSIX shell when a shell would
 * change it, so that sh reads back s byte for byte: a quote as '\'',
 * a newline as it is (inside the quotes: the argument spans lines),
 * every other control character and invalid UTF-8 byte as
 * "$(printf '\ooo')" outside the quotes, so none is written raw. */
void cli_shell_arg(FILE *f, const char *s);
/* Estimated memory of one worker of a pool sampling w (its sampling
 * workspace: the GLPK problems and the operators grow with the
 * interfaces; measured about 11 KB per interface on walls/large.yaml,
 * estimated at 16 KB), in bytes. */
double cli_worker_bytes(const struct wall *w);
/* The worker threads for n samples of w into *threads: requested (0:
 * the default, def) but never more than n, nor than the memory holds
 * at cli_worker_bytes each (the machine's memory, or the address-space
 * limit when lower).  A default is cut down to fit; an explicit request
 * that does not fit is a usage error: returns 2 after printing it, with
 * the count that fits.  Else 0.  It also sets the limit of the LP
 * solver's allocator on each worker (cli_lp's mem_limit_mb, unless the
 * environment set it): the half of the memory above shared out between
 * the *threads workers. */
int cli_threads(const char *cmd, const struct wall *w, int requested,
		int def, long n, int *threads);

/* The LP solvers' settings (sample.h): from the environment (main.c:
 * SLIPWALL_LP_START, and for tests SLIPWALL_LP_FAULT and
 * SLIPWALL_GLPK_MEM_MB, which wins over cli_threads' limit), read once
 * before any command; each command copies it into its options. */
extern struct sample_lp_config cli_lp;
/* Read the environment into cli_lp: 0, or -1 after printing why not (a
 * start that is not one; a bad test variable is only said, and
 * ignored, as it always was). */
int cli_lp_from_env(void);

#endif
