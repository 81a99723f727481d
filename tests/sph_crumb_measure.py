#!/usr/bin/env python3
"""sph_crumb_measure.py RC FRAME.csv...: an SPH loaf's centre against its outer
surface, from its particles alone (a particles_*.csv of
scripts/scenes/sph/bread_of_the_dead.lua: x_m, y_m, T_degC, outer (1 where
the oven's heat enters, sph_outer.c), browning and saturation; a bubble
particle is gas and carries neither: empty cells, read as NaN here; a `nan`
cell, which the scene wrote before helper userfix10, is refused).

The centre: the particles within RC (m) of the particles' centroid; the
outer surface: the particles flagged outer. For each, the mean temperature
over all its particles, and the mean browning and saturation over its dough
particles (those with a browning). Prints one line a file:
'FILE centre_T T centre_browning B centre_saturation S outer_browning BO
outer_saturation SO outer_T TO centre_n N dough_n D' (#18, helper sphcrumb:
claim_sph_bread_of_the_dead_crumb_pale, tests/sph_dead_test.sh; outer_T, the
outer surface's mean temperature, helper deadcrust's
claim_sph_bread_of_the_dead_crust_browns)."""
import csv, math, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import csv_cell  # noqa: E402


def nanmean(v):
    v = [x for x in v if not math.isnan(x)]
    return sum(v) / len(v) if v else float("nan")


def measure(path, rc):
    with open(path) as f:
        rows = [{k: csv_cell.cell(v) for k, v in r.items()} for r in csv.DictReader(f)]
    n = len(rows)
    cx, cy = sum(r["x_m"] for r in rows) / n, sum(r["y_m"] for r in rows) / n
    centre = [r for r in rows if math.hypot(r["x_m"] - cx, r["y_m"] - cy) < rc]
    outer = [r for r in rows if r["outer"] > 0]
    dough = lambda part: [r for r in part if not math.isnan(r["browning"])]
    return {"centre_T": nanmean([r["T_degC"] for r in centre]),
            "centre_browning": nanmean([r["browning"] for r in dough(centre)]),
            "centre_saturation": nanmean([r["saturation"] for r in dough(centre)]),
            "outer_browning": nanmean([r["browning"] for r in dough(outer)]),
            "outer_saturation": nanmean([r["saturation"] for r in dough(outer)]),
            "outer_T": nanmean([r["T_degC"] for r in outer]),
            "centre_n": len(centre), "dough_n": len(dough(centre))}


def crumb_bars(dx, part, at, s_raw, wet, end, bo):
    """The four bars of the SPH crumb claims (claim_sph_angel_cake_crumb_pale, tests/sph_cake_test.sh;
    claim_sph_bread_of_the_dead_crumb_pale, tests/sph_dead_test.sh), set by helper sphcrumb before the cake's
    first run with water: (a) the crumb's browning below 0.1 at the end; (b) at most 103 degC while it holds half
    its raw water; (c) it keeps half its water; (d) the outer surface browns at least twice the crumb, and 0.01 more.
    part names the crumb ("the crumb band", "the centre"), at the end's time; s_raw its raw saturation; wet the
    (when, T) of each frame where it held half its water; end its (browning, saturation) at the end; bo the outer
    surface's browning there. Prints each bar; returns whether all hold."""
    bc, s_end = end
    hot = max(wet, key=lambda w: w[1]) if wet else None
    checks = [
        ("a", bc < 0.1, f"{part}'s browning {bc:.4f} {at} (bar < 0.1)"),
        ("b", bool(wet) and hot[1] <= 103,
         (f"{part} at most {hot[1]:.2f} degC ({hot[0]}) over the {len(wet)} frames where it held half its water "
          "(bar 103)") if wet else f"{part} never held half its water"),
        ("c", s_end >= 0.5 * s_raw,
         f"{part}'s saturation {s_end:.4f} {at}, {s_end / s_raw:.3f} of its raw {s_raw:.4f} (bar 0.5)"),
        ("d", bo >= max(2 * bc, bc + 0.01),
         f"the outer surface's browning {bo:.4f} against {part}'s {bc:.4f} (bar: at least twice, and 0.01 more)"),
    ]
    for k, ok, what in checks:
        print(f"dx {dx}: {'ok  ' if ok else 'FAIL'} ({k}) {what}")
    return all(ok for _, ok, _ in checks)


def main(argv):
    if len(argv) < 3:
        print(__doc__.strip().splitlines()[0]); return 2
    rc = float(argv[1])
    for path in argv[2:]:
        m = measure(path, rc)
        print(os.path.basename(path), " ".join(f"{k} {v:.6g}" for k, v in m.items()))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
