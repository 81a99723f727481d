/* unit_render.c: pictures of a scene (render.c): fixed colour ranges that
 * frames of a run share, colliders drawn, the colour bar's ticks.
 *
 * The scene: a 2D jelly block at 20 degC on a tray heated to 180 degC, in a
 * 180 degC oven. Pictures are decoded with libpng's simplified API and read
 * at places hearth_picture_info gives (plot area, colour bar). */
#define _POSIX_C_SOURCE 200809L /* mkdtemp */

#include <math.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "colormap.h"
#include "fs_fixture.h"
#include "mpm_fixture.h"
#include "png_fixture.h"
#include "test.h"


static const unsigned char *pixel(const unsigned char *px, int w, double x, double y) {
    return px + 3 * ((size_t)floor(y) * (size_t)w + (size_t)floor(x));
}

static int near_rgb(const unsigned char *p, const unsigned char c[3], int tol) {
    return abs(p[0] - c[0]) <= tol && abs(p[1] - c[1]) <= tol && abs(p[2] - c[2]) <= tol;
}

/* The heated scene: jelly block [0.05, 0.15] x [0.02, 0.05] at 20 degC on a
 * tray [0, 0.2] x [0, 0.02] at 180 degC, oven air 180 degC. */
static hearth_scene *heated_scene_on(hearth_solver solver) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 2, d.dx = 0.005, d.solver = solver;
    d.lo[0] = d.lo[1] = d.lo[2] = 0;
    d.hi[0] = 0.2, d.hi[1] = 0.1, d.hi[2] = 0.005;
    d.oven_temperature = 180, d.oven_beta = 30;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NULL;
    /* a conductive jelly (diffusivity 1e-3 m^2/s), so a few hundred steps warm it */
    const char *names[] = {"E", "nu", "density", "conductivity", "specific_heat"};
    const double vals[] = {2e5, 0.3, 1000, 10, 10};
    hearth_error e0;
    int m = hearth_scene_add_material(s, "elastic", names, vals, 5, &e0);
    if (m < 0) fprintf(stderr, "material: %s\n", e0.msg);
    hearth_error err;
    hearth_shape *tray = hearth_shape_box((double[3]){0.1, 0.01, 0}, (double[3]){0.1, 0.01, 1});
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = tray, cd.mode = HEARTH_STICKY, cd.temperature = 180, cd.beta = 200;
    CHECK(hearth_scene_add_collider(s, &cd, &err) >= 0);
    hearth_shape_free(tray);
    hearth_shape *block = hearth_shape_box((double[3]){0.1, 0.035, 0}, (double[3]){0.05, 0.015, 1});
    hearth_body_def bd = hearth_default_body_def();
    bd.shape = block, bd.material = m, bd.temperature = 20, bd.jitter = 0;
    CHECK(hearth_scene_add_body(s, &bd, &err) >= 0);
    hearth_shape_free(block);
    return s;
}
static hearth_scene *heated_scene(void) { return heated_scene_on(HEARTH_SOLVER_MPM); }

/* The pixel at the centre of the last particle drawn (on top of the others in 2D). */
static const unsigned char *last_particle_pixel(const hearth_scene *s, const hearth_picture_info *in,
                                                const unsigned char *px, int w) {
    const int n = hearth_scene_particle_count(s);
    const double *X = hearth_scene_positions(s);
    const double sc = in->area[2] / (in->view_hi[0] - in->view_lo[0]);
    double x = in->area[0] + (X[3 * (n - 1)] - in->view_lo[0]) * sc;
    double y = in->area[1] + in->area[3] - (X[3 * (n - 1) + 1] - in->view_lo[1]) * sc;
    return pixel(px, w, x, y);
}

/* Two frames of a heating scene map a temperature to one colour: both use
 * 20..180 degC (the seeded block to the tray and oven), whatever their data,
 * and each frame's top particle shows inferno at (T - 20) / 160. Per-frame
 * ranges (the old renderer) drew the uniform first frame mid-map and the
 * second frame's coldest particle black. */
TEST(png_fixed_range_across_frames) {
    char dir[64], path[2][128];
    make_dir(dir, sizeof dir);
    hearth_scene *s = heated_scene();
    CHECK(s != NULL);
    hearth_error err;
    hearth_picture_info in[2];
    hearth_picture_def d = hearth_default_picture_def();
    d.field = "temperature", d.kind = HEARTH_PICTURE_PARTICLES, d.width = 640;
    for (int f = 0; f < 2; f++) {
        if (f) CHECK(hearth_scene_step(s, 400, &err) == HEARTH_OK);
        snprintf(path[f], sizeof path[f], "%s/frame%d.png", dir, f);
        CHECK(hearth_render(s, &d, path[f], &in[f], &err) == HEARTH_OK);
        printf("frame %d: t = %.4g s, data %.3f..%.3f degC, range %.3f..%.3f, %d x %d px\n", f, hearth_scene_time(s),
               in[f].data[0], in[f].data[1], in[f].range[0], in[f].range[1], in[f].width, in[f].height);
        CHECK(in[f].range[0] == 20 && in[f].range[1] == 180);
        int w = 0, h = 0;
        unsigned char *px = decode_rgb(path[f], &w, &h);
        CHECK(px != NULL);
        CHECK(w == in[f].width && h == in[f].height);
        const int n = hearth_scene_particle_count(s);
        double T[4096];
        CHECK(n <= 4096);
        CHECK(hearth_scene_particle_field(s, "temperature", T, &err) == HEARTH_OK);
        unsigned char want[3];
        cmap_eval(CMAP_INFERNO, (T[n - 1] - 20) / 160, want);
        const unsigned char *got = last_particle_pixel(s, &in[f], px, w);
        printf("  top particle at %.3f degC: pixel %d %d %d, inferno gives %d %d %d\n", T[n - 1], got[0], got[1], got[2],
               want[0], want[1], want[2]);
        CHECK(near_rgb(got, want, 2));
        free(px);
    }
    CHECK(in[1].data[1] > in[0].data[1] + 1); /* the block did warm: the frames' data differ, their ranges do not */
    CHECK(in[0].width == in[1].width && in[0].height == in[1].height);
    hearth_scene_destroy(s);
    rm_dir(dir);
}

/* The tray is drawn: pixels inside it are the collider grey in both kinds of
 * picture (the dashboard saves slices), and empty space above the block is
 * the white background. */
static void colliders_drawn(hearth_solver solver) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    hearth_scene *s = heated_scene_on(solver);
    CHECK(s != NULL);
    static const unsigned char grey[3] = {150, 152, 160}, white[3] = {255, 255, 255};
    for (int kind = 0; kind < 2; kind++) {
        hearth_picture_def d = hearth_default_picture_def();
        d.field = "temperature", d.kind = kind ? HEARTH_PICTURE_PARTICLES : HEARTH_PICTURE_SLICE, d.width = 500;
        hearth_picture_info in;
        hearth_error err;
        snprintf(path, sizeof path, "%s/k%d.png", dir, kind);
        CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_OK);
        int w = 0, h = 0;
        unsigned char *px = decode_rgb(path, &w, &h);
        CHECK(px != NULL);
        const double sc = in.area[2] / (in.view_hi[0] - in.view_lo[0]);
        const unsigned char *tray = pixel(px, w, in.area[0] + 0.02 * sc, in.area[1] + in.area[3] - 0.01 * sc);
        const unsigned char *air = pixel(px, w, in.area[0] + 0.02 * sc, in.area[1] + in.area[3] - 0.08 * sc);
        printf("%s: tray pixel %d %d %d, air pixel %d %d %d\n", kind ? "particles" : "slice", tray[0], tray[1], tray[2],
               air[0], air[1], air[2]);
        CHECK(near_rgb(tray, grey, 1));
        CHECK(!near_rgb(tray, white, 40));
        CHECK(kind == 0 || near_rgb(air, white, 0)); /* a slice's empty space is its own light grey */
        free(px);
    }
    hearth_scene_destroy(s);
    rm_dir(dir);
}
TEST(png_colliders_drawn) { colliders_drawn(HEARTH_SOLVER_MPM); }
/* The same on SPH (#18, helper userfix11): an SPH scene's colliders are the scene's, drawn by the same path. Its
 * brief read the open list's "SPH colliders do not draw" (a drawing sheet's heat, refused on SPH) as pictures; the
 * SPH scenes' frames drew their trays and moulds on main, and this holds it (it passes on main). */
TEST(png_sph_colliders_drawn) { colliders_drawn(HEARTH_SOLVER_SPH); }

/* The colour bar has 4-6 ticks at nice values inside the range (40, 80, 120,
 * 160 for 20..180 degC), its unit as printed, and a tick mark at each: the
 * pixel just right of the bar at a tick's height is dark, and text (ink) lies
 * right of every tick. */
TEST(png_colorbar_ticks) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    hearth_scene *s = heated_scene();
    CHECK(s != NULL);
    hearth_picture_def d = hearth_default_picture_def();
    d.field = "temperature", d.kind = HEARTH_PICTURE_PARTICLES, d.width = 640;
    hearth_picture_info in;
    hearth_error err;
    snprintf(path, sizeof path, "%s/bar.png", dir);
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_OK);
    printf("%d ticks:", in.nticks);
    for (int k = 0; k < in.nticks; k++) printf(" %g", in.ticks[k]);
    printf(" (%s), unit '%s'\n", in.colormap, in.unit);
    CHECK(in.nticks == 4);
    for (int k = 0; k < 4 && k < in.nticks; k++) CHECK(in.ticks[k] == 40.0 * (k + 1));
    CHECK(!strcmp(in.unit, "\xc2\xb0" "C") && !strcmp(in.colormap, "inferno"));
    int w = 0, h = 0;
    unsigned char *px = decode_rgb(path, &w, &h);
    CHECK(px != NULL);
    for (int k = 0; k < in.nticks; k++) {
        double y = in.bar[1] + in.bar[3] - (in.ticks[k] - in.range[0]) / (in.range[1] - in.range[0]) * in.bar[3];
        const unsigned char *mark = pixel(px, w, in.bar[0] + in.bar[2] + 2, y);
        int ink = 0;
        for (int dy = -4; dy <= 4; dy++)
            for (int x = (int)(in.bar[0] + in.bar[2] + 6); x < (int)(in.bar[0] + in.bar[2] + 40) && x < w; x++)
                ink += pixel(px, w, x, y + dy)[0] < 128;
        printf("tick %g at y %.1f: mark %d, label ink %d px\n", in.ticks[k], y, mark[0], ink);
        CHECK(mark[0] < 140);
        CHECK(ink > 10);
    }
    /* a dimensionless field says so ("-", never a lone "1" that reads as a tick) */
    d.field = "J";
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_OK);
    CHECK(!strcmp(in.unit, "-"));
    /* a speed's bar starts at rest */
    d.field = "speed";
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_OK);
    CHECK(!strcmp(in.unit, "m/s") && in.range[0] == 0);
    free(px);
    hearth_scene_destroy(s);
    rm_dir(dir);
}

/* Options and their errors: a fixed range is used as given, an unknown
 * colour map is refused naming the valid ones, a tensor is refused naming its
 * components, a backwards range is refused. */
TEST(png_options_checked) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    hearth_scene *s = heated_scene();
    CHECK(s != NULL);
    snprintf(path, sizeof path, "%s/o.png", dir);
    hearth_picture_def d = hearth_default_picture_def();
    d.field = "temperature", d.range_mode = HEARTH_RANGE_FIXED, d.range[0] = 0, d.range[1] = 250, d.colormap = "cividis";
    hearth_picture_info in;
    hearth_error err;
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_OK);
    CHECK(in.range[0] == 0 && in.range[1] == 250 && !strcmp(in.colormap, "cividis"));
    d.colormap = "jet";
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_ERR_PARAM);
    printf("%s\n", err.msg);
    CHECK(strstr(err.msg, "'jet'") && strstr(err.msg, "viridis") && strstr(err.msg, "cividis"));
    d.colormap = NULL, d.range[0] = 300;
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_ERR_PARAM);
    printf("%s\n", err.msg);
    d = hearth_default_picture_def();
    d.field = "stress";
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_ERR_PARAM);
    CHECK(strstr(err.msg, "stress_xx") != NULL);
    d.field = "saturation_typo";
    CHECK(hearth_render(s, &d, path, &in, &err) != HEARTH_OK);
    /* GROW holds a range and widens it to the data: 100..120 grows to hold 20 degC */
    d = hearth_default_picture_def();
    d.field = "temperature", d.range_mode = HEARTH_RANGE_GROW, d.range[0] = 100, d.range[1] = 120;
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_OK);
    printf("grow: data %g..%g, range %g..%g\n", in.data[0], in.data[1], in.range[0], in.range[1]);
    CHECK(in.range[0] == in.data[0] && in.data[0] < 21 && in.range[1] == 120);
    hearth_scene_destroy(s);
    rm_dir(dir);
}

/* A 3D particle picture's slab (hearth_picture_def.depth; #18, helper userfix11). Bars set before the first run: a
 * depth in 2D, on a slice, of 0 or below, and an `at` outside the domain's z are refused naming depth or at and what
 * is valid; depth = inf draws the very pixels of the default (every particle, speeds 1 to 3 m/s); a slab 2 dx
 * thick about the middle draws the middle body of three stacked along z alone (its data 2 .. 2 m/s) and its title
 * gives "particles at z = 0.1 ± 0.02 m". */
TEST(png_depth_checked) {
    char dir[64], path[128], path2[128];
    make_dir(dir, sizeof dir);
    hearth_error err;
    hearth_picture_info in;
    snprintf(path, sizeof path, "%s/d.png", dir);
    snprintf(path2, sizeof path2, "%s/e.png", dir);
    hearth_scene *s2 = heated_scene();
    CHECK(s2 != NULL);
    hearth_picture_def d = hearth_default_picture_def();
    d.field = "temperature", d.kind = HEARTH_PICTURE_PARTICLES, d.depth = 0.01;
    CHECK(hearth_render(s2, &d, path, &in, &err) == HEARTH_ERR_PARAM);
    printf("%s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "depth = 0.01 m draws a slab of a 3D particle picture; this is a 2D scene");
    hearth_scene_destroy(s2);
    hearth_scene_def sd = hearth_default_scene_def();
    sd.dim = 3, sd.dx = 0.02, sd.gravity[1] = 0;
    for (int k = 0; k < 3; k++) sd.lo[k] = 0, sd.hi[k] = 0.2;
    hearth_scene *s = fx_scene_def(&sd);
    CHECK(s != NULL);
    const char *names[] = {"E", "nu", "density"};
    const double vals[] = {2e5, 0.3, 1000};
    const int m = hearth_scene_add_material(s, "elastic", names, vals, 3, &err);
    CHECK(m >= 0);
    /* a cube of three bodies along z, each its own speed: z in [0.06, 0.08) at 1 m/s, [0.08, 0.12] at 2, (0.12,
     * 0.14] at 3; ppc 8 at dx 20 mm: particle layers 2.5 mm apart, the middle body's from 0.08125 to 0.11875 */
    for (int k = 0; k < 3; k++) {
        const double z0 = k == 0 ? 0.06 : k == 1 ? 0.08 : 0.12, z1 = k == 0 ? 0.08 : k == 1 ? 0.12 : 0.14;
        const double c[3] = {0.1, 0.1, 0.5 * (z0 + z1)}, half[3] = {0.04, 0.04, 0.5 * (z1 - z0)};
        hearth_shape *part = hearth_shape_box(c, half);
        hearth_body_def bd = hearth_default_body_def();
        bd.shape = part, bd.material = m, bd.jitter = 0, bd.ppc = 8, bd.velocity[0] = k + 1;
        CHECK(hearth_scene_add_body(s, &bd, &err) >= 0);
        hearth_shape_free(part);
    }
    d = hearth_default_picture_def();
    d.field = "temperature", d.kind = HEARTH_PICTURE_SLICE, d.depth = 0.01;
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_ERR_PARAM);
    printf("%s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "this is a slice");
    d.kind = HEARTH_PICTURE_PARTICLES, d.depth = 0;
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_ERR_PARAM);
    printf("%s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "depth = 0 m; valid: a slab's thickness > 0, or inf for every particle");
    d.depth = 0.04, d.at = 0.3;
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_ERR_PARAM);
    printf("%s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "at = 0.3 m, the slab's middle along z; valid range [0, 0.2]");
    /* inf: the default's pixels */
    d = hearth_default_picture_def();
    d.field = "speed", d.kind = HEARTH_PICTURE_PARTICLES;
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_OK);
    d.depth = INFINITY;
    CHECK(hearth_render(s, &d, path2, &in, &err) == HEARTH_OK);
    int w = 0, h = 0, w2 = 0, h2 = 0;
    unsigned char *a = decode_rgb(path, &w, &h), *b = decode_rgb(path2, &w2, &h2);
    CHECK(a && b && w == w2 && h == h2 && !memcmp(a, b, (size_t)3 * w * h));
    free(a), free(b);
    printf("every particle: data %g .. %g m/s\n", in.data[0], in.data[1]);
    CHECK(in.data[0] == 1 && in.data[1] == 3);
    /* the slab 0.08 .. 0.12 holds the middle body's particles alone */
    d.depth = 0.04;
    const hearth_status st = hearth_render(s, &d, path, &in, &err);
    if (st) printf("%s\n", err.msg);
    CHECK(st == HEARTH_OK);
    printf("slab: data %g .. %g m/s, title %s\n", in.data[0], in.data[1], in.title);
    CHECK(in.data[0] == 2 && in.data[1] == 2);
    CHECK_STR_CONTAINS(in.title, "   particles at z = 0.1 ± 0.02 m");
    hearth_scene_destroy(s);
    rm_dir(dir);
}

/* A scene whose rates run S times fast (the physical presets: a 25 minute
 * bake in 5 simulated seconds) titles its pictures with the real time, in
 * minutes past two of them, beside the simulated seconds and the factor;
 * time_scale 1 titles with the simulated seconds alone; a factor out of
 * (0, 1e9] is refused naming it and the range. */
TEST(png_title_gives_real_time) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/t.png", dir);
    hearth_scene *s = heated_scene();
    CHECK(s != NULL);
    hearth_error err;
    CHECK(hearth_scene_step(s, 400, &err) == HEARTH_OK);
    const double t = hearth_scene_time(s);
    hearth_picture_def d = hearth_default_picture_def();
    d.field = "temperature";
    hearth_picture_info in;
    const double scales[3] = {1, 300 * 60 / t, 30 / t}; /* simulated, 300 real minutes, 30 real seconds */
    for (int k = 0; k < 3; k++) {
        d.time_scale = scales[k];
        CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_OK);
        printf("time_scale %g at t = %g s: \"%s\"\n", scales[k], t, in.title);
        double shown = NAN;
        char unit[8] = "";
        CHECK(sscanf(in.title, "t = %lf %7s", &shown, unit) == 2);
        const double want = k == 1 ? 300 : k == 2 ? 30 : t;
        CHECK(fabs(shown - want) <= 5e-4 * want); /* 4 significant digits */
        CHECK(!strcmp(unit, k == 1 ? "min" : "s"));
        CHECK((strstr(in.title, "simulated") != NULL) == (k > 0));
        CHECK(strstr(in.title, "step 400") != NULL);
    }
    const double bad[4] = {0, -1, NAN, 2e9};
    for (int k = 0; k < 4; k++) {
        d.time_scale = bad[k];
        CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_ERR_PARAM);
        printf("%s\n", err.msg);
        CHECK(strstr(err.msg, "time_scale") && strstr(err.msg, "(0, 1e9]"));
    }
    hearth_scene_destroy(s);
    rm_dir(dir);
}

/* A long title (a 64-byte label, the real and simulated times, the step) stays clear of the colour bar's
 * name above the bar (#18, helper userview3: drying.lua's "time lapse: ..." title ran into "saturation (-)" at
 * 800 px). Bar set before the first run: right of the bar's left edge and above the bar, the picture with the
 * long title is pixel for pixel the one with no label (only the bar's name is drawn there), and the long
 * title still leaves ink left of the bar. */
TEST(png_long_title_clear_of_bar) {
    char dir[64], plain[128], longp[128];
    make_dir(dir, sizeof dir);
    snprintf(plain, sizeof plain, "%s/plain.png", dir);
    snprintf(longp, sizeof longp, "%s/long.png", dir);
    hearth_scene *s = heated_scene();
    CHECK(s != NULL);
    hearth_error err;
    CHECK(hearth_scene_step(s, 400, &err) == HEARTH_OK);
    hearth_picture_def d = hearth_default_picture_def();
    d.field = "temperature", d.width = 800, d.time_scale = 50;
    hearth_picture_info a, b;
    CHECK(hearth_render(s, &d, plain, &a, &err) == HEARTH_OK);
    char label[65];
    memset(label, 'W', 64), label[64] = '\0';
    d.label = label;
    CHECK(hearth_render(s, &d, longp, &b, &err) == HEARTH_OK);
    printf("long title (%zu bytes): \"%s\"\n", strlen(b.title), b.title);
    int w = 0, h = 0, w2 = 0, h2 = 0;
    unsigned char *pa = decode_rgb(plain, &w, &h), *pb = decode_rgb(longp, &w2, &h2);
    CHECK(pa && pb && w == w2 && h == h2);
    if (!pa || !pb || w != w2 || h != h2) {
        free(pa), free(pb);
        hearth_scene_destroy(s);
        rm_dir(dir);
        return;
    }
    int differ = 0, ink = 0;
    for (int y = 0; y < (int)b.bar[1] - 1; y++) {
        for (int x = (int)b.bar[0]; x < w; x++) differ += memcmp(pixel(pa, w, x, y), pixel(pb, w, x, y), 3) != 0;
        for (int x = 0; x < (int)b.bar[0]; x++) ink += pixel(pb, w, x, y)[0] < 128;
    }
    printf("above the bar and right of x = %.1f px: %d pixels differ from the unlabelled picture; title ink left of it %d px\n",
           b.bar[0], differ, ink);
    CHECK(differ == 0);
    CHECK(ink > 500);
    free(pa), free(pb);
    hearth_scene_destroy(s);
    rm_dir(dir);
}

/* Every allocation a picture makes may fail: each failure is HEARTH_ERR_NOMEM
 * with nothing leaked, for both kinds (the colliders' map included). */
TEST(png_alloc_failures) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/a.png", dir);
    hearth_scene *s = heated_scene();
    CHECK(s != NULL);
    for (int kind = 0; kind < 2; kind++) {
        size_t base = hearth_bytes_allocated();
        int failed = 0, done = 0;
        for (long k = 0; k < 32 && !done; k++) {
            hearth_picture_def d = hearth_default_picture_def();
            d.field = "temperature", d.kind = kind ? HEARTH_PICTURE_PARTICLES : HEARTH_PICTURE_SLICE, d.width = 200;
            hearth_error err = {0};
            mem_fail_after(k);
            hearth_status st = hearth_render(s, &d, path, NULL, &err);
            mem_fail_after(-1);
            if (st) {
                failed++;
                CHECK(st == HEARTH_ERR_NOMEM);
            } else done = 1;
            CHECK(hearth_bytes_allocated() == base);
        }
        printf("%s: %d allocations failed one by one, then it drew\n", kind ? "particles" : "slice", failed);
        CHECK(failed >= 2 && done);
    }
    hearth_scene_destroy(s);
    rm_dir(dir);
}

/* A 2D scene lo = 0, hi = (w, hh) at dx with an elastic material (*m its index), for the particle-fill pictures. */
static hearth_scene *elastic_2d(double dx, double w, double hh, int *m) {
    hearth_scene_def sd = hearth_default_scene_def();
    sd.dim = 2, sd.dx = dx;
    sd.lo[0] = sd.lo[1] = sd.lo[2] = 0;
    sd.hi[0] = w, sd.hi[1] = hh, sd.hi[2] = 0.01;
    hearth_scene *s = fx_scene_def(&sd);
    *m = -1;
    if (!s) return NULL;
    const char *names[] = {"E", "nu", "density"};
    const double vals[] = {2e5, 0.3, 1000};
    hearth_error err;
    *m = hearth_scene_add_material(s, "elastic", names, vals, 3, &err);
    return s;
}

/* A 2D body whose particles have paired up (#18, helper userfix5; userview3's item 6: the leavened physical cookies,
 * particles at J ~2.5 whose nearest neighbour lies at 0.73 of their own spacing, drew as loose beads): a lattice of
 * spacing h (each particle's volume h^2) whose columns are moved 0.3 h toward each other in pairs, so a disc of 1.3 h
 * across leaves a stripe 0.3 h wide between pairs while the material, by volume, fills the block. The bar, set
 * before the fill was written: no background pixel inside the block (1 h in from its outline); and a lone particle
 * of the same volume is drawn as its disc alone: no ink from 0.65 h + 2 px to 1.5 h from its centre. */
TEST(png_particles_paired_filled) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/pairs.png", dir);
    hearth_error err;
    int m;
    hearth_scene *s = elastic_2d(0.01, 0.2, 0.1, &m);
    CHECK(s != NULL && m >= 0);
    if (!s) return;
    const double h = 0.005, x0 = 0.05, y0 = 0.03;
    enum { NX = 20, NY = 8 };
    double X[3 * (NX * NY + 1)];
    for (int i = 0; i < NX; i++)
        for (int j = 0; j < NY; j++) {
            double *x = X + 3 * (i * NY + j);
            x[0] = x0 + (i + 0.5) * h + (i % 2 ? -0.3 : 0.3) * h, x[1] = y0 + (j + 0.5) * h, x[2] = 0;
        }
    double *lone = X + 3 * NX * NY;
    lone[0] = 0.175, lone[1] = 0.05, lone[2] = 0;
    CHECK(hearth_scene_add_particles(s, m, NX * NY + 1, X, NULL, h * h, &err) == NX * NY + 1);
    hearth_picture_def d = hearth_default_picture_def();
    d.field = "speed", d.kind = HEARTH_PICTURE_PARTICLES, d.width = 800;
    hearth_picture_info in;
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_OK);
    int w = 0, ht = 0;
    unsigned char *px = decode_rgb(path, &w, &ht);
    CHECK(px != NULL);
    if (!px) {
        hearth_scene_destroy(s);
        return;
    }
    static const unsigned char white[3] = {255, 255, 255};
    const double sc = in.area[2] / (in.view_hi[0] - in.view_lo[0]);
    int inside = 0, holes = 0, halo = 0, ring = 0;
    for (int y = 0; y < ht; y++)
        for (int x = 0; x < w; x++) {
            const double mx = in.view_lo[0] + (x + 0.5 - in.area[0]) / sc;
            const double my = in.view_lo[1] + (in.area[1] + in.area[3] - (y + 0.5)) / sc;
            if (mx > x0 + h && mx < x0 + (NX - 1) * h && my > y0 + h && my < y0 + (NY - 1) * h) {
                inside++;
                holes += near_rgb(pixel(px, w, x, y), white, 8);
            }
            const double r = hypot(mx - lone[0], my - lone[1]) * sc;
            if (r > 0.65 * h * sc + 2 && r < 1.5 * h * sc) {
                ring++;
                halo += !near_rgb(pixel(px, w, x, y), white, 8);
            }
        }
    printf("%.2f px per h; inside the paired block: %d of %d pixels background (need 0); around the lone particle: %d of %d "
           "pixels inked from 0.65 h + 2 px to 1.5 h (need 0)\n", h * sc, holes, inside, halo, ring);
    CHECK(inside > 1000 && holes == 0);
    CHECK(ring > 100 && halo == 0);
    free(px);
    hearth_scene_destroy(s);
    rm_dir(dir);
}

/* A long title on a narrow picture (#18, helper userfix5; userview3's item 11: drying.lua's 93-byte title at
 * width = 300 was set 4 px high, half the 8 px floor font). The bar, set before the change: at width 300 a 47-byte
 * label with a time_scale's long time gives title ink (above the plot, in the left 150 px) spanning at least 12 rows
 * with at least 10 of them inked: two lines at the floor font, where one line set at half of it spans about 5. */
TEST(png_narrow_title_two_lines) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/narrow.png", dir);
    hearth_scene *s = heated_scene();
    CHECK(s != NULL);
    if (!s) return;
    hearth_error err;
    CHECK(hearth_scene_step(s, 40, &err) == HEARTH_OK);
    hearth_picture_def d = hearth_default_picture_def();
    d.field = "temperature", d.width = 300, d.time_scale = 50;
    d.label = "time lapse: 1 s of drying a frame, skin 0.5 mm";
    hearth_picture_info in;
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_OK);
    int w = 0, h = 0;
    unsigned char *px = decode_rgb(path, &w, &h);
    CHECK(px != NULL);
    if (!px) {
        hearth_scene_destroy(s);
        return;
    }
    int first = -1, last = -1, rows = 0;
    for (int y = 0; y < (int)in.area[1] - 1; y++) {
        int ink = 0;
        for (int x = 0; x < 150 && x < w; x++) ink += pixel(px, w, x, y)[0] < 160;
        if (ink) rows++, last = y, first = first < 0 ? y : first;
    }
    printf("title \"%s\" at %d px wide: ink rows %d..%d (%d inked) above the plot's top at %.1f px\n", in.title, w, first, last,
           rows, in.area[1]);
    CHECK(first >= 0 && last - first + 1 >= 12 && rows >= 10);
    CHECK(strstr(in.title, d.label) == in.title); /* info->title keeps it whole, on one line */
    free(px);
    hearth_scene_destroy(s);
    rm_dir(dir);
}

/* A 2D particle picture's fill holds a band of its samples at once, not the picture's (#18, helper userfix6; render.c's
 * fill_material probed the whole picture at once, 40 bytes a sample, and lifted the demo's peak 13.9 -> 23.9 MB).
 * A block of 12800 particles (dx 5 mm, 4 a cell) in a 1 x 0.6 m domain drawn 1600 px wide, where the fill samples
 * every pixel (dx/8 = 0.6 mm against 0.63 mm a pixel): ~1.4 M samples, 55 MB at 40 bytes. What the fill adds is the
 * library's peak (hearth_bytes_peak) after drawing "speed" (filled) over its peak after the same picture of
 * "velocity" (a vector: no fill, the discs alone; every other buffer the same). The bar, set at 15:07 UTC before the
 * first run: the fill adds at most 2 MiB. */
TEST(png_particle_fill_memory_bounded) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    hearth_error err;
    int m;
    hearth_scene *s = elastic_2d(0.005, 1, 0.6, &m);
    CHECK(s != NULL && m >= 0);
    if (!s) return;
    enum { NX = 160, NY = 80 };
    const double h = 0.0025;
    double *X = malloc(sizeof(double) * 3 * NX * NY);
    CHECK(X != NULL);
    if (!X) {
        hearth_scene_destroy(s);
        return;
    }
    for (int i = 0; i < NX; i++)
        for (int j = 0; j < NY; j++) {
            double *x = X + 3 * (i * NY + j);
            x[0] = 0.2 + (i + 0.5) * h, x[1] = 0.05 + (j + 0.5) * h, x[2] = 0;
        }
    CHECK(hearth_scene_add_particles(s, m, NX * NY, X, NULL, h * h, &err) == NX * NY);
    free(X);
    hearth_picture_def d = hearth_default_picture_def();
    d.kind = HEARTH_PICTURE_PARTICLES, d.width = 1600;
    hearth_picture_info in;
    const size_t held = hearth_bytes_allocated();
    d.field = "velocity";
    snprintf(path, sizeof path, "%s/discs.png", dir);
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_OK);
    const size_t discs = hearth_bytes_peak();
    d.field = "speed";
    snprintf(path, sizeof path, "%s/filled.png", dir);
    CHECK(hearth_render(s, &d, path, &in, &err) == HEARTH_OK);
    const size_t filled = hearth_bytes_peak();
    const double px_per_m = in.area[2] / (in.view_hi[0] - in.view_lo[0]);
    const double added = (double)(filled - discs) / (1 << 20);
    printf("%.0f x %.0f px picture, %.2f px per mm (a fill sample a pixel below %.2f px per mm): the library held %.2f MB; "
           "peak over it %.2f MB drawing the discs alone, %.2f MB filled: the fill adds %.2f MiB (bar 2)\n",
           in.area[2], in.area[3], px_per_m / 1000, 8 / (s->def.dx * 1000), held / 1e6, (discs - held) / 1e6,
           (filled - held) / 1e6, added);
    CHECK(px_per_m * 0.125 * s->def.dx <= 1.0); /* the picture is sampled at a pixel, as the bar's numbers assume */
    CHECK(added <= 2.0);
    hearth_scene_destroy(s);
    rm_dir(dir);
}

TEST_MAIN(T(png_fixed_range_across_frames), T(png_colliders_drawn), T(png_sph_colliders_drawn), T(png_colorbar_ticks), T(png_options_checked), T(png_depth_checked),
          T(png_title_gives_real_time), T(png_alloc_failures), T(png_long_title_clear_of_bar),
          T(png_particles_paired_filled), T(png_narrow_title_two_lines), T(png_particle_fill_memory_bounded))
