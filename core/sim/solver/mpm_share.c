/* mpm_share.c: how the MPM step hands its blocks to the threads of a
 * team: claims from both ends of each phase's range (3D at more than one
 * thread), P2G's flushes in colour order without a barrier per colour, and
 * the one-region step's spans (2D: each chunk of the sort first to its own
 * thread). Which thread steps a block moves no bits. */
#include <sched.h>

#include "mpm_block.h"

#ifdef _OPENMP
#include <omp.h>
#endif


static unsigned long long claim_range(int lo, int hi) { return (unsigned)lo | (unsigned long long)(unsigned)hi << 32; }

/* the next block of range *c from its front (back = 0) or back, or -1 once none is left */
int claim_take(unsigned long long *c, const int back) {
    unsigned long long v = __atomic_load_n(c, __ATOMIC_RELAXED);
    for (;;) {
        const int lo = (int)(unsigned)v, hi = (int)(unsigned)(v >> 32);
        if (lo >= hi) return -1;
        const unsigned long long nv = back ? claim_range(lo, hi - 1) : claim_range(lo + 1, hi);
        if (__atomic_compare_exchange_n(c, &v, nv, 0, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) return back ? hi - 1 : lo;
    }
}

/* This thread's end of every range: odd threads take from the back. */
int claim_end(void) {
#ifdef _OPENMP
    return omp_get_thread_num() & 1;
#else
    return 0;
#endif
}

/* The claims for a step's phases (3D, a team of more than one thread, the
 * colour phases not asked for), or NULL: the phases then keep their
 * schedules and P2G its colour barriers. */
mpm_claims *claims_begin(hearth_scene *s, mpm_claims *cl) {
    mpm_state *m = s->mpm;
    m->claims = NULL;
    m->p2g_ordered = 0;
#ifdef _OPENMP
    if (s->g.dim != 3 || m->colour_phases || s->ps.n < SCENE_PARALLEL_MIN || omp_get_max_threads() < 2) return NULL;
    for (int c = 0; c < 8; c++) cl->colour[c] = claim_range(m->colour_start[c], m->colour_start[c + 1]);
    cl->grid = claim_range(0, s->g.nactive);
    cl->g2p = claim_range(m->k_lo, m->k_hi);
    m->claims = cl;
    m->p2g_ordered = 1;
    m->claims_regions++;
    return cl;
#else
    (void)cl;
    return NULL;
#endif
}

void claims_end(mpm_state *m) {
    m->claims = NULL;
    m->p2g_ordered = 0;
}

/* P2G's flushes in order without a barrier per colour (p2g_ordered): a
 * block's tile reaches its own block and the +1 neighbours, so the blocks
 * whose tiles share a node with it are its 26 neighbours, and each node sums
 * from its (at most 8) source blocks in the order of their colours, as the
 * colour phases did, when each block flushes only after its neighbours of
 * lower colour have (flushed, release / acquire): the same sums in the same
 * order, the same bits. Claims go colour by colour (a thread moves to the
 * next colour once every block of this one is claimed), so a block waits
 * only on blocks already claimed, which wait only on lower colours: no
 * cycle. The tile, most of a block's work, is made before the wait, and a
 * neighbour of lower colour was claimed earlier, so a wait is rare and
 * short: it needs the other thread to be finishing a neighbour at the seam.
 * Spins (pause), then yields the core to whoever holds the block. */
void p2g_wait_lower(const hearth_scene *s, const int bc[3]) {
    const grid *g = &s->g;
    const mpm_state *m = s->mpm;
    const int cb = (bc[0] & 1) | (bc[1] & 1) << 1 | (bc[2] & 1) << 2;
    for (int dx = -1; dx <= 1; dx++)
        for (int dy = -1; dy <= 1; dy++)
            for (int dz = -1; dz <= 1; dz++) {
                const int c = cb ^ ((dx != 0) | (dy != 0) << 1 | (dz != 0) << 2);
                const int x = bc[0] + dx, y = bc[1] + dy, z = bc[2] + dz;
                if (c >= cb || x < 0 || y < 0 || z < 0 || x >= g->nb[0] || y >= g->nb[1] || z >= g->nb[2]) continue;
                const int b = grid_block_id(g, x, y, z), q = m->pbof[b];
                if (q < m->k_lo || q >= m->k_hi || m->pb[q].block != b) continue; /* no particles there (or not this rank's) */
                for (int spin = 0; !__atomic_load_n(&m->partial[q].flushed, __ATOMIC_ACQUIRE); spin++) {
                    if (spin < 4096) {
#if defined(__x86_64__) || defined(__i386__)
                        __builtin_ia32_pause();
#endif
                    } else {
                        sched_yield();
                    }
                }
            }
}


span_walk span_walk_start(int T) {
    span_walk w = {.P = 1, .T = T};
#ifdef _OPENMP
    w.me = omp_get_thread_num();
    w.P = omp_get_num_threads();
#endif
    w.c0 = (int)((long)w.me * T / w.P), w.c1 = (int)((long)(w.me + 1) * T / w.P);
    return w;
}

/* A run from one end of *sp (the front: own), a share of what is left, down to single blocks; 0 when it is empty. */
static int span_take(mpm_span *sp, const int own, const int P, int *lo, int *hi) {
    unsigned long long v = __atomic_load_n(&sp->lohi, __ATOMIC_RELAXED);
    for (;;) {
        const int a = (int)(unsigned)v, b = (int)(v >> 32), left = b - a;
        if (left <= 0) return 0;
        const int run = left / (2 * P) > 1 ? left / (2 * P) : 1;
        const int na = own ? a + run : a, nb = own ? b : b - run;
        const unsigned long long nv = (unsigned long long)(unsigned)na | (unsigned long long)(unsigned)nb << 32;
        if (__atomic_compare_exchange_n(&sp->lohi, &v, nv, 1, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {
            *lo = own ? a : nb;
            *hi = *lo + run;
            return 1;
        }
    }
}

/* The next run [*lo, *hi) of phase sp's blocks for this thread: its own chunks' from the front, then the others'
 * from the back, from chunk c1 on; 0 when none is left. ready (P2G's, NULL when every chunk is): a chunk not yet
 * published is passed over (its owner or the thread listing it takes it all). */
int span_next(mpm_span *sp, span_walk *w, const int *ready, int *lo, int *hi) {
    for (; w->j < w->T; w->j++) {
        const int own = w->j < w->c1 - w->c0, c = (w->c0 + w->j) % w->T;
        if (ready && !__atomic_load_n(&ready[c], __ATOMIC_ACQUIRE)) continue;
        if (span_take(&sp[c], own, w->P, lo, hi)) {
            if (!own) w->back += *hi - *lo;
            return 1;
        }
    }
    return 0;
}

/* a phase's blocks taken from other threads' chunks into m->span_back (once a phase per thread) */
void span_count(mpm_state *m, int phase, const span_walk *w) {
    if (w->back) __atomic_fetch_add(&m->span_back[phase], w->back, __ATOMIC_RELAXED);
}

