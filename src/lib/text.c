/* text.c - bounded line reading and printable names; see text.h. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "slipwall/status.h"
#include "slipwall/text.h"

enum text_line text_getline(FILE *f, char **line, size_t *cap, size_t max,
			    size_t *len)
{
	size_t n = 0;
	int c;
	errno = 0;
	flockfile(f);
	while ((c = getc_unlocked(f)) != EOF && c != '\n') {
		if (n >= max) {
			funlockfile(f);
			*len = n;
			return TEXT_LINE_LONG;
		}
		if (n + 2 > *cap) {
			size_t nc = *cap ? 2 * *cap : 256;
			while (nc < n + 2)
				nc *= 2;
			*line = sw_xrealloc(*line, nc);
			*cap = nc;
		}
		if (c == 0)
			break;	/* not text: stop reading at once */
		(*line)[n++] = (char)c;
	}
	int err = ferror(f);
	funlockfile(f);
	if (!*line) {
		*line = sw_xmalloc(1);
		*cap = 1;
	}
	(*line)[n] = 0;
	*len = n;
	if (c == EOF && err)
		return TEXT_LINE_ERROR;
	if (c == 0)
		return TEXT_LINE_NUL;
	if (c == EOF)
		return n ? TEXT_LINE_CUT : TEXT_LINE_EOF;
	return TEXT_LINE_OK;
}

int text_utf8_len(const unsigned char *s)
{
	unsigned c = s[0];
	int n;
	unsigned min;
	if (c < 0x80)
		return 1;
	if (c >= 0xc2 && c <= 0xdf) {
		n = 2;
		min = 0x80;
	} else if (c >= 0xe0 && c <= 0xef) {
		n = 3;
		min = 0x800;
	} else if (c >= 0xf0 && c <= 0xf4) {
		n = 4;
		min = 0x10000;
	} else {
		return 0;
	}
	unsigned cp = c & (0x3fu >> (n - 1));
	for (int i = 1; i < n; i++) {
		if ((s[i] & 0xc0) != 0x80)
			return 0;
		cp = cp << 6 | (s[i] & 0x3fu);
	}
	if (cp < min || cp > 0x10ffff || (cp >= 0xd800 && cp <= 0xdfff))
		return 0;
	return n;
}

/* The escape of the byte or character at s into out (at least 5 bytes),
 * or 0 when it prints as it is; *used gets the bytes of s it covers. */
static int escape_at(const unsigned char *s, char *out, int *used)
{
	int n = text_utf8_len(s);
	*used = n ? n : 1;
	if (n == 1 && s[0] >= 0x20 && s[0] != 0x7f)
		return 0;
	if (n == 2 && s[0] == 0xc2 && s[1] < 0xa0) {	/* C1 controls */
		snprintf(out, 5, "\\x%02x", s[1]);
		return 1;
	}
	if (n > 1)
		return 0;
	switch (s[0]) {
	case 0x1b: strcpy(out, "\\e"); break;
	case '\a': strcpy(out, "\\a"); break;
	case '\n': strcpy(out, "\\n"); break;
	case '\r': strcpy(out, "\\r"); break;
	case '\t': strcpy(out, "\\t"); break;
	default: snprintf(out, 5, "\\x%02x", s[0]);
	}
	return 1;
}

int text_is_clean(const char *s)
{
	char e[8];
	int used;
	for (const unsigned char *p = (const unsigned char *)s; *p; p += used)
		if (escape_at(p, e, &used))
			return 0;
	return 1;
}

char *text_clean(const char *s)
{
	size_t n = strlen(s);
	char *out = sw_xmalloc(4 * n + 1), *o = out;
	char e[8];
	int used;
	for (const unsigned char *p = (const unsigned char *)s; *p; p += used) {
		if (escape_at(p, e, &used)) {
			size_t k = strlen(e);
			memcpy(o, e, k);
			o += k;
		} else {
			memcpy(o, p, (size_t)used);
			o += used;
		}
	}
	*o = 0;
	return out;
}

size_t text_bom(const char *s, size_t len)
{
	return len >= 3 && !memcmp(s, "\xef\xbb\xbf", 3) ? 3 : 0;
}

char *text_num(char *buf, size_t len, double v, int prec)
{
	if (isfinite(v))
		snprintf(buf, len, "%.*g", prec, v);
	else
		snprintf(buf, len, "-");
	return buf;
}

int text_is_decimal(const char *s)
{
	int digits = 0;
	if (*s == '+' || *s == '-')
		s++;
	for (; isdigit((unsigned char)*s); s++)
		digits++;
	if (*s == '.')
		for (s++; isdigit((unsigned char)*s); s++)
			digits++;
	if (!digits)
		return 0;
	if (*s == 'e' || *s == 'E') {
		s++;
		if (*s == '+' || *s == '-')
			s++;
		if (!isdigit((unsigned char)*s))
			return 0;
		while (isdigit((unsigned char)*s))
			s++;
	}
	return *s == '\0';
}

int text_parse_long(const char *s, long lo, long hi, long *out)
{
	/* digits only, a sign first: strtol also skips spaces */
	const char *d = s + (*s == '+' || *s == '-');
	if (!isdigit((unsigned char)*d) || strspn(d, "0123456789") != strlen(d))
		return -1;
	char *end;
	errno = 0;
	long v = strtol(s, &end, 10);
	if (errno || end == s || *end || v < lo || v > hi)
		return -1;
	*out = v;
	return 0;
}

int text_parse_double(const char *s, double *out)
{
	if (!text_is_decimal(s))
		return -1;
	/* ERANGE on underflow is fine, as in the wall file (1e-400 is 0);
	 * an overflow gives an infinity */
	char *end;
	double v = strtod(s, &end);
	if (end == s || *end || !isfinite(v))
		return -1;
	*out = v;
	return 0;
}
