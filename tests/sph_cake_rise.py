#!/usr/bin/env python3
"""sph_cake_rise.py DX A_W BAKED.csv END.csv: the SPH angel food cake
(scripts/scenes/sph/angel_food_cake.lua) measured from its particles alone
(its particles_*.csv: x_m, y_m, T_degC, J = det F, browning; a bubble
particle carries no browning: an empty cell, NaN in the rows here).

Pieces: each side of the pan's tube (x below and above the pan's axis,
x = 0.1 m) is one piece of batter when every particle on it is linked to the
rest, as tests/sph_roll_measure.py links the roll's (union-find over pairs):
two raw particles link closer than two raw spacings, 2 DX, which leaves a gap
of one DX between their own extents (DX wide each); a torn cake, or a
particle thrown onto the tube's top, leaves more. A bubble particle is its
gas (thesis §3.3.3: bubble particles are the batter's particles in every way
but their pressure, eq. 3.48-3.51, which sets their rest volume to the gas's
V_b), so its own extent is sqrt(V_b) DX wide and it reaches (sqrt(V_b) - 1)
DX / 2 further than a raw particle: the pair links closer than 2 DX plus both
reaches, the same one DX of gap between their extents (#18, helper
angelpieces: at a fixed 2 DX a bubble at the cap, V_b = 4, 2 DX across, in
the middle of the cavity its gas fills stood 2.0-2.3 DX from the batter
around it and counted as a piece apart). V_b is the bubble's gas volume at
its temperature (below); with cells that stay open (A_W > 0, as the scene
sets sph.bubble_stays_open = water_activity > 0) a bubble that had reached
the cap at the bake's end keeps it in END.csv (matched by the particles' id
column), as the solver's open cell keeps its volume.

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
from sph_roll_measure import piece_labels, piece_sizes  # noqa: E402
import csv_cell  # noqa: E402

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
    """Rows (x, y, T, J, browning, id); id -1 where the file has no id column; browning NaN for a bubble."""
    with open(path) as f:
        return [(float(r["x_m"]), float(r["y_m"]), float(r["T_degC"]), float(r["J"]),
                 csv_cell.cell(r["browning"], "browning"),
                 int(r.get("id") or -1)) for r in csv.DictReader(f)]


def rest_volume(row, a_w, opened=()):
    """A particle's rest volume over a raw one's: 1 for batter; a bubble's gas volume at its temperature, or the
    cap when its id is in opened (its cell reached the cap and stays open)."""
    if not math.isnan(row[4]):
        return 1.0
    return VMAX if len(row) > 5 and row[5] in opened else gas_volume(row[2], a_w)


def opened_ids(rows, a_w):
    """The ids of the bubbles at the cap in rows (the bake's end) whose cells stay open: none with the dry gas."""
    if a_w <= 0:
        return set()
    return {r[5] for r in rows if math.isnan(r[4]) and r[5] >= 0 and gas_volume(r[2], a_w) >= VMAX}


def side(rows, dx, a_w=0.0, opened=()):
    """One side's pieces, and its batter and bubble particles outside its largest piece."""
    reach = [(math.sqrt(rest_volume(r, a_w, opened)) - 1) * dx / 2 for r in rows]
    labels = piece_labels([(r[0], r[1]) for r in rows], 2 * dx, reach)
    sizes, main = piece_sizes(labels)
    off = [r for r, l in zip(rows, labels) if l != main]
    bubbles = sum(1 for r in off if math.isnan(r[4]))
    return len(sizes), len(off) - bubbles, bubbles


def sides(rows, dx, a_w=0.0, opened=()):
    """'pieces_left L pieces_right R off_batter B off_bubbles G': B, G summed over both sides."""
    l = side([r for r in rows if r[0] < AXIS], dx, a_w, opened)
    r = side([r for r in rows if r[0] >= AXIS], dx, a_w, opened)
    return "pieces_left %d pieces_right %d off_batter %d off_bubbles %d" % (l[0], r[0], l[1] + r[1], l[2] + r[2])


def worst_bubble(rows, a_w):
    """The largest J / V_b(T) over the bubble particles, and that bubble's T."""
    worst, at = 0.0, math.nan
    for x, y, T, J, b, *_ in rows:
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
    if a_w > 0 and any(r[5] < 0 for r in baked + end):
        sys.exit("sph_cake_rise: %s or %s has no id column: with A_W > 0 (open cells) the measure follows each "
                 "bubble from the bake's end by its id (the scene writes it since helper angelpieces)"
                 % (sys.argv[3], sys.argv[4]))
    w, T = worst_bubble(baked, a_w)
    print("%s worst_bubble_over_gas %.4f at_T %.1f" % (sides(baked, dx, a_w), w, T))
    print(sides(end, dx, a_w, opened_ids(baked, a_w)))


if __name__ == "__main__":
    main()
