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

/* W(r, h), eq. 3.9 */
static inline double sph_w(int dim, double r, double h) {
    const double q = 2.0 * r / h;
    if (q >= 2.0) return 0.0;
    const double f = q < 1.0 ? 1.0 - 1.5 * q * q + 0.75 * q * q * q : 0.25 * (2.0 - q) * (2.0 - q) * (2.0 - q);
    return sph_sigma(dim, h) * f;
}

/* dW/dr (<= 0), eq. 3.11 times dq/dr. The gradient of W(x_i - x_j) with
 * respect to x_i is dW/dr (x_i - x_j) / r. */
static inline double sph_dw(int dim, double r, double h) {
    const double q = 2.0 * r / h;
    if (q >= 2.0) return 0.0;
    const double f = q < 1.0 ? -3.0 * q + 2.25 * q * q : -0.75 * (2.0 - q) * (2.0 - q);
    return sph_sigma(dim, h) * f * 2.0 / h;
}

/* Laplacian of the cubic spline: W'' + (d - 1) W' / r (for the colour field, eq. 3.28). */
static inline double sph_lap_w(int dim, double r, double h) {
    const double q = 2.0 * r / h;
    if (q >= 2.0) return 0.0;
    const double sg = sph_sigma(dim, h), k = 2.0 / h;
    if (r <= 0) return -3.0 * dim * sg * k * k; /* the limit r -> 0: W''(0) = W'(r)/r = -3 sg k^2 */
    const double f1 = q < 1.0 ? -3.0 * q + 2.25 * q * q : -0.75 * (2.0 - q) * (2.0 - q);
    const double f2 = q < 1.0 ? -3.0 + 4.5 * q : 1.5 * (2.0 - q); /* eq. 3.12 (whose printed 1.5 (2 - 1) is (2 - q)) */
    return sg * (f2 * k * k + (dim - 1) * f1 * k / r);
}

/* Laplacian of the viscosity kernel, eq. 3.8 (>= 0 inside the support). */
static inline double sph_lap_visc(int dim, double r, double h) {
    if (r >= h) return 0.0;
    return dim == 3 ? 45.0 / (SPH_PI * h * h * h * h * h * h) * (h - r) : 40.0 / (SPH_PI * h * h * h * h * h) * (h - r);
}
#endif
