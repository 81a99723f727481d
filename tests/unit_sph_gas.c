/* unit_sph_gas.c: CO2 dissolved in the dough's water (sph.dough_water,
 * core/sim/solver/sph_gas.c): Henry's law shares each bubble's CO2 between
 * its gas and an even share of the particles' water (thesis eq. 2.44, Fan
 * et al.), checked against closed forms computed here. */
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

/* The share each bubble draws on, from the particles: a 2D block 10 x 6 at
 * 2 mm of dough (1100 kg/m^3) with 9 bubble particles of raw gas volume 1
 * and 3 of 2 (and a fixed speck, a wall), all at 60 degC, dough_water 0.43: w = 0.43 sum(m) / 1000 /
 * sum(bubble V0), the masses and volumes as placed here; after one step each
 * bubble's rest density is rho0 / V_b with V_b from the balance above at
 * that w (the closed form, computed here), and without the gas law the
 * option is refused by name. */
TEST(sph_dough_water_share_from_particles) {
    const double dx = 0.002, lo[3] = {0, 0, 0}, hi[3] = {0.04, 0.04, 0}, rho = 1100, T = 60, dw = 0.43;
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.tension = 1;
    d.sph.gas_law = 1;
    d.sph.bubble_vapour = AW;
    d.sph.bubble_T0 = T0;
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

TEST_MAIN(T(sph_dissolved_co2_mole_balance), T(sph_dough_water_share_from_particles))
