/* physics_constants.h: the physical constants more than one field uses, each
 * once (CODATA 2018 exact values): kelvin offset, the molar gas constant and the
 * Stefan-Boltzmann constant (the oven walls' radiation, fields/thermal.h). */
#ifndef HEARTH_PHYSICS_CONSTANTS_H
#define HEARTH_PHYSICS_CONSTANTS_H

#define KELVIN 273.15     /* degC to K */
#define R_GAS 8.314462618 /* J/(mol K) */
#define SIGMA_SB 5.670374419e-8 /* Stefan-Boltzmann constant, W/(m^2 K^4) (exact from h, c, k_B) */

#endif
