/*
 * plot.c - the plotting kit of the report's figures: colours, text that
 * also goes into the SVG's searchable text layer, axes with ticks and
 * grid, legends, captions, curves.  See plot.h; report.c draws the
 * figures with it.
 *
 * The SVG text layer: cairo 1.16 writes text into SVG as glyph outlines,
 * so the numbers on a figure could not be searched or checked.  Every
 * label goes through plot_text(), which also records it; after the SVG
 * surface is finished, plot_svg_text_layer() splices the recorded labels
 * in before </svg> as transparent <text> elements at the same place and
 * size.
 */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "plot.h"
#include "slipwall/status.h"
#include "slipwall/text.h"

/* ---- colours ------------------------------------------------------------ */

void plot_rgb(cairo_t *cr, struct rgb c, double alpha)
{
	cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha);
}

/* ---- a figure being drawn, and its text layer ---------------------------- */

void plot_labels_clear(struct fig *f)
{
	for (int i = 0; i < f->nlab; i++)
		free(f->lab[i].s);
	free(f->lab);
	f->lab = NULL;
	f->nlab = f->caplab = 0;
}

void plot_text(struct fig *f, double x, double y, double size, int bold,
	       double ax, double ay, double angle, const char *fmt, ...)
{
	char buf[512];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(buf, sizeof buf, fmt, ap);
	va_end(ap);
	cairo_t *cr = f->cr;
	cairo_save(cr);
	cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
			       bold ? CAIRO_FONT_WEIGHT_BOLD :
			       CAIRO_FONT_WEIGHT_NORMAL);
	cairo_set_font_size(cr, size);
	cairo_text_extents_t te;
	cairo_font_extents_t fe;
	cairo_text_extents(cr, buf, &te);
	cairo_font_extents(cr, &fe);
	/* the box: advance wide, ascent + descent high */
	double dx = -ax * te.x_advance;
	double dy = fe.ascent - ay * (fe.ascent + fe.descent);
	double th = -angle * M_PI / 180;
	cairo_translate(cr, x, y);
	cairo_rotate(cr, th);
	cairo_move_to(cr, dx, dy);
	cairo_show_text(cr, buf);
	cairo_restore(cr);
	if (f->nlab == f->caplab) {
		f->caplab = f->caplab ? 2 * f->caplab : 32;
		f->lab = sw_xrealloc(f->lab, sizeof *f->lab * (size_t)f->caplab);
	}
	struct label *l = &f->lab[f->nlab++];
	l->s = sw_xstrdup(buf);
	l->x = x + dx * cos(th) - dy * sin(th);
	l->y = y + dx * sin(th) + dy * cos(th);
	l->size = size;
	l->angle = -angle;
	l->bold = bold;
}

static void xml_escape(FILE *o, const char *text)
{
	/* no control character: XML 1.0 forbids most of them */
	char *clean = text_clean(text);
	for (const char *s = clean; *s; s++) {
		switch (*s) {
		case '&':
			fputs("&amp;", o);
			break;
		case '<':
			fputs("&lt;", o);
			break;
		case '>':
			fputs("&gt;", o);
			break;
		case '"':
			fputs("&quot;", o);
			break;
		default:
			fputc(*s, o);
		}
	}
	free(clean);
}

/* Splice the recorded labels into the SVG file PATH before its </svg>;
 * errors name NAME (the figure's final name). */
enum sw_status plot_svg_text_layer(const char *path, const char *name,
				   const struct fig *f, char *err)
{
	FILE *in = fopen(path, "rb");
	if (!in)
		return sw_fail(err, SW_EIO, "%s: cannot read back: %s", name,
			       strerror(errno));
	size_t cap = 1 << 16, n = 0, got;
	char *buf = sw_xmalloc(cap);
	while ((got = fread(buf + n, 1, cap - n, in)) > 0) {
		n += got;
		if (n == cap)
			buf = sw_xrealloc(buf, cap *= 2);
	}
	fclose(in);
	char *end = NULL;
	for (size_t i = n >= 6 ? n - 6 + 1 : 0; i-- > 0;)
		if (!memcmp(buf + i, "</svg>", 6)) {
			end = buf + i;
			break;
		}
	if (!end) {
		free(buf);
		return sw_fail(err, SW_EIO, "%s: cairo wrote no </svg>", name);
	}
	FILE *o = fopen(path, "wb");
	if (!o) {
		free(buf);
		return sw_fail(err, SW_EIO, "%s: cannot write: %s", name,
			       strerror(errno));
	}
	fwrite(buf, 1, (size_t)(end - buf), o);
	fprintf(o, "<g id=\"slipwall-text\" fill=\"#000000\" fill-opacity=\"0\" "
		"font-family=\"DejaVu Sans, sans-serif\">\n");
	for (int i = 0; i < f->nlab; i++) {
		const struct label *l = &f->lab[i];
		fprintf(o, "<text x=\"%.2f\" y=\"%.2f\" font-size=\"%.1f\"%s",
			l->x, l->y, l->size, l->bold ? " font-weight=\"bold\"" : "");
		if (l->angle != 0)
			fprintf(o, " transform=\"rotate(%.1f %.2f %.2f)\"",
				l->angle, l->x, l->y);
		fputc('>', o);
		xml_escape(o, l->s);
		fputs("</text>\n", o);
	}
	fputs("</g>\n", o);
	fwrite(end, 1, n - (size_t)(end - buf), o);
	free(buf);
	int bad = ferror(o);
	if (fclose(o) || bad)
		return sw_fail(err, SW_EIO, "%s: cannot write: %s", name,
			       strerror(errno ? errno : EIO));
	return SW_OK;
}

/* ---- axes ------------------------------------------------------------------ */

double plot_x(const struct axes *a, double v)
{
	return a->x + (v - a->x0) / (a->x1 - a->x0) * a->w;
}

double plot_y(const struct axes *a, double v)
{
	return a->y + a->h - (v - a->y0) / (a->y1 - a->y0) * a->h;
}

static double plot_step(double range, int target)
{
	double raw = range / target;
	double mag = pow(10, floor(log10(raw)));
	double r = raw / mag;
	double s = r <= 1 ? 1 : r <= 2 ? 2 : r <= 2.5 ? 2.5 : r <= 5 ? 5 : 10;
	return s * mag;
}

static void plot_tick_label(char *buf, size_t len, double v, double step)
{
	if (fabs(v) < step * 1e-9)
		v = 0;
	snprintf(buf, len, "%g", v);
}

/* Frame, grid, ticks and the axis labels; title above. */
void plot_axes(struct fig *f, const struct axes *a, const char *xlabel,
	       const char *ylabel, const char *title, int xticks_int)
{
	cairo_t *cr = f->cr;
	char b[64];
	double sx = plot_step(a->x1 - a->x0, 6), sy = plot_step(a->y1 - a->y0, 5);
	if (xticks_int && sx < 1)
		sx = 1;
	cairo_set_line_width(cr, 0.5);
	/* counted loops: a step below the ulp of the values cannot hang */
	double x_first = ceil(a->x0 / sx - 1e-9) * sx;
	for (int i = 0; i < 100; i++) {
		double v = x_first + i * sx;
		if (v > a->x1 + 1e-9 * sx)
			break;
		double x = plot_x(a, v);
		plot_rgb(cr, C_GREY, 0.35);
		cairo_move_to(cr, x, a->y);
		cairo_line_to(cr, x, a->y + a->h);
		cairo_stroke(cr);
		plot_rgb(cr, C_BLACK, 1);
		cairo_move_to(cr, x, a->y + a->h);
		cairo_line_to(cr, x, a->y + a->h + 4);
		cairo_stroke(cr);
		plot_tick_label(b, sizeof b, v, sx);
		plot_text(f, x, a->y + a->h + 6, 10, 0, 0.5, 0, 0, "%s", b);
	}
	double y_first = ceil(a->y0 / sy - 1e-9) * sy;
	for (int i = 0; i < 100; i++) {
		double v = y_first + i * sy;
		if (v > a->y1 + 1e-9 * sy)
			break;
		double y = plot_y(a, v);
		plot_rgb(cr, C_GREY, 0.35);
		cairo_move_to(cr, a->x, y);
		cairo_line_to(cr, a->x + a->w, y);
		cairo_stroke(cr);
		plot_rgb(cr, C_BLACK, 1);
		cairo_move_to(cr, a->x - 4, y);
		cairo_line_to(cr, a->x, y);
		cairo_stroke(cr);
		plot_tick_label(b, sizeof b, v, sy);
		plot_text(f, a->x - 6, y, 10, 0, 1, 0.5, 0, "%s", b);
	}
	plot_rgb(cr, C_BLACK, 1);
	cairo_set_line_width(cr, 0.8);
	cairo_rectangle(cr, a->x, a->y, a->w, a->h);
	cairo_stroke(cr);
	if (xlabel)
		plot_text(f, a->x + a->w / 2, a->y + a->h + 21, 11, 0, 0.5, 0, 0,
			  "%s", xlabel);
	if (ylabel)
		plot_text(f, a->x - 56, a->y + a->h / 2, 11, 0, 0.5, 0, 90, "%s",
			  ylabel);
	if (title)
		plot_text(f, a->x, a->y - 6, 12, 1, 0, 1, 0, "%s", title);
}

void plot_clip(cairo_t *cr, const struct axes *a)
{
	cairo_save(cr);
	cairo_rectangle(cr, a->x, a->y, a->w, a->h);
	cairo_clip(cr);
}

void plot_style(cairo_t *cr, enum lg_style s, struct rgb c)
{
	static const double dash[] = {5, 3};
	plot_rgb(cr, c, 1);
	cairo_set_dash(cr, NULL, 0, 0);
	switch (s) {
	case LG_LINE:
		cairo_set_line_width(cr, 2.4);
		break;
	case LG_THIN:
		cairo_set_line_width(cr, 1.0);
		break;
	case LG_DASH:
		cairo_set_line_width(cr, 1.4);
		cairo_set_dash(cr, dash, 2, 0);
		break;
	default:
		cairo_set_line_width(cr, 1.0);
	}
}

void plot_legend(struct fig *f, const struct axes *a, const struct lg_item *it,
		 int n, int where)
{
	cairo_t *cr = f->cr;
	double lh = 13, pad = 5, sw = 22, tw = 0;
	cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL,
			       CAIRO_FONT_WEIGHT_NORMAL);
	cairo_set_font_size(cr, 9.5);
	for (int i = 0; i < n; i++) {
		cairo_text_extents_t te;
		cairo_text_extents(cr, it[i].text, &te);
		tw = fmax(tw, te.x_advance);
	}
	double bw = pad * 3 + sw + tw, bh = pad * 2 + lh * n;
	double x = where & LG_LEFT ? a->x + 6 : a->x + a->w - bw - 6;
	double y = where & LG_BOTTOM ? a->y + a->h - bh - 6 : a->y + 6;
	cairo_set_source_rgba(cr, 1, 1, 1, 0.88);
	cairo_rectangle(cr, x, y, bw, bh);
	cairo_fill_preserve(cr);
	plot_rgb(cr, C_GREY, 1);
	cairo_set_line_width(cr, 0.5);
	cairo_stroke(cr);
	for (int i = 0; i < n; i++) {
		double yy = y + pad + lh * i + lh / 2;
		if (it[i].style == LG_BAND || it[i].style == LG_BAR) {
			plot_rgb(cr, it[i].c, it[i].style == LG_BAND ? 0.35 : 0.45);
			cairo_rectangle(cr, x + pad, yy - 4, sw, 8);
			cairo_fill(cr);
		} else {
			plot_style(cr, it[i].style, it[i].c);
			cairo_move_to(cr, x + pad, yy);
			cairo_line_to(cr, x + pad + sw, yy);
			cairo_stroke(cr);
			cairo_set_dash(cr, NULL, 0, 0);
		}
		plot_rgb(cr, C_BLACK, 1);
		plot_text(f, x + 2 * pad + sw, yy, 9.5, 0, 0, 0.5, 0, "%s",
			  it[i].text);
	}
}

/* Caption lines under the plot, left-aligned. */
void plot_caption(struct fig *f, double y, const char *s)
{
	plot_rgb(f->cr, C_BLACK, 1);
	plot_text(f, 14, y, 9.5, 0, 0, 0, 0, "%s", s);
}

/* A curve y(x) on n points. */
void plot_curve(cairo_t *cr, const struct axes *a, const double *x,
		const double *y, int n)
{
	int pen = 0;
	for (int i = 0; i < n; i++) {
		if (!isfinite(y[i])) {
			pen = 0;
			continue;
		}
		if (pen)
			cairo_line_to(cr, plot_x(a, x[i]), plot_y(a, y[i]));
		else
			cairo_move_to(cr, plot_x(a, x[i]), plot_y(a, y[i]));
		pen = 1;
	}
	cairo_stroke(cr);
}

double plot_max(const double *x, int n)
{
	double m = 0;
	for (int i = 0; i < n; i++)
		if (isfinite(x[i]) && x[i] > m)
			m = x[i];
	return m;
}

void plot_white(struct fig *f)
{
	cairo_set_source_rgb(f->cr, 1, 1, 1);
	cairo_paint(f->cr);
	cairo_set_source_rgb(f->cr, 0, 0, 0);
}

/* The standard plot box of a one-plot figure with `cap` caption lines. */
struct axes plot_box(int cap)
{
	struct axes a = {0};
	a.x = 72;
	a.y = 30;
	a.w = FIG_W - a.x - 16;
	a.h = PLOT_H - a.y - 48 + (cap ? 0 : 0);
	return a;
}

double plot_height(int cap)
{
	return PLOT_H + (cap ? 6 + 13 * cap : 0);
}
