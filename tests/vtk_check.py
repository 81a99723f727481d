#!/usr/bin/env python3
"""vtk_check.py CASE OUTDIR: reads what tests/lua/dumps_run.lua wrote in OUTDIR.

OUTDIR/check/frame_NNNN.txt hold the scene's own values at each VTU frame
(s:particles: id, x, y, temperature, the 9 stress components), so every
number read back by a reader is compared with what the scene itself said.

Cases that need VTK (Debian python3-vtk9) exit 77 (skipped) without it:
  vtk_reads_time_series   the .pvd's frames load with VTK's XML reader, each
                          reporting its TimeValue as its time step, equal to
                          the .pvd's timestep and the scene's time
  vtk_reads_tensor_and_ids  "stress [Pa]" is the active 9-component tensor,
                          "id" the GlobalIds, stable across frames; values by id
                          match the scene's
  ply_fields_visible      VTK's PLY reader (ParaView's) loads every vertex with
                          the colour array; the raw properties (read here by
                          hand, as Blender, Open3D or plyfile would) carry id and
                          temperature
Without VTK:
  pvd_lists_every_frame   the .pvd and each VTU's XML part are well-formed XML;
                          the .pvd lists every frame on disk, in order, with
                          times equal to each file's TimeValue
"""
import os
import re
import struct
import sys
import xml.etree.ElementTree as ET

case, out = sys.argv[1], sys.argv[2]
VTU, PLY, CHECK = os.path.join(out, "vtu"), os.path.join(out, "ply"), os.path.join(out, "check")


def fail(msg):
    print("FAIL: " + msg, file=sys.stderr)
    sys.exit(1)


def need_vtk():
    try:
        import vtk  # noqa: F401
    except ImportError:
        print("SKIP: VTK's Python module is missing (Debian: apt-get install python3-vtk9; "
              "scripts/test installs it through scripts/setup.sh hearth_install_optional)")
        sys.exit(77)
    return vtk


def scene_frames():
    """The scene's own values: [(t, {id: (x, y, T, stress9)})]."""
    frames = []
    for name in sorted(os.listdir(CHECK)):
        lines = open(os.path.join(CHECK, name)).read().split("\n")
        t = float(lines[0].split()[1])
        rows = {}
        for line in lines[1:]:
            if line:
                v = line.split()
                rows[int(v[0])] = (float(v[1]), float(v[2]), float(v[3]), [float(x) for x in v[4:13]])
        frames.append((t, rows))
    if len(frames) < 3:
        fail(f"the scene recorded {len(frames)} frames; expected at least 3")
    return frames


def pvd_entries():
    root = ET.parse(os.path.join(VTU, "run.pvd")).getroot()  # raises on malformed XML
    if root.tag != "VTKFile" or root.get("type") != "Collection":
        fail(f"run.pvd: root is {root.tag} type={root.get('type')}, not a VTKFile Collection")
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]


def vtu_xml(path):
    """The XML part of a raw-appended VTU, parsed (the binary block cut out)."""
    b = open(path, "rb").read()
    i = b.find(b"<AppendedData")
    j = b.rfind(b"</AppendedData>")
    if i < 0 or j < 0:
        fail(f"{path}: no appended data block")
    return ET.fromstring(b[:i] + b"<AppendedData/>" + b[j + len(b"</AppendedData>"):])


def le_time_value(path):
    b = open(path, "rb").read()
    root = vtu_xml(path)
    arr = [a for a in root.iter("DataArray") if a.get("Name") == "TimeValue"]
    if len(arr) != 1:
        fail(f"{path}: {len(arr)} TimeValue arrays")
    base = b.find(b"_", b.find(b"<AppendedData")) + 1
    off = base + int(arr[0].get("offset"))
    n, = struct.unpack_from("<Q", b, off)
    if n != 8:
        fail(f"{path}: TimeValue holds {n} bytes")
    return struct.unpack_from("<d", b, off + 8)[0]


if case == "pvd_lists_every_frame":
    entries = pvd_entries()
    on_disk = sorted(f for f in os.listdir(VTU) if f.endswith(".vtu"))
    files = [f for _, f in entries]
    print(f"run.pvd lists {len(files)} frames; {len(on_disk)} VTU files on disk")
    if files != on_disk:
        fail(f"run.pvd lists {files}, the folder holds {on_disk}")
    times = [t for t, _ in entries]
    if any(b <= a for a, b in zip(times, times[1:])):
        fail(f"times not increasing: {times}")
    for t, f in entries:
        tv = le_time_value(os.path.join(VTU, f))
        if tv != t:
            fail(f"{f}: TimeValue {tv!r}, run.pvd says {t!r}")
    scene_t = [t for t, _ in scene_frames()]
    if times != scene_t:
        fail(f"run.pvd times {times}, the scene's {scene_t}")
    print("times", times)
    sys.exit(0)

vtk = need_vtk()
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as SDDP  # noqa: E402


def vtk_to_list(a):
    """A VTK data array as Python numbers (scalars) or tuples (components),
    read through VTK's own accessors: no numpy, which python3-vtk9 only
    recommends, so a fresh machine without it still runs these checks."""
    n, c = a.GetNumberOfTuples(), a.GetNumberOfComponents()
    if c == 1:
        return [a.GetValue(i) if hasattr(a, "GetValue") else a.GetTuple1(i) for i in range(n)]
    return [a.GetTuple(i) for i in range(n)]


def read_vtu(path):
    r = vtk.vtkXMLUnstructuredGridReader()
    r.SetFileName(path)
    r.UpdateInformation()
    info = r.GetOutputInformation(0)
    steps = info.Get(SDDP.TIME_STEPS()) if info.Has(SDDP.TIME_STEPS()) else None
    r.Update()
    return steps, r.GetOutput()


def by_id(grid):
    pd = grid.GetPointData()
    ids = vtk_to_list(pd.GetGlobalIds())
    return {int(i): k for k, i in enumerate(ids)}


if case == "vtk_reads_time_series":
    # the .pvd read with VTK's own XML parser, as ParaView's PVD reader does
    p = vtk.vtkXMLDataParser()
    p.SetFileName(os.path.join(VTU, "run.pvd"))
    if not p.Parse():
        fail("VTK's XML parser refuses run.pvd")
    coll = p.GetRootElement().FindNestedElementWithName("Collection")
    n = coll.GetNumberOfNestedElements()
    frames = scene_frames()
    print(f"VTK {vtk.vtkVersion.GetVTKVersion()}: run.pvd has {n} timesteps; the scene wrote {len(frames)} frames")
    if n != len(frames):
        fail(f"{n} timesteps in run.pvd, {len(frames)} frames")
    for k in range(n):
        e = coll.GetNestedElement(k)
        t_pvd = float(e.GetAttribute("timestep"))
        steps, g = read_vtu(os.path.join(VTU, e.GetAttribute("file")))
        print(f"  {e.GetAttribute('file')}: pvd t = {t_pvd!r}, reader TIME_STEPS = {steps}, points {g.GetNumberOfPoints()}")
        if steps is None or len(steps) != 1 or steps[0] != t_pvd or t_pvd != frames[k][0]:
            fail(f"frame {k}: reader time {steps}, pvd {t_pvd!r}, scene {frames[k][0]!r}")
        if g.GetNumberOfPoints() != len(frames[k][1]) or g.GetNumberOfCells() != g.GetNumberOfPoints():
            fail(f"frame {k}: {g.GetNumberOfPoints()} points, {g.GetNumberOfCells()} cells, the scene has {len(frames[k][1])}")
    sys.exit(0)

if case == "vtk_reads_tensor_and_ids":
    frames = scene_frames()
    files = sorted(f for f in os.listdir(VTU) if f.endswith(".vtu"))
    first_ids, worst_s, worst_T, worst_x = None, 0.0, 0.0, 0.0
    for k, f in enumerate(files):
        _, g = read_vtu(os.path.join(VTU, f))
        pd = g.GetPointData()
        names = [pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())]
        for want in ("id", "mass [kg/m]", "volume [m^2]", "temperature [degC]", "stress [Pa]", "velocity [m/s]"):
            if want not in names:
                fail(f"{f}: no array '{want}' (arrays: {names})")
        ten, vec = pd.GetTensors(), pd.GetVectors()
        if ten is None or ten.GetName() != "stress [Pa]" or ten.GetNumberOfComponents() != 9:
            fail(f"{f}: the active tensors are {ten and ten.GetName()}, not the 9-component stress")
        if vec is None or vec.GetName() != "velocity [m/s]":
            fail(f"{f}: the active vectors are {vec and vec.GetName()}")
        idx = by_id(g)
        if first_ids is None:
            first_ids = set(idx)
        elif set(idx) != first_ids:
            fail(f"{f}: the particle ids differ from frame 0's")
        if set(idx) != set(frames[k][1]):
            fail(f"{f}: ids differ from the scene's s:particles ids")
        S = vtk_to_list(ten)
        T = vtk_to_list(pd.GetArray("temperature [degC]"))
        X = vtk_to_list(g.GetPoints().GetData())
        m = vtk_to_list(pd.GetArray("mass [kg/m]"))
        V = vtk_to_list(pd.GetArray("volume [m^2]"))
        rho = vtk_to_list(pd.GetArray("density [kg/m^3]"))
        for pid, (x, y, temp, st) in frames[k][1].items():
            i = idx[pid]
            worst_x = max(worst_x, abs(X[i][0] - x), abs(X[i][1] - y))
            worst_T = max(worst_T, abs(T[i] - temp))
            worst_s = max(worst_s, max(abs(S[i][c] - st[c]) for c in range(9)))
            if abs(m[i] / V[i] - rho[i]) > 1e-12 * rho[i]:
                fail(f"{f}: particle {pid}: mass / volume = {m[i] / V[i]}, density {rho[i]}")
    smax = max(abs(c) for fr in frames for r in fr[1].values() for c in r[3])
    print(f"{len(files)} frames, {len(first_ids)} ids; by id, largest differences from the scene: "
          f"position {worst_x:.3g} m, temperature {worst_T:.3g} degC, stress {worst_s:.3g} Pa (largest stress {smax:.3g} Pa)")
    if worst_x != 0 or worst_T != 0 or worst_s != 0:
        fail("values read by VTK differ from the scene's (the files are Float64 of the same doubles)")
    if smax <= 0:
        fail("the stress is zero everywhere: nothing was tested")
    sys.exit(0)

if case == "ply_fields_visible":
    frames = scene_frames()
    files = sorted(f for f in os.listdir(PLY) if f.endswith(".ply"))
    if len(files) != len(frames):
        fail(f"{len(files)} PLY files, {len(frames)} frames")
    f = files[-1]
    path = os.path.join(PLY, f)
    r = vtk.vtkPLYReader()
    r.SetFileName(path)
    r.Update()
    o = r.GetOutput()
    pd = o.GetPointData()
    names = [pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())]
    print(f"VTK's PLY reader (ParaView's): {o.GetNumberOfPoints()} points, arrays {names}")
    if o.GetNumberOfPoints() != len(frames[-1][1]):
        fail(f"{o.GetNumberOfPoints()} points, the scene has {len(frames[-1][1])}")
    rgb = pd.GetArray("RGB")
    if rgb is None or rgb.GetNumberOfComponents() != 3:
        fail("no RGB array: ParaView would show the points with no field")
    # The raw properties, parsed by hand from the header as any PLY reader does.
    b = open(path, "rb").read()
    end = b.find(b"end_header\n") + len(b"end_header\n")
    head = b[:end].decode()
    props = re.findall(r"property (\w+) (\w+)", head)
    fmt = "<" + "".join({"double": "d", "int": "i", "uchar": "B"}[t] for t, _ in props)
    names = [n for _, n in props]
    row = struct.calcsize(fmt)
    n = int(re.search(r"element vertex (\d+)", head).group(1))
    if len(b) != end + n * row:
        fail(f"{f}: {len(b)} bytes, the header promises {end + n * row}")
    m = re.search(r"comment color (\S+) (\S+) (\S+) (\S+) (\S+)", head)
    if not m or m.group(1) != "temperature" or float(m.group(2)) != 20 or float(m.group(3)) != 80:
        fail(f"{f}: the colour comment is {m and m.group(0)}; expected temperature 20 80")
    spread, worst = set(), 0.0
    for i in range(n):
        v = dict(zip(names, struct.unpack_from(fmt, b, end + i * row)))
        scene = frames[-1][1][v["id"]]
        worst = max(worst, abs(v["temperature"] - scene[2]))
        c = rgb.GetTuple3(i)
        if c != (v["red"], v["green"], v["blue"]):
            fail(f"vertex {i}: VTK's RGB {c}, the file's {v['red'], v['green'], v['blue']}")
        spread.add(c)
    print(f"{n} vertices, {len(spread)} distinct colours; temperature by id differs from the scene's by {worst:.3g} degC; "
          f"properties {names}")
    if worst != 0:
        fail("PLY temperatures differ from the scene's")
    if len(spread) < 10:
        fail("fewer than 10 distinct colours: the colour map does not show the temperature")
    sys.exit(0)

fail(f"unknown case {case}")
