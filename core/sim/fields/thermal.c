/* thermal.c: heat transport (Ding et al. 2019 eq. 9, §6.3, §6.6).
 *
 *   rho alpha Dtheta/Dt = div(kappa grad theta) - theta c lambda div v
 *
 * Nodes get temperature from the particles weighted by heat capacity
 * m alpha (eq. 17 with alpha folded in, so energy is conserved when alpha
 * varies between materials). The conduction operator is the particle-
 * quadrature Galerkin Laplacian L_ij = sum_p V_p kappa_p grad w_ip . grad w_jp,
 * whose columns sum to zero, so conduction conserves heat exactly in both
 * the forward (gamma = 0) and backward (gamma = 1) Euler updates of §6.3.
 * Particles take the change of their nodes' temperature (FLIP, eq. 21) in G2P.
 * The operator itself is applied by transport.c, in one pass with water's.
 *
 * Boundaries relax toward the outside temperature: the flux into the body is
 * S beta (theta_out - theta) (the printed signs in §4/§6.3 are ambiguous; the
 * analytic slab test decides). Boundary particles and their areas S come from
 * boundary.c (§6.6), with the depth of their temperature sample: the oven's
 * coefficient is beta / (1 + beta d / kappa) (find_boundary). An oven with radiating walls (#18: oven.wall_temperature,
 * oven.emissivity) adds eps sigma (T_w^4 - T_s^4) at the face T_s of that closure, as one coefficient and outside
 * temperature with the air's (thermal.h's thermal_oven_exchange; docs/validation.md, "An oven's hot walls").
 * Heated colliders act through surface quadrature points: each particle within
 * 2 dx of the collider carries V_p delta(sdf) of contact area (delta a hat
 * whose integral is one, so the band sums to the contact area), and its point
 * is its projection on the collider's face, where the Robin term
 * beta (theta_c - theta(x_s)) w_i(x_s) of the weak form is evaluated. The band
 * particles themselves (V_p / dx each, within dx, rejected) put the contact half
 * a cell inside the body and made it first order (`heat_collider_robin_converges`,
 * docs/validation.md). Under latent_heat and forward Euler a point whose nodes
 * carry dried particles reads the dried face instead of theta(x_s) (dried_face:
 * the wet rows' hold at T_b otherwise kept the face's field near T_b and the
 * lone dried row on the tray passed the tray's temperature).
 *
 * Held temperatures (Dirichlet): a collider with infinite beta holds the nodes
 * on or inside its face, a body with fixed_temperature the nodes it fills (at
 * least half their heat capacity); those nodes keep the temperature and leave
 * the unknowns of both schemes (mark_held; the CG below). B-splines do not
 * vanish on the face, so a held collider's face also carries Nitsche's
 * symmetric terms at the same surface points (heat_contact_apply): without
 * them its order was 0.86 and its error eight times larger. A held body has
 * no face to carry them (order 0.9). `heat_dirichlet_slab_converges`.
 *
 * The expansion term uses absolute temperature (theta + 273.15): in degrees C
 * it would change sign at the freezing point.
 *
 * Forward Euler with an oven merges the nodes just past the air surface that
 * hold a sliver of heat capacity into their fullest neighbour, shared equally
 * among neighbours tied for fullest (small_nodes.c:
 * their 1/c increments left a FLIP pattern in the outer particles that did not
 * converge, `heat_slab_surface_rows_converge`).
 * Latent heat (the scene's latent_heat, issue #18; Ding et al.'s eq. 9 has no
 * such term): the water evaporating through the air boundary takes
 * L = HEARTH_LATENT_HEAT per kg from the heat of the particle it leaves. The
 * sink is added where the evaporation is computed (transport.c), on the same
 * weights w_ip as the water it removes, so the nodes lose L times the water
 * they lose; forward Euler folds it into the sources, backward Euler takes it
 * on the right-hand side, lagged (the evaporation is the step start's). Its
 * rate of change with the particle's own temperature is at most L e g
 * (s - s_amb) S, g the vapour factor's bound (water_latent_stiffness, 14.1 at
 * a 100 degC boiling point), so the explicit step is limited as for a Robin
 * coefficient L e g (s - s_amb), with the largest excess the particles hold
 * when the step starts (thermal_dt_limit). With the switch on, oven_ledger (thermal_ledger.c) tallies the oven's Robin
 * heat so that heat in = sensible heat + L x water lost can be checked
 * (`latent_heat_energy_balance`: to 1e-13; a particle that reaches water.c's
 * saturation floor keeps water whose heat was taken, so the books then differ
 * by L times what the floor kept). Rejected: a sink on the particle's
 * temperature after G2P, which would take heat that the nodes never lost
 * from the FLIP update. With the switch, evaporation is driven by the vapour
 * pressure (water.h's water_vapour_factor: Ding et al.'s beta^w theta s alone,
 * linear in theta, let a strong sink cool a surface toward 0 K): a wet
 * surface sits at its wet-bulb balance (`latent_heat_wet_plateau`,
 * `latent_heat_stops_at_wet_bulb`, docs/validation.md). Interior boiling is the
 * other half of the same switch, and it acts on the particles after G2P,
 * where their heat lives: a wet particle past the scene's boiling_point
 * turns the excess into vapour (water.c's water_boil), so a crumb plateaus
 * at 100 degC while a dried crust heats on (`latent_heat_crumb_plateau`);
 * it is a projection, so it needs no step limit.
 *
 * FLIP keeps heat exactly but not a maximum principle: where two materials
 * share nodes a particle can overshoot (seen: 108.7 degC from a 90 degC start
 * in `heat_flip_pic_bounds`), and at a strong Robin contact the contact rows
 * pass the collider's temperature (7035 degC on a 5000 degC tray at beta
 * 1e9). fields/flip_bound.c brings such a particle back before G2P
 * (`heat_flip_pic_bounds`, `heat_stays_within_its_sources`); the nodes'
 * own update is not bounded (the Robin contact's consistent weights, the
 * B-spline Laplacian's positive off-diagonal entries). */
#include "thermal.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "scene.h"
#include "mpm.h"
#include "transport.h"

#include "physics_constants.h"
#include "small_nodes.h"
#include "subcell.h"

/* A heated collider's contact: particles within CONTACT_BAND cells of its face
 * each carry V_p delta(sdf) of its area, delta the hat (2 dx - s) / (2 dx^2) on
 * [0, 2 dx), whose integral is one: a lattice with 1, 2, 3 or 4 particles a
 * cell across the band sums it exactly (the midpoint rule is exact on a line),
 * and a turned lattice samples its smooth slope with little ripple (the box
 * 1/dx on [0, dx) this replaced jumps at s = dx). */
#define CONTACT_BAND 2.0
static inline double contact_delta(double sd, double dx) { return (CONTACT_BAND * dx - sd) / (0.5 * CONTACT_BAND * CONTACT_BAND * dx * dx); }

/* A node is held by a body when at least half its heat capacity is the held
 * particles' (a node on the face between a held and a free body has exactly
 * half: the tolerance decides it for holding, whatever the round-off). */
#define HOLD_TOL 1e-3

/* Nitsche's penalty for a held collider's face, gamma kappa / dx
 * (heat_contact_apply). It must outweigh the flux terms for the symmetric form
 * to stay positive; 4 does on the slab ladders (checked for faces on a node
 * row and turned 30 degrees, not proven for every cut), and the explicit step
 * is limited as for beta = gamma kappa / dx (thermal_dt_limit). */
#define NITSCHE_GAMMA 4.0

void thermal_init(thermal_state *h) { *h = (thermal_state){0}; }

void thermal_free(thermal_state *h) {
    mem_free(h->bnd_coef, sizeof(double) * (size_t)h->bnd_cap);
    mem_free(h->bnd_temp, sizeof(double) * (size_t)h->bnd_cap);
    mem_free(h->bnd_surf, sizeof(double) * (size_t)h->bnd_cap);
    mem_free(h->cg_partial, sizeof(double) * (size_t)h->cg_cap);
    mem_free(h->ct, sizeof(double) * THERMAL_CT * (size_t)h->ct_cap);
    mem_free(h->fix, sizeof(double) * (size_t)h->fix_cap);
    mem_free(h->fix_w, sizeof(double) * (size_t)h->fix_cap);
    mem_free(h->hold_h, sizeof(double) * (size_t)h->hold_cap);
    mem_free(h->sub_fit, sizeof(double) * h->sub_cap);
    mem_free(h->bound_c, sizeof(double) * 2 * (size_t)h->bound_cap);
    thermal_init(h);
}

int thermal_cg_iterations(const hearth_scene *s) { return s->heat.cg_iterations; }

int thermal_active(const hearth_scene *s) { return (s->ps.enabled & (1u << PC_TEMPERATURE)) != 0; }

double thermal_walls_h_max(const hearth_scene *s) {
    if (!thermal_oven_radiates(&s->def)) return 0.0;
    double hot = s->def.oven_temperature; /* the walls or the hottest other heat */
    for (int c = 0; c < s->ncol; c++)
        if (!isnan(s->cols[c].temperature) && s->cols[c].temperature > hot) hot = s->cols[c].temperature;
    const double t = (s->def.oven_wall_temperature > hot ? s->def.oven_wall_temperature : hot) + KELVIN;
    return t > 0 ? 4.0 * thermal_oven_rad(&s->def) * t * t * t : 0.0;
}

double thermal_dt_limit(const hearth_scene *s) {
    if (!thermal_active(s) || s->def.heat_implicit) return INFINITY;
    /* the strongest boundary coupling: a node's heat capacity against S beta */
    double beta = isnan(s->def.oven_temperature) ? 0 : s->def.oven_beta;
    beta += thermal_walls_h_max(s); /* the walls' h_r at its largest (0 without walls) */
    for (int c = 0; c < s->ncol; c++)
        if (!isnan(s->cols[c].temperature) && isfinite(s->cols[c].beta) && s->cols[c].beta > beta) beta = s->cols[c].beta; /* held nodes are not integrated */
    int held = 0; /* a held collider's Nitsche penalty acts as beta = gamma kappa / dx */
    for (int c = 0; c < s->ncol; c++) held |= !isnan(s->cols[c].temperature) && isinf(s->cols[c].beta);
    double dt = INFINITY;
    for (int m = 0; m < s->mats.n; m++) {
        const material_slot *ms = &s->mats.slot[m];
        /* a particle's alpha and kappa follow its water (material.h): conduction at the end, dried or wet, of the
         * smaller alpha / kappa; the Robin terms against the smallest alpha, the dried one (without the dry
         * parameters both are the wet ones, the expressions as before) */
        double ck, k;
        material_heat_stiffest(ms, &ck, &k);
        const double rho = ms->params[ms->density_index], rak = rho * ck, ra = rho * material_specific_heat_min(ms);
        /* forward Euler on the B-spline Laplacian: rho alpha dx^2 / (2 dim kappa), at the reference density;
         * a particle swollen past what the step covers conducts over less than J V_0 (transport.c, cond_volume_cap) */
        if (k > 0) dt = fmin(dt, rak * s->def.dx * s->def.dx / (2.0 * s->def.dim * k));
        /* and on the Robin term: a boundary cell's rho alpha dx^dim against beta dx^(dim-1) */
        if (beta > 0) dt = fmin(dt, ra * s->def.dx / (2.0 * beta));
        /* the Nitsche face conducts at the wet kappa (find_boundary) */
        if (held && ms->core[CP_CONDUCTIVITY] > 0)
            dt = fmin(dt, ra * s->def.dx * s->def.dx / (2.0 * NITSCHE_GAMMA * ms->core[CP_CONDUCTIVITY]));
    }
    /* the latent sink L e theta_abs f(theta_abs) (s - s_amb) S falls with the particle's own temperature at the
     * rate L e g (s - s_amb) S, g = d(theta f) / d theta <= water_latent_stiffness (the vapour's factor f,
     * water.h; 14.1 at a 100 degC boiling point): a Robin term of coefficient L e g (s - s_amb), limited as the
     * oven's, rho alpha dx / (2 L e g (s - s_amb)), with the largest e (s - s_amb) / (rho alpha) the particles
     * hold (water_latent_rate: G2P's scan of the saturations the next field step starts from; a scene with a
     * holding wet collider keeps s - s_amb <= 1, water.c says why). Rejected: the
     * bound s - s_amb <= 1 for every material, which set the physical loaf's (s = 0.218) latent limit 4.6x
     * shorter than its saturations need (docs/validation.md, "Evaporation stops at the wet-bulb"). */
    if (s->def.latent_heat && (s->ps.enabled & (1u << PC_WATER))) {
        const double q = water_latent_rate(s);
        const double stiff = water_latent_stiffness(water_psat_boiling(s), s->def.boiling_point + KELVIN);
        if (q > 0) dt = fmin(dt, s->def.dx / (2.0 * HEARTH_LATENT_HEAT * stiff * q));
    }
    return dt;
}

void thermal_step_stands(thermal_state *h) {
    h->oven_heat_in += h->step_oven_heat;
    h->step_oven_heat = 0;
}

double thermal_energy(const hearth_scene *s) {
    if (!thermal_active(s)) return 0;
    double e = 0;
    const double *T = pcold(&s->ps, PC_TEMPERATURE), *m = pcold(&s->ps, PC_MASS);
    const int *mat = pcoli(&s->ps, PC_MAT);
    /* m alpha(w) (theta + 273.15): with dry_specific_heat the heat capacity left after the water that went took
     * its own (material_specific_heat); heat in = the integral of m alpha(w) dtheta + L x water lost, which a
     * difference of this sum does not give when alpha moved (tests/unit_dry_heat.c keeps those books); SPH's heat
     * reads alpha(w) too (sph_heat.c) */
    for (int i = 0; i < s->ps.n; i++) {
        const material_slot *ms = &s->mats.slot[mat[i]];
        e += m[i] * material_specific_heat(ms, &s->ps, i) * (T[i] + KELVIN);
    }
    return e;
}

/* ---- boundary coefficients ------------------------------------------- */

static double field_at(const grid *g, const double x[3], int ch, int *m);

/* Fills s->heat.bnd_coef (S beta, W/K) and s->heat.bnd_temp (degrees C) for the
 * particles flagged PF_BOUNDARY, from the air boundary (boundary.c) and the
 * heated colliders. Other particles' entries are stale: readers check the
 * flag first, so the interior costs no memory traffic. */
static hearth_status find_boundary(hearth_scene *s) {
    const grid *g = &s->g;
    particles *ps = &s->ps;
    const int n = ps->n;
    double *coef = s->heat.bnd_coef, *temp = s->heat.bnd_temp, *surf = s->heat.bnd_surf;
    const double *X = pcold(ps, PC_X);
    int *flags = pcoli(ps, PC_FLAGS); /* live with temperature */
    const int oven = thermal_oven_on(&s->def);
    const int *mat = pcoli(ps, PC_MAT);
    const double beta = s->def.oven_beta, *depth = s->boundary.depth;
    /* the oven's radiating walls (#18): eps sigma, 0 without them (thermal.h) */
    const double rad = thermal_oven_rad(&s->def), t_wall = s->def.oven_wall_temperature, t_air = s->def.oven_temperature;
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++)
        if (flags[i] & PF_BOUNDARY) { /* flagged by boundary.c: the air boundary */
            /* The grid samples the particle's temperature at depth d below the
             * surface (boundary.c), colder than the surface by d q / kappa, so the
             * flux q = beta (theta_out - theta_s) is beta / (1 + beta d / kappa) times
             * theta_out - theta_p: the Robin condition moved in by d, exact for a
             * linear profile. Without it the flux was overstated by about 0.6 dx Bi / R
             * (first order). A coefficient, not an extrapolated temperature, so the
             * implicit operator stays symmetric. With no conduction nothing carries heat
             * from the surface to the sample: the flux acts on the particle directly. */
            double b = 0.0, r = 1.0, to = 0.0;
            if (oven) { /* the layer above the sample conducts as the particle does, dried or not */
                const double kap = material_conductivity(&s->mats.slot[mat[i]], ps, i);
                if (rad > 0) {
                    /* Radiating walls: beta (T_air - T_s) + eps sigma (T_w^4 - T_s^4) as one coefficient B and one
                     * outside temperature T_o (thermal_oven_exchange), T_s the face the same closure reads from the
                     * nodes' temperature at the particle (the sample the flux acts on, thermal_surface_temperature's),
                     * so the walls see the face's temperature and not the sample's, colder by the layer's drop. The
                     * radiation's coefficient is taken at the step's start (explicitly in h_r, as transport.c's
                     * latent sink): backward Euler keeps its symmetric operator, lagged in h_r alone. */
                    int nm;
                    const double th = field_at(g, X + 3 * i, CH_T, &nm);
                    const double tp = nm ? th : pcold(ps, PC_TEMPERATURE)[i];
                    const double B = thermal_oven_exchange(beta, t_air, rad, t_wall, tp, depth[i], kap, &to, &r);
                    b = B * r;
                } else {
                    const double den = thermal_film_den(beta, depth[i], kap);
                    r = 1.0 / den, b = beta / den, to = t_air;
                }
            }
            coef[i] = s->boundary.area[i] * b;
            temp[i] = to;
            if (surf) surf[i] = r; /* the surface's temperature by the same closure (thermal_surface_temperature) */
        }
    /* heated colliders: surface quadrature points on the collider's face; a held
     * collider's (infinite beta) carry its face's Nitsche terms */
    s->heat.nct = 0;
    for (int c = 0; c < s->ncol; c++) {
        const collider *col = &s->cols[c];
        if (isnan(col->temperature) || !(col->beta > 0)) continue;
        for (int i = 0; i < n; i++) {
            const double *x = X + 3 * i;
            double nrm[3] = {0, 0, 0};
            if (!collider_near(col, x)) continue;
            const double sd = collider_sdf(col, x, nrm);
            if (sd >= CONTACT_BAND * g->dx) continue;
            if (!(flags[i] & PF_BOUNDARY)) coef[i] = temp[i] = 0.0; /* the probe's flag; the contact is not in coef */
            if (surf) surf[i] = NAN; /* its surface is the collider's contact, which the oven's closure does not describe: the
                            * loaf's base on its tray browned 0.29 at 10 min through it, 0.96 from its own temperature */
            flags[i] |= PF_BOUNDARY;
            if (s->heat.nct == s->heat.ct_cap) return HEARTH_ERR_NOMEM; /* thermal_prepare sized it: n per collider */
            const double Vp = mpm_state_of(s)->vol[i]; /* J V_0, from this step's P2G */
            double *ct = s->heat.ct + THERMAL_CT * s->heat.nct++;
            for (int d = 0; d < 3; d++) ct[d] = x[d] - sd * nrm[d], ct[3 + d] = -nrm[d];
            const double S = Vp * contact_delta(fmax(sd, 0.0), g->dx);
            const int held = isinf(col->beta);
            ct[6] = held ? S : col->beta * S;
            ct[7] = col->temperature;
            ct[8] = held ? s->mats.slot[mat[i]].core[CP_CONDUCTIVITY] : 0.0;
            ct[9] = NAN; /* the nodes' field; dried_face may set the dried face's reading */
            ct[10] = c;
        }
    }
    return HEARTH_OK;
}

/* A point's B-spline stencil: the storage, local index, weight and weight
 * gradient (1/m) of its nodes that carry heat capacity, the weights
 * renormalised to sum to one (a node without material has no temperature).
 * Returns the count. gw may be NULL. */
static int contact_stencil(const grid *g, const double x[3], double *node[27], int l[27], double w[27], double (*gw)[3]) {
    const int D = g->dim, NPB = g->nodes_per_block;
    double wd[3][3], dw[3][3];
    int base[3];
    grid_point_weights(g, x, base, wd, dw);
    for (int d = 0; d < D; d++)
        for (int k = 0; k < 3; k++) dw[d][k] *= g->inv_dx;
    int m = 0;
    double wsum = 0;
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
            for (int c = 0; c < (D == 3 ? 3 : 1); c++) {
                const int gi[3] = {base[0] + a, base[1] + b, D == 3 ? base[2] + c : 0};
                int in = 1;
                for (int d = 0; d < D; d++) in &= gi[d] >= 0 && gi[d] <= g->nn[d] - 1;
                if (!in) continue;
                const int slot = g->slot[grid_block_id(g, gi[0] / GRID_B, gi[1] / GRID_B, gi[2] / GRID_B)];
                if (slot < 0) continue;
                const int li = D == 2 ? (gi[0] % GRID_B) * GRID_B + gi[1] % GRID_B
                                      : ((gi[0] % GRID_B) * GRID_B + gi[1] % GRID_B) * GRID_B + gi[2] % GRID_B;
                double *nd = grid_block(g, slot);
                const double wz = D == 3 ? wd[2][c] : 1.0, wt = wd[0][a] * wd[1][b] * wz;
                if (!(nd[CH_HC * NPB + li] > 0) || wt == 0) continue;
                node[m] = nd, l[m] = li, w[m] = wt;
                if (gw) {
                    gw[m][0] = dw[0][a] * wd[1][b] * wz;
                    gw[m][1] = wd[0][a] * dw[1][b] * wz;
                    gw[m][2] = D == 3 ? wd[0][a] * wd[1][b] * dw[2][c] : 0.0;
                }
                m++;
                wsum += wt;
            }
    for (int k = 0; k < m; k++) w[k] /= wsum;
    return m;
}

/* The nodes' channel ch at x: sum_j w_j(x) node_j[ch] over contact_stencil's
 * nodes (the B-spline field there, 0 where none has storage); *m the nodes. */
static double field_at(const grid *g, const double x[3], int ch, int *m) {
    double *node[27], w[27];
    int l[27];
    const int NPB = g->nodes_per_block;
    *m = contact_stencil(g, x, node, l, w, NULL);
    double v = 0;
    for (int j = 0; j < *m; j++) v += w[j] * node[j][ch * NPB + l[j]];
    return v;
}
double thermal_field_at(const hearth_scene *s, const double x[3], int ch, int *m) { return field_at(&s->g, x, ch, m); }

double thermal_surface_temperature(const hearth_scene *s, int i, double *sample) {
    const particles *ps = &s->ps;
    if (!thermal_oven_on(&s->def) || !s->heat.bnd_surf || i >= s->heat.bnd_cap) return NAN;
    if (!(pcoli(ps, PC_FLAGS)[i] & PF_BOUNDARY) || !(s->heat.bnd_coef[i] > 0)) return NAN; /* not on the oven's air */
    if (isnan(s->heat.bnd_surf[i])) return NAN; /* by a heated collider's face (find_boundary) */
    /* the sample the flux read: the nodes' temperature at the particle (this step's solution), not the particle's
     * own, which FLIP and subcell.c keep nearer its own, shallower place (docs/validation.md, "The surface's
     * colour": with the particle's own the drying slab's surface read 9.2, 2.0, 1.1 K hot at 4, 2, 1 mm, with
     * the nodes' 0.1, 1.2, 1.1 K cool of the closed form's) */
    int m;
    const double th = field_at(&s->g, pcold(ps, PC_X) + 3 * i, CH_T, &m);
    if (m == 0) return NAN;
    /* q = beta (T_o - T_s) = beta r (T_o - th): the air film takes the share r of the difference, the layer above
     * the sample the rest */
    const double To = s->heat.bnd_temp[i];
    if (sample) *sample = th;
    return thermal_face_temperature(To, th, s->heat.bnd_surf[i]);
}

/* The colliders' surface terms on the nodes, out_i += (A x)_i - b_i (b only
 * when src), x from channel in, at each point x_s with area S:
 *   Robin contact:  A_ij = beta S w_i w_j, b_i = beta S w_i T;
 *   a held face (Nitsche's method, symmetric; nu the body's outward normal):
 *   A_ij = kappa S (gamma / dx w_i w_j - w_i dw_j/dnu - dw_i/dnu w_j),
 *   b_i = kappa S (gamma / dx w_i - dw_i/dnu) T.
 * The held face's nodes are also eliminated (mark_held); Nitsche's terms give
 * the free rows whose B-splines reach across the face the flux through it,
 * which eliminating nodes alone leaves out (the B-splines do not vanish on the
 * face), so the face is consistent. Serial in the particles' order, so
 * deterministic at any thread count; the points are a surface's, few against
 * the body's particles. */
static void heat_contact_apply(hearth_scene *s, int in, int out, int src) {
    const grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    for (int k = 0; k < s->heat.nct; k++) {
        const double *ct = s->heat.ct + THERMAL_CT * k;
        double *node[27], w[27], gw[27][3];
        int l[27];
        const int m = contact_stencil(g, ct, node, l, w, gw);
        double v = 0, dv = 0;
        for (int j = 0; j < m; j++) {
            const double xj = node[j][in * NPB + l[j]];
            v += w[j] * xj;
            dv += (gw[j][0] * ct[3] + gw[j][1] * ct[4] + gw[j][2] * ct[5]) * xj;
        }
        const double T = src ? ct[7] : 0.0;
        if (ct[8] == 0) { /* Robin */
            if (!isnan(ct[9]) && !src) continue; /* on a dried face: a known source (dried_face), not in the operator */
            const double f = ct[6] * ((isnan(ct[9]) ? v : ct[9]) - T);
            for (int j = 0; j < m; j++) node[j][out * NPB + l[j]] += f * w[j];
            continue;
        }
        const double kS = ct[8] * ct[6], pen = NITSCHE_GAMMA * g->inv_dx;
        for (int j = 0; j < m; j++) {
            const double dn = gw[j][0] * ct[3] + gw[j][1] * ct[4] + gw[j][2] * ct[5];
            node[j][out * NPB + l[j]] += kS * (pen * w[j] * (v - T) - w[j] * dv - dn * (v - T));
        }
    }
}

/* ---- held (Dirichlet) nodes -------------------------------------------- */

/* Marks the nodes that keep a temperature in s->heat.fix (NaN: free) and sets
 * their CH_T to it (held_settle later sets CH_T0 too; G2P blends by hold_h):
 * a node inside or on the face of a held collider (infinite beta), within the
 * collider's node-row tolerance; a node at least half of whose heat capacity
 * comes from held particles (a body with fixed_temperature), at those
 * particles' mean temperature. Free of cost when the scene holds neither. */
static hearth_status mark_held(hearth_scene *s) {
    grid *g = &s->g;
    particles *ps = &s->ps;
    const int NPB = g->nodes_per_block, D = g->dim, n = ps->n;
    if (s->heat.held_n != n) { /* rescan when particles come or go (bodies, cutting, restore) */
        s->heat.held = 0;
        const int *flags = pcoli(ps, PC_FLAGS);
        for (int i = 0; i < n && !s->heat.held; i++) s->heat.held = (flags[i] & PF_HOLD_T) != 0;
        s->heat.held_n = n;
    }
    int cols = 0;
    for (int c = 0; c < s->ncol; c++) cols |= !isnan(s->cols[c].temperature) && isinf(s->cols[c].beta);
    s->heat.nfix = 0;
    if (!cols && !s->heat.held) return HEARTH_OK;
    const int nn = g->nactive * NPB;
    if (nn > s->heat.fix_cap) {
        const int cap = 2 * nn;
        double *a = mem_alloc(sizeof(double) * (size_t)cap), *b = mem_alloc(sizeof(double) * (size_t)cap);
        if (!a || !b) {
            mem_free(a, sizeof(double) * (size_t)cap);
            mem_free(b, sizeof(double) * (size_t)cap);
            return HEARTH_ERR_NOMEM;
        }
        mem_free(s->heat.fix, sizeof(double) * (size_t)s->heat.fix_cap);
        mem_free(s->heat.fix_w, sizeof(double) * (size_t)s->heat.fix_cap);
        s->heat.fix = a, s->heat.fix_w = b, s->heat.fix_cap = cap;
    }
    double *fix = s->heat.fix, *fw = s->heat.fix_w;
    for (int k = 0; k < nn; k++) fix[k] = fw[k] = 0.0;
    if (s->heat.held) { /* the held particles' heat capacity and C theta on their nodes */
        const double *X = pcold(ps, PC_X), *M = pcold(ps, PC_MASS), *T = pcold(ps, PC_TEMPERATURE);
        const int *flags = pcoli(ps, PC_FLAGS), *mat = pcoli(ps, PC_MAT);
        for (int i = 0; i < n; i++) {
            if (!(flags[i] & PF_HOLD_T)) continue;
            double *node[27], w[27];
            int l[27];
            /* the particle's own stencil: its nodes all carry its heat capacity, so none is dropped */
            const int m = contact_stencil(g, X + 3 * i, node, l, w, NULL);
            const double hc = M[i] * material_specific_heat(&s->mats.slot[mat[i]], ps, i); /* as P2G's */
            for (int j = 0; j < m; j++) {
                const int k = (int)((node[j] - g->data) / ((ptrdiff_t)g->nch * NPB)) * NPB + l[j];
                fw[k] += w[j] * hc;
                fix[k] += w[j] * hc * T[i];
            }
        }
    }
    for (int b = 0; b < g->nactive; b++) {
        double *node = grid_block(g, b);
        int bc[3];
        grid_block_coords(g, g->active[b], bc);
        for (int l = 0; l < NPB; l++) {
            const int k = b * NPB + l;
            const double c = node[CH_HC * NPB + l];
            double held = NAN;
            if (c > 0 && fw[k] >= (0.5 - HOLD_TOL) * c) held = fix[k] / fw[k];
            if (c > 0 && cols) {
                int gi[3];
                grid_node_index(g, bc, l, gi);
                double xn[3] = {0, 0, 0};
                for (int d = 0; d < D; d++) xn[d] = g->lo[d] + gi[d] * g->dx;
                for (int q = 0; q < s->ncol; q++) {
                    const collider *col = &s->cols[q];
                    if (isnan(col->temperature) || !isinf(col->beta) || !collider_near(col, xn)) continue;
                    if (collider_sdf(col, xn, NULL) <= COLLIDER_ROW_TOL * g->dx) held = col->temperature;
                }
            }
            fix[k] = held;
            if (!isnan(held)) {
                node[CH_T * NPB + l] = held;
                s->heat.nfix++;
            }
        }
    }
    if (!s->heat.nfix) return HEARTH_OK;
    /* each particle's weight on held nodes, for G2P (positions do not change before it) */
    if (n > s->heat.hold_cap) {
        double *h = mem_alloc(sizeof(double) * (size_t)n);
        if (!h) return HEARTH_ERR_NOMEM;
        mem_free(s->heat.hold_h, sizeof(double) * (size_t)s->heat.hold_cap);
        s->heat.hold_h = h, s->heat.hold_cap = n;
    }
    const double *X = pcold(ps, PC_X);
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        double *node[27], w[27];
        int l[27];
        const int m = contact_stencil(g, X + 3 * i, node, l, w, NULL);
        double h = 0;
        for (int j = 0; j < m; j++) {
            const int k = (int)((node[j] - g->data) / ((ptrdiff_t)g->nch * NPB)) * NPB + l[j];
            if (!isnan(fix[k])) h += w[j];
        }
        s->heat.hold_h[i] = h;
    }
    return HEARTH_OK;
}

/* After the update: held nodes' CH_T0 takes their temperature, so FLIP (eq. 21)
 * carries no change from them. A held node's theta^n is the particles' mean,
 * not the held value, and FLIP would hand the difference to the particles
 * around it every step, heating them without bound (seen: a free block beside
 * a held one at 150 degC reached 218 degC); G2P instead blends the particles
 * touching held nodes toward the nodes' field by their weight on them. */
static void held_settle(hearth_scene *s) {
    if (!s->heat.nfix) return;
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    for (int b = 0; b < g->nactive; b++) {
        double *node = grid_block(g, b);
        for (int l = 0; l < NPB; l++)
            if (!isnan(s->heat.fix[b * NPB + l])) node[CH_T0 * NPB + l] = node[CH_T * NPB + l];
    }
}

/* Zero channel ch at the held nodes (their rows leave the CG's unknowns). */
static void clear_held(hearth_scene *s, int ch) {
    if (!s->heat.nfix) return;
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    for (int b = 0; b < g->nactive; b++) {
        double *node = grid_block(g, b);
        for (int l = 0; l < NPB; l++)
            if (!isnan(s->heat.fix[b * NPB + l])) node[ch * NPB + l] = 0.0;
    }
}

/* Deterministic dot product over nodes with heat capacity: per block, then in
 * block order. On MPI slabs over the blocks this rank owns (the halo layers
 * hold copies), then over the ranks in rank order (mpm_ranks_fields_reduce):
 * every rank gets the same bits, so all take the same CG iterations. */
static double dot(hearth_scene *s, int a, int b) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    double *part = s->heat.cg_partial;
    const unsigned char *own = mpm_ranks_fields_owned(s);
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        const double *node = grid_block(g, k);
        double acc = 0;
        for (int l = 0; l < NPB; l++)
            if (node[CH_HC * NPB + l] > 0) acc += node[a * NPB + l] * node[b * NPB + l];
        part[k] = own && !own[k] ? 0.0 : acc;
    }
    double sum = 0;
    for (int k = 0; k < g->nactive; k++) sum += part[k];
    mpm_ranks_fields_reduce(s, &sum, 1, NULL, 0);
    return sum;
}

static void clear_channel(hearth_scene *s, int ch) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) memset(grid_block(g, k) + ch * NPB, 0, sizeof(double) * (size_t)NPB);
}

/* A heated collider's Robin contact on a dried face (issue #18, helper baseface).
 *
 * Why. The contact reads theta(x_s), the all-particle B-spline field at the
 * face point (heat_contact_apply). Under latent_heat the face's nodes are
 * shared by the dried row on the tray and the wet rows above it, held at T_b
 * by water_boil and weighing three times as much (bread's c 2700 wet, 907.5
 * dried), so the field reads near T_b however hot the dried row is, the tray
 * lets in about beta (T_p - T_b), and FLIP (eq. 21) hands the lone dried row
 * its nodes' share as sensible heat that nothing conducts on: the row passed
 * the 200 degC tray (237, 207 degC at 5, 2.5 mm in unit_base_contact;
 * docs/validation.md, "A dried row hotter than its tray").
 *
 * What. The flux through the face is set by the material at the face, and
 * where the face has dried that is the dried layer. Each point whose
 * stencil's nodes carry dried particles (subcell_dried: moisture ratio under
 * 0.01) reads the dried particles' temperature at the face instead of the
 * field: the largest over its nodes i of the dried particles' own mean
 * there, S_i / W_i, S_i = sum_p w_ip C_p T_p, W_i = sum_p w_ip C_p over dried
 * p (C_p = m_p alpha_p, P2G's weights), at the step start. On a face the
 * largest is the node nearest the tray, which only the dried row beside the
 * face reaches: the material at the face. The flux beta (T_p - reading)
 * stops when that material reaches the tray's temperature, so the tray cannot
 * drive it past T_p; where no dried particle reaches a point's nodes the
 * point reads the field as before (every bake before its base dries, every
 * scene without latent_heat or without heated colliders: their bits are
 * unchanged). Measured (docs/validation.md, "The tray reads the dried face"):
 * the largest particle temperature 183.3, 179.6, 180.0 degC at 5, 2.5, 1.25
 * mm against the tray's 200, and the water boiled converging to the fine 1D
 * reference at order ~1.5 from below; the price is a slow front at coarse dx
 * (15% short at 5 mm, where main boiled 4% too much): a coarse dried row
 * still sits too hot for its height, and its reading throttles the flux.
 *
 * Convergence. The dried particles nearest the face lie within about dx / 2
 * of it, so their mean differs from the face's temperature by at most
 * |dT/dn| dx / 2 plus their spread across the node's support (both O(dx));
 * as dx -> 0 the reading tends to the face's temperature and the Robin term
 * to beta (T_p - T_s), the continuous condition. First order, not second:
 * no extrapolation to the face along the dried fit's gradient (a single
 * dried row has none, subcell.c's node_fit, and between a hot row and a row
 * just dried the extrapolation overshoots the face by the rows' difference).
 *
 * Rejected (measured, unit_base_contact, docs/validation.md): each point
 * reading its own particle when that particle is dried (the wet rows' points
 * still read the field, let in the heat and FLIP gave the dried row its share:
 * 219 degC at 5 mm); the w_i(x_s)-weighted mean of the nodes' dried means
 * instead of the largest (a row just dried pulls the reading down, the flux
 * jumps and the row above it takes it: 206.8 degC at 5 mm).
 *
 * Stability. The reading is the step start's, so the term is explicit in the
 * particles' temperatures: a node gains at most dt beta S / C_i of the
 * difference and a dried particle its share of that, within forward Euler's
 * own Robin limit rho alpha dx / (2 beta) (thermal_dt_limit). Backward Euler
 * has no step limit, so there the contact stays on the field (implicit, as
 * before): a lagged reading at its long steps would need the limit it exists
 * to avoid. Channels: CH_R and CH_B as scratch, zero again on return (the
 * transport pass then accumulates into them). */
static hearth_status dried_face(hearth_scene *s, hearth_error *err) {
    grid *g = &s->g;
    particles *ps = &s->ps;
    if (s->def.heat_implicit || !s->def.latent_heat || !(ps->enabled & (1u << PC_WATER))) return HEARTH_OK;
    const int NPB = g->nodes_per_block, n = ps->n;
    const double *X = pcold(ps, PC_X), *M = pcold(ps, PC_MASS), *T = pcold(ps, PC_TEMPERATURE);
    const int *mat = pcoli(ps, PC_MAT);
    int any = 0;
    for (int i = 0; i < n; i++) { /* serial in the particles' order: the same sums at any thread count */
        if (!subcell_dried(s, i)) continue;
        const double c = M[i] * material_specific_heat(&s->mats.slot[mat[i]], ps, i); /* as P2G's */
        if (!(c > 0)) continue;
        double *node[27], w[27];
        int l[27];
        const int m = contact_stencil(g, X + 3 * i, node, l, w, NULL);
        for (int j = 0; j < m; j++) node[j][CH_R * NPB + l[j]] += w[j] * c, node[j][CH_B * NPB + l[j]] += w[j] * c * T[i];
        any = 1;
    }
    /* every rank takes part in the slab exchange, so only a scene of one rank may stop here */
    if (!any && s->mpm->nranks == 1) return HEARTH_OK;
    const int sums[2] = {CH_R, CH_B};
    hearth_status st = mpm_ranks_fields_sum(s, sums, 2, err);
    if (st) return st;
    for (int q = 0; q < s->heat.nct; q++) {
        double *ct = s->heat.ct + THERMAL_CT * q;
        if (ct[8] != 0) continue; /* a held face's Nitsche terms */
        double *node[27], w[27];
        int l[27];
        const int m = contact_stencil(g, ct, node, l, w, NULL);
        for (int j = 0; j < m; j++) {
            const double W = node[j][CH_R * NPB + l[j]];
            if (!(W > 0)) continue;
            const double v = node[j][CH_B * NPB + l[j]] / W;
            if (isnan(ct[9]) || v > ct[9]) ct[9] = v;
        }
    }
    clear_channel(s, CH_R);
    clear_channel(s, CH_B);
    return HEARTH_OK;
}


hearth_status thermal_prepare(hearth_scene *s, hearth_error *err) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block, n = s->ps.n;
    /* bnd_surf also when browning's surface reading came after the arrays (an oven lit later: scene.c) */
    if (n > s->heat.bnd_cap || g->nactive > s->heat.cg_cap || ((s->ps.enabled & (1u << PC_SURFACE)) && !s->heat.bnd_surf)) {
        const int nc = n > s->heat.bnd_cap ? n : s->heat.bnd_cap, gc = g->nactive > s->heat.cg_cap ? g->nactive * 2 : s->heat.cg_cap;
        double *a = mem_alloc(sizeof(double) * (size_t)nc), *b = mem_alloc(sizeof(double) * (size_t)nc);
        /* bnd_surf only for browning's surface reading (PC_SURFACE: MPM, browning and an oven, scene.c) */
        const int surf = (s->ps.enabled & (1u << PC_SURFACE)) != 0;
        double *c = mem_alloc(sizeof(double) * (size_t)gc), *e = surf ? mem_alloc(sizeof(double) * (size_t)nc) : NULL;
        if (!a || !b || !c || (surf && !e)) {
            mem_free(a, sizeof(double) * (size_t)nc);
            mem_free(b, sizeof(double) * (size_t)nc);
            mem_free(e, sizeof(double) * (size_t)nc);
            mem_free(c, sizeof(double) * (size_t)gc);
            return err_set(err, HEARTH_ERR_NOMEM, "out of memory for heat transport (%d particles)", n);
        }
        mem_free(s->heat.bnd_coef, sizeof(double) * (size_t)s->heat.bnd_cap);
        mem_free(s->heat.bnd_temp, sizeof(double) * (size_t)s->heat.bnd_cap);
        mem_free(s->heat.bnd_surf, sizeof(double) * (size_t)s->heat.bnd_cap);
        mem_free(s->heat.cg_partial, sizeof(double) * (size_t)s->heat.cg_cap);
        s->heat.bnd_coef = a;
        s->heat.bnd_temp = b;
        s->heat.bnd_surf = e;
        s->heat.cg_partial = c;
        s->heat.bnd_cap = nc;
        s->heat.cg_cap = gc;
    }
    /* node temperatures (eq. 17): C theta / C */
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            const double c = node[CH_HC * NPB + l];
            node[CH_T * NPB + l] = c > 0 ? node[CH_T * NPB + l] / c : 0.0;
            node[CH_T0 * NPB + l] = node[CH_T * NPB + l];
            node[CH_R * NPB + l] = node[CH_B * NPB + l] = 0.0;
        }
    }
    int heated = 0; /* contact points: at most one per particle and heated collider */
    for (int c = 0; c < s->ncol; c++) heated += !isnan(s->cols[c].temperature) && s->cols[c].beta > 0;
    if (heated && (size_t)n * (size_t)heated > (size_t)s->heat.ct_cap) {
        if ((size_t)n * (size_t)heated > (size_t)INT32_MAX / THERMAL_CT)
            return err_set(err, HEARTH_ERR_NOMEM, "too many heated collider contacts (%d particles, %d colliders)", n, heated);
        const int cap = n * heated;
        double *x = mem_alloc(sizeof(double) * THERMAL_CT * (size_t)cap);
        if (!x) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for heated collider contact (%d particles)", n);
        mem_free(s->heat.ct, sizeof(double) * THERMAL_CT * (size_t)s->heat.ct_cap);
        s->heat.ct = x, s->heat.ct_cap = cap;
    }
    if (find_boundary(s) || mark_held(s))
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory for held temperatures (%d grid blocks)", g->nactive);
    /* MPI slabs: each contact point to the rank that holds its whole stencil */
    hearth_status st = mpm_ranks_fields_contacts(s, err);
    if (st || !heated) return st;
    return dried_face(s, err);
}

/* One heat-only pass of the operator (the CG's products). */
static void apply(hearth_scene *s, int in, int out) {
    const transport_pass tp = {.heat_in = in, .heat_out = out, .heat_src = -1, .water = 0};
    transport_apply(s, &tp);
}

void thermal_sheet_return(hearth_scene *s, int i, double heat) {
    const double *x = pcold(&s->ps, PC_X) + 3 * i;
    for (int c = 0; c < s->ncol; c++) {
        collider *col = &s->cols[c];
        if (!collider_draws(col) || !collider_near(col, x)) continue;
        if (collider_sdf(col, x, NULL) < CONTACT_BAND * s->g.dx) {
            col->step_ret += heat;
            return;
        }
    }
}

void thermal_sheet_returns_done(hearth_scene *s) {
    for (int c = 0; c < s->ncol; c++) {
        collider *col = &s->cols[c];
        if (!collider_draws(col)) continue;
        mpm_ranks_fields_reduce(s, &col->step_ret, 1, NULL, 0); /* every rank's clamped particles, in rank order */
        col->step_heat += col->step_ret;
        col->step_ret = 0;
    }
}

void thermal_contact(hearth_scene *s) {
    /* the heated colliders' contact into L theta^n - b (both schemes read CH_B - CH_R) */
    heat_contact_apply(s, CH_T, CH_R, 1);
}

hearth_status thermal_finish(hearth_scene *s, double dt, hearth_error *err) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    /* held nodes keep their temperature: no update, no unknown */
    clear_held(s, CH_R);
    clear_held(s, CH_B);
    if (!s->def.heat_implicit && thermal_oven_on(&s->def)) {
        small_nodes_explicit_step(s, dt); /* forward Euler, the surface's small nodes merged */
        held_settle(s);
        thermal_step_books(s, dt);
        return HEARTH_OK;
    }
    if (!s->def.heat_implicit) { /* forward Euler (gamma = 0) */
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
        for (int k = 0; k < g->nactive; k++) {
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) {
                const double c = node[CH_HC * NPB + l];
                if (c > 0) node[CH_T * NPB + l] += dt * (node[CH_B * NPB + l] - node[CH_R * NPB + l]) / c;
            }
        }
        held_settle(s);
        thermal_step_books(s, dt);
        return HEARTH_OK;
    }
    /* backward Euler (gamma = 1): (C/dt + L) x = C/dt theta^n + b, solved by
     * conjugate gradients from x = theta^n; r = b - L theta^n. Preconditioned by
     * the diagonal C/dt: node heat capacities span orders of magnitude between
     * the interior and the edge of a body, and plain CG needed ~480 iterations
     * at a tiny step where the preconditioned one needs a handful.
     * Channels: CH_T = x, CH_CG_R = r, CH_B = z = M^-1 r, CH_CG_P = p, CH_R = Ap.
     * Held nodes are eliminated: x starts at their temperature (mark_held), so
     * L x^0 carries their known values to the right-hand side, and r, z, p and
     * Ap are zero on them, which leaves CG the symmetric system of the free
     * nodes. An infinite-beta stand-in (beta = 1e9) would keep them as
     * unknowns with rows 1e9 times stiffer and cost iterations:
     * `heat_dirichlet_cg_iterations`. */
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            const double c = node[CH_HC * NPB + l];
            const double r = c > 0 ? node[CH_B * NPB + l] - node[CH_R * NPB + l] : 0.0;
            node[CH_CG_R * NPB + l] = r;
            node[CH_B * NPB + l] = c > 0 ? r * dt / c : 0.0;
            node[CH_CG_P * NPB + l] = node[CH_B * NPB + l];
        }
    }
    /* Stop when the residual is 1e-12 of C theta / dt (theta in degrees C). The
     * residual's sum is all the energy an inexact solve can create, since the
     * conduction operator's columns sum to zero. */
    double scale = 0;
    const unsigned char *own = mpm_ranks_fields_owned(s); /* MPI slabs: each node once */
    for (int k = 0; k < g->nactive; k++) {
        if (own && !own[k]) continue;
        const double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            const double v = node[CH_HC * NPB + l] * (fabs(node[CH_T * NPB + l]) + 1.0) / dt;
            scale += v * v;
        }
    }
    mpm_ranks_fields_reduce(s, &scale, 1, NULL, 0);
    scale = sqrt(scale);
    double rz = dot(s, CH_CG_R, CH_B), rr = dot(s, CH_CG_R, CH_CG_R);
    s->heat.cg_iterations = 0;
    for (int it = 0; it < 2000 && sqrt(rr) > 1e-12 * scale; it++) {
        clear_channel(s, CH_R);
        apply(s, CH_CG_P, CH_R);
        heat_contact_apply(s, CH_CG_P, CH_R, 0);
        /* MPI slabs: the halo layers' share of Ap to its owners, and their values back */
        const int ap = CH_R;
        hearth_status st = mpm_ranks_fields_sum(s, &ap, 1, err);
        if (st) return st;
        clear_held(s, CH_R);
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
        for (int k = 0; k < g->nactive; k++) {
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) {
                const double c = node[CH_HC * NPB + l];
                node[CH_R * NPB + l] = c > 0 ? node[CH_R * NPB + l] + c / dt * node[CH_CG_P * NPB + l] : 0.0;
            }
        }
        const double pAp = dot(s, CH_CG_P, CH_R);
        if (!(pAp > 0)) break;
        const double alpha = rz / pAp;
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
        for (int k = 0; k < g->nactive; k++) {
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) {
                const double c = node[CH_HC * NPB + l];
                if (!(c > 0)) continue;
                node[CH_T * NPB + l] += alpha * node[CH_CG_P * NPB + l];
                node[CH_CG_R * NPB + l] -= alpha * node[CH_R * NPB + l];
                node[CH_B * NPB + l] = node[CH_CG_R * NPB + l] * dt / c;
            }
        }
        const double rz2 = dot(s, CH_CG_R, CH_B), beta = rz2 / rz;
        rz = rz2;
        rr = dot(s, CH_CG_R, CH_CG_R);
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
        for (int k = 0; k < g->nactive; k++) {
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) node[CH_CG_P * NPB + l] = node[CH_B * NPB + l] + beta * node[CH_CG_P * NPB + l];
        }
        s->heat.cg_iterations = it + 1;
    }
    held_settle(s);
    thermal_step_books(s, dt);
    return HEARTH_OK;
}
