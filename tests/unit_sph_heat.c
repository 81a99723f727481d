/* unit_sph_heat.c: the SPH solver's surface heat (Rodriguez-Arenas 2011 eq.
 * 3.42, taken per unit area of surface: core/sim/solver/sph_heat.c) against
 * closed forms at several resolutions: the heat a block takes in through its
 * outline, and a Robin slab's temperature profile and uptake against its
 * series; and whether the roll's bubble spots reach their gas volume. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hearth/hearth.h"
#include "scene.h"
#include "sph.h"
#include "sph_fixture.h"
#include "sph_robin_slab.h"
#include "sph_state.h"
#include "test.h"


static double sum_mT(const hearth_scene *s) {
    const double *T = pcold(&s->ps, PC_TEMPERATURE), *m = pcold(&s->ps, PC_MASS);
    double E = 0;
    for (int i = 0; i < s->ps.n; i++) E += m[i] * T[i];
    return E;
}

/* A block at 26 degC in a 180 degC oven, heated by eq. 3.42 alone (k_h,ext =
 * h / c = 1 kg/(m^2 s), no conduction, no gravity) at three spacings: a 2D
 * slab 40 x 20 mm periodic along x (two faces, no corners), a 2D 40 x 20 mm
 * block and a 3D 20 x 20 x 10 mm one. Over 20 steps the temperature barely
 * moves, so the heat taken, sum m dT (the specific heat divides out of
 * k_h,ext = h / c), over k (T_ext - T0) t, is the area the surface particles
 * stand for, one face dx^(d-1) each. For the slab that is its two faces at
 * any dx (within 0.5%: the outer rows warm a little over the 20 steps). A
 * block's corner particle (2D) stands for one face where the outline has two,
 * and in 3D an edge particle for one of two and a corner for one of three:
 * the closed form is the outline less 4 dx (2D) or less dx^2 (sum over the
 * 12 edges of (length / dx - 2) + 2 x 8) (3D), within 0.5% again, a
 * shortfall of first order in dx. The thesis's form as printed (r^2 / rho
 * per particle) went as dx^3 per unit area: 64x from 2 to 0.5 mm. */
TEST(sph_heat_ext_flux_per_area) {
    for (int c = 0; c < 3; c++) {
        const int dim = c == 2 ? 3 : 2, periodic = c == 0;
        const double dxs[3] = {0.002, dim == 2 ? 0.001 : 0.00125, dim == 2 ? 0.0005 : 0.001};
        const double *blo, lo2[3] = {0.02, 0.02, 0}, lo3[3] = {0.02, 0.02, 0.02}, lop[3] = {0, 0.02, 0};
        const double *bhi, hi2[3] = {0.06, 0.04, 0}, hi3[3] = {0.04, 0.04, 0.03}, hip[3] = {0.04, 0.04, 0};
        blo = c == 0 ? lop : c == 1 ? lo2 : lo3;
        bhi = c == 0 ? hip : c == 1 ? hi2 : hi3;
        const double k = 1.0, Text = 180, T0 = 26;
        const double outline = c == 0 ? 2 * 0.04 : c == 1 ? 2 * (0.04 + 0.02) : 2 * (0.02 * 0.02 + 2 * 0.02 * 0.01);
        const char *what = c == 0 ? "2D periodic slab" : c == 1 ? "2D block" : "3D block";
        double per_area[3];
        for (int r = 0; r < 3; r++) {
            const double dx = dxs[r], lo[3] = {0, 0, 0}, hi[3] = {periodic ? 0.04 : 0.08, 0.06, 0.05};
            hearth_scene_def d = sph_def(dim, dx, lo, hi);
            d.gravity[1] = 0;
            d.sph.periodic[0] = periodic;
            d.oven_temperature = Text;
            d.oven_beta = 0;
            d.sph.heat_ext = k;
            hearth_scene *s = hearth_scene_create(&d, NULL);
            CHECK(s != NULL);
            if (!s) return;
            const int m = newtonian(s, 1000, 1e4, 1.0);
            CHECK(m >= 0 && sph_box(s, m, blo, bhi, 0, T0) >= 0);
            const double E0 = sum_mT(s);
            hearth_error err;
            CHECK(hearth_scene_step(s, 20, &err) == HEARTH_OK);
            per_area[r] = (sum_mT(s) - E0) / (s->t * (Text - T0) * outline);
            double faces = outline; /* the closed form: the faces the surface particles stand for */
            if (c == 1) faces -= 4 * dx;
            if (c == 2) faces -= dx * dx * (4 * (0.02 / dx + 0.02 / dx + 0.01 / dx - 6) + 16);
            printf("%s, dx %.2f mm (%d particles): heat in per unit area %.4f of k (T_ext - T0); the particles' faces "
                   "%.4f of the outline\n",
                   what, 1e3 * dx, s->ps.n, per_area[r], faces / outline);
            CHECK(fabs(per_area[r] / k / (faces / outline) - 1) < 0.005);
            hearth_scene_destroy(s);
        }
        printf("%s: finest over coarsest %.4f\n", what, per_area[2] / per_area[0]);
        if (periodic) CHECK(fabs(per_area[2] / per_area[0] - 1) < 0.005);
    }
}

/* The Robin slab converges to its series at 10, 20 and 40 particles across:
 * the worst profile error shrinks at an observed order of at least 0.8 at
 * each step (the surface heat lands in the outer row, a layer dx thick,
 * rather than at the face: first order), and so does the error of the heat
 * taken, which comes within 2% of the series at 40 across. */
TEST(sph_heat_ext_slab_converges) {
    double th, q;
    slab_series(1, 0, 0.5, &th, &q); /* the reference itself: Incropera's table, Bi = 1 */
    CHECK_NEAR(th, 0.77253, 2e-5);
    const int Ns[] = {10, 20, 40};
    double E[3], Q[3], Qx[3];
    for (int r = 0; r < 3; r++) {
        CHECK(robin_slab(Ns[r], &E[r], &Q[r], &Qx[r], NULL) == 0);
        printf("Robin slab, %d across: worst profile error %.4f of T0 - T_ext; heat taken %.5f of the most, series "
               "%.5f (%+.2f%%)\n",
               Ns[r], E[r], Q[r], Qx[r], 100 * (Q[r] / Qx[r] - 1));
    }
    for (int r = 1; r < 3; r++) {
        const double order = log(E[r - 1] / E[r]) / log(2.0);
        const double qorder = log(fabs(Q[r - 1] / Qx[r - 1] - 1) / fabs(Q[r] / Qx[r] - 1)) / log(2.0);
        printf("Robin slab: %d -> %d across, observed order %.2f (profile), %.2f (heat taken)\n", Ns[r - 1], Ns[r],
               order, qorder);
        CHECK(order >= 0.8 && qorder >= 0.8);
    }
    CHECK(fabs(Q[2] / Qx[2] - 1) < 0.02);
}

/* ---- the roll's gas: bubble clusters narrower than the kernel ------------- */

/* V_b / V_b0 of the gas law with water vapour (sph_gas.c), from its closed
 * form: ideal gas in Kelvin, the CO2's moles held in P_a - P_v, P_v = a_w
 * P_sat(T) by Clausius-Clapeyron through 100 degC at 101325 Pa, 40.66 kJ/mol. */
static double vb_closed(double aw, double T0, double T) {
    const double hr = 40660.0 / 8.314462618, tb = 373.15;
    const double pv0 = aw * exp(-hr * (1 / (T0 + 273.15) - 1 / tb)), pv = aw * exp(-hr * (1 / (T + 273.15) - 1 / tb));
    return (T + 273.15) / (T0 + 273.15) * (1 - pv0) / (1 - pv);
}

/* A dough disc 40 mm across (lattice at 2 mm, no gravity, a Newtonian dough
 * with the thesis's Tait and its tension) whose bubble particles sit in spots
 * 1.6 spacings in radius at a pitch of 4.5, as the bread roll's: each spot is
 * narrower than the kernel's support. Heated uniformly 26 -> 80 degC and held,
 * the gas law with the dough's water vapour (a_w 0.95) wants each bubble at
 * V_b(80) / V_b(26); the body's volume (sum of m / rho) should grow to
 * (n_dough + n_bubble V_b) / n. Returns hot / raw volume. With film (not
 * NULL), heated to Thot instead and also measured from the positions alone:
 * film[0] the mean distance from each film particle (a dough particle with a
 * bubble particle within 1.5 spacings) to its nearest dough particle, in raw
 * spacings, film[1] the least such distance, film[2] the film particles' mean
 * Tait pressure over B (hot), film[3] the same of the bubble particles. */
static double cluster_dough(double Thot, double *want, double *film) {
    const double dx = 0.002, lo[3] = {0, 0, 0}, hi[3] = {0.12, 0.12, 0}, aw = 0.95;
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.tension = 1;
    d.sph.gas_law = 1;
    d.sph.bubble_vapour = aw;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return NAN;
    const char *n[] = {"density", "bulk", "viscosity", "bubble"};
    double v[] = {1000, 1e4, 2.0, 0};
    hearth_error err;
    const int dough = hearth_scene_add_material(s, "newtonian", n, v, 4, &err);
    v[3] = 1;
    const int bub = hearth_scene_add_material(s, "newtonian", n, v, 4, &err);
    int nb = 0, nd = 0;
    for (int j = 0; j < 40 && dough >= 0 && bub >= 0; j++)
        for (int i = 0; i < 40; i++) {
            double p[3] = {0.06 + (i - 19.5) * dx, 0.06 + (j - 19.5) * dx, 0};
            if (hypot(p[0] - 0.06, p[1] - 0.06) > 0.02) continue;
            /* the nearest spot centre on a pitch-4.5 grid through the centre */
            const double pitch = 4.5 * dx, sx = 0.06 + pitch * round((p[0] - 0.06) / pitch),
                         sy = 0.06 + pitch * round((p[1] - 0.06) / pitch);
            const int b = hypot(p[0] - sx, p[1] - sy) < 1.6 * dx;
            if (hearth_scene_add_particles(s, b ? bub : dough, 1, p, NULL, dx * dx, &err) != 1)
                fprintf(stderr, "%s\n", err.msg);
            *(b ? &nb : &nd) += 1;
        }
    sph_heat_speck(s, dough, 0.005, 0.005, 26); /* turns the temperature field on */
    double V[2] = {0, 0};
    for (int phase = 0; phase < 2; phase++) {
        for (int k = 0; phase == 1 && k < 600; k++) {
            double *T = pcold(&s->ps, PC_TEMPERATURE);
            for (int i = 0; i < s->ps.n; i++) T[i] = 26 + (Thot - 26) * (k + 1) / 600;
            if (hearth_scene_step(s, 1, &err) != HEARTH_OK) break;
        }
        if (hearth_scene_step(s, 300, &err) != HEARTH_OK) fprintf(stderr, "%s\n", err.msg);
        const double *rho = sph_particle_values(s, "density"), *m = pcold(&s->ps, PC_MASS);
        const int *flags = pcoli(&s->ps, PC_FLAGS);
        for (int i = 0; rho && i < s->ps.n; i++)
            if (!(flags[i] & PF_FIXED)) V[phase] += m[i] / rho[i];
    }
    *want = (nd + nb * vb_closed(aw, 26, Thot)) / (nd + nb);
    printf("%d bubble and %d dough particles, 26 -> %g degC: volume hot/raw %.4f, the gas law's %.4f\n", nb, nd, Thot,
           V[1] / V[0], *want);
    if (film) {
        const struct sph_state *st = s->sph;
        const double *x = pcold(&s->ps, PC_X);
        const int *mat = pcoli(&s->ps, PC_MAT), *flags = pcoli(&s->ps, PC_FLAGS), np = s->ps.n;
        double sum = 0, least = HUGE_VAL, pf = 0, pb = 0;
        int nf = 0, nbub = 0;
        for (int i = 0; i < np; i++) {
            if (flags[i] & PF_FIXED) continue;
            if (mat[i] == bub) {
                pb += st->prs[i] / st->B[i], nbub++;
                continue;
            }
            double dd = HUGE_VAL, db = HUGE_VAL;
            for (int j = 0; j < np; j++) {
                if (j == i || (flags[j] & PF_FIXED)) continue;
                const double r = hypot(x[3 * i] - x[3 * j], x[3 * i + 1] - x[3 * j + 1]) / dx;
                if (mat[j] == bub) db = fmin(db, r);
                else dd = fmin(dd, r);
            }
            if (db > 1.5) continue;
            sum += dd, least = fmin(least, dd), pf += st->prs[i] / st->B[i], nf++;
        }
        film[0] = sum / nf, film[1] = least, film[2] = pf / nf, film[3] = pb / nbub;
        printf("%d film particles at %g degC: nearest dough particle %.3f spacings on average, %.3f at least; "
               "Tait pressure over B %.4f (films), %.4f (bubbles)\n",
               nf, Thot, film[0], film[1], film[2], film[3]);
    }
    hearth_scene_destroy(s);
    return V[1] / V[0];
}

/* The roll's spots reach their gas volume within 3%: the question was whether
 * eq. 3.13's density, which counts the dough around a spot narrower than the
 * kernel, keeps a spot from ever reaching rho0 / V_b (so that it would push
 * on without bound and stretch the films between spots until they tear). It
 * does not: a soft dough lets the spots take their volume (measured 1.4910
 * against 1.4900). In the hot roll the bubbles stand short of V_b because the
 * set dough's elasticity holds them (docs/validation.md "SPH bread roll"). */
TEST(sph_gas_law_clusters_reach_gas_volume) {
    CHECK_NEAR(vb_closed(0.95, 26, 80), 2.1, 0.05); /* docs/validation.md's figure for the closed form */
    double want;
    const double got = cluster_dough(80, &want, NULL);
    CHECK(fabs(got / want - 1) <= 0.03);
}

/* ---- mirror symmetry ------------------------------------------------------ */

/* One mirror case: two 2D blocks 18 x 20 mm of Newtonian batter, 4 mm apart
 * about x = 40 mm in a box 80 mm wide, seeded one particle per cell at 2 mm (the box a
 * whole number of spacings wide, so the lattice is its own mirror image about
 * x = 40 mm), at 26 degC in a 180 degC oven: eq. 3.42's surface heat, eq.
 * 3.45's conduction and the Robin flux (beta 10). case 0: the particles
 * pinned (heat alone). case 1: free, under gravity on a slip floor, between
 * two slip walls and around a slip tube in the middle (the angel food cake's
 * pan), the floor heated (200 degC, beta 30). case 2, the control: case 1
 * with the left wall heated (200 degC, beta 30) and the right one not, which
 * must show. After `t` s: the worst |T_i - T_i'| over mirrored pairs i, i'
 * (paired by position and material when seeded, followed by id), the worst
 * |x_i + x_i' - 2 c|, and the right half's mean temperature less the left's.
 * Returns the count of unpaired particles, -1 on failure. */
static int mirror_case(int which, double t, double *dT, double *dx_pos, double *lr) {
    const double dx = 0.002, c = 0.04, lo[3] = {0, 0, 0}, hi[3] = {0.08, 0.06, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.oven_temperature = 180;
    d.oven_beta = 10;
    d.sph.heat_ext = 1;
    d.sph.heat_int = 0.5;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return -1;
    const int m = newtonian(s, 600, 2e4, 2.0);
    /* two blocks, one each side of the tube (2 mm either side of x = c) */
    const double llo[3] = {c - 0.02, 0.01, 0}, lhi[3] = {c - 0.002, 0.03, 0};
    const double rlo[3] = {c + 0.002, 0.01, 0}, rhi[3] = {c + 0.02, 0.03, 0};
    int rc = m >= 0 && sph_box(s, m, llo, lhi, which == 0, 26) >= 0 && sph_box(s, m, rlo, rhi, which == 0, 26) >= 0
                 ? 0
                 : -1;
    hearth_error err;
    for (int q = 0; which > 0 && q < 4 && !rc; q++) { /* floor, left and right walls, the tube */
        hearth_collider_def cd = hearth_default_collider_def();
        double p[3] = {0, 0.01, 0}, nrm[3] = {0, 1, 0}, bc[3] = {c, 0.015, 0}, bh[3] = {0.002, 0.015, 0.5};
        if (q == 1) p[0] = c - 0.0205, p[1] = 0, nrm[0] = 1, nrm[1] = 0;
        if (q == 2) p[0] = c + 0.0205, p[1] = 0, nrm[0] = -1, nrm[1] = 0;
        cd.shape = q == 3 ? hearth_shape_box(bc, bh) : hearth_shape_plane(p, nrm);
        cd.mode = HEARTH_SLIP;
        if (q == 0 || (which == 2 && q == 1)) cd.temperature = 200, cd.beta = 30;
        if (hearth_scene_add_collider(s, &cd, &err) < 0) rc = -1, fprintf(stderr, "%s\n", err.msg);
        hearth_shape_free((hearth_shape *)cd.shape);
    }
    /* each particle's mirror image, found once by position and material */
    const int n0 = s->ps.n;
    int *mate = malloc(sizeof(int) * (n0 > 0 ? n0 : 1)), unpaired = 0;
    const double *x = hearth_scene_positions(s);
    const int *mat = pcoli(&s->ps, PC_MAT), *id = pcoli(&s->ps, PC_ID);
    for (int i = 0; i < n0 && mate; i++) { /* ids are 0..n-1 in seeding order before the first step */
        mate[id[i]] = -1;
        for (int j = 0; j < n0; j++)
            if (fabs(x[3 * j] - (2 * c - x[3 * i])) < 1e-9 && fabs(x[3 * j + 1] - x[3 * i + 1]) < 1e-12 && mat[j] == mat[i])
                mate[id[i]] = id[j];
        unpaired += mate[id[i]] < 0;
    }
    if (!mate || (!rc && hearth_scene_advance(s, t, &err))) rc = -1, fprintf(stderr, "%s\n", mate ? err.msg : "no memory");
    *dT = *dx_pos = *lr = 0;
    if (!rc) {
        const int n = s->ps.n;
        int *at = malloc(sizeof(int) * (n0 > 0 ? n0 : 1)); /* id -> index now */
        const double *T = pcold(&s->ps, PC_TEMPERATURE);
        x = hearth_scene_positions(s), id = pcoli(&s->ps, PC_ID);
        double sl = 0, sr = 0;
        int nl = 0, nr = 0;
        for (int i = 0; at && i < n; i++) {
            at[id[i]] = i;
            if (x[3 * i] < c) sl += T[i], nl++;
            else sr += T[i], nr++;
        }
        for (int k = 0; at && k < n0; k++) {
            if (mate[k] < 0) continue;
            const int i = at[k], j = at[mate[k]];
            *dT = fmax(*dT, fabs(T[i] - T[j]));
            *dx_pos = fmax(*dx_pos, fabs(x[3 * i] + x[3 * j] - 2 * c) + fabs(x[3 * i + 1] - x[3 * j + 1]));
        }
        *lr = nl && nr ? sr / nr - sl / nl : NAN;
        if (!at) rc = -1;
        free(at);
    }
    free(mate);
    hearth_scene_destroy(s);
    return rc ? -1 : unpaired;
}

/* A mirror-symmetric scene heats mirror-symmetrically (issue #18's angel
 * food cake heated 13.7 degC more on the right at 1 s: its seed and its
 * bubble spots were not mirror images, scripts/scenes/sph/angel_food_cake.lua;
 * this checks the solver's part: surface heat, conduction, Robin, heated
 * collider, slip walls, motion). Mirrored particles sum their neighbours in
 * mirrored order (the cell list walks +x on both sides), so they agree to
 * round-off, not to the bit: measured 7e-15 degC pinned, 1e-12 degC and
 * 5e-15 m with motion after 0.2 s. The bounds, 1e-9 degC and 1e-9 m, leave
 * that room to grow on another compiler or optimisation level and stay 8
 * orders under what the control's one heated wall shows (0.66 degC worst
 * pair, 0.28 degC between the halves' means; asked: above 0.1). */
TEST(sph_heat_mirror_symmetric) {
    const char *what[3] = {"pinned, heat only", "free, in a slip pan with a heated floor", "control: left wall heated"};
    for (int k = 0; k < 3; k++) {
        double dT, dX, lr;
        const int unpaired = mirror_case(k, 0.2, &dT, &dX, &lr);
        printf("%s: %d unpaired particles; after 0.2 s worst |T - T_mirror| %.3g degC, worst position mismatch %.3g "
               "m, right less left mean %.3g degC\n",
               what[k], unpaired, dT, dX, lr);
        CHECK(unpaired == 0);
        if (k < 2) CHECK(dT < 1e-9 && dX < 1e-9 && fabs(lr) < 1e-9);
        else CHECK(dT > 0.1 && lr < -0.1);
    }
}

/* The films between the roll's bubble spots are not pulled into tension by
 * the bubbles beside them (#18: the roll tore along its rings of films).
 * The spots of sph_gas_law_clusters_reach_gas_volume heated to 70 degC (V_b
 * 1.58, films still over a spacing thick) in a dough at rest with no
 * gravity and no load: its films should stand at the dough's rest spacing
 * and pressure, whatever the bubbles' volume. Eq. 3.13's mass sum counted
 * fewer neighbours beside the expanded bubbles and read the films' dough as
 * stretched, so Tait pulled it together: measured from the positions, the
 * film particles' nearest dough neighbour came to 0.510 spacings on average
 * and 0.192 at least (the films' particles paired, SPH's tensile clumping).
 * With the rest-volume sum (sort_and_list, Hopkins 2013) 0.993 and 0.699.
 * Asserted: the mean within 3% of a spacing and no pair closer than half a
 * spacing. */
TEST(sph_gas_law_films_keep_rest_spacing) {
    double want, film[4];
    cluster_dough(70, &want, film);
    CHECK(fabs(film[0] - 1) <= 0.03);
    CHECK(film[1] > 0.5);
}

/* ---- the density Tait reads: the sum, or the particle's own volume -------- */

/* A 2D block of dough 40 x 24 mm (lattice at 2 mm, no gravity, Tait with its
 * tension and the gas law, B = 1.4e4 Pa) at rest for 20 steps; then the same
 * block with sph.continuity_density, and that one again set expanding, v =
 * rate (x - c). At rest nothing is stretched, so the right pressure is 0
 * everywhere: eq. 3.13's sum, which counts the neighbours in the kernel,
 * reads the outer row (surface particles) short of its rest density and
 * pulls it with Tait's tension, a skin that squeezes what it holds (the bread
 * roll's, docs/validation.md "The roll's skin"), while the particle's own
 * volume m / (V0 det F) reads 0 (20 steps each). Expanding (8 steps, before
 * the tension's wave from the edges reaches the centre, so the strain there
 * is still uniform), the own volume must follow the
 * positions: det F of the particles that start within 5 mm of the centre
 * against their patch's area grown from the start, sqrt of the ratio of
 * the determinants of their positions' covariance (a uniform strain scales
 * it by det F^2). Outputs: [0] the outer row's mean p / B, [1] the
 * inside's, [2] the centre patch's area ratio from the positions, [3] its
 * mean det F. */
static void moments(const double *x, double m[5]) {
    m[0] += x[0], m[1] += x[1], m[2] += x[0] * x[0], m[3] += x[1] * x[1], m[4] += x[0] * x[1];
}

static double cov_det(const double m[5], int n) {
    const double cx = m[0] / n, cy = m[1] / n;
    return (m[2] / n - cx * cx) * (m[3] / n - cy * cy) - (m[4] / n - cx * cy) * (m[4] / n - cx * cy);
}

/* mode: 0 eq. 3.13's sum, 1 the own volume (continuity_density), 2 the sum
 * renormalised by the kernel's filled part (renormalised_density) */
static void skin_case(int mode, double rate, int steps, double out[4]) {
    const double dx = 0.002, lo[3] = {0, 0, 0}, hi[3] = {0.1, 0.08, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.tension = 1;
    d.sph.gas_law = 1;
    d.sph.continuity_density = mode == 1;
    d.sph.renormalised_density = mode == 2;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    out[0] = out[1] = out[2] = out[3] = NAN;
    if (!s) return;
    const int m = newtonian(s, 1100, 1e5, 2.0);
    const double blo[3] = {0.03, 0.028, 0}, bhi[3] = {0.07, 0.052, 0}, c[2] = {0.05, 0.04};
    if (m < 0 || sph_box(s, m, blo, bhi, 0, 26) < 0) {
        hearth_scene_destroy(s);
        return;
    }
    double *v = pcold(&s->ps, PC_V);
    const double *x = pcold(&s->ps, PC_X);
    const int *id = pcoli(&s->ps, PC_ID);
    int patch[64], np = 0;
    double m0[5] = {0, 0, 0, 0, 0}, m1[5] = {0, 0, 0, 0, 0}; /* sums of x, y, xx, yy, xy */
    for (int i = 0; i < s->ps.n; i++) {
        v[3 * i] = rate * (x[3 * i] - c[0]), v[3 * i + 1] = rate * (x[3 * i + 1] - c[1]);
        if (fabs(x[3 * i] - c[0]) < 0.005 && fabs(x[3 * i + 1] - c[1]) < 0.005 && np < 64) {
            patch[np++] = id[i];
            moments(x + 3 * i, m0);
        }
    }
    hearth_error err;
    if (hearth_scene_step(s, steps, &err) != HEARTH_OK) fprintf(stderr, "%s\n", err.msg);
    x = pcold(&s->ps, PC_X), id = pcoli(&s->ps, PC_ID);
    const double *F = pcold(&s->ps, PC_F);
    const struct sph_state *st = s->sph;
    double ps = 0, pi = 0, J = 0;
    int ns = 0, ni = 0;
    for (int i = 0; i < s->ps.n; i++) {
        if (st->surf[i]) ps += st->prs[i] / st->B[i], ns++;
        else pi += st->prs[i] / st->B[i], ni++;
        for (int k = 0; k < np; k++)
            if (id[i] == patch[k]) {
                J += (F[9 * i] * F[9 * i + 4] - F[9 * i + 1] * F[9 * i + 3]) / np;
                moments(x + 3 * i, m1);
            }
    }
    out[0] = ps / ns, out[1] = pi / ni, out[2] = sqrt(cov_det(m1, np) / cov_det(m0, np)), out[3] = J;
    printf("%s, %s, %d steps: Tait pressure over B, outer row (%d) %.4f, inside (%d) %.4f; the centre patch (%d) grew %.5f by "
           "its positions, det F %.5f\n",
           mode == 1 ? "own volume (continuity_density)" : mode == 2 ? "the sum over the kernel's filled part (renormalised_density)" : "eq. 3.13's sum", rate > 0 ? "expanding" : "at rest", steps, ns,
           out[0], ni, out[1], np, out[2], out[3]);
    hearth_scene_destroy(s);
}

TEST(sph_continuity_density_reads_no_skin) {
    double sum[4], own[4], grow[4];
    skin_case(0, 0, 20, sum);
    skin_case(1, 0, 20, own);
    skin_case(1, 5, 8, grow);
    CHECK(sum[0] < -0.1);                              /* the skin the sum reads at rest */
    CHECK(fabs(own[0]) < 1e-3 && fabs(own[1]) < 1e-3); /* at rest nothing is stretched */
    CHECK(grow[2] > 1.005);                            /* the patch did expand */
    CHECK(fabs((grow[3] - 1) / (grow[2] - 1) - 1) < 0.1); /* and det F says by how much */
    CHECK(grow[1] < 0);                                /* so Tait pulls inside */
    /* without the gas law there is no pressure to read it: refused, by name */
    const double lo[3] = {0, 0, 0}, hi[3] = {0.1, 0.1, 0};
    hearth_scene_def d = sph_def(2, 0.005, lo, hi);
    d.sph.continuity_density = 1;
    hearth_error err;
    hearth_scene *s = hearth_scene_create(&d, &err);
    CHECK(s == NULL && strstr(err.msg, "sph.continuity_density") && strstr(err.msg, "sph.gas_law"));
    if (s) hearth_scene_destroy(s);
    else printf("refused: %s\n", err.msg);
}

/* ---- a bubble's gas: its own stiffness, not the dough's ------------------- */

/* A bubble holds an ideal gas at the oven's pressure P_a: CO2 whose moles are
 * fixed plus water vapour at a_w P_sat(T) (eq. 2.42-2.43), so at its volume V
 * its gauge pressure is (P_a - P_v)(V_b / V - 1), V_b the volume where it
 * stands at P_a (sph_bubble_volume). The gas's stiffness is P_a - P_v,
 * whatever dough holds it. A 2D block of dough 20 x 12 mm (no gravity, the
 * gas law with vapour 0.95, each particle's density from its own volume) with
 * its middle 6 x 6 mm bubble particles, all at 85 degC and at their raw
 * volume, one step: each bubble's pressure against the closed form computed
 * here, for a dough of bulk 1e6 Pa and one of 1e7 Pa (Tait B 1.4e5 and 1.4e6:
 * both stiffer than the gas), and for a soft one (bulk 1e4 Pa, B 1.4e3, as
 * soft as the raw bread roll's), which the dough's B used to cap at B (V_b -
 * 1), a fortieth of its gas (the time step now counts the gas's sound speed,
 * sph_gas.c sph_gas_sound_speed). Without sph.gas_pressure the bubble pushes
 * B (V_b - 1), ten times harder in the 1e7 dough than in the 1e6. Returns the
 * bubbles' mean pressure; *B their Tait B; *spread the largest difference
 * between bubbles. */
/* The block of dough with its middle 3 x 3 bubbles, at T everywhere, after
 * `steps` steps (the sum takes the gas law's rest volumes from the second,
 * sph.c rest_volume): dough of bulk `bulk`, sph.gas_pressure pa, the density
 * by the particle's own volume (continuity_density). NULL on a failure
 * (printed); *bub the bubbles' material. */
static hearth_scene *bubble_block(double bulk, double pa, double T, int steps, int *bub) {
    const double dx = 0.002, lo[3] = {0, 0, 0}, hi[3] = {0.04, 0.04, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.tension = 1;
    d.sph.gas_law = 1;
    d.sph.bubble_vapour = 0.95;
    d.sph.continuity_density = 1;
    d.sph.gas_pressure = pa;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return NULL;
    const char *n[] = {"density", "bulk", "viscosity", "bubble"};
    double v[] = {1100, bulk, 2.0, 0};
    hearth_error err;
    const int dough = hearth_scene_add_material(s, "newtonian", n, v, 4, &err);
    v[3] = 1;
    *bub = hearth_scene_add_material(s, "newtonian", n, v, 4, &err);
    for (int j = 0; j < 6 && dough >= 0 && *bub >= 0; j++)
        for (int i = 0; i < 10; i++) {
            double p[3] = {0.01 + (i + 0.5) * dx, 0.014 + (j + 0.5) * dx, 0};
            const int b = i >= 3 && i < 6 && j >= 1 && j < 4; /* the middle 3 x 3 */
            if (hearth_scene_add_particles(s, b ? *bub : dough, 1, p, NULL, dx * dx, &err) != 1)
                fprintf(stderr, "%s\n", err.msg);
        }
    sph_heat_speck(s, dough, 0.035, 0.035, T); /* turns the temperature field on */
    double *Tp = pcold(&s->ps, PC_TEMPERATURE);
    for (int i = 0; Tp && i < s->ps.n; i++) Tp[i] = T;
    if (Tp && hearth_scene_step(s, steps, &err) == HEARTH_OK) return s;
    fprintf(stderr, "%s\n", Tp ? err.msg : "no temperature field");
    hearth_scene_destroy(s);
    return NULL;
}

static double bubble_push(double bulk, double pa, double T, double *B, double *spread) {
    int bub;
    hearth_scene *s = bubble_block(bulk, pa, T, 1, &bub);
    double mean = NAN;
    *spread = NAN, *B = NAN;
    if (s) {
        const struct sph_state *st = s->sph;
        const int *mat = pcoli(&s->ps, PC_MAT);
        double sum = 0, lo_p = HUGE_VAL, hi_p = -HUGE_VAL;
        int nb = 0;
        for (int i = 0; i < s->ps.n; i++)
            if (mat[i] == bub) sum += st->prs[i], nb++, lo_p = fmin(lo_p, st->prs[i]), hi_p = fmax(hi_p, st->prs[i]), *B = st->B[i];
        mean = sum / nb, *spread = hi_p - lo_p;
        hearth_scene_destroy(s);
    }
    return mean;
}

TEST(sph_bubble_gas_pressure_is_the_gas) {
    const double T = 85, aw = 0.95, pa = 101325;
    const double pv = aw * 101325 * exp(-40660.0 / 8.314462618 * (1 / (T + 273.15) - 1 / 373.15));
    const double vb = vb_closed(aw, 26, T), want = (pa - pv) * (vb - 1); /* at the raw volume: V_b / V = V_b */
    double B1, B2, B3, B4, sp1, sp2, sp3, sp4;
    const double p1 = bubble_push(1e6, pa, T, &B1, &sp1), p2 = bubble_push(1e7, pa, T, &B2, &sp2);
    const double p3 = bubble_push(1e4, pa, T, &B3, &sp3), p4 = bubble_push(1e7, 0, T, &B4, &sp4);
    printf("85 degC, V_b %.4f, P_a - P_v %.1f Pa: gas pressure %.1f Pa (closed form)\n", vb, pa - pv, want);
    printf("dough bulk 1e6 (B %.4g): %.1f Pa (spread %.3g); bulk 1e7 (B %.4g): %.1f Pa (spread %.3g)\n", B1, p1, sp1, B2,
           p2, sp2);
    printf("soft dough bulk 1e4 (B %.4g): %.1f Pa (spread %.3g), B (V_b - 1) %.2f; without gas_pressure, bulk 1e7: %.1f "
           "Pa, B (V_b - 1) %.1f\n",
           B3, p3, sp3, B3 * (vb - 1), p4, B4 * (vb - 1));
    CHECK(B1 > pa && B2 > pa);            /* both doughs are stiffer than the gas */
    CHECK(fabs(p1 / want - 1) < 1e-3);    /* the gas's own pressure */
    CHECK(fabs(p2 / want - 1) < 1e-3);    /* whatever dough holds it */
    CHECK(sp1 < 1e-6 * want && sp2 < 1e-6 * want);
    CHECK(B3 < 0.1 * (pa - pv) && fabs(p3 / want - 1) < 1e-3 && sp3 < 1e-6 * want); /* a soft dough's B no longer caps it */
    CHECK(fabs(p4 / (B4 * (vb - 1)) - 1) < 1e-3);                 /* off: the dough's B, as before */
}

/* The same block read by sph.renormalised_density: at rest its outer row,
 * whose kernel hangs half over the free surface, reads no tension (the sum
 * alone read -0.231 B there), and its inside none either (the sum's +0.18 B
 * was the false skin squeezing it); set expanding, Tait pulls inside, as
 * with the particle's own volume, by about as much (within a third). */
TEST(sph_renormalised_density_reads_no_skin) {
    double ren[4], grow[4], own[4];
    skin_case(2, 0, 20, ren);
    skin_case(2, 5, 8, grow);
    skin_case(1, 5, 8, own);
    CHECK(fabs(ren[0]) < 1e-3 && fabs(ren[1]) < 1e-3); /* at rest nothing is stretched */
    CHECK(grow[2] > 1.005);                            /* the patch did expand */
    CHECK(grow[1] < 0 && fabs(grow[1] / own[1] - 1) < 0.34); /* and Tait pulls inside as by the own volume */
    const double lo[3] = {0, 0, 0}, hi[3] = {0.1, 0.1, 0};
    hearth_scene_def d = sph_def(2, 0.005, lo, hi);
    d.sph.renormalised_density = 1;
    hearth_error err;
    hearth_scene *s = hearth_scene_create(&d, &err); /* without the gas law: refused, by name */
    CHECK(s == NULL && strstr(err.msg, "sph.renormalised_density") && strstr(err.msg, "sph.gas_law"));
    if (s) hearth_scene_destroy(s);
    else printf("refused: %s\n", err.msg);
}

/* The six options that act through sph.gas_law's pressure are refused
 * without it, each by one table (sph_gas.c sph_gas_check_def): the messages word for
 * word as they were when each had its own check (scripts and users grep
 * them), and none of them once sph.gas_law is on. */
TEST(sph_gas_law_refusals_word_for_word) {
    static const char *want[] = {
        "scene: sph.continuity_density = true needs sph.gas_law = true (it is the gas law's pressure that reads the "
        "particle's own volume); set both or neither",
        "scene: sph.renormalised_density = true needs sph.gas_law = true (it is the gas law's pressure that reads it); "
        "set both or neither",
        "scene: sph.own_squeeze = true needs sph.gas_law = true (it is the gas law's dough that reads its squeeze from "
        "its own volume); set both or neither",
        "scene: sph.gas_pressure = 25000 Pa needs sph.gas_law = true (it is the gas law's bubble that holds the gas); "
        "set sph.gas_law = true or sph.gas_pressure = 0",
        "scene: sph.dough_water = 0.43 needs sph.gas_law = true (its CO2 comes out into the gas law's bubbles); set "
        "sph.gas_law = true or sph.dough_water = 0",
        "scene: sph.bubble_stays_open = true needs sph.gas_law = true (it is the gas law's bubble that opens at "
        "bubble_vmax); set both or neither",
    };
    const double lo[3] = {0, 0, 0}, hi[3] = {0.1, 0.1, 0};
    for (int k = 0; k < 6; k++)
        for (int law = 0; law < 2; law++) {
            hearth_scene_def d = sph_def(2, 0.005, lo, hi);
            d.sph.gas_law = law;
            d.sph.continuity_density = k == 0;
            d.sph.renormalised_density = k == 1;
            d.sph.own_squeeze = k == 2;
            d.sph.gas_pressure = k == 3 ? 2.5e4 : 0;
            d.sph.dough_water = k == 4 ? 0.43 : 0;
            d.sph.bubble_stays_open = k == 5;
            hearth_error err;
            err.msg[0] = 0;
            hearth_scene *s = hearth_scene_create(&d, &err);
            printf("option %d, gas_law %d: %s\n", k, law, s ? "accepted" : err.msg);
            CHECK(law ? s != NULL : s == NULL && strcmp(err.msg, want[k]) == 0);
            if (s) hearth_scene_destroy(s);
        }
}

/* What tears the roll with both switches on (docs/validation.md "Both
 * switches on"): the gas law's bubble pushes B (V_b / J - 1), the dough's
 * stiffness B for the gas's P_a - P_v, and V_b grows without bound toward
 * the dough's boiling point, so near the cap a bubble pushes many times its
 * gas, and the crust's last closed cells burst its top just before they
 * open. The block's bubbles at their raw volume (J = 1, one step, the
 * density by their own volume) at 70 and 91 degC (V_b 1.58 and 3.75, both
 * closed) against their ideal gas at that volume, (P_a - P_v0)(T / T0) +
 * P_v(T) - P_a (eq. 2.42-2.43, 3.49-3.50, computed here), with sph.gas_pressure
 * pa (0: B-stiff, the default; 101325 the roll's preset). */
static void near_cap_ratios(double pa_set, double ratio[2], double *B) {
    const double aw = 0.95, T0 = 26, pa = 101325, Ts[2] = {70, 91};
    for (int k = 0; k < 2; k++) {
        const double T = Ts[k], hr = 40660.0 / 8.314462618;
        const double pv0 = aw * pa * exp(-hr * (1 / (T0 + 273.15) - 1 / 373.15));
        const double pv = aw * pa * exp(-hr * (1 / (T + 273.15) - 1 / 373.15));
        const double ideal = (pa - pv0) * (T + 273.15) / (T0 + 273.15) + pv - pa;
        double spread;
        const double p = bubble_push(1e6, pa_set, T, B, &spread);
        ratio[k] = p / ideal;
        printf("%.0f degC: V_b %.4f, bubble pushes %.1f Pa (B %.4g), its ideal gas %.1f Pa: %.4fx\n", T,
               vb_closed(aw, T0, T), p, *B, ideal, ratio[k]);
        CHECK(ideal > 0 && p > 0);
    }
    printf("the ratio at 91 degC is %.4fx the one at 70 degC\n", ratio[1] / ratio[0]);
}

/* The gas law's default (sph.gas_pressure = 0: B-stiff bubbles; the bread
 * roll's preset sets the own gas since rolltray): a gas law whose stiffness is
 * its gas's keeps one ratio at every temperature; asked: the ratio at 91 degC
 * within 1.5x of the one at 70. Expected failure while the default's bubbles
 * are B-stiff. */
TEST(sph_gas_law_bubble_near_cap_within_its_gas) {
    double ratio[2], B;
    near_cap_ratios(0, ratio, &B);
    if (!(ratio[1] / ratio[0] < 1.5))
        XFAIL("at 91 degC a bubble pushes %.2fx its ideal gas, %.2fx the ratio at 70 degC (asked: within 1.5x): the gas "
              "law's pressure B (V_b / J - 1) takes the dough's stiffness for the gas's P_a - P_v, and V_b diverges at "
              "the boiling point; the bread roll's crust cells pushed up to 4.7x their gas near it while its preset "
              "left sph.gas_pressure at 0 (sph.gas_pressure = 101325 pushes the gas itself, "
              "sph_gas_law_own_gas_one_ratio, and is the roll's preset now)",
              ratio[1], ratio[1] / ratio[0]);
}

/* sph.gas_pressure = 101325: the same bubbles, each stiff as its own gas,
 * push their ideal gas exactly (the closed form above, ratio 1) at 70 as at
 * 91 degC, in a dough of Tait B 1.4e5 Pa, stiffer than that gas. */
TEST(sph_gas_law_own_gas_one_ratio) {
    double ratio[2], B;
    near_cap_ratios(101325, ratio, &B);
    printf("own gas: %.6fx and %.6fx their ideal gas at 70 and 91 degC (dough B %.4g)\n", ratio[0], ratio[1], B);
    CHECK(B > 101325);
    CHECK(fabs(ratio[0] - 1) < 1e-3 && fabs(ratio[1] - 1) < 1e-3);
}

/* The time step counts the bubble's gas. A gas-stiff bubble, p = K (rho /
 * rho_b - 1) with K = P_a - P_v, carries c^2 = K / rho_b = K V_b / rho0:
 * in the soft dough of sph_bubble_gas_pressure_is_the_gas (bulk 1e4 Pa, its
 * own wave 3.0 m/s) at 85 degC that is 10.3 m/s (computed here), so the CFL
 * step must be cfl dx / c_gas or shorter, before the first step (sph_dt.c,
 * from the materials and the gas) and after it (the step's c_max, sph.c
 * signal_speed); without sph.gas_pressure the dough's own wave sets it. */
static void gas_dt_case(double pa, double *dt0, double *dt1, double *cmax) {
    int bub;
    hearth_scene *s = bubble_block(1e4, pa, 85, 0, &bub);
    *dt0 = *dt1 = *cmax = NAN;
    if (!s) return;
    *dt0 = sph_stable_dt(s);
    hearth_error err;
    if (hearth_scene_step(s, 1, &err) == HEARTH_OK) *dt1 = sph_stable_dt(s), *cmax = s->c_max;
    hearth_scene_destroy(s);
}

TEST(sph_gas_sound_speed_limits_dt) {
    const double T = 85, aw = 0.95, pa = 101325, rho0 = 1100, dx = 0.002, cfl = 0.5;
    const double pv = aw * 101325 * exp(-40660.0 / 8.314462618 * (1 / (T + 273.15) - 1 / 373.15));
    const double cg = sqrt((pa - pv) * vb_closed(aw, 26, T) / rho0), limit = cfl * dx / cg;
    double g0, g1, gc, d0, d1, dc;
    gas_dt_case(pa, &g0, &g1, &gc);
    gas_dt_case(0, &d0, &d1, &dc);
    printf("gas sound speed %.4f m/s (closed form), CFL step %.4g s: with gas_pressure dt %.4g before the first step, "
           "%.4g after (c_max %.4f); without, %.4g and %.4g (c_max %.4f)\n",
           cg, limit, g0, g1, gc, d0, d1, dc);
    CHECK(g0 <= limit * (1 + 1e-9) && g1 <= limit * (1 + 1e-9));
    CHECK(fabs(gc / cg - 1) < 0.02); /* the step's report: the gas's speed (T moved one step) */
    CHECK(d0 > 2 * limit && dc < 0.5 * cg); /* the soft dough alone: its own, slower wave */
}

/* Which particles eq. 3.42 heats (sph_outer.c, #18). Two 2D bodies of rest
 * spacing dx 1 mm (h 2.4 mm), one step, no gravity:
 *  - a 40 x 30 mm block around a closed 10 x 10 mm cavity: the particles
 *    within dx of its outline are all outer, and none deeper than that (the
 *    cavity's walls take no oven heat: the body encloses them);
 *  - a 40 x 10 mm block under a layer of particles 2 dx apart (their rest
 *    volume still dx^2, as the angel food cake's expanded bubbles are): the
 *    layer's top row is outer, the dense block's top row under it is not.
 * The colour field's flag (st->surf, eq. 3.29), which eq. 3.42 heated before,
 * is printed beside: it marked the cavity's walls (40 particles) and missed 28
 * of the second body's 86 outline particles (there it did not mark the dense
 * row; in the risen cake it marked such rows, whose layers are not this
 * regular). */
static hearth_scene *outer_case(int sparse, double dx) {
    const double lo[3] = {0, 0, 0}, hi[3] = {0.08, 0.08, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.oven_temperature = 180;
    d.oven_beta = 0;
    d.sph.heat_ext = 1;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return NULL;
    const int m = newtonian(s, 1000, 1e4, 1.0);
    int ok = m >= 0;
    if (!sparse) { /* four boxes round the cavity [0.035, 0.045] x [0.03, 0.04] */
        ok = ok && box_body(s, m, 0.02, 0.02, 0.06, 0.03, 0, 26) >= 0 && box_body(s, m, 0.02, 0.04, 0.06, 0.05, 0, 26) >= 0;
        ok = ok && box_body(s, m, 0.02, 0.03, 0.035, 0.04, 0, 26) >= 0 && box_body(s, m, 0.045, 0.03, 0.06, 0.04, 0, 26) >= 0;
    } else { /* the dense block, and a 20 x 5 mm block stretched twofold about (0.02, 0.03) into the layer */
        ok = ok && box_body(s, m, 0.02, 0.02, 0.06, 0.03, 0, 26) >= 0;
        const int n0 = s->ps.n;
        ok = ok && box_body(s, m, 0.02, 0.03, 0.04, 0.035, 0, 26) >= 0;
        double *x = pcold(&s->ps, PC_X);
        for (int i = n0; i < s->ps.n; i++) x[3 * i] = 0.02 + 2 * (x[3 * i] - 0.02), x[3 * i + 1] = 0.03 + 2 * (x[3 * i + 1] - 0.03);
    }
    hearth_error err;
    if (!ok || hearth_scene_step(s, 1, &err) != HEARTH_OK) {
        hearth_scene_destroy(s);
        return NULL;
    }
    return s;
}

TEST(sph_oven_heats_outer_surface_only) {
    const double dx = 0.001;
    for (int sparse = 0; sparse < 2; sparse++) {
        hearth_scene *s = outer_case(sparse, dx);
        CHECK(s != NULL);
        if (!s) return;
        const double *x = hearth_scene_positions(s), *outer = sph_particle_values(s, "outer"),
                     *surf = sph_particle_values(s, "surface");
        CHECK(outer != NULL && surf != NULL);
        if (!outer || !surf) {
            hearth_scene_destroy(s);
            return;
        }
        int want = 0, got = 0, wrong = 0, cs_want = 0, cs_wrong = 0;
        for (int i = 0; i < s->ps.n; i++) {
            const double px = x[3 * i], py = x[3 * i + 1];
            int should, shouldnt;
            if (!sparse) { /* distance to the outline [0.02, 0.06] x [0.02, 0.05] */
                const double e = fmin(fmin(px - 0.02, 0.06 - px), fmin(py - 0.02, 0.05 - py));
                should = e < dx, shouldnt = e > 1.5 * dx;
            } else { /* the layer's top row (y 0.039) and the outline's sides and base; not the dense top row inside */
                const int inside_x = px > 0.02 + 3 * dx && px < 0.06 - 3 * dx;
                should = py > 0.038 || py < 0.02 + dx || px < 0.02 + 1.2 * dx || px > 0.06 - 1.2 * dx;
                shouldnt = inside_x && fabs(py - 0.0295) < 0.1 * dx;
            }
            want += should, got += should && outer[i] > 0.5, wrong += shouldnt && outer[i] > 0.5;
            cs_want += should && surf[i] > 0.5, cs_wrong += shouldnt && surf[i] > 0.5;
        }
        printf("%s: outer surface %d of the %d particles that should be, %d that should not; the colour field %d and %d\n",
               sparse ? "dense block under a layer 2 dx apart" : "block round a closed cavity", got, want, wrong, cs_want,
               cs_wrong);
        CHECK(want > 0 && got == want && wrong == 0);
        hearth_scene_destroy(s);
    }
}

TEST_MAIN(T(sph_heat_ext_flux_per_area), T(sph_heat_ext_slab_converges), T(sph_gas_law_clusters_reach_gas_volume),
          T(sph_heat_mirror_symmetric), T(sph_gas_law_films_keep_rest_spacing),
          T(sph_continuity_density_reads_no_skin), T(sph_bubble_gas_pressure_is_the_gas),
          T(sph_renormalised_density_reads_no_skin), T(sph_gas_law_refusals_word_for_word),
          T(sph_gas_law_bubble_near_cap_within_its_gas), T(sph_gas_law_own_gas_one_ratio), T(sph_gas_sound_speed_limits_dt),
          T(sph_oven_heats_outer_surface_only))
