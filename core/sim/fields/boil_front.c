/* boil_front.c: the boiling front of latent_heat on MPM (issue #18), water_boil_front and its passes, out of
 * water.c (which keeps water_boil, the per-particle boiling SPH calls and G2P's test), so that water.c stays
 * about water's transport. The names keep water.h's prefix: water.h declares them. */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "water.h"

#include "alloc.h"
#include "error.h"
#include "grid.h"
#include "material.h"
#include "mpm.h"
#include "physics_constants.h"
#include "scene.h"

/* The boiling front (issue #18; MPM with latent_heat). Calling water_boil
 * in G2P, each particle boils the heat its own nodes hand it: every wet
 * particle within a stencil of the nodes the flux reaches boils at once, so
 * the zone at T_b is about two cells wide (1.85-2.29 dx) and the top dries
 * only when the whole layer has (docs/validation.md, "The drying front
 * against Stefan"). In a real Stefan front the wet layer at T_b has no
 * gradient and the heat is taken at its outer edge. So G2P leaves each wet
 * particle that passed T_b at T_b and its excess E_p = m_p c_p (T_p - T_b)
 * here (the heat water_boil would have boiled), and this pass hands each
 * node's share of it back to the node's boiling particles, the side the
 * heat comes from first:
 *   H_i = sum_p w_ip E_p,  G_i = sum_p w_ip g_p,
 *   Q_p = g_p sum_i w_ip H_i / G_i,  g_p = exp(K e_p),
 * e_p the particle's offset from node i along the node's temperature
 * gradient (front_pair), over the particles with water to boil. Sum_p Q_p =
 * sum_i H_i = sum_p E_p: exact, node by node. Q_p boils water down to the
 * floor (water_boil's dm = Q / L); what a particle's water cannot take goes
 * round again (front_pass, up to WATER_FRONT_PASSES passes) and what is left at
 * the end goes back to the particles that boiled it. K = 3: K 8 and 20 made
 * the front sharper but broke the slab's first order and its columns'
 * symmetry. Serial over nodes and particles in their order (the same bits
 * at any thread count; boil_front_threads_same_bits); MPI slabs sum the node
 * channels. It costs what the front needs (the frontspeed branch,
 * docs/performance.md "The boiling front's cost"), with the bits of the walk
 * over every wet particle: a step where nothing passed T_b returns at once;
 * on one rank a pass makes G_i and the gradient only where this pass's
 * senders reach and passes by the receivers whose stencil reaches no such
 * block (front_pass says why that changes no bit), and each pair's g and each
 * particle's stencil are made once a step (front_pair_of, front_stencil). MPI slabs keep the whole walk. Rejected (docs/validation.md, "A sharper boiling front" and its
 * sequel): ordering by dryness (exp(40 (1 - X/X_0))), which let one column
 * run ahead of its neighbours; the ordering only at nodes holding both a
 * dried and a wet particle, which dried the crumb slab 14.2% early. On its
 * own this pass overheated a wet block's last dried particles (a FLIP
 * sub-cell offset, +40 K, that G2P never damps); subcell.c's exchange
 * relaxes it, and the two run together.
 *
 * Continuous in the room (#18, helper frontroom). A particle's room is c_p = L (W_p - W_floor), the heat its
 * water can boil down to the floor (water_boil's cap: dm = min(E / L, spare)), 0 without spare. Three places
 * let a particle's part jump at c_p = 0, and each now goes to the no-room particle's as c_p -> 0:
 *   sender:   it sends s_p = min(E_p, c_p) and keeps E_p - s_p, so T_p = T_b + (E_p - s_p) / (m c)
 *             (this one already held: a particle without room sends nothing and keeps T_p);
 *   receiver: it weighs in G_i with g_p rho_p, rho_p = min(1, c_p / E_p) (c_p the room left at that pass),
 *             G_i = sum_p w_ip g_p rho_p and q_p = g_p rho_p sum_i w_ip H_i / G_i. Before, one ulp of room
 *             weighed as much as a full particle: it drew a full share of its nodes' H_i, took a ulp of it, and
 *             sent the rest again from its own place in the next pass;
 *   the rest: what the passes could not hand out goes back by w_ip s_p / sum_q w_iq s_q (front_return), not
 *             by w_ip E_p, which gave a dried particle's whole excess a say in its wet neighbours' heat.
 * A wet particle, whose room holds its own excess (c_p >= E_p), keeps rho_p = 1 and s_p = E_p exactly: its
 * numbers are the ones it had, so only nodes near a particle that could not boil its own excess move. On
 * MPI slabs a dried particle's spare of 0 or one ulp, by the rounding of its volume, now gives the same
 * answer to rounding (mpi_dough_dries_matches_one_rank; docs/validation.md, "The front's shares scale with
 * room"). The books stay exact: rho_p splits each H_i otherwise, not its sum (sum_p w_ip g_p rho_p H_i / G_i
 * = H_i over the node's receivers), so still sum_p (Q_p + kept_p) = sum_p E_p; Q_p <= c_p boils dm = Q_p / L
 * and kept_p is sensible heat: heat in = sensible + L x water boiled (latent_heat_boiling_energy_balance).
 * G2P's gas reads the same T_b + (E_p - s_p) / (m c) for a sender (mpm_g2p.c), not the T_b it leaves it at
 * until this pass: at T_b a dried particle with one ulp of spare made its CO2 at 100 degC and one with none at
 * its own temperature, and the slabs' velocities moved by 1e-8 through the gas's pressure. */
#define WATER_FRONT_K 3.0
#define WATER_FRONT_PASSES 8
#define FRONT_NS 7 /* scratch doubles a particle, before the pair weights (front_ng) */
enum { FRONT_H = CH_R, FRONT_G = CH_B }; /* dead after thermal_finish until the next P2G (grid.c) */

/* Stencil nodes a particle: the pair weights it keeps for the step (front_pair_of). */
static int front_ng(const grid *g) { return g->dim == 3 ? 27 : 9; }

/* The scratch's doubles: FRONT_NS a particle, its pair weights (front_ng), its stencil's weights (front_ng),
 * the stencil's nodes and count (front_ng + 1 ints: front_stencil), then a byte of marks per active grid block
 * (FB_*), in one allocation, so the front asks the allocator as often as it did before the stencil cache. */
static size_t front_ints(const hearth_scene *s) { return ((size_t)front_ng(&s->g) + 1) * (size_t)s->ps.n; }
static size_t front_need(const hearth_scene *s) {
    return (FRONT_NS + 2 * (size_t)front_ng(&s->g)) * (size_t)s->ps.n + (front_ints(s) * sizeof(int) + sizeof(double) - 1) / sizeof(double) +
           ((size_t)s->g.nactive + sizeof(double) - 1) / sizeof(double);
}

hearth_status water_boil_front_prepare(hearth_scene *s, hearth_error *err) {
    water_state *w = &s->water;
    if ((size_t)s->g.nactive * (size_t)s->g.nodes_per_block > (size_t)INT_MAX) /* front_stencil packs a node in an int */
        return err_set(err, HEARTH_ERR_NOMEM, "too many grid blocks for the boiling front's stencils (%d active)", s->g.nactive);
    const size_t need = front_need(s);
    if (need <= w->front_cap) return HEARTH_OK;
    double *f = mem_alloc(sizeof(double) * need);
    if (!f) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the boiling front's scratch (%d particles)", s->ps.n);
    mem_free(w->front, sizeof(double) * w->front_cap);
    w->front = f, w->front_cap = need;
    return HEARTH_OK;
}

/* The heat's direction at each node: a = dx grad T (K a cell) from the new
 * temperatures (CH_T, nodes with mass), central where both neighbours hold
 * mass, one-sided where one does; into FRONT_A (dead after G2P, as CH_R). */
static const int FRONT_A[3] = {CH_CG_R, CH_CG_P, CH_HC};

/* Block slot k's nodes. Only front_pair reads FRONT_A, at the nodes a sender reaches (front_mark), so the
 * blocks that hold none are skipped: nothing else reads these channels before the next step writes them. */
static void front_gradient(grid *g, int k) {
    const int D = g->dim, NPB = g->nodes_per_block;
    int bc[3];
    grid_block_coords(g, g->active[k], bc);
    double *d = grid_block(g, k);
    for (int l = 0; l < NPB; l++) {
        int gi[3];
        grid_node_index(g, bc, l, gi);
        for (int ax = 0; ax < D; ax++) {
            double a = 0;
            if (d[CH_M * NPB + l] > 0) {
                double Tn[2];
                int ok[2];
                for (int sgn = 0; sgn < 2; sgn++) {
                    int gj[3] = {gi[0], gi[1], gi[2]}, lj;
                    gj[ax] += sgn ? 1 : -1;
                    const double *nj = grid_node_at(g, gj, &lj);
                    ok[sgn] = nj && nj[CH_M * NPB + lj] > 0;
                    Tn[sgn] = ok[sgn] ? nj[CH_T * NPB + lj] : 0.0;
                }
                const double T = d[CH_T * NPB + l];
                a = ok[0] && ok[1] ? 0.5 * (Tn[1] - Tn[0]) : ok[1] ? Tn[1] - T : ok[0] ? T - Tn[0] : 0.0;
            }
            d[FRONT_A[ax] * NPB + l] = a;
        }
    }
}

/* The marks of an active grid block (a byte each, after the particles' scratch): FB_SENT, a sender of this
 * pass reaches one of its nodes; FB_GRAD, its FRONT_A holds this step's gradient. */
enum { FB_SENT = 1, FB_GRAD = 2 };

/* A sender reaches node (storage node): its block is marked, and its gradient made on first reach. */
static void front_mark(grid *g, unsigned char *fb, const double *node) {
    const int k = (int)((size_t)(node - g->data) / ((size_t)g->nch * (size_t)g->nodes_per_block));
    if (!(fb[k] & FB_GRAD)) front_gradient(g, k), fb[k] |= FB_GRAD;
    fb[k] |= FB_SENT;
}

/* Whether the stencil of point x (grid_point_weights' base, the same arithmetic) reaches a block marked
 * FB_SENT: a receiver that reaches none gets nothing this pass (below). */
static int front_near(const grid *g, const unsigned char *fb, const double *x) {
    int lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    for (int d = 0; d < g->dim; d++) {
        const int base = (int)floor((x[d] - g->lo[d]) * g->inv_dx - 0.5);
        const int a = base < 0 ? 0 : base, b = base + 2 > g->nn[d] - 1 ? g->nn[d] - 1 : base + 2;
        if (a > b) return 0;
        lo[d] = a / GRID_B, hi[d] = b / GRID_B;
    }
    for (int bx = lo[0]; bx <= hi[0]; bx++)
        for (int by = lo[1]; by <= hi[1]; by++)
            for (int bz = lo[2]; bz <= hi[2]; bz++) {
                const int k = g->slot[grid_block_id(g, bx, by, bz)];
                if (k >= 0 && (fb[k] & FB_SENT)) return 1;
            }
    return 0;
}

/* Particle p's weight on node i: exp(K e), e = ((x_p - x_i) / dx) . a / (|a| + A0), so that on a node the
 * heat comes to from one side, the particles on that side take it first; across a (1D) front they share
 * alike. A0 = 0.1 K a cell: a node inside the wet zone, flat at T_b, shares alike (its rounding's direction
 * is no direction). */
static double front_pair(const grid *g, const double *node, int l, const double *x, const int gi[3]) {
    const int NPB = g->nodes_per_block;
    double a2 = 0, e = 0;
    for (int d = 0; d < g->dim; d++) {
        const double a = node[FRONT_A[d] * NPB + l];
        a2 += a * a;
        e += (x[d] - (g->lo[d] + gi[d] * g->dx)) * g->inv_dx * a;
    }
    return exp(WATER_FRONT_K * e / (sqrt(a2) + 0.1));
}

/* A particle's stencil, made once a step (helper citime, docs/performance.md "Room in CI: the front's
 * stencils, a 2D box's bounds"): the passes and front_return walked grid_point_nodes_of afresh for every
 * sender and receiver in each of their loops (up to 3 a pass, 8 passes, then 2): with them, the front was 63%
 * of latent_heat_crumb_plateau's sampled time. It costs 9 doubles and 10 ints a particle in 2D (27 and 28 in
 * 3D) in the front's one scratch allocation.
 * The positions and the grid's storage hold from G2P to the front's end, so each walk found the same nodes and
 * weights: they are kept here in grid_point_nodes_of's order, the node as slot * nodes_per_block + l, and the
 * weights are its products, bit for bit. n[i] < 0: not made yet this step. */
typedef struct front_stencil {
    double *w; /* front_ng a particle */
    int *node; /* front_ng a particle: slot * nodes_per_block + l */
    int *n;    /* a particle: its nodes, -1 before it is made */
    int shift; /* log2 nodes_per_block (16 or 64): a node's slot and l by a shift and a mask, not a division */
} front_stencil;

/* Particle i's stencil made: grid_point_nodes_of's nodes and weights in its order. */
static __attribute__((noinline)) void front_nodes_make(const grid *g, const front_stencil *fs, int i, const double *x) {
    const int NG = front_ng(g), NPB = g->nodes_per_block;
    double *wi = fs->w + (size_t)NG * i;
    int *ni = fs->node + (size_t)NG * i;
    grid_point_nodes pn;
    grid_point_nodes_of(g, x, &pn);
    for (int j = 0; j < pn.n; j++) wi[j] = pn.w[j], ni[j] = pn.slot[j] * NPB + pn.l[j];
    fs->n[i] = pn.n;
}

/* Particle i's stencil nodes (their count; *w and *node its rows), made on the first ask of the step. */
static inline int front_nodes(const grid *g, const front_stencil *fs, int i, const double *x, const double **w, const int **node) {
    const int NG = front_ng(g);
    if (fs->n[i] < 0) front_nodes_make(g, fs, i, x);
    *w = fs->w + (size_t)NG * i, *node = fs->node + (size_t)NG * i;
    return fs->n[i];
}

/* Storage of a stencil node (front_stencil's packing) and its local index in *l. */
static inline double *front_node(const grid *g, const front_stencil *fs, int at, int *l) {
    *l = at & ((1 << fs->shift) - 1);
    return grid_block(g, at >> fs->shift);
}

/* front_pair of a particle's j-th stencil node (made: below). */
static __attribute__((noinline)) double front_pair_make(const grid *g, const front_stencil *fs, double *gp, const int *node,
                                                        int j, const double *x) {
    int l, gi[3] = {0, 0, 0};
    const double *nd = front_node(g, fs, node[j], &l);
    /* the node's grid coordinates: the stencil's base on each axis (grid_point_weights' arithmetic) and the
     * one of its 3 nodes whose local index is the node's (3 < GRID_B, so one does) */
    for (int d = 0; d < g->dim; d++) {
        const int base = (int)floor((x[d] - g->lo[d]) * g->inv_dx - 0.5);
        const int ld = g->dim == 2 ? (d ? l % GRID_B : l / GRID_B) : (d == 0 ? l / (GRID_B * GRID_B) : d == 1 ? (l / GRID_B) % GRID_B : l % GRID_B);
        gi[d] = base + (((ld - base) % GRID_B) + GRID_B) % GRID_B;
    }
    gp[j] = front_pair(g, nd, l, x, gi);
    return gp[j];
}

/* front_pair of a particle's j-th stencil node, made once a step: the positions and the gradient hold through
 * the passes, so it is the same number every pass asks for (0: not made yet; exp(K e) > 0). The node's grid
 * coordinates (front_pair_make) are grid_point_nodes_of's gi. */
static inline double front_pair_of(const grid *g, const front_stencil *fs, double *gp, const int *node, int j, const double *x) {
    return gp[j] > 0 ? gp[j] : front_pair_make(g, fs, gp, node, j, x);
}

/* The heat particle i's water can boil, L x its spare over the floor (water_boil's cap; 0 without spare): what
 * it may send (the rest of its E_p it keeps) and what it may take. W is the step's before the front boils. */
static double front_cap0(const hearth_scene *s, int i, const double *W, const double *vol) {
    const material_slot *ms = &s->mats.slot[pcoli(&s->ps, PC_MAT)[i]];
    return water_room(W[i] - water_floor(ms->core[CP_WATER_DENSITY], vol[i]));
}

/* A receiver's weight in G_i, its room against the excess it brought: rho_p = min(1, cap_p / E_p). 1 for a
 * particle whose water can boil its own excess (every wet one), so its share is the one it took before; it
 * falls to 0 with the room, so one ulp of room draws one ulp's share, not a full particle's (header). */
static double front_room(double cap, double E) { return cap >= E ? 1.0 : cap > 0 ? cap / E : 0.0; }

/* One pass of the hand-out: each particle's r_p (J) to the nodes, H_i = sum_p w_ip r_p, and back to the
 * receivers with room left (cap_p > 0), q_p = g_p sum_i w_ip H_i / G_i, G_i = sum_p w_ip g_p over them. A
 * receiver takes up to its room; what it cannot take is its r_p for the next pass. A node without receivers
 * hands its H_i back to the particles that sent it (w_ip r_p each) to send again (front_return hands out what
 * is left at the end: kept by the overflowing particle, the heat of a block's nodes ran into its last wet
 * particles); the weight of a node without storage stays with the sender (kept_p). Sum_p (q_p + kept_p) = sum_p r_p. Returns the heat still to
 * hand out.
 *
 * What it costs is the front's, not the body's: on one rank G_i is made only at the nodes a sender reaches
 * (the rest hold -1), and a receiver whose stencil reaches no block such a node lies in is passed by. The
 * bits are those of the walk over every node and particle, which MPI slabs keep (all: G sums over the
 * ranks with H, and a node's senders may sit on another rank): a node without senders has H_i = +0, so a
 * receiver's q gains +0 there whatever G_i is; its `back` only counts times r_p, +0 for a non-sender, and
 * a sender's nodes all hold G_i, summed over the same receivers in the same order; a passed-by receiver's
 * r, cap, Q, kept and the pass's sum `left` change by +0 (q = take = 0). */
static double front_pass(hearth_scene *s, const int chs[2], int all, unsigned char *fb, double *gc, const front_stencil *fs,
                         const double *E, double *r, double *cap, double *Q, double *kept, double *near, hearth_error *err,
                         hearth_status *st) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block, n = s->ps.n, NG = front_ng(g);
    const double *X = pcold(&s->ps, PC_X);
    for (int k = 0; k < g->nactive; k++) {
        double *d = grid_block(g, k);
        memset(d + chs[0] * NPB, 0, sizeof(double) * (size_t)NPB);
        if (all) {
            memset(d + chs[1] * NPB, 0, sizeof(double) * (size_t)NPB);
        } else {
            for (int l = 0; l < NPB; l++) d[chs[1] * NPB + l] = -1.0; /* no sender reaches it (yet) */
            fb[k] &= (unsigned char)~FB_SENT;
        }
    }
    /* the senders, then the receivers: each channel still sums its particles in their order */
    for (int i = 0; i < n; i++) {
        if (!(r[i] > 0)) continue;
        const double *w;
        const int *at;
        const int nn = front_nodes(g, fs, i, X + 3 * i, &w, &at);
        for (int j = 0; j < nn; j++) {
            int l;
            double *node = front_node(g, fs, at[j], &l);
            node[chs[0] * NPB + l] += w[j] * r[i];
            if (!all && node[chs[1] * NPB + l] < 0) node[chs[1] * NPB + l] = 0, front_mark(g, fb, node);
        }
    }
    for (int i = 0; i < n; i++) { /* near: the receivers walked, for the gather (cap and the marks hold till then) */
        if (!(cap[i] > 0)) continue;
        near[i] = all || front_near(g, fb, X + 3 * i);
        if (!(near[i] > 0)) continue;
        const double rho = front_room(cap[i], E[2 * i]);
        const double *w;
        const int *at;
        const int nn = front_nodes(g, fs, i, X + 3 * i, &w, &at);
        for (int j = 0; j < nn; j++) {
            int l;
            double *node = front_node(g, fs, at[j], &l);
            if (!(node[chs[1] * NPB + l] < 0)) node[chs[1] * NPB + l] += w[j] * (rho * front_pair_of(g, fs, gc + (size_t)NG * i, at, j, X + 3 * i));
        }
    }
    if ((*st = mpm_ranks_fields_sum(s, chs, 2, err))) return 0;
    double left = 0;
    for (int i = 0; i < n; i++) {
        if (!(r[i] > 0) && !(cap[i] > 0 && near[i] > 0)) continue;
        const double *w;
        const int *at;
        const int nn = front_nodes(g, fs, i, X + 3 * i, &w, &at);
        double q = 0, back = 0, none = 1; /* none: the weight on nodes without storage */
        const double rho = cap[i] > 0 ? front_room(cap[i], E[2 * i]) : 0.0;
        for (int j = 0; j < nn; j++) {
            int l;
            const double *node = front_node(g, fs, at[j], &l);
            const double wt = w[j];
            none -= wt;
            const double G = node[chs[1] * NPB + l];
            if (G > 0) {
                if (cap[i] > 0) q += wt * (rho * front_pair_of(g, fs, gc + (size_t)NG * i, at, j, X + 3 * i)) * node[chs[0] * NPB + l] / G;
            } else {
                back += wt;
            }
        }
        const double r0 = r[i] > 0 ? r[i] : 0.0;
        kept[i] += none * r0;
        q = cap[i] > 0 ? q : 0.0;
        const double take = q < cap[i] ? q : cap[i] > 0 ? cap[i] : 0.0;
        Q[i] += take;
        cap[i] -= take;
        r[i] = q - take + back * r0;
        left += r[i];
    }
    return left;
}

/* What particle i sent to the front, s_p = min(E_p, cap_p): the weight of its share of the rest below. */
static double front_sent(const hearth_scene *s, int i, const double *E, const double *W, const double *vol) {
    return water_front_sent(E[2 * i], front_cap0(s, i, W, vol));
}

/* The rest r_p back to the particles that boiled (E_p > 0), by w_ip s_p / sum_q w_iq s_q on each node,
 * into kept; a sender's weight on a node without storage stays with it. r ends at 0. */
static hearth_status front_return(hearth_scene *s, const int chs[2], const front_stencil *fs, double *r, double *kept,
                                  const double *E, hearth_error *err) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block, n = s->ps.n;
    const double *X = pcold(&s->ps, PC_X), *W = pcold(&s->ps, PC_WATER), *vol = mpm_state_of(s)->vol;
    for (int k = 0; k < g->nactive; k++) {
        double *d = grid_block(g, k);
        for (int c = 0; c < 2; c++) memset(d + chs[c] * NPB, 0, sizeof(double) * (size_t)NPB);
    }
    for (int i = 0; i < n; i++) {
        if (!(E[2 * i] > 0)) continue;
        const double *w;
        const int *at;
        const int nn = front_nodes(g, fs, i, X + 3 * i, &w, &at);
        const double sent = front_sent(s, i, E, W, vol); /* once a particle, not once a node: W holds till the books */
        for (int j = 0; j < nn; j++) {
            int l;
            double *node = front_node(g, fs, at[j], &l);
            const double wt = w[j];
            if (r[i] > 0) node[chs[0] * NPB + l] += wt * r[i];
            node[chs[1] * NPB + l] += wt * sent;
        }
    }
    hearth_status st = mpm_ranks_fields_sum(s, chs, 2, err);
    if (st) return st;
    for (int i = 0; i < n; i++) {
        if (!(E[2 * i] > 0)) continue;
        const double *w;
        const int *at;
        const int nn = front_nodes(g, fs, i, X + 3 * i, &w, &at);
        double q = 0, none = 1;
        for (int j = 0; j < nn; j++) {
            int l;
            const double *node = front_node(g, fs, at[j], &l);
            const double wt = w[j];
            none -= wt;
            const double S = node[chs[1] * NPB + l];
            if (S > 0) q += wt * node[chs[0] * NPB + l] / S; /* S = 0: no sender weighs on it, so no rest is there */
        }
        kept[i] += front_sent(s, i, E, W, vol) * q + none * (r[i] > 0 ? r[i] : 0.0);
    }
    for (int i = 0; i < n; i++) r[i] = 0;
    return HEARTH_OK;
}

hearth_status water_boil_front(hearth_scene *s, hearth_error *err) {
    particles *ps = &s->ps;
    const int n = ps->n;
    double *E = s->water.front, *T = pcold(ps, PC_TEMPERATURE), *Tmax = pcold(ps, PC_TEMP_MAX), *W = pcold(ps, PC_WATER);
    const double *vol = mpm_state_of(s)->vol;
    /* the scratch: E_p, m c (from G2P), then r, cap, Q, kept, near (FRONT_NS doubles a particle) */
    double *r = E + 2 * (size_t)n, *cap = r + n, *Q = cap + n, *kept = Q + n, *near = kept + n;
    const int chs[2] = {FRONT_H, FRONT_G};
    s->water.front_removed = 0;
    int boils = 0;
    for (int i = 0; i < n; i++) {
        r[i] = cap[i] = Q[i] = kept[i] = 0;
        if (!(E[2 * i] > 0)) continue;
        boils = 1;
        cap[i] = front_cap0(s, i, W, vol);
        /* what water_boil would boil goes to the pool; the rest the particle keeps, as water_boil leaves it (a
         * dried particle that water_take's floor leaves a rounding's spare, or that diffusion wets a little,
         * would otherwise be held at T_b every step, handing its heat to the front) */
        r[i] = water_front_sent(E[2 * i], cap[i]);
        kept[i] = E[2 * i] - r[i];
    }
    /* MPI slabs walk every node and particle (front_pass); one rank walks the front's own, and without a
     * particle past T_b has nothing to do: every pass, front_return and the books below would change nothing */
    const int all = s->mpm->nranks > 1 || s->water.front_walk_all;
    if (!all && !boils) return HEARTH_OK;
    grid *g = &s->g;
    double *gc = E + FRONT_NS * (size_t)n;
    memset(gc, 0, sizeof(double) * (size_t)front_ng(g) * (size_t)n);
    const front_stencil fs = {gc + (size_t)front_ng(g) * (size_t)n, (int *)(gc + 2 * (size_t)front_ng(g) * (size_t)n),
                              (int *)(gc + 2 * (size_t)front_ng(g) * (size_t)n) + (size_t)front_ng(g) * (size_t)n,
                              g->dim == 3 ? 6 : 4};
    HEARTH_ASSERT(1 << fs.shift == g->nodes_per_block);
    for (int i = 0; i < n; i++) fs.n[i] = -1;
    unsigned char *fb = (unsigned char *)(fs.node + front_ints(s));
    /* MPI slabs: the gradient at a slab's first node row reads the row below, in the lower halo layer, and
     * a node of the upper halo reads its neighbours there; mpm.c cleared both layers before the grid update
     * (mpm_ranks_fields_clear) and halo_back refilled only the upper blocks this rank's particles touch, so
     * the gradient went one-sided (or 0) at the seam where one process's is central, and the seam's boiling
     * particles took other shares (tests/mpi/dough.lua, its tray at 250 degC through beta 1e5: 5.9e-5 in
     * saturation after 150 steps, 1.0e-3 after 200; mpi_dough_boils_matches_one_rank). The owners' mass and
     * temperatures back first: a node pass then gives the owner's bits (mpm_ranks_fields.c). */
    const int chT[2] = {CH_M, CH_T};
    hearth_status st = s->mpm->nranks > 1 ? mpm_ranks_fields_fill(s, chT, 2, err) : HEARTH_OK;
    if (st) return st;
    for (int k = 0; k < g->nactive; k++) {
        if (all) front_gradient(g, k);
        fb[k] = all ? FB_GRAD | FB_SENT : 0;
    }
    for (int pass = 0; pass < WATER_FRONT_PASSES; pass++) {
        const double left = front_pass(s, chs, all, fb, gc, &fs, E, r, cap, Q, kept, near, err, &st);
        if (st) return st;
        if (!(left > 0) && s->mpm->nranks == 1) break; /* every rank takes part in each pass's exchange */
    }
    /* what is still to hand out after the passes goes back over the nodes to every particle that boiled, in
     * proportion to w_ip E_p, as sensible heat: left with the receiver that last overflowed, the heat of a
     * whole block's nodes ran into its last wet particles (247 degC in a 200 degC oven, latent_heat_wet_plateau) */
    if ((st = front_return(s, chs, &fs, r, kept, E, err))) return st;
    double removed = 0;
    for (int i = 0; i < n; i++) {
        if (!(E[2 * i] > 0) && !(kept[i] > 0)) continue;
        if (kept[i] > 0 && cap[i] > 0) { /* heat kept or handed back boils what water is left first: wet stays at T_b */
            const double take = kept[i] < cap[i] ? kept[i] : cap[i];
            Q[i] += take, cap[i] -= take, kept[i] -= take;
        }
        const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
        const double floor_w = water_floor(ms->core[CP_WATER_DENSITY], vol[i]);
        /* within its room; a particle that filled it is at the floor exactly, so that it boils no more (a
         * rounding's spare would make it a source every step, at T_b, handing its heat on) */
        const int filled = E[2 * i] > 0 && !(cap[i] > 0);
        const double dm = filled ? W[i] - floor_w : Q[i] / HEARTH_LATENT_HEAT;
        W[i] = filled ? floor_w : W[i] - dm;
        removed += dm;
        /* what it could not boil, its own or passed on and back; a particle that never boiled has no m c here,
         * but it only keeps heat it sent (r and kept start at 0 without E) */
        if (kept[i] > 0) T[i] += kept[i] / E[2 * i + 1];
        if (T[i] > Tmax[i]) Tmax[i] = T[i];
    }
    s->water.front_removed = removed;
    return HEARTH_OK;
}
