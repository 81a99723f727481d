/* unit_mpm_memory.c: what the MPM particle store and sort hold and how they
 * grow (issue 20): exact seeding reservations, growth by half, the peak
 * while columns grow, the sort keys G2P files, and the parallel bookkeeping's
 * results at one and two threads. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "grid.h"
#include "mpm_fixture.h"

#ifdef _OPENMP
#include <omp.h>
#endif

static hearth_scene *scene_2d(double dx) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 2;
    d.dx = dx;
    d.wall = HEARTH_SLIP;
    d.seed = 3;
    return fx_scene_def(&d);
}

static int seed_disc(hearth_scene *s, int mat, double cx, double cy, double r, double vx) {
    const double c[3] = {cx, cy, 0}, v[3] = {vx, -0.5, 0};
    hearth_shape *b = hearth_shape_sphere(c, r);
    hearth_error err;
    const int n = hearth_scene_seed_shape(s, mat, b, 4, 0.6, v, &err);
    hearth_shape_free(b);
    return n;
}

/* Seeding reserves exactly the particles it adds: no spare room after one
 * shape, nor after a second (the power-of-two growth left up to 2x). */
TEST(seed_reserves_exactly) {
    hearth_scene *s = scene_2d(1.0 / 128);
    const int m = fx_elastic(s, 1e5, 0.3, 1000);
    const int n1 = seed_disc(s, m, 0.4, 0.5, 0.15, 0);
    printf("  after one disc: n = %d, cap = %d\n", s->ps.n, s->ps.cap);
    CHECK(n1 > 4096); /* more than one chunk of the seeding loop */
    CHECK(s->ps.cap == n1);
    const int n2 = seed_disc(s, m, 0.7, 0.5, 0.1, 0);
    printf("  after two: n = %d, cap = %d\n", s->ps.n, s->ps.cap);
    CHECK(n2 > 0 && s->ps.cap == n1 + n2);
    hearth_scene_destroy(s);
}

/* Appends grow the store by half its capacity (not double), and a growth
 * that fails part way leaves the store's capacity, contents and byte count
 * as they were once it is freed. */
TEST(particles_grow_by_half) {
    particles ps;
    particles_init(&ps);
    hearth_error err;
    const size_t base = hearth_bytes_allocated();
    CHECK(particles_reserve(&ps, 1000, &err) == HEARTH_OK && ps.cap == 1000);
    ps.n = 1000;
    for (int i = 0; i < 3000; i++) pcold(&ps, PC_X)[i] = i;
    CHECK(particles_reserve(&ps, 1001, &err) == HEARTH_OK);
    printf("  1000 -> %d for 1001\n", ps.cap);
    CHECK(ps.cap == 1500);
    CHECK(particles_reserve(&ps, 4000, &err) == HEARTH_OK && ps.cap == 4000); /* a big ask is met exactly */
    int ok = 1;
    for (int i = 0; i < 3000; i++) ok &= pcold(&ps, PC_X)[i] == i;
    for (int i = 3000; i < 12000; i++) ok &= pcold(&ps, PC_X)[i] == 0; /* the new room is zeroed */
    CHECK(ok);
    particles_free(&ps);
    CHECK(hearth_bytes_allocated() == base);
    for (int k = 0; k < 8; k++) { /* a fresh store each time; its growth fails at column k */
        particles_init(&ps);
        CHECK(particles_reserve(&ps, 4000, &err) == HEARTH_OK);
        ps.n = 1000;
        for (int i = 0; i < 3000; i++) pcold(&ps, PC_X)[i] = i;
        mem_fail_after(k);
        const hearth_status st = particles_reserve(&ps, 9000, &err);
        mem_fail_after(-1);
        CHECK(st == HEARTH_ERR_NOMEM && ps.cap == 4000 && ps.n == 1000);
        CHECK(strstr(err.msg, "particle column") != NULL);
        ok = 1;
        for (int i = 0; i < 3000; i++) ok &= pcold(&ps, PC_X)[i] == i;
        CHECK(ok);
        CHECK(particles_reserve(&ps, 9000, &err) == HEARTH_OK && ps.cap == 9000); /* the grown columns are kept */
        particles_free(&ps);
        CHECK(hearth_bytes_allocated() == base); /* every column freed with its true size */
    }
}

/* Particles added in many small batches, with steps between: the most the
 * library ever holds stays within 1.25x of what it holds at the end (growing
 * every column at once held old and new copies: about 1.7x). */
TEST(growth_peak_bounded) {
    hearth_scene *s = scene_2d(1.0 / 128);
    const int m = fx_elastic(s, 1e5, 0.3, 1000);
    hearth_error err;
    enum { BATCH = 600 };
    static double x[3 * BATCH];
    int added = 0;
    for (int b = 0; b < 40; b++) {
        for (int i = 0; i < BATCH; i++) {
            const int q = b * BATCH + i;
            x[3 * i] = 0.1 + 0.8 * (q % 160) / 160.0;
            x[3 * i + 1] = 0.1 + 0.8 * (q / 160) / 160.0;
            x[3 * i + 2] = 0;
        }
        CHECK(hearth_scene_add_particles(s, m, BATCH, x, NULL, 1e-5, &err) == BATCH);
        added += BATCH;
        CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
    }
    const size_t held_now = hearth_bytes_allocated(), held_peak = hearth_bytes_peak(); /* the test's process held nothing before */
    const double ratio = (double)held_peak / (double)held_now;
    printf("  %d particles: %zu bytes held at the end, peak %zu (%.3fx); cap %d\n", added, held_now, held_peak, ratio,
           s->ps.cap);
    CHECK(s->ps.cap < 1.5 * added + 1);
    CHECK(ratio <= 1.25);
    hearth_scene_destroy(s);
}

/* The block keys G2P files are those of the positions it leaves, and a scene
 * whose sort recomputes them every step (as it did) runs the same bits. */
TEST(sort_keys_from_g2p) {
    hearth_scene *a = scene_2d(1.0 / 96), *b = scene_2d(1.0 / 96);
    hearth_scene *sc[2] = {a, b};
    for (int k = 0; k < 2; k++) {
        const int m = fx_elastic(sc[k], 1e5, 0.3, 1000);
        CHECK(seed_disc(sc[k], m, 0.3, 0.6, 0.12, 3.0) > 0);
        fx_box_collider(sc[k], (double[3]){0.7, 0.3, 0}, (double[3]){0.05, 0.2, 0}, HEARTH_SLIP, -0.5);
    }
    hearth_error err;
    long recomputed = 0;
    for (int step = 0; step < 60; step++) {
        b->mpm->keys_n = -1; /* b's sort files every particle itself */
        CHECK(hearth_scene_step(a, 1, &err) == HEARTH_OK && hearth_scene_step(b, 1, &err) == HEARTH_OK);
        const mpm_state *m = a->mpm;
        CHECK(m->keys_n == a->ps.n && m->keys_step == a->step);
        const double *X = pcold(&a->ps, PC_X);
        for (int i = 0; i < a->ps.n; i++) {
            int bb[3] = {0, 0, 0};
            for (int d = 0; d < 2; d++) bb[d] = (int)floor((X[3 * i + d] - a->g.lo[d]) * a->g.inv_dx - 0.5) / GRID_B;
            recomputed += m->keys[i] != grid_block_id(&a->g, bb[0], bb[1], bb[2]);
        }
    }
    hearth_stats sa, sb;
    hearth_scene_stats(a, &sa);
    hearth_scene_stats(b, &sb);
    printf("  keys that differ from the positions' blocks: %ld; hashes %016llx %016llx; out of domain %ld %ld\n", recomputed,
           (unsigned long long)hearth_scene_hash(a), (unsigned long long)hearth_scene_hash(b), a->out_of_domain, b->out_of_domain);
    CHECK(recomputed == 0);
    CHECK(hearth_scene_hash(a) == hearth_scene_hash(b));
    CHECK(sa.particles == sb.particles && a->out_of_domain == b->out_of_domain);
    hearth_scene_destroy(a);
    hearth_scene_destroy(b);
}

/* The parallel counting sort, block lists and grid activation (a table of
 * more than 16384 blocks, so grid_activate splits it too): one and two
 * threads give the same bits, with particles crossing blocks every step. */
TEST(determinism_threads_2d_bookkeeping) {
    uint64_t h[2];
    for (int t = 1; t <= 2; t++) {
        hearth_set_threads(t);
        hearth_scene *s = scene_2d(1.0 / 512);
        CHECK(s->g.nblocks > 16384);
        const int m = fx_elastic(s, 1e5, 0.3, 1000);
        CHECK(seed_disc(s, m, 0.3, 0.6, 0.07, 4.0) > 0);
        CHECK(seed_disc(s, m, 0.6, 0.5, 0.05, -4.0) > 0);
        CHECK(s->ps.n >= SCENE_PARALLEL_MIN); /* so the step really runs on two threads */
        CHECK(s->ps.n >= s->g.nblocks);       /* and the sort counts in chunks (mpm_sort: 2 x blocks <= 2 x particles) */
        hearth_error err;
        CHECK(hearth_scene_step(s, 25, &err) == HEARTH_OK); /* about 3 cells of travel: blocks change every step */
        h[t - 1] = hearth_scene_hash(s);
        printf("  %d thread(s): %d particles, %d active blocks, hash %016llx\n", t, s->ps.n, s->g.nactive,
               (unsigned long long)h[t - 1]);
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
    CHECK(h[0] == h[1]);
}

/* The gather's one-region step (2D, two threads, a table of fewer than
 * 16384 blocks: the sort's count, lists and grid activation run in the
 * step's region, mpm_sort_begin): the same bits as one thread and as the
 * separate regions of the colour phases (HEARTH_MPM_COLOUR_PHASES=1), with
 * particles crossing blocks (permutations in the region) and a disc added
 * mid-run (the particle blocks, the grid and the tile store grow in the
 * region's singles). */
static uint64_t one_region_run(int threads, int phases, long *permuted, int *nblocks) {
    if (phases) setenv("HEARTH_MPM_COLOUR_PHASES", "1", 1);
    hearth_set_threads(threads);
    hearth_scene *s = scene_2d(1.0 / 160);
    unsetenv("HEARTH_MPM_COLOUR_PHASES");
    const int m = fx_elastic(s, 1e5, 0.3, 1000);
    hearth_error err;
    uint64_t h = 0;
    if (seed_disc(s, m, 0.3, 0.6, 0.12, 3.0) <= 0 || hearth_scene_step(s, 10, &err) != HEARTH_OK) goto out;
    const unsigned long e0 = s->ps.edits;
    if (seed_disc(s, m, 0.7, 0.4, 0.08, -3.0) <= 0 || hearth_scene_step(s, 20, &err) != HEARTH_OK) goto out;
    *permuted = (long)(s->ps.edits - e0) - 1; /* the seeding's edit aside: the sorts that moved particles */
    *nblocks = s->g.nblocks;
    h = hearth_scene_hash(s);
    printf("  %d thread(s)%s: %d particles, %d blocks of the box, %d particle blocks, %ld permuting sorts, hash %016llx\n",
           threads, phases ? ", colour phases" : "", s->ps.n, s->g.nblocks, s->mpm->npb, *permuted, (unsigned long long)h);
    CHECK(s->ps.n >= SCENE_PARALLEL_MIN && 2 * s->g.nblocks <= 2 * s->ps.n); /* two threads, the chunked count */
out:
    hearth_scene_destroy(s);
    return h;
}

TEST(determinism_threads_one_region_sort) {
    long perm[3] = {0, 0, 0};
    int nb = 0;
    const uint64_t h1 = one_region_run(1, 0, &perm[0], &nb), h2 = one_region_run(2, 0, &perm[1], &nb),
                   hp = one_region_run(2, 1, &perm[2], &nb);
    hearth_set_threads(0);
    CHECK(nb < GRID_ACTIVATE_PARALLEL_MIN); /* the activation in the region is the sort's own (not the big box's) */
    CHECK(perm[1] > 0);                     /* keys out of order: the permutation ran in the step's region */
    CHECK(h1 != 0 && h1 == h2 && h1 == hp);
}

/* The one-region step's share-out (mpm.c's span_next): P2G, the grid update
 * and G2P each hand a chunk's blocks first to the thread that owns it, from
 * the front, and a thread done with its own takes from the back of the
 * others'. 1, 2, 3 and 4 threads (more threads than this machine's cores, so
 * threads come late and the others take from their chunks), with damping (the
 * grid update's other branch) and particles crossing blocks: the same bits. */
static uint64_t share_out_run(int threads, long blocks[3], long back[3]) {
    hearth_set_threads(threads);
    hearth_scene *s = scene_2d(1.0 / 160);
    s->def.damping = 2.0;
    const int m = fx_elastic(s, 1e5, 0.3, 1000);
    hearth_error err;
    uint64_t h = 0;
    if (seed_disc(s, m, 0.3, 0.6, 0.12, 3.0) <= 0 || seed_disc(s, m, 0.7, 0.4, 0.1, -3.0) <= 0 ||
        hearth_scene_step(s, 30, &err) != HEARTH_OK)
        goto out;
    h = hearth_scene_hash(s);
    for (int p = 0; p < 3; p++) blocks[p] = s->mpm->span_blocks[p], back[p] = s->mpm->span_back[p];
    printf("  %d thread(s): %d particles, hash %016llx; blocks taken from another thread's chunk: P2G %ld of %ld, "
           "grid %ld of %ld, G2P %ld of %ld\n", threads, s->ps.n, (unsigned long long)h, back[MPM_SPAN_P2G],
           blocks[MPM_SPAN_P2G], back[MPM_SPAN_GRID], blocks[MPM_SPAN_GRID], back[MPM_SPAN_G2P], blocks[MPM_SPAN_G2P]);
    CHECK(s->ps.n >= SCENE_PARALLEL_MIN && s->g.nblocks <= s->ps.n); /* the chunked count: the one-region step */
out:
    hearth_scene_destroy(s);
    return h;
}

TEST(determinism_threads_one_region_share_out) {
    uint64_t h[4];
    long blocks[4][3], back[4][3];
    for (int t = 1; t <= 4; t++) h[t - 1] = share_out_run(t, blocks[t - 1], back[t - 1]);
    hearth_set_threads(0);
    CHECK(h[0] != 0 && h[0] == h[1] && h[0] == h[2] && h[0] == h[3]);
    CHECK(blocks[0][MPM_SPAN_P2G] == 0); /* one thread: the colour phases, no share-out */
    for (int t = 2; t <= 4; t++)
        for (int p = 0; p < 3; p++) { /* every step went the one-region way, and no block was taken twice */
            CHECK(blocks[t - 1][p] > 0 && blocks[t - 1][p] == blocks[1][p]);
            CHECK(back[t - 1][p] >= 0 && back[t - 1][p] <= blocks[t - 1][p]);
        }
}

/* The team waits (team_wait.c) against the OpenMP barrier (HEARTH_TEAM_SPIN=0)
 * and a 1 us spin (mostly sleeps; at 3 threads on this machine's 2 cores a
 * thread is often late, so the counts of finished work let the others on
 * without it): 2D's one-region step (sort, P2G, grid update, permutations)
 * and 3D's claimed step and separate sort, the same bits at 1, 2 and 3
 * threads. The waits counter says which path ran: none with the OpenMP
 * barrier, some with the spin. */
static uint64_t team_run(int dim, int threads, const char *spin, long *waits) {
    if (spin) setenv("HEARTH_TEAM_SPIN", spin, 1);
    hearth_set_threads(threads);
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = dim;
    d.dx = dim == 2 ? 1.0 / 160 : 1.0 / 40;
    d.wall = HEARTH_SLIP;
    d.seed = 3;
    hearth_scene *s = fx_scene_def(&d);
    unsetenv("HEARTH_TEAM_SPIN");
    const int m = fx_elastic(s, 1e5, 0.3, 1000);
    hearth_error err;
    uint64_t h = 0;
    const int n = dim == 2 ? seed_disc(s, m, 0.3, 0.6, 0.12, 3.0) + seed_disc(s, m, 0.7, 0.4, 0.1, -3.0)
                           : seed_disc(s, m, 0.4, 0.5, 0.2, 3.0);
    if (n <= 0 || hearth_scene_step(s, 20, &err) != HEARTH_OK) goto out;
    h = hearth_scene_hash(s);
    *waits = s->mpm->team.waits;
    printf("  %dD, %d thread(s), HEARTH_TEAM_SPIN=%s: %d particles, hash %016llx, late-partner waits %ld, slept %ld\n", dim,
           threads, spin ? spin : "(unset)", s->ps.n, (unsigned long long)h, s->mpm->team.waits, s->mpm->team.sleeps);
    CHECK(s->ps.n >= SCENE_PARALLEL_MIN);
out:
    hearth_scene_destroy(s);
    return h;
}

TEST(team_waits_same_bits) {
    for (int dim = 2; dim <= 3; dim++) {
        long w = 0;
        const uint64_t h1 = team_run(dim, 1, NULL, &w);
        CHECK(h1 != 0 && w == 0); /* one thread waits for no one */
        for (int t = 2; t <= 3; t++) {
            long wo = -1, ws = 0, w1 = 0;
            CHECK(team_run(dim, t, "0", &wo) == h1);
            CHECK(wo == 0); /* the OpenMP barrier: the team waits never ran */
            CHECK(team_run(dim, t, NULL, &ws) == h1);
            CHECK(team_run(dim, t, "1", &w1) == h1);
            CHECK(ws + w1 > 0); /* the team waits ran and found a partner late */
        }
    }
    hearth_set_threads(0);
}

/* An allocation failing inside the one-region step (the sort's singles, the
 * tile store) comes back as an error from the step, on every thread alike
 * (no thread left at a barrier): each of the step's allocations after a disc
 * is added, failed in turn. */
TEST(one_region_sort_out_of_memory) {
    hearth_set_threads(2);
    int failed = 0, k;
    for (k = 0; k < 40; k++) {
        hearth_scene *s = scene_2d(1.0 / 160);
        const int m = fx_elastic(s, 1e5, 0.3, 1000);
        hearth_error err;
        CHECK(seed_disc(s, m, 0.3, 0.6, 0.12, 3.0) > 0 && hearth_scene_step(s, 2, &err) == HEARTH_OK);
        CHECK(seed_disc(s, m, 0.7, 0.4, 0.08, -3.0) > 0);
        mem_fail_after(k);
        const hearth_status st = hearth_scene_step(s, 1, &err);
        mem_fail_after(-1);
        if (st != HEARTH_OK) {
            CHECK(st == HEARTH_ERR_NOMEM);
            printf("  allocation %d failed: %s\n", k, err.msg);
            failed++;
        }
        hearth_scene_destroy(s);
        if (st == HEARTH_OK) break; /* the step makes fewer allocations than k */
    }
    hearth_set_threads(0);
    printf("  %d of the step's allocations failed in turn, each an error from the step; allocation %d is past them\n", failed, k);
    CHECK(failed > 0 && k < 40);
}

/* The permutation tests' columns: every value tells its column and place
 * (1000 c + i; doubles + 0.25). */
static void permute_fill(particles *ps, const int n) {
    for (int c = 0; c < PC_COUNT; c++) {
        if (!(ps->enabled & (1u << c))) continue;
        const int nc = particles_col_ncomp(ps, c);
        for (int i = 0; i < n * nc; i++) {
            if (particles_col_is_int(c)) pcoli(ps, c)[i] = 1000 * c + i;
            else pcold(ps, c)[i] = 1000.0 * c + i + 0.25;
        }
    }
}

/* kind 0: runs shifted by a few dozen places, as a sort after a step makes
 * (each rotated run's place i takes i + 39); 1: a scattered order, i 2713 mod
 * n (2713 is prime and divides neither test's n); 2: a few places moved, over
 * places that keep theirs (every 500 places, i and i + 30 swapped and a
 * three-cycle of i + 7, i + 9, i + 12; the first and last places among them):
 * the passes skip the kept places, and a moved place's source lies across
 * some of them */
static void permute_order(int *order, const int n, const int kind) {
    for (int i = 0; i < n; i++) order[i] = i;
    if (kind == 0)
        for (int i = 0; i + 40 < n; i += 97) {
            const int last = order[i + 39];
            memmove(order + i + 1, order + i, sizeof(int) * 39);
            order[i] = last;
        }
    else if (kind == 1)
        for (int i = 0; i < n; i++) order[i] = (int)(((long)i * 2713) % n);
    else {
        for (int i = 0; i + 30 < n; i += 500) {
            order[i] = i + 30, order[i + 30] = i;
            order[i + 7] = i + 9, order[i + 9] = i + 12, order[i + 12] = i + 7;
        }
        order[n - 1] = n - 2, order[n - 2] = n - 1;
    }
}

/* The values not where order sends them (place i holds what place order[i] held). */
static int permute_wrong(const particles *ps, const int *order, const int n) {
    int bad = 0;
    for (int c = 0; c < PC_COUNT; c++) {
        if (!(ps->enabled & (1u << c))) continue;
        const int nc = particles_col_ncomp(ps, c);
        for (int i = 0; i < n; i++)
            for (int k = 0; k < nc; k++) {
                const long want = 1000L * c + (long)order[i] * nc + k;
                bad += particles_col_is_int(c) ? pcoli(ps, c)[i * nc + k] != want
                                               : pcold(ps, c)[i * nc + k] != (double)want + 0.25;
            }
    }
    return bad;
}

static const char *const kind_name[3] = {"shifted", "scattered", "sparse"};

/* particles_permute gives new[i] = old[order[i]] in every column, whether
 * the particles moved a little (the window through a ring, whole records)
 * or anywhere (following the cycles), at one and two threads, through n
 * doubles of scratch (SPH's) or n ints (MPM's keys; there with a plugin
 * state of 40 doubles, wider than the cycles' 256-byte slice). */
TEST(particles_permute_orders) {
    hearth_error err;
    for (int ints = 0; ints < 2; ints++)
    for (int kind = 0; kind < 3; kind++)
        for (int t = 1; t <= 2; t++) {
            hearth_set_threads(t);
            particles ps;
            particles_init(&ps);
            const int n = 6000, stride = ints ? 40 : 5;
            CHECK(particles_enable(&ps, PC_FLAGS, &err) == HEARTH_OK && particles_set_state_stride(&ps, stride, &err) == HEARTH_OK);
            CHECK(particles_reserve_exact(&ps, n, &err) == HEARTH_OK);
            ps.n = n;
            permute_fill(&ps, n);
            int *order = malloc(sizeof(int) * n);
            const size_t room = (ints ? sizeof(int) : sizeof(double)) * (size_t)n;
            void *scratch = malloc(room);
            permute_order(order, n, kind);
            particles_permute(&ps, order, scratch, room);
            const int bad = permute_wrong(&ps, order, n);
            printf("  %s order, %d thread(s), n %s of scratch: %d wrong values\n", kind_name[kind], t,
                   ints ? "ints" : "doubles", bad);
            CHECK(bad == 0);
            free(order);
            free(scratch);
            particles_free(&ps);
        }
    hearth_set_threads(0);
}

/* particles_permute_team_range: each thread of a team moves its own places
 * of every column, with the records within W outside them saved before the
 * team's barrier. Ranges of 1-4 threads, uneven, one empty and two shorter
 * than W; a shifted order (W 39: by places), a sparse one (W 30: by places,
 * some sources across a range's edge) and a scattered one (W near n: by
 * columns, particles_permute_team): every value where the order sends it. */
TEST(particles_permute_team_range_orders) {
    static const int split[5][5] = {{0}, {0, 40000}, {0, 24713, 40000}, {0, 7000, 7000, 40000}, {0, 20, 16000, 16030, 40000}};
    hearth_error err;
    for (int kind = 0; kind < 3; kind++)
        for (int P = 1; P <= 4; P++) {
            particles ps;
            particles_init(&ps);
            const int n = 40000; /* the keys' 4 n bytes hold each of 4 threads' saved records at W 39 */
            CHECK(particles_enable(&ps, PC_FLAGS, &err) == HEARTH_OK && particles_set_state_stride(&ps, 5, &err) == HEARTH_OK);
            CHECK(particles_reserve_exact(&ps, n, &err) == HEARTH_OK);
            ps.n = n;
            permute_fill(&ps, n);
            int *order = malloc(sizeof(int) * n);
            const size_t room = sizeof(int) * (size_t)n; /* the MPM sort's keys */
            void *scratch = malloc(room);
            permute_order(order, n, kind);
            int W = 0;
            for (int i = 0; i < n; i++) W = abs(order[i] - i) > W ? abs(order[i] - i) : W;
            const unsigned long e0 = ps.edits;
            int ranges[4] = {-1, -1, -1, -1};
#pragma omp parallel num_threads(P)
            {
                int me = 0;
#ifdef _OPENMP
                me = omp_get_thread_num();
#endif
                if (omp_get_num_threads() == P)
                    ranges[me] = particles_permute_team_range(&ps, order, W, scratch, room, split[P][me], split[P][me + 1], NULL);
            }
            const int bad = permute_wrong(&ps, order, n);
            printf("  %s order (W %d), %d thread(s), by %s: %d wrong values\n", kind_name[kind], W, P,
                   ranges[0] == 1 ? "places" : ranges[0] == 0 ? "columns" : "?", bad);
            CHECK(bad == 0 && ps.edits == e0 + 1);
            for (int t = 0; t < P; t++) CHECK(ranges[t] == (kind != 1)); /* every thread alike: W 39 and 30 fit, W ~n does not */
            free(order);
            free(scratch);
            particles_free(&ps);
        }
}

/* At two threads a 2D step keeps each particle block's P2G tile, and the
 * tiles' halo store lives in the room of the sort's order and keys (dead from
 * the end of the sort until G2P files the next keys, after the gather:
 * mpm_p2g_gather.c). A square of 32 cells at ppc 4 needs 9.49 bytes a
 * particle of store against their 8, so the scratch block grows, exactly, in
 * the step. With every allocation of the first step made to fail in turn,
 * each failure is reported (one of them the store's, by name), the scene
 * steps on after it to the same bits as a run that never failed (the sort's
 * scratch made again), and every byte is freed with its size. */
static hearth_scene *store_scene(int *n) {
    hearth_scene *s = scene_2d(0.5 / 32);
    const int m = fx_elastic(s, 1e4, 0.3, 1000);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.25, 0.25, 0}, v[3] = {0.2, -0.3, 0};
    *n = fx_box(s, m, c, h, 4, v);
    return s;
}

TEST(gather_store_in_sort_scratch) {
    hearth_set_threads(2);
    const size_t before = hearth_bytes_allocated();
    int n;
    hearth_error err;
    hearth_scene *s = store_scene(&n);
    CHECK(n >= SCENE_PARALLEL_MIN);
    CHECK(hearth_scene_step(s, 3, &err) == HEARTH_OK);
    const uint64_t h0 = hearth_scene_hash(s);
    const mpm_state *m = mpm_state_of(s);
    const double store = (double)m->tiles_cap * sizeof(double);
    printf("  %d particles, %d particle blocks: store %.2f bytes a particle, the sort's scratch %.2f (order and keys "
           "%.2f), hash %016llx\n",
           n, m->npb, store / n, (double)m->scratch_bytes / n, 8.0 * m->scratch_cap / n, (unsigned long long)h0);
    CHECK(store > 8.0 * m->scratch_cap); /* the case that grows the block */
    CHECK(m->tiles == (const double *)(const void *)m->keys && (double)m->scratch_bytes == store);
    hearth_scene_destroy(s);
    const size_t base = hearth_bytes_allocated(); /* the plugin cache keeps its first entry */
    printf("  held after the first scene: %zu bytes more than before it\n", base - before);
    CHECK(base - before <= 4096);
    int failures = 0, store_failures = 0;
    for (long k = 0; k < 100; k++) {
        s = store_scene(&n);
        mem_fail_after(k);
        const hearth_status st = hearth_scene_step(s, 1, &err);
        mem_fail_after(-1);
        if (st == HEARTH_OK) {
            hearth_scene_destroy(s);
            break;
        }
        failures++;
        CHECK(st == HEARTH_ERR_NOMEM);
        const int named = strstr(err.msg, "P2G's tiles") != NULL;
        store_failures += named;
        if (named) printf("  injected failure %ld: %s\n", k, err.msg);
        CHECK(hearth_scene_step(s, 3, &err) == HEARTH_OK); /* on after the failure, all of it again */
        const uint64_t h = hearth_scene_hash(s);
        if (h != h0) printf("  injected failure %ld (%s): hash %016llx after 3 steps\n", k, err.msg, (unsigned long long)h);
        CHECK(h == h0);
        hearth_scene_destroy(s);
        CHECK(hearth_bytes_allocated() == base);
    }
    printf("  %d allocations of the first step failed in turn, %d of them the store's\n", failures, store_failures);
    CHECK(failures > 0 && store_failures == 1);
    hearth_set_threads(0);
}

/* Zero bytes are not out of memory (#21): a rank whose slab holds no
 * particle sizes its step scratch by 0, and a NULL from mem_alloc(0) was
 * reported as "out of memory for 0 particle volumes" on that rank alone. The
 * empty block is non-NULL, costs no bytes, takes no injected failure, frees
 * and grows like NULL. */
TEST(alloc_zero_is_not_out_of_memory) {
    const size_t before = hearth_bytes_allocated();
    void *a = mem_alloc(0), *c = mem_calloc(0);
    printf("  mem_alloc(0) = %p, mem_calloc(0) = %p, bytes held %zu -> %zu\n", a, c, before, hearth_bytes_allocated());
    CHECK(a != NULL && c != NULL);
    CHECK(hearth_bytes_allocated() == before);
    mem_fail_after(0); /* the next real allocation fails: a zero-byte one is not one */
    void *z = mem_alloc(0);
    void *f = mem_alloc(8);
    mem_fail_after(-1);
    printf("  with a failure injected: mem_alloc(0) = %p, mem_alloc(8) = %p\n", z, f);
    CHECK(z != NULL && f == NULL);
    double *g = mem_realloc(a, 0, 4 * sizeof(double)); /* grows from the empty block as from NULL */
    CHECK(g != NULL);
    for (int i = 0; i < 4; i++) g[i] = i;
    CHECK(hearth_bytes_allocated() == before + 4 * sizeof(double));
    void *e = mem_realloc(g, 4 * sizeof(double), 0); /* shrinking to nothing frees it and gives the empty block */
    printf("  grown to 32 bytes and back to 0: %p, bytes held %zu\n", e, hearth_bytes_allocated());
    CHECK(e != NULL && hearth_bytes_allocated() == before);
    mem_free(e, 0);
    mem_free(c, 0);
    mem_free(z, 123); /* the empty block never came from the hook: any size frees nothing */
    CHECK(hearth_bytes_allocated() == before);
}

TEST_MAIN(T(seed_reserves_exactly), T(alloc_zero_is_not_out_of_memory), T(particles_grow_by_half), T(growth_peak_bounded), T(sort_keys_from_g2p),
          T(determinism_threads_2d_bookkeeping), T(determinism_threads_one_region_sort), T(determinism_threads_one_region_share_out), T(one_region_sort_out_of_memory),
          T(particles_permute_orders), T(particles_permute_team_range_orders), T(gather_store_in_sort_scratch),
          T(team_waits_same_bits))
