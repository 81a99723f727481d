/* unit_dumps.c: particle dumps (VTU and PLY).
 *
 * Each file is parsed back here with a reader written for the test, decoding
 * little-endian bytes by hand, so the check does not depend on the host's
 * byte order nor share code with the writer. Values must come back bit for
 * bit: the dumps are Float64 of the same doubles the API returns. */
#define _GNU_SOURCE /* mkdtemp, setrlimit, memmem */

#include <dirent.h>
#include <signal.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "alloc.h"
#include "colormap.h"
#include "fs_fixture.h"
#include "mpm_fixture.h"

/* ---- helpers --------------------------------------------------------- */

static uint64_t le_u64(const unsigned char *p) {
    uint64_t v = 0;
    for (int i = 7; i >= 0; i--) v = v << 8 | p[i];
    return v;
}

static double le_f64(const unsigned char *p) {
    uint64_t u = le_u64(p);
    double d;
    memcpy(&d, &u, sizeof d);
    return d;
}

/* Same doubles bit for bit (NaN included). */
static int same_doubles(const double *a, const double *b, size_t n) {
    for (size_t i = 0; i < n; i++)
        if (memcmp(&a[i], &b[i], sizeof(double)) != 0) return 0;
    return 1;
}

/* A small 2D solid block, moving and stepped a few times so that time,
 * velocity and density are all non-trivial. With `stateful` the material is
 * the nan_after fixture (never reaching its NaN): it keeps per-particle
 * state, so evaluating stress fields allocates, and allocation failures
 * reach the dumps' field-evaluation error paths too. */
static hearth_scene *small_scene(int stateful) {
    hearth_scene *s = fx_scene(2, 0.05, 0.0, 1.0);
    if (!s) return NULL;
    int m = -1;
    if (stateful) {
        const char *nm[] = {"after"};
        const double nv[] = {1e9};
        hearth_error err;
        m = hearth_scene_add_material(s, fx_test_plugin("nan_after"), nm, nv, 1, &err);
        if (m < 0) fprintf(stderr, "material: %s\n", err.msg);
    } else {
        m = fx_elastic(s, 1e5, 0.3, 1000);
    }
    CHECK(m >= 0);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.1, 0.1, 0}, v[3] = {0.3, -0.2, 0};
    CHECK(fx_box(s, m, c, h, 4, v) > 0);
    hearth_error err;
    CHECK(hearth_scene_step(s, 3, &err) == HEARTH_OK);
    return s;
}

/* ---- a VTU reader, just enough for these files ------------------------ */

typedef struct vtu {
    unsigned char *buf;
    size_t len;
    const char *xml;           /* up to the appended data: NUL-terminated copy */
    const unsigned char *data; /* the byte after '_' */
} vtu;

static int vtu_load(vtu *v, const char *path) {
    memset(v, 0, sizeof *v);
    v->buf = slurp(path, &v->len);
    if (!v->buf) return 0;
    char *app = strstr((char *)v->buf, "<AppendedData encoding=\"raw\">");
    if (!app) return 0;
    char *us = strchr(app, '_');
    if (!us) return 0;
    v->data = (unsigned char *)us + 1;
    *app = '\0'; /* the XML part ends here; binary data may contain NULs anyway */
    v->xml = (const char *)v->buf;
    return 1;
}

/* The DataArray tag carrying Name="name": its attribute `attr` as a number. */
static int vtu_attr(const vtu *v, const char *name, const char *attr, unsigned long long *out) {
    char key[128];
    snprintf(key, sizeof key, "Name=\"%s\"", name);
    const char *p = strstr(v->xml, key);
    if (!p) return 0;
    const char *open = p, *close = strchr(p, '>');
    while (open > v->xml && *open != '<') open--;
    char want[64];
    snprintf(want, sizeof want, " %s=\"", attr);
    const char *a = strstr(open, want);
    if (!a || !close || a > close) return 0;
    *out = strtoull(a + strlen(want), NULL, 10);
    return 1;
}

/* The bytes of an appended array, with its byte count; NULL if out of the file. */
static const unsigned char *vtu_array(const vtu *v, const char *name, uint64_t *bytes) {
    unsigned long long off;
    if (!vtu_attr(v, name, "offset", &off)) return NULL;
    const unsigned char *end = v->buf + v->len;
    if (v->data + off + 8 > end) return NULL;
    *bytes = le_u64(v->data + off);
    if (v->data + off + 8 + *bytes > end) return NULL;
    return v->data + off + 8;
}

/* Structure every VTU from hearth must have, for any particle count. */
static void check_vtu_common(const vtu *v, const hearth_scene *s) {
    const size_t n = (size_t)hearth_scene_particle_count(s);
    CHECK_STR_CONTAINS(v->xml, "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
                               "header_type=\"UInt64\">");
    char want[128];
    snprintf(want, sizeof want, "NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\"", n, n);
    CHECK_STR_CONTAINS(v->xml, want);

    /* Every live field is a PointData array "name [unit]" with its component count. */
    char names[256];
    snprintf(names, sizeof names, "%s", hearth_scene_fields(s));
    uint64_t last_end = 0;
    for (char *save = NULL, *f = strtok_r(names, " ", &save); f; f = strtok_r(NULL, " ", &save)) {
        unsigned long long nc = 0;
        char an[96];
        snprintf(an, sizeof an, "%s [%s]", f, hearth_field_unit(f));
        CHECK(vtu_attr(v, an, "NumberOfComponents", &nc));
        CHECK(nc == (unsigned long long)hearth_field_components(f));
        uint64_t bytes = 0;
        const unsigned char *p = vtu_array(v, an, &bytes);
        CHECK(p != NULL);
        CHECK(bytes == 8 * nc * n);
        if (p) last_end = (uint64_t)(p - v->data) + bytes;
    }
    /* The last field's data ends the block: nothing is missing or left over. */
    const char *tail = "\n</AppendedData>\n</VTKFile>\n";
    CHECK(last_end + strlen(tail) == (uint64_t)(v->buf + v->len - v->data));
    CHECK(memcmp(v->data + last_end, tail, strlen(tail)) == 0);

    /* Time as FieldData, one tuple. */
    hearth_stats st;
    hearth_scene_stats(s, &st);
    uint64_t bytes = 0;
    const unsigned char *t = vtu_array(v, "TimeValue", &bytes);
    CHECK(t && bytes == 8);
    if (t) CHECK(le_f64(t) == st.t);
    unsigned long long tuples = 0;
    CHECK(vtu_attr(v, "TimeValue", "NumberOfTuples", &tuples) && tuples == 1);
    CHECK(strstr(v->xml, "Name=\"TIME\"") == NULL);
    CHECK_STR_CONTAINS(v->xml, "<PointData Vectors=\"velocity [m/s]\" Tensors=\"stress [Pa]\" GlobalIds=\"id\">");

    /* Ids bit for bit, masses, and volumes that are mass over density. */
    const unsigned char *id = vtu_array(v, "id", &bytes);
    CHECK(id && bytes == 4 * n);
    const int *ids = hearth_scene_particle_ids(s);
    for (size_t i = 0; id && i < n; i++)
        CHECK((int32_t)(id[4 * i] | id[4 * i + 1] << 8 | id[4 * i + 2] << 16 | (uint32_t)id[4 * i + 3] << 24) == ids[i]);
    const int d2 = hearth_scene_get_def(s)->dim == 2;
    const unsigned char *ma = vtu_array(v, d2 ? "mass [kg/m]" : "mass [kg]", &bytes);
    CHECK(ma && bytes == 8 * n);
    const unsigned char *vo = vtu_array(v, d2 ? "volume [m^2]" : "volume [m^3]", &bytes);
    CHECK(vo && bytes == 8 * n);
    double *rho = malloc(sizeof(double) * (n + 1));
    hearth_error err;
    CHECK(hearth_scene_particle_field(s, "density", rho, &err) == HEARTH_OK);
    for (size_t i = 0; ma && vo && i < n; i++) {
        CHECK(le_f64(ma + 8 * i) == hearth_scene_particle_masses(s)[i]);
        CHECK(fabs(le_f64(ma + 8 * i) / le_f64(vo + 8 * i) - rho[i]) <= 1e-12 * rho[i]);
    }
    free(rho);

    /* One VTK_VERTEX per particle. */
    const unsigned char *conn = vtu_array(v, "connectivity", &bytes);
    CHECK(conn && bytes == 8 * n);
    for (size_t i = 0; conn && i < n; i++) CHECK(le_u64(conn + 8 * i) == i);
    const unsigned char *offs = vtu_array(v, "offsets", &bytes);
    CHECK(offs && bytes == 8 * n);
    for (size_t i = 0; offs && i < n; i++) CHECK(le_u64(offs + 8 * i) == i + 1);
    const unsigned char *types = vtu_array(v, "types", &bytes);
    CHECK(types && bytes == n);
    for (size_t i = 0; types && i < n; i++) CHECK(types[i] == 1);
}

/* ---- a PLY reader ------------------------------------------------------ */

typedef struct ply {
    unsigned char *buf;
    size_t len, n, nprops, row; /* row: bytes per vertex */
    char props[40][32];
    size_t size[40], off[40];   /* each property's bytes (uchar 1, int 4, double 8) and offset in the row */
    double t;
    const unsigned char *body;
} ply;

static int ply_load(ply *p, const char *path) {
    memset(p, 0, sizeof *p);
    p->t = NAN;
    p->buf = slurp(path, &p->len);
    if (!p->buf) return 0;
    char *end = strstr((char *)p->buf, "end_header\n");
    if (!end) return 0;
    p->body = (unsigned char *)end + strlen("end_header\n");
    *end = '\0';
    char *save = NULL;
    char *line = strtok_r((char *)p->buf, "\n", &save);
    if (!line || strcmp(line, "ply") != 0) return 0;
    line = strtok_r(NULL, "\n", &save);
    if (!line || strcmp(line, "format binary_little_endian 1.0") != 0) return 0;
    while ((line = strtok_r(NULL, "\n", &save))) {
        char name[32], type[16];
        unsigned long n;
        if (strncmp(line, "comment hearth t=", 17) == 0) p->t = strtod(line + 17, NULL);
        else if (sscanf(line, "element vertex %lu", &n) == 1) p->n = n;
        else if (sscanf(line, "property %15s %31s", type, name) == 2 && p->nprops < 40) {
            size_t sz = !strcmp(type, "double") ? 8 : !strcmp(type, "int") ? 4 : !strcmp(type, "uchar") ? 1 : 0;
            if (!sz) return 0;
            p->size[p->nprops] = sz;
            p->off[p->nprops] = p->row;
            p->row += sz;
            snprintf(p->props[p->nprops++], sizeof p->props[0], "%s", name);
        } else if (strncmp(line, "comment ", 8) != 0) return 0; /* anything else is unexpected */
    }
    return 1;
}

static int ply_prop(const ply *p, const char *name) {
    for (size_t k = 0; k < p->nprops; k++)
        if (!strcmp(p->props[k], name)) return (int)k;
    return -1;
}

static double ply_value(const ply *p, size_t i, int prop) {
    const unsigned char *b = p->body + i * p->row + p->off[prop];
    if (p->size[prop] == 1) return b[0];
    if (p->size[prop] == 4) return (int32_t)(b[0] | b[1] << 8 | b[2] << 16 | (uint32_t)b[3] << 24);
    return le_f64(b);
}

/* Header and size every PLY from hearth must have. */
static void check_ply_common(const ply *p, const hearth_scene *s) {
    const size_t n = (size_t)hearth_scene_particle_count(s);
    hearth_stats st;
    hearth_scene_stats(s, &st);
    CHECK(p->n == n);
    CHECK(p->t == st.t);
    CHECK(p->nprops >= 3 && !strcmp(p->props[0], "x") && !strcmp(p->props[1], "y") && !strcmp(p->props[2], "z"));
    /* the colours ParaView, Blender and MeshLab show, then id, mass, volume */
    CHECK(ply_prop(p, "red") == 3 && ply_prop(p, "green") == 4 && ply_prop(p, "blue") == 5);
    CHECK(ply_prop(p, "id") == 6 && ply_prop(p, "mass") == 7 && ply_prop(p, "volume") == 8);
    size_t want = 9;
    char names[256];
    snprintf(names, sizeof names, "%s", hearth_scene_fields(s));
    for (char *save = NULL, *f = strtok_r(names, " ", &save); f; f = strtok_r(NULL, " ", &save)) {
        char prop[64];
        int nc = hearth_field_components(f);
        for (int k = 0; k < nc; k++) {
            static const char *const vec[3] = {"_x", "_y", "_z"};
            static const char *const ten[9] = {"_xx", "_xy", "_xz", "_yx", "_yy", "_yz", "_zx", "_zy", "_zz"};
            snprintf(prop, sizeof prop, "%s%s", f, nc == 1 ? "" : nc == 3 ? vec[k] : ten[k]);
            CHECK(ply_prop(p, prop) == (int)want);
            want++;
        }
    }
    CHECK(p->nprops == want);
    CHECK((size_t)(p->buf + p->len - p->body) == n * p->row);
}

/* ---- cases ------------------------------------------------------------- */

TEST(vtu_roundtrip) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/scene.vtu", dir);
    hearth_scene *s = small_scene(0);
    CHECK(s != NULL);
    if (!s) return;
    hearth_error err = {0};
    CHECK(hearth_write_vtu(s, path, &err) == HEARTH_OK);
    CHECK(err.code == HEARTH_OK);

    vtu v;
    CHECK(vtu_load(&v, path));
    if (v.xml) {
        check_vtu_common(&v, s);
        const int n = hearth_scene_particle_count(s);
        CHECK(n > 10);
        uint64_t bytes = 0;
        const unsigned char *pts = vtu_array(&v, "Points", &bytes);
        CHECK(pts && bytes == 24 * (uint64_t)n);
        double *got = malloc(sizeof(double) * 3 * (size_t)n), *want = malloc(sizeof(double) * (size_t)n);
        for (int i = 0; pts && i < 3 * n; i++) got[i] = le_f64(pts + 8 * i);
        if (pts) CHECK(same_doubles(got, hearth_scene_positions(s), 3 * (size_t)n));

        const unsigned char *rho = vtu_array(&v, "density [kg/m^3]", &bytes);
        CHECK(rho && bytes == 8 * (uint64_t)n);
        CHECK(hearth_scene_particle_field(s, "density", want, &err) == HEARTH_OK);
        for (int i = 0; rho && i < n; i++) got[i] = le_f64(rho + 8 * i);
        if (rho) CHECK(same_doubles(got, want, (size_t)n));
        CHECK(want[0] > 500 && want[0] < 2000); /* a real density, not zeros */
        free(got);
        free(want);
    }
    free(v.buf);
    hearth_scene_destroy(s);
    CHECK(count_tmp(dir) == 0);
    rm_dir(dir);
}

TEST(ply_roundtrip) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    snprintf(path, sizeof path, "%s/scene.ply", dir);
    hearth_scene *s = small_scene(0);
    CHECK(s != NULL);
    if (!s) return;
    hearth_error err = {0};
    CHECK(hearth_write_ply(s, path, &err) == HEARTH_OK);

    ply p;
    CHECK(ply_load(&p, path));
    if (p.body) {
        check_ply_common(&p, s);
        const size_t n = (size_t)hearth_scene_particle_count(s);
        CHECK(n > 10);
        double *speed = malloc(sizeof(double) * n), *vel = malloc(sizeof(double) * 3 * n);
        CHECK(hearth_scene_particle_field(s, "speed", speed, &err) == HEARTH_OK);
        CHECK(hearth_scene_particle_field(s, "velocity", vel, &err) == HEARTH_OK);
        const double *x = hearth_scene_positions(s);
        const int px = ply_prop(&p, "x"), psp = ply_prop(&p, "speed"), pvy = ply_prop(&p, "velocity_y");
        CHECK(psp >= 0 && pvy >= 0);
        int bad = 0;
        for (size_t i = 0; psp >= 0 && pvy >= 0 && i < n; i++) {
            double row[3] = {ply_value(&p, i, px), ply_value(&p, i, px + 1), ply_value(&p, i, px + 2)};
            double sp = ply_value(&p, i, psp), vy = ply_value(&p, i, pvy);
            bad += !same_doubles(row, x + 3 * i, 3) || !same_doubles(&sp, &speed[i], 1) ||
                   !same_doubles(&vy, &vel[3 * i + 1], 1);
        }
        CHECK(bad == 0);
        CHECK(speed[0] > 0.1); /* the block moves */
        /* ids and masses as the API gives them */
        const int pid = ply_prop(&p, "id"), pm = ply_prop(&p, "mass");
        int idbad = 0;
        for (size_t i = 0; i < n; i++)
            idbad += ply_value(&p, i, pid) != hearth_scene_particle_ids(s)[i] ||
                     ply_value(&p, i, pm) != hearth_scene_particle_masses(s)[i];
        CHECK(idbad == 0);

        /* Colours from a given range: each vertex is the map's colour of its
         * speed, and the header says which field, range and map. */
        hearth_ply_def def = hearth_default_ply_def();
        def.color_field = "speed";
        def.range[0] = 0.0, def.range[1] = 1.0;
        def.colormap = "inferno";
        CHECK(hearth_write_ply_with(s, path, &def, &err) == HEARTH_OK);
        size_t hl = 0;
        char *raw = (char *)slurp(path, &hl);
        CHECK(raw && memmem(raw, hl, "comment color speed 0 1 m/s inferno\n", 36));
        free(raw);
        ply q;
        CHECK(ply_load(&q, path));
        if (q.body) {
            const int pr = ply_prop(&q, "red");
            int cbad = 0;
            for (size_t i = 0; i < n; i++) {
                unsigned char rgb[3];
                cmap_eval(CMAP_INFERNO, speed[i], rgb);
                for (int k = 0; k < 3; k++) cbad += ply_value(&q, i, pr + k) != rgb[k];
            }
            printf("ply_roundtrip: %zu vertices; speed %.4g m/s is rgb %g %g %g\n", n, speed[0], ply_value(&q, 0, pr),
                   ply_value(&q, 0, pr + 1), ply_value(&q, 0, pr + 2));
            CHECK(cbad == 0);
        }
        free(q.buf);
        /* a tensor cannot be a colour; an unknown map is named */
        def.color_field = "stress";
        CHECK(hearth_write_ply_with(s, path, &def, &err) == HEARTH_ERR_PARAM);
        CHECK_STR_CONTAINS(err.msg, "is a tensor");
        def.color_field = NULL, def.colormap = "jet";
        CHECK(hearth_write_ply_with(s, path, &def, &err) == HEARTH_ERR_PARAM);
        CHECK_STR_CONTAINS(err.msg, "colormap 'jet' is unknown");
        free(speed);
        free(vel);
    }
    free(p.buf);
    hearth_scene_destroy(s);
    CHECK(count_tmp(dir) == 0);
    rm_dir(dir);
}

typedef hearth_status (*writer_fn)(const hearth_scene *, const char *, hearth_error *);

/* After a failed overwrite the old file must be there byte for byte. */
static void check_untouched(const char *path, const unsigned char *before, size_t n0) {
    size_t n1 = 0;
    unsigned char *now = slurp(path, &n1);
    CHECK(now && n1 == n0 && memcmp(now, before, n0) == 0);
    free(now);
}

static void atomic_case(writer_fn write, const char *ext) {
    char dir[64], path[160];
    make_dir(dir, sizeof dir);
    hearth_scene *s = small_scene(1);
    CHECK(s != NULL);
    if (!s) return;
    hearth_error err = {0};

    /* A folder that does not exist. */
    snprintf(path, sizeof path, "%s/no_such_dir/scene.%s", dir, ext);
    CHECK(write(s, path, &err) == HEARTH_ERR_IO);
    CHECK(err.code == HEARTH_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, "No such file");

    /* A good file, then failed overwrites. */
    snprintf(path, sizeof path, "%s/scene.%s", dir, ext);
    CHECK(write(s, path, &err) == HEARTH_OK);
    size_t n0 = 0;
    unsigned char *before = slurp(path, &n0);
    CHECK(before && n0 > 1000);

    /* A write that fails part way: the file size limit stops it mid-file
     * (EFBIG), as a full disk would. SIGXFSZ would kill us, so ignore it. */
    void (*old_handler)(int) = signal(SIGXFSZ, SIG_IGN);
    struct rlimit old_lim, lim;
    CHECK(getrlimit(RLIMIT_FSIZE, &old_lim) == 0);
    lim = old_lim;
    lim.rlim_cur = 700;
    CHECK(setrlimit(RLIMIT_FSIZE, &lim) == 0);
    hearth_status st = write(s, path, &err);
    CHECK(setrlimit(RLIMIT_FSIZE, &old_lim) == 0);
    signal(SIGXFSZ, old_handler);
    CHECK(st == HEARTH_ERR_IO);
    CHECK_STR_CONTAINS(err.msg, path);
    CHECK_STR_CONTAINS(err.msg, "too large");
    check_untouched(path, before, n0);

    /* Every allocation the write makes fails in turn: NOMEM each time, the
     * old file kept, nothing leaked. */
    size_t bytes0 = hearth_bytes_allocated();
    int fails = 0, field_fails = 0;
    for (long k = 0; k < 100; k++) {
        mem_fail_after(k);
        st = write(s, path, &err);
        mem_fail_after(-1);
        if (st == HEARTH_OK) break;
        fails++;
        field_fails += strstr(err.msg, "field '") != NULL;
        CHECK(st == HEARTH_ERR_NOMEM);
        CHECK(err.code == HEARTH_ERR_NOMEM);
        CHECK_STR_CONTAINS(err.msg, path);
        check_untouched(path, before, n0);
        CHECK(hearth_bytes_allocated() == bytes0);
        CHECK(count_tmp(dir) == 0); /* now: a later write would reuse the name */
    }
    CHECK(fails >= 3);       /* the field list, the buffer, a field's scratch */
    CHECK(field_fails >= 1); /* a failure while evaluating fields was reached */
    check_untouched(path, before, n0); /* the final good write wrote the same bytes */
    CHECK(hearth_bytes_allocated() == bytes0);

    CHECK(count_tmp(dir) == 0);
    free(before);
    hearth_scene_destroy(s);
    rm_dir(dir);
}

TEST(dumps_atomic) {
    atomic_case(hearth_write_vtu, "vtu");
    atomic_case(hearth_write_ply, "ply");
}

TEST(dumps_empty_scene) {
    char dir[64], path[128];
    make_dir(dir, sizeof dir);
    hearth_scene *s = fx_scene(2, 0.05, 0.0, 1.0);
    CHECK(s != NULL);
    if (!s) return;
    CHECK(fx_elastic(s, 1e5, 0.3, 1000) >= 0);
    CHECK(hearth_scene_particle_count(s) == 0);
    hearth_error err = {0};

    snprintf(path, sizeof path, "%s/empty.vtu", dir);
    CHECK(hearth_write_vtu(s, path, &err) == HEARTH_OK);
    vtu v;
    CHECK(vtu_load(&v, path));
    if (v.xml) {
        check_vtu_common(&v, s);
        uint64_t bytes = 1;
        CHECK(vtu_array(&v, "Points", &bytes) != NULL && bytes == 0);
    }
    free(v.buf);

    snprintf(path, sizeof path, "%s/empty.ply", dir);
    CHECK(hearth_write_ply(s, path, &err) == HEARTH_OK);
    ply p;
    CHECK(ply_load(&p, path));
    if (p.body) check_ply_common(&p, s);
    free(p.buf);

    hearth_scene_destroy(s);
    CHECK(count_tmp(dir) == 0);
    rm_dir(dir);
}

TEST_MAIN(T(vtu_roundtrip), T(ply_roundtrip), T(dumps_atomic), T(dumps_empty_scene))
