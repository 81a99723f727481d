/* small_nodes.h: forward Euler's heat update with the air surface's small
 * nodes merged into their fullest neighbours (small_nodes.c has the reasons). */
#ifndef HEARTH_SMALL_NODES_H
#define HEARTH_SMALL_NODES_H

struct hearth_scene;

/// One forward Euler update of the nodes' temperature, CH_T += dt (B - R) / c,
/// where a node with under SMALL_NODE of its fullest neighbour's heat capacity
/// takes that neighbour's increment and gives it its source and capacity (heat
/// conserved to round-off). Reads CH_B, CH_R, CH_HC, CH_CG_R (the nodes' volume
/// fraction) and the held nodes; uses CH_CG_P as scratch. Deterministic at any
/// thread count.
void small_nodes_explicit_step(struct hearth_scene *s, double dt);
#endif
