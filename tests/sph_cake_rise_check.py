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
  runaway two bubbles at 100 degC, one at J 1.2 (under its dry gas's 1.2474),
          one at J 1.6: the worst J / V_b is 1.6 / 1.2474 = 1.283 with a_w 0
Exit 0 pass, 1 fail (prints the numbers)."""
import math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sph_cake_rise as cake  # noqa: E402

DX = 0.003
NAN = float("nan")


def block(x0, bubbles=()):
    """Rows (x, y, T, J, browning) of a 10 x 12 block from x0; bubbles: (i, j) that are bubble particles."""
    return [(x0 + i * DX, 0.0115 + j * DX, 100.0, 1.0, NAN if (i, j) in bubbles else 0.1)
            for j in range(12) for i in range(10)]


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
