/* settings.c: the scene's and solvers' settings, described once.
 *
 * Before this table a setting lived in five places (hearth.h, scene.c's
 * defaults and checks, sph.c's checks, lua_scene.c's field copies and
 * init.lua's checks and defaults), and they drifted: the oven's beta was 0 in
 * C and 10 in Lua. Now the C defaults and checks are loops over this table,
 * the Lua binding reads it at run time (core.scene_settings), and `hearth help
 * scene`, `hearth doc man|lua` print it; tests/lua/settings_schema.lua and the
 * cli test settings_docs_current fail when a copy disagrees. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <string.h>

#include "error.h"
#include "settings.h"

/* A setting is written through its kind's C type; enums are stored as int. */
_Static_assert(sizeof(hearth_contact) == sizeof(int), "wall is stored as an int");
_Static_assert(sizeof(hearth_guard_policy) == sizeof(int), "guard is stored as an int");

#define OFF(f) ((long)offsetof(hearth_scene_def, f))

static const char *const w_wall[] = {"sticky", "slip", "separate", NULL};
static const char *const w_guard[] = {"stop", "rollback", NULL};
static const char *const w_heat[] = {"explicit", "implicit", NULL};
static const char *const w_transfer[] = {"apic", "pic", NULL};
static const char *const w_solver[] = {"mpm", "sph", NULL};
static const char *const w_blend[] = {"nonlinear", "linear", "labels", NULL};
static const char *const w_mixing[] = {"fixed", "dynamic", NULL};
static const char *const w_time_units[] = {"real", "animation", NULL};
static const double box_def[6] = {0, 0, 0, 1, 1, 1};
static const double gravity_def[3] = {0, -9.81, 0};

/* Field order within one entry: name, kind, unit, help, def, min, max,
 * min_open, nan_ok, words, vec_def, offset, offset2, field, knob. */
#define REAL(n, unit, help, def, lo, hi, f, knob) {n, HEARTH_SETTING_REAL, unit, help, def, lo, hi, 0, 0, NULL, NULL, OFF(f), -1, #f, knob}
#define REAL_GT(n, unit, help, def, lo, hi, f, knob) {n, HEARTH_SETTING_REAL, unit, help, def, lo, hi, 1, 0, NULL, NULL, OFF(f), -1, #f, knob}
#define INT(n, help, def, lo, hi, f, knob) {n, HEARTH_SETTING_INT, "1", help, def, lo, hi, 0, 0, NULL, NULL, OFF(f), -1, #f, knob}
#define FLAG(n, help, f) {n, HEARTH_SETTING_FLAG, "", help, 0, 0, 1, 0, 0, NULL, NULL, OFF(f), -1, #f, 0}
#define CHOICE(n, help, def, words, f, knob) {n, HEARTH_SETTING_CHOICE, "", help, def, 0, 0, 0, 0, words, NULL, OFF(f), -1, #f, knob}
#define LUA_CHOICE(n, help, def, words, knob) {n, HEARTH_SETTING_CHOICE, "", help, def, 0, 0, 0, 0, words, NULL, -1, -1, "", knob}
#define SPH(n, unit, help, def, lo, hi) REAL("sph." #n, unit, help, def, lo, hi, sph.n, 0)
#define SPH_FLAG(n, help, f) FLAG("sph." n, help, sph.f)

static const hearth_setting settings[] = {
    /* ---- the scene (scene.c) ---- */
    {"name", HEARTH_SETTING_TEXT, "", "a label for the scene, kept with its Lua state (nothing reads it yet)", NAN, 0, 0, 0, 0, NULL, NULL, -1, -1, "", 0},
    INT("dim", "2 (plane strain) or 3", 2, 2, 3, dim, 1),
    REAL_GT("dx", "m", "grid spacing", 0.01, 0, HUGE_VAL, dx, 1),
    {"box", HEARTH_SETTING_BOX, "m", "the domain {{lo}, {hi}}; each axis at least 6 dx long (z ignored in 2D)", NAN, 0, 0, 0, 0,
     NULL, box_def, OFF(lo), OFF(hi), "lo, hi", 0},
    {"gravity", HEARTH_SETTING_VECTOR, "m/s^2", "acceleration of gravity", NAN, 0, 0, 0, 0, NULL, gravity_def, OFF(gravity), -1,
     "gravity", 0},
    CHOICE("solver", "which solver steps the scene: MPM (Ding et al. 2019) or SPH (Rodriguez-Arenas 2011)", 0, w_solver,
           solver, 1),
    REAL_GT("cfl", "1", "CFL number: dt = cfl dx / (speed + wave speed); 1 is the waves' limit (MPM past 0.64 in 2D, 0.52 in 3D also holds dt under a lone particle's)", 0.5, 0, 4, cfl, 1),
    REAL("dt_max", "s", "largest step; 0 = no limit", 0, 0, HUGE_VAL, dt_max, 1),
    CHOICE("wall", "contact at the domain's walls", 1, w_wall, wall, 0),
    REAL("friction", "1", "Coulomb friction coefficient at the walls", 0, 0, HUGE_VAL, wall_friction, 0),
    CHOICE("guard", "what the stability guard does: stop with a diagnosis, or roll back, halve dt and retry", 0, w_guard,
           guard, 1),
    INT("max_rollbacks", "consecutive rollbacks before the guard stops anyway", 8, 0, 60, max_rollbacks, 1),
    REAL_GT("energy_growth", "1", "kinetic energy growth in one step that the guard calls a runaway", 10, 1, HUGE_VAL,
            energy_growth, 0),
    /* a knob, so any scene runs on another sampling of its bodies (--set seed=N; docs/validation.md, "Tests that
     * flip with the seeding") */
    {"seed", HEARTH_SETTING_SEED, "1", "seed of jittered seeding and random labels (0 acts as 1)", 1, 0, 4503599627370496.0,
     0, 0, NULL, NULL, OFF(seed), -1, "seed", 1},
    {"oven.temperature", HEARTH_SETTING_REAL, "degC",
     "oven air temperature of the Robin boundary (Ding et al. eq. 9); unset = no oven, and an oven makes the temperature "
     "field live",
     NAN, -273.15, 5000, 0, 1, NULL, NULL, OFF(oven_temperature), -1, "oven_temperature", 0},
    REAL("oven.beta", "W/(m^2 K)", "oven air heat transfer coefficient beta", 10, 0, HUGE_VAL, oven_beta, 0),
    {"oven.wall_temperature", HEARTH_SETTING_REAL, "degC",
     "the oven's radiating walls: q = oven.emissivity sigma (T_w^4 - T_s^4) (T in K) at the oven's air surface, beside "
     "beta (T_air - T_s) (both solvers; fields/thermal.h); unset = no radiation",
     NAN, -273.15, 5000, 0, 1, NULL, NULL, OFF(oven_wall_temperature), -1, "oven_wall_temperature", 1},
    REAL("oven.emissivity", "1",
         "effective emissivity of the oven walls' exchange with the surface (a small body in a large enclosure: the "
         "body's own); 0 = no radiation",
         0, 0, 1, oven_emissivity, 1),
    REAL_GT("oven.radiation_scale", "1",
            "multiplies emissivity sigma as a scene whose heat runs N times fast multiplies beta (1 = physical time)", 1, 0,
            1e9, oven_radiation_scale, 0),
    REAL("oven.saturation", "1",
         "ambient saturation (humidity) that evaporation goes toward: q.n = beta^w theta (s - s_amb) (our extension of Ding "
         "et al. §3.2); 0 = dry air",
         0, 0, 1, oven_saturation, 0),
    CHOICE("heat", "heat time stepping: forward Euler (dt limited by conduction) or backward Euler (CG solve)", 0, w_heat,
           heat_implicit, 1),
    FLAG("water_momentum", "the water's motion relative to the solid carries momentum (Ding et al. eq. 26-27)",
         water_momentum),
    FLAG("latent_heat", "evaporated water takes 2.26 MJ/kg (water's latent heat near 100 degC) from the heat of the particle "
         "it leaves, and a wet particle does not heat past boiling_point but boils its water (both solvers; beyond Ding et al. eq. 9): "
         "a wet crumb holds at the boiling point, a dry crust heats on. With it, evaporation is driven by the vapour "
         "pressure: Ding's beta^w theta (s - s_amb) times P_sat(T) / P_sat(boiling_point) (Clausius-Clapeyron, at most 1), "
         "so a wet surface stops cooling at its wet-bulb temperature. "
         "Off by default and for the animation-unit presets h.library.paper_oven.*", latent_heat),
    REAL("boiling_point", "degC",
         "with latent_heat: a particle that holds water does not heat past this; the excess heat boils its water, "
         "m c (T - T_b) / L, and the vapour leaves (the crumb's plateau)", 100, -273.15, 5000, boiling_point, 0),
    REAL("gas_vent", "m/s",
         "CO2 loss through open surface pores: an air-boundary particle whose gas porosity is at least vent_porosity "
         "loses its CO2 at dn^g/dt = -gas_vent S_p / V_p (n^g - n*), S_p its share of the surface, n* the CO2 at "
         "which its pores stand at the material's ambient_pressure (0 without one) (MPM; beyond Ding et al. "
         "§5.4: a real dough's surface cells open and vent); 0 = none",
         0, 0, 1e6, gas_vent, 0),
    REAL_GT("vent_porosity", "1",
            "with gas_vent: the gas porosity n^p at which a surface particle's pores open to the air (a foam's cells "
            "touch past ~0.64-0.74, the packing fractions of spheres)",
            0.7, 0, 1, vent_porosity, 0),
    CHOICE("transfer", "momentum transfer: APIC, or PIC (no affine part: dissipative)", 0, w_transfer, transfer, 1),
    REAL("heat_flip", "1", "temperature to particles: 1 FLIP (eq. 21) .. 0 PIC (the nodes' value)", 1, 0, 1, heat_flip, 1),
    REAL("damping", "1/s", "velocity damping c for static problems: each step the grid velocity is divided by 1 + c dt "
         "(MPM); 0 = off", 0, 0, 1e9, damping, 1),
    FLAG("periodic_x", "the box wraps along x: material leaving at one face enters at the other, no walls there (the "
         "box length a whole number of dx; MPM without heat or water, or SPH)", periodic[0]),
    FLAG("periodic_y", "the box wraps along y (as periodic_x)", periodic[1]),
    FLAG("periodic_z", "the box wraps along z (as periodic_x; 3D)", periodic[2]),
    FLAG("browning",
         "integrate a browning index 0..1 per particle from its temperature and water history (Zanoni et al. 1995 "
         "first-order kinetics; fields/browning.c); makes the temperature field live",
         browning),
    REAL("browning_scale", "1",
         "multiplies the browning rate (1 = physical time; a scene whose heat runs N times fast sets N)", 1, 0, 1e9,
         browning_scale, 0),
    FLAG("two_field",
         "MPM keeps two velocity fields at the nodes a crack crosses, so the two sides of a crack (a ridge of the "
         "materials' damage) move apart or slide instead of moving as one (damage-field-gradient partitioning, Homel & "
         "Herbold 2017; solver/mpm_two_field.c), and at the nodes two bodies (two s:add calls) both reach, so they push "
         "on each other only where they touch and part freely (Bardenhagen et al. 2000; with one field they meet up to "
         "a cell apart). Three or more bodies at one node: the lowest body id against all the others. 2D MPM on one "
         "rank, no sticky colliders, no periodic axes; about 3x the CPU of a one-field step",
         two_field),
    REAL("two_field_friction", "1", "with two_field: Coulomb friction coefficient between the two sides of a crack, or "
         "two bodies, where they press together (0 = they slide freely)", 0, 0, 10, two_field_friction, 0),
    INT("field_steps", "MPM heat, water and CO2 update on the grid every k-th step, over the k steps' time (the "
        "particles carry them, and make and vent their CO2, every step): 0 = k automatic (the default), each update "
        "within a tenth of the fields' explicit limit; 1 = every step (single rate, the old scheme to the bit); k = every "
        "k-th (fields/field_clock.c)", 0, 0, 4096, field_steps, 1),
    LUA_CHOICE("blend", "how bodies of h.mix{...} materials are simulated: the blend model, linearly blended parameters, "
               "or random binary labels (Nagasawa et al. Figs. 1, 9, 10)", 0, w_blend, 1),
    LUA_CHOICE("mixing", "dynamic: h.mix bodies share one mixture whose ratios follow the particles (Nagasawa et al. eq. "
               "43-44; needs blend = nonlinear)", 0, w_mixing, 0),
    /* The scene's clock, for what a user reads (#18, helper userfix10): its pictures' titles and the dashboard's
     * status line say the same time. Lua-side: the simulation never reads it. */
    {"time_scale", HEARTH_SETTING_REAL, "1",
     "the real seconds one simulated second stands for, in a scene whose rates run time_scale times fast (a "
     "physical preset's oven.time_scale): its pictures (unless one gives its own) and the dashboard give the real time beside the simulated one", 1, 0, 1e9, 1, 0, NULL, NULL, -1, -1, "", 0},
    LUA_CHOICE("time_units", "what a simulated second is: real (time_scale real seconds), or animation (Ding et al. "
               "Table 2's animation units, no real time: the dashboard says so beside the time)", 0, w_time_units, 0),
    /* ---- the SPH solver (sph.c; Rodriguez-Arenas 2011 equation numbers), checked when solver = sph ---- */
    SPH(h_factor, "1", "smoothing length h over the particle spacing V0^(1/dim) (2.4: lattice sum of W V within 1e-3 of 1)",
        2.4, 1, 6),
    SPH_FLAG("leapfrog", "leapfrog drift-kick-drift (§3.6) instead of symplectic Euler (eq. 3.57-3.58)", leapfrog),
    SPH(gamma, "1", "Tait exponent (eq. 3.17)", 7, 1, 15),
    SPH(av_beta, "1", "Monaghan artificial viscosity beta (eq. 3.41); 0 = off", 0, 0, 100),
    SPH(surface_tension, "N/m", "colour-field surface tension sigma (eq. 3.30); 0 = off", 0, 0, 1e6),
    SPH(surface_threshold, "1", "|grad C| h above this marks a surface particle (§3.1.8)", 0.75, 0, 10),
    SPH(alpha_c, "1", "collider response (eq. 3.33): normal restitution", 0, 0, 1),
    SPH(beta_c, "1", "collider response (eq. 3.33): tangential keep", 1, 0, 1),
    /* XSPH moves a particle toward its neighbours' mean velocity by epsilon
     * times the difference: above 1 it overshoots and grows (Table 4.1 lists
     * 5, the text of §4.3 uses 0.5) */
    SPH(xsph0, "1", "XSPH tuner epsilon (eq. 3.34) at xsph_T0; above 1 XSPH overshoots the neighbours' mean velocity", 0, 0,
        1),
    SPH(xsph_f, "1", "XSPH tuner epsilon at xsph_Tf (eq. 4.4)", 0, 0, 1),
    SPH(xsph_T0, "degC", "temperature of the XSPH tuner line's start (below xsph_Tf)", 26, -273.15, 5000),
    SPH(xsph_Tf, "degC", "temperature of the XSPH tuner line's end", 120, -273.15, 5000),
    /* eq. 3.42 per unit area (sph_heat.c): an oven's h / c is ~0.01 kg/(m^2 s)
     * in real time, times a scene's time scale; the old form's 1e8-1e9 are
     * refused so a scene written for it says so rather than boils */
    SPH(heat_ext, "kg/(m^2 s)",
        "k_h,ext of eq. 3.42 per unit area of surface: h / c, the surface heat transfer coefficient over the specific "
        "heat (scaled as a scene's time scale; a bread oven: 4.4); 0 = off. Scenes written for the printed form's "
        "1e8-1e9 (before #18) are refused: docs/validation.md, SPH surface heat per unit area",
        0, 0, 1e6),
    /* eq. 3.45's k_h,int multiplies m_j / rho^2 and the kernel's Laplacian,
     * so it is kappa / c (kg/(m s)); k_h,int / rho is the diffusivity */
    SPH(heat_int, "kg/(m s)",
        "k_h,int of eq. 3.45: the conductivity over the specific heat, kappa / c (the diffusivity times the density; "
        "scaled as a scene's time scale); the wet value where a material sets dry_conductivity or dry_specific_heat "
        "(each particle's kappa(w) / conductivity scales it, its heat over m alpha(w)); 0 = off",
        0, 0, 1e6),
    SPH_FLAG("adaptive_h", "Sigalotti adaptive smoothing length (eq. 3.54-3.56)", adaptive_h),
    SPH(k_g, "1", "eq. 3.54 factor k_g", 1, 0.1, 10),
    SPH(eps_g, "1", "eq. 3.54 factor epsilon_g", 0.5, 0, 1),
    SPH(bubble_T0, "degC", "temperature where bubbles have their initial volume (eq. 3.50)", 26, -273, 5000),
    SPH(dt_viscous, "1", "viscous step factor: dt <= dt_viscous rho h^2 / mu", 0.125, 1e-6, 1),
    SPH(dt_force, "1", "force step factor: dt <= dt_force sqrt(h / |a|)", 0.25, 1e-6, 1),
    SPH_FLAG("periodic_x", "the box's x faces wrap", periodic[0]),
    SPH_FLAG("periodic_y", "the box's y faces wrap", periodic[1]),
    SPH_FLAG("periodic_z", "the box's z faces wrap", periodic[2]),
    SPH_FLAG("tension", "keep negative Tait pressure, as the thesis (otherwise clamped to 0: free surfaces stay clean)",
             tension),
    SPH(artificial_stress, "1",
        "Monaghan's epsilon (2000) against the tensile instability; 0.2-0.3 is usual, 0 = off (it also resists a cooling "
        "bubble's contraction)",
        0, 0, 1),
    SPH_FLAG("gas_law",
             "Tait against each particle's rest density, a bubble's rho0 / V_b(T) (eq. 3.49-3.50 in Kelvin): the rise "
             "follows the temperature and is bounded by it; off = eq. 3.51 while heating, then eq. 3.52, as the thesis",
             gas_law),
    SPH(bubble_vapour, "1",
        "with gas_law: the dough's water activity a_w; water vapour a_w P_sat(T) joins the bubble's gas (eq. 2.42-2.43, "
        "Clausius-Clapeyron); 0 = dry gas",
        0, 0, 0.99),
    SPH(bubble_vmax, "1", "with gas_law: the largest V_b / V_b0, where the crumb's cells open and vent (the vapour law "
        "diverges at the boiling point)", 4, 1, 100),
    /* a cell that has vented at the cap holds the oven's air at P_a whatever its
     * temperature: cooling draws air in, not the crumb (sph_gas.c) */
    SPH_FLAG("bubble_stays_open",
             "with gas_law: a bubble that has reached bubble_vmax stays open (its cell vented to the oven's air) and keeps "
             "that volume as it cools, instead of contracting as a closed gas",
             bubble_stays_open),
    /* a cell open to the air loses the gas that overfills it (sph_gas.c) */
    SPH_FLAG("surface_vent",
             "with gas_law: a bubble particle on the body's outer surface (open to the oven's air) vents: its gas holds "
             "the outside pressure (zero gauge), and what left is gone if the cell closes again; one within its h of a "
             "collider does not (its outside there is the tray). The field gas_left is the share of a bubble's gas "
             "still in its cell",
             surface_vent),
    SPH_FLAG("continuity_density",
             "with gas_law: Tait and the gas law read each particle's density from its own volume, m / (V0 det F) (the "
             "continuity equation, Gray, Monaghan & Swift 2001), not the summation (eq. 3.13), which reads a free surface "
             "or a tray as stretched and pulls it into a skin",
             continuity_density),
    SPH_FLAG("renormalised_density",
             "with gas_law: Tait and the gas law read the summed density (eq. 3.13 over rest volumes) divided by the part "
             "of the kernel the body fills, sum_j V0_j det F_j W_ij, at most 1 (Ferrand et al. 2013's gamma): a free "
             "surface or a tray side reads no stretch, the inside keeps the sum",
             renormalised_density),
    /* the sum spreads a held-back bubble's missing volume into its dough
     * (docs/validation.md "Why the roll's base leaves its tray") */
    SPH_FLAG("own_squeeze",
             "with gas_law: Tait reads the summed density only as far as the particle's own volume m / (V0 det F) "
             "confirms a squeeze, min(rho_sum, max(rho0, rho_own)): the sum's tension between films stays, a hot "
             "bubble's missing volume no longer squeezes its dough neighbours",
             own_squeeze),
    /* an ideal gas's isothermal bulk modulus is its pressure: a bubble at the
     * oven's 101325 Pa less its vapour is that stiff, whatever its dough's Tait B */
    SPH(gas_pressure, "Pa",
        "with gas_law: the outside pressure P_a of a bubble's ideal gas: its stiffness is its gas's own, P_a - P_v(T) "
        "(eq. 2.42-2.43), at any dough stiffness, so it pushes (P_a - P_v) (rho / rho_b - 1) (an oven: 101325); "
        "0 = the dough's Tait B",
        0, 0, 1e7),
    /* bread dough holds 0.41-0.45 kg of water per kg (a flour's 60-65% water
     * on its own weight); the dissolved CO2 it holds is as much as the gas */
    SPH(dough_water, "kg/kg",
        "with gas_law: the dough's water mass fraction; CO2 dissolves in it by Henry's law (Sander 2015; thesis eq. "
        "2.44) and comes out into the bubbles as the dough heats (each bubble draws on an even share of the "
        "particles' water per raw gas volume); 0 = none",
        0, 0, 0.9),
    /* SPH's zero-energy modes: a pair that closes inside one kernel moves no
     * velocity gradient (eq. 3.27), so nothing the dough reads from det F
     * holds it (docs/validation.md "The roll's bounce on its tray") */
    SPH(hourglass, "1",
        "hourglass control: each pair's relative velocity along its line beyond what the velocity gradient (eq. 3.27) "
        "predicts is damped with this many times the pair's viscosity (eq. 3.19), implicitly (Ganzenmueller 2015's "
        "control in rate form); 0 = off",
        0, 0, 100),
};

const hearth_setting *hearth_scene_settings(int *n) {
    if (n) *n = (int)(sizeof settings / sizeof settings[0]);
    return settings;
}

const hearth_setting *hearth_scene_setting(const char *name) {
    for (size_t k = 0; name && k < sizeof settings / sizeof settings[0]; k++)
        if (!strcmp(settings[k].name, name)) return &settings[k];
    return NULL;
}

static void *at(hearth_scene_def *d, long off) { return (char *)d + off; }
static const void *cat(const hearth_scene_def *d, long off) { return (const char *)d + off; }

void settings_defaults(hearth_scene_def *d) {
    memset(d, 0, sizeof *d);
    for (size_t k = 0; k < sizeof settings / sizeof settings[0]; k++) {
        const hearth_setting *e = &settings[k];
        if (e->offset < 0) continue;
        switch (e->kind) {
        case HEARTH_SETTING_REAL: *(double *)at(d, e->offset) = e->def; break;
        case HEARTH_SETTING_INT:
        case HEARTH_SETTING_FLAG:
        case HEARTH_SETTING_CHOICE: *(int *)at(d, e->offset) = (int)e->def; break;
        case HEARTH_SETTING_SEED: *(uint64_t *)at(d, e->offset) = (uint64_t)e->def; break;
        case HEARTH_SETTING_VECTOR: memcpy(at(d, e->offset), e->vec_def, 3 * sizeof(double)); break;
        case HEARTH_SETTING_BOX:
            memcpy(at(d, e->offset), e->vec_def, 3 * sizeof(double));
            memcpy(at(d, e->offset2), e->vec_def + 3, 3 * sizeof(double));
            break;
        case HEARTH_SETTING_TEXT: break;
        }
    }
}

/* " m", " W/(m^2 K)"; nothing for dimensionless */
static const char *unit_sp(const hearth_setting *e) { return e->unit[0] && strcmp(e->unit, "1") ? " " : ""; }
static const char *unit_of(const hearth_setting *e) { return strcmp(e->unit, "1") ? e->unit : ""; }

static hearth_status bad_range(const hearth_setting *e, double v, hearth_error *err) {
    return err_set(err, HEARTH_ERR_PARAM, "scene: %s = %.15g%s%s; valid range %c%g, %g%c%s%s (%s)", e->name, v,
                   unit_sp(e), unit_of(e), e->min_open ? '(' : '[', e->min, e->max, isinf(e->max) ? ')' : ']',
                   unit_sp(e), unit_of(e), e->help);
}

static hearth_status check_one(const hearth_scene_def *d, const hearth_setting *e, hearth_error *err) {
    switch (e->kind) {
    case HEARTH_SETTING_REAL: {
        const double v = *(const double *)cat(d, e->offset);
        if (isnan(v) && e->nan_ok) return HEARTH_OK;
        /* finite always; HUGE_VAL as max only means "no upper bound" */
        if (!isfinite(v) || !(e->min_open ? v > e->min : v >= e->min) || !(v <= e->max)) return bad_range(e, v, err);
        return HEARTH_OK;
    }
    case HEARTH_SETTING_INT: {
        const int v = *(const int *)cat(d, e->offset);
        if (!(v >= e->min && v <= e->max)) return bad_range(e, v, err);
        return HEARTH_OK;
    }
    case HEARTH_SETTING_SEED: {
        const uint64_t v = *(const uint64_t *)cat(d, e->offset);
        if (!((double)v <= e->max)) return bad_range(e, (double)v, err);
        return HEARTH_OK;
    }
    case HEARTH_SETTING_FLAG: {
        const int v = *(const int *)cat(d, e->offset);
        if (v != 0 && v != 1)
            return err_set(err, HEARTH_ERR_PARAM, "scene: %s = %d; valid: 0 (false), 1 (true) (%s)", e->name, v, e->help);
        return HEARTH_OK;
    }
    case HEARTH_SETTING_CHOICE: {
        const int v = *(const int *)cat(d, e->offset);
        int n = 0;
        while (e->words[n]) n++;
        if (v >= 0 && v < n) return HEARTH_OK;
        char list[256] = "";
        size_t len = 0;
        for (int k = 0; k < n && len < sizeof list; k++)
            len += (size_t)snprintf(list + len, sizeof list - len, "%s%d (%s)", k ? ", " : "", k, e->words[k]);
        return err_set(err, HEARTH_ERR_PARAM, "scene: %s = %d; valid: %s (%s)", e->name, v, list, e->help);
    }
    case HEARTH_SETTING_VECTOR: /* finiteness here; box extents against dx in scene.c */
    case HEARTH_SETTING_BOX:
    case HEARTH_SETTING_TEXT: return HEARTH_OK;
    }
    return HEARTH_OK;
}

hearth_status settings_check(const hearth_scene_def *d, const char *prefix, const char *skip_prefix,
                             hearth_error *err) {
    const size_t np = strlen(prefix), ns = skip_prefix ? strlen(skip_prefix) : 0;
    for (size_t k = 0; k < sizeof settings / sizeof settings[0]; k++) {
        const hearth_setting *e = &settings[k];
        if (e->offset < 0 || strncmp(e->name, prefix, np) || (skip_prefix && !strncmp(e->name, skip_prefix, ns))) continue;
        hearth_status st = check_one(d, e, err);
        if (st) return st;
    }
    return HEARTH_OK;
}
