/* unit_checkpoint.c: checkpoints are untrusted input. A valid file restores
 * bit-identically; a damaged or crafted one is refused with a message naming
 * the file and what is wrong, and nothing crashes (run under ASan). Crafted
 * files are made from a real save, changed in memory and resealed with
 * ck_reseal so they pass the checksum and reach the parser. */
#include <sys/stat.h>

#include "alloc.h"
#include "checkpoint_fixture.h"
#include "mpm.h"

/* A save restores bit-identically, from a file and from memory, and the
 * header holds the size and the CRC of the whole file. */
TEST(checkpoint_v4_roundtrip) {
    hearth_scene *s = small_scene();
    CHECK(s);
    if (!s) return;
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img && n > CK_HEADER_SIZE);
    uint32_t version, crc;
    uint64_t size;
    memcpy(&version, img + 8, 4);
    memcpy(&size, img + CK_OFF_SIZE, 8);
    memcpy(&crc, img + CK_OFF_CRC, 4);
    CHECK(version == CK_VERSION);
    CHECK(size == n);
    CHECK(crc == ck_crc(img, n));
    CHECK(find(img, n, "elastic", 7) != (size_t)-1);
    CHECK(find(img, n, "/", 1) == (size_t)-1 || find(img, n, ".so", 3) == (size_t)-1); /* no plugin path */
    hearth_error err;
    hearth_scene *r = hearth_scene_load_mem(img, n, "mem", &err);
    CHECK(r);
    if (r) {
        CHECK(hearth_scene_hash(r) == hearth_scene_hash(s));
        CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
        CHECK(hearth_scene_step(r, 20, &err) == HEARTH_OK);
        CHECK(hearth_scene_hash(r) == hearth_scene_hash(s));
        hearth_stats a, b;
        hearth_scene_stats(s, &a);
        hearth_scene_stats(r, &b);
        CHECK(a.t == b.t && a.step == b.step);
        /* saving the restored scene again gives the same bytes as saving the original */
        size_t n1, n2;
        uint8_t *i1 = save_image(s, &n1), *i2 = save_image(r, &n2);
        CHECK(i1 && i2 && n1 == n2 && memcmp(i1, i2, n1) == 0);
        free(i1);
        free(i2);
    }
    hearth_scene_destroy(r);
    free(img);
    hearth_scene_destroy(s);
}

TEST(checkpoint_bad_magic) {
    hearth_scene *s = small_scene();
    size_t n;
    uint8_t *img = save_image(s, &n);
    img[0] = 'X';
    hearth_error err;
    CHECK(hearth_scene_load_mem(img, n, "m.ck", &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "m.ck");
    CHECK_STR_CONTAINS(err.msg, "bad magic");
    CHECK(hearth_scene_load_mem("HEARTH", 6, "short.ck", &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "bad magic");
    CHECK(hearth_scene_load_mem(NULL, 0, "empty.ck", &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "empty.ck");
    free(img);
    hearth_scene_destroy(s);
}

/* Cut short anywhere: refused, from memory and from a file (whose header
 * size is checked before the body is read). */
TEST(checkpoint_truncated) {
    hearth_scene *s = small_scene();
    size_t n;
    uint8_t *img = save_image(s, &n);
    hearth_error err;
    int refused = 0, tried = 0;
    for (size_t cut = 0; cut < n; cut += cut < 64 ? 1 : 37) {
        tried++;
        hearth_scene *r = hearth_scene_load_mem(img, cut, "cut.ck", &err);
        refused += r == NULL && strstr(err.msg, "cut.ck") != NULL;
        hearth_scene_destroy(r);
    }
    /* resealed after the cut: the size and CRC agree, the parser finds the end */
    int resealed = 0;
    for (size_t cut = CK_HEADER_SIZE; cut < n; cut += 13) {
        uint8_t *b = malloc(cut);
        memcpy(b, img, cut);
        ck_reseal(b, cut);
        hearth_scene *r = hearth_scene_load_mem(b, cut, "cut.ck", &err);
        resealed += r == NULL && (strstr(err.msg, "ends early") || strstr(err.msg, "truncated") || strstr(err.msg, "checkpoint"));
        tried++;
        hearth_scene_destroy(r);
        free(b);
    }
    printf("  %d of %d cuts refused\n", refused + resealed, tried);
    CHECK(refused + resealed == tried);
    char path[] = "/tmp/hearth_cut_XXXXXX";
    const int fd = mkstemp(path);
    CHECK(fd >= 0 && write(fd, img, n / 2) == (ssize_t)(n / 2));
    close(fd);
    CHECK(hearth_scene_load(path, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, "the header says");
    remove(path);
    free(img);
    hearth_scene_destroy(s);
}

/* Every single-byte change of a small checkpoint is refused (the CRC covers
 * the whole file: settings, materials and colliders included). */
TEST(checkpoint_every_byte_flip) {
    hearth_scene *s = small_scene();
    size_t n;
    uint8_t *img = save_image(s, &n);
    int loaded = 0;
    hearth_error err;
    for (size_t i = 0; i < n; i++) {
        img[i] ^= 0xFF;
        hearth_scene *r = hearth_scene_load_mem(img, n, "flip.ck", &err);
        if (r) loaded++;
        hearth_scene_destroy(r);
        img[i] ^= 0xFF;
    }
    printf("  %zu bytes flipped one at a time, %d loaded\n", n, loaded);
    CHECK(loaded == 0);
    free(img);
    hearth_scene_destroy(s);
}

/* Random single-bit flips (issue 15: 657 of 2500 loaded silently in v2). */
TEST(checkpoint_bitflip_campaign) {
    hearth_scene *s = small_scene();
    size_t n;
    uint8_t *img = save_image(s, &n);
    uint64_t rng = 88172645463325252ULL;
    int loaded = 0;
    hearth_error err;
    enum { FLIPS = 2500 };
    for (int k = 0; k < FLIPS; k++) {
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        const size_t byte = (size_t)(rng % n);
        const uint8_t bit = (uint8_t)(1u << ((rng >> 32) % 8));
        img[byte] ^= bit;
        hearth_scene *r = hearth_scene_load_mem(img, n, "flip.ck", &err);
        loaded += r != NULL;
        hearth_scene_destroy(r);
        img[byte] ^= bit;
    }
    printf("  %d random bit flips, %d loaded silently\n", FLIPS, loaded);
    CHECK(loaded == 0);
    free(img);
    hearth_scene_destroy(s);
}

/* The same flips resealed (what a crafted file can do): whatever loads holds
 * only values the constructors accept, and nothing crashes under ASan. */
TEST(checkpoint_resealed_flips) {
    hearth_scene *s = small_scene();
    size_t n;
    uint8_t *img = save_image(s, &n);
    uint8_t *b = malloc(n);
    uint64_t rng = 0x9E3779B97F4A7C15ULL;
    int loaded = 0, refused = 0;
    hearth_error err;
    for (int k = 0; k < 2500; k++) {
        memcpy(b, img, n);
        rng ^= rng << 13;
        rng ^= rng >> 7;
        rng ^= rng << 17;
        b[CK_HEADER_SIZE + rng % (n - CK_HEADER_SIZE)] ^= (uint8_t)(1u << ((rng >> 32) % 8));
        ck_reseal(b, n);
        hearth_scene *r = hearth_scene_load_mem(b, n, "resealed.ck", &err);
        if (r) {
            loaded++;
            /* a loaded scene steps without tripping the sanitizers */
            hearth_scene_step(r, 1, &err);
        } else {
            refused++;
            if (!strstr(err.msg, "resealed.ck")) {
                printf("  message without the file: %s\n", err.msg);
                CHECK(0);
            }
        }
        hearth_scene_destroy(r);
    }
    printf("  2500 resealed bit flips: %d refused with a message, %d loaded (changed values still in range)\n", refused,
           loaded);
    CHECK(refused + loaded == 2500);
    CHECK(refused > 0);
    free(b);
    free(img);
    hearth_scene_destroy(s);
}

/* ---- crafted fields ---------------------------------------------------- */

static void set_u32_after(uint8_t *b, size_t n, const char *tag, size_t off, uint32_t v) {
    const size_t at = find(b, n, tag, 4);
    CHECK(at != (size_t)-1);
    if (at != (size_t)-1) memcpy(b + at + 4 + off, &v, 4);
}
static void set_f64_after(uint8_t *b, size_t n, const char *tag, size_t off, double v) {
    const size_t at = find(b, n, tag, 4);
    CHECK(at != (size_t)-1);
    if (at != (size_t)-1) memcpy(b + at + 4 + off, &v, 8);
}

static void count_2e31(uint8_t *b, size_t n) { set_u32_after(b, n, "PART", 0, 1u << 31); }
static void count_2e30(uint8_t *b, size_t n) { set_u32_after(b, n, "PART", 0, 1u << 30); }
static void count_plus1(uint8_t *b, size_t n) {
    const size_t at = find(b, n, "PART", 4);
    uint32_t v;
    memcpy(&v, b + at + 4, 4);
    set_u32_after(b, n, "PART", 0, v + 1);
}
static void browning_bit(uint8_t *b, size_t n) { /* a column hearth_scene_save never writes */
    const size_t at = find(b, n, "PART", 4);
    uint32_t v;
    memcpy(&v, b + at + 12, 4);
    set_u32_after(b, n, "PART", 8, v | (1u << PC_BROWNING));
}
static void guard_state_7(uint8_t *b, size_t n) { set_u32_after(b, n, "CLK ", 0, 7); }
static void guard_state_neg(uint8_t *b, size_t n) { set_u32_after(b, n, "CLK ", 0, (uint32_t)-1); }
static void dx_nan(uint8_t *b, size_t n) { set_f64_after(b, n, "DEF ", 4, NAN); }
static void dx_tiny(uint8_t *b, size_t n) { set_f64_after(b, n, "DEF ", 4, 1e-300); }
static void dx_negative(uint8_t *b, size_t n) { set_f64_after(b, n, "DEF ", 4, -0.1); }
static void box_huge(uint8_t *b, size_t n) { set_f64_after(b, n, "DEF ", 4 + 8 + 24, 1e300); } /* hi[0] */
static void dim_7(uint8_t *b, size_t n) { set_u32_after(b, n, "DEF ", 0, 7); }
static void wall_mode_9(uint8_t *b, size_t n) { set_u32_after(b, n, "DEF ", 4 + 8 + 72 + 16, 9); }
static void plugin_path(uint8_t *b, size_t n) {
    const size_t at = find(b, n, "elastic", 7);
    CHECK(at != (size_t)-1);
    memcpy(b + at, "/tmp/el", 7);
}
static void plugin_dots(uint8_t *b, size_t n) {
    const size_t at = find(b, n, "elastic", 7);
    memcpy(b + at, "../../x", 7);
}
static void schema_hash(uint8_t *b, size_t n) {
    const size_t at = find(b, n, "elastic", 7);
    b[at + 7 + 4] ^= 1; /* after the name: u32 ABI, then the u64 hash */
}
static void abi_2(uint8_t *b, size_t n) {
    const size_t at = find(b, n, "elastic", 7);
    const uint32_t v = 2;
    memcpy(b + at + 7, &v, 4);
}
static void particle_x_nan(uint8_t *b, size_t n) {
    const size_t at = find(b, n, "\1\0\0\0x", 5); /* the column "x": length 1, then the name */
    CHECK(at != (size_t)-1);
    const double v = NAN;
    memcpy(b + at + 5 + 8, &v, 8);
}
static void particle_material_9(uint8_t *b, size_t n) {
    const size_t at = find(b, n, "\10\0\0\0material", 12);
    CHECK(at != (size_t)-1);
    const int32_t v = 9;
    memcpy(b + at + 12, &v, 4);
}
static void curve_points_huge(uint8_t *b, size_t n) {
    /* after the core parameters: u32 curve count, then param, points */
    const size_t at = find(b, n, "COLS", 4);
    (void)at;
    const size_t m = find(b, n, "elastic", 7);
    const size_t off = m + 7 + 4 + 8 + 4 + 8 * 3 + 8 * CP_COUNT + 4 + 4; /* elastic has 3 parameters */
    const uint32_t v = 0x7fffffff;
    memcpy(b + off, &v, 4);
}
/* The first sphere node: the second collider is a union (kind 6) of two
 * spheres (kind 2); searched from the colliders' tag. */
static size_t first_sphere(const uint8_t *b, size_t n) {
    const size_t cols = find(b, n, "COLS", 4);
    const int32_t sphere[2] = {2, 0};
    const size_t at = find(b + cols, n - cols, sphere, 8);
    CHECK(cols != (size_t)-1 && at != (size_t)-1);
    return cols + at;
}
static void shape_nan_radius(uint8_t *b, size_t n) {
    const size_t at = first_sphere(b, n);
    const double v = NAN;
    memcpy(b + at + 8 + 9 * 8, &v, 8); /* r is the 10th double */
}
static void shape_kind_99(uint8_t *b, size_t n) {
    const size_t at = first_sphere(b, n);
    const int32_t k = 99;
    memcpy(b + at, &k, 4);
}
static void trailing(uint8_t *b, size_t n) { (void)b, (void)n; }

TEST(checkpoint_crafted_fields) {
    hearth_scene *s = small_scene();
    size_t n;
    uint8_t *img = save_image(s, &n);
    expect_refused(img, n, count_2e31, "particle count");
    expect_refused(img, n, count_2e30, "particle count");
    expect_refused(img, n, count_plus1, "particle");
    expect_refused(img, n, browning_bit, "a browning column in a scene with browning = false");
    expect_refused(img, n, guard_state_7, "guard state out of range");
    expect_refused(img, n, guard_state_neg, "guard state out of range");
    expect_refused(img, n, dx_nan, "dx is not finite");
    expect_refused(img, n, dx_tiny, "dx");
    expect_refused(img, n, dx_negative, "dx");
    expect_refused(img, n, box_huge, "box");
    expect_refused(img, n, dim_7, "dim");
    expect_refused(img, n, wall_mode_9, "wall mode");
    expect_refused(img, n, plugin_path, "not a plugin name");
    expect_refused(img, n, plugin_dots, "not a plugin name");
    expect_refused(img, n, schema_hash, "another parameter schema");
    expect_refused(img, n, abi_2, "ABI 2");
    expect_refused(img, n, particle_x_nan, "not finite");
    expect_refused(img, n, particle_material_9, "unknown material");
    expect_refused(img, n, curve_points_huge, "point count");
    expect_refused(img, n, shape_nan_radius, "collider shape");
    expect_refused(img, n, shape_kind_99, "unknown node kind");
    (void)trailing;
    /* bytes after the end */
    uint8_t *b = malloc(n + 8);
    memcpy(b, img, n);
    memset(b + n, 0, 8);
    ck_reseal(b, n + 8);
    hearth_error err;
    CHECK(hearth_scene_load_mem(b, n + 8, "long.ck", &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "bytes after the end");
    free(b);
    free(img);
    hearth_scene_destroy(s);
}

/* A 2^31 particle count in a small file allocates nothing large: refused
 * before the columns are reserved. An allocator that records the largest
 * request watches the load. */
static size_t largest;
static void *watch_alloc(void *ud, void *p, size_t osize, size_t nsize) {
    (void)ud, (void)osize;
    if (nsize == 0) {
        free(p);
        return NULL;
    }
    if (nsize > largest) largest = nsize;
    return realloc(p, nsize);
}

TEST(checkpoint_count_before_alloc) {
    hearth_scene *s = small_scene();
    size_t n;
    uint8_t *img = save_image(s, &n);
    hearth_scene_destroy(s);
    count_2e31(img, n);
    ck_reseal(img, n);
    hearth_set_allocator(watch_alloc, NULL);
    largest = 0;
    hearth_error err;
    hearth_scene *r = hearth_scene_load_mem(img, n, "big.ck", &err);
    hearth_set_allocator(NULL, NULL);
    CHECK(r == NULL);
    CHECK(err.code == HEARTH_ERR_FORMAT);
    CHECK_STR_CONTAINS(err.msg, "particle count larger than the file holds");
    printf("  %zu-byte file, largest allocation %zu bytes\n", n, largest);
    CHECK(largest < (size_t)1 << 20);
    free(img);
}

/* A folder or a FIFO named as a checkpoint is refused, without blocking. */
TEST(checkpoint_not_regular_file) {
    hearth_error err;
    CHECK(hearth_scene_load("/tmp", &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "not a regular file");
    char dir[] = "/tmp/hearth_fifo_XXXXXX";
    CHECK(mkdtemp(dir) != NULL);
    char path[64];
    snprintf(path, sizeof path, "%s/ck", dir);
    CHECK(mkfifo(path, 0600) == 0);
    CHECK(hearth_scene_load(path, &err) == NULL); /* would block forever in fopen */
    CHECK_STR_CONTAINS(err.msg, "not a regular file");
    remove(path);
    rmdir(dir);
    CHECK(hearth_scene_load("/nonexistent/x.ck", &err) == NULL && err.code == HEARTH_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, "/nonexistent/x.ck");
}

/* Every allocation of a load failing in turn: a refusal with a message and
 * nothing leaked, until the load goes through. */
TEST(checkpoint_alloc_failures) {
    hearth_scene *s = small_scene();
    size_t n;
    uint8_t *img = save_image(s, &n);
    const uint64_t want = hearth_scene_hash(s);
    hearth_scene_destroy(s);
    const size_t base = hearth_bytes_allocated();
    int failed = 0, k;
    for (k = 0; k < 500; k++) {
        hearth_error err;
        mem_fail_after(k);
        hearth_scene *r = hearth_scene_load_mem(img, n, "nomem.ck", &err);
        mem_fail_after(-1);
        if (r) {
            CHECK(hearth_scene_hash(r) == want);
            hearth_scene_destroy(r);
            break;
        }
        failed++;
        CHECK(err.code != HEARTH_OK);
        CHECK_STR_CONTAINS(err.msg, "nomem.ck");
        CHECK(hearth_bytes_allocated() == base);
    }
    printf("  %d allocation failures refused before the load went through\n", failed);
    CHECK(k < 500 && failed > 5);
    free(img);
}

static void set_before_clk(uint8_t *b, size_t n, size_t back, const void *v, size_t len) {
    memcpy(b + clk_at(b, n) - V16_DEF_BYTES - V6_DEF_BYTES - back, v, len);
}
static void damping_nan(uint8_t *b, size_t n) { set_before_clk(b, n, V5_DEF_BYTES, &(double){NAN}, 8); }
static void boiling_cold(uint8_t *b, size_t n) { set_before_clk(b, n, V5_DEF_BYTES - 8, &(double){-300}, 8); }
static void periodic_y_2(uint8_t *b, size_t n) { set_before_clk(b, n, 8 + 8 + 8 + 4 + 8, &(int32_t){2}, 4); }
static void two_field_neg(uint8_t *b, size_t n) { set_before_clk(b, n, 8 + 8 + 8 + 4, &(int32_t){-1}, 4); }
static void gas_vent_neg(uint8_t *b, size_t n) { set_before_clk(b, n, 16, &(double){-0.02}, 8); }
static void vent_porosity_15(uint8_t *b, size_t n) { set_before_clk(b, n, 8, &(double){1.5}, 8); }
static void vent_porosity_0(uint8_t *b, size_t n) { set_before_clk(b, n, 8, &(double){0}, 8); }
static void vent_porosity_inf(uint8_t *b, size_t n) { set_before_clk(b, n, 8, &(double){INFINITY}, 8); }
/* version 16's fields, the last of DEF (checkpoint_fixture.h): walls, emissivity, radiation_scale */
static void set_v16(uint8_t *b, size_t n, int k, double v) { memcpy(b + clk_at(b, n) - V16_DEF_BYTES + 8 * k, &v, 8); }
static void walls_cold(uint8_t *b, size_t n) { set_v16(b, n, 0, -300); }
static void walls_inf(uint8_t *b, size_t n) { set_v16(b, n, 0, INFINITY); }
static void emissivity_15(uint8_t *b, size_t n) { set_v16(b, n, 1, 1.5); }
static void emissivity_nan(uint8_t *b, size_t n) { set_v16(b, n, 1, NAN); }
static void radiation_scale_0(uint8_t *b, size_t n) { set_v16(b, n, 2, 0); }

/* A hostile version 5 file: each DEF field version 5 added is checked on its
 * own, the message naming the field, the value read and the valid range. */
TEST(checkpoint_v5_def_fields_refused) {
    hearth_scene *s = small_scene();
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    if (!img) return;
    expect_refused(img, n, damping_nan, "scene: damping = nan 1/s is outside its valid range [0, 1e+09]");
    expect_refused(img, n, boiling_cold, "boiling_point = -300 degC is outside its valid range [-273.15, 5000]");
    expect_refused(img, n, periodic_y_2, "periodic_y = 2 is neither 0 nor 1");
    expect_refused(img, n, two_field_neg, "two_field = -1 is neither 0 nor 1");
    expect_refused(img, n, gas_vent_neg, "gas_vent = -0.02 m/s is outside its valid range [0, 1e+06]");
    expect_refused(img, n, vent_porosity_15, "vent_porosity = 1.5 is outside its valid range (0, 1]");
    expect_refused(img, n, vent_porosity_0, "vent_porosity = 0 is outside its valid range (0, 1]");
    expect_refused(img, n, vent_porosity_inf, "vent_porosity = inf is outside its valid range (0, 1]");
    /* and version 16's oven walls */
    expect_refused(img, n, walls_cold, "oven.wall_temperature = -300 degC is outside its valid range [-273.15, 5000]");
    expect_refused(img, n, walls_inf, "oven.wall_temperature = inf degC is outside its valid range [-273.15, 5000]");
    expect_refused(img, n, emissivity_15, "oven.emissivity = 1.5 is outside its valid range [0, 1]");
    expect_refused(img, n, emissivity_nan, "oven.emissivity = nan is outside its valid range [0, 1]");
    expect_refused(img, n, radiation_scale_0, "oven.radiation_scale = 0 is outside its valid range (0, 1e+09]");
    free(img);
    hearth_scene_destroy(s);
}

/* A venting scene (gas_vent > 0, open pores: porosity 0.8 >= vent_porosity
 * 0.7; as tests/lua/gas_vent.lua, coarser) saved mid-run and restored
 * continues bit-identically to the unbroken run; an otherwise equal scene
 * without venting ends elsewhere, so the equality says the restored scene
 * vents. */
static hearth_scene *vent_scene(double gas_vent) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.02;
    d.hi[0] = d.hi[1] = 0.3;
    d.gravity[1] = 0;
    d.dt_max = 2e-4;
    d.oven_temperature = 40;
    d.oven_beta = 10;
    d.gas_vent = gas_vent;
    d.vent_porosity = 0.7;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NULL;
    const char *nm[] = {"E", "nu", "tau_y", "eta", "density", "porosity", "gas_rate", "reaction_temperature",
                        "reaction_width", "expansion"};
    const double nv[] = {1e5, 0.3, 1e6, 0, 500, 0.8, 1e-8, 40, 20, 0};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "cam_clay_dough", nm, nv, 10, &err);
    if (m < 0) printf("  material: %s\n", err.msg);
    CHECK(m >= 0);
    hearth_shape *disc = hearth_shape_sphere((const double[3]){0.15, 0.15, 0}, 0.08);
    hearth_body_def b = hearth_default_body_def();
    b.shape = disc, b.material = m, b.jitter = 0, b.temperature = 40;
    CHECK(hearth_scene_add_body(s, &b, &err) >= 0);
    hearth_shape_free(disc);
    CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
    return s;
}
TEST(checkpoint_venting_continues_same_bits) {
    hearth_scene *s = vent_scene(0.02), *still = vent_scene(0);
    CHECK(s && still);
    if (!s || !still) return;
    const char *path = "vent_roundtrip.ck";
    hearth_error err;
    CHECK(hearth_scene_save(s, path, &err) == HEARTH_OK);
    if (err.code) printf("  save: %s\n", err.msg);
    hearth_scene *r = hearth_scene_load(path, &err);
    if (!r) printf("  load: %s\n", err.msg);
    CHECK(r != NULL);
    remove(path);
    if (r) {
        CHECK(r->def.gas_vent == 0.02 && r->def.vent_porosity == 0.7);
        CHECK(hearth_scene_step(s, 40, &err) == HEARTH_OK);
        CHECK(hearth_scene_step(r, 40, &err) == HEARTH_OK);
        CHECK(hearth_scene_step(still, 40, &err) == HEARTH_OK);
        const uint64_t hs = hearth_scene_hash(s), hr = hearth_scene_hash(r), h0 = hearth_scene_hash(still);
        printf("  %d particles, 20 + 40 steps: hash unbroken %016llx, restored %016llx, not venting %016llx\n",
               hearth_scene_particle_count(s), (unsigned long long)hs, (unsigned long long)hr, (unsigned long long)h0);
        CHECK(hr == hs);
        CHECK(h0 != hs);
        hearth_scene_destroy(r);
    }
    hearth_scene_destroy(s);
    hearth_scene_destroy(still);
}

/* The memos (exp_memo.h) are a cache: a venting dough's save holds no memo column, its restore refills them
 * (checkpoint_venting_continues_same_bits: the same bits), and a file that claims one, as no hearth writes
 * it, is refused by name rather than read into the cache. */
/* claim_column: the file's PART chunk claims column c among its saved columns */
static void claim_column(uint8_t *b, size_t n, int c) {
    const size_t at = find(b, n, "PART", 4);
    uint32_t v;
    memcpy(&v, b + at + 12, 4);
    set_u32_after(b, n, "PART", 8, v | (1u << c));
}
static void memo_bit(uint8_t *b, size_t n) { claim_column(b, n, PC_GAS_MEMO); }
TEST(checkpoint_memo_columns_refused) {
    hearth_scene *s = vent_scene(0.02);
    CHECK(s != NULL);
    if (!s) return;
    CHECK(s->ps.enabled & (1u << PC_GAS_MEMO));
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    if (img) {
        CHECK(find(img, n, "gas_memo", 8) == (size_t)-1);
        CHECK(find(img, n, "vent_rate", 9) != (size_t)-1); /* the columns beside it are there */
        expect_refused(img, n, memo_bit, "a memo column");
        free(img);
    }
    hearth_scene_destroy(s);
}

/* A cache column c (name, width doubles a particle, its first the key) after steps that filled
 * `filled` of s's entries: the save holds no such column and a file that claims one (bit) is refused by
 * name; the restore starts it zeroed and, 40 steps on, has the unbroken run's bits. */
static void memo_roundtrip(hearth_scene *s, int c, const char *name, int width, int filled,
                           void (*bit)(uint8_t *, size_t), const char *path) {
    hearth_error err;
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    if (img) {
        CHECK(find(img, n, name, strlen(name)) == (size_t)-1);
        expect_refused(img, n, bit, "a memo column");
        free(img);
    }
    CHECK(hearth_scene_save(s, path, &err) == HEARTH_OK);
    hearth_scene *r = hearth_scene_load(path, &err);
    if (!r) printf("  load: %s\n", err.msg);
    CHECK(r != NULL);
    remove(path);
    if (!r) return;
    int empty = 0;
    CHECK(r->ps.enabled & (1u << c));
    for (int i = 0; i < r->ps.n; i++) empty += pcold(&r->ps, c)[(size_t)width * i] == 0;
    CHECK(empty == r->ps.n);
    CHECK(hearth_scene_step(s, 40, &err) == HEARTH_OK);
    CHECK(hearth_scene_step(r, 40, &err) == HEARTH_OK);
    printf("  %s: %d particles, %d memo entries filled at the save, %d empty after the restore; 40 steps on: hash "
           "unbroken %016llx, restored %016llx\n", name, s->ps.n, filled, empty,
           (unsigned long long)hearth_scene_hash(s), (unsigned long long)hearth_scene_hash(r));
    CHECK(hearth_scene_hash(r) == hearth_scene_hash(s));
    hearth_scene_destroy(r);
}

/* The temperature curves' memo (PC_CURVE_MEMO, material_batch.c) is a cache too: a dough with a curve on
 * tau_y saves no memo column after 20 steps that filled it, its restore starts it empty and continues with the
 * same bits as the unbroken run, and a file that claims it is refused by name. */
static void curve_memo_bit(uint8_t *b, size_t n) { claim_column(b, n, PC_CURVE_MEMO); }
TEST(checkpoint_curve_memo_refused_and_refilled) {
    hearth_scene *s = vent_scene(0.02);
    CHECK(s != NULL);
    if (!s) return;
    hearth_error err;
    const double T[2] = {20, 60}, ty[2] = {1e6, 5e5};
    CHECK(hearth_scene_material_curve(s, 0, "tau_y", 2, T, ty, 1, &err) == HEARTH_OK);
    CHECK(s->ps.enabled & (1u << PC_CURVE_MEMO));
    CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
    int filled = 0;
    for (int i = 0; i < s->ps.n; i++) filled += pcold(&s->ps, PC_CURVE_MEMO)[CURVE_MEMO_WIDTH * i] > 0;
    CHECK(filled == s->ps.n);
    memo_roundtrip(s, PC_CURVE_MEMO, "curve_memo", CURVE_MEMO_WIDTH, filled, curve_memo_bit, "curve_memo_roundtrip.ck");
    hearth_scene_destroy(s);
}

/* The plugin's memo (PC_PLUGIN_MEMO, <hearth/material.h> rule 10: cam_clay_dough's log b_zz) is a cache as
 * well: the 2D dough of vent_scene fills it (16 B a particle: memo_size 2), its save holds no such column and a
 * file that claims one is refused by name; the restore starts it zeroed and continues with the unbroken run's
 * bits. */
static void plugin_memo_bit(uint8_t *b, size_t n) { claim_column(b, n, PC_PLUGIN_MEMO); }
TEST(checkpoint_plugin_memo_refused_and_refilled) {
    hearth_scene *s = vent_scene(0.02);
    CHECK(s != NULL);
    if (!s) return;
    CHECK(s->ps.enabled & (1u << PC_PLUGIN_MEMO));
    CHECK(s->ps.memo_stride == 2 && particles_col_bytes(&s->ps, PC_PLUGIN_MEMO) == 16);
    int filled = 0;
    for (int i = 0; i < s->ps.n; i++) filled += pcold(&s->ps, PC_PLUGIN_MEMO)[2 * i] > 0; /* a key b_zz > 0 */
    CHECK(filled > 0);
    memo_roundtrip(s, PC_PLUGIN_MEMO, "plugin_memo", 2, filled, plugin_memo_bit, "plugin_memo_roundtrip.ck");
    hearth_scene_destroy(s);
}

/* The step's bound on a lone particle (mpm_self.c; helper wallcrush) comes from the previous step's G2P (self_max)
 * and binds at cfl > 0.9 / sqrt(dim). Version 13 saves it: an elastic block and a lone particle falling beside it
 * at cfl 0.9 (the bound binding), saved after 20 steps and restored, continue bit for bit as the run that never stopped (20 steps more);
 * the same restore with self_max 0, as a version 12 file restored it, takes its first step unbounded and ends on
 * other bits, so the equality says the bound came back. */
static hearth_scene *lone_scene(void) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.05;
    d.cfl = 0.9;
    d.dt_max = 1;
    d.gravity[1] = -1; /* slow: at 9.81 m/s^2 the speed's CFL term binds before the bound does */
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NULL;
    const int m = fx_elastic(s, 1e4, 0.3, 1000);
    CHECK(fx_box(s, m, (const double[3]){0.5, 0.3, 0}, (const double[3]){0.1, 0.1, 0}, 4, NULL) > 0);
    hearth_error err;
    const double x[3] = {0.2, 0.5, 0};
    CHECK(hearth_scene_add_particles(s, m, 1, x, NULL, 0.025 * 0.025, &err) >= 0);
    CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
    return s;
}
TEST(checkpoint_self_max_continues_same_bits) {
    hearth_scene *s = lone_scene();
    CHECK(s != NULL);
    if (!s) return;
    CHECK(mpm_self_asked(s) && s->self_max > 0);
    size_t n;
    uint8_t *img = save_image(s, &n);
    CHECK(img != NULL);
    hearth_error err;
    hearth_scene *r = img ? hearth_scene_load_mem(img, n, "lone.ck", &err) : NULL;
    hearth_scene *z = img ? hearth_scene_load_mem(img, n, "lone.ck", &err) : NULL;
    if (!r && img) printf("  refused: %s\n", err.msg);
    CHECK(r != NULL && z != NULL);
    if (r && z) {
        const double saved = s->self_max;
        CHECK(r->self_max == saved);
        z->self_max = 0; /* as a version 12 file restored it */
        const double dt_bound = mpm_self_dt(s);
        CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
        CHECK(hearth_scene_step(r, 20, &err) == HEARTH_OK);
        CHECK(hearth_scene_step(z, 20, &err) == HEARTH_OK);
        const uint64_t hs = hearth_scene_hash(s), hr = hearth_scene_hash(r), hz = hearth_scene_hash(z);
        printf("  cfl 0.9, self_max %.6f at the save (its step bound %.3g s); 20 steps on: hash %016llx unbroken, %016llx "
               "restored, %016llx restored without it; t %.9g / %.9g / %.9g s\n", saved, dt_bound, (unsigned long long)hs,
               (unsigned long long)hr, (unsigned long long)hz, s->t, r->t, z->t);
        CHECK(hr == hs);
        CHECK(hz != hs);
    }
    hearth_scene_destroy(r);
    hearth_scene_destroy(z);
    free(img);
    hearth_scene_destroy(s);
}

TEST_MAIN(T(checkpoint_v4_roundtrip), T(checkpoint_bad_magic), T(checkpoint_truncated), T(checkpoint_every_byte_flip),
          T(checkpoint_bitflip_campaign), T(checkpoint_resealed_flips), T(checkpoint_crafted_fields),
          T(checkpoint_count_before_alloc),
          T(checkpoint_not_regular_file), T(checkpoint_alloc_failures),
          T(checkpoint_v5_def_fields_refused), T(checkpoint_venting_continues_same_bits),
          T(checkpoint_memo_columns_refused),
          T(checkpoint_curve_memo_refused_and_refilled), T(checkpoint_plugin_memo_refused_and_refilled), T(checkpoint_self_max_continues_same_bits))
