/* unit_dough.c: the cam_clay_dough plugin (Ding et al. 2019 §5.2-5.3, eq. 12,
 * §6.5) through its ABI, against conditions computed here from the returned
 * stress alone: the yield function, the KKT conditions of the closest-point
 * projection, the first-order optimality of the viscoplastic minimisation,
 * a closed-form von Mises radial return, frame indifference, and extremes.
 *
 * Every case starts from rest (b^E = I) and takes one step with
 * f = I + dt L, so the trial elastic state is b_tr = f f^T and the trial
 * Hencky strain eps_tr = 1/2 log(f f^T) is known without the plugin. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "hearth/hearth.h"
#include "hearth/material.h"
#include "material.h"
#include "tensor.h"
#include "test.h"
#define PLUGIN_FIXTURE_SEED 0x0d0c0ffee
#include "plugin_fixture.h"

#include "dough_params.h"

static const hearth_material *dough(void) { return load_material("cam_clay_dough"); }

static void lame(const double *p, double *mu, double *lambda) { lame_from(p[P_E], p[P_NU], mu, lambda); }

/* tau = C eps and eps = C^-1 tau for the isotropic Hencky law. */
static void c_apply(const double *p, const double eps[9], double tau[9]) {
    double mu, la;
    lame(p, &mu, &la);
    const double tr = eps[0] + eps[4] + eps[8];
    for (int i = 0; i < 9; i++) tau[i] = 2 * mu * eps[i] + (i % 4 == 0 ? la * tr : 0);
}
static void c_inverse(const double *p, const double tau[9], double eps[9]) {
    double mu, la;
    lame(p, &mu, &la);
    const double tr = tau[0] + tau[4] + tau[8];
    for (int i = 0; i < 9; i++) eps[i] = (tau[i] - (i % 4 == 0 ? la / (3 * la + 2 * mu) * tr : 0)) / (2 * mu);
}

/* p, q, deviator s and the yield function of eq. 12. */
static double coefficient(double n) {
    if (!(n > 0)) return 0;
    const double l = log(1 / n);
    return 9.0 / (4.0 * l * l * (3.5 * n + 1.0));
}
static double yield_f(const double tau[9], double M, double ty, double *p_out, double *q_out, double s[9]) {
    const double p = -(tau[0] + tau[4] + tau[8]) / 3;
    for (int i = 0; i < 9; i++) s[i] = tau[i] + (i % 4 == 0 ? p : 0);
    const double q = sqrt(1.5) * norm9(s);
    if (p_out) *p_out = p;
    if (q_out) *q_out = q;
    return M * p * p + q * q - ty * ty;
}

/* The step f = R diag(exp(e)) R^T from rest: eps_tr = R diag(e) R^T. */
static void trial(const double e[3], const double R[9], double f[9], double eps_tr[9]) {
    double D[9] = {0}, RD[9], E[9] = {0}, RE[9];
    for (int i = 0; i < 3; i++) D[4 * i] = exp(e[i]), E[4 * i] = e[i];
    t3_mul(R, D, RD);
    t3_mul_abt(RD, R, f);
    t3_mul(R, E, RE);
    t3_mul_abt(RE, R, eps_tr);
}

/* A trial state outside the surface: principal log strains with a deviator
 * well past yield and a volume change (either sign) of at most 2%. Plastic
 * compaction is then at most 2%, short of the closed-pore cap (J^P >= 1 -
 * 0.5 n^p_0 >= 0.975 for the porosities used), so these returns are eq. 12's
 * alone. */
static void random_outside(double e[3]) {
    const double vol = (2 * uni() - 1) * 0.02;
    double d[3], m = 0;
    for (int i = 0; i < 3; i++) d[i] = (2 * uni() - 1) * 0.05, m += d[i] / 3;
    for (int i = 0; i < 3; i++) e[i] = vol / 3 + d[i] - m;
}

/* eta = 0: the returned stress lies on the surface (|f| <= 1e-10 tau_y^2) and
 * is the closest point: C^-1 (tau_tr - tau) = gamma df/dtau with gamma >= 0,
 * to 1e-9 relative. */
TEST(dough_closest_point) {
    const hearth_material *m = dough();
    CHECK(m != NULL);
    if (!m) return;
    double worst_f = 0, worst_kkt = 0;
    const double ns[] = {0.0, 0.05, 0.3, 0.7, 0.95};
    for (int k = 0; k < 40; k++) {
        const double p[NP] = {4e4, 0.3, 20 + 200 * uni(), 0, 0.5, 500, 1};
        const double n = ns[k % 5];
        double e[3], R[9], f[9], eps_tr[9], tau_tr[9], tau[9], st[NSTATE];
        random_outside(e);
        random_rotation(R);
        trial(e, R, f, eps_tr);
        c_apply(p, eps_tr, tau_tr);
        const double M = coefficient(n);
        double s[9], pp, q;
        if (!(yield_f(tau_tr, M, p[P_TAU_Y], NULL, NULL, s) > 0)) continue; /* only returns are of interest */
        CHECK(step_from_rest(m, p, f, 1e-3, n, 20, st, tau) == 0);
        const double fv = yield_f(tau, M, p[P_TAU_Y], &pp, &q, s);
        worst_f = fmax(worst_f, fabs(fv) / (p[P_TAU_Y] * p[P_TAU_Y]));
        double d[9], dtau[9], nrm[9], r[9];
        for (int i = 0; i < 9; i++) dtau[i] = tau_tr[i] - tau[i];
        c_inverse(p, dtau, d);
        for (int i = 0; i < 9; i++) nrm[i] = 3 * s[i] - (i % 4 == 0 ? 2 * M * pp / 3 : 0); /* df/dtau */
        double dn = 0, nn = 0;
        for (int i = 0; i < 9; i++) dn += d[i] * nrm[i], nn += nrm[i] * nrm[i];
        const double gamma = dn / nn;
        CHECK(gamma > 0);
        for (int i = 0; i < 9; i++) r[i] = d[i] - gamma * nrm[i];
        worst_kkt = fmax(worst_kkt, norm9(r) / norm9(d));
    }
    printf("  worst |f|/tau_y^2 = %.3g (need <= 1e-10), worst KKT residual |dEps - gamma df/dtau|/|dEps| = %.3g (need <= 1e-9)\n",
           worst_f, worst_kkt);
    CHECK(worst_f <= 1e-10);
    CHECK(worst_kkt <= 1e-9);
}

/* eta > 0: the stationarity of 1/2 |tau_tr - tau|_{C^-1}^2 + dt/eta g(f(tau)),
 *   C^-1 (tau_tr - tau) = (dt/eta) f(tau) df/dtau,  f(tau) > 0, to 1e-9. */
TEST(dough_viscoplastic_optimality) {
    const hearth_material *m = dough();
    CHECK(m != NULL);
    if (!m) return;
    double worst = 0, fmin_rel = INFINITY;
    const double etas[] = {1e-2, 1, 100, 1e4, 1e6};
    for (int k = 0; k < 40; k++) {
        const double p[NP] = {4e4, 0.3, 20, etas[k % 5], 0.5, 500, 1};
        const double n = 0.05 + 0.8 * uni(), dt = 1e-3;
        double e[3], R[9], f[9], eps_tr[9], tau_tr[9], tau[9], st[NSTATE], s[9], pp, q;
        random_outside(e);
        random_rotation(R);
        trial(e, R, f, eps_tr);
        c_apply(p, eps_tr, tau_tr);
        const double M = coefficient(n);
        if (!(yield_f(tau_tr, M, p[P_TAU_Y], NULL, NULL, s) > 0)) continue;
        CHECK(step_from_rest(m, p, f, dt, n, 20, st, tau) == 0);
        const double fv = yield_f(tau, M, p[P_TAU_Y], &pp, &q, s);
        fmin_rel = fmin(fmin_rel, fv / (p[P_TAU_Y] * p[P_TAU_Y]));
        double d[9], dtau[9], r[9];
        for (int i = 0; i < 9; i++) dtau[i] = tau_tr[i] - tau[i];
        c_inverse(p, dtau, d);
        for (int i = 0; i < 9; i++) r[i] = d[i] - dt / p[P_ETA] * fmax(fv, 0) * (3 * s[i] - (i % 4 == 0 ? 2 * M * pp / 3 : 0));
        worst = fmax(worst, norm9(r) / norm9(d));
    }
    printf("  worst |C^-1(tau_tr - tau) - dt/eta f df/dtau| / |C^-1(tau_tr - tau)| = %.3g (need <= 1e-9); smallest "
           "f/tau_y^2 = %.3g (viscous: stays outside)\n",
           worst, fmin_rel);
    CHECK(worst <= 1e-9);
    CHECK(fmin_rel > 0);
}

/* Inside the surface the trial state is the answer: tau = C eps_tr, J^P = 1. */
TEST(dough_inside_unchanged) {
    const hearth_material *m = dough();
    CHECK(m != NULL);
    if (!m) return;
    double worst = 0;
    for (int k = 0; k < 20; k++) {
        const double p[NP] = {4e4, 0.3, 20, k % 2 ? 500 : 0, 0.5, 500, 1};
        double e[3], R[9], f[9], eps_tr[9], tau_tr[9], tau[9], st[NSTATE], s[9];
        for (int i = 0; i < 3; i++) e[i] = (2 * uni() - 1) * 2e-4; /* |tau| ~ 10 Pa < tau_y */
        random_rotation(R);
        trial(e, R, f, eps_tr);
        c_apply(p, eps_tr, tau_tr);
        const double n = 0.3;
        CHECK(yield_f(tau_tr, coefficient(n), p[P_TAU_Y], NULL, NULL, s) < 0);
        CHECK(step_from_rest(m, p, f, 1e-3, n, 20, st, tau) == 0);
        double d[9];
        for (int i = 0; i < 9; i++) d[i] = tau[i] - tau_tr[i];
        worst = fmax(worst, norm9(d) / norm9(tau_tr));
        CHECK(fabs(m->plastic_J(p, st) - 1) <= 1e-12);
    }
    /* the floor is rounding in log(exp(2 eps)) / 2 at |eps| ~ 1e-4: about 1e-16 / 1e-4 relative */
    printf("  worst |tau - C eps_tr| / |C eps_tr| = %.3g (need <= 1e-10)\n", worst);
    CHECK(worst <= 1e-10);
}

/* Von Mises radial return in closed form: p = p_tr, s = s_tr tau_y / q_tr.
 * Trial states past yield in shear with a mean stress of the order of tau_y
 * (volume change +-1e-3 at K = 3.3e4 Pa: |p_tr| <= 33 Pa, tau_y = 20 Pa). */
static double vm_difference(const hearth_material *m, double n, int *count) {
    double worst = 0;
    rng = 0x5eedu;
    *count = 0;
    for (int k = 0; k < 20; k++) {
        const double p[NP] = {4e4, 0.3, 20, 0, 0.5, 500, 1};
        double e[3], R[9], f[9], eps_tr[9], tau_tr[9], tau[9], st[NSTATE], s[9], pt, qt, want[9], d[9];
        random_outside(e);
        const double shift = (2 * uni() - 1) * 1e-3 / 3 - (e[0] + e[1] + e[2]) / 3;
        for (int i = 0; i < 3; i++) e[i] += shift;
        random_rotation(R);
        trial(e, R, f, eps_tr);
        c_apply(p, eps_tr, tau_tr);
        yield_f(tau_tr, 0, p[P_TAU_Y], &pt, &qt, s);
        if (!(qt > p[P_TAU_Y])) continue;
        for (int i = 0; i < 9; i++) want[i] = s[i] * p[P_TAU_Y] / qt - (i % 4 == 0 ? pt : 0);
        if (step_from_rest(m, p, f, 1e-3, n, 20, st, tau)) return INFINITY;
        for (int i = 0; i < 9; i++) d[i] = tau[i] - want[i];
        worst = fmax(worst, norm9(d) / norm9(want));
        (*count)++;
    }
    return worst;
}

/* n^p -> 0: the return becomes von Mises. Exact at n^p = 0, and the
 * difference shrinks as n^p does; the 1e-8 at n^p = 1e-9 is checked
 * last (eq. 12's coefficient falls only like 1/ln^2(1/n^p)). */
TEST(dough_von_mises_limit) {
    const hearth_material *m = dough();
    CHECK(m != NULL);
    if (!m) return;
    int c0, c;
    const double d0 = vm_difference(m, 0, &c0);
    printf("  n^p = 0: worst relative difference from the von Mises radial return %.3g over %d returns\n", d0, c0);
    CHECK(c0 >= 10);
    CHECK(d0 <= 1e-10); /* rounding: |tau_tr| is ~100 |tau| here */
    const double ns[] = {1e-1, 1e-3, 1e-6, 1e-9};
    double prev = INFINITY, d9 = 0;
    for (int k = 0; k < 4; k++) {
        const double d = vm_difference(m, ns[k], &c);
        printf("  n^p = %g: coefficient M = %.3g, worst relative difference %.3g\n", ns[k], coefficient(ns[k]), d);
        CHECK(d < prev); /* converges towards von Mises */
        prev = d;
        d9 = d;
    }
    if (d9 > 1e-8)
        XFAIL("at n^p = 1e-9 the return differs from von Mises by %.3g (issue asks 1e-8): eq. 12's coefficient "
              "9/(4 ln^2(1/n)(7/2 n + 1)) is still %.3g there, and the associative flow shrinks p by 1/(1 + 2 K M gamma) with "
              "gamma ~ (q_tr/tau_y - 1)/(6 mu), which is O(M q_tr/tau_y), not small, far past yield; the limit is exact only at n^p = 0 (checked above to 1e-10)",
              d9, coefficient(1e-9));
    else CHECK(d9 <= 1e-8);
}

/* The 3D near-rest path (log and exp as power series, no eigenvectors) and
 * the eigen path meet at |b/m - I| = 0.1 (m = tr(b)/3): trials whose deviator
 * spans 1e-5 .. 0.3 in log strain, on both sides of it, return to the
 * closest point (eta = 0) or the viscous optimum (eta > 0) to 1e-9, and a
 * trial inside the surface comes back as C eps_tr to 1e-10. */
TEST(dough_near_identity_return) {
    const hearth_material *m = dough();
    CHECK(m != NULL);
    if (!m) return;
    double worst_kkt = 0, worst_f = 0, worst_in = 0, worst_state = 0;
    int near = 0, far = 0;
    for (int k = 0; k < 120; k++) {
        const double scale = pow(10, -5 + 4.5 * uni()), n = 0.05 + 0.8 * uni(), dt = 1e-3;
        double e[3], R[9], f[9], eps_tr[9], tau_tr[9], tau[9], st[NSTATE], s[9], pp, q;
        const double vol = (2 * uni() - 1) * 0.02;
        double d[3], mean = 0, dist = 0;
        for (int i = 0; i < 3; i++) d[i] = (2 * uni() - 1) * scale, mean += d[i] / 3;
        double lam[3], lm = 0; /* b's eigenvalues over their mean */
        for (int i = 0; i < 3; i++) e[i] = vol / 3 + d[i] - mean, lam[i] = exp(2 * (d[i] - mean)), lm += lam[i] / 3;
        for (int i = 0; i < 3; i++) dist += pow(lam[i] / lm - 1, 2);
        if (sqrt(dist) <= 0.1) near++;
        else far++;
        random_rotation(R);
        trial(e, R, f, eps_tr);
        double p[NP] = {4e4, 0.3, 1, 0, 0.5, 500, 1};
        const double M = coefficient(n);
        c_apply(p, eps_tr, tau_tr);
        yield_f(tau_tr, M, 0, &pp, &q, s);
        const double reach = sqrt(M * pp * pp + q * q); /* the trial's "radius" */
        /* eta > 0 on two in three: scaled to the trial, so the viscous optimum
         * stays clear of the surface (6 mu gamma ~ 0.1 .. 10); closer, f is a
         * difference of near-equal numbers and the check measures rounding */
        if (k % 3) p[P_ETA] = pow(10, 2 * uni() - 1) * 60 * dt * (p[P_E] / 2.6) * reach * reach;
        if (k % 4 == 3) { /* inside: tau_y past the trial */
            p[P_TAU_Y] = 1.5 * reach;
            CHECK(step_from_rest(m, p, f, dt, n, 20, st, tau) == 0);
            double r[9];
            for (int i = 0; i < 9; i++) r[i] = tau[i] - tau_tr[i];
            worst_in = fmax(worst_in, norm9(r) / norm9(tau_tr));
            continue;
        }
        p[P_TAU_Y] = 0.5 * reach;
        CHECK(step_from_rest(m, p, f, dt, n, 20, st, tau) == 0);
        const double fv = yield_f(tau, M, p[P_TAU_Y], &pp, &q, s);
        double dtau[9], dd[9], nrm[9], r[9];
        for (int i = 0; i < 9; i++) dtau[i] = tau_tr[i] - tau[i];
        c_inverse(p, dtau, dd);
        for (int i = 0; i < 9; i++) nrm[i] = 3 * s[i] - (i % 4 == 0 ? 2 * M * pp / 3 : 0); /* df/dtau */
        if (p[P_ETA] == 0) {
            worst_f = fmax(worst_f, fabs(fv) / (p[P_TAU_Y] * p[P_TAU_Y]));
            double dn = 0, nn = 0;
            for (int i = 0; i < 9; i++) dn += dd[i] * nrm[i], nn += nrm[i] * nrm[i];
            for (int i = 0; i < 9; i++) r[i] = dd[i] - dn / nn * nrm[i];
        } else {
            for (int i = 0; i < 9; i++) r[i] = dd[i] - dt / p[P_ETA] * fmax(fv, 0) * nrm[i];
        }
        worst_kkt = fmax(worst_kkt, norm9(r) / norm9(dd));
        /* the stored state is the returned elastic strain: b^E = exp(2 eps), eps = C^-1 tau, and J^P = J / exp(tr eps) */
        double eps[9], l[3], Q[9], D[9] = {0}, QD[9], b[9], db[9];
        c_inverse(p, tau, eps);
        t3_sym_eigen(eps, l, Q);
        for (int i = 0; i < 3; i++) D[4 * i] = exp(2 * l[i]);
        t3_mul(Q, D, QD);
        t3_mul_abt(QD, Q, b);
        const double sb[9] = {st[0], st[3], st[5], st[3], st[1], st[4], st[5], st[4], st[2]}; /* xx yy zz xy yz zx */
        for (int i = 0; i < 9; i++) db[i] = sb[i] - b[i];
        worst_state = fmax(worst_state, norm9(db) / norm9(b));
        worst_state = fmax(worst_state, fabs(st[6] * exp(eps[0] + eps[4] + eps[8]) / t3_det(f) - 1));
    }
    printf("  %d trials on the near path, %d on the eigen path: worst optimality residual %.3g (need <= 1e-9), worst "
           "|f|/tau_y^2 %.3g (eta = 0, need <= 1e-10), worst inside |tau - C eps_tr|/|C eps_tr| %.3g (need <= 1e-10), worst stored b^E and J^P against exp(2 C^-1 tau) "
           "%.3g (need <= 1e-12)\n",
           near, far, worst_kkt, worst_f, worst_in, worst_state);
    CHECK(near >= 30 && far >= 10);
    CHECK(worst_kkt <= 1e-9);
    CHECK(worst_f <= 1e-10);
    CHECK(worst_in <= 1e-10);
    CHECK(worst_state <= 1e-12);
}

/* The largest |tau(Q F) - Q tau(F) Q^T| / |tau| over 10 plastic histories
 * of 6 steps each; the observer's turn rotates the velocity gradients
 * (L' = Q L Q^T). plane = 1 draws plane-strain gradients, as a 2D scene's
 * (no out-of-plane entries): the unrotated history then takes the plugin's
 * plane-strain path and the rotated one its general path. */
static double frame_error(const hearth_material *m, int plane) {
    double worst = 0;
    for (int k = 0; k < 10; k++) {
        const double p[NP] = {4e4, 0.3, 20, k % 2 ? 0 : 300, 0.5, 500, 1};
        double Q[9], st[NSTATE], str[NSTATE], F[9], Fr[9];
        random_rotation(Q);
        m->init(p, st);
        m->init(p, str);
        t3_identity(F);
        for (int s = 0; s < 6; s++) {
            const double dt = 1e-3;
            double L[9], Lr[9], QL[9], f[9], Fn[9], tau[9], taur[9], want[9], QT[9], d[9];
            for (int i = 0; i < 9; i++) L[i] = plane && (i % 3 == 2 || i >= 6) ? 0 : (2 * uni() - 1) * 0.05 / dt;
            for (int i = 0; i < 9; i++) f[i] = (i % 4 == 0) + dt * L[i];
            t3_mul(f, F, Fn);
            t3_copy(Fn, F);
            t3_mul(Q, L, QL);
            t3_mul_abt(QL, Q, Lr);
            t3_mul(Q, F, Fr);
            hearth_point a = {.dt = dt, .temperature = 50, .porosity = 0.2, .saturation = NAN, .p = p, .state = st};
            hearth_point b = a;
            b.state = str;
            memcpy(a.grad_v, L, sizeof L), memcpy(a.F, F, sizeof F);
            memcpy(b.grad_v, Lr, sizeof Lr), memcpy(b.F, Fr, sizeof Fr);
            CHECK(m->stress(&a, tau) == 0);
            CHECK(m->stress(&b, taur) == 0);
            t3_mul(Q, tau, QT);
            t3_mul_abt(QT, Q, want);
            for (int i = 0; i < 9; i++) d[i] = taur[i] - want[i];
            worst = fmax(worst, norm9(d) / fmax(1, norm9(tau)));
            CHECK(fabs(m->plastic_J(p, st) - m->plastic_J(p, str)) <= 1e-12);
        }
    }
    return worst;
}

/* tau(Q F) = Q tau(F) Q^T over a plastic history. */
TEST(dough_frame_indifference) {
    const hearth_material *m = dough();
    CHECK(m != NULL);
    if (!m) return;
    const double worst = frame_error(m, 0);
    printf("  worst |tau(QF) - Q tau(F) Q^T| / |tau| = %.3g over 10 plastic histories of 6 steps (need <= 1e-9)\n", worst);
    CHECK(worst <= 1e-9);
}

/* The plane-strain path (every point of a 2D scene) returns what the
 * general path returns for the same history seen in a turned frame. */
TEST(dough_plane_strain_path) {
    const hearth_material *m = dough();
    CHECK(m != NULL);
    if (!m) return;
    const double worst = frame_error(m, 1);
    printf("  worst |tau_general(QF) - Q tau_plane(F) Q^T| / |tau| = %.3g over 10 plastic plane-strain histories (need <= 1e-9)\n",
           worst);
    CHECK(worst <= 1e-9);
}

/* The extremes matrix: every corner returns finite numbers or a code that
 * describe_error documents; never NaN. Three steps each, so the stored state
 * is exercised too. */
TEST(dough_extremes) {
    const hearth_material *m = dough();
    CHECK(m != NULL);
    if (!m) return;
    const double Es[] = {1e2, 1e8}, etas[] = {0, 1e-3, 1e8}, nps[] = {1e-8, 0.1, 0.999}, tys[] = {1e-3, 1e5},
                 Ts[] = {-20, 400};
    /* the last three (and the two pure volume changes) take the plugin's near-rest path: a deviator of
     * 1e-9, one of 2%, and a volume compacted to e^-3 with a 5% deviator */
    const double strains[][3] = {{3, 3, 3},       {-3, -3, -3},         {3, -3, 0},           {-3, 3, 3}, {3, 0, 0},
                                 {0, 0, -3},      {1e-9, -1e-9, 0},     {0.02, -0.01, -0.01}, {-1, -1.05, -1}};
    const int NSTRAIN = (int)(sizeof strains / sizeof strains[0]);
    int cases = 0, codes = 0, bad = 0;
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < 3; b++)
            for (int c = 0; c < 3; c++)
                for (int d = 0; d < 2; d++)
                    for (int t = 0; t < 2; t++)
                        for (int e = 0; e < NSTRAIN; e++) {
                            const double p[NP] = {Es[a], 0.3, tys[d], etas[b], 0.5, 500, 1};
                            double R[9], f[9], eps_tr[9], tau[9], st[NSTATE];
                            random_rotation(R);
                            trial(strains[e], R, f, eps_tr);
                            int rc = step_from_rest(m, p, f, 1e-4, nps[c], Ts[t], st, tau);
                            for (int s = 0; s < 2 && rc == 0; s++) { /* two more steps at rest: evaluate the stored state */
                                hearth_point pt = {.dt = 1e-4, .temperature = Ts[t], .porosity = nps[c],
                                                   .saturation = NAN, .p = p, .state = st};
                                memcpy(pt.F, f, sizeof f);
                                memset(pt.grad_v, 0, sizeof pt.grad_v);
                                rc = m->stress(&pt, tau);
                            }
                            cases++;
                            if (rc) {
                                codes++;
                                const char *txt = m->describe_error(rc);
                                if (!txt || strcmp(txt, "unknown error") == 0) {
                                    bad++;
                                    fprintf(stderr, "undocumented code %d at E %g eta %g n %g tau_y %g strain %d\n", rc,
                                            p[P_E], p[P_ETA], nps[c], p[P_TAU_Y], e);
                                }
                                continue;
                            }
                            int finite = 1;
                            for (int i = 0; i < 9; i++) finite &= isfinite(tau[i]);
                            for (int i = 0; i < NSTATE; i++) finite &= isfinite(st[i]);
                            const double jp = m->plastic_J(p, st);
                            finite &= isfinite(jp) && jp > 0;
                            if (!finite) {
                                bad++;
                                fprintf(stderr, "non-finite at E %g eta %g n %g tau_y %g T %g strain %d\n", p[P_E],
                                        p[P_ETA], nps[c], p[P_TAU_Y], Ts[t], e);
                            }
                        }
    /* the documented refusals: porosity outside [0, 1), inverted F */
    const double p[NP] = {4e4, 0.3, 20, 0, 0.5, 500, 1};
    double st[NSTATE], tau[9], I[9];
    t3_identity(I);
    const int rc1 = step_from_rest(m, p, I, 1e-4, 1.0, 20, st, tau), rc2 = step_from_rest(m, p, I, 1e-4, -0.1, 20, st, tau);
    CHECK(rc1 > 0 && rc1 == rc2);
    CHECK_STR_CONTAINS(m->describe_error(rc1), "porosity");
    double Finv[9] = {-1, 0, 0, 0, 1, 0, 0, 0, 1};
    CHECK_STR_CONTAINS(m->describe_error(step_from_rest(m, p, Finv, 1e-4, 0.1, 20, st, tau)), "inverted");
    /* NaN porosity (the field off) reads as von Mises, not as an error */
    CHECK(step_from_rest(m, p, I, 1e-4, NAN, 20, st, tau) == 0);
    printf("  %d corners (E x eta x n^p x tau_y x T x log-strains from 1e-9 to +-3): %d finite, %d documented codes, %d bad\n", cases,
           cases - codes - bad, codes, bad);
    CHECK(bad == 0);
}

/* Closed pores: squeezed hard for many steps (the porosity passed as the
 * core computes it, n^p = 1 - (1 - n^p_0) / J^P), the dough compacts plastically
 * but never below J^P = 1 - compaction n^p_0, so n^p stays >= n^p_0 / 2 and
 * the gas pressure of eq. 13 stays bounded. */
TEST(dough_closed_pores) {
    const hearth_material *m = dough();
    CHECK(m != NULL);
    if (!m) return;
    const double p[NP] = {2e3, 0.3, 20, 0, 0.5, 500, 1}, n0 = 0.1, dt = 1e-3;
    double st[NSTATE], F[9], tau[9], jp_min = 1;
    m->init(p, st);
    t3_identity(F);
    for (int k = 0; k < 200; k++) {
        double L[9] = {0}, f[9], Fn[9];
        L[0] = L[4] = L[8] = -0.2; /* steady isotropic compression: 2e-4 volumetric strain per step */
        L[1] = 0.5;                /* and shear */
        for (int i = 0; i < 9; i++) f[i] = (i % 4 == 0) + dt * L[i];
        t3_mul(f, F, Fn);
        t3_copy(Fn, F);
        double np = 1 - (1 - n0) / m->plastic_J(p, st);
        hearth_point pt = {.dt = dt, .temperature = 20, .porosity = np < 1e-6 ? 1e-6 : np, .saturation = NAN, .p = p,
                           .state = st};
        memcpy(pt.grad_v, L, sizeof L), memcpy(pt.F, F, sizeof F);
        CHECK(m->stress(&pt, tau) == 0);
        jp_min = fmin(jp_min, m->plastic_J(p, st));
    }
    printf("  J = %.4f after 200 squeezing steps; smallest J^P = %.6f (cap 1 - 0.5 n0 = %.6f)\n", t3_det(F), jp_min,
           1 - 0.5 * n0);
    CHECK(jp_min < 1 - 0.25 * n0);             /* it did compact plastically */
    CHECK(jp_min >= 1 - 0.5 * n0 - 1e-12);     /* but not past the cap */
}

/* Stiffening pores: pulled apart hydrostatically for many steps (the gas
 * pressure of an inflating dough does this), the dough dilates plastically
 * up to n^p = max_porosity, J^P = (1 - n^p_0) / (1 - max_porosity), and no further;
 * without the cap (max_porosity 1) the same pull takes it past. */
TEST(dough_pore_cap) {
    const hearth_material *m = dough();
    CHECK(m != NULL);
    if (!m) return;
    const double n0 = 0.1, dt = 1e-3, cap = 0.3;
    double jp_end[2];
    for (int c = 0; c < 2; c++) {
        const double p[NP] = {2e3, 0.3, 20, 0, 0.5, 500, c ? 1 : cap};
        double st[NSTATE], F[9], tau[9];
        m->init(p, st);
        t3_identity(F);
        for (int k = 0; k < 300; k++) {
            double L[9] = {0}, f[9], Fn[9];
            L[0] = L[4] = L[8] = 0.4; /* steady isotropic expansion: 1.2e-3 volumetric strain per step */
            for (int i = 0; i < 9; i++) f[i] = (i % 4 == 0) + dt * L[i];
            t3_mul(f, F, Fn);
            t3_copy(Fn, F);
            double np = 1 - (1 - n0) / m->plastic_J(p, st);
            hearth_point pt = {.dt = dt, .temperature = 20, .porosity = np > 0.999999 ? 0.999999 : np, .saturation = NAN,
                               .p = p, .state = st};
            memcpy(pt.grad_v, L, sizeof L), memcpy(pt.F, F, sizeof F);
            CHECK(m->stress(&pt, tau) == 0);
        }
        jp_end[c] = m->plastic_J(p, st);
    }
    const double jcap = (1 - n0) / (1 - cap);
    printf("  J^P after 300 pulling steps: %.6f with max_porosity %g (cap (1 - n0) / (1 - %g) = %.6f), %.6f without\n",
           jp_end[0], cap, cap, jcap, jp_end[1]);
    CHECK(fabs(jp_end[0] - jcap) <= 1e-9); /* dilated up to the cap, not past it */
    CHECK(jp_end[1] > jcap + 0.05);        /* the uncapped dough goes on */
}

/* The core's cut-off of a cracked point (core/sim/material.h): the tensile
 * principal values of tau go to 0, the compressive ones and the principal
 * frame stay. tau = R diag(300, -200, 50) R^T, R a rotation about z. */
TEST(dough_tension_cutoff) {
    const double c = cos(0.3), s = sin(0.3), R[9] = {c, -s, 0, s, c, 0, 0, 0, 1}, l[3] = {300, -200, 50}, w[3] = {0, -200, 0};
    double tau[9], want[9], worst = 0;
    for (int r = 0; r < 3; r++)
        for (int k = 0; k < 3; k++) {
            tau[3 * r + k] = want[3 * r + k] = 0;
            for (int j = 0; j < 3; j++) tau[3 * r + k] += R[3 * r + j] * l[j] * R[3 * k + j], want[3 * r + k] += R[3 * r + j] * w[j] * R[3 * k + j];
        }
    material_tension_cutoff(tau);
    for (int i = 0; i < 9; i++) worst = fmax(worst, fabs(tau[i] - want[i]));
    printf("  cut-off error %.2e Pa\n", worst);
    CHECK(worst <= 1e-9);
    double cmp[9] = {-5, 1, 0, 1, -3, 0, 0, 0, -1}, orig[9]; /* all compressive: unchanged */
    memcpy(orig, cmp, sizeof cmp);
    material_tension_cutoff(cmp);
    for (int i = 0; i < 9; i++) CHECK(cmp[i] == orig[i]);
}

/* The shipped plugin's stress_block (<hearth/material.h> rule 7) against its
 * stress, point by point, bit for bit (tau, the state written, the code), on
 * 2D blocks built to cross every branch of the block's plane-strain path:
 * points inside the surface (the path itself), trials past the log-free
 * bound (the return map), porosity 0, NaN and out of range, out-of-plane
 * shear in the state or the step, a -0 shear, an inverted F, a non-finite
 * state, and the damage update; E and tau_y by point (curve columns) in one
 * block, uniform in the other. Counts how many points the law returned
 * plastically (the state's b^E is not the trial's), so both kinds are seen. */
TEST(dough_block_matches_stress_2d) {
    const hearth_material *m = dough();
    CHECK(m != NULL && m->stress_block != NULL);
    if (!m || !m->stress_block) return;
    enum { N = 64 };
    int elastic = 0, plastic = 0, refused = 0, differ = 0;
    for (int blk = 0; blk < 2; blk++) {
        double p[NP];
        for (int k = 0; k < NP; k++) p[k] = m->params[k].def;
        p[P_FRACTURE_STRAIN] = 0.02;
        double gv[9][N], F[9][N], T[N], n[N], Ec[N], tyc[N], st0[N * NSTATE], st1[N * NSTATE], st2[N * NSTATE];
        for (int j = 0; j < N; j++) {
            const double big = j % 4 == 3 ? 40.0 : 0.02; /* 1/s: a quarter of the points far past yield */
            for (int c = 0; c < 9; c++) gv[c][j] = (c == 2 || c == 5 || c == 6 || c == 7) ? 0 : big * (2 * uni() - 1);
            for (int c = 0; c < 9; c++) F[c][j] = (c % 4 == 0) + (c == 2 || c == 5 || c == 6 || c == 7 ? 0 : 0.05 * (2 * uni() - 1));
            double *s = st0 + j * NSTATE;
            m->init(p, s);
            /* an advanced state inside the surface: elastic strains of 1e-4 against tau_y / E = 5e-4 */
            s[0] = 1 + 2e-4 * (2 * uni() - 1), s[1] = 1 + 2e-4 * (2 * uni() - 1), s[2] = 1 + 1e-4 * uni();
            s[3] = 1e-4 * (2 * uni() - 1), s[6] = 1 + 0.02 * (2 * uni() - 1);
            n[j] = 0.05 + 0.2 * uni();
            T[j] = 20 + 100 * uni();
            Ec[j] = p[P_E] * (0.5 + uni()), tyc[j] = p[P_TAU_Y] * (0.5 + uni());
        }
        n[1] = 0, n[2] = NAN, n[5] = 1.5;                 /* von Mises; NaN reads as 0; refused */
        st0[4 * NSTATE + 4] = 0.001;                      /* point 4: out-of-plane shear in the state */
        gv[2][8] = 0.5;                                   /* point 8: out-of-plane step */
        st0[12 * NSTATE + 3] = -0.0, st0[13 * NSTATE + 4] = -0.0; /* -0 shears */
        gv[1][12] = gv[3][12] = 0;                        /* point 12: no in-plane shear at all (no rotation) */
        /* point 14: no rotation, tension along x and compression along y, so eigen_plane's +0 off-diagonal
         * entries of Q give tau_xy = +0 where a -0 in their place gives -0 */
        for (int c = 0; c < 9; c++) gv[c][14] = 0;
        st0[14 * NSTATE + 0] = 1 + 2e-4, st0[14 * NSTATE + 1] = 1 - 2e-4, st0[14 * NSTATE + 2] = 1, st0[14 * NSTATE + 3] = 0;
        F[0][16] = -1;                                    /* inverted */
        st0[20 * NSTATE + 2] = INFINITY;                  /* not finite */
        st0[24 * NSTATE + 7] = 0.999;                     /* damage near 1 */
        const double dt = 1e-3;
        /* one point at a time */
        memcpy(st1, st0, sizeof st0);
        double tau1[N][9];
        int code1[N];
        for (int j = 0; j < N; j++) {
            double q[NP];
            memcpy(q, p, sizeof q);
            if (blk == 1) q[P_E] = Ec[j], q[P_TAU_Y] = tyc[j];
            hearth_point pt = {.dt = dt, .temperature = T[j], .porosity = n[j], .saturation = NAN, .p = q,
                               .state = st1 + j * NSTATE, .dim = 2};
            for (int c = 0; c < 9; c++) pt.grad_v[c] = gv[c][j], pt.F[c] = F[c][j];
            for (int c = 0; c < 9; c++) tau1[j][c] = 0;
            code1[j] = m->stress(&pt, tau1[j]);
        }
        /* the block */
        memcpy(st2, st0, sizeof st0);
        double tcol[9][N];
        double *tau2[9];
        const double *columns[NP] = {0};
        if (blk == 1) columns[P_E] = Ec, columns[P_TAU_Y] = tyc;
        hearth_block b = {.n = N, .dim = 2, .dt = dt, .temperature = T, .porosity = n, .saturation = NULL, .p = p,
                          .p_col = columns, .state = st2, .state_stride = NSTATE};
        for (int c = 0; c < 9; c++) b.grad_v[c] = gv[c], b.F[c] = F[c], tau2[c] = tcol[c];
        int code2[N];
        m->stress_block(&b, tau2, code2);
        for (int j = 0; j < N; j++) {
            int same = code1[j] == code2[j] && memcmp(st1 + j * NSTATE, st2 + j * NSTATE, NSTATE * sizeof(double)) == 0;
            if (!code1[j])
                for (int c = 0; c < 9; c++) same &= memcmp(&tau1[j][c], &tcol[c][j], sizeof(double)) == 0;
            if (!same) {
                printf("  block %d point %d differs (codes %d, %d)\n", blk, j, code1[j], code2[j]);
                differ++;
            }
            if (code1[j]) {
                refused++;
                continue;
            }
            /* elastic: the stored b^E is the trial f b f^T (its xx entry, recomputed as the law does) */
            const double *s = st0 + j * NSTATE;
            const double f0 = 1 + dt * gv[0][j], f1 = dt * gv[1][j];
            const double g0 = f0 * s[0] + f1 * s[3], g1 = f0 * s[3] + f1 * s[1];
            if (st1[j * NSTATE] == g0 * f0 + g1 * f1) elastic++;
            else plastic++;
        }
    }
    printf("  %d points: %d elastic, %d plastic, %d refused; %d differ between stress and stress_block\n", 2 * N, elastic,
           plastic, refused, differ);
    CHECK(differ == 0);
    CHECK(elastic >= 40 && plastic >= 20 && refused >= 4);
}

/* `hearth plugin check` on the built plugin. */
TEST(dough_plugin_check) {
    const hearth_material *m = check_built_plugin("cam_clay_dough");
    if (!m) return;
    CHECK(m->plastic_J != NULL);
    CHECK((m->needs & (HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_POROSITY | HEARTH_NEEDS_THERMAL_EXPANSION)) ==
          (HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_POROSITY | HEARTH_NEEDS_THERMAL_EXPANSION));
}

TEST_MAIN(T(dough_closest_point), T(dough_viscoplastic_optimality), T(dough_inside_unchanged), T(dough_von_mises_limit),
          T(dough_frame_indifference), T(dough_plane_strain_path), T(dough_near_identity_return), T(dough_extremes),
          T(dough_closed_pores), T(dough_pore_cap), 
          
          T(dough_tension_cutoff),
          T(dough_block_matches_stress_2d), T(dough_plugin_check))
