/* transport.h: one particle pass that applies the heat conduction and water
 * flux operators on the grid (Ding et al. 2019 §6.2-6.3). See transport.c. */
#ifndef HEARTH_TRANSPORT_H
#define HEARTH_TRANSPORT_H

struct hearth_scene;

typedef struct transport_pass {
    int heat_in;  ///< grid channel the heat operator reads (node temperature or CG direction), -1: no heat
    int heat_out; ///< channel that accumulates (L x)_i
    int heat_src; ///< channel that accumulates the boundary and expansion sources, -1: none;
                  ///< heat_out itself: it takes (L x)_i - src_i, one scatter fewer
    int water;    ///< also the Fick flux and evaporation into CH_DMW (and water momentum)
    double dt;    ///< the step, for the water mass change
} transport_pass;

/// One coloured pass over the particle blocks. Nodes must hold temperature
/// (CH_T) and saturation (CH_SW) already; boundary coefficients and areas
/// come from thermal.c and boundary.c.
void transport_apply(struct hearth_scene *s, const transport_pass *tp);
#endif
