/* io_particles.c: particle dumps for ParaView and other tools.
 *
 * Two formats, both binary Float64 so values survive bit for bit:
 *  - VTK XML UnstructuredGrid (.vtu): one VTK_VERTEX cell per particle, every
 *    array in one raw appended block. Raw rather than base64 because base64
 *    costs a third more space and an encoding pass for nothing ParaView needs;
 *    XML rather than legacy .vtk because legacy binary is big-endian only.
 *  - PLY (binary_little_endian): one vertex row per particle, for tools that
 *    read point clouds but not VTK (Blender, MeshLab, Open3D).
 *
 * Only the public API is used, so a dump sees exactly what a user of
 * hearth_scene_particle_field would see. Files go through atomic_file, so a
 * failed write leaves any old file as it was and no temp file behind.
 *
 * Both formats are little-endian whatever the host: a big-endian host swaps
 * each value on the way out. The alternative, declaring the host's order
 * (VTK's byte_order, PLY's binary_big_endian), would make files depend on
 * the machine that wrote them. */
#include <errno.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "atomic_file.h"
#include "error.h"
#include "hearth/hearth.h"

/* ---- the live fields ------------------------------------------------- */

enum { NAME_CAP = 64 };

/* Walks a copy of hearth_scene_fields: that string is a per-scene cache the
 * library rewrites on every call (error messages call it too), so iterating
 * the original while evaluating fields would read a moving target. */
typedef struct field_walk {
    const char *p;
    char name[NAME_CAP];
    int nc;
} field_walk;

static int field_next(field_walk *w) {
    while (*w->p == ' ') w->p++;
    if (!*w->p) return 0;
    size_t len = strcspn(w->p, " ");
    HEARTH_ASSERT(len < NAME_CAP); /* names come from the library itself */
    memcpy(w->name, w->p, len);
    w->name[len] = '\0';
    w->p += len;
    w->nc = hearth_field_components(w->name);
    HEARTH_ASSERT(w->nc == 1 || w->nc == 3 || w->nc == 9); /* the public contract; PLY names the components */
    return 1;
}

/* Evaluate one field at every particle; failures name the file being written. */
static hearth_status field_values(const hearth_scene *s, const char *field, double *out, const char *path,
                                  hearth_error *err) {
    hearth_error e = {0};
    hearth_status st = hearth_scene_particle_field(s, field, out, &e);
    if (st) return err_set(err, st, "%s: field '%s': %s", path, field, e.msg);
    return HEARTH_OK;
}

/* ---- little-endian output ------------------------------------------- */

typedef struct dump {
    atomic_file af;
    int swap;   /* host is big-endian: reverse each value's bytes */
    int err_no; /* errno of the first failed write; later writes are skipped */
} dump;

static hearth_status dump_open(dump *d, const char *path, hearth_error *err) {
    const uint16_t one = 1;
    d->swap = *(const unsigned char *)&one != 1;
    d->err_no = 0;
    return atomic_open(&d->af, path, err);
}

static void put_bytes(dump *d, const void *p, size_t n) {
    if (d->err_no || n == 0) return;
    errno = 0;
    if (fwrite(p, 1, n, d->af.f) != n) d->err_no = errno ? errno : EIO;
}

/* n values of `size` bytes each, written little-endian. */
static void put_le(dump *d, const void *p, size_t size, size_t n) {
    if (!d->swap || size == 1) {
        put_bytes(d, p, size * n);
        return;
    }
    const unsigned char *b = p;
    unsigned char tmp[4096];
    const size_t per = sizeof tmp / size;
    while (n && !d->err_no) {
        size_t k = n < per ? n : per;
        for (size_t i = 0; i < k; i++)
            for (size_t j = 0; j < size; j++) tmp[i * size + j] = b[i * size + size - 1 - j];
        put_bytes(d, tmp, k * size);
        b += k * size;
        n -= k;
    }
}

static void put_text(dump *d, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void put_text(dump *d, const char *fmt, ...) {
    if (d->err_no) return;
    va_list ap;
    va_start(ap, fmt);
    errno = 0;
    if (vfprintf(d->af.f, fmt, ap) < 0) d->err_no = errno ? errno : EIO;
    va_end(ap);
}

/* Commit, or on an earlier write error drop the temp file and say why. */
static hearth_status dump_finish(dump *d, const char *path, hearth_error *err) {
    if (d->err_no) {
        atomic_abort(&d->af);
        return err_set(err, HEARTH_ERR_IO, "%s: write failed: %s", path, strerror(d->err_no));
    }
    return atomic_commit(&d->af, err);
}

/* A copy of the field list and a scratch buffer of `doubles` values, both
 * counted by mem_*. The buffer always holds at least one value so that an
 * empty scene takes the same allocation path as any other. */
typedef struct scratch {
    char *names;
    double *buf;
    size_t doubles;
} scratch;

static hearth_status scratch_get(scratch *sc, const hearth_scene *s, const char *path, hearth_error *err) {
    sc->doubles = 0;
    sc->buf = NULL;
    sc->names = mem_strdup(hearth_scene_fields(s));
    if (!sc->names)
        return err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory for a dump of %d particles", path,
                       hearth_scene_particle_count(s));
    return HEARTH_OK;
}

static hearth_status scratch_buf(scratch *sc, size_t doubles, const char *path, hearth_error *err) {
    sc->doubles = doubles + 1;
    sc->buf = mem_alloc(sizeof(double) * sc->doubles);
    if (!sc->buf) {
        sc->doubles = 0;
        return err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory for a dump (%zu bytes)", path,
                       sizeof(double) * (doubles + 1));
    }
    return HEARTH_OK;
}

static void scratch_free(scratch *sc) {
    mem_free(sc->buf, sizeof(double) * sc->doubles);
    mem_strfree(sc->names);
}

/* Largest and total component counts over the live fields. */
static void field_counts(const char *names, size_t *max_nc, size_t *total_nc) {
    field_walk w = {names, "", 0};
    *max_nc = *total_nc = 0;
    while (field_next(&w)) {
        if ((size_t)w.nc > *max_nc) *max_nc = (size_t)w.nc;
        *total_nc += (size_t)w.nc;
    }
}

static const char *unit_of(const char *field) {
    const char *u = hearth_field_unit(field);
    return u ? u : "?";
}

/* ---- VTU ------------------------------------------------------------- */

/* Offsets in the appended block count from the byte after '_'; every array
 * there is a UInt64 byte count (header_type) followed by the bytes. */
static void vtu_array_tag(dump *d, const char *type, const char *name, int nc, uint64_t *offset, uint64_t bytes) {
    put_text(d, "<DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" format=\"appended\" offset=\"%llu\"/>\n",
             type, name, nc, (unsigned long long)*offset);
    *offset += sizeof(uint64_t) + bytes;
}

/* FieldData arrays have no Piece to take their length from: VTK reads an
 * array without NumberOfTuples there as empty. */
static void vtu_time_tag(dump *d, uint64_t *offset) {
    put_text(d, "<DataArray type=\"Float64\" Name=\"TIME\" NumberOfComponents=\"1\" NumberOfTuples=\"1\" "
                "format=\"appended\" offset=\"%llu\"/>\n",
             (unsigned long long)*offset);
    *offset += sizeof(uint64_t) + sizeof(double);
}

static void vtu_count(dump *d, uint64_t bytes) { put_le(d, &bytes, sizeof bytes, 1); }

/* Connectivity 0..n-1 or offsets 1..n, in chunks: no n-sized integer array. */
static void vtu_ramp(dump *d, size_t n, int64_t first) {
    vtu_count(d, (uint64_t)n * sizeof(int64_t));
    int64_t chunk[512];
    for (size_t i = 0; i < n;) {
        size_t k = 0;
        for (; k < 512 && i < n; k++, i++) chunk[k] = first + (int64_t)i;
        put_le(d, chunk, sizeof chunk[0], k);
    }
}

hearth_status hearth_write_vtu(const hearth_scene *s, const char *path, hearth_error *err) {
    err_clear(err);
    const size_t n = (size_t)hearth_scene_particle_count(s);
    hearth_stats stats;
    hearth_scene_stats(s, &stats);
    scratch sc;
    size_t max_nc = 0, total_nc = 0;
    hearth_status st = scratch_get(&sc, s, path, err);
    if (st) return st;
    field_counts(sc.names, &max_nc, &total_nc);
    /* Fields go out one at a time, so the buffer holds the widest one only. */
    dump d;
    if ((st = scratch_buf(&sc, n * max_nc, path, err)) || (st = dump_open(&d, path, err))) {
        scratch_free(&sc);
        return st;
    }

    /* The XML part: every offset follows from n and the component counts. */
    uint64_t off = 0;
    put_text(&d, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                 "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<UnstructuredGrid>\n<FieldData>\n"
                 "<!-- TIME: sim time (s) -->\n");
    vtu_time_tag(&d, &off);
    put_text(&d, "</FieldData>\n<Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n<Points>\n", n, n);
    vtu_array_tag(&d, "Float64", "Points", 3, &off, 3 * sizeof(double) * n);
    put_text(&d, "</Points>\n<Cells>\n");
    vtu_array_tag(&d, "Int64", "connectivity", 1, &off, sizeof(int64_t) * n);
    vtu_array_tag(&d, "Int64", "offsets", 1, &off, sizeof(int64_t) * n);
    vtu_array_tag(&d, "UInt8", "types", 1, &off, n);
    put_text(&d, "</Cells>\n<PointData>\n");
    field_walk w = {sc.names, "", 0};
    while (field_next(&w)) {
        /* VTK XML has no unit attribute; a comment keeps the unit for people. */
        put_text(&d, "<!-- %s: %s -->\n", w.name, unit_of(w.name));
        vtu_array_tag(&d, "Float64", w.name, w.nc, &off, sizeof(double) * (size_t)w.nc * n);
    }
    put_text(&d, "</PointData>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_");

    /* The appended block, in the order of the offsets above. */
    vtu_count(&d, sizeof(double));
    put_le(&d, &stats.t, sizeof(double), 1);
    vtu_count(&d, 3 * sizeof(double) * n);
    put_le(&d, hearth_scene_positions(s), sizeof(double), 3 * n);
    vtu_ramp(&d, n, 0);
    vtu_ramp(&d, n, 1);
    vtu_count(&d, n);
    unsigned char vertex[512];
    memset(vertex, 1, sizeof vertex); /* VTK_VERTEX */
    for (size_t i = 0; i < n; i += sizeof vertex) put_bytes(&d, vertex, n - i < sizeof vertex ? n - i : sizeof vertex);
    w = (field_walk){sc.names, "", 0};
    while (!d.err_no && field_next(&w)) {
        if ((st = field_values(s, w.name, sc.buf, path, err))) break;
        vtu_count(&d, sizeof(double) * (size_t)w.nc * n);
        put_le(&d, sc.buf, sizeof(double), (size_t)w.nc * n);
    }
    put_text(&d, "\n</AppendedData>\n</VTKFile>\n");
    scratch_free(&sc);
    if (st) {
        atomic_abort(&d.af);
        return st;
    }
    return dump_finish(&d, path, err);
}

/* ---- PLY ------------------------------------------------------------- */

hearth_status hearth_write_ply(const hearth_scene *s, const char *path, hearth_error *err) {
    err_clear(err);
    const size_t n = (size_t)hearth_scene_particle_count(s);
    hearth_stats stats;
    hearth_scene_stats(s, &stats);
    scratch sc;
    size_t max_nc = 0, total_nc = 0;
    hearth_status st = scratch_get(&sc, s, path, err);
    if (st) return st;
    field_counts(sc.names, &max_nc, &total_nc);
    /* PLY is row-major (one vertex after another) while fields come a column
     * at a time, so the whole body is assembled first: n rows of row_len,
     * then room for one field's values. Writing field by field with seeks
     * would save the memory but not work on pipes. */
    const size_t row_len = 3 + total_nc;
    if ((st = scratch_buf(&sc, n * row_len + n * max_nc, path, err))) {
        scratch_free(&sc);
        return st;
    }
    double *rows = sc.buf, *col = sc.buf + n * row_len;
    const double *x = hearth_scene_positions(s);
    for (size_t i = 0; i < n; i++) memcpy(rows + i * row_len, x + 3 * i, 3 * sizeof(double));
    field_walk w = {sc.names, "", 0};
    for (size_t c = 3; field_next(&w); c += (size_t)w.nc) {
        if ((st = field_values(s, w.name, col, path, err))) {
            scratch_free(&sc);
            return st;
        }
        for (size_t i = 0; i < n; i++)
            memcpy(rows + i * row_len + c, col + i * (size_t)w.nc, sizeof(double) * (size_t)w.nc);
    }

    dump d;
    if ((st = dump_open(&d, path, err))) {
        scratch_free(&sc);
        return st;
    }
    /* %.17g: the time reads back as the same double. */
    put_text(&d, "ply\nformat binary_little_endian 1.0\ncomment hearth t=%.17g\n", stats.t);
    w = (field_walk){sc.names, "", 0};
    while (field_next(&w)) put_text(&d, "comment unit %s %s\n", w.name, unit_of(w.name));
    put_text(&d, "element vertex %zu\nproperty double x\nproperty double y\nproperty double z\n", n);
    static const char *const axis[3] = {"_x", "_y", "_z"};
    static const char *const pair[9] = {"_xx", "_xy", "_xz", "_yx", "_yy", "_yz", "_zx", "_zy", "_zz"};
    w = (field_walk){sc.names, "", 0};
    while (field_next(&w))
        for (int k = 0; k < w.nc; k++)
            put_text(&d, "property double %s%s\n", w.name, w.nc == 1 ? "" : w.nc == 3 ? axis[k] : pair[k]);
    put_text(&d, "end_header\n");
    put_le(&d, rows, sizeof(double), n * row_len);
    scratch_free(&sc);
    return dump_finish(&d, path, err);
}
