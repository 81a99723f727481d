/* unit_sph_dry.c: a dried crust on the SPH solver (issue #18; sph_heat.c):
 * per-particle conductivity and heat capacity from the materials'
 * dry_conductivity and dry_specific_heat, MPM's rules (material.h; the MPM
 * tests are unit_dry_crust.c and unit_dry_heat.c).
 *
 * The closed forms the tests derive, each from the particle's own columns with
 * the rule, not with the code's: r = w / w0, the water a particle holds over
 * the water it was made with (w0 = s_0 rho^w V_0), and
 *   kappa(r) = kappa_d + (kappa - kappa_d) min(r, 1),
 *   alpha(r) = alpha_d + (alpha - alpha_d) r.
 * - Two layers in series: in a steady slab conducting through a wet layer
 *   and a dried one, the flux kappa dtheta/dy is the same in both, so the
 *   slopes' ratio is kappa_wet / kappa(r_dry).
 * - A block whose water holds still heats by Q / sum m alpha(r) on the
 *   mass-weighted mean, Q the oven's heat in.
 * - A drying, boiling bake keeps the books heat in = sum over steps of
 *   m alpha(r at the step's start) dtheta + L x water lost. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "hearth/hearth.h"
#include "scene.h"
#include "sph_fixture.h"
#include "sph_state.h"
#include "test.h"
#include "water.h"

#define KELVIN 273.15
#define PI 3.14159265358979323846
/* h.library.dough.bread's numbers (lua/hearth/dough_physical.lua), unit_dry_heat.c's: kappa 0.51 W/(m K) wet,
 * 0.23 dried; alpha 2700 J/(kg K) wet, 0.55 x 1650 dried (its solids' share of the mass times their specific
 * heat); heat and water 300 times fast, so 5 s is its 25 minute bake. */
#define S_FAST 300.0
static const double RHO = 484, C_WET = 2700, C_DRY = 0.55 * 1650, K_WET = 0.51, K_DRY = 0.23, SAT = 0.218;
static const double OVEN_T = 200, OVEN_BETA = 30 * S_FAST, EVAP = 1.2e-5 * S_FAST, WATER_K = 2e-9 / (373.15 * 0.218) * S_FAST;

/* The rules above from particle i's columns (rho^w 1000, the materials' default). */
static double ratio_of(const hearth_scene *s, int i) {
    const particles *ps = &s->ps;
    return pcold(ps, PC_WATER)[i] / (pcold(ps, PC_SAT0)[i] * 1000.0 * pcold(ps, PC_VOL0)[i]);
}
static double alpha_of(const hearth_scene *s, int i, double cd) {
    const double r = ratio_of(s, i);
    return cd + (C_WET - cd) * (r > 0 ? r : 0.0);
}
static double kappa_of(const hearth_scene *s, int i, double kd) {
    const double r = ratio_of(s, i);
    return kd + (K_WET - kd) * (r > 1 ? 1 : r > 0 ? r : 0);
}

/* A dough material for SPH: pinned bodies only, so soft and thin (the mechanics only sets dt), with the bread's
 * heat and water; kd and cd its dry parameters (0: as wet), water_k and evap as given. SPH conducts at the
 * scene's heat_int = kappa / c and reads only kappa(w) / conductivity from the material, so the conductivities
 * stay the real ones (0.51, 0.23) where the scene's heat_int is 300 times fast. */
static int dough(hearth_scene *s, double kd, double cd, double water_k, double evap) {
    const char *n[] = {"density", "bulk", "viscosity", "specific_heat", "conductivity", "water_diffusivity", "evaporation",
                       "dry_conductivity", "dry_specific_heat"};
    const double v[] = {RHO, 1, 1e-3, C_WET, K_WET, water_k, evap, kd, cd};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "newtonian", n, v, 9, &err);
    if (m < 0) printf("  material: %s\n", err.msg);
    CHECK(m >= 0);
    return m;
}

static int pinned_box(hearth_scene *s, int m, const double c[3], const double hh[3], double T, double sat) {
    hearth_body_def bd = hearth_default_body_def();
    bd.shape = hearth_shape_box(c, hh);
    bd.material = m, bd.ppc = 1, bd.jitter = 0, bd.fixed = 1, bd.temperature = T, bd.saturation = sat;
    hearth_error err;
    const int id = hearth_scene_add_body(s, &bd, &err);
    if (id < 0) printf("  body: %s\n", err.msg);
    hearth_shape_free((hearth_shape *)bd.shape);
    return id;
}

/* ---- two layers in series -------------------------------------------------
 * A pinned slab N rows thick (y), 8 columns periodic along x, the lower half
 * wet, the upper half dried to twice water.c's saturation floor (r = 0.0092),
 * with the bread's conductivities, heat_int = kappa_wet / c_wet 300 times
 * fast (its time scale). The test holds the lowest and highest G = 2 rows at
 * 150 and 50 degC after every step (the kernel reaches 2.4 spacings: two
 * rows, so the free rows see held ones where a wall would be): Dirichlet
 * faces. From a linear start it runs 8 relaxation times H^2 / (pi^2 D_dried)
 * (a bound on the slowest mode's). Each layer's slope is a least-squares line
 * through the rows that see their own material only and no held row (at
 * least 2.4 spacings from the interface plane and from the held rows); the
 * lines' jump at the interface plane, over the whole drop, says whether the
 * pair's mean joins them as two layers in series do. Returns the slope ratio
 * dry / wet; *want kappa_wet / kappa(r_dry), *jump the relative jump. */
static double series_slab(int N, double *want, double *jump, long *steps) {
    const int G = 2;
    const double H = 0.02, dx = H / N, Th = 150, Tc = 50, hs = 2.4 * dx;
    const double lo[3] = {0, 0, 0}, hi[3] = {8 * dx, H + 8 * dx, 0}, y0 = 4 * dx, yi = y0 + 0.5 * H;
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.periodic[0] = 1;
    d.sph.heat_ext = 0;
    d.sph.heat_int = K_WET * S_FAST / C_WET;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    CHECK(s != NULL);
    if (!s) return NAN;
    const int m = dough(s, K_DRY, 0, 1e-18, 0); /* water live but still: no evaporation, next to no diffusion */
    const double c[3] = {4 * dx, y0 + 0.5 * H, 0}, hh[3] = {4 * dx, 0.5 * H, 0.5};
    CHECK(pinned_box(s, m, c, hh, 0.5 * (Th + Tc), SAT) >= 0);
    particles *ps = &s->ps;
    const double *X = pcold(ps, PC_X);
    double *T = pcold(ps, PC_TEMPERATURE), *W = pcold(ps, PC_WATER);
    const double ylo = y0 + G * dx, yhi = y0 + H - G * dx; /* the held rows lie below ylo and above yhi */
    for (int i = 0; i < ps->n; i++) {
        const double y = X[3 * i + 1];
        if (y > yi) W[i] = 2 * WATER_SATURATION_FLOOR * 1000.0 * pcold(ps, PC_VOL0)[i]; /* above the floor: at rest */
        T[i] = y < ylo ? Th : y > yhi ? Tc : Th + (Tc - Th) * (y - ylo) / (yhi - ylo);
    }
    const double Dd = K_DRY * S_FAST / (RHO * C_WET), tend = 8 * H * H / (PI * PI * Dd);
    hearth_error err;
    while (hearth_scene_time(s) < tend) {
        if (hearth_scene_step(s, 1, &err) != HEARTH_OK) {
            printf("  step: %s\n", err.msg);
            CHECK(0);
            break;
        }
        for (int i = 0; i < ps->n; i++) {
            const double y = X[3 * i + 1];
            if (y < ylo) T[i] = Th;
            if (y > yhi) T[i] = Tc;
        }
    }
    hearth_stats hs_;
    hearth_scene_stats(s, &hs_);
    *steps = hs_.step;
    /* the two fits, and the dried rows' kappa from their columns */
    double sw[5] = {0}, sd[5] = {0}, kd = 0;
    int nd = 0;
    for (int i = 0; i < ps->n; i++) {
        const double y = X[3 * i + 1];
        if (y > yi) kd += kappa_of(s, i, K_DRY), nd++;
        double *a = NULL;
        if (y > ylo + hs && y < yi - hs) a = sw;
        if (y < yhi - hs && y > yi + hs) a = sd;
        if (!a) continue;
        a[0] += 1, a[1] += y, a[2] += y * y, a[3] += T[i], a[4] += y * T[i];
    }
    kd /= nd;
    const double bw = (sw[0] * sw[4] - sw[1] * sw[3]) / (sw[0] * sw[2] - sw[1] * sw[1]), aw = (sw[3] - bw * sw[1]) / sw[0];
    const double bd = (sd[0] * sd[4] - sd[1] * sd[3]) / (sd[0] * sd[2] - sd[1] * sd[1]), ad = (sd[3] - bd * sd[1]) / sd[0];
    *want = K_WET / kd;
    *jump = ((aw + bw * yi) - (ad + bd * yi)) / (Th - Tc);
    printf("  %d rows (dx %.3g mm), %ld steps, t %.1f s: slopes wet %.2f K/m (%d rows), dried %.2f K/m (%d rows); "
           "ratio %.5f, kappa_wet / kappa_dried %.5f (rel. error %.2e); the lines' jump at the interface %.2e of the drop\n",
           N, dx * 1e3, *steps, hearth_scene_time(s), bw, (int)(sw[0] / 8), bd, (int)(sd[0] / 8), bd / bw, *want,
           bd / bw / *want - 1, *jump);
    hearth_scene_destroy(s);
    return bd / bw;
}

/* The slopes' ratio is kappa_wet / kappa_dried (2.21 here) within 1% at 20
 * and 40 rows, the error falling (the bar: the fitted rows see one material
 * each and the renormalised Laplacian carries a linear profile's flux, so what
 * is left is the start's transient, e^-8 of a departure of a fifth of the
 * drop, and the fits' few rows; a scheme that read one kappa for both layers
 * misses by 121%). The slopes alone do not see the pair's mean: the lines'
 * jump at the interface plane does (an interface resistance). The bar first
 * set, 2% of the drop, passed the arithmetic mean too (measured: 1.39% and
 * 0.64% at 20 and 40 rows, against the harmonic mean's 0.146% and 0.072%), so
 * it is 0.5%, a third of the arithmetic mean's coarse jump, and it must fall
 * with the spacing (an interface error of first order). */
TEST(sph_dry_slab_slopes_in_series) {
    const int Ns[2] = {20, 40};
    double err[2], jump[2], want;
    long steps;
    for (int k = 0; k < 2; k++) {
        const double got = series_slab(Ns[k], &want, &jump[k], &steps);
        err[k] = fabs(got / want - 1);
    }
    printf("  ratio errors %.2e, %.2e (observed order %.2f); jumps %.2e, %.2e\n", err[0], err[1], log2(err[0] / err[1]),
           jump[0], jump[1]);
    CHECK(err[0] < 0.01 && err[1] < 0.01);
    CHECK(err[1] < err[0]);
    CHECK(fabs(jump[0]) < 0.005 && fabs(jump[1]) < 0.005);
    CHECK(fabs(jump[1]) < fabs(jump[0]));
}

/* ---- a block heats at its capacity ----------------------------------------
 * A pinned 40 x 20 mm block of the bread at 25 degC in its 200 degC oven
 * (Robin beta, the oven's ledger with latent_heat), its water held still (no
 * evaporation, next to no diffusion, below the boiling point) at the ratio r of
 * what it was made with, for 0.05 s (15 real seconds: the dried corners stay
 * below the boiling point). */
static double heats_by(double dx, double r, double *rise) {
    const double lo[3] = {0, 0, 0}, hi[3] = {0.1, 0.06, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.oven_temperature = OVEN_T;
    d.oven_beta = OVEN_BETA;
    d.sph.heat_ext = 0;
    d.sph.heat_int = K_WET * S_FAST / C_WET;
    d.latent_heat = 1;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    CHECK(s != NULL);
    if (!s) return INFINITY;
    const int m = dough(s, K_DRY, C_DRY, 1e-18, 0);
    const double c[3] = {0.05, 0.03, 0}, hh[3] = {0.02, 0.01, 0.5};
    CHECK(pinned_box(s, m, c, hh, 25, SAT) >= 0);
    particles *ps = &s->ps;
    for (int i = 0; i < ps->n; i++) pcold(ps, PC_WATER)[i] *= fmax(r, 2 * WATER_SATURATION_FLOOR / SAT);
    double M = 0, MC = 0;
    for (int i = 0; i < ps->n; i++) M += pcold(ps, PC_MASS)[i], MC += pcold(ps, PC_MASS)[i] * alpha_of(s, i, C_DRY);
    hearth_error err;
    CHECK(hearth_scene_advance(s, 0.05, &err) == HEARTH_OK);
    hearth_stats st;
    hearth_scene_stats(s, &st);
    double up = 0, MC1 = 0, Tmax = -INFINITY;
    for (int i = 0; i < ps->n; i++) {
        const double mi = pcold(ps, PC_MASS)[i], T = pcold(ps, PC_TEMPERATURE)[i];
        up += mi * (T - 25.0), MC1 += mi * alpha_of(s, i, C_DRY), Tmax = fmax(Tmax, T);
    }
    up /= M;
    const double want = st.oven_heat_in / MC;
    *rise = up;
    printf("  dx %.3g mm, water ratio %.2f: alpha %.1f J/(kg K); heat in %.6g J/m over %ld steps; mean rise %.6f K, "
           "Q / sum m alpha %.6f K (rel. diff %.2g); hottest %.2f degC; capacity moved %.2g\n",
           dx * 1e3, r, MC / M, st.oven_heat_in, st.step, up, want, (up - want) / want, Tmax, MC1 / MC - 1);
    CHECK(fabs(MC1 / MC - 1) < 1e-12); /* the water held still, so alpha did */
    CHECK(Tmax < 100);                 /* nothing boiled */
    hearth_scene_destroy(s);
    return (up - want) / want;
}

/* Dried (r = 0: dry_specific_heat), half-dried and wet blocks each heat by
 * Q / sum m alpha(r) on the mean, to round-off: every particle's Robin heat is
 * the ledger's term and its conduction pairs cancel, each over m alpha(r).
 * Bar 1e-9 (unit_dry_heat.c's): far above round-off over the steps, far below
 * the factor 2.98 a solver reading the wet alpha for the dried block misses
 * by. The dried block is the hottest after the same time. At 4 and 2 mm. */
TEST(sph_dry_block_heats_at_its_capacity) {
    const double dxs[2] = {0.004, 0.002}, rs[3] = {0.0, 0.5, 1.0};
    for (int k = 0; k < 2; k++) {
        double dT[3], e[3];
        for (int q = 0; q < 3; q++) e[q] = heats_by(dxs[k], rs[q], &dT[q]);
        printf("  dx %.3g mm: mean rise dried %.3f K, half %.3f K, wet %.3f K (alpha wet / dried %.3f)\n", dxs[k] * 1e3,
               dT[0], dT[1], dT[2], C_WET / C_DRY);
        for (int q = 0; q < 3; q++) CHECK(fabs(e[q]) < 1e-9);
        CHECK(dT[0] > dT[1] && dT[1] > dT[2]);
    }
}

/* ---- the books of a drying bake -------------------------------------------
 * The same block with its water live (the bread's diffusivity and
 * evaporation, latent_heat on), baked 5 s (25 minutes): the surface dries,
 * the crumb heats toward boiling. Stepped one step at a time; particles found
 * by id, since the neighbour sort reorders the columns. Returns (Q - sensible
 * - L x water lost) / Q; *share the latent part of Q, *lost the share of heat
 * capacity gone with the water, *naive the imbalance of the difference of
 * sum m alpha(r) (theta + 273.15), which misses the heat the water carried. */
static hearth_scene *bake(double dx, double kd, double cd) {
    const double lo[3] = {0, 0, 0}, hi[3] = {0.1, 0.06, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.oven_temperature = OVEN_T;
    d.oven_beta = OVEN_BETA;
    d.sph.heat_ext = 0;
    d.sph.heat_int = K_WET * S_FAST / C_WET;
    d.latent_heat = 1;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    CHECK(s != NULL);
    if (!s) return NULL;
    const int m = dough(s, kd, cd, WATER_K, EVAP);
    const double c[3] = {0.05, 0.03, 0}, hh[3] = {0.02, 0.01, 0.5};
    CHECK(pinned_box(s, m, c, hh, 25, SAT) >= 0);
    return s;
}

static double books(double dx, double *share, double *lost, double *naive) {
    hearth_scene *s = bake(dx, K_DRY, C_DRY);
    if (!s) return INFINITY;
    const particles *ps = &s->ps;
    const int n = ps->n;
    double *a0 = malloc(sizeof(double) * (size_t)n), *T0 = malloc(sizeof(double) * (size_t)n);
    hearth_stats st;
    hearth_scene_stats(s, &st);
    const double E0 = st.heat_energy, W0 = st.water_mass;
    double C0 = 0, sens = 0;
    for (int i = 0; i < n; i++) C0 += pcold(ps, PC_MASS)[i] * alpha_of(s, i, C_DRY);
    hearth_error err;
    while (hearth_scene_time(s) < 5.0 - 1e-12) {
        for (int i = 0; i < n; i++) {
            const int id = pcoli(ps, PC_ID)[i];
            a0[id] = alpha_of(s, i, C_DRY), T0[id] = pcold(ps, PC_TEMPERATURE)[i];
        }
        if (hearth_scene_step(s, 1, &err) != HEARTH_OK) {
            printf("  step: %s\n", err.msg);
            CHECK(0);
            break;
        }
        for (int i = 0; i < n; i++) {
            const int id = pcoli(ps, PC_ID)[i];
            sens += pcold(ps, PC_MASS)[i] * a0[id] * (pcold(ps, PC_TEMPERATURE)[i] - T0[id]);
        }
    }
    hearth_scene_stats(s, &st);
    double C1 = 0, Tmin = INFINITY, Tmax = -INFINITY;
    for (int i = 0; i < n; i++) {
        C1 += pcold(ps, PC_MASS)[i] * alpha_of(s, i, C_DRY);
        Tmin = fmin(Tmin, pcold(ps, PC_TEMPERATURE)[i]), Tmax = fmax(Tmax, pcold(ps, PC_TEMPERATURE)[i]);
    }
    const double Q = st.oven_heat_in, dW = W0 - st.water_mass, miss = (sens + HEARTH_LATENT_HEAT * dW - Q) / Q;
    *share = HEARTH_LATENT_HEAT * dW / Q;
    *lost = 1 - C1 / C0;
    *naive = (st.heat_energy - E0 + HEARTH_LATENT_HEAT * dW - Q) / Q;
    printf("  dx %.3g mm, %ld steps, t %.2f s: heat in %.6g J/m = integral m alpha dtheta %.6g + L x water %.6g "
           "(%.3g of %.3g kg/m); imbalance %.3g; with the difference of sum m alpha (theta + 273.15) %.3g; heat "
           "capacity gone with the water %.3f; temperatures %.1f to %.1f degC\n",
           dx * 1e3, st.step, st.t, Q, sens, HEARTH_LATENT_HEAT * dW, dW, W0, miss, *naive, *lost, Tmin, Tmax);
    free(a0);
    free(T0);
    hearth_scene_destroy(s);
    return miss;
}

/* Heat in = integral of m alpha(w) dtheta + L x water lost to 1% (the bar of
 * sph_latent_heat_energy_balance and dry_heat_energy_balance: a particle at
 * the saturation floor keeps water whose heat was taken) at 4 and 2 mm; the
 * latent part at least a fifth of the books and at least 5% of the heat
 * capacity gone with the water, so the case exercises what it checks; the
 * books without the carried heat must not close. */
TEST(sph_dry_energy_balance) {
    const double dxs[2] = {0.004, 0.002};
    for (int k = 0; k < 2; k++) {
        double share, lost, naive;
        const double miss = books(dxs[k], &share, &lost, &naive);
        CHECK(fabs(miss) < 0.01);
        CHECK(share > 0.2);
        CHECK(lost > 0.05);
        CHECK(fabs(naive) > 0.01);
    }
}

/* ---- bits ------------------------------------------------------------------
 * Without either dry parameter SPH's heat is the thesis's form in its former
 * bits: the drying bake's hash after 1 s equals the one the solver gave before
 * the dry parameters reached SPH (pinned from commit f004263, whose SPH read
 * the wet specific heat everywhere: 0x3115e7196d9355b5, which main still gave
 * at 6f21942). The oven's flux through the film (sph_heat.c's sph_film_share,
 * helper sphflux) changes the outer particles' heat on purpose, so the pin is
 * now the wet bake of the commit that brought it (50687d0), the rest of the
 * wet path as at f004263. With both set, the same bits on 1 and 2
 * threads (3200 particles at 0.5 mm, above SCENE_PARALLEL_MIN: the pair loops
 * run on both), and other bits than the wet bake's. */
static unsigned long long bake_hash(double dx, double kd, double cd, int threads, double until) {
    hearth_set_threads(threads);
    hearth_scene *s = bake(dx, kd, cd);
    hearth_error err;
    if (s && threads > 1) CHECK(s->ps.n > SCENE_PARALLEL_MIN); /* the loops run on both threads */
    CHECK(s && hearth_scene_advance(s, until, &err) == HEARTH_OK);
    if (s) {
        hearth_stats st;
        hearth_scene_stats(s, &st);
        printf("  %d particles, %ld steps to %.3g s, %d thread(s)\n", st.particles, st.step, until, threads);
    }
    const unsigned long long h = s ? (unsigned long long)hearth_scene_hash(s) : 0;
    hearth_scene_destroy(s);
    hearth_set_threads(0);
    return h;
}

#define WET_BAKE_HASH 0xc76296b1e4fabd1fULL
TEST(sph_dry_defaults_same_bits) {
    const unsigned long long h0 = bake_hash(0.002, 0, 0, 1, 1.0);
    printf("  wet bake (no dry parameter), 1 s: %016llx, pinned %016llx\n", h0, WET_BAKE_HASH);
    CHECK(h0 == WET_BAKE_HASH);
    const unsigned long long h1 = bake_hash(0.0005, K_DRY, C_DRY, 1, 0.01);
    const unsigned long long h2 = bake_hash(0.0005, K_DRY, C_DRY, 2, 0.01);
    const unsigned long long hw = bake_hash(0.0005, 0, 0, 1, 0.01);
    printf("  dried bake, 1 thread %016llx, 2 threads %016llx (wet %016llx)\n", h1, h2, hw);
    CHECK(h1 == h2 && h1 != hw);
}

/* ---- the step limits --------------------------------------------------------
 * sph_heat_stable_dt with the dry parameters: conduction's 0.1 h^2 rho / k_h,int
 * over R = min(2 k/alpha at the stiffest end, K / alpha_dried) (sph_heat.c: a
 * harmonic pair mean is at most twice either end and at most the largest k),
 * with k = c kappa / kappa_wet; the Robin term's 0.25 rho alpha_dried sp / beta.
 * Derived here from the parameters for the bread (k / alpha: wet 1, dried
 * (2700 x 0.23 / 0.51) / 907.5 = 1.342): both parameters R = 2.684, only
 * dry_conductivity R = 1 (the limit as before: the dried end conducts less),
 * only dry_specific_heat R = 2.975; at beta 30 (conduction binds) and 3e5
 * W/(m^2 K) (the Robin term binds), hmin 4.8 mm, rhomin 484. Bar 1e-12. */
static double limit_of(double kd, double cd, double beta) {
    const double lo[3] = {0, 0, 0}, hi[3] = {0.1, 0.06, 0};
    hearth_scene_def d = sph_def(2, 0.002, lo, hi);
    d.gravity[1] = 0;
    d.oven_temperature = OVEN_T;
    d.oven_beta = beta;
    d.sph.heat_ext = 0;
    d.sph.heat_int = K_WET * S_FAST / C_WET;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    CHECK(s != NULL);
    if (!s) return NAN;
    const int m = dough(s, kd, cd, 1e-18, 0);
    const double c[3] = {0.05, 0.03, 0}, hh[3] = {0.01, 0.01, 0.5};
    CHECK(pinned_box(s, m, c, hh, 25, SAT) >= 0);
    const double dt = sph_heat_stable_dt(s, 0.0048, RHO);
    hearth_scene_destroy(s);
    return dt;
}

TEST(sph_dry_step_limits_take_the_stiffest_end) {
    const double hmin = 0.0048, hf = 2.4, kint = K_WET * S_FAST / C_WET, betas[2] = {30, 3e5};
    const struct {
        double kd, cd;
    } c[3] = {{K_DRY, C_DRY}, {K_DRY, 0}, {0, C_DRY}};
    for (int b = 0; b < 2; b++)
        for (int k = 0; k < 3; k++) {
            const double kw_end = C_WET, ad = c[k].cd > 0 ? c[k].cd : C_WET;
            const double kd_end = c[k].kd > 0 ? C_WET * c[k].kd / K_WET : C_WET; /* k = c kappa / kappa_wet */
            const double stiff = fmax(kw_end / C_WET, kd_end / ad), R = fmin(2 * stiff, C_WET / ad);
            const double cond = 0.1 * hmin * hmin * RHO / kint / R, robin = 0.25 * RHO * ad * hmin / hf / betas[b];
            const double want = fmin(cond, robin), got = limit_of(c[k].kd, c[k].cd, betas[b]);
            printf("  beta %6.0f, dry_conductivity %.2f, dry_specific_heat %6.1f: R %.4f, conduction %.6f s, Robin "
                   "%.6f s; limit %.6f s, derived %.6f s\n",
                   betas[b], c[k].kd, c[k].cd, R, cond, robin, got, want);
            CHECK(fabs(got - want) <= 1e-12 * want);
        }
}

TEST_MAIN(T(sph_dry_slab_slopes_in_series), T(sph_dry_block_heats_at_its_capacity), T(sph_dry_energy_balance),
          T(sph_dry_defaults_same_bits), T(sph_dry_step_limits_take_the_stiffest_end))
