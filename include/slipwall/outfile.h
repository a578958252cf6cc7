/*
 * outfile.h - the one output policy of every command and the workbench
 * (docs/reliability.md, "Outputs"):
 *
 *  - An output is never one of the inputs.  Its path is compared with
 *    every input file by device and inode, however either is spelled
 *    (`./w.yaml`, a symbolic or a hard link): SW_EINPUT (exit 2),
 *    "PATH: this is the input file IN: WHAT would overwrite it".
 *  - A file is written whole: into PATH.tmp beside it, flushed to the
 *    disk (fsync), then renamed over PATH.  A failure (a full disk) or an
 *    abort removes PATH.tmp and leaves the old PATH byte for byte.  A
 *    symbolic link is written through: the file it names is replaced
 *    (keeping its permissions), the link stays a link.
 *  - A stream - a FIFO or a character device (/dev/null, /dev/stdout, a
 *    terminal) - is written directly, never replaced by a regular file,
 *    where the output allows it (OUTFILE_STREAM: run --samples, sweep
 *    --csv); so is one of the process's own descriptors (/dev/stdout,
 *    /dev/fd/N: through a copy of it, at its offset, whatever it is:
 *    `sweep --csv /dev/stdout > f` puts the CSV after the table in f).
 *    A FIFO that no process reads is never waited on in
 *    silence: "slipwall: PATH: waiting for a process to read this FIFO"
 *    goes to stderr, then the open waits (a reader started beside the
 *    command, `cat FIFO &`, may come a moment later); SIGINT (Ctrl-C),
 *    SIGTERM or SIGHUP ends the wait with SW_EINTR and "PATH:
 *    interrupted (SIGNAL) while waiting for a process to read this
 *    FIFO: nothing was written".  Where the output does not allow
 *    a stream (the workbench's save and summary, report.md) and for
 *    anything else that is not a regular file (a directory, a block
 *    device, a socket) the path is refused, naming what it is.
 *  - Directories (report --out, sweep --out) are checked before any
 *    work: an existing directory (a symbolic link to one is one), or a
 *    path whose nearest existing ancestor is a directory that mkdir -p
 *    can work in; the files the command will write in it are checked as
 *    files (not an input, not a directory or a device).
 *
 * Every refusal but "is an input" is SW_EIO (exit 1) with
 * "PATH: cannot write: why" ("cannot create" for a directory), the
 * words of the messages before this module.  The checks are made when
 * the command starts (outfile_check, outfile_check_dir: no sampling is
 * lost to a path that cannot be written) and again when the file is
 * opened.
 */
#ifndef SLIPWALL_OUTFILE_H
#define SLIPWALL_OUTFILE_H

#include <stdio.h>
#include <sys/stat.h>

#include "slipwall/status.h"

/* flags: a FIFO or a character device is written directly */
#define OUTFILE_STREAM 1

/* A file being written.  After a successful outfile_open, exactly one
 * of outfile_commit and outfile_abort must be called. */
struct outfile {
	FILE *f;
	char *path;	/* as given (messages) */
	char *dest;	/* what is replaced: path, or the file a link names */
	char *tmp;	/* DEST.tmp; NULL when written directly (a stream) */
	int err;	/* the first failed outfile_flush's errno, or 0 */
};

/* The index in inputs (NULL-terminated; NULL itself: none) of the input
 * that st is (the same device and inode), or -1.  An input that does not
 * exist is no file. */
int outfile_input(const struct stat *st, const char *const *inputs);

/* Can path be written as an output (see above)?  SW_OK, or the refusal
 * in err.  what names the output in the message ("the samples", "the
 * CSV"). */
enum sw_status outfile_check(const char *path, const char *const *inputs,
			     int flags, const char *what, char *err);

/* Would outfile_open(path, ..., OUTFILE_STREAM, ...) write path
 * directly - one of the process's own descriptors (/dev/stdout,
 * /dev/fd/N), or a FIFO or character device that exists - rather than
 * into PATH.tmp?  (sweep --csv streams its rows into PATH.tmp as the
 * values finish, but writes a stream after its table.) */
int outfile_is_stream(const char *path);

/* Open path for writing (outfile_check first): o->f is PATH.tmp, or the
 * stream itself. */
enum sw_status outfile_open(struct outfile *o, const char *path,
			    const char *const *inputs, int flags,
			    const char *what, char *err);
/* Flush what was written so far (a file written as its work goes on:
 * sweep's rows).  The first failure's errno is kept for
 * outfile_commit, which then fails with it; returns it, or 0. */
int outfile_flush(struct outfile *o);
/* Flush (fsync a file), close and rename PATH.tmp over the destination.
 * On any failure PATH.tmp is removed: SW_EIO, "PATH: cannot write: why".
 * o is released either way. */
enum sw_status outfile_commit(struct outfile *o, char *err);
/* Close and remove PATH.tmp: the destination is as it was (a stream
 * keeps what was written to it).  o is released. */
void outfile_abort(struct outfile *o);

/* Open a stream-or-file output by descriptor, for the samples file that
 * is appended row by row (runlog.c): open(path, O_WRONLY | O_CREAT |
 * extra), a FIFO that no process reads said on stderr before the wait
 * (above), the descriptor in blocking mode; *st is what was opened.  Inputs and kinds as outfile_check, OUTFILE_STREAM.  Returns
 * the descriptor, or -1 with the refusal in err and *stp its status. */
int outfile_open_fd(const char *path, int extra, const char *const *inputs,
		     const char *what, struct stat *st, enum sw_status *stp,
		     char *err);
/* The temporary file beside the file path names, DEST.tmp, DEST being
 * path or the file its symbolic link names: created empty (truncated if
 * a killed process left one), with old's permissions where old (the
 * file it replaces) is given.  outfile_open writes a whole file there;
 * runlog.c the new samples file's header, so that the old one stays
 * whole until then.  *dest and *tmp (malloc'd) get both names; rename
 * *tmp to *dest to replace it.  Returns the descriptor, or -1 with
 * "DEST.tmp: cannot write: why" in err. */
int outfile_open_beside(const char *path, const struct stat *old,
			char **dest, char **tmp, char *err);

/* Can dir be the directory of a command's files (see above)?  names
 * (NULL-terminated, or NULL) are the files it will write in dir: each
 * that exists is checked as an output (outfile_check, not a stream). */
enum sw_status outfile_check_dir(const char *dir, const char *const *names,
				 const char *const *inputs, const char *what,
				 char *err);

#endif
