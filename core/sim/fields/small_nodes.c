/* small_nodes.c: forward Euler heat with the air surface's small nodes merged
 * (moved out of thermal.c, which calls it; the reasons follow).
 *
 * A node just past the surface holds a sliver of heat capacity (the aligned
 * slab's first air node: 1/32 of a full node, from the outer particles' weight
 * tails), so its forward Euler increment (B - R) / c is some thirty times the
 * rate of its neighbours, and in the opposite sign to the surface's heating
 * (its row of the Galerkin Laplacian has the outer particles' full gradient
 * over that sliver). FLIP (eq. 21) hands w_ip times that increment to the
 * outer particles, and the particle pattern it leaves across the outer rows is
 * one the grid's mass-weighted average barely sees, so nothing damps it: it
 * grows with the heat taken in and does not shrink with dx (explicit slab,
 * particle a quarter cell in: +0.019 at 20 and at 30 cells across L, its
 * neighbours -0.040/-0.049 and +0.036/+0.045). This is the small cut-cell
 * problem; the remedy is the cut-cell one, merging: a node with less than
 * SMALL_NODE of the capacity of its fullest neighbour takes that neighbour's
 * increment, and the neighbour takes both sources over both capacities, so
 * heat is conserved to round-off (tied neighbours take equal shares of the
 * source and capacity, and the small node their mean increment). Rejected: a FLIP-PIC blend on the
 * area-holding particles (the grid's one-sided average at the surface
 * samples deeper material: PIC there pulls the outer rows cold, 0.014 at
 * blend 0.01; 0.19 and heat lost at full PIC), depositing the Robin heat on
 * the particles by area (the same pattern, 2.6 times larger), or at the
 * surface points (its sign flips, the size stays). Only with an oven (the
 * small nodes are found from boundary.c's volume fraction) and only for
 * forward Euler; the implicit solve has no 1/c amplification. */
#include "small_nodes.h"

#include <math.h>
#include <string.h>

#include "grid.h"
#include "scene.h"

#define SMALL_NODE 0.1

/* grid_node_at with the dimension D a compile-time constant: node gi's block
 * storage and local index, NULL past the grid or in a block without storage. */
static inline __attribute__((always_inline)) double *node_at(const grid *g, const int D, const int gi[3], int *l) {
    for (int d = 0; d < D; d++)
        if (gi[d] < 0 || gi[d] > g->nn[d] - 1) return NULL;
    const int slot = g->slot[grid_block_id(g, gi[0] / GRID_B, gi[1] / GRID_B, D == 3 ? gi[2] / GRID_B : 0)];
    if (slot < 0) return NULL;
    *l = D == 2 ? (gi[0] % GRID_B) * GRID_B + gi[1] % GRID_B : ((gi[0] % GRID_B) * GRID_B + gi[1] % GRID_B) * GRID_B + gi[2] % GRID_B;
    return grid_block(g, slot);
}

/* The nodes a small node gi (capacity c) merges into: its fullest neighbours
 * (below), when c < SMALL_NODE of them, leaving out any that is small itself
 * or held; their count (0: no merge), their storage in nj and local indices
 * in lj. The axis neighbours come first, the diagonals only when none of them
 * will do (six lookups, not 26, for most small nodes: the merge cost 6% of a
 * 3D oven step with all 26), and then only when fuller than the axis ones by
 * more than round-off. Every neighbour within round-off (TIE) of the fullest
 * is a target and the small node's share is split equally among them: along
 * an aligned face the three inner neighbours of an air node tie, and a tie
 * broken by round-off sent neighbouring air nodes different ways (a ripple of
 * 0.008 along the slab's face); a node on a mirror plane has tied left and
 * right neighbours, and a tie broken by loop order (the first, the left)
 * heated one side (mpm_oven_mirror_symmetric: 1e-4 and 3e-3 degC between
 * mirrored particles at dx 5 and 2.5 mm, the gap flipping with the loop).
 * The set does not depend on the loop's order, so a reflection maps it to
 * itself; it depends only on the grid, so it is the same at any thread or
 * rank count. */
#define TIE 1e-9
#define MERGE_MAX 26
static inline __attribute__((always_inline)) int merge_targets_d(const hearth_scene *s, const int D, const int gi[3], double c,
                                                                  double *nj[MERGE_MAX], int lj[MERGE_MAX]) {
    const grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    double *node[MERGE_MAX], cap[MERGE_MAX], cmax = 0;
    int l[MERGE_MAX], m = 0, lo = 0, hi = 0;
    for (int pass = 0; pass < 2 && !(hi > lo && c < SMALL_NODE * cmax); pass++) { /* diagonals only when no axis neighbour will do */
        const int from = m;
        double pmax = 0;
        for (int a = -1; a <= 1; a++)
            for (int b = -1; b <= 1; b++)
                for (int e = D == 3 ? -1 : 0; e <= (D == 3 ? 1 : 0); e++) {
                    const int nz = (a != 0) + (b != 0) + (e != 0);
                    if (!nz || (pass == 0) != (nz == 1)) continue;
                    const int gj[3] = {gi[0] + a, gi[1] + b, gi[2] + e};
                    double *n = node_at(g, D, gj, &l[m]);
                    if (!n) continue;
                    node[m] = n, cap[m] = n[CH_HC * NPB + l[m]];
                    if (cap[m] > pmax) pmax = cap[m];
                    m++;
                }
        if (pmax > cmax * (1.0 + TIE)) lo = from, hi = m, cmax = pmax; /* a later pass's only when fuller by more than round-off */
    }
    if (!(c < SMALL_NODE * cmax)) return 0;
    int n = 0;
    for (int j = lo; j < hi; j++) {
        if (!(cap[j] * (1.0 + TIE) >= cmax) || node[j][CH_CG_R * NPB + l[j]] < SMALL_NODE) continue;
        if (s->heat.nfix) {
            const int kj = (int)((node[j] - g->data) / ((ptrdiff_t)g->nch * NPB)) * NPB + l[j];
            if (!isnan(s->heat.fix[kj])) continue;
        }
        nj[n] = node[j], lj[n] = l[j], n++;
    }
    return n;
}

static int merge_targets(const hearth_scene *s, const int gi[3], double c, double *nj[MERGE_MAX], int lj[MERGE_MAX]) {
    return s->g.dim == 2 ? merge_targets_d(s, 2, gi, c, nj, lj) : merge_targets_d(s, 3, gi, c, nj, lj);
}

/* Forward Euler with the small nodes merged (above). CH_CG_R holds the volume
 * fraction phi from boundary.c (phi < SMALL_NODE marks a candidate: a full node
 * has 1, a node on an aligned face 1/2); CH_CG_P is scratch: the capacity a
 * node takes in, or -1 on a merged node. Serial over every block, in block
 * order, so deterministic at any thread count. A small node is found by its
 * own phi, not by its block's flag of holding surface area (boundary.c): the
 * loaf's bottom nodes on the tray hold no area, and a sliver of area that
 * came and went flagged a block on one side of the loaf's axis and not its
 * mirror image, which straddles two blocks (mpm_oven_mirror_symmetric,
 * 3e-3 degC at dx 2.5 mm). */
void small_nodes_explicit_step(hearth_scene *s, double dt) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) memset(grid_block(g, k) + CH_CG_P * NPB, 0, sizeof(double) * (size_t)NPB);
    for (int k = 0; k < g->nactive; k++) { /* each small node's source and capacity into its target */
        double *node = grid_block(g, k);
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        for (int l = 0; l < NPB; l++) {
            const double c = node[CH_HC * NPB + l];
            if (!(c > 0) || !(node[CH_CG_R * NPB + l] < SMALL_NODE)) continue;
            if (s->heat.nfix && !isnan(s->heat.fix[k * NPB + l])) continue;
            int gi[3], lj[MERGE_MAX];
            double *nj[MERGE_MAX];
            grid_node_index(g, bc, l, gi);
            const int n = merge_targets(s, gi, c, nj, lj);
            if (!n) continue;
            const double src = (node[CH_B * NPB + l] - node[CH_R * NPB + l]) / n, share = c / n; /* a tie shares equally */
            for (int j = 0; j < n; j++) nj[j][CH_B * NPB + lj[j]] += src, nj[j][CH_CG_P * NPB + lj[j]] += share;
            node[CH_CG_P * NPB + l] = -1.0;
        }
    }
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            const double c = node[CH_HC * NPB + l], extra = node[CH_CG_P * NPB + l];
            if (c > 0 && extra >= 0) node[CH_T * NPB + l] += dt * (node[CH_B * NPB + l] - node[CH_R * NPB + l]) / (c + extra);
        }
    }
    for (int k = 0; k < g->nactive; k++) { /* a merged node takes its target's increment */
        double *node = grid_block(g, k);
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        for (int l = 0; l < NPB; l++) {
            if (node[CH_CG_P * NPB + l] != -1.0) continue;
            int gi[3], lj[MERGE_MAX];
            double *nj[MERGE_MAX];
            grid_node_index(g, bc, l, gi);
            const int n = merge_targets(s, gi, node[CH_HC * NPB + l], nj, lj); /* the same lookup as above */
            double dT = 0; /* the mean of its targets' increments: their shares' heat adds up to the sources */
            for (int j = 0; j < n; j++) dT += nj[j][CH_T * NPB + lj[j]] - nj[j][CH_T0 * NPB + lj[j]];
            if (n) node[CH_T * NPB + l] += dT / n;
        }
    }
}
