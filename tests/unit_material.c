/* unit_material.c: the material door (core/sim/material.h) gives, for every
 * in-tree plugin, exactly the plugin's own stress plus the core's documented
 * coupling terms (Ding et al. 2019 eq. 10, 13, 14), and fills the point with
 * what the caller supplies. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "test.h"
#define PLUGIN_FIXTURE_SEED 0x6d6174657269616cULL
#include "plugin_fixture.h"
#include "material.h"
#include "params.h"

static const char *const in_tree[] = {"elastic", "newtonian", "cam_clay_dough", "snow_plastic", "von_mises_sauce", "maxwell_sph"};
#define N_IN_TREE (int)(sizeof in_tree / sizeof in_tree[0])

/* A deformation large enough that the plastic laws yield in one step, so J^P != 1. */
static void deformation(double F[9], double L[9], double dt) {
    const double f[9] = {1.25, 0.2, 0, 0.05, 0.85, 0, 0, 0, 1.02};
    for (int a = 0; a < 9; a++) F[a] = f[a], L[a] = (f[a] - (a % 4 == 0)) / dt;
}

static void defaults(const hearth_material *m, double *p) {
    for (int i = 0; i < m->nparams; i++) p[i] = m->params[i].def;
}

static double *fresh_state(const hearth_material *m, const double *p) {
    double *st = calloc((size_t)(m->state_size > 0 ? m->state_size : 1), sizeof(double));
    m->init(p, st);
    return st;
}

/* With no coupling asked for, the door is the plugin: the same tau, bit for
 * bit, and the point carries the temperature, porosity and saturation given. */
TEST(door_plugin_only_each_plugin) {
    for (int k = 0; k < N_IN_TREE; k++) {
        const hearth_material *m = load_material(in_tree[k]);
        CHECK(m != NULL);
        if (!m) continue;
        double p[256], F[9], L[9], tau_direct[9], tau_door[9];
        const double dt = 1e-3;
        defaults(m, p);
        deformation(F, L, dt);
        double *s1 = fresh_state(m, p), *s2 = fresh_state(m, p);
        hearth_point a = {.dt = dt, .temperature = 35, .porosity = 0.1, .saturation = 0.4, .p = p, .state = s1};
        memcpy(a.grad_v, L, sizeof L), memcpy(a.F, F, sizeof a.F);
        hearth_point b = a;
        b.state = s2;
        b.temperature = b.porosity = b.saturation = -1; /* the door must overwrite these */
        const int rd = m->stress(&a, tau_direct);
        const material_env env = {.temperature = 35, .porosity = 0.1, .saturation = 0.4};
        const int rg = material_point_eval(m, NULL, &b, &env, tau_door);
        plugin_call_leave();
        CHECK(rd == 0 && rg == 0);
        CHECK(b.temperature == 35 && b.porosity == 0.1 && b.saturation == 0.4);
        CHECK(memcmp(tau_direct, tau_door, sizeof tau_door) == 0);
        CHECK(m->state_size == 0 || memcmp(s1, s2, sizeof(double) * (size_t)m->state_size) == 0);
        printf("  %-16s tau_xy %.6g Pa, door and plugin agree bit for bit\n", m->name, tau_door[1]);
        free(s1), free(s2);
    }
}

/* With gas, water and thermal expansion, the door adds exactly
 *   -J c_w (s - s_0)                        (eq. 14, water)
 *   -n^g R (theta + 273.15) / n^p(J^P_1)   (eq. 13, gas, porosity after the step's flow)
 *   -c lambda (theta - theta_ref)          (eq. 10 as a thermal strain: the same at every J^E)
 * to the diagonal, and passes the plastic porosity n^p = 1 - (1 - n^p_0) / J^P_0 (§5.4's gas volume fraction;
 * gas.h) to the plugin. */
TEST(door_core_terms_each_plugin) {
    for (int k = 0; k < N_IN_TREE; k++) {
        const hearth_material *m = load_material(in_tree[k]);
        CHECK(m != NULL);
        if (!m) continue;
        double p[256], F[9], L[9], tau_direct[9], tau_door[9], core[CP_COUNT] = {0};
        core[CP_POROSITY0] = 0.2, core[CP_EXPANSION] = 3e3, core[CP_REFERENCE_T] = 20, core[CP_WATER_STIFFNESS] = 5e4;
        const double dt = 1e-3, T = 80, sat = 0.6, sat0 = 0.5, ng = 2.0;
        defaults(m, p);
        deformation(F, L, dt);
        const double J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
                         F[2] * (F[3] * F[7] - F[4] * F[6]);
        double *s1 = fresh_state(m, p), *s2 = fresh_state(m, p);
        const double JP0 = m->plastic_J ? m->plastic_J(p, s1) : 1.0;
        double np0 = 1 - (1 - core[CP_POROSITY0]) / JP0;
        np0 = fmin(fmax(np0, 1e-6), 0.999999);
        hearth_point a = {.dt = dt, .temperature = T, .porosity = np0, .saturation = sat, .p = p, .state = s1};
        memcpy(a.grad_v, L, sizeof L), memcpy(a.F, F, sizeof a.F);
        hearth_point b = a;
        b.state = s2;
        const int rd = m->stress(&a, tau_direct);
        const double JP1 = m->plastic_J ? m->plastic_J(p, s1) : 1.0;
        double np1 = m->plastic_J ? 1 - (1 - core[CP_POROSITY0]) / JP1 : np0;
        np1 = fmin(fmax(np1, 1e-6), 0.999999);
        const double tw = -J * core[CP_WATER_STIFFNESS] * (sat - sat0);
        const double tg = -ng * 8.314462618 * (T + 273.15) / np1;
        const double th = core[CP_EXPANSION] * (T - core[CP_REFERENCE_T]);
        const double gas_col[2] = {0, ng}, s0_col[2] = {0, sat0};
        const material_env env = {.flags = MATERIAL_POROSITY_PLASTIC | MATERIAL_EXPANSION, .J = J, .temperature = T,
                                  .saturation = sat, .gas = gas_col, .saturation0 = s0_col, .index = 1};
        const int rg = material_point_eval(m, core, &b, &env, tau_door);
        plugin_call_leave();
        CHECK(rd == 0 && rg == 0);
        CHECK(b.porosity == np0);
        double worst = 0;
        for (int i = 0; i < 9; i++) {
            const double want = tau_direct[i] + (i % 4 == 0 ? tw + tg - th : 0.0);
            worst = fmax(worst, fabs(tau_door[i] - want) / fmax(1.0, fabs(want)));
        }
        printf("  %-16s J^P %.6f -> %.6f, terms water %.6g gas %.6g expansion %.6g Pa, worst relative difference %.2e\n",
               m->name, JP0, JP1, tw, tg, -th, worst);
        CHECK(worst <= 1e-15);
        free(s1), free(s2);
    }
}

/* A plugin code comes back as is; with MATERIAL_ZERO_FAILED the point carries
 * only the core's terms (MPM's rule), without it tau is what the plugin left. */
TEST(door_failure_codes) {
    char path[4096];
    const char *dir = getenv("HEARTH_TEST_PLUGIN_DIR");
    CHECK(dir != NULL);
    if (!dir) return;
    snprintf(path, sizeof path, "%s/hearth_err_code.so", dir);
    const hearth_material *m = load_material(path);
    CHECK(m != NULL);
    if (!m) return;
    double p[256], F[9], L[9], tau[9], core[CP_COUNT] = {0};
    core[CP_EXPANSION] = 1e3, core[CP_REFERENCE_T] = 20;
    defaults(m, p);
    deformation(F, L, 1e-3);
    hearth_point pt = {.dt = 1e-3, .p = p};
    memcpy(pt.grad_v, L, sizeof L), memcpy(pt.F, F, sizeof pt.F);
    for (int i = 0; i < 9; i++) tau[i] = 42;
    material_env env = {.flags = MATERIAL_ZERO_FAILED | MATERIAL_EXPANSION, .J = 1, .temperature = 30, .saturation = NAN, .porosity = NAN};
    CHECK(material_point_eval(m, core, &pt, &env, tau) == 7);
    for (int i = 0; i < 9; i++) CHECK(tau[i] == (i % 4 == 0 ? -1e4 : 0.0));
    for (int i = 0; i < 9; i++) tau[i] = 42;
    env.flags = 0;
    CHECK(material_point_eval(m, NULL, &pt, &env, tau) == 7);
    for (int i = 0; i < 9; i++) CHECK(tau[i] == 42);
    plugin_call_leave();
}

TEST_MAIN(T(door_plugin_only_each_plugin), T(door_core_terms_each_plugin), T(door_failure_codes))
