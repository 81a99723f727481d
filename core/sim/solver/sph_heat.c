/* sph_heat.c: the SPH solver's heat rates (Rodriguez-Arenas 2011 eq. 3.42,
 * 3.45-3.46) and the oven's Robin flux with heated colliders' contact beta
 * (as MPM's, Ding et al. 2019 §6.6), the oven's radiating walls (#18, thermal.h's thermal_oven_exchange), and the
 * limits they put on dt.
 * phase_forces (sph.c) calls sph_heat_rates after the viscous moments;
 * sph_fields_advance moves the temperatures by st->dT, and the water with
 * them (sph_water.c). */
#include <math.h>

#include "material.h"
#include "thermal.h"
#include "sph_kernel.h"
#include "sph_state.h"
#include "water.h"

/* Per particle: internal heat (eq. 3.45-3.46) over the neighbours, external
 * heat at the body's outer surface particles (eq. 3.42 per unit area of
 * surface, not as printed: see there) and the Robin exchange. Which particles
 * are on the outer surface is sph_outer.c's (st->outer), not the colour
 * field's flag (st->surf): in the risen angel food cake (#18) the colour
 * field missed its top and marked batter rows inside it, which took 46% of
 * the oven's heat and made the crumb hotter than the crust.
 *
 * Eq. 3.45's Laplacian is eq. 3.8's kernel, the viscous term's, and had its
 * bias: summed over a resting lattice at h = 2.4 spacings it is 5.7% strong,
 * whatever the spacing, so slab conduction decayed 1.1%, 4.6%, 5.5% fast at
 * 12, 24, 48 particles along the wave (the kernel's smoothing pulling the
 * other way at coarse spacings) and the error grew with resolution. It now
 * takes the viscous term's per-particle factor (sph_viscous_factor: 2 dim
 * over the second moment, blended to the lattice's at surfaces): the slab's
 * error falls at order 2 (`sph_heat_conduction_converges`). The factor is
 * the pair's mean, so sum m T is still conserved to round-off.
 *
 * A dried crust (issue #18): with a material's dry_conductivity or
 * dry_specific_heat set (sph_heat_dry), each particle has its own conductivity
 * and heat capacity, MPM's (material.h): kappa_i = kappa(w_i), alpha_i =
 * alpha(w_i), linear in the moisture ratio. The scene's k_h,int = kappa / c
 * stays the wet value, so particle i conducts as
 *   k_i = c_i kappa(w_i) / kappa_i,wet  (J/(kg K); k_h,int k_i is its kappa),
 * c_i its material's specific_heat; a pair conducts through the harmonic mean
 *   k_ij = 2 k_i k_j / (k_i + k_j)
 * (Cleary & Monaghan 1999, J. Comput. Phys. 148:227, eq. 9 with its
 * harmonic pair conductivity: the series conductance of the two halves of
 * the pair, so a dried row next to a wet one carries the flux two layers in
 * series do, `sph_dry_slab_slopes_in_series`); the heat i takes from j,
 *   m_i k_h,int 4 m_j k_ij / (rho_i + rho_j)^2 (T_j - T_i) L_ij,
 * is symmetric in the pair, so sum m alpha T is conserved to round-off,
 * and i's temperature moves by its heat over m_i alpha_i. Eq. 3.42's
 * k_h,ext = h / c and the Robin flux act on m_i alpha_i the same way. The
 * arithmetic mean (the water's, sph_water.c) was rejected here: across a
 * jump in kappa it lets the better conductor set the flux, which the series
 * closed form does not. Without either parameter in any material the rates
 * are the thesis's form above, in its bits (a scene of two materials of
 * different specific_heat keeps conserving sum m T, as before). */
static int sph_heat_dry(const hearth_scene *s) {
    for (int m = 0; m < s->mats.n; m++)
        if (s->mats.slot[m].core[CP_DRY_CONDUCTIVITY] > 0 || s->mats.slot[m].core[CP_DRY_SPECIFIC_HEAT] > 0) return 1;
    return 0;
}

/* k_i above: the material's specific_heat times its kappa(w_i) / kappa_wet (1 when it has no dry_conductivity, or
 * no conductivity to scale: SPH's conduction is k_h,int's, and dry_conductivity <= conductivity). */
static double sph_dry_k(const hearth_scene *s, int i, int mat) {
    const material_slot *ms = &s->mats.slot[mat];
    const double cw = ms->core[CP_SPECIFIC_HEAT], kw = ms->core[CP_CONDUCTIVITY];
    if (!(ms->core[CP_DRY_CONDUCTIVITY] > 0) || !(kw > 0)) return cw;
    return cw * (material_conductivity(ms, &s->ps, i) / kw);
}

/* The oven's flux at an outer particle crosses the half-layer between the face it stands for and its centre
 * (its rest volume V = m / rho0, eq. 3.43's, a layer sp = V^(1/d) thick; d = sp / 2 from face to centre), as MPM's
 * find_boundary moves its Robin condition in by the sample's depth: the film and the half-layer in series,
 * h (T_ext - T_s) = kappa (T_s - T_i) / d, pass h (T_ext - T_i) / (1 + h d / kappa) (thermal.h's thermal_film_den,
 * Ding et al. 2019 §3.2's heat flow condition over a layer conducting by Fourier's law). h is the oven's
 * coefficient per unit area, eq. 3.42's k_h,ext c (what sph_heat_rates gives per unit area, c the material's
 * specific_heat) plus the Robin beta; kappa the conduction eq. 3.45 gives the particle, k_h,int c, or k_h,int k_i
 * with a dry parameter (k_i = c kappa(w_i) / kappa_wet, sph_dry_k; ki its value, < 0: take it here; c the
 * step's columns). h / kappa is
 * what counts, so S and c cancel: k_h,ext / k_h,int without the Robin term. Returns the film's share
 * r = 1 / (1 + h d / kappa) of particle i: 1 without conduction (the face is the particle), and 1 for a particle
 * that is not outer or sits by a heated collider (within h: eq. 3.42's outside is the collider; within its spacing:
 * the Robin contact), whose surface is a contact the air film does not describe (MPM's by a collider's face, too);
 * *face (may be NULL) says whether i has a face in the oven's air. One rule for the flux (sph_heat_rates) and the
 * face temperature browning reads (sph_surface_temperatures), so the face the colour sees is the one the heat
 * crossed.
 * With the oven's radiating walls (#18) the film carries B = h + h_r toward T_o = (h T_ext + h_r T_w) / B, h_r the
 * walls' coefficient at the face's own temperature by thermal_oven_exchange's fixed point (MPM's find_boundary's
 * closure), and r = 1 / (1 + B d / kappa): the outer particle takes B r (T_o - T_i) over its face, which is
 * r [h (T_ext - T_i) + h_r (T_w - T_i)], so the air's part keeps its terms and the walls add r h_r (T_w - T_i).
 * *hr gets h_r (0 without walls; for a particle by a heated collider the walls' h_r at T_i, the film being 1) and
 * *to T_o (T_ext without walls, to the bit); either may be NULL. */
static double sph_film_share(const hearth_scene *s, const sph_cols *cs, int i, double ki, int *face, double *hr,
                             double *to) {
    const struct sph_state *st = s->sph;
    const hearth_sph_def *o = &s->def.sph;
    const sph_cols c = *cs;
    const double Text = s->def.oven_temperature, beta = isfinite(Text) ? s->def.oven_beta : 0.0;
    const double rad = thermal_oven_rad(&s->def), Tw = s->def.oven_wall_temperature;
    if (face) *face = 0;
    if (hr) *hr = 0.0;
    if (to) *to = Text;
    if (!st->outer[i] || !isfinite(Text) || !(o->heat_ext > 0 || beta > 0 || rad > 0)) return 1.0;
    const double Vr = c.m[i] / st->rho0[i], sp = c.dim == 3 ? cbrt(Vr) : sqrt(Vr);
    for (int q = 0; q < s->ncol; q++) { /* sph_heat_rates's two rules for a collider's outside */
        const collider *cl = &s->cols[q];
        if (isnan(cl->temperature) || !collider_near(cl, c.x + 3 * i)) continue;
        const double sd = collider_sdf(cl, c.x + 3 * i, NULL);
        if ((o->heat_ext > 0 && sd < st->h[i]) || (cl->beta > 0 && sd < sp)) {
            if (hr && rad > 0) *hr = thermal_radiative_h(rad, Tw, c.T[i]);
            return 1.0;
        }
    }
    if (face) *face = 1;
    const double cw = s->mats.slot[c.mat[i]].core[CP_SPECIFIC_HEAT];
    const double h = o->heat_ext * cw + beta;
    const double kappa = o->heat_int * (sph_heat_dry(s) ? (ki >= 0 ? ki : sph_dry_k(s, i, c.mat[i])) : cw);
    if (!(rad > 0)) return 1.0 / thermal_film_den(h, 0.5 * sp, kappa); /* without walls: sphflux's bits */
    double To, r;
    const double B = thermal_oven_exchange(h, Text, rad, Tw, c.T[i], 0.5 * sp, kappa, &To, &r);
    if (hr) *hr = B - h;
    if (to) *to = To;
    return r;
}

void sph_heat_rates(hearth_scene *s) {
    struct sph_state *st = s->sph;
    const hearth_sph_def *o = &s->def.sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, dim = c.dim, *mat = c.mat;
    const double *x = c.x, *m = c.m, *T = c.T;
    const int *off = st->nl.off, *nb = st->nl.j;
    if (!T) return;
    const double Text = s->def.oven_temperature;
    /* Robin heat exchange (Ding et al. 2019 §6.6, the MPM solver's oven): beta
     * of the oven and of heated colliders, next to eq. 3.42's heat_ext */
    const double beta_oven = isfinite(Text) ? s->def.oven_beta : 0.0;
    /* the oven's radiating walls (#18, thermal.h): eps sigma, 0 without them */
    const double rad = thermal_oven_rad(&s->def), Tw = s->def.oven_wall_temperature;
    int robin = beta_oven > 0 || rad > 0;
    for (int q = 0; q < s->ncol; q++) robin |= !isnan(s->cols[q].temperature) && s->cols[q].beta > 0;
    /* with latent_heat the oven's Robin heat is tallied (heat_ledger), as MPM's (thermal_ledger.c's oven_ledger) */
    const int ledger = s->def.latent_heat && robin;
    if (s->def.latent_heat && !robin)
        for (int i = 0; i < n; i++) st->qo[i] = 0;
    const int dry = sph_heat_dry(s);
    /* the water's pairs in this walk, where sph_water_prepare ran this step (sph_water.c; the same r and kernel,
     * each sum in list order: the bits of the water's own walk) */
    const int water = st->wready && water_active(s);
    /* With a dry parameter each particle's k_i, taken once here rather than once for each pair it is in (the same
     * values, so the same bits: a pair's conduction read it from both sides, which cost the bread of the dead 12% of
     * its run with its water, helper sphcrumb), where sph_water_ensure made room (a caller outside the step may not
     * have: then per pair, as before) */
    double *kd = dry && st->kd && st->wcap >= n ? st->kd : NULL;
    if (kd) {
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
        for (int i = 0; i < n; i++) kd[i] = sph_dry_k(s, i, mat[i]);
    }
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        const double ri = st->rho[i];
        const material_slot *msi = &s->mats.slot[mat[i]];
        /* with a dry parameter: i's k_i and alpha(w_i), and the sums below are heat per m_i until divided by it */
        const double ki = dry ? (kd ? kd[i] : sph_dry_k(s, i, mat[i])) : 0.0;
        const double ai = dry ? material_specific_heat(msi, &s->ps, i) : 0.0;
        double dTi = 0, dw = 0;
        const int wi = water && !(st->wd[i] < 0); /* i trades water (a bubble trades none) */
        if (o->heat_int > 0 || wi)
            for (int k = off[i]; k < off[i + 1]; k++) {
                const int j = nb[k];
                double d[3];
                sph_disp(&st->cells, x + 3 * i, x + 3 * j, d);
                const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                if (r <= 0) continue;
                const double hij = 0.5 * (st->h[i] + st->h[j]), rj = st->rho[j], lap = sph_lap_visc(dim, r, hij);
                if (wi && sph_water_pairs_with(st->wd, i, j)) dw += sph_water_pair(st, m, i, j, lap); /* sph_water.c's */
                if (!(o->heat_int > 0)) continue;
                /* eq. 3.8 renormalised as in the viscous term (sph_viscous_factor), the pair's mean factor
                 * so what i gains j loses */
                const double lv = lap * 0.5 * (st->vc[i] + st->vc[j]);
                /* with a dry parameter the pair's conductivity factor, the harmonic mean of the two (Cleary &
                 * Monaghan 1999, eq. 9); without, 1 (a product by 1 is exact: the thesis's bits) */
                double kij = 1.0;
                if (dry) {
                    const double kj = kd ? kd[j] : sph_dry_k(s, j, mat[j]);
                    kij = ki + kj > 0 ? 2 * (ki * kj) / (ki + kj) : 0.0;
                }
                dTi += o->heat_int * 4 * m[j] / ((ri + rj) * (ri + rj)) * (T[j] - T[i]) * lv * kij; /* eq. 3.45-3.46 */
            }
        /* the oven's flux crosses the half-layer to i's centre (sph_film_share; 1 where none, the thesis's bits) */
        double hr = 0.0; /* the walls' h_r at i's face (sph_film_share; 0 without walls) */
        const double film = st->outer[i] ? sph_film_share(s, &c, i, dry ? ki : -1.0, NULL, &hr, NULL) : 1.0;
        if (o->heat_ext > 0 && st->outer[i]) { /* eq. 3.42 at surface particles, per unit area (below) */
            double Tout = Text;
            for (int q = 0; q < s->ncol; q++) { /* a heated collider within h is the outside instead */
                const collider *cl = &s->cols[q];
                if (isnan(cl->temperature) || !collider_near(cl, x + 3 * i)) continue;
                if (collider_sdf(cl, x + 3 * i, NULL) < st->h[i]) Tout = cl->temperature;
            }
            if (isfinite(Tout)) {
                /* The thesis prints k (T_i - T_ext) r_i^2 / rho_i with r_i of
                 * eq. 3.43: a temperature rate in an area over a density, so
                 * the heat a surface particle takes, m_i c times it, goes as
                 * r^2 m ~ dx^(d+2) while the face it stands for goes as
                 * dx^(d-1): the flux per unit area of surface fell as dx^3
                 * (a roll at dx 1.5 mm heated 0.42x the one at 2 mm). Ours
                 * is a Robin flux q = h (T_ext - T) per unit area, as eq.
                 * 3.45 does inside with k_h,int = kappa / c: k_h,ext = h / c
                 * (kg/(m^2 s)) and
                 *   dT_i/dt = k_h,ext (T_ext - T_i) A_i / m_i,
                 * A_i = V_i^((d-1)/d) the particle's face (its rest volume
                 * V_i = m_i / rho0_i, eq. 3.43's, as the Robin term below;
                 * times st->oshare, less than 1 where the outer particles
                 * crowd along the surface, sph_outer.c):
                 * r_i^2 / rho_i becomes A_i / (rho_i V_i) with the mass for
                 * rho_i V_i (a surface particle's summed density is low for
                 * want of neighbours). The sum over a surface row is
                 * k (T_ext - T) times its area, at any dx
                 * (sph_heat_ext_flux_per_area). The thesis's sign is
                 * reversed: heat flows from the hotter side. */
                const double Vr = m[i] / st->rho0[i], face = (dim == 3 ? cbrt(Vr) * cbrt(Vr) : sqrt(Vr)) * st->oshare[i];
                dTi += film * o->heat_ext * (Tout - T[i]) * face / m[i] * (dry ? msi->core[CP_SPECIFIC_HEAT] : 1.0);
            }
        }
        if (dry) dTi = ai > 0 ? dTi / ai : 0.0; /* heat per m_i over alpha(w_i) */
        if (robin) { /* the oven's Robin flux and heated colliders' contact beta, as MPM sees them */
            /* Each surface particle (the ones eq. 3.42 heats) carries its
             * face, V^((d-1)/d) of its rest volume, as a boundary node does in
             * MPM (boundary.c), less where outer particles crowd (st->oshare,
             * sph_outer.c); a particle within its spacing of a heated
             * collider carries the same face of contact (MPM: within dx). The
             * colour gradient as a surface delta (V |grad C|) would need no
             * flag, but with particles on one side only it sums to 0.69 of a
             * block's outline. */
            const double ci = dry ? ai : msi->core[CP_SPECIFIC_HEAT], Vr = m[i] / st->rho0[i];
            const double sp = dim == 3 ? cbrt(Vr) : sqrt(Vr), face = Vr / sp;
            /* With radiating walls the oven's Robin part carries beta + h_r toward (beta T_ext + h_r T_w) / (beta +
             * h_r), h_r at the face's temperature (sph_film_share: thermal_oven_exchange's fixed point), through the
             * same film: with eq. 3.42's part above the particle takes B r (T_o - T_i) over its face, MPM's closure;
             * taken at the step's start, as the whole rate is (forward Euler). Without walls: sphflux's bits. */
            const double bo = beta_oven + hr, To = hr > 0 ? (beta_oven * Text + hr * Tw) / bo : Text;
            double coef = bo > 0 && st->outer[i] ? film * face * st->oshare[i] * bo : 0.0, Tr = To;
            for (int q = 0; q < s->ncol; q++) {
                const collider *cl = &s->cols[q];
                if (isnan(cl->temperature) || !(cl->beta > 0) || !collider_near(cl, x + 3 * i)) continue;
                if (!(collider_sdf(cl, x + 3 * i, NULL) < sp)) continue;
                const double cS = face * cl->beta; /* the pan's temperature wins the ambient, areas add (as MPM) */
                Tr = coef > 0 ? (Tr * coef + cl->temperature * cS) / (coef + cS) : cl->temperature;
                coef += cS;
            }
            if (coef > 0 && ci > 0) dTi += coef * (Tr - T[i]) / (m[i] * ci);
            /* the oven's part (W), for latent_heat's ledger: coef (Tr - T) is the sum of its parts */
            if (ledger) st->qo[i] = bo > 0 && st->outer[i] ? film * face * st->oshare[i] * bo * (To - T[i]) : 0.0;
        }
        st->dT[i] = dTi;
        if (water) st->dW[i] = dw; /* the water's pairs, which sph_water_rates completes */
    }
    if (water) st->wpairs = 1;
}

/* With a dry parameter (sph_heat_dry) particle i's conduction runs at k_h,int sum_j k_ij (...) / alpha_i, k_ij
 * the harmonic mean of k_i and k_j: at most 2 k_i (the mean of k_i with anything) and at most K, the largest
 * specific_heat of the scene's materials (k_j <= c_j). So its rate is at most
 *   R = min(2 k_i / alpha_i, K / alpha_i)
 * times the thesis's, and the limit 0.1 h^2 rho / k_h,int shrinks by the largest R: k_i / alpha_i at the
 * stiffest end of its material (material_heat_stiffest: alpha and kappa linear in the moisture ratio, so the
 * ratio is extreme dried or wet; k = c kappa / kappa_wet), 1 / alpha_i at the dried alpha (the smallest).
 * Only dry_conductivity: R = 1, the limit as before; the bread's pair (907.5 J/(kg K), 0.23 of 0.51 W/(m K))
 * gives R = 2.68, where a pair of a dried and a wet particle reaches 1.85: the bound holds for any pair, across
 * materials too. *ext the factor eq. 3.42's and the Robin limits take, the smallest alpha_dried / c over
 * the materials (1 without dry_specific_heat). */
static double sph_dry_rate_bound(const hearth_scene *s, double *ext) {
    double K = 0, R = 0;
    *ext = 1.0;
    for (int m = 0; m < s->mats.n; m++) K = fmax(K, s->mats.slot[m].core[CP_SPECIFIC_HEAT]);
    for (int m = 0; m < s->mats.n; m++) {
        const material_slot *ms = &s->mats.slot[m];
        const double cw = ms->core[CP_SPECIFIC_HEAT], kw = ms->core[CP_CONDUCTIVITY], amin = material_specific_heat_min(ms);
        double as, ks;
        material_heat_stiffest(ms, &as, &ks);
        const double kr = kw > 0 ? cw * (ks / kw) : cw; /* k at that end */
        if (as > 0 && amin > 0) R = fmax(R, fmin(2 * kr / as, K / amin));
        if (cw > 0) *ext = fmin(*ext, amin / cw);
    }
    return R;
}

double sph_heat_stable_dt(const hearth_scene *s, double hmin, double rhomin) {
    const hearth_sph_def *o = &s->def.sph;
    const particles *ps = &s->ps;
    const double *T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL;
    double dt = INFINITY, ext = 1.0;
    const double R = sph_heat_dry(s) ? sph_dry_rate_bound(s, &ext) : 1.0;
    if (o->heat_int > 0 && T) dt = fmin(dt, 0.1 * hmin * hmin * rhomin / o->heat_int / R); /* eq. 3.45 has 1/rho */
    /* eq. 3.42 per unit area: a surface particle relaxes at k A / m = k / (rho sp);
     * a quarter of that time, as the Robin limit below (faster by c / alpha_dried with dry_specific_heat) */
    if (o->heat_ext > 0 && T) dt = fmin(dt, 0.25 * rhomin * hmin / o->h_factor / o->heat_ext * ext);
    if (T) { /* Robin: a face of V / spacing against the heat capacity rho c V */
        double beta = isnan(s->def.oven_temperature) ? 0 : s->def.oven_beta, bc = 0;
        beta += thermal_walls_h_max(s); /* the walls' h_r at its largest (thermal.c; 0 without walls) */
        for (int k = 0; k < s->ncol; k++)
            if (!isnan(s->cols[k].temperature) && s->cols[k].beta > bc) bc = s->cols[k].beta;
        beta += bc;
        for (int m = 0; m < s->mats.n && beta > 0; m++) {
            const material_slot *ms = &s->mats.slot[m];
            /* the dried alpha, the smallest (material_specific_heat_min; specific_heat without dry_specific_heat) */
            const double rc = ms->params[ms->density_index] * material_specific_heat_min(ms);
            if (rc > 0) dt = fmin(dt, 0.25 * rc * hmin / o->h_factor / beta);
        }
    }
    return dt;
}

/* The oven's Robin heat over the step (J, or J/m in 2D), summed in particle
 * order (the same bits on any thread count) from what sph_heat_rates kept:
 * only with latent_heat, for the books heat in = sensible heat + L x water
 * lost (`sph_latent_heat_energy_balance`). thermal_step_stands counts it once
 * the step stands. */
static void heat_ledger(hearth_scene *s, double dt) {
    s->heat.step_oven_heat = 0;
    if (!s->def.latent_heat || isnan(s->def.oven_temperature) || !(s->ps.enabled & (1u << PC_TEMPERATURE))) return;
    const double *qo = s->sph->qo;
    double q = 0;
    for (int i = 0; i < s->ps.n; i++) q += qo[i];
    s->heat.step_oven_heat = dt * q;
}

/* Each outer particle's face temperature (st->ts, degC; NaN for the rest), for browning.c: colour is the surface's
 * (issue #18), and an outer particle's centre lies half its spacing under the face it stands for, colder than the
 * face by that half-layer's conduction: T_s = T_o - (T_o - T_i) r (thermal.h's thermal_face_temperature), r the
 * film's share and T_o the outside sph_film_share gives (T_ext; with radiating walls the air's and the walls' blend
 * at the face's h_r), the same closure that moved the flux in (sph_heat_rates), so the face's
 * temperature and the heat that crossed it agree. A particle by a heated collider keeps its own temperature
 * (NaN here: browning reads T_i). Read at the step's end temperatures, which browning integrates; only
 * in a scene that browns (sph_fields_advance). */
static void sph_surface_temperatures(hearth_scene *s) {
    struct sph_state *st = s->sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n;
    const double *T = c.T;
    if (!st->ts) return; /* made with the step's columns in a scene that browns (sph.c's ensure) */
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        int face;
        double To;
        const double r = sph_film_share(s, &c, i, -1.0, &face, NULL, &To);
        st->ts[i] = face ? thermal_face_temperature(To, T[i], r) : NAN;
    }
}

/* Temperatures and water forward by their rates (sph_water.c: with
 * latent_heat a wet particle past the boiling point boils), then the highest
 * temperatures. */
void sph_fields_advance(hearth_scene *s, double dt) {
    const struct sph_state *st = s->sph;
    const sph_cols c = sph_cols_of(s);
    double *T = c.T, *Tmax = c.Tmax;
    if (T)
        for (int i = 0; i < c.n; i++) T[i] += dt * st->dT[i];
    heat_ledger(s, dt); /* with latent_heat: the oven's heat in, for the books */
    if (water_active(s)) sph_water_advance(s, dt);
    if (T && Tmax)
        for (int i = 0; i < c.n; i++)
            if (T[i] > Tmax[i]) Tmax[i] = T[i];
    /* browning.c is their one reader: a scene that does not brown pays for no face temperatures (#18, helper
     * userfix6; particle_values gives none then) */
    if (T && s->def.browning) sph_surface_temperatures(s);
}
