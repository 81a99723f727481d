/* mixing.h: dynamic mixing ratios of a mixture material (Nagasawa et al.
 * 2019 §6, eq. 43-44). Runs only when the scene holds a mixture. */
#ifndef HEARTH_MIXING_H
#define HEARTH_MIXING_H
#include "hearth/hearth.h"
#include "material.h" /* MIX_MAX */

struct hearth_scene;

/// Does the scene hold a mixture material?
int mixing_active(const struct hearth_scene *s);
/// After the sort, before P2G: each mixture particle's dynamic ratios are the
/// grid average of its neighbours' initial ratios (eq. 43, 44).
hearth_status mixing_update(struct hearth_scene *s, hearth_error *err);
/// Initial (and dynamic) ratios of mixture particles [from, to), normalised; NULL: the first
/// constituent. Their masses follow the blend's density.
hearth_status mixing_set_ratios(struct hearth_scene *s, int from, int to, const double *ratios, hearth_error *err);
#endif
