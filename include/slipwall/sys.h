/*
 * sys.h - the calls to the system that several rooms make: the
 * monotonic clock, `mkdir -p` and the signal mask of a new thread.  One
 * copy each, so that every timing is taken the same way and every
 * directory is made the same way.
 */
#ifndef SLIPWALL_SYS_H
#define SLIPWALL_SYS_H

#include <signal.h>
#include <stddef.h>

/* Seconds on the monotonic clock (CLOCK_MONOTONIC): only differences
 * mean anything.  Thread-safe, async-signal-safe. */
double sys_now(void);

/* Make the directory dir and its missing parents, mode 0777 less the
 * umask; directories that exist already are fine (a final component
 * that exists as a file is not found here: stat it when that matters).
 * Returns 0, or -1 with errno set (ENAMETOOLONG when dir has PATH_MAX
 * bytes or more, ENOENT when it is empty) and, when failed is not NULL, the path of the
 * directory that could not be made (a prefix of dir, or dir itself) in
 * failed[0..failed_len). */
int sys_mkdir_p(const char *dir, char *failed, size_t failed_len);

/* Before pthread_create: block every signal in this thread (the new
 * thread inherits the mask; *old is the mask to restore after) except
 * the ones a fault raises on the faulting thread - SIGSEGV, SIGBUS,
 * SIGFPE, SIGILL, SIGABRT - which the kernel would otherwise deliver
 * with the default action, past a front end's handler for them (the
 * workbench restores the terminal there, tui_fatal.c). */
void sys_block_signals(sigset_t *old);

#endif
