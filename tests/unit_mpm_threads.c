/* unit_mpm_threads.c: the MPM step is bit-identical at any thread count and across a checkpoint,
 * and its scratch belongs to the solver. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "mpm_fixture.h"

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
        hearth_scene_set_body_force(s, fx_antigravity, &up);
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

/* One thread gathers too in 2D (mpm_p2g_gather.c, mpm_p2g_store_held: the
 * colour phases' strided sweeps cost it 15% more CPU at 512 cells). The same
 * scene as p2g_gather_matches_colour_phases' 2D one at one thread: the store
 * held (the gather ran) without the switch, none with it, and the same bits
 * both ways and as at two threads. */
TEST(p2g_gather_one_thread_matches_colour_phases) {
    uint64_t h[3];
    for (int run = 0; run < 3; run++) {
        const int phases = run == 1, threads = run == 2 ? 2 : 1;
        hearth_set_threads(threads);
        hearth_scene_def d = hearth_default_scene_def();
        d.dim = 2;
        d.dx = 1.0 / 128;
        d.damping = 3.0;
        hearth_scene *s = fx_scene_def(&d);
        s->mpm->colour_phases = phases;
        const int m = fx_elastic(s, 5e4, 0.3, 1000);
        const double c[3] = {0.5, 0.45, 0}, hh[3] = {0.15, 0.1, 0}, v[3] = {0.3, -1.5, 0};
        CHECK(fx_box(s, m, c, hh, 4, v) >= SCENE_PARALLEL_MIN); /* large enough for the gather */
        const double fc[3] = {0.5, 0.25, 0}, fh[3] = {0.4, 0.1, 0};
        CHECK(fx_box_collider(s, fc, fh, HEARTH_STICKY, 0.2) == 0);
        hearth_error err;
        CHECK(hearth_scene_step(s, 60, &err) == HEARTH_OK);
        CHECK((s->mpm->tiles_cap > 0) == !phases); /* the gather ran at one thread unless switched off */
        h[run] = hearth_scene_hash(s);
        printf("  %d thread(s), %s: %d particles, store %zu doubles, hash %016llx\n", threads,
               phases ? "colour phases (the switch)" : "the default path", s->ps.n, s->mpm->tiles_cap, (unsigned long long)h[run]);
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
    CHECK(h[0] == h[1]);
    CHECK(h[0] == h[2]);
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

/* The MPM step's scratch is MPM's (struct mpm_state, mpm.h): made with the
 * scene, grown by the sort, P2G's volumes only once heat or water is live;
 * and the memory estimate's scratch term is the sort's 16 bytes (order and
 * keys, the permutation working in the keys' room) and the volumes' 8, at
 * one thread. In 2D P2G's tile store is held too, at any thread count since
 * one thread gathers as well (mpm_p2g_gather.c, mpm_p2g_store_held): per particle block the halo of its 6x6 node tile
 * around its 4x4 block, 20 nodes, of mass and two momenta, 3 x 20 doubles
 * = 480 bytes, for 16 cells x 4 particles (s:add's default ppc): 7.5 bytes a
 * particle, the limit of a large body; a square of L cells at ppc 4 spans
 * L / 4 + 1 particle blocks a side (a particle's block is its B-spline base
 * node's, half a cell back), so its store holds 480 (L / 4 + 1)^2 bytes for
 * 4 L^2 particles: 9.49 a particle at L = 32, 8.14 at L = 96, counted here
 * from tiles_cap after a step at one thread and at two. The store lives in the room of
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
        const double store = 480.0 / 64; /* bytes a particle, as derived above, at 1 thread as at 2 */
        const double est = scene_bytes_per_particle(s), held = (double)s->mpm->tiles_cap * sizeof(double) / n;
        const double span = L / 4 + 1, counted = 480 * span * span / n;
        const double keys = 2.0 * sizeof(int) * s->mpm->scratch_cap, scratch = (double)s->mpm->scratch_bytes;
        printf("  %d thread(s), %d cells a side: %d particles, %d particle blocks, estimate %.2f bytes a particle "
               "(columns %.0f), store held %.2f bytes a particle (counted %.2f), the sort's scratch %.2f "
               "(order and keys %.2f)\n",
               threads, L, n, s->mpm->npb, est, cols, held, counted, scratch / n, keys / n);
        CHECK(est == cols + (2 * sizeof(int) > store ? 2 * sizeof(int) : store) + sizeof(double));
        CHECK(held == counted);
        CHECK(held >= store);
        /* the store in order and keys' block, which grew only by what it lacked */
        CHECK(s->mpm->tiles == (double *)(void *)s->mpm->keys);
        CHECK(scratch == (keys > held * n ? keys : held * n));
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
}

TEST(mpm_state_owned_by_solver) {
    hearth_set_threads(1); /* the tile store's term is mpm_store_in_estimate's */
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

TEST_MAIN(T(determinism_threads), T(checkpoint_restore), T(determinism_threads_sticky_damped), T(p2g_gather_matches_colour_phases), T(p2g_gather_one_thread_matches_colour_phases), T(determinism_threads_3d_claims), T(mpm_store_in_estimate), T(mpm_state_owned_by_solver))
