/* boundary.c: the air surface of the material (Ding et al. 2019 §6.6).
 *
 * The surface is measured from the material's volume fraction on the grid,
 * phi_i = sum_p w_ip V_p / dx^dim (one inside, zero in the air, a smooth ramp
 * about three cells wide across the surface). By the coarea formula the
 * integral of |grad phi| over the grid is the mean perimeter (area in 3D) of
 * phi's level sets, which tends to the true surface whatever way it lies on
 * the grid. Each grid cell takes |grad psi| dx^dim from the gradient of the
 * multilinear interpolant at its centre, psi being phi clipped to [0.2, 0.8]
 * and rescaled (the clip keeps a disordered interior's noise out: with
 * [0.1, 0.9] a disc seeded with jitter 1 measured 1.03 of its perimeter at 32
 * cells, with [0.2, 0.8] 1.0001; the mean of the level sets between stays on
 * the surface), along n, the gradient averaged over the 3^dim cells around. A cell's area goes to its
 * corners by their mass and a node's to its particles by their mass share
 * w_ip m_p / m_i, so the particles' areas sum exactly to the cells'.
 *
 * Rejected: one face dx^(dim-1) per boundary node (an empty face neighbour),
 * given to the node's closest particle, which this replaced (issue #17): it
 * counts the staircase, so a square turned 45 degrees took in 0.72 of the
 * heat of an aligned one, and a disc's (ball's) effective Biot number tended
 * to 0.90 (0.83) of the true one as dx shrank. The paper's per-particle
 * S_p = (9 pi/16 V_p^2)^(1/3) counts about a third of a flat surface at 8
 * particles per cell with one pick per node.
 *
 * What is not air: past the grid is the domain wall, and material pressed
 * against it (particles stop one cell from it, so their stencils reach the
 * last node) does not exchange heat or water through it; along an axis
 * whose end node has mass within three nodes of a cell, the cell's gradient
 * loses that component. Near a collider (the cell centre within 2 dx of it)
 * the gradient loses its component along the collider's normal: contact,
 * not air. A face ending on a collider keeps its full length, since the
 * tangential gradient's integral across the ramp is the face's extent.
 *
 * Cost: the node volumes come from P2G, one more tile channel when heat or
 * water is live (a separate scatter pass cost more: issue #17's follow-up);
 * then node passes when an oven or evaporation is live; the particle gather runs only where
 * a particle block's tile holds surface. `robin_square_rotations`,
 * `robin_disc_converges`, `robin_ball_converges` (tests/unit_heat.c) check it. */
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
    mem_free(b->depth, sizeof(double) * (size_t)b->area_cap);
    mem_free(b->blocks, (size_t)b->blocks_cap);
    boundary_init(b);
}

int boundary_needed(const hearth_scene *s) {
    if (!isnan(s->def.oven_temperature) && s->def.oven_beta > 0) return 1;
    for (int m = 0; m < s->mats.n; m++)
        if (s->mats.slot[m].core[CP_EVAPORATION] > 0 && (s->ps.enabled & (1u << PC_WATER))) return 1;
    return 0;
}

static hearth_status ensure_area(hearth_scene *s, hearth_error *err) {
    const int n = s->ps.n, nb = s->g.nactive;
    if (2 * nb > s->boundary.blocks_cap) { /* two flags per active block, with room to grow */
        unsigned char *b = mem_alloc((size_t)nb * 4);
        if (!b) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for boundary blocks (%d blocks)", nb);
        mem_free(s->boundary.blocks, (size_t)s->boundary.blocks_cap);
        s->boundary.blocks = b;
        s->boundary.blocks_cap = nb * 4;
    }
    if (n <= s->boundary.area_cap) return HEARTH_OK;
    double *a = mem_alloc(sizeof(double) * (size_t)n), *dep = mem_alloc(sizeof(double) * (size_t)n);
    if (!a || !dep) {
        mem_free(a, sizeof(double) * (size_t)n);
        mem_free(dep, sizeof(double) * (size_t)n);
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory for boundary particles (%d particles)", n);
    }
    mem_free(s->boundary.area, sizeof(double) * (size_t)s->boundary.area_cap);
    mem_free(s->boundary.depth, sizeof(double) * (size_t)s->boundary.area_cap);
    s->boundary.area = a;
    s->boundary.depth = dep;
    s->boundary.area_cap = n;
    return HEARTH_OK;
}

/* Node (gi) of the grid: its block's storage and local index, or NULL when
 * the node lies past the grid or in a block without storage (empty air). */
static double *node_at(const grid *g, const int gi[3], int *l) {
    for (int d = 0; d < g->dim; d++)
        if (gi[d] < 0 || gi[d] > g->nn[d] - 1) return NULL;
    const int slot = g->slot[grid_block_id(g, gi[0] / GRID_B, gi[1] / GRID_B, gi[2] / GRID_B)];
    if (slot < 0) return NULL;
    *l = g->dim == 2 ? (gi[0] % GRID_B) * GRID_B + gi[1] % GRID_B
                     : ((gi[0] % GRID_B) * GRID_B + gi[1] % GRID_B) * GRID_B + gi[2] % GRID_B;
    return grid_block(g, slot);
}

/* The storage of the 3^dim blocks around block bc, the block itself among
 * them, indexed ((a+1) 3 + b+1) 3 + c+1 for the offset (a, b, c) (no c in
 * 2D); NULL past the grid or where a block has no storage. Looked up once a
 * block, so a node's neighbours across the block's faces cost an index. */
static void block_ring(const grid *g, const int bc[3], const double *ring[27]) {
    const int D = g->dim;
    int r = 0;
    for (int a = -1; a <= 1; a++)
        for (int b = -1; b <= 1; b++)
            for (int c = D == 3 ? -1 : 0; c <= (D == 3 ? 1 : 0); c++) {
                const int x = bc[0] + a, y = bc[1] + b, z = bc[2] + c;
                int slot = -1;
                if (x >= 0 && y >= 0 && z >= 0 && x < g->nb[0] && y < g->nb[1] && z < g->nb[2]) slot = g->slot[grid_block_id(g, x, y, z)];
                ring[r++] = slot >= 0 ? grid_block(g, slot) : NULL;
            }
}

/* Node gi + off (each component in -1..1) given node gi at local index l of
 * block storage node, whose blocks around are ring: its storage and local
 * index, or NULL past the grid or in a block without storage (empty air). */
static inline const double *node_off(const grid *g, const double *node, const double *const ring[27], int l, const int gi[3],
                                     const int off[3], int *lj) {
    int in = 1, step = 0;
    for (int d = 0; d < g->dim; d++) {
        const int c = gi[d] % GRID_B + off[d];
        in &= c >= 0 && c < GRID_B;
        step = step * GRID_B + off[d];
    }
    if (in) {
        *lj = l + step;
        return node;
    }
    int r = 0, lo = 0;
    for (int d = 0; d < g->dim; d++) {
        const int n = gi[d] + off[d];
        if (n < 0 || n > g->nn[d] - 1) return NULL;
        const int c = gi[d] % GRID_B + off[d], o = c < 0 ? -1 : c >= GRID_B ? 1 : 0;
        r = r * 3 + o + 1;
        lo = lo * GRID_B + c - o * GRID_B;
    }
    *lj = lo;
    return ring[r];
}

/* Channel ch of node gi, 0 where the node has no storage (and past the grid). */
static double node_value(const grid *g, const int gi[3], int ch) {
    int l;
    const double *node = node_at(g, gi, &l);
    return node ? node[ch * g->nodes_per_block + l] : 0.0;
}

/* Is any of the blocks at bc + o, o in {lo..lo+1}^dim (lo = -1 or 0), flagged? */
static int any_flag(const grid *g, const unsigned char *flag, const int bc[3], int lo) {
    for (int a = lo; a <= lo + 1; a++)
        for (int b = lo; b <= lo + 1; b++)
            for (int c = lo; c <= (g->dim == 3 ? lo + 1 : lo); c++) {
                const int x = bc[0] + a, y = bc[1] + b, z = g->dim == 3 ? bc[2] + c : 0;
                if (x < 0 || y < 0 || z < 0 || x >= g->nb[0] || y >= g->nb[1] || z >= g->nb[2]) continue;
                const int slot = g->slot[grid_block_id(g, x, y, z)];
                if (slot >= 0 && flag[slot]) return 1;
            }
    return 0;
}

/* ---- the depth of a particle's temperature sample (the oven's Robin offset) ----
 * A particle of the ramp holds its share of the surface but sits up to a cell or
 * two inside it, and the grid gives it the temperature of its nodes, which
 * average their particles by mass: nodes in the air see only material deeper
 * than themselves. Against a linear profile the sample is that of a point at
 * depth d_p (the slab's outermost particle, a quarter cell in: d = 0.57 dx), so
 * beta (theta_out - theta_p) overstates the flux by 1 + beta d_p / kappa, an
 * error of order dx (about 0.6 dx Bi / R on a disc). thermal.c divides it out.
 *
 * Across a flat surface at depth t below node i (grid units) the node's volume
 * fraction is P(t), the quadratic B-spline's integral up to t, and the mass
 * weighted mean depth of its material E(t) = t - G(t) / P(t), G the kernel's first
 * moment up to t. A particle's t_p solves sum_i w_ip P(t_p + delta_i) = phi_p
 * (delta_i = -n . (x_i - x_p), n the outward normal from grad phi), which
 * matches the grid's own interpolant at this particle whatever its offset to the
 * nodes, and d_p = sum_i w_ip E(t_p + delta_i). Against the discrete 1D lattice
 * the estimate is within 0.015 dx for the outer two rows, which hold nine tenths
 * of the area. Tilted surfaces see the axis kernel's profile (the same variance;
 * the projected kernel's tails differ slightly).
 * Rejected: (phi_p - 1/2) / |grad phi| (phi is not linear across the ramp: 20%
 * long at half a cell); the geometric depth alone (the nodes' averaging adds
 * 0.3 dx at the outer row); a scatter of the particles' first moment (exact for
 * any arrangement but three more channels or a colour pass each step). */
static inline double kernel_P(double t) { /* int_-inf^t N(u) du, N the quadratic B-spline */
    if (t <= -1.5) return 0.0;
    if (t <= -0.5) return (1.5 + t) * (1.5 + t) * (1.5 + t) / 6.0;
    if (t <= 0.5) return 1.0 / 6.0 + 0.75 * (t + 0.5) - (t * t * t + 0.125) / 3.0;
    if (t < 1.5) return 1.0 - (1.5 - t) * (1.5 - t) * (1.5 - t) / 6.0;
    return 1.0;
}

static inline double kernel_N(double t) { /* the quadratic B-spline, P's derivative */
    const double a = fabs(t);
    return a < 0.5 ? 0.75 - a * a : a < 1.5 ? 0.5 * (1.5 - a) * (1.5 - a) : 0.0;
}

static inline double kernel_E(double t) { /* mean depth of the material a node at depth t sees */
    const double p = kernel_P(t);
    if (p < 1e-9) return t > -1.5 ? 0.25 * (t + 1.5) : 0.0; /* the limit t -> -1.5 */
    const double a = -fabs(t); /* G(t) = int_-inf^t u N(u) du is even */
    double G = 0;
    if (a <= -1.5) G = 0;
    else if (a <= -0.5) G = 0.5 * ((1.5 + a) * (1.5 + a) * (1.5 + a) * (1.5 + a) / 4 - 0.5 * (1.5 + a) * (1.5 + a) * (1.5 + a));
    else G = -0.125 + 0.375 * (a * a - 0.25) - (a * a * a * a - 0.0625) / 4;
    return t - G / p;
}

/* d_p in grid units from the stencil weights wt, the offsets de and phi_p. */
static double sample_depth(const double *wt, const double *de, int nst, double phi) {
    double lo = -4.5, hi = 4.5, t = 0;
    for (int it = 0; it < 40; it++) { /* safeguarded Newton on the monotone sum_i w P(t + delta_i) */
        double f = -phi, fp = 0;
        for (int k = 0; k < nst; k++) {
            f += wt[k] * kernel_P(t + de[k]);
            fp += wt[k] * kernel_N(t + de[k]);
        }
        if (fabs(f) < 1e-10) break;
        if (f < 0) lo = t;
        else hi = t;
        double tn = fp > 0 ? t - f / fp : 0.5 * (lo + hi);
        if (!(tn > lo && tn < hi)) tn = 0.5 * (lo + hi);
        if (fabs(tn - t) < 1e-9) break;
        t = tn;
    }
    double d = 0;
    for (int k = 0; k < nst; k++) d += wt[k] * kernel_E(t + de[k]);
    return fmin(3.0, fmax(0.0, d)); /* the area reaches about two cells in */
}

/* Each particle's area m_p sum_i w_ip r_i from CH_CG_P, one particle block at
 * a time, and with an oven the depth of its temperature sample from the volume
 * fraction phi in CH_CG_R. Only blocks whose tile holds area are gathered: the
 * interior of a large body is skipped. */
static void area_gather(hearth_scene *s, int k, int want_depth) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block, TN = grid_tile_count(g), D = g->dim;
    const pblock pb = mpm_state_of(s)->pb[k];
    int bc[3];
    grid_block_coords(g, pb.block, bc);
    int any = 0; /* does the tile (block and +1 neighbours) hold area? */
    for (int a = 0; a <= 1 && !any; a++)
        for (int b = 0; b <= 1 && !any; b++)
            for (int c = 0; c <= (D == 3) && !any; c++) any = s->boundary.blocks[g->slot[grid_block_id(g, bc[0] + a, bc[1] + b, bc[2] + c)]];
    if (!any) return; /* most particle blocks lie inside the body */
    double r[GRID_T * GRID_T * GRID_T], ph[GRID_T * GRID_T * GRID_T];
    for (int t = 0; t < TN; t++) {
        int l;
        const double *node = grid_block(g, grid_tile_slot(g, bc, t, &l));
        r[t] = node[CH_CG_P * NPB + l];
        ph[t] = node[CH_CG_R * NPB + l];
    }
    const double *X = pcold(&s->ps, PC_X), *M = pcold(&s->ps, PC_MASS);
    int *flags = s->ps.enabled & (1u << PC_FLAGS) ? pcoli(&s->ps, PC_FLAGS) : NULL;
    for (int i = pb.start; i < pb.end; i++) { /* the weights are a tensor product: one axis at a time */
        double w[3][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, dw[3][3] = {{0}}, fx[3] = {0, 0, 0};
        int lb[3] = {0, 0, 0};
        for (int d = 0; d < D; d++) {
            const double Xd = (X[3 * i + d] - g->lo[d]) * g->inv_dx;
            const int base = (int)floor(Xd - 0.5);
            fx[d] = Xd - base;
            bspline_weights(fx[d], w[d], dw[d]);
            lb[d] = base - bc[d] * GRID_B;
        }
        double a = 0;
        for (int x = 0; x < 3; x++)
            for (int y = 0; y < 3; y++) {
                const double wxy = w[0][x] * w[1][y];
                if (D == 2) {
                    a += wxy * r[(lb[0] + x) * GRID_T + lb[1] + y];
                } else {
                    const double *row = r + ((lb[0] + x) * GRID_T + lb[1] + y) * GRID_T + lb[2];
                    a += wxy * (w[2][0] * row[0] + w[2][1] * row[1] + w[2][2] * row[2]);
                }
            }
        if (!(a > 0)) continue;
        s->boundary.area[i] = M[i] * a;
        if (flags) flags[i] |= PF_BOUNDARY;
        if (!want_depth) continue;
        /* phi and its gradient (grid units) at the particle, and the stencil */
        double wt[27], pos[27][3], phi = 0, gr[3] = {0, 0, 0};
        int nst = 0;
        for (int x = 0; x < 3; x++)
            for (int y = 0; y < 3; y++)
                for (int z = 0; z < (D == 3 ? 3 : 1); z++) {
                    const int t = D == 2 ? (lb[0] + x) * GRID_T + lb[1] + y : ((lb[0] + x) * GRID_T + lb[1] + y) * GRID_T + lb[2] + z;
                    const double wz = D == 3 ? w[2][z] : 1.0;
                    wt[nst] = w[0][x] * w[1][y] * wz;
                    phi += wt[nst] * ph[t];
                    gr[0] += dw[0][x] * w[1][y] * wz * ph[t];
                    gr[1] += w[0][x] * dw[1][y] * wz * ph[t];
                    if (D == 3) gr[2] += w[0][x] * w[1][y] * dw[2][z] * ph[t];
                    const int idx[3] = {x, y, z};
                    for (int d = 0; d < 3; d++) pos[nst][d] = d < D ? idx[d] - fx[d] : 0.0; /* x_i - x_p */
                    nst++;
                }
        const double gn = sqrt(gr[0] * gr[0] + gr[1] * gr[1] + gr[2] * gr[2]);
        if (!(gn > 1e-6)) continue; /* no direction to measure along: depth 0, no correction */
        double de[27];
        for (int q = 0; q < nst; q++) de[q] = (gr[0] * pos[q][0] + gr[1] * pos[q][1] + gr[2] * pos[q][2]) / gn; /* -n . (x_i - x_p), n = -grad phi / |grad phi| */
        s->boundary.depth[i] = sample_depth(wt, de, nst, phi) * g->dx;
    }
}

/* The clipped volume fraction psi = (phi - PHI_LO) / (PHI_HI - PHI_LO) in [0, 1]:
 * its gradient's integral is the mean perimeter of phi's level sets between
 * the two, and the clip keeps the noise of a disordered interior (phi within
 * 1 - PHI_HI of one) from counting as surface. */
#define PHI_LO 0.2
#define PHI_HI 0.8
static inline double clip_psi(double phi) { return fmin(1.0, fmax(0.0, (phi - PHI_LO) / (PHI_HI - PHI_LO))); }

hearth_status boundary_find(hearth_scene *s, hearth_error *err) {
    hearth_status st = ensure_area(s, err);
    if (st) return st;
    grid *g = &s->g;
    particles *ps = &s->ps;
    const int D = g->dim, NPB = g->nodes_per_block, n = ps->n;
    double *area = s->boundary.area;
    memset(area, 0, sizeof(double) * (size_t)n);
    memset(s->boundary.depth, 0, sizeof(double) * (size_t)n);
    int *flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    if (flags)
        for (int i = 0; i < n; i++) flags[i] &= ~PF_BOUNDARY;
    if (!boundary_needed(s)) return HEARTH_OK;
    const mpm_state *m = mpm_state_of(s); /* the sort's particle blocks */
    /* the depth of the temperature samples only serves the oven's Robin term */
    const int want_depth = !isnan(s->def.oven_temperature) && s->def.oven_beta > 0 && (ps->enabled & (1u << PC_TEMPERATURE));

    /* 1. P2G left the node volumes sum_p w_ip J V_0 in CH_CG_R (mpm.c: the
     * scatter rides along with the mass); from them the volume fraction phi, kept
     * there until area_gather */
    const double cellv = D == 2 ? g->dx * g->dx : g->dx * g->dx * g->dx;
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        unsigned char mixed = 0;
        for (int l = 0; l < NPB; l++) {
            const double phi = node[CH_CG_R * NPB + l] / cellv;
            node[CH_CG_R * NPB + l] = phi; /* psi is taken from it where needed; the depth (area_gather) reads phi */
            mixed |= clip_psi(phi) < 1.0;
        }
        s->boundary.blocks[k] = mixed; /* a block where psi is not one everywhere */
    }
    /* only cells with a corner in a mixed block have a gradient: the interior is skipped */
    unsigned char *near = s->boundary.blocks + g->nactive; /* ensure_area leaves room for two flags per block */
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        near[k] = (unsigned char)any_flag(g, s->boundary.blocks, bc, -1);
    }

    /* 2. each cell's gradient of psi (grid units), from the multilinear
     * interpolant at its centre, in CH_CG_P, CH_B, CH_T0 of its upper corner, and
     * the mass of its corners in CH_R: a node with mass has its +1 neighbours in
     * storage (they are in its particles' tiles), so every cell with mass has its
     * upper corner stored, while a lower corner may be empty air. These channels
     * are scratch until thermal_prepare fills them. */
    const int NC = 1 << D, GCH[3] = {CH_CG_P, CH_B, CH_T0};
#pragma omp parallel for schedule(dynamic, 4) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        for (int d = 0; d < D; d++) memset(node + GCH[d] * NPB, 0, sizeof(double) * (size_t)NPB);
        memset(node + CH_R * NPB, 0, sizeof(double) * (size_t)NPB);
        if (!near[k]) continue;
        const double *ring[27];
        block_ring(g, bc, ring);
        for (int l = 0; l < NPB; l++) {
            int gi[3];
            grid_node_index(g, bc, l, gi);
            int inside = 1;
            for (int d = 0; d < D; d++) inside &= gi[d] >= 1;
            if (!inside) continue; /* no cell below the grid's first node */
            double psi[8], msum = 0;
            for (int c = 0; c < NC; c++) {
                int off[3] = {0, 0, 0}, lj;
                for (int d = 0; d < D; d++) off[d] = -!((c >> d) & 1);
                const double *nj = node_off(g, node, ring, l, gi, off, &lj);
                psi[c] = nj ? clip_psi(nj[CH_CG_R * NPB + lj]) : 0.0;
                msum += nj ? nj[CH_M * NPB + lj] : 0.0;
            }
            if (!(msum > 0)) continue;
            double gr[3] = {0, 0, 0};
            for (int c = 0; c < NC; c++)
                for (int d = 0; d < D; d++) gr[d] += ((c >> d) & 1 ? psi[c] : -psi[c]) / (NC / 2);
            /* a face against the domain wall is no air surface: along an axis whose
             * end node (on this line) has mass within three nodes, drop that component */
            for (int d = 0; d < D; d++) {
                int ej[3] = {gi[0], gi[1], gi[2]};
                if (gi[d] - 1 <= 2) ej[d] = 0;
                else if (gi[d] >= g->nn[d] - 3) ej[d] = g->nn[d] - 1;
                else continue;
                if (node_value(g, ej, CH_M) > 0) gr[d] = 0;
            }
            /* nor is contact with a collider: drop the component along its normal */
            double xc[3] = {0, 0, 0};
            for (int d = 0; d < D; d++) xc[d] = g->lo[d] + (gi[d] - 0.5) * g->dx;
            for (int c = 0; c < s->ncol; c++) {
                double nrm[3] = {0, 0, 0};
                if (!collider_near(&s->cols[c], xc) || collider_sdf(&s->cols[c], xc, nrm) >= 2 * g->dx) continue;
                double gn = 0;
                for (int d = 0; d < D; d++) gn += gr[d] * nrm[d];
                for (int d = 0; d < D; d++) gr[d] -= gn * nrm[d];
            }
            for (int d = 0; d < D; d++) node[GCH[d] * NPB + l] = gr[d];
            node[CH_R * NPB + l] = msum;
        }
    }
    /* 3. each cell's area: its gradient along the normal n of the gradient averaged
     * over the 3^dim cells around it, grad psi . n dx^dim. Taking |grad psi| counts
     * the staircase a lattice-seeded curve leaves in psi (the tangential ripple adds
     * to the length in second order, a fixed fraction at every dx: +0.9% on a disc);
     * along a smoother normal the ripple cancels in first order. Then CH_R holds the
     * cell's area over the mass of its corners. */
#pragma omp parallel for schedule(dynamic, 4) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        unsigned char any = 0;
        if (!near[k]) {
            s->boundary.blocks[k] = 0;
            continue;
        }
        const double *ring[27];
        block_ring(g, bc, ring);
        for (int l = 0; l < NPB; l++) {
            const double msum = node[CH_R * NPB + l];
            if (!(msum > 0)) continue;
            double gr[3] = {0, 0, 0}, nv[3] = {0, 0, 0};
            for (int d = 0; d < D; d++) gr[d] = node[GCH[d] * NPB + l];
            if (gr[0] == 0 && gr[1] == 0 && gr[2] == 0) {
                node[CH_R * NPB + l] = 0;
                continue;
            }
            int gi[3];
            grid_node_index(g, bc, l, gi);
            for (int a = -1; a <= 1; a++)
                for (int b = -1; b <= 1; b++)
                    for (int c = -1; c <= (D == 3 ? 1 : -1); c++) {
                        const int off[3] = {a, b, D == 3 ? c : 0};
                        int lj;
                        const double *nj = node_off(g, node, ring, l, gi, off, &lj);
                        if (!nj) continue;
                        for (int d = 0; d < D; d++) nv[d] += nj[GCH[d] * NPB + lj];
                    }
            double nn2 = 0, gn = 0;
            for (int d = 0; d < D; d++) nn2 += nv[d] * nv[d];
            for (int d = 0; d < D; d++) gn += gr[d] * nv[d];
            gn = nn2 > 0 ? gn / sqrt(nn2) : 0.0;
            /* grad psi . n dx^dim = gr . n dx^(dim-1) */
            node[CH_R * NPB + l] = gn > 0 ? gn * (D == 2 ? g->dx : g->dx * g->dx) / msum : 0.0;
            any |= gn > 0;
        }
        s->boundary.blocks[k] = any; /* a cell of this block holds area */
    }
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        near[k] = (unsigned char)any_flag(g, s->boundary.blocks, bc, 0); /* its nodes' cells reach +1 blocks */
    }
    /* 4. r_i = sum over the node's cells of (area / corner mass), in CH_CG_P; the
     * blocks that hold any */
#pragma omp parallel for schedule(dynamic, 4) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        unsigned char any = 0;
        const double *ring[27] = {NULL};
        if (near[k]) block_ring(g, bc, ring);
        for (int l = 0; l < NPB && near[k]; l++) {
            double r = 0;
            if (node[CH_M * NPB + l] > 0) {
                int gi[3];
                grid_node_index(g, bc, l, gi);
                for (int c = 0; c < NC; c++) {
                    int off[3] = {0, 0, 0}, lj;
                    for (int d = 0; d < D; d++) off[d] = (c >> d) & 1;
                    const double *nj = node_off(g, node, ring, l, gi, off, &lj);
                    if (nj) r += nj[CH_R * NPB + lj];
                }
            }
            node[CH_CG_P * NPB + l] = r;
            any |= r > 0;
        }
        if (!near[k]) memset(node + CH_CG_P * NPB, 0, sizeof(double) * (size_t)NPB);
        s->boundary.blocks[k] = any;
    }
    /* 5. each particle's share m_p sum_i w_ip r_i: the shares of a cell's area sum to it */
#pragma omp parallel for schedule(dynamic, 2) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < m->npb; k++) area_gather(s, k, want_depth);
    return HEARTH_OK;
}
