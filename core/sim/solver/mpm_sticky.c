/* mpm_sticky.c: sticky colliders supply their reaction (issue #17).
 *
 * A sticky face holds the nodes on and inside it at its velocity. Two things
 * a wall needs were missing from that, and both are here: P2G gives each
 * particle within 1.5 dx outside a sticky face a mirror that carries its
 * stress (the weak form's boundary term for the free nodes whose B-spline
 * reaches into the collider: mpm_p2g_mirror), and after the grid update the
 * held nodes within 1.5 dx inside the face take the odd reflection of the
 * free velocity (mpm_sticky_ghosts_block), so the velocity field is linear
 * through the wall. Each alone left the particle row 0.75 dx above a floor
 * about 9% over; together the base stress of a settled column converges at
 * first order (`column_base_stress`, docs/validation.md). A face just off
 * a node row leaves a free node almost on it, whose own stress the mirrors
 * cancel: the face also holds the nodes up to STICKY_NEAR_BAND (0.3) dx
 * outside it, each at the velocity linear from the face (colliders.h), and
 * the held nodes under half a cell inside take that linear velocity too
 * ("The sticky face's clamp" in docs/validation.md). Only scenes with
 * a sticky collider run any of this (mpm.c instantiates P2G with and
 * without mirrors). */
#include "mpm_sticky.h"

#include <math.h>
#include <string.h>

#include "colliders.h"

/* 1 when the point p lies on or inside collider cl, or where no particle can
 * be (outside the box's usable region on a closed axis). A reflection through
 * a sticky face is used only when the collider goes on that deep behind the
 * reflected point's reach: a thin sticky blade with material on both sides
 * keeps holding its nodes at its velocity, or the far side's particles would
 * read, and receive, the near side's reflection. */
static int solid_behind(const hearth_scene *s, const collider *cl, const double p[3]) {
    const grid *g = &s->g;
    for (int d = 0; d < g->dim; d++)
        if (!s->def.periodic[d] && (p[d] < g->lo[d] + g->dx || p[d] > g->lo[d] + (g->nn[d] - 2) * g->dx)) return 1;
    return collider_sdf(cl, p, NULL) <= COLLIDER_ROW_TOL * g->dx;
}

/* The quadratic B-spline N(r) of a distance r in cells (the weight of a node r cells away). */
static inline double bspline_at(double r) {
    r = fabs(r);
    return r < 0.5 ? 0.75 - r * r : r < 1.5 ? 0.5 * (1.5 - r) * (1.5 - r) : 0.0;
}

/* The reaction of sticky colliders on the free nodes next to their faces.
 * A node within 1.5 dx of a face has part of its B-spline support inside the
 * collider, where there is no material; its equation then needs the weak
 * form's boundary term (the face's traction times the node's weight there,
 * 1/8 for the first node row above a face on a row), and the grid update,
 * which only holds the nodes on and inside the face, drops it. The material
 * next to the face then made up the missing force: the particle row 0.75 dx
 * above a sticky floor carried 18% too much stress at every dx, and the base
 * stress of a settled column overshot more as dx shrank
 * (`column_base_stress`). Each particle within 1.5 dx outside a sticky face
 * gets a mirror particle reflected through the face, with its Kirchhoff
 * stress and volume and no mass or momentum, whose stress force goes to the
 * particle's own stencil nodes (evenly extended stress: the traction term is
 * exact for a stress constant near the face, and first order in dx beyond).
 * For a face on a node row the mirrors fill exactly the lattice sites the
 * collider cuts away, so the first free row sees the stencil of an interior
 * node. The nodes on and inside the face receive mirror force too, which
 * does nothing: the grid update sets their velocity. Slip and separate
 * colliders supply no shear and may let go, and a grip holds material inside
 * it whose own stress reaches those nodes: none of them gets mirrors.
 * Rejected: mirroring in a pass after P2G (a mirror's stencil may leave the
 * particle's tile, so it would need tau stored per particle and a serial
 * scatter); restricting the mirror to the particle's stencil keeps it in the
 * tile, and for a face along a grid axis that stencil holds every free node
 * the mirror reaches. Only a scene with a sticky collider pays for this. */
void mpm_p2g_mirror(const hearth_scene *s, const int D, const double *x, const double *tau, double k0, int block,
                       double *tile) {
    const grid *g = &s->g;
    const int TN = D == 2 ? GRID_T * GRID_T : GRID_T * GRID_T * GRID_T;
    const double dx = g->dx, inv_dx = g->inv_dx;
    int base[3] = {0, 0, 0}, have_stencil = 0;
    double fx[3] = {0, 0, 0};
    for (int c = 0; c < s->ncol; c++) {
        const collider *cl = &s->cols[c];
        if (cl->mode != HEARTH_STICKY || !collider_near(cl, x)) continue;
        double n[3];
        const double phi = collider_sdf(cl, x, n);
        if (!(phi >= 0 && phi < 1.5 * dx)) continue;
        if (D == 2) n[2] = 0.0;
        const double deep[3] = {x[0] - (2 * phi + 1.5 * dx) * n[0], x[1] - (2 * phi + 1.5 * dx) * n[1],
                                x[2] - (2 * phi + 1.5 * dx) * n[2]}; /* the far end of the mirror's stencil */
        if (!solid_behind(s, cl, deep)) continue;
        if (!have_stencil) { /* the particle's stencil in its block's tile, as p2g_block found it (recomputed
                              * here, for the few particles near a face, so that p2g_block's stay in registers) */
            int bc[3];
            grid_block_coords(g, block, bc);
            for (int d = 0; d < D; d++) {
                const int b = (int)floor((x[d] - g->lo[d]) * inv_dx - 0.5);
                fx[d] = (x[d] - g->lo[d]) * inv_dx - b;
                base[d] = b - bc[d] * GRID_B;
            }
            have_stencil = 1;
        }
        /* node i relative to the mirror x - 2 phi n: (x_i - x) + 2 phi n, in cells */
        const double sh[3] = {2 * phi * n[0] * inv_dx, 2 * phi * n[1] * inv_dx, 2 * phi * n[2] * inv_dx};
        /* per axis: the mirror's weight of each stencil row, and the row's height over the face's
         * tangent plane at the particle (cells) */
        double wm[3][3], hn[3][3], ft[3][3][3]; /* ft[d][a]: -k0 tau's column d times the row's offset (m) */
        for (int d = 0; d < 3; d++)
            for (int a = 0; a < 3; a++) {
                const double rm = d < D ? a - fx[d] + sh[d] : 0.0;
                wm[d][a] = d < D ? bspline_at(rm) : (a == 0);
                hn[d][a] = d < D ? (a - fx[d]) * n[d] : 0.0;
                for (int q = 0; q < 3; q++) ft[d][a][q] = -k0 * tau[3 * q + d] * rm * dx;
            }
        /* only nodes on the free side of the tangent plane: the others are held (exactly so for a
         * flat face), and skipping them makes a particle's mirror a few nodes' work, not 27 */
        const double h0 = phi * inv_dx - COLLIDER_ROW_TOL;
        for (int a = 0; a < 3; a++) {
            if (wm[0][a] == 0.0) continue;
            for (int b = 0; b < 3; b++) {
                if (wm[1][b] == 0.0) continue;
                for (int cc = 0; cc < (D == 3 ? 3 : 1); cc++) {
                    const double w = wm[0][a] * wm[1][b] * wm[2][cc];
                    if (w == 0.0 || h0 + hn[0][a] + hn[1][b] + hn[2][cc] <= 0.0) continue;
                    const int t = D == 2 ? (base[0] + a) * GRID_T + (base[1] + b)
                                         : ((base[0] + a) * GRID_T + (base[1] + b)) * GRID_T + (base[2] + cc);
                    for (int q = 0; q < D; q++) tile[(q + 1) * TN + t] += w * (ft[0][a][q] + ft[1][b][q] + ft[2][cc][q]);
                }
            }
        }
    }
}

/* 1 when a particle of the block whose origin node is org may lie within
 * 1.5 dx outside a sticky face. Its particles lie within 2 dx of the block's
 * centre along each axis (their base node is one of the block's), and an SDF
 * changes no faster than the distance, so one SDF per block and collider
 * rules out the blocks far from every face: most of them, whose particles
 * then skip mpm_p2g_mirror's SDF (a plane's bounding box is everything). */
int mpm_block_near_sticky(const hearth_scene *s, const int D, const int org[3]) {
    const grid *g = &s->g;
    double c[3] = {0, 0, 0};
    for (int d = 0; d < D; d++) c[d] = g->lo[d] + (org[d] + 2.5) * g->dx;
    const double r = (D == 3 ? 1.7321 : 1.4143) * 2.0 * g->dx + 0.25 * g->dx; /* the half diagonal, with room */
    for (int k = 0; k < s->ncol; k++) {
        const collider *cl = &s->cols[k];
        if (cl->mode != HEARTH_STICKY) continue;
        const double phi = collider_sdf(cl, c, NULL);
        if (phi < r + 1.5 * g->dx && phi > -r) return 1;
    }
    return 0;
}

/* The first sticky collider that holds the point x (on or inside its face,
 * or within STICKY_NEAR_BAND dx outside it, as grid_update_block decides), or NULL; its velocity at x in vb, and its
 * sdf and outward normal there in *phi and n when asked. */
static const collider *sticky_held(const hearth_scene *s, const double x[3], double vb[3], double *phi, double n[3]) {
    for (int c = 0; c < s->ncol; c++) {
        const collider *cl = &s->cols[c];
        if (cl->mode != HEARTH_STICKY || !collider_near(cl, x)) continue;
        double nn[3];
        const double d = collider_sdf(cl, x, nn);
        if (d > collider_hold_band(cl) * s->g.dx) continue;
        collider_velocity_at(cl, x, vb);
        if (s->g.dim == 2) vb[2] = 0.0;
        if (phi) *phi = d;
        if (n) memcpy(n, nn, sizeof nn);
        return cl;
    }
    return NULL;
}

/* The grid velocity at x, multilinear in the 2^dim nodes around it, reading
 * a node marked for a ghost as its sticky collider's velocity (not the grid,
 * which mpm_sticky_ghosts_block may be writing; an unmarked held node holds that
 * velocity anyway) and leaving out nodes without mass. Returns 0 when no
 * node counts. */
static int grid_velocity_linear(const hearth_scene *s, const double x[3], double v[3]) {
    const grid *g = &s->g;
    const int D = g->dim, NPB = g->nodes_per_block;
    int b[3] = {0, 0, 0};
    double f[3] = {0, 0, 0}, sw = 0;
    for (int d = 0; d < D; d++) {
        const double X = (x[d] - g->lo[d]) * g->inv_dx;
        b[d] = (int)floor(X);
        f[d] = X - b[d];
    }
    v[0] = v[1] = v[2] = 0.0;
    for (int k = 0; k < (1 << D); k++) {
        int gi[3] = {0, 0, 0};
        double w = 1, xi[3] = {0, 0, 0};
        for (int d = 0; d < D; d++) {
            const int o = (k >> d) & 1;
            gi[d] = b[d] + o;
            w *= o ? f[d] : 1.0 - f[d];
            xi[d] = g->lo[d] + gi[d] * g->dx;
        }
        if (w == 0.0) continue;
        int inside = 1;
        for (int d = 0; d < D; d++) inside = inside && gi[d] >= 0 && gi[d] < g->nn[d];
        if (!inside) continue;
        double vn[3];
        const int bc[3] = {gi[0] / GRID_B, gi[1] / GRID_B, gi[2] / GRID_B};
        const int slot = g->slot[grid_block_id(g, bc[0], bc[1], bc[2])];
        if (slot < 0) continue;
        const int l = D == 2 ? (gi[0] % GRID_B) * GRID_B + gi[1] % GRID_B
                             : ((gi[0] % GRID_B) * GRID_B + gi[1] % GRID_B) * GRID_B + gi[2] % GRID_B;
        const double *node = grid_block(g, slot);
        if (node[l] == 0.0) continue;
        if (node[l] < 0.0) { /* marked: a node mpm_sticky_ghosts_block may be writing; held at v_b */
            if (!sticky_held(s, xi, vn, NULL, NULL)) continue;
        } else {
            for (int d = 0; d < 3; d++) vn[d] = node[(d + 1) * NPB + l];
        }
        for (int d = 0; d < 3; d++) v[d] += w * vn[d];
        sw += w;
    }
    if (!(sw > 0)) return 0;
    for (int d = 0; d < 3; d++) v[d] /= sw;
    return 1;
}

/* The held nodes within 1.5 dx inside a sticky face take the odd reflection
 * of the free velocity, v_i = 2 v_b - v(x_i - 2 phi_i n), instead of v_b
 * (ghost nodes), and those held just outside it (0 < phi_i <= STICKY_NEAR_BAND
 * dx, colliders.h) the velocity linear from the face's to the grid's a cell
 * further out, v_i = v_b + phi_i / (phi_i + dx) (v(x_i + dx n) - v_b): such a
 * node, left free, had no net force but its weight (the mirrors' even stress
 * cancels its own), and a column hanging from the face fell off; held at v_b
 * it clamped the body up to 0.3 dx inside the face (a thin blade's, with no
 * solid behind it, still is). A held node under half a cell inside the face
 * takes the same linear velocity, from a point 1.5 dx out, not the reflection,
 * whose point lies among held nodes read as v_b: there the body was held
 * 0.04-0.08 dx inside the face at every dx. A particle near the face reads them in G2P: a
 * velocity field linear through the wall then gives the particle its exact
 * velocity and gradient, where holding those nodes at v_b left the particle
 * 0.25 dx above a floor on a node row 16% short of its strain rate (its lowest node,
 * weight 1/32, a cell inside the floor, read 0 instead of -v of the first
 * free row), and the rows next to the floor settled to a wrong stress
 * (`column_base_stress`). Together with mpm_p2g_mirror's reaction this is the
 * mirror-particle treatment of a sticky face: stress extended evenly,
 * velocity oddly. Nothing but G2P reads these nodes after the grid update,
 * and the nodes it writes are never read here (held nodes are read as v_b),
 * so blocks may run in any order. Only a scene with a sticky collider runs it. */
void mpm_sticky_ghosts_block(const hearth_scene *s, int k) {
    const grid *g = &s->g;
    const int D = g->dim, NPB = g->nodes_per_block;
    double *node = grid_block(g, k);
    int bc[3];
    grid_block_coords(g, g->active[k], bc);
    for (int l = 0; l < NPB; l++) {
        if (!(node[l] < 0.0)) continue; /* marked by grid_update_block */
        int idx[3];
        grid_node_index(g, bc, l, idx);
        double xi[3] = {0, 0, 0}, vb[3], n[3], phi;
        for (int d = 0; d < D; d++) xi[d] = g->lo[d] + idx[d] * g->dx;
        const collider *cl = sticky_held(s, xi, vb, &phi, n);
        if (!cl || !(phi > -1.5 * g->dx)) continue;
        if (D == 2) n[2] = 0.0;
        const double deep[3] = {xi[0] - 1.5 * g->dx * n[0], xi[1] - 1.5 * g->dx * n[1], xi[2] - 1.5 * g->dx * n[2]};
        if (!solid_behind(s, cl, deep)) continue; /* a particle beyond the collider may read this node */
        /* the grid point this node's velocity is read from, `step` along n, and (not the reflection) the node's
         * share f of that point's velocity over the face's */
        double step, f = 0;
        int reflect = 0;
        if (phi > COLLIDER_ROW_TOL * g->dx) /* just outside the face (STICKY_NEAR_BAND): linear from it */
            step = g->dx, f = phi / (phi + g->dx);
        else if (phi > -0.5 * g->dx && phi < -COLLIDER_ROW_TOL * g->dx)
            /* under half a cell inside: the reflection x_i - 2 phi n would lie within half a cell of the face,
             * where the grid velocity reads this node itself and its held neighbours as v_b; the velocity linear
             * from the face to the grid 1.5 dx out, which only free nodes carry, instead (the same for a linear
             * field) */
            step = 1.5 * g->dx - phi, f = phi / (1.5 * g->dx);
        else
            step = -2 * phi, reflect = 1; /* the odd reflection */
        double xr[3] = {0, 0, 0}, vr[3];
        for (int d = 0; d < D; d++) xr[d] = xi[d] + step * n[d];
        if (!grid_velocity_linear(s, xr, vr)) continue;
        for (int d = 0; d < D; d++) node[(d + 1) * NPB + l] = reflect ? 2 * vb[d] - vr[d] : vb[d] + f * (vr[d] - vb[d]);
    }
}
