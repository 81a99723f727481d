/* unit_sph_gas.c: the gas law's options (core/sim/solver/sph_gas.c). CO2
 * dissolved in the dough's water (sph.dough_water): Henry's law shares each
 * bubble's CO2 between its gas and an even share of the particles' water
 * (thesis eq. 2.44, Fan et al.), checked against closed forms computed here;
 * and the dough's squeeze read from its own volume (sph.own_squeeze). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hearth/hearth.h"
#include "scene.h"
#include "sph.h"
#include "sph_fixture.h"
#include "sph_state.h"
#include "test.h"

static const double R = 8.314462618, PA = 101325, AW = 0.95, T0 = 26;

/* CO2's Henry solubility H^cp in water, mol / (m^3 Pa): 3.3e-4 at 298.15 K,
 * d ln H / d(1/T) = 2400 K (Sander 2015, Atmos. Chem. Phys. 15, 4399). */
static double henry(double T) { return 3.3e-4 * exp(2400.0 * (1 / (T + 273.15) - 1 / 298.15)); }

/* The CO2's partial pressure in a bubble at the oven's pressure: P_a less
 * the vapour a_w P_sat(T) (eq. 2.43 through 100 degC, 40.66 kJ/mol). */
static double p_co2(double T) { return PA - AW * PA * exp(-40660.0 / R * (1 / (T + 273.15) - 1 / 373.15)); }

static hearth_sph_def gas_def(void) {
    hearth_sph_def o = hearth_default_scene_def().sph;
    o.gas_law = 1;
    o.bubble_vapour = AW;
    o.bubble_T0 = T0;
    o.bubble_vmax = 1e6; /* no cap: the balance itself */
    return o;
}

/* Moles of CO2 per unit raw gas volume: in the gas at volume V (per raw
 * volume) and P_c, n_g = P_c V / (R T), and dissolved in w of water at the
 * same P_c, n_d = H(T) P_c w. A closed bubble keeps n_g + n_d: each V_b that
 * sph_bubble_volume_dissolved gives at 26-90 degC holds the moles it held at
 * 26 degC, to rounding, for w = 0.5 and 2 (the roll's share is about 2). With
 * w = 0 it is sph_bubble_volume bit for bit; with water, the CO2 the water
 * gives up as H falls makes the bubble larger than the dry law's. */
TEST(sph_dissolved_co2_mole_balance) {
    const hearth_sph_def o = gas_def();
    const double ws[2] = {0.5, 2.0}, Ts[5] = {26, 50, 70, 85, 90};
    for (int a = 0; a < 2; a++) {
        const double w = ws[a];
        double n0 = NAN;
        for (int k = 0; k < 5; k++) {
            const double T = Ts[k], V = sph_bubble_volume_dissolved(&o, 1, T, w), pc = p_co2(T);
            const double ng = pc * V / (R * (T + 273.15)), nd = henry(T) * pc * w;
            if (k == 0) n0 = ng + nd;
            printf("w %.1f, %2.0f degC: V_b %.6f (dry law %.6f), CO2 in the gas %.4f, dissolved %.4f mol/m^3, total / "
                   "total at 26 degC - 1 = %.2e\n",
                   w, T, V, sph_bubble_volume(&o, 1, T), ng, nd, (ng + nd) / n0 - 1);
            CHECK(fabs((ng + nd) / n0 - 1) < 1e-12);
            if (k == 0) CHECK(fabs(V - 1) < 1e-12);
            else CHECK(V > sph_bubble_volume(&o, 1, T) && nd < henry(Ts[k - 1]) * p_co2(Ts[k - 1]) * w);
        }
    }
    for (int k = 0; k < 5; k++) CHECK(sph_bubble_volume_dissolved(&o, 1, Ts[k], 0) == sph_bubble_volume(&o, 1, Ts[k]));
}

/* A 2D SPH box 40 x 40 mm at spacing dx for a block of dough with bubbles:
 * no gravity, Tait's tension, the gas law with the dough's water activity
 * (vapour AW) and the bubbles' raw volume at T0. */
static hearth_scene_def bubbly_def(double dx) {
    const double lo[3] = {0, 0, 0}, hi[3] = {0.04, 0.04, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.tension = 1;
    d.sph.gas_law = 1;
    d.sph.bubble_vapour = AW;
    d.sph.bubble_T0 = T0;
    return d;
}

/* The share each bubble draws on, from the particles: a 2D block 10 x 6 at
 * 2 mm of dough (1100 kg/m^3) with 9 bubble particles of raw gas volume 1
 * and 3 of 2 (and a fixed speck, a wall), all at 60 degC, dough_water 0.43: w = 0.43 sum(m) / 1000 /
 * sum(bubble V0), the masses and volumes as placed here; after one step each
 * bubble's rest density is rho0 / V_b with V_b from the balance above at
 * that w (the closed form, computed here), and without the gas law the
 * option is refused by name. */
TEST(sph_dough_water_share_from_particles) {
    const double dx = 0.002, rho = 1100, T = 60, dw = 0.43;
    hearth_scene_def d = bubbly_def(dx);
    d.sph.dough_water = dw;
    hearth_error err;
    hearth_scene *s = hearth_scene_create(&d, &err);
    CHECK(s != NULL);
    if (!s) return;
    const char *n[] = {"density", "bulk", "viscosity", "bubble"};
    double v[] = {rho, 1e6, 2.0, 0};
    int mat[3];
    for (int b = 0; b < 3; b++) v[3] = b, mat[b] = hearth_scene_add_material(s, "newtonian", n, v, 4, &err);
    double mass = 0, gas = 0;
    for (int j = 0; j < 6; j++)
        for (int i = 0; i < 10; i++) {
            double p[3] = {0.01 + (i + 0.5) * dx, 0.014 + (j + 0.5) * dx, 0};
            const int b = i >= 3 && i < 6 && j >= 1 && j < 4 ? 1 : i == 8 && j < 3 ? 2 : 0;
            if (hearth_scene_add_particles(s, mat[b], 1, p, NULL, dx * dx, &err) != 1) fprintf(stderr, "%s\n", err.msg);
            mass += rho * dx * dx, gas += b * dx * dx;
        }
    sph_heat_speck(s, mat[0], 0.035, 0.035, T); /* turns the temperature field on; fixed: a wall, not dough */
    double *Tp = pcold(&s->ps, PC_TEMPERATURE);
    for (int i = 0; Tp && i < s->ps.n; i++) Tp[i] = T;
    CHECK(Tp && hearth_scene_step(s, 1, &err) == HEARTH_OK);
    const double want = dw * mass / 1000 / gas;
    const double pc0 = p_co2(T0), pc = p_co2(T), Tk = T + 273.15, T0k = T0 + 273.15;
    const double vb = Tk / T0k * pc0 / pc * (1 + henry(T0) * R * T0k * want) - henry(T) * R * Tk * want;
    printf("water per raw gas volume %.6f (placed: %.6f); V_b at %.0f degC %.6f (dry law %.6f)\n", s->sph->water_per_gas,
           want, T, vb, sph_bubble_volume(&d.sph, 1, T));
    CHECK(fabs(s->sph->water_per_gas / want - 1) < 1e-12);
    const int *pm = pcoli(&s->ps, PC_MAT);
    int nb = 0, ok = 1;
    for (int i = 0; i < s->ps.n; i++) {
        const double bub = pm[i] == mat[1] ? 1 : pm[i] == mat[2] ? 2 : 0;
        if (bub == 0) continue;
        nb++;
        ok &= fabs(s->sph->rhof[i] / (rho / (bub * vb)) - 1) < 1e-12;
    }
    CHECK(nb == 12 && ok);
    hearth_scene_destroy(s);
    d.sph.gas_law = 0;
    s = hearth_scene_create(&d, &err);
    CHECK(s == NULL && strcmp(err.msg, "scene: sph.dough_water = 0.43 needs sph.gas_law = true (its CO2 comes out into "
                                       "the gas law's bubbles); set sph.gas_law = true or sph.dough_water = 0") == 0);
    if (s) hearth_scene_destroy(s);
    else printf("refused: %s\n", err.msg);
}

/* ---- sph.own_squeeze: the dough's squeeze from its own volume ------------ */

/* A 2D block of dough 20 x 12 mm at 2 mm (bulk 1e6 Pa, Tait B 1.4e5, no
 * gravity), its middle 3 x 3 bubble particles, all at 60 degC and at their
 * raw volume, read as the bread roll's preset reads it (the gas law with
 * vapour 0.95 and the gas's own stiffness, tension, the renormalised sum),
 * after `steps` steps (the sum takes the gas law's rest volumes from the
 * second). The bubbles stand below their gas volume (V_b 1.34), as the set
 * crust holds the roll's (hotter: 1.3-1.7 against 3-4). Outputs over the dough particles within 1.5
 * spacings of a bubble: [0] their mean Tait pressure over B, [1] the largest
 * excess of a pressure over what its own volume gives, B ((1 / J)^7 - 1)
 * clamped at 0 from below, over B, [2] their mean det F - 1; [3] the bubbles'
 * mean pressure in Pa. */
static void held_bubbles(int own, int steps, double out[4]) {
    const double dx = 0.002, T = 60;
    hearth_scene_def d = bubbly_def(dx);
    d.sph.renormalised_density = 1;
    d.sph.gas_pressure = PA;
    d.sph.own_squeeze = own;
    d.energy_growth = 1e9; /* the sum's false squeeze sets the block moving at once: read it, do not stop */
    out[0] = out[1] = out[2] = out[3] = NAN;
    hearth_error err;
    hearth_scene *s = hearth_scene_create(&d, &err);
    if (!s) return;
    const char *n[] = {"density", "bulk", "viscosity", "bubble"};
    double v[] = {1100, 1e6, 2.0, 0};
    const int dough = hearth_scene_add_material(s, "newtonian", n, v, 4, &err);
    v[3] = 1;
    const int bub = hearth_scene_add_material(s, "newtonian", n, v, 4, &err);
    for (int j = 0; j < 6 && dough >= 0 && bub >= 0; j++)
        for (int i = 0; i < 10; i++) {
            double p[3] = {0.01 + (i + 0.5) * dx, 0.014 + (j + 0.5) * dx, 0};
            const int b = i >= 3 && i < 6 && j >= 1 && j < 4;
            if (hearth_scene_add_particles(s, b ? bub : dough, 1, p, NULL, dx * dx, &err) != 1)
                fprintf(stderr, "%s\n", err.msg);
        }
    sph_heat_speck(s, dough, 0.035, 0.035, T);
    double *Tp = pcold(&s->ps, PC_TEMPERATURE);
    for (int i = 0; Tp && i < s->ps.n; i++) Tp[i] = T;
    if (!Tp || hearth_scene_step(s, steps, &err) != HEARTH_OK) {
        fprintf(stderr, "%s\n", Tp ? err.msg : "no temperature field");
        hearth_scene_destroy(s);
        return;
    }
    const particles *ps = &s->ps;
    const double *x = pcold(ps, PC_X), *F = pcold(ps, PC_F);
    const int *mat = pcoli(ps, PC_MAT), *flags = pcoli(ps, PC_FLAGS);
    const struct sph_state *st = s->sph;
    double p = 0, excess = 0, dJ = 0, pb = 0;
    int nd = 0, nb = 0;
    for (int i = 0; i < ps->n; i++) {
        if (flags[i] & PF_FIXED) continue;
        if (mat[i] == bub) {
            pb += st->prs[i], nb++;
            continue;
        }
        int near = 0;
        for (int k = 0; k < ps->n && !near; k++)
            near = mat[k] == bub && hypot(x[3 * i] - x[3 * k], x[3 * i + 1] - x[3 * k + 1]) < 1.5 * dx;
        if (!near) continue;
        const double J = F[9 * i] * F[9 * i + 4] - F[9 * i + 1] * F[9 * i + 3];
        const double own_p = fmax(0, st->B[i] * (pow(1 / J, d.sph.gamma) - 1));
        p += st->prs[i] / st->B[i], dJ += J - 1, nd++;
        excess = fmax(excess, (st->prs[i] - own_p) / st->B[i]);
    }
    out[0] = p / nd, out[1] = excess, out[2] = dJ / nd, out[3] = pb / nb;
    printf("%s, %d steps: %d dough particles beside the %d bubbles: Tait p / B %.5f (mean), the largest excess over "
           "their own volume's %.3e B, det F - 1 %.2e (mean); the bubbles' pressure %.1f Pa\n",
           own ? "own_squeeze" : "the renormalised sum", steps, nd, nb, out[0], out[1], out[2], out[3]);
    hearth_scene_destroy(s);
}

/* The sum over rest volumes lends a held-back bubble's missing volume to its
 * dough neighbours, which read a squeeze their own det F (within 1e-3 of 1
 * here: the block has barely moved) does not have: Tait charges it at gamma
 * 7 (docs/validation.md "Why the roll's base leaves its tray"). With
 * sph.own_squeeze no dough particle's pressure exceeds its own volume's, and
 * the bubbles still push with their gas. (Without the gas law it is refused:
 * sph_gas_law_refusals_word_for_word, unit_sph_heat.c.) */
TEST(sph_own_squeeze_dough_beside_held_bubble) {
    double sum[4], own[4];
    held_bubbles(0, 2, sum);
    held_bubbles(1, 2, own);
    CHECK(fabs(sum[2]) < 1e-3 && fabs(own[2]) < 1e-3); /* nothing has moved: the dough holds its own volume */
    CHECK(sum[0] > 0.05 && sum[1] > 0.05);            /* the sum's false squeeze */
    CHECK(own[1] <= 1e-12 && fabs(own[0]) < 1e-2);     /* no more than its own volume says */
    CHECK(own[3] > 0.5 * sum[3] && own[3] > 1e4);      /* the bubbles push with their gas either way */
}

/* Where the sum reads a stretch, own_squeeze keeps it, bit for bit (the
 * films' cohesion, docs/validation.md "The films' tension"); where the dough
 * is truly squeezed both read it. A dough block 40 x 24 mm (no bubbles, the
 * renormalised sum, tension, no gravity, B 1.4e4) set expanding, then
 * compressing, v = rate (x - c), 8 steps: every particle's pressure with and
 * without the option; *in the inside's mean p / B, with and without. */
/* The dough block both tests below use: 40 x 24 mm at dx 2 mm in a 100 x 80 mm
 * box, the renormalised sum, tension, the gas law, no gravity; own_squeeze
 * as asked. NULL when the scene or the block cannot be made. */
static hearth_scene *dough_block(int own) {
    const double dx = 0.002, lo[3] = {0, 0, 0}, hi[3] = {0.1, 0.08, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.tension = 1;
    d.sph.gas_law = 1;
    d.sph.renormalised_density = 1;
    d.sph.own_squeeze = own;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return NULL;
    const int m = newtonian(s, 1100, 1e5, 2.0);
    const double blo[3] = {0.03, 0.028, 0}, bhi[3] = {0.07, 0.052, 0};
    if (m >= 0 && sph_box(s, m, blo, bhi, 0, 26) >= 0) return s;
    hearth_scene_destroy(s);
    return NULL;
}

static double block_pressure(int own, double rate, double *in) {
    const double c[2] = {0.05, 0.04};
    hearth_scene *s = dough_block(own);
    *in = NAN;
    double sum = NAN;
    hearth_error err;
    if (s) {
        double *v = pcold(&s->ps, PC_V);
        const double *x = pcold(&s->ps, PC_X);
        for (int i = 0; i < s->ps.n; i++) v[3 * i] = rate * (x[3 * i] - c[0]), v[3 * i + 1] = rate * (x[3 * i + 1] - c[1]);
        if (hearth_scene_step(s, 8, &err) == HEARTH_OK) {
            const struct sph_state *st = s->sph;
            double pi = 0;
            int ni = 0;
            sum = 0;
            for (int i = 0; i < s->ps.n; i++) {
                sum += st->prs[i] * (i + 1); /* order-weighted: a change anywhere shows */
                if (!st->surf[i]) pi += st->prs[i] / st->B[i], ni++;
            }
            *in = pi / ni;
        } else fprintf(stderr, "%s\n", err.msg);
    }
    hearth_scene_destroy(s);
    return sum;
}

TEST(sph_own_squeeze_keeps_stretch_and_true_squeeze) {
    double in_sum, in_own, c_sum, c_own;
    const double e_sum = block_pressure(0, 5, &in_sum), e_own = block_pressure(1, 5, &in_own);
    printf("expanding: inside p / B %.6f (sum), %.6f (own_squeeze); pressures' weighted sums %.17g and %.17g\n", in_sum,
           in_own, e_sum, e_own);
    CHECK(in_sum < 0 && e_sum == e_own); /* the stretch is the sum's, untouched */
    block_pressure(0, -5, &c_sum);
    block_pressure(1, -5, &c_own);
    printf("compressing: inside p / B %.6f (sum), %.6f (own_squeeze)\n", c_sum, c_own);
    CHECK(c_sum > 0 && c_own > 0.8 * c_sum && c_own <= c_sum * (1 + 1e-12)); /* a true squeeze both read */
}

/* Two dough particles pushed within 0.4 spacings of each other in a block at
 * rest (the bread roll's hot dough, helper sphbounce: of the 20 particles
 * past 0.25 m/s in 1.5-1.8 s at 2 mm, 13 had a neighbour within 0.30-0.78
 * spacings, and 14 of the 16 dough ones stood at p = 0 with a summed density
 * 1.1-1.5x rest; docs/validation.md "The roll's bounce on its tray"). The renormalised sum reads the pair squeezed
 * and Tait pushes it apart; own_squeeze reads the squeeze from det F, which
 * the smoothed velocity gradient of eq. 3.27 keeps at 1 for a pair that
 * closes inside one kernel, so the pair gets no pressure at all. A 40 x 24 mm
 * block at 2 mm, no gravity, B 1.4e4, one step after the move: the pair's
 * mean Tait pressure and the acceleration that parts it (along the pair,
 * positive apart). The bar, stated before measuring: with own_squeeze the
 * pair's pressure at least half the sum's, since no volume the dough can hold
 * brings two particles within 0.4 spacings and the sum is what sees it. */
static void pair_closed(int own, double *p, double *apart) {
    const double dx = 0.002;
    *p = *apart = NAN;
    hearth_scene *s = dough_block(own);
    hearth_error err;
    if (s) {
        double *x = pcold(&s->ps, PC_X);
        const int *id = pcoli(&s->ps, PC_ID);
        int a = -1, b = -1; /* the particle nearest the middle and its right-hand neighbour */
        for (int i = 0; i < s->ps.n; i++)
            if (a < 0 || hypot(x[3 * i] - 0.05, x[3 * i + 1] - 0.04) < hypot(x[3 * a] - 0.05, x[3 * a + 1] - 0.04)) a = i;
        for (int i = 0; i < s->ps.n; i++)
            if (fabs(x[3 * i] - x[3 * a] - dx) < 1e-9 && fabs(x[3 * i + 1] - x[3 * a + 1]) < 1e-9) b = i;
        if (b >= 0) {
            x[3 * b] -= 0.6 * dx;
            const int ia = id[a], ib = id[b];
            if (hearth_scene_step(s, 1, &err) == HEARTH_OK) {
                const struct sph_state *st = s->sph;
                const int *nid = pcoli(&s->ps, PC_ID);
                for (int i = 0; i < s->ps.n; i++) { /* the step sorts the particles: find the pair again */
                    if (nid[i] == ia) a = i;
                    if (nid[i] == ib) b = i;
                }
                *p = 0.5 * (st->prs[a] + st->prs[b]);
                *apart = st->acc[3 * b] - st->acc[3 * a];
            } else fprintf(stderr, "%s\n", err.msg);
        }
    }
    hearth_scene_destroy(s);
}

TEST(sph_own_squeeze_resists_pairing) {
    double p_sum, a_sum, p_own, a_own;
    pair_closed(0, &p_sum, &a_sum);
    pair_closed(1, &p_own, &a_own);
    printf("a pair at 0.4 spacings: Tait p %.1f Pa and parting acceleration %.1f m/s^2 (the sum); %.1f Pa and %.1f "
           "m/s^2 (own_squeeze)\n", p_sum, a_sum, p_own, a_own);
    CHECK(p_sum > 0 && a_sum > 0); /* the sum reads the pair and pushes it apart */
    if (!(p_own >= 0.5 * p_sum))
        XFAIL("with sph.own_squeeze a pair of dough particles closed to 0.4 spacings gets p = %.1f Pa against the "
              "sum's %.1f (parting acceleration %.1f m/s^2 against %.1f): its own det F says 1, so nothing holds "
              "particles apart, and in the bread roll's hot base they pair and spring apart at 0.2-0.6 m/s, the "
              "noise that sets the roll hopping on its tray (docs/validation.md \"The roll's bounce on its tray\"); "
              "sph.hourglass (sph_hourglass.c, off in the roll's preset) damps such pairs' motion (at 2 mm 1.5-1.9 s "
              "with a particle past 0.25 m/s 0.206 -> 0.021, no hop), but pushes no pair that is already close: this "
              "one reads the same with it",
              p_own, p_sum, a_own, a_sum);
}

TEST_MAIN(T(sph_dissolved_co2_mole_balance), T(sph_dough_water_share_from_particles),
          T(sph_own_squeeze_dough_beside_held_bubble), T(sph_own_squeeze_keeps_stretch_and_true_squeeze),
          T(sph_own_squeeze_resists_pairing))
