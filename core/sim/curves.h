/* curves.h: parameters that are functions of temperature (piecewise linear),
 * evaluated by the core so plugins see plain numbers. */
#ifndef HEARTH_CURVES_H
#define HEARTH_CURVES_H

typedef struct curve {
    int param;        /* schema index */
    int n;            /* points */
    double *T, *v;    /* T ascending (degrees C) */
    int irreversible; /* evaluate at the highest temperature reached */
} curve;

/// Value at temperature T: linear between points, constant beyond the ends.
double curve_eval(const curve *c, double T);
#endif
