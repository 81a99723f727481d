/* sph_kernel.h: the SPH kernels of Rodriguez-Arenas 2011 (§3.1.3).
 *
 * h is the support radius (the thesis's convention, q = 2 r / h, eq. 3.10).
 * Cubic spline (eq. 3.9, 3.11): the thesis prints the 3D factor as
 * 1 / (pi h^3), which is the normalisation of the same spline written with
 * the smoothing length H = h / 2; with support h the integral is 1 only with
 * 8 / (pi h^3) (3D) and 40 / (7 pi h^2) (2D), which is what we use (checked
 * by the lattice normalisation test). The derivative of eq. 3.11 is in q;
 * dW/dr = sigma / h^d f'(q) 2 / h.
 * Viscosity kernel Laplacian (eq. 3.8, Mueller et al. 2003):
 * 45 / (pi h^6) (h - r) in 3D; its 2D form is 40 / (pi h^5) (h - r). */
#ifndef HEARTH_SPH_KERNEL_H
#define HEARTH_SPH_KERNEL_H
#include <math.h>

#define SPH_PI 3.14159265358979323846

static inline double sph_sigma(int dim, double h) {
    return dim == 3 ? 8.0 / (SPH_PI * h * h * h) : 40.0 / (7.0 * SPH_PI * h * h);
}

/* What the kernels below compute from h alone: a pair loop whose pairs
 * mostly share one h (h_ij = h_i when h_j = h_i) makes it once per particle
 * (sph_kc_of) instead of once per pair. Each kernel is written in terms of
 * it, so the two ways give the same bits. */
typedef struct sph_kc {
    double h;  /* support radius */
    double sg; /* sph_sigma(dim, h) */
    double k;  /* dq/dr = 2 / h */
    double lv; /* eq. 3.8's factor: 45 / (pi h^6) in 3D, 40 / (pi h^5) in 2D */
} sph_kc;

static inline sph_kc sph_kc_of(int dim, double h) {
    return (sph_kc){h, sph_sigma(dim, h), 2.0 / h,
                    dim == 3 ? 45.0 / (SPH_PI * h * h * h * h * h * h) : 40.0 / (SPH_PI * h * h * h * h * h)};
}

/* The pair's constants as `const sph_kc *name`: particle i's own (kci, for
 * h_i) when h_j = h_i, as h_ij = (h_i + h_j) / 2 (eq. 3.56) is then h_i
 * exactly; else made for h_ij. */
#define SPH_PAIR_KC(name, dim, kci, hi, hj)                                                                            \
    sph_kc name##_own;                                                                                                 \
    const sph_kc *name = &(kci);                                                                                       \
    if ((hj) != (hi)) {                                                                                                \
        name##_own = sph_kc_of(dim, 0.5 * ((hi) + (hj)));                                                              \
        name = &name##_own;                                                                                            \
    }

/* W(r, h), eq. 3.9 */
static inline double sph_w_kc(const sph_kc *c, double r) {
    const double q = 2.0 * r / c->h;
    if (q >= 2.0) return 0.0;
    const double f = q < 1.0 ? 1.0 - 1.5 * q * q + 0.75 * q * q * q : 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
    return c->sg * f;
}
static inline double sph_w(int dim, double r, double h) {
    const sph_kc c = sph_kc_of(dim, h);
    return sph_w_kc(&c, r);
}

/* dW/dr (<= 0), eq. 3.11 times dq/dr. The gradient of W(x_i - x_j) with
 * respect to x_i is dW/dr (x_i - x_j) / r. */
static inline double sph_dw_kc(const sph_kc *c, double r) {
    const double q = 2.0 * r / c->h;
    if (q >= 2.0) return 0.0;
    const double f = q < 1.0 ? -3.0 * q + 2.25 * q * q : -0.75 * (2.0 - q) * (2.0 - q);
    return c->sg * f * 2.0 / c->h;
}
static inline double sph_dw(int dim, double r, double h) {
    const sph_kc c = sph_kc_of(dim, h);
    return sph_dw_kc(&c, r);
}

/* Laplacian of the cubic spline: W'' + (d - 1) W' / r (for the colour field, eq. 3.28). */
static inline double sph_lap_w_kc(int dim, const sph_kc *c, double r) {
    const double q = 2.0 * r / c->h;
    if (q >= 2.0) return 0.0;
    const double sg = c->sg, k = c->k;
    if (r <= 0) return -3.0 * dim * sg * k * k; /* the limit r -> 0: W''(0) = W'(r)/r = -3 sg k^2 */
    const double f1 = q < 1.0 ? -3.0 * q + 2.25 * q * q : -0.75 * (2.0 - q) * (2.0 - q);
    const double f2 = q < 1.0 ? -3.0 + 4.5 * q : 1.5 * (2.0 - q); /* eq. 3.12 (whose printed 1.5 (2 - 1) is (2 - q)) */
    return sg * (f2 * k * k + (dim - 1) * f1 * k / r);
}
static inline double sph_lap_w(int dim, double r, double h) {
    const sph_kc c = sph_kc_of(dim, h);
    return sph_lap_w_kc(dim, &c, r);
}

/* W, dW/dr and the Laplacian of W at one r > 0, as sph_w_kc, sph_dw_kc and
 * sph_lap_w_kc give them (the same expressions), with one test of q; lap
 * may be NULL (a loop that needs no Laplacian then computes none). */
static inline void sph_w_dw_lap_kc(int dim, const sph_kc *c, double r, double *w, double *dw, double *lap) {
    const double q = 2.0 * r / c->h;
    if (q >= 2.0) {
        *w = *dw = 0.0;
        if (lap) *lap = 0.0;
        return;
    }
    double fw, f1, f2;
    if (q < 1.0) {
        fw = 1.0 - 1.5 * q * q + 0.75 * q * q * q;
        f1 = -3.0 * q + 2.25 * q * q;
        f2 = -3.0 + 4.5 * q;
    } else {
        fw = 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
        f1 = -0.75 * (2.0 - q) * (2.0 - q);
        f2 = 1.5 * (2.0 - q);
    }
    const double sg = c->sg, k = c->k;
    *w = sg * fw;
    *dw = sg * f1 * 2.0 / c->h;
    if (lap) *lap = r <= 0 ? -3.0 * dim * sg * k * k : sg * (f2 * k * k + (dim - 1) * f1 * k / r);
}

/* Laplacian of the viscosity kernel, eq. 3.8 (>= 0 inside the support). */
static inline double sph_lap_visc_kc(const sph_kc *c, double r) {
    if (r >= c->h) return 0.0;
    return c->lv * (c->h - r);
}
static inline double sph_lap_visc(int dim, double r, double h) {
    const sph_kc c = sph_kc_of(dim, h);
    return sph_lap_visc_kc(&c, r);
}
#endif
