/* mpm_ranks.c: one MPM scene over MPI ranks, the first working step (#21).
 *
 * What this is, plainly: a replicated scene with the particle work split.
 * Every rank holds every particle and the whole grid. After the sort (the
 * same on every rank), the particle blocks are cut into one contiguous run
 * per rank, balanced by particle count; block ids are x-major, so a run is a
 * slab along x (its two end faces ragged by block columns). Each rank runs
 * P2G and G2P for its own run only. After P2G the written node slots are
 * summed over the ranks in rank order (ranks_sum_grid), every rank runs the
 * grid update (and any field pass) on the whole grid, and after G2P every
 * rank's particles and block partials go to every rank (ranks_allgather), so
 * the next sort, the guard, probes, outputs and checkpoints see the whole
 * scene on every rank, exactly the same. A guard stop is therefore the same
 * decision on every rank with the same diagnosis: all ranks stop together.
 *
 * This is not domain decomposition: the memory per rank is the whole scene
 * and the messages per step grow with the whole particle count, not with a
 * slab's surface (docs/scaling.md has the model and the measurements). It is
 * the honest first step the issue allows: exact bookkeeping first, the halo
 * and migration of true slabs next, on top of the same partition.
 *
 * Rejected: MPI_Allreduce for the grid (its summation order is the MPI
 * library's choice, so two runs could differ in the last bit); owner by
 * fixed x slabs of equal width (a block of dough on one side of the box would
 * leave ranks idle).
 *
 * Determinism: the partition depends only on the sorted particles and the
 * rank count; each rank's P2G sums its blocks in the usual colour order; the
 * ranks' sums are added in rank order. A node touched by one rank only has
 * the bits of the one-process run; a node on a seam between two runs sums
 * the same terms in another grouping (a difference of a few ulps,
 * `mpi_elastic_matches_one_rank`). */
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "mpm.h"
#include "particles.h"
#include "ranks.h"
#include "thermal.h"
#include "water.h"

hearth_status mpm_ranks_init(mpm_state *m, hearth_error *err) {
    m->nranks = ranks_size();
    m->kfirst = mem_calloc(sizeof(int) * ((size_t)m->nranks + 1));
    m->pfirst = mem_calloc(sizeof(int) * ((size_t)m->nranks + 1));
    if (!m->kfirst || !m->pfirst) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the MPM rank tables");
    return HEARTH_OK;
}

void mpm_ranks_free(mpm_state *m) {
    mem_free(m->kfirst, sizeof(int) * ((size_t)m->nranks + 1));
    mem_free(m->pfirst, sizeof(int) * ((size_t)m->nranks + 1));
    m->kfirst = m->pfirst = NULL;
}

void mpm_ranks_partition(hearth_scene *s) {
    mpm_state *m = s->mpm;
    const int N = m->nranks, n = s->ps.n;
    if (N == 1) {
        m->k_lo = 0, m->k_hi = m->npb;
        return;
    }
    /* block k goes to rank floor(start_k N / n): runs in block order, about n / N
     * particles each; rank r's run starts at the first block with start_k N >= r n */
    int k = 0;
    for (int r = 0; r <= N; r++) {
        while (k < m->npb && (long long)m->pb[k].start * N < (long long)r * n) k++;
        m->kfirst[r] = k;
    }
    for (int r = 0; r <= N; r++) m->pfirst[r] = m->kfirst[r] < m->npb ? m->pb[m->kfirst[r]].start : n;
    const int me = ranks_rank();
    m->k_lo = m->kfirst[me], m->k_hi = m->kfirst[me + 1];
}

hearth_status mpm_ranks_sum_grid(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    if (m->nranks == 1) return HEARTH_OK;
    const grid *g = &s->g;
    int lo = 0, hi = 0;
    if (m->k_hi > m->k_lo) {
        /* slots ascend with block ids, and a block's tile reaches its +1 neighbours:
         * this rank wrote slots from its first block's to its last block's (+1, +1, +1) */
        int c[3];
        grid_block_coords(g, m->pb[m->k_hi - 1].block, c);
        lo = g->slot[m->pb[m->k_lo].block];
        hi = g->slot[grid_block_id(g, c[0] + 1, c[1] + 1, c[2] + (g->dim == 3))] + 1;
        HEARTH_ASSERT(lo >= 0 && hi > lo && hi <= g->nactive);
    }
    hearth_status st = ranks_sum_grid(&s->g, lo, hi, err);
    if (st) return st;
    /* the field passes between P2G and G2P read every particle's volume */
    if (m->vol && (thermal_active(s) || water_active(s))) ranks_allgather(m->vol, sizeof(double), m->pfirst);
    return HEARTH_OK;
}

void mpm_ranks_gather(hearth_scene *s) {
    mpm_state *m = s->mpm;
    if (m->nranks == 1) return;
    particles *ps = &s->ps;
    ranks_allgather(m->partial, sizeof(pb_partial), m->kfirst);
    /* G2P filed its own particles' sort keys (mpm_sort.c): the other ranks' come with their particles */
    ranks_allgather(m->keys, sizeof(int), m->pfirst);
    for (int c = 0; c < PC_COUNT; c++)
        if ((ps->enabled & (1u << c)) && ps->col[c]) ranks_allgather(ps->col[c], particles_col_bytes(ps, c), m->pfirst);
}
