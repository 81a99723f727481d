/* plot.c: <hearth/plot.h>, line and scatter plots on log or linear axes,
 * drawn with Cairo (canvas.c) and written atomically by io_png.c: the one
 * plotting module behind trade, rheometer and fit. It replaced two hand
 * copies of the same log-log code in cmd_rheometer.c and cmd_trade.c, and
 * then the bitmap font and hand-drawn pixels they used; the geometry
 * (margins, grid, legend) stayed, so a point lands where it did. */
#include "hearth/plot.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"

#include "error.h"
#include "canvas.h"

#define PLOT_DIM_MIN 200
#define PLOT_DIM_MAX 8192
/* the frame's margins (pixels): room for the title above, tick labels left and below */
enum { M_LEFT = 78, M_RIGHT = 24, M_TOP = 52, M_BOTTOM = 62, LEGEND_STEP = 17 };

static const unsigned char C_BG[3] = {255, 255, 255}, C_AXIS[3] = {0, 0, 0}, C_GRID[3] = {228, 228, 228},
                           C_MINOR[3] = {243, 243, 243}, C_TEXT[3] = {30, 30, 30};
static const unsigned char PALETTE[8][3] = {{31, 119, 180}, {214, 39, 40},   {44, 160, 44},   {255, 127, 14},
                                            {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {23, 190, 207}};
static const double DOT_R = 3.5, RING_OUT = 7.5, RING_IN = 5.5;

typedef struct series {
    int n;
    double *x, *y;
    char *label;
    char **point_labels; /* n entries or NULL */
    unsigned char color[3];
    hearth_plot_marker marker;
    int line_width, behind;
} series;

struct hearth_plot {
    int w, h;
    char *title, *x_label, *y_label;
    hearth_plot_scale xs, ys;
    hearth_plot_legend_pos legend;
    int n, cap;
    series *s;
};

hearth_plot_def hearth_default_plot_def(void) {
    return (hearth_plot_def){.width = 760, .height = 520, .x_scale = HEARTH_PLOT_LOG, .y_scale = HEARTH_PLOT_LOG,
                             .legend = HEARTH_LEGEND_TOP_LEFT};
}

hearth_plot_series_def hearth_default_plot_series_def(void) {
    hearth_plot_series_def d = {.marker = HEARTH_MARKER_DOT};
    memcpy(d.color, PALETTE[0], 3);
    return d;
}

void hearth_plot_color(int i, unsigned char rgb[3]) { memcpy(rgb, PALETTE[((i % 8) + 8) % 8], 3); }

/* a counted copy of an optional string; *ok cleared when it could not be made */
static char *dup_opt(const char *s, int *ok) {
    if (!s) return NULL;
    char *c = mem_strdup(s);
    if (!c) *ok = 0;
    return c;
}

static void series_free(series *s) {
    mem_free(s->x, sizeof(double) * (size_t)s->n);
    mem_free(s->y, sizeof(double) * (size_t)s->n);
    mem_strfree(s->label);
    if (s->point_labels) {
        for (int i = 0; i < s->n; i++) mem_strfree(s->point_labels[i]);
        mem_free(s->point_labels, sizeof(char *) * (size_t)s->n);
    }
    memset(s, 0, sizeof *s);
}

void hearth_plot_free(hearth_plot *p) {
    if (!p) return;
    for (int i = 0; i < p->n; i++) series_free(&p->s[i]);
    mem_free(p->s, sizeof(series) * (size_t)p->cap);
    mem_strfree(p->title);
    mem_strfree(p->x_label);
    mem_strfree(p->y_label);
    mem_free(p, sizeof *p);
}

hearth_plot *hearth_plot_create(const hearth_plot_def *def, hearth_error *err) {
    if (def->width < PLOT_DIM_MIN || def->width > PLOT_DIM_MAX || def->height < PLOT_DIM_MIN ||
        def->height > PLOT_DIM_MAX) {
        err_set(err, HEARTH_ERR_PARAM, "plot size %d x %d px; valid range [%d, %d] each", def->width, def->height,
                PLOT_DIM_MIN, PLOT_DIM_MAX);
        return NULL;
    }
    if ((unsigned)def->x_scale > HEARTH_PLOT_LINEAR || (unsigned)def->y_scale > HEARTH_PLOT_LINEAR) {
        err_set(err, HEARTH_ERR_PARAM, "plot axis scale %d / %d; valid: HEARTH_PLOT_LOG (0), HEARTH_PLOT_LINEAR (1)",
                (int)def->x_scale, (int)def->y_scale);
        return NULL;
    }
    if ((unsigned)def->legend > HEARTH_LEGEND_NONE) {
        err_set(err, HEARTH_ERR_PARAM, "plot legend position %d; valid: 0 (top left), 1 (bottom left), 2 (none)",
                (int)def->legend);
        return NULL;
    }
    hearth_plot *p = mem_calloc(sizeof *p);
    if (!p) {
        err_set(err, HEARTH_ERR_NOMEM, "out of memory for a plot");
        return NULL;
    }
    int ok = 1;
    p->w = def->width;
    p->h = def->height;
    p->xs = def->x_scale;
    p->ys = def->y_scale;
    p->legend = def->legend;
    p->title = dup_opt(def->title, &ok);
    p->x_label = dup_opt(def->x_label, &ok);
    p->y_label = dup_opt(def->y_label, &ok);
    if (!ok) {
        hearth_plot_free(p);
        err_set(err, HEARTH_ERR_NOMEM, "out of memory for a plot's labels");
        return NULL;
    }
    return p;
}

int hearth_plot_add_series(hearth_plot *p, const hearth_plot_series_def *d, hearth_error *err) {
    if (d->n < 0 || (d->n > 0 && (!d->x || !d->y)))
        return err_set(err, HEARTH_ERR_PARAM, "plot series %d: n = %d with %s; n >= 0 values in x and y", p->n, d->n,
                       d->n < 0 ? "a negative count" : "no x or y array"),
               -1;
    if ((unsigned)d->marker > HEARTH_MARKER_RING)
        return err_set(err, HEARTH_ERR_PARAM, "plot series %d: marker %d; valid: none (0), dot (1), ring (2)", p->n,
                       (int)d->marker),
               -1;
    if (d->line_width < 0 || d->line_width > 2)
        return err_set(err, HEARTH_ERR_PARAM, "plot series %d: line_width %d px; valid range [0, 2]", p->n,
                       d->line_width),
               -1;
    if (p->n == p->cap) {
        int ncap = p->cap ? 2 * p->cap : 4;
        series *ns = mem_realloc(p->s, sizeof(series) * (size_t)p->cap, sizeof(series) * (size_t)ncap);
        if (!ns) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for plot series %d", p->n), -1;
        p->s = ns;
        p->cap = ncap;
    }
    series s = {.n = d->n, .marker = d->marker, .line_width = d->line_width, .behind = d->behind != 0};
    memcpy(s.color, d->color, 3);
    int ok = 1;
    size_t bytes = sizeof(double) * (size_t)d->n;
    if (d->n > 0) {
        s.x = mem_alloc(bytes);
        s.y = mem_alloc(bytes);
        if (s.x) memcpy(s.x, d->x, bytes);
        if (s.y) memcpy(s.y, d->y, bytes);
        ok = s.x && s.y;
    }
    s.label = dup_opt(d->label, &ok);
    if (ok && d->point_labels && d->n > 0) {
        s.point_labels = mem_calloc(sizeof(char *) * (size_t)d->n);
        ok = s.point_labels != NULL;
        for (int i = 0; ok && i < d->n; i++) s.point_labels[i] = dup_opt(d->point_labels[i], &ok);
    }
    if (!ok) {
        series_free(&s);
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory for plot series %d", p->n), -1;
    }
    p->s[p->n] = s;
    return p->n++;
}

/* ---- drawing --------------------------------------------------------------- */

/* One axis: its scale and range, in decades (log) or in the values themselves. */
typedef struct axis {
    hearth_plot_scale scale;
    double lo, hi; /* log10 of the ends on a log axis */
    double step;   /* a linear axis's tick spacing */
} axis;

static int drawable(const axis *a, double v) { return isfinite(v) && (a->scale == HEARTH_PLOT_LINEAR || v > 0); }
static double axis_t(const axis *a, double v) { return a->scale == HEARTH_PLOT_LOG ? log10(v) : v; }

/* 1, 2 or 5 times a power of ten, the smallest not below x */
static double nice_step(double x) {
    double e = pow(10, floor(log10(x))), m = x / e;
    return (m <= 1 ? 1 : m <= 2 ? 2 : m <= 5 ? 5 : 10) * e;
}

/* The range of one axis over every drawable point of every series (one
 * that cannot be drawn stretches neither axis): whole decades, at least one;
 * a linear axis about five steps of 1, 2 or 5 x 10^k. */
static void axis_fit(const hearth_plot *p, int yaxis, axis *a, const axis *other) {
    double mn = INFINITY, mx = -INFINITY;
    for (int k = 0; k < p->n; k++)
        for (int i = 0; i < p->s[k].n; i++) {
            double v = yaxis ? p->s[k].y[i] : p->s[k].x[i], o = yaxis ? p->s[k].x[i] : p->s[k].y[i];
            if (drawable(a, v) && drawable(other, o)) mn = fmin(mn, v), mx = fmax(mx, v);
        }
    if (a->scale == HEARTH_PLOT_LOG) {
        if (!(mn <= mx)) mn = 1, mx = 10;
        a->lo = floor(log10(mn));
        a->hi = ceil(log10(mx));
        if (a->hi <= a->lo) a->hi = a->lo + 1;
        return;
    }
    if (!(mn <= mx)) mn = 0, mx = 1;
    if (mx == mn) { /* one value: a unit-wide window around it */
        double half = mn != 0 ? 0.5 * fabs(mn) : 0.5;
        mn -= half, mx += half;
    }
    a->step = nice_step((mx - mn) / 5);
    a->lo = floor(mn / a->step) * a->step;
    a->hi = ceil(mx / a->step) * a->step;
}

typedef struct frame {
    canvas c;
    int left, top, pw, ph;
    axis ax, ay;
} frame;

#define PX(f, v) ((f)->left + (axis_t(&(f)->ax, v) - (f)->ax.lo) / ((f)->ax.hi - (f)->ax.lo) * (f)->pw)
#define PY(f, v) ((f)->top + (f)->ph - (axis_t(&(f)->ay, v) - (f)->ay.lo) / ((f)->ay.hi - (f)->ay.lo) * (f)->ph)

enum { FS = 12 }; /* label size (px); the title is larger */

/* A one-pixel line that lands on pixel centres (x.5), so a grid line is one
 * crisp row or column, as the bitmap plots had. */
static void line(frame *f, double x0, double y0, double x1, double y1, const unsigned char c[3], double width) {
    cairo_t *cr = f->c.cr;
    if (x0 == x1) x0 = x1 = floor(x0) + 0.5;
    if (y0 == y1) y0 = y1 = floor(y0) + 0.5;
    cairo_move_to(cr, x0, y0);
    cairo_line_to(cr, x1, y1);
    canvas_rgb(&f->c, c, 1);
    cairo_set_line_width(cr, width);
    cairo_stroke(cr);
}

static void disc(frame *f, double x, double y, double r, const unsigned char c[3]) {
    cairo_arc(f->c.cr, x, y, r, 0, 2 * CANVAS_PI);
    canvas_rgb(&f->c, c, 1);
    cairo_fill(f->c.cr);
}

static void decade_label(int k, char *buf, size_t n) {
    if (k >= -2 && k <= 3) snprintf(buf, n, "%g", pow(10, k));
    else snprintf(buf, n, "1e%d", k);
}

static void x_tick_label(frame *f, double px, const char *s) {
    canvas_text(&f->c, px, f->top + f->ph + 9, s, FS, CANVAS_CENTER, CANVAS_TOP, 0, C_TEXT);
}
static void y_tick_label(frame *f, double py, const char *s) {
    canvas_text(&f->c, f->left - 9, py, s, FS, CANVAS_RIGHT, CANVAS_MIDDLE, 0, C_TEXT);
}

/* Log axes: light lines at 2..9 of every decade (labelled at 2 and 5 when the
 * axis spans two decades or fewer, else a short axis reads as two numbers),
 * darker lines, ticks and labels at the decades. */
static void grid_log(frame *f, int yaxis) {
    const axis *a = yaxis ? &f->ay : &f->ax;
    const int top = f->top, left = f->left, pw = f->pw, ph = f->ph;
    char buf[64];
    int minor_labels = a->hi - a->lo <= 2;
    for (int k = (int)a->lo; k < (int)a->hi; k++)
        for (int j = 2; j <= 9; j++) {
            double v = j * pow(10, k);
            if (yaxis) {
                double py = PY(f, v);
                line(f, left, py, left + pw, py, C_MINOR, 1);
                if (minor_labels && (j == 2 || j == 5)) snprintf(buf, sizeof buf, "%g", v), y_tick_label(f, py, buf);
            } else {
                double px = PX(f, v);
                line(f, px, top, px, top + ph, C_MINOR, 1);
                if (minor_labels && (j == 2 || j == 5)) snprintf(buf, sizeof buf, "%g", v), x_tick_label(f, px, buf);
            }
        }
}

static void major_log(frame *f, int yaxis) {
    const axis *a = yaxis ? &f->ay : &f->ax;
    const int top = f->top, left = f->left, pw = f->pw, ph = f->ph;
    char buf[64];
    for (int k = (int)a->lo; k <= (int)a->hi; k++) {
        decade_label(k, buf, sizeof buf);
        if (yaxis) {
            double py = PY(f, pow(10, k));
            line(f, left, py, left + pw, py, C_GRID, 1);
            line(f, left - 5, py, left, py, C_AXIS, 1);
            y_tick_label(f, py, buf);
        } else {
            double px = PX(f, pow(10, k));
            line(f, px, top, px, top + ph, C_GRID, 1);
            line(f, px, top + ph, px, top + ph + 5, C_AXIS, 1);
            x_tick_label(f, px, buf);
        }
    }
}

/* Linear axes: a line, tick and label at every step. */
static void major_linear(frame *f, int yaxis) {
    const axis *a = yaxis ? &f->ay : &f->ax;
    const int top = f->top, left = f->left, pw = f->pw, ph = f->ph;
    char buf[64];
    long n = lround((a->hi - a->lo) / a->step);
    for (long k = 0; k <= n; k++) {
        double v = a->lo + (double)k * a->step;
        if (fabs(v) < 1e-9 * a->step) v = 0; /* no "-0" or "1e-17" at the origin */
        snprintf(buf, sizeof buf, "%g", v);
        if (yaxis) {
            double py = PY(f, v);
            line(f, left, py, left + pw, py, C_GRID, 1);
            line(f, left - 5, py, left, py, C_AXIS, 1);
            y_tick_label(f, py, buf);
        } else {
            double px = PX(f, v);
            line(f, px, top, px, top + ph, C_GRID, 1);
            line(f, px, top + ph, px, top + ph + 5, C_AXIS, 1);
            x_tick_label(f, px, buf);
        }
    }
}

static int point_ok(const frame *f, const series *s, int i) {
    return drawable(&f->ax, s->x[i]) && drawable(&f->ay, s->y[i]);
}

static void ring(frame *f, double x, double y, const unsigned char c[3]) {
    cairo_arc(f->c.cr, x, y, 0.5 * (RING_OUT + RING_IN), 0, 2 * CANVAS_PI);
    canvas_rgb(&f->c, c, 1);
    cairo_set_line_width(f->c.cr, RING_OUT - RING_IN);
    cairo_stroke(f->c.cr);
}

/* Rings first (the line runs into them), then the line, then dots over it,
 * then the point labels. A line breaks at a point that cannot be drawn. */
static void draw_series(frame *f, const series *s) {
    if (s->marker == HEARTH_MARKER_RING)
        for (int i = 0; i < s->n; i++)
            if (point_ok(f, s, i)) ring(f, PX(f, s->x[i]), PY(f, s->y[i]), s->color);
    if (s->line_width > 0) {
        cairo_t *cr = f->c.cr;
        int open = 0;
        for (int i = 0; i < s->n; i++) {
            if (!point_ok(f, s, i)) {
                open = 0;
                continue;
            }
            if (open) cairo_line_to(cr, PX(f, s->x[i]), PY(f, s->y[i]));
            else cairo_move_to(cr, PX(f, s->x[i]), PY(f, s->y[i]));
            open = 1;
        }
        canvas_rgb(&f->c, s->color, 1);
        cairo_set_line_width(cr, 1.25 * s->line_width);
        cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
        cairo_stroke(cr);
    }
    if (s->marker == HEARTH_MARKER_DOT)
        for (int i = 0; i < s->n; i++)
            if (point_ok(f, s, i)) disc(f, PX(f, s->x[i]), PY(f, s->y[i]), DOT_R, s->color);
    if (s->point_labels)
        for (int i = 0; i < s->n; i++)
            if (s->point_labels[i] && point_ok(f, s, i))
                canvas_text(&f->c, PX(f, s->x[i]) + 7, PY(f, s->y[i]) - 4, s->point_labels[i], 0.9 * FS, CANVAS_LEFT,
                            CANVAS_BASELINE, 0, s->color);
}

/* One legend row: the series' marker (or its line when it has none) and its label. */
static void legend_entry(frame *f, const series *s, int y) {
    const int x = f->left;
    if (s->marker == HEARTH_MARKER_DOT) disc(f, x + 16, y + 3, DOT_R, s->color);
    else if (s->marker == HEARTH_MARKER_RING) ring(f, x + 16, y + 3, s->color);
    else line(f, x + 8, y + 3, x + 24, y + 3, s->color, 1.25 * (s->line_width > 0 ? s->line_width : 1));
    canvas_text(&f->c, x + 28, y + 3, s->label, FS, CANVAS_LEFT, CANVAS_MIDDLE, 0, C_TEXT);
}

hearth_status hearth_plot_write_png(const hearth_plot *p, const char *path, hearth_error *err) {
    frame F = {.left = M_LEFT, .top = M_TOP, .pw = p->w - M_LEFT - M_RIGHT, .ph = p->h - M_TOP - M_BOTTOM};
    frame *f = &F;
    F.ax.scale = p->xs;
    F.ay.scale = p->ys;
    axis_fit(p, 0, &F.ax, &F.ay); /* drawable() reads only the other axis's scale */
    axis_fit(p, 1, &F.ay, &F.ax);
    if (canvas_init(&F.c, p->w, p->h, C_BG, err)) return err->code;
    const int left = F.left, top = F.top, pw = F.pw, ph = F.ph;
    /* grid under everything: the minor lines, then the major ones with their ticks and labels */
    if (p->xs == HEARTH_PLOT_LOG) grid_log(f, 0);
    if (p->ys == HEARTH_PLOT_LOG) grid_log(f, 1);
    if (p->xs == HEARTH_PLOT_LOG) major_log(f, 0);
    else major_linear(f, 0);
    if (p->ys == HEARTH_PLOT_LOG) major_log(f, 1);
    else major_linear(f, 1);
    line(f, left, top, left + pw, top, C_AXIS, 1);
    line(f, left, top + ph, left + pw, top + ph, C_AXIS, 1);
    line(f, left, top, left, top + ph, C_AXIS, 1);
    line(f, left + pw, top, left + pw, top + ph, C_AXIS, 1);
    /* the series stay inside the frame, but a marker on its edge shows whole */
    cairo_save(F.c.cr);
    cairo_rectangle(F.c.cr, left - RING_OUT - 1, top - RING_OUT - 1, pw + 2 * RING_OUT + 3, ph + 2 * RING_OUT + 3);
    cairo_clip(F.c.cr);
    for (int pass = 1; pass >= 0; pass--)
        for (int k = 0; k < p->n; k++)
            if (p->s[k].behind == pass) draw_series(f, &p->s[k]);
    cairo_restore(F.c.cr);
    /* title (large when it fits), axis names, legend */
    if (p->title) {
        double size = canvas_text_width(&F.c, p->title, 17) <= p->w - left - 8 ? 17 : FS;
        canvas_text(&F.c, left, 14, p->title, size, CANVAS_LEFT, CANVAS_TOP, 0, C_TEXT);
    }
    if (p->x_label) canvas_text(&F.c, left + pw / 2.0, p->h - 24, p->x_label, FS + 1, CANVAS_CENTER, CANVAS_TOP, 0, C_TEXT);
    if (p->y_label) canvas_text(&F.c, 8, top - 8, p->y_label, FS + 1, CANVAS_LEFT, CANVAS_BASELINE, 0, C_TEXT);
    if (p->legend != HEARTH_LEGEND_NONE) {
        int rows = 0;
        for (int k = 0; k < p->n; k++) rows += p->s[k].label != NULL;
        int y = p->legend == HEARTH_LEGEND_TOP_LEFT ? top + 10 : top + ph - 6 - LEGEND_STEP * rows;
        /* a white box under the entries so grid lines do not run through the text */
        if (rows) {
            double wmax = 0;
            for (int k = 0; k < p->n; k++)
                if (p->s[k].label) wmax = fmax(wmax, canvas_text_width(&F.c, p->s[k].label, FS));
            canvas_rgb(&F.c, C_BG, 0.85);
            cairo_rectangle(F.c.cr, left + 4, y - 5, 30 + wmax, LEGEND_STEP * rows + 4);
            cairo_fill(F.c.cr);
        }
        for (int k = 0; k < p->n; k++)
            if (p->s[k].label) legend_entry(f, &p->s[k], y), y += LEGEND_STEP;
    }
    F.c.title = p->title; /* the file's Title text too, as a frame's (io_png.c) */
    hearth_status st = canvas_write_png(&F.c, path, err);
    canvas_free(&F.c);
    return st;
}
