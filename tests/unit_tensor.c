/* unit_tensor.c: tests for core/sim/tensor.c (3x3 algebra, eigen, SVD, polar, log/exp). */
#include <math.h>
#include <stdint.h>

#include "tensor.h"
#include "test.h"

/* splitmix64 with a fixed seed: reproducible on every platform, unlike rand(). */
static uint64_t rng_state = 0x9e3779b97f4a7c15ull;

static uint64_t splitmix64(void) {
    uint64_t z = (rng_state += 0x9e3779b97f4a7c15ull);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

/* Uniform in [0, 1). */
static double uniform(void) { return (double)(splitmix64() >> 11) * 0x1.0p-53; }

static void rand_mat(double A[9]) {
    for (int i = 0; i < 9; i++) A[i] = 2.0 * uniform() - 1.0;
}

static void rand_rot(double R[9]) {
    double u[3] = {uniform(), uniform(), uniform()};
    t3_random_rotation(u, R);
}

static double fro(const double A[9]) { return sqrt(t3_ddot(A, A)); }

static double fro_diff(const double A[9], const double B[9]) {
    double d = 0.0;
    for (int i = 0; i < 9; i++) d += (A[i] - B[i]) * (A[i] - B[i]);
    return sqrt(d);
}

/* R D R^T for diagonal D = diag(d). */
static void rot_diag(const double R[9], const double d[3], double M[9]) {
    double D[9] = {d[0], 0, 0, 0, d[1], 0, 0, 0, d[2]}, T[9];
    t3_mul(R, D, T);
    t3_mul_abt(T, R, M);
}

/* |Q^T Q - I| and |det Q - 1| both within tol. */
static void check_rotation(const double Q[9], double tol) {
    double QtQ[9], I[9];
    t3_mul_atb(Q, Q, QtQ);
    t3_identity(I);
    CHECK_NEAR(fro_diff(QtQ, I), 0.0, tol);
    CHECK_NEAR(t3_det(Q), 1.0, tol);
}

TEST(tensor_mul_inverse) {
    double I[9];
    t3_identity(I);
    for (int n = 0; n < 200; n++) {
        double A[9], B[9], Ai[9], P[9], AB[9];
        rand_mat(A);
        rand_mat(B);
        if (fabs(t3_det(A)) < 0.2) continue; /* keep A well conditioned */
        CHECK(t3_inverse(A, Ai));
        t3_mul(A, Ai, P);
        CHECK_NEAR(fro_diff(P, I), 0.0, 1e-13);
        t3_mul(Ai, A, P);
        CHECK_NEAR(fro_diff(P, I), 0.0, 1e-13);
        t3_mul(A, B, AB);
        CHECK_NEAR(t3_det(AB), t3_det(A) * t3_det(B), 1e-13);

        /* The transposed products agree with transpose + mul. */
        double At[9], Bt[9], X[9], Y[9];
        t3_transpose(A, At);
        t3_transpose(B, Bt);
        t3_mul(At, B, X);
        t3_mul_atb(A, B, Y);
        CHECK_NEAR(fro_diff(X, Y), 0.0, 1e-15);
        t3_mul(A, Bt, X);
        t3_mul_abt(A, B, Y);
        CHECK_NEAR(fro_diff(X, Y), 0.0, 1e-15);
        CHECK_NEAR(t3_trace(AB), t3_ddot(At, B), 1e-14);
    }
    double x[3] = {1, 2, 3}, y[3], M[9] = {1, 2, 3, 4, 5, 6, 7, 8, 10};
    t3_mulv(M, x, y);
    CHECK(y[0] == 14 && y[1] == 32 && y[2] == 53);
    CHECK_NEAR(t3_det(M), -3.0, 1e-15);

    /* A singular matrix is refused and the output left alone. */
    double S[9] = {1, 2, 3, 2, 4, 6, 0, 1, 1}, out[9] = {42, 42, 42, 42, 42, 42, 42, 42, 42};
    CHECK(t3_inverse(S, out) == 0);
    CHECK(out[0] == 42 && out[8] == 42);
}

/* Reconstruction, orthonormality, det +1 and ascending order of t3_sym_eigen. */
static void check_eigen(const double S[9]) {
    double l[3], Q[9], R[9];
    t3_sym_eigen(S, l, Q);
    rot_diag(Q, l, R);
    CHECK_NEAR(fro_diff(R, S), 0.0, 1e-13 * fmax(fro(S), 1e-300));
    check_rotation(Q, 1e-13);
    CHECK(l[0] <= l[1] && l[1] <= l[2]);
}

TEST(tensor_sym_eigen) {
    for (int n = 0; n < 200; n++) {
        double M[9], S[9];
        rand_mat(M);
        for (int i = 0; i < 3; i++)
            for (int j = 0; j < 3; j++) S[3 * i + j] = 0.5 * (M[3 * i + j] + M[3 * j + i]);
        check_eigen(S);
    }
    /* Repeated eigenvalues, rotated so Jacobi has real work to do. */
    for (int n = 0; n < 50; n++) {
        double R[9], S[9], l[3], Q[9];
        rand_rot(R);
        rot_diag(R, (double[3]){2, 2, 5}, S);
        check_eigen(S);
        t3_sym_eigen(S, l, Q);
        CHECK_NEAR(l[0], 2.0, 1e-14);
        CHECK_NEAR(l[1], 2.0, 1e-14);
        CHECK_NEAR(l[2], 5.0, 1e-14);
        rot_diag(R, (double[3]){-7, -7, -7}, S);
        check_eigen(S);
        rot_diag(R, (double[3]){1e-8, 1, 1e8}, S);
        check_eigen(S);
    }
    double I[9], l[3], Q[9];
    t3_identity(I);
    check_eigen(I);
    t3_sym_eigen(I, l, Q);
    CHECK(l[0] == 1 && l[1] == 1 && l[2] == 1);
    double Z[9] = {0};
    t3_sym_eigen(Z, l, Q);
    CHECK(l[0] == 0 && l[1] == 0 && l[2] == 0);
    check_rotation(Q, 0.0);

    /* Closed form: the 2x2 block [[2,1],[1,2]] has eigenvalues 1 and 3, with
     * eigenvector (1,-1,0)/sqrt(2) for 1. */
    double K[9] = {2, 1, 0, 1, 2, 0, 0, 0, 3};
    check_eigen(K);
    t3_sym_eigen(K, l, Q);
    CHECK_NEAR(l[0], 1.0, 1e-15);
    CHECK_NEAR(l[1], 3.0, 1e-15);
    CHECK_NEAR(l[2], 3.0, 1e-15);
    CHECK_NEAR(fabs(Q[0]), sqrt(0.5), 1e-15);
    CHECK_NEAR(Q[0] + Q[3], 0.0, 1e-15);
    CHECK_NEAR(Q[6], 0.0, 1e-15);
}

/* Reconstruction, U and V rotations, |s| descending; returns s in s_out. */
static void check_svd(const double A[9], double s_out[3]) {
    double U[9], s[3], V[9], US[9], R[9];
    t3_svd(A, U, s, V);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) US[3 * r + c] = U[3 * r + c] * s[c];
    t3_mul_abt(US, V, R);
    CHECK_NEAR(fro_diff(R, A), 0.0, 1e-12 * fro(A));
    check_rotation(U, 1e-12);
    check_rotation(V, 1e-12);
    CHECK(s[0] >= s[1] && s[1] >= fabs(s[2]) && s[1] >= 0);
    if (s_out) {
        s_out[0] = s[0];
        s_out[1] = s[1];
        s_out[2] = s[2];
    }
}

TEST(tensor_svd) {
    double s[3];
    for (int n = 0; n < 300; n++) {
        double A[9];
        rand_mat(A);
        check_svd(A, s);
        CHECK(t3_det(A) >= 0 ? s[2] >= 0 : s[2] <= 0);
        CHECK_NEAR(s[0] * s[1] * s[2], t3_det(A), 1e-13);
    }
    for (int n = 0; n < 50; n++) {
        double R1[9], R2[9], T[9], A[9];
        rand_rot(R1);
        rand_rot(R2);
        /* Large stretch: the small singular value survives to ~eps*|A|. */
        double D[9] = {1e6, 0, 0, 0, 1, 0, 0, 0, 1e-6};
        t3_mul(R1, D, T);
        t3_mul_abt(T, R2, A);
        check_svd(A, s);
        CHECK_NEAR(s[0], 1e6, 1e-9);
        CHECK_NEAR(s[1], 1.0, 1e-9);
        CHECK_NEAR(s[2], 1e-6, 1e-9);

        /* Reflection: the negative sign lands on the smallest value. */
        double F[9] = {3, 0, 0, 0, 2, 0, 0, 0, -1};
        t3_mul(R1, F, T);
        t3_mul_abt(T, R2, A);
        check_svd(A, s);
        CHECK_NEAR(s[0], 3.0, 1e-13);
        CHECK_NEAR(s[1], 2.0, 1e-13);
        CHECK_NEAR(s[2], -1.0, 1e-13);

        /* Repeated singular values, with and without reflection. */
        double E[9] = {2, 0, 0, 0, 2, 0, 0, 0, -2};
        t3_mul(R1, E, T);
        t3_mul_abt(T, R2, A);
        check_svd(A, s);
        CHECK_NEAR(s[2], -2.0, 1e-13);
        double G[9] = {5, 0, 0, 0, 1, 0, 0, 0, 1};
        t3_mul(R1, G, T);
        t3_mul_abt(T, R2, A);
        check_svd(A, s);

        /* Rank one (a b^T) and rank two. */
        double a[3] = {uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};
        double b[3] = {uniform() - 0.5, uniform() - 0.5, uniform() - 0.5};
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) A[3 * r + c] = a[r] * b[c];
        check_svd(A, s);
        CHECK_NEAR(s[1], 0.0, 1e-14);
        CHECK_NEAR(s[2], 0.0, 1e-14);
        double H[9] = {4, 0, 0, 0, 1, 0, 0, 0, 0};
        t3_mul(R1, H, T);
        t3_mul_abt(T, R2, A);
        check_svd(A, s);
        CHECK_NEAR(s[2], 0.0, 1e-14);

        /* Near identity. */
        double N[9];
        t3_identity(N);
        for (int i = 0; i < 9; i++) N[i] += 1e-9 * (uniform() - 0.5);
        check_svd(N, s);
    }
    double I[9];
    t3_identity(I);
    check_svd(I, s);
    CHECK(s[0] == 1 && s[1] == 1 && s[2] == 1);
    double M[9] = {1, 0, 0, 0, 1, 0, 0, 0, -1}; /* a pure reflection */
    check_svd(M, s);
    CHECK(s[0] == 1 && s[1] == 1 && s[2] == -1);
    double Z[9] = {0}, U[9], V[9];
    t3_svd(Z, U, s, V);
    CHECK(s[0] == 0 && s[1] == 0 && s[2] == 0);
    check_rotation(U, 0.0);
    check_rotation(V, 0.0);
    /* Tiny and huge scales stay finite and accurate (power-of-two rescaling). */
    double Sm[9], Bg[9];
    rand_mat(Sm);
    for (int i = 0; i < 9; i++) {
        Bg[i] = Sm[i] * 1e200;
        Sm[i] *= 1e-200;
    }
    check_svd(Sm, s);
    check_svd(Bg, s);
}

static void check_polar(const double A[9]) {
    double R[9], S[9], RS[9];
    t3_polar(A, R, S);
    check_rotation(R, 1e-12);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) CHECK(S[3 * i + j] == S[3 * j + i]);
    t3_mul(R, S, RS);
    CHECK_NEAR(fro_diff(RS, A), 0.0, 1e-12 * fro(A));
}

TEST(tensor_polar) {
    for (int n = 0; n < 200; n++) {
        double A[9], R[9], S[9], l[3], Q[9];
        rand_mat(A);
        check_polar(A);
        /* For det A > 0 the stretch is positive definite. */
        t3_polar(A, R, S);
        t3_sym_eigen(S, l, Q);
        if (t3_det(A) > 1e-6) CHECK(l[0] > 0);
    }
    /* A known rotation times a known stretch is recovered. */
    double axis[3] = {1, 2, 2}, R0[9], S0[9], A[9], R[9], S[9];
    t3_rotation(axis, 0.7, R0);
    double U[9];
    double u[3] = {0.3, 0.6, 0.9};
    t3_random_rotation(u, U);
    rot_diag(U, (double[3]){1.5, 0.5, 2.5}, S0);
    t3_mul(R0, S0, A);
    check_polar(A);
    t3_polar(A, R, S);
    CHECK_NEAR(fro_diff(R, R0), 0.0, 1e-13);
    CHECK_NEAR(fro_diff(S, S0), 0.0, 1e-13);
    /* A reflection still gives a rotation R (S takes the negative sign). */
    double F[9] = {2, 0, 0, 0, 1, 0, 0, 0, -0.5};
    t3_mul(R0, F, A);
    check_polar(A);
    /* Rank deficient. */
    double H[9] = {1, 2, 3, 2, 4, 6, 0, 1, 1};
    check_polar(H);
}

TEST(tensor_log_exp) {
    for (int n = 0; n < 100; n++) {
        double R[9], S[9], L[9], E[9];
        rand_rot(R);
        double d[3] = {exp(2 * uniform() - 1), exp(2 * uniform() - 1), exp(2 * uniform() - 1)};
        rot_diag(R, d, S);
        CHECK(t3_sym_log(S, L));
        t3_sym_exp(L, E);
        CHECK_NEAR(fro_diff(E, S), 0.0, 1e-12 * fro(S));
        /* Stretched: eigenvalues spanning 1e-3..1e3. */
        rot_diag(R, (double[3]){1e3, 1, 1e-3}, S);
        CHECK(t3_sym_log(S, L));
        t3_sym_exp(L, E);
        CHECK_NEAR(fro_diff(E, S), 0.0, 1e-12 * fro(S));
    }
    const double e = exp(1.0);
    double D[9] = {e, 0, 0, 0, e * e, 0, 0, 0, e * e * e}, L[9];
    double want[9] = {1, 0, 0, 0, 2, 0, 0, 0, 3};
    CHECK(t3_sym_log(D, L));
    CHECK_NEAR(fro_diff(L, want), 0.0, 1e-14);
    double I[9], Z[9] = {0}, E[9];
    t3_identity(I);
    CHECK(t3_sym_log(I, L));
    CHECK_NEAR(fro(L), 0.0, 0.0);
    t3_sym_exp(Z, E);
    CHECK_NEAR(fro_diff(E, I), 0.0, 0.0);
    /* Not positive definite: indefinite, singular, negative definite. */
    double B1[9] = {1, 0, 0, 0, -1, 0, 0, 0, 2};
    double B2[9] = {1, 0, 0, 0, 0, 0, 0, 0, 1};
    double B3[9] = {-1, 0, 0, 0, -2, 0, 0, 0, -3};
    double B4[9] = {1, 2, 0, 2, 1, 0, 0, 0, 1}; /* eigenvalues -1, 1, 3 */
    CHECK(t3_sym_log(B1, L) == 0);
    CHECK(t3_sym_log(B2, L) == 0);
    CHECK(t3_sym_log(B3, L) == 0);
    CHECK(t3_sym_log(B4, L) == 0);
}

TEST(tensor_rotation) {
    const double pi = 3.14159265358979323846;
    double z[3] = {0, 0, 1}, x[3] = {1, 0, 0}, y[3], R[9];
    t3_rotation(z, pi / 2, R);
    t3_mulv(R, x, y);
    CHECK_NEAR(y[0], 0.0, 1e-15);
    CHECK_NEAR(y[1], 1.0, 1e-15);
    CHECK_NEAR(y[2], 0.0, 1e-15);
    check_rotation(R, 1e-15);

    /* A general axis is left fixed and the trace is 1 + 2 cos(angle). */
    double axis[3] = {1 / sqrt(3.0), -1 / sqrt(3.0), 1 / sqrt(3.0)}, ax[3];
    t3_rotation(axis, 1.234, R);
    check_rotation(R, 1e-14);
    t3_mulv(R, axis, ax);
    for (int i = 0; i < 3; i++) CHECK_NEAR(ax[i], axis[i], 1e-15);
    CHECK_NEAR(t3_trace(R), 1 + 2 * cos(1.234), 1e-14);

    /* Random rotations: orthonormal, det 1, and their mean tends to zero as it
     * must for the uniform (Haar) distribution; a biased sampler would not. */
    double mean[9] = {0};
    const int N = 20000;
    for (int n = 0; n < N; n++) {
        rand_rot(R);
        check_rotation(R, 1e-14);
        for (int i = 0; i < 9; i++) mean[i] += R[i] / N;
    }
    for (int i = 0; i < 9; i++) CHECK_NEAR(mean[i], 0.0, 0.03);
}

TEST_MAIN(T(tensor_mul_inverse), T(tensor_sym_eigen), T(tensor_svd), T(tensor_polar),
          T(tensor_log_exp), T(tensor_rotation))
