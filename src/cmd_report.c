/*
 * cmd_report.c - `slipwall report`: figures and a summary of a run.
 *
 * Not built yet (issue "Figures and reports"): the command says so and
 * exits with status 2, rather than pretending.
 */
#include <stdio.h>

#include "cli.h"

int cmd_report(int argc, char **argv)
{
	(void)argc;
	(void)argv;
	fprintf(stderr,
		"slipwall report: not available in this version (figures are planned);\n"
		"use 'slipwall run --json' and 'slipwall compare --json' for the numbers.\n");
	return 2;
}
