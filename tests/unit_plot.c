/* unit_plot.c: <hearth/plot.h>, the plots of trade, rheometer and fit, and
 * the public atomic file of <hearth/hearth.h>.
 *
 * Pictures are decoded with libpng's own simplified API and checked at pixels
 * whose place follows from the frame's geometry: a default plot is 760 x 520
 * with the frame from x = 78 (658 px wide) and y = 52 (406 px high). */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "fs_fixture.h"
#include "hearth/hearth.h"
#include "hearth/plot.h"
#include "png_fixture.h"
#include "test.h"

enum { W = 760, H = 520, LEFT = 78, TOP = 52, PW = 658, PH = 406 };

static const unsigned char GREEN[3] = {44, 160, 44}, PURPLE[3] = {148, 103, 189};


static int is_rgb(const unsigned char *px, int w, int x, int y, const unsigned char c[3]) {
    return !memcmp(px + 3 * ((size_t)y * w + x), c, 3);
}

/* Write the plot into dir/name and decode it (W x H checked). */
static unsigned char *render(hearth_plot *p, const char *dir, const char *name) {
    char path[512];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    hearth_error err = {0};
    CHECK(hearth_plot_write_png(p, path, &err) == HEARTH_OK);
    int w = 0, h = 0;
    unsigned char *px = decode_rgb(path, &w, &h);
    CHECK(px != NULL);
    CHECK(w == W && h == H);
    return px;
}

static hearth_plot *new_plot(hearth_plot_scale xs, hearth_plot_scale ys, hearth_plot_legend_pos legend) {
    hearth_plot_def d = hearth_default_plot_def();
    d.x_scale = xs, d.y_scale = ys, d.legend = legend;
    d.title = "test plot", d.x_label = "x [1]", d.y_label = "y [1]";
    hearth_error err = {0};
    hearth_plot *p = hearth_plot_create(&d, &err);
    CHECK(p != NULL);
    return p;
}

static void add_dots(hearth_plot *p, int n, const double *x, const double *y, const unsigned char c[3], const char *label) {
    hearth_plot_series_def s = hearth_default_plot_series_def();
    s.n = n, s.x = x, s.y = y, s.label = label;
    memcpy(s.color, c, 3);
    hearth_error err = {0};
    CHECK(hearth_plot_add_series(p, &s, &err) >= 0);
}

/* Log axes span whole decades around the data, so (100, 1000) between
 * (10, 100) and (1000, 1e4) is the frame's centre; a decade is a major line. */
TEST(plot_log_axes_place_points) {
    char dir[64];
    make_dir(dir, sizeof dir);
    hearth_plot *p = new_plot(HEARTH_PLOT_LOG, HEARTH_PLOT_LOG, HEARTH_LEGEND_NONE);
    const double x[] = {10, 1000, 100}, y[] = {100, 1e4, 1000};
    add_dots(p, 3, x, y, GREEN, NULL);
    unsigned char *px = render(p, dir, "log.png");
    if (px) {
        CHECK(is_rgb(px, W, LEFT + PW / 2, TOP + PH / 2, GREEN));     /* (100, 1000): the centre */
        CHECK(is_rgb(px, W, LEFT, TOP + PH, GREEN));                  /* (10, 100): bottom left */
        CHECK(is_rgb(px, W, LEFT + PW, TOP, GREEN));                  /* (1000, 1e4): top right */
        CHECK(is_rgb(px, W, 255, 145, (const unsigned char[3]){255, 255, 255})); /* between grid lines */
        CHECK(is_rgb(px, W, LEFT + PW / 2, 145, (const unsigned char[3]){228, 228, 228})); /* x = 100's line */
        CHECK(is_rgb(px, W, LEFT - 3, TOP + PH / 2, (const unsigned char[3]){0, 0, 0})); /* y = 1000's tick */
        CHECK(!is_rgb(px, W, 94, 65, GREEN)); /* no legend asked for */
    }
    free(px);
    hearth_plot_free(p);
    rm_dir(dir);
}

/* Linear axes: ends on whole steps of 1, 2 or 5 x 10^k, negative values
 * allowed; a single value gets a window around it. */
TEST(plot_linear_axes_place_points) {
    char dir[64];
    make_dir(dir, sizeof dir);
    hearth_plot *p = new_plot(HEARTH_PLOT_LINEAR, HEARTH_PLOT_LINEAR, HEARTH_LEGEND_NONE);
    const double x[] = {0, 10, 5}, y[] = {0, 5, 2.5}; /* x: 0..10 by 2, y: 0..5 by 1 */
    add_dots(p, 3, x, y, GREEN, NULL);
    unsigned char *px = render(p, dir, "lin.png");
    if (px) {
        CHECK(is_rgb(px, W, LEFT + PW / 2, TOP + PH / 2, GREEN));
        CHECK(is_rgb(px, W, LEFT + PW, TOP, GREEN));
        CHECK(is_rgb(px, W, LEFT, TOP + PH, GREEN));
    }
    free(px);
    hearth_plot_free(p);
    p = new_plot(HEARTH_PLOT_LINEAR, HEARTH_PLOT_LINEAR, HEARTH_LEGEND_NONE);
    const double x2[] = {3, 3, 3}, y2[] = {-2, 2, 0}; /* x: one value, 1..5; y: -2..2 by 1 */
    add_dots(p, 3, x2, y2, PURPLE, NULL);
    px = render(p, dir, "lin2.png");
    if (px) {
        CHECK(is_rgb(px, W, LEFT + PW / 2, TOP + PH / 2, PURPLE)); /* (3, 0) */
        CHECK(is_rgb(px, W, LEFT + PW / 2, TOP, PURPLE));          /* (3, 2) */
        CHECK(!is_rgb(px, W, LEFT + PW / 4, TOP + PH / 2, PURPLE));
    }
    free(px);
    hearth_plot_free(p);
    rm_dir(dir);
}

/* Points a log axis cannot show (<= 0, NaN, inf) are skipped and do not
 * stretch the axes: the picture is the one without them. */
TEST(plot_skips_undrawable_points) {
    char dir[64];
    make_dir(dir, sizeof dir);
    const double x[] = {10, 1000, 0, -1, NAN, 100}, y[] = {100, 1e4, 5, -1, 3, INFINITY};
    hearth_plot *a = new_plot(HEARTH_PLOT_LOG, HEARTH_PLOT_LOG, HEARTH_LEGEND_TOP_LEFT);
    hearth_plot *b = new_plot(HEARTH_PLOT_LOG, HEARTH_PLOT_LOG, HEARTH_LEGEND_TOP_LEFT);
    add_dots(a, 6, x, y, GREEN, "data");
    add_dots(b, 2, x, y, GREEN, "data");
    unsigned char *pa = render(a, dir, "a.png"), *pb = render(b, dir, "b.png");
    CHECK(pa && pb && !memcmp(pa, pb, (size_t)W * H * 3));
    free(pa);
    free(pb);
    hearth_plot_free(a);
    hearth_plot_free(b);
    rm_dir(dir);
}

/* A series marked `behind` is drawn under the others whatever the order they
 * were added in; the legend keeps add order, top left or bottom left. */
TEST(plot_layers_and_legend) {
    char dir[64];
    make_dir(dir, sizeof dir);
    const double x[] = {10, 100, 1000}, y[] = {100, 1000, 1e4};
    for (int behind = 0; behind <= 1; behind++) {
        hearth_plot *p = new_plot(HEARTH_PLOT_LOG, HEARTH_PLOT_LOG, behind ? HEARTH_LEGEND_BOTTOM_LEFT : HEARTH_LEGEND_TOP_LEFT);
        add_dots(p, 3, x, y, GREEN, "points");
        hearth_plot_series_def s = hearth_default_plot_series_def();
        s.n = 2, s.x = (const double[]){10, 1000}, s.y = (const double[]){100, 1e4}; /* through the middle point */
        s.marker = HEARTH_MARKER_NONE, s.line_width = 2, s.behind = behind, s.label = "line";
        memcpy(s.color, PURPLE, 3);
        hearth_error err = {0};
        CHECK(hearth_plot_add_series(p, &s, &err) == 1);
        unsigned char *px = render(p, dir, behind ? "behind.png" : "front.png");
        if (px) {
            int line_on_dot = 0;
            for (int dy = -1; dy <= 1; dy++)
                for (int dx = -1; dx <= 1; dx++) line_on_dot |= is_rgb(px, W, LEFT + PW / 2 + dx, TOP + PH / 2 + dy, PURPLE);
            CHECK(line_on_dot == !behind);
            int line_seen = 0; /* the line between the dots, a quarter of the way along */
            for (int dy = -2; dy <= 2; dy++) line_seen |= is_rgb(px, W, LEFT + PW / 4, TOP + PH - PH / 4 + dy, PURPLE);
            CHECK(line_seen);
            /* legend rows 17 px apart (room for a 12 px font): a dot for "points", then the line's sample for "line" */
            int y0 = behind ? TOP + PH - 6 - 2 * 17 : TOP + 10;
            CHECK(is_rgb(px, W, LEFT + 16, y0 + 3, GREEN));
            CHECK(is_rgb(px, W, LEFT + 16, y0 + 17 + 3, PURPLE));
            CHECK(!is_rgb(px, W, LEFT + 16, y0 + 17 + 6, PURPLE)); /* a line, not a block */
        }
        free(px);
        hearth_plot_free(p);
    }
    rm_dir(dir);
}

/* Every bad argument is refused with a message naming it and the valid range. */
TEST(plot_bad_input) {
    hearth_error err = {0};
    hearth_plot_def d = hearth_default_plot_def();
    d.width = 100;
    CHECK(hearth_plot_create(&d, &err) == NULL);
    CHECK(err.code == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "valid range [200, 8192]");
    d = hearth_default_plot_def();
    d.y_scale = (hearth_plot_scale)7;
    CHECK(hearth_plot_create(&d, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "HEARTH_PLOT_LINEAR");
    d = hearth_default_plot_def();
    d.legend = (hearth_plot_legend_pos)9;
    CHECK(hearth_plot_create(&d, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "legend position 9");
    d = hearth_default_plot_def();
    hearth_plot *p = hearth_plot_create(&d, &err);
    CHECK(p != NULL);
    hearth_plot_series_def s = hearth_default_plot_series_def();
    s.n = -1;
    CHECK(hearth_plot_add_series(p, &s, &err) == -1 && err.code == HEARTH_ERR_PARAM);
    s.n = 2;
    CHECK(hearth_plot_add_series(p, &s, &err) == -1);
    CHECK_STR_CONTAINS(err.msg, "no x or y array");
    const double v[2] = {1, 2};
    s.x = s.y = v;
    s.marker = (hearth_plot_marker)5;
    CHECK(hearth_plot_add_series(p, &s, &err) == -1);
    CHECK_STR_CONTAINS(err.msg, "marker 5");
    s.marker = HEARTH_MARKER_DOT, s.line_width = 3;
    CHECK(hearth_plot_add_series(p, &s, &err) == -1);
    CHECK_STR_CONTAINS(err.msg, "valid range [0, 2]");
    s.line_width = 1;
    CHECK(hearth_plot_add_series(p, &s, &err) == 0); /* the refusals left the plot as it was */
    CHECK(hearth_plot_write_png(p, "/nonexistent-hearth-dir/p.png", &err) == HEARTH_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "/nonexistent-hearth-dir/p.png");
    hearth_plot_free(p);
    hearth_plot_free(NULL);
}

/* Every allocation the plot makes can fail: each failure is HEARTH_ERR_NOMEM
 * and leaks nothing, and with enough memory the same calls succeed. */
TEST(plot_alloc_failures) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/p.png", dir);
    const double x[] = {1, 10, 100}, y[] = {2, 20, 200};
    const char *labels[] = {"a", NULL, "c"};
    size_t base = hearth_bytes_allocated();
    int failed = 0, done = 0;
    for (long k = 0; k < 64 && !done; k++) {
        hearth_error err = {0};
        mem_fail_after(k);
        hearth_plot_def d = hearth_default_plot_def();
        d.title = "t", d.x_label = "x", d.y_label = "y";
        hearth_plot *p = hearth_plot_create(&d, &err);
        int ok = p != NULL;
        for (int i = 0; ok && i < 5; i++) { /* five series: the series table grows once */
            hearth_plot_series_def s = hearth_default_plot_series_def();
            s.n = 3, s.x = x, s.y = y, s.label = "s", s.point_labels = labels;
            ok = hearth_plot_add_series(p, &s, &err) == i;
        }
        if (ok) ok = hearth_plot_write_png(p, path, &err) == HEARTH_OK;
        mem_fail_after(-1);
        if (!ok) {
            failed++;
            CHECK(err.code == HEARTH_ERR_NOMEM);
        } else done = 1;
        hearth_plot_free(p);
        CHECK(hearth_bytes_allocated() == base);
    }
    CHECK(failed > 10 && done);
    rm_dir(dir);
}

/* The public atomic file: a commit replaces the file whole, an abort or a
 * failure leaves it as it was, and no temp file stays behind. */
TEST(atomic_file_public_api) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/out.csv", dir);
    size_t base = hearth_bytes_allocated(), n = 0;
    hearth_error err = {0};
    hearth_atomic_file *af = hearth_atomic_file_open(path, &err);
    CHECK(af != NULL);
    if (af) {
        hearth_atomic_file_printf(af, "rate,%s\n%d,%.3g\n", "stress", 3, 0.25);
        hearth_atomic_file_write(af, "abc", 3);
        CHECK(count_tmp(dir) == 1); /* written beside the file, not over it */
        CHECK(hearth_atomic_file_commit(af, &err) == HEARTH_OK);
    }
    unsigned char *text = slurp(path, &n);
    CHECK(text && !strcmp((const char *)text, "rate,stress\n3,0.25\nabc"));
    free(text);
    af = hearth_atomic_file_open(path, &err);
    CHECK(af != NULL);
    if (af) {
        hearth_atomic_file_printf(af, "half a file");
        hearth_atomic_file_abort(af);
    }
    text = slurp(path, &n);
    CHECK(text && !strcmp((const char *)text, "rate,stress\n3,0.25\nabc"));
    free(text);
    hearth_atomic_file_abort(NULL);
    CHECK(count_tmp(dir) == 0);
    CHECK(hearth_atomic_file_open("/nonexistent-hearth-dir/x.csv", &err) == NULL);
    CHECK(err.code == HEARTH_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "/nonexistent-hearth-dir/x.csv");
    mem_fail_after(0);
    CHECK(hearth_atomic_file_open(path, &err) == NULL);
    mem_fail_after(-1);
    CHECK(err.code == HEARTH_ERR_NOMEM);
    CHECK(hearth_bytes_allocated() == base);
    CHECK(count_tmp(dir) == 0);
    rm_dir(dir);
}

TEST_MAIN(T(plot_log_axes_place_points), T(plot_linear_axes_place_points), T(plot_skips_undrawable_points),
          T(plot_layers_and_legend), T(plot_bad_input), T(plot_alloc_failures), T(atomic_file_public_api))
