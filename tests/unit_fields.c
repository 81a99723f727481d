/* unit_fields.c: each field module's state has its own lifetime (issue #16:
 * "each field owns its state"). The init of every state allocates nothing,
 * and its free releases exactly the bytes the state holds (alloc.h counts
 * every byte), leaving the state as init left it; the scene's destroy then
 * finds nothing more to free. */
#include <string.h>

#include "alloc.h"
#include "boundary.h"
#include "material.h"
#include "mixing.h"
#include "mpm_fixture.h"
#include "thermal.h"
#include "water.h"

/* A mixture (von_mises_sauce, honey and mayo) that loses water to an oven,
 * with a temperature curve, stepped with the implicit heat solve: every field
 * state holds memory afterwards. */
static hearth_scene *busy_scene(void) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 2;
    d.dx = 1.0 / 32;
    d.oven_temperature = 180;
    d.oven_beta = 10;
    d.heat_implicit = 1;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NULL;
    static const char *const N0[] = {"sigma_y", "eta", "h", "density", "water_diffusivity", "evaporation"};
    static const char *const N1[] = {"sigma_y", "eta", "h", "density"};
    static const double HONEY[] = {0.0, 8.0, 1.0, 1400, 1e-9, 1e-4}, MAYO[] = {70.8, 30.5, 0.442, 950};
    const char *const *names[2] = {N0, N1};
    const double *values[2] = {HONEY, MAYO};
    const int n[2] = {6, 4};
    hearth_error err;
    const int m = hearth_scene_add_mixture(s, "von_mises_sauce", 2, names, values, n, &err);
    CHECK(m >= 0);
    if (m < 0) {
        fprintf(stderr, "mixture: %s\n", err.msg);
        hearth_scene_destroy(s);
        return NULL;
    }
    const double T[] = {20, 100}, v[] = {8, 2};
    CHECK(hearth_scene_material_curve(s, m, "eta", 2, T, v, 0, &err) == HEARTH_OK);
    hearth_shape *box = hearth_shape_box((const double[3]){0.5, 0.3, 0}, (const double[3]){0.15, 0.1, 0});
    hearth_body_def b = hearth_default_body_def();
    b.shape = box, b.material = m, b.ratios[0] = 1, b.ratios[1] = 1;
    CHECK(hearth_scene_add_body(s, &b, &err) >= 0);
    hearth_shape_free(box);
    CHECK(hearth_scene_step(s, 3, &err) == HEARTH_OK);
    return s;
}

/* Bytes a material table holds, from its own bookkeeping. */
static size_t table_bytes(const material_table *t) {
    size_t b = sizeof(material_slot) * (size_t)t->cap;
    for (int i = 0; i < t->n; i++) {
        const material_slot *ms = &t->slot[i];
        const size_t np = (size_t)(ms->m->nparams > 0 ? ms->m->nparams : 1);
        b += sizeof(double) * np + sizeof(curve) * (size_t)ms->ncurves + sizeof(double) * np * (size_t)ms->mix_k;
        for (int k = 0; k < ms->ncurves; k++) b += 2 * sizeof(double) * (size_t)ms->curves[k].n;
    }
    return b;
}

TEST(fields_init_allocates_nothing) {
    const size_t b0 = hearth_bytes_allocated();
    material_table t;
    thermal_state h;
    boundary_state bd;
    water_state w;
    mixing_state x;
    material_table_init(&t);
    thermal_init(&h);
    boundary_init(&bd);
    water_init(&w);
    mixing_init(&x);
    CHECK(hearth_bytes_allocated() == b0);
    CHECK(t.n == 0 && t.cap == 0 && t.slot == NULL);
    CHECK(h.bnd_cap == 0 && h.cg_cap == 0 && h.bnd_coef == NULL && h.cg_partial == NULL);
    CHECK(bd.area == NULL && bd.blocks == NULL);
    CHECK(w.lost == 0 && w.limits_valid == 0);
    CHECK(x.mat == -1 && x.nodes == NULL && x.cap == 0);
    /* freeing an empty state is a no-op, so a scene that never used a field frees it alike */
    material_table_free(&t);
    thermal_free(&h);
    boundary_free(&bd);
    water_free(&w);
    mixing_free(&x);
    CHECK(hearth_bytes_allocated() == b0);
}

TEST(fields_free_releases_state) {
    hearth_scene_destroy(busy_scene()); /* loads and caches the plugin, which stays */
    const size_t b0 = hearth_bytes_allocated();
    hearth_scene *s = busy_scene();
    CHECK(s != NULL);
    if (!s) return;

    /* bnd_coef and bnd_temp; bnd_surf only when browning reads the oven's surface (this scene has no browning) */
    const size_t nb = s->heat.bnd_surf ? 3 : 2;
    /* and flip_bound.c's per-particle scratch (two doubles a particle), which the heat's state owns */
    size_t held = sizeof(double) * (nb * (size_t)s->heat.bnd_cap + (size_t)s->heat.cg_cap + 2 * (size_t)s->heat.bound_cap),
           b = hearth_bytes_allocated();
    printf("  heat holds %zu bytes (%d CG iterations last step)\n", held, s->heat.cg_iterations);
    CHECK(held > 0 && s->heat.cg_iterations > 0);
    thermal_free(&s->heat);
    CHECK(hearth_bytes_allocated() == b - held);
    CHECK(s->heat.bnd_coef == NULL && s->heat.bnd_surf == NULL && s->heat.cg_partial == NULL && s->heat.bnd_cap == 0 &&
          s->heat.cg_iterations == 0);

    held = sizeof(double) * 2 * (size_t)s->boundary.area_cap + (size_t)s->boundary.blocks_cap, b = hearth_bytes_allocated();
    printf("  boundary holds %zu bytes\n", held);
    CHECK(held > 0);
    boundary_free(&s->boundary);
    CHECK(hearth_bytes_allocated() == b - held);
    CHECK(s->boundary.area == NULL && s->boundary.depth == NULL && s->boundary.blocks == NULL);

    held = sizeof(double) * s->mix.cap, b = hearth_bytes_allocated();
    printf("  mixing holds %zu bytes (mixture material %d)\n", held, s->mix.mat);
    CHECK(held > 0 && s->mix.mat >= 0);
    mixing_free(&s->mix);
    CHECK(hearth_bytes_allocated() == b - held);
    CHECK(s->mix.nodes == NULL && s->mix.mat == -1);

    b = hearth_bytes_allocated();
    printf("  water lost %.3g kg/m so far\n", s->water.lost);
    CHECK(s->water.lost > 0 && s->water.limits_valid);
    water_free(&s->water); /* holds no memory */
    CHECK(hearth_bytes_allocated() == b);
    CHECK(s->water.lost == 0 && !s->water.limits_valid);

    held = table_bytes(&s->mats), b = hearth_bytes_allocated();
    printf("  materials hold %zu bytes (%d slots)\n", held, s->mats.n);
    CHECK(held > 0 && s->mats.n == 1 && s->mats.slot[0].ncurves == 1 && s->mats.slot[0].mix_k == 2);
    material_table_free(&s->mats);
    CHECK(hearth_bytes_allocated() == b - held);
    CHECK(s->mats.slot == NULL && s->mats.n == 0 && s->mats.cap == 0);

    /* the scene's own free calls each field's free again: nothing twice, nothing left */
    hearth_scene_destroy(s);
    CHECK(hearth_bytes_allocated() == b0);
}

TEST_MAIN(T(fields_init_allocates_nothing), T(fields_free_releases_state))
