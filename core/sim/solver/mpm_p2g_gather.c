/* mpm_p2g_gather.c: P2G's gather path, the usual step's P2G in 2D at any
 * thread count (mpm.c's step_team). Each particle block's P2G keeps its tile
 * instead of flushing it in 2^dim colour phases: the part over its own block
 * in that block's nodes, the halo over its +1 neighbours in a store
 * (mpm_p2g_keep_tile); after one barrier the grid update gathers each
 * block's node sums from the tiles that reach it, in colour order, with the
 * flush's test (mpm_p2g_gather): the same sums in the same order as the
 * colour phases, so the same bits. The store lives in the room of the
 * sort's order and keys, dead while it is live (mpm_p2g_store_reserve), and
 * the memory estimate counts the larger of the two
 * (mpm_p2g_store_bytes_per_particle). Why 2D only, and what the gather and its
 * store cost: docs/performance.md, "Fewer synchronisations a step". */
#include <stddef.h>

#include "alloc.h"
#include "error.h"
#include "mpm.h"

#define FORCE_INLINE static inline __attribute__((always_inline))

/* step_team's gather path (momentum only) keeps each particle block's tile
 * until every block has scattered: the part over its own block (GRID_B^dim
 * nodes) in that block's nodes, which nothing else writes before the gather,
 * and the halo over its +1 neighbours in the store, as one box for each set
 * of axes o (bit d: +1 along axis d) of GRID_T - GRID_B nodes along those
 * axes and GRID_B along the others, in o's order, channel by channel: 20
 * nodes a block in 2D, 152 in 3D (of 36 and 216). 2D writes no z momentum. */
#define P2G_STORE_NCH(D) ((D) == 2 ? 3 : GRID_NCH_MOMENTUM)
#define P2G_HALO(D) ((D) == 2 ? GRID_T * GRID_T - GRID_B * GRID_B : GRID_T * GRID_T * GRID_T - GRID_B * GRID_B * GRID_B)
/* the nodes of halo box o, and where it starts in a block's store (channel 0) */
FORCE_INLINE int halo_nodes(const int D, int o) {
    int n = 1;
    for (int d = 0; d < D; d++) n *= o >> d & 1 ? GRID_T - GRID_B : GRID_B;
    return n;
}
FORCE_INLINE int halo_start(const int D, int o) {
    int n = 0;
    for (int q = 1; q < o; q++) n += halo_nodes(D, q);
    return P2G_STORE_NCH(D) * n;
}

/* the tile's part over block bc's own nodes into them, and its halo into the store at halo (p2g_block's STORE) */
FORCE_INLINE void keep_tile(const grid *g, const int D, const int bc[3], const double *tile, double *halo) {
    const int TN = D == 2 ? GRID_T * GRID_T : GRID_T * GRID_T * GRID_T, NPB = g->nodes_per_block, NCH = P2G_STORE_NCH(D);
    for (int o = 0; o < (1 << D); o++) {
        const int o0 = o & 1 ? GRID_B : 0, o1 = o & 2 ? GRID_B : 0, o2 = o & 4 ? GRID_B : 0;
        const int n0 = o0 ? GRID_T - GRID_B : GRID_B, n1 = o1 ? GRID_T - GRID_B : GRID_B,
                  n2 = D == 3 ? (o2 ? GRID_T - GRID_B : GRID_B) : 1, nn = n0 * n1 * n2;
        int l;
        double *node = o ? NULL : grid_tile_node(g, D, bc, 0, 0, 0, &l);
        double *box = o ? halo + halo_start(D, o) : NULL;
        for (int a = 0; a < n0; a++)
            for (int b = 0; b < n1; b++)
                for (int e = 0; e < n2; e++) {
                    const int t = D == 2 ? (a + o0) * GRID_T + b + o1 : ((a + o0) * GRID_T + b + o1) * GRID_T + e + o2;
                    const int i = (a * n1 + b) * n2 + e; /* o = 0: the node's index in its block */
                    for (int ch = 0; ch < NCH; ch++) {
                        if (o) box[ch * nn + i] = tile[ch * TN + t];
                        else node[ch * NPB + i] = tile[ch * TN + t];
                    }
                }
    }
}

void mpm_p2g_keep_tile(hearth_scene *s, int D, int k, const int bc[3], const double *tile) {
    const mpm_state *m = s->mpm;
    if (D == 2) keep_tile(&s->g, 2, bc, tile, m->tiles + (size_t)k * (size_t)(P2G_STORE_NCH(2) * P2G_HALO(2)));
    else keep_tile(&s->g, 3, bc, tile, m->tiles + (size_t)k * (size_t)(P2G_STORE_NCH(3) * P2G_HALO(3)));
}

/* step_team's gather: active block k takes the kept tiles (mpm_p2g_keep_tile)
 * of the particle blocks that reach it, itself and its -1 neighbours along
 * each axis (a tile covers its block and the +1 neighbours), in the order of
 * their colours, which is the order in which p2g_team's colour phases flush
 * them into its nodes, and with the flush's test (a node the tile's mass
 * missed takes nothing from it): the same sums from zero in the same order,
 * so the same bits, after one barrier where the colour phases have 2^dim (4
 * in 2D, 8 in 3D); and the grid update runs on the block right after, while
 * its nodes are in cache. */
FORCE_INLINE void p2g_gather_block(hearth_scene *s, const int D, int k) {
    const grid *g = &s->g;
    const mpm_state *m = s->mpm;
    const int NPB = g->nodes_per_block, NCH = P2G_STORE_NCH(D);
    double *node = grid_block(g, k);
    double acc[P2G_STORE_NCH(3) * GRID_B * GRID_B * GRID_B]; /* the sums, from +0 like the zeroed nodes */
    for (int i = 0; i < NCH * NPB; i++) acc[i] = 0.0;
    int bc[3];
    grid_block_coords(g, g->active[k], bc);
    const int cb = (bc[0] & 1) | (bc[1] & 1) << 1 | (bc[2] & 1) << 2;
    for (int c = 0; c < (1 << D); c++) {
        /* the source block of colour c lies at -1 along the axes where its parity differs from this block's */
        const int o = c ^ cb;
        int sc[3] = {bc[0], bc[1], bc[2]}, inside = 1;
        for (int d = 0; d < D; d++)
            if (o >> d & 1) inside &= sc[d]-- > 0;
        if (!inside) continue;
        const int q = m->pbof[grid_block_id(g, sc[0], sc[1], sc[2])];
        if (q < 0) continue; /* no particles there */
        /* o = 0: this block's own part, in its nodes; else halo box o of the source's store, which holds
         * this block's nodes from GRID_B on along the offset axes */
        const double *src = o ? m->tiles + (size_t)q * (size_t)(NCH * P2G_HALO(D)) + halo_start(D, o) : node;
        const int stride = o ? halo_nodes(D, o) : NPB;
        const int n0 = o & 1 ? GRID_T - GRID_B : GRID_B, n1 = o & 2 ? GRID_T - GRID_B : GRID_B,
                  n2 = D == 3 ? (o & 4 ? GRID_T - GRID_B : GRID_B) : 1;
        for (int a = 0; a < n0; a++)
            for (int b = 0; b < n1; b++)
                for (int e = 0; e < n2; e++) {
                    const int i = (a * n1 + b) * n2 + e, l = D == 2 ? a * GRID_B + b : (a * GRID_B + b) * GRID_B + e;
                    if (src[i] == 0.0) continue;
                    for (int ch = 0; ch < NCH; ch++) acc[ch * NPB + l] += src[ch * stride + i];
                }
    }
    for (int i = 0; i < NCH * NPB; i++) node[i] = acc[i];
}

void mpm_p2g_gather(hearth_scene *s, int k) {
    if (s->g.dim == 2) p2g_gather_block(s, 2, k);
    else p2g_gather_block(s, 3, k);
}

/* Whether step_team gathers (2D, at any thread count), and room in the tile
 * store for this step's particle blocks when it does. One thread gathers too:
 * the colour phases visit the particle blocks colour by colour, four strided
 * sweeps over the sorted particles and the grid, where the gather walks them
 * once in memory order; at one thread 2D 512 cells took 15% more CPU with the
 * flush for 4% fewer instructions in P2G, which made 2 threads look 2.4x
 * faster than 1 (issue 20; docs/performance.md, "One thread's P2G in colour
 * order"). The same bits either way (the gather sums in colour order). 3D
 * keeps the flush too, ordered per block at more than one thread (mpm.c's
 * p2g_wait_lower): on a quiet machine the gather gave 3D at 32 cells nothing
 * (2 threads / 1: 1.78x against 1.79x with the colour phases, threads.sh)
 * for 19 bytes a particle of store (237.6 -> 256.8, over issue 20's 240),
 * where 2D at 128 cells went 1.40x -> 1.51x for 8 bytes
 * (docs/performance.md, "Fewer synchronisations a step"). mpm_p2g_store_held
 * leaves out the particle count: mpm_bytes_per_particle's estimate asks it
 * for scenes large enough to hold the store. */
int mpm_p2g_store_held(const hearth_scene *s) {
    return s->g.dim == 2 && s->mpm && !s->mpm->colour_phases;
}

/* The store lives in the sort's scratch (mpm_scratch_room): from the end of
 * the sort to G2P, which files the next step's keys after the grid update's
 * barrier (every gather done), keys and order hold nothing, and their 8 bytes
 * a particle hold the store of full blocks (7.5); the block grows, exactly,
 * only where the store needs more (blocks part full at a body's edges). Its
 * own array, grown by half when short, held 8.3 bytes a particle more at 2D
 * 128 cells (164.7 bytes a particle at 2 threads against 156.3 at one). */
size_t mpm_p2g_store_need(const hearth_scene *s, int npb) {
    const size_t per = s->g.dim == 2 ? P2G_STORE_NCH(2) * P2G_HALO(2) : P2G_STORE_NCH(3) * P2G_HALO(3);
    return per * (size_t)npb;
}

hearth_status mpm_p2g_store_room(hearth_scene *s, int npb, hearth_error *err) {
    mpm_state *m = s->mpm;
    const size_t need = mpm_p2g_store_need(s, npb);
    m->tiles_cap = 0;
    m->tiles = NULL;
    if (mpm_scratch_room(s, sizeof(double) * need, err))
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory for P2G's tiles of %d particle blocks", npb);
    m->tiles = (double *)(void *)m->keys; /* the allocator's alignment, as for any block of doubles */
    m->tiles_cap = need;
    return HEARTH_OK;
}

hearth_status mpm_p2g_store_reserve(hearth_scene *s, int *gather, hearth_error *err) {
    mpm_state *m = s->mpm;
    *gather = s->ps.n >= SCENE_PARALLEL_MIN && mpm_p2g_store_held(s);
    m->tiles_cap = 0;
    m->tiles = NULL;
    return *gather ? mpm_p2g_store_room(s, m->npb, err) : HEARTH_OK;
}

/* mpm_bytes_per_particle's share of the store where it will be held (2D,
 * at any thread count: mpm_p2g_store_reserve): one tile (P2G_STORE_NCH x
 * P2G_HALO doubles) per particle block, a block's 16 cells full at s:add's
 * default ppc 4, 64 particles (3 x 20 x 8 / 64 = 7.5 bytes; `hearth bench
 * --threads 2 --dim 2 --cells 128` measured 8.3, its edge blocks part full).
 * A sparser seeding holds more per particle. It shares the room of the
 * sort's order and keys (mpm_p2g_store_reserve): the estimate counts the
 * larger of the two. */
double mpm_p2g_store_bytes_per_particle(const hearth_scene *s) {
    if (!mpm_p2g_store_held(s)) return 0;
    return (double)(sizeof(double) * P2G_STORE_NCH(2) * P2G_HALO(2)) / (4 * GRID_B * GRID_B);
}
