/* unit_sph_gradient.c: the velocity gradient that integrates F (eq. 3.27 of
 * Rodriguez-Arenas 2011, core/sim/solver/sph_kinematics.c) with and without
 * sph.corrected_gradient, Bonet & Lok's (1999) kernel-gradient correction.
 * A linear velocity field v = A x has the gradient A everywhere; the plain
 * sum reads A K, K the kernel's first moment, which is about half the
 * identity at a free surface; the corrected one reads A to round-off, at the
 * surface too. The vector loops give the general loops' bits with it on. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "hearth/hearth.h"
#include "particles.h"
#include "scene.h"
#include "sph.h"
#include "sph_fixture.h"
#include "sph_neighbours.h"
#include "sph_state.h"
#include "test.h"

/* A block of newtonian liquid (jittered by half a spacing) without gravity,
 * given v = A (x - c) and stepped once: the largest |L - A| / |A| (Frobenius)
 * over the particles sph_kinematics flags as surface, and over the rest. */
static int linear_field(int dim, int corrected, double *err_surf, double *err_in, int *nsurf) {
    const double dx = dim == 2 ? 0.002 : 0.004, lo[3] = {0, 0, 0}, hi[3] = {0.1, 0.08, dim == 2 ? 0 : 0.08};
    const double A[9] = {3, 1, 0.5, -2, -1, 0.25, 0.75, -0.5, 1.5}; /* 1/s; 2D reads its upper-left 2 x 2 */
    double nA = 0;
    for (int a = 0; a < dim; a++)
        for (int b = 0; b < dim; b++) nA += A[3 * a + b] * A[3 * a + b];
    nA = sqrt(nA);
    hearth_scene_def d = sph_def(dim, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.corrected_gradient = corrected;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return 0;
    int ok = 0;
    const int m = newtonian(s, 1000, 1e5, 1.0);
    const double c[3] = {0.05, 0.04, dim == 2 ? 0 : 0.04}, hh[3] = {0.02, 0.015, dim == 2 ? 0.5 : 0.015};
    hearth_shape *bx = hearth_shape_box(c, hh);
    hearth_body_def bd = hearth_default_body_def();
    bd.shape = bx, bd.material = m, bd.ppc = 1, bd.jitter = 0.5;
    hearth_error err;
    if (m >= 0 && hearth_scene_add_body(s, &bd, &err) >= 0) {
        double *v = pcold(&s->ps, PC_V);
        const double *x = pcold(&s->ps, PC_X);
        for (int i = 0; i < s->ps.n; i++)
            for (int a = 0; a < dim; a++) {
                v[3 * i + a] = 0;
                for (int b = 0; b < dim; b++) v[3 * i + a] += A[3 * a + b] * (x[3 * i + b] - c[b]);
            }
        /* one step: C holds the gradient of the velocities it started from (no predrift without leapfrog) */
        if (hearth_scene_step(s, 1, &err) == HEARTH_OK) {
            const struct sph_state *st = s->sph;
            *err_surf = *err_in = 0;
            *nsurf = 0;
            for (int i = 0; i < s->ps.n; i++) {
                double L[9], e = 0;
                particles_C3(&s->ps, i, L);
                for (int a = 0; a < dim; a++)
                    for (int b = 0; b < dim; b++) e += (L[3 * a + b] - A[3 * a + b]) * (L[3 * a + b] - A[3 * a + b]);
                e = sqrt(e) / nA;
                if (st->surf[i]) *err_surf = fmax(*err_surf, e), ++*nsurf;
                else *err_in = fmax(*err_in, e);
            }
            ok = 1;
        } else fprintf(stderr, "%s\n", err.msg);
    } else fprintf(stderr, "%s\n", err.msg);
    hearth_shape_free(bx);
    hearth_scene_destroy(s);
    return ok;
}

TEST(sph_corrected_gradient_exact_for_linear_field) {
    for (int dim = 2; dim <= 3; dim++) {
        double sp, ip, sc, ic;
        int ns, ns2;
        const int ok = linear_field(dim, 0, &sp, &ip, &ns) && linear_field(dim, 1, &sc, &ic, &ns2);
        CHECK(ok);
        if (!ok) return;
        printf("%dD, %d surface particles: largest |L - A| / |A| plain %.3g (surface), %.3g (inside); corrected %.3g, %.3g\n",
               dim, ns, sp, ip, sc, ic);
        CHECK(ns > 0 && ns == ns2);
        CHECK(sp > 0.2);                /* the plain sum misses the empty half of the kernel */
        CHECK(sc < 1e-9 && ic < 1e-9); /* the corrected one is exact for a linear field */
    }
}

/* sph_fast_paths_same_bits (unit_sph.c) with the correction on: the 2D and
 * 3D vector loops sum K term for term as the general loop does. */
TEST(sph_corrected_gradient_fast_paths_same_bits) {
    for (int dim = 2; dim <= 3; dim++) {
        uint64_t hsh[2];
        for (int k = 0; k < 2; k++) {
            sph_fast_paths = 1 - k;
            const double dx = dim == 2 ? 0.004 : 0.01, lo[3] = {0, 0, 0}, hi[3] = {0.2, 0.2, dim == 2 ? 0 : 0.2};
            hearth_scene_def d = sph_def(dim, dx, lo, hi);
            d.sph.xsph0 = 0.1;
            d.sph.av_beta = 1;
            d.sph.corrected_gradient = 1;
            hearth_scene *s = hearth_scene_create(&d, NULL);
            const char *n[] = {"density", "viscosity", "mu_e", "bulk"};
            const double v[] = {1000, 0.5, 100, 1e4};
            hearth_error err;
            int m = hearth_scene_add_material(s, "maxwell_sph", n, v, 4, &err);
            double c[3] = {0.1, 0.06, dim == 2 ? 0 : 0.1}, hh[3] = {0.05, 0.05, dim == 2 ? 0.5 : 0.05};
            hearth_shape *bx = hearth_shape_box(c, hh);
            hearth_body_def bd = hearth_default_body_def();
            bd.shape = bx, bd.material = m, bd.ppc = 1, bd.jitter = 0.5;
            CHECK(hearth_scene_add_body(s, &bd, &err) >= 0);
            hearth_shape_free(bx);
            CHECK(hearth_scene_step(s, dim == 2 ? 20 : 10, &err) == HEARTH_OK);
            hsh[k] = hearth_scene_hash(s);
            hearth_scene_destroy(s);
        }
        sph_fast_paths = 1;
        printf("%dD: hash with the one-h loops %016llx, general loops %016llx\n", dim, (unsigned long long)hsh[0],
               (unsigned long long)hsh[1]);
        CHECK(hsh[0] == hsh[1]);
    }
}

TEST_MAIN(T(sph_corrected_gradient_exact_for_linear_field), T(sph_corrected_gradient_fast_paths_same_bits))
