/* boundary.h: the boundary particles of Ding et al. 2019 §6.6, where oven
 * air meets the material (heat exchange, evaporation). */
#ifndef HEARTH_BOUNDARY_H
#define HEARTH_BOUNDARY_H
#include "hearth/hearth.h"

struct hearth_scene;

/// Does anything in the scene act through the air boundary (an oven, evaporation)?
int boundary_needed(const struct hearth_scene *s);
/// After P2G (node masses): fill s->bnd_area with each particle's share of the
/// air surface (m^(dim-1); 0 inside) and set PF_BOUNDARY on those particles
/// (all zero when nothing needs the boundary). Runs when heat or water is live.
/// Uses the grid channels CH_CG_R and CH_CG_P as scratch.
hearth_status boundary_find(struct hearth_scene *s, hearth_error *err);
#endif
