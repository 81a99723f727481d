/* flip_bound.h: FLIP's temperature increment held within each particle's local bounds (fields/flip_bound.c). */
#ifndef HEARTH_FLIP_BOUND_H
#define HEARTH_FLIP_BOUND_H
#include "hearth/hearth.h"

struct hearth_scene;

/// After thermal_finish (CH_T the new node temperatures, CH_T0 the step start's)
/// and before subcell.c and G2P: the particles whose FLIP update (eq. 21) would
/// leave their local bounds move, before G2P adds the increment, toward the
/// step start's node field at every node they touch, and so do the other
/// particles on those nodes (exactly conserving; flip_bound.c says why). A scene
/// where no particle would leave its bounds is untouched, to the bit. Uses
/// CH_CG_P as scratch. Fails only on MPI slabs (the halo exchange out of memory).
/// Before subcell.c moves the dried particles: the step's range of the particles' temperatures and the sources.
void flip_bound_prepare(struct hearth_scene *s, double fdt);
hearth_status flip_bound_apply(struct hearth_scene *s, hearth_error *err);

#endif
