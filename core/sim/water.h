/* water.h: water in the mixture, Ding et al. 2019 §3.2, §5.5, §6.2. Runs only
 * when the water field is live. */
#ifndef HEARTH_WATER_H
#define HEARTH_WATER_H
#include "hearth/hearth.h"

struct hearth_scene;

/* Saturation never reaches zero (Ding et al. §3: "our mixture will never be
 * completely dry"): particles keep at least this much. */
#define WATER_SATURATION_FLOOR 1e-4

/// Is the water field live?
int water_active(const struct hearth_scene *s);
/// Does a material ask for water (diffusivity, evaporation, water pressure, or a plugin that needs saturation)?
int water_material_wants(const struct hearth_scene *s, int mat);
/// Turn the water field on; particles that have none get their material's initial saturation.
hearth_status water_enable(struct hearth_scene *s, hearth_error *err);
/// Give particles [from, to) saturation sat (NaN: their material's), floored.
void water_init_particles(struct hearth_scene *s, int from, int to, double sat);
/// Largest explicit water step (s), INFINITY when inactive.
double water_dt_limit(const struct hearth_scene *s);
/// Saturation of particle i (from its water mass and current volume).
double water_saturation(const struct hearth_scene *s, int i);
/// After P2G and the boundary search, before the momentum grid update:
/// grid water mass and saturation (eq. 15, 18), Fick flux and evaporation
/// (eq. 22, 25), the particle water update (eq. 19-20), wet colliders, and
/// with def.water_momentum the relative water momentum (eq. 26-27).
/// Particle positions must still be those of P2G.
void water_update(struct hearth_scene *s, double dt);
/// Total water in the particles (kg, or kg/m in 2D).
double water_total(const struct hearth_scene *s);
#endif
