/* fuzz_csv.c: the flow-curve CSV reader and what `hearth fit` does with it.
 *
 * Bytes -> file -> hearth_flow_curve_read -> hearth_hb_fit, as cmd_fit.c does; and the
 * same bytes as one line through csv_trim / csv_split, and as a sauce
 * library (`hearth rheometer --library FILE`), which shares the line reader. A curve that reads must hold at least 3 finite
 * positive points; a fit that succeeds must give finite, non-negative
 * parameters; every refusal carries a message. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "csv.h"
#include "fuzz_util.h"
#include "hearth/lab.h"

#define FIT_MAX_POINTS 64

static void split_line(const uint8_t *data, size_t size) {
    char *line = malloc(size + 1);
    if (!line) return;
    memcpy(line, data, size);
    line[size] = '\0';
    char *cells[16];
    int n = csv_split(csv_trim(line), cells, 16);
    FUZZ_CHECK(n >= 1 && n <= 16);
    for (int i = 0; i < n; i++) FUZZ_CHECK(cells[i] >= line && cells[i] <= line + size);
    free(line);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    split_line(data, size);
    const char *path = fuzz_temp_file(data, size, ".csv");
    if (!path) return 0;
    hearth_error err;
    memset(&err, 0, sizeof err);
    hearth_sauce_library lib;
    if (hearth_sauce_library_load(path, &lib, &err) == HEARTH_OK) {
        for (int i = 0; i < lib.n; i++)
            FUZZ_CHECK(lib.items[i].h > 0 && lib.items[i].eta > 0 && lib.items[i].sigma_y >= 0);
        hearth_sauce_library_free(&lib);
    } else {
        FUZZ_CHECK(err.msg[0] != '\0');
    }
    memset(&err, 0, sizeof err);
    hearth_flow_curve c;
    if (hearth_flow_curve_read(path, &c, &err) != HEARTH_OK) {
        if (fuzz_verbose()) fprintf(stderr, "fuzz_csv: %s\n", err.msg);
        FUZZ_CHECK(err.code != HEARTH_OK && err.msg[0] != '\0');
        FUZZ_CHECK(c.n == 0 && !c.rate && !c.stress);
        return 0;
    }
    FUZZ_CHECK(c.n >= 3 && c.rate && c.stress);
    for (int i = 0; i < c.n; i++)
        FUZZ_CHECK(isfinite(c.rate[i]) && c.rate[i] > 0 && isfinite(c.stress[i]) && c.stress[i] > 0);
    /* The fit's cost grows with the points and its paths do not: fitting only
     * curves of up to FIT_MAX_POINTS keeps long files (whose parsing matters)
     * from slowing every input tenfold. */
    hearth_hb_fit_result fr;
    if (c.n > FIT_MAX_POINTS) {
        hearth_flow_curve_free(&c);
        return 0;
    }
    if (hearth_hb_fit(c.rate, c.stress, c.n, &fr, &err) == HEARTH_OK) {
        FUZZ_CHECK(isfinite(fr.sigma_y) && fr.sigma_y >= 0);
        FUZZ_CHECK(isfinite(fr.eta) && fr.eta >= 0);
        FUZZ_CHECK(isfinite(fr.h) && fr.h > 0);
        FUZZ_CHECK(!isnan(fr.rel_error) && fr.rel_error >= 0);
    } else {
        FUZZ_CHECK(err.msg[0] != '\0');
    }
    hearth_flow_curve_free(&c);
    return 0;
}
