/* rheometer_mpm.c: the virtual rheometer's second mode, the real MPM solver
 * between moving plates (<hearth/lab.h>). It uses only the public scene API, so
 * it measures exactly what a scene would simulate: the transfers, the grid,
 * the colliders and the plugin together.
 *
 * Why a plane layer and not a cone-and-plate: in 2D plane strain, a layer
 * between parallel plates is in homogeneous simple shear, the flow the
 * paper's cone geometry is built to produce (Nagasawa et al. 2019, section 3:
 * "a constant shear rate"), with no curvature to correct for. The layer is
 * finite in x and ends at slip walls, where the flow turns; the measurement
 * uses the middle half only. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "hearth/lab.h"

hearth_rheometer_mpm_opts hearth_rheometer_mpm_default_opts(void) {
    return (hearth_rheometer_mpm_opts){.gap = 0.01, .cells = 16, .length = 4, .ppc = 4, .rel_tol = 2e-4, .max_time = 1};
}

/* The measurement over the middle half of the layer: mean sigma_xy, and the
 * least-squares slope of v_x against y over the inner 80% of the gap. */
static hearth_status measure(hearth_scene *s, double x0, double x1, double y0, double y1, double *buf, double *stress,
                             double *rate, hearth_error *err) {
    const int n = hearth_scene_particle_count(s);
    const double *X = hearth_scene_positions(s);
    if (hearth_scene_particle_field(s, "stress_xy", buf, err)) return err->code;
    double sum = 0;
    int cnt = 0;
    for (int i = 0; i < n; i++)
        if (X[3 * i] >= x0 && X[3 * i] <= x1) sum += buf[i], cnt++;
    if (hearth_scene_particle_field(s, "velocity_x", buf, err)) return err->code;
    const double ya = y0 + 0.1 * (y1 - y0), yb = y1 - 0.1 * (y1 - y0);
    double sy = 0, sv = 0, syy = 0, syv = 0;
    int m = 0;
    for (int i = 0; i < n; i++) {
        const double x = X[3 * i], y = X[3 * i + 1];
        if (x < x0 || x > x1 || y < ya || y > yb) continue;
        sy += y, sv += buf[i], syy += y * y, syv += y * buf[i], m++;
    }
    if (cnt == 0 || m < 2) return err_set(err, HEARTH_ERR_STATE, "rheometer (mpm): no particles left in the measuring window");
    *stress = sum / cnt;
    *rate = (m * syv - sy * sv) / (m * syy - sy * sy);
    return HEARTH_OK;
}

hearth_status hearth_rheometer_mpm_steady(const char *plugin, const double *p, double rate,
                                          const hearth_rheometer_mpm_opts *o, hearth_rheometer_mpm_result *r,
                                          hearth_error *err) {
    hearth_error local;
    if (!err) err = &local;
    err_clear(err);
    hearth_rheometer_mpm_opts opt = o ? *o : hearth_rheometer_mpm_default_opts();
    memset(r, 0, sizeof *r);
    if (!(rate > 0) || !isfinite(rate))
        return err_set(err, HEARTH_ERR_PARAM, "rheometer (mpm): shear rate must be finite and > 0 1/s, got %g", rate);
    if (!(opt.gap > 0) || !isfinite(opt.gap) || opt.cells < 4 || opt.cells > 1024 || !(opt.length >= 1 && opt.length <= 64) ||
        opt.ppc < 1 || opt.ppc > 64 || !(opt.rel_tol > 0) || !(opt.max_time > 0))
        return err_set(err, HEARTH_ERR_PARAM,
                       "rheometer (mpm): options out of range (gap > 0 m, cells 4..1024, length 1..64 gaps, ppc 1..64, "
                       "rel_tol > 0, max_time > 0 s)");
    const hearth_plugin *pl = hearth_plugin_load(plugin, err);
    if (!pl) return err->code;
    const hearth_material *m = hearth_plugin_material(pl);
    enum { NP = 64 };
    if (m->nparams > NP) return err_set(err, HEARTH_ERR_PLUGIN, "rheometer (mpm): plugin '%s' has more than %d parameters", m->name, NP);
    const char *names[NP];
    for (int i = 0; i < m->nparams; i++) names[i] = m->params[i].name;

    const double H = opt.gap, dx = H / opt.cells, pad = 4 * dx, Lx = opt.length * H + 6 * dx;
    const double V = 0.5 * rate * H;
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 2;
    d.dx = dx;
    d.hi[0] = Lx;
    d.hi[1] = H + 2 * pad;
    d.gravity[1] = 0;
    d.wall = HEARTH_SLIP;
    hearth_scene *s = hearth_scene_create(&d, err);
    if (!s) return err->code;
    hearth_status st = HEARTH_OK;
    double *x = NULL, *v = NULL, *buf = NULL;
    hearth_shape *bottom = NULL, *top = NULL;
    size_t nbytes = 0;
    int mat = hearth_scene_add_material(s, plugin, names, p, m->nparams, err);
    if (mat < 0) goto fail;
    /* the layer: a k x k lattice per cell, moving with the simple-shear profile */
    const int k = (int)fmax(1, floor(sqrt((double)opt.ppc) + 0.5));
    const double hp = dx / k, xa = 3 * dx, xb = Lx - 3 * dx, y0 = pad, y1 = pad + H;
    const int nx = (int)lround((xb - xa) / hp), ny = opt.cells * k, n = nx * ny;
    nbytes = sizeof(double) * 3 * (size_t)n;
    x = mem_alloc(nbytes);
    v = mem_alloc(nbytes);
    buf = mem_alloc(nbytes);
    if (!x || !v || !buf) {
        st = err_set(err, HEARTH_ERR_NOMEM, "rheometer (mpm): out of memory for %d particles", n);
        goto fail;
    }
    for (int j = 0; j < ny; j++)
        for (int i = 0; i < nx; i++) {
            double *xp = x + 3 * ((size_t)j * nx + i), *vp = v + 3 * ((size_t)j * nx + i);
            xp[0] = xa + (i + 0.5) * hp;
            xp[1] = y0 + (j + 0.5) * hp;
            xp[2] = vp[1] = vp[2] = 0;
            vp[0] = rate * (xp[1] - 0.5 * (y0 + y1));
        }
    if (hearth_scene_add_particles(s, mat, n, x, v, hp * hp, err) < 0) goto fail;
    /* the plates: sticky half-spaces whose faces are the layer's faces, far longer than the domain */
    const double ctr_b[3] = {0.5 * Lx, y0 - 0.5, 0}, ctr_t[3] = {0.5 * Lx, y1 + 0.5, 0}, half[3] = {10 * Lx + 1, 0.5, 0.5};
    bottom = hearth_shape_box(ctr_b, half);
    top = hearth_shape_box(ctr_t, half);
    if (!bottom || !top) {
        st = err_set(err, HEARTH_ERR_NOMEM, "rheometer (mpm): out of memory for the plates");
        goto fail;
    }
    hearth_collider_def cb = hearth_default_collider_def(), ct = hearth_default_collider_def();
    cb.shape = bottom, ct.shape = top;
    cb.mode = ct.mode = HEARTH_STICKY;
    cb.velocity[0] = -V, ct.velocity[0] = V;
    if (hearth_scene_add_collider(s, &cb, err) < 0 || hearth_scene_add_collider(s, &ct, err) < 0) goto fail;

    /* run in windows of 25 steps; steady when three windows in a row change
     * the mean stress by less than rel_tol (relative) */
    const double mx0 = xa + 0.25 * (xb - xa), mx1 = xa + 0.75 * (xb - xa);
    double prev = NAN, sig = 0, g = 0;
    int calm = 0;
    hearth_stats stt;
    for (;;) {
        if ((st = hearth_scene_step(s, 25, err))) goto fail;
        if ((st = measure(s, mx0, mx1, y0, y1, buf, &sig, &g, err))) goto fail;
        hearth_scene_stats(s, &stt);
        if (!isfinite(sig)) {
            st = err_set(err, HEARTH_ERR_PLUGIN, "rheometer (mpm): the shear stress is not finite at t = %g s", stt.t);
            goto fail;
        }
        calm = isfinite(prev) && fabs(sig - prev) <= opt.rel_tol * fabs(sig) ? calm + 1 : 0;
        prev = sig;
        if (calm >= 3) {
            r->steady = 1;
            break;
        }
        if (stt.t >= opt.max_time) break;
    }
    r->stress = sig;
    r->rate = g;
    r->plate_speed = V;
    r->time = stt.t;
    r->steps = stt.step;
    r->particles = n;
    if (!r->steady)
        st = err_set(err, HEARTH_ERR_STATE,
                     "rheometer (mpm): no steady stress at rate %g 1/s within %g s (last %g Pa, still changing)", rate,
                     opt.max_time, sig);
fail:
    if (!st && err->code) st = err->code;
    hearth_shape_free(bottom);
    hearth_shape_free(top);
    mem_free(x, nbytes);
    mem_free(v, nbytes);
    mem_free(buf, nbytes);
    hearth_scene_destroy(s);
    return st;
}
