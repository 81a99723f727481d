/* unit_checkpoint_versions.c: files from older versions of the format. A
 * version this hearth still reads (4 to 8) loads with the fields added since
 * at their defaults and continues as the scene it was saved from; an older
 * one is refused by its version, and an old layout this one cannot read
 * (2D's 3x3 tensors) with a message that says why. Old files are rebuilt from
 * a new save by cutting what later versions appended (checkpoint_fixture.h). */
#include "checkpoint_fixture.h"
#include "tensor2.h"

static void version_2(uint8_t *b, size_t n) {
    (void)n;
    const uint32_t v = 2;
    memcpy(b + 8, &v, 4);
}

/* Version 2 files are refused by their version, not parsed. */
TEST(checkpoint_old_version) {
    hearth_scene *s = small_scene();
    size_t n;
    uint8_t *img = save_image(s, &n);
    version_2(img, n);
    hearth_error err;
    CHECK(hearth_scene_load_mem(img, n, "old.ck", &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "old.ck");
    CHECK_STR_CONTAINS(err.msg, "version 2");
    free(img);
    hearth_scene_destroy(s);
}

/* A 2D MPM store keeps C and F as 2x2 blocks (tensor2.h), saved as "C_xy"
 * and "F_xy". A 2D checkpoint from before (the 9-component "C" and "F",
 * rebuilt here from a new save: the same values, embedded) is refused with
 * a message that says why, not read as misaligned columns. */
TEST(checkpoint_2d_old_tensors_refused) {
    hearth_scene *s = small_scene();
    CHECK(s && s->def.dim == 2 && s->ps.t2);
    size_t n;
    uint8_t *img = save_image(s, &n);
    const size_t np = (size_t)hearth_scene_particle_count(s);
    const size_t at = find(img, n, "\4\0\0\0C_xy", 8);
    CHECK(at != (size_t)-1 && at + 2 * (8 + 32 * np) <= n);
    CHECK(memcmp(img + at + 8 + 32 * np, "\4\0\0\0F_xy", 8) == 0);
    const size_t rest = at + 2 * (8 + 32 * np), m = at + 2 * (5 + 72 * np) + (n - rest);
    uint8_t *b = malloc(m), *o = b;
    memcpy(o, img, at), o += at;
    for (int t = 0; t < 2; t++) {
        const uint32_t len = 1;
        memcpy(o, &len, 4), o += 4;
        *o++ = t ? 'F' : 'C';
        for (size_t i = 0; i < np; i++) {
            double a[4], e[9];
            memcpy(a, img + at + t * (8 + 32 * np) + 8 + 32 * i, sizeof a);
            t2_embed(a, t ? 1.0 : 0.0, e);
            memcpy(o, e, sizeof e), o += sizeof e;
        }
    }
    memcpy(o, img + rest, n - rest);
    ck_reseal(b, m);
    hearth_error err;
    CHECK(hearth_scene_load_mem(b, m, "old2d.ck", &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "old2d.ck");
    CHECK_STR_CONTAINS(err.msg, "before the 2x2 particle store");
    printf("  refused: %s\n", err.msg);
    free(b);
    free(img);
    hearth_scene_destroy(s);
}

/* A version 4 file (version 5's layout without the DEF fields 5 appended,
 * rebuilt here from a new save without version 6's fields, version 7's dry_conductivity and version 8's
 * dry_specific_heat) still loads,
 * those fields at their defaults,
 * and continues as the scene it was saved from; version 3 is refused by
 * version (docs/checkpoints.md). */
TEST(checkpoint_v4_reads_at_defaults) {
    /* a version 4 file has no field_steps and reads as 1, the single-rate scheme that wrote it (checkpoint.c),
     * not as today's default (0, automatic): the saved scene runs single rate too, so the copy continues it */
    hearth_scene *s = small_scene_k(1);
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    if (!img || !s) return;
    /* version 16's DEF tail, then the DEF fields 5 and 6 appended and the clocks' version 6 and 7 tails cut out */
    cut_v16_def(img, &n);
    const size_t clk = clk_at(img, n), cut = V5_DEF_BYTES + V6_DEF_BYTES, tail = clk + 4 + V5_CLK_BYTES;
    const size_t vt = V6_CLK_BYTES + V7_CLK_BYTES;
    size_t m = n - cut - vt;
    uint8_t *b = malloc(m);
    memcpy(b, img, clk - cut);
    memcpy(b + clk - cut, img + clk, tail - clk);
    memcpy(b + tail - cut, img + tail + vt, n - tail - vt);
    /* and the last four core material parameters before version 12's (version 7's dry_conductivity, version 8's
     * dry_specific_heat, version 10's ambient_pressure and open_temperature) and version 12's: files before 7 hold
     * CP_COUNT - 4 - V12_CORE of them */
    if (!cut_core_params(b, &m, 4 + V12_CORE)) {
        free(b);
        free(img);
        hearth_scene_destroy(s);
        return;
    }
    const uint32_t v4 = 4;
    memcpy(b + 8, &v4, 4);
    ck_reseal(b, m);
    hearth_error err;
    hearth_scene *r = hearth_scene_load_mem(b, m, "v4.ck", &err);
    if (!r) printf("  v4 refused: %s\n", err.msg);
    CHECK(r != NULL);
    if (r) {
        const hearth_scene_def d0 = hearth_default_scene_def();
        printf("  v4 file of %zu bytes (v5: %zu): damping %g, boiling_point %g, periodic %d %d %d, two_field %d (%g), "
               "gas_vent %g, vent_porosity %g\n", m, n, r->def.damping, r->def.boiling_point, r->def.periodic[0],
               r->def.periodic[1], r->def.periodic[2], r->def.two_field, r->def.two_field_friction, r->def.gas_vent,
               r->def.vent_porosity);
        CHECK(r->def.damping == d0.damping && r->def.boiling_point == d0.boiling_point);
        CHECK(!r->def.periodic[0] && !r->def.periodic[1] && !r->def.periodic[2] && !r->def.two_field);
        CHECK(r->def.two_field_friction == d0.two_field_friction && r->def.gas_vent == d0.gas_vent &&
              r->def.vent_porosity == d0.vent_porosity);
        continues_as(s, r, "v4 copy");
        hearth_scene_destroy(r);
    }
    const uint32_t v3 = 3;
    memcpy(b + 8, &v3, 4);
    ck_reseal(b, m);
    CHECK(hearth_scene_load_mem(b, m, "v3.ck", &err) == NULL);
    printf("  %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "checkpoint version 3; this hearth reads versions 4 to 16 only");
    free(b);
    free(img);
    hearth_scene_destroy(s);
}

/* A wet block in an oven whose material sets dry_specific_heat, to 300 s. */
static hearth_scene *dry_heat_scene(double dry_c) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.1;
    d.gravity[1] = 0;
    d.oven_temperature = 180;
    d.oven_beta = 10;
    d.latent_heat = 1;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NULL;
    const char *nm[] = {"E", "density", "specific_heat", "conductivity", "saturation", "evaporation", "dry_specific_heat"};
    const double nv[] = {1e4, 500, 2700, 0.5, 0.3, 1e-5, dry_c};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "elastic", nm, nv, 7, &err);
    CHECK(m >= 0);
    const double c[3] = {0.5, 0.4, 0}, h[3] = {0.1, 0.1, 0};
    CHECK(fx_box(s, m, c, h, 1, NULL) > 0);
    CHECK(hearth_scene_step(s, 3, &err) == HEARTH_OK);
    return s;
}

/* Scene s saved, as the older version's writer would have: its image without the last `cut` core material
 * parameters, stamped `version`; that file loaded (NULL, the refusal printed, when it is not). *bytes gets the
 * older file's size, *newer the image's. */
static hearth_scene *load_older(hearth_scene *s, int cut, uint32_t version, size_t *bytes, size_t *newer) {
    uint8_t *img = save_image(s, newer);
    CHECK(img != NULL);
    *bytes = *newer;
    if (!img || !cut_core_params(img, bytes, cut)) {
        free(img);
        return NULL;
    }
    memcpy(img + 8, &version, 4);
    ck_reseal(img, *bytes);
    char name[16];
    snprintf(name, sizeof name, "v%u.ck", (unsigned)version);
    hearth_error err;
    hearth_scene *r = hearth_scene_load_mem(img, *bytes, name, &err);
    if (!r) printf("  v%u refused: %s\n", (unsigned)version, err.msg);
    free(img);
    return r;
}

/* Version 8 carries a material's dry_specific_heat through a save; a version
 * 7 file (a version 8 image without it, before the curve count) loads with 0,
 * as wet, and continues as the scene it was saved from, which had 0. */
TEST(checkpoint_v7_reads_dry_specific_heat_as_wet) {
    hearth_scene *s = dry_heat_scene(900);
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    hearth_error err;
    hearth_scene *r = img ? hearth_scene_load_mem(img, n, "v8.ck", &err) : NULL;
    CHECK(r != NULL);
    if (r) {
        printf("  v8: dry_specific_heat %g saved, %g restored\n", s->mats.slot[0].core[CP_DRY_SPECIFIC_HEAT],
               r->mats.slot[0].core[CP_DRY_SPECIFIC_HEAT]);
        CHECK(r->mats.slot[0].core[CP_DRY_SPECIFIC_HEAT] == 900);
        hearth_scene_destroy(r);
    }
    free(img);
    hearth_scene_destroy(s);
    s = dry_heat_scene(0);
    size_t m;
    r = load_older(s, 3 + V12_CORE, 7, &m, &n); /* without dry_specific_heat, version 10's two and version 12's */
    CHECK(r != NULL);
    if (r) {
        CHECK(r->mats.slot[0].core[CP_DRY_SPECIFIC_HEAT] == 0);
        printf("  v7 file of %zu bytes (v8: %zu)\n", m, n);
        continues_as(s, r, "v7 copy");
        hearth_scene_destroy(r);
    }
    hearth_scene_destroy(s);
}

/* Version 9 saves the browning surface's column (PC_SURFACE) of an MPM scene with browning and an oven; a
 * version 8 file (a version 9 image with that column cut out of PART, its bit cleared and the hash its writer
 * took, over the columns it held) loads with the column zeroed, each particle browning at its own temperature
 * until the next field step finds the surface again (browning.c), and steps on. */
TEST(checkpoint_v8_reads_browning_surface_as_zero) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 2, d.dx = 0.01, d.gravity[1] = 0, d.browning = 1, d.browning_scale = 600, d.oven_temperature = 250, d.oven_beta = 40;
    d.field_steps = 1; /* every step carries the fields: the surface is found at once */
    for (int k = 0; k < 3; k++) d.lo[k] = 0, d.hi[k] = 0.2;
    hearth_scene *s = fx_scene_def(&d);
    CHECK(s != NULL);
    if (!s) return;
    hearth_error err;
    const char *nm[] = {"E", "density", "specific_heat", "conductivity"};
    const double nv[] = {1e4, 500, 2800.0 / 600, 0.4};
    const int m = hearth_scene_add_material(s, "elastic", nm, nv, 4, &err);
    CHECK(m >= 0);
    const double c[3] = {0.1, 0.1, 0}, h[3] = {0.04, 0.04, 0};
    CHECK(fx_box(s, m, c, h, 1, NULL) > 0);
    CHECK(hearth_scene_step(s, 5, &err) == HEARTH_OK);
    CHECK(s->ps.enabled & (1u << PC_SURFACE));
    int live = 0;
    for (int i = 0; i < s->ps.n; i++) live += pcold(&s->ps, PC_SURFACE)[2 * i] != 0;
    CHECK(live > 0); /* something the cut takes out */
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    if (img && !cut_core_params(img, &n, 2 + V12_CORE)) { /* version 10's ambient_pressure and open_temperature, 12's */
        free(img);
        hearth_scene_destroy(s);
        return;
    }
    const size_t at = img ? find(img, n, "browning_surface", 16) : (size_t)-1, part = img ? find(img, n, "PART", 4) : (size_t)-1;
    CHECK(at != (size_t)-1 && part != (size_t)-1);
    if (at == (size_t)-1 || part == (size_t)-1) {
        free(img);
        hearth_scene_destroy(s);
        return;
    }
    const size_t from = at - 4, len = 4 + 16 + sizeof(double) * 2 * (size_t)s->ps.n; /* name (u32 length, bytes), data */
    memmove(img + from, img + from + len, n - from - len);
    n -= len;
    uint32_t en;
    memcpy(&en, img + part + 12, 4);
    en &= ~(1u << PC_SURFACE);
    memcpy(img + part + 12, &en, 4);
    const uint32_t live_cols = s->ps.enabled, v8 = 8;
    s->ps.enabled &= ~(1u << PC_SURFACE); /* the hash a writer without the column took */
    const uint64_t h8 = hearth_scene_hash(s);
    s->ps.enabled = live_cols;
    memcpy(img + n - 8, &h8, 8);
    memcpy(img + 8, &v8, 4);
    ck_reseal(img, n);
    hearth_scene *r = hearth_scene_load_mem(img, n, "v8.ck", &err);
    if (!r) printf("  v8 refused: %s\n", err.msg);
    CHECK(r != NULL);
    if (r) {
        int zero = 1;
        for (int i = 0; i < r->ps.n; i++) zero &= pcold(&r->ps, PC_SURFACE)[2 * i] == 0 && pcold(&r->ps, PC_SURFACE)[2 * i + 1] == 0;
        CHECK(zero);
        CHECK(hearth_scene_step(r, 5, &err) == HEARTH_OK);
        int again = 0;
        for (int i = 0; i < r->ps.n; i++) again += pcold(&r->ps, PC_SURFACE)[2 * i] != 0;
        printf("  v8 file of %zu bytes: loaded with the column zeroed (%d particles held an offset when saved), %d after 5 steps\n", n,
               live, again);
        CHECK(again > 0);
        hearth_scene_destroy(r);
    }
    free(img);
    hearth_scene_destroy(s);
}

/* Version 10 carries a material's ambient_pressure and open_temperature through a save; a version 9 file (a
 * version 10 image without the two, before the curve count) loads with ambient_pressure 0 (eq. 13 as printed) and
 * open_temperature at its default, and continues as the scene it was saved from, which had both so. */
TEST(checkpoint_v9_reads_ambient_pressure_as_zero) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.1;
    d.gravity[1] = 0;
    hearth_scene *s = fx_scene_def(&d);
    CHECK(s != NULL);
    if (!s) return;
    const char *nm[] = {"E", "density", "porosity", "ambient_pressure", "open_temperature", "reference_temperature"};
    const double nv[] = {1e4, 484, 0.5, 101325, 70, 25};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "elastic", nm, nv, 6, &err);
    CHECK(m >= 0);
    const double c[3] = {0.5, 0.4, 0}, h[3] = {0.1, 0.1, 0};
    CHECK(fx_box(s, m, c, h, 1, NULL) > 0);
    CHECK(hearth_scene_step(s, 3, &err) == HEARTH_OK);
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    hearth_scene *r = img ? hearth_scene_load_mem(img, n, "v10.ck", &err) : NULL;
    if (!r && img) printf("  v10 refused: %s\n", err.msg);
    CHECK(r != NULL);
    if (r) {
        printf("  v10: ambient_pressure %g, open_temperature %g restored\n", r->mats.slot[0].core[CP_AMBIENT_PRESSURE],
               r->mats.slot[0].core[CP_OPEN_TEMPERATURE]);
        CHECK(r->mats.slot[0].core[CP_AMBIENT_PRESSURE] == 101325 && r->mats.slot[0].core[CP_OPEN_TEMPERATURE] == 70);
        continues_as(s, r, "v10 copy");
        hearth_scene_destroy(r);
    }
    free(img);
    hearth_scene_destroy(s);
    s = dry_heat_scene(0);
    size_t k;
    r = load_older(s, 2 + V12_CORE, 9, &k, &n); /* without ambient_pressure and open_temperature (and 12's) */
    CHECK(r != NULL);
    if (r) {
        const hearth_param *cp = hearth_core_params(NULL);
        CHECK(r->mats.slot[0].core[CP_AMBIENT_PRESSURE] == 0);
        CHECK(r->mats.slot[0].core[CP_OPEN_TEMPERATURE] == cp[CP_OPEN_TEMPERATURE].def);
        printf("  v9 file of %zu bytes (v10: %zu)\n", k, n);
        continues_as(s, r, "v9 copy");
        hearth_scene_destroy(r);
    }
    hearth_scene_destroy(s);
}

/* The lowest particle's height above y0, in cells of s. */
static double lowest_above(const hearth_scene *s, double y0) {
    double lo = 1e300;
    for (int i = 0; i < s->ps.n; i++) lo = fmin(lo, pcold(&s->ps, PC_X)[3 * i + 1]);
    return (lo - y0) / s->def.dx;
}

/* Version 11 carries a sticky face's glue (particles.h's PC_GLUE): a sticky face holds only what has touched it
 * (mpm_touch.c). Before it, a sticky face held every node on and inside it, so a body within a cell and a half of
 * one was held where it was. A 6 x 3 cm elastic block released 1 dx above a sticky tray (dx 1 cm, 2 x 2 particles
 * a cell, half-spacing dx / 4) and saved before its first step loads as a version 11 file and falls onto the
 * tray: its lowest particle rests within 0.05 dx of the half-spacing after 0.15 s (contact_test.sh's bar); the same
 * file stamped version 10 means what version 10 meant: the block is held off the tray, its lowest particle 0.75 dx
 * or more above it (a fall puts it at 0.25; main before glue held drop.lua's block at 1.000 dx from 1 dx). The
 * first bar, within 0.02 dx of its start, misread the old rule: it held the tray's node row only, and the block
 * sagged onto that row's reach (1.25 -> 1.157 dx here; main's own build, 9c8120c, reads this file to the same
 * positions and velocities, a weighted sum equal to 17 digits: docs/validation.md "A sticky face holds what
 * touched it"; the hashes differ by the flags column this copy enables). */
TEST(checkpoint_v10_sticky_holds_as_then) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 2, d.dx = 0.01;
    for (int k = 0; k < 3; k++) d.lo[k] = 0, d.hi[k] = 0.2;
    hearth_scene *s = fx_scene_def(&d);
    CHECK(s != NULL);
    if (!s) return;
    const int m = fx_elastic(s, 1e5, 0.3, 1000);
    const double tc[3] = {0.1, 0.03, 0}, th[3] = {0.1, 0.01, 0}; /* the tray's face at y = 0.04, a node row */
    CHECK(fx_box_collider(s, tc, th, HEARTH_STICKY, 0.0) == 0);
    const double c[3] = {0.1, 0.065, 0}, h[3] = {0.03, 0.015, 0}; /* its base at 0.05: 1 dx up */
    CHECK(fx_box(s, m, c, h, 4, NULL) > 0);
    const double start = lowest_above(s, 0.04);
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    if (!img) {
        hearth_scene_destroy(s);
        return;
    }
    hearth_error err;
    if (!cut_core_params(img, &n, V12_CORE)) { /* a version 11 file holds no second CO2 share */
        free(img);
        hearth_scene_destroy(s);
        return;
    }
    for (uint32_t v = 11; v >= 10; v--) {
        memcpy(img + 8, &v, 4);
        ck_reseal(img, n);
        hearth_scene *r = hearth_scene_load_mem(img, n, v == 11 ? "v11.ck" : "v10.ck", &err);
        if (!r) printf("  v%u refused: %s\n", (unsigned)v, err.msg);
        CHECK(r != NULL);
        if (!r) continue;
        CHECK(hearth_scene_advance(r, 0.15, &err) == HEARTH_OK);
        const double low = lowest_above(r, 0.04);
        printf("  v%u copy: lowest particle %.4f dx above the sticky tray at the save, %.4f after 0.15 s, hash %016llx (%s)\n",
               (unsigned)v, start, low, (unsigned long long)hearth_scene_hash(r),
               v == 11 ? "need 0.20..0.30: it fell and rests" : "need 0.75 or more: held off the tray, as then");
        CHECK(v == 11 ? fabs(low - 0.25) <= 0.05 : low >= 0.75);
        hearth_scene_destroy(r);
    }
    free(img);
    hearth_scene_destroy(s);
}

/* Version 12 carries a material's second CO2 share (gas_rate_2, reaction_temperature_2, reaction_width_2; gas.c)
 * through a save; a version 11 file (a version 12 image without the three, before the curve count) loads with
 * gas_rate_2 0 (no second share) and the other two at their defaults, and continues as the scene it was saved
 * from, which had no second share. */
TEST(checkpoint_v11_reads_no_second_share) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.1;
    d.gravity[1] = 0;
    hearth_scene *s = fx_scene_def(&d);
    CHECK(s != NULL);
    if (!s) return;
    const char *nm[] = {"E", "density", "gas_rate", "gas_rate_2", "reaction_temperature_2", "reaction_width_2"};
    const double nv[] = {1e4, 484, 1e-3, 2e-3, 60, 15};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "elastic", nm, nv, 6, &err);
    CHECK(m >= 0);
    const double c[3] = {0.5, 0.4, 0}, h[3] = {0.1, 0.1, 0};
    hearth_body_def bd = hearth_default_body_def();
    hearth_shape *box = hearth_shape_box(c, h);
    bd.shape = box, bd.material = m, bd.temperature = 55;
    CHECK(hearth_scene_add_body(s, &bd, &err) == 0);
    hearth_shape_free(box);
    CHECK(hearth_scene_step(s, 3, &err) == HEARTH_OK);
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    hearth_scene *r = img ? hearth_scene_load_mem(img, n, "v12.ck", &err) : NULL;
    if (!r && img) printf("  v12 refused: %s\n", err.msg);
    CHECK(r != NULL);
    if (r) {
        const double *k = r->mats.slot[0].core;
        printf("  v12: gas_rate_2 %g, reaction_temperature_2 %g, reaction_width_2 %g restored\n", k[CP_GAS_RATE_2],
               k[CP_REACTION_T_2], k[CP_REACTION_WIDTH_2]);
        CHECK(k[CP_GAS_RATE_2] == 2e-3 && k[CP_REACTION_T_2] == 60 && k[CP_REACTION_WIDTH_2] == 15);
        continues_as(s, r, "v12 copy");
        hearth_scene_destroy(r);
    }
    free(img);
    hearth_scene_destroy(s);
    s = dry_heat_scene(0);
    size_t k;
    r = load_older(s, V12_CORE, 11, &k, &n); /* without the second share */
    CHECK(r != NULL);
    if (r) {
        const hearth_param *cp = hearth_core_params(NULL);
        CHECK(r->mats.slot[0].core[CP_GAS_RATE_2] == 0);
        CHECK(r->mats.slot[0].core[CP_REACTION_T_2] == cp[CP_REACTION_T_2].def);
        CHECK(r->mats.slot[0].core[CP_REACTION_WIDTH_2] == cp[CP_REACTION_WIDTH_2].def);
        printf("  v11 file of %zu bytes (v12: %zu)\n", k, n);
        continues_as(s, r, "v11 copy");
        hearth_scene_destroy(r);
    }
    hearth_scene_destroy(s);
}

/* A pinned block at 70 degC whose material gives both CO2 shares an amount (gas_amount, gas_amount_2; gas.h's
 * gas_share_capped), 20 steps in: mid-reaction, the first share's 5e-4 mol/kg not yet made. amounts 0: the same
 * block without them. */
static hearth_scene *amount_scene(int amounts) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.1;
    d.gravity[1] = 0;
    d.dt_max = 1e-2;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NULL;
    const char *nm[] = {"E", "density", "conductivity", "gas_rate", "reaction_temperature", "gas_rate_2",
                        "reaction_temperature_2", "gas_amount", "gas_amount_2"};
    const double nv[] = {1e4, 500, 0, 0.015, 100, 0.02, 60, 5e-4, 5e-3};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "elastic", nm, nv, amounts ? 9 : 7, &err);
    CHECK(m >= 0);
    const double c[3] = {0.5, 0.4, 0}, h[3] = {0.1, 0.1, 0};
    hearth_body_def bd = hearth_default_body_def();
    hearth_shape *box = hearth_shape_box(c, h);
    bd.shape = box, bd.material = m, bd.temperature = 70, bd.fixed = 1; /* pinned: its gas would burst it */
    CHECK(hearth_scene_add_body(s, &bd, &err) == 0);
    hearth_shape_free(box);
    CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
    return s;
}

/* the first particle's gas_made entries set to v (the column's data follows its name) */
static double made_value;
static void made_set(uint8_t *b, size_t n) {
    const size_t at = find(b, n, "gas_made", 8);
    CHECK(at != (size_t)-1);
    if (at != (size_t)-1) memcpy(b + at + 8, &made_value, 8);
}
static void as_is(uint8_t *b, size_t n) { (void)b, (void)n; }
static void made_bit(uint8_t *b, size_t n) { /* claims the column in a file that has none */
    const size_t at = find(b, n, "PART", 4);
    uint32_t v;
    memcpy(&v, b + at + 12, 4);
    v |= 1u << PC_GAS_MADE;
    memcpy(b + at + 12, &v, 4);
}

/* Version 13 carries each share's amount and the CO2 each particle has made of it (PC_GAS_MADE). Saved
 * mid-reaction (the first share's amount met by no particle yet), the restore holds the same counts and, 60 steps
 * on (both shares used up by then), the unbroken run's bits and counts equal to the amounts. A crafted count above
 * its share's amount, a negative one, and the column claimed in a version 12 file are refused by name; a version
 * 12 file (a version 13 image of the block without amounts, cut of the two and the clocks' self_max) loads with
 * amounts 0, no column, and continues as the scene it was saved from. */
TEST(checkpoint_gas_made_mid_reaction) {
    hearth_scene *s = amount_scene(1);
    CHECK(s != NULL);
    if (!s) return;
    double lo = 1, hi = 0;
    for (int i = 0; i < s->ps.n; i++) {
        lo = fmin(lo, pcold(&s->ps, PC_GAS_MADE)[2 * i]);
        hi = fmax(hi, pcold(&s->ps, PC_GAS_MADE)[2 * i]);
    }
    printf("  t = %.3f s, %d particles: share 1 made %.6g..%.6g of 5e-4 mol/kg, share 2 %.6g of 5e-3\n", s->t, s->ps.n,
           lo, hi, pcold(&s->ps, PC_GAS_MADE)[1]);
    CHECK(lo > 0 && hi < 5e-4 && pcold(&s->ps, PC_GAS_MADE)[1] < 5e-3); /* mid-reaction, both shares */
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    hearth_error err;
    hearth_scene *r = img ? hearth_scene_load_mem(img, n, "new.ck", &err) : NULL;
    if (!r && img) printf("  the new file refused: %s\n", err.msg);
    CHECK(r != NULL);
    if (r) {
        CHECK(r->mats.slot[0].core[CP_GAS_AMOUNT] == 5e-4 && r->mats.slot[0].core[CP_GAS_AMOUNT_2] == 5e-3);
        CHECK(r->ps.enabled & (1u << PC_GAS_MADE));
        CHECK(memcmp(pcold(&r->ps, PC_GAS_MADE), pcold(&s->ps, PC_GAS_MADE), sizeof(double) * 2 * (size_t)s->ps.n) == 0);
        CHECK(hearth_scene_step(s, 60, &err) == HEARTH_OK);
        CHECK(hearth_scene_step(r, 60, &err) == HEARTH_OK);
        int used = 1;
        for (int i = 0; i < r->ps.n; i++)
            used &= pcold(&r->ps, PC_GAS_MADE)[2 * i] == 5e-4 && pcold(&r->ps, PC_GAS_MADE)[2 * i + 1] == 5e-3;
        printf("  60 steps on: hash %016llx unbroken, %016llx restored; both shares used up: %s\n",
               (unsigned long long)hearth_scene_hash(s), (unsigned long long)hearth_scene_hash(r), used ? "yes" : "no");
        CHECK(hearth_scene_hash(r) == hearth_scene_hash(s));
        CHECK(used);
        hearth_scene_destroy(r);
    }
    if (img) {
        made_value = 6e-4;
        expect_refused(img, n, made_set, "a particle's CO2 made outside [0, its share's gas_amount]");
        made_value = -1e-9;
        expect_refused(img, n, made_set, "a particle's CO2 made outside [0, its share's gas_amount]");
        size_t k = n;
        if (cut_core_params(img, &k, V13_CORE)) { /* a version 12 file cannot hold the column */
            memcpy(img + 8, &(uint32_t){12}, 4);
            expect_refused(img, k, as_is, "a CO2-made column in a file older than version 13");
        }
    }
    free(img);
    hearth_scene_destroy(s);
    s = amount_scene(0);
    CHECK(s != NULL && !(s->ps.enabled & (1u << PC_GAS_MADE)));
    if (!s) return;
    size_t k;
    r = load_older(s, V13_CORE, 12, &k, &n);
    CHECK(r != NULL);
    if (r) {
        CHECK(r->mats.slot[0].core[CP_GAS_AMOUNT] == 0 && r->mats.slot[0].core[CP_GAS_AMOUNT_2] == 0);
        CHECK(!(r->ps.enabled & (1u << PC_GAS_MADE)) && r->self_max == 0);
        printf("  v12 file of %zu bytes (v13: %zu)\n", k, n);
        continues_as(s, r, "v12 copy");
        hearth_scene_destroy(r);
    }
    img = save_image(s, &n);
    if (img) { /* a version 12 file that claims the column */
        size_t m = n;
        if (cut_core_params(img, &m, V13_CORE)) {
            memcpy(img + 8, &(uint32_t){12}, 4);
            expect_refused(img, m, made_bit, "a CO2-made column in a file older than version 13");
        }
    }
    free(img);
    hearth_scene_destroy(s);
}

/* Version 14 appended each collider's start_temperature, warm_time and t_added (a tray that warms). A version 13
 * file (a new image cut of them, stamped 13) loads with colliders that do not warm: small_scene's two colliders
 * continue as the scene it was saved from, and a heated collider saved while warming (its slot holds the
 * temperature it warms toward) reads as at that temperature, what a version 13 writer meant by it. */
TEST(checkpoint_v13_colliders_do_not_warm) {
    hearth_scene *s = small_scene();
    size_t n, m;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    if (!img || !s) return;
    m = n;
    CHECK(cut_v14_colliders(img, &m) && m == n - V16_DEF_BYTES - 2 * (V14_COL_BYTES + V15_COL_BYTES));
    const uint32_t v13 = 13;
    memcpy(img + 8, &v13, 4);
    ck_reseal(img, m);
    hearth_error err;
    hearth_scene *r = hearth_scene_load_mem(img, m, "v13.ck", &err);
    if (!r) printf("  v13 refused: %s\n", err.msg);
    CHECK(r != NULL);
    if (r) {
        printf("  v13 file of %zu bytes (v14: %zu)\n", m, n);
        continues_as(s, r, "v13 copy");
        hearth_scene_destroy(r);
    }
    free(img);
    hearth_scene_destroy(s);
    /* a tray warming from 20 toward 180 degC, saved mid-warm */
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.1;
    s = fx_scene_def(&d);
    const double fc[3] = {0.5, 0.1, 0}, fh[3] = {0.5, 0.05, 0};
    hearth_shape *tray = hearth_shape_box(fc, fh);
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = tray, cd.temperature = 180, cd.beta = 100, cd.start_temperature = 20, cd.warm_time = 1;
    CHECK(hearth_scene_add_collider(s, &cd, &err) == 0);
    hearth_shape_free(tray);
    s->t = 0.5; /* as if stepped there: its present temperature */
    collider_set_time(&s->cols[0], s->t);
    CHECK_NEAR(s->cols[0].temperature, 180 - 160 * exp(-0.5), 1e-9);
    img = save_image(s, &n);
    CHECK(img != NULL);
    if (!img) return;
    r = hearth_scene_load_mem(img, n, "current.ck", &err);
    CHECK(r != NULL);
    if (r) { /* the new file: warming on from where it was */
        CHECK(r->cols[0].temperature == s->cols[0].temperature && r->cols[0].warm_time == 1);
        hearth_scene_destroy(r);
    }
    m = n;
    CHECK(cut_v14_colliders(img, &m));
    memcpy(img + 8, &v13, 4);
    ck_reseal(img, m);
    r = hearth_scene_load_mem(img, m, "v13.ck", &err);
    CHECK(r != NULL);
    if (r) {
        printf("  saved warming at %.3f degC; a v13 copy reads %.3f degC, not warming (warm_time %g)\n",
               s->cols[0].temperature, r->cols[0].temperature, r->cols[0].warm_time);
        CHECK(r->cols[0].temperature == 180 && r->cols[0].warm_time == 0);
        hearth_scene_destroy(r);
    }
    free(img);
    hearth_scene_destroy(s);
}

/* Version 15 appended each collider's heat_capacity, area and its sheet's state (a sheet the food draws from,
 * colliders.h). A block on a drawing sheet saved mid-warm goes on with the same bits, the sheet's temperature and
 * books too; a version 14 copy (cut of them, stamped 14) loads with a sheet that draws nothing and warms by its
 * warm_time, what a version 14 writer meant. */
TEST(checkpoint_v14_sheets_draw_nothing) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.0025;
    d.gravity[1] = 0;
    d.lo[0] = d.lo[1] = -0.03, d.hi[0] = d.hi[1] = 0.03;
    hearth_scene *s = fx_scene_def(&d);
    const char *nm[] = {"E", "density", "conductivity", "specific_heat"};
    const double nv[] = {1e-2, 1000, 0.5, 2000};
    hearth_error err;
    const int mat = hearth_scene_add_material(s, "elastic", nm, nv, 4, &err);
    const double bc[3] = {0, 0.005, 0}, bh[3] = {0.01, 0.005, 1}, pp[3] = {0, 0, 0}, pn[3] = {0, 1, 0};
    hearth_shape *blk = hearth_shape_box(bc, bh), *plate = hearth_shape_plane(pp, pn);
    hearth_body_def b = hearth_default_body_def();
    b.shape = blk, b.material = mat, b.jitter = 0, b.temperature = 20, b.fixed = 1;
    CHECK(mat >= 0 && hearth_scene_add_body(s, &b, &err) == 0);
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = plate, cd.temperature = 190, cd.beta = 100, cd.start_temperature = 20, cd.warm_time = 40;
    cd.heat_capacity = 2430, cd.area = 0.06;
    CHECK(hearth_scene_add_collider(s, &cd, &err) == 0);
    hearth_shape_free(blk);
    hearth_shape_free(plate);
    CHECK(hearth_scene_set_dt_limits(s, 0.5, 0.5, &err) == HEARTH_OK);
    CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
    size_t n, m;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    if (!img) return;
    hearth_scene *r = hearth_scene_load_mem(img, n, "v16.ck", &err);
    CHECK(r != NULL);
    if (r) {
        CHECK(hearth_scene_set_dt_limits(r, 0.5, 0.5, &err) == HEARTH_OK);
        continues_as(s, r, "restored");
        printf("  sheet %.6f degC drawn %.3f J/m saved scene, %.6f degC drawn %.3f J/m restored\n", s->cols[0].sheet_T,
               s->cols[0].drawn, r->cols[0].sheet_T, r->cols[0].drawn);
        CHECK(r->cols[0].sheet_T == s->cols[0].sheet_T && r->cols[0].drawn == s->cols[0].drawn &&
              r->cols[0].oven_in == s->cols[0].oven_in && r->cols[0].temperature == s->cols[0].temperature);
        CHECK(s->cols[0].drawn > 0);
        hearth_scene_destroy(r);
    }
    m = n;
    CHECK(cut_v15_colliders(img, &m) && m == n - V16_DEF_BYTES - V15_COL_BYTES);
    const uint32_t v14 = 14;
    memcpy(img + 8, &v14, 4);
    ck_reseal(img, m);
    r = hearth_scene_load_mem(img, m, "v14.ck", &err);
    if (!r) printf("  v14 refused: %s\n", err.msg);
    CHECK(r != NULL);
    if (r) {
        const double t = hearth_scene_time(r), want = 190 - 170 * exp(-t / 40);
        printf("  a v14 copy at %.1f s: the sheet %.6f degC, drawing nothing (heat_capacity %g), its exponential %.6f\n", t,
               r->cols[0].temperature, r->cols[0].heat_capacity, want);
        CHECK(r->cols[0].heat_capacity == 0 && r->cols[0].warm_time == 40);
        CHECK_NEAR(r->cols[0].temperature, want, 1e-9);
        hearth_scene_destroy(r);
    }
    free(img);
    hearth_scene_destroy(s);
}

/* Version 16 appended the oven's radiating walls to DEF: they are kept, and a restore continues with the same bits
 * (continues_as); a version 15 copy of the same save (its DEF without them) reads an oven without walls: no wall
 * temperature, emissivity 0, radiation_scale 1, as every file before 16 was written. */
TEST(checkpoint_v16_keeps_oven_walls) {
    hearth_scene *s = small_scene();
    CHECK(s != NULL);
    if (!s) return;
    s->def.oven_wall_temperature = 250, s->def.oven_emissivity = 0.9, s->def.oven_radiation_scale = 2;
    hearth_error err;
    CHECK(hearth_scene_step(s, 2, &err) == HEARTH_OK);
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    if (!img) return;
    hearth_scene *r = hearth_scene_load_mem(img, n, "v16.ck", &err);
    if (!r) printf("  v16 refused: %s\n", err.msg);
    CHECK(r != NULL);
    if (r) {
        printf("  v16: walls %g degC, emissivity %g, radiation_scale %g restored\n", r->def.oven_wall_temperature,
               r->def.oven_emissivity, r->def.oven_radiation_scale);
        CHECK(r->def.oven_wall_temperature == 250 && r->def.oven_emissivity == 0.9 && r->def.oven_radiation_scale == 2);
        continues_as(s, r, "restored from version 16");
        hearth_scene_destroy(r);
    }
    size_t m = n;
    cut_v16_def(img, &m);
    CHECK(m == n - V16_DEF_BYTES);
    ck_reseal(img, m);
    r = hearth_scene_load_mem(img, m, "v16.ck", &err);
    if (!r) printf("  v15 refused: %s\n", err.msg);
    CHECK(r != NULL);
    if (r) {
        printf("  v15 copy: walls %g, emissivity %g, radiation_scale %g\n", r->def.oven_wall_temperature,
               r->def.oven_emissivity, r->def.oven_radiation_scale);
        CHECK(isnan(r->def.oven_wall_temperature) && r->def.oven_emissivity == 0 && r->def.oven_radiation_scale == 1);
        hearth_scene_destroy(r);
    }
    free(img);
    hearth_scene_destroy(s);
}

TEST_MAIN(T(checkpoint_old_version), T(checkpoint_2d_old_tensors_refused), T(checkpoint_v4_reads_at_defaults),
          T(checkpoint_v7_reads_dry_specific_heat_as_wet), T(checkpoint_v8_reads_browning_surface_as_zero),
          T(checkpoint_v9_reads_ambient_pressure_as_zero), T(checkpoint_v10_sticky_holds_as_then),
          T(checkpoint_v11_reads_no_second_share), T(checkpoint_gas_made_mid_reaction),
          T(checkpoint_v13_colliders_do_not_warm), T(checkpoint_v14_sheets_draw_nothing),
          T(checkpoint_v16_keeps_oven_walls))
