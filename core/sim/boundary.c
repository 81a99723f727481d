/* boundary.c: boundary particles (Ding et al. 2019 §6.6).
 *
 * A grid node is on the boundary when it has mass and a face neighbour that
 * is empty air: an empty node of the grid. Past the grid's last node is the
 * domain wall: material pressed against a wall (particles stop one cell from
 * it, so their stencils reach the last node) does not exchange heat or water
 * through it. A node inside a collider is contact, not air. Each boundary
 * node picks its closest particle: P2G records every node's closest particle
 * as it scatters (mpm.c), so the search costs no pass of its own.
 *
 * A pick carries the node's face area dx^(dim-1) rather than the paper's
 * S_p = (9 pi/16 V_p^2)^(1/3): with one pick per boundary node the latter
 * counts about a third of a flat surface at 8 particles per cell, and the
 * heat slab test misses by far more than 1e-2 (see thermal.c). A particle
 * picked by several nodes (a corner) adds their areas. */
#include "boundary.h"

#include <math.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "scene.h"

int boundary_needed(const hearth_scene *s) {
    if (!isnan(s->def.oven_temperature) && s->def.oven_beta > 0) return 1;
    for (int m = 0; m < s->nmat; m++)
        if (s->mats[m].core[CP_EVAPORATION] > 0 && (s->ps.enabled & (1u << PC_WATER))) return 1;
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
    const int n = s->ps.n;
    if (n <= s->bnd_area_cap) return HEARTH_OK;
    double *a = mem_alloc(sizeof(double) * (size_t)n);
    if (!a) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for boundary particles (%d particles)", n);
    mem_free(s->bnd_area, sizeof(double) * (size_t)s->bnd_area_cap);
    s->bnd_area = a;
    s->bnd_area_cap = n;
    return HEARTH_OK;
}

hearth_status boundary_find(hearth_scene *s, hearth_error *err) {
    hearth_status st = ensure_area(s, err);
    if (st) return st;
    grid *g = &s->g;
    particles *ps = &s->ps;
    const int D = g->dim, NPB = g->nodes_per_block, n = ps->n;
    double *area = s->bnd_area;
    memset(area, 0, sizeof(double) * (size_t)n);
    int *flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    if (flags)
        for (int i = 0; i < n; i++) flags[i] &= ~PF_BOUNDARY;
    if (!boundary_needed(s)) return HEARTH_OK;

    /* P2G left each node's closest particle in CH_CG_P (index + 1; 0: none). Keep
     * it on boundary nodes, clear it elsewhere. */
#pragma omp parallel for schedule(dynamic, 4) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        for (int l = 0; l < NPB; l++) {
            if (node[l] <= 0 || node[CH_CG_P * NPB + l] == 0) {
                node[CH_CG_P * NPB + l] = 0;
                continue;
            }
            int gi[3];
            grid_node_index(g, bc, l, gi);
            int edge = 0;
            for (int d = 0; d < D && !edge; d++)
                for (int sgn = -1; sgn <= 1; sgn += 2) {
                    int nb[3] = {gi[0], gi[1], gi[2]};
                    nb[d] += sgn;
                    if (air_or_mass(g, nb) == 0) edge = 1;
                }
            double xi[3] = {0, 0, 0};
            for (int d = 0; d < D; d++) xi[d] = g->lo[d] + gi[d] * g->dx;
            int in_col = 0;
            for (int c = 0; c < s->ncol && edge && !in_col; c++)
                in_col = collider_near(&s->cols[c], xi) && collider_sdf(&s->cols[c], xi, NULL) < 0;
            if (!edge || in_col) node[CH_CG_P * NPB + l] = 0;
        }
    }
    const double face = D == 2 ? g->dx : g->dx * g->dx;
    for (int k = 0; k < g->nactive; k++) { /* serial: several nodes may pick one particle */
        const double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            const int p = (int)node[CH_CG_P * NPB + l] - 1;
            if (p < 0) continue;
            area[p] += face;
            if (flags) flags[p] |= PF_BOUNDARY;
        }
    }
    return HEARTH_OK;
}
