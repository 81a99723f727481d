/* column_fixture.h: what the 1D column tests share (unit_drying_front.c, the
 * top under the oven's air; unit_base_contact.c, the base on a tray;
 * unit_top_column.c, the loaf's top from its start): their measuring switches
 * read from the environment, unset in the suite, and the middle column's top
 * particle. */
#ifndef HEARTH_TEST_COLUMN_FIXTURE_H
#define HEARTH_TEST_COLUMN_FIXTURE_H
#include <math.h>
#include <stdlib.h>

#include "mpm_fixture.h"

/* A measuring switch: the environment's value of name, or dflt when unset. */
static inline double knob(const char *name, double dflt) {
    const char *v = getenv(name);
    return v ? atof(v) : dflt;
}

/* The top particle of the column at x = xmid: the shallowest within dx/2 of it, or -1. */
static inline int column_top_particle(const hearth_scene *s, double xmid, double dx) {
    const double *X = pcold(&s->ps, PC_X);
    int best = -1;
    for (int i = 0; i < s->ps.n; i++)
        if (fabs(X[3 * i] - xmid) < 0.5 * dx && (best < 0 || X[3 * i + 1] > X[3 * best + 1])) best = i;
    return best;
}
#endif
