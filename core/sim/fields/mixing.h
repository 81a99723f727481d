/* mixing.h: dynamic mixing ratios of a mixture material (Nagasawa et al.
 * 2019 §6, eq. 43-44). Runs only when the scene holds a mixture. */
#ifndef HEARTH_MIXING_H
#define HEARTH_MIXING_H
#include "hearth/hearth.h"
#include "material.h" /* MIX_MAX */

struct hearth_scene;

/* The mixture's own state (mixing.c), held by value in the scene as s->mix.
 * Only mixing.c writes it; bodies.c, probe.c, scene.c and checkpoint.c read
 * mat. */
typedef struct mixing_state {
    int mat;       /* the mixture material, -1 when none */
    double *nodes; /* its node sums, (k + 1) per node, indexed like the grid's blocks */
    size_t cap;    /* doubles */
} mixing_state;

/// No mixture (allocates nothing).
void mixing_init(mixing_state *x);
/// Free the node sums; x is empty afterwards (mixing_init's state).
void mixing_free(mixing_state *x);

/// Does the scene hold a mixture material?
int mixing_active(const struct hearth_scene *s);
/// After the sort, before P2G: each mixture particle's dynamic ratios are the
/// grid average of its neighbours' initial ratios (eq. 43, 44).
hearth_status mixing_update(struct hearth_scene *s, hearth_error *err);
/// Initial (and dynamic) ratios of mixture particles [from, to), normalised; NULL: the first
/// constituent. Their masses follow the blend's density.
hearth_status mixing_set_ratios(struct hearth_scene *s, int from, int to, const double *ratios, hearth_error *err);
#endif
