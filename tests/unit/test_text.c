/*
 * test_text.c - numbers as people write them (text_parse_long,
 * text_parse_double, text_is_decimal: the options' and the wall file's
 * rule), text_bom (the wall, tests and samples files' readers) and
 * text_clean (what reaches a terminal) and text_num (a statistic in a
 * table, or "-" where it has no value).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/text.h"
#include "tap.h"

static void test_decimal(void)
{
	const char *yes[] = {"0", "5", "-5", "+5", "0.25", ".5", "5.", "1e3",
			     "1E-3", "-2.5e+10", "1e-400"};
	const char *no[] = {"", " 5", "5 ", "0x10", "0x0.4p0", "inf", "nan",
			    "-inf", "1e", "e5", ".", "+", "5,0", "1_000",
			    "5\n"};
	for (size_t k = 0; k < sizeof yes / sizeof *yes; k++)
		tap_ok(text_is_decimal(yes[k]), "'%s' is a decimal", yes[k]);
	for (size_t k = 0; k < sizeof no / sizeof *no; k++) {
		char *c = text_clean(no[k]);
		tap_ok(!text_is_decimal(no[k]), "'%s' is not", c);
		free(c);
	}
}

static void test_parse(void)
{
	double d = -1;
	tap_ok(text_parse_double("0.4", &d) == 0 && d == 0.4, "0.4 reads");
	d = -1;
	tap_ok(text_parse_double("1e-400", &d) == 0 && d == 0,
	       "1e-400 reads as 0 (an underflow, as the wall file reads it)");
	d = -1;
	tap_ok(text_parse_double("0x0.4p0", &d) == -1 && d == -1,
	       "hexadecimal is refused, *out untouched");
	tap_ok(text_parse_double("1e400", &d) == -1, "1e400 (infinite) is refused");
	tap_ok(text_parse_double(" 0.4", &d) == -1, "a leading space is refused");
	long l = -1;
	tap_ok(text_parse_long("12", 0, 100, &l) == 0 && l == 12, "12 reads");
	tap_ok(text_parse_long("+12", 0, 100, &l) == 0 && l == 12, "+12 reads");
	l = -1;
	tap_ok(text_parse_long(" 5", 0, 100, &l) == -1 && l == -1,
	       "' 5' is refused (strtol skips the space)");
	tap_ok(text_parse_long("0x10", 0, 100, &l) == -1, "0x10 is refused");
	tap_ok(text_parse_long("5.0", 0, 100, &l) == -1, "5.0 is not whole");
	tap_ok(text_parse_long("101", 0, 100, &l) == -1, "101 is out of range");
	tap_ok(text_parse_long("-", 0, 100, &l) == -1, "a sign alone is refused");
}

static void test_bom(void)
{
	tap_ok(text_bom("\xef\xbb\xbfsample", 9) == 3, "a UTF-8 byte-order mark is 3 bytes");
	tap_ok(text_bom("\xef\xbb", 2) == 0, "two of its bytes are none");
	tap_ok(text_bom("sample", 6) == 0, "text without one: 0");
}

static void test_clean(void)
{
	char *c = text_clean("a\033[2Jb\nc\td");
	tap_ok(!strcmp(c, "a\\e[2Jb\\nc\\td"), "escape, newline and tab are shown, "
	       "not sent (%s)", c);
	free(c);
	c = text_clean("λ ≤ 0.5");
	tap_ok(!strcmp(c, "λ ≤ 0.5"), "UTF-8 passes as it is");
	free(c);
}

static void test_num(void)
{
	char b[32];
	tap_ok(!strcmp(text_num(b, sizeof b, 283.375049, 6), "283.375"),
	       "6 significant digits (%s)", b);
	tap_ok(!strcmp(text_num(b, sizeof b, 0.000123456, 3), "0.000123"),
	       "3 of a small value (%s)", b);
	tap_ok(!strcmp(text_num(b, sizeof b, NAN, 6), "-"),
	       "no value (NaN: no accepted sample) is '-' (%s)", b);
	tap_ok(!strcmp(text_num(b, sizeof b, INFINITY, 6), "-") &&
	       !strcmp(text_num(b, sizeof b, -INFINITY, 6), "-"),
	       "an infinite value is '-' too, never 'inf'");
	char tiny[4];
	tap_ok(!strcmp(text_num(tiny, sizeof tiny, 123456, 6), "123"),
	       "a short buffer is cut, not overrun (%s)", tiny);
}

int main(void)
{
	test_decimal();
	test_parse();
	test_bom();
	test_clean();
	test_num();
	return tap_done();
}
