#!/usr/bin/env python3
"""vtk_pieces.py ONE_DIR MANY_DIR RANKS: the VTU series of tests/mpi/pieces.lua
from one process (ONE_DIR/block.pvd listing .vtu frames) and from RANKS MPI
ranks (MANY_DIR/block.pvd listing .pvtu indexes of one piece per rank), read
with VTK's own XML readers (vtkXMLUnstructuredGridReader,
vtkXMLPUnstructuredGridReader: what ParaView uses).

Checks, frame by frame: the same times; the index names RANKS pieces, each on
disk; the pieces together hold every particle once (ids); the point count,
and the point arrays' names, types and components, equal the one-process
file's; every value (points and arrays), matched by particle id, within 1e-12
relative of the one-process run (the ranks' seams sum the same terms in
another grouping: tests/mpi_compare.py); and the last frame's pieces equal,
bit for bit, MANY_DIR/vtu/whole.vtu, the same run's scene gathered whole
(s:vtu) after it. Exits 77 without VTK (Debian python3-vtk9)."""
import os
import sys
import xml.etree.ElementTree as ET

one_dir, many_dir, ranks = sys.argv[1], sys.argv[2], int(sys.argv[3])
TOL = 1e-12


def fail(msg):
    print("FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


try:
    import vtk
except ImportError:
    print("SKIP: VTK's Python module is missing (Debian: apt-get install python3-vtk9)")
    sys.exit(77)


def series(d):
    """[(time, path)] of d/vtu/block.pvd"""
    pvd = os.path.join(d, "vtu", "block.pvd")
    if not os.path.exists(pvd):
        fail(f"no {pvd}")
    root = ET.parse(pvd).getroot()
    return [(float(e.get("timestep")), os.path.join(d, "vtu", e.get("file"))) for e in root.iter("DataSet")]


def read(path):
    r = vtk.vtkXMLPUnstructuredGridReader() if path.endswith(".pvtu") else vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.Update()
    if r.GetErrorCode():
        fail(f"VTK could not read {path}")
    g = r.GetOutput()
    pd = g.GetPointData()
    arrays = []
    for k in range(pd.GetNumberOfArrays()):
        a = pd.GetArray(k)
        arrays.append((a.GetName(), a.GetDataTypeAsString(), a.GetNumberOfComponents(), a))
    return g, arrays


def by_id(g, arrays):
    """{id: [every component of Points and of every array]}"""
    ids = next(a for n, _, _, a in arrays if n == "id")
    pts = g.GetPoints().GetData()
    rows = {}
    for i in range(g.GetNumberOfPoints()):
        row = list(pts.GetTuple(i))
        for _, _, _, a in arrays:
            row.extend(a.GetTuple(i))
        rows[int(ids.GetValue(i))] = row
    if len(rows) != g.GetNumberOfPoints():
        fail("a particle id appears twice")
    return rows


one, many = series(one_dir), series(many_dir)
if len(one) < 2 or len(one) != len(many):
    fail(f"{len(one)} frames from one process, {len(many)} from {ranks} ranks")
worst = 0.0
for (t1, f1), (tn, fn) in zip(one, many):
    if t1 != tn:
        fail(f"frame times differ: {t1!r} against {tn!r}")
    if not f1.endswith(".vtu") or not fn.endswith(".pvtu"):
        fail(f"the one-process .pvd should list .vtu files and the {ranks}-rank one .pvtu: {f1}, {fn}")
    pieces = [p.get("Source") for p in ET.parse(fn).getroot().iter("Piece")]
    if len(pieces) != ranks or not all(os.path.exists(os.path.join(os.path.dirname(fn), p)) for p in pieces):
        fail(f"{fn} names {pieces}: not {ranks} pieces on disk")
    g1, a1 = read(f1)
    gn, an = read(fn)
    sig1 = [(n, t, c) for n, t, c, _ in a1]
    sign = [(n, t, c) for n, t, c, _ in an]
    if sig1 != sign:
        fail(f"point arrays differ:\n one process {sig1}\n {ranks} ranks  {sign}")
    if g1.GetNumberOfPoints() != gn.GetNumberOfPoints() or g1.GetNumberOfPoints() == 0:
        fail(f"t={t1}: {g1.GetNumberOfPoints()} points from one process, {gn.GetNumberOfPoints()} from the pieces")
    if gn.GetNumberOfCells() != gn.GetNumberOfPoints():
        fail(f"t={t1}: {gn.GetNumberOfCells()} cells for {gn.GetNumberOfPoints()} points")
    r1, rn = by_id(g1, a1), by_id(gn, an)
    if set(r1) != set(rn):
        fail(f"t={t1}: particle ids differ ({len(set(r1) ^ set(rn))} in one only)")
    # each piece alone: its own particles, none shared with another piece
    seen = 0
    for p in pieces:
        gp, ap = read(os.path.join(os.path.dirname(fn), p))
        seen += gp.GetNumberOfPoints()
    if seen != gn.GetNumberOfPoints():
        fail(f"t={t1}: the pieces hold {seen} points, the index reads {gn.GetNumberOfPoints()}")
    ncol = len(next(iter(r1.values())))
    for c in range(ncol):
        scale = max(max(abs(r[c]) for r in r1.values()), max(abs(r[c]) for r in rn.values()))
        if scale > 0:
            worst = max(worst, max(abs(r1[i][c] - rn[i][c]) for i in r1) / scale)
    print(f"t={t1:.4g}: {gn.GetNumberOfPoints()} points in {len(pieces)} pieces "
          f"({', '.join(str(read(os.path.join(os.path.dirname(fn), p))[0].GetNumberOfPoints()) for p in pieces)}), "
          f"{len(an)} point arrays as the one-process file's")
print(f"largest relative difference from the one-process frames {worst:.3e} (tolerance {TOL:g})")
if worst > TOL:
    sys.exit(1)
gw, aw = read(os.path.join(many_dir, "vtu", "whole.vtu"))
if by_id(gw, aw) != rn:
    fail(f"the last frame's pieces differ from the same run's scene gathered whole (vtu/whole.vtu)")
print("the last frame's pieces hold the gathered scene's values bit for bit")
leftover = [f for d in (one_dir, many_dir) for f in os.listdir(os.path.join(d, "vtu")) if "tmp" in f]
if leftover:
    fail(f"temporary files left: {leftover}")
