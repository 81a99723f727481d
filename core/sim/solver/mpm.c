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
 * count. No atomics. At any thread count, the usual 2D step
 * (step_team) keeps every block's tile instead and the grid update gathers
 * each node's sum from the tiles in the same colour order (mpm_p2g_gather.c):
 * the same bits, with one barrier where the colour phases take 2^dim. 3D at
 * more than one thread flushes each block after its neighbours of lower
 * colour instead of a barrier per colour (p2g_wait_lower), and every phase
 * hands out blocks from both ends (claim_take): the same bits.
 *
 * Files: this one orders the step (sort, P2G, the grid update, G2P, in one
 * parallel region where it can) and holds P2G and the grid update;
 * mpm_g2p.c holds G2P and the step report's reduction; mpm_share.c how a
 * phase's blocks go to threads (claims, spans); mpm_block.h what they share.
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
#include <limits.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "plugins.h"
#include "mpm.h"
#include "mpm_sticky.h"
#include "mpm_touch.h"
#include "solver.h"
#include "gas.h"
#include "material.h"
#include "thermal.h"
#include "water.h"
#include "boundary.h"
#include "mixing.h"
#include "transport.h"
#include "subcell.h"
#include "flip_bound.h"
#include "tensor2.h"
#include "phase_clock.h"
#include "mpm_block.h"

#ifdef _OPENMP
#include <omp.h>
#endif

/* ---- state ----------------------------------------------------------- */

static void mpm_free(hearth_scene *s) {
    mpm_state *m = s->mpm;
    if (!m) return;
    mpm_scratch_free(m);
    mpm_self_free(m);
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
    hearth_status st = team_wait_init(&m->team, err);
    if (st) return st;
    return mpm_ranks_init(m, err);
}

/* ---- P2G ------------------------------------------------------------- */

/* p[0..1] += x (unaligned: a stencil may start at any node of the tile) */
FORCE_INLINE void p2g_add2(double *p, v2d x) {
    v2d y;
    memcpy(&y, p, sizeof y);
    y += x;
    memcpy(p, &y, sizeof y);
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
/* two_field (2D only): the nodes' reference damage gradients and body tags, then the second field's mass and
 * momentum, past the channels above in the same tile (2D uses 36 nodes of its 216) */
enum { P2G_GX = P2G_NCH, P2G_GY, P2G_GB, P2G_BM, P2G_BX, P2G_BY, P2G_NCH_TWO };
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
                for (int c = 0; c < 3; c++) tile[(P2G_GX + c) * TN + a * GRID_T + b] = node[(CH_TF_GX + c) * NPB + l];
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

        int base[3];
        double fx[3], w[3][3];
        tile_stencil(g, D, x, org, inv_dx, base, fx, w);
        /* the stencil's 3 nodes must lie in the 6-node tile: mpm_sort's clamp_to_grid */
        for (int d = 0; d < D; d++) HEARTH_ASSERT(base[d] >= 0 && base[d] <= GRID_T - 3);
        const double mv0 = m * v[0], mv1 = m * v[1], mv2 = m * v[2];
        /* heat (eq. 17, weighted by heat capacity m alpha so energy is conserved across materials; alpha the
         * particle's, at the water it holds: material_specific_heat) */
        const double hc = HS ? m * material_specific_heat(&s->mats.slot[mat[i]], ps, i) : 0.0, hct = HS ? hc * Tcol[i] : 0.0;
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
                    if (TWO && mpm_two_field_second(tp[P2G_GX * TN + t], tp[P2G_GY * TN + t], tp[P2G_GB * TN + t], dgrad + 3 * i)) {
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
        team_wait_barrier(&m->team);
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
    /* a slip or separate face holds a node only where the body touches it (mpm_touch.c): the block's masks,
     * each made when a node first asks */
    mpm_touch_cache touch = {.done = 0, .field = s->def.two_field ? (ch0 == CH_TF_M ? 2 : 1) : 0};
    int near[COLLIDER_NEAR_CAP]; /* the colliders near this block's nodes (mpm_block.h) */
    double blo[3], bhi[3];
    const int nnear = mpm_block_colliders(s, bc, 0, blo, bhi, near), nwalk = nnear < 0 ? s->ncol : nnear;
    for (int l = 0; l < NPB; l++) {
        const double m = node[l];
        if (m <= 0.0) {
            node[NPB + l] = node[2 * NPB + l] = node[3 * NPB + l] = 0.0;
            continue;
        }
        int idx[3], held = 0; /* held: a face acted on the node (two_field's contact reads it: mpm_two_field.c) */
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
        /* domain walls act on the two node layers nearest each face; a slip or separate wall only where
         * the body touches it (mpm_touch.c) */
        for (int d = 0; d < D; d++) {
            const double zero[3] = {0, 0, 0};
            double n[3] = {0, 0, 0};
            if (idx[d] < wlo[d]) n[d] = 1.0;
            else if (idx[d] > whi[d]) n[d] = -1.0;
            else continue;
            if (((mpm_touch_gated(def->wall) && (def->wall == HEARTH_SLIP || v[d] * n[d] < 0)) || mpm_touch_glued(def->wall)) &&
                !mpm_touch_holds(s, &touch, g->active[k], bc, s->ncol + 2 * d + (n[d] < 0), l, dt))
                continue;
            contact_apply(def->wall, def->wall_friction, n, zero, v), held = 1;
        }
        for (int q = 0; q < nwalk; q++) {
            const int c = nnear < 0 ? q : near[q];
            double n[3];
            /* Every collider, a grip too, holds the nodes inside it and on its
             * face (COLLIDER_ROW_TOL), none outside: a grip clamps at its face.
             * (Holding a grip's nodes a cell outside kept a pulled strip from
             * peeling off, at the cost of a clamp one cell in; G2P's carry now
             * keeps the stress continuous instead.) A sticky face also holds
             * those within STICKY_NEAR_BAND cells outside it, which
             * mpm_sticky_ghosts_block then gives the velocity linear from the
             * face (colliders.h). */
            const double band = collider_hold_band(&s->cols[c]) * g->dx;
            if (!collider_near(&s->cols[c], xi)) continue;
            const double phi = collider_sdf(&s->cols[c], xi, n);
            if (phi > band) continue;
            double vb[3];
            collider_velocity_at(&s->cols[c], xi, vb);
            if (D == 2) n[2] = vb[2] = 0.0;
            /* only where the body touches the face, or (sticky) has touched it (mpm_touch.c); a separate face
             * leaves a node that does not approach it alone anyway, so it asks only for one that does */
            const double vn = (v[0] - vb[0]) * n[0] + (v[1] - vb[1]) * n[1] + (v[2] - vb[2]) * n[2];
            if (((mpm_touch_gated(s->cols[c].mode) && (s->cols[c].mode != HEARTH_SEPARATE || vn < 0)) ||
                 mpm_touch_glued(s->cols[c].mode)) &&
                !mpm_touch_holds(s, &touch, g->active[k], bc, c, l, dt)) {
                vcol2 = fmax(vcol2, vb[0] * vb[0] + vb[1] * vb[1] + vb[2] * vb[2]);
                continue;
            }
            /* a held node within reach of a sticky face's reflection: a negative mass marks it for
             * mpm_sticky_ghosts_block, which finds it without an SDF per node and restores the sign */
            if (s->cols[c].mode == HEARTH_STICKY && phi > -1.5 * g->dx) node[l] = -m;
            contact_apply(s->cols[c].mode, s->cols[c].friction, n, vb, v), held = 1;
            vcol2 = fmax(vcol2, vb[0] * vb[0] + vb[1] * vb[1] + vb[2] * vb[2]);
        }
        node[NPB + l] = v[0];
        node[2 * NPB + l] = v[1];
        node[3 * NPB + l] = D == 3 ? v[2] : held * (double)def->two_field; /* 2D two_field: the held mark */
    }
    return vcol2;
}

/* The sticky colliders' ghost nodes, after the grid update's wait. */
static void grid_sticky_team(hearth_scene *s) {
    const grid *g = &s->g;
#pragma omp for schedule(dynamic, 4)
    for (int k = 0; k < g->nactive; k++) mpm_sticky_ghosts_block(s, k);
    const int NPB = g->nodes_per_block; /* the marks off again, once every ghost has been read */
#pragma omp for schedule(static)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) node[l] = fabs(node[l]);
    }
}

/* The grid update for the team of the enclosing region (one thread outside
 * one); ends with a barrier, so G2P may read any node. The fastest collider
 * speed squared goes into *vcol2 (shared), the largest of the threads' own:
 * a maximum, the same whatever the threads. */
static void grid_update_team(hearth_scene *s, double dt, double *vcol2, const int gather, mpm_sort_team *t, const int nactive) {
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
        unsigned done = 0;
        while (span_next(t->span[MPM_SPAN_GRID], &w, NULL, &lo, &hi)) {
            for (int k = lo; k < hi; k++) {
                mpm_p2g_gather(s, k);
                v2 = fmax(v2, s->def.damping > 0 ? grid_update_block(s, k, dt, damp, 1, CH_M) : grid_update_block(s, k, dt, 1.0, 0, CH_M));
            }
            done += (unsigned)(hi - lo);
        }
        span_count(s->mpm, MPM_SPAN_GRID, &w);
        /* G2P may read any node once every block is updated, whoever updated it: a thread still on its way
         * from the sort finds no block left and need not be waited for (a maximum of the threads' own, as
         * below; a thread with no block adds 0) */
        if (v2 > 0) {
#pragma omp critical(mpm_vcol2)
            if (v2 > *vcol2) *vcol2 = v2;
        }
        team_count_add(&t->updated, done);
        team_count_wait(&s->mpm->team, &t->updated, (unsigned)nactive); /* this thread's count: the sort's single sets g's */
        if (s->mpm->sticky_faces) { /* every thread past the sort's single (g->nactive) */
            team_wait_barrier(&s->mpm->team);
            grid_sticky_team(s);
        }
        return;
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
    team_wait_barrier(&s->mpm->team);
    if (s->mpm->sticky_faces) grid_sticky_team(s);
}

double mpm_grid_update(hearth_scene *s, double dt) {
    double vcol2 = 0; /* the fastest collider at a node with mass (the guard's driven energy) */
    /* a body force that is not thread-safe (a Lua function) keeps the update on one thread */
    const int par = s->ps.n >= SCENE_PARALLEL_MIN && !s->body_force_serial;
    mpm_claims cl;
    if (par) claims_begin(s, &cl);
#pragma omp parallel if (par)
    grid_update_team(s, dt, &vcol2, 0, NULL, 0);
    claims_end(s->mpm);
    return sqrt(vcol2);
}

/* step_team's phases after P2G, for every thread of its region; t: the one-region step's (NULL otherwise),
 * with this thread's count of active blocks (the sort's; g->nactive is set in a single without a barrier) */
static void step_team_rest(hearth_scene *s, double dt, const int gather, block_fn g2p, double *vcol2, mpm_sort_team *t,
                           const int nactive) {
    mpm_state *m = s->mpm;
    grid_update_team(s, dt, vcol2, gather, t, nactive);
    PHASE_MARK(PH_GRID);
    if (t) {
        g2p_chunks(s, t, g2p, dt); /* resets each block's pbof: k_lo and k_hi come from a single without a barrier */
        PHASE_MARK(PH_G2P);
        return;
    }
    g2p_team(s, g2p, dt);
    PHASE_MARK(PH_G2P);
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
 * those a step (a region's start and end still sleep; the waits inside it
 * spin first, team_wait.c). In 2D (gather, one thread too), P2G scatters every
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
    PHASE_FORK();
#pragma omp parallel if (s->ps.n >= SCENE_PARALLEL_MIN)
    {
        PHASE_MARK(PH_FORK);
        if (gather) {
            /* every block's tile, in any order: each keeps its own; the loop's barrier before the gather.
             * Guided: long runs of neighbouring blocks per thread (g2p_team says why) */
            double tile[GRID_NCH_MOMENTUM * GRID_T * GRID_T * GRID_T];
#pragma omp for schedule(guided) nowait
            for (int k = m->k_lo; k < m->k_hi; k++) store(s, k, dt, tile);
            team_wait_barrier(&m->team);
        } else {
            p2g_team(s, p2g, dt);
        }
        PHASE_MARK(PH_P2G);
        step_team_rest(s, dt, gather, g2p, &vcol2, NULL, 0);
    }
    PHASE_MARK(PH_JOIN);
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
static void p2g_store_chunks(hearth_scene *s, mpm_sort_team *t, const int all_ready, block_fn store, double dt, const int npb) {
    mpm_state *m = s->mpm;
    double tile[GRID_NCH_MOMENTUM * GRID_T * GRID_T * GRID_T];
    span_walk w = span_walk_start(t->T);
    int lo, hi;
    unsigned done = 0;
    while (span_next(t->span[MPM_SPAN_P2G], &w, all_ready ? NULL : t->ready, &lo, &hi)) {
        for (int k = lo; k < hi; k++) {
            m->partial[k] = (pb_partial){.fail_i = -1, .fastest = -1};
            store(s, k, dt, tile);
        }
        done += (unsigned)(hi - lo);
    }
    span_count(m, MPM_SPAN_P2G, &w);
    /* the gather once every tile is kept, whoever kept it (the grid update's wait says why) */
    team_count_add(&t->stored, done);
    team_count_wait(&m->team, &t->stored, (unsigned)npb); /* this thread's count: the sort's single sets m->npb */
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
    PHASE_FORK();
#pragma omp parallel
    {
        PHASE_MARK(PH_FORK);
        int kof[MPM_SORT_CHUNKS_MAX + 1], nactive = 0;
        const int W = mpm_sort_team_run(s, t, kof, &nactive);
        if (!t->st) {
            if (W >= 0) { /* this thread moves the places of its own chunks' particle blocks (span_walk); past a barrier */
                const span_walk w = span_walk_start(t->T);
                const int lo = kof[w.c0] < kof[t->T] ? m->pb[kof[w.c0]].start : ps->n,
                          hi = kof[w.c1] < kof[t->T] ? m->pb[kof[w.c1]].start : ps->n;
                particles_permute_team_range(ps, m->order, W, m->keys, room, lo, hi, &m->team);
                PHASE_MARK(PH_PERMUTE);
            }
            const int grow = mpm_p2g_store_need(s, kof[t->T]) > have;
            if (grow) { /* every thread is past the sort's reads of keys and order */
#pragma omp single
                gst = mpm_p2g_store_room(s, kof[t->T], err);
            }
            if (!gst) {
                p2g_store_chunks(s, t, W >= 0 || grow, store, dt, kof[t->T]);
                PHASE_MARK(PH_P2G);
                step_team_rest(s, dt, 1, g2p, &vcol2, t, nactive);
            }
        }
    }
    PHASE_MARK(PH_JOIN);
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
    int usual = !heat && !water && !wrap && s->mpm->nranks == 1 && !s->body_force_serial && !s->def.two_field && !mpm_self_asked(s);
    hearth_status st;
    int sorted = 0;
    s->mpm->step_dt = dt; /* the slabs' touch masks (mpm_ranks.c's halo_sum) */
    if ((st = mpm_glue_mark(s, dt, err))) return st; /* a sticky face's glue: before the sort (mpm_touch.c) */
    PHASE_STEP();
    if (usual && !mixing_active(s) && s->ps.n >= SCENE_PARALLEL_MIN && mpm_p2g_store_held(s)) { /* the gather's step */
        mpm_sort_team t;
        if ((st = mpm_sort_begin(s, &t, err))) return st;
        if (t.T > 1) { /* the sort's count and lists in the step's region */
            mpm_span spans[MPM_SPANS][MPM_SORT_CHUNKS_MAX]; /* the sort sets chunk c's before it publishes it */
            t.span = spans;
            double vcol;
            if ((st = step_team_sorted(s, dt, rep, &t, &vcol, err))) return st;
            rep->driven_kinetic = 0.5 * rep->mass * vcol * vcol;
            st = mpm_ranks_report(s, dt, vcol, rep, err);
            PHASE_MARK(PH_REDUCE);
            return st;
        }
        sorted = 1; /* mpm_sort_begin sorted as mpm_sort does */
    }
    if (!sorted && (st = mpm_sort(s, err))) return st;
    if (mixing_active(s) && (st = mixing_update(s, err))) return st;
    heat = heat_now(s), water = water_now(s); /* as the mixing left them */
    usual = !heat && !water && !wrap && s->mpm->nranks == 1 && !s->body_force_serial && !s->def.two_field && !mpm_self_asked(s);
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
        st = mpm_ranks_report(s, dt, vcol, rep, err);
        PHASE_MARK(PH_REDUCE);
        return st;
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
        if (heat) flip_bound_prepare(s, fdt); /* the heat's bounds, before subcell.c moves any particle */
        /* latent_heat: the dried particles' sub-cell exchange, from the step-start temperatures G2P adds to */
        if (heat && water && (st = subcell_exchange(s, fdt, err))) return st;
        /* FLIP's increment within the heat's bounds (flip_bound.c), from the temperatures G2P adds to */
        if (heat && (st = flip_bound_apply(s, err))) return st;
        mpm_ranks_fields_clear(s);
    }
    if (s->def.two_field) mpm_two_field_split(s);
    const double vcol = mpm_grid_update(s, dt);
    if (s->def.two_field) mpm_two_field_contact(s, dt);
    if ((st = mpm_ranks_halo_back(s, err))) return st;
    if (wrap) mpm_periodic_fold(s, 1);
    const int front = heat && water && s->def.latent_heat;
    if (front && (st = water_boil_front_prepare(s, err))) return st;
    if (mpm_self_asked(s) && (st = mpm_self_gather(s, err))) return st;
    mpm_g2p(s, dt, rep);
    /* before the wrap: the positions and nodes G2P left (water.c) */
    if (front && (st = water_boil_front(s, err))) return st;
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
    dt = fmin(dt, mpm_self_dt(s)); /* a lone particle's or small cluster's own mode (mpm_self.c) */
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
