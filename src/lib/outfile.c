/*
 * outfile.c - the one output policy: never an input, files whole,
 * streams written directly, directories checked first; see
 * slipwall/outfile.h.
 *
 * The checks go by what the path is now (stat, following links): the
 * device and inode against every input, the kind of file.  A file is
 * written to DEST.tmp, where DEST is the path or the file a symbolic
 * link names (so that the link stays a link and the temporary file is on
 * the destination's file system, where rename is atomic).  A stream is
 * opened O_NONBLOCK first: open(2) of a FIFO for writing blocks until a
 * reader comes, and fails at once with ENXIO in that mode.
 */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "slipwall/outfile.h"
#include "slipwall/text.h"

int outfile_input(const struct stat *st, const char *const *inputs)
{
	for (int i = 0; inputs && inputs[i]; i++) {
		struct stat in;
		if (stat(inputs[i], &in) == 0 && in.st_dev == st->st_dev &&
		    in.st_ino == st->st_ino)
			return i;
	}
	return -1;
}

/* What a file that is not a regular one is, for the messages. */
static const char *kind(mode_t m)
{
	return S_ISDIR(m) ? strerror(EISDIR) : S_ISFIFO(m) ? "a FIFO" :
	       S_ISCHR(m) ? "a character device" :
	       S_ISBLK(m) ? "a block device" :
	       S_ISSOCK(m) ? "a socket" : "not a regular file";
}

static int is_stream(mode_t m)
{
	return S_ISFIFO(m) || S_ISCHR(m);
}

/* The descriptor path names when it is one of the process's own
 * (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N), else -1: a
 * stream output there is written through that descriptor, at its
 * offset (`--csv /dev/stdout > f` appends to f after the table, where
 * opening the path anew would truncate f, and a rename replace it). */
static int own_fd(const char *path)
{
	if (!strcmp(path, "/dev/stdout"))
		return STDOUT_FILENO;
	if (!strcmp(path, "/dev/stderr"))
		return STDERR_FILENO;
	const char *p = !strncmp(path, "/dev/fd/", 8) ? path + 8 :
			!strncmp(path, "/proc/self/fd/", 14) ? path + 14 : NULL;
	if (!p || !*p || strlen(p) > 6 || strspn(p, "0123456789") != strlen(p))
		return -1;
	return atoi(p);
}

/* The directory of path (malloc'd): "." for a bare name. */
static char *parent_of(const char *path)
{
	const char *slash = strrchr(path, '/');
	if (!slash)
		return sw_xstrdup(".");
	if (slash == path)
		return sw_xstrdup("/");
	char *p = sw_xmalloc((size_t)(slash - path) + 1);
	memcpy(p, path, (size_t)(slash - path));
	p[slash - path] = 0;
	return p;
}

/* Can a file be created in the directory of dest (its temporary file,
 * or itself)?  SW_OK or the reason, naming path. */
static enum sw_status dir_writable(const char *path, const char *dest,
				   char *err)
{
	char *dir = parent_of(dest);
	struct stat st;
	int e = stat(dir, &st) != 0 ? errno : !S_ISDIR(st.st_mode) ? ENOTDIR :
		access(dir, W_OK | X_OK) != 0 ? errno : 0;
	free(dir);
	if (e)
		return sw_fail(err, SW_EIO, "%s: cannot write: %s", path,
			       strerror(e));
	return SW_OK;
}

/* The file path names: itself, or what its symbolic link names
 * (malloc'd). */
static char *destination(const char *path)
{
	struct stat l;
	char *real;
	if (lstat(path, &l) == 0 && S_ISLNK(l.st_mode) &&
	    (real = realpath(path, NULL)))
		return real;
	return sw_xstrdup(path);
}

/* outfile_check; the directory's permissions only when dir is set
 * (outfile_open lets the creation of PATH.tmp say why it fails). */
static enum sw_status check(const char *path, const char *const *inputs,
			    int flags, const char *what, int dir, char *err)
{
	struct stat st;
	int fd = flags & OUTFILE_STREAM ? own_fd(path) : -1;
	if (fd >= 0 && fstat(fd, &st) == 0) {
		int k = outfile_input(&st, inputs);
		if (k >= 0)
			return sw_fail(err, SW_EINPUT, "%s: this is the input "
				       "file %s: %s would overwrite it", path,
				       inputs[k], what);
		return SW_OK;
	}
	if (stat(path, &st) != 0) {
		if (errno != ENOENT)
			return sw_fail(err, SW_EIO, "%s: cannot write: %s", path,
				       strerror(errno));
		return dir ? dir_writable(path, path, err) : SW_OK;
	}
	int k = outfile_input(&st, inputs);
	if (k >= 0)
		return sw_fail(err, SW_EINPUT, "%s: this is the input file %s: "
			       "%s would overwrite it", path, inputs[k], what);
	if (is_stream(st.st_mode) && (flags & OUTFILE_STREAM))
		return SW_OK;
	if (!S_ISREG(st.st_mode))
		return sw_fail(err, SW_EIO, "%s: cannot write: %s%s", path,
			       kind(st.st_mode), S_ISDIR(st.st_mode) ? "" :
			       ", not a file (it would be replaced by one)");
	if (!dir)
		return SW_OK;
	char *dest = destination(path);
	enum sw_status rc = dir_writable(path, dest, err);
	free(dest);
	return rc;
}

int outfile_is_stream(const char *path)
{
	struct stat st;
	return own_fd(path) >= 0 ||
	       (stat(path, &st) == 0 && is_stream(st.st_mode));
}

enum sw_status outfile_check(const char *path, const char *const *inputs,
			     int flags, const char *what, char *err)
{
	return check(path, inputs, flags, what, 1, err);
}

/* How often a wait for a FIFO's reader tries the FIFO again. */
#define WAIT_READER_NS 50000000L	/* 50 ms */

/* "waiting for a process to read this FIFO", then the wait for a
 * reader; SIGINT, SIGTERM and SIGHUP (those a run catches, run.h) end
 * it: -1 with errno EINTR and the signal in *sig.
 *
 * open(2) has no variant that unblocks signals atomically (as pselect
 * and ppoll do), so a blocking open with a handler that sets a flag
 * leaves a window: a signal between the flag's test and the call is
 * handled, and the open blocks on.  Here the three signals are blocked
 * from before the message to the end of the wait, and the wait is
 * open(O_NONBLOCK), which fails with ENXIO while no process reads, then
 * sigtimedwait for 50 ms: a signal sent at any moment is taken by the
 * next sigtimedwait, and a reader that comes is found within 50 ms.  A
 * signal ignored at start (nohup) is not blocked: Linux would keep it
 * pending while blocked, and the wait would end on it. */
static int wait_reader(const char *path, int oflags, int *sig)
{
	static const int sigs[3] = {SIGINT, SIGTERM, SIGHUP};
	sigset_t set, old;
	sigemptyset(&set);
	for (int k = 0; k < 3; k++) {
		struct sigaction now;
		if (sigaction(sigs[k], NULL, &now) == 0 &&
		    now.sa_handler != SIG_IGN)
			sigaddset(&set, sigs[k]);
	}
	pthread_sigmask(SIG_BLOCK, &set, &old);
	char *c = text_clean(path);
	fprintf(stderr, "slipwall: %s: waiting for a process to read this "
		"FIFO\n", c);
	free(c);
	const struct timespec tick = {0, WAIT_READER_NS};
	const struct timespec none = {0, 0};
	int fd, got = -1;
	while ((fd = open(path, oflags | O_NONBLOCK, 0666)) < 0 &&
	       (errno == ENXIO || errno == EINTR)) {
		got = sigtimedwait(&set, NULL, &tick);
		if (got > 0)
			break;
	}
	int e = errno;
	/* the reader came with the signal: the signal wins, as it would
	 * have a moment later */
	if (fd >= 0 && (got = sigtimedwait(&set, NULL, &none)) > 0) {
		close(fd);
		fd = -1;
	}
	if (got > 0)
		e = EINTR;
	pthread_sigmask(SIG_SETMASK, &old, NULL);
	*sig = got > 0 ? got : 0;
	errno = e;
	return fd;
}

int outfile_open_fd(const char *path, int extra, const char *const *inputs,
		    const char *what, struct stat *st, enum sw_status *stp,
		    char *err)
{
	*stp = SW_EIO;
	int oflags = O_WRONLY | O_CREAT | O_CLOEXEC | extra;
	int fd = open(path, oflags | O_NONBLOCK, 0666);
	if (fd < 0 && errno == ENXIO) {
		/* a FIFO that no process reads: said, then waited for (a
		 * reader started beside the command may come a moment
		 * later); a signal ends the wait with a message, not in
		 * silence */
		int sig;
		fd = wait_reader(path, oflags, &sig);
		if (fd < 0 && sig) {
			*stp = SW_EINTR;
			sw_fail(err, SW_EINTR, "%s: interrupted (%s) while "
				"waiting for a process to read this FIFO: "
				"nothing was written", path, strsignal(sig));
			return -1;
		}
	}
	if (fd < 0) {
		sw_fail(err, SW_EIO, "%s: cannot create: %s", path,
			strerror(errno));
		return -1;
	}
	int fl = fcntl(fd, F_GETFL);
	if (fstat(fd, st) != 0 || fl < 0 ||
	    fcntl(fd, F_SETFL, fl & ~O_NONBLOCK) != 0) {
		sw_fail(err, SW_EIO, "%s: %s", path, strerror(errno));
		close(fd);
		return -1;
	}
	int k = outfile_input(st, inputs);
	if (k >= 0 || !(S_ISREG(st->st_mode) || is_stream(st->st_mode))) {
		if (k >= 0) {
			*stp = SW_EINPUT;
			sw_fail(err, SW_EINPUT, "%s: this is the input file %s: "
				"%s would overwrite it", path, inputs[k], what);
		} else {
			sw_fail(err, SW_EIO, "%s: cannot create: %s", path,
				kind(st->st_mode));
		}
		close(fd);
		return -1;
	}
	*stp = SW_OK;
	return fd;
}

int outfile_open_beside(const char *path, const struct stat *old,
			char **dest, char **tmp, char *err)
{
	*dest = destination(path);
	size_t n = strlen(*dest) + 5;
	*tmp = sw_xmalloc(n);
	snprintf(*tmp, n, "%s.tmp", *dest);
	int fd = open(*tmp, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
	if (fd < 0) {
		sw_fail(err, SW_EIO, "%s: cannot write: %s", *tmp,
			strerror(errno));
		free(*dest);
		free(*tmp);
		*dest = *tmp = NULL;
		return -1;
	}
	/* the file replaced keeps its permissions */
	if (old)
		fchmod(fd, old->st_mode & 07777);
	return fd;
}

/* Release what o holds. */
static void outfile_free(struct outfile *o)
{
	free(o->path);
	free(o->dest);
	free(o->tmp);
	memset(o, 0, sizeof *o);
}

enum sw_status outfile_open(struct outfile *o, const char *path,
			    const char *const *inputs, int flags,
			    const char *what, char *err)
{
	memset(o, 0, sizeof *o);
	enum sw_status rc = check(path, inputs, flags, what, 0, err);
	if (rc != SW_OK)
		return rc;
	struct stat st;
	int own = flags & OUTFILE_STREAM ? own_fd(path) : -1;
	if (own >= 0 && (own = dup(own)) >= 0) {
		if (!(o->f = fdopen(own, "w"))) {
			close(own);
			return sw_fail(err, SW_EIO, "%s: cannot write: %s", path,
				       strerror(errno));
		}
		o->path = sw_xstrdup(path);
		errno = 0;
		return SW_OK;
	}
	int exists = stat(path, &st) == 0;
	if (exists && is_stream(st.st_mode)) {
		int fd = outfile_open_fd(path, 0, inputs, what, &st, &rc, err);
		if (fd < 0)
			return rc;
		if (!(o->f = fdopen(fd, "w"))) {
			close(fd);
			return sw_fail(err, SW_EIO, "%s: cannot write: %s", path,
				       strerror(errno));
		}
		o->path = sw_xstrdup(path);
		errno = 0;
		return SW_OK;
	}
	o->path = sw_xstrdup(path);
	int fd = outfile_open_beside(path, exists ? &st : NULL, &o->dest,
				     &o->tmp, err);
	if (fd < 0) {
		outfile_free(o);
		return SW_EIO;
	}
	if (!(o->f = fdopen(fd, "w"))) {
		rc = sw_fail(err, SW_EIO, "%s: cannot write: %s", o->tmp,
			     strerror(errno));
		close(fd);
		unlink(o->tmp);
		outfile_free(o);
		return rc;
	}
	errno = 0;	/* a failed write below leaves its reason here */
	return SW_OK;
}

int outfile_flush(struct outfile *o)
{
	if (!o->err && (ferror(o->f) || fflush(o->f) != 0))
		o->err = errno ? errno : EIO;
	return o->err;
}

enum sw_status outfile_commit(struct outfile *o, char *err)
{
	int e = o->err;
	if (!e && (ferror(o->f) || fflush(o->f) != 0))
		e = errno ? errno : EIO;
	if (!e && o->tmp && fsync(fileno(o->f)) != 0)
		e = errno;
	if (fclose(o->f) != 0 && !e)
		e = errno ? errno : EIO;
	if (!e && o->tmp && rename(o->tmp, o->dest) != 0)
		e = errno;
	enum sw_status st = SW_OK;
	if (e) {
		if (o->tmp)
			unlink(o->tmp);
		st = sw_fail(err, SW_EIO, "%s: cannot write: %s", o->path,
			     strerror(e));
	}
	outfile_free(o);
	return st;
}

void outfile_abort(struct outfile *o)
{
	if (o->f)
		fclose(o->f);
	if (o->tmp)
		unlink(o->tmp);
	outfile_free(o);
}

/* The nearest ancestor of dir that exists must be a directory that a
 * directory can be made in.  SW_OK or the reason, naming dir. */
static enum sw_status can_make(const char *dir, char *err)
{
	char *p = sw_xstrdup(dir);
	struct stat st;
	int e = 0;
	for (;;) {
		char *up = parent_of(p);
		free(p);
		p = up;
		if (stat(p, &st) == 0) {
			e = !S_ISDIR(st.st_mode) ? ENOTDIR :
			    access(p, W_OK | X_OK) != 0 ? errno : 0;
			break;
		}
		if (errno != ENOENT) {
			e = errno;
			break;
		}
		if (!strcmp(p, ".") || !strcmp(p, "/"))
			break;
	}
	free(p);
	if (e)
		return sw_fail(err, SW_EIO, "%s: cannot create: %s", dir,
			       strerror(e));
	return SW_OK;
}

enum sw_status outfile_check_dir(const char *dir, const char *const *names,
				 const char *const *inputs, const char *what,
				 char *err)
{
	struct stat st;
	if (!*dir)
		return sw_fail(err, SW_EIO, "an empty directory name");
	if (stat(dir, &st) != 0) {
		if (errno == ENOENT)
			return can_make(dir, err);
		return sw_fail(err, SW_EIO, "%s: cannot create: %s", dir,
			       strerror(errno));
	}
	int k = outfile_input(&st, inputs);
	if (k >= 0)
		return sw_fail(err, SW_EINPUT, "%s: this is the input file %s: "
			       "%s would overwrite it", dir, inputs[k], what);
	if (!S_ISDIR(st.st_mode))
		return sw_fail(err, SW_EIO, "%s: cannot create: %s", dir,
			       strerror(ENOTDIR));
	if (access(dir, W_OK | X_OK) != 0)
		return sw_fail(err, SW_EIO, "%s: cannot write: %s", dir,
			       strerror(errno));
	for (int i = 0; names && names[i]; i++) {
		size_t n = strlen(dir) + strlen(names[i]) + 2;
		char *p = sw_xmalloc(n);
		snprintf(p, n, "%s/%s", dir, names[i]);
		enum sw_status rc = SW_OK;
		if (lstat(p, &st) == 0)
			rc = outfile_check(p, inputs, 0, what, err);
		free(p);
		if (rc != SW_OK)
			return rc;
	}
	return SW_OK;
}
