/* checkpoint.h: private parts of the checkpoint format (checkpoint.c reads,
 * checkpoint_save.c writes) that shapes.c, the unit tests and the fuzz target
 * need: the bounds-checked read cursor, the header layout, ck_reseal, and the
 * plugin schema's hash both halves use.
 *
 * Layout of version 6 (native byte order and double width, both recorded and
 * checked; every count is unsigned 32-bit, every string a u32 length then its
 * bytes without a terminator):
 *
 *   header, 40 bytes:
 *     0  "HEARTHCK"
 *     8  u32 version (6; 4 added the humid oven, wet colliders' beta_water, held temperatures,
 *        latent_heat, browning and its scale; 5 appended damping, boiling_point, periodic,
 *        two_field, two_field_friction, gas_vent and vent_porosity to the DEF section.
 *        Version 4 files are read with those at their defaults, the values every
 *        version 4 file had: its writer refused any other; 6 appended field_steps to DEF and
 *        the fields' cycle to CLK, read from 4 and 5 as 1, every step, and a new cycle)
 *    12  u32 byte-order mark 0x01020304
 *    16  u32 sizeof(double) (8)
 *    20  u32 header size (40)
 *    24  u64 total file size in bytes
 *    32  u32 CRC-32 of the whole file, computed with these 4 bytes taken as 0
 *    36  u32 reserved, 0
 *   sections, each opened by a 4-byte tag:
 *    "DEF " the scene definition (put_def in checkpoint.c); version 5 appends
 *           f64 damping, f64 boiling_point, i32 periodic[3], i32 two_field,
 *           f64 two_field_friction, f64 gas_vent, f64 vent_porosity; version 6
 *           i32 field_steps; version 16 f64 oven_wall_temperature, oven_emissivity and
 *           oven_radiation_scale
 *    "CLK " i32 guard state, then the clocks and the jitter generator; version 6 appends
 *           f64 the fields' cycle time, i32 its steps, f64 and i32 the last field step's
 *           version 7 appends i32 whether the water's step limits are kept (1) and f64 their
 *           dmax, emax and lmax (water.h's water_state)
 *           version 13 appends f64 self_max (mpm_self.c's bound on a lone particle, in [0, 9])
 *    "MATS" u32 count; per material: name, u32 ABI, u64 schema hash,
 *           u32 nparams, f64 params, f64 core params (params.h's order: version 7 appended
 *           dry_conductivity, version 8 dry_specific_heat, version 10 ambient_pressure and open_temperature, version 12
 *           the second CO2 share's three, version 13 gas_amount and gas_amount_2), u32 curves, curves (each: u32 param,
 *           u32 points, u32 flags: bit 0 irreversible, bit 1 a moisture curve; f64 x, f64 values)
 *    "COLS" u32 count; per collider: shape tree (shape_read_mem), contact and pose, heat and water; version 14
 *           appends f64 start_temperature, warm_time and t_added; version 15 f64 heat_capacity, area, sheet_T,
 *           sheet_t, last_heat, last_span, oven_in, drawn
 *    "PART" u32 n, u32 state stride, u32 enabled columns; per enabled column
 *           its name and n * (bytes per particle)
 *    "HASH" u64 hearth_scene_hash of the restored particles
 *   and nothing after it.
 */
#ifndef HEARTH_CHECKPOINT_H
#define HEARTH_CHECKPOINT_H
#include <stddef.h>
#include <stdint.h>

#define CK_MAGIC "HEARTHCK"
/* 7: the water's step limits in the clocks, the materials' dry_conductivity (params.h); 8: their dry_specific_heat;
 * 9: the browning surface's column (PC_SURFACE, "browning_surface") in PART for MPM with browning and an oven: a
 * version 8 or older file has none and loads with it zeroed, its hash taken over the columns it holds (an older
 * hearth refuses a version 9 file by its version, not by a column it would misread); 10: the materials'
 * ambient_pressure and open_temperature (params.h; gas.h's gas_tau_ambient); 11: the sticky faces' glue column
 * (PC_GLUE, "glue", mpm_touch.c) in PART for an MPM scene with a sticky face that has stepped: an older file has
 * none, and its first step glues what its sticky faces held then (every particle whose stencil reaches a node on
 * or inside them), so it goes on as it was saved (an older hearth refuses a version 11 file by its version); 12: the
 * materials' second CO2 share, gas_rate_2, reaction_temperature_2, reaction_width_2 (params.h; gas.c): an older file
 * has none and loads with gas_rate_2 0, its bits; 13: the materials' gas_amount and gas_amount_2 (params.h; gas.h's
 * gas_share_capped), the CO2 each share has made (PC_GAS_MADE, "gas_made") in PART when a material has an amount, and
 * f64 self_max appended to CLK (the last step's bound on a lone particle, mpm_self.c): an older file has no amounts
 * (no limit), so nothing made, and self_max 0 (its first step unbounded, as it restored then); 14: each collider's
 * start_temperature, warm_time and t_added appended in COLS (a tray that warms, colliders.h), its temperature slot the
 * one it warms toward: an older file's colliders do not warm; 15: each collider's heat_capacity and area (a sheet the food
 * draws heat from, colliders.h) and its state (f64 sheet temperature, its time, the last field step's draw and span,
 * the oven's input and the draw since added) appended in COLS: an older file's sheets draw nothing; 16: the oven's wall
 * temperature, emissivity and radiation_scale appended to DEF (fields/thermal.h): an older file's oven has no
 * radiating walls */
#define CK_VERSION 16u
/// Oldest version read: a version 4 file is version 5's layout without the
/// DEF fields version 5 appended.
#define CK_VERSION_MIN 4u
#define CK_BOM 0x01020304u
#define CK_HEADER_SIZE 40u
#define CK_OFF_SIZE 24u
#define CK_OFF_CRC 32u

/// Largest checkpoint hearth reads (bytes): above it the file is refused
/// before it is read. 2^36 = 64 GiB, a few hundred million particles.
#define CK_FILE_MAX ((uint64_t)1 << 36)

/// A read cursor over a checkpoint image in memory. Every read checks the
/// bytes left first; after the first failure bad stays set, every read returns
/// zeros, and what names the failure (a static string, or msg) for the message.
typedef struct ck_cursor {
    const uint8_t *p; ///< next byte
    size_t left;      ///< bytes from p to the end of the image
    int bad;
    const char *what; ///< why the cursor went bad (static or msg), NULL while good
    char msg[192];    ///< a failure's text built from the value read (a setting out of its range)
} ck_cursor;

/// Copy n bytes to out and advance; on too few bytes zero out, set bad and
/// return -1 (what = "truncated").
int ck_get(ck_cursor *c, void *out, size_t n);
/// Mark the cursor bad with a reason (static string) unless it already is. Returns -1.
int ck_fail(ck_cursor *c, const char *what);

/// The CRC-32 a checkpoint image of n bytes should carry (the header's field
/// taken as 0). n must be at least CK_HEADER_SIZE.
uint32_t ck_crc(const uint8_t *buf, size_t n);

/// Recompute and store the whole-file checksum (and the size field) of the
/// checkpoint image buf[0..n) in place, so a fuzzer's or a test's changes to
/// the body reach the parser instead of stopping at the checksum. Does nothing
/// when n is smaller than the header.
void ck_reseal(uint8_t *buf, size_t n);

struct hearth_material;
/// FNV-1a over what a saved material depends on (checkpoint.c): written with
/// each material (checkpoint_save.c) and compared on load, so a plugin whose
/// parameters or state changed meaning is refused rather than misread.
uint64_t ck_schema_hash(const struct hearth_material *m);
#endif
