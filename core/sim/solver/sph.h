/* sph.h: the SPH solver of Rodriguez-Arenas 2011 (ch. 3-4), a second way to
 * step a scene (solver = HEARTH_SOLVER_SPH). It shares the scene's
 * particles, materials (plugins), colliders, probes and outputs with MPM;
 * everything SPH keeps for itself lives in struct sph_state. */
#ifndef HEARTH_SIM_SPH_H
#define HEARTH_SIM_SPH_H
#include "scene.h"

struct sph_state;

/* The scene reaches the step, its stable dt (CFL as MPM's, cfl dx / (speed
 * + sound speed); viscous, dt_viscous rho h^2 / mu; force, dt_force
 * sqrt(h / |a|); heat), the state's free and the region particles may fill
 * through sph_solver (solver.h). */

/// Check the SPH options of a scene definition (sph_solver.check).
hearth_status sph_check_def(const hearth_scene_def *d, hearth_error *err);

/// Per-particle results of the last step, in the scene's current particle
/// order; NULL before the first step or after particles were added/removed.
/// which: "density", "pressure", "h", "surface" (0/1, the colour field's), "outer" (0/1, the
/// body's outer surface, where the oven heats: sph_outer.c; NULL in a scene with no temperature, water or fixed
/// body, where nothing reads it and it is not made), "surface_temperature" (degC: an outer particle's
/// face temperature by the oven's air-film closure, NaN for the rest; NULL without the temperature field or in a
/// scene that does not brown, where nothing reads them and they are not made; sph_heat.c's
/// sph_surface_temperatures, which browning.c reads).
const double *sph_particle_values(const hearth_scene *s, const char *which);

/// A bubble particle's gas volume V_b at temperature T (degC) for its initial
/// volume vb0 (the material's `bubble`, eq. 3.50): the ideal gas in Kelvin with
/// the water vapour of sph.bubble_vapour (eq. 2.42-2.43), at most
/// vb0 sph.bubble_vmax. What sph.gas_law's rest density rho0 / V_b uses.
double sph_bubble_volume(const hearth_sph_def *o, double vb0, double T);
#endif
