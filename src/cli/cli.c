/* cli.c - helpers shared by the batch commands; see cli.h. */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "cli.h"
#include "slipwall/json.h"
#include "slipwall/mc.h"
#include "slipwall/text.h"
#include "slipwall/wallfile.h"

int cli_tests(const char *file, const struct wall *w, double **tests,
	      long *ntests)
{
	char err[SW_ERRLEN];
	*tests = NULL;
	*ntests = 0;
	if (file) {
		if (cli_read_tests(file, tests, ntests, err) != SW_OK) {
			cli_errorf("%s", err);
			return 2;
		}
	} else if (w->ntests > 0) {
		*ntests = w->ntests;
		*tests = sw_xmalloc(sizeof(double) * (size_t)*ntests);
		memcpy(*tests, w->tests, sizeof(double) * (size_t)*ntests);
	}
	return 0;
}

/* SLIPWALL_GLPK_MEM_MB set the limit (cli_lp_from_env) */
static int lp_mem_env;

void cli_memory_note(const char *cmd)
{
	long oom = mc_memory_errors();
	if (oom > 0)	/* each made a sample "numerical" (src/lib/lp_glpk.c) */
		cli_errorf("slipwall %s: the LP solver ran out of memory %ld "
			   "time%s (its limit: %d MB per thread): the "
			   "samples it was solving were rejected as "
			   "numerical; free memory or use fewer --threads",
			   cmd, oom, oom == 1 ? "" : "s", cli_lp.mem_limit_mb);
}

int cli_check_depth(const char *cmd, const struct wall *w, const char *path,
		    double depth)
{
	if (depth >= 0 && w->anywhere)
		return cli_usage_error(cmd, "--depth: %s draws its contact "
				       "points anywhere (contacts.positions): "
				       "there is no depth", path);
	return 0;
}

int cli_load_wall_quiet(const char *path, struct wall **w)
{
	char err[SW_ERRLEN];
	enum sw_status st = wallfile_load(path, w, err);
	if (st != SW_OK) {
		cli_errorf("%s", err);
		return sw_status_exit(st);
	}
	return 0;
}

int cli_load_wall(const char *path, struct wall **w)
{
	int rc = cli_load_wall_quiet(path, w);
	if (!rc)
		cli_warn_wall(*w);
	return rc;
}

/* The wall's warnings, each into buf without the wall's path: 0, the
 * friction lock (wall_friction_lock); 1, blocks that rest on no joint
 * (wall_hanging); 2, blocks that overhang their bearing
 * (wall_overhang_text).  Returns 0 when w has no such thing. */
#define WALL_WARNINGS 3
static int warning_text(const struct wall *w, int which, char *buf,
			size_t len)
{
	char what[512];
	if (which == 0 && wall_friction_lock_text(w, what, sizeof what))
		snprintf(buf, len, "%s: associative friction locks them (at "
			 "a right angle, when the product is 1 or more), and "
			 "every sample starts from the associative field, so "
			 "its load may be the sliding load, or `unbounded`, "
			 "where the wall rocks at less (docs/method.md, \"What "
			 "the method cannot answer\")", what);
	else if (which == 1 && wall_hanging_text(w, what, sizeof what))
		snprintf(buf, len, "%s: the weight hangs on the friction of "
			 "side joints (an opening without a lintel?), held by "
			 "a clamp that the sequential LP's fixed capacities "
			 "can lose: such samples are rejected as `hanging` "
			 "(docs/method.md, \"What the method cannot answer\")",
			 what);
	else if (which == 2 && wall_overhang_text(w, what, sizeof what))
		snprintf(buf, len, "%s: at a contact depth above 0 its weight "
			 "acts beyond its contact points, and it is held by the "
			 "friction and contact of its neighbours (a jamb half "
			 "over an opening?), a clamp that the sequential LP's "
			 "fixed capacities can lose: such samples are rejected "
			 "as `hanging` (docs/method.md, \"Blocks that overhang "
			 "an opening\")", what);
	else
		return 0;
	return 1;
}

void cli_warn_wall(const struct wall *w)
{
	char text[1024];
	for (int i = 0; i < WALL_WARNINGS; i++)
		if (warning_text(w, i, text, sizeof text))
			fprintf(stderr, "slipwall: warning: %s: %s\n",
				w->path ? w->path : "the wall", text);
}

void cli_json_warnings(struct json *j, const struct wall *w)
{
	char text[1024];
	json_key(j, "warnings");
	json_array_begin(j);
	for (int i = 0; i < WALL_WARNINGS; i++)
		if (warning_text(w, i, text, sizeof text))
			json_string(j, text);
	json_array_end(j);
}

const char *cli_demo_wall(void)
{
	static char path[PATH_MAX];
	char exe[PATH_MAX];
	ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
	if (n > 0) {
		exe[n] = 0;
		char *slash = strrchr(exe, '/');
		if (slash)
			*slash = 0;
		/* running from the build tree: use the source tree's walls */
		if (!strcmp(exe, SLIPWALL_BUILDDIR)) {
			snprintf(path, sizeof path, "%s/walls/demo.yaml",
				 SLIPWALL_SRCDIR);
			if (access(path, R_OK) == 0)
				return path;
		}
	}
	snprintf(path, sizeof path, "%s/walls/demo.yaml", SLIPWALL_DATADIR);
	return path;
}

/* The cleaned copies cli_text returned last: a ring, so that one printf
 * can take several; the copies are freed as the ring turns (and the
 * last ones at exit, by the system). */
static char *text_ring[8];
static int text_next;

const char *cli_text(const char *s)
{
	if (!s || text_is_clean(s))
		return s;
	free(text_ring[text_next]);
	char *c = text_ring[text_next] = text_clean(s);
	text_next = (text_next + 1) % 8;
	return c;
}

/* vprintf into a malloc'd string, cleaned for printing. */
static char *clean_vformat(const char *fmt, va_list ap)
{
	char *raw = NULL;
	size_t len = 0;
	FILE *f = open_memstream(&raw, &len);
	if (!f)
		return text_clean(fmt);
	vfprintf(f, fmt, ap);
	if (fclose(f) != 0 || !raw) {
		free(raw);
		return text_clean(fmt);
	}
	char *c = text_clean(raw);
	free(raw);
	return c;
}

void cli_errorf(const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	char *s = clean_vformat(fmt, ap);
	va_end(ap);
	fprintf(stderr, "%s\n", s);
	free(s);
}

int cli_usage_error(const char *cmd, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	char *s = clean_vformat(fmt, ap);
	va_end(ap);
	fprintf(stderr, "slipwall %s: %s\nTry 'slipwall %s --help'.\n", cmd, s,
		cmd);
	free(s);
	return 2;
}

int cli_parse_seed(const char *s, unsigned long *out)
{
	/* digits only: strtoull would take "-1" as 2^64-1, and " 5" */
	if (!*s || strspn(s, "0123456789") != strlen(s))
		return -1;
	char *end;
	errno = 0;
	unsigned long long v = strtoull(s, &end, 10);
	if (errno || *end || v > WALL_SEED_MAX)
		return -1;
	*out = (unsigned long)v;
	return 0;
}

int cli_parse_time_limit(const char *s, double *out)
{
	double v;
	if (text_parse_double(s, &v) || !(v > 0) || v > CLI_TIME_LIMIT_MAX)
		return -1;
	*out = v;
	return 0;
}

double cli_worker_bytes(const struct wall *w)
{
	return 1048576.0 + 16384.0 * (double)w->nifaces +
	       4096.0 * (double)w->nblocks;
}

/* Bytes the process may use: the machine's memory, or RLIMIT_AS. */
static double memory_bytes(void)
{
	long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGESIZE);
	double m = pages > 0 && size > 0 ? (double)pages * (double)size :
		   INFINITY;
	struct rlimit rl;
	if (getrlimit(RLIMIT_AS, &rl) == 0 && rl.rlim_cur != RLIM_INFINITY &&
	    (double)rl.rlim_cur < m)
		m = (double)rl.rlim_cur;
	return m;
}

int cli_threads(const char *cmd, const struct wall *w, int requested,
		int def, long n, int *threads)
{
	int t = requested > 0 ? requested : def;
	if (t < 1)
		t = 1;
	if (n > 0 && t > n)
		t = (int)n;
	double per = cli_worker_bytes(w), mem = memory_bytes();
	/* half the memory for the workers: the rest is the wall, the
	 * samples in flight, the tally and everything else */
	double fit = floor(0.5 * mem / per);
	if ((double)t > fit) {
		int k = fit >= 1 ? (int)fit : 1;
		if (requested > 0 && requested > k)
			return cli_usage_error(cmd, "--threads %d: each worker "
					       "needs about %.0f MB for this wall "
					       "(%d interfaces), %.1f GB in all: "
					       "use at most %d (half of the %.1f "
					       "GB of memory)", requested,
					       per / 1048576.0, w->nifaces,
					       (double)t * per / 1e9, k,
					       mem / 1e9);
		t = k;
	}
	*threads = t;
	/* and the LP solver's allocator, on each of them, that half shared
	 * out: it runs out inside its own accounting (src/lib/lp_glpk.c,
	 * "Out of memory"), which fails a sample, before the kernel kills
	 * the process */
	if (!lp_mem_env) {
		double mb = 0.5 * mem / (double)t / 1048576.0;
		cli_lp.mem_limit_mb = !(mb >= 1) ? 1 : mb >= INT_MAX ? INT_MAX :
				      (int)mb;
	}
	return 0;
}

struct sample_lp_config cli_lp = { .start = SAMPLE_START_DEFAULT };

int cli_lp_from_env(void)
{
	char err[SW_ERRLEN];
	sample_lp_config_default(&cli_lp);
	if (sample_lp_config_parse(&cli_lp, getenv("SLIPWALL_LP_START"),
				   NULL, NULL, err)) {
		fprintf(stderr, "slipwall: %s\n", err);
		return -1;
	}
	if (sample_lp_config_parse(&cli_lp, NULL,
				   getenv("SLIPWALL_LP_FAULT"), NULL, err))
		fprintf(stderr, "slipwall: %s\n", err);
	if (sample_lp_config_parse(&cli_lp, NULL, NULL,
				   getenv("SLIPWALL_GLPK_MEM_MB"), err))
		fprintf(stderr, "slipwall: %s\n", err);
	lp_mem_env = cli_lp.mem_limit_mb > 0;
	return 0;
}

/* Bounds of a file of test loads: a line, and the whole file (the wall
 * loader's 16 MiB; a million loads fit in a tenth of it). */
#define TESTS_LINE_MAX 4096
#define TESTS_FILE_MAX ((size_t)16 << 20)

/* A load as people write it: decimal digits, a point, an exponent -
 * not strtod's hexadecimal, infinity or NaN. */
static int decimal_number(const char *p, const char *end)
{
	int digits = 0;
	for (const char *q = p; q < end; q++) {
		if (isdigit((unsigned char)*q))
			digits = 1;
		else if (!strchr("+-.eE", *q))
			return 0;
	}
	return digits;
}

enum sw_status cli_read_tests(const char *path, double **out, long *nout,
			      char *err)
{
	FILE *f = fopen(path, "r");
	if (!f)
		return sw_fail(err, SW_EINPUT, "%s: cannot open: %s", path,
			       strerror(errno));
	char *line = NULL;
	size_t cap = 0, len, total = 0;
	long lineno = 0, n = 0, xcap = 0;
	double *x = NULL;
	enum sw_status st = SW_OK;
	enum text_line got = TEXT_LINE_EOF;
	while (st == SW_OK && (got = text_getline(f, &line, &cap,
						  TESTS_LINE_MAX, &len)) > 0) {
		lineno++;
		total += len + 1;
		if (total > TESTS_FILE_MAX) {
			st = sw_fail(err, SW_EINPUT, "%s:%ld:1: more than %zu "
				     "MiB: too large for a file of test loads",
				     path, lineno, TESTS_FILE_MAX >> 20);
			break;
		}
		char *hash = strchr(line, '#');
		if (hash)
			*hash = 0;
		char *p = line;
		/* a byte-order mark, as some editors save UTF-8 */
		if (lineno == 1)
			p += text_bom(p, strlen(p));
		while (isspace((unsigned char)*p))
			p++;
		if (!*p)
			continue;
		int col = (int)(p - line) + 1;
		char *end;
		errno = 0;
		double v = strtod(p, &end);
		if (end == p || errno == ERANGE || !isfinite(v) ||
		    !decimal_number(p, end) ||
		    (*end && !isspace((unsigned char)*end))) {
			st = sw_fail(err, SW_EINPUT, "%s:%ld:%d: a load must be "
				     "a number, in decimal", path, lineno, col);
			break;
		}
		if (!(v > 0)) {
			/* as the wall file's tests: loads (a wall that fell
			 * under no load is no test of a collapse load) */
			st = sw_fail(err, SW_EINPUT, "%s:%ld:%d: a collapse load "
				     "must be > 0", path, lineno, col);
			break;
		}
		char *q = end;
		while (isspace((unsigned char)*q))
			q++;
		if (*q) {
			st = sw_fail(err, SW_EINPUT, "%s:%ld:%d: one load per "
				     "line (a '#' starts a comment)", path,
				     lineno, (int)(q - line) + 1);
			break;
		}
		if (n == xcap) {
			xcap = xcap ? 2 * xcap : 64;
			x = sw_xrealloc(x, sizeof(double) * (size_t)xcap);
		}
		x[n++] = v;
	}
	if (st == SW_OK && got == TEXT_LINE_NUL)
		st = sw_fail(err, SW_EINPUT, "%s:%ld:%zu: a NUL byte in a text "
			     "file", path, lineno + 1, len + 1);
	else if (st == SW_OK && got == TEXT_LINE_LONG)
		st = sw_fail(err, SW_EINPUT, "%s:%ld:1: a line longer than %d "
			     "bytes: not a file of test loads", path, lineno + 1,
			     TESTS_LINE_MAX);
	else if (st == SW_OK && got == TEXT_LINE_ERROR)
		st = sw_fail(err, SW_EINPUT, "%s: cannot read: %s", path,
			     strerror(errno));
	free(line);
	fclose(f);
	if (st != SW_OK) {
		free(x);
		return st;
	}
	*out = x;
	*nout = n;
	return SW_OK;
}

/* Is line (a whole line, its newline included or not) the marker of
 * synthetic loads: "# slipwall: synthetic", blanks allowed around the
 * words? */
static int synthetic_marker(const char *line)
{
	static const char *const words[] = {"#", "slipwall:", "synthetic"};
	const char *p = line;
	for (int k = 0; k < 3; k++) {
		while (*p == ' ' || *p == '\t')
			p++;
		size_t n = strlen(words[k]);
		if (strncmp(p, words[k], n))
			return 0;
		p += n;
	}
	while (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')
		p++;
	return *p == 0;
}

int cli_tests_synthetic(const char *path)
{
	FILE *f = fopen(path, "r");
	if (!f)
		return 0;
	char line[512];
	int yes = 0, whole = 1;
	while (!yes && fgets(line, sizeof line, f)) {
		/* only a line read whole from its start can be the marker */
		yes = whole && synthetic_marker(line);
		whole = strchr(line, '\n') != NULL;
	}
	fclose(f);
	return yes;
}

void cli_shell_arg(FILE *f, const char *s)
{
	int plain = *s != 0;
	for (const char *p = s; *p; p++)
		if (!isalnum((unsigned char)*p) && !strchr("/._-+=,:", *p))
			plain = 0;
	if (plain) {
		fprintf(f, " %s", s);
		return;
	}
	fputs(" '", f);
	int used;
	for (const char *p = s; *p; p += used) {
		int n = text_utf8_len((const unsigned char *)p);
		used = n ? n : 1;
		char one[8] = {0};
		memcpy(one, p, (size_t)used);
		if (*p == '\'') {
			fputs("'\\''", f);
		} else if (*p == '\n' || text_is_clean(one)) {
			fwrite(p, 1, (size_t)used, f);
		} else {
			/* a control character or an invalid byte: made by
			 * printf, outside the quotes ($(...) drops trailing
			 * newlines only, and this is none) */
			fputs("'\"$(printf '", f);
			for (int k = 0; k < used; k++)
				fprintf(f, "\\%03o", (unsigned char)p[k]);
			fputs("')\"'", f);
		}
	}
	fputc('\'', f);
}
