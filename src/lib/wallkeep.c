/*
 * wallkeep.c - a changed wall saved over its file keeps the file's
 * comments and formatting (docs/wall-format.md, "Saving").
 *
 * Called by wallfile_save with three texts: the file as it is (orig),
 * the file's model as wallfile_save writes it (old), and the changed
 * model as wallfile_save writes it (new).  old and new come from one
 * writer, so they have one shape; where they differ is exactly what
 * changed.  The three are parsed (the limits of a wall file) and walked
 * together, by key in mappings and by index in lists; each value that
 * differs between old and new is found in orig by the same path and
 * replaced there by new's text of it, byte range for byte range, at the
 * marks libyaml gives (character indices, turned into byte offsets).
 * A key that new has and orig lacks (a default the edit changed) is
 * added to its mapping: after the mapping's last line, at its keys'
 * indentation, or before the `}` of a flow mapping.  A scalar in orig
 * where new has a flow mapping of equal values (friction: 0.8 against
 * {bed: 0.85, head: 0.85}) becomes the one value.
 *
 * A block list one item longer or shorter in new (a block added or
 * removed) gets or loses that item's line (an item written on one
 * line), with the prefix ("  - ") of its neighbour.
 *
 * Anything else (a list that changed by more than one item, a key that
 * went, a value that new writes over several lines, a block mapping in
 * orig where new has a scalar) is refused: NULL, and wallfile_save
 * writes the whole file anew.  The result is only a candidate: wallfile_save keeps it
 * only when it loads to the changed model.
 */
#include <stdlib.h>
#include <string.h>

#include "slipwall/status.h"
#include "slipwall/text.h"
#include "wallkeep.h"

/* One parsed text: its document and the byte offset of each character
 * index libyaml's marks count. */
struct wallkeep_text {
	const char *s;
	size_t len;
	yaml_document_t doc;
	size_t *off;		/* off[i]: byte of character i; off[n] = len */
	size_t n;
};

/* One change to orig: bytes [a, b) become text (a == b: an insertion);
 * seq keeps insertions at one place in the order they were made. */
struct wallkeep_patch {
	size_t a, b;
	char *text;
	int seq;
};

struct wallkeep {
	struct wallkeep_text o, x, y;	/* orig, old, new */
	struct wallkeep_patch *p;
	int np;
};

static int wallkeep_parse(struct wallkeep_text *t, const char *s, size_t len,
			  wallkeep_yaml_fn parse)
{
	char err[SW_ERRLEN];
	t->s = s;
	t->len = len;
	if (parse(s, len, "", &t->doc, err))
		return -1;
	t->off = sw_xmalloc(sizeof *t->off * (len + 1));
	t->n = 0;
	/* libyaml's marks do not count a byte order mark */
	for (size_t i = text_bom(s, len); i < len; i++)
		if (((unsigned char)s[i] & 0xc0) != 0x80)
			t->off[t->n++] = i;
	t->off[t->n] = len;
	return 0;
}

static void wallkeep_text_free(struct wallkeep_text *t)
{
	if (t->off)
		yaml_document_delete(&t->doc);
	free(t->off);
}

static yaml_node_t *node(struct wallkeep_text *t, int id)
{
	return yaml_document_get_node(&t->doc, id);
}

static size_t byte_at(const struct wallkeep_text *t, yaml_mark_t m)
{
	return m.index <= t->n ? t->off[m.index] : t->len;
}

/* The text of node id of t, when it is on one line; NULL otherwise. */
static char *one_line(struct wallkeep_text *t, int id)
{
	yaml_node_t *n = node(t, id);
	size_t a = byte_at(t, n->start_mark), b = byte_at(t, n->end_mark);
	if (b < a || memchr(t->s + a, '\n', b - a) ||
	    memchr(t->s + a, '\r', b - a))
		return NULL;
	char *s = sw_xmalloc(b - a + 1);
	memcpy(s, t->s + a, b - a);
	s[b - a] = 0;
	return s;
}

/* Where a line after the one on which node id of orig ends goes: the
 * end of that line (*fresh 0: the new text starts with a line break),
 * or, when the node ends at the start of a line (a block collection
 * ends there), that place (*fresh 1: the new text ends with one). */
static size_t after_line(struct wallkeep *k, int id, int *fresh)
{
	size_t at = byte_at(&k->o, node(&k->o, id)->end_mark);
	*fresh = at > 0 && k->o.s[at - 1] == '\n';
	while (!*fresh && at < k->o.len && k->o.s[at] != '\n' &&
	       !(k->o.s[at] == '\r' && at + 1 < k->o.len &&
		 k->o.s[at + 1] == '\n'))
		at++;
	return at;
}

static int add_patch(struct wallkeep *k, size_t a, size_t b, char *text)
{
	if (!text)
		return -1;
	k->p = sw_xrealloc(k->p, sizeof *k->p * (size_t)(k->np + 1));
	k->p[k->np] = (struct wallkeep_patch){a, b, text, k->np};
	k->np++;
	return 0;
}

/* Are node i of s and node j of t the same value? (old and new have no
 * aliases: the recursion follows their nesting.) */
static int same(struct wallkeep_text *s, int i, struct wallkeep_text *t, int j)
{
	yaml_node_t *a = node(s, i), *b = node(t, j);
	if (!a || !b || a->type != b->type)
		return 0;
	switch (a->type) {
	case YAML_SCALAR_NODE:
		return a->data.scalar.length == b->data.scalar.length &&
		       !memcmp(a->data.scalar.value, b->data.scalar.value,
			       a->data.scalar.length);
	case YAML_SEQUENCE_NODE: {
		yaml_node_item_t *p = a->data.sequence.items.start;
		yaml_node_item_t *q = b->data.sequence.items.start;
		long n = a->data.sequence.items.top - p;
		if (n != b->data.sequence.items.top - q)
			return 0;
		for (long k = 0; k < n; k++)
			if (!same(s, p[k], t, q[k]))
				return 0;
		return 1;
	}
	case YAML_MAPPING_NODE: {
		yaml_node_pair_t *p = a->data.mapping.pairs.start;
		yaml_node_pair_t *q = b->data.mapping.pairs.start;
		long n = a->data.mapping.pairs.top - p;
		if (n != b->data.mapping.pairs.top - q)
			return 0;
		for (long k = 0; k < n; k++)
			if (!same(s, p[k].key, t, q[k].key) ||
			    !same(s, p[k].value, t, q[k].value))
				return 0;
		return 1;
	}
	default:
		return 0;
	}
}

/* The pair of mapping m (in t) whose key is the scalar key (in u). */
static yaml_node_pair_t *find(struct wallkeep_text *t, yaml_node_t *m,
			      struct wallkeep_text *u, int key)
{
	for (yaml_node_pair_t *p = m->data.mapping.pairs.start;
	     p < m->data.mapping.pairs.top; p++) {
		yaml_node_t *a = node(t, p->key);
		if (a && a->type == YAML_SCALAR_NODE && same(t, p->key, u, key))
			return p;
	}
	return NULL;
}

/* Node o of orig becomes node y of new, written on one line.  A scalar
 * in orig for a mapping of equal scalars in new is written as that
 * scalar (the short form of friction). */
static int replace(struct wallkeep *k, int o, int y)
{
	yaml_node_t *no = node(&k->o, o), *ny = node(&k->y, y);
	if (no->type == YAML_MAPPING_NODE &&
	    no->data.mapping.style != YAML_FLOW_MAPPING_STYLE)
		return -1;
	if (no->type == YAML_SEQUENCE_NODE &&
	    no->data.sequence.style != YAML_FLOW_SEQUENCE_STYLE)
		return -1;
	if (no->type == YAML_SCALAR_NODE && ny->type == YAML_MAPPING_NODE &&
	    ny->data.mapping.pairs.top > ny->data.mapping.pairs.start) {
		yaml_node_pair_t *p = ny->data.mapping.pairs.start;
		int all = node(&k->y, p->value)->type == YAML_SCALAR_NODE;
		for (yaml_node_pair_t *q = p + 1;
		     all && q < ny->data.mapping.pairs.top; q++)
			all = same(&k->y, p->value, &k->y, q->value);
		if (all)
			y = p->value;
	}
	return add_patch(k, byte_at(&k->o, no->start_mark),
			 byte_at(&k->o, no->end_mark), one_line(&k->y, y));
}

/* The lines of new from key's to value's last (a section of the top
 * level, as new writes it: blocks:, supports:, ...), when key is at
 * column 0; NULL otherwise. */
static char *section(struct wallkeep *k, int key, int value)
{
	yaml_node_t *kn = node(&k->y, key), *vn = node(&k->y, value);
	if (kn->start_mark.column != 0)
		return NULL;
	size_t a = byte_at(&k->y, kn->start_mark);
	size_t b = byte_at(&k->y, vn->end_mark);
	if (b > a && k->y.s[b - 1] == '\n')
		b--;
	while (b < k->y.len && k->y.s[b] != '\n')
		b++;
	char *s = sw_xmalloc(b - a + 1);
	memcpy(s, k->y.s + a, b - a);
	s[b - a] = 0;
	return s;
}

/* Add key: value (key and value nodes of new) to mapping o of orig. */
static int insert(struct wallkeep *k, int o, int key, int value)
{
	yaml_node_t *m = node(&k->o, o);
	char *kt = one_line(&k->y, key), *vt = one_line(&k->y, value);
	yaml_node_pair_t *first = m->data.mapping.pairs.start;
	yaml_node_pair_t *last = m->data.mapping.pairs.top - 1;
	int rc = -1;
	if (kt && !vt && last >= first &&
	    m->data.mapping.style != YAML_FLOW_MAPPING_STYLE &&
	    node(&k->o, first->key)->start_mark.column == 0) {
		/* a whole section of the top level, written as new has it */
		char *sec = section(k, key, value);
		free(kt);
		kt = NULL;
		if (!sec)
			goto out;
		kt = sec;
		vt = NULL;
	}
	if (!kt || last < first)
		goto out;
	if (!vt) {		/* kt is the whole section */
		vt = kt;
		kt = NULL;
		int at_line_start;
		size_t at = after_line(k, last->value, &at_line_start);
		size_t need = strlen(vt) + 3;
		char *s = sw_xmalloc(need);
		snprintf(s, need, at_line_start ? "%s\n" : "\n%s", vt);
		rc = add_patch(k, at, at, s);
		goto out;
	}
	size_t need = strlen(kt) + strlen(vt) + 8;
	if (m->data.mapping.style == YAML_FLOW_MAPPING_STYLE) {
		size_t at = byte_at(&k->o, m->end_mark);
		if (at == 0 || k->o.s[at - 1] != '}')
			goto out;
		char *s = sw_xmalloc(need);
		snprintf(s, need, ", %s: %s", kt, vt);
		rc = add_patch(k, at - 1, at - 1, s);
		goto out;
	}
	/* block: a line after the line where the last value ends, at the
	 * column of the mapping's keys */
	yaml_node_t *fk = node(&k->o, first->key);
	size_t col = fk->start_mark.column;
	int at_line_start;
	size_t at = after_line(k, last->value, &at_line_start);
	need += col;
	char *s = sw_xmalloc(need);
	if (at_line_start)
		snprintf(s, need, "%*s%s: %s\n", (int)col, "", kt, vt);
	else
		snprintf(s, need, "\n%*s%s: %s", (int)col, "", kt, vt);
	rc = add_patch(k, at, at, s);
out:
	free(kt);
	free(vt);
	return rc;
}

static int walk(struct wallkeep *k, int x, int y, int o);


/* The bytes before item it of block list o on its line ("  - "), when
 * they are only spaces and one dash: their start in *a and end in *b. */
static int item_prefix(struct wallkeep *k, int it, size_t *a, size_t *b)
{
	*b = byte_at(&k->o, node(&k->o, it)->start_mark);
	*a = *b;
	while (*a > 0 && k->o.s[*a - 1] != '\n')
		(*a)--;
	int dashes = 0;
	for (size_t i = *a; i < *b; i++) {
		if (k->o.s[i] == '-')
			dashes++;
		else if (k->o.s[i] != ' ')
			return -1;
	}
	return dashes == 1 ? 0 : -1;
}

/* Lists x (old) and y (new) one item apart (a block added or removed),
 * o a block list with x's items: the item added to (or taken from) o on
 * a line of its own, the others walked.  Only one item may differ. */
static int list_item(struct wallkeep *k, int x, int y, int o)
{
	yaml_node_t *nx = node(&k->x, x), *ny = node(&k->y, y);
	yaml_node_t *no = node(&k->o, o);
	yaml_node_item_t *ix = nx->data.sequence.items.start;
	yaml_node_item_t *iy = ny->data.sequence.items.start;
	yaml_node_item_t *io = no->data.sequence.items.start;
	long n = nx->data.sequence.items.top - ix;
	long m = ny->data.sequence.items.top - iy;
	long j = 0, add = m > n;
	if (no->data.sequence.style == YAML_FLOW_SEQUENCE_STYLE || n < 1)
		return replace(k, o, y);
	while (j < n && j < m && same(&k->x, ix[j], &k->y, iy[j]))
		j++;
	for (long i = j; i < (add ? n : m); i++)	/* the rest, shifted */
		if (!same(&k->x, ix[i + !add], &k->y, iy[i + add]))
			return -1;
	size_t a, b;
	if (item_prefix(k, io[j < n ? j : n - 1], &a, &b))
		return -1;
	if (!add) {		/* take item j's line out */
		yaml_node_t *it = node(&k->o, io[j]);
		size_t e = byte_at(&k->o, it->end_mark);
		if (memchr(k->o.s + b, '\n', e - b))
			return -1;	/* over several lines */
		while (e < k->o.len && k->o.s[e] != '\n')
			e++;
		return add_patch(k, a, e < k->o.len ? e + 1 : e,
				 sw_xstrdup(""));
	}
	char *t = one_line(&k->y, iy[j]);
	if (!t)
		return -1;
	size_t need = (b - a) + strlen(t) + 2;
	char *s = sw_xmalloc(need);
	size_t at = a;
	int fresh;
	if (j == n)		/* after the last item's line */
		at = after_line(k, io[n - 1], &fresh);
	if (j == n && !fresh) {
		snprintf(s, need, "\n%.*s%s", (int)(b - a), k->o.s + a, t);
	} else {
		snprintf(s, need, "%.*s%s\n", (int)(b - a), k->o.s + a, t);
	}
	free(t);
	return add_patch(k, at, at, s);
}

/* Walk old x, new y and orig o together (see the top of the file). */
static int walk(struct wallkeep *k, int x, int y, int o)
{
	if (same(&k->x, x, &k->y, y))
		return 0;
	yaml_node_t *nx = node(&k->x, x), *ny = node(&k->y, y);
	yaml_node_t *no = node(&k->o, o);
	if (!nx || !ny || !no)
		return -1;
	if (nx->type == YAML_MAPPING_NODE && ny->type == YAML_MAPPING_NODE &&
	    no->type == YAML_MAPPING_NODE) {
		for (yaml_node_pair_t *p = nx->data.mapping.pairs.start;
		     p < nx->data.mapping.pairs.top; p++)
			if (!find(&k->y, ny, &k->x, p->key) &&
			    find(&k->o, no, &k->x, p->key))
				return -1;	/* a key that went */
		for (long i = 0; i < ny->data.mapping.pairs.top -
				     ny->data.mapping.pairs.start; i++) {
			ny = node(&k->y, y);
			no = node(&k->o, o);
			yaml_node_pair_t q = ny->data.mapping.pairs.start[i];
			yaml_node_pair_t *px = find(&k->x, node(&k->x, x),
						    &k->y, q.key);
			yaml_node_pair_t *po = find(&k->o, no, &k->y, q.key);
			int rc = 0;
			if (px && same(&k->x, px->value, &k->y, q.value))
				continue;
			if (px && po)
				rc = walk(k, px->value, q.value, po->value);
			else if (po)
				rc = replace(k, po->value, q.value);
			else
				rc = insert(k, o, q.key, q.value);
			if (rc)
				return -1;
		}
		return 0;
	}
	if (nx->type == YAML_SEQUENCE_NODE && ny->type == YAML_SEQUENCE_NODE &&
	    no->type == YAML_SEQUENCE_NODE) {
		long n = nx->data.sequence.items.top - nx->data.sequence.items.start;
		long ny_n = ny->data.sequence.items.top - ny->data.sequence.items.start;
		if (n != no->data.sequence.items.top - no->data.sequence.items.start)
			return replace(k, o, y);
		if (ny_n == n + 1 || ny_n == n - 1)
			return list_item(k, x, y, o);
		if (n != ny_n)
			return replace(k, o, y);
		for (long i = 0; i < n; i++)
			if (walk(k, node(&k->x, x)->data.sequence.items.start[i],
				 node(&k->y, y)->data.sequence.items.start[i],
				 node(&k->o, o)->data.sequence.items.start[i]))
				return -1;
		return 0;
	}
	return replace(k, o, y);
}

static int by_place(const void *a, const void *b)
{
	const struct wallkeep_patch *p = a, *q = b;
	if (p->a != q->a)
		return p->a < q->a ? -1 : 1;
	return p->seq - q->seq;
}

/* orig with the patches made; NULL when two overlap.  The line breaks
 * a patch adds are orig's (CR LF when its first line ends so). */
static char *apply(struct wallkeep *k, size_t *len)
{
	const char *nl = memchr(k->o.s, '\n', k->o.len);
	int crlf = nl && nl > k->o.s && nl[-1] == '\r';
	qsort(k->p, (size_t)k->np, sizeof *k->p, by_place);
	size_t n = k->o.len + 1;
	for (int i = 0; i < k->np; i++) {
		if (i && k->p[i].a < k->p[i - 1].b)
			return NULL;
		n += 2 * strlen(k->p[i].text);
	}
	char *out = sw_xmalloc(n);
	size_t at = 0, w = 0;
	for (int i = 0; i < k->np; i++) {
		memcpy(out + w, k->o.s + at, k->p[i].a - at);
		w += k->p[i].a - at;
		for (const char *t = k->p[i].text; *t; t++) {
			if (*t == '\n' && crlf)
				out[w++] = '\r';
			out[w++] = *t;
		}
		at = k->p[i].b;
	}
	memcpy(out + w, k->o.s + at, k->o.len - at);
	w += k->o.len - at;
	out[w] = 0;
	*len = w;
	return out;
}

char *wallkeep_patch(const char *orig, size_t olen, const char *old,
		     size_t oldlen, const char *new, size_t newlen,
		     size_t *len, wallkeep_yaml_fn parse)
{
	struct wallkeep k;
	char *out = NULL;
	memset(&k, 0, sizeof k);
	if (!wallkeep_parse(&k.o, orig, olen, parse) &&
	    !wallkeep_parse(&k.x, old, oldlen, parse) &&
	    !wallkeep_parse(&k.y, new, newlen, parse) &&
	    yaml_document_get_root_node(&k.o.doc) &&
	    yaml_document_get_root_node(&k.x.doc) &&
	    yaml_document_get_root_node(&k.y.doc) && !walk(&k, 1, 1, 1))
		out = apply(&k, len);
	for (int i = 0; i < k.np; i++)
		free(k.p[i].text);
	free(k.p);
	wallkeep_text_free(&k.o);
	wallkeep_text_free(&k.x);
	wallkeep_text_free(&k.y);
	return out;
}

size_t wallkeep_header(const char *text, size_t len)
{
	size_t at = text_bom(text, len);
	while (at < len) {
		size_t e = at;
		while (e < len && text[e] != '\n')
			e++;
		size_t i = at;
		while (i < e && (text[i] == ' ' || text[i] == '\t' ||
				 text[i] == '\r'))
			i++;
		if (i < e && text[i] != '#')
			break;
		at = e < len ? e + 1 : e;
	}
	return at;
}
