/* checkpoint_fixture.h: what the checkpoint tests (unit_checkpoint.c, the
 * hostile and damaged files; unit_checkpoint_versions.c, the older versions)
 * share: a small scene with something in every section, a save's image in
 * memory, a search in it, a refusal of a crafted copy, and the byte layout of
 * the fields later versions appended (checkpoint.h). */
#ifndef HEARTH_CHECKPOINT_FIXTURE_H
#define HEARTH_CHECKPOINT_FIXTURE_H
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "checkpoint.h"
#include "mpm_fixture.h"
#include "shapes.h"

/* A small scene with something in every section: a temperature curve, two
 * colliders (one a boolean tree), the temperature column. */
static inline hearth_scene *small_scene_k(int field_steps) {
    hearth_scene_def d = hearth_default_scene_def();
    d.field_steps = field_steps;
    d.dx = 0.1;
    d.oven_temperature = 180;
    d.oven_beta = 10;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NULL;
    const int m = fx_elastic(s, 1e4, 0.3, 1000);
    const double T[2] = {20, 100}, E[2] = {1e4, 2e4};
    hearth_error err;
    CHECK(hearth_scene_material_curve(s, m, "E", 2, T, E, 0, &err) == HEARTH_OK);
    const double c[3] = {0.5, 0.4, 0}, h[3] = {0.1, 0.1, 0};
    CHECK(fx_box(s, m, c, h, 1, NULL) > 0);
    const double fc[3] = {0.5, 0.1, 0}, fh[3] = {0.5, 0.05, 0};
    CHECK(fx_box_collider(s, fc, fh, HEARTH_STICKY, 0.0) >= 0);
    hearth_shape *a = hearth_shape_sphere((const double[]){0.2, 0.8, 0}, 0.05);
    hearth_shape *b = hearth_shape_sphere((const double[]){0.25, 0.8, 0}, 0.05);
    hearth_shape *u = hearth_shape_combine(HEARTH_UNION, a, b);
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = u;
    cd.velocity[0] = 0.01;
    CHECK(hearth_scene_add_collider(s, &cd, &err) >= 0);
    hearth_shape_free(a);
    hearth_shape_free(b);
    hearth_shape_free(u);
    CHECK(hearth_scene_step(s, 3, &err) == HEARTH_OK);
    return s;
}
static inline hearth_scene *small_scene(void) { return small_scene_k(hearth_default_scene_def().field_steps); }

/* The image of a save, read back into memory (malloc'd; *n its size). */
static inline uint8_t *save_image(const hearth_scene *s, size_t *n) {
    *n = 0;
    char path[] = "/tmp/hearth_ck_XXXXXX";
    const int fd = mkstemp(path);
    CHECK(fd >= 0);
    if (fd < 0) return NULL;
    close(fd);
    hearth_error err;
    CHECK(hearth_scene_save(s, path, &err) == HEARTH_OK);
    FILE *f = fopen(path, "rb");
    uint8_t *buf = NULL;
    if (f) {
        fseek(f, 0, SEEK_END);
        *n = (size_t)ftell(f);
        rewind(f);
        buf = malloc(*n);
        if (buf && fread(buf, 1, *n, f) != *n) *n = 0;
        fclose(f);
    }
    remove(path);
    return buf;
}

static inline size_t find(const uint8_t *buf, size_t n, const void *what, size_t len) {
    for (size_t i = 0; i + len <= n; i++)
        if (memcmp(buf + i, what, len) == 0) return i;
    return (size_t)-1;
}

/* Load a resealed copy of img changed by fn; expect a refusal whose message
 * names the image and contains want. */
static inline void expect_refused(const uint8_t *img, size_t n, void (*fn)(uint8_t *, size_t), const char *want) {
    uint8_t *b = malloc(n);
    memcpy(b, img, n);
    fn(b, n);
    ck_reseal(b, n);
    hearth_error err;
    hearth_scene *s = hearth_scene_load_mem(b, n, "crafted.ck", &err);
    CHECK(s == NULL);
    CHECK(err.code != HEARTH_OK);
    CHECK_STR_CONTAINS(err.msg, "crafted.ck");
    CHECK_STR_CONTAINS(err.msg, want);
    printf("  refused: %s\n", err.msg);
    hearth_scene_destroy(s);
    free(b);
}

/* The DEF fields version 5 appended sit last in the section but for version
 * 6's field_steps, just before the clocks' tag: offsets from "CLK " back, the
 * field_steps beyond them (checkpoint.h's layout). Version 6 also appended the
 * fields' cycle to the clocks (V6_CLK_BYTES after their V5_CLK_BYTES), version 7
 * the water's step limits after those (V7_CLK_BYTES). */
#define V5_DEF_BYTES (8 + 8 + 3 * 4 + 4 + 8 + 8 + 8)
#define V6_DEF_BYTES 4
#define V5_CLK_BYTES (4 + 3 * 8 + 8 + 4 + 5 * 8 + 8 + 8 + 4 + 4 + 8)
#define V6_CLK_BYTES (8 + 4 + 8 + 4)
#define V7_CLK_BYTES (4 + 3 * 8)
static inline size_t clk_at(const uint8_t *b, size_t n) {
    const size_t at = find(b, n, "CLK ", 4);
    CHECK(at != (size_t)-1 && at >= CK_HEADER_SIZE + V5_DEF_BYTES + V6_DEF_BYTES); /* (and V16_DEF_BYTES in a 16) */
    return at;
}

/* Version 16 appended the oven's walls to DEF (oven.wall_temperature, oven.emissivity, oven.radiation_scale: three
 * f64), its last fields, right before "CLK ": V16_DEF_BYTES. cut_v16_def cuts them out of an image stamped 16 and
 * stamps it 15, the layout every older file's DEF has (an image stamped older is left alone, so a test that cut
 * them first and then calls cut_v15_colliders or cut_v14_colliders, which call this, does not cut twice). */
#define V16_DEF_BYTES 24
static inline void cut_v16_def(uint8_t *b, size_t *n) {
    uint32_t v;
    memcpy(&v, b + 8, 4);
    if (v < 16) return;
    const size_t at = clk_at(b, *n);
    memmove(b + at - V16_DEF_BYTES, b + at, *n - at);
    *n -= V16_DEF_BYTES;
    memcpy(b + 8, &(uint32_t){15}, 4);
}

/* The core material parameters version 13 appended (the shares' amounts: gas_amount, gas_amount_2, params.h), and
 * those version 12 appended (the second CO2 share: gas_rate_2, reaction_temperature_2, reaction_width_2) with
 * them: every file before 12 lacks all five, after those its own version lacks. */
#define V13_CORE 2
#define V12_CORE (3 + V13_CORE)
/* Version 13 appended f64 self_max to the clocks, their last field (right before "MATS") */
#define V13_CLK_BYTES 8

/* Each collider's fields version 14 appended (start_temperature, warm_time, t_added), after its shape tree and the
 * 216 bytes of contact, pose, heat and water before them, and version 15's after those (heat_capacity, area and the
 * sheet's six state numbers): cut_colliders_after(b, n, keep, len) cuts len bytes a collider from 216 + keep on.
 * cut_v15_colliders makes a version 14 file's colliders (*n shrinks by 64 a collider), cut_v14_colliders a file's
 * older than 14 (by 24 + 64); both cut version 16's DEF tail first (cut_v16_def, V16_DEF_BYTES more), so either
 * gives the whole of an older file's layout. Return 0 when the section cannot be walked. */
#define V14_COL_BYTES 24
#define V15_COL_BYTES 64
static inline int cut_colliders_after(uint8_t *b, size_t *n, size_t keep, size_t len) {
    cut_v16_def(b, n); /* a file older than 15 is older than 16: its DEF has no walls */
    const size_t cols = find(b, *n, "COLS", 4);
    CHECK(cols != (size_t)-1);
    if (cols == (size_t)-1) return 0;
    uint32_t ncol;
    memcpy(&ncol, b + cols + 4, 4);
    size_t at = cols + 8;
    for (uint32_t i = 0; i < ncol; i++) {
        ck_cursor c = {b + at, *n - at, 0, NULL, {0}};
        hearth_shape *sh = shape_read_mem(&c, 0);
        CHECK(sh != NULL);
        if (!sh) return 0;
        hearth_shape_free(sh);
        at = (size_t)(c.p - b) + 216 + keep;
        memmove(b + at, b + at + len, *n - at - len);
        *n -= len;
    }
    return 1;
}
static inline int cut_v15_colliders(uint8_t *b, size_t *n) { return cut_colliders_after(b, n, V14_COL_BYTES, V15_COL_BYTES); }
static inline int cut_v14_colliders(uint8_t *b, size_t *n) { return cut_colliders_after(b, n, 0, V14_COL_BYTES + V15_COL_BYTES); }

/* The image of a save of one material, "elastic" (3 parameters), with the
 * last k of its core parameters cut out, as files from before they were
 * appended hold them (before the curve count; *n shrinks by 8 k), and
 * without the clocks' version 13 tail (self_max) and the colliders' version 14
 * and 15 ones: every caller makes a file older than 13. Returns 0 when the material is not found. */
static inline int cut_core_params(uint8_t *b, size_t *n, int k) {
    const size_t el = find(b, *n, "elastic", 7), mats = find(b, *n, "MATS", 4);
    CHECK(el != (size_t)-1 && mats != (size_t)-1 && mats < el);
    if (el == (size_t)-1 || mats == (size_t)-1 || mats > el) return 0;
    const size_t at = el + 7 + 4 + 8 + 4 + 8 * 3 + 8 * (size_t)(CP_COUNT - k), len = 8 * (size_t)k;
    memmove(b + at, b + at + len, *n - at - len);
    *n -= len;
    memmove(b + mats - V13_CLK_BYTES, b + mats, *n - mats);
    *n -= V13_CLK_BYTES;
    return cut_v14_colliders(b, n);
}

/* A restored copy r continues as the scene s it was saved from: the same
 * hash after 10 more steps of each. */
static inline void continues_as(hearth_scene *s, hearth_scene *r, const char *what) {
    hearth_error err;
    CHECK(hearth_scene_step(s, 10, &err) == HEARTH_OK);
    CHECK(hearth_scene_step(r, 10, &err) == HEARTH_OK);
    printf("  after 10 more steps: hash %016llx saved scene, %016llx %s\n", (unsigned long long)hearth_scene_hash(s),
           (unsigned long long)hearth_scene_hash(r), what);
    CHECK(hearth_scene_hash(r) == hearth_scene_hash(s));
}

#endif
