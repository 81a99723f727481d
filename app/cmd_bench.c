/* cmd_bench.c: `hearth bench`, the throughput of a standard elastic block.
 *
 * The problem is the one ../shared/bench/mpm_reference.c steps, so the two
 * can be compared in one run (scripts/bench/compare_reference.sh): a block
 * filling [0.2,0.8]^dim of the unit box at 8 particles per cell (4 in 2D),
 * neo-Hookean E = 1e5 Pa, nu = 0.3, rho = 1000, gravity, sticky walls,
 * dt = 1e-4 * 64 / cells. With --fields the same particles also carry heat
 * (an oven), or heat, CO2 and water (scripts/bench/fields_overhead.sh).
 *
 * --ranks (#21, docs/scaling.md): under `mpirun -n N` the same block over N
 * ranks, one JSON row for N, printed by rank 0; scripts/bench/ranks.sh runs
 * 1, 2 and 4 and makes the table. --weak widens the box and the block along
 * x by N (the slabs' axis), so every rank keeps the one-rank particle count.
 * The communication share is each rank's time inside its MPI exchanges over
 * the timed steps' wall time, the largest over the ranks; the bytes are those
 * a rank received per step, the largest too. The slabs stay between the
 * timed steps (hearth_scene_keep_slabs), as `hearth run` keeps them: the
 * whole-set gather at the end of a step call is a reader's cost, not a step's. */
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "hearth/hearth.h"
#include "progress.h"

int cmd_bench(int argc, char **argv) {
    long threads = 0, cells = 64, steps = 40, dim = 3;
    int ranks = 0, weak = 0;
    const char *fields = "none";
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--ranks") || !strcmp(a, "--weak")) {
            *(a[2] == 'r' ? &ranks : &weak) = 1;
            continue;
        }
        if (!strcmp(a, "--fields") && i + 1 < argc) {
            fields = argv[++i];
            if (strcmp(fields, "none") && strcmp(fields, "heat") && strcmp(fields, "all")) {
                fprintf(stderr, "hearth bench: --fields %s; valid: none, heat (an oven), all (heat, CO2 and water)\n", fields);
                return 2;
            }
            continue;
        }
        if (!strcmp(a, "--help")) {
            printf("usage: hearth bench [--threads N] [--cells N] [--steps N] [--dim 2|3] [--fields none|heat|all]\n"
                   "       mpirun -n N hearth bench --ranks [--weak] [--threads N] [--cells N] [--steps N] [--dim 2|3]\n"
                   "Steps an elastic block filling [0.2,0.8]^dim of a unit box with N cells per side\n"
                   "(default 64: about 440k particles in 3D) and prints JSON with particles, steps,\n"
                   "threads, seconds, particle_steps_per_s, bytes_per_particle (what particles and grid\n"
                   "fill), capacity_bytes_per_particle (held, spare room included) and\n"
                   "peak_bytes_per_particle (the most held at once).\n"
                   "--fields heat adds an oven (temperature); all adds leavening CO2 and water too.\n"
                   "A size whose particles cannot fit (count, or this machine's memory) is refused with the numbers.\n"
                   "--ranks: over mpirun's N ranks (a build with MPI), one JSON row for N: ranks, threads,\n"
                   "scaling (strong: the fixed block; --weak: box and block N times as long along x, so the\n"
                   "particles per rank stay fixed), particles, particles_per_rank, steps, seconds,\n"
                   "ms_per_step, particle_steps_per_s, comm_share (time inside MPI exchanges / step time,\n"
                   "the largest over the ranks), comm_seconds, bytes_received_per_step (the largest over\n"
                   "the ranks), slab_steps, replicated_steps. Without mpirun it prints the one-rank row.\n"
                   "scripts/bench/ranks.sh runs 1, 2 and 4 ranks and prints the scaling table.\n");
            return 0;
        }
        if (i + 1 >= argc) {
            fprintf(stderr, "hearth bench: %s needs a value (see --help)\n", a);
            return 2;
        }
        long *dst = !strcmp(a, "--threads") ? &threads : !strcmp(a, "--cells") ? &cells : !strcmp(a, "--steps") ? &steps
                  : !strcmp(a, "--dim")     ? &dim
                                            : NULL;
        if (!dst) {
            fprintf(stderr, "hearth bench: unknown option '%s' (see --help)\n", a);
            return 2;
        }
        /* --cells up to the grid's own limit per axis (grid.h's GRID_CELLS_MAX); the sizes that cannot fit are
         * refused below by their particle count, and by the library (grid blocks, memory) with its numbers */
        long lo = dst == &dim ? 2 : dst == &cells ? 16 : 1, hi = dst == &dim ? 3 : dst == &cells ? 1L << 22 : 1000000;
        if ((*dst = app_parse_int("bench", a, argv[++i], lo, hi)) < 0) return 2;
    }
    /* The block is 0.6 of the box per side at 2 particles per cell per axis: about (1.2 cells)^dim particles.
     * A scene holds at most INT_MAX / 2 (scene.c); refuse here, before the grid is made, with the largest size
     * that fits. Memory is the library's check at seeding (its bytes per particle against this machine's). */
    const double per_axis = 1.2 * (double)cells + 1.0, count = dim == 3 ? per_axis * per_axis * per_axis : per_axis * per_axis;
    if (count > (double)(INT_MAX / 2)) {
        const long most = (long)((dim == 3 ? cbrt((double)(INT_MAX / 2)) : sqrt((double)(INT_MAX / 2))) - 1.0) * 5 / 6;
        fprintf(stderr, "hearth bench: --cells %ld in %ldD gives about %.3g particles; a scene holds at most %d, so --cells is "
                        "at most %ld in %ldD\n", cells, dim, count, INT_MAX / 2, most, dim);
        return 2;
    }
    if (weak && !ranks) {
        fprintf(stderr, "hearth bench: --weak scales the block with the rank count; it goes with --ranks (see --help)\n");
        return 2;
    }
    if (ranks && hearth_ranks_size() == 1)
        fprintf(stderr, "hearth bench --ranks: %s, so this is the one-rank row; for N ranks: mpirun -n N hearth bench --ranks\n",
                hearth_ranks_built() ? "not started by mpirun" : "this hearth was built without MPI (meson -Dmpi=enabled with libopenmpi-dev)");
    if (threads > 0) hearth_set_threads((int)threads);
    const int N = ranks ? hearth_ranks_size() : 1;
    const double W = weak ? N : 1; /* the block's length along x, in units of the one-rank block's */

    hearth_scene_def d = hearth_default_scene_def();
    d.dim = (int)dim;
    d.dx = 1.0 / cells;
    if (weak) d.hi[0] = 0.4 + 0.6 * W; /* the block [0.2, 0.2 + 0.6 W] with 0.2 m either side */
    d.wall = HEARTH_STICKY;
    d.dt_max = 1e-4 * 64.0 / cells;
    d.cfl = 0.5;
    d.seed = 7;
    const int heat = strcmp(fields, "none") != 0, all = !strcmp(fields, "all");
    if (heat) {
        d.oven_temperature = 180;
        d.oven_beta = 10;
    }
    hearth_error err;
    hearth_scene *s = hearth_scene_create(&d, &err);
    const char *names[] = {"E", "nu", "density", "gas_rate", "water_diffusivity", "evaporation", "water_stiffness"};
    const double vals[] = {1e5, 0.3, 1000, 1e-3, 1e-10, 1e-6, 1e3};
    int mat = s ? hearth_scene_add_material(s, "elastic", names, vals, all ? 7 : 3, &err) : -1;
    const double c[3] = {0.2 + 0.3 * W, 0.5, dim == 3 ? 0.5 : 0.0}, h[3] = {0.3 * W, 0.3, 0.3};
    hearth_shape *box = hearth_shape_box(c, h);
    int n = mat >= 0 && box ? hearth_scene_seed_shape(s, mat, box, dim == 3 ? 8 : 4, 0.5, NULL, &err) : -1;
    hearth_shape_free(box);
    if (n <= 0) {
        fprintf(stderr, "hearth bench: %s\n", n == 0 ? "the block holds no particles" : err.msg);
        hearth_scene_destroy(s);
        return 1;
    }
    if (ranks) hearth_scene_keep_slabs(s, 1);
    /* one warm-up step sizes every buffer, so the timed steps measure the steady state */
    if (hearth_scene_step(s, 1, &err)) {
        fprintf(stderr, "hearth bench: %s\n", err.msg);
        hearth_scene_destroy(s);
        return 1;
    }
    double b0, c0, b1, c1;
    long slabs0, rep0, pass0, slabs1, rep1, pass1;
    hearth_ranks_traffic(&b0, &c0);
    hearth_ranks_steps(&slabs0, &rep0, &pass0);
    const double t0 = progress_wall();
    hearth_status rc = hearth_scene_step(s, (int)steps, &err);
    const double secs = progress_wall() - t0;
    hearth_ranks_traffic(&b1, &c1);
    hearth_ranks_steps(&slabs1, &rep1, &pass1);
    if (rc) {
        fprintf(stderr, "hearth bench: %s\n", err.msg);
        hearth_scene_destroy(s);
        return rc == HEARTH_ERR_GUARD ? 3 : 1;
    }
    if (ranks) {
        hearth_stats st;
        hearth_scene_stats(s, &st); /* particles: every rank's */
        const double share = hearth_ranks_max((c1 - c0) / secs), comm = hearth_ranks_max(c1 - c0),
                     bytes = hearth_ranks_max((b1 - b0) / (double)steps), wall = hearth_ranks_max(secs);
        if (hearth_ranks_rank() == 0)
            printf("{\"ranks\": %d, \"threads\": %d, \"scaling\": \"%s\", \"dim\": %ld, \"cells\": %ld, \"particles\": %d, "
                   "\"particles_per_rank\": %.1f, \"steps\": %ld, \"seconds\": %.6g, \"ms_per_step\": %.3f, "
                   "\"particle_steps_per_s\": %.6g, \"comm_share\": %.4f, \"comm_seconds\": %.6g, "
                   "\"bytes_received_per_step\": %.0f, \"slab_steps\": %ld, \"replicated_steps\": %ld}\n",
                   N, hearth_get_threads(), weak ? "weak" : "strong", dim, cells, st.particles, (double)st.particles / N, steps,
                   wall, 1e3 * wall / (double)steps, (double)st.particles * (double)steps / wall, share, comm, bytes,
                   slabs1 - slabs0, rep1 - rep0);
        hearth_scene_destroy(s);
        return 0;
    }
    /* bytes_per_particle: what particles and grid fill; capacity: what the library holds, spare room
     * included; peak: the most it held at once, seeding and growth included */
    const double held = (double)hearth_bytes_allocated();
    printf("{\"particles\": %d, \"steps\": %ld, \"threads\": %d, \"seconds\": %.4f, \"particle_steps_per_s\": %.6g, "
           "\"bytes_per_particle\": %.1f, \"capacity_bytes_per_particle\": %.1f, \"peak_bytes_per_particle\": %.1f, "
           "\"dim\": %ld, \"cells\": %ld, \"fields\": \"%s\"}\n",
           n, steps, hearth_get_threads(), secs, (double)n * steps / secs, (double)hearth_scene_bytes_used(s) / n, held / n,
           (double)hearth_bytes_peak() / n, dim, cells, hearth_scene_fields(s));
    hearth_scene_destroy(s);
    return 0;
}
