/* canvas.c: the Cairo canvas, text, ticks and units shared by render.c and
 * plot.c. Cairo replaced a hand-made canvas and a 5x7 bitmap font: pictures
 * now have antialiased lines, real fonts and sizes that fit the picture.
 * Cairo's own PNG writer was rejected because it writes in place; the pixels
 * go through png_write_rgb, which writes a temporary file and renames it. */
#include "canvas.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "io_png.h"

hearth_status canvas_init(canvas *c, int w, int h, const unsigned char bg[3], hearth_error *err) {
    memset(c, 0, sizeof *c);
    if (w < 1 || h < 1 || w > CANVAS_DIM_MAX || h > CANVAS_DIM_MAX)
        return err_set(err, HEARTH_ERR_PARAM, "picture size %d x %d px; valid range [1, %d] each", w, h, CANVAS_DIM_MAX);
    cairo_surface_t *sf = cairo_image_surface_create(CAIRO_FORMAT_RGB24, w, h);
    if (cairo_surface_status(sf) != CAIRO_STATUS_SUCCESS) {
        cairo_surface_destroy(sf);
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory for a %d x %d picture", w, h);
    }
    cairo_t *cr = cairo_create(sf);
    if (cairo_status(cr) != CAIRO_STATUS_SUCCESS) {
        cairo_destroy(cr);
        cairo_surface_destroy(sf);
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory for a %d x %d picture", w, h);
    }
    *c = (canvas){w, h, sf, cr, NULL};
    canvas_rgb(c, bg, 1);
    cairo_paint(cr);
    cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
    return HEARTH_OK;
}

void canvas_free(canvas *c) {
    if (c->cr) cairo_destroy(c->cr);
    if (c->sf) cairo_surface_destroy(c->sf);
    memset(c, 0, sizeof *c);
}

void canvas_rgb(canvas *c, const unsigned char rgb[3], double alpha) {
    cairo_set_source_rgba(c->cr, rgb[0] / 255.0, rgb[1] / 255.0, rgb[2] / 255.0, alpha);
}

hearth_status canvas_write_png(canvas *c, const char *path, hearth_error *err) {
    cairo_surface_flush(c->sf);
    if (cairo_status(c->cr) != CAIRO_STATUS_SUCCESS)
        return err_set(err, HEARTH_ERR_NOMEM, "drawing '%s' failed: %s", path, cairo_status_to_string(cairo_status(c->cr)));
    size_t bytes = (size_t)c->w * (size_t)c->h * 3;
    unsigned char *rgb = mem_alloc(bytes);
    if (!rgb) return err_set(err, HEARTH_ERR_NOMEM, "out of memory writing '%s'", path);
    const unsigned char *data = cairo_image_surface_get_data(c->sf);
    const int stride = cairo_image_surface_get_stride(c->sf);
    for (int y = 0; y < c->h; y++) /* RGB24 keeps each pixel in a native-endian uint32 as 0x00RRGGBB */
        for (int x = 0; x < c->w; x++) {
            uint32_t p;
            memcpy(&p, data + (size_t)y * stride + 4 * (size_t)x, 4);
            unsigned char *o = rgb + 3 * ((size_t)y * c->w + x);
            o[0] = (unsigned char)(p >> 16), o[1] = (unsigned char)(p >> 8), o[2] = (unsigned char)p;
        }
    hearth_status st = png_write_rgb_titled(path, c->w, c->h, rgb, c->title, err);
    mem_free(rgb, bytes);
    return st;
}

double canvas_text_width(canvas *c, const char *s, double size) {
    cairo_text_extents_t e;
    cairo_set_font_size(c->cr, size);
    cairo_text_extents(c->cr, s, &e);
    return e.x_advance;
}

void canvas_text(canvas *c, double x, double y, const char *s, double size, int h_anchor, int v_anchor, double angle,
                 const unsigned char rgb[3]) {
    if (!s || !*s) return;
    cairo_t *cr = c->cr;
    cairo_set_font_size(cr, size);
    cairo_text_extents_t e;
    cairo_text_extents(cr, s, &e);
    /* vertical anchors from the font's ascent, not the string's ink, so labels
     * in a row share one baseline whatever letters they hold */
    double dx = h_anchor == CANVAS_CENTER ? -0.5 * e.x_advance : h_anchor == CANVAS_RIGHT ? -e.x_advance : 0;
    double asc = 0.75 * size;
    double dy = v_anchor == CANVAS_TOP ? asc : v_anchor == CANVAS_MIDDLE ? 0.5 * asc : 0;
    cairo_save(cr);
    cairo_translate(cr, x, y);
    cairo_rotate(cr, -angle);
    cairo_move_to(cr, dx, dy);
    canvas_rgb(c, rgb, 1);
    cairo_show_text(cr, s);
    cairo_new_path(cr);
    cairo_restore(cr);
}

int canvas_ticks(double lo, double hi, int min_n, int max_n, double *t, double *step) {
    static const double mant[] = {1, 2, 2.5, 4, 5};
    if (!(hi > lo) || !isfinite(lo) || !isfinite(hi)) {
        t[0] = lo;
        *step = 1;
        return 1;
    }
    double best = 0;
    int best_n = 0, best_miss = 1 << 30;
    /* candidate steps from the whole span down to about a thousandth of it,
     * coarse first: the first whose count lies in [min_n, max_n] wins, else
     * the one that misses the range by the fewest ticks */
    const int e_hi = (int)floor(log10(hi - lo)) + 1;
    for (int e = e_hi; e >= e_hi - 4; e--)
        for (int m = 4; m >= 0; m--) {
            double st = mant[m] * pow(10, e);
            int n = (int)(floor(hi / st + 1e-9) - ceil(lo / st - 1e-9)) + 1;
            int miss = n < min_n ? min_n - n : n > max_n ? n - max_n : 0;
            if (miss < best_miss) best = st, best_n = n, best_miss = miss;
        }
    double k0 = ceil(lo / best - 1e-9);
    int n = 0;
    for (int i = 0; i < best_n && n < max_n; i++) {
        double v = (k0 + i) * best;
        if (fabs(v) < 1e-9 * best) v = 0;
        t[n++] = v;
    }
    *step = best;
    return n;
}

void canvas_tick_label(double v, double step, char *buf, size_t n) {
    if (v == 0) {
        snprintf(buf, n, "0");
        return;
    }
    double a = fmax(fabs(v), step);
    if (a >= 1e5 || a < 1e-3) {
        snprintf(buf, n, "%.3g", v);
        return;
    }
    /* decimals enough for the step: 0.25 needs two, 50 none */
    int dec = 0;
    while (dec < 6 && fabs(step * pow(10, dec) - round(step * pow(10, dec))) > 1e-6 * step * pow(10, dec)) dec++;
    snprintf(buf, n, "%.*f", dec, v);
}

void canvas_unit(const char *unit, char *buf, size_t n) {
    if (!unit || !*unit || !strcmp(unit, "1")) {
        snprintf(buf, n, "-");
        return;
    }
    static const struct { const char *from, *to; } subs[] = {{"degC", "\xc2\xb0" "C"}, {"^2", "\xc2\xb2"}, {"^3", "\xc2\xb3"}};
    size_t o = 0;
    for (const char *p = unit; *p && o + 4 < n;) {
        int done = 0;
        for (size_t k = 0; k < sizeof subs / sizeof subs[0] && !done; k++) {
            size_t l = strlen(subs[k].from);
            if (!strncmp(p, subs[k].from, l)) {
                size_t tl = strlen(subs[k].to);
                if (o + tl + 1 >= n) break;
                memcpy(buf + o, subs[k].to, tl);
                o += tl, p += l, done = 1;
            }
        }
        if (!done) buf[o++] = *p++;
    }
    buf[o] = '\0';
}
