/* mpm_g2p.c: G2P, the grid's velocities back to the particles (APIC, Jiang
 * et al. 2015), F advanced by C (Ding et al. 2019 eq. 15-16), positions
 * moved, the fields' changes handed out, and each block's partials reduced
 * into the step report in block order. mpm.c says how the step is ordered. */
#include <math.h>
#include <string.h>

#include "mpm_block.h"
#include "gas.h"
#include "boundary.h"
#include "transport.h"

#ifdef _OPENMP
#include <omp.h>
#endif

FORCE_INLINE void g2p_block(hearth_scene *s, const int D, const int HEAT, const int WATER, const int TWO, int k, double dt,
                            double *tile) {
    grid *g = &s->g;
    particles *ps = &s->ps;
    /* HEAT 2: the update also needs the nodes' temperature at the particle (a FLIP-PIC blend or held
     * temperatures); HEAT 1, pure FLIP (heat_flip = 1, nothing held, the usual case), gathers only the change */
    const int PIC = HEAT == 2;
    double *Tcol = HEAT ? pcold(ps, PC_TEMPERATURE) : NULL, *Tmax = HEAT ? pcold(ps, PC_TEMP_MAX) : NULL;
    double *Gcol = HEAT && (ps->enabled & (1u << PC_GAS)) ? pcold(ps, PC_GAS) : NULL;
    double *Mcol = Gcol && (ps->enabled & (1u << PC_GAS_MADE)) ? pcold(ps, PC_GAS_MADE) : NULL; /* gas.h's gas_share_capped */
    const int *flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    const double *hold_h = HEAT && s->heat.nfix > 0 ? s->heat.hold_h : NULL; /* held temperatures (thermal.c) */
    const double boil = HEAT && WATER && s->def.latent_heat ? s->def.boiling_point : INFINITY; /* no boiling: never passed */
    /* latent_heat: the boiling heat goes to water_boil_front's scratch, which hands each node's share to its
     * hot side first (water.c) */
    double *front = boil < INFINITY ? s->water.front : NULL;
    const int vent = Gcol && s->def.gas_vent > 0 && s->boundary.area; /* boundary.c found the surface this step */
    const double fdt = field_dt(s, dt); /* the CO2's time: the fields' cycle (HEAT runs on its field steps only) */
    const pblock pb = s->mpm->pb[k];
    pb_partial *pp = &s->mpm->partial[k];
    /* the next sort's keys (mpm_sort); a periodic scene wraps after G2P and files its particles there */
    int *keys = s->def.periodic[0] || s->def.periodic[1] || s->def.periodic[2] ? NULL : s->mpm->keys;
    int clamped = 0;
    const int TN = D == 2 ? GRID_T * GRID_T : GRID_T * GRID_T * GRID_T;
    const int NPB = g->nodes_per_block;
    /* alpha, how much of a uniform stress over its neighbourhood comes back into a particle's C (mpm_self.c), only at
     * a cfl where mpm_stable_dt's bound on it can be the tighter: the nodes' g_i in tile channels SCH.. SCH + D - 1 */
    const int SELF = mpm_self_asked(s), SCH = D == 2 ? 10 : 6;
    const double *selfg = SELF ? s->mpm->self_g : NULL;
    int bc[3];
    grid_block_coords(g, pb.block, bc);
    const int org[3] = {bc[0] * GRID_B, bc[1] * GRID_B, bc[2] * GRID_B};

    /* gather the tile's velocities once; particles then read a small dense array */
    for (int a = 0; a < GRID_T; a++)
        for (int b = 0; b < GRID_T; b++)
            for (int c = 0; c < (D == 3 ? GRID_T : 1); c++) {
                const int t = D == 2 ? a * GRID_T + b : (a * GRID_T + b) * GRID_T + c;
                int l;
                const int slot = grid_tile_slot_at(g, D, bc, a, b, c, &l);
                const double *node = grid_block(g, slot);
                for (int d = 0; d < 3; d++) tile[d * TN + t] = node[(d + 1) * NPB + l];
                if (HEAT) {
                    tile[3 * TN + t] = node[CH_T * NPB + l] - node[CH_T0 * NPB + l];
                    if (PIC) tile[4 * TN + t] = node[CH_T * NPB + l];
                }
                if (WATER) { /* the change of node saturation, ds_i = dm_i / (rho_0 V_i) (water.c) */
                    const double cw = node[CH_MW * NPB + l];
                    tile[5 * TN + t] = cw > 0 ? node[CH_DMW * NPB + l] / cw : 0.0;
                }
                if (SELF)
                    for (int d = 0; d < D; d++) tile[(SCH + d) * TN + t] = selfg[((size_t)slot * (size_t)NPB + (size_t)l) * MPM_SELF_NCH + (size_t)d];
                if (TWO) { /* two_field (2D): the second field's velocity, the node's reference gradient and body tag */
                    for (int ch = 0; ch < 2; ch++) {
                        tile[(6 + ch) * TN + t] = node[(CH_TF_PX + ch) * NPB + l];
                        tile[(8 + ch) * TN + t] = node[(CH_TF_GX + ch) * NPB + l];
                    }
                    tile[12 * TN + t] = node[CH_TF_GB * NPB + l]; /* past SELF's 10 and 11 */
                }
            }
    const double *dgrad = TWO ? s->mpm->dgrad : NULL;

    double *X = pcold(ps, PC_X), *V = pcold(ps, PC_V), *Cc = pcold(ps, PC_C);
    const double *M = pcold(ps, PC_MASS);
    const int *mat = pcoli(ps, PC_MAT);
    const double dx = g->dx, inv_dx = g->inv_dx, Dinv = 4.0 * inv_dx * inv_dx;
    double lo[3], hi[3];
    for (int d = 0; d < 3; d++) {
        lo[d] = g->lo[d] + dx;                       /* keep every particle's stencil on the grid */
        hi[d] = g->lo[d] + (g->nn[d] - 2) * dx;
        if (s->def.periodic[d]) lo[d] = -INFINITY, hi[d] = INFINITY; /* wrapped after G2P instead */
    }
    /* the colliders near this block, two cells past its nodes (mpm_block.h); a particle outside that box (one that
     * moved far) walks them all */
    int near[COLLIDER_NEAR_CAP];
    double nlo[3], nhi[3];
    const int nnear = mpm_block_colliders(s, bc, 2, nlo, nhi, near);
    double ke = 0, mass = 0, vmax = -1, move2 = 0, selfmax = 0;
    int mover = -1;
    double w_removed = 0, w_dmax = 0, w_emax = 0, w_lmax = 0;
    int fastest = -1;
    long ood = 0;
    for (int i = pb.start; i < pb.end; i++) {
        double *x = X + 3 * i, *v = V + 3 * i, *C = Cc + (D == 2 ? 4 : 9) * i; /* 2D: the in-plane 2x2 (tensor2.h) */
        int base[3];
        double fx[3], w[3][3];
        tile_stencil(g, D, x, org, inv_dx, base, fx, w);
        double nv[3] = {0, 0, 0}, B[9] = {0}, dT = 0, Tn = 0, ds = 0; /* 2D sums B's in-plane entries 0, 1, 3, 4 */
        double self = 0; /* SELF: sum_i w_ip (x_i - x_p) . g_i */
        /* the stencil's corner in the tile: the 3^dim nodes then sit at constant offsets from it */
        const double *const tp = tile + (D == 2 ? base[0] * GRID_T + base[1] : (base[0] * GRID_T + base[1]) * GRID_T + base[2]);
        /* 3D sums nv and B in pairs of lanes: Ak = {B[3k], B[3k+1]} += (wt u_k) {d0, d1} and Nk = {nv[k], B[3k+2]}
         * += (wt u_k) {1, d2}. Each lane does the scalar sum's operations in its order ((wt u_k) 1 is wt u_k
         * exactly), so the bits are the same; the sums take half the instructions (3D G2P, callgrind). */
        v2d A0 = {0, 0}, A1 = {0, 0}, A2 = {0, 0}, N0 = {0, 0}, N1 = {0, 0}, N2 = {0, 0};
        v2d q2[3] = {{1.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}};
        if (D == 3)
            for (int c = 0; c < 3; c++) q2[c][1] = (c - fx[2]) * dx;
        for (int a = 0; a < 3; a++) {
            const double d0 = (a - fx[0]) * dx;
            for (int b = 0; b < 3; b++) {
                const double d1 = (b - fx[1]) * dx, wab = w[0][a] * w[1][b];
                if (D == 2) {
                    const int t = a * GRID_T + b;
                    /* two_field: a particle of the node's second field reads that field's velocity */
                    const int sec = TWO && mpm_two_field_second(tp[8 * TN + t], tp[9 * TN + t], tp[12 * TN + t], dgrad + 3 * i);
                    const double u0 = sec ? tp[6 * TN + t] : tp[t], u1 = sec ? tp[7 * TN + t] : tp[TN + t];
                    if (HEAT) dT += wab * tp[3 * TN + t];
                    if (PIC) Tn += wab * tp[4 * TN + t];
                    if (WATER) ds += wab * tp[5 * TN + t];
                    if (SELF) self += wab * (d0 * tp[SCH * TN + t] + d1 * tp[(SCH + 1) * TN + t]);
                    nv[0] += wab * u0;
                    nv[1] += wab * u1;
                    B[0] += wab * u0 * d0; B[1] += wab * u0 * d1;
                    B[3] += wab * u1 * d0; B[4] += wab * u1 * d1;
                } else {
                    const v2d p01 = {d0, d1};
                    for (int c = 0; c < 3; c++) {
                        const double wt = wab * w[2][c];
                        const int t = (a * GRID_T + b) * GRID_T + c;
                        if (HEAT) dT += wt * tp[3 * TN + t];
                        if (PIC) Tn += wt * tp[4 * TN + t];
                        if (WATER) ds += wt * tp[5 * TN + t];
                        if (SELF) self += wt * (d0 * tp[SCH * TN + t] + d1 * tp[(SCH + 1) * TN + t] + q2[c][1] * tp[(SCH + 2) * TN + t]);
                        const double wu0 = wt * tp[t], wu1 = wt * tp[TN + t], wu2 = wt * tp[2 * TN + t];
                        const v2d g0 = {wu0, wu0}, g1 = {wu1, wu1}, g2 = {wu2, wu2};
                        A0 += g0 * p01; N0 += g0 * q2[c];
                        A1 += g1 * p01; N1 += g1 * q2[c];
                        A2 += g2 * p01; N2 += g2 * q2[c];
                    }
                }
            }
        }
        if (D == 3) {
            nv[0] = N0[0], nv[1] = N1[0], nv[2] = N2[0];
            B[0] = A0[0], B[1] = A0[1], B[2] = N0[1];
            B[3] = A1[0], B[4] = A1[1], B[5] = N1[1];
            B[6] = A2[0], B[7] = A2[1], B[8] = N2[1];
        }
        /* alpha = tr(D^-1 sum_i w_ip (x_i - x_p) g_i^T) / dim: 1 for a lone particle or cluster, ~0 inside a body */
        if (SELF) selfmax = fmax(selfmax, Dinv * self / D);
        if (D == 2) C[0] = Dinv * B[0], C[1] = Dinv * B[1], C[2] = Dinv * B[3], C[3] = Dinv * B[4];
        else
            for (int a = 0; a < 9; a++) C[a] = Dinv * B[a];
        /* the water the particle held when the step began, for boiling's heat capacity below (P2G's; water_take
         * changes the water first) */
        const double w_step = WATER ? pcold(ps, PC_WATER)[i] : 0.0;
        /* water first: its step limits use the temperature the flux was evaluated at */
        if (WATER) w_removed += water_take(s, i, ds, &w_dmax, &w_emax, &w_lmax);
        if (HEAT) { /* FLIP (eq. 21): the particle takes its nodes' temperature change */
            const double T0 = Tcol[i], flip = s->def.heat_flip;
            double T1 = !PIC ? T0 + dT : thermal_flip_blend(flip, T0, dT, Tn); /* FLIP-PIC blend */
            if (PIC && hold_h && hold_h[i] > 0) T1 += hold_h[i] * (Tn - T1); /* toward held nodes (thermal.c's held_settle) */
            /* a held body's particle keeps its temperature (thermal.c holds its nodes) */
            if (front) front[2 * i] = 0.0;
            /* the temperature the gas below reads: the particle's own, or a front sender's T_b plus the excess its
             * water cannot boil, which it keeps (boil_front.c: it sends min(E, L spare)); so a dried particle whose
             * spare is one ulp makes the gas one with none makes, not the gas of T_b (the front hands out the rest
             * after G2P); NaN: the particle's own */
            double Tgas = NAN;
            if (!(flags && (flags[i] & PF_HOLD_T))) {
                Tcol[i] = T1;
                /* interior boiling (latent_heat): wet matter stays at the boiling point (water.c) */
                if (WATER && T1 > boil) {
                    const double mc = pcold(ps, PC_MASS)[i] * material_specific_heat_of(&s->mats.slot[mat[i]], ps, i, w_step);
                    const double vol = mpm_state_of(s)->vol[i];
                    const double spare = pcold(ps, PC_WATER)[i] - water_floor(s->mats.slot[mat[i]].core[CP_WATER_DENSITY], vol);
                    if (front && spare > 0 && mc > 0) { /* water_boil's test; the heat to water_boil_front */
                        front[2 * i] = mc * (T1 - boil), front[2 * i + 1] = mc;
                        Tcol[i] = boil;
                        const double E = front[2 * i];
                        Tgas = boil + (E - water_front_sent(E, water_room(spare))) / mc; /* boil + 0 / mc = boil when wet */
                    } else if (!front) {
                        w_removed += water_boil(s, i, &Tcol[i], boil, vol, mc);
                    }
                }
            }
            if (Tcol[i] > Tmax[i]) Tmax[i] = Tcol[i];
            if (Gcol) { /* CO2 over the cycle, temperature moving linearly from T0 to T1 (§5.4), less what its
                         * earlier steps made (gas.c's gas_between: the gas moves every step) */
                const material_slot *gm = &s->mats.slot[mat[i]];
                const double R0 = gm->params[gm->density_index];
                double *made = Mcol ? Mcol + 2 * (size_t)i : NULL; /* each share within its amount, if it has one */
                Gcol[i] += gas_share_capped(gas_moles_field_step(T0, isnan(Tgas) ? Tcol[i] : Tgas, fdt, s->field_acc,
                                                                 gm->core[CP_GAS_RATE], R0, gm->core[CP_REACTION_T],
                                                                 gm->core[CP_REACTION_WIDTH]),
                                            R0, gm->core[CP_GAS_AMOUNT], made);
                if (gm->core[CP_GAS_RATE_2] > 0) /* the second share, after the first (gas.c) */
                    Gcol[i] += gas_share_capped(gas_moles_field_step(T0, isnan(Tgas) ? Tcol[i] : Tgas, fdt, s->field_acc,
                                                                     gm->core[CP_GAS_RATE_2], R0, gm->core[CP_REACTION_T_2],
                                                                     gm->core[CP_REACTION_WIDTH_2]),
                                                R0, gm->core[CP_GAS_AMOUNT_2], made ? made + 1 : NULL);
                if (vent) Gcol[i] = gas_vent(s, i, Gcol[i], dt); /* open surface pores vent to the air (gas.c) */
            }
        }
        if (flags && (flags[i] & PF_FIXED)) { /* a pinned particle keeps its place */
            memset(v, 0, 3 * sizeof(double));
            memset(C, 0, (D == 2 ? 4 : 9) * sizeof(double));
            if (keys) {
                clamped += clamp_to_grid(g, x);
                keys[i] = block_of_position(g, x);
            }
            continue;
        }
        /* A grip carries the particles inside it rigidly (the nodes near its
         * face mix in the material's velocity, which let a held end slip out),
         * but their C stays the grid's: deep inside, where every node is held,
         * that is the grip's skew(omega); within a cell of the face it takes the
         * free material's shear, so the stress is continuous across the face
         * and the face holds. With C = skew(omega) there the carried particles
         * stayed unstressed, the first free node row saw a free surface and the
         * material slid off unless the nodes a cell outside were held too: a
         * clamp a cell in from the face (`grip_cantilever_clamped_at_face`). */
        int carried = 0;
        int listed = nnear >= 0 && point_in_box(nlo, nhi, x);
        for (int q = 0, nq = listed ? nnear : s->ncol; q < nq && !carried; q++) {
            const int c = listed ? near[q] : q;
            if (s->cols[c].mode == HEARTH_GRIP && collider_near(&s->cols[c], x))
                carried = collider_carry_particle(&s->cols[c], D, dt, x, v, NULL);
        }
        /* The guard judges motion, not only the end speed: a wall or collider
         * below may zero v after the particle has already jumped cells. The
         * grid's velocity over dt is the motion asked for; a carried particle
         * moves with its grip. */
        const double xo[3] = {x[0], x[1], x[2]};
        int out = 0;
        for (int d = 0; d < D; d++) {
            if (!carried) {
                v[d] = nv[d];
                x[d] += dt * nv[d];
            }
            /* a particle that left the domain is put back on its edge and counted, never dropped */
            if (x[d] < lo[d]) { x[d] = lo[d]; out = 1; }
            else if (x[d] > hi[d]) { x[d] = hi[d]; out = 1; }
        }
        ood += out;
        /* Grid nodes past the middle of a thin wall see the far face's normal and
         * let material through; a particle that ends inside a collider is put
         * back on its surface (the usual particle-level safeguard). */
        listed = nnear >= 0 && point_in_box(nlo, nhi, x);
        for (int q = 0, nq = listed ? nnear : s->ncol; q < nq && !carried; q++) {
            const int c = listed ? near[q] : q;
            if (!collider_near(&s->cols[c], x) || !collider_project_particle(&s->cols[c], D, x, v)) continue;
            if (listed && !point_in_box(nlo, nhi, x)) { /* pushed out of the box: the colliders after c, all of them */
                for (int c2 = c + 1; c2 < s->ncol; c2++)
                    if (collider_near(&s->cols[c2], x)) collider_project_particle(&s->cols[c2], D, x, v);
                break;
            }
        }
        /* The sort's clamp and key, here where x is in registers: a collider
         * may have pushed x off the grid, and NaN goes to the low edge, as in
         * clamp_to_grid (lo and hi are its bounds off a periodic axis, and a
         * periodic scene files no keys here). */
        if (keys) {
            int bk[3] = {0, 0, 0}, off = 0;
            for (int d = 0; d < D; d++) {
                if (!(x[d] >= lo[d])) x[d] = lo[d], off = 1;
                else if (x[d] > hi[d]) x[d] = hi[d], off = 1;
                bk[d] = (int)((unsigned)base_node((x[d] - g->lo[d]) * inv_dx) / GRID_B);
            }
            clamped += off;
            keys[i] = grid_block_id(g, bk[0], bk[1], bk[2]);
        }
        {
            double m2 = 0;
            for (int d = 0; d < D; d++) {
                const double dd = carried ? x[d] - xo[d] : dt * nv[d];
                m2 += dd * dd;
            }
            if (m2 > move2) { move2 = m2; mover = i; }
        }
        if (!all_finite(x, 3)) record_fail(pp, i, FAIL_X, 0);
        else if (!all_finite(v, 3)) record_fail(pp, i, FAIL_V, 0);
        else if (!all_finite(C, D == 2 ? 4 : 9)) record_fail(pp, i, FAIL_C, 0);
        const double sp2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
        ke += 0.5 * M[i] * sp2;
        mass += M[i];
        if (sp2 > vmax) { vmax = sp2; fastest = i; }
    }
    pp->ke = ke;
    pp->mass = mass;
    pp->vmax = vmax;
    pp->fastest = fastest;
    pp->selfmax = selfmax;
    pp->move = sqrt(move2);
    pp->mover = mover;
    pp->ood = ood;
    pp->clamped = clamped;
    pp->water_removed = w_removed;
    pp->water_dmax = w_dmax;
    pp->water_emax = w_emax;
    pp->water_lmax = w_lmax;
}

/* G2P's, indexed [dim == 3][heat][water], heat 0 (none), 1 (FLIP) or 2 (with the PIC part: g2p_heat) */
BLOCK_FN(g2p, 2, 0, 0) BLOCK_FN(g2p, 2, 0, 1) BLOCK_FN(g2p, 2, 1, 0) BLOCK_FN(g2p, 2, 1, 1) BLOCK_FN(g2p, 2, 2, 0) BLOCK_FN(g2p, 2, 2, 1)
BLOCK_FN(g2p, 3, 0, 0) BLOCK_FN(g2p, 3, 0, 1) BLOCK_FN(g2p, 3, 1, 0) BLOCK_FN(g2p, 3, 1, 1) BLOCK_FN(g2p, 3, 2, 0) BLOCK_FN(g2p, 3, 2, 1)
static const block_fn g2p_fns[2][3][2] = {{{g2p_200, g2p_201}, {g2p_210, g2p_211}, {g2p_220, g2p_221}},
                                          {{g2p_300, g2p_301}, {g2p_310, g2p_311}, {g2p_320, g2p_321}}};

/* two_field's, 2D, indexed [heat][water] as above */
#define G2P_TWO_FN(H, W) \
    static void g2p_two_##H##W(hearth_scene *s, int k, double dt, double *tile) { g2p_block(s, 2, H, W, 1, k, dt, tile); }
G2P_TWO_FN(0, 0) G2P_TWO_FN(0, 1) G2P_TWO_FN(1, 0) G2P_TWO_FN(1, 1) G2P_TWO_FN(2, 0) G2P_TWO_FN(2, 1)
static const block_fn g2p_two_fns[3][2] = {{g2p_two_00, g2p_two_01}, {g2p_two_10, g2p_two_11}, {g2p_two_20, g2p_two_21}};

/* G2P's heat instantiation: 0 without heat; 1 for pure FLIP, whose update
 * needs only the nodes' temperature change; 2 where it also reads their
 * temperature (a FLIP-PIC blend, heat_flip < 1, or held temperatures), which
 * is one more channel gathered per node (0.15M of the 2D dough's 18.4M
 * instructions a step, callgrind). */
static int g2p_heat(const hearth_scene *s) {
    if (!heat_now(s)) return 0;
    return s->def.heat_flip != 1.0 || s->heat.nfix > 0 ? 2 : 1;
}

block_fn g2p_fn(const hearth_scene *s) {
    if (s->def.two_field) return g2p_two_fns[g2p_heat(s)][water_now(s)];
    return g2p_fns[s->g.dim == 3][g2p_heat(s)][water_now(s)];
}

/* G2P's blocks for the team of the enclosing region (one thread outside one);
 * no barrier at the end. Guided, not dynamic chunks of 2: neighbouring
 * particle blocks share a cache line of each column they write at their
 * border (x, v, C, the keys, F in P2G) and their partials' lines, so blocks
 * handed out two at a time to alternating threads had both cores write the
 * same lines at about every other border in every pass, a cost that grows
 * with the number of blocks (2D's blocks hold 64 particles where 3D's hold
 * 512: 8 times the borders a particle). Guided hands each thread long runs
 * of neighbouring blocks (half of what is left, then less), so a pass has
 * about 2 log2(blocks) borders between threads instead of blocks / 2, and it
 * still ends in single blocks where a late thread catches up. */
void g2p_team(hearth_scene *s, block_fn fn, double dt) {
    const mpm_state *m = s->mpm;
    double tile[9 * GRID_T * GRID_T * GRID_T]; /* 3D's channels 6-8: SELF's g_i */
    if (m->claims) { /* 3D at more than one thread: from both ends, the same thread on the same end as P2G (claim_take) */
        const int back = claim_end();
        for (int k; (k = claim_take(&m->claims->g2p, back)) >= 0;) fn(s, k, dt, tile);
        return;
    }
#pragma omp for schedule(guided) nowait
    for (int k = m->k_lo; k < m->k_hi; k++) fn(s, k, dt, tile); /* this rank's blocks (all on one rank) */
}

/* The blocks' partials into the step report, in block order, so sums and the first failure do not depend on threads. */
void g2p_reduce(hearth_scene *s, step_report *rep) {
    mpm_state *m = s->mpm;
    mpm_ranks_gather(s);
    *rep = (step_report){.particle = -1, .fastest = -1, .mover = -1};
    double vmax = -1, mass = 0;
    for (int k = 0; k < m->npb; k++) {
        const pb_partial *pp = &m->partial[k];
        if (pp->fail_i >= 0 && (rep->particle < 0 || pp->fail_i < rep->particle)) {
            rep->particle = pp->fail_i;
            rep->kind = (fail_kind)pp->fail_kind;
            rep->code = pp->fail_code;
        }
        rep->kinetic += pp->ke;
        mass += pp->mass;
        if (pp->vmax > vmax) {
            vmax = pp->vmax;
            rep->fastest = pp->fastest;
        }
        if (pp->move > rep->max_move) {
            rep->max_move = pp->move;
            rep->mover = pp->mover;
        }
        if (pp->cmax > rep->c_max) rep->c_max = pp->cmax;
        if (pp->numax > rep->nu_max) rep->nu_max = pp->numax;
        if (pp->selfmax > rep->self_max) rep->self_max = pp->selfmax;
        rep->out_of_domain += pp->ood + pp->clamped;
    }
    /* the keys stand for the positions the step leaves, if it stands (s->step is then one more) */
    const int wrap = s->def.periodic[0] || s->def.periodic[1] || s->def.periodic[2];
    m->keys_n = wrap ? -1 : s->ps.n;
    m->keys_step = s->step + 1;
    m->keys_edits = s->ps.edits;
    rep->max_speed = vmax > 0 ? sqrt(vmax) : 0.0;
    rep->mass = mass;
}

void mpm_g2p(hearth_scene *s, double dt, step_report *rep) {
    const block_fn fn = g2p_fn(s);
    mpm_claims cl;
    claims_begin(s, &cl);
#pragma omp parallel if (s->ps.n >= SCENE_PARALLEL_MIN)
    g2p_team(s, fn, dt);
    claims_end(s->mpm);
    g2p_reduce(s, rep);
}

/* G2P's blocks in the one-region step, chunk by chunk, each first to its P2G's thread (span_next); no barrier.
 * Each block's place in the block table back to none as it goes (every gather is done: the grid update's wait),
 * for the next step's scatter. */
void g2p_chunks(hearth_scene *s, mpm_sort_team *t, block_fn fn, double dt) {
    mpm_state *m = s->mpm;
    double tile[9 * GRID_T * GRID_T * GRID_T]; /* 3D's channels 6-8: SELF's g_i */
    span_walk w = span_walk_start(t->T);
    int lo, hi;
    while (span_next(t->span[MPM_SPAN_G2P], &w, NULL, &lo, &hi))
        for (int k = lo; k < hi; k++) {
            fn(s, k, dt, tile);
            m->pbof[m->pb[k].block] = -1;
        }
    span_count(s->mpm, MPM_SPAN_G2P, &w);
}

