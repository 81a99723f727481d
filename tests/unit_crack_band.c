/* unit_crack_band.c: the crack band of plugins/cam_clay_dough.c ("the crack
 * band": Bazant & Oh 1983) in the MPM solver, not at one material point.
 *
 * A plane-strain bar of cam_clay_dough made elastic-brittle (tau_y 1e9 Pa so
 * it never yields, eta 0, no heat, gas or water; nu = 0 so that plane strain
 * is uniaxial stress and the closed forms below are exact to small strain;
 * the stretch rule with a constant fracture_strain eps_f and the crack band
 * with crack_opening w_c and crack_band h = dx, as h.material gives a preset
 * with crack_band 0) is pulled apart by two grips (HEARTH_GRIP) whose faces
 * lie on node rows. One cell across the middle has a fracture_strain 5%
 * lower, so the crack starts there and not where round-off puts it. Each
 * particle's stress work W_p = int V tau... = int V0 J sigma : sym(C) dt is
 * summed by the test from the stress field and the APIC C (the velocity
 * gradient the plugin is given: F <- (I + dt C) F), so the energy a crack
 * takes is measured whether the failure is quasi-static or snaps back.
 *
 * The closed form (derived here, not computed by the code under test): with
 * nu = 0 the Kirchhoff stress is tau_xx = E eps (Hencky), and the stretch
 * rule's measure sqrt(2/3) N : D is (2/3) d eps for a uniaxial strain
 * (dev eps = eps (2, -1, -1) / 3). So the peak is at eps_p = 1.5 eps_f,
 * f_t = E eps_p, and the band (the plugin's header, "the crack band")
 * softens linearly from f_t to 0 over a further strain 1.5 (w_c / h - eps_f):
 * the area under its stress-strain line is 1.5 f_t (w_c / h) / 2, so a band of
 * width h that separates takes per unit crack area
 *   G = 0.75 f_t w_c                         when w_c / h > eps_f,
 * the plugin's G_f = f_t w_c / 2 in its own stretch measure, and, in a cell
 * too large for the band (w_c / h <= eps_f), where the point drops at its
 * peak, its elastic energy there, 0.75 f_t h eps_f. The law before (helper
 * crackband's first commit on this branch) took the undamaged tension times
 * 1 - x / (1.5 w_c / h): h E eps_p^2 / 2 + 0.75 f_t w_c + E (1.5 w_c / h)^2 h / 6
 * per area, with h in the first term and 1 / h in the last, and where
 * w_c / h > eps_f it hardened past its peak (docs/validation.md, "Is the
 * crack band mesh-objective?"). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mpm_fixture.h"

#define EPS_F 0.02
#define E_MOD 4e4

typedef struct band_run {
    double dx, wc;
    double peak_force; /* N per m of depth: sum V sigma_xx over the gauge / its length, largest */
    double ft_area;    /* f_t x H, the closed form's peak force */
    double work_band;  /* sum of W_p over the particles past the peak (D > 0.5), per unit area, J/m^2 */
    double work_all;   /* sum of W_p over every particle, less the elastic energy of the unbroken ones, per area */
    double g_closed;   /* G above, J/m^2: 0.75 f_t w_c, or 0.75 f_t h eps_f in a cell too large for the band */
    double g_design;   /* 0.75 f_t w_c: the h-independent (designed) part */
    double band_cells; /* the width of the particles past the peak in cells (columns x dx/2 / dx) */
    int broken;        /* particles at D = 1 */
    int cols;          /* particle columns past the peak */
    long steps;
    int ok;
} band_run;

static int dough_material(hearth_scene *s, double ef, double wc, double h) {
    const char *n[] = {"E", "nu", "tau_y", "eta", "density", "fracture_strain", "fracture_stretch", "crack_opening", "crack_band"};
    const double v[] = {E_MOD, 0.0, 1e9, 0.0, 500, ef, 1, wc, h};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "cam_clay_dough", n, v, 9, &err);
    if (m < 0) fprintf(stderr, "material: %s\n", err.msg);
    return m;
}

/* The elastic energy of an unbroken particle, nu = 0: psi = mu (eps1^2 + eps2^2), eps = log of F's stretches. */
static double hencky_energy_2d(const double F[9]) {
    const double a = F[0] * F[0] + F[1] * F[1], b = F[0] * F[3] + F[1] * F[4], c = F[3] * F[3] + F[4] * F[4];
    const double m = 0.5 * (a + c), r = sqrt(0.25 * (a - c) * (a - c) + b * b);
    const double e1 = 0.5 * log(m + r), e2 = 0.5 * log(m - r);
    return 0.5 * E_MOD * (e1 * e1 + e2 * e2);
}

static band_run pull_bar(double dx, double wc) {
    band_run R = {.dx = dx, .wc = wc};
    const double L = getenv("CB_L") ? atof(getenv("CB_L")) : 0.012, H = 0.004, Lg = 0.004, V = 0.01, y0 = 0.01;
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 2;
    d.dx = dx;
    d.gravity[1] = 0;
    d.lo[0] = -0.02, d.hi[0] = 0.02;
    d.lo[1] = 0, d.hi[1] = 0.02;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return R;
    const int ma = dough_material(s, EPS_F, wc, dx), mb = dough_material(s, 0.95 * EPS_F, wc, dx);
    const int mc = dough_material(s, 0, wc, dx); /* the ends: fracture_strain 0, never cracks */
    CHECK(ma >= 0 && mb >= 0 && mc >= 0);
    /* along x: the gripped end and 4 mm past the grip's face that never crack (the grip's face concentrates the
     * strain: there the bar broke first, at 2 and 1 mm, when it could), the bar, the weak cell [0, dx] across
     * the middle, the bar, the other end; every edge on a cell edge, so the seeding is the lattice's */
    const double xl = -0.5 * L - Lg, xr = 0.5 * L + Lg, xs = 0.5 * L - 0.004;
    const double edge[7] = {xl, -xs, 0, dx, xs, xr};
    const int mat[5] = {mc, ma, mb, ma, mc};
    for (int k = 0; k < 5; k++) {
        const double c[3] = {0.5 * (edge[k] + edge[k + 1]), y0, 0}, hh[3] = {0.5 * (edge[k + 1] - edge[k]), 0.5 * H, 0};
        if (edge[k + 1] > edge[k]) CHECK(fx_box(s, mat[k], c, hh, 4, NULL) > 0); /* at dx = 2 mm the bar's right part is empty */
    }
    for (int side = -1; side <= 1; side += 2) { /* faces at x = -+L/2, on node rows */
        const double gc[3] = {side * (0.5 * L + 0.005), y0, 0}, gh[3] = {0.005, H, 0};
        CHECK(fx_box_collider(s, gc, gh, HEARTH_GRIP, side * V) >= 0);
    }
    const int n = s->ps.n;
    double *W = calloc((size_t)n, sizeof *W), *sig = malloc((size_t)n * 9 * sizeof *sig), *Cn = malloc((size_t)n * 4 * sizeof *Cn);
    double *x0 = malloc((size_t)n * sizeof *x0); /* each particle's x at rest, by id */
    for (int i = 0; i < n; i++) { /* ids are given from 0 at seeding: the test's arrays are indexed by them */
        const int k = hearth_scene_particle_ids(s)[i];
        CHECK(k >= 0 && k < n);
        if (k < 0 || k >= n) {
            hearth_scene_destroy(s);
            free(W), free(sig), free(Cn), free(x0);
            return R;
        }
        x0[k] = pcold(&s->ps, PC_X)[3 * i];
    }
    const int stride = s->ps.state_stride;
    hearth_error err;
    if (hearth_scene_particle_field(s, "stress", sig, &err) != HEARTH_OK) CHECK(0);
    const double eps_p = 1.5 * 0.95 * EPS_F, ft = E_MOD * eps_p / exp(eps_p); /* Cauchy = tau / J at the peak */
    R.ft_area = ft * H;
    double t_end = 1e9;
    while (s->t < t_end && s->t < 0.2) {
        /* the step's F update uses this C (G2P of the last step wrote it), F <- (I + dt C) F: the work is dt C :
         * sigma V at the step's middle, the mean of the stress power with the stresses before and after it */
        const double t0 = s->t;
        const int *id = hearth_scene_particle_ids(s);
        for (int i = 0; i < n; i++) {
            double C[9], F[9];
            particles_C3(&s->ps, i, C);
            particles_F3(&s->ps, i, F);
            double *c = Cn + 4 * id[i];
            c[0] = C[0], c[1] = 0.5 * (C[1] + C[3]), c[2] = C[4];
            const double *g = sig + 9 * i;
            c[3] = pcold(&s->ps, PC_VOL0)[i] * (F[0] * F[4] - F[1] * F[3]) * (g[0] * c[0] + (g[1] + g[3]) * c[1] + g[4] * c[2]);
        }
        if (hearth_scene_step(s, 1, &err) != HEARTH_OK) {
            fprintf(stderr, "step: %s\n", err.msg);
            break;
        }
        if (hearth_scene_particle_field(s, "stress", sig, &err) != HEARTH_OK) break;
        const double dt = s->t - t0;
        id = hearth_scene_particle_ids(s);
        for (int i = 0; i < n; i++) {
            const double *c = Cn + 4 * id[i], *g = sig + 9 * i;
            const double pw = pcold(&s->ps, PC_VOL0)[i] * particles_J(&s->ps, i) * (g[0] * c[0] + (g[1] + g[3]) * c[1] + g[4] * c[2]);
            W[id[i]] += 0.5 * dt * (c[3] + pw);
        }
        R.steps++;
        /* the force: sum V sigma_xx over the particles between the grips' faces over the faces' distance */
        const double xf = 0.5 * L + V * s->t;
        double sf = 0;
        for (int i = 0; i < n; i++) {
            const double *x = pcold(&s->ps, PC_X) + 3 * i;
            if (fabs(x[0]) < xf) sf += pcold(&s->ps, PC_VOL0)[i] * particles_J(&s->ps, i) * sig[9 * i];
        }
        const double force = sf / (2 * xf);
        if (force > R.peak_force) R.peak_force = force;
        int broken = 0;
        for (int i = 0; i < n; i++) broken += pcold(&s->ps, PC_STATE)[(size_t)stride * i + 7] >= 1;
        if (broken > 0 && t_end > 1e8) t_end = s->t + 0.02; /* then run on while the halves ring */
    }
    /* the energy: the band's particles past the peak, and all less the unbroken ones' elastic energy */
    const int *id = hearth_scene_particle_ids(s);
    double wb = 0, wa = 0;
    unsigned char col[4096] = {0};
    for (int i = 0; i < n; i++) {
        const double D = pcold(&s->ps, PC_STATE)[(size_t)stride * i + 7];
        double F[9];
        particles_F3(&s->ps, i, F);
        wa += W[id[i]];
        if (D > 0.5) {
            wb += W[id[i]];
            /* its column at rest: x0 = x - displacement; the columns are dx/2 apart from xl + dx/4 */
            R.broken += D >= 1;
        } else {
            wa -= pcold(&s->ps, PC_VOL0)[i] * hencky_energy_2d(F);
        }
    }
    /* columns past the peak, by the particles' x at rest (seeded on the dx/2 lattice; the bar moves little) */
    for (int i = 0; i < n; i++) {
        const double D = pcold(&s->ps, PC_STATE)[(size_t)stride * i + 7];
        if (!(D > 0.5)) continue;
        const double x = x0[id[i]];
        const int c = (int)floor((x - xl) / (0.5 * dx));
        if (c >= 0 && c < 4096) {
            if (!col[c] && getenv("CB_PROFILE")) printf("    past the peak: column at x %.2f mm\n", (xl + (c + 0.5) * 0.5 * dx) * 1e3);
            col[c] = 1;
        }
    }
    for (int c = 0; c < 4096; c++) R.cols += col[c];
    if (getenv("CB_PROFILE")) { /* each column near the middle: its mean D and its work per area */
        const int c0 = (int)floor((0 - xl) / (0.5 * dx));
        for (int c = c0 - 6; c <= c0 + 7; c++) {
            double sd = 0, sw = 0;
            int k = 0;
            for (int i = 0; i < n; i++) {
                const double x = x0[id[i]];
                if ((int)floor((x - xl) / (0.5 * dx)) != c) continue;
                sd += pcold(&s->ps, PC_STATE)[(size_t)stride * i + 7], sw += W[id[i]], k++;
            }
            printf("    column %+d (x %.2f mm): %d particles, mean D %.3f, work %.5f J/m^2\n", c - c0, (xl + (c + 0.5) * 0.5 * dx) * 1e3, k, k ? sd / k : 0, sw / H);
        }
    }
    R.band_cells = R.cols * 0.5;
    R.work_band = wb / H, R.work_all = wa / H;
    const double tt = E_MOD * eps_p; /* the work is per reference volume: f_t in Kirchhoff's tension, tau = J sigma */
    R.g_design = 0.75 * tt * wc;
    R.g_closed = wc / dx > 0.95 * EPS_F ? R.g_design : 0.75 * tt * dx * 0.95 * EPS_F;
    R.ok = R.broken > 0;
    free(W), free(sig), free(Cn), free(x0);
    hearth_scene_destroy(s);
    return R;
}

static void print_run(const band_run *r) {
    printf("  dx %.3f mm: peak force %.4f N/m (f_t H %.4f, ratio %.3f); work per area: band %.5f J/m^2, all %.5f; "
           "closed form G %.5f (band/closed %.3f), designed 0.75 f_t w_c %.5f (band/designed %.3f); band %d columns "
           "= %.1f cells; %d particles at D = 1; %ld steps\n",
           r->dx * 1e3, r->peak_force, r->ft_area, r->peak_force / r->ft_area, r->work_band, r->work_all, r->g_closed,
           r->work_band / r->g_closed, r->g_design, r->work_band / r->g_design, r->cols, r->band_cells, r->broken, r->steps);
}

/* The three bars, once per process: w_c = 0.05 mm (CB_WC to change it, CB_L the gauge length, CB_PROFILE for
 * each column's damage and work), so that w_c / h (0.025, 0.05, 0.1) is above the weak cell's eps_f (0.019) at every
 * dx: a band that can hold G_f at f_t (Bazant & Oh's limit on the element size, h < w_c / eps_f). */
static const double DXS[3] = {2e-3, 1e-3, 5e-4};
static band_run RUNS[3];
static void run_ladder(double wc_default) {
    const double wc = getenv("CB_WC") ? atof(getenv("CB_WC")) : wc_default;
    for (int k = 0; k < 3; k++) {
        RUNS[k] = pull_bar(DXS[k], wc);
        print_run(&RUNS[k]);
    }
}

/* The crack starts at the peak and stays one band wide. Bars (a priori): the peak force within 3% of f_t H at
 * each dx (f_t from the closed form: the pull is quasi-static, grip speed / wave speed ~1e-3, and the Hencky law is
 * exact in tau; 3% for the force read from particle stresses over a gauge a particle short or long); the band
 * (the particles past the peak, D > 0.5) at most 1.5 cells wide, as the crack band assumes one of width h = dx
 * (two particle columns at ppc 4): a wider band is a softening that runs into its neighbours. */
TEST(crack_band_bar_one_band_at_f_t) {
    run_ladder(5e-5);
    for (int k = 0; k < 3; k++) {
        const band_run *r = &RUNS[k];
        CHECK(r->ok);
        CHECK(fabs(r->peak_force / r->ft_area - 1) <= 0.03);
        CHECK(r->band_cells <= 1.5);
    }
}

/* The energy a crack takes per unit area converges to the designed G_f, 0.75 f_t w_c for this bar (the plugin's
 * G_f = f_t w_c / 2 in its stretch measure, which for a uniaxial strain is 2/3 of it: header). Bar (the brief's, a
 * priori): within 10% at the two finest dx (1 and 0.5 mm), and the error at 0.5 mm no larger than at 2 mm. */
TEST(crack_band_work_per_area_converges) {
    run_ladder(5e-5);
    double e[3];
    for (int k = 0; k < 3; k++) e[k] = RUNS[k].work_band / RUNS[k].g_design - 1;
    printf("  work per area / 0.75 f_t w_c - 1: %+.3f (2 mm), %+.3f (1 mm), %+.3f (0.5 mm)\n", e[0], e[1], e[2]);
    CHECK(RUNS[0].ok && RUNS[1].ok && RUNS[2].ok);
    CHECK(fabs(e[1]) <= 0.1 && fabs(e[2]) <= 0.1);
    CHECK(fabs(e[2]) <= fabs(e[0]));
}

/* A cell too large for the band: w_c = 0.01 mm, so w_c / h (0.005, 0.01) is at most eps_f (0.019) at 2 and 1 mm and
 * the point drops at its peak (the plugin's header); its crack takes its elastic energy there, 0.75 f_t h eps_f per
 * area, more than G_f and falling with h, until at 0.5 mm (w_c / h 0.02) the band holds G_f. Bars (a priori): at
 * each dx within 3% of that closed form (the bar above: 4.5% at 2 mm came from a softening the coarse grid
 * resolves worse; here nothing softens), still one cell wide. */
TEST(crack_band_coarse_cell_drops_at_peak) {
    run_ladder(1e-5);
    for (int k = 0; k < 3; k++) {
        const band_run *r = &RUNS[k];
        CHECK(r->ok);
        CHECK(fabs(r->work_band / r->g_closed - 1) <= 0.03);
        CHECK(r->band_cells <= 1.5);
    }
}

TEST_MAIN(T(crack_band_bar_one_band_at_f_t), T(crack_band_work_per_area_converges), T(crack_band_coarse_cell_drops_at_peak))
