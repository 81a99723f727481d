#!/usr/bin/env python3
"""lava_cake_claims_check.py CASE: tests/baking/lava_cake_check.py (the lava cake's claims, #18) on lava_cake.csv
and lava_cake_times.csv files written by hand, each claim just inside and just outside each of its limits, so a
measure that stopped reading a column, a time or a limit would fail here.
  stands  bake 12 s, cut 12.4 s, end 13 s, dx 4 mm: the uncut edge moved 7.9 mm and the height at the cut 75.1%
          of the bake's end holds; 8.0 mm, or 74.9%, fails; the height is the cut frame's, not its neighbours';
          a failure with a cause exits 77 and prints it
  flows   the reach right of the centre grown by 8.1 mm from the cut's frame to the last, three frames from the
          cut on: holds; 7.9 mm, or only two frames from the cut on, fails
Exit 0 pass, 1 fail (prints which case gave what)."""
import os
import shutil
import subprocess
import sys
import tempfile

CHECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "lava_cake_check.py")
COLS = "t_s,centre_temperature_degC,height_m,reach_right_m,reach_left_m"


def outputs(rows, times=(12.0, 12.4, 13.0)):
    """a folder holding lava_cake.csv (rows: (t, height, reach_right, reach_left)) and lava_cake_times.csv"""
    d = tempfile.mkdtemp()
    with open(os.path.join(d, "lava_cake.csv"), "w") as f:
        f.write(COLS + "\n")
        for t, hgt, right, left in rows:
            f.write(f"{t:.3f},40.00,{hgt:.5f},{right:.5f},{left:.5f}\n")
    with open(os.path.join(d, "lava_cake_times.csv"), "w") as f:
        f.write("bake_end_s,cut_s,end_s\n%.6f,%.6f,%.6f\n" % times)
    return d


def verdict(mode, rows, cause=None, times=(12.0, 12.4, 13.0)):
    d = outputs(rows, times)
    r = subprocess.run([sys.executable, CHECK, mode, d, "0.004"] + ([cause] if cause else []), capture_output=True,
                       text=True)
    shutil.rmtree(d)
    return r.returncode, r.stdout


def standing(moved, kept, others=None):
    """frames every 0.2 s from 11.8 s: height 40 mm at the bake's end (12 s), kept x that at the cut (12.4 s) and
    others x 40 mm (default: kept's) at every other frame; the left edge 30 mm out until the cut and 30 mm + moved at
    the end"""
    h0 = 0.040
    o = (kept if others is None else others) * h0
    return [(11.8, o, 0.03, 0.03), (12.0, h0, 0.03, 0.03), (12.2, o, 0.03, 0.03),
            (12.4, kept * h0, 0.008, 0.03), (12.6, o, 0.02, 0.03 + moved / 2),
            (12.8, o, 0.03, 0.03 + moved), (13.0, o, 0.03, 0.03 + moved)]


def flowing(grown, from_cut=(12.4, 12.6, 13.0)):
    rows = [(12.0, 0.04, 0.03, 0.03), (12.2, 0.04, 0.03, 0.03)]
    for k, t in enumerate(from_cut):  # 8 mm at the cut's frame, grown at the last, half of it between
        rows.append((t, 0.035, 0.008 + grown * (0 if k == 0 else 1 if k == len(from_cut) - 1 else 0.5), 0.03))
    return rows


def main():
    case = sys.argv[1]
    checks = []  # (what, got rc, wanted rc, printed)
    if case == "stands":
        for what, rows, want in (("moved 7.9 mm, kept 75.1%", standing(0.0079, 0.751), 0),
                                 ("moved 8.0 mm", standing(0.0080, 0.9), 1),
                                 ("kept 74.9%", standing(0.0, 0.749), 1),
                                 ("kept 74.9% at the cut, 100% at the other frames", standing(0.0, 0.749, 1.0), 1),
                                 ("kept 90% at the cut, 50% at the other frames", standing(0.0, 0.9, 0.5), 0)):
            rc, out = verdict("stands", rows)
            checks.append((what, rc, want, out))
        rc, out = verdict("stands", standing(0.0, 0.5), "a cause")
        checks.append(("kept 50% with a cause", rc if "EXPECTED FAILURE: a cause" in out else -1, 77, out))
    elif case == "flows":
        for what, rows, want in (("grown 8.1 mm", flowing(0.0081), 0), ("grown 7.9 mm", flowing(0.0079), 1),
                                 ("grown 20 mm over two frames", flowing(0.02, (12.4, 13.0)), 1)):
            rc, out = verdict("flows", rows)
            checks.append((what, rc, want, out))
    else:
        print(f"unknown case {case}")
        return 1
    bad = 0
    for what, rc, want, out in checks:
        print(f"{case}: {what}: exit {rc} (wanted {want}): {out.strip()}")
        bad += rc != want
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
