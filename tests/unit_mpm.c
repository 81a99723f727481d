/* unit_mpm.c: the MPM core against closed forms and conservation laws: the transfers, free fall,
 * waves, stresses, probes and the optional columns. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "grid.h"
#include "mpm_fixture.h"

#define PI 3.14159265358979323846

static uint64_t rng_state = 12345;
static double urand(void) {
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return (double)((z ^ (z >> 31)) >> 11) * (1.0 / 9007199254740992.0);
}

/* Quadratic B-splines: partition of unity, linear and quadratic moments, and
 * derivatives that match finite differences. */
TEST(bspline_weights) {
    for (int k = 0; k < 1000; k++) {
        double fx = 0.5 + urand(), w[3], dw[3];
        bspline_weights(fx, w, dw);
        double s0 = 0, s1 = 0, s2 = 0, sd = 0, sdx = 0;
        for (int i = 0; i < 3; i++) {
            s0 += w[i];
            s1 += w[i] * (i - fx);
            s2 += w[i] * (i - fx) * (i - fx);
            sd += dw[i];
            sdx += dw[i] * i; /* d/dX sum_i w_i x_i = d/dX X = 1 */
            CHECK(w[i] >= 0);
        }
        CHECK_NEAR(s0, 1.0, 1e-15);
        CHECK_NEAR(s1, 0.0, 1e-15);
        CHECK_NEAR(s2, 0.25, 1e-15); /* D_p = dx^2/4 I, as APIC uses */
        CHECK_NEAR(sd, 0.0, 1e-15);
        CHECK_NEAR(sdx, 1.0, 1e-14);
        /* dw is dw_i/dX at fixed base */
        const double h = 1e-6;
        double wp[3], wm[3], tmp[3];
        bspline_weights(fx + h, wp, tmp);
        bspline_weights(fx - h, wm, tmp);
        for (int i = 0; i < 3; i++) CHECK_NEAR((wp[i] - wm[i]) / (2 * h), dw[i], 1e-8);
    }
}

static void momenta(const hearth_scene *s, double mass_mom[4], double L[3], int affine) {
    const particles *ps = &s->ps;
    memset(mass_mom, 0, 4 * sizeof(double));
    memset(L, 0, 3 * sizeof(double));
    const double Dk = 0.25 * s->def.dx * s->def.dx;
    for (int i = 0; i < ps->n; i++) {
        const double m = pcold(ps, PC_MASS)[i], *x = pcold(ps, PC_X) + 3 * i, *v = pcold(ps, PC_V) + 3 * i;
        double C[9];
        particles_C3(ps, i, C); /* a 2D store's 2x2 block, embedded */
        mass_mom[0] += m;
        for (int d = 0; d < 3; d++) mass_mom[1 + d] += m * v[d];
        L[0] += m * (x[1] * v[2] - x[2] * v[1]);
        L[1] += m * (x[2] * v[0] - x[0] * v[2]);
        L[2] += m * (x[0] * v[1] - x[1] * v[0]);
        if (affine) { /* APIC: L_affine = m eps_abc (C D)_cb with D = dx^2/4 I */
            L[0] += m * Dk * (C[7] - C[5]);
            L[1] += m * Dk * (C[2] - C[6]);
            L[2] += m * Dk * (C[3] - C[1]);
        }
    }
}

static void grid_momenta(const hearth_scene *s, double mass_mom[4], double L[3]) {
    const grid *g = &s->g;
    const int D = g->dim, NPB = g->nodes_per_block;
    memset(mass_mom, 0, 4 * sizeof(double));
    memset(L, 0, 3 * sizeof(double));
    for (int k = 0; k < g->nactive; k++) {
        const double *node = grid_block(g, k);
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        for (int l = 0; l < NPB; l++) {
            int gi[3];
            grid_node_index(g, bc, l, gi);
            double x[3] = {0, 0, 0};
            for (int d = 0; d < D; d++) x[d] = g->lo[d] + gi[d] * g->dx;
            const double m = node[l], p[3] = {node[NPB + l], node[2 * NPB + l], node[3 * NPB + l]};
            mass_mom[0] += m;
            for (int d = 0; d < 3; d++) mass_mom[1 + d] += p[d];
            L[0] += x[1] * p[2] - x[2] * p[1];
            L[1] += x[2] * p[0] - x[0] * p[2];
            L[2] += x[0] * p[1] - x[1] * p[0];
        }
    }
}

static double rel(double a, double b) { return fabs(a - b) / fmax(1e-300, fmax(fabs(a), fabs(b))); }

/* P2G then G2P (dt = 0, no grid forces) conserves mass, linear and angular
 * momentum, the latter with APIC's affine term (Jiang et al. 2015). */
static void conservation(int dim) {
    hearth_scene *s = fx_scene(dim, 0.05, 0, 1);
    int mat = fx_elastic(s, 1e3, 0.3, 1000);
    const int n = 300;
    double x[3 * 300], v[3 * 300];
    for (int i = 0; i < 3 * n; i++) {
        x[i] = 0.2 + 0.6 * urand();
        v[i] = urand() - 0.5;
    }
    hearth_error err;
    CHECK(hearth_scene_add_particles(s, mat, n, x, v, 1e-4, &err) == n);
    for (int i = 0; i < n; i++)
        for (int a = 0; a < particles_tn(&s->ps); a++) /* 2D: the in-plane 2x2 only (tensor2.h) */
            pcold(&s->ps, PC_C)[particles_tn(&s->ps) * i + a] = 4 * (urand() - 0.5);
    double P0[4], L0[3], Pg[4], Lg[3], P1[4], L1[3];
    momenta(s, P0, L0, 1);
    CHECK(mpm_sort(s, &err) == HEARTH_OK);
    step_report rep;
    mpm_p2g(s, 0.0, &rep);
    grid_momenta(s, Pg, Lg);
    /* turn momentum into velocity without forces */
    for (int k = 0; k < s->g.nactive; k++) {
        double *node = grid_block(&s->g, k);
        const int NPB = s->g.nodes_per_block;
        for (int l = 0; l < NPB; l++)
            for (int d = 1; d <= 3; d++) node[d * NPB + l] = node[l] > 0 ? node[d * NPB + l] / node[l] : 0;
    }
    mpm_g2p(s, 0.0, &rep);
    momenta(s, P1, L1, 1);
    for (int d = 0; d < 4; d++) {
        CHECK(rel(P0[d], Pg[d]) <= 1e-12);
        CHECK(rel(P0[d], P1[d]) <= 1e-12);
    }
    const double Ls = sqrt(L0[0] * L0[0] + L0[1] * L0[1] + L0[2] * L0[2]);
    for (int d = 0; d < 3; d++) {
        CHECK(fabs(L0[d] - Lg[d]) <= 1e-12 * Ls);
        CHECK(fabs(Lg[d] - L1[d]) <= 1e-12 * Ls);
    }
    printf("  %dD: mass %.3g, |L| %.6g, grid-particle |dL|/|L| = %.2g, after G2P %.2g\n", dim, P0[0], Ls,
           fabs(L0[2] - Lg[2]) / Ls, fabs(Lg[2] - L1[2]) / Ls);
    hearth_scene_destroy(s);
}

TEST(transfer_conservation_2d) { conservation(2); }
TEST(transfer_conservation_3d) { conservation(3); }

/* A spinning elastic disc keeps its angular momentum to round-off and never
 * gains energy (the setup: rho 1, E 1e3, nu 0.2, R 0.15, dx 1/64, 4 ppc,
 * omega 10 rad/s, dt 2e-4, one revolution). */
/* PIC transfer (h.scene{transfer = "pic"}) keeps linear momentum but drops the
 * affine part, so a spinning disc loses angular momentum each step where APIC
 * keeps it (the rotating_disc test); the trade's `transfer` knob relies on it. */
TEST(transfer_pic_dissipates) {
    double Lrel[2];
    for (int pic = 0; pic <= 1; pic++) {
        hearth_scene_def d = hearth_default_scene_def();
        d.dx = 1.0 / 32;
        d.gravity[1] = 0;
        d.dt_max = 5e-4;
        d.transfer = pic;
        hearth_scene *s = fx_scene_def(&d);
        const int mat = fx_elastic(s, 1e3, 0.2, 1);
        const double c[3] = {0.5, 0.5, 0};
        hearth_shape *disc = hearth_shape_sphere(c, 0.15);
        hearth_error err;
        const int n = hearth_scene_seed_shape(s, mat, disc, 4, 0.0, NULL, &err);
        hearth_shape_free(disc);
        for (int i = 0; i < n; i++) {
            const int tn = particles_tn(&s->ps); /* C_xy at 1, C_yx at 2 of a 2D store's 2x2 (3 of a 3x3) */
            double *x = pcold(&s->ps, PC_X) + 3 * i, *v = pcold(&s->ps, PC_V) + 3 * i, *C = pcold(&s->ps, PC_C) + tn * i;
            v[0] = -10 * (x[1] - 0.5), v[1] = 10 * (x[0] - 0.5);
            C[1] = -10, C[tn == 4 ? 2 : 3] = 10;
        }
        s->max_speed = 1.5;
        double P[4], L0[3], L[3];
        momenta(s, P, L0, 1);
        CHECK(hearth_scene_step(s, 200, &err) == HEARTH_OK);
        momenta(s, P, L, 1);
        Lrel[pic] = L[2] / L0[2];
        hearth_scene_destroy(s);
    }
    printf("  angular momentum after 200 steps: APIC %.12f, PIC %.6f of the start\n", Lrel[0], Lrel[1]);
    CHECK(fabs(Lrel[0] - 1) < 1e-10);
    CHECK(Lrel[1] < 0.99);
    CHECK(Lrel[1] > 0);
}

TEST(rotating_disc) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 1.0 / 64;
    d.gravity[1] = 0;
    d.dt_max = 2e-4;
    d.cfl = 1.0;
    hearth_scene *s = fx_scene_def(&d);
    const double E = 1e3, nu = 0.2, w = 10;
    int mat = fx_elastic(s, E, nu, 1);
    const double c[3] = {0.5, 0.5, 0};
    hearth_shape *disc = hearth_shape_sphere(c, 0.15);
    hearth_error err;
    int n = hearth_scene_seed_shape(s, mat, disc, 4, 0.0, NULL, &err);
    hearth_shape_free(disc);
    CHECK(n > 1000);
    for (int i = 0; i < n; i++) { /* rigid rotation: v = w x r, C = grad v */
        const int tn = particles_tn(&s->ps); /* C_xy at 1, C_yx at 2 of a 2D store's 2x2 (3 of a 3x3) */
        double *x = pcold(&s->ps, PC_X) + 3 * i, *v = pcold(&s->ps, PC_V) + 3 * i, *C = pcold(&s->ps, PC_C) + tn * i;
        v[0] = -w * (x[1] - 0.5);
        v[1] = w * (x[0] - 0.5);
        C[1] = -w;
        C[tn == 4 ? 2 : 3] = w;
    }
    s->max_speed = w * 0.15;
    const double mu = E / (2 * (1 + nu)), lam = E * nu / ((1 + nu) * (1 - 2 * nu));
    double P[4], L0[3], L[3];
    momenta(s, P, L0, 1);
    double ke0 = 0;
    for (int i = 0; i < n; i++) {
        const double *v = pcold(&s->ps, PC_V) + 3 * i;
        ke0 += 0.5 * pcold(&s->ps, PC_MASS)[i] * (v[0] * v[0] + v[1] * v[1]);
    }
    const double E0 = ke0 + neo_hookean_energy(s, mu, lam);
    const int steps = (int)lround(2 * PI / w / 2e-4);
    double worst_L = 0, worst_E = -1;
    for (int k = 0; k < steps; k++) {
        CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
        momenta(s, P, L, 1);
        worst_L = fmax(worst_L, fabs(L[2] / L0[2] - 1));
        hearth_stats st;
        hearth_scene_stats(s, &st);
        worst_E = fmax(worst_E, (st.kinetic + neo_hookean_energy(s, mu, lam)) / E0 - 1);
    }
    hearth_stats st;
    hearth_scene_stats(s, &st);
    printf("  %d particles, %d steps to t = %.4f s: max |L/L0 - 1| = %.3g, max energy rise = %.3g%%\n", n, steps, st.t,
           worst_L, 100 * worst_E);
    CHECK(fabs(st.dt - 2e-4) < 1e-15);
    CHECK(worst_L <= 1e-10);
    CHECK(worst_E <= 1e-3);
    hearth_scene_destroy(s);
}

/* Free fall: the centroid follows g t^2 / 2. Symplectic Euler's position lags
 * the parabola by g t dt / 2, a relative error of dt / t, so 1e-6 needs
 * dt <= 1e-6 t: we step at 5e-8 s and compare at t >= 0.08 s. */
/* Free fall: with symplectic Euler (v += g dt, then x += v dt) a body falls
 * g dt^2 N(N+1)/2 in N steps, the exact g t^2/2 plus g t dt/2: the error is
 * first order, dt/t relative. Checked against that discrete closed form to
 * 1e-9 at two step sizes (so the order is exactly 1), which costs 3072 steps
 * where bounding the error itself below 1e-6 took two million. */
TEST(free_fall) {
    hearth_set_threads(1);
    const double T = 0.125, dts[] = {1.0 / 8192, 1.0 / 16384}; /* binary fractions: T is an exact number of steps */
    double err_dt[2] = {0, 0};
    for (int k = 0; k < 2; k++) {
        hearth_scene_def d = hearth_default_scene_def();
        d.dx = 1.0 / 16;
        d.dt_max = dts[k];
        hearth_scene *s = fx_scene_def(&d);
        int mat = fx_elastic(s, 1e4, 0.3, 1000);
        const double c[3] = {0.5, 0.8, 0}, h[3] = {1.0 / 32, 1.0 / 32, 0};
        int n = fx_box(s, mat, c, h, 4, NULL);
        CHECK(n == 4);
        double y0 = 0, y = 0;
        for (int i = 0; i < n; i++) y0 += pcold(&s->ps, PC_X)[3 * i + 1] / n;
        hearth_error err;
        CHECK(hearth_scene_advance(s, T, &err) == HEARTH_OK);
        for (int i = 0; i < n; i++) y += pcold(&s->ps, PC_X)[3 * i + 1] / n;
        const double N = (double)s->step, g = 9.81, dt = T / N;
        const double discrete = 0.5 * g * dt * dt * N * (N + 1);
        err_dt[k] = ((y0 - y) - 0.5 * g * T * T) / (0.5 * g * T * T);
        printf("  dt %.3g: %ld steps, fall %.12f m, discrete closed form %.12f m, relative error vs g t^2/2 %.4g\n",
               dts[k], s->step, y0 - y, discrete, err_dt[k]);
        CHECK(s->step == (long)llround(T / dts[k]));
        CHECK(fabs((y0 - y) - discrete) <= 1e-9 * discrete);
        hearth_scene_destroy(s);
    }
    const double order = log(err_dt[0] / err_dt[1]) / log(2.0);
    printf("  observed order in dt: %.6f\n", order);
    CHECK(fabs(order - 1) < 1e-6);
    hearth_set_threads(0);
}

/* Vibrating bar (Bardenhagen 2002): L 25, E 100, rho 1, nu 0, fixed at x = 0,
 * v0 = 0.1 sin(pi x / 2L). The centre-of-mass velocity oscillates with period
 * 4L/c = 10 s and amplitude 0.2/pi = 0.063662. */
TEST(vibrating_bar) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.5;
    d.lo[0] = -3;
    d.hi[0] = 30;
    d.lo[1] = 0;
    d.hi[1] = 5;
    d.gravity[1] = 0;
    d.cfl = 0.2;
    hearth_scene *s = fx_scene_def(&d);
    int mat = fx_elastic(s, 100, 0.0, 1);
    const double Lb = 25, c[3] = {12.5, 2.5, 0}, h[3] = {12.5, 0.5, 0};
    int n = fx_box(s, mat, c, h, 4, NULL);
    CHECK(n == 50 * 2 * 4);
    for (int i = 0; i < n; i++) {
        double x = pcold(&s->ps, PC_X)[3 * i];
        pcold(&s->ps, PC_V)[3 * i] = 0.1 * sin(PI * x / (2 * Lb));
        pcold(&s->ps, PC_C)[0 + particles_tn(&s->ps) * i] = 0.1 * PI / (2 * Lb) * cos(PI * x / (2 * Lb));
    }
    s->max_speed = 0.1;
    const double p[3] = {0, 0, 0}, nrm[3] = {1, 0, 0};
    hearth_shape *wall = hearth_shape_plane(p, nrm);
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = wall;
    cd.mode = HEARTH_STICKY;
    hearth_error err;
    CHECK(hearth_scene_add_collider(s, &cd, &err) == 0);
    hearth_shape_free(wall);
    /* zero crossings with hysteresis: small high-frequency ripples near zero
     * must not count, so a crossing is confirmed once |v| passes 0.01 on the
     * other side, and dated at the last sign change before that */
    double prev_v = 0.063662, prev_t = 0, peak = 0, worst_amp = 0, last_change = 0;
    double crossings[16];
    int nc = 0, npeaks = 0, sign = 1;
    while (s->t < 50.0) {
        if (hearth_scene_step(s, 1, &err) != HEARTH_OK) {
            fprintf(stderr, "%s\n", err.msg);
            test_failures++;
            break;
        }
        double vc = 0, m = 0;
        for (int i = 0; i < n; i++) {
            vc += pcold(&s->ps, PC_MASS)[i] * pcold(&s->ps, PC_V)[3 * i];
            m += pcold(&s->ps, PC_MASS)[i];
        }
        vc /= m;
        if ((prev_v > 0) != (vc > 0)) last_change = prev_t + (s->t - prev_t) * prev_v / (prev_v - vc);
        if (vc * sign < -0.01 && nc < 16) {
            worst_amp = fmax(worst_amp, fabs(fabs(peak) / 0.063662 - 1));
            npeaks++;
            crossings[nc++] = last_change;
            sign = -sign;
            peak = 0;
        }
        if (fabs(vc) > fabs(peak)) peak = vc;
        prev_v = vc;
        prev_t = s->t;
    }
    CHECK(nc >= 10);
    /* successive crossings are half a period apart */
    double period = nc >= 2 ? 2 * (crossings[nc - 1] - crossings[0]) / (nc - 1) : 0;
    printf("  %d particles, %ld steps, period %.5f s (exact 10), worst peak amplitude error %.3g%% over %d peaks\n", n,
           s->step, period, 100 * worst_amp, npeaks);
    CHECK(fabs(period / 10.0 - 1) <= 0.01);
    CHECK(worst_amp <= 0.02);
    hearth_scene_destroy(s);
}

/* Probes: a block at rest has its own density, J = 1 and no stress; outside is NaN. */
TEST(probe_fields) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 1.0 / 32;
    d.gravity[1] = 0;
    hearth_scene *s = fx_scene_def(&d);
    int m = fx_elastic(s, 1e4, 0.3, 800);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.2, 0.2, 0}, v[3] = {0.3, 0, 0};
    fx_box(s, m, c, h, 4, v);
    hearth_error err;
    double val[3];
    CHECK(hearth_probe_point(s, "density", c, val, &err) == HEARTH_OK);
    CHECK_NEAR(val[0], 800, 1e-9);
    CHECK(hearth_probe_point(s, "J", c, val, &err) == HEARTH_OK);
    CHECK_NEAR(val[0], 1, 1e-12);
    CHECK(hearth_probe_point(s, "pressure", c, val, &err) == HEARTH_OK);
    CHECK_NEAR(val[0], 0, 1e-9);
    CHECK(hearth_probe_point(s, "velocity", c, val, &err) == HEARTH_OK);
    CHECK_NEAR(val[0], 0.3, 1e-12);
    CHECK_NEAR(val[1], 0, 1e-12);
    const double out[3] = {0.1, 0.1, 0};
    CHECK(hearth_probe_point(s, "speed", out, val, &err) == HEARTH_OK);
    CHECK(isnan(val[0]));
    CHECK(hearth_probe_point(s, "temperature", c, val, &err) == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "field 'temperature' is not live");
    CHECK_STR_CONTAINS(err.msg, "temperature = 20");
    CHECK(hearth_probe_point(s, "temprature", c, val, &err) == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "unknown field 'temprature'");
    double line[11];
    const double a[3] = {0, 0.5, 0}, b[3] = {1, 0.5, 0};
    CHECK(hearth_probe_line(s, "density", a, b, 11, line, &err) == HEARTH_OK);
    CHECK(isnan(line[0]) && isnan(line[10]));
    CHECK_NEAR(line[5], 800, 1e-9);
    double slice[40 * 30];
    CHECK(hearth_probe_slice(s, "velocity", 2, 0, 40, 30, slice, &err) == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "velocity_x");
    CHECK(hearth_probe_slice(s, "velocity_x", 2, 0, 40, 30, slice, &err) == HEARTH_OK);
    CHECK(isnan(slice[0]));
    CHECK_NEAR(slice[15 * 40 + 20], 0.3, 1e-12);
    /* compressing the block gives a positive pressure and J < 1 */
    for (int i = 0; i < s->ps.n; i++) {
        const int tn = particles_tn(&s->ps); /* F_yy at 3 of a 2D store's 2x2 (4 of a 3x3) */
        double *F = pcold(&s->ps, PC_F) + tn * i;
        F[0] = F[tn == 4 ? 3 : 4] = 0.95;
    }
    CHECK(hearth_probe_point(s, "pressure", c, val, &err) == HEARTH_OK);
    CHECK(val[0] > 0);
    CHECK(hearth_probe_point(s, "von_mises", c, val, &err) == HEARTH_OK);
    CHECK(val[0] >= 0 && isfinite(val[0]));
    hearth_scene_destroy(s);
}

/* The full Cauchy stress: a small uniform stretch e along x and shear g in
 * xy give, to first order, sigma_xx = (lambda + 2 mu) e, sigma_yy = sigma_zz
 * = lambda e, sigma_xy = mu g and no xz, yz: each component in its place.
 * The scalar fields (stress_xx .. stress_yz, pressure, von_mises) agree
 * with the tensor, at a point, along a line and at the particles. */
TEST(stress_tensor_components) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 1.0 / 32;
    d.gravity[1] = 0;
    hearth_scene *s = fx_scene_def(&d);
    const double E = 1e4, nu = 0.3, e = 1e-4, g = 2e-4;
    int m = fx_elastic(s, E, nu, 800);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.2, 0.2, 0}, v0[3] = {0, 0, 0};
    fx_box(s, m, c, h, 4, v0);
    for (int i = 0; i < s->ps.n; i++) {
        double *F = pcold(&s->ps, PC_F) + particles_tn(&s->ps) * i; /* F_xx, F_xy: 0 and 1 in a 2x2 and a 3x3 */
        F[0] = 1 + e;
        F[1] = g;
    }
    const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
    hearth_error err;
    CHECK(hearth_field_components("stress") == 9);
    double sig[9];
    CHECK(hearth_probe_point(s, "stress", c, sig, &err) == HEARTH_OK);
    printf("  sigma = [%.6g %.6g %.6g; %.6g %.6g %.6g; %.6g %.6g %.6g] Pa\n", sig[0], sig[1], sig[2], sig[3], sig[4], sig[5],
           sig[6], sig[7], sig[8]);
    printf("  first order: xx %.6g, yy = zz %.6g, xy %.6g Pa\n", (lam + 2 * mu) * e, lam * e, mu * g);
    const double tol = 1e-3 * (lam + 2 * mu) * e; /* second-order terms: e^2, g^2 relative */
    CHECK_NEAR(sig[0], (lam + 2 * mu) * e, tol);
    CHECK_NEAR(sig[4], lam * e, tol);
    CHECK_NEAR(sig[8], lam * e, tol);
    CHECK_NEAR(sig[1], mu * g, tol);
    CHECK_NEAR(sig[3], mu * g, tol);
    CHECK_NEAR(sig[2], 0, 1e-12);
    CHECK_NEAR(sig[5], 0, 1e-12);
    CHECK_NEAR(sig[6], 0, 1e-12);
    CHECK_NEAR(sig[7], 0, 1e-12);
    static const char *const comp[] = {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_xz", "stress_yz"};
    static const int at[] = {0, 4, 8, 1, 2, 5};
    for (int k = 0; k < 6; k++) {
        double v;
        CHECK(hearth_probe_point(s, comp[k], c, &v, &err) == HEARTH_OK);
        CHECK_NEAR(v, sig[at[k]], 1e-12 * (1 + fabs(sig[at[k]])));
    }
    double p, q;
    CHECK(hearth_probe_point(s, "pressure", c, &p, &err) == HEARTH_OK);
    CHECK_NEAR(p, -(sig[0] + sig[4] + sig[8]) / 3, 1e-12);
    CHECK(hearth_probe_point(s, "von_mises", c, &q, &err) == HEARTH_OK);
    double ss = 0;
    for (int k = 0; k < 9; k++) ss += pow(sig[k] + (k % 4 == 0 ? p : 0), 2);
    CHECK_NEAR(q, sqrt(1.5 * ss), 1e-9);
    /* a line gives 9 numbers a sample; a slice wants one component */
    double line[5 * 9];
    const double a[3] = {0.4, 0.5, 0}, b[3] = {0.6, 0.5, 0};
    CHECK(hearth_probe_line(s, "stress", a, b, 5, line, &err) == HEARTH_OK);
    CHECK_NEAR(line[2 * 9 + 0], sig[0], 1e-12);
    CHECK_NEAR(line[2 * 9 + 1], sig[1], 1e-12);
    double slice[4];
    CHECK(hearth_probe_slice(s, "stress", 2, 0, 2, 2, slice, &err) == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "stress_xx");
    CHECK(hearth_probe_slice(s, "stress_yy", 2, 0, 2, 2, slice, &err) == HEARTH_OK);
    /* the tensor is listed once among the live fields; its components are not */
    const char *live = hearth_scene_fields(s);
    CHECK_STR_CONTAINS(live, "stress");
    CHECK(strstr(live, "stress_") == NULL);
    double *pf = malloc(sizeof(double) * 9 * (size_t)s->ps.n);
    CHECK(hearth_scene_particle_field(s, "stress", pf, &err) == HEARTH_OK);
    CHECK_NEAR(pf[9 * (s->ps.n / 2) + 4], sig[4], 1e-12);
    free(pf);
    hearth_scene_destroy(s);
}

/* Optional columns exist only when enabled, and travel with their particle
 * through sorting and checkpoints. */
TEST(particles_optional_columns) {
    hearth_scene *s = fx_scene(2, 1.0 / 32, 0, 1);
    hearth_error err;
    /* no conduction, so the temperatures used as tags below stay put */
    const char *nm[] = {"E", "conductivity"};
    const double nv[] = {1e4, 0.0};
    int m = hearth_scene_add_material(s, "elastic", nm, nv, 2, &err);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.2, 0.1, 0}, v[3] = {0, 0, 0};
    fx_box(s, m, c, h, 4, v);
    CHECK(!(s->ps.enabled & (1u << PC_TEMPERATURE)) && s->ps.col[PC_TEMPERATURE] == NULL);
    CHECK(strstr(hearth_scene_fields(s), "temperature") == NULL);
    const size_t before = hearth_bytes_allocated();
    CHECK(scene_enable_temperature(s, &err) == HEARTH_OK);
    /* temperature, its running maximum and the flags: 8 + 8 + 4 bytes a particle */
    CHECK(hearth_bytes_allocated() - before == (2 * sizeof(double) + sizeof(int)) * (size_t)s->ps.cap);
    CHECK(strstr(hearth_scene_fields(s), "temperature") != NULL);
    /* tag each particle's temperature with its id, then scramble the order */
    for (int i = 0; i < s->ps.n; i++) pcold(&s->ps, PC_TEMPERATURE)[i] = pcoli(&s->ps, PC_ID)[i];
    for (int i = 0; i < s->ps.n; i++) pcold(&s->ps, PC_V)[3 * i] = (i % 2 ? 1.5 : -1.5);
    CHECK(hearth_scene_step(s, 30, &err) == HEARTH_OK);
    int moved = 0;
    for (int i = 0; i < s->ps.n; i++) {
        CHECK(pcold(&s->ps, PC_TEMPERATURE)[i] == pcoli(&s->ps, PC_ID)[i]);
        moved += pcoli(&s->ps, PC_ID)[i] != i;
    }
    CHECK(moved > 0); /* the sort did reorder particles */
    char path[] = "/tmp/hearth_cols_XXXXXX";
    int fd = mkstemp(path);
    close(fd);
    CHECK(hearth_scene_save(s, path, &err) == HEARTH_OK);
    hearth_scene *r = hearth_scene_load(path, &err);
    CHECK(r && (r->ps.enabled & (1u << PC_TEMPERATURE)));
    for (int i = 0; r && i < r->ps.n; i++) CHECK(pcold(&r->ps, PC_TEMPERATURE)[i] == pcoli(&r->ps, PC_ID)[i]);
    remove(path);
    hearth_scene_destroy(r);
    hearth_scene_destroy(s);
}

/* A body force field adds to gravity: one that cancels it leaves a block at rest. */
TEST(body_force) {
    hearth_scene *s = fx_scene(2, 1.0 / 32, 0, 1);
    int m = fx_elastic(s, 1e4, 0.3, 1000);
    const double c[3] = {0.5, 0.6, 0}, h[3] = {0.1, 0.1, 0};
    fx_box(s, m, c, h, 4, NULL);
    double up = 9.81;
    hearth_scene_set_body_force(s, fx_antigravity, &up);
    hearth_error err;
    CHECK(hearth_scene_advance(s, 0.2, &err) == HEARTH_OK);
    hearth_stats st;
    hearth_scene_stats(s, &st);
    CHECK(st.max_speed < 1e-12);
    up = 2 * 9.81; /* now a net 9.81 upwards */
    CHECK(hearth_scene_advance(s, 0.3, &err) == HEARTH_OK);
    hearth_scene_stats(s, &st);
    printf("  net upward 9.81 m/s^2 for 0.1 s: speed %.5f m/s (expect 0.981)\n", st.max_speed);
    CHECK_NEAR(st.max_speed, 0.981, 1e-3);
    hearth_scene_destroy(s);
}

/* hearth_body_def.smooth_surface (#18, helper loafbase): the seeding's outer layer (lattice points within 1.25
 * spacings h of the surface) stays on the lattice while the interior keeps the same jitter draw. A box whose base
 * lies on the lattice's half-spacing (y = 0.1, a node row) has its lowest row exactly h/2 above it when smooth and
 * spread over the jitter (+-0.25 h at jitter 0.5) when not; a base through a lattice row (y = 0.1 + h/2) has its first
 * row inside, h above it, flat too; and in 3D. The jittered base's spread is what stood the physical loaf's base off its
 * tray. */
static hearth_scene *seed_box(int dim, double dx, double ylo, int smooth, int *n) {
    hearth_scene *s = fx_scene(dim, dx, 0, 1);
    const int mat = fx_elastic(s, 1e4, 0.3, 1000);
    const double c[3] = {0.4, ylo + 0.1, dim == 3 ? 0.5 : 0}, half[3] = {0.2, 0.1, 0.1};
    hearth_body_def b = hearth_default_body_def();
    b.shape = hearth_shape_box(c, half);
    b.material = mat;
    b.smooth_surface = smooth;
    hearth_error err;
    *n = hearth_scene_add_body(s, &b, &err) >= 0 ? hearth_scene_body_particles(s, 0) : -1;
    hearth_shape_free((hearth_shape *)b.shape);
    return s;
}

/* the spread (max - min) of the lowest row's heights above ylo: particles within h of it */
static double base_spread(const hearth_scene *s, int n, double ylo, double h, double *lowest) {
    double lo = INFINITY, hi = -INFINITY;
    const double *x = pcold(&s->ps, PC_X);
    for (int i = 0; i < n; i++) {
        const double y = x[3 * i + 1] - ylo;
        if (y < h) lo = fmin(lo, y), hi = fmax(hi, y);
    }
    *lowest = lo;
    return hi - lo;
}

TEST(seed_smooth_surface_flat_face) {
    const double h = 0.01, ylo = 0.1; /* dx 0.02, ppc 4: h = dx / 2 */
    int nj, ns;
    hearth_scene *sj = seed_box(2, 0.02, ylo, 0, &nj), *ss = seed_box(2, 0.02, ylo, 1, &ns);
    CHECK(nj > 0 && nj == ns); /* a face on the half-spacing: no jittered point crosses it either way */
    double lj, ls;
    const double spread_j = base_spread(sj, nj, ylo, h, &lj), spread_s = base_spread(ss, ns, ylo, h, &ls);
    printf("  base on the half-spacing: lowest row's spread jittered %.4f h, smooth %.2e h (lowest at %.6f h)\n",
           spread_j / h, spread_s / h, ls / h);
    CHECK(spread_j > 0.3 * h);
    CHECK(spread_s < 1e-9 * h);
    CHECK(fabs(ls - 0.5 * h) < 1e-9 * h);
    /* the interior (farther than 1.5 h from every face) is the same draw, and still jittered */
    const double *xj = pcold(&sj->ps, PC_X), *xs = pcold(&ss->ps, PC_X);
    int inner = 0, same = 0, off_lattice = 0;
    for (int i = 0; i < nj && nj == ns; i++) {
        const double x = xj[3 * i], y = xj[3 * i + 1];
        const double d = fmin(fmin(x - 0.2, 0.6 - x), fmin(y - ylo, ylo + 0.2 - y));
        if (d < 1.5 * h + 0.25 * h) continue;
        inner++;
        same += xj[3 * i] == xs[3 * i] && xj[3 * i + 1] == xs[3 * i + 1];
        const double fy = (y - ylo) / h - 0.5;
        off_lattice += fabs(fy - floor(fy + 0.5)) > 0.01;
    }
    printf("  interior: %d particles, %d the same in both, %d off the lattice\n", inner, same, off_lattice);
    CHECK(inner > 100 && same == inner && off_lattice > inner / 2);
    /* every particle of the smooth seeding within 1.25 h of a face sits on the lattice */
    int layer = 0, on = 0;
    for (int i = 0; i < ns; i++) {
        const double x = xs[3 * i], y = xs[3 * i + 1];
        const double d = fmin(fmin(x - 0.2, 0.6 - x), fmin(y - ylo, ylo + 0.2 - y));
        if (d >= 1.25 * h) continue;
        layer++;
        const double fx = (x - 0.2) / h - 0.5, fy = (y - ylo) / h - 0.5;
        on += fabs(fx - floor(fx + 0.5)) < 1e-6 && fabs(fy - floor(fy + 0.5)) < 1e-6;
    }
    printf("  outer layer: %d particles, %d on the lattice\n", layer, on);
    CHECK(layer > 50 && on == layer);
    hearth_scene_destroy(sj);
    hearth_scene_destroy(ss);
    /* a base through a lattice row: smooth, the first row inside stands h above it, flat */
    const double yrow = ylo + 0.5 * h;
    sj = seed_box(2, 0.02, yrow, 0, &nj);
    ss = seed_box(2, 0.02, yrow, 1, &ns);
    CHECK(nj > 0 && ns > 0);
    const double sp_j = base_spread(sj, nj, yrow, 1.5 * h, &lj), sp_s = base_spread(ss, ns, yrow, 1.5 * h, &ls);
    printf("  base through a row: lowest heights' spread jittered %.4f h (lowest %.4f h), smooth %.2e h (lowest %.6f h)\n",
           sp_j / h, lj / h, sp_s / h, ls / h);
    CHECK(sp_j > 0.3 * h);
    CHECK(sp_s < 1e-9 * h && fabs(ls - h) < 1e-9 * h);
    hearth_scene_destroy(sj);
    hearth_scene_destroy(ss);
    /* 3D (ppc 4 rounds to 2^3: h = dx / 2 = 0.02), the base on a node row: flat when smooth */
    const double y3 = 0.12;
    sj = seed_box(3, 0.04, y3, 0, &nj);
    ss = seed_box(3, 0.04, y3, 1, &ns);
    CHECK(nj > 1000 && nj == ns);
    const double s3j = base_spread(sj, nj, y3, 0.02, &lj), s3s = base_spread(ss, ns, y3, 0.02, &ls);
    printf("  3D, %d particles: lowest row's spread jittered %.4f h, smooth %.2e h (lowest %.6f h)\n", ns, s3j / 0.02,
           s3s / 0.02, ls / 0.02);
    CHECK(s3j > 0.3 * 0.02);
    CHECK(s3s < 1e-9 * 0.02 && fabs(ls - 0.01) < 1e-9 * 0.02);
    hearth_scene_destroy(sj);
    hearth_scene_destroy(ss);
}

TEST_MAIN(T(bspline_weights), T(transfer_conservation_2d), T(transfer_conservation_3d), T(transfer_pic_dissipates), T(rotating_disc), T(free_fall), T(vibrating_bar), T(probe_fields), T(stress_tensor_components), T(particles_optional_columns), T(body_force), T(seed_smooth_surface_flat_face))
