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
static double energy_lost_at(double dt, int transfer, double dx) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = dx;
    d.gravity[1] = 0;
    d.dt_max = dt;
    d.transfer = transfer;
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
    printf("  %s dt %.3g s, %d particles: %ld steps to t = %.4f s, energy lost %.4e of %.4e J (%.3e per step)\n",
           transfer == HEARTH_TRANSFER_PIC ? "PIC " : transfer == HEARTH_TRANSFER_FLIP ? "FLIP" : "APIC", dt, n, s->step, st.t,
           lost, E0, lost / (double)s->step);
    CHECK(labs(s->step - lround(T / dt)) <= 1); /* uniform: the last step lands on T */
    hearth_scene_destroy(s);
    return lost;
}

static double energy_lost(double dt, int pic) { return energy_lost_at(dt, pic ? HEARTH_TRANSFER_PIC : HEARTH_TRANSFER_APIC, 1.0 / 32); }

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

/* transfer = "flip" (mpm_g2p.c: APIC plus a share alpha = 1 - dt / flip_tau of each particle's residual, Fei
 * et al. 2021), flip_tau the default 0.1 s, on the same square at dx (the steps dts, CFL as the APIC test's at
 * dx 1/32), judged by apic_energy_converges_in_dt's rule: each change at most 3/4 of the one before. Returns
 * whether it settles; the ratios go to r[2]. */
static int flip_settles(double dx, const double dts[4], double r[2], double lost[4]) {
    for (int k = 0; k < 4; k++) lost[k] = energy_lost_at(dts[k], HEARTH_TRANSFER_FLIP, dx);
    for (int k = 0; k < 4; k++) CHECK(lost[k] > 0); /* the blend never makes energy here either */
    int settles = 1;
    for (int k = 0; k < 2; k++) {
        r[k] = fabs(lost[k + 2] - lost[k + 1]) / fabs(lost[k + 1] - lost[k]);
        printf("  FLIP dx 1/%.0f: change at halving %d over the one before: %.3f (asked <= 0.75)\n", 1 / dx, k + 2, r[k]);
        if (!(r[k] <= 0.75)) settles = 0;
    }
    return settles;
}

/* At dx 1/64 (2704 particles; the steps halved with dx: the same CFL numbers) aflip's measurement (16f1520, a
 * serial scatter) read 1.96, 1.52, 1.19, 0.97 % lost, ratios 0.742, 0.674: the loss falls as dt does. Asked
 * too: the blend loses less than APIC at the first step (APIC 13.9 % there). */
TEST(flip_energy_converges_in_dt_dx64) {
    const double dts[4] = {1.2e-4, 6e-5, 3e-5, 1.5e-5};
    double r[2], lost[4];
    const int ok = flip_settles(1.0 / 64, dts, r, lost);
    const double apic = energy_lost_at(dts[0], HEARTH_TRANSFER_APIC, 1.0 / 64);
    printf("  FLIP lost %.2f, %.2f, %.2f, %.2f %%; APIC at %.3g s %.2f %%\n", 100 * lost[0], 100 * lost[1], 100 * lost[2],
           100 * lost[3], dts[0], 100 * apic);
    CHECK(lost[0] < apic);
    CHECK(ok);
}

/* At dx 1/32, the APIC test's own steps: aflip read 13.24, 15.93, 18.44, 19.67 % (ratios 0.931, 0.493), the loss
 * growing as dt falls at first: at 8 particle rows a wavelength what is left is mostly dx's error (the same
 * square at 1/64 loses a tenth as much), which the blend cannot take away. An expected failure while it does
 * not settle, printing the ratios. */
TEST(flip_energy_converges_in_dt_dx32) {
    const double dts[4] = {2.4e-4, 1.2e-4, 6e-5, 3e-5};
    double r[2], lost[4];
    if (!flip_settles(1.0 / 32, dts, r, lost))
        XFAIL("FLIP's energy lost over 0.1 s at dx 1/32 does not settle as dt halves (%.2f, %.2f, %.2f, %.2f %%; "
              "ratios %.3f, %.3f, asked <= 0.75): at 8 particle rows a wavelength the loss left is mostly the "
              "resolution's (dx 1/64 settles), and the kept residual's noise grows with the step count "
              "(docs/validation.md, 'A mergeable APIC-FLIP transfer')",
              100 * lost[0], 100 * lost[1], 100 * lost[2], 100 * lost[3], r[0], r[1]);
}

/* The shear-wave square (2D, dx 1/64: 2704 particles, past SCENE_PARALLEL_MIN) or a 3D cube in the same wave,
 * stepped n steps with transfer, flip_tau tau, at threads; its hash. */
static uint64_t wave_hash_oven(int dim, int transfer, double tau, int threads, int n, double oven) {
    hearth_set_threads(threads);
    hearth_scene_def d = hearth_default_scene_def();
    d.oven_temperature = oven; /* NaN: none; else heat scatters through P2G's field channels too */
    d.dim = dim;
    d.dx = dim == 2 ? 1.0 / 64 : 1.0 / 32;
    d.gravity[1] = -9.81;
    d.transfer = transfer;
    d.flip_tau = tau;
    hearth_scene *s = fx_scene_def(&d);
    const int mat = fx_elastic(s, 1e3, 0.3, 1);
    const double c[3] = {0.5, 0.5, dim == 3 ? 0.5 : 0}, h[3] = {dim == 2 ? 0.2 : 0.12, dim == 2 ? 0.2 : 0.12, dim == 3 ? 0.12 : 0};
    const int np = fx_box(s, mat, c, h, 4, NULL);
    CHECK(np >= SCENE_PARALLEL_MIN); /* so the step really runs on two threads */
    for (int i = 0; i < np; i++) {
        const double y = pcold(&s->ps, PC_X)[3 * i + 1];
        pcold(&s->ps, PC_V)[3 * i] = 0.05 * sin(2 * PI * (y - 0.3) / 0.4);
    }
    s->max_speed = 0.05;
    hearth_error err;
    CHECK(hearth_scene_step(s, n, &err) == HEARTH_OK);
    const uint64_t hash = hearth_scene_hash(s);
    printf("  %dD transfer %d tau %g, oven %g degC, %d thread(s), %d particles, %d steps: %016llx\n", dim, transfer, tau, oven,
           threads, np, n, (unsigned long long)hash);
    hearth_scene_destroy(s);
    hearth_set_threads(0);
    return hash;
}
static uint64_t wave_hash(int dim, int transfer, double tau, int threads, int n) {
    return wave_hash_oven(dim, transfer, tau, threads, n, NAN);
}

/* The blend's P2G runs in the colour phases and its G2P per particle: the same bits at one and two threads, in
 * 2D and in 3D (where two threads claim blocks from both ends, mpm.c's claims). */
TEST(flip_same_bits_threads) {
    CHECK(wave_hash(2, HEARTH_TRANSFER_FLIP, 0.1, 1, 40) == wave_hash(2, HEARTH_TRANSFER_FLIP, 0.1, 2, 40));
    CHECK(wave_hash(3, HEARTH_TRANSFER_FLIP, 0.1, 1, 10) == wave_hash(3, HEARTH_TRANSFER_FLIP, 0.1, 2, 10));
    /* an oven: the heat's channels in P2G's tile and the grid before FLIP's (3D: all nine tile channels in use) */
    CHECK(wave_hash_oven(2, HEARTH_TRANSFER_FLIP, 0.1, 1, 20, 200) == wave_hash_oven(2, HEARTH_TRANSFER_FLIP, 0.1, 2, 20, 200));
    CHECK(wave_hash_oven(3, HEARTH_TRANSFER_FLIP, 0.1, 1, 5, 200) == wave_hash_oven(3, HEARTH_TRANSFER_FLIP, 0.1, 2, 5, 200));
    CHECK(wave_hash_oven(3, HEARTH_TRANSFER_FLIP, 1e-9, 1, 5, 200) == wave_hash_oven(3, HEARTH_TRANSFER_APIC, 0.1, 1, 5, 200));
}

/* flip_tau at or below dt makes alpha 0: v_p = v^{n+1}(x_p) + 0 (v_p - v^n(x_p)), APIC's velocity to the bit, and
 * P2G's extra channels take nothing from the momentum: APIC's hash (through the colour phases instead of the
 * one-region step, which give the same bits), and a blend that keeps something moves it. */
TEST(flip_alpha_zero_is_apic) {
    const uint64_t apic = wave_hash(2, HEARTH_TRANSFER_APIC, 0.1, 1, 30);
    CHECK(wave_hash(2, HEARTH_TRANSFER_FLIP, 1e-9, 1, 30) == apic);
    CHECK(wave_hash(2, HEARTH_TRANSFER_FLIP, 0.1, 1, 30) != apic);
    const uint64_t apic3 = wave_hash(3, HEARTH_TRANSFER_APIC, 0.1, 1, 5);
    CHECK(wave_hash(3, HEARTH_TRANSFER_FLIP, 1e-9, 1, 5) == apic3);
}

/* Hostile settings: each refused at creation with a message naming the setting and its range, never run. */
TEST(flip_settings_refused) {
    static const double bad_tau[] = {0.0, -0.1, NAN, INFINITY, -INFINITY};
    hearth_error err;
    for (size_t k = 0; k < sizeof bad_tau / sizeof bad_tau[0]; k++) {
        hearth_scene_def d = hearth_default_scene_def();
        d.transfer = HEARTH_TRANSFER_FLIP;
        d.flip_tau = bad_tau[k];
        hearth_scene *s = hearth_scene_create(&d, &err);
        CHECK(s == NULL);
        printf("  flip_tau %g: %s\n", bad_tau[k], err.msg);
        CHECK_STR_CONTAINS(err.msg, "flip_tau");
        hearth_scene_destroy(s);
    }
    hearth_scene_def d = hearth_default_scene_def();
    d.transfer = 3;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    printf("  transfer 3: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "transfer");
    d = hearth_default_scene_def();
    d.transfer = HEARTH_TRANSFER_FLIP;
    d.solver = HEARTH_SOLVER_SPH;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    printf("  flip with SPH: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "transfer = \"flip\" needs solver = \"mpm\"");
    d = hearth_default_scene_def();
    d.transfer = HEARTH_TRANSFER_FLIP;
    d.two_field = 1;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    printf("  flip with two_field: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "two_field");
    /* the checkpoint format keeps transfer but not flip_tau: a scene that moved it is refused at save */
    d = hearth_default_scene_def();
    d.transfer = HEARTH_TRANSFER_FLIP;
    d.flip_tau = 0.5;
    hearth_scene *s = fx_scene_def(&d);
    CHECK(s != NULL);
    CHECK(hearth_scene_save(s, "flip_tau_refused.ckpt", &err) != HEARTH_OK);
    printf("  save: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "flip_tau");
    hearth_scene_destroy(s);
}

/* The blend keeps linear momentum: sum_p m_p v^n(x_p) = sum_i v_i^n sum_p w_ip m_p = sum_i m_i v_i^n, which is
 * P2G's momentum sum_p m_p v_p (APIC's affine terms sum to zero about each particle), so the kept residuals sum
 * to zero. Checked on a spinning blob that crosses a periodic seam (mpm_periodic_conserves_momentum's scene,
 * transfer = "flip", flip_tau 0.01 s: alpha 0.9 and less a step): the fold must carry the blend's channels, or the
 * seam's nodes would read half their velocity before the update and the momentum would move. */
TEST(flip_conserves_momentum_periodic) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 1.0 / 64;
    d.hi[0] = 0.5, d.hi[1] = 0.5;
    d.gravity[1] = 0;
    d.periodic[0] = 1;
    d.transfer = HEARTH_TRANSFER_FLIP;
    d.flip_tau = 0.01;
    hearth_scene *s = fx_scene_def(&d);
    CHECK(s != NULL);
    if (!s) return;
    const int m = fx_elastic(s, 1e4, 0.3, 1000);
    const double c[3] = {0.4, 0.25, 0}, h[3] = {0.06, 0.06, 0}, v0[3] = {1.0, 0.1, 0};
    fx_box(s, m, c, h, 4, v0);
    double *X = pcold(&s->ps, PC_X), *V = pcold(&s->ps, PC_V), *C = pcold(&s->ps, PC_C);
    const int tn = particles_tn(&s->ps);
    for (int i = 0; i < s->ps.n; i++) { /* a spin of 5 rad/s about the centre */
        V[3 * i] -= 5 * (X[3 * i + 1] - c[1]);
        V[3 * i + 1] += 5 * (X[3 * i] - c[0]);
        C[tn * i + 1] = -5, C[tn * i + 2] = 5;
    }
    double p0[2] = {0, 0};
    const double *M = pcold(&s->ps, PC_MASS);
    for (int i = 0; i < s->ps.n; i++) p0[0] += M[i] * V[3 * i], p0[1] += M[i] * V[3 * i + 1];
    hearth_error err;
    int crossed = 0;
    double worst = 0;
    while (s->t < 0.25) { /* past the seam at x = 0.5 */
        CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
        X = pcold(&s->ps, PC_X), V = pcold(&s->ps, PC_V), M = pcold(&s->ps, PC_MASS);
        double p[2] = {0, 0};
        int lo = 0, hi = 0;
        for (int i = 0; i < s->ps.n; i++) {
            p[0] += M[i] * V[3 * i], p[1] += M[i] * V[3 * i + 1];
            lo += X[3 * i] < 0.1, hi += X[3 * i] > 0.4;
        }
        crossed |= lo > 0 && hi > 0;
        worst = fmax(worst, hypot(p[0] - p0[0], p[1] - p0[1]) / hypot(p0[0], p0[1]));
    }
    printf("  %d particles, %ld steps to t = %.3f s: crossed the seam: %s; largest momentum change / |P0| %.2e\n", s->ps.n,
           s->step, s->t, crossed ? "yes" : "no", worst);
    CHECK(crossed);
    CHECK(worst < 1e-12);
    hearth_scene_destroy(s);
}

TEST_MAIN(T(apic_energy_converges_in_dt), T(flip_energy_converges_in_dt_dx64), T(flip_energy_converges_in_dt_dx32),
          T(flip_same_bits_threads), T(flip_alpha_zero_is_apic), T(flip_settings_refused), T(flip_conserves_momentum_periodic))
