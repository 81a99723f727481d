/* unit_two_field.c: two velocity fields at a crack (scene setting two_field,
 * core/sim/solver/mpm_two_field.c).
 *
 * The scenes: two blocks of one material side by side, touching along the
 * line x = X0, no gravity, far from every wall. The particles within dx/2 of
 * the line are cracked (the dough's damage state set to 1), the rest intact:
 * a crack through one body. The closed forms, from momentum alone:
 *  - each block is a free body as soon as the crack carries nothing, so each
 *    keeps its own momentum, in the direction along the crack (sliding) and
 *    away from it (opening); the pair's total is kept in every case;
 *  - with one field the nodes on the crack move both sides together, so each
 *    block's momentum does not stay its own: the same scenes with two_field
 *    off show the tests can fail. */
#include <stdint.h>
#include <stdio.h>

#include "mpm_fixture.h"

#define X0 0.1
/* a step call that must succeed: 1 when it did, else the message printed and the case failed */
static int check_ok_(hearth_status st, const hearth_error *err, int line) {
    if (st == HEARTH_OK) return 1;
    fprintf(stderr, "%s:%d: step failed: %s\n", __FILE__, line, err->msg);
    test_failures++;
    return 0;
}
#define CHECK_OK(st, err) check_ok_((st), &(err), __LINE__)
enum { S_DAMAGE = 7 }; /* cam_clay_dough's state: b^E (6), J^P, then the damage (plugins/cam_clay_dough.c) */

/* Two blocks meeting at X0, the left moving at vl and the right at vr, and a crack along X0 unless intact. */
static hearth_scene *blocks(double dx, int two_field, const double vl[3], const double vr[3], int intact) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 2;
    d.dx = dx;
    d.lo[0] = d.lo[1] = 0;
    d.hi[0] = d.hi[1] = 0.2;
    d.gravity[0] = d.gravity[1] = d.gravity[2] = 0;
    d.two_field = two_field;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NULL;
    /* a stiff dough that stays elastic at these speeds (tau_y far above its stresses); it may crack */
    const char *nm[] = {"E", "nu", "tau_y", "eta", "density", "fracture_strain"};
    const double nv[] = {2e5, 0.3, 1e9, 0, 1000, 0.5};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "cam_clay_dough", nm, nv, 6, &err);
    CHECK(m >= 0);
    const double h[3] = {0.025, 0.04, 0}, cl[3] = {X0 - 0.025, 0.1, 0}, cr[3] = {X0 + 0.025, 0.1, 0};
    fx_box(s, m, cl, h, 4, vl);
    fx_box(s, m, cr, h, 4, vr);
    if (!intact) {
        const double *X = pcold(&s->ps, PC_X);
        double *st = pcold(&s->ps, PC_STATE);
        for (int i = 0; i < s->ps.n; i++)
            if (fabs(X[3 * i] - X0) < dx / 2) st[(size_t)i * s->ps.state_stride + S_DAMAGE] = 1;
    }
    return s;
}

/* momentum of the particles left of X0 at the start (ids below half: the left block was seeded first) and right */
static void momenta(const hearth_scene *s, int nleft, double pl[2], double pr[2]) {
    const particles *ps = &s->ps;
    const double *V = pcold(ps, PC_V), *M = pcold(ps, PC_MASS);
    const int *id = pcoli(ps, PC_ID);
    pl[0] = pl[1] = pr[0] = pr[1] = 0;
    for (int i = 0; i < ps->n; i++) {
        double *p = id[i] < nleft ? pl : pr;
        p[0] += M[i] * V[3 * i];
        p[1] += M[i] * V[3 * i + 1];
    }
}

/* Runs the two blocks for steps and returns the left block's momentum kept along axis (1 = all of it), and the
 * pair's total momentum change over the initial momentum scale. */
static void run_pair(int two_field, const double vl[3], const double vr[3], int axis, double *kept, double *drift) {
    hearth_scene *s = blocks(0.01, two_field, vl, vr, 0);
    CHECK(s != NULL);
    if (!s) return;
    const int nleft = s->ps.n / 2;
    double pl0[2], pr0[2], pl[2], pr[2];
    momenta(s, nleft, pl0, pr0);
    hearth_error err;
    /* 0.1 s: the blocks move 1 cell either way (0.1 m/s), and waves cross them several times */
    const double until = 0.1;
    while (s->t < until - 1e-12)
        if (!CHECK_OK(hearth_scene_step(s, 1, &err), err)) break;
    momenta(s, nleft, pl, pr);
    const double scale = fabs(pl0[0]) + fabs(pl0[1]) + fabs(pr0[0]) + fabs(pr0[1]);
    *kept = pl[axis] / pl0[axis];
    *drift = (fabs(pl[0] + pr[0] - pl0[0] - pr0[0]) + fabs(pl[1] + pr[1] - pl0[1] - pr0[1])) / scale;
    printf("  two_field %d: after %ld steps (t = %.3f s) the left block keeps %.9f of its momentum along %c; "
           "total momentum change %.3g of the initial\n",
           two_field, s->step, s->t, *kept, "xy"[axis], *drift);
    hearth_scene_destroy(s);
}

/* Sliding along the crack: the left block up, the right down. Two fields: each keeps its momentum, the total to
 * 1e-12. One field: the crack's nodes drag them together (0.38 kept). Each block's own momentum is kept to 1e-4,
 * not to rounding: where the blocks have slid past each other's ends the crack's damage ridge ends, its
 * gradients turn, and a few nodes there put particles of both blocks in one field (measured 6.8e-5 at dx 1 cm). */
TEST(two_field_crack_slides_free) {
    const double vl[3] = {0, 0.1, 0}, vr[3] = {0, -0.1, 0};
    double kept, drift, kept1, drift1;
    run_pair(1, vl, vr, 1, &kept, &drift);
    run_pair(0, vl, vr, 1, &kept1, &drift1);
    CHECK_NEAR(kept, 1.0, 1e-4);
    CHECK(drift < 1e-12);
    CHECK(kept1 < 0.9); /* the one-field step sticks: the test can fail */
}

/* Opening: the blocks move apart across the crack. Two fields: each keeps its momentum, the total to 1e-12. */
TEST(two_field_crack_opens_free) {
    const double vl[3] = {-0.1, 0, 0}, vr[3] = {0.1, 0, 0};
    double kept, drift, kept1, drift1;
    run_pair(1, vl, vr, 0, &kept, &drift);
    run_pair(0, vl, vr, 0, &kept1, &drift1);
    CHECK_NEAR(kept, 1.0, 1e-9);
    CHECK(drift < 1e-12);
    CHECK(kept1 < 0.9);
}

/* Closing: the blocks move toward each other across the crack. The contact correction keeps them from passing
 * through each other (the same normal velocity at the crack's nodes) and keeps the total momentum (to 1e-12):
 * the left block is stopped at least as much as with one field's sticking. */
TEST(two_field_crack_closes_in_contact) {
    const double vl[3] = {0.1, 0, 0}, vr[3] = {-0.1, 0, 0};
    double kept, drift, kept1, drift1;
    run_pair(1, vl, vr, 0, &kept, &drift);
    run_pair(0, vl, vr, 0, &kept1, &drift1);
    CHECK(drift < 1e-12);
    CHECK(kept < 0.9); /* the contact stops the approach: no free pass through the crack */
}

/* Friction: sliding along a crack that is pressed shut (the blocks also approach): with two_field_friction 0.5
 * the sliding momentum decays, and faster than without friction; the total is kept. */
TEST(two_field_crack_friction) {
    double kept[2];
    for (int f = 0; f < 2; f++) {
        hearth_scene *s = blocks(0.01, 1, (const double[3]){0.05, 0.1, 0}, (const double[3]){-0.05, -0.1, 0}, 0);
        CHECK(s != NULL);
        if (!s) return;
        s->def.two_field_friction = f ? 0.5 : 0.0;
        const int nleft = s->ps.n / 2;
        double pl0[2], pr0[2], pl[2], pr[2];
        momenta(s, nleft, pl0, pr0);
        hearth_error err;
        while (s->t < 0.05 - 1e-12)
            if (!CHECK_OK(hearth_scene_step(s, 1, &err), err)) break;
        momenta(s, nleft, pl, pr);
        kept[f] = pl[1] / pl0[1];
        const double drift = (fabs(pl[0] + pr[0] - pl0[0] - pr0[0]) + fabs(pl[1] + pr[1] - pl0[1] - pr0[1])) /
                             (fabs(pl0[0]) + fabs(pl0[1]) + fabs(pr0[0]) + fabs(pr0[1]));
        printf("  friction %.1f: the left block keeps %.6f of its sliding momentum; total momentum change %.3g\n",
               s->def.two_field_friction, kept[f], drift);
        CHECK(drift < 1e-12);
        hearth_scene_destroy(s);
    }
    CHECK(kept[1] < kept[0] - 0.01);
}

/* Without a cracked particle no node splits: the two_field step is the one-field step to the bit. Sliding blocks
 * (intact: they stick) and a heated dough block falling on the floor. */
TEST(two_field_off_same_bits) {
    uint64_t h[2];
    for (int on = 0; on < 2; on++) {
        hearth_scene *s = blocks(0.01, on, (const double[3]){0, 0.1, 0}, (const double[3]){0, -0.1, 0}, 1);
        CHECK(s != NULL);
        if (!s) return;
        hearth_error err;
        CHECK_OK(hearth_scene_step(s, 100, &err), err);
        h[on] = hearth_scene_hash(s);
        hearth_scene_destroy(s);
    }
    printf("  intact blocks: hash %016llx off, %016llx on\n", (unsigned long long)h[0], (unsigned long long)h[1]);
    CHECK(h[0] == h[1]);
    for (int on = 0; on < 2; on++) {
        hearth_scene_def d = hearth_default_scene_def();
        d.dim = 2;
        d.dx = 0.01;
        d.hi[0] = d.hi[1] = 0.2;
        d.oven_temperature = 180;
        d.oven_beta = 30;
        d.field_steps = 1; /* heat every step: at the automatic default these 200 steps hold no heat update */
        d.two_field = on;
        hearth_scene *s = fx_scene_def(&d);
        CHECK(s != NULL);
        if (!s) return;
        const char *nm[] = {"E", "conductivity", "expansion"};
        const double nv[] = {2e4, 0.4, 50};
        hearth_error err;
        const int m = hearth_scene_add_material(s, "elastic", nm, nv, 3, &err);
        const double c[3] = {0.1, 0.06, 0}, hb[3] = {0.04, 0.03, 0};
        hearth_shape *box = hearth_shape_box(c, hb);
        hearth_body_def bd = hearth_default_body_def();
        bd.shape = box, bd.material = m, bd.temperature = 20;
        CHECK(hearth_scene_add_body(s, &bd, &err) >= 0);
        hearth_shape_free(box);
        CHECK_OK(hearth_scene_step(s, 200, &err), err);
        h[on] = hearth_scene_hash(s);
        hearth_scene_destroy(s);
    }
    printf("  heated falling block: hash %016llx off, %016llx on\n", (unsigned long long)h[0], (unsigned long long)h[1]);
    CHECK(h[0] == h[1]);
}

/* The crack's two fields give the same bits on 1 and 2 threads (enough particles that the step runs on two). */
TEST(two_field_threads_same_bits) {
    uint64_t h[2];
    for (int t = 1; t <= 2; t++) {
        hearth_set_threads(t);
        hearth_scene *s = blocks(0.0025, 1, (const double[3]){0.05, 0.1, 0}, (const double[3]){-0.05, -0.1, 0}, 0);
        CHECK(s != NULL);
        if (!s) return;
        CHECK(s->ps.n >= SCENE_PARALLEL_MIN);
        hearth_error err;
        CHECK_OK(hearth_scene_step(s, 40, &err), err);
        h[t - 1] = hearth_scene_hash(s);
        printf("  %d thread(s): hash %016llx (%d particles)\n", t, (unsigned long long)h[t - 1], s->ps.n);
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
    CHECK(h[0] == h[1]);
}

/* What two_field does not carry is refused by name: 3D, SPH, sticky colliders. (A checkpoint is no
 * longer refused: two_field_checkpoint_continues_same_bits.) */
TEST(two_field_refusals) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 3;
    d.dx = 0.02;
    d.two_field = 1;
    hearth_error err;
    hearth_scene *s = hearth_scene_create(&d, &err);
    CHECK(s == NULL);
    if (!s) printf("  dim 3: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "two_field is 2D only");
    if (s) hearth_scene_destroy(s);
    d.dim = 2;
    d.solver = HEARTH_SOLVER_SPH;
    s = hearth_scene_create(&d, &err);
    CHECK(s == NULL);
    CHECK_STR_CONTAINS(err.msg, "two_field = true needs solver = \"mpm\"");
    if (s) hearth_scene_destroy(s);
    s = blocks(0.01, 1, (const double[3]){0, 0, 0}, (const double[3]){0, 0, 0}, 0);
    CHECK(s != NULL);
    if (!s) return;
    const double c[3] = {0.1, 0.03, 0}, hb[3] = {0.05, 0.01, 0};
    CHECK(fx_box_collider(s, c, hb, HEARTH_STICKY, 0) >= 0);
    CHECK(hearth_scene_step(s, 1, &err) != HEARTH_OK);
    printf("  sticky collider: %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "two_field does not carry sticky colliders");
    hearth_scene_destroy(s);
}

/* two_field and its friction are in checkpoint format version 5's DEF section, and the fields are
 * rebuilt from the particles each step: cracked blocks sliding past each other, saved mid-run, go on
 * with the same bits as the unbroken run. */
TEST(two_field_checkpoint_continues_same_bits) {
    hearth_scene *s = blocks(0.01, 1, (const double[3]){0.05, 0.1, 0}, (const double[3]){-0.05, -0.1, 0}, 0);
    CHECK(s != NULL);
    if (!s) return;
    s->def.two_field_friction = 0.3;
    hearth_error err;
    CHECK_OK(hearth_scene_step(s, 20, &err), err);
    CHECK_OK(hearth_scene_save(s, "two_field_roundtrip.ckpt", &err), err);
    hearth_scene *r = hearth_scene_load("two_field_roundtrip.ckpt", &err);
    if (!r) printf("  load: %s\n", err.msg);
    CHECK(r != NULL);
    remove("two_field_roundtrip.ckpt");
    if (r) {
        CHECK(r->def.two_field == 1 && r->def.two_field_friction == 0.3);
        CHECK_OK(hearth_scene_step(s, 40, &err), err);
        CHECK_OK(hearth_scene_step(r, 40, &err), err);
        printf("  %d particles, 20 + 40 steps: hash %016llx unbroken, %016llx restored\n", s->ps.n,
               (unsigned long long)hearth_scene_hash(s), (unsigned long long)hearth_scene_hash(r));
        CHECK(hearth_scene_hash(r) == hearth_scene_hash(s));
        hearth_scene_destroy(r);
    }
    hearth_scene_destroy(s);
}

TEST_MAIN(T(two_field_crack_slides_free), T(two_field_crack_opens_free), T(two_field_crack_closes_in_contact),
          T(two_field_crack_friction), T(two_field_off_same_bits), T(two_field_threads_same_bits), T(two_field_refusals),
          T(two_field_checkpoint_continues_same_bits))
