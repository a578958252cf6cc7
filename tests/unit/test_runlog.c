/*
 * test_runlog.c - the samples file: the exact text of the header and of
 * a row, a round trip of awkward positions bit for bit (17 significant
 * digits), the accepted loads read back, and every kind of bad file
 * refused at its FILE:LINE:COLUMN.
 */
#include <float.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "slipwall/runlog.h"
#include "tap.h"

#define M 2		/* interfaces of the fake wall */

static struct wall fake;	/* the runlog reads nifaces (and nblocks) */
static char dir[] = "/tmp/test_runlog.XXXXXX";

static char *path_of(const char *name)
{
	static char buf[4][256];
	static int k;
	k = (k + 1) % 4;
	snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
	return buf[k];
}

static char *slurp(const char *path)
{
	FILE *f = fopen(path, "r");
	if (!f)
		return NULL;
	static char buf[1 << 16];
	size_t n = fread(buf, 1, sizeof buf - 1, f);
	buf[n] = 0;
	fclose(f);
	return buf;
}

static void spit(const char *path, const char *text)
{
	FILE *f = fopen(path, "w");
	fputs(text, f);
	fclose(f);
}

static void test_format(void)
{
	char err[SW_ERRLEN];
	const char *p = path_of("fmt.csv");
	struct runlog *l = NULL;
	runlog_create(&l, p, &fake, NULL, err);
	tap_ok(l != NULL, "runlog_create creates the file");
	if (!l)
		return;
	tap_ok(!strcmp(runlog_path(l), p), "runlog_path");
	struct record it;
	record_init(&it, &fake);
	it.index = 0;
	it.status = SAMPLE_ACCEPTED;
	it.lambda_max = 1.5;
	it.lambda_min = 0.1;
	it.iterations = 12;
	it.draw.xi[0] = 0.25;
	it.draw.xi[1] = 0.75;
	it.draw.xi[2] = 0;
	it.draw.xi[3] = 1;
	runlog_write(l, &it, err);
	it.index = 1;
	it.status = SAMPLE_NO_MECHANISM;
	it.lambda_max = 2;
	it.lambda_min = 1;	/* not the result of a rejected sample */
	it.iterations = 200;
	runlog_write(l, &it, err);
	it.index = 2;
	it.status = SAMPLE_UNBOUNDED;
	it.lambda_max = NAN;
	it.lambda_min = NAN;
	it.iterations = 0;
	runlog_write(l, &it, err);
	tap_ok(runlog_close(l, err) == SW_OK, "runlog_close");
	const char *want =
		"sample,status,lambda_max,lambda_min,iterations,xa_1,xb_1,xa_2,xb_2\n"
		"0,accepted,1.5,0.10000000000000001,12,0.25,0.75,0,1\n"
		"1,no_mechanism,2,,200,0.25,0.75,0,1\n"
		"2,unbounded,,,0,0.25,0.75,0,1\n";
	const char *got = slurp(p);
	tap_ok(got && !strcmp(got, want), "header and rows as docs/run.md "
	       "(\"The samples file\") says (17 digits; empty when not computed or rejected)");
	if (got && strcmp(got, want))
		printf("# got:\n%s", got);
	record_free(&it);
}


/* runlog_read_draws' positions (the tests below check them; the
 * frictions have test_friction_columns) */
static enum sw_status read_positions(const char *p, const struct wall *w,
				     double **x, long *n, char *warn,
				     char *err)
{
	struct draw_table t = {0};
	enum sw_status st = runlog_read_draws(p, w, &t, warn, err);
	if (st == SW_OK) {
		*x = t.xi;
		*n = t.rows;
		free(t.mu);
	}
	return st;
}

static void test_round_trip(void)
{
	char err[SW_ERRLEN];
	const char *p = path_of("rt.csv");
	struct runlog *l = NULL;
	runlog_create(&l, p, &fake, NULL, err);
	struct record it;
	record_init(&it, &fake);
	/* values whose shortest decimal needs all 17 digits, the smallest
	 * subnormal, the double just below 1, thirds and tenths */
	double awkward[] = {
		0.1, 1.0 / 3, 2.0 / 3, 0x1.fffffffffffffp-1, 4.9406564584124654e-324,
		DBL_MIN, 0.30000000000000004, 1e-17, 0.5, 0.123456789012345678,
		0.99999999999999989, 0.7,
	};
	int na = (int)(sizeof awkward / sizeof *awkward);
	long rows = 50;
	double *want = malloc(sizeof(double) * 2 * M * (size_t)rows);
	srand(7);
	for (long i = 0; i < rows; i++) {
		it.index = i;
		it.status = i % 5 ? SAMPLE_ACCEPTED : SAMPLE_NOT_CONVERGED;
		it.lambda_max = 1000.0 / (double)(i + 3);
		it.lambda_min = 100.0 / (double)(i + 7);
		for (int k = 0; k < 2 * M; k += 2) {
			double a = awkward[(i + k) % na];
			double b = (double)rand() / RAND_MAX;
			it.draw.xi[k] = a < b ? a : b;
			it.draw.xi[k + 1] = a < b ? b : a;
		}
		memcpy(want + 2 * M * i, it.draw.xi, sizeof(double) * 2 * M);
		runlog_write(l, &it, err);
	}
	runlog_close(l, err);

	double *xi = NULL;
	long n = 0;
	enum sw_status st = read_positions(p, &fake, &xi, &n, NULL, err);
	tap_ok(st == SW_OK && n == rows, "positions read back: 50 rows");
	tap_ok(st == SW_OK && !memcmp(xi, want, sizeof(double) * 2 * M *
				      (size_t)rows),
	       "every position identical bit for bit");
	free(xi);
	free(want);

	double *lam = NULL;
	st = runlog_read_loads(p, &fake, &lam, &n, NULL, err);
	int ok = st == SW_OK && n == 40;
	for (long i = 0, k = 0; ok && i < rows; i++)
		if (i % 5)
			ok = lam[k++] == 100.0 / (double)(i + 7);
	tap_ok(ok, "accepted loads read back exactly, rejected skipped (40)");
	free(lam);
	record_free(&it);
}

/* A bad file must be refused with this "LINE:COL: substring". */
static void refused(const char *name, const char *text, int loads,
		    const char *where, const char *sub)
{
	char err[SW_ERRLEN] = "";
	const char *p = path_of(name);
	spit(p, text);
	double *x = NULL;
	long n = -1;
	enum sw_status st = loads ? runlog_read_loads(p, &fake, &x, &n, NULL, err) :
			    read_positions(p, &fake, &x, &n, NULL, err);
	char prefix[300];
	snprintf(prefix, sizeof prefix, "%s:%s: ", p, where);
	int ok = st == SW_EINPUT && !strncmp(err, prefix, strlen(prefix)) &&
		 strstr(err, sub) && x == NULL && n == -1;
	tap_ok(ok, "%s refused at %s (%s)", name, where, sub);
	if (!ok)
		printf("#   status %d, message: %s\n", st, err);
	free(x);
}

#define HDR "sample,status,lambda_max,lambda_min,iterations,xa_1,xb_1,xa_2,xb_2\n"

static void test_errors(void)
{
	refused("empty.csv", "", 0, "1:1", "empty file");
	refused("nothdr.csv", "a,b,c\n", 0, "1:1", "expected column 'sample'");
	refused("hdr3.csv", "sample,status,lambda_max,lambda_x,iterations\n",
		0, "1:26", "expected column 'lambda_min'");
	refused("odd.csv", "sample,status,lambda_max,lambda_min,iterations,"
		"xa_1\n", 0, "1:48", "pairs");
	refused("pairname.csv", "sample,status,lambda_max,lambda_min,"
		"iterations,xa_1,xa_2\n", 0, "1:53", "expected column 'xb_1'");
	refused("otherwall.csv", "sample,status,lambda_max,lambda_min,"
		"iterations,xa_1,xb_1\n0,accepted,1,1,1,0,1\n", 0, "1:48",
		"of 1 interfaces, the wall has 2");
	/* compare --samples and report --samples read the loads: a file of
	 * another wall is refused there too, with fewer or more interfaces */
	refused("otherwall-loads.csv", "sample,status,lambda_max,lambda_min,"
		"iterations,xa_1,xb_1\n0,accepted,1,1,1,0,1\n", 1, "1:48",
		"of 1 interfaces, the wall has 2");
	refused("biggerwall-loads.csv", "sample,status,lambda_max,lambda_min,"
		"iterations,xa_1,xb_1,xa_2,xb_2,xa_3,xb_3\n"
		"0,accepted,1,1,1,0,1,0,1,0,1\n", 1, "1:48",
		"of 3 interfaces, the wall has 2");
	refused("norows.csv", HDR, 0, "2:1", "no samples");
	refused("short.csv", HDR "0,accepted,1,1,3,0.1,0.9,0.2\n", 0, "2:29",
		"8 fields, the header has 9");
	refused("long.csv", HDR "0,accepted,1,1,3,0.1,0.9,0.2,0.8,7\n", 0,
		"2:34", "10 fields");
	refused("status.csv", HDR "0,accepted,1,1,3,0.1,0.9,0.2,0.8\n"
		"1,exploded,1,1,3,0.1,0.9,0.2,0.8\n", 0, "3:3",
		"unknown status");
	refused("nan.csv", HDR "0,accepted,1,1,3,0.1,nan,0.2,0.8\n", 0,
		"2:22", "must be a number");
	refused("junk.csv", HDR "0,accepted,1,1,3,0.1,0.9x,0.2,0.8\n", 0,
		"2:22", "must be a number");
	refused("emptypos.csv", HDR "0,accepted,1,1,3,0.1,0.9,,0.8\n", 0,
		"2:26", "must be a number");
	refused("range.csv", HDR "0,accepted,1,1,3,0.1,0.9,0.2,1.5\n", 0,
		"2:30", "between 0 and 1");
	refused("order.csv", HDR "0,accepted,1,1,3,0.6,0.4,0.2,0.8\n", 0,
		"2:22", "xb must not be less than xa");
	refused("loadmissing.csv", HDR "0,accepted,1,,3,0.1,0.9,0.2,0.8\n", 1,
		"2:14", "lambda_min");
	refused("loadneg.csv", HDR "0,accepted,1,-2,3,0.1,0.9,0.2,0.8\n", 1,
		"2:14", "lambda_min");
	refused("loadstatus.csv", HDR "0,accepte,1,1,3,0.1,0.9,0.2,0.8\n", 1,
		"2:3", "unknown status");
	/* every sample once: two runs' files joined would count the loads
	 * twice (the repeat's line, the first's in the message) */
	refused("twice.csv", HDR "0,accepted,1,1,3,0.1,0.9,0.2,0.8\n"
		"1,accepted,2,2,3,0.1,0.9,0.2,0.8\n"
		"0,accepted,1,1,3,0.1,0.9,0.2,0.8\n", 1, "4:1",
		"sample 0 again (first on line 2)");
	/* slipwall writes lambda_min <= lambda_max; older files exceed it
	 * by round-off only (runlog_read_loads) */
	refused("minmax.csv", HDR "0,accepted,1,1,3,0.1,0.9,0.2,0.8\n"
		"1,accepted,1,1.5,3,0.1,0.9,0.2,0.8\n", 1, "3:14",
		"lambda_min is above lambda_max");
	refused("nomax.csv", HDR "0,accepted,,1,3,0.1,0.9,0.2,0.8\n", 1,
		"2:12", "needs a lambda_max");
	refused("twice-pos.csv", HDR "5,accepted,1,1,3,0.1,0.9,0.2,0.8\n"
		"7,no_mechanism,1,,3,0.1,0.9,0.2,0.8\n"
		"7,accepted,1,2,3,0.1,0.9,0.2,0.8\n", 0, "4:1",
		"sample 7 again (first on line 3)");
	refused("negid.csv", HDR "-1,accepted,1,1,3,0.1,0.9,0.2,0.8\n", 1,
		"2:1", "sample's number");
	refused("textid.csv", HDR "x,accepted,1,1,3,0.1,0.9,0.2,0.8\n", 0,
		"2:1", "sample's number");

	char err[SW_ERRLEN];
	double *x = NULL;
	long n;
	enum sw_status st = read_positions(path_of("missing.csv"),
						  &fake, &x, &n, NULL, err);
	tap_ok(st == SW_EINPUT && strstr(err, "missing.csv: cannot open"),
	       "a missing file is refused with its name");

	/* CRLF line ends are read; a last line without its newline is a
	 * row cut by a kill: dropped, with a warning */
	const char *p = path_of("crlf.csv");
	spit(p, "sample,status,lambda_max,lambda_min,iterations,xa_1,xb_1,"
	     "xa_2,xb_2\r\n0,accepted,1,0.5,3,0.1,0.9,0.2,0.8\r\n"
	     "1,accepted,1,0.25,3,0,1,0.5,0.5");
	char warn[SW_ERRLEN] = "x";
	st = read_positions(p, &fake, &x, &n, warn, err);
	tap_ok(st == SW_OK && n == 1 && x[0] == 0.1 && x[3] == 0.8,
	       "CRLF accepted; a last row without its newline dropped");
	tap_ok(strstr(warn, "crlf.csv:3: warning: the last row is "
		      "incomplete") != NULL, "... with a warning at its line");
	free(x);
	double *lam = NULL;
	st = runlog_read_loads(p, &fake, &lam, &n, warn, err);
	tap_ok(st == SW_OK && n == 1 && lam[0] == 0.5 &&
	       strstr(warn, "crlf.csv:3: warning"),
	       "the loads reader drops it too, with the warning");
	free(lam);
	/* a whole file: no warning */
	spit(p, HDR "0,accepted,1,0.5,3,0.1,0.9,0.2,0.8\n");
	st = runlog_read_loads(p, &fake, &lam, &n, warn, err);
	tap_ok(st == SW_OK && n == 1 && warn[0] == 0, "no warning when whole");
	free(lam);
	/* a cut row cut in the middle of a number: still only dropped */
	spit(p, HDR "0,accepted,1,0.5,3,0.1,0.9,0.2,0.8\n1,accepted,1,0.2");
	st = read_positions(p, &fake, &x, &n, warn, err);
	tap_ok(st == SW_OK && n == 1 && warn[0], "a row cut mid-number "
	       "dropped with a warning");
	free(x);
}

/* Lines have a bound: a file without line ends (/dev/zero) is refused
 * at once instead of filling the memory. */
static void test_bounds(void)
{
	char err[SW_ERRLEN];
	double *x = NULL;
	long n = -1;
	enum sw_status st = read_positions("/dev/zero", &fake, &x, &n,
						  NULL, err);
	tap_ok(st == SW_EINPUT && strstr(err, "/dev/zero:1:1: a NUL byte"),
	       "/dev/zero refused at once: %s", err);
	const char *p = path_of("longrow.csv");
	FILE *f = fopen(p, "w");
	fputs(HDR "0,accepted,1,0.5,3,0.1,0.9,0.2,0.8\n", f);
	for (int i = 0; i < 100000; i++)
		fputs("0.1", f);
	fputs("\n", f);
	fclose(f);
	st = runlog_read_loads(p, &fake, &x, &n, NULL, err);
	tap_ok(st == SW_EINPUT && strstr(err, "longrow.csv:3:1: a line longer "
					 "than"), "a row longer than its header "
	       "allows is refused: %s", err);
}

/* An output never destroys an input, however its path is spelled, and
 * one samples file has one writer. */
static void test_guards(void)
{
	char err[SW_ERRLEN], other[4200], cwd[4096];
	const char *p = path_of("input.csv");
	spit(p, HDR "0,accepted,1,0.5,3,0.1,0.9,0.2,0.8\n");
	const char *keep[] = {"nothing-here.yaml", p, NULL};
	struct runlog *l = NULL;
	/* the same file through "dir/./input.csv" */
	snprintf(other, sizeof other, "%s/./input.csv", dir);
	enum sw_status st = runlog_create(&l, other, &fake, keep, err);
	tap_ok(st == SW_EINPUT && !l && strstr(err, "the samples would "
					       "overwrite it"),
	       "another spelling of an input is refused: %s", err);
	/* through a hard link */
	snprintf(other, sizeof other, "%s/link.csv", dir);
	unlink(other);
	if (link(p, other) == 0) {
		st = runlog_create(&l, other, &fake, keep, err);
		tap_ok(st == SW_EINPUT && !l, "a hard link to an input is "
		       "refused");
	} else {
		tap_skip("a hard link to an input is refused",
			 "no hard links here");
	}
	const char *got = slurp(p);
	tap_ok(got && !strncmp(got, HDR "0,accepted", strlen(HDR) + 10),
	       "the input is untouched");
	/* relative spelling from the directory */
	if (getcwd(cwd, sizeof cwd) && chdir(dir) == 0) {
		st = runlog_create(&l, "input.csv", &fake, keep, err);
		tap_ok(st == SW_EINPUT && !l, "a relative spelling is refused");
		if (chdir(cwd) != 0)
			tap_ok(0, "chdir back");
	}
	/* two writers */
	const char *q = path_of("shared.csv");
	struct runlog *a = NULL, *b = NULL;
	st = runlog_create(&a, q, &fake, keep, err);
	tap_ok(st == SW_OK && a, "the first writer opens it");
	st = runlog_create(&b, q, &fake, keep, err);
	tap_ok(st == SW_EINPUT && !b && strstr(err, "another process is "
					       "writing"),
	       "the second is refused while the first holds it: %s", err);
	runlog_close(a, err);
	st = runlog_create(&b, q, &fake, keep, err);
	tap_ok(st == SW_OK && b, "and accepted once the first is closed");
	runlog_close(b, err);
}

int main(void)
{
	fake.nifaces = M;
	fake.nblocks = 2;
	if (!mkdtemp(dir)) {
		perror("mkdtemp");
		return 1;
	}
	test_format();
	test_round_trip();
	test_bounds();
	test_guards();
	test_errors();
	char cmd[300];
	snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
	if (system(cmd) != 0)
		tap_diag("could not remove %s", dir);
	return tap_done();
}
