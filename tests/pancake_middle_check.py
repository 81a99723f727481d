#!/usr/bin/env python3
"""pancake_middle_check.py CASE: tests/pancake_middle_measure.py (what lies under the physical pancake's middle, and
the 1D slab it is compared with) on cases whose answer is known without it. The column cases are landed.csv files
written by hand at DX 2 mm: a sheet of rows DX / 2 apart, two particles a row on the centre line (x = XC -+ DX / 4,
as a lattice of 4 a cell), each row at 80 degC.
  gap       a stray particle on the pan at 0.5 mm (x = XC) and the sheet's rows from 3.0 to 9.0 mm: a gap of 2.5 mm
            (1.25 DX), the base at 3.0 mm with one particle under it, the sheet 7.0 mm thick (rows 3.0..9.0 plus a
            half-extent DX / 4 at each face), its own middle at 6.0 mm; a stray on the pan 1.2 mm right of the line
            (off it) is not counted
  contact   the sheet's rows from 0.5 to 8.5 mm: no gap wider than DX, the base at 0.5 mm, nothing under it,
            9.0 mm thick; rows from 0.5 to 6.5 mm and a lone particle at 9.5 mm (a gap above the line's
            midpoint is not what the sheet rests on): no gap, the base at 0.5 mm
  series    the slab without boiling, its lower face held at 190 degC (a coefficient of 1e12), its upper face
            insulated, 8 mm of the preset's wet batter from 20 degC: its middle within 0.5 degC of Carslaw & Jaeger's
            series at 30, 60 and 210 s (the bar set before the first run)
Exit 0 pass, 1 fail (prints the numbers)."""
import os, sys, tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import pancake_middle_measure as m  # noqa: E402

DX = 0.002


def landed(heights, extra=()):
    """a landed.csv holding two particles a row at the given heights (m above the pan) and the extra (x, y) points"""
    f = tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False)
    f.write("t_s,id,x_m,y_m,z_m,J,temperature_degC\n")
    k = 0
    pts = [(m.XC + s * DX / 4, m.PAN + hgt) for hgt in heights for s in (-1, 1)] + list(extra)
    for x, y in pts:
        f.write(f"3.5000,{k},{x:.6f},{y:.6f},0.000000,1.00000,80.00\n")
        k += 1
    f.close()
    return f.name


def near(a, b, tol=1e-9):
    return abs(a - b) <= tol


def main():
    case = sys.argv[1]
    rows = [0.003 + 0.001 * i for i in range(7)]
    if case == "gap":
        path = landed(rows, [(m.XC, m.PAN + 0.0005), (m.XC + 0.0012, m.PAN + 0.0005)])
        c = m.centre_column(m.read_landed(path), DX)
        os.unlink(path)
        ok = [near(c["gap"], 0.0025), near(c["heights"][c["base"]], 0.003), c["under"] == 1,
              near(c["thickness"], 0.007), near(c["sheet_middle_y"], 0.006)]
        print(f"gap: {c['gap'] * 1e3:.3f} mm, base {c['heights'][c['base']] * 1e3:.3f} mm, under {c['under']}, "
              f"thickness {c['thickness'] * 1e3:.3f} mm, its middle at {c['sheet_middle_y'] * 1e3:.3f} mm (need 2.5, "
              f"3.0, 1, 7.0, 6.0)")
    elif case == "contact":
        path = landed([0.0005 + 0.001 * i for i in range(9)])
        c = m.centre_column(m.read_landed(path), DX)
        os.unlink(path)
        ok = [c["gap"] == 0.0, near(c["heights"][c["base"]], 0.0005), c["under"] == 0, near(c["thickness"], 0.009)]
        path = landed([0.0005 + 0.001 * i for i in range(7)], [(m.XC, m.PAN + 0.0095)])
        d = m.centre_column(m.read_landed(path), DX)
        os.unlink(path)
        ok += [d["gap"] == 0.0, near(d["heights"][d["base"]], 0.0005), d["under"] == 0]
        print(f"contact: gap {c['gap'] * 1e3:.3f} mm, base {c['heights'][c['base']] * 1e3:.3f} mm, under "
              f"{c['under']}, thickness {c['thickness'] * 1e3:.3f} mm (need 0, 0.5, 0, 9.0); with a lone particle 3 mm "
              f"above the top row: gap {d['gap'] * 1e3:.3f} mm, base {d['heights'][d['base']] * 1e3:.3f} mm, under "
              f"{d['under']} (need 0, 0.5, 0)")
    elif case == "series":
        p = dict(m.PRESET, hpan=1e12, hair=0.0)
        L, alpha = 0.008, p["k"] / (p["rho"] * p["c"])
        got = m.slab(L, first=1e9, landed=1e9, end=210.0, p=p, boil=False, times=(30.0, 60.0))
        ok = []
        for t in (30.0, 60.0, 210.0):
            want = m.series_middle(L, t, alpha, p["T0"], p["Tpan"])
            ok.append(abs(got[t] - want) <= 0.5)
            print(f"series: t {t:.0f} s: slab middle {got[t]:.3f} degC, series {want:.3f} (need within 0.5)")
    else:
        sys.exit(__doc__)
    sys.exit(0 if all(ok) else 1)


if __name__ == "__main__":
    main()
