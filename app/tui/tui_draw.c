/* tui_draw.c: field values to half-block cells, colour bars and sparklines.
 * Pure functions (see tui_draw.h), but for the colour map the views draw with
 * (tui_use_colormap), which the one drawing thread sets around each view. */
#include "tui_draw.h"

#include <hearth/hearth.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

tui_color_mode tui_pick_mode(const char *term, const char *no_color, int utf8, long colors) {
    if (!term || !*term || !strcmp(term, "dumb")) return TUI_PLAIN;
    if ((no_color && *no_color) || !utf8) return TUI_ASCII; /* https://no-color.org: any non-empty value */
    if (colors >= 0x1000000L) return TUI_TRUECOLOR;
    if (colors >= 256) return TUI_256;
    return TUI_ASCII;
}

/* Five stops in the spirit of viridis (dark blue, blue, teal, green, yellow):
 * perceptually ordered and readable for the common colour blindnesses. */
static const unsigned char stops[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};

/* the map the views draw with: NULL for the stops above, else a name of
 * hearth_colormap_names() (the browning field's dough-to-crust map) */
static const char *view_map;

void tui_use_colormap(const char *name) { view_map = name; }

void tui_colormap(double u, unsigned char rgb[3]) {
    if (view_map && hearth_colormap_rgb(view_map, u, rgb) == 0) return;
    if (!(u > 0)) u = 0;
    if (u > 1) u = 1;
    double x = u * 4;
    int i = (int)x;
    if (i > 3) i = 3;
    double f = x - i;
    for (int k = 0; k < 3; k++) rgb[k] = (unsigned char)lround(stops[i][k] + f * (stops[i + 1][k] - stops[i][k]));
}

static int nearest_level(int c) { /* the cube's levels are 0, 95, 135, 175, 215, 255 */
    static const int lv[6] = {0, 95, 135, 175, 215, 255};
    int best = 0;
    for (int i = 1; i < 6; i++)
        if (abs(c - lv[i]) < abs(c - lv[best])) best = i;
    return best;
}

int tui_rgb_to_256(const unsigned char rgb[3]) {
    static const int lv[6] = {0, 95, 135, 175, 215, 255};
    int r = nearest_level(rgb[0]), g = nearest_level(rgb[1]), b = nearest_level(rgb[2]);
    long dc = 0, dg = 0;
    int cube[3] = {lv[r], lv[g], lv[b]};
    int mean = (rgb[0] + rgb[1] + rgb[2]) / 3;
    int mx = rgb[0], mn = rgb[0];
    for (int k = 1; k < 3; k++) mx = rgb[k] > mx ? rgb[k] : mx, mn = rgb[k] < mn ? rgb[k] : mn;
    int gi = mean < 8 ? 0 : mean > 238 ? 23 : (mean - 8) / 10; /* greys 232..255 are 8, 18, ..., 238 */
    int grey = 8 + 10 * gi;
    for (int k = 0; k < 3; k++) {
        dc += (long)(rgb[k] - cube[k]) * (rgb[k] - cube[k]);
        dg += (long)(rgb[k] - grey) * (rgb[k] - grey);
    }
    /* a grey only for a colour with little chroma: by RGB distance alone the
     * colour map's muted purples and teals went grey and drew grey bands */
    return dg < dc && mx - mn < 24 ? 232 + gi : 16 + 36 * r + 6 * g + b;
}

int32_t tui_color(double u, tui_color_mode m) {
    if (isnan(u) || m < TUI_256) return TUI_DEFAULT;
    unsigned char c[3];
    tui_colormap(u, c);
    if (m == TUI_TRUECOLOR) return (int32_t)c[0] << 16 | (int32_t)c[1] << 8 | c[2];
    return tui_rgb_to_256(c);
}

char tui_density_char(double u) {
    static const char ramp[] = " .:-=+*#%@";
    if (isnan(u)) return ' ';
    if (!(u > 0)) u = 0;
    if (u > 1) u = 1;
    return ramp[1 + (int)lround(u * 8)];
}

void tui_range(const double *v, long n, double *lo, double *hi) {
    double a = INFINITY, b = -INFINITY;
    for (long i = 0; i < n; i++)
        if (isfinite(v[i])) {
            if (v[i] < a) a = v[i];
            if (v[i] > b) b = v[i];
        }
    *lo = a <= b ? a : NAN;
    *hi = a <= b ? b : NAN;
}

/* the sample under pixel (px, py) of a pw x ph grid (py = 0 at the top), as u in 0..1 or NaN */
static double pixel(const double *f, int fw, int fh, double lo, double hi, double u0, double u1, double v0, double v1,
                    int px, int py, int pw, int ph) {
    double fu = u0 + (u1 - u0) * (px + 0.5) / pw, fv = v1 - (v1 - v0) * (py + 0.5) / ph;
    if (fu < 0 || fu >= 1 || fv < 0 || fv >= 1) return NAN;
    int c = (int)(fu * fw), r = (int)(fv * fh);
    if (c >= fw) c = fw - 1;
    if (r >= fh) r = fh - 1;
    double x = f[(long)r * fw + c];
    if (!isfinite(x)) return NAN;
    /* a uniform field (up to rounding in the probe's averages) shows as mid colour */
    return hi - lo > 1e-9 * fmax(fabs(lo), fabs(hi)) ? (x - lo) / (hi - lo) : 0.5;
}

void tui_draw_heatmap(const double *f, int fw, int fh, double lo, double hi, double u0, double u1, double v0,
                      double v1, tui_color_mode m, int cols, int rows, tui_cell *out) {
    for (int r = 0; r < rows; r++)
        for (int c = 0; c < cols; c++) {
            double a = pixel(f, fw, fh, lo, hi, u0, u1, v0, v1, c, 2 * r, cols, 2 * rows);
            double b = pixel(f, fw, fh, lo, hi, u0, u1, v0, v1, c, 2 * r + 1, cols, 2 * rows);
            tui_cell *o = &out[(long)r * cols + c];
            o->fg = o->bg = TUI_DEFAULT;
            if (m < TUI_256) {
                double mean = isnan(a) ? b : isnan(b) ? a : 0.5 * (a + b);
                o->ch = (uint32_t)tui_density_char(mean);
            } else if (isnan(a) && isnan(b)) {
                o->ch = ' ';
            } else if (isnan(a)) { /* only the lower pixel is material: a lower half block on the default background */
                o->ch = TUI_LOWER_HALF;
                o->fg = tui_color(b, m);
            } else {
                o->ch = TUI_UPPER_HALF;
                o->fg = tui_color(a, m);
                o->bg = tui_color(b, m);
            }
        }
}

void tui_draw_solids(tui_cell *cells, int cols, int rows, const unsigned char *solid, tui_color_mode m) {
    const int32_t grey = m == TUI_TRUECOLOR ? 0x6e6e78 : 242;
    for (int r = 0; r < rows; r++)
        for (int c = 0; c < cols; c++) {
            tui_cell *o = &cells[(long)r * cols + c];
            const int st = solid[(long)(2 * r) * cols + c], sb = solid[(long)(2 * r + 1) * cols + c];
            if (!st && !sb) continue;
            if (m < TUI_256) { /* characters only: a hatch where nothing else is drawn */
                if (o->ch == ' ') o->ch = '/';
                continue;
            }
            /* what each half shows now: material colour, or the default (empty) */
            int32_t top = TUI_DEFAULT, bot = TUI_DEFAULT;
            if (o->ch == TUI_UPPER_HALF) top = o->fg, bot = o->bg;
            else if (o->ch == TUI_LOWER_HALF) bot = o->fg;
            if (top == TUI_DEFAULT && st) top = grey;
            if (bot == TUI_DEFAULT && sb) bot = grey;
            if (top == TUI_DEFAULT) o->ch = TUI_LOWER_HALF, o->fg = bot, o->bg = TUI_DEFAULT;
            else o->ch = TUI_UPPER_HALF, o->fg = top, o->bg = bot;
        }
}

void tui_draw_colorbar(tui_color_mode m, int cols, tui_cell *out) {
    for (int c = 0; c < cols; c++) {
        double u = cols > 1 ? (double)c / (cols - 1) : 0.5;
        out[c].fg = out[c].bg = TUI_DEFAULT;
        if (m < TUI_256) out[c].ch = (uint32_t)tui_density_char(u);
        else {
            out[c].ch = ' ';
            out[c].bg = tui_color(u, m);
        }
    }
}

void tui_sparkline(const double *v, int n, int width, int ascii, uint32_t *out) {
    static const char aramp[] = " _.-=+*#"; /* index 1..7 used; 0 is 'no data' */
    int first = n > width ? n - width : 0, pad = width - (n - first);
    double lo, hi;
    tui_range(v + first, n - first, &lo, &hi);
    for (int i = 0; i < width; i++) {
        if (i < pad) {
            out[i] = ' ';
            continue;
        }
        double x = v[first + i - pad];
        if (!isfinite(x)) {
            out[i] = ' ';
            continue;
        }
        double u = hi > lo ? (x - lo) / (hi - lo) : 0;
        int k = (int)lround(u * 7); /* 0..7 */
        out[i] = ascii ? (uint32_t)aramp[k == 0 ? 1 : k] : 0x2581u + (uint32_t)k;
    }
}

int tui_utf8(uint32_t cp, char *b) {
    if (cp < 0x80) return b[0] = (char)cp, 1;
    if (cp < 0x800) return b[0] = (char)(0xC0 | cp >> 6), b[1] = (char)(0x80 | (cp & 0x3F)), 2;
    if (cp < 0x10000)
        return b[0] = (char)(0xE0 | cp >> 12), b[1] = (char)(0x80 | (cp >> 6 & 0x3F)), b[2] = (char)(0x80 | (cp & 0x3F)), 3;
    b[0] = (char)(0xF0 | cp >> 18), b[1] = (char)(0x80 | (cp >> 12 & 0x3F)), b[2] = (char)(0x80 | (cp >> 6 & 0x3F));
    b[3] = (char)(0x80 | (cp & 0x3F));
    return 4;
}
