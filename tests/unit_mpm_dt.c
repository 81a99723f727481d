/* unit_mpm_dt.c: the MPM step over dt at a fixed dx (issue #18, helper
 * crackdt; docs/validation.md "The crack over the time step").
 *
 * Why: bread.lua's plain loaf cracks or not with the step sequence alone
 * (the scene's three loaves, which never touch, only share dt), and its
 * smooth numbers (the slump's height, the damage summed over the loaf) move
 * further at each halving of a uniform dt instead of less. The cause found
 * is the transfer: each P2G/G2P round trip keeps a particle's velocity only
 * up to the affine part of the field around it (APIC, Jiang et al. 2015),
 * and loses some of the rest every step. Measured below, that loss per step
 * falls more slowly than dt (as dt^0.76), so over a fixed time it grows as
 * dt falls at a fixed dx (as dt^-0.24): a numerical damping that counts
 * steps as well as time, and the loaf's ringing, which it damps, is what the
 * stretch rule's damage sums (it counts stretch along the elastic strain).
 * This test measures it on an elastic body, where nothing else takes
 * energy: the step is otherwise symplectic Euler, whose energy error stays
 * bounded and does not grow with the number of steps (rotating_disc). */
#include <math.h>
#include <stdio.h>

#include "mpm_fixture.h"
#include "tensor.h"
#define PI 3.14159265358979323846

/* A free elastic square (no gravity, no walls near: E 1e3, nu 0.3, rho 1, 0.4 m, dx 1/32, 4 ppc) started in
 * a shear wave of one wavelength across it, v_x = A sin(2 pi (y - y0) / 0.4), A 0.05 m/s (C its gradient, so
 * the first P2G carries the field as APIC would), stepped at a uniform dt to T = 0.1 s (about 4 periods of the
 * mode). Returns the share of the starting energy (kinetic + elastic) lost by T. */
static double energy_lost(double dt, int pic) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 1.0 / 32;
    d.gravity[1] = 0;
    d.dt_max = dt;
    d.transfer = pic;
    hearth_scene *s = fx_scene_def(&d);
    const double E = 1e3, nu = 0.3, A = 0.05, y0 = 0.3, lw = 0.4, T = 0.1;
    const int mat = fx_elastic(s, E, nu, 1);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.2, 0.2, 0};
    const int n = fx_box(s, mat, c, h, 4, NULL);
    CHECK(n > 600);
    const int tn = particles_tn(&s->ps); /* C_xy at 1 of a 2D store's 2x2 (of a 3x3 too) */
    for (int i = 0; i < n; i++) {
        const double y = pcold(&s->ps, PC_X)[3 * i + 1];
        pcold(&s->ps, PC_V)[3 * i] = A * sin(2 * PI * (y - y0) / lw);
        pcold(&s->ps, PC_C)[tn * i + 1] = A * 2 * PI / lw * cos(2 * PI * (y - y0) / lw);
    }
    s->max_speed = A;
    const double mu = E / (2 * (1 + nu)), lam = E * nu / ((1 + nu) * (1 - 2 * nu));
    double ke0 = 0;
    for (int i = 0; i < n; i++) {
        const double *v = pcold(&s->ps, PC_V) + 3 * i;
        ke0 += 0.5 * pcold(&s->ps, PC_MASS)[i] * (v[0] * v[0] + v[1] * v[1]);
    }
    const double E0 = ke0 + neo_hookean_energy(s, mu, lam);
    hearth_error err;
    CHECK(hearth_scene_advance(s, T, &err) == HEARTH_OK);
    hearth_stats st;
    hearth_scene_stats(s, &st);
    const double lost = 1 - (st.kinetic + neo_hookean_energy(s, mu, lam)) / E0;
    printf("  %s dt %.3g s, %d particles: %ld steps to t = %.4f s, energy lost %.4e of %.4e J (%.3e per step)\n", pic ? "PIC " : "APIC", dt,
           n, s->step, st.t, lost, E0, lost / (double)s->step);
    CHECK(labs(s->step - lround(T / dt)) <= 1); /* uniform: the last step lands on T */
    hearth_scene_destroy(s);
    return lost;
}

/* A free elastic body's energy over a fixed time, at four uniform steps (dt about the wave's CFL 0.28, and three
 * halvings), should converge as dt falls: nothing in the continuum takes energy, so what an integration of
 * order p > 0 loses should settle, its change shrinking at each halving. Asked: each change at most 3/4 of the
 * one before (an observed order in the changes of 0.4 or more). Measured (docs/validation.md, 'The crack over
 * the time step'): 34.7, 40.7, 48.0, 57.2 % lost at 2.4e-4 .. 3e-5 s, the loss growing by x1.17-1.19 at each
 * halving and its changes growing too: every P2G/G2P round trip keeps a particle's velocity up to the affine
 * part of its neighbourhood (APIC, Jiang et al. 2015) and loses part of the rest, so the damping counts steps
 * as well as time. Until the transfer stops doing that this is an expected failure that prints the numbers.
 * Checked as plain claims: every loss positive (the transfer never makes energy) and PIC, which keeps no affine
 * part, losing more than APIC. */
TEST(apic_energy_converges_in_dt) {
    const double dts[4] = {2.4e-4, 1.2e-4, 6e-5, 3e-5};
    double lost[4];
    for (int k = 0; k < 4; k++) lost[k] = energy_lost(dts[k], 0);
    for (int k = 0; k < 4; k++) CHECK(lost[k] > 0);
    for (int k = 0; k < 3; k++)
        printf("  APIC, dt %.3g -> %.3g: energy lost x%.3f, observed order in dt %.3f\n", dts[k], dts[k + 1],
               lost[k + 1] / lost[k], log(lost[k] / lost[k + 1]) / log(2.0));
    const double pic = energy_lost(dts[0], 1);
    printf("  PIC at dt %.3g loses x%.1f of APIC's\n", dts[0], pic / lost[0]);
    CHECK(pic > lost[0]);
    int settles = 1;
    for (int k = 0; k < 2; k++) {
        const double ratio = fabs(lost[k + 2] - lost[k + 1]) / fabs(lost[k + 1] - lost[k]);
        printf("  change at halving %d over the one before: %.3f (asked <= 0.75)\n", k + 2, ratio);
        if (!(ratio <= 0.75)) settles = 0;
    }
    if (!settles)
        XFAIL("the energy lost over 0.1 s does not settle as dt halves (%.1f, %.1f, %.1f, %.1f %%): APIC's "
              "round trip damps the non-affine motion every step, so the loss counts steps as well as time "
              "(docs/validation.md, 'The crack over the time step')",
              100 * lost[0], 100 * lost[1], 100 * lost[2], 100 * lost[3]);
}

TEST_MAIN(T(apic_energy_converges_in_dt))
