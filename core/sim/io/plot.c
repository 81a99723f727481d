/* plot.c: <hearth/plot.h>, line and scatter plots on log or linear axes,
 * drawn on the image.c canvas with the font.c bitmap font and written by
 * io_png.c. It replaced two hand copies of the same log-log code in
 * cmd_rheometer.c and cmd_trade.c; the geometry (margins, grid, labels,
 * legend) is theirs, so the flow-curve pictures did not change a pixel.
 * Only this file knows how a plot is drawn: a renderer with antialiased
 * text can replace it behind the same header. */
#include "hearth/plot.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "font.h"
#include "image.h"
#include "io_png.h"

#define PLOT_DIM_MIN 200
#define PLOT_DIM_MAX 8192
/* the frame's margins (pixels): room for the title above, tick labels left and below */
enum { M_LEFT = 78, M_RIGHT = 24, M_TOP = 52, M_BOTTOM = 62, LEGEND_STEP = 14 };

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
    img im;
    int left, top, pw, ph;
    axis ax, ay;
} frame;

#define PX(f, v) ((f)->left + (axis_t(&(f)->ax, v) - (f)->ax.lo) / ((f)->ax.hi - (f)->ax.lo) * (f)->pw)
#define PY(f, v) ((f)->top + (f)->ph - (axis_t(&(f)->ay, v) - (f)->ay.lo) / ((f)->ay.hi - (f)->ay.lo) * (f)->ph)

static void decade_label(int k, char *buf, size_t n) {
    if (k >= -2 && k <= 3) snprintf(buf, n, "%g", pow(10, k));
    else snprintf(buf, n, "1e%d", k);
}

static void x_tick_label(frame *f, double px, const char *s) {
    img_text(&f->im, (int)lround(px) - font_text_width(s, 1) / 2, f->top + f->ph + 9, s, 1, C_TEXT);
}
static void y_tick_label(frame *f, double py, const char *s) {
    img_text(&f->im, f->left - 9 - font_text_width(s, 1), (int)lround(py) - 4, s, 1, C_TEXT);
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
                img_line(&f->im, left, py, left + pw, py, C_MINOR);
                if (minor_labels && (j == 2 || j == 5)) snprintf(buf, sizeof buf, "%g", v), y_tick_label(f, py, buf);
            } else {
                double px = PX(f, v);
                img_line(&f->im, px, top, px, top + ph, C_MINOR);
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
            img_line(&f->im, left, py, left + pw, py, C_GRID);
            img_line(&f->im, left - 5, py, left, py, C_AXIS);
            y_tick_label(f, py, buf);
        } else {
            double px = PX(f, pow(10, k));
            img_line(&f->im, px, top, px, top + ph, C_GRID);
            img_line(&f->im, px, top + ph, px, top + ph + 5, C_AXIS);
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
            img_line(&f->im, left, py, left + pw, py, C_GRID);
            img_line(&f->im, left - 5, py, left, py, C_AXIS);
            y_tick_label(f, py, buf);
        } else {
            double px = PX(f, v);
            img_line(&f->im, px, top, px, top + ph, C_GRID);
            img_line(&f->im, px, top + ph, px, top + ph + 5, C_AXIS);
            x_tick_label(f, px, buf);
        }
    }
}

static int point_ok(const frame *f, const series *s, int i) {
    return drawable(&f->ax, s->x[i]) && drawable(&f->ay, s->y[i]);
}

static void ring(frame *f, double x, double y, const unsigned char c[3]) {
    img_disc(&f->im, x, y, RING_OUT, c);
    img_disc(&f->im, x, y, RING_IN, C_BG);
}

/* Rings first (the line runs into them), then the line, then dots over it,
 * then the point labels. */
static void draw_series(frame *f, const series *s) {
    if (s->marker == HEARTH_MARKER_RING)
        for (int i = 0; i < s->n; i++)
            if (point_ok(f, s, i)) ring(f, PX(f, s->x[i]), PY(f, s->y[i]), s->color);
    if (s->line_width > 0)
        for (int i = 0; i + 1 < s->n; i++) {
            if (!point_ok(f, s, i) || !point_ok(f, s, i + 1)) continue;
            double x0 = PX(f, s->x[i]), y0 = PY(f, s->y[i]), x1 = PX(f, s->x[i + 1]), y1 = PY(f, s->y[i + 1]);
            for (int w = 0; w < s->line_width; w++) img_line(&f->im, x0, y0 + w, x1, y1 + w, s->color);
        }
    if (s->marker == HEARTH_MARKER_DOT)
        for (int i = 0; i < s->n; i++)
            if (point_ok(f, s, i)) img_disc(&f->im, PX(f, s->x[i]), PY(f, s->y[i]), DOT_R, s->color);
    if (s->point_labels)
        for (int i = 0; i < s->n; i++)
            if (s->point_labels[i] && point_ok(f, s, i))
                img_text(&f->im, (int)lround(PX(f, s->x[i])) + 6, (int)lround(PY(f, s->y[i])) - 10, s->point_labels[i], 1,
                         s->color);
}

/* One legend row: the series' marker (or its line when it has none) and its label. */
static void legend_entry(frame *f, const series *s, int y) {
    const int x = f->left;
    if (s->marker == HEARTH_MARKER_DOT) img_disc(&f->im, x + 16, y + 3, DOT_R, s->color);
    else if (s->marker == HEARTH_MARKER_RING) ring(f, x + 16, y + 3, s->color);
    else
        for (int w = 0; w < (s->line_width > 0 ? s->line_width : 1); w++)
            img_line(&f->im, x + 8, y + 3 + w, x + 24, y + 3 + w, s->color);
    img_text(&f->im, x + 28, y, s->label, 1, C_TEXT);
}

hearth_status hearth_plot_write_png(const hearth_plot *p, const char *path, hearth_error *err) {
    frame F = {.left = M_LEFT, .top = M_TOP, .pw = p->w - M_LEFT - M_RIGHT, .ph = p->h - M_TOP - M_BOTTOM};
    frame *f = &F;
    F.ax.scale = p->xs;
    F.ay.scale = p->ys;
    axis_fit(p, 0, &F.ax, &F.ay); /* drawable() reads only the other axis's scale */
    axis_fit(p, 1, &F.ay, &F.ax);
    if (img_init(&F.im, p->w, p->h, C_BG, err)) return err->code;
    const int left = F.left, top = F.top, pw = F.pw, ph = F.ph;
    /* grid under everything: the minor lines, then the major ones with their ticks and labels */
    if (p->xs == HEARTH_PLOT_LOG) grid_log(f, 0);
    if (p->ys == HEARTH_PLOT_LOG) grid_log(f, 1);
    if (p->xs == HEARTH_PLOT_LOG) major_log(f, 0);
    else major_linear(f, 0);
    if (p->ys == HEARTH_PLOT_LOG) major_log(f, 1);
    else major_linear(f, 1);
    img_line(&F.im, left, top, left + pw, top, C_AXIS);
    img_line(&F.im, left, top + ph, left + pw, top + ph, C_AXIS);
    img_line(&F.im, left, top, left, top + ph, C_AXIS);
    img_line(&F.im, left + pw, top, left + pw, top + ph, C_AXIS);
    for (int pass = 1; pass >= 0; pass--)
        for (int k = 0; k < p->n; k++)
            if (p->s[k].behind == pass) draw_series(f, &p->s[k]);
    /* title (large when it fits), axis names, legend */
    if (p->title) img_text(&F.im, left, 12, p->title, font_text_width(p->title, 2) <= p->w - left - 8 ? 2 : 1, C_TEXT);
    if (p->x_label) img_text(&F.im, left + pw / 2 - font_text_width(p->x_label, 1) / 2, p->h - 22, p->x_label, 1, C_TEXT);
    if (p->y_label) img_text(&F.im, 8, top - 14, p->y_label, 1, C_TEXT);
    if (p->legend != HEARTH_LEGEND_NONE) {
        int rows = 0;
        for (int k = 0; k < p->n; k++) rows += p->s[k].label != NULL;
        int y = p->legend == HEARTH_LEGEND_TOP_LEFT ? top + 10 : top + ph - 6 - LEGEND_STEP * rows;
        for (int k = 0; k < p->n; k++)
            if (p->s[k].label) legend_entry(f, &p->s[k], y), y += LEGEND_STEP;
    }
    hearth_status st = png_write_rgb(path, F.im.w, F.im.h, F.im.rgb, err);
    img_free(&F.im);
    return st;
}
