/*
 * main.c - the program's entry: the workbench, or a batch command.
 *
 *   slipwall [WALL.yaml]        the workbench (default: the demo wall)
 *   slipwall COMMAND ...        run, solve, check, compare, report, sweep
 */
#include <errno.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "slipwall/sample.h"
#include "workbench.h"

static const struct {
	const char *name;
	int (*fn)(int, char **);
	const char *summary;
} commands[] = {
	{"run", cmd_run, "sample the collapse load (Monte Carlo)"},
	{"solve", cmd_solve, "one solution: standard, gilbert or global"},
	{"check", cmd_check, "validate a wall; print blocks, interfaces, loads"},
	{"compare", cmd_compare, "samples against experimental loads (KS test)"},
	{"report", cmd_report, "figures and a summary of a run"},
	{"sweep", cmd_sweep, "one run per value of friction, depth or load point"},
};

static void usage(FILE *f)
{
	fprintf(f,
		"usage: slipwall [WALL.yaml]          the workbench (default: the demo wall)\n"
		"       slipwall COMMAND [ARGS]       a batch command\n"
		"\n"
		"Probabilistic limit analysis of dry-masonry walls that collapse by\n"
		"sliding: rigid blocks, unilateral contact, non-associative Coulomb\n"
		"friction, contact points drawn at random (Monte Carlo).\n"
		"\n"
		"commands:\n");
	for (size_t i = 0; i < sizeof commands / sizeof *commands; i++)
		fprintf(f, "  %-9s %s\n", commands[i].name, commands[i].summary);
	fprintf(f,
		"\n'slipwall COMMAND --help' describes a command; 'man slipwall' all.\n"
		"Exit status: 0 success, 1 analysis failure, 2 bad input or usage.\n");
}

/* A result that did not reach standard output (a full disk, a closed
 * pipe) is a failure, not a silent success. */
static int finish(int rc)
{
	int before = errno;
	errno = 0;
	if (fflush(stdout) != 0 || ferror(stdout)) {
		/* errno is the flush's.  A write that failed earlier left
		 * only stdout's error mark: errno is its reason if it is a
		 * write's (a full disk: ENOSPC), else another call's (sweep
		 * --csv F | true said "Success") */
		int e = errno ? errno : before;
		int wr = e == EPIPE || e == ENOSPC || e == EIO || e == EFBIG ||
			 e == EDQUOT;
		fprintf(stderr, "slipwall: standard output: %s\n", wr ?
			strerror(e) : "a write failed (a closed pipe or a "
			"full disk): the output is incomplete");
		return rc ? rc : 1;
	}
	return rc;
}

int main(int argc, char **argv)
{
	sw_init();	/* the library's process set-up: GSL's handler off */
	/* the LP solvers' settings (cli_lp): SLIPWALL_LP_START
	 * (docs/method.md) must name a start, a misspelt one would
	 * silently run the default */
	if (cli_lp_from_env())
		return 2;
	if (argc >= 2) {
		const char *a = argv[1];
		if (!strcmp(a, "--help") || !strcmp(a, "-h") || !strcmp(a, "help")) {
			usage(stdout);
			return 0;
		}
		if (!strcmp(a, "--version")) {
			printf("slipwall %s\n", sw_version());
			return 0;
		}
		for (size_t i = 0; i < sizeof commands / sizeof *commands; i++)
			if (!strcmp(a, commands[i].name)) {
				/* a closed pipe (`--samples /dev/stdout |
				 * head`) is a write error with a message
				 * (EPIPE), not a silent death by SIGPIPE */
				signal(SIGPIPE, SIG_IGN);
				return finish(commands[i].fn(argc - 1, argv + 1));
			}
		if (a[0] == '-') {
			fprintf(stderr, "slipwall: unknown option '%s'\n", a);
			usage(stderr);
			return 2;
		}
		if (argc > 2) {
			fprintf(stderr, "slipwall: the workbench takes one wall file\n");
			usage(stderr);
			return 2;
		}
		return tui_main(a, &cli_lp);
	}
	return tui_main(cli_demo_wall(), &cli_lp);
}
