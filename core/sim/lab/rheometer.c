/* rheometer.c: the homogeneous virtual rheometer, flow-curve CSV reading and
 * the Herschel-Bulkley fit of Nagasawa et al. 2019 (eq. 1, 2). */
#include "plugins.h"
#include "hearth/lab.h"

#include "csv.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "material.h"
#include "tensor.h"

hearth_rheometer_opts hearth_rheometer_default_opts(void) {
    hearth_rheometer_opts o = {.dt = 0, .rel_tol = 1e-6, .window = 64, .max_strain = 1e7, .max_steps = 4000000};
    return o;
}

double hearth_hb_stress(double sigma_y, double eta, double h, double rate) { return sigma_y + eta * pow(rate, h); }

void hearth_log_spaced(double lo, double hi, int n, double *rates) {
    if (n <= 0) return;
    rates[0] = lo;
    if (n == 1) return;
    double a = log(lo), b = log(hi);
    for (int i = 1; i < n - 1; i++) rates[i] = exp(a + (b - a) * i / (n - 1));
    rates[n - 1] = hi;
}

/* ---- the driver ------------------------------------------------------------- */

typedef struct rig {
    const hearth_material *m;
    const double *p;
    double *state;
    size_t sbytes;
    int density;   /* index of "density", -1 when absent */
    double F[9];
    double rate;
    long steps;
    double strain, time;
} rig;

static hearth_status rig_open(rig *g, const hearth_material *m, const double *p, double rate, hearth_error *err) {
    memset(g, 0, sizeof *g);
    if (!m || !p) return err_set(err, HEARTH_ERR_PARAM, "no material or parameters given");
    if (!(rate > 0) || !isfinite(rate))
        return err_set(err, HEARTH_ERR_PARAM, "shear rate must be finite and > 0 1/s, got %g", rate);
    g->m = m;
    g->p = p;
    g->rate = rate;
    g->density = -1;
    for (int i = 0; i < m->nparams; i++)
        if (m->params[i].name && !strcmp(m->params[i].name, "density")) g->density = i;
    g->sbytes = (size_t)(m->state_size > 0 ? m->state_size : 0) * sizeof(double);
    if (g->sbytes) {
        g->state = mem_alloc(g->sbytes);
        if (!g->state) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the plugin state");
    }
    plugin_call_enter(m, "init");
    m->init(p, g->state);
    plugin_call_leave();
    for (int i = 0; i < 9; i++) g->F[i] = (i % 4 == 0);
    return HEARTH_OK;
}

static void rig_close(rig *g) {
    mem_free(g->state, g->sbytes);
    g->state = NULL;
}

/* One step of simple shear: F <- (I + dt L) F, then the plugin. */
static hearth_status rig_step(rig *g, double dt, double *sigma, hearth_error *err) {
    double L[9] = {0}, f[9], Fn[9];
    L[1] = g->rate;
    for (int i = 0; i < 9; i++) f[i] = (i % 4 == 0) + dt * L[i];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++)
            Fn[3 * r + c] = f[3 * r] * g->F[c] + f[3 * r + 1] * g->F[3 + c] + f[3 * r + 2] * g->F[6 + c];
    memcpy(g->F, Fn, sizeof Fn);
    hearth_point pt;
    memcpy(pt.grad_v, L, sizeof L);
    memcpy(pt.F, g->F, sizeof pt.F);
    pt.dt = dt;
    pt.p = g->p;
    pt.state = g->state;
    const unsigned needs = g->m->needs;
    /* a bench-top rheometer: room temperature, no pores, dry, and none of the
     * core's coupling terms (at 20 degC, dry and without gas they would add
     * only the expansion of a material whose reference is not 20 degC) */
    const material_env env = {
        .temperature = (needs & (HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_THERMAL_EXPANSION)) ? 20.0 : NAN,
        .porosity = (needs & HEARTH_NEEDS_POROSITY) ? 0.0 : NAN,
        .saturation = (needs & HEARTH_NEEDS_SATURATION) ? 0.0 : NAN,
    };
    double tau[9];
    for (int i = 0; i < 9; i++) tau[i] = NAN;
    g->steps++;
    g->strain += g->rate * dt;
    g->time += dt;
    int rc = material_point_eval(g->m, NULL, &pt, &env, tau);
    plugin_call_leave();
    if (rc == MATERIAL_NONFINITE) rc = 0; /* a non-finite tau is caught below, with the shear it came from */
    if (rc) {
        const char *t = g->m->describe_error ? g->m->describe_error(rc) : NULL;
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "material '%s' returned code %d (%s) at step %ld, shear strain %g, rate %g 1/s, dt %g s",
                       g->m->name, rc, t ? t : "no description", g->steps, g->strain, g->rate, dt);
    }
    double J = t3_det(g->F);
    double s = 0.5 * (tau[1] + tau[3]) / J;
    if (!isfinite(s))
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "material '%s' gave a non-finite shear stress at step %ld, shear strain %g, rate %g 1/s, "
                       "dt %g s",
                       g->m->name, g->steps, g->strain, g->rate, dt);
    *sigma = s;
    return HEARTH_OK;
}

/* P-wave modulus rho c^2 from the plugin's wave speed: an upper bound of the
 * shear stiffness, used until the first steps have measured the shear
 * modulus itself. */
static double rig_modulus(const rig *g) {
    plugin_call_enter(g->m, "wave_speed");
    double c = g->m->wave_speed(g->p, g->state);
    plugin_call_leave();
    double rho = g->density >= 0 ? g->p[g->density] : 1000.0;
    double M = rho * c * c;
    return isfinite(M) && M > 0 ? M : 0;
}

static hearth_status check_opts(const hearth_rheometer_opts *o, hearth_error *err) {
    if (!(o->dt >= 0) || !isfinite(o->dt))
        return err_set(err, HEARTH_ERR_PARAM, "dt must be >= 0 s (0 = adaptive), got %g", o->dt);
    if (!(o->rel_tol > 0) || !(o->rel_tol < 1))
        return err_set(err, HEARTH_ERR_PARAM, "rel_tol must be in (0, 1), got %g", o->rel_tol);
    if (o->window < 2) return err_set(err, HEARTH_ERR_PARAM, "window must be >= 2 steps, got %d", o->window);
    if (!(o->max_strain > 0) || o->max_steps < 1)
        return err_set(err, HEARTH_ERR_PARAM, "max_strain and max_steps must be > 0");
    return HEARTH_OK;
}

hearth_status hearth_rheometer_steady(const hearth_material *m, const double *p, double rate,
                                      const hearth_rheometer_opts *o, hearth_rheometer_result *r, hearth_error *err) {
    err_clear(err);
    hearth_rheometer_opts def = hearth_rheometer_default_opts();
    if (!o) o = &def;
    memset(r, 0, sizeof *r);
    hearth_status st = check_opts(o, err);
    if (st) return st;
    rig g;
    if ((st = rig_open(&g, m, p, rate, err))) return st;
    double sigma = 0, ref = NAN, dprev = NAN, G = 0;
    int steady = 0;
    while (!steady) {
        if (g.steps >= o->max_steps || g.strain >= o->max_strain) break;
        double dt = o->dt;
        if (dt == 0) {
            /* Each step shears by 1% of the elastic strain |sigma| / G. G is the
             * largest tangent shear modulus seen so far (the first steps from rest
             * load elastically and measure it); before that, the P-wave modulus
             * from wave_speed bounds it from above. The floor 1e-9 G starts the
             * run from rest; the step then grows 1% per step while loading. */
            double Gu = G > 0 ? G : rig_modulus(&g);
            dt = Gu > 0 ? 0.01 * fmax(fabs(sigma), 1e-9 * Gu) / (Gu * rate) : 0.01 / rate;
        }
        double before = sigma, strain0 = g.strain;
        if ((st = rig_step(&g, dt, &sigma, err))) break;
        double de = g.strain - strain0;
        if (de > 0 && fabs(sigma) > fabs(before)) {
            double t = fabs(sigma - before) / de;
            if (isfinite(t) && t > G) G = t;
        }
        if (g.steps % o->window) continue;
        if (isfinite(ref)) {
            double d = sigma - ref, tol = o->rel_tol * fabs(sigma);
            if (d == 0 || fabs(d) <= 1e-13 * fabs(sigma)) steady = 1; /* at the rounding floor */
            else if (fabs(d) <= tol && isfinite(dprev) && dprev != 0) {
                /* windows shrink the remaining drift by rho each: what is left is d rho / (1 - rho) */
                double rho = d / dprev;
                double rest = rho <= 0 ? fabs(d) : rho < 1 ? fabs(d) * rho / (1 - rho) : INFINITY;
                if (rest <= tol) steady = 1;
            }
            dprev = d;
        }
        ref = sigma;
    }
    r->stress = sigma;
    r->strain = g.strain;
    r->time = g.time;
    r->steps = g.steps;
    r->steady = steady;
    rig_close(&g);
    if (st) return st;
    if (!steady)
        return err_set(err, HEARTH_ERR_STATE,
                       "material '%s' did not reach a steady shear stress at rate %g 1/s within %ld steps "
                       "(shear strain %g; last sigma_xy = %g Pa); a solid has no flow curve",
                       m->name, rate, r->steps, r->strain, sigma);
    return HEARTH_OK;
}

hearth_status hearth_rheometer_startup(const hearth_material *m, const double *p, double rate, double dt, int n,
                                       double *sigma, hearth_error *err) {
    err_clear(err);
    if (!(dt > 0) || !isfinite(dt)) return err_set(err, HEARTH_ERR_PARAM, "start-up needs dt > 0 s, got %g", dt);
    if (n < 1) return err_set(err, HEARTH_ERR_PARAM, "start-up needs at least 1 step, got %d", n);
    rig g;
    hearth_status st = rig_open(&g, m, p, rate, err);
    if (st) return st;
    for (int i = 0; i < n && !st; i++) st = rig_step(&g, dt, &sigma[i], err);
    rig_close(&g);
    return st;
}

hearth_status hearth_rheometer_flow_curve(const hearth_material *m, const double *p, const double *rates, int n,
                                          const hearth_rheometer_opts *o, double *stress, hearth_error *err) {
    err_clear(err);
    for (int i = 0; i < n; i++) {
        hearth_rheometer_result r;
        hearth_status st = hearth_rheometer_steady(m, p, rates[i], o, &r, err);
        stress[i] = r.stress;
        if (st) return st;
    }
    return HEARTH_OK;
}

/* ---- flow-curve CSV ----------------------------------------------------- */

void hearth_flow_curve_free(hearth_flow_curve *c) {
    if (!c) return;
    size_t bytes = sizeof(double) * (size_t)(c->n > 0 ? c->n : 0);
    mem_free(c->rate, bytes);
    mem_free(c->stress, bytes);
    memset(c, 0, sizeof *c);
}



#define CSV_MAX_CELLS 64
#define CSV_LINE 4096
/* A rheometer gives tens of points; the cap keeps the doubling of cap and
 * the byte counts far from int overflow, and a runaway file from memory. */
#define CURVE_MAX_ROWS 1000000

hearth_status hearth_flow_curve_read(const char *path, hearth_flow_curve *c, hearth_error *err) {
    err_clear(err);
    memset(c, 0, sizeof *c);
    FILE *f = fopen(path, "r");
    if (!f) return err_set(err, HEARTH_ERR_IO, "%s: cannot open: %s", path, strerror(errno));
    char line[CSV_LINE];
    char *cells[CSV_MAX_CELLS];
    int lineno = 0, col_rate = -1, col_stress = -1, header_line = 0, rows = 0, cap = 0;
    hearth_status st = HEARTH_OK;
    double *xy = NULL; /* rate, stress pairs */
    for (;;) {
        csv_line got = csv_read_line(f, line, sizeof line);
        if (got == CSV_LINE_EOF || got == CSV_LINE_IO) break; /* IO: ferror below names it */
        if (lineno == INT_MAX) { /* lineno++ must not overflow: only a file of >2^31 blank lines gets here */
            st = err_set(err, HEARTH_ERR_FORMAT, "%s: more than %d lines", path, INT_MAX);
            break;
        }
        lineno++;
        if (got == CSV_LINE_TOO_LONG) {
            st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d is longer than %d characters", path, lineno, CSV_LINE - 1);
            break;
        }
        if (got == CSV_LINE_NUL) {
            st = err_set(err, HEARTH_ERR_FORMAT,
                         "%s: line %d holds a NUL byte: this is not a text CSV file (saved as UTF-16? save it as UTF-8)",
                         path, lineno);
            break;
        }
        size_t len = strlen(line);
        if (lineno == 1 && len >= 3 && (unsigned char)line[0] == 0xEF && (unsigned char)line[1] == 0xBB &&
            (unsigned char)line[2] == 0xBF)
            memmove(line, line + 3, len - 2); /* UTF-8 byte order mark */
        char *t = csv_trim(line);
        if (!*t || *t == '#') continue;
        int nc = csv_split(t, cells, CSV_MAX_CELLS);
        if (!header_line) {
            header_line = lineno;
            for (int i = 0; i < nc; i++) {
                /* the names with their units, as `hearth rheometer` writes them (#18, helper userfix7), or the
                 * bare names it wrote before and a hand-made file may use */
                if ((!strcmp(cells[i], "shear_rate_1_per_s") || !strcmp(cells[i], "shear_rate")) && col_rate < 0)
                    col_rate = i;
                if ((!strcmp(cells[i], "stress_Pa") || !strcmp(cells[i], "stress")) && col_stress < 0) col_stress = i;
            }
            if (col_rate < 0 || col_stress < 0) {
                st = err_set(err, HEARTH_ERR_FORMAT,
                             "%s: line %d (header row): the header must name the columns 'shear_rate_1_per_s' (or "
                             "'shear_rate', 1/s) and 'stress_Pa' (or 'stress', Pa); %s missing (first cell '%s')",
                             path, lineno,
                             col_rate < 0 && col_stress < 0 ? "both are" : col_rate < 0 ? "'shear_rate' is" : "'stress' is",
                             nc > 0 ? cells[0] : "");
                break;
            }
            continue;
        }
        int row = rows + 1;
        int need = (col_rate > col_stress ? col_rate : col_stress) + 1;
        if (nc < need) {
            st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d (data row %d): %d cell%s, but the %s column is number %d",
                         path, lineno, row, nc, nc == 1 ? "" : "s", col_rate >= nc ? "shear_rate" : "stress", need);
            break;
        }
        double v[2];
        const int cols[2] = {col_rate, col_stress};
        const char *names[2] = {"shear_rate", "stress"};
        for (int k = 0; k < 2 && !st; k++) {
            const char *cell = cells[cols[k]];
            char *end = NULL;
            v[k] = strtod(cell, &end);
            if (!*cell || end == cell || *end || !isfinite(v[k]))
                st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d (data row %d): %s '%s' is not a finite number", path,
                             lineno, row, names[k], cell);
            else if (!(v[k] > 0))
                st = err_set(err, HEARTH_ERR_FORMAT,
                             "%s: line %d (data row %d): %s %g must be > 0 (the fit uses relative residuals and the "
                             "plot log-log axes)",
                             path, lineno, row, names[k], v[k]);
        }
        if (st) break;
        if (rows == CURVE_MAX_ROWS) {
            st = err_set(err, HEARTH_ERR_FORMAT,
                         "%s: line %d: more than %d data rows; a measured flow curve has tens (thin the data first)", path,
                         lineno, CURVE_MAX_ROWS);
            break;
        }
        if (rows == cap) {
            int ncap = cap ? 2 * cap : 64;
            double *nxy = mem_realloc(xy, sizeof(double) * 2 * (size_t)cap, sizeof(double) * 2 * (size_t)ncap);
            if (!nxy) {
                st = err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory at line %d", path, lineno);
                break;
            }
            xy = nxy;
            cap = ncap;
        }
        xy[2 * rows] = v[0];
        xy[2 * rows + 1] = v[1];
        rows++;
    }
    if (!st && ferror(f)) st = err_set(err, HEARTH_ERR_IO, "%s: read error after line %d", path, lineno);
    fclose(f);
    if (!st && !header_line)
        st = err_set(err, HEARTH_ERR_FORMAT, "%s: empty file: expected a header row naming 'shear_rate' and 'stress'", path);
    else if (!st && rows < 3)
        st = err_set(err, HEARTH_ERR_FORMAT,
                     "%s: only %d data row%s after the header (line %d): fitting sigma_y, eta and h needs at least 3",
                     path, rows, rows == 1 ? "" : "s", header_line);
    if (!st) {
        c->rate = mem_alloc(sizeof(double) * (size_t)rows);
        c->stress = mem_alloc(sizeof(double) * (size_t)rows);
        if (!c->rate || !c->stress) {
            mem_free(c->rate, sizeof(double) * (size_t)rows);
            mem_free(c->stress, sizeof(double) * (size_t)rows);
            c->rate = c->stress = NULL;
            st = err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory", path);
        } else {
            c->n = rows;
            for (int i = 0; i < rows; i++) c->rate[i] = xy[2 * i], c->stress[i] = xy[2 * i + 1];
        }
    }
    mem_free(xy, sizeof(double) * 2 * (size_t)cap);
    return st;
}

/* ---- the fit (eq. 2) -------------------------------------------------------- */

typedef struct fit_data {
    const double *x, *y; /* rate, stress */
    int n;
} fit_data;

static double fit_objective(const fit_data *d, double sy, double eta, double h) {
    double s = 0;
    for (int i = 0; i < d->n; i++) {
        double r = (sy + eta * pow(d->x[i], h) - d->y[i]) / d->y[i];
        s += r * r;
    }
    return s;
}

/* For fixed h: minimise sum ((sy + eta x_i^h) / y_i - 1)^2 over sy >= 0,
 * eta >= 0. Unconstrained normal equations of the columns a_i = 1/y_i and
 * b_i = x_i^h / y_i; when that optimum leaves the feasible quadrant the
 * optimum lies on an edge (two-variable NNLS), so both edges are tried. */
static double fit_profile(const fit_data *d, double h, double *sy_out, double *eta_out) {
    double aa = 0, ab = 0, bb = 0, a1 = 0, b1 = 0;
    for (int i = 0; i < d->n; i++) {
        double a = 1 / d->y[i], b = pow(d->x[i], h) / d->y[i];
        aa += a * a, ab += a * b, bb += b * b, a1 += a, b1 += b;
    }
    double best = INFINITY, bsy = 0, beta = 0;
    double det = aa * bb - ab * ab;
    if (det > 1e-14 * aa * bb) {
        double sy = (a1 * bb - b1 * ab) / det, eta = (aa * b1 - ab * a1) / det;
        if (sy >= 0 && eta >= 0) {
            best = fit_objective(d, sy, eta, h);
            bsy = sy, beta = eta;
        }
    }
    if (!isfinite(best)) {
        double eta = bb > 0 ? fmax(b1 / bb, 0) : 0; /* sy = 0 */
        double o1 = fit_objective(d, 0, eta, h);
        double sy = aa > 0 ? fmax(a1 / aa, 0) : 0; /* eta = 0 */
        double o2 = fit_objective(d, sy, 0, h);
        if (o1 <= o2) best = o1, bsy = 0, beta = eta;
        else best = o2, bsy = sy, beta = 0;
    }
    *sy_out = bsy;
    *eta_out = beta;
    return best;
}

hearth_status hearth_hb_fit(const double *rate, const double *stress, int n, hearth_hb_fit_result *out,
                            hearth_error *err) {
    err_clear(err);
    memset(out, 0, sizeof *out);
    if (n < 3) return err_set(err, HEARTH_ERR_PARAM, "fit: %d points; fitting sigma_y, eta and h needs at least 3", n);
    for (int i = 0; i < n; i++)
        if (!(rate[i] > 0) || !(stress[i] > 0) || !isfinite(rate[i]) || !isfinite(stress[i]))
            return err_set(err, HEARTH_ERR_PARAM, "fit: point %d (rate %g, stress %g): both must be finite and > 0", i + 1,
                           rate[i], stress[i]);
    fit_data d = {rate, stress, n};
    /* scan h on a fine grid (the profile can have more than one dip), then golden-section the best bracket */
    enum { NSCAN = 300 };
    const double hlo = 0.02, hhi = 3.0;
    double bestv = INFINITY, sy, eta;
    int bi = 0;
    double hs[NSCAN];
    for (int k = 0; k < NSCAN; k++) {
        hs[k] = hlo * pow(hhi / hlo, (double)k / (NSCAN - 1));
        double v = fit_profile(&d, hs[k], &sy, &eta);
        if (v < bestv) bestv = v, bi = k;
    }
    double a = hs[bi > 0 ? bi - 1 : 0], b = hs[bi < NSCAN - 1 ? bi + 1 : NSCAN - 1];
    const double gr = 0.61803398874989484820;
    double c1 = b - gr * (b - a), c2 = a + gr * (b - a);
    double f1 = fit_profile(&d, c1, &sy, &eta), f2 = fit_profile(&d, c2, &sy, &eta);
    for (int it = 0; it < 200 && b - a > 1e-13 * b; it++) {
        if (f1 <= f2) {
            b = c2, c2 = c1, f2 = f1;
            c1 = b - gr * (b - a);
            f1 = fit_profile(&d, c1, &sy, &eta);
        } else {
            a = c1, c1 = c2, f1 = f2;
            c2 = a + gr * (b - a);
            f2 = fit_profile(&d, c2, &sy, &eta);
        }
    }
    double h = f1 <= f2 ? c1 : c2;
    double v = fit_profile(&d, h, &sy, &eta);
    if (!(v <= bestv)) { /* the grid point itself was better (flat profile) */
        h = hs[bi];
        v = fit_profile(&d, h, &sy, &eta);
    }
    if (!isfinite(v)) return err_set(err, HEARTH_ERR_PARAM, "fit: the objective is not finite; check the data");
    out->sigma_y = sy;
    out->eta = eta;
    out->h = h;
    out->objective = v;
    out->rel_error = sqrt(v / n);
    return HEARTH_OK;
}
