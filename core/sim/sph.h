/* sph.h: the SPH solver of Rodriguez-Arenas 2011 (ch. 3-4), a second way to
 * step a scene (solver = HEARTH_SOLVER_SPH). It shares the scene's
 * particles, materials (plugins), colliders, probes and outputs with MPM;
 * everything SPH keeps for itself lives in struct sph_state. */
#ifndef HEARTH_SIM_SPH_H
#define HEARTH_SIM_SPH_H
#include "scene.h"

struct sph_state;

/// One SPH step of length dt (the scene's step loop calls it instead of mpm_step).
hearth_status sph_step(hearth_scene *s, double dt, step_report *rep, hearth_error *err);
/// The stable step: CFL (as MPM: cfl dx / (speed + sound speed)), viscous
/// (dt_viscous rho h^2 / mu), force (dt_force sqrt(h / |a|)) and heat limits.
double sph_stable_dt(const hearth_scene *s);
/// Check the SPH options of a scene definition.
hearth_status sph_check_def(const hearth_scene_def *d, hearth_error *err);
void sph_free(struct sph_state *st);

/// Per-particle results of the last step, in the scene's current particle
/// order; NULL before the first step or after particles were added/removed.
/// which: "density", "pressure", "h", "browning", "surface" (0/1).
const double *sph_particle_values(const hearth_scene *s, const char *which);
#endif
