/* unit_sph_surface.c: the face temperature SPH's outer particles brown at (issue #18, helper sphsurface;
 * core/sim/solver/sph_heat.c's sph_surface_temperatures, the air-film closure shared with MPM in thermal.h):
 * against the Robin slab's series at three resolutions, and what browning.c integrates from it; and that a scene
 * that reads no face temperatures or no outer surface makes none (helper userfix6). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hearth/hearth.h"
#include "scene.h"
#include "sph.h"
#include "sph_fixture.h"
#include "sph_state.h"
#include "sph_robin_slab.h"
#include "test.h"

/* The Robin slab of sph_heat_ext_slab_converges (Bi = 1, Fo = 0.3, 10, 20 and 40 particles across 2L = 20 mm): the
 * face temperature the closure gives the outer rows against the series at the face. The bars, set at 12:27 UTC
 * on 2026-12-07 before the first SPH run of the closure (from a 1D finite-volume model of the same discretisation,
 * which read the face's error 0.025 / 0.013 / 0.0065 of T0 - T_ext with the closure and 0.032 / 0.016 / 0.008
 * with the particle's own temperature): the closure's error falls with dx, by a factor of at most 0.7 per halving,
 * and at every resolution it is below the error of reading the particle's own temperature as the face's (the
 * reason to read the closure at all). Printed too: the particle's own error against the series at its own depth
 * (what the centre is, dx/2 under the face) and the closure's signed error. */
TEST(sph_surface_temperature_slab_matches_series) {
    const int Ns[] = {10, 20, 40};
    robin_slab_face f[3];
    for (int r = 0; r < 3; r++) {
        double E, Q, Qx;
        CHECK(robin_slab(Ns[r], &E, &Q, &Qx, &f[r]) == 0);
        printf("Robin slab, %d across (%d outer particles): face theta* series %.5f; error of the face reading %.5f "
               "(signed %+.5f), of the particle's own T read as the face's %.5f, of its own T at its depth %.5f\n",
               Ns[r], f[r].n, f[r].series_face, f[r].face_err, f[r].face_bias, f[r].own_err, f[r].depth_err);
        CHECK(f[r].n > 0 && f[r].face_err < f[r].own_err);
    }
    for (int r = 1; r < 3; r++) {
        const double ratio = f[r].face_err / f[r - 1].face_err;
        printf("Robin slab: %d -> %d across, face reading's error ratio %.3f (bar 0.7), observed order %.2f\n", Ns[r - 1],
               Ns[r], ratio, log(1 / ratio) / log(2.0));
        CHECK(ratio <= 0.7);
    }
}

/* The same slab with the oven's flux moved in by the film (sph_heat.c's sph_film_share: the flux crosses the half
 * spacing between the face and the outer particle's centre, h (T_ext - T_i) / (1 + h d / kappa), thermal.h's
 * thermal_film_den, as MPM's find_boundary). Against the series: the heat taken, and the face reading. The bars,
 * set at 15:01 UTC on 2026-12-07 before the first run of the committed code, from the 1D finite-volume model of
 * the same discretisation (scripts/validation/sph_surface_fv.py --film: the face's error 0.0022 / 0.00056 / 0.00014,
 * order 2) and from the old bar of sph_heat_ext_slab_converges (within 2% at 40 across): the heat taken within 2%
 * of the series at every resolution, its error falling by at least half per halving (order >= 1); the face
 * reading's error under 0.005 at 10 across and falling by a factor of at most 0.4 per halving (order >= 1.3). */
TEST(sph_surface_flux_through_film_matches_series) {
    const int Ns[] = {10, 20, 40};
    robin_slab_face f[3];
    double E[3], Q[3], Qx[3], qe[3];
    for (int r = 0; r < 3; r++) {
        CHECK(robin_slab(Ns[r], &E[r], &Q[r], &Qx[r], &f[r]) == 0);
        qe[r] = Q[r] / Qx[r] - 1;
        printf("Robin slab through the film, %d across: heat taken %.5f of the most, series %.5f (%+.3f%%, bar 2%%); "
               "face reading's error %.5f (signed %+.5f); worst profile error %.5f\n",
               Ns[r], Q[r], Qx[r], 100 * qe[r], f[r].face_err, f[r].face_bias, E[r]);
        CHECK(fabs(qe[r]) < 0.02);
    }
    CHECK(f[0].face_err < 0.005);
    for (int r = 1; r < 3; r++) {
        const double qr = fabs(qe[r] / qe[r - 1]), fr = f[r].face_err / f[r - 1].face_err;
        printf("Robin slab through the film: %d -> %d across, heat taken's error ratio %.3f (bar 0.5), order %.2f; "
               "face reading's ratio %.3f (bar 0.4), order %.2f\n",
               Ns[r - 1], Ns[r], qr, log(1 / qr) / log(2.0), fr, log(1 / fr) / log(2.0));
        CHECK(qr <= 0.5 && fr <= 0.4);
    }
}

/* Zanoni et al. 1995's first-order kinetics, written out here rather than taken from browning.c: k0 42000 1/s,
 * Ea 64151 J/mol. */
static double zanoni_k(double T) { return 42000.0 * exp(-64151.0 / (8.314462618 * (T + 273.15))); }

/* A pinned 2D block 20 x 10 mm at dx 1 mm, 150 degC in a 200 degC oven by eq. 3.42 (k_h,ext 20, k_h,int 1,
 * kg/(m^2 s) and kg/(m s): h d / kappa = 20 x 0.0005 / 1 = 0.01 on the half-spacing d), browning on, no water,
 * one step: an outer particle's index is the kinetics' at the closure's face temperature, written out here
 * (200 - (200 - T_i) / (1 + 0.01)), an interior particle's at its own temperature; the oven's side is hotter, so
 * the outer one browns more than its own temperature would. The bars: within 1e-12 relative of those values. */
TEST(sph_outer_browns_at_face_temperature) {
    const double dx = 0.001, lo[3] = {0, 0, 0}, hi[3] = {0.04, 0.03, 0}, Text = 200, T0 = 150;
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.heat_ext = 20;
    d.sph.heat_int = 1;
    d.oven_temperature = Text;
    d.oven_beta = 0;
    d.browning = 1;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    CHECK(s != NULL);
    if (!s) return;
    const int m = newtonian(s, 1000, 1e4, 1.0);
    const double blo[3] = {0.01, 0.01, 0}, bhi[3] = {0.03, 0.02, 0};
    CHECK(m >= 0 && sph_box(s, m, blo, bhi, 1, T0) >= 0);
    hearth_error err;
    CHECK(hearth_scene_step(s, 1, &err) == HEARTH_OK);
    const double *outer = sph_particle_values(s, "outer"), *ts = sph_particle_values(s, "surface_temperature");
    const double *T = pcold(&s->ps, PC_TEMPERATURE), *b = pcold(&s->ps, PC_BROWNING), dt = s->dt_last;
    CHECK(outer != NULL && ts != NULL);
    int no = 0, ni = 0, bad = 0;
    double worst = 0, gain = 0;
    for (int i = 0; outer && ts && i < s->ps.n; i++) {
        const int out = outer[i] > 0.5;
        const double Tb = out ? Text - (Text - T[i]) / (1 + 20 * 0.5 * dx / 1) : T[i];
        const double want = -expm1(-zanoni_k(Tb) * dt), rel = fabs(b[i] / want - 1);
        worst = fmax(worst, rel);
        bad += out ? !(fabs(ts[i] - Tb) < 1e-9) : !isnan(ts[i]);
        if (out) no++, gain += b[i] / -expm1(-zanoni_k(T[i]) * dt);
        else ni++;
    }
    printf("%d outer, %d interior particles: worst relative gap to the kinetics at the face (outer) or own (interior) "
           "temperature %.2e; outer particles brown %.4f times what their own temperature gives; %d face readings off\n",
           no, ni, worst, no ? gain / no : 0.0, bad);
    CHECK(no > 0 && ni > 0 && worst < 1e-12 && bad == 0 && gain / no > 1);
    hearth_scene_destroy(s);
}

/* A scene pays only for the physics it uses (#18, helper userfix6): the face temperatures are browning.c's alone, so
 * a scene that does not brown makes none. Twin 2D blocks 20 x 10 mm at dx 1 mm, 150 degC in a 200 degC oven by eq.
 * 3.42 (k_h,ext 20, k_h,int 1), free to move (gravity on, on the domain's floor), one browning and one not. The
 * bars, set at 15:10 UTC before the first run: after a step the one that does not brown gives no face temperatures
 * (particle_values NULL; the other gives them), and a second step leaves its face temperatures' slots as the test
 * wrote them (a sentinel in each: nothing computed them); after 40 steps both hold the same positions, velocities and
 * temperatures bit for bit (the face temperatures feed browning alone), and the browning one has browned. */
static hearth_scene *oven_block(int browning) {
    const double dx = 0.001, lo[3] = {0, 0, 0}, hi[3] = {0.04, 0.03, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.sph.heat_ext = 20;
    d.sph.heat_int = 1;
    d.oven_temperature = 200;
    d.oven_beta = 0;
    d.browning = browning;
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return NULL;
    const int m = newtonian(s, 1000, 1e4, 1.0);
    const double blo[3] = {0.01, 0.0, 0}, bhi[3] = {0.03, 0.01, 0};
    if (m < 0 || sph_box(s, m, blo, bhi, 0, 150) < 0) {
        hearth_scene_destroy(s);
        return NULL;
    }
    return s;
}

TEST(sph_surface_temperature_skipped_without_browning) {
    hearth_scene *off = oven_block(0), *on = oven_block(1);
    CHECK(off != NULL && on != NULL);
    if (!off || !on) {
        if (off) hearth_scene_destroy(off);
        if (on) hearth_scene_destroy(on);
        return;
    }
    hearth_error err;
    CHECK(hearth_scene_step(off, 1, &err) == HEARTH_OK && hearth_scene_step(on, 1, &err) == HEARTH_OK);
    const double *ts_off = sph_particle_values(off, "surface_temperature"), *ts_on = sph_particle_values(on, "surface_temperature");
    const int n = off->ps.n;
    int faces = 0;
    for (int i = 0; ts_on && i < n; i++) faces += !isnan(ts_on[i]);
    /* the sentinel slots, where the scene without browning has the array (since helper userfix7 it has none,
     * sph_surface_temperature_not_allocated_without_browning: then nothing can be written and none is touched) */
    const double SENTINEL = -12345.0;
    for (int i = 0; off->sph->ts && i < n; i++) off->sph->ts[i] = SENTINEL;
    CHECK(hearth_scene_step(off, 1, &err) == HEARTH_OK && hearth_scene_step(on, 1, &err) == HEARTH_OK);
    int touched = 0;
    for (int i = 0; off->sph->ts && i < n; i++) touched += off->sph->ts[i] != SENTINEL;
    CHECK(hearth_scene_step(off, 38, &err) == HEARTH_OK && hearth_scene_step(on, 38, &err) == HEARTH_OK);
    const particles *a = &off->ps, *b = &on->ps;
    const size_t v3 = sizeof(double) * 3 * (size_t)n, v1 = sizeof(double) * (size_t)n;
    const int same = a->n == b->n && off->step == on->step && off->t == on->t &&
                     !memcmp(pcold(a, PC_X), pcold(b, PC_X), v3) && !memcmp(pcold(a, PC_V), pcold(b, PC_V), v3) &&
                     !memcmp(pcold(a, PC_TEMPERATURE), pcold(b, PC_TEMPERATURE), v1);
    double bmax = 0;
    for (int i = 0; i < b->n; i++) bmax = fmax(bmax, pcold(b, PC_BROWNING)[i]);
    printf("%d particles; after a step: face temperatures %s without browning, %s with it (%d outer particles' faces); "
           "a second step without browning rewrote %d of its %d sentinel slots (need 0); after %ld steps positions, "
           "velocities and temperatures %s (need the same bits); the browning block's most browned %.3e (need > 0)\n",
           n, ts_off ? "given" : "none", ts_on ? "given" : "none", faces, touched, n, off->step,
           same ? "the same bits" : "DIFFER", bmax);
    CHECK(ts_off == NULL && ts_on != NULL && faces > 0);
    CHECK(touched == 0);
    CHECK(same && off->step == 40 && bmax > 0);
    hearth_scene_destroy(off);
    hearth_scene_destroy(on);
}

/* #18, helper userfix7: the face temperatures' array itself (st->ts, a double a particle with ensure's 1/4 margin) was
 * allocated with the step's columns in every SPH scene, browning or not. The twin oven blocks above; the bars, set at
 * 17:55 UTC before the first run: after 5 steps the scene without browning holds no array (NULL) and the one with it
 * does; the solver's bytes_per_particle estimate (what `hearth run --memory` and the particle ceiling read) is 10
 * bytes (8 x 1.25) lower without browning; and the library's bytes held by the scene without browning are lower than
 * the same scene's bytes would be with the array, by at least the array's 8 x cap bytes (read from the two scenes'
 * held bytes: the browning twin also carries the browning column, 8 bytes a particle, so the gap is at least 16 x n). */
TEST(sph_surface_temperature_not_allocated_without_browning) {
    const size_t b0 = hearth_bytes_allocated();
    hearth_scene *off = oven_block(0);
    hearth_error err;
    CHECK(off != NULL);
    if (!off) return;
    CHECK(hearth_scene_step(off, 5, &err) == HEARTH_OK);
    const size_t b_off = hearth_bytes_allocated() - b0;
    hearth_scene *on = oven_block(1);
    CHECK(on != NULL);
    if (!on) {
        hearth_scene_destroy(off);
        return;
    }
    CHECK(hearth_scene_step(on, 5, &err) == HEARTH_OK);
    const size_t b_on = hearth_bytes_allocated() - b0 - b_off;
    const int n = off->ps.n, cap = off->sph->cap;
    const double per_off = sph_solver.bytes_per_particle(off), per_on = sph_solver.bytes_per_particle(on);
    printf("%d particles (cap %d): face temperatures' array %s without browning, %s with it; bytes_per_particle %.2f "
           "without, %.2f with (need 10 less); bytes held %zu without, %zu with: %zd more (need >= 16 x n = %d)\n", n,
           cap, off->sph->ts ? "ALLOCATED" : "none", on->sph->ts ? "allocated" : "NONE", per_off, per_on, b_off, b_on,
           (ptrdiff_t)(b_on - b_off), 16 * n);
    CHECK(off->sph->ts == NULL && on->sph->ts != NULL);
    CHECK(fabs((per_on - per_off) - 10.0) < 1e-9);
    CHECK(b_on >= b_off + (size_t)16 * (size_t)n);
    hearth_scene_destroy(off);
    hearth_scene_destroy(on);
}

/* The same for the outer surface (sph_outer.c; #18, helper userfix6: 22% of funnel.lua's run, a fluid with no heat
 * and no water). Its readers all come with the flags column (temperature, water, a fixed body), so a block with none
 * makes no outer surface. Twin 2D blocks of a Newtonian fluid 20 x 10 mm at dx 1 mm under gravity: one without a
 * temperature, one at a uniform 20 degC with no oven and no conduction (its temperature moves nothing). The bars, set
 * at 15:20 UTC before the first run: after a step the first gives no outer surface (particle_values NULL) and the
 * second does (some particles on it); a second step leaves the first's outer slots as the test wrote them (a
 * sentinel); after 40 steps the two hold the same positions and velocities bit for bit. */
static hearth_scene *plain_block(double T) {
    const double dx = 0.001, lo[3] = {0, 0, 0}, hi[3] = {0.04, 0.03, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return NULL;
    const int m = newtonian(s, 1000, 1e4, 1.0);
    const double blo[3] = {0.01, 0.0, 0}, bhi[3] = {0.03, 0.01, 0};
    if (m < 0 || sph_box(s, m, blo, bhi, 0, T) < 0) {
        hearth_scene_destroy(s);
        return NULL;
    }
    return s;
}

TEST(sph_outer_surface_skipped_without_readers) {
    hearth_scene *bare = plain_block(NAN), *warm = plain_block(20);
    CHECK(bare != NULL && warm != NULL);
    if (!bare || !warm) {
        if (bare) hearth_scene_destroy(bare);
        if (warm) hearth_scene_destroy(warm);
        return;
    }
    hearth_error err;
    CHECK(hearth_scene_step(bare, 1, &err) == HEARTH_OK && hearth_scene_step(warm, 1, &err) == HEARTH_OK);
    const double *o_bare = sph_particle_values(bare, "outer"), *o_warm = sph_particle_values(warm, "outer");
    const int n = bare->ps.n;
    int outer = 0;
    for (int i = 0; o_warm && i < warm->ps.n; i++) outer += o_warm[i] > 0.5;
    const double SENTINEL = -7.0;
    for (int i = 0; i < n; i++) bare->sph->outer[i] = SENTINEL;
    CHECK(hearth_scene_step(bare, 1, &err) == HEARTH_OK && hearth_scene_step(warm, 1, &err) == HEARTH_OK);
    int touched = 0;
    for (int i = 0; i < n; i++) touched += bare->sph->outer[i] != SENTINEL;
    CHECK(hearth_scene_step(bare, 38, &err) == HEARTH_OK && hearth_scene_step(warm, 38, &err) == HEARTH_OK);
    const particles *a = &bare->ps, *b = &warm->ps;
    const size_t v3 = sizeof(double) * 3 * (size_t)n;
    const int same = a->n == b->n && bare->step == warm->step && bare->t == warm->t &&
                     !memcmp(pcold(a, PC_X), pcold(b, PC_X), v3) && !memcmp(pcold(a, PC_V), pcold(b, PC_V), v3);
    printf("%d particles; after a step: outer surface %s without a temperature, %s at 20 degC (%d particles on it); a "
           "second step without one rewrote %d of its %d sentinel slots (need 0); after %ld steps positions and "
           "velocities %s (need the same bits)\n", n, o_bare ? "made" : "none", o_warm ? "made" : "none", outer,
           touched, n, bare->step, same ? "the same bits" : "DIFFER");
    CHECK(o_bare == NULL && o_warm != NULL && outer > 0);
    CHECK(touched == 0);
    CHECK(same && bare->step == 40);
    hearth_scene_destroy(bare);
    hearth_scene_destroy(warm);
}

TEST_MAIN(T(sph_surface_temperature_slab_matches_series), T(sph_surface_flux_through_film_matches_series),
          T(sph_outer_browns_at_face_temperature),
          T(sph_surface_temperature_skipped_without_browning), T(sph_surface_temperature_not_allocated_without_browning),
          T(sph_outer_surface_skipped_without_readers))
