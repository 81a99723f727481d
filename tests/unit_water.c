/* unit_water.c: water transport (Ding et al. 2019 §3.2, §5.5, §6.2) against
 * Crank's sheet solution and a fine 1D finite-volume solution, its
 * conservation, the saturation floor, water pressure and the momentum switch. */
#include <math.h>
#include <stdlib.h>
#include <unistd.h>

#include "mpm_fixture.h"
#include "tensor.h"
#include "water.h"
#include "water_reference.h"

#define PI 3.14159265358979323846
#define KELVIN 273.15

/* Crank (1975) eq. 4.18: fraction of the final exchange of a sheet of
 * thickness 2a with both faces held, at Fo = D t / a^2. */
static double crank_sheet(double Fo) {
    double sum = 0;
    for (int n = 0; n < 200; n++) {
        const double k = 2 * n + 1;
        sum += 8 / (k * k * PI * PI) * exp(-k * k * PI * PI * Fo / 4);
    }
    return 1 - sum;
}

TEST(water_crank_reference) {
    CHECK_NEAR(crank_sheet(0.125), 0.398928, 1e-6);
    /* a large L is the held surface; a small one the lumped 1 - exp(-L Fo) */
    CHECK_NEAR(crank_sheet_robin(0.125, 1e5), crank_sheet(0.125), 1e-4);
    CHECK_NEAR(crank_sheet_robin(0.5, 1e-4), 1 - exp(-1e-4 * 0.5), 1e-8);
    printf("  Crank 4.18 at Fo = 0.125: %.6f; 4.54 with L = 1: %.6f at Fo = 0.1, %.6f at Fo = 0.5\n", crank_sheet(0.125),
           crank_sheet_robin(0.1, 1), crank_sheet_robin(0.5, 1));
}

/* A strip |x| < a, pinned, water only; no flux through its top and bottom. */
typedef struct strip {
    hearth_scene *s;
    double a, dx;
} strip;

static strip make_strip(double a, int cells, int rows, const char *const *names, const double *values, int n, double sat) {
    strip st = {NULL, a, a / cells};
    hearth_scene_def d = hearth_default_scene_def();
    const double dx = st.dx;
    d.dx = dx;
    d.gravity[1] = 0;
    d.lo[0] = -a - 6 * dx;
    d.hi[0] = a + 6 * dx;
    d.lo[1] = 0;
    d.hi[1] = (rows + 6) * dx;
    st.s = fx_scene_def(&d);
    hearth_error err;
    const int m = hearth_scene_add_material(st.s, "elastic", names, values, n, &err);
    if (m < 0) fprintf(stderr, "material: %s\n", err.msg);
    CHECK(m >= 0);
    /* `rows` cells high, between a tray and a lid (impermeable plain colliders)
     * just past its bottom and top node rows: the air faces are then `rows`
     * boundary node rows, each carrying dx of surface, exactly the strip's
     * height. (Without them the faces' ends gain or lose about a node row of
     * surface, 1/6 of this strip's: see boundary.c.) */
    const double yc = (0.5 * rows + 3) * dx, c[3] = {0, yc, 0}, h[3] = {a, 0.5 * rows * dx, 0};
    for (int side = -1; side <= 1; side += 2) {
        const double p[3] = {0, yc + side * (0.5 * rows * dx + 0.1 * dx), 0}, nrm[3] = {0, -side, 0};
        hearth_collider_def cd = hearth_default_collider_def();
        cd.shape = hearth_shape_plane(p, nrm);
        hearth_error e2;
        CHECK(hearth_scene_add_collider(st.s, &cd, &e2) >= 0);
        hearth_shape_free((hearth_shape *)cd.shape);
    }
    hearth_shape *box = hearth_shape_box(c, h);
    hearth_body_def b = hearth_default_body_def();
    b.shape = box;
    b.material = m;
    b.jitter = 0;
    b.fixed = 1;
    b.saturation = sat;
    CHECK(hearth_scene_add_body(st.s, &b, &err) >= 0);
    hearth_shape_free(box);
    return st;
}

/* Small contrast: saturation 0.500 inside, faces held at 0.495 by wet
 * colliders touching them, so D = K theta s is constant to 1%. At 80 cells
 * -1.69% before the held faces were reworked (issue #17), -0.13% since
 * (water.c); the ladder is water_sheet_fixed_surface_converges. */
TEST(water_crank_small_contrast) {
    const double a = 0.01, D = 1e-6, th = 20 + KELVIN, sbar = 0.4975;
    const char *nm[] = {"E", "density", "water_diffusivity"};
    const double nv[] = {1e3, 1000, D / (th * sbar)};
    strip st = make_strip(a, 80, 2, nm, nv, 3, 0.5);
    hearth_error err;
    for (int side = -1; side <= 1; side += 2) {
        const double p[3] = {side * a, 0, 0}, nrm[3] = {-side, 0, 0};
        hearth_collider_def cd = hearth_default_collider_def();
        cd.shape = hearth_shape_plane(p, nrm);
        cd.saturation = 0.495;
        CHECK(hearth_scene_add_collider(st.s, &cd, &err) >= 0);
        hearth_shape_free((hearth_shape *)cd.shape);
    }
    hearth_scene *s = st.s;
    const double t_end = 0.125 * a * a / D;
    hearth_stats sts;
    hearth_scene_stats(s, &sts);
    const double W0 = sts.water_mass, Winf = 0.495 / 0.5 * W0;
    CHECK(hearth_scene_advance(s, t_end, &err) == HEARTH_OK);
    hearth_scene_stats(s, &sts);
    const double F = (W0 - sts.water_mass) / (W0 - Winf), exact = crank_sheet(0.125);
    printf("  %d particles, %ld steps: exchanged fraction %.6f, Crank %.6f, relative error %.3g\n", sts.particles, sts.step, F,
           exact, F / exact - 1);
    CHECK(fabs(F / exact - 1) < 0.02);
    hearth_scene_destroy(s);
}

/* ---- Crank's sheet, constant diffusivity, at several resolutions --------
 * The sheet |x| < a exchanges water through both faces: (a) held at S by wet
 * colliders (eq. 4.18), (b) a Robin exchange toward S with L = a alpha / D
 * (eq. 4.54), through wet colliders with beta_water or through the air to a
 * humid oven (evaporation toward oven.saturation). Ding's diffusivity
 * K theta s depends on s; the sheet starts at s0 = 0.5 and goes toward
 * S = 0.5 + 1e-4, so D is constant to 2e-4 (the exchanged fraction's
 * bias from it is below that), far under the errors measured. */
typedef enum { SHEET_HELD, SHEET_COLLIDER_ROBIN, SHEET_OVEN_ROBIN } sheet_bc;

#define SHEET_S0 0.5
#define SHEET_S 0.5001

/* Relative error of the exchanged fraction against Crank's at each Fo[k]
 * (the largest returned), the sheet `cells` cells across half its thickness
 * and `rows` cells high. */
static double sheet_error(sheet_bc bc, int cells, int rows, double L, const double *Fo, int nt) {
    const double a = 0.01, D = 1e-6, th = 20 + KELVIN, rho0 = 1000, alpha = L * D / a;
    const double K = D / (th * 0.5 * (SHEET_S0 + SHEET_S));
    const char *nm[] = {"E", "density", "water_diffusivity", "evaporation"};
    const double nv[] = {1e3, 1000, K, bc == SHEET_OVEN_ROBIN ? alpha * rho0 / th : 0};
    strip st = make_strip(a, cells, rows, nm, nv, bc == SHEET_OVEN_ROBIN ? 4 : 3, SHEET_S0);
    hearth_scene *s = st.s;
    hearth_error err;
    if (bc == SHEET_OVEN_ROBIN) s->def.oven_saturation = SHEET_S; /* the scene's def: what h.scene{oven = ...} sets */
    else
        for (int side = -1; side <= 1; side += 2) {
            const double p[3] = {side * a, 0, 0}, nrm[3] = {-side, 0, 0};
            hearth_collider_def cd = hearth_default_collider_def();
            cd.shape = hearth_shape_plane(p, nrm);
            cd.saturation = SHEET_S;
            if (bc == SHEET_COLLIDER_ROBIN) cd.beta_water = alpha * rho0;
            CHECK(hearth_scene_add_collider(s, &cd, &err) >= 0);
            hearth_shape_free((hearth_shape *)cd.shape);
        }
    hearth_stats sts;
    hearth_scene_stats(s, &sts);
    const double W0 = sts.water_mass, Winf = SHEET_S / SHEET_S0 * W0;
    double worst = 0;
    printf("  %2d cells, %2d rows:", cells, rows);
    for (int k = 0; k < nt; k++) {
        CHECK(hearth_scene_advance(s, Fo[k] * a * a / D, &err) == HEARTH_OK);
        hearth_scene_stats(s, &sts);
        const double F = (sts.water_mass - W0) / (Winf - W0);
        const double exact = bc == SHEET_HELD ? crank_sheet(Fo[k]) : crank_sheet_robin(Fo[k], L);
        printf(" Fo %.2f: %.5f (Crank %.5f, %+.2e)", Fo[k], F, exact, F / exact - 1);
        worst = fmax(worst, fabs(F / exact - 1));
    }
    printf("; %ld steps\n", sts.step);
    hearth_scene_destroy(s);
    return worst;
}

/* The ladder's cells across a: the first `levels` of 10, 20, 40, or
 * WATER_LADDER="10 20 40 80" (scripts/validation/water_ladder.sh runs longer
 * ones). Returns the count. */
static int ladder_cells(int cells[8], int levels) {
    int n = levels;
    cells[0] = 10, cells[1] = 20, cells[2] = 40;
    const char *env = getenv("WATER_LADDER");
    if (env) {
        n = 0;
        for (char *end; n < 8; env = end) {
            const long v = strtol(env, &end, 10);
            if (end == env) break;
            cells[n++] = (int)v;
        }
    }
    return n;
}

/* The ladder: errors at each level and the observed orders between them;
 * returns the order between the last two levels, *finest the last error.
 * The strip is `rows` cells high at every level, or with rows = 0 0.6 a high
 * (its rows refined with its thickness). */
static double sheet_ladder(sheet_bc bc, double L, int rows, int levels, double *finest) {
    int cells[8];
    const int n = ladder_cells(cells, levels);
    CHECK(n >= 2);
    const double Fo[] = {0.05, 0.2};
    double e[8], order = 0;
    for (int k = 0; k < n; k++) e[k] = sheet_error(bc, cells[k], rows > 0 ? rows : (int)lround(0.6 * cells[k]), L, Fo, 2);
    printf("  largest relative errors");
    for (int k = 0; k < n; k++) printf(" %.3e", e[k]);
    printf("; observed orders");
    for (int k = 1; k < n; k++) printf(" %.2f", order = log(e[k - 1] / e[k]) / log((double)cells[k] / cells[k - 1]));
    printf("\n");
    *finest = e[n - 1];
    return order;
}

/* Held faces. Before (S held on every node within dx/2, FLIP beside it, no
 * boundary term for the free nodes): 23.6%, 10.8%, 5.2% low, orders 1.12,
 * 1.04. Now 3.9%, 0.92%, 0.30%, orders 2.07, 1.65 (water.c: held_value,
 * water_face_flux, held_particles); at 80 cells 0.11%, order 1.44: between
 * first and second order (docs/validation.md). */
TEST(water_sheet_fixed_surface_converges) {
    double fine;
    const double order = sheet_ladder(SHEET_HELD, 0, 6, 3, &fine);
    CHECK(order >= 1.2);
    CHECK(fine < 0.005);
}

TEST(water_sheet_robin_converges) {
    double fine;
    printf(" wet colliders, beta_water = rho0 alpha, L = 1:\n");
    const double oc = sheet_ladder(SHEET_COLLIDER_ROBIN, 1.0, 6, 3, &fine); /* 1.8%, 0.32%, 0.043%: orders 2.46, 2.91 */
    CHECK(oc >= 1.8);
    CHECK(fine < 1e-3);
}

/* The same Robin exchange through the air toward a humid oven (evaporation
 * toward oven.saturation, L = 1). The grid samples a surface particle's
 * saturation at a depth d below the surface (boundary.c), and the exchange
 * now goes through the layer between (water_surface_excess, water.h).
 * Before, it took that sample as the surface's: the flux was overstated by
 * 1 + L d / a and the ladder first order (+6.9%, +3.7%, +1.9%, +0.95% at 10,
 * 20, 40, 80 cells, 6 rows; orders 0.90, 0.96, 0.99; on the strip below
 * +6.9%, +3.6%, +1.8%, orders 0.92, 0.98). Now +0.80%, +0.23%, +0.060%
 * (orders 1.77, 1.96).
 *
 * The strip is 0.6 a high here, not 6 rows at every level: beside the tray
 * and the lid a particle's volume fraction misses the collider's side, so
 * its sample depth reads short (0.36 dx rather than 0.55 at the outer row
 * next to them) and its flux is under-corrected. Over two cells of each
 * face that is an O(dx) error on an O(dx / height) share of the surface:
 * second order on a body of fixed size, but first order on a strip whose
 * height shrinks with dx (6 rows: +0.80%, +0.52%, +0.30%, +0.16%).
 * WATER_OVEN_ROWS=6 runs that ladder (scripts/validation/water_ladder.sh)
 * and then does not check the order. */
TEST(water_humid_oven_converges) {
    double fine;
    const char *env = getenv("WATER_OVEN_ROWS");
    const int rows = env ? atoi(env) : 0;
    printf(" humid oven, evaporation toward oven.saturation, L = 1, the strip %s:\n", rows > 0 ? "of fixed rows" : "0.6 a high");
    const double order = sheet_ladder(SHEET_OVEN_ROBIN, 1.0, rows, 3, &fine); /* 2.2 s on one thread */
    if (rows > 0) return; /* the contact corners' share is fixed: for the docs, not a convergence claim */
    printf("  observed order between the last two levels %.2f (at least 1.5 checked), finest error %.2e (below 1e-3 checked)\n", order,
           fine);
    CHECK(order >= 1.5);
    CHECK(fine < 1e-3);
}

/* The same held and Robin sheets in 3D (the held nodes' extension and the
 * face flux walk 3^3 stencils there): a slab |x| < a, 4 cells square, its
 * other faces free (no evaporation: no flux), 10 cells across a, against
 * Crank at Fo = 0.2 and against the 2D sheet's error at the same resolution. */
static double sheet3d_error(int robin) {
    const double a = 0.01, D = 1e-6, th = 20 + KELVIN, dx = a / 10, L = 1.0;
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = 3, d.dx = dx, d.gravity[1] = 0;
    d.lo[0] = -a - 6 * dx, d.hi[0] = a + 6 * dx;
    for (int k = 1; k < 3; k++) d.lo[k] = 0, d.hi[k] = 12 * dx;
    hearth_scene *s = fx_scene_def(&d);
    const char *nm[] = {"E", "density", "water_diffusivity"};
    const double nv[] = {1e3, 1000, D / (th * 0.5 * (SHEET_S0 + SHEET_S))};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "elastic", nm, nv, 3, &err);
    CHECK(m >= 0);
    for (int side = -1; side <= 1; side += 2) {
        const double p[3] = {side * a, 0, 0}, nrm[3] = {-side, 0, 0};
        hearth_collider_def cd = hearth_default_collider_def();
        cd.shape = hearth_shape_plane(p, nrm);
        cd.saturation = SHEET_S;
        if (robin) cd.beta_water = L * D / a * 1000;
        CHECK(hearth_scene_add_collider(s, &cd, &err) >= 0);
        hearth_shape_free((hearth_shape *)cd.shape);
    }
    const double c[3] = {0, 6 * dx, 6 * dx}, h[3] = {a, 2 * dx, 2 * dx};
    hearth_shape *box = hearth_shape_box(c, h);
    hearth_body_def b = hearth_default_body_def();
    b.shape = box, b.material = m, b.jitter = 0, b.fixed = 1, b.saturation = SHEET_S0;
    CHECK(hearth_scene_add_body(s, &b, &err) >= 0);
    hearth_shape_free(box);
    hearth_stats sts;
    hearth_scene_stats(s, &sts);
    const double W0 = sts.water_mass, Winf = SHEET_S / SHEET_S0 * W0;
    CHECK(hearth_scene_advance(s, 0.2 * a * a / D, &err) == HEARTH_OK);
    hearth_scene_stats(s, &sts);
    const double F = (sts.water_mass - W0) / (Winf - W0), exact = robin ? crank_sheet_robin(0.2, L) : crank_sheet(0.2);
    printf("  3D %s, 10 cells, %d particles, %ld steps: %.5f against Crank %.5f (%+.2e)\n", robin ? "Robin" : "held", sts.particles,
           sts.step, F, exact, F / exact - 1);
    hearth_scene_destroy(s);
    return F / exact - 1;
}

TEST(water_sheet_3d_matches_2d) {
    const double Fo[] = {0.2};
    for (int robin = 0; robin <= 1; robin++) {
        const double e2 = sheet_error(robin ? SHEET_COLLIDER_ROBIN : SHEET_HELD, 10, 6, 1.0, Fo, 1), e3 = sheet3d_error(robin);
        /* the 2D sheet's errors at Fo = 0.2, 10 cells: held 0.99%, Robin 0.51% (sheet_error gives |error|);
         * 3D solves the same 1D problem: held 1.07%, Robin 0.47% */
        CHECK(fabs(fabs(e3) - e2) < 2e-3);
    }
}


/* Drying through the evaporation boundary (toward s = 0): the strip |x| < a,
 * `cells` across a and `rows` high, beta^w theta = L rho_0 K theta / a.
 * drying_reference fills fd with the 1D solution's remaining fraction at t =
 * 25, 75, 150 s (7500 implicit steps on 2000 cells, about a second);
 * drying_error prints the strip's against it and returns the largest
 * relative difference. */
#define DRY_A 0.01
#define DRY_KTH 1e-6
#define DRY_S0 0.8
static const double dry_times[3] = {25, 75, 150};

static void drying_reference(double L, double fd[3]) {
    /* dt 0.02 s: within 2e-5 of dt 0.005 s at every check time, at a quarter of the cost */
    drying_fd(2000, DRY_A, DRY_KTH, L * 1000 * DRY_KTH / DRY_A, 1000, DRY_S0, dry_times, 3, fd, 0.02);
}

static double drying_error(double L, int cells, int rows, const double fd[3]) {
    const double a = DRY_A, th = 20 + KELVIN, Kth = DRY_KTH, rho0 = 1000, bth = L * rho0 * Kth / a;
    const char *nm[] = {"E", "density", "water_diffusivity", "evaporation"};
    const double nv[] = {1e3, 1000, Kth / th, bth / th};
    strip st = make_strip(a, cells, rows, nm, nv, 4, DRY_S0);
    hearth_scene *s = st.s;
    const double *times = dry_times;
    hearth_stats sts;
    hearth_scene_stats(s, &sts);
    const double W0 = sts.water_mass;
    hearth_error err;
    double worst = 0;
    for (int k = 0; k < 3; k++) {
        CHECK(hearth_scene_advance(s, times[k], &err) == HEARTH_OK);
        hearth_scene_stats(s, &sts);
        const double got = sts.water_mass / W0;
        printf("  t = %5.1f s: water remaining %.5f, 1D finite volumes %.5f, relative difference %.3g (lost %.4g of %.4g kg/m)\n",
               times[k], got, fd[k], got / fd[k] - 1, sts.water_lost, W0);
        worst = fmax(worst, fabs(got / fd[k] - 1));
        /* what left is what the boundary took: the books balance */
        CHECK_NEAR(sts.water_mass + sts.water_lost, W0, 1e-12 * W0);
    }
    printf("  L = %g, %d cells, %d rows, %d particles, %ld steps; worst relative difference %.3g\n", L, cells, rows, sts.particles,
           sts.step, worst);
    hearth_scene_destroy(s);
    return worst;
}

/* Full drying, L = 0.5, 40 cells, 6 rows. 0.00958 before the evaporation went
 * through the sample's depth (water_surface_excess), 0.00141 since. */
TEST(water_drying_vs_fd) {
    double fd[3];
    drying_reference(0.5, fd);
    const double worst = drying_error(0.5, 40, 6, fd);
    CHECK(fd[2] < 0.7); /* the test dries the sheet substantially */
    CHECK(worst < 0.02);
}

/* Fast drying, L = 5: the surface dries out and the exchange is limited by
 * what diffusion (D = K theta s, small where it is dry) brings through the
 * layer between the sample and the surface, which the quadratic in
 * water_surface_excess (s^2/2 linear across the layer) carries. The strip is
 * 0.6 a high, as in water_humid_oven_converges. Largest differences at 10, 20
 * cells: without the depth 24%, 11%; with the coefficient beta^w theta / (1 +
 * a / s_d), linear in s, 8.0%, 3.0%; with the quadratic 2.9%, 0.65%. */
TEST(water_drying_fast_vs_fd) {
    double fd[3], e[8];
    int cells[8];
    const int n = ladder_cells(cells, 2); /* 10, 20; the script adds 40 (0.41%) */
    CHECK(n >= 2);
    drying_reference(5.0, fd);
    for (int k = 0; k < n; k++) e[k] = drying_error(5.0, cells[k], (int)lround(0.6 * cells[k]), fd);
    printf("  largest relative differences");
    for (int k = 0; k < n; k++) printf(" %.3e", e[k]);
    printf("; observed orders");
    for (int k = 1; k < n; k++) printf(" %.2f", log(e[k - 1] / e[k]) / log((double)cells[k] / cells[k - 1]));
    const double order = log(e[0] / e[1]) / log((double)cells[1] / cells[0]);
    printf("\n  first order %.2f (at least 1 checked); finest %.3g (below 0.01 checked), each level below the last\n", order, e[n - 1]);
    CHECK(fd[2] < 0.4); /* most of the water leaves */
    CHECK(order >= 1.0);
    for (int k = 1; k < n; k++) CHECK(e[k] < e[k - 1]);
    CHECK(e[n - 1] < 0.01);
}

/* Bulk diffusion: a sine mode between insulated faces decays as
 * exp(-D (pi/L)^2 t), L the sheet's thickness. Returns the relative error of
 * its amplitude after one decay time, the sheet `cells` cells across a. */
static double mode_error(int cells) {
    const double a = 0.01, D = 1e-6, th = 20 + KELVIN, amp = 1e-4;
    const char *nm[] = {"E", "density", "water_diffusivity"};
    const double nv[] = {1e3, 1000, D / (th * 0.5)};
    strip st = make_strip(a, cells, 2, nm, nv, 3, 0.5);
    hearth_scene *s = st.s;
    const double kx = PI / (2 * a);
    for (int i = 0; i < s->ps.n; i++) {
        const double x = pcold(&s->ps, PC_X)[3 * i];
        pcold(&s->ps, PC_WATER)[i] *= 1 + amp / 0.5 * sin(kx * x);
    }
    const double t_end = 1.0 / (D * kx * kx);
    hearth_error err;
    CHECK(hearth_scene_advance(s, t_end, &err) == HEARTH_OK);
    double num = 0, den = 0;
    for (int i = 0; i < s->ps.n; i++) {
        const double x = pcold(&s->ps, PC_X)[3 * i], sx = sin(kx * x);
        num += (water_saturation(s, i) - 0.5) * sx;
        den += sx * sx;
    }
    const double got = num / den / amp, exact = exp(-1.0);
    printf("  %2d cells: mode amplitude after one decay time %.6f, exact %.6f, relative error %+.3e\n", cells, got, exact,
           got / exact - 1);
    hearth_scene_destroy(s);
    return fabs(got / exact - 1);
}

/* The interior's order: the same mode at 10, 20, 40 cells across a (the
 * faces are insulated: no boundary condition to spoil it). Second order, as
 * heat's: 9.7e-3, 2.4e-3, 6.1e-4. */
TEST(water_interior_mode_second_order) {
    int cells[8];
    const int n = ladder_cells(cells, 3);
    CHECK(n >= 2);
    double e[8], lowest = 9;
    for (int k = 0; k < n; k++) e[k] = mode_error(cells[k]);
    printf("  observed orders");
    for (int k = 1; k < n; k++) {
        const double o = log(e[k - 1] / e[k]) / log((double)cells[k] / cells[k - 1]);
        printf(" %.2f", o);
        lowest = fmin(lowest, o);
    }
    printf("\n");
    CHECK(lowest > 1.8);
    CHECK(e[n - 1] < 1e-3);
}

/* Two fixed elastic blocks side by side, no gravity, dx 1/32: the left one
 * wet (s = 0.9), the right one dry (s = 0.1). */
static hearth_scene *wet_beside_dry(void) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 1.0 / 32;
    d.gravity[1] = 0;
    hearth_scene *s = fx_scene_def(&d);
    const char *nm[] = {"E", "density", "water_diffusivity"};
    const double nv[] = {1e3, 1000, 1e-5};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "elastic", nm, nv, 3, &err);
    CHECK(m >= 0);
    const double c1[3] = {0.4, 0.5, 0}, c2[3] = {0.6, 0.5, 0}, h[3] = {0.1, 0.15, 0};
    hearth_shape *b1 = hearth_shape_box(c1, h), *b2 = hearth_shape_box(c2, h);
    hearth_body_def bd = hearth_default_body_def();
    bd.fixed = 1, bd.material = m;
    bd.shape = b1, bd.saturation = 0.9;
    CHECK(hearth_scene_add_body(s, &bd, &err) >= 0);
    bd.shape = b2, bd.saturation = 0.1;
    CHECK(hearth_scene_add_body(s, &bd, &err) >= 0);
    hearth_shape_free(b1);
    hearth_shape_free(b2);
    return s;
}

/* Diffusion alone moves water and never makes or loses any. */
TEST(water_conservation) {
    hearth_scene *s = wet_beside_dry();
    hearth_error err;
    hearth_stats st;
    hearth_scene_stats(s, &st);
    const double w0 = st.water_mass;
    double worst = 0, smin = 1, smax = 0;
    for (int k = 0; k < 1000; k++) {
        CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
        hearth_scene_stats(s, &st);
        worst = fmax(worst, fabs(st.water_mass / w0 - 1));
    }
    for (int i = 0; i < s->ps.n; i++) {
        const double si = water_saturation(s, i);
        smin = fmin(smin, si);
        smax = fmax(smax, si);
    }
    printf("  1000 steps of %.3g s: max |W/W0 - 1| = %.3g; saturation now in [%.4f, %.4f]; water lost %.3g\n", st.dt, worst,
           smin, smax, st.water_lost);
    CHECK(worst < 1e-12);
    CHECK(fabs(st.water_lost) < 1e-12 * w0);
    CHECK(smin > 0.1 && smax < 0.9); /* the two blocks exchanged water */
    hearth_scene_destroy(s);
}

/* Water's flux runs over a particle's quadrature volume J V_0, as heat's
 * conduction does, but unlike heat (whose capacity m alpha = rho_0 alpha V_0
 * is fixed, so a swollen particle's diffusivity is J times the material's and
 * forward Euler needed transport.c's cap, lone_hot_particles_stay_bounded) its
 * capacity scales with J too: a node's saturation is m_i / (rho_0 V_i) with
 * V_i = sum_p w_ip J_p V_0,p, and a particle takes rho_0 J_p V_0,p sum_i w_ip
 * ds_i. So the saturation's diffusivity is K theta s whatever J is, and
 * water_dt_limit's dx^2 / (2 dim D) holds without a cap. Checked here: the
 * water_conservation blocks with the wet one swollen to J = 1e6 and 1e30 (a
 * lone molten particle of marshmallow.lua reached 1e30 before eq. 10 became a
 * strain) at the same water content s, at the scene's own step. Derived
 * outside the code: J cancels, so the two runs give the same saturations
 * (to 0.01: their steps differ by 0.1%, and at 1e6 the dry block still
 * weighs 1e-6 in the shared nodes), and the water is conserved; a forward Euler runaway (heat's was
 * x4 a step) would grow without end, so the largest change of any particle's
 * saturation in one step must not grow from steps 451-500 to steps 951-1000
 * (windows, so a multirate cycle's field step falls in each). It was "the
 * largest saturation must not grow from step 500 to 1000", which read the
 * bounded overshoot below: that plateau wanders between particles on the
 * diffusion's time scale (seeded with seeds 2-5 it still rose 0.0001-0.023 from
 * step 500 to 1000; run to 40000 steps, seeds 3 and 5 settled at 1.151 and 1.173:
 * docs/validation.md, "Tests that flip with the seeding"). The change per step
 * falls 4.4 to 34 times over the ten samplings (seeds 1-5, jittered and
 * smooth_surface); with the water's field step forced to 16 steps (field_steps
 * 16, past its explicit limit: a local build, not kept) it rose from 0.24 to
 * 1.0 at J 1e30 and the check failed, as it must (at J 1e6 the saturations hit
 * their floor at once, 1.8 a step in both windows, and conservation failed). Not asserted, printed: the dry particles next to
 * the swollen block overshoot the 0.9 they draw from (1.18 here, 1.03 at
 * J = 10, none at 2): a bounded plateau of the particle transfer at a sharp
 * volume contrast, which a cap on the flux volume would not touch (the
 * capacity V_i is the swollen one's). */
TEST(water_swollen_particles_no_runaway) {
    const double Js[2] = {1e6, 1e30};
    double ends[2][2] = {{0}};
    for (int k = 0; k < 2; k++) {
        hearth_scene *s = wet_beside_dry();
        hearth_error err;
        /* swell the wet block (F = J^(1/2) in the plane) and give it the water of s = 0.9 at that volume */
        particles *ps = &s->ps;
        const int tn = particles_tn(ps);
        double *F = pcold(ps, PC_F), *W = pcold(ps, PC_WATER);
        int swollen = 0;
        for (int i = 0; i < ps->n; i++) {
            if (pcold(ps, PC_X)[3 * i] > 0.5) continue;
            const double r = sqrt(Js[k]);
            double *f = F + (size_t)tn * i;
            for (int c = 0; c < tn; c++) f[c] = 0;
            f[0] = r, f[tn == 4 ? 3 : 4] = r;
            if (tn == 9) f[8] = 1;
            W[i] *= Js[k];
            swollen++;
        }
        hearth_stats st;
        hearth_scene_stats(s, &st);
        const double w0 = st.water_mass;
        double worst = 0, smin = 1, smax = 0, smax500 = 0, rate[2] = {0, 0};
        int finite = 1;
        double *prev = malloc(sizeof *prev * (size_t)ps->n);
        CHECK(prev != NULL);
        for (int n = 1; n <= 1000; n++) {
            const int window = (n > 500 - 50 && n <= 500) || n > 1000 - 50; /* the 50 steps to 500 and to 1000 */
            if (window)
                for (int i = 0; i < ps->n; i++) prev[i] = water_saturation(s, i);
            CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
            hearth_scene_stats(s, &st);
            worst = fmax(worst, fabs(st.water_mass / w0 - 1));
            if (window)
                for (int i = 0; i < ps->n; i++) rate[n > 500] = fmax(rate[n > 500], fabs(water_saturation(s, i) - prev[i]));
            if (n != 500 && n != 1000) continue;
            smin = 1, smax = 0;
            for (int i = 0; i < ps->n; i++) {
                const double si = water_saturation(s, i);
                finite &= isfinite(si);
                smin = fmin(smin, si);
                smax = fmax(smax, si);
            }
            if (n == 500) smax500 = smax;
        }
        free(prev);
        ends[k][0] = smin, ends[k][1] = smax;
        printf("  J %.0e on %d of %d particles, 1000 steps of %.3g s: saturation in [%.6f, %.6f] (largest %.6f at step "
               "500; it started in [0.1, 0.9]); max |W/W0 - 1| = %.3g; the largest change of a particle's saturation "
               "in one step: %.3g over steps 451-500, %.3g over steps 951-1000\n",
               Js[k], swollen, ps->n, st.dt, smin, smax, smax500, worst, rate[0], rate[1]);
        CHECK(finite);
        CHECK(worst < 1e-9);
        CHECK(rate[1] <= rate[0]);
        hearth_scene_destroy(s);
    }
    printf("  J 1e6 against 1e30: saturation extremes differ by %.3g and %.3g\n", fabs(ends[1][0] - ends[0][0]),
           fabs(ends[1][1] - ends[0][1]));
    CHECK(fabs(ends[1][0] - ends[0][0]) < 1e-2 && fabs(ends[1][1] - ends[0][1]) < 1e-2);
}

/* Fierce evaporation: saturation stops at the documented floor, never at 0 or NaN.
 * The material has no diffusivity, so each surface particle dries at the
 * full beta^w theta s of its own area. With diffusion (K = 1e-6, as this test
 * had) the exchange now goes through the layer between the grid's sample and
 * the surface and is limited by what diffusion brings to a drying surface
 * (water_surface_excess): after these steps the driest particle holds 0.0222
 * (it reached the floor when the sample was taken for the surface), so the
 * floor would not be reached. */
TEST(water_saturation_floor) {
    const char *nm[] = {"E", "density", "water_diffusivity", "evaporation"};
    const double nv[] = {1e3, 1000, 0, 10};
    strip st = make_strip(0.005, 10, 6, nm, nv, 4, 0.3);
    hearth_error err;
    CHECK(hearth_scene_step(st.s, 4000, &err) == HEARTH_OK);
    double smin = 1;
    int finite = 1;
    for (int i = 0; i < st.s->ps.n; i++) {
        const double si = water_saturation(st.s, i);
        finite &= isfinite(si);
        smin = fmin(smin, si);
    }
    hearth_stats sts;
    hearth_scene_stats(st.s, &sts);
    printf("  after %ld steps (%.3g s): smallest saturation %.3g (floor %.1g), water left %.3g kg/m\n", sts.step, sts.t, smin,
           WATER_SATURATION_FLOOR, sts.water_mass);
    CHECK(finite);
    CHECK(smin >= WATER_SATURATION_FLOOR * (1 - 1e-12));
    CHECK(smin < 2 * WATER_SATURATION_FLOOR); /* it did reach the floor */
    hearth_scene_destroy(st.s);
}

/* A free block dries in the air; water pressure (eq. 14) pulls it in.
 * Returns the volume history sampled every `every` steps. */
static int drying_block(int momentum, int nsamples, int every, double *vol, double *water) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.002;
    d.lo[0] = d.lo[1] = 0;
    d.hi[0] = 0.1;
    d.hi[1] = 0.04;
    d.water_momentum = momentum;
    d.gravity[1] = 0; /* no settling: the water alone moves it */
    hearth_scene *s = fx_scene_def(&d);
    const char *nm[] = {"E", "nu", "density", "water_diffusivity", "evaporation", "water_stiffness"};
    const double nv[] = {2e4, 0.3, 1100, 2e-6 / (20 + KELVIN), 1.1 / (20 + KELVIN), 1e5};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "elastic", nm, nv, 6, &err);
    const double c[3] = {0.05, 0.02, 0}, h[3] = {0.03, 0.008, 0};
    hearth_shape *box = hearth_shape_box(c, h);
    hearth_body_def b = hearth_default_body_def();
    b.shape = box, b.material = m, b.saturation = 0.7, b.jitter = 0;
    int ok = m >= 0 && hearth_scene_add_body(s, &b, &err) >= 0;
    hearth_shape_free(box);
    for (int k = 0; ok && k < nsamples; k++) {
        ok = hearth_scene_step(s, every, &err) == HEARTH_OK;
        double v = 0;
        for (int i = 0; i < s->ps.n; i++) v += pcold(&s->ps, PC_VOL0)[i] * particles_J(&s->ps, i);
        vol[k] = v;
        hearth_stats st;
        hearth_scene_stats(s, &st);
        water[k] = st.water_mass;
    }
    if (!ok) fprintf(stderr, "drying block: %s\n", err.msg);
    hearth_scene_destroy(s);
    return ok;
}

TEST(water_drying_shrinks) {
    enum { NS = 12 };
    double vol[NS], water[NS];
    CHECK(drying_block(0, NS, 400, vol, water));
    int mono = 1;
    for (int k = 1; k < NS; k++) mono &= vol[k] < vol[k - 1] && water[k] < water[k - 1];
    printf("  volume %.5g -> %.5g m^2 (%.2f%%) while water %.4g -> %.4g kg/m; monotone: %s\n", vol[0], vol[NS - 1],
           100 * (vol[NS - 1] / vol[0] - 1), water[0], water[NS - 1], mono ? "yes" : "no");
    CHECK(mono);
    CHECK(vol[NS - 1] < 0.99 * vol[0]);
}

/* The relative water momentum (eq. 26-27) is a switch; on a drying block it
 * changes the result, and only a little (the flux is slow). */
TEST(water_momentum_switch) {
    enum { NS = 6 };
    double v0[NS], w0[NS], v1[NS], w1[NS];
    CHECK(drying_block(0, NS, 400, v0, w0));
    CHECK(drying_block(1, NS, 400, v1, w1));
    const double dv = v1[NS - 1] / v0[NS - 1] - 1, dw = w1[NS - 1] / w0[NS - 1] - 1;
    printf("  after %d steps: volume off %.8g, on %.8g (relative %.3g); water off %.8g, on %.8g (relative %.3g)\n", NS * 400,
           v0[NS - 1], v1[NS - 1], dv, w0[NS - 1], w1[NS - 1], dw);
    CHECK(isfinite(dv) && isfinite(dw));
    CHECK(dv != 0);
    CHECK(fabs(dv) < 1e-2);
}

/* The fields are live only with water, and say how to turn them on. */
TEST(water_probe_fields) {
    hearth_scene *s = fx_scene(2, 0.02, 0, 1);
    const int m = fx_elastic(s, 1e4, 0.3, 1000);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.1, 0.1, 0};
    CHECK(fx_box(s, m, c, h, 4, NULL) > 0);
    double out[3];
    hearth_error err;
    CHECK(hearth_probe_point(s, "saturation", c, out, &err) != HEARTH_OK);
    CHECK_STR_CONTAINS(err.msg, "saturation = 0.5");
    hearth_scene_destroy(s);

    const char *nm[] = {"E", "density", "water_stiffness", "saturation"};
    const double nv[] = {1e4, 1000, 1e4, 0.35};
    s = fx_scene(2, 0.02, 0, 1);
    const int m2 = hearth_scene_add_material(s, "elastic", nm, nv, 4, &err);
    CHECK(m2 >= 0);
    CHECK(fx_box(s, m2, c, h, 4, NULL) > 0);
    CHECK(strstr(hearth_scene_fields(s), "saturation") != NULL);
    CHECK(hearth_probe_point(s, "saturation", c, out, &err) == HEARTH_OK);
    CHECK_NEAR(out[0], 0.35, 1e-12);
    CHECK(hearth_probe_point(s, "water_pressure", c, out, &err) == HEARTH_OK);
    CHECK_NEAR(out[0], 0, 1e-9);
    CHECK(hearth_probe_point(s, "water_mass", c, out, &err) == HEARTH_OK);
    CHECK_NEAR(out[0], 350, 1e-9); /* kg of water per m^3 */
    hearth_scene_destroy(s);
}

/* Bad input names the parameter and its range. */
TEST(water_bad_input) {
    hearth_scene *s = fx_scene(2, 0.02, 0, 1);
    const int m = fx_elastic(s, 1e4, 0.3, 1000);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.1, 0.1, 0};
    hearth_shape *box = hearth_shape_box(c, h);
    hearth_body_def b = hearth_default_body_def();
    b.shape = box, b.material = m, b.saturation = 1.5;
    hearth_error err;
    CHECK(hearth_scene_add_body(s, &b, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "saturation = 1.5; valid range [0, 1]");
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = box;
    cd.saturation = -0.1;
    CHECK(hearth_scene_add_collider(s, &cd, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "collider saturation = -0.1; valid range [0, 1]");
    cd.saturation = 0.5, cd.beta_water = -1;
    CHECK(hearth_scene_add_collider(s, &cd, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "collider beta_water = -1 kg/(m^2 s); valid range [0, inf)");
    cd.saturation = NAN, cd.beta_water = 0.1; /* an exchange needs the saturation it goes toward */
    CHECK(hearth_scene_add_collider(s, &cd, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "collider beta_water = 0.1 kg/(m^2 s) needs the collider's saturation");
    hearth_scene_def d = hearth_default_scene_def();
    d.oven_saturation = 1.2;
    CHECK(hearth_scene_create(&d, &err) == NULL);
    CHECK_STR_CONTAINS(err.msg, "oven.saturation");
    const char *nm[] = {"evaporation"};
    const double nv[] = {-1};
    CHECK(hearth_scene_add_material(s, "elastic", nm, nv, 1, &err) < 0);
    CHECK_STR_CONTAINS(err.msg, "evaporation");
    hearth_shape_free(box);
    hearth_scene_destroy(s);
}

/* A run with water saved and restored continues bit-identically, a humid
 * oven and a Robin wet collider included. */
TEST(water_checkpoint_restore) {
    const char *nm[] = {"E", "density", "water_diffusivity", "evaporation", "water_stiffness"};
    const double nv[] = {1e3, 1000, 1e-8, 1e-4, 1e3};
    strip st = make_strip(0.005, 10, 6, nm, nv, 5, 0.6);
    hearth_error err;
    st.s->def.oven_saturation = 0.3;
    const double p[3] = {0.005, 0, 0}, nrm[3] = {-1, 0, 0};
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = hearth_shape_plane(p, nrm);
    cd.saturation = 0.9;
    cd.beta_water = 1e-3;
    CHECK(hearth_scene_add_collider(st.s, &cd, &err) >= 0);
    hearth_shape_free((hearth_shape *)cd.shape);
    CHECK(hearth_scene_step(st.s, 50, &err) == HEARTH_OK);
    char path[] = "/tmp/hearth_water_ckXXXXXX";
    const int fd = mkstemp(path);
    CHECK(fd >= 0);
    close(fd);
    CHECK(hearth_scene_save(st.s, path, &err) == HEARTH_OK);
    CHECK(hearth_scene_step(st.s, 50, &err) == HEARTH_OK);
    hearth_scene *r = hearth_scene_load(path, &err);
    CHECK(r != NULL);
    if (r) {
        CHECK(hearth_scene_step(r, 50, &err) == HEARTH_OK);
        CHECK(hearth_scene_hash(r) == hearth_scene_hash(st.s));
        hearth_stats a, b;
        hearth_scene_stats(r, &a);
        hearth_scene_stats(st.s, &b);
        CHECK(a.water_lost == b.water_lost);
        CHECK(r->def.oven_saturation == 0.3);
        CHECK(r->cols[r->ncol - 1].beta_water == 1e-3);
        hearth_scene_destroy(r);
    }
    remove(path);
    hearth_scene_destroy(st.s);
}

TEST_MAIN(T(water_crank_reference), T(water_crank_small_contrast), T(water_sheet_fixed_surface_converges),
          T(water_sheet_robin_converges), T(water_humid_oven_converges), T(water_sheet_3d_matches_2d), T(water_drying_vs_fd), T(water_drying_fast_vs_fd), T(water_interior_mode_second_order), T(water_conservation), T(water_swollen_particles_no_runaway),
          T(water_saturation_floor), T(water_drying_shrinks), T(water_momentum_switch), T(water_probe_fields),
          T(water_bad_input), T(water_checkpoint_restore))
