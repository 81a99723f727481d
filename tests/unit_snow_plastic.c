/* unit_snow_plastic.c: the snow_plastic plugin (Stomakhin et al. 2013 §5:
 * fixed-corotated elasticity, elastic singular values clamped to
 * [1 - theta_c, 1 + theta_s], hardening e^{xi (1 - J_P)}) through its ABI,
 * against closed forms computed here from an SVD of the step alone.
 *
 * Every case starts from rest (F_E = I) and takes one step f = I + dt L, so
 * the trial F_E is f: its singular values s_i and left singular vectors U
 * come from tensor.h's SVD, not from the plugin. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "hearth/hearth.h"
#include "hearth/material.h"
#include "tensor.h"
#include "test.h"
#define PLUGIN_FIXTURE_SEED 0x5a0f1a7e
#include "plugin_fixture.h"

enum { P_E, P_NU, P_DENSITY, P_THETA_C, P_THETA_S, P_XI, NP };
enum { NSTATE = 7, S_JP = 6 };

static const hearth_material *snow(void) { return load_material("snow_plastic"); }

/* f = R1 diag(exp(e)) R2^T: singular values exp(e), left vectors R1. */
static void step_with(const double e[3], const double R1[9], const double R2[9], double f[9]) {
    double D[9] = {0}, RD[9];
    for (int i = 0; i < 3; i++) D[4 * i] = exp(e[i]);
    t3_mul(R1, D, RD);
    t3_mul_abt(RD, R2, f);
}

/* The expected return from rest (header of plugins/snow_plastic.c): clamp
 * the singular values of f, J_P = det f / J_E, and
 * tau = U diag(2 h mu (s^2 - s) + h lambda (J_E - 1) J_E) U^T. */
static void expected(const double *p, const double f[9], double tau[9], double *jp, double sc[3]) {
    double U[9], s[3], V[9];
    t3_svd(f, U, s, V);
    double mu, la;
    lame_from(p[P_E], p[P_NU], &mu, &la);
    for (int i = 0; i < 3; i++) sc[i] = fmin(fmax(s[i], 1 - p[P_THETA_C]), 1 + p[P_THETA_S]);
    const double JE = sc[0] * sc[1] * sc[2];
    *jp = t3_det(f) / JE;
    const double h = exp(p[P_XI] * (1 - *jp));
    double d[3];
    for (int i = 0; i < 3; i++) d[i] = 2 * h * mu * (sc[i] * sc[i] - sc[i]) + h * la * (JE - 1) * JE;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            tau[3 * r + c] = 0;
            for (int k = 0; k < 3; k++) tau[3 * r + c] += U[3 * r + k] * d[k] * U[3 * c + k];
        }
}

static void sort_down(double s[3]) {
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (s[j] > s[i]) {
                const double t = s[i];
                s[i] = s[j], s[j] = t;
            }
}

/* The stored b_E's eigenvalues, as singular values of F_E, sorted. */
static void stored_stretches(const double *st, double s[3]) {
    const double B[9] = {st[0], st[3], st[5], st[3], st[1], st[4], st[5], st[4], st[2]};
    double l[3], Q[9];
    t3_sym_eigen(B, l, Q);
    for (int i = 0; i < 3; i++) s[i] = sqrt(l[i]);
    sort_down(s);
}

/* Past the clamp: the stored elastic stretches are the clamped singular
 * values of f (so they lie in [1 - theta_c, 1 + theta_s]), J_P takes the
 * rest, and tau is the hardened fixed-corotated stress of the clamped F_E. */
TEST(snow_clamp_respected) {
    const hearth_material *m = snow();
    CHECK(m != NULL);
    if (!m) return;
    double worst_s = 0, worst_tau = 0, worst_jp = 0, outside = 0;
    for (int k = 0; k < 60; k++) {
        const double p[NP] = {1e3 + 1e5 * uni(), 0.45 * uni(), 500, 0.01 + 0.1 * uni(), 0.002 + 0.02 * uni(), 20 * uni()};
        double e[3], R1[9], R2[9], f[9], st[NSTATE], tau[9], want[9], jp, sc[3], s[3], d[9];
        for (int i = 0; i < 3; i++) e[i] = (2 * uni() - 1) * 0.3;
        random_rotation(R1);
        random_rotation(R2);
        step_with(e, R1, R2, f);
        CHECK(step_from_rest(m, p, f, 1e-3, NAN, NAN, st, tau) == 0);
        expected(p, f, want, &jp, sc);
        stored_stretches(st, s);
        sort_down(sc);
        for (int i = 0; i < 3; i++) {
            worst_s = fmax(worst_s, fabs(s[i] - sc[i]));
            outside = fmax(outside, fmax(1 - p[P_THETA_C] - s[i], s[i] - 1 - p[P_THETA_S]));
        }
        for (int i = 0; i < 9; i++) d[i] = tau[i] - want[i];
        worst_tau = fmax(worst_tau, norm9(d) / fmax(1, norm9(want)));
        worst_jp = fmax(worst_jp, fabs(m->plastic_J(p, st) - jp));
    }
    printf("  worst |s_E - clamp(s)| %.3g, past the clamp by %.3g, |tau - closed form| / |tau| %.3g, |J_P - det f / J_E| %.3g\n",
           worst_s, outside, worst_tau, worst_jp);
    CHECK(worst_s <= 1e-12);
    CHECK(outside <= 1e-12);
    CHECK(worst_tau <= 1e-9);
    CHECK(worst_jp <= 1e-12);
}

/* Inside the clamp: nothing is plastic. b_E = f f^T, J_P = 1, and tau is the
 * fixed-corotated stress 2 mu (F - R) F^T + lambda (J - 1) J I of f itself
 * (R from the polar decomposition). */
TEST(snow_elastic_inside) {
    const hearth_material *m = snow();
    CHECK(m != NULL);
    if (!m) return;
    double worst_b = 0, worst_tau = 0, worst_jp = 0;
    for (int k = 0; k < 40; k++) {
        const double p[NP] = {4e4, 0.3, 500, 2.5e-2, 7.5e-3, 10};
        double e[3], R1[9], R2[9], f[9], st[NSTATE], tau[9], R[9], S[9], FR[9], want[9], b[9], d[9];
        for (int i = 0; i < 3; i++) e[i] = log(1 - 0.02 + 0.026 * uni()); /* inside [0.975, 1.0075] */
        random_rotation(R1);
        random_rotation(R2);
        step_with(e, R1, R2, f);
        CHECK(step_from_rest(m, p, f, 1e-3, NAN, NAN, st, tau) == 0);
        t3_polar(f, R, S);
        double mu, la;
        lame_from(p[P_E], p[P_NU], &mu, &la);
        const double J = t3_det(f);
        for (int i = 0; i < 9; i++) FR[i] = f[i] - R[i];
        t3_mul_abt(FR, f, want);
        for (int i = 0; i < 9; i++) want[i] = 2 * mu * want[i] + (i % 4 == 0 ? la * (J - 1) * J : 0);
        for (int i = 0; i < 9; i++) d[i] = tau[i] - want[i];
        worst_tau = fmax(worst_tau, norm9(d) / norm9(want));
        t3_mul_abt(f, f, b);
        const double sb[6] = {b[0], b[4], b[8], b[1], b[5], b[2]};
        for (int i = 0; i < 6; i++) worst_b = fmax(worst_b, fabs(st[i] - sb[i]));
        worst_jp = fmax(worst_jp, fabs(m->plastic_J(p, st) - 1));
    }
    printf("  worst |b_E - f f^T| %.3g, |tau - fixed corotated| / |tau| %.3g, |J_P - 1| %.3g\n", worst_b, worst_tau, worst_jp);
    CHECK(worst_b <= 1e-13);
    CHECK(worst_tau <= 1e-9);
    CHECK(worst_jp <= 1e-13);
}

/* tau(Q F) = Q tau(F) Q^T and the same J_P over a plastic history: the
 * observer's turn rotates the velocity gradients (L' = Q L Q^T). */
TEST(snow_frame_indifference) {
    const hearth_material *m = snow();
    CHECK(m != NULL);
    if (!m) return;
    double worst = 0, worst_jp = 0, jp_min = 1, jp_max = 1;
    for (int k = 0; k < 10; k++) {
        const double p[NP] = {4e4, 0.3, 500, 2.5e-2, 7.5e-3, 10};
        double Q[9], st[NSTATE], str[NSTATE], F[9], Fr[9];
        random_rotation(Q);
        m->init(p, st);
        m->init(p, str);
        t3_identity(F);
        for (int s = 0; s < 6; s++) {
            const double dt = 1e-3;
            double L[9], Lr[9], QL[9], f[9], Fn[9], tau[9], taur[9], want[9], Qtau[9], d[9];
            for (int i = 0; i < 9; i++) L[i] = (2 * uni() - 1) * 0.05 / dt;
            for (int i = 0; i < 9; i++) f[i] = (i % 4 == 0) + dt * L[i];
            t3_mul(f, F, Fn);
            t3_copy(Fn, F);
            t3_mul(Q, L, QL);
            t3_mul_abt(QL, Q, Lr);
            t3_mul(Q, F, Fr);
            hearth_point a = {.dt = dt, .temperature = NAN, .porosity = NAN, .saturation = NAN, .p = p, .state = st};
            hearth_point b = a;
            b.state = str;
            memcpy(a.grad_v, L, sizeof L), memcpy(a.F, F, sizeof F);
            memcpy(b.grad_v, Lr, sizeof Lr), memcpy(b.F, Fr, sizeof Fr);
            CHECK(m->stress(&a, tau) == 0);
            CHECK(m->stress(&b, taur) == 0);
            t3_mul(Q, tau, Qtau);
            t3_mul_abt(Qtau, Q, want);
            for (int i = 0; i < 9; i++) d[i] = taur[i] - want[i];
            worst = fmax(worst, norm9(d) / fmax(1, norm9(tau)));
            worst_jp = fmax(worst_jp, fabs(m->plastic_J(p, st) - m->plastic_J(p, str)));
            jp_min = fmin(jp_min, m->plastic_J(p, st)), jp_max = fmax(jp_max, m->plastic_J(p, st));
        }
    }
    printf("  worst |tau(QF) - Q tau Q^T| / |tau| %.3g, |J_P - J_P'| %.3g over J_P in [%.4f, %.4f]\n", worst, worst_jp,
           jp_min, jp_max);
    CHECK(jp_min < 0.99 || jp_max > 1.01); /* the history was plastic */
    CHECK(worst <= 1e-9);
    CHECK(worst_jp <= 1e-12);
}

/* Every parameter at its schema's ends, trial log-stretches up to +-3 over
 * ten steps: tau finite and wave_speed finite and > 0, or a code
 * describe_error explains. Bad input gives its documented code. */
TEST(snow_extremes) {
    const hearth_material *m = snow();
    CHECK(m != NULL);
    if (!m) return;
    int cases = 0, bad = 0;
    for (int i = 0; i < NP; i++)
        for (int side = 0; side < 2; side++)
            for (int dir = 0; dir < 4; dir++) {
                double p[NP];
                for (int j = 0; j < NP; j++) p[j] = m->params[j].def;
                p[i] = side ? m->params[i].max : m->params[i].min;
                /* log-stretch per step 0.3: ten steps reach +-3 */
                const double rates[4][3] = {{0.3, 0.3, 0.3}, {-0.3, -0.3, -0.3}, {0.3, -0.3, 0}, {-0.3, 0.3, 0.3}};
                double R[9], st[NSTATE], F[9], tau[9];
                random_rotation(R);
                m->init(p, st);
                t3_identity(F);
                for (int s = 0; s < 10; s++) {
                    const double dt = 1e-3;
                    double f[9], Fn[9];
                    step_with(rates[dir], R, R, f);
                    t3_mul(f, F, Fn);
                    t3_copy(Fn, F);
                    hearth_point pt = {.dt = dt, .temperature = NAN, .porosity = NAN, .saturation = NAN, .p = p, .state = st};
                    for (int j = 0; j < 9; j++) pt.grad_v[j] = (f[j] - (j % 4 == 0)) / dt;
                    memcpy(pt.F, F, sizeof F);
                    const int rc = m->stress(&pt, tau);
                    cases++;
                    if (rc) {
                        const char *t = m->describe_error(rc);
                        if (!t || strcmp(t, "unknown error") == 0) bad++;
                        break;
                    }
                    for (int j = 0; j < 9; j++)
                        if (!isfinite(tau[j])) bad++;
                    const double c = m->wave_speed(p, st);
                    if (!(isfinite(c) && c > 0)) bad++;
                    if (!isfinite(m->plastic_J(p, st))) bad++;
                }
            }
    printf("  %d steps over %d parameter ends x 4 directions: %d not finite or unexplained\n", cases, 2 * NP, bad);
    CHECK(bad == 0);
    /* bad input: an inverted F, a NaN state, a step that inverts */
    const double p[NP] = {4e4, 0.3, 500, 2.5e-2, 7.5e-3, 10};
    double st[NSTATE], tau[9];
    const double Finv[9] = {-1, 0, 0, 0, 1, 0, 0, 0, 1};
    CHECK_STR_CONTAINS(m->describe_error(step_from_rest(m, p, Finv, 1e-4, NAN, NAN, st, tau)), "inverted");
    m->init(p, st);
    st[S_JP] = NAN;
    hearth_point pt = {.dt = 1e-4, .temperature = NAN, .porosity = NAN, .saturation = NAN, .p = p, .state = st};
    for (int j = 0; j < 9; j++) pt.grad_v[j] = 0, pt.F[j] = j % 4 == 0;
    CHECK_STR_CONTAINS(m->describe_error(m->stress(&pt, tau)), "not finite");
    m->init(p, st);
    pt.grad_v[0] = -2 / pt.dt; /* f_xx = -1 */
    CHECK_STR_CONTAINS(m->describe_error(m->stress(&pt, tau)), "step inverts");
}

/* `hearth plugin check` on the built plugin; the schema's units and help. */
TEST(snow_plugin_check) {
    const hearth_material *m = check_built_plugin("snow_plastic");
    if (!m) return;
    CHECK(m->plastic_J != NULL);
    CHECK(m->needs == 0); /* no temperature, gas or expansion: the Stomakhin-like baseline */
}

TEST_MAIN(T(snow_clamp_respected), T(snow_elastic_inside), T(snow_frame_indifference), T(snow_extremes),
          T(snow_plugin_check))
