/*
 * test_json.c - the JSON writer (include/slipwall/json.h): what it
 * promises, one check each.  Nesting and commas (compact and indented,
 * empty containers, arrays of arrays), string escapes (quote, backslash,
 * \n \r \t, other control characters as \u00XX, C1 and DEL, valid UTF-8
 * kept, invalid bytes as \ufffd, keys escaped as values), doubles (the
 * shortest of 15..17 digits that reads back, 0 and -0 as "0", NaN and
 * the infinities as null), integers at their limits, and the helpers.
 * Every check prints what was written when it fails.
 */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/json.h"
#include "tap.h"

/* An in-memory writer: jbegin, the calls, jend returns the text (the
 * caller frees it). */
static FILE *jf;
static char *jbuf;
static size_t jlen;

static struct json *jbegin(int indent)
{
	static struct json j;
	jf = open_memstream(&jbuf, &jlen);
	json_init(&j, jf, indent);
	return &j;
}

static char *jend(struct json *j)
{
	json_end(j);
	fclose(jf);
	return jbuf;
}

/* got == want, named; on a failure both are shown */
static void same(char *got, const char *want, const char *name)
{
	if (!tap_ok(got && !strcmp(got, want), "%s", name)) {
		tap_diag("got:  %s", got ? got : "(nothing)");
		tap_diag("want: %s", want);
	}
	free(got);
}

/* What json_double writes for v (no newline) */
static char *dbl(double v)
{
	struct json *j = jbegin(0);
	json_double(j, v);
	char *s = jend(j);
	s[strcspn(s, "\n")] = 0;
	return s;
}

static void test_nesting(void)
{
	struct json *j = jbegin(0);
	json_object_begin(j);
	json_key(j, "a");
	json_array_begin(j);
	json_double(j, 0.1);
	json_double(j, 1.0 / 3);
	json_double(j, NAN);
	json_int(j, -7);
	json_array_end(j);
	json_key(j, "s\"q");
	json_string(j, "line\nbreak\\");
	json_key(j, "e");
	json_object_begin(j);
	json_object_end(j);
	json_key(j, "b");
	json_bool(j, 1);
	json_object_end(j);
	same(jend(j), "{\"a\":[0.1,0.3333333333333333,null,-7],"
	     "\"s\\\"q\":\"line\\nbreak\\\\\",\"e\":{},\"b\":true}\n",
	     "compact: an object of an array, an escaped key, an empty "
	     "object, a bool; commas only between values");

	j = jbegin(0);
	json_array_begin(j);
	json_array_begin(j);
	json_int(j, 1);
	json_int(j, 2);
	json_array_end(j);
	json_array_begin(j);
	json_array_end(j);
	json_array_begin(j);
	json_object_begin(j);
	json_key_int(j, "k", 3);
	json_object_end(j);
	json_null(j);
	json_array_end(j);
	json_array_end(j);
	same(jend(j), "[[1,2],[],[{\"k\":3},null]]\n",
	     "arrays of arrays: a comma after each inner array, none after "
	     "an empty one's opening");

	j = jbegin(0);
	json_object_begin(j);
	json_object_end(j);
	same(jend(j), "{}\n", "an empty top-level object, then a newline");

	j = jbegin(0);
	json_int(j, 5);
	same(jend(j), "5\n", "a bare top-level value");

	j = jbegin(1);
	json_object_begin(j);
	json_key(j, "a");
	json_array_begin(j);
	json_int(j, 1);
	json_int(j, 2);
	json_array_end(j);
	json_key(j, "e");
	json_array_begin(j);
	json_array_end(j);
	json_key_string(j, "s", "x");
	json_object_end(j);
	same(jend(j), "{\n  \"a\": [\n    1,\n    2\n  ],\n  \"e\": [],\n"
	     "  \"s\": \"x\"\n}\n",
	     "indented: 2 spaces a level, \": \" after keys, empty "
	     "containers on one line");

	/* deeper than the 63 levels the writer tracks: still one bracket
	 * of each per level, and nothing written out of bounds */
	j = jbegin(0);
	for (int i = 0; i < 70; i++)
		json_array_begin(j);
	for (int i = 0; i < 70; i++)
		json_array_end(j);
	char *s = jend(j), want[160];
	memset(want, '[', 70);
	memset(want + 70, ']', 70);
	strcpy(want + 140, "\n");
	same(s, want, "70 nested empty arrays (past the 63 tracked levels): "
	     "70 '[' then 70 ']'");
}

static void test_strings(void)
{
	struct json *j = jbegin(0);
	json_string(j, "q\" b\\ n\n r\r t\t /");
	same(jend(j), "\"q\\\" b\\\\ n\\n r\\r t\\t /\"\n",
	     "string: quote, backslash, \\n, \\r, \\t escaped; '/' as it is");

	j = jbegin(0);
	json_string(j, "\x01\x1f\x1b[2J\x7f");
	same(jend(j), "\"\\u0001\\u001f\\u001b[2J\\u007f\"\n",
	     "string: other C0 controls, ESC and DEL as \\u00XX");

	j = jbegin(0);
	json_string(j, "\xc2\x85|\xc2\x9b|\xc2\xa0|\xc3\xa9|\xe2\x82\xac|"
		    "\xf0\x9f\x98\x80");
	same(jend(j), "\"\\u0085|\\u009b|\xc2\xa0|\xc3\xa9|\xe2\x82\xac|"
	     "\xf0\x9f\x98\x80\"\n",
	     "string: C1 controls (U+0085, U+009B) as \\u00XX; valid UTF-8 "
	     "(U+00A0, U+00E9, U+20AC, U+1F600) kept as it is");

	j = jbegin(0);
	json_string(j, "a\xff" "b\xc3" "c\xe2\x82");
	same(jend(j), "\"a\\ufffdb\\ufffdc\\ufffd\\ufffd\"\n",
	     "string: bytes that are not UTF-8 (0xff, a cut 2-byte and "
	     "3-byte sequence) as \\ufffd, one per byte");

	j = jbegin(0);
	json_string(j, NULL);
	same(jend(j), "\"\"\n", "string: NULL is written as \"\"");

	j = jbegin(0);
	json_object_begin(j);
	json_key_string(j, "t\tab\x01", "v");
	json_object_end(j);
	same(jend(j), "{\"t\\tab\\u0001\":\"v\"}\n",
	     "keys are escaped as strings are");
}

static void test_doubles(void)
{
	static const struct {
		double v;
		const char *want;
	} t[] = {
		{ 0.1, "0.1" },
		{ -2.5, "-2.5" },
		{ 1.0 / 3, "0.3333333333333333" },		/* 16 digits */
		{ 0.1 + 0.2, "0.30000000000000004" },		/* 17 */
		{ 1e21, "1e+21" },
		{ 1e300, "1e+300" },
		{ 123456789012345.0, "123456789012345" },	/* 15 */
		{ 9007199254740993.0, "9007199254740992" },	/* 2^53 + 1 rounds */
		{ 5e-324, "4.94065645841247e-324" },		/* least subnormal */
		{ 1.7976931348623157e308, "1.7976931348623157e+308" },
		{ 0.0, "0" },
		{ -0.0, "0" },
		{ NAN, "null" },
		{ INFINITY, "null" },
		{ -INFINITY, "null" },
	};
	for (size_t i = 0; i < sizeof t / sizeof t[0]; i++) {
		char *s = dbl(t[i].v);
		if (!tap_ok(!strcmp(s, t[i].want), "double %.17g -> %s",
			    t[i].v, t[i].want))
			tap_diag("got %s", s);
		free(s);
	}

	/* every finite value reads back exactly, in at most 17 digits */
	int ok = 1, worst = 0;
	double bad = 0;
	unsigned long long x = 88172645463325252ULL;
	for (int i = 0; i < 20000 && ok; i++) {
		x ^= x << 13;
		x ^= x >> 7;
		x ^= x << 17;
		double v;
		memcpy(&v, &x, sizeof v);
		if (!isfinite(v))
			continue;
		char *s = dbl(v);
		int digits = 0, lead = 1;	/* significant: from the first
						 * non-zero digit */
		for (const char *p = s; *p && *p != 'e'; p++) {
			if (*p >= '1' && *p <= '9')
				lead = 0;
			digits += !lead && *p >= '0' && *p <= '9';
		}
		if (v != 0 && (strtod(s, NULL) != v || digits > 17)) {
			ok = 0;
			bad = v;
		}
		if (digits > worst)
			worst = digits;
		free(s);
	}
	tap_ok(ok, "20,000 random bit patterns: each finite double reads "
	       "back exactly, at most %d significant digits written%s", worst,
	       ok ? "" : " (failed)");
	if (!ok)
		tap_diag("first failure: %.17g", bad);
}

static void test_scalars(void)
{
	struct json *j = jbegin(0);
	json_array_begin(j);
	json_int(j, LLONG_MIN);
	json_int(j, LLONG_MAX);
	json_uint(j, ULLONG_MAX);
	json_bool(j, 0);
	json_bool(j, 7);
	json_null(j);
	json_array_end(j);
	same(jend(j), "[-9223372036854775808,9223372036854775807,"
	     "18446744073709551615,false,true,null]\n",
	     "integers at their limits (json_uint up to 2^64 - 1), bools "
	     "(any non-zero is true), null");

	j = jbegin(0);
	json_object_begin(j);
	json_key_string(j, "s", "v");
	json_key_double(j, "d", INFINITY);
	json_key_double(j, "e", 2.0);
	json_key_int(j, "i", -1);
	json_object_end(j);
	same(jend(j), "{\"s\":\"v\",\"d\":null,\"e\":2,\"i\":-1}\n",
	     "json_key_string, _double, _int: a key and its value, commas "
	     "between pairs");
}

int main(void)
{
	test_nesting();
	test_strings();
	test_doubles();
	test_scalars();
	return tap_done();
}
