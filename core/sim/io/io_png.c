/* io_png.c: atomic PNG writing and grey PNG reading over libpng.
 *
 * libpng reports errors by longjmp out of its calls. Every longjmp lands in
 * one small function per direction (encode, decode) that owns nothing the
 * jump could leave half-updated: what has to survive a jump (png structs,
 * buffers, the error text) lives in a struct reached through a pointer, so it
 * needs no `volatile`. Nothing longjmps across the library's API (style
 * rule 4).
 *
 * libpng's own allocations go through mem_alloc via the *_struct_2 hooks, so
 * they are counted and the allocation-failure tests reach libpng's paths too.
 */
#define _POSIX_C_SOURCE 200809L /* fsync, fileno, getpid, open */

#include "io_png.h"

#include <errno.h>
#include <fcntl.h>
#include <png.h>
#include <setjmp.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "alloc.h"
#include "error.h"

/* State shared with libpng's callbacks. why holds the first reason seen: an
 * I/O callback records strerror before calling png_error, and on_error then
 * keeps that rather than libpng's vaguer "Write Error". */
typedef struct pngio {
    FILE *fp;
    char why[256];
    char warning[112]; /* libpng's last warning */
    int io_failed; /* the OS refused a read or write (errno in why) */
    int oom;       /* an allocation failed */
    int truncated; /* the file ended early */
    int too_large; /* the header asks for more than PNG_DIM_MAX / PNG_PIXELS_MAX */
} pngio;

/* No chunk a mask needs (IHDR, PLTE, tRNS, IDAT pieces) is near this. */
#define PNG_CHUNK_MAX ((png_alloc_size_t)8 << 20)

/* ---- libpng hooks ---------------------------------------------------- */

/* libpng's free hook gets no size, but mem_free needs one: keep it in a header
 * as large as max_align_t so the block handed to libpng stays aligned. */
#define HOOK_HDR _Alignof(max_align_t)
_Static_assert(HOOK_HDR >= sizeof(size_t), "header must hold the block size");

static png_voidp hook_malloc(png_structp p, png_alloc_size_t n) {
    pngio *io = png_get_mem_ptr(p);
    unsigned char *b = n <= SIZE_MAX - HOOK_HDR ? mem_alloc(n + HOOK_HDR) : NULL;
    if (!b) {
        if (io) io->oom = 1;
        return NULL; /* libpng turns this into png_error("Out of memory") */
    }
    size_t sz = n;
    memcpy(b, &sz, sizeof sz);
    return b + HOOK_HDR;
}

static void hook_free(png_structp p, png_voidp ptr) {
    (void)p;
    if (!ptr) return;
    unsigned char *b = (unsigned char *)ptr - HOOK_HDR;
    size_t sz;
    memcpy(&sz, b, sizeof sz);
    mem_free(b, sz + HOOK_HDR);
}

/* libpng often says what was wrong in a warning just before a vaguer error
 * ("Image width is zero in IHDR", then "Invalid IHDR data"), so the last
 * warning goes into the message beside the error. */
static void on_error(png_structp p, png_const_charp msg) {
    pngio *io = png_get_error_ptr(p);
    if (!io->why[0]) {
        if (io->warning[0]) snprintf(io->why, sizeof io->why, "%s (%s)", msg, io->warning);
        else snprintf(io->why, sizeof io->why, "%s", msg);
    }
    png_longjmp(p, 1);
}

/* Warnings (unknown chunks, a bad sRGB profile) never stop a read or write,
 * and the library does not print (hearth.h): kept only for on_error. */
static void on_warning(png_structp p, png_const_charp msg) {
    pngio *io = png_get_error_ptr(p);
    snprintf(io->warning, sizeof io->warning, "%s", msg);
}

static void on_write(png_structp p, png_bytep data, size_t n) {
    pngio *io = png_get_io_ptr(p);
    if (fwrite(data, 1, n, io->fp) != n) {
        io->io_failed = 1;
        snprintf(io->why, sizeof io->why, "%s", strerror(errno));
        png_error(p, "write failed");
    }
}

static void on_flush(png_structp p) {
    (void)p; /* the caller flushes and fsyncs once at the end */
}

static void on_read(png_structp p, png_bytep data, size_t n) {
    pngio *io = png_get_io_ptr(p);
    if (fread(data, 1, n, io->fp) == n) return;
    if (ferror(io->fp)) {
        io->io_failed = 1;
        snprintf(io->why, sizeof io->why, "%s", strerror(errno));
    } else {
        io->truncated = 1;
        snprintf(io->why, sizeof io->why, "the file ends early (truncated)");
    }
    png_error(p, "read failed");
}

/* ---- writing --------------------------------------------------------- */

/* hearth_png_set_source's text: set once by the command line before a scene runs, read by every PNG written. */
static char g_source[1024];

void hearth_png_set_source(const char *text) {
    snprintf(g_source, sizeof g_source, "%s", text ? text : "");
}

/* Encode to io->fp. Returns 0 on success; on failure io says why. */
static int encode(pngio *io, int w, int h, const unsigned char *rgb, const char *title) {
    png_structp p = png_create_write_struct_2(PNG_LIBPNG_VER_STRING, io, on_error, on_warning,
                                              io, hook_malloc, hook_free);
    if (!p) {
        io->oom = 1;
        return -1;
    }
    png_infop info = png_create_info_struct(p);
    if (!info) {
        io->oom = 1;
        png_destroy_write_struct(&p, NULL);
        return -1;
    }
    if (setjmp(png_jmpbuf(p))) {
        png_destroy_write_struct(&p, &info);
        return -1;
    }
    png_set_write_fn(p, io, on_write, on_flush);
    png_set_IHDR(p, info, (png_uint_32)w, (png_uint_32)h, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    /* Say the bytes are sRGB, which is what the colour maps produce, so viewers
     * do not guess a different gamma. */
    png_set_sRGB(p, info, PNG_sRGB_INTENT_PERCEPTUAL);
    /* The title as text: iTXt, since a title holds UTF-8 (degree signs); tEXt is Latin-1. Then the run that
     * drew it (PNG's "Source" keyword: the device or program that made the image), so a frame copied into a
     * paper's folder still names its scene and settings (#18, helper userview5). */
    const char *key[2] = {"Title", "Source"}, *text[2] = {title, g_source};
    for (int k = 0; k < 2; k++) {
        if (!text[k] || !*text[k]) continue;
        png_text t = {0};
        t.compression = PNG_ITXT_COMPRESSION_NONE;
        t.key = (png_charp)key[k];
        t.text = (png_charp)text[k];
        t.itxt_length = strlen(text[k]);
        t.lang = (png_charp) "";
        t.lang_key = (png_charp) "";
        png_set_text(p, info, &t, 1);
    }
    png_write_info(p, info);
    for (int y = 0; y < h; y++) png_write_row(p, rgb + (size_t)y * (size_t)w * 3);
    png_write_end(p, info);
    png_destroy_write_struct(&p, &info);
    return 0;
}

/* The rename is durable only once the folder itself is synced. This is best
 * effort: the file at path is already complete either way, so a failure
 * here is not reported. */
static void sync_parent(const char *path) {
    const char *slash = strrchr(path, '/');
    char dir[4096];
    if (!slash) {
        snprintf(dir, sizeof dir, ".");
    } else if (slash == path) {
        snprintf(dir, sizeof dir, "/");
    } else {
        size_t n = (size_t)(slash - path);
        if (n >= sizeof dir) return;
        memcpy(dir, path, n);
        dir[n] = '\0';
    }
    int fd = open(dir, O_RDONLY);
    if (fd < 0) return;
    (void)fsync(fd);
    close(fd);
}

hearth_status png_write_rgb(const char *path, int w, int h, const unsigned char *rgb,
                            hearth_error *err) {
    return png_write_rgb_titled(path, w, h, rgb, NULL, err);
}

hearth_status png_write_rgb_titled(const char *path, int w, int h, const unsigned char *rgb,
                                   const char *title, hearth_error *err) {
    HEARTH_ASSERT(path);
    if (w < 1 || h < 1 || w > PNG_DIM_MAX || h > PNG_DIM_MAX)
        return err_set(err, HEARTH_ERR_PARAM,
                       "cannot write PNG '%s': image size %dx%d is outside 1..%d", path, w, h,
                       PNG_DIM_MAX);
    HEARTH_ASSERT(rgb);

    /* Same folder as path so rename() stays on one file system and is atomic. */
    size_t tmp_n = strlen(path) + 32;
    char *tmp = mem_alloc(tmp_n);
    if (!tmp) return err_set(err, HEARTH_ERR_NOMEM, "cannot write PNG '%s': out of memory", path);
    snprintf(tmp, tmp_n, "%s.tmp.%ld", path, (long)getpid());

    pngio io = {0};
    hearth_status st = HEARTH_OK;
    io.fp = fopen(tmp, "wb");
    if (!io.fp) {
        st = err_set(err, HEARTH_ERR_IO, "cannot write PNG '%s': %s", path, strerror(errno));
        mem_free(tmp, tmp_n);
        return st;
    }

    if (encode(&io, w, h, rgb, title) != 0) {
        if (io.oom && !io.io_failed)
            st = err_set(err, HEARTH_ERR_NOMEM, "cannot write PNG '%s': out of memory", path);
        else
            st = err_set(err, HEARTH_ERR_IO, "cannot write PNG '%s': %s", path,
                         io.why[0] ? io.why : "libpng failed");
    } else if (fflush(io.fp) != 0 || fsync(fileno(io.fp)) != 0) {
        /* A full disk often shows up only here, not in fwrite. */
        st = err_set(err, HEARTH_ERR_IO, "cannot write PNG '%s': %s", path, strerror(errno));
    }
    if (fclose(io.fp) != 0 && st == HEARTH_OK)
        st = err_set(err, HEARTH_ERR_IO, "cannot write PNG '%s': %s", path, strerror(errno));

    if (st == HEARTH_OK && rename(tmp, path) != 0)
        st = err_set(err, HEARTH_ERR_IO, "cannot write PNG '%s': cannot replace it: %s", path,
                     strerror(errno));
    if (st != HEARTH_OK)
        remove(tmp);
    else
        sync_parent(path);
    mem_free(tmp, tmp_n);
    return st;
}

/* ---- reading --------------------------------------------------------- */

/* What decode builds; the caller releases it whether decode succeeded or not. */
typedef struct decoded {
    png_structp p;
    png_infop info;
    unsigned char *rgba; /* w*h*4 */
    png_bytep *rows;     /* h row pointers into rgba */
    size_t w, h;
} decoded;

/* Decode io->fp (signature already consumed) to 8-bit RGBA in d. 0 on success. */
static int decode(pngio *io, decoded *d) {
    d->p = png_create_read_struct_2(PNG_LIBPNG_VER_STRING, io, on_error, on_warning, io,
                                    hook_malloc, hook_free);
    if (!d->p) {
        io->oom = 1;
        return -1;
    }
    d->info = png_create_info_struct(d->p);
    if (!d->info) {
        io->oom = 1;
        return -1;
    }
    if (setjmp(png_jmpbuf(d->p))) return -1;

    png_set_read_fn(d->p, io, on_read);
    png_set_sig_bytes(d->p, 8);
    /* The size limits are checked below, after IHDR and before any image
     * memory, so the message can give them; libpng's own check ("exceeds
     * user limit") cannot. Its limits stay as a backstop at 2^31 - 1. */
    png_set_user_limits(d->p, PNG_UINT_31_MAX, PNG_UINT_31_MAX);
    /* Ancillary chunks that carry compressed or unbounded data (text, ICC
     * profiles, suggested palettes) mean nothing to a mask: skip them unread
     * rather than inflate them, and cap what any one chunk may allocate. */
    static const png_byte skip[] = {'i', 'C', 'C', 'P', '\0', 'z', 'T', 'X', 't', '\0', 'i', 'T', 'X', 't', '\0',
                                    't', 'E', 'X', 't', '\0', 's', 'P', 'L', 'T', '\0', 'e', 'X', 'I', 'f', '\0'};
    png_set_keep_unknown_chunks(d->p, PNG_HANDLE_CHUNK_NEVER, skip, (int)(sizeof skip / 5));
    png_set_keep_unknown_chunks(d->p, PNG_HANDLE_CHUNK_NEVER, NULL, 0); /* and every unknown chunk */
    png_set_chunk_malloc_max(d->p, PNG_CHUNK_MAX);
    png_read_info(d->p, d->info);
    {
        png_uint_32 iw = png_get_image_width(d->p, d->info), ih = png_get_image_height(d->p, d->info);
        if (iw > PNG_DIM_MAX || ih > PNG_DIM_MAX || (uint64_t)iw * ih > PNG_PIXELS_MAX) {
            io->too_large = 1;
            snprintf(io->why, sizeof io->why,
                     "the image is %lux%lu pixels; the largest PNG read is %dx%d pixels and %d megapixels in all",
                     (unsigned long)iw, (unsigned long)ih, PNG_DIM_MAX, PNG_DIM_MAX, (int)(PNG_PIXELS_MAX >> 20));
            png_error(d->p, "image too large");
        }
    }

    /* Normalise every flavour to 8-bit RGBA, then one loop computes luminance.
     * Rejected: png_set_rgb_to_gray, whose weights and gamma handling differ
     * between libpng versions, and which would still need alpha handled here. */
    int ct = png_get_color_type(d->p, d->info);
    int bits = png_get_bit_depth(d->p, d->info);
    if (bits == 16) png_set_scale_16(d->p); /* rounds; strip_16 would truncate */
    if (ct == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(d->p);
    if (ct == PNG_COLOR_TYPE_GRAY && bits < 8) png_set_expand_gray_1_2_4_to_8(d->p);
    if (png_get_valid(d->p, d->info, PNG_INFO_tRNS)) png_set_tRNS_to_alpha(d->p);
    if (ct == PNG_COLOR_TYPE_GRAY || ct == PNG_COLOR_TYPE_GRAY_ALPHA) png_set_gray_to_rgb(d->p);
    png_set_add_alpha(d->p, 0xff, PNG_FILLER_AFTER); /* no-op when alpha exists */
    png_set_interlace_handling(d->p);
    png_read_update_info(d->p, d->info);

    d->w = png_get_image_width(d->p, d->info);
    d->h = png_get_image_height(d->p, d->info);
    if (png_get_rowbytes(d->p, d->info) != d->w * 4)
        png_error(d->p, "unexpected row layout after conversion to RGBA");

    if (d->w > SIZE_MAX / 4 / d->h) png_error(d->p, "image too large for this machine");
    /* Whole image, not row by row: interlaced files fill rows over seven passes. */
    d->rgba = mem_alloc(d->w * d->h * 4);
    d->rows = mem_alloc(d->h * sizeof *d->rows);
    if (!d->rgba || !d->rows) {
        io->oom = 1;
        png_error(d->p, "out of memory");
    }
    for (size_t y = 0; y < d->h; y++) d->rows[y] = d->rgba + y * d->w * 4;
    png_read_image(d->p, d->rows);
    png_read_end(d->p, NULL);
    return 0;
}

static void decoded_free(decoded *d) {
    if (d->p) png_destroy_read_struct(&d->p, d->info ? &d->info : NULL, NULL);
    mem_free(d->rgba, d->w * d->h * 4);
    mem_free(d->rows, d->h * sizeof *d->rows);
}

hearth_status png_read_gray(const char *path, int *w, int *h, unsigned char **pixels,
                            hearth_error *err) {
    HEARTH_ASSERT(path && w && h && pixels);
    *w = *h = 0;
    *pixels = NULL;

    pngio io = {0};
    io.fp = fopen(path, "rb");
    if (!io.fp)
        return err_set(err, HEARTH_ERR_IO, "cannot open PNG '%s': %s", path, strerror(errno));

    /* Check the signature ourselves so "not a PNG" is told apart from a damaged PNG. */
    unsigned char sig[8];
    size_t got = fread(sig, 1, sizeof sig, io.fp);
    if (got != sizeof sig || png_sig_cmp(sig, 0, sizeof sig) != 0) {
        hearth_status st =
            ferror(io.fp)
                ? err_set(err, HEARTH_ERR_IO, "cannot read PNG '%s': %s", path, strerror(errno))
                : err_set(err, HEARTH_ERR_FORMAT,
                          "'%s' is not a PNG file (it does not start with the PNG signature)",
                          path);
        fclose(io.fp);
        return st;
    }

    decoded d = {0};
    hearth_status st = HEARTH_OK;
    if (decode(&io, &d) != 0) {
        if (io.io_failed)
            st = err_set(err, HEARTH_ERR_IO, "cannot read PNG '%s': %s", path, io.why);
        else if (io.too_large)
            st = err_set(err, HEARTH_ERR_PARAM, "cannot read PNG '%s': %s", path, io.why);
        else if (io.oom)
            st = err_set(err, HEARTH_ERR_NOMEM, "cannot read PNG '%s': out of memory", path);
        else
            st = err_set(err, HEARTH_ERR_FORMAT, "cannot read PNG '%s': %s", path,
                         io.why[0] ? io.why : "libpng failed");
    }
    fclose(io.fp);

    unsigned char *out = NULL;
    if (st == HEARTH_OK) {
        out = mem_alloc(d.w * d.h);
        if (!out) st = err_set(err, HEARTH_ERR_NOMEM, "cannot read PNG '%s': out of memory", path);
    }
    if (out) {
        const unsigned char *q = d.rgba;
        for (size_t i = 0; i < d.w * d.h; i++, q += 4) {
            /* Rec. 601 weights in integers (x1000) so results are exact and
             * identical everywhere; then "over white" with rounding. */
            unsigned lum = (299u * q[0] + 587u * q[1] + 114u * q[2] + 500u) / 1000u;
            unsigned a = q[3];
            out[i] = (unsigned char)((lum * a + 255u * (255u - a) + 127u) / 255u);
        }
        *w = (int)d.w;
        *h = (int)d.h;
        *pixels = out;
    }
    decoded_free(&d);
    return st;
}
