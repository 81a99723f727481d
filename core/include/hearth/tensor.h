/* hearth/tensor.h: the 3x3 helpers a material plugin needs, header-only.
 *
 * Every function is static inline and uses only <math.h>, so a plugin that
 * includes this header needs no symbol from the host process and no library
 * beyond libm: build it with `cc -shared -fPIC $(pkg-config --cflags hearth)
 * law.c -lm`. The core uses the same functions (core/sim/tensor.c wraps them
 * and adds the heavier algebra: SVD, polar, symmetric log/exp), so a plugin
 * and the solver compute a product or an eigen-decomposition bit for bit
 * alike.
 *
 * Matrices are double[9], row-major (A[3*row+col]), as in <hearth/material.h>.
 * The products write through a local temporary, so an output may alias an
 * input. Symmetric tensors kept in a plugin's per-point state are packed as
 * six doubles in the order of HEARTH_SYM_XX .. HEARTH_SYM_ZX.
 */
#ifndef HEARTH_TENSOR_H
#define HEARTH_TENSOR_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

/// Slots of a packed symmetric tensor (six doubles): the diagonal, then xy, yz, zx.
enum { HEARTH_SYM_XX, HEARTH_SYM_YY, HEARTH_SYM_ZZ, HEARTH_SYM_XY, HEARTH_SYM_YZ, HEARTH_SYM_ZX, HEARTH_SYM_COUNT };

/// A = I.
static inline void hearth_t3_identity(double A[9]) {
    for (int i = 0; i < 9; i++) A[i] = (i % 4 == 0) ? 1.0 : 0.0;
}

/// B = A.
static inline void hearth_t3_copy(const double A[9], double B[9]) {
    for (int i = 0; i < 9; i++) B[i] = A[i];
}

/// At = A^T (At may be A).
static inline void hearth_t3_transpose(const double A[9], double At[9]) {
    double T[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) T[3 * c + r] = A[3 * r + c];
    hearth_t3_copy(T, At);
}

/// C = A B.
static inline void hearth_t3_mul(const double A[9], const double B[9], double C[9]) {
    double T[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            T[3 * r + c] = A[3 * r] * B[c] + A[3 * r + 1] * B[3 + c] + A[3 * r + 2] * B[6 + c];
    hearth_t3_copy(T, C);
}

/// C = A^T B.
static inline void hearth_t3_mul_atb(const double A[9], const double B[9], double C[9]) {
    double T[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) T[3 * r + c] = A[r] * B[c] + A[3 + r] * B[3 + c] + A[6 + r] * B[6 + c];
    hearth_t3_copy(T, C);
}

/// C = A B^T.
static inline void hearth_t3_mul_abt(const double A[9], const double B[9], double C[9]) {
    double T[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            T[3 * r + c] = A[3 * r] * B[3 * c] + A[3 * r + 1] * B[3 * c + 1] + A[3 * r + 2] * B[3 * c + 2];
    hearth_t3_copy(T, C);
}

/// y = A x (y may be x).
static inline void hearth_t3_mulv(const double A[9], const double x[3], double y[3]) {
    double t[3];
    for (int r = 0; r < 3; r++) t[r] = A[3 * r] * x[0] + A[3 * r + 1] * x[1] + A[3 * r + 2] * x[2];
    y[0] = t[0];
    y[1] = t[1];
    y[2] = t[2];
}

/// det A, by cofactors of the first row.
static inline double hearth_t3_det(const double A[9]) {
    return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) + A[2] * (A[3] * A[7] - A[4] * A[6]);
}

/// tr A.
static inline double hearth_t3_trace(const double A[9]) { return A[0] + A[4] + A[8]; }

/// A:B = sum of A_ij B_ij.
static inline double hearth_t3_ddot(const double A[9], const double B[9]) {
    double d = 0.0;
    for (int i = 0; i < 9; i++) d += A[i] * B[i];
    return d;
}

/// Ainv = A^-1 by the adjugate. Returns 0, leaving Ainv untouched, when |det A| < 1e-300 or is NaN.
static inline int hearth_t3_inverse(const double A[9], double Ainv[9]) {
    double C[9];
    C[0] = A[4] * A[8] - A[5] * A[7];
    C[1] = A[2] * A[7] - A[1] * A[8];
    C[2] = A[1] * A[5] - A[2] * A[4];
    C[3] = A[5] * A[6] - A[3] * A[8];
    C[4] = A[0] * A[8] - A[2] * A[6];
    C[5] = A[2] * A[3] - A[0] * A[5];
    C[6] = A[3] * A[7] - A[4] * A[6];
    C[7] = A[1] * A[6] - A[0] * A[7];
    C[8] = A[0] * A[4] - A[1] * A[3];
    double det = A[0] * C[0] + A[1] * C[3] + A[2] * C[6];
    if (!(fabs(det) >= 1e-300)) return 0; /* also rejects NaN */
    double inv = 1.0 / det;
    for (int i = 0; i < 9; i++) Ainv[i] = C[i] * inv;
    return 1;
}

/// Unpack six doubles (HEARTH_SYM_* order) into a full symmetric B.
static inline void hearth_sym_to_full(const double s[6], double B[9]) {
    B[0] = s[HEARTH_SYM_XX], B[4] = s[HEARTH_SYM_YY], B[8] = s[HEARTH_SYM_ZZ];
    B[1] = B[3] = s[HEARTH_SYM_XY];
    B[5] = B[7] = s[HEARTH_SYM_YZ];
    B[2] = B[6] = s[HEARTH_SYM_ZX];
}

/// Pack the symmetric part of B, (B + B^T)/2, into six doubles (HEARTH_SYM_* order).
static inline void hearth_full_to_sym(const double B[9], double s[6]) {
    s[HEARTH_SYM_XX] = B[0], s[HEARTH_SYM_YY] = B[4], s[HEARTH_SYM_ZZ] = B[8];
    s[HEARTH_SYM_XY] = 0.5 * (B[1] + B[3]);
    s[HEARTH_SYM_YZ] = 0.5 * (B[5] + B[7]);
    s[HEARTH_SYM_ZX] = 0.5 * (B[2] + B[6]);
}

/// A = Q diag(d) Q^T. The upper triangle is computed and mirrored, so A is exactly symmetric.
static inline void hearth_sym_from_eigen(const double Q[9], const double d[3], double A[9]) {
    for (int r = 0; r < 3; r++)
        for (int c = r; c < 3; c++) {
            const double v = Q[3 * r] * d[0] * Q[3 * c] + Q[3 * r + 1] * d[1] * Q[3 * c + 1] + Q[3 * r + 2] * d[2] * Q[3 * c + 2];
            A[3 * r + c] = A[3 * c + r] = v;
        }
}

/// Lame parameters from Young's modulus E (Pa) and Poisson's ratio nu (< 0.5):
/// mu = E / (2 (1 + nu)), lambda = E nu / ((1 + nu)(1 - 2 nu)), both in Pa.
static inline void hearth_lame(double E, double nu, double *mu, double *lambda) {
    *mu = E / (2 * (1 + nu));
    *lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
}

/* ---- symmetric eigen-decomposition (cyclic Jacobi) and its column helpers ---- */

/// Exchange columns a and b of A.
static inline void hearth_t3_swap_cols(double A[9], int a, int b) {
    for (int r = 0; r < 3; r++) {
        double t = A[3 * r + a];
        A[3 * r + a] = A[3 * r + b];
        A[3 * r + b] = t;
    }
}

/// Negate column c of A.
static inline void hearth_t3_negate_col(double A[9], int c) {
    for (int r = 0; r < 3; r++) A[3 * r + c] = -A[3 * r + c];
}

/// Right-multiply columns p, q of A by the Jacobi rotation [[c, s], [-s, c]].
static inline void hearth_t3_rotate_cols(double A[9], int p, int q, double c, double s) {
    for (int r = 0; r < 3; r++) {
        double ap = A[3 * r + p], aq = A[3 * r + q];
        A[3 * r + p] = c * ap - s * aq;
        A[3 * r + q] = s * ap + c * aq;
    }
}

/// Smaller root t of t^2 + 2 zeta t - 1 = 0, zeta = (beta - alpha) / (2 gamma): the tangent of the
/// Jacobi angle that zeroes the (p,q) coupling with |angle| <= pi/4 (Golub & Van Loan 8.5.2).
/// hypot keeps it finite when zeta is huge; the sign choice avoids cancellation.
static inline double hearth_t3_jacobi_tangent(double alpha, double beta, double gamma) {
    double zeta = (beta - alpha) / (2.0 * gamma);
    double sgn = zeta >= 0.0 ? 1.0 : -1.0;
    return sgn / (fabs(zeta) + hypot(1.0, zeta));
}

/// S = Q diag(l) Q^T for symmetric S: l ascending, Q a rotation (det +1). Only the upper triangle
/// of S is read. Cyclic Jacobi: slower than the closed-form cubic but accurate to machine precision
/// even for repeated or clustered eigenvalues, where the trigonometric formula loses half the
/// digits. Stops when the off-diagonal part is below 1e-15 of the whole, or after 50 sweeps.
static inline void hearth_t3_sym_eigen(const double S[9], double l[3], double Q[9]) {
    static const int P[3] = {0, 0, 1}, Qi[3] = {1, 2, 2};
    double a[9];
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) a[3 * i + j] = a[3 * j + i] = S[3 * i + j];
    hearth_t3_identity(Q);

    double norm2 = 0.0;
    for (int i = 0; i < 9; i++) norm2 += a[i] * a[i];
    double tol2 = 1e-15 * 1e-15 * norm2;

    for (int sweep = 0; sweep < 50; sweep++) {
        double off2 = 2.0 * (a[1] * a[1] + a[2] * a[2] + a[5] * a[5]);
        if (off2 <= tol2) break;
        for (int k = 0; k < 3; k++) {
            int p = P[k], q = Qi[k];
            double apq = a[3 * p + q];
            if (apq == 0.0) continue;
            double t = hearth_t3_jacobi_tangent(a[4 * p], a[4 * q], apq);
            double c = 1.0 / sqrt(1.0 + t * t), s = t * c;
            /* A <- J^T A J with the updates of Golub & Van Loan alg. 8.5.2;
             * the diagonal uses the t*apq form, which is more accurate. */
            int r = 3 - p - q; /* the remaining index */
            double arp = a[3 * r + p], arq = a[3 * r + q];
            a[3 * r + p] = a[3 * p + r] = c * arp - s * arq;
            a[3 * r + q] = a[3 * q + r] = s * arp + c * arq;
            a[4 * p] -= t * apq;
            a[4 * q] += t * apq;
            a[3 * p + q] = a[3 * q + p] = 0.0;
            hearth_t3_rotate_cols(Q, p, q, c, s);
        }
    }

    l[0] = a[0];
    l[1] = a[4];
    l[2] = a[8];
    /* Sort ascending (three elements: a tiny exchange sort), moving columns. */
    for (int i = 0; i < 2; i++)
        for (int j = i + 1; j < 3; j++)
            if (l[j] < l[i]) {
                double t = l[i];
                l[i] = l[j];
                l[j] = t;
                hearth_t3_swap_cols(Q, i, j);
            }
    /* Every swap flips det Q; an eigenvector's sign is free, so fix it here. */
    if (hearth_t3_det(Q) < 0.0) hearth_t3_negate_col(Q, 2);
}

#ifdef __cplusplus
}
#endif
#endif
