/* shape_mask.c: the signed distance field behind hearth_shape_mask.
 *
 * A mask is a grey PNG whose dark pixels (luminance < 128, "darker than 50%
 * grey") are inside. At creation we compute, once, a signed distance at every
 * pixel centre; queries then cost one bilinear lookup, so a mask collider is
 * as cheap as a box and independent of the shape's complexity.
 *
 * The field. For an outside pixel, let q be the nearest inside pixel centre
 * (exact Euclidean distance in metres); for an inside pixel, the nearest
 * outside one. The sample is +-(|p - q| - delta). delta is the half-pixel
 * convention that puts the zero level set between the last inside and first
 * outside centres instead of on a centre: an inside/outside pair along an
 * axis gets -s/2 and +s/2, so the bilinear zero crossing sits exactly on the
 * pixel edge between them.
 *
 * Non-square pixels (the image rectangle's aspect differs from the image's)
 * are handled exactly as far as distances go: the transform runs with the
 * real pixel spacings sx, sy as weights, so |p - q| is the true distance in
 * metres. A constant delta cannot be half a pixel in both directions, so we
 * take the radius of the ellipse inscribed in a pixel, in the direction of q:
 * delta = 0.5 |d| / sqrt(di^2 + dj^2) for the lattice offset (di, dj). It is
 * s/2 along each axis, and exactly the usual half pixel in every direction
 * when pixels are square. Rejected: delta = min(sx, sy)/2, which overstates
 * distances near the boundary by up to half the pixel's anisotropy.
 *
 * The transform is Felzenszwalb and Huttenlocher's (2012): per column the
 * nearest site row (two sweeps), then per row the lower envelope of parabolas
 * over those columns. It is exact and O(pixels). We track which site is
 * nearest (not only the squared distance) because delta depends on it.
 *
 * Outside the image the shape is empty. The transform for inside pixels sees
 * a ring of virtual outside pixels just beyond the image, and every depth is
 * bounded by the distance to the image's edge, so an inside pixel on the
 * border gets at most half a pixel of depth and the zero level set closes at
 * the image rectangle: the solid never leaves lo..hi.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "io_png.h"
#include "shapes.h"

struct shape_mask {
    int w, h;
    double lo[2], hi[2];
    double s[2]; /* pixel size in x and y (metres) */
    float *d;    /* w*h samples at pixel centres, row 0 at the bottom (y = lo[1] + s[1]/2).
                  * float: half the memory, and 7 digits is far below a pixel. */
};

/* Column indices fit 16 bits (virtual rows -1 and h included), which saves
 * 2 bytes per pixel of scratch on the largest masks. */
#define NONE INT16_MIN
_Static_assert(MASK_DIM_MAX + 1 < INT16_MAX, "row indices must fit int16_t");

static size_t field_bytes(int w, int h) { return (size_t)w * (size_t)h * sizeof(float); }

/* ---- the distance transform -------------------------------------------- */

/* Scratch of one transform; every array is from mem_alloc. */
typedef struct edt {
    int w, h;
    const unsigned char *px; /* grey, top row first (as png_read_gray gives it) */
    int16_t *ny;             /* w*h: nearest site row in the same column, or NONE */
    int16_t *above;          /* w: nearest site row at or above the current row */
    double *f, *z;           /* w+2, w+3: one row's column costs; envelope breakpoints */
    int *v, *near;           /* w+2: envelope parabolas; nearest column per position */
} edt;

static int inside_px(const edt *t, int i, int j) {
    return t->px[(size_t)(t->h - 1 - j) * (size_t)t->w + (size_t)i] < 128;
}

/* Nearest site for each position p in 0..n-1 under cost (p - q)^2 + f[q]
 * (FH's lower envelope of parabolas; f[q] = inf means "no site at q").
 * near[p] = -1 when there is no site at all. v needs n, z n + 1 entries. */
static void fh_nearest(const double *f, int n, int *v, double *z, int *near) {
    int k = -1;
    for (int q = 0; q < n; q++) {
        if (isinf(f[q])) continue;
        double s = -HUGE_VAL;
        while (k >= 0) {
            int r = v[k];
            s = ((f[q] + (double)q * q) - (f[r] + (double)r * r)) / (2.0 * (q - r));
            if (s > z[k]) break;
            k--; /* parabola r is nowhere lowest */
        }
        k++;
        v[k] = q;
        z[k] = k == 0 ? -HUGE_VAL : s;
        z[k + 1] = HUGE_VAL;
    }
    if (k < 0) {
        for (int p = 0; p < n; p++) near[p] = -1;
        return;
    }
    k = 0;
    for (int p = 0; p < n; p++) {
        while (z[k + 1] < p) k++;
        near[p] = v[k];
    }
}

/* One signed transform: the sites are the pixels with inside_px == want; the
 * samples of all other pixels are written into field. Distances to inside
 * sites are positive (the pixel is outside), to outside sites negative. The
 * outside sites include the virtual ring around the image (pad). */
static void edt_run(edt *t, int want, const double s[2], float *field) {
    int w = t->w, h = t->h, pad = !want;
    /* columns: nearest site row, from below then from above */
    for (int j = 0; j < h; j++)
        for (int i = 0; i < w; i++) {
            size_t k = (size_t)j * (size_t)w + (size_t)i;
            int16_t below = j > 0 ? t->ny[k - (size_t)w] : (int16_t)(pad ? -1 : NONE);
            t->ny[k] = inside_px(t, i, j) == want ? (int16_t)j : below;
        }
    for (int i = 0; i < w; i++) t->above[i] = (int16_t)(pad ? h : NONE);
    for (int j = h - 1; j >= 0; j--)
        for (int i = 0; i < w; i++) {
            size_t k = (size_t)j * (size_t)w + (size_t)i;
            if (inside_px(t, i, j) == want) t->above[i] = (int16_t)j;
            int a = t->above[i], b = t->ny[k];
            if (a != NONE && (b == NONE || a - j < j - b)) t->ny[k] = (int16_t)a;
        }
    /* rows: envelope over columns, in units of sx so FH's unit spacing applies.
     * Positions 0 and w+1 are the virtual columns beside the image. */
    double r2 = (s[1] / s[0]) * (s[1] / s[0]);
    for (int j = 0; j < h; j++) {
        const int16_t *row = t->ny + (size_t)j * (size_t)w;
        t->f[0] = t->f[w + 1] = pad ? 0.0 : HUGE_VAL;
        for (int i = 0; i < w; i++) {
            double dj = (double)(j - row[i]);
            t->f[i + 1] = row[i] == NONE ? HUGE_VAL : r2 * dj * dj;
        }
        fh_nearest(t->f, w + 2, t->v, t->z, t->near);
        for (int i = 0; i < w; i++) {
            if (inside_px(t, i, j) == want) continue; /* a site: the other transform's job */
            int q = t->near[i + 1];
            HEARTH_ASSERT(q >= 0); /* mask_load checked there is an inside pixel */
            double di = (double)(i + 1 - q);
            double dj = (double)(j - (q == 0 || q == w + 1 ? j : row[q - 1]));
            double dist = hypot(s[0] * di, s[1] * dj);
            double val = dist * (1.0 - 0.5 / sqrt(di * di + dj * dj)); /* minus delta */
            /* A depth is never more than the distance to the image's edge,
             * which is what the virtual ring gives along each axis. The bound
             * matters only for non-square pixels: there the Euclidean nearest
             * site need not have the smallest distance minus delta (a site
             * along the short side has the smaller delta), so a border pixel
             * could get more than half a pixel of depth and the solid would
             * cross the image rectangle. fuzz_png_mask found it: a 16x1 mask
             * over 2 x 1 m was 0.44 m deep at its top edge (corpus file
             * crash-aniso-16x1-leaks-above.png). Square pixels never reach it. */
            if (!want) {
                double ex = fmin(i + 0.5, w - i - 0.5) * s[0], ey = fmin(j + 0.5, h - j - 0.5) * s[1];
                val = fmin(val, fmin(ex, ey));
            }
            field[(size_t)j * (size_t)w + (size_t)i] = (float)(want ? val : -val);
        }
    }
}

static void edt_free(edt *t) {
    size_t n = (size_t)t->w + 2;
    mem_free(t->ny, (size_t)t->w * (size_t)t->h * sizeof *t->ny);
    mem_free(t->above, (size_t)t->w * sizeof *t->above);
    mem_free(t->f, n * sizeof *t->f);
    mem_free(t->z, (n + 1) * sizeof *t->z);
    mem_free(t->v, n * sizeof *t->v);
    mem_free(t->near, n * sizeof *t->near);
}

/* ---- creation ------------------------------------------------------------ */

/* Width and height from the IHDR chunk, without decoding: lets us refuse a
 * huge image before png_read_gray allocates 5 bytes per pixel for it.
 * 0 when the file is not readable as a PNG header; png_read_gray then
 * reports why, in its own words. */
static int peek_png_size(const char *path, unsigned long *w, unsigned long *h) {
    static const unsigned char sig[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char b[24];
    FILE *fp = fopen(path, "rb");
    if (!fp) return 0;
    size_t got = fread(b, 1, sizeof b, fp);
    fclose(fp);
    if (got != sizeof b || memcmp(b, sig, 8) != 0 || memcmp(b + 12, "IHDR", 4) != 0) return 0;
    *w = (unsigned long)b[16] << 24 | (unsigned long)b[17] << 16 | (unsigned long)b[18] << 8 | b[19];
    *h = (unsigned long)b[20] << 24 | (unsigned long)b[21] << 16 | (unsigned long)b[22] << 8 | b[23];
    return 1;
}

static shape_mask *too_large(const char *path, unsigned long w, unsigned long h, hearth_error *err) {
    err_set(err, HEARTH_ERR_PARAM, "mask '%s' is %lux%lu pixels; the largest mask is %dx%d", path, w, h,
            MASK_DIM_MAX, MASK_DIM_MAX);
    return NULL;
}

static shape_mask *mask_alloc(int w, int h) {
    shape_mask *m = mem_calloc(sizeof *m);
    if (!m) return NULL;
    m->w = w;
    m->h = h;
    m->d = mem_alloc(field_bytes(w, h));
    if (!m->d) {
        mem_free(m, sizeof *m);
        return NULL;
    }
    return m;
}

/* 0 when a pixel would be too small to be a number (lo and hi a few ulps apart). */
static int mask_set_rect(shape_mask *m, const double lo[2], const double hi[2]) {
    for (int a = 0; a < 2; a++) {
        m->lo[a] = lo[a];
        m->hi[a] = hi[a];
    }
    m->s[0] = (hi[0] - lo[0]) / m->w;
    m->s[1] = (hi[1] - lo[1]) / m->h;
    return m->s[0] >= DBL_MIN && m->s[1] >= DBL_MIN;
}

/* lo < hi in both axes, with a pixel size that is a positive finite number. */
static int rect_ok(const double lo[2], const double hi[2]) {
    for (int a = 0; a < 2; a++) {
        if (!isfinite(lo[a]) || !isfinite(hi[a]) || !(lo[a] < hi[a])) return 0;
        if (!isfinite(hi[a] - lo[a])) return 0;
    }
    return 1;
}

shape_mask *mask_load(const char *path, const double lo[2], const double hi[2], hearth_error *err) {
    if (!path) {
        err_set(err, HEARTH_ERR_PARAM, "hearth_shape_mask: the PNG path is NULL");
        return NULL;
    }
    if (!lo || !hi) {
        err_set(err, HEARTH_ERR_PARAM, "mask '%s': the rectangle lo..hi is missing", path);
        return NULL;
    }
    if (!rect_ok(lo, hi)) {
        err_set(err, HEARTH_ERR_PARAM,
                "mask '%s': lo must be below hi in both x and y, all finite (got lo = (%g, %g), hi = (%g, %g))",
                path, lo[0], lo[1], hi[0], hi[1]);
        return NULL;
    }
    unsigned long pw, ph;
    if (peek_png_size(path, &pw, &ph) && (pw > MASK_DIM_MAX || ph > MASK_DIM_MAX)) return too_large(path, pw, ph, err);

    int w, h;
    unsigned char *px;
    if (png_read_gray(path, &w, &h, &px, err) != HEARTH_OK) return NULL;
    size_t npx = (size_t)w * (size_t)h;
    if (w > MASK_DIM_MAX || h > MASK_DIM_MAX) { /* the file changed since the peek */
        mem_free(px, npx);
        return too_large(path, (unsigned long)w, (unsigned long)h, err);
    }
    size_t ninside = 0;
    for (size_t k = 0; k < npx; k++) ninside += px[k] < 128;
    if (ninside == 0) {
        mem_free(px, npx);
        err_set(err, HEARTH_ERR_FORMAT,
                "mask '%s' has nothing inside: no pixel is darker than 50%% grey (draw the shape dark on a light background)",
                path);
        return NULL;
    }

    shape_mask *m = mask_alloc(w, h);
    size_t n = (size_t)w + 2;
    edt t = {.w = w, .h = h, .px = px};
    t.ny = mem_alloc(npx * sizeof *t.ny);
    t.above = mem_alloc((size_t)w * sizeof *t.above);
    t.f = mem_alloc(n * sizeof *t.f);
    t.z = mem_alloc((n + 1) * sizeof *t.z);
    t.v = mem_alloc(n * sizeof *t.v);
    t.near = mem_alloc(n * sizeof *t.near);
    if (m && !mask_set_rect(m, lo, hi)) {
        mask_free(m);
        m = NULL;
        err_set(err, HEARTH_ERR_PARAM, "mask '%s': the rectangle lo..hi is too small for %dx%d pixels", path, w, h);
    } else if (m && t.ny && t.above && t.f && t.z && t.v && t.near) {
        edt_run(&t, 1, m->s, m->d); /* outside pixels: distance to the shape */
        edt_run(&t, 0, m->s, m->d); /* inside pixels: depth */
    } else {
        mask_free(m);
        m = NULL;
        err_set(err, HEARTH_ERR_NOMEM, "mask '%s': out of memory for its %dx%d distance field", path, w, h);
    }
    edt_free(&t);
    mem_free(px, npx);
    return m;
}

shape_mask *mask_copy(const shape_mask *m) {
    shape_mask *c = mask_alloc(m->w, m->h);
    if (!c) return NULL;
    float *d = c->d;
    *c = *m;
    c->d = d;
    memcpy(c->d, m->d, field_bytes(m->w, m->h));
    return c;
}

void mask_free(shape_mask *m) {
    if (!m) return;
    mem_free(m->d, field_bytes(m->w, m->h));
    mem_free(m, sizeof *m);
}

void mask_bounds(const shape_mask *m, double lo[2], double hi[2]) {
    for (int a = 0; a < 2; a++) {
        lo[a] = m->lo[a];
        hi[a] = m->hi[a];
    }
}

/* ---- queries -------------------------------------------------------------- */

/* Inside the rectangle spanned by the pixel centres: bilinear interpolation.
 * Elsewhere: the value at the nearest point c of that rectangle plus |x - c|.
 * The centre ring reaches half a pixel short of the image edge; the field is
 * at least -s/2 on its border (the virtual outside ring), so this is >= 0 on
 * and beyond the image rectangle and grows like the distance far away. */
static double field_at(const shape_mask *m, double x, double y) {
    /* continuous sample coordinates: centre (i, j) is at u = i, v = j */
    double u = (x - m->lo[0]) / m->s[0] - 0.5, v = (y - m->lo[1]) / m->s[1] - 0.5;
    double cu = u < 0 ? 0 : (u > m->w - 1 ? m->w - 1 : u);
    double cv = v < 0 ? 0 : (v > m->h - 1 ? m->h - 1 : v);
    double ex = (u - cu) * m->s[0], ey = (v - cv) * m->s[1], e = hypot(ex, ey);
    /* cell: clamped so the last centre row and column use the cell below them */
    int i0 = m->w > 1 ? (int)fmin(floor(cu), m->w - 2) : 0, i1 = i0 + (m->w > 1);
    int j0 = m->h > 1 ? (int)fmin(floor(cv), m->h - 2) : 0, j1 = j0 + (m->h > 1);
    double tx = cu - i0, ty = cv - j0;
    size_t w = (size_t)m->w;
    double f00 = m->d[(size_t)j0 * w + (size_t)i0], f10 = m->d[(size_t)j0 * w + (size_t)i1];
    double f01 = m->d[(size_t)j1 * w + (size_t)i0], f11 = m->d[(size_t)j1 * w + (size_t)i1];
    double f = (1 - ty) * ((1 - tx) * f00 + tx * f10) + ty * ((1 - tx) * f01 + tx * f11);
    return f + e;
}

/* Step of the normal's central differences, in pixels; see mask_sdf. */
#define NORMAL_STEP 3.0

/* The gradient is not the bilinear one. A thresholded mask is a staircase,
 * and the exact transform faithfully keeps its corners: measured on a disc of
 * radius 40 px, the bilinear gradient is up to 57 degrees off the true normal
 * within a pixel of the edge and still 10 at 20 px. Central differences over
 * +-3 px average the staircase out: <= 5 degrees on that disc at every
 * distance, <= 6 on edges at 5..30 degrees, ~10 at 45 degrees (the worst
 * staircase). Steps of 2 px gave 12, 4 px hardly better than 3 while rounding
 * sharp tips more. The cost is four extra lookups, no stored data. The
 * shape's values stay the exact sampled ones; only normals are smoothed, and
 * within 3 px of a sharp tip or a thin part they blend both sides, which is
 * all the pixels can tell anyway. */
double mask_sdf(const shape_mask *m, double x, double y, double g[2]) {
    if (!isfinite(x) || !isfinite(y)) {
        if (g) {
            g[0] = 0.0;
            g[1] = 1.0;
        }
        return isnan(x) || isnan(y) ? NAN : HUGE_VAL;
    }
    if (g) {
        double hx = NORMAL_STEP * m->s[0], hy = NORMAL_STEP * m->s[1];
        g[0] = (field_at(m, x + hx, y) - field_at(m, x - hx, y)) / (2 * hx);
        g[1] = (field_at(m, x, y + hy) - field_at(m, x, y - hy)) / (2 * hy);
    }
    return field_at(m, x, y);
}

/* ---- serialisation ------------------------------------------------------- */

int mask_write(FILE *f, const shape_mask *m) {
    int32_t wh[2] = {m->w, m->h};
    double r[4] = {m->lo[0], m->lo[1], m->hi[0], m->hi[1]};
    if (fwrite(wh, sizeof wh, 1, f) != 1 || fwrite(r, sizeof r, 1, f) != 1) return -1;
    size_t n = (size_t)m->w * (size_t)m->h;
    return fwrite(m->d, sizeof *m->d, n, f) == n ? 0 : -1;
}

shape_mask *mask_read(FILE *f) {
    int32_t wh[2];
    double r[4];
    if (fread(wh, sizeof wh, 1, f) != 1 || fread(r, sizeof r, 1, f) != 1) return NULL;
    if (wh[0] < 1 || wh[1] < 1 || wh[0] > MASK_DIM_MAX || wh[1] > MASK_DIM_MAX) return NULL;
    double lo[2] = {r[0], r[1]}, hi[2] = {r[2], r[3]};
    if (!rect_ok(lo, hi)) return NULL;
    shape_mask *m = mask_alloc(wh[0], wh[1]);
    if (!m) return NULL;
    size_t n = (size_t)m->w * (size_t)m->h;
    int ok = mask_set_rect(m, lo, hi) && fread(m->d, sizeof *m->d, n, f) == n;
    for (size_t k = 0; ok && k < n; k++) ok = isfinite(m->d[k]);
    if (!ok) {
        mask_free(m);
        return NULL;
    }
    return m;
}
