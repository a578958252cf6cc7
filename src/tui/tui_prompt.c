/*
 * tui_prompt.c - the prompt line of the main screen: a label, a text
 * being typed, and what to do with it on Enter (a tui_prompt_done
 * callback: an edit typed in, a path to save to).  While t->prompting,
 * the main screen hands every key here (tui_home.c) and draws the line
 * with tui_prompt_draw.
 */
#include <stdio.h>
#include <string.h>

#include <curses.h>

#include "tui.h"

void tui_prompt(struct tui *t, const char *label, const char *initial,
		tui_prompt_done done)
{
	t->prompting = 1;
	snprintf(t->plabel, sizeof t->plabel, "%s", label);
	snprintf(t->pbuf, sizeof t->pbuf, "%s", initial ? initial : "");
	t->plen = (int)strlen(t->pbuf);
	t->pdone = done;
}

void tui_prompt_key(struct tui *t, int ch)
{
	if (ch == '\n' || ch == '\r' || ch == KEY_ENTER) {
		char text[sizeof t->pbuf];
		memcpy(text, t->pbuf, sizeof text);
		t->prompting = 0;
		t->pdone(t, text);
	} else if (ch == 27 || ch == 7) {	/* Esc, Ctrl-G */
		t->prompting = 0;
		tui_message(t, 0, "cancelled");
	} else if (ch == KEY_BACKSPACE || ch == 127 || ch == 8) {
		/* remove one UTF-8 character */
		while (t->plen > 0 &&
		       ((unsigned char)t->pbuf[--t->plen] & 0xc0) == 0x80)
			;
		t->pbuf[t->plen] = 0;
	} else if (ch == 21) {			/* Ctrl-U */
		t->plen = 0;
		t->pbuf[0] = 0;
	} else if (ch >= 32 && ch < 256 && ch != 127 &&
		   t->plen < (int)sizeof t->pbuf - 1) {
		t->pbuf[t->plen++] = (char)ch;
		t->pbuf[t->plen] = 0;
	}
}

void tui_prompt_draw(struct tui *t, int y)
{
	char buf[PATH_MAX + 128];
	int C = t->cols;
	/* the end of a long text stays in view */
	const char *p = t->pbuf;
	int room = C - 3 - (int)strlen(t->plabel) - 2;
	while ((int)strlen(p) > room && *p)
		p++;
	snprintf(buf, sizeof buf, "%s: %s", t->plabel, p);
	attron(A_BOLD);
	tui_text(y, 0, C - 1, buf);
	attroff(A_BOLD);
	int len = (int)strlen(buf);
	if (len < C - 1) {
		attron(A_REVERSE);
		mvaddch(y, len, ' ');
		attroff(A_REVERSE);
	}
}
