/* browning.h: the crust's colour from each particle's temperature and water
 * history (Zanoni, Peri & Bruno 1995; browning.c has the reasons). */
#ifndef HEARTH_BROWNING_H
#define HEARTH_BROWNING_H

struct hearth_scene;

/* Zanoni et al. (1995), instant heating of dried crumb at 140-250 degC: the
 * colour difference Delta E to the raw dough follows first-order kinetics
 * toward Delta E_inf = 52 (the burnt sample) with an Arrhenius rate,
 * k0 = 42000 1/s and Ea = 64151 J/mol. */
#define BROWNING_DE_INF 52.0
#define BROWNING_K0 42000.0
#define BROWNING_EA 64151.0
#include "physics_constants.h"
#define BROWNING_R R_GAS

/// First-order rate k (1/s) at temperature T (degrees C), times scale
/// (hearth_scene_def.browning_scale); 0 at or below absolute zero.
double browning_rate(double T, double scale);
/// The fraction of the dry rate a particle of saturation sat browns at,
/// initial saturation sat0: 1 - sat/sat0 within [0, 1]; 1 for a body that
/// started dry (sat0 at water.c's floor).
double browning_water_factor(double sat, double sat0);
/// One exact step of db/dt = k f (1 - b) at fixed k f: b <- 1 - (1 - b) exp(-k f dt).
double browning_advance(double b, double kf, double dt);
/// Advance every particle's PC_BROWNING by dt from its present temperature
/// (and saturation, when the water field is live). The column must exist.
void browning_step(struct hearth_scene *s, double dt);
/// The temperature (degrees C) and saturation particle i browned at in the last step that stood: on the oven's air
/// surface (MPM) its surface's, by the oven's and the evaporation's closures; at an SPH outer particle its face's
/// temperature and its own saturation; else its own. sat is NaN without the water field. The probes' fields
/// browning_temperature and browning_saturation (probe.c) read it.
void browning_reading(const struct hearth_scene *s, int i, double *T, double *sat);
#endif
