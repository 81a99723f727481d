/* memo_mismatch.c: test fixture. The neo-Hookean law of scalars_mismatch.c
 * with a stress_block that keeps log J in the point's memo (<hearth/material.h>
 * rule 10) keyed on nothing: once an entry is written it is read for any J.
 * With the memo NULL, zeroed, or warm from the same block it gives stress's
 * bits; with entries swapped between points it gives another point's log J,
 * which `hearth plugin check` must catch, naming the memo and the point
 * (plugin_check_memo_keyed). */
#include <hearth/material.h>
#include <hearth/tensor.h>
#include <math.h>
#include <stddef.h>

enum { P_E, P_NU, P_DENSITY, P_COUNT };

static const hearth_param params[P_COUNT] = {
    [P_E] = {"E", "Pa", "Young's modulus", 1e4, 1e-2, 1e12},
    [P_NU] = {"nu", "1", "Poisson's ratio", 0.3, 0.0, 0.499},
    [P_DENSITY] = {"density", "kg/m^3", "mass density at rest", 1000, 1e-3, 1e5},
};

static void init(const double *p, double *state) {
    (void)p;
    (void)state;
}

static int stress(hearth_point *pt, double tau[9]) {
    const double *F = pt->F;
    const double J = hearth_t3_det(F);
    if (!(J > 0)) return 1;
    double mu, lambda;
    hearth_lame(pt->p[P_E], pt->p[P_NU], &mu, &lambda);
    const double vol = lambda * log(J);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            const double b = F[3 * r] * F[3 * c] + F[3 * r + 1] * F[3 * c + 1] + F[3 * r + 2] * F[3 * c + 2];
            tau[3 * r + c] = mu * (b - (r == c)) + (r == c ? vol : 0.0);
        }
    return 0;
}

/* log J of point j through its memo, keyed on nothing: m[1] once written is read for any J (the slip) */
static double log_unkeyed(double *m, double J) {
    if (m[0] != 0) return m[1];
    m[0] = 1, m[1] = log(J);
    return m[1];
}

static int stress_block(const hearth_block *b, double *const tau[9], int *code) {
    int bad = 0;
    for (int j = 0; j < b->n; j++) {
        double p[P_COUNT], F[9];
        for (int k = 0; k < P_COUNT; k++) p[k] = hearth_block_param(b, k, j);
        for (int c = 0; c < 9; c++) F[c] = b->F[c][j];
        const double J = hearth_t3_det(F);
        code[j] = !(J > 0);
        bad += code[j];
        if (code[j]) continue;
        double mu, lambda;
        hearth_lame(p[P_E], p[P_NU], &mu, &lambda);
        const double vol = lambda * (b->memo ? log_unkeyed(b->memo + (size_t)j * b->memo_stride, J) : log(J));
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) {
                const double bb = F[3 * r] * F[3 * c] + F[3 * r + 1] * F[3 * c + 1] + F[3 * r + 2] * F[3 * c + 2];
                tau[3 * r + c][j] = mu * (bb - (r == c)) + (r == c ? vol : 0.0);
            }
    }
    return bad;
}

static double wave_speed(const double *p, const double *state) {
    (void)state;
    double mu, lambda;
    hearth_lame(p[P_E], p[P_NU], &mu, &lambda);
    return sqrt((lambda + 2 * mu) / p[P_DENSITY]);
}

static const char *describe_error(int code) { return code == 1 ? "inverted element (det F <= 0)" : "unknown error"; }

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = "memo_mismatch",
    .summary = "fixture: a stress_block whose memo is keyed on nothing",
    .params = params,
    .nparams = P_COUNT,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
    .stress_block = stress_block,
    .needs = HEARTH_NEEDS_MEMO,
    .memo_size = 2,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }
