/*
 * wallfile.c - reading and writing wall files (the format:
 * docs/wall-format.md).
 *
 * Called by the command line and the workbench; returns a finished
 * `struct wall` that the caller owns, or SW_EINPUT with a message
 * "FILE:LINE:COLUMN: what is wrong" that points at the offending value.
 *
 * Reading takes three steps over a buffer of at most WALLFILE_MAX_BYTES:
 *
 *  1. An event pass (yaml_parser_parse) that only counts nesting and
 *     events.  libyaml takes time quadratic in the nesting depth (a file of
 *     100,000 '[' takes over a minute), so a document nested deeper than
 *     WALLFILE_MAX_DEPTH is refused here, after a few dozen events, before
 *     the document is built.  Syntax errors are reported from this pass.
 *  2. yaml_parser_load builds the document.  Aliases become shared node
 *     references (a recursive alias makes a cycle), so memory stays
 *     proportional to the file; but a walk can reach one node many times
 *     (an "alias bomb").
 *  3. A walk driven by the schema: every mapping is checked for unknown
 *     and duplicate keys (libyaml accepts duplicates silently), every value
 *     for its type and range.  The walk never descends into content the
 *     schema does not expect, so its depth is bounded by the schema and a
 *     cycle cannot trap it; every node it reaches counts against
 *     WALLFILE_MAX_NODES, which bounds the work an alias bomb can cause.
 *
 * Numbers are plain scalars of the form [-+]digits[.digits][e[-+]digits]:
 * a quoted "0.6" is a string, and .inf, .nan, hexadecimal and "0.6x" are
 * refused.  Counts are plain integers.
 *
 * Blocks are added in the order: layout (course by course), `blocks`,
 * `supports` polygons; wall_finish() then adds the ground and does the
 * geometric validation (its messages point at the marks set here).
 *
 * Writing (wallfile_save) keeps a generated wall generated: when the
 * free blocks are the layout's (in its order, each with its own
 * vertices, some perhaps left out) followed by others, it writes
 * `layout:` with `omit:` for the blocks left out and the others under
 * `blocks:`; any other wall gets every free block as an explicit
 * polygon.  Either way the wall loads again to the same model, blocks in
 * the same order.  Numbers are written with the fewest significant
 * digits (15, 16 or 17) that read back bit for bit, strings
 * double-quoted with every character YAML folds or refuses escaped.
 * Saved over the file the wall was read from, that file's comments and
 * formatting are kept: wallkeep.c patches the changed values into its
 * text, and the result is kept only if it loads to the same model.
 *
 * Every YAML text the program parses (the file, each --set value) goes
 * through reader_load, with the limits of steps 1-3 above; a value's
 * aliases are copied as shared nodes, never expanded (edit_copy).
 */
#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <yaml.h>

#include "slipwall/geom.h"
#include "slipwall/layout.h"
#include "slipwall/outfile.h"
#include "slipwall/text.h"
#include "slipwall/wallfile.h"
#include "wallkeep.h"

#define WALLFILE_MAX_DEPTH 64

/* The state of one read: the document, the wall being built, the error
 * buffer, and the count of nodes the walk has reached. */
struct reader {
	const char *name;
	yaml_document_t doc;
	struct wall *w;
	char *err;
	long visits;
	const struct wallfile_edit *edits;	/* wallfile_load_edited */
	int nedits;
	/* the file's anchors and aliases in document order (pass 1, when
	 * `track`): libyaml's document keeps an alias as a second
	 * reference to its anchor's node, so a message about the value
	 * points at the anchor, and names the aliases too (reader_fail_at) */
	int track;
	struct anchor_mark *marks;
	int nmarks, capmarks;
};

/* An anchor (&name) or an alias (*name) of the file and where it is. */
struct anchor_mark {
	char name[48];		/* cut to fit: two names alike in their first
				 * 47 bytes count as one, and a message may
				 * then name an alias of the other too */
	int alias;
	yaml_mark_t at;
};

/* At most this many are kept (an alias bomb has millions); a message
 * about a value anchored beyond them names no alias. */
#define READER_MAX_MARKS 4096

/* The nodes an edit adds carry this line (plus the edit's index) in
 * their marks, so that a message about them names the edit, not a place
 * in the file. */
#define EDIT_LINE ((size_t)1 << 40)

/* ---------------------------------------------------------------- errors */

static int reader_fail_at(struct reader *r, yaml_mark_t m, const char *fmt,
			  ...) __attribute__((format(printf, 3, 4)));

/* Where the value at m, if an anchor's, is used through its aliases:
 * " (the value of &NAME, used through *NAME at L:C, L:C ...)", or "".
 * libyaml refuses an anchor's name a second time, so the uses are the
 * aliases of that name after it.  Into buf, of ALIASES_LEN bytes. */
#define ALIASES_LEN 256
static const char *reader_aliases(const struct reader *r, yaml_mark_t m,
				  char *buf)
{
	const size_t size = ALIASES_LEN;
	buf[0] = 0;
	int a = -1;
	for (int i = 0; i < r->nmarks && a < 0; i++)
		if (!r->marks[i].alias && r->marks[i].at.line == m.line &&
		    r->marks[i].at.column == m.column)
			a = i;
	if (a < 0)
		return buf;
	const char *name = r->marks[a].name;
	size_t len = 0;
	int uses = 0;
	for (int i = a + 1; i < r->nmarks; i++) {
		const struct anchor_mark *u = &r->marks[i];
		if (!u->alias || strcmp(u->name, name))
			continue;
		if (uses++ == 0)
			len = (size_t)snprintf(buf, size, " (the value of "
					       "&%s, used through *%s at %zu:%zu",
					       name, name, u->at.line + 1,
					       u->at.column + 1);
		else if (len < size - 32)
			len += (size_t)snprintf(buf + len, size - len,
						", %zu:%zu", u->at.line + 1,
						u->at.column + 1);
	}
	if (uses && len < size - 2)
		snprintf(buf + len, size - len, ")");
	else if (uses)
		snprintf(buf + size - 6, 6, "...)");
	return buf;
}

/* Pass 1's record of an anchor or an alias (reader.track). */
static void reader_mark(struct reader *r, const unsigned char *name,
			int alias, yaml_mark_t at)
{
	if (!r->track || !name || r->nmarks >= READER_MAX_MARKS)
		return;
	if (r->nmarks == r->capmarks) {
		r->capmarks = r->capmarks ? 2 * r->capmarks : 16;
		r->marks = sw_xrealloc(r->marks, sizeof *r->marks *
				       (size_t)r->capmarks);
	}
	struct anchor_mark *k = &r->marks[r->nmarks++];
	snprintf(k->name, sizeof k->name, "%s", (const char *)name);
	k->alias = alias;
	k->at = at;
}

static int reader_fail_at(struct reader *r, yaml_mark_t m, const char *fmt,
			  ...)
{
	char msg[SW_ERRLEN], uses[ALIASES_LEN];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(msg, sizeof msg, fmt, ap);
	va_end(ap);
	if (m.line >= EDIT_LINE && m.line - EDIT_LINE < (size_t)r->nedits)
		sw_fail(r->err, SW_EINPUT, "%s: %s",
			r->edits[m.line - EDIT_LINE].label, msg);
	else
		sw_fail(r->err, SW_EINPUT, "%s:%zu:%zu: %s%s", r->name,
			m.line + 1, m.column + 1, msg,
			reader_aliases(r, m, uses));
	return -1;
}

#define FAIL(r, n, ...) reader_fail_at((r), (n)->start_mark, __VA_ARGS__)

static struct wall_mark mark_of(const yaml_node_t *n)
{
	struct wall_mark m = {(int)n->start_mark.line + 1,
			      (int)n->start_mark.column + 1};
	if (n->start_mark.line >= EDIT_LINE)	/* an edit: no place */
		m.line = m.col = 0;
	return m;
}

/* A short printable copy of a scalar, for messages. */
static const char *shown(const yaml_node_t *n, char *buf, size_t len)
{
	size_t j = 0;
	for (size_t i = 0; i < n->data.scalar.length && j + 4 < len; i++) {
		unsigned char c = n->data.scalar.value[i];
		buf[j++] = (c < 0x20 || c == 0x7f) ? '?' : (char)c;
	}
	if (j + 4 >= len && n->data.scalar.length > j) {
		memcpy(buf + j, "...", 3);
		j += 3;
	}
	buf[j] = '\0';
	return buf;
}

/* What a node is, for "must be a number, not a list" messages. */
static const char *kind_of(const yaml_node_t *n)
{
	switch (n->type) {
	case YAML_MAPPING_NODE:
		return "a mapping";
	case YAML_SEQUENCE_NODE:
		return "a list";
	case YAML_SCALAR_NODE:
		if (n->data.scalar.length == 0 &&
		    n->data.scalar.style == YAML_PLAIN_SCALAR_STYLE)
			return "empty";
		if (n->data.scalar.style != YAML_PLAIN_SCALAR_STYLE)
			return "a quoted string";
		return "a string";
	default:
		return "nothing";
	}
}

/* The error of libyaml's parser, located.  Reader errors (bad encoding)
 * carry a byte offset instead of a mark. */
static int reader_yaml_error(struct reader *r, const yaml_parser_t *p,
			     const char *buf, size_t len)
{
	yaml_mark_t m = p->problem_mark;
	const char *problem = p->problem ? p->problem : "YAML error";

	switch (p->error) {
	case YAML_MEMORY_ERROR:
		sw_fail(r->err, SW_EINPUT, "%s: out of memory while reading",
			r->name);
		return -1;
	case YAML_READER_ERROR:
		m.line = 0;
		m.column = 0;
		for (size_t i = 0; i < p->problem_offset && i < len; i++) {
			if (buf[i] == '\n') {
				m.line++;
				m.column = 0;
			} else {
				m.column++;
			}
		}
		if (p->problem_value >= 0)
			return reader_fail_at(r, m, "%s (byte 0x%02x)",
					      problem, p->problem_value);
		return reader_fail_at(r, m, "%s", problem);
	default:
		if (p->context)
			return reader_fail_at(r, m, "%s (%s at line %zu, column %zu)",
					      problem, p->context,
					      p->context_mark.line + 1,
					      p->context_mark.column + 1);
		return reader_fail_at(r, m, "%s", problem);
	}
}

/* ------------------------------------------------------------ node access */

/* Every node the walk reaches goes through here: count it, refuse tags. */
static yaml_node_t *reader_node(struct reader *r, int id)
{
	yaml_node_t *n = yaml_document_get_node(&r->doc, id);
	if (!n) {
		sw_fail(r->err, SW_EINPUT, "%s: malformed YAML document",
			r->name);
		return NULL;
	}
	if (++r->visits > WALLFILE_MAX_NODES) {
		FAIL(r, n, "the document expands to more than %d nodes (aliases?)",
		     WALLFILE_MAX_NODES);
		return NULL;
	}
	const char *def = n->type == YAML_MAPPING_NODE ? YAML_DEFAULT_MAPPING_TAG
			  : n->type == YAML_SEQUENCE_NODE ? YAML_DEFAULT_SEQUENCE_TAG
							  : YAML_DEFAULT_SCALAR_TAG;
	if (n->tag && strcmp((const char *)n->tag, def)) {
		FAIL(r, n, "YAML tags are not supported here ('%s')",
		     (const char *)n->tag);
		return NULL;
	}
	return n;
}

static int key_is(const yaml_node_t *k, const char *name)
{
	return k->data.scalar.length == strlen(name) &&
	       !memcmp(k->data.scalar.value, name, k->data.scalar.length);
}

/* Check that n is a mapping whose keys are among keys[] (NULL-terminated),
 * each at most once; vals[i] is the value of keys[i], or NULL. */
static int reader_map(struct reader *r, yaml_node_t *n, const char *what,
		      const char *const *keys, yaml_node_t **vals)
{
	int nkeys = 0;
	while (keys[nkeys])
		vals[nkeys++] = NULL;
	if (n->type != YAML_MAPPING_NODE)
		return FAIL(r, n, "%s must be a mapping, not %s", what,
			    kind_of(n));
	for (yaml_node_pair_t *p = n->data.mapping.pairs.start;
	     p < n->data.mapping.pairs.top; p++) {
		yaml_node_t *k = reader_node(r, p->key);
		if (!k)
			return -1;
		if (k->type != YAML_SCALAR_NODE)
			return FAIL(r, k, "a key in %s must be a string, not %s",
				    what, kind_of(k));
		char buf[48];
		int i = 0;
		while (keys[i] && !key_is(k, keys[i]))
			i++;
		if (!keys[i])
			return FAIL(r, k, "unknown key '%s' in %s",
				    shown(k, buf, sizeof buf), what);
		if (vals[i])
			return FAIL(r, k, "duplicate key '%s' in %s", keys[i],
				    what);
		vals[i] = reader_node(r, p->value);
		if (!vals[i])
			return -1;
	}
	return 0;
}

static int is_nonfinite_word(const char *s)
{
	if (*s == '+' || *s == '-')
		s++;
	if (*s == '.')
		s++;
	return !strcasecmp(s, "inf") || !strcasecmp(s, "infinity") ||
	       !strcasecmp(s, "nan");
}

/* A plain scalar, or an error naming what it is instead. */
static const char *reader_plain(struct reader *r, yaml_node_t *n,
				const char *what, const char *type)
{
	if (n->type != YAML_SCALAR_NODE ||
	    n->data.scalar.style != YAML_PLAIN_SCALAR_STYLE ||
	    n->data.scalar.length == 0) {
		FAIL(r, n, "%s must be %s, not %s", what, type, kind_of(n));
		return NULL;
	}
	return (const char *)n->data.scalar.value;
}

static int reader_number(struct reader *r, yaml_node_t *n, const char *what,
			 double *out)
{
	char buf[48];
	const char *s = reader_plain(r, n, what, "a number");
	if (!s)
		return -1;
	if (is_nonfinite_word(s))
		return FAIL(r, n, "%s must be a finite number, got '%s'", what,
			    shown(n, buf, sizeof buf));
	if (!text_is_decimal(s))
		return FAIL(r, n, "%s must be a number, got '%s'", what,
			    shown(n, buf, sizeof buf));
	char *end;
	errno = 0;
	double v = strtod(s, &end);
	if (*end || !isfinite(v))
		return FAIL(r, n, "%s must be a finite number, got '%s'", what,
			    shown(n, buf, sizeof buf));
	*out = v;
	return 0;
}

/* A number with lo <= v (lo < v when strict) and v <= hi. */
static int reader_number_in(struct reader *r, yaml_node_t *n,
			    const char *what, double lo, int strict, double hi,
			    double *out)
{
	double v;
	if (reader_number(r, n, what, &v))
		return -1;
	if ((strict ? !(v > lo) : !(v >= lo)) || v > hi) {
		if (isinf(hi))
			return FAIL(r, n, "%s must be %s %g (got %g)", what,
				    strict ? ">" : ">=", lo, v);
		if (strict)
			return FAIL(r, n, "%s must be > %g and <= %g (got %g)",
				    what, lo, hi, v);
		return FAIL(r, n, "%s must be between %g and %g (got %g)", what,
			    lo, hi, v);
	}
	*out = v;
	return 0;
}

/* A plain integer literal in [lo, hi]. */
static int reader_integer(struct reader *r, yaml_node_t *n, const char *what,
			  unsigned long long lo, unsigned long long hi,
			  unsigned long long *out)
{
	char buf[48];
	const char *s = reader_plain(r, n, what, "an integer");
	if (!s)
		return -1;
	const char *d = s;
	int neg = 0, ok;
	if (*d == '+' || *d == '-')
		neg = *d++ == '-';
	ok = *d != '\0';
	for (const char *p = d; *p; p++)
		ok &= isdigit((unsigned char)*p) != 0;
	if (!ok)
		return FAIL(r, n, "%s must be an integer, got '%s'", what,
			    shown(n, buf, sizeof buf));
	errno = 0;
	unsigned long long v = strtoull(d, NULL, 10);
	if ((neg && v != 0) || v < lo)
		return FAIL(r, n, "%s must be an integer >= %llu (got %s)", what,
			    lo, shown(n, buf, sizeof buf));
	if (errno == ERANGE || v > hi)
		return FAIL(r, n, "%s must be an integer <= %llu (got %s)", what,
			    hi, shown(n, buf, sizeof buf));
	*out = v;
	return 0;
}

/* A string scalar of any style, without NUL bytes, not empty. */
static const char *reader_string(struct reader *r, yaml_node_t *n,
				 const char *what)
{
	if (n->type != YAML_SCALAR_NODE ||
	    (n->data.scalar.length == 0 &&
	     n->data.scalar.style == YAML_PLAIN_SCALAR_STYLE)) {
		FAIL(r, n, "%s must be a string, not %s", what, kind_of(n));
		return NULL;
	}
	if (n->data.scalar.length == 0 ||
	    memchr(n->data.scalar.value, '\0', n->data.scalar.length)) {
		FAIL(r, n, "%s must be a non-empty string without NUL bytes",
		     what);
		return NULL;
	}
	return (const char *)n->data.scalar.value;
}

/* One of the words in choices[] (NULL-terminated): its index. */
static int reader_choice(struct reader *r, yaml_node_t *n, const char *what,
			 const char *const *choices)
{
	char buf[48];
	const char *s = reader_string(r, n, what);
	if (!s)
		return -1;
	for (int i = 0; choices[i]; i++)
		if (!strcmp(s, choices[i]))
			return i;
	return FAIL(r, n, "%s must be '%s' or '%s', got '%s'", what,
		    choices[0], choices[1], shown(n, buf, sizeof buf));
}

static int reader_list(struct reader *r, yaml_node_t *n, const char *what)
{
	if (n->type != YAML_SEQUENCE_NODE)
		return FAIL(r, n, "%s must be a list, not %s", what, kind_of(n));
	return 0;
}

static int list_len(const yaml_node_t *n)
{
	return (int)(n->data.sequence.items.top - n->data.sequence.items.start);
}

/* [x, y]: a list of exactly two numbers. */
static int reader_pair(struct reader *r, yaml_node_t *n, const char *what,
		       double out[2])
{
	if (n->type != YAML_SEQUENCE_NODE || list_len(n) != 2)
		return FAIL(r, n, "%s must be a list of 2 numbers [x, y]%s", what,
			    n->type == YAML_SEQUENCE_NODE ? "" : ", not a scalar or mapping");
	for (int i = 0; i < 2; i++) {
		yaml_node_t *c = reader_node(r, n->data.sequence.items.start[i]);
		if (!c || reader_number(r, c, what, &out[i]))
			return -1;
	}
	return 0;
}

/* [[x, y], [x, y], [x, y], ...]: at least 3 vertices; *xy is malloc'd. */
static int reader_polygon(struct reader *r, yaml_node_t *n, const char *what,
			  double **xy, int *nv)
{
	*xy = NULL;
	if (reader_list(r, n, what))
		return -1;
	int m = list_len(n);
	if (m < 3)
		return FAIL(r, n, "%s needs at least 3 vertices (got %d)", what,
			    m);
	double *p = sw_xmalloc(sizeof(double) * 2 * (size_t)m);
	for (int i = 0; i < m; i++) {
		yaml_node_t *c = reader_node(r, n->data.sequence.items.start[i]);
		if (!c || reader_pair(r, c, "a vertex", &p[2 * i])) {
			free(p);
			return -1;
		}
	}
	int far = geom_far_vertex(p, m);
	char thin[200];
	if (far >= 0 && wall_thin_text(p, m, thin, sizeof thin)) {
		free(p);
		return FAIL(r, n, "the polygon %s", thin);
	}
	if (far >= 0) {
		free(p);
		return FAIL(r, reader_node(r, n->data.sequence.items.start[far]),
			    "vertex %d %s", far + 1,
			    wall_far_text);
	}
	*xy = p;
	*nv = m;
	return 0;
}

static yaml_node_t *reader_item(struct reader *r, yaml_node_t *list, int i)
{
	return reader_node(r, list->data.sequence.items.start[i]);
}

/* ----------------------------------------------------------- the sections */

static int read_material(struct reader *r, yaml_node_t *n)
{
	static const char *const keys[] = {"friction", "unit_weight",
					   "thickness", NULL};
	static const char *const fkeys[] = {"bed", "head", "cov", NULL};
	yaml_node_t *v[3], *f[3];
	struct wall *w = r->w;

	if (reader_map(r, n, "material", keys, v))
		return -1;
	if (v[0] && v[0]->type == YAML_MAPPING_NODE) {
		if (reader_map(r, v[0], "friction", fkeys, f))
			return -1;
		for (int i = 0; i < 2; i++)
			if (!f[i])
				return FAIL(r, v[0], "friction needs both 'bed' and 'head' (missing '%s')",
					    fkeys[i]);
		if (reader_number_in(r, f[0], "friction (bed)", 0, 0, INFINITY,
				     &w->mu_bed) ||
		    reader_number_in(r, f[1], "friction (head)", 0, 0, INFINITY,
				     &w->mu_head))
			return -1;
		w->friction_mark[0] = mark_of(f[0]);
		w->friction_mark[1] = mark_of(f[1]);
		/* friction as a random variable (docs/wall-format.md) */
		if (f[2] && reader_number_in(r, f[2], "friction (cov)", 0, 0,
					     WALL_COV_MAX, &w->mu_cov))
			return -1;
	} else if (v[0]) {
		if (reader_number_in(r, v[0], "friction", 0, 0, INFINITY,
				     &w->mu_bed))
			return -1;
		w->mu_head = w->mu_bed;
		w->friction_mark[0] = w->friction_mark[1] = mark_of(v[0]);
	}
	if (v[1] && reader_number_in(r, v[1], "unit_weight", 0, 1, INFINITY,
				     &w->unit_weight))
		return -1;
	if (v[1])
		w->unit_weight_mark = mark_of(v[1]);
	if (v[2] && reader_number_in(r, v[2], "thickness", 0, 1, INFINITY,
				     &w->thickness))
		return -1;
	return 0;
}

static int read_layout(struct reader *r, yaml_node_t *n)
{
	static const char *const keys[] = {"block", "courses", "length", "bond",
					   "first_course", "origin", "omit", NULL};
	static const char *const bonds[] = {"running", "stack", NULL};
	static const char *const firsts[] = {"half", "full", NULL};
	yaml_node_t *v[7];
	struct wall *w = r->w;
	struct wall_layout *l = &w->layout;
	unsigned long long courses;
	double size[2];

	if (reader_map(r, n, "layout", keys, v))
		return -1;
	for (int i = 0; i < 3; i++)
		if (!v[i])
			return FAIL(r, n, "layout needs '%s'", keys[i]);
	if (reader_pair(r, v[0], "layout block [width, height]", size))
		return -1;
	if (!(size[0] > 0) || !(size[1] > 0))
		return FAIL(r, v[0], "layout block width and height must be > 0 (got [%g, %g])",
			    size[0], size[1]);
	l->block_w = size[0];
	l->block_h = size[1];
	if (reader_integer(r, v[1], "courses", 1, 1000000, &courses))
		return -1;
	l->courses = (int)courses;
	if (reader_number_in(r, v[2], "length", 0, 1, INFINITY, &l->length))
		return -1;
	if (l->length < l->block_w / 2)
		return FAIL(r, v[2], "length %g is shorter than half a block (%g)",
			    l->length, l->block_w / 2);
	l->bond = BOND_RUNNING;
	if (v[3]) {
		int b = reader_choice(r, v[3], "bond", bonds);
		if (b < 0)
			return -1;
		l->bond = b == 0 ? BOND_RUNNING : BOND_STACK;
	}
	l->first_half = 1;
	if (v[4]) {
		int f = reader_choice(r, v[4], "first_course", firsts);
		if (f < 0)
			return -1;
		l->first_half = f == 0;
	}
	l->x0 = 0;
	l->y0 = w->has_ground ? w->ground_y : 0;
	if (v[5]) {
		double o[2];
		if (reader_pair(r, v[5], "origin", o))
			return -1;
		l->x0 = o[0];
		l->y0 = o[1];
	}
	l->present = 1;
	if (layout_generate(w, mark_of(n), r->err) != SW_OK)
		return -1;
	/* omit: blocks of the courses left out (a wall edited and saved
	 * by the workbench); the layout's blocks are all w has so far */
	if (v[6]) {
		if (reader_list(r, v[6], "layout omit"))
			return -1;
		for (int i = 0; i < list_len(v[6]); i++) {
			yaml_node_t *c = reader_item(r, v[6], i);
			const char *id;
			if (!c || !(id = reader_string(r, c, "layout omit")))
				return -1;
			int k = 0;
			while (k < w->nblocks && strcmp(w->blocks[k].id, id))
				k++;
			for (int j = 0; k == w->nblocks && j < i; j++) {
				yaml_node_t *e = reader_item(r, v[6], j);
				if (e && e->type == YAML_SCALAR_NODE &&
				    !strcmp((const char *)e->data.scalar.value, id))
					return FAIL(r, c, "layout omit: '%s' is "
						    "already in the list (item %d)",
						    id, j + 1);
			}
			if (k == w->nblocks)
				return FAIL(r, c, "layout omit: the layout has no block '%s'",
					    id);
			free(w->blocks[k].id);
			free(w->blocks[k].xy);
			memmove(w->blocks + k, w->blocks + k + 1,
				sizeof *w->blocks * (size_t)(w->nblocks - k - 1));
			w->nblocks--;
		}
	}
	return 0;
}

static int read_blocks(struct reader *r, yaml_node_t *n)
{
	static const char *const keys[] = {"id", "vertices", NULL};
	yaml_node_t *v[2];

	if (reader_list(r, n, "blocks"))
		return -1;
	for (int i = 0; i < list_len(n); i++) {
		yaml_node_t *b = reader_item(r, n, i);
		const char *id = NULL;
		double *xy;
		int nv;
		if (!b || reader_map(r, b, "a block", keys, v))
			return -1;
		if (v[0] && !(id = reader_string(r, v[0], "id")))
			return -1;
		if (id && wall_id_reserved(id))
			return FAIL(r, v[0], "'%s' is a reserved name (the "
				    "program's own foundation support): give "
				    "this block another id", id);
		if (!v[1])
			return FAIL(r, b, "a block needs 'vertices'");
		if (reader_polygon(r, v[1], "vertices", &xy, &nv))
			return -1;
		wall_add_block(r->w, id, xy, nv, 0, mark_of(b));
		free(xy);
	}
	return 0;
}

/* Supports in two passes: the ground first (the layout stands on it),
 * the fixed polygons after the free blocks. */
static int read_supports(struct reader *r, yaml_node_t *n, int polygons)
{
	static const char *const keys[] = {"ground", "vertices", "id", NULL};
	static const char *const gkeys[] = {"y", NULL};
	yaml_node_t *v[3], *g[1];
	struct wall *w = r->w;

	if (reader_list(r, n, "supports"))
		return -1;
	for (int i = 0; i < list_len(n); i++) {
		yaml_node_t *s = reader_item(r, n, i);
		if (!s || reader_map(r, s, "a support", keys, v))
			return -1;
		if (!v[0] == !v[1])
			return FAIL(r, s, "a support is either 'ground' or 'vertices'%s",
				    v[0] ? ", not both" : "");
		if (v[0] && v[2])
			return FAIL(r, v[2], "'id' belongs to a 'vertices' support, not to 'ground'");
		if (v[0] && !polygons) {
			if (w->has_ground)
				return FAIL(r, v[0], "there is already a ground support");
			if (reader_map(r, v[0], "ground", gkeys, g))
				return -1;
			w->ground_y = 0;
			if (g[0] && reader_number(r, g[0], "ground y",
						  &w->ground_y))
				return -1;
			w->has_ground = 1;
			w->ground_mark = mark_of(v[0]);
		}
		if (v[1] && polygons) {
			const char *id = NULL;
			double *xy;
			int nv;
			if (v[2] && !(id = reader_string(r, v[2], "id")))
				return -1;
			if (id && wall_id_reserved(id))
				return FAIL(r, v[2], "'%s' is a reserved name "
					    "(the program's own foundation "
					    "support): give this support "
					    "another id", id);
			if (reader_polygon(r, v[1], "vertices", &xy, &nv))
				return -1;
			wall_add_block(w, id, xy, nv, 1, mark_of(s));
			free(xy);
		}
	}
	return 0;
}

static int read_direction(struct reader *r, yaml_node_t *n, double d[2])
{
	if (reader_pair(r, n, "direction", d))
		return -1;
	/* a direction only points: [1.7e308, 1.7e308] is [1, 1], whose
	 * length does not overflow (wall_finish makes it a unit vector) */
	double big = fmax(fabs(d[0]), fabs(d[1]));
	if (big > 1 && isfinite(big) && !isfinite(hypot(d[0], d[1]))) {
		d[0] /= big;
		d[1] /= big;
	}
	double len = hypot(d[0], d[1]);
	if (!(len > 0) || !isfinite(len))
		return FAIL(r, n, "direction must be a non-zero vector (got [%g, %g])",
			    d[0], d[1]);
	return 0;
}

static int read_loads(struct reader *r, yaml_node_t *n)
{
	static const char *const keys[] = {"point", "body", NULL};
	static const char *const pkeys[] = {"at", "direction", "magnitude",
					    NULL};
	static const char *const bkeys[] = {"direction", "magnitude", NULL};
	yaml_node_t *v[2], *p[3];

	if (reader_list(r, n, "loads"))
		return -1;
	for (int i = 0; i < list_len(n); i++) {
		yaml_node_t *item = reader_item(r, n, i);
		struct wall_load ld;
		memset(&ld, 0, sizeof ld);
		ld.block = -1;
		ld.magnitude = 1;
		if (!item || reader_map(r, item, "a load", keys, v))
			return -1;
		if (!v[0] == !v[1])
			return FAIL(r, item, "a load is either 'point' or 'body'%s",
				    v[0] ? ", not both" : "");
		if (v[0]) {
			ld.kind = LOAD_POINT;
			if (reader_map(r, v[0], "a point load", pkeys, p))
				return -1;
			if (!p[0])
				return FAIL(r, v[0], "a point load needs 'at'");
			if (!p[1])
				return FAIL(r, v[0], "a point load needs 'direction'");
			if (reader_pair(r, p[0], "at", ld.at) ||
			    read_direction(r, p[1], ld.dir))
				return -1;
			if (p[2] && reader_number_in(r, p[2], "magnitude", 0, 1,
						     INFINITY, &ld.magnitude))
				return -1;
			ld.mark = mark_of(p[0]);
		} else {
			ld.kind = LOAD_BODY;
			if (reader_map(r, v[1], "a body load", bkeys, p))
				return -1;
			if (!p[0])
				return FAIL(r, v[1], "a body load needs 'direction'");
			if (read_direction(r, p[0], ld.dir))
				return -1;
			if (p[1] && reader_number_in(r, p[1], "magnitude", 0, 1,
						     INFINITY, &ld.magnitude))
				return -1;
			ld.mark = mark_of(p[0]);
		}
		wall_add_load(r->w, &ld);
	}
	return 0;
}

static int read_contacts(struct reader *r, yaml_node_t *n)
{
	static const char *const keys[] = {"depth", "positions", NULL};
	static const char *const pos[] = {"anywhere", "depth", NULL};
	yaml_node_t *v[2];

	if (reader_map(r, n, "contacts", keys, v))
		return -1;
	if (v[0] && reader_number_in(r, v[0], "depth", 0, 0, 0.5, &r->w->depth))
		return -1;
	if (v[1]) {
		int p = reader_choice(r, v[1], "positions", pos);
		if (p < 0)
			return -1;
		r->w->anywhere = p == 0;
	}
	return 0;
}

static int read_analysis(struct reader *r, yaml_node_t *n)
{
	static const char *const keys[] = {"samples", "seed", "design_load",
					   NULL};
	yaml_node_t *v[3];
	unsigned long long x;

	if (reader_map(r, n, "analysis", keys, v))
		return -1;
	if (v[0]) {
		if (reader_integer(r, v[0], "samples", 1, INT_MAX, &x))
			return -1;
		r->w->samples = (int)x;
	}
	if (v[1]) {
		if (reader_integer(r, v[1], "seed", 0, WALL_SEED_MAX, &x))
			return -1;
		r->w->seed = (unsigned long)x;
	}
	if (v[2] && reader_number_in(r, v[2], "design_load", 0, 1, INFINITY,
				     &r->w->design_load))
		return -1;
	return 0;
}

static int read_tests(struct reader *r, yaml_node_t *n)
{
	static const char *const keys[] = {"loads", NULL};
	yaml_node_t *v[1];
	struct wall *w = r->w;

	if (reader_map(r, n, "tests", keys, v))
		return -1;
	if (!v[0])
		return FAIL(r, n, "tests needs 'loads'");
	if (reader_list(r, v[0], "tests loads"))
		return -1;
	int m = list_len(v[0]);
	free(w->tests);
	w->tests = sw_xmalloc(sizeof(double) * (size_t)(m + 1));
	w->ntests = 0;
	for (int i = 0; i < m; i++) {
		yaml_node_t *c = reader_item(r, v[0], i);
		if (!c || reader_number_in(r, c, "a test load", 0, 1, INFINITY,
					   &w->tests[i]))
			return -1;
		w->ntests++;
	}
	return 0;
}

/* The top-level mapping: sections in the order the model needs them. */
static int read_wall(struct reader *r, yaml_node_t *root)
{
	enum { NAME, MATERIAL, LAYOUT, BLOCKS, SUPPORTS, LOADS, CONTACTS,
	       ANALYSIS, TESTS };
	static const char *const keys[] = {"name", "material", "layout",
					   "blocks", "supports", "loads",
					   "contacts", "analysis", "tests",
					   NULL};
	yaml_node_t *v[9];
	struct wall *w = r->w;

	if (reader_map(r, root, "the top level", keys, v))
		return -1;
	if (v[NAME]) {
		const char *s = reader_string(r, v[NAME], "name");
		if (!s)
			return -1;
		w->name = sw_xstrdup(s);
	}
	if (v[MATERIAL] && read_material(r, v[MATERIAL]))
		return -1;
	if (v[SUPPORTS] && read_supports(r, v[SUPPORTS], 0))
		return -1;
	if (v[LAYOUT] && read_layout(r, v[LAYOUT]))
		return -1;
	if (v[BLOCKS] && read_blocks(r, v[BLOCKS]))
		return -1;
	if (v[SUPPORTS] && read_supports(r, v[SUPPORTS], 1))
		return -1;
	if (v[LOADS] && read_loads(r, v[LOADS]))
		return -1;
	if (v[CONTACTS] && read_contacts(r, v[CONTACTS]))
		return -1;
	if (v[ANALYSIS] && read_analysis(r, v[ANALYSIS]))
		return -1;
	if (v[TESTS] && read_tests(r, v[TESTS]))
		return -1;

	/* what the whole model needs, pointed at the file (wall_finish
	 * checks the same, but has no place to point at) */
	int nfree = 0, nfixed = 0;
	for (int k = 0; k < w->nblocks; k++) {
		nfree += !w->blocks[k].fixed;
		nfixed += w->blocks[k].fixed;
	}
	if (nfree == 0)
		return FAIL(r, v[BLOCKS] ? v[BLOCKS] : root,
			    "the wall has no blocks (give a 'layout' or 'blocks')");
	if (nfixed == 0 && !w->has_ground)
		return FAIL(r, v[SUPPORTS] ? v[SUPPORTS] : root,
			    "the wall has no support (add 'supports: [{ground: {y: 0}}]')");
	if (w->nloads == 0)
		return FAIL(r, v[LOADS] ? v[LOADS] : root,
			    "the wall has no live load (add a 'loads' entry)");
	return 0;
}

/* ------------------------------------------------------------------ edits */

/* wallfile_load_edited: each edit changes the document before the walk,
 * as editing the file would.  Nodes are referred to by id, never by
 * pointer: adding a node may move the node array. */

static int reader_load(struct reader *r, const char *buf, size_t len,
		       yaml_document_t *doc);

static void edit_mark(struct reader *r, int id, int k)
{
	yaml_node_t *n = yaml_document_get_node(&r->doc, id);
	n->start_mark.line = n->end_mark.line = EDIT_LINE + (size_t)k;
	n->start_mark.column = n->end_mark.column = 0;
}

/* Copy node id of src (the edit's value) into r->doc; the new id, or 0
 * (out of memory, or nested too deep).  Each node of src is copied once
 * (copied[id - 1] remembers where to): an alias stays a shared
 * reference, as in a file, so that a value of a few hundred bytes with
 * nested aliases cannot expand to gigabytes here (issue 23); the walk's
 * node count then bounds the work, as for a file. */
static int edit_copy(struct reader *r, yaml_document_t *src, int *copied,
		     int id, int k, int depth)
{
	yaml_node_t *n = yaml_document_get_node(src, id);
	int out = 0;
	if (!n || depth > WALLFILE_MAX_DEPTH)
		return 0;
	if (copied[id - 1])
		return copied[id - 1];
	switch (n->type) {
	case YAML_SCALAR_NODE:
		out = yaml_document_add_scalar(&r->doc, NULL,
					       n->data.scalar.value,
					       (int)n->data.scalar.length,
					       n->data.scalar.style);
		copied[id - 1] = out;
		break;
	case YAML_SEQUENCE_NODE: {
		int nitems = (int)(n->data.sequence.items.top -
				   n->data.sequence.items.start);
		out = copied[id - 1] = yaml_document_add_sequence(
			&r->doc, NULL, YAML_FLOW_SEQUENCE_STYLE);
		for (int i = 0; out && i < nitems; i++) {
			n = yaml_document_get_node(src, id);
			int c = edit_copy(r, src, copied,
					  n->data.sequence.items.start[i], k,
					  depth + 1);
			if (!c || !yaml_document_append_sequence_item(&r->doc,
								      out, c))
				return 0;
		}
		break;
	}
	case YAML_MAPPING_NODE: {
		int npairs = (int)(n->data.mapping.pairs.top -
				   n->data.mapping.pairs.start);
		out = copied[id - 1] = yaml_document_add_mapping(
			&r->doc, NULL, YAML_FLOW_MAPPING_STYLE);
		for (int i = 0; out && i < npairs; i++) {
			n = yaml_document_get_node(src, id);
			yaml_node_pair_t p = n->data.mapping.pairs.start[i];
			int kc = edit_copy(r, src, copied, p.key, k, depth + 1);
			int vc = kc ? edit_copy(r, src, copied, p.value, k,
						depth + 1) : 0;
			if (!vc || !yaml_document_append_mapping_pair(&r->doc,
								      out, kc, vc))
				return 0;
		}
		break;
	}
	default:
		return 0;
	}
	if (out)
		edit_mark(r, out, k);
	return out;
}

/* A copy of the whole value val into r->doc (edit_copy). */
static int edit_copy_value(struct reader *r, yaml_document_t *val, int k)
{
	size_t n = (size_t)(val->nodes.top - val->nodes.start);
	int *copied = calloc(n + 1, sizeof *copied);
	if (!copied)
		return 0;
	int id = edit_copy(r, val, copied, 1, k, 0);
	free(copied);
	return id;
}

enum edit_step { STEP_ON, STEP_DONE, STEP_FAIL, STEP_OOM };

/* The component comp of edit k in the mapping cur: put the value val
 * there when it is the last, else find or make the mapping it names
 * (*child). */
static enum edit_step edit_step_mapping(struct reader *r, int k,
					yaml_document_t *val, int cur,
					char *comp, int last, int *child)
{
	yaml_node_t *n = yaml_document_get_node(&r->doc, cur);
	yaml_node_pair_t *pair = NULL;
	for (yaml_node_pair_t *q = n->data.mapping.pairs.start;
	     q < n->data.mapping.pairs.top; q++) {
		yaml_node_t *kn = yaml_document_get_node(&r->doc, q->key);
		if (kn && kn->type == YAML_SCALAR_NODE && key_is(kn, comp))
			pair = q;
	}
	if (last) {
		int v = edit_copy_value(r, val, k);
		if (!v)
			return STEP_OOM;
		n = yaml_document_get_node(&r->doc, cur);
		if (pair) {
			/* (the array did not move: no pair was added to
			 * this mapping) */
			for (yaml_node_pair_t *q = n->data.mapping.pairs.start;
			     q < n->data.mapping.pairs.top; q++) {
				yaml_node_t *kn =
				    yaml_document_get_node(&r->doc, q->key);
				if (kn->type == YAML_SCALAR_NODE &&
				    key_is(kn, comp))
					q->value = v;
			}
		} else {
			int kc = yaml_document_add_scalar(&r->doc, NULL,
				(yaml_char_t *)comp, -1,
				YAML_PLAIN_SCALAR_STYLE);
			if (!kc || !yaml_document_append_mapping_pair(&r->doc,
								      cur, kc,
								      v))
				return STEP_OOM;
			edit_mark(r, kc, k);
		}
		return STEP_DONE;
	}
	if (pair) {
		*child = pair->value;
		return STEP_ON;
	}
	int kc = yaml_document_add_scalar(&r->doc, NULL, (yaml_char_t *)comp,
					  -1, YAML_PLAIN_SCALAR_STYLE);
	int c = yaml_document_add_mapping(&r->doc, NULL,
					  YAML_BLOCK_MAPPING_STYLE);
	if (!kc || !c || !yaml_document_append_mapping_pair(&r->doc, cur, kc, c))
		return STEP_OOM;
	edit_mark(r, kc, k);
	edit_mark(r, c, k);
	*child = c;
	return STEP_ON;
}

/* The component comp of edit k in the list cur: an index, where the
 * value val goes when it is the last, else the node to go on in
 * (*child). */
static enum edit_step edit_step_sequence(struct reader *r, int k,
					 yaml_document_t *val, int cur,
					 const char *comp, int last,
					 int *child)
{
	yaml_node_t *n = yaml_document_get_node(&r->doc, cur);
	long len = (long)(n->data.sequence.items.top -
			  n->data.sequence.items.start);
	char *end;
	errno = 0;
	long idx = strtol(comp, &end, 10);
	if (!isdigit((unsigned char)*comp) || *end || errno || idx >= len) {
		sw_fail(r->err, SW_EINPUT, "%s: '%s' is not an item of a list "
			"of %ld (items count from 0)", r->edits[k].label, comp,
			len);
		return STEP_FAIL;
	}
	if (last) {
		int v = edit_copy_value(r, val, k);
		if (!v)
			return STEP_OOM;
		n = yaml_document_get_node(&r->doc, cur);
		n->data.sequence.items.start[idx] = v;
		return STEP_DONE;
	}
	*child = n->data.sequence.items.start[idx];
	return STEP_ON;
}

/* material.friction given as one number, with a key under it (--set
 * material.friction.bed=0.3): the number is the friction of both kinds of
 * joint, so the value becomes {bed: it, head: it} (the same node twice,
 * as an alias would make it, so that a message about it still points
 * at the file) and the key is set in that mapping (docs/run.md, the
 * overrides).  friction is the scalar node, parent the mapping that
 * holds it under the key "friction".  The new mapping's id, or 0 (out
 * of memory). */
static int edit_friction_mapping(struct reader *r, int k, int parent,
				 int friction)
{
	int map = yaml_document_add_mapping(&r->doc, NULL,
					    YAML_FLOW_MAPPING_STYLE);
	if (!map)
		return 0;
	edit_mark(r, map, k);
	static const char *const kinds[] = {"bed", "head"};
	for (int i = 0; i < 2; i++) {
		int kc = yaml_document_add_scalar(&r->doc, NULL,
			(yaml_char_t *)kinds[i], -1, YAML_PLAIN_SCALAR_STYLE);
		if (!kc || !yaml_document_append_mapping_pair(&r->doc, map, kc,
							      friction))
			return 0;
		edit_mark(r, kc, k);
	}
	yaml_node_t *p = yaml_document_get_node(&r->doc, parent);
	for (yaml_node_pair_t *q = p->data.mapping.pairs.start;
	     q < p->data.mapping.pairs.top; q++) {
		yaml_node_t *kn = yaml_document_get_node(&r->doc, q->key);
		if (q->value == friction && kn->type == YAML_SCALAR_NODE &&
		    key_is(kn, "friction"))
			q->value = map;
	}
	return map;
}

/* Apply edit k: parse its value, find or make the path, put the value
 * there. */
static int edit_apply(struct reader *r, int k)
{
	const struct wallfile_edit *e = &r->edits[k];
	yaml_document_t val;
	char key[256];
	int rc = -1;

	if (strlen(e->key) >= sizeof key || !*e->key) {
		sw_fail(r->err, SW_EINPUT, "%s: not a key of a wall file",
			e->label);
		return -1;
	}
	/* the value goes through the file's limits, its messages read
	 * "LABEL:LINE:COLUMN: ..." (LINE and COLUMN in the value) */
	struct reader vr;
	char verr[SW_ERRLEN];
	memset(&vr, 0, sizeof vr);
	vr.name = "";
	vr.err = verr;
	if (reader_load(&vr, e->value, strlen(e->value), &val)) {
		/* verr is ":LINE:COLUMN: what"; the label may be long */
		int cut = strlen(e->label) > 80;
		sw_fail(r->err, SW_EINPUT, "%.*s%s: not a YAML value: %s",
			cut ? 77 : 80, e->label, cut ? "..." : "",
			verr + (verr[0] == ':'));
		return -1;
	}
	if (!yaml_document_get_root_node(&val)) {
		sw_fail(r->err, SW_EINPUT, "%s: no value", e->label);
		goto out;
	}

	/* walk the path; make the mappings it lacks */
	snprintf(key, sizeof key, "%s", e->key);
	int cur = 1, parent = 0;	/* the root, and the node above */
	char *save = NULL;
	char *comp = strtok_r(key, ".", &save);
	while (comp) {
		char *next = strtok_r(NULL, ".", &save);
		yaml_node_t *n = yaml_document_get_node(&r->doc, cur);
		enum edit_step st;
		int from = cur;
		if (n->type == YAML_MAPPING_NODE) {
			st = edit_step_mapping(r, k, &val, cur, comp, !next,
					       &cur);
		} else if (n->type == YAML_SEQUENCE_NODE) {
			st = edit_step_sequence(r, k, &val, cur, comp, !next,
						&cur);
		} else if (comp - key == (ptrdiff_t)strlen("material.friction.") &&
			   !strncmp(e->key, "material.friction.", (size_t)(comp - key))) {
			from = edit_friction_mapping(r, k, parent, cur);
			if (!from)
				goto oom;
			st = edit_step_mapping(r, k, &val, from, comp, !next,
					       &cur);
		} else {
			sw_fail(r->err, SW_EINPUT, "%s: '%s' is inside a "
				"single value, which has no keys", e->label,
				comp);
			goto out;
		}
		if (st == STEP_OOM)
			goto oom;
		if (st != STEP_ON) {
			rc = st == STEP_DONE ? 0 : -1;
			goto out;
		}
		parent = from;
		comp = next;
	}
	sw_fail(r->err, SW_EINPUT, "%s: not a key of a wall file", e->label);
	goto out;
oom:
	sw_fail(r->err, SW_EINPUT, "%s: cannot apply (out of memory, or the "
		"value is nested too deeply)", e->label);
out:
	yaml_document_delete(&val);
	return rc;
}

/* ------------------------------------------------------------------ entry */

/* Pass 1: nesting depth and event count, before libyaml builds a
 * document (see the top of the file). */
static int wallfile_prescan(struct reader *r, const char *buf, size_t len)
{
	yaml_parser_t p;
	yaml_event_t ev;
	int depth = 0, rc = 0;
	long events = 0;

	yaml_parser_initialize(&p);
	yaml_parser_set_input_string(&p, (const unsigned char *)buf, len);
	for (;;) {
		if (!yaml_parser_parse(&p, &ev)) {
			rc = reader_yaml_error(r, &p, buf, len);
			break;
		}
		yaml_event_type_t t = ev.type;
		if (t == YAML_ALIAS_EVENT)
			reader_mark(r, ev.data.alias.anchor, 1, ev.start_mark);
		else if (t == YAML_SCALAR_EVENT)
			reader_mark(r, ev.data.scalar.anchor, 0, ev.start_mark);
		else if (t == YAML_SEQUENCE_START_EVENT)
			reader_mark(r, ev.data.sequence_start.anchor, 0,
				    ev.start_mark);
		else if (t == YAML_MAPPING_START_EVENT)
			reader_mark(r, ev.data.mapping_start.anchor, 0,
				    ev.start_mark);
		if (t == YAML_SEQUENCE_START_EVENT ||
		    t == YAML_MAPPING_START_EVENT) {
			if (++depth > WALLFILE_MAX_DEPTH)
				rc = reader_fail_at(r, ev.start_mark,
						    "nested deeper than %d levels",
						    WALLFILE_MAX_DEPTH);
		} else if (t == YAML_SEQUENCE_END_EVENT ||
			   t == YAML_MAPPING_END_EVENT) {
			depth--;
		}
		if (++events > WALLFILE_MAX_NODES && !rc)
			rc = reader_fail_at(r, ev.start_mark,
					    "the document has more than %d nodes",
					    WALLFILE_MAX_NODES);
		yaml_event_delete(&ev);
		if (rc || t == YAML_STREAM_END_EVENT)
			break;
	}
	yaml_parser_delete(&p);
	return rc;
}

/* The one way this program parses YAML (a wall file, a --set value):
 * the size, depth and event limits of wallfile_prescan, then the
 * document into *doc (which the caller deletes), and no second
 * document.  -1 and r->err on any error, *doc then empty. */
static int reader_load(struct reader *r, const char *buf, size_t len,
		       yaml_document_t *doc)
{
	yaml_parser_t p;
	yaml_document_t extra;
	int rc = 0;

	memset(doc, 0, sizeof *doc);
	if (len > WALLFILE_MAX_BYTES) {
		sw_fail(r->err, SW_EINPUT, "%s: larger than %u bytes",
			r->name, WALLFILE_MAX_BYTES);
		return -1;
	}
	if (wallfile_prescan(r, buf, len))
		return -1;
	yaml_parser_initialize(&p);
	yaml_parser_set_input_string(&p, (const unsigned char *)buf, len);
	if (!yaml_parser_load(&p, doc)) {
		r->nmarks = 0;	/* a syntax error, not a value's */
		reader_yaml_error(r, &p, buf, len);
		yaml_parser_delete(&p);
		memset(doc, 0, sizeof *doc);
		return -1;
	}
	/* a second document is a mistake, not something to ignore */
	if (!yaml_parser_load(&p, &extra)) {
		rc = reader_yaml_error(r, &p, buf, len);
	} else {
		yaml_node_t *root2 = yaml_document_get_root_node(&extra);
		if (root2)
			rc = reader_fail_at(r, root2->start_mark,
					    "a wall file holds one YAML "
					    "document; here starts another");
		yaml_document_delete(&extra);
	}
	yaml_parser_delete(&p);
	if (rc) {
		yaml_document_delete(doc);
		memset(doc, 0, sizeof *doc);
	}
	return rc;
}

/* The parser wallkeep_patch takes (wallkeep.h, wallkeep_yaml_fn). */
static int wallfile_yaml_load(const char *buf, size_t len, const char *name,
			      yaml_document_t *doc, char *err)
{
	struct reader r;
	memset(&r, 0, sizeof r);
	r.name = name;
	r.err = err;
	return reader_load(&r, buf, len, doc);
}

static enum sw_status parse_edited(const char *buf, size_t len,
				   const char *name,
				   const struct wallfile_edit *edits,
				   int nedits, struct wall **out, char *err)
{
	struct reader r;
	int rc = 0;

	*out = NULL;
	memset(&r, 0, sizeof r);
	r.name = name ? name : "<wall>";
	r.err = err;
	r.track = 1;
	if (len > WALLFILE_MAX_BYTES)
		return sw_fail(err, SW_EINPUT,
			       "%s: file is larger than %u bytes", r.name,
			       WALLFILE_MAX_BYTES);
	if (reader_load(&r, buf, len, &r.doc)) {
		free(r.marks);
		return SW_EINPUT;
	}
	yaml_node_t *root = yaml_document_get_root_node(&r.doc);
	if (!root) {
		sw_fail(err, SW_EINPUT, "%s:1:1: the file is empty", r.name);
		rc = -1;
		goto out;
	}

	r.edits = edits;
	r.nedits = nedits;
	for (int k = 0; k < nedits && !rc; k++) {
		if (root->type != YAML_MAPPING_NODE) {
			FAIL(&r, root, "the top level must be a mapping, not %s",
			     kind_of(root));
			rc = -1;
		} else {
			rc = edit_apply(&r, k);
		}
		root = yaml_document_get_root_node(&r.doc);
	}
	if (rc)
		goto out;

	r.w = wall_new();
	r.w->path = sw_xstrdup(r.name);
	r.visits = 0;
	if (!(root = reader_node(&r, 1)) || read_wall(&r, root) ||
	    wall_finish(r.w, err) != SW_OK) {
		rc = -1;
		wall_free(r.w);
		r.w = NULL;
	}
out:
	yaml_document_delete(&r.doc);
	free(r.marks);
	if (rc)
		return SW_EINPUT;
	*out = r.w;
	return SW_OK;
}

enum sw_status wallfile_parse(const char *buf, size_t len, const char *name,
			      struct wall **out, char *err)
{
	return parse_edited(buf, len, name, NULL, 0, out, err);
}

enum sw_status wallfile_load(const char *path, struct wall **out, char *err)
{
	return wallfile_load_edited(path, NULL, 0, out, err);
}

enum sw_status wallfile_load_edited(const char *path,
				    const struct wallfile_edit *edits,
				    int nedits, struct wall **out, char *err)
{
	*out = NULL;
	FILE *f = fopen(path, "rb");
	if (!f)
		return sw_fail(err, SW_EINPUT, "%s: cannot read: %s", path,
			       strerror(errno));
	struct stat st;
	if (fstat(fileno(f), &st) == 0 && S_ISREG(st.st_mode) &&
	    (unsigned long long)st.st_size > WALLFILE_MAX_BYTES) {
		fclose(f);
		return sw_fail(err, SW_EINPUT,
			       "%s: file is larger than %u bytes", path,
			       WALLFILE_MAX_BYTES);
	}
	/* read at most one byte more than allowed: works for pipes too */
	size_t cap = 1 << 16, len = 0;
	char *buf = sw_xmalloc(cap);
	for (;;) {
		if (len == cap) {
			if (cap > WALLFILE_MAX_BYTES)
				break;
			cap *= 2;
			buf = sw_xrealloc(buf, cap);
		}
		size_t got = fread(buf + len, 1, cap - len, f);
		len += got;
		if (got == 0)
			break;
	}
	if (ferror(f)) {
		int e = errno;
		free(buf);
		fclose(f);
		return sw_fail(err, SW_EINPUT, "%s: cannot read: %s", path,
			       strerror(e));
	}
	fclose(f);
	if (len > WALLFILE_MAX_BYTES) {
		free(buf);
		return sw_fail(err, SW_EINPUT,
			       "%s: file is larger than %u bytes", path,
			       WALLFILE_MAX_BYTES);
	}
	enum sw_status st2 = parse_edited(buf, len, path, edits, nedits, out,
					  err);
	free(buf);
	return st2;
}

/* ----------------------------------------------------------------- saving */

/* The code point at s (UTF-8) in *cp; its length, or 1 with *cp = -1
 * for a byte that does not start a valid sequence. */
static int save_utf8(const unsigned char *s, long *cp)
{
	int n = s[0] < 0x80 ? 1 : (s[0] & 0xe0) == 0xc0 ? 2 :
		(s[0] & 0xf0) == 0xe0 ? 3 : (s[0] & 0xf8) == 0xf0 ? 4 : 0;
	static const long least[] = {0, 0, 0x80, 0x800, 0x10000};
	long c = n == 1 ? s[0] : n ? s[0] & (0x7f >> n) : -1;
	for (int i = 1; i < n && c >= 0; i++)
		c = (s[i] & 0xc0) == 0x80 ? c << 6 | (s[i] & 0x3f) : -1;
	if (!n || c < least[n] || c > 0x10ffff || (c >= 0xd800 && c <= 0xdfff))
		c = -1;
	*cp = c;
	return c < 0 ? 1 : n;
}

/* A YAML double-quoted string that reads back to the same bytes.  YAML
 * folds line breaks in a quoted scalar to spaces and refuses characters
 * that are not printable, so everything but printable characters that
 * are no line break is escaped: C0 (tab and newline too), DEL, C1
 * (U+0085, NEL, is a YAML line break), U+2028 and U+2029 (line breaks),
 * the byte order mark U+FEFF, U+FFFE and U+FFFF.  A byte that is not
 * UTF-8 (no wall file can hold one) becomes U+FFFD. */
static void save_string(FILE *f, const char *s)
{
	fputc('"', f);
	for (const unsigned char *p = (const unsigned char *)s; *p;) {
		long c;
		int n = save_utf8(p, &c);
		if (c == '"' || c == '\\')
			fprintf(f, "\\%c", (int)c);
		else if (c < 0)
			fputs("\\uFFFD", f);
		else if (c < 0x20 || (c >= 0x7f && c <= 0x9f))
			fprintf(f, "\\x%02lx", c);
		else if (c == 0x2028 || c == 0x2029 || c == 0xfeff ||
			 c == 0xfffe || c == 0xffff)
			fprintf(f, "\\u%04lX", c);
		else
			fwrite(p, 1, (size_t)n, f);
		p += n;
	}
	fputc('"', f);
}

/* Numbers as the shortest of %.15g, %.16g, %.17g that strtod reads back
 * to the same double (0.7, not 0.69999999999999996).  A ring of buffers,
 * so that one fprintf can take several. */
struct save_nums {
	char b[8][32];
	int k;
};

static const char *num(struct save_nums *s, double v)
{
	char *p = s->b[s->k++ % 8];
	for (int prec = 15; prec <= 17; prec++) {
		snprintf(p, 32, "%.*g", prec, v);
		if (strtod(p, NULL) == v)
			break;
	}
	return p;
}

static void save_polygon(FILE *f, const double *xy, int nv)
{
	struct save_nums ns = {.k = 0};
	fputc('[', f);
	for (int i = 0; i < nv; i++)
		fprintf(f, "%s[%s, %s]", i ? ", " : "", num(&ns, xy[2 * i]),
			num(&ns, xy[2 * i + 1]));
	fputc(']', f);
}

/* Is w its layout plus edits?  1 when its free blocks are the layout's
 * blocks in the layout's order (same vertices, some left out: *omit,
 * malloc'd indices into the layout's blocks) followed by blocks of their
 * own; *gen (the generated blocks, to free) then names them. */
static int save_layout_plan(const struct wall *w, struct wall **gen,
			    int **omit, int *nomit)
{
	char err[SW_ERRLEN];
	struct wall_mark none = {0, 0};
	*gen = NULL;
	*omit = NULL;
	*nomit = 0;
	if (!w->layout.present)
		return 0;
	struct wall *g = wall_new();
	g->layout = w->layout;
	if (layout_generate(g, none, err) != SW_OK) {
		wall_free(g);
		return 0;
	}
	int *om = sw_xmalloc(sizeof(int) * (size_t)(g->nblocks + 1));
	int j = 0, n = 0, ok = 1, extra = 0;
	for (int k = 0; k < w->nblocks && ok; k++) {
		const struct wall_block *b = &w->blocks[k];
		if (b->fixed)
			continue;
		int q = j;
		while (q < g->nblocks && strcmp(g->blocks[q].id, b->id))
			q++;
		if (q == g->nblocks) {
			/* not generated; no generated block may follow */
			for (int i = 0; i < g->nblocks && ok; i++)
				ok = strcmp(g->blocks[i].id, b->id) != 0;
			extra = 1;
			continue;
		}
		const struct wall_block *gb = &g->blocks[q];
		ok = !extra && gb->nv == b->nv &&
		     !memcmp(gb->xy, b->xy, sizeof(double) * 2 * (size_t)b->nv);
		while (j < q)
			om[n++] = j++;
		j = q + 1;
	}
	while (ok && j < g->nblocks)
		om[n++] = j++;
	if (!ok) {
		free(om);
		wall_free(g);
		return 0;
	}
	*gen = g;
	*omit = om;
	*nomit = n;
	return 1;
}

static void save_layout(FILE *f, const struct wall *w, const struct wall *g,
			const int *omit, int nomit)
{
	struct save_nums ns = {.k = 0};
	const struct wall_layout *l = &w->layout;
	fprintf(f, "layout:\n");
	fprintf(f, "  block: [%s, %s]\n", num(&ns, l->block_w), num(&ns, l->block_h));
	fprintf(f, "  courses: %d\n", l->courses);
	fprintf(f, "  length: %s\n", num(&ns, l->length));
	fprintf(f, "  bond: %s\n", l->bond == BOND_RUNNING ? "running" : "stack");
	fprintf(f, "  first_course: %s\n", l->first_half ? "half" : "full");
	if (l->x0 != 0 || l->y0 != (w->has_ground ? w->ground_y : 0))
		fprintf(f, "  origin: [%s, %s]\n", num(&ns, l->x0), num(&ns, l->y0));
	if (nomit) {
		fprintf(f, "  omit: [");
		for (int i = 0; i < nomit; i++) {
			fputs(i ? ", " : "", f);
			save_string(f, g->blocks[omit[i]].id);
		}
		fprintf(f, "]\n");
	}
}

static void save_wall(FILE *f, const struct wall *w)
{
	fputs("# slipwall wall file (docs/wall-format.md); written by slipwall\n",
	      f);
	if (w->name) {
		fputs("name: ", f);
		save_string(f, w->name);
		fputc('\n', f);
	}
	struct save_nums ns = {.k = 0};
	fprintf(f, "material:\n");
	fprintf(f, "  friction: {bed: %s, head: %s", num(&ns, w->mu_bed),
		num(&ns, w->mu_head));
	if (w->mu_cov > 0)
		fprintf(f, ", cov: %s", num(&ns, w->mu_cov));
	fprintf(f, "}\n");
	fprintf(f, "  unit_weight: %s\n", num(&ns, w->unit_weight));
	fprintf(f, "  thickness: %s\n", num(&ns, w->thickness));

	struct wall *g;
	int *omit, nomit;
	int as_layout = save_layout_plan(w, &g, &omit, &nomit);
	if (as_layout)
		save_layout(f, w, g, omit, nomit);
	int nfree = 0, nfixed = 0;
	for (int k = 0; k < w->nblocks; k++) {
		if (k == w->ground_block)
			continue;
		/* with a layout, only the blocks of their own */
		int gen = 0;
		for (int i = 0; as_layout && i < g->nblocks && !gen; i++)
			gen = !strcmp(g->blocks[i].id, w->blocks[k].id);
		nfree += !w->blocks[k].fixed && !gen;
		nfixed += w->blocks[k].fixed;
	}
	if (nfree) {
		fprintf(f, "blocks:\n");
		for (int k = 0; k < w->nblocks; k++) {
			const struct wall_block *b = &w->blocks[k];
			int gen = 0;
			for (int i = 0; as_layout && i < g->nblocks && !gen; i++)
				gen = !strcmp(g->blocks[i].id, b->id);
			if (b->fixed || gen)
				continue;
			fputs("  - {id: ", f);
			save_string(f, b->id);
			fputs(", vertices: ", f);
			save_polygon(f, b->xy, b->nv);
			fputs("}\n", f);
		}
	}
	if (w->has_ground || nfixed) {
		fprintf(f, "supports:\n");
		if (w->has_ground)
			fprintf(f, "  - ground: {y: %s}\n", num(&ns, w->ground_y));
		for (int k = 0; k < w->nblocks; k++) {
			const struct wall_block *b = &w->blocks[k];
			if (!b->fixed || k == w->ground_block)
				continue;
			fputs("  - {id: ", f);
			save_string(f, b->id);
			fputs(", vertices: ", f);
			save_polygon(f, b->xy, b->nv);
			fputs("}\n", f);
		}
	}
	if (w->nloads) {
		fprintf(f, "loads:\n");
		for (int l = 0; l < w->nloads; l++) {
			const struct wall_load *ld = &w->loads[l];
			if (ld->kind == LOAD_POINT)
				fprintf(f, "  - point: {at: [%s, %s], direction: [%s, %s], magnitude: %s}\n",
					num(&ns, ld->at[0]), num(&ns, ld->at[1]),
					num(&ns, ld->dir[0]), num(&ns, ld->dir[1]),
					num(&ns, ld->magnitude));
			else
				fprintf(f, "  - body: {direction: [%s, %s], magnitude: %s}\n",
					num(&ns, ld->dir[0]), num(&ns, ld->dir[1]),
					num(&ns, ld->magnitude));
		}
	}
	fprintf(f, "contacts:\n");
	fprintf(f, "  depth: %s\n", num(&ns, w->depth));
	fprintf(f, "  positions: %s\n", w->anywhere ? "anywhere" : "depth");
	fprintf(f, "analysis:\n");
	fprintf(f, "  samples: %d\n", w->samples);
	fprintf(f, "  seed: %lu\n", w->seed);
	if (w->design_load > 0)
		fprintf(f, "  design_load: %.17g\n", w->design_load);
	if (w->ntests) {
		fprintf(f, "tests:\n  loads: [");
		for (int i = 0; i < w->ntests; i++)
			fprintf(f, "%s%s", i ? ", " : "", num(&ns, w->tests[i]));
		fprintf(f, "]\n");
	}
	free(omit);
	wall_free(g);
}

/* w as save_wall writes it, in memory (malloc'd, NUL-terminated). */
static char *save_text(const struct wall *w, size_t *len)
{
	char *buf = NULL;
	FILE *f = open_memstream(&buf, len);
	if (!f)
		return NULL;
	save_wall(f, w);
	if (fclose(f) != 0) {
		free(buf);
		return NULL;
	}
	return buf;
}

/* The wall file w was read from, when it is a regular file of at most
 * WALLFILE_MAX_BYTES (O_NONBLOCK: a FIFO there cannot block the save);
 * malloc'd, NUL-terminated, or NULL. */
static char *save_source(const char *path, size_t *len)
{
	int fd = path ? open(path, O_RDONLY | O_NONBLOCK | O_NOCTTY) : -1;
	struct stat st;
	char *buf = NULL;
	if (fd < 0)
		return NULL;
	if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) &&
	    (unsigned long long)st.st_size <= WALLFILE_MAX_BYTES) {
		size_t n = (size_t)st.st_size, got = 0;
		buf = sw_xmalloc(n + 1);
		while (got < n) {
			ssize_t r = read(fd, buf + got, n - got);
			if (r <= 0)
				break;
			got += (size_t)r;
		}
		buf[got] = 0;
		*len = got;
	}
	close(fd);
	return buf;
}

/* Does text load to the model that save_wall writes as want? */
static int save_loads_as(const char *text, size_t len, const char *want)
{
	char err[SW_ERRLEN];
	struct wall *w;
	size_t n;
	if (wallfile_parse(text, len, "<saved>", &w, err) != SW_OK)
		return 0;
	char *got = save_text(w, &n);
	int same = got && !strcmp(got, want);
	free(got);
	wall_free(w);
	return same;
}

/* The text to save for w, new (save_wall's): the file w was read from
 * when w is its model, that file with the changed values patched in
 * place (wallkeep.c) when that loads to w, else new under the file's
 * top comments.  See docs/wall-format.md, "Saving". */
static char *save_keeping(const struct wall *w, char *new, size_t *len)
{
	size_t olen, xlen;
	char err[SW_ERRLEN];
	struct wall *w0;
	char *orig = save_source(w->path, &olen);
	if (!orig)
		return new;
	if (wallfile_parse(orig, olen, w->path, &w0, err) != SW_OK) {
		free(orig);
		return new;
	}
	char *old = save_text(w0, &xlen);
	wall_free(w0);
	char *out = NULL;
	if (old && !strcmp(old, new)) {
		out = orig;		/* nothing changed */
		*len = olen;
		orig = NULL;
	} else if (old) {
		size_t plen;
		char *p = wallkeep_patch(orig, olen, old, xlen, new, *len,
					 &plen, wallfile_yaml_load);
		if (p && save_loads_as(p, plen, new)) {
			out = p;
			*len = plen;
		} else {
			free(p);
		}
	}
	if (!out) {		/* anew, under the file's top comments */
		size_t h = wallkeep_header(orig, olen);
		/* which take the place of the writer's own first line */
		const char *nl = strchr(new, '\n');
		size_t skip = h && nl ? (size_t)(nl + 1 - new) : 0;
		out = sw_xmalloc(h + *len - skip + 1);
		memcpy(out, orig, h);
		memcpy(out + h, new + skip, *len - skip + 1);
		*len += h - skip;
	}
	free(old);
	free(orig);
	free(new);
	return out;
}

enum sw_status wallfile_save(const struct wall *w, const char *path,
			     char *err)
{
	size_t len;
	char *text = save_text(w, &len);
	if (!text)
		return sw_fail(err, SW_EIO, "%s: out of memory", path);
	text = save_keeping(w, text, &len);
	struct outfile out;
	enum sw_status st = outfile_open(&out, path, NULL, 0, "the wall",
					 err);
	if (st == SW_OK) {
		fwrite(text, 1, len, out.f);
		st = outfile_commit(&out, err);
	}
	free(text);
	return st;
}
