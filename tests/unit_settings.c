/* unit_settings.c: the settings schema (hearth_scene_settings) against the C
 * copies derived from it: hearth_default_scene_def's values and
 * hearth_scene_create's range checks. A default or a range that drifts from
 * the table fails here; the Lua side is held to it by tests/lua/settings_schema.lua,
 * the man page and docs/lua.md by the cli test settings_docs_current. */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "hearth/hearth.h"
#include "test.h"

static char *field(hearth_scene_def *d, long off) { return (char *)d + off; }

/* Every default in the struct is the table's; the drift #16 named is resolved to the Lua value. */
TEST(settings_defaults_from_schema) {
    int n = 0;
    const hearth_setting *set = hearth_scene_settings(&n);
    CHECK(n > 40);
    hearth_scene_def d = hearth_default_scene_def();
    for (int k = 0; k < n; k++) {
        const hearth_setting *e = &set[k];
        if (e->offset < 0) continue;
        const char *f = field(&d, e->offset);
        int ok = 1;
        switch (e->kind) {
        case HEARTH_SETTING_REAL: ok = isnan(e->def) ? isnan(*(const double *)f) : *(const double *)f == e->def; break;
        case HEARTH_SETTING_INT:
        case HEARTH_SETTING_FLAG:
        case HEARTH_SETTING_CHOICE: ok = *(const int *)f == (int)e->def; break;
        case HEARTH_SETTING_SEED: ok = *(const uint64_t *)f == (uint64_t)e->def; break;
        case HEARTH_SETTING_VECTOR: ok = !memcmp(f, e->vec_def, 3 * sizeof(double)); break;
        case HEARTH_SETTING_BOX:
            ok = !memcmp(f, e->vec_def, 3 * sizeof(double)) && !memcmp(field(&d, e->offset2), e->vec_def + 3, 3 * sizeof(double));
            break;
        case HEARTH_SETTING_TEXT: break;
        }
        if (!ok) fprintf(stderr, "default of %s differs from the schema\n", e->name);
        CHECK(ok);
    }
    /* the values the issue and the old literals named, so a table edit that moves one is seen */
    CHECK(d.oven_beta == 10); /* was 0 in C, 10 in Lua: the Lua user's value is kept */
    CHECK(isnan(d.oven_temperature));
    CHECK(d.dim == 2 && d.dx == 0.01 && d.cfl == 0.5 && d.gravity[1] == -9.81 && d.max_rollbacks == 8);
    CHECK(d.wall == HEARTH_SLIP && d.guard == HEARTH_GUARD_STOP && d.solver == HEARTH_SOLVER_MPM && d.seed == 1);
    CHECK(d.sph.h_factor == 2.4 && d.sph.gamma == 7 && d.sph.beta_c == 1 && d.sph.xsph_Tf == 120);
    /* the defaults pass their own checks, under either solver */
    hearth_error err;
    for (int solver = 0; solver < 2; solver++) {
        d.solver = solver;
        hearth_scene *s = hearth_scene_create(&d, &err);
        CHECK(s != NULL);
        hearth_scene_destroy(s);
    }
}

/* Just outside each numeric setting's range, hearth_scene_create refuses
 * with the setting's name, its range and its unit. */
TEST(settings_ranges_named) {
    int n = 0;
    const hearth_setting *set = hearth_scene_settings(&n);
    int tried = 0;
    for (int k = 0; k < n; k++) {
        const hearth_setting *e = &set[k];
        if (e->offset < 0 || (e->kind != HEARTH_SETTING_REAL && e->kind != HEARTH_SETTING_INT && e->kind != HEARTH_SETTING_SEED))
            continue;
        for (int side = 0; side < 2; side++) {
            double bad;
            if (side == 0) {
                if (e->kind == HEARTH_SETTING_SEED) continue; /* unsigned: nothing below 0 */
                bad = e->min_open ? e->min : e->kind == HEARTH_SETTING_INT ? e->min - 1 : e->min - fmax(1e-3, fabs(e->min) * 1e-3);
            } else {
                if (isinf(e->max)) bad = INFINITY; /* finite always */
                else bad = e->kind == HEARTH_SETTING_REAL ? e->max + fmax(1e-3, fabs(e->max) * 1e-3) : e->max + 1;
            }
            hearth_scene_def d = hearth_default_scene_def();
            if (!strncmp(e->name, "sph.", 4)) d.solver = HEARTH_SOLVER_SPH;
            char *f = field(&d, e->offset);
            if (e->kind == HEARTH_SETTING_REAL) *(double *)f = bad;
            else if (e->kind == HEARTH_SETTING_INT) *(int *)f = (int)bad;
            else *(uint64_t *)f = (uint64_t)bad;
            hearth_error err;
            hearth_scene *s = hearth_scene_create(&d, &err);
            CHECK(s == NULL);
            hearth_scene_destroy(s);
            char want[96];
            snprintf(want, sizeof want, "scene: %s = ", e->name);
            CHECK_STR_CONTAINS(err.msg, want);
            CHECK_STR_CONTAINS(err.msg, "valid range");
            if (strcmp(e->unit, "1")) CHECK_STR_CONTAINS(err.msg, e->unit);
            tried++;
        }
    }
    CHECK(tried > 40);
    hearth_error err;
    hearth_scene_def d = hearth_default_scene_def();
    d.oven_beta = -1;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "scene: oven.beta = -1 W/(m^2 K); valid range [0, inf) W/(m^2 K)");
}

/* Words and flags: an index outside the words, a flag other than 0 or 1. */
TEST(settings_words_and_flags) {
    hearth_error err;
    hearth_scene_def d = hearth_default_scene_def();
    d.wall = HEARTH_GRIP; /* colliders only */
    CHECK(hearth_scene_create(&d, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "scene: wall = 3; valid: 0 (sticky), 1 (slip), 2 (separate)");
    d = hearth_default_scene_def();
    d.water_momentum = 2;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "scene: water_momentum = 2; valid: 0 (false), 1 (true)");
    d = hearth_default_scene_def();
    d.solver = HEARTH_SOLVER_SPH;
    d.sph.periodic[2] = 5;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "scene: sph.periodic_z = 5");
    d.sph.periodic[2] = 0;
    d.sph.xsph_T0 = 130; /* the rule between two options stays sph.c's */
    CHECK(hearth_scene_create(&d, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "sph.xsph_Tf = 120 degC must be above sph.xsph_T0 = 130 degC");
    d = hearth_default_scene_def();
    d.sph.gamma = 99; /* SPH options are checked only when SPH steps the scene */
    hearth_scene *s = hearth_scene_create(&d, &err);
    CHECK(s != NULL);
    hearth_scene_destroy(s);
}

/* The table itself: unique names, help and units on every entry, words for choices, lookup by name. */
TEST(settings_table_well_formed) {
    int n = 0;
    const hearth_setting *set = hearth_scene_settings(&n);
    for (int k = 0; k < n; k++) {
        const hearth_setting *e = &set[k];
        CHECK(e->name && e->name[0] && e->help && e->help[0] && e->unit && e->field);
        CHECK(hearth_scene_setting(e->name) == e);
        for (int j = 0; j < k; j++) CHECK(strcmp(set[j].name, e->name) != 0);
        if (e->kind == HEARTH_SETTING_CHOICE) {
            int w = 0;
            while (e->words && e->words[w]) w++;
            CHECK(w >= 2 && e->def >= 0 && e->def < w);
        }
        if (e->kind == HEARTH_SETTING_VECTOR || e->kind == HEARTH_SETTING_BOX) CHECK(e->vec_def != NULL);
        if (e->kind == HEARTH_SETTING_BOX) CHECK(e->offset2 >= 0);
        if (e->kind == HEARTH_SETTING_REAL && !isnan(e->def))
            CHECK((e->min_open ? e->def > e->min : e->def >= e->min) && e->def <= e->max);
    }
    /* every field of hearth_scene_def has a row: the bytes no row covers are alignment padding only
     * (less than a double between two rows), so a new field without a row fails here */
    unsigned char covered[sizeof(hearth_scene_def)] = {0};
    for (int k = 0; k < n; k++) {
        const hearth_setting *e = &set[k];
        if (e->offset < 0) continue;
        size_t size = e->kind == HEARTH_SETTING_REAL || e->kind == HEARTH_SETTING_SEED ? 8
                      : e->kind == HEARTH_SETTING_VECTOR || e->kind == HEARTH_SETTING_BOX ? 24 : sizeof(int);
        CHECK((size_t)e->offset + size <= sizeof covered);
        for (size_t b = 0; b < size && (size_t)e->offset + b < sizeof covered; b++) covered[e->offset + b]++;
        if (e->kind == HEARTH_SETTING_BOX)
            for (size_t b = 0; b < size; b++) covered[e->offset2 + b]++;
    }
    size_t gap = 0;
    for (size_t b = 0; b < sizeof covered; b++) {
        CHECK(covered[b] <= 1); /* no two rows write the same bytes */
        gap = covered[b] ? 0 : gap + 1;
        if (gap >= sizeof(double)) fprintf(stderr, "hearth_scene_def bytes %zu..: no settings row\n", b + 1 - gap);
        CHECK(gap < sizeof(double));
    }
    CHECK(hearth_scene_setting("oven.beta") && !strcmp(hearth_scene_setting("oven.beta")->unit, "W/(m^2 K)"));
    CHECK(hearth_scene_setting("nope") == NULL);
    CHECK(hearth_scene_setting(NULL) == NULL);
}

TEST_MAIN(T(settings_defaults_from_schema), T(settings_ranges_named), T(settings_words_and_flags),
          T(settings_table_well_formed))
