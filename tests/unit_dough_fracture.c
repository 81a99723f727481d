/* unit_dough_fracture.c: cam_clay_dough's crust fracture (issue #18) through
 * its ABI, one material point at a time: the damage of the elastic strain
 * rule, the stretch rule's Miner sum over the strain to fracture (the set
 * crumb's, the heat-set's share of the water's brittleness), and the crack
 * band's softening over Bazant & Oh's crack strain (the solver's side of the
 * band is tests/unit_crack_band.c). Split from unit_dough.c, which keeps the
 * return mapping of eq. 12. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "hearth/hearth.h"
#include "hearth/material.h"
#include "material.h"
#include "tensor.h"
#include "test.h"
#define PLUGIN_FIXTURE_SEED 0x0d0cf7ac
#include "plugin_fixture.h"
#include "dough_params.h"

static const hearth_material *dough(void) { return load_material("cam_clay_dough"); }

/* Damage (the header's "crust fracture"): D is the largest fraction of
 * fracture_strain that the largest principal deviatoric elastic Hencky strain
 * has reached. A steady pure-shear stretch L = diag(a, -a, 0) of an elastic
 * point (tau_y 1e9) has, after k steps, the Hencky strains k log(1 + a dt),
 * k log(1 - a dt), 0, so D = min(1, e1 / eps_f) with e1 their largest minus
 * their mean, on the plane path and the general (3D) one. A uniform dilation
 * and fracture_strain 0 leave D at 0; a ductile point (tau_y 20 Pa, E 2e3 Pa:
 * yield strain ~0.01 < eps_f = 0.05) yields and never cracks. */
TEST(dough_fracture_damage) {
    const hearth_material *m = dough();
    CHECK(m != NULL && m->damage != NULL);
    if (!m || !m->damage) return;
    const double dt = 1e-3, a = 5.0, ef = 0.05;
    double dmax[5];
    for (int c = 0; c < 5; c++) { /* 0 plane, 1 general, 2 dilation, 3 fracture off, 4 ductile */
        const double p[NP] = {2e3, 0.3, c == 4 ? 20 : 1e9, 0, 0.5, 500, 1, c == 3 ? 0 : ef};
        double st[NSTATE], F[9], tau[9], L[9] = {0};
        if (c == 2) L[0] = L[4] = L[8] = 0.4;
        else L[0] = a, L[4] = -a;
        if (c == 1) L[2] = L[6] = 1e-9; /* off the plane: the general path */
        m->init(p, st);
        t3_identity(F);
        double worst = 0;
        for (int k = 1; k <= 80; k++) {
            double f[9], Fn[9];
            for (int i = 0; i < 9; i++) f[i] = (i % 4 == 0) + dt * L[i];
            t3_mul(f, F, Fn);
            t3_copy(Fn, F);
            hearth_point pt = {.dt = dt, .temperature = 20, .porosity = 0.1, .saturation = NAN, .p = p, .state = st};
            memcpy(pt.grad_v, L, sizeof L), memcpy(pt.F, F, sizeof F);
            CHECK(m->stress(&pt, tau) == 0);
            const double e0 = k * log1p(a * dt), e1 = k * log1p(-a * dt), e1max = e0 - (e0 + e1) / 3;
            const double want = c >= 2 ? 0 : fmin(1, e1max / ef);
            if (c != 4) worst = fmax(worst, fabs(m->damage(p, st) - want)); /* 4: only bounded, below */
        }
        dmax[c] = m->damage(p, st);
        printf("  case %d: damage after 80 steps %.6f, largest error against the closed form %.2e\n", c, dmax[c], worst);
        CHECK(worst <= (c == 1 ? 1e-6 : 1e-9));
    }
    CHECK(dmax[0] == 1 && dmax[1] == 1); /* the elastic point cracked (e1 reaches 0.05 near step 10) */
    CHECK(dmax[4] > 0 && dmax[4] < 0.5); /* the ductile one yielded first: its elastic strain stays near tau_y / E */
}

/* The stretch rule (fracture_stretch = 1, the header's "crust fracture"):
 * D adds sqrt(2/3) N : D dt / eps_f a step, N the unit deviatoric elastic
 * strain after the step. An elastic point (tau_y 1e9) in pure shear L =
 * diag(a, -a, 0) has principal Hencky strains h = (k log(1 + a dt), k log(1 -
 * a dt), 0) after k steps, so the closed form sums e.L / |e| over the steps,
 * e = h - mean(h). Cases: 0 stretched while brittle (eps_f 0.2) against that
 * sum; 1 stretched while wet (eps_f 1), then dried (eps_f 0.02) at rest: the
 * stretch rule keeps D, the elastic rule cracks it (the band of session 28);
 * 2 stretched 20 steps and back 20: D returns; 3 uniform dilation: 0. The
 * closed form is summed here from h, not by the plugin's code. */
TEST(dough_fracture_stretch_rule) {
    const hearth_material *m = dough();
    CHECK(m != NULL && m->damage != NULL);
    if (!m || !m->damage) return;
    const double dt = 1e-3, a = 5.0;
    double dend[5], dpeak[5];
    for (int c = 0; c < 5; c++) { /* 4: case 1 under the elastic rule */
        double p[NP] = {2e3, 0.3, 1e9, 0, 0.5, 500, 1, c == 1 || c == 4 ? 1 : 0.2, c == 4 ? 0 : 1};
        double st[NSTATE], F[9], tau[9];
        m->init(p, st);
        t3_identity(F);
        double worst = 0, want = 0, h0 = 0, h1 = 0;
        dpeak[c] = 0;
        for (int k = 1; k <= 60; k++) {
            double L[9] = {0};
            const double sg = c == 2 && k > 20 ? -1 : 1;
            if (c == 3) L[0] = L[4] = L[8] = 0.4;
            else if (!((c == 1 || c == 4) && k > 20) && !(c == 2 && k > 40)) L[0] = sg * a, L[4] = -sg * a;
            if ((c == 1 || c == 4) && k > 20) p[P_FRACTURE_STRAIN] = 0.02; /* dried at rest */
            double f[9], Fn[9];
            for (int i = 0; i < 9; i++) f[i] = (i % 4 == 0) + dt * L[i];
            t3_mul(f, F, Fn);
            t3_copy(Fn, F);
            hearth_point pt = {.dt = dt, .temperature = 20, .porosity = 0.1, .saturation = NAN, .p = p, .state = st};
            memcpy(pt.grad_v, L, sizeof L), memcpy(pt.F, F, sizeof F);
            CHECK(m->stress(&pt, tau) == 0);
            h0 += log1p(L[0] * dt), h1 += log1p(L[4] * dt);
            if (c == 0 || c == 2) { /* the closed form, for a point that never cracks before the end (case 2) or does */
                const double mean = (h0 + h1) / 3, e0 = h0 - mean, e1 = h1 - mean, e2 = -mean;
                const double ne = sqrt(e0 * e0 + e1 * e1 + e2 * e2);
                if (ne > 0 && want < 1) want = fmin(1, fmax(0, want + sqrt(2.0 / 3.0) * (e0 * L[0] + e1 * L[4]) / ne * dt / 0.2));
                worst = fmax(worst, fabs(m->damage(p, st) - want));
            }
            dpeak[c] = fmax(dpeak[c], m->damage(p, st));
        }
        dend[c] = m->damage(p, st);
        printf("  case %d: damage peak %.6f, end %.6f; largest error against the closed form %.2e\n", c, dpeak[c], dend[c],
               worst);
        CHECK(worst <= 1e-9);
    }
    CHECK(dend[0] == 1);                           /* 0.2 of stretch along the strain: cracked (near step 35) */
    CHECK(dend[1] < 0.15 && dend[1] == dpeak[1]);  /* wet stretch counted at eps_f 1; drying at rest adds nothing */
    CHECK(dend[4] == 1);                           /* the elastic rule cracks the same point as it dries */
    CHECK(dpeak[2] > 0.4 && dend[2] < 0.1 * dpeak[2]); /* stretched and let back: given back (log(1+x) + log(1-x) < 0
                                                          leaves a small deviator the other way) */
    CHECK(dend[3] < 1e-12);                        /* a uniform dilation is pores, not a crack (roundoff only) */
}

/* An elastic point (tau_y 1e9) in pure shear at rate a (L = diag(a, -a, 0)),
 * 30 steps of dt 1e-3 under the stretch rule, against the closed form of the
 * damage summed here with strain to fracture want_ef: returns the largest
 * difference over the steps, and the final damage in *d_end. */
static double shear_damage_error(const hearth_material *m, const double *p, double want_ef, double *d_end) {
    const double dt = 1e-3, a = 5.0;
    double st[NSTATE], F[9], tau[9], L[9] = {0};
    L[0] = a, L[4] = -a;
    m->init(p, st);
    t3_identity(F);
    double worst = 0, want = 0, h0 = 0, h1 = 0;
    for (int k = 1; k <= 30; k++) {
        double f[9], Fn[9];
        for (int i = 0; i < 9; i++) f[i] = (i % 4 == 0) + dt * L[i];
        t3_mul(f, F, Fn);
        t3_copy(Fn, F);
        hearth_point pt = {.dt = dt, .temperature = 20, .porosity = 0.1, .saturation = NAN, .p = p, .state = st};
        memcpy(pt.grad_v, L, sizeof L), memcpy(pt.F, F, sizeof F);
        CHECK(m->stress(&pt, tau) == 0);
        h0 += log1p(a * dt), h1 += log1p(-a * dt);
        const double mean = (h0 + h1) / 3, e0 = h0 - mean, e1 = h1 - mean, e2 = -mean;
        const double ne = sqrt(e0 * e0 + e1 * e1 + e2 * e2);
        if (ne > 0 && want < 1) want = fmin(1, fmax(0, want + sqrt(2.0 / 3.0) * (e0 * a - e1 * a) / ne * dt / want_ef));
        worst = fmax(worst, fabs(m->damage(p, st) - want));
    }
    *d_end = m->damage(p, st);
    return worst;
}

/* The set crumb's strain to fracture (fracture_strain_set, the header's "the
 * set crumb"): under the stretch rule a point's strain to fracture is the
 * smaller of fracture_strain and fracture_strain_set (when > 0). The same
 * elastic point in pure shear as dough_fracture_stretch_rule, against the
 * closed form summed here with eps_f = 0.2, in three cases: 0 wet (100) but
 * set (0.2); 1 dried (0.2) and set at 5 (the dry value rules); 2 wet (100)
 * with no set value (0): D stays at 0.2/100 of the others'. */
TEST(dough_fracture_set_takes_smaller) {
    const hearth_material *m = dough();
    CHECK(m != NULL && m->damage != NULL);
    if (!m || !m->damage) return;
    const double efs[3] = {100, 0.2, 100}, sets[3] = {0.2, 5, 0}, want_ef[3] = {0.2, 0.2, 100};
    for (int c = 0; c < 3; c++) {
        const double p[NP] = {2e3, 0.3, 1e9, 0, 0.5, 500, 1, efs[c], 1, sets[c]};
        double d;
        const double worst = shear_damage_error(m, p, want_ef[c], &d);
        printf("  case %d (fracture_strain %g, fracture_strain_set %g): damage %.6f, largest error against the closed "
               "form %.2e\n", c, efs[c], sets[c], d, worst);
        CHECK(worst <= 1e-9);
        CHECK(c == 2 ? d < 0.01 : d > 0.5); /* the cases tell the two strains apart */
    }
}

/* The heat-set (fracture_unset, the header's "the heat-set"): under the
 * stretch rule the water's strain to fracture counts as fracture_strain /
 * (1 - fracture_unset), and the set crumb's (fracture_strain_set) as it is.
 * The same elastic point in pure shear as dough_fracture_set_takes_smaller,
 * fracture_strain 0.2 (a dried skin), against the closed form summed with
 * the strain to fracture each case should have: 0 set (unset 0): 0.2, the
 * rule as before; 1 half set: 0.4, half the damage; 2 raw (unset 1): none;
 * 3 raw but with a set crumb's 0.2: 0.2 (the set itself is not gated). */
TEST(dough_fracture_unset_gates_water_brittleness) {
    const hearth_material *m = dough();
    CHECK(m != NULL && m->damage != NULL);
    if (!m || !m->damage) return;
    const double unset[4] = {0, 0.5, 1, 1}, sets[4] = {0, 0, 0, 0.2}, want_ef[4] = {0.2, 0.4, INFINITY, 0.2};
    double dend[4];
    for (int c = 0; c < 4; c++) {
        const double p[NP] = {2e3, 0.3, 1e9, 0, 0.5, 500, 1, 0.2, 1, sets[c], 0, 0, unset[c]};
        const double worst = shear_damage_error(m, p, want_ef[c], &dend[c]);
        printf("  case %d (fracture_unset %g, fracture_strain_set %g): damage %.6f, largest error against the closed "
               "form %.2e\n", c, unset[c], sets[c], dend[c], worst);
        CHECK(worst <= 1e-9);
    }
    CHECK(dend[0] > 0.5);                         /* dried and set: the skin spends its stretch */
    CHECK(fabs(dend[1] - 0.5 * dend[0]) <= 1e-9); /* half set: half the brittleness */
    CHECK(dend[2] == 0);                          /* dried but raw: leathery, nothing */
    CHECK(fabs(dend[3] - dend[0]) <= 1e-9);       /* the set crumb's strain is not gated */
}

/* The crack band (crack_opening w_c, crack_band h; the header's "the crack
 * band", Bazant & Oh 1983): past its fracture strain eps_f a point's tension
 * falls linearly from the peak's to 0 over the crack strain w_c / h - eps_f,
 * so the work per volume to separation of a point that stays elastic, its
 * elastic energy at the peak (f_t eps_f / 2) and the softening's
 * (f_t (w_c / h - eps_f) / 2), is f_t w_c / (2 h): h times it, the energy per
 * unit crack area, is G_f = f_t w_c / 2 whatever h (issue #18, helper
 * crackband; before, the tension was the undamaged one times 1 - x / (w_c /
 * h), which grows past the peak, and the elastic energy at the peak came on
 * top: tests/unit_crack_band.c). A point in pure shear (dough_fracture_stretch_rule's L,
 * eps_f 0.05), w_c 1 mm, at h = 2, 4 and 8 mm (w_c / h 0.5, 0.25, 0.125, all
 * above eps_f: a band that can take G_f at f_t), next to a twin without the
 * band (w_c 0) that keeps the law's own stress; two points: an elastic one
 * (tau_y 1e9), whose tension must fall on the line f_t (1 - x / (w_c / h -
 * eps_f)) at x past the peak (to two steps' share of it, and two of the
 * peak's strain: f_t is read at the step that passes it), and whose h times
 * the trapezoid sum of the tension over the stretch from rest is f_t w_c / 2
 * (2%), the same at the three h (2%); and one that yields (tau_y 20 Pa, its
 * tension flat at the yield surface past ~0.01 of strain), whose tension is
 * the twin's times 1 - x / (w_c / h - eps_f) (two steps' share), so its
 * softening takes h f_t (w_c / h - eps_f) / 2 (2%): eps_f h f_t / 2 less
 * than G_f, the pre-peak share, which it spent as plastic work. In both, the
 * stretch sqrt(2/3) N : L dt summed from damage 0.5 (the peak) to 1 is
 * w_c / h - eps_f (to two steps' stretch); f_t the twin's tension at the
 * peak. */
TEST(dough_crack_band_softening) {
    const hearth_material *m = dough();
    CHECK(m != NULL && m->damage != NULL);
    if (!m || !m->damage) return;
    const double dt = 2e-5, a = 5.0, ef = 0.05, wc = 1e-3, hs[3] = {2e-3, 4e-3, 8e-3};
    for (int y = 0; y < 2; y++) { /* 0 yields, 1 elastic */
        double G[3];
        for (int c = 0; c < 3; c++) {
            const double eb = wc / hs[c], u = eb - ef, step = sqrt(2.0 / 3.0) * 2 * a * dt / sqrt(2.0); /* the stretch a step takes */
            double p[NP] = {2e3, 0.3, y ? 1e9 : 20, 0, 0.5, 500, 1, ef, 1, 0, wc, hs[c]}, q[NP];
            memcpy(q, p, sizeof p);
            q[P_CRACK_OPENING] = 0;
            double st[NSTATE], sq[NSTATE], F[9], tau[9], tq[9], L[9] = {0};
            L[0] = a, L[4] = -a;
            m->init(p, st), m->init(q, sq);
            t3_identity(F);
            double past = -1, ft = 0, work = 0, soft = 0, prev = 0, worst = 0;
            int k = 0;
            for (; k < 200000 && m->damage(p, st) < 1; k++) {
                double f[9], Fn[9];
                for (int i = 0; i < 9; i++) f[i] = (i % 4 == 0) + dt * L[i];
                t3_mul(f, F, Fn);
                t3_copy(Fn, F);
                hearth_point pt = {.dt = dt, .temperature = 20, .porosity = 0.1, .saturation = NAN, .p = p, .state = st};
                memcpy(pt.grad_v, L, sizeof L), memcpy(pt.F, F, sizeof F);
                CHECK(m->stress(&pt, tau) == 0);
                hearth_point pq = pt;
                pq.p = q, pq.state = sq;
                CHECK(m->stress(&pq, tq) == 0);
                const double d = m->damage(p, st), t = tau[0], tw = tq[0]; /* x is the tensile principal direction */
                work += 0.5 * (prev + t) * step; /* from rest: the elastic energy at the peak counts */
                if (past < 0 && d >= 0.5) past = 0, ft = tw;
                else if (past >= 0) {
                    past += step;
                    soft += 0.5 * (prev + t) * step;
                    const double line = (y ? ft : tw) * fmax(0, 1 - past / u); /* elastic: from the peak's; yielding: the twin's */
                    if (d < 1) worst = fmax(worst, fabs(t - line) / ft);
                }
                prev = t;
            }
            G[c] = hs[c] * (y ? work : soft);
            const double want = y ? ft * wc / 2 : hs[c] * ft * u / 2;
            printf("  %s, h %.0f mm: softening stretch %.5f (w_c / h - eps_f %.5f, a step %.1e), tension off the line by %.2e "
                   "of f_t, %s %.6f J/m^2 against %.6f (f_t %.2f Pa), %d steps\n",
                   y ? "elastic" : "yielding", hs[c] * 1e3, past, u, step, worst,
                   y ? "h x work from rest" : "h x softening work", G[c], want, ft, k);
            CHECK(m->damage(p, st) >= 1 && fabs(past - u) <= 2 * step);
            CHECK(worst <= 2 * step / u + (y ? 2 * step / ef : 0)); /* elastic: f_t read up to a step past the peak */
            CHECK(fabs(G[c] - want) <= 0.02 * want);
        }
        if (y) CHECK(fabs(G[0] - G[2]) <= 0.02 * G[2]); /* elastic: the same energy per crack area at 2 and 8 mm */
    }
}

TEST_MAIN(T(dough_fracture_damage), T(dough_fracture_stretch_rule), T(dough_fracture_set_takes_smaller), T(dough_fracture_unset_gates_water_brittleness), T(dough_crack_band_softening))
