#!/usr/bin/env bash
# batch_instructions.sh BEFORE_BUILD AFTER_BUILD: what the batched material
# call (issue 20, <hearth/material.h> rule 7) does to the plugin's stress and
# to P2G, in callgrind instructions per particle-step (one thread), on
# `hearth bench` 3D 32 cells and 2D 256 cells (elastic) and on the dough step
# with all fields (scripts/bench/dough_step.lua, 2D 64 cells; per step, as
# report.sh's row). Each count is the difference of a short and a long run,
# so setup cancels; docs/performance.md's method. The builds are meson build
# folders without -march=native (valgrind does not decode AVX-512), e.g.
#   meson setup build/nn --buildtype=release -Dnative=false
#   ninja -C build/nn app/hearth plugins/hearth_elastic.so plugins/hearth_cam_clay_dough.so
# "plugin stress" is the inclusive count of the plugin's stress and
# stress_block (a block's one call covers its points); "door" adds the core's
# per-point work around it (P2G's material call site: p2g_stress, or before
# this work the stress part of p2g_block, which the count cannot split, so
# the before column shows the plugin only).
set -euo pipefail
[ $# -eq 2 ] || { echo "usage: $0 BEFORE_BUILD AFTER_BUILD" >&2; exit 2; }
root=$(cd "$(dirname "$0")/../.." && pwd)
export BEFORE=$(cd "$1" && pwd) AFTER=$(cd "$2" && pwd) ROOT=$root
exec python3 - <<'PY'
import json, os, re, subprocess, tempfile
E = os.environ
tmp = tempfile.mkdtemp()

def callgrind(build, cmd):
    f = os.path.join(tmp, "cg.out")
    env = dict(E, OMP_NUM_THREADS="1", OMP_WAIT_POLICY="passive", HEARTH_PLUGIN_PATH=build + "/plugins")  # hearth re-executes itself to set the wait policy otherwise
    r = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + f, build + "/app/hearth"] + cmd,
                       capture_output=True, text=True, env=env, check=True)
    total = int(re.search(r"Collected : (\d+)", r.stderr).group(1))
    ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", f], capture_output=True, text=True,
                         check=True).stdout
    ph = {"p2g": 0, "stress": 0, "door": 0}
    for line in ann.splitlines():
        m = re.match(r"\s*([\d,]+)\s.*?:(\w+) \[(.*)\]", line)
        if not m:
            continue
        n, fn, obj = int(m.group(1).replace(",", "")), m.group(2), m.group(3)
        if fn == "mpm_p2g" and not ph["p2g"]:
            ph["p2g"] = n
        if "hearth_elastic" in obj or "hearth_cam_clay_dough" in obj:
            if fn in ("stress", "stress_block"):
                ph["stress"] += n
        if fn == "material_run_eval":
            ph["door"] += n
    return total, ph, r.stdout

def per(build, cmd_of, s1, s2, n_of):
    a, b = callgrind(build, cmd_of(s1)), callgrind(build, cmd_of(s2))
    n = n_of(a[2]) * (s2 - s1)
    return {"total": (b[0] - a[0]) / n, **{k: (b[1][k] - a[1][k]) / n for k in a[1]}}

rows = []
for dim, cells, s1, s2 in ((3, 32, 1, 4), (2, 256, 1, 5)):
    cmd = lambda s: ["bench", "--threads", "1", "--dim", str(dim), "--cells", str(cells), "--steps", str(s)]
    for name, build in (("before", E["BEFORE"]), ("after", E["AFTER"])):
        r = per(build, cmd, s1, s2, lambda out: json.loads(out)["particles"])
        rows.append((f"hearth bench {dim}D {cells} cells, per particle-step", name, r))
for name, build in (("before", E["BEFORE"]), ("after", E["AFTER"])):
    cmd = lambda s: ["run", E["ROOT"] + "/scripts/bench/dough_step.lua", "--quiet", "--out", tmp, "--set", "only=dough",
                     "--set", f"steps={s}", "--set", "dim=2", "--set", "cells=64"]
    r = per(build, cmd, 2, 12, lambda out: 1)
    rows.append(("dough step with all fields, 2D 64 cells, per step", name, r))
print("| run | tree | whole step | mpm_p2g | plugin stress | door (after: material_run_eval) |")
print("|---|---|---:|---:|---:|---:|")
for what, name, r in rows:
    print(f"| {what} | {name} | {r['total']:.0f} | {r['p2g']:.0f} | {r['stress']:.0f} | {r['door']:.0f} |")
PY
