"""csv_cell.py: one CSV cell as a number, as the scenes write them (docs/outputs.md): an empty cell is "not
measured" and reads NaN; a `nan` written out is refused, since the rule is an empty cell (helper userfix10).
Shared by the test scripts that read the SPH particle files."""
import math


def cell(v, what="a cell"):
    if v == "":
        return math.nan
    x = float(v)
    if math.isnan(x):
        raise ValueError("%s reads %r: not measured is an empty cell (docs/outputs.md)" % (what, v))
    return x
