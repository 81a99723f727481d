/* mpm_ranks.c: one MPM scene over MPI ranks (#21), in two modes chosen per
 * step call (slabs_fit), never by the user.
 *
 * Slabs (domain decomposition). The box's block layers along its longest
 * axis are cut into one slab per rank, by particle count. A rank holds only
 * the particles whose base node's block lies in its slab, and activates only
 * the blocks they touch: its slab and one ghost layer, the upper neighbour's
 * first (a block's tile reaches its +1 neighbours only, so there is no ghost
 * on the lower face). After P2G the ghost blocks' sums go to their owner,
 * which adds them after its own; the owner runs the grid update and sends
 * the ghost blocks' values back (halo_sum, mpm_ranks_halo_back). At the next
 * sort particles that left the slab go to the neighbour (mpm_ranks_migrate).
 * The step report is combined over the ranks in rank order, along a tree. Every
 * MPM_RANKS_REBALANCE steps the cuts follow the particle counts. The slabs
 * stay across step calls until something reads the particles
 * (hearth_scene_whole, which every Lua scene method but the stepping ones
 * calls): then every rank gathers the whole set in rank order. Per step a rank
 * receives the ghost layer's sums or values and its marks, the particles
 * crossing its faces and at most log2 N step reports (a tree in rank order):
 * constant as the scene grows along the axis (docs/scaling.md, `mpi_halo_traffic_bounded_4`).
 *
 * Heat, water and CO2 run on slabs too (mpm_ranks_fields.c): with fields a
 * rank also holds one complete block layer each side of its slab (mark bit
 * 2; halo_sum and halo_back keep to bit 1's blocks), filled with the owners'
 * values after P2G and after each field scatter, so the boundary search, the
 * explicit update's small-node merge and the CG's vector updates run on
 * every block a rank holds; the CG's dot products and the field sums are
 * added in rank order. A heated collider's contact points go to the rank
 * owning their base node's block (their particle's foot on the face can lie
 * past the halo layer: mpm_ranks_fields_contacts), and every rank gets the
 * box's end planes' mass flags for the surface search's domain-wall test (the
 * end layer can lie past its halo: mpm_ranks_fields_wall). CO2 is a particle quantity
 * (G2P); stats() adds its sums over the ranks.
 *
 * Replicated (scenes whose passes read every particle inside a step: mixing,
 * periodic axes, the rollback guard, held bodies, wet colliders,
 * water_momentum; slabs_fit). Every rank holds
 * every particle and the whole grid; after the sort the particle blocks are
 * cut into one contiguous run per rank; each rank runs P2G and G2P for its
 * run only; the written node slots are summed over the ranks in rank order
 * (ranks_sum_grid), every rank runs the grid update and the field passes on
 * the whole grid, and after G2P every rank's particles go to every rank.
 *
 * Rejected: MPI_Allreduce for the grid (its summation order is the MPI
 * library's choice, so two runs could differ in the last bit); slabs of equal
 * width (a block of dough on one side of the box would leave ranks idle); a
 * gather at the end of every step call (s:step(n) and s:run call the core one
 * step, or 64, at a time: the whole set would move every step); a whole-set
 * gather to rebalance (each rank's per-layer counts, added in rank order,
 * give the same cuts everywhere, and neighbour passes move the particles).
 *
 * Determinism: the cuts depend only on the particles and the rank count; a
 * rank's particles are its residents in order, then the lower neighbour's
 * arrivals, then the upper's, then the stable sort; each rank's P2G sums its
 * blocks in the usual colour order, and a ghost node adds the neighbour's
 * sum after the owner's. A node touched by one rank only has the bits of the
 * one-process run; a node on a seam sums the same terms in another grouping
 * (a few ulps, `mpi_elastic_matches_one_rank`). */
#include <math.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "mixing.h"
#include "mpm.h"
#include "mpm_touch.h"
#include "particles.h"
#include "ranks.h"
#include "thermal.h"
#include "water.h"

/* what each rank tells the others after G2P in the slab mode */
typedef struct rank_report {
    step_report rep;
    double vcol; /* the fastest collider speed at a node with mass among this rank's own blocks */
    long clamped; /* particles the sort put back inside the grid this step */
    int n, blocks; /* particles; active blocks outside the ghost layer */
} rank_report;

/* Slabs (the decomposed mode): while live, this rank holds only the particles
 * whose base node's block lies in block layers [cut[me], cut[me + 1]) along
 * axis. */
struct mpm_slabs {
    int live, axis, nlayer;
    int keep;               /* the host calls hearth_scene_whole before reading: slabs stay between step calls */
    long ood0;              /* s->out_of_domain when this step's sort began (the sort counts its own clamps) */
    int ntotal;             /* particles over all ranks (a step neither adds nor removes any) */
    int blocks;             /* active blocks over all ranks, each counted by its owner (the last step's) */
    unsigned char *lowmark; /* the layer cut[me]'s blocks the lower neighbour's particles touch */
    size_t lowcap;
    double *halo;           /* packed node values of ghost blocks */
    size_t halocap;         /* doubles */
    int *cut;               /* nranks + 1 */
    int *count;             /* nlayer: particles per block layer */
    long balanced;          /* the step at which the cuts were last set */
    unsigned char *drop;    /* per particle: leaves this rank */
    size_t dropcap;
    unsigned char *out[2];  /* packed particles for the lower and the upper neighbour */
    size_t outcap[2];
    int *nall;              /* nranks + 1: every rank's particle count, then the prefix */
    uint64_t *touch;        /* the touch masks: the ghost layer's, packed to send up, then the layer cut[me]'s from
                             * below (layer blocks x faces, 0 where none came; mpm_touch.c) */
    size_t touchcap;        /* uint64_t */
    int touch_nf;           /* faces a block's masks hold (mpm_touch_faces), 0 when none came this step */
};

/* (a test may give the state a rank count by hand, without the slab tables) */
static int slabs_live(const mpm_state *m) { return m->slabs && m->slabs->live; }

hearth_status mpm_ranks_init(mpm_state *m, hearth_error *err) {
    m->nranks = ranks_size();
    m->kfirst = mem_calloc(sizeof(int) * ((size_t)m->nranks + 1));
    m->pfirst = mem_calloc(sizeof(int) * ((size_t)m->nranks + 1));
    m->slabs = mem_calloc(sizeof(struct mpm_slabs));
    if (!m->kfirst || !m->pfirst || !m->slabs) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the MPM rank tables");
    struct mpm_slabs *sl = m->slabs;
    sl->cut = mem_calloc(sizeof(int) * ((size_t)m->nranks + 1));
    sl->nall = mem_calloc(sizeof(int) * ((size_t)m->nranks + 1));
    if (!sl->cut || !sl->nall) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the MPM rank tables");
    return HEARTH_OK;
}

void mpm_ranks_free(mpm_state *m) {
    mpm_ranks_fields_free(m);
    struct mpm_slabs *sl = m->slabs;
    if (sl) {
        mem_free(sl->cut, sizeof(int) * ((size_t)m->nranks + 1));
        mem_free(sl->nall, sizeof(int) * ((size_t)m->nranks + 1));
        mem_free(sl->count, sizeof(int) * (size_t)sl->nlayer * ((size_t)m->nranks + 2));
        mem_free(sl->drop, sl->dropcap);
        mem_free(sl->lowmark, sl->lowcap);
        mem_free(sl->halo, sl->halocap * sizeof(double));
        for (int k = 0; k < 2; k++) mem_free(sl->out[k], sl->outcap[k]);
        mem_free(sl->touch, sl->touchcap * sizeof(uint64_t));
        mem_free(sl, sizeof *sl);
        m->slabs = NULL;
    }
    mem_free(m->kfirst, sizeof(int) * ((size_t)m->nranks + 1));
    mem_free(m->pfirst, sizeof(int) * ((size_t)m->nranks + 1));
    m->kfirst = m->pfirst = NULL;
}

void mpm_ranks_partition(hearth_scene *s) {
    mpm_state *m = s->mpm;
    const int N = m->nranks, n = s->ps.n;
    if (N == 1 || slabs_live(m)) { /* slabs: every particle this rank holds is its own */
        m->k_lo = 0, m->k_hi = m->npb;
        return;
    }
    /* block k goes to rank floor(start_k N / n): runs in block order, about n / N
     * particles each; rank r's run starts at the first block with start_k N >= r n */
    int k = 0;
    for (int r = 0; r <= N; r++) {
        while (k < m->npb && (long long)m->pb[k].start * N < (long long)r * n) k++;
        m->kfirst[r] = k;
    }
    for (int r = 0; r <= N; r++) m->pfirst[r] = m->kfirst[r] < m->npb ? m->pb[m->kfirst[r]].start : n;
    const int me = ranks_rank();
    m->k_lo = m->kfirst[me], m->k_hi = m->kfirst[me + 1];
}

static hearth_status halo_sum(hearth_scene *s, hearth_error *err);

hearth_status mpm_ranks_sum_grid(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    if (m->nranks == 1) return HEARTH_OK;
    if (slabs_live(m)) {
        hearth_status st = halo_sum(s, err);
        /* heat and water: the halo layers get every channel of their owners' blocks */
        return st ? st : mpm_ranks_fields_fill(s, NULL, 0, err);
    }
    const grid *g = &s->g;
    int lo = 0, hi = 0;
    if (m->k_hi > m->k_lo) {
        /* slots ascend with block ids, and a block's tile reaches its +1 neighbours:
         * this rank wrote slots from its first block's to its last block's (+1, +1, +1) */
        int c[3];
        grid_block_coords(g, m->pb[m->k_hi - 1].block, c);
        lo = g->slot[m->pb[m->k_lo].block];
        hi = g->slot[grid_block_id(g, c[0] + 1, c[1] + 1, c[2] + (g->dim == 3))] + 1;
        HEARTH_ASSERT(lo >= 0 && hi > lo && hi <= g->nactive);
    }
    hearth_status st = ranks_sum_grid(&s->g, lo, hi, err);
    if (st) return st;
    /* the field passes between P2G and G2P read every particle's volume (whether
     * to gather is the scene's, never this rank's pointer: mpm_reserve made it) */
    if (thermal_active(s) || water_active(s)) ranks_allgather(m->vol, sizeof(double), m->pfirst);
    return HEARTH_OK;
}

void mpm_ranks_gather(hearth_scene *s) {
    mpm_state *m = s->mpm;
    if (m->nranks == 1 || slabs_live(m)) return;
    particles *ps = &s->ps;
    ranks_allgather(m->partial, sizeof(pb_partial), m->kfirst);
    /* G2P filed its own particles' sort keys (mpm_sort.c): the other ranks' come with their particles */
    ranks_allgather(m->keys, sizeof(int), m->pfirst);
    for (int c = 0; c < PC_COUNT; c++)
        if ((ps->enabled & (1u << c)) && ps->col[c]) ranks_allgather(ps->col[c], particles_col_bytes(ps, c), m->pfirst);
}

/* ---- slabs: particles owned by rank --------------------------------- */

/* The slab mode holds, per rank, only the particles of its slab, so anything
 * that reads every particle inside a step must not run. Heat, water and CO2
 * run on slabs (mpm_ranks_fields.c); the scenes that keep the replicated mode
 * above, chosen here for the whole step call, are: mixing (a particle pass
 * before the sort), periodic axes (wrapped on the whole set), the rollback
 * guard (its snapshot is the whole scene), bodies with fixed_temperature
 * (thermal.c's held nodes sum the held particles' capacity outside P2G),
 * wet colliders (water.c's held saturations read nodes up to three cells
 * from the face and scatter without a tile) and water_momentum (the
 * transport adds into the momentum the halo layers already hold). */
static int slabs_fit(const hearth_scene *s) {
    const mpm_state *m = s->mpm;
    if (m->nranks == 1 || !m->slabs) return 0;
    if (mixing_active(s)) return 0;
    if (s->def.periodic[0] || s->def.periodic[1] || s->def.periodic[2]) return 0;
    if (s->def.guard == HEARTH_GUARD_ROLLBACK) return 0;
    if (water_active(s)) {
        if (s->def.water_momentum) return 0;
        for (int c = 0; c < s->ncol; c++)
            if (!isnan(s->cols[c].saturation)) return 0;
    }
    if (thermal_active(s) && (s->ps.enabled & (1u << PC_FLAGS))) {
        const int *flags = pcoli(&s->ps, PC_FLAGS);
        for (int i = 0; i < s->ps.n; i++)
            if (flags[i] & PF_HOLD_T) return 0;
    }
    int axis = 0;
    for (int d = 1; d < s->g.dim; d++)
        if (s->g.nb[d] > s->g.nb[axis]) axis = d;
    return s->g.nb[axis] >= m->nranks; /* every slab at least one block layer thick */
}

/* The block layer along the slab axis of particle i's base node (clamped to
 * the grid as the sort does, without moving the particle). */
static int layer_of(const hearth_scene *s, int axis, const double *x) {
    const grid *g = &s->g;
    double xa = x[axis];
    const double lo = g->lo[axis] + g->dx, hi = g->lo[axis] + (g->nn[axis] - 2) * g->dx;
    if (!(xa >= lo)) xa = lo;
    else if (xa > hi) xa = hi;
    return base_node((xa - g->lo[axis]) * g->inv_dx) / GRID_B;
}

static int owner_of(const struct mpm_slabs *sl, int N, int layer) {
    int r = 0;
    while (r + 1 < N && layer >= sl->cut[r + 1]) r++;
    return r;
}

/* The cuts from the particle counts per layer (the whole set's, or every
 * rank's added in rank order: the same cuts on every rank): rank r starts at
 * the layer boundary nearest r n / N, and every slab keeps at least one layer. */
static hearth_status slabs_cut(hearth_scene *s, int spread, hearth_error *err) {
    mpm_state *m = s->mpm;
    struct mpm_slabs *sl = m->slabs;
    const int N = m->nranks;
    int axis = 0;
    for (int d = 1; d < s->g.dim; d++)
        if (s->g.nb[d] > s->g.nb[axis]) axis = d;
    const int L = s->g.nb[axis];
    if (L != sl->nlayer) {
        int *c = mem_alloc(sizeof(int) * (size_t)L * ((size_t)N + 2));
        if (!c) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the slab counts");
        mem_free(sl->count, sizeof(int) * (size_t)sl->nlayer * ((size_t)N + 2));
        sl->count = c, sl->nlayer = L;
    }
    sl->axis = axis;
    int *mine = sl->count + L, *all = sl->count + 2 * L;
    memset(mine, 0, sizeof(int) * (size_t)L);
    const double *X = pcold(&s->ps, PC_X);
    for (int i = 0; i < s->ps.n; i++) mine[layer_of(s, axis, X + 3 * i)]++;
    /* spread over the ranks: every rank's counts (L ints each), added in rank
     * order (integers: exact); else every rank counted the same whole set */
    if (spread) ranks_allgather_fixed(mine, all, sizeof(int) * (size_t)L);
    long long n = 0;
    for (int l = 0; l < L; l++) {
        int c = spread ? 0 : mine[l];
        if (spread)
            for (int r = 0; r < N; r++) c += all[(size_t)r * L + l];
        sl->count[l] = c;
        n += c;
    }
    long long before = 0;
    int l = 0;
    sl->cut[0] = 0;
    for (int r = 1; r < N; r++) {
        while (l < L && before * N < (long long)r * n) before += sl->count[l++];
        /* the layer boundary nearest r n / N: the first one past it can
         * overshoot by a whole layer (a block of 4 layers on 4 ranks gave
         * rank 0 more than half its particles) */
        int c = l;
        if (l > 0 && (long long)r * n - (before - sl->count[l - 1]) * N < before * N - (long long)r * n) c = l - 1;
        if (c < sl->cut[r - 1] + 1) c = sl->cut[r - 1] + 1;
        if (c > L - (N - r)) c = L - (N - r);
        sl->cut[r] = c;
    }
    sl->cut[N] = L;
    sl->balanced = s->step;
    return HEARTH_OK;
}

/* From the whole set to this rank's slab: no message, every rank drops the others'. */
static hearth_status slabs_scatter(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    struct mpm_slabs *sl = m->slabs;
    hearth_status st = slabs_cut(s, 0, err);
    if (st) return st;
    const int n = s->ps.n, me = ranks_rank();
    if ((size_t)n > sl->dropcap) {
        unsigned char *d = mem_alloc((size_t)n);
        if (!d) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the slab split (%d particles)", n);
        mem_free(sl->drop, sl->dropcap);
        sl->drop = d, sl->dropcap = (size_t)n;
    }
    const double *X = pcold(&s->ps, PC_X);
    for (int i = 0; i < n; i++) sl->drop[i] = owner_of(sl, m->nranks, layer_of(s, sl->axis, X + 3 * i)) != me;
    sl->ntotal = n;
    particles_compact(&s->ps, sl->drop);
    sl->live = 1;
    return HEARTH_OK;
}

/* From the slabs to the whole set on every rank, in rank order (rank 0's
 * particles, then rank 1's, ...): the order the step report's particle
 * indices refer to (mpm_ranks_report). */
static hearth_status slabs_gather(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    struct mpm_slabs *sl = m->slabs;
    particles *ps = &s->ps;
    const int N = m->nranks, me = ranks_rank();
    int mine = ps->n;
    ranks_allgather_fixed(&mine, sl->nall, sizeof(int));
    int *first = m->pfirst;
    first[0] = 0;
    for (int r = 0; r < N; r++) first[r + 1] = first[r] + sl->nall[r];
    /* every rank learns every count before any can fail, so a rank that
     * cannot grow says so alone: the caller stops (and mpirun ends the job) */
    hearth_status st = particles_reserve(ps, first[N], err);
    if (st) return st;
    for (int c = 0; c < PC_COUNT; c++) {
        if (!(ps->enabled & (1u << c)) || !ps->col[c]) continue;
        const size_t b = particles_col_bytes(ps, c);
        char *col = ps->col[c];
        if (first[me]) memmove(col + b * (size_t)first[me], col, b * (size_t)mine);
        ranks_allgather(col, b, first);
    }
    ps->n = first[N];
    ps->edits++;
    sl->live = 0;
    return HEARTH_OK;
}

int mpm_ranks_slab(const mpm_state *m, int *axis, int *lo, int *hi) {
    if (!slabs_live(m)) return 0;
    const int me = ranks_rank();
    *axis = m->slabs->axis, *lo = m->slabs->cut[me], *hi = m->slabs->cut[me + 1];
    return 1;
}

void mpm_ranks_begin(hearth_scene *s) {
    mpm_state *m = s->mpm;
    if (!m || slabs_live(m) || !slabs_fit(s)) return;
    /* water's step limits from the whole set, before it is split (water_finish keeps them over the ranks) */
    water_keep_limits(s);
    /* every rank holds the same whole set here: a failure (out of memory for
     * the drop flags) is the same on every rank, and the run stays replicated */
    if (slabs_scatter(s, NULL)) m->slabs->live = 0;
}

void mpm_ranks_keep(hearth_scene *s, int on) {
    if (s->mpm && s->mpm->slabs) s->mpm->slabs->keep = on != 0;
}

/* A failed step call leaves the ranks where each one stopped: a rank that ran
 * out of memory (or found a halo not matching its owner's) returns at once,
 * while the others wait for its part of the next exchange. Were it to go on
 * to the host's next collective (the gather below, stats()' sums, the run
 * record), every rank would wait for ever (#21: an empty rank's spurious
 * "out of memory" hung wall_column.lua at 4 ranks). So, but for the guard's
 * stop, which the combined step report gives every rank at the same point,
 * a failed call ends this rank's exchanges; the host reports the error and
 * leaves, and mpirun ends the others. Rejected: agreeing on the failure
 * over the ranks (the others are inside a neighbour exchange, not at a
 * point where they could learn it). */
hearth_status mpm_ranks_end(hearth_scene *s, hearth_status st, hearth_error *err) {
    mpm_state *m = s->mpm;
    if (m && m->nranks > 1 && st && st != HEARTH_ERR_GUARD) m->failed_alone = 1;
    if (!m || !slabs_live(m) || m->slabs->keep || m->failed_alone) return st;
    hearth_error e2;
    const hearth_status g = slabs_gather(s, st ? &e2 : err); /* a host that reads the scene directly */
    return st ? st : g;
}

hearth_status mpm_ranks_usable(const hearth_scene *s, hearth_error *err) {
    const mpm_state *m = s->mpm;
    if (!m || !m->failed_alone) return HEARTH_OK;
    return err_set(err, HEARTH_ERR_STATE,
                   "MPI rank %d: an earlier step failed on this rank, perhaps on it alone, so it takes part in no exchange with the "
                   "other ranks again; end the run (mpirun then ends every rank)",
                   ranks_rank());
}

hearth_status mpm_ranks_whole(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    if (!m || !slabs_live(m)) return HEARTH_OK;
    hearth_status st = mpm_ranks_usable(s, err);
    if (st) return st;
    return slabs_gather(s, err);
}

int mpm_ranks_blocks(const hearth_scene *s) {
    const mpm_state *m = s->mpm;
    return m && slabs_live(m) ? m->slabs->blocks : s->g.nactive;
}

int mpm_ranks_holds_slab(const hearth_scene *s) { return s->mpm && slabs_live(s->mpm); }

int mpm_ranks_particles(const hearth_scene *s) {
    const mpm_state *m = s->mpm;
    return m && slabs_live(m) ? m->slabs->ntotal : s->ps.n;
}

/* A particle's bytes, every enabled column in column order. */
static size_t particle_bytes(const particles *ps) {
    size_t b = 0;
    for (int c = 0; c < PC_COUNT; c++)
        if ((ps->enabled & (1u << c)) && ps->col[c]) b += particles_col_bytes(ps, c);
    return b;
}

static void pack(const particles *ps, int i, unsigned char *dst) {
    for (int c = 0; c < PC_COUNT; c++) {
        if (!(ps->enabled & (1u << c)) || !ps->col[c]) continue;
        const size_t b = particles_col_bytes(ps, c);
        memcpy(dst, (const char *)ps->col[c] + b * (size_t)i, b);
        dst += b;
    }
}

static void unpack(particles *ps, int i, const unsigned char *src) {
    for (int c = 0; c < PC_COUNT; c++) {
        if (!(ps->enabled & (1u << c)) || !ps->col[c]) continue;
        const size_t b = particles_col_bytes(ps, c);
        memcpy((char *)ps->col[c] + b * (size_t)i, src, b);
        src += b;
    }
}

static hearth_status grow(unsigned char **buf, size_t *cap, size_t need, hearth_error *err) {
    if (need <= *cap) return HEARTH_OK;
    const size_t c = need + need / 2;
    unsigned char *b = mem_alloc(c);
    if (!b) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the particles leaving this rank (%zu bytes)", c);
    mem_free(*buf, *cap);
    *buf = b, *cap = c;
    return HEARTH_OK;
}

/* One pass: every particle whose owner is below this rank goes down, above
 * goes up. Returns in *far whether any rank sent a particle that is not yet
 * at its owner (it goes on in the next pass). */
static hearth_status migrate_pass(hearth_scene *s, unsigned char *far, hearth_error *err) {
    mpm_state *m = s->mpm;
    struct mpm_slabs *sl = m->slabs;
    particles *ps = &s->ps;
    const int n = ps->n, N = m->nranks, me = ranks_rank();
    if ((size_t)n > sl->dropcap) {
        unsigned char *d = mem_alloc((size_t)n + (size_t)n / 2);
        if (!d) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the slab crossings (%d particles)", n);
        mem_free(sl->drop, sl->dropcap);
        sl->drop = d, sl->dropcap = (size_t)n + (size_t)n / 2;
    }
    const double *X = pcold(ps, PC_X);
    int ndown = 0, nup = 0;
    *far = 0;
    for (int i = 0; i < n; i++) {
        const int r = owner_of(sl, N, layer_of(s, sl->axis, X + 3 * i));
        sl->drop[i] = r < me ? 1 : r > me ? 2 : 0;
        ndown += r < me, nup += r > me;
        *far |= r < me - 1 || r > me + 1;
    }
    const size_t pb = particle_bytes(ps);
    hearth_status st;
    if ((st = grow(&sl->out[0], &sl->outcap[0], pb * (size_t)ndown, err)) ||
        (st = grow(&sl->out[1], &sl->outcap[1], pb * (size_t)nup, err)))
        return st;
    int kd = 0, ku = 0;
    for (int i = 0; i < n; i++)
        if (sl->drop[i] == 1) pack(ps, i, sl->out[0] + pb * (size_t)kd++);
        else if (sl->drop[i] == 2) pack(ps, i, sl->out[1] + pb * (size_t)ku++);
    const void *lo, *hi;
    size_t nlo, nhi;
    if ((st = ranks_neighbours(sl->out[0], pb * (size_t)ndown, sl->out[1], pb * (size_t)nup, &lo, &nlo, &hi, &nhi, err))) return st;
    if (ndown + nup == 0 && nlo + nhi == 0) return HEARTH_OK; /* G2P's keys still stand */
    if (ndown + nup) particles_compact(ps, sl->drop);
    const int arrive = (int)((nlo + nhi) / pb), n0 = ps->n;
    if ((st = particles_reserve(ps, n0 + arrive, err))) return st;
    /* residents in their order, then the lower neighbour's, then the upper's: the
     * same for a given rank count, and the sort that follows is stable */
    for (int k = 0; k < (int)(nlo / pb); k++) unpack(ps, n0 + k, (const unsigned char *)lo + pb * (size_t)k);
    for (int k = 0; k < (int)(nhi / pb); k++) unpack(ps, n0 + (int)(nlo / pb) + k, (const unsigned char *)hi + pb * (size_t)k);
    ps->n = n0 + arrive;
    ps->edits++;
    return HEARTH_OK;
}

hearth_status mpm_ranks_migrate(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    if (!slabs_live(m)) return HEARTH_OK;
    struct mpm_slabs *sl = m->slabs;
    sl->ood0 = s->out_of_domain;
    hearth_status st;
    /* every MPM_RANKS_REBALANCE steps the cuts follow the particle count: each
     * rank counts its particles per layer, the counts are added in rank order,
     * and every rank finds the same new cuts (slabs_cut) */
    if (s->step - sl->balanced >= MPM_RANKS_REBALANCE && (st = slabs_cut(s, 1, err))) return st;
    /* A particle moves less than a cell a step (the guard stops a step that
     * moves one further) and a slab is at least a block of 4 cells, so after a
     * step it crosses at most one face: one pass. After a rebalance, or a
     * particle a collider or a plugin threw further, passes go on (each moves
     * it one rank closer; at most N - 1) until none is left on the way. */
    unsigned char far;
    do {
        if ((st = migrate_pass(s, &far, err))) return st;
        ranks_max_bytes(&far, 1);
        if (far) ranks_count_step(2);
    } while (far);
    return HEARTH_OK;
}

/* The blocks of block layer l along the slab axis, in one fixed order (the
 * same on every rank): calls fn(id, k) for the k-th block of the layer. */
#define FOR_LAYER(g, axis, l, id, k, body)                                                        \
    do {                                                                                          \
        const int o1_ = (axis) == 0 ? 1 : 0, o2_ = (axis) == 2 ? 1 : 2;                           \
        int k = 0;                                                                                \
        for (int i1_ = 0; i1_ < (g)->nb[o1_]; i1_++)                                              \
            for (int i2_ = 0; i2_ < (g)->nb[o2_]; i2_++, k++) {                                   \
                int c_[3];                                                                        \
                c_[axis] = (l), c_[o1_] = i1_, c_[o2_] = i2_;                                     \
                const int id = grid_block_id((g), c_[0], c_[1], c_[2]);                           \
                (void)id, (void)k;                                                                \
                body                                                                              \
            }                                                                                     \
    } while (0)

static int layer_blocks(const grid *g, int axis) { return g->nblocks / g->nb[axis]; }

/* The ghost layer: the first layer of the upper neighbour's slab, which this
 * rank's particles in its own last layer reach (a block's tile reaches its +1
 * neighbours only, so the lower face has none). */
static int ghost_layer(const mpm_state *m) {
    const int me = ranks_rank();
    return me + 1 < m->nranks ? m->slabs->cut[me + 1] : -1;
}

hearth_status mpm_ranks_mark(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    if (!slabs_live(m)) return HEARTH_OK;
    struct mpm_slabs *sl = m->slabs;
    const grid *g = &s->g;
    const int S = layer_blocks(g, sl->axis), up = ghost_layer(m), me = ranks_rank();
    hearth_status st = grow(&sl->out[1], &sl->outcap[1], (size_t)S, err);
    if (st) return st;
    if ((size_t)S > sl->lowcap) {
        unsigned char *b = mem_alloc((size_t)S);
        if (!b) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the ghost layer's marks (%d blocks)", S);
        mem_free(sl->lowmark, sl->lowcap);
        sl->lowmark = b, sl->lowcap = (size_t)S;
    }
    /* the ghost layer's touched blocks go up; the lower neighbour's come in and
     * get storage here too, so its sums have somewhere to land */
    if (up >= 0) FOR_LAYER(g, sl->axis, up, id, k, { sl->out[1][k] = m->mark[id] & 1; });
    const void *lo, *hi;
    size_t nlo, nhi;
    if ((st = ranks_neighbours(NULL, 0, sl->out[1], up >= 0 ? (size_t)S : 0, &lo, &nlo, &hi, &nhi, err))) return st;
    memset(sl->lowmark, 0, (size_t)S);
    if (me > 0) {
        HEARTH_ASSERT(nlo == (size_t)S);
        memcpy(sl->lowmark, lo, (size_t)S);
        FOR_LAYER(g, sl->axis, sl->cut[me], id, k, { m->mark[id] |= sl->lowmark[k]; });
    }
    /* heat and water: a complete layer each side (mark bit 2; halo_sum and halo_back move bit 1's blocks) */
    return mpm_ranks_fields_mark(s, err);
}

static hearth_status halo_reserve(struct mpm_slabs *sl, size_t n, hearth_error *err) {
    if (n <= sl->halocap) return HEARTH_OK;
    double *b = mem_alloc((n + n / 4) * sizeof(double));
    if (!b) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the ghost blocks' node values (%zu bytes)", n * sizeof(double));
    mem_free(sl->halo, sl->halocap * sizeof(double));
    sl->halo = b, sl->halocap = n + n / 4;
    return HEARTH_OK;
}

/* A slip or separate face holds a node only where a particle in its stencil touches the face (mpm_touch.c),
 * and the particles whose stencils reach the first layer of a slab include the lower neighbour's: after the
 * ghost layer's sums, its touch masks (every face's, for each block this rank's particles touched) go up too,
 * and the owner ORs them into its own (mpm_ranks_touch_below), so a node on a seam is held as on one rank. */
static hearth_status halo_touch(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    struct mpm_slabs *sl = m->slabs;
    const grid *g = &s->g;
    const int up = ghost_layer(m), me = ranks_rank(), F = mpm_touch_faces(s), S = layer_blocks(g, sl->axis);
    const size_t need = (size_t)S * (size_t)F;
    if (need > sl->touchcap) {
        uint64_t *b = mem_alloc(need * sizeof(uint64_t));
        if (!b) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the seam's touch masks (%zu bytes)", need * sizeof(uint64_t));
        mem_free(sl->touch, sl->touchcap * sizeof(uint64_t));
        sl->touch = b, sl->touchcap = need;
    }
    size_t nup = 0;
    if (up >= 0)
        FOR_LAYER(g, sl->axis, up, id, k, {
            if (m->mark[id] & 1) {
                int bc[3];
                grid_block_coords(g, id, bc);
                for (int f = 0; f < F; f++) sl->touch[nup++] = mpm_touch_face_mask(s, bc, f, m->step_dt);
            }
        });
    const void *lo, *hi;
    size_t nlo, nhi;
    hearth_status st = ranks_neighbours(NULL, 0, sl->touch, nup * sizeof(uint64_t), &lo, &nlo, &hi, &nhi, err);
    if (st) return st;
    memset(sl->touch, 0, need * sizeof(uint64_t));
    sl->touch_nf = 0;
    if (me > 0) {
        const uint64_t *src = lo;
        size_t r = 0;
        FOR_LAYER(g, sl->axis, sl->cut[me], id, k, {
            if (sl->lowmark[k]) {
                memcpy(sl->touch + (size_t)k * (size_t)F, src + r, (size_t)F * sizeof(uint64_t));
                r += (size_t)F;
            }
        });
        HEARTH_ASSERT(r * sizeof(uint64_t) == nlo);
        sl->touch_nf = F;
    }
    return HEARTH_OK;
}

uint64_t mpm_ranks_touch_below(const hearth_scene *s, int id, int f) {
    const mpm_state *m = s->mpm;
    if (!slabs_live(m) || !m->slabs->touch_nf) return 0;
    const struct mpm_slabs *sl = m->slabs;
    const grid *g = &s->g;
    int c[3];
    grid_block_coords(g, id, c);
    if (c[sl->axis] != sl->cut[ranks_rank()]) return 0;
    const int o1 = sl->axis == 0 ? 1 : 0, o2 = sl->axis == 2 ? 1 : 2; /* FOR_LAYER's order */
    const int k = c[o1] * g->nb[o2] + c[o2];
    return sl->touch[(size_t)k * (size_t)sl->touch_nf + (size_t)f];
}

/* After P2G: this rank's sums on the ghost layer go to their owner, which adds
 * them after its own (own, then the lower neighbour's: a fixed order); here
 * they are cleared, so the grid update sees only blocks this rank owns. */
static hearth_status halo_sum(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    struct mpm_slabs *sl = m->slabs;
    grid *g = &s->g;
    const int up = ghost_layer(m), me = ranks_rank();
    const size_t sd = (size_t)g->nch * (size_t)g->nodes_per_block;
    size_t nup = 0;
    if (up >= 0) FOR_LAYER(g, sl->axis, up, id, k, { nup += m->mark[id] & 1 ? sd : 0; });
    hearth_status st = halo_reserve(sl, nup, err);
    if (st) return st;
    size_t w = 0;
    if (up >= 0)
        FOR_LAYER(g, sl->axis, up, id, k, {
            if (m->mark[id] & 1) {
                double *b = grid_block(g, g->slot[id]);
                memcpy(sl->halo + w, b, sd * sizeof(double));
                memset(b, 0, sd * sizeof(double));
                w += sd;
            }
        });
    const void *lo, *hi;
    size_t nlo, nhi;
    if ((st = ranks_neighbours(NULL, 0, sl->halo, nup * sizeof(double), &lo, &nlo, &hi, &nhi, err))) return st;
    if (me > 0) {
        const double *src = lo;
        size_t r = 0;
        FOR_LAYER(g, sl->axis, sl->cut[me], id, k, {
            if (sl->lowmark[k]) {
                double *b = grid_block(g, g->slot[id]);
                for (size_t j = 0; j < sd; j++) b[j] += src[r + j];
                r += sd;
            }
        });
        HEARTH_ASSERT(r * sizeof(double) == nlo);
    }
    return halo_touch(s, err);
}

hearth_status mpm_ranks_halo_back(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    if (!slabs_live(m)) return HEARTH_OK;
    struct mpm_slabs *sl = m->slabs;
    grid *g = &s->g;
    const int up = ghost_layer(m), me = ranks_rank();
    const size_t sd = (size_t)g->nch * (size_t)g->nodes_per_block;
    /* the owner's updated values of the blocks the lower neighbour touched go back down */
    size_t ndown = 0;
    if (me > 0) FOR_LAYER(g, sl->axis, sl->cut[me], id, k, { ndown += sl->lowmark[k] ? sd : 0; });
    hearth_status st = halo_reserve(sl, ndown, err);
    if (st) return st;
    size_t w = 0;
    if (me > 0)
        FOR_LAYER(g, sl->axis, sl->cut[me], id, k, {
            if (sl->lowmark[k]) {
                memcpy(sl->halo + w, grid_block(g, g->slot[id]), sd * sizeof(double));
                w += sd;
            }
        });
    const void *lo, *hi;
    size_t nlo, nhi;
    if ((st = ranks_neighbours(sl->halo, ndown * sizeof(double), NULL, 0, &lo, &nlo, &hi, &nhi, err))) return st;
    if (up >= 0) {
        const double *src = hi;
        size_t r = 0;
        FOR_LAYER(g, sl->axis, up, id, k, {
            if (m->mark[id] & 1) {
                memcpy(grid_block(g, g->slot[id]), src + r, sd * sizeof(double));
                r += sd;
            }
        });
        HEARTH_ASSERT(r * sizeof(double) == nhi);
    }
    return HEARTH_OK;
}

/* mpm_self.c's node sums (MPM_SELF_NCH doubles a node, by grid slot) across a seam: the ghost layer's go up and the
 * owner adds them after its own, then the owner's whole sums come back down (halo_sum's and halo_back's order), so
 * every node a rank's particles read holds the sums of every rank's particles. */
hearth_status mpm_ranks_self_halo(hearth_scene *s, double *sums, hearth_error *err) {
    mpm_state *m = s->mpm;
    if (!slabs_live(m)) return HEARTH_OK;
    struct mpm_slabs *sl = m->slabs;
    const grid *g = &s->g;
    const int up = ghost_layer(m), me = ranks_rank();
    const size_t sd = MPM_SELF_NCH * (size_t)g->nodes_per_block;
    size_t n = 0, w = 0, r = 0;
    if (up >= 0) FOR_LAYER(g, sl->axis, up, id, k, { n += m->mark[id] & 1 ? sd : 0; });
    hearth_status st = halo_reserve(sl, n, err);
    if (st) return st;
    if (up >= 0)
        FOR_LAYER(g, sl->axis, up, id, k, {
            if (m->mark[id] & 1) {
                memcpy(sl->halo + w, sums + (size_t)g->slot[id] * sd, sd * sizeof(double));
                w += sd;
            }
        });
    const void *lo, *hi;
    size_t nlo, nhi;
    if ((st = ranks_neighbours(NULL, 0, sl->halo, n * sizeof(double), &lo, &nlo, &hi, &nhi, err))) return st;
    if (me > 0) {
        const double *src = lo;
        FOR_LAYER(g, sl->axis, sl->cut[me], id, k, {
            if (sl->lowmark[k]) {
                double *b = sums + (size_t)g->slot[id] * sd;
                for (size_t j = 0; j < sd; j++) b[j] += src[r + j];
                r += sd;
            }
        });
        HEARTH_ASSERT(r * sizeof(double) == nlo);
    }
    n = w = r = 0;
    if (me > 0) FOR_LAYER(g, sl->axis, sl->cut[me], id, k, { n += sl->lowmark[k] ? sd : 0; });
    if ((st = halo_reserve(sl, n, err))) return st;
    if (me > 0)
        FOR_LAYER(g, sl->axis, sl->cut[me], id, k, {
            if (sl->lowmark[k]) {
                memcpy(sl->halo + w, sums + (size_t)g->slot[id] * sd, sd * sizeof(double));
                w += sd;
            }
        });
    if ((st = ranks_neighbours(sl->halo, n * sizeof(double), NULL, 0, &lo, &nlo, &hi, &nhi, err))) return st;
    if (up >= 0) {
        const double *src = hi;
        FOR_LAYER(g, sl->axis, up, id, k, {
            if (m->mark[id] & 1) {
                memcpy(sums + (size_t)g->slot[id] * sd, src + r, sd * sizeof(double));
                r += sd;
            }
        });
        HEARTH_ASSERT(r * sizeof(double) == nhi);
    }
    return HEARTH_OK;
}

/* One rank's part of the step report, holding only what the combination
 * reads, each at the value a rank-order fold from an empty report would
 * leave (no particle: -1 and 0; a non-positive maximum: 0), so that
 * report_combine over the ranks equals that fold. */
static rank_report report_leaf(const step_report *q, double vcol, long clamped, int n, int blocks) {
    rank_report l = {.rep = {.particle = -1, .fastest = -1, .mover = -1}, .vcol = vcol > 0 ? vcol : 0, .clamped = clamped, .n = n, .blocks = blocks};
    step_report *t = &l.rep;
    if (q->particle >= 0) t->particle = q->particle, t->kind = q->kind, t->code = q->code;
    if (q->fastest >= 0 && q->max_speed > -1) t->max_speed = q->max_speed, t->fastest = q->fastest; /* the fold never took a NaN */
    if (q->max_move > 0) t->max_move = q->max_move, t->mover = q->mover >= 0 ? q->mover : -1;
    t->kinetic = q->kinetic, t->mass = q->mass, t->out_of_domain = q->out_of_domain;
    t->c_max = q->c_max > 0 ? q->c_max : 0;
    t->nu_max = q->nu_max > 0 ? q->nu_max : 0;
    t->self_max = q->self_max > 0 ? q->self_max : 0;
    return l;
}

/* acc, the ranks [a, b) combined, then next, the ranks [b, c): next's
 * particle indices move past acc's particles; the first failure, the first
 * of equal maxima, sums (ranks_combine). */
static void report_combine(void *acc, const void *next, void *ctx) {
    (void)ctx;
    rank_report *a = acc;
    const rank_report *b = next;
    step_report *t = &a->rep;
    const step_report *q = &b->rep;
    const int off = a->n;
    if (t->particle < 0 && q->particle >= 0) t->particle = off + q->particle, t->kind = q->kind, t->code = q->code;
    if (q->fastest >= 0 && q->max_speed > (t->fastest >= 0 ? t->max_speed : -1)) t->max_speed = q->max_speed, t->fastest = off + q->fastest;
    if (q->max_move > t->max_move) t->max_move = q->max_move, t->mover = q->mover >= 0 ? off + q->mover : -1;
    t->kinetic += q->kinetic;
    t->mass += q->mass;
    t->out_of_domain += q->out_of_domain;
    if (q->c_max > t->c_max) t->c_max = q->c_max;
    if (q->nu_max > t->nu_max) t->nu_max = q->nu_max;
    if (q->self_max > t->self_max) t->self_max = q->self_max;
    a->n += b->n, a->blocks += b->blocks, a->clamped += b->clamped;
    if (b->vcol > a->vcol) a->vcol = b->vcol;
}

/* The step report over the ranks, combined in rank order (a fixed binary
 * tree: each rank receives at most log2 N reports, not N) so every rank gets
 * the same one. Particle indices become indices into the whole set in rank
 * order (slabs_gather's order). Then the guard's verdict: when the guard will
 * stop (a failed particle, a CFL violation, a runaway), every rank gathers the
 * whole set so its diagnosis names the particle, the same on every rank. */
hearth_status mpm_ranks_report(hearth_scene *s, double dt, double vcol, step_report *rep, hearth_error *err) {
    mpm_state *m = s->mpm;
    struct mpm_slabs *sl = m->slabs;
    if (m->nranks > 1) ranks_count_step(slabs_live(m) ? 1 : 0);
    if (!slabs_live(m)) return HEARTH_OK;
    ranks_count_held(s->ps.n);
    const grid *g = &s->g;
    const int me = ranks_rank();
    int ghosts = 0; /* the ghost layer's blocks, and with fields the lower halo layer's */
    for (int k = 0; k < g->nactive; k++) {
        int c[3];
        grid_block_coords(g, g->active[k], c);
        ghosts += c[sl->axis] < sl->cut[me] || c[sl->axis] >= sl->cut[me + 1];
    }
    rank_report t = report_leaf(rep, vcol, s->out_of_domain - sl->ood0, s->ps.n, g->nactive - ghosts);
    ranks_combine(&t, sizeof t, report_combine, NULL);
    sl->blocks = t.blocks;
    const long clamped = t.clamped;
    const double vc = t.vcol;
    t.rep.driven_kinetic = 0.5 * t.rep.mass * vc * vc;
    *rep = t.rep;
    s->out_of_domain = sl->ood0 + clamped; /* every rank's clamps, the same count on every rank */
    int stop = rep->particle >= 0;
    if (!stop) {
        /* the guard's own test, without its particle names (they need the whole set) */
        step_report dry = *rep;
        dry.fastest = dry.mover = -1;
        const double cfl = s->cfl_last;
        char keep[sizeof s->diagnosis];
        memcpy(keep, s->diagnosis, sizeof keep);
        stop = guard_check(s, &dry, dt, s->max_speed);
        memcpy(s->diagnosis, keep, sizeof keep);
        s->cfl_last = cfl;
    }
    return stop ? slabs_gather(s, err) : HEARTH_OK;
}
