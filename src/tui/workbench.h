/*
 * workbench.h - the one door into src/tui/: the program's main calls it
 * for `slipwall [WALL.yaml]`.  Everything else in the room (tui.h) is
 * private to it.
 */
#ifndef SLIPWALL_WORKBENCH_H
#define SLIPWALL_WORKBENCH_H

/* Run the workbench on the wall file `path` until the user quits (or a
 * SIGHUP, SIGINT, SIGTERM).  Needs a terminal on stdin and stdout.
 * Returns the process exit status: 0, 2 for a wall that does not load or
 * no terminal, 1 for a failure of the terminal. */
struct sample_lp_config;
/* lp: the LP solvers' settings the command line read from the
 * environment (src/cli/main.c), for every workspace of the workbench. */
int tui_main(const char *path, const struct sample_lp_config *lp);

#endif
