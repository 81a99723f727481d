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
 * Only the public API is used (and colormap.h for the PLY's colours), so a
 * dump sees exactly what a user of hearth_scene_particle_field would see. Files go through atomic_file, so a
 * failed write leaves any old file as it was and no temp file behind.
 *
 * Both formats are little-endian whatever the host: a big-endian host swaps
 * each value on the way out. The alternative, declaring the host's order
 * (VTK's byte_order, PLY's binary_big_endian), would make files depend on
 * the machine that wrote them. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "atomic_file.h"
#include "colormap.h"
#include "error.h"
#include "hearth/hearth.h"
#include "io_vtu.h"

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

/* Mass and volume per particle: per metre of depth in 2D. */
static const char *mass_unit(const hearth_scene *s) { return hearth_scene_get_def(s)->dim == 2 ? "kg/m" : "kg"; }
static const char *volume_unit(const hearth_scene *s) { return hearth_scene_get_def(s)->dim == 2 ? "m^2" : "m^3"; }

/* Each particle's volume, mass over its density: the density field is what
 * the solver itself uses (MPM: m / (V0 det F); SPH: the summed density), so
 * mass / volume reads back as the "density" array. */
static hearth_status particle_volumes(const hearth_scene *s, double *out, const char *path, hearth_error *err) {
    hearth_status st = field_values(s, "density", out, path, err);
    if (st) return st;
    const double *m = hearth_scene_particle_masses(s);
    const size_t n = (size_t)hearth_scene_particle_count(s);
    for (size_t i = 0; i < n; i++) out[i] = m[i] / out[i];
    return HEARTH_OK;
}

/* ---- VTU ------------------------------------------------------------- */

/* Units travel in the array names, "temperature [degC]": VTK's XML format has
 * no unit attribute, and a name is the one thing every reader (VTK, ParaView,
 * meshio, VisIt) keeps and shows, in ParaView's colour legend too. The
 * alternative, an InformationKey element, is dropped by readers that do not
 * register the key (VTK 9.1 among them). */
static void vtu_name(char *out, size_t n, const char *field, const char *unit) { snprintf(out, n, "%s [%s]", field, unit); }

/* Offsets in the appended block count from the byte after '_'; every array
 * there is a UInt64 byte count (header_type) followed by the bytes. */
static void vtu_array_tag(dump *d, const char *type, const char *name, int nc, uint64_t *offset, uint64_t bytes) {
    put_text(d, "<DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" format=\"appended\" offset=\"%llu\"/>\n",
             type, name, nc, (unsigned long long)*offset);
    *offset += sizeof(uint64_t) + bytes;
}

/* The time as FieldData "TimeValue": the array vtkXMLReader reports as the
 * file's time step (SetActiveTimeDataArrayName's default), so a .vtu opened
 * alone still has its time. FieldData arrays have no Piece to take their
 * length from: without NumberOfTuples VTK reads them as empty. The old name
 * TIME is gone; nothing read it. */
static void vtu_time_tag(dump *d, uint64_t *offset) {
    put_text(d, "<DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfComponents=\"1\" NumberOfTuples=\"1\" "
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

/* The point arrays after Points, in file order: fn(ctx, type, name, nc) for
 * each. A piece's header and the .pvtu index both list them through this,
 * so the two cannot disagree. */
typedef void (*vtu_array_fn)(void *ctx, const char *type, const char *name, int nc);
static void vtu_point_arrays(const hearth_scene *s, const char *names, vtu_array_fn fn, void *ctx) {
    char name[NAME_CAP + 16];
    fn(ctx, "Int32", "id", 1);
    vtu_name(name, sizeof name, "mass", mass_unit(s));
    fn(ctx, "Float64", name, 1);
    vtu_name(name, sizeof name, "volume", volume_unit(s));
    fn(ctx, "Float64", name, 1);
    field_walk w = {names, "", 0};
    while (field_next(&w)) {
        vtu_name(name, sizeof name, w.name, unit_of(w.name));
        fn(ctx, "Float64", name, w.nc);
    }
}

/* The PointData element's attributes: velocity is ParaView's active vectors,
 * stress its active tensors (glyphs, eigenvalues), id the GlobalIds. */
static void vtu_point_data_open(dump *d, const char *element) {
    char vec[NAME_CAP + 16], ten[NAME_CAP + 16];
    vtu_name(vec, sizeof vec, "velocity", unit_of("velocity"));
    vtu_name(ten, sizeof ten, "stress", unit_of("stress"));
    put_text(d, "<%s Vectors=\"%s\" Tensors=\"%s\" GlobalIds=\"id\">\n", element, vec, ten);
}

typedef struct piece_tags {
    dump *d;
    uint64_t *off;
    size_t n;
} piece_tags;

static void piece_tag(void *ctx, const char *type, const char *name, int nc) {
    piece_tags *p = ctx;
    const size_t size = !strcmp(type, "Int32") ? sizeof(int32_t) : sizeof(double);
    vtu_array_tag(p->d, type, name, nc, p->off, size * (size_t)nc * p->n);
}

hearth_status vtu_write_range(const hearth_scene *s, const char *path, size_t lo, size_t hi, hearth_error *err) {
    err_clear(err);
    const size_t all = (size_t)hearth_scene_particle_count(s);
    HEARTH_ASSERT(lo <= hi && hi <= all);
    const size_t n = hi - lo; /* particles lo .. hi-1 of this process's set */
    hearth_stats stats;
    hearth_scene_stats(s, &stats);
    scratch sc;
    size_t max_nc = 0, total_nc = 0;
    hearth_status st = scratch_get(&sc, s, path, err);
    if (st) return st;
    field_counts(sc.names, &max_nc, &total_nc);
    /* Fields go out one at a time, so the buffer holds the widest one only
     * (at least one value each: the volumes use it too). A field is evaluated
     * at every particle the process holds, and the range's part written. */
    dump d;
    if ((st = scratch_buf(&sc, all * (max_nc ? max_nc : 1), path, err)) || (st = dump_open(&d, path, err))) {
        scratch_free(&sc);
        return st;
    }

    /* The XML part: every offset follows from n and the component counts. */
    uint64_t off = 0;
    put_text(&d, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
                 "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<UnstructuredGrid>\n<FieldData>\n"
                 "<!-- TimeValue: sim time (s) -->\n");
    vtu_time_tag(&d, &off);
    put_text(&d, "</FieldData>\n<Piece NumberOfPoints=\"%zu\" NumberOfCells=\"%zu\">\n<Points>\n", n, n);
    vtu_array_tag(&d, "Float64", "Points", 3, &off, 3 * sizeof(double) * n);
    put_text(&d, "</Points>\n<Cells>\n");
    vtu_array_tag(&d, "Int64", "connectivity", 1, &off, sizeof(int64_t) * n);
    vtu_array_tag(&d, "Int64", "offsets", 1, &off, sizeof(int64_t) * n);
    vtu_array_tag(&d, "UInt8", "types", 1, &off, n);
    put_text(&d, "</Cells>\n");
    vtu_point_data_open(&d, "PointData");
    vtu_point_arrays(s, sc.names, piece_tag, &(piece_tags){&d, &off, n});
    put_text(&d, "</PointData>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_");

    /* The appended block, in the order of the offsets above. An empty piece
     * (no particles yet) writes its counts alone: its columns may be NULL. */
    vtu_count(&d, sizeof(double));
    put_le(&d, &stats.t, sizeof(double), 1);
    vtu_count(&d, 3 * sizeof(double) * n);
    if (n) put_le(&d, hearth_scene_positions(s) + 3 * lo, sizeof(double), 3 * n);
    vtu_ramp(&d, n, 0);
    vtu_ramp(&d, n, 1);
    vtu_count(&d, n);
    unsigned char vertex[512];
    memset(vertex, 1, sizeof vertex); /* VTK_VERTEX */
    for (size_t i = 0; i < n; i += sizeof vertex) put_bytes(&d, vertex, n - i < sizeof vertex ? n - i : sizeof vertex);
    vtu_count(&d, sizeof(int32_t) * n);
    if (n) put_le(&d, hearth_scene_particle_ids(s) + lo, sizeof(int32_t), n); /* int is 32 bits on every host hearth builds on */
    vtu_count(&d, sizeof(double) * n);
    if (n) put_le(&d, hearth_scene_particle_masses(s) + lo, sizeof(double), n);
    if (!(st = particle_volumes(s, sc.buf, path, err))) {
        vtu_count(&d, sizeof(double) * n);
        put_le(&d, sc.buf + lo, sizeof(double), n);
    }
    field_walk w = {sc.names, "", 0};
    while (!st && !d.err_no && field_next(&w)) {
        if ((st = field_values(s, w.name, sc.buf, path, err))) break;
        vtu_count(&d, sizeof(double) * (size_t)w.nc * n);
        put_le(&d, sc.buf + (size_t)w.nc * lo, sizeof(double), (size_t)w.nc * n);
    }
    put_text(&d, "\n</AppendedData>\n</VTKFile>\n");
    scratch_free(&sc);
    if (st) {
        atomic_abort(&d.af);
        return st;
    }
    return dump_finish(&d, path, err);
}

hearth_status hearth_write_vtu(const hearth_scene *s, const char *path, hearth_error *err) {
    return vtu_write_range(s, path, 0, (size_t)hearth_scene_particle_count(s), err);
}

static void index_tag(void *ctx, const char *type, const char *name, int nc) {
    put_text(ctx, "<PDataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\"/>\n", type, name, nc);
}

/* A file name in an XML attribute: the five characters XML reserves escaped. */
static void put_attr(dump *d, const char *v) {
    for (; *v; v++) {
        switch (*v) {
        case '&': put_text(d, "&amp;"); break;
        case '<': put_text(d, "&lt;"); break;
        case '>': put_text(d, "&gt;"); break;
        case '"': put_text(d, "&quot;"); break;
        case '\'': put_text(d, "&apos;"); break;
        default: put_bytes(d, v, 1);
        }
    }
}

hearth_status vtu_write_index(const hearth_scene *s, const char *path, const char *stem, int npieces, hearth_error *err) {
    err_clear(err);
    scratch sc;
    hearth_status st = scratch_get(&sc, s, path, err);
    if (st) return st;
    dump d;
    if ((st = dump_open(&d, path, err))) {
        scratch_free(&sc);
        return st;
    }
    /* The pieces carry the data, their TimeValue too; the index names the
     * arrays (the same names, types and components as a one-process .vtu)
     * and the pieces, relative to itself. */
    put_text(&d, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" "
                 "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<PUnstructuredGrid GhostLevel=\"0\">\n"
                 "<PPoints>\n<PDataArray type=\"Float64\" Name=\"Points\" NumberOfComponents=\"3\"/>\n</PPoints>\n");
    vtu_point_data_open(&d, "PPointData");
    vtu_point_arrays(s, sc.names, index_tag, &d);
    put_text(&d, "</PPointData>\n");
    for (int k = 0; k < npieces; k++) {
        put_text(&d, "<Piece Source=\"");
        put_attr(&d, stem);
        put_text(&d, "_p%d.vtu\"/>\n", k);
    }
    put_text(&d, "</PUnstructuredGrid>\n</VTKFile>\n");
    scratch_free(&sc);
    return dump_finish(&d, path, err);
}

/* ---- PLY ------------------------------------------------------------- */

/* What each tool shows of these files (checked with VTK 9.1's vtkPLYReader,
 * which ParaView uses): ParaView/VTK read the points and red/green/blue as
 * the "RGB" array and skip every other property; Blender (4.x) and MeshLab
 * show the colours as vertex colours, and Blender imports the other vertex
 * properties as attributes; Open3D and plyfile read every property. So the
 * colours carry one field for the viewers, the raw doubles carry all of them
 * for scripts. */

hearth_ply_def hearth_default_ply_def(void) {
    return (hearth_ply_def){.color = 1, .color_field = NULL, .range = {0, 0}, .colormap = NULL};
}

/* Temperature where live (what a baking scene is about), else speed. */
static const char *default_color_field(const char *names) {
    field_walk w = {names, "", 0};
    while (field_next(&w))
        if (!strcmp(w.name, "temperature")) return "temperature";
    return "speed";
}

/* Little-endian copy of one value into a row. */
static unsigned char *store_le(unsigned char *dst, const void *src, size_t size, int swap) {
    const unsigned char *b = src;
    for (size_t j = 0; j < size; j++) dst[j] = swap ? b[size - 1 - j] : b[j];
    return dst + size;
}

/* The colour field's values as magnitudes (a vector's length), in col. */
static hearth_status color_values(const hearth_scene *s, const char *field, double *col, const char *path,
                                  hearth_error *err) {
    const int nc = hearth_field_components(field);
    if (nc != 1 && nc != 3)
        return err_set(err, HEARTH_ERR_PARAM,
                       "%s: color_field '%s' %s; colour by a scalar, a vector (its magnitude) or one component "
                       "(velocity_x, stress_xy, von_mises, ...)",
                       path, field, nc == 0 ? "is not a field" : "is a tensor");
    hearth_status st = field_values(s, field, col, path, err);
    if (st || nc == 1) return st;
    const size_t n = (size_t)hearth_scene_particle_count(s);
    for (size_t i = 0; i < n; i++)
        col[i] = sqrt(col[3 * i] * col[3 * i] + col[3 * i + 1] * col[3 * i + 1] + col[3 * i + 2] * col[3 * i + 2]);
    return HEARTH_OK;
}

hearth_status hearth_write_ply_with(const hearth_scene *s, const char *path, const hearth_ply_def *def,
                                    hearth_error *err) {
    err_clear(err);
    const hearth_ply_def dd = def ? *def : hearth_default_ply_def();
    const int map = cmap_by_name(dd.colormap ? dd.colormap : "viridis");
    if (dd.color && map < 0)
        return err_set(err, HEARTH_ERR_PARAM, "%s: colormap '%s' is unknown (valid: viridis, inferno, gray, browning)",
                       path, dd.colormap);
    if (dd.color && !(isfinite(dd.range[0]) && isfinite(dd.range[1])))
        return err_set(err, HEARTH_ERR_PARAM, "%s: range = {%g, %g}; both ends must be finite", path, dd.range[0],
                       dd.range[1]);
    const size_t n = (size_t)hearth_scene_particle_count(s);
    hearth_stats stats;
    hearth_scene_stats(s, &stats);
    scratch sc;
    size_t max_nc = 0, total_nc = 0;
    hearth_status st = scratch_get(&sc, s, path, err);
    if (st) return st;
    field_counts(sc.names, &max_nc, &total_nc);
    const char *cfield = dd.color ? (dd.color_field ? dd.color_field : default_color_field(sc.names)) : NULL;
    /* PLY is row-major (one vertex after another) while fields come a column
     * at a time, so the whole body is assembled first, as bytes: the row mixes
     * doubles, uchar colours and an int id. Writing field by field with seeks
     * would save the memory but not work on pipes. The scratch doubles hold
     * one field's values (at least 3 per particle: a colour vector) and the
     * rows after them. */
    const size_t row_bytes = 3 * 8 + (cfield ? 3 : 0) + 4 + 8 * (2 + total_nc);
    const size_t col_len = n * (max_nc > 3 ? max_nc : 3);
    const size_t row_doubles = (n * row_bytes + sizeof(double) - 1) / sizeof(double);
    if ((st = scratch_buf(&sc, col_len + row_doubles, path, err))) {
        scratch_free(&sc);
        return st;
    }
    double *col = sc.buf;
    unsigned char *rows = (unsigned char *)(sc.buf + col_len);
    const uint16_t one = 1;
    const int swap = *(const unsigned char *)&one != 1;
    double lo = dd.range[0], hi = dd.range[1];
    size_t at = 0; /* byte offset of the next property in row 0 */
    const double *x = hearth_scene_positions(s);
    for (size_t i = 0; i < n; i++)
        for (int k = 0; k < 3; k++) store_le(rows + i * row_bytes + 8 * (size_t)k, x + 3 * i + k, 8, swap);
    at = 24;
    if (cfield) {
        if ((st = color_values(s, cfield, col, path, err))) goto fail;
        if (!(lo < hi)) { /* the frame's own range */
            lo = INFINITY, hi = -INFINITY;
            for (size_t i = 0; i < n; i++)
                if (isfinite(col[i])) lo = col[i] < lo ? col[i] : lo, hi = col[i] > hi ? col[i] : hi;
            if (!(lo <= hi)) lo = 0, hi = 1; /* no finite value: every vertex gets the NaN grey */
        }
        for (size_t i = 0; i < n; i++) {
            /* a single-valued frame maps to the middle of the map */
            double t = hi > lo ? (col[i] - lo) / (hi - lo) : isnan(col[i]) ? col[i] : 0.5;
            cmap_eval(map, t, rows + i * row_bytes + at);
        }
        at += 3;
    }
    const int *ids = hearth_scene_particle_ids(s);
    const double *mass = hearth_scene_particle_masses(s);
    for (size_t i = 0; i < n; i++) {
        int32_t id = ids[i];
        store_le(store_le(rows + i * row_bytes + at, &id, 4, swap), mass + i, 8, swap);
    }
    at += 12;
    if ((st = particle_volumes(s, col, path, err))) goto fail;
    for (size_t i = 0; i < n; i++) store_le(rows + i * row_bytes + at, col + i, 8, swap);
    at += 8;
    field_walk w = {sc.names, "", 0};
    while (field_next(&w)) {
        if ((st = field_values(s, w.name, col, path, err))) goto fail;
        for (size_t i = 0; i < n; i++)
            for (int k = 0; k < w.nc; k++)
                store_le(rows + i * row_bytes + at + 8 * (size_t)k, col + i * (size_t)w.nc + k, 8, swap);
        at += 8 * (size_t)w.nc;
    }
    HEARTH_ASSERT(at == row_bytes);

    dump d;
    if ((st = dump_open(&d, path, err))) goto fail;
    /* %.17g: the time and range read back as the same doubles. */
    put_text(&d, "ply\nformat binary_little_endian 1.0\ncomment hearth t=%.17g\n", stats.t);
    if (cfield)
        put_text(&d, "comment color %s %.17g %.17g %s %s\n", cfield, lo, hi, unit_of(cfield),
                 dd.colormap ? dd.colormap : "viridis");
    put_text(&d, "comment unit mass %s\ncomment unit volume %s\n", mass_unit(s), volume_unit(s));
    w = (field_walk){sc.names, "", 0};
    while (field_next(&w)) put_text(&d, "comment unit %s %s\n", w.name, unit_of(w.name));
    put_text(&d, "element vertex %zu\nproperty double x\nproperty double y\nproperty double z\n", n);
    if (cfield) put_text(&d, "property uchar red\nproperty uchar green\nproperty uchar blue\n");
    put_text(&d, "property int id\nproperty double mass\nproperty double volume\n");
    static const char *const axis[3] = {"_x", "_y", "_z"};
    static const char *const pair[9] = {"_xx", "_xy", "_xz", "_yx", "_yy", "_yz", "_zx", "_zy", "_zz"};
    w = (field_walk){sc.names, "", 0};
    while (field_next(&w))
        for (int k = 0; k < w.nc; k++)
            put_text(&d, "property double %s%s\n", w.name, w.nc == 1 ? "" : w.nc == 3 ? axis[k] : pair[k]);
    put_text(&d, "end_header\n");
    put_bytes(&d, rows, n * row_bytes);
    scratch_free(&sc);
    return dump_finish(&d, path, err);
fail:
    scratch_free(&sc);
    return st;
}

hearth_status hearth_write_ply(const hearth_scene *s, const char *path, hearth_error *err) {
    return hearth_write_ply_with(s, path, NULL, err);
}
