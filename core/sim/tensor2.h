/* tensor2.h: the 2x2 in-plane tensors of a 2D (plane strain) MPM scene.
 *
 * A 2D MPM store keeps C and F as their four in-plane entries, row-major
 * [xx, xy, yx, yy] (particles.h, ps->t2). Plane strain: the velocity has no z
 * component and no gradient along z, so C's z row and column are 0 and F
 * stays block diagonal with F_zz = 1 (F is the total deformation gradient:
 * a plastic law's out-of-plane stretch lives in its own state, never in F).
 * t2_embed gives the 3x3 a plugin or a probe takes; everything the core does
 * with the in-plane block alone is here. Header-only: P2G inlines it. */
#ifndef HEARTH_SIM_TENSOR2_H
#define HEARTH_SIM_TENSOR2_H

/// out = the 3x3 with a's in-plane block, zz on the diagonal and 0 elsewhere.
static inline void t2_embed(const double a[4], double zz, double out[9]) {
    out[0] = a[0], out[1] = a[1], out[2] = 0.0;
    out[3] = a[2], out[4] = a[3], out[5] = 0.0;
    out[6] = 0.0, out[7] = 0.0, out[8] = zz;
}

/// The in-plane block of a 3x3.
static inline void t2_of_t3(const double A[9], double a[4]) {
    a[0] = A[0], a[1] = A[1], a[2] = A[3], a[3] = A[4];
}

/// det of the 2x2 (= det of its embedding with F_zz = 1).
static inline double t2_det(const double a[4]) { return a[0] * a[3] - a[1] * a[2]; }

/// Fn = (I + dt C) F, the MPM update of F (Fn must not alias F).
static inline void t2_advance(const double C[4], const double F[4], double dt, double Fn[4]) {
    Fn[0] = F[0] + dt * (C[0] * F[0] + C[1] * F[2]);
    Fn[1] = F[1] + dt * (C[0] * F[1] + C[1] * F[3]);
    Fn[2] = F[2] + dt * (C[2] * F[0] + C[3] * F[2]);
    Fn[3] = F[3] + dt * (C[2] * F[1] + C[3] * F[3]);
}
#endif
