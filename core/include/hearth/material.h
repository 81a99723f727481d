/* hearth/material.h: the material plugin ABI and its contract. A plugin needs
 * this header and, for 3x3 algebra, the header-only <hearth/tensor.h>; both are
 * installed (`pkg-config --cflags hearth`), and a plugin links nothing but libm.
 *
 * A plugin is a shared object named hearth_<name>.so that exports one symbol,
 * HEARTH_MATERIAL_ENTRY ("hearth_material_v1"), returning a pointer to a
 * static descriptor. Every rule below is one the loader (core/sim/plugins.c)
 * or the solvers enforce; the loader refuses a plugin that breaks a load-time
 * rule with a message naming the file, the field and the fix. Run
 * `hearth plugin check hearth_<name>.so` to meet them before a scene does.
 *
 * THE CONTRACT
 *
 * 1. Size and version (checked first, before any other field is read).
 *    abi_version == HEARTH_MATERIAL_ABI, struct_size == sizeof(hearth_material)
 *    and real_size == sizeof(double) as the plugin was compiled. struct_size
 *    must cover every field through describe_error; the loader copies only
 *    struct_size bytes, so an optional callback appended after the plugin was
 *    built reads as NULL, and a newer plugin's extra fields are ignored.
 *    hearth_material and hearth_point only grow at the end; a change to either
 *    that breaks layout bumps HEARTH_MATERIAL_ABI, and the loader refuses any
 *    other major version. hearth_point carries no size of its own: a field
 *    appended to it comes with a new HEARTH_NEEDS_* bit, and a core that does
 *    not know a needs bit refuses the plugin, so a plugin that sets the bit
 *    never reads past an older core's point, and one that does not never
 *    reads the new field.
 *
 * 2. Descriptor. name is [a-z0-9_]+ (it is the file's <name> and a Lua
 *    string: the loader refuses a file hearth_<other>.so that holds it, since
 *    a checkpoint finds a plugin again by this name). init, stress, wave_speed
 *    and describe_error are non-NULL;
 *    blend, plastic_J, viscosity, damage, stress_block, bulk_modulus and scalars_block may be NULL,
 *    and memo_size 0. nparams <= 256 with params
 *    non-NULL when nparams > 0; 0 <= state_size <= 4096; 0 <= memo_size <= HEARTH_MEMO_MAX (rule 10);
 *    needs holds only known HEARTH_NEEDS_* bits.
 *
 * 3. Parameters. Each name is a Lua identifier [A-Za-z_][A-Za-z0-9_]*, unique
 *    in the schema; unit is non-NULL (SI, "1" when dimensionless); min and max
 *    are finite with min <= max; min <= def <= max.
 *    - `density` is required: unit exactly "kg/m^3" and min > 0 (the core
 *      gives particles their mass from it).
 *    - The names in HEARTH_RESERVED_PARAM_NAMES are the core's own parameters,
 *      which every material accepts in the same table as the plugin's (see
 *      hearth_core_params() in <hearth/hearth.h> for units, ranges and help);
 *      a plugin parameter with one of these names is refused.
 *    - Under the SPH solver a parameter named `viscosity` (Pa s) is the
 *      core's: SPH applies it itself (Morris et al. viscous term, eq. 3.19 of
 *      Rodriguez-Arenas 2011, with no-slip walls), passes 0 for it to stress,
 *      and limits the step with its kinematic value viscosity/density. The
 *      name is looked up once per material, when it is added to an SPH
 *      scene. Under MPM the plugin applies it, like any other parameter.
 *
 * 4. Wave speed. wave_speed must be finite and > 0 over the whole schema. At
 *    load the loader calls init and then wave_speed on a fresh state at the
 *    defaults, with each parameter at its min and at its max (the rest at
 *    defaults), with every parameter at its min and with every one at its max,
 *    and refuses the plugin at the first bad value; during a run a bad value
 *    goes to the stability guard, which names the plugin. MPM
 *    limits the step with it (CFL); SPH takes it as the sound speed c0 of its
 *    Tait pressure.
 *
 * 5. Concurrency. init is called from one thread while a scene is built.
 *    stress, wave_speed, plastic_J, viscosity and blend are called from many
 *    OpenMP threads at once, each call on its own point and state. A plugin
 *    must therefore keep no writable global or static data: everything a call
 *    needs is in its arguments, everything it keeps is in the point's state.
 *
 * 6. Calls. Every pointer the core passes is valid only for the duration of
 *    the call. A callback returns: it does not exit, abort, longjmp or block
 *    (the hearth command ends with status 4, naming the plugin and the
 *    callback, when one crashes or calls exit). stress reports failure by its
 *    return code, never by printing; a code, or a NaN or infinite tau, goes to
 *    the stability guard, which stops the scene naming the plugin and the
 *    code's describe_error text (or, under the rollback policy, retries the
 *    step smaller).
 *
 * 7. The batched stress (optional, appended last: a plugin built before it
 *    reads as NULL). stress_block(b, tau, code) does for each of the b->n
 *    points of a hearth_block what stress does for one hearth_point with
 *    the same values, and must give the SAME BITS: tau, the state it writes
 *    and the code (the tau of a point with a nonzero code is not read).
 *    `hearth plugin check` compares the two on a battery of points (random F
 *    near and far from I, advanced states, temperatures, parameters that
 *    vary by point, dim 2 and 3) and names the first point that differs.
 *    Bit for bit is easy to keep: do each point's arithmetic in the same
 *    order as stress does (hoisting a value that is the same for every point,
 *    such as the Lame constants of uniform parameters, gives the same bits);
 *    the compiler vectorises across points without reordering a point's
 *    operations, but not calls such as log, so leave those in their own
 *    scalar loop. MPM's P2G calls stress_block when the plugin has one, for
 *    runs of up to HEARTH_BLOCK_MAX consecutive particles of one material,
 *    and stress for the rest (a mixture's particles, a material with more
 *    than 8 parameters on curves; a point whose F failed is in no run); everything else (SPH, probes, the guard, the rheometer)
 *    calls stress. The environment variable HEARTH_PLUGIN_NO_BATCH=1, set
 *    before a plugin is loaded, makes the core ignore stress_block (the same
 *    results, one call per point), for comparing the two in a scene.
 *
 * 8. Dimension. hearth_point.dim and hearth_block.dim say in which dimension
 *    the point lives: 3, or 2 for a 2D scene, which is plane strain: F and
 *    grad_v have F[2] = F[5] = F[6] = F[7] = 0 (no out-of-plane shear; F[8]
 *    is the out-of-plane stretch, 1 unless the law or the solver keeps one),
 *    and the solver reads tau's in-plane block (it still counts tau[8] for
 *    pressure and yield). A plugin may use it to skip the zero terms; the
 *    stress must be the one the 3x3 formula gives. A plugin that reads dim
 *    sets HEARTH_NEEDS_DIM (rule 1: an older core, without the field,
 *    refuses it). The core fills dim for every plugin.
 *
 * 9. The batched scalars (optional, appended after bulk_modulus: a plugin built before it reads as
 *    NULL). scalars_block(b, out) gives, for each of the b->n points of a block, the per-point scalars
 *    the core otherwise asks one call at a time: out[HEARTH_SCALAR_k][j] is what the one-point callback
 *    (wave_speed, plastic_J, bulk_modulus, viscosity, damage) returns for point j's parameters
 *    (hearth_block_param) and state, with the SAME BITS. out[k] is NULL for a scalar the core does not
 *    want this call (it asks only for scalars whose one-point callback the plugin has); the other
 *    columns hold b->n values to write. It reads only n, dim, p, p_col, state and state_stride, and
 *    writes nothing but out (the state is read-only here). MPM's P2G calls it only with stress_block,
 *    on the blocks it hands stress_block: before the stress (J^P and K at the start of the step) and
 *    after it (the wave speed, viscosity, damage and J^P of the state the stress wrote).
 *    HEARTH_PLUGIN_NO_BATCH=1 makes the core ignore it too. `hearth plugin check` compares it with the
 *    one-point callbacks on the batched battery's blocks and names the first point that differs.
 *
 * 10. The block's memo (optional: memo_size, appended after scalars_block, with HEARTH_NEEDS_MEMO). A
 *    plugin with stress_block may ask for memo_size doubles per point (1..HEARTH_MEMO_MAX) that the core
 *    keeps for it and hands to stress_block as hearth_block.memo: point j's at memo + j * memo_stride.
 *    It is a cache, not state: between the fields' updates a point's temperature holds, and a law may
 *    meet an argument it met the step before (cam_clay_dough's log of the out-of-plane stretch b_zz),
 *    whose value the memo can keep. An entry holds zeros or what this plugin's stress_block last wrote
 *    into some point's memo, of some block, in some earlier call: not necessarily this point's (the core
 *    moves memos with their particles, but a restored or grown scene starts from zeros), not
 *    necessarily for this material's parameters. So stress_block must give the SAME BITS whatever the
 *    memo holds of that kind, or when memo is NULL (the core passes none): key every cached value on
 *    every input it is a function of, compared bit for bit, and make a zeroed entry miss. The core
 *    neither hashes nor saves the memo (a checkpoint that claims one is refused), so a hit cannot move
 *    a scene's bits. `hearth plugin check` runs each batched block with the memo NULL, zeroed, warm
 *    (the same block again, every key met) and swapped between points (point j's memo is point n-1-j's),
 *    and names the first point whose results differ from the one-point stress. HEARTH_NEEDS_MEMO makes
 *    a core that does not know the field refuse the plugin; memo_size > 0 needs the bit and the bit
 *    needs memo_size > 0 and stress_block. HEARTH_PLUGIN_NO_BATCH=1 drops the memo with stress_block.
 *
 * All tensors are 3x3, row-major (a[3*row+col]), in SI units. 2D scenes are
 * plane strain: the solver passes tensors whose z row and column describe no
 * deformation, and ignores the zz stress for motion (it still counts for
 * pressure and yield). SPH keeps only the deviatoric part of tau / J; its
 * pressure is the Tait equation's.
 */
#ifndef HEARTH_MATERIAL_H
#define HEARTH_MATERIAL_H

#ifdef __cplusplus
extern "C" {
#endif

/// Major version of this ABI. The loader refuses any other value.
#define HEARTH_MATERIAL_ABI 1
/// Name of the one exported entry symbol.
#define HEARTH_MATERIAL_ENTRY hearth_material_v1
#define HEARTH_MATERIAL_ENTRY_NAME "hearth_material_v1"

/// Bits of hearth_material.needs: fields the core must keep live for this material.
enum {
    HEARTH_NEEDS_TEMPERATURE = 1u << 0, ///< hearth_point.temperature is filled (degrees C)
    HEARTH_NEEDS_POROSITY = 1u << 1,    ///< hearth_point.porosity is filled (0..1)
    HEARTH_NEEDS_SATURATION = 1u << 2,  ///< hearth_point.saturation is filled (0..1)
    /// The law is written to be completed by the core's thermal expansion (Ding et al. eq. 10): a thermal
    /// strain taken out of F and grad_v when the plugin gives bulk_modulus, else the pressure
    /// -c*lambda*(T-Tref) I added after the stress. The core applies it to any material whose core
    /// parameter `expansion` (c*lambda) is > 0, flagged or not; the flag states the intent, and
    /// `hearth plugin check` and the rheometer fill the temperature for it.
    HEARTH_NEEDS_THERMAL_EXPANSION = 1u << 3,
    /// hearth_point.dim and hearth_block.dim are read (contract rule 8). Every core that knows the bit
    /// fills them for every plugin; the bit only makes an older core, whose point has no dim, refuse.
    HEARTH_NEEDS_DIM = 1u << 4,
    /// hearth_block.memo and memo_stride are read (contract rule 10; memo_size > 0). A core that does not
    /// know the bit refuses the plugin, so stress_block never reads past an older core's block.
    HEARTH_NEEDS_MEMO = 1u << 5
};

/// The most doubles of memo a point may have (hearth_material.memo_size, contract rule 10).
#define HEARTH_MEMO_MAX 8

/// The most points a hearth_block holds (stress_block may keep per-point scratch of this size on its stack).
#define HEARTH_BLOCK_MAX 64

/// Columns of scalars_block's out (contract rule 9): the one-point callback each column stands for.
enum {
    HEARTH_SCALAR_WAVE_SPEED,   ///< wave_speed (m/s)
    HEARTH_SCALAR_PLASTIC_J,    ///< plastic_J (1)
    HEARTH_SCALAR_BULK_MODULUS, ///< bulk_modulus (Pa)
    HEARTH_SCALAR_VISCOSITY,    ///< viscosity (Pa s)
    HEARTH_SCALAR_DAMAGE,       ///< damage (1)
    HEARTH_SCALAR_COUNT
};

/// The parameter names the core reserves (contract rule 3): its own per-material parameters, in the
/// order of hearth_core_params(). The loader refuses a plugin parameter with any of these names.
#define HEARTH_RESERVED_PARAM_NAMES                                                                          \
    "conductivity", "specific_heat", "expansion", "reference_temperature", "gas_rate", "reaction_temperature", \
        "reaction_width", "porosity", "saturation", "water_diffusivity", "evaporation", "water_stiffness",       \
        "water_density", "bubble", "dry_conductivity", "dry_specific_heat", "ambient_pressure", "open_temperature", \
        "gas_rate_2", "reaction_temperature_2", "reaction_width_2", "gas_amount", "gas_amount_2"

/// One entry of a parameter schema. def must lie in [min, max].
typedef struct hearth_param {
    const char *name; ///< identifier used in Lua and on the command line
    const char *unit; ///< SI unit, e.g. "Pa", "Pa s", "kg/m^3", "1" for dimensionless
    const char *help; ///< one line for `hearth plugins`
    double def, min, max;
} hearth_param;

/// One material point, solver-agnostic (MPM and SPH fill it the same way).
/// Valid only for the duration of one callback; its layout is fixed for a given
/// HEARTH_MATERIAL_ABI (contract rule 1).
typedef struct hearth_point {
    double grad_v[9]; ///< velocity gradient dv/dx over the step (1/s)
    double F[9];      ///< total deformation gradient at the END of the step (already updated by the solver)
    double dt;        ///< step (s); 0 means "evaluate only": do not advance time-dependent state
    /// degrees C, (0..1), (0..1); NaN when the scene does not carry the field. Declare the ones the law
    /// reads in `needs`: HEARTH_NEEDS_TEMPERATURE turns the temperature field on. MPM and SPH fill
    /// porosity (from plastic_J and the core's `porosity`) when the material needs it (MPM also when the
    /// scene has gas); SPH carries no saturation, and a material that needs it is refused when added
    /// to an SPH scene.
    double temperature, porosity, saturation;
    const double *p;  ///< resolved parameters in schema order (curves evaluated, blends applied), nparams doubles
    double *state;    ///< plugin-owned per-point state, state_size doubles (may be NULL when state_size is 0)
    /// 2 or 3: the dimension of the scene the point lives in (contract rule 8; appended with HEARTH_NEEDS_DIM).
    int dim;
} hearth_point;

/// A block of points of one material as columns (structure of arrays), for the optional stress_block
/// callback (contract rule 7): entry c (row-major, a[3*row+col]) of point j's F is F[c][j]. Everything
/// a hearth_point carries, with what is the same for every point given once. Valid only for the
/// duration of one call; the columns do not alias each other or the output.
typedef struct hearth_block {
    int n;                   ///< points, 1..HEARTH_BLOCK_MAX
    int dim;                 ///< 2 or 3, as hearth_point.dim (rule 8)
    double dt;               ///< as hearth_point.dt, the same for every point
    const double *grad_v[9]; ///< velocity gradient columns (1/s), n values each
    const double *F[9];      ///< deformation gradient columns at the END of the step, n values each
    /// Columns of n values for the fields the plugin declares in `needs` (NaN where the scene does not
    /// carry the field, as in hearth_point); NULL for a field it does not declare.
    const double *temperature, *porosity, *saturation;
    /// The parameters that are the same for every point of the block (schema order, nparams doubles,
    /// curves already applied). Read parameter k of point j with hearth_block_param().
    const double *p;
    /// nparams pointers: NULL where p[k] holds for every point, else a column of the n points' values
    /// (a temperature or moisture curve makes a parameter vary from point to point).
    const double *const *p_col;
    double *state;    ///< point j's state at state + j * state_stride (NULL when state_size is 0)
    int state_stride; ///< doubles from one point's state to the next, >= state_size
    /// Appended with HEARTH_NEEDS_MEMO (contract rule 10): point j's memo_size doubles of cache at
    /// memo + j * memo_stride, or NULL (no memo this call). Read only by a plugin that sets the bit.
    double *memo;
    int memo_stride; ///< doubles from one point's memo to the next, >= memo_size
} hearth_block;

/// Parameter k of point j of block b.
static inline double hearth_block_param(const hearth_block *b, int k, int j) {
    return b->p_col[k] ? b->p_col[k][j] : b->p[k];
}

/// The descriptor a plugin returns. Static storage, never freed by the core.
typedef struct hearth_material {
    int abi_version; ///< must be HEARTH_MATERIAL_ABI
    int struct_size; ///< sizeof(hearth_material) as the plugin was compiled
    int real_size;   ///< sizeof(double) as the plugin was compiled
    const char *name;    ///< short identifier, [a-z0-9_]+
    const char *summary; ///< one line
    const hearth_param *params;
    int nparams;
    int state_size;  ///< doubles of per-point state (0 allowed)
    unsigned needs;  ///< HEARTH_NEEDS_* bits

    /// Required. Set the initial state of a point at rest (F = I). state is never NULL here; the
    /// core may skip the call for a material whose state_size is 0.
    void (*init)(const double *p, double *state);
    /// Required. Advance state over pt->dt and write the Kirchhoff stress tau = J sigma (Pa).
    /// Returns 0 on success, or a plugin-specific positive code explained by describe_error; a code
    /// goes to the stability guard like a NaN stress (contract rule 6). Called concurrently (rule 5).
    int (*stress)(hearth_point *pt, double tau[9]);
    /// Required. An upper bound of the speed of elastic/pressure waves (m/s): the CFL limit under MPM,
    /// the Tait sound speed under SPH. Finite and > 0 (contract rule 4). state is NULL when state_size is 0.
    double (*wave_speed)(const double *p, const double *state);
    /// Optional (may be NULL). Blend k parameter sets with weights alpha (summing to 1) into out.
    int (*blend)(int k, const double *alpha, const double *const *pk, double *out);
    /// Required. Text for a code returned by stress. Static storage.
    const char *(*describe_error)(int code);
    /// Optional (may be NULL, meaning 1). Plastic volume ratio J^P from the state, for porosity (Ding et al. §5.4).
    double (*plastic_J)(const double *p, const double *state);
    /// Optional (may be NULL; read only when struct_size covers it). The dynamic viscosity (Pa s)
    /// the stress applies explicitly from the velocity gradient, for the step limit
    /// dt <= rho dx^2 / (2 dim eta). Leave NULL when viscous flow is integrated implicitly.
    double (*viscosity)(const double *p, const double *state);
    /// Optional (may be NULL, meaning an intact material; read only when struct_size covers it). The
    /// point's damage in [0, 1] from its state. At 1 the point is cracked: the core cuts the stress
    /// off in tension (each tensile principal value of tau set to 0, so a crack's faces carry
    /// compression only) and adds none of its pressures (gas, water, thermal expansion: the crack
    /// vents the pores and frees the faces). Called concurrently (rule 5). Called once with state NULL
    /// when a material is added: return 0 when a point with these parameters can never crack (the
    /// core then never asks per point and lists no `damage` field), anything else when it may; a
    /// material given curves or a blend is asked again at each curve value and each constituent.
    double (*damage)(const double *p, const double *state);
    /// Optional (may be NULL; read only when struct_size covers it). The batched stress (contract rule 7):
    /// for each point j < b->n, advance its state and write tau[c][j] (c = 0..8) and code[j] exactly as
    /// stress would for that point alone, bit for bit. Returns the number of points with a nonzero code.
    /// Called concurrently, each call on its own block (rule 5).
    int (*stress_block)(const hearth_block *b, double *const tau[9], int *code);
    /// Optional (may be NULL; read only when struct_size covers it). The small-strain bulk modulus K (Pa)
    /// of the law at these parameters and state: the stiffness against a change of volume at rest
    /// (lambda + 2/3 mu for an isotropic law). Finite and > 0 when given. With it the core's thermal
    /// expansion (core parameter `expansion`, c lambda of Ding et al. eq. 10) is a thermal strain,
    /// ln J_th = c lambda (T - T_ref) / K: the core hands stress a point's F and grad_v with that
    /// isotropic stretch taken out (F = F_M F_th, F_th = J_th^(1/3) I), so the law's own return map sees
    /// the whole elastic stress and a free body expands by J_th and no further, whether it yields or not.
    /// Without it the core adds the thermal pressure -c lambda (T - T_ref) I after the stress, outside the
    /// law's yield condition (a yielding skeleton then never relaxes it). Called concurrently (rule 5).
    /// Asked only when a material has `expansion` > 0 and a temperature. A value that is NaN, infinite
    /// or <= 0 fails that point (no pressure is put in its place): the stability guard stops the run,
    /// naming the plugin, its file and the value. `hearth plugin check` asks it at the defaults, at the
    /// parameter corners and in advanced states, and compares it with the law's own mean stress under a
    /// small isotropic volume change (a warning where the law flows plastically there).
    double (*bulk_modulus)(const double *p, const double *state);
    /// Optional (may be NULL; read only when struct_size covers it). The batched scalars (contract rule 9):
    /// for each point j < b->n and each k with out[k] non-NULL, out[k][j] = the one-point callback k's value
    /// (HEARTH_SCALAR_*) for point j's parameters and state, bit for bit. Reads the state, never writes it.
    /// Called concurrently, each call on its own block (rule 5).
    void (*scalars_block)(const hearth_block *b, double *const out[HEARTH_SCALAR_COUNT]);
    /// Optional (0 when struct_size does not cover it). Doubles of per-point memo stress_block keeps
    /// (contract rule 10), 0..HEARTH_MEMO_MAX; > 0 only with stress_block and HEARTH_NEEDS_MEMO.
    int memo_size;
} hearth_material;

/// The entry point a plugin defines.
typedef const hearth_material *(*hearth_material_entry_fn)(void);

#if defined(_WIN32)
#define HEARTH_PLUGIN_EXPORT __declspec(dllexport)
#else
#define HEARTH_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
}
#endif
#endif
