/*
 * test_history.c - the run history's index file: rows read back as
 * written (numbers to the last bit, NaN, text with tabs, the cov), rows
 * of an index written before the cov column (cov 0), the header
 * written once, the last N rows, lines that are not rows skipped, the
 * runs directory made when missing (the workbench says where it is:
 * tui_file_runs_dir reads the environment); a file over
 * 4 MiB read from its end only; /dev/zero and a FIFO refused.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "slipwall/history.h"
#include "tap.h"

static void row(struct history_row *r, int run)
{
	memset(r, 0, sizeof *r);
	snprintf(r->session, sizeof r->session, "20260101-120000");
	r->run = run;
	snprintf(r->wall, sizeof r->wall, "Demo wall");
	snprintf(r->what, sizeof r->what, "friction\tbed %d", run);
	r->mu_bed = 0.1 * run;	/* not exact in binary: must round-trip */
	r->mu_head = 0.7;
	r->mu_cov = run == 2 ? 0.2 : 0;	/* run 2: random friction */
	r->depth = 0.25;
	r->load = 0;
	r->at[0] = 0.8;
	r->at[1] = 1.0 / 3;
	r->dir[0] = 1;
	r->samples = 1000 + run;
	r->accepted = 990 + run;
	r->p05 = 35.32 + run;
	r->p05_lo = run == 1 ? NAN : 35.0;
	r->p05_hi = run == 1 ? NAN : 36.0;
	r->p50 = 38.47;
	r->p95 = 235.4;
	snprintf(r->file, sizeof r->file, "/tmp/runs/demo-%d.csv", run);
}

int main(void)
{
	char err[SW_ERRLEN], dir[PATH_MAX], path[PATH_MAX];
	char base[] = "/tmp/slipwall-history-XXXXXX";
	if (!mkdtemp(base)) {
		perror("mkdtemp");
		return 1;
	}
	snprintf(dir, sizeof dir, "%s/a/b", base);
	tap_ok(history_runs_make(dir, err) == 0 && access(dir, W_OK) == 0,
	       "the runs directory is made when missing");
	history_index_path(dir, path, sizeof path);

	struct history_row w[3], *r = NULL;
	int n = -1;
	tap_ok(history_read(path, 0, &r, &n, err) == SW_OK && n == 0,
	       "no index yet: no rows");
	free(r);
	for (int i = 0; i < 3; i++) {
		row(&w[i], i + 1);
		if (history_append(path, &w[i], err) != SW_OK)
			tap_diag("%s", err);
	}
	/* a line cut short and a stranger: both skipped; a row of an index
	 * written before the mu_cov column (21 columns, friction 0.55
	 * certain) and one whose cov is not a number */
	FILE *f = fopen(path, "a");
	fputs("20260101-120000\t4\tcut short\n", f);
	fputs("not a row at all\n", f);
	fputs("20251201-090000\t7\tOld wall\tfriction\t0.55\t0.55\t0.25\t0\t"
	      "point\t0.8\t0.5\t1\t0\t100\t99\t30\tnan\tnan\t31\t40\t"
	      "/tmp/runs/old-7.csv\n", f);
	fputs("20251201-090000\t8\tOld wall\tfriction\t0.55\t0.55\t0.25\t0\t"
	      "point\t0.8\t0.5\t1\t0\t100\t99\t30\tnan\tnan\t31\t40\t"
	      "/tmp/runs/old-8.csv\tlots\n", f);
	fclose(f);

	enum sw_status st = history_read(path, 0, &r, &n, err);
	tap_ok(st == SW_OK && n == 4,
	       "four rows read back (the cut, the stranger and the bad cov skipped): %d", n);
	tap_ok(n == 4 && r[3].run == 7 && r[3].mu_cov == 0 && r[3].mu_bed == 0.55 &&
	       !strcmp(r[3].file, "/tmp/runs/old-7.csv"),
	       "a row written before the mu_cov column: read, cov 0 (friction certain)");
	tap_ok(n == 4 && r[1].mu_cov == 0.2 && r[0].mu_cov == 0,
	       "the cov read back (run 2's 0.2; run 1's 0: not random)");
	int same = n == 4;
	for (int i = 0; i < 3 && same; i++) {
		same = r[i].run == w[i].run && r[i].mu_bed == w[i].mu_bed &&
		       r[i].at[1] == w[i].at[1] && r[i].samples == w[i].samples &&
		       r[i].accepted == w[i].accepted && r[i].p05 == w[i].p05 &&
		       r[i].mu_cov == w[i].mu_cov &&
		       r[i].load == 0 && !strcmp(r[i].file, w[i].file) &&
		       !strcmp(r[i].session, w[i].session) &&
		       !strcmp(r[i].wall, "Demo wall");
	}
	tap_ok(same, "every field as written, to the last bit");
	tap_ok(n == 4 && isnan(r[0].p05_lo) && r[1].p05_lo == 35.0,
	       "NaN (no interval yet) read back as NaN");
	tap_ok(n == 4 && !strcmp(r[0].what, "friction bed 1"),
	       "a tab in the text becomes a space: '%s'", n ? r[0].what : "");
	free(r);

	tap_ok(history_read(path, 2, &r, &n, err) == SW_OK && n == 2 &&
	       r[0].run == 3 && r[1].run == 7, "the last 2 rows, oldest first");
	free(r);

	f = fopen(path, "r");
	char line[4096];
	int headers = 0;
	while (fgets(line, sizeof line, f))
		headers += !strncmp(line, "session\trun\t", 12);
	fclose(f);
	tap_ok(headers == 1, "the header is written once (%d)", headers);

	/* a file larger than the reader's bound (4 MiB): only its end is
	 * read, and the first (cut) line there is dropped (issue 23) */
	struct history_row big;
	row(&big, 7);
	int nbig = 0;
	while (nbig < 40000) {
		big.run = ++nbig;
		if (history_append(path, &big, err) != SW_OK)
			break;
	}
	st = history_read(path, 0, &r, &n, err);
	tap_ok(st == SW_OK && n > 1000 && n < nbig && r[n - 1].run == nbig &&
	       r[0].run == nbig - n + 1,
	       "of %d rows in a file over 4 MiB, the last %d are read, whole",
	       nbig, n);
	free(r);
	unlink(path);

	/* what is not a regular file is refused, at once (a FIFO would
	 * block the writer, /dev/zero feed the reader for ever) */
	if (symlink("/dev/zero", path) == 0) {
		tap_ok(history_read(path, 0, &r, &n, err) == SW_EIO &&
		       strstr(err, "not a regular file"),
		       "history.tsv -> /dev/zero: not read (%s)", err);
		tap_ok(history_append(path, &big, err) == SW_EIO &&
		       strstr(err, "not a regular file"),
		       "history.tsv -> /dev/zero: not written (%s)", err);
		unlink(path);
	}
	if (mkfifo(path, 0600) == 0) {
		tap_ok(history_append(path, &big, err) == SW_EIO &&
		       strstr(err, "not a regular file (a FIFO)"),
		       "history.tsv a FIFO: not opened (%s)", err);
		unlink(path);
	}

	unlink(path);
	rmdir(dir);
	snprintf(dir, sizeof dir, "%s/a", base);
	rmdir(dir);
	rmdir(base);
	return tap_done();
}
