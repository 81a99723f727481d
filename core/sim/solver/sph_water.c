/* sph_water.c: water in the SPH solver (issue #18), the same law as MPM's
 * (fields/water.c: Ding et al. 2019 §3.2, eq. 8 and 22) on SPH's particles,
 * as the thesis proposes (Rodriguez-Arenas 2011 §6: "the water content can
 * be stored as a property of each particle").
 *
 * Live only when a material asks for water (water_material_wants, as in
 * MPM): each particle carries its water mass in PC_WATER, MPM's column, and
 * its saturation is water_saturation's, m^w / (rho_0^w V_0) on SPH: the rest
 * volume, not J V_0 (water.h says why: SPH's det F drifts at the surface).
 * Per step:
 *
 *   dm^w_i/dt = sum_j rho_0^w D_ij 4 m_i m_j / (rho_i + rho_j)^2 c_ij L_ij (s_j - s_i)
 *               - [i on the surface] e_i,
 *
 * - Fick's flux (eq. 22, q = -rho_0^w K theta s grad s, D = K theta s)
 *   through the SPH Laplacian the heat uses (sph_heat.c: eq. 3.45-3.46 with
 *   eq. 3.8's kernel L_ij, sph_lap_visc, and the pair's mean c_ij of the
 *   viscous renormalisation st->vc, which makes the heat slab converge at
 *   order 2). 4 m_i m_j / (rho_i + rho_j)^2 is V_i V_j; multiplied by
 *   m_i and written with both masses it is symmetric in i and j, so what i
 *   gains j loses and the pair sums move no water (to round-off). A
 *   coefficient that varies is taken as the pair's mean, D_ij = (D_i +
 *   D_j) / 2, as Cleary & Monaghan (1999, J. Comput. Phys. 148, 227, eq. 9
 *   with its pair coefficient) do for conductivity; the arithmetic mean is
 *   the midpoint value of the finite volumes that water_drying_vs_fd takes
 *   as the reference (their harmonic mean would let a dried surface row
 *   throttle the flux toward it, which K theta s does not ask).
 * - evaporation e_i (kg/s) at the surface particles SPH finds for its heat
 *   (st->surf, sph_kinematics), through water_evaporation, MPM's Robin form
 *   with its layer (water.h): each surface particle carries the face its
 *   Robin heat gives it, V^((d-1)/d) of its rest volume V = m / rho_0, and
 *   its sample lies half a spacing inside that face (the lattice's surface
 *   is half a spacing past its last row), toward the oven's ambient
 *   saturation s_amb. The flag does not tell air from a tray: a face
 *   resting on a collider evaporates too, as it takes the oven's Robin heat
 *   (sph_heat.c); MPM's boundary.c takes contact faces out of the air
 *   surface, which SPH has no measure for yet.
 * - with the scene's latent_heat, e_i takes L e_i / (m_i alpha_i) from dT_i,
 *   alpha_i = alpha(w_i) (material_specific_heat; the wet c without dry_specific_heat)
 *   (MPM takes L e_p from the nodes around particle p, transport.c); once the
 *   temperatures moved, a wet particle past the boiling point boils its
 *   excess heat away through water.c's water_boil, MPM's own.
 *
 * The pairs' sum is made in sph_heat_rates's pair walk, which has the
 * pair's r and kernel value at hand (sph_water_prepare fills what it reads
 * first; sph_water_pair, sph_state.h, is the term either walk sums), and
 * here only for a step that walk did not make (no temperature field).
 * Forward Euler, like SPH's heat. What leaves (evaporation, boiling, less
 * what the saturation floor hands back) goes into s->water.step_removed and
 * counts once the step stands (water_step_stands, scene.c), as in MPM, so
 * water_total + water.lost stays the starting water (`sph_water_conserves`).
 * Bubble particles (CP_BUBBLE > 0, the thesis's gas, eq. 3.48-3.50) hold
 * no liquid water: water_init_particles seeds them at the floor whatever
 * their material's saturation (its default 0.5 had made the bread roll's
 * bubbles a water source: its centre read 0.31 of the dough's 0.218 at
 * 0.02 s, docs/validation.md "SPH's saturation at rest"), and here they
 * neither trade water with their neighbours nor evaporate: the water goes
 * round a bubble through the dough's films (our choice; the vapour that
 * joins a bubble's gas is sph.bubble_vapour's, sph_gas.c).
 * Every particle writes only its own slots and sums its neighbours in list
 * order; the removed water is summed serially in particle order: the same
 * bits on any thread count. Not carried on SPH: wet colliders, the water's
 * momentum (eq. 26-27) and water pressure for plugins (HEARTH_NEEDS_SATURATION):
 * sph_check_def and solver_accepts refuse them. */
#include <math.h>

#include "alloc.h"
#include "error.h"
#include "material.h"
#include "physics_constants.h"
#include "sph_kernel.h"
#include "sph_neighbours.h"
#include "sph_state.h"
#include "water.h"

int sph_water_live(const hearth_scene *s) { return water_active(s) || s->def.latent_heat; }

void sph_water_free(struct sph_state *st) {
    const size_t c = (size_t)st->wcap;
    mem_free(st->dW, sizeof(double) * c);
    mem_free(st->sw, sizeof(double) * c);
    mem_free(st->wd, sizeof(double) * c);
    mem_free(st->qo, sizeof(double) * c);
    mem_free(st->kd, sizeof(double) * c);
    mem_free(st->rwd, sizeof(double) * c);
    st->dW = st->sw = st->wd = st->qo = st->kd = st->rwd = NULL;
    st->wcap = 0;
}

/* Recomputed every step, so a larger set starts empty: nothing is carried
 * over, and a scene without water or latent_heat keeps none (it pays only
 * for the physics it uses). */
hearth_status sph_water_ensure(hearth_scene *s, int n, hearth_error *err) {
    struct sph_state *st = s->sph;
    if (!sph_water_live(s) || n <= st->wcap) return HEARTH_OK;
    sph_water_free(st);
    const int cap = n + n / 4 + 16;
    const size_t b = sizeof(double) * (size_t)cap;
    st->dW = mem_calloc(b), st->sw = mem_calloc(b), st->wd = mem_calloc(b), st->qo = mem_calloc(b), st->kd = mem_calloc(b);
    st->rwd = mem_calloc(b);
    st->wcap = cap;
    if (!st->dW || !st->sw || !st->wd || !st->qo || !st->kd || !st->rwd) {
        sph_water_free(st);
        return err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory for the water of %d particles", n);
    }
    return HEARTH_OK;
}

/* Fills st->sw with each particle's saturation, st->wd with its K theta s (-1: a bubble, which trades none) and
 * st->rwd with its rho_0^w, for the pairs (sph_heat_rates sums them in its own pair loop, which walks the same
 * lists with the same r: the water's own walk had cost the bread of the dead 5% of its run, helper sphcrumb). */
void sph_water_prepare(hearth_scene *s) {
    struct sph_state *st = s->sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, *mat = c.mat;
    const double *T = c.T;
    double *sw = st->sw, *D = st->wd, *rw = st->rwd;
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        const material_slot *ms = &s->mats.slot[mat[i]];
        sw[i] = water_saturation(s, i);
        D[i] = ms->core[CP_WATER_DIFFUSIVITY] * ((T ? T[i] : ms->core[CP_REFERENCE_T]) + KELVIN) * sw[i]; /* K theta s */
        if (water_sph_gas(s, ms)) D[i] = -1; /* a bubble: no exchange (below) */
        rw[i] = ms->core[CP_WATER_DENSITY];
    }
    st->wready = 1;
}

/* st->dW with each particle's water rate (kg/s): the pairs' flux (unless sph_heat_rates summed it this step,
 * st->wpairs) less its evaporation; with latent_heat takes L e_i from st->dT (sph_heat_rates ran). */
void sph_water_rates(hearth_scene *s) {
    struct sph_state *st = s->sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, dim = c.dim, *mat = c.mat;
    const double *x = c.x, *m = c.m, *T = c.T;
    const int *off = st->nl.off, *nb = st->nl.j;
    const double s_amb = s->def.oven_saturation;
    const int latent = s->def.latent_heat && T;
    const double psat_b = water_psat_boiling(s); /* with latent_heat: the vapour's factor (water.h), MPM's */
    if (!st->wready) sph_water_prepare(s);
    const int pairs = !st->wpairs;
    const double *sw = st->sw, *D = st->wd;
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        const material_slot *ms = &s->mats.slot[mat[i]];
        const double rwi = ms->core[CP_WATER_DENSITY];
        if (D[i] < 0) { /* a bubble holds no water and trades none */
            st->dW[i] = 0;
            continue;
        }
        double dw = 0;
        if (pairs) {
            for (int k = off[i]; k < off[i + 1]; k++) {
                const int j = nb[k];
                if (!sph_water_pairs_with(D, i, j)) continue; /* water goes round a bubble, through its films */
                double d[3];
                sph_disp(&st->cells, x + 3 * i, x + 3 * j, d);
                const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
                if (r <= 0) continue;
                dw += sph_water_pair(st, m, i, j, sph_lap_visc(dim, r, 0.5 * (st->h[i] + st->h[j])));
            }
        } else {
            dw = st->dW[i]; /* the pairs' sum, sph_heat_rates's */
        }
        double e = 0;
        if (st->outer[i] && ms->core[CP_EVAPORATION] > 0) {
            /* its share of the outer surface (sph_outer.c), the face eq. 3.42's heat enters by */
            const double Vr = m[i] / st->rho0[i], sp = dim == 3 ? cbrt(Vr) : sqrt(Vr), face = Vr / sp * st->oshare[i];
            const double th = (T ? T[i] : ms->core[CP_REFERENCE_T]) + KELVIN;
            e = water_evaporation(ms->core[CP_EVAPORATION], ms->core[CP_WATER_DIFFUSIVITY], rwi, th, sw[i], s_amb, 0.5 * sp,
                                  face, psat_b);
            const double mc = m[i] * material_specific_heat(ms, &s->ps, i); /* alpha(w) at the step's start, as sph_heat_rates */
            if (latent && mc > 0) st->dT[i] -= HEARTH_LATENT_HEAT * e / mc;
        }
        st->dW[i] = dw - e;
    }
    st->wready = st->wpairs = 0;
}

/* After the temperatures moved by st->dT (before their maxima are taken, as
 * in MPM's G2P): the water by st->dW, floored as MPM's (water_take), and
 * with latent_heat the boiling of water_boil. Serial
 * in particle order, so the step's removed water has the same bits on any
 * thread count. */
void sph_water_advance(hearth_scene *s, double dt) {
    struct sph_state *st = s->sph;
    const sph_cols c = sph_cols_of(s);
    double *W = pcold(&s->ps, PC_WATER), *T = c.T, removed = 0;
    const double boil = s->def.latent_heat && T ? s->def.boiling_point : INFINITY;
    for (int i = 0; i < c.n; i++) {
        const material_slot *ms = &s->mats.slot[c.mat[i]];
        const double vol = c.V0[i], cap = ms->core[CP_WATER_DENSITY] * vol, before = W[i]; /* V_0: water_saturation's */
        double w = before + dt * st->dW[i];
        if (w < WATER_SATURATION_FLOOR * cap) w = WATER_SATURATION_FLOOR * cap;
        W[i] = w;
        /* W[i] falls by what boiled; m alpha(w) at the water the step began with, the capacity sph_heat_rates
         * heated it with (MPM's P2G likewise) */
        if (T && T[i] > boil) water_boil(s, i, &T[i], boil, vol, c.m[i] * material_specific_heat_of(ms, &s->ps, i, before));
        removed += before - W[i];
    }
    s->water.step_removed = removed;
}

/* The water's limits on forward Euler: the pair Laplacian's, as the heat's
 * (0.1 h^2 / D, sph_heat_stable_dt); a surface particle's water rho_0 s V
 * against its loss beta theta s V / spacing (a quarter of that time, as the
 * Robin heat; the vapour's factor, at most 1, only slows the loss); and with
 * latent_heat the sink's rate of change with the particle's temperature,
 * L beta g (s - s_amb) face against rho c V, a Robin coefficient
 * L beta g (s - s_amb), g the vapour's factor's bound (water_latent_stiffness,
 * water.h: 14.1 at a 100 degC boiling point). The step's sink acts on these
 * very saturations (sph_water_rates reads water_saturation at the step's
 * start), and the surface layer only lowers the excess (water_surface_excess),
 * so the largest positive beta (s - s_amb) / (rho c) over the particles bounds
 * it exactly; the surface flags are not known before the step, so every
 * particle counts. Below s_amb the sink is a source growing with theta, which
 * forward Euler does not make oscillate. Rejected: s - s_amb <= 1 for every
 * material (4.6x too tight at the physical bread's s = 0.218). */
double sph_water_stable_dt(const hearth_scene *s, double hmin, double rhomin) {
    (void)rhomin;
    if (!water_active(s)) return INFINITY;
    const particles *ps = &s->ps;
    const double *T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL;
    const double spmin = hmin / s->def.sph.h_factor, s_amb = s->def.oven_saturation;
    const int latent = s->def.latent_heat && T;
    double dmax = 0, emax = 0, lmax = 0, dt = INFINITY;
    for (int i = 0; i < ps->n; i++) {
        const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
        if (water_sph_gas(s, ms)) continue; /* a bubble trades no water (sph_water_rates) */
        const double th = (T ? T[i] : ms->core[CP_REFERENCE_T]) + KELVIN, sat = water_saturation(s, i);
        dmax = fmax(dmax, ms->core[CP_WATER_DIFFUSIVITY] * th * sat);
        emax = fmax(emax, ms->core[CP_EVAPORATION] * th / ms->core[CP_WATER_DENSITY]);
        const double ex = sat - s_amb, b = ms->core[CP_EVAPORATION];
        if (latent && ex > 0 && b > 0) {
            const double rc = ms->params[ms->density_index] * material_specific_heat_min(ms); /* the dried alpha */
            lmax = fmax(lmax, rc > 0 ? b * ex / rc : INFINITY);
        }
    }
    if (dmax > 0) dt = fmin(dt, 0.1 * hmin * hmin / dmax);
    if (emax > 0) dt = fmin(dt, 0.25 * spmin / emax);
    if (lmax > 0) {
        const double g = water_latent_stiffness(water_psat_boiling(s), s->def.boiling_point + KELVIN);
        dt = fmin(dt, 0.25 * spmin / (HEARTH_LATENT_HEAT * g * lmax));
    }
    return dt;
}
