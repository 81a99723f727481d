"""scene_csv.py CSV SCENE.lua: a shipped scene's CSV as its readers take it (#18, helper userfix5).
scene_csv.py --units SCENE.lua CSV...: the naming rules alone (time and units), for CSVs whose cells have rules of
their own; SCENE.lua may be - for a CSV no scene wrote (s:run{csv = ...}'s in a test's own script).
scene_csv.py --time-check, --unit-check: each naming rule on headers written here, whose verdicts are known.

Every cell is a finite number, or empty where nothing was measured. An empty cell is allowed only in a column the
scene's header declares may be one, on a line

    -- NAME.csv may leave empty (not measured): col, col,
    --   col, ...

(a list ending in a comma goes on at the next comment line). -1 or 0 standing in for "not measured" reads as a
value (pancake.csv's -1 degC while no batter lay on the pan's centre, helper userview3's item 3): an empty cell
cannot be taken for one.

A time column says its unit in its name (#18, helper userfix6: bread.csv, muffins.csv and tear_open.csv wrote a bare
`t` where the other scenes wrote `t_s`): a column named `t` or `time` is refused, and one named `t_...` must be `t_s`
(the simulated time, s) or a real time, `t_real_s` or `t_real_min` (a scene whose rates run S times fast).

Every other column says its unit the same way (#18, helper userfix7: the SPH particle files' `T`, s:run's `kinetic`
said none): its name ends in `_<unit>` (UNITS below: `_m`, `_degC`, `_J_per_m`, `_m_s` for m/s, `_1_per_m`, ...), or
it is a dimensionless quantity hearth names the same everywhere (one of its words is in PLAIN: `browning`,
`saturation`, `fraction`, `share`, `J` (det F), `id`, `particles`, ...), or its scene declares it on a line

    -- NAME.csv has no unit: col, col,
    --   col, ...

(a count, flag, label or ratio of the scene's own, which its header explains). A probe's column `field_<unit>@x:y:z`
is judged by the part before `@`. `T`, `x`, `kinetic` or `area_plain` are refused.

Exit 0 when the file keeps the rules, 1 naming the first cell or column that breaks one.
"""
import csv
import math
import os
import re
import sys


def declared(scene, name, what):
    """The columns the scene at path `scene` lists on its `-- NAME.csv <what>:` lines (a set; empty if none)."""
    if scene in (None, "-"):
        return set()
    cols, lines = set(), open(scene, encoding="utf-8").read().splitlines()
    head = re.compile(r"^--\s*(\S+\.csv) " + re.escape(what) + r":\s*(.*)$")
    for k, line in enumerate(lines):
        m = head.match(line)
        # NNNN in the declared name stands for a frame's number (particles_NNNN.csv)
        if not m or not re.fullmatch(re.escape(m.group(1)).replace("NNNN", r"\d+"), name):
            continue
        text = m.group(2).strip()
        while text.endswith(",") and k + 1 < len(lines) and lines[k + 1].startswith("--"):
            k += 1
            text += " " + lines[k][2:].strip()
        cols |= {c.strip() for c in text.split(",") if c.strip()}
    return cols


def declared_empty(scene, name):
    """The columns the scene at path `scene` declares may be empty in its CSV `name` (a set; empty if none)."""
    return declared(scene, name, "may leave empty (not measured)")


def declared_plain(scene, name):
    """The columns the scene at path `scene` declares have no unit in its CSV `name` (a set; empty if none)."""
    return declared(scene, name, "has no unit")


TIME_NAMES = ("t_s", "t_real_s", "t_real_min")


def time_column_fault(head):
    """why the header `head` (a list of column names) breaks the time rule, or None"""
    for col in head:
        name = col.strip()
        if name == "t" or name.lower() == "time":  # T is a temperature (the SPH scenes' particles_*.csv)
            return f"column {name!r} gives no unit: name the simulated time t_s (s), a real time t_real_s or t_real_min"
        if name.startswith("t_") and name not in TIME_NAMES:
            return f"column {name!r}: a time column is one of {', '.join(TIME_NAMES)}"
    return None


# The units a column's name may end in, as `_<unit>`: SI symbols, `_per_` for a quotient whose numerator is a unit
# (J_per_m: 2D's energy per metre of depth) and the run-together forms the scenes used first (m_s for m/s, kg_m3 for
# kg/m^3, Pa3s for eq. 11's Pa s^3 fluidity).
UNITS = ("s", "min", "m", "mm", "m2", "m3", "degC", "K", "J", "J_per_m", "W", "N", "N_per_m", "Pa", "Pa_s", "Pa3s",
         "m_s", "1_per_m", "1_per_s", "kg", "kg_per_m", "kg_m3", "mol_m3", "mol_kg", "mol_per_kg_s", "MB")
# Dimensionless quantities hearth names the same in every CSV: a column with one of these words needs no unit.
PLAIN = {"browning", "saturation", "moisture", "fraction", "share", "ratio", "relative", "porosity", "damage", "J",
         "id", "step", "steps", "particles", "pieces", "bodies", "boundary"}


def unit_fault(col, plain=frozenset()):
    """why the column `col` says no unit (None when it does, or needs none)"""
    name = col.strip()
    base = name.split("@", 1)[0]  # a probe's column: field_<unit>@x:y:z
    if base in plain or name in plain:
        return None
    if any(base.endswith("_" + u) for u in UNITS):
        return None
    if any(w in PLAIN for w in base.split("_")):
        return None
    hint = {"T": "T_degC", "x": "x_m", "y": "y_m", "z": "z_m", "kinetic": "kinetic_J or kinetic_J_per_m (2D)",
            "temperature": "temperature_degC", "density": "density_kg_m3", "pressure": "pressure_Pa"}.get(base)
    return (f"column {name!r} gives no unit: end its name in _<unit> ({hint or ', '.join(UNITS[:8]) + ', ...'}), or "
            "declare it in its scene (-- NAME.csv has no unit: ...) if it is a count, flag or ratio")


def naming_fault(head, plain=frozenset()):
    """why the header `head` breaks the time rule or the unit rule, or None"""
    why = time_column_fault(head)
    if why:
        return why
    for col in head:
        if col.strip() in TIME_NAMES:
            continue
        why = unit_fault(col, plain)
        if why:
            return why
    return None


def check_time(path, scene=None):
    with open(path, encoding="utf-8") as f:
        head = next(csv.reader(f), [])
    why = naming_fault(head, declared_plain(scene, os.path.basename(path)))
    if why:
        print(f"{path}:1: {why}")
        return 1
    times = [c for c in head if c in TIME_NAMES]
    print(f"{path}: time columns {times or 'none (not a time series)'}; every column says its unit")
    return 0


def time_check():
    """the time rule on headers whose verdicts are known (a column that only starts with t is not a time)"""
    cases = [("t,front_m", False), ("time,x", False), ("x,y,T", True), ("t_sim,x", False), ("t_s,front_m", True),
             ("oven_degC,leavener,t_s,height_m,t_real_s", True), ("t_real_min,centre_T_degC", True),
             ("tau_y_Pa,top_m,torn,thickness_m", True), ("bake_end_s,cut_s,end_s", True)]
    return verdicts(cases, time_column_fault)


def unit_check():
    """the unit rule on headers whose verdicts are known (#18, helper userfix7: a bare T, x or kinetic says no unit;
    the old s:run header and SPH particle file are refused, the new ones kept)"""
    cases = [("x,y,T", False), ("x_m,y_m,T", False), ("t_s,step,dt_s,particles,kinetic,max_speed", False),
             ("t_s,step,dt_s,particles,kinetic_J_per_m,max_speed_m_s", True),
             ("t_s,kinetic_J,speed_m_s@0.5:0.2:0,saturation@0.1:0.1:0", True), ("t_s,speed@0.5:0.2:0", False),
             ("t_s,area_plain,height_plain_m", False), ("t_s,top_browning,centre_saturation,water_fraction", True),
             ("t_s,mean_temperature_C", False), ("x_m,y_m,T_degC,J,browning,density_kg_m3,pressure_Pa,id", True),
             ("oven_degC,leavener,t_s,height_m,t_real_s", False), ("t_real_min,centre_T_degC", True),
             ("shear_rate,stress", False), ("shear_rate_1_per_s,stress_Pa,hb_stress_Pa", True)]
    ok = verdicts(cases, naming_fault)
    # a scene's declaration lets a count, flag or ratio of its own go without a unit
    got = naming_fault("oven_degC,leavener,height_m".split(","), {"leavener"}) is None
    print(f"'oven_degC,leavener,height_m' with leavener declared: {'kept' if got else 'refused'} "
          f"({'as known' if got else 'WRONG'})")
    return ok if got else 1


def verdicts(cases, fault):
    bad = 0
    for head, ok in cases:
        why = fault(head.split(","))
        got = why is None
        print(f"{head!r}: {'kept' if got else 'refused: ' + why} ({'as known' if got == ok else 'WRONG'})")
        bad += got != ok
    return 1 if bad else 0


def check_cells(path, scene):
    rows = list(csv.reader(open(path, encoding="utf-8")))
    if check_time(path, scene):
        return 1
    head, may = rows[0], declared_empty(scene, os.path.basename(path))
    may &= set(head)  # a preset may write fewer columns (pancake.lua's paper preset has no middle_*)
    empty = 0
    for n, r in enumerate(rows[1:], start=2):
        if len(r) != len(head):
            print(f"{path}:{n}: {len(r)} cells for {len(head)} columns")
            return 1
        for col, c in zip(head, r):
            if c == "":
                if col not in may:
                    print(f"{path}:{n}: column {col} is empty; {scene} does not declare it may be")
                    return 1
                empty += 1
                continue
            try:
                v = float(c)
            except ValueError:
                v = math.nan
            if not math.isfinite(v):
                print(f"{path}:{n}: column {col} reads {c!r}, not a finite number")
                return 1
    print(f"{path}: {len(rows) - 1} rows, {empty} empty cells (not measured), in the declared columns "
          f"{sorted(may) or 'none'}")
    return 0


if __name__ == "__main__":
    if sys.argv[1] == "--time-check":
        sys.exit(time_check())
    if sys.argv[1] == "--unit-check":
        sys.exit(unit_check())
    if sys.argv[1] == "--units":
        sys.exit(max([check_time(p, sys.argv[2]) for p in sys.argv[3:]] or [0]))
    sys.exit(check_cells(sys.argv[1], sys.argv[2]))
