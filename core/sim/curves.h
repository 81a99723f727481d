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
/// Inline: P2G evaluates each curve of a material for every particle, every step.
static inline double curve_eval(const curve *c, double T) {
    if (!(T > c->T[0])) return c->v[0]; /* NaN temperature reads as the first point */
    if (T >= c->T[c->n - 1]) return c->v[c->n - 1];
    int lo = 0, hi = c->n - 1;
    if (c->n <= 16) { /* a scan: the usual few-point curve, evaluated per particle per step */
        hi = 1;
        while (c->T[hi] <= T) hi++;
        lo = hi - 1;
    } else { /* bisection: long tables */
        while (hi - lo > 1) {
            int mid = (lo + hi) / 2;
            if (c->T[mid] <= T) lo = mid;
            else hi = mid;
        }
    }
    const double a = (T - c->T[lo]) / (c->T[hi] - c->T[lo]);
    return c->v[lo] + a * (c->v[hi] - c->v[lo]);
}
#endif
