/* mpm_sort.c: the MPM step's bookkeeping (Jiang et al. 2015's sorted
 * particles, in grid blocks): the sort's scratch, a stable counting sort of
 * the particles by block, the runs of particles per block and their colours,
 * and the grid blocks their tiles touch. Every pass runs in parallel over
 * chunks whose results do not depend on the chunking, so the particle order,
 * the block lists and the grid slots are the same bits for any thread count
 * (`determinism_threads`, `determinism_threads_2d_bookkeeping`). */
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "mpm.h"
#include "thermal.h"
#include "water.h"
#include "phase_clock.h"

#ifdef _OPENMP
#include <omp.h>
#endif

/* the keys and order's block (keys first, order after scratch_cap ints) */
static void keys_free(mpm_state *m) {
    mem_free(m->keys, m->scratch_bytes);
    m->keys = m->order = NULL;
    m->scratch_bytes = 0;
    m->keys_n = -1; /* the keys went with the scratch */
}

/* keys and order for cap particles in one block of bytes (>= 8 cap) */
static int keys_alloc(mpm_state *m, int cap, size_t bytes) {
    if (!(m->keys = mem_alloc(bytes))) return 0;
    m->order = m->keys + cap;
    m->scratch_bytes = bytes;
    return 1;
}

void mpm_scratch_free(mpm_state *m) {
    keys_free(m);
    mem_free(m->vol, sizeof(double) * (size_t)m->scratch_cap);
    m->vol = NULL;
    m->scratch_cap = 0;
}

/* Room for n particles' step scratch: grown when the particle count grows, so
 * the step loop allocates nothing otherwise. */
static hearth_status mpm_reserve(hearth_scene *s, int n, hearth_error *err) {
    mpm_state *m = s->mpm;
    if (n > m->scratch_cap || (m->scratch_cap > 0 && !m->keys)) { /* no keys: mpm_scratch_room failed */
        int cap = s->ps.cap > n ? s->ps.cap : n;
        mpm_scratch_free(m);
        if (!keys_alloc(m, cap, 2 * sizeof(int) * (size_t)cap))
            return err_set(err, HEARTH_ERR_NOMEM, "out of memory for sorting %d particles", n);
        m->scratch_cap = cap;
    }
    /* the field passes read each particle's volume from here rather than F (72 bytes a particle) */
    if (!m->vol && (thermal_active(s) || water_active(s)) && !(m->vol = mem_alloc(sizeof(double) * (size_t)m->scratch_cap)))
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory for %d particle volumes", m->scratch_cap);
    return HEARTH_OK;
}

hearth_status mpm_scratch_room(hearth_scene *s, size_t bytes, hearth_error *err) {
    mpm_state *m = s->mpm;
    HEARTH_ASSERT(m->keys_n < 0); /* nothing in the block is live: the sort took the keys */
    if (bytes <= m->scratch_bytes) return HEARTH_OK;
    /* exactly what is asked: the store's need moves with the particle blocks, which grow slowly */
    keys_free(m);
    if (keys_alloc(m, m->scratch_cap, bytes)) return HEARTH_OK;
    /* no keys or order now: the next sort allocates them again (mpm_reserve) */
    return err_set(err, HEARTH_ERR_NOMEM, "out of memory for %zu bytes of the sort's scratch", bytes);
}

/* Room for npb particle blocks, grown by half when short: sized by the
 * blocks this step's particles fill, not by every block of the box. */
static hearth_status pb_reserve(mpm_state *m, int need, hearth_error *err) {
    if (need <= m->pbcap) return HEARTH_OK;
    const int cap = m->pbcap + m->pbcap / 2 > need ? m->pbcap + m->pbcap / 2 : need;
    /* contents are rebuilt by every sort, so fresh arrays replace the old ones */
    pblock *pb = mem_alloc(sizeof(pblock) * (size_t)cap);
    int *cp = mem_alloc(sizeof(int) * (size_t)cap);
    pb_partial *pp = mem_alloc(sizeof(pb_partial) * (size_t)cap);
    if (!pb || !cp || !pp) {
        mem_free(pb, sizeof(pblock) * (size_t)cap);
        mem_free(cp, sizeof(int) * (size_t)cap);
        mem_free(pp, sizeof(pb_partial) * (size_t)cap);
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory for %d particle blocks", need);
    }
    mem_free(m->pb, sizeof(pblock) * (size_t)m->pbcap);
    mem_free(m->colour_pb, sizeof(int) * (size_t)m->pbcap);
    mem_free(m->partial, sizeof(pb_partial) * (size_t)m->pbcap);
    m->pb = pb;
    m->colour_pb = cp;
    m->partial = pp;
    m->pbcap = cap;
    return HEARTH_OK;
}

/* The chunks the sort's bookkeeping splits into: one per thread when there
 * is enough to share (at most SORT_CHUNKS_MAX, for the stack arrays below),
 * else one. Every result is independent of it. */
#define SORT_CHUNKS_MAX MPM_SORT_CHUNKS_MAX
static int sort_chunks(int n) {
#ifdef _OPENMP
    if (n < SCENE_PARALLEL_MIN) return 1;
    const int t = omp_get_max_threads();
    return t < 1 ? 1 : t > SORT_CHUNKS_MAX ? SORT_CHUNKS_MAX : t;
#else
    (void)n;
    return 1;
#endif
}

/* Stable counting sort of the particles by keys, on one thread: order[j] is
 * the particle that goes to place j, and counts[b] becomes the first place of
 * block b (counts[nblocks] = n). Returns 0 when the keys were already in
 * order (order untouched). sort_team does the same in chunks. */
static int sort_counting(mpm_state *m, int n) {
    const int NB = m->nblocks;
    const int *keys = m->keys;
    int *order = m->order, *counts = m->counts, unsorted = 0;
    memset(counts, 0, sizeof(int) * ((size_t)NB + 1));
    for (int i = 0; i < n; i++) {
        counts[keys[i] + 1]++;
        unsorted |= i > 0 && keys[i - 1] > keys[i];
    }
    for (int b = 0; b < NB; b++) counts[b + 1] += counts[b];
    if (!unsorted) return 0;
    for (int i = 0; i < n; i++) order[counts[keys[i]]++] = i;
    /* counts[b] advanced to block b's end, the start of b + 1 */
    memmove(counts + 1, counts, sizeof(int) * (size_t)NB);
    counts[0] = 0;
    return 1;
}

/* The colour lists, in block order within a colour: O(particle blocks), serial. */
static void sort_colours(hearth_scene *s) {
    const grid *g = &s->g;
    mpm_state *m = s->mpm;
    int ncolour[8] = {0};
    for (int k = 0; k < m->npb; k++) {
        int c[3];
        grid_block_coords(g, m->pb[k].block, c);
        ncolour[(c[0] & 1) | (c[1] & 1) << 1 | (c[2] & 1) << 2]++;
    }
    m->colour_start[0] = 0;
    for (int k = 0; k < 8; k++) m->colour_start[k + 1] = m->colour_start[k] + ncolour[k];
    int fill[8];
    memcpy(fill, m->colour_start, sizeof fill);
    for (int k = 0; k < m->npb; k++) {
        int c[3];
        grid_block_coords(g, m->pb[k].block, c);
        m->colour_pb[fill[(c[0] & 1) | (c[1] & 1) << 1 | (c[2] & 1) << 2]++] = k;
    }
}

/* Block id's particles: counts holds the blocks' starts (hist NULL), or
 * inside sort_team hist holds each chunk's count of them (T rows of NB). */
static inline int block_total(const int *counts, const int *hist, int NB, int T, int id) {
    if (!hist) return counts[id + 1] - counts[id];
    int sum = 0;
    for (int q = 0; q < T; q++) sum += hist[(size_t)q * NB + id];
    return sum;
}

/* Whether block (bx, by, bz) or its -1 neighbour along some axes holds
 * particles: the blocks a particle block's tile touches (block_total's
 * counts or hist). */
static inline unsigned char touched(const grid *g, const int *counts, const int *hist, int NB, int T, int bx, int by, int bz) {
    const int nz = g->dim == 3;
    unsigned char hit = 0;
    for (int dx = 0; dx <= (bx > 0); dx++)
        for (int dy = 0; dy <= (by > 0); dy++)
            for (int dz = 0; dz <= (nz && bz > 0); dz++)
                hit |= block_total(counts, hist, NB, T, grid_block_id(g, bx - dx, by - dy, bz - dz)) > 0;
    return hit;
}

/* The particle blocks (runs of one block, in block order) and the blocks
 * their tiles touch (mark: a block is touched when it or its -1 neighbour
 * along some axes holds particles). Both are worked out per block from
 * counts, in parallel, with no write shared between threads. */
static hearth_status sort_blocks(hearth_scene *s, int T, hearth_error *err) {
    const grid *g = &s->g;
    mpm_state *m = s->mpm;
    const int NB = m->nblocks, *counts = m->counts;
    int part[SORT_CHUNKS_MAX + 1] = {0};
#pragma omp parallel for schedule(static) num_threads(T) if (T > 1)
    for (int c = 0; c < T; c++) {
        const int lo = (int)((long)NB * c / T), hi = (int)((long)NB * (c + 1) / T);
        int k = 0;
        for (int b = lo; b < hi; b++) k += counts[b + 1] > counts[b];
        part[c + 1] = k;
    }
    for (int c = 0; c < T; c++) part[c + 1] += part[c];
    hearth_status st = pb_reserve(m, part[T], err);
    if (st) return st;
    m->npb = part[T];
    const int nb1 = g->nb[1], nb2 = g->nb[2];
#pragma omp parallel num_threads(T) if (T > 1)
    {
#pragma omp for schedule(static)
        for (int c = 0; c < T; c++) {
            const int lo = (int)((long)NB * c / T), hi = (int)((long)NB * (c + 1) / T);
            int k = part[c];
            for (int b = lo; b < hi; b++)
                if (counts[b + 1] > counts[b]) m->pb[k++] = (pblock){b, counts[b], counts[b + 1]};
        }
#pragma omp for schedule(static)
        for (int bx = 0; bx < g->nb[0]; bx++)
            for (int by = 0; by < nb1; by++)
                for (int bz = 0; bz < nb2; bz++) m->mark[grid_block_id(g, bx, by, bz)] = touched(g, counts, NULL, NB, 1, bx, by, bz);
    }
    sort_colours(s);
    return HEARTH_OK;
}

/* The chunks of the sort's first passes go to whichever thread comes first:
 * each thread starts at the chunk a static split would give it and then
 * takes every chunk no thread has claimed yet (claim: zero at the step's
 * start). Under OMP_WAIT_POLICY=passive a thread woken late (the region's
 * start, a barrier) then finds its chunks done rather than the others
 * waiting for it; what a chunk computes does not depend on who does it.
 * Returns the next chunk claimed, or -1. */
static int first_chunk(int T) {
#ifdef _OPENMP
    return (int)((long)omp_get_thread_num() * T / omp_get_num_threads());
#else
    (void)T;
    return 0;
#endif
}

static int claim_chunk(int *claim, int T, int c0, int *j) {
    while (*j < T) {
        const int c = (c0 + (*j)++) % T;
        if (!__atomic_exchange_n(&claim[c], 1, __ATOMIC_ACQ_REL)) return c;
    }
    return -1;
}

/* The sort's count and lists for the threads of a parallel region: its own
 * in mpm_sort, or mpm.c's one-region step (mpm_sort_begin). With T chunks of
 * particles, chunk c counts its own particles per block (hist, T x nblocks);
 * a particle's place is its block's start, plus the block's particles in
 * earlier chunks, plus those before it in its own chunk: the serial sort's
 * place, so the order is the same bits for any T (`determinism_threads_*`).
 * The block starts, the particle blocks, the marks and the grid's slots are
 * integers from the same counts, so they are the serial sort's too.
 *
 * After the count's wait hist is only read until every thread is past the
 * marks. Each chunk of the block table is added up once (table_chunk: its
 * blocks' totals into counts, its particles, particle blocks and, in 2D, its
 * marks, a row of blocks behind), and once every chunk is added up each
 * thread's exclusive scan over the T chunks' totals gives the chunks'
 * offsets, so each chunk activates its own blocks of the grid and lists its
 * particle blocks from counts. Until the sortscan branch every thread added up
 * the whole table itself to spare that wait (O(T nblocks) reads each, and 2D's
 * marks made twice, the second time from hist): at 2D 128 cells the lists
 * then took each of 2 threads about as long as 1 thread (docs/performance.md,
 * "The sort's table split between threads"). With the keys in order the sort
 * waits twice (the count, the table; 3D's activation once more); with
 * OMP_WAIT_POLICY=passive (main.c) a wait that sleeps costs a futex round
 * trip, which is why the waits spin first (team_wait.c) and why work handed
 * out by claims is waited for by count, not by thread.
 * The count's, the table's and the lists' chunks are claimed (claim_chunk).
 * Out of order, hist turns into places after a barrier, the order is filled
 * after another, and the caller permutes (particles_permute_team). Returns
 * the farthest a particle moves in the order (particles_permute_within's W)
 * when the keys were out of order, else -1; kof gets the chunks' first
 * particle blocks (kof[T]: all of them; every thread's own copy); t->st gets
 * a reservation's status. */
#define MARK_ROW_MAX 4096 /* 2D's marks are made with the table's totals where a row of blocks fits on the stack */
/* out[y]: whether block b0 + y holds particles, y < len (its T rows of hist summed) */
static void occupied(const int *hist, int NB, int T, int b0, int len, unsigned char *out) {
    for (int y = 0; y < len; y++) {
        int sum = 0;
        for (int q = 0; q < T; q++) sum += hist[(size_t)q * NB + b0 + y];
        out[y] = sum > 0;
    }
}

/* Chunk c of the block table, [NB c / T, NB (c + 1) / T): each block's particles, its T rows of hist
 * summed, go to counts (here a total per block, where sort_counting leaves its start), and out gets the
 * chunk's particles, particle blocks and (early: 2D with the activation in the region) marks, which it
 * writes to m->mark. A block is marked when it or its -1 neighbours hold particles; a chunk that starts
 * past the first row reads the row before it (and its own row's first blocks) from hist itself, so no
 * chunk waits for another. By runs of blocks within one row (2D) or the chunk (3D), so the sums
 * vectorise (a block at a time took 20 instructions a block, runs about 3, callgrind). */
static void table_chunk(const grid *g, mpm_state *m, const int *hist, int T, int c, int early, int out[3]) {
    const int NB = m->nblocks, nb1 = g->nb[1];
    const int lo = (int)((long)NB * c / T), hi = (int)((long)NB * (c + 1) / T);
    unsigned char rows[2][MARK_ROW_MAX]; /* 2D: which blocks of this row and the one before hold particles */
    int np = 0, nk = 0, na = 0;
    if (early && lo < hi) {
        const int bx = lo / nb1, by0 = lo - bx * nb1;
        if (bx > 0)
            occupied(hist, NB, T, (bx - 1) * nb1, nb1, rows[~bx & 1]);
        else
            memset(rows[~bx & 1], 0, (size_t)nb1);
        occupied(hist, NB, T, bx * nb1, by0, rows[bx & 1]);
    }
    for (int b = lo; b < hi;) {
        int e = hi, bx = 0, by0 = 0;
        if (early) { /* b = bx nb1 + by */
            bx = b / nb1, by0 = b - bx * nb1;
            if (e > (bx + 1) * nb1) e = (bx + 1) * nb1;
        }
        const int len = e - b;
        int *tot = m->counts + b;
        memcpy(tot, hist + b, sizeof(int) * (size_t)len);
        for (int q = 1; q < T; q++) {
            const int *h = hist + (size_t)q * NB + b;
            for (int y = 0; y < len; y++) tot[y] += h[y];
        }
        for (int y = 0; y < len; y++) np += tot[y], nk += tot[y] > 0;
        if (early) {
            unsigned char *cur = rows[bx & 1], *prev = rows[~bx & 1], *mk = m->mark + (b - by0);
            for (int y = 0; y < len; y++) cur[by0 + y] = tot[y] > 0;
            int y = by0;
            if (y == 0) mk[0] = cur[0] | prev[0], na += mk[0], y = 1;
            for (; y < by0 + len; y++) {
                mk[y] = cur[y] | cur[y - 1] | prev[y] | prev[y - 1];
                na += mk[y];
            }
        }
        b = e;
    }
    out[0] = np, out[1] = nk, out[2] = na;
}

int mpm_sort_team_run(hearth_scene *s, mpm_sort_team *t, int kof[MPM_SORT_CHUNKS_MAX + 1], int *nactive) {
    grid *g = &s->g;
    mpm_state *m = s->mpm;
    const int NB = m->nblocks, T = t->T, n = s->ps.n, *keys = m->keys, nb1 = g->nb[1], nb2 = g->nb[2];
    int *order = m->order, *hist = m->hist;
    /* each chunk of particles counts its own per block; then the barrier every count waits for */
    const int c0 = first_chunk(T);
    for (int j = 0, c; (c = claim_chunk(t->claim[0], T, c0, &j)) >= 0;) {
        int *h = hist + (size_t)c * NB, u = 0;
        memset(h, 0, sizeof(int) * (size_t)NB);
        const int lo = (int)((long)n * c / T), hi = (int)((long)n * (c + 1) / T);
        for (int i = lo; i < hi; i++) {
            h[keys[i]]++;
            u |= i > 0 && keys[i - 1] > keys[i];
        }
        t->unsorted[c] = u;
        team_count_add(&t->counted, 1);
    }
    /* on once every chunk is counted, whoever counted it: a thread woken late finds them all done and the
     * others need not wait for it (nothing writes hist before the next barrier, past every thread's reads) */
    team_count_wait(&m->team, &t->counted, (unsigned)T);
    PHASE_MARK(PH_COUNT);
    int unsorted = 0;
    for (int c = 0; c < T; c++) unsorted |= t->unsorted[c];
    /* Each chunk of the table is added up once, by whoever claims it (table_chunk): its blocks' totals go to
     * counts, its particles, particle blocks and (2D) marks to t->chunk_tot; once every chunk is done each
     * thread's exclusive scan over the T chunks' totals gives the chunks' offsets (poff, koff, aoff). */
    const int early = t->activate && g->dim == 2 && nb1 <= MARK_ROW_MAX;
    for (int j = 0, c; (c = claim_chunk(t->claim[2], T, c0, &j)) >= 0;) {
        table_chunk(g, m, hist, T, c, early, t->chunk_tot[c]);
        team_count_add(&t->totalled, 1);
    }
    team_count_wait(&m->team, &t->totalled, (unsigned)T);
    int poff[SORT_CHUNKS_MAX + 1] = {0}, koff[SORT_CHUNKS_MAX + 1] = {0}, aoff[SORT_CHUNKS_MAX + 1] = {0};
    for (int c = 0; c < T; c++) {
        poff[c + 1] = poff[c] + t->chunk_tot[c][0];
        koff[c + 1] = koff[c] + t->chunk_tot[c][1];
        aoff[c + 1] = aoff[c] + t->chunk_tot[c][2];
    }
    /* A step that finds more particle blocks or marks than ever grows the lists first (every thread
     * sees the same need, so all or none meet the single). */
    if (koff[T] > t->pbcap || (early && aoff[T] > t->gcap)) {
#pragma omp single
        {
            if (koff[T] > t->pbcap) t->st = pb_reserve(m, koff[T], t->err);
            if (!t->st && early && aoff[T] > t->gcap) t->st = grid_activate_reserve(g, aoff[T], t->err);
        }
    }
    memcpy(kof, koff, sizeof(int) * (size_t)(T + 1));
    if (nactive) *nactive = aoff[T];
    if (t->st) return -1;
    const int late = t->activate && !early; /* the activation after a barrier (3D, or 2D rows too long for the stack) */
    /* 2D's marks are made; 3D's read hist (no chunk waits for another) and are counted for a later
     * activation; 2D activates the chunk's blocks here. A chunk done is published (t->ready, with release
     * order: its particle blocks and their grid blocks are written) for the step's P2G (mpm.c's
     * p2g_store_chunks), which then needs no barrier. */
    const int *counts = m->counts;
    for (int j = 0, c; (c = claim_chunk(t->claim[1], T, c0, &j)) >= 0;) {
        const int lo = (int)((long)NB * c / T), hi = (int)((long)NB * (c + 1) / T);
        if (!early) {
            int bc[3], na = 0;
            grid_block_coords(g, lo < NB ? lo : 0, bc);
            for (int b = lo; b < hi; b++) { /* b = grid_block_id(bc): z fastest */
                const unsigned char mk = touched(g, NULL, hist, NB, T, bc[0], bc[1], bc[2]);
                m->mark[b] = mk;
                na += mk != 0;
                if (++bc[2] == nb2) {
                    bc[2] = 0;
                    if (++bc[1] == nb1) bc[1] = 0, bc[0]++;
                }
            }
            t->amark[c] = na;
        } else {
            grid_activate_chunk(g, m->mark, lo, hi, aoff[c]);
        }
        /* the chunk's particle blocks from its offsets and its blocks' totals */
        int run = poff[c], k = koff[c];
        for (int b = lo; b < hi; b++) {
            const int start = run;
            run += counts[b];
            if (run > start) m->pb[k++] = (pblock){b, start, run};
        }
        /* the step hands the chunk's particle blocks out from these (P2G's and G2P's) and, activated here, its
         * grid blocks (mpm.c's span_next) */
        if (t->span) {
            mpm_span_set(&t->span[MPM_SPAN_P2G][c], koff[c], k);
            mpm_span_set(&t->span[MPM_SPAN_G2P][c], koff[c], k);
            if (early) mpm_span_set(&t->span[MPM_SPAN_GRID][c], aoff[c], aoff[c + 1]);
        }
        if (!late && !unsorted) __atomic_store_n(&t->ready[c], 1, __ATOMIC_RELEASE);
    }
#pragma omp single nowait
    {
        m->npb = koff[T];
        if (t->set_range) m->k_lo = 0, m->k_hi = koff[T]; /* one rank: every particle block (mpm_ranks_partition) */
        if (early) g->nactive = aoff[T];
    }
    /* 3D's activation waits for every chunk's marks, the places for every thread's reads of hist */
    if (unsorted || late) team_wait_barrier(&m->team);
    if (late) { /* grid_activate, here in the same region: the slots of each chunk of the table */
        for (int c = 0; c < T; c++) aoff[c + 1] = aoff[c] + t->amark[c];
        if (nactive) *nactive = aoff[T];
        if (aoff[T] > t->gcap) {
#pragma omp single
            t->st = grid_activate_reserve(g, aoff[T], t->err);
        }
        if (t->st) return -1;
#pragma omp for schedule(static) nowait
        for (int c = 0; c < T; c++) {
            grid_activate_chunk(g, m->mark, (int)((long)NB * c / T), (int)((long)NB * (c + 1) / T), aoff[c]);
            if (t->span) mpm_span_set(&t->span[MPM_SPAN_GRID][c], aoff[c], aoff[c + 1]);
            if (!unsorted) __atomic_store_n(&t->ready[c], 1, __ATOMIC_RELEASE); /* its blocks were listed before the barrier */
        }
#pragma omp single nowait
        g->nactive = aoff[T];
    }
    PHASE_MARK(PH_LISTS);
    if (!unsorted) return -1;
    /* each chunk of particles' first place in each block: the block's start and the block's particles
     * in earlier chunks; then the order, once every block has its places */
#pragma omp for schedule(static) nowait
    for (int c = 0; c < T; c++) {
        const int lo = (int)((long)NB * c / T), hi = (int)((long)NB * (c + 1) / T);
        int run = poff[c];
        for (int b = lo; b < hi; b++)
            for (int q = 0; q < T; q++) {
                int *h = hist + (size_t)q * NB + b;
                const int k = *h;
                *h = run;
                run += k;
            }
    }
    team_wait_barrier(&m->team);
#pragma omp for schedule(static) nowait
    for (int c = 0; c < T; c++) {
        int *h = hist + (size_t)c * NB, far = 0;
        const int lo = (int)((long)n * c / T), hi = (int)((long)n * (c + 1) / T);
        for (int i = lo; i < hi; i++) {
            const int p = h[keys[i]]++;
            order[p] = i;
            if ((p > i ? p - i : i - p) > far) far = p > i ? p - i : i - p;
        }
        t->far[c] = far;
    }
    team_wait_barrier(&m->team);
    int W = 0;
    for (int c = 0; c < T; c++) W = t->far[c] > W ? t->far[c] : W;
    PHASE_MARK(PH_ORDER);
    return W;
}

/* Sort keys from G2P: G2P files each particle in its block while its new
 * position is in registers (and clamps it to the grid, as below), so the
 * sort's own pass over the positions runs only when those keys are stale:
 * the first step, particles added or removed, a rolled back step, periodic
 * axes (wrapped after G2P). 3D 32 cells, one thread: the pass cost about 64
 * instructions per particle-step. The serial part before the count; *Tc
 * gets the count's chunks. */
static hearth_status sort_begin(hearth_scene *s, int *Tc, hearth_error *err) {
    grid *g = &s->g;
    particles *ps = &s->ps;
    hearth_status st = mpm_ranks_migrate(s, err); /* slabs: crossings to the neighbour ranks first */
    if (st) return st;
    const int n = ps->n;
    st = mpm_reserve(s, n, err);
    if (st) return st;
    mpm_state *m = s->mpm;
    double *X = pcold(ps, PC_X);
    int *keys = m->keys;
    const int wrap = s->def.periodic[0] || s->def.periodic[1] || s->def.periodic[2];
    if (wrap || m->keys_n != n || m->keys_step != s->step || m->keys_edits != ps->edits) {
        long moved = 0;
        if (wrap) mpm_periodic_wrap_all(s);
#pragma omp parallel for schedule(static) reduction(+ : moved) if (n >= SCENE_PARALLEL_MIN)
        for (int i = 0; i < n; i++) {
            moved += clamp_to_grid(g, X + 3 * i);
            keys[i] = block_of_position(g, X + 3 * i);
        }
        s->out_of_domain += moved;
    }
    m->keys_n = -1; /* the permutation below takes their room as its scratch */
    const int T = sort_chunks(n);
    /* The chunked count keeps a table of blocks per chunk: only where that
     * is at most 8 bytes a particle (a big, mostly empty box counts
     * serially rather than hold tables the size of the box per thread; the
     * order is the same either way). */
    *Tc = T > 1 && (size_t)T * (size_t)m->nblocks <= 2 * (size_t)n ? T : 1;
    const size_t hneed = *Tc > 1 ? (size_t)*Tc * (size_t)m->nblocks : 0;
    if (hneed > m->histcap) {
        int *h = mem_alloc(sizeof(int) * hneed);
        if (!h) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the sort's block counts (%d chunks)", *Tc);
        mem_free(m->hist, sizeof(int) * m->histcap);
        m->hist = h;
        m->histcap = hneed;
    }
    const int base = s->def.two_field ? GRID_NCH_TWO : thermal_active(s) || water_active(s) ? GRID_NCH_MAX : GRID_NCH_MOMENTUM;
    /* transfer = "flip": the nodes' velocity before the grid update, D channels past the scene's own (mpm.c's P2G) */
    const int flip = s->def.transfer == HEARTH_TRANSFER_FLIP ? g->dim : 0;
    m->flip_ch = flip ? base : 0;
    return grid_set_channels(g, base + flip, flip, err);
}

/* The team's shared part, for a region of Tc threads. The grid's activation
 * goes in the region when nothing changes the marks after it (a periodic
 * axis's ghosts, a rank's halo) and it costs no barrier there (2D) or the
 * box is big (its own two regions took six synchronisations a step), or in
 * 3D, where it costs one barrier: serially it zeroed every active block
 * (about 0.7 MB at the 32-cell bench) on one thread while the other slept,
 * and the high-x half's lines then moved to the core that writes them in
 * P2G (mpm.c's claims: thread c zeroes chunk c of the block table, the end
 * of the box it works through the step). HEARTH_MPM_COLOUR_PHASES=1 keeps the
 * serial activation of small boxes with the rest of the old 3D step. */
static void team_setup(hearth_scene *s, int Tc, mpm_sort_team *t, hearth_error *err) {
    const mpm_state *m = s->mpm;
    const grid *g = &s->g;
    const int wrap = s->def.periodic[0] || s->def.periodic[1] || s->def.periodic[2];
    *t = (mpm_sort_team){.T = Tc, .pbcap = m->pbcap, .gcap = g->cap < g->acap ? g->cap : g->acap, .err = err};
    t->activate = Tc > 1 && !wrap && m->nranks == 1 && (g->dim == 2 || m->nblocks >= GRID_ACTIVATE_PARALLEL_MIN || !m->colour_phases);
}

/* After the count and lists, one way or the other: the colour lists, the marks' extra blocks, the grid. */
static hearth_status sort_end(hearth_scene *s, int activated, hearth_error *err) {
    mpm_state *m = s->mpm;
    hearth_status st;
    if (s->def.periodic[0] || s->def.periodic[1] || s->def.periodic[2]) mpm_periodic_mark(s, m->mark);
    if ((st = mpm_ranks_mark(s, err))) return st;
    if (!activated && (st = grid_activate(&s->g, m->mark, err))) return st;
    mpm_ranks_partition(s); /* which particle blocks this rank steps */
    return HEARTH_OK;
}

/* The count and lists after sort_begin, in their own region when Tc > 1, and the rest. */
static hearth_status sort_rest(hearth_scene *s, int Tc, mpm_sort_team *t, hearth_error *err) {
    mpm_state *m = s->mpm;
    particles *ps = &s->ps;
    hearth_status st;
    if (Tc == 1) {
        const int unsorted = sort_counting(m, ps->n);
        PHASE_MARK(PH_COUNT);
        if (unsorted) particles_permute(ps, m->order, m->keys, sizeof(int) * (size_t)m->scratch_cap);
        PHASE_MARK(PH_PERMUTE);
        if ((st = sort_blocks(s, sort_chunks(ps->n), err))) return st;
        st = sort_end(s, 0, err);
        PHASE_MARK(PH_LISTS);
        return st;
    }
    /* the usual parallel sort: one region, the permutation in it */
    PHASE_FORK();
#pragma omp parallel num_threads(Tc)
    {
        PHASE_MARK(PH_FORK);
        int kof[MPM_SORT_CHUNKS_MAX + 1];
        const int W = mpm_sort_team_run(s, t, kof, NULL);
        if (W >= 0) particles_permute_team(ps, m->order, W, m->keys, sizeof(int) * (size_t)m->scratch_cap, &m->team);
        PHASE_MARK(PH_PERMUTE);
    }
    PHASE_MARK(PH_JOIN);
    if (t->st) return t->st;
    sort_colours(s);
    st = sort_end(s, t->activate, err);
    PHASE_MARK(PH_LISTS);
    return st;
}

hearth_status mpm_sort(hearth_scene *s, hearth_error *err) {
    int Tc;
    hearth_status st = sort_begin(s, &Tc, err);
    PHASE_MARK(PH_SORT_PRE);
    if (st) return st;
    mpm_sort_team t;
    team_setup(s, Tc, &t, err);
    return sort_rest(s, Tc, &t, err);
}

hearth_status mpm_sort_begin(hearth_scene *s, mpm_sort_team *t, hearth_error *err) {
    int Tc;
    hearth_status st = sort_begin(s, &Tc, err);
    PHASE_MARK(PH_SORT_PRE);
    if (st) return st;
    team_setup(s, Tc, t, err);
    if (Tc > 1 && t->activate) { /* the step's region runs the count and lists (mpm_sort_team_run) */
        t->set_range = 1;
        return HEARTH_OK;
    }
    st = sort_rest(s, Tc, t, err);
    t->T = 0;
    return st;
}
