/*
 * history.c - the workbench's run history and its index file
 * (history.h).
 *
 * The index is opened with O_NONBLOCK and used only when it is a
 * regular file: a FIFO there would block the first edit (an open for
 * writing waits for a reader), and /dev/zero (a link, say) would feed
 * the reader for ever.  The reader reads at most the last
 * HISTORY_MAX_BYTES of the file, so the H screen never waits on a
 * large file either.
 *
 * Where the runs directory is comes from the front end (the workbench
 * reads $SLIPWALL_RUNS, $XDG_DATA_HOME and $HOME: tui_file.c): the
 * library reads no environment: configuration is passed, not read.
 */
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "slipwall/history.h"
#include "slipwall/sys.h"

#define HISTORY_HEADER                                                      \
	"session\trun\twall\twhat\tmu_bed\tmu_head\tdepth\tanywhere\tload\t" \
	"x\ty\tdx\tdy\tsamples\taccepted\tp05\tp05_lo\tp05_hi\tp50\tp95\tfile\t" \
	"mu_cov\n"
/* columns of a row; the rows of an index written before mu_cov (the
 * last column, so that they are the first 21 of a row) have one less,
 * and are read with mu_cov 0 (friction not random) */
#define HISTORY_COLS 22
#define HISTORY_MAX_BYTES (4L << 20)	/* read at most the last 4 MiB */

/* Open path with flags (O_NONBLOCK added); -1 and err unless it is a
 * regular file (or missing, *missing set, when flags lack O_CREAT). */
static int history_open(const char *path, int flags, int *missing,
			char *err)
{
	struct stat st;
	if (missing)
		*missing = 0;
	/* stat first: opening a FIFO for writing with no reader fails
	 * (ENXIO) with a message that does not say why */
	if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
		sw_fail(err, SW_EIO, "%s: not a regular file (%s)", path,
			S_ISDIR(st.st_mode) ? "a directory" :
			S_ISFIFO(st.st_mode) ? "a FIFO" :
			S_ISCHR(st.st_mode) ? "a device" : "not a file");
		return -1;
	}
	int fd = open(path, flags | O_NONBLOCK | O_NOCTTY | O_CLOEXEC, 0666);
	if (fd < 0) {
		if (missing && errno == ENOENT) {
			*missing = 1;
			return -1;
		}
		sw_fail(err, SW_EIO, "%s: cannot open: %s", path,
			strerror(errno));
		return -1;
	}
	if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
		close(fd);
		sw_fail(err, SW_EIO, "%s: not a regular file", path);
		return -1;
	}
	return fd;
}

int history_runs_make(const char *dir, char *err)
{
	if (sys_mkdir_p(dir, NULL, 0)) {
		sw_fail(err, SW_EIO, "%s: cannot make the directory: %s", dir,
			strerror(errno));
		return -1;
	}
	return 0;
}

int history_index_path(const char *dir, char *out, size_t len)
{
	int n = snprintf(out, len, "%s/history.tsv", dir);
	return n < 0 || (size_t)n >= len ? -1 : 0;
}

/* Text without tabs and line breaks. */
static int history_text(char *buf, size_t len, const char *s)
{
	size_t k = 0;
	for (; *s && k + 1 < len; s++)
		buf[k++] = (*s == '\t' || *s == '\n' || *s == '\r') ? ' ' : *s;
	buf[k] = 0;
	return (int)k;
}

enum sw_status history_append(const char *path, const struct history_row *r,
			      char *err)
{
	char wall[sizeof r->wall], what[sizeof r->what], file[sizeof r->file];
	char line[2 * PATH_MAX];
	history_text(wall, sizeof wall, r->wall);
	history_text(what, sizeof what, r->what);
	history_text(file, sizeof file, r->file);
	int n = snprintf(line, sizeof line,
			 "%s\t%d\t%s\t%s\t%.17g\t%.17g\t%.17g\t%d\t%s\t"
			 "%.17g\t%.17g\t%.17g\t%.17g\t%ld\t%ld\t"
			 "%.17g\t%.17g\t%.17g\t%.17g\t%.17g\t%s\t%.17g\n",
			 r->session, r->run, wall, what, r->mu_bed, r->mu_head,
			 r->depth, r->anywhere,
			 r->load == 0 ? "point" : r->load == 1 ? "body" : "none",
			 r->at[0], r->at[1], r->dir[0], r->dir[1], r->samples,
			 r->accepted, r->p05, r->p05_lo, r->p05_hi, r->p50,
			 r->p95, file, r->mu_cov);
	if (n < 0 || (size_t)n >= sizeof line)
		return sw_fail(err, SW_EIO, "%s: history line too long", path);
	int fd = history_open(path, O_WRONLY | O_APPEND | O_CREAT, NULL, err);
	if (fd < 0)
		return SW_EIO;
	struct stat st;
	int bad = fstat(fd, &st) != 0;
	if (!bad && st.st_size == 0) {
		size_t h = strlen(HISTORY_HEADER);
		bad = write(fd, HISTORY_HEADER, h) != (ssize_t)h;
	}
	if (!bad)
		bad = write(fd, line, (size_t)n) != (ssize_t)n;
	int e = errno;
	if (close(fd) != 0 && !bad) {
		bad = 1;
		e = errno;
	}
	if (bad)
		return sw_fail(err, SW_EIO, "%s: cannot write: %s", path,
			       strerror(e));
	return SW_OK;
}

/* Split line (modified) at tabs into at most max fields. */
static int history_split(char *line, char **f, int max)
{
	int n = 0;
	char *s = line;
	while (n < max) {
		f[n++] = s;
		char *tab = strchr(s, '\t');
		if (!tab)
			break;
		*tab = 0;
		s = tab + 1;
	}
	char *nl = strchr(f[n - 1], '\n');
	if (nl)
		*nl = 0;
	return n;
}

static int history_num(const char *s, double *v)
{
	char *end;
	*v = strtod(s, &end);
	return end == s || *end ? -1 : 0;
}

static int history_long(const char *s, long *v)
{
	char *end;
	errno = 0;
	*v = strtol(s, &end, 10);
	return end == s || *end || errno ? -1 : 0;
}

/* One line into r; -1 when it is not a row. */
static int history_parse(char *line, struct history_row *r)
{
	char *f[HISTORY_COLS + 1];
	long run, any, samples, accepted;
	int cols = history_split(line, f, HISTORY_COLS + 1);
	if (cols != HISTORY_COLS && cols != HISTORY_COLS - 1)
		return -1;
	memset(r, 0, sizeof *r);
	if (cols == HISTORY_COLS &&
	    (history_num(f[21], &r->mu_cov) || !(r->mu_cov >= 0)))
		return -1;
	if (strlen(f[0]) >= sizeof r->session || history_long(f[1], &run) ||
	    history_long(f[7], &any) || history_long(f[13], &samples) ||
	    history_long(f[14], &accepted))
		return -1;
	double *num[] = {&r->mu_bed, &r->mu_head, &r->depth};
	for (int i = 0; i < 3; i++)
		if (history_num(f[4 + i], num[i]))
			return -1;
	double *pos[] = {&r->at[0], &r->at[1], &r->dir[0], &r->dir[1]};
	for (int i = 0; i < 4; i++)
		if (history_num(f[9 + i], pos[i]))
			return -1;
	double *q[] = {&r->p05, &r->p05_lo, &r->p05_hi, &r->p50, &r->p95};
	for (int i = 0; i < 5; i++)
		if (history_num(f[15 + i], q[i]))
			return -1;
	snprintf(r->session, sizeof r->session, "%s", f[0]);
	r->run = (int)run;
	snprintf(r->wall, sizeof r->wall, "%s", f[2]);
	snprintf(r->what, sizeof r->what, "%s", f[3]);
	r->anywhere = any != 0;
	r->load = !strcmp(f[8], "point") ? 0 : !strcmp(f[8], "body") ? 1 : -1;
	r->samples = samples;
	r->accepted = accepted;
	snprintf(r->file, sizeof r->file, "%s", f[20]);
	return 0;
}

enum sw_status history_read(const char *path, int max,
			    struct history_row **rows, int *n, char *err)
{
	*rows = NULL;
	*n = 0;
	int missing;
	int fd = history_open(path, O_RDONLY, &missing, err);
	if (fd < 0)
		return missing ? SW_OK : SW_EIO;
	/* the last HISTORY_MAX_BYTES only; the first line there may be
	 * cut, and is dropped */
	struct stat st;
	int cut = fstat(fd, &st) == 0 && st.st_size > HISTORY_MAX_BYTES &&
		  lseek(fd, st.st_size - HISTORY_MAX_BYTES, SEEK_SET) >= 0;
	FILE *fp = fdopen(fd, "r");
	if (!fp) {
		close(fd);
		return sw_fail(err, SW_EIO, "%s: cannot open: %s", path,
			       strerror(errno));
	}
	long left = HISTORY_MAX_BYTES;
	/* a ring of the last max rows */
	int cap = max > 0 ? max : 64, cnt = 0, head = 0;
	struct history_row *ring = sw_xmalloc(sizeof *ring * (size_t)cap);
	char line[4 * PATH_MAX];
	struct history_row r;
	while (left > 0 && fgets(line, sizeof line, fp)) {
		left -= (long)strlen(line);
		if (cut) {	/* the rest of a line before the window */
			cut = strchr(line, '\n') == NULL;
			continue;
		}
		if (!strchr(line, '\n') && !feof(fp)) {
			/* too long to be a row: skip the rest of it */
			int c;
			while (left > 0 && (c = fgetc(fp)) != EOF && c != '\n')
				left--;
			continue;
		}
		if (history_parse(line, &r))
			continue;
		if (cnt < cap) {
			if (max <= 0 && cnt == cap - 1) {
				cap *= 2;
				struct history_row *nr = realloc(ring, sizeof *ring * (size_t)cap);
				if (!nr) {
					free(ring);
					fclose(fp);
					return sw_fail(err, SW_EIO, "out of memory");
				}
				ring = nr;
			}
			ring[cnt++] = r;
		} else {
			ring[head] = r;
			head = (head + 1) % cap;
		}
	}
	int bad = ferror(fp);
	fclose(fp);
	if (bad) {
		free(ring);
		return sw_fail(err, SW_EIO, "%s: cannot read", path);
	}
	/* oldest first */
	struct history_row *out = sw_xmalloc(sizeof *out * (size_t)(cnt + 1));
	for (int i = 0; i < cnt; i++)
		out[i] = ring[(head + i) % cnt];
	free(ring);
	*rows = out;
	*n = cnt;
	return SW_OK;
}
