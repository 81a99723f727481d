#!/usr/bin/env python3
"""pancake_landed_measure.py DX LANDED.csv [--bar]: the pancake after its flip, measured from its particles
(pancake.lua's landed.csv: x, y, J columns, metres), not through the solver's fields.
pancake_landed_measure.py DX --through OUT [--bar]: the same pieces in every frame of a run with --set particles=1
(OUT/particles_*.csv) from the flip (OUT/flip.csv) on, and each frame's length along the piece's long axis.

Pieces: particles closer than 1.5 DX are linked (union-find, tests/sph_roll_measure.py's piece_labels). At rest
the scene's particles (4 a cell in 2D) stand DX / 2 apart; a link of 1.5 DX bridges a stretched sheet's thinned
rows, not a torn gap.

Holes: over the middle 80% of the largest piece's x-extent (its rounded ends left out), the piece's thickness in
columns DX / 2 wide, each column's particle areas (J (DX/2)^2 in 2D) over its width; a hole is a run of columns
whose thickness is under a quarter of the median column's. Its width is the run's.

Prints the particle count, the pieces, the largest's share, where it lies (its mean x, its lowest particle above the
pan), its thickness (median, min, max, coefficient of variation over the middle 80%) and the widest hole in DX; with
--bar exits 1 unless (the bar set at 07:47 UTC on helper pancakeflip's day, before its first run): (1) the largest
piece holds at least 95% of the particles, (2) it lies right of the pivot (mean x > 0.165 m) with its lowest
particle within DX of the pan (y 0.01 m), and (3) no hole is wider than 2 DX."""
import csv, glob, math, os, statistics, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sph_roll_measure import piece_labels, piece_sizes  # noqa: E402


PAN, XP = 0.01, 0.165  # m: the pan's top and the spatula's pivot x (scripts/scenes/baking/pancake.lua)


def through(dx, out, bar):
    """Every frame from the flip on: its pieces at 1.5 dx links, the largest's share and its length along its long
    axis (the principal axis of its particles). The bar (set at 07:56 UTC on helper pancakeflip's day, after the
    2 mm runs of the old turn and of the smooth turn, before any other run of the smooth turn): in every frame from
    the flip to the end the largest piece holds at least 95% of the particles (it is not torn apart mid-air and
    joined again where its pieces land)."""
    if not os.path.exists(os.path.join(out, "flip.csv")):
        sys.exit("pancake_landed_measure: %s has no flip.csv: the pancake was not flipped" % out)
    flip_t = float(list(csv.DictReader(open(os.path.join(out, "flip.csv"))))[0]["flip_time_s"])
    worst, before, last = 1.0, None, None
    for path in sorted(glob.glob(os.path.join(out, "particles_*.csv"))):
        rows = list(csv.DictReader(open(path)))
        if not rows:
            continue
        t = float(rows[0]["t_s"])
        pts = [(float(r["x_m"]), float(r["y_m"])) for r in rows]
        labels = piece_labels(pts, 1.5 * dx)
        sizes, big = piece_sizes(labels)
        mine = [pts[i] for i in range(len(pts)) if labels[i] == big]
        mx, my = sum(p[0] for p in mine) / len(mine), sum(p[1] for p in mine) / len(mine)
        sxx = sum((p[0] - mx) ** 2 for p in mine)
        syy = sum((p[1] - my) ** 2 for p in mine)
        sxy = sum((p[0] - mx) * (p[1] - my) for p in mine)
        th = 0.5 * math.atan2(2 * sxy, sxx - syy)
        along = [(p[0] - mx) * math.cos(th) + (p[1] - my) * math.sin(th) for p in mine]
        length = max(along) - min(along)
        share = sizes[big] / len(pts)
        if t < flip_t:
            before = length
            continue
        last = length
        worst = min(worst, share)
        print(f"  t {t:.3f} s: {len(sizes)} pieces, the largest {share:.4f} of the particles, {length * 1e3:.1f} mm long")
    if before is None or last is None:
        sys.exit("pancake_landed_measure: no frame before and after the flip at %.3f s in %s" % (flip_t, out))
    print(f"dx {dx * 1e3:g} mm: flip at {flip_t:.3f} s; from then on the largest piece holds at least {worst:.4f} of "
          f"the particles (need >= 0.95); its length {before * 1e3:.1f} mm before the flip, {last * 1e3:.1f} mm at "
          f"the end ({last / before:.2f}x)")
    if bar:
        sys.exit(0 if worst >= 0.95 else 1)


def main():
    args = sys.argv[1:]
    bar = "--bar" in args
    args = [a for a in args if a != "--bar"]
    if len(args) == 3 and args[1] == "--through":
        through(float(args[0]), args[2], bar)
        return
    if len(args) != 2:
        sys.exit(__doc__)
    dx = float(args[0])
    rows = list(csv.DictReader(open(args[1])))
    if not rows:
        sys.exit("pancake_landed_measure: %s has no particles" % args[1])
    pts = [(float(r["x_m"]), float(r["y_m"])) for r in rows]
    J = [float(r["J"]) for r in rows]
    labels = piece_labels(pts, 1.5 * dx)
    sizes, big = piece_sizes(labels)
    share = sizes[big] / len(pts)
    mine = [i for i in range(len(pts)) if labels[i] == big]
    mean_x = sum(pts[i][0] for i in mine) / len(mine)
    low = min(pts[i][1] for i in mine) - PAN
    x0, x1 = min(pts[i][0] for i in mine), max(pts[i][0] for i in mine)
    w = dx / 2
    ncol = int((x1 - x0) / w) + 1
    thick = [0.0] * ncol
    for i in mine:
        thick[min(ncol - 1, int((pts[i][0] - x0) / w))] += J[i] * (dx / 2) ** 2 / w
    a, b = int(0.1 * ncol), ncol - int(0.1 * ncol)
    mid = thick[a:b] or thick
    med = statistics.median(mid)
    run = widest = 0
    for t in mid:
        run = run + 1 if t < med / 4 else 0
        widest = max(widest, run)
    hole = widest * w / dx
    cv = statistics.pstdev(mid) / statistics.mean(mid) if statistics.mean(mid) > 0 else float("nan")
    small = sorted(sizes.values(), reverse=True)[1:6]
    print(f"dx {dx * 1e3:g} mm: {len(pts)} particles in {len(sizes)} pieces at 1.5 dx links (largest {share:.4f} of "
          f"them; next {small}); the largest from x {x0:.4f} to {x1:.4f} m, mean x {mean_x:.4f} m (pivot {XP}), "
          f"lowest particle {low * 1e3:.2f} mm above the pan; thickness over its middle 80%: median "
          f"{med * 1e3:.2f} mm, min {min(mid) * 1e3:.2f}, max {max(mid) * 1e3:.2f}, cv {cv:.3f}; widest hole "
          f"{hole:.1f} dx")
    if bar:
        ok = [share >= 0.95, mean_x > XP and low <= dx, hole <= 2]
        print(f"bar: largest piece >= 0.95 of the particles: {ok[0]}; landed right of the pivot on the pan: {ok[1]}; "
              f"no hole wider than 2 dx: {ok[2]}")
        sys.exit(0 if all(ok) else 1)


if __name__ == "__main__":
    main()
