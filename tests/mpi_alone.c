/* mpi_alone.c: a step that fails on one MPI rank alone must end the run, not
 * leave every rank waiting (#21). Run under mpirun by tests/mpi_test.sh
 * (mpi_lone_failure_ends_every_rank_4). A block thrown along a long box fills
 * the right end's rank, empty at first, after a few dozen steps; that rank's
 * next allocation is made to fail (mem_fail_after), so it fails a step the
 * others do not. Then, as `hearth run` does, the host reads stats() and, in
 * mode "gather", lets the step call gather the slabs; those were collectives
 * the failed rank entered while the others waited in a neighbour exchange.
 * Each rank prints its status; the failed one exits 3 without MPI_Finalize
 * (app/main.c), and mpirun ends the others. */
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "alloc.h"
#include "mpm_fixture.h"

int main(int argc, char **argv) {
    hearth_ranks_init(&argc, &argv);
    const int N = hearth_ranks_size(), me = hearth_ranks_rank();
    const int keep = argc > 1 && !strcmp(argv[1], "stats"); /* else "gather": each step call gathers the slabs */
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 2;
    d.dx = 1.0 / 64;
    d.lo[0] = d.lo[1] = 0;
    d.hi[0] = 2, d.hi[1] = 0.5;
    d.wall = HEARTH_SLIP;
    if (keep) d.oven_temperature = 200, d.oven_beta = 40; /* heat: stats() adds its sums over the ranks */
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return 1;
    const char *n[] = {"E", "nu", "density", "specific_heat", "conductivity"};
    const double v[] = {5e4, 0.3, 1000, 3000, 5};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "elastic", n, v, keep ? 5 : 3, &err);
    if (m < 0) return fprintf(stderr, "material: %s\n", err.msg), 1;
    const double c[3] = {0.15, 0.21, 0}, h[3] = {0.07, 0.09, 0}, vel[3] = {4, -0.5, 0};
    if (fx_box(s, m, c, h, 4, vel) <= 0) return 1;
    hearth_scene_keep_slabs(s, keep);
    hearth_status st = hearth_scene_step(s, 1, &err); /* the slabs and every table are set up */
    if (st) return fprintf(stderr, "rank %d: the first step failed: %s\n", me, err.msg), 1;
    if (me == N - 1) mem_fail_after(0); /* its next allocation fails: when the block's particles first reach it */
    st = hearth_scene_step(s, 400, &err);
    mem_fail_after(-1);
    hearth_stats stats;
    hearth_scene_stats(s, &stats);
    printf("rank %d of %d (%s): step call status %d after step %ld%s%s\n", me, N, keep ? "stats" : "gather", (int)st, stats.step,
           st ? ": " : "", st ? err.msg : "");
    if (st) { /* as app/main.c leaves a failed run over ranks */
        hearth_status again = hearth_scene_step(s, 1, &err);
        printf("rank %d: a further step: status %d: %s\n", me, (int)again, again ? err.msg : "");
        fflush(stdout);
        _exit(3);
    }
    hearth_scene_destroy(s);
    hearth_ranks_finalize();
    return 0;
}
