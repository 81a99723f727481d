/* mpm_touch.c: a slip or separate face holds a node only where the body touches it, a sticky one where it
 * touches or has touched (#18).
 *
 * The grid update holds every node on or inside a collider's face (and the two
 * node layers of a closed domain wall) whose velocity approaches it. A node on
 * the face has mass from every particle within 1.5 dx of it (quadratic
 * B-splines), so the contact used to engage up to about a cell before the body
 * reached the face: a block released a cell above a separate tray came to rest
 * a cell above it, on nothing, and the physical loaf's base, once its bottom
 * rows had swelled off the tray, never came back down (docs/validation.md, "A
 * body rests on what it touches").
 *
 * Here a held node of a slip or separate face needs a particle that touches
 * that face among the particles whose stencil holds the node. A particle
 * touches when its distance to the face is at most its own half-extent h_p
 * (half its current spacing, (J V0)^(1/dim) / 2: a risen loaf's swollen base
 * rests higher than a fresh one; 2D's default 4 particles a cell sit dx / 2
 * apart, h_p = dx / 4), with two allowances:
 *  - COLLIDER_ROW_TOL dx, as for a node on a face's row: a body seeded on a
 *    lattice with the face at its edge has its lowest row at h_p up to the
 *    SDF's round-off;
 *  - the distance the particle closes on the face in this step, dt times its
 *    approach speed: without it a falling body's base row can pass the face
 *    before the contact engages, and collider_project_particle stops it on the
 *    face, h_p too low.
 * A quarter of h_p more (an allowance for the particle's shape under F) left
 * dropped blocks resting 0.03-0.06 dx above h_p; without it they rest within
 * 0.03 dx below it (docs/validation.md). The particles that still cross the
 * face are put back by collider_project_particle after G2P, as before.
 *
 * A grip holds every node on and inside it (it holds the material inside it).
 *
 * A sticky face is glue: it must hold a body in tension too, and the touch test
 * alone let go of a vibrating bar's glued end as it stretched away
 * (vibrating_bar: no period found) and of a Couette layer whose sticky lid sits
 * 1e-6 dx off its top (couette_lid_on_node_row: 0.0 of the lid speed), while
 * holding every node on and inside it grabbed a body released a cell above it
 * and hung it there. So a sticky face holds a node where a particle in its
 * stencil touches it now or has touched it before: glue with memory, and no
 * strength (a glued particle stays glued). mpm_glue_mark, at the step's start
 * (the positions P2G scatters from, before the sort), runs the same test,
 * `touches`, for each sticky face and sets the particle's bit for that face in
 * its own column PC_GLUE (the six domain wall faces slots 0..5, collider c slot
 * 6 + c, past the last slot colliders share it; the column is enabled the first
 * time a scene has a sticky face); the grid update's mask for a sticky face is
 * then the stencils of the particles holding its bit. Not bits of PC_FLAGS:
 * that column is the heat's too (boundary.c marks PF_BOUNDARY only where it
 * exists, and flip_bound.c clamps those particles instead of relaxing them), so
 * enabling it for glue could change a sticky scene's heat. Per face, not any
 * sticky face: a body glued to one sticky face whose glued particles pass
 * within a stencil of another it never touches would be caught by that one too
 * (tests/contact/two_faces.lua: a sheet carried over a sticky tray 0.75 dx above
 * it; docs/validation.md, "A sticky face holds what touched it"). The bits
 * travel as any column: the sort permutes them, a slab crossing carries them
 * (mpm_ranks.c packs every enabled column), the ranks' halo_touch sends a sticky
 * face's glue masks with the others (mpm_touch_face_mask), and checkpoint
 * version 11 saves the column; an older file had its sticky faces hold every
 * node on and inside them, so its first step glues each particle whose stencil
 * reaches such a node (held_before_glue) and it goes on as it was saved. A
 * particle glued to a collider keeps its bit if the collider's mode changes; a
 * scene without a sticky face pays nothing (no column, no pass), and the pass
 * skips the distances of a chunk of particles far from a collider (exactly:
 * mpm_glue_mark says how). The sticky mirrors
 * and ghost reflections (mpm_sticky.c) are as before: the mirrors by distance
 * (a free-falling body's stress is nil), the reflections at the held nodes.
 *
 * The test reads the particles of the 2^dim particle blocks whose stencils
 * reach the grid block (the block itself and its -1 neighbours: a particle's
 * stencil starts at its block's base node), sorted by the step's sort, only
 * for a grid block with a node on a slip, separate or sticky face, once per
 * block and face. It reads positions P2G scattered from (and the glue bits)
 * and writes nothing; mpm_glue_mark writes only each particle's own glue: the
 * same result at any thread count or order. Rejected: a touch channel
 * scattered in P2G like the mass (every scene's P2G and its tiles, the
 * gather's store and the ranks' halo sums would carry one more channel for a
 * few nodes on a tray); setting the glue bits inside the mask (a particle
 * block is read by up to 2^dim grid blocks at once: racing writes). Under MPI
 * slabs the lower neighbour's masks for a seam's blocks come with the ghost
 * sums (mpm_ranks.c's halo_touch), so a node on a seam is held as on one rank. */
#include "mpm_touch.h"

#include <math.h>

#include "colliders.h"


/* the particle block of grid block id, or -1 (the sort lists them in ascending block order) */
static int pb_of_block(const mpm_state *m, int id) {
    int lo = 0, hi = m->npb - 1;
    while (lo <= hi) {
        const int mid = (lo + hi) / 2, b = m->pb[mid].block;
        if (b == id) return mid;
        if (b < id) lo = mid + 1;
        else hi = mid - 1;
    }
    return -1;
}

double mpm_touch_half_extent(const hearth_scene *s, int i) {
    const double v = particles_J(&s->ps, i) * pcold(&s->ps, PC_VOL0)[i];
    return 0.5 * (s->g.dim == 2 ? sqrt(fabs(v)) : cbrt(fabs(v)));
}

/* The face: collider c, or (c NULL) the domain wall on axis d, side (0 low, 1 high). Returns the particle's
 * distance to it (m) and its outward normal n there. */
static double face_distance(const hearth_scene *s, const collider *c, int d, int side, const double x[3], double n[3]) {
    const grid *g = &s->g;
    if (c) {
        const double phi = collider_sdf(c, x, n);
        if (g->dim == 2) n[2] = 0.0;
        return phi;
    }
    /* G2P keeps particles within [lo + dx, lo + (nn - 2) dx]: the walls' faces (their held layers end there) */
    for (int a = 0; a < 3; a++) n[a] = 0.0;
    n[d] = side ? -1.0 : 1.0;
    return side ? g->lo[d] + (g->nn[d] - 2) * g->dx - x[d] : x[d] - (g->lo[d] + g->dx);
}

/* 1: particle i touches the face (collider c, or the wall on axis d, side) this step of dt: its distance within
 * its half-extent and the allowances above. The one test of the slip and separate faces' hold and of the glue. */
static int touches(const hearth_scene *s, const collider *c, int d, int side, int i, double dt) {
    const grid *g = &s->g;
    const double *x = pcold(&s->ps, PC_X) + 3 * i, *v = pcold(&s->ps, PC_V) + 3 * i;
    if (c && !collider_near(c, x)) return 0; /* the bound reaches 2 dx past the face */
    double n[3];
    const double phi = face_distance(s, c, d, side, x, n);
    if (phi > 2.0 * g->dx) return 0;
    const double reach = mpm_touch_half_extent(s, i) + COLLIDER_ROW_TOL * g->dx;
    if (phi <= reach) return 1;
    /* within reach only by what it closes this step: the face's velocity too */
    double vb[3] = {0, 0, 0};
    if (c) collider_velocity_at(c, x, vb);
    if (g->dim == 2) vb[2] = 0.0;
    const double close = -((v[0] - vb[0]) * n[0] + (v[1] - vb[1]) * n[1] + (v[2] - vb[2]) * n[2]);
    return phi <= reach + dt * fmax(0.0, close);
}

uint64_t mpm_touch_mask(const hearth_scene *s, const int bc[3], const collider *c, int d, int side, double dt, int glue,
                        int field) {
    const grid *g = &s->g;
    const mpm_state *m = s->mpm;
    const int D = g->dim;
    const double *X = pcold(&s->ps, PC_X);
    if (glue && !(s->ps.enabled & (1u << PC_GLUE))) return 0; /* no step has marked (a caller outside mpm_step) */
    const int *glued = glue ? pcoli(&s->ps, PC_GLUE) : NULL;
    if (field && !mpm_two_field_bodies(s)) field = 0; /* no node is split by body: every particle holds for both */
    uint64_t mask = 0;
    for (int o = 0; o < (D == 2 ? 4 : 8); o++) {
        int b[3] = {bc[0] - (o & 1), bc[1] - ((o >> 1) & 1), D == 3 ? bc[2] - ((o >> 2) & 1) : 0};
        if (b[0] < 0 || b[1] < 0 || b[2] < 0) continue;
        const int k = pb_of_block(m, grid_block_id(g, b[0], b[1], b[2]));
        if (k < 0) continue;
        for (int i = m->pb[k].start; i < m->pb[k].end; i++) {
            if (glue ? !(glued[i] & glue) : !touches(s, c, d, side, i, dt)) continue;
            const double *x = X + 3 * i;
            /* its stencil's nodes in this block */
            int lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
            for (int a = 0; a < D; a++) {
                const int base = base_node((x[a] - g->lo[a]) * g->inv_dx) - bc[a] * GRID_B;
                lo[a] = base < 0 ? 0 : base;
                hi[a] = base + 2 > GRID_B - 1 ? GRID_B - 1 : base + 2;
            }
            for (int p = lo[0]; p <= hi[0]; p++)
                for (int q = lo[1]; q <= hi[1]; q++)
                    for (int r = lo[2]; r <= hi[2]; r++) {
                        /* two_field: where two bodies meet, a body touching the face holds only its own field */
                        const int gi[3] = {bc[0] * GRID_B + p, bc[1] * GRID_B + q, 0};
                        if (field && !mpm_two_field_holds(s, i, gi, field)) continue;
                        mask |= (uint64_t)1 << (D == 2 ? p * GRID_B + q : (p * GRID_B + q) * GRID_B + r);
                    }
        }
    }
    return mask;
}

int mpm_touch_gated(hearth_contact mode) { return mode == HEARTH_SLIP || mode == HEARTH_SEPARATE; }

int mpm_touch_glued(hearth_contact mode) { return mode == HEARTH_STICKY; }

int mpm_touch_faces(const hearth_scene *s) { return s->ncol + 6; }

int mpm_touch_glue_bit(const hearth_scene *s, int f) {
    const int slot = f >= s->ncol ? f - s->ncol : 6 + f;
    return 1 << (slot < GLUE_SLOTS ? slot : GLUE_SLOTS - 1);
}

/* 1: face f exists (a collider, or a domain wall on a closed axis of the scene's dimension); *mode is its contact */
static int face_mode(const hearth_scene *s, int f, hearth_contact *mode) {
    if (f < s->ncol) return *mode = s->cols[f].mode, 1;
    const int d = (f - s->ncol) / 2;
    *mode = s->def.wall;
    return d < s->g.dim && !s->def.periodic[d];
}

/* face f's mask, whatever its mode: the glued particles' stencils for a sticky face, the touching ones' else */
static uint64_t face_mask(const hearth_scene *s, const int bc[3], int f, double dt, int field) {
    const int w = f - s->ncol; /* a wall: axis w / 2, side w % 2 */
    hearth_contact mode;
    face_mode(s, f, &mode);
    const int glue = mpm_touch_glued(mode) ? mpm_touch_glue_bit(s, f) : 0;
    return w < 0 ? mpm_touch_mask(s, bc, &s->cols[f], 0, 0, dt, glue, field)
                 : mpm_touch_mask(s, bc, NULL, w / 2, w % 2, dt, glue, field);
}

uint64_t mpm_touch_face_mask(const hearth_scene *s, const int bc[3], int f, double dt) {
    hearth_contact mode;
    if (!face_mode(s, f, &mode) || !(mpm_touch_gated(mode) || mpm_touch_glued(mode))) return 0;
    if (f < s->ncol) return face_mask(s, bc, f, dt, 0);
    const int d = (f - s->ncol) / 2, side = (f - s->ncol) % 2;
    const grid *g = &s->g;
    /* the walls hold the two node layers nearest each face: a block that has none of them has no mask */
    const int lo = bc[d] * GRID_B, hi = lo + GRID_B - 1;
    if (side ? hi < g->nn[d] - 2 : lo > 1) return 0;
    return face_mask(s, bc, f, dt, 0);
}

int mpm_touch_holds(const hearth_scene *s, mpm_touch_cache *tc, int id, const int bc[3], int f, int l, double dt) {
    uint64_t mask;
    if (f < MPM_TOUCH_CACHE && tc->done >> f & 1) {
        mask = tc->mask[f];
    } else {
        mask = face_mask(s, bc, f, dt, tc->field);
        if (s->mpm->nranks > 1) mask |= mpm_ranks_touch_below(s, id, f); /* a seam's other side */
        if (f < MPM_TOUCH_CACHE) tc->mask[f] = mask, tc->done |= (uint64_t)1 << f;
    }
    return (int)(mask >> l & 1);
}

enum { GLUE_CHUNK = 64 }; /* particles whose face distance mpm_glue_mark skips together */

/* 1: a node of particle i's stencil is one the sticky face held before glue (checkpoints before version 11):
 * a collider's node on or inside its face, a wall's node in its two layers */
static int held_before_glue(const hearth_scene *s, const collider *c, int d, int side, int i) {
    const grid *g = &s->g;
    const double *x = pcold(&s->ps, PC_X) + 3 * i;
    int base[3] = {0, 0, 0};
    for (int a = 0; a < g->dim; a++) base[a] = base_node((x[a] - g->lo[a]) * g->inv_dx);
    if (!c) return side ? base[d] + 2 > g->nn[d] - 3 : base[d] < 2;
    if (!collider_near(c, x)) return 0;
    for (int p = 0; p < 3; p++)
        for (int q = 0; q < 3; q++)
            for (int r = 0; r < (g->dim == 3 ? 3 : 1); r++) {
                const int o[3] = {p, q, r};
                double xi[3] = {0, 0, 0}, n[3];
                for (int a = 0; a < g->dim; a++) xi[a] = g->lo[a] + (base[a] + o[a]) * g->dx;
                if (collider_sdf(c, xi, n) <= COLLIDER_ROW_TOL * g->dx) return 1;
            }
    return 0;
}

/* 1: the scene has a sticky face (a collider, or the domain walls on a closed axis) */
static int sticky_faces(const hearth_scene *s) {
    hearth_contact mode;
    for (int f = 0; f < mpm_touch_faces(s); f++)
        if (face_mode(s, f, &mode) && mpm_touch_glued(mode)) return 1;
    return 0;
}

hearth_status mpm_glue_column(hearth_scene *s, hearth_error *err) {
    if (s->def.solver != HEARTH_SOLVER_MPM || (s->ps.enabled & (1u << PC_GLUE)) || !sticky_faces(s)) return HEARTH_OK;
    return particles_enable(&s->ps, PC_GLUE, err);
}

hearth_status mpm_glue_mark(hearth_scene *s, double dt, hearth_error *err) {
    const grid *g = &s->g;
    const int legacy = s->glue_legacy; /* once, at the first step after the restore */
    s->glue_legacy = 0;
    if (!sticky_faces(s)) return HEARTH_OK;
    particles *ps = &s->ps;
    const int nf = mpm_touch_faces(s); /* every face; the sticky ones are marked */
    const hearth_status st = mpm_glue_column(s, err);
    if (st) return st;
    int *glued = pcoli(ps, PC_GLUE);
    const double *X = pcold(ps, PC_X);
    const int n = ps->n, nchunk = (n + GLUE_CHUNK - 1) / GLUE_CHUNK;
    /* In chunks of the store's order (the last sort's: neighbours): a collider far from a chunk's box is far from
     * every particle in it. A shape's distance changes by at most L times a move, L = 1 for the exact leaves and
     * their min / max (shapes.c) and about 1 for a mask's sampled field: a chunk whose centre stands more than
     * 2 (r + 2 dx) off the face, r the box's half-diagonal, has no particle within the 2 dx the test reads even
     * for L = 2, so its distances are skipped (the same bits: the test's answer for each particle is unchanged) */
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < nchunk; k++) {
        const int i0 = k * GLUE_CHUNK, i1 = i0 + GLUE_CHUNK < n ? i0 + GLUE_CHUNK : n;
        double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (int i = i0; i < i1; i++)
            for (int a = 0; a < 3; a++) lo[a] = fmin(lo[a], X[3 * i + a]), hi[a] = fmax(hi[a], X[3 * i + a]);
        const double mid[3] = {0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2])};
        const double r = 0.5 * sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                    (hi[2] - lo[2]) * (hi[2] - lo[2]));
        for (int f = 0; f < nf; f++) {
            hearth_contact mode;
            if (!face_mode(s, f, &mode) || !mpm_touch_glued(mode)) continue;
            const int bit = mpm_touch_glue_bit(s, f), w = f - s->ncol;
            const collider *c = w < 0 ? &s->cols[f] : NULL;
            if (c && !legacy && collider_sdf(c, mid, NULL) > 2.0 * (r + 2.0 * g->dx)) continue;
            const int d = w < 0 ? 0 : w / 2, side = w < 0 ? 0 : w % 2;
            for (int i = i0; i < i1; i++)
                if (!(glued[i] & bit) && (touches(s, c, d, side, i, dt) || (legacy && held_before_glue(s, c, d, side, i))))
                    glued[i] |= bit;
        }
    }
    return HEARTH_OK;
}
