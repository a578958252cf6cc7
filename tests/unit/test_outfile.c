/*
 * test_outfile.c - the output policy (slipwall/outfile.h): an output
 * is never an input, files are written whole, streams are written and
 * not replaced, directories are checked before any work.  (A FIFO
 * without a reader: tests/cli/hostile.sh.)
 */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "slipwall/outfile.h"
#include "tap.h"

static char dir[] = "/tmp/test_outfile.XXXXXX";

static const char *at(const char *name)
{
	static char p[8][512];
	static int k;
	k = (k + 1) % 8;
	snprintf(p[k], sizeof p[k], "%s/%s", dir, name);
	return p[k];
}

static void put(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");
	if (f) {
		fputs(text, f);
		fclose(f);
	}
}

static int has(const char *path, const char *text)
{
	char buf[256] = "";
	FILE *f = fopen(path, "r");
	if (!f)
		return 0;
	size_t n = fread(buf, 1, sizeof buf - 1, f);
	buf[n] = 0;
	fclose(f);
	return !strcmp(buf, text);
}

static int exists(const char *path)
{
	struct stat st;
	return lstat(path, &st) == 0;
}

/* Write text to path through outfile; the status. */
static enum sw_status write_to(const char *path, const char *const *in,
			       int flags, const char *text, char *err)
{
	struct outfile o;
	enum sw_status st = outfile_open(&o, path, in, flags, "the test",
					 err);
	if (st != SW_OK)
		return st;
	fputs(text, o.f);
	return outfile_commit(&o, err);
}

static void test_inputs(void)
{
	char err[SW_ERRLEN];
	put(at("in.yaml"), "input\n");
	link(at("in.yaml"), at("hard.yaml"));
	symlink(at("in.yaml"), at("soft.yaml"));
	const char *in[] = {at("in.yaml"), NULL};
	const char *paths[] = {at("in.yaml"), at("hard.yaml"), at("soft.yaml"),
			       at("./in.yaml")};
	for (int i = 0; i < 4; i++) {
		enum sw_status st = write_to(paths[i], in, 0, "output\n", err);
		tap_ok(st == SW_EINPUT && strstr(err, "this is the input file") &&
		       has(at("in.yaml"), "input\n"),
		       "an input as the output (%s): SW_EINPUT, untouched",
		       paths[i] + strlen(dir) + 1);
	}
	struct stat st;
	stat(at("in.yaml"), &st);
	tap_ok(outfile_input(&st, (const char *const[]){at("x"), at("soft.yaml"),
							NULL}) == 1,
	       "outfile_input: the index of the input a file is");
}

static void test_whole(void)
{
	char err[SW_ERRLEN];
	put(at("old.csv"), "old\n");
	chmod(at("old.csv"), 0640);
	struct outfile o;
	tap_ok(outfile_open(&o, at("old.csv"), NULL, 0, "the test", err) ==
	       SW_OK && exists(at("old.csv.tmp")),
	       "a file is written to PATH.tmp");
	fputs("new, half", o.f);
	outfile_abort(&o);
	tap_ok(has(at("old.csv"), "old\n") && !exists(at("old.csv.tmp")),
	       "abort: the old file byte for byte, no temporary file");
	tap_ok(write_to(at("old.csv"), NULL, 0, "new\n", err) == SW_OK &&
	       has(at("old.csv"), "new\n") && !exists(at("old.csv.tmp")),
	       "commit: renamed over the old file");
	struct stat st;
	tap_ok(stat(at("old.csv"), &st) == 0 && (st.st_mode & 0777) == 0640,
	       "the file replaced keeps its permissions");
	/* a symbolic link is written through */
	mkdir(at("real"), 0700);
	put(at("real/t.csv"), "old\n");
	symlink(at("real/t.csv"), at("link.csv"));
	tap_ok(write_to(at("link.csv"), NULL, 0, "new\n", err) == SW_OK &&
	       lstat(at("link.csv"), &st) == 0 && S_ISLNK(st.st_mode) &&
	       has(at("real/t.csv"), "new\n"),
	       "a symbolic link stays a link; the file it names is replaced");
}

/* A file written as its work goes on (sweep's rows): the first failed
 * flush's errno is what the commit reports, whatever errno says by then,
 * and the old file stays. */
static void test_flush(void)
{
	char err[SW_ERRLEN];
	put(at("rows.csv"), "old\n");
	struct outfile o;
	outfile_open(&o, at("rows.csv"), NULL, 0, "the test", err);
	tap_ok(outfile_flush(&o) == 0, "outfile_flush: 0 while writes succeed");
	/* a write that fails (the file shut under the stream) */
	int fd = open("/dev/null", O_RDONLY);
	dup2(fd, fileno(o.f));
	close(fd);
	fputs("row\n", o.f);
	int e = outfile_flush(&o);
	errno = ENOTTY;	/* what later calls leave */
	fputs("row\n", o.f);
	tap_ok(e == EBADF && outfile_flush(&o) == EBADF &&
	       outfile_commit(&o, err) == SW_EIO && strstr(err, strerror(EBADF)) &&
	       has(at("rows.csv"), "old\n") && !exists(at("rows.csv.tmp")),
	       "a failed flush: the commit fails with its reason (%s), the old "
	       "file as it was", err);
}

static void test_streams(void)
{
	char err[SW_ERRLEN];
	struct stat st;
	tap_ok(write_to("/dev/null", NULL, OUTFILE_STREAM, "x\n", err) ==
	       SW_OK && stat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode),
	       "a character device is written to and stays a device");
	enum sw_status rc = write_to("/dev/null", NULL, 0, "x\n", err);
	tap_ok(rc == SW_EIO && strstr(err, "character device") &&
	       stat("/dev/null", &st) == 0 && S_ISCHR(st.st_mode),
	       "... refused where a stream is not allowed (%s)", err);
	mkfifo(at("fifo"), 0600);
	int r = open(at("fifo"), O_RDONLY | O_NONBLOCK);
	rc = write_to(at("fifo"), NULL, OUTFILE_STREAM, "through\n", err);
	char buf[32] = "";
	ssize_t n = r >= 0 ? read(r, buf, sizeof buf - 1) : -1;
	tap_ok(rc == SW_OK && n == 8 && !memcmp(buf, "through\n", 8) &&
	       stat(at("fifo"), &st) == 0 && S_ISFIFO(st.st_mode),
	       "a FIFO with a reader gets the output and stays a FIFO");
	if (r >= 0)
		close(r);
	rc = write_to(at("fifo"), NULL, 0, "x\n", err);
	tap_ok(rc == SW_EIO && strstr(err, "a FIFO"),
	       "... refused where a stream is not allowed (%s)",
	       err + strlen(dir) + 1);
	/* one of the process's own descriptors: through a copy of it */
	int pfd[2];
	if (pipe(pfd) == 0) {
		char fdpath[64];
		snprintf(fdpath, sizeof fdpath, "/dev/fd/%d", pfd[1]);
		rc = write_to(fdpath, NULL, OUTFILE_STREAM, "own\n", err);
		close(pfd[1]);
		n = read(pfd[0], buf, sizeof buf - 1);
		tap_ok(rc == SW_OK && n == 4 && !memcmp(buf, "own\n", 4),
		       "/dev/fd/N: written through the descriptor");
		close(pfd[0]);
	}
	rc = write_to(at("real"), NULL, OUTFILE_STREAM, "x\n", err);
	tap_ok(rc == SW_EIO && strstr(err, "Is a directory"),
	       "a directory is refused (%s)", err);
}

static void test_dirs(void)
{
	char err[SW_ERRLEN];
	const char *names[] = {"report.md", NULL};
	symlink(at("real"), at("dirlink"));
	tap_ok(outfile_check_dir(at("dirlink"), names, NULL, "t", err) == SW_OK,
	       "a symbolic link to a directory is a directory");
	tap_ok(outfile_check_dir(at("new/deeper"), names, NULL, "t", err) ==
	       SW_OK, "a directory that mkdir -p can make");
	put(at("afile"), "x");
	tap_ok(outfile_check_dir(at("afile/r"), names, NULL, "t", err) ==
	       SW_EIO && strstr(err, "Not a directory"),
	       "under a file: refused (%s)", err + strlen(dir) + 1);
	tap_ok(outfile_check_dir(at("afile"), names, NULL, "t", err) ==
	       SW_EIO && strstr(err, "Not a directory"),
	       "a file: refused");
	mkdir(at("real/report.md"), 0700);
	tap_ok(outfile_check_dir(at("real"), names, NULL, "t", err) == SW_EIO,
	       "a directory where a file of it goes: refused (%s)",
	       err + strlen(dir) + 1);
	const char *in[] = {at("in.yaml"), NULL};
	const char *innames[] = {"in.yaml", NULL};
	tap_ok(outfile_check_dir(dir, innames, in, "t", err) == SW_EINPUT,
	       "an input among the files of the directory: SW_EINPUT");
}

int main(void)
{
	if (!mkdtemp(dir)) {
		tap_ok(0, "mkdtemp: %s", strerror(errno));
		return tap_done();
	}
	test_inputs();
	test_whole();
	test_flush();
	test_streams();
	test_dirs();
	char cmd[600];
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
	if (system(cmd) != 0)
		tap_diag("could not remove %s", dir);
	return tap_done();
}
