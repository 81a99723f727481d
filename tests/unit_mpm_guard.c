/* unit_mpm_guard.c: what the MPM step refuses and how it says so: the guard (NaN, plugin
 * errors, CFL, collider drive), bad input, and every failed allocation. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "mpm_fixture.h"

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

TEST_MAIN(T(guard_nan_plugin), T(guard_plugin_error), T(guard_cfl_and_rollback), T(scene_bad_input), T(alloc_failure_paths), T(guard_collider_drive))
