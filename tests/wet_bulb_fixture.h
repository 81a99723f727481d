/* wet_bulb_fixture.h: the #18 wet-bulb reproducer's run and checks, the same
 * for both solvers (unit_latent.c: MPM; unit_sph_water.c: SPH). Each test
 * builds its own pinned wet block; this steps it for 1 s, takes the coldest
 * particle after every step, and checks it against the wet bulb T_wb of its
 * initial saturation s0 (water_reference.h's wet_bulb_vapour, the test's own
 * closed form) and the latent books. Needs test.h's CHECK and scene.h. */
#ifndef HEARTH_WET_BULB_FIXTURE_H
#define HEARTH_WET_BULB_FIXTURE_H
#include <math.h>
#include <stdio.h>

#include "hearth/hearth.h"
#include "scene.h"
#include "test.h"

/* Steps s for 1 s and checks: the closed form itself is a temperature
 * (finite, above absolute zero, below the start T0); every particle stays
 * finite; the coldest stays above T_wb; the sink acts (the coldest falls more
 * than 10 K below T0, where the oven alone would warm it); heat in through
 * the oven = sensible + L x water lost, to 1%. Destroys s. */
static inline void wet_bulb_run_checks(hearth_scene *s, double T_wb, double T0, double s0) {
    hearth_stats st;
    hearth_scene_stats(s, &st);
    const double E0 = st.heat_energy, W0 = st.water_mass;
    hearth_error err;
    double lo = INFINITY, t_lo = 0;
    int finite = 1;
    while (hearth_scene_time(s) < 1.0 - 1e-12) {
        CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
        const double *T = pcold(&s->ps, PC_TEMPERATURE);
        for (int i = 0; i < s->ps.n; i++) {
            finite &= isfinite(T[i]);
            if (T[i] < lo) lo = T[i], t_lo = hearth_scene_time(s);
        }
    }
    hearth_scene_stats(s, &st);
    const double dE = st.heat_energy - E0, dW = W0 - st.water_mass, Q = st.oven_heat_in;
    const double miss = (dE + HEARTH_LATENT_HEAT * dW - Q) / Q;
    printf("  %ld steps, t = %.3f s: coldest particle %.2f degC (at %.3f s) against the wet bulb %.2f degC of s = %.2f; "
           "heat in %.6g J/m = sensible %.6g + L x water %.6g; imbalance %.3g\n",
           st.step, st.t, lo, t_lo, T_wb, s0, Q, dE, HEARTH_LATENT_HEAT * dW, miss);
    CHECK(isfinite(T_wb) && T_wb > -273.15 && T_wb < T0); /* the closed form itself */
    CHECK(finite);
    CHECK(lo > T_wb);
    CHECK(lo < T0 - 10); /* the sink acts */
    CHECK(fabs(miss) < 0.01);
    hearth_scene_destroy(s);
}
#endif
