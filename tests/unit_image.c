/* unit_image.c: PNG files, colour maps and the Cairo canvas (text, ticks, units).
 *
 * PNGs written by hearth are decoded here with libpng's own simplified API,
 * so a bug shared by png_write_rgb and png_read_gray cannot hide itself. */
#define _POSIX_C_SOURCE 200809L /* mkdtemp, opendir */

#include <dirent.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "alloc.h"
#include "colormap.h"
#include "canvas.h"
#include "io_png.h"
#include "fs_fixture.h"
#include "png_fixture.h"
#include "test.h"

/* ---- helpers --------------------------------------------------------- */





static void spit(const char *path, const void *data, size_t n) {
    FILE *f = fopen(path, "wb");
    CHECK(f != NULL);
    if (!f) return;
    CHECK(fwrite(data, 1, n, f) == n);
    fclose(f);
}


static int lum601(int r, int g, int b) { return (int)lround(0.299 * r + 0.587 * g + 0.114 * b); }

/* ---- PNG ------------------------------------------------------------- */

TEST(png_roundtrip) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    size_t bytes0 = hearth_bytes_allocated();

    /* Odd sizes and three independent ramps catch row stride and channel order mistakes. */
    enum { W = 37, H = 23 };
    unsigned char rgb[W * H * 3];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++) {
            unsigned char *q = rgb + (y * W + x) * 3;
            q[0] = (unsigned char)(x * 255 / (W - 1));
            q[1] = (unsigned char)(y * 255 / (H - 1));
            q[2] = (unsigned char)((x * 7 + y * 13) & 255);
        }
    snprintf(path, sizeof path, "%s/grad.png", dir);
    hearth_error err = {0};
    CHECK(png_write_rgb(path, W, H, rgb, &err) == HEARTH_OK);

    int w = 0, h = 0;
    unsigned char *back = decode_rgb(path, &w, &h);
    CHECK(back != NULL);
    CHECK(w == W && h == H);
    if (back && w == W && h == H) CHECK(memcmp(back, rgb, sizeof rgb) == 0);
    free(back);

    unsigned char *g = NULL;
    CHECK(png_read_gray(path, &w, &h, &g, &err) == HEARTH_OK);
    CHECK(w == W && h == H && g != NULL);
    if (g && w == W && h == H) {
        static const int px[][2] = {{0, 0}, {W - 1, 0}, {0, H - 1}, {W - 1, H - 1}, {17, 9}};
        for (size_t k = 0; k < sizeof px / sizeof px[0]; k++) {
            const unsigned char *q = rgb + (px[k][1] * W + px[k][0]) * 3;
            CHECK_NEAR(g[px[k][1] * W + px[k][0]], lum601(q[0], q[1], q[2]), 0.5);
        }
        CHECK(g[0] == 0); /* top left is black: row 0 really is the top */
    }
    mem_free(g, (size_t)w * (size_t)h);

    /* RGBA: alpha composites over white. */
    static const unsigned char rgba[4 * 4] = {255, 0, 0, 255, 0, 0, 0, 0,
                                              0, 0, 0, 128, 100, 100, 100, 128};
    png_image pi;
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    pi.width = 4;
    pi.height = 1;
    pi.format = PNG_FORMAT_RGBA;
    snprintf(path, sizeof path, "%s/rgba.png", dir);
    CHECK(png_image_write_to_file(&pi, path, 0, rgba, 0, NULL));
    CHECK(png_read_gray(path, &w, &h, &g, &err) == HEARTH_OK);
    if (g && w == 4 && h == 1) {
        CHECK(g[0] == 76);  /* red, opaque: 0.299 * 255 */
        CHECK(g[1] == 255); /* fully transparent: white */
        CHECK(g[2] == 127); /* black at 128/255: 255 * 127/255 */
        CHECK(g[3] == 177); /* 100 * 128/255 + 127 = 177.2 */
    }
    mem_free(g, (size_t)w * (size_t)h);

    /* 16-bit grey: scaled to 8 bits with rounding. */
    static const png_uint_16 gray16[3] = {0, 25700, 65535};
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    pi.width = 1;
    pi.height = 3; /* a column, to check the row order too */
    pi.format = PNG_FORMAT_LINEAR_Y;
    snprintf(path, sizeof path, "%s/g16.png", dir);
    CHECK(png_image_write_to_file(&pi, path, 0, gray16, 0, NULL));
    CHECK(png_read_gray(path, &w, &h, &g, &err) == HEARTH_OK);
    if (g && w == 1 && h == 3) CHECK(g[0] == 0 && g[1] == 100 && g[2] == 255);
    mem_free(g, (size_t)w * (size_t)h);

    /* Palette. */
    static const unsigned char pal[3 * 3] = {0, 0, 255, 0, 255, 0, 200, 200, 200};
    static const unsigned char idx[3] = {2, 0, 1};
    memset(&pi, 0, sizeof pi);
    pi.version = PNG_IMAGE_VERSION;
    pi.width = 3;
    pi.height = 1;
    pi.format = PNG_FORMAT_RGB_COLORMAP;
    pi.colormap_entries = 3;
    snprintf(path, sizeof path, "%s/pal.png", dir);
    CHECK(png_image_write_to_file(&pi, path, 0, idx, 0, pal));
    CHECK(png_read_gray(path, &w, &h, &g, &err) == HEARTH_OK);
    if (g && w == 3 && h == 1) CHECK(g[0] == 200 && g[1] == 29 && g[2] == 150);
    mem_free(g, (size_t)w * (size_t)h);

    CHECK(hearth_bytes_allocated() == bytes0);
    rm_dir(dir);
}

TEST(png_atomic_on_failure) {
    char dir[64], path[128], sub[128];
    make_dir(dir, sizeof dir);
    size_t bytes0 = hearth_bytes_allocated();
    hearth_error err = {0};
    unsigned char rgb[4 * 3 * 3];
    for (size_t i = 0; i < sizeof rgb; i++) rgb[i] = (unsigned char)(i * 11);

    /* A folder that does not exist. */
    snprintf(path, sizeof path, "%s/no_such_dir/x.png", dir);
    CHECK(png_write_rgb(path, 4, 3, rgb, &err) == HEARTH_ERR_IO);
    CHECK(err.code == HEARTH_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, "No such file");

    /* A good file, then a failed overwrite must leave it byte for byte. */
    snprintf(path, sizeof path, "%s/good.png", dir);
    CHECK(png_write_rgb(path, 4, 3, rgb, &err) == HEARTH_OK);
    size_t n0 = 0, n1 = 0;
    unsigned char *before = slurp(path, &n0);
    CHECK(before != NULL && n0 > 8);

    CHECK(png_write_rgb(path, 0, 3, rgb, &err) == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, "0x3");

    /* Every allocation the write makes (libpng and zlib included) fails in
     * turn; each failure must report NOMEM and keep the old file. */
    unsigned char other[4 * 3 * 3];
    memset(other, 99, sizeof other);
    int fails = 0;
    for (long k = 0; k < 1000; k++) {
        mem_fail_after(k);
        hearth_status st = png_write_rgb(path, 4, 3, other, &err);
        mem_fail_after(-1);
        if (st == HEARTH_OK) break;
        fails++;
        CHECK(st == HEARTH_ERR_NOMEM);
        unsigned char *now = slurp(path, &n1);
        CHECK(now && n1 == n0 && memcmp(now, before, n0) == 0);
        free(now);
        CHECK(count_tmp(dir) == 0);
    }
    CHECK(fails >= 3); /* the loop did reach past the name buffer into libpng */
    CHECK(hearth_bytes_allocated() == bytes0);

    /* The last round succeeded: the new content is there. Put the old one back. */
    int w = 0, h = 0;
    unsigned char *dec = decode_rgb(path, &w, &h);
    CHECK(dec && w == 4 && h == 3 && memcmp(dec, other, sizeof other) == 0);
    free(dec);
    spit(path, before, n0);

    /* rename() failing (the target is a folder) removes the temporary file. */
    snprintf(sub, sizeof sub, "%s/a_folder.png", dir);
    CHECK(mkdir(sub, 0700) == 0);
    CHECK(png_write_rgb(sub, 4, 3, rgb, &err) == HEARTH_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, sub);

    /* The old file is intact and still decodes to the first image. */
    unsigned char *after = slurp(path, &n1);
    CHECK(after && n1 == n0 && memcmp(after, before, n0) == 0);
    dec = decode_rgb(path, &w, &h);
    CHECK(dec && w == 4 && h == 3 && memcmp(dec, rgb, sizeof rgb) == 0);
    free(dec);
    free(after);
    free(before);

    CHECK(count_tmp(dir) == 0);
    rm_dir(dir);
}

TEST(png_read_errors) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    size_t bytes0 = hearth_bytes_allocated();
    hearth_error err = {0};
    int w = 7, h = 7;
    static unsigned char sentinel[1];
    unsigned char *g = sentinel; /* must come back NULL */

    snprintf(path, sizeof path, "%s/missing.png", dir);
    CHECK(png_read_gray(path, &w, &h, &g, &err) == HEARTH_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, "No such file");
    CHECK(g == NULL && w == 0 && h == 0);

    snprintf(path, sizeof path, "%s/notes.png", dir);
    static const char text[] = "this is a text file, not a picture\n";
    spit(path, text, sizeof text - 1);
    CHECK(png_read_gray(path, &w, &h, &g, &err) == HEARTH_ERR_FORMAT);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, "not a PNG");
    CHECK(g == NULL);

    /* Shorter than the signature. */
    spit(path, "\x89PN", 3);
    CHECK(png_read_gray(path, &w, &h, &g, &err) == HEARTH_ERR_FORMAT);

    /* A real PNG cut in half: the signature passes, libpng fails later. */
    enum { W = 40, H = 30 };
    unsigned char rgb[W * H * 3];
    for (size_t i = 0; i < sizeof rgb; i++) rgb[i] = (unsigned char)(i * 31 % 251);
    snprintf(path, sizeof path, "%s/cut.png", dir);
    CHECK(png_write_rgb(path, W, H, rgb, &err) == HEARTH_OK);
    size_t n = 0;
    unsigned char *full = slurp(path, &n);
    CHECK(full != NULL);
    spit(path, full, n / 2);
    CHECK(png_read_gray(path, &w, &h, &g, &err) == HEARTH_ERR_FORMAT);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, "truncated");
    CHECK(g == NULL && w == 0 && h == 0);

    /* Allocation failures while reading report NOMEM and leak nothing. */
    spit(path, full, n);
    free(full);
    int fails = 0;
    for (long k = 0; k < 1000; k++) {
        mem_fail_after(k);
        hearth_status st = png_read_gray(path, &w, &h, &g, &err);
        mem_fail_after(-1);
        if (st == HEARTH_OK) {
            mem_free(g, (size_t)w * (size_t)h);
            break;
        }
        fails++;
        CHECK(st == HEARTH_ERR_NOMEM);
        CHECK(g == NULL);
    }
    CHECK(fails >= 3);

    CHECK(hearth_bytes_allocated() == bytes0);
    rm_dir(dir);
}

/* ---- reading every flavour, and what must be refused ------------------ */

static int left_half_dark(int x, int y, void *ud) {
    (void)y;
    (void)ud;
    return x < 4;
}

/* Every colour type and bit depth libpng knows, with and without tRNS and
 * interlacing, reads to the exact grey png_fixture.h gives for it. */
TEST(png_read_flavours) {
    char dir[64], path[160];
    make_dir(dir, sizeof dir);
    size_t bytes0 = hearth_bytes_allocated();
    enum { W = 9, H = 7 };
    for (int k = 0; k < PNG_FLAVOURS; k++) {
        const png_flavour *f = &png_flavours[k];
        snprintf(path, sizeof path, "%s/%s.png", dir, f->name);
        CHECK(write_png_flavour(path, f, W, H, left_half_dark, NULL) == 0);
        hearth_error err = {0};
        int w = 0, h = 0;
        unsigned char *g = NULL;
        hearth_status st = png_read_gray(path, &w, &h, &g, &err);
        if (st != HEARTH_OK) fprintf(stderr, "%s: %s\n", f->name, err.msg);
        CHECK(st == HEARTH_OK);
        if (st != HEARTH_OK) continue;
        CHECK(w == W && h == H);
        int bad = 0;
        for (int y = 0; y < H; y++)
            for (int x = 0; x < W; x++) {
                int want = x < 4 ? f->want_dark : f->want_light;
                if (g[y * W + x] != want) {
                    if (!bad) fprintf(stderr, "%s: pixel (%d, %d) is %d, want %d\n", f->name, x, y, g[y * W + x], want);
                    bad++;
                }
            }
        CHECK(bad == 0);
        mem_free(g, (size_t)w * (size_t)h);
    }
    CHECK(hearth_bytes_allocated() == bytes0);
    rm_dir(dir);
}

/* Sizes the reader must refuse from the header, before it allocates the
 * image: the message names the file and the limit. */
TEST(png_read_size_limits) {
    char dir[64], path[160];
    make_dir(dir, sizeof dir);
    size_t bytes0 = hearth_bytes_allocated();
    static const struct {
        uint32_t w, h;
        hearth_status want;
        const char *says;
    } cases[] = {
        {0, 5, HEARTH_ERR_FORMAT, "width is zero"},
        {5, 0, HEARTH_ERR_FORMAT, "height is zero"},
        {40000, 3, HEARTH_ERR_PARAM, "the largest PNG read is 32768x32768"},
        {3, 40000, HEARTH_ERR_PARAM, "3x40000"},
        {8193, 8193, HEARTH_ERR_PARAM, "64 megapixels"},        /* each side fine, the area is not */
        {32768, 32768, HEARTH_ERR_PARAM, "64 megapixels"},      /* would be 5 GB */
        {0x80000000u, 1, HEARTH_ERR_FORMAT, "cannot read PNG"}, /* past PNG's 2^31 - 1 */
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        snprintf(path, sizeof path, "%s/size%zu.png", dir, k);
        CHECK(write_png_header_only(path, cases[k].w, cases[k].h) == 0);
        hearth_error err = {0};
        int w = 7, h = 7;
        unsigned char *g = (unsigned char *)path;
        CHECK(png_read_gray(path, &w, &h, &g, &err) == cases[k].want);
        CHECK_STR_CONTAINS(err.msg, path);
        CHECK_STR_CONTAINS(err.msg, cases[k].says);
        CHECK(g == NULL && w == 0 && h == 0);
        printf("%ux%u: %s\n", cases[k].w, cases[k].h, err.msg);
    }
    CHECK(hearth_bytes_allocated() == bytes0);
    rm_dir(dir);
}

/* A good file damaged every way a download or a disk does it: cut at every
 * length, one byte changed at every offset (CRC left stale, or recomputed so
 * the damage reaches the decoder). Each read either succeeds with the right
 * size or fails with a message naming the file; nothing leaks. */
TEST(png_read_damaged) {
    char dir[64], path[160];
    make_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/good.png", dir);
    CHECK(write_png_flavour(path, &png_flavours[3], 9, 7, left_half_dark, NULL) == 0); /* gray8 */
    size_t n = 0;
    unsigned char *good = slurp(path, &n);
    CHECK(good != NULL && n > 60);
    if (!good) return;
    unsigned char *buf = malloc(n);
    CHECK(buf != NULL);
    if (!buf) return;
    size_t bytes0 = hearth_bytes_allocated();
    int refused = 0, read_ok = 0;
    for (int pass = 0; pass < 3; pass++)
        for (size_t at = 0; at < n; at++) {
            size_t len = n;
            memcpy(buf, good, n);
            if (pass == 0) {
                len = at; /* cut */
            } else {
                buf[at] ^= (unsigned char)(0x5A + at);
                if (pass == 2 && at >= 8) { /* recompute the CRC of the chunk holding at */
                    size_t c = 8;
                    while (c + 12 <= n) {
                        uint32_t cl = (uint32_t)good[c] << 24 | (uint32_t)good[c + 1] << 16 |
                                      (uint32_t)good[c + 2] << 8 | good[c + 3];
                        if (at >= c + 4 && at < c + 8 + cl) {
                            pf_be32(buf + c + 8 + cl, pf_crc32(buf + c + 4, cl + 4));
                            break;
                        }
                        c += 12 + cl;
                    }
                }
            }
            spit(path, buf, len);
            hearth_error err = {0};
            int w = 0, h = 0;
            unsigned char *g = NULL;
            if (png_read_gray(path, &w, &h, &g, &err) == HEARTH_OK) {
                read_ok++;
                CHECK(g != NULL && w >= 1 && h >= 1 && (size_t)w * (size_t)h <= PNG_PIXELS_MAX);
                mem_free(g, (size_t)w * (size_t)h);
            } else {
                refused++;
                CHECK(err.code != HEARTH_OK);
                CHECK_STR_CONTAINS(err.msg, path);
                CHECK(g == NULL);
            }
        }
    printf("png_read_damaged: %zu-byte file, %d damaged copies refused, %d read\n", n, refused, read_ok);
    CHECK(refused >= (int)n); /* every cut is refused, and more */
    CHECK(hearth_bytes_allocated() == bytes0);
    free(buf);
    free(good);
    rm_dir(dir);
}

/* ---- colour maps ----------------------------------------------------- */

static void check_rgb(int map, double t, int r, int g, int b) {
    unsigned char c[3];
    cmap_eval(map, t, c);
    CHECK_NEAR(c[0], r, 2);
    CHECK_NEAR(c[1], g, 2);
    CHECK_NEAR(c[2], b, 2);
}

TEST(colormap_endpoints) {
    check_rgb(CMAP_VIRIDIS, 0.0, 68, 1, 84);
    check_rgb(CMAP_VIRIDIS, 1.0, 253, 231, 37);
    check_rgb(CMAP_INFERNO, 0.0, 0, 0, 4);
    check_rgb(CMAP_INFERNO, 1.0, 252, 255, 164);
    check_rgb(CMAP_VIRIDIS, 0.5, 33, 145, 140); /* matplotlib's viridis(0.5) */
    check_rgb(CMAP_GRAY, 0.0, 0, 0, 0);
    check_rgb(CMAP_GRAY, 1.0, 255, 255, 255);

    /* Clamping, including infinities. */
    check_rgb(CMAP_VIRIDIS, -3.0, 68, 1, 84);
    check_rgb(CMAP_INFERNO, 7.0, 252, 255, 164);
    check_rgb(CMAP_VIRIDIS, INFINITY, 253, 231, 37);
    check_rgb(CMAP_VIRIDIS, -INFINITY, 68, 1, 84);

    /* Viridis was designed so lightness rises steadily. */
    double prev = -1;
    for (int i = 0; i < 64; i++) {
        unsigned char c[3];
        cmap_eval(CMAP_VIRIDIS, i / 63.0, c);
        double l = 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2];
        if (!(l > prev)) fprintf(stderr, "viridis lightness not rising at sample %d\n", i);
        CHECK(l > prev);
        prev = l;
    }

    unsigned char c[3] = {1, 2, 3};
    cmap_eval(CMAP_INFERNO, NAN, c);
    CHECK(c[0] == CMAP_NAN_GREY && c[1] == CMAP_NAN_GREY && c[2] == CMAP_NAN_GREY);
    cmap_eval(CMAP_VIRIDIS, NAN, c);
    CHECK(c[0] == CMAP_NAN_GREY && c[1] == CMAP_NAN_GREY && c[2] == CMAP_NAN_GREY);

    CHECK(cmap_by_name("viridis") == CMAP_VIRIDIS);
    CHECK(cmap_by_name("inferno") == CMAP_INFERNO);
    CHECK(cmap_by_name("gray") == CMAP_GRAY);
    CHECK(cmap_by_name("jet") == -1);
    CHECK(cmap_by_name("cividis") == CMAP_CIVIDIS && cmap_by_name("coolwarm") == CMAP_COOLWARM);
    CHECK(cmap_by_name("diverging") == CMAP_COOLWARM && !strcmp(cmap_name(CMAP_BROWNING), "browning"));
    check_rgb(CMAP_CIVIDIS, 0.0, 0, 34, 78);
    check_rgb(CMAP_CIVIDIS, 1.0, 254, 232, 56);
    check_rgb(CMAP_COOLWARM, 0.0, 59, 76, 192);
    check_rgb(CMAP_COOLWARM, 0.5, 221, 220, 220); /* the light middle of a diverging map */
    check_rgb(CMAP_COOLWARM, 1.0, 180, 4, 38);
    /* cividis and the browning map darken or lighten steadily too (the crust darkens with the index) */
    double pc = -1, pb = 1e9;
    for (int i = 0; i < 64; i++) {
        unsigned char q[3];
        cmap_eval(CMAP_CIVIDIS, i / 63.0, q);
        double l = 0.299 * q[0] + 0.587 * q[1] + 0.114 * q[2];
        CHECK(l > pc);
        pc = l;
        cmap_eval(CMAP_BROWNING, i / 63.0, q);
        l = 0.299 * q[0] + 0.587 * q[1] + 0.114 * q[2];
        CHECK(l < pb);
        pb = l;
    }
    CHECK(cmap_by_name("") == -1);
    CHECK(cmap_by_name(NULL) == -1);
}

/* ---- the canvas ----------------------------------------------------- */

/* Ink of a w x h canvas: pixels that are not the white background. */
static int ink(canvas *c, int x0, int x1) {
    cairo_surface_flush(c->sf);
    const unsigned char *d = cairo_image_surface_get_data(c->sf);
    int stride = cairo_image_surface_get_stride(c->sf), n = 0;
    for (int y = 0; y < c->h; y++)
        for (int x = x0; x < x1 && x < c->w; x++) {
            uint32_t p;
            memcpy(&p, d + (size_t)y * stride + 4 * (size_t)x, 4);
            n += (p & 0xffffff) != 0xffffff;
        }
    return n;
}

/* Text is drawn with a real font: digits leave ink, each digit's ink differs
 * from the others', wider text takes more room, and text hanging off every
 * edge is clipped (ASan checks the writes). */
TEST(canvas_text_draws) {
    static const unsigned char white[3] = {255, 255, 255}, black[3] = {0, 0, 0};
    hearth_error err = {0};
    canvas c;
    CHECK(canvas_init(&c, 200, 40, white, &err) == HEARTH_OK);
    CHECK(ink(&c, 0, 200) == 0);
    double w1 = canvas_text_width(&c, "0", 20), w10 = canvas_text_width(&c, "0123456789", 20);
    printf("width of '0' %.2f px, of ten digits %.2f px at 20 px\n", w1, w10);
    CHECK(w1 > 5 && w1 < 20);
    CHECK(fabs(w10 - 10 * w1) < 1.0); /* the digits of a sans face share one advance */
    canvas_text(&c, 2, 20, "0123456789", 20, CANVAS_LEFT, CANVAS_MIDDLE, 0, black);
    int all = ink(&c, 0, 200);
    CHECK(all > 10 * 20);
    CHECK(ink(&c, (int)ceil(2 + w10 + 2), 200) == 0); /* nothing right of the text's width */
    int cells[10];
    for (int d = 0; d < 10; d++) cells[d] = ink(&c, (int)(2 + d * w1), (int)(2 + (d + 1) * w1));
    int distinct = 0; /* digits are told apart: their ink counts mostly differ (a tie or two is allowed) */
    for (int a = 0; a < 10; a++) {
        int seen = 0;
        for (int b = 0; b < a; b++) seen |= cells[b] == cells[a];
        distinct += !seen;
    }
    printf("%d distinct ink counts among the ten digits\n", distinct);
    CHECK(distinct >= 8);
    canvas_free(&c);
    CHECK(canvas_init(&c, 20, 10, white, &err) == HEARTH_OK);
    canvas_text(&c, -7, -5, "Wg", 30, CANVAS_LEFT, CANVAS_TOP, 0, black);
    canvas_text(&c, 15, 6, "Hy\xe2\x82\xac", 20, CANVAS_CENTER, CANVAS_BASELINE, 1.0, black);
    canvas_text(&c, 1e6, -1e6, "x", 1000, CANVAS_RIGHT, CANVAS_MIDDLE, 0, black);
    CHECK(ink(&c, 0, 20) > 0);
    canvas_free(&c);
    CHECK(canvas_init(&c, 0, 10, white, &err) == HEARTH_ERR_PARAM);
    CHECK(strstr(err.msg, "valid range") != NULL);
    canvas_free(&c); /* a zeroed canvas frees */
}

/* Ticks are 1, 2, 2.5, 4 or 5 x 10^k, inside the range, and as many as asked
 * for: a colour bar from 20 to 180 degC reads 40, 80, 120, 160,
 * never the two end numbers alone. */
TEST(canvas_ticks_nice) {
    static const struct { double lo, hi; } cases[] = {{20, 180}, {0, 1}, {53.8, 63.2}, {-3e-4, 7e-4}, {117, 134},
                                                     {0, 1e5}, {189, 189.0001}, {-1, 1}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        double t[8], step;
        int n = canvas_ticks(cases[k].lo, cases[k].hi, 4, 6, t, &step);
        printf("[%g, %g]: %d ticks, step %g:", cases[k].lo, cases[k].hi, n, step);
        for (int i = 0; i < n; i++) printf(" %g", t[i]);
        printf("\n");
        CHECK(n >= 4 && n <= 6);
        double e = pow(10, floor(log10(step))), m = step / e;
        CHECK(fabs(m - 1) < 1e-9 || fabs(m - 2) < 1e-9 || fabs(m - 2.5) < 1e-9 || fabs(m - 4) < 1e-9 || fabs(m - 5) < 1e-9);
        char prev[32] = "", lab[32];
        for (int i = 0; i < n; i++) {
            CHECK(t[i] >= cases[k].lo - 1e-9 * step && t[i] <= cases[k].hi + 1e-9 * step);
            if (i) CHECK(fabs(t[i] - t[i - 1] - step) < 1e-6 * step);
            canvas_tick_label(t[i], step, lab, sizeof lab); /* never "189 ... 189": each label its own number */
            CHECK(strcmp(lab, prev) != 0);
            memcpy(prev, lab, sizeof prev);
        }
    }
    char buf[32];
    canvas_tick_label(0.25, 0.25, buf, sizeof buf);
    CHECK(!strcmp(buf, "0.25"));
    canvas_tick_label(150, 50, buf, sizeof buf);
    CHECK(!strcmp(buf, "150"));
    canvas_tick_label(-1e-18, 0.5, buf, sizeof buf); /* treated as the value it is, not "-0" */
    CHECK(strcmp(buf, "-0") != 0);
    canvas_unit("1", buf, sizeof buf);
    CHECK(!strcmp(buf, "-")); /* a dimensionless field says so, never a lone "1" */
    canvas_unit("degC", buf, sizeof buf);
    CHECK(!strcmp(buf, "\xc2\xb0" "C"));
    canvas_unit("kg/m^3", buf, sizeof buf);
    CHECK(!strcmp(buf, "kg/m\xc2\xb3"));
}

TEST_MAIN(T(png_roundtrip), T(png_atomic_on_failure), T(png_read_errors), T(png_read_flavours),
          T(png_read_size_limits), T(png_read_damaged), T(colormap_endpoints),
          T(canvas_text_draws), T(canvas_ticks_nice))
