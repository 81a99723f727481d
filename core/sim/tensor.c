/* tensor.c: 3x3 matrix algebra (row-major double[9]).
 *
 * Only libm, no allocation, so the file can sit in a PIC static library that
 * both libhearth and plugins link. The products below go through a local
 * temporary, which makes them safe even when the output aliases an input
 * (the header does not promise that; it is just cheap insurance). */
#include "tensor.h"

#include <float.h>
#include <math.h>

/* Jacobi stops once the off-diagonal part is this small relative to the whole
 * matrix: a few ulps, i.e. machine precision. */
#define T3_JACOBI_TOL 1e-15
#define T3_MAX_SWEEPS 50

/* The small products and the inverse are <hearth/tensor.h>'s, which plugins
 * include directly; these out-of-line names keep the core's call sites and
 * give the core and the plugins one implementation. */
void t3_identity(double A[9]) { hearth_t3_identity(A); }
void t3_copy(const double A[9], double B[9]) { hearth_t3_copy(A, B); }
void t3_transpose(const double A[9], double At[9]) { hearth_t3_transpose(A, At); }
void t3_mul(const double A[9], const double B[9], double C[9]) { hearth_t3_mul(A, B, C); }
void t3_mul_atb(const double A[9], const double B[9], double C[9]) { hearth_t3_mul_atb(A, B, C); }
void t3_mul_abt(const double A[9], const double B[9], double C[9]) { hearth_t3_mul_abt(A, B, C); }
void t3_mulv(const double A[9], const double x[3], double y[3]) { hearth_t3_mulv(A, x, y); }
double t3_trace(const double A[9]) { return hearth_t3_trace(A); }
double t3_ddot(const double A[9], const double B[9]) { return hearth_t3_ddot(A, B); }
int t3_inverse(const double A[9], double Ainv[9]) { return hearth_t3_inverse(A, Ainv); }

/* ---- small vector helpers (columns of row-major matrices) ---- */

static double dot3(const double a[3], const double b[3]) {
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void get_col(const double A[9], int c, double v[3]) {
    v[0] = A[c];
    v[1] = A[3 + c];
    v[2] = A[6 + c];
}

static void set_col(double A[9], int c, const double v[3]) {
    A[c] = v[0];
    A[3 + c] = v[1];
    A[6 + c] = v[2];
}

/* Normalise v in place; returns the old length. */
static double normalize3(double v[3]) {
    double n = sqrt(dot3(v, v));
    if (n > 0.0) {
        v[0] /= n;
        v[1] /= n;
        v[2] /= n;
    }
    return n;
}

/* v -= (u.v) u for unit u. */
static void remove_component(double v[3], const double u[3]) {
    double d = dot3(u, v);
    v[0] -= d * u[0];
    v[1] -= d * u[1];
    v[2] -= d * u[2];
}

/* A unit vector orthogonal to unit u: start from the axis u is least aligned
 * with, so the projection cannot cancel badly. */
static void any_orthogonal(const double u[3], double v[3]) {
    int k = 0;
    if (fabs(u[1]) < fabs(u[k])) k = 1;
    if (fabs(u[2]) < fabs(u[k])) k = 2;
    v[0] = v[1] = v[2] = 0.0;
    v[k] = 1.0;
    remove_component(v, u);
    normalize3(v);
}

/* E = Q diag(d) Q^T, computing the upper triangle and mirroring it so the
 * result is exactly symmetric (the two halves would differ by rounding). */
static void sym_from_eigen(const double Q[9], const double d[3], double E[9]) {
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) {
            double e = 0.0;
            for (int k = 0; k < 3; k++) e += Q[3 * i + k] * d[k] * Q[3 * j + k];
            E[3 * i + j] = E[3 * j + i] = e;
        }
}

/* ---- symmetric eigen-decomposition ---- */

/* Plugins need it too (snow_plastic's return map), so it lives in <hearth/tensor.h>. */
void t3_sym_eigen(const double S[9], double l[3], double Q[9]) { hearth_t3_sym_eigen(S, l, Q); }

/* ---- SVD ---- */

void t3_svd(const double A[9], double U[9], double s[3], double V[9]) {
    /* One-sided (Hestenes) Jacobi: rotate the columns of B = A V until they are
     * mutually orthogonal; then B = U diag(s). Rejected: eigen-decomposing A^T A,
     * which squares the condition number, so for stretches of 1e6 the small
     * singular vectors carry errors ~1e-4. One-sided Jacobi keeps the small
     * singular values to relative accuracy. */
    double m = 0.0;
    for (int i = 0; i < 9; i++) m = fmax(m, fabs(A[i]));
    t3_identity(U);
    t3_identity(V);
    s[0] = s[1] = s[2] = 0.0;
    if (m == 0.0) return;

    /* Scale by a power of two (exact) so column norms squared cannot overflow
     * or underflow; undone on s at the end. */
    int e = 0;
    if (isfinite(m)) frexp(m, &e);
    double B[9];
    for (int i = 0; i < 9; i++) B[i] = ldexp(A[i], -e);

    static const int P[3] = {0, 0, 1}, Qi[3] = {1, 2, 2};
    for (int sweep = 0; sweep < T3_MAX_SWEEPS; sweep++) {
        int rotated = 0;
        for (int k = 0; k < 3; k++) {
            int p = P[k], q = Qi[k];
            double bp[3], bq[3];
            get_col(B, p, bp);
            get_col(B, q, bq);
            double alpha = dot3(bp, bp), beta = dot3(bq, bq), gamma = dot3(bp, bq);
            /* Columns already orthogonal to working precision: skip. */
            if (!(fabs(gamma) > T3_JACOBI_TOL * sqrt(alpha) * sqrt(beta))) continue;
            double t = hearth_t3_jacobi_tangent(alpha, beta, gamma);
            double c = 1.0 / sqrt(1.0 + t * t), sn = t * c;
            hearth_t3_rotate_cols(B, p, q, c, sn);
            hearth_t3_rotate_cols(V, p, q, c, sn);
            rotated = 1;
        }
        if (!rotated) break;
    }

    double b[3][3], n[3];
    for (int i = 0; i < 3; i++) {
        get_col(B, i, b[i]);
        n[i] = sqrt(dot3(b[i], b[i]));
    }
    /* Sort by column norm, descending, carrying V's columns along. */
    for (int i = 0; i < 2; i++)
        for (int j = i + 1; j < 3; j++)
            if (n[j] > n[i]) {
                double t = n[i];
                n[i] = n[j];
                n[j] = t;
                for (int r = 0; r < 3; r++) {
                    double x = b[i][r];
                    b[i][r] = b[j][r];
                    b[j][r] = x;
                }
                hearth_t3_swap_cols(V, i, j);
            }
    /* Swaps may have made V a reflection. Flipping its last column (and B's,
     * so that A V = B still holds) makes it a rotation; the sign then shows up
     * in s[2] below. */
    if (t3_det(V) < 0.0) {
        hearth_t3_negate_col(V, 2);
        for (int r = 0; r < 3; r++) b[2][r] = -b[2][r];
    }

    /* U's columns. A tiny or zero column carries no usable direction (rank
     * deficiency), so complete the basis by Gram-Schmidt, and always take the
     * last column as u0 x u1: that makes U a rotation by construction. */
    double u[3][3];
    for (int r = 0; r < 3; r++) u[0][r] = b[0][r];
    normalize3(u[0]); /* n[0] >= 0.5 after scaling */
    for (int r = 0; r < 3; r++) u[1][r] = b[1][r];
    remove_component(u[1], u[0]);
    if (normalize3(u[1]) > 1e-150) {
        remove_component(u[1], u[0]); /* second pass: "twice is enough" */
        normalize3(u[1]);
    } else {
        any_orthogonal(u[0], u[1]);
    }
    u[2][0] = u[0][1] * u[1][2] - u[0][2] * u[1][1];
    u[2][1] = u[0][2] * u[1][0] - u[0][0] * u[1][2];
    u[2][2] = u[0][0] * u[1][1] - u[0][1] * u[1][0];
    for (int i = 0; i < 3; i++) set_col(U, i, u[i]);

    /* s from the sorted norms keeps |s| descending exactly; the sign of s[2]
     * is whichever way b2 points along u2, i.e. the sign of det A. */
    s[0] = ldexp(n[0], e);
    s[1] = ldexp(n[1], e);
    s[2] = ldexp(dot3(u[2], b[2]) < 0.0 ? -n[2] : n[2], e);
}

void t3_polar(const double A[9], double R[9], double S[9]) {
    /* From the SVD: A = (U V^T)(V diag(s) V^T). With U, V rotations R is a
     * rotation even for det A < 0; S then has one negative eigenvalue. */
    double U[9], s[3], V[9];
    t3_svd(A, U, s, V);
    t3_mul_abt(U, V, R);
    sym_from_eigen(V, s, S);
}

int t3_sym_log(const double S[9], double L[9]) {
    double l[3], Q[9];
    t3_sym_eigen(S, l, Q);
    if (!(l[0] > 0.0)) return 0; /* l ascending: l[0] is the smallest */
    double d[3] = {log(l[0]), log(l[1]), log(l[2])};
    sym_from_eigen(Q, d, L);
    return 1;
}

void t3_sym_exp(const double S[9], double E[9]) {
    double l[3], Q[9];
    t3_sym_eigen(S, l, Q);
    double d[3] = {exp(l[0]), exp(l[1]), exp(l[2])};
    sym_from_eigen(Q, d, E);
}

/* ---- rotations ---- */

void t3_rotation(const double axis[3], double angle, double R[9]) {
    /* Rodrigues: R = I + sin(a) K + (1 - cos(a)) K^2, K the cross-product matrix.
     * The axis is renormalised so a slightly-off axis still yields a rotation;
     * a zero axis yields the identity. */
    double k[3] = {axis[0], axis[1], axis[2]};
    if (normalize3(k) == 0.0) {
        t3_identity(R);
        return;
    }
    double sa = sin(angle), ca = 1.0 - cos(angle);
    double x = k[0], y = k[1], z = k[2];
    R[0] = 1.0 - ca * (y * y + z * z);
    R[1] = -sa * z + ca * x * y;
    R[2] = sa * y + ca * x * z;
    R[3] = sa * z + ca * x * y;
    R[4] = 1.0 - ca * (x * x + z * z);
    R[5] = -sa * x + ca * y * z;
    R[6] = -sa * y + ca * x * z;
    R[7] = sa * x + ca * y * z;
    R[8] = 1.0 - ca * (x * x + y * y);
}

void t3_random_rotation(const double u[3], double R[9]) {
    /* Shoemake, "Uniform random rotations", Graphics Gems III (1992): the
     * quaternion below is uniform on S^3, hence R uniform (Haar) on SO(3). */
    const double two_pi = 6.283185307179586476925286766559;
    double r1 = sqrt(1.0 - u[0]), r2 = sqrt(u[0]);
    double t1 = two_pi * u[1], t2 = two_pi * u[2];
    double x = r1 * sin(t1), y = r1 * cos(t1), z = r2 * sin(t2), w = r2 * cos(t2);
    R[0] = 1.0 - 2.0 * (y * y + z * z);
    R[1] = 2.0 * (x * y - z * w);
    R[2] = 2.0 * (x * z + y * w);
    R[3] = 2.0 * (x * y + z * w);
    R[4] = 1.0 - 2.0 * (x * x + z * z);
    R[5] = 2.0 * (y * z - x * w);
    R[6] = 2.0 * (x * z - y * w);
    R[7] = 2.0 * (y * z + x * w);
    R[8] = 1.0 - 2.0 * (x * x + y * y);
}
