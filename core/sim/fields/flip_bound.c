/* flip_bound.c: heat's maximum principle at the particles (#18, helper
 * maxprinciple): no particle ends a field step hotter than the hottest thing
 * in the scene at its start (every particle, the oven air, each heated
 * collider) nor colder than the coldest.
 *
 * Why. FLIP (Ding et al. 2019 eq. 21) hands particle p its nodes' change,
 * T_p + sum_i w_ip dT_i, dT_i = T_i^{n+1} - T_i^n, and that change belongs to
 * the node's average T_i^n = sum_p w_ip C_p T_p / C_i. Where a steep contrast
 * sits inside a node's support the particle already hotter than its nodes is
 * pushed on past every source. Measured (docs/validation.md, "The heat's
 * maximum principle"): a 5000 degC tray through beta 1e9 W/(m^2 K) left its
 * contact rows at 7035 degC; the muffin cups (Table 2's beta 150) 114.3 degC
 * in a 105 degC oven; unit_heat_bc's Robin plate at Bi 100 147 degC against
 * 120. With latent heat subcell.c's fit extrapolated a dried row past both
 * bounds (6573 and -247 degC, backward Euler), and a wet particle held at T_b
 * beside dried ones took its nodes' cooling (-197 degC).
 *
 * What. The bounds [lo, hi] are taken before subcell.c moves the dried
 * particles (flip_bound_prepare), widened by the largest change the expansion
 * term (eq. 9's theta c lambda div v, a volumetric source) makes in the field
 * step. Each particle's update as G2P will make it (T_p + sum_i w_ip dT_i, or
 * the scene's FLIP-PIC blend) is tested; nothing is written where every
 * particle stays inside, so a scene that never breaks the bounds keeps its
 * bits. Two remedies:
 * - A particle in the body (not PF_BOUNDARY) that would leave them gives
 *   each node of its stencil a share theta_i of its relaxation toward the
 *   nodes' mean, the least share that brings it back (1 where that cannot),
 *   and every particle then moves by
 *     c_p = sum_i w_ip theta_i (A_i - T_p),  A_i = sum_q w_iq C_q T_q / sum_q w_iq C_q,
 *   A_i the particles' mean now (subcell.c has moved some since P2G). Summed
 *   with the weights C_p this is sum_i theta_i (sum_q w_iq C_q A_i -
 *   sum_p w_ip C_p T_p) = 0 for any shares: exactly conserving, unlike a
 *   clamp or a blend per particle. A particle whose nodes all take share 1
 *   ends at its PIC value sum_i w_ip T_i^{n+1}, inside its nodes' range.
 *   Rounds repeat (at most BOUND_ROUNDS) when a neighbour's mixed update
 *   leaves the bounds in turn.
 * - A particle on a boundary (the oven's air surface, a heated collider's
 *   contact band) that would leave them is clamped at the bound: the heat a
 *   source's Robin term let in past the source's own temperature goes back to
 *   it (the oven's ledger under latent_heat counts it). Relaxing those as the
 *   body's was measured and rejected: at a Robin contact of Bi 100 it spread
 *   the contact row's heat inward every step, the face's field fell and the
 *   slab took 72% too much heat at 5 cells (unit_heat_bc's
 *   heat_collider_robin_converges: order 1.46; clamped: 2.15 and 2.84).
 * A particle on the oven's air surface under latent_heat has no lower bound:
 * evaporation cools it toward its wet bulb, which no source's temperature
 * sets (the drying slab at 60 degC sits at 45.8 degC).
 *
 * Not fixed here: the nodes' own update can pass the bounds (the Robin
 * contact's consistent weights w_j(x_s) w_k(x_s); the B-spline Laplacian's
 * positive off-diagonal entries in 2D and 3D), so a particle relaxed to its
 * PIC value is only as bounded as its nodes.
 *
 * Order and threads. The tests are per particle (parallel, read only); the
 * shares, the means and the clamps are written serially in particle order:
 * the same bits at any thread count. MPI slabs agree on the bounds (a max
 * over the ranks), go on while any rank has a particle out, and sum the
 * shares and means through the halo exchange. Channels after thermal_finish
 * and subcell.c, dead until the next P2G: CH_CG_P (shares), CH_R, CH_B
 * (means). */
#include "flip_bound.h"

#include <math.h>
#include <string.h>

#include "scene.h"
#include "boundary.h"
#include "mpm.h"
#include "grid.h"
#include "alloc.h"
#include "error.h"
#include "material.h"
#include "physics_constants.h"
#include "thermal.h"

/* A particle leaves the bounds when it passes them by more than this share
 * of their scale (|hi| + |lo| + 1 K): far above the increments' rounding
 * (1e-16 of the values), far below anything a reader sees; rounds of the
 * relaxation before the rest is left (none was left in the cases measured). */
#define BOUND_TOL 1e-9
#define BOUND_ROUNDS 4
#define BOUND_MARK CH_CG_P
#define BOUND_W CH_R /* sum_p w_ip C_p, then the nodes' mean of the particles' temperatures in BOUND_A */
#define BOUND_A CH_B

/* The step's bounds: [lo, hi] the range of the particles' step-start temperatures and of the scene's heat
 * sources (oven air, heated colliders), widened by the largest change the expansion term (eq. 9's
 * theta c lambda div v, a volumetric source) may make in the field step fdt; latent: a particle on the
 * oven's air surface has no lower bound (evaporation cools it toward its wet bulb). */
typedef struct bounds {
    double lo, hi, tol;
    int latent;
} bounds;

static bounds step_bounds(const hearth_scene *s, double fdt) {
    const particles *ps = &s->ps;
    const int n = ps->n;
    const double *T = pcold(ps, PC_TEMPERATURE), *V0 = pcold(ps, PC_VOL0), *M = pcold(ps, PC_MASS);
    const int *mat = pcoli(ps, PC_MAT);
    int expansion = 0;
    for (int m = 0; m < s->mats.n; m++) expansion |= s->mats.slot[m].core[CP_EXPANSION] > 0;
    double lo = INFINITY, hi = -INFINITY, q = 0;
#pragma omp parallel for schedule(static) reduction(min : lo) reduction(max : hi, q) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        if (T[i] < lo) lo = T[i];
        if (T[i] > hi) hi = T[i];
        if (!expansion) continue;
        const material_slot *ms = &s->mats.slot[mat[i]];
        const double cl = ms->core[CP_EXPANSION], c = M[i] * material_specific_heat(ms, ps, i);
        if (cl > 0 && c > 0) { /* transport.c's source V0 c lambda theta_abs tr C over the field step */
            const double r = fabs(V0[i] * cl * (T[i] + KELVIN) * particles_trC(ps, i)) * fdt / c;
            if (r > q) q = r;
        }
    }
    double mx[3] = {hi, -lo, q};
    if (s->mpm->nranks > 1) mpm_ranks_fields_reduce(s, NULL, 0, mx, 3); /* MPI slabs: every rank's particles */
    hi = mx[0], lo = -mx[1], q = mx[2];
    if (!isnan(s->def.oven_temperature) && s->def.oven_beta > 0) lo = fmin(lo, s->def.oven_temperature), hi = fmax(hi, s->def.oven_temperature);
    if (thermal_oven_radiates(&s->def)) /* the walls are a source too: the outside temperature lies between air and walls */
        lo = fmin(lo, s->def.oven_wall_temperature), hi = fmax(hi, s->def.oven_wall_temperature);
    for (int c = 0; c < s->ncol; c++) {
        const double Tc = s->cols[c].temperature;
        if (!isnan(Tc) && s->cols[c].beta > 0) lo = fmin(lo, Tc), hi = fmax(hi, Tc);
    }
    const bounds b = {.lo = lo - q, .hi = hi + q, .tol = BOUND_TOL * (fabs(hi) + fabs(lo) + 1.0), .latent = 0};
    return b;
}

/* How far particle i's update, as G2P makes it (before boiling) from T_i + c (the step start's temperature
 * moved by the shares so far), leaves the bounds beyond their tolerance: the share phi in (0, 1] of the move
 * left to it (sum_i w_ip (1 - theta_i) (T_i^n - T_i), theta_i the nodes' shares so far) that brings it back to
 * the bound it passed (1 where that move points away from it); 0 inside. */
static double leaves(const hearth_scene *s, int i, const double *X, const double *T, double c, int marked, const bounds *b,
                     double *clamp) {
    const grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    grid_point_nodes pn;
    grid_point_nodes_of(g, X + 3 * i, &pn);
    double dT = 0, Tn = 0, r = 0;
    for (int j = 0; j < pn.n; j++) {
        const double *node = pn.node[j];
        const int l = pn.l[j];
        const double t1 = node[CH_T * NPB + l], t0 = node[CH_T0 * NPB + l];
        dT += pn.w[j] * (t1 - t0);
        Tn += pn.w[j] * t1;
        r += pn.w[j] * (1.0 - (marked ? fmin(node[BOUND_MARK * NPB + l], 1.0) : 0.0)) * ((marked ? node[BOUND_A * NPB + l] : t0) - T[i]);
    }
    const double f = s->def.heat_flip, T0 = T[i] + c;
    const double T1 = thermal_flip_blend(f, T0, dT, Tn); /* as G2P will make it */
    const double hi = b->hi, lo = b->latent && s->boundary.area[i] > 0 ? -INFINITY : b->lo;
    if (clamp) { /* a boundary particle: how far past the bounds, signed (its clamp, after the moves) */
        *clamp = T1 > hi + b->tol ? hi - T1 : T1 < lo - b->tol ? lo - T1 : 0.0;
        return 0.0;
    }
    const double ex = T1 > hi + b->tol ? T1 - hi : T1 < lo - b->tol ? T1 - lo : 0.0;
    if (ex == 0.0) return 0.0;
    const double fr = f * r; /* the move's effect on T1: the blend keeps the share f of the particle's own */
    return ex * fr < 0 && fabs(fr) > fabs(ex) ? fabs(ex / fr) : 1.0;
}

void flip_bound_prepare(hearth_scene *s, double fdt) {
    const bounds b = step_bounds(s, fdt);
    s->heat.bound_lo = b.lo, s->heat.bound_hi = b.hi, s->heat.bound_tol = b.tol;
}

hearth_status flip_bound_apply(hearth_scene *s, hearth_error *err) {
    particles *ps = &s->ps;
    grid *g = &s->g;
    const int n = ps->n, NPB = g->nodes_per_block;
    if (n == 0 && s->mpm->nranks <= 1) return HEARTH_OK; /* an empty slab still joins the ranks' reductions */
    const double *X = pcold(ps, PC_X);
    double *T = pcold(ps, PC_TEMPERATURE);
    const int *flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    const bounds bd = {.lo = s->heat.bound_lo, .hi = s->heat.bound_hi, .tol = s->heat.bound_tol,
                       .latent = s->def.latent_heat && (ps->enabled & (1u << PC_WATER)) && boundary_needed(s)};
    if (n > s->heat.bound_cap) {
        double *c = mem_alloc(sizeof(double) * 2 * (size_t)n);
        if (!c) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the heat's bounds (%d particles)", n);
        mem_free(s->heat.bound_c, sizeof(double) * 2 * (size_t)s->heat.bound_cap);
        s->heat.bound_c = c, s->heat.bound_cap = n;
    }
    double *cor = s->heat.bound_c, *phi = cor + n;
    int marked = 0, moved_any = 0; /* a round marked nodes (their channels hold the marks and means); cor holds moves */
    for (int round = 0; round <= BOUND_ROUNDS; round++) {
        long count = 0;
#pragma omp parallel for schedule(static) reduction(+ : count) if (n >= SCENE_PARALLEL_MIN)
        for (int i = 0; i < n; i++) {
            const int skip = flags && (flags[i] & (PF_HOLD_T | PF_BOUNDARY)); /* the boundary's are clamped below */
            phi[i] = skip ? 0.0 : leaves(s, i, X, T, moved_any ? cor[i] : 0.0, marked, &bd, NULL);
            count += phi[i] > 0;
        }
        double any = (double)count; /* MPI slabs: every rank goes on while any rank has a particle out */
        if (s->mpm->nranks > 1) mpm_ranks_fields_reduce(s, &any, 1, NULL, 0);
        if (!(any > 0) || round == BOUND_ROUNDS) break; /* the last round only counts what is left */
        if (!marked) { /* the marks, and the nodes' means of the particles' temperatures now (subcell.c moved the
                        * dried ones since P2G): the moves toward them conserve heat exactly */
            for (int k = 0; k < g->nactive; k++) {
                double *blk = grid_block(g, k);
                memset(blk + BOUND_MARK * NPB, 0, sizeof(double) * (size_t)NPB);
                memset(blk + BOUND_W * NPB, 0, sizeof(double) * (size_t)NPB);
                memset(blk + BOUND_A * NPB, 0, sizeof(double) * (size_t)NPB);
            }
            const double *Mm = pcold(ps, PC_MASS);
            const int *mat = pcoli(ps, PC_MAT);
            for (int i = 0; i < n; i++) { /* serial: the same sums at any thread count */
                const double c = Mm[i] * material_specific_heat(&s->mats.slot[mat[i]], ps, i);
                grid_point_nodes pn;
                grid_point_nodes_of(g, X + 3 * i, &pn);
                for (int j = 0; j < pn.n; j++) {
                    pn.node[j][BOUND_W * NPB + pn.l[j]] += pn.w[j] * c;
                    pn.node[j][BOUND_A * NPB + pn.l[j]] += pn.w[j] * c * T[i];
                }
            }
            const int sums[2] = {BOUND_W, BOUND_A};
            hearth_status st = mpm_ranks_fields_sum(s, sums, 2, err);
            if (st) return st;
            for (int k = 0; k < g->nactive; k++) {
                double *blk = grid_block(g, k);
                for (int l = 0; l < NPB; l++)
                    blk[BOUND_A * NPB + l] = blk[BOUND_W * NPB + l] > 0 ? blk[BOUND_A * NPB + l] / blk[BOUND_W * NPB + l] : 0.0;
            }
        }
        for (int i = 0; i < n; i++) { /* serial: the same shares at any thread count */
            if (!(phi[i] > 0)) continue;
            grid_point_nodes pn;
            grid_point_nodes_of(g, X + 3 * i, &pn);
            for (int j = 0; j < pn.n; j++) {
                double *th = &pn.node[j][BOUND_MARK * NPB + pn.l[j]];
                *th = phi[i] >= 1.0 ? 1.0 : fmin(1.0, *th + phi[i] * (1.0 - *th));
            }
        }
        const int mark = BOUND_MARK;
        hearth_status st = mpm_ranks_fields_sum(s, &mark, 1, err); /* MPI: a halo node's share is its owner's */
        if (st) return st;
        marked = moved_any = 1;
        /* each particle's move from its step-start temperature, by the shares so far */
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
        for (int i = 0; i < n; i++) {
            cor[i] = 0.0;
            if (flags && (flags[i] & PF_HOLD_T)) continue;
            grid_point_nodes pn;
            grid_point_nodes_of(g, X + 3 * i, &pn);
            for (int j = 0; j < pn.n; j++) {
                const double *node = pn.node[j];
                const int l = pn.l[j];
                const double th = fmin(node[BOUND_MARK * NPB + l], 1.0); /* MPI slabs sum two ranks' shares of a halo node */
                if (th > 0) cor[i] += pn.w[j] * th * (node[BOUND_A * NPB + l] - T[i]);
            }
        }
    }
    /* the boundary particles, clamped at the bounds: the heat a source's Robin term let in past its own
     * temperature goes back to it (the oven's ledger, latent_heat, counts what its particles return) */
    if (flags) {
        const double *Mm = pcold(ps, PC_MASS);
        const int *mat = pcoli(ps, PC_MAT);
        double ret_oven = 0;
        for (int i = 0; i < n; i++) {
            if (!(flags[i] & PF_BOUNDARY) || (flags[i] & PF_HOLD_T)) continue;
            double cl = 0;
            leaves(s, i, X, T, moved_any ? cor[i] : 0.0, marked, &bd, &cl);
            if (cl == 0.0) continue;
            if (!moved_any) memset(cor, 0, sizeof(double) * (size_t)n), moved_any = 1;
            cor[i] += cl;
            const double back = Mm[i] * material_specific_heat(&s->mats.slot[mat[i]], ps, i) * cl;
            if (s->heat.bnd_coef[i] > 0) ret_oven += back;
            else thermal_sheet_return(s, i, back); /* a drawing sheet's contact alone: back to the sheet */
        }
        thermal_sheet_returns_done(s);
        /* MPI slabs: every rank's particles, as oven_ledger's own sum (thermal.c); each rank's alone left the
         * ledger short by the other ranks' returns once a boundary particle was clamped (docs/validation.md, "A
         * sticky face holds what touched it") */
        if (s->mpm->nranks > 1) mpm_ranks_fields_reduce(s, &ret_oven, 1, NULL, 0);
        s->heat.step_oven_heat += ret_oven;
    }
    if (!moved_any) return HEARTH_OK;
    for (int i = 0; i < n; i++) T[i] += cor[i];
    return HEARTH_OK;
}
