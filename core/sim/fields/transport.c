/* transport.c: the particle pass of the diffusive fields' grid operators.
 *
 * Heat (Ding et al. 2019 eq. 9, §6.3) and water (eq. 22, 25) are both
 * diffusion on the grid with particle quadrature: each particle gathers its
 * nodes' value and gradient, and scatters grad w_ip . (flux) plus its
 * boundary and source terms back. One pass does both when both fields are
 * live, so their stencils, tiles and volumes are computed once per particle
 * (the fields' cost against the momentum step is a target of issue #4).
 *
 * Heat:   out_i += sum_p grad w_ip . (V_p kappa_p grad x_p) + sum_p S_p beta_p w_ip x_p,
 *         src_i += sum_p w_ip (S_p beta_p theta_out,p - V0 c lambda theta_abs,p div v_p - L e_p),
 *         e_p the particle's evaporation (kg/s) when the scene's latent_heat is on,
 *         x the input channel: node temperature, or the CG direction.
 * Water:  dm_i += dt sum_p V_p q_p . grad w_ip - dt sum_p w_ip beta^w theta_p (s_surface,p - s_amb) S_p,
 *         q_p = -K theta rho_0^w s_p grad s (eq. 22), and with water_momentum the
 *         relative water momentum of eq. 26-27 (see water.c); s_amb the oven's
 *         ambient saturation; s_surface,p from the grid's s_p at the particle and
 *         the depth of that sample (water_surface_excess). Wet colliders' faces: water_face_flux, after this pass.
 * The conduction and Fick terms use the B-spline gradients, whose columns sum
 * to zero, so neither creates heat or water.
 *
 * Forward Euler's conduction volume (cond_volume_cap): a particle conducts
 * over its quadrature volume J V_0 but holds heat m alpha = rho_0 alpha V_0,
 * so its diffusivity is J kappa / (rho_0 alpha), and thermal_dt_limit's
 * rho_0 alpha dx^2 / (2 dim kappa) covers J up to that limit over the step
 * taken. A particle that swells far past it (a lone molten one under its
 * thermal pressure, eq. 10: J ~ 1e30 in marshmallow.lua at expansion 2 Pa/K)
 * made the step unstable, and its temperature and its neighbours' went to
 * 1e30-1e90 degC (`lone_hot_particles_stay_bounded`). So the explicit pass
 * conducts over at most COND_J_MARGIN V_0 (dt limit / dt), and the heat still
 * sums to zero over the nodes. The margin 2: thermal_dt_limit is itself
 * conservative for a full body (quadratic B-splines' stiffness stencil
 * [-1/6, -1/3, 1, -1/3, -1/6] / dx^2 peaks at 4 / (3 dx^2) against the lumped
 * capacity, so forward Euler holds to 1.5 rho alpha dx^2 / kappa, 6x the 2D
 * limit), and swollen doughs are common: at margin 1 the cap acted on 6.2e6
 * particle-steps of the test suite (J 1-2 at a heat-limited step), moving
 * their numbers; at 2 only on 1539, all in bodies that swell without end
 * (J up to 1e50). The implicit solve needs no cap and has none.
 *
 * Particle blocks go in the 2^dim colours of P2G: deterministic, no atomics.
 * Dimension and the live fields are compile-time constants of each
 * instantiation, as in mpm.c.
 *
 * Where it sits in a step: between P2G and the momentum grid update,
 * boundary.c measures the air surface and hands each particle its share,
 * thermal.c and water.c turn node sums into temperature and saturation and
 * fill the boundary particles' coefficients, and this pass applies both
 * diffusion operators (forward Euler heat folds its sources into the same
 * sum); then thermal.c updates node temperatures (explicitly, or by CG whose
 * products are heat-only passes of this file). Water's flux and evaporation
 * run before the momentum grid update so the relative water momentum
 * (water_momentum, eq. 26-27) can join the grid momentum, and every pass sees
 * P2G's positions.
 *
 * Cost against the momentum step (3D bench; scripts/bench/fields_instructions.sh
 * counts instructions, fields_overhead.sh times): heat 1.57x and all fields
 * 1.92x in instructions, against 2.3x and 3.7x when each field had passes of
 * its own (at 24 cells, with the boundary since measured: 1.76x and 2.18x,
 * docs/performance.md "The fields' passes"). */
#include "transport.h"

#include <math.h>
#include <string.h>

#include "scene.h"
#include "mpm.h"

#include "physics_constants.h"
/* cond_volume_cap's margin over forward Euler's limit (header) */
#define COND_J_MARGIN 2.0
#define FORCE_INLINE static inline __attribute__((always_inline))

FORCE_INLINE int tile_index(const int D, const int base[3], int a, int b, int c) {
    return D == 2 ? (base[0] + a) * GRID_T + base[1] + b : ((base[0] + a) * GRID_T + base[1] + b) * GRID_T + base[2] + c;
}

/* Two doubles in one register (GCC's vector extension; SSE2 on x86-64): the 2D
 * passes below do two lanes of the same arithmetic at once. Each lane does the
 * operations of the scalar code in its order (the build does not contract a
 * product and a sum into an FMA: -std=c17 sets -ffp-contract=off), so the
 * results are the scalar code's to the bit. */
typedef double v2d __attribute__((vector_size(16)));
FORCE_INLINE v2d v2_load(const double *p) {
    v2d v;
    memcpy(&v, p, sizeof v);
    return v;
}
FORCE_INLINE void v2_store(double *p, v2d v) { memcpy(p, &v, sizeof v); }

/* v and grad v at a particle from tile values, for NC (1 or 2) channels at
 * once so they share the stencil: sum_i v_i w_ip and sum_i v_i grad w_ip. */
FORCE_INLINE void gather(const int D, const int NC, const double *const v[2], const int base[3], double w[3][3],
                         double dw[3][3], double val[2], double grad[2][3]) {
    if (D == 2) { /* the pairs (ta, tb) and (val, grad_0) in one register each: the same sums lane by lane */
        const v2d wd1[3] = {{w[1][0], dw[1][0]}, {w[1][1], dw[1][1]}, {w[1][2], dw[1][2]}};
        v2d vg[2] = {{val[0], grad[0][0]}, {val[1], grad[1][0]}};
        for (int a = 0; a < 3; a++) {
            const v2d wd0 = {w[0][a], dw[0][a]};
            v2d tab[2] = {{0, 0}, {0, 0}};
            for (int b = 0; b < 3; b++) {
                const int t = tile_index(D, base, a, b, 0);
                for (int k = 0; k < NC; k++) tab[k] += v[k][t] * wd1[b];
            }
            for (int k = 0; k < NC; k++) {
                vg[k] += tab[k][0] * wd0;
                grad[k][1] += tab[k][1] * w[0][a];
            }
        }
        for (int k = 0; k < NC; k++) val[k] = vg[k][0], grad[k][0] = vg[k][1];
        return;
    }
    for (int a = 0; a < 3; a++) {
        /* sum over b of (w1, dw1) x (sum over c of w2) and w1 x (sum over c of dw2) */
        double ta[2] = {0, 0}, tb[2] = {0, 0}, tc[2] = {0, 0};
        for (int b = 0; b < 3; b++) {
            const int t = tile_index(D, base, a, b, 0);
            for (int k = 0; k < NC; k++) {
                double s0, s1 = 0;
                if (D == 3) {
                    const double *vc = v[k] + t;
                    s0 = vc[0] * w[2][0] + vc[1] * w[2][1] + vc[2] * w[2][2];
                    s1 = vc[0] * dw[2][0] + vc[1] * dw[2][1] + vc[2] * dw[2][2];
                } else {
                    s0 = v[k][t];
                }
                ta[k] += s0 * w[1][b];
                tb[k] += s0 * dw[1][b];
                tc[k] += s1 * w[1][b];
            }
        }
        for (int k = 0; k < NC; k++) {
            val[k] += ta[k] * w[0][a];
            grad[k][0] += ta[k] * dw[0][a];
            grad[k][1] += tb[k] * w[0][a];
            if (D == 3) grad[k][2] += tc[k] * w[0][a];
        }
    }
}

/* out_k,i += grad w_ip . f_k + w_ip r_k for NC (1 or 2) outputs sharing the stencil,
 * one axis at a time as the gather: with w_ip = w0_a w1_b w2_c, the node's term
 * is w1_b u_a + dw1_b q_a (2D), u_a = w0_a r + dw0_a f_0 and q_a = w0_a f_1 once
 * a row; 3D takes (w1_b u_a + dw1_b q_a) w2_c + (w1_b z_a) dw2_c, z_a = w0_a f_2.
 * About half the products of the node-by-node form, (w0_a w1_b) r + ((dw0_a
 * w1_b) f_0 + (w0_a dw1_b) f_1), that it replaced: the same sums in another
 * order, so the nodes' values moved by round-off (0.26M of the 2D dough's 18.0M
 * instructions a step; docs/performance.md "The fields' passes"). */
FORCE_INLINE void scatter(const int D, const int NC, double *const out[2], const int base[3], double w[3][3],
                          double dw[3][3], double f[2][3], const double r[2]) {
    if (D == 2) { /* nodes b = 0, 1 of each row in one register, b = 2 alone */
        const v2d w1 = {w[1][0], w[1][1]}, dw1 = {dw[1][0], dw[1][1]};
        for (int a = 0; a < 3; a++) {
            const int t = tile_index(D, base, a, 0, 0);
            for (int k = 0; k < NC; k++) {
                const double u = w[0][a] * r[k] + dw[0][a] * f[k][0], q = w[0][a] * f[k][1];
                const v2d A = w1 * u + dw1 * q;
                v2_store(out[k] + t, v2_load(out[k] + t) + A);
                out[k][t + 2] += w[1][2] * u + dw[1][2] * q;
            }
        }
        return;
    }
    const v2d w2 = {w[2][0], w[2][1]}, dw2 = {dw[2][0], dw[2][1]}; /* nodes c = 0, 1 in one register, c = 2 alone */
    for (int a = 0; a < 3; a++) {
        double u[2], q[2], z[2];
        for (int k = 0; k < NC; k++) {
            u[k] = w[0][a] * r[k] + dw[0][a] * f[k][0];
            q[k] = w[0][a] * f[k][1];
            z[k] = w[0][a] * f[k][2];
        }
        for (int b = 0; b < 3; b++) {
            const int t = tile_index(D, base, a, b, 0);
            for (int k = 0; k < NC; k++) {
                const double A = w[1][b] * u[k] + dw[1][b] * q[k], B = w[1][b] * z[k];
                double *oc = out[k] + t;
                v2_store(oc, v2_load(oc) + (w2 * A + dw2 * B));
                oc[2] += A * w[2][2] + B * dw[2][2];
            }
        }
    }
}

/* tile layout: [0] heat input, [1] heat out, [2] heat sources, [3] saturation,
 * [4] water mass change, [5..7] water momentum */
enum { T_IN, T_OUT, T_SRC, T_SAT, T_DM, T_DP, T_COUNT = T_DP + 3 };

FORCE_INLINE void pass_block(hearth_scene *s, const int D, const int HEAT, const int SRC, const int WATER, const int LAT,
                             const transport_pass *tp, int q, double *tile) {
    grid *g = &s->g;
    particles *ps = &s->ps;
    const int NPB = g->nodes_per_block, TN = D == 2 ? GRID_T * GRID_T : GRID_T * GRID_T * GRID_T;
    const int mom = WATER && s->def.water_momentum;
    const mpm_state *m = mpm_state_of(s); /* the sort's blocks and P2G's volumes */
    const pblock pb = m->pb[m->colour_pb[q]];
    const double *vol = m->vol;
    int bc[3];
    grid_block_coords(g, pb.block, bc);
    for (int a = 0; a < GRID_T; a++) /* gather the inputs once into dense tiles */
        for (int b = 0; b < GRID_T; b++)
            for (int c = 0; c < (D == 3 ? GRID_T : 1); c++) {
                int l;
                const double *node = grid_tile_node(g, D, bc, a, b, c, &l);
                const int t = D == 2 ? a * GRID_T + b : (a * GRID_T + b) * GRID_T + c;
                if (HEAT) tile[T_IN * TN + t] = node[tp->heat_in * NPB + l];
                if (WATER) tile[T_SAT * TN + t] = node[CH_SW * NPB + l];
            }
    /* sources into the output channel itself (out_i += (L x)_i - src_i) when the caller asks for one sum */
    const int apart = SRC && tp->heat_src != tp->heat_out;
    if (HEAT) memset(tile + T_OUT * TN, 0, sizeof(double) * (size_t)TN * (apart ? 2 : 1));
    if (WATER) memset(tile + T_DM * TN, 0, sizeof(double) * (size_t)TN * (mom ? 4 : 1));
    double *tin = tile + T_IN * TN, *tout = tile + T_OUT * TN, *tsrc = tile + T_SRC * TN;
    double *sat = tile + T_SAT * TN, *dm = tile + T_DM * TN, *dp = tile + T_DP * TN;

    const double *X = pcold(ps, PC_X), *V0 = pcold(ps, PC_VOL0);
    const double *T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL;
    const double *V = WATER ? pcold(ps, PC_V) : NULL, *W = WATER ? pcold(ps, PC_WATER) : NULL;
    double *Q = mom ? pcold(ps, PC_QW) : NULL; /* kept only for the momentum coupling */
    const double *area = s->boundary.area, *depth = s->boundary.depth, dt = tp->dt, s_amb = s->def.oven_saturation;
    const double psat_b = WATER ? water_psat_boiling(s) : 0.0; /* with latent_heat: the vapour's factor (water.h) */
    const int *mat = pcoli(ps, PC_MAT), *flags = pcoli(ps, PC_FLAGS); /* live with heat and with water */
    int jmax_mat = -1; /* the material whose conduction cap jmax holds: it depends on the material alone */
    double jmax = 0;
    for (int i = pb.start; i < pb.end; i++) {
        int base[3] = {0, 0, 0};
        double w[3][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, dw[3][3] = {{0}};
        for (int d = 0; d < D; d++) {
            const double Xd = (X[3 * i + d] - g->lo[d]) * g->inv_dx;
            const int bb = base_node(Xd); /* floor: the sort keeps X >= 1 (mpm.h) */
            bspline_weights(Xd - bb, w[d], dw[d]);
            for (int k = 0; k < 3; k++) dw[d][k] *= g->inv_dx;
            base[d] = bb - bc[d] * GRID_B;
        }
        const material_slot *ms = &s->mats.slot[mat[i]];
        const double Vp = vol[i]; /* J V_0, from P2G */
        const int bnd = (flags[i] & PF_BOUNDARY) != 0;
        /* value and gradient at the particle, contracted one axis at a time (the
         * weights are a tensor product): about half the work of node by node */
        double val[2] = {0, 0}, grad[2][3] = {{0, 0, 0}, {0, 0, 0}};
        const double *const in[2] = {HEAT ? tin : sat, sat};
        gather(D, HEAT + WATER, in, base, w, dw, val, grad);
        const double xp = HEAT ? val[0] : 0.0, *gx = grad[0], si = WATER ? val[HEAT] : 0.0, *gs = grad[HEAT];
        double qk[3] = {0, 0, 0}, bcoef = 0, source = 0;
        if (HEAT) {
            /* a dried particle conducts less (material_conductivity), whichever fields this pass runs */
            const double k = material_conductivity(ms, ps, i);
            double kv = Vp;
            if (SRC && !apart && k > 0) { /* forward Euler: at most the volume its step covers (cond_volume_cap, above) */
                if (mat[i] != jmax_mat) { /* once per run of one material: the same expression, so the same bits */
                    jmax_mat = mat[i];
                    /* at thermal_dt_limit's alpha / kappa, the smaller of the dried and the wet end's
                     * (material_heat_stiffest): every particle's own cap is then at least this one */
                    double ck, kk;
                    material_heat_stiffest(ms, &ck, &kk);
                    jmax = COND_J_MARGIN * ms->params[ms->density_index] * ck * g->dx * g->dx / (2.0 * D * kk * dt);
                }
                /* fmin's value without the call where the cap does not act (both ordered, Vp below) */
                const double cap = V0[i] * jmax;
                kv = Vp < cap ? Vp : fmin(Vp, cap);
            }
            const double kap = kv * k;
            for (int d = 0; d < 3; d++) qk[d] = kap * gx[d];
            bcoef = bnd ? s->heat.bnd_coef[i] : 0.0; /* thermal.c fills only flagged entries */
            if (SRC) {
                source = bnd ? bcoef * s->heat.bnd_temp[i] : 0.0;
                const double cl = ms->core[CP_EXPANSION];
                if (cl > 0) source -= V0[i] * cl * (T[i] + KELVIN) * particles_trC(ps, i);
            }
        }
        double qn[3] = {0, 0, 0}, evap = 0;
        if (WATER) {
            const double rho0 = ms->core[CP_WATER_DENSITY], sp = W[i] / (rho0 * Vp);
            const double th = (T ? T[i] : ms->core[CP_REFERENCE_T]) + KELVIN; /* absolute: see water.c */
            const double kq = -ms->core[CP_WATER_DIFFUSIVITY] * th * rho0 * sp; /* eq. 22 */
            for (int d = 0; d < 3; d++) qn[d] = kq * gs[d];
            /* evaporation from the saturation the grid sees at the particle, as the
             * heat Robin term uses the interpolated temperature, toward the oven's
             * ambient saturation (our extension: Ding et al. §3.2 dry into s = 0),
             * through the layer between the sample's depth and the surface
             * (water_surface_excess, water.h) */
            if (bnd && area && area[i] > 0) {
                evap = water_evaporation(ms->core[CP_EVAPORATION], ms->core[CP_WATER_DIFFUSIVITY], rho0, th, si, s_amb,
                                         depth[i], area[i], psat_b); /* kg/s */
                /* latent heat (the scene's latent_heat; beyond Ding et al. eq. 9): the
                 * evaporated water leaves with L per kg from this particle's heat, on
                 * the same weights w_ip as the water, so the heat the nodes lose is L
                 * times the water they lose. Implicit heat takes it on the right-hand
                 * side, lagged: the evaporation is the step start's. A compile-time
                 * constant (its own instantiation), so scenes without the switch run
                 * the code they ran before. */
                if (LAT) source -= HEARTH_LATENT_HEAT * evap;
            }
            if (mom) { /* v^w = v^s + q^w / rho^w; the grid takes w V dq + dt V (v^w (x) q^w) grad w */
                double vw[3], dq[3];
                for (int d = 0; d < 3; d++) {
                    vw[d] = V[3 * i + d] + qn[d] / (rho0 * sp);
                    dq[d] = Q[3 * i + d] - qn[d];
                }
                for (int a = 0; a < 3; a++)
                    for (int b = 0; b < 3; b++)
                        for (int c = 0; c < (D == 3 ? 3 : 1); c++) {
                            const double wc = D == 3 ? w[2][c] : 1.0, wt = w[0][a] * w[1][b] * wc;
                            const double qg = qn[0] * dw[0][a] * w[1][b] * wc + qn[1] * w[0][a] * dw[1][b] * wc +
                                              (D == 3 ? qn[2] * w[0][a] * w[1][b] * dw[2][c] : 0.0);
                            const int t = tile_index(D, base, a, b, c);
                            for (int d = 0; d < D; d++) dp[d * TN + t] += Vp * (wt * dq[d] + dt * vw[d] * qg);
                        }
                memcpy(Q + 3 * i, qn, sizeof qn);
            }
        }
        /* scatter grad w . f + w r, again one axis at a time */
        {
            double *const out[2] = {HEAT ? tout : dm, dm};
            double f[2][3], r[2];
            if (HEAT) {
                for (int d = 0; d < 3; d++) f[0][d] = qk[d];
                r[0] = bcoef * xp - (SRC && !apart ? source : 0.0);
            }
            if (WATER) {
                for (int d = 0; d < 3; d++) f[HEAT][d] = dt * Vp * qn[d];
                r[HEAT] = -dt * evap;
            }
            scatter(D, HEAT + WATER, out, base, w, dw, f, r);
        }
        if (apart) {
            double *const out[2] = {tsrc, tsrc};
            double f[2][3] = {{0, 0, 0}, {0, 0, 0}};
            const double r[2] = {source, 0};
            scatter(D, 1, out, base, w, dw, f, r);
        }
    }
    for (int a = 0; a < GRID_T; a++) /* flush into the block and its +1 neighbours */
        for (int b = 0; b < GRID_T; b++)
            for (int c = 0; c < (D == 3 ? GRID_T : 1); c++) {
                const int t = D == 2 ? a * GRID_T + b : (a * GRID_T + b) * GRID_T + c;
                int l;
                double *node = grid_tile_node(g, D, bc, a, b, c, &l);
                if (HEAT) {
                    node[tp->heat_out * NPB + l] += tout[t];
                    if (apart) node[tp->heat_src * NPB + l] += tsrc[t];
                }
                if (WATER) {
                    node[CH_DMW * NPB + l] += dm[t];
                    if (mom)
                        for (int d = 0; d < D; d++) node[(CH_PX + d) * NPB + l] += dp[d * TN + t];
                }
            }
}

typedef void (*block_fn)(hearth_scene *, const transport_pass *, int, double *);
#define PASS(D, H, S, W, L)                                                                                    \
    static void pass_##D##_##H##S##W##L(hearth_scene *s, const transport_pass *tp, int q, double *tile) { \
        pass_block(s, D, H, S, W, L, tp, q, tile);                                                           \
    }
PASS(2, 1, 1, 1, 1) PASS(2, 1, 1, 1, 0) PASS(2, 1, 1, 0, 0) PASS(2, 1, 0, 0, 0) PASS(2, 0, 0, 1, 0)
PASS(3, 1, 1, 1, 1) PASS(3, 1, 1, 1, 0) PASS(3, 1, 1, 0, 0) PASS(3, 1, 0, 0, 0) PASS(3, 0, 0, 1, 0)

void transport_apply(hearth_scene *s, const transport_pass *tp) {
    const int heat = tp->heat_in >= 0, src = heat && tp->heat_src >= 0, water = tp->water, d3 = s->g.dim == 3;
    block_fn fn = NULL;
    if (heat && src && water && s->def.latent_heat) fn = d3 ? pass_3_1111 : pass_2_1111;
    else if (heat && src && water) fn = d3 ? pass_3_1110 : pass_2_1110;
    else if (heat && src) fn = d3 ? pass_3_1100 : pass_2_1100;
    else if (heat && !water) fn = d3 ? pass_3_1000 : pass_2_1000;
    else if (!heat && water) fn = d3 ? pass_3_0010 : pass_2_0010;
    if (!fn) return; /* heat without sources alongside water is never asked for */
    const mpm_state *m = mpm_state_of(s); /* the sort's particle blocks, in colours */
#pragma omp parallel if (s->ps.n >= SCENE_PARALLEL_MIN)
    {
        double tile[T_COUNT * GRID_T * GRID_T * GRID_T];
        for (int col = 0; col < 8; col++) { /* the loop's barrier keeps the colours apart */
#pragma omp for schedule(dynamic, 2)
            for (int q = m->colour_start[col]; q < m->colour_start[col + 1]; q++) fn(s, tp, q, tile);
        }
    }
}
