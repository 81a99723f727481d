/* scalars_mismatch.c: test fixture. The neo-Hookean law of batch_mismatch.c
 * with a faithful stress_block (stress point by point), whose scalars_block
 * (<hearth/material.h> rule 9) computes the wave speed as
 * sqrt(lambda / rho + 2 mu / rho) for the one-point sqrt((lambda + 2 mu) / rho):
 * the same speed on paper, other bits on most points, which `hearth plugin
 * check` must catch, naming the point and the scalar
 * (plugin_check_scalars_matches). */
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

static int stress_block(const hearth_block *b, double *const tau[9], int *code) {
    int bad = 0;
    for (int j = 0; j < b->n; j++) {
        double p[P_COUNT], t[9];
        for (int k = 0; k < P_COUNT; k++) p[k] = hearth_block_param(b, k, j);
        hearth_point pt = {.dt = b->dt, .p = p, .state = NULL, .dim = b->dim};
        for (int c = 0; c < 9; c++) pt.F[c] = b->F[c][j], pt.grad_v[c] = b->grad_v[c][j];
        code[j] = stress(&pt, t);
        bad += code[j] != 0;
        for (int c = 0; c < 9; c++) tau[c][j] = t[c];
    }
    return bad;
}

static double wave_speed(const double *p, const double *state) {
    (void)state;
    double mu, lambda;
    hearth_lame(p[P_E], p[P_NU], &mu, &lambda);
    return sqrt((lambda + 2 * mu) / p[P_DENSITY]);
}

static void scalars_block(const hearth_block *b, double *const out[HEARTH_SCALAR_COUNT]) {
    if (!out[HEARTH_SCALAR_WAVE_SPEED]) return;
    for (int j = 0; j < b->n; j++) {
        double mu, lambda;
        const double rho = hearth_block_param(b, P_DENSITY, j);
        hearth_lame(hearth_block_param(b, P_E, j), hearth_block_param(b, P_NU, j), &mu, &lambda);
        out[HEARTH_SCALAR_WAVE_SPEED][j] = sqrt(lambda / rho + 2 * mu / rho); /* the slip */
    }
}

static const char *describe_error(int code) { return code == 1 ? "inverted element (det F <= 0)" : "unknown error"; }

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = "scalars_mismatch",
    .summary = "fixture: a scalars_block whose wave speed differs from wave_speed in the last bits",
    .params = params,
    .nparams = P_COUNT,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
    .stress_block = stress_block,
    .scalars_block = scalars_block,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }
