/* snow_plastic.c: the elastoplastic law of Stomakhin et al. 2013 ("A Material
 * Point Method for snow simulation", ACM TOG 32(4) 102, §5): fixed-corotated
 * elasticity whose elastic stretches are clamped, with exponential hardening.
 * Stomakhin et al. 2014 ("Augmented MPM for phase-change and varied
 * materials", ACM TOG 33(4) 138) build their solids on this law; hearth uses
 * it as the Stomakhin-like baseline of Ding et al. 2019 Fig. 17 (§7.5): no
 * leavening gas, no viscoplasticity and no thermal expansion (Ding et al. §2:
 * "neither Stomakhin et al. nor Gao et al." model expansion).
 *
 * ---- elasticity (Stomakhin et al. 2013 §5) --------------------------------
 *   Psi(F_E, F_P) = mu(F_P) |F_E - R_E|_F^2 + lambda(F_P)/2 (J_E - 1)^2,
 * R_E the rotation of the polar decomposition of F_E, J_E = det F_E. Its
 * Kirchhoff stress tau = dPsi/dF_E F_E^T is, with F_E = U Sigma V^T,
 *   tau = U diag(2 mu (s_i^2 - s_i) + lambda (J_E - 1) J_E) U^T:
 * it depends on the left stretch only, so the law lives in the principal
 * frame of b_E = F_E F_E^T (eigenvalues s_i^2, eigenvectors U). Its small
 * strain tangent is linear elasticity with Lame parameters mu and lambda.
 * 2014 splits the energy into a deviatoric and a dilational part so that it
 * can treat the dilation implicitly down to the incompressible limit; with
 * hearth's explicit steps and a compressible solid that split changes
 * nothing the baseline needs, so the 2013 form is kept.
 *
 * ---- plasticity (2013 §5) --------------------------------------------------
 * The elastic singular values are clamped to [1 - theta_c, 1 + theta_s]
 * (critical compression and stretch); what the clamp removes goes into
 * F_P = F_E^-1 F. The paper's reference snow uses theta_c = 2.5e-2 and
 * theta_s = 7.5e-3 (the defaults here). Rate-independent: no viscosity,
 * no yield stress; the elastic stretch itself is bounded.
 *
 * ---- hardening (2013 §5) ------------------------------------------------------
 *   mu(F_P) = mu_0 e^{xi (1 - J_P)},  lambda(F_P) = lambda_0 e^{xi (1 - J_P)},
 * J_P = det F_P, xi = 10 in the reference snow: plastic compaction (J_P < 1)
 * stiffens, plastic dilation softens. mu_0, lambda_0 come from (E, nu) as in
 * elastic.c. xi (1 - J_P) < xi since J_P > 0, so the factor never overflows;
 * below e^-700 (a J_P past 1 + 700/xi) it is held at e^-700, where the
 * stiffness is already zero to double precision, so wave_speed stays > 0.
 *
 * ---- temperature -----------------------------------------------------------
 * None here. In Stomakhin et al. 2014 temperature reaches the mechanics
 * through the phase (solid or fluid, with latent heat) that selects the
 * material parameters; a cookie dough does not melt in an oven, so the
 * baseline is a solid throughout with constant E and nu. Heat still flows
 * (the core's heat transport, which 2014 also has); a scene may give E a
 * temperature curve like any parameter if it wants a phase change.
 *
 * ---- state -----------------------------------------------------------------------
 * Seven doubles: b_E (xx, yy, zz, xy, yz, zx) and J_P. As in cam_clay_dough.c:
 * the trial b_tr = f b_n f^T with f = I + dt grad_v (the same f the core
 * applies to F, so F_E,tr = f F_E,n) is objective as it stands, and the
 * clamp acts on its eigenvalues s_i^2. J_P = det F / J_E is stored from the
 * core's total F after each step, so it never drifts from the deformation.
 *
 * dt = 0 evaluates the stress of the stored state without advancing it.
 */
#include <hearth/material.h>
#include <math.h>

#include <hearth/tensor.h>

enum { P_E, P_NU, P_DENSITY, P_THETA_C, P_THETA_S, P_XI, P_COUNT };

/* Defaults: the snow paper's reference values for theta_c, theta_s and xi;
 * E and density the cookie column of Ding et al. Table 2 (the baseline's
 * material), nu 0.3 as the dough presets (lua/hearth/dough.lua). */
static const hearth_param params[P_COUNT] = {
    [P_E] = {"E", "Pa", "Young's modulus E_0 before hardening (Ding et al. Table 2 cookie: 4e4)", 4e4, 1e-2, 1e12},
    /* Up to 0.49: lambda grows like 1/(1 - 2 nu) */
    [P_NU] = {"nu", "1", "Poisson's ratio", 0.3, 0.0, 0.49},
    [P_DENSITY] = {"density", "kg/m^3", "mass density at rest (Ding et al. Table 2 cookie: 500)", 500, 1e-3, 1e5},
    [P_THETA_C] = {"theta_c", "1",
                   "critical compression: elastic singular values >= 1 - theta_c (Stomakhin et al. 2013: 2.5e-2)", 2.5e-2,
                   0, 0.99},
    [P_THETA_S] = {"theta_s", "1",
                   "critical stretch: elastic singular values <= 1 + theta_s (Stomakhin et al. 2013: 7.5e-3)", 7.5e-3, 0,
                   10},
    [P_XI] = {"xi", "1", "hardening coefficient: moduli x exp(xi (1 - J_P)) (Stomakhin et al. 2013: 10)", 10, 0, 100},
};

enum { S_XX = HEARTH_SYM_XX, S_YY = HEARTH_SYM_YY, S_ZZ = HEARTH_SYM_ZZ, S_XY = HEARTH_SYM_XY, S_YZ = HEARTH_SYM_YZ,
       S_ZX = HEARTH_SYM_ZX, S_JP, S_COUNT };

enum {
    E_INVERTED = 1, /* det F <= 0 or not finite */
    E_STEP = 2,     /* grad_v not finite, or det(I + dt grad_v) <= 0 */
    E_STATE = 3     /* stored b_E or J_P not finite, or b_E not positive definite */
};

/* e^{xi (1 - J_P)}, held at e^-700 and above (header). */
static double hardening(const double *p, double jp) { return exp(fmax(p[P_XI] * (1 - jp), -700.0)); }

static void init(const double *p, double *state) {
    (void)p;
    state[S_XX] = state[S_YY] = state[S_ZZ] = 1;
    state[S_XY] = state[S_YZ] = state[S_ZX] = 0;
    state[S_JP] = 1;
}

static int stress(hearth_point *pt, double tau[9]) {
    const double *prm = pt->p;
    const double J = hearth_t3_det(pt->F);
    if (!(J > 0) || !isfinite(J)) return E_INVERTED;
    double *st = pt->state;
    for (int i = 0; i < S_COUNT; i++)
        if (!isfinite(st[i])) return E_STATE;
    if (!(st[S_JP] > 0)) return E_STATE;
    double B[9];
    hearth_sym_to_full(st, B);
    if (pt->dt > 0) { /* trial b_tr = f b_n f^T */
        double f[9], fB[9];
        for (int i = 0; i < 9; i++) f[i] = (i % 4 == 0) + pt->dt * pt->grad_v[i];
        const double jf = hearth_t3_det(f);
        if (!(jf > 0) || !isfinite(jf)) return E_STEP;
        hearth_t3_mul(f, B, fB);
        hearth_t3_mul_abt(fB, f, B);
    }
    double l[3], Q[9], s[3];
    hearth_t3_sym_eigen(B, l, Q);
    if (!(l[0] > 0 && l[1] > 0 && l[2] > 0) || !isfinite(l[0] + l[1] + l[2])) return E_STATE;
    for (int i = 0; i < 3; i++) s[i] = sqrt(l[i]);
    if (pt->dt > 0) {
        /* the clamp of the elastic singular values (2013 §5); F_P takes the rest */
        const double lo = 1 - prm[P_THETA_C], hi = 1 + prm[P_THETA_S];
        for (int i = 0; i < 3; i++) s[i] = fmin(fmax(s[i], lo), hi);
        const double d[3] = {s[0] * s[0], s[1] * s[1], s[2] * s[2]};
        hearth_sym_from_eigen(Q, d, B);
        st[S_XX] = B[0], st[S_YY] = B[4], st[S_ZZ] = B[8];
        st[S_XY] = B[1], st[S_YZ] = B[5], st[S_ZX] = B[2];
        st[S_JP] = J / (s[0] * s[1] * s[2]); /* J_P = J / J_E */
    }
    double mu, lambda;
    hearth_lame(prm[P_E], prm[P_NU], &mu, &lambda);
    const double h = hardening(prm, st[S_JP]);
    const double JE = s[0] * s[1] * s[2];
    const double vol = h * lambda * (JE - 1) * JE;
    const double d[3] = {2 * h * mu * (s[0] * s[0] - s[0]) + vol, 2 * h * mu * (s[1] * s[1] - s[1]) + vol,
                         2 * h * mu * (s[2] * s[2] - s[2]) + vol};
    hearth_sym_from_eigen(Q, d, tau);
    return 0;
}

/* Small-strain P-wave speed sqrt((lambda + 2 mu) h / rho) with the current
 * hardening h: the law's tangent at F_E = I. Within the clamp F_E stays
 * within a few percent of a rotation, so the tangent changes little. */
static double wave_speed(const double *p, const double *state) {
    double mu, lambda;
    hearth_lame(p[P_E], p[P_NU], &mu, &lambda);
    const double h = hardening(p, state && state[S_JP] > 0 ? state[S_JP] : 1.0);
    return sqrt((lambda + 2 * mu) * h / p[P_DENSITY]);
}

static double plastic_J(const double *p, const double *state) {
    (void)p;
    return state ? state[S_JP] : 1.0;
}

static const char *describe_error(int code) {
    switch (code) {
    case E_INVERTED: return "inverted element (det F <= 0)";
    case E_STEP: return "grad_v is not finite, or the step inverts: det(I + dt grad_v) <= 0";
    case E_STATE: return "elastic state b_E or J_P is not finite, or b_E is not positive definite";
    default: return "unknown error";
    }
}

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = "snow_plastic",
    .summary = "fixed-corotated solid with clamped elastic stretch and hardening (Stomakhin et al. 2013 snow law)",
    .params = params,
    .nparams = P_COUNT,
    .state_size = S_COUNT,
    .needs = 0, /* no temperature, gas or expansion (header) */
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
    .plastic_J = plastic_J,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void); /* for -Wmissing-prototypes */
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }
