/* unit_drying_front.c: does the dried crust grow as a drying front should, and
 * converge in dx? (issue #18, helper stefan)
 *
 * The closed form. A wet slab (saturation s: water 1000 s kg/m^3, the rho_0^w
 * s of Ding et al. eq. 8) whose wet part is held at the boiling point T_b
 * (water.c's water_boil), its top in the oven (T_o, beta). Once the top is at
 * T_b a dried layer of depth d grows over a crumb at T_b; its conductivity
 * is k (dry_conductivity), its heat capacity rho c. Quasi-steady, the profile
 * in the layer is linear and the flux through air film and layer in series is
 *   q(d) = (T_o - T_b) / (a + b d),   a = 1 / beta, b = 1 / k,           (1)
 * the surface at T_s = T_b + q b d. All the heat that enters either boils
 * water at the front or warms the layer, whose sensible heat (linear profile)
 * is rho c (T_s - T_b) d / 2 = rho c q b d^2 / 2. So with W = 1000 s L
 * (latent heat per volume):
 *   d/dt [W d + rho c b q(d) d^2 / 2] = q(d).                           (2)
 * Without the sensible term, W dd/dt = q:
 *   t(d) = W (a d + b d^2 / 2) / (T_o - T_b)                            (3)
 * (the brief's d / beta + d^2 / (2 k) = (T_o - T_b) t / W). With it, since
 * d/dd [q d^2] = (T_o - T_b) (2 a d + b d^2) / (a + b d)^2 and
 * (2 a u + b u^2) / (a + b u) = u + a / b - (a^2 / b) / (a + b u):
 *   t(d) = (3) + (rho c b / 2) [d^2 / 2 + (a / b) d - (a / b)^2 ln(1 + b d / a)].   (4)
 * (4) - (3) is the Stefan number's correction, St = rho c (T_s - T_b) / W;
 * what (4) still leaves out (the layer's profile is not quite linear while it
 * grows) is of order St^2 (the heat-balance integral's error, Goodman 1958).
 *
 * The model's details, and how this case keeps them out: evaporation through
 * the surface (eq. 8, with the wet-bulb factor) and the water's diffusion back
 * toward the front (eq. 22) are 0 here, so water leaves only by water_boil, as
 * (1)-(4) assume; the conductivity is linear in the water ratio
 * (material_conductivity), so a dry particle conducts with dry_conductivity
 * and the one at the front in between; the physical presets' time scale S
 * multiplies every rate (conductivity, beta, ...) and divides the time, which
 * leaves (1)-(4) in real time unchanged, so this runs in real units (S = 1).
 *
 * The scene: a slab spanning the box in x (the box walls are no air surface,
 * boundary.c, so only its top meets the oven: 1D), deep enough that the front
 * never nears the insulated bottom, everything starting wet at T_b, so the
 * front starts at t = 0. Pinned (no mechanics), implicit heat. Bread's
 * numbers (lua/hearth/dough_physical.lua): rho 484 kg/m^3, c 2700 J/(kg K),
 * conductivity 0.51 wet, 0.23 dry, s = 0.218, the oven 200 degC at 30 W/(m^2 K).
 * Measured: the dried depth as an integral, the water boiled per unit area
 * over 1000 s (d_int, the better-defined measure: energy is conserved, so it
 * is the heat in less the crust's sensible heat), the middle column's depth
 * where the moisture ratio crosses 0.5, the front's width, when the top
 * particle is half dry, and the dried crust's temperatures, the field's (the
 * B-spline probe) and the particles' own, at dx 4, 2, 1 mm (the table each
 * test prints; docs/validation.md, "The drying front against Stefan"). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "column_fixture.h"
#include "mpm_fixture.h"
#include "stefan_form.h"
#include "browning.h"

static const double RHO = 484, CP = 2700, KW = 0.51, KD = 0.23, SAT = 0.218, TO = 200, TB = 100, BETA = 30;
static const double DEPTH = 0.024, WIDTH = 0.024; /* the slab; the front reaches ~6.5 mm in 25 min */
#define NT 10 /* samples, every 150 s to 25 min */
static const double EVERY = 150;

/* (3) and (4) (stefan_form.h) with this slab's numbers: the time at which the front reaches d, and back. */
static stefan_form form(void) { return (stefan_form){BETA, KD, RHO * CP, 1000 * SAT * HEARTH_LATENT_HEAT, TO, TB}; }
static double t_of_d(double d, int sensible) { const stefan_form f = form(); return stefan_t_of_d(&f, d, sensible); }
static double d_of_t(double t, int sensible) { const stefan_form f = form(); return stefan_d_of_t(&f, t, sensible); }

/* Measurement switches, unset in the tests (docs/validation.md's loaf
 * comparison used them): FRONT_T0 the slab's start (degC; a cold crumb, as the
 * loaf's 25 degC), FRONT_EVAP and FRONT_K the evaporation beta^w and the water
 * diffusivity K (bread's 1.2e-5 and 2.46e-11), FRONT_DX one spacing for the
 * three runs (a whole number of cells across WIDTH), FRONT_DT the step,
 * FRONT_FLIP the heat_flip, FRONT_DEBUG the end's crust profile. With any set,
 * the checks no longer speak of (4): read the table. (Read by knob,
 * column_fixture.h.) */

typedef struct front {
    double d[NT];    /* water boiled / (1000 s) per unit area (m) */
    double half[NT]; /* the middle column's depth where the moisture ratio crosses 0.5 (m) */
    double top[NT];  /* the top particle's temperature in the middle column (degC) */
    double ytop;     /* its depth below the surface (m) */
    double t_half;   /* when the top particle's moisture ratio fell below 0.5 (s) */
    double t_dry;    /* when it fell below 0.01, so that water_boil lets it heat past T_b (s) */
    double width;    /* the front's width at the end: depth of ratio 0.1 to depth of ratio 0.9 (m) */
    double spread;   /* the columns' dried depth at the end: (largest - smallest) / largest */
    double b_top[NT], Ts_top[NT], probe_top[NT]; /* with BROWN: the top particle's browning, the air surface's
                                                  * temperature browning.c gave it, the field at its place */
    double row_depth[3], row_b[3];               /* with BROWN, at the end: the middle column's rows within 3 dx
                                                  * of the top that hold air area, their depth and index, top first */
    int nrows;
    double crust_probe, crust_part; /* at the end, over the middle column's dried particles (ratio < 0.01), the
                                     * largest |T - T_(4)(depth)| / (T_s - T_b) of the probe (the B-spline average
                                     * at the particle's place) and of the particle's own temperature */
} front;

/* The middle column's particles (within dx/2 of the slab's middle): their
 * depths and moisture ratios, top first. Returns how many. */
static int column(const hearth_scene *s, double dx, double *depth, double *ratio, double *temp, int cap) {
    const double *X = pcold(&s->ps, PC_X), *Wp = pcold(&s->ps, PC_WATER), *S0 = pcold(&s->ps, PC_SAT0);
    const double *V0 = pcold(&s->ps, PC_VOL0), *T = pcold(&s->ps, PC_TEMPERATURE);
    int n = 0;
    for (int i = 0; i < s->ps.n && n < cap; i++) {
        if (fabs(X[3 * i] - 0.5 * WIDTH) >= 0.5 * dx) continue;
        double y = DEPTH - X[3 * i + 1], r = Wp[i] / (1000 * S0[i] * V0[i]), Ti = T[i];
        int k = n++;
        for (; k > 0 && depth[k - 1] > y; k--) depth[k] = depth[k - 1], ratio[k] = ratio[k - 1], temp[k] = temp[k - 1];
        depth[k] = y, ratio[k] = r, temp[k] = Ti;
    }
    return n;
}

/* The depth where the ratio first rises past level, top down, linear between particles. */
static double crossing(const double *depth, const double *ratio, int n, double level) {
    if (n == 0 || ratio[0] >= level) return 0;
    for (int k = 1; k < n; k++)
        if (ratio[k] >= level)
            return depth[k - 1] + (depth[k] - depth[k - 1]) * (level - ratio[k - 1]) / (ratio[k] - ratio[k - 1]);
    return depth[n - 1];
}

static int BROWN; /* the run bakes with browning on (drying_front_surface_browns) */

/* The slab at dx, stepped at dt_max; fills f. flip: the scene's heat_flip. */
static int run(double dx, double dt_max, double flip, front *f) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = dx;
    d.gravity[1] = 0;
    /* particles are seeded at least a cell from the box walls: the box starts a cell before the slab */
    d.lo[0] = d.lo[1] = -dx;
    d.hi[0] = WIDTH + dx;
    d.hi[1] = DEPTH + 0.008;
    d.oven_temperature = TO;
    d.oven_beta = BETA;
    d.latent_heat = 1;
    d.boiling_point = TB;
    d.heat_implicit = 1;
    d.heat_flip = flip;
    d.browning = BROWN;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return 0;
    hearth_error err;
    const char *nm[] = {"E", "density", "conductivity", "specific_heat", "water_diffusivity", "evaporation", "dry_conductivity"};
    const double v[] = {1e-2, RHO, KW, CP, knob("FRONT_K", 0.0), knob("FRONT_EVAP", 0.0), KD};
    const int m = hearth_scene_add_material(s, "elastic", nm, v, 7, &err);
    if (m < 0) printf("    material: %s\n", err.msg);
    CHECK(m >= 0);
    const double c[3] = {0.5 * WIDTH, 0.5 * DEPTH, 0}, h[3] = {0.5 * WIDTH, 0.5 * DEPTH, 0};
    hearth_shape *box = hearth_shape_box(c, h);
    hearth_body_def b = hearth_default_body_def();
    b.shape = box, b.material = m, b.jitter = 0, b.fixed = 1, b.temperature = knob("FRONT_T0", TB), b.saturation = SAT;
    CHECK(hearth_scene_add_body(s, &b, &err) == 0);
    hearth_shape_free(box);
    CHECK(hearth_scene_set_dt_limits(s, 0.5, dt_max, &err) == HEARTH_OK);
    hearth_stats st;
    hearth_scene_stats(s, &st);
    const double W0 = st.water_mass;
    enum { CAP = 512 };
    double depth[CAP], ratio[CAP], temp[CAP];
    f->t_half = f->t_dry = INFINITY;
    const int sub = 15; /* the top's drying time to EVERY / sub */
    for (int k = 0; k < NT; k++) {
        for (int j = 1; j <= sub; j++) {
            if (hearth_scene_advance(s, k * EVERY + j * EVERY / sub, &err) != HEARTH_OK) {
                printf("    advance: %s\n", err.msg);
                CHECK(0);
                hearth_scene_destroy(s);
                return 0;
            }
            const int n = column(s, dx, depth, ratio, temp, CAP);
            if (n > 0 && ratio[0] < 0.5 && !isfinite(f->t_half)) f->t_half = hearth_scene_time(s);
            if (n > 0 && ratio[0] < 0.01 && !isfinite(f->t_dry)) f->t_dry = hearth_scene_time(s);
        }
        hearth_scene_stats(s, &st);
        f->d[k] = (W0 - st.water_mass) / (1000 * SAT * WIDTH);
        const int n = column(s, dx, depth, ratio, temp, CAP);
        f->half[k] = crossing(depth, ratio, n, 0.5);
        f->top[k] = temp[0];
        f->ytop = depth[0];
        if (BROWN && k == NT - 1 && getenv("FRONT_DEBUG")) { /* the middle column's rows: depth, index, surface offset */
            const double *X = pcold(&s->ps, PC_X), *o = pcold(&s->ps, PC_SURFACE), *bb = pcold(&s->ps, PC_BROWNING);
            for (int i = 0; i < s->ps.n; i++)
                if (fabs(X[3 * i] - 0.5 * WIDTH) < 0.5 * dx && DEPTH - X[3 * i + 1] < 4 * dx)
                    printf("      row at %.3f mm: b %.4f, surface offset %.2f K, depth %.3f mm, area %.3g\n", 1e3 * (DEPTH - X[3 * i + 1]), bb[i],
                           o[2 * i], 1e3 * s->boundary.depth[i], s->boundary.area[i]);
        }
        if (BROWN && k == NT - 1) {
            f->nrows = 0;
            const double *X = pcold(&s->ps, PC_X), *bb = pcold(&s->ps, PC_BROWNING);
            for (int i = 0; i < s->ps.n; i++) {
                const double dp = DEPTH - X[3 * i + 1];
                if (!(fabs(X[3 * i] - 0.5 * WIDTH) < 0.5 * dx && dp < 3 * dx && s->boundary.area[i] > 0)) continue;
                int same = 0; /* the column is two particles wide: one of each row */
                for (int q = 0; q < f->nrows; q++) same |= fabs(f->row_depth[q] - dp) < 0.1 * dx;
                if (same) continue;
                int j = f->nrows < 3 ? f->nrows++ : 3; /* insert by depth, keeping the three shallowest */
                for (; j > 0 && f->row_depth[j - 1] > dp; j--)
                    if (j < 3) f->row_depth[j] = f->row_depth[j - 1], f->row_b[j] = f->row_b[j - 1];
                if (j < 3) f->row_depth[j] = dp, f->row_b[j] = bb[i];
            }
        }
        if (BROWN) {
            const int it = column_top_particle(s, 0.5 * WIDTH, dx);
            const double *o = pcold(&s->ps, PC_SURFACE), *X = pcold(&s->ps, PC_X);
            f->b_top[k] = pcold(&s->ps, PC_BROWNING)[it];
            f->Ts_top[k] = pcold(&s->ps, PC_TEMPERATURE)[it] + o[2 * it];
            CHECK(hearth_probe_point(s, "temperature", X + 3 * it, &f->probe_top[k], &err) == HEARTH_OK);
        }
        if (k == NT - 1) {
            f->width = crossing(depth, ratio, n, 0.9) - crossing(depth, ratio, n, 0.1);
            const double t = (k + 1) * EVERY, d4 = d_of_t(t, 1), q = (TO - TB) / (1 / BETA + d4 / KD), dT = q * d4 / KD;
            f->crust_probe = f->crust_part = 0;
            for (int i = 0; i < n; i++) {
                if (ratio[i] >= 0.01) continue;
                const double at[3] = {0.5 * WIDTH, DEPTH - depth[i], 0}, lin = TB + fmax(0, q * (d4 - depth[i]) / KD);
                double pT = NAN;
                CHECK(hearth_probe_point(s, "temperature", at, &pT, &err) == HEARTH_OK);
                f->crust_probe = fmax(f->crust_probe, fabs(pT - lin) / dT);
                f->crust_part = fmax(f->crust_part, fabs(temp[i] - lin) / dT);
                if (getenv("FRONT_DEBUG"))
                    printf("      depth %.3f mm: ratio %.4f, T %.2f degC, probe %.2f, (4) %.2f\n", 1e3 * depth[i], ratio[i],
                           temp[i], pT, lin);
            }
        }
    }
    /* each column's dried depth (particles binned by x cell): a 1D slab dries alike across */
    const int nc = (int)lround(WIDTH / dx);
    double *col = calloc((size_t)nc, sizeof(double));
    const double *X = pcold(&s->ps, PC_X), *Wp = pcold(&s->ps, PC_WATER), *S0 = pcold(&s->ps, PC_SAT0);
    const double *V0 = pcold(&s->ps, PC_VOL0);
    for (int i = 0; i < s->ps.n; i++) {
        int j = (int)(X[3 * i] / dx);
        j = j < 0 ? 0 : j >= nc ? nc - 1 : j;
        col[j] += (1000 * S0[i] * V0[i] - Wp[i]) / (1000 * SAT * dx);
    }
    double lo = INFINITY, hi = 0;
    for (int j = 0; j < nc; j++) lo = fmin(lo, col[j]), hi = fmax(hi, col[j]);
    f->spread = (hi - lo) / hi;
    free(col);
    printf("    dx %.4g mm, dt_max %.3g s, heat_flip %.0f: %d particles, %ld steps; columns' dried depth %.3f .. %.3f mm\n",
           1e3 * dx, dt_max, flip, s->ps.n, s->step, 1e3 * lo, 1e3 * hi);
    hearth_scene_destroy(s);
    return 1;
}

static void table(const front *f, int n, const double *dxs) {
    printf("    t (min) | d (3) | d (4) mm | d_int at dx");
    for (int r = 0; r < n; r++) printf(" %g", 1e3 * dxs[r]);
    printf(" mm | ratio-0.5 depth | T_s (4) | T_top (T of (4) at its depth)\n");
    for (int k = 0; k < NT; k++) {
        const double t = (k + 1) * EVERY, d3 = d_of_t(t, 0), d4 = d_of_t(t, 1);
        const double q = (TO - TB) / (1 / BETA + d4 / KD);
        printf("    %5.1f | %.3f | %.3f |", t / 60, 1e3 * d3, 1e3 * d4);
        for (int r = 0; r < n; r++) printf(" %.3f", 1e3 * f[r].d[k]);
        printf(" |");
        for (int r = 0; r < n; r++) printf(" %.3f", 1e3 * f[r].half[k]);
        printf(" | %.2f |", TB + q * d4 / KD);
        for (int r = 0; r < n; r++) printf(" %.2f (%.2f)", f[r].top[k], TB + fmax(0, q * (d4 - f[r].ytop) / KD));
        printf("\n");
    }
    for (int r = 0; r < n; r++)
        printf("    dx %g mm: the top particle (depth %.3f mm) half dry at %.1f min, dry (ratio 0.01) at %.1f min, (4) puts the front at its centre at %.1f min, past it at %.1f; "
               "front width (ratio 0.1 to 0.9) %.3f mm = %.2f dx; columns' spread %.4f; dried crust's worst |T - T_(4)| / (T_s - T_b): "
               "probe %.3f, particles %.3f\n",
               1e3 * dxs[r], 1e3 * f[r].ytop, f[r].t_half / 60, f[r].t_dry / 60, t_of_d(f[r].ytop, 1) / 60, t_of_d(2 * f[r].ytop, 1) / 60, 1e3 * f[r].width, f[r].width / dxs[r],
               f[r].spread, f[r].crust_probe, f[r].crust_part);
}

static double DXS[3] = {0.004, 0.002, 0.001};

/* The three runs at 4, 2, 1 mm, stepped at 1 s (0.25 s moves the front by
 * under 0.02 mm and the top's half-dry time by 0.3 min at most), FLIP heat (the
 * scenes' default); prints the table. */
static void three(front f[3]) {
    if (getenv("FRONT_DX")) DXS[0] = DXS[1] = DXS[2] = knob("FRONT_DX", 0);
    for (int r = 0; r < 3; r++) CHECK(run(DXS[r], knob("FRONT_DT", 1.0), knob("FRONT_FLIP", 1.0), &f[r]));
    table(f, 3, DXS);
}

/* The front follows (4) and converges in dx, each bar a priori:
 * - the integral front at 25 min: successive differences d(4 mm) - d(2 mm)
 *   over d(2 mm) - d(1 mm) above 1.6 (first order gives 2: the boiling zone is
 *   a stencil wide, so it places the front to within O(dx)); their Richardson
 *   limit 2 d(1 mm) - d(2 mm) within St^2 of (4) (what (4) leaves out), and
 *   nearer (4) than half the distance (3)-(4), so the crust's sensible heat is
 *   resolved (the test tells (3) from (4));
 * - the top particle's moisture ratio falls below 0.5 when (4)'s front passes
 *   its centre plus a delay that halves with dx (ratio above 1.5 each halving):
 *   the boiling zone's width in time;
 * - the front's width (ratio 0.1 to 0.9) under 3 dx, the B-spline stencil,
 *   at every dx: a front, not a zone of fixed width;
 * - the dried crust's temperature field (the B-spline probe at the middle
 *   column's dried particles) against (4)'s linear profile: under 0.1 of
 *   T_s - T_b at 1 mm (the steady dried slab's bar, unit_dry_crust) and
 *   falling at first order (ratio above 1.6) from 2 to 1 mm;
 * - the columns dry alike to 1% at 1 mm (the slab is 1D; its top corners at
 *   the box walls are the only 2D place). */
TEST(drying_front_follows_stefan) {
    front f[3];
    three(f);
    const int e = NT - 1;
    const double t = NT * EVERY, d3 = d_of_t(t, 0), d4 = d_of_t(t, 1), q = (TO - TB) / (1 / BETA + d4 / KD);
    const double st = RHO * CP * q * d4 / KD / (1000 * SAT * HEARTH_LATENT_HEAT);
    const double ratio = (f[0].d[e] - f[1].d[e]) / (f[1].d[e] - f[2].d[e]), rich = 2 * f[2].d[e] - f[1].d[e];
    printf("    25 min: d_int %.3f, %.3f, %.3f mm; differences' ratio %.2f (asked > 1.6); Richardson %.3f mm against (4) %.3f, "
           "(3) %.3f mm: %.2f%% off (4) (asked < St^2 = %.2f%%, St %.4f)\n",
           1e3 * f[0].d[e], 1e3 * f[1].d[e], 1e3 * f[2].d[e], ratio, 1e3 * rich, 1e3 * d4, 1e3 * d3, 100 * fabs(rich - d4) / d4,
           100 * st * st, st);
    CHECK(ratio > 1.6);
    CHECK(fabs(rich - d4) / d4 < st * st);
    CHECK(fabs(rich - d4) < 0.5 * fabs(d3 - d4));
    double delay[3];
    for (int r = 0; r < 3; r++) delay[r] = f[r].t_half - t_of_d(f[r].ytop, 1);
    printf("    the top's drying delay: %.2f, %.2f, %.2f min (ratios %.2f, %.2f, asked > 1.5)\n", delay[0] / 60, delay[1] / 60,
           delay[2] / 60, delay[0] / delay[1], delay[1] / delay[2]);
    CHECK(delay[0] / delay[1] > 1.5 && delay[1] / delay[2] > 1.5);
    for (int r = 0; r < 3; r++) CHECK(f[r].width < 3 * DXS[r]);
    printf("    dried crust's field against (4): %.3f, %.3f, %.3f of T_s - T_b (asked < 0.1 at 1 mm, ratio %.2f > 1.6)\n",
           f[0].crust_probe, f[1].crust_probe, f[2].crust_probe, f[1].crust_probe / f[2].crust_probe);
    CHECK(f[2].crust_probe < 0.1);
    CHECK(f[1].crust_probe / f[2].crust_probe > 1.6);
    CHECK(f[2].spread < 0.01);
}

/* What loaf_physical.lua's CSV reads (the top particle's own temperature), the
 * dried particles' temperatures, against (4)'s profile: asked, as of the
 * field, under 0.1 of T_s - T_b at 1 mm and falling from 2 to 1 mm (bars set
 * before the fix, by helper stefan). FLIP (eq. 21) hands a particle its
 * nodes' change, never their value, so a sub-cell difference between
 * particles was never damped, and it grew while a dried particle shared nodes
 * with wet ones held at 100 degC: 0.101, 0.177, 0.302 at 4, 2, 1 mm before
 * (helper boilflip's measurement, docs/validation.md "Dried particles take
 * the field's temperature"). fields/subcell.c now relaxes each dried particle
 * toward its nodes' linear fit over the dried particles alone, conserving
 * heat exactly and leaving the wet rows out, so the front's kink stays
 * (docs/validation.md "Sub-cell exchange among dried particles"). */
TEST(drying_front_crust_particles_follow_profile) {
    front f[3];
    three(f);
    const double e1 = f[2].crust_part, e2 = f[1].crust_part;
    printf("    dried particles' own temperatures against (4): %.3f, %.3f, %.3f of T_s - T_b at 4, 2, 1 mm "
           "(the field's: %.3f, %.3f, %.3f; asked < 0.1 at 1 mm and falling from 2 mm)\n",
           f[0].crust_part, e2, e1, f[0].crust_probe, f[1].crust_probe, f[2].crust_probe);
    CHECK(e1 < 0.1);
    CHECK(e1 < e2);
}

/* The closed form's surface browning: browning.c's kinetics (Zanoni et al. 1995) at full rate (the surface is
 * dry from t = 0, when the front starts) integrated over (4)'s surface temperature T_s(t) = T_b + q d / k,
 * by the midpoint rule in steps of 1 s (rounding below 1e-6 of b). */
static double b_closed_at(double y, double t_end) {
    double I = 0;
    const int n = (int)lround(t_end);
    for (int j = 0; j < n; j++) {
        const double t = j + 0.5, d4 = d_of_t(t, 1), q = (TO - TB) / (1 / BETA + d4 / KD);
        if (d4 > y) I += browning_rate(TB + q * (d4 - y) / KD, 1.0); /* dry from when the front passes y */
    }
    return -expm1(-I);
}
static double b_closed(double t_end) { return b_closed_at(0, t_end); }

/* The top's colour against the closed form's surface (issue #18, helper surfacecolour). Colour is the surface's,
 * and browning.c reads, for a particle on the oven's air surface, the surface temperature the oven's flux defines
 * (thermal.c's thermal_surface_temperature: T_o - (T_o - th) / (1 + beta d / kappa), th the nodes' value at the
 * particle, d its sample's depth) and the surface's saturation by the evaporation's closure (here, with no
 * evaporation and no diffusivity, the particle's own). The same slab, browning on, 25 min at 4 and 2 mm: the
 * middle column's top particle's index against b_closed (0.2818), the surface's temperature against (4)'s
 * T_s (144.46 degC). Bars, each with its reason:
 * - the index's error at 2 mm under 15% of the closed form: the front itself (d_int) is 6.1% off (4) at 2 mm, and the
 *   top particle dries 2.7 min late there (drying_front_follows_stefan: the boiling zone's width), and its
 *   water factor holds it back meanwhile (a first-order delay we do not remove here);
 * - the error falling with dx: |b(2) - b_c| under 0.7 |b(4) - b_c| (first order gives 0.5);
 * - the surface temperature within 0.05 (T_s - T_b) of (4)'s at both dx (the closure exact on a linear profile:
 *   what is left is the field's own error, 0.14 at 2 mm in the crust, smaller at the surface).
 * Honesty about the bars: they were fixed after a first measurement of this case at 4 and 2 mm during the work,
 * from the reasons above, not fitted to it. Measured (25 min, 4 / 2 / 1 mm): before (the particle's own
 * temperature) 0.183 / 0.206 / 0.241; the surface from the particle's own temperature (rejected) 0.325 / 0.296 /
 * 0.290 with T_s 153.6 / 146.5 / 145.6 degC; the surface from the nodes' sample (this) 0.224 / 0.255 with T_s
 * 144.3 / 143.2 degC (1 mm: 0.265, 143.3); with the surface taken dry (water factor 1, not done) 0.252 / 0.264.
 * The rows under the top that hold air area too (boundary.c's ramp) read the profiles d0 above their sample
 * (browning.c): bars, set before measuring, that their index falls with depth and stays under the form's at half
 * a cell above the row (b_closed_at). Measured at 25 min (4 mm rows at 1, 3, 5 mm; 2 mm rows at 0.5, 1.5, 2.5 mm):
 * 0.224, 0.118, 0.036 and 0.255, 0.204, 0.140 (the form there 0.193, 0.078, 0.020 and 0.235, 0.158, 0.101; half
 * a cell above 0.282, 0.193, 0.078 and 0.282, 0.235, 0.158); every row read at the surface (surfacecolour's
 * first version) 0.224, 0.170, 0.079 and 0.255, 0.250, 0.236, over the bar at 3 of 4 rows.
 * 2.6 s CPU in release: release_only. */
TEST(drying_front_surface_browns) {
    BROWN = 1;
    const int nr = getenv("FRONT_NR") ? atoi(getenv("FRONT_NR")) : 2;
    front f[3];
    for (int r = 0; r < nr; r++) CHECK(run(DXS[r], knob("FRONT_DT", 1.0), 1.0, &f[r]));
    for (int k = 0; k < NT; k++) {
        const double t = (k + 1) * EVERY, d4 = d_of_t(t, 1), q = (TO - TB) / (1 / BETA + d4 / KD);
        printf("    %5.1f min: (4) T_s %.2f b %.4f |", t / 60, TB + q * d4 / KD, b_closed(t));
        for (int r = 0; r < nr; r++)
            printf(" dx %g: b %.4f T_s %.2f T_p %.2f probe %.2f |", 1e3 * DXS[r], f[r].b_top[k], f[r].Ts_top[k], f[r].top[k], f[r].probe_top[k]);
        printf("\n");
    }
    const int e = NT - 1;
    const double t = NT * EVERY, d4 = d_of_t(t, 1), q = (TO - TB) / (1 / BETA + d4 / KD), Ts = TB + q * d4 / KD, bc = b_closed(t);
    const double e4 = fabs(f[0].b_top[e] - bc), e2 = fabs(f[1].b_top[e] - bc);
    printf("    25 min: top index %.4f, %.4f at 4, 2 mm against %.4f (errors %.1f%%, %.1f%%: asked < 15%% at 2 mm, ratio %.2f "
           "< 0.7); surface %.2f, %.2f degC against %.2f (asked within %.2f K)\n",
           f[0].b_top[e], f[1].b_top[e], bc, 100 * e4 / bc, 100 * e2 / bc, e2 / e4, f[0].Ts_top[e], f[1].Ts_top[e], Ts,
           0.05 * (Ts - TB));
    CHECK(e2 < 0.15 * bc);
    CHECK(e2 < 0.7 * e4);
    for (int r = 0; r < 2; r++) CHECK(fabs(f[r].Ts_top[e] - Ts) < 0.05 * (Ts - TB));
    /* the rows under the top that also hold air area (boundary.c's ramp) read the profile d0 above their
     * sample, not the surface: their colour falls with depth and stays under the form's half a cell above them */
    for (int r = 0; r < 2; r++) {
        CHECK(f[r].nrows >= 2);
        for (int j = 0; j < f[r].nrows; j++) {
            const double up = b_closed_at(fmax(0, f[r].row_depth[j] - 0.5 * DXS[r]), t);
            printf("    dx %g mm, row %d at %.2f mm: index %.4f; the form %.4f there, %.4f half a cell above\n", 1e3 * DXS[r],
                   j, 1e3 * f[r].row_depth[j], f[r].row_b[j], b_closed_at(f[r].row_depth[j], t), up);
            if (j == 0) continue;
            CHECK(f[r].row_b[j] <= f[r].row_b[j - 1]);
            CHECK(f[r].row_b[j] <= up);
        }
    }
}

TEST_MAIN(T(drying_front_follows_stefan), T(drying_front_crust_particles_follow_profile), T(drying_front_surface_browns))
