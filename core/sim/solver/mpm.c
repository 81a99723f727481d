/* mpm.c: one explicit MPM step (Ding et al. 2019 §6.1, eq. 15-16; Jiang et al. 2015 APIC).
 *
 * Transfers use quadratic B-splines. The force on the grid uses the moving
 * least squares form of Hu et al. 2018 (MLS-MPM): grad w_ip ~ w_ip D^-1 (x_i - x_p)
 * with D = dx^2/4 I, and the APIC affine matrix C_p is the velocity gradient
 * that advances F. We chose it over the classic B-spline gradient form because
 * it needs no stored stress or velocity gradient (one plugin call per particle
 * per step, fused into P2G) and keeps linear and angular momentum exactly
 * (`transfer_conservation_*`, `rotating_disc`).
 *
 * Step order (design notes): sort particles into blocks, then per particle
 * F <- (I + dt C) F and the plugin's stress, fused into P2G; grid update with
 * gravity, walls and colliders; G2P with APIC velocity and C, positions.
 *
 * Determinism: P2G runs block by block in 2^dim colour phases. Blocks of one
 * colour are two blocks apart, and a block's particles touch only itself and
 * the next block on each axis, so no two threads ever write the same node and
 * every node sums its contributions in the same order whatever the thread
 * count. No atomics. With more than one thread, the usual 2D step
 * (step_team) keeps every block's tile instead and the grid update gathers
 * each node's sum from the tiles in the same colour order (mpm_p2g_gather.c):
 * the same bits, with one barrier where the colour phases take 2^dim. 3D at
 * more than one thread flushes each block after its neighbours of lower
 * colour instead of a barrier per colour (p2g_wait_lower), and every phase
 * hands out blocks from both ends (claim_take): the same bits.
 *
 * P2G scatters each particle into a dense 6^dim tile, then adds the tile into
 * its block and the block's +1 neighbours. The fields ride these passes when
 * they are live (see transport.c): P2G also scatters heat capacity and
 * C theta, water mass and capacity, records each particle's volume J V_0
 * and scatters it too (boundary.c's volume fraction: one more tile channel
 * instead of a pass of its own, 3D 24 cells heat 2.01x -> 1.92x a no-field
 * step); G2P hands out the nodes' changes of temperature and saturation and
 * integrates CO2 over the step. G2P also records the largest distance a
 * particle was moved (dt |v| from the grid, before a wall or collider stops
 * it), so the guard sees a jump of many cells onto a floor as a CFL stop.
 *
 * `transfer = "pic"` drops the affine momentum in P2G (C still advances F):
 * dissipative, for comparison (`transfer_pic_dissipates`). `heat_flip` blends
 * the particles' temperature from FLIP (1, eq. 21, exact in heat) toward PIC
 * (0, the nodes' value, which keeps a maximum principle: `heat_flip_pic_bounds`).
 * Both are knobs of `hearth trade`.
 *
 * Cost, in callgrind instructions on `hearth bench --dim 3 --cells 24`
 * (23391 particles, one thread, per step), when the plugin call record, the
 * wave-speed check and the move record came in: P2G 37.16M -> 37.54M (+1.0%),
 * G2P 34.68M -> 35.29M (+1.8%), the whole step 75.26M -> 76.24M (+1.3%).
 * The 3D benchmark's particles and grid fill 242 bytes per particle at 32
 * cells (234 at 64), and the library holds no more: seeding reserves exactly
 * (it held 299 and 282, and 380-460 at its peak, before, issue 20). The cost
 * of each phase, before and after the sort keys moved into G2P, is in
 * docs/performance.md (scripts/bench/report.sh). */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <sched.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "plugins.h"
#include "mpm.h"
#include "mpm_sticky.h"
#include "solver.h"
#include "gas.h"
#include "material.h"
#include "thermal.h"
#include "water.h"
#include "boundary.h"
#include "mixing.h"
#include "transport.h"
#include "tensor2.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#define FORCE_INLINE static inline __attribute__((always_inline))

/* Whether this step updates heat and water on the grid, and over what time:
 * the fields' clock (fields/field_clock.c) skips them on most steps of a
 * multirate cycle; the particles' temperature, water and CO2 still ride along. */
static inline int heat_now(const hearth_scene *s) { return thermal_active(s) && !s->field_skip; }
static inline int water_now(const hearth_scene *s) { return water_active(s) && !s->field_skip; }
static inline double field_dt(const hearth_scene *s, double dt) { return s->field_dt > 0 ? s->field_dt : dt; }

/* two doubles, one SSE2 register: 3D P2G's scatter and G2P's sums run in pairs of lanes */
typedef double v2d __attribute__((vector_size(16)));

/* ---- state ----------------------------------------------------------- */

static void mpm_free(hearth_scene *s) {
    mpm_state *m = s->mpm;
    if (!m) return;
    mpm_scratch_free(m);
    mem_free(m->pb, sizeof(pblock) * (size_t)m->pbcap);
    mem_free(m->colour_pb, sizeof(int) * (size_t)m->pbcap);
    mem_free(m->partial, sizeof(pb_partial) * (size_t)m->pbcap);
    mem_free(m->counts, sizeof(int) * ((size_t)m->nblocks + 1));
    mem_free(m->mark, (size_t)m->nblocks);
    mem_free(m->hist, sizeof(int) * m->histcap);
    mem_free(m->pbof, sizeof(int) * (size_t)m->nblocks);
    mpm_two_field_free(m);
    mpm_ranks_free(m);
    mem_free(m, sizeof *m);
    s->mpm = NULL;
}

/* The tables over every block of the box are made with the scene; the
 * per-particle scratch waits for particles (mpm_reserve). */
static hearth_status mpm_init(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm = mem_calloc(sizeof *m);
    if (!m) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the MPM solver's state");
    m->nblocks = s->g.nblocks;
    m->keys_n = -1;
    m->counts = mem_calloc(sizeof(int) * ((size_t)m->nblocks + 1));
    m->mark = mem_calloc((size_t)m->nblocks);
    m->pbof = mem_alloc(sizeof(int) * (size_t)m->nblocks);
    if (!m->counts || !m->mark || !m->pbof) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the grid tables");
    for (int b = 0; b < m->nblocks; b++) m->pbof[b] = -1; /* step_team's gather: no particle block anywhere yet */
    /* the colour phases at any thread count: for measuring the gather against them on one build (the same bits) */
    const char *cp = getenv("HEARTH_MPM_COLOUR_PHASES");
    m->colour_phases = cp && strcmp(cp, "1") == 0;
    return mpm_ranks_init(m, err);
}

/* ---- P2G ------------------------------------------------------------- */

static void record_fail(pb_partial *pp, int i, fail_kind kind, int code) {
    if (pp->fail_i < 0) {
        pp->fail_i = i;
        pp->fail_kind = kind;
        pp->fail_code = code;
    }
}

/* Whether every a[k] is finite, with one test instead of one per value: x - x
 * is +0 for a finite x and NaN for an infinite or NaN one, so the sum is 0
 * exactly when all are (the compiler may not fold x - x to 0 without
 * -ffinite-math-only). 5 instructions a particle-step fewer in 2D (callgrind). */
FORCE_INLINE int all_finite(const double *a, const int n) {
    double z = 0.0;
    for (int k = 0; k < n; k++) z += a[k] - a[k];
    return z == 0.0;
}

/* p[0..1] += x (unaligned: a stencil may start at any node of the tile) */
FORCE_INLINE void p2g_add2(double *p, v2d x) {
    v2d y;
    memcpy(&y, p, sizeof y);
    y += x;
    memcpy(p, &y, sizeof y);
}

/* ---- 3D at more than one thread: claims from both ends, P2G's flushes in order ---- */

/* Each phase's range of blocks [lo, hi) in one word, handed out one block at
 * a time, even threads taking from the front and odd ones from the back: at
 * two threads, thread 0 works the low-x end of every phase (the particle
 * blocks, each colour's list and the active grid blocks are all in block
 * order, x slowest) and thread 1 the high-x end, and they meet wherever the
 * work splits, a block apart at most. So each grid node is written (P2G's
 * eight colours, the grid update) and read (G2P) by the same core through
 * the step, but at the seam between the two ends, where `dynamic` and
 * `guided` handed blocks to either thread at random and about half of each
 * node's cache lines went from core to core at each of its nine writes; the
 * 32-cell bench's grid (about 0.7 MB) fits a core's L2, where one thread
 * keeps it (issue 20, docs/performance.md "3D at 32 cells"). Which thread
 * steps a block moves no bits. On the stack of the region's caller (its own
 * cache lines: every claim writes one). */
typedef struct mpm_claims {
    unsigned long long colour[8], grid, g2p;
} __attribute__((aligned(64))) mpm_claims;

static unsigned long long claim_range(int lo, int hi) { return (unsigned)lo | (unsigned long long)(unsigned)hi << 32; }

/* the next block of range *c from its front (back = 0) or back, or -1 once none is left */
static int claim_take(unsigned long long *c, const int back) {
    unsigned long long v = __atomic_load_n(c, __ATOMIC_RELAXED);
    for (;;) {
        const int lo = (int)(unsigned)v, hi = (int)(unsigned)(v >> 32);
        if (lo >= hi) return -1;
        const unsigned long long nv = back ? claim_range(lo, hi - 1) : claim_range(lo + 1, hi);
        if (__atomic_compare_exchange_n(c, &v, nv, 0, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) return back ? hi - 1 : lo;
    }
}

/* This thread's end of every range: odd threads take from the back. */
static int claim_end(void) {
#ifdef _OPENMP
    return omp_get_thread_num() & 1;
#else
    return 0;
#endif
}

/* The claims for a step's phases (3D, a team of more than one thread, the
 * colour phases not asked for), or NULL: the phases then keep their
 * schedules and P2G its colour barriers. */
static mpm_claims *claims_begin(hearth_scene *s, mpm_claims *cl) {
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

static void claims_end(mpm_state *m) {
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
static void p2g_wait_lower(const hearth_scene *s, const int bc[3]) {
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

/* P2G's tile holds only the channels it writes: momentum, then heat, then
 * water, then the volume sum_p w_ip J V_0 (boundary.c's volume fraction; it
 * goes to CH_CG_R, which grid_activate zeroes in a field scene). The heat
 * pair (capacity, capacity x temperature) and the water pair (mass,
 * capacity) each sit interleaved, node by node, in their two channels' room,
 * so a node takes each pair in one two-lane add (the same operations lane by
 * lane, so the same bits; 0.15M of the 2D dough's 18.2M instructions a
 * step fewer, callgrind). */
enum { P2G_HC = GRID_NCH_MOMENTUM, P2G_T, P2G_MW, P2G_SW, P2G_V, P2G_NCH };
/* two_field (2D only): the nodes' reference damage gradients, then the second field's mass and momentum, past
 * the channels above in the same tile (2D uses 36 nodes of its 216) */
enum { P2G_GX = P2G_NCH, P2G_GY, P2G_BM, P2G_BX, P2G_BY, P2G_NCH_TWO };
_Static_assert(P2G_NCH_TWO * GRID_T * GRID_T <= P2G_NCH * GRID_T * GRID_T * GRID_T, "2D's two_field tile fits");
static const int p2g_channel[P2G_NCH] = {CH_M, CH_PX, CH_PY, CH_PZ, CH_HC, CH_T, CH_MW, CH_SW, CH_CG_R};

/* D (2 or 3), HEAT (0: no temperature; 1: the material reads it; 2: and the heat channels scatter, a field
 * step of field_clock.c), WATER (water live and a field step) and MIRROR (a
 * sticky collider: mpm_p2g_mirror) are compile-time constants in each
 * instantiation below, so a momentum-only scene runs the momentum-only loops
 * and a scene without sticky colliders carries no test for them (a runtime
 * test there cost 0.5% of P2G's instructions). */
FORCE_INLINE void p2g_block(hearth_scene *s, const int D, const int HEAT, const int WATER, const int MIRROR, const int TWO,
                            const int STORE, int k, double dt, double *tile) {
    grid *g = &s->g;
    particles *ps = &s->ps;
    mpm_state *st = s->mpm;
    const int HS = HEAT == 2; /* the heat channels scatter (a field step) */
    const pblock pb = st->pb[k];
    pb_partial *pp = &st->partial[k];
    double *vol = st->vol; /* loaded once: the plugin call in the loop would otherwise reload it */
    const int TN = D == 2 ? GRID_T * GRID_T : GRID_T * GRID_T * GRID_T;
    const int NPB = g->nodes_per_block;
    int bc[3];
    grid_block_coords(g, pb.block, bc);
    const int org[3] = {bc[0] * GRID_B, bc[1] * GRID_B, bc[2] * GRID_B};
    const int near_face = MIRROR ? mpm_block_near_sticky(s, D, org) : 0;
    if (STORE) st->pbof[pb.block] = k; /* for the gather (mpm_p2g_gather) */
    memset(tile, 0, sizeof(double) * GRID_NCH_MOMENTUM * (size_t)TN);
    if (HS) memset(tile + P2G_HC * TN, 0, sizeof(double) * 2 * (size_t)TN);
    if (WATER) memset(tile + P2G_MW * TN, 0, sizeof(double) * 2 * (size_t)TN);
    if (HS || WATER) memset(tile + P2G_V * TN, 0, sizeof(double) * (size_t)TN);
    const double *dgrad = TWO ? st->dgrad : NULL; /* two_field: each particle's damage gradient (mpm_two_field.c) */
    if (TWO) {
        memset(tile + P2G_BM * TN, 0, sizeof(double) * 3 * (size_t)TN);
        for (int a = 0; a < GRID_T; a++)
            for (int b = 0; b < GRID_T; b++) {
                int l;
                const double *node = grid_tile_node(g, D, bc, a, b, 0, &l);
                tile[P2G_GX * TN + a * GRID_T + b] = node[CH_TF_GX * NPB + l];
                tile[P2G_GY * TN + a * GRID_T + b] = node[CH_TF_GY * NPB + l];
            }
    }

    const double *X = pcold(ps, PC_X), *V = pcold(ps, PC_V), *M = pcold(ps, PC_MASS), *V0 = pcold(ps, PC_VOL0);
    const double *Cc = pcold(ps, PC_C);
    const int *mat = pcoli(ps, PC_MAT);
    /* the material reads the temperature every step (HEAT 1 or 2), the heat channels scatter only on a field step
     * (HEAT 2, HS): the fields' clock, field_clock.c */
    const double *Tcol = HEAT ? pcold(ps, PC_TEMPERATURE) : NULL;
    const double *Gcol = ps->enabled & (1u << PC_GAS) ? pcold(ps, PC_GAS) : NULL;
    const double *Wcol = ps->enabled & (1u << PC_WATER) ? pcold(ps, PC_WATER) : NULL;
    const double *S0col = Wcol ? pcold(ps, PC_SAT0) : NULL;
    const double dx = g->dx, inv_dx = g->inv_dx, Dinv = 4.0 * inv_dx * inv_dx;
    const int apic = s->def.transfer == 0;
    double cmax = 0, numax = 0; /* numax: largest kinematic viscosity a plugin applies (m^2/s) */
    /* what this scene supplies to the material door, the same for every particle; gas needs the porosity */
    const unsigned env_flags = MATERIAL_ZERO_FAILED | (Gcol ? MATERIAL_POROSITY_PLASTIC : 0u) | (HEAT ? MATERIAL_EXPANSION : 0u);
    double taus[9][HEARTH_BLOCK_MAX], Js[HEARTH_BLOCK_MAX]; /* stresses (columns) and det F of the chunk from mpm_p2g_stress */

    for (int i = pb.start; i < pb.end; i++) {
        /* C: 2D keeps its in-plane 2x2 block (plane strain, tensor2.h) */
        const double *x = X + 3 * i, *v = V + 3 * i, *C = Cc + (D == 2 ? 4 : 9) * i;
        const int j = (i - pb.start) % HEARTH_BLOCK_MAX;
        if (j == 0) /* the material call site: F and the stresses of the next HEARTH_BLOCK_MAX particles (mpm_stress.c) */
            mpm_p2g_stress(s, D, i, pb.end - i < HEARTH_BLOCK_MAX ? pb.end - i : HEARTH_BLOCK_MAX, dt, env_flags, Tcol, Wcol,
                           Gcol, S0col, taus, Js, pp, &cmax, &numax);
        const double J = Js[j];
        /* affine momentum with the stress folded in (MLS-MPM): Q = m C - dt V0 D^-1 tau */
        const double m = M[i], k0 = dt * V0[i] * Dinv, mC = apic ? m : 0.0; /* PIC drops the affine momentum */
        double Q[9]; /* 2D fills and reads its in-plane entries 0, 1, 3, 4 only */
        if (D == 2) {
            Q[0] = mC * C[0] - k0 * taus[0][j], Q[1] = mC * C[1] - k0 * taus[1][j];
            Q[3] = mC * C[2] - k0 * taus[3][j], Q[4] = mC * C[3] - k0 * taus[4][j];
        } else {
            for (int a = 0; a < 9; a++) Q[a] = mC * C[a] - k0 * taus[a][j];
        }

        int base[3] = {0, 0, 0};
        double fx[3] = {0, 0, 0}, w[3][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, dw[3];
        for (int d = 0; d < D; d++) {
            const double Xd = (x[d] - g->lo[d]) * inv_dx;
            const int b = base_node(Xd);
            fx[d] = Xd - b;
            base[d] = b - org[d];
            /* the stencil's 3 nodes must lie in the 6-node tile: mpm_sort's clamp_to_grid */
            HEARTH_ASSERT(base[d] >= 0 && base[d] <= GRID_T - 3);
            bspline_weights(fx[d], w[d], dw);
        }
        const double mv0 = m * v[0], mv1 = m * v[1], mv2 = m * v[2];
        /* heat (eq. 17, weighted by heat capacity m alpha so energy is conserved across materials) */
        const double hc = HS ? m * s->mats.slot[mat[i]].core[CP_SPECIFIC_HEAT] : 0.0, hct = HS ? hc * Tcol[i] : 0.0;
        const double vi = J * V0[i];
        if (HS || WATER) vol[i] = vi; /* for transport.c, water_take and the volume channel */
        /* water mass and capacity rho_0^w J V_0 (eq. 15, 18) */
        const double mw = WATER ? Wcol[i] : 0.0, cap = WATER ? s->mats.slot[mat[i]].core[CP_WATER_DENSITY] * J * V0[i] : 0.0;
        /* the stencil's corner in the tile: the 3^dim nodes then sit at constant offsets from it */
        const int toff = D == 2 ? base[0] * GRID_T + base[1] : (base[0] * GRID_T + base[1]) * GRID_T + base[2];
        double *const tp = tile + toff;
        double *const th = tile + P2G_HC * TN + 2 * toff, *const tw = tile + P2G_MW * TN + 2 * toff; /* the pairs */
        const v2d hp = {hc, hct}, wp = {mw, cap};
        /* 3D: the c = 0, 1 pair's weights along z and offsets (c - fx) dx, and c = 2's offset */
        const v2d w2_01 = {w[2][0], w[2][1]}, d2_01 = {(0 - fx[2]) * dx, (1 - fx[2]) * dx};
        const double d2_2 = (2 - fx[2]) * dx;
        for (int a = 0; a < 3; a++) {
            /* the volume weighs in as (V w_a) w_b w_c, the order of the pass it replaced: the same bits */
            const double d0 = (a - fx[0]) * dx, va = vi * w[0][a];
            for (int b = 0; b < 3; b++) {
                const double d1 = (b - fx[1]) * dx, wab = w[0][a] * w[1][b], vab = va * w[1][b];
                if (D == 2) {
                    const int t = a * GRID_T + b;
                    tp[t] += wab * m;
                    tp[TN + t] += wab * (mv0 + Q[0] * d0 + Q[1] * d1);
                    tp[2 * TN + t] += wab * (mv1 + Q[3] * d0 + Q[4] * d1);
                    if (HS) p2g_add2(th + 2 * t, (v2d){wab, wab} * hp);
                    if (WATER) p2g_add2(tw + 2 * t, (v2d){wab, wab} * wp);
                    if (HS || WATER) tp[P2G_V * TN + t] += vab;
                    /* the second field's particles at this node scatter the same terms into its channels too */
                    if (TWO && mpm_two_field_second(tp[P2G_GX * TN + t], tp[P2G_GY * TN + t], dgrad[2 * i], dgrad[2 * i + 1])) {
                        tp[P2G_BM * TN + t] += wab * m;
                        tp[P2G_BX * TN + t] += wab * (mv0 + Q[0] * d0 + Q[1] * d1);
                        tp[P2G_BY * TN + t] += wab * (mv1 + Q[3] * d0 + Q[4] * d1);
                    }
                } else {
                    /* Momentum: the nodes c = 0 and 1 are adjacent in the tile, so they go as a pair of lanes
                     * (c = 2 alone). ((mv + Q d0) + Q d1) is the same for the three c, and each lane does the
                     * scalar expression's operations in its order: the same bits, 3D P2G's scatter in fewer
                     * instructions (callgrind). */
                    const int t0 = (a * GRID_T + b) * GRID_T;
                    const double s0 = mv0 + Q[0] * d0 + Q[1] * d1, s1 = mv1 + Q[3] * d0 + Q[4] * d1,
                                 s2 = mv2 + Q[6] * d0 + Q[7] * d1;
                    const v2d w01 = (v2d){wab, wab} * w2_01;
                    p2g_add2(tp + t0, w01 * (v2d){m, m});
                    p2g_add2(tp + TN + t0, w01 * ((v2d){s0, s0} + (v2d){Q[2], Q[2]} * d2_01));
                    p2g_add2(tp + 2 * TN + t0, w01 * ((v2d){s1, s1} + (v2d){Q[5], Q[5]} * d2_01));
                    p2g_add2(tp + 3 * TN + t0, w01 * ((v2d){s2, s2} + (v2d){Q[8], Q[8]} * d2_01));
                    const double wt2 = wab * w[2][2];
                    tp[t0 + 2] += wt2 * m;
                    tp[TN + t0 + 2] += wt2 * (s0 + Q[2] * d2_2);
                    tp[2 * TN + t0 + 2] += wt2 * (s1 + Q[5] * d2_2);
                    tp[3 * TN + t0 + 2] += wt2 * (s2 + Q[8] * d2_2);
                    for (int c = 0; c < (HS || WATER ? 3 : 0); c++) {
                        const double wt = wab * w[2][c];
                        const int t = t0 + c;
                        if (HS) p2g_add2(th + 2 * t, (v2d){wt, wt} * hp);
                        if (WATER) p2g_add2(tw + 2 * t, (v2d){wt, wt} * wp);
                        if (HS || WATER) tp[P2G_V * TN + t] += vab * w[2][c];
                    }
                }
            }
        }
        if (MIRROR && near_face) {
            double tau[9];
            for (int a = 0; a < 9; a++) tau[a] = taus[a][j];
            mpm_p2g_mirror(s, D, x, tau, k0, pb.block, tile);
        }
    }

    pp->cmax = cmax;
    pp->numax = numax;
    if (STORE) { /* kept for the gather instead of the flush below */
        mpm_p2g_keep_tile(s, D, k, bc, tile);
        return;
    }

    /* flush the tile into the block and its +1 neighbours (after the lower colours' flushes there when ordered) */
    if (st->p2g_ordered) p2g_wait_lower(s, bc);
    for (int a = 0; a < GRID_T; a++)
        for (int b = 0; b < GRID_T; b++)
            for (int c = 0; c < (D == 3 ? GRID_T : 1); c++) {
                const int t = D == 2 ? a * GRID_T + b : (a * GRID_T + b) * GRID_T + c;
                if (tile[t] == 0.0) continue;
                int l;
                double *node = grid_tile_node(g, D, bc, a, b, c, &l);
                for (int ch = 0; ch < GRID_NCH_MOMENTUM; ch++) node[ch * NPB + l] += tile[ch * TN + t];
                if (HS) /* the interleaved pairs */
                    for (int ch = 0; ch < 2; ch++) node[p2g_channel[P2G_HC + ch] * NPB + l] += tile[P2G_HC * TN + 2 * t + ch];
                if (WATER)
                    for (int ch = 0; ch < 2; ch++) node[p2g_channel[P2G_MW + ch] * NPB + l] += tile[P2G_MW * TN + 2 * t + ch];
                if (HS || WATER) node[CH_CG_R * NPB + l] += tile[P2G_V * TN + t];
                if (TWO)
                    for (int ch = 0; ch < 3; ch++) node[(CH_TF_M + ch) * NPB + l] += tile[(P2G_BM + ch) * TN + t];
            }
    if (st->p2g_ordered) __atomic_store_n(&pp->flushed, 1, __ATOMIC_RELEASE);
}

typedef void (*block_fn)(hearth_scene *, int, double, double *);
/* the instantiations, indexed [dim == 3][heat][water] */
#define BLOCK_FN(kind, D, H, W) \
    static void kind##_##D##H##W(hearth_scene *s, int k, double dt, double *tile) { kind##_block(s, D, H, W, 0, k, dt, tile); }
/* the stored-tile P2G of step_team's gather path (momentum only), indexed [sticky][dim == 3] */
#define P2G_STORE_FN(D, M, H) \
    static void p2g_store_##D##M##H(hearth_scene *s, int k, double dt, double *tile) { p2g_block(s, D, H, 0, M, 0, 1, k, dt, tile); }
/* [temperature: a heat scene's step between its field steps][sticky][dim == 3] */
P2G_STORE_FN(2, 0, 0) P2G_STORE_FN(3, 0, 0) P2G_STORE_FN(2, 1, 0) P2G_STORE_FN(3, 1, 0)
P2G_STORE_FN(2, 0, 1) P2G_STORE_FN(3, 0, 1) P2G_STORE_FN(2, 1, 1) P2G_STORE_FN(3, 1, 1)
static const block_fn p2g_store_fns[2][2][2] = {{{p2g_store_200, p2g_store_300}, {p2g_store_210, p2g_store_310}},
                                                {{p2g_store_201, p2g_store_301}, {p2g_store_211, p2g_store_311}}};
/* P2G's, indexed [sticky][dim == 3][heat][water] */
#define P2G_FN(D, H, W, M) \
    static void p2g_##D##H##W##M(hearth_scene *s, int k, double dt, double *tile) { p2g_block(s, D, H, W, M, 0, 0, k, dt, tile); }
/* two_field's, 2D without sticky colliders, indexed [heat][water] */
#define P2G_TWO_FN(H, W) \
    static void p2g_two_##H##W(hearth_scene *s, int k, double dt, double *tile) { p2g_block(s, 2, H, W, 0, 1, 0, k, dt, tile); }
P2G_TWO_FN(0, 0) P2G_TWO_FN(0, 1) P2G_TWO_FN(1, 0) P2G_TWO_FN(1, 1) P2G_TWO_FN(2, 0) P2G_TWO_FN(2, 1)
static const block_fn p2g_two_fns[3][2] = {{p2g_two_00, p2g_two_01}, {p2g_two_10, p2g_two_11}, {p2g_two_20, p2g_two_21}};
P2G_FN(2, 0, 0, 0) P2G_FN(2, 0, 1, 0) P2G_FN(2, 1, 0, 0) P2G_FN(2, 1, 1, 0) P2G_FN(2, 2, 0, 0) P2G_FN(2, 2, 1, 0)
P2G_FN(3, 0, 0, 0) P2G_FN(3, 0, 1, 0) P2G_FN(3, 1, 0, 0) P2G_FN(3, 1, 1, 0) P2G_FN(3, 2, 0, 0) P2G_FN(3, 2, 1, 0)
P2G_FN(2, 0, 0, 1) P2G_FN(2, 0, 1, 1) P2G_FN(2, 1, 0, 1) P2G_FN(2, 1, 1, 1) P2G_FN(2, 2, 0, 1) P2G_FN(2, 2, 1, 1)
P2G_FN(3, 0, 0, 1) P2G_FN(3, 0, 1, 1) P2G_FN(3, 1, 0, 1) P2G_FN(3, 1, 1, 1) P2G_FN(3, 2, 0, 1) P2G_FN(3, 2, 1, 1)
/* [sticky][dim == 3][heat: p2g_heat][water] */
static const block_fn p2g_fns[2][2][3][2] = {
    {{{p2g_2000, p2g_2010}, {p2g_2100, p2g_2110}, {p2g_2200, p2g_2210}},
     {{p2g_3000, p2g_3010}, {p2g_3100, p2g_3110}, {p2g_3200, p2g_3210}}},
    {{{p2g_2001, p2g_2011}, {p2g_2101, p2g_2111}, {p2g_2201, p2g_2211}},
     {{p2g_3001, p2g_3011}, {p2g_3101, p2g_3111}, {p2g_3201, p2g_3211}}}};

/* P2G's heat instantiation: 0 without temperature, 1 when the material reads it but the fields rest this
 * step (field_clock.c), 2 on a field step: the heat channels scatter too. */
static int p2g_heat(const hearth_scene *s) { return !thermal_active(s) ? 0 : s->field_skip ? 1 : 2; }

/* P2G's instantiation for this step's scene, and its blocks' partials reset (serial: O(particle blocks)). */
static block_fn p2g_prepare(hearth_scene *s) {
    mpm_state *m = s->mpm;
    m->sticky_faces = 0;
    for (int c = 0; c < s->ncol; c++) m->sticky_faces |= s->cols[c].mode == HEARTH_STICKY;
    for (int k = 0; k < m->npb; k++) m->partial[k] = (pb_partial){.fail_i = -1, .fastest = -1};
    if (m->p2g_ordered) /* where each block's neighbours are (p2g_wait_lower); back to -1 after P2G (p2g_team) */
        for (int k = 0; k < m->npb; k++) m->pbof[m->pb[k].block] = k;
    if (s->def.two_field) return p2g_two_fns[p2g_heat(s)][water_now(s)]; /* 2D, no sticky face (mpm_step) */
    return p2g_fns[m->sticky_faces][s->g.dim == 3][p2g_heat(s)][water_now(s)];
}

/* P2G's colour phases, for the team of the enclosing parallel region (one
 * thread outside one): orphaned loops, so mpm_step can run P2G, the grid
 * update and G2P in one region (step_team). One block at a time: dynamic
 * chunks of two 512-particle blocks left one thread up to a chunk idle at
 * each of 3D's 8 colour barriers (a model of the 3D 32-cell bench's 27 blocks
 * a colour: 4.2% of P2G; 0.4% with single blocks). The order in which a
 * colour's blocks run moves no bits: no two of them share a node. */
static void p2g_team(hearth_scene *s, block_fn fn, double dt) {
    mpm_state *m = s->mpm;
    double tile[P2G_NCH * GRID_T * GRID_T * GRID_T];
    if (m->claims) { /* 3D at more than one thread: the colours in order, one barrier at the end (p2g_wait_lower) */
        const int back = claim_end();
        for (int col = 0; col < 8; col++)
            for (int q; (q = claim_take(&m->claims->colour[col], back)) >= 0;)
                if (m->colour_pb[q] >= m->k_lo && m->colour_pb[q] < m->k_hi) fn(s, m->colour_pb[q], dt, tile); /* this rank's */
#pragma omp barrier
#pragma omp for schedule(static) nowait
        for (int k = 0; k < m->npb; k++) m->pbof[m->pb[k].block] = -1;
        return;
    }
    for (int col = 0; col < 8; col++) {
        const int a = m->colour_start[col], b = m->colour_start[col + 1];
        if (a == b) continue; /* 2D fills 4 colours of 8: no barrier for the rest (every thread sees the same a, b) */
#pragma omp for schedule(dynamic, 1)
        for (int q = a; q < b; q++)
            if (m->colour_pb[q] >= m->k_lo && m->colour_pb[q] < m->k_hi) fn(s, m->colour_pb[q], dt, tile); /* this rank's */
        /* the implicit barrier of omp for separates colours */
    }
}

void mpm_p2g(hearth_scene *s, double dt, step_report *rep) {
    (void)rep;
    mpm_claims cl;
    claims_begin(s, &cl);
    const block_fn fn = p2g_prepare(s);
#pragma omp parallel if (s->ps.n >= SCENE_PARALLEL_MIN)
    p2g_team(s, fn, dt);
    claims_end(s->mpm);
}

/* ---- the one-region step's share-out ---------------------------------- */

/* In the one-region step (step_team_sorted) a chunk's particle blocks and its
 * grid blocks go, in P2G, the grid update and G2P alike, first to the thread
 * that owns the chunk (the sort's static split: the chunk it counts and lists
 * first), which takes them from the front of the chunk's span; a thread done
 * with its own chunks takes from the back of the others'. So a particle's
 * columns are read and written by one core from phase to phase and step to
 * step, save where a late thread's share is taken from its tail. Before, P2G
 * went by chunk too but G2P and the grid update by `schedule(guided)`, whose
 * first half went to whichever thread came first: about every other step,
 * G2P ran each particle block on the other core from its P2G, and the x, v,
 * C, F and key lines (about 150 bytes a particle, 3.7 MB at 2D 128 cells,
 * each core's half near its 2 MiB L2) crossed between the cores twice a
 * step. Which thread takes a block moves no bits: each block's work is its
 * own (the same instructions, callgrind). */
typedef struct span_walk {
    int me, P, c0, c1, T, j; /* this thread of P; its own chunks [c0, c1) of T; the chunk being taken from */
    long back;               /* the blocks it took from other threads' chunks */
} span_walk;

static span_walk span_walk_start(int T) {
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
static int span_next(mpm_span *sp, span_walk *w, const int *ready, int *lo, int *hi) {
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
static void span_count(mpm_state *m, int phase, const span_walk *w) {
    if (w->back) __atomic_fetch_add(&m->span_back[phase], w->back, __ATOMIC_RELAXED);
}

/* ---- grid update ----------------------------------------------------- */

/* One active block's nodes; returns the fastest collider speed squared at a
 * node with mass (the guard's driven energy). DAMP is a compile-time constant
 * in each of the two loops of mpm_grid_update, so the undamped one carries no
 * damping test: OpenMP outlines a parallel loop before inlining, so the
 * constant must reach the block, not a function holding the pragma. */
FORCE_INLINE double grid_update_block(hearth_scene *s, int k, double dt, double damp, const int DAMP, const int ch0) {
    grid *g = &s->g;
    const int D = g->dim, NPB = g->nodes_per_block;
    const hearth_scene_def *def = &s->def;
    double vcol2 = 0;
    double *node = grid_block(g, k) + (size_t)ch0 * (size_t)NPB; /* ch0: CH_M, or two_field's second field CH_TF_M */
    int bc[3];
    grid_block_coords(g, g->active[k], bc);
    /* domain walls act on the two node layers nearest each face; a periodic axis has none */
    int wlo[3], whi[3];
    for (int d = 0; d < 3; d++) {
        wlo[d] = def->periodic[d] ? INT_MIN : 2;
        whi[d] = def->periodic[d] ? INT_MAX : g->nn[d] - 3;
    }
    for (int l = 0; l < NPB; l++) {
        const double m = node[l];
        if (m <= 0.0) {
            node[NPB + l] = node[2 * NPB + l] = node[3 * NPB + l] = 0.0;
            continue;
        }
        int idx[3];
        grid_node_index(g, bc, l, idx);
        double xi[3] = {0, 0, 0};
        for (int d = 0; d < D; d++) xi[d] = g->lo[d] + idx[d] * g->dx;
        double v[3] = {node[NPB + l] / m, node[2 * NPB + l] / m, D == 3 ? node[3 * NPB + l] / m : 0.0};
        double acc[3] = {def->gravity[0], def->gravity[1], D == 3 ? def->gravity[2] : 0.0};
        if (s->body_force) {
            double extra[3] = {0, 0, 0};
            s->body_force(s->body_force_ud, s->t, xi, extra);
            for (int d = 0; d < D; d++) acc[d] += extra[d];
        }
        for (int d = 0; d < D; d++) v[d] += dt * acc[d];
        if (DAMP)
            for (int d = 0; d < D; d++) v[d] *= damp;
        /* domain walls act on the two node layers nearest each face */
        for (int d = 0; d < D; d++) {
            const double zero[3] = {0, 0, 0};
            double n[3] = {0, 0, 0};
            if (idx[d] < wlo[d]) n[d] = 1.0;
            else if (idx[d] > whi[d]) n[d] = -1.0;
            else continue;
            contact_apply(def->wall, def->wall_friction, n, zero, v);
        }
        for (int c = 0; c < s->ncol; c++) {
            double n[3];
            /* Every collider, a grip too, holds the nodes inside it and on its
             * face (COLLIDER_ROW_TOL), none outside: a grip clamps at its face.
             * (Holding a grip's nodes a cell outside kept a pulled strip from
             * peeling off, at the cost of a clamp one cell in; G2P's carry now
             * keeps the stress continuous instead.) */
            const double band = COLLIDER_ROW_TOL * g->dx;
            if (!collider_near(&s->cols[c], xi)) continue;
            const double phi = collider_sdf(&s->cols[c], xi, n);
            if (phi > band) continue;
            /* a held node within reach of a sticky face's reflection: a negative mass marks it for
             * mpm_sticky_ghosts_block, which finds it without an SDF per node and restores the sign */
            if (s->cols[c].mode == HEARTH_STICKY && phi > -1.5 * g->dx) node[l] = -m;
            double vb[3];
            collider_velocity_at(&s->cols[c], xi, vb);
            if (D == 2) n[2] = vb[2] = 0.0;
            contact_apply(s->cols[c].mode, s->cols[c].friction, n, vb, v);
            vcol2 = fmax(vcol2, vb[0] * vb[0] + vb[1] * vb[1] + vb[2] * vb[2]);
        }
        node[NPB + l] = v[0];
        node[2 * NPB + l] = v[1];
        node[3 * NPB + l] = D == 3 ? v[2] : 0.0;
    }
    return vcol2;
}

/* The grid update for the team of the enclosing region (one thread outside
 * one); ends with a barrier, so G2P may read any node. The fastest collider
 * speed squared goes into *vcol2 (shared), the largest of the threads' own:
 * a maximum, the same whatever the threads. */
static void grid_update_team(hearth_scene *s, double dt, double *vcol2, const int gather, mpm_sort_team *t) {
    const grid *g = &s->g;
    double v2 = 0;
    if (s->def.two_field) { /* the second field's nodes (mpm_two_field.c) take the same update */
        const double damp = s->def.damping > 0 ? 1.0 / (1.0 + s->def.damping * dt) : 1.0;
#pragma omp for schedule(dynamic, 4) nowait
        for (int k = 0; k < g->nactive; k++) v2 = fmax(v2, grid_update_block(s, k, dt, damp, s->def.damping > 0, CH_TF_M));
    }
    mpm_claims *cl = s->mpm->claims; /* 3D at more than one thread: from both ends (claim_take), never gathering */
    if (t) { /* the one-region step: chunk by chunk, each first to its P2G's thread (span_next) */
        const double damp = s->def.damping > 0 ? 1.0 / (1.0 + s->def.damping * dt) : 1.0;
        span_walk w = span_walk_start(t->T);
        int lo, hi;
        while (span_next(t->span[MPM_SPAN_GRID], &w, NULL, &lo, &hi))
            for (int k = lo; k < hi; k++) {
                mpm_p2g_gather(s, k);
                v2 = fmax(v2, s->def.damping > 0 ? grid_update_block(s, k, dt, damp, 1, CH_M) : grid_update_block(s, k, dt, 1.0, 0, CH_M));
            }
        span_count(s->mpm, MPM_SPAN_GRID, &w);
    } else if (cl) {
        const int back = claim_end(), DAMP = s->def.damping > 0;
        const double damp = DAMP ? 1.0 / (1.0 + s->def.damping * dt) : 1.0; /* as below */
        if (DAMP)
            for (int k; (k = claim_take(&cl->grid, back)) >= 0;) v2 = fmax(v2, grid_update_block(s, k, dt, damp, 1, CH_M));
        else
            for (int k; (k = claim_take(&cl->grid, back)) >= 0;) v2 = fmax(v2, grid_update_block(s, k, dt, 1.0, 0, CH_M));
    } else if (s->def.damping > 0) {
        /* Velocity damping for static problems, implicit in the drag (v' = v + dt (g - c v')) so any c dt
         * is stable; an explicit factor 1 - c dt would reverse velocities past c dt = 1. It acts after
         * gravity and before walls and colliders: damping the momentum before gravity instead would
         * leave a body in equilibrium a residual velocity dt g c dt / (1 + c dt), and it would sink. */
        const double damp = 1.0 / (1.0 + s->def.damping * dt);
#pragma omp for schedule(guided, 4) nowait
        for (int k = 0; k < g->nactive; k++) {
            if (gather) mpm_p2g_gather(s, k);
            v2 = fmax(v2, grid_update_block(s, k, dt, damp, 1, CH_M));
        }
    } else {
#pragma omp for schedule(guided, 4) nowait
        for (int k = 0; k < g->nactive; k++) {
            if (gather) mpm_p2g_gather(s, k); /* step_team's stored tiles into this block's nodes first */
            v2 = fmax(v2, grid_update_block(s, k, dt, 1.0, 0, CH_M));
        }
    }
#pragma omp critical(mpm_vcol2)
    if (v2 > *vcol2) *vcol2 = v2;
#pragma omp barrier
    if (s->mpm->sticky_faces) {
#pragma omp for schedule(dynamic, 4)
        for (int k = 0; k < g->nactive; k++) mpm_sticky_ghosts_block(s, k);
        const int NPB = g->nodes_per_block; /* the marks off again, once every ghost has been read */
#pragma omp for schedule(static)
        for (int k = 0; k < g->nactive; k++) {
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) node[l] = fabs(node[l]);
        }
    }
}

double mpm_grid_update(hearth_scene *s, double dt) {
    double vcol2 = 0; /* the fastest collider at a node with mass (the guard's driven energy) */
    /* a body force that is not thread-safe (a Lua function) keeps the update on one thread */
    const int par = s->ps.n >= SCENE_PARALLEL_MIN && !s->body_force_serial;
    mpm_claims cl;
    if (par) claims_begin(s, &cl);
#pragma omp parallel if (par)
    grid_update_team(s, dt, &vcol2, 0, NULL);
    claims_end(s->mpm);
    return sqrt(vcol2);
}

/* ---- G2P ------------------------------------------------------------- */

FORCE_INLINE void g2p_block(hearth_scene *s, const int D, const int HEAT, const int WATER, const int TWO, int k, double dt,
                            double *tile) {
    grid *g = &s->g;
    particles *ps = &s->ps;
    /* HEAT 2: the update also needs the nodes' temperature at the particle (a FLIP-PIC blend or held
     * temperatures); HEAT 1, pure FLIP (heat_flip = 1, nothing held, the usual case), gathers only the change */
    const int PIC = HEAT == 2;
    double *Tcol = HEAT ? pcold(ps, PC_TEMPERATURE) : NULL, *Tmax = HEAT ? pcold(ps, PC_TEMP_MAX) : NULL;
    double *Gcol = HEAT && (ps->enabled & (1u << PC_GAS)) ? pcold(ps, PC_GAS) : NULL;
    const int *flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    const double *hold_h = HEAT && s->heat.nfix > 0 ? s->heat.hold_h : NULL; /* held temperatures (thermal.c) */
    const double boil = HEAT && WATER && s->def.latent_heat ? s->def.boiling_point : INFINITY; /* no boiling: never passed */
    const int vent = Gcol && s->def.gas_vent > 0 && s->boundary.area; /* boundary.c found the surface this step */
    const double fdt = field_dt(s, dt); /* the CO2's time: the fields' cycle (HEAT runs on its field steps only) */
    const pblock pb = s->mpm->pb[k];
    pb_partial *pp = &s->mpm->partial[k];
    /* the next sort's keys (mpm_sort); a periodic scene wraps after G2P and files its particles there */
    int *keys = s->def.periodic[0] || s->def.periodic[1] || s->def.periodic[2] ? NULL : s->mpm->keys;
    int clamped = 0;
    const int TN = D == 2 ? GRID_T * GRID_T : GRID_T * GRID_T * GRID_T;
    const int NPB = g->nodes_per_block;
    int bc[3];
    grid_block_coords(g, pb.block, bc);
    const int org[3] = {bc[0] * GRID_B, bc[1] * GRID_B, bc[2] * GRID_B};

    /* gather the tile's velocities once; particles then read a small dense array */
    for (int a = 0; a < GRID_T; a++)
        for (int b = 0; b < GRID_T; b++)
            for (int c = 0; c < (D == 3 ? GRID_T : 1); c++) {
                const int t = D == 2 ? a * GRID_T + b : (a * GRID_T + b) * GRID_T + c;
                int l;
                const double *node = grid_tile_node(g, D, bc, a, b, c, &l);
                for (int d = 0; d < 3; d++) tile[d * TN + t] = node[(d + 1) * NPB + l];
                if (HEAT) {
                    tile[3 * TN + t] = node[CH_T * NPB + l] - node[CH_T0 * NPB + l];
                    if (PIC) tile[4 * TN + t] = node[CH_T * NPB + l];
                }
                if (WATER) { /* the change of node saturation, ds_i = dm_i / (rho_0 V_i) (water.c) */
                    const double cw = node[CH_MW * NPB + l];
                    tile[5 * TN + t] = cw > 0 ? node[CH_DMW * NPB + l] / cw : 0.0;
                }
                if (TWO) /* two_field (2D): the second field's velocity and the node's reference gradient */
                    for (int ch = 0; ch < 2; ch++) {
                        tile[(6 + ch) * TN + t] = node[(CH_TF_PX + ch) * NPB + l];
                        tile[(8 + ch) * TN + t] = node[(CH_TF_GX + ch) * NPB + l];
                    }
            }
    const double *dgrad = TWO ? s->mpm->dgrad : NULL;

    double *X = pcold(ps, PC_X), *V = pcold(ps, PC_V), *Cc = pcold(ps, PC_C);
    const double *M = pcold(ps, PC_MASS);
    const int *mat = pcoli(ps, PC_MAT);
    const double dx = g->dx, inv_dx = g->inv_dx, Dinv = 4.0 * inv_dx * inv_dx;
    double lo[3], hi[3];
    for (int d = 0; d < 3; d++) {
        lo[d] = g->lo[d] + dx;                       /* keep every particle's stencil on the grid */
        hi[d] = g->lo[d] + (g->nn[d] - 2) * dx;
        if (s->def.periodic[d]) lo[d] = -INFINITY, hi[d] = INFINITY; /* wrapped after G2P instead */
    }
    double ke = 0, mass = 0, vmax = -1, move2 = 0;
    int mover = -1;
    double w_removed = 0, w_dmax = 0, w_emax = 0;
    int fastest = -1;
    long ood = 0;
    for (int i = pb.start; i < pb.end; i++) {
        double *x = X + 3 * i, *v = V + 3 * i, *C = Cc + (D == 2 ? 4 : 9) * i; /* 2D: the in-plane 2x2 (tensor2.h) */
        int base[3] = {0, 0, 0};
        double fx[3] = {0, 0, 0}, w[3][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, dw[3];
        for (int d = 0; d < D; d++) {
            const double Xd = (x[d] - g->lo[d]) * inv_dx;
            const int b = base_node(Xd);
            fx[d] = Xd - b;
            base[d] = b - org[d];
            bspline_weights(fx[d], w[d], dw);
        }
        double nv[3] = {0, 0, 0}, B[9] = {0}, dT = 0, Tn = 0, ds = 0; /* 2D sums B's in-plane entries 0, 1, 3, 4 */
        /* the stencil's corner in the tile: the 3^dim nodes then sit at constant offsets from it */
        const double *const tp = tile + (D == 2 ? base[0] * GRID_T + base[1] : (base[0] * GRID_T + base[1]) * GRID_T + base[2]);
        /* 3D sums nv and B in pairs of lanes: Ak = {B[3k], B[3k+1]} += (wt u_k) {d0, d1} and Nk = {nv[k], B[3k+2]}
         * += (wt u_k) {1, d2}. Each lane does the scalar sum's operations in its order ((wt u_k) 1 is wt u_k
         * exactly), so the bits are the same; the sums take half the instructions (3D G2P, callgrind). */
        v2d A0 = {0, 0}, A1 = {0, 0}, A2 = {0, 0}, N0 = {0, 0}, N1 = {0, 0}, N2 = {0, 0};
        v2d q2[3] = {{1.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}};
        if (D == 3)
            for (int c = 0; c < 3; c++) q2[c][1] = (c - fx[2]) * dx;
        for (int a = 0; a < 3; a++) {
            const double d0 = (a - fx[0]) * dx;
            for (int b = 0; b < 3; b++) {
                const double d1 = (b - fx[1]) * dx, wab = w[0][a] * w[1][b];
                if (D == 2) {
                    const int t = a * GRID_T + b;
                    /* two_field: a particle of the node's second field reads that field's velocity */
                    const int sec = TWO && mpm_two_field_second(tp[8 * TN + t], tp[9 * TN + t], dgrad[2 * i], dgrad[2 * i + 1]);
                    const double u0 = sec ? tp[6 * TN + t] : tp[t], u1 = sec ? tp[7 * TN + t] : tp[TN + t];
                    if (HEAT) dT += wab * tp[3 * TN + t];
                    if (PIC) Tn += wab * tp[4 * TN + t];
                    if (WATER) ds += wab * tp[5 * TN + t];
                    nv[0] += wab * u0;
                    nv[1] += wab * u1;
                    B[0] += wab * u0 * d0; B[1] += wab * u0 * d1;
                    B[3] += wab * u1 * d0; B[4] += wab * u1 * d1;
                } else {
                    const v2d p01 = {d0, d1};
                    for (int c = 0; c < 3; c++) {
                        const double wt = wab * w[2][c];
                        const int t = (a * GRID_T + b) * GRID_T + c;
                        if (HEAT) dT += wt * tp[3 * TN + t];
                        if (PIC) Tn += wt * tp[4 * TN + t];
                        if (WATER) ds += wt * tp[5 * TN + t];
                        const double wu0 = wt * tp[t], wu1 = wt * tp[TN + t], wu2 = wt * tp[2 * TN + t];
                        const v2d g0 = {wu0, wu0}, g1 = {wu1, wu1}, g2 = {wu2, wu2};
                        A0 += g0 * p01; N0 += g0 * q2[c];
                        A1 += g1 * p01; N1 += g1 * q2[c];
                        A2 += g2 * p01; N2 += g2 * q2[c];
                    }
                }
            }
        }
        if (D == 3) {
            nv[0] = N0[0], nv[1] = N1[0], nv[2] = N2[0];
            B[0] = A0[0], B[1] = A0[1], B[2] = N0[1];
            B[3] = A1[0], B[4] = A1[1], B[5] = N1[1];
            B[6] = A2[0], B[7] = A2[1], B[8] = N2[1];
        }
        if (D == 2) C[0] = Dinv * B[0], C[1] = Dinv * B[1], C[2] = Dinv * B[3], C[3] = Dinv * B[4];
        else
            for (int a = 0; a < 9; a++) C[a] = Dinv * B[a];
        /* water first: its step limits use the temperature the flux was evaluated at */
        if (WATER) w_removed += water_take(s, i, ds, &w_dmax, &w_emax);
        if (HEAT) { /* FLIP (eq. 21): the particle takes its nodes' temperature change */
            const double T0 = Tcol[i], flip = s->def.heat_flip;
            double T1 = !PIC || flip == 1.0 ? T0 + dT : flip * (T0 + dT) + (1.0 - flip) * Tn; /* FLIP-PIC blend */
            if (PIC && hold_h && hold_h[i] > 0) T1 += hold_h[i] * (Tn - T1); /* toward held nodes (thermal.c's held_settle) */
            /* a held body's particle keeps its temperature (thermal.c holds its nodes) */
            if (!(flags && (flags[i] & PF_HOLD_T))) {
                Tcol[i] = T1;
                /* interior boiling (latent_heat): wet matter stays at the boiling point (water.c) */
                if (WATER && T1 > boil) w_removed += water_boil(s, i, &Tcol[i], boil);
            }
            if (Tcol[i] > Tmax[i]) Tmax[i] = Tcol[i];
            if (Gcol) { /* CO2 over the cycle, temperature moving linearly from T0 to T1 (§5.4), less what its
                         * earlier steps made (gas.c's gas_between: the gas moves every step) */
                const material_slot *gm = &s->mats.slot[mat[i]];
                Gcol[i] += gas_moles_field_step(T0, Tcol[i], fdt, s->field_acc, gm->core[CP_GAS_RATE],
                                                gm->params[gm->density_index], gm->core[CP_REACTION_T],
                                                gm->core[CP_REACTION_WIDTH]);
                if (vent) Gcol[i] *= gas_vent_factor(s, i, dt); /* open surface pores lose their CO2 (gas.c) */
            }
        }
        if (flags && (flags[i] & PF_FIXED)) { /* a pinned particle keeps its place */
            memset(v, 0, 3 * sizeof(double));
            memset(C, 0, (D == 2 ? 4 : 9) * sizeof(double));
            if (keys) {
                clamped += clamp_to_grid(g, x);
                keys[i] = block_of_position(g, x);
            }
            continue;
        }
        /* A grip carries the particles inside it rigidly (the nodes near its
         * face mix in the material's velocity, which let a held end slip out),
         * but their C stays the grid's: deep inside, where every node is held,
         * that is the grip's skew(omega); within a cell of the face it takes the
         * free material's shear, so the stress is continuous across the face
         * and the face holds. With C = skew(omega) there the carried particles
         * stayed unstressed, the first free node row saw a free surface and the
         * material slid off unless the nodes a cell outside were held too: a
         * clamp a cell in from the face (`grip_cantilever_clamped_at_face`). */
        int carried = 0;
        for (int c = 0; c < s->ncol && !carried; c++)
            if (s->cols[c].mode == HEARTH_GRIP && collider_near(&s->cols[c], x))
                carried = collider_carry_particle(&s->cols[c], D, dt, x, v, NULL);
        /* The guard judges motion, not only the end speed: a wall or collider
         * below may zero v after the particle has already jumped cells. The
         * grid's velocity over dt is the motion asked for; a carried particle
         * moves with its grip. */
        const double xo[3] = {x[0], x[1], x[2]};
        int out = 0;
        for (int d = 0; d < D; d++) {
            if (!carried) {
                v[d] = nv[d];
                x[d] += dt * nv[d];
            }
            /* a particle that left the domain is put back on its edge and counted, never dropped */
            if (x[d] < lo[d]) { x[d] = lo[d]; out = 1; }
            else if (x[d] > hi[d]) { x[d] = hi[d]; out = 1; }
        }
        ood += out;
        /* Grid nodes past the middle of a thin wall see the far face's normal and
         * let material through; a particle that ends inside a collider is put
         * back on its surface (the usual particle-level safeguard). */
        for (int c = 0; c < s->ncol && !carried; c++)
            if (collider_near(&s->cols[c], x)) collider_project_particle(&s->cols[c], D, x, v);
        /* The sort's clamp and key, here where x is in registers: a collider
         * may have pushed x off the grid, and NaN goes to the low edge, as in
         * clamp_to_grid (lo and hi are its bounds off a periodic axis, and a
         * periodic scene files no keys here). */
        if (keys) {
            int bk[3] = {0, 0, 0}, off = 0;
            for (int d = 0; d < D; d++) {
                if (!(x[d] >= lo[d])) x[d] = lo[d], off = 1;
                else if (x[d] > hi[d]) x[d] = hi[d], off = 1;
                bk[d] = (int)((unsigned)base_node((x[d] - g->lo[d]) * inv_dx) / GRID_B);
            }
            clamped += off;
            keys[i] = grid_block_id(g, bk[0], bk[1], bk[2]);
        }
        {
            double m2 = 0;
            for (int d = 0; d < D; d++) {
                const double dd = carried ? x[d] - xo[d] : dt * nv[d];
                m2 += dd * dd;
            }
            if (m2 > move2) { move2 = m2; mover = i; }
        }
        if (!all_finite(x, 3)) record_fail(pp, i, FAIL_X, 0);
        else if (!all_finite(v, 3)) record_fail(pp, i, FAIL_V, 0);
        else if (!all_finite(C, D == 2 ? 4 : 9)) record_fail(pp, i, FAIL_C, 0);
        const double sp2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        ke += 0.5 * M[i] * sp2;
        mass += M[i];
        if (sp2 > vmax) { vmax = sp2; fastest = i; }
    }
    pp->ke = ke;
    pp->mass = mass;
    pp->vmax = vmax;
    pp->fastest = fastest;
    pp->move = sqrt(move2);
    pp->mover = mover;
    pp->ood = ood;
    pp->clamped = clamped;
    pp->water_removed = w_removed;
    pp->water_dmax = w_dmax;
    pp->water_emax = w_emax;
}

/* G2P's, indexed [dim == 3][heat][water], heat 0 (none), 1 (FLIP) or 2 (with the PIC part: g2p_heat) */
BLOCK_FN(g2p, 2, 0, 0) BLOCK_FN(g2p, 2, 0, 1) BLOCK_FN(g2p, 2, 1, 0) BLOCK_FN(g2p, 2, 1, 1) BLOCK_FN(g2p, 2, 2, 0) BLOCK_FN(g2p, 2, 2, 1)
BLOCK_FN(g2p, 3, 0, 0) BLOCK_FN(g2p, 3, 0, 1) BLOCK_FN(g2p, 3, 1, 0) BLOCK_FN(g2p, 3, 1, 1) BLOCK_FN(g2p, 3, 2, 0) BLOCK_FN(g2p, 3, 2, 1)
static const block_fn g2p_fns[2][3][2] = {{{g2p_200, g2p_201}, {g2p_210, g2p_211}, {g2p_220, g2p_221}},
                                          {{g2p_300, g2p_301}, {g2p_310, g2p_311}, {g2p_320, g2p_321}}};

/* two_field's, 2D, indexed [heat][water] as above */
#define G2P_TWO_FN(H, W) \
    static void g2p_two_##H##W(hearth_scene *s, int k, double dt, double *tile) { g2p_block(s, 2, H, W, 1, k, dt, tile); }
G2P_TWO_FN(0, 0) G2P_TWO_FN(0, 1) G2P_TWO_FN(1, 0) G2P_TWO_FN(1, 1) G2P_TWO_FN(2, 0) G2P_TWO_FN(2, 1)
static const block_fn g2p_two_fns[3][2] = {{g2p_two_00, g2p_two_01}, {g2p_two_10, g2p_two_11}, {g2p_two_20, g2p_two_21}};

/* G2P's heat instantiation: 0 without heat; 1 for pure FLIP, whose update
 * needs only the nodes' temperature change; 2 where it also reads their
 * temperature (a FLIP-PIC blend, heat_flip < 1, or held temperatures), which
 * is one more channel gathered per node (0.15M of the 2D dough's 18.4M
 * instructions a step, callgrind). */
static int g2p_heat(const hearth_scene *s) {
    if (!heat_now(s)) return 0;
    return s->def.heat_flip != 1.0 || s->heat.nfix > 0 ? 2 : 1;
}

static block_fn g2p_fn(const hearth_scene *s) {
    if (s->def.two_field) return g2p_two_fns[g2p_heat(s)][water_now(s)];
    return g2p_fns[s->g.dim == 3][g2p_heat(s)][water_now(s)];
}

/* G2P's blocks for the team of the enclosing region (one thread outside one);
 * no barrier at the end. Guided, not dynamic chunks of 2: neighbouring
 * particle blocks share a cache line of each column they write at their
 * border (x, v, C, the keys, F in P2G) and their partials' lines, so blocks
 * handed out two at a time to alternating threads had both cores write the
 * same lines at about every other border in every pass, a cost that grows
 * with the number of blocks (2D's blocks hold 64 particles where 3D's hold
 * 512: 8 times the borders a particle). Guided hands each thread long runs
 * of neighbouring blocks (half of what is left, then less), so a pass has
 * about 2 log2(blocks) borders between threads instead of blocks / 2, and it
 * still ends in single blocks where a late thread catches up. */
static void g2p_team(hearth_scene *s, block_fn fn, double dt) {
    const mpm_state *m = s->mpm;
    double tile[6 * GRID_T * GRID_T * GRID_T];
    if (m->claims) { /* 3D at more than one thread: from both ends, the same thread on the same end as P2G (claim_take) */
        const int back = claim_end();
        for (int k; (k = claim_take(&m->claims->g2p, back)) >= 0;) fn(s, k, dt, tile);
        return;
    }
#pragma omp for schedule(guided) nowait
    for (int k = m->k_lo; k < m->k_hi; k++) fn(s, k, dt, tile); /* this rank's blocks (all on one rank) */
}

/* The blocks' partials into the step report, in block order, so sums and the first failure do not depend on threads. */
static void g2p_reduce(hearth_scene *s, step_report *rep) {
    mpm_state *m = s->mpm;
    mpm_ranks_gather(s);
    *rep = (step_report){.particle = -1, .fastest = -1, .mover = -1};
    double vmax = -1, mass = 0;
    for (int k = 0; k < m->npb; k++) {
        const pb_partial *pp = &m->partial[k];
        if (pp->fail_i >= 0 && (rep->particle < 0 || pp->fail_i < rep->particle)) {
            rep->particle = pp->fail_i;
            rep->kind = (fail_kind)pp->fail_kind;
            rep->code = pp->fail_code;
        }
        rep->kinetic += pp->ke;
        mass += pp->mass;
        if (pp->vmax > vmax) {
            vmax = pp->vmax;
            rep->fastest = pp->fastest;
        }
        if (pp->move > rep->max_move) {
            rep->max_move = pp->move;
            rep->mover = pp->mover;
        }
        if (pp->cmax > rep->c_max) rep->c_max = pp->cmax;
        if (pp->numax > rep->nu_max) rep->nu_max = pp->numax;
        rep->out_of_domain += pp->ood + pp->clamped;
    }
    /* the keys stand for the positions the step leaves, if it stands (s->step is then one more) */
    const int wrap = s->def.periodic[0] || s->def.periodic[1] || s->def.periodic[2];
    m->keys_n = wrap ? -1 : s->ps.n;
    m->keys_step = s->step + 1;
    m->keys_edits = s->ps.edits;
    rep->max_speed = vmax > 0 ? sqrt(vmax) : 0.0;
    rep->mass = mass;
}

void mpm_g2p(hearth_scene *s, double dt, step_report *rep) {
    const block_fn fn = g2p_fn(s);
    mpm_claims cl;
    claims_begin(s, &cl);
#pragma omp parallel if (s->ps.n >= SCENE_PARALLEL_MIN)
    g2p_team(s, fn, dt);
    claims_end(s->mpm);
    g2p_reduce(s, rep);
}

/* G2P's blocks in the one-region step, chunk by chunk, each first to its P2G's thread (span_next); no barrier */
static void g2p_chunks(hearth_scene *s, mpm_sort_team *t, block_fn fn, double dt) {
    double tile[6 * GRID_T * GRID_T * GRID_T];
    span_walk w = span_walk_start(t->T);
    int lo, hi;
    while (span_next(t->span[MPM_SPAN_G2P], &w, NULL, &lo, &hi))
        for (int k = lo; k < hi; k++) fn(s, k, dt, tile);
    span_count(s->mpm, MPM_SPAN_G2P, &w);
}

/* step_team's phases after P2G, for every thread of its region; t: the one-region step's (NULL otherwise) */
static void step_team_rest(hearth_scene *s, double dt, const int gather, block_fn g2p, double *vcol2, mpm_sort_team *t) {
    mpm_state *m = s->mpm;
    grid_update_team(s, dt, vcol2, gather, t);
    if (t) g2p_chunks(s, t, g2p, dt);
    else g2p_team(s, g2p, dt);
    if (gather) { /* the block table back to no particle block anywhere, for the next step's scatter */
#pragma omp for schedule(static) nowait
        for (int k = m->k_lo; k < m->k_hi; k++) m->pbof[m->pb[k].block] = -1;
    }
}

/* P2G, the grid update and G2P in one parallel region, for a step with
 * nothing between them that needs one thread or opens regions of its own (no
 * heat or water, no periodic axis, one rank, a thread-safe body force). With
 * OMP_WAIT_POLICY=passive (main.c) each synchronisation wakes a sleeping
 * thread (a futex round trip). One region instead of three keeps two of
 * those a step. With more than one thread (gather), P2G scatters every
 * particle block into its own stored tile in one loop, and the grid update
 * gathers each block's node sums from those tiles in colour order
 * (mpm_p2g_gather) before updating it: one barrier between them where the
 * colour phases took 2^dim and the grid update's loop one more (2D 11 -> 8
 * synchronisations a step; threads_sync.sh). The same sums in the same
 * order: the same bits. 3D at more than one thread keeps P2G's flush and
 * orders it per block instead (claims_begin): with the sort's region, 14 -> 8
 * synchronisations a step at the 32-cell bench. Returns the fastest collider
 * speed (mpm_grid_update's). */
static double step_team(hearth_scene *s, double dt, step_report *rep, const int gather) {
    mpm_claims cl;
    if (!gather) claims_begin(s, &cl); /* 3D at more than one thread (the gather is 2D's) */
    const block_fn p2g = p2g_prepare(s), g2p = g2p_fn(s);
    mpm_state *m = s->mpm;
    const block_fn store = p2g_store_fns[thermal_active(s)][m->sticky_faces][s->g.dim == 3];
    double vcol2 = 0;
#pragma omp parallel if (s->ps.n >= SCENE_PARALLEL_MIN)
    {
        if (gather) {
            /* every block's tile, in any order: each keeps its own; the loop's barrier before the gather.
             * Guided: long runs of neighbouring blocks per thread (g2p_team says why) */
            double tile[GRID_NCH_MOMENTUM * GRID_T * GRID_T * GRID_T];
#pragma omp for schedule(guided)
            for (int k = m->k_lo; k < m->k_hi; k++) store(s, k, dt, tile);
        } else {
            p2g_team(s, p2g, dt);
        }
        step_team_rest(s, dt, gather, g2p, &vcol2, NULL);
    }
    claims_end(m);
    g2p_reduce(s, rep);
    return sqrt(vcol2);
}

/* The gather's scatter in the one-region step: each chunk of the sort's
 * particle blocks as soon as the sort has published it (t->ready; all of
 * them when all_ready), with no barrier between the sort and P2G. Each
 * thread starts with its own chunks (the ones it sorted, unless it came
 * late) and then helps with the others that are ready, from their backs
 * (span_next: the grid update and G2P share out the same way, so a block
 * stays on its thread); a chunk whose owner is still sorting is left to it.
 * Every block once, whichever thread takes it: the same bits. Ends with the
 * barrier before the gather. */
static void p2g_store_chunks(hearth_scene *s, mpm_sort_team *t, const int all_ready, block_fn store, double dt) {
    mpm_state *m = s->mpm;
    double tile[GRID_NCH_MOMENTUM * GRID_T * GRID_T * GRID_T];
    span_walk w = span_walk_start(t->T);
    int lo, hi;
    while (span_next(t->span[MPM_SPAN_P2G], &w, all_ready ? NULL : t->ready, &lo, &hi))
        for (int k = lo; k < hi; k++) {
            m->partial[k] = (pb_partial){.fail_i = -1, .fastest = -1};
            store(s, k, dt, tile);
        }
    span_count(m, MPM_SPAN_P2G, &w);
#pragma omp barrier
}

/* The gather's step (2D, more than one thread, one rank, nothing between
 * the phases) with the sort's count and lists at the start of its one
 * region (mpm_sort_begin): the sort's region ended and the step's began at
 * two synchronisations, and with the keys in order P2G starts on each chunk
 * of particle blocks as the sort publishes it (p2g_store_chunks), so the
 * step has the count's barrier, P2G's and the grid update's; out of order
 * the permutation (its region gone too) ends past a barrier. The grid's
 * activation, the particle blocks' range, their partials and the tile store
 * are done in the region (the store lives in the sort's scratch; it grows,
 * in a single, only when the scratch is short). Bits: mpm_sort's and
 * step_team's. */
static hearth_status step_team_sorted(hearth_scene *s, double dt, step_report *rep, mpm_sort_team *t, double *vcol,
                                      hearth_error *err) {
    mpm_state *m = s->mpm;
    particles *ps = &s->ps;
    m->sticky_faces = 0;
    for (int c = 0; c < s->ncol; c++) m->sticky_faces |= s->cols[c].mode == HEARTH_STICKY;
    const block_fn g2p = g2p_fn(s), store = p2g_store_fns[thermal_active(s)][m->sticky_faces][s->g.dim == 3];
    /* the tile store in the sort's scratch (mpm_p2g_gather.c), dead once the count (keys in order) or the
     * permutation (out of order) is done, before any tile is kept */
    const size_t room = sizeof(int) * (size_t)m->scratch_cap, have = m->scratch_bytes / sizeof(double);
    m->tiles = (double *)(void *)m->keys;
    m->tiles_cap = 0;
    hearth_status gst = HEARTH_OK;
    double vcol2 = 0;
#pragma omp parallel
    {
        int kof[MPM_SORT_CHUNKS_MAX + 1];
        const int W = mpm_sort_team_run(s, t, kof);
        if (!t->st) {
            if (W >= 0) { /* this thread moves the places of its own chunks' particle blocks (span_walk); past a barrier */
                const span_walk w = span_walk_start(t->T);
                const int lo = kof[w.c0] < kof[t->T] ? m->pb[kof[w.c0]].start : ps->n,
                          hi = kof[w.c1] < kof[t->T] ? m->pb[kof[w.c1]].start : ps->n;
                particles_permute_team_range(ps, m->order, W, m->keys, room, lo, hi);
            }
            const int grow = mpm_p2g_store_need(s, kof[t->T]) > have;
            if (grow) { /* every thread is past the sort's reads of keys and order */
#pragma omp single
                gst = mpm_p2g_store_room(s, kof[t->T], err);
            }
            if (!gst) {
                p2g_store_chunks(s, t, W >= 0 || grow, store, dt);
                step_team_rest(s, dt, 1, g2p, &vcol2, t);
            }
        }
    }
    if (t->st) return t->st;
    if (gst) return gst;
    m->tiles_cap = mpm_p2g_store_need(s, m->npb); /* what hearth_scene_bytes_used counts */
    m->span_blocks[MPM_SPAN_P2G] += m->npb, m->span_blocks[MPM_SPAN_G2P] += m->npb;
    m->span_blocks[MPM_SPAN_GRID] += s->g.nactive;
    g2p_reduce(s, rep);
    *vcol = sqrt(vcol2);
    return HEARTH_OK;
}

hearth_status mpm_step(hearth_scene *s, double dt, step_report *rep, hearth_error *err) {
    HEARTH_ASSERT(s->ps.t2 == (s->g.dim == 2)); /* P2G and G2P read 2D's C and F as 2x2 blocks (scene.c sets it) */
    int heat = heat_now(s), water = water_now(s);
    const int wrap = s->def.periodic[0] || s->def.periodic[1] || s->def.periodic[2];
    int usual = !heat && !water && !wrap && s->mpm->nranks == 1 && !s->body_force_serial && !s->def.two_field;
    hearth_status st;
    int sorted = 0;
    if (usual && !mixing_active(s) && s->ps.n >= SCENE_PARALLEL_MIN && mpm_p2g_store_held(s)) { /* the gather's step */
        mpm_sort_team t;
        if ((st = mpm_sort_begin(s, &t, err))) return st;
        if (t.T > 1) { /* the sort's count and lists in the step's region */
            mpm_span spans[MPM_SPANS][MPM_SORT_CHUNKS_MAX]; /* the sort sets chunk c's before it publishes it */
            t.span = spans;
            double vcol;
            if ((st = step_team_sorted(s, dt, rep, &t, &vcol, err))) return st;
            rep->driven_kinetic = 0.5 * rep->mass * vcol * vcol;
            return mpm_ranks_report(s, dt, vcol, rep, err);
        }
        sorted = 1; /* mpm_sort_begin sorted as mpm_sort does */
    }
    if (!sorted && (st = mpm_sort(s, err))) return st;
    if (mixing_active(s) && (st = mixing_update(s, err))) return st;
    heat = heat_now(s), water = water_now(s); /* as the mixing left them */
    usual = !heat && !water && !wrap && s->mpm->nranks == 1 && !s->body_force_serial && !s->def.two_field;
    if (wrap && (thermal_active(s) || water_active(s)))
        return err_set(err, HEARTH_ERR_PARAM, "scene: periodic axes (periodic_%c) do not carry %s yet; use a closed box",
                       "xyz"[s->def.periodic[0] ? 0 : s->def.periodic[1] ? 1 : 2], thermal_active(s) ? "heat" : "water");
    if (s->def.two_field) { /* 2D, one rank, no periodic axis (scene.c's check) */
        for (int c = 0; c < s->ncol; c++)
            if (s->cols[c].mode == HEARTH_STICKY)
                return err_set(err, HEARTH_ERR_PARAM, "scene: two_field does not carry sticky colliders (collider %d); "
                                                      "use mode = \"slip\" or \"separate\", or set two_field = false", c);
        if ((st = mpm_two_field_prepare(s, err))) return st;
    }
    if (usual) { /* the usual step: one region */
        int gather;
        if ((st = mpm_p2g_store_reserve(s, &gather, err))) return st;
        const double vcol = step_team(s, dt, rep, gather);
        rep->driven_kinetic = 0.5 * rep->mass * vcol * vcol;
        return mpm_ranks_report(s, dt, vcol, rep, err);
    }
    mpm_p2g(s, dt, rep);
    if ((st = mpm_ranks_sum_grid(s, err))) return st;
    if (wrap) mpm_periodic_fold(s, 0);
    if (heat || water) {
        const double fdt = field_dt(s, dt); /* the fields' time: their cycle's steps together (field_clock.c) */
        if ((st = boundary_find(s, err))) return st;
        if (heat && (st = thermal_prepare(s, err))) return st;
        if (water) water_prepare(s);
        /* L theta^n and the heat sources, the water flux and evaporation: one pass */
        /* forward Euler needs only L theta^n - b, so the sources go into CH_R too (CH_B stays 0) */
        const transport_pass tp = {.heat_in = heat ? CH_T : -1, .heat_out = CH_R, .heat_src = s->def.heat_implicit ? CH_B : CH_R,
                                   .water = water, .dt = fdt};
        transport_apply(s, &tp);
        if (water) water_face_flux(s, fdt);
        if (heat) thermal_contact(s);
        /* MPI slabs: the scatters' halo shares to their owners and back (mpm_ranks_fields.c) */
        const int sums[3] = {CH_R, CH_B, CH_DMW};
        if ((st = mpm_ranks_fields_sum(s, heat ? sums : sums + 2, (heat ? 2 : 0) + (water ? 1 : 0), err))) return st;
        if (heat && (st = thermal_finish(s, fdt, err))) return st;
        mpm_ranks_fields_clear(s);
    }
    if (s->def.two_field) mpm_two_field_split(s);
    const double vcol = mpm_grid_update(s, dt);
    if (s->def.two_field) mpm_two_field_contact(s);
    if ((st = mpm_ranks_halo_back(s, err))) return st;
    if (wrap) mpm_periodic_fold(s, 1);
    mpm_g2p(s, dt, rep);
    if (wrap) mpm_periodic_wrap_all(s);
    if (water) water_finish(s);
    rep->driven_kinetic = 0.5 * rep->mass * vcol * vcol;
    return mpm_ranks_report(s, dt, vcol, rep, err);
}

double mpm_stable_dt(const hearth_scene *s) {
    /* the tightest of: motion and waves (CFL), the user's maximum, explicit conduction */
    const double sp = s->max_speed + s->c_max;
    double dt = sp > 0 ? s->def.cfl * s->def.dx / sp : INFINITY;
    if (s->def.dt_max > 0 && dt > s->def.dt_max) dt = s->def.dt_max;
    const double heat = thermal_dt_limit(s), water = water_dt_limit(s);
    if (dt > heat) dt = heat;
    if (dt > water) dt = water;
    /* explicit viscosity is diffusion of momentum: the same limit as explicit heat */
    if (s->nu_max > 0 && dt > s->def.dx * s->def.dx / (2.0 * s->def.dim * s->nu_max))
        dt = s->def.dx * s->def.dx / (2.0 * s->def.dim * s->nu_max);
    if (isinf(dt)) dt = s->def.cfl * s->def.dx; /* nothing moves or conducts: as if at 1 m/s */
    return dt * s->dt_scale;
}

/* Particles stay a node inside the grid, so a particle's B-spline base node
 * lies in [0, nn - 3] where its block's tile holds its stencil (block_of_position). */
static void mpm_region(const hearth_scene *s, double lo[3], double hi[3]) {
    for (int d = 0; d < 3; d++) {
        lo[d] = d < s->def.dim ? s->g.lo[d] + s->g.dx : 0;
        hi[d] = d < s->def.dim ? s->g.lo[d] + (s->g.nn[d] - 2) * s->g.dx : 0; /* periodic: the box's own [lo, hi) */
    }
}

/* order; the keys (the permutation's scratch) and P2G's volumes, counted
 * whether or not heat or water is on yet (either may turn on after the
 * particles are seeded); and the gather's tile store where it will be held
 * (mpm_p2g_gather.c), which shares order and keys' room. */
static double mpm_bytes_per_particle(const hearth_scene *s) {
    const double keys = 2 * sizeof(int), tiles = mpm_p2g_store_bytes_per_particle(s); /* the tiles in the keys' room */
    return (keys > tiles ? keys : tiles) + sizeof(double);
}

/* The grid is the scene's; the step scratch is MPM's own (mpm_state); its
 * options are the scene's, checked there. */
const solver mpm_solver = {
    .name = "mpm",
    .init = mpm_init,
    .free = mpm_free,
    .stable_dt = mpm_stable_dt,
    .step = mpm_step,
    .region = mpm_region,
    .bytes_per_particle = mpm_bytes_per_particle,
    /* temperature from the heat field, porosity from plastic_J (P2G), saturation from the water field */
    .supplies = HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_POROSITY | HEARTH_NEEDS_SATURATION,
    .can_checkpoint = 1,
    .uses_grid = 1,
};
