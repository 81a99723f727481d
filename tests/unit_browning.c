/* unit_browning.c: the crust's colour (fields/browning.c, Zanoni, Peri &
 * Bruno 1995) in both solvers: the index follows its closed form at a
 * constant temperature, only the surface of a block in an oven browns, and
 * a crust that cools keeps its colour. */
#include <math.h>
#include <string.h>

#include "browning.h"
#include "mpm_fixture.h"
#include "water.h"

/* A 2D scene of either solver with the browning field on, no gravity. */
static hearth_scene *brown_scene(int solver, double dx, double w, double scale, double oven) {
    hearth_scene_def d = hearth_default_scene_def();
    d.solver = solver;
    d.dim = 2;
    d.dx = dx;
    for (int k = 0; k < 3; k++) d.lo[k] = 0, d.hi[k] = w;
    d.gravity[1] = 0;
    d.browning = 1;
    d.browning_scale = scale;
    d.oven_temperature = oven;
    return fx_scene_def(&d);
}

/* A block of material mat at temperature T (degrees C), ppc particles a cell. */
static int brown_block(hearth_scene *s, int mat, const double c[3], const double h[3], int ppc, int fixed, double T) {
    hearth_body_def bd = hearth_default_body_def();
    hearth_shape *b = hearth_shape_box(c, h);
    bd.shape = b;
    bd.material = mat;
    bd.ppc = ppc;
    bd.jitter = 0;
    bd.fixed = fixed;
    bd.temperature = T;
    hearth_error err;
    const int id = hearth_scene_add_body(s, &bd, &err);
    if (id < 0) fprintf(stderr, "body: %s\n", err.msg);
    hearth_shape_free(b);
    return id;
}

static int brown_material(hearth_scene *s, int solver, double cp, double kappa) {
    hearth_error err;
    int m;
    if (solver == HEARTH_SOLVER_SPH) {
        const char *n[] = {"density", "bulk", "viscosity", "specific_heat", "conductivity"};
        const double v[] = {500, 1e4, 1.0, cp, kappa};
        m = hearth_scene_add_material(s, "newtonian", n, v, 5, &err);
    } else {
        const char *n[] = {"E", "nu", "density", "specific_heat", "conductivity"};
        const double v[] = {1e4, 0.3, 500, cp, kappa};
        m = hearth_scene_add_material(s, "elastic", n, v, 5, &err);
    }
    if (m < 0) fprintf(stderr, "material: %s\n", err.msg);
    return m;
}

/* The published numbers, and the rate's own closed form at 200 degC. */
static void check_rate(void) {
    const double k200 = BROWNING_K0 * exp(-BROWNING_EA / (BROWNING_R * 473.15));
    printf("Zanoni et al. 1995: k(100 degC) = %.3e 1/s, k(200 degC) = %.3e 1/s\n", browning_rate(100, 1),
           browning_rate(200, 1));
    CHECK_NEAR(browning_rate(200, 1), k200, 1e-15);
    CHECK(browning_rate(200, 1) > 3.4e-3 && browning_rate(200, 1) < 3.6e-3);
    CHECK(browning_rate(-300, 1) == 0);
    CHECK(browning_water_factor(0.5, 0.5) == 0 && browning_water_factor(0, 0.5) == 1);
    CHECK(browning_water_factor(0.3, WATER_SATURATION_FLOOR) == 1); /* a body given no water is dry */
}

/* At a constant 200 degC the index of every particle is 1 - exp(-k t) to
 * 1e-6, in MPM and in SPH, at two step sizes (the update is exact per step,
 * so dt does not enter). A checkpoint of such a scene is refused, naming
 * the switch. browning_scale 500 makes k = 1.75 1/s so a second
 * of simulated time covers most of the curve. */
TEST(browning_closed_form) {
    check_rate();
    for (int solver = 0; solver < 2; solver++)
        for (int half = 0; half < 2; half++) {
            hearth_scene *s = brown_scene(solver, 0.01, 0.2, 500, NAN);
            CHECK(s != NULL);
            if (!s) return;
            if (half) s->def.dt_max = 5e-4;
            const int m = brown_material(s, solver, 2500, 0.5);
            const double c[3] = {0.1, 0.1, 0}, h[3] = {0.03, 0.03, 0.5};
            CHECK(m >= 0 && brown_block(s, m, c, h, 4, solver == HEARTH_SOLVER_MPM, 200) >= 0);
            CHECK_STR_CONTAINS(hearth_scene_fields(s), "browning");
            hearth_error err;
            CHECK(hearth_scene_advance(s, 1.0, &err) == HEARTH_OK);
            const double k = browning_rate(200, 500), want = 1 - exp(-k * s->t);
            double worst = 0, bmin = 1, bmax = 0;
            double *b = malloc(sizeof(double) * (size_t)(s->ps.n > 0 ? s->ps.n : 1));
            if (!b) return;
            CHECK(hearth_scene_particle_field(s, "browning", b, &err) == HEARTH_OK); /* what Lua and VTU read */
            for (int i = 0; i < s->ps.n; i++) {
                worst = fmax(worst, fabs(b[i] - want));
                bmin = fmin(bmin, b[i]), bmax = fmax(bmax, b[i]);
            }
            free(b);
            printf("%s, dt %s: t = %.4f s after %ld steps, index %.9f..%.9f, closed form %.9f, worst |diff| %.2e\n",
                   solver ? "sph" : "mpm", half ? "<= 5e-4 s" : "stable", s->t, (long)s->step, bmin, bmax, want, worst);
            CHECK(s->ps.n > 0);
            CHECK(worst <= 1e-6);
            hearth_scene_destroy(s);
        }
}

/* A 10 cm square of bread dough baked 20 minutes at 250 degC with
 * beta = 40 W/(m^2 K) (convection and radiation of a hearth oven): kappa =
 * 0.4 W/(m K), rho = 500 kg/m^3, c = 2800 J/(kg K) (alpha = 2.9e-7 m^2/s).
 * The time-scale mapping: dividing c by S = 600 makes heat S times faster
 * (conduction and the Robin flux both scale with 1/(rho c)), so 2 s of
 * simulated time are 20 minutes of bake, and browning_scale = S keeps the
 * kinetics on the same clock. Surface layer mean index above 0.3, the
 * centre particle below 0.05, at dx = 5 mm and 2.5 mm, in either solver:
 * MPM's loaf held still (fixed, 4 particles a cell, its outer layer dx / 2
 * deep); SPH's free (no gravity), one particle a spacing (outer layer dx
 * deep), the oven's beta on its surface particles' faces as on MPM's
 * boundary nodes, and eq. 3.45 inside with k_h,int = kappa / c on the same
 * clock (S kappa / c = 600 x 0.4 / 2800). */
static void surface_not_crumb(int solver) {
    const double S = 600, L = 0.1, cp = 2800, beta = 40, kappa = 0.4;
    const int sph = solver == HEARTH_SOLVER_SPH;
    double surf[2];
    for (int r = 0; r < 2; r++) {
        const double dx = r ? 0.0025 : 0.005, layer = sph ? dx : dx / 2;
        hearth_scene *s = brown_scene(solver, dx, 0.2, S, 250);
        CHECK(s != NULL);
        if (!s) return;
        s->def.oven_beta = beta;
        if (sph) s->def.sph.heat_int = S * kappa / cp;
        const int m = brown_material(s, solver, cp / S, kappa);
        const double c[3] = {0.1, 0.1, 0}, h[3] = {L / 2, L / 2, 0.5};
        CHECK(m >= 0 && brown_block(s, m, c, h, sph ? 1 : 4, !sph, 20) >= 0);
        hearth_error err;
        const hearth_status st = hearth_scene_advance(s, 1200 / S, &err);
        CHECK(st == HEARTH_OK);
        if (st != HEARTH_OK) fprintf(stderr, "advance: %s\n", err.msg);
        const double *x = pcold(&s->ps, PC_X), *T = pcold(&s->ps, PC_TEMPERATURE), *b = pcold(&s->ps, PC_BROWNING);
        double sb = 0, sT = 0, dmin = INFINITY;
        int ns = 0, ic = -1;
        for (int i = 0; i < s->ps.n; i++) {
            const double ex = L / 2 - fabs(x[3 * i] - c[0]), ey = L / 2 - fabs(x[3 * i + 1] - c[1]);
            if (fmin(ex, ey) < layer) sb += b[i], sT += T[i], ns++; /* the outer particle layer */
            const double dc = hypot(x[3 * i] - c[0], x[3 * i + 1] - c[1]);
            if (dc < dmin) dmin = dc, ic = i;
        }
        CHECK(ns > 0 && ic >= 0);
        if (ns == 0 || ic < 0) return;
        surf[r] = sb / ns;
        printf("%s, dx %.4g m: %d particles, bake %.0f s (simulated %.3g s, %ld steps): surface layer (%d) index %.3f "
               "(Delta E %.1f) at %.1f degC; centre index %.2e at %.1f degC\n",
               sph ? "sph" : "mpm", dx, s->ps.n, s->t * S, s->t, (long)s->step, ns, surf[r], surf[r] * BROWNING_DE_INF,
               sT / ns, b[ic], T[ic]);
        CHECK(surf[r] > 0.3);
        CHECK(b[ic] < 0.05);
        hearth_scene_destroy(s);
    }
    printf("surface index change with refinement: %.3f\n", surf[1] - surf[0]);
}

TEST(browning_surface_not_crumb) { surface_not_crumb(HEARTH_SOLVER_MPM); }

/* The same bake in SPH (#18: browning in both solvers). */
TEST(browning_surface_not_crumb_sph) { surface_not_crumb(HEARTH_SOLVER_SPH); }

/* A block browned at 200 degC, then cooled to 20 degC (its temperatures set
 * directly), keeps its colour: the index moves by less than 1e-4 over the
 * next half second, and stays above 0.5, in both solvers. A law of the
 * current temperature (sph.c's eq. 4.6 before) would drop to its raw value. */
TEST(browning_history_not_current) {
    for (int solver = 0; solver < 2; solver++) {
        hearth_scene *s = brown_scene(solver, 0.01, 0.2, 500, NAN);
        CHECK(s != NULL);
        if (!s) return;
        const int m = brown_material(s, solver, 2500, 0.5);
        const double c[3] = {0.1, 0.1, 0}, h[3] = {0.03, 0.03, 0.5};
        CHECK(m >= 0 && brown_block(s, m, c, h, 4, solver == HEARTH_SOLVER_MPM, 200) >= 0);
        hearth_error err;
        CHECK(hearth_scene_advance(s, 0.5, &err) == HEARTH_OK);
        double hot = 0, cold = 0, drift = 0;
        const int n = s->ps.n;
        for (int i = 0; i < n; i++) {
            hot += pcold(&s->ps, PC_BROWNING)[i] / n;
            pcold(&s->ps, PC_TEMPERATURE)[i] = 20;
        }
        double *before = malloc(sizeof(double) * (size_t)n);
        if (!before) return;
        memcpy(before, pcold(&s->ps, PC_BROWNING), sizeof(double) * (size_t)n);
        CHECK(hearth_scene_advance(s, 1.0, &err) == HEARTH_OK);
        for (int i = 0; i < n; i++) {
            const double b = pcold(&s->ps, PC_BROWNING)[i];
            cold += b / n;
            drift = fmax(drift, fabs(b - before[i]));
            CHECK(b >= before[i]); /* never pales */
        }
        printf("%s: index %.6f after 0.5 s at 200 degC, %.6f after 0.5 s more at 20 degC (largest change %.2e)\n",
               solver ? "sph" : "mpm", hot, cold, drift);
        CHECK(hot > 0.5);
        CHECK(drift < 1e-4);
        free(before);
        hearth_scene_destroy(s);
    }
}

/* Water: at a constant 200 degC a body as wet as its dough (s = s_0 = 0.5)
 * does not brown at all, one dried to half its saturation browns at half
 * the rate (1 - exp(-k t / 2) to 1e-6), and a body given no water follows
 * the dry closed form. Water does not move here (no diffusivity, no
 * evaporation), so each particle's factor 1 - s/s_0 stays what it was set to. */
TEST(browning_wet_does_not_brown) {
    hearth_scene *s = brown_scene(HEARTH_SOLVER_MPM, 0.01, 0.3, 500, NAN);
    CHECK(s != NULL);
    if (!s) return;
    const int m = brown_material(s, HEARTH_SOLVER_MPM, 2500, 0.5);
    const double cw[3] = {0.08, 0.1, 0}, cd[3] = {0.22, 0.1, 0}, h[3] = {0.04, 0.04, 0.5};
    hearth_body_def bd = hearth_default_body_def();
    hearth_shape *wet = hearth_shape_box(cw, h), *dry = hearth_shape_box(cd, h);
    bd.material = m, bd.ppc = 4, bd.jitter = 0, bd.fixed = 1, bd.temperature = 200;
    hearth_error err;
    bd.shape = wet, bd.saturation = 0.5;
    CHECK(hearth_scene_add_body(s, &bd, &err) >= 0);
    bd.shape = dry, bd.saturation = 0;
    CHECK(hearth_scene_add_body(s, &bd, &err) >= 0);
    hearth_shape_free(wet), hearth_shape_free(dry);
    CHECK(s->ps.enabled & (1u << PC_WATER));
    int n = s->ps.n;
    for (int i = 0; i < n; i++) /* the wet body's left half dried to s = 0.25 */
        if (pcold(&s->ps, PC_X)[3 * i] < cw[0]) pcold(&s->ps, PC_WATER)[i] *= 0.5;
    CHECK(hearth_scene_advance(s, 1.0, &err) == HEARTH_OK);
    n = s->ps.n;
    const double k = browning_rate(200, 500), t = s->t;
    double e_wet = 0, e_half = 0, e_dry = 0;
    int nw = 0, nh = 0, nd = 0;
    for (int i = 0; i < n; i++) {
        const double x = pcold(&s->ps, PC_X)[3 * i], b = pcold(&s->ps, PC_BROWNING)[i];
        if (x > 0.15) e_dry = fmax(e_dry, fabs(b - (1 - exp(-k * t)))), nd++;
        else if (x < cw[0]) e_half = fmax(e_half, fabs(b - (1 - exp(-0.5 * k * t)))), nh++;
        else e_wet = fmax(e_wet, fabs(b)), nw++;
    }
    printf("t = %.3f s: wet (%d) largest index %.2e; half dried (%d) |diff| %.2e from %.6f; dry (%d) |diff| %.2e from %.6f\n",
           t, nw, e_wet, nh, e_half, 1 - exp(-0.5 * k * t), nd, e_dry, 1 - exp(-k * t));
    CHECK(nw > 0 && nh > 0 && nd > 0);
    CHECK(e_wet <= 1e-12);
    CHECK(e_half <= 1e-6);
    CHECK(e_dry <= 1e-6);
    hearth_scene_destroy(s);
}

/* A browning scene saves and restores: the index, the switch and its scale
 * come back, and both copies go on browning alike (bit for bit). */
TEST(browning_checkpoint_roundtrip) {
    hearth_scene *s = brown_scene(HEARTH_SOLVER_MPM, 0.01, 0.2, 500, 150);
    CHECK(s != NULL);
    if (!s) return;
    const int m = brown_material(s, HEARTH_SOLVER_MPM, 2500, 0.5);
    const double c[3] = {0.1, 0.1, 0}, h[3] = {0.03, 0.03, 0.5};
    CHECK(m >= 0 && brown_block(s, m, c, h, 4, 1, 200) >= 0); /* hot dough cooling in a 150 degC oven */
    hearth_error err;
    CHECK(hearth_scene_advance(s, 0.5, &err) == HEARTH_OK);
    const char *path = "browning_roundtrip.ckpt";
    CHECK(hearth_scene_save(s, path, &err) == HEARTH_OK);
    hearth_scene *r = hearth_scene_load(path, &err);
    if (!r) fprintf(stderr, "load: %s\n", err.msg);
    CHECK(r != NULL);
    if (r) {
        CHECK(r->def.browning == 1 && r->def.browning_scale == 500);
        double most = 0;
        for (int i = 0; i < s->ps.n; i++) most = fmax(most, pcold(&s->ps, PC_BROWNING)[i]);
        CHECK(most > 0.01); /* something to carry over */
        CHECK(hearth_scene_hash(r) == hearth_scene_hash(s));
        CHECK(hearth_scene_step(s, 10, &err) == HEARTH_OK);
        CHECK(hearth_scene_step(r, 10, &err) == HEARTH_OK);
        int same = r->ps.n == s->ps.n;
        for (int i = 0; same && i < s->ps.n; i++) same = pcold(&s->ps, PC_BROWNING)[i] == pcold(&r->ps, PC_BROWNING)[i];
        printf("  largest index %.4f saved; after 10 more steps the copies agree: %s\n", most, same ? "yes" : "no");
        CHECK(same);
        hearth_scene_destroy(r);
    }
    remove(path);
    hearth_scene_destroy(s);
}

/* The browning of the oven's air surface (browning.c's surface_offsets) at 1 and 2 threads: a 2D block of 6400
 * particles (above SCENE_PARALLEL_MIN, so the loops run on both) in a 250 degC oven, 0.5 s at browning_scale 600:
 * the same hash, and the surface offsets live on its outer particles (some nonzero, hotter than their own). */
TEST(browning_surface_threads) {
    uint64_t h[2];
    for (int t = 1; t <= 2; t++) {
        hearth_set_threads(t);
        hearth_scene *s = brown_scene(HEARTH_SOLVER_MPM, 0.0025, 0.2, 600, 250);
        CHECK(s != NULL);
        if (!s) return;
        s->def.oven_beta = 40;
        const int m = brown_material(s, HEARTH_SOLVER_MPM, 2800.0 / 600, 0.4);
        const double c[3] = {0.1, 0.1, 0}, hh[3] = {0.05, 0.05, 0.5};
        CHECK(m >= 0 && brown_block(s, m, c, hh, 4, 1, 20) >= 0);
        CHECK(s->ps.n >= SCENE_PARALLEL_MIN);
        CHECK(s->ps.enabled & (1u << PC_SURFACE));
        hearth_error err;
        CHECK(hearth_scene_advance(s, 0.5, &err) == HEARTH_OK);
        int live = 0;
        for (int i = 0; i < s->ps.n; i++) live += pcold(&s->ps, PC_SURFACE)[2 * i] > 0;
        h[t - 1] = hearth_scene_hash(s);
        printf("  %d thread(s): %d particles, %d read a hotter surface, hash %016llx\n", t, s->ps.n, live, (unsigned long long)h[t - 1]);
        CHECK(live > 0);
        hearth_scene_destroy(s);
    }
    hearth_set_threads(0);
    CHECK(h[0] == h[1]);
}

/* An oven lit after the scene was made (hearth_scene_set_oven, Lua's s:oven) reads the surface as one made with
 * it: the same 1600-particle block in a 250 degC oven (beta 40) for 0.2 s at browning_scale 600, made with the oven
 * and made without one then lit before its bodies and after them: the same hash, and surface offsets live.
 * Before, the column was made only with the scene and the later oven browned every particle at its own
 * temperature (a different hash, no offsets). */
TEST(browning_surface_with_oven_lit_later) {
    uint64_t h[3];
    int live[3];
    for (int k = 0; k < 3; k++) {
        hearth_scene *s = brown_scene(HEARTH_SOLVER_MPM, 0.005, 0.2, 600, k == 0 ? 250 : NAN);
        CHECK(s != NULL);
        if (!s) return;
        hearth_error err;
        if (k == 0) s->def.oven_beta = 40;
        if (k == 1) CHECK(hearth_scene_set_oven(s, 250, 40, &err) == HEARTH_OK);
        const int m = brown_material(s, HEARTH_SOLVER_MPM, 2800.0 / 600, 0.4);
        const double c[3] = {0.1, 0.1, 0}, hh[3] = {0.05, 0.05, 0.5};
        CHECK(m >= 0 && brown_block(s, m, c, hh, 4, 1, 20) >= 0);
        if (k == 2) CHECK(hearth_scene_set_oven(s, 250, 40, &err) == HEARTH_OK);
        CHECK(hearth_scene_advance(s, 0.2, &err) == HEARTH_OK);
        live[k] = 0;
        if (s->ps.enabled & (1u << PC_SURFACE))
            for (int i = 0; i < s->ps.n; i++) live[k] += pcold(&s->ps, PC_SURFACE)[2 * i] > 0;
        h[k] = hearth_scene_hash(s);
        printf("  oven %s: %d particles, %d read a hotter surface, hash %016llx\n",
               k == 0 ? "made with the scene" : k == 1 ? "lit before the bodies" : "lit after the bodies", s->ps.n, live[k],
               (unsigned long long)h[k]);
        hearth_scene_destroy(s);
    }
    CHECK(live[0] > 0 && live[1] == live[0] && live[2] == live[0]);
    CHECK(h[1] == h[0] && h[2] == h[0]);
}

/* What the colour reads (#18, helper crustdry): the fields browning_temperature and browning_saturation are what
 * the kinetics read in the last step, so a scene can print its crust's surface history. Bars set before the first
 * run (17:51 UTC, 2026-12-07; the off-surface count reworded at 17:53, still before it): after one more step every
 * particle's index is browning_advance of its index before, at the rate of the two fields read after the step
 * (|diff| <= 1e-14); on MPM's air surface they are the surface's (some particles read hotter than their own
 * temperature, all below the 250 degC oven, and a wet block's surface reads drier than its particle), every
 * particle off it (its offsets PC_SURFACE both 0) the particle's own, bit for bit; an SPH outer particle reads its
 * face, hotter than itself; without water the saturation is NaN. MPM: a pinned wet block (s 0.2, evaporating,
 * diffusing) in a 250 degC oven, beta 40, 0.3 s at browning_scale 600; SPH: a free block, no water, 0.1 s. */
static void reading_is_what_browns(int solver) {
    const double S = 600;
    const int sph = solver == HEARTH_SOLVER_SPH;
    hearth_scene *s = brown_scene(solver, 0.005, 0.2, S, 250);
    CHECK(s != NULL);
    if (!s) return;
    s->def.oven_beta = 40;
    if (sph) s->def.sph.heat_int = S * 0.4 / 2800;
    hearth_error err;
    int m;
    if (sph) {
        m = brown_material(s, solver, 2800 / S, 0.4);
    } else {
        const char *n[] = {"E", "nu", "density", "specific_heat", "conductivity", "water_diffusivity", "evaporation"};
        const double v[] = {1e4, 0.3, 500, 2800 / S, 0.4, 1e-8 * S, 1.2e-5 * S};
        m = hearth_scene_add_material(s, "elastic", n, v, 7, &err);
    }
    CHECK(m >= 0);
    const double c[3] = {0.1, 0.1, 0}, h[3] = {0.04, 0.04, 0.5};
    hearth_body_def bd = hearth_default_body_def();
    hearth_shape *box = hearth_shape_box(c, h);
    bd.shape = box, bd.material = m, bd.ppc = sph ? 1 : 4, bd.jitter = 0, bd.fixed = !sph, bd.temperature = 20;
    if (!sph) bd.saturation = 0.2;
    const int body = m >= 0 ? hearth_scene_add_body(s, &bd, &err) : -1;
    hearth_shape_free(box);
    CHECK(body >= 0);
    if (body < 0) {
        fprintf(stderr, "set-up: %s\n", err.msg);
        hearth_scene_destroy(s);
        return;
    }
    CHECK(hearth_scene_advance(s, sph ? 0.1 : 0.3, &err) == HEARTH_OK);
    const int n = s->ps.n;
    double *b0 = malloc(sizeof(double) * (size_t)n), *Tr = malloc(sizeof(double) * (size_t)n),
           *sr = malloc(sizeof(double) * (size_t)n), *sown = malloc(sizeof(double) * (size_t)n);
    memcpy(b0, pcold(&s->ps, PC_BROWNING), sizeof(double) * (size_t)n);
    CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
    CHECK(s->ps.n == n);
    CHECK(hearth_scene_particle_field(s, "browning_temperature", Tr, &err) == HEARTH_OK);
    CHECK(hearth_scene_particle_field(s, "browning_saturation", sr, &err) == HEARTH_OK);
    const int wet = (s->ps.enabled & (1u << PC_WATER)) != 0;
    if (wet) CHECK(hearth_scene_particle_field(s, "saturation", sown, &err) == HEARTH_OK);
    const double *T = pcold(&s->ps, PC_TEMPERATURE), *b = pcold(&s->ps, PC_BROWNING);
    /* off the surface: MPM's offsets both 0 (browning.c), SPH's particles not outer (the boundary field: sph_outer.c,
     * where sph_heat.c gives a face temperature) */
    const double *o = (s->ps.enabled & (1u << PC_SURFACE)) ? pcold(&s->ps, PC_SURFACE) : NULL;
    double *face = malloc(sizeof(double) * (size_t)n);
    CHECK(hearth_scene_particle_field(s, "boundary", face, &err) == HEARTH_OK);
    double worst = 0, Tmax = -INFINITY, ds = 0;
    int hotter = 0, own = 0, off = 0, nan_s = 0;
    for (int i = 0; i < n; i++) {
        const double f = wet ? browning_water_factor(sr[i], pcold(&s->ps, PC_SAT0)[i]) : 1.0;
        worst = fmax(worst, fabs(b[i] - browning_advance(b0[i], browning_rate(Tr[i], S) * f, s->dt_last)));
        Tmax = fmax(Tmax, Tr[i]);
        const int on = o ? (o[2 * i] != 0.0 || o[2 * i + 1] != 0.0) : face[i] > 0.5;
        if (on && Tr[i] > T[i]) hotter++;
        if (on && wet) ds = fmin(ds, sr[i] - sown[i]);
        if (!on) off++, own += Tr[i] == T[i] && (!wet || sr[i] == sown[i]);
        nan_s += isnan(sr[i]);
    }
    printf("  %s: %d particles after %.3f s (step dt %.3g s): index against the fields' rate, worst |diff| %.1e; "
           "%d read a hotter surface (hottest %.2f degC), %d of %d off it their own; %s\n",
           sph ? "sph" : "mpm", n, s->t, s->dt_last, worst, hotter, Tmax, own, off,
           wet ? "water live" : "no water");
    if (wet) printf("  the surface's saturation against its particle's, most below: %.4f\n", ds);
    CHECK(worst <= 1e-14);
    CHECK(hotter > 0 && off > 0 && own == off);
    CHECK(Tmax < 250);
    if (wet) CHECK(ds < 0 && nan_s == 0);
    else CHECK(nan_s == n);
    free(b0), free(Tr), free(sr), free(sown), free(face);
    hearth_scene_destroy(s);
}

TEST(browning_reading_is_what_browns) { reading_is_what_browns(HEARTH_SOLVER_MPM); }
TEST(browning_reading_is_what_browns_sph) { reading_is_what_browns(HEARTH_SOLVER_SPH); }

TEST_MAIN(T(browning_closed_form), T(browning_checkpoint_roundtrip), T(browning_surface_not_crumb), T(browning_surface_not_crumb_sph), T(browning_history_not_current),
          T(browning_wet_does_not_brown), T(browning_surface_threads), T(browning_surface_with_oven_lit_later),
          T(browning_reading_is_what_browns), T(browning_reading_is_what_browns_sph))
