/*
 * runlog.c - the samples file: writing rows as they come, reading them
 * back; see runlog.h.
 *
 * Writing: the `run` command (and the workbench) calls runlog_write()
 * for every sample popped from the pool, in index order.  The row is
 * formatted into a buffer owned by the log and handed to the kernel with
 * one write(2): no stdio buffer holds half a row, so a process killed at
 * any instant leaves a file of complete rows (a write to a regular file
 * is only ever short when the disk is full, which is reported).  Numbers
 * are printed with 17 significant digits, so positions read back are
 * bit-identical and a replay (--positions) recomputes the same samples.
 *
 * Reading: a small strict CSV reader (no quoting: the file never needs
 * it).  Every field is checked and a problem is reported at its
 * FILE:LINE:COLUMN.
 */
#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "slipwall/outfile.h"
#include "slipwall/runlog.h"
#include "slipwall/text.h"

struct runlog {
	char *path;
	int fd;
	int nifaces;
	int mu;			/* rows have the draw's friction (mu_k) */
	int failed;		/* a write failed: close reports it */
	char *buf;		/* the row being formatted */
	size_t len, cap;
	off_t good;		/* file size after the last whole row */
};

/* ---- writing ----------------------------------------------------------- */

static void put(struct runlog *l, const char *s, size_t n)
{
	if (l->len + n + 1 > l->cap) {
		while (l->len + n + 1 > l->cap)
			l->cap = l->cap ? 2 * l->cap : 4096;
		l->buf = sw_xrealloc(l->buf, l->cap);
	}
	memcpy(l->buf + l->len, s, n);
	l->len += n;
}

static void put_str(struct runlog *l, const char *s)
{
	put(l, s, strlen(s));
}

/* A number with 17 significant digits (exact round trip); empty when
 * not finite (not computed). */
static void put_num(struct runlog *l, double v)
{
	char tmp[40];
	if (!isfinite(v))
		return;
	int n = snprintf(tmp, sizeof tmp, "%.17g", v);
	put(l, tmp, (size_t)n);
}

/* Hand the buffer to the kernel: one write(2) unless the kernel takes
 * less (a full disk), then the rest and an error. */
static enum sw_status flush_row(struct runlog *l, char *err)
{
	size_t off = 0;
	while (off < l->len) {
		ssize_t n = write(l->fd, l->buf + off, l->len - off);
		if (n < 0 && errno == EINTR)
			continue;
		if (n <= 0) {
			/* a full disk can take part of a row: cut the file
			 * back to the last whole row */
			if (off > 0 && ftruncate(l->fd, l->good) == 0)
				lseek(l->fd, l->good, SEEK_SET);
			l->failed = 1;
			l->len = 0;
			return sw_fail(err, SW_EIO, "%s: cannot write: %s",
				       l->path, n < 0 ? strerror(errno) :
				       "nothing written");
		}
		off += (size_t)n;
	}
	l->good += (off_t)l->len;
	l->len = 0;
	return SW_OK;
}

static void runlog_free(struct runlog *l)
{
	free(l->buf);
	free(l->path);
	free(l);
}

enum sw_status runlog_create(struct runlog **out, const char *path,
			     const struct wall *w, const char *const *keep,
			     char *err)
{
	*out = NULL;
	/* not O_TRUNC: an old file is replaced only once it is known to be
	 * none of the inputs and not another run's, and once the new
	 * header is written (below); a FIFO that no process reads is
	 * said, then waited for (outfile.h) */
	struct stat st;
	enum sw_status ost;
	int fd = outfile_open_fd(path, 0, keep, "the samples", &st, &ost,
				 err);
	if (fd < 0)
		return ost;
	int old = -1;		/* the old file, locked until replaced */
	char *dest = NULL, *tmp = NULL;
	if (S_ISREG(st.st_mode)) {
		/* locked, and still the file at path: a run that replaced
		 * it between our open and our lock is writing it */
		struct stat now;
		int e = flock(fd, LOCK_EX | LOCK_NB) != 0 ? errno :
			stat(path, &now) != 0 ? errno :
			now.st_dev != st.st_dev || now.st_ino != st.st_ino ?
			EWOULDBLOCK : 0;
		if (e) {
			close(fd);
			if (e == EWOULDBLOCK)
				return sw_fail(err, SW_EINPUT, "%s: another "
					       "process is writing this samples "
					       "file (it is locked)", path);
			return sw_fail(err, SW_EIO, "%s: cannot lock: %s",
				       path, strerror(e));
		}
		if (st.st_size > 0) {
			/* the old samples stay whole until the new header is
			 * written: it goes to DEST.tmp, renamed over the old
			 * file after (a full disk leaves the old file) */
			old = fd;
			fd = outfile_open_beside(path, &st, &dest, &tmp, err);
			if (fd < 0) {
				close(old);
				return SW_EIO;
			}
			flock(fd, LOCK_EX | LOCK_NB);	/* a new file */
		}
	}
	struct runlog *l = sw_xcalloc(1, sizeof *l);
	l->path = sw_xstrdup(path);
	l->fd = fd;
	l->nifaces = w->nifaces;
	put_str(l, "sample,status,lambda_max,lambda_min,iterations");
	for (int k = 1; k <= w->nifaces; k++) {
		char tmp[48];
		int n = snprintf(tmp, sizeof tmp, ",xa_%d,xb_%d", k, k);
		put(l, tmp, (size_t)n);
	}
	/* random friction: each sample's draw has it (draw.h) */
	l->mu = w->mu_cov > 0;
	for (int k = 1; l->mu && k <= w->nifaces; k++) {
		char tmp[48];
		int n = snprintf(tmp, sizeof tmp, ",mu_%d", k);
		put(l, tmp, (size_t)n);
	}
	put(l, "\n", 1);
	enum sw_status rc = flush_row(l, err);
	/* the header on the disk before it replaces the old samples: a
	 * crash of the machine just after the rename then leaves the new
	 * header, not an empty file where the old rows were */
	if (rc == SW_OK && tmp && fsync(fd) != 0)
		rc = sw_fail(err, SW_EIO, "%s: cannot write: %s", path,
			     strerror(errno));
	if (rc == SW_OK && tmp && rename(tmp, dest) != 0)
		rc = sw_fail(err, SW_EIO, "%s: cannot replace: %s", path,
			     strerror(errno));
	if (rc != SW_OK) {
		if (tmp)
			unlink(tmp);
		close(fd);
		runlog_free(l);
	} else {
		*out = l;
	}
	if (old >= 0)
		close(old);
	free(dest);
	free(tmp);
	return rc;
}

enum sw_status runlog_write(struct runlog *l, const struct record *it,
			    char *err)
{
	char tmp[64];
	int n = snprintf(tmp, sizeof tmp, "%ld,%s,", it->index,
			 sample_status_name(it->status));
	put(l, tmp, (size_t)n);
	put_num(l, it->lambda_max);
	put(l, ",", 1);
	/* the result exists only for accepted samples */
	if (it->status == SAMPLE_ACCEPTED)
		put_num(l, it->lambda_min);
	n = snprintf(tmp, sizeof tmp, ",%d", it->iterations);
	put(l, tmp, (size_t)n);
	for (int k = 0; k < 2 * l->nifaces; k++) {
		put(l, ",", 1);
		put_num(l, it->draw.xi[k]);
	}
	for (int k = 0; l->mu && k < l->nifaces; k++) {
		put(l, ",", 1);
		put_num(l, it->draw.mu[k]);
	}
	put(l, "\n", 1);
	return flush_row(l, err);
}

enum sw_status runlog_close(struct runlog *l, char *err)
{
	if (!l)
		return SW_OK;
	enum sw_status st = SW_OK;
	if (l->failed)
		st = sw_fail(err, SW_EIO, "%s: some rows could not be written",
			     l->path);
	if (close(l->fd) != 0 && st == SW_OK)
		st = sw_fail(err, SW_EIO, "%s: %s", l->path, strerror(errno));
	runlog_free(l);
	return st;
}

const char *runlog_path(const struct runlog *l)
{
	return l->path;
}

/* ---- reading ----------------------------------------------------------- */

#define FIXED_COLS 5	/* sample,status,lambda_max,lambda_min,iterations */

static const char *fixed_names[FIXED_COLS] = {
	"sample", "status", "lambda_max", "lambda_min", "iterations",
};

/* Bounds on what a reader takes (docs/reliability.md): the header of
 * the largest wall the loader accepts is a few MB; a row has five
 * fields and two numbers per interface, each at most 24 characters
 * ("-2.2250738585072014e-308"); the sample count is that of `run -n`;
 * the positions held in memory are bounded too. */
#define HEADER_MAX ((size_t)16 << 20)
#define ROW_FIELD_MAX 32
#define ROWS_MAX 1000000000L
#define POSITIONS_MAX ((size_t)8 << 30)	/* bytes of positions held */

/* A data row's `sample` number and the line it is on (check_ids): both
 * below ROWS_MAX + 2, so 8 bytes a row, as much as an accepted load. */
struct row_id {
	int sample, line;
};

/* A CSV file being read: the current line split in place into fields,
 * each with its 1-based column for messages. */
struct reader {
	const char *path;
	FILE *f;
	char *line;
	size_t cap, len;	/* len: of the line before splitting */
	size_t max;		/* longest line accepted */
	long lineno;
	int cut;		/* the last line had no end: dropped */
	char **field;
	int *col;
	int nfield, capfield;
	int nmu;		/* the header's mu_k columns: 0 or its m */
	struct row_id *ids;	/* each data row's sample number, its line */
	long nids, capids;
};

static int reader_open(struct reader *r, const char *path, char *err)
{
	memset(r, 0, sizeof *r);
	r->path = path;
	r->max = HEADER_MAX;
	r->f = fopen(path, "r");
	if (!r->f) {
		sw_fail(err, SW_EINPUT, "%s: cannot open: %s", path,
			strerror(errno));
		return -1;
	}
	return 0;
}

static void reader_close(struct reader *r)
{
	if (r->f)
		fclose(r->f);
	free(r->line);
	free(r->field);
	free(r->col);
	free(r->ids);
}

/* The next line, split at commas.  Returns 1, 0 at the end of the file,
 * -1 (err filled) on a read error, a NUL byte or a line longer than
 * r->max.  A last line without its '\n' is a row that a kill cut while
 * it was written (runlog_write writes whole rows): it is dropped and
 * r->cut raised, for a warning. */
static int reader_next(struct reader *r, char *err)
{
	size_t n;
	enum text_line got = text_getline(r->f, &r->line, &r->cap, r->max, &n);
	switch (got) {
	case TEXT_LINE_EOF:
		return 0;
	case TEXT_LINE_CUT:
		r->cut = 1;
		return 0;
	case TEXT_LINE_ERROR:
		sw_fail(err, SW_EINPUT, "%s:%ld: cannot read: %s", r->path,
			r->lineno + 1, strerror(errno));
		return -1;
	case TEXT_LINE_NUL:
		sw_fail(err, SW_EINPUT, "%s:%ld:%zu: a NUL byte in a text file",
			r->path, r->lineno + 1, n + 1);
		return -1;
	case TEXT_LINE_LONG:
		sw_fail(err, SW_EINPUT, "%s:%ld:1: a line longer than %zu "
			"bytes: not a samples file%s", r->path, r->lineno + 1,
			r->max, r->lineno ? " of this header" : "");
		return -1;
	case TEXT_LINE_OK:
		break;
	}
	r->lineno++;
	while (n > 0 && r->line[n - 1] == '\r')
		r->line[--n] = 0;
	r->len = n;
	r->nfield = 0;
	char *p = r->line;
	for (;;) {
		if (r->nfield == r->capfield) {
			r->capfield = r->capfield ? 2 * r->capfield : 64;
			r->field = sw_xrealloc(r->field, sizeof *r->field *
					       (size_t)r->capfield);
			r->col = sw_xrealloc(r->col, sizeof *r->col *
					     (size_t)r->capfield);
		}
		r->field[r->nfield] = p;
		r->col[r->nfield] = (int)(p - r->line) + 1;
		r->nfield++;
		char *c = strchr(p, ',');
		if (!c)
			break;
		*c = 0;
		p = c + 1;
	}
	return 1;
}

/* The warning of a reader that dropped a cut last row; "" if none. */
static void reader_warning(const struct reader *r, char *warn)
{
	if (!warn)
		return;
	warn[0] = 0;
	if (r->cut)
		snprintf(warn, SW_ERRLEN, "%s:%ld: warning: the last row is "
			 "incomplete (no end of line: a run killed while "
			 "writing it?); it is ignored", r->path, r->lineno + 1);
}

static enum sw_status at(const struct reader *r, int field, char *err,
			 const char *what)
{
	return sw_fail(err, SW_EINPUT, "%s:%ld:%d: %s", r->path, r->lineno,
		       field < r->nfield ? r->col[field] :
		       (int)r->len + 1, what);
}

/* Check the header: the five fixed columns, then xa_k,xb_k pairs, then
 * (random friction) mu_k for every k.  *m gets the number of interfaces,
 * r->nmu the mu columns'. */
static enum sw_status read_header(struct reader *r, int *m, char *err)
{
	int got = reader_next(r, err);
	if (got < 0)
		return SW_EINPUT;
	if (got == 0)
		return sw_fail(err, SW_EINPUT, "%s:1:1: %s: not a samples "
			       "file", r->path, r->cut ? "an incomplete header "
			       "(no end of line)" : "empty file");
	/* a byte-order mark, as a spreadsheet saves UTF-8 */
	size_t bom = text_bom(r->field[0], strlen(r->field[0]));
	r->field[0] += bom;
	r->col[0] += (int)bom;
	for (int k = 0; k < FIXED_COLS; k++) {
		if (k >= r->nfield || strcmp(r->field[k], fixed_names[k])) {
			char msg[128];
			snprintf(msg, sizeof msg, "expected column '%s': not a "
				 "samples file of 'slipwall run'",
				 fixed_names[k]);
			return at(r, k, err, msg);
		}
	}
	int extra = r->nfield - FIXED_COLS;
	int npos = extra;	/* the xa_k,xb_k columns: up to the first mu_ */
	for (int k = 0; k < extra; k++)
		if (!strncmp(r->field[FIXED_COLS + k], "mu_", 3)) {
			npos = k;
			break;
		}
	if (npos != extra && 2 * (extra - npos) != npos)
		return at(r, FIXED_COLS + npos, err, "the frictions mu_k "
			  "come one per interface, after its positions");
	r->nmu = extra - npos;
	for (int k = 0; k < r->nmu; k++) {
		char want[48];
		snprintf(want, sizeof want, "mu_%d", k + 1);
		if (strcmp(r->field[FIXED_COLS + npos + k], want)) {
			char msg[96];
			snprintf(msg, sizeof msg, "expected column '%s'", want);
			return at(r, FIXED_COLS + npos + k, err, msg);
		}
	}
	extra = npos;
	if (extra % 2)
		return at(r, r->nfield - 1, err,
			  "the contact positions come in xa_k,xb_k pairs");
	for (int k = 0; k < extra; k++) {
		char want[48];
		snprintf(want, sizeof want, "%s_%d", k % 2 ? "xb" : "xa",
			 k / 2 + 1);
		if (strcmp(r->field[FIXED_COLS + k], want)) {
			char msg[96];
			snprintf(msg, sizeof msg, "expected column '%s'", want);
			return at(r, FIXED_COLS + k, err, msg);
		}
	}
	*m = extra / 2;
	r->max = 64 + ROW_FIELD_MAX * ((size_t)FIXED_COLS + (size_t)extra +
				       (size_t)r->nmu);
	return SW_OK;
}

static int parse_num(const char *s, double *v)
{
	char *end;
	if (!*s)
		return -1;
	/* ERANGE on underflow is fine (a subnormal is still a number); an
	 * overflow gives an infinity */
	*v = strtod(s, &end);
	if (*end || !isfinite(*v))
		return -1;
	return 0;
}

/* Check the fixed fields of a data row; *status gets its status. */
static enum sw_status check_row(struct reader *r, int m, int *status,
				char *err)
{
	int want = FIXED_COLS + 2 * m + r->nmu;
	if (r->nfield != want) {
		char msg[128];
		snprintf(msg, sizeof msg, "%d fields, the header has %d%s",
			 r->nfield, want,
			 r->nfield < want ? " (an incomplete row?)" : "");
		return at(r, r->nfield < want ? r->nfield : want, err, msg);
	}
	/* the sample's number: a whole number below ROWS_MAX (check_ids
	 * finds the ones that repeat) */
	char *end;
	errno = 0;
	long id = strtol(r->field[0], &end, 10);
	if (!isdigit((unsigned char)r->field[0][0]) || *end || errno ||
	    id >= ROWS_MAX)
		return at(r, 0, err, "the sample's number must be a whole "
			  "number from 0");
	if (r->nids == r->capids) {
		r->capids = r->capids ? 2 * r->capids : 256;
		r->ids = sw_xrealloc(r->ids, sizeof *r->ids *
				     (size_t)r->capids);
	}
	r->ids[r->nids++] = (struct row_id){(int)id, (int)r->lineno};
	*status = sample_status_parse(r->field[1]);
	if (*status < 0)
		return at(r, 1, err, "unknown status (accepted or a "
			  "rejection reason such as no_mechanism)");
	return SW_OK;
}

static int by_sample(const void *a, const void *b)
{
	const struct row_id *x = a, *y = b;
	if (x->sample != y->sample)
		return x->sample < y->sample ? -1 : 1;
	return (x->line > y->line) - (x->line < y->line);
}

/* Every sample once: a number that repeats is two runs' files joined
 * (or a row copied), whose loads would count twice.  The message names
 * the repeat's line and the first. */
static enum sw_status check_ids(struct reader *r, char *err)
{
	if (r->nids > 1)
		qsort(r->ids, (size_t)r->nids, sizeof *r->ids, by_sample);
	long worst = -1;	/* the earliest line that repeats a number */
	for (long i = 1; i < r->nids; i++)
		if (r->ids[i].sample == r->ids[i - 1].sample &&
		    (worst < 0 || r->ids[i].line < r->ids[worst].line))
			worst = i;
	if (worst < 0)
		return SW_OK;
	long i = worst;
	while (i > 0 && r->ids[i - 1].sample == r->ids[worst].sample)
		i--;
	return sw_fail(err, SW_EINPUT, "%s:%d:1: sample %d again (first on "
		       "line %d): every sample once (two runs' files joined?)",
		       r->path, r->ids[worst].line, r->ids[worst].sample,
		       r->ids[i].line);
}

/* The header's interfaces are the wall's: a file of another wall is
 * refused, not read as this one's. */
static enum sw_status check_wall(const struct reader *r, int m,
				 const struct wall *w, char *err)
{
	if (m == w->nifaces)
		return SW_OK;
	char msg[200];
	snprintf(msg, sizeof msg, "the file has the contact positions of %d "
		 "interfaces, the wall has %d: a samples file of another wall?",
		 m, w->nifaces);
	return at(r, FIXED_COLS, err, msg);
}

/* The bound on rows: that of `run -n`, and for positions the memory
 * they take. */
static enum sw_status too_many(const struct reader *r, long n, size_t per,
			       char *err)
{
	if (n >= ROWS_MAX)
		return sw_fail(err, SW_EINPUT, "%s:%ld:1: more than %ld "
			       "samples: too large for a samples file", r->path,
			       r->lineno, ROWS_MAX);
	if (per && ((size_t)n + 1) * per * sizeof(double) > POSITIONS_MAX)
		return sw_fail(err, SW_EINPUT, "%s:%ld:1: the contact "
			       "positions of more than %ld samples would take "
			       "more than %zu GiB of memory", r->path, r->lineno,
			       n, POSITIONS_MAX >> 30);
	return SW_OK;
}

/* A samples file of w opened, its header read and checked against w:
 * SW_OK and its m interfaces, or the message.  reader_close() it
 * whatever this returns. */
static enum sw_status reader_start(struct reader *r, const char *path,
				   const struct wall *w, int *m, char *err)
{
	if (reader_open(r, path, err))
		return SW_EINPUT;
	enum sw_status st = read_header(r, m, err);
	return st == SW_OK ? check_wall(r, *m, w, err) : st;
}

enum sw_status runlog_read_draws(const char *path, const struct wall *w,
				 struct draw_table *t, char *warn, char *err)
{
	struct reader r;
	int m;
	enum sw_status st = reader_start(&r, path, w, &m, err);
	double *x = NULL, *mu = NULL;
	long n = 0, cap = 0;
	size_t per = 2 * (size_t)m + (size_t)r.nmu;
	if (st == SW_OK && w->mu_cov > 0 && !r.nmu)
		st = sw_fail(err, SW_EINPUT, "%s:1:1: the wall's friction is "
			     "random (cov %g) but the file has no friction "
			     "columns (mu_k) to replay", path, w->mu_cov);
	while (st == SW_OK) {
		int got = reader_next(&r, err);
		if (got <= 0) {
			if (got < 0)
				st = SW_EINPUT;
			break;
		}
		int status;
		if ((st = check_row(&r, m, &status, err)) != SW_OK ||
		    (st = too_many(&r, n, per, err)) != SW_OK)
			break;
		if (n == cap) {
			cap = cap ? 2 * cap : 256;
			x = sw_xrealloc(x, sizeof(double) * 2 * (size_t)m *
					       (size_t)cap + 1);
			if (r.nmu)
				mu = sw_xrealloc(mu, sizeof(double) * (size_t)m *
						 (size_t)cap + 1);
		}
		double *row = x + 2 * (size_t)m * (size_t)n;
		for (int k = 0; k < 2 * m && st == SW_OK; k++) {
			double v = 0;
			if (parse_num(r.field[FIXED_COLS + k], &v))
				st = at(&r, FIXED_COLS + k, err,
					"a contact position must be a number");
			else if (v < 0 || v > 1)
				st = at(&r, FIXED_COLS + k, err,
					"a contact position must be between "
					"0 and 1");
			else if (k % 2 && v < row[k - 1])
				st = at(&r, FIXED_COLS + k, err,
					"xb must not be less than xa");
			row[k] = v;
		}
		for (int k = 0; k < r.nmu && st == SW_OK; k++) {
			double v = 0;
			int c = FIXED_COLS + 2 * m + k;
			if (parse_num(r.field[c], &v) || v < 0 ||
			    v > WALL_FRICTION_MAX)
				st = at(&r, c, err, "a friction must be a "
					"number from 0 to 1000");
			mu[(size_t)m * (size_t)n + (size_t)k] = v;
		}
		n++;
	}
	if (st == SW_OK && n == 0)
		st = sw_fail(err, SW_EINPUT, "%s:%ld:1: no samples in the file",
			     path, r.lineno + 1);
	if (st == SW_OK)
		st = check_ids(&r, err);
	reader_warning(&r, warn);
	reader_close(&r);
	if (st != SW_OK) {
		free(x);
		free(mu);
		return st;
	}
	t->xi = x;
	t->mu = mu;
	t->rows = n;
	return SW_OK;
}

enum sw_status runlog_read_loads(const char *path, const struct wall *w,
				 double **lam, long *n, char *warn, char *err)
{
	struct reader r;
	int m;
	enum sw_status st = reader_start(&r, path, w, &m, err);
	double *x = NULL;
	long k = 0, cap = 0;
	struct wall_quantity q;
	wall_quantity(w, &q);
	while (st == SW_OK) {
		int got = reader_next(&r, err);
		if (got <= 0) {
			if (got < 0)
				st = SW_EINPUT;
			break;
		}
		int status = -1;	/* check_row sets it */
		if ((st = check_row(&r, m, &status, err)) != SW_OK ||
		    (st = too_many(&r, r.lineno, 0, err)) != SW_OK)
			break;
		if (status != SAMPLE_ACCEPTED)
			continue;
		double v, vmax;
		if (parse_num(r.field[3], &v) || v < 0) {
			st = at(&r, 3, err, "an accepted sample needs a "
				"lambda_min: a finite number >= 0");
			break;
		}
		if (parse_num(r.field[2], &vmax)) {
			st = at(&r, 2, err, "an accepted sample needs a "
				"lambda_max: a finite number");
			break;
		}
		/* slipwall writes lambda_min <= lambda_max (docs/method.md,
		 * step 5); files of versions before that rule have it above
		 * by round-off, up to 8.5e-10 of the load, so 1e-6 of it
		 * separates those from a file with its columns swapped or
		 * edited by hand */
		if (v > vmax + 1e-6 * fabs(vmax)) {
			st = at(&r, 3, err, "lambda_min is above lambda_max "
				"(the onset load of a mechanism is at most the "
				"SLP's load): not a file that slipwall wrote");
			break;
		}
		if (k == cap) {
			cap = cap ? 2 * cap : 256;
			x = sw_xrealloc(x, sizeof(double) * (size_t)cap);
		}
		x[k++] = q.scale * v;
	}
	if (st == SW_OK)
		st = check_ids(&r, err);
	reader_warning(&r, warn);
	reader_close(&r);
	if (st != SW_OK) {
		free(x);
		return st;
	}
	*lam = x;
	*n = k;
	return SW_OK;
}
