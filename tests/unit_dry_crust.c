/* unit_dry_crust.c: a dried crust conducts less (issue #18, dry_conductivity).
 *
 * The closed form: a slab 0 < y < L whose water is gone (w = 0), on a block
 * held at T_c = 100 degC (the wet crumb at its plateau), its top in the oven
 * (T_o, beta). Steady, the slab's profile is linear and the flux through it is
 * the oven's:
 *   beta (T_o - T_s) = (k / L) (T_s - T_c)  =>  T_s = (beta T_o + (k / L) T_c) / (beta + k / L),
 *   T(y) = T_c + (T_s - T_c) y / L,
 * with k the slab's conductivity: dry_conductivity when dry, conductivity with
 * all its water, and linear in the water ratio between (material_conductivity,
 * material.h). The slab is wide (8 L), so its middle is the 1D slab: the
 * oven's sides are 4 L away. The test derives T(y) and compares the
 * particles' temperatures in the middle after 10 time constants. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mpm_fixture.h"

static hearth_shape *box2(double x0, double x1, double y0, double y1) {
    const double c[3] = {0.5 * (x0 + x1), 0.5 * (y0 + y1), 0}, h[3] = {0.5 * (x1 - x0), 0.5 * (y1 - y0), 0};
    return hearth_shape_box(c, h);
}

enum { KW, KD }; /* the slab's conductivity and dry_conductivity */
static const double L = 0.005, BETA = 30, TO = 200, TC = 100, K[2] = {0.35, 0.18}, RHO = 1000, CP = 2500;

/* The slab at `cells` cells across L, its water ratio `ratio` of the start,
 * dry_conductivity kd; stepped implicitly to 10 time constants of the slower
 * (dry) slab. Returns the largest |T_p - T(y_p)| over the particles in the
 * middle (|x| < L) against the profile of conductivity kexp, in units of
 * T_s - T_c; prints both. hash: the scene's hash at the end. */
static double run(int cells, double ratio, double kd, double kexp, int threads, unsigned long long *hash) {
    const double dx = L / cells, W = 8 * L;
    hearth_set_threads(threads);
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = dx;
    d.gravity[1] = 0;
    d.oven_temperature = TO;
    d.oven_beta = BETA;
    d.heat_implicit = 1;
    d.heat_flip = 0; /* PIC: particles read their nodes, so the steady profile is the grid's, without FLIP's history */
    const double D = ceil((0.5 * W + 4 * dx) / dx) * dx; /* 0 on a node row */
    for (int k = 0; k < 2; k++) d.lo[k] = -D, d.hi[k] = D;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return INFINITY;
    hearth_error err;
    /* water live (a diffusivity), but it cannot move out of a dry particle: Fick's flux is -K theta rho s grad s */
    const char *nm[] = {"E", "density", "conductivity", "specific_heat", "saturation", "water_diffusivity", "dry_conductivity"};
    /* 1e-18: over 10 time constants the water spreads sqrt(K theta t) ~ 1 um, so the ratio stays where the test put it */
    const double slab_v[] = {1e-2, RHO, K[KW], CP, 0.5, 1e-18, kd};
    const double held_v[] = {1e-2, RHO, K[KW], CP, 0.0, 0.0, 0.0};
    const int ms = hearth_scene_add_material(s, "elastic", nm, slab_v, 7, &err);
    const int mh = hearth_scene_add_material(s, "elastic", nm, held_v, 7, &err);
    CHECK(ms >= 0 && mh >= 0);
    hearth_body_def b = hearth_default_body_def();
    hearth_shape *slab = box2(-0.5 * W, 0.5 * W, 0, L), *held = box2(-0.5 * W, 0.5 * W, -3 * dx, 0);
    b.shape = slab, b.material = ms, b.jitter = 0, b.temperature = TC, b.fixed = 1;
    CHECK(hearth_scene_add_body(s, &b, &err) == 0);
    b.shape = held, b.material = mh, b.fixed_temperature = 1;
    CHECK(hearth_scene_add_body(s, &b, &err) == 1);
    hearth_shape_free(slab);
    hearth_shape_free(held);
    /* the slab's water: ratio of what it started with (PC_SAT0 rho^w V_0) */
    for (int i = 0; i < s->ps.n; i++)
        if (pcoli(&s->ps, PC_BODY)[i] == 0) pcold(&s->ps, PC_WATER)[i] *= ratio;
    const double tau = RHO * CP * L * L / fmin(K[KD], kexp), dt = tau / 20;
    CHECK(hearth_scene_set_dt_limits(s, 0.5, dt, &err) == HEARTH_OK);
    CHECK(hearth_scene_advance(s, 10 * tau, &err) == HEARTH_OK);
    const double ts = (BETA * TO + kexp / L * TC) / (BETA + kexp / L);
    double worst = 0, wsum = 0, wmin = INFINITY, wmax = 0;
    for (int i = 0; i < s->ps.n; i++) {
        if (pcoli(&s->ps, PC_BODY)[i] != 0) continue;
        const double *x = pcold(&s->ps, PC_X) + 3 * i, w = pcold(&s->ps, PC_WATER)[i];
        wsum += w, wmin = fmin(wmin, w), wmax = fmax(wmax, w);
        if (fabs(x[0]) >= L) continue;
        const double exact = TC + (ts - TC) * x[1] / L;
        if (getenv("DRY_DEBUG") && x[0] > 0 && x[0] < dx) printf("      y/dx %.3f T %.3f exact %.3f\n", x[1] / dx, pcold(&s->ps, PC_TEMPERATURE)[i], exact);
        worst = fmax(worst, fabs(pcold(&s->ps, PC_TEMPERATURE)[i] - exact));
    }
    printf("    L/dx %2d, water ratio %.2f, dry_conductivity %.2f: T_s = %.2f degC (k = %.3f W/(m K)); "
           "worst |T - T(y)| %.3f K = %.4f (T_s - T_c); slab water %.3g .. %.3g kg\n",
           cells, ratio, kd, ts, kexp, worst, worst / (ts - TC), wmin, wmax);
    if (hash) *hash = (unsigned long long)hearth_scene_hash(s);
    hearth_scene_destroy(s);
    hearth_set_threads(0);
    return worst / (ts - TC);
}

/* The closed form's surface temperature for conductivity k. */
static double surface_t(double k) { return (BETA * TO + k / L * TC) / (BETA + k / L); }

/* How far the closed form for conductivity k lies from the one for k2, at the
 * surface, in units of its own T_s - T_c: the error's unit in run(). A run
 * whose error is under half of it is nearer its own profile than the other's. */
static double gap(double k, double k2) { return fabs(surface_t(k) - surface_t(k2)) / (surface_t(k) - TC); }

/* The dried slab's surface climbs to the closed form's T_s for dry_conductivity,
 * converging at first order or better from 8 to 16 cells across L (the heat's
 * boundary layer is first order: the top particles read nodes past the
 * surface, which flattens the profile's last cell, wet or dry); with all its
 * water it follows the wet slab's profile, and half dried the conductivity
 * halfway (the linear form). Each error must be under half the closed-form
 * distance to the neighbouring case (dry against half, half against the
 * nearer of wet and dry, wet against half), so the test tells the three
 * conductivities apart; and the dried slab read against the wet profile must
 * miss by more than half their distance (the test can fail). The bars are the
 * closed forms' own distances, not the measured errors. */
TEST(dry_crust_steady_surface) {
    const double kh = 0.5 * (K[KD] + K[KW]);
    const double e8 = run(8, 0.0, K[KD], K[KD], 0, NULL), e16 = run(16, 0.0, K[KD], K[KD], 0, NULL);
    const double gd = gap(K[KD], kh), gw = gap(K[KW], kh), gh = fmin(gap(kh, K[KD]), gap(kh, K[KW]));
    printf("    dried: error %.4f at 8 cells, %.4f at 16 (ratio %.2f; asked > 2 and < %.4f at 16)\n", e8, e16, e8 / e16,
           0.5 * gd);
    CHECK(e8 / e16 > 2);
    CHECK(e16 < 0.5 * gd);
    const double ew = run(8, 1.0, K[KD], K[KW], 0, NULL), eh = run(8, 0.5, K[KD], kh, 0, NULL);
    const double ex = run(8, 0.0, K[KD], K[KW], 0, NULL);
    printf("    with its water %.4f (asked < %.4f), half %.4f (< %.4f); dried against the wet profile %.4f (> %.4f)\n", ew,
           0.5 * gw, eh, 0.5 * gh, ex, 0.5 * gap(K[KW], K[KD]));
    CHECK(ew < 0.5 * gw);
    CHECK(eh < 0.5 * gh);
    CHECK(ex > 0.5 * gap(K[KW], K[KD]));
}

/* dry_conductivity 0 (the default) and dry_conductivity = conductivity give
 * the same bits on a dried slab (both conduct as wet: kd + (k - kd) r = k),
 * and a dried slab gives the same bits on 1 and 2 threads. */
TEST(dry_crust_same_bits) {
    unsigned long long h0, hk, h1, h2;
    run(8, 0.0, 0.0, K[KW], 1, &h0);
    run(8, 0.0, K[KW], K[KW], 1, &hk);
    printf("    hash dry_conductivity 0: %016llx, = conductivity: %016llx\n", h0, hk);
    CHECK(h0 == hk);
    run(8, 0.0, K[KD], K[KD], 1, &h1);
    run(8, 0.0, K[KD], K[KD], 2, &h2);
    printf("    hash dried, 1 thread: %016llx, 2 threads: %016llx\n", h1, h2);
    CHECK(h1 == h2 && h1 != h0);
}

/* dry_conductivity above conductivity is refused, naming both and the range. */
TEST(dry_crust_refusals) {
    hearth_scene *s = fx_scene(2, 0.01, -0.1, 0.1);
    if (!s) return;
    hearth_error err;
    const char *nm[] = {"conductivity", "dry_conductivity"};
    const double v[] = {0.35, 0.5};
    CHECK(hearth_scene_add_material(s, "elastic", nm, v, 2, &err) < 0);
    printf("    %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "dry_conductivity = 0.5 W/(m K) exceeds its conductivity = 0.35 W/(m K)");
    CHECK_STR_CONTAINS(err.msg, "valid range [0, conductivity]");
    const double neg[] = {0.35, -1};
    CHECK(hearth_scene_add_material(s, "elastic", nm, neg, 2, &err) < 0);
    printf("    %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "dry_conductivity");
    hearth_scene_destroy(s);
}

TEST_MAIN(T(dry_crust_steady_surface), T(dry_crust_same_bits), T(dry_crust_refusals))
