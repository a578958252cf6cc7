/* json.c - a small streaming JSON writer; see json.h. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/json.h"
#include "slipwall/text.h"

void json_init(struct json *j, FILE *f, int indent)
{
	memset(j, 0, sizeof *j);
	j->f = f;
	j->indent = indent;
	j->first[0] = 1;
}

static void newline(struct json *j)
{
	if (!j->indent)
		return;
	fputc('\n', j->f);
	for (int i = 0; i < j->depth; i++)
		fputs("  ", j->f);
}

/* Before a value: a comma and a newline unless it follows a key. */
static void pre_value(struct json *j)
{
	if (j->after_key) {
		j->after_key = 0;
		return;
	}
	if (j->depth > 0) {
		if (!j->first[j->depth])
			fputc(',', j->f);
		newline(j);
	}
	j->first[j->depth] = 0;
}

static void open(struct json *j, char c)
{
	pre_value(j);
	fputc(c, j->f);
	if (j->depth < 63)
		j->depth++;
	j->first[j->depth] = 1;
}

static void close(struct json *j, char c)
{
	int empty = j->first[j->depth];
	if (j->depth > 0)
		j->depth--;
	if (!empty)
		newline(j);
	fputc(c, j->f);
}

void json_object_begin(struct json *j) { open(j, '{'); }
void json_object_end(struct json *j) { close(j, '}'); }
void json_array_begin(struct json *j) { open(j, '['); }
void json_array_end(struct json *j) { close(j, ']'); }

/* A JSON string: control characters (C0, DEL, C1) as \u escapes, so
 * that the text is safe on a terminal too; bytes that are not valid
 * UTF-8 (a path can hold any byte) as U+FFFD, so that the document is
 * valid JSON whatever the input. */
static void put_string(FILE *f, const char *s)
{
	fputc('"', f);
	for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
		int n = text_utf8_len(p);
		if (n == 0) {
			fputs("\\ufffd", f);
			continue;
		}
		if (n == 2 && p[0] == 0xc2 && p[1] < 0xa0) {
			fprintf(f, "\\u%04x", p[1]);
			p++;
			continue;
		}
		if (n > 1) {
			fwrite(p, 1, (size_t)n, f);
			p += n - 1;
			continue;
		}
		switch (*p) {
		case '"': fputs("\\\"", f); break;
		case '\\': fputs("\\\\", f); break;
		case '\n': fputs("\\n", f); break;
		case '\r': fputs("\\r", f); break;
		case '\t': fputs("\\t", f); break;
		default:
			if (*p < 0x20 || *p == 0x7f)
				fprintf(f, "\\u%04x", *p);
			else
				fputc(*p, f);
		}
	}
	fputc('"', f);
}

void json_key(struct json *j, const char *k)
{
	pre_value(j);
	put_string(j->f, k);
	fputs(j->indent ? ": " : ":", j->f);
	j->after_key = 1;
}

void json_string(struct json *j, const char *s)
{
	pre_value(j);
	put_string(j->f, s ? s : "");
}

void json_double(struct json *j, double v)
{
	pre_value(j);
	if (!isfinite(v))
		fputs("null", j->f);
	else if (v == 0)
		fputs("0", j->f);	/* no "-0" */
	else {
		/* the shortest of 15..17 digits that reads back exactly */
		char buf[40];
		for (int prec = 15; prec <= 17; prec++) {
			snprintf(buf, sizeof buf, "%.*g", prec, v);
			if (strtod(buf, NULL) == v)
				break;
		}
		fputs(buf, j->f);
	}
}

void json_int(struct json *j, long long v)
{
	pre_value(j);
	fprintf(j->f, "%lld", v);
}

void json_uint(struct json *j, unsigned long long v)
{
	pre_value(j);
	fprintf(j->f, "%llu", v);
}

void json_bool(struct json *j, int v)
{
	pre_value(j);
	fputs(v ? "true" : "false", j->f);
}

void json_null(struct json *j)
{
	pre_value(j);
	fputs("null", j->f);
}

void json_end(struct json *j)
{
	fputc('\n', j->f);
	fflush(j->f);
}

void json_key_string(struct json *j, const char *k, const char *s)
{
	json_key(j, k);
	json_string(j, s);
}

void json_key_double(struct json *j, const char *k, double v)
{
	json_key(j, k);
	json_double(j, v);
}

void json_key_int(struct json *j, const char *k, long long v)
{
	json_key(j, k);
	json_int(j, v);
}
