/* curves.h: parameters that are functions of temperature (piecewise linear),
 * evaluated by the core so plugins see plain numbers; and factors over the
 * moisture ratio that multiply them (a crust stiffens as it dries, #18).
 *
 * A moisture curve's abscissa is X/X_0, the particle's water mass over its
 * initial water mass (the drying kinetics' moisture ratio, dry basis: the
 * dry solids do not change), and its values are dimensionless factors on
 * the parameter (its value or its temperature curve's). A factor rather than
 * a second value: the dough's tau_y already follows temperature (Ding et al.
 * Fig. 8), and a dried crust is that dough made stiffer, so the two
 * multiply. Rejected: a curve over the saturation s itself, which ties a
 * preset to the saturation a scene gives its dough (s = 0.22 for a 45 %
 * water dough of density 500, 0.47 unproofed), while X/X_0 is 1 for any raw
 * dough. */
#ifndef HEARTH_CURVES_H
#define HEARTH_CURVES_H

/* What a curve is a function of (curve.of). */
enum { CURVE_OF_TEMPERATURE = 0, CURVE_OF_MOISTURE = 1 };

typedef struct curve {
    int param;        /* schema index */
    int n;            /* points */
    double *T, *v;    /* T ascending: degrees C, or X/X_0 for a moisture curve (then v are factors) */
    int irreversible; /* at the highest temperature reached; a moisture curve at the driest state reached */
    int of;           /* CURVE_OF_*; a material's temperature curves come before its moisture curves */
} curve;

/// Value at temperature (or moisture ratio) T: linear between points, constant beyond the ends.
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

/// curve_eval at x[0], ..., x[n - 1] into out: the same values, each point's
/// segment tried first where the last point's was (the particles of a block
/// lie close together, and so do their temperatures). The curve's abscissae
/// strictly increase (material.c checks), so T[lo] <= T < T[lo + 1] holds for
/// one segment only: the one curve_eval's scan finds.
static inline void curve_eval_column(const curve *c, const double *x, int n, double *out) {
    if (c->n > 16) {
        for (int j = 0; j < n; j++) out[j] = curve_eval(c, x[j]);
        return;
    }
    const double *Tc = c->T, *v = c->v, first = Tc[0], last = Tc[c->n - 1];
    int lo = 0;
    for (int j = 0; j < n; j++) {
        const double T = x[j];
        if (!(T > first)) {
            out[j] = v[0];
            continue;
        }
        if (T >= last) {
            out[j] = v[c->n - 1];
            continue;
        }
        if (!(Tc[lo] <= T && T < Tc[lo + 1])) {
            int hi = 1;
            while (Tc[hi] <= T) hi++;
            lo = hi - 1;
        }
        const double a = (T - Tc[lo]) / (Tc[lo + 1] - Tc[lo]);
        out[j] = v[lo] + a * (v[lo + 1] - v[lo]);
    }
}
#endif
