/* unit_subcell.c: the sub-cell heat exchange among dried particles
 * (fields/subcell.c, issue #18): exactly conserving, blind to wet particles,
 * exact on linear profiles, damping the sub-cell mode FLIP leaves, and the
 * same bits at 1 and 2 threads. What it does to the drying front and the
 * crust's temperatures is unit_drying_front.c's. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "mpm_fixture.h"
#include "material.h"
#include "subcell.h"

/* bread's numbers (lua/hearth/dough_physical.lua) and a dried specific heat, so C_p moves with the water */
static const double RHO = 484, CP = 2700, CPD = 1500, KW = 0.51, KD = 0.23, SAT = 0.218;

/* A pinned 24 x 12 mm block (dx 2 mm: 12 x 6 cells, 288 particles) in a 200 degC oven with latent_heat, stepped
 * once so that the grid holds the particles' stencils (pinned: they stay). */
static hearth_scene *block(double dx, double w, double h) {
    hearth_scene_def d = fx_oven_def(dx, 200, 30);
    d.latent_heat = 1;
    d.heat_implicit = 1;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NULL;
    hearth_error err;
    const char *nm[] = {"E", "density", "conductivity", "specific_heat", "dry_conductivity", "dry_specific_heat"};
    const double v[] = {1e-2, RHO, KW, CP, KD, CPD};
    const int m = hearth_scene_add_material(s, "elastic", nm, v, 6, &err);
    CHECK(m >= 0);
    const double c[3] = {0.05, 0.03, 0}, hh[3] = {0.5 * w, 0.5 * h, 0};
    CHECK(fx_pinned_box(s, m, c, hh, 100, SAT) >= 0);
    CHECK(hearth_scene_set_dt_limits(s, 0.5, 1.0, &err) == HEARTH_OK);
    CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
    return s;
}

static double heat_capacity(const hearth_scene *s, int i) {
    const material_slot *ms = &s->mats.slot[pcoli(&s->ps, PC_MAT)[i]];
    return pcold(&s->ps, PC_MASS)[i] * material_specific_heat(ms, &s->ps, i);
}

/* The upper half of the block dried (water 0), the lower half wet at 100 degC;
 * the dried particles at a linear profile in x and y, plus amp times +-1 by
 * the parity of their row and column (the sub-cell mode: two particles a cell
 * along each axis). */
static void set_state(hearth_scene *s, double amp) {
    particles *ps = &s->ps;
    const double *X = pcold(ps, PC_X), dx = s->g.dx;
    double *T = pcold(ps, PC_TEMPERATURE), *W = pcold(ps, PC_WATER);
    for (int i = 0; i < ps->n; i++) {
        const double x = X[3 * i] - 0.05, y = X[3 * i + 1] - 0.03;
        if (y > 0) {
            const long r = lround(floor(y / (0.5 * dx))), c = lround(floor(x / (0.5 * dx)));
            W[i] = 0;
            T[i] = 120 + 2000 * y + 500 * x + amp * ((r + c) % 2 ? 1 : -1);
        } else {
            T[i] = 100;
        }
    }
}

/* Each bar a priori:
 * - heat: sum C_p T_p over every particle unchanged to 1e-12 of the
 *   exchanged heat's scale (sum C_p times the mode's amplitude): the exchange
 *   is a node-by-node identity (subcell.c), so only rounding remains;
 * - the wet particles' temperatures unchanged bit for bit (phi = 0);
 * - a linear profile over the dried half unchanged to 1e-9 K, the surface and
 *   the wet boundary's particles included (each node's fit is exact there);
 * - the +-1 K sub-cell mode falls to under half: r = pi^2 kappa_d / (rho
 *   alpha_d (dx/2)^2) = 3.1 1/s here, so 1 - exp(-r dt) = 0.956 of the way
 *   over dt = 1 s toward the fits, which see the mode only where a node's
 *   neighbours are few (the block's edges);
 * - with no dried particle (all wet) nothing changes, bit for bit. */
TEST(subcell_conserves_heat_and_keeps_linear_profiles) {
    hearth_scene *s = block(0.002, 0.024, 0.012);
    CHECK(s != NULL);
    if (!s) return;
    particles *ps = &s->ps;
    const int n = ps->n;
    double *T = pcold(ps, PC_TEMPERATURE), *Tw = malloc(sizeof(double) * (size_t)n);
    hearth_error err;
    /* all wet: nothing moves */
    memcpy(Tw, T, sizeof(double) * (size_t)n);
    CHECK(subcell_exchange(s, 1.0, &err) == HEARTH_OK);
    CHECK(memcmp(Tw, T, sizeof(double) * (size_t)n) == 0);
    /* linear */
    set_state(s, 0);
    memcpy(Tw, T, sizeof(double) * (size_t)n);
    CHECK(subcell_exchange(s, 1.0, &err) == HEARTH_OK);
    double lin = 0;
    int wet_same = 1, ndry = 0;
    const double *W = pcold(ps, PC_WATER);
    for (int i = 0; i < n; i++) {
        if (W[i] == 0) lin = fmax(lin, fabs(T[i] - Tw[i])), ndry++;
        else wet_same &= memcmp(&T[i], &Tw[i], sizeof(double)) == 0;
    }
    /* the mode */
    set_state(s, 1.0);
    double E0 = 0, C = 0;
    for (int i = 0; i < n; i++) E0 += heat_capacity(s, i) * T[i], C += heat_capacity(s, i);
    CHECK(subcell_exchange(s, 1.0, &err) == HEARTH_OK);
    double E1 = 0, mode = 0;
    const double *X = pcold(ps, PC_X);
    for (int i = 0; i < n; i++) {
        E1 += heat_capacity(s, i) * T[i];
        if (W[i] == 0) mode = fmax(mode, fabs(T[i] - (120 + 2000 * (X[3 * i + 1] - 0.03) + 500 * (X[3 * i] - 0.05))));
        else wet_same &= T[i] == 100;
    }
    printf("  %d particles, %d dried: a linear profile moves by %.3g K at most; the +-1 K mode is %.4f K after; "
           "heat %.6e J/m before, change %.3g of sum C x 1 K; wet particles unchanged: %s\n",
           n, ndry, lin, mode, E0, (E1 - E0) / C, wet_same ? "yes" : "no");
    CHECK(ndry > 0 && ndry < n);
    CHECK(lin < 1e-9);
    CHECK(mode < 0.5);
    CHECK(fabs(E1 - E0) < 1e-12 * C);
    CHECK(wet_same);
    free(Tw);
    hearth_scene_destroy(s);
}

/* The 24 x 24 mm block at dx 1 mm (2304 particles, past SCENE_PARALLEL_MIN) with its top 3 mm dried at
 * 130 degC over wet particles at the boiling point: the three same-bits cases below start from it. */
static hearth_scene *dried_top_block(void) {
    hearth_scene *s = block(0.001, 0.024, 0.024);
    CHECK(s != NULL);
    if (!s) return NULL;
    particles *ps = &s->ps;
    const double *X = pcold(ps, PC_X);
    double *T = pcold(ps, PC_TEMPERATURE), *W = pcold(ps, PC_WATER);
    for (int i = 0; i < ps->n; i++)
        if (X[3 * i + 1] > 0.042 - 0.003) W[i] = 0, T[i] = 130;
    CHECK(ps->n >= SCENE_PARALLEL_MIN);
    return s;
}

/* A 24 x 24 mm block at dx 1 mm (2304 particles, past SCENE_PARALLEL_MIN: the
 * step runs on two threads) with its top 3 mm dried at 130 degC, 20 implicit
 * steps of 1 s with latent_heat: the same hash at 1 and 2 threads (the
 * exchange walks the particles in their sorted order, the same at any count),
 * and the exchange ran (dried particles present at the end). */
TEST(subcell_threads_same_bits) {
    uint64_t h[2] = {0, 1};
    int ndry = 0;
    for (int t = 1; t <= 2; t++) {
        hearth_set_threads(t);
        hearth_scene *s = dried_top_block();
        if (!s) break;
        particles *ps = &s->ps;
        hearth_error err;
        CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
        h[t - 1] = hearth_scene_hash(s);
        ndry = 0; /* dried as subcell.c counts them: the moisture ratio under 0.01 */
        for (int i = 0; i < ps->n; i++) ndry += material_moisture_ratio(&s->mats.slot[pcoli(ps, PC_MAT)[i]], ps, i) < 0.01;
        printf("  %d thread(s): %d particles, %d dried, hash %016llx\n", t, ps->n, ndry, (unsigned long long)h[t - 1]);
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
    CHECK(ndry > 0);
    CHECK(h[0] == h[1]);
}

/* The boiling front's pass (water_boil_front, water.c) on the same block: its wet
 * particles start at the boiling point under the 130 degC dried top, so heat
 * reaches them and they boil in each of the 20 steps. The pass is serial over
 * the sorted particles, so the hash must be the same at 1 and 2 threads; and
 * the pass must have had boiling heat to hand out in the last step (some
 * wet particle's E_p > 0 in its scratch), else this checks nothing. */
TEST(boil_front_threads_same_bits) {
    uint64_t h[2] = {0, 1};
    int boiling[2] = {0, 0};
    for (int t = 1; t <= 2; t++) {
        hearth_set_threads(t);
        hearth_scene *s = dried_top_block();
        if (!s) break;
        particles *ps = &s->ps;
        hearth_error err;
        CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
        h[t - 1] = hearth_scene_hash(s);
        int any = 0; /* E_p > 0 also on dried particles a rounding above the water floor (water.c keeps theirs) */
        for (int i = 0; i < ps->n && s->water.front; i++) {
            any += s->water.front[2 * i] > 0;
            boiling[t - 1] += s->water.front[2 * i] > 0 && material_moisture_ratio(&s->mats.slot[pcoli(ps, PC_MAT)[i]], ps, i) > 0.01;
        }
        printf("  %d thread(s): %d particles, %d wet ones boiling in the last step (%d with E_p > 0), hash %016llx\n", t, ps->n,
               boiling[t - 1], any,
               (unsigned long long)h[t - 1]);
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
    CHECK(boiling[0] > 0 && boiling[0] == boiling[1]);
    CHECK(h[0] == h[1]);
}

/* The front's passes walk only the front on one rank (boil_front.c: G_i where this pass's senders reach,
 * the receivers whose stencil reaches those blocks, the pair weights once a step, nothing on a step where no
 * particle passed T_b) and claim the bits of the walk over every node and particle that MPI slabs keep. On
 * the block above with its lower half at 60 degC (a front over wet particles that do not boil, which the
 * front's own walk passes by), one thread, the two walks (water_state's front_walk_all) must give the same
 * hash, with some wet particles boiling in the last step and some not, else this checks nothing. */
TEST(boil_front_walk_same_bits) {
    uint64_t h[2] = {0, 1};
    int boiling = 0, wet = 0;
    hearth_set_threads(1);
    for (int all = 0; all <= 1; all++) {
        hearth_scene *s = dried_top_block();
        if (!s) break;
        s->water.front_walk_all = all;
        particles *ps = &s->ps;
        const double *X = pcold(ps, PC_X);
        double *T = pcold(ps, PC_TEMPERATURE);
        for (int i = 0; i < ps->n; i++)
            if (X[3 * i + 1] < 0.030) T[i] = 60; /* a cool bottom: wet particles that do not boil */
        hearth_error err;
        CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
        h[all] = hearth_scene_hash(s);
        boiling = wet = 0;
        for (int i = 0; i < ps->n && s->water.front; i++) {
            const int w = material_moisture_ratio(&s->mats.slot[pcoli(ps, PC_MAT)[i]], ps, i) > 0.01;
            wet += w;
            boiling += s->water.front[2 * i] > 0 && w;
        }
        printf("  %s: %d of %d wet particles boiling in the last step, hash %016llx\n",
               all ? "every node and particle" : "the front's own", boiling, wet, (unsigned long long)h[all]);
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
    CHECK(boiling > 0 && boiling < wet);
    CHECK(h[0] == h[1]);
}

TEST_MAIN(T(subcell_conserves_heat_and_keeps_linear_profiles), T(subcell_threads_same_bits), T(boil_front_threads_same_bits),
          T(boil_front_walk_same_bits))
