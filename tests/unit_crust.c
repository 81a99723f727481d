/* unit_crust.c: parameters that follow water content (issue #18): a moisture
 * curve's factor multiplies a parameter (and its temperature curve), an
 * irreversible one remembers the driest state, bad curves are refused with
 * their numbers, and a checkpoint carries both the curve and the memory. The
 * crust's scene-level claims (it dries first, resists more, cracks) are
 * tests/lua/crust_*.lua. */
#include <math.h>
#include <string.h>

#include "material.h"
#include "mpm_fixture.h"
#include "water.h"

/* An elastic block that holds water (evaporation makes the field live), no gravity, one temperature. */
static hearth_scene *crust_scene(int *mat, double evaporation) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 2;
    d.dx = 0.01;
    for (int k = 0; k < 3; k++) d.lo[k] = 0, d.hi[k] = 0.2;
    d.gravity[1] = 0;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NULL;
    const char *n[] = {"E", "nu", "density", "evaporation"};
    const double v[] = {1e4, 0.3, 500, evaporation};
    hearth_error err;
    *mat = hearth_scene_add_material(s, "elastic", n, v, 4, &err);
    if (*mat < 0) fprintf(stderr, "material: %s\n", err.msg);
    return s;
}
static hearth_scene *wet_scene(int *mat) { return crust_scene(mat, 1e-6); }

static int wet_block(hearth_scene *s, int mat, double sat) {
    hearth_body_def bd = hearth_default_body_def();
    const double c[3] = {0.1, 0.1, 0}, h[3] = {0.02, 0.02, 0.5};
    hearth_shape *b = hearth_shape_box(c, h);
    bd.shape = b;
    bd.material = mat;
    bd.ppc = 4;
    bd.jitter = 0;
    bd.saturation = sat;
    hearth_error err;
    const int id = hearth_scene_add_body(s, &bd, &err);
    if (id < 0) fprintf(stderr, "body: %s\n", err.msg);
    hearth_shape_free(b);
    return id;
}

/* Give particle i the moisture ratio r (its water over the water it was given). */
static void set_ratio(hearth_scene *s, int i, double r) {
    const material_slot *ms = &s->mats.slot[pcoli(&s->ps, PC_MAT)[i]];
    pcold(&s->ps, PC_WATER)[i] = r * pcold(&s->ps, PC_SAT0)[i] * ms->core[CP_WATER_DENSITY] * pcold(&s->ps, PC_VOL0)[i];
}

static double param_at(hearth_scene *s, int i, int k) {
    double scratch[MATERIAL_MAX_PARAMS];
    return material_params(&s->mats, &s->ps, pcoli(&s->ps, PC_MAT)[i], i, scratch)[k];
}

/* The factor multiplies E at the particle's ratio; an irreversible curve keeps
 * the driest ratio reached when water returns; a reversible one follows; a
 * temperature curve and a factor multiply. */
TEST(crust_moisture_curve_factor) {
    int m;
    hearth_scene *s = wet_scene(&m);
    CHECK(s != NULL && m >= 0);
    hearth_error err;
    const double x[] = {0.1, 0.5, 1.0}, f[] = {50, 5, 1};
    CHECK(hearth_scene_material_curve_of(s, m, "E", HEARTH_CURVE_MOISTURE, 3, x, f, 1, &err) == HEARTH_OK);
    CHECK(wet_block(s, m, 0.4) >= 0 && s->ps.n > 1);
    CHECK((s->ps.enabled & (1u << PC_DRIED)) && (s->ps.enabled & (1u << PC_WATER)));
    const int kE = params_index(s->mats.slot[m].m, "E");
    /* raw dough: x1 */
    CHECK_NEAR(param_at(s, 0, kE), 1e4, 1e-9);
    /* ratio 0.3: between 0.1 (x50) and 0.5 (x5), linear: x27.5 */
    set_ratio(s, 0, 0.3);
    CHECK_NEAR(param_at(s, 0, kE), 27.5e4, 1e-6);
    water_dried_step(s); /* the step stands at ratio 0.3 */
    CHECK_NEAR(pcold(&s->ps, PC_DRIED)[0], 0.7, 1e-12);
    set_ratio(s, 0, 0.9); /* crumb water diffuses back */
    const double kept = param_at(s, 0, kE);
    water_dried_step(s);
    CHECK_NEAR(pcold(&s->ps, PC_DRIED)[0], 0.7, 1e-12); /* the memory never falls */
    printf("  E at ratio 0.3: %.4g Pa; after the water returns to 0.9: %.4g Pa (irreversible)\n", 27.5e4, kept);
    CHECK_NEAR(kept, 27.5e4, 1e-6);
    /* an untouched particle still reads the raw value */
    CHECK_NEAR(param_at(s, 1, kE), 1e4, 1e-9);
    /* beyond the ends: constant */
    set_ratio(s, 1, 0.0);
    CHECK_NEAR(param_at(s, 1, kE), 50e4, 1e-6);
    hearth_scene_destroy(s);

    /* reversible, on top of a temperature curve: E(T) x f(X/X0) */
    s = wet_scene(&m);
    CHECK(s != NULL && m >= 0);
    const double T[] = {20, 120}, ET[] = {1e4, 3e4};
    CHECK(hearth_scene_material_curve_of(s, m, "E", HEARTH_CURVE_MOISTURE, 3, x, f, 0, &err) == HEARTH_OK);
    CHECK(hearth_scene_material_curve(s, m, "E", 2, T, ET, 0, &err) == HEARTH_OK); /* after the factor: ordered */
    CHECK(s->mats.slot[m].curves[0].of == CURVE_OF_TEMPERATURE && s->mats.slot[m].curves[1].of == CURVE_OF_MOISTURE);
    CHECK(!(s->ps.enabled & (1u << PC_DRIED))); /* a reversible factor needs no memory */
    CHECK(wet_block(s, m, 0.4) >= 0);
    pcold(&s->ps, PC_TEMPERATURE)[0] = 70; /* E(T) = 2e4 */
    set_ratio(s, 0, 0.5);                  /* x5 */
    CHECK_NEAR(param_at(s, 0, kE), 10e4, 1e-6);
    set_ratio(s, 0, 1.0); /* wet again: x1, reversible */
    CHECK_NEAR(param_at(s, 0, kE), 2e4, 1e-6);
    hearth_scene_destroy(s);

    /* without water the ratio is 1: the curve leaves the raw value */
    hearth_scene *dry = fx_scene(2, 0.01, 0, 0.2);
    CHECK(dry != NULL);
    const int me = fx_elastic(dry, 1e4, 0.3, 500);
    CHECK(hearth_scene_material_curve_of(dry, me, "E", HEARTH_CURVE_MOISTURE, 3, x, f, 1, &err) == HEARTH_OK);
    const double c[3] = {0.1, 0.1, 0}, h[3] = {0.02, 0.02, 0};
    CHECK(fx_box(dry, me, c, h, 4, NULL) > 0);
    CHECK(!(dry->ps.enabled & (1u << PC_WATER)));
    CHECK(hearth_scene_step(dry, 3, &err) == HEARTH_OK);
    CHECK_NEAR(param_at(dry, 0, kE), 1e4, 1e-9);
    hearth_scene_destroy(dry);
}

/* Bad curves are refused with the numbers and the range. */
TEST(crust_moisture_curve_refusals) {
    int m;
    hearth_scene *s = wet_scene(&m);
    CHECK(s != NULL && m >= 0);
    hearth_error err;
    const double neg[] = {-0.1, 1}, ok[] = {0.1, 1}, f[] = {10, 1}, zero[] = {0, 1};
    CHECK(hearth_scene_material_curve_of(s, m, "E", HEARTH_CURVE_MOISTURE, 2, neg, f, 1, &err) == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, ">= 0");
    CHECK(hearth_scene_material_curve_of(s, m, "E", HEARTH_CURVE_MOISTURE, 2, ok, zero, 1, &err) == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "factor 0 at moisture ratio 0.1");
    CHECK(hearth_scene_material_curve_of(s, m, "E", (hearth_curve_of)7, 2, ok, f, 1, &err) == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "moisture (1)");
    /* nu <= 0.49 (the elastic plugin's range): 0.3 x 10 leaves it */
    CHECK(hearth_scene_material_curve_of(s, m, "nu", HEARTH_CURVE_MOISTURE, 2, ok, f, 1, &err) == HEARTH_ERR_PARAM);
    printf("  refused: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "outside the range");
    CHECK(!(s->ps.enabled & (1u << PC_DRIED))); /* a refused curve changes nothing */
    CHECK(s->mats.slot[m].ncurves == 0);
    /* one of each kind per parameter; the product with a later temperature curve is checked too */
    CHECK(hearth_scene_material_curve_of(s, m, "E", HEARTH_CURVE_MOISTURE, 2, ok, f, 1, &err) == HEARTH_OK);
    CHECK(hearth_scene_material_curve_of(s, m, "E", HEARTH_CURVE_MOISTURE, 2, ok, f, 1, &err) == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "already has a moisture curve");
    const double T[] = {20, 100}, big[] = {1e4, 2e11}; /* x10 reaches 2e12 > the elastic plugin's E max */
    CHECK(hearth_scene_material_curve(s, m, "E", 2, T, big, 0, &err) == HEARTH_ERR_PARAM);
    printf("  refused: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "moisture factors");
    hearth_scene_destroy(s);
}

/* A checkpoint carries the moisture curve (its flags) and each particle's driest state. */
TEST(crust_moisture_checkpoint_roundtrip) {
    int m;
    hearth_scene *s = wet_scene(&m);
    CHECK(s != NULL && m >= 0);
    hearth_error err;
    const double x[] = {0.1, 1.0}, f[] = {20, 1}, T[] = {20, 100}, ET[] = {1e4, 2e4};
    CHECK(hearth_scene_material_curve_of(s, m, "E", HEARTH_CURVE_MOISTURE, 2, x, f, 1, &err) == HEARTH_OK);
    CHECK(hearth_scene_material_curve(s, m, "E", 2, T, ET, 1, &err) == HEARTH_OK);
    CHECK(wet_block(s, m, 0.4) >= 0);
    for (int i = 0; i < s->ps.n; i += 3) set_ratio(s, i, 0.2);
    water_dried_step(s);
    for (int i = 0; i < s->ps.n; i += 3) set_ratio(s, i, 0.8);
    const int kE = params_index(s->mats.slot[m].m, "E");
    const char *path = "crust_roundtrip.ckpt";
    CHECK(hearth_scene_save(s, path, &err) == HEARTH_OK);
    hearth_scene *r = hearth_scene_load(path, &err);
    if (!r) fprintf(stderr, "load: %s\n", err.msg);
    CHECK(r != NULL);
    if (r) {
        CHECK(hearth_scene_hash(r) == hearth_scene_hash(s));
        CHECK(r->mats.slot[m].ncurves == 2 && r->mats.slot[m].curves[1].of == CURVE_OF_MOISTURE &&
              r->mats.slot[m].curves[1].irreversible);
        int same = r->ps.n == s->ps.n;
        for (int i = 0; same && i < s->ps.n; i++) same = param_at(r, i, kE) == param_at(s, i, kE);
        printf("  E of a dried particle: %.4g Pa saved, %.4g Pa restored\n", param_at(s, 0, kE), param_at(r, 0, kE));
        CHECK(same && param_at(r, 0, kE) > 10e4);
        hearth_scene_destroy(r);
    }
    remove(path);
    hearth_scene_destroy(s);
}

/* A stateless plugin (elastic) whose E a curve raises is asked its wave speed
 * per particle: the step limit follows the dried E x 100, not the cached base
 * value (before: c_max stayed at the base, the stiffened block outran its
 * step and inverted). */
TEST(crust_curve_wave_speed_per_particle) {
    int m;
    hearth_scene *s = wet_scene(&m);
    CHECK(s != NULL && m >= 0);
    hearth_error err;
    const double x[] = {0.1, 1.0}, f[] = {100, 1};
    CHECK(hearth_scene_material_curve_of(s, m, "E", HEARTH_CURVE_MOISTURE, 2, x, f, 0, &err) == HEARTH_OK);
    CHECK(wet_block(s, m, 0.4) >= 0);
    for (int i = 0; i < s->ps.n; i++) set_ratio(s, i, 0.05);
    CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
    const material_slot *ms = &s->mats.slot[m];
    double p[MATERIAL_MAX_PARAMS];
    memcpy(p, ms->params, sizeof(double) * (size_t)ms->m->nparams);
    p[params_index(ms->m, "E")] *= 100;
    const double dried = ms->m->wave_speed(p, NULL);
    printf("  largest wave speed %.6g m/s; the plugin's at E x 100 %.6g, at E %.6g (the cached value)\n", s->c_max, dried,
           ms->wave_speed);
    CHECK(ms->wave_per_point);
    CHECK_NEAR(s->c_max, dried, 1e-9 * dried);
    hearth_scene_destroy(s);
}

/* The door's per-run parameters (material_run_params, material_batch.c)
 * give material_params' bits at every particle: a parameter with a
 * temperature and a moisture curve, one with only a moisture curve, one with
 * only a temperature curve, at temperatures and moisture ratios that differ
 * per particle; and in a scene without water, where the factors are folded
 * once per run. */
static int run_params_match(hearth_scene *s, int m, int *checked) {
    const material_slot *ms = &s->mats.slot[m];
    const int np = ms->m->nparams, n = s->ps.n;
    material_run_params rp;
    int bad = 0;
    for (int i0 = 0; i0 < n; i0 += 5) { /* runs of up to 7 points from every fifth particle */
        material_run_params_init(&rp, ms, &s->ps);
        for (int i = i0; i < n && i < i0 + 7; i++) {
            double scratch[MATERIAL_MAX_PARAMS];
            const double *want = material_params(&s->mats, &s->ps, m, i, scratch);
            const double *got = material_run_params_at(&rp, ms, &s->ps, i);
            if (memcmp(want, got, sizeof(double) * (size_t)np)) {
                if (!bad) fprintf(stderr, "  particle %d (run from %d): parameters differ from material_params\n", i, i0);
                bad++;
            }
            (*checked)++;
        }
    }
    return bad;
}

TEST(crust_run_params_match_resolve) {
    for (int wet = 1; wet >= 0; wet--) {
        int m;
        hearth_scene *s = crust_scene(&m, wet ? 1e-6 : 0); /* no evaporation: no water field, every ratio 1 */
        CHECK(s != NULL && m >= 0);
        hearth_error err;
        const double x[] = {0.1, 0.5, 1.0}, f[] = {50, 5, 1}, g[] = {0.5, 0.9, 1.2};
        const double T[] = {20, 70, 120}, ET[] = {1e4, 2e4, 3e4}, rho[] = {500, 450, 400};
        /* irreversible with water (the driest ratio reached); without, a reversible one keeps PC_DRIED off */
        CHECK(hearth_scene_material_curve_of(s, m, "E", HEARTH_CURVE_MOISTURE, 3, x, f, wet, &err) == HEARTH_OK);
        CHECK(hearth_scene_material_curve_of(s, m, "nu", HEARTH_CURVE_MOISTURE, 3, x, g, 0, &err) == HEARTH_OK);
        CHECK(hearth_scene_material_curve(s, m, "E", 3, T, ET, 1, &err) == HEARTH_OK);
        CHECK(hearth_scene_material_curve(s, m, "density", 3, T, rho, 0, &err) == HEARTH_OK);
        CHECK(wet_block(s, m, wet ? 0.4 : NAN) >= 0 && s->ps.n > 20); /* NAN: the body brings no water */
        CHECK(!(s->ps.enabled & (1u << PC_WATER)) == !wet);
        double *Tp = pcold(&s->ps, PC_TEMPERATURE), *Tmax = pcold(&s->ps, PC_TEMP_MAX);
        for (int i = 0; i < s->ps.n; i++) {
            Tp[i] = 10 + 1.3 * i;
            Tmax[i] = Tp[i] + (i % 3) * 7;
            if (wet) set_ratio(s, i, 0.05 + 0.011 * (i % 97));
        }
        if (wet) water_dried_step(s);
        for (int i = 0; wet && i < s->ps.n; i += 2) set_ratio(s, i, 1.0); /* water back at every other particle */
        int checked = 0;
        const int bad = run_params_match(s, m, &checked);
        printf("  %s: %d of %d particle parameter sets differ from material_params\n", wet ? "with water" : "without water",
               bad, checked);
        CHECK(bad == 0 && checked >= s->ps.n);
        hearth_scene_destroy(s);
    }
}

TEST_MAIN(T(crust_moisture_curve_factor), T(crust_run_params_match_resolve), T(crust_moisture_curve_refusals), T(crust_moisture_checkpoint_roundtrip),
          T(crust_curve_wave_speed_per_particle))
