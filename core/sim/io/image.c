/* image.c: drawing on an RGB canvas.
 *
 * Everything is hard-edged (no antialiasing) and uses only comparisons and
 * rounding of doubles, so a frame is the same bytes on every machine and can
 * be pinned by a hash in tests. Coordinates are clamped in double before any
 * conversion to int, so wild values (1e300, a particle that blew up) clip
 * instead of overflowing. */
#include "image.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "colormap.h"
#include "error.h"
#include "font.h"

static size_t img_bytes(const img *im) { return (size_t)im->w * (size_t)im->h * 3; }

static void put(img *im, int x, int y, const unsigned char c[3]) {
    unsigned char *q = im->rgb + ((size_t)y * (size_t)im->w + (size_t)x) * 3;
    q[0] = c[0];
    q[1] = c[1];
    q[2] = c[2];
}

hearth_status img_init(img *im, int w, int h, const unsigned char bg[3], hearth_error *err) {
    HEARTH_ASSERT(im);
    memset(im, 0, sizeof *im);
    if (w < 1 || h < 1 || w > IMG_DIM_MAX || h > IMG_DIM_MAX)
        return err_set(err, HEARTH_ERR_PARAM, "image size %dx%d is outside 1..%d", w, h,
                       IMG_DIM_MAX);
    size_t n = (size_t)w * (size_t)h * 3;
    unsigned char *p = mem_alloc(n);
    if (!p)
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory for a %dx%d image (%zu bytes)", w, h,
                       n);
    im->w = w;
    im->h = h;
    im->rgb = p;
    static const unsigned char black[3] = {0, 0, 0};
    img_fill_rect(im, 0, 0, w, h, bg ? bg : black);
    return HEARTH_OK;
}

void img_free(img *im) {
    if (!im) return;
    mem_free(im->rgb, img_bytes(im));
    memset(im, 0, sizeof *im);
}

void img_fill_rect(img *im, int x0, int y0, int x1, int y1, const unsigned char c[3]) {
    if (x1 < x0) {
        int t = x0;
        x0 = x1;
        x1 = t;
    }
    if (y1 < y0) {
        int t = y0;
        y0 = y1;
        y1 = t;
    }
    if (x0 < 0) x0 = 0;
    if (y0 < 0) y0 = 0;
    if (x1 > im->w) x1 = im->w;
    if (y1 > im->h) y1 = im->h;
    for (int y = y0; y < y1; y++)
        for (int x = x0; x < x1; x++) put(im, x, y, c);
}

/* Clamp v to [lo, hi] and convert; NaN never reaches here. */
static int clampi(double v, int lo, int hi) {
    if (v < lo) return lo;
    if (v > hi) return hi;
    return (int)v;
}

void img_disc(img *im, double cx, double cy, double r, const unsigned char c[3]) {
    if (!isfinite(cx) || !isfinite(cy) || !isfinite(r) || r < 0) return;
    /* Rows and columns whose centres can be within r, clipped to the canvas. */
    int i0 = clampi(ceil(cx - r), 0, im->w), i1 = clampi(floor(cx + r), -1, im->w - 1);
    int j0 = clampi(ceil(cy - r), 0, im->h), j1 = clampi(floor(cy + r), -1, im->h - 1);
    double r2 = r * r;
    for (int j = j0; j <= j1; j++) {
        double dy = j - cy;
        for (int i = i0; i <= i1; i++) {
            double dx = i - cx;
            if (dx * dx + dy * dy <= r2) put(im, i, j, c);
        }
    }
}

/* Liang-Barsky: shrink [t0, t1] to where p + t d stays in [lo, hi] on one axis.
 * Returns 0 when nothing is left. */
static int clip_axis(double p, double d, double lo, double hi, double *t0, double *t1) {
    if (d == 0) return p >= lo && p <= hi;
    double a = (lo - p) / d, b = (hi - p) / d;
    if (a > b) {
        double t = a;
        a = b;
        b = t;
    }
    if (a > *t0) *t0 = a;
    if (b < *t1) *t1 = b;
    return *t0 <= *t1;
}

void img_line(img *im, double x0, double y0, double x1, double y1, const unsigned char c[3]) {
    if (!isfinite(x0) || !isfinite(y0) || !isfinite(x1) || !isfinite(y1)) return;
    /* Clip first so a line to a far-away point costs pixels on screen only.
     * The half-pixel margin keeps end pixels that round onto the canvas. */
    double dx = x1 - x0, dy = y1 - y0, t0 = 0, t1 = 1;
    if (!clip_axis(x0, dx, -0.5, im->w - 0.5, &t0, &t1)) return;
    if (!clip_axis(y0, dy, -0.5, im->h - 0.5, &t0, &t1)) return;
    double ax = x0 + t0 * dx, ay = y0 + t0 * dy;
    double bx = x0 + t1 * dx, by = y0 + t1 * dy;

    /* DDA with one step per pixel along the longer axis. Rejected: integer
     * Bresenham, which needs the end points rounded first and so drifts from
     * the true line after clipping. */
    double len = fmax(fabs(bx - ax), fabs(by - ay));
    int n = (int)ceil(len);
    for (int k = 0; k <= n; k++) {
        double t = n ? (double)k / n : 0.0;
        long i = lround(ax + t * (bx - ax)), j = lround(ay + t * (by - ay));
        if (i >= 0 && i < im->w && j >= 0 && j < im->h) put(im, (int)i, (int)j, c);
    }
}

void img_text(img *im, int x, int y, const char *s, int scale, const unsigned char c[3]) {
    font_draw(im->rgb, im->w, im->h, x, y, s, scale, c);
}

void img_colorbar(img *im, int x, int y, int w, int h, int map, double vmin, double vmax,
                  const char *unit) {
    if (w < 1 || h < 1) return;
    /* Labels are 2x on tall bars (full frames) and 1x on small previews. */
    int scale = h >= 200 ? 2 : 1;
    int lx = x + w + 3 * scale; /* labels start a little right of the bar */

    /* Pick the label colour against what is already under the labels, so the
     * bar reads on a dark scene and on a white page alike. */
    static const unsigned char white[3] = {235, 235, 235}, black[3] = {20, 20, 20};
    const unsigned char *ink = white;
    if (lx >= 0 && lx < im->w && y >= 0 && y < im->h) {
        const unsigned char *q = im->rgb + ((size_t)y * (size_t)im->w + (size_t)lx) * 3;
        if (0.299 * q[0] + 0.587 * q[1] + 0.114 * q[2] > 128) ink = black;
    }

    for (int j = 0; j < h; j++) {
        unsigned char c[3];
        cmap_eval(map, h > 1 ? 1.0 - (double)j / (h - 1) : 0.5, c);
        img_fill_rect(im, x, y + j, x + w, y + j + 1, c);
    }
    /* A one-pixel frame so the low end of inferno does not melt into a dark canvas. */
    img_fill_rect(im, x - 1, y - 1, x + w + 1, y, ink);
    img_fill_rect(im, x - 1, y + h, x + w + 1, y + h + 1, ink);
    img_fill_rect(im, x - 1, y, x, y + h, ink);
    img_fill_rect(im, x + w, y, x + w + 1, y + h, ink);

    char top[64], bottom[64];
    snprintf(top, sizeof top, "%.3g", vmax);
    snprintf(bottom, sizeof bottom, "%.3g", vmin);
    int glyph_h = 7 * scale, line = FONT_CELL_H * scale;
    img_text(im, lx, y, top, scale, ink);
    img_text(im, lx, y + h - glyph_h, bottom, scale, ink);
    if (!unit || !*unit) return;
    if (h >= 3 * line) {
        img_text(im, lx, y + (h - glyph_h) / 2, unit, scale, ink);
    } else {
        /* No room between the two labels: put the unit after the top one. */
        img_text(im, lx + font_text_width(top, scale) + FONT_CELL_W * scale, y, unit, scale, ink);
    }
}
