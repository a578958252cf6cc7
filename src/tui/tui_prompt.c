/*
 * tui_prompt.c - the prompt line of the main screen: a label, a text
 * being typed, and what to do with it on Enter (a tui_prompt_done
 * callback: an edit typed in, a path to save to).  While t->prompting,
 * the main screen hands the prompt's keys of the key table (tui_keys.c:
 * Enter, Esc, Backspace, Ctrl-U) to their handlers here and every other
 * key to tui_prompt_type, and draws the line with tui_prompt_draw.
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
	t->pcomp[0] = 0;
	t->pcands_on = 0;
}

void tui_prompt_accept(struct tui *t, int ch)
{
	char text[sizeof t->pbuf];
	(void)ch;
	memcpy(text, t->pbuf, sizeof text);
	t->prompting = 0;
	t->pdone(t, text);
}

void tui_prompt_cancel(struct tui *t, int ch)
{
	(void)ch;
	t->prompting = 0;
	tui_message(t, 0, "cancelled");
}

void tui_prompt_erase(struct tui *t, int ch)
{
	(void)ch;
	/* remove one UTF-8 character */
	while (t->plen > 0 && ((unsigned char)t->pbuf[--t->plen] & 0xc0) == 0x80)
		;
	t->pbuf[t->plen] = 0;
}

void tui_prompt_clear(struct tui *t, int ch)
{
	(void)ch;
	t->plen = 0;
	t->pbuf[0] = 0;
}

void tui_prompt_type(struct tui *t, int ch)
{
	if (ch >= 32 && ch < 256 && ch != 127 &&
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
	if (t->pcands_on && y > 0 && !strcmp(t->pcomp, t->pbuf)) {
		move(y - 1, 0);	/* Tab's candidates (tui_complete.c) */
		clrtoeol();
		tui_text(y - 1, 0, C - 1, t->pcands);
	}
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
