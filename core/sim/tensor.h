/* tensor.h: 3x3 matrix algebra for the solvers.
 * Matrices are double[9], row-major (A[3*r+c]). Outputs may not alias inputs
 * unless a function says so. The small helpers plugins need are static inline
 * in the public <hearth/tensor.h>; the t3_ names below wrap them for the core
 * (one implementation), and add the heavier algebra only the core uses (SVD,
 * polar, symmetric log and exp, rotations). Built as a small static library
 * that libhearth links; plugins do not link it. */
#ifndef HEARTH_SIM_TENSOR_H
#define HEARTH_SIM_TENSOR_H

#include "hearth/tensor.h"

void t3_identity(double A[9]);
void t3_copy(const double A[9], double B[9]);
void t3_transpose(const double A[9], double At[9]);
void t3_mul(const double A[9], const double B[9], double C[9]);     ///< C = A B
void t3_mul_atb(const double A[9], const double B[9], double C[9]); ///< C = A^T B
void t3_mul_abt(const double A[9], const double B[9], double C[9]); ///< C = A B^T
void t3_mulv(const double A[9], const double x[3], double y[3]);    ///< y = A x
/* inline: the field passes take a determinant per particle per step */
static inline double t3_det(const double A[9]) { return hearth_t3_det(A); }
double t3_trace(const double A[9]);
double t3_ddot(const double A[9], const double B[9]);              ///< A:B
/// Inverse; returns 0 when |det| is below 1e-300 (Ainv untouched).
int t3_inverse(const double A[9], double Ainv[9]);
/// Symmetric eigen-decomposition S = Q diag(l) Q^T (cyclic Jacobi), Q a rotation, l ascending.
void t3_sym_eigen(const double S[9], double l[3], double Q[9]);
/// SVD A = U diag(s) V^T with U, V rotations (det +1); s[2] takes the sign of det A,
/// |s| descending.
void t3_svd(const double A[9], double U[9], double s[3], double V[9]);
/// Polar decomposition A = R S, R a rotation, S symmetric.
void t3_polar(const double A[9], double R[9], double S[9]);
/// log and exp of a symmetric matrix (log needs S positive definite; returns 0 otherwise).
int t3_sym_log(const double S[9], double L[9]);
void t3_sym_exp(const double S[9], double E[9]);
/// Rotation by angle (rad) about a unit axis (Rodrigues).
void t3_rotation(const double axis[3], double angle, double R[9]);
/// A uniformly distributed random rotation from three numbers in [0,1) (Shoemake's quaternion method).
void t3_random_rotation(const double u[3], double R[9]);
#endif
