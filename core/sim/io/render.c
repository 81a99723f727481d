/* render.c: pictures of a scene for people: particles coloured by a field,
 * and plane slices, each with a colour bar, a title and the sim time. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "colormap.h"
#include "error.h"
#include "image.h"
#include "io_png.h"
#include "scene.h"

static const unsigned char BG[3] = {24, 24, 28}, FG[3] = {230, 230, 230}, FRAME[3] = {90, 90, 100};

static int map_for(const char *field) {
    if (strcmp(field, "browning") == 0) return CMAP_BROWNING; /* the crust index (fields/browning.c) */
    return strncmp(field, "temperature", 11) == 0 ? CMAP_INFERNO : CMAP_VIRIDIS;
}

static void finite_range(const double *v, long n, double *lo, double *hi) {
    *lo = INFINITY;
    *hi = -INFINITY;
    for (long i = 0; i < n; i++)
        if (isfinite(v[i])) {
            if (v[i] < *lo) *lo = v[i];
            if (v[i] > *hi) *hi = v[i];
        }
    if (*lo > *hi) *lo = *hi = 0;
}

/* Plot area inside the canvas that keeps the domain's aspect ratio. */
typedef struct frame {
    int x0, y0, w, h; /* pixels */
    double lo[2], hi[2];
} frame;

static frame layout(const img *im, const double lo[2], const double hi[2]) {
    const int top = 28, bottom = 10, left = 10, right = 110;
    int aw = im->w - left - right, ah = im->h - top - bottom;
    if (aw < 8) aw = 8;
    if (ah < 8) ah = 8;
    double sx = aw / (hi[0] - lo[0]), sy = ah / (hi[1] - lo[1]), sc = sx < sy ? sx : sy;
    frame f = {left, top, (int)((hi[0] - lo[0]) * sc), (int)((hi[1] - lo[1]) * sc), {lo[0], lo[1]}, {hi[0], hi[1]}};
    f.x0 += (aw - f.w) / 2;
    return f;
}

static void decorate(img *im, const frame *f, const hearth_scene *s, const char *field, int map, double vmin, double vmax) {
    const char *unit = hearth_field_unit(field);
    char title[160];
    snprintf(title, sizeof title, "%s [%s]   t = %.4g s   step %ld", field, unit ? unit : "?", s->t, s->step);
    img_text(im, 10, 8, title, 1, FG);
    img_line(im, f->x0 - 1, f->y0 - 1, f->x0 + f->w, f->y0 - 1, FRAME);
    img_line(im, f->x0 - 1, f->y0 + f->h, f->x0 + f->w, f->y0 + f->h, FRAME);
    img_line(im, f->x0 - 1, f->y0 - 1, f->x0 - 1, f->y0 + f->h, FRAME);
    img_line(im, f->x0 + f->w, f->y0 - 1, f->x0 + f->w, f->y0 + f->h, FRAME);
    int bh = f->h > 60 ? f->h - 20 : f->h;
    img_colorbar(im, im->w - 100, f->y0 + 10, 16, bh, map, vmin, vmax, unit);
}

static hearth_status scalar_per_particle(const hearth_scene *s, const char *field, double **out, hearth_error *err) {
    const int n = s->ps.n, nc = hearth_field_components(field);
    if (nc == 0) return hearth_scene_particle_field(s, field, NULL, err); /* produces the unknown-field message */
    if (nc == 9) /* a tensor has no one colour: its components and invariants are fields of their own */
        return err_set(err, HEARTH_ERR_PARAM,
                       "field '%s' is a tensor; picture one component (%s_xx, %s_yy, %s_zz, %s_xy, %s_xz, %s_yz), "
                       "pressure or von_mises", field, field, field, field, field, field, field);
    double *v = mem_alloc(sizeof(double) * (size_t)(n > 0 ? n : 1) * (size_t)nc);
    if (!v) return err_set(err, HEARTH_ERR_NOMEM, "out of memory rendering '%s'", field);
    hearth_status st = hearth_scene_particle_field(s, field, v, err);
    if (st) {
        mem_free(v, sizeof(double) * (size_t)(n > 0 ? n : 1) * (size_t)nc);
        return st;
    }
    if (nc == 3) /* a vector shows as its magnitude */
        for (int i = 0; i < n; i++) v[i] = sqrt(v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1] + v[3 * i + 2] * v[3 * i + 2]);
    *out = v;
    return HEARTH_OK;
}

hearth_status hearth_render_particles(const hearth_scene *s, const char *field, const char *path, int width, int height,
                                      hearth_error *err) {
    err_clear(err);
    const int n = s->ps.n, nc = hearth_field_components(field);
    double *val = NULL;
    hearth_status st = scalar_per_particle(s, field, &val, err);
    if (st) return st;
    img im;
    if ((st = img_init(&im, width, height, BG, err))) {
        mem_free(val, sizeof(double) * (size_t)(n > 0 ? n : 1) * (size_t)nc);
        return st;
    }
    const double lo[2] = {s->def.lo[0], s->def.lo[1]}, hi[2] = {s->def.hi[0], s->def.hi[1]};
    frame f = layout(&im, lo, hi);
    double vmin, vmax;
    finite_range(val, n, &vmin, &vmax);
    const int map = map_for(field);
    if (map == CMAP_BROWNING) vmin = 0, vmax = 1; /* absolute: raw dough to dark crust */
    const double sc = f.w / (hi[0] - lo[0]);
    /* a particle covers its share of a cell: (dx^dim / ppc)^(1/dim) */
    double r = 0.5 * sc * pow(n > 0 ? pcold(&s->ps, PC_VOL0)[0] : s->def.dx * s->def.dx, 1.0 / s->def.dim);
    if (r < 0.7) r = 0.7;
    /* 3D: draw far to near so the nearest particle wins the pixel */
    int *ord = NULL;
    if (s->def.dim == 3 && n > 0) {
        ord = mem_alloc(sizeof(int) * (size_t)n);
        if (ord) {
            const double *X = pcold(&s->ps, PC_X);
            const double zlo = s->def.lo[2], zr = s->def.hi[2] - s->def.lo[2];
            enum { NB = 256 };
            int cnt[NB + 1] = {0};
            for (int i = 0; i < n; i++) cnt[1 + (int)fmin(NB - 1, fmax(0, (X[3 * i + 2] - zlo) / zr * NB))]++;
            for (int b = 0; b < NB; b++) cnt[b + 1] += cnt[b];
            for (int i = 0; i < n; i++) ord[cnt[(int)fmin(NB - 1, fmax(0, (X[3 * i + 2] - zlo) / zr * NB))]++] = i;
        }
    }
    const double *X = pcold(&s->ps, PC_X);
    for (int k = 0; k < n; k++) {
        const int i = ord ? ord[k] : k;
        unsigned char c[3];
        cmap_eval(map, vmax > vmin ? (val[i] - vmin) / (vmax - vmin) : 0.5, c);
        img_disc(&im, f.x0 + (X[3 * i] - lo[0]) * sc, f.y0 + f.h - (X[3 * i + 1] - lo[1]) * sc, r, c);
    }
    if (ord) mem_free(ord, sizeof(int) * (size_t)n);
    mem_free(val, sizeof(double) * (size_t)(n > 0 ? n : 1) * (size_t)nc);
    /* colliders are drawn as their outline: pixels where the distance changes sign */
    for (int c = 0; c < s->ncol; c++)
        for (int py = f.y0; py < f.y0 + f.h; py++)
            for (int px = f.x0; px < f.x0 + f.w; px++) {
                double x[3] = {lo[0] + (px + 0.5 - f.x0) / sc, lo[1] + (f.y0 + f.h - py - 0.5) / sc,
                               s->def.dim == 3 ? 0.5 * (s->def.lo[2] + s->def.hi[2]) : 0};
                double d = collider_sdf(&s->cols[c], x, NULL);
                if (d <= 0 && d > -1.5 / sc) {
                    unsigned char *p = im.rgb + 3 * ((size_t)py * im.w + px);
                    p[0] = 200, p[1] = 200, p[2] = 210;
                }
            }
    decorate(&im, &f, s, field, map, vmin, vmax);
    st = png_write_rgb(path, im.w, im.h, im.rgb, err);
    img_free(&im);
    return st;
}

hearth_status hearth_render_slice(const hearth_scene *s, const char *field, int axis, double at, const char *path, int width,
                                  hearth_error *err) {
    err_clear(err);
    const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2;
    const double lo[2] = {s->def.lo[u], s->def.lo[v]}, hi[2] = {s->def.hi[u], s->def.hi[v]};
    if (width < 64 || width > 8192) return err_set(err, HEARTH_ERR_PARAM, "slice picture: width %d px; valid range [64, 8192]", width);
    int height = (int)((width - 120) * (hi[1] - lo[1]) / (hi[0] - lo[0])) + 38;
    if (height < 64) height = 64;
    img im;
    hearth_status st = img_init(&im, width, height, BG, err);
    if (st) return st;
    frame f = layout(&im, lo, hi);
    const int sw = f.w > 1 ? f.w : 1, sh = f.h > 1 ? f.h : 1;
    /* sample at about one value per dx/2, then scale up: the field has no finer detail */
    int nw = (int)ceil((hi[0] - lo[0]) / (0.5 * s->def.dx)), nh = (int)ceil((hi[1] - lo[1]) / (0.5 * s->def.dx));
    if (nw > sw) nw = sw;
    if (nh > sh) nh = sh;
    double *val = mem_alloc(sizeof(double) * (size_t)nw * (size_t)nh);
    if (!val) {
        img_free(&im);
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory for a %d x %d slice", nw, nh);
    }
    if ((st = hearth_probe_slice(s, field, axis, at, nw, nh, val, err))) {
        mem_free(val, sizeof(double) * (size_t)nw * (size_t)nh);
        img_free(&im);
        return st;
    }
    double vmin, vmax;
    finite_range(val, (long)nw * nh, &vmin, &vmax);
    const int map = map_for(field);
    if (map == CMAP_BROWNING) vmin = 0, vmax = 1; /* absolute, as particles: frames of a bake compare */
    for (int py = 0; py < f.h; py++)
        for (int px = 0; px < f.w; px++) {
            int row = (int)((double)(f.h - 1 - py) / f.h * nh), col = (int)((double)px / f.w * nw);
            double x = val[(size_t)row * nw + col];
            unsigned char c[3];
            if (isfinite(x)) cmap_eval(map, vmax > vmin ? (x - vmin) / (vmax - vmin) : 0.5, c);
            else memcpy(c, BG, 3);
            memcpy(im.rgb + 3 * ((size_t)(f.y0 + py) * im.w + f.x0 + px), c, 3);
        }
    mem_free(val, sizeof(double) * (size_t)nw * (size_t)nh);
    decorate(&im, &f, s, field, map, vmin, vmax);
    st = png_write_rgb(path, im.w, im.h, im.rgb, err);
    img_free(&im);
    return st;
}
