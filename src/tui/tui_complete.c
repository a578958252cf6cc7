/*
 * tui_complete.c - Tab in a path prompt (save, report, open): the file
 * names of the prompt's text completed as a shell completes them
 * (issue 27).
 *
 * The text is a path: its directory part (up to the last '/', "." when
 * none; a leading "~/" is $HOME) is read with readdir, and the names
 * that begin with the rest are the candidates (names beginning with a
 * dot only when the rest does).  One candidate: the text becomes it,
 * with a '/' after a directory.  More: the text grows to their longest
 * common prefix; a second Tab that could not make it grow lists them on
 * the line above the prompt (tui_prompt_draw draws t->pcands while the
 * text is still t->pcomp), sorted, as many as fit.  None: the message
 * says so.  Only the UI thread runs this; a directory is read once per
 * Tab, at most TUI_COMPLETE_MAX names of it kept.
 */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "tui.h"

#define TUI_COMPLETE_MAX 4096	/* candidates kept from one directory */

static int tui_complete_cmp(const void *a, const void *b)
{
	return strcmp(*(char *const *)a, *(char *const *)b);
}

/* Is dir/name a directory (through a symbolic link)? */
static int tui_complete_isdir(const char *dir, const char *name)
{
	char p[PATH_MAX];
	struct stat st;
	if ((size_t)snprintf(p, sizeof p, "%s/%s", dir, name) >= sizeof p)
		return 0;
	return stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}

void tui_prompt_complete(struct tui *t, int ch)
{
	char dir[PATH_MAX], head[PATH_MAX];
	const char *base;
	(void)ch;
	/* head: the text up to and with its last '/'; dir: where to look */
	const char *slash = strrchr(t->pbuf, '/');
	if (slash) {
		size_t hl = (size_t)(slash - t->pbuf) + 1;
		memcpy(head, t->pbuf, hl);
		head[hl] = 0;
		base = slash + 1;
	} else {
		head[0] = 0;
		base = t->pbuf;
	}
	const char *home = getenv("HOME");
	if (!strncmp(head, "~/", 2) && home && home[0])
		snprintf(dir, sizeof dir, "%s/%s", home, head + 2);
	else
		snprintf(dir, sizeof dir, "%s", head[0] ? head : ".");

	DIR *d = opendir(dir);
	if (!d) {
		tui_message(t, 1, "Tab: cannot read %s", dir);
		return;
	}
	char **c = NULL;
	int n = 0, cap = 0;
	size_t bl = strlen(base);
	struct dirent *e;
	while ((e = readdir(d)) && n < TUI_COMPLETE_MAX) {
		const char *nm = e->d_name;
		if (!strcmp(nm, ".") || !strcmp(nm, "..") ||
		    strncmp(nm, base, bl) || (nm[0] == '.' && base[0] != '.'))
			continue;
		if (n == cap) {
			cap = cap ? 2 * cap : 32;
			char **v = realloc(c, sizeof *c * (size_t)cap);
			if (!v)
				break;
			c = v;
		}
		c[n] = strdup(nm);
		if (c[n])
			n++;
	}
	closedir(d);
	if (n == 0) {
		free(c);
		tui_message(t, 1, "Tab: no file name in %s begins with \"%s\"",
			    dir, base);
		return;
	}
	qsort(c, (size_t)n, sizeof *c, tui_complete_cmp);

	/* the longest common prefix of the candidates */
	size_t lcp = strlen(c[0]);
	for (int i = 1; i < n; i++) {
		size_t k = 0;
		while (k < lcp && c[i][k] == c[0][k])
			k++;
		lcp = k;
	}
	char text[sizeof t->pbuf];
	int grew = lcp > bl;
	int fits = (size_t)snprintf(text, sizeof text, "%s%.*s%s", head,
				    (int)lcp, c[0],
				    n == 1 && tui_complete_isdir(dir, c[0]) ?
				    "/" : "") < sizeof text;
	if (fits && (grew || n == 1)) {
		snprintf(t->pbuf, sizeof t->pbuf, "%s", text);
		t->plen = (int)strlen(t->pbuf);
	}
	if (n > 1 && !grew && !strcmp(t->pcomp, t->pbuf)) {
		/* the second Tab: the list */
		size_t at = 0;
		int shown = 0;
		for (int i = 0; i < n; i++) {
			int isdir = tui_complete_isdir(dir, c[i]);
			size_t need = strlen(c[i]) + (isdir ? 1 : 0) + 2;
			if (at + need + 16 >= sizeof t->pcands)
				break;
			at += (size_t)snprintf(t->pcands + at,
					       sizeof t->pcands - at, "%s%s%s",
					       i ? "  " : "", c[i],
					       isdir ? "/" : "");
			shown++;
		}
		if (shown < n)
			snprintf(t->pcands + at, sizeof t->pcands - at,
				 "  (+%d)", n - shown);
		t->pcands_on = 1;
	} else {
		t->pcands_on = 0;
	}
	snprintf(t->pcomp, sizeof t->pcomp, "%s", t->pbuf);
	for (int i = 0; i < n; i++)
		free(c[i]);
	free(c);
}
