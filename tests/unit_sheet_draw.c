/* unit_sheet_draw.c: a warming sheet the food draws its heat from (colliders.h's heat_capacity and area, #18 helper
 * traydraw). The sheet's balance C A dT/dt = (C A / w) (T_end - T) - Q(t), Q the heat its contact passes (thermal.c's
 * sheet_ledger).
 *
 * Bars set before the first run (15:08 UTC, 7 Dec 2026, before the first run): (a) the books over a run, the oven's input
 * (integrated here by the trapezoid rule over the sheet's own temperatures, not read from its books) against the
 * sheet's sensible heat plus the heat the food's particles gained, within 1%; and the heat the sheet's books say it
 * gave against what the food gained, within 1%. (b) a lumped sheet under a lumped food block (a thin block of a very
 * high conductivity, Bi = 1e-3) against the exact solution of the two coupled linear ODEs, at two time steps: the
 * heat the block took within 2% at the finer, and an observed order of at least 0.7 (the sheet takes the last field
 * step's draw: first order in the step expected). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mpm_fixture.h"
#include "thermal.h"

/* Half-plane {(x - p) . n < 0}. */
static hearth_shape *half(double px, double py, double nx, double ny) {
    const double p[3] = {px, py, 0}, n[3] = {nx, ny, 0};
    return hearth_shape_plane(p, n);
}

typedef struct {
    double L, W, dx, rho, alpha, kappa; /* the block 0 < y < L, |x| < W / 2, pinned; its material */
    double beta, Te, T0, Tf0, w, Ca, A; /* the sheet under it (the half-plane y < 0) */
    int implicit, field_steps;
    double dt, tend;
} sheet_case;

typedef struct {
    double food_heat, drawn, oven_trap, oven_books, sheet_heat, sheet_T, plain_T, Cf, mean_Tf;
    long steps;
} sheet_result;

static hearth_scene *sheet_scene(const sheet_case *c, int draws) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = c->dx;
    d.gravity[1] = 0;
    const double D = ceil((0.6 * fmax(c->L, c->W)) / c->dx + 4) * c->dx;
    for (int k = 0; k < 2; k++) d.lo[k] = -D, d.hi[k] = D;
    d.heat_implicit = c->implicit;
    d.field_steps = c->field_steps;
    hearth_scene *s = fx_scene_def(&d);
    const char *nm[] = {"E", "density", "conductivity", "specific_heat"};
    const double nv[] = {1e-2, c->rho, c->kappa, c->alpha};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "elastic", nm, nv, 4, &err);
    CHECK(m >= 0);
    const double ctr[3] = {0, 0.5 * c->L, 0}, hw[3] = {0.5 * c->W, 0.5 * c->L, 1};
    hearth_shape *blk = hearth_shape_box(ctr, hw);
    hearth_body_def b = hearth_default_body_def();
    b.shape = blk, b.material = m, b.jitter = 0, b.temperature = c->Tf0, b.fixed = 1;
    CHECK(hearth_scene_add_body(s, &b, &err) == 0);
    hearth_shape_free(blk);
    hearth_shape *plate = half(0, 0, 0, 1);
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = plate, cd.temperature = c->Te, cd.beta = c->beta, cd.start_temperature = c->T0, cd.warm_time = c->w;
    if (draws) cd.heat_capacity = c->Ca, cd.area = c->A;
    CHECK(hearth_scene_add_collider(s, &cd, &err) == 0);
    hearth_shape_free(plate);
    CHECK(hearth_scene_set_dt_limits(s, 0.5, c->dt, &err) == HEARTH_OK);
    return s;
}

static double food_heat(const hearth_scene *s, double alpha) {
    double e = 0;
    for (int i = 0; i < s->ps.n; i++) e += pcold(&s->ps, PC_MASS)[i] * alpha * pcold(&s->ps, PC_TEMPERATURE)[i];
    return e;
}

static sheet_result run_sheet(const sheet_case *c) {
    sheet_result r = {0};
    hearth_scene *s = sheet_scene(c, 1);
    hearth_error err;
    const double e0 = food_heat(s, c->alpha);
    double cap = 0;
    for (int i = 0; i < s->ps.n; i++) cap += pcold(&s->ps, PC_MASS)[i] * c->alpha;
    const collider *col = &s->cols[0];
    const double CA = c->Ca * c->A;
    /* the oven's input C A / w (T_end - T) dt by the trapezoid rule over the sheet's states, each at its field step's end */
    double tp = col->sheet_t, Tp = col->sheet_T, trap = 0;
    hearth_stats sts;
    for (;;) {
        hearth_scene_stats(s, &sts);
        if (sts.t >= c->tend * (1 - 1e-12)) break;
        if (sts.t + c->dt > c->tend) CHECK(hearth_scene_advance(s, c->tend, &err) == HEARTH_OK);
        else CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
        if (col->sheet_t > tp) {
            trap += 0.5 * (col->sheet_t - tp) * CA / c->w * ((c->Te - Tp) + (c->Te - col->sheet_T));
            tp = col->sheet_t, Tp = col->sheet_T;
        }
    }
    hearth_scene_stats(s, &sts);
    r.food_heat = food_heat(s, c->alpha) - e0;
    r.mean_Tf = c->Tf0 + r.food_heat / cap;
    r.Cf = cap;
    r.drawn = col->drawn;
    r.oven_trap = trap;
    r.oven_books = col->oven_in;
    r.sheet_heat = CA * (col->sheet_T - c->T0);
    r.sheet_T = col->sheet_T;
    r.steps = sts.step;
    CHECK_NEAR(col->sheet_t, c->tend, 1e-9 * c->tend);
    hearth_scene_destroy(s);
    /* the same sheet without the draw (warm_time alone) */
    r.plain_T = c->Te + (c->T0 - c->Te) * exp(-c->tend / c->w);
    return r;
}

/* (a) The books: the physical cookie's sheet (1 mm aluminium, 2430 J/(m^2 K), its time constant 40 s under the
 * oven's 30 W/(m^2 K) on both faces, 190 degC) under a 17.5 mm dough of 0.5 W/(m K), through pan_beta 100, the sheet
 * three times the dough's width; explicit heat, the fields' automatic cycle. */
TEST(sheet_draw_energy_balance) {
    const sheet_case c = {.L = 0.0175, .W = 0.04, .dx = 0.0025, .rho = 1000, .alpha = 2000, .kappa = 0.5,
                          .beta = 100, .Te = 190, .T0 = 20, .Tf0 = 20, .w = 40, .Ca = 2430, .A = 0.12,
                          .implicit = 0, .field_steps = 0, .dt = 0.5, .tend = 120};
    const sheet_result r = run_sheet(&c);
    const double rhs = r.sheet_heat + r.food_heat, bal = (r.oven_trap - rhs) / r.oven_trap;
    const double tally = (r.drawn - r.food_heat) / r.food_heat, books = (r.oven_books - r.oven_trap) / r.oven_trap;
    printf("  %ld steps to %.0f s: oven input %.2f J/m (trapezoid over the sheet's states; its books %.2f, %+.2e)\n",
           r.steps, c.tend, r.oven_trap, r.oven_books, books);
    printf("  sheet's sensible heat %.2f J/m + food's gain %.2f J/m = %.2f: %+.3e of the oven's input (bar 1%%)\n",
           r.sheet_heat, r.food_heat, rhs, bal);
    printf("  the draw the sheet's books took %.2f J/m against the food's gain: %+.3e (bar 1%%)\n", r.drawn, tally);
    printf("  the sheet at %.0f s: %.2f degC drawn on, %.2f degC as warm_time alone; the food's mean %.2f degC\n", c.tend,
           r.sheet_T, r.plain_T, r.mean_Tf);
    CHECK(fabs(bal) < 0.01);
    CHECK(fabs(tally) < 0.01);
    CHECK(r.sheet_T < r.plain_T && r.food_heat > 0);
}

/* The exact solution of the lumped pair: sheet C_s dTs/dt = (C_s / w)(Te - Ts) - G (Ts - Tf), food C_f dTf/dt =
 * G (Ts - Tf). With y = (Ts - Te, Tf - Te), dy/dt = M y, M = [[-(a + gs), gs], [gf, -gf]], a = 1 / w, gs = G / C_s,
 * gf = G / C_f: eigenvalues l^2 + (a + gs + gf) l + a gf = 0 (both real and negative: the discriminant is at least
 * (a + gf)^2 - 4 a gf >= 0), eigenvectors (gf + l, gf) from M's second row, y(0) = c1 v1 + c2 v2. */
static void lumped_pair(double Cs, double Cf, double G, double w, double Te, double Ts0, double Tf0, double t, double *Ts,
                        double *Tf) {
    const double a = 1 / w, gs = G / Cs, gf = G / Cf, b = a + gs + gf, disc = sqrt(b * b - 4 * a * gf);
    const double l1 = 0.5 * (-b + disc), l2 = 0.5 * (-b - disc);
    const double v1[2] = {gf + l1, gf}, v2[2] = {gf + l2, gf}, y0[2] = {Ts0 - Te, Tf0 - Te};
    const double det = v1[0] * v2[1] - v2[0] * v1[1];
    const double c1 = (y0[0] * v2[1] - v2[0] * y0[1]) / det, c2 = (v1[0] * y0[1] - y0[0] * v1[1]) / det;
    *Ts = Te + c1 * v1[0] * exp(l1 * t) + c2 * v2[0] * exp(l2 * t);
    *Tf = Te + c1 * v1[1] * exp(l1 * t) + c2 * v2[1] * exp(l2 * t);
}

/* (b) The lumped pair: a 10 x 20 mm block of kappa 1e4 W/(m K) (Bi = beta L / kappa = 1e-3) on a sheet of the same
 * heat capacity (C_s = C_a A = 5000 x 0.04 = 200 J/(K m), C_f = rho alpha L W = 200), contact G = beta W = 20 W/(K m),
 * the sheet's time constant 5 s; implicit heat, the fields every step, to 10 s at dt 0.2 and 0.1 s. */
TEST(sheet_draw_lumped_pair_closed_form) {
    sheet_case c = {.L = 0.01, .W = 0.02, .dx = 0.0025, .rho = 1000, .alpha = 1000, .kappa = 1e4, .beta = 1000,
                    .Te = 200, .T0 = 20, .Tf0 = 20, .w = 5, .Ca = 5000, .A = 0.04, .implicit = 1, .field_steps = 1,
                    .tend = 10};
    const double dts[2] = {0.2, 0.1};
    double err[2];
    for (int k = 0; k < 2; k++) {
        c.dt = dts[k];
        const sheet_result r = run_sheet(&c);
        double Ts, Tf;
        lumped_pair(c.Ca * c.A, r.Cf, c.beta * c.W, c.w, c.Te, c.T0, c.Tf0, c.tend, &Ts, &Tf);
        const double exact = r.Cf * (Tf - c.Tf0);
        err[k] = (r.food_heat - exact) / exact;
        printf("  dt %.2f s (%ld steps; C_f %.2f J/(K m)): food's heat %.3f J/m, exact %.3f: %+.3e; sheet %.3f degC, "
               "exact %.3f; food's mean %.3f, exact %.3f\n",
               c.dt, r.steps, r.Cf, r.food_heat, exact, err[k], r.sheet_T, Ts, r.mean_Tf, Tf);
    }
    const double order = log(fabs(err[0]) / fabs(err[1])) / log(2.0);
    printf("  observed order %.2f (bar >= 0.7); the finer's error %.2f%% (bar 2%%)\n", order, 100 * fabs(err[1]));
    CHECK(fabs(err[1]) < 0.02);
    CHECK(order >= 0.7);
}

/* Time scaling as the physical presets do it (dough_physical.lua: beta and the conductivity x S, the heat capacities
 * real, warm_time the real one over S): the energy test's cookie sheet at S = 50, to 120 / S s with steps S times
 * shorter, takes the same heat and ends at the same temperature as at S = 1 (bar set before the first run: 1e-6
 * relative; a heat capacity scaled with them would be S times too heavy and fail it). */
TEST(sheet_draw_time_scaled) {
    const double S = 50;
    const sheet_case c1 = {.L = 0.0175, .W = 0.04, .dx = 0.0025, .rho = 1000, .alpha = 2000, .kappa = 0.5,
                           .beta = 100, .Te = 190, .T0 = 20, .Tf0 = 20, .w = 40, .Ca = 2430, .A = 0.12,
                           .implicit = 0, .field_steps = 1, .dt = 0.5, .tend = 120};
    sheet_case cS = c1;
    cS.kappa *= S, cS.beta *= S, cS.w /= S, cS.dt /= S, cS.tend /= S;
    const sheet_result r1 = run_sheet(&c1), rS = run_sheet(&cS);
    const double dq = (rS.food_heat - r1.food_heat) / r1.food_heat, dT = (rS.sheet_T - r1.sheet_T) / r1.sheet_T;
    printf("  S = 1: %ld steps, food %.6f J/m, sheet %.9f degC; S = %g: %ld steps, food %.6f J/m (%+.2e), sheet %.9f "
           "degC (%+.2e); bar 1e-6\n", r1.steps, r1.food_heat, r1.sheet_T, S, rS.steps, rS.food_heat, dq, rS.sheet_T, dT);
    CHECK(fabs(dq) < 1e-6 && fabs(dT) < 1e-6);
}

/* What the core refuses, each naming the parameter and its range; a sheet with nothing on it is the warm_time
 * exponential (the special case: no draw). */
TEST(sheet_draw_refusals) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.01;
    hearth_scene *s = fx_scene_def(&d);
    hearth_shape *plate = half(0, 0.1, 0, 1);
    hearth_error err;
    struct {
        double C, A, w, beta;
        const char *says;
    } bad[] = {
        {-1, 0.1, 1, 100, "heat_capacity = -1 J/(m^2 K); valid range (0, 1e9]"},
        {NAN, 0.1, 1, 100, "heat_capacity = nan J/(m^2 K); valid range (0, 1e9]"},
        {INFINITY, 0.1, 1, 100, "heat_capacity = inf J/(m^2 K); valid range (0, 1e9]"},
        {2430, 0, 1, 100, "area = 0 m^2 (in 2D m, per metre of depth); valid range (0, 1e6]"},
        {2430, -0.1, 1, 100, "area = -0.1 m^2"},
        {2430, NAN, 1, 100, "area = nan m^2"},
        {0, 0.1, 1, 100, "heat_capacity = 0 J/(m^2 K); valid range (0, 1e9]"},
        {2430, 0.1, 0, 100, "needs warm_time > 0 and start_temperature"},
        {2430, 0.1, 1, INFINITY, "needs a finite beta"},
    };
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        hearth_collider_def cd = hearth_default_collider_def();
        cd.shape = plate, cd.temperature = 190, cd.beta = bad[k].beta, cd.start_temperature = 20;
        cd.warm_time = bad[k].w, cd.heat_capacity = bad[k].C, cd.area = bad[k].A;
        CHECK(hearth_scene_add_collider(s, &cd, &err) < 0);
        printf("  refused: %s\n", err.msg);
        CHECK_STR_CONTAINS(err.msg, bad[k].says);
    }
    /* nothing on the sheet: the oven alone, the warm_time exponential to rounding */
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = plate, cd.temperature = 190, cd.beta = 100, cd.start_temperature = 20, cd.warm_time = 0.05;
    cd.heat_capacity = 2430, cd.area = 0.3;
    CHECK(hearth_scene_add_collider(s, &cd, &err) == 0);
    CHECK(hearth_scene_set_dt_limits(s, 0.5, 0.003, &err) == HEARTH_OK);
    CHECK(hearth_scene_advance(s, 0.1, &err) == HEARTH_OK);
    const double want = 190 - 170 * exp(-s->cols[0].sheet_t / 0.05);
    printf("  an empty sheet at %.4f s: %.12f degC, the exponential %.12f\n", s->cols[0].sheet_t, s->cols[0].sheet_T, want);
    CHECK_NEAR(s->cols[0].sheet_T, want, 1e-9);
    CHECK(s->cols[0].drawn == 0);
    hearth_scene_destroy(s);
    /* SPH: the contact's heat is not booked there */
    d = hearth_default_scene_def();
    d.dx = 0.01, d.solver = HEARTH_SOLVER_SPH;
    s = fx_scene_def(&d);
    cd.heat_capacity = 2430, cd.area = 0.3;
    CHECK(hearth_scene_add_collider(s, &cd, &err) < 0);
    printf("  refused: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "needs the MPM solver");
    hearth_scene_destroy(s);
    hearth_shape_free(plate);
}

TEST_MAIN(T(sheet_draw_energy_balance), T(sheet_draw_lumped_pair_closed_form), T(sheet_draw_time_scaled),
          T(sheet_draw_refusals))
