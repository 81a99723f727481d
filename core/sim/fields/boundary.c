/* boundary.c: boundary particles (Ding et al. 2019 §6.6).
 *
 * A grid node is on the boundary when it has mass and a face neighbour that
 * is empty air: an empty node of the grid. Past the grid's last node is the
 * domain wall: material pressed against a wall (particles stop one cell from
 * it, so their stencils reach the last node) does not exchange heat or water
 * through it. A node inside a collider is contact, not air. Each boundary
 * node picks its closest particle. Only particles whose stencil reaches a
 * boundary node are measured, so a large body pays for its skin, not its
 * bulk.
 *
 * A pick carries the node's face area dx^(dim-1) rather than the paper's
 * S_p = (9 pi/16 V_p^2)^(1/3): with one pick per boundary node the latter
 * counts about a third of a flat surface at 8 particles per cell, and the
 * heat slab test misses by far more than 1e-2 (see thermal.c). A particle
 * picked by several nodes (a corner) adds their areas. At the ends of a face
 * this over- or under-counts about one node row (see tests/unit_water.c,
 * `water_drying_vs_fd`, and the heat slab's first-order convergence in
 * docs/trade/). */
#include "boundary.h"

#include <math.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "scene.h"
#include "mpm.h"

void boundary_init(boundary_state *b) { *b = (boundary_state){0}; }

void boundary_free(boundary_state *b) {
    mem_free(b->area, sizeof(double) * (size_t)b->area_cap);
    mem_free(b->blocks, (size_t)b->blocks_cap);
    boundary_init(b);
}

int boundary_needed(const hearth_scene *s) {
    if (!isnan(s->def.oven_temperature) && s->def.oven_beta > 0) return 1;
    for (int m = 0; m < s->mats.n; m++)
        if (s->mats.slot[m].core[CP_EVAPORATION] > 0 && (s->ps.enabled & (1u << PC_WATER))) return 1;
    return 0;
}

/* Mass of node (i, j, k), or -1 past the grid (the wall, not air). */
static double air_or_mass(const grid *g, const int gi[3]) {
    for (int d = 0; d < g->dim; d++)
        if (gi[d] < 0 || gi[d] > g->nn[d] - 1) return -1;
    const int slot = g->slot[grid_block_id(g, gi[0] / GRID_B, gi[1] / GRID_B, gi[2] / GRID_B)];
    if (slot < 0) return 0;
    const int l = g->dim == 2 ? (gi[0] % GRID_B) * GRID_B + gi[1] % GRID_B
                              : ((gi[0] % GRID_B) * GRID_B + gi[1] % GRID_B) * GRID_B + gi[2] % GRID_B;
    return grid_block(g, slot)[l];
}

static hearth_status ensure_area(hearth_scene *s, hearth_error *err) {
    const int n = s->ps.n, nb = s->g.nactive;
    if (nb > s->boundary.blocks_cap) {
        unsigned char *b = mem_alloc((size_t)nb * 2);
        if (!b) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for boundary blocks (%d blocks)", nb);
        mem_free(s->boundary.blocks, (size_t)s->boundary.blocks_cap);
        s->boundary.blocks = b;
        s->boundary.blocks_cap = nb * 2;
    }
    if (n <= s->boundary.area_cap) return HEARTH_OK;
    double *a = mem_alloc(sizeof(double) * (size_t)n);
    if (!a) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for boundary particles (%d particles)", n);
    mem_free(s->boundary.area, sizeof(double) * (size_t)s->boundary.area_cap);
    s->boundary.area = a;
    s->boundary.area_cap = n;
    return HEARTH_OK;
}

/* One particle block's share of the search: the boundary nodes of its tile
 * (block and +1 neighbours) in a dense array, the particles whose stencil
 * reaches one of them, and the tile written back. A node's running best
 * comes in with it, so the result is that of visiting every particle in
 * colour order. The squared distance is x - x_i per axis, summed in order:
 * near-ties on a lattice round the same way every step. */
static void closest_in_block(hearth_scene *s, int k) {
    grid *g = &s->g;
    const int D = g->dim, NPB = g->nodes_per_block, TN = grid_tile_count(g);
    const pblock pb = mpm_state_of(s)->pb[k];
    int bc[3];
    grid_block_coords(g, pb.block, bc);
    int any = 0; /* the tile spans the block and its +1 neighbours: is there a boundary node in any? */
    for (int a = 0; a <= 1 && !any; a++)
        for (int b = 0; b <= 1 && !any; b++)
            for (int c = 0; c <= (D == 3) && !any; c++) any = s->boundary.blocks[g->slot[grid_block_id(g, bc[0] + a, bc[1] + b, bc[2] + c)]];
    if (!any) return; /* most particle blocks lie inside the body */
    double best[GRID_T * GRID_T * GRID_T];
    int pick[GRID_T * GRID_T * GRID_T];
    any = 0;
    for (int t = 0; t < TN; t++) {
        int l;
        const double *node = grid_block(g, grid_tile_slot(g, bc, t, &l));
        best[t] = node[CH_CG_R * NPB + l];
        pick[t] = -1;
        any |= best[t] >= 0;
    }
    if (!any) return; /* the blocks have boundary nodes, this tile none */
    /* near[base]: a boundary node in the 3^dim stencil starting at base (a node of the block) */
    unsigned char near[GRID_B * GRID_B * GRID_B];
    for (int a = 0; a < GRID_B; a++)
        for (int b = 0; b < GRID_B; b++)
            for (int c = 0; c < (D == 3 ? GRID_B : 1); c++) {
                int hit = 0;
                for (int i = 0; i < 3 && !hit; i++)
                    for (int j = 0; j < 3 && !hit; j++)
                        for (int m = 0; m < (D == 3 ? 3 : 1) && !hit; m++)
                            hit = best[D == 2 ? (a + i) * GRID_T + b + j : ((a + i) * GRID_T + b + j) * GRID_T + c + m] >= 0;
                near[D == 2 ? a * GRID_B + b : (a * GRID_B + b) * GRID_B + c] = (unsigned char)hit;
            }
    const double *X = pcold(&s->ps, PC_X);
    for (int i = pb.start; i < pb.end; i++) {
        const double *x = X + 3 * i;
        int base[3] = {0, 0, 0}, lb[3] = {0, 0, 0};
        for (int d = 0; d < D; d++) {
            base[d] = (int)floor((x[d] - g->lo[d]) * g->inv_dx - 0.5);
            lb[d] = base[d] - bc[d] * GRID_B;
        }
        if (!near[D == 2 ? lb[0] * GRID_B + lb[1] : (lb[0] * GRID_B + lb[1]) * GRID_B + lb[2]]) continue;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                for (int c = 0; c < (D == 3 ? 3 : 1); c++) {
                    const int t = D == 2 ? (lb[0] + a) * GRID_T + lb[1] + b : ((lb[0] + a) * GRID_T + lb[1] + b) * GRID_T + lb[2] + c;
                    if (best[t] < 0) continue;
                    const int gi[3] = {base[0] + a, base[1] + b, base[2] + c};
                    double d2 = 0;
                    for (int d = 0; d < D; d++) {
                        const double e = x[d] - (g->lo[d] + gi[d] * g->dx);
                        d2 += e * e;
                    }
                    if (d2 < best[t]) {
                        best[t] = d2;
                        pick[t] = i;
                    }
                }
    }
    for (int t = 0; t < TN; t++) {
        if (pick[t] < 0) continue;
        int l;
        double *node = grid_block(g, grid_tile_slot(g, bc, t, &l));
        node[CH_CG_R * NPB + l] = best[t];
        node[CH_CG_P * NPB + l] = pick[t];
    }
}

hearth_status boundary_find(hearth_scene *s, hearth_error *err) {
    hearth_status st = ensure_area(s, err);
    if (st) return st;
    grid *g = &s->g;
    particles *ps = &s->ps;
    const int D = g->dim, NPB = g->nodes_per_block, n = ps->n;
    double *area = s->boundary.area;
    memset(area, 0, sizeof(double) * (size_t)n);
    int *flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    if (flags)
        for (int i = 0; i < n; i++) flags[i] &= ~PF_BOUNDARY;
    if (!boundary_needed(s)) return HEARTH_OK;

    /* mark boundary nodes: CH_CG_R = best squared distance so far (-1: not a
     * boundary node), CH_CG_P = the particle picked */
    const int stride[3] = {D == 2 ? GRID_B : GRID_B * GRID_B, D == 2 ? 1 : GRID_B, 1}; /* node index steps within a block */
#pragma omp parallel for schedule(dynamic, 4) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        s->boundary.blocks[k] = 0;
        for (int l = 0; l < NPB; l++) {
            node[CH_CG_R * NPB + l] = -1;
            node[CH_CG_P * NPB + l] = -1;
            if (node[l] <= 0) continue;
            int gi[3];
            grid_node_index(g, bc, l, gi);
            int edge = 0;
            for (int d = 0; d < D && !edge; d++)
                for (int sgn = -1; sgn <= 1; sgn += 2) {
                    int nb[3] = {gi[0], gi[1], gi[2]};
                    nb[d] += sgn;
                    const int lc = gi[d] % GRID_B + sgn; /* a neighbour inside this block is read directly */
                    if (lc >= 0 && lc < GRID_B && nb[d] < g->nn[d]) {
                        if (node[l + sgn * stride[d]] == 0) edge = 1;
                    } else if (air_or_mass(g, nb) == 0) {
                        edge = 1;
                    }
                }
            if (!edge) continue;
            double xi[3] = {0, 0, 0};
            for (int d = 0; d < D; d++) xi[d] = g->lo[d] + gi[d] * g->dx;
            int in_col = 0;
            for (int c = 0; c < s->ncol && !in_col; c++)
                in_col = collider_near(&s->cols[c], xi) && collider_sdf(&s->cols[c], xi, NULL) < 0;
            if (!in_col) {
                node[CH_CG_R * NPB + l] = INFINITY;
                s->boundary.blocks[k] = 1;
            }
        }
    }
    /* the closest particle of each boundary node; colours keep writes apart, and
     * particles go in sorted order, so a tie goes to the first one met on any thread count */
    const mpm_state *m = mpm_state_of(s); /* the sort's particle blocks */
    for (int col = 0; col < 8; col++) {
#pragma omp parallel for schedule(dynamic, 2) if (n >= SCENE_PARALLEL_MIN)
        for (int q = m->colour_start[col]; q < m->colour_start[col + 1]; q++) closest_in_block(s, m->colour_pb[q]);
    }
    const double face = D == 2 ? g->dx : g->dx * g->dx;
    for (int k = 0; k < g->nactive; k++) { /* serial: several nodes may pick one particle */
        const double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            const int p = (int)node[CH_CG_P * NPB + l];
            if (node[CH_CG_R * NPB + l] < 0 || p < 0) continue;
            area[p] += face;
            if (flags) flags[p] |= PF_BOUNDARY;
        }
    }
    return HEARTH_OK;
}
