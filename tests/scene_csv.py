"""scene_csv.py CSV SCENE.lua: a shipped scene's CSV as its readers take it (#18, helper userfix5).
scene_csv.py --time CSV...: the time rule alone, for CSVs whose cells have rules of their own.
scene_csv.py --time-check: the time rule on headers written here, whose verdicts are known.

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

Exit 0 when the file keeps the rules, 1 naming the first cell or column that breaks one.
"""
import csv
import math
import os
import re
import sys


def declared_empty(scene, name):
    """The columns the scene at path `scene` declares may be empty in its CSV `name` (a set; empty if none)."""
    cols, lines = set(), open(scene, encoding="utf-8").read().splitlines()
    head = re.compile(r"^--\s*" + re.escape(name) + r" may leave empty \(not measured\):\s*(.*)$")
    for k, line in enumerate(lines):
        m = head.match(line)
        if not m:
            continue
        text = m.group(1).strip()
        while text.endswith(",") and k + 1 < len(lines) and lines[k + 1].startswith("--"):
            k += 1
            text += " " + lines[k][2:].strip()
        cols |= {c.strip() for c in text.split(",") if c.strip()}
    return cols


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


def check_time(path):
    with open(path, encoding="utf-8") as f:
        head = next(csv.reader(f), [])
    why = time_column_fault(head)
    if why:
        print(f"{path}:1: {why}")
        return 1
    times = [c for c in head if c in TIME_NAMES]
    print(f"{path}: time columns {times or 'none (not a time series)'}")
    return 0


def time_check():
    """the rule on headers whose verdicts are known (a column that only starts with t is not a time)"""
    cases = [("t,front_m", False), ("time,x", False), ("x,y,T", True), ("t_sim,x", False), ("t_s,front_m", True),
             ("oven_degC,leavener,t_s,height_m,t_real_s", True), ("t_real_min,centre_T_degC", True),
             ("tau_y_Pa,top_m,torn,thickness_m", True), ("bake_end_s,cut_s,end_s", True)]
    bad = 0
    for head, ok in cases:
        got = time_column_fault(head.split(",")) is None
        print(f"{head!r}: {'kept' if got else 'refused'} ({'as known' if got == ok else 'WRONG'})")
        bad += got != ok
    return 1 if bad else 0


def check_cells(path, scene):
    rows = list(csv.reader(open(path, encoding="utf-8")))
    if check_time(path):
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
    if sys.argv[1] == "--time":
        sys.exit(max([check_time(p) for p in sys.argv[2:]] or [0]))
    sys.exit(check_cells(sys.argv[1], sys.argv[2]))
