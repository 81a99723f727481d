/* mpm_stress.c: P2G's material call site (mpm.h, mpm_p2g_stress). For the
 * next HEARTH_BLOCK_MAX particles of a particle block: F <- (I + dt C) F, and
 * their stresses, through the batched door (material.h, material_run_eval)
 * for each run of live particles of one material, so a plugin with
 * stress_block (<hearth/material.h> rule 7) gets the run in one call. A 2D
 * store's 2x2 C and F go in as their plane strain 3x3 (tensor2.h). P2G
 * (mpm.c) calls it at every HEARTH_BLOCK_MAX-th particle of a block and reads
 * the stresses from its columns as it scatters. Failures are recorded after
 * the runs, in particle order, as the one-point loop recorded them, so the
 * guard names the same particle. Out of line: one call per 64 particles. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "material.h"
#include "mpm.h"
#include "tensor2.h"

/* As mpm.c's record_fail: the block keeps its first failure. */
static void stress_fail(pb_partial *pp, int i, fail_kind kind, int code) {
    if (pp->fail_i < 0) {
        pp->fail_i = i;
        pp->fail_kind = kind;
        pp->fail_code = code;
    }
}

static int finite9(const double *a) {
    for (int k = 0; k < 9; k++)
        if (!isfinite(a[k])) return 0;
    return 1;
}

void mpm_p2g_stress(hearth_scene *s, int D, int i0, int n, double dt, unsigned env_flags, const double *Tcol,
                    const double *Wcol, const double *Gcol, const double *S0col, double (*tau)[HEARTH_BLOCK_MAX], double *Js,
                    pb_partial *pp, double *cmax, double *numax) {
    particles *ps = &s->ps;
    const double *Cc = pcold(ps, PC_C), *V0 = pcold(ps, PC_VOL0);
    double *Fc = pcold(ps, PC_F);
    const int *mat = pcoli(ps, PC_MAT);
    const int *pflags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    enum { P_LIVE, P_FIXED, P_BADF };
    unsigned char kind[HEARTH_BLOCK_MAX];
    int code[HEARTH_BLOCK_MAX];
    double wave[HEARTH_BLOCK_MAX], sat[HEARTH_BLOCK_MAX];
    double Fs[9][HEARTH_BLOCK_MAX], Ls[9][HEARTH_BLOCK_MAX]; /* F and C as the block's columns */
    for (int j = 0; j < n; j++) {
        const int i = i0 + j;
        /* F^{n+1} = (I + dt C) F^n: C is the APIC velocity gradient from the last G2P */
        double J;
        int fine;
        if (D == 2) {
            /* the 2D store keeps C and F as their in-plane 2x2 blocks (tensor2.h); the
             * plugin ABI is 3x3, so they go in as their plane strain embedding
             * (C's z row and column 0, F_zz = 1) and the whole tau comes back */
            const double *C = Cc + 4 * i;
            double *F = Fc + 4 * i, Fn[4], F3[9], C3[9];
            t2_advance(C, F, dt, Fn);
            memcpy(F, Fn, sizeof Fn);
            J = t2_det(F);
            /* a finite J means a finite F (every entry is a factor of J: see the 3D branch) */
            fine = J > 0 && (J <= DBL_MAX || (isfinite(F[0]) && isfinite(F[1]) && isfinite(F[2]) && isfinite(F[3])));
            t2_embed(F, 1.0, F3);
            t2_embed(C, 0.0, C3);
            for (int c = 0; c < 9; c++) Fs[c][j] = F3[c], Ls[c][j] = C3[c];
        } else {
            const double *C = Cc + 9 * i;
            double *F = Fc + 9 * i, Fn[9];
            for (int r = 0; r < 3; r++)
                for (int c = 0; c < 3; c++)
                    Fn[3 * r + c] = F[3 * r + c] + dt * (C[3 * r] * F[c] + C[3 * r + 1] * F[3 + c] + C[3 * r + 2] * F[6 + c]);
            memcpy(F, Fn, sizeof Fn);
            for (int c = 0; c < 9; c++) Fs[c][j] = Fn[c], Ls[c][j] = C[c];
            J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
            /* Every entry of F is a factor of a product in J, and +, - and * of an inf or NaN give an inf or
             * a NaN: a finite J means a finite F. So finite9 is needed only when J is +inf (finite entries
             * whose products overflow), and the test is the same as J > 0 && finite9(F) for every F. It
             * saves the nine entry tests: 23 instructions a particle-step in 3D, 14 in 2D (callgrind). */
            fine = J > 0 && (J <= DBL_MAX || finite9(F));
        }
        Js[j] = J;
        kind[j] = pflags && (pflags[i] & PF_FIXED) ? P_FIXED : !fine ? P_BADF : P_LIVE;
        if (kind[j] != P_LIVE)
            for (int c = 0; c < 9; c++) tau[c][j] = 0;
        else if (Wcol) sat[j] = Wcol[i] / (s->mats.slot[mat[i]].core[CP_WATER_DENSITY] * J * V0[i]);
    }
    for (int j = 0; j < n;) { /* runs of live particles of one material */
        if (kind[j] != P_LIVE) {
            j++;
            continue;
        }
        int e = j + 1;
        while (e < n && kind[e] == P_LIVE && mat[i0 + e] == mat[i0 + j]) e++;
        material_run run = {.mat = mat[i0 + j], .i0 = i0 + j, .n = e - j, .dim = D, .plane = D == 2, .dt = dt, .flags = env_flags, .J = Js + j,
                            .temperature = Tcol ? Tcol + i0 + j : NULL, .saturation = Wcol ? sat + j : NULL,
                            .gas = Gcol, .saturation0 = S0col};
        double *tc[9];
        for (int c = 0; c < 9; c++) {
            run.F[c] = Fs[c] + j;
            run.grad_v[c] = Ls[c] + j;
            tc[c] = tau[c] + j;
        }
        const double nu = material_run_eval(&s->mats, ps, &run, tc, code + j, wave + j);
        if (nu > *numax) *numax = nu;
        j = e;
    }
    for (int j = 0; j < n; j++) {
        if (kind[j] == P_BADF) stress_fail(pp, i0 + j, FAIL_F, 0);
        if (kind[j] != P_LIVE) continue;
        if (code[j]) stress_fail(pp, i0 + j,
                                 code[j] == MATERIAL_NONFINITE ? FAIL_STRESS : code[j] == MATERIAL_BAD_BULK ? FAIL_BULK : FAIL_PLUGIN,
                                 code[j] < 0 ? 0 : code[j]);
        /* NaN, inf or <= 0 would make the next dt NaN or 0 (fmax would also
         * drop a NaN silently): the guard stops the run naming the plugin */
        const double c = wave[j];
        if (!(c > 0 && c <= DBL_MAX)) stress_fail(pp, i0 + j, FAIL_WAVE, 0);
        else if (c > *cmax) *cmax = c;
    }
}
