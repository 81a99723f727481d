/* unit_ranks.c: the MPM step's split among MPI ranks (core/sim/solver/
 * mpm_ranks.c) without MPI: the partition for any rank count, checked on
 * one process by giving the state a rank count by hand, and the one-rank
 * path. These run in the sanitizer pass too (a build without MPI), where
 * the mpi suite skips. */
#include <string.h>

#include "alloc.h"
#include "mpm_fixture.h"
#include "ranks.h"

/* s's MPM state as if the run had n ranks (this process is rank 0) */
static void set_ranks(hearth_scene *s, int n) {
    mpm_state *m = s->mpm;
    mpm_ranks_free(m);
    m->nranks = n;
    m->kfirst = mem_calloc(sizeof(int) * ((size_t)n + 1));
    m->pfirst = mem_calloc(sizeof(int) * ((size_t)n + 1));
}

/* Runs of particle blocks, one per rank, in block order, covering every
 * block once, each within one block's particles of n / N. */
TEST(ranks_partition_balanced) {
    hearth_scene *s = fx_scene(2, 1.0 / 64, 0, 1);
    CHECK(s != NULL);
    if (!s) return;
    const int mat = fx_elastic(s, 1e4, 0.3, 1000);
    const double c[3] = {0.45, 0.4, 0}, h[3] = {0.3, 0.15, 0};
    const int n = fx_box(s, mat, c, h, 4, NULL);
    CHECK(n > 1000);
    hearth_error err;
    CHECK(hearth_scene_step(s, 3, &err) == HEARTH_OK);
    const mpm_state *m = s->mpm;
    int biggest = 0;
    for (int k = 0; k < m->npb; k++)
        if (m->pb[k].end - m->pb[k].start > biggest) biggest = m->pb[k].end - m->pb[k].start;
    const int counts[] = {2, 3, 4, 7};
    for (size_t q = 0; q < sizeof counts / sizeof *counts; q++) {
        const int N = counts[q];
        set_ranks(s, N);
        mpm_ranks_partition(s);
        CHECK(m->kfirst[0] == 0 && m->kfirst[N] == m->npb);
        CHECK(m->pfirst[0] == 0 && m->pfirst[N] == n);
        CHECK(m->k_lo == m->kfirst[0] && m->k_hi == m->kfirst[1]); /* this process is rank 0 */
        for (int r = 0; r < N; r++) {
            CHECK(m->kfirst[r] <= m->kfirst[r + 1]);
            CHECK(m->pfirst[r] == (m->kfirst[r] < m->npb ? m->pb[m->kfirst[r]].start : n));
            const int mine = m->pfirst[r + 1] - m->pfirst[r];
            if (abs(mine * N - n) > biggest * N)
                printf("  %d ranks: rank %d has %d particles of %d (largest block %d)\n", N, r, mine, n, biggest);
            CHECK(abs(mine * N - n) <= biggest * N);
        }
        printf("  %d ranks: particles per rank", N);
        for (int r = 0; r < N; r++) printf(" %d", m->pfirst[r + 1] - m->pfirst[r]);
        printf(" (n = %d, largest block %d)\n", n, biggest);
    }
    set_ranks(s, 1); /* as the scene was made, so it frees what it holds */
    CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
    hearth_scene_destroy(s);
}

/* Without mpirun (and in a build without MPI) there is one rank, the step
 * walks every block, and nothing is exchanged. */
TEST(ranks_one_process) {
    CHECK(hearth_ranks_size() == 1 && hearth_ranks_rank() == 0);
    CHECK(ranks_size() == 1 && ranks_rank() == 0);
    hearth_scene *s = fx_scene(2, 1.0 / 32, 0, 1);
    CHECK(s != NULL);
    if (!s) return;
    const int mat = fx_elastic(s, 1e4, 0.3, 1000);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.2, 0.1, 0};
    CHECK(fx_box(s, mat, c, h, 4, NULL) > 0);
    hearth_error err;
    CHECK(hearth_scene_step(s, 2, &err) == HEARTH_OK);
    CHECK(s->mpm->nranks == 1 && s->mpm->k_lo == 0 && s->mpm->k_hi == s->mpm->npb && s->mpm->npb > 0);
    double bytes = -1, seconds = -1;
    hearth_ranks_traffic(&bytes, &seconds);
    CHECK(bytes == 0 && seconds == 0);
    hearth_scene_destroy(s);
    hearth_ranks_finalize(); /* a no-op here, and safe twice */
    hearth_ranks_finalize();
}

TEST_MAIN(T(ranks_partition_balanced), T(ranks_one_process))
