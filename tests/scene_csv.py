"""scene_csv.py CSV SCENE.lua: a shipped scene's CSV as its readers take it (#18, helper userfix5).

Every cell is a finite number, or empty where nothing was measured. An empty cell is allowed only in a column the
scene's header declares may be one, on a line

    -- NAME.csv may leave empty (not measured): col, col,
    --   col, ...

(a list ending in a comma goes on at the next comment line). -1 or 0 standing in for "not measured" reads as a
value (pancake.csv's -1 degC while no batter lay on the pan's centre, helper userview3's item 3): an empty cell
cannot be taken for one. Exit 0 when the file keeps the rule, 1 naming the first cell that breaks it.
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


def check_cells(path, scene):
    rows = list(csv.reader(open(path, encoding="utf-8")))
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
    sys.exit(check_cells(sys.argv[1], sys.argv[2]))
