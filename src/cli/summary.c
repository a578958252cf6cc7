/* summary.c - reading back a run's JSON summary; see summary.h. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "summary.h"

/* The value of top-level key `key` in text: a string (copied into str,
 * escapes \" and \\ undone) returns 1, a number (into *num) 2, null or
 * absent 0. */
static int top_value(const char *text, const char *key, char *str,
		     size_t len, double *num)
{
	char pat[64];
	snprintf(pat, sizeof pat, "\n  \"%s\": ", key);
	const char *p = strstr(text, pat);
	if (!p)
		return 0;
	p += strlen(pat);
	if (*p == '"') {
		size_t u = 0;
		for (p++; *p && *p != '"'; p++) {
			if (*p == '\\' && (p[1] == '"' || p[1] == '\\'))
				p++;
			else if (*p == '\\')
				return 0;	/* other escapes: not ours */
			if (u + 1 < len)
				str[u++] = *p;
		}
		str[u] = 0;
		return *p == '"' ? 1 : 0;
	}
	char *end;
	double v = strtod(p, &end);
	if (end == p || (*end != ',' && *end != '\n'))
		return 0;
	*num = v;
	return 2;
}

static int same_file(const char *a, const char *b)
{
	struct stat sa, sb;
	if (!strcmp(a, b))
		return 1;
	return stat(a, &sa) == 0 && stat(b, &sb) == 0 &&
	       sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

int summary_beside(const char *csv, struct summary_file *s)
{
	memset(s, 0, sizeof *s);
	size_t n = strlen(csv);
	if (n < 5 || strcmp(csv + n - 4, ".csv") || n + 1 > sizeof s->path)
		return -1;
	snprintf(s->path, sizeof s->path, "%.*s.json", (int)(n - 4), csv);
	FILE *f = fopen(s->path, "r");
	if (!f)
		return -1;
	char *text = malloc(1 << 20);
	size_t got = text ? fread(text, 1, (1 << 20) - 1, f) : 0;
	fclose(f);
	if (!text)
		return -1;
	text[got] = 0;
	double v;
	char dummy[8];
	int ok = top_value(text, "samples_file", s->samples_file,
			   sizeof s->samples_file, &v) == 1 &&
		 same_file(s->samples_file, csv);
	if (ok) {
		if (top_value(text, "wall", s->wall, sizeof s->wall, &v) != 1)
			s->wall[0] = 0;
		if (top_value(text, "wall_digest", s->wall_digest,
			      sizeof s->wall_digest, &v) != 1)
			s->wall_digest[0] = 0;
		s->has_standard = top_value(text, "standard", dummy,
					    sizeof dummy, &s->standard) == 2;
		s->has_gilbert = top_value(text, "gilbert", dummy,
					   sizeof dummy, &s->gilbert) == 2;
	}
	free(text);
	return ok ? 0 : -1;
}
