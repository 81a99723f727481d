/* hearth/hearth.h: the public C API of libhearth, the simulator.
 *
 * Used by the command line, the Lua binding, the dashboard and the tests.
 * The library never exits, aborts or prints: every failure that comes from
 * outside the program returns a status and fills a hearth_error whose text
 * names the file, parameter or particle and the valid range.
 *
 * Units are SI; temperature is in degrees C. Vectors are always 3 doubles;
 * 2D scenes use x and y and keep z = 0.
 */
#ifndef HEARTH_H
#define HEARTH_H

#include <stddef.h>
#include <stdint.h>

#include "material.h"

#ifdef __cplusplus
extern "C" {
#endif

#define HEARTH_VERSION "0.1.0"

/// Status codes at the API boundary.
typedef enum hearth_status {
    HEARTH_OK = 0,
    HEARTH_ERR_IO,      ///< a file could not be read or written
    HEARTH_ERR_PLUGIN,  ///< a plugin could not be loaded or failed a check
    HEARTH_ERR_PARAM,   ///< a parameter is unknown or out of range
    HEARTH_ERR_NOMEM,   ///< an allocation failed
    HEARTH_ERR_GUARD,   ///< the stability guard stopped the run (see hearth_stats.diagnosis)
    HEARTH_ERR_FORMAT,  ///< a file is not in the expected format or version
    HEARTH_ERR_STATE    ///< the call does not fit the object's state
} hearth_status;

/// Filled by every call that can fail. msg is one or more lines, no trailing newline.
typedef struct hearth_error {
    hearth_status code;
    char msg[1024];
} hearth_error;

/* ---- memory --------------------------------------------------------- */

/// Allocator hook, Lua style: nsize == 0 frees ptr; otherwise (re)allocates.
/// Returns NULL on failure. osize is the old size (0 for a new block).
typedef void *(*hearth_alloc_fn)(void *ud, void *ptr, size_t osize, size_t nsize);
/// Replace the allocator for all later allocations. NULL restores the default.
/// Call it before creating any scene.
void hearth_set_allocator(hearth_alloc_fn fn, void *ud);
/// Bytes currently held by the library (particles, grid, scratch), all scenes together.
size_t hearth_bytes_allocated(void);
/// The most bytes the library held at once since the process started (growing arrays hold old and new).
size_t hearth_bytes_peak(void);
/// The most the library may hold at once, in bytes (0: no ceiling of its own). An allocation
/// past it fails as out-of-memory would: the call that needed it returns its error and
/// nothing else changes. A scene's particles and grid are also refused up front, with
/// the estimate, when they would not fit under it. Programs running other people's scenes
/// set it (hearth run --memory); the library's own default is the machine's memory.
void hearth_set_memory_limit(size_t bytes);
/// Every PNG the process writes after this call carries text (UTF-8, copied, at most 1023 bytes; NULL or ""
/// for none) as its "Source" text, beside its "Title": the command line sets the run that drew it (`hearth run
/// scene.lua --set k=v ...` and the version), so a frame copied away still names its scene and settings. Call
/// it before a scene runs, from one thread.
void hearth_png_set_source(const char *text);
/// That ceiling, or the machine's physical memory when lower (SIZE_MAX when neither is known).
size_t hearth_memory_limit(void);
/// The machine's physical memory in bytes (SIZE_MAX when unknown).
size_t hearth_machine_memory(void);
/// 1 when an allocation was refused for the ceiling since it was last set.
int hearth_memory_limit_refused(void);

/// A host's interrupt (a signal it caught): a step call of many steps (hearth_scene_step,
/// hearth_scene_advance_steps) returns early, between two steps, when `interrupted` answers
/// non-zero; the scene is whole at the last step's end and the host reports the interrupt.
/// NULL (the default) never stops early. Not over MPI ranks (their step calls are collective).
void hearth_set_interrupt_check(int (*interrupted)(void));

/* ---- threads -------------------------------------------------------- */

/// Number of OpenMP threads the library uses (0 = the OpenMP default). Results
/// do not depend on it: every parallel loop is deterministic.
void hearth_set_threads(int n);
int hearth_get_threads(void);

/// Remove the temporary files ("<name>.tmp.<pid>") that runs killed while
/// writing left under dir (recursively), when their process is gone. Returns
/// the number removed. Hosts call it before a run writes into dir.
int hearth_clean_stale_temps(const char *dir);

/* ---- plugins -------------------------------------------------------- */

typedef struct hearth_plugin hearth_plugin; ///< a loaded plugin; lives until process exit

/// Add a folder to the end of the plugin search path (the scene's folder, say).
/// The search order is: the build's plugin folder, the install folder, every
/// folder in $HEARTH_PLUGIN_PATH (colon separated), then folders added here.
void hearth_plugin_path_add(const char *dir);
/// Load a plugin by name ("elastic" finds hearth_elastic.so on the path) or by
/// a path containing '/'. Loaded plugins are cached by resolved path.
const hearth_plugin *hearth_plugin_load(const char *name_or_path, hearth_error *err);
/// From now on (for the rest of the process) load plugins only by name
/// ([a-z0-9_]+, resolved on the search path), and refuse a file that resolves
/// under writable_dir (NULL for none): the policy for a scene run without
/// --trust, which may write only there. A path containing '/' is refused.
void hearth_plugin_restrict(const char *writable_dir);
const hearth_material *hearth_plugin_material(const hearth_plugin *pl);
/// Plugins loaded so far in this process, in load order (for run records):
/// the count, and the i-th (NULL out of range).
int hearth_plugin_loaded_count(void);
const hearth_plugin *hearth_plugin_loaded(int i);
const char *hearth_plugin_file(const hearth_plugin *pl);
/// Call fn for every plugin file found on the search path (each name once, first wins).
/// Returns the number of files visited.
int hearth_plugin_each(void (*fn)(void *ud, const char *name, const char *path), void *ud);

/// One line of the conformance report. passed: 1 the check passed, 0 it failed,
/// 2 it passed with a warning the detail explains (a property that could not be
/// checked where the law flowed plastically; not counted as a failure).
typedef void (*hearth_check_fn)(void *ud, const char *check, int passed, const char *detail);
/// Run the conformance battery on a plugin file. Returns the number of failed
/// checks (0 = all pass), or -1 when the plugin cannot be loaded (err says why).
int hearth_plugin_check(const char *path, hearth_check_fn fn, void *ud, hearth_error *err);

/// The plugin callback the calling thread is running, for crash reports
/// (`hearth run` names the plugin when one segfaults or calls exit()).
typedef struct hearth_plugin_call_info {
    const char *material; ///< the descriptor's name, or "(unknown)" before the descriptor is read
    const char *file;     ///< the plugin's path, or "" when it was not loaded from a file
    const char *callback; ///< "init", "stress", "wave_speed", "plastic_J", "viscosity", "blend", ...
    const char *context;  ///< what the core was doing ("" when nothing in particular)
} hearth_plugin_call_info;
/// 1 and fills out when the calling thread is inside a plugin callback, else 0.
/// Async-signal-safe (reads only; the strings are static or live until exit).
int hearth_plugin_call_current(hearth_plugin_call_info *out);
/// Mark the calling thread as inside callback `callback` (a static string) of
/// material m, for callers outside the core that call a plugin directly (the
/// Lua binding's blend); pair with hearth_plugin_call_leave.
void hearth_plugin_call_enter(const hearth_material *m, const char *callback);
void hearth_plugin_call_leave(void);

/* ---- shapes (signed distance functions) ----------------------------- */

typedef struct hearth_shape hearth_shape; ///< immutable tree of primitives; owned by the caller

typedef enum hearth_shape_op { HEARTH_UNION, HEARTH_INTERSECT, HEARTH_SUBTRACT } hearth_shape_op;

/// Half-space below the plane through point with outward normal n (solid where (x-point).n < 0).
hearth_shape *hearth_shape_plane(const double point[3], const double normal[3]);
/// Axis-aligned box by centre and half extents. In 2D the z extent is ignored.
hearth_shape *hearth_shape_box(const double centre[3], const double half[3]);
/// Sphere (a disc in 2D, where z is 0).
hearth_shape *hearth_shape_sphere(const double centre[3], double radius);
/// Capped cylinder: centre, unit axis, radius, half height.
hearth_shape *hearth_shape_cylinder(const double centre[3], const double axis[3], double radius, double half_height);
/// Capsule: segment a-b swept by radius.
hearth_shape *hearth_shape_capsule(const double a[3], const double b[3], double radius);
/// Open container (cup, ramekin, pan): a cylinder wall of inner radius r_in and
/// thickness wall around axis, a floor of thickness floor below base, height of
/// the wall measured up the axis from base. The inside is empty.
hearth_shape *hearth_shape_container(const double base[3], const double axis[3], double r_in,
                                     double height, double wall, double floor);
/// A 2D shape from a mask image: pixels darker than 50% grey are inside. The
/// image spans the rectangle lo..hi (x right, y up: the image's top row is at hi[1]).
/// Reads the PNG with libpng. The shape is infinite in z (use hearth_shape_extrude for 3D).
hearth_shape *hearth_shape_mask(const char *png_path, const double lo[2], const double hi[2], hearth_error *err);
/// Limit a shape to z0 <= z <= z1 (an extruded mask in 3D).
hearth_shape *hearth_shape_extrude(const hearth_shape *s, double z0, double z1);
/// Boolean combination (copies a and b).
hearth_shape *hearth_shape_combine(hearth_shape_op op, const hearth_shape *a, const hearth_shape *b);
hearth_shape *hearth_shape_copy(const hearth_shape *s);
void hearth_shape_free(hearth_shape *s);
/// Why the last shape constructor called on this thread returned NULL: static
/// text naming the argument and its valid range ("sphere: centre is not finite
/// (NaN or inf)"), or "out of memory". NULL after a constructor that succeeded.
/// (hearth_shape_mask reports through its hearth_error instead.)
const char *hearth_shape_error(void);
/// Signed distance (negative inside) at x; normal (may be NULL) gets the outward unit gradient.
double hearth_shape_sdf(const hearth_shape *s, const double x[3], double normal[3]);
/// A box that contains the solid part (infinite extents for a plane).
void hearth_shape_bounds(const hearth_shape *s, double lo[3], double hi[3]);

/* ---- scenes --------------------------------------------------------- */

typedef struct hearth_scene hearth_scene;

/// Contact response at walls and colliders.
typedef enum hearth_contact {
    HEARTH_STICKY = 0,  ///< velocity equals the boundary's
    HEARTH_SLIP = 1,    ///< normal velocity removed, tangential kept (friction applies); on MPM only where the body touches the face
    HEARTH_SEPARATE = 2, ///< only approaching normal velocity removed (friction applies); on MPM only where the body touches
    HEARTH_GRIP = 3      ///< colliders only: sticky, and particles inside are carried rigidly (a clamp holding a dough's end)
} hearth_contact;

typedef enum hearth_guard_policy {
    HEARTH_GUARD_STOP = 0,    ///< stop with a diagnosis
    HEARTH_GUARD_ROLLBACK = 1 ///< roll back to the last good state, halve dt, retry (max_rollbacks times)
} hearth_guard_policy;

/// Which solver steps a scene.
typedef enum hearth_solver {
    HEARTH_SOLVER_MPM = 0, ///< material point method (Ding et al. 2019)
    HEARTH_SOLVER_SPH = 1  ///< smoothed particle hydrodynamics (Rodriguez-Arenas 2011, ch. 3-4)
} hearth_solver;

/// Options of the SPH solver (used when solver = HEARTH_SOLVER_SPH). Equation
/// numbers are Rodriguez-Arenas 2011. Start from hearth_default_scene_def();
/// ranges and defaults are the sph.* rows of hearth_scene_settings().
typedef struct hearth_sph_def {
    double h_factor;       ///< smoothing length h (kernel support radius) over the particle spacing V0^(1/dim); default 2.4 (lattice sum of W V within 1e-3 of 1)
    int leapfrog;          ///< 0: symplectic Euler (eq. 3.57-3.58); 1: leapfrog drift-kick-drift (§3.6)
    double gamma;          ///< Tait exponent (eq. 3.17); default 7
    double av_beta;        ///< Monaghan artificial viscosity beta (eq. 3.41); default 0 (off)
    double surface_tension;///< colour-field surface tension sigma (eq. 3.30), N/m; 0 = off
    double surface_threshold; ///< |grad C| h above this marks a surface particle (§3.1.8); default 0.75
    double alpha_c, beta_c;///< collider response (eq. 3.33): normal restitution and tangential keep; default 0, 1
    double xsph0, xsph_f;  ///< XSPH tuner epsilon (eq. 3.34, 0..1) at xsph_T0 and xsph_Tf (eq. 4.4); default 0, 0
    double xsph_T0, xsph_Tf; ///< temperatures of the XSPH tuner's line (degrees C); default 26, 120
    double heat_ext;       ///< k_h,ext of eq. 3.42 per unit area of surface: h / c, kg/(m^2 s) (time-scaled); 0 = off
    double heat_int;       ///< k_h,int of eq. 3.45: kappa / c, kg/(m s) (k_h,int / rho is the diffusivity; time-scaled); 0 = off
    int adaptive_h;        ///< 1: Sigalotti adaptive smoothing length (eq. 3.54-3.56)
    double k_g, eps_g;     ///< eq. 3.54 factors; default 1 and 0.5
    double bubble_T0;      ///< temperature where bubbles have their initial volume (degrees C, eq. 3.50); default 26
    double dt_viscous;     ///< viscous step factor: dt <= dt_viscous rho h^2 / mu; default 0.125
    double dt_force;       ///< force step factor: dt <= dt_force sqrt(h / |a|); default 0.25
    int periodic[3];       ///< 1 = periodic along that axis (box faces wrap); default 0
    int tension;           ///< 0: negative Tait pressure clamped to 0 (free surfaces stay clean); 1: kept, as the thesis; default 0
    double artificial_stress; ///< Monaghan's epsilon (2000) against the tensile instability, 0..1 (0.2-0.3 usual); default 0 = off (it also resists a cooling bubble's contraction)
    int gas_law;           ///< 1: each particle's Tait pressure against its rest density, a bubble's rho0 / V_b(T) (eq. 3.49-3.50, ideal gas; rises with T and falls back as it cools); 0: eq. 3.51 while heating and eq. 3.52's kept density, as the thesis; default 0
    double bubble_vapour;  ///< with gas_law: the dough's water activity a_w; the bubble's gas takes water vapour a_w P_sat(T) (eq. 2.42-2.43); 0 = dry gas (default)
    double bubble_vmax;    ///< with gas_law: the largest V_b / V_b0 (where the crumb's cells open and vent); default 4
    int continuity_density; ///< with gas_law: the pressure reads each particle's density from its own volume, m / (V0 det F) (the continuity equation through eq. 3.27), not eq. 3.13's sum, which reads a free surface as stretched; default 0
    int renormalised_density; ///< with gas_law: the summed density over the part of the kernel the body fills, sum_j V0_j det F_j W_ij (at most 1; Ferrand et al. 2013's gamma), so a free surface or a collider's side reads no stretch and the inside keeps the sum; default 0
    int own_squeeze;      ///< with gas_law: Tait (eq. 3.17) reads the summed density (eq. 3.13) only as far as the particle's own volume m / (V0 det F) confirms a squeeze, min(rho_sum, max(rho0, rho_own)): the sum's tension holds the films, and a held-back bubble's missing volume no longer reads as its dough neighbours' squeeze; default 0
    double gas_pressure;   ///< with gas_law: the outside pressure P_a (Pa) whose ideal gas a bubble holds: its stiffness is its gas's own, P_a - P_v(T) (the vapour's partial pressure, eq. 2.42-2.43), at any dough stiffness, so it pushes (P_a - P_v)(rho / rho_b - 1), its ideal gas exactly; 0 = the dough's Tait B (default)
    double dough_water;    ///< with gas_law: the dough's water as a mass fraction (kg/kg, bread dough ~0.43); CO2 dissolves in it by Henry's law (Sander 2015; thesis eq. 2.44, Fan et al.) and comes out of solution into the bubbles as it heats, each bubble drawing on an even share of all the particles' water per unit raw gas volume; 0 = no dissolved CO2 (default)
    double hourglass;      ///< hourglass control: each pair's relative velocity along its line beyond what eq. 3.27's velocity gradient predicts is damped with this many times eq. 3.19's pair viscosity (implicit; sph_hourglass.c, after Ganzenmueller 2015's control in rate form); 0 = off (default)
    int bubble_stays_open; ///< with gas_law: a bubble that has reached bubble_vmax stays open (its cell vented to the oven's air) and keeps that volume as it cools, instead of contracting as a closed gas; default 0
    int surface_vent;      ///< with gas_law: a bubble particle on the body's outer surface (sph_outer.c's flood fill: open to the oven's air) vents: its gas holds the outside pressure (zero gauge) and the gas that leaves is gone when the cell closes again (a ruptured cell; Lostie et al.'s crust permeation, thesis eq. 2.60, with no crust between cell and air); default 0
} hearth_sph_def;

/// A scene's settings. Each field is one row of hearth_scene_settings(), which
/// gives its Lua name, unit, default, valid range and help (`hearth help scene`).
typedef struct hearth_scene_def {
    int dim;              ///< 2 (plane strain) or 3
    double dx;            ///< grid spacing (m)
    double lo[3], hi[3];  ///< domain box (m); in 2D z is ignored
    double gravity[3];    ///< m/s^2
    double cfl;           ///< CFL number in (0, 4]; dt = cfl dx / (speed + wave speed)
    double dt_max;        ///< user maximum dt (s); 0 = none
    hearth_contact wall;  ///< domain walls
    double wall_friction; ///< Coulomb coefficient at the walls
    hearth_guard_policy guard;
    int max_rollbacks;    ///< consecutive rollbacks before the guard stops anyway
    double energy_growth; ///< kinetic energy growth per step that counts as runaway
    uint64_t seed;        ///< for jittered seeding
    double oven_temperature; ///< oven air temperature (degrees C) for the Robin boundary; NaN = no oven
    double oven_beta;        ///< oven air heat transfer coefficient beta (W/(m^2 K)), >= 0
    double oven_saturation;  ///< ambient saturation s_amb (0..1) that evaporation goes toward: q.n = beta^w theta (s - s_amb)
    int heat_implicit;       ///< 0: forward Euler heat (dt limited by conduction); 1: backward Euler (CG solve)
    int water_momentum;      ///< 1: the water's motion relative to the solid carries momentum (Ding et al. eq. 26-27)
    int transfer;            ///< momentum transfer: 0 APIC (default), 1 PIC (no affine part: dissipative)
    double heat_flip;        ///< temperature to particles: 1 FLIP (default, eq. 21) .. 0 PIC (the nodes' value)
    int solver;              ///< hearth_solver; default MPM
    hearth_sph_def sph;      ///< SPH options (solver = HEARTH_SOLVER_SPH)
    double damping;          ///< MPM velocity damping c (1/s): the grid velocity decays as 1/(1 + c dt) a step; 0 = off
    int periodic[3];         ///< 1: the box wraps along that axis (no walls there); the box length must be a whole number of dx. SPH: as sph.periodic
    int browning;            ///< 1: integrate the per-particle browning index from temperature and water history (Zanoni et al. 1995; fields/browning.c); makes the temperature field live. Default 0
    double browning_scale;   ///< multiplies the browning rate: 1 for physical time; the time-scale factor of a scene whose heat runs in animation units. Default 1
    int latent_heat;         ///< 1: evaporated water takes HEARTH_LATENT_HEAT J/kg from the particle's heat, its evaporation is scaled by the vapour pressure P_sat(T) / P_sat(boiling_point) (at most 1), and wet particles boil at boiling_point (both solvers; beyond Ding et al. eq. 8-9); default 0
    double boiling_point;    ///< with latent_heat: a particle holding water does not heat past this (degrees C); the excess boils its water away (MPM). Default 100
    int two_field;           ///< 1: MPM keeps two velocity fields at nodes across a crack (damage-field-gradient partitioning, Homel & Herbold 2017; solver/mpm_two_field.c); 2D, one rank. Default 0
    double two_field_friction; ///< with two_field: Coulomb coefficient between the two fields where they press together (0 = frictionless). Default 0
    double gas_vent;         ///< m/s: CO2 leaves an air-boundary particle whose pores are open (porosity >= vent_porosity) at dn^g/dt = -gas_vent S_p / V_p n^g (MPM; beyond Ding et al.; fields/gas.c). Default 0 = none
    double vent_porosity;    ///< with gas_vent: the gas porosity at which a surface particle's pores open to the air. Default 0.7
    int field_steps;         ///< MPM heat, water and CO2 update on the grid every k-th step over the k steps' time (fields/field_clock.c): 0 = k automatic from the fields' explicit limit (default), 1 = every step (single rate, the old scheme to the bit), k = every k-th
    double oven_wall_temperature; ///< the oven's radiating walls (degrees C): q = emissivity sigma (T_w^4 - T_s^4) at the oven's air surface, beside beta (T_air - T_s) (both solvers; fields/thermal.h); NaN = none (default)
    double oven_emissivity;       ///< with oven_wall_temperature: the exchange's effective emissivity, 0..1 (a small body in a large enclosure: the body's own); 0 = no radiation (default)
    double oven_radiation_scale;  ///< multiplies emissivity sigma, as the physical presets multiply beta: 1 for physical time, N for a scene whose heat runs N times fast. Default 1
} hearth_scene_def;

/// Latent heat of vaporisation of water near 100 degC (J/kg): 2257 kJ/kg at
/// 100 degC and 1 atm (IAPWS-IF97 steam tables; CRC Handbook of Chemistry and
/// Physics, "Enthalpy of vaporization of water"), rounded as 2.26 MJ/kg. The
/// scene's latent_heat switch uses it; one value, since the sink only matters
/// near the boiling point where the dough's surface sits while it is wet.
#define HEARTH_LATENT_HEAT 2.26e6

/// Defaults: those of hearth_scene_settings() (2D, dx 0.01, box [0,1]^3, gravity
/// (0,-9.81,0), cfl 0.5, slip walls, no friction, guard stops, 8 rollbacks, energy
/// growth 10, seed 1, no oven (its beta 10 once there is one), explicit heat, no water
/// momentum, no latent heat, APIC, MPM). An oven makes the temperature field live.
hearth_scene_def hearth_default_scene_def(void);

/// How a scene setting's value is written.
typedef enum hearth_setting_kind {
    HEARTH_SETTING_REAL = 0, ///< a finite double in [min, max] (min excluded when min_open); NaN too when nan_ok
    HEARTH_SETTING_INT,      ///< a whole number in [min, max], stored as int
    HEARTH_SETTING_SEED,     ///< a whole number in [min, max], stored as uint64_t
    HEARTH_SETTING_FLAG,     ///< 0 or 1 (true or false in Lua), stored as int
    HEARTH_SETTING_CHOICE,   ///< one of words[] (Lua spells the word; C stores its index as int or an enum)
    HEARTH_SETTING_VECTOR,   ///< 3 finite doubles (vec_def), a {x, y[, z]} table in Lua
    HEARTH_SETTING_BOX,      ///< lo and hi, 3 doubles each (vec_def holds 6), {{lo}, {hi}} in Lua
    HEARTH_SETTING_TEXT      ///< a string (Lua only)
} hearth_setting_kind;

/// One scene or solver setting: the one description the C defaults and range
/// checks, the Lua binding's h.scene{...}, `hearth help scene`, the man page and
/// docs/lua.md all derive from. Static storage.
typedef struct hearth_setting {
    const char *name;  ///< as Lua spells it: "dx", "oven.beta", "sph.h_factor" (a dot: a key of a sub-table)
    hearth_setting_kind kind;
    const char *unit;  ///< SI unit, "1" for dimensionless, "" for words, flags and text
    const char *help;  ///< one line
    double def;        ///< default (REAL, INT, SEED, FLAG; CHOICE: the word's index); NaN = unset (nan_ok)
    double min, max;   ///< valid range (REAL, INT, SEED); max may be HUGE_VAL
    int min_open;      ///< 1: the value must be > min
    int nan_ok;        ///< 1: NaN is valid and means "none" (oven.temperature: no oven)
    const char *const *words; ///< CHOICE: the words, NULL-terminated; the value is the index
    const double *vec_def;    ///< VECTOR (3) and BOX (6: lo then hi) defaults; NULL otherwise
    long offset;       ///< byte offset of the value in hearth_scene_def, -1 when only the Lua binding keeps it
    long offset2;      ///< BOX: offset of hi (offset is lo); -1 otherwise
    const char *field; ///< the hearth_scene_def field ("oven_beta", "sph.h_factor"), or "" for Lua-only
    int knob;          ///< 1: `hearth run --set NAME=V` may change it in any scene (and `hearth trade --knob`)
} hearth_setting;

/// The scene's and solvers' settings, in the order they are documented (count in
/// *n). hearth_default_scene_def() fills from it and hearth_scene_create checks
/// every setting with an offset against it.
const hearth_setting *hearth_scene_settings(int *n);
/// The setting called name (as Lua spells it), or NULL.
const hearth_setting *hearth_scene_setting(const char *name);
hearth_scene *hearth_scene_create(const hearth_scene_def *def, hearth_error *err);
void hearth_scene_destroy(hearth_scene *s);
const hearth_scene_def *hearth_scene_get_def(const hearth_scene *s);
/// Change dt_max / cfl while running (values checked; returns status).
hearth_status hearth_scene_set_dt_limits(hearth_scene *s, double cfl, double dt_max, hearth_error *err);

/// Set the oven air temperature (degrees C; NaN removes the oven) and its heat
/// transfer coefficient beta (W/(m^2 K), >= 0) while running. Values are checked
/// as in hearth_scene_create; an oven makes the temperature field live
/// (particles without a temperature start at room temperature).
hearth_status hearth_scene_set_oven(hearth_scene *s, double temperature, double beta, hearth_error *err);

/// Add a material from a plugin with named parameters (others take defaults).
/// Besides the plugin's own schema, every material accepts the core's field
/// properties: conductivity (W/(m K)), specific_heat (J/(kg K)), expansion
/// (c lambda, Pa/K), reference_temperature (degrees C), leavening and water
/// properties; see hearth_core_params. A material with water_diffusivity,
/// evaporation or water_stiffness > 0, or one whose plugin needs saturation,
/// makes the water field live.
/// Returns the material id (>= 0) or -1 with err filled: unknown names suggest
/// the nearest valid name; out-of-range values give the range and unit.
int hearth_scene_add_material(hearth_scene *s, const char *plugin, const char *const *names,
                              const double *values, int n, hearth_error *err);
int hearth_scene_material_count(const hearth_scene *s);
/// A dynamic mixture (Nagasawa et al. 2019 §6, eq. 43-44): k (2..8) constituents of one
/// plugin with a blend callback, constituent c given as names[c]/values[c]/n[c] like
/// hearth_scene_add_material (the first one's core field properties are the mixture's).
/// Bodies of it give their initial mixing ratios (hearth_body_def.ratios); every step
/// each particle's dynamic ratios are the grid average of its neighbours' initial
/// ratios, and its parameters the plugin's blend at those ratios. One mixture per
/// scene. Returns the material id or -1.
int hearth_scene_add_mixture(hearth_scene *s, const char *plugin, int k, const char *const *const *names,
                             const double *const *values, const int *n, hearth_error *err);
/// The dynamic mixing ratios, 8 per particle (the mixture's k in *k; zero for
/// other materials' particles), or NULL when the scene holds no mixture.
const double *hearth_scene_mixing_ratios(const hearth_scene *s, int *k);
/// The schema of the field properties every material has (count in *n).
const hearth_param *hearth_core_params(int *n);
const hearth_material *hearth_scene_material_info(const hearth_scene *s, int mat);
const double *hearth_scene_material_params(const hearth_scene *s, int mat);

/// Particles given explicitly: x and v are 3 doubles each per particle (v may be
/// NULL for rest), volume each (m^3, or area x 1 m in 2D). Returns the number added or -1.
int hearth_scene_add_particles(hearth_scene *s, int material, int n, const double *x, const double *v,
                               double volume, hearth_error *err);
/// Fill a shape with ppc particles per cell (rounded to a lattice of k^dim), jittered
/// by `jitter` (0..1 of the sub-cell) from the scene's seeded generator. Returns the count added.
int hearth_scene_seed_shape(hearth_scene *s, int material, const hearth_shape *shape, int ppc, double jitter,
                            const double velocity[3], hearth_error *err);

typedef void (*hearth_motion_fn)(void *ud, double t, double v[3], double omega[3]);

typedef struct hearth_collider_def {
    const hearth_shape *shape; ///< copied
    hearth_contact mode;
    double friction;           ///< Coulomb coefficient
    double velocity[3];        ///< constant translation velocity (m/s), used when motion is NULL
    double omega[3];           ///< constant angular velocity (rad/s) about pivot, used when motion is NULL
    double pivot[3];           ///< rotation centre at t = 0 (moves with the collider)
    hearth_motion_fn motion;   ///< optional: velocity and omega as functions of time
    void *motion_ud;
    double temperature;        ///< a heated collider (pan, tray): its temperature (degrees C); NaN = not heated
    double beta;               ///< contact heat transfer coefficient (W/(m^2 K)) ("conductive theta, beta", Ding et al. Table 2);
                               ///< INFINITY holds the touching material at `temperature` (Dirichlet: the grid nodes on or inside its face; MPM only)
    double saturation;         ///< a wet collider (cloth, humid surface) holds the saturation of the particles touching it; NaN = dry
    double beta_water;         ///< with saturation: 0 holds it at the contact (Dirichlet); > 0 exchanges water instead, a flux
                               ///< beta_water (s - saturation) out of the body through the contact (Robin), kg/(m^2 s)
    double start_temperature;  ///< with temperature and warm_time > 0: a tray that goes into the oven cold. The collider is at
                               ///< start_temperature (degrees C) when added and approaches temperature as a lumped sheet heated
                               ///< by the oven, T(t) = temperature + (start_temperature - temperature) exp(-(t - t_added) /
                               ///< warm_time), each heat step taking its mean over the step; read only when warm_time > 0
    double warm_time;          ///< the sheet's time constant (s), its heat capacity per area over the coefficient that heats it
                               ///< (rho c thickness / beta_total); 0 (the default, and a zeroed def) = at temperature from
                               ///< the start
    double heat_capacity;      ///< with warm_time > 0: the sheet's heat capacity per area (J/(m^2 K), rho c thickness), so the
                               ///< heat it gives the food is taken from it: C A dT/dt = (C A / warm_time) (temperature - T) -
                               ///< (the heat its contact passed this field step), one lumped temperature over the sheet (MPM
                               ///< only; a finite beta). 0 (the default) = the food draws nothing from it (T(t) above)
    double area;               ///< with heat_capacity: the sheet's area (m^2; in 2D its length, m, per metre of depth), the
                               ///< area that holds C and that the oven heats
} hearth_collider_def;

hearth_collider_def hearth_default_collider_def(void);
/// Returns the collider id or -1.
int hearth_scene_add_collider(hearth_scene *s, const hearth_collider_def *def, hearth_error *err);
/// Set a collider's velocity function (for scenes restored from a checkpoint).
hearth_status hearth_scene_collider_motion(hearth_scene *s, int id, hearth_motion_fn fn, void *ud, hearth_error *err);

/// Extra body force as an acceleration field (m/s^2), added to gravity. NULL removes it.
typedef void (*hearth_body_force_fn)(void *ud, double t, const double x[3], double acc[3]);
/// MPM calls fn at every grid node with mass each step, SPH at every particle, both
/// from several threads at once in a large scene.
void hearth_scene_set_body_force(hearth_scene *s, hearth_body_force_fn fn, void *ud);
/// The same for a function that must not run on several threads at once (a Lua
/// function): while it is set, the MPM grid update and SPH's force loop run on
/// one thread, calling fn in a fixed order. NULL removes it.
void hearth_scene_set_body_force_serial(hearth_scene *s, hearth_body_force_fn fn, void *ud);
/// Set gravity now (m/s^2; z ignored in 2D), for later steps. HEARTH_ERR_PARAM when not finite.
hearth_status hearth_scene_set_gravity(hearth_scene *s, const double g[3], hearth_error *err);
/// Gravity as a function of time (a ramp, a tilt): fn(ud, t, g) is called once
/// at the start of every step, outside parallel loops, with the step's start
/// time, and its g (m/s^2) acts for that step. A non-finite component keeps the
/// previous gravity. NULL removes the function; gravity keeps its last value.
/// Not saved by checkpoints (as motion callbacks).
typedef void (*hearth_gravity_fn)(void *ud, double t, double g[3]);
void hearth_scene_set_gravity_fn(hearth_scene *s, hearth_gravity_fn fn, void *ud);

/// Advance n steps. HEARTH_ERR_GUARD when the guard stopped the run (see
/// hearth_stats.diagnosis). With the rollback policy the scene is left at the
/// last good state; with the stop policy it keeps the failed step for inspection.
hearth_status hearth_scene_step(hearth_scene *s, int n, hearth_error *err);
/// Over MPI ranks each rank steps only its slab's particles. By default a
/// step call ends with every particle back on every rank. A host that calls
/// hearth_scene_whole before it reads or edits particles may keep the slabs
/// between step calls (on = 1), so stepping one call at a time costs no
/// whole-scene gather; the Lua binding does.
void hearth_scene_keep_slabs(hearth_scene *s, int on);
/// Every particle back on every rank (collective: every rank calls it at the
/// same point; a no-op in one process or when the slabs are not kept).
hearth_status hearth_scene_whole(hearth_scene *s, hearth_error *err);
/// Advance until sim time t_end (the last step is shortened to land on it).
hearth_status hearth_scene_advance(hearth_scene *s, double t_end, hearth_error *err);
/// As hearth_scene_advance, but take at most max_steps steps (< 0: no limit), so
/// a host can draw or take input between steps (the dashboard). Returns HEARTH_OK
/// with the scene short of t_end when the limit was reached.
hearth_status hearth_scene_advance_steps(hearth_scene *s, double t_end, long max_steps, hearth_error *err);

typedef enum hearth_guard_state {
    HEARTH_GUARD_OK = 0,
    HEARTH_GUARD_ROLLED_BACK, ///< recovered by rolling back at least once
    HEARTH_GUARD_STOPPED      ///< a check failed; diagnosis says which
} hearth_guard_state;

typedef struct hearth_stats {
    double t, dt;          ///< sim time and the last step (s)
    long step;
    int particles;
    double kinetic;        ///< 1/2 sum m |v|^2 (J, or J/m in 2D)
    double max_speed;      ///< m/s
    double cfl;            ///< (max speed + wave speed) dt / dx of the last step
    double wave_speed;     ///< largest material wave speed (m/s)
    long out_of_domain;    ///< particles pushed back inside the domain so far
    int rollbacks;         ///< rollbacks so far
    hearth_guard_state guard;
    char diagnosis[1024];  ///< empty unless the guard acted
    int grid_blocks;       ///< active grid blocks
    double heat_energy;    ///< sum m alpha (theta + 273.15) over particles (J), alpha each particle's at the water it
                           ///< holds (a material's dry_specific_heat; MPM and SPH); 0 without temperature
    int cg_iterations;     ///< conjugate-gradient iterations of the last implicit heat solve
    double gas_moles;      ///< CO2 in the particles (mol, or mol/m in 2D); 0 without leavening
    double water_mass;     ///< water in the particles (kg, or kg/m in 2D); 0 without water
    double water_lost;     ///< water that left through the boundary so far (kg, or kg/m in 2D); negative if gained
    double oven_heat_in;   ///< heat in through the oven's air boundary so far (J, or J/m in 2D); tallied only with latent_heat on, else 0
    double field_limit;    ///< the fields' own explicit step limit (s: conduction, boundary, latent sink, water); infinite without them or with implicit heat
    double field_dt;       ///< the time the last field update covered (s); 0 before the first
    int field_cycle;       ///< the steps the last field update covered (1 = single rate)
} hearth_stats;
/// The scene's figures. Over MPI ranks with the slabs kept between step calls
/// (hearth_scene_keep_slabs) and heat or water live, the particle sums are added
/// over the ranks: then every rank must call it, as every rank runs the same script.
void hearth_scene_stats(const hearth_scene *s, hearth_stats *st);
/// Simulated time (s): hearth_stats.t without the sums over every particle.
double hearth_scene_time(const hearth_scene *s);

/* ---- bodies and events --------------------------------------------- */

/// A body: a shape filled with particles of one material.
typedef struct hearth_body_def {
    const hearth_shape *shape; ///< not kept
    int material;              ///< from hearth_scene_add_material
    int ppc;                   ///< particles per cell (rounded to a k^dim lattice)
    double jitter;             ///< 0..1 of the sub-cell, from the scene's seeded generator
    double velocity[3];        ///< m/s
    double temperature;        ///< initial temperature (degrees C); NaN = not set. Setting it makes the temperature field live.
    double saturation;         ///< initial water saturation (0..1); NaN = the material's. Setting it makes the water field live.
    int fixed;                 ///< pinned: the particles never move (for tests of the fields alone)
    double ratios[8];          ///< a mixture's initial mixing ratios per constituent (normalised; need not sum to 1)
    int fixed_temperature;     ///< 1: the body keeps `temperature` (Dirichlet: its particles and the grid nodes it fills); needs a temperature; MPM only
    int smooth_surface;        ///< 1: particles seeded within 1.25 lattice spacings of the shape's surface are not jittered, so a flat
                               ///< face is flat (a base resting on a tray); 0 (default): every particle jittered alike
} hearth_body_def;

/// ppc 4, jitter 0.5, at rest, temperature and saturation unset.
hearth_body_def hearth_default_body_def(void);
/// Seed a body. Returns its id (>= 0) or -1; a shape that holds no particle is an error.
int hearth_scene_add_body(hearth_scene *s, const hearth_body_def *def, hearth_error *err);
int hearth_scene_body_count(const hearth_scene *s);
/// Number of particles a body still has (cutting removes some).
int hearth_scene_body_particles(const hearth_scene *s, int body);
/// Random binary labels (Nagasawa et al. 2019, Fig. 1c): give every particle of
/// a body one of k materials (all from the same plugin), drawn independently
/// with probability ratio[i] / sum(ratio). The draw hashes `seed` with each
/// particle's stable id, so it is deterministic and independent of particle
/// order. Mass (density x volume) and plugin state follow the new material.
/// counts (may be NULL) gets the number of particles given each material.
hearth_status hearth_scene_body_labels(hearth_scene *s, int body, int k, const int *materials, const double *ratio,
                                       uint64_t seed, int *counts, hearth_error *err);
/// Set the velocity of every particle of a body (a push). Returns status.
hearth_status hearth_scene_body_set_velocity(hearth_scene *s, int body, const double v[3], hearth_error *err);
/// A fixed body's prescribed rigid motion (SPH only: walls, lids, paddles,
/// pistons): its particles move with velocity + omega x (x - pivot), the pivot
/// (m, at the time of the call) moving with the body; motion (may be NULL)
/// gives velocity and omega as functions of time, called once at the start of
/// every step outside parallel loops (as a collider's). velocity, omega and
/// pivot may be NULL (zero). The velocity enters the viscous term (no-slip on
/// the moving wall) and the pressure and artificial viscosity terms. A second
/// call replaces the body's motion. HEARTH_ERR_PARAM under MPM (move a collider
/// instead), for a body that is not fixed, or for non-finite values.
hearth_status hearth_scene_body_motion(hearth_scene *s, int body, const double velocity[3], const double omega[3],
                                       const double pivot[3], hearth_motion_fn motion, void *motion_ud,
                                       hearth_error *err);
/// Remove every particle inside a shape (cutting). Returns the number removed, or -1.
int hearth_scene_remove_inside(hearth_scene *s, const hearth_shape *shape, hearth_error *err);
/// Replace a collider's motion with constant velocities (removes any motion callback).
hearth_status hearth_scene_collider_set_velocity(hearth_scene *s, int id, const double v[3], const double omega[3],
                                                 hearth_error *err);
/// Move a collider now by d (m), e.g. to press or place it.
hearth_status hearth_scene_collider_translate(hearth_scene *s, int id, const double d[3], hearth_error *err);
int hearth_scene_collider_count(const hearth_scene *s);
/// A heated collider's heat now: out[0] its temperature (degC; NaN when not heated; a warming sheet's present one),
/// out[1] the heat a drawing sheet (heat_capacity > 0) has given the food and out[2] the oven's input into it since
/// it was added (J; in 2D per metre of depth; 0 for a collider that does not draw).
hearth_status hearth_scene_collider_heat(const hearth_scene *s, int id, double out[3], hearth_error *err);
/// Signed distance (m, negative inside) from x to the nearest collider in its
/// current pose; +INFINITY when the scene has none. For drawing colliders.
double hearth_scene_collider_distance(const hearth_scene *s, const double x[3]);

/* ---- temperature curves --------------------------------------------- */

/// Make parameter `param` of material `mat` a piecewise-linear function of
/// temperature through n points (T ascending, degrees C; values inside the
/// parameter's range; constant beyond the ends). Irreversible curves are
/// evaluated at the highest temperature each particle has reached (setting
/// gelatinises and stays set). The core evaluates curves, so plugins see plain
/// numbers. Makes the temperature field live.
hearth_status hearth_scene_material_curve(hearth_scene *s, int mat, const char *param, int n, const double *T,
                                          const double *v, int irreversible, hearth_error *err);
/// What a material curve is a function of (hearth_scene_material_curve_of).
typedef enum hearth_curve_of {
    HEARTH_CURVE_TEMPERATURE = 0, ///< degrees C; values are the parameter's (hearth_scene_material_curve)
    /// The moisture ratio X/X0: a particle's water mass over the water it was given (1 for a raw dough,
    /// 0 bone dry; 1 in a scene without water). Values are dimensionless factors (> 0) that multiply the
    /// parameter, or its temperature curve's value: a crust is its dough stiffened by drying (issue #18).
    HEARTH_CURVE_MOISTURE = 1
} hearth_curve_of;
/// A curve of parameter `param` of material `mat` over `of`: n points (x ascending), constant beyond
/// the ends. A parameter takes at most one curve of each kind; with both, every product of the
/// temperature values and the factors must lie in the parameter's range. An irreversible moisture
/// curve is evaluated at the lowest moisture ratio each particle has reached (a dried crust stays
/// crisp when water diffuses back). HEARTH_CURVE_TEMPERATURE is hearth_scene_material_curve.
hearth_status hearth_scene_material_curve_of(hearth_scene *s, int mat, const char *param, hearth_curve_of of, int n,
                                             const double *x, const double *v, int irreversible, hearth_error *err);
/// Check plugin parameters without a scene (for early, precise errors in scripts).
hearth_status hearth_material_check(const char *plugin, const char *const *names, const double *values, int n,
                                    hearth_error *err);

/* ---- fields and probes ---------------------------------------------- */

/// Names of the fields live in this scene, space separated (static until the scene changes).
const char *hearth_scene_fields(const hearth_scene *s);
/// Number of components of a field (1, 3 or 9), or 0 when the name is unknown.
/// "stress" has 9: the Cauchy stress row-major (xx xy xz yx yy yz zx zy zz, Pa,
/// tension positive); its symmetric components are the scalar fields stress_xx,
/// stress_yy, stress_zz, stress_xy, stress_xz and stress_yz.
int hearth_field_components(const char *field);
/// Unit of a field ("m/s", "kg/m^3", ...), or NULL when unknown.
const char *hearth_field_unit(const char *field);

/// Value of a field at a point (kernel-weighted over nearby particles). out gets
/// the components; NaN where no particle supports the point.
hearth_status hearth_probe_point(const hearth_scene *s, const char *field, const double x[3], double *out,
                                 hearth_error *err);
/// n samples along a..b (n >= 2); out gets n*components values.
hearth_status hearth_probe_line(const hearth_scene *s, const char *field, const double a[3], const double b[3],
                                int n, double *out, hearth_error *err);
/// A plane slice normal to axis (0,1,2) at coordinate `at`, rasterised to w x h
/// samples over the domain (row 0 at the low end of the second in-plane axis).
/// In 2D, axis 2 is the whole domain. Scalar fields only ("velocity_x" etc. for components).
hearth_status hearth_probe_slice(const hearth_scene *s, const char *field, int axis, double at, int w, int h,
                                 double *out, hearth_error *err);
/// A field evaluated at every particle: out gets count*components values.
hearth_status hearth_scene_particle_field(const hearth_scene *s, const char *field, double *out, hearth_error *err);
/// Current volume of the material, sum of V0 J over particles (m^3, or m^2 in 2D).
double hearth_scene_volume(const hearth_scene *s);
/// Particle positions, 3 doubles each, valid until the next step.
const double *hearth_scene_positions(const hearth_scene *s);
int hearth_scene_particle_count(const hearth_scene *s);
/// Bytes the scene's live data fills: its particles' columns and the
/// solver's per-particle step scratch for the particles it holds, a rollback
/// snapshot, and the grid's tables and active blocks. Spare capacity is not
/// counted (hearth_bytes_allocated counts what is held, spare included).
size_t hearth_scene_bytes_used(const hearth_scene *s);
/// Particle ids, one each, in the order of hearth_scene_positions and
/// hearth_scene_particle_field; valid until the next step. An id is given at
/// seeding and never changes or is reused, while the order of particles does
/// (the step sorts them), so a marked particle is found again by its id.
const int *hearth_scene_particle_ids(const hearth_scene *s);
/// Particle masses, one each in the same order (kg; kg/m in 2D, per metre of
/// depth); valid until the next step. A particle's volume is its mass over
/// the "density" field (m^3; m^2 in 2D), as the dumps write it.
const double *hearth_scene_particle_masses(const hearth_scene *s);

/* ---- pictures -------------------------------------------------------- */

/// What a picture shows. Start from hearth_default_picture_def().
typedef enum hearth_picture_kind {
    HEARTH_PICTURE_SLICE = 0,    ///< a plane slice of the field (hearth_probe_slice); outside the material is background
    HEARTH_PICTURE_PARTICLES = 1 ///< the particles as discs (3D: an orthographic view along -z, nearer on top)
} hearth_picture_kind;

/// How a picture's colour range is chosen.
typedef enum hearth_picture_range_mode {
    HEARTH_RANGE_DEFAULT = 0, ///< the field's fixed range (hearth_picture_default_range), else the frame's data
    HEARTH_RANGE_FIXED,       ///< exactly range[0]..range[1]; values beyond take the end colours
    HEARTH_RANGE_FRAME,       ///< the frame's own data (frames of a run do not compare)
    HEARTH_RANGE_GROW         ///< range[0]..range[1] widened to hold the frame's data (s:run holds a field's range so)
} hearth_picture_range_mode;

typedef struct hearth_picture_def {
    const char *field;            ///< a scalar field (a vector shows as its magnitude; a tensor is refused)
    hearth_picture_kind kind;     ///< default HEARTH_PICTURE_SLICE
    int width, height;            ///< pixels, 64..8192; height 0 (default) follows the domain's aspect; default width 800
    int axis;                     ///< slices: the axis normal to the plane, 0..2 (default 2)
    double at;                    ///< slices: the plane's position along axis (m); NaN (default) = the domain's middle;
                                  ///< 3D particles with a depth: the slab's middle along z (m), NaN the domain's
    hearth_picture_range_mode range_mode; ///< default HEARTH_RANGE_DEFAULT
    double range[2];              ///< field units, range[0] < range[1]; read by FIXED and GROW
    const char *colormap;         ///< a name of hearth_colormap_names(); NULL (default) = the field's own
    /// The real seconds one simulated second stands for, in a scene whose rates run time_scale times fast (the
    /// physical presets' oven.time_scale): the title then gives the real time beside the simulated one.
    /// (0, 1e9]; 1 (default) = the title gives the simulated time alone.
    double time_scale;
    /// A short text the title shows before the time, saying what the frame is of or what its clock means
    /// ("oven 110 °C": a scene that bakes several ovens into one folder tree); UTF-8, at most
    /// HEARTH_PICTURE_LABEL_MAX bytes, no control characters. NULL or "" (default) = the time alone. The caller
    /// keeps it; it is read during the call only.
    const char *label;
    /// The part of the picture's plane it shows (m): {horizontal lo, vertical lo, horizontal hi, vertical hi}, the
    /// axes as the picture's (x and y for particles; a slice's in-plane axes in order), inside the domain, lo < hi;
    /// the height follows its aspect. NaN (default) = the whole domain. A close-up of a thin body: a 10 mm
    /// pancake in a 0.32 m box (#18, helper userfix5).
    double region[4];
    /// 3D particle pictures: draw only the particles within depth / 2 of the plane z = at, a slab through the body
    /// seen along -z, and the colliders where that plane cuts them; the title says where ("particles at z = 0.04 ±
    /// 0.0025 m"). A finite number > 0 (m). NaN or +inf (default) = every particle, a projection of every depth.
    /// A crust is one particle deep: the projection shows the front face's, a slab the ring of a cut (#18, helper
    /// userfix11). Refused in 2D and for slices.
    double depth;
} hearth_picture_def;

/// The longest hearth_picture_def.label in bytes: with the longest time and a 3D picture's plane it still fits the
/// title's 320 bytes (128 + 3 + 87 + 46 at the most: a 19-digit step, "particles at z = ... ± ... m"). It was 64
/// while the title was one line (#18, helper userfix3); since a title that one line would set too small puts its label
/// on a line of its own, across the picture (render.c, helper userfix5), what bounds a label is this buffer
/// (#18, helper userfix10: pull_twist.lua's label with eta's unit, 67 bytes, fell back to its short form).
#define HEARTH_PICTURE_LABEL_MAX 128

hearth_picture_def hearth_default_picture_def(void);

/// What a picture was drawn with (for a caller holding a range across frames, and for tests).
typedef struct hearth_picture_info {
    int width, height;   ///< pixels
    double range[2];     ///< the colour range used (field units)
    double data[2];      ///< the smallest and largest finite value drawn (NaN when none)
    int nticks;          ///< colour bar ticks, 4..6 unless the range is degenerate
    double ticks[8];     ///< their values, ascending
    char colormap[16];   ///< the colour map's name
    char unit[32];       ///< the colour bar's unit as printed ("°C", "-" for a dimensionless field)
    double area[4];      ///< the plot area: left, top, width, height (pixels)
    double view_lo[2], view_hi[2]; ///< the domain it shows (m), horizontal then vertical axis
    double bar[4];       ///< the colour bar: left, top, width, height (pixels); range[1] at the top
    char title[320];     ///< the title as drawn: the label, the time (real and simulated with a time_scale) and the step
} hearth_picture_info;

/// Draw a picture of the scene as an RGB PNG, written atomically: the field in
/// its colour map, a colour bar with 4-6 ticks and the field's name and unit,
/// axes in metres, the time (the real time too with a time_scale), colliders as filled grey shapes with an
/// outline. info may be NULL. Errors: HEARTH_ERR_PARAM (an unknown field or
/// colour map, naming the valid ones; a tensor field; a size, axis, range or
/// time_scale out of range), HEARTH_ERR_IO naming the path, HEARTH_ERR_NOMEM.
hearth_status hearth_render(const hearth_scene *s, const hearth_picture_def *def, const char *path,
                            hearth_picture_info *info, hearth_error *err);
/// The field's fixed colour range, which frames of a run share: temperature
/// from the coldest temperature particles were seeded with to the hottest of
/// that, the oven and heated or holding colliders; saturation, browning,
/// porosity, mixing ratios and the boundary flag 0..1. Returns 1 and fills
/// range, or 0 for a field with no fixed range (its range comes from the data).
int hearth_picture_default_range(const hearth_scene *s, const char *field, double range[2]);
/// The colour maps pictures know, as "viridis, inferno, cividis, coolwarm, browning, gray".
const char *hearth_colormap_names(void);
/// Colour of t (0..1, clamped; NaN gives a dark grey) in the named map as
/// 8-bit sRGB. Returns 0, or -1 for an unknown name (rgb untouched).
int hearth_colormap_rgb(const char *name, double t, unsigned char rgb[3]);
/// hearth_render of the particles with the field's default range and colour map.
hearth_status hearth_render_particles(const hearth_scene *s, const char *field, const char *path, int width, int height,
                                      hearth_error *err);
/// hearth_render of a slice (axis, at), width pixels wide, with the field's defaults.
hearth_status hearth_render_slice(const hearth_scene *s, const char *field, int axis, double at, const char *path,
                                  int width, hearth_error *err);

/// Create a folder and any missing parents (like mkdir -p). Output folders use it.
hearth_status hearth_mkdir_p(const char *dir, hearth_error *err);

/* ---- particle dumps ------------------------------------------------- */

/// Write every particle as VTK XML UnstructuredGrid (.vtu, one VTK_VERTEX cell
/// per particle; ParaView and VTK read it). Binary appended data ("raw"
/// encoding), Float64 values. FieldData "TimeValue" holds the sim time (s),
/// the array VTK's XML readers take the time from. PointData: "id" (Int32,
/// hearth_scene_particle_ids, the GlobalIds attribute), "mass [kg]",
/// "volume [m^3]" (2D: "mass [kg/m]", "volume [m^2]"), then every live field
/// as "name [unit]" (hearth_field_unit; "[1]" for a dimensionless one), with
/// "stress [Pa]" the 9-component row-major Cauchy stress (the Tensors
/// attribute) and "velocity [m/s]" the Vectors attribute. Written atomically.
hearth_status hearth_write_vtu(const hearth_scene *s, const char *path, hearth_error *err);
/// Over MPI ranks (collective: every rank calls it with the same path, in the
/// shared output folder; path ends in ".pvtu"): each rank writes its own
/// particles as the piece STEM_pR.vtu beside path (hearth_write_vtu's arrays;
/// in the slab mode the rank's slab, with no gather; a whole scene is cut
/// into N runs of particles), and once every piece is on disk rank 0 writes
/// the .pvtu index naming them. Every file is written atomically. When any
/// rank fails, every rank returns an error (the failing one with its cause).
hearth_status hearth_write_vtu_pieces(const hearth_scene *s, const char *path, hearth_error *err);

/// Options of a PLY dump. Start from hearth_default_ply_def().
typedef struct hearth_ply_def {
    /// Colour the vertices (uchar red, green, blue, which ParaView, Blender and
    /// MeshLab show). Default 1.
    int color;
    /// Field the colours show: a scalar, a vector's magnitude, or a component
    /// ("velocity_x"). NULL (default): temperature when live, else speed.
    const char *color_field;
    /// Colour range in the field's unit; lo >= hi (default {0, 0}): the
    /// frame's own finite min and max.
    double range[2];
    /// Colour map name (cmap names: "viridis", "inferno", ...); NULL: viridis.
    const char *colormap;
} hearth_ply_def;
hearth_ply_def hearth_default_ply_def(void);
/// Binary little-endian PLY, one vertex per particle: x y z (double), red
/// green blue (uchar, when def->color), id (int), mass and volume (double,
/// units as the VTU), then one double property per live field component
/// (velocity_x .. _z, stress_xx, stress_xy, ... row-major). Units, the time
/// and the colour field and range are "comment" lines. def NULL: defaults.
hearth_status hearth_write_ply_with(const hearth_scene *s, const char *path, const hearth_ply_def *def,
                                    hearth_error *err);
/// hearth_write_ply_with(s, path, NULL, err).
hearth_status hearth_write_ply(const hearth_scene *s, const char *path, hearth_error *err);

/* ---- checkpoints ---------------------------------------------------- */

/// Save the full state (written atomically). Motion callbacks are not saved.
hearth_status hearth_scene_save(const hearth_scene *s, const char *path, hearth_error *err);
/// Restore a scene saved by hearth_scene_save. The file is untrusted input: it is
/// refused (NULL, err naming the file and what is wrong) unless its size, its
/// CRC-32 over the whole file and every value in it check out. Plugins are
/// found by name on the plugin search path (never by a path in the file), and
/// their ABI and parameter schema must match those at the save.
hearth_scene *hearth_scene_load(const char *path, hearth_error *err);
/// As hearth_scene_load, from a checkpoint image of n bytes in memory (the
/// caller keeps it; it is not modified). name labels the image in messages
/// (NULL: "(checkpoint in memory)"). For fuzzing and for hosts that keep
/// checkpoints elsewhere than in files.
hearth_scene *hearth_scene_load_mem(const void *data, size_t n, const char *name, hearth_error *err);
/// A 64-bit hash of the particle state, for determinism checks.
uint64_t hearth_scene_hash(const hearth_scene *s);

/* ---- atomic files (for hosts: the command line, the Lua binding) ------ */

/// A file being written atomically: readers of its path see the old file or
/// the whole new one, never a torn one (a temp file "<path>.tmp.<pid>" in the
/// same folder, fsynced and renamed over path at commit).
typedef struct hearth_atomic_file hearth_atomic_file;

#if defined(__GNUC__)
#define HEARTH_PRINTF_LIKE(f, a) __attribute__((format(printf, f, a)))
#else
#define HEARTH_PRINTF_LIKE(f, a)
#endif

/// Start writing path. NULL on failure: HEARTH_ERR_IO (the temp file cannot be
/// created; the message names path and why) or HEARTH_ERR_NOMEM. The handle
/// must end in hearth_atomic_file_commit or hearth_atomic_file_abort.
hearth_atomic_file *hearth_atomic_file_open(const char *path, hearth_error *err);
/// Append n bytes. A failed write is remembered and reported by the commit.
void hearth_atomic_file_write(hearth_atomic_file *af, const void *data, size_t n);
/// Append formatted text (printf rules). Failures as hearth_atomic_file_write.
void hearth_atomic_file_printf(hearth_atomic_file *af, const char *fmt, ...) HEARTH_PRINTF_LIKE(2, 3);
/// Flush, fsync and rename over path, then release af. On any failure
/// (including an earlier write's) the temp file is removed, path is left as
/// it was and HEARTH_ERR_IO names path and the cause.
hearth_status hearth_atomic_file_commit(hearth_atomic_file *af, hearth_error *err);
/// Give up: remove the temp file and release af (NULL is fine).
void hearth_atomic_file_abort(hearth_atomic_file *af);

/* ---- MPI ranks (docs/scaling.md) ---------------------------------------- */
/// Join mpirun's ranks: when hearth was built with MPI (-Dmpi) and this
/// process was started by mpirun (its environment says so), MPI is started
/// here; otherwise the process is one rank. Call once from main, before any
/// scene; returns the rank count. An MPM scene then splits its particle blocks
/// among the ranks (every rank holds the whole scene: docs/scaling.md says what
/// that costs); an SPH scene refuses to run on more than one.
int hearth_ranks_init(int *argc, char ***argv);
/// This process's rank, 0 .. hearth_ranks_size() - 1 (0 without MPI).
int hearth_ranks_rank(void);
/// How many ranks run the scene (1 without MPI or without mpirun).
int hearth_ranks_size(void);
/// 1 when this build has MPI (the rank tests skip otherwise).
int hearth_ranks_built(void);
/// Leave the ranks (MPI_Finalize) after every scene is freed. Safe without MPI and twice.
void hearth_ranks_finalize(void);
/// What this rank's exchanges cost since hearth_ranks_init: bytes received
/// (the grid sums and particle gathers of every MPM step) and wall-clock
/// seconds spent inside them, waiting for the other ranks included. 0 and 0
/// on one rank.
void hearth_ranks_traffic(double *bytes, double *seconds);
/// MPM steps this process took over MPI ranks in the slab mode (each rank
/// holds its slab's particles; docs/scaling.md) and in the replicated mode
/// (every rank holds the whole scene: heat, water, mixing, CO2, periodic
/// axes and the rollback guard need it); and the migration passes past the
/// first of a step (a rebalance that moved a cut by more than a slab).
void hearth_ranks_steps(long *slabs, long *replicated, long *passes);
/// The largest v over the ranks, on every rank (collective; v on one rank):
/// `hearth bench --ranks` reports its slowest rank's figures.
double hearth_ranks_max(double v);
/// Of hearth_ranks_traffic's bytes, those that came in whole-set gathers
/// (every step in the replicated mode; in the slab mode only when a reader,
/// a rebalance or the guard needs the whole scene): the rest is the halo,
/// the crossings and the step report.
double hearth_ranks_gathered(void);
/// The fewest and the most particles this rank held at the end of a slab-mode
/// step (0 and 0 before any): a rank whose slab held none says so (#21).
void hearth_ranks_held(int *least, int *most);

#ifdef __cplusplus
}
#endif
#endif
