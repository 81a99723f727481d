#!/usr/bin/env bash
# report.sh: the MPM performance table of docs/performance.md (issue 20), before
# (a commit, main at a3b95dc by default) and after (this tree), in one run.
#
#   scripts/bench/report.sh [--full] [--before REF] [--out FILE]
#
# Writes FILE (default docs/performance.md) and prints it. Rows:
#   - instructions per particle-step, 1 thread, 3D and 2D, against the minimal
#     references ../shared/bench/mpm_reference.c and mpm_reference2d.c on the
#     same problems (callgrind: the count repeats exactly where wall time on a
#     shared machine does not), and the same split by phase (sort, P2G, grid
#     update, G2P; inclusive);
#   - 2 threads against 1 in wall time: the median of per-pair ratios of
#     interleaved runs (noisy on a shared machine: read the ratio, not the times);
#   - bytes per particle (`hearth bench`): what particles and grid fill, what the
#     library holds (capacity) and the most it held at once (peak); before, the
#     bench printed only what was held. Peak RSS over the run, less a tiny run's,
#     per particle, is printed for both;
#   - the dough step with all fields against the elastic step (instructions);
#   - the dough step by phase (inclusive instructions of the sort, P2G and its
#     plugin stress and parameter lookups, the boundary, heat, water, G2P...);
#   - how the cost per particle-step grows from about 20k to 1.2M particles,
#     3D and 2D (to 4M in both with --full; a before tree whose bench refuses
#     the size, as a3b95dc's refused more than 1024 cells, shows "-"): wall ns
#     per particle-step at one thread, bytes per particle and peak RSS.
# Sections of FILE that this script does not make (hand-written notes: SPH,
# the batched call...) are kept, after the ones it makes.
# Counts are per particle-step from the difference of a short and a long run,
# so setup cancels. Built without -march=native (valgrind does not decode
# AVX-512): the before tree in build/bench-before/REF, this one in build/nn.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
full=0 before=a3b95dc out="$root/docs/performance.md"
while [ $# -gt 0 ]; do
    case $1 in
    --full) full=1 ;;
    --before) before=$2; shift ;;
    --out) out=$2; shift ;;
    -h | --help) sed -n 2,28p "$0"; exit 0 ;;
    *) echo "report.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
command -v valgrind >/dev/null || { echo "report.sh: needs valgrind" >&2; exit 2; }
shared="$root/../shared/bench"
[ -f "$shared/mpm_reference.c" ] && [ -f "$shared/mpm_reference2d.c" ] ||
    { echo "report.sh: $shared/mpm_reference.c and mpm_reference2d.c are needed" >&2; exit 2; }

targets="app/hearth plugins/hearth_elastic.so plugins/hearth_cam_clay_dough.so plugins/hearth_newtonian.so"
build() { # build SRC_DIR BUILD_DIR: the hearth program and the two plugins the rows use
    [ -f "$2/build.ninja" ] || meson setup "$2" "$1" --buildtype=release -Dnative=false >/dev/null
    ninja -C "$2" $targets >/dev/null
}
bsrc="$root/build/bench-before/$before"
if [ ! -f "$bsrc/meson.build" ]; then
    mkdir -p "$bsrc"
    git -C "$root" archive "$before" | tar -x -C "$bsrc"
fi
echo "report.sh: building $before (build/bench-before) and this tree (build/nn)" >&2
build "$bsrc" "$bsrc/build/nn"
build "$root" "$root/build/nn"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cc -O3 -o "$tmp/ref3" "$shared/mpm_reference.c" -lm
cc -O3 -o "$tmp/ref2" "$shared/mpm_reference2d.c" -lm

export REPORT_FULL=$full REPORT_BEFORE=$before REPORT_TMP=$tmp REPORT_OUT=$out
export REPORT_BEFORE_DIR="$bsrc/build/nn" REPORT_AFTER_DIR="$root/build/nn" REPORT_ROOT=$root
exec python3 - <<'PY'
import json, os, re, statistics, subprocess, sys, time

E = os.environ
full, tmp, out = E["REPORT_FULL"] == "1", E["REPORT_TMP"], E["REPORT_OUT"]
trees = {"before": E["REPORT_BEFORE_DIR"], "after": E["REPORT_AFTER_DIR"]}
srcs = {"before": os.path.dirname(os.path.dirname(trees["before"])), "after": E["REPORT_ROOT"]}
PHASES = ["mpm_sort", "particles_permute", "mpm_p2g", "mpm_grid_update", "mpm_g2p"]
# A plain step (no heat, water, wrap or ranks) runs the three middle phases in
# one region (mpm.c's step_team), where each is its own team function: a phase
# that callgrind does not see by its own name is read from its team function.
TEAM = {"mpm_p2g": "p2g_team", "mpm_grid_update": "grid_update_team", "mpm_g2p": "g2p_team"}

def log(msg):
    print("report.sh: " + msg, file=sys.stderr, flush=True)

def env(tree, threads):
    return dict(E, OMP_NUM_THREADS=str(threads), OMP_WAIT_POLICY="passive", HEARTH_PLUGIN_PATH=trees[tree] + "/plugins")

def hearth(tree):
    return trees[tree] + "/app/hearth"

def callgrind(cmd, tree=None, threads=1):
    """Instructions of cmd: the total, the inclusive count of each MPM phase (and, under
    "omp", of every OpenMP region body: the work threads share), and stdout."""
    f = os.path.join(tmp, "cg.out")
    r = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=" + f] + cmd, capture_output=True, text=True,
                       env=env(tree or "after", threads), check=True)
    total = int(re.search(r"Collected : (\d+)", r.stderr).group(1))
    ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", f], capture_output=True, text=True,
                         check=True).stdout
    ph = {"omp": 0}
    for line in ann.splitlines():
        m = re.match(r"\s*([\d,]+)\s.*?:(\w+) \[", line)
        if m and m.group(2) in PHASES and m.group(2) not in ph:
            ph[m.group(2)] = int(m.group(1).replace(",", ""))
        if m and m.group(2) in TEAM.values() and "team:" + m.group(2) not in ph:
            ph["team:" + m.group(2)] = int(m.group(1).replace(",", ""))
        m = re.match(r"\s*([\d,]+)\s.*?:[\w.]+\._omp_fn\.\d+ \[", line)
        if m:
            ph["omp"] += int(m.group(1).replace(",", ""))
    for p, fn in TEAM.items():
        if p not in ph and "team:" + fn in ph:
            ph[p] = ph["team:" + fn]
    return total, ph, r.stdout

FLOW = os.path.join(E["REPORT_ROOT"], "scripts/bench/flow_step.lua")  # public Lua API only: runs on the before tree too

def flow_cg(tree, threads, s1=2, s2=6):
    """Per particle-step instructions of flow_step.lua (2D, 256 cells): total and phases, and the region bodies."""
    runs = [callgrind([hearth(tree), "run", FLOW, "--quiet", "--out", tmp, "--set", f"steps={s}"], tree, threads) for s in (s1, s2)]
    n = int(re.search(r"particles=(\d+)", runs[0][2]).group(1))
    per = lambda a, b: (b - a) / (n * (s2 - s1))
    return per(runs[0][0], runs[1][0]), {p: per(runs[0][1].get(p, 0), runs[1][1].get(p, 0)) for p in PHASES + ["omp"]}

def bench_omp(tree, dim, cells, s1, s2):
    """At two threads: instructions per particle-step in all, and outside every parallel region (serial)."""
    runs = [callgrind([hearth(tree), "bench", "--threads", "2", "--dim", str(dim), "--cells", str(cells), "--steps", str(s)],
                      tree, 2) for s in (s1, s2)]
    n = json.loads(runs[0][2])["particles"]
    tot = (runs[1][0] - runs[0][0]) / (n * (s2 - s1))
    par = (runs[1][1]["omp"] - runs[0][1]["omp"]) / (n * (s2 - s1))
    return tot, tot - par

def bench_cg(tree, dim, cells, s1, s2):
    """Instructions per particle-step of `hearth bench` (total and by phase), from s1 and s2 timed steps."""
    runs = [callgrind([hearth(tree), "bench", "--threads", "1", "--dim", str(dim), "--cells", str(cells), "--steps", str(s)], tree)
            for s in (s1, s2)]
    n = json.loads(runs[0][2])["particles"]
    per = lambda a, b: (b - a) / (n * (s2 - s1))
    return n, per(runs[0][0], runs[1][0]), {p: per(runs[0][1].get(p, 0), runs[1][1].get(p, 0)) for p in PHASES}

def ref_cg(dim, cells, s1, s2):
    exe = os.path.join(tmp, "ref3" if dim == 3 else "ref2")
    runs = [callgrind([exe, str(cells), str(s)]) for s in (s1, s2)]
    n = int(re.search(r"particles=(\d+)", runs[0][2]).group(1))
    return n, (runs[1][0] - runs[0][0]) / (n * (s2 - s1))

def bench(tree, dim, cells, steps, threads=1, refused_ok=False):
    r = subprocess.run([hearth(tree), "bench", "--threads", str(threads), "--dim", str(dim), "--cells", str(cells), "--steps",
                        str(steps)], capture_output=True, text=True, env=env(tree, threads))
    if r.returncode == 2 and refused_ok:  # a usage refusal (the size), not a failed run
        return None
    if r.returncode:
        raise subprocess.CalledProcessError(r.returncode, r.args, r.stdout, r.stderr)
    return json.loads(r.stdout)

def rss_kb(tree, dim, cells):
    f = os.path.join(tmp, "rss")
    subprocess.run(["/usr/bin/time", "-f", "%M", "-o", f, hearth(tree), "bench", "--threads", "1", "--dim", str(dim),
                    "--cells", str(cells), "--steps", "1"], capture_output=True, env=env(tree, 1), check=True)
    return int(open(f).read().split()[-1])

load0 = os.getloadavg()[0]
rows = []  # (measure, before, after, note)
lines = []

# ---- instructions per particle-step against the references ---------------
cfg = {3: (32, 1, 4), 2: (256, 1, 5)}
cg = {}
for dim, (cells, s1, s2) in cfg.items():
    log(f"callgrind {dim}D, {cells} cells")
    nr, ref = ref_cg(dim, cells, s1, s2)
    cg[dim] = {"ref": ref, "nref": nr}
    for t in trees:
        cg[dim][t] = bench_cg(t, dim, cells, s1, s2)
    nb, ib, _ = cg[dim]["before"]
    na, ia, _ = cg[dim]["after"]
    rows.append((f"elastic step, {dim}D, 1 thread, vs the reference ({cells} cells; {na} vs {nr} particles): reference / hearth instructions",
                 f"{ref / ib:.2f}x ({ib:.0f} vs {ref:.0f})", f"{ref / ia:.2f}x ({ia:.0f} vs {ref:.0f})",
                 ">= 0.9x" if dim == 3 else ">= 0.7x"))

# ---- 2 threads against 1 --------------------------------------------------
sizes = {2: [128, 256, 512] + ([1024] if full else []), 3: [32, 64] + ([96] if full else [])}
speed = {}
for dim, cl in sizes.items():
    for cells in cl:
        log(f"threads {dim}D, {cells} cells")
        n = bench("after", dim, cells, 1)["particles"]
        steps = max(5, int((3e6 if dim == 2 else 1.5e6) / n))
        for t in trees:
            ratios = []
            for _ in range(3):  # interleaved pairs; the median of their ratios
                a = bench(t, dim, cells, steps, 1)["particle_steps_per_s"]
                b = bench(t, dim, cells, steps, 2)["particle_steps_per_s"]
                ratios.append(b / a)
            speed[(dim, cells, t)] = statistics.median(ratios)
for dim, cl in sizes.items():
    rows.append((f"2 threads vs 1, {dim}D, {cl[0]}-{cl[-1]} cells (wall time, median of 3 interleaved pairs)",
                 ", ".join(f"{speed[(dim, c, 'before')]:.2f}" for c in cl) + "x",
                 ", ".join(f"{speed[(dim, c, 'after')]:.2f}" for c in cl) + "x", ">= 1.8x" if dim == 2 else ">= 1.9x"))

# ---- a flowing scene, and the serial share at two threads ----------------------
log("callgrind: flow_step.lua, 1 and 2 threads")
flow = {t: flow_cg(t, 1) for t in trees}
rows.append(("flowing 2D block (flow_step.lua, 256 cells, 41944 particles), 1 thread: instructions per particle-step "
             "(the sort's share, its permutation's)",
             "%.0f (%.0f, %.0f)" % (flow["before"][0], flow["before"][1]["mpm_sort"], flow["before"][1]["particles_permute"]),
             "%.0f (%.0f, %.0f)" % (flow["after"][0], flow["after"][1]["mpm_sort"], flow["after"][1]["particles_permute"]), "-"))
def bound(tot, ser):
    return 1.0 / (ser / tot + (1 - ser / tot) / 2)
amd = {}
for t in trees:
    f_tot, f_ph = flow_cg(t, 2)
    amd[("flow", t)] = (f_tot, f_tot - f_ph["omp"])
    amd[("bench", t)] = bench_omp(t, 2, 256, 1, 3)
    amd[("bench3", t)] = bench_omp(t, 3, 32, 1, 3)
for k, what in (("bench", "`hearth bench --dim 2 --cells 256`"), ("bench3", "`hearth bench --dim 3 --cells 32`"),
                ("flow", "flow_step.lua")):
    rows.append((f"2 threads, {what}: instructions per particle-step outside parallel regions (serial), and the speed-up "
                 "that leaves at best (Amdahl)",
                 "%.1f of %.0f: %.3fx" % (amd[(k, 'before')][1], amd[(k, 'before')][0], bound(*amd[(k, 'before')])),
                 "%.1f of %.0f: %.3fx" % (amd[(k, 'after')][1], amd[(k, 'after')][0], bound(*amd[(k, 'after')])), "-"))

# ---- memory -----------------------------------------------------------------
mem = {}
for dim, cells in [(3, 32), (3, 64), (2, 128), (2, 512)]:
    log(f"memory {dim}D, {cells} cells")
    for t in trees:
        j = bench(t, dim, cells, 2)
        small = 16 if dim == 3 else 32
        n0 = bench(t, dim, small, 1)["particles"]
        rss = (rss_kb(t, dim, cells) - rss_kb(t, dim, small)) * 1024.0 / (j["particles"] - n0)
        mem[(dim, cells, t)] = (j, rss)
def memcell(dim, cells, t):
    j, rss = mem[(dim, cells, t)]
    if "capacity_bytes_per_particle" in j:
        return (f"{j['bytes_per_particle']:.0f} used, {j['capacity_bytes_per_particle']:.0f} held, peak "
                f"{j['peak_bytes_per_particle']:.0f}; RSS {rss:.0f}")
    return f"{j['bytes_per_particle']:.0f} held; RSS {rss:.0f}"
for dim in (3, 2):
    for cells in [c for (d, c, t) in mem if d == dim and t == "after"]:
        rows.append((f"bytes per particle, {dim}D, {cells} cells (`hearth bench`; peak RSS per particle beside it)",
                     memcell(dim, cells, "before"), memcell(dim, cells, "after"),
                     ("<= 240" if dim == 3 else "<= 160") + ", peak <= 1.25x steady"))

# ---- the dough step against the elastic step -------------------------------
# The dough step by phase: inclusive instructions of these functions a step (the
# plugin's `stress` or `stress_block` with the libm calls it makes; transport_apply is the fields'
# particle pass, boundary_find the air surface, thermal_* the node updates).
DOUGH_PHASES = [("mpm_sort", "sort"), ("mpm_p2g", "P2G (all of it)"),
                ("material_run_eval", "  of which the material door (the plugin's stress included)"),
                ("stress", "  of which the plugin's stress (one point a call)"),
                ("stress_block", "  of which the plugin's stress (a block a call)"),
                ("material_params_resolve", "  of which parameters and curves per point"),
                ("boundary_find", "boundary (the air surface)"), ("thermal_prepare", "heat: node temperatures, boundary coefficients"),
                ("transport_apply", "heat (and water) particle pass"), ("thermal_finish", "heat: node update"),
                ("water_prepare", "water: node saturation"), ("water_face_flux", "water: wet colliders"),
                ("mpm_grid_update", "grid update"), ("mpm_g2p", "G2P (all of it)"), ("gas_moles_step", "  of which CO2 (gas)"),
                ("water_finish", "water: particle update"), ("mixing_update", "mixing")]

def fn_counts(f):
    ann = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", f], capture_output=True, text=True,
                         check=True).stdout
    c = {}
    for line in ann.splitlines():
        m = re.match(r"\s*([\d,]+)\s.*?:(\w+) \[", line)
        if m and m.group(2) not in c:
            c[m.group(2)] = int(m.group(1).replace(",", ""))
    for p, fn in TEAM.items():
        if p not in c and fn in c:
            c[p] = c[fn]
    return c

def dough_cg(t, only, steps):
    total, _, _ = callgrind([hearth(t), "run", srcs[t] + "/scripts/bench/dough_step.lua", "--quiet", "--out", tmp, "--set",
                             "only=" + only, "--set", f"steps={steps}", "--set", "dim=2", "--set", "cells=64"], t)
    return total, fn_counts(os.path.join(tmp, "cg.out"))

dough = {}
def dough_ratio(t):
    runs = {(o, k): dough_cg(t, o, k) for o in ("elastic", "dough") for k in (2, 12)}
    per = lambda o, fn=None: ((runs[(o, 12)][0] - runs[(o, 2)][0]) if fn is None else
                              (runs[(o, 12)][1].get(fn, 0) - runs[(o, 2)][1].get(fn, 0))) / 10
    e, d = per("elastic"), per("dough")
    dough[t] = {"elastic": e, "dough": d, **{fn: (per("elastic", fn), per("dough", fn)) for fn, _ in DOUGH_PHASES + [("mpm_step", "")]}}
    return f"{d / e:.2f}x ({d / 1e6:.2f}M vs {e / 1e6:.2f}M a step)"
log("dough vs elastic")
rows.append(("dough step with all fields vs the elastic step (2D, 64 cells, instructions)", dough_ratio("before"),
             dough_ratio("after"), "<= 1.5x"))
# ---- SPH against DualSPHysics: an estimate from instructions (DualSPHysics does not run here) -----------
# Issue 20 measured 0.40x DualSPHysics 5.4 per step and 0.71x per simulated second when this dam break
# counted 19,641 instructions per particle-step (20k particles, docs/performance.md's SPH section); if time
# follows instructions, a count c gives 0.40 x 19641 / c and 0.71 x 19641 / c.
SPH = os.path.join(E["REPORT_ROOT"], "scripts/bench/sph_dam_break.lua")  # public Lua API: the before tree runs it too
def sph_cg(t):
    try:
        a, b = (callgrind([hearth(t), "run", SPH, "--quiet", "--out", tmp, "--set", "dx=0.002", "--set", f"steps={k}"], t)[0]
                for k in (0, 2))
    except subprocess.CalledProcessError:
        return None
    return (b - a) / 2 / 20000
def sph_cell(t):
    c = sph_cg(t)
    if c is None:
        return "- (the tree does not run the scene)"
    return f"about {0.40 * 19641 / c:.2f}x per step, {0.71 * 19641 / c:.2f}x per simulated second ({c:,.0f} instructions per particle-step)"
log("SPH dam break, 20k particles")
rows.append(("SPH dam break vs DualSPHysics 5.4 CPU, 20k particles (estimated from instructions: issue 20's 0.40x per step "
             "and 0.71x per simulated second at 19,641, scaled by the count; DualSPHysics does not run here)",
             sph_cell("before"), sph_cell("after"), ">= 1.0x per step, >= 1.5x per simulated second"))

# ---- phases ----------------------------------------------------------------
ph_lines = ["| phase | " + " | ".join(f"{d}D before | {d}D after" for d in (3, 2)) + " | flow before | flow after |",
            "|---|" + "---:|" * 6]
for p in PHASES:
    ph_lines.append(f"| {p} | " + " | ".join(f"{cg[d]['before'][2][p]:.0f} | {cg[d]['after'][2][p]:.0f}" for d in (3, 2))
                    + f" | {flow['before'][1][p]:.0f} | {flow['after'][1][p]:.0f} |")
ph_lines.append("| whole step | " + " | ".join(f"{cg[d]['before'][1]:.0f} | {cg[d]['after'][1]:.0f}" for d in (3, 2))
                + f" | {flow['before'][0]:.0f} | {flow['after'][0]:.0f} |")
ph_lines.append("| reference | " + " | ".join(f"{cg[d]['ref']:.0f} | {cg[d]['ref']:.0f}" for d in (3, 2)) + " | - | - |")

dough_lines = ["| phase (millions of instructions a step) | elastic (after) | dough before | dough after |", "|---|---:|---:|---:|"]
for fn, what in DOUGH_PHASES:
    if any(dough[t][fn][1] for t in trees):
        dough_lines.append(f"| {what} (`{fn}`) | {dough['after'][fn][0] / 1e6:.2f} | {dough['before'][fn][1] / 1e6:.2f} | "
                           f"{dough['after'][fn][1] / 1e6:.2f} |")
rest = {t: [dough[t][k] - sum(dough[t][fn][i] for fn, w in DOUGH_PHASES if not w.startswith(" ")) for i, k in
            enumerate(("elastic", "dough"))] for t in trees}
dough_lines.append(f"| the rest (step control, the guard, Lua) | {rest['after'][0] / 1e6:.2f} | {rest['before'][1] / 1e6:.2f} | "
                   f"{rest['after'][1] / 1e6:.2f} |")
dough_lines.append(f"| whole step | {dough['after']['elastic'] / 1e6:.2f} | {dough['before']['dough'] / 1e6:.2f} | "
                   f"{dough['after']['dough'] / 1e6:.2f} |")

# ---- growth ----------------------------------------------------------------
# about 20k, 80k, 320k, 1.2M and (--full) 4M particles: 8 a cell over 0.6^3 of the box in 3D, 4 over 0.6^2 in 2D
grow = {3: [23, 36, 57, 88] + ([132] if full else []), 2: [118, 236, 471, 913] + ([1667] if full else [])}
g_lines = ["| dim | cells | particles | before ns / particle-step | after ns / particle-step | before bytes / particle | "
           "after bytes / particle (used, held) | after peak RSS / particle |", "|---:|---:|---:|---:|---:|---:|---:|---:|"]
for dim, cl in grow.items():
    for cells in cl:
        log(f"growth {dim}D, {cells} cells")
        res = {}
        for t in trees:
            j1 = bench(t, dim, cells, 1, refused_ok=t == "before")  # the before tree's bench may refuse the size
            if j1 is None:
                res[t] = None
                continue
            n = j1["particles"]
            steps = max(2, int(2e6 / n))
            js = [bench(t, dim, cells, steps) for _ in range(2)]
            res[t] = (n, min(1e9 / j["particle_steps_per_s"] for j in js), js[0])
        ja = res["after"][2]
        bt = ("%.0f" % res["before"][1], "%.0f" % res["before"][2]["bytes_per_particle"]) if res["before"] else ("-", "-")
        small = 16 if dim == 3 else 32  # less a tiny run's peak, as in the memory rows
        rss = (rss_kb("after", dim, cells) - rss_kb("after", dim, small)) * 1024.0 / (res["after"][0] - bench("after", dim, small, 1)["particles"])
        g_lines.append(f"| {dim}D | {cells} | {res['after'][0]} | {bt[0]} | {res['after'][1]:.0f} | "
                       f"{bt[1]} | {ja['bytes_per_particle']:.0f}, "
                       f"{ja['capacity_bytes_per_particle']:.0f} | {rss:.0f} |")

# ---- write ----------------------------------------------------------------
doc = f"""# Performance

Made by `scripts/bench/report.sh{' --full' if full else ''}` ({time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())};
load average {load0:.1f} at the start and {os.getloadavg()[0]:.1f} at the end, on {os.cpu_count()} cores):
before is {E['REPORT_BEFORE']}, after is this tree. Both built without `-march=native`
(valgrind does not decode AVX-512), one run on a shared 2-core machine: instruction
counts repeat exactly; wall-time rows are ratios from interleaved runs, and
under a load above the core count they measure the machine more than hearth
(a 2-thread run that lands on idle cores while its 1-thread twin shared one
shows 4x and more): read the serial-share rows, which are instruction counts,
for what the code itself leaves to one thread.
Instructions are per particle-step, from the difference of a short and a long
run (setup cancels). The references are `../shared/bench/mpm_reference.c` and
`mpm_reference2d.c` (`cc -O3`), stepping the problem of `hearth bench`.

| measure | before | after | target |
|---|---|---|---|
""" + "\n".join(f"| {a} | {b} | {c} | {d} |" for a, b, c, d in rows) + f"""

## Instructions per particle-step by phase (1 thread, inclusive)

3D: {cfg[3][0]} cells, {cg[3]['after'][0]} particles; 2D: {cfg[2][0]} cells, {cg[2]['after'][0]} particles.
The sort's keys now come from G2P (mpm_sort no longer walks the positions;
G2P carries that work); particles_permute is part of mpm_sort. `hearth bench`'s
block starts at rest and its particles hardly change blocks in a few steps, so
its sort rarely reorders; flow_step.lua throws a block across the box, so the
sort reorders every step (2D, 256 cells).

""" + "\n".join(ph_lines) + """

## Memory

`bytes_per_particle` of `hearth bench` counts what the particles' columns,
the step's per-particle scratch and the grid (tables and active blocks) fill
(`hearth_scene_bytes_used`); `capacity_bytes_per_particle` what the library
holds, spare room included (before this work the bench printed only that);
`peak_bytes_per_particle` the most it held at once (an allocator hook in the
bench). RSS is the run's peak resident size less a tiny run's, per particle:
it includes what the allocator keeps and the page tables.

## The dough step by phase

`scripts/bench/dough_step.lua` (2D, 64 cells, one thread, callgrind): the
elastic step and the cam_clay_dough step with all its fields (oven, heat, CO2,
expansion) on the same particles, inclusive instructions of each phase a step
(the difference of 12 and 2 steps over 10). Rows indented are part of the row
above; "the rest" is the whole step less the top-level rows.

""" + "\n".join(dough_lines) + """

## Growth from 20k particles

The elastic block of `hearth bench` in 3D and 2D, one thread, wall ns per
particle-step (the faster of two runs, on a shared machine), bytes per particle
(`hearth bench`), and the run's peak RSS less a tiny run's, per particle (as in
the memory rows). "-": the before tree's bench refused the size.

""" + "\n".join(g_lines) + "\n"
os.makedirs(os.path.dirname(out), exist_ok=True)
# the sections this script does not make (SPH, from scripts/bench/sph_instructions.sh, and the notes on
# each piece of work, written by hand) are kept as they stand, in their order, after the ones it makes
made = {m.group(1) for m in re.finditer(r"^## (.+)$", doc, re.M)}
if os.path.exists(out):
    old = open(out).read()
    for sec in re.split(r"\n(?=## )", old)[1:]:
        if sec.split("\n", 1)[0][3:].strip() not in made:
            doc += "\n" + sec.rstrip("\n") + "\n"
with open(out + ".tmp", "w") as f:
    f.write(doc)
os.replace(out + ".tmp", out)
print(doc)
PY
