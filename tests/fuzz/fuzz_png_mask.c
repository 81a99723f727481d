/* fuzz_png_mask.c: the PNG mask reader and its signed distance field.
 *
 * Bytes -> file -> mask_load (IHDR peek, libpng decode to grey, the distance
 * transform) -> a few queries. A refusal must carry a message; a field that
 * loads must be finite everywhere inside its rectangle and positive outside
 * it (shape_mask.c promises the solid never leaves lo..hi).
 *
 * Chunk CRCs. Almost any mutation inside a chunk breaks its CRC, and libpng
 * then stops at once, so a fuzzer that cannot see into libpng (Debian's is
 * not instrumented) would test little but the CRC check. Inputs of even
 * length therefore get every chunk's CRC recomputed before they are read;
 * odd lengths are read as they are, which keeps the CRC error path in play
 * (the committed bad_ihdr_crc.png has odd length). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_util.h"
#include "shapes.h"

static uint32_t crc32_png(const uint8_t *p, size_t n) {
    static uint32_t table[256];
    if (!table[1])
        for (uint32_t i = 0; i < 256; i++) {
            uint32_t c = i;
            for (int k = 0; k < 8; k++) c = c & 1 ? 0xEDB88320u ^ (c >> 1) : c >> 1;
            table[i] = c;
        }
    uint32_t c = 0xFFFFFFFFu;
    for (size_t i = 0; i < n; i++) c = table[(c ^ p[i]) & 0xFF] ^ (c >> 8);
    return c ^ 0xFFFFFFFFu;
}

/* Recompute the CRC of every whole chunk after the 8-byte signature; stop at
 * the first chunk whose length runs past the end. */
static void fix_crcs(uint8_t *b, size_t n) {
    size_t at = 8;
    while (at + 12 <= n) {
        uint32_t len = (uint32_t)b[at] << 24 | (uint32_t)b[at + 1] << 16 | (uint32_t)b[at + 2] << 8 | b[at + 3];
        if (len > n - at - 12) break;
        uint32_t c = crc32_png(b + at + 4, (size_t)len + 4);
        uint8_t *q = b + at + 8 + len;
        q[0] = (uint8_t)(c >> 24), q[1] = (uint8_t)(c >> 16), q[2] = (uint8_t)(c >> 8), q[3] = (uint8_t)c;
        at += (size_t)len + 12;
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const char *path;
    if (size % 2 == 0) {
        uint8_t *copy = malloc(size ? size : 1);
        if (!copy) return 0;
        memcpy(copy, data, size);
        fix_crcs(copy, size);
        path = fuzz_temp_file(copy, size, ".png");
        free(copy);
    } else {
        path = fuzz_temp_file(data, size, ".png");
    }
    if (!path) return 0;
    /* A non-square rectangle so the anisotropic path of the transform runs too. */
    const double lo[2] = {-0.5, 0.0}, hi[2] = {1.5, 1.0};
    hearth_error err;
    memset(&err, 0, sizeof err);
    shape_mask *m = mask_load(path, lo, hi, &err);
    if (!m) {
        if (fuzz_verbose()) fprintf(stderr, "fuzz_png_mask: %s\n", err.msg);
        FUZZ_CHECK(err.code != HEARTH_OK);
        FUZZ_CHECK(err.msg[0] != '\0');
        FUZZ_CHECK(memchr(err.msg, '\0', sizeof err.msg) != NULL);
        return 0;
    }
    for (int j = 0; j <= 8; j++)
        for (int i = 0; i <= 8; i++) {
            double x = lo[0] + (hi[0] - lo[0]) * i / 8.0, y = lo[1] + (hi[1] - lo[1]) * j / 8.0, g[2];
            double d = mask_sdf(m, x, y, g);
            FUZZ_CHECK(isfinite(d) && isfinite(g[0]) && isfinite(g[1]));
        }
    double g[2];
    FUZZ_CHECK(mask_sdf(m, lo[0] - 0.25, 0.5, g) > 0);
    FUZZ_CHECK(mask_sdf(m, 0.5, hi[1] + 0.25, g) > 0);
    shape_mask *c = mask_copy(m);
    FUZZ_CHECK(c != NULL);
    FUZZ_CHECK(mask_sdf(c, 0.3, 0.7, NULL) == mask_sdf(m, 0.3, 0.7, NULL));
    mask_free(c);
    mask_free(m);
    return 0;
}
