/* unit_top_column.c: the physical loaf's top as a 1D column in the model,
 * against an independent fine 1D finite-volume reference
 * (scripts/validation/top_reference.c; docs/validation.md, "The top's
 * reference from the loaf's start"; issue #18, helper topref).
 *
 * The question: loaf_physical.lua's top browns 0.136 / 0.157 / 0.153 at 5 /
 * 2.5 / 1.25 mm after 25 min, where the Stefan form (a crumb already at
 * 100 degC, the front from t = 0) browns its surface 0.28. Is ~0.15 what this
 * physics gives for a loaf that starts at 25 degC, or a numerical shortfall?
 * The reference answers for the 1D column; this case runs the same column in
 * the model, so that what is left between them is numerics.
 *
 * The column: a slab spanning the box in x (the box walls are no air surface,
 * boundary.c: only its top meets the oven), DEPTH deep (about half the loaf's
 * height: its bottom on the box wall is the symmetry plane), pinned, starting
 * at 25 degC and the dough's saturation, with h.library.dough.bread's heat and
 * water (lua/hearth/dough_physical.lua: rho 484, c 2700 wet and 907.5 dry,
 * kappa 0.51 wet and 0.23 dry, s0 0.218, D 2e-9 m^2/s at 373.15 K and s0 through
 * eq. 22's K = D / (373.15 s0), beta^w 1.2e-5) in h.library.oven.bread (200 degC,
 * beta 30 W/(m^2 K)), latent heat and the boiling point at 100 degC on,
 * browning on, forward Euler heat with FLIP, the loaf's own choices. Real time
 * (S = 1): the preset multiplies every rate by S and divides the time, so the
 * history in real time is the same (top_reference.c's header; checked: the
 * preset's numbers divided by S are these). The top particle of the middle
 * column, at 25 min: its browning (browning.c reads its air surface), the
 * surface's temperature and saturation it browns at (its own plus PC_SURFACE's
 * offsets), its own temperature and saturation.
 *
 * The reference's numbers, for this column (H = 40 mm, insulated below): the
 * face's index at 25 min 0.11107, 0.11143, 0.11157 at h 0.2, 0.1, 0.05 mm
 * (Richardson with the observed order, about 1.2: 0.1117), its temperature
 * 126.75, 126.57, 126.55 degC (the face's value moves by a few tenths of a
 * kelvin as each cell finishes boiling: the enthalpy method's staircase).
 * REF_B and REF_TS are h = 0.05 mm's.
 *
 * Bars, set before the model's column was first run (and written here then):
 * - loaf_top_follows_reference: the top's index at 2.5 mm within 15% of the
 *   reference's (as drying_front_surface_browns asks of the Stefan slab at
 *   2 mm: the top particle's drying delay, first order in dx, and its water
 *   factor hold it back meanwhile); the surface temperature browning reads at
 *   25 min within 0.1 (T_s - T_b) of the reference's face at 2.5 mm
 *   (drying_front_follows_stefan's bar for the crust's field at its finest dx).
 * - loaf_top_error_falls_with_dx: the index's error falling from 5 to 2.5 mm,
 *   |e(2.5)| < 0.7 |e(5)| (first order gives 0.5). An expected failure: both
 *   errors are within 2% of the reference (5, 2.5, 1.25, 0.625 mm: +0.1%,
 *   -0.4%, -0.4%, -1.6%, TOP_DX0 / TOP_DX1 for the fine pair), so the error at
 *   5 mm is small by cancellation (its surface reads 1-8 K hot of the
 *   reference's face while the top is wet, 6 K cool at 25 min) and the ratio
 *   says nothing; the surface's history, printed, converges.
 * The three bars were one test when they were set; it was split in two after
 * the first run, so that the bars that pass stand on their own.
 * Measuring switches, unset in the tests: TOP_DX0, TOP_DX1 the two spacings,
 * TOP_DT the largest step (s, real), TOP_TW / TOP_EPS / TOP_HC radiating walls, TOP_S the preset's time scale (every rate
 * S times fast, the time 1/S: at 300 the history is the real-time one to 0.03 K
 * and 1e-4 of the index), TOP_DIFF and TOP_EVAP factors on K and beta^w.
 * The first run put the column 36 mm deep, not whole 5 mm cells, so the 5 mm
 * top particle sat 2.25 mm deep, not dx/4 (0.1127 and 0.1070 at 5 and 2.5 mm);
 * 40 mm (whole cells at 5, 2.5, 1.25 mm) puts it dx/4 deep, as in the loaf.
 * 0.9 s wall for both runs in release (each test runs them).
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "column_fixture.h"
#include "mpm_fixture.h"
#include "water.h"

static const double RHO = 484, CW = 2700, CD = 907.5, KW = 0.51, KD = 0.23, SAT = 0.218, TO = 200, TB = 100, BETA = 30,
                    DREF = 2e-9, BW = 1.2e-5, T0 = 25;
static const double DEPTH = 0.040, WIDTH = 0.02; /* whole cells at 5, 2.5, 1.25 mm: the top particle dx/4 deep */
/* top_reference h=0.05 H=40 at 25 min; its history every 5 min (T_f, b_f) for the table */
static const double REF_B = 0.11157, REF_TS = 126.55;
static const double REF_HIST[5][2] = {{95.62, 0.00237}, {106.10, 0.01599}, {114.12, 0.03832}, {120.82, 0.07004}, {126.55, 0.11157}};
#define NT 25 /* samples, every real minute */

typedef struct column {
    double b[NT], Ts[NT], ss[NT], Tp[NT], sp[NT], depth;
} column;

/* The column at dx in h.library.oven.bread's oven, or (walls not NaN) in air at 200 degC with h_c 10 W/(m^2 K)
 * and walls at `walls` degC radiating with eps 0.9 (top_reference rad=1 hc=10 eps=0.9 Tw=walls). */
static int run_oven(double dx, column *c, double walls) {
    /* TOP_S: the preset's way, every rate S times fast and the time 1/S (a check that real time is the same history) */
    const double S = knob("TOP_S", 1);
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = dx;
    d.gravity[1] = 0;
    d.lo[0] = d.lo[1] = -dx; /* particles are seeded at least a cell from the box walls */
    d.hi[0] = WIDTH + dx;
    d.hi[1] = DEPTH + 0.008;
    d.oven_temperature = TO;
    d.oven_beta = BETA * S;
    /* TOP_TW, TOP_EPS, TOP_HC (measuring switches): the oven's radiating walls (degC), their emissivity, and the
     * air's own coefficient in place of beta (top_reference rad=1 Tw= eps= hc=; docs/validation.md, "An oven's hot
     * walls") */
    if (getenv("TOP_TW") || !isnan(walls)) {
        d.oven_wall_temperature = knob("TOP_TW", walls), d.oven_emissivity = knob("TOP_EPS", 0.9);
        d.oven_radiation_scale = S, d.oven_beta = knob("TOP_HC", 10) * S;
    }
    d.latent_heat = 1;
    d.boiling_point = TB;
    d.browning = 1;
    d.browning_scale = S;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return 0;
    hearth_error err;
    const char *nm[] = {"E", "density", "conductivity", "specific_heat", "dry_specific_heat", "dry_conductivity",
                        "water_diffusivity", "evaporation"};
    const double v[] = {1e-2, RHO, KW * S, CW, CD, KD * S, knob("TOP_DIFF", 1) * DREF / ((TB + KELVIN) * SAT) * S,
                        knob("TOP_EVAP", 1) * BW * S};
    const int m = hearth_scene_add_material(s, "elastic", nm, v, 8, &err);
    if (m < 0) printf("    material: %s\n", err.msg);
    CHECK(m >= 0);
    const double ctr[3] = {0.5 * WIDTH, 0.5 * DEPTH, 0}, half[3] = {0.5 * WIDTH, 0.5 * DEPTH, 0};
    hearth_shape *box = hearth_shape_box(ctr, half);
    hearth_body_def b = hearth_default_body_def();
    b.shape = box, b.material = m, b.jitter = 0, b.fixed = 1, b.temperature = T0, b.saturation = SAT;
    CHECK(hearth_scene_add_body(s, &b, &err) == 0);
    hearth_shape_free(box);
    CHECK(hearth_scene_set_dt_limits(s, 0.5, knob("TOP_DT", 1.0) / S, &err) == HEARTH_OK);
    for (int k = 0; k < NT; k++) {
        if (hearth_scene_advance(s, 60.0 * (k + 1) / S, &err) != HEARTH_OK) {
            printf("    advance: %s\n", err.msg);
            CHECK(0);
            hearth_scene_destroy(s);
            return 0;
        }
        const int it = column_top_particle(s, 0.5 * WIDTH, dx);
        const double *o = pcold(&s->ps, PC_SURFACE), *T = pcold(&s->ps, PC_TEMPERATURE);
        c->b[k] = pcold(&s->ps, PC_BROWNING)[it];
        c->Tp[k] = T[it], c->sp[k] = water_saturation(s, it);
        c->Ts[k] = T[it] + o[2 * it], c->ss[k] = c->sp[k] + o[2 * it + 1];
        c->depth = DEPTH - pcold(&s->ps, PC_X)[3 * it + 1];
    }
    printf("    dx %g mm: %d particles, %ld steps; the top particle %.3f mm deep\n", 1e3 * dx, s->ps.n, s->step, 1e3 * c->depth);
    hearth_scene_destroy(s);
    return 1;
}

static int run(double dx, column *c) { return run_oven(dx, c, NAN); }

static void two(column c[2], double dxs[2]) {
    dxs[0] = knob("TOP_DX0", 0.005), dxs[1] = knob("TOP_DX1", 0.0025);
    for (int r = 0; r < 2; r++) CHECK(run(dxs[r], &c[r]));
    printf("    min | dx %g mm: b, surface T, s, particle T, s | dx %g mm: the same | reference's face: T, b\n", 1e3 * dxs[0],
           1e3 * dxs[1]);
    for (int k = 0; k < NT; k++) {
        printf("    %3d |", k + 1);
        for (int r = 0; r < 2; r++)
            printf(" %.4f %7.2f %.4f %7.2f %.4f |", c[r].b[k], c[r].Ts[k], c[r].ss[k], c[r].Tp[k], c[r].sp[k]);
        if ((k + 1) % 5 == 0) printf(" %7.2f %.4f", REF_HIST[k / 5][0], REF_HIST[k / 5][1]);
        printf("\n");
    }
}

TEST(loaf_top_follows_reference) {
    column c[2];
    double dxs[2];
    two(c, dxs);
    const int e = NT - 1;
    const double e0 = c[0].b[e] - REF_B, e1 = c[1].b[e] - REF_B;
    printf("    25 min: the top's index %.4f, %.4f at %g, %g mm against the reference's %.4f (errors %+.1f%%, %+.1f%%: asked "
           "under 15%% at the finer); surface %.2f, %.2f degC against %.2f (asked within %.2f K at the finer)\n",
           c[0].b[e], c[1].b[e], 1e3 * dxs[0], 1e3 * dxs[1], REF_B, 100 * e0 / REF_B, 100 * e1 / REF_B, c[0].Ts[e], c[1].Ts[e],
           REF_TS, 0.1 * (REF_TS - TB));
    CHECK(fabs(e1) < 0.15 * REF_B);
    CHECK(fabs(c[1].Ts[e] - REF_TS) < 0.1 * (REF_TS - TB));
}

TEST(loaf_top_error_falls_with_dx) {
    column c[2];
    double dxs[2];
    two(c, dxs);
    const int e = NT - 1;
    const double e0 = c[0].b[e] - REF_B, e1 = c[1].b[e] - REF_B;
    double h0 = 0, h1 = 0; /* the surface's largest distance from the reference's face at 10, 15, 20, 25 min */
    for (int k = 1; k < 5; k++)
        h0 = fmax(h0, fabs(c[0].Ts[5 * k + 4] - REF_HIST[k][0])), h1 = fmax(h1, fabs(c[1].Ts[5 * k + 4] - REF_HIST[k][0]));
    printf("    25 min: the index's errors %+.5f, %+.5f at %g, %g mm (%+.1f%%, %+.1f%% of the reference's %.4f); ratio %.2f "
           "(asked < 0.7); the surface's largest distance from the reference's face at 10-25 min %.2f, %.2f K\n",
           e0, e1, 1e3 * dxs[0], 1e3 * dxs[1], 100 * e0 / REF_B, 100 * e1 / REF_B, REF_B, fabs(e1 / e0), h0, h1);
    if (!(fabs(e1) < 0.7 * fabs(e0)))
        XFAIL("the top's index at 25 min is %+.1f%% and %+.1f%% off the reference at %g and %g mm (ratio %.2f, asked < 0.7): "
              "both within 2%% of it (1.25 and 0.625 mm: -0.4%%, -1.6%%, TOP_DX0=0.00125 TOP_DX1=0.000625), so the coarse "
              "error is small by cancellation, not converged: its surface reads hot of the reference's face while the top is wet "
              "and %.1f K cool at 25 min (the finer: %.1f K). The integral's error at this size does not fall with dx; the "
              "surface's history does (largest distance at 10-25 min %.2f, %.2f K). docs/validation.md, helper topref.",
              100 * e0 / REF_B, 100 * e1 / REF_B, 1e3 * dxs[0], 1e3 * dxs[1], fabs(e1 / e0), REF_TS - c[0].Ts[e],
              REF_TS - c[1].Ts[e], h0, h1);
}

/* The oven's radiating walls (#18, helper ovenwall; fields/thermal.h's thermal_oven_exchange) in the same column:
 * air at 200 degC with h_c 10 W/(m^2 K) and walls at 250 degC, eps 0.9, at 2.5 mm, against top_reference rad=1
 * hc=10 eps=0.9 Tw=250 at 25 min (face index 0.24790, 0.24856, 0.24883 at h 0.2, 0.1, 0.05 mm; the face 149.92,
 * 150.14, 150.11 degC; REF_W_* are h = 0.05 mm's). The bars are loaf_top_follows_reference's, set by helper
 * topref before its first run: the index within 15% of the reference's at 2.5 mm, the surface browning reads
 * within 0.1 (T_s - T_b). Not set blind: the column was first run with these walls by a measuring switch (TOP_TW,
 * 15:21 UTC on 2026-12-07), 0.2414 and 149.85 degC at 2.5 mm (0.2097, 150.78 at 5 mm), before this test was
 * written; it keeps the walls' path through the boiling front, drying and browning held to the reference. */
static const double REF_W_B = 0.24883, REF_W_TS = 150.11;
TEST(loaf_top_with_walls_follows_reference) {
    column c;
    CHECK(run_oven(0.0025, &c, 250));
    const double b = c.b[NT - 1], ts = c.Ts[NT - 1], e = b / REF_W_B - 1, tol = 0.1 * (REF_W_TS - TB);
    printf("    walls 250 degC, h_c 10: 25 min, dx 2.5 mm: index %.4f against the reference's %.4f (error %+.1f%%, bar "
           "15%%); surface %.2f degC against %.2f (bar within %.2f K)\n", b, REF_W_B, 100 * e, ts, REF_W_TS, tol);
    CHECK(fabs(e) < 0.15 && fabs(ts - REF_W_TS) < tol);
}

TEST_MAIN(T(loaf_top_follows_reference), T(loaf_top_error_falls_with_dx), T(loaf_top_with_walls_follows_reference))
