#!/usr/bin/env python3
"""sph_cake_rise.py DX A_W BAKED.csv END.csv: the SPH angel food cake
(scripts/scenes/sph/angel_food_cake.lua) measured from its particles alone
(its particles_*.csv: x, y in m, T in degC, J = det F, browning; a bubble
particle carries no browning, NaN).

Pieces: each side of the pan's tube (x below and above the pan's axis,
x = 0.1 m) is one piece of batter when every particle on it is linked to the
rest at two raw spacings, as tests/sph_roll_measure.py links the roll's
(union-find over pairs closer than 2 DX): a bubble at the gas law's cap
(V_b = 4) moves its neighbours out by about sqrt(4) DX, and a torn cake, or
a particle thrown onto the tube's top, leaves a gap with none within two.

Bubbles against their gas (#18: eq. 3.51 once pushed a bubble to 1.44x its
gas's volume, docs/validation.md "The bread of the dead stays in one
piece"): each bubble particle's own volume J against the volume its gas
has at its temperature, written here from the thesis and not read from the
solver: eq. 3.50 in Kelvin with the water vapour of eq. 2.42-2.43 (Fan et
al.'s bubble: P_v = a_w P_sat(T), Clausius-Clapeyron through 101325 Pa at
100 degC with Delta H_v = 40.66 kJ/mol) at the oven's 101325 Pa,
  V_b = (T / T0) (P_a - P_v(T0)) / (P_a - P_v(T)),  T0 = 26 degC,
capped at sph.bubble_vmax's 4 (the cells open and vent). A_W = 0 is the dry
gas, T / T0. Only the bake's end is judged: a cooling bubble's gas
contracts while the set crumb may hold it open, which is no runaway.

Prints 'pieces_left L pieces_right R off_batter B off_bubbles G
worst_bubble_over_gas W at_T T' for BAKED.csv (B and G: the batter and the
bubble particles outside their side's largest piece), then the pieces' part
of that line for END.csv."""
import csv, math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sph_roll_measure import piece_labels  # noqa: E402

AXIS = 0.1  # the pan's mirror axis (the scene's cx), m
P_A, T0, VMAX = 101325.0, 26.0, 4.0
KELVIN, R_GAS, DH_V = 273.15, 8.314462618, 40660.0


def p_sat(T):
    """Water's saturated vapour pressure (Pa) at T degC (eq. 2.43)."""
    return 101325.0 * math.exp(-(DH_V / R_GAS) * (1 / (T + KELVIN) - 1 / (100 + KELVIN)))


def gas_volume(T, a_w):
    """V_b / V_b0 of a bubble's air and steam at T degC (eq. 2.42-2.43, 3.50 in Kelvin), capped at VMAX."""
    V = (T + KELVIN) / (T0 + KELVIN)
    if a_w > 0:
        pv0, pv = a_w * p_sat(T0), a_w * p_sat(T)
        V = V * (P_A - pv0) / (P_A - pv) if pv < P_A else math.inf
    return min(V, VMAX)


def load(path):
    with open(path) as f:
        return [(float(r["x"]), float(r["y"]), float(r["T"]), float(r["J"]), float(r["browning"]))
                for r in csv.DictReader(f)]


def side(rows, dx):
    """One side's pieces, and its batter and bubble particles outside its largest piece."""
    labels = piece_labels([(r[0], r[1]) for r in rows], 2 * dx)
    sizes = {}
    for l in labels:
        sizes[l] = sizes.get(l, 0) + 1
    main = max(sizes, key=sizes.get)
    off = [r for r, l in zip(rows, labels) if l != main]
    bubbles = sum(1 for r in off if math.isnan(r[4]))
    return len(sizes), len(off) - bubbles, bubbles


def sides(rows, dx):
    """'pieces_left L pieces_right R off_batter B off_bubbles G': B, G summed over both sides."""
    l = side([r for r in rows if r[0] < AXIS], dx)
    r = side([r for r in rows if r[0] >= AXIS], dx)
    return "pieces_left %d pieces_right %d off_batter %d off_bubbles %d" % (l[0], r[0], l[1] + r[1], l[2] + r[2])


def worst_bubble(rows, a_w):
    """The largest J / V_b(T) over the bubble particles, and that bubble's T."""
    worst, at = 0.0, math.nan
    for x, y, T, J, b in rows:
        if math.isnan(b):
            q = J / gas_volume(T, a_w)
            if q > worst:
                worst, at = q, T
    return worst, at


def main():
    if len(sys.argv) != 5:
        sys.exit(__doc__)
    dx, a_w = float(sys.argv[1]), float(sys.argv[2])
    baked, end = load(sys.argv[3]), load(sys.argv[4])
    if not baked or not end:
        sys.exit("sph_cake_rise: no particles in %s or %s" % (sys.argv[3], sys.argv[4]))
    w, T = worst_bubble(baked, a_w)
    print("%s worst_bubble_over_gas %.4f at_T %.1f" % (sides(baked, dx), w, T))
    print(sides(end, dx))


if __name__ == "__main__":
    main()
