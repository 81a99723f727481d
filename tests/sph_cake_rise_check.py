#!/usr/bin/env python3
"""sph_cake_rise_check.py CASE: tests/sph_cake_rise.py (the SPH angel food
cake's pieces and bubbles against their gas, #18) on cases whose answer is
known without it.
  gas     its gas volume against numbers worked by hand from eq. 2.42-2.43 and
          3.50: dry air T / T0 in Kelvin, 373.15 / 299.15 = 1.2474 at 100
          degC (docs/validation.md's sph_gas_law_follows_temperature gives the
          same); with a_w = 0.95 at 80 degC: P_sat = 101325 exp(-(40660 /
          8.314462618)(1/353.15 - 1/373.15)) = 48.24 kPa, P_v 45.83 kPa, at 26
          degC P_sat 3.96 kPa, P_v 3.76 kPa: (353.15 / 299.15)(97.56 / 55.50)
          = 2.075 (the validation doc's "2.1 at 80 degC"); past the batter's
          boiling point (a_w P_sat > P_a) the cap, 4
  sides   two blocks of 10 x 12 particles on a lattice of spacing DX, one each
          side of the pan's axis: one piece each. Then on the left one a
          bubble clump of 3 particles (browning NaN) moved 3 DX off its side:
          2 pieces left, 1 right, 3 bubbles and no batter off the largest
          piece; a batter particle moved likewise counts as batter
  cavity  (#18, helper angelpieces; bars set before the scene was measured
          with them) a 15 x 15 block of batter (left of the axis) with the
          13 lattice sites within 2.05 DX of its centre site emptied (13
          DX^2) and a clump of 3 bubble particles at 170 degC, a_w 0.94 (the
          cap, V_b = 4 each: 12 DX^2 of gas), 0.1 DX about the centre: the
          nearest batter sites are sqrt(5) DX = 2.236 DX from the centre (at
          (2, 1) DX and its mirror images), and the clump's nearest pair is
          sqrt(1.9^2 + 1) = 2.147 DX apart: one piece (a bubble at
          the cap reaches (sqrt(4) - 1) DX / 2 = 0.5 DX further, links at
          2.5 DX); at a fixed 2 DX (the old measure) 2 pieces; the same clump
          at 26 degC (its raw volume) 2 pieces. Batter torn: two 5 x 12
          blocks 2.2 DX apart, 2 pieces; the same 3.2 DX apart with both
          torn faces bubble particles at the cap (they link at 3 DX), 2
          pieces. Cooled: the clump at 30 degC in END rows, its ids at the cap
          in the bake's rows: with a_w 0.94 (cells open) one piece, with the
          dry gas (cells closed, its gas at 30 degC) 2 pieces
  runaway two bubbles at 100 degC, one at J 1.2 (under its dry gas's 1.2474),
          one at J 1.6: the worst J / V_b is 1.6 / 1.2474 = 1.283 with a_w 0
Exit 0 pass, 1 fail (prints the numbers)."""
import math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sph_cake_rise as cake  # noqa: E402
from sph_roll_measure import piece_labels  # noqa: E402

DX = 0.003
NAN = float("nan")


def block(x0, bubbles=()):
    """Rows (x, y, T, J, browning) of a 10 x 12 block from x0; bubbles: (i, j) that are bubble particles."""
    return [(x0 + i * DX, 0.0115 + j * DX, 100.0, 1.0, NAN if (i, j) in bubbles else 0.1)
            for j in range(12) for i in range(10)]


def cavity(T_clump):
    """Rows (x, y, T, J, browning, id) of the cavity case: batter ids from 0, the clump's 1000-1002."""
    c = 7 * DX
    rows = [(0.03 + i * DX, 0.0115 + j * DX, 100.0, 1.0, 0.1, 15 * j + i) for j in range(15) for i in range(15)
            if (i * DX - c) ** 2 + (j * DX - c) ** 2 >= (2.05 * DX) ** 2]
    clump = [(0.1 * DX, 0.0), (-0.1 * DX, 0.0), (0.0, 0.1 * DX)]
    return rows + [(0.03 + c + a, 0.0115 + c + b, T_clump, 1.0, NAN, 1000 + k) for k, (a, b) in enumerate(clump)]


def torn(gap, faces_bubble):
    """Rows of two 5 x 12 blocks of batter, gap DX between their facing columns; faces_bubble: those columns are
    bubble particles at 170 degC."""
    rows = []
    for j in range(12):
        for i in range(10):
            x = 0.03 + i * DX + (gap - DX if i >= 5 else 0.0)
            face = i in (4, 5) and faces_bubble
            rows.append((x, 0.0115 + j * DX, 170.0 if face else 100.0, 1.0, NAN if face else 0.1, 12 * j + i))
    return rows


def main():
    case = sys.argv[1] if len(sys.argv) == 2 else ""
    if case == "gas":
        got = (cake.gas_volume(100, 0), cake.gas_volume(80, 0.95), cake.gas_volume(120, 0.95))
        want = (1.2474, 2.075, 4.0)
        print("V_b dry at 100 degC %.4f (hand 1.2474), a_w 0.95 at 80 degC %.4f (hand 2.075), at 120 degC %.4f "
              "(the cap 4)" % got)
        ok = all(abs(g - w) <= 2e-3 * w for g, w in zip(got, want))
    elif case == "sides":
        whole = block(0.03) + block(0.12)
        s1 = cake.sides(whole, DX)

        def moved(n, bubble):
            """The left block with the first n particles of its first column (k = 0, 10, 20..) 3 DX further left."""
            return [(x - 3 * DX, y, T, J, NAN if bubble else b) if k % 10 == 0 and k // 10 < n else (x, y, T, J, b)
                    for k, (x, y, T, J, b) in enumerate(block(0.03))]

        s2 = cake.sides(moved(3, True) + block(0.12), DX)
        s3 = cake.sides(moved(1, False) + block(0.12), DX)
        print("whole: %s\nbubble clump off: %s\nbatter particle off: %s" % (s1, s2, s3))
        ok = (s1 == "pieces_left 1 pieces_right 1 off_batter 0 off_bubbles 0"
              and s2 == "pieces_left 2 pieces_right 1 off_batter 0 off_bubbles 3"
              and s3 == "pieces_left 2 pieces_right 1 off_batter 1 off_bubbles 0")
    elif case == "cavity":
        hot, cold, cooled = cavity(170.0), cavity(26.0), cavity(30.0)
        clump = [r for r in hot if math.isnan(r[4])]
        near = min(math.hypot(a[0] - b[0], a[1] - b[1]) for a in clump for b in hot if not math.isnan(b[4])) / DX
        fixed = len(set(piece_labels([(r[0], r[1]) for r in hot], 2 * DX)))
        got = {
            "hot": cake.side(hot, DX, 0.94)[0],
            "cold": cake.side(cold, DX, 0.94)[0],
            "torn 2.2": cake.side(torn(2.2 * DX, False), DX, 0.94)[0],
            "torn 3.2, gas faces": cake.side(torn(3.2 * DX, True), DX, 0.94)[0],
            "cooled open": cake.side(cooled, DX, 0.94, cake.opened_ids(hot, 0.94))[0],
            "cooled closed": cake.side(cooled, DX, 0.0, cake.opened_ids(hot, 0.0))[0],
        }
        want = {"hot": 1, "cold": 2, "torn 2.2": 2, "torn 3.2, gas faces": 2, "cooled open": 1, "cooled closed": 2}
        print("the clump's nearest batter %.3f DX (hand 2.147); V_b at 170 degC, a_w 0.94: %.3f (the cap 4)"
              % (near, cake.gas_volume(170.0, 0.94)))
        print("pieces at a fixed 2 DX %d (hand 2); " % fixed
              + ", ".join("%s %d (hand %d)" % (k, got[k], want[k]) for k in want))
        ok = got == want and fixed == 2 and abs(near - math.sqrt(1.9 ** 2 + 1)) < 1e-9
    elif case == "runaway":
        rows = [(0.05, 0.02, 100.0, 1.2, NAN), (0.06, 0.02, 100.0, 1.6, NAN), (0.07, 0.02, 100.0, 3.0, 0.2)]
        w, T = cake.worst_bubble(rows, 0)
        print("worst bubble J / V_b %.4f at %.1f degC (hand 1.6 / 1.2474 = 1.2827; the batter's J 3 not counted)" % (w, T))
        ok = abs(w - 1.6 / (373.15 / 299.15)) < 1e-6 and T == 100.0
    else:
        sys.exit(__doc__)
    print("ok" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
