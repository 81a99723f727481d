/* boundary.h: the boundary particles of Ding et al. 2019 §6.6, where oven
 * air meets the material (heat exchange, evaporation). */
#ifndef HEARTH_BOUNDARY_H
#define HEARTH_BOUNDARY_H
#include "hearth/hearth.h"

struct hearth_scene;

/* The boundary's own state (boundary.c), held by value in the scene as
 * s->boundary. Written only by boundary_find; thermal.c and transport.c read
 * area. */
typedef struct boundary_state {
    double *area;          /* per particle: its share of the air surface (m^(dim-1)), 0 away from it */
    double *depth;         /* per particle with area, an oven or evaporation live: the depth (m) below the surface at
                            * which the grid samples its temperature and saturation (boundary.c); 0 elsewhere.
                            * Same capacity as area. */
    int area_cap;
    unsigned char *blocks; /* two flags per active grid block (boundary.c); the first: a node of it passes surface to particles */
    int blocks_cap;
} boundary_state;

/* The depth (grid units) at which the grid samples a flat face's outer row of
 * particles, a quarter cell in (boundary.c's D_OF_PHI, averaged over the
 * offsets): a particle whose sample is this deep or less stands for the
 * surface itself. */
#define BOUNDARY_OUTER_DEPTH 0.57

/// Empty state (allocates nothing).
void boundary_init(boundary_state *b);
/// Free the arrays; b is empty afterwards (boundary_init's state).
void boundary_free(boundary_state *b);

/// Does anything in the scene act through the air boundary (an oven, evaporation)?
int boundary_needed(const struct hearth_scene *s);
/// After P2G (node masses, and node volumes sum w_ip J V_0 in CH_CG_R): fill s->boundary.area with each particle's share of the
/// air surface (m^(dim-1); 0 inside), s->boundary.depth with the depth of their temperature and saturation sample
/// when an oven or evaporation is live (thermal.c's and transport.c's offsets), and set PF_BOUNDARY on those particles
/// (all zero when nothing needs the boundary). Runs when heat or water is live.
/// Uses the grid channels CH_CG_R, CH_CG_P, CH_R, CH_B and CH_T0 as scratch (thermal_prepare fills them next).
hearth_status boundary_find(struct hearth_scene *s, hearth_error *err);
#endif
