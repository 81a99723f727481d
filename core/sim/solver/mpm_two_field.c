/* mpm_two_field.c: two velocity fields at the nodes a crack crosses or two
 * bodies meet (scene setting two_field; 2D MPM, one rank).
 *
 * With one velocity field a node moves everything near it together, so a
 * cracked point is carried along with the material on both sides of it: a
 * crack can carry no tension (material.h's cut-off) but can never open or
 * slide (the marshmallow's skin, docs/validation.md "The marshmallow's ooze").
 * Damage-field-gradient partitioning (Homel & Herbold 2017, "Field-gradient
 * partitioning for fracture and frictional contact in the material point
 * method", IJNME 109, 1013-1044, §2-3; as used by Wolper et al. 2019, CD-MPM,
 * §5) gives such a node two fields:
 *  - each particle's damage D_p is 1 where its plugin reports it cracked
 *    (damage >= 1, the core's own threshold for the tension cut-off) and 0
 *    otherwise: intact but strained material stays one body;
 *  - the nodes take the mass-weighted damage D_i = sum w m D_p / sum w m, and
 *    each particle its gradient grad D_p = sum_i D_i grad w_ip (H&H eq. 7-8);
 *  - each node takes as reference the particle gradient of largest norm in
 *    its support (H&H §3.1), and is split where that norm is at least
 *    SPLIT / dx: on a crack (a ridge of D) the particles on either side have
 *    gradients of opposite sign, so a particle whose gradient points against
 *    the node's (negative dot product) goes into the second field (H&H eq. 9);
 *    on a plateau or a step of D every gradient has one sign and nothing is
 *    split, so a wholly cracked skin stays with what it encloses;
 *  - P2G scatters every particle into the total (CH_M..: the field passes see
 *    all the material), and the second field's particles also into CH_TF_M..
 *    (mpm.c's TWO instantiations); before the grid update the first field
 *    becomes the total less the second (mpm_two_field_split). Where every
 *    particle of a node is in the second field the two sums are the same
 *    operations in the same order, so the first field's mass is exactly 0;
 *  - the grid update (gravity, walls, colliders) runs on each field; then
 *    where the two fields approach along the reference normal n (from the
 *    first field toward the second: the second lies where the gradients point
 *    against the node's), each takes the centre-of-mass normal velocity, and
 *    a Coulomb friction two_field_friction limits their tangential slip
 *    (Bardenhagen et al. 2000, "The material-point method for granular
 *    materials", CMAME 187, eq. 20-27; H&H §4). The correction keeps the
 *    node's momentum exactly (m_A dv_A = -m_B dv_B); fields moving apart are
 *    left alone, so a crack opens freely;
 *  - G2P reads each particle's velocity at each node from its own field, by
 *    the same test with the same gradients as P2G.
 * Two bodies (particles.h's PC_BODY: each s:add is one) meet the same way:
 * with one field a body is held up by another through every node their
 * stencils share, up to 1.5 dx apart (tests/contact/pebble.lua). A node whose
 * support holds particles of two or more bodies is split by body instead of
 * by damage: its reference body is the lowest body id in its support (found
 * in the prepare pass, so P2G and G2P agree), that body's particles are the
 * first field and every other body's the second (three or more bodies at one
 * node: all but the lowest share the second field and move as one there).
 * Its normal n, from the first field toward the second, is a body's mass
 * gradient sum m_p grad w_ip (Bardenhagen et al. 2000: a body's normal at a
 * node), the first's negated, of the two the larger (the choice NairnMPM
 * calls the maximum volume gradient). Measured (tests/unit_body_contact.c): a block sliding on
 * a slab took the block's gradient, tilted at its ends, as its normal when
 * that was used alone, and its friction came out 2x mu g; the difference of
 * the two, 30% over at 2.5 mm; the larger, 5.7% (18.7% at 5 mm, 8 cells).
 * The same correction as at a crack applies, approach stopped, momentum kept,
 * separation free, Coulomb friction two_field_friction, with three changes:
 *  - only where the bodies touch by the step's end: the gap along n between
 *    the first field's surface, max (x_p . n + h_p), and the second's, min
 *    (x_p . n - h_p), over the particles facing the node, is at most what the
 *    fields close in dt (h_p and the allowances are mpm_touch.c's, the faces'
 *    touch test). Without it two bodies meet a cell apart, as with one field
 *    (the block on pebble.lua's pebbles rested at 1.66 dx, touching 0.75);
 *  - a field that a face (wall or collider) held at the node in the grid
 *    update is rigid there: the other field takes its normal velocity (and
 *    the friction against it), and the face takes the reaction. The
 *    momentum-weighted correction after the face had held a pebble pushed it
 *    into its tray (the block then lay on the tray at 0.25 dx);
 *  - a face holds a field where a particle of that field's body touches the
 *    face (mpm_two_field_holds, for mpm_touch.c): the pebble touching the
 *    tray had the tray hold the block's field too, a cell up (1.18 dx).
 * The rigid rule and the face's field are for body nodes only: a crack's
 * nodes keep the behaviour they had (its sides never touched a face in a
 * test). Where a crack meets a
 * body boundary the body rule wins at the nodes both bodies touch, and the
 * damage rule stands at the nodes only one body touches (the crack's sides
 * within one body part as before). Each particle carries its body's tag,
 * body + 2 (>= 1: a particle of no body has -1), next to its damage gradient
 * in m->dgrad; a node's tag channel CH_TF_GB holds its reference body's tag,
 * 0 where fewer than two bodies touch it. A scene of one body (or of none)
 * splits no node by body and takes the damage-only path to the bit.
 * A scene without a cracked particle or a second body splits no node: the second field is
 * empty, the first is the total to the bit, and the step is the one-field
 * step's bits (two_field_off_same_bits). A scene with two_field = false
 * allocates and runs none of this.
 *
 * Determinism: the scatters run in mpm.c's colour phases (no two blocks of a
 * colour share a node), the largest-norm choice keeps the first particle in a
 * node's fixed order on ties: the same bits for any thread count. */
#include <math.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "material.h"
#include "mpm.h"
#include "mpm_touch.h"
#include "plugins.h"

/* A node is split where its reference damage gradient is at least SPLIT / dx:
 * a lone cracked column of particles gives about 0.5 / dx beside it; a
 * smooth rounding of 0/1 damage over several cells does not split. */
#define SPLIT 0.25

/* particle entries of m->dgrad: damage gradient x, y, body tag */
#define PD 3

void mpm_two_field_free(mpm_state *m) {
    mem_free(m->dgrad, sizeof(double) * PD * (size_t)m->dgrad_cap);
    m->dgrad = NULL;
    m->dgrad_cap = 0;
}

/* 1 for a cracked particle (its plugin's damage at 1), else 0 (header) */
static double cracked(const hearth_scene *s, int i) {
    const particles *ps = &s->ps;
    const int m = pcoli(ps, PC_MAT)[i];
    const material_slot *ms = &s->mats.slot[m];
    if (!ms->fracture || !ms->m->damage) return 0.0;
    double pscratch[SCENE_MAX_PARAMS];
    plugin_call_enter(ms->m, "damage");
    const double d = ms->m->damage(material_params(&s->mats, ps, m, i, pscratch),
                                   ps->state_stride ? pcold(ps, PC_STATE) + (size_t)i * ps->state_stride : NULL);
    plugin_call_leave();
    return d >= 1.0 ? 1.0 : 0.0;
}

/* a particle's 3x3 stencil: base node, weights and weight derivatives per dx */
typedef struct stencil2 {
    int base[2];
    double w[2][3], dw[2][3];
} stencil2;

static void stencil_of(const grid *g, const double *x, stencil2 *st) {
    for (int d = 0; d < 2; d++) {
        const double X = (x[d] - g->lo[d]) * g->inv_dx;
        st->base[d] = base_node(X);
        bspline_weights(X - st->base[d], st->w[d], st->dw[d]);
    }
}

/* whether two or more bodies can meet: the body rule runs only then */
int mpm_two_field_bodies(const hearth_scene *s) { return (s->ps.enabled & (1u << PC_BODY)) && s->nbodies > 1; }

/* a particle's body tag: body + 2, >= 1 (a particle of no body has -1) */
static double body_tag(const hearth_scene *s, int i) { return (double)pcoli(&s->ps, PC_BODY)[i] + 2.0; }

/* a stencil node: always in an active block (the sort activated every block a particle's stencil touches) */
static double *node_of(const grid *g, int i0, int i1, int *l) {
    const int gi[3] = {i0, i1, 0};
    double *node = grid_node_at(g, gi, l);
    HEARTH_ASSERT(node);
    return node;
}

int mpm_two_field_holds(const hearth_scene *s, int i, const int gi[3], int field) {
    int l = 0;
    const double *node = grid_node_at(&s->g, gi, &l);
    const double gb = node ? node[CH_TF_GB * s->g.nodes_per_block + l] : 0.0;
    return !(gb > 0.0) || (field == 2) == (s->mpm->dgrad[PD * i + 2] != gb);
}

/* pass 1, per particle block (colour phases): sum w m and w m D_p at the nodes */
static void scatter_damage(hearth_scene *s, int k) {
    const grid *g = &s->g;
    const particles *ps = &s->ps;
    const pblock pb = s->mpm->pb[k];
    const int NPB = g->nodes_per_block;
    const double *X = pcold(ps, PC_X), *M = pcold(ps, PC_MASS);
    const int bodies = mpm_two_field_bodies(s);
    for (int i = pb.start; i < pb.end; i++) {
        stencil2 st;
        stencil_of(g, X + 3 * i, &st);
        const double m = M[i], md = m * cracked(s, i), tag = bodies ? body_tag(s, i) : 0.0;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                int l = 0;
                double *node = node_of(g, st.base[0] + a, st.base[1] + b, &l);
                const double w = st.w[0][a] * st.w[1][b];
                node[CH_TF_M * NPB + l] += w * m;
                node[CH_TF_D * NPB + l] += w * md;
                if (bodies) { /* the support's lowest tag in CH_TF_GB (0: none yet), its highest in CH_TF_GX for now */
                    double *lo = node + CH_TF_GB * NPB + l, *hi = node + CH_TF_GX * NPB + l;
                    if (*lo == 0.0 || tag < *lo) *lo = tag;
                    if (tag > *hi) *hi = tag;
                }
            }
    }
}

/* pass 3, per particle block: grad D_p = sum_i D_i grad w_ip (1/m) */
static void gather_gradient(hearth_scene *s, int k) {
    const grid *g = &s->g;
    const pblock pb = s->mpm->pb[k];
    const int NPB = g->nodes_per_block;
    const double *X = pcold(&s->ps, PC_X);
    double *G = s->mpm->dgrad;
    for (int i = pb.start; i < pb.end; i++) {
        stencil2 st;
        stencil_of(g, X + 3 * i, &st);
        double gx = 0, gy = 0;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                int l = 0;
                const double *node = node_of(g, st.base[0] + a, st.base[1] + b, &l);
                const double D = node[CH_TF_D * NPB + l];
                gx += D * st.dw[0][a] * st.w[1][b];
                gy += D * st.w[0][a] * st.dw[1][b];
            }
        G[PD * i] = gx * g->inv_dx;
        G[PD * i + 1] = gy * g->inv_dx;
        G[PD * i + 2] = mpm_two_field_bodies(s) ? body_tag(s, i) : 0.0;
    }
}

/* pass 4, per particle block (colour phases): each node's reference, the particle gradient of largest norm; where
 * two bodies meet, the two fields' mass gradients instead (header; the larger becomes the normal) */
static void scatter_reference(hearth_scene *s, int k) {
    const grid *g = &s->g;
    const pblock pb = s->mpm->pb[k];
    const int NPB = g->nodes_per_block;
    const double *X = pcold(&s->ps, PC_X), *G = s->mpm->dgrad, *M = pcold(&s->ps, PC_MASS);
    const int bodies = mpm_two_field_bodies(s);
    for (int i = pb.start; i < pb.end; i++) {
        const double px = G[PD * i], py = G[PD * i + 1], n2 = px * px + py * py;
        if (n2 == 0.0 && !bodies) continue;
        stencil2 st;
        stencil_of(g, X + 3 * i, &st);
        const double mg = M[i] * g->inv_dx;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                int l = 0;
                double *node = node_of(g, st.base[0] + a, st.base[1] + b, &l);
                double *gx = node + CH_TF_GX * NPB + l, *gy = node + CH_TF_GY * NPB + l;
                const double gb = node[CH_TF_GB * NPB + l];
                if (gb > 0.0) { /* a body contact node: dw is d w_ip / d x_p, so a field's mass gradient (d / d x_i) is
                                 * sum -m dw: the first's negated (outward) in CH_TF_GX/GY, the second's in CH_TF_D/S,
                                 * each pointing from the first toward the second */
                    const int sec = G[PD * i + 2] != gb;
                    const double sg = sec ? -mg : mg;
                    node[(sec ? CH_TF_D : CH_TF_GX) * NPB + l] += sg * st.dw[0][a] * st.w[1][b];
                    node[(sec ? CH_TF_S : CH_TF_GY) * NPB + l] += sg * st.w[0][a] * st.dw[1][b];
                } else if (n2 > *gx * *gx + *gy * *gy) {
                    *gx = px, *gy = py; /* ties keep the first (a fixed order) */
                }
            }
    }
}

/* pass 5, per particle block (colour phases), where bodies meet: at each body contact node (unit normal n by now),
 * the first field's surface max (x_p . n + h_p) in CH_TF_D and the second's min (x_p . n - h_p) in CH_TF_S, h_p
 * the particle's half-extent (mpm_touch.c's, the colliders' touch test), over the particles that face the node:
 * those whose extent along the tangent t overlaps the node's cell, |(x_p - x_i) . t| <= dx / 2 + h_p. (Over the
 * whole support a tilted n projects a flat body's far corner below a neighbour it is still a cell above: the
 * block on pebble.lua's pebbles then rested 0.27 dx over touching.) */
static void scatter_surfaces(hearth_scene *s, int k) {
    const grid *g = &s->g;
    const pblock pb = s->mpm->pb[k];
    const int NPB = g->nodes_per_block;
    const double *X = pcold(&s->ps, PC_X), *G = s->mpm->dgrad;
    for (int i = pb.start; i < pb.end; i++) {
        const double *x = X + 3 * i, h = mpm_touch_half_extent(s, i);
        stencil2 st;
        stencil_of(g, x, &st);
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) {
                int l = 0;
                double *node = node_of(g, st.base[0] + a, st.base[1] + b, &l);
                const double gb = node[CH_TF_GB * NPB + l];
                if (!(gb > 0.0)) continue;
                const double nx = node[CH_TF_GX * NPB + l], ny = node[CH_TF_GY * NPB + l];
                const double rx = x[0] - (g->lo[0] + (st.base[0] + a) * g->dx), ry = x[1] - (g->lo[1] + (st.base[1] + b) * g->dx);
                if (fabs(ny * rx - nx * ry) > 0.5 * g->dx + h) continue; /* not facing the node */
                const double xn = x[0] * nx + x[1] * ny;
                double *sa = node + CH_TF_D * NPB + l, *sb = node + CH_TF_S * NPB + l;
                if (G[PD * i + 2] != gb) *sb = fmin(*sb, xn - h);
                else *sa = fmax(*sa, xn + h);
            }
    }
}

/* Runs fn over this step's particle blocks in the colour phases (mpm.c's p2g_team), for the team of the enclosing region. */
static void colours_team(hearth_scene *s, void (*fn)(hearth_scene *, int)) {
    const mpm_state *m = s->mpm;
    for (int col = 0; col < 8; col++) {
        const int a = m->colour_start[col], b = m->colour_start[col + 1];
        if (a == b) continue;
#pragma omp for schedule(dynamic, 1)
        for (int q = a; q < b; q++) fn(s, m->colour_pb[q]);
    }
}

hearth_status mpm_two_field_prepare(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    grid *g = &s->g;
    HEARTH_ASSERT(g->dim == 2 && g->nch == GRID_NCH_TWO && m->nranks == 1);
    if (s->ps.n > m->dgrad_cap) {
        mpm_two_field_free(m);
        if (!(m->dgrad = mem_alloc(sizeof(double) * PD * (size_t)s->ps.n)))
            return err_set(err, HEARTH_ERR_NOMEM, "out of memory for %d particles' damage gradients (two_field)", s->ps.n);
        m->dgrad_cap = s->ps.n;
    }
    const int NPB = g->nodes_per_block;
    const double split2 = (SPLIT * g->inv_dx) * (SPLIT * g->inv_dx);
    const int bodies = mpm_two_field_bodies(s);
#pragma omp parallel if (s->ps.n >= SCENE_PARALLEL_MIN)
    {
        colours_team(s, scatter_damage);
#pragma omp for schedule(static)
        for (int k = 0; k < g->nactive; k++) { /* D_i, and the mass channel back to 0 for P2G */
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) {
                const double mw = node[CH_TF_M * NPB + l];
                node[CH_TF_D * NPB + l] = mw > 0 ? node[CH_TF_D * NPB + l] / mw : 0.0;
                node[CH_TF_M * NPB + l] = 0.0;
                if (bodies) { /* two or more tags: the lowest is the reference; fewer: no body split */
                    double *lo = node + CH_TF_GB * NPB + l, *hi = node + CH_TF_GX * NPB + l;
                    if (!(*hi > *lo)) *lo = 0.0;
                    *hi = 0.0;
                }
            }
        }
#pragma omp for schedule(dynamic, 2)
        for (int k = 0; k < m->npb; k++) gather_gradient(s, k);
        if (bodies) {
#pragma omp for schedule(static)
            for (int k = 0; k < g->nactive; k++) { /* a body contact node's D_i is read: its channel takes a gradient */
                double *node = grid_block(g, k);
                for (int l = 0; l < NPB; l++)
                    if (node[CH_TF_GB * NPB + l] > 0.0) node[CH_TF_D * NPB + l] = 0.0;
            }
        }
        colours_team(s, scatter_reference);
#pragma omp for schedule(static)
        for (int k = 0; k < g->nactive; k++) { /* a node below the threshold is not split (a body contact node is) */
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) {
                double *gx = node + CH_TF_GX * NPB + l, *gy = node + CH_TF_GY * NPB + l;
                if (node[CH_TF_GB * NPB + l] == 0.0 && *gx * *gx + *gy * *gy < split2) *gx = *gy = 0.0;
                if (node[CH_TF_GB * NPB + l] > 0.0) { /* a body contact node: its unit normal, surfaces not found yet */
                    const double bx = node[CH_TF_D * NPB + l], by = node[CH_TF_S * NPB + l];
                    if (bx * bx + by * by > *gx * *gx + *gy * *gy) *gx = bx, *gy = by; /* the larger gradient (header) */
                    const double gl = sqrt(*gx * *gx + *gy * *gy);
                    if (gl > 0) *gx /= gl, *gy /= gl;
                    node[CH_TF_D * NPB + l] = -INFINITY;
                    node[CH_TF_S * NPB + l] = INFINITY;
                }
            }
        }
        if (bodies) {
            colours_team(s, scatter_surfaces);
#pragma omp for schedule(static)
            for (int k = 0; k < g->nactive; k++) { /* the gap: the second body's surface less the first's */
                double *node = grid_block(g, k);
                for (int l = 0; l < NPB; l++)
                    if (node[CH_TF_GB * NPB + l] > 0.0) node[CH_TF_D * NPB + l] = node[CH_TF_S * NPB + l] - node[CH_TF_D * NPB + l];
            }
        }
    }
    return HEARTH_OK;
}

void mpm_two_field_split(hearth_scene *s) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            const double mb = node[CH_TF_M * NPB + l];
            if (!(mb > 0)) continue;
            const double ma = node[CH_M * NPB + l] - mb;
            for (int d = 0; d < 3; d++) {
                double *p = node + (CH_PX + d) * NPB + l;
                *p = ma > 0 ? *p - node[(CH_TF_PX + d) * NPB + l] : 0.0;
            }
            node[CH_M * NPB + l] = ma > 0 ? ma : 0.0;
        }
    }
}

/* one field's correction at a contact node: r its velocity less the centre of mass's, rn = r . n */
static void correct(double *v, const double r[2], double rn, const double n[2], double mu) {
    const double t[2] = {r[0] - rn * n[0], r[1] - rn * n[1]}, tl = sqrt(t[0] * t[0] + t[1] * t[1]);
    const double slip = tl > 0 ? fmin(mu * fabs(rn), tl) / tl : 0.0; /* Coulomb: at most mu |normal change| */
    v[0] -= rn * n[0] + slip * t[0];
    v[1] -= rn * n[1] + slip * t[1];
}

void mpm_two_field_contact(hearth_scene *s, double dt) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    const double mu = s->def.two_field_friction, tol = COLLIDER_ROW_TOL * g->dx;
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            /* the grid update's marks where a face held each field (mpm.c's grid_update_block, 2D's z channel),
             * read and cleared */
            const int ha = node[CH_PZ * NPB + l] != 0.0, hb = node[CH_TF_PZ * NPB + l] != 0.0;
            node[CH_PZ * NPB + l] = node[CH_TF_PZ * NPB + l] = 0.0;
            const double ma = node[CH_M * NPB + l], mb = node[CH_TF_M * NPB + l];
            if (!(ma > 0 && mb > 0)) continue;
            const double gx = node[CH_TF_GX * NPB + l], gy = node[CH_TF_GY * NPB + l], gl = sqrt(gx * gx + gy * gy);
            if (!(gl > 0)) continue;
            const double n[2] = {gx / gl, gy / gl}; /* from the first field toward the second */
            double va[2] = {node[CH_PX * NPB + l], node[CH_PY * NPB + l]};
            double vb[2] = {node[CH_TF_PX * NPB + l], node[CH_TF_PY * NPB + l]};
            const double close = (va[0] - vb[0]) * n[0] + (va[1] - vb[1]) * n[1];
            if (!(close > 0)) continue; /* apart or sliding: free */
            /* two bodies: in contact only where they touch by the step's end (the colliders' test, mpm_touch.c) */
            const int body = node[CH_TF_GB * NPB + l] > 0.0;
            if (body && node[CH_TF_D * NPB + l] > dt * close + tol) continue;
            if (body && (ha || hb)) { /* a body a face holds here is rigid: the other takes its normal velocity */
                if (ha && hb) continue; /* the faces have set both */
                double *vf = ha ? vb : va; /* the free field, its velocity relative to the held one's */
                const double *vh = ha ? va : vb, r[2] = {vf[0] - vh[0], vf[1] - vh[1]};
                correct(vf, r, r[0] * n[0] + r[1] * n[1], n, mu);
                node[(ha ? CH_TF_PX : CH_PX) * NPB + l] = vf[0], node[(ha ? CH_TF_PY : CH_PY) * NPB + l] = vf[1];
                continue;
            }
            const double vc[2] = {(ma * va[0] + mb * vb[0]) / (ma + mb), (ma * va[1] + mb * vb[1]) / (ma + mb)};
            const double ra[2] = {va[0] - vc[0], va[1] - vc[1]}, rb[2] = {vb[0] - vc[0], vb[1] - vc[1]};
            correct(va, ra, ra[0] * n[0] + ra[1] * n[1], n, mu);
            correct(vb, rb, rb[0] * n[0] + rb[1] * n[1], n, mu);
            node[CH_PX * NPB + l] = va[0], node[CH_PY * NPB + l] = va[1];
            node[CH_TF_PX * NPB + l] = vb[0], node[CH_TF_PY * NPB + l] = vb[1];
        }
    }
}
