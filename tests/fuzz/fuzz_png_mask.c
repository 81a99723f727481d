/* fuzz_png_mask.c: the PNG mask reader and its signed distance field.
 *
 * Bytes -> file -> mask_load (IHDR peek, libpng decode to grey, the distance
 * transform) -> a few queries. A refusal must carry a message; a field that
 * loads must be finite everywhere inside its rectangle and positive outside
 * it (shape_mask.c promises the solid never leaves lo..hi). */
#include <math.h>
#include <string.h>

#include "fuzz_util.h"
#include "shapes.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    const char *path = fuzz_temp_file(data, size, ".png");
    if (!path) return 0;
    /* A non-square rectangle so the anisotropic path of the transform runs too. */
    const double lo[2] = {-0.5, 0.0}, hi[2] = {1.5, 1.0};
    hearth_error err;
    memset(&err, 0, sizeof err);
    shape_mask *m = mask_load(path, lo, hi, &err);
    if (!m) {
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
