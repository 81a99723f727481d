/* checkpoint.c: save and restore the full scene state.
 *
 * Layout (version 2, native endianness, checked on load; version 2 added the
 * water properties, the wet colliders and the water-lost clock):
 *   "HEARTHCK" u32 version u32 0x01020304 u32 sizeof(double)
 *   scene definition and clocks, field by field
 *   materials: plugin name, parameter count, parameters
 *   colliders: shape tree, contact, motion so far
 *   particles: count, state stride, enabled mask, then each enabled column
 *   u64 hash of the particle columns
 * A restored scene continues bit-identically: particle order, clocks, dt
 * scale, the jitter generator and collider poses are all in the file. Motion
 * callbacks are code and are not saved; re-attach them with
 * hearth_scene_collider_motion. */
#include <stdint.h>
#include <string.h>

#include "alloc.h"
#include "atomic_file.h"
#include "error.h"
#include "scene.h"
#include "shapes.h"

#define CK_MAGIC "HEARTHCK"
#define CK_VERSION 2u

typedef struct ck_io {
    FILE *f;
    int bad;
} ck_io;

static void wr(ck_io *io, const void *p, size_t n) {
    if (!io->bad && n && fwrite(p, n, 1, io->f) != 1) io->bad = 1;
}
static void rd(ck_io *io, void *p, size_t n) {
    if (!io->bad && n && fread(p, n, 1, io->f) != 1) io->bad = 1;
}
#define WR(io, v) wr(io, &(v), sizeof(v))
#define RD(io, v) rd(io, &(v), sizeof(v))

static void wr_str(ck_io *io, const char *s) {
    uint32_t n = (uint32_t)strlen(s);
    WR(io, n);
    wr(io, s, n);
}

static void rd_str(ck_io *io, char *buf, size_t cap) {
    uint32_t n = 0;
    RD(io, n);
    if (n >= cap) {
        io->bad = 1;
        return;
    }
    rd(io, buf, n);
    buf[io->bad ? 0 : n] = '\0';
}

static void io_def(ck_io *io, hearth_scene_def *d, int writing) {
    void (*f)(ck_io *, void *, size_t) = writing ? (void (*)(ck_io *, void *, size_t))wr : rd;
    int32_t dim = d->dim, wall = d->wall, guard = d->guard, mr = d->max_rollbacks;
    f(io, &dim, sizeof dim);
    f(io, &d->dx, sizeof d->dx);
    f(io, d->lo, sizeof d->lo);
    f(io, d->hi, sizeof d->hi);
    f(io, d->gravity, sizeof d->gravity);
    f(io, &d->cfl, sizeof d->cfl);
    f(io, &d->dt_max, sizeof d->dt_max);
    f(io, &wall, sizeof wall);
    f(io, &d->wall_friction, sizeof d->wall_friction);
    f(io, &guard, sizeof guard);
    f(io, &mr, sizeof mr);
    f(io, &d->energy_growth, sizeof d->energy_growth);
    f(io, &d->seed, sizeof d->seed);
    int32_t hi = d->heat_implicit, wm = d->water_momentum, tr = d->transfer;
    f(io, &d->oven_temperature, sizeof d->oven_temperature);
    f(io, &d->oven_beta, sizeof d->oven_beta);
    f(io, &hi, sizeof hi);
    f(io, &wm, sizeof wm);
    f(io, &tr, sizeof tr);
    f(io, &d->heat_flip, sizeof d->heat_flip);
    d->transfer = tr;
    d->heat_implicit = hi;
    d->water_momentum = wm;
    d->dim = dim;
    d->wall = (hearth_contact)wall;
    d->guard = (hearth_guard_policy)guard;
    d->max_rollbacks = mr;
}

static void io_clocks(ck_io *io, hearth_scene *s, int writing) {
    void (*f)(ck_io *, void *, size_t) = writing ? (void (*)(ck_io *, void *, size_t))wr : rd;
    int64_t step = s->step, ood = s->out_of_domain;
    int32_t rb = s->rollbacks, guard = s->guard, next_id = s->next_id, nbodies = s->nbodies;
    f(io, &s->t, sizeof s->t);
    f(io, &s->dt_last, sizeof s->dt_last);
    f(io, &s->dt_scale, sizeof s->dt_scale);
    f(io, &step, sizeof step);
    f(io, &rb, sizeof rb);
    f(io, &s->max_speed, sizeof s->max_speed);
    f(io, &s->c_max, sizeof s->c_max);
    f(io, &s->kinetic, sizeof s->kinetic);
    f(io, &s->kinetic_peak, sizeof s->kinetic_peak);
    f(io, &s->cfl_last, sizeof s->cfl_last);
    f(io, &ood, sizeof ood);
    f(io, &guard, sizeof guard);
    f(io, &s->rng, sizeof s->rng);
    f(io, &next_id, sizeof next_id);
    f(io, &nbodies, sizeof nbodies);
    f(io, &s->water_lost, sizeof s->water_lost);
    s->nbodies = nbodies;
    s->step = step;
    s->out_of_domain = ood;
    s->rollbacks = rb;
    s->guard = (hearth_guard_state)guard;
    s->next_id = next_id;
}

hearth_status hearth_scene_save(const hearth_scene *s, const char *path, hearth_error *err) {
    err_clear(err);
    if (s->def.solver != HEARTH_SOLVER_MPM) /* SPH (sph.c): its options and final densities are not in the format yet */
        return err_set(err, HEARTH_ERR_PARAM, "save %s: checkpoints of SPH scenes (solver = \"sph\") are not supported yet",
                       path);
    if (s->mix_mat >= 0) /* mixing.c: the constituents' parameter sets are not in the format yet */
        return err_set(err, HEARTH_ERR_PARAM, "save %s: checkpoints of scenes with a dynamic mixture are not supported yet",
                       path);
    atomic_file af;
    hearth_status st = atomic_open(&af, path, err);
    if (st) return st;
    ck_io io = {af.f, 0};
    wr(&io, CK_MAGIC, 8);
    uint32_t hdr[3] = {CK_VERSION, 0x01020304u, (uint32_t)sizeof(double)};
    wr(&io, hdr, sizeof hdr);
    hearth_scene_def d = s->def;
    io_def(&io, &d, 1);
    io_clocks(&io, (hearth_scene *)s, 1);
    int32_t nmat = s->nmat;
    WR(&io, nmat);
    for (int i = 0; i < s->nmat; i++) {
        wr_str(&io, hearth_plugin_file(s->mats[i].plugin));
        wr_str(&io, s->mats[i].m->name);
        int32_t np = s->mats[i].m->nparams;
        WR(&io, np);
        wr(&io, s->mats[i].params, sizeof(double) * (size_t)np);
        wr(&io, s->mats[i].core, sizeof(double) * CP_COUNT);
        int32_t nc = s->mats[i].ncurves;
        WR(&io, nc);
        for (int k = 0; k < nc; k++) {
            const curve *c = &s->mats[i].curves[k];
            int32_t hdr3[3] = {c->param, c->n, c->irreversible};
            wr(&io, hdr3, sizeof hdr3);
            wr(&io, c->T, sizeof(double) * (size_t)c->n);
            wr(&io, c->v, sizeof(double) * (size_t)c->n);
        }
    }
    int32_t ncol = s->ncol;
    WR(&io, ncol);
    for (int i = 0; i < s->ncol; i++) {
        const collider *c = &s->cols[i];
        if (!io.bad && shape_write(io.f, c->shape)) io.bad = 1;
        int32_t mode = c->mode, has_motion = c->motion != NULL;
        WR(&io, mode);
        WR(&io, c->friction);
        wr(&io, c->vel, sizeof c->vel);
        wr(&io, c->omega, sizeof c->omega);
        wr(&io, c->pivot0, sizeof c->pivot0);
        wr(&io, c->offset, sizeof c->offset);
        wr(&io, c->R, sizeof c->R);
        WR(&io, has_motion);
        WR(&io, c->temperature);
        WR(&io, c->beta);
        WR(&io, c->saturation);
    }
    const particles *ps = &s->ps;
    int32_t n = ps->n, stride = ps->state_stride;
    uint32_t enabled = ps->enabled;
    WR(&io, n);
    WR(&io, stride);
    WR(&io, enabled);
    for (int c = 0; c < PC_COUNT; c++) {
        if (!(ps->enabled & (1u << c))) continue;
        wr_str(&io, particles_col_name(c));
        if (ps->col[c]) wr(&io, ps->col[c], particles_col_bytes(ps, c) * (size_t)ps->n);
    }
    uint64_t h = hearth_scene_hash(s);
    WR(&io, h);
    if (io.bad) {
        atomic_abort(&af);
        return err_set(err, HEARTH_ERR_IO, "%s: write failed", path);
    }
    return atomic_commit(&af, err);
}

static hearth_scene *load_fail(hearth_scene *s, FILE *f, hearth_error *err, const char *path, const char *what) {
    if (err && err->code == HEARTH_OK) err_set(err, HEARTH_ERR_FORMAT, "%s: not a valid hearth checkpoint: %s", path, what);
    hearth_scene_destroy(s);
    if (f) fclose(f);
    return NULL;
}

hearth_scene *hearth_scene_load(const char *path, hearth_error *err) {
    err_clear(err);
    FILE *f = fopen(path, "rb");
    if (!f) {
        err_set(err, HEARTH_ERR_IO, "%s: cannot open checkpoint", path);
        return NULL;
    }
    ck_io io = {f, 0};
    char magic[8];
    uint32_t hdr[3];
    rd(&io, magic, 8);
    rd(&io, hdr, sizeof hdr);
    if (io.bad || memcmp(magic, CK_MAGIC, 8) != 0) return load_fail(NULL, f, err, path, "bad magic");
    if (hdr[1] != 0x01020304u || hdr[2] != sizeof(double))
        return load_fail(NULL, f, err, path, "written on a machine with another byte order or double size");
    if (hdr[0] != CK_VERSION) {
        err_set(err, HEARTH_ERR_FORMAT, "%s: checkpoint version %u; this hearth reads version %u", path, hdr[0], CK_VERSION);
        return load_fail(NULL, f, err, path, "");
    }
    hearth_scene_def d;
    memset(&d, 0, sizeof d);
    io_def(&io, &d, 0);
    if (io.bad) return load_fail(NULL, f, err, path, "truncated header");
    hearth_scene *s = hearth_scene_create(&d, err);
    if (!s) return load_fail(NULL, f, NULL, path, "");
    hearth_scene clocks;
    memset(&clocks, 0, sizeof clocks);
    io_clocks(&io, &clocks, 0);
    int32_t nmat = 0;
    RD(&io, nmat);
    if (io.bad || nmat < 0 || nmat > 4096) return load_fail(s, f, err, path, "bad material count");
    for (int i = 0; i < nmat; i++) {
        char file[4096], name[256];
        int32_t np = 0;
        rd_str(&io, file, sizeof file);
        rd_str(&io, name, sizeof name);
        RD(&io, np);
        if (io.bad || np < 0 || np > 1024) return load_fail(s, f, err, path, "bad material record");
        double vals[1024 + CP_COUNT];
        rd(&io, vals, sizeof(double) * (size_t)np);
        rd(&io, vals + np, sizeof(double) * CP_COUNT);
        if (io.bad) return load_fail(s, f, err, path, "truncated material record");
        /* the plugin by its saved path first, then by name on the search path */
        hearth_error e2;
        const hearth_plugin *pl = hearth_plugin_load(file, &e2);
        const char *which = pl ? file : name;
        const hearth_material *m = pl ? hearth_plugin_material(pl) : NULL;
        if (!m) {
            pl = hearth_plugin_load(name, err);
            if (!pl) return load_fail(s, f, err, path, "");
            m = hearth_plugin_material(pl);
        }
        if (m->nparams != np) {
            err_set(err, HEARTH_ERR_FORMAT, "%s: material '%s' was saved with %d parameters; the plugin now has %d", path, name, np,
                    m->nparams);
            return load_fail(s, f, err, path, "");
        }
        const char *names[1024 + CP_COUNT];
        for (int k = 0; k < np; k++) names[k] = m->params[k].name;
        const hearth_param *cp = hearth_core_params(NULL);
        for (int k = 0; k < CP_COUNT; k++) names[np + k] = cp[k].name;
        const int mat = hearth_scene_add_material(s, which, names, vals, np + CP_COUNT, err);
        if (mat < 0) return load_fail(s, f, err, path, "");
        int32_t nc = 0;
        RD(&io, nc);
        if (io.bad || nc < 0 || nc > np) return load_fail(s, f, err, path, "bad curve count");
        for (int k = 0; k < nc; k++) {
            int32_t h3[3] = {0, 0, 0};
            rd(&io, h3, sizeof h3);
            if (io.bad || h3[0] < 0 || h3[0] >= np || h3[1] < 1 || h3[1] > 10000) return load_fail(s, f, err, path, "bad curve");
            const size_t bytes = sizeof(double) * (size_t)h3[1];
            double *T = mem_alloc(bytes), *v = mem_alloc(bytes);
            if (T && v) {
                rd(&io, T, bytes);
                rd(&io, v, bytes);
            }
            int bad = !T || !v || io.bad || hearth_scene_material_curve(s, mat, m->params[h3[0]].name, h3[1], T, v, h3[2], err);
            mem_free(T, bytes);
            mem_free(v, bytes);
            if (bad) return load_fail(s, f, err, path, "bad curve");
        }
    }
    int32_t ncol = 0;
    RD(&io, ncol);
    if (io.bad || ncol < 0 || ncol > 4096) return load_fail(s, f, err, path, "bad collider count");
    for (int i = 0; i < ncol; i++) {
        hearth_shape *sh = shape_read(f, 0);
        if (!sh) return load_fail(s, f, err, path, "bad collider shape");
        collider c;
        int32_t mode = 0, has_motion = 0;
        RD(&io, mode);
        RD(&io, c.friction);
        rd(&io, c.vel, sizeof c.vel);
        rd(&io, c.omega, sizeof c.omega);
        rd(&io, c.pivot0, sizeof c.pivot0);
        rd(&io, c.offset, sizeof c.offset);
        rd(&io, c.R, sizeof c.R);
        RD(&io, has_motion);
        RD(&io, c.temperature);
        RD(&io, c.beta);
        RD(&io, c.saturation);
        hearth_collider_def cd = hearth_default_collider_def();
        cd.shape = sh;
        cd.mode = (hearth_contact)mode;
        cd.friction = c.friction;
        memcpy(cd.velocity, c.vel, sizeof c.vel);
        memcpy(cd.omega, c.omega, sizeof c.omega);
        memcpy(cd.pivot, c.pivot0, sizeof c.pivot0);
        cd.temperature = c.temperature;
        cd.beta = c.beta;
        cd.saturation = c.saturation;
        int id = io.bad ? -1 : hearth_scene_add_collider(s, &cd, err);
        hearth_shape_free(sh);
        if (id < 0) return load_fail(s, f, err, path, "bad collider record");
        memcpy(s->cols[id].offset, c.offset, sizeof c.offset);
        memcpy(s->cols[id].R, c.R, sizeof c.R);
    }
    int32_t n = 0, stride = 0;
    uint32_t enabled = 0;
    RD(&io, n);
    RD(&io, stride);
    RD(&io, enabled);
    if (io.bad || n < 0 || stride < 0 || stride > 4096 || (enabled & ((1u << PC_NCORE) - 1)) != (1u << PC_NCORE) - 1 ||
        enabled >= (1u << PC_COUNT))
        return load_fail(s, f, err, path, "bad particle header");
    particles *ps = &s->ps;
    if (particles_set_state_stride(ps, stride, err)) return load_fail(s, f, err, path, "");
    for (int c = PC_NCORE; c < PC_COUNT; c++)
        if ((enabled & (1u << c)) && particles_enable(ps, c, err)) return load_fail(s, f, err, path, "");
    if (n && particles_reserve(ps, n, err)) return load_fail(s, f, err, path, "");
    for (int c = 0; c < PC_COUNT; c++) {
        if (!(enabled & (1u << c))) continue;
        char name[64];
        rd_str(&io, name, sizeof name);
        if (io.bad || strcmp(name, particles_col_name(c)) != 0) return load_fail(s, f, err, path, "particle columns out of order");
        if (ps->col[c]) rd(&io, ps->col[c], particles_col_bytes(ps, c) * (size_t)n);
    }
    ps->n = n;
    uint64_t h = 0;
    RD(&io, h);
    if (io.bad) return load_fail(s, f, err, path, "truncated particle data");
    if (h != hearth_scene_hash(s)) return load_fail(s, f, err, path, "particle data checksum mismatch (file damaged)");
    for (int i = 0; i < n; i++) {
        int m = pcoli(ps, PC_MAT)[i];
        if (m < 0 || m >= s->nmat) return load_fail(s, f, err, path, "particle with an unknown material");
    }
    fclose(f);
    /* clocks last: adding materials and particles above touched them */
    s->t = clocks.t;
    s->dt_last = clocks.dt_last;
    s->dt_scale = clocks.dt_scale;
    s->step = clocks.step;
    s->rollbacks = clocks.rollbacks;
    s->max_speed = clocks.max_speed;
    s->c_max = clocks.c_max;
    s->kinetic = clocks.kinetic;
    s->kinetic_peak = clocks.kinetic_peak;
    s->cfl_last = clocks.cfl_last;
    s->out_of_domain = clocks.out_of_domain;
    s->guard = clocks.guard;
    s->rng = clocks.rng;
    s->next_id = clocks.next_id;
    s->nbodies = clocks.nbodies;
    s->water_lost = clocks.water_lost;
    return s;
}
