/*
 * tui_file.c - where the workbench's files go: the samples file of each
 * run (tui_run.c streams to it), the wall each run sampled beside it
 * (X.yaml beside X.csv, which H reopens: tui_compare.c), and the wall's
 * short name that names them and the default of a save (tui_io.c).
 *
 * Samples files: $SLIPWALL_RUNS, else $XDG_DATA_HOME/slipwall/runs, else
 * ~/.local/share/slipwall/runs (made if missing), named
 * <wall>-<YYYYmmdd-HHMMSS>-<run>.csv: <wall> is the wall file's name
 * without .yaml, <run> counts the runs of the session (each edit, reset
 * or open starts one).  The file streams from the first sample, so
 * saving never copies it.  The environment is read here, not in the
 * library: history_runs_make is given the directory.
 *
 * Two sessions started in the same second ask for the same name.  The
 * name is taken by creating the file (O_CREAT | O_EXCL), which only one
 * of them can do; the other goes on to <...>-<run>.1.csv, .2.csv ...
 * (a check with access() before runlog_create opened the file left
 * both free to pick it, and a name taken by a dangling symbolic link
 * was written through it).  runlog_create then opens the empty file the
 * session made.
 */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "slipwall/wallfile.h"
#include "tui.h"

/* The length of stem without a run's stamp "-YYYYMMDD-HHMMSS-N" or
 * "-YYYYMMDD-HHMMSS-N.K" at its end (tui_file_csv_path's), or its whole
 * length: a run's wall reopened from H is named by the wall it came
 * from, not by every stamp of its reopenings. */
static size_t stem_without_stamp(const char *s)
{
	size_t n = strlen(s), i = n;
	int dot = 0;
	for (;;) {	/* the run number, and a ".K" after it */
		size_t e = i;
		while (i > 0 && isdigit((unsigned char)s[i - 1]))
			i--;
		if (i == e)
			return n;
		if (!dot && i > 0 && s[i - 1] == '.') {
			dot = 1;
			i--;
			continue;
		}
		break;
	}
	static const int width[2] = {6, 8};	/* HHMMSS, YYYYMMDD */
	for (int k = 0; k < 2; k++) {
		if (i < 1 || s[i - 1] != '-')
			return n;
		i--;
		for (int d = 0; d < width[k]; d++, i--)
			if (i < 1 || !isdigit((unsigned char)s[i - 1]))
				return n;
	}
	return i > 1 && s[i - 1] == '-' ? i - 1 : n;
}

void tui_file_stem(const struct wall *w, char *out, size_t len)
{
	const char *p = w->path ? w->path : (w->name ? w->name : "wall");
	const char *slash = strrchr(p, '/');
	snprintf(out, len, "%s", slash ? slash + 1 : p);
	char *dot = strrchr(out, '.');
	if (dot && dot != out && (!strcmp(dot, ".yaml") || !strcmp(dot, ".yml")))
		*dot = 0;
	out[stem_without_stamp(out)] = 0;
	for (char *s = out; *s; s++)
		if (*s == ' ' || *s == '/' || (unsigned char)*s < 32)
			*s = '_';
	if (!out[0])
		snprintf(out, len, "wall");
}

int tui_file_runs_dir(char *out, size_t len, char *err)
{
	const char *env = getenv("SLIPWALL_RUNS");
	const char *xdg = getenv("XDG_DATA_HOME");
	const char *home = getenv("HOME");
	int n;

	if (env && env[0])
		n = snprintf(out, len, "%s", env);
	else if (xdg && xdg[0] == '/')
		n = snprintf(out, len, "%s/slipwall/runs", xdg);
	else if (home && home[0])
		n = snprintf(out, len, "%s/.local/share/slipwall/runs", home);
	else {
		sw_fail(err, SW_EIO, "no place for the samples files: set SLIPWALL_RUNS or HOME");
		return -1;
	}
	if (n < 0 || (size_t)n >= len) {
		sw_fail(err, SW_EIO, "the runs directory's path is too long");
		return -1;
	}
	return history_runs_make(out, err);
}

int tui_file_csv_path(struct tui *t, char *out, size_t len, char *err)
{
	char dir[PATH_MAX], stem[128], stamp[32];

	if (tui_file_runs_dir(dir, sizeof dir, err))
		return -1;
	time_t now = time(NULL);
	struct tm tm;
	localtime_r(&now, &tm);
	strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &tm);
	tui_file_stem(t->w, stem, sizeof stem);
	for (int k = 0; k < 1000; k++) {
		int n;
		if (k == 0)
			n = snprintf(out, len, "%s/%s-%s-%d.csv", dir, stem, stamp,
				     t->runno);
		else
			n = snprintf(out, len, "%s/%s-%s-%d.%d.csv", dir, stem,
				     stamp, t->runno, k);
		if (n < 0 || (size_t)n >= len) {
			sw_fail(err, SW_EIO, "%s: path too long", dir);
			return -1;
		}
		int fd = open(out, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
		if (fd >= 0) {
			close(fd);
			return 0;
		}
		if (errno != EEXIST) {
			sw_fail(err, SW_EIO, "%s: cannot create: %s", out,
				strerror(errno));
			return -1;
		}
	}
	sw_fail(err, SW_EIO, "%s: 1000 samples files of run %d this second",
		dir, t->runno);
	return -1;
}

int tui_file_run_wall_path(const char *csv, char *out, size_t len)
{
	size_t n = strlen(csv);
	if (n < 5 || strcmp(csv + n - 4, ".csv") || n + 2 > len)
		return 0;
	memcpy(out, csv, n - 4);
	memcpy(out + n - 4, ".yaml", 6);
	return 1;
}

void tui_file_save_run_wall(struct tui *t)
{
	char path[PATH_MAX], err[SW_ERRLEN];
	if (!t->run.csv[0] ||
	    !tui_file_run_wall_path(t->run.csv, path, sizeof path))
		return;
	if (wallfile_save(t->w, path, err) != SW_OK)
		tui_message(t, 1, "the run's wall: %s (run %d cannot be "
			    "reopened from H)", err, t->runno);
}
