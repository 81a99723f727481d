/* params.h: checking user parameters against a plugin's schema. */
#ifndef HEARTH_PARAMS_H
#define HEARTH_PARAMS_H
#include "hearth/hearth.h"

/// Fill out[] (schema order) from defaults and the given name/value pairs.
/// Unknown names suggest the nearest valid one; values outside [min,max] give the range and unit.
hearth_status params_resolve(const hearth_material *m, const char *const *names, const double *values, int n,
                             double *out, hearth_error *err);
/// Index of a parameter by name, or -1.
int params_index(const hearth_material *m, const char *name);
/// The candidate closest to word by edit distance (NULL when nothing is close).
const char *params_nearest(const char *word, const char *const *candidates, int n);
#endif
