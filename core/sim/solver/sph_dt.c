/* sph_dt.c: the SPH solver's stable time step, the smallest of the CFL
 * limit cfl dx / (speed + sound speed) (as MPM's, so the guard's checks
 * hold), the viscous limit dt_viscous h^2 / nu, the force limit
 * dt_force sqrt(h / |a|), the heat limits (sph_heat.c) and the water's
 * (sph_water.c), capped by dt_max.
 * Before the first step the sound speed comes from the materials'
 * wave_speed; after it, from the step's report (s->c_max: c0, or Tait's
 * sound speed at the particle's density where eq. 3.52 lowered the density
 * it is taken against, or a bubble's gas's own with sph.gas_pressure:
 * sph_gas.c sph_gas_sound_speed; sph.c's signal_speed says why). h is the raw
 * particles' (h_factor V0^(1/dim)): a bubble grown by sph.gas_law has a
 * larger h, so hmin stays on the safe side. */
#include <math.h>

#include "material.h"
#include "plugins.h"
#include "sph_state.h"

double sph_stable_dt(const hearth_scene *s) {
    const hearth_sph_def *o = &s->def.sph;
    const particles *ps = &s->ps;
    const int dim = s->def.dim;
    double c = s->c_max;
    double dt = INFINITY, pscratch[SCENE_MAX_PARAMS];
    const double *T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL;
    double hmin = INFINITY, numax = 0, rhomin = INFINITY;
    const double w = s->step == 0 ? sph_dough_water_share(s) : 0; /* sph.dough_water's share, for the first step */
    for (int i = 0; i < ps->n; i++) {
        const int m = pcoli(ps, PC_MAT)[i];
        const material_slot *ms = &s->mats.slot[m];
        const double *p = T ? material_params(&s->mats, &s->ps, m, i, pscratch) : ms->params;
        const double V0 = pcold(ps, PC_VOL0)[i], h = o->h_factor * (dim == 3 ? cbrt(V0) : sqrt(V0));
        if (h < hmin) hmin = h;
        if (p[ms->density_index] < rhomin) rhomin = p[ms->density_index];
        const int vi = s->sph->visc_index[m]; /* a particle has a material, so the state exists */
        if (vi >= 0) {
            const double nu = p[vi] / p[ms->density_index];
            if (nu > numax) numax = nu;
        }
        if (s->step == 0) { /* before the first step the sound speed comes from the materials */
            plugin_call_enter(ms->m, "wave_speed");
            const double ci = ms->m->wave_speed(p, ms->m->state_size > 0 ? pcold(ps, PC_STATE) + (size_t)i * ps->state_stride : NULL);
            plugin_call_leave();
            if (ci > c) c = ci;
            /* a bubble whose stiffness is its gas's (sph.gas_pressure) outruns the raw dough's waves */
            const double cg = T ? sph_gas_sound_speed(o, ms->core[CP_BUBBLE], p[ms->density_index], T[i], w) : 0;
            if (cg > c) c = cg;
        }
    }
    if (!isfinite(hmin)) hmin = s->def.dx;
    const double sp = s->max_speed + c;
    if (sp > 0) dt = s->def.cfl * s->def.dx / sp;
    if (numax > 0) dt = fmin(dt, o->dt_viscous * hmin * hmin / numax);
    if (s->sph && s->sph->amax > 0) dt = fmin(dt, o->dt_force * sqrt(hmin / s->sph->amax));
    dt = fmin(dt, sph_heat_stable_dt(s, hmin, rhomin));
    dt = fmin(dt, sph_water_stable_dt(s, hmin, rhomin));
    if (s->def.dt_max > 0 && dt > s->def.dt_max) dt = s->def.dt_max;
    if (isinf(dt)) dt = s->def.cfl * s->def.dx;
    return dt * s->dt_scale;
}
