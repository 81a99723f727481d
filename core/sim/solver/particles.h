/* particles.h: the structure-of-arrays particle store.
 *
 * Every per-particle quantity is a column. Core columns always exist; optional
 * columns (temperature, water, gas, mixing ratios, ...) are allocated only when
 * a scene or material enables them, so a scene pays only for what it uses.
 * Sorting, checkpoints, rollback snapshots and hashing walk the column table,
 * so a new field needs one line in the table and nothing else. */
#ifndef HEARTH_PARTICLES_H
#define HEARTH_PARTICLES_H
#include <stdint.h>

#include "hearth/hearth.h"
#include "tensor.h"
#include "tensor2.h"

struct team_wait; /* team_wait.h */

typedef enum pcol {
    /* core: always present */
    PC_X,     /* position (m), 3 */
    PC_V,     /* velocity (m/s), 3 */
    PC_C,     /* APIC affine velocity = velocity gradient (1/s), 9 (4 in a 2x2 store: t2) */
    PC_F,     /* deformation gradient, 9 (4 in a 2x2 store: t2) */
    PC_MASS,  /* kg, 1 */
    PC_VOL0,  /* initial volume (m^3), 1 */
    PC_MAT,   /* material index (int32) */
    PC_ID,    /* stable id, survives sorting (int32) */
    PC_STATE, /* plugin state, state_stride doubles */
    PC_NCORE,
    /* optional: enabled on demand by later modules */
    PC_TEMPERATURE = PC_NCORE, /* degrees C, 1 */
    PC_TEMP_MAX,               /* highest temperature reached (for irreversible curves), 1 */
    PC_BODY,                   /* body id (int32), for scenes built from bodies */
    PC_FLAGS,                  /* PF_* bits (int32) */
    PC_GAS,                    /* CO2 moles per unit reference volume n^g (mol/m^3), 1 */
    PC_WATER,                  /* water mass m_p^w (kg; kg/m in 2D), 1 */
    PC_SAT0,                   /* initial saturation s_0 (the zero of the water pressure, eq. 14), 1 */
    PC_QW,                     /* water flux relative to the solid q^w (kg/(m^2 s)), 3 */
    PC_MIX,                    /* initial mixing ratios of a mixture's constituents (labels), MIX_MAX */
    PC_MIXD,                   /* dynamic mixing ratios (Nagasawa et al. eq. 44), MIX_MAX */
    PC_BROWNING,               /* browning index Delta E / Delta E_inf (Zanoni et al. 1995), 0..1, 1 (browning.c) */
    PC_DRIED,                  /* 1 - the lowest moisture ratio X/X_0 reached, 0..1 (irreversible moisture curves), 1 */
    PC_THERMAL,                /* thermal volume strain ln J_th at the last stress (eq. 10 as a strain: material.h), 1 */
    PC_VENT,                   /* gas_vent: h S_p at the last field step, 0 where closed or inside (gas.c's gas_between), 1 */
    PC_SURFACE,                /* browning with an oven (MPM): the air surface's temperature (K) and saturation above the
                                * particle's own at the last field step, 0 inside (browning.c), 2 */
    PC_GLUE,                   /* the sticky faces the particle has touched: bit s for glue slot s (mpm_touch.c's
                                * mpm_touch_glue_bit), int32; enabled in an MPM scene with a sticky face */
    PC_GAS_MADE,               /* the CO2 each share has made (mol/kg: gas_rate's, gas_rate_2's), 2; enabled when a
                                * material gives a share an amount (gas_amount, gas_amount_2; gas.h's gas_share_capped) */
    /* memos (exp_memo.h): a cache of exp at the particle's last argument, 2 (the argument, its exp); never
     * hashed nor saved: a zeroed entry misses, so any value computes the same bits */
    PC_THERMAL_MEMO,           /* the thermal split's exp(-ln J_th / 3) (material_batch.c's thermal_scales_block) */
    PC_GAS_MEMO,               /* the CO2 rate's exp(-u^2), u = (theta - theta_r) / dtheta (gas.c's gas_between) */
    /* a cache of the temperature curves' values at the particle's last temperatures, CURVE_MEMO_WIDTH: its
     * material's curve stamp, T and T_max (the key, compared bit for bit), then the values of the material's
     * first CURVE_MEMO_WIDTH - 3 temperature curves (material_batch.c's run_params_columns); a zeroed entry
     * misses (stamps start at 1). Never hashed nor saved, as the exp memos */
    PC_CURVE_MEMO,
    /* a plugin's memo (<hearth/material.h> rule 10), memo_stride doubles: a cache its stress_block keys on the
     * arguments it holds; allocated only in an MPM scene with a material whose plugin asks for one (memo_size),
     * never hashed nor saved, as the memos above */
    PC_PLUGIN_MEMO,
    PC_COUNT
} pcol;

/// Whether column c is a memo (a cache, not state: hearth_scene_hash and checkpoints leave it out).
static inline int particles_col_is_memo(int c) {
    return c == PC_THERMAL_MEMO || c == PC_GAS_MEMO || c == PC_CURVE_MEMO || c == PC_PLUGIN_MEMO;
}
/* PC_CURVE_MEMO's doubles a particle: the key (stamp, T, T_max) and two curves' values, the cookie's and
 * muffin's (tau_y and eta); a material with more temperature curves evaluates the rest every step */
enum { CURVE_MEMO_WIDTH = 5 };

enum { PF_FIXED = 1, PF_BOUNDARY = 2, PF_HOLD_T = 4 }; /* pinned body; boundary particle (Ding et al. §6.6); keeps its temperature (a held body) */
/* PC_GLUE's slots (mpm_touch.c): the domain walls' six faces 0..5, collider c 6 + c; colliders past the last
 * slot share it. A glued particle stays glued. */
enum { GLUE_SLOTS = 31 };

typedef struct particles {
    int n, cap;            /* cap: particles every enabled column holds room for */
    int ccap[PC_COUNT];    /* room each column actually holds (>= cap after a failed growth) */
    int state_stride;      /* doubles of plugin state per particle (max over materials) */
    int memo_stride;       /* doubles of PC_PLUGIN_MEMO per particle (max memo_size over the scene's plugins) */
    int t2;                /* 1: C and F keep their 2x2 in-plane blocks only (a 2D MPM scene; tensor2.h) */
    uint32_t enabled;      /* bit c set when column c is allocated */
    unsigned long edits;   /* bumped when particles are added, removed, reordered or overwritten
                            * wholesale: the MPM sort trusts the block keys G2P filed only while it stands */
    void *col[PC_COUNT];
} particles;

/// Name, components and element size of a column (state uses state_stride).
const char *particles_col_name(int c);
/// The name a store writes to a checkpoint: a 2x2 store's C and F are "C_xy" and "F_xy".
const char *particles_col_label(const particles *ps, int c);
int particles_col_ncomp(const particles *ps, int c);
int particles_col_is_int(int c);
size_t particles_col_bytes(const particles *ps, int c); /* bytes per particle */

static inline double *pcold(const particles *ps, int c) { return (double *)ps->col[c]; }
static inline int *pcoli(const particles *ps, int c) { return (int *)ps->col[c]; }

/* C and F of particle i whatever the store's width: a 2x2 store's are
 * embedded in plane strain (F_zz = 1, tensor2.h). */
static inline int particles_tn(const particles *ps) { return ps->t2 ? 4 : 9; }
static inline void particles_F3(const particles *ps, int i, double F[9]) {
    const double *f = pcold(ps, PC_F) + (size_t)particles_tn(ps) * i;
    if (ps->t2) t2_embed(f, 1.0, F);
    else for (int k = 0; k < 9; k++) F[k] = f[k];
}
static inline void particles_C3(const particles *ps, int i, double C[9]) {
    const double *c = pcold(ps, PC_C) + (size_t)particles_tn(ps) * i;
    if (ps->t2) t2_embed(c, 0.0, C);
    else for (int k = 0; k < 9; k++) C[k] = c[k];
}
/// det F of particle i
static inline double particles_J(const particles *ps, int i) {
    const double *f = pcold(ps, PC_F) + (size_t)particles_tn(ps) * i;
    return ps->t2 ? t2_det(f) : t3_det(f);
}
/// tr C of particle i (the rate of volume change)
static inline double particles_trC(const particles *ps, int i) {
    const double *c = pcold(ps, PC_C) + (size_t)particles_tn(ps) * i;
    return ps->t2 ? c[0] + c[3] : c[0] + c[4] + c[8];
}
/// C = 0 (a uniform motion) for particle i; with rest = 1 also F = I (a particle at rest)
static inline void particles_tensors_rest(particles *ps, int i, int rest) {
    const int tn = particles_tn(ps);
    double *c = pcold(ps, PC_C) + (size_t)tn * i, *f = pcold(ps, PC_F) + (size_t)tn * i;
    for (int k = 0; k < tn; k++) c[k] = 0.0;
    if (rest)
        for (int k = 0; k < tn; k++) f[k] = k % (tn == 4 ? 3 : 4) == 0;
}

void particles_init(particles *ps);
void particles_free(particles *ps);
/// Make room for cap particles in every enabled column, growing by at least
/// half the present capacity (amortised appends at a 1.5x spare, not 2x).
hearth_status particles_reserve(particles *ps, int cap, hearth_error *err);
/// Make room for exactly cap particles (a caller that knows its final count:
/// seeding), no spare.
hearth_status particles_reserve_exact(particles *ps, int cap, hearth_error *err);
/// Allocate an optional column (zeroed). Enabling twice is a no-op.
hearth_status particles_enable(particles *ps, int c, hearth_error *err);
/// Grow the plugin state stride, keeping existing state.
hearth_status particles_set_state_stride(particles *ps, int stride, hearth_error *err);
/// PC_PLUGIN_MEMO enabled with room for stride doubles a particle (at least); a wider one starts zeroed (a cache).
hearth_status particles_set_memo_stride(particles *ps, int stride, hearth_error *err);
/// Reorder every column so that new[i] = old[order[i]], through room bytes of
/// scratch, at least 4 n (the MPM sort lends its n keys, read by then); more
/// room lets more columns take the window's ring (particles.c).
void particles_permute(particles *ps, const int *order, void *scratch, size_t room);
/// The same when the caller knows W, the largest |order[i] - i| (the MPM sort finds it while it
/// fills order, which spares this a parallel region of its own).
void particles_permute_within(particles *ps, const int *order, int W, void *scratch, size_t room);
/// particles_permute_within for every thread of the caller's parallel region (all must call it with the
/// same W): it waits for the team (order filled), each thread takes whole columns through its 1 / T of
/// the scratch, and it returns past a barrier of the team that follows the moves (and so every
/// thread's work before the call). tw: the team's waits (team_wait.h), or NULL for OpenMP barriers.
void particles_permute_team(particles *ps, const int *order, int W, void *scratch, size_t room, struct team_wait *tw);
/// particles_permute_team by places instead of columns: this thread moves places [lo, hi) of every column (the
/// team's ranges tile [0, n)), so the records a thread owns stay in its core's cache (mpm.c's one-region step
/// gives each thread the places of the particle blocks it runs). The records within W outside [lo, hi) are saved
/// in this thread's 1 / T of the scratch before the team's barrier; when they and a ring of W + 1 records do not
/// fit there (a permutation that moves particles far), it is particles_permute_team. A range that moves under a
/// quarter of its places copies only the moved ones (particles.c's permute_sparse). Returns past a barrier:
/// 1 when it went by places, 0 by columns (the same on every thread).
int particles_permute_team_range(particles *ps, const int *order, int W, void *scratch, size_t room, int lo, int hi,
                                 struct team_wait *tw);
/// Copy every enabled column of src into dst (same layout); dst grows as needed.
hearth_status particles_copy(particles *dst, const particles *src, hearth_error *err);
/// Remove particles whose flag is non-zero, keeping order. Returns the number removed.
int particles_compact(particles *ps, const unsigned char *remove);
#endif
