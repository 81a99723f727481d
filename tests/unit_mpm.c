/* unit_mpm.c: the MPM core against closed forms and conservation laws. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "alloc.h"
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

static double neo_hookean_energy(const hearth_scene *s, double mu, double lam) {
    double E = 0;
    for (int i = 0; i < s->ps.n; i++) {
        double F[9];
        particles_F3(&s->ps, i, F);
        double tr = 0;
        for (int a = 0; a < 9; a++) tr += F[a] * F[a];
        const double J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
        const double lj = log(J);
        E += pcold(&s->ps, PC_VOL0)[i] * (0.5 * mu * (tr - 3) - mu * lj + 0.5 * lam * lj * lj);
    }
    return E;
}

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

/* A mixed 3D scene: a block and a ball of two materials hitting a sphere and a plane. */
static hearth_scene *busy_scene(void) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 3;
    d.dx = 1.0 / 32;
    d.wall = HEARTH_SEPARATE;
    d.wall_friction = 0.3;
    hearth_scene *s = fx_scene_def(&d);
    int a = fx_elastic(s, 5e4, 0.3, 1000);
    const char *nn[] = {"bulk", "viscosity"};
    const double nv[] = {1e5, 0.5};
    hearth_error err;
    int b = hearth_scene_add_material(s, "newtonian", nn, nv, 2, &err);
    const double c1[3] = {0.4, 0.5, 0.5}, h1[3] = {0.12, 0.1, 0.1}, v1[3] = {1, -1, 0};
    fx_box(s, a, c1, h1, 8, v1);
    const double c2[3] = {0.65, 0.6, 0.45};
    hearth_shape *ball = hearth_shape_sphere(c2, 0.1);
    hearth_scene_seed_shape(s, b, ball, 8, 0.7, NULL, &err);
    hearth_shape_free(ball);
    const double sc[3] = {0.5, 0.2, 0.5};
    hearth_shape *sph = hearth_shape_sphere(sc, 0.12);
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = sph;
    cd.mode = HEARTH_SLIP;
    cd.friction = 0.2;
    cd.velocity[0] = 0.1;
    cd.omega[1] = 2.0;
    memcpy(cd.pivot, sc, sizeof sc);
    hearth_scene_add_collider(s, &cd, &err);
    hearth_shape_free(sph);
    return s;
}

/* 1 vs 2 threads: bit-identical particle states after 100 steps. */
TEST(determinism_threads) {
    uint64_t h[2];
    for (int t = 1; t <= 2; t++) {
        hearth_set_threads(t);
        hearth_scene *s = busy_scene();
        hearth_error err;
        CHECK(s->ps.n >= SCENE_PARALLEL_MIN); /* so the step really runs on two threads */
        CHECK(hearth_scene_step(s, 100, &err) == HEARTH_OK);
        h[t - 1] = hearth_scene_hash(s);
        hearth_stats st;
        hearth_scene_stats(s, &st);
        printf("  %d thread(s): %d particles, t = %.5g s, hash %016llx\n", t, st.particles, st.t, (unsigned long long)h[t - 1]);
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
    CHECK(h[0] == h[1]);
}

/* A checkpoint restore continues bit-identically. */
TEST(checkpoint_restore) {
    hearth_error err;
    hearth_scene *s = busy_scene();
    CHECK(hearth_scene_step(s, 40, &err) == HEARTH_OK);
    char path[] = "/tmp/hearth_ckpt_XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    close(fd);
    CHECK(hearth_scene_save(s, path, &err) == HEARTH_OK);
    CHECK(hearth_scene_step(s, 60, &err) == HEARTH_OK);
    uint64_t want = hearth_scene_hash(s);
    hearth_scene *r = hearth_scene_load(path, &err);
    CHECK(r != NULL);
    if (r) {
        CHECK(hearth_scene_step(r, 60, &err) == HEARTH_OK);
        hearth_stats a, b;
        hearth_scene_stats(s, &a);
        hearth_scene_stats(r, &b);
        CHECK(a.t == b.t && a.step == b.step);
        CHECK(hearth_scene_hash(r) == want);
        hearth_scene_destroy(r);
    }
    /* a damaged file is refused with a reason */
    FILE *f = fopen(path, "r+b");
    fseek(f, -100, SEEK_END);
    fputc(0x5a, f);
    fclose(f);
    r = hearth_scene_load(path, &err);
    CHECK(r == NULL);
    CHECK_STR_CONTAINS(err.msg, "checksum");
    remove(path);
    r = hearth_scene_load("/nonexistent/x.ckpt", &err);
    CHECK(r == NULL && err.code == HEARTH_ERR_IO);
    hearth_scene_destroy(s);
}

/* A NaN from a plugin is caught with the particle and material named. */
TEST(guard_nan_plugin) {
    hearth_scene *s = fx_scene(2, 1.0 / 32, 0, 1);
    int a = fx_elastic(s, 1e4, 0.3, 1000);
    hearth_error err;
    const char *nm[] = {"after"};
    const double nv[] = {5};
    int b = hearth_scene_add_material(s, fx_test_plugin("nan_after"), nm, nv, 1, &err);
    CHECK(b == 1);
    const double c[3] = {0.5, 0.3, 0}, h[3] = {0.1, 0.1, 0};
    fx_box(s, a, c, h, 4, NULL);
    const double x[3] = {0.5, 0.41, 0};
    CHECK(hearth_scene_add_particles(s, b, 1, x, NULL, 1e-4, &err) == 1);
    const int id = s->next_id - 1;
    hearth_status st = hearth_scene_step(s, 20, &err);
    CHECK(st == HEARTH_ERR_GUARD);
    char want[64];
    snprintf(want, sizeof want, "(id %d)", id);
    CHECK_STR_CONTAINS(err.msg, want);
    CHECK_STR_CONTAINS(err.msg, "material 'nan_after'");
    CHECK_STR_CONTAINS(err.msg, "stress is NaN");
    CHECK_STR_CONTAINS(err.msg, "step 6");
    hearth_stats stats;
    hearth_scene_stats(s, &stats);
    CHECK(stats.guard == HEARTH_GUARD_STOPPED);
    printf("  %s\n", err.msg);
    hearth_scene_destroy(s);
}

/* A plugin's error code is reported with the plugin's own text. */
TEST(guard_plugin_error) {
    hearth_scene *s = fx_scene(2, 1.0 / 32, 0, 1);
    hearth_error err;
    int m = hearth_scene_add_material(s, fx_test_plugin("err_code"), NULL, NULL, 0, &err);
    CHECK(m == 0);
    const double c[3] = {0.5, 0.3, 0}, h[3] = {0.05, 0.05, 0};
    fx_box(s, m, c, h, 4, NULL);
    CHECK(hearth_scene_step(s, 1, &err) == HEARTH_ERR_GUARD);
    CHECK_STR_CONTAINS(err.msg, "code 7");
    CHECK_STR_CONTAINS(err.msg, "return mapping did not converge");
    printf("  %s\n", err.msg);
    hearth_scene_destroy(s);
}

/* cfl = 4 breaks the wave CFL condition: the guard stops with that diagnosis,
 * and with the rollback policy the run completes by halving dt. */
TEST(guard_cfl_and_rollback) {
    for (int policy = 0; policy <= 1; policy++) {
        hearth_scene_def d = hearth_default_scene_def();
        d.dx = 1.0 / 32;
        d.cfl = 4.0;
        d.guard = policy ? HEARTH_GUARD_ROLLBACK : HEARTH_GUARD_STOP;
        hearth_scene *s = fx_scene_def(&d);
        int m = fx_elastic(s, 1e5, 0.3, 1000);
        const double c[3] = {0.5, 0.3, 0}, h[3] = {0.1, 0.1, 0};
        fx_box(s, m, c, h, 4, NULL);
        hearth_error err;
        hearth_status st = hearth_scene_step(s, 30, &err);
        hearth_stats stats;
        hearth_scene_stats(s, &stats);
        if (!policy) {
            CHECK(st == HEARTH_ERR_GUARD);
            CHECK_STR_CONTAINS(err.msg, "CFL violated");
            printf("  stop: %s\n", err.msg);
        } else {
            CHECK(st == HEARTH_OK);
            CHECK(stats.rollbacks > 0);
            CHECK(stats.guard == HEARTH_GUARD_ROLLED_BACK);
            CHECK(stats.cfl <= 1.0 + 1e-9);
            printf("  rollback: 30 steps done with %d rollbacks, last cfl %.3g\n", stats.rollbacks, stats.cfl);
        }
        hearth_scene_destroy(s);
    }
}

/* A block resting on a plane collider stays on it; a pressing collider squashes it. */
TEST(colliders_contact) {
    hearth_scene *s = fx_scene(2, 1.0 / 64, 0, 1);
    int m = fx_elastic(s, 2e4, 0.3, 1000);
    const double c[3] = {0.5, 0.35, 0}, h[3] = {0.1, 0.1, 0};
    fx_box(s, m, c, h, 4, NULL);
    const double p0[3] = {0, 0.2, 0}, up[3] = {0.0, 1, 0};
    hearth_shape *floor_ = hearth_shape_plane(p0, up);
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = floor_;
    cd.mode = HEARTH_SEPARATE;
    hearth_error err;
    CHECK(hearth_scene_add_collider(s, &cd, &err) == 0);
    hearth_shape_free(floor_);
    CHECK(hearth_scene_advance(s, 0.4, &err) == HEARTH_OK);
    double ymin = 1, ymax = 0;
    for (int i = 0; i < s->ps.n; i++) {
        ymin = fmin(ymin, pcold(&s->ps, PC_X)[3 * i + 1]);
        ymax = fmax(ymax, pcold(&s->ps, PC_X)[3 * i + 1]);
    }
    printf("  resting block: lowest particle at y = %.4f (floor 0.2), top %.4f\n", ymin, ymax);
    CHECK(ymin > 0.2 - 0.25 / 64);
    /* a press whose face starts at 0.42 and moves down at 0.2 m/s for 0.5 s ends at 0.32 */
    const double pc[3] = {0.5, 0.45, 0}, ph[3] = {0.3, 0.03, 0};
    hearth_shape *press = hearth_shape_box(pc, ph);
    cd.shape = press;
    cd.mode = HEARTH_STICKY;
    cd.velocity[1] = -0.2;
    CHECK(hearth_scene_add_collider(s, &cd, &err) == 1);
    hearth_shape_free(press);
    CHECK(hearth_scene_advance(s, 0.9, &err) == HEARTH_OK);
    double ytop = 0;
    for (int i = 0; i < s->ps.n; i++) ytop = fmax(ytop, pcold(&s->ps, PC_X)[3 * i + 1]);
    printf("  pressed block: top at y = %.4f (press face at %.4f)\n", ytop, 0.32);
    CHECK(ytop < ymax - 0.03);
    CHECK(ytop < 0.32 + 1.5 / 64);
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

/* Bad input gets a message naming the parameter and the valid range. */
TEST(scene_bad_input) {
    hearth_error err;
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 4;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "dim = 4");
    d = hearth_default_scene_def();
    d.cfl = 0;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "(0, 4]");
    hearth_scene *s = fx_scene(2, 0.05, 0, 1);
    const char *nm[] = {"E", "nu", "densty"};
    const double bad[] = {1e4, 0.3, 1000};
    CHECK(hearth_scene_add_material(s, "elastic", nm, bad, 3, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "did you mean 'density'");
    const char *nm2[] = {"nu"};
    const double bad2[] = {0.6};
    CHECK(hearth_scene_add_material(s, "elastic", nm2, bad2, 1, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "[0, 0.499]");
    int m = fx_elastic(s, 1e4, 0.3, 1000);
    const double x[3] = {1.5, 0.5, 0};
    CHECK(hearth_scene_add_particles(s, m, 1, x, NULL, 1e-4, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "x = 1.5");
    hearth_scene_destroy(s);
}

/* Every allocation on the way to a stepping scene may fail; each failure is
 * reported, nothing crashes and nothing leaks. */
TEST(alloc_failure_paths) {
    const size_t base = hearth_bytes_allocated();
    int failures = 0;
    for (long k = 0; k < 200; k++) {
        mem_fail_after(k);
        hearth_error err = {0};
        hearth_scene *s = hearth_scene_create(NULL, &err);
        int ok = s != NULL;
        int m = ok ? hearth_scene_add_material(s, "elastic", NULL, NULL, 0, &err) : -1;
        ok = ok && m >= 0;
        const double c[3] = {0.5, 0.5, 0}, h[3] = {0.1, 0.1, 0};
        hearth_shape *b = hearth_shape_box(c, h);
        ok = ok && b && hearth_scene_seed_shape(s, m, b, 4, 0.5, NULL, &err) > 0;
        hearth_shape_free(b);
        ok = ok && hearth_scene_step(s, 2, &err) == HEARTH_OK;
        mem_fail_after(-1);
        if (!ok) {
            failures++;
            CHECK(err.code == HEARTH_ERR_NOMEM || b == NULL);
        }
        hearth_scene_destroy(s);
        if (hearth_bytes_allocated() > base + 4096) /* the plugin cache may keep its first entry */
            printf("  injected failure %ld left %zu bytes counted\n", k, hearth_bytes_allocated() - base);
        CHECK(hearth_bytes_allocated() <= base + 4096);
        if (ok) break;
    }
    printf("  %d injected failures reported cleanly before a run succeeded\n", failures);
    CHECK(failures > 5);
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

static void antigravity(void *ud, double t, const double x[3], double acc[3]) {
    (void)t;
    (void)x;
    acc[1] = *(const double *)ud;
}

/* The one-region step (mpm.c's step_team) with every part of the grid
 * update it carries: damping, a thread-safe body force, and a sticky
 * collider's ghost and mark loops between the update and G2P. 1 vs 2
 * threads: bit-identical particle states. */
TEST(determinism_threads_sticky_damped) {
    uint64_t h[2];
    for (int t = 1; t <= 2; t++) {
        hearth_set_threads(t);
        hearth_scene_def d = hearth_default_scene_def();
        d.dim = 2;
        d.dx = 1.0 / 128;
        d.damping = 3.0;
        hearth_scene *s = fx_scene_def(&d);
        const int m = fx_elastic(s, 5e4, 0.3, 1000);
        const double c[3] = {0.5, 0.45, 0}, hh[3] = {0.15, 0.1, 0}, v[3] = {0.3, -1.5, 0};
        CHECK(fx_box(s, m, c, hh, 4, v) >= SCENE_PARALLEL_MIN); /* so the step really runs on two threads */
        const double fc[3] = {0.5, 0.25, 0}, fh[3] = {0.4, 0.1, 0}; /* its top touches the block from the start */
        CHECK(fx_box_collider(s, fc, fh, HEARTH_STICKY, 0.2) == 0);
        double up = 3.0; /* a third of gravity off: a body force that runs on every thread */
        hearth_scene_set_body_force(s, antigravity, &up);
        hearth_error err;
        CHECK(hearth_scene_step(s, 80, &err) == HEARTH_OK);
        CHECK(s->mpm->sticky_faces == 1 && !s->body_force_serial);
        h[t - 1] = hearth_scene_hash(s);
        hearth_stats st;
        hearth_scene_stats(s, &st);
        printf("  %d thread(s): %d particles, t = %.5g s, fastest %.5g m/s, hash %016llx\n", t, st.particles, st.t,
               st.max_speed, (unsigned long long)h[t - 1]);
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
    CHECK(h[0] == h[1]);
}

/* At more than one thread, step_team's P2G keeps each particle block's tile
 * and the grid update gathers the nodes' sums from them in colour order (one
 * barrier where the colour phases took 2^dim); HEARTH_MPM_COLOUR_PHASES=1
 * (colour_phases) keeps the colour phases. Both at two threads, in 2D and 3D,
 * with a sticky face (its mirror terms go into the tile's halo too) and
 * damping: the same bits, and the gather path really taken in 2D; 3D keeps
 * the colour phases either way, and holds no store (mpm.c, p2g_store_reserve). */
TEST(p2g_gather_matches_colour_phases) {
    hearth_set_threads(2);
    for (int dim = 2; dim <= 3; dim++) {
        uint64_t h[2];
        for (int phases = 0; phases < 2; phases++) {
            hearth_scene_def d = hearth_default_scene_def();
            d.dim = dim;
            d.dx = dim == 2 ? 1.0 / 128 : 1.0 / 40;
            d.damping = 3.0;
            hearth_scene *s = fx_scene_def(&d);
            s->mpm->colour_phases = phases;
            const int m = fx_elastic(s, 5e4, 0.3, 1000);
            const double z = dim == 3, c[3] = {0.5, 0.45, 0.5 * z}, hh[3] = {0.15, 0.1, 0.1 * z}, v[3] = {0.3, -1.5, 0.2 * z};
            CHECK(fx_box(s, m, c, hh, 4, v) >= SCENE_PARALLEL_MIN); /* so the step really runs on two threads */
            const double fc[3] = {0.5, 0.25, 0.5 * z}, fh[3] = {0.4, 0.1, 0.4 * z}; /* its top touches the block from the start */
            CHECK(fx_box_collider(s, fc, fh, HEARTH_STICKY, 0.2) == 0);
            hearth_error err;
            CHECK(hearth_scene_step(s, dim == 2 ? 60 : 20, &err) == HEARTH_OK);
            CHECK(s->mpm->sticky_faces == 1);
            CHECK((s->mpm->tiles_cap > 0) == (!phases && dim == 2)); /* the gather ran (its store exists) only in 2D without the switch */
            h[phases] = hearth_scene_hash(s);
            printf("  %dD, %s: %d particles, %d particle blocks, store %zu doubles, hash %016llx\n", dim,
                   phases ? "colour phases (the switch)" : "the default path", s->ps.n, s->mpm->npb, s->mpm->tiles_cap, (unsigned long long)h[phases]);
            hearth_scene_destroy(s);
        }
        CHECK(h[0] == h[1]);
    }
    hearth_set_threads(0);
}

/* 3D at more than one thread (mpm.c's claims): each phase hands out blocks
 * from both ends of its range, and P2G orders each block's flush after its
 * lower-coloured neighbours' instead of a barrier per colour. Three scenes
 * that take every path of it: busy_scene (the one-region step, a slip
 * collider, two materials), a block on a sticky plate with damping (the
 * mirror terms in the tile, the damped update, the sticky ghost loops) and a
 * ball in an oven (heat: P2G, the grid update and G2P in regions of their
 * own). One thread, two and three (an odd thread takes from the front too),
 * and two with HEARTH_MPM_COLOUR_PHASES's barriers: one hash per scene, and
 * the claims really taken at two and three threads. */
static hearth_scene *claims_scene(int kind) {
    if (kind == 0) return busy_scene();
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 3;
    d.dx = 1.0 / 40;
    hearth_error err;
    if (kind == 1) {
        d.damping = 3.0;
        hearth_scene *s = fx_scene_def(&d);
        const int m = fx_elastic(s, 5e4, 0.3, 1000);
        const double c[3] = {0.5, 0.45, 0.5}, hh[3] = {0.15, 0.1, 0.1}, v[3] = {0.3, -1.5, 0.2};
        fx_box(s, m, c, hh, 8, v);
        const double fc[3] = {0.5, 0.25, 0.5}, fh[3] = {0.4, 0.1, 0.4}; /* its top touches the block from the start */
        fx_box_collider(s, fc, fh, HEARTH_STICKY, 0.2);
        return s;
    }
    d.oven_temperature = 180;
    d.oven_beta = 30;
    /* the heat channels in every grid update: at the automatic field clock (field_clock.c) these 30 steps would
     * take no field update (the limit is seconds) */
    d.field_steps = 1;
    hearth_scene *s = fx_scene_def(&d);
    const char *nm[] = {"E", "conductivity", "expansion"};
    const double nv[] = {2e4, 0.4, 50};
    const int m = hearth_scene_add_material(s, "elastic", nm, nv, 3, &err);
    const double c[3] = {0.5, 0.3, 0.5};
    hearth_shape *ball = hearth_shape_sphere(c, 0.15);
    hearth_body_def bd = hearth_default_body_def();
    bd.shape = ball, bd.material = m, bd.temperature = 20;
    hearth_scene_add_body(s, &bd, &err);
    hearth_shape_free(ball);
    return s;
}

TEST(determinism_threads_3d_claims) {
    static const char *kinds[] = {"busy scene", "sticky plate, damped", "oven (heat)"};
    static const int threads[] = {1, 2, 3, 2}, phases[] = {0, 0, 0, 1};
    for (int kind = 0; kind < 3; kind++) {
        uint64_t h[4];
        for (int r = 0; r < 4; r++) {
            hearth_set_threads(threads[r]);
            hearth_scene *s = claims_scene(kind);
            s->mpm->colour_phases = phases[r];
            hearth_error err;
            CHECK(s->ps.n >= SCENE_PARALLEL_MIN); /* so the step really runs on the threads */
            CHECK(hearth_scene_step(s, 30, &err) == HEARTH_OK);
            CHECK((s->mpm->claims_regions > 0) == (threads[r] > 1 && !phases[r]));
            if (kind == 2) CHECK(s->ps.enabled & (1u << PC_TEMPERATURE));
            for (int b = 0; b < s->mpm->nblocks; b++) CHECK(s->mpm->pbof[b] == -1); /* back to none between steps */
            h[r] = hearth_scene_hash(s);
            printf("  %s, %d thread(s)%s: %d particles, %d particle blocks, %ld regions with claims, hash %016llx\n", kinds[kind],
                   threads[r], phases[r] ? ", colour phases" : "", s->ps.n, s->mpm->npb, s->mpm->claims_regions,
                   (unsigned long long)h[r]);
            hearth_scene_destroy(s);
        }
        CHECK(h[1] == h[0] && h[2] == h[0] && h[3] == h[0]);
    }
    hearth_set_threads(0);
}

/* A body force field adds to gravity: one that cancels it leaves a block at rest. */
TEST(body_force) {
    hearth_scene *s = fx_scene(2, 1.0 / 32, 0, 1);
    int m = fx_elastic(s, 1e4, 0.3, 1000);
    const double c[3] = {0.5, 0.6, 0}, h[3] = {0.1, 0.1, 0};
    fx_box(s, m, c, h, 4, NULL);
    double up = 9.81;
    hearth_scene_set_body_force(s, antigravity, &up);
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

/* A collider that starts to move gives the material energy at once: a block
 * resting on a sticky plate that starts to rise at 0.5 m/s multiplies its
 * kinetic energy thousands of times in one step. That is driven, not a
 * runaway: the guard judges growth against the energy of the material moving
 * as fast as the fastest collider holding it (guard.c). Before, the guard
 * stopped this run on the first moving step ("kinetic energy ran away"). */
TEST(guard_collider_drive) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 1.0 / 64;
    hearth_scene *s = fx_scene_def(&d);
    int m = fx_elastic(s, 2e4, 0.3, 1000);
    const double c[3] = {0.5, 0.3, 0}, h[3] = {0.1, 0.05, 0};
    fx_box(s, m, c, h, 4, NULL);
    const double pc[3] = {0.5, 0.2, 0}, ph[3] = {0.3, 0.05, 0};
    const int id = fx_box_collider(s, pc, ph, HEARTH_STICKY, 0);
    CHECK(id == 0);
    hearth_error err;
    CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK); /* at rest but for one step of gravity */
    const double up[3] = {0, 0.5, 0}, no[3] = {0, 0, 0};
    CHECK(hearth_scene_collider_set_velocity(s, id, up, no, &err) == HEARTH_OK);
    const double ke0 = s->kinetic;
    hearth_status st = hearth_scene_advance(s, 0.1, &err);
    hearth_stats stats;
    hearth_scene_stats(s, &stats);
    printf("  kinetic energy at rest %.3g J, after the plate moved %.3g J; guard: %s\n", ke0, stats.kinetic,
           st == HEARTH_OK ? "ok" : stats.diagnosis);
    CHECK(st == HEARTH_OK);
    CHECK(stats.kinetic > 100 * ke0);
    /* a real runaway is still caught: guard_cfl_and_rollback and guard_nan_plugin */
    hearth_scene_destroy(s);
}

/* A grip (HEARTH_GRIP) holds the end of a body that overlaps it: an elastic
 * strip whose ends sit in two grips that move apart at 2 cm/s under gravity
 * stays up and stretches. The particles inside a grip move rigidly with it.
 * A sticky collider pushes the strip's ends out of itself and glues them to
 * its faces: the strip hangs from the faces. (Before the sticky face's
 * reaction (p2g_mirror, sticky_ghosts_block) the free nodes next to a sticky
 * face missed it and the strip peeled off and fell 13.5 mm in 0.16 s.) */
static double pulled_strip(hearth_contact mode, double *length) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.002;
    d.hi[0] = 0.2, d.hi[1] = 0.1;
    hearth_scene *s = fx_scene_def(&d);
    int m = fx_elastic(s, 4e4, 0.3, 500);
    const double y0 = 0.03, c[3] = {0.1, y0, 0}, h[3] = {0.03, 0.006, 0};
    fx_box(s, m, c, h, 4, NULL);
    hearth_error err;
    for (int side = -1; side <= 1; side += 2) { /* each grip covers 1 cm of the strip's end */
        const double gc[3] = {0.1 + side * 0.027, y0, 0}, gh[3] = {0.007, 0.01, 0};
        CHECK(fx_box_collider(s, gc, gh, mode, side * 0.02) >= 0);
    }
    CHECK(hearth_scene_advance(s, 0.16, &err) == HEARTH_OK);
    double sy = 0, lo = 1, hi = 0;
    int n = 0;
    for (int i = 0; i < s->ps.n; i++) {
        const double *x = pcold(&s->ps, PC_X) + 3 * i;
        lo = fmin(lo, x[0]), hi = fmax(hi, x[0]);
        if (fabs(x[0] - 0.1) < 0.01) sy += x[1], n++;
    }
    *length = hi - lo;
    hearth_scene_destroy(s);
    return n ? sy / n - y0 : -1;
}

TEST(grip_holds_pulled_strip) {
    double lg, ls;
    const double dg = pulled_strip(HEARTH_GRIP, &lg), ds = pulled_strip(HEARTH_STICKY, &ls);
    printf("  middle of the strip moved %.2f mm held by grips (length %.1f mm), %.2f mm by sticky colliders (length %.1f mm); "
           "start length 60 mm, grips moved 3.2 mm each\n", dg * 1e3, lg * 1e3, ds * 1e3, ls * 1e3);
    CHECK(fabs(dg) < 0.002);              /* held up */
    CHECK(fabs(lg - (0.059 + 0.0064)) < 0.001); /* particle extent 59 mm at the start; the held ends moved with the grips */
    CHECK(fabs(ds) < 0.002);              /* glued to the sticky faces: it hangs there */
    CHECK(fabs(ls - lg) > 0.005);         /* but not carried: the ends were pushed out of the boxes */
}

/* The MPM step's scratch is MPM's (struct mpm_state, mpm.h): made with the
 * scene, grown by the sort, P2G's volumes only once heat or water is live;
 * and the memory estimate's scratch term is the sort's 16 bytes (order and
 * keys, the permutation working in the keys' room) and the volumes' 8, at
 * one thread. At two threads in 2D P2G's tile store is held too (mpm.c,
 * p2g_store_reserve): per particle block the halo of its 6x6 node tile
 * around its 4x4 block, 20 nodes, of mass and two momenta, 3 x 20 doubles
 * = 480 bytes, for 16 cells x 4 particles (s:add's default ppc): 7.5 bytes a
 * particle, the limit of a large body; a square of L cells at ppc 4 spans
 * L / 4 + 1 particle blocks a side (a particle's block is its B-spline base
 * node's, half a cell back), so its store holds 480 (L / 4 + 1)^2 bytes for
 * 4 L^2 particles: 9.49 a particle at L = 32, 8.14 at L = 96, counted here
 * from tiles_cap after a step at two threads. The store lives in the room of
 * the sort's order and keys (8 bytes a particle, dead between the sort and
 * G2P; mpm_p2g_store_reserve): the scratch block holds the larger of the
 * two, and the estimate counts the larger of 8 and 7.5. */
TEST(mpm_store_in_estimate) {
    for (int run = 0; run < 3; run++) {
        const int threads = run == 0 ? 1 : 2, L = run < 2 ? 32 : 96;
        hearth_set_threads(threads);
        hearth_scene *s = fx_scene(2, 0.5 / L, 0, 1);
        CHECK(s != NULL);
        if (!s) break;
        const int m = fx_elastic(s, 1e4, 0.3, 1000);
        const double c[3] = {0.5, 0.5, 0}, h[3] = {0.25, 0.25, 0}, v[3] = {0, 0, 0};
        const int n = fx_box(s, m, c, h, 4, v);
        CHECK(n == 4 * L * L && n >= SCENE_PARALLEL_MIN);
        hearth_error err;
        CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
        double cols = 0;
        for (int k = 0; k < PC_COUNT; k++)
            if (s->ps.enabled & (1u << k)) cols += (double)particles_col_bytes(&s->ps, k);
        const double store = threads > 1 ? 480.0 / 64 : 0; /* bytes a particle, as derived above */
        const double est = scene_bytes_per_particle(s), held = (double)s->mpm->tiles_cap * sizeof(double) / n;
        const double span = L / 4 + 1, counted = threads > 1 ? 480 * span * span / n : 0;
        const double keys = 2.0 * sizeof(int) * s->mpm->scratch_cap, scratch = (double)s->mpm->scratch_bytes;
        printf("  %d thread(s), %d cells a side: %d particles, %d particle blocks, estimate %.2f bytes a particle "
               "(columns %.0f), store held %.2f bytes a particle (counted %.2f), the sort's scratch %.2f "
               "(order and keys %.2f)\n",
               threads, L, n, s->mpm->npb, est, cols, held, counted, scratch / n, keys / n);
        CHECK(est == cols + (2 * sizeof(int) > store ? 2 * sizeof(int) : store) + sizeof(double));
        CHECK(held == counted);
        CHECK(held >= store);
        /* the store in order and keys' block, which grew only by what it lacked */
        CHECK(threads == 1 || s->mpm->tiles == (double *)(void *)s->mpm->keys);
        CHECK(scratch == (keys > held * n ? keys : held * n));
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
}

TEST(mpm_state_owned_by_solver) {
    hearth_set_threads(1); /* no tile store: its term is mpm_store_in_estimate's */
    hearth_scene *s = fx_scene(2, 0.05, 0, 1);
    CHECK(s != NULL);
    if (!s) return;
    const mpm_state *st = mpm_state_of(s);
    CHECK(st != NULL && st->counts != NULL && st->mark != NULL && st->nblocks == s->g.nblocks);
    CHECK(s->g.slot != NULL);
    CHECK(st->scratch_cap == 0 && st->pb == NULL); /* no particles yet */
    const int m = fx_elastic(s, 1e4, 0.3, 1000);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.1, 0.1, 0};
    hearth_shape *b = hearth_shape_box(c, h);
    hearth_error err;
    const int n = hearth_scene_seed_shape(s, m, b, 4, 0.5, NULL, &err);
    hearth_shape_free(b);
    CHECK(n > 0);
    CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
    CHECK(st->scratch_cap >= n && st->npb > 0 && st->colour_start[8] == st->npb);
    CHECK(st->vol == NULL); /* no heat, no water: no volumes */
    double cols = 0;
    for (int k = 0; k < PC_COUNT; k++)
        if (s->ps.enabled & (1u << k)) cols += (double)particles_col_bytes(&s->ps, k);
    CHECK(scene_bytes_per_particle(s) == cols + 2 * sizeof(int) + sizeof(double)); /* order; keys (the permutation's scratch); volumes */
    CHECK(hearth_scene_set_oven(s, 180, 10, &err) == HEARTH_OK);
    CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
    CHECK(st->vol != NULL);
    hearth_scene_destroy(s);
    hearth_set_threads(0);
}

/* Plane Couette flow between a resting floor and a lid sliding at U, both
 * sticky box colliders whose faces lie on node rows (y = 4 dx and 8 dx; the
 * box faces are computed as centre -/+ half, so their SDF at the row is zero
 * up to round-off) at dx = 1/64 and 1/128. The steady profile is linear, so the particles' mean
 * speed is U/2. `shift` moves the lid's face by shift*dx (positive: up, out
 * of the fluid). Returns the mean vx/U of the particles in the middle of the
 * layer, away from its free ends. */
static double couette_mean(double dx, double shift) {
    hearth_scene_def d = hearth_default_scene_def();
    const double U = 0.01, y0 = 0.0625, y1 = 0.125; /* node rows at dx = 1/64 and 1/128 */
    d.dx = dx;
    d.hi[1] = 0.25;
    d.gravity[1] = 0;
    hearth_scene *s = fx_scene_def(&d);
    const char *nn[] = {"bulk", "viscosity", "density"};
    const double nv[] = {1e5, 10, 1000}; /* c = 10 m/s, nu = 0.01 m^2/s: h^2/nu = 0.39 s */
    hearth_error err;
    const int m = hearth_scene_add_material(s, "newtonian", nn, nv, 3, &err);
    const double c[3] = {0.5, 0.5 * (y0 + y1), 0}, h[3] = {0.12, 0.5 * (y1 - y0), 0};
    fx_box(s, m, c, h, 4, NULL); /* free ends: a closed channel would carry no net flow */
    const double fc[3] = {0.5, 0.5 * y0 + 0.0001, 0}, fh[3] = {0.6, y0 - fc[1], 0};
    CHECK(fx_box_collider(s, fc, fh, HEARTH_STICKY, 0) == 0);
    const double ytop = y1 + shift * dx, lc[3] = {0.5, 0.5 * (ytop + 0.2) + 0.0003, 0}, lh[3] = {0.6, lc[1] - ytop, 0};
    CHECK(fx_box_collider(s, lc, lh, HEARTH_STICKY, U) == 1);
    CHECK(hearth_scene_advance(s, 0.8, &err) == HEARTH_OK); /* the slowest mode decays as exp(-pi^2 nu t / h^2) */
    double sv = 0;
    int n = 0;
    for (int i = 0; i < s->ps.n; i++) {
        const double *x = pcold(&s->ps, PC_X) + 3 * i;
        if (fabs(x[0] - 0.5) < 0.05) sv += pcold(&s->ps, PC_V)[3 * i], n++;
    }
    hearth_scene_destroy(s);
    return n ? sv / n / U : NAN;
}

/* A collider face on a node row holds that row whatever the round-off of its
 * SDF there: the layer moves at U/2 (0.5 +- 0.02), the same (within 0.005)
 * with the lid's face 1e-6 dx either side of the row. */
TEST(couette_lid_on_node_row) {
    for (int k = 1; k <= 2; k++) {
        const double dx = 1.0 / (64 * k);
        const double on = couette_mean(dx, 0), up = couette_mean(dx, 1e-6), down = couette_mean(dx, -1e-6);
        printf("  dx = 1/%d: Couette layer mean speed / lid speed: face on the row %.4f, 1e-6 dx out %.4f, 1e-6 dx in %.4f "
               "(exact 0.5)\n", 64 * k, on, up, down);
        CHECK(fabs(on - 0.5) < 0.02);
        CHECK(fabs(up - on) < 0.005);
        CHECK(fabs(down - on) < 0.005);
    }
}

/* A cantilever clamped by a grip sags under its own weight. Beam of length
 * L = 0.1 m beyond the grip's face, thickness t = 0.01 m (`cells` cells),
 * E = 3e7 Pa, nu = 0, rho = 1000: Euler-Bernoulli tip deflection
 * w = q L^4 / (8 E I) = 1.5 rho g L^4 / (E t^2) = 0.49 mm, plus Timoshenko's
 * shear term E t^2 / (3 kappa G L^2) = 0.8 (t/L)^2 of it (kappa = 5/6,
 * G = E/2). The grip's face lies on a node row. The beam settles under a
 * test-side mass-proportional damping (v and C scaled by exp(-a dt) after
 * each step, a = 2 omega_1: the first mode is critically damped and every
 * mode decays as exp(-omega_1 t)), run for omega_1 t = 9. Returns the
 * deflection of the last cell over the closed form there. */
/* Mean position of the particles that lay in the beam's last cell at rest
 * (x > L - dx: the deflection moves them a small fraction of a cell in x). */
static void tip_mean(const hearth_scene *s, double L, double dx, double *xm, double *ym) {
    double sx = 0, sy = 0;
    int n = 0;
    for (int i = 0; i < s->ps.n; i++) {
        const double *x = pcold(&s->ps, PC_X) + 3 * i;
        if (x[0] > L - dx) sx += x[0], sy += x[1], n++;
    }
    *xm = n ? sx / n : NAN;
    *ym = n ? sy / n : NAN;
}

static double cantilever_tip(int cells) {
    const double L = 0.1, t = 0.01, E = 3e7, rho = 1000, g = 9.81, dx = t / cells, Lg = 0.01;
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = dx;
    d.lo[0] = -0.02, d.hi[0] = 0.14;
    d.lo[1] = -0.02, d.hi[1] = 0.06;
    d.gravity[1] = -g;
    hearth_scene *s = fx_scene_def(&d);
    const int m = fx_elastic(s, E, 0.0, rho);
    const double y0 = 0.02, c[3] = {0.5 * (L - Lg), y0 + 0.5 * t, 0}, h[3] = {0.5 * (L + Lg), 0.5 * t, 0};
    fx_box(s, m, c, h, 4, NULL);
    const double gc[3] = {-0.5 * Lg - 0.005, y0 + 0.5 * t, 0}, gh[3] = {0.5 * Lg + 0.005, t, 0}; /* face at x = 0 */
    CHECK(fx_box_collider(s, gc, gh, HEARTH_GRIP, 0) == 0);
    const double w_eb = 1.5 * rho * g * pow(L, 4) / (E * t * t); /* at the tip, for the printout */
    const double omega1 = 1.875104 * 1.875104 * sqrt(E * t * t / 12 / (rho * pow(L, 4))), a = 2 * omega1;
    double x0, yr;
    tip_mean(s, L, dx, &x0, &yr);
    hearth_error err;
    while (s->t < 9 / omega1) {
        const double t0 = s->t;
        if (hearth_scene_step(s, 1, &err) != HEARTH_OK) {
            fprintf(stderr, "%s\n", err.msg);
            test_failures++;
            break;
        }
        const double f = exp(-a * (s->t - t0));
        double *V = pcold(&s->ps, PC_V), *C = pcold(&s->ps, PC_C);
        for (int i = 0; i < 3 * s->ps.n; i++) V[i] *= f;
        for (int i = 0; i < particles_tn(&s->ps) * s->ps.n; i++) C[i] *= f;
    }
    double x1, y1;
    tip_mean(s, L, dx, &x1, &y1);
    const double w = yr - y1;
    /* the closed form at the tip cell's centroid x0: Euler-Bernoulli
     * q x^2 (6 L^2 - 4 L x + x^2) / (24 E I) plus the shear term q (L x - x^2/2) / (kappa G t) */
    const double q = rho * g * t, EI = E * t * t * t / 12, kG = 5 * E / 12;
    const double w_exact = q * x0 * x0 * (6 * L * L - 4 * L * x0 + x0 * x0) / (24 * EI) + q * (L * x0 - 0.5 * x0 * x0) / (kG * t);
    printf("  %2d cells through: %d particles, %ld steps, deflection at x = %.5f m %.5f mm, closed form %.5f mm "
           "(E-B at the tip %.5f): ratio %.4f\n", cells, s->ps.n, s->step, x0, w * 1e3, w_exact * 1e3, w_eb * 1e3, w / w_exact);
    hearth_scene_destroy(s);
    return w / w_exact;
}

/* A grip clamps at its face: a cantilever held by one converges to the beam's
 * closed form from 4 to 6 cells through the thickness. (Clamped a cell in,
 * as grips were, the beam was 6.9% short at 4 cells.) The ladder to 8 cells
 * is in docs/validation.md. */
TEST(grip_cantilever_clamped_at_face) {
    const double r4 = cantilever_tip(4), r6 = cantilever_tip(6);
    const double e4 = fabs(r4 - 1), e6 = fabs(r6 - 1);
    printf("  error %.2f%% (4 cells), %.2f%% (6 cells): observed order %.2f\n", 100 * e4, 100 * e6, log(e4 / e6) / log(1.5));
    CHECK(e4 < 0.04);
    CHECK(e6 < 0.025);
    CHECK(e6 < e4);
    if (getenv("HEARTH_LONG_LADDER")) { /* scripts/validation/walls.sh: about a minute more */
        const double e8 = fabs(cantilever_tip(8) - 1);
        printf("  error %.2f%% (8 cells): observed order from 6 to 8 cells %.2f\n", 100 * e8, log(e6 / e8) / log(8.0 / 6));
    }
}

/* An elastic column (E = 1e6 Pa, nu = 0, rho = 1000, H = 0.1 m, width H/2)
 * settles on a sticky floor (a box collider whose face lies on a node row)
 * under a test-side mass-proportional damping (v and C scaled by
 * exp(-a dt) after each step; a = 2 omega_1 of the column's first axial mode,
 * run for omega_1 t = 12: the scene API has no damping yet). With nu = 0 the
 * vertical stress is -3 p, so the pressure probe at the base should read
 * rho g H / 3. Returns that probe over rho g H / 3, `cells` across the
 * height; row1 gets the mean particle pressure of the particle row 0.75 dx
 * above the floor over the exact rho g (H - y) / 3 there. */
static double column_base(int cells, double *interior, double *row1) {
    const double H = 0.1, E = 1e6, rho = 1000, g = 9.81, dx = H / cells, yf = 0.02;
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = dx;
    d.lo[0] = 0, d.hi[0] = 0.1;
    d.lo[1] = 0, d.hi[1] = 0.15;
    d.gravity[1] = -g;
    hearth_scene *s = fx_scene_def(&d);
    const int m = fx_elastic(s, E, 0.0, rho);
    const double c[3] = {0.05, yf + 0.5 * H, 0}, h[3] = {0.25 * H, 0.5 * H, 0};
    fx_box(s, m, c, h, 4, NULL);
    const double fc[3] = {0.05, 0.5 * yf, 0}, fh[3] = {0.1, 0.5 * yf, 0};
    CHECK(fx_box_collider(s, fc, fh, HEARTH_STICKY, 0) == 0);
    const double omega1 = 0.5 * PI * sqrt(E / rho) / H, a = 2 * omega1;
    hearth_error err;
    while (s->t < 12 / omega1) {
        const double t0 = s->t;
        if (hearth_scene_step(s, 1, &err) != HEARTH_OK) {
            fprintf(stderr, "%s\n", err.msg);
            test_failures++;
            break;
        }
        const double f = exp(-a * (s->t - t0));
        double *V = pcold(&s->ps, PC_V), *C = pcold(&s->ps, PC_C);
        for (int i = 0; i < 3 * s->ps.n; i++) V[i] *= f;
        for (int i = 0; i < particles_tn(&s->ps) * s->ps.n; i++) C[i] *= f;
    }
    const double ref = rho * g * H / 3;
    double p = NAN, pm = NAN;
    const double xb[3] = {0.05, yf, 0}, xm[3] = {0.05, yf + 0.5 * H, 0};
    CHECK(hearth_probe_point(s, "pressure", xb, &p, &err) == HEARTH_OK);
    CHECK(hearth_probe_point(s, "pressure", xm, &pm, &err) == HEARTH_OK);
    *interior = pm / (0.5 * ref);
    double *pp = malloc(sizeof(double) * (size_t)s->ps.n), sp = 0, sy = 0;
    int n1 = 0;
    CHECK(pp && hearth_scene_particle_field(s, "pressure", pp, &err) == HEARTH_OK);
    for (int i = 0; pp && i < s->ps.n; i++) {
        const double *x = pcold(&s->ps, PC_X) + 3 * i;
        if (fabs(x[0] - 0.05) < 0.01 && x[1] >= yf + 0.5 * dx && x[1] < yf + dx) sp += pp[i], sy += x[1], n1++;
    }
    free(pp);
    *row1 = n1 ? sp / n1 / (rho * g * (H + yf - sy / n1) / 3) : NAN;
    printf("  %3d cells tall: %4d particles, %3ld steps: base probe / (rho g H / 3) = %.4f; mid-height %.4f; "
           "the particles 0.75 dx above the floor %.4f\n", cells, s->ps.n, s->step, p / ref, *interior, *row1);
    hearth_scene_destroy(s);
    return p / ref;
}

/* The stress probe at the base of a settled column approaches rho g H as dx
 * shrinks, at first order, and so does the particle row 0.75 dx above the
 * floor (the interior within 0.5% at every level). Before the sticky face's
 * mirror (p2g_mirror, sticky_ghosts_block) the base probe read +1.2%, +3.5%,
 * +4.7% and that row +19.6%, +18.1%, +17.4% at 10, 20, 40 cells. */
TEST(column_base_stress) {
    double mid[3], r[3], row1[3];
    for (int k = 0; k < 3; k++) r[k] = column_base(10 << k, &mid[k], &row1[k]);
    for (int k = 0; k < 3; k++) CHECK(fabs(mid[k] - 1) < 0.005);
    const double e[3] = {fabs(r[0] - 1), fabs(r[1] - 1), fabs(r[2] - 1)};
    const double q[3] = {fabs(row1[0] - 1), fabs(row1[1] - 1), fabs(row1[2] - 1)};
    printf("  base probe error %.2f%%, %.2f%%, %.2f%%: observed order %.2f, %.2f; row 0.75 dx up %.2f%%, %.2f%%, %.2f%%: "
           "order %.2f, %.2f\n", 100 * e[0], 100 * e[1], 100 * e[2], log2(e[0] / e[1]), log2(e[1] / e[2]), 100 * q[0],
           100 * q[1], 100 * q[2], log2(q[0] / q[1]), log2(q[1] / q[2]));
    CHECK(e[2] < 0.015);
    CHECK(q[2] < 0.01);
    for (int k = 0; k < 2; k++) {
        CHECK(log2(e[k] / e[k + 1]) > 0.8);
        CHECK(log2(q[k] / q[k + 1]) > 0.8);
    }
    if (getenv("HEARTH_LONG_LADDER")) { /* scripts/validation/walls.sh */
        double m80, q80;
        const double e80 = fabs(column_base(80, &m80, &q80) - 1);
        printf("  80 cells: base probe error %.2f%%, order from 40 %.2f; row 0.75 dx up %.2f%%, order %.2f\n", 100 * e80,
               log2(e[2] / e80), 100 * fabs(q80 - 1), log2(q[2] / fabs(q80 - 1)));
    }
}

/* A shear wave in a box periodic along x and y, filled with a Newtonian fluid
 * (nu = 0.01 m^2/s): u_x = U sin(k y) decays as exp(-nu k^2 t) with no wall
 * anywhere. `cells` across the period L = 0.25 m; run to nu k^2 t = 0.6.
 * Returns the measured amplitude over the closed form, less 1. */
static double shear_wave(int cells, int *n_out) {
    const double L = 0.25, U = 0.01, nu = 0.01, k = 2 * PI / L, T = 0.6 / (nu * k * k);
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = L / cells;
    d.lo[0] = d.lo[1] = 0;
    d.hi[0] = d.hi[1] = L;
    d.gravity[1] = 0;
    d.periodic[0] = d.periodic[1] = 1;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NAN;
    const char *nn[] = {"bulk", "viscosity", "density"};
    const double nv[] = {1e5, nu * 1000, 1000};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "newtonian", nn, nv, 3, &err);
    const double c[3] = {0.5 * L, 0.5 * L, 0}, h[3] = {L, L, 0}; /* larger than the box: fills the period */
    const int n = fx_box(s, m, c, h, 4, NULL);
    *n_out = n;
    double *X = pcold(&s->ps, PC_X), *V = pcold(&s->ps, PC_V), *C = pcold(&s->ps, PC_C);
    for (int i = 0; i < s->ps.n; i++) { /* the wave and its velocity gradient (APIC's C) */
        V[3 * i] = U * sin(k * X[3 * i + 1]);
        C[particles_tn(&s->ps) * i + 1] = U * k * cos(k * X[3 * i + 1]); /* C_xy: 1 in a 2x2 and a 3x3 */
    }
    if (hearth_scene_advance(s, T, &err) != HEARTH_OK) {
        fprintf(stderr, "%s\n", err.msg);
        test_failures++;
    }
    X = pcold(&s->ps, PC_X), V = pcold(&s->ps, PC_V);
    double a = 0, vy = 0;
    for (int i = 0; i < s->ps.n; i++) a += 2 * V[3 * i] * sin(k * X[3 * i + 1]) / s->ps.n, vy = fmax(vy, fabs(V[3 * i + 1]));
    const double exact = U * exp(-nu * k * k * s->t);
    printf("  %2d cells: %5d particles, %4ld steps to t = %.4f s: amplitude %.6f mm/s, closed form %.6f: ratio - 1 = %+.5f; "
           "largest |v_y| %.2e m/s\n", cells, s->ps.n, s->step, s->t, a * 1e3, exact * 1e3, a / exact - 1, vy);
    CHECK(vy < 1e-3 * U); /* a shear wave: nothing moves across it */
    hearth_scene_destroy(s);
    return a / exact - 1;
}

/* The periodic box has no walls: the shear wave decays at the viscous rate,
 * 5% fast at 16 cells a wavelength, within 1% at 32, the error shrinking
 * faster than second order. (HEARTH_LONG_LADDER: 64 cells too.) */
TEST(mpm_periodic_shear_wave) {
    int n16, n32;
    const double e16 = shear_wave(16, &n16), e32 = shear_wave(32, &n32);
    printf("  observed order %.2f\n", log2(fabs(e16) / fabs(e32)));
    CHECK(n16 == 16 * 16 * 4 && n32 == 32 * 32 * 4); /* the period filled exactly: no particle at both faces */
    CHECK(fabs(e16) < 0.06);
    CHECK(fabs(e32) < 0.01);
    CHECK(log2(fabs(e16) / fabs(e32)) > 2);
    if (getenv("HEARTH_LONG_LADDER")) {
        int n64;
        const double e64 = shear_wave(64, &n64);
        printf("  observed order from 32 to 64 cells %.2f\n", log2(fabs(e32) / fabs(e64)));
    }
}

/* An elastic blob, spinning and moving along x, crosses the seam of a box
 * periodic along x (slip walls in y, far away): the grid sums its momentum
 * across the seam, so the total is kept to round-off, and the blob comes
 * back whole (the same extent in x as at the start, once unwrapped). */
TEST(mpm_periodic_conserves_momentum) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 1.0 / 64;
    d.hi[0] = 0.5, d.hi[1] = 0.5;
    d.gravity[1] = 0;
    d.periodic[0] = 1;
    hearth_scene *s = fx_scene_def(&d);
    CHECK(s != NULL);
    if (!s) return;
    const int m = fx_elastic(s, 1e4, 0.3, 1000);
    const double c[3] = {0.4, 0.25, 0}, h[3] = {0.06, 0.06, 0}, v0[3] = {1.0, 0.1, 0};
    fx_box(s, m, c, h, 4, v0);
    double *X = pcold(&s->ps, PC_X), *V = pcold(&s->ps, PC_V), *C = pcold(&s->ps, PC_C);
    for (int i = 0; i < s->ps.n; i++) { /* and a spin of 5 rad/s about the centre */
        V[3 * i] -= 5 * (X[3 * i + 1] - c[1]);
        V[3 * i + 1] += 5 * (X[3 * i] - c[0]);
        const int tn = particles_tn(&s->ps); /* C_xy at 1, C_yx at 2 of a 2D store's 2x2 (3 of a 3x3) */
        C[tn * i + 1] = -5, C[tn * i + (tn == 4 ? 2 : 3)] = 5;
    }
    double p0[2] = {0, 0};
    const double *M = pcold(&s->ps, PC_MASS);
    for (int i = 0; i < s->ps.n; i++) p0[0] += M[i] * V[3 * i], p0[1] += M[i] * V[3 * i + 1];
    hearth_error err;
    int crossed = 0;
    double worst = 0;
    while (s->t < 0.5) { /* 0.5 m along x: once round the period */
        CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
        X = pcold(&s->ps, PC_X), V = pcold(&s->ps, PC_V), M = pcold(&s->ps, PC_MASS);
        double p[2] = {0, 0};
        int lo = 0, hi = 0;
        for (int i = 0; i < s->ps.n; i++) {
            p[0] += M[i] * V[3 * i], p[1] += M[i] * V[3 * i + 1];
            lo += X[3 * i] < 0.1, hi += X[3 * i] > 0.4;
            CHECK(X[3 * i] >= 0 && X[3 * i] < 0.5);
        }
        crossed |= lo > 0 && hi > 0;
        worst = fmax(worst, hypot(p[0] - p0[0], p[1] - p0[1]) / hypot(p0[0], p0[1]));
    }
    /* unwrapped about the blob's centre x_c = 0.4 + 1.0 t - 0.5 (mod 0.5): its extent along x */
    const double xc = fmod(0.4 + 1.0 * s->t, 0.5);
    double ulo = 1, uhi = -1;
    for (int i = 0; i < s->ps.n; i++) {
        double u = X[3 * i] - xc;
        u -= 0.5 * round(u / 0.5);
        ulo = fmin(ulo, u), uhi = fmax(uhi, u);
    }
    printf("  %d particles, %ld steps to t = %.3f s: the blob crossed the seam: %s; largest momentum change / |P0| %.2e; "
           "x extent about its centre [%.4f, %.4f] m (from [-0.06, 0.06], spinning)\n", s->ps.n, s->step, s->t,
           crossed ? "yes" : "no", worst, ulo, uhi);
    CHECK(crossed);
    CHECK(worst < 1e-12);
    CHECK(uhi - ulo < 0.2); /* whole, not torn at the seam */
    CHECK(s->out_of_domain == 0);
    hearth_scene_destroy(s);
}

/* What periodic axes refuse, each named: a period that is not a whole
 * number of cells, a z axis in 2D, heat (its passes have no ghosts yet);
 * a checkpoint (format version 5) keeps them; SPH takes them as its own
 * sph.periodic axes. */
TEST(mpm_periodic_refusals) {
    hearth_error err;
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.03; /* 33.3 cells across the unit box */
    d.periodic[0] = 1;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "whole number of cells");
    d = hearth_default_scene_def();
    d.periodic[2] = 1;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "periodic_z in a 2D scene");
    d = hearth_default_scene_def();
    d.dx = 1.0 / 32;
    d.periodic[1] = 1;
    hearth_scene *s = fx_scene_def(&d);
    CHECK(s != NULL);
    if (!s) return;
    const int m = fx_elastic(s, 1e4, 0.3, 1000);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.1, 0.1, 0};
    fx_box(s, m, c, h, 4, NULL);
    CHECK(hearth_scene_step(s, 2, &err) == HEARTH_OK);
    /* periodic axes are in checkpoint format version 5's DEF section: the copy wraps as the original */
    CHECK(hearth_scene_save(s, "periodic_roundtrip.ck", &err) == HEARTH_OK);
    hearth_scene *r = hearth_scene_load("periodic_roundtrip.ck", &err);
    if (!r) printf("  load: %s\n", err.msg);
    CHECK(r != NULL);
    remove("periodic_roundtrip.ck");
    if (r) {
        CHECK(r->def.periodic[0] == 0 && r->def.periodic[1] == 1);
        CHECK(hearth_scene_step(s, 10, &err) == HEARTH_OK);
        CHECK(hearth_scene_step(r, 10, &err) == HEARTH_OK);
        printf("  periodic_y restored; 10 steps on: %016llx %016llx\n", (unsigned long long)hearth_scene_hash(s),
               (unsigned long long)hearth_scene_hash(r));
        CHECK(hearth_scene_hash(r) == hearth_scene_hash(s));
        hearth_scene_destroy(r);
    }
    CHECK(hearth_scene_set_oven(s, 180, 10, &err) == HEARTH_OK);
    CHECK(hearth_scene_step(s, 1, &err) != HEARTH_OK);
    CHECK_STR_CONTAINS(err.msg, "periodic axes (periodic_y) do not carry heat");
    hearth_scene_destroy(s);
    d = hearth_default_scene_def();
    d.solver = HEARTH_SOLVER_SPH;
    d.dx = 0.03; /* SPH needs no whole number of cells */
    d.periodic[0] = 1;
    s = fx_scene_def(&d);
    CHECK(s != NULL && s->def.sph.periodic[0] == 1 && s->def.sph.periodic[1] == 0);
    hearth_scene_destroy(s);
}

TEST_MAIN(T(bspline_weights), T(transfer_conservation_2d), T(transfer_conservation_3d), T(transfer_pic_dissipates), T(rotating_disc), T(free_fall),
          T(vibrating_bar), T(determinism_threads), T(checkpoint_restore), T(guard_nan_plugin), T(guard_plugin_error),
          T(guard_cfl_and_rollback), T(colliders_contact), T(probe_fields), T(stress_tensor_components), T(scene_bad_input), T(alloc_failure_paths),
          T(particles_optional_columns), T(body_force), T(determinism_threads_sticky_damped), T(p2g_gather_matches_colour_phases), T(determinism_threads_3d_claims), T(guard_collider_drive), T(grip_holds_pulled_strip),
          T(mpm_state_owned_by_solver), T(mpm_store_in_estimate), T(couette_lid_on_node_row), T(grip_cantilever_clamped_at_face), T(column_base_stress),
          T(mpm_periodic_shear_wave), T(mpm_periodic_conserves_momentum), T(mpm_periodic_refusals))
