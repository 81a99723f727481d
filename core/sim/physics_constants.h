/* physics_constants.h: the physical constants more than one field uses, each
 * once (CODATA 2018 exact values): kelvin offset and the molar gas constant. */
#ifndef HEARTH_PHYSICS_CONSTANTS_H
#define HEARTH_PHYSICS_CONSTANTS_H

#define KELVIN 273.15     /* degC to K */
#define R_GAS 8.314462618 /* J/(mol K) */

#endif
