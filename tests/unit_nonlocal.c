/* unit_nonlocal.c: the damage driver's average over a physical length
 * (scene setting damage_length, core/sim/solver/mpm_nonlocal.c;
 * <hearth/material.h> rule 11; issue #18, helper nonlocal), against closed
 * forms: the average of a step is the step convolved with a Gaussian of
 * sigma = damage_length / 2 at every dx; a constant stays itself up to a free
 * surface (the normalised weight); and cam_clay_dough's stretch rule spends
 * the average it is handed in place of its own stretch. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hearth/hearth.h"
#include "hearth/material.h"
#include "mpm_fixture.h"
#include "test.h"
#define PLUGIN_FIXTURE_SEED 0x6e6c6f63
#include "plugin_fixture.h"

enum { S_RATE = 8 }; /* cam_clay_dough's stored stretch rate (its state's 9th double) */

/* A 2D slab of cam_clay_dough (defaults) filling x, y in [0.02, 0.18] of a 0.2 m box at dx, damage_length len;
 * its particles' drivers set by f(x), then the average taken once. Returns the scene (NULL on failure). */
static hearth_scene *averaged(double dx, double len, double (*f)(double)) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 2, d.dx = dx, d.damage_length = len;
    for (int k = 0; k < 3; k++) d.lo[k] = 0, d.hi[k] = 0.2;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NULL;
    hearth_error err;
    const int m = hearth_scene_add_material(s, "cam_clay_dough", NULL, NULL, 0, &err);
    CHECK(m >= 0);
    const double c[3] = {0.1, 0.1, 0}, h[3] = {0.08, 0.08, 0}, v[3] = {0};
    hearth_shape *b = hearth_shape_box(c, h);
    CHECK(hearth_scene_seed_shape(s, m, b, 4, 0.0, v, &err) > 0);
    hearth_shape_free(b);
    particles *ps = &s->ps;
    for (int i = 0; i < ps->n; i++) pcold(ps, PC_STATE)[(size_t)i * ps->state_stride + S_RATE] = f(pcold(ps, PC_X)[3 * i]);
    CHECK(mpm_nonlocal(s, &err) == HEARTH_OK);
    return s;
}

static double step_at_centre(double x) { return x > 0.1 ? 1.0 : 0.0; }
static double constant(double x) { return 0.7 + 0 * x; }

/* A step of the driver at x = 0.1 (2 cells of 4 ppc each side of it, so it falls midway between two particle
 * columns) comes back as Phi((x - 0.1) / sigma), sigma = damage_length / 2 = 10 mm, at dx 5 and 2.5 mm (sigma
 * 2 and 4 cells): the nodes' Gaussian and the B-splines' round trip together have sigma's variance at every dx
 * (mpm_nonlocal.c). Read in the slab's middle third of height, over |x - 0.1| < 3 sigma, 60 mm from the free
 * surface. The bar, 0.02 of the jump: the round trip is not a Gaussian (a B-spline has no tails) and the
 * particles sample the step at dx / 4; a width that followed the cell instead (sigma = dx) misses
 * Phi(x / 10 mm) by 0.15 (5 mm) and 0.29 (2.5 mm) at x = 5 mm, so the bar tells the two apart at both dx. */
TEST(nonlocal_average_of_a_step_is_a_gaussian_of_the_length) {
    const double len = 0.02, sigma = 0.5 * len;
    for (int r = 0; r < 2; r++) {
        const double dx = r ? 0.0025 : 0.005;
        hearth_scene *s = averaged(dx, len, step_at_centre);
        if (!s) return;
        const particles *ps = &s->ps;
        double worst = 0;
        int n = 0;
        for (int i = 0; i < ps->n; i++) {
            const double x = pcold(ps, PC_X)[3 * i], y = pcold(ps, PC_X)[3 * i + 1];
            if (fabs(y - 0.1) > 0.027 || fabs(x - 0.1) > 3 * sigma) continue;
            const double want = 0.5 * (1 + erf((x - 0.1) / (sigma * sqrt(2.0))));
            const double got = pcold(ps, PC_NONLOCAL)[i];
            worst = fmax(worst, fabs(got - want));
            n++;
        }
        printf("    dx %.1f mm: %d particles within 3 sigma of the step; worst |average - Phi| %.4f (asked < 0.02)\n",
               dx * 1e3, n, worst);
        CHECK(n > 20);
        CHECK(worst < 0.02);
        hearth_scene_destroy(s);
    }
}

/* A constant driver averages to itself at every particle, the free surface's included: the weight is
 * normalised by the averaged volume (an unnormalised sum would read about half at the surface). */
TEST(nonlocal_constant_holds_to_the_free_surface) {
    hearth_scene *s = averaged(0.005, 0.02, constant);
    if (!s) return;
    double worst = 0;
    for (int i = 0; i < s->ps.n; i++) worst = fmax(worst, fabs(pcold(&s->ps, PC_NONLOCAL)[i] - 0.7));
    printf("    %d particles: worst |average - 0.7| %.3g\n", s->ps.n, worst);
    CHECK(worst < 1e-12);
    hearth_scene_destroy(s);
}

/* One point of cam_clay_dough under the stretch rule (fracture_strain 0.5, no crack band), at rest
 * (grad_v = 0: no stretch of its own). Handed a nonlocal rate of 2 1/s for a step of 1 ms it spends
 * 2e-3 / 0.5 = 4e-3 of its extensibility; with NaN (no average) it keeps 0. And the driver it stores
 * is its own rate: one step of pure shear L = diag(r, -r, 0) from rest leaves the Hencky strain
 * log diag(1 + r dt, 1 - r dt, 1) / 1, whose deviator e gives N = e / |e| and the rate
 * sqrt(2/3) N : L = sqrt(2/3) r (e_xx - e_yy) / |e| (about 2 r / sqrt(3)). */
TEST(dough_damage_spends_the_nonlocal_rate) {
    const hearth_material *m = load_material("cam_clay_dough");
    CHECK(m != NULL);
    if (!m) return;
    CHECK(m->damage_driver != NULL && (m->needs & HEARTH_NEEDS_NONLOCAL));
    double p[32];
    for (int k = 0; k < m->nparams; k++) {
        p[k] = m->params[k].def;
        if (!strcmp(m->params[k].name, "fracture_strain")) p[k] = 0.5;
        if (!strcmp(m->params[k].name, "fracture_stretch")) p[k] = 1;
        if (!strcmp(m->params[k].name, "tau_y")) p[k] = 1e9; /* elastic */
    }
    double st[16], tau[9];
    const double rates[2] = {2.0, NAN};
    for (int c = 0; c < 2; c++) {
        m->init(p, st);
        hearth_point pt = {.dt = 1e-3, .temperature = 20, .porosity = 0.1, .saturation = NAN, .nonlocal = rates[c],
                           .p = p, .state = st, .dim = 3};
        for (int k = 0; k < 9; k++) pt.F[k] = k % 4 == 0, pt.grad_v[k] = 0;
        CHECK(m->stress(&pt, tau) == 0);
        const double D = m->damage(p, st), want = c == 0 ? 2e-3 / 0.5 : 0;
        printf("    nonlocal %g 1/s: damage %.6g (closed form %.6g)\n", rates[c], D, want);
        CHECK(fabs(D - want) <= 1e-15);
    }
    const double r = 0.3, dt = 1e-3;
    m->init(p, st);
    hearth_point pt = {.dt = dt, .temperature = 20, .porosity = 0.1, .saturation = NAN, .nonlocal = NAN, .p = p,
                       .state = st, .dim = 3};
    for (int k = 0; k < 9; k++) pt.grad_v[k] = 0, pt.F[k] = k % 4 == 0;
    pt.grad_v[0] = r, pt.grad_v[4] = -r;
    pt.F[0] = 1 + dt * r, pt.F[4] = 1 - dt * r;
    CHECK(m->stress(&pt, tau) == 0);
    const double lx = log(1 + dt * r), ly = log(1 - dt * r), mean = (lx + ly) / 3;
    const double ex = lx - mean, ey = ly - mean, ez = -mean;
    const double want = sqrt(2.0 / 3.0) * r * (ex - ey) / sqrt(ex * ex + ey * ey + ez * ez), got = m->damage_driver(st);
    printf("    pure shear at %g 1/s: stored rate %.15g (closed form %.15g)\n", r, got, want);
    CHECK(fabs(got - want) <= 1e-12 * want && fabs(want - 2 * r / sqrt(3.0)) < 1e-3 * want);
}

/* damage_length where the average is not taken: another solver, periodic axes; each refused by name. */
TEST(nonlocal_refusals) {
    hearth_scene_def d = hearth_default_scene_def();
    d.damage_length = 0.01;
    d.periodic[0] = 1;
    hearth_error err;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    printf("    %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "damage_length");
    d.periodic[0] = 0;
    d.solver = HEARTH_SOLVER_SPH;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    printf("    %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "damage_length");
}

TEST_MAIN(T(nonlocal_average_of_a_step_is_a_gaussian_of_the_length), T(nonlocal_constant_holds_to_the_free_surface),
          T(dough_damage_spends_the_nonlocal_rate), T(nonlocal_refusals))
