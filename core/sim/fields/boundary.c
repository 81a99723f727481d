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
 * With an oven or evaporation, each particle holding area also gets the depth
 * of its temperature and saturation sample below the surface (sample_depth,
 * below), which thermal.c divides out of the Robin flux and transport.c out of
 * the evaporation.
 *
 * Cost: the node volumes come from P2G, one more tile channel when heat or
 * water is live (a separate scatter pass cost more: issue #17's follow-up);
 * then node passes when an oven or evaporation is live; the particle gather runs only where
 * a particle block's tile holds surface; the depth is one more interpolation
 * and a table lookup for particles holding area. `robin_square_rotations`,
 * `robin_disc_converges`, `robin_ball_converges` (tests/unit_heat.c) check it. */
#include "boundary.h"

#include <math.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "scene.h"
#include "mpm.h"
#include "thermal.h"

#define FORCE_INLINE static inline __attribute__((always_inline))

void boundary_init(boundary_state *b) { *b = (boundary_state){0}; }

void boundary_free(boundary_state *b) {
    mem_free(b->area, sizeof(double) * (size_t)b->area_cap);
    mem_free(b->depth, sizeof(double) * (size_t)b->area_cap);
    mem_free(b->blocks, (size_t)b->blocks_cap);
    boundary_init(b);
}

int boundary_needed(const hearth_scene *s) {
    if (thermal_oven_on(&s->def)) return 1;
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

/* The storage of the 3^dim blocks around block bc, the block itself among
 * them, indexed ((a+1) 3 + b+1) 3 + c+1 for the offset (a, b, c) (no c in
 * 2D); NULL past the grid or where a block has no storage. Looked up once a
 * block, so a node's neighbours across the block's faces cost an index. */
FORCE_INLINE void block_ring(const grid *g, const int D, const int bc[3], const double *ring[27]) {
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
 * index, or NULL past the grid or in a block without storage (empty air).
 * D is a compile-time constant of each caller's instantiation and node
 * indices are never negative, so the loops unroll and gi % GRID_B is a mask. */
FORCE_INLINE const double *node_off(const grid *g, const int D, const double *node, const double *const ring[27], int l,
                                    const int gi[3], const int off[3], int *lj) {
    int in = 1, step = 0;
    for (int d = 0; d < D; d++) {
        const int c = (gi[d] & (GRID_B - 1)) + off[d];
        in &= c >= 0 && c < GRID_B;
        step = step * GRID_B + off[d];
    }
    if (in) {
        *lj = l + step;
        return node;
    }
    int r = 0, lo = 0;
    for (int d = 0; d < D; d++) {
        const int n = gi[d] + off[d];
        if (n < 0 || n > g->nn[d] - 1) return NULL;
        const int c = (gi[d] & (GRID_B - 1)) + off[d], o = c < 0 ? -1 : c >= GRID_B ? 1 : 0;
        r = r * 3 + o + 1;
        lo = lo * GRID_B + c - o * GRID_B;
    }
    *lj = lo;
    return ring[r];
}

/* The window of nodes lo..lo+n-1 (lo -1 or 0, n <= GRID_B + 2) along each axis
 * from block bc's origin node, x-major as a block's nodes: each one's storage
 * and local index as node_off finds them (NULL past the grid or in a block
 * without storage). cell_gradient reads a block's corners from it: looked up
 * once a block instead of once per node and corner (each node is a corner of
 * 2^dim cells), with the same values, so the same bits (0.05M of the 2D
 * dough's 18.1M instructions a step). cell_area and node_share look their
 * neighbours up lazily: most of their nodes stop before reading any (no mass,
 * no gradient), and a window cost them more than it saved. */
#define WIN_MAX ((GRID_B + 2) * (GRID_B + 2) * (GRID_B + 2))
FORCE_INLINE void window(const grid *g, const int D, const int bc[3], const double *const ring[27], int lo, int n,
                         const double *wn[WIN_MAX], int wl[WIN_MAX]) {
    int j = 0;
    for (int a = lo; a < lo + n; a++)
        for (int b = lo; b < lo + n; b++)
            for (int c = D == 3 ? lo : 0; c < (D == 3 ? lo + n : 1); c++, j++) {
                const int o[3] = {a, b, c};
                int r = 0, l = 0, past = 0, in = 1;
                for (int d = 0; d < D; d++) {
                    const int gi = bc[d] * GRID_B + o[d], s = o[d] < 0 ? -1 : o[d] >= GRID_B ? 1 : 0;
                    past |= gi < 0 || gi > g->nn[d] - 1;
                    in &= s == 0;
                    r = r * 3 + s + 1;
                    l = l * GRID_B + o[d] - s * GRID_B;
                }
                wn[j] = in ? ring[r] : past ? NULL : ring[r]; /* node_off: the block's own nodes are never past */
                wl[j] = l;
            }
}

/* Channel ch of node gi, 0 where the node has no storage (and past the grid). */
static double node_value(const grid *g, const int gi[3], int ch) {
    int l;
    const double *node = grid_node_at(g, gi, &l);
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

/* fmin(1.0, fmax(0.0, x)) without the two libm calls (without -ffinite-math-only
 * the compiler keeps them calls): the same value for every x, NaN (0) and -0.0
 * (kept, as glibc's fmax(0.0, -0.0) keeps it) included. */
static inline double clamp01(double x) {
    const double y = x >= 0.0 ? x : 0.0;
    return y > 1.0 ? 1.0 : y;
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
 * fraction is P(t), the quadratic B-spline N's integral up to t, and the mass
 * weighted mean depth of its material is E(t) = t - G(t) / P(t), G the kernel's
 * first moment up to t. A particle at depth t_p reads phi_p = sum_i w_ip P(t_i)
 * and samples the temperature at d_p = sum_i w_ip E(t_i), t_i = t_p - n . (x_i -
 * x_p). Both depend on the particle's offset to the nodes; D_OF_PHI holds d_p
 * against phi_p averaged over the offset (axis-aligned: both sums over the three
 * nodes of one axis, averaged over 200 offsets for each t_p in [-1.5, 2.5] by
 * 0.005, then d_p read at phi_p = k / 64), so a particle costs its phi_p and a
 * table lookup. Against the per-offset value it is within 0.023 dx for the
 * outer row (a quarter cell in), 0.034 dx for the next; on a curved surface the
 * offsets vary and the errors largely average out (the disc's errors move by at
 * most 0.0011 against the per-offset root, all of the same sign).
 * Rejected: solving sum_i w_ip P(t_p + delta_i) = phi_p per particle and summing
 * E over the stencil (within 0.015 dx of the discrete lattice, but in the 3D
 * bench it cost 2.7 no-field steps with a full Newton solve, 0.72 with one
 * step from a tabled guess, against 0.07 for the table); (phi_p - 1/2) / |grad phi| (phi is not linear across the
 * ramp: 20% long at half a cell, and it misses the nodes' averaging, 0.3 dx at
 * the outer row); a scatter of the particles' first moment (exact for any
 * arrangement but three more channels and a colour pass each step). */
static const double D_OF_PHI[65] = { /* d_p (grid units) at phi_p = k / 64 */
    0.050830, 0.050830, 0.077850, 0.099507, 0.118196, 0.134954, 0.150332, 0.164670,
    0.178204, 0.191103, 0.203494, 0.215476, 0.227129, 0.238515, 0.249688, 0.260692,
    0.271567, 0.282346, 0.293059, 0.303734, 0.314395, 0.325066, 0.335769, 0.346524,
    0.357352, 0.368272, 0.379305, 0.390470, 0.401787, 0.413277, 0.424961, 0.436860,
    0.448996, 0.461397, 0.474085, 0.487087, 0.500435, 0.514160, 0.528293, 0.542873,
    0.557941, 0.573541, 0.589725, 0.606548, 0.624073, 0.642373, 0.661533, 0.681647,
    0.702828, 0.725207, 0.748943, 0.774229, 0.801295, 0.830436, 0.862018, 0.896519,
    0.934578, 0.977076, 1.025267, 1.081051, 1.147522, 1.230272, 1.341284, 1.516325,
    2.500028};

/* d_p (grid units) at the particle's interpolated volume fraction phi_p. */
static inline double sample_depth(double phi) {
    const double u = clamp01(phi) * 64.0;
    const int k = u >= 64.0 ? 63 : (int)u;
    return D_OF_PHI[k] + (u - k) * (D_OF_PHI[k + 1] - D_OF_PHI[k]);
}

/* The clipped volume fraction psi = (phi - PHI_LO) / (PHI_HI - PHI_LO) in [0, 1]:
 * its gradient's integral is the mean perimeter of phi's level sets between
 * the two, and the clip keeps the noise of a disordered interior (phi within
 * 1 - PHI_HI of one) from counting as surface. */
#define PHI_LO 0.2
#define PHI_HI 0.8
static inline double clip_psi(double phi) { return clamp01((phi - PHI_LO) / (PHI_HI - PHI_LO)); }

/* sum_i w_ip f_i over a particle's 3^D stencil, f a tile's nodes copied out
 * (GRID_T to a side, lb the stencil's lowest node in the tile): the weights a
 * tensor product, one axis at a time. area_gather's, for r and for phi. The
 * stencil's nodes stand at fixed offsets from its lowest one (o). */
FORCE_INLINE double tile_interp(const int D, const double *f, const int lb[3], double w[3][3]) {
    const double *o = D == 2 ? f + lb[0] * GRID_T + lb[1] : f + (lb[0] * GRID_T + lb[1]) * GRID_T + lb[2];
    double sum = 0;
    for (int x = 0; x < 3; x++)
        for (int y = 0; y < 3; y++) {
            const double wxy = w[0][x] * w[1][y];
            if (D == 2) {
                sum += wxy * o[x * GRID_T + y];
            } else {
                const double *row = o + (x * GRID_T + y) * GRID_T;
                sum += wxy * (w[2][0] * row[0] + w[2][1] * row[1] + w[2][2] * row[2]);
            }
        }
    return sum;
}

/* Each particle's area m_p sum_i w_ip r_i from CH_CG_P, one particle block at
 * a time, and with an oven or evaporation the depth of its sample from the volume
 * fraction phi in CH_CG_R. Only blocks whose tile holds area are gathered: the
 * interior of a large body is skipped. */
FORCE_INLINE void area_gather(hearth_scene *s, const int D, int k, int want_depth) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    const pblock pb = mpm_state_of(s)->pb[k];
    int bc[3];
    grid_block_coords(g, pb.block, bc);
    int any = 0; /* does the tile (block and +1 neighbours) hold area? */
    for (int a = 0; a <= 1 && !any; a++)
        for (int b = 0; b <= 1 && !any; b++)
            for (int c = 0; c <= (D == 3) && !any; c++) any = s->boundary.blocks[g->slot[grid_block_id(g, bc[0] + a, bc[1] + b, bc[2] + c)]];
    if (!any) return; /* most particle blocks lie inside the body */
    double r[GRID_T * GRID_T * GRID_T], ph[GRID_T * GRID_T * GRID_T];
    /* the box of the tile's nodes with r != 0 (NaN counts): most particles of a
     * surface block sit inside, where r is 0 on their whole stencil */
    int rlo[3] = {GRID_T, GRID_T, D == 3 ? GRID_T : 0}, rhi[3] = {-1, -1, 0};
    for (int a = 0; a < GRID_T; a++)
        for (int b = 0; b < GRID_T; b++)
            for (int c = 0; c < (D == 3 ? GRID_T : 1); c++) {
                int l;
                const double *node = grid_tile_node(g, D, bc, a, b, c, &l);
                const int t = D == 2 ? a * GRID_T + b : (a * GRID_T + b) * GRID_T + c;
                r[t] = node[CH_CG_P * NPB + l];
                ph[t] = node[CH_CG_R * NPB + l];
                if (r[t] != 0.0) {
                    const int at[3] = {a, b, c};
                    for (int d = 0; d < D; d++) {
                        rlo[d] = at[d] < rlo[d] ? at[d] : rlo[d];
                        rhi[d] = at[d] > rhi[d] ? at[d] : rhi[d];
                    }
                }
            }
    if (rhi[0] < 0) return; /* r is 0 over the whole tile */
    const double *X = pcold(&s->ps, PC_X), *M = pcold(&s->ps, PC_MASS);
    int *flags = s->ps.enabled & (1u << PC_FLAGS) ? pcoli(&s->ps, PC_FLAGS) : NULL;
    for (int i = pb.start; i < pb.end; i++) { /* the weights are a tensor product: one axis at a time */
        int lb[3] = {0, 0, 0}, miss = 0;
        double Xd[3];
        for (int d = 0; d < D; d++) {
            Xd[d] = (X[3 * i + d] - g->lo[d]) * g->inv_dx;
            lb[d] = base_node(Xd[d]) - bc[d] * GRID_B; /* floor: the sort keeps X >= 1 (mpm.h) */
            miss |= lb[d] + 2 < rlo[d] || lb[d] > rhi[d];
        }
        /* r is 0 on the whole stencil: the sum below would be 0 (r >= 0 and
         * finite where it is not 0), and the particle holds no area */
        if (miss) continue;
        double w[3][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, dw[3];
        for (int d = 0; d < D; d++) bspline_weights(Xd[d] - (lb[d] + bc[d] * GRID_B), w[d], dw);
        const double a = tile_interp(D, r, lb, w);
        if (!(a > 0)) continue;
        s->boundary.area[i] = M[i] * a;
        if (flags) flags[i] |= PF_BOUNDARY;
        if (!want_depth) continue;
        const double phi = tile_interp(D, ph, lb, w); /* the interpolated volume fraction */
        s->boundary.depth[i] = sample_depth(phi) * g->dx;
    }
}

/* 2. each cell's gradient of psi (grid units), from the multilinear
 * interpolant at its centre, in CH_CG_P, CH_B, CH_T0 of its upper corner, and
 * the mass of its corners in CH_R: a node with mass has its +1 neighbours in
 * storage (they are in its particles' tiles), so every cell with mass has its
 * upper corner stored, while a lower corner may be empty air. These channels
 * are scratch until thermal_prepare fills them. Block k; near: its flag. */
FORCE_INLINE void cell_gradient(hearth_scene *s, const int D, int k, int near) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block, NC = 1 << D, GCH[3] = {CH_CG_P, CH_B, CH_T0};
    double *node = grid_block(g, k);
    int bc[3];
    grid_block_coords(g, g->active[k], bc);
    for (int d = 0; d < D; d++) memset(node + GCH[d] * NPB, 0, sizeof(double) * (size_t)NPB);
    memset(node + CH_R * NPB, 0, sizeof(double) * (size_t)NPB);
    if (!near) return;
    const double *ring[27], *wn[WIN_MAX];
    int wl[WIN_MAX];
    block_ring(g, D, bc, ring);
    /* the block's nodes and their -1 neighbours: psi and mass once each */
    const int WN = GRID_B + 1, NW = D == 3 ? WN * WN * WN : WN * WN;
    window(g, D, bc, ring, -1, WN, wn, wl);
    double wpsi[WIN_MAX], wm[WIN_MAX];
    for (int j = 0; j < NW; j++) {
        wpsi[j] = wn[j] ? clip_psi(wn[j][CH_CG_R * NPB + wl[j]]) : 0.0;
        wm[j] = wn[j] ? wn[j][CH_M * NPB + wl[j]] : 0.0;
    }
    for (int l = 0; l < NPB; l++) {
        int gi[3];
        grid_node_index_d(D, bc, l, gi);
        int inside = 1;
        for (int d = 0; d < D; d++) inside &= gi[d] >= 1;
        if (!inside) continue; /* no cell below the grid's first node */
        double psi[8], msum = 0;
        for (int c = 0; c < NC; c++) {
            int j = 0; /* the corner's window index: local coordinate + offset (-1 or 0) + 1 */
            for (int d = 0; d < D; d++) j = j * WN + (gi[d] & (GRID_B - 1)) + ((c >> d) & 1);
            psi[c] = wpsi[j];
            msum += wm[j];
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
            const int w = mpm_ranks_fields_wall(s, d, ej); /* MPI slabs: the end layer may lie past the rank's halo */
            if (w > 0 || (w < 0 && node_value(g, ej, CH_M) > 0)) gr[d] = 0;
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
 * cell's area over the mass of its corners. Returns whether a cell of block k
 * holds area. */
FORCE_INLINE unsigned char cell_area(hearth_scene *s, const int D, int k) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block, GCH[3] = {CH_CG_P, CH_B, CH_T0};
    double *node = grid_block(g, k);
    int bc[3];
    grid_block_coords(g, g->active[k], bc);
    unsigned char any = 0;
    const double *ring[27];
    block_ring(g, D, bc, ring);
    for (int l = 0; l < NPB; l++) {
        const double msum = node[CH_R * NPB + l];
        if (!(msum > 0)) continue;
        double gr[3] = {0, 0, 0}, nv[3] = {0, 0, 0}, na = 0;
        for (int d = 0; d < D; d++) gr[d] = node[GCH[d] * NPB + l];
        if (gr[0] == 0 && gr[1] == 0 && gr[2] == 0) {
            node[CH_R * NPB + l] = 0;
            continue;
        }
        int gi[3];
        grid_node_index_d(D, bc, l, gi);
        for (int a = -1; a <= 1; a++)
            for (int b = -1; b <= 1; b++)
                for (int c = -1; c <= (D == 3 ? 1 : -1); c++) {
                    const int off[3] = {a, b, D == 3 ? c : 0};
                    int lj;
                    const double *nj = node_off(g, D, node, ring, l, gi, off, &lj);
                    if (!nj) continue;
                    for (int d = 0; d < D; d++) nv[d] += nj[GCH[d] * NPB + lj], na += fabs(nj[GCH[d] * NPB + lj]);
                }
        double nn2 = 0, gn = 0;
        for (int d = 0; d < D; d++) nn2 += nv[d] * nv[d];
        for (int d = 0; d < D; d++) gn += gr[d] * nv[d];
        /* a sum that cancels to round-off has no direction: along a contact face
         * (the collider took the normal components) the tangential gradients of
         * the cells around cancel to 1e-16 of their size, and their sign, which
         * an ulp decides, gave a cell the whole of |grad psi| as area or none
         * (two MPI slab runs, whose seams sum P2G in another order, differed by
         * 1e-7 in temperature) */
        gn = nn2 > 1e-20 * na * na ? gn / sqrt(nn2) : 0.0;
        /* grad psi . n dx^dim = gr . n dx^(dim-1) */
        node[CH_R * NPB + l] = gn > 0 ? gn * (D == 2 ? g->dx : g->dx * g->dx) / msum : 0.0;
        any |= gn > 0;
    }
    return any;
}

/* 4. r_i = sum over the node's cells of (area / corner mass), in CH_CG_P, for
 * block k (near: a block within reach holds area). Returns whether any r_i > 0. */
FORCE_INLINE unsigned char node_share(hearth_scene *s, const int D, int k, int near) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block, NC = 1 << D;
    double *node = grid_block(g, k);
    if (!near) {
        memset(node + CH_CG_P * NPB, 0, sizeof(double) * (size_t)NPB);
        return 0;
    }
    int bc[3];
    grid_block_coords(g, g->active[k], bc);
    unsigned char any = 0;
    const double *ring[27];
    block_ring(g, D, bc, ring);
    for (int l = 0; l < NPB; l++) {
        double r = 0;
        if (node[CH_M * NPB + l] > 0) {
            int gi[3];
            grid_node_index_d(D, bc, l, gi);
            for (int c = 0; c < NC; c++) {
                int off[3] = {0, 0, 0}, lj;
                for (int d = 0; d < D; d++) off[d] = (c >> d) & 1;
                const double *nj = node_off(g, D, node, ring, l, gi, off, &lj);
                if (nj) r += nj[CH_R * NPB + lj];
            }
        }
        node[CH_CG_P * NPB + l] = r;
        any |= r > 0;
    }
    return any;
}

/* The passes of each dimension: D a compile-time constant in each (as in
 * mpm.c and transport.c), so the stencil loops unroll. */
static void cell_gradient_2(hearth_scene *s, int k, int near) { cell_gradient(s, 2, k, near); }
static void cell_gradient_3(hearth_scene *s, int k, int near) { cell_gradient(s, 3, k, near); }
static unsigned char cell_area_2(hearth_scene *s, int k) { return cell_area(s, 2, k); }
static unsigned char cell_area_3(hearth_scene *s, int k) { return cell_area(s, 3, k); }
static unsigned char node_share_2(hearth_scene *s, int k, int near) { return node_share(s, 2, k, near); }
static unsigned char node_share_3(hearth_scene *s, int k, int near) { return node_share(s, 3, k, near); }
static void area_gather_2(hearth_scene *s, int k, int want_depth) { area_gather(s, 2, k, want_depth); }
static void area_gather_3(hearth_scene *s, int k, int want_depth) { area_gather(s, 3, k, want_depth); }

hearth_status boundary_find(hearth_scene *s, hearth_error *err) {
    hearth_status st = ensure_area(s, err);
    if (st) return st;
    grid *g = &s->g;
    particles *ps = &s->ps;
    const int D = g->dim, NPB = g->nodes_per_block, n = ps->n, d3 = D == 3;
    double *area = s->boundary.area, *depth = s->boundary.depth;
    int *flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) { /* one pass, in parallel: run serially it was most of the fields' serial share */
        area[i] = depth[i] = 0.0;
        if (flags) flags[i] &= ~PF_BOUNDARY;
    }
    if (!boundary_needed(s)) return HEARTH_OK;
    const mpm_state *m = mpm_state_of(s); /* the sort's particle blocks */
    /* the depth of the samples serves the oven's Robin term and evaporation
     * (transport.c: the node saturation averages by capacity, rho_0^w V, as the
     * temperature does by heat capacity, so a uniform material's samples lie at
     * the same depth) */
    int want_depth = thermal_oven_on(&s->def) && (ps->enabled & (1u << PC_TEMPERATURE));
    for (int q = 0; q < s->mats.n && !want_depth; q++)
        want_depth = s->mats.slot[q].core[CP_EVAPORATION] > 0 && (ps->enabled & (1u << PC_WATER));

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
    /* 2. the cells' gradients */
#pragma omp parallel for schedule(dynamic, 4) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) (d3 ? cell_gradient_3 : cell_gradient_2)(s, k, near[k]);
    /* 3. the cells' areas; a block flags whether a cell of it holds area */
#pragma omp parallel for schedule(dynamic, 4) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) s->boundary.blocks[k] = near[k] ? (d3 ? cell_area_3 : cell_area_2)(s, k) : 0;
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        near[k] = (unsigned char)any_flag(g, s->boundary.blocks, bc, 0); /* its nodes' cells reach +1 blocks */
    }
    /* 4. the nodes' shares r_i; the blocks that hold any */
#pragma omp parallel for schedule(dynamic, 4) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) s->boundary.blocks[k] = (d3 ? node_share_3 : node_share_2)(s, k, near[k]);
    /* MPI slabs: a halo layer's flags near its outer face read blocks this rank
     * does not hold; the particles' gather (5.) goes by them, so the owners'
     * (thermal.c's small-node merge no longer does: it finds small nodes by
     * their own phi) */
    if ((st = mpm_ranks_fields_fill_flags(s, s->boundary.blocks, err))) return st;
    /* 5. each particle's share m_p sum_i w_ip r_i: the shares of a cell's area sum to it */
#pragma omp parallel for schedule(dynamic, 2) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < m->npb; k++) (d3 ? area_gather_3 : area_gather_2)(s, k, want_depth);
    return HEARTH_OK;
}
