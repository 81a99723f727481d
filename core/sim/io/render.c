/* render.c: pictures of a scene for people: particles coloured by a field,
 * and plane slices, drawn with Cairo (canvas.c).
 *
 * Frames of a run compare: a field has a fixed colour range by default
 * (hearth_picture_default_range; temperature from the coldest seeded value to
 * the hottest source, saturation and browning 0..1), and a caller that holds a
 * range (s:run) passes it back with HEARTH_RANGE_GROW; the picture's size
 * depends on the domain and the asked width only. Each picture carries what a
 * reader needs to use it alone: a colour bar with 4-6 ticks and the unit as
 * its title ("saturation (-)", never a lone "1"), axes in metres, the
 * simulated time, and the colliders (tray, nozzle, plates, cup) as filled
 * grey shapes with an outline, sampled from their signed distance so every
 * collider shape is drawn the same way. White background: a picture goes
 * into a paper or a slide as it is. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"

#include "canvas.h"
#include "colormap.h"
#include "error.h"
#include "scene.h"

static const unsigned char BG[3] = {255, 255, 255}, FG[3] = {20, 20, 24}, FRAME[3] = {60, 60, 66},
                           COLLIDER[3] = {150, 152, 160}, COLLIDER_EDGE[3] = {70, 72, 80}, EMPTY[3] = {236, 236, 238};

hearth_picture_def hearth_default_picture_def(void) {
    return (hearth_picture_def){.kind = HEARTH_PICTURE_SLICE, .width = 800, .axis = 2, .at = NAN,
                                .range_mode = HEARTH_RANGE_DEFAULT, .range = {NAN, NAN}, .time_scale = 1,
                                .region = {NAN, NAN, NAN, NAN}, .depth = NAN};
}

static int is_unit_interval(const char *f) {
    static const char *const names[] = {"saturation", "browning", "porosity", "mixing_ratio", "boundary"};
    for (size_t k = 0; k < sizeof names / sizeof names[0]; k++)
        if (!strncmp(f, names[k], strlen(names[k]))) return 1;
    return 0;
}

int hearth_picture_default_range(const hearth_scene *s, const char *field, double range[2]) {
    if (is_unit_interval(field)) {
        range[0] = 0, range[1] = 1;
        return 1;
    }
    if (strcmp(field, "temperature") != 0) return 0;
    double lo = INFINITY, hi = -INFINITY;
    if (s->seeded_t_known) lo = s->seeded_t[0], hi = s->seeded_t[1];
    else if (s->ps.enabled & (1u << PC_TEMPERATURE)) /* restored from a checkpoint: the particles as they are now */
        for (int i = 0; i < s->ps.n; i++) {
            double T = pcold(&s->ps, PC_TEMPERATURE)[i];
            if (isfinite(T)) lo = fmin(lo, T), hi = fmax(hi, T);
        }
    /* the hottest source: the oven's air, heated or holding colliders */
    if (isfinite(s->def.oven_temperature)) hi = fmax(hi, s->def.oven_temperature), lo = fmin(lo, s->def.oven_temperature);
    for (int c = 0; c < s->ncol; c++)
        if (isfinite(s->cols[c].temperature)) hi = fmax(hi, s->cols[c].temperature), lo = fmin(lo, s->cols[c].temperature);
    if (!(hi > lo)) return 0;
    range[0] = lo, range[1] = hi;
    return 1;
}

/* fields that are never negative and read best from zero */
static int magnitude_like(const char *f) {
    return hearth_field_components(f) == 3 || !strcmp(f, "speed") || !strcmp(f, "von_mises");
}

static int map_for(const char *field) {
    if (!strcmp(field, "browning")) return CMAP_BROWNING; /* the crust index (fields/browning.c) */
    if (!strncmp(field, "temperature", 11)) return CMAP_INFERNO;
    if (!strncmp(field, "stress_", 7) || !strncmp(field, "velocity_", 9)) return CMAP_COOLWARM; /* signed */
    return CMAP_VIRIDIS;
}

static hearth_status scalar_per_particle(const hearth_scene *s, const char *field, double **out, size_t *bytes,
                                         hearth_error *err) {
    const int n = s->ps.n, nc = hearth_field_components(field);
    if (nc == 0) return hearth_scene_particle_field(s, field, NULL, err); /* produces the unknown-field message */
    if (nc == 9) /* a tensor has no one colour: its components and invariants are fields of their own */
        return err_set(err, HEARTH_ERR_PARAM,
                       "field '%s' is a tensor; picture one component (%s_xx, %s_yy, %s_zz, %s_xy, %s_xz, %s_yz), "
                       "pressure or von_mises", field, field, field, field, field, field, field);
    *bytes = sizeof(double) * (size_t)(n > 0 ? n : 1) * (size_t)nc;
    double *v = mem_alloc(*bytes);
    if (!v) return err_set(err, HEARTH_ERR_NOMEM, "out of memory rendering '%s'", field);
    hearth_status st = hearth_scene_particle_field(s, field, v, err);
    if (st) {
        mem_free(v, *bytes);
        return st;
    }
    if (nc == 3) /* a vector shows as its magnitude */
        for (int i = 0; i < n; i++) v[i] = sqrt(v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2]);
    *out = v;
    return HEARTH_OK;
}

/* ---- layout ---------------------------------------------------------------- */

/* Margins in units of the font size fs, which follows the picture's width:
 * a title line above, tick labels and an axis name below and left, the
 * colour bar with its tick labels right. */
enum { FONT_FLOOR = 8 }; /* px: the smallest font a picture's text is set in by its width */
static double font_size(int width) { return fmin(16, fmax(FONT_FLOOR, width / 50.0)); }
static void margins(double fs, double *l, double *r, double *t, double *b) {
    *l = 5.2 * fs, *r = 7.6 * fs, *t = 2.6 * fs, *b = 3.4 * fs;
}

/* The height that gives the domain's aspect to the plot area. */
static int aspect_height(int width, double du, double dv) {
    double fs = font_size(width), l, r, t, b;
    margins(fs, &l, &r, &t, &b);
    int h = (int)lround((width - l - r) * dv / du + t + b);
    return h < 64 ? 64 : h > CANVAS_DIM_MAX ? CANVAS_DIM_MAX : h;
}

typedef struct frame {
    double x0, y0, w, h; /* plot area (pixels) */
    double lo[2], hi[2]; /* the domain shown (m) */
    double sc;           /* pixels per metre */
    double fs;
} frame;

static frame layout(const canvas *c, const double lo[2], const double hi[2]) {
    frame f = {.fs = font_size(c->w)};
    double l, r, t, b;
    margins(f.fs, &l, &r, &t, &b);
    double aw = fmax(8, c->w - l - r), ah = fmax(8, c->h - t - b);
    double sx = aw / (hi[0] - lo[0]), sy = ah / (hi[1] - lo[1]);
    f.sc = sx < sy ? sx : sy;
    f.w = (hi[0] - lo[0]) * f.sc, f.h = (hi[1] - lo[1]) * f.sc;
    f.x0 = l + 0.5 * (aw - f.w), f.y0 = t + 0.5 * (ah - f.h);
    memcpy(f.lo, lo, sizeof f.lo);
    memcpy(f.hi, hi, sizeof f.hi);
    return f;
}

static double px_of(const frame *f, double x) { return f->x0 + (x - f->lo[0]) * f->sc; }
static double py_of(const frame *f, double y) { return f->y0 + f->h - (y - f->lo[1]) * f->sc; }

/* Axes in metres: the frame, ticks outside it, labels and the axis names. */
static void axes(canvas *c, const frame *f, const char *uname, const char *vname) {
    cairo_t *cr = c->cr;
    const double fs = f->fs, tick = 0.4 * fs;
    canvas_rgb(c, FRAME, 1);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, f->x0 - 0.5, f->y0 - 0.5, f->w + 1, f->h + 1);
    cairo_stroke(cr);
    double t[8], step;
    char buf[48];
    int n = canvas_ticks(f->lo[0], f->hi[0], 4, 7, t, &step);
    for (int k = 0; k < n; k++) {
        double x = px_of(f, t[k]);
        cairo_move_to(cr, x, f->y0 + f->h + 0.5);
        cairo_line_to(cr, x, f->y0 + f->h + tick);
        canvas_tick_label(t[k], step, buf, sizeof buf);
        canvas_text(c, x, f->y0 + f->h + tick + 0.2 * fs, buf, 0.85 * fs, CANVAS_CENTER, CANVAS_TOP, 0, FG);
    }
    canvas_rgb(c, FRAME, 1);
    cairo_stroke(cr);
    n = canvas_ticks(f->lo[1], f->hi[1], 3, 6, t, &step);
    for (int k = 0; k < n; k++) {
        double y = py_of(f, t[k]);
        cairo_move_to(cr, f->x0 - 0.5, y);
        cairo_line_to(cr, f->x0 - tick, y);
        canvas_tick_label(t[k], step, buf, sizeof buf);
        canvas_text(c, f->x0 - tick - 0.25 * fs, y, buf, 0.85 * fs, CANVAS_RIGHT, CANVAS_MIDDLE, 0, FG);
    }
    canvas_rgb(c, FRAME, 1);
    cairo_stroke(cr);
    snprintf(buf, sizeof buf, "%s (m)", uname);
    canvas_text(c, f->x0 + 0.5 * f->w, f->y0 + f->h + tick + 1.35 * fs, buf, 0.9 * fs, CANVAS_CENTER, CANVAS_TOP, 0, FG);
    snprintf(buf, sizeof buf, "%s (m)", vname);
    canvas_text(c, 0.9 * fs, f->y0 + 0.5 * f->h, buf, 0.9 * fs, CANVAS_CENTER, CANVAS_MIDDLE, CANVAS_PI / 2, FG);
}

/* The colour bar right of the frame: vmax at the top, ticks and labels on
 * its right, "field (unit)" as its title. Returns where that name starts (px), the title's right limit. */
static double colorbar(canvas *c, const frame *f, int map, const char *field, const char *unit, hearth_picture_info *info) {
    cairo_t *cr = c->cr;
    const double fs = f->fs;
    const double bx = f->x0 + f->w + 1.2 * fs, bw = 1.2 * fs, by = f->y0, bh = f->h;
    info->bar[0] = bx, info->bar[1] = by, info->bar[2] = bw, info->bar[3] = bh;
    info->area[0] = f->x0, info->area[1] = f->y0, info->area[2] = f->w, info->area[3] = f->h;
    memcpy(info->view_lo, f->lo, sizeof f->lo);
    memcpy(info->view_hi, f->hi, sizeof f->hi);
    const int nb = (int)fmax(2, ceil(bh));
    for (int k = 0; k < nb; k++) { /* one row of the bar a step, top = 1 */
        unsigned char rgb[3];
        cmap_eval(map, 1.0 - (k + 0.5) / nb, rgb);
        canvas_rgb(c, rgb, 1);
        cairo_rectangle(cr, bx, by + bh * k / nb, bw, bh / nb + 0.6);
        cairo_fill(cr);
    }
    canvas_rgb(c, FRAME, 1);
    cairo_set_line_width(cr, 1);
    cairo_rectangle(cr, bx - 0.5, by - 0.5, bw + 1, bh + 1);
    cairo_stroke(cr);
    const double lo = info->range[0], hi = info->range[1];
    double step;
    info->nticks = canvas_ticks(lo, hi, 4, 6, info->ticks, &step);
    char buf[64];
    for (int k = 0; k < info->nticks; k++) {
        double y = by + bh - (info->ticks[k] - lo) / (hi - lo) * bh;
        cairo_move_to(cr, bx + bw, y);
        cairo_line_to(cr, bx + bw + 0.35 * fs, y);
        canvas_rgb(c, FRAME, 1);
        cairo_stroke(cr);
        canvas_tick_label(info->ticks[k], step, buf, sizeof buf);
        canvas_text(c, bx + bw + 0.55 * fs, y, buf, 0.85 * fs, CANVAS_LEFT, CANVAS_MIDDLE, 0, FG);
    }
    snprintf(buf, sizeof buf, "%s (%s)", field, unit);
    double tw = canvas_text_width(c, buf, 0.9 * fs);
    double tx = fmax(0.3 * fs, fmin(bx, c->w - 0.7 * fs - tw)); /* right-aligned to the canvas when the name is long */
    canvas_text(c, tx, by - 0.45 * fs, buf, 0.9 * fs, CANVAS_LEFT, CANVAS_BASELINE, 0, FG);
    return tx;
}

/* The title: the label, the time and the step. A scene whose rates run time_scale times
 * fast (a 25 minute bake in 5 simulated seconds) is read in real time, so the
 * title gives that first, in minutes past two of them, and the simulated
 * seconds and the factor after it: a picture in a paper says which clock.
 * The label comes first (#18): a frame looked at alone, oven_110/heat_0005.png
 * among several ovens' folders, says what it is of; the folder's name is lost
 * once the picture is copied into a note. The title ends a font size short of the colour bar's name (right, px),
 * whose line it shares: a long one (a label, the real and simulated times) starts at the canvas's left margin
 * instead of the plot's and, if it still does not fit, is set smaller, down to half the font size, and past that is cut
 * there (a long label of wide letters; info->title keeps it whole) (#18: drying.lua's "time lapse: ..." title had
 * run into "saturation (-)" at 800 px). */
/* The size (px) that sets text within room px: the font size fs, or smaller down to half of it. Measured again at the
 * smaller size: the font's hinted advances round glyph by glyph, so the width is not quite proportional
 * (cookies.lua's 95-byte title had come out 10 px longer than scaled, and was cut). */
static double fit_size(canvas *c, const char *text, double fs, double room) {
    const double tw = canvas_text_width(c, text, fs);
    if (tw <= room) return fs;
    double size = fs * fmax(0.5, fmin(1, room / tw));
    for (int k = 0; k < 4 && size > 0.5 * fs; k++) {
        const double w = canvas_text_width(c, text, size);
        if (w <= room) break;
        size = fmax(0.5 * fs, size * room / w * 0.99);
    }
    return size;
}

/* One line of the title at (x, y) (its top), set at size and cut at right (px). */
static void title_line(canvas *c, double x, double y, const char *text, double size, double right) {
    cairo_save(c->cr);
    cairo_rectangle(c->cr, 0, 0, fmax(0, right), c->h);
    cairo_clip(c->cr);
    canvas_text(c, x, y, text, size, CANVAS_LEFT, CANVAS_TOP, 0, FG);
    cairo_restore(c->cr);
}

/* A 3D particle picture's slab (hearth_picture_def.depth): 1 and its middle and half thickness along z (m) when the
 * picture draws a slab, 0 when it draws every particle. */
static int slab_of(const hearth_scene *s, const hearth_picture_def *d, double *zc, double *half) {
    if (s->def.dim != 3 || d->kind != HEARTH_PICTURE_PARTICLES || !isfinite(d->depth)) return 0;
    *zc = isnan(d->at) ? 0.5 * (s->def.lo[2] + s->def.hi[2]) : d->at;
    *half = 0.5 * d->depth;
    return 1;
}

static void title(canvas *c, const frame *f, const hearth_scene *s, const hearth_picture_def *d, hearth_picture_info *info,
                  double right) {
    char *buf = info->title;
    const size_t n = sizeof info->title;
    const double time_scale = d->time_scale;
    int at = d->label && d->label[0] ? snprintf(buf, n, "%s   ", d->label) : 0; /* label <= 128 bytes: fits */
    if (time_scale == 1) {
        snprintf(buf + at, n - at, "t = %.4g s   (step %ld)", s->t, s->step);
    } else {
        const double real = s->t * time_scale;
        if (real >= 120)
            snprintf(buf + at, n - at, "t = %.4g min   (%.4g s simulated x %g, step %ld)", real / 60, s->t, time_scale, s->step);
        else snprintf(buf + at, n - at, "t = %.4g s   (%.4g s simulated x %g, step %ld)", real, s->t, time_scale, s->step);
    }
    /* A 3D particle picture is a projection: every depth drawn over each other, the nearest (largest z) on top. It
     * says so, or a muffin cup's front wall and its middle read as two walls (#18, helper userfix9; userview4's
     * item 15: muffins.lua --set dim=3 drew each wall twice under a title like the 2D one's). */
    /* A 3D slice says where it cuts, and a slab which particles it draws (#18, helper userfix11; userfix9's Left: the
     * axes' names gave a slice's plane, not where along its normal it lay). */
    static const char *const names[3] = {"x", "y", "z"};
    double zc, half;
    const size_t used = strlen(buf);
    if (slab_of(s, d, &zc, &half)) snprintf(buf + used, n - used, "   particles at z = %.4g ± %.3g m", zc, half);
    else if (s->def.dim == 3 && d->kind == HEARTH_PICTURE_PARTICLES) snprintf(buf + used, n - used, "   seen along -z");
    else if (s->def.dim == 3)
        snprintf(buf + used, n - used, "   %s = %.4g m", names[d->axis],
                 isnan(d->at) ? 0.5 * (s->def.lo[d->axis] + s->def.hi[d->axis]) : d->at);
    const double fs = f->fs;
    double x = f->x0, size = fs;
    if (x + canvas_text_width(c, buf, fs) > right - fs) {
        x = fmin(f->x0, 0.3 * fs);
        size = fit_size(c, buf, fs, right - fs - x);
    }
    if (size >= FONT_FLOOR - 1e-9 || !at) {
        title_line(c, x, 0.6 * fs, buf, size, right - 0.5 * fs);
        return;
    }
    /* Two lines (#18, helper userfix5; userview3's item 11): one would be set under the floor font (drying.lua's
     * 93-byte title at width = 300 came out 4 px high, past that cut short of the time). The label on the first,
     * across the canvas above the colour bar's name (whose top is at least 1.1 fs below the picture's top); the time
     * under it, short of that name, from the plot's left edge when it fits there (the top tick's label lies left of
     * it). Both fit the top margin (2.6 fs): a line set at the top y spans to y + 0.97 of its size. */
    char label[HEARTH_PICTURE_LABEL_MAX + 1];
    snprintf(label, sizeof label, "%s", d->label);
    const char *time = buf + at;
    const double l1 = fit_size(c, label, fs, c->w - 0.6 * fs);
    title_line(c, 0.3 * fs, 0.2 * fs, label, l1, c->w - 0.3 * fs);
    double x2 = f->x0;
    if (x2 + canvas_text_width(c, time, fs) > right - fs) x2 = fmin(f->x0, 0.3 * fs);
    title_line(c, x2, 1.3 * fs, time, fit_size(c, time, fs, right - fs - x2), right - 0.5 * fs);
}

/* Colliders as filled grey shapes: each pixel of the plot area is shaded by
 * how much of it lies inside a collider, from the signed distance at its
 * centre (in 3D particle views the least over a few depths, so a tray below
 * the middle plane shows); pass 1 draws the outline, a line about a pixel wide
 * where the distance crosses zero. Pixels are blended straight into the
 * surface: a Cairo path cannot follow an arbitrary signed distance, and
 * sampling it is what keeps every collider shape (boxes, planes, booleans,
 * masks) drawn the same way. */
typedef struct collider_map {
    int px0, py0, w, h; /* the pixels sampled: the plot area */
    float *d;           /* signed distance to the nearest collider (pixels, negative inside); NULL: none */
} collider_map;

static void collider_map_free(collider_map *m) {
    if (m->d) mem_free(m->d, sizeof(float) * (size_t)m->w * (size_t)m->h);
    m->d = NULL;
}

/* Sample the colliders once per picture; the fill and the outline both read it. */
static hearth_status collider_map_make(collider_map *m, const frame *f, const hearth_scene *s, const int uv[2], int naxis,
                                       const double *depths, int ndepth, hearth_error *err) {
    memset(m, 0, sizeof *m);
    if (s->ncol == 0) return HEARTH_OK;
    m->px0 = (int)ceil(f->x0), m->py0 = (int)ceil(f->y0);
    m->w = (int)floor(f->x0 + f->w) - m->px0, m->h = (int)floor(f->y0 + f->h) - m->py0;
    if (m->w <= 0 || m->h <= 0) return HEARTH_OK;
    if (!(m->d = mem_alloc(sizeof(float) * (size_t)m->w * (size_t)m->h)))
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory drawing the colliders (%d x %d px)", m->w, m->h);
    /* Each collider's bounds at its pose now, grown by two pixels (collider_update_bounds and the MPM bounds,
     * which are geometry alone: the tray's half-space, a 2D box's prism): a point they pass by is
     * more than two pixels from that collider, and a pixel whose distance is 0.5 px or more is drawn by
     * neither pass (colliders_draw), so leaving such a collider out of dmin changes no pixel (helper speed:
     * the cup's distance at every pixel was a tenth of tear_open.lua's muffin). Up to MAP_BOUNDED colliders;
     * any after them are asked at every pixel, as before. */
    enum { MAP_BOUNDED = 16 };
    collider nb[MAP_BOUNDED];
    const int nbk = s->ncol < MAP_BOUNDED ? s->ncol : MAP_BOUNDED;
    const double margin = 2.0 / f->sc;
    for (int k = 0; k < nbk; k++) {
        nb[k] = s->cols[k];
        collider_update_bounds_tight(&nb[k], margin);
    }
    for (int j = 0; j < m->h; j++)
        for (int i = 0; i < m->w; i++) {
            double dmin = INFINITY;
            for (int k = 0; k < s->ncol; k++)
                for (int z = 0; z < ndepth; z++) {
                    double x[3] = {0, 0, 0};
                    x[uv[0]] = f->lo[0] + (m->px0 + i + 0.5 - f->x0) / f->sc;
                    x[uv[1]] = f->lo[1] + (f->y0 + f->h - (m->py0 + j) - 0.5) / f->sc;
                    if (naxis >= 0) x[naxis] = depths[z];
                    if (k < nbk && !collider_near(&nb[k], x)) continue;
                    dmin = fmin(dmin, collider_sdf(&s->cols[k], x, NULL));
                }
            m->d[(size_t)j * m->w + i] = (float)(dmin * f->sc);
        }
    return HEARTH_OK;
}

/* pass 0: the fill, shaded by how much of each pixel lies inside (from the
 * distance at its centre); pass 1: the outline, about a pixel wide where the
 * distance crosses zero. Blended straight into the surface's pixels. */
static void colliders_draw(canvas *c, const collider_map *m, int pass) {
    if (!m->d) return;
    cairo_surface_flush(c->sf);
    unsigned char *data = cairo_image_surface_get_data(c->sf);
    const int stride = cairo_image_surface_get_stride(c->sf);
    const unsigned char *col = pass == 0 ? COLLIDER : COLLIDER_EDGE;
    for (int j = 0; j < m->h; j++)
        for (int i = 0; i < m->w; i++) {
            const double dp = m->d[(size_t)j * m->w + i];
            double a = pass == 0 ? fmin(1, fmax(0, 0.5 - dp)) : fmin(1, fmax(0, 1.0 - fabs(dp + 0.5) / 0.9));
            if (a <= 0) continue;
            uint32_t p;
            unsigned char *q = data + (size_t)(m->py0 + j) * stride + 4 * (size_t)(m->px0 + i);
            memcpy(&p, q, 4);
            double r = (p >> 16) & 255, g = (p >> 8) & 255, b = p & 255;
            r = a * col[0] + (1 - a) * r, g = a * col[1] + (1 - a) * g, b = a * col[2] + (1 - a) * b;
            p = ((uint32_t)lround(r) << 16) | ((uint32_t)lround(g) << 8) | (uint32_t)lround(b);
            memcpy(q, &p, 4);
        }
    cairo_surface_mark_dirty(c->sf);
}

/* ---- the range ------------------------------------------------------------ */

static void data_range(const double *v, long n, double out[2]) {
    out[0] = INFINITY, out[1] = -INFINITY;
    for (long i = 0; i < n; i++)
        if (isfinite(v[i])) out[0] = fmin(out[0], v[i]), out[1] = fmax(out[1], v[i]);
    if (out[0] > out[1]) out[0] = out[1] = NAN;
}

static hearth_status choose_range(const hearth_scene *s, const hearth_picture_def *d, hearth_picture_info *info,
                                  hearth_error *err) {
    double *r = info->range;
    const double *dat = info->data;
    switch (d->range_mode) {
    case HEARTH_RANGE_FIXED:
    case HEARTH_RANGE_GROW:
        if (!isfinite(d->range[0]) || !isfinite(d->range[1]) || !(d->range[0] < d->range[1]))
            return err_set(err, HEARTH_ERR_PARAM, "picture of '%s': range = {%g, %g}; two finite numbers, the first smaller",
                           d->field, d->range[0], d->range[1]);
        r[0] = d->range[0], r[1] = d->range[1];
        if (d->range_mode == HEARTH_RANGE_GROW && isfinite(dat[0])) r[0] = fmin(r[0], dat[0]), r[1] = fmax(r[1], dat[1]);
        return HEARTH_OK;
    case HEARTH_RANGE_DEFAULT:
        if (hearth_picture_default_range(s, d->field, r)) return HEARTH_OK;
        r[0] = dat[0], r[1] = dat[1]; /* no fixed range for this field: the frame's */
        break;
    case HEARTH_RANGE_FRAME:
        r[0] = dat[0], r[1] = dat[1];
        break;
    default:
        return err_set(err, HEARTH_ERR_PARAM, "picture: range mode %d; valid 0..3", (int)d->range_mode);
    }
    if (!isfinite(r[0])) r[0] = 0, r[1] = 1; /* nothing to draw */
    if (r[0] >= 0 && magnitude_like(d->field)) { /* a speed's bar starts at rest */
        r[0] = 0;
        if (!(r[1] > 0)) r[1] = 1;
    }
    if (!(r[1] > r[0])) { /* one value: a window around it, so the bar still has ticks */
        double half = r[0] != 0 ? 0.05 * fabs(r[0]) : 0.5;
        r[0] -= half, r[1] += half;
    }
    return HEARTH_OK;
}

/* ---- drawing ---------------------------------------------------------------- */

/* The picture's in-plane axes: u horizontal, v vertical (a particle picture's x and y, a slice's plane in order). */
static void view_axes(const hearth_picture_def *d, int *u, int *v) {
    const int slice = d->kind == HEARTH_PICTURE_SLICE;
    *u = slice && d->axis == 0 ? 1 : 0, *v = !slice || d->axis == 2 ? 1 : 2;
}

/* Those axes and the part of them the picture shows: its region, or the domain. */
static void view_of(const hearth_scene *s, const hearth_picture_def *d, int *u, int *v, double lo[2], double hi[2]) {
    view_axes(d, u, v);
    if (isnan(d->region[0])) {
        lo[0] = s->def.lo[*u], lo[1] = s->def.lo[*v], hi[0] = s->def.hi[*u], hi[1] = s->def.hi[*v];
    } else lo[0] = d->region[0], lo[1] = d->region[1], hi[0] = d->region[2], hi[1] = d->region[3];
}

static hearth_status check_def(const hearth_scene *s, const hearth_picture_def *d, int *map, hearth_error *err) {
    if (!d->field) return err_set(err, HEARTH_ERR_PARAM, "picture: no field named");
    if ((unsigned)d->kind > HEARTH_PICTURE_PARTICLES)
        return err_set(err, HEARTH_ERR_PARAM, "picture: kind %d; valid: slice (0), particles (1)", (int)d->kind);
    if (d->width < 64 || d->width > 8192)
        return err_set(err, HEARTH_ERR_PARAM, "picture: width = %d px; valid range [64, 8192]", d->width);
    if (d->height != 0 && (d->height < 64 || d->height > 8192))
        return err_set(err, HEARTH_ERR_PARAM, "picture: height = %d px; valid range [64, 8192], or 0 to follow the domain",
                       d->height);
    if (d->axis < 0 || d->axis > 2 || (s->def.dim == 2 && d->kind == HEARTH_PICTURE_SLICE && d->axis != 2))
        return err_set(err, HEARTH_ERR_PARAM, "picture: axis %d; valid: %s", d->axis, s->def.dim == 2 ? "z (2) in 2D" : "x, y, z (0..2)");
    if (!(d->time_scale > 0 && d->time_scale <= 1e9))
        return err_set(err, HEARTH_ERR_PARAM, "picture: time_scale = %g; valid range (0, 1e9], 1 for a scene in real time",
                       d->time_scale);
    if (d->label) {
        /* control characters first: the length's refusal quotes the label's start, and an escape sequence a
         * scene put there would reach the user's terminal */
        const size_t len = strlen(d->label);
        for (size_t k = 0; k < len; k++)
            if ((unsigned char)d->label[k] < 32 || d->label[k] == 127)
                return err_set(err, HEARTH_ERR_PARAM, "picture: label has a control character (byte %zu); the title is one line", k + 1);
        if (len > HEARTH_PICTURE_LABEL_MAX) {
            int cut = 20; /* its start in the message, cut on a UTF-8 character's first byte */
            while (cut > 0 && ((unsigned char)d->label[cut] & 0xC0) == 0x80) cut--;
            return err_set(err, HEARTH_ERR_PARAM, "picture: label of %zu bytes (\"%.*s...\"); at most %d, a short text before the time",
                           len, cut, d->label, HEARTH_PICTURE_LABEL_MAX);
        }
    }
    if (!isnan(d->depth) && d->depth != INFINITY) {
        if (s->def.dim != 3 || d->kind != HEARTH_PICTURE_PARTICLES)
            return err_set(err, HEARTH_ERR_PARAM, "picture: depth = %g m draws a slab of a 3D particle picture; this "
                           "is a %s", d->depth, s->def.dim != 3 ? "2D scene" : "slice (its plane is at)");
        if (!(d->depth > 0))
            return err_set(err, HEARTH_ERR_PARAM, "picture: depth = %g m; valid: a slab's thickness > 0, or inf for "
                           "every particle", d->depth);
        const double zlo = s->def.lo[2], zhi = s->def.hi[2];
        if (!isnan(d->at) && !(d->at >= zlo && d->at <= zhi))
            return err_set(err, HEARTH_ERR_PARAM, "picture: at = %g m, the slab's middle along z; valid range [%g, %g] "
                           "(the domain's z)", d->at, zlo, zhi);
    }
    int set = 0;
    for (int k = 0; k < 4; k++) set += !isnan(d->region[k]);
    if (set) { /* a close-up: inside the domain's plane, lo < hi on both axes */
        static const char *const names[3] = {"x", "y", "z"};
        int u, v;
        view_axes(d, &u, &v);
        const double *r = d->region, *lo = s->def.lo, *hi = s->def.hi, tol = 1e-9 * (hi[u] - lo[u] + hi[v] - lo[v]);
        int ok = set == 4;
        for (int k = 0; k < 4; k++) ok = ok && isfinite(r[k]);
        ok = ok && r[0] < r[2] && r[1] < r[3] && r[0] >= lo[u] - tol && r[2] <= hi[u] + tol && r[1] >= lo[v] - tol &&
             r[3] <= hi[v] + tol;
        if (!ok)
            return err_set(err, HEARTH_ERR_PARAM,
                           "picture: region = {{%g, %g}, {%g, %g}} (m); valid: {{%s lo, %s lo}, {%s hi, %s hi}}, lo < hi, "
                           "inside the domain's %s [%g, %g] and %s [%g, %g]",
                           r[0], r[1], r[2], r[3], names[u], names[v], names[u], names[v], names[u], lo[u], hi[u], names[v],
                           lo[v], hi[v]);
    }
    *map = d->colormap ? cmap_by_name(d->colormap) : map_for(d->field);
    if (*map < 0)
        return err_set(err, HEARTH_ERR_PARAM, "picture: colormap '%s' is unknown; valid: %s", d->colormap, cmap_names());
    return HEARTH_OK;
}

/* The material between a 2D picture's particle discs (#18, helper userfix5; userview3's item 6: the leavened
 * physical cookies, particles at J ~2.5, drew as loose beads with white channels between them). MPM particles do not
 * stay on a lattice: in that cookie a particle's nearest neighbour lies at a median 0.73 of its own spacing (V0 J)^(1/2),
 * so they pair and chain and leave voids a spacing or two wide that no disc of the particle's own volume covers,
 * while the continuum the grid sees has no hole there. Under the discs, each sample of the plot is filled where the particles' volume fraction under the transfer kernel (probe.c: V0 J, B-spline
 * weighted, 1.5 dx) is at least 1/2, which is where a flat face of material lies (the kernel is symmetric), in the
 * probe's mass-weighted colour; the discs drawn over it keep each particle's own value. On a body still near its
 * lattice the discs (1.3 spacings across) cover the fill but for slivers in the scallops of its outline; a lone
 * particle is its disc alone (its fraction is under 1/2). What it closes: a round void up to about a cell across
 * (its centre's fraction stays above 1/2) and a straight opening narrower than about 0.7 dx; a crack a cell wide or
 * more stays open (pull_twist's torn test is a gap of dx), where the discs alone closed openings under ~0.15 dx.
 * The probe's own material test (1/4) would have put a halo
 * of about dx/3 around every body. Rejected: larger discs (the outline would grow with them and a foam's real
 * pores close), a per-scene kind = "slice" (it loses the particles' own values). 3D draws the particles of every
 * depth over each other, which fills a picture's gaps: its slice is one plane, so it is not drawn there. A field
 * the slice probe does not take (a vector's magnitude) leaves the discs alone (the picture as before). */
static hearth_status fill_material(canvas *c, const frame *f, const hearth_scene *s, const hearth_picture_def *d, int map,
                                   const hearth_picture_info *info, hearth_error *err) {
    if (hearth_field_components(d->field) != 1) return HEARTH_OK; /* a vector: the slice probe takes components only */
    const int sw = f->w > 1 ? (int)f->w : 1, sh = f->h > 1 ? (int)f->h : 1;
    /* a sample a pixel, or dx/8 when pixels are finer: the fill's edge, smoothed over one sample, stays within a
     * pixel of the material's (at dx/2, as a slice samples, it had drawn a pale fringe half a sample wide) */
    int nw = (int)ceil((f->hi[0] - f->lo[0]) / (0.125 * s->def.dx)), nh = (int)ceil((f->hi[1] - f->lo[1]) / (0.125 * s->def.dx));
    if (nw > sw) nw = sw;
    if (nh > sh) nh = sh;
    /* The samples are probed a band of rows at a time (#18, helper userfix6): the probe holds 3 doubles a sample
     * (its sums) and this 2 more, 40 bytes a pixel for the whole picture at once (an 800 px frame's 10 MB, the demo's
     * peak 13.9 -> 23.9 MB). A band of FILL_BAND samples holds 1.3 MB at most; a band's samples are the whole
     * slice's, summed in the same order (probe_slice_rows), so the picture keeps its bits. Each band walks the
     * particles once more to find those that reach it (a few comparisons each). Rejected: probing at cell
     * resolution and interpolating (a coarser fraction moves the fill's edge, the picture changes). */
    enum { FILL_BAND = 32768 };
    const int band = nw >= FILL_BAND ? 1 : (FILL_BAND / nw < nh ? FILL_BAND / nw : nh);
    const size_t bytes = sizeof(double) * (size_t)nw * (size_t)band;
    double *val = mem_alloc(bytes), *frac = mem_alloc(bytes);
    hearth_status st = val && frac ? HEARTH_OK : err_set(err, HEARTH_ERR_NOMEM, "out of memory filling a %d x %d picture", nw, nh);
    cairo_surface_t *img = NULL;
    if (!st) {
        img = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, nw, nh);
        if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS)
            st = err_set(err, HEARTH_ERR_NOMEM, "out of memory filling a %d x %d picture", nw, nh);
    }
    unsigned char *data = st ? NULL : cairo_image_surface_get_data(img);
    const int stride = st ? 0 : cairo_image_surface_get_stride(img);
    const double span = info->range[1] - info->range[0];
    const double rect[4] = {f->lo[0], f->lo[1], f->hi[0], f->hi[1]};
    for (int row0 = 0; !st && row0 < nh; row0 += band) {
        const int rows = nh - row0 < band ? nh - row0 : band;
        if ((st = probe_slice_rows(s, d->field, 2, 0, rect, nw, nh, row0, rows, val, frac, err)) == HEARTH_ERR_PARAM) {
            st = HEARTH_OK; /* a field the slice does not take: the discs alone */
            err_clear(err);
            cairo_surface_destroy(img);
            mem_free(val, bytes), mem_free(frac, bytes);
            return st;
        }
        for (int r = 0; !st && r < rows; r++) { /* probe row row0 + r (from the low end of y) is image row nh - 1 - it */
            const int row = nh - 1 - (row0 + r);
            for (int col = 0; col < nw; col++) {
                const size_t q = (size_t)r * nw + col;
                uint32_t p = 0;
                if (frac[q] >= 0.5 && isfinite(val[q])) {
                    unsigned char rgb[3];
                    cmap_eval(map, (val[q] - info->range[0]) / span, rgb);
                    p = 0xff000000u | ((uint32_t)rgb[0] << 16) | ((uint32_t)rgb[1] << 8) | rgb[2];
                }
                memcpy(data + (size_t)row * stride + 4 * (size_t)col, &p, 4);
            }
        }
    }
    if (!st) {
        cairo_surface_mark_dirty(img);
        cairo_save(c->cr);
        cairo_rectangle(c->cr, f->x0, f->y0, f->w, f->h);
        cairo_clip(c->cr);
        cairo_translate(c->cr, f->x0, f->y0);
        cairo_scale(c->cr, f->w / nw, f->h / nh);
        cairo_set_source_surface(c->cr, img, 0, 0);
        cairo_pattern_set_filter(cairo_get_source(c->cr), CAIRO_FILTER_BILINEAR);
        cairo_pattern_set_extend(cairo_get_source(c->cr), CAIRO_EXTEND_PAD);
        cairo_paint(c->cr);
        cairo_restore(c->cr);
    }
    if (img) cairo_surface_destroy(img);
    mem_free(val, bytes), mem_free(frac, bytes);
    return st;
}

static hearth_status draw_particles(canvas *c, const hearth_scene *s, const hearth_picture_def *d, int map,
                                    hearth_picture_info *info, hearth_error *err) {
    const int n = s->ps.n;
    double *val = NULL;
    size_t bytes = 0;
    hearth_status st = scalar_per_particle(s, d->field, &val, &bytes, err);
    if (st) return st;
    /* a slab: the particles outside it are not drawn (NaN: data_range passes them by; the loop below skips them),
     * and the colliders are cut at its middle plane, as a slice cuts them */
    double zc = 0, half = 0;
    const int slab = slab_of(s, d, &zc, &half);
    if (slab) {
        const double *Xs = pcold(&s->ps, PC_X);
        for (int i = 0; i < n; i++)
            if (!(fabs(Xs[3 * i + 2] - zc) <= half)) val[i] = NAN;
    }
    data_range(val, n, info->data);
    if ((st = choose_range(s, d, info, err))) {
        mem_free(val, bytes);
        return st;
    }
    double lo[2], hi[2];
    int pu, pv;
    view_of(s, d, &pu, &pv, lo, hi);
    frame f = layout(c, lo, hi);
    const int uv[2] = {0, 1};
    double depths[5];
    for (int k = 0; k < 5; k++) depths[k] = s->def.lo[2] + (k + 0.5) / 5 * (s->def.hi[2] - s->def.lo[2]);
    if (slab) depths[0] = zc;
    collider_map cm;
    const int ndepth = s->def.dim == 3 && !slab ? 5 : 1;
    if ((st = collider_map_make(&cm, &f, s, uv, s->def.dim == 3 ? 2 : -1, depths, ndepth, err))) {
        mem_free(val, bytes);
        return st;
    }
    colliders_draw(c, &cm, 0);
    if (s->def.dim == 2 && (st = fill_material(c, &f, s, d, map, info, err))) {
        collider_map_free(&cm);
        mem_free(val, bytes);
        return st;
    }
    /* a particle covers its share of a cell: (dx^dim / ppc)^(1/dim) */
    /* a particle covers its share of the material now: (V0 J)^(1/dim) across,
     * so a risen loaf stays solid rather than breaking into dots */
    double *J = n > 0 ? mem_alloc(sizeof(double) * (size_t)n) : NULL;
    if (n > 0 && !J) {
        collider_map_free(&cm);
        mem_free(val, bytes);
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory rendering '%s'", d->field);
    }
    /* MPM only: an SPH particle's J comes from its density's kernel sum, which
     * thins out at a free surface and would draw spray as large discs */
    if (J && (s->def.solver != HEARTH_SOLVER_MPM || hearth_scene_particle_field(s, "J", J, err) != HEARTH_OK))
        for (int i = 0; i < n; i++) J[i] = 1; /* as seeded */
    err_clear(err);
    const double *V0 = n > 0 ? pcold(&s->ps, PC_VOL0) : NULL;
    /* 3D: draw far to near so the nearest particle wins the pixel */
    int *ord = NULL;
    if (s->def.dim == 3 && n > 0 && (ord = mem_alloc(sizeof(int) * (size_t)n))) {
        const double *X = pcold(&s->ps, PC_X);
        const double zlo = s->def.lo[2], zr = s->def.hi[2] - s->def.lo[2];
        enum { NB = 256 };
        int cnt[NB + 1] = {0};
        for (int i = 0; i < n; i++) cnt[1 + (int)fmin(NB - 1, fmax(0, (X[3 * i + 2] - zlo) / zr * NB))]++;
        for (int b = 0; b < NB; b++) cnt[b + 1] += cnt[b];
        for (int i = 0; i < n; i++) ord[cnt[(int)fmin(NB - 1, fmax(0, (X[3 * i + 2] - zlo) / zr * NB))]++] = i;
    }
    const double *X = pcold(&s->ps, PC_X);
    cairo_save(c->cr);
    cairo_rectangle(c->cr, f.x0, f.y0, f.w, f.h);
    cairo_clip(c->cr);
    const double span = info->range[1] - info->range[0];
    for (int k = 0; k < n; k++) {
        const int i = ord ? ord[k] : k;
        if (slab && !(fabs(X[3 * i + 2] - zc) <= half)) continue; /* outside the slab */
        unsigned char rgb[3];
        cmap_eval(map, (val[i] - info->range[0]) / span, rgb);
        canvas_rgb(c, rgb, 1);
        const double J1 = isfinite(J[i]) ? fmin(4, fmax(0.25, J[i])) : 1;
        const double r = fmax(0.7, 0.65 * f.sc * pow(V0[i] * J1, 1.0 / s->def.dim)); /* 1.3 spacings across: no lattice gaps */
        cairo_arc(c->cr, px_of(&f, X[3 * i]), py_of(&f, X[3 * i + 1]), r, 0, 2 * CANVAS_PI);
        cairo_fill(c->cr);
    }
    cairo_restore(c->cr);
    if (ord) mem_free(ord, sizeof(int) * (size_t)n);
    if (J) mem_free(J, sizeof(double) * (size_t)n);
    mem_free(val, bytes);
    colliders_draw(c, &cm, 1);
    collider_map_free(&cm);
    axes(c, &f, "x", "y");
    title(c, &f, s, d, info, colorbar(c, &f, map, d->field, info->unit, info));
    return HEARTH_OK;
}

static hearth_status draw_slice(canvas *c, const hearth_scene *s, const hearth_picture_def *d, int map,
                                hearth_picture_info *info, hearth_error *err) {
    static const char *const names[3] = {"x", "y", "z"};
    int u, v;
    double lo[2], hi[2];
    view_of(s, d, &u, &v, lo, hi);
    const double at = isnan(d->at) ? 0.5 * (s->def.lo[d->axis] + s->def.hi[d->axis]) : d->at;
    frame f = layout(c, lo, hi);
    const int sw = f.w > 1 ? (int)f.w : 1, sh = f.h > 1 ? (int)f.h : 1;
    /* sample at about one value per dx/2: the field has no finer detail */
    int nw = (int)ceil((hi[0] - lo[0]) / (0.5 * s->def.dx)), nh = (int)ceil((hi[1] - lo[1]) / (0.5 * s->def.dx));
    if (nw > sw) nw = sw;
    if (nh > sh) nh = sh;
    size_t bytes = sizeof(double) * (size_t)nw * (size_t)nh;
    double *val = mem_alloc(bytes);
    if (!val) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for a %d x %d slice", nw, nh);
    const double rect[4] = {lo[0], lo[1], hi[0], hi[1]};
    hearth_status st = probe_slice_fraction(s, d->field, d->axis, at, rect, nw, nh, val, NULL, err);
    if (!st) {
        data_range(val, (long)nw * nh, info->data);
        st = choose_range(s, d, info, err);
    }
    cairo_surface_t *img = NULL;
    if (!st) {
        img = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, nw, nh);
        if (cairo_surface_status(img) != CAIRO_STATUS_SUCCESS) st = err_set(err, HEARTH_ERR_NOMEM, "out of memory for a %d x %d slice", nw, nh);
    }
    if (st) {
        if (img) cairo_surface_destroy(img);
        mem_free(val, bytes);
        return st;
    }
    /* the samples as a small image (row 0 = the top of the picture), outside
     * the material transparent; Cairo scales it up, smoothly */
    unsigned char *data = cairo_image_surface_get_data(img);
    const int stride = cairo_image_surface_get_stride(img);
    const double span = info->range[1] - info->range[0];
    for (int row = 0; row < nh; row++)
        for (int col = 0; col < nw; col++) {
            double x = val[(size_t)(nh - 1 - row) * nw + col];
            uint32_t p = 0;
            if (isfinite(x)) {
                unsigned char rgb[3];
                cmap_eval(map, (x - info->range[0]) / span, rgb);
                p = 0xff000000u | ((uint32_t)rgb[0] << 16) | ((uint32_t)rgb[1] << 8) | rgb[2];
            }
            memcpy(data + (size_t)row * stride + 4 * (size_t)col, &p, 4);
        }
    cairo_surface_mark_dirty(img);
    mem_free(val, bytes);
    canvas_rgb(c, EMPTY, 1);
    cairo_rectangle(c->cr, f.x0, f.y0, f.w, f.h);
    cairo_fill(c->cr);
    cairo_save(c->cr);
    cairo_rectangle(c->cr, f.x0, f.y0, f.w, f.h);
    cairo_clip(c->cr);
    cairo_translate(c->cr, f.x0, f.y0);
    cairo_scale(c->cr, f.w / nw, f.h / nh);
    cairo_set_source_surface(c->cr, img, 0, 0);
    cairo_pattern_set_filter(cairo_get_source(c->cr), CAIRO_FILTER_BILINEAR);
    cairo_pattern_set_extend(cairo_get_source(c->cr), CAIRO_EXTEND_PAD);
    cairo_paint(c->cr);
    cairo_restore(c->cr);
    cairo_surface_destroy(img);
    const int uv[2] = {u, v};
    collider_map cm;
    if ((st = collider_map_make(&cm, &f, s, uv, s->def.dim == 3 ? d->axis : -1, &at, 1, err))) return st;
    colliders_draw(c, &cm, 0);
    colliders_draw(c, &cm, 1);
    collider_map_free(&cm);
    axes(c, &f, names[u], names[v]);
    title(c, &f, s, d, info, colorbar(c, &f, map, d->field, info->unit, info));
    return HEARTH_OK;
}

hearth_status hearth_render(const hearth_scene *s, const hearth_picture_def *d, const char *path, hearth_picture_info *info,
                            hearth_error *err) {
    err_clear(err);
    hearth_picture_info local;
    if (!info) info = &local;
    memset(info, 0, sizeof *info);
    int map = CMAP_VIRIDIS;
    hearth_status st = check_def(s, d, &map, err);
    if (st) return st;
    if (hearth_field_components(d->field) == 0) return hearth_scene_particle_field(s, d->field, NULL, err);
    snprintf(info->colormap, sizeof info->colormap, "%s", cmap_name(map));
    canvas_unit(hearth_field_unit(d->field), info->unit, sizeof info->unit);
    int height = d->height;
    if (height == 0) {
        int u, v;
        double lo[2], hi[2];
        view_of(s, d, &u, &v, lo, hi);
        height = aspect_height(d->width, hi[0] - lo[0], hi[1] - lo[1]);
    }
    canvas c;
    if ((st = canvas_init(&c, d->width, height, BG, err))) return st;
    info->width = c.w, info->height = c.h;
    st = d->kind == HEARTH_PICTURE_PARTICLES ? draw_particles(&c, s, d, map, info, err) : draw_slice(&c, s, d, map, info, err);
    c.title = info->title; /* the title as drawn, also as the file's text: what the frame says it shows */
    if (!st) st = canvas_write_png(&c, path, err);
    canvas_free(&c);
    return st;
}

hearth_status hearth_render_particles(const hearth_scene *s, const char *field, const char *path, int width, int height,
                                      hearth_error *err) {
    hearth_picture_def d = hearth_default_picture_def();
    d.field = field, d.kind = HEARTH_PICTURE_PARTICLES, d.width = width, d.height = height;
    return hearth_render(s, &d, path, NULL, err);
}

hearth_status hearth_render_slice(const hearth_scene *s, const char *field, int axis, double at, const char *path, int width,
                                  hearth_error *err) {
    hearth_picture_def d = hearth_default_picture_def();
    d.field = field, d.axis = axis, d.at = at, d.width = width;
    return hearth_render(s, &d, path, NULL, err);
}

const char *hearth_colormap_names(void) { return cmap_names(); }

int hearth_colormap_rgb(const char *name, double t, unsigned char rgb[3]) {
    int map = cmap_by_name(name);
    if (map < 0) return -1;
    cmap_eval(map, t, rgb);
    return 0;
}
