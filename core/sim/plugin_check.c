/* plugin_check.c: the conformance battery behind `hearth plugin check`.
 *
 * Each check drives the plugin's callbacks directly, with no scene, so a
 * plugin author learns exactly which property fails and by how much. The
 * battery is deterministic: random deformations come from a fixed-seed
 * splitmix64, so a failure reproduces run after run.
 *
 * Tolerances are relative to the stress magnitude (or to the parameter
 * scale at rest), because plugin stiffnesses span 1e-2..1e12 Pa. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "material.h"
#include "plugins.h"
#include "tensor.h"

#define CHECK_TRIALS 20
#define PLUGIN_CHECK_MAX_PARAMS 256
#define CHECK_DETAIL 1024

typedef struct check_rig {
    const hearth_material *m;
    int density;          /* index of the density parameter */
    double *p;            /* working parameters (nparams) */
    double *state;        /* state_size doubles, or NULL when 0 */
    hearth_check_fn fn;
    void *ud;
    int failed;
    const char *file; /* the plugin's file, for the checks that name it */
} check_rig;

/* passed: 1 pass, 0 fail, 2 pass with a warning (hearth_check_fn) */
static void check_report(check_rig *r, const char *name, int passed, const char *detail) {
    if (!passed) r->failed++;
    if (r->fn) r->fn(r->ud, name, passed, detail);
}

static void check_defaults(check_rig *r) {
    for (int i = 0; i < r->m->nparams; i++) r->p[i] = r->m->params[i].def;
}

/* The state is poisoned with NaN before init, so a plugin that forgets to
 * initialise part of it fails loudly here instead of by luck in a scene. */
static void check_init(check_rig *r) {
    for (int i = 0; i < r->m->state_size; i++) r->state[i] = NAN;
    plugin_call_enter(r->m, "init");
    r->m->init(r->p, r->state);
    plugin_call_leave();
}

/* One stress call. tau starts as NaN so an entry the plugin never writes
 * shows up as non-finite. Fields the plugin does not ask for stay NaN, as
 * in a scene that does not enable them. */
static int check_stress(check_rig *r, const double F[9], const double L[9], double dt, double tau[9]) {
    hearth_point pt;
    memcpy(pt.grad_v, L, sizeof pt.grad_v);
    memcpy(pt.F, F, sizeof pt.F);
    pt.dt = dt;
    pt.p = r->p;
    pt.state = r->state;
    /* a plugin on its own, no scene: room temperature, a fixed mid-range
     * porosity and saturation, and none of the core's coupling terms (the
     * checks test the plugin's stress, not the core's) */
    const unsigned needs = r->m->needs;
    const material_env env = {
        .temperature = (needs & (HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_THERMAL_EXPANSION)) ? 20.0 : NAN,
        .porosity = (needs & HEARTH_NEEDS_POROSITY) ? 0.1 : NAN,
        .saturation = (needs & HEARTH_NEEDS_SATURATION) ? 0.5 : NAN,
    };
    for (int i = 0; i < 9; i++) tau[i] = NAN;
    const int rc = material_point_eval(r->m, NULL, &pt, &env, tau);
    plugin_call_leave();
    /* a non-finite tau is the checks' own finding, not a plugin code */
    return rc == MATERIAL_NONFINITE ? 0 : rc;
}

static const char *check_describe(const check_rig *r, int rc) {
    plugin_call_enter(r->m, "describe_error");
    const char *t = r->m->describe_error(rc);
    plugin_call_leave();
    return t;
}

static double check_wave_speed(const check_rig *r) {
    plugin_call_enter(r->m, "wave_speed");
    const double c = r->m->wave_speed(r->p, r->m->state_size > 0 ? r->state : NULL);
    plugin_call_leave();
    return c;
}

static const char *check_code_text(const check_rig *r, int rc) {
    const char *t = check_describe(r, rc);
    return t ? t : "(describe_error returned NULL)";
}

static double check_norm(const double A[9]) {
    double s = 0;
    for (int i = 0; i < 9; i++) s += A[i] * A[i];
    return sqrt(s);
}

static uint64_t check_next(uint64_t *s) {
    uint64_t z = (*s += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
}

static double check_uniform(uint64_t *s) { return (double)(check_next(s) >> 11) * 0x1.0p-53; }

/* A random velocity gradient whose one step from rest, F = I + dt L, moves
 * F about 0.1 from I: large enough to exercise nonlinearity, small enough
 * that det F stays well above 0 (Gershgorin keeps it >= 0.7^3 or so). */
static void check_random_step(uint64_t *s, double dt, double L[9], double F[9]) {
    do {
        for (int i = 0; i < 9; i++) L[i] = (2 * check_uniform(s) - 1) * 0.1 / dt;
        for (int i = 0; i < 9; i++) F[i] = (i % 4 == 0) + dt * L[i];
    } while (!(t3_det(F) > 0));
}

/* ---- the checks -------------------------------------------------------- */

static void check_rest(check_rig *r) {
    char detail[CHECK_DETAIL];
    double F[9], L[9] = {0}, tau[9], scale = 1;
    check_defaults(r);
    for (int i = 0; i < r->m->nparams; i++) scale = fmax(scale, fabs(r->p[i]));
    check_init(r);
    t3_identity(F);
    int rc = check_stress(r, F, L, 1e-4, tau);
    if (rc) {
        snprintf(detail, sizeof detail, "stress returned code %d at rest: %s", rc, check_code_text(r, rc));
        check_report(r, "rest", 0, detail);
        return;
    }
    double n = check_norm(tau), tol = 1e-9 * scale;
    snprintf(detail, sizeof detail, "|tau| = %.3g Pa at F = I, grad_v = 0 (tolerance %.3g = 1e-9 x max(1, max |default|))",
             n, tol);
    check_report(r, "rest", n <= tol, detail);
}

static void check_symmetric(check_rig *r) {
    char detail[CHECK_DETAIL];
    uint64_t seed = 0x5eed0001u;
    double worst = -1, w_asym = 0, w_tau = 0;
    int bad = -1;
    for (int k = 0; k < CHECK_TRIALS && bad < 0; k++) {
        double L[9], F[9], tau[9], tauT[9], d[9];
        check_defaults(r);
        check_init(r);
        check_random_step(&seed, 1e-4, L, F);
        int rc = check_stress(r, F, L, 1e-4, tau);
        if (rc) {
            snprintf(detail, sizeof detail, "trial %d: stress returned code %d: %s", k, rc, check_code_text(r, rc));
            check_report(r, "symmetric", 0, detail);
            return;
        }
        t3_transpose(tau, tauT);
        for (int i = 0; i < 9; i++) d[i] = tau[i] - tauT[i];
        double asym = check_norm(d), n = check_norm(tau);
        double ratio = asym / (1e-10 * fmax(1, n));
        if (!(ratio <= 1)) bad = k;
        if (bad == k || ratio >= worst) {
            worst = ratio;
            w_asym = asym;
            w_tau = n;
        }
    }
    if (bad >= 0)
        snprintf(detail, sizeof detail,
                 "trial %d: |tau - tau^T| = %.3g Pa with |tau| = %.3g Pa (tolerance 1e-10 x max(1, |tau|)); "
                 "Kirchhoff stress must be symmetric",
                 bad, w_asym, w_tau);
    else
        snprintf(detail, sizeof detail,
                 "worst |tau - tau^T| = %.3g Pa with |tau| = %.3g Pa over %d random steps (tolerance 1e-10 x "
                 "max(1, |tau|))",
                 w_asym, w_tau, CHECK_TRIALS);
    check_report(r, "symmetric", bad < 0, detail);
}

/* tau(Q F, Q L Q^T) must equal Q tau(F, L) Q^T: a material's response may not
 * depend on how the observer is turned. */
static void check_frame(check_rig *r) {
    char detail[CHECK_DETAIL];
    uint64_t seed = 0xf7a3e001u;
    double worst = -1, w_diff = 0, w_tau = 0;
    int bad = -1;
    for (int k = 0; k < CHECK_TRIALS && bad < 0; k++) {
        double u[3], Q[9], L[9], F[9], QF[9], QL[9], QLQt[9], tau[9], taur[9], Qt[9], want[9], d[9];
        for (int i = 0; i < 3; i++) u[i] = check_uniform(&seed);
        t3_random_rotation(u, Q);
        check_random_step(&seed, 1e-4, L, F);
        check_defaults(r);
        check_init(r);
        int rc = check_stress(r, F, L, 1e-4, tau);
        t3_mul(Q, F, QF);
        t3_mul(Q, L, QL);
        t3_mul_abt(QL, Q, QLQt);
        check_init(r);
        if (!rc) rc = check_stress(r, QF, QLQt, 1e-4, taur);
        if (rc) {
            snprintf(detail, sizeof detail, "trial %d: stress returned code %d: %s", k, rc, check_code_text(r, rc));
            check_report(r, "frame_indifference", 0, detail);
            return;
        }
        t3_mul(Q, tau, Qt);
        t3_mul_abt(Qt, Q, want);
        for (int i = 0; i < 9; i++) d[i] = taur[i] - want[i];
        double diff = check_norm(d), n = check_norm(tau);
        double ratio = diff / (1e-9 * fmax(1, n));
        if (!(ratio <= 1)) bad = k;
        if (bad == k || ratio >= worst) {
            worst = ratio;
            w_diff = diff;
            w_tau = n;
        }
    }
    if (bad >= 0)
        snprintf(detail, sizeof detail,
                 "trial %d: |tau(QF, QLQ^T) - Q tau(F, L) Q^T| = %.3g Pa with |tau| = %.3g Pa (tolerance 1e-9 x "
                 "max(1, |tau|)); the stress depends on the observer's orientation",
                 bad, w_diff, w_tau);
    else
        snprintf(detail, sizeof detail,
                 "worst |tau' - Q tau Q^T| = %.3g Pa with |tau| = %.3g Pa over %d random rotations (tolerance "
                 "1e-9 x max(1, |tau|))",
                 w_diff, w_tau, CHECK_TRIALS);
    check_report(r, "frame_indifference", bad < 0, detail);
}

/* The parameters at one corner of the schema: the defaults with parameter i
 * pinned at its min (side 0) or max (side 1), or with i = -1 every parameter
 * there (the loader's all-min and all-max corners); at names the corner. */
static void check_corner(check_rig *r, int i, int side, char at[160]) {
    check_defaults(r);
    if (i >= 0) {
        const hearth_param *q = &r->m->params[i];
        r->p[i] = side ? q->max : q->min;
        snprintf(at, 160, "%s = %g %s (%s)", q->name, r->p[i], q->unit, side ? "max" : "min");
    } else {
        for (int j = 0; j < r->m->nparams; j++) r->p[j] = side ? r->m->params[j].max : r->m->params[j].min;
        snprintf(at, 160, "every parameter at its %s", side ? "max" : "min");
    }
}

/* One parameter pinned at a bound (i >= 0), or every parameter at its min or
 * max (i = -1: the loader's all-min and all-max corners), then 5 steps of
 * shear and stretch. Returns 1 on pass; on failure writes why into detail.
 * note gets a stress code the plugin explained (accepted: refusing an
 * extreme state is legitimate). */
static int check_extreme_case(check_rig *r, int i, int side, char *detail, char *note) {
    const double dt = 1e-3;
    /* dt L: 10% shear and a few % stretch per step, a hard but physical deformation. */
    const double L[9] = {0.05 / dt, 0.1 / dt, 0, 0, -0.03 / dt, 0, 0, 0, 0.02 / dt};
    double F[9], A[9], Fn[9], tau[9];
    char at[160];
    check_corner(r, i, side, at);
    check_init(r);
    t3_identity(F);
    for (int s = 0; s < 5; s++) {
        for (int j = 0; j < 9; j++) A[j] = (j % 4 == 0) + dt * L[j];
        t3_mul(A, F, Fn); /* tensor.h does not promise that outputs may alias */
        t3_copy(Fn, F);
        int rc = check_stress(r, F, L, dt, tau);
        if (rc) {
            const char *t = check_describe(r, rc);
            if (!t) {
                snprintf(detail, CHECK_DETAIL, "%s: step %d: stress returned code %d and describe_error(%d) is NULL", at,
                         s + 1, rc, rc);
                return 0;
            }
            if (!*note) snprintf(note, CHECK_DETAIL, "; accepted %s: step %d code %d \"%s\"", at, s + 1, rc, t);
            break;
        }
        for (int j = 0; j < 9; j++)
            if (!isfinite(tau[j])) {
                snprintf(detail, CHECK_DETAIL, "%s: step %d: tau[%d] = %g is not finite", at, s + 1, j, tau[j]);
                return 0;
            }
    }
    double c = check_wave_speed(r);
    if (!(isfinite(c) && c > 0)) {
        snprintf(detail, CHECK_DETAIL, "%s: wave_speed = %g m/s, must be finite and > 0", at, c);
        return 0;
    }
    return 1;
}

static void check_extremes(check_rig *r) {
    char detail[CHECK_DETAIL], note[CHECK_DETAIL] = "";
    int n = r->m->nparams;
    for (int i = -1; i < n; i++)
        for (int side = 0; side < 2; side++)
            if (!check_extreme_case(r, i, side, detail, note)) {
                check_report(r, "extremes", 0, detail);
                return;
            }
    snprintf(detail, sizeof detail,
             "%d parameters at min and max, and all at min and all at max, 5 steps each: tau finite, wave_speed "
             "finite > 0%.400s",
             n, note);
    check_report(r, "extremes", 1, detail);
}

/* The CFL limit trusts wave_speed. Compare it with the P-wave modulus M
 * measured from a tiny uniaxial strain; two step sizes cancel a viscous
 * stress linear in the rate (tau = M eps + V eps/dt), which a wave does not
 * feel at the grid scale. Too low is unsafe; far too high wastes steps. */
static void check_wave(check_rig *r) {
    char detail[CHECK_DETAIL];
    const double eps = 1e-6, dts[2] = {1e-6, 2e-6};
    double txx[2];
    check_defaults(r);
    check_init(r);
    double c = check_wave_speed(r), rho = r->p[r->density];
    for (int k = 0; k < 2; k++) {
        double F[9], L[9] = {0}, tau[9];
        t3_identity(F);
        F[0] += eps;
        L[0] = eps / dts[k];
        check_init(r);
        int rc = check_stress(r, F, L, dts[k], tau);
        if (rc) {
            snprintf(detail, sizeof detail, "uniaxial strain %g at dt = %g s: stress returned code %d: %s", eps,
                     dts[k], rc, check_code_text(r, rc));
            check_report(r, "wave_speed", 0, detail);
            return;
        }
        txx[k] = tau[0];
    }
    double M = (2 * txx[1] - txx[0]) / eps, rc2 = rho * c * c;
    int ok = isfinite(c) && c > 0 && isfinite(M) && rc2 >= 0.95 * M && (M <= 0 || rc2 <= 25 * M);
    const char *why = ok ? ""
                      : !(isfinite(c) && c > 0) ? "; wave_speed must be finite and > 0"
                      : !isfinite(M)            ? "; the measured stress is not finite"
                      : rc2 < 0.95 * M ? "; wave_speed underestimates the stiffness, so the CFL limit is unsafe"
                                       : "; wave_speed is over 5x the measured one, so steps are needlessly small";
    snprintf(detail, sizeof detail,
             "c = %.6g m/s, sqrt(M/rho) = %.6g m/s (M = %.6g Pa from uniaxial strain %g, rho = %g kg/m^3; "
             "need 0.95 <= rho c^2 / M <= 25)%s",
             c, M > 0 ? sqrt(M / rho) : 0.0, M, eps, rho, why);
    check_report(r, "wave_speed", ok, detail);
}

/* ---- bulk_modulus (optional) ---------------------------------------------- */

/* K at the rig's parameters and state (NULL when the plugin has none). */
static double check_bulk_value(const check_rig *r) {
    plugin_call_enter(r->m, "bulk_modulus");
    const double K = r->m->bulk_modulus(r->p, r->m->state_size > 0 ? r->state : NULL);
    plugin_call_leave();
    return K;
}

static int check_bulk_ok(double K) { return K > 0 && K < INFINITY; }

/* The mean Kirchhoff stress of a small isotropic volume change ln J = 3 ln(1 + a) from a fresh state at
 * the defaults, with the rate part cancelled as check_wave does (tau = K ln J + V ln J / dt at two dt).
 * Returns the plugin's code (0: *Kmeas = mean stress / ln J); *plastic is 1 when the plugin's plastic_J
 * left 1, i.e. the law flowed plastically under that change (its mean stress then need not be K ln J). */
static int check_bulk_measure(check_rig *r, double a, double *Kmeas, int *plastic) {
    const double dts[2] = {1e-6, 2e-6}, lnJ = 3 * log1p(a);
    double pm[2];
    *plastic = 0;
    for (int k = 0; k < 2; k++) {
        double F[9], L[9] = {0}, tau[9];
        t3_identity(F);
        for (int d = 0; d < 3; d++) F[4 * d] += a, L[4 * d] = a / dts[k];
        check_defaults(r);
        check_init(r);
        const int rc = check_stress(r, F, L, dts[k], tau);
        if (rc) return rc;
        pm[k] = (tau[0] + tau[4] + tau[8]) / 3;
        if (r->m->plastic_J) {
            plugin_call_enter(r->m, "plastic_J");
            const double JP = r->m->plastic_J(r->p, r->m->state_size > 0 ? r->state : NULL);
            plugin_call_leave();
            if (!(JP == 1)) *plastic = 1;
        }
    }
    *Kmeas = (2 * pm[1] - pm[0]) / lnJ;
    return 0;
}

/* Tolerance on the measured K: the strain is 1e-6, so a law whose K is right agrees to ~1e-6 (a
 * neo-Hookean's mean stress is K ln J + O(ln J^2)); 1% leaves room for a law whose small-strain
 * stiffness is a secant, and still catches a K given in the wrong units or off by a factor. */
#define CHECK_BULK_TOL 0.01

/* The optional bulk_modulus, which the core divides by for eq. 10's thermal strain
 * (<hearth/material.h>; core/sim/material.h, material_thermal_scales): finite and > 0 at the defaults, at
 * every parameter corner the extremes check uses (fresh states) and at advanced states (the defaults,
 * 1..4 random steps of stress, CHECK_TRIALS times); then K against the law's own mean stress under a
 * small isotropic compression and expansion. A mismatch where the law flowed plastically (plastic_J
 * moved) is a warning: there the mean stress is not K ln J, and K is still the elastic stiffness.
 * Reported only for a plugin with bulk_modulus. */
static void check_bulk(check_rig *r) {
    if (!r->m->bulk_modulus) return;
    char detail[CHECK_DETAIL];
    const hearth_material *m = r->m;
    /* the defaults */
    check_defaults(r);
    check_init(r);
    const double K0 = check_bulk_value(r);
    if (!check_bulk_ok(K0)) {
        snprintf(detail, sizeof detail,
                 "%.400s: bulk_modulus returned %g Pa at the defaults (fresh state from init); it must be finite and > 0 "
                 "(the core divides eq. 10's thermal strain by it)",
                 r->file, K0);
        check_report(r, "bulk_modulus", 0, detail);
        return;
    }
    double Klo = K0, Khi = K0;
    /* the parameter corners: each at its min and max, then all at min and all at max */
    for (int i = -1; i < m->nparams; i++)
        for (int side = 0; side < 2; side++) {
            char at[160];
            check_corner(r, i, side, at);
            check_init(r);
            const double K = check_bulk_value(r);
            if (!check_bulk_ok(K)) {
                snprintf(detail, sizeof detail,
                         "%.400s: bulk_modulus returned %g Pa with %s (fresh state); it must be finite and > 0 over the "
                         "whole schema",
                         r->file, K, at);
                check_report(r, "bulk_modulus", 0, detail);
                return;
            }
        }
    /* advanced states at the defaults */
    uint64_t seed = 0xb01c4001u;
    int states = 0;
    for (int k = 0; k < CHECK_TRIALS; k++) {
        double L[9], A[9], F[9], Fn[9], tau[9];
        check_defaults(r);
        check_init(r);
        t3_identity(F);
        int s = 0, rc = 0;
        for (; s < k % 4 + 1 && !rc; s++) {
            check_random_step(&seed, 1e-4, L, A);
            t3_mul(A, F, Fn);
            t3_copy(Fn, F);
            rc = check_stress(r, F, L, 1e-4, tau);
        }
        if (rc) continue; /* a state the law refused is not one a scene keeps */
        const double K = check_bulk_value(r);
        if (!check_bulk_ok(K)) {
            snprintf(detail, sizeof detail,
                     "%.400s: bulk_modulus returned %g Pa at the defaults after %d random steps of stress (trial %d); it "
                     "must be finite and > 0 in every state",
                     r->file, K, s, k);
            check_report(r, "bulk_modulus", 0, detail);
            return;
        }
        Klo = fmin(Klo, K), Khi = fmax(Khi, K);
        states++;
    }
    /* K against the law's own stress, compressed and stretched by ln J = 3 ln(1 -+ 1e-6) */
    const double as[2] = {-1e-6, 1e-6};
    const char *const way[2] = {"compression", "expansion"};
    double Km[2];
    int plastic[2], bad = -1, warn = -1;
    for (int k = 0; k < 2; k++) {
        const int rc = check_bulk_measure(r, as[k], &Km[k], &plastic[k]);
        if (rc) {
            snprintf(detail, sizeof detail, "%.400s: isotropic %s ln J = %.3g at the defaults: stress returned code %d: %s",
                     r->file, way[k], 3 * log1p(as[k]), rc, check_code_text(r, rc));
            check_report(r, "bulk_modulus", 0, detail);
            return;
        }
        if (!(fabs(Km[k] - K0) <= CHECK_BULK_TOL * K0)) {
            if (plastic[k] && warn < 0) warn = k;
            if (!plastic[k] && bad < 0) bad = k;
        }
    }
    if (bad >= 0) {
        snprintf(detail, sizeof detail,
                 "%.400s: bulk_modulus returned %.6g Pa at the defaults, but the law's mean stress under isotropic %s "
                 "ln J = %.3g gives K = %.6g Pa (off by %.3g%%; tolerance %g%%) and its plastic_J stayed 1: K must be "
                 "the stiffness against a change of volume (lambda + 2/3 mu), or eq. 10's thermal strain is wrong",
                 r->file, K0, way[bad], 3 * log1p(as[bad]), Km[bad], 100 * fabs(Km[bad] / K0 - 1), 100 * CHECK_BULK_TOL);
        check_report(r, "bulk_modulus", 0, detail);
        return;
    }
    char tail[200] = "";
    if (warn >= 0)
        snprintf(tail, sizeof tail,
                 "; warning: under %s the law flowed plastically (plastic_J moved) and its mean stress gives %.6g Pa "
                 "(off by %.3g%%), so K could not be checked there",
                 way[warn], Km[warn], 100 * fabs(Km[warn] / K0 - 1));
    snprintf(detail, sizeof detail,
             "K = %.6g Pa at the defaults; finite and > 0 at %d parameter corners and %d advanced states (%.6g .. "
             "%.6g Pa); the law's mean stress / ln J: %.6g Pa (compression), %.6g Pa (expansion), tolerance %g%%%s",
             K0, 2 * (m->nparams + 1), states, Klo, Khi, Km[0], Km[1], 100 * CHECK_BULK_TOL, tail);
    check_report(r, "bulk_modulus", warn >= 0 ? 2 : 1, detail);
}

/* ---- batched and one-point agree bit for bit (<hearth/material.h> rule 7) ---- */

/* The battery's blocks: the dimension, the number of points (a full block and
 * odd counts, for a plugin's remainder loops), dt (0: evaluate only), and
 * whether every other parameter varies by point (a column) or all are the
 * block's. */
static const struct {
    int dim, n, vary;
    double dt;
} batch_blocks[] = {{3, HEARTH_BLOCK_MAX, 0, 1e-3}, {3, 37, 1, 1e-3}, {2, HEARTH_BLOCK_MAX, 0, 1e-3}, {2, 29, 1, 1e-3},
                    {3, 13, 1, 0.0}};
enum { BATCH_NBLOCKS = sizeof batch_blocks / sizeof batch_blocks[0] };

/* Point j's deformation: near I (|F - I| ~ 0.05, and a step dt grad_v ~ 0.025)
 * for even j, far from it (~0.6 and ~0.3: stretch and shear of tens of per
 * cent, which takes a law such as cam_clay_dough off its near-identity path)
 * for odd j, inverted (det F < 0) for every 16th; in 2D plane strain (no
 * out-of-plane shear, F[8] = 1). */
static void batch_random_F(uint64_t *seed, int dim, int j, double dt, double F[9], double L[9]) {
    const double a = j % 2 ? 0.6 : 0.05;
    do {
        for (int i = 0; i < 9; i++) {
            F[i] = (i % 4 == 0) + a * (2 * check_uniform(seed) - 1);
            L[i] = (2 * check_uniform(seed) - 1) * (dt > 0 ? 0.5 * a / dt : 10);
        }
        if (dim == 2) F[2] = F[5] = F[6] = F[7] = L[2] = L[5] = L[6] = L[7] = 0, F[8] = 1, L[8] = 0;
    } while (!(t3_det(F) > 0.05));
    if (j % 16 == 15)
        for (int i = 0; i < 3; i++) F[i] = -F[i];
}

typedef struct batch_pts {
    int n, dim, stride;
    double dt;
    double *F[9], *L[9], *T, *P, *S, *pv, *stA, *stB, *tauA, *tauB[9];
    double *st0, *memo; /* rule 10: the block's starting states, and its memo (memo_size + 1 doubles a point) */
    int *codeA, *codeB;
    int scalars_bad, scalars_points; /* rule 9: a point whose scalars differ; points compared */
    char scalars_detail[CHECK_DETAIL];
} batch_pts;

/* rule 9: scalars_block against the one-point callbacks on the block's points (their parameters and the
 * states the stress left), bit for bit; the first point that differs into b->scalars_detail. */
static void batch_scalars(const check_rig *r, batch_pts *b, int blk, const hearth_block *blk_) {
    const hearth_material *m = r->m;
    const int n = b->n, np = m->nparams, ss = m->state_size;
    double col[HEARTH_SCALAR_COUNT][HEARTH_BLOCK_MAX];
    double *out[HEARTH_SCALAR_COUNT] = {0};
    double (*one[HEARTH_SCALAR_COUNT])(const double *, const double *) = {
        [HEARTH_SCALAR_WAVE_SPEED] = m->wave_speed, [HEARTH_SCALAR_PLASTIC_J] = m->plastic_J,
        [HEARTH_SCALAR_BULK_MODULUS] = m->bulk_modulus, [HEARTH_SCALAR_VISCOSITY] = m->viscosity,
        [HEARTH_SCALAR_DAMAGE] = m->damage};
    static const char *const name[HEARTH_SCALAR_COUNT] = {"wave_speed", "plastic_J", "bulk_modulus", "viscosity", "damage"};
    for (int k = 0; k < HEARTH_SCALAR_COUNT; k++) {
        out[k] = one[k] ? col[k] : NULL; /* the core asks only what the plugin has a one-point callback for */
        for (int j = 0; j < n; j++) col[k][j] = NAN;
    }
    plugin_call_enter(m, "scalars_block");
    m->scalars_block(blk_, out);
    for (int j = 0; j < n && !b->scalars_bad; j++) {
        double q[PLUGIN_CHECK_MAX_PARAMS];
        for (int k = 0; k < np; k++) q[k] = b->pv[(size_t)k * HEARTH_BLOCK_MAX + j];
        const double *st = ss ? b->stB + (size_t)j * b->stride : NULL;
        for (int k = 0; k < HEARTH_SCALAR_COUNT && !b->scalars_bad; k++) {
            if (!one[k]) continue;
            plugin_call_enter(m, name[k]);
            const double x = one[k](q, st), y = col[k][j];
            if (memcmp(&x, &y, sizeof x) != 0) {
                b->scalars_bad = 1;
                snprintf(b->scalars_detail, CHECK_DETAIL,
                         "block %d (dim %d, %d points), point %d: %s one-point %.17g, scalars_block %.17g (differ by %.3g)",
                         blk, b->dim, n, j, name[k], x, y, y - x);
            }
        }
    }
    plugin_call_leave();
    b->scalars_points += n;
}

/* Why point j differs, into detail; 0 when both calls agree bit for bit. */
static int batch_compare(const check_rig *r, const batch_pts *b, int blk, int j, char *detail) {
    const int ss = r->m->state_size;
    char where[200];
    snprintf(where, sizeof where, "block %d (dim %d, %d points, dt %g), point %d (F[0..2] = %.17g %.17g %.17g)", blk, b->dim,
             b->n, b->dt, j, b->F[0][j], b->F[1][j], b->F[2][j]);
    if (b->codeA[j] != b->codeB[j]) {
        snprintf(detail, CHECK_DETAIL, "%s: one-point stress returned code %d, stress_block code %d", where, b->codeA[j],
                 b->codeB[j]);
        return 1;
    }
    if (b->codeA[j]) return 0; /* the tau of a refused point is not read */
    for (int c = 0; c < 9; c++) {
        const double x = b->tauA[9 * j + c], y = b->tauB[c][j];
        if (memcmp(&x, &y, sizeof x) != 0) {
            snprintf(detail, CHECK_DETAIL, "%s: tau[%d] one-point %.17g, batched %.17g (differ by %.3g)", where, c, x, y, y - x);
            return 1;
        }
    }
    for (int k = 0; k < ss; k++) {
        const double x = b->stA[(size_t)j * b->stride + k], y = b->stB[(size_t)j * b->stride + k];
        if (memcmp(&x, &y, sizeof x) != 0) {
            snprintf(detail, CHECK_DETAIL, "%s: state[%d] one-point %.17g, batched %.17g afterwards", where, k, x, y);
            return 1;
        }
    }
    return 0;
}

/* rule 10: the block again from its starting states with a memo, zeroed, then warm (as the zeroed run left
 * it: every key met), then with point j's entry swapped for point n-1-j's; each run's tau, state and code
 * against the one-point stress, bit for bit. Returns 1 (detail says which memo) when a point differs. */
static int batch_memo(const check_rig *r, batch_pts *b, int blk, hearth_block *blk_, char *detail) {
    static const char *const how[3] = {"zeroed", "warm (the same block again)", "swapped between points"};
    const hearth_material *m = r->m;
    const int n = b->n, w = m->memo_size + 1; /* a stride past memo_size: a plugin must use it */
    memset(b->memo, 0, sizeof(double) * (size_t)n * w);
    blk_->memo = b->memo, blk_->memo_stride = w;
    for (int pass = 0; pass < 3; pass++) {
        if (pass == 2)
            for (int j = 0; j < n / 2; j++)
                for (int k = 0; k < w; k++) {
                    double *x = b->memo + (size_t)j * w + k, *y = b->memo + (size_t)(n - 1 - j) * w + k;
                    const double t = *x;
                    *x = *y, *y = t;
                }
        memcpy(b->stB, b->st0, sizeof(double) * (size_t)n * b->stride);
        for (int c = 0; c < 9; c++)
            for (int j = 0; j < n; j++) b->tauB[c][j] = NAN;
        for (int j = 0; j < n; j++) b->codeB[j] = -12345;
        plugin_call_enter(m, "stress_block");
        m->stress_block(blk_, b->tauB, b->codeB);
        plugin_call_leave();
        for (int j = 0; j < n; j++) {
            char why[CHECK_DETAIL];
            if (batch_compare(r, b, blk, j, why)) {
                snprintf(detail, CHECK_DETAIL, "with the memo %s (rule 10): %.*s", how[pass], CHECK_DETAIL - 64, why);
                return 1;
            }
        }
    }
    blk_->memo = NULL;
    return 0;
}

/* One block of the battery: each point's state advanced by j % 4 steps of
 * its own (one-point calls), its parameters and fields drawn, then one call
 * of each kind on copies of the same state. Returns 1 when a point differs. */
static int batch_block(check_rig *r, batch_pts *b, int blk, uint64_t *seed, char *detail) {
    const hearth_material *m = r->m;
    const int np = m->nparams, ss = m->state_size, n = b->n;
    const unsigned needs = m->needs;
    const double *pcolumn[PLUGIN_CHECK_MAX_PARAMS];
    for (int k = 0; k < np; k++) pcolumn[k] = batch_blocks[blk].vary && k % 2 ? b->pv + (size_t)k * HEARTH_BLOCK_MAX : NULL;
    check_defaults(r);
    for (int j = 0; j < n; j++) {
        double q[PLUGIN_CHECK_MAX_PARAMS], L[9], F[9], tau[9];
        for (int k = 0; k < np; k++) {
            const hearth_param *h = &m->params[k];
            double v = h->def;
            if (pcolumn[k]) v = fmin(h->max, fmax(h->min, v * (0.8 + 0.45 * check_uniform(seed))));
            b->pv[(size_t)k * HEARTH_BLOCK_MAX + j] = q[k] = v;
        }
        b->T[j] = needs & (HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_THERMAL_EXPANSION) ? 20 + 180 * check_uniform(seed) : NAN;
        b->P[j] = needs & HEARTH_NEEDS_POROSITY ? 0.5 * check_uniform(seed) : NAN;
        b->S[j] = needs & HEARTH_NEEDS_SATURATION ? check_uniform(seed) : NAN;
        double *st = ss ? b->stA + (size_t)j * b->stride : NULL;
        for (int k = 0; k < b->stride; k++) b->stA[(size_t)j * b->stride + k] = NAN;
        if (st) {
            plugin_call_enter(m, "init");
            m->init(q, st);
        }
        double Fw[9];
        t3_identity(Fw);
        for (int w = 0; w < j % 4; w++) { /* an advanced state: a few steps of its own */
            double A[9], Fn[9];
            check_random_step(seed, 1e-3, L, A);
            t3_mul(A, Fw, Fn);
            t3_copy(Fn, Fw);
            hearth_point pt = {.dt = 1e-3, .p = q, .state = st, .temperature = b->T[j], .porosity = b->P[j],
                               .saturation = b->S[j], .dim = b->dim};
            memcpy(pt.F, Fw, sizeof pt.F);
            memcpy(pt.grad_v, L, sizeof pt.grad_v);
            plugin_call_enter(m, "stress");
            if (m->stress(&pt, tau)) break;
        }
        batch_random_F(seed, b->dim, j, b->dt, F, L);
        for (int c = 0; c < 9; c++) b->F[c][j] = F[c], b->L[c][j] = L[c];
    }
    memcpy(b->stB, b->stA, sizeof(double) * (size_t)n * b->stride);
    if (m->memo_size > 0) memcpy(b->st0, b->stA, sizeof(double) * (size_t)n * b->stride);
    /* one point at a time */
    for (int j = 0; j < n; j++) {
        double q[PLUGIN_CHECK_MAX_PARAMS];
        for (int k = 0; k < np; k++) q[k] = b->pv[(size_t)k * HEARTH_BLOCK_MAX + j];
        hearth_point pt = {.dt = b->dt, .p = q, .state = ss ? b->stA + (size_t)j * b->stride : NULL, .temperature = b->T[j],
                           .porosity = b->P[j], .saturation = b->S[j], .dim = b->dim};
        for (int c = 0; c < 9; c++) pt.F[c] = b->F[c][j], pt.grad_v[c] = b->L[c][j];
        for (int c = 0; c < 9; c++) b->tauA[9 * j + c] = NAN;
        plugin_call_enter(m, "stress");
        b->codeA[j] = m->stress(&pt, b->tauA + 9 * j);
    }
    /* the block */
    double p0[PLUGIN_CHECK_MAX_PARAMS];
    for (int k = 0; k < np; k++) p0[k] = pcolumn[k] ? NAN : b->pv[(size_t)k * HEARTH_BLOCK_MAX]; /* a column's p[k] is not read */
    hearth_block blk_ = {.n = n, .dim = b->dim, .dt = b->dt, .p = p0, .p_col = pcolumn, .state = ss ? b->stB : NULL,
                         .state_stride = b->stride,
                         .temperature = needs & (HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_THERMAL_EXPANSION) ? b->T : NULL,
                         .porosity = needs & HEARTH_NEEDS_POROSITY ? b->P : NULL,
                         .saturation = needs & HEARTH_NEEDS_SATURATION ? b->S : NULL};
    for (int c = 0; c < 9; c++) {
        blk_.F[c] = b->F[c];
        blk_.grad_v[c] = b->L[c];
        for (int j = 0; j < n; j++) b->tauB[c][j] = NAN;
    }
    for (int j = 0; j < n; j++) b->codeB[j] = -12345;
    plugin_call_enter(m, "stress_block");
    const int nbad = m->stress_block(&blk_, b->tauB, b->codeB);
    plugin_call_leave();
    if (m->scalars_block && !b->scalars_bad) batch_scalars(r, b, blk, &blk_);
    for (int j = 0; j < n; j++)
        if (batch_compare(r, b, blk, j, detail)) return 1;
    if (m->memo_size > 0 && batch_memo(r, b, blk, &blk_, detail)) return 1;
    int want = 0;
    for (int j = 0; j < n; j++) want += b->codeB[j] != 0;
    if (nbad != want) {
        snprintf(detail, CHECK_DETAIL, "block %d (dim %d, %d points): stress_block returned %d, but %d points have a nonzero code",
                 blk, b->dim, n, nbad, want);
        return 1;
    }
    return 0;
}

/* Reported only for a plugin with stress_block. */
static int check_batched(check_rig *r) {
    const hearth_material *m = r->m;
    if (!m->stress_block) {
        if (m->scalars_block)
            check_report(r, "scalars", 2, "scalars_block without stress_block: the core calls it only beside stress_block "
                                          "(<hearth/material.h> rule 9), so it is never called");
        return 0;
    }
    char detail[CHECK_DETAIL];
    if (m->nparams > PLUGIN_CHECK_MAX_PARAMS) {
        snprintf(detail, sizeof detail, "%d parameters: the check compares at most %d", m->nparams, PLUGIN_CHECK_MAX_PARAMS);
        check_report(r, "batched", 0, detail);
        return 0;
    }
    const int N = HEARTH_BLOCK_MAX, stride = m->state_size + 1; /* a stride past the state: a plugin must use it */
    const size_t dN = sizeof(double) * N;
    const int memo_w = m->memo_size > 0 ? m->memo_size + 1 : 0; /* batch_memo's stride */
    const size_t bytes = dN * (18 + 3 + 9 + 9 + (size_t)m->nparams + 3 * (size_t)stride + (size_t)memo_w) + 2 * sizeof(int) * N;
    char *mem = mem_alloc(bytes);
    if (!mem) return -1;
    double *d = (double *)mem;
    batch_pts b = {.stride = stride};
    for (int c = 0; c < 9; c++) b.F[c] = d, d += N;
    for (int c = 0; c < 9; c++) b.L[c] = d, d += N;
    b.T = d, d += N;
    b.P = d, d += N;
    b.S = d, d += N;
    b.tauA = d, d += 9 * N;
    for (int c = 0; c < 9; c++) b.tauB[c] = d, d += N;
    b.pv = d, d += (size_t)m->nparams * N;
    b.stA = d, d += (size_t)stride * N;
    b.stB = d, d += (size_t)stride * N;
    b.st0 = d, d += (size_t)stride * N;
    b.memo = d, d += (size_t)memo_w * N;
    b.codeA = (int *)d;
    b.codeB = b.codeA + N;
    uint64_t seed = 0xba7c4001u;
    int bad = 0, points = 0, refused = 0;
    for (int k = 0; k < BATCH_NBLOCKS && !bad; k++) {
        b.n = batch_blocks[k].n;
        b.dim = batch_blocks[k].dim;
        b.dt = batch_blocks[k].dt;
        bad = batch_block(r, &b, k, &seed, detail);
        points += b.n;
        for (int j = 0; j < b.n && !bad; j++) refused += b.codeA[j] != 0;
    }
    if (!bad)
        snprintf(detail, sizeof detail,
                 "stress_block and stress agree bit for bit (tau, state, code) on %d points in %d blocks (dim 2 and 3, F "
                 "near and far from I, advanced states, parameters varying by point; %d refused alike)%s",
                 points, BATCH_NBLOCKS, refused,
                 m->memo_size > 0 ? "; with the memo NULL, zeroed, warm and swapped between points (rule 10)" : "");
    check_report(r, "batched", !bad, detail);
    if (m->scalars_block) {
        if (!b.scalars_bad)
            snprintf(b.scalars_detail, sizeof b.scalars_detail,
                     "scalars_block and the one-point scalars agree bit for bit on %d points (the batched battery's "
                     "parameters and states)", b.scalars_points);
        check_report(r, "scalars", !b.scalars_bad, b.scalars_detail);
    }
    mem_free(mem, bytes);
    return 0;
}

int hearth_plugin_check(const char *path, hearth_check_fn fn, void *ud, hearth_error *err) {
    /* "hearth plugin check hearth_foo.so" names a file in the current folder,
     * which the loader would read as a plugin name; make it a path. A bare
     * name ("elastic") still goes through the search path. */
    char local[4096];
    size_t n = path ? strlen(path) : 0;
    if (n > 3 && !strchr(path, '/') && strcmp(path + n - 3, ".so") == 0) {
        int w = snprintf(local, sizeof local, "./%s", path);
        if (w > 0 && (size_t)w < sizeof local) path = local;
    }
    const hearth_plugin *pl = hearth_plugin_load(path, err);
    if (!pl) return -1;
    check_rig r = {.m = hearth_plugin_material(pl), .density = plugin_density_index(pl), .fn = fn, .ud = ud,
                   .file = hearth_plugin_file(pl) ? hearth_plugin_file(pl) : path};
    size_t pbytes = (size_t)r.m->nparams * sizeof(double), sbytes = (size_t)r.m->state_size * sizeof(double);
    r.p = mem_alloc(pbytes);
    r.state = mem_alloc(sbytes);
    if ((pbytes && !r.p) || (sbytes && !r.state)) {
        mem_free(r.p, pbytes);
        mem_free(r.state, sbytes);
        err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory for the conformance check", hearth_plugin_file(pl));
        return -1;
    }
    /* each check names itself to a crash report (hearth_plugin_call_current) */
    const char *file = hearth_plugin_file(pl);
    plugin_call_set_context(file, "check 'rest'");
    check_rest(&r);
    plugin_call_set_context(file, "check 'symmetric'");
    check_symmetric(&r);
    plugin_call_set_context(file, "check 'frame_indifference'");
    check_frame(&r);
    plugin_call_set_context(file, "check 'extremes'");
    check_extremes(&r);
    plugin_call_set_context(file, "check 'wave_speed'");
    check_wave(&r);
    plugin_call_set_context(file, "check 'bulk_modulus'");
    check_bulk(&r);
    plugin_call_set_context(file, "check 'batched'");
    const int brc = check_batched(&r);
    plugin_call_set_context(NULL, NULL);
    if (brc < 0) {
        mem_free(r.p, pbytes);
        mem_free(r.state, sbytes);
        err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory for the batched check", hearth_plugin_file(pl));
        return -1;
    }
    mem_free(r.p, pbytes);
    mem_free(r.state, sbytes);
    return r.failed;
}
