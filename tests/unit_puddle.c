/* unit_puddle.c: does an MPM yield-stress layer come to rest as the closed form's puddle?
 *
 * The closed form. A perfectly plastic (or Bingham) layer spreading slowly on a no-slip plane stops where the
 * floor's shear stress rho g h |h'| has fallen to the yield stress in shear tau_y everywhere (the shallow-layer
 * balance, h << L): h h' = -tau_y / (rho g), so the pile at rest has the critical profile
 *   h(x)^2 = 2 tau_y (L - |x|) / (rho g)
 * (Nye 1951 for an ice sheet; Liu & Mei 1989 for a Bingham mud; Balmforth et al. 2006 as the final state of a slow
 * viscoplastic dam break). Its area (plane strain, per metre) is A = (4/3) h0 L with
 * h0^2 = 2 tau_y L / (rho g), so A alone gives
 *   h0 = (3 A tau_y / (2 rho g))^(1/3),   L = rho g h0^2 / (2 tau_y).
 * tau_y is the yield stress in simple shear: the von Mises sauce's sigma_y (plugins/von_mises_sauce.c maps it onto
 * the tensorial yield with the von Mises factor, q = sqrt(3) tau_y).
 *
 * The MPM side: a rectangle of hot chilli sauce (Nagasawa et al. 2019, Table 1, Hc: sigma_y 8.11 Pa, eta 2.85
 * Pa s^h, h 0.456; assets/sauces.csv) released on a sticky floor (a box collider whose face lies on a node row),
 * 2D plane strain, rho 1000, g 9.81. Its area, 36 x 30 mm, gives h0 = 11.0 mm and L = 73.5 mm (h0 / L = 0.15;
 * the pile spans 74 cells at the coarse dx of 2 mm, 5.5 cells deep). See puddle() for the moduli and the damping.
 *
 * Bars, set before the first run (18:25 UTC, 7 Dec 2026, helper puddle): at dx = 1 mm the rest height at the middle
 * h0 and the half-width L each within 10% of the closed form; and h0's error smaller at 1 mm than at 2 mm.
 * Diagnostics: PUDDLE_DX=d runs one puddle at dx d (m), no verdict (PUDDLE_FLOOR_FRICTION=mu: on a slip floor of
 * Coulomb mu); PUDDLE_TRACE=1 prints the spread every 0.5 s; PUDDLE_DUMP=file writes the particles at rest;
 * PUDDLE_REST=f the rest criterion's growth per second as a fraction of L (1e-3; 0 runs to the longest run);
 * PUDDLE_DOUGH=flow|off puts the melted cookie dough (cam_clay_dough, with or without its flow_stress; dough_law
 * below) in the sauce's place, PUDDLE_TMAX=s the longest run (its viscosity is 1e3-1e4 times the sauce's, so
 * it creeps for minutes: what it prints then is the state at that time; docs/validation.md, #18 helper puddle2).
 * PUDDLE_SNAP, PUDDLE_PPC, PUDDLE_SHIFT, PUDDLE_W, PUDDLE_PIC, PUDDLE_DAMPING, PUDDLE_JITTER: the slit on the
 * symmetry line (below; #18 helper puddleslit), and the two sauce_spread_neighbours_follow_F cases, the pile at
 * 4 mm for 2 s: do neighbouring particles part as their F says? */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hearth/lab.h"
#include "mpm_fixture.h"

typedef struct puddle_result {
    double h0, L;       /* measured: rest height at the middle, half-width (m) */
    double h0_cf, L_cf; /* the closed form from the seeded area */
    double crest, tau_eff, front, Hc; /* diagnostics: see puddle() */
    double gapF, gapF_x, gapF_y;      /* neighbours against F: the largest |gap / (h |F e_x|) - 1|, and where (m) */
    double mid_gap;                   /* the widest gap of a pair straddling the symmetry line, in cells (0: none) */
    double t_rest, vmax;
    long steps;
    int n, ok;
} puddle_result;

static int load_sauce(const char *name, hearth_sauce *out) {
    const char *root = getenv("HEARTH_SOURCE_ROOT");
    char path[4096];
    snprintf(path, sizeof path, "%s/assets/sauces.csv", root && *root ? root : ".");
    hearth_sauce_library lib;
    hearth_error err;
    if (hearth_sauce_library_load(path, &lib, &err)) {
        fprintf(stderr, "library: %s\n", err.msg);
        return 0;
    }
    const hearth_sauce *s = hearth_sauce_find(&lib, name);
    if (s) *out = *s;
    hearth_sauce_library_free(&lib);
    return s != NULL;
}

/* Half the span of the particles, each standing for the sqrt(vol) square around it. */
static double half_width(const hearth_scene *s) {
    const double *X = pcold(&s->ps, PC_X), *V0 = pcold(&s->ps, PC_VOL0);
    double xl = 1e300, xr = -1e300;
    for (int i = 0; i < s->ps.n; i++) {
        const double half = 0.5 * sqrt(V0[i]);
        xl = fmin(xl, X[3 * i] - half), xr = fmax(xr, X[3 * i] + half);
    }
    return 0.5 * (xr - xl);
}

static double max_speed(const hearth_scene *s) {
    double v2 = 0;
    const double *v = pcold(&s->ps, PC_V);
    for (int i = 0; i < s->ps.n; i++) v2 = fmax(v2, v[3 * i] * v[3 * i] + v[3 * i + 1] * v[3 * i + 1]);
    return sqrt(v2);
}

/* The surface height over the floor at x: the highest particle within half a cell of x, plus its half spacing
 * (a particle stands for the sqrt(vol) square around it). -1 when no particle is there. */
static double height_at(const hearth_scene *s, double x, double yf, double dx) {
    const double *X = pcold(&s->ps, PC_X), *V0 = pcold(&s->ps, PC_VOL0);
    double top = -1;
    for (int i = 0; i < s->ps.n; i++)
        if (fabs(X[3 * i] - x) < 0.5 * dx) top = fmax(top, X[3 * i + 1] - yf + 0.5 * sqrt(V0[i]));
    return top;
}

/* One puddle at dx. The moduli are not the paper's 1e6 / 1e5 Pa (section 4.6): the closed form is rigid-plastic,
 * and its limit only needs them far above the stresses, rho g h0 = 108 Pa and tau_y = 8 Pa; kappa = mu = 1e4 Pa
 * keeps the elastic strains under 1.1% (volume) and 0.08% (shear at yield) and the wave speed at 4.8 m/s, so the
 * step is 7x the paper moduli's. The scene's damping c = 2 sqrt(g / H) (H the rectangle's 36 mm) makes the slump
 * slow, as the closed form assumes: the drag time 1/c is half the free fall's sqrt(H / g), and a front moving at
 * the drag's terminal speed g (h0 / L) / c coasts g (h0 / L) / c^2 = 1.4 mm (2% of L) once its slope is gone.
 * Damping acts on velocity only, so it changes no state at rest. */
/* The melted cookie dough in the cam_clay_dough plugin, for PUDDLE_DOUGH (a diagnostic; docs/validation.md, #18
 * helper puddle2). Its plateau from lua/hearth/dough_physical.lua's cookie on branch cookiespread2-dough (helper
 * cookiespread, fixed there before any run): tau_y 16.6 Pa on eq. 12's q (q = sqrt(3) s, s = 9.6 Pa in shear, the
 * AACC disc's bound rho g H^2 / (2R)), mu 1.3e4 Pa s (6 mu_s, Huppert 1982 on Miller & Hoseney 1997's spread),
 * density 1200, flow_stress 82 Pa (rho g H of that disc). eta in the plugin's Pa^3 s as that file maps mu: 2 tau_y^2
 * mu without flow_stress, mu q_r (q_r + tau_y) with q_r = max(tau_y, flow_stress). No gas field: n^p reads 0, so eq.
 * 12 is von Mises q <= tau_y, a plain yield-stress dough. E and nu give the sauce's kappa = mu = 1e4 Pa (E 2.25e4,
 * nu 0.125), so the two piles differ only in the law. */
typedef struct dough_law {
    int on, flow; /* on: the dough instead of the sauce; flow: with flow_stress */
    double q_y, mu, rho, flow_stress;
} dough_law;

/* A diagnostic's variable, read only with PUDDLE_DX (a diagnostic run): the tests' own runs ignore them */
static const char *diag_env(const char *name) { return getenv("PUDDLE_DX") ? getenv(name) : NULL; }

static dough_law dough_from_env(void) {
    dough_law dl = {0, 0, 16.6, 1.3e4, 1200, 1200 * 9.81 * 0.007};
    const char *e = getenv("PUDDLE_DOUGH"); /* "flow" (the preset's flow_stress) or "off" */
    /* only with PUDDLE_DX: the test's verdict and its cause are the sauce's */
    if (e && *e && getenv("PUDDLE_DX")) dl.on = 1, dl.flow = strcmp(e, "off") != 0;
    return dl;
}

/* PUDDLE_SNAP=prefix (a diagnostic with PUDDLE_DX, docs/validation.md #18 helper puddleslit): the particles every
 * 0.05 s up to PUDDLE_SNAP_TMAX (1 s), one file prefix_<ms>.txt each: id, x and y over the floor (m), vx, vy
 * (m/s), J = det F, the Cauchy stress xx yy xy zz (Pa), the density (kg/m^3), the pressure (Pa), von Mises q (Pa),
 * F xx xy yx yy; and the state at the end of the run (its time in the name). */
static void snap(const hearth_scene *s, double yf) {
    const char *pre = diag_env("PUDDLE_SNAP");
    const int n = s->ps.n;
    double *st = malloc(sizeof(double) * 9 * (size_t)n), *rho = malloc(sizeof(double) * (size_t)n);
    double *p = malloc(sizeof(double) * (size_t)n), *q = malloc(sizeof(double) * (size_t)n);
    hearth_error err;
    char path[4096];
    snprintf(path, sizeof path, "%s_%04.0f.txt", pre, 1e3 * s->t);
    FILE *f = fopen(path, "w");
    if (f && st && rho && p && q && !hearth_scene_particle_field(s, "stress", st, &err) &&
        !hearth_scene_particle_field(s, "density", rho, &err) && !hearth_scene_particle_field(s, "pressure", p, &err) &&
        !hearth_scene_particle_field(s, "von_mises", q, &err)) {
        const double *X = pcold(&s->ps, PC_X), *V = pcold(&s->ps, PC_V);
        const int *id = hearth_scene_particle_ids(s);
        for (int i = 0; i < n; i++) {
            double F[9];
            particles_F3(&s->ps, i, F);
            const double J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
                             F[2] * (F[3] * F[7] - F[4] * F[6]);
            fprintf(f, "%d %.9g %.9g %.6g %.6g %.9g %.6g %.6g %.6g %.6g %.6g %.6g %.6g %.6g %.6g %.6g %.6g\n", id[i],
                    X[3 * i], X[3 * i + 1] - yf, V[3 * i], V[3 * i + 1], J, st[9 * i], st[9 * i + 4], st[9 * i + 1],
                    st[9 * i + 8], rho[i], p[i], q[i], F[0], F[1], F[3], F[4]);
        }
    }
    if (f) fclose(f);
    free(st), free(rho), free(p), free(q);
}

/* Neighbours against their deformation gradients (docs/validation.md, #18 helper puddleslit). The seeding is an
 * unjittered lattice of spacing hs, so a particle's column and row are its lattice indices at t = 0. Two particles of
 * one row in neighbouring columns started hs e_x apart; to first order in hs they are now hs F e_x apart, F their
 * mean deformation gradient. The ratio |x_b - x_a| / (hs |F e_x|) is 1 while the particles move as their F says,
 * and the grid's velocity is smooth over the gap; above 1 the pair has parted further than the material they carry
 * was stretched: a gap the continuum does not have (a slit), below 1 they bunch. Only pairs above two cells from
 * the floor (the held row and the B-spline's reach over it are another matter: validation.md, helper puddle). */
typedef struct lattice {
    int *col, *row, ncol, nrow, n; /* by id: the particle's column and row; the id at (column, row) or -1 */
    int *at;
    double *x0; /* by id: the seeded position, x y (a jittered seeding's pairs start off hs e_x) */
    double hs, x_mid;
} lattice;

static lattice lattice_of(const hearth_scene *s, double hs) {
    lattice L = {0};
    const int n = s->ps.n, *id = hearth_scene_particle_ids(s);
    const double *X = pcold(&s->ps, PC_X);
    double xl = 1e300, yl = 1e300, xr = -1e300;
    int idmax = 0;
    for (int i = 0; i < n; i++) xl = fmin(xl, X[3 * i]), xr = fmax(xr, X[3 * i]), yl = fmin(yl, X[3 * i + 1]);
    for (int i = 0; i < n; i++) idmax = id[i] > idmax ? id[i] : idmax;
    L.n = idmax + 1, L.hs = hs, L.x_mid = 0.5 * (xl + xr);
    L.col = malloc(sizeof(int) * (size_t)L.n), L.row = malloc(sizeof(int) * (size_t)L.n);
    L.x0 = malloc(sizeof(double) * 2 * (size_t)L.n);
    if (!L.col || !L.row || !L.x0) return L;
    /* the seeding's lattice sites are the domain's lo + (k + 1/2) hs, and a jitter (at most 1/2) moves a particle
     * less than hs / 4 off its site, so floor() gives its site whatever the jitter */
    const int c0 = (int)floor((xl - s->def.lo[0]) / hs), r0 = (int)floor((yl - s->def.lo[1]) / hs);
    for (int i = 0; i < n; i++) {
        L.x0[2 * id[i]] = X[3 * i], L.x0[2 * id[i] + 1] = X[3 * i + 1];
        L.col[id[i]] = (int)floor((X[3 * i] - s->def.lo[0]) / hs) - c0;
        L.row[id[i]] = (int)floor((X[3 * i + 1] - s->def.lo[1]) / hs) - r0;
        L.ncol = L.col[id[i]] + 1 > L.ncol ? L.col[id[i]] + 1 : L.ncol;
        L.nrow = L.row[id[i]] + 1 > L.nrow ? L.row[id[i]] + 1 : L.nrow;
    }
    L.at = malloc(sizeof(int) * (size_t)L.ncol * (size_t)L.nrow);
    if (!L.at) return L;
    for (long k = 0; k < (long)L.ncol * L.nrow; k++) L.at[k] = -1;
    for (int i = 0; i < n; i++) L.at[(long)L.col[id[i]] * L.nrow + L.row[id[i]]] = id[i];
    return L;
}

static void lattice_free(lattice *L) { free(L->col), free(L->row), free(L->at), free(L->x0); }

/* r->gapF (and where) and r->mid_gap from the particles now; yf the floor, dx the cell */
static void neighbours_against_F(const hearth_scene *s, const lattice *L, double yf, double dx, puddle_result *r) {
    const int n = s->ps.n, *id = hearth_scene_particle_ids(s);
    int *idx = malloc(sizeof(int) * (size_t)L->n);
    if (!idx || !L->at || !L->x0) {
        free(idx);
        r->gapF = NAN;
        return;
    }
    for (int i = 0; i < n; i++) idx[id[i]] = i;
    const double *X = pcold(&s->ps, PC_X);
    /* the pair straddling the symmetry line: the columns either side of the seeded middle (none if a column is on
     * it) */
    const double c_mid = 0.5 * (L->ncol - 1);
    const int straddle = fabs(c_mid - floor(c_mid) - 0.5) < 1e-9, cl = (int)floor(c_mid);
    for (int c = 0; c + 1 < L->ncol; c++)
        for (int w = 0; w < L->nrow; w++) {
            const int ia = L->at[(long)c * L->nrow + w], ib = L->at[(long)(c + 1) * L->nrow + w];
            if (ia < 0 || ib < 0) continue;
            const int a = idx[ia], b = idx[ib];
            if (straddle && c == cl) r->mid_gap = fmax(r->mid_gap, (X[3 * b] - X[3 * a]) / dx);
            if (X[3 * a + 1] - yf < 2 * dx || X[3 * b + 1] - yf < 2 * dx) continue;
            double Fa[9], Fb[9];
            particles_F3(&s->ps, a, Fa);
            particles_F3(&s->ps, b, Fb);
            /* F dx0, F the pair's mean (row-major), dx0 their seeded offset (hs e_x unjittered) */
            const double d0x = L->x0[2 * ib] - L->x0[2 * ia], d0y = L->x0[2 * ib + 1] - L->x0[2 * ia + 1];
            const double fx = 0.5 * ((Fa[0] + Fb[0]) * d0x + (Fa[1] + Fb[1]) * d0y);
            const double fy = 0.5 * ((Fa[3] + Fb[3]) * d0x + (Fa[4] + Fb[4]) * d0y);
            const double gx = X[3 * b] - X[3 * a], gy = X[3 * b + 1] - X[3 * a + 1];
            const double dev = fabs(sqrt(gx * gx + gy * gy) / sqrt(fx * fx + fy * fy) - 1);
            if (dev > r->gapF)
                r->gapF = dev, r->gapF_x = 0.5 * (X[3 * a] + X[3 * b]) - L->x_mid,
                r->gapF_y = 0.5 * (X[3 * a + 1] + X[3 * b + 1]) - yf;
        }
    free(idx);
}

static puddle_result puddle(const hearth_sauce *sc, double dx, double t_max, int ppc_arg, double rest_arg) {
    puddle_result r = {0};
    const dough_law dl = dough_from_env();
    const double rho = dl.on ? dl.rho : 1000, g = 9.81, H = 0.036, yf = 0.02;
    const double W = diag_env("PUDDLE_W") ? atof(diag_env("PUDDLE_W")) : 0.030; /* PUDDLE_W: a diagnostic width (m) */
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = dx;
    d.lo[0] = -0.12, d.hi[0] = 0.12;
    d.lo[1] = 0, d.hi[1] = 0.08;
    d.gravity[1] = -g;
    d.damping = 2 * sqrt(g / H);
    /* diagnostics for the slit on the symmetry line (docs/validation.md, #18 helper puddleslit; only with
     * PUDDLE_DX): PUDDLE_SHIFT=m moves the block along x (dx/2 puts the symmetry line between node columns),
     * PUDDLE_PPC=n seeds n per cell (4; a test's ppc_arg > 0 sets it), PUDDLE_PIC=1 the PIC transfer,
     * PUDDLE_DAMPING=f multiplies the damping, PUDDLE_JITTER=f seeds with that jitter (0; the scenes' 0.5) */
    const double shift = diag_env("PUDDLE_SHIFT") ? atof(diag_env("PUDDLE_SHIFT")) : 0;
    const int ppc = ppc_arg > 0 ? ppc_arg : diag_env("PUDDLE_PPC") ? atoi(diag_env("PUDDLE_PPC")) : 4;
    const double jitter = diag_env("PUDDLE_JITTER") ? atof(diag_env("PUDDLE_JITTER")) : 0; /* the scenes' is 0.5 */
    if (diag_env("PUDDLE_PIC")) d.transfer = 1;
    if (diag_env("PUDDLE_DAMPING")) d.damping *= atof(diag_env("PUDDLE_DAMPING"));
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return r;
    const char *names[] = {"kappa", "mu", "sigma_y", "eta", "h", "density"};
    const double vals[] = {1e4, 1e4, sc->sigma_y, sc->eta, sc->h, rho};
    hearth_error err;
    const char *dnames[] = {"E", "nu", "tau_y", "eta", "density"};
    const double qr = fmax(dl.q_y, dl.flow_stress);
    const double deta = dl.flow ? dl.mu * qr * (qr + dl.q_y) : 2 * dl.q_y * dl.q_y * dl.mu;
    const double dvals[] = {2.25e4, 0.125, dl.q_y, deta, rho};
    if (dl.on)
        printf("  cam_clay_dough: tau_y %.3g Pa on q (%.3g in shear), eta %.3g Pa^3 s (%s flow_stress), density %g\n",
               dl.q_y, dl.q_y / sqrt(3.0), deta, dl.flow ? "with" : "without", rho);
    const int m = dl.on ? hearth_scene_add_material(s, "cam_clay_dough", dnames, dvals, 5, &err)
                        : hearth_scene_add_material(s, "von_mises_sauce", names, vals, 6, &err);
    if (m < 0) {
        fprintf(stderr, "material: %s\n", err.msg);
        hearth_scene_destroy(s);
        return r;
    }
    const double c[3] = {shift, yf + 0.5 * H, 0}, h[3] = {0.5 * W, 0.5 * H, 0};
    hearth_shape *blk = hearth_shape_box(c, h);
    const int seeded = hearth_scene_seed_shape(s, m, blk, ppc, jitter, NULL, &err);
    hearth_shape_free(blk);
    if (seeded <= 0) {
        fprintf(stderr, "seed: %s\n", seeded < 0 ? err.msg : "no particles");
        hearth_scene_destroy(s);
        return r;
    }
    const double fc[3] = {0, 0.5 * yf, 0}, fh[3] = {0.2, 0.5 * yf, 0};
    /* PUDDLE_FLOOR_FRICTION=mu: a diagnostic, the floor a slip face of Coulomb mu instead of sticky (mu >> 1 holds
     * the nodes the body touches, without the sticky face's glue) */
    const char *fmu = getenv("PUDDLE_FLOOR_FRICTION");
    hearth_shape *fb = hearth_shape_box(fc, fh);
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = fb, cd.mode = fmu ? HEARTH_SLIP : HEARTH_STICKY, cd.friction = fmu ? atof(fmu) : 0;
    const int floor_id = hearth_scene_add_collider(s, &cd, &err);
    hearth_shape_free(fb);
    if (floor_id < 0) {
        fprintf(stderr, "floor: %s\n", err.msg);
        hearth_scene_destroy(s);
        return r;
    }
    double A = 0;
    for (int i = 0; i < s->ps.n; i++) A += pcold(&s->ps, PC_VOL0)[i];
    const double tau = dl.on ? dl.q_y / sqrt(3.0) : sc->sigma_y;
    r.h0_cf = cbrt(3 * A * tau / (2 * rho * g));
    r.L_cf = rho * g * r.h0_cf * r.h0_cf / (2 * tau);
    r.ok = 1;
    /* rest: the half-width grew less than 0.1% of the closed form's L over the last second (the shear-thinning
     * flow index 0.456 makes the last creep slow; eta u^h is still 9% of tau_y at 0.06 1/s) */
    const char *rest_env = getenv("PUDDLE_REST"); /* the rest criterion's fraction of L per second; 0 = run to t_max */
    const double rest_frac = rest_arg >= 0 ? rest_arg : rest_env ? atof(rest_env) : 1e-3;
    const int k_lat = (int)floor(sqrt((double)ppc) + 0.5);
    lattice lat = lattice_of(s, dx / (k_lat < 1 ? 1 : k_lat));
    double Lprev = half_width(s);
    const double snap_tmax = diag_env("PUDDLE_SNAP_TMAX") ? atof(diag_env("PUDDLE_SNAP_TMAX")) : 1.0;
    if (diag_env("PUDDLE_SNAP")) snap(s, yf);
    for (int j = 1; diag_env("PUDDLE_SNAP") && j <= (int)(snap_tmax / 0.05 + 0.5); j++) {
        if (hearth_scene_advance(s, 0.05 * j, &err) != HEARTH_OK) break;
        snap(s, yf);
    }
    for (int k = 1; k <= (int)(t_max / 0.5 + 0.5); k++) {
        if (hearth_scene_advance(s, 0.5 * k, &err) != HEARTH_OK) {
            fprintf(stderr, "advance: %s\n", err.msg);
            r.ok = 0;
            break;
        }
        r.vmax = max_speed(s);
        const double Lk = half_width(s);
        if (getenv("PUDDLE_TRACE"))
            printf("    t %.1f s: max speed %.3g m/s, half-width %.2f mm\n", s->t, r.vmax, 1e3 * Lk);
        if (k % 2 == 0) {
            if (Lk - Lprev < rest_frac * r.L_cf) break;
            Lprev = Lk;
        }
    }
    if (diag_env("PUDDLE_SNAP")) snap(s, yf);
    neighbours_against_F(s, &lat, yf, dx, &r);
    lattice_free(&lat);
    r.t_rest = s->t;
    r.steps = s->step;
    r.n = s->ps.n;
    const double *X = pcold(&s->ps, PC_X);
    double xl = 1e300, xr = -1e300;
    for (int i = 0; i < s->ps.n; i++) xl = fmin(xl, X[3 * i]), xr = fmax(xr, X[3 * i]);
    const double xm = 0.5 * (xl + xr);
    r.L = half_width(s);
    r.h0 = height_at(s, xm, yf, dx);
    /* the crest: the highest surface within a tenth of L of the middle (a slit can open on the symmetry line, where
     * the spread stretches the two middle particle columns apart) */
    for (int k = -4; k <= 4; k++) r.crest = fmax(r.crest, height_at(s, xm + k * 0.025 * r.L, yf, dx));
    /* the effective yield stress the rest state implies: L = (rho g / (2 tau)) (3 A tau / (2 rho g))^(2/3) goes as
     * tau^(-1/3), so tau_eff = tau_y (L_cf / L)^3; and the front's height against the tallest vertical face a
     * Tresca material stands, H_c = 3.83 tau_y / (rho g) (limit analysis's upper bound; Chen 1975), where the
     * shallow form has h -> 0 */
    r.tau_eff = tau * pow(r.L_cf / r.L, 3);
    r.front = height_at(s, xm + r.L - dx, yf, dx);
    r.Hc = 3.83 * tau / (rho * g);
    if (getenv("PUDDLE_DUMP")) { /* the particles at rest, x y (m) over the floor, for a plot */
        FILE *f = fopen(getenv("PUDDLE_DUMP"), "w");
        for (int i = 0; f && i < s->ps.n; i++) fprintf(f, "%g %g\n", X[3 * i], X[3 * i + 1] - yf);
        if (f) fclose(f);
    }
    printf("  dx %.1f mm: %d particles, %ld steps, rest at t = %.1f s (max speed %.2g m/s)\n", 1e3 * dx, r.n, r.steps,
           r.t_rest, r.vmax);
    printf("    h0 at the middle %.2f mm, crest %.2f mm (closed form %.2f: %+.1f%%, %+.1f%%), L %.2f mm (closed form "
           "%.2f, %+.1f%%)\n", 1e3 * r.h0, 1e3 * r.crest, 1e3 * r.h0_cf, 100 * (r.h0 / r.h0_cf - 1),
           100 * (r.crest / r.h0_cf - 1), 1e3 * r.L, 1e3 * r.L_cf, 100 * (r.L / r.L_cf - 1));
    printf("    effective yield from L %.3g Pa (%.2f tau_y); front (a cell in) %.2f mm high, H_c %.2f mm\n", r.tau_eff,
           r.tau_eff / tau, 1e3 * r.front, 1e3 * r.Hc);
    printf("    %d per cell: neighbours against F: largest |gap / (h |F e_x|) - 1| %.3f at x %+.1f mm, %.1f mm up; the "
           "pair across the symmetry line at most %.2f cells apart%s\n", ppc, r.gapF, 1e3 * r.gapF_x, 1e3 * r.gapF_y,
           r.mid_gap, r.mid_gap > 0 ? "" : " (a column on it)");
    /* the profile against the closed form's on the measured L: h(x)^2 = 2 tau (L - |x|) / (rho g) */
    printf("    profile |x|/L: h / closed form on the measured L:");
    for (int k = 0; k <= 9; k++) {
        const double xk = xm + k * 0.1 * r.L, want = sqrt(2 * tau * (r.L - fabs(xk - xm)) / (rho * g));
        printf(" %.1f:%.2f", 0.1 * k, height_at(s, xk, yf, dx) / want);
    }
    printf("\n");
    hearth_scene_destroy(s);
    return r;
}

TEST(sauce_puddle_rests_at_yield_profile) {
    hearth_sauce sc;
    CHECK(load_sauce("hot_chilli", &sc));
    if (test_failures) return;
    printf("  %s: tau_y %.3g Pa, eta %.3g Pa s^h, h %.3g\n", sc.label, sc.sigma_y, sc.eta, sc.h);
    /* 4 mm (6 s of CPU) only for the observed order of L over three dx; the bars read 2 and 1 mm */
    const double dxs[3] = {0.004, 0.002, 0.001};
    puddle_result r[3];
    if (getenv("PUDDLE_DX")) { /* a diagnostic: one puddle at another dx, no verdict */
        const char *tm = getenv("PUDDLE_TMAX"); /* the longest run (s), 15 by default */
        puddle_result one = puddle(&sc, atof(getenv("PUDDLE_DX")), tm ? atof(tm) : 15.0, 0, -1);
        CHECK(one.ok);
        return;
    }
    for (int k = 0; k < 3; k++) {
        r[k] = puddle(&sc, dxs[k], 15.0, 4, -1);
        CHECK(r[k].ok);
        if (!r[k].ok) return;
    }
    const double e0 = fabs(r[1].h0 / r[1].h0_cf - 1), e1 = fabs(r[2].h0 / r[2].h0_cf - 1);
    const double eL0 = fabs(r[1].L / r[1].L_cf - 1), eL = fabs(r[2].L / r[2].L_cf - 1);
    /* L's observed order over 4, 2, 1 mm, and the Richardson estimate of L at dx -> 0 it gives */
    const double pL = log((r[0].L - r[1].L) / (r[1].L - r[2].L)) / log(2.0);
    const double Linf = r[2].L + (r[2].L - r[1].L) / (pow(2.0, pL) - 1);
    printf("  h0 error %.1f%% at 2 mm, %.1f%% at 1 mm (observed order %.2f); L error %.1f%%, %.1f%%, %.1f%% at 4, 2, 1 "
           "mm (observed order %.2f), extrapolated to dx -> 0: %.2f mm (%+.1f%%); bars: h0 and L within 10%% at 1 mm, "
           "h0's error falling\n", 100 * e0, 100 * e1, log(e0 / e1) / log(2.0), 100 * fabs(r[0].L / r[0].L_cf - 1),
           100 * eL0, 100 * eL, pL, 1e3 * Linf, 100 * (Linf / r[2].L_cf - 1));
    if (!(e1 < 0.10 && eL < 0.10 && e1 < e0))
        XFAIL("the sauce rests narrower than the closed form's puddle: L %+.1f%%, %+.1f%% at 2, 1 mm (effective yield "
              "%.2f, %.2f tau_y), crest %+.1f%%, %+.1f%%, the middle cut by a slit (the 2 x 2 seeding's columns, "
              "stretched past a cell apart, part further than their F: #18 helper puddleslit; none at 16 per cell); "
              "its front stands %.1f, %.1f mm high "
              "where the form goes to 0 (a Tresca face stands %.1f mm). L moves toward the form as dx falls (observed "
              "order %.2f, extrapolated to %+.1f%% of the form): the resolution of the thin layer and its front holds "
              "it, not the sticky face (a slip floor of Coulomb 1000 holds it within 1-4 points; docs/validation.md, "
              "#18 helper puddle)",
              100 * (r[1].L / r[1].L_cf - 1), 100 * (r[2].L / r[2].L_cf - 1), r[1].tau_eff / sc.sigma_y,
              r[2].tau_eff / sc.sigma_y, 100 * (r[1].crest / r[1].h0_cf - 1), 100 * (r[2].crest / r[2].h0_cf - 1),
              1e3 * r[1].front, 1e3 * r[2].front, 1e3 * r[1].Hc, pL, 100 * (Linf / r[2].L_cf - 1));
}

/* Does the spreading pile's particles stay where their F puts them? (docs/validation.md, #18 helper puddleslit) The
 * slit the puddle opens on its symmetry line at 2 and 1 mm is a pair of particle columns that parted further than
 * their own F was stretched (at 2 mm, 10 s: the two middle columns 5.4 spacings apart where their F_xx says 3.4-3.8),
 * the grid no longer resolving the layer between columns once they stand more than a cell apart. The same puddle
 * at dx 4 mm run 2 s (no rest criterion; L near 40 mm of its 45 at rest, the middle stretched some 3x). Bar, set at
 * 20:45 UTC on 7 Dec 2026 before any run at 4 mm: every pair of neighbouring particles of one row above two cells
 * parted as their mean F says within 5%: |gap / (h |F e_x|) - 1| <= 0.05. At 16 per cell (4 x 4) that is the
 * claim; at the scenes' 4 per cell (2 x 2, s:add's default) the 2 mm trace read the middle pair 25% past its F at 1
 * s: an expected failure there until the seeding or the transfer changes. */
static void neighbours_follow_F(int ppc) {
    hearth_sauce sc;
    CHECK(load_sauce("hot_chilli", &sc));
    if (test_failures) return;
    const puddle_result r = puddle(&sc, 0.004, 2.0, ppc, 0);
    CHECK(r.ok);
    CHECK(isfinite(r.gapF));
    if (!r.ok || !isfinite(r.gapF)) return;
    printf("  bar: every neighbouring pair above two cells within 5%% of hs |F e_x|: measured %.3f\n", r.gapF);
    if (r.gapF <= 0.05) return;
    if (ppc == 4)
        XFAIL("at 4 per cell neighbouring particles part %.1f%% further or closer than their F says (at x %+.1f mm, "
              "%.1f mm up): the 2 x 2 columns, stretched some 3x, stand more than a cell apart and the grid no longer "
              "carries the material between them; at 16 per cell the same run holds the bar (docs/validation.md, #18 "
              "helper puddleslit)", 100 * r.gapF, 1e3 * r.gapF_x, 1e3 * r.gapF_y);
    else
        CHECK(r.gapF <= 0.05);
}

TEST(sauce_spread_neighbours_follow_F_16ppc) { neighbours_follow_F(16); }
TEST(sauce_spread_neighbours_follow_F_4ppc) { neighbours_follow_F(4); }

TEST_MAIN(T(sauce_puddle_rests_at_yield_profile), T(sauce_spread_neighbours_follow_F_16ppc),
          T(sauce_spread_neighbours_follow_F_4ppc))
