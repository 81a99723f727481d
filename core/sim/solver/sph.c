/* sph.c: one SPH step (Rodriguez-Arenas 2011, ch. 3-4; equation numbers are
 * the thesis's).
 *
 * Order of a step (sph_step, one static function per phase):
 *   sph_walls_begin      fixed particles take their body's prescribed
 *                        velocity, or 0 (sph_walls.c)
 *   phase_predrift       (leapfrog: drift half a step); periodic wrap
 *   phase_neighbours     sort particles by cell, neighbour lists and with
 *                        them the density by summation (3.13) (sph_neighbours.c)
 *   phase_density        per-particle constants; Sigalotti adaptive h
 *                        (3.54-3.56) if asked
 *   sph_pairs_prepare    which list slot holds each pair's other half, for
 *                        sph_forces and sph_xsph, which evaluate each pair
 *                        once (sph_forces.c)
 *   sph_kinematics     velocity gradient (3.27), colour field and its
 *                        gradient (3.28-3.29), surface particles; the
 *                        viscous renormalisation (sph_viscosity.c)
 *   phase_pressure       Tait (3.17); bubble particles (3.48-3.51) while they
 *                        heat, the final-density Tait (3.52) afterwards; or
 *                        with sph.gas_law Tait against each particle's rest
 *                        density, a bubble's the gas law's (sph_gas.c)
 *   phase_stress         F <- (I + dt L) F, the plugin's Kirchhoff stress
 *                        through the material door; its deviator enters the
 *                        momentum equation (Tait gives the pressure)
 *   sph_artificial_stress  on tensile principal stresses (Monaghan 2000)
 *                        (sph_forces.c)
 *   sph_forces           pressure (3.18), deviatoric stress, artificial
 *                        stress, viscosity (3.19) with no-slip walls (Morris
 *                        et al. 1997), artificial viscosity beta term (3.41),
 *                        surface tension (3.30), gravity; the kick
 *                        (sph_forces.c)
 *   sph_hourglass        with sph.hourglass, the pairs' motion (3.27) does not
 *                        describe damped, implicitly (sph_hourglass.c)
 *   sph_outer_surface    the body's outer surface particles (sph_outer.c: a
 *                        flood fill; the colour field of 3.29 misses a risen
 *                        cake's top and marks rows inside it)
 *   sph_water_prepare    the saturations the water's pairs read (sph_water.c)
 *   sph_heat_rates       heat (sph_heat.c): internal (3.45-3.46), external
 *                        at outer surface particles (3.42), the oven's Robin flux
 *                        and heated colliders' contact beta (as MPM); in the
 *                        same pair walk the water's Fick flux (sph_water_pair)
 *   sph_water_rates      water as MPM's (Ding eq. 8, 22; sph_water.c)
 *   sph_xsph             XSPH (3.34 with the tuner of 4.4; sph_xsph.c)
 *   sph_fields_advance   temperatures and water forward; boiling (sph_heat.c)
 *   phase_drift          drift (3.57-3.58), colliders and walls with the
 *                        thesis's response (3.31-3.33)
 *   sph_walls_end        moving fixed bodies move rigidly (sph_walls.c)
 * The crust's colour (§4.4) is no phase: scene.c integrates the browning
 * index of either solver from each particle's temperature history
 * (fields/browning.c, Zanoni et al. 1995, the thesis's [89]) where we used
 * eq. 4.5-4.6's texture coordinate, linear in the present temperature.
 * Every particle writes only its own slots and sums its neighbours in list
 * order, so a step is deterministic for any thread count. The step's helpers
 * live beside it (sph_state.h shares the state): the viscosity rule and eq.
 * 3.8's renormalisation in sph_viscosity.c, the forces in sph_forces.c, the
 * wall particles in sph_walls.c, the heat rates in sph_heat.c, the stable dt in sph_dt.c.
 *
 * dt (sph_stable_dt, sph_dt.c) is the smallest of CFL (cfl dx / (speed + sound speed),
 * as MPM, so the guard's checks hold; the sound speed is c0, or Tait's at the
 * particle's density where eq. 3.52 lowered its reference: signal_speed),
 * viscous (dt_viscous rho h^2 / mu), force (dt_force sqrt(h/|a|)) and heat limits.
 *
 * Where we differ from the thesis, each with its reason at the code: the
 * cubic spline's factor is 8/(pi h^3) (sph_kernel.h: the printed 1/(pi h^3)
 * belongs to the smoothing-length convention); the default h is 2.4 particle
 * spacings (the lattice sum of W V is within 1e-3 of 1 there); negative Tait
 * pressure is clamped unless `sph.tension` (a free surface otherwise clumps
 * and climbs walls); a heating bubble's pressure is never below Tait (eq. 3.51
 * alone lets it be squeezed onto its neighbours); a cooling bubble's final
 * density rises by (T_prev + 273.15) / (T + 273.15), capped at rest (its gas
 * contracts); a surface particle's final density is its interior neighbours'
 * (its own summed density is low for want of neighbours); the colour field's
 * Laplacian includes the particle's own term (without it eq. 3.30 pushes
 * outward); the external heat flows toward the outside temperature (the thesis
 * prints T_i - T_ext); XSPH epsilon is at most 1 (Table 4.1's 5 overshoots;
 * the text of §4.3 uses 0.5) and under eq. 4.4 a pair shares one (sph_xsph.c:
 * so eq. 3.34 keeps momentum); fixed particles are no-slip walls in eq. 3.19
 * (Morris et al. 1997), their drag taken implicitly in the kick, and a fixed
 * body may move rigidly (a lid, a paddle: sph_walls.c); eq. 3.19's
 * Laplacian (the kernel of eq. 3.8) is renormalised per particle by its
 * discrete second moment (sph_viscous_factor). Eq. 3.8 summed over a resting
 * lattice is 5.7% stronger than its integral at h = 2.4 spacings (3.8% with
 * rows sliding), a bias fixed by h over the spacing, so it does not shrink
 * as the spacing does: a creeping channel start-up was 4.6%, 5.2%, 5.4% slow
 * at 10, 20, 40 particles across. We chose the renormalisation over Morris
 * et al.'s grad W . r / r^2 form because that form, too, is off by a fixed
 * fraction on a lattice (0.9% weak resting, 0.6% strong sliding in 2D, 1.8%
 * weak in 3D), while the renormalised sum is exact for a quadratic velocity
 * on any resting lattice and within 0.3% sliding; it keeps the thesis's
 * kernel (and so its viscous dt limit). Now the start-up converges (order
 * 1.2, `sph_creeping_startup_converges`) and so does the steady profile
 * (order 1.9, `sph_poiseuille_converges`). Eq. 3.45's heat Laplacian uses the
 * same kernel, so it takes the same factor (sph_heat.c; slab conduction then
 * converges at order 2, `sph_heat_conduction_converges`).
 *
 * Shared with MPM: particles, plugins through the material door (porosity from
 * plastic_J for a material that needs it; no saturation: a material that needs
 * it is refused when added), water (sph_water.c: MPM's law and column, its
 * evaporation and latent sink), colliders, probes, outputs, the oven's Robin flux
 * and heated colliders' contact beta (each outer surface particle carries its face
 * V^((d-1)/d) of oven surface, a particle within its spacing of a heated
 * collider the same face of contact; `sph_oven_robin`), a dried crust's
 * dry_conductivity and dry_specific_heat (sph_heat.c: they scale `sph.heat_int`
 * and the heat capacity per particle). Not shared: the conduction
 * parameter itself (eq. 3.45 uses `sph.heat_int`), thermal expansion, CO2 and water pressure (eq. 14) (not
 * applied), wet colliders and the water's momentum (refused), collider friction and the slip/separate distinction (both
 * take the thesis response; beta_c plays friction's part; sticky is sticky,
 * and so is a grip, which carries no particles here; both are also no-slip
 * walls in eq. 3.19's viscous term, sph_collider_drag in sph_walls.c). A rollback restores the
 * particles but not the final densities of eq. 3.52.
 *
 * Not built: checkpoints of SPH scenes (can_checkpoint = 0, so saving one is
 * refused with a message); the local convex hull for surface particles
 * (§3.1.8).
 *
 * Known limits the scenes show (scripts/scenes/sph/): the elastic Maxwell
 * stress alone does not hold a shape against the tensile instability; bread
 * of the dead sets artificial_stress = 0.3 and holds to 2.5 s instead of
 * splitting at 1.9 s. The bread roll (#18) split by 0.3 s with the pressure
 * clamped (no cohesion: its stretched base tears as it slumps, before it has
 * warmed), and with `tension` and artificial stress its top burst at 1.64 s
 * under eq. 3.51, whose bubble then pushed by whatever volume it already
 * gained (it now stops at its gas's volume, bubble_expands);
 * its preset (h.library.sph.bread_roll) now takes tension, artificial stress
 * and sph.gas_law (docs/validation.md "SPH bread roll (#18)"), and with the
 * gas law the density sums rest volumes (sort_and_list): eq. 3.13's mass sum
 * read the dough films beside expanded bubbles as stretched, Tait pulled
 * them into pairs and the roll tore at 0.5 s; it now rises past 1.3x whole
 * (docs/validation.md "The films' tension"). Eq. 3.13 also reads a free
 * surface, and a collider's side, as stretched (half the kernel is empty), so
 * with tension the roll's outline is a skin that lifts it off its tray;
 * sph.continuity_density reads the particle's own volume instead (sph_gas.c),
 * off in the roll's preset because its films then tear (docs/validation.md
 * "The roll's skin"); the preset takes sph.renormalised_density, the sum
 * divided by the part of the kernel the body fills, which removes the skin
 * and keeps the sum inside (docs/validation.md "The roll's skin,
 * renormalised"). From 1.5 s that roll's base arches off its tray: the sum
 * reads the dough beside hot bubbles the set dough holds back as squeezed
 * (docs/validation.md "Why the roll's base leaves its tray"); the preset's
 * sph.own_squeeze (sph_gas.c) takes the squeeze from each particle's own det
 * F ("The roll's base: its own squeeze"); with the preset's crumb setting
 * where bread sets the roll rises 1.43x and its base's ends lift from 1.6 s
 * as the set crust rounds over closed bubbles ("The roll's set"). At
 * eps 0.3 a block in strong uniform tension still creeps toward pairs over
 * many sound crossings (`sph_artificial_stress_fluid`: 0.68 spacings at 1 s;
 * 0.5 holds). Surface tension above about 0.02 N/m does not settle a 0.06 m
 * drop (`sph_surface_tension_rounds_drop`). */
#include "plugins.h"
#include "solver.h"
#include "sph.h"
#include "settings.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "material.h"
#include "sph_kernel.h"
#include "sph_state.h"
#include "tensor.h"
#include "water.h"

/* ---- options ---------------------------------------------------------------- */

hearth_status sph_check_def(const hearth_scene_def *d, hearth_error *err) {
    const hearth_sph_def *o = &d->sph;
    /* each option's range (flags 0 or 1), unit and help: settings.c's table; here the rules between options */
    hearth_status st = settings_check(d, "sph.", NULL, err);
    if (st) return st;
    if (d->water_momentum) /* sph_water.c carries the water's mass, not its momentum (eq. 26-27) */
        return err_set(err, HEARTH_ERR_PARAM,
                       "scene: water_momentum = true is not carried by solver = \"sph\" (its water moves no momentum); use "
                       "solver = \"mpm\" or water_momentum = false");
    if ((st = sph_gas_check_def(o, err))) return st; /* the gas law's options, refused without it (sph_gas.c) */
    if (o->renormalised_density && o->continuity_density)
        return err_set(err, HEARTH_ERR_PARAM,
                       "scene: sph.renormalised_density and sph.continuity_density are two densities for the same "
                       "pressure; set one of them");
    if (!(o->xsph_Tf > o->xsph_T0))
        return err_set(err, HEARTH_ERR_PARAM, "scene: sph.xsph_Tf = %g degC must be above sph.xsph_T0 = %g degC",
                       o->xsph_Tf, o->xsph_T0);
    return HEARTH_OK;
}

/* ---- storage ---------------------------------------------------------------- */

#define ARRAYS(X)                                                                                                      \
    X(rho, 1) X(prs, 1) X(h, 1) X(S, 9) X(acc, 3) X(vnew, 3) X(N, 3) X(lapC, 1) X(surf, 1) X(rhof, 1)                  \
        X(dT, 1) X(rho0, 1) X(B, 1) X(mu, 1) X(c0, 1) X(xsph, 1) X(perm, 1) X(Tprev, 1) X(sp, 1) X(R, 9) X(vc, 1)  \
        X(vr, 1) X(outer, 1) X(oshare, 1)
/* and ts, the outer particles' face temperatures, only in a scene that browns (their one reader: browning.c; #18,
 * helper userfix7: a double a particle every SPH scene had paid for) */
/* Frees the per-particle columns (ARRAYS, key, order) of a set sized for cap
 * particles: sph_free's set, and ensure's old set or the new one it could not
 * complete (mem_free passes over the columns left NULL). */
static void arrays_free(struct sph_state *a, int cap) {
    const size_t c = (size_t)cap;
#define FREE(x, k) mem_free(a->x, sizeof(double) * (k) * c);
    ARRAYS(FREE)
#undef FREE
    mem_free(a->ts, sizeof(double) * c);
    mem_free(a->gasleft, sizeof(double) * c);
    mem_free(a->key, sizeof(int) * c);
    mem_free(a->order, sizeof(int) * c);
}

static void sph_free(hearth_scene *s) {
    struct sph_state *st = s->sph;
    if (!st) return;
    sph_cells_free(&st->cells);
    sph_nlist_free(&st->nl);
    sph_walls_free(st);
    mem_free(st->pairc, sizeof(double) * st->pairc_cap);
    mem_free(st->pairm, sizeof(int) * st->pairm_cap);
    arrays_free(st, st->cap);
    mem_free(st->visc_index, sizeof(int) * (size_t)st->visc_cap);
    sph_water_free(st);
    sph_hourglass_free(st);
    sph_outer_free(st);
    mem_free(st, sizeof *st);
    s->sph = NULL;
}

/* The scene's SPH state, made on first use (a material added, or a step). */
struct sph_state *sph_state_of(hearth_scene *s, hearth_error *err) {
    if (!s->sph) {
        s->sph = mem_calloc(sizeof *s->sph);
        if (!s->sph) {
            err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory");
            return NULL;
        }
        s->sph->n = -1;
    }
    return s->sph;
}

static hearth_status ensure(hearth_scene *s, int n, hearth_error *err) {
    struct sph_state *st = sph_state_of(s, err);
    if (!st) return HEARTH_ERR_NOMEM;
    if (n <= st->cap) return HEARTH_OK;
    int cap = n + n / 4 + 16;
    struct sph_state nw = *st;
    int ok = 1;
#define ALLOC(a, k)                                                                                                    \
    nw.a = mem_calloc(sizeof(double) * (k) * (size_t)cap);                                                             \
    ok = ok && nw.a;
    ARRAYS(ALLOC)
    nw.ts = NULL;
    if (s->def.browning) {
        ALLOC(ts, 1)
    }
    nw.gasleft = NULL;
    if (s->def.sph.surface_vent) { /* the gas a vented cell has lost (sph_gas.c), only in a scene that vents */
        ALLOC(gasleft, 1)
    }
#undef ALLOC
    nw.key = mem_alloc(sizeof(int) * (size_t)cap);
    nw.order = mem_alloc(sizeof(int) * (size_t)cap);
    ok = ok && nw.key && nw.order;
    if (ok && st->n > 0) { /* the arrays kept across steps */
        memcpy(nw.rhof, st->rhof, sizeof(double) * (size_t)st->n);
        memcpy(nw.Tprev, st->Tprev, sizeof(double) * (size_t)st->n);
        if (nw.gasleft && st->gasleft) memcpy(nw.gasleft, st->gasleft, sizeof(double) * (size_t)st->n);
    }
    if (!ok) {
        arrays_free(&nw, cap);
        return err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory for %d particles", n);
    }
    arrays_free(st, st->cap);
    nw.cap = cap;
    *st = nw;
    return HEARTH_OK;
}

/* ---- helpers ---------------------------------------------------------------- */

static int finite_n(const double *a, int n) {
    for (int i = 0; i < n; i++)
        if (!isfinite(a[i])) return 0;
    return 1;
}

/* The particle's rest volume for its smoothing length: V0, or with
 * sph.gas_law m / rho_f, the volume its rest density gives it (eq. 3.53's
 * h = h0 (rho0 / rho)^(1/dim) with the rest density for the summed one, which
 * is low at a free surface for want of neighbours): an expanded bubble keeps
 * its neighbours within reach, as the thesis asks of eq. 3.53 ("so that they
 * are connected by a dough medium and do not fall apart as the volume
 * increases"). rhof and rho0 are the last step's, in the particles' order. */
static double rest_volume(const hearth_scene *s, int i) {
    const struct sph_state *st = s->sph;
    const double V0 = pcold(&s->ps, PC_VOL0)[i];
    if (!s->def.sph.gas_law || st->n != s->ps.n || !(st->rhof[i] > 0) || !(st->rho0[i] > 0)) return V0;
    return V0 * fmax(1.0, st->rho0[i] / st->rhof[i]);
}

/* Per-particle material constants: rest density, Tait B, viscosity (eq. 4.1
 * through a curve), sound speed, XSPH tuner (eq. 4.4), smoothing length. */
static void particle_constants(hearth_scene *s, int i, const double *T, double *pscratch) {
    struct sph_state *st = s->sph;
    const particles *ps = &s->ps;
    const int m = pcoli(ps, PC_MAT)[i];
    const material_slot *ms = &s->mats.slot[m];
    const double *p = T ? material_params(&s->mats, &s->ps, m, i, pscratch) : ms->params;
    const double rho0 = p[ms->density_index];
    plugin_call_enter(ms->m, "wave_speed");
    const double c = ms->m->wave_speed(p, ms->m->state_size > 0 ? pcold(ps, PC_STATE) + (size_t)i * ps->state_stride : NULL);
    plugin_call_leave();
    st->rho0[i] = rho0;
    st->c0[i] = isfinite(c) && c > 0 ? c : 0;
    st->B[i] = rho0 * st->c0[i] * st->c0[i] / s->def.sph.gamma; /* eq. 3.17: c0^2 = gamma B / rho0 */
    const int vi = st->visc_index[m];
    st->mu[i] = vi >= 0 ? p[vi] : 0.0;
    const hearth_sph_def *o = &s->def.sph;
    double eps = o->xsph0;
    if (T) { /* eq. 4.4, held at the ends */
        double u = (T[i] - o->xsph_T0) / (o->xsph_Tf - o->xsph_T0);
        u = u < 0 ? 0 : u > 1 ? 1 : u;
        eps = o->xsph0 + u * (o->xsph_f - o->xsph0);
    }
    st->xsph[i] = eps;
    const double V0 = rest_volume(s, i);
    st->h[i] = o->h_factor * (s->def.dim == 3 ? cbrt(V0) : sqrt(V0));
}

static hearth_status sort_and_list(hearth_scene *s, double hcell, const double *h, hearth_error *err) {
    struct sph_state *st = s->sph;
    particles *ps = &s->ps;
    const int n = ps->n;
    hearth_status e = sph_cells_setup(&st->cells, s->def.dim, s->def.lo, s->def.hi, hcell, s->def.sph.periodic, err);
    if (e) return e;
    const double *x = pcold(ps, PC_X);
    for (int i = 0; i < n; i++) st->key[i] = sph_cell_of(&st->cells, x + 3 * i);
    sph_cells_sort(&st->cells, st->key, n, st->order);
    int moved = 0;
    for (int i = 0; i < n && !moved; i++) moved = st->order[i] != i;
    if (moved) {
        particles_permute(ps, st->order, st->perm, sizeof(double) * (size_t)n);
        /* the SPH arrays that carry over: final density (eq. 3.52) and h (for the adaptive pass) */
        for (int i = 0; i < n; i++) st->perm[i] = st->rhof[st->order[i]];
        memcpy(st->rhof, st->perm, sizeof(double) * (size_t)n);
        for (int i = 0; i < n; i++) st->perm[i] = st->Tprev[st->order[i]];
        memcpy(st->Tprev, st->perm, sizeof(double) * (size_t)n);
        if (st->gasleft) { /* sph.surface_vent reads the last step's outer flag before sph_outer_surface renews it */
            for (int i = 0; i < n; i++) st->perm[i] = st->gasleft[st->order[i]];
            memcpy(st->gasleft, st->perm, sizeof(double) * (size_t)n);
            for (int i = 0; i < n; i++) st->perm[i] = st->outer[st->order[i]];
            memcpy(st->outer, st->perm, sizeof(double) * (size_t)n);
        }
        if (h) {
            for (int i = 0; i < n; i++) st->perm[i] = h[st->order[i]];
            memcpy(st->h, st->perm, sizeof(double) * (size_t)n);
        }
    }
    /* the density of eq. 3.13 comes with the lists (one walk over the neighbours, not two) */
    const int vol = s->def.sph.gas_law && h;
    if (vol && moved) {
        for (int i = 0; i < n; i++) st->perm[i] = st->vr[st->order[i]];
        memcpy(st->vr, st->perm, sizeof(double) * (size_t)n);
    }
    const double *m = pcold(ps, PC_MASS);
    e = sph_nlist_build(&st->nl, &st->cells, pcold(ps, PC_X), n, h ? st->h : NULL, hcell,
                                      vol ? st->vr : m, h ? st->rho : NULL, err);
    /* With sph.gas_law the particles' rest volumes differ (a bubble's grows
     * with its gas, the dough's does not), and eq. 3.13's mass sum smooths
     * the number of particles across a bubble's edge: a dough particle beside
     * expanded bubbles has fewer neighbours in its kernel than in dough and
     * reads a low density, so Tait pulls it (the films between bubbles go into
     * tension, their particles pair and tear), while the bubble beside dough
     * reads a high one and pushes on past its gas volume. The sum of rest
     * volumes, rho_i = (m_i / V_i) sum_j V_j W_ij with V the rest volume
     * (rest_volume), is 1 x rho_i's rest density wherever each particle holds
     * its own rest volume, whatever its neighbours' are: Hopkins 2013 (MNRAS
     * 428, 2840, §2: the volume element x_i / sum_j x_j W_ij, here with x_j =
     * V_j; x = m is eq. 3.13, x = 1 Hu & Adams 2006's number density, J.
     * Comput. Phys. 213, 844). For equal rest
     * volumes it is eq. 3.13 again; scenes without gas_law keep eq. 3.13's
     * bits. docs/validation.md "SPH bread roll (#18)", "The films' tension". */
    if (!e && vol)
        for (int i = 0; i < n; i++) st->rho[i] *= m[i] / st->vr[i];
    return e;
}

/* ---- the step's phases ----------------------------------------------------------- */

/* Leapfrog's first half drift (drift-kick-drift; symplectic Euler, eq.
 * 3.57-3.58, drifts once at the end), then positions on periodic axes back
 * into the box. */
static void phase_predrift(hearth_scene *s, double dt) {
    const hearth_sph_def *o = &s->def.sph;
    const sph_cols c = sph_cols_of(s);
    if (o->leapfrog)
        for (int i = 0; i < c.n; i++)
            if (!(c.flags && (c.flags[i] & PF_FIXED)))
                for (int a = 0; a < c.dim; a++) c.x[3 * i + a] += 0.5 * dt * c.v[3 * i + a];
    for (int a = 0; a < c.dim; a++)
        if (o->periodic[a]) {
            const double lo = s->def.lo[a], L = s->def.hi[a] - lo;
            for (int i = 0; i < c.n; i++) c.x[3 * i + a] = lo + fmod(fmod(c.x[3 * i + a] - lo, L) + L, L);
        }
}

/* Smoothing lengths from the rest volumes, h = h_factor V0^(1/dim); then
 * sort by cell and build the neighbour lists. */
static hearth_status phase_neighbours(hearth_scene *s, hearth_error *err) {
    struct sph_state *st = s->sph;
    const particles *ps = &s->ps;
    const int n = ps->n, dim = s->def.dim;
    double hmax = 0;
    for (int i = 0; i < n; i++) {
        const double V0 = rest_volume(s, i);
        const double h0 = s->def.sph.h_factor * (dim == 3 ? cbrt(V0) : sqrt(V0));
        st->h[i] = h0;
        st->vr[i] = V0; /* the gas law's density sum (sort_and_list) */
        if (h0 > hmax) hmax = h0;
    }
    return sort_and_list(s, hmax, st->h, err);
}

/* Per-particle constants; the density by summation (eq. 3.13) came with the
 * lists (sort_and_list). With adaptive h, Sigalotti et al.'s pass: eq. 3.54
 * with the geometric mean of eq. 3.55, then the lists and the density again
 * for the new h. */
static hearth_status phase_density(hearth_scene *s, hearth_error *err) {
    struct sph_state *st = s->sph;
    const hearth_sph_def *o = &s->def.sph;
    const int n = s->ps.n;
    double pscratch[SCENE_MAX_PARAMS];
    const double *T = sph_cols_of(s).T;
    for (int i = 0; i < n; i++) particle_constants(s, i, T, pscratch);
    /* st->rho: summed with the lists (sort_and_list) */
    if (!o->adaptive_h) return HEARTH_OK;
    double lg = 0;
    for (int i = 0; i < n; i++) lg += log(st->rho[i]);
    const double rbar = exp(lg / n);
    double hm = 0;
    for (int i = 0; i < n; i++) {
        st->h[i] *= o->k_g * pow(st->rho[i] / rbar, -o->eps_g);
        if (st->h[i] > hm) hm = st->h[i];
    }
    hearth_status e = sort_and_list(s, hm, st->h, err); /* order unchanged unless the cells changed */
    if (e) return e;
    T = sph_cols_of(s).T;
    for (int i = 0; i < n; i++) {
        const double hkeep = st->h[i];
        particle_constants(s, i, T, pscratch);
        st->h[i] = hkeep;
    }
    return HEARTH_OK; /* st->rho: summed with the new lists */
}

/* Whether bubble particle i expands by eq. 3.51: while it heats above
 * bubble_T0 and is still smaller than its gas, rho_i > rho_bi = rho0 / V_b
 * (eq. 3.49-3.50). The thesis (after eq. 3.51): "Equation 3.51 for bubble
 * pressure cannot be used indefinitely since the volume will continue to
 * increase. In order to avoid this, the pressure term changes back to" Tait
 * (eq. 3.17, against the final density of eq. 3.52). Without the volume test
 * a bubble pushed at B (V_b - 1) for as long as it heated, whatever volume it
 * had reached: in the bread of the dead (#18) the bubbles stood at rho0 / rho
 * = 1.93 at 1.2 s where their gas's V_b(T) was 1.34, and the webs of dough
 * between them tore into slits (docs/validation.md "The bread of the dead
 * stays in one piece"). rho_i is eq. 3.48's, the summed density. */
static inline int bubble_expands(const hearth_sph_def *o, const struct sph_state *st, int i, double bub,
                                 const double *T) {
    if (!(bub > 0) || !T || !(T[i] > o->bubble_T0) || !(T[i] > st->Tprev[i])) return 0;
    const double Vb = bub * (T[i] + KELVIN) / (o->bubble_T0 + KELVIN);
    return st->rho[i] * Vb > st->rho0[i];
}

/* Pressure: Tait (eq. 3.17) against the final density (eq. 3.52); bubble
 * particles (eq. 3.48-3.51) while they heat and are smaller than their gas
 * (bubble_expands). While any bubble expands, dough and bubbles keep their
 * density as the final density. */
static void phase_pressure(hearth_scene *s) {
    struct sph_state *st = s->sph;
    const hearth_sph_def *o = &s->def.sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, *mat = c.mat;
    const double *T = c.T;
    const int *off = st->nl.off, *nb = st->nl.j;
    if (o->gas_law) { /* sph_gas.c */
        sph_pressure_gas_law(s);
        return;
    }
    for (int i = 0; i < n; i++) {
        const material_slot *ms = &s->mats.slot[mat[i]];
        const double gam = o->gamma, rho0 = st->rho0[i];
        const double bub = ms->core[CP_BUBBLE];
        if (!isfinite(st->rhof[i])) st->rhof[i] = rho0;
        /* A cooling bubble contracts: eq. 3.51's ideal gas in reverse (V
         * proportional to absolute temperature), so its final density of
         * eq. 3.52 rises back toward the rest density. Without this a baked
         * bubble dough keeps its oven volume however cold it gets; the thesis
         * raises rho_f by hand for the collapsing angel food cake (§4.4). */
        if (bub > 0 && T && T[i] < st->Tprev[i])
            st->rhof[i] = fmin(rho0, st->rhof[i] * (st->Tprev[i] + KELVIN) / (T[i] + KELVIN));
        st->prs[i] = st->B[i] * (pow(st->rho[i] / st->rhof[i], gam) - 1); /* eq. 3.17, 3.52 */
        if (bubble_expands(o, st, i, bub, T)) { /* eq. 3.51 (Kelvin: ideal gas) */
            const double Vb = bub * (T[i] + KELVIN) / (o->bubble_T0 + KELVIN);
            /* Not below Tait: eq. 3.51 alone has no resistance to compression,
             * so a heating bubble squeezed by its neighbours (on a tray, seen)
             * collapses onto them and explodes when it stops heating. */
            st->prs[i] = fmax(st->prs[i], st->B[i] * st->rho[i] / rho0 * (Vb - 1));
        }
        /* A free surface has too few neighbours, so its summed density is low
         * and Tait pulls: particles clump and climb walls (tensile
         * instability). Clamped unless the scene asks for tension. */
        if (!o->tension && st->prs[i] < 0) st->prs[i] = 0;
    }
    int any_heating = 0;
    for (int i = 0; i < n && !any_heating; i++)
        any_heating = bubble_expands(o, st, i, s->mats.slot[mat[i]].core[CP_BUBBLE], T);
    if (any_heating) {
        /* A surface particle's summed density is low for want of neighbours,
         * not because it expanded: keeping that as its final density would
         * make it explode when it is surrounded again. Interior particles
         * keep their own density; surface particles the mean of their
         * interior neighbours'. */
        for (int i = 0; i < n; i++)
            if (!st->surf[i] && st->rho[i] < st->rhof[i]) st->rhof[i] = st->rho[i];
        for (int i = 0; i < n; i++) {
            if (!st->surf[i]) continue;
            double sum = 0;
            int cnt = 0;
            for (int k = off[i]; k < off[i + 1]; k++)
                if (!st->surf[nb[k]]) sum += st->rhof[nb[k]], cnt++;
            if (cnt && sum / cnt < st->rhof[i]) st->rhof[i] = sum / cnt;
        }
    }
    if (T) memcpy(st->Tprev, T, sizeof(double) * (size_t)n);
}

/* The plugin's stress through the material door: F <- (I + dt L) F with L
 * of eq. 3.27, then the deviator of sigma = tau / J enters the momentum
 * equation (Tait gives the pressure). Returns 0, or 1 with rep naming the
 * first failed particle in particle order (a bad F, a plugin code or a
 * non-finite tau), so the guard's answer does not depend on the threads. */
static int phase_stress(hearth_scene *s, double dt, step_report *rep) {
    struct sph_state *st = s->sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, *mat = c.mat, *flags = c.flags;
    const double *T = c.T;
    const int stride = s->ps.state_stride;
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        double *Si = st->S + 9 * i;
        memset(Si, 0, 9 * sizeof(double));
        if (flags && (flags[i] & PF_FIXED)) continue;
        const double *L = c.C + 9 * i;
        double *Fi = c.F + 9 * i, f[9], Fn[9];
        for (int a = 0; a < 9; a++) f[a] = (a % 4 == 0) + dt * L[a];
        for (int r = 0; r < 3; r++)
            for (int q = 0; q < 3; q++)
                Fn[3 * r + q] = f[3 * r] * Fi[q] + f[3 * r + 1] * Fi[3 + q] + f[3 * r + 2] * Fi[6 + q];
        memcpy(Fi, Fn, sizeof Fn);
        const double J = Fi[0] * (Fi[4] * Fi[8] - Fi[5] * Fi[7]) - Fi[1] * (Fi[3] * Fi[8] - Fi[5] * Fi[6]) +
                         Fi[2] * (Fi[3] * Fi[7] - Fi[4] * Fi[6]);
        if (!(J > 0) || !finite_n(Fi, 9)) {
            Si[0] = NAN; /* recorded below, in particle order */
            continue;
        }
        const material_slot *ms = &s->mats.slot[mat[i]];
        double pscratch[SCENE_MAX_PARAMS];
        const double *p = material_params(&s->mats, &s->ps, mat[i], i, pscratch);
        const int vi = st->visc_index[mat[i]];
        if (vi >= 0) { /* eq. 3.19 applies the viscosity: the plugin sees none (sph_viscosity_index) */
            if (p != pscratch) {
                memcpy(pscratch, p, sizeof(double) * (size_t)ms->m->nparams);
                p = pscratch;
            }
            pscratch[vi] = 0;
        }
        hearth_point pt;
        memcpy(pt.grad_v, L, sizeof pt.grad_v);
        memcpy(pt.F, Fi, sizeof pt.F);
        pt.dt = dt;
        pt.p = p;
        pt.state = c.state ? c.state + (size_t)i * stride : NULL;
        /* The porosity as MPM gives it, n^p = 1 - (1 - n^p_0) / J^P from the plugin's plastic_J at the
         * start of the step, to a material that needs it (cam_clay_dough's yield surface); NaN to
         * the rest, which do not read it. No saturation: sph_water.c's water is not handed to a
         * plugin; a material that needs it is refused when added (sph_solver.supplies). None of the core's coupling terms: they are
         * isotropic, and SPH keeps only the deviator (Tait gives the pressure). */
        const material_env env = {
            .flags = (ms->m->needs & HEARTH_NEEDS_POROSITY ? MATERIAL_POROSITY_PLASTIC : 0u) | (ms->fracture ? MATERIAL_DAMAGE : 0u),
            .temperature = T ? T[i] : NAN,
            .saturation = NAN,
            .porosity = NAN,
            .dim = s->def.dim, /* <hearth/material.h> rule 8 */
        };
        double tau[9];
        const int code = material_point_eval(ms->m, ms->core, &pt, &env, tau);
        plugin_call_leave();
        if (code) { /* recorded below, in particle order: a plugin code, or -1 for a non-finite tau */
            Si[0] = NAN;
            Si[1] = code == MATERIAL_NONFINITE ? -1.0 : (double)code;
            continue;
        }
        const double tr = (tau[0] + tau[4] + tau[8]) / 3;
        for (int a = 0; a < 9; a++) Si[a] = (tau[a] - (a % 4 == 0 ? tr : 0.0)) / J;
    }
    for (int i = 0; i < n; i++)
        if (isnan(st->S[9 * i])) {
            const double code = st->S[9 * i + 1];
            rep->kind = code > 0 ? FAIL_PLUGIN : code < 0 ? FAIL_STRESS : FAIL_F;
            rep->particle = i;
            rep->code = code > 0 ? (int)code : 0;
            return 1;
        }
    return 0;
}

/* The sound speed of particle i's pressure law, for the CFL limit (sph_dt.c
 * reads it as the step report's c_max) and the guard's wave check. Tait
 * (eq. 3.17) is P = B ((rho / rho_r)^gamma - 1) with B = rho0 c0^2 / gamma
 * set by the rest density rho0, so
 *   c^2 = dP/drho = c0^2 (rho0 / rho_r) (rho / rho_r)^(gamma - 1).
 * Against rho_r = rho0 a weakly compressible flow stays within about 1% of
 * rho0, and c0 (what DualSPHysics takes for its time step too) is then c
 * within 3%, which cfl's margin covers: those particles keep c0, as before.
 * Eq. 3.52 lowers rho_r to the final density rho_f a bubble dough reached,
 * and that stiffens it: a particle whose rho_f fell to half of rho0 and is
 * squeezed back to rho0 carries c = 11 c0 at gamma 7. angel_food_cake did
 * that by its crust (a batter particle at rho_f 347 kg/m^3 of 600, rho/rho_f
 * 1.4): at c0's dt its waves crossed 1.7, then 3.7 particle spacings a step
 * and the kinetic energy ran away at step 128, unless eq. 4.4's epsilon of
 * 0.3 at the hot crust damped it (one epsilon of 0.05, or each pair's mean,
 * did not). So those particles count Tait's speed at their present density,
 * never less than c0. With sph.gas_law the dough's Tait is against rho0, a
 * bubble's gas (sph_gas.c) K (rho / rho_b - 1), c^2 = K / rho_b: with K = B
 * faster than c0 only past V_b = gamma; its gas's own K: sph_gas_sound_speed. */
static inline double signal_speed(const struct sph_state *st, const hearth_sph_def *o, int i, double bub, double T) {
    const double c0 = st->c0[i], rho0 = st->rho0[i], rf = st->rhof[i];
    if (o->gas_law && o->gas_pressure > 0) return fmax(c0, sph_gas_sound_speed(o, bub, rho0, T, st->water_per_gas));
    if (o->gas_law) return bub > 0 && o->gamma * rf < rho0 ? c0 * sqrt(rho0 / (o->gamma * rf)) : c0;
    if (!(rf < rho0)) return c0; /* Tait against the rest density (NaN: no reference yet) */
    const double r = st->rho[i] / rf, r6 = o->gamma == 7 ? (r * r) * (r * r) * (r * r) : pow(r, o->gamma - 1);
    const double c = c0 * sqrt(rho0 / rf * r6);
    return c > c0 ? c : c0;
}

/* The drift (eq. 3.57-3.58; the
 * second half under leapfrog), colliders and box walls with the thesis's
 * response (eq. 3.31-3.33: v = beta_c v_t - alpha_c v_n), and the report:
 * kinetic energy, the fastest particle, the largest sound speed, and the
 * first particle with a non-finite x or v or a bad wave speed. */
static void phase_drift(hearth_scene *s, double dt, step_report *rep) {
    struct sph_state *st = s->sph;
    const hearth_sph_def *o = &s->def.sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, dim = c.dim, *flags = c.flags;
    const double *m = c.m;
    double *x = c.x, *v = c.v, *T = c.T;
    const double drift = o->leapfrog ? 0.5 * dt : dt;
    double ke = 0, vmax = 0, cmax = 0;
    int fastest = -1;
    for (int i = 0; i < n; i++) {
        double *xi = x + 3 * i, *vi = v + 3 * i;
        if (flags && (flags[i] & PF_FIXED)) { /* moved by sph_walls_end; a moving wall's speed limits dt */
            const double sp = sqrt(vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2]);
            if (sp > vmax) vmax = sp, fastest = i;
            continue;
        }
        for (int q = 0; q < dim; q++) xi[q] += drift * vi[q];
        for (int q = 0; q < s->ncol; q++) {
            const collider *cl = &s->cols[q];
            if (!collider_near(cl, xi)) continue;
            double nrm[3];
            const double phi = collider_sdf(cl, xi, nrm);
            if (!(phi < 0)) continue;
            for (int a = 0; a < dim; a++) xi[a] -= phi * nrm[a];
            double vb[3];
            collider_velocity_at(cl, xi, vb);
            if (cl->mode == HEARTH_STICKY || cl->mode == HEARTH_GRIP) {
                for (int a = 0; a < dim; a++) vi[a] = vb[a];
                continue;
            }
            double rel[3], vn = 0;
            for (int a = 0; a < 3; a++) rel[a] = vi[a] - vb[a];
            for (int a = 0; a < dim; a++) vn += rel[a] * nrm[a];
            if (vn >= 0) continue;
            for (int a = 0; a < dim; a++) { /* eq. 3.33: v = beta_c v_t - alpha_c v_n */
                const double nv = vn * nrm[a], tv = rel[a] - nv;
                vi[a] = vb[a] + o->beta_c * tv - o->alpha_c * nv;
            }
        }
        for (int a = 0; a < dim; a++) { /* box walls, the same response */
            if (o->periodic[a]) continue;
            const double lo = s->def.lo[a], hi = s->def.hi[a];
            if (xi[a] < lo || xi[a] > hi) {
                xi[a] = xi[a] < lo ? lo : hi;
                const double sgn = xi[a] <= lo ? -1.0 : 1.0; /* outward normal */
                if (vi[a] * sgn > 0) {
                    for (int b = 0; b < dim; b++)
                        if (b != a) vi[b] *= o->beta_c;
                    vi[a] *= -o->alpha_c;
                }
            }
        }
        if (!finite_n(xi, 3) && rep->particle < 0) rep->kind = FAIL_X, rep->particle = i;
        if (!finite_n(vi, 3) && rep->particle < 0) rep->kind = FAIL_V, rep->particle = i;
        const double sp = sqrt(vi[0] * vi[0] + vi[1] * vi[1] + vi[2] * vi[2]);
        ke += 0.5 * m[i] * sp * sp;
        if (sp > vmax) vmax = sp, fastest = i;
        const double ci = signal_speed(st, o, i, s->mats.slot[c.mat[i]].core[CP_BUBBLE], T ? T[i] : NAN);
        if (ci > cmax) cmax = ci;
        /* particle_constants keeps 0 for a wave speed that is NaN, inf or <= 0: the guard names the plugin */
        if (!(st->c0[i] > 0) && rep->particle < 0) rep->kind = FAIL_WAVE, rep->particle = i;
    }
    rep->kinetic = ke;
    rep->max_speed = vmax;
    rep->fastest = fastest;
    rep->c_max = cmax;
}


/* ---- the step ----------------------------------------------------------------- */

/* One SPH step: the phases in order (the file's header lists them with
 * their equations). A phase reads what the ones before it left in
 * struct sph_state and the particles; a failed plugin stress ends the step
 * early with rep naming the particle, for the guard. */
static hearth_status sph_step(hearth_scene *s, double dt, step_report *rep, hearth_error *err) {
    const int n = s->ps.n;
    memset(rep, 0, sizeof *rep);
    rep->particle = -1;
    rep->fastest = -1;
    rep->mover = -1;
    hearth_status e = ensure(s, n > 0 ? n : 1, err);
    if (!e) e = sph_water_ensure(s, n > 0 ? n : 1, err); /* only with water or latent_heat */
    if (!e) e = sph_hourglass_ensure(s, n > 0 ? n : 1, err); /* only with sph.hourglass */
    if (e) return e;
    struct sph_state *st = s->sph;
    if (st->n != n) /* particles added or removed since the last step: final densities start over */
        for (int i = 0; i < n; i++) {
            st->rhof[i] = st->Tprev[i] = NAN;
            if (st->gasleft) st->gasleft[i] = NAN, st->outer[i] = 0;
        }
    st->valid = 0;
    if (n == 0) {
        st->n = 0;
        return HEARTH_OK;
    }
    sph_walls_begin(s, s->t);
    phase_predrift(s, dt);
    if ((e = phase_neighbours(s, err))) return e;
    if ((e = phase_density(s, err))) return e;
    if ((e = sph_pairs_prepare(s, err))) return e;
    sph_kinematics(s);
    phase_pressure(s);
    if (phase_stress(s, dt, rep)) return HEARTH_OK; /* the guard reads rep */
    sph_artificial_stress(s);
    sph_forces(s, dt);
    sph_hourglass(s, dt);
    /* the oven's heat enters there (sph_outer.c). Its readers, the heat, the water's evaporation, browning's face
     * temperatures and the "boundary" field, each come with the flags column (scene.c's temperature, water.c's
     * water): a scene with none of them (funnel.lua: 22% of its run) pays nothing for it (#18, helper userfix6) */
    if (s->ps.enabled & (1u << PC_FLAGS)) sph_outer_surface(s);
    if (water_active(s)) sph_water_prepare(s); /* the saturations the water's pairs read in the heat's walk */
    sph_heat_rates(s); /* reads st->vc and st->sp (sph_kinematics) */
    if (water_active(s)) sph_water_rates(s); /* after the heat: the latent sink takes from st->dT */
    sph_xsph(s);
    sph_fields_advance(s, dt); /* sph_heat.c */
    phase_drift(s, dt, rep);
    sph_walls_end(s, dt);
    st->n = n;
    st->valid = 1;
    return HEARTH_OK;
}

const double *sph_particle_values(const hearth_scene *s, const char *which) {
    const struct sph_state *st = s->sph;
    if (!st || !st->valid || st->n != s->ps.n) return NULL;
    if (!strcmp(which, "density")) return st->rho;
    if (!strcmp(which, "pressure")) return st->prs;
    if (!strcmp(which, "h")) return st->h;
    if (!strcmp(which, "gasleft")) return st->gasleft; /* NULL unless sph.surface_vent (sph_gas.c's vent()) */
    if (!strcmp(which, "surface")) return st->surf;
    if (!strcmp(which, "outer")) return s->ps.enabled & (1u << PC_FLAGS) ? st->outer : NULL; /* made then (sph_step) */
    if (!strcmp(which, "surface_temperature")) /* made for browning.c alone: in a scene that browns (sph_heat.c) */
        return s->def.browning && (s->ps.enabled & (1u << PC_TEMPERATURE)) ? st->ts : NULL;
    return NULL;
}

/* What ensure() and the neighbour lists keep per particle: the ARRAYS
 * doubles and the sort's key and order, each with ensure's 1/4 margin; the
 * lists' offsets, the water's doubles when it is live, and per entry for the neighbours within the support
 * h = h_factor V0^(1/dim) (the lattice points of a disc or ball of radius h,
 * with the 1/4 margin) its index, its pair slot (an int) and its pair terms
 * (dim + 1 doubles; sph_pairs_prepare). Adaptive h (sph.adaptive_h) may grow the
 * lists past this. */
static double sph_bytes_per_particle(const hearth_scene *s) {
#define COUNT(a, k) +(k)
    const double doubles = 0 ARRAYS(COUNT) + (s->def.browning ? 1 : 0) /* ts, in a scene that browns */
                           + (s->def.sph.surface_vent ? 1 : 0);         /* gasleft, in a scene that vents */
#undef COUNT
    const double hf = s->def.sph.h_factor;
    const double nb = s->def.dim == 3 ? 4.0 / 3.0 * SPH_PI * hf * hf * hf : SPH_PI * hf * hf;
    const double entry = 2 * sizeof(int) + (s->def.dim + 1) * sizeof(double);
    const double water = sph_water_live(s) ? SPH_WATER_ARRAYS : 0; /* sph_water_ensure's, with the same margin */
    const double hg = sph_hourglass_doubles(s); /* sph_hourglass_ensure's, likewise */
    return 1.25 * ((doubles + water + hg) * sizeof(double) + 2 * sizeof(int)) + sizeof(int) + 1.25 * nb * entry;
}

/* No grid, so no margin: particles may fill the whole box. */
static void sph_region(const hearth_scene *s, double lo[3], double hi[3]) {
    for (int d = 0; d < 3; d++) lo[d] = s->def.lo[d], hi[d] = s->def.hi[d];
}

const solver sph_solver = {
    .name = "sph",
    .check = sph_check_def,
    .material_added = sph_material_added,
    .stable_dt = sph_stable_dt,
    .step = sph_step,
    .free = sph_free,
    .region = sph_region,
    .bytes_per_particle = sph_bytes_per_particle,
    .particle_values = sph_particle_values,
    /* temperature from the heat field, porosity from plastic_J (phase_stress); the water field
     * (sph_water.c) is not handed to plugins as their point's saturation */
    .supplies = HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_POROSITY,
    .can_checkpoint = 0, /* its options and final densities (eq. 3.52) are not in the format yet */
    .uses_grid = 0,      /* neighbours come from its own cell list (sph_neighbours.c) */
};
