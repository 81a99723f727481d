#!/usr/bin/env python3
"""bread_claims_check.py CASE: tests/bread_claims.py (bread.lua's claims, #18) on bread.csv
files written by hand, each claim just inside and just outside each of its limits, so a
check that stopped reading a column or a limit would fail here.
  rises        the plain loaf: area +20 % peak / +12 % end, taller: holds; +14 % peak,
               +9 % end, or lower than the raw dough: fails
  scored       the one-slit loaf rising as above: its slit open past one cell and wider
               than at the start holds; narrower than a cell or than at the start fails
  dries        the top drier than the centre at every frame, lost > 5x the centre's
               share, below X/X0 0.5, the centre >= 0.85: holds; each broken: fails
  cracks       a notch a tenth of the height deep and two cells wide: holds (0); a
               hair shallower or one cell wide: the expected failure (77)
  slit_widens  the lowest height before the end, height and gap grown since: holds;
               the lowest at the end, or the gap not grown: fails
Exit 0 pass, 1 fail (prints which file gave what)."""
import contextlib, io, os, sys, tempfile

sys.dont_write_bytecode = True  # no __pycache__ in the source tree the tests run from
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bread_claims  # noqa: E402

COLS = ("t_s,height_plain_m,height_one_slit_m,height_two_slits_m,gap_one_slit_m,gap_two_slits_left_m,"
        "gap_two_slits_right_m,area_plain_m2,area_one_slit_m2,area_two_slits_m2,crack_depth_m,crack_width_m,moisture_top,"
        "moisture_centre,cracked,top_arc_m").split(",")


def csv_of(rows):
    """a bread.csv whose frames are the dicts in rows (unnamed columns 0)"""
    f = tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False)
    f.write(",".join(COLS) + "\n")
    for k, r in enumerate(rows):
        f.write(",".join(str(r.get(c, k * 0.5 if c == "t_s" else 0)) for c in COLS) + "\n")
    f.close()
    return f.name


def expect(label, want, fn, *args):
    path = args[0]
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        got = fn(*args)
    os.unlink(path)
    lines = [ln for ln in out.getvalue().splitlines() if not ln.startswith("EXPECTED FAILURE")]
    print(f"{label}: exit {got} (want {want}): {lines[-1] if lines else ''}")
    return got == want


def loaf(col, areas, heights, gaps=None):
    rows = [{"area_" + col + "_m2": a, "height_" + col + "_m": h} for a, h in zip(areas, heights)]
    for r, g in zip(rows, gaps or []):
        r["gap_one_slit_m"] = g
    return csv_of(rows)


def main(case):
    ok = True
    if case == "rises":
        A, H = [0.005, 0.006, 0.0056], [0.070, 0.066, 0.071]  # +20 % peak, +12 % end, taller
        ok &= expect("rises", 0, bread_claims.rises, loaf("plain", A, H), 0.005, "plain")
        ok &= expect("peak +14 %", 1, bread_claims.rises, loaf("plain", [0.005, 0.0057, 0.0056], H), 0.005, "plain")
        ok &= expect("end +9 %", 1, bread_claims.rises, loaf("plain", [0.005, 0.006, 0.00545], H), 0.005, "plain")
        ok &= expect("lower than raw", 1, bread_claims.rises, loaf("plain", A, [0.070, 0.066, 0.0699]), 0.005, "plain")
    elif case == "scored":
        A, H = [0.005, 0.006, 0.0056], [0.066, 0.062, 0.068]
        ok &= expect("slit open", 0, bread_claims.rises, loaf("one_slit", A, H, [0.006, 0.005, 0.012]), 0.005, "one_slit")
        ok &= expect("slit under a cell", 1, bread_claims.rises, loaf("one_slit", A, H, [0.004, 0.003, 0.0049]), 0.005,
                     "one_slit")
        ok &= expect("slit narrower than at the start", 1, bread_claims.rises,
                     loaf("one_slit", A, H, [0.012, 0.011, 0.010]), 0.005, "one_slit")
    elif case == "dries":
        top, ctr = [1.0, 0.6, 0.5, 0.45, 0.40], [1.0, 0.99, 0.98, 0.96, 0.95]

        def water(t, c):
            return csv_of([{"moisture_top": a, "moisture_centre": b} for a, b in zip(t, c)])
        ok &= expect("dries first", 0, bread_claims.dries, water(top, ctr), 0.005)
        ok &= expect("top wetter at one frame", 1, bread_claims.dries, water([1.0, 0.995, 0.5, 0.45, 0.40], ctr), 0.005)
        ok &= expect("top at X/X0 0.5", 1, bread_claims.dries, water(top[:-1] + [0.5], ctr[:-1] + [0.95]), 0.005)
        ok &= expect("centre at 0.84", 1, bread_claims.dries, water([1.0, 0.6, 0.5, 0.45, 0.10], ctr[:-1] + [0.84]), 0.005)
        ok &= expect("top lost under 5x the centre", 1, bread_claims.dries, water(top[:-1] + [0.49], ctr[:-1] + [0.89]), 0.005)
        ok &= expect("three frames", 1, bread_claims.dries, water(top[:3], ctr[:3]), 0.005)
    elif case == "cracks":
        def notch(d, w):
            return csv_of([{"height_plain_m": 0.075}, {"height_plain_m": 0.075, "crack_depth_m": d, "crack_width_m": w}])
        ok &= expect("crack", 0, bread_claims.cracks, notch(0.0075, 0.008), 0.004)
        ok &= expect("shallower than a tenth", 77, bread_claims.cracks, notch(0.00749, 0.008), 0.004)
        ok &= expect("one cell wide", 77, bread_claims.cracks, notch(0.0150, 0.004), 0.004)
    elif case == "slit_widens":
        def slit(h, g):
            return csv_of([{"height_one_slit_m": a, "gap_one_slit_m": b} for a, b in zip(h, g)])
        ok &= expect("widens", 0, bread_claims.slit_widens, slit([0.066, 0.060, 0.062, 0.070], [0.007, 0.006, 0.008, 0.015]))
        ok &= expect("lowest at the end", 1, bread_claims.slit_widens,
                     slit([0.066, 0.064, 0.062, 0.060], [0.007, 0.006, 0.008, 0.015]))
        ok &= expect("gap not grown", 1, bread_claims.slit_widens,
                     slit([0.066, 0.060, 0.062, 0.070], [0.007, 0.006, 0.008, 0.006]))
    else:
        sys.exit(__doc__)
    return 0 if ok else 1


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1]))
