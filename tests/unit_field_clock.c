/* unit_field_clock.c: the fields' own clock (fields/field_clock.c, issue 20).
 * A block in an oven with conduction and leavening: its fields' explicit
 * limit is about 1600 of its mechanical steps, so the automatic cycle spans
 * many steps. Each test prints what it measured. */
#include <math.h>
#include <string.h>

#include "field_clock.h"
#include "mpm_fixture.h"

/* The block both scenes bake, 0.3 m square at 20 degC, in `law` with parameters nm = nv (n of them). */
static hearth_scene *add_block(hearth_scene *s, const char *law, const char *const *nm, const double *nv, int n) {
    if (!s) return NULL;
    hearth_error err;
    const int m = hearth_scene_add_material(s, law, nm, nv, n, &err);
    if (m < 0) printf("  material: %s\n", err.msg);
    CHECK(m >= 0);
    hearth_shape *box = hearth_shape_box((const double[3]){0.5, 0.25, 0}, (const double[3]){0.15, 0.15, 0});
    hearth_body_def b = hearth_default_body_def();
    b.shape = box, b.material = m, b.temperature = 20;
    CHECK(hearth_scene_add_body(s, &b, &err) >= 0);
    hearth_shape_free(box);
    return s;
}

/* 2D, dx 1/32 m; an elastic block 0.3 m square, rho c = 2e4 J/(m^3 K), kappa 30 W/(m K): conduction's limit
 * rho c dx^2 / (4 kappa) = 0.163 s, the oven's (beta 25) 12.5 s; steps of dt_max 1e-4 s. CO2 from eq. 11. */
static hearth_scene *oven_block(int field_steps) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 1.0 / 32;
    d.dt_max = 1e-4;
    d.oven_temperature = 150;
    d.oven_beta = 25;
    d.field_steps = field_steps;
    const char *nm[] = {"E", "density", "specific_heat", "conductivity", "gas_rate", "reaction_temperature",
                        "reaction_width", "expansion", "reference_temperature"};
    const double nv[] = {1e5, 1000, 20, 30, 2.5e-5, 40, 20, 0.1, 20};
    return add_block(fx_scene_def(&d), "elastic", nm, nv, 9);
}

/* Steps until the k-th field update has closed its cycle (at most max steps); returns the steps taken. */
static long step_to_update(hearth_scene *s, int updates, long max) {
    hearth_error err;
    long n = 0;
    for (int u = 0; u < updates && n < max; n++) {
        CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
        u += s->field_phase == 0;
    }
    return n;
}

/* The automatic cycle covers at most FIELD_SAFETY of the limit, the time its own steps took, and
 * more than one step here; a pinned field_steps is obeyed; field_steps = 1 updates every step. */
TEST(field_clock_cycle_within_limit) {
    hearth_scene *a = oven_block(0), *p = oven_block(7), *one = oven_block(1);
    CHECK(a && p && one);
    if (!a || !p || !one) return;
    const long n = step_to_update(a, 2, 100000);
    hearth_stats st;
    hearth_scene_stats(a, &st);
    printf("  automatic: %ld steps to the second update; limit %.6g s, dt %.3g s, last update %.6g s over %d steps "
           "(%.4f of the limit)\n", n, st.field_limit, st.dt, st.field_dt, st.field_cycle, st.field_dt / st.field_limit);
    CHECK(st.field_cycle > 100);
    CHECK(n == 2L * st.field_cycle);
    CHECK(st.field_dt <= FIELD_SAFETY * st.field_limit);
    CHECK(fabs(st.field_dt - st.field_cycle * st.dt) <= 1e-12 * st.field_dt); /* the cycle's own steps' time */
    hearth_error err;
    CHECK(hearth_scene_step(p, 30, &err) == HEARTH_OK && hearth_scene_step(one, 30, &err) == HEARTH_OK);
    hearth_scene_stats(p, &st);
    printf("  field_steps = 7: last update over %d steps (%.3g s); phase after 30 steps %d\n", st.field_cycle,
           st.field_dt, p->field_phase);
    CHECK(st.field_cycle == 7 && p->field_phase == 30 % 7);
    hearth_scene_stats(one, &st);
    printf("  field_steps = 1: last update over %d step (%.3g s)\n", st.field_cycle, st.field_dt);
    CHECK(st.field_cycle == 1 && st.field_dt == st.dt);
    hearth_scene_destroy(a);
    hearth_scene_destroy(p);
    hearth_scene_destroy(one);
}

/* Heat taken in, hottest particle and CO2 after three automatic cycles against single rate over the same
 * steps. The measures: the heat gained relative to itself, the hottest particle's rise, the CO2 made. */
TEST(field_clock_matches_single_rate) {
    hearth_scene *a = oven_block(0), *one = oven_block(1);
    CHECK(a && one);
    if (!a || !one) return;
    hearth_stats s0;
    hearth_scene_stats(a, &s0);
    const long n = step_to_update(a, 3, 100000);
    hearth_error err;
    CHECK(hearth_scene_step(one, (int)n, &err) == HEARTH_OK);
    hearth_stats sa, s1;
    hearth_scene_stats(a, &sa);
    hearth_scene_stats(one, &s1);
    double ta = -INFINITY, t1 = -INFINITY;
    for (int i = 0; i < a->ps.n; i++) ta = fmax(ta, pcold(&a->ps, PC_TEMPERATURE)[i]);
    for (int i = 0; i < one->ps.n; i++) t1 = fmax(t1, pcold(&one->ps, PC_TEMPERATURE)[i]);
    const double qa = sa.heat_energy - s0.heat_energy, q1 = s1.heat_energy - s0.heat_energy;
    const double dq = qa / q1 - 1, dT = (ta - t1) / (t1 - 20), dg = sa.gas_moles / s1.gas_moles - 1;
    printf("  %ld steps (3 cycles of %d), t = %.4g s: heat in %.8g (cycle) vs %.8g J/m (every step), %+.2e; hottest %.6f vs "
           "%.6f degC (%+.2e of its rise); CO2 %.8g vs %.8g mol/m (%+.2e)\n", n, sa.field_cycle, sa.t, qa, q1, dq, ta, t1,
           dT, sa.gas_moles, s1.gas_moles, dg);
    CHECK(sa.t == s1.t && sa.field_cycle > 100 && s1.field_cycle == 1);
    CHECK(q1 > 0 && t1 > 20 && s1.gas_moles > 0);
    CHECK(fabs(dq) < 1e-2);
    CHECK(fabs(dT) < 5e-2); /* the corner particle's FLIP jumps: first order in the update's time */
    CHECK(fabs(dg) < 1e-3);
    hearth_scene_destroy(a);
    hearth_scene_destroy(one);
}

/* Saved mid-cycle (a checkpoint in memory) and restored, the scene closes its cycle on the same step over the
 * same time: the same bits as the unbroken run, past the next update. */
TEST(field_clock_checkpoint_mid_cycle) {
    hearth_scene *s = oven_block(0);
    CHECK(s != NULL);
    if (!s) return;
    hearth_error err;
    CHECK(hearth_scene_step(s, 250, &err) == HEARTH_OK);
    const int phase = s->field_phase;
    const double acc = s->field_acc;
    char path[] = "field_clock_mid_cycle.ck";
    CHECK(hearth_scene_save(s, path, &err) == HEARTH_OK);
    hearth_scene *r = hearth_scene_load(path, &err);
    remove(path);
    if (!r) printf("  load: %s\n", err.msg);
    CHECK(r != NULL);
    if (!r) return;
    CHECK(r->field_phase == phase && r->field_acc == acc);
    CHECK(hearth_scene_step(s, 200, &err) == HEARTH_OK && hearth_scene_step(r, 200, &err) == HEARTH_OK);
    hearth_stats st;
    hearth_scene_stats(r, &st);
    printf("  saved at step 250, %d steps (%.4g s) into a cycle; 200 steps on: updates every %d steps, hash %016llx "
           "unbroken, %016llx restored\n", phase, acc, st.field_cycle, (unsigned long long)hearth_scene_hash(s),
           (unsigned long long)hearth_scene_hash(r));
    /* an update came between: the cycle closed after st.field_cycle - phase steps and restarted */
    CHECK(phase > 0 && phase + 200 >= st.field_cycle && r->field_phase == phase + 200 - st.field_cycle);
    CHECK(hearth_scene_hash(s) == hearth_scene_hash(r));
    hearth_scene_destroy(s);
    hearth_scene_destroy(r);
}

/* The cycle and its updates give the same bits at 1 and 2 threads. */
TEST(field_clock_threads_same_bits) {
    unsigned long long h[2];
    for (int t = 1; t <= 2; t++) {
        hearth_set_threads(t);
        hearth_scene *s = oven_block(0);
        CHECK(s != NULL);
        if (!s) return;
        step_to_update(s, 2, 100000);
        hearth_error err;
        CHECK(hearth_scene_step(s, 37, &err) == HEARTH_OK);
        h[t - 1] = (unsigned long long)hearth_scene_hash(s);
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
    printf("  two updates and 37 steps: hash %016llx at 1 thread, %016llx at 2\n", h[0], h[1]);
    CHECK(h[0] == h[1]);
}

/* The oven block in cam_clay_dough, which gives bulk_modulus and stress_block: eq. 10 as a thermal strain
 * through the batched door, so both memos (exp_memo.h) are live, the thermal split's and the CO2's. */
static hearth_scene *dough_block(void) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 1.0 / 32;
    d.dt_max = 1e-4;
    d.oven_temperature = 150;
    d.oven_beta = 25;
    const char *nm[] = {"density", "specific_heat", "conductivity", "gas_rate", "reaction_temperature",
                        "reaction_width", "expansion", "reference_temperature"};
    const double nv[] = {1000, 20, 30, 2.5e-5, 40, 20, 0.1, 20};
    return add_block(fx_scene_def(&d), "cam_clay_dough", nm, nv, 8);
}

/* The memos are read between the fields' updates, and give the bits of the exp they stand for: a dough
 * block through two updates and 37 steps hashes the same whether its memos work or are emptied before every
 * step (every exp computed, as before the memos), and differently once a memo's value is falsified one step
 * after the update (the steps after read it). Each filled memo holds exp of its argument. */
TEST(field_clock_memos_read_for_same_bits) {
    hearth_scene *s[3] = {dough_block(), dough_block(), dough_block()}; /* memos; emptied each step; falsified once */
    CHECK(s[0] && s[1] && s[2]);
    if (!s[0] || !s[1] || !s[2]) goto done;
    const int memo[2] = {PC_THERMAL_MEMO, PC_GAS_MEMO};
    for (int k = 0; k < 2; k++) CHECK(s[0]->ps.enabled & (1u << memo[k]));
    hearth_error err;
    int hits[2] = {0, 0};
    for (int v = 0; v < 3; v++) {
        particles *ps = &s[v]->ps;
        long steps = 0;
        for (int u = 0; u < 2 && steps < 100000; steps++) {
            if (v == 1)
                for (int k = 0; k < 2; k++) memset(ps->col[memo[k]], 0, sizeof(double) * 2 * (size_t)ps->n);
            CHECK(hearth_scene_step(s[v], 1, &err) == HEARTH_OK);
            u += s[v]->field_phase == 0;
        }
        if (v == 0)
            for (int k = 0; k < 2; k++) {
                const double *m = pcold(ps, memo[k]);
                for (int i = 0; i < ps->n; i++) {
                    hits[k] += m[2 * i + 1] != 0;
                    if (m[2 * i + 1] != 0) CHECK(m[2 * i + 1] == exp(m[2 * i]));
                }
            }
        for (int j = 0; j < 37; j++) {
            /* the step after an update fills the memos at the new temperatures; then every filled memo's value
             * off by a factor: the next steps read it where the argument holds */
            if (v == 2 && j == 1)
                for (int k = 0; k < 2; k++) {
                    double *m = pcold(ps, memo[k]);
                    for (int i = 0; i < ps->n; i++) m[2 * i + 1] *= 1.5;
                }
            if (v == 1)
                for (int k = 0; k < 2; k++) memset(ps->col[memo[k]], 0, sizeof(double) * 2 * (size_t)ps->n);
            CHECK(hearth_scene_step(s[v], 1, &err) == HEARTH_OK);
        }
        printf("  %s: %ld steps to the second update, 37 more: hash %016llx\n",
               v == 0 ? "memos" : v == 1 ? "memos emptied each step" : "memos falsified after the update", steps,
               (unsigned long long)hearth_scene_hash(s[v]));
    }
    hearth_stats st;
    hearth_scene_stats(s[0], &st);
    printf("  %d particles, updates every %d steps; filled memos after the second update: thermal split %d, CO2 %d\n",
           s[0]->ps.n, st.field_cycle, hits[0], hits[1]);
    CHECK(st.field_cycle > 37); /* the 37 steps after the update are all between updates */
    CHECK(hits[0] > 0 && hits[1] > 0);
    CHECK(hearth_scene_hash(s[0]) == hearth_scene_hash(s[1]));
    CHECK(hearth_scene_hash(s[0]) != hearth_scene_hash(s[2]));
done:
    for (int v = 0; v < 3; v++)
        if (s[v]) hearth_scene_destroy(s[v]);
}

/* The plugin's memo (PC_PLUGIN_MEMO, <hearth/material.h> rule 10: cam_clay_dough's log b_zz) gives log's bits
 * and is read between the fields' updates, where a point that does not flow keeps its b_zz (a plastic step
 * rebuilds it): the 2D dough block through an update and 37 steps hashes the same
 * with the memo working and emptied before every step (every log computed, as before it), and differently
 * when every filled entry's value is moved by 1e-12 one step after the update (the steps after read it). Each
 * filled entry holds log of its key. */
TEST(field_clock_plugin_memo_same_bits) {
    hearth_scene *s[3] = {dough_block(), dough_block(), dough_block()}; /* memo; emptied each step; falsified once */
    CHECK(s[0] && s[1] && s[2]);
    if (!s[0] || !s[1] || !s[2]) goto done;
    CHECK(s[0]->ps.enabled & (1u << PC_PLUGIN_MEMO));
    hearth_error err;
    int filled = 0;
    for (int v = 0; v < 3; v++) {
        particles *ps = &s[v]->ps;
        const int w = ps->memo_stride;
        const size_t bytes = sizeof(double) * (size_t)w * (size_t)ps->n;
        long steps = 0;
        for (int u = 0; u < 1 && steps < 100000; steps++) {
            if (v == 1) memset(ps->col[PC_PLUGIN_MEMO], 0, bytes);
            if (hearth_scene_step(s[v], 1, &err) != HEARTH_OK) {
                printf("  step: %s\n", err.msg);
                CHECK(0);
                goto done;
            }
            u += s[v]->field_phase == 0;
        }
        for (int j = 0; j < 37; j++) {
            if (v == 2 && j == 1) /* filled at the step after the update; read by the steps after */
                for (int i = 0; i < ps->n; i++) pcold(ps, PC_PLUGIN_MEMO)[(size_t)w * i + 1] += 1e-12;
            if (v == 1) memset(ps->col[PC_PLUGIN_MEMO], 0, bytes);
            if (hearth_scene_step(s[v], 1, &err) != HEARTH_OK) {
                printf("  step: %s\n", err.msg);
                CHECK(0);
                goto done;
            }
        }
        if (v == 0) {
            const double *m = pcold(ps, PC_PLUGIN_MEMO);
            for (int i = 0; i < ps->n; i++, m += w)
                if (m[0] != 0) {
                    filled++;
                    CHECK(m[1] == log(m[0]));
                }
        }
        printf("  %s: %ld steps to the update, 37 more: hash %016llx\n",
               v == 0 ? "memo" : v == 1 ? "memo emptied each step" : "memo falsified after the update", steps,
               (unsigned long long)hearth_scene_hash(s[v]));
    }
    printf("  %d particles, %d filled memo entries\n", s[0]->ps.n, filled);
    CHECK(filled > 0);
    CHECK(hearth_scene_hash(s[0]) == hearth_scene_hash(s[1]));
    CHECK(hearth_scene_hash(s[0]) != hearth_scene_hash(s[2]));
done:
    for (int v = 0; v < 3; v++)
        if (s[v]) hearth_scene_destroy(s[v]);
}

/* The temperature curves' memo (PC_CURVE_MEMO, material_batch.c) gives the curves' bits: the dough block with
 * an irreversible curve on tau_y through an update and 20 steps, then a reversible one on E added (a new stamp:
 * entries written for tau_y alone hold no E) and 20 more steps, then a third, on eta (beyond the memo's two
 * values: evaluated every step), through the next update and 37 steps; it hashes the same whether its memo works
 * or is emptied before every step, and differently once the memo's values are falsified one step after the
 * update (the steps after read them). */
TEST(field_clock_curve_memo_same_bits) {
    hearth_scene *s[3] = {dough_block(), dough_block(), dough_block()}; /* memo; emptied each step; falsified once */
    CHECK(s[0] && s[1] && s[2]);
    if (!s[0] || !s[1] || !s[2]) goto done;
    hearth_error err;
    const double T[2] = {20, 60}, ty[2] = {200, 2000}, E[2] = {1e5, 5e4}, eta[2] = {500, 100};
    int hits = 0, updates = 0;
    for (int v = 0; v < 3; v++) {
        particles *ps = &s[v]->ps;
        const size_t bytes = sizeof(double) * CURVE_MEMO_WIDTH * (size_t)ps->n;
        CHECK(hearth_scene_material_curve(s[v], 0, "tau_y", 2, T, ty, 1, &err) == HEARTH_OK);
        CHECK(ps->enabled & (1u << PC_CURVE_MEMO));
        long steps = 0;
        for (int u = 0, j = 0; u < 2 && steps < 100000; steps++) {
            if (u == 1 && j == 20) CHECK(hearth_scene_material_curve(s[v], 0, "E", 2, T, E, 0, &err) == HEARTH_OK);
            if (u == 1 && j == 40) CHECK(hearth_scene_material_curve(s[v], 0, "eta", 2, T, eta, 0, &err) == HEARTH_OK);
            j += u == 1;
            if (v == 1) memset(ps->col[PC_CURVE_MEMO], 0, bytes);
            CHECK(hearth_scene_step(s[v], 1, &err) == HEARTH_OK);
            u += s[v]->field_phase == 0;
        }
        if (v == 0) {
            const material_slot *ms = &s[v]->mats.slot[0];
            const double *m = pcold(ps, PC_CURVE_MEMO);
            for (int i = 0; i < ps->n; i++, m += CURVE_MEMO_WIDTH) {
                hits += m[0] == ms->curve_stamp;
                if (m[0] == ms->curve_stamp) /* tau_y at T_max, E at T: the first two temperature curves */
                    CHECK(m[3] == curve_eval(&ms->curves[0], m[2]) && m[4] == curve_eval(&ms->curves[1], m[1]));
            }
            updates = (int)steps;
        }
        for (int j = 0; j < 37; j++) {
            if (v == 2 && j == 1)
                for (int i = 0; i < ps->n; i++) /* E's (an elastic block: tau_y's bound is not reached) */
                    pcold(ps, PC_CURVE_MEMO)[CURVE_MEMO_WIDTH * i + 4] *= 1.5;
            if (v == 1) memset(ps->col[PC_CURVE_MEMO], 0, bytes);
            CHECK(hearth_scene_step(s[v], 1, &err) == HEARTH_OK);
        }
        printf("  %s: %ld steps to the second update, 37 more: hash %016llx\n",
               v == 0 ? "memo" : v == 1 ? "memo emptied each step" : "memo falsified after the update", steps,
               (unsigned long long)hearth_scene_hash(s[v]));
    }
    printf("  %d particles; %d steps to the second update; filled entries after it %d; curves %d, stamp %d\n",
           s[0]->ps.n, updates, hits, s[0]->mats.slot[0].ncurves, s[0]->mats.slot[0].curve_stamp);
    CHECK(updates > 60); /* the curves were added between the updates */
    CHECK(hits > 0);
    CHECK(hearth_scene_hash(s[0]) == hearth_scene_hash(s[1]));
    CHECK(hearth_scene_hash(s[0]) != hearth_scene_hash(s[2]));
done:
    for (int v = 0; v < 3; v++)
        if (s[v]) hearth_scene_destroy(s[v]);
}

/* field_steps outside [0, 4096] is refused, naming the setting and its range. */
TEST(field_clock_bad_setting) {
    hearth_scene_def d = hearth_default_scene_def();
    hearth_error err;
    for (int k = 0; k < 2; k++) {
        d.field_steps = k ? 5000 : -1;
        hearth_scene *s = hearth_scene_create(&d, &err);
        CHECK(s == NULL);
        if (s) hearth_scene_destroy(s);
        printf("  field_steps = %d: %s\n", d.field_steps, err.msg);
        CHECK_STR_CONTAINS(err.msg, "field_steps");
        CHECK_STR_CONTAINS(err.msg, "4096");
    }
}

TEST_MAIN(T(field_clock_cycle_within_limit), T(field_clock_matches_single_rate), T(field_clock_checkpoint_mid_cycle),
          T(field_clock_threads_same_bits), T(field_clock_bad_setting), T(field_clock_memos_read_for_same_bits), T(field_clock_plugin_memo_same_bits),
          T(field_clock_curve_memo_same_bits))
