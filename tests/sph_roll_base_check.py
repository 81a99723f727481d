#!/usr/bin/env python3
"""sph_roll_base_check.py CASE: tests/sph_roll_base.py (how the SPH bread roll sits on its
tray, #18) on particle sets whose answer is known without it: a half-disc loaf of dough on
a square lattice of spacing DX, 40 DX wide and 20 DX tall, its bottom row on the tray
plane y = 0.01 (as the slip collider holds a resting particle).
  flat     as built: gap 0, mean 0, all 41 bottom-row particles in contact
  lifted   the particles above the middle third of the base, bottom to top, lifted by
           1.5 DX (a blister): gap 1.5 DX (to 1e-9), the ends still in contact
  jittered each particle moved by up to DX/4 up or down (a fixed pattern): gap at most DX/4
           above the lowest, so under DX
  hole     the bottom five rows of three middle columns taken out (a hole up from the tray,
           one column wider than the DX window either side can bridge): gap 5 DX
Exit 0 pass, 1 fail (prints the numbers)."""
import math, os, subprocess, sys, tempfile

DX, TRAY, W, H = 0.002, 0.01, 20, 20


def loaf(move=lambda i, j, y: y, drop=lambda i, j: False):
    pts = []
    for j in range(0, H + 1):
        for i in range(-W, W + 1):
            if (i / W) ** 2 + (j / H) ** 2 <= 1 and not drop(i, j):
                pts.append((0.08 + i * DX, move(i, j, TRAY + j * DX)))
    return pts


def run(pts):
    with tempfile.TemporaryDirectory() as d:
        path = os.path.join(d, "p.csv")
        with open(path, "w") as f:
            f.write("x_m,y_m\n" + "".join("%.9g,%.9g\n" % p for p in pts))
        here = os.path.dirname(os.path.abspath(__file__))
        out = subprocess.run([sys.executable, os.path.join(here, "sph_roll_base.py"), str(DX), str(TRAY), path],
                             capture_output=True, text=True, check=True).stdout.split()
    return {out[i]: float(out[i + 1]) for i in range(0, len(out), 2)}


def main(case):
    if case == "flat":
        m = run(loaf())
        ok = m["gap"] == 0 and m["mean"] == 0 and m["contact"] == 2 * W + 1
        want = f"gap 0, mean 0, contact {2 * W + 1}"
    elif case == "lifted":
        m = run(loaf(move=lambda i, j, y: y + 1.5 * DX if abs(i) <= W // 3 else y))
        ok = abs(m["gap"] - 1.5 * DX) < 1e-9 and m["contact"] > 0
        want = f"gap {1.5 * DX:g} (1.5 DX), some contact at the ends"
    elif case == "jittered":
        m = run(loaf(move=lambda i, j, y: y + 0.25 * DX * math.sin(12.9898 * i + 78.233 * j) ** 2))
        ok = m["gap"] <= 0.25 * DX + 1e-12
        want = f"gap <= {0.25 * DX:g} (DX/4)"
    elif case == "hole":
        m = run(loaf(drop=lambda i, j: abs(i) <= 1 and j < 5))
        ok = abs(m["gap"] - 5 * DX) < 1e-9
        want = f"gap {5 * DX:g} (5 DX)"
    else:
        sys.exit(f"unknown case {case}")
    print(f"{case}: {m} (want {want})")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main(sys.argv[1])
