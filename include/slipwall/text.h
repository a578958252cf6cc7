/*
 * text.h - text in and out: lines read with a bound, and names made
 * safe to print.
 *
 * Reading: text_getline() is getline(3) with a limit on the length of a
 * line, so that a file without line ends (/dev/zero, a binary file)
 * costs a bounded amount of memory and gives a message instead of
 * growing until the machine swaps.  It also says whether the line ended
 * with '\n' (a samples file's last row without one was cut by a kill).
 *
 * Printing: names, ids and paths come from files and command lines and
 * may hold control characters (ESC, BEL, a newline) or invalid UTF-8.
 * text_clean() returns a copy that is safe on a terminal and in CSV,
 * Markdown and JSON text: every control character (C0, DEL and the C1
 * range U+0080..U+009F) and every byte that is not part of valid UTF-8
 * becomes a visible escape, \e, \a, \n, \t, \r or \xNN; valid UTF-8
 * text is kept as it is.  text_num() prints a statistic, or "-" where
 * it has no value.
 */
#ifndef SLIPWALL_TEXT_H
#define SLIPWALL_TEXT_H

#include <stddef.h>
#include <stdio.h>

enum text_line {
	TEXT_LINE_EOF = 0,	/* nothing more */
	TEXT_LINE_OK = 1,	/* a line, *len bytes, '\n' not included */
	TEXT_LINE_CUT = 2,	/* a last line without '\n' */
	TEXT_LINE_LONG = -1,	/* more than max bytes without a '\n' */
	TEXT_LINE_NUL = -2,	/* a NUL byte in the line (reading stops) */
	TEXT_LINE_ERROR = -3,	/* a read error: errno */
};

/* Read the next line of f into *line (malloc'd, grown as needed, NUL
 * terminated, '\n' removed; *cap its size) of at most max bytes.
 * *len gets its length; on TEXT_LINE_NUL, the offset of the NUL byte,
 * where reading stopped. */
enum text_line text_getline(FILE *f, char **line, size_t *cap, size_t max,
			    size_t *len);

/* A printable copy of s (see above), malloc'd: the caller frees it. */
char *text_clean(const char *s);
/* Is s printable as it is (text_clean would not change it)? */
int text_is_clean(const char *s);
/* Length of the valid UTF-8 sequence at s (1..4), 0 if there is none. */
int text_utf8_len(const unsigned char *s);

/* v with prec significant digits ("%.*g") into buf, or "-" where v
 * is not a number or not finite (a statistic without its values: no
 * accepted sample, the standard deviation of one value); returns buf,
 * for use inside a printf.  The tables and panes for people use it;
 * the CSV and JSON files write nan and null instead. */
char *text_num(char *buf, size_t len, double v, int prec);

/* Parse a whole number in [lo, hi] / a finite double: the whole of s,
 * decimal as people write it (text_is_decimal: no spaces, no
 * hexadecimal, infinity or NaN, which strtod also reads); 0 on
 * success, -1 (and *out untouched) otherwise. */
int text_parse_long(const char *s, long lo, long hi, long *out);
int text_parse_double(const char *s, double *out);
/* The length of a UTF-8 byte-order mark at the start of s (len bytes),
 * as some editors and spreadsheets write one: 3, or 0 without one. */
size_t text_bom(const char *s, size_t len);
/* Is s a decimal number: [-+]digits[.digits][(e|E)[-+]digits], with
 * some digit?  The wall file's numbers and the options' alike. */
int text_is_decimal(const char *s);

#endif
