/* unit_sph_transport.c: momentum and heat through SPH (Rodriguez-Arenas 2011, ch. 3):
 * channel and Couette flows, the viscosity and wall ladders, artificial
 * stress, moving walls, surface tension, conduction and the oven's Robin flux,
 * against closed forms. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "alloc.h"
#include "hearth/hearth.h"
#include "scene.h"
#include "solver.h"
#include "sph.h"
#include "sph_kernel.h"
#include "sph_fixture.h"
#include "sph_neighbours.h"
#include "test.h"

static void push_x(void *ud, double t, const double x[3], double acc[3]) {
    (void)t, (void)x;
    acc[0] = *(const double *)ud;
}

/* The start-up of plane Poiseuille flow from rest under a body force f
 * between plates a distance L apart (no-slip at y = 0 and L): the steady
 * parabola less its odd sine modes, each decaying at its own rate. */
static double startup_series(double f, double nu, double L, double y, double t) {
    double u = f / (2 * nu) * y * (L - y);
    for (int k = 1; k < 400; k += 2) {
        const double e = exp(-k * k * SPH_PI * SPH_PI * nu * t / (L * L));
        if (e < 1e-18) break;
        u -= 4 * f * L * L / (nu * SPH_PI * SPH_PI * SPH_PI * k * k * k) * sin(k * SPH_PI * y / L) * e;
    }
    return u;
}

/* Channel flow between fixed plates (periodic in x, twelve columns, three
 * wall layers, the wall surface half a spacing beyond the last wall
 * particle, L = 0.02 m with N particles across) under a body force f, at
 * viscosity eta, from rest. At each of the nt times ts (in units of L^2 /
 * nu) err[k] is the worst |u - u_series| over the fluid particles as a
 * fraction of the series' centreline speed then, and slow[k] is how much the
 * mean fluid speed falls short of the series' mean at the same particles
 * (positive: slow). Returns 0, or -1 if a step failed or a velocity is not
 * finite. The peak of the steady profile, f L^2 / (8 nu), is 5 mm/s at any
 * eta. */
/* The start-up of plane Couette flow from rest: the lid at y = L slides at U
 * from t = 0, the floor at y = 0 stays: the steady line less its sine
 * modes, each decaying at its own rate. */
static double couette_series(double U, double nu, double L, double y, double t) {
    double u = U * y / L;
    for (int k = 1; k < 4000; k++) {
        const double e = exp(-k * k * SPH_PI * SPH_PI * nu * t / (L * L));
        if (e < 1e-18) break;
        u -= 2 * U / (k * SPH_PI) * (k % 2 ? 1.0 : -1.0) * sin(k * SPH_PI * y / L) * e;
    }
    return u;
}

/* As channel below, with the body force f or (lid > 0) with no force and the
 * top wall moving at lid m/s along x (hearth_scene_body_motion), measured
 * against the Couette start-up as a fraction of the lid speed. */
static int channel_lid(int N, double eta, double lid, const double *ts, int nt, double *err, double *slow, int debug);

static int channel(int N, double eta, const double *ts, int nt, double *err, double *slow, int debug) {
    return channel_lid(N, eta, 0, ts, nt, err, slow, debug);
}

static int channel_lid(int N, double eta, double lid, const double *ts, int nt, double *err, double *slow, int debug) {
    const double L = 0.02, dx = L / N, w = 3 * dx, lo[3] = {0, 0, 0}, hi[3] = {12 * dx, L + 2 * w, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.periodic[0] = 1;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return -1;
    const double rho = 1000, nu = eta / rho;
    double f = lid > 0 ? 0.0 : 0.1 * eta;
    int m = newtonian(s, rho, 1e3, eta);
    const int top = box_body(s, m, 0, L + w, hi[0], hi[1], 1, NAN);
    int ok = box_body(s, m, 0, 0, hi[0], w, 1, NAN) >= 0 && top >= 0 && box_body(s, m, 0, w, hi[0], L + w, 0, NAN) >= 0;
    if (lid > 0) {
        const double U[3] = {lid, 0, 0};
        hearth_error e;
        ok = ok && hearth_scene_body_motion(s, top, U, NULL, NULL, NULL, NULL, &e) == HEARTH_OK;
    } else
        hearth_scene_set_body_force(s, push_x, &f);
    int rcode = ok ? 0 : -1;
    for (int k = 0; k < nt && !rcode; k++) {
        hearth_error e;
        const double t = ts[k] * L * L / nu;
        if (hearth_scene_advance(s, t, &e)) {
            fprintf(stderr, "%s\n", e.msg);
            rcode = -1;
            break;
        }
        const double *x = hearth_scene_positions(s), *v = pcold(&s->ps, PC_V);
        const int *flags = pcoli(&s->ps, PC_FLAGS);
        const double uc = lid > 0 ? lid : startup_series(f, nu, L, 0.5 * L, s->t);
        double worst = 0, su = 0, sw = 0;
        for (int i = 0; i < hearth_scene_particle_count(s); i++) {
            if (flags[i] & PF_FIXED) continue;
            const double y = x[3 * i + 1] - w;
            const double want = lid > 0 ? couette_series(lid, nu, L, y, s->t) : startup_series(f, nu, L, y, s->t);
            if (!isfinite(v[3 * i])) rcode = -1;
            worst = fmax(worst, fabs(v[3 * i] - want));
            su += v[3 * i], sw += want;
            if (debug && x[3 * i] < dx) printf("t %.4g y %.5f u %.5g want %.5g vy %.3g\n", ts[k], y, v[3 * i], want, v[3 * i + 1]);
        }
        err[k] = worst / uc;
        slow[k] = 1 - su / sw;
    }
    hearth_scene_destroy(s);
    return rcode;
}

/* The steady channel of `channel` at N particles across after tend_viscous
 * L^2 / nu (e^(-pi^2 tend_viscous) of the start-up left, which the series
 * accounts for): the worst error as a fraction of the peak, or NAN if a step
 * failed. */
static double poiseuille_n(int N, double eta, double tend_viscous, int debug) {
    double err = NAN, slow = NAN;
    const int rc = channel(N, eta, &tend_viscous, 1, &err, &slow, debug);
    printf("poiseuille at %g Pa s, %d across: worst |u - u_exact| = %.2f%% of the peak, mean %.2f%% slow (t = %g L^2/nu)\n",
           eta, N, 100 * err, 100 * slow, tend_viscous);
    return rc ? NAN : err;
}

static double poiseuille(double eta, double tend_viscous, int debug) { return poiseuille_n(20, eta, tend_viscous, debug); }

/* The steady profile u(y) = f / (2 nu) y (L - y) within 3% of the peak.
 * Measured 0.58% (0.56% fast on average) with Morris et al.'s no-slip wall
 * velocities (sph_walls.c, sph_wall_frame) and eq. 3.8 renormalised by its second
 * moment (sph_viscous_factor); 2.2% (1.9% slow) before the renormalisation,
 * when the moment over rows sliding past each other was 3.8% above the
 * integral at h = 2.4 spacings; 12.6% with wall particles at rest in eq.
 * 3.19 (slip). */
TEST(sph_poiseuille) {
    const double err = poiseuille(1.0, 1.0, getenv("SPH_DEBUG") != NULL);
    CHECK(err < 0.03);
}

/* The no-slip wall drag is integrated implicitly: at 1e4 Pa s (the viscous
 * dt limit governs) the channel stays finite and within 10% of the start-up
 * series after half of L^2 / nu (measured 0.61%; 4.8% before eq. 3.8 was
 * renormalised, when the resting lattice's sum, 5.7% strong, held the
 * particles back). Taken explicitly, the wall velocities of up to
 * 5 v_a grew the velocities to 89 m/s. */
TEST(sph_wall_drag_stable) {
    const double err = poiseuille(1e4, 0.5, 0);
    CHECK(isfinite(err) && err < 0.1);
}

/* A creeping channel starts up from rest (1e4 Pa s: the particles move
 * 1e-4 of a spacing, so they stay on their lattice, and what is measured is
 * the viscous operator itself) at 10 and 20 particles across; at t = 0.05,
 * 0.2 and 0.5 L^2 / nu the worst error against the start-up series, as a
 * fraction of the centreline speed then, shrinks with the spacing, at an
 * observed order of at least 1, and is under 1% at 20 across. With eq. 3.8
 * summed over the resting lattice (5.7% strong at h = 2.4 spacings) the
 * flow was 4.6% and 5.2% slow and the error grew with resolution. (The
 * ladder to 80 across: scripts/validation/sph_viscosity_ladder.sh.) */
TEST(sph_creeping_startup_converges) {
    const double ts[] = {0.05, 0.2, 0.5};
    const int Ns[] = {10, 20};
    double E[2] = {NAN, NAN};
    for (int r = 0; r < 2; r++) {
        double err[3], slow[3];
        CHECK(channel(Ns[r], 1e4, ts, 3, err, slow, getenv("SPH_DEBUG") != NULL) == 0);
        E[r] = 0;
        for (int k = 0; k < 3; k++) {
            printf("creeping start-up, %d across, t = %.2f L^2/nu: worst error %.3f%% of the centreline, mean %.3f%% slow\n",
                   Ns[r], ts[k], 100 * err[k], 100 * slow[k]);
            E[r] = fmax(E[r], err[k]);
        }
    }
    const double order = log(E[0] / E[1]) / log(2.0);
    printf("creeping start-up: worst error %.3f%% (10 across), %.3f%% (20 across), observed order %.2f\n", 100 * E[0],
           100 * E[1], order);
    CHECK(E[1] < E[0]);
    CHECK(order >= 1.0);
    CHECK(E[1] < 0.01);
}

/* The steady Poiseuille profile (1 Pa s, rows sliding past each other, run
 * for L^2 / nu) converges: its worst error as a fraction of the peak shrinks
 * from 10 to 20 particles across at an observed order of at least 1. */
TEST(sph_poiseuille_converges) {
    const double e10 = poiseuille_n(10, 1.0, 1.0, 0), e20 = poiseuille_n(20, 1.0, 1.0, 0);
    const double order = log(e10 / e20) / log(2.0);
    printf("steady poiseuille: worst error %.3f%% (10 across), %.3f%% (20 across), observed order %.2f\n", 100 * e10,
           100 * e20, order);
    CHECK(isfinite(e10) && isfinite(e20));
    CHECK(order >= 1.0);
}

/* A creeping Couette start-up driven by a moving fixed-particle lid
 * (hearth_scene_body_motion: the top wall slides at 5 mm/s along x; 1e4 Pa s,
 * so the particles stay on their lattice) at 10 and 20 particles across: at
 * t = 0.05, 0.2 and 0.5 L^2 / nu the worst error against the start-up series,
 * as a fraction of the lid speed, shrinks at an observed order of at least 1
 * and is under 1% at 20 across. Before walls could move the lid stood still
 * and the fluid never started (error 100% of the lid speed at both). */
TEST(sph_couette_moving_lid_converges) {
    const double ts[] = {0.05, 0.2, 0.5};
    const int Ns[] = {10, 20};
    double E[2] = {NAN, NAN};
    for (int r = 0; r < 2; r++) {
        double err[3], slow[3];
        CHECK(channel_lid(Ns[r], 1e4, 5e-3, ts, 3, err, slow, getenv("SPH_DEBUG") != NULL) == 0);
        E[r] = 0;
        for (int k = 0; k < 3; k++) {
            printf("couette start-up, %d across, t = %.2f L^2/nu: worst error %.3f%% of the lid speed, mean %.3f%% slow\n",
                   Ns[r], ts[k], 100 * err[k], 100 * slow[k]);
            E[r] = fmax(E[r], err[k]);
        }
    }
    const double order = log(E[0] / E[1]) / log(2.0);
    printf("couette start-up: worst error %.3f%% (10 across), %.3f%% (20 across), observed order %.2f\n", 100 * E[0],
           100 * E[1], order);
    CHECK(E[1] < E[0]);
    CHECK(order >= 1.0);
    CHECK(E[1] < 0.01);
}

/* The ladders behind the two tests above, longer:
 * scripts/validation/sph_viscosity_ladder.sh runs this case with
 * SPH_LADDER="10 20 40 80" (particles across; default "10 20", so running
 * every case stays quick). Not a meson test of its own: the two above check
 * its first rung. Prints one row per resolution and the observed order
 * between neighbours. The start-up's error must shrink from one rung to the
 * next. The steady profile's is printed only: it shrinks to 40 across and
 * then stops at about 0.3% (80 across: 0.36%, 0.28% slow), the rows sliding
 * past each other making the second moment anisotropic (M_yy 0.2% above
 * tr M / dim), which a scalar renormalisation cannot remove. */
TEST(sph_viscosity_ladder) {
    const char *env = getenv("SPH_LADDER");
    int Ns[8], nN = 0;
    for (const char *p = env ? env : "10 20"; *p && nN < 8;) {
        char *end;
        const long v = strtol(p, &end, 10);
        if (end == p) break;
        if (v >= 4 && v <= 400) Ns[nN++] = (int)v;
        p = end;
    }
    CHECK(nN >= 2);
    const double ts[] = {0.05, 0.2, 0.5};
    double Es[8], Ps[8];
    printf("%6s %12s %12s %12s %10s %12s %10s\n", "across", "start-up %", "slow(0.5) %", "order", "steady %", "steady slow %", "order");
    for (int r = 0; r < nN; r++) {
        double err[3], slow[3];
        CHECK(channel(Ns[r], 1e4, ts, 3, err, slow, 0) == 0);
        Es[r] = fmax(err[0], fmax(err[1], err[2]));
        double e = NAN, sl = NAN, one = 1.0;
        CHECK(channel(Ns[r], 1.0, &one, 1, &e, &sl, 0) == 0);
        Ps[r] = e;
        const double o1 = r ? log(Es[r - 1] / Es[r]) / log((double)Ns[r] / Ns[r - 1]) : NAN;
        const double o2 = r ? log(Ps[r - 1] / Ps[r]) / log((double)Ns[r] / Ns[r - 1]) : NAN;
        printf("%6d %12.3f %12.3f %12.2f %10.3f %12.3f %10.2f\n", Ns[r], 100 * Es[r], 100 * slow[2], o1, 100 * Ps[r],
               100 * sl, o2);
        fflush(stdout);
        if (r) CHECK(Es[r] < Es[r - 1]);
    }
}

static int slab_conduction(int N, double *err, double *rate); /* below, with its test */

/* A rung list from an environment variable ("10 20 40"), or def. */
static int ladder_env(const char *name, const char *def, int *Ns, int cap) {
    const char *env = getenv(name);
    int nN = 0;
    for (const char *p = env ? env : def; *p && nN < cap;) {
        char *end;
        const long v = strtol(p, &end, 10);
        if (end == p) break;
        if (v >= 4 && v <= 400) Ns[nN++] = (int)v;
        p = end;
    }
    return nN;
}

/* The ladders behind sph_couette_moving_lid_converges and
 * sph_heat_conduction_converges, longer: scripts/validation/sph_walls_ladder.sh
 * runs this case with SPH_LADDER (particles across the Couette layer; default
 * "10 20") and SPH_HEAT_LADDER (particles along the slab's wave; default
 * "12 24"). Not a meson test of its own: the two above check its first rungs.
 * Each error must shrink from one rung to the next. */
TEST(sph_walls_ladder) {
    int Ns[8], Hs[8];
    const int nN = ladder_env("SPH_LADDER", "10 20", Ns, 8), nH = ladder_env("SPH_HEAT_LADDER", "12 24", Hs, 8);
    CHECK(nN >= 2 && nH >= 2);
    const double ts[] = {0.05, 0.2, 0.5};
    double Es[8];
    printf("moving-lid Couette start-up (1e4 Pa s, lid 5 mm/s)\n%6s %14s %14s %14s %8s\n", "across", "worst % of U",
           "at 0.2 L^2/nu", "at 0.5 L^2/nu", "order");
    for (int r = 0; r < nN; r++) {
        double err[3], slow[3];
        CHECK(channel_lid(Ns[r], 1e4, 5e-3, ts, 3, err, slow, 0) == 0);
        Es[r] = fmax(err[0], fmax(err[1], err[2]));
        const double o = r ? log(Es[r - 1] / Es[r]) / log((double)Ns[r] / Ns[r - 1]) : NAN;
        printf("%6d %14.4f %14.4f %14.4f %8.2f\n", Ns[r], 100 * Es[r], 100 * err[1], 100 * err[2], o);
        fflush(stdout);
        if (r) CHECK(Es[r] < Es[r - 1]);
    }
    double Hh[8];
    printf("slab conduction (eq. 3.45-3.46, one e-fold)\n%6s %14s %14s %8s\n", "along", "worst % of A", "rate / D k^2",
           "order");
    for (int r = 0; r < nH; r++) {
        double rate = NAN;
        CHECK(slab_conduction(Hs[r], &Hh[r], &rate) == 0);
        const double o = r ? log(Hh[r - 1] / Hh[r]) / log((double)Hs[r] / Hs[r - 1]) : NAN;
        printf("%6d %14.4f %14.5f %8.2f\n", Hs[r], 100 * Hh[r], rate, o);
        fflush(stdout);
        if (r) CHECK(Hh[r] < Hh[r - 1]);
    }
}

/* Smallest and largest nearest-neighbour distance over a periodic 2D box
 * of size hi, in units of a (O(n^2): small blocks only). */
static void nn_range(const hearth_scene *s, const double hi[3], double a, double *dmin, double *dmax) {
    const double *x = hearth_scene_positions(s);
    const int n = hearth_scene_particle_count(s);
    *dmin = INFINITY, *dmax = 0;
    for (int i = 0; i < n; i++) {
        double best = INFINITY;
        for (int j = 0; j < n; j++) {
            if (j == i) continue;
            double dd[2];
            for (int c = 0; c < 2; c++) {
                dd[c] = x[3 * i + c] - x[3 * j + c];
                dd[c] -= hi[c] * round(dd[c] / hi[c]);
            }
            best = fmin(best, hypot(dd[0], dd[1]));
        }
        *dmin = fmin(*dmin, best / a), *dmax = fmax(*dmax, best / a);
    }
}

/* A periodic 16 x 16 block in uniform tension, 1% jitter, Tait pressure
 * kept negative (sph.tension), run for 0.15 s (about 240 sound crossings of
 * a spacing) with artificial stress epsilon:
 *   elastic = 0: Monaghan 2000's fluid case. Particles of rest volume dx^2
 *     on a lattice of spacing 1.02 dx: the summed density is 4% below rest
 *     and the Tait pressure about -0.24 B everywhere.
 *   elastic = 1: Gray, Monaghan & Swift 2001's solid case. maxwell_sph
 *     (mu_e 1e4 Pa, lambda 100 s) at its rest spacing, prestressed in
 *     uniaxial deviatoric tension S = sigma0 (n n - I/3), sigma0 = 1 kPa,
 *     n at 30 degrees to x (so the principal frame is not the axes').
 * Uniform stress is an equilibrium; the tensile instability is what moves
 * particles. Returns the nearest-neighbour distance range over the lattice
 * spacing at the end. */
static void tension_block(int elastic, double eps, double *dmin, double *dmax) {
    const int N = 16;
    const double dx = 0.002, a = (elastic ? 1.0 : 1.02) * dx, lo[3] = {0, 0, 0}, hi[3] = {N * a, N * a, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.periodic[0] = d.sph.periodic[1] = 1;
    d.sph.tension = 1;
    d.sph.artificial_stress = eps;
    *dmin = *dmax = NAN;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return;
    hearth_error err;
    int m;
    if (elastic) {
        const char *names[] = {"density", "viscosity", "mu_e", "lambda", "bulk"};
        const double vals[] = {1000, 0.1, 1e4, 100, 1e4};
        m = hearth_scene_add_material(s, "maxwell_sph", names, vals, 5, &err);
        if (m < 0) fprintf(stderr, "%s\n", err.msg);
    } else
        m = newtonian(s, 1000, 1e4, 1.0);
    uint64_t r = 42;
    for (int j = 0; j < N; j++)
        for (int i = 0; i < N; i++) {
            double p[3] = {(i + 0.5) * a, (j + 0.5) * a, 0};
            for (int c = 0; c < 2; c++) {
                r = r * 6364136223846793005ULL + 1442695040888963407ULL;
                p[c] += 0.01 * a * ((double)(r >> 11) / 9007199254740992.0 - 0.5);
            }
            if (hearth_scene_add_particles(s, m, 1, p, NULL, dx * dx, &err) != 1) fprintf(stderr, "%s\n", err.msg);
        }
    if (elastic) { /* plugin state: S xx, yy, zz, xy, yz, zx */
        const double sig0 = 1e3, c = cos(SPH_PI / 6), sn = sin(SPH_PI / 6);
        for (int i = 0; i < s->ps.n; i++) {
            double *S = pcold(&s->ps, PC_STATE) + (size_t)i * s->ps.state_stride;
            S[0] = sig0 * (c * c - 1.0 / 3), S[1] = sig0 * (sn * sn - 1.0 / 3), S[2] = -sig0 / 3;
            S[3] = sig0 * c * sn, S[4] = S[5] = 0;
        }
    }
    const double tend = getenv("SPH_AS_T") ? atof(getenv("SPH_AS_T")) : 0.15; /* longer runs for the notes below */
    for (int k = 1; k <= 5; k++) {
        if (hearth_scene_advance(s, tend * k / 5, &err)) {
            fprintf(stderr, "%s\n", err.msg);
            break;
        }
        nn_range(s, hi, a, dmin, dmax);
        printf("%s, epsilon %.2f, t = %.3f s: nearest-neighbour distance %.3f to %.3f spacings\n",
               elastic ? "elastic, deviatoric tension" : "fluid, negative pressure", eps, s->t, *dmin, *dmax);
    }
    hearth_scene_destroy(s);
}

/* A block in tension (elastic: 1, fluid: 0) without and with artificial
 * stress (epsilon 0.3, or SPH_AS_EPS): without, nearest neighbours pair up
 * (below half a spacing); with, each stays within 10% of the spacing. */
static void check_tension(int elastic) {
    double lo0, hi0, lo1, hi1;
    tension_block(elastic, 0.0, &lo0, &hi0);
    tension_block(elastic, getenv("SPH_AS_EPS") ? atof(getenv("SPH_AS_EPS")) : 0.3, &lo1, &hi1);
    CHECK(lo0 < 0.5);
    CHECK(lo1 > 0.9 && hi1 < 1.1);
}

/* Artificial stress (Monaghan 2000, sph.c): without it the stretched fluid
 * (1 Pa s) pairs up (nearest neighbours at 0.45 spacings within 0.03 s,
 * measured); with epsilon = 0.3 every nearest neighbour stays within 10% of
 * the spacing (measured 0.97 to 1.03). Longer (SPH_AS_T=1): at epsilon 0.3
 * it creeps, 0.68 by 1 s; epsilon 0.5 stays within 0.94 to 1.07. */
TEST(sph_artificial_stress_fluid) { check_tension(0); }

/* The same for an elastic solid (0.1 Pa s) in deviatoric tension along a
 * tilted axis (Gray et al. 2001): without artificial stress nearest
 * neighbours come to 0.2 to 0.35 spacings (measured); with epsilon = 0.3
 * within 10% (measured 0.99 to 1.01; to 1 s, 0.90 to 1.03). */
TEST(sph_artificial_stress_elastic) { check_tension(1); }

/* The oven's Robin flux reaches SPH particles (sph.c): a 40 x 20 mm block
 * (1 mm particles, no gravity, no conduction, no eq. 3.42) at 26 degC in a
 * 180 degC oven with beta = 50 W/(m^2 K) takes in heat at beta P (T_oven - T)
 * with P its perimeter (per metre of depth in 2D), within 5% (measured 3.4%
 * short: the four corners), over 20 steps (the temperature barely moves, so
 * the rate is the initial one). With beta = 0 it takes in none; on a tray
 * at 180 degC with contact beta 50 (oven beta 0) it takes in beta W
 * (T_tray - T) through its 40 mm bottom W, within 5%. */
TEST(sph_oven_robin) {
    for (int k = 0; k < 3; k++) {
        const double dx = 0.001, lo[3] = {0, 0, 0}, hi[3] = {0.08, 0.06, 0}, beta = k == 1 ? 50.0 : 0.0, cp = 2500;
        hearth_scene_def d = sph_def(2, dx, lo, hi);
        d.gravity[1] = 0;
        d.oven_temperature = 180;
        d.oven_beta = beta;
        hearth_scene *s = hearth_scene_create(&d, NULL);
        CHECK(s != NULL);
        if (!s) return;
        const char *n[] = {"density", "bulk", "viscosity", "specific_heat"};
        const double v[] = {1000, 1e4, 1.0, cp};
        hearth_error err;
        int m = hearth_scene_add_material(s, "newtonian", n, v, 4, &err);
        CHECK(m >= 0);
        CHECK(box_body(s, m, 0.02, 0.02, 0.06, 0.04, 0, 26) >= 0);
        if (k == 2) { /* the tray under the block */
            double pt[3] = {0, 0.02, 0}, nrm[3] = {0, 1, 0};
            hearth_collider_def cd = hearth_default_collider_def();
            cd.shape = hearth_shape_plane(pt, nrm);
            cd.mode = HEARTH_SLIP;
            cd.temperature = 180;
            cd.beta = 50;
            CHECK(hearth_scene_add_collider(s, &cd, &err) >= 0);
            hearth_shape_free((hearth_shape *)cd.shape);
        }
        const double *T = pcold(&s->ps, PC_TEMPERATURE), *mass = pcold(&s->ps, PC_MASS);
        double E0 = 0, E1 = 0;
        for (int i = 0; i < s->ps.n; i++) E0 += mass[i] * cp * T[i];
        CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
        T = pcold(&s->ps, PC_TEMPERATURE), mass = pcold(&s->ps, PC_MASS);
        for (int i = 0; i < s->ps.n; i++) E1 += mass[i] * cp * T[i];
        const double want = (k == 1 ? beta * 2 * (0.04 + 0.02) : k == 2 ? 50 * 0.04 : 0.0) * (180 - 26) * s->t;
        const char *what = k == 0 ? "oven beta 0" : k == 1 ? "oven beta 50" : "tray beta 50";
        printf("%s: heat in %.4g J over %.3g s, expected %.4g J\n", what, E1 - E0, s->t, want);
        if (k)
            CHECK(fabs((E1 - E0) - want) <= 0.05 * want);
        else
            CHECK(E1 - E0 == 0);
        hearth_scene_destroy(s);
    }
}

/* A paddle of fixed particles (hearth_scene_body_motion) sweeps through a
 * pool at 0.1 m/s (1% of the sound speed) for 2 cm, 5 spacings: no fluid
 * particle passes through it. Each fluid particle that started ahead of the
 * paddle (right of its front face) is still ahead at the end, and none lies
 * inside the paddle's three layers; the paddle kept its shape. */
TEST(sph_moving_lid_holds_fluid) {
    const double dx = 0.004, lo[3] = {0, 0, 0}, hi[3] = {0.24, 0.1, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    hearth_scene *s = hearth_scene_create(&d, NULL);
    CHECK(s != NULL);
    if (!s) return;
    const int m = newtonian(s, 1000, 1e5, 1.0);
    CHECK(box_body(s, m, 0, 0, hi[0], 3 * dx, 1, NAN) >= 0); /* floor */
    const double px0 = 0.06, px1 = px0 + 3 * dx;
    const int paddle = box_body(s, m, px0, 3 * dx, px1, 0.09, 1, NAN);
    CHECK(paddle >= 0);
    CHECK(box_body(s, m, 0, 3 * dx, px0, 0.05, 0, NAN) >= 0);
    CHECK(box_body(s, m, px1, 3 * dx, hi[0], 0.05, 0, NAN) >= 0);
    const double U[3] = {0.1, 0, 0};
    hearth_error err;
    CHECK(hearth_scene_body_motion(s, paddle, U, NULL, NULL, NULL, NULL, &err) == HEARTH_OK);
    const int n = hearth_scene_particle_count(s);
    int *ahead = calloc((size_t)n, sizeof *ahead);
    CHECK(ahead != NULL);
    if (!ahead) return;
    const double *x = hearth_scene_positions(s);
    const int *id = pcoli(&s->ps, PC_ID), *flags = pcoli(&s->ps, PC_FLAGS);
    for (int i = 0; i < n; i++) ahead[id[i]] = !(flags[i] & PF_FIXED) && x[3 * i] > px1;
    CHECK(hearth_scene_advance(s, 0.2, &err) == HEARTH_OK);
    x = hearth_scene_positions(s);
    id = pcoli(&s->ps, PC_ID), flags = pcoli(&s->ps, PC_FLAGS);
    const int *body = pcoli(&s->ps, PC_BODY);
    double pmin = INFINITY, pmax = -INFINITY;
    for (int i = 0; i < n; i++)
        if (body[i] == paddle) pmin = fmin(pmin, x[3 * i]), pmax = fmax(pmax, x[3 * i]);
    int behind = 0, inside = 0, nahead = 0;
    double worst = INFINITY;
    for (int i = 0; i < n; i++) {
        if (flags[i] & PF_FIXED) continue;
        const double xi = x[3 * i], yi = x[3 * i + 1];
        if (ahead[id[i]]) {
            nahead++;
            behind += xi < pmax + 0.5 * dx;
            worst = fmin(worst, xi - pmax);
        }
        inside += yi > 3 * dx && yi < 0.09 && xi > pmin - 0.25 * dx && xi < pmax + 0.25 * dx;
    }
    hearth_stats st;
    hearth_scene_stats(s, &st);
    printf("paddle moved %.4f m (want %.4f), width %.6f m (want %.6f); %d fluid particles ahead, %d fell behind its "
           "face, %d inside it; closest ahead %.3f spacings from its last layer; guard %d\n",
           pmin - (px0 + 0.5 * dx), 0.1 * s->t, pmax - pmin, 2 * dx, nahead, behind, inside, worst / dx, st.guard);
    CHECK_NEAR(pmin - (px0 + 0.5 * dx), 0.1 * s->t, 1e-9);
    CHECK_NEAR(pmax - pmin, 2 * dx, 1e-12);
    CHECK(nahead > 100);
    CHECK(behind == 0);
    CHECK(inside == 0);
    free(ahead);
    hearth_scene_destroy(s);
}

/* One run of sph_wall_motion_rigid's wheel: with cfl 4 and the rollback
 * policy every step is first refused by the guard (CFL) and retried at half
 * dt, so the pivot's move of a refused step must be dropped. Returns the
 * rollbacks, or -1 when a check failed. */
static int spin_wheel(double cfl, int check_errors) {
    const double lo[3] = {0, 0, 0}, hi[3] = {0.2, 0.2, 0}, dx = 0.005;
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.cfl = cfl;
    d.guard = HEARTH_GUARD_ROLLBACK;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return -1;
    const int m = newtonian(s, 1000, 1e4, 0.1);
    const double c0[3] = {0.1, 0.1, 0};
    hearth_shape *disc = hearth_shape_sphere(c0, 0.03);
    hearth_body_def bd = hearth_default_body_def();
    bd.shape = disc, bd.material = m, bd.ppc = 1, bd.jitter = 0, bd.fixed = 1;
    hearth_error err;
    const int wheel = hearth_scene_add_body(s, &bd, &err);
    hearth_shape_free(disc);
    const int free_body = box_body(s, m, 0.01, 0.01, 0.04, 0.04, 0, NAN);
    int ok = wheel >= 0 && free_body >= 0;
    const double V[3] = {0.02, -0.01, 0}, W[3] = {0, 0, 3.0}, bad[3] = {NAN, 0, 0};
    if (check_errors) {
        ok = ok && hearth_scene_body_motion(s, free_body, V, NULL, NULL, NULL, NULL, &err) == HEARTH_ERR_PARAM;
        printf("free body: %s\n", err.msg);
        ok = ok && strstr(err.msg, "not fixed") != NULL;
        ok = ok && hearth_scene_body_motion(s, 7, V, NULL, NULL, NULL, NULL, &err) == HEARTH_ERR_PARAM;
        ok = ok && strstr(err.msg, "does not exist") != NULL;
        ok = ok && hearth_scene_body_motion(s, wheel, bad, NULL, NULL, NULL, NULL, &err) == HEARTH_ERR_PARAM;
        ok = ok && strstr(err.msg, "velocity") != NULL;
    }
    ok = ok && hearth_scene_body_motion(s, wheel, V, W, c0, NULL, NULL, &err) == HEARTH_OK;
    const int n = hearth_scene_particle_count(s);
    const double *x = hearth_scene_positions(s);
    const int *body = pcoli(&s->ps, PC_BODY);
    double r0 = 0;
    for (int i = 0; i < n; i++)
        if (body[i] == wheel) r0 += hypot(x[3 * i] - c0[0], x[3 * i + 1] - c0[1]);
    ok = ok && hearth_scene_step(s, 40, &err) == HEARTH_OK;
    x = hearth_scene_positions(s);
    body = pcoli(&s->ps, PC_BODY);
    const double c1[2] = {c0[0] + V[0] * s->t, c0[1] + V[1] * s->t};
    double r1 = 0, xs = 0;
    int k = 0;
    for (int i = 0; i < n; i++)
        if (body[i] == wheel) r1 += hypot(x[3 * i] - c1[0], x[3 * i + 1] - c1[1]), xs += x[3 * i], k++;
    hearth_stats st;
    hearth_scene_stats(s, &st);
    printf("spinning wheel, cfl %g: mean radius %.12f -> %.12f m, centre x %.9f (want %.9f) after %.4f s, %d rollbacks\n",
           cfl, r0 / k, r1 / k, xs / k, c1[0], s->t, st.rollbacks);
    ok = ok && fabs(r1 / k - r0 / k) < 1e-12 && fabs(xs / k - c1[0]) < 1e-9;
    hearth_scene_destroy(s);
    return ok ? st.rollbacks : -1;
}

/* A fixed body's motion: a disc spun about its centre while its centre
 * translates keeps every particle's distance to the moving centre (the
 * rigid motion is exact), also when the guard rolls steps back (cfl 4);
 * the API refuses a free body, a missing body, non-finite values and the
 * MPM solver, each with a message naming it. */
TEST(sph_wall_motion_rigid) {
    CHECK(spin_wheel(0.3, 1) == 0);
    CHECK(spin_wheel(4.0, 0) > 0);
    const double V[3] = {0.02, -0.01, 0};
    hearth_error err;
    hearth_scene_def dm = hearth_default_scene_def();
    dm.dim = 2;
    hearth_scene *mp = hearth_scene_create(&dm, NULL);
    CHECK(mp != NULL);
    if (!mp) return;
    CHECK(hearth_scene_body_motion(mp, 0, V, NULL, NULL, NULL, NULL, &err) == HEARTH_ERR_PARAM);
    printf("MPM: %s\n", err.msg);
    CHECK(strstr(err.msg, "collider") != NULL);
    hearth_scene_destroy(mp);
}

/* Collider response (eq. 3.31-3.33): a particle hitting a plane keeps beta_c
 * of its tangential velocity and leaves with alpha_c of its normal speed. */
TEST(sph_collider_response) {
    const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 0};
    hearth_scene_def d = sph_def(2, 0.01, lo, hi);
    d.gravity[1] = 0;
    d.sph.alpha_c = 0.5;
    d.sph.beta_c = 0.8;
    d.dt_max = 1e-3;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    CHECK(s != NULL);
    if (!s) return;
    int m = newtonian(s, 1000, 1e4, 0);
    double x0[3] = {0.5, 0.3005, 0}, v0[3] = {0.2, -1.0, 0};
    hearth_error err;
    CHECK(hearth_scene_add_particles(s, m, 1, x0, v0, 1e-4, &err) == 1);
    hearth_collider_def cd = hearth_default_collider_def();
    double p[3] = {0, 0.3, 0}, nrm[3] = {0, 1, 0};
    cd.shape = hearth_shape_plane(p, nrm);
    cd.mode = HEARTH_SLIP;
    CHECK(hearth_scene_add_collider(s, &cd, &err) >= 0);
    hearth_shape_free((hearth_shape *)cd.shape);
    CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
    const double *v = pcold(&s->ps, PC_V), *x = hearth_scene_positions(s);
    printf("after contact: x = (%.6f, %.6f), v = (%.6f, %.6f)\n", x[0], x[1], v[0], v[1]);
    CHECK_NEAR(x[1], 0.3, 1e-12);
    CHECK_NEAR(v[0], 0.8 * 0.2, 1e-12);
    CHECK_NEAR(v[1], 0.5 * 1.0, 1e-12);
    hearth_scene_destroy(s);
}

/* The channel of `poiseuille` between two sticky plane colliders instead of
 * fixed-particle walls (no particles beyond y = 0 and y = L; 20 across,
 * periodic in x, 1 Pa s, at L^2 / nu): a no-slip collider is a wall in eq.
 * 3.19 (sph_collider_drag, sph_walls.c), so the steady parabola must hold to
 * the fixed walls' bar, 3% of the peak (bar set before the first run; the
 * walls' own channel measured 0.58%). Before, a sticky collider stopped only
 * particles that crossed it, and the body force slid the whole layer along.
 * Measured 3.00% (4.88% with the summed density in the wall term): an
 * expected failure, the cause printed. */
TEST(sph_sticky_collider_channel) {
    const int N = 20;
    const double L = 0.02, dx = L / N, lo[3] = {0, 0, 0}, hi[3] = {12 * dx, L, 0}, eta = 1.0, rho = 1000;
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.periodic[0] = 1;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    CHECK(s != NULL);
    if (!s) return;
    double f = 0.1 * eta;
    const int m = newtonian(s, rho, 1e3, eta);
    CHECK(box_body(s, m, 0, 0, hi[0], L, 0, NAN) >= 0);
    hearth_scene_set_body_force(s, push_x, &f);
    hearth_error e;
    for (int k = 0; k < 2; k++) {
        hearth_collider_def cd = hearth_default_collider_def();
        double p[3] = {0, k ? L : 0, 0}, nrm[3] = {0, k ? -1 : 1, 0};
        cd.shape = hearth_shape_plane(p, nrm);
        cd.mode = HEARTH_STICKY;
        CHECK(hearth_scene_add_collider(s, &cd, &e) >= 0);
        hearth_shape_free((hearth_shape *)cd.shape);
    }
    const double nu = eta / rho;
    CHECK(hearth_scene_advance(s, L * L / nu, &e) == HEARTH_OK);
    const double *x = hearth_scene_positions(s), *v = pcold(&s->ps, PC_V);
    const double peak = startup_series(f, nu, L, 0.5 * L, s->t);
    double worst = 0;
    for (int i = 0; i < hearth_scene_particle_count(s); i++)
    {
        worst = fmax(worst, fabs(v[3 * i] - startup_series(f, nu, L, x[3 * i + 1], s->t)));
        if (getenv("SPH_DEBUG") && x[3 * i] < dx)
            printf("y %.5f u %.5g want %.5g\n", x[3 * i + 1], v[3 * i], startup_series(f, nu, L, x[3 * i + 1], s->t));
    }
    printf("channel between sticky colliders, %d across: worst |u - u_exact| = %.2f%% of the peak (%.4g m/s)\n", N,
           100 * worst / peak, peak);
    CHECK(isfinite(worst));
    if (!(worst / peak < 0.03))
        XFAIL("the channel between sticky colliders is %.2f%% off its parabola (bar 3%%, the fixed walls' 0.58%%): the "
              "first row runs 7%% fast and the second 10%% slow; a collider fills neither eq. 3.13's density sum nor "
              "the fluid pairs' neighbourhood that fixed wall particles fill, so the two rows nearest it see a "
              "truncated kernel (sph_collider_drag adds only eq. 3.19's wall term). 4.88%% with the virtual wall's "
              "term over the row's summed density rather than its rest density",
              100 * worst / peak);
    hearth_scene_destroy(s);
}

/* Internal heat (eq. 3.45-3.46) in a pinned block, hot left half: the
 * pairwise form conserves sum m T exactly and the halves approach each other. */
TEST(sph_heat_internal_conserves) {
    const double lo[3] = {0, 0, 0}, hi[3] = {0.1, 0.1, 0};
    hearth_scene_def d = sph_def(2, 0.005, lo, hi);
    d.sph.heat_int = 0.5;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    CHECK(s != NULL);
    if (!s) return;
    int m = newtonian(s, 1000, 1e4, 0);
    CHECK(box_body(s, m, 0.02, 0.02, 0.05, 0.08, 1, 80) >= 0);
    CHECK(box_body(s, m, 0.05, 0.02, 0.08, 0.08, 1, 20) >= 0);
    const int n = s->ps.n;
    double E0 = 0, dT0 = 0, E1 = 0;
    const double *mass = pcold(&s->ps, PC_MASS);
    for (int i = 0; i < n; i++) E0 += mass[i] * pcold(&s->ps, PC_TEMPERATURE)[i];
    hearth_error err;
    CHECK(hearth_scene_step(s, 200, &err) == HEARTH_OK);
    const double *T = pcold(&s->ps, PC_TEMPERATURE), *x = hearth_scene_positions(s);
    double hot = 0, cold = 0;
    int nh = 0, nc = 0;
    for (int i = 0; i < n; i++) {
        E1 += mass[i] * T[i];
        if (x[3 * i] < 0.05) hot += T[i], nh++;
        else cold += T[i], nc++;
    }
    dT0 = 60;
    printf("heat: sum m T %.15g -> %.15g; halves %.3f and %.3f degC\n", E0, E1, hot / nh, cold / nc);
    CHECK_NEAR(E1, E0, 1e-12 * E0);
    CHECK(hot / nh - cold / nc < 0.9 * dT0 && hot / nh > cold / nc);
    hearth_scene_destroy(s);
}

/* Slab conduction by eq. 3.45-3.46 on a resting lattice: a pinned block,
 * periodic along both axes (L = 0.1 m long, 8 particles deep, N particles
 * along x), starts at T = 50 + 30 cos(2 pi x / L) degC. With D = heat_int /
 * rho the series is one term: the amplitude decays as exp(-D k^2 t). At
 * t = 1 / (D k^2) (one e-fold) err is the worst |T - T_series| over the
 * particles as a fraction of the initial amplitude and rate the decay rate
 * of the fitted amplitude over D k^2 (1 exact). dt is held at 0.01 h^2 / D
 * (a tenth of the heat limit), so explicit Euler's own error, second order
 * too, stays below 0.3%. Returns 0, or -1 when a step failed. */
static int slab_conduction(int N, double *err, double *rate) {
    const double L = 0.1, dx = L / N, lo[3] = {0, 0, 0}, hi[3] = {L, 8 * dx, 0}, rho = 1000, D = 1e-2;
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.periodic[0] = d.sph.periodic[1] = 1;
    d.sph.heat_int = D * rho;
    d.dt_max = 0.01 * (d.sph.h_factor * dx) * (d.sph.h_factor * dx) / D;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return -1;
    const int m = newtonian(s, rho, 1e4, 0);
    int rc = box_body(s, m, 0, 0, hi[0], hi[1], 1, 50) >= 0 ? 0 : -1;
    const double k = 2 * SPH_PI / L, A = 30, t = 1 / (D * k * k);
    const int n = hearth_scene_particle_count(s);
    const double *x = hearth_scene_positions(s);
    double *T = pcold(&s->ps, PC_TEMPERATURE);
    for (int i = 0; i < n && !rc; i++) T[i] = 50 + A * cos(k * x[3 * i]);
    hearth_error e;
    if (!rc && hearth_scene_advance(s, t, &e)) {
        fprintf(stderr, "%s\n", e.msg);
        rc = -1;
    }
    x = hearth_scene_positions(s);
    T = pcold(&s->ps, PC_TEMPERATURE);
    const double want = A * exp(-D * k * k * s->t);
    double worst = 0, sc = 0, cc = 0;
    for (int i = 0; i < n && !rc; i++) {
        const double cs = cos(k * x[3 * i]);
        if (!isfinite(T[i])) rc = -1;
        worst = fmax(worst, fabs(T[i] - 50 - want * cs));
        sc += (T[i] - 50) * cs, cc += cs * cs;
    }
    *err = worst / A;
    *rate = log(A / (sc / cc)) / (D * k * k * s->t);
    hearth_scene_destroy(s);
    return rc;
}

/* The slab of slab_conduction converges to its series at 20, 40 and 80
 * particles along the wave: the worst error shrinks at an observed order of
 * at least 1 at each step and the decay rate comes within 1% of D k^2. */
TEST(sph_heat_conduction_converges) {
    const int Ns[] = {12, 24, 48};
    double E[3], R[3];
    for (int r = 0; r < 3; r++) {
        CHECK(slab_conduction(Ns[r], &E[r], &R[r]) == 0);
        printf("slab conduction, %d along: worst error %.3f%% of the amplitude, decay rate %.4f of D k^2\n", Ns[r],
               100 * E[r], R[r]);
    }
    for (int r = 1; r < 3; r++) {
        const double order = log(E[r - 1] / E[r]) / log(2.0);
        printf("slab conduction: %d -> %d along, observed order %.2f\n", Ns[r - 1], Ns[r], order);
        CHECK(order >= 1.0);
    }
    CHECK(fabs(R[2] - 1) < 0.01);
}

/* A square drop, result of one surface-tension run: the farthest particle
 * from the centroid over the square's half-diagonal, and the polar second
 * moment of area over the square's (a^2/6 per unit area). */
static int square_drop(double sigma, double *rmax_rel, double *J_rel) {
    const double dx = 0.003, a = 0.06, lo[3] = {0, 0, 0}, hi[3] = {0.2, 0.2, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[0] = d.gravity[1] = d.gravity[2] = 0;
    d.sph.surface_tension = sigma;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return -1;
    int m = newtonian(s, 1000, 1e4, 0.5);
    if (m < 0 || box_body(s, m, 0.1 - a / 2, 0.1 - a / 2, 0.1 + a / 2, 0.1 + a / 2, 0, NAN) < 0) {
        hearth_scene_destroy(s);
        return -1;
    }
    hearth_error err;
    if (hearth_scene_advance(s, 1.2, &err)) {
        fprintf(stderr, "%s\n", err.msg);
        hearth_scene_destroy(s);
        return -1;
    }
    const int n = hearth_scene_particle_count(s);
    const double *x = hearth_scene_positions(s);
    double cx = 0, cy = 0;
    for (int i = 0; i < n; i++) cx += x[3 * i] / n, cy += x[3 * i + 1] / n;
    double rmax = 0, J = 0;
    for (int i = 0; i < n; i++) {
        const double r2 = (x[3 * i] - cx) * (x[3 * i] - cx) + (x[3 * i + 1] - cy) * (x[3 * i + 1] - cy);
        J += r2 / n;
        if (r2 > rmax) rmax = r2;
    }
    /* the lattice's own: particles at cell centres, half a spacing in from the edges */
    const double ai = a - dx;
    *rmax_rel = sqrt(rmax) / (ai / sqrt(2.0));
    *J_rel = J / (a * a / 6);
    hearth_scene_destroy(s);
    return 0;
}

/* Surface tension (colour field, eq. 3.28-3.30): a square drop without
 * gravity rounds up. Its corners come in toward the circle of the same area
 * (radius a / sqrt(pi), 0.80 of the half-diagonal) and its second moment of
 * area falls toward the circle's (6 / (2 pi) = 0.955 of the square's). The
 * same drop without surface tension keeps its corners. 0.06 m of water-like
 * fluid (1000 kg/m^3, 0.5 Pa s, c = 3.2 m/s), 400 particles, 1.2 s.
 * sigma is small on purpose: from about 0.02 N/m on, the corner particles,
 * pulled by eq. 3.30 alone (the force acts on surface particles only), shoot
 * past the circle and the drop does not settle (0.05 N/m: farthest particle
 * 0.90-0.95 and wandering; 2 N/m: the drop flies apart). */
TEST(sph_surface_tension_rounds_drop) {
    double r0 = 0, J0 = 0, r1 = 0, J1 = 0;
    CHECK(square_drop(0, &r0, &J0) == 0);
    CHECK(square_drop(0.005, &r1, &J1) == 0);
    printf("square drop after 1.2 s: without tension farthest particle %.3f of the half-diagonal, second moment %.4f "
           "of the square's; with sigma = 0.005 N/m %.3f and %.4f (circle: 0.798 and 0.955)\n",
           r0, J0, r1, J1);
    CHECK(r0 > 0.97 && J0 > 0.97);
    CHECK(r1 < 0.90);      /* corners pulled at least half-way toward the circle */
    CHECK(r1 > 0.70);      /* not collapsed */
    CHECK(J1 < J0 - 0.02); /* the whole drop rounder, not just its corner particles */
}

TEST_MAIN(T(sph_poiseuille), T(sph_wall_drag_stable), T(sph_creeping_startup_converges), T(sph_poiseuille_converges), T(sph_couette_moving_lid_converges), T(sph_viscosity_ladder), T(sph_walls_ladder), T(sph_artificial_stress_fluid), T(sph_artificial_stress_elastic), T(sph_oven_robin), T(sph_moving_lid_holds_fluid), T(sph_wall_motion_rigid), T(sph_collider_response), T(sph_sticky_collider_channel), T(sph_heat_internal_conserves), T(sph_heat_conduction_converges), T(sph_surface_tension_rounds_drop))
