/*
 * plot.h - the plotting kit of the report's figures (private to
 * src/lib/): what a figure is drawn on, its colours, axes, legends,
 * captions and curves.  report.c draws the paper's figures with it; the
 * kit knows nothing of loads or walls.
 *
 * Units are points (1/72 in): a figure is FIG_W wide, a one-plot figure
 * PLOT_H high plus its caption lines.  Every text goes through
 * plot_text(), which records it for the SVG's text layer
 * (plot_svg_text_layer); free the record with plot_labels_clear().
 */
#ifndef SLIPWALL_PLOT_H
#define SLIPWALL_PLOT_H

#include <stddef.h>
#include <cairo.h>

#include "slipwall/status.h"

#define FIG_W 480.0		/* figure width, pt */
#define PLOT_H 300.0		/* a single plot figure's height, pt */

/* ---- colours ------------------------------------------------------------ */

struct rgb {
	double r, g, b;
};
/* Okabe & Ito (2008), "Color Universal Design" */
static const struct rgb C_BLACK = {0, 0, 0};
static const struct rgb C_ORANGE = {0.902, 0.624, 0.0};
static const struct rgb C_SKY = {0.337, 0.706, 0.914};
static const struct rgb C_GREEN = {0.0, 0.620, 0.451};
static const struct rgb C_BLUE = {0.0, 0.447, 0.698};
static const struct rgb C_VERMILLION = {0.835, 0.369, 0.0};
static const struct rgb C_PURPLE = {0.800, 0.475, 0.655};
static const struct rgb C_GREY = {0.55, 0.55, 0.55};

#define C_MODEL C_VERMILLION
#define C_TESTS C_BLACK

void plot_rgb(cairo_t *cr, struct rgb c, double alpha);

/* ---- a figure being drawn, and its text layer ---------------------------- */

struct label {
	char *s;
	double x, y, size, angle;	/* baseline start, pt, degrees */
	int bold;
};

struct fig {
	cairo_t *cr;
	double w, h;
	struct label *lab;	/* what plot_text drew, for the SVG */
	int nlab, caplab;
};

/* Draw text at (x, y) anchored at (ax, ay) of its box (0 left/top,
 * 0.5 centre, 1 right/bottom), rotated by angle degrees
 * (counter-clockwise on the page), and record it for the text layer. */
void plot_text(struct fig *f, double x, double y, double size, int bold,
	       double ax, double ay, double angle, const char *fmt, ...)
	__attribute__((format(printf, 9, 10)));
void plot_labels_clear(struct fig *f);
/* Splice the recorded labels into the SVG file PATH before its </svg>;
 * errors name NAME (the figure's final name). */
enum sw_status plot_svg_text_layer(const char *path, const char *name,
				   const struct fig *f, char *err);
/* Paint the page white (and leave black as the source). */
void plot_white(struct fig *f);
/* Caption lines under the plot, left-aligned. */
void plot_caption(struct fig *f, double y, const char *s);

/* ---- axes ------------------------------------------------------------------ */

struct axes {
	double x, y, w, h;	/* the plot box on the page, pt */
	double x0, x1, y0, y1;	/* the data range */
};

/* Data to page coordinates. */
double plot_x(const struct axes *a, double v);
double plot_y(const struct axes *a, double v);
/* Frame, grid, ticks and the axis labels; title above. */
void plot_axes(struct fig *f, const struct axes *a, const char *xlabel,
	       const char *ylabel, const char *title, int xticks_int);
/* Clip to the plot box (cairo_save'd: cairo_restore ends it). */
void plot_clip(cairo_t *cr, const struct axes *a);
/* The standard plot box of a one-plot figure with `cap` caption lines,
 * and that figure's height. */
struct axes plot_box(int cap);
double plot_height(int cap);
/* The largest finite x[i], at least 0. */
double plot_max(const double *x, int n);
/* A curve y(x) on n points (a gap where y is not finite). */
void plot_curve(cairo_t *cr, const struct axes *a, const double *x,
		const double *y, int n);

/* ---- legends ---------------------------------------------------------------- */

/* A legend in a corner of the plot: where = LG_LEFT | LG_BOTTOM bits
 * (0: top right). */
#define LG_LEFT 1
#define LG_BOTTOM 2
enum lg_style { LG_LINE, LG_THIN, LG_DASH, LG_BAND, LG_BAR };
struct lg_item {
	enum lg_style style;
	struct rgb c;
	const char *text;
};

/* Set the line of a style in colour c. */
void plot_style(cairo_t *cr, enum lg_style s, struct rgb c);
void plot_legend(struct fig *f, const struct axes *a, const struct lg_item *it,
		 int n, int where);

#endif
