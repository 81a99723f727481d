/* sph_heat.c: the SPH solver's heat rates (Rodriguez-Arenas 2011 eq. 3.42,
 * 3.45-3.46) and the oven's Robin flux with heated colliders' contact beta
 * (as MPM's, Ding et al. 2019 §6.6), and the limits they put on dt.
 * phase_forces (sph.c) calls sph_heat_rates after the viscous moments;
 * sph_fields_advance moves the temperatures by st->dT, and the water with
 * them (sph_water.c). */
#include <math.h>

#include "material.h"
#include "sph_kernel.h"
#include "sph_state.h"
#include "water.h"

/* Per particle: internal heat (eq. 3.45-3.46) over the neighbours, external
 * heat at surface particles (eq. 3.42 per unit area of surface, not as printed:
 * see there) and the Robin exchange.
 *
 * Eq. 3.45's Laplacian is eq. 3.8's kernel, the viscous term's, and had its
 * bias: summed over a resting lattice at h = 2.4 spacings it is 5.7% strong,
 * whatever the spacing, so slab conduction decayed 1.1%, 4.6%, 5.5% fast at
 * 12, 24, 48 particles along the wave (the kernel's smoothing pulling the
 * other way at coarse spacings) and the error grew with resolution. It now
 * takes the viscous term's per-particle factor (sph_viscous_factor: 2 dim
 * over the second moment, blended to the lattice's at surfaces): the slab's
 * error falls at order 2 (`sph_heat_conduction_converges`). The factor is
 * the pair's mean, so sum m T is still conserved to round-off. */
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
    int robin = beta_oven > 0;
    for (int q = 0; q < s->ncol; q++) robin |= !isnan(s->cols[q].temperature) && s->cols[q].beta > 0;
    /* with latent_heat the oven's Robin heat is tallied (heat_ledger), as MPM's (thermal.c's oven_ledger) */
    const int ledger = s->def.latent_heat && robin;
    if (s->def.latent_heat && !robin)
        for (int i = 0; i < n; i++) st->qo[i] = 0;
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        const double ri = st->rho[i];
        double dTi = 0;
        if (o->heat_int > 0)
            for (int k = off[i]; k < off[i + 1]; k++) {
                const int j = nb[k];
                double d[3];
                sph_disp(&st->cells, x + 3 * i, x + 3 * j, d);
                const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                if (r <= 0) continue;
                const double hij = 0.5 * (st->h[i] + st->h[j]), rj = st->rho[j];
                /* eq. 3.8 renormalised as in the viscous term (sph_viscous_factor), the pair's mean factor
                 * so what i gains j loses */
                const double lv = sph_lap_visc(dim, r, hij) * 0.5 * (st->vc[i] + st->vc[j]);
                dTi += o->heat_int * 4 * m[j] / ((ri + rj) * (ri + rj)) * (T[j] - T[i]) * lv; /* eq. 3.45-3.46 */
            }
        if (o->heat_ext > 0 && st->surf[i]) { /* eq. 3.42 at surface particles, per unit area (below) */
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
                 * V_i = m_i / rho0_i, eq. 3.43's, as the Robin term below):
                 * r_i^2 / rho_i becomes A_i / (rho_i V_i) with the mass for
                 * rho_i V_i (a surface particle's summed density is low for
                 * want of neighbours). The sum over a surface row is
                 * k (T_ext - T) times its area, at any dx
                 * (sph_heat_ext_flux_per_area). The thesis's sign is
                 * reversed: heat flows from the hotter side. */
                const double Vr = m[i] / st->rho0[i], face = dim == 3 ? cbrt(Vr) * cbrt(Vr) : sqrt(Vr);
                dTi += o->heat_ext * (Tout - T[i]) * face / m[i];
            }
        }
        if (robin) { /* the oven's Robin flux and heated colliders' contact beta, as MPM sees them */
            /* Each surface particle (the ones eq. 3.42 heats) carries its
             * face, V^((d-1)/d) of its rest volume, as a boundary node does in
             * MPM (boundary.c); a particle within its spacing of a heated
             * collider carries the same face of contact (MPM: within dx). The
             * colour gradient as a surface delta (V |grad C|) would need no
             * flag, but with particles on one side only it sums to 0.69 of a
             * block's outline. */
            const double ci = s->mats.slot[mat[i]].core[CP_SPECIFIC_HEAT], Vr = m[i] / st->rho0[i];
            const double sp = dim == 3 ? cbrt(Vr) : sqrt(Vr), face = Vr / sp;
            double coef = beta_oven > 0 && st->surf[i] ? face * beta_oven : 0.0, Tr = Text;
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
            if (ledger) st->qo[i] = beta_oven > 0 && st->surf[i] ? face * beta_oven * (Text - T[i]) : 0.0;
        }
        st->dT[i] = dTi;
    }
}

double sph_heat_stable_dt(const hearth_scene *s, double hmin, double rhomin) {
    const hearth_sph_def *o = &s->def.sph;
    const particles *ps = &s->ps;
    const double *T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL;
    double dt = INFINITY;
    if (o->heat_int > 0 && T) dt = fmin(dt, 0.1 * hmin * hmin * rhomin / o->heat_int); /* eq. 3.45 has 1/rho */
    /* eq. 3.42 per unit area: a surface particle relaxes at k A / m = k / (rho sp);
     * a quarter of that time, as the Robin limit below */
    if (o->heat_ext > 0 && T) dt = fmin(dt, 0.25 * rhomin * hmin / o->h_factor / o->heat_ext);
    if (T) { /* Robin: a face of V / spacing against the heat capacity rho c V */
        double beta = isnan(s->def.oven_temperature) ? 0 : s->def.oven_beta, bc = 0;
        for (int k = 0; k < s->ncol; k++)
            if (!isnan(s->cols[k].temperature) && s->cols[k].beta > bc) bc = s->cols[k].beta;
        beta += bc;
        for (int m = 0; m < s->mats.n && beta > 0; m++) {
            const material_slot *ms = &s->mats.slot[m];
            const double rc = ms->params[ms->density_index] * ms->core[CP_SPECIFIC_HEAT];
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
}
