/* params.h: checking user parameters against a plugin's schema. */
#ifndef HEARTH_PARAMS_H
#define HEARTH_PARAMS_H
#include "hearth/hearth.h"

/* The field properties every material has, besides its plugin's parameters. */
enum {
    CP_CONDUCTIVITY, CP_SPECIFIC_HEAT, CP_EXPANSION, CP_REFERENCE_T,
    CP_GAS_RATE, CP_REACTION_T, CP_REACTION_WIDTH, CP_POROSITY0,
    CP_SATURATION0, CP_WATER_DIFFUSIVITY, CP_EVAPORATION, CP_WATER_STIFFNESS, CP_WATER_DENSITY,
    CP_BUBBLE, /* SPH bubble particles (Rodriguez-Arenas §3.3.3) */
    CP_DRY_CONDUCTIVITY, /* conduction of the dried material (material_conductivity, material.h); last, so
                          * checkpoints before version 7 read the others in place */
    CP_DRY_SPECIFIC_HEAT, /* heat capacity of the dried material (material_specific_heat, material.h); last, so
                           * checkpoints before version 8 read the others in place */
    CP_AMBIENT_PRESSURE,  /* the pores' gas stands at the atmosphere (gas.h, gas_tau_ambient); with */
    CP_OPEN_TEMPERATURE,  /* ... the temperature its cells open at: both last, so checkpoints before 10 read the others */
    CP_GAS_RATE_2,        /* a second CO2 share, eq. 14's bell again with its own amount, centre and width (gas.c): */
    CP_REACTION_T_2,      /* ... its centre theta_r and */
    CP_REACTION_WIDTH_2,  /* ... its width dtheta; the three last, so checkpoints before 12 read the others */
    CP_GAS_AMOUNT,        /* the first share's reactant: the most CO2 it makes (mol/kg; 0 = no limit; gas.h's */
    CP_GAS_AMOUNT_2,      /* ... gas_share_capped), and the second's; both last, so checkpoints before 13 read the others */
    CP_COUNT
};

/// Fill out[] (plugin schema order) and core[] (CP_* order) from defaults and
/// the given name/value pairs. Unknown names suggest the nearest valid one;
/// values outside [min,max] give the range and unit.
hearth_status params_resolve(const hearth_material *m, const char *const *names, const double *values, int n,
                             double *out, double *core, hearth_error *err);
/// Index of a parameter by name, or -1.
int params_index(const hearth_material *m, const char *name);
/// The candidate closest to word by edit distance (NULL when nothing is close).
const char *params_nearest(const char *word, const char *const *candidates, int n);
#endif
