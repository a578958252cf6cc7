/*
 * json.h - a small streaming JSON writer (no DOM).
 *
 * The caller opens objects and arrays and names keys; the writer keeps
 * the commas and the nesting right (at most 63 levels are tracked) and
 * prints each double with the fewest of 15, 16 or 17 significant digits
 * that read back to the same double (0 and -0 as "0"; NaN and
 * infinities become null).  Strings are escaped: '"', '\\', \n, \r, \t,
 * the other control characters (C0, DEL, C1) as \u00XX, bytes that are
 * not valid UTF-8 as \ufffd; a NULL string is written as "".
 */
#ifndef SLIPWALL_JSON_H
#define SLIPWALL_JSON_H

#include <stdio.h>

struct json {
	FILE *f;
	int depth;
	int first[64];		/* per level: nothing written yet */
	int after_key;
	int indent;		/* pretty-print with 2 spaces */
};

void json_init(struct json *j, FILE *f, int indent);
void json_object_begin(struct json *j);
void json_object_end(struct json *j);
void json_array_begin(struct json *j);
void json_array_end(struct json *j);
void json_key(struct json *j, const char *k);
void json_string(struct json *j, const char *s);
void json_double(struct json *j, double v);
void json_int(struct json *j, long long v);
/* An unsigned integer written exactly (seeds: up to 2^64 - 1). */
void json_uint(struct json *j, unsigned long long v);
void json_bool(struct json *j, int v);
void json_null(struct json *j);
/* Finish: newline after the top-level value. */
void json_end(struct json *j);

/* A key and its value: json_key() then json_string(), json_double(),
 * json_int(). */
void json_key_string(struct json *j, const char *k, const char *s);
void json_key_double(struct json *j, const char *k, double v);
void json_key_int(struct json *j, const char *k, long long v);

#endif
