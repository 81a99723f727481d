/* unit_colliders.c: shapes (SDFs, normals, bounds, ownership), moving
 * colliders and the grid contact rule. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "alloc.h"
#include "colliders.h"
#include "tensor.h"
#include "hearth/hearth.h"
#include "test.h"

#define PI 3.14159265358979323846

static double sdf_at(const hearth_shape *s, double x, double y, double z) {
    double p[3] = {x, y, z};
    return hearth_shape_sdf(s, p, NULL);
}

TEST(shape_sdf_primitives) {
    size_t base = hearth_bytes_allocated();
    /* plane: the normal is normalised */
    hearth_shape *pl = hearth_shape_plane((double[]){0, 1, 0}, (double[]){0, 2, 0});
    CHECK(pl);
    CHECK_NEAR(sdf_at(pl, 5, 3, 7), 2.0, 1e-15);
    CHECK_NEAR(sdf_at(pl, 0, 0.5, 0), -0.5, 1e-15);
    CHECK_NEAR(sdf_at(pl, -4, 1, 9), 0.0, 1e-15);
    CHECK(!hearth_shape_plane((double[]){0, 0, 0}, (double[]){0, 0, 0}));

    /* box: faces, edges, corners, inside */
    hearth_shape *bx = hearth_shape_box((double[]){1, 2, 3}, (double[]){1, 2, 3});
    CHECK_NEAR(sdf_at(bx, 1, 2, 3), -1.0, 1e-15);
    CHECK_NEAR(sdf_at(bx, 1.5, 2, 3), -0.5, 1e-15);
    CHECK_NEAR(sdf_at(bx, 2, 2, 3), 0.0, 1e-15);
    CHECK_NEAR(sdf_at(bx, 3, 2, 3), 1.0, 1e-15);
    CHECK_NEAR(sdf_at(bx, 3, 5, 3), sqrt(2.0), 1e-15);
    CHECK_NEAR(sdf_at(bx, 3, 5, 7), sqrt(3.0), 1e-15);
    CHECK(!hearth_shape_box((double[]){0, 0, 0}, (double[]){1, -1, 1}));
    /* a 2D box (half z = 0) is a rectangle at z = 0: its z extent is ignored */
    hearth_shape *rc = hearth_shape_box((double[]){0, 0, 0}, (double[]){1, 0.5, 0});
    CHECK_NEAR(sdf_at(rc, 0, 0, 0), -0.5, 1e-15);
    CHECK_NEAR(sdf_at(rc, 0.9, 0.1, 0), -0.1, 1e-15);
    CHECK_NEAR(sdf_at(rc, 2, 0, 0), 1.0, 1e-15);
    CHECK_NEAR(sdf_at(rc, 4, 4.5, 0), 5.0, 1e-15);

    /* sphere, and the same sphere as a disc at z = 0 */
    hearth_shape *sp = hearth_shape_sphere((double[]){1, 0, 0}, 2);
    CHECK_NEAR(sdf_at(sp, 1, 0, 0), -2.0, 1e-15);
    CHECK_NEAR(sdf_at(sp, 4, 0, 0), 1.0, 1e-15);
    CHECK_NEAR(sdf_at(sp, 1, 2, 0), 0.0, 1e-15);
    CHECK_NEAR(sdf_at(sp, 1, 3, 4), 3.0, 1e-15);
    CHECK(!hearth_shape_sphere((double[]){0, 0, 0}, 0));
    CHECK(!hearth_shape_sphere((double[]){0, 0, 0}, -1));
    hearth_shape *disc = hearth_shape_sphere((double[]){0.5, 0.5, 0}, 0.2);
    CHECK_NEAR(sdf_at(disc, 0.8, 0.9, 0), 0.3, 1e-15);
    CHECK_NEAR(sdf_at(disc, 0.5, 0.4, 0), -0.1, 1e-15);

    /* capped cylinder along z (axis given unnormalised) */
    hearth_shape *cy = hearth_shape_cylinder((double[]){0, 0, 0}, (double[]){0, 0, 3}, 1, 2);
    CHECK_NEAR(sdf_at(cy, 0, 0, 0), -1.0, 1e-15);
    CHECK_NEAR(sdf_at(cy, 0, 0, 1.5), -0.5, 1e-15);
    CHECK_NEAR(sdf_at(cy, 0.6, 0.8, 0), 0.0, 1e-15);
    CHECK_NEAR(sdf_at(cy, 2, 0, 0), 1.0, 1e-15);
    CHECK_NEAR(sdf_at(cy, 0, 0, 3), 1.0, 1e-15);
    CHECK_NEAR(sdf_at(cy, 0, 2, 3), sqrt(2.0), 1e-15);
    CHECK(!hearth_shape_cylinder((double[]){0, 0, 0}, (double[]){0, 0, 0}, 1, 1));
    CHECK(!hearth_shape_cylinder((double[]){0, 0, 0}, (double[]){0, 1, 0}, 0, 1));
    /* oblique axis u = (1,1,0)/sqrt2, w perpendicular: 1 past the cap, 1 past the rim */
    hearth_shape *co = hearth_shape_cylinder((double[]){1, 1, 1}, (double[]){1, 1, 0}, 0.5, 2);
    double s2 = sqrt(0.5);
    CHECK_NEAR(sdf_at(co, 1 + 3 * s2 - 1.5 * s2, 1 + 3 * s2 + 1.5 * s2, 1), sqrt(2.0), 1e-14);
    CHECK_NEAR(sdf_at(co, 1 + 1 * s2, 1 + 1 * s2, 1.2), -0.3, 1e-14);
    /* a y-axis cylinder in 2D is a rectangle of half width r, half height hh */
    hearth_shape *cr = hearth_shape_cylinder((double[]){0, 0, 0}, (double[]){0, 1, 0}, 1, 0.5);
    CHECK_NEAR(sdf_at(cr, 0.9, 0, 0), -0.1, 1e-15);
    CHECK_NEAR(sdf_at(cr, 2, 1.5, 0), sqrt(2.0), 1e-15);
    CHECK_NEAR(sdf_at(cr, -2, 0.2, 0), 1.0, 1e-15);

    /* capsule */
    hearth_shape *ca = hearth_shape_capsule((double[]){0, 0, 0}, (double[]){2, 0, 0}, 0.5);
    CHECK_NEAR(sdf_at(ca, 1, 0, 0), -0.5, 1e-15);
    CHECK_NEAR(sdf_at(ca, 1, 2, 0), 1.5, 1e-15);
    CHECK_NEAR(sdf_at(ca, -1, 0, 0), 0.5, 1e-15);
    CHECK_NEAR(sdf_at(ca, 2, 0.5, 0), 0.0, 1e-15);
    CHECK_NEAR(sdf_at(ca, 3, 1, 0), sqrt(2.0) - 0.5, 1e-15);
    CHECK(!hearth_shape_capsule((double[]){0, 0, 0}, (double[]){1, 0, 0}, 0));

    /* container (r_in 1, height 2, wall 0.2, floor 0.3) on the y axis: a U in 2D */
    hearth_shape *cu = hearth_shape_container((double[]){0, 0, 0}, (double[]){0, 1, 0}, 1, 2, 0.2, 0.3);
    CHECK(cu);
    CHECK_NEAR(sdf_at(cu, 0, 1.5, 0), 1.0, 1e-15);       /* inside the cup: the wall is nearest */
    CHECK_NEAR(sdf_at(cu, 0.5, 0.25, 0), 0.25, 1e-15);   /* just above the floor */
    CHECK_NEAR(sdf_at(cu, 1.1, 1, 0), -0.1, 1e-15);      /* right arm of the U */
    CHECK_NEAR(sdf_at(cu, -1.1, 1, 0), -0.1, 1e-15);     /* left arm */
    CHECK_NEAR(sdf_at(cu, 1.05, 1, 0), -0.05, 1e-15);
    CHECK_NEAR(sdf_at(cu, 0, -0.15, 0), -0.15, 1e-15);   /* middle of the floor */
    CHECK_NEAR(sdf_at(cu, 1.1, 0, 0), -0.1, 1e-15);      /* wall/floor seam is solid */
    CHECK_NEAR(sdf_at(cu, 0, 3, 0), sqrt(2.0), 1e-15);   /* open top: nearest is the rim */
    CHECK_NEAR(sdf_at(cu, 1.5, 1, 0), 0.3, 1e-15);       /* outside the wall */
    CHECK_NEAR(sdf_at(cu, 0, -1.3, 0), 1.0, 1e-15);      /* below the floor */
    CHECK_NEAR(sdf_at(cu, 1.5, -0.6, 0), 0.3 * sqrt(2.0), 1e-15);
    CHECK_NEAR(sdf_at(cu, 1.1, 2, 0), 0.0, 1e-15);       /* on the rim */
    CHECK_NEAR(sdf_at(cu, 0, 1, 1.1), -0.1, 1e-15);      /* 3D: the wall goes all round */
    CHECK_NEAR(sdf_at(cu, 0.6, 1, 0.8), 0.0, 1e-15);     /* inner face */
    CHECK(!hearth_shape_container((double[]){0, 0, 0}, (double[]){0, 1, 0}, 0, 1, 0.1, 0.1));
    CHECK(!hearth_shape_container((double[]){0, 0, 0}, (double[]){0, 1, 0}, 1, 1, 0, 0.1));
    CHECK(!hearth_shape_container((double[]){0, 0, 0}, (double[]){0, 0, 0}, 1, 1, 0.1, 0.1));
    CHECK(!hearth_shape_container((double[]){0, 0, 0}, (double[]){0, 1, 0}, 1, 1, 0.1, -0.1));
    /* no floor: a ring; the inside of the ring is open */
    hearth_shape *ring = hearth_shape_container((double[]){0, 0, 0}, (double[]){0, 1, 0}, 1, 2, 0.2, 0);
    CHECK_NEAR(sdf_at(ring, 0.5, 0.1, 0), 0.5, 1e-15);

    hearth_shape *all[] = {pl, bx, rc, sp, disc, cy, co, cr, ca, cu, ring};
    for (size_t i = 0; i < sizeof all / sizeof all[0]; i++) {
        CHECK(all[i]);
        hearth_shape_free(all[i]);
    }
    CHECK(hearth_bytes_allocated() == base);
}

/* Two overlapping unit spheres, centres 1.5 apart on x. */
static void two_spheres(hearth_shape **a, hearth_shape **b) {
    *a = hearth_shape_sphere((double[]){0, 0, 0}, 1);
    *b = hearth_shape_sphere((double[]){1.5, 0, 0}, 1);
}

TEST(shape_sdf_combine) {
    size_t base = hearth_bytes_allocated();
    hearth_shape *a, *b;
    two_spheres(&a, &b);
    hearth_shape *u = hearth_shape_combine(HEARTH_UNION, a, b);
    hearth_shape *in = hearth_shape_combine(HEARTH_INTERSECT, a, b);
    hearth_shape *sub = hearth_shape_combine(HEARTH_SUBTRACT, a, b);
    CHECK(u && in && sub);
    CHECK_NEAR(sdf_at(u, 0, 0, 0), -1.0, 1e-15);
    CHECK_NEAR(sdf_at(u, 3, 0, 0), 0.5, 1e-15);
    CHECK_NEAR(sdf_at(in, 0.75, 0, 0), -0.25, 1e-15);
    CHECK_NEAR(sdf_at(in, 0, 0, 0), 0.5, 1e-15);
    CHECK_NEAR(sdf_at(sub, 0, 0, 0), -0.5, 1e-15);
    CHECK_NEAR(sdf_at(sub, 0.75, 0, 0), 0.25, 1e-15);
    CHECK_NEAR(sdf_at(sub, -2, 0, 0), 1.0, 1e-15);
    CHECK(!hearth_shape_combine(HEARTH_UNION, a, NULL));
    CHECK(!hearth_shape_combine((hearth_shape_op)9, a, b));

    double lo[3], hi[3];
    hearth_shape_bounds(u, lo, hi);
    CHECK(lo[0] == -1 && hi[0] == 2.5 && lo[1] == -1 && hi[1] == 1 && lo[2] == -1 && hi[2] == 1);
    hearth_shape_bounds(in, lo, hi);
    CHECK(lo[0] == 0.5 && hi[0] == 1 && lo[1] == -1 && hi[1] == 1);
    hearth_shape_bounds(sub, lo, hi);
    CHECK(lo[0] == -1 && hi[0] == 1);
    hearth_shape *pl = hearth_shape_plane((double[]){0, 0, 0}, (double[]){0, 1, 0});
    hearth_shape_bounds(pl, lo, hi);
    CHECK(lo[0] == -HUGE_VAL && hi[1] == HUGE_VAL);
    hearth_shape *cut = hearth_shape_combine(HEARTH_INTERSECT, pl, a); /* lower half ball */
    hearth_shape_bounds(cut, lo, hi);
    CHECK(lo[1] == -1 && hi[1] == 1 && lo[0] == -1);
    CHECK_NEAR(sdf_at(cut, 0, 0.5, 0), 0.5, 1e-15);
    CHECK_NEAR(sdf_at(cut, 0, -0.5, 0), -0.5, 1e-15);
    hearth_shape *cu = hearth_shape_container((double[]){0, 0, 0}, (double[]){0, 1, 0}, 1, 2, 0.2, 0.3);
    hearth_shape_bounds(cu, lo, hi);
    CHECK_NEAR(lo[0], -1.2, 1e-15);
    CHECK_NEAR(hi[0], 1.2, 1e-15);
    CHECK_NEAR(lo[1], -0.3, 1e-15);
    CHECK_NEAR(hi[1], 2.0, 1e-15);
    CHECK_NEAR(hi[2], 1.2, 1e-15);
    hearth_shape *cy = hearth_shape_cylinder((double[]){0, 0, 0}, (double[]){1, 1, 0}, 1, 2);
    hearth_shape_bounds(cy, lo, hi);
    CHECK_NEAR(hi[0], 2 * sqrt(0.5) + sqrt(0.5), 1e-14);
    CHECK_NEAR(hi[2], 1.0, 1e-15);

    /* a nested tree, its deep copy, and the originals freed first */
    hearth_shape *tree = hearth_shape_combine(HEARTH_SUBTRACT, u, cu);
    hearth_shape *cp = hearth_shape_copy(tree);
    CHECK(tree && cp);
    hearth_shape_free(a);
    hearth_shape_free(b);
    hearth_shape_free(u);
    double p[3] = {0.3, -0.7, 0.2};
    CHECK(hearth_shape_sdf(cp, p, NULL) == hearth_shape_sdf(tree, p, NULL));
    hearth_shape_free(tree);
    CHECK_NEAR(sdf_at(cp, 1.5, 0, 0), -0.3, 1e-15); /* union -1, but the cup wall is 0.3 away */

    /* allocation failure at every point of combine and copy: NULL, no leak */
    size_t held = hearth_bytes_allocated();
    int failures = 0;
    for (long k = 0; k < 64; k++) {
        mem_fail_after(k);
        hearth_shape *t = hearth_shape_combine(HEARTH_UNION, cp, in);
        hearth_shape *c2 = t ? hearth_shape_copy(t) : NULL;
        mem_fail_after(-1);
        if (!t || !c2) failures++;
        hearth_shape_free(c2);
        hearth_shape_free(t);
        CHECK(hearth_bytes_allocated() == held);
        if (t && c2) break;
    }
    CHECK(failures > 8); /* each of the two trees has >= 5 nodes */
    mem_fail_after(0);
    CHECK(!hearth_shape_sphere((double[]){0, 0, 0}, 1));
    mem_fail_after(-1);
    hearth_shape_free(NULL);
    CHECK(!hearth_shape_copy(NULL));

    hearth_shape_free(cp);
    hearth_shape_free(in);
    hearth_shape_free(sub);
    hearth_shape_free(pl);
    hearth_shape_free(cut);
    hearth_shape_free(cu);
    hearth_shape_free(cy);
    CHECK(hearth_bytes_allocated() == base);
}

/* Deterministic uniform numbers in [lo, hi). */
static double rnd(uint64_t *s, double lo, double hi) {
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(*s >> 11) * (1.0 / 9007199254740992.0);
}

TEST(shape_normals) {
    double n[3];
    /* analytic cases */
    hearth_shape *sp = hearth_shape_sphere((double[]){1, 2, 3}, 1);
    CHECK_NEAR(hearth_shape_sdf(sp, (double[]){1, 2, 6}, n), 2.0, 1e-15);
    CHECK(n[0] == 0 && n[1] == 0 && n[2] == 1);
    hearth_shape_sdf(sp, (double[]){1.3, 2.4, 3}, n); /* inside, still outward */
    CHECK_NEAR(n[0], 0.6, 1e-15);
    CHECK_NEAR(n[1], 0.8, 1e-15);
    hearth_shape_sdf(sp, (double[]){1, 2, 3}, n); /* centre: the documented fallback */
    CHECK(n[0] == 0 && n[1] == 1 && n[2] == 0);
    hearth_shape *pl = hearth_shape_plane((double[]){0, 0, 0}, (double[]){3, 4, 0});
    hearth_shape_sdf(pl, (double[]){7, -2, 1}, n);
    CHECK_NEAR(n[0], 0.6, 1e-15);
    CHECK_NEAR(n[1], 0.8, 1e-15);
    hearth_shape *bx = hearth_shape_box((double[]){0, 0, 0}, (double[]){1, 2, 3});
    hearth_shape_sdf(bx, (double[]){1.5, 0.3, -0.2}, n);
    CHECK(n[0] == 1 && n[1] == 0 && n[2] == 0);
    hearth_shape_sdf(bx, (double[]){0.1, -1.9, 0.5}, n);
    CHECK(n[0] == 0 && n[1] == -1 && n[2] == 0);
    hearth_shape_sdf(bx, (double[]){0.2, 0.1, 2.5}, n);
    CHECK(n[0] == 0 && n[1] == 0 && n[2] == 1);

    /* every shape: unit, outward, equal to the central-difference gradient
     * wherever that gradient has unit length (off ridges) */
    hearth_shape *a = hearth_shape_sphere((double[]){0, 0, 0}, 1);
    hearth_shape *b = hearth_shape_box((double[]){0.8, 0.2, 0}, (double[]){0.5, 0.4, 0.6});
    hearth_shape *shapes[] = {
        sp, pl, bx, a, b,
        hearth_shape_cylinder((double[]){0.1, 0, 0}, (double[]){1, 2, 0.5}, 0.7, 0.9),
        hearth_shape_capsule((double[]){-0.5, 0, 0}, (double[]){0.5, 0.5, 0.2}, 0.4),
        hearth_shape_container((double[]){0, -1, 0}, (double[]){0, 1, 0}, 0.8, 1.5, 0.2, 0.25),
        hearth_shape_container((double[]){0, 0, 0}, (double[]){1, 1, 1}, 0.5, 1.0, 0.1, 0.2),
        hearth_shape_combine(HEARTH_UNION, a, b),
        hearth_shape_combine(HEARTH_INTERSECT, a, b),
        hearth_shape_combine(HEARTH_SUBTRACT, a, b),
    };
    int nshapes = (int)(sizeof shapes / sizeof shapes[0]), compared = 0;
    uint64_t seed = 12345;
    for (int k = 0; k < nshapes; k++) {
        CHECK(shapes[k]);
        for (int i = 0; i < 300; i++) {
            double x[3] = {rnd(&seed, -2, 2), rnd(&seed, -2, 2), rnd(&seed, -2, 2)};
            double d = hearth_shape_sdf(shapes[k], x, n), g[3];
            CHECK_NEAR(sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]), 1.0, 1e-12);
            double h = 1e-6;
            for (int j = 0; j < 3; j++) {
                double xp[3] = {x[0], x[1], x[2]}, xm[3] = {x[0], x[1], x[2]};
                xp[j] += h;
                xm[j] -= h;
                g[j] = (hearth_shape_sdf(shapes[k], xp, NULL) - hearth_shape_sdf(shapes[k], xm, NULL)) / (2 * h);
            }
            double gl = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
            if (fabs(gl - 1) > 1e-6) continue; /* a ridge: no gradient to match */
            compared++;
            for (int j = 0; j < 3; j++) CHECK_NEAR(n[j], g[j], 1e-6);
            double xo[3] = {x[0] + 1e-4 * n[0], x[1] + 1e-4 * n[1], x[2] + 1e-4 * n[2]};
            CHECK(hearth_shape_sdf(shapes[k], xo, NULL) > d); /* outward */
        }
    }
    CHECK(compared > nshapes * 250);

    /* 2D: shapes placed in z = 0 give normals in the plane, even on the axis */
    hearth_shape *cup = shapes[7];
    double pts[][3] = {{0, 0, 0}, {0.85, 0, 0}, {-0.9, 0.4, 0}, {0.3, -1.1, 0}, {0, 1.2, 0}};
    for (size_t i = 0; i < sizeof pts / sizeof pts[0]; i++) {
        hearth_shape_sdf(cup, pts[i], n);
        CHECK(n[2] == 0);
    }
    hearth_shape_sdf(cup, (double[]){0.83, 0.1, 0}, n); /* in the right arm, nearer the inside */
    CHECK_NEAR(n[0], -1.0, 1e-15);
    hearth_shape_sdf(cup, (double[]){0.2, -1.2, 0}, n); /* under the floor */
    CHECK_NEAR(n[1], -1.0, 1e-15);
    hearth_shape *rc = hearth_shape_box((double[]){0, 0, 0}, (double[]){1, 0.3, 0});
    hearth_shape_sdf(rc, (double[]){0.2, 0.1, 0}, n);
    CHECK(n[0] == 0 && n[1] == 1 && n[2] == 0);
    hearth_shape_free(rc);

    for (int k = 0; k < nshapes; k++) hearth_shape_free(shapes[k]);
}

/* The box of the collider test after a quarter turn about z through the origin. */
static void check_box_matches(const collider *c, const double ctr[3], const double half[3]) {
    hearth_shape *ref = hearth_shape_box(ctr, half);
    uint64_t seed = 7;
    for (int i = 0; i < 200; i++) {
        double x[3] = {rnd(&seed, -2, 3), rnd(&seed, -2, 3), rnd(&seed, -1, 1)};
        CHECK_NEAR(collider_sdf(c, x, NULL), hearth_shape_sdf(ref, x, NULL), 1e-9);
    }
    /* off a ridge the normals agree too */
    double x[3] = {ctr[0] + half[0] + 0.5, ctr[1], ctr[2]}, n[3], nr[3];
    collider_sdf(c, x, n);
    hearth_shape_sdf(ref, x, nr);
    for (int j = 0; j < 3; j++) CHECK_NEAR(n[j], nr[j], 1e-9);
    hearth_shape_free(ref);
}

static int motion_calls;
static void motion_fn(void *ud, double t, double v[3], double omega[3]) {
    *(int *)ud += 1;
    v[0] = t;
    v[1] = 2;
    v[2] = 0;
    omega[0] = omega[1] = 0;
    omega[2] = 3 * t;
}

TEST(collider_motion) {
    size_t base = hearth_bytes_allocated();
    hearth_error err;
    collider c;
    hearth_collider_def def;
    memset(&def, 0, sizeof def);

    /* translation: the sphere's centre moves with vel */
    hearth_shape *sp = hearth_shape_sphere((double[]){0, 0, 0}, 1);
    def.shape = sp;
    def.velocity[0] = 1;
    CHECK(collider_init(&c, &def, &err) == HEARTH_OK);
    collider_advance(&c, 0.5);
    collider_advance(&c, 0.5);
    CHECK_NEAR(collider_sdf(&c, (double[]){1, 0, 0}, NULL), -1.0, 1e-15);
    CHECK_NEAR(collider_sdf(&c, (double[]){3, 0, 0}, NULL), 1.0, 1e-15);
    collider_free(&c);
    collider_free(&c); /* idempotent */

    /* rotation about a fixed pivot: a quarter turn in 100 steps */
    double half[3] = {0.5, 0.1, 0.2};
    hearth_shape *bx = hearth_shape_box((double[]){1, 0, 0}, half);
    memset(&def, 0, sizeof def);
    def.shape = bx;
    def.omega[2] = PI / 2;
    CHECK(collider_init(&c, &def, &err) == HEARTH_OK);
    double v[3];
    collider_velocity_at(&c, (double[]){1, 0, 0}, v);
    CHECK_NEAR(v[1], PI / 2, 1e-15);
    CHECK(v[0] == 0 && v[2] == 0);
    for (int i = 0; i < 100; i++) collider_advance(&c, 0.01);
    check_box_matches(&c, (double[]){0, 1, 0}, (double[]){0.1, 0.5, 0.2});
    collider_free(&c);

    /* translation and rotation together: the pivot (the box centre) travels */
    def.velocity[0] = 1;
    def.pivot[0] = 1;
    CHECK(collider_init(&c, &def, &err) == HEARTH_OK);
    for (int i = 0; i < 100; i++) collider_advance(&c, 0.01);
    check_box_matches(&c, (double[]){2, 0, 0}, (double[]){0.1, 0.5, 0.2});
    collider_velocity_at(&c, (double[]){2, 0.5, 0}, v); /* 0.5 above the moving pivot */
    CHECK_NEAR(v[0], 1 - 0.5 * PI / 2, 1e-12);
    CHECK_NEAR(v[1], 0.0, 1e-12);
    collider_free(&c);

    /* a motion callback replaces the constants: motion(0) at init, then motion(t) */
    memset(&def, 0, sizeof def);
    def.shape = sp;
    def.velocity[0] = 99;
    def.motion = motion_fn;
    def.motion_ud = &motion_calls;
    motion_calls = 0;
    CHECK(collider_init(&c, &def, &err) == HEARTH_OK);
    CHECK(motion_calls == 1);
    CHECK(c.vel[0] == 0 && c.vel[1] == 2);
    collider_set_time(&c, 2.0);
    CHECK(motion_calls == 2);
    CHECK(c.vel[0] == 2 && c.vel[1] == 2 && c.omega[2] == 6);
    collider_advance(&c, 0.5);
    CHECK_NEAR(collider_sdf(&c, (double[]){1, 1, 0}, NULL), -1.0, 1e-15);
    collider_velocity_at(&c, (double[]){1, 2, 0}, v); /* 1 above the pivot (1,1,0) */
    CHECK_NEAR(v[0], 2 - 6, 1e-15);
    CHECK_NEAR(v[1], 2, 1e-15);
    collider_free(&c);

    hearth_shape_free(sp);
    hearth_shape_free(bx);
    CHECK(hearth_bytes_allocated() == base);
}

static void check_v(const double v[3], double x, double y, double z) {
    CHECK_NEAR(v[0], x, 1e-14);
    CHECK_NEAR(v[1], y, 1e-14);
    CHECK_NEAR(v[2], z, 1e-14);
}

TEST(contact_modes) {
    const double n[3] = {0, 1, 0}, still[3] = {0, 0, 0};
    double v[3];
    /* approaching a still floor at (3,-1,0) */
    memcpy(v, (double[]){3, -1, 0}, sizeof v);
    contact_apply(HEARTH_STICKY, 0.5, n, still, v);
    check_v(v, 0, 0, 0);
    memcpy(v, (double[]){3, -1, 0}, sizeof v);
    contact_apply(HEARTH_SLIP, 0, n, still, v);
    check_v(v, 3, 0, 0);
    memcpy(v, (double[]){3, -1, 0}, sizeof v);
    contact_apply(HEARTH_SLIP, 0.5, n, still, v); /* slows: 3 - 0.5*1 */
    check_v(v, 2.5, 0, 0);
    memcpy(v, (double[]){3, -1, 0}, sizeof v);
    contact_apply(HEARTH_SLIP, 5, n, still, v); /* stops: 5*1 >= 3 */
    check_v(v, 0, 0, 0);
    memcpy(v, (double[]){3, -1, 0}, sizeof v);
    contact_apply(HEARTH_SLIP, 3, n, still, v); /* exactly at the cone: stops */
    check_v(v, 0, 0, 0);
    memcpy(v, (double[]){3, -1, 4}, sizeof v);
    contact_apply(HEARTH_SEPARATE, 1, n, still, v); /* |vt| 5 -> 4, direction kept */
    check_v(v, 2.4, 0, 3.2);

    /* leaving the floor: slip still removes the normal part, separate leaves v alone */
    memcpy(v, (double[]){3, 1, 0}, sizeof v);
    contact_apply(HEARTH_SLIP, 0, n, still, v);
    check_v(v, 3, 0, 0);
    memcpy(v, (double[]){3, 1, 0}, sizeof v);
    contact_apply(HEARTH_SEPARATE, 0.5, n, still, v);
    check_v(v, 3, 1, 0);
    memcpy(v, (double[]){3, 0, 0}, sizeof v); /* pure sliding: no normal impulse, no friction */
    contact_apply(HEARTH_SEPARATE, 10, n, still, v);
    check_v(v, 3, 0, 0);

    /* a moving boundary: everything is relative to vb = (1, 0.5, 0) */
    const double vb[3] = {1, 0.5, 0};
    memcpy(v, (double[]){3, -1, 0}, sizeof v);
    contact_apply(HEARTH_STICKY, 0, n, vb, v);
    check_v(v, 1, 0.5, 0);
    memcpy(v, (double[]){3, -1, 0}, sizeof v); /* rel (2,-1.5): vt 2 - 0.5*1.5 */
    contact_apply(HEARTH_SEPARATE, 0.5, n, vb, v);
    check_v(v, 2.25, 0.5, 0);
    memcpy(v, (double[]){3, 0.7, 0}, sizeof v); /* faster than the boundary: separating */
    contact_apply(HEARTH_SEPARATE, 0.5, n, vb, v);
    check_v(v, 3, 0.7, 0);
    memcpy(v, (double[]){3, 0.7, 0}, sizeof v);
    contact_apply(HEARTH_SLIP, 0.5, n, vb, v); /* rel (2,0.2): vt 2 - 0.1 */
    check_v(v, 2.9, 0.5, 0);

    /* an oblique wall, n = (1,1,0)/sqrt2, v = (-2,0,0): vn = -sqrt2, vt = (-1,1,0) */
    const double s = sqrt(0.5), no[3] = {s, s, 0};
    memcpy(v, (double[]){-2, 0, 0}, sizeof v);
    contact_apply(HEARTH_SLIP, 0, no, still, v);
    check_v(v, -1, 1, 0);
    memcpy(v, (double[]){-2, 0, 0}, sizeof v);
    contact_apply(HEARTH_SLIP, 0.5, no, still, v); /* |vt| sqrt2 -> sqrt2/2 */
    check_v(v, -0.5, 0.5, 0);
    memcpy(v, (double[]){-2, 0, 0}, sizeof v);
    contact_apply(HEARTH_SEPARATE, 1, no, still, v);
    check_v(v, 0, 0, 0);
}

TEST(collider_bad_def) {
    size_t base = hearth_bytes_allocated();
    hearth_shape *sp = hearth_shape_sphere((double[]){0, 0, 0}, 1);
    hearth_collider_def def;
    hearth_error err;
    collider c;

#define BAD(mutate, word)                                                                          \
    do {                                                                                           \
        memset(&def, 0, sizeof def);                                                               \
        def.shape = sp;                                                                            \
        mutate;                                                                                    \
        memset(&err, 0, sizeof err);                                                               \
        CHECK(collider_init(&c, &def, &err) == HEARTH_ERR_PARAM);                                  \
        CHECK(err.code == HEARTH_ERR_PARAM);                                                       \
        CHECK_STR_CONTAINS(err.msg, word);                                                         \
        CHECK_STR_CONTAINS(err.msg, "valid");                                                      \
        CHECK(c.shape == NULL);                                                                    \
        collider_free(&c);                                                                         \
    } while (0)

    BAD(def.shape = NULL, "shape");
    BAD(def.friction = -0.1, "friction");
    CHECK_STR_CONTAINS(err.msg, "[0, inf)");
    BAD(def.friction = NAN, "friction");
    BAD(def.friction = INFINITY, "friction");
    BAD(def.velocity[1] = NAN, "velocity[1]");
    BAD(def.omega[2] = INFINITY, "omega[2]");
    BAD(def.pivot[0] = NAN, "pivot[0]");
    BAD(def.mode = (hearth_contact)7, "mode");
    CHECK_STR_CONTAINS(err.msg, "0 (sticky)");
#undef BAD

    /* out of memory while copying the shape */
    memset(&def, 0, sizeof def);
    def.shape = sp;
    def.friction = 0.3;
    mem_fail_after(0);
    hearth_status st = collider_init(&c, &def, &err);
    mem_fail_after(-1);
    CHECK(st == HEARTH_ERR_NOMEM && err.code == HEARTH_ERR_NOMEM);
    collider_free(&c);
    /* and a good def works and owns its copy */
    CHECK(collider_init(&c, &def, &err) == HEARTH_OK);
    hearth_shape_free(sp);
    CHECK_NEAR(collider_sdf(&c, (double[]){0, 2, 0}, NULL), 1.0, 1e-15);
    collider_free(&c);
    CHECK(hearth_bytes_allocated() == base);
}

/* collider_bound_half_space (MPM's tray): its box must hold every point whose collider_sdf is within the
 * margin (2 dx), to the last bit, so that the callers, whose bands are all within it, find what the
 * infinite box found; and it must leave out the points well past it, else it saves nothing. For the six
 * axis normals of a plane at 0.2 with a pivot at 0.37, moved by a velocity over 7 steps (offset 0.0203...),
 * dx 1/64 and 2.5 mm: points at 4001 distances across -3..3 margins and, around the margin itself, 200
 * ulp steps either side, the other two coordinates spread over -5..5 m. A turned plane and a slanted
 * normal keep the infinite box. */
TEST(plane_box_holds_the_band) {
    hearth_error err;
    long held = 0, missed = 0, pruned = 0, far = 0;
    for (int k = 0; k < 3; k++)
        for (int sg = -1; sg <= 1; sg += 2)
            for (int r = 0; r < 2; r++) {
                const double dx = r ? 0.0025 : 1.0 / 64, M = 2 * dx;
                double p[3] = {0.3, 0.3, 0.3}, u[3] = {0, 0, 0};
                p[k] = 0.2, u[k] = sg;
                hearth_shape *pl = hearth_shape_plane(p, u);
                hearth_collider_def def;
                memset(&def, 0, sizeof def);
                def.shape = pl;
                def.velocity[k] = 0.0029;
                for (int d = 0; d < 3; d++) def.pivot[d] = 0.37;
                collider c;
                CHECK(collider_init(&c, &def, &err) == HEARTH_OK);
                hearth_shape_free(pl);
                for (int i = 0; i < 7; i++) collider_advance(&c, 1.0);
                collider_update_bounds(&c, M);
                collider_bound_half_space(&c, M);
                const double face = 0.2 + c.offset[k];
                for (int j = 0; j < 4401; j++) {
                    double x[3];
                    for (int d = 0; d < 3; d++) x[d] = -5 + 10 * (double)((j * 7919 + d * 104729) % 4001) / 4000;
                    if (j < 4001) {
                        x[k] = face + sg * (-3 + 6 * (double)j / 4000) * M;
                    } else { /* 200 ulp steps either side of the margin */
                        double y = face + sg * M;
                        for (int q = 0; q < 200; q++) y = nextafter(y, sg > 0 ? -INFINITY : INFINITY);
                        for (int q = 0; q < j - 4001; q++) y = nextafter(y, sg > 0 ? INFINITY : -INFINITY);
                        x[k] = y;
                    }
                    const double sd = collider_sdf(&c, x, NULL);
                    const int near = collider_near(&c, x);
                    if (sd <= M) held += near, missed += !near;
                    if (sd >= 1.01 * M) far++, pruned += !near;
                }
                collider_free(&c);
            }
    printf("  points within the margin: %ld in the box, %ld missed; past 1.01 margins: %ld of %ld left out\n", held, missed,
           pruned, far);
    CHECK(missed == 0 && held > 0);
    CHECK(pruned == far && far > 0);
    /* turned, or slanted: the whole space, as collider_update_bounds gives a plane */
    hearth_shape *pl = hearth_shape_plane((double[]){0, 0.2, 0}, (double[]){0, 1, 0});
    hearth_shape *sl = hearth_shape_plane((double[]){0, 0.2, 0}, (double[]){0.1, 1, 0});
    for (int t = 0; t < 2; t++) {
        hearth_collider_def def;
        memset(&def, 0, sizeof def);
        def.shape = t ? sl : pl;
        def.omega[2] = t ? 0 : 0.1;
        collider c;
        CHECK(collider_init(&c, &def, &err) == HEARTH_OK);
        collider_advance(&c, 0.5);
        collider_update_bounds(&c, 0.01);
        collider_bound_half_space(&c, 0.01);
        CHECK(collider_near(&c, (double[]){0, 1e3, 0}) && collider_near(&c, (double[]){1e3, -1e3, 1e3}));
        collider_free(&c);
    }
    hearth_shape_free(pl);
    hearth_shape_free(sl);
}

/* collider_bound_prism (helper citime): a 2D box (no z extent) gets its rectangle's box grown by the margin,
 * open in z, and every point whose SDF is within the margin must still be in it, or MPM's callers would miss
 * a contact they found before (each asks collider_near first). A box moved 7 s at 2.9 mm/s, and the same
 * box turned about z by 0.7 rad, at dx 1/64 and 2.5 mm: points on 4001 rays from the box's centre at -3..3
 * margins past its rectangle (z spread over -5..5 m), and on the +x face 200 ulp steps either side of the
 * margin. Bar, a priori: none within the margin missed; every point past 1.01 margins of the moved
 * rectangle's own axis-aligned box (along x or y) left out where the box is finite (the unturned box, and the
 * turned one when its R keeps z exactly); a 3D box keeps its finite box
 * and a 2D sphere's box is not narrowed. */
TEST(box_2d_box_holds_the_band) {
    hearth_error err;
    long held = 0, missed = 0, pruned = 0, far = 0, turned_finite = 0;
    for (int t = 0; t < 2; t++)
        for (int r = 0; r < 2; r++) {
            const double dx = r ? 0.0025 : 1.0 / 64, M = 2 * dx;
            hearth_shape *bx = hearth_shape_box((double[]){0.3, 0.2, 0}, (double[]){0.05, 0.02, 0});
            hearth_collider_def def;
            memset(&def, 0, sizeof def);
            def.shape = bx;
            def.velocity[0] = 0.0029, def.velocity[1] = -0.0013;
            def.omega[2] = t ? 0.1 : 0.0;
            for (int d = 0; d < 2; d++) def.pivot[d] = 0.31;
            collider c;
            CHECK(collider_init(&c, &def, &err) == HEARTH_OK);
            hearth_shape_free(bx);
            for (int i = 0; i < 7; i++) collider_advance(&c, 1.0);
            collider_update_bounds(&c, M);
            CHECK(!isfinite(c.blo[2]) && !isfinite(c.bhi[0])); /* before: the whole space */
            collider_bound_prism(&c, M);
            const int finite = isfinite(c.blo[0]) && isfinite(c.bhi[0]) && isfinite(c.blo[1]) && isfinite(c.bhi[1]);
            CHECK(!isfinite(c.blo[2]) && !isfinite(c.bhi[2]));
            if (!t) CHECK(finite);
            turned_finite += t && finite;
            double ctr[3] = {0.3, 0.2, 0}, cw[3], alo[2] = {INFINITY, INFINITY}, ahi[2] = {-INFINITY, -INFINITY};
            for (int d = 0; d < 3; d++) ctr[d] -= c.pivot0[d];
            t3_mulv(c.R, ctr, cw);
            for (int d = 0; d < 2; d++) cw[d] += c.pivot0[d] + c.offset[d];
            for (int k = 0; k < 4; k++) { /* the moved rectangle's own axis-aligned box, for "far" */
                const double e[2] = {k & 1 ? 0.05 : -0.05, k & 2 ? 0.02 : -0.02};
                for (int d = 0; d < 2; d++) {
                    const double v = cw[d] + c.R[3 * d] * e[0] + c.R[3 * d + 1] * e[1];
                    alo[d] = fmin(alo[d], v), ahi[d] = fmax(ahi[d], v);
                }
            }
            for (int j = 0; j < 4401; j++) {
                double x[3];
                x[2] = -5 + 10 * (double)((j * 7919) % 4001) / 4000;
                if (j < 4001) { /* a ray at angle a from the centre, to -3..3 margins past the rectangle's corner radius */
                    const double a = 2 * 3.14159265358979323846 * (double)((j * 104729) % 4001) / 4001, len = hypot(0.05, 0.02) + (-3 + 6 * (double)j / 4000) * M;
                    x[0] = cw[0] + len * cos(a), x[1] = cw[1] + len * sin(a);
                } else { /* the +x face (unturned) at the margin, 200 ulp steps either side */
                    double y = cw[0] + 0.05 + M;
                    for (int q = 0; q < 200; q++) y = nextafter(y, -INFINITY);
                    for (int q = 0; q < j - 4001; q++) y = nextafter(y, INFINITY);
                    x[0] = y, x[1] = cw[1];
                }
                const double sd = collider_sdf(&c, x, NULL);
                const int near = collider_near(&c, x);
                if (sd <= M) held += near, missed += !near;
                /* far: past 1.01 margins of that box along x or y (a point by its corner may be farther than
                 * the margin from the rectangle and still in the box: no bar on those) */
                const double ex = fmax(fmax(alo[0] - x[0], x[0] - ahi[0]), fmax(alo[1] - x[1], x[1] - ahi[1]));
                if (finite && ex >= 1.01 * M) far++, pruned += !near;
            }
            collider_free(&c);
        }
    printf("  points within the margin: %ld in the box, %ld missed; past 1.01 margins of its box: %ld of %ld left out; turned box "
           "finite at %ld of 2 resolutions\n", held, missed, pruned, far, turned_finite);
    CHECK(missed == 0 && held > 0);
    CHECK(pruned == far && far > 0);
    /* a 3D box keeps collider_update_bounds' finite box; a 2D sphere (not a box) is left as it was */
    hearth_shape *b3 = hearth_shape_box((double[]){0.3, 0.2, 0.1}, (double[]){0.05, 0.02, 0.03});
    hearth_shape *sp = hearth_shape_sphere((double[]){0.3, 0.2, 0}, 0.05);
    for (int k = 0; k < 2; k++) {
        hearth_collider_def def;
        memset(&def, 0, sizeof def);
        def.shape = k ? sp : b3;
        collider c;
        CHECK(collider_init(&c, &def, &err) == HEARTH_OK);
        collider_update_bounds(&c, 0.01);
        double lo[3], hi[3];
        memcpy(lo, c.blo, sizeof lo), memcpy(hi, c.bhi, sizeof hi);
        collider_bound_prism(&c, 0.01);
        CHECK(memcmp(lo, c.blo, sizeof lo) == 0 && memcmp(hi, c.bhi, sizeof hi) == 0);
        collider_free(&c);
    }
    hearth_shape_free(b3);
    hearth_shape_free(sp);
}

TEST_MAIN(T(shape_sdf_primitives), T(shape_sdf_combine), T(shape_normals), T(collider_motion), T(contact_modes),
          T(collider_bad_def), T(plane_box_holds_the_band), T(box_2d_box_holds_the_band))
