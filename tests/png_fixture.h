/* png_fixture.h: PNG files of every flavour, written with libpng directly,
 * for the reader's tests (unit_image.c, unit_mask.c), and decode_rgb for the
 * tests that read pictures back (unit_plot.c, unit_render.c).
 *
 * A picture is given as "dark" and "light" pixels (a predicate); each flavour
 * says what samples those get in its own colour type and bit depth, and what
 * grey png_read_gray must return for them (Rec. 601 luminance over white). */
#ifndef HEARTH_PNG_FIXTURE_H
#define HEARTH_PNG_FIXTURE_H
#include <png.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct png_flavour {
    const char *name;
    int depth, ctype, interlace;
    unsigned dark[4], light[4]; /* samples at full depth, per channel (palette: the index) */
    int trns;                   /* grey/RGB: the light colour is transparent; palette: index 1 is */
    int want_dark, want_light;  /* what png_read_gray gives */
} png_flavour;

/* Palette of every palette flavour: index 0 a green whose luminance is 124. */
static const png_color fixture_palette[2] = {{10, 200, 30}, {255, 255, 255}};

#define PF_G(d, l) {d, 0, 0, 0}, {l, 0, 0, 0}
static const png_flavour png_flavours[] = {
    {"gray1", 1, PNG_COLOR_TYPE_GRAY, 0, PF_G(0, 1), 0, 0, 255},
    {"gray2", 2, PNG_COLOR_TYPE_GRAY, 0, PF_G(1, 3), 0, 85, 255},
    {"gray4", 4, PNG_COLOR_TYPE_GRAY, 0, PF_G(5, 15), 0, 85, 255},
    {"gray8", 8, PNG_COLOR_TYPE_GRAY, 0, PF_G(100, 250), 0, 100, 250},
    {"gray16", 16, PNG_COLOR_TYPE_GRAY, 0, PF_G(100 * 257, 65535), 0, 100, 255},
    {"gray8_trns", 8, PNG_COLOR_TYPE_GRAY, 0, PF_G(100, 200), 1, 100, 255},
    {"gray4_interlaced", 4, PNG_COLOR_TYPE_GRAY, 1, PF_G(5, 15), 0, 85, 255},
    {"palette8", 8, PNG_COLOR_TYPE_PALETTE, 0, PF_G(0, 1), 0, 124, 255},
    {"palette2_trns", 2, PNG_COLOR_TYPE_PALETTE, 0, PF_G(0, 1), 1, 124, 255},
    {"rgb8", 8, PNG_COLOR_TYPE_RGB, 0, {10, 200, 30, 0}, {255, 255, 255, 0}, 0, 124, 255},
    {"rgb16", 16, PNG_COLOR_TYPE_RGB, 0, {10 * 257, 200 * 257, 30 * 257, 0}, {65535, 65535, 65535, 0}, 0, 124, 255},
    {"rgb8_trns", 8, PNG_COLOR_TYPE_RGB, 0, {10, 200, 30, 0}, {0, 0, 0, 0}, 1, 124, 255},
    {"gray_alpha8", 8, PNG_COLOR_TYPE_GRAY_ALPHA, 0, {100, 255, 0, 0}, {0, 0, 0, 0}, 0, 100, 255},
    {"gray_alpha16", 16, PNG_COLOR_TYPE_GRAY_ALPHA, 0, {100 * 257, 65535, 0, 0}, {0, 0, 0, 0}, 0, 100, 255},
    /* light: black at alpha 128 over white, (255 * 127 + 127) / 255 = 127 */
    {"rgba8", 8, PNG_COLOR_TYPE_RGBA, 0, {10, 200, 30, 255}, {0, 0, 0, 128}, 0, 124, 127},
    {"rgba16", 16, PNG_COLOR_TYPE_RGBA, 0, {10 * 257, 200 * 257, 30 * 257, 65535}, {0, 0, 0, 0}, 0, 124, 255},
    {"rgba8_interlaced", 8, PNG_COLOR_TYPE_RGBA, 1, {10, 200, 30, 255}, {0, 0, 0, 128}, 0, 124, 127},
};
#undef PF_G
#define PNG_FLAVOURS ((int)(sizeof png_flavours / sizeof png_flavours[0]))

static inline int pf_channels(int ctype) {
    return ctype == PNG_COLOR_TYPE_RGB ? 3 : ctype == PNG_COLOR_TYPE_GRAY_ALPHA ? 2 : ctype == PNG_COLOR_TYPE_RGBA ? 4 : 1;
}

/* Write a w x h picture in flavour f: dark(x, y) picks dark samples (y = 0 is
 * the top row). Returns 0 on success. */
static inline int write_png_flavour(const char *path, const png_flavour *f, int w, int h,
                                    int (*dark)(int x, int y, void *ud), void *ud) {
    FILE *fp = fopen(path, "wb");
    if (!fp) return -1;
    png_structp p = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = p ? png_create_info_struct(p) : NULL;
    int nc = pf_channels(f->ctype), bpp = nc * f->depth;
    size_t rowbytes = ((size_t)w * (size_t)bpp + 7) / 8;
    unsigned char *pix = calloc((size_t)h, rowbytes);
    png_bytep *rows = calloc((size_t)h, sizeof *rows);
    if (!p || !info || !pix || !rows || setjmp(png_jmpbuf(p))) {
        png_destroy_write_struct(&p, &info);
        free(pix);
        free(rows);
        fclose(fp);
        return -1;
    }
    for (int y = 0; y < h; y++) {
        unsigned char *r = pix + (size_t)y * rowbytes;
        rows[y] = r;
        for (int x = 0; x < w; x++) {
            const unsigned *smp = dark(x, y, ud) ? f->dark : f->light;
            for (int c = 0; c < nc; c++) {
                size_t bit = ((size_t)x * (size_t)nc + (size_t)c) * (size_t)f->depth;
                if (f->depth == 16) {
                    r[bit / 8] = (unsigned char)(smp[c] >> 8);
                    r[bit / 8 + 1] = (unsigned char)smp[c];
                } else if (f->depth == 8) {
                    r[bit / 8] = (unsigned char)smp[c];
                } else { /* packed, leftmost pixel in the high bits */
                    r[bit / 8] |= (unsigned char)(smp[c] << (8 - f->depth - bit % 8));
                }
            }
        }
    }
    png_init_io(p, fp);
    png_set_IHDR(p, info, (png_uint_32)w, (png_uint_32)h, f->depth, f->ctype,
                 f->interlace ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (f->ctype == PNG_COLOR_TYPE_PALETTE) png_set_PLTE(p, info, fixture_palette, 2);
    if (f->trns) {
        if (f->ctype == PNG_COLOR_TYPE_PALETTE) {
            png_byte alpha[2] = {255, 0};
            png_set_tRNS(p, info, alpha, 2, NULL);
        } else {
            png_color_16 key = {0, (png_uint_16)f->light[0], (png_uint_16)f->light[1], (png_uint_16)f->light[2],
                                (png_uint_16)f->light[0]};
            png_set_tRNS(p, info, NULL, 0, &key);
        }
    }
    png_write_info(p, info);
    png_write_image(p, rows);
    png_write_end(p, info);
    png_destroy_write_struct(&p, &info);
    free(pix);
    free(rows);
    return fclose(fp) == 0 ? 0 : -1;
}

/* CRC-32 of PNG chunks (ISO 3309), for files built byte by byte. */
static inline uint32_t pf_crc32(const unsigned char *b, size_t n) {
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) {
        c ^= b[i];
        for (int k = 0; k < 8; k++) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
    }
    return c ^ 0xFFFFFFFFu;
}

static inline void pf_be32(unsigned char *b, uint32_t v) {
    b[0] = (unsigned char)(v >> 24), b[1] = (unsigned char)(v >> 16), b[2] = (unsigned char)(v >> 8), b[3] = (unsigned char)v;
}

/* A PNG that is a signature, an IHDR of w x h (8-bit grey), a 2-byte IDAT
 * (a zlib header, no data) and IEND: a reader sees the size it claims and
 * reaches the image data, which then runs out. Returns 0 on success. */
static inline int write_png_header_only(const char *path, uint32_t w, uint32_t h) {
    unsigned char b[8 + 25 + 14 + 12] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    unsigned char *c = b + 8;
    pf_be32(c, 13);
    memcpy(c + 4, "IHDR", 4);
    pf_be32(c + 8, w);
    pf_be32(c + 12, h);
    c[16] = 8, c[17] = 0, c[18] = 0, c[19] = 0, c[20] = 0;
    pf_be32(c + 21, pf_crc32(c + 4, 17));
    unsigned char *d = c + 25;
    pf_be32(d, 2);
    memcpy(d + 4, "IDAT", 4);
    d[8] = 0x78, d[9] = 0x01;
    pf_be32(d + 10, pf_crc32(d + 4, 6));
    unsigned char *e = d + 14;
    pf_be32(e, 0);
    memcpy(e + 4, "IEND", 4);
    pf_be32(e + 8, pf_crc32(e + 4, 4));
    FILE *fp = fopen(path, "wb");
    if (!fp) return -1;
    size_t ok = fwrite(b, sizeof b, 1, fp);
    return fclose(fp) == 0 && ok == 1 ? 0 : -1;
}
/* Decode path with libpng's simplified API to 8-bit RGB (malloc'd, rows top
 * first); NULL on failure. For the tests that read pictures back. */
static inline unsigned char *decode_rgb(const char *path, int *w, int *h) {
    png_image im;
    memset(&im, 0, sizeof im);
    im.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&im, path)) return NULL;
    im.format = PNG_FORMAT_RGB;
    unsigned char *buf = malloc(PNG_IMAGE_SIZE(im));
    if (!buf || !png_image_finish_read(&im, NULL, buf, 0, NULL)) {
        png_image_free(&im);
        free(buf);
        return NULL;
    }
    *w = (int)im.width;
    *h = (int)im.height;
    return buf;
}
#endif
