#!/usr/bin/env python3
"""mpi_compare.py A.csv B.csv TOL: particle states (id, then columns) written
by two runs of tests/mpi/*.lua. Rows are matched by id. For each column the
difference is relative to that column's largest magnitude (a component near
zero would otherwise divide by nothing). Prints the largest relative
difference and the column; exits 1 when it exceeds TOL or the ids differ."""
import sys


def load(path):
    rows = {}
    with open(path) as f:
        for line in f:
            line = line.strip()
            if line:
                p = line.split(",")
                rows[int(p[0])] = [float(v) for v in p[1:]]
    return rows


def main():
    a, b, tol = load(sys.argv[1]), load(sys.argv[2]), float(sys.argv[3])
    if set(a) != set(b) or not a:
        print(f"particle ids differ: {len(a)} against {len(b)} particles, {len(set(a) ^ set(b))} ids in one only")
        return 1
    ncol = len(next(iter(a.values())))
    worst, wcol = 0.0, -1
    for c in range(ncol):
        scale = max(max(abs(r[c]) for r in a.values()), max(abs(r[c]) for r in b.values()))
        if scale == 0:
            continue
        d = max(abs(a[i][c] - b[i][c]) for i in a) / scale
        if d > worst:
            worst, wcol = d, c
    print(f"largest relative difference {worst:.3e} (column {wcol + 1}) over {len(a)} particles; tolerance {tol:g}")
    return 0 if worst <= tol else 1


if __name__ == "__main__":
    sys.exit(main())
