/* unit_mask.c: cookie-cutter shapes from PNG masks (hearth_shape_mask) and
 * their extrusion to 3D (hearth_shape_extrude). */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L /* mkdtemp */
#endif
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "alloc.h"
#include "hearth/hearth.h"
#include "io_png.h"
#include "png_fixture.h"
#include "shapes.h"
#include "test.h"

#define PI 3.14159265358979323846

static double sdf_at(const hearth_shape *s, double x, double y, double z) {
    double p[3] = {x, y, z};
    return hearth_shape_sdf(s, p, NULL);
}

/* ---- fixtures ------------------------------------------------------------ */

/* A fresh folder under /tmp for the files a case writes; each case removes
 * its files, and the (then empty) folder goes at exit. */
static char tmp_dir[64];
static void rm_tmp_dir(void) { rmdir(tmp_dir); }
static const char *tmp_path(char *buf, size_t n, const char *name) {
    if (!tmp_dir[0]) {
        snprintf(tmp_dir, sizeof tmp_dir, "/tmp/hearth_unit_mask_XXXXXX");
        if (!mkdtemp(tmp_dir)) {
            fprintf(stderr, "cannot make a temporary folder\n");
            exit(1);
        }
        atexit(rm_tmp_dir);
    }
    snprintf(buf, n, "%s/%s", tmp_dir, name);
    return buf;
}

/* Write a black-on-white w x h PNG; inside(i, r) gets column i and row r (top first). */
static void write_mask(const char *path, int w, int h, int (*inside)(int i, int r, void *ud), void *ud) {
    unsigned char *rgb = malloc((size_t)w * (size_t)h * 3);
    for (int r = 0; r < h; r++)
        for (int i = 0; i < w; i++) memset(rgb + ((size_t)r * (size_t)w + (size_t)i) * 3, inside(i, r, ud) ? 0 : 255, 3);
    hearth_error err = {0};
    CHECK(png_write_rgb(path, w, h, rgb, &err) == HEARTH_OK);
    free(rgb);
}

/* The disc of radius 40 px centred in a 100 x 100 image. */
static int disc40(int i, int r, void *ud) {
    (void)ud;
    double dx = i + 0.5 - 50, dy = r + 0.5 - 50;
    return dx * dx + dy * dy < 40.0 * 40.0;
}

/* Pseudo-random blobs: a reproducible image with many boundary shapes for the
 * exactness check (xorshift, seeded by position). */
static int blobs(int i, int r, void *ud) {
    (void)ud;
    uint32_t x = (uint32_t)(i / 3 * 7919 + r / 2 * 104729 + 12345);
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return (x % 5) < 2 || (i + r) % 11 == 0;
}

static int all_white(int i, int r, void *ud) {
    (void)i, (void)r, (void)ud;
    return 0;
}

static int all_black(int i, int r, void *ud) {
    (void)i, (void)r, (void)ud;
    return 1;
}

static uint64_t rng = 0x9e3779b97f4a7c15u;
static double rnd(double a, double b) {
    rng = rng * 6364136223846793005u + 1442695040888963407u;
    return a + (b - a) * (double)(rng >> 11) / 9007199254740992.0;
}

/* The field sample at pixel (i, r) computed by brute force: the nearest
 * opposite pixel centre (the virtual outside ring one pixel beyond the image
 * included for inside pixels), minus the inscribed-ellipse half pixel, and a
 * depth no more than the distance to the image's edge. Ties between sites at
 * the same distance may give different half pixels, so returns the interval
 * [lo, hi] of valid magnitudes. */
static void brute_sample(int w, int h, int (*inside)(int, int, void *), int i, int r, double sx, double sy,
                         double *lo, double *hi) {
    int in = inside(i, r, NULL);
    double best = HUGE_VAL;
    *lo = HUGE_VAL;
    *hi = -HUGE_VAL;
    for (int pass = 0; pass < 2; pass++)
        for (int rr = -1; rr <= h; rr++)
            for (int ii = -1; ii <= w; ii++) {
                int ring = rr < 0 || rr >= h || ii < 0 || ii >= w;
                if (ring && !in) continue; /* the ring is outside: a site only for inside pixels */
                if (!ring && inside(ii, rr, NULL) == in) continue;
                double di = ii - i, dj = rr - r, d = hypot(sx * di, sy * dj);
                if (pass == 0) {
                    if (d < best) best = d;
                } else if (d <= best * (1 + 1e-12)) {
                    double v = d * (1 - 0.5 / sqrt(di * di + dj * dj));
                    *lo = fmin(*lo, v);
                    *hi = fmax(*hi, v);
                }
            }
    if (in) { /* a depth is at most the distance to the image's edge (shape_mask.c) */
        double edge = fmin(fmin(i + 0.5, w - i - 0.5) * sx, fmin(r + 0.5, h - r - 0.5) * sy);
        double t = fmin(*lo, edge);
        *lo = -fmin(*hi, edge);
        *hi = -t;
    }
}

/* Compare the field at every step-th pixel centre with brute force. */
static void check_exact(const char *path, int w, int h, int (*inside)(int, int, void *), const double lo[2],
                        const double hi[2], int step) {
    hearth_error err = {0};
    hearth_shape *s = hearth_shape_mask(path, lo, hi, &err);
    CHECK(s);
    if (!s) return;
    double sx = (hi[0] - lo[0]) / w, sy = (hi[1] - lo[1]) / h;
    int bad = 0;
    for (int r = 0; r < h; r++)
        for (int i = 0; i < w; i++) {
            if ((r * w + i) % step) continue;
            double blo, bhi;
            brute_sample(w, h, inside, i, r, sx, sy, &blo, &bhi);
            /* row r (top first) is at y = hi - (r + 0.5) sy */
            double d = sdf_at(s, lo[0] + (i + 0.5) * sx, hi[1] - (r + 0.5) * sy, 0.0);
            double tol = 1e-6 * fmax(fabs(blo), fmax(sx, sy));
            if (!(d >= blo - tol && d <= bhi + tol)) {
                if (bad++ < 5)
                    fprintf(stderr, "  pixel (%d, %d): field %.9g, brute force %.9g..%.9g\n", i, r, d, blo, bhi);
            }
        }
    CHECK(bad == 0);
    hearth_shape_free(s);
}

/* ---- cases ---------------------------------------------------------------- */

TEST(mask_sdf_disc) {
    size_t base = hearth_bytes_allocated();
    char path[128], bpath[128], kpath[128];
    tmp_path(path, sizeof path, "disc.png");
    write_mask(path, 100, 100, disc40, NULL);
    hearth_error err = {0};
    const double lo[2] = {0, 0}, hi[2] = {1, 1};
    hearth_shape *s = hearth_shape_mask(path, lo, hi, &err);
    CHECK(s);
    if (!s) {
        fprintf(stderr, "  %s\n", err.msg);
        return;
    }
    const double px = 0.01, tol = 1.5 * px;
    CHECK_NEAR(sdf_at(s, 0.5, 0.5, 0), -0.4, tol);
    CHECK_NEAR(sdf_at(s, 0.5, 0.95, 0), 0.05, tol);
    CHECK_NEAR(sdf_at(s, 0.5, 0.5, 123.0), -0.4, tol); /* infinite in z */
    double worst = 0, worst_deg = 0;
    for (int k = 0; k < 72; k++) {
        double a = 2 * PI * k / 72, c = cos(a), sn = sin(a);
        double d = sdf_at(s, 0.5 + 0.4 * c, 0.5 + 0.4 * sn, 0);
        worst = fmax(worst, fabs(d));
        CHECK_NEAR(d, 0.0, tol);
        /* outside: half a pixel out, further, and beyond the image (0.6 leaves
         * the rectangle near the axes) */
        const double radii[5] = {0.405, 0.41, 0.43, 0.47, 0.6};
        for (int m = 0; m < 5; m++) {
            double x[3] = {0.5 + radii[m] * c, 0.5 + radii[m] * sn, 0}, n[3];
            double dd = hearth_shape_sdf(s, x, n);
            CHECK_NEAR(dd, radii[m] - 0.4, radii[m] < 0.5 ? tol : 0.1);
            CHECK(dd > 0);
            CHECK_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-12);
            CHECK(n[2] == 0.0);
            double cosang = n[0] * c + n[1] * sn;
            double deg = acos(fmin(1.0, cosang)) * 180 / PI;
            worst_deg = fmax(worst_deg, deg);
            if (!(deg < 10.0)) fprintf(stderr, "  r %g angle %d: %.2f deg\n", radii[m], k * 5, deg);
            CHECK(deg < 10.0);
        }
    }
    printf("  disc: |sdf| on the circle <= %.4g (pixel 0.01); normals within %.2f degrees of radial\n", worst,
           worst_deg);
    /* nothing solid outside the image rectangle, and the distance grows there */
    CHECK(sdf_at(s, -0.001, 0.5, 0) > 0);
    CHECK(sdf_at(s, 1.5, 1.5, 0) > 0.5);
    CHECK_NEAR(sdf_at(s, 3.0, 0.5, 0), 2.1, tol);
    /* NaN in, NaN out (no undefined conversion) */
    CHECK(isnan(sdf_at(s, NAN, 0.5, 0)));
    CHECK(sdf_at(s, INFINITY, 0.5, 0) > 1e300);
    hearth_shape_free(s);

    /* The samples are the exact transform: square pixels, non-square pixels
     * (the anisotropic weights), and an image full of small shapes touching
     * the border (the virtual outside ring). */
    check_exact(path, 100, 100, disc40, lo, hi, 7);
    check_exact(path, 100, 100, disc40, (const double[]){-1, 0}, (const double[]){2, 1}, 7);
    tmp_path(bpath, sizeof bpath, "blobs.png");
    write_mask(bpath, 37, 23, blobs, NULL);
    check_exact(bpath, 37, 23, blobs, (const double[]){0, 0}, (const double[]){37, 23}, 1);
    check_exact(bpath, 37, 23, blobs, (const double[]){0, 0}, (const double[]){1, 3}, 1);
    check_exact(bpath, 37, 23, blobs, (const double[]){0, 0}, (const double[]){0.3, 0.01}, 1);
    remove(bpath);

    /* an all-black image is the full rectangle */
    tmp_path(kpath, sizeof kpath, "black.png");
    write_mask(kpath, 8, 4, all_black, NULL);
    hearth_shape *k = hearth_shape_mask(kpath, (const double[]){0, 0}, (const double[]){2, 1}, &err);
    CHECK(k);
    if (k) {
        CHECK(sdf_at(k, 1.0, 0.5, 0) < 0);
        CHECK_NEAR(sdf_at(k, 2.0, 0.5, 0), 0.0, 1e-6);
        CHECK(sdf_at(k, 2.01, 0.5, 0) > 0);
    }
    hearth_shape_free(k);
    remove(kpath);
    remove(path);
    CHECK(hearth_bytes_allocated() == base);
}

static const char *asset(char *buf, size_t n, const char *name) {
    const char *root = getenv("HEARTH_SOURCE_ROOT");
    snprintf(buf, n, "%s/assets/masks/%s", root && *root ? root : ".", name);
    return buf;
}

TEST(mask_assets_load) {
    size_t base = hearth_bytes_allocated();
    char path[4096];
    hearth_error err = {0};
    const double lo[2] = {0.1, 0.1}, hi[2] = {0.3, 0.3};
    hearth_shape *star = hearth_shape_mask(asset(path, sizeof path, "star.png"), lo, hi, &err);
    CHECK(star);
    if (!star) fprintf(stderr, "  %s (set HEARTH_SOURCE_ROOT to the repository)\n", err.msg);
    if (star) {
        double blo[3], bhi[3];
        hearth_shape_bounds(star, blo, bhi);
        CHECK(blo[0] == lo[0] && blo[1] == lo[1] && bhi[0] == hi[0] && bhi[1] == hi[1]);
        CHECK(isinf(blo[2]) && blo[2] < 0 && isinf(bhi[2]) && bhi[2] > 0);
        CHECK(sdf_at(star, 0.2, 0.2, 0) < -0.01);
        const double corners[4][2] = {{0.1, 0.1}, {0.3, 0.1}, {0.1, 0.3}, {0.3, 0.3}};
        for (int k = 0; k < 4; k++) CHECK(sdf_at(star, corners[k][0], corners[k][1], 0) > 0.01);
        /* the top point is up: just below it inside, beside it outside */
        CHECK(sdf_at(star, 0.2, 0.28, 0) < 0);
        CHECK(sdf_at(star, 0.16, 0.28, 0) > 0);
    }
    hearth_shape_free(star);

    /* 160 x 200 pixels on 0.08 x 0.1 m: square pixels of 0.5 mm */
    const double glo[2] = {0, 0}, ghi[2] = {0.08, 0.1};
    hearth_shape *man = hearth_shape_mask(asset(path, sizeof path, "gingerbread.png"), glo, ghi, &err);
    CHECK(man);
    if (!man) fprintf(stderr, "  %s\n", err.msg);
    if (man) {
        double blo[3], bhi[3];
        hearth_shape_bounds(man, blo, bhi);
        CHECK(blo[0] == 0 && blo[1] == 0 && bhi[0] == 0.08 && bhi[1] == 0.1);
        CHECK(sdf_at(man, 0.04, 0.08, 0) < -0.01);  /* head */
        CHECK(sdf_at(man, 0.04, 0.045, 0) < -0.01); /* belly */
        CHECK(sdf_at(man, 0.04, 0.005, 0) > 0);     /* between the feet */
        CHECK(sdf_at(man, 0.0, 0.0, 0) > 0.005);
        CHECK(sdf_at(man, 0.08, 0.1, 0) > 0.005);
    }
    hearth_shape_free(man);
    CHECK(hearth_bytes_allocated() == base);
}

TEST(mask_extrude) {
    size_t base = hearth_bytes_allocated();
    char path[128];
    tmp_path(path, sizeof path, "disc.png");
    write_mask(path, 100, 100, disc40, NULL);
    hearth_error err = {0};
    hearth_shape *m = hearth_shape_mask(path, (const double[]){0, 0}, (const double[]){1, 1}, &err);
    CHECK(m);
    hearth_shape *e = hearth_shape_extrude(m, 0.1, 0.3);
    CHECK(e);
    hearth_shape_free(m); /* the extrusion owns a copy */
    if (e) {
        const double tol = 0.015;
        CHECK(sdf_at(e, 0.5, 0.5, 0.2) < 0);
        CHECK(sdf_at(e, 0.5, 0.5, 0.1) <= 1e-12);
        CHECK(sdf_at(e, 0.5, 0.5, 0.3) <= 1e-12);
        CHECK_NEAR(sdf_at(e, 0.5, 0.5, 0.2), -0.1, 1e-12); /* nearer the caps than the rim */
        CHECK_NEAR(sdf_at(e, 0.5, 0.5, 0.35), 0.05, 1e-12);
        CHECK_NEAR(sdf_at(e, 0.5, 0.5, 0.0), 0.1, 1e-12);
        CHECK(sdf_at(e, 0.5, 0.5, 5.0) > 4);
        CHECK_NEAR(sdf_at(e, 0.95, 0.5, 0.2), 0.05, tol); /* beside the wall */
        /* beyond the rim: the distance to the edge ring, not max of the two */
        CHECK_NEAR(sdf_at(e, 0.95, 0.5, 0.4), hypot(0.05, 0.1), tol);
        double n[3];
        hearth_shape_sdf(e, (const double[]){0.5, 0.5, 0.31}, n);
        CHECK(n[0] == 0 && n[1] == 0 && n[2] == 1);
        hearth_shape_sdf(e, (const double[]){0.5, 0.5, 0.09}, n);
        CHECK(n[2] == -1);
        hearth_shape_sdf(e, (const double[]){0.95, 0.5, 0.2}, n);
        CHECK(n[0] > 0.98 && n[2] == 0);
        double blo[3], bhi[3];
        hearth_shape_bounds(e, blo, bhi);
        CHECK(blo[0] == 0 && blo[1] == 0 && bhi[0] == 1 && bhi[1] == 1);
        CHECK(blo[2] == 0.1 && bhi[2] == 0.3);
        /* copies and unions carry the extrusion */
        hearth_shape *c = hearth_shape_copy(e);
        CHECK(c && sdf_at(c, 0.95, 0.5, 0.4) == sdf_at(e, 0.95, 0.5, 0.4));
        hearth_shape *b = hearth_shape_box((const double[]){3, 0, 0}, (const double[]){0.1, 0.1, 0.1});
        hearth_shape *u = hearth_shape_combine(HEARTH_UNION, c, b);
        CHECK(u && sdf_at(u, 0.5, 0.5, 0.2) < 0 && sdf_at(u, 3, 0, 0) < 0);
        hearth_shape_free(u);
        hearth_shape_free(b);
        hearth_shape_free(c);
    }
    hearth_shape_free(e);

    /* a 3D child gets max(), which never overstates: the sphere cut to a slab,
     * seen from above, is 1.5 from the top cap (not sqrt(1 + 1.5^2)) */
    hearth_shape *sp = hearth_shape_sphere((const double[]){0, 0, 0}, 1);
    hearth_shape *cut = hearth_shape_extrude(sp, -0.5, 0.5);
    CHECK(cut);
    if (cut) CHECK_NEAR(sdf_at(cut, 0, 0, 2), 1.5, 1e-15);
    hearth_shape_free(cut);
    /* bad arguments */
    CHECK(!hearth_shape_extrude(NULL, 0, 1));
    CHECK(!hearth_shape_extrude(sp, 1, 1));
    CHECK(!hearth_shape_extrude(sp, 1, 0));
    CHECK(!hearth_shape_extrude(sp, NAN, 1));
    hearth_shape_free(sp);
    remove(path);
    CHECK(hearth_bytes_allocated() == base);
}

TEST(mask_errors) {
    size_t base = hearth_bytes_allocated();
    hearth_error err = {0};
    const double lo[2] = {0, 0}, hi[2] = {1, 1};

    char missing[128];
    tmp_path(missing, sizeof missing, "no_such_mask.png");
    CHECK(!hearth_shape_mask(missing, lo, hi, &err));
    CHECK(err.code == HEARTH_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, missing);

    char text[128];
    tmp_path(text, sizeof text, "notes.png");
    FILE *f = fopen(text, "w");
    CHECK(f);
    if (f) {
        fputs("this is not a picture of a star\n", f);
        fclose(f);
    }
    err = (hearth_error){0};
    CHECK(!hearth_shape_mask(text, lo, hi, &err));
    CHECK(err.code == HEARTH_ERR_FORMAT);
    CHECK_STR_CONTAINS(err.msg, text);
    CHECK_STR_CONTAINS(err.msg, "not a PNG");

    char white[128];
    tmp_path(white, sizeof white, "white.png");
    write_mask(white, 16, 16, all_white, NULL);
    err = (hearth_error){0};
    CHECK(!hearth_shape_mask(white, lo, hi, &err));
    CHECK(err.code != HEARTH_OK);
    CHECK_STR_CONTAINS(err.msg, white);
    CHECK_STR_CONTAINS(err.msg, "nothing inside");

    char disc[128];
    tmp_path(disc, sizeof disc, "disc.png");
    write_mask(disc, 100, 100, disc40, NULL);
    const double bad[][4] = {{0, 0, 0, 1}, {0, 0, 1, 0}, {1, 0, 0, 1}, {0, 0, 1, -1}, {0, 0, NAN, 1}, {0, 0, INFINITY, 1}};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        err = (hearth_error){0};
        CHECK(!hearth_shape_mask(disc, (const double[]){bad[k][0], bad[k][1]}, (const double[]){bad[k][2], bad[k][3]},
                                 &err));
        CHECK(err.code == HEARTH_ERR_PARAM);
        CHECK_STR_CONTAINS(err.msg, "lo must be below hi");
        CHECK_STR_CONTAINS(err.msg, disc);
    }
    err = (hearth_error){0};
    CHECK(!hearth_shape_mask(NULL, lo, hi, &err));
    CHECK(err.code == HEARTH_ERR_PARAM);
    CHECK(!hearth_shape_mask(disc, NULL, hi, &err));
    err = (hearth_error){0};
    CHECK(!hearth_shape_mask(disc, lo, (const double[]){1e-310, 1}, &err)); /* pixels below DBL_MIN */
    CHECK(err.code == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "too small");
    CHECK(!hearth_shape_mask(missing, lo, hi, NULL)); /* err is optional */

    /* larger than 4096 pixels in one direction: refused from the header */
    char wide[128];
    tmp_path(wide, sizeof wide, "wide.png");
    write_mask(wide, 4097, 2, all_black, NULL);
    err = (hearth_error){0};
    CHECK(!hearth_shape_mask(wide, lo, hi, &err));
    CHECK(err.code == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, wide);
    CHECK_STR_CONTAINS(err.msg, "4096");

    /* every allocation that can fail, fails cleanly (libpng's included) */
    int failures = 0;
    for (long k = 0; k < 10000; k++) {
        mem_fail_after(k);
        err = (hearth_error){0};
        hearth_shape *s = hearth_shape_mask(disc, lo, hi, &err);
        mem_fail_after(-1);
        if (s) {
            hearth_shape_free(s);
            break;
        }
        failures++;
        CHECK(err.code == HEARTH_ERR_NOMEM);
        CHECK_STR_CONTAINS(err.msg, disc);
        CHECK(hearth_bytes_allocated() == base);
    }
    printf("  %d injected allocation failures reported cleanly\n", failures);
    CHECK(failures > 5);

    remove(text);
    remove(white);
    remove(disc);
    remove(wide);
    CHECK(hearth_bytes_allocated() == base);
}

TEST(mask_serialise) {
    size_t base = hearth_bytes_allocated();
    char path[4096];
    hearth_error err = {0};
    hearth_shape *m = hearth_shape_mask(asset(path, sizeof path, "star.png"), (const double[]){0.1, 0.1},
                                        (const double[]){0.3, 0.4}, &err); /* non-square pixels too */
    CHECK(m);
    if (!m) {
        fprintf(stderr, "  %s (set HEARTH_SOURCE_ROOT to the repository)\n", err.msg);
        return;
    }
    hearth_shape *e = hearth_shape_extrude(m, -0.05, 0.02);
    hearth_shape_free(m);
    CHECK(e);
    FILE *f = tmpfile();
    CHECK(f);
    if (!e || !f) return;
    CHECK(shape_write(f, e) == 0);
    long size = ftell(f);
    rewind(f);
    hearth_shape *r = shape_read(f, 0);
    CHECK(r);
    CHECK(ftell(f) == size); /* read exactly what was written */
    if (r) {
        for (int k = 0; k < 100; k++) {
            double x[3] = {rnd(0.0, 0.4), rnd(0.0, 0.5), rnd(-0.1, 0.07)}, na[3], nb[3];
            double a = hearth_shape_sdf(e, x, na), b = hearth_shape_sdf(r, x, nb);
            CHECK(a == b);
            CHECK(memcmp(na, nb, sizeof na) == 0);
        }
        double alo[3], ahi[3], blo[3], bhi[3];
        hearth_shape_bounds(e, alo, ahi);
        hearth_shape_bounds(r, blo, bhi);
        CHECK(memcmp(alo, blo, sizeof alo) == 0 && memcmp(ahi, bhi, sizeof ahi) == 0);
    }
    hearth_shape_free(r);

    /* a stream cut short anywhere reads as NULL, never a half shape */
    unsigned char *bytes = malloc((size_t)size);
    rewind(f);
    CHECK(fread(bytes, 1, (size_t)size, f) == (size_t)size);
    /* node headers are 112 bytes (kind, op, 13 doubles); the mask's own
     * header (w, h, lo, hi) 40 more */
    const long cuts[] = {0, 8, 60, 112, 120, 130, 224, 232, 250, 264, size / 2, size - 1};
    for (size_t k = 0; k < sizeof cuts / sizeof cuts[0]; k++) {
        FILE *g = tmpfile();
        CHECK(g);
        if (!g) break;
        fwrite(bytes, 1, (size_t)cuts[k], g);
        rewind(g);
        hearth_shape *t = shape_read(g, 0);
        CHECK(!t);
        hearth_shape_free(t);
        fclose(g);
    }
    free(bytes);
    fclose(f);
    hearth_shape_free(e);
    CHECK(hearth_bytes_allocated() == base);
}

/* ---- every PNG flavour, damaged files, the smallest masks ------------------ */

static int disc_xy(int x, int y, void *ud) {
    (void)ud;
    double dx = x + 0.5 - 20, dy = y + 0.5 - 15;
    return dx * dx + dy * dy < 9.0 * 9.0;
}

/* A disc drawn in every colour type and depth whose dark and light greys
 * fall either side of 50% gives the very same field as 8-bit grey. */
TEST(mask_png_flavours) {
    size_t base = hearth_bytes_allocated();
    char ref_path[128], path[128];
    const double lo[2] = {0, 0}, hi[2] = {0.4, 0.3};
    tmp_path(ref_path, sizeof ref_path, "ref.png");
    write_mask(ref_path, 40, 30, disc_xy, NULL);
    hearth_error err = {0};
    hearth_shape *ref = hearth_shape_mask(ref_path, lo, hi, &err);
    CHECK(ref != NULL);
    if (!ref) return;
    int tried = 0;
    for (int k = 0; k < PNG_FLAVOURS; k++) {
        const png_flavour *f = &png_flavours[k];
        if (!(f->want_dark < 128 && f->want_light >= 128)) continue; /* not a two-sided mask */
        tried++;
        tmp_path(path, sizeof path, f->name);
        CHECK(write_png_flavour(path, f, 40, 30, disc_xy, NULL) == 0);
        err = (hearth_error){0};
        hearth_shape *m = hearth_shape_mask(path, lo, hi, &err);
        if (!m) fprintf(stderr, "%s: %s\n", f->name, err.msg);
        CHECK(m != NULL);
        if (!m) continue;
        int differ = 0;
        for (int j = 0; j <= 30; j++)
            for (int i = 0; i <= 40; i++) {
                double x = -0.05 + 0.5 * i / 40, y = -0.05 + 0.4 * j / 30;
                differ += sdf_at(m, x, y, 0) != sdf_at(ref, x, y, 0);
            }
        if (differ) fprintf(stderr, "%s: %d samples differ from 8-bit grey\n", f->name, differ);
        CHECK(differ == 0);
        hearth_shape_free(m);
        unlink(path);
    }
    printf("mask_png_flavours: %d flavours match 8-bit grey\n", tried);
    CHECK(tried >= 12);
    hearth_shape_free(ref);
    unlink(ref_path);
    CHECK(hearth_bytes_allocated() == base);
}

/* A mask file cut short or with a byte changed: refused naming the file, or
 * (a change the format cannot see) read; never a crash, never a leak. */
TEST(mask_damaged_files) {
    char path[128];
    tmp_path(path, sizeof path, "damaged.png");
    write_mask(path, 40, 30, disc_xy, NULL);
    FILE *f = fopen(path, "rb");
    CHECK(f != NULL);
    if (!f) return;
    unsigned char good[4096];
    size_t n = fread(good, 1, sizeof good, f);
    fclose(f);
    CHECK(n > 60 && n < sizeof good);
    const double lo[2] = {0, 0}, hi[2] = {1, 1};
    size_t base = hearth_bytes_allocated();
    int refused = 0, loaded = 0;
    for (int pass = 0; pass < 2; pass++)
        for (size_t at = 0; at < n; at += pass ? 1 : 3) {
            unsigned char buf[4096];
            memcpy(buf, good, n);
            size_t len = pass ? n : at;
            if (pass) buf[at] ^= 0xA5;
            f = fopen(path, "wb");
            CHECK(f && fwrite(buf, 1, len, f) == len);
            if (f) fclose(f);
            hearth_error err = {0};
            hearth_shape *m = hearth_shape_mask(path, lo, hi, &err);
            if (m) {
                loaded++;
                hearth_shape_free(m);
            } else {
                refused++;
                CHECK(err.code != HEARTH_OK);
                CHECK_STR_CONTAINS(err.msg, path);
            }
        }
    printf("mask_damaged_files: %d refused, %d loaded\n", refused, loaded);
    CHECK(refused > (int)n / 3);
    CHECK(hearth_bytes_allocated() == base);
    unlink(path);
}

static int one_px(int i, int r, void *ud) {
    (void)ud;
    return i == 0 && r == 0;
}

static int middle_of_line(int i, int r, void *ud) {
    (void)ud;
    return i + r >= 10 && i + r < 30; /* one of i, r is always 0 */
}

/* The smallest masks: one pixel, one row, one column. Inside is negative,
 * the image's outside positive, all finite. */
TEST(mask_tiny_images) {
    size_t base = hearth_bytes_allocated();
    static const struct {
        int w, h;
        int (*inside)(int, int, void *);
        double in[2]; /* a point inside, in the unit square */
    } cases[] = {{1, 1, one_px, {0.5, 0.5}}, {40, 1, middle_of_line, {0.5, 0.5}}, {1, 40, middle_of_line, {0.5, 0.5}}};
    char path[128];
    tmp_path(path, sizeof path, "tiny.png");
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        write_mask(path, cases[k].w, cases[k].h, cases[k].inside, NULL);
        hearth_error err = {0};
        hearth_shape *m = hearth_shape_mask(path, (const double[]){0, 0}, (const double[]){1, 1}, &err);
        CHECK(m != NULL);
        if (!m) continue;
        double in = sdf_at(m, cases[k].in[0], cases[k].in[1], 0);
        CHECK(isfinite(in) && in < 0);
        CHECK(sdf_at(m, -0.5, 0.5, 0) > 0 && sdf_at(m, 0.5, 1.5, 0) > 0);
        for (int j = 0; j <= 10; j++)
            for (int i = 0; i <= 10; i++) CHECK(isfinite(sdf_at(m, i / 10.0, j / 10.0, 0)));
        hearth_shape_free(m);
    }
    unlink(path);
    CHECK(hearth_bytes_allocated() == base);
}

/* Sizes refused from the header, before any pixel is decoded: zero (libpng's
 * words, with the file) and past 4096 a side (the mask limit, named). */
TEST(mask_header_sizes) {
    size_t base = hearth_bytes_allocated();
    static const struct {
        uint32_t w, h;
        hearth_status want;
        const char *says;
    } cases[] = {
        {0, 5, HEARTH_ERR_FORMAT, "width is zero"},
        {5, 0, HEARTH_ERR_FORMAT, "height is zero"},
        {4097, 1, HEARTH_ERR_PARAM, "is 4097x1 pixels; the largest mask is 4096x4096"},
        {1, 5000, HEARTH_ERR_PARAM, "the largest mask is 4096x4096"},
        {0x7FFFFFFFu, 0x7FFFFFFFu, HEARTH_ERR_PARAM, "the largest mask is 4096x4096"},
    };
    char path[128];
    tmp_path(path, sizeof path, "header.png");
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        CHECK(write_png_header_only(path, cases[k].w, cases[k].h) == 0);
        hearth_error err = {0};
        CHECK(!hearth_shape_mask(path, (const double[]){0, 0}, (const double[]){1, 1}, &err));
        CHECK(err.code == cases[k].want);
        CHECK_STR_CONTAINS(err.msg, path);
        CHECK_STR_CONTAINS(err.msg, cases[k].says);
        printf("%s\n", err.msg);
    }
    unlink(path);
    CHECK(hearth_bytes_allocated() == base);
}

/* Non-square pixels: the solid stays inside the image rectangle. A 16 x 1
 * mask over 2 x 1 m (pixels 0.125 x 1 m), all dark but the first pixel, was
 * 0.44 m deep at its top edge before depths were bounded by the distance to
 * the edge (found by fuzz_png_mask). */
static int all_but_first(int i, int r, void *ud) {
    (void)r, (void)ud;
    return i > 0;
}

TEST(mask_anisotropic_inside_rect) {
    char path[128];
    tmp_path(path, sizeof path, "aniso.png");
    const double lo[2] = {-0.5, 0}, hi[2] = {1.5, 1};
    int bad = 0, n = 0;
    for (int shape = 0; shape < 2; shape++) {
        int w = shape ? 1 : 16, h = shape ? 16 : 1; /* wide pixels, then tall ones */
        write_mask(path, w, h, shape ? all_black : all_but_first, NULL);
        hearth_error err = {0};
        hearth_shape *m = hearth_shape_mask(path, lo, hi, &err);
        CHECK(m != NULL);
        if (!m) continue;
        for (int k = 0; k <= 64; k++) {
            double t = k / 64.0, x = lo[0] + (hi[0] - lo[0]) * t, y = lo[1] + (hi[1] - lo[1]) * t;
            const double out[4][2] = {{x, hi[1] + 0.01}, {x, lo[1] - 0.01}, {lo[0] - 0.01, y}, {hi[0] + 0.01, y}};
            for (int q = 0; q < 4; q++, n++) bad += !(sdf_at(m, out[q][0], out[q][1], 0) > 0);
            double edge = sdf_at(m, x, hi[1], 0); /* on the rectangle: never inside */
            bad += !(edge >= -1e-12);
        }
        hearth_shape_free(m);
    }
    unlink(path);
    printf("mask_anisotropic_inside_rect: %d of %d points outside the rectangle read as inside\n", bad, n);
    CHECK(bad == 0);
}

TEST_MAIN(T(mask_sdf_disc), T(mask_assets_load), T(mask_extrude), T(mask_errors), T(mask_serialise),
          T(mask_png_flavours), T(mask_damaged_files), T(mask_tiny_images), T(mask_header_sizes),
          T(mask_anisotropic_inside_rect))
