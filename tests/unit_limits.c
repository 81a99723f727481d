/* unit_limits.c: scene numbers refused before anything is allocated, and
 * scenes at the edges of what the grid can hold. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "alloc.h"
#include "mpm_fixture.h"

/* A collider whose shape covers the whole box: its projection used to put
 * particles outside the grid after the step's clamp, and the next sort
 * filed them in a block whose tile did not hold their stencil (a stack
 * overflow in p2g_block). The scene must run (or be refused with a message). */
static void covering_collider(int dim) {
    hearth_scene *s = fx_scene(dim, 0.05, 0.0, 1.0);
    CHECK(s);
    if (!s) return;
    const int m = fx_elastic(s, 1e5, 0.3, 1000);
    const double c[3] = {0.5, 0.5, dim == 3 ? 0.5 : 0.0}, h[3] = {0.1, 0.1, dim == 3 ? 0.1 : 0.0};
    CHECK(fx_box(s, m, c, h, 2, NULL) > 0);
    const double cc[3] = {0.5, 0.5, dim == 3 ? 0.5 : 0.0}, ch[3] = {2.0, 2.0, dim == 3 ? 2.0 : 0.0};
    CHECK(fx_box_collider(s, cc, ch, HEARTH_SLIP, 0.0) >= 0);
    hearth_error err;
    const hearth_status st = hearth_scene_step(s, 5, &err);
    if (st) printf("  refused: %s\n", err.msg);
    CHECK(st == HEARTH_OK || err.msg[0]);
    hearth_stats stats;
    hearth_scene_stats(s, &stats);
    printf("  %d particles, %ld steps, %ld pushed back into the grid\n", stats.particles, stats.step, stats.out_of_domain);
    CHECK(st != HEARTH_OK || stats.step == 5);
    CHECK(stats.out_of_domain > 0); /* the collider did push them out */
    /* the collider's projection (after G2P's clamp) leaves particles outside
     * the grid; the sort, where their block is chosen, brings every one back */
    CHECK(mpm_sort(s, &err) == HEARTH_OK);
    const grid *g = &s->g;
    int outside = 0;
    for (int i = 0; i < s->ps.n; i++)
        for (int d = 0; d < dim; d++) {
            const double x = pcold(&s->ps, PC_X)[3 * i + d];
            outside += !(x >= g->lo[d] + g->dx && x <= g->lo[d] + (g->nn[d] - 2) * g->dx);
        }
    CHECK(outside == 0);
    hearth_scene_destroy(s);
}

TEST(covering_collider_2d) { covering_collider(2); }
TEST(covering_collider_3d) { covering_collider(3); }

/* ---- scene numbers ------------------------------------------------------- */

/* hearth_scene_create refuses def and says want (NULL scene, HEARTH_ERR_PARAM). */
static void refused(const hearth_scene_def *d, const char *want) {
    hearth_error err;
    const size_t before = hearth_bytes_allocated();
    hearth_scene *s = hearth_scene_create(d, &err);
    CHECK(s == NULL);
    CHECK(err.code == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, want);
    CHECK(hearth_bytes_allocated() == before); /* refused before anything was allocated, or all of it freed */
    printf("  refused: %s\n", err.msg);
    hearth_scene_destroy(s);
}

TEST(scene_dx_refused) {
    const double bad[] = {NAN, INFINITY, -INFINITY, 0.0, -0.01, 1e-300};
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        hearth_scene_def d = hearth_default_scene_def();
        d.dx = bad[k];
        refused(&d, k < 5 ? "dx =" : "cells per axis");
    }
}

TEST(scene_box_refused) {
    hearth_scene_def d = hearth_default_scene_def();
    d.hi[0] = d.lo[0]; /* zero size */
    refused(&d, "box axis x spans");
    d = hearth_default_scene_def();
    d.hi[1] = -1; /* negative size */
    refused(&d, "box axis y spans");
    d = hearth_default_scene_def();
    d.lo[0] = NAN;
    refused(&d, "box axis x");
    d = hearth_default_scene_def();
    d.hi[0] = 1e300; /* gave a negative block count in grid.c */
    refused(&d, "cells per axis");
    d = hearth_default_scene_def();
    d.lo[1] = -1e308;
    d.hi[1] = 1e308; /* the span overflows to inf */
    refused(&d, "cells per axis");
    d = hearth_default_scene_def();
    d.dim = 3;
    d.dx = 1e-4; /* 10^4 cells a side: 1.6e10 blocks */
    refused(&d, "grid blocks over the box; the limit is");
}

/* A particle count the machine cannot hold is refused with the estimate,
 * before anything is allocated (issue 15: a 150 GB scene was OOM-killed). */
TEST(scene_particles_memory_refused) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 3;
    d.dx = 0.02;
    for (int k = 0; k < 3; k++) d.lo[k] = 0, d.hi[k] = 20; /* 1000 cells a side, 1.6e7 blocks */
    hearth_scene *s = fx_scene_def(&d);
    CHECK(s);
    if (!s) return;
    const int m = fx_elastic(s, 1e5, 0.3, 1000);
    const double c[3] = {10, 10, 10}, h[3] = {10, 10, 10};
    hearth_shape *b = hearth_shape_box(c, h);
    hearth_error err;
    const size_t before = hearth_bytes_allocated();
    /* ~1e9 particles at one per cell: ~2e11 bytes */
    CHECK(hearth_scene_seed_shape(s, m, b, 1, 0, NULL, &err) == -1);
    CHECK(err.code == HEARTH_ERR_PARAM);
    CHECK_STR_CONTAINS(err.msg, "would need about");
    CHECK_STR_CONTAINS(err.msg, "GB of memory");
    printf("  refused: %s\n", err.msg);
    /* 8 per cell: more particles than an int counts */
    CHECK(hearth_scene_seed_shape(s, m, b, 8, 0, NULL, &err) == -1);
    CHECK_STR_CONTAINS(err.msg, "at most");
    printf("  refused: %s\n", err.msg);
    CHECK(hearth_bytes_allocated() == before);
    CHECK(s->ps.n == 0);
    double x[3] = {1, 1, 1};
    CHECK(hearth_scene_add_particles(s, m, -1, x, NULL, 1e-6, &err) == -1);
    CHECK_STR_CONTAINS(err.msg, "n = -1");
    hearth_shape_free(b);
    hearth_scene_destroy(s);
}

/* A program's memory ceiling (hearth run --memory): particles past it are
 * refused up front with the estimate and the ceiling's words; a step whose
 * grid would pass it fails as out-of-memory, holds no more than the ceiling,
 * and the scene steps on once the ceiling is lifted. */
TEST(memory_limit_refuses_seed_and_growth) {
    hearth_scene *s = fx_scene(2, 0.01, 0.0, 1.0);
    CHECK(s);
    if (!s) return;
    const int m = fx_elastic(s, 1e5, 0.3, 1000);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.3, 0.3, 0};
    hearth_shape *b = hearth_shape_box(c, h);
    hearth_error err;
    /* the box's 3600 cells at 4 per cell: ~14400 particles, a few MB; 1 MB over what is held now refuses them */
    hearth_set_memory_limit(hearth_bytes_allocated() + ((size_t)1 << 20));
    CHECK(hearth_scene_seed_shape(s, m, b, 4, 0, NULL, &err) == -1);
    CHECK_STR_CONTAINS(err.msg, "would need about");
    CHECK_STR_CONTAINS(err.msg, "this run may use");
    CHECK_STR_CONTAINS(err.msg, "--memory");
    printf("  refused: %s\n", err.msg);
    CHECK(s->ps.n == 0);
    /* room for the particles but not for the first step's grid blocks and scratch */
    hearth_set_memory_limit(0);
    CHECK(hearth_scene_seed_shape(s, m, b, 4, 0, NULL, &err) > 0);
    const size_t held = hearth_bytes_allocated(), ceiling = held + 4096;
    hearth_set_memory_limit(ceiling);
    CHECK(!hearth_memory_limit_refused());
    const hearth_status st = hearth_scene_step(s, 1, &err);
    printf("  step under a ceiling %zu bytes over the %zu held: status %d, %s\n", ceiling - held, held, (int)st,
           st ? err.msg : "ran");
    CHECK(st == HEARTH_ERR_NOMEM);
    CHECK(hearth_memory_limit_refused());
    CHECK_STR_CONTAINS(err.msg, "the simulation reached its memory ceiling of");
    CHECK(hearth_bytes_allocated() <= ceiling);
    hearth_set_memory_limit(0);
    CHECK(!hearth_memory_limit_refused());
    CHECK(hearth_scene_step(s, 2, &err) == HEARTH_OK);
    hearth_stats stats;
    hearth_scene_stats(s, &stats);
    CHECK(stats.step == 2);
    hearth_shape_free(b);
    hearth_scene_destroy(s);
}

/* A host's interrupt ends a call of many steps between two of them: asked
 * before each step after the first, the third "yes" ends a 50-step call after
 * 3 steps, in hearth_scene_step and hearth_scene_advance_steps alike (s:run
 * asks for 64 at a time: a step of seconds made an interrupt wait minutes);
 * without an interrupt every step runs. */
static int g_asked, g_yes_at;
static int interrupted_at(void) { return ++g_asked >= g_yes_at; }

TEST(interrupt_check_stops_between_steps) {
    hearth_scene *s = fx_scene(2, 0.05, 0.0, 1.0);
    CHECK(s);
    if (!s) return;
    const int m = fx_elastic(s, 1e5, 0.3, 1000);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.2, 0.2, 0};
    hearth_shape *b = hearth_shape_box(c, h);
    hearth_error err;
    CHECK(hearth_scene_seed_shape(s, m, b, 2, 0, NULL, &err) > 0);
    hearth_stats st;
    hearth_set_interrupt_check(interrupted_at);
    g_asked = 0, g_yes_at = 3;
    CHECK(hearth_scene_step(s, 50, &err) == HEARTH_OK);
    hearth_scene_stats(s, &st);
    printf("  hearth_scene_step(50), interrupted at the 3rd question: %ld steps, %d questions\n", (long)st.step, g_asked);
    CHECK(st.step == 3);
    g_asked = 0, g_yes_at = 3;
    CHECK(hearth_scene_advance_steps(s, 1e6, 50, &err) == HEARTH_OK);
    hearth_scene_stats(s, &st);
    printf("  hearth_scene_advance_steps(50), likewise: %ld steps in all\n", (long)st.step);
    CHECK(st.step == 6);
    g_asked = 0, g_yes_at = 1 << 30;
    CHECK(hearth_scene_step(s, 50, &err) == HEARTH_OK);
    hearth_scene_stats(s, &st);
    CHECK(st.step == 56);
    hearth_set_interrupt_check(NULL);
    CHECK(hearth_scene_step(s, 4, &err) == HEARTH_OK);
    hearth_scene_stats(s, &st);
    CHECK(st.step == 60);
    hearth_shape_free(b);
    hearth_scene_destroy(s);
}

/* A NaN centre or radius is named as such, not reported as out of memory. */
TEST(shape_nan_named) {
    const double nanc[3] = {NAN, 0, 0}, c[3] = {0, 0, 0}, axis[3] = {0, 0, 0}, up[3] = {0, 1, 0};
    CHECK(hearth_shape_sphere(nanc, 0.1) == NULL);
    CHECK_STR_CONTAINS(hearth_shape_error(), "sphere: centre is not finite");
    CHECK(hearth_shape_sphere(c, NAN) == NULL);
    CHECK_STR_CONTAINS(hearth_shape_error(), "sphere: radius must be finite and > 0");
    CHECK(hearth_shape_box(c, (const double[]){1, NAN, 1}) == NULL);
    CHECK_STR_CONTAINS(hearth_shape_error(), "box: half extents");
    CHECK(hearth_shape_cylinder(c, axis, 0.1, 0.1) == NULL);
    CHECK_STR_CONTAINS(hearth_shape_error(), "cylinder: axis");
    CHECK(hearth_shape_container(c, up, 0.1, 0, 0.01, 0) == NULL);
    CHECK_STR_CONTAINS(hearth_shape_error(), "container: height + floor");
    CHECK(hearth_shape_plane(c, axis) == NULL);
    CHECK_STR_CONTAINS(hearth_shape_error(), "plane: normal");
    CHECK(hearth_shape_capsule(c, nanc, 0.1) == NULL);
    CHECK_STR_CONTAINS(hearth_shape_error(), "capsule: an end is not finite");
    hearth_shape *ok = hearth_shape_sphere(c, 0.1);
    CHECK(ok && hearth_shape_error() == NULL);
    CHECK(hearth_shape_extrude(ok, 1, 0) == NULL);
    CHECK_STR_CONTAINS(hearth_shape_error(), "extrude: z0 and z1");
    hearth_shape_free(ok);
}

TEST_MAIN(T(covering_collider_2d), T(covering_collider_3d), T(scene_dx_refused), T(scene_box_refused),
          T(scene_particles_memory_refused), T(memory_limit_refuses_seed_and_growth), T(interrupt_check_stops_between_steps),
          T(shape_nan_named))
