/* mpm_ranks_fields.c: heat, water and CO2 on MPI slabs (#21), beside the
 * momentum-only slab mode of mpm_ranks.c.
 *
 * The field passes between P2G and the grid update read more than a
 * particle's own tile: boundary.c's surface search takes gradients of the
 * volume fraction one node either side and averages them over the cells
 * around, and thermal.c's small-node merge looks at a node's 26 neighbours and
 * scatters into the fullest (shared equally when tied). These reach at most three nodes from the nodes
 * a rank's particles touch, less than a block layer (GRID_B = 4). A heated
 * collider's contact point (the particle's foot on the face) does not keep
 * to that: it lies up to two cells from its particle, or as deep as the
 * particle went into the collider, so each point goes to the rank owning its
 * base node's block (mpm_ranks_fields_contacts), whose slab and upper halo
 * layer hold its whole stencil. The surface search's domain-wall test reads
 * the box's end node, which may lie further still: every rank gets the end
 * planes' mass flags (wall_planes). So with fields each rank
 * keeps one complete block layer on each side of its slab: the upper
 * neighbour's first layer (the momentum mode's ghost layer, now with every
 * block its owner has, not only the ones this rank's particles touch) and
 * the lower neighbour's last layer. Their storage is asked for at the sort
 * (mpm_ranks_fields_mark: mark bit 2, so halo_sum and halo_back, which move
 * only the blocks this rank's particles touch, keep to bit 1).
 *
 * The rule that keeps them right: after every particle scatter the halo
 * layers' sums go to their owners (sum), and after that the owners' values
 * come back (fill). Between the two every node of the two halo layers holds
 * its owner's bits, so every node pass (temperature from C theta, phi, the
 * merge, the CG's vector updates) runs on all active blocks, the halo
 * layers' copies giving the owner's results; only a pass's values within its
 * reach of the outer faces of the halo layers are wrong, and nothing this
 * rank keeps reads them (the reach above). Before the grid update the halo
 * layers are cleared (mpm_ranks_fields_clear), so the momentum mode's
 * halo_back finds them as it left them.
 *
 * Reductions: the CG's dot products, the oven's heat ledger and the step's
 * water take each rank's partial over the blocks it owns (or its
 * particles), allgathered and added in rank order: the same bits on every
 * rank and in every run with this rank count (mpm_ranks_fields_reduce).
 *
 * Traffic a step (3D, explicit heat): one fill of every channel after P2G
 * and one sum and fill of the transport's outputs, each two block layers;
 * the implicit solve adds one sum and fill of one channel and three
 * allgathers of a double per CG iteration. None of it grows with the
 * particle count along the slab axis (`mpi_heat_halo_traffic_bounded_4`). */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "mpm.h"
#include "ranks.h"
#include "thermal.h"
#include "water.h"

struct mpm_slab_fields {
    double *buf[2];      /* packed node values for the lower and the upper neighbour */
    size_t cap[2];       /* doubles */
    unsigned char *own;  /* per active slot: the block lies in this rank's slab */
    int owncap;
    unsigned char *lay;  /* a layer's marks for a neighbour */
    size_t laycap;
    double *red;         /* nranks x RED_MAX: the reductions' allgather */
    int redn;            /* ranks it was sized for */
    double *cbuf[2];     /* contact points for the lower and the upper neighbour */
    size_t ccap[2];      /* doubles */
    unsigned char *wall; /* the box's two end planes along the axis: a node's mass > 0 (mpm_ranks_fields_wall) */
    size_t wallcap;
};

#define RED_MAX 8 /* doubles one reduction carries */

void mpm_ranks_fields_free(mpm_state *m) {
    struct mpm_slab_fields *f = m->sfields;
    if (!f) return;
    for (int k = 0; k < 2; k++) mem_free(f->buf[k], f->cap[k] * sizeof(double));
    for (int k = 0; k < 2; k++) mem_free(f->cbuf[k], f->ccap[k] * sizeof(double));
    mem_free(f->wall, f->wallcap);
    mem_free(f->own, (size_t)f->owncap);
    mem_free(f->lay, f->laycap);
    mem_free(f->red, sizeof(double) * RED_MAX * (size_t)f->redn);
    mem_free(f, sizeof *f);
    m->sfields = NULL;
}

static hearth_status state(mpm_state *m, hearth_error *err) {
    if (m->sfields) return HEARTH_OK;
    struct mpm_slab_fields *f = mem_calloc(sizeof(struct mpm_slab_fields));
    double *red = mem_alloc(sizeof(double) * RED_MAX * (size_t)m->nranks);
    if (!f || !red) {
        mem_free(f, sizeof *f);
        mem_free(red, sizeof(double) * RED_MAX * (size_t)m->nranks);
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the slabs' field tables");
    }
    f->red = red, f->redn = m->nranks;
    m->sfields = f;
    return HEARTH_OK;
}

/* Block id of the k-th block of block layer l along axis (mpm_ranks.c's FOR_LAYER order). */
static int layer_block(const grid *g, int axis, int l, int k) {
    const int o1 = axis == 0 ? 1 : 0, o2 = axis == 2 ? 1 : 2;
    int c[3];
    c[axis] = l, c[o1] = k / g->nb[o2], c[o2] = k % g->nb[o2];
    return grid_block_id(g, c[0], c[1], c[2]);
}

/* fields_on: the scene has heat or water (the reductions, stats() among them between steps, and the tables);
 * fields_live: and this step updates them. A step of the fields' clock without an update (field_clock.c: the
 * same steps on every rank) moves no field halo and marks no halo layer. */
static int fields_on(const hearth_scene *s) { return thermal_active(s) || water_active(s); }
static int fields_live(const hearth_scene *s) { return fields_on(s) && !s->field_skip; }

hearth_status mpm_ranks_fields_mark(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    int axis, lo, hi;
    if (!mpm_ranks_slab(m, &axis, &lo, &hi) || !fields_on(s)) return HEARTH_OK;
    hearth_status st = state(m, err); /* at every sort: the reductions between field steps use its buffer */
    if (st || s->field_skip) return st;
    struct mpm_slab_fields *f = m->sfields;
    const grid *g = &s->g;
    const int S = g->nblocks / g->nb[axis], me = ranks_rank(), N = m->nranks;
    if ((size_t)(2 * S) > f->laycap) {
        unsigned char *b = mem_alloc((size_t)(2 * S));
        if (!b) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the halo layers' marks (%d blocks)", S);
        mem_free(f->lay, f->laycap);
        f->lay = b, f->laycap = (size_t)(2 * S);
    }
    /* this rank's first layer (the lower neighbour's particles already in it)
     * goes down, its last up: the neighbours' halo layers get the owner's blocks */
    for (int k = 0; k < S; k++) {
        f->lay[k] = m->mark[layer_block(g, axis, lo, k)] != 0;
        f->lay[S + k] = m->mark[layer_block(g, axis, hi - 1, k)] != 0;
    }
    const void *from_lo, *from_hi;
    size_t nlo, nhi;
    if ((st = ranks_neighbours(f->lay, me > 0 ? (size_t)S : 0, f->lay + S, me + 1 < N ? (size_t)S : 0, &from_lo, &nlo, &from_hi,
                               &nhi, err)))
        return st;
    if (me > 0) {
        HEARTH_ASSERT(nlo == (size_t)S);
        for (int k = 0; k < S; k++) m->mark[layer_block(g, axis, lo - 1, k)] |= ((const unsigned char *)from_lo)[k] ? 2 : 0;
    }
    if (me + 1 < N) {
        HEARTH_ASSERT(nhi == (size_t)S);
        for (int k = 0; k < S; k++) m->mark[layer_block(g, axis, hi, k)] |= ((const unsigned char *)from_hi)[k] ? 2 : 0;
    }
    return HEARTH_OK;
}

static hearth_status reserve(struct mpm_slab_fields *f, int which, size_t n, hearth_error *err) {
    if (n <= f->cap[which]) return HEARTH_OK;
    const size_t c = n + n / 4;
    double *b = mem_alloc(c * sizeof(double));
    if (!b) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the halo layers' node values (%zu bytes)", c * sizeof(double));
    mem_free(f->buf[which], f->cap[which] * sizeof(double));
    f->buf[which] = b, f->cap[which] = c;
    return HEARTH_OK;
}

/* The channels ch[0..nc) (all when ch is NULL) of layer l's active blocks,
 * in layer order: packed into dst (mode 0), packed and zeroed (1), copied
 * from src (2) or added from src (3). Returns the doubles moved. */
static size_t layer_io(grid *g, int axis, int l, const int *ch, int nc, double *dst, const double *src, int mode) {
    const int S = g->nblocks / g->nb[axis], NPB = g->nodes_per_block;
    const int n = ch ? nc : g->nch;
    size_t w = 0;
    for (int k = 0; k < S; k++) {
        const int slot = g->slot[layer_block(g, axis, l, k)];
        if (slot < 0) continue;
        double *b = grid_block(g, slot);
        for (int c = 0; c < n; c++, w += (size_t)NPB) {
            double *v = b + (size_t)(ch ? ch[c] : c) * (size_t)NPB;
            if (mode <= 1) {
                memcpy(dst + w, v, sizeof(double) * (size_t)NPB);
                if (mode == 1) memset(v, 0, sizeof(double) * (size_t)NPB);
            } else if (mode == 2) {
                memcpy(v, src + w, sizeof(double) * (size_t)NPB);
            } else {
                for (int j = 0; j < NPB; j++) v[j] += src[w + (size_t)j];
            }
        }
    }
    return w;
}

static size_t layer_doubles(const grid *g, int axis, int l, int nc) {
    const int S = g->nblocks / g->nb[axis];
    size_t n = 0;
    for (int k = 0; k < S; k++) n += g->slot[layer_block(g, axis, l, k)] >= 0;
    return n * (size_t)nc * (size_t)g->nodes_per_block;
}

/* Send layer sl_down (packing mode pm) to the lower neighbour and sl_up to
 * the upper one; receive into layers rl_lo and rl_hi (mode rm). -1: none. */
static hearth_status exchange(hearth_scene *s, const int *ch, int nc, int sl_down, int sl_up, int pm, int rl_lo, int rl_hi, int rm,
                              hearth_error *err) {
    mpm_state *m = s->mpm;
    struct mpm_slab_fields *f = m->sfields;
    grid *g = &s->g;
    int axis, lo, hi;
    mpm_ranks_slab(m, &axis, &lo, &hi);
    const int n = ch ? nc : g->nch;
    size_t nd = sl_down >= 0 ? layer_doubles(g, axis, sl_down, n) : 0, nu = sl_up >= 0 ? layer_doubles(g, axis, sl_up, n) : 0;
    hearth_status st;
    if ((st = reserve(f, 0, nd, err)) || (st = reserve(f, 1, nu, err))) return st;
    if (sl_down >= 0) layer_io(g, axis, sl_down, ch, nc, f->buf[0], NULL, pm);
    if (sl_up >= 0) layer_io(g, axis, sl_up, ch, nc, f->buf[1], NULL, pm);
    const void *from_lo, *from_hi;
    size_t nlo, nhi;
    if ((st = ranks_neighbours(f->buf[0], nd * sizeof(double), f->buf[1], nu * sizeof(double), &from_lo, &nlo, &from_hi, &nhi, err)))
        return st;
    /* the lower neighbour's first, then the upper's: a fixed order where both land on one layer */
    /* the halo layers hold the same active blocks as the layers they copy (mpm_ranks_fields_mark) */
    if (rl_lo >= 0 && layer_doubles(g, axis, rl_lo, n) * sizeof(double) != nlo)
        return err_set(err, HEARTH_ERR_STATE, "slabs: the lower halo layer does not match its owner's blocks");
    if (rl_hi >= 0 && layer_doubles(g, axis, rl_hi, n) * sizeof(double) != nhi)
        return err_set(err, HEARTH_ERR_STATE, "slabs: the upper halo layer does not match its owner's blocks");
    if (rl_lo >= 0) layer_io(g, axis, rl_lo, ch, nc, NULL, from_lo, rm);
    if (rl_hi >= 0) layer_io(g, axis, rl_hi, ch, nc, NULL, from_hi, rm);
    return HEARTH_OK;
}

/* Nodes in a plane across the axis (the other axes' node counts). */
static size_t plane_nodes(const grid *g, int axis) {
    size_t n = 1;
    for (int d = 0; d < g->dim; d++)
        if (d != axis) n *= (size_t)g->nn[d];
    return n;
}

/* The domain-wall test of boundary.c's surface search reads the box's end
 * node along each axis, up to three nodes from a cell; through the chain of
 * the search (a particle's nodes, their cells, the cells around each) a rank
 * whose slab ends two layers below the end layer reads it, and holds no copy
 * (measured: 5.7e-7 in temperature on a column against the far wall). Every
 * rank gets both end planes' "has mass" flags after P2G instead: the owners
 * of the end layers set theirs, a bytewise max over the ranks (integers:
 * any order gives the same bytes). */
static hearth_status wall_planes(hearth_scene *s, int axis, int lo, int hi, hearth_error *err) {
    struct mpm_slab_fields *f = s->mpm->sfields;
    const grid *g = &s->g;
    const size_t P = plane_nodes(g, axis);
    if (2 * P > f->wallcap) {
        unsigned char *b = mem_alloc(2 * P);
        if (!b) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the box's end planes (%zu nodes)", 2 * P);
        mem_free(f->wall, f->wallcap);
        f->wall = b, f->wallcap = 2 * P;
    }
    memset(f->wall, 0, 2 * P);
    const int S = g->nblocks / g->nb[axis], NPB = g->nodes_per_block;
    for (int side = 0; side < 2; side++) {
        const int end = side ? g->nn[axis] - 1 : 0, l = end / GRID_B;
        if (l < lo || l >= hi) continue;
        for (int k = 0; k < S; k++) {
            const int slot = g->slot[layer_block(g, axis, l, k)];
            if (slot < 0) continue;
            const double *node = grid_block(g, slot);
            int bc[3];
            grid_block_coords(g, g->active[slot], bc);
            for (int li = 0; li < NPB; li++) {
                int gi[3];
                grid_node_index(g, bc, li, gi);
                if (gi[axis] != end || !(node[CH_M * NPB + li] > 0)) continue;
                size_t idx = 0;
                int in = 1;
                for (int d = 0; d < g->dim; d++)
                    if (d != axis) in &= gi[d] < g->nn[d], idx = idx * (size_t)g->nn[d] + (size_t)gi[d];
                if (in) f->wall[(size_t)side * P + idx] = 1;
            }
        }
    }
    ranks_max_bytes(f->wall, 2 * P);
    return HEARTH_OK;
}

int mpm_ranks_fields_wall(const hearth_scene *s, int d, const int gi[3]) {
    const mpm_state *m = s->mpm;
    int axis, lo, hi;
    if (!m || !m->sfields || !m->sfields->wall || !mpm_ranks_slab(m, &axis, &lo, &hi) || d != axis) return -1;
    const grid *g = &s->g;
    size_t idx = 0;
    for (int e = 0; e < g->dim; e++)
        if (e != axis) {
            if (gi[e] >= g->nn[e]) return 0;
            idx = idx * (size_t)g->nn[e] + (size_t)gi[e];
        }
    return m->sfields->wall[(gi[axis] == 0 ? 0 : plane_nodes(g, axis)) + idx];
}

hearth_status mpm_ranks_fields_fill(hearth_scene *s, const int *ch, int nc, hearth_error *err) {
    mpm_state *m = s->mpm;
    int axis, lo, hi;
    if (!mpm_ranks_slab(m, &axis, &lo, &hi) || !fields_live(s)) return HEARTH_OK;
    const int me = ranks_rank(), dn = me > 0, up = me + 1 < m->nranks;
    hearth_status st = state(m, err);
    if (st) return st;
    if (!ch) { /* the first fill of a step (after P2G): which active blocks this rank owns */
        struct mpm_slab_fields *f = m->sfields;
        const grid *g = &s->g;
        if (g->nactive > f->owncap) {
            unsigned char *o = mem_alloc((size_t)g->nactive * 2);
            if (!o) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the slab's block owners (%d blocks)", g->nactive);
            mem_free(f->own, (size_t)f->owncap);
            f->own = o, f->owncap = g->nactive * 2;
        }
        for (int k = 0; k < g->nactive; k++) {
            int c[3];
            grid_block_coords(g, g->active[k], c);
            f->own[k] = c[axis] >= lo && c[axis] < hi;
        }
        if ((st = wall_planes(s, axis, lo, hi, err))) return st;
    }
    /* the first layer goes down (the lower neighbour's upper halo), the last up */
    return exchange(s, ch, nc, dn ? lo : -1, up ? hi - 1 : -1, 0, dn ? lo - 1 : -1, up ? hi : -1, 2, err);
}

hearth_status mpm_ranks_fields_sum(hearth_scene *s, const int *ch, int nc, hearth_error *err) {
    mpm_state *m = s->mpm;
    int axis, lo, hi;
    if (!mpm_ranks_slab(m, &axis, &lo, &hi) || !fields_live(s)) return HEARTH_OK;
    const int me = ranks_rank(), dn = me > 0, up = me + 1 < m->nranks;
    /* the halo layers' scatters go to their owners, which add them after their own */
    hearth_status st = exchange(s, ch, nc, dn ? lo - 1 : -1, up ? hi : -1, 1, dn ? lo : -1, up ? hi - 1 : -1, 3, err);
    return st ? st : mpm_ranks_fields_fill(s, ch, nc, err);
}

hearth_status mpm_ranks_fields_fill_flags(hearth_scene *s, unsigned char *flag, hearth_error *err) {
    mpm_state *m = s->mpm;
    int axis, lo, hi;
    if (!mpm_ranks_slab(m, &axis, &lo, &hi) || !fields_live(s)) return HEARTH_OK;
    struct mpm_slab_fields *f = m->sfields;
    const grid *g = &s->g;
    const int S = g->nblocks / g->nb[axis], me = ranks_rank(), dn = me > 0, up = me + 1 < m->nranks;
    size_t nd = 0, nu = 0; /* the layers' active blocks in layer order (f->lay: 2 S bytes, mpm_ranks_fields_mark) */
    for (int k = 0; k < S; k++) {
        const int a = g->slot[layer_block(g, axis, lo, k)], b = g->slot[layer_block(g, axis, hi - 1, k)];
        if (dn && a >= 0) f->lay[nd++] = flag[a];
        if (up && b >= 0) f->lay[S + nu++] = flag[b];
    }
    const void *from_lo, *from_hi;
    size_t nlo, nhi;
    hearth_status st = ranks_neighbours(f->lay, nd, f->lay + S, nu, &from_lo, &nlo, &from_hi, &nhi, err);
    if (st) return st;
    for (int side = 0; side < 2; side++) {
        if (side ? !up : !dn) continue;
        const int l = side ? hi : lo - 1;
        const unsigned char *src = side ? from_hi : from_lo;
        size_t r = 0;
        for (int k = 0; k < S; k++) {
            const int a = g->slot[layer_block(g, axis, l, k)];
            if (a < 0) continue;
            if (r == (side ? nhi : nlo)) return err_set(err, HEARTH_ERR_STATE, "slabs: a halo layer does not match its owner's blocks");
            flag[a] = src[r++];
        }
    }
    return HEARTH_OK;
}

void mpm_ranks_fields_clear(hearth_scene *s) {
    mpm_state *m = s->mpm;
    int axis, lo, hi;
    if (!mpm_ranks_slab(m, &axis, &lo, &hi) || !fields_live(s)) return;
    grid *g = &s->g;
    const int NPB = g->nodes_per_block, S = g->nblocks / g->nb[axis];
    for (int side = 0; side < 2; side++) {
        const int l = side ? hi : lo - 1;
        if (l < 0 || l >= g->nb[axis]) continue;
        for (int k = 0; k < S; k++) {
            const int slot = g->slot[layer_block(g, axis, l, k)];
            if (slot >= 0) memset(grid_block(g, slot), 0, sizeof(double) * (size_t)g->nch * (size_t)NPB);
        }
    }
}

const unsigned char *mpm_ranks_fields_owned(const hearth_scene *s) {
    const mpm_state *m = s->mpm;
    int axis, lo, hi;
    if (!m || !mpm_ranks_slab(m, &axis, &lo, &hi) || !m->sfields) return NULL;
    return m->sfields->own;
}

void mpm_ranks_fields_reduce(const hearth_scene *s, double *sum, int nsum, double *max, int nmax) {
    const mpm_state *m = s->mpm;
    int axis, lo, hi;
    if (!m || !mpm_ranks_slab(m, &axis, &lo, &hi) || !fields_on(s)) return;
    if (m->failed_alone) return; /* this rank's own sums: it exchanges nothing after a failed step (mpm_ranks_end) */
    /* the step's sort made the state (mpm_ranks_fields_mark): every rank got here through it */
    HEARTH_ASSERT(m->sfields && nsum + nmax <= RED_MAX);
    const int w = nsum + nmax;
    double mine[RED_MAX] = {0}, *all = m->sfields->red;
    for (int k = 0; k < nsum; k++) mine[k] = sum[k];
    for (int k = 0; k < nmax; k++) mine[nsum + k] = max[k];
    ranks_allgather_fixed(mine, all, sizeof(double) * (size_t)w);
    for (int k = 0; k < nsum; k++) { /* in rank order: the same bits on every rank */
        double t = 0;
        for (int r = 0; r < m->nranks; r++) t += all[r * w + k];
        sum[k] = t;
    }
    for (int k = 0; k < nmax; k++) {
        double t = all[nsum + k];
        for (int r = 1; r < m->nranks; r++)
            if (all[r * w + nsum + k] > t) t = all[r * w + nsum + k];
        max[k] = t;
    }
}

/* A contact point's owner: the rank whose slab holds the block of the point's
 * base node along the axis (grid_point_weights' floor, clamped to the grid). */
static int contact_layer(const grid *g, int axis, const double *ct) {
    const int b = (int)floor((ct[axis] - g->lo[axis]) * g->inv_dx - 0.5);
    const int l = (b < 0 ? b - (GRID_B - 1) : b) / GRID_B;
    return l < 0 ? 0 : l >= g->nb[axis] ? g->nb[axis] - 1 : l;
}

/* Why the points move: a point is its particle's foot on the collider's face,
 * up to CONTACT_BAND cells away from the particle and, for a particle pressed
 * into the collider, as deep as it went; its B-spline stencil (base node to
 * base + 2) then reaches past the one halo layer above the slab, into nodes no
 * copy of which this rank holds, and thermal.c's contact_stencil would drop
 * them and renormalise (issue #21). Held by the rank owning its base node's
 * block, the stencil stays within that slab and its upper halo layer, both
 * filled with the owners' values, and the scatter's halo share goes to its
 * owner with the transport's (mpm_ranks_fields_sum). Points moving more than
 * one slab go on in further passes. Order: a rank's own points in particle
 * order, then the lower neighbour's, then the upper's, per pass: the same on
 * every run with this rank count. */
hearth_status mpm_ranks_fields_contacts(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    int axis, lo, hi;
    if (!m || !mpm_ranks_slab(m, &axis, &lo, &hi) || !thermal_active(s)) return HEARTH_OK;
    int heated = 0; /* the same colliders on every rank: all ranks return here, or none */
    for (int c = 0; c < s->ncol; c++) heated += !isnan(s->cols[c].temperature) && s->cols[c].beta > 0;
    if (!heated) return HEARTH_OK;
    hearth_status st = state(m, err);
    if (st) return st;
    struct mpm_slab_fields *f = m->sfields;
    thermal_state *h = &s->heat;
    const grid *g = &s->g;
    const size_t W = THERMAL_CT;
    for (;;) {
        for (int k = 0; k < 2; k++)
            if ((size_t)h->nct * W > f->ccap[k]) {
                const size_t c = (size_t)h->nct * W + (size_t)h->nct * W / 4;
                double *b = mem_alloc(c * sizeof(double));
                if (!b) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for moving %d contact points between ranks", h->nct);
                mem_free(f->cbuf[k], f->ccap[k] * sizeof(double));
                f->cbuf[k] = b, f->ccap[k] = c;
            }
        size_t nd = 0, nu = 0;
        int keep = 0;
        for (int k = 0; k < h->nct; k++) {
            const double *ct = h->ct + W * (size_t)k;
            const int l = contact_layer(g, axis, ct);
            if (l < lo) memcpy(f->cbuf[0] + W * nd++, ct, W * sizeof(double));
            else if (l >= hi) memcpy(f->cbuf[1] + W * nu++, ct, W * sizeof(double));
            else memmove(h->ct + W * (size_t)keep++, ct, W * sizeof(double));
        }
        unsigned char more = nd || nu;
        ranks_max_bytes(&more, 1);
        if (!more) return HEARTH_OK; /* keep == nct */
        h->nct = keep;
        const void *from_lo, *from_hi;
        size_t nlo, nhi;
        if ((st = ranks_neighbours(f->cbuf[0], nd * W * sizeof(double), f->cbuf[1], nu * W * sizeof(double), &from_lo, &nlo,
                                   &from_hi, &nhi, err)))
            return st;
        const size_t add = (nlo + nhi) / sizeof(double), need = (size_t)keep * W + add;
        if (need > (size_t)h->ct_cap * W) {
            if (need / W > (size_t)INT32_MAX / W)
                return err_set(err, HEARTH_ERR_NOMEM, "too many heated collider contacts (%zu) on one rank", need / W);
            const int cap = (int)(need / W);
            double *x = mem_alloc(sizeof(double) * need);
            if (!x) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for %d heated collider contacts", cap);
            memcpy(x, h->ct, sizeof(double) * (size_t)keep * W);
            mem_free(h->ct, sizeof(double) * W * (size_t)h->ct_cap);
            h->ct = x, h->ct_cap = cap;
        }
        memcpy(h->ct + (size_t)keep * W, from_lo, nlo);
        memcpy(h->ct + (size_t)keep * W + nlo / sizeof(double), from_hi, nhi);
        h->nct = keep + (int)(add / W);
    }
}
