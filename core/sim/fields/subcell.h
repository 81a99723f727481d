/* subcell.h: the sub-cell heat exchange among dried particles (issue #18;
 * subcell.c has the reasons). */
#ifndef HEARTH_SUBCELL_H
#define HEARTH_SUBCELL_H
#include "hearth/hearth.h"

struct hearth_scene;

/// With the scene's latent_heat, on a step that updates heat (MPM, between
/// the heat solve and G2P): each dried particle's step-start temperature moves
/// toward its nodes' mean over the dried particles alone, conserving sum m
/// alpha(w) theta exactly node by node; fdt is the fields' time (s). Uses the
/// grid channels CH_CG_P and CH_B as scratch (dead after thermal_finish).
/// Nothing changes where no particle has dried. Fails only on an MPI slab
/// exchange's allocation.
hearth_status subcell_exchange(struct hearth_scene *s, double fdt, hearth_error *err);
/// Whether particle i takes part in the exchange as dried (moisture ratio
/// under 0.01, not held at a temperature, the scene's latent_heat on with
/// water): the one test of "dried" that subcell.c and thermal.c's tray
/// contact (find_boundary) share.
int subcell_dried(const struct hearth_scene *s, int i);
#endif
