/* mpm.h: the MPM solver's own state (mpm_state) and its phases. mpm.c owns
 * the state: it is made when an MPM scene is created (mpm_solver.init),
 * grown by the sort when the particle count grows (never otherwise in the
 * step loop) and freed with the scene (mpm_solver.free). An SPH scene has
 * none. The field passes that run inside an MPM step (boundary, transport,
 * thermal, water, mixing) walk the sort's particle blocks and read P2G's
 * volumes through mpm_state_of(), read-only. */
#ifndef HEARTH_SIM_MPM_H
#define HEARTH_SIM_MPM_H
#include <math.h>
#include <stdint.h>

#include "error.h"
#include "grid.h"
#include "scene.h"
#include "team_wait.h"

/* A run of sorted particles sharing one grid block. */
typedef struct pblock {
    int block, start, end;
} pblock;

/* A lone particle's or small cluster's own mode (mpm_self.c): the step is held to MPM_SELF_MARGIN of its stability
 * bound (mpm_stable_dt), which can bind only at cfl > MPM_SELF_MARGIN / sqrt(dim); mpm_self_asked says whether the
 * step measures it (mpm_self_gather after the grid update, G2P's alpha). */
#define MPM_SELF_MARGIN 0.9
#define MPM_SELF_NCH 4 /* mpm_self.c's doubles a node: g_i (3), then the node's mass */
int mpm_self_asked(const hearth_scene *s);
hearth_status mpm_self_gather(hearth_scene *s, hearth_error *err);
void mpm_self_free(struct mpm_state *m);
double mpm_self_dt(const hearth_scene *s); /* the step's bound, INFINITY when nothing was measured */

/* Per particle-block partial results, reduced in block order. */
typedef struct pb_partial {
    int fail_i, fail_kind, fail_code, fastest, mover;
    int clamped; /* particles G2P put back inside the grid after a collider pushed them out */
    double move; /* largest displacement in the block this step (m) */
    double ke, mass, vmax, cmax, numax; /* numax: largest kinematic viscosity eta / rho (m^2/s) */
    double selfmax; /* largest share of a particle's own affine mode in the block (mpm_g2p.c), 0 when not asked */
    long ood;
    /* water.c's per-block sums, written by G2P's block loop and reduced by water_finish: they stay
     * here with the other partials so a step's reduction is one array in block order */
    double water_removed, water_dmax, water_emax, water_lmax;
    int flushed; /* 3D's ordered P2G (mpm.c's p2g_team): the block's tile is in the nodes (release / acquire) */
} pb_partial;

typedef struct mpm_state {
    /* the sort's per-particle scratch, scratch_cap long: G2P writes the keys,
     * the sort reads them into order, and the permutation then takes the
     * keys' room as its scratch (particles_permute: 8 bytes a particle in
     * all, where a separate n doubles for the permutation made 12). One
     * block of scratch_bytes (at least 8 scratch_cap): keys, then order, then
     * any room the gather's tile store asked for (tiles below) */
    int *keys, *order;
    size_t scratch_bytes;
    int keys_n;             /* keys hold the blocks of these many particles, written by G2P */
    long keys_step;         /* for the positions after this step: a rolled back step's keys do not count */
    unsigned long keys_edits; /* ps.edits when G2P filed them */
    /* the counting sort's per-chunk block counts, nchunks x nblocks */
    int *hist;
    size_t histcap;
    double *vol;            /* with heat or water: each particle's volume J V_0 this step, from P2G (NULL otherwise) */
    int scratch_cap;
    /* per block of the box (nblocks as when made: the grid never changes size) */
    int nblocks;
    int *counts;            /* nblocks + 1: the sort's per-block counts (block starts, or totals after sort_team) */
    unsigned char *mark;    /* nblocks */
    /* the particle blocks of this step, pbcap long */
    pblock *pb;
    int npb, pbcap;
    int *colour_pb;         /* pb indices grouped by colour */
    /* step_team's gather path (mpm_p2g_gather.c): each particle block's kept halo (P2G_STORE_NCH x P2G_HALO
     * doubles each), tiles_cap doubles in all this step (0 when it does not gather), in the sort's scratch
     * (keys and order are dead from the end of the sort until G2P files the next keys, after the gather);
     * and per block of the box the particle block there (nblocks; -1 where none, and everywhere between steps) */
    double *tiles;
    size_t tiles_cap;
    int *pbof;
    double *self_g;         /* mpm_self.c: each active node's g_i and mass (MPM_SELF_NCH doubles), when asked */
    size_t self_g_cap;
    int colour_phases;      /* HEARTH_MPM_COLOUR_PHASES=1 at init: step_team keeps the colour phases at any thread count */
    /* 3D, more than one thread (mpm.c): the blocks each phase hands out from both ends of its range, and whether
     * P2G orders each block's flush after its lower-coloured neighbours' instead of a barrier per colour (both
     * set by the caller of a region for its span, NULL and 0 otherwise) */
    struct mpm_claims *claims;
    int p2g_ordered;
    long claims_regions;    /* regions that ran with them (for the tests) */
    int colour_start[9];
    pb_partial *partial;
    int sticky_faces;       /* this step's scene has a sticky collider: P2G adds its faces' reaction (p2g_mirror) */
    /* the one-region step's share-out (mpm.c's span_next), summed over its steps, per phase (MPM_SPAN_*: P2G's
     * and G2P's particle blocks, the grid update's active blocks): the blocks run, and those a thread took from
     * the back of another thread's chunk, which changed core between the phases (the tests print them) */
    long span_blocks[3], span_back[3];
    /* MPI ranks (mpm_ranks.c): this rank steps particle blocks [k_lo, k_hi); rank r
     * owns blocks [kfirst[r], kfirst[r + 1]) and particles [pfirst[r], pfirst[r + 1]) */
    int nranks, k_lo, k_hi;
    double step_dt;         /* this step's dt, for the touch masks the slabs' halo_sum makes (mpm_touch.c) */
    int *kfirst, *pfirst;   /* nranks + 1 each */
    int failed_alone;       /* a step call failed here with an error the other ranks may not share: no more exchanges (mpm_ranks_end) */
    struct mpm_slabs *slabs; /* the slab mode's state (mpm_ranks.c) */
    struct mpm_slab_fields *sfields; /* the slabs' halo layers for heat and water (mpm_ranks_fields.c) */
    double *dgrad;          /* two_field: each particle's damage gradient (x, y; 1/m) and body tag this step (mpm_two_field.c) */
    int dgrad_cap;
    /* the waits of the step's teams (team_wait.h; HEARTH_TEAM_SPIN at init): the sort's, the one-region
     * step's and 3D's claimed step's barriers spin a while before they sleep */
    team_wait team;
} mpm_state;

/* ---- two velocity fields at cracks (mpm_two_field.c; scene setting two_field, 2D) ---- */

/// After the sort, before P2G: each particle's damage gradient (m->dgrad) and
/// each node's reference gradient (CH_TF_GX, CH_TF_GY; zero where the node is
/// not split). Fails only for memory.
hearth_status mpm_two_field_prepare(hearth_scene *s, hearth_error *err);
/// Whether a particle goes into the second field of a node whose reference
/// gradient is (gx, gy) and reference body tag gb. pd is the particle's entry
/// of m->dgrad: its damage gradient (px, py) and its body tag. Where two bodies
/// touch the node (gb > 0) every particle of another body than the reference
/// is in the second field; elsewhere the sign of the gradients' dot product
/// decides (Homel & Herbold 2017), and a node that is not split has (0, 0)
/// and keeps all.
static inline int mpm_two_field_second(double gx, double gy, double gb, const double *pd) {
    return gb > 0.0 ? pd[2] != gb : gx * pd[0] + gy * pd[1] < 0.0;
}
/// Before the grid update: the first field's mass and momentum are the total
/// less the second's (P2G scatters every particle into the total, so the
/// field passes see all the material).
void mpm_two_field_split(hearth_scene *s);
/// After both fields' grid updates (of dt s): where the fields press together
/// (two bodies: and touch by the step's end), the contact correction
/// (frictionless or Coulomb, momentum kept).
void mpm_two_field_contact(hearth_scene *s, double dt);
void mpm_two_field_free(mpm_state *m);
/// Whether two or more bodies may meet (the scene has them), so nodes may be split by body.
int mpm_two_field_bodies(const hearth_scene *s);
/// Whether particle i belongs to field (1 first, 2 second) at grid node gi (a node of its stencil), for a face's
/// touch test (mpm_touch.c): at a node two bodies meet, by its body; elsewhere every particle is in both.
int mpm_two_field_holds(const hearth_scene *s, int i, const int gi[3], int field);

/// The MPM state of s (NULL under another solver), for the field passes an
/// MPM step runs: the particle blocks of this step's sort and P2G's volumes.
static inline const mpm_state *mpm_state_of(const hearth_scene *s) { return s->mpm; }

/* ---- the sort (mpm_sort.c) and what G2P shares with it ---------------- */

/* The block of a particle's B-spline base node. P2G and G2P read the
 * particle's stencil from its block's tile, which holds base nodes 0..3 of the
 * block and two more: that is only true when the base node lies in
 * [0, nn - 3], which block_of_position's callers guarantee (mpm_sort). */
/* The lowest node of a particle's stencil along an axis, from its grid
 * coordinate X = (x - lo) / dx. Particles stay a node inside the grid
 * (clamp_to_grid, G2P), so X >= 1 and truncation is floor: floor is a libm
 * call where the target has no rounding instruction (x86-64 without SSE4.1,
 * the build callgrind counts), about 20 instructions per axis per pass. */
static inline int base_node(double X) {
    HEARTH_ASSERT(X >= 0.5);
    return (int)(X - 0.5);
}

static inline int block_of_position(const grid *g, const double *x) {
    int b[3] = {0, 0, 0};
    for (int d = 0; d < g->dim; d++) b[d] = base_node((x[d] - g->lo[d]) * g->inv_dx) / GRID_B;
    return grid_block_id(g, b[0], b[1], b[2]);
}

/* Put a particle outside the usable domain (one cell inside the box: every
 * node of its stencil on the grid) back on its edge. Returns 1 if it moved.
 * G2P clamps too, but a collider's projection comes after that clamp, and a
 * collider that covers the box projects particles out of the grid: the sort
 * then filed them in a block whose tile did not hold their stencil (a write
 * outside P2G's tile and the block tables). Clamping here, where the block is
 * chosen, makes the invariant hold whatever moved the particle (a collider,
 * a plugin, a restored file). A NaN coordinate goes to the low edge so the
 * cast below stays defined; the guard has already stopped on it. */
static inline int clamp_to_grid(const grid *g, double *x) {
    int moved = 0;
    for (int d = 0; d < g->dim; d++) {
        const double lo = g->lo[d] + g->dx, hi = g->lo[d] + (g->nn[d] - 2) * g->dx;
        if (!(x[d] >= lo)) {
            x[d] = lo;
            moved = 1;
        } else if (x[d] > hi) {
            x[d] = hi;
            moved = 1;
        }
    }
    return moved;
}

/// Sort the particles into grid blocks, list the particle blocks and
/// activate the grid blocks their tiles touch (mpm_sort.c).
hearth_status mpm_sort(hearth_scene *s, hearth_error *err);
/// mpm_sort inside the caller's parallel region (mpm.c's one-region step),
/// for one rank and no periodic axis. mpm_sort_begin does the serial part
/// before it; when t->T > 1 every thread of the region then calls
/// mpm_sort_team_run, which lists the particle blocks (m->npb, this rank's
/// range), marks and activates the grid, fills the order and returns the
/// farthest move in it when the keys were out of order (the caller then runs
/// particles_permute_team with it; -1 when in order), and t->st says whether
/// a reservation failed (every thread sees the same). kof gets each chunk's
/// first particle block (kof[T]: all of them; every thread its own copy).
/// The lists and the grid are complete after the team's next barrier; before
/// it, a chunk c with t->ready[c] set (acquire order) has its particle blocks
/// [kof[c], kof[c + 1]) and their grid blocks ready (2D, keys in order; its
/// blocks are handed out through t->span[MPM_SPAN_P2G][c]). The spans of the
/// grid update (chunk c's active blocks) and of G2P (its particle blocks
/// again) are set before the team's next barrier. t->T == 0: mpm_sort_begin
/// sorted as mpm_sort does (no colour lists are made in the region: the
/// gather does not read them). Bits: mpm_sort's.
#define MPM_SORT_CHUNKS_MAX 64
/// A range of indices [lo, hi) that the threads take runs from at both ends at
/// once (mpm.c's span_take): lo in the low 32 bits, hi in the high. Each on its
/// own cache line: two threads taking from neighbouring spans would otherwise
/// pass one line back and forth.
typedef struct mpm_span {
    _Alignas(64) unsigned long long lohi;
} mpm_span;
static inline void mpm_span_set(mpm_span *sp, int lo, int hi) {
    sp->lohi = (unsigned long long)(unsigned)lo | (unsigned long long)(unsigned)hi << 32;
}
/// the one-region step's phases that hand out a chunk's blocks: P2G's and G2P's particle blocks, the grid update's
enum { MPM_SPAN_P2G, MPM_SPAN_GRID, MPM_SPAN_G2P, MPM_SPANS };
_Static_assert(MPM_SPANS == 3, "mpm_state's span_blocks and span_back hold one count per phase");
typedef struct mpm_sort_team {
    int T;             /* the count's chunks (more than one), or 0 */
    int activate;      /* the grid's activation in the region too */
    int set_range;     /* and this rank's particle blocks (one rank: all of them) */
    int pbcap, gcap;   /* the lists' room when the region began (the singles grow them) */
    hearth_status st;
    hearth_error *err;
    int unsorted[MPM_SORT_CHUNKS_MAX], far[MPM_SORT_CHUNKS_MAX], amark[MPM_SORT_CHUNKS_MAX]; /* per chunk */
    int chunk_tot[MPM_SORT_CHUNKS_MAX][3]; /* per chunk of the block table: its particles, particle blocks, 2D marks */
    /* per chunk, atomics (__atomic builtins): the count's, the lists' and the table's claims, the lists published, and the
     * blocks each phase of the step hands out (mpm_span) */
    int claim[3][MPM_SORT_CHUNKS_MAX], ready[MPM_SORT_CHUNKS_MAX];
    /* the caller's MPM_SPANS rows of spans (mpm.c's one-region step; NULL: none kept), apart from the struct,
     * which is zeroed every step (12 KB) */
    mpm_span (*span)[MPM_SORT_CHUNKS_MAX];
    /* the count's chunks done, the table's chunks added up, P2G's particle blocks stored and the grid
     * update's blocks done (the one-region step): a thread moves on once the work is done, whoever did it
     * (team_count_wait) */
    team_count counted, totalled, stored, updated;
} mpm_sort_team;
hearth_status mpm_sort_begin(hearth_scene *s, mpm_sort_team *t, hearth_error *err);
/// nactive (NULL: not wanted): this thread's copy of the active grid blocks' count when the region activates.
int mpm_sort_team_run(hearth_scene *s, mpm_sort_team *t, int kof[MPM_SORT_CHUNKS_MAX + 1], int *nactive);
/// Release the sort's per-particle scratch (mpm_sort.c).
void mpm_scratch_free(mpm_state *m);
/// The sort's scratch at least bytes long, between the sort and G2P (its
/// keys and order are dead then; the keys stay invalid, keys_n -1): the
/// gather's tile store (mpm_p2g_gather.c). Fails only for memory.
hearth_status mpm_scratch_room(hearth_scene *s, size_t bytes, hearth_error *err);
/// Along the periodic axes: every particle into the period; the blocks
/// holding the nodes the marked blocks' ghosts stand for; the ghosts' mass
/// and momentum onto their nodes (unfold 0) and their nodes' velocity back
/// (unfold 1) (mpm_periodic.c).
void mpm_periodic_wrap_all(hearth_scene *s);
void mpm_periodic_mark(const hearth_scene *s, unsigned char *mark);
void mpm_periodic_fold(hearth_scene *s, int unfold);
/* mpm_p2g_gather.c: the usual step's P2G in 2D (any thread count) keeps each particle block's tile (own
 * part in its block's nodes, halo in the store) and the grid update gathers them in colour order */
/// Whether the store is held (2D at any thread count, not HEARTH_MPM_COLOUR_PHASES); leaves out the particle count.
int mpm_p2g_store_held(const hearth_scene *s);
/// After the sort: *gather, whether this step gathers, and room in the store for its particle blocks when it does.
hearth_status mpm_p2g_store_reserve(hearth_scene *s, int *gather, hearth_error *err);
/// The store's doubles for npb particle blocks, and room for them in the sort's scratch (m->tiles, tiles_cap):
/// once the sort no longer reads its keys and order (the one-region step's store grows there). Fails only for memory.
size_t mpm_p2g_store_need(const hearth_scene *s, int npb);
hearth_status mpm_p2g_store_room(hearth_scene *s, int npb, hearth_error *err);
/// Particle block k (block coordinates bc) keeps its P2G tile: own part into its nodes, halo into the store.
void mpm_p2g_keep_tile(hearth_scene *s, int D, int k, const int bc[3], const double *tile);
/// Active block k's node sums from the kept tiles that reach it, in colour order (the colour phases' bits).
void mpm_p2g_gather(hearth_scene *s, int k);
/// The store's bytes a particle for the memory estimate (0 where it is not held).
double mpm_p2g_store_bytes_per_particle(const hearth_scene *s);
void mpm_p2g(hearth_scene *s, double dt, step_report *rep);
/// Returns the largest collider speed (m/s) at a node with mass that a collider set.
double mpm_grid_update(hearth_scene *s, double dt);
void mpm_g2p(hearth_scene *s, double dt, step_report *rep);
/* mpm_ranks.c: the MPM step over MPI ranks (a no-op on one rank) */
hearth_status mpm_ranks_init(mpm_state *m, hearth_error *err);
void mpm_ranks_free(mpm_state *m);
/// After the sort: each rank's run of particle blocks, split by particle count.
void mpm_ranks_partition(hearth_scene *s);
/// After P2G: the nodes summed over the ranks (and P2G's volumes shared).
hearth_status mpm_ranks_sum_grid(hearth_scene *s, hearth_error *err);
/// After G2P's blocks: every rank's particles and block partials to every rank.
void mpm_ranks_gather(hearth_scene *s);
/* The slab mode (mpm_ranks.c): each rank holds the particles of its slab of
 * block layers along the box's longest axis for the length of a step call;
 * the cuts follow the particle count every MPM_RANKS_REBALANCE steps. */
#define MPM_RANKS_REBALANCE 50
/// At the start of a step call: the slab mode when the scene allows it and
/// the whole set is on every rank (else nothing: the replicated mode, or the
/// slabs of the last call). They stay until hearth_scene_whole (a reader).
void mpm_ranks_begin(hearth_scene *s);
/// Whether the slabs stay between step calls (hearth_scene_keep_slabs).
void mpm_ranks_keep(hearth_scene *s, int on);
/// At the end of a step call: the whole set again unless the host keeps the
/// slabs. Returns st, or the gather's error when st is HEARTH_OK. A failed
/// call other than the guard's stop (which every rank reaches together)
/// may be this rank's alone: the rank then takes part in no exchange again.
hearth_status mpm_ranks_end(hearth_scene *s, hearth_status st, hearth_error *err);
/// HEARTH_ERR_STATE (and why) when a step call failed on this rank alone
/// (mpm_ranks_end): every collective entry point asks before it exchanges.
hearth_status mpm_ranks_usable(const hearth_scene *s, hearth_error *err);
/// The whole set on every rank again (hearth_scene_whole); collective.
hearth_status mpm_ranks_whole(hearth_scene *s, hearth_error *err);
/// Particles over all ranks.
int mpm_ranks_particles(const hearth_scene *s);
/// Whether this rank holds only its slab's particles now (else the whole set).
int mpm_ranks_holds_slab(const hearth_scene *s);
/// Active grid blocks over all ranks (each counted once).
int mpm_ranks_blocks(const hearth_scene *s);
/// At the start of the sort: particles that left this rank's slab go to the neighbour's.
hearth_status mpm_ranks_migrate(hearth_scene *s, hearth_error *err);
/// Before the grid blocks are activated: the blocks of this rank's first
/// layer the lower neighbour's particles touch get storage too.
hearth_status mpm_ranks_mark(hearth_scene *s, hearth_error *err);
/// After the grid update: the owners' node values of the ghost blocks back to the ranks that touch them.
hearth_status mpm_ranks_halo_back(hearth_scene *s, hearth_error *err);
/* Slabs: the touch mask (mpm_touch.h) of face f (mpm_touch_face) that the lower neighbour's particles give
 * block id of this rank's first layer, sent with the ghost layer's sums (halo_sum); 0 elsewhere. */
uint64_t mpm_ranks_touch_below(const hearth_scene *s, int id, int f);
/* mpm_self.c's node sums across a slab's seam (nothing off slabs) */
hearth_status mpm_ranks_self_halo(hearth_scene *s, double *sums, hearth_error *err);
/// In the slab mode: 1, this rank's slab's block layers [*lo, *hi) along *axis; else 0.
int mpm_ranks_slab(const mpm_state *m, int *axis, int *lo, int *hi);
/* mpm_ranks_fields.c: heat and water on slabs, through one complete block
 * layer each side of the slab (no-ops outside the slab mode or without fields) */
void mpm_ranks_fields_free(mpm_state *m);
/// In mpm_ranks_mark: storage for the halo layers (the neighbours' blocks in them).
hearth_status mpm_ranks_fields_mark(hearth_scene *s, hearth_error *err);
/// The owners' values of channels ch[0..nc) (every channel when ch is NULL) into the halo layers.
hearth_status mpm_ranks_fields_fill(hearth_scene *s, const int *ch, int nc, hearth_error *err);
/// After a particle scatter into channels ch[0..nc): the halo layers' sums to their owners, then fill.
hearth_status mpm_ranks_fields_sum(hearth_scene *s, const int *ch, int nc, hearth_error *err);
/// One byte per active block slot (boundary.c's surface flags): the owners' into the halo layers.
hearth_status mpm_ranks_fields_fill_flags(hearth_scene *s, unsigned char *flag, hearth_error *err);
/// Before the grid update: the halo layers cleared (the grid update sees the slab's blocks and the bare ghosts).
void mpm_ranks_fields_clear(hearth_scene *s);
/// Per active block slot: whether this rank owns it (sums over nodes count it once); NULL outside the slab mode.
const unsigned char *mpm_ranks_fields_owned(const hearth_scene *s);
/// After thermal.c's find_boundary: each heated collider contact point to the rank owning its base node's block.
hearth_status mpm_ranks_fields_contacts(hearth_scene *s, hearth_error *err);
/// boundary.c's domain-wall test on slabs: whether the box's end node gi (gi[d] 0 or nn[d] - 1) has mass,
/// the owner's answer; -1 when d is not the slab axis or outside the slab mode (read the node).
int mpm_ranks_fields_wall(const hearth_scene *s, int d, const int gi[3]);
/// Every rank's sum[0..nsum) added and max[0..nmax) maxed, in rank order, in place (nsum + nmax <= 8).
void mpm_ranks_fields_reduce(const hearth_scene *s, double *sum, int nsum, double *max, int nmax);
/// At the end of the step: the step report over the ranks (vcol: the fastest collider speed at a node).
hearth_status mpm_ranks_report(hearth_scene *s, double dt, double vcol, step_report *rep, hearth_error *err);
hearth_status mpm_step(hearth_scene *s, double dt, step_report *rep, hearth_error *err);
/* The stable step: CFL, the user's maximum, explicit conduction, water and viscosity. */
double mpm_stable_dt(const hearth_scene *s);
/* P2G's material call site (mpm_stress.c): particles i0 .. i0 + n - 1 of a particle block (n <=
 * HEARTH_BLOCK_MAX) get F <- (I + dt C) F, their stresses into the columns tau[c][j] (the core's terms
 * added; zero for a pinned particle and one whose F or stress failed), det F into Js; failures go to pp,
 * the largest wave speed and kinematic viscosity to cmax and numax. The field columns are P2G's (NULL
 * when the scene does not carry them). */
void mpm_p2g_stress(hearth_scene *s, int D, int i0, int n, double dt, unsigned env_flags, const double *Tcol,
                    const double *Wcol, const double *Gcol, const double *S0col, double (*tau)[HEARTH_BLOCK_MAX], double *Js,
                    pb_partial *pp, double *cmax, double *numax);
#endif
