/* unit_mixing.c: dynamic mixing ratios (Nagasawa et al. 2019 eq. 43-44) and
 * the per-particle blend of a mixture's constituents. */
#include <math.h>

#include "mixing.h"
#include "mpm_fixture.h"
#include "plugins.h"

/* honey-like and mayo-like parameter sets (Table 1 magnitudes) */
static const char *const NAMES[] = {"sigma_y", "eta", "h", "density"};
static const double HONEY[] = {0.0, 8.0, 1.0, 1400}, MAYO[] = {70.8, 30.5, 0.442, 950};

static int add_mix(hearth_scene *s, hearth_error *err) {
    const char *const *names[2] = {NAMES, NAMES};
    const double *values[2] = {HONEY, MAYO};
    const int n[2] = {4, 4};
    return hearth_scene_add_mixture(s, "von_mises_sauce", 2, names, values, n, err);
}

static int add_box(hearth_scene *s, int m, const double c[3], const double h[3], double r0, double r1, int fixed) {
    hearth_shape *box = hearth_shape_box(c, h);
    hearth_body_def b = hearth_default_body_def();
    b.shape = box, b.material = m, b.jitter = 0, b.fixed = fixed;
    b.ratios[0] = r0, b.ratios[1] = r1;
    hearth_error err;
    const int id = hearth_scene_add_body(s, &b, &err);
    if (id < 0) fprintf(stderr, "body: %s\n", err.msg);
    hearth_shape_free(box);
    return id;
}

/* The plugin's own blend at ratios (a, 1 - a). */
static void blend_at(const hearth_scene *s, int m, double a, double *out) {
    const hearth_material *mat = s->mats.slot[m].m;
    const double *pk[2] = {s->mats.slot[m].mix_params, s->mats.slot[m].mix_params + mat->nparams};
    const double alpha[2] = {a, 1 - a};
    CHECK(mat->blend(2, alpha, pk, out) == 0);
}

/* One body of a 30:70 mixture flows under gravity: its ratios stay 30:70
 * exactly (the weights are a partition of unity) and every particle's
 * parameters are the plugin's blend at 30:70. */
TEST(mixing_uniform_ratios_exact) {
    hearth_scene *s = fx_scene(2, 1.0 / 48, 0, 1);
    hearth_error err;
    const int m = add_mix(s, &err);
    CHECK(m >= 0);
    const double c[3] = {0.5, 0.3, 0}, h[3] = {0.15, 0.1, 0};
    CHECK(add_box(s, m, c, h, 3, 7, 0) >= 0); /* ratios need not be normalised */
    CHECK(hearth_scene_step(s, 30, &err) == HEARTH_OK);
    double want[SCENE_MAX_PARAMS], scratch[SCENE_MAX_PARAMS], worst_a = 0, worst_p = 0, worst_m = 0;
    blend_at(s, m, 0.3, want);
    const int np = s->mats.slot[m].m->nparams, di = s->mats.slot[m].density_index;
    for (int i = 0; i < s->ps.n; i++) {
        const double *a = pcold(&s->ps, PC_MIXD) + MIX_MAX * i;
        worst_a = fmax(worst_a, fmax(fabs(a[0] - 0.3), fabs(a[1] - 0.7)));
        const double *p = material_params(&s->mats, &s->ps, m, i, scratch);
        for (int k = 0; k < np; k++) worst_p = fmax(worst_p, fabs(p[k] - want[k]) / fmax(fabs(want[k]), 1e-300));
        worst_m = fmax(worst_m, fabs(pcold(&s->ps, PC_MASS)[i] / (want[di] * pcold(&s->ps, PC_VOL0)[i]) - 1));
    }
    hearth_stats st;
    hearth_scene_stats(s, &st);
    printf("  %d particles after %ld steps (max speed %.3g m/s): max |ratio - 30:70| = %.2g, max relative parameter "
           "difference from the blend %.2g, mass from the blend's density %.2g\n",
           st.particles, st.step, st.max_speed, worst_a, worst_p, worst_m);
    CHECK(st.max_speed > 0.01); /* it moved */
    CHECK(worst_a < 1e-12);
    CHECK(worst_p < 1e-12);
    CHECK(worst_m < 1e-12);
    hearth_scene_destroy(s);
}

/* Pure honey against pure mayo: beyond 3 dx of the interface (a node gathers
 * from 1.5 dx, a particle from its nodes 1.5 dx away) the ratios stay pure,
 * across it they grade over the kernel's width; every particle's ratios are a
 * convex combination (in [0, 1], summing to 1). */
TEST(mixing_interface_grades) {
    const double dx = 1.0 / 48;
    hearth_scene *s = fx_scene(2, dx, 0, 1);
    s->def.gravity[1] = 0;
    hearth_error err;
    const int m = add_mix(s, &err);
    const double c1[3] = {0.4, 0.5, 0}, c2[3] = {0.6, 0.5, 0}, h[3] = {0.1, 0.1, 0};
    CHECK(add_box(s, m, c1, h, 1, 0, 1) >= 0);
    CHECK(add_box(s, m, c2, h, 0, 1, 1) >= 0);
    CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
    int far_pure = 1, convex = 1, mixed = 0;
    for (int i = 0; i < s->ps.n; i++) {
        const double x = pcold(&s->ps, PC_X)[3 * i], *a = pcold(&s->ps, PC_MIXD) + MIX_MAX * i;
        convex &= a[0] >= -1e-15 && a[1] >= -1e-15 && fabs(a[0] + a[1] - 1) < 1e-12;
        if (fabs(x - 0.5) > 3 * dx) far_pure &= (x < 0.5 ? a[0] : a[1]) > 1 - 1e-12;
        else if (a[0] > 0.05 && a[1] > 0.05) mixed++;
    }
    printf("  %d particles near the interface carry both constituents\n", mixed);
    CHECK(far_pure);
    CHECK(convex);
    CHECK(mixed > 0);
    hearth_scene_destroy(s);
}

TEST(mixing_bad_input) {
    hearth_scene *s = fx_scene(2, 1.0 / 32, 0, 1);
    hearth_error err;
    const char *const *names[2] = {NAMES, NAMES};
    const double *values[2] = {HONEY, MAYO};
    const int n[2] = {4, 4};
    CHECK(hearth_scene_add_mixture(s, "von_mises_sauce", 1, names, values, n, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "valid range [2, 8]");
    const char *en[] = {"E"};
    const double ev[] = {1e4};
    const char *const *enames[2] = {en, en};
    const double *evalues[2] = {ev, ev};
    const int en1[2] = {1, 1};
    CHECK(hearth_scene_add_mixture(s, "elastic", 2, enames, evalues, en1, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "no blend callback");
    const double bad[] = {-1, 30.5, 0.442, 950};
    const double *bvalues[2] = {HONEY, bad};
    CHECK(hearth_scene_add_mixture(s, "von_mises_sauce", 2, names, bvalues, n, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "mixture constituent 2");
    hearth_scene_destroy(s);

    s = fx_scene(2, 1.0 / 32, 0, 1);
    const int m = add_mix(s, &err);
    CHECK(m >= 0);
    CHECK(add_mix(s, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "already holds one");
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.1, 0.1, 0};
    CHECK(add_box(s, m, c, h, 0, 0, 0) < 0);
    hearth_shape *box = hearth_shape_box(c, h);
    hearth_body_def b = hearth_default_body_def();
    b.shape = box, b.material = m;
    CHECK(hearth_scene_add_body(s, &b, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "give its mixing ratios");
    b.ratios[0] = 1, b.ratios[2] = 0.5; /* a third ratio for a two-part mixture */
    CHECK(hearth_scene_add_body(s, &b, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "mixing ratio 3");
    CHECK(hearth_scene_particle_count(s) == 0);
    b.ratios[2] = 0;
    CHECK(hearth_scene_add_body(s, &b, &err) >= 0);
    hearth_shape_free(box);
    CHECK(hearth_scene_save(s, "/tmp/hearth_mix_never.ck", &err) != HEARTH_OK);
    CHECK_STR_CONTAINS(err.msg, "dynamic mixture");
    hearth_scene_destroy(s);
}

TEST_MAIN(T(mixing_uniform_ratios_exact), T(mixing_interface_grades), T(mixing_bad_input))
