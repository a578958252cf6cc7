/*
 * tui_meaning.c - the help's second page, "what the numbers mean"
 * (tui_help.c shows it; Tab switches pages): λ_min, p05 and its
 * interval, standard and gilbert, the mechanism letters and the
 * rejection reasons, short and plain.  What it says is what
 * docs/method.md ("One sample", "Single-solution methods", "Rejection
 * reasons") and docs/statistics.md ("The characteristic value and its
 * 99 % interval") say at length.  The letters come from sample.h's
 * JOINT_* and the reasons from its SAMPLE_STATUS_TABLE (through
 * sample_status_name and sample_status_text), so a new reason shows up
 * here without an edit of this file.
 */
#include <stdio.h>

#include "slipwall/sample.h"
#include "tui.h"

/* The page's fixed lines; "%L" is replaced by "λ" (or "lam"), a tab
 * pads to the column of the text (TUI_MEANING_COL). */
static const char *const tui_meaning_text[] = {
	"%L_min\tone sample's collapse load: the least load at which the mechanism",
	"          it finds can start (docs/method.md).  Each sample draws its own",
	"          contact points (and friction, when random), hence its own %L_min;",
	"          in N for a point load.  Only accepted samples are counted.",
	"p05\tthe characteristic value: 5 % of the accepted %L_min lie below it.",
	"          Its 99 % interval [lo, hi]: two of the sorted loads that hold the",
	"          true p05 between them with 99 % probability or more, whatever",
	"          the distribution; from 90 accepted samples (docs/statistics.md).",
	"standard\tone solution, contact points at the joints' ends, friction that",
	"          dilates (associative): an upper value; S on the histogram axis.",
	"gilbert\tthe same contact points, friction that does not dilate (solved",
	"          as a sample is): G on the histogram axis.",
	"",
	"Mechanism letters, one per joint in the order of the interfaces:",
};

#define TUI_MEANING_TEXT ((int)(sizeof tui_meaning_text / sizeof *tui_meaning_text))
#define TUI_MEANING_COL 10

/* The letters, two lines (sample.h's JOINT_*). */
#define TUI_MEANING_JOINTS 2

/* text with %L replaced by the locale's lambda, a tab padded */
static void tui_meaning_fill(const struct tui *t, const char *text, char *buf,
			     size_t len)
{
	size_t n = 0;
	buf[0] = 0;
	for (const char *p = text; *p && n + 1 < len; p++) {
		if (p[0] == '%' && p[1] == 'L') {
			n += (size_t)snprintf(buf + n, len - n, "%s", tui_lam(t));
			p++;
		} else if (*p == '\t') {
			int pad = TUI_MEANING_COL - tui_cols(buf);
			n += (size_t)snprintf(buf + n, len - n, "%*s",
					      pad > 1 ? pad : 1, "");
		} else {
			buf[n++] = *p;
			buf[n] = 0;
		}
		if (n >= len)
			n = len - 1;
	}
}

int tui_meaning_line(const struct tui *t, int line, char *buf, size_t len)
{
	buf[0] = 0;
	if (line < TUI_MEANING_TEXT) {
		tui_meaning_fill(t, tui_meaning_text[line], buf, len);
		return 1;
	}
	line -= TUI_MEANING_TEXT;
	if (line == 0) {
		snprintf(buf, len, "  %c closed   %c slides   %c hinges (one point "
			 "opens, it turns about the other)", JOINT_CLOSED,
			 JOINT_SLIDES, JOINT_HINGES);
		return 1;
	}
	if (line == 1) {
		snprintf(buf, len, "  %c hinges and slides   %c opens (both points "
			 "open: the blocks separate)", JOINT_HINGE_SLIDES,
			 JOINT_OPENS);
		return 1;
	}
	line -= TUI_MEANING_JOINTS;
	if (line == 0)
		return 1;	/* a blank */
	if (line == 1) {
		snprintf(buf, len, "Rejected samples, by reason (the samples "
			 "file's status: what it means):");
		return 1;
	}
	line -= 2;	/* the reasons: every status but accepted */
	for (int s = 0; s < SAMPLE_STATUS_COUNT; s++) {
		if (s == SAMPLE_ACCEPTED || line-- > 0)
			continue;
		snprintf(buf, len, "  %-15s %s",
			 sample_status_name((enum sample_status)s),
			 sample_status_text((enum sample_status)s));
		return 1;
	}
	return 0;
}
