/* mixing.h: dynamic mixing ratios of a mixture material (Nagasawa et al.
 * 2019 §6, eq. 43-44). Runs only when the scene holds a mixture. */
#ifndef HEARTH_MIXING_H
#define HEARTH_MIXING_H
#include "hearth/hearth.h"

struct hearth_scene;

#define MIX_MAX 8 /* constituents of a mixture, and the width of the ratio columns */

/// Does the scene hold a mixture material?
int mixing_active(const struct hearth_scene *s);
/// After the sort, before P2G: each mixture particle's dynamic ratios are the
/// grid average of its neighbours' initial ratios (eq. 43, 44).
hearth_status mixing_update(struct hearth_scene *s, hearth_error *err);
/// Initial (and dynamic) ratios of mixture particles [from, to), normalised; NULL: the first
/// constituent. Their masses follow the blend's density.
hearth_status mixing_set_ratios(struct hearth_scene *s, int from, int to, const double *ratios, hearth_error *err);
/// The blend of the mixture's constituents at particle i's dynamic ratios, into out.
void mixing_params(const struct hearth_scene *s, int mat, int i, double *out);
#endif
