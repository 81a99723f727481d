/* unit_dry_heat.c: a dried crust holds less heat (issue #18, dry_specific_heat).
 *
 * The closed form the tests derive: a particle's mass m stays the wet dough's,
 * and the mixture rule for its solids m_s and the water w it holds,
 *   m alpha(w) = m_s c_s + w c_w,
 * is linear in w: alpha(w) = alpha_d + (alpha - alpha_d) r, r = w / w0 the
 * water it holds over the water it was made with (w0 = s_0 rho^w V_0), alpha
 * the material's specific_heat and alpha_d = m_s c_s / m its dry_specific_heat.
 * The temperature equation alpha(w) m dtheta/dt = heat in - L x water
 * evaporated (water leaves at the particle's temperature with its own
 * sensible heat) integrates to the books
 *   heat in = sum_p integral m_p alpha(w_p) dtheta_p + L x water lost,
 * and a body whose water stays put heats by dtheta = Q / (sum_p m_p alpha(w_p))
 * on the mass-weighted mean: a dried body (r = 0) Q / (M alpha_d), a half-dried
 * one at alpha's midpoint, a wet one Q / (M alpha). Each test computes alpha(w)
 * from the particle's water column with this rule, not with the code's. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "mpm_fixture.h"
#include "thermal.h"
#include "water.h"

#define KELVIN 273.15
/* h.library.dough.bread's numbers (lua/hearth/dough_physical.lua) with its time scale S = 300: heat and water
 * 300 times fast, so 5 s is its 25 minute bake */
#define S_FAST 300.0
static const double RHO = 484, C_WET = 2700, C_DRY = 0.55 * 1650, KAPPA = 0.51 * S_FAST, SAT = 0.218;
static const double OVEN_T = 200, OVEN_BETA = 30 * S_FAST, EVAP = 1.2e-5 * S_FAST, WATER_K = 2e-9 / (373.15 * 0.218) * S_FAST;

/* The rule above, from particle i's own columns: the water it holds over s_0 rho^w V_0 (rho^w 1000, the
 * materials' default). */
static double alpha_of(const hearth_scene *s, int i, double cd) {
    const particles *ps = &s->ps;
    const double w0 = pcold(ps, PC_SAT0)[i] * 1000.0 * pcold(ps, PC_VOL0)[i];
    const double r = pcold(ps, PC_WATER)[i] / w0;
    return cd + (C_WET - cd) * (r > 0 ? r : 0.0);
}

/* A pinned 40 x 20 mm block of the bread at 25 degC in its 200 degC oven, with latent_heat (the oven's books);
 * water diffusivity and evaporation as given, dry_specific_heat cd. */
static hearth_scene *block(double dx, double cd, double water_k, double evap, int implicit) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = dx;
    d.gravity[1] = 0;
    d.lo[0] = d.lo[1] = 0;
    d.hi[0] = 0.1;
    d.hi[1] = 0.06;
    d.oven_temperature = OVEN_T;
    d.oven_beta = OVEN_BETA;
    d.latent_heat = 1;
    d.heat_implicit = implicit;
    if (implicit) d.dt_max = 0.02; /* a pinned block has no CFL limit: without it the implicit heat takes a few steps */
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NULL;
    const char *nm[] = {"E", "density", "specific_heat", "conductivity", "saturation", "water_diffusivity", "evaporation",
                        "dry_specific_heat"};
    const double nv[] = {1e4, RHO, C_WET, KAPPA, SAT, water_k, evap, cd};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "elastic", nm, nv, 8, &err);
    if (m < 0) printf("  material: %s\n", err.msg);
    CHECK(m >= 0);
    const double c[3] = {0.05, 0.03, 0}, h[3] = {0.02, 0.01, 0};
    hearth_shape *box = hearth_shape_box(c, h);
    hearth_body_def bd = hearth_default_body_def();
    bd.shape = box, bd.material = m, bd.jitter = 0, bd.fixed = 1;
    bd.temperature = 25;
    CHECK(hearth_scene_add_body(s, &bd, &err) >= 0);
    hearth_shape_free(box);
    return s;
}

/* A block whose water holds still (no diffusion, no evaporation, below the boiling point) at water ratio r,
 * heated 0.1 s (30 real seconds, below the boiling point): its mean temperature rise per joule the oven put in is 1 / (M alpha(r)). */
static double heats_by(double cd, double r, double *dT) {
    /* water live (a diffusivity) but still: the saturation is uniform, so Fick's flux is round-off */
    hearth_scene *s = block(0.004, cd, 1e-18, 0.0, 0);
    if (!s) return INFINITY;
    particles *ps = &s->ps;
    /* the water ratio r of what each particle was made with (at least water.c's saturation floor) */
    for (int i = 0; i < ps->n; i++) pcold(ps, PC_WATER)[i] = fmax(r, 2 * WATER_SATURATION_FLOOR / SAT) * pcold(ps, PC_WATER)[i];
    hearth_error err;
    double M = 0, MC = 0;
    for (int i = 0; i < ps->n; i++) M += pcold(ps, PC_MASS)[i], MC += pcold(ps, PC_MASS)[i] * alpha_of(s, i, cd);
    CHECK(hearth_scene_advance(s, 0.1, &err) == HEARTH_OK);
    hearth_stats st;
    hearth_scene_stats(s, &st);
    double rise = 0, MC1 = 0, Tmax = -INFINITY;
    for (int i = 0; i < ps->n; i++) {
        const double m = pcold(ps, PC_MASS)[i], T = pcold(ps, PC_TEMPERATURE)[i];
        rise += m * (T - 25.0);
        MC1 += m * alpha_of(s, i, cd);
        Tmax = fmax(Tmax, T);
    }
    rise /= M;
    const double want = st.oven_heat_in / MC; /* the closed form: Q / sum m alpha(w) */
    *dT = rise;
    printf("  dry_specific_heat %6.1f, water ratio %.2f: alpha %.1f J/(kg K); heat in %.6g J/m over %ld steps; mean rise "
           "%.6f K, Q / (M alpha) %.6f K (rel. diff %.2g); hottest %.2f degC; capacity moved %.2g\n",
           cd, r, MC / M, st.oven_heat_in, st.step, rise, want, (rise - want) / want, Tmax, MC1 / MC - 1);
    CHECK(fabs(MC1 / MC - 1) < 1e-12); /* the water held still, so alpha did */
    CHECK(Tmax < 100); /* nothing boiled */
    hearth_scene_destroy(s);
    return (rise - want) / want;
}

/* A dried block (r = 0: dry_specific_heat), a half-dried one (the midpoint)
 * and a wet one (specific_heat) each heat by Q / (M alpha(r)) on the mean, to
 * round-off: every step's update puts dt (B - R)_i into the node capacities
 * C_i = sum_p w_ip m_p alpha_p and FLIP hands it back on the same weights, so
 * sum_p m_p alpha_p dtheta_p is the oven's heat exactly. Bar 1e-9, far above
 * round-off over some hundreds of steps and far below the factor 2.98 a scheme
 * reading the wet alpha for the dried block would miss by. The dried block,
 * in the same oven, is the hotter after the same time. */
TEST(dry_heat_block_heats_at_its_capacity) {
    double dT[3];
    const double e0 = heats_by(C_DRY, 0.0, &dT[0]), e5 = heats_by(C_DRY, 0.5, &dT[1]), e1 = heats_by(C_DRY, 1.0, &dT[2]);
    printf("  mean rise dried %.3f K, half %.3f K, wet %.3f K (alpha ratio wet / dry %.3f)\n", dT[0], dT[1], dT[2],
           C_WET / C_DRY);
    CHECK(fabs(e0) < 1e-9 && fabs(e5) < 1e-9 && fabs(e1) < 1e-9);
    CHECK(dT[0] > dT[1] && dT[1] > dT[2]);
}

/* The books of a drying, boiling bake. Stepped one step at a time: each
 * step adds sum_p m_p alpha(w_p) (theta_p' - theta_p), alpha at the water the
 * particle held when the step began (the test's rule above; particles found by
 * id, since the sort reorders the columns). Returns the relative imbalance
 * (Q - sensible - L x water lost) / Q; *share the latent part's share of Q,
 * *naive the imbalance of the difference of sum m alpha(w) (theta + 273.15), which
 * leaves out the heat the water carried away at its temperature, *lost the
 * share of the block's heat capacity gone with its water. */
static double books(double dx, int implicit, double cd, double *share, double *naive, double *lost) {
    hearth_scene *s = block(dx, cd, WATER_K, EVAP, implicit);
    if (!s) return INFINITY;
    const particles *ps = &s->ps;
    const int n = ps->n;
    double *a0 = malloc(sizeof(double) * (size_t)n), *T0 = malloc(sizeof(double) * (size_t)n);
    hearth_stats st;
    hearth_scene_stats(s, &st);
    const double E0 = st.heat_energy, W0 = st.water_mass;
    double C0 = 0;
    for (int i = 0; i < n; i++) C0 += pcold(ps, PC_MASS)[i] * alpha_of(s, i, cd);
    hearth_error err;
    double sens = 0;
    while (hearth_scene_time(s) < 5.0 - 1e-12) {
        for (int i = 0; i < n; i++) {
            const int id = pcoli(ps, PC_ID)[i];
            a0[id] = alpha_of(s, i, cd), T0[id] = pcold(ps, PC_TEMPERATURE)[i];
        }
        if (hearth_scene_step(s, 1, &err) != HEARTH_OK) {
            printf("  step: %s\n", err.msg);
            CHECK(0);
            break;
        }
        for (int i = 0; i < n; i++) {
            const int id = pcoli(ps, PC_ID)[i];
            sens += pcold(ps, PC_MASS)[i] * a0[id] * (pcold(ps, PC_TEMPERATURE)[i] - T0[id]);
        }
    }
    hearth_scene_stats(s, &st);
    double C1 = 0;
    for (int i = 0; i < n; i++) C1 += pcold(ps, PC_MASS)[i] * alpha_of(s, i, cd);
    const double Q = st.oven_heat_in, dW = W0 - st.water_mass, miss = (sens + HEARTH_LATENT_HEAT * dW - Q) / Q;
    *share = HEARTH_LATENT_HEAT * dW / Q;
    *naive = (st.heat_energy - E0 + HEARTH_LATENT_HEAT * dW - Q) / Q;
    *lost = 1 - C1 / C0;
    printf("  dx %.3g m, %s, dry_specific_heat %.1f, %ld steps, t = %.2f s: heat in %.6g J/m = integral m alpha dtheta "
           "%.6g + L x water %.6g (%.3g of %.3g kg/m); imbalance %.3g; with the difference of sum m alpha (theta + "
           "273.15) instead %.3g; heat capacity gone with the water %.3f\n",
           dx, implicit ? "implicit" : "explicit", cd, st.step, st.t, Q, sens, HEARTH_LATENT_HEAT * dW, dW, W0, miss,
           *naive, *lost);
    free(a0);
    free(T0);
    hearth_scene_destroy(s);
    return miss;
}

/* Heat in through the oven's Robin boundary = integral of m alpha(w) dtheta +
 * L x water lost, to 1 % (latent_heat_energy_balance's bar; a particle that
 * reaches water.c's saturation floor keeps water whose heat was taken), for
 * the bread with its dry_specific_heat baked 25 minutes (its surface dries,
 * its crumb boils), at two resolutions and in both heat schemes. The latent
 * part must carry a good share of the books and a good share of the heat
 * capacity must have gone with the water, so that the case exercises what it
 * checks; and the books without the carried heat (a difference of the heat
 * content sum m alpha (theta + 273.15)) must not close, so that the integral's
 * form is what closes them. */
TEST(dry_heat_energy_balance) {
    double share, naive, lost;
    const struct {
        double dx;
        int implicit;
    } c[3] = {{0.004, 0}, {0.002, 0}, {0.004, 1}};
    for (int k = 0; k < 3; k++) {
        const double miss = books(c[k].dx, c[k].implicit, C_DRY, &share, &naive, &lost);
        CHECK(fabs(miss) < 0.01);
        CHECK(share > 0.2);
        CHECK(lost > 0.05);
        CHECK(fabs(naive) > 0.01);
    }
}

/* dry_specific_heat 0 (the default) and dry_specific_heat = specific_heat give
 * the same bits on the drying bake (alpha_d + (alpha - alpha_d) r = alpha and
 * the step limits the same), and the bake with the bread's dry_specific_heat the
 * same bits on 1 and 2 threads (3200 particles at 1 mm, above SCENE_PARALLEL_MIN). */
static unsigned long long bake_hash(double dx, double cd, int threads) {
    hearth_set_threads(threads);
    hearth_scene *s = block(dx, cd, WATER_K, EVAP, 0);
    hearth_error err;
    CHECK(s && hearth_scene_advance(s, 0.5, &err) == HEARTH_OK);
    const unsigned long long h = s ? (unsigned long long)hearth_scene_hash(s) : 0;
    hearth_scene_destroy(s);
    hearth_set_threads(0);
    return h;
}

TEST(dry_heat_same_bits) {
    const unsigned long long h0 = bake_hash(0.004, 0, 1), hc = bake_hash(0.004, C_WET, 1);
    printf("  hash dry_specific_heat 0: %016llx, = specific_heat: %016llx\n", h0, hc);
    CHECK(h0 == hc);
    const unsigned long long h1 = bake_hash(0.001, C_DRY, 1), h2 = bake_hash(0.001, C_DRY, 2), hw = bake_hash(0.001, 0, 1);
    printf("  hash dry_specific_heat %.1f, 1 thread: %016llx, 2 threads: %016llx (0: %016llx)\n", C_DRY, h1, h2, hw);
    CHECK(h1 == h2 && h1 != hw);
}

/* Forward Euler's step limits with a dried end (thermal_dt_limit): conduction's rho alpha dx^2 / (2 dim kappa)
 * at the end, dried (dry_specific_heat, dry_conductivity) or wet, of the smaller alpha / kappa, since alpha and
 * kappa are both linear in the water ratio r and alpha(r) / kappa(r) is then monotone in r, its least value at
 * r = 0 or 1; the Robin term's rho alpha dx / (2 beta) at the smallest alpha, the dried one (a node may hold a
 * dried particle's capacity alone). The test derives both from the parameters, for the bread's numbers in real
 * units (907.5 / 0.23 = 3946 dried against 2700 / 0.51 = 5294 wet: the dried end the smaller), with one
 * dry parameter or both, under a weak oven (conduction binds) and a strong one (the Robin term binds). */
static double limit_of(double cd, double kd, double beta) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = 0.004;
    d.gravity[1] = 0;
    d.oven_temperature = OVEN_T;
    d.oven_beta = beta;
    hearth_scene *s = fx_scene_def(&d);
    if (!s) return NAN;
    const char *nm[] = {"E", "density", "specific_heat", "conductivity", "dry_specific_heat", "dry_conductivity"};
    const double nv[] = {1e4, RHO, C_WET, 0.51, cd, kd};
    hearth_error err;
    const int m = hearth_scene_add_material(s, "elastic", nm, nv, 6, &err);
    CHECK(m >= 0);
    const double c[3] = {0.5, 0.5, 0}, h[3] = {0.02, 0.02, 0};
    CHECK(fx_box(s, m, c, h, 2, NULL) > 0);
    const double dt = thermal_dt_limit(s);
    hearth_scene_destroy(s);
    return dt;
}

TEST(dry_heat_step_limits_take_the_dried_end) {
    const double dx = 0.004, kw = 0.51, kd = 0.23, betas[2] = {30, 300};
    const struct {
        double cd, kd;
    } c[3] = {{C_DRY, kd}, {0, kd}, {C_DRY, 0}};
    for (int b = 0; b < 2; b++)
        for (int k = 0; k < 3; k++) {
            const double ce = c[k].cd > 0 ? c[k].cd : C_WET, ke = c[k].kd > 0 ? c[k].kd : kw; /* the dried end */
            const double ratio = fmin(C_WET / kw, ce / ke), cond = RHO * ratio * dx * dx / (2 * 2);
            const double robin = RHO * ce * dx / (2 * betas[b]), want = fmin(cond, robin);
            const double got = limit_of(c[k].cd, c[k].kd, betas[b]);
            printf("  beta %3.0f, dry_specific_heat %6.1f, dry_conductivity %.2f: conduction %.4f s, Robin %.4f s; "
                   "limit %.6f s, derived %.6f s\n", betas[b], c[k].cd, c[k].kd, cond, robin, got, want);
            CHECK(fabs(got - want) <= 1e-12 * want);
        }
}

/* dry_specific_heat above specific_heat is refused, naming both and the range; below 0 by the schema. */
TEST(dry_heat_refusals) {
    hearth_scene *s = fx_scene(2, 0.01, -0.1, 0.1);
    if (!s) return;
    hearth_error err;
    const char *nm[] = {"specific_heat", "dry_specific_heat"};
    const double v[] = {2700, 3000};
    CHECK(hearth_scene_add_material(s, "elastic", nm, v, 2, &err) < 0);
    printf("  %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "dry_specific_heat = 3000 J/(kg K) exceeds its specific_heat = 2700 J/(kg K)");
    CHECK_STR_CONTAINS(err.msg, "valid range [0, specific_heat]");
    const double neg[] = {2700, -1};
    CHECK(hearth_scene_add_material(s, "elastic", nm, neg, 2, &err) < 0);
    printf("  %s\n", err.msg);
    CHECK_STR_CONTAINS(err.msg, "dry_specific_heat");
    hearth_scene_destroy(s);
}

TEST_MAIN(T(dry_heat_block_heats_at_its_capacity), T(dry_heat_step_limits_take_the_dried_end), T(dry_heat_energy_balance), T(dry_heat_same_bits), T(dry_heat_refusals))
