#!/usr/bin/env bash
# sph_phases.sh [DX]: where the SPH dam break's instructions go, per
# particle-step by phase (scripts/bench/sph_dam_break.lua, 1 thread, under
# callgrind, the difference of a run with 2 more steps and one without, as
# sph_instructions.sh), from each function's own (exclusive) count; what no
# phase names is "rest" (the plugin's stress, pow, step bookkeeping, sort).
#   scripts/bench/sph_phases.sh          # dx 0.002: 20k particles
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/scripts/bench/callgrind.sh"
dx=${1:-0.002}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for k in 0 2; do
    OMP_WAIT_POLICY=passive OMP_NUM_THREADS=1 HEARTH_PLUGIN_PATH="$root/build/nn/plugins" valgrind --tool=callgrind \
        --callgrind-out-file="$tmp/cg.$k" "$nn_hearth" run "$root/scripts/bench/sph_dam_break.lua" --quiet \
        --set dx="$dx" --set steps=$k > /dev/null 2>&1
    callgrind_annotate --threshold=100 "$tmp/cg.$k" 2> /dev/null | grep -E '^ *[0-9,]+ ' > "$tmp/fn.$k"
done
python3 - "$tmp" "$dx" <<'PY'
import re, sys
tmp, dx = sys.argv[1], float(sys.argv[2])
n = round(0.2 / dx) * round(0.4 / dx)
def load(k):
    f = {}
    for line in open(f"{tmp}/fn.{k}"):
        m = re.match(r'^\s*([\d,]+)\s+(?:\([^)]*\)\s+)?(\S+)', line)
        if m: f[m.group(2)] = f.get(m.group(2), 0) + int(m.group(1).replace(',', ''))
    return f
a, b = load(0), load(2)
total = b.pop('PROGRAM', 0) - a.pop('PROGRAM', 0)
phases = [('neighbour lists with the density (sph_nlist_build)', ('sph_nlist_build', 'stencil')),
          ('velocity gradient, colour field, viscous moments (phase_kinematics)', ('phase_kinematics', 'sph_viscous_factor')),
          ('forces and kick (sph_forces; phase_forces before)', ('sph_forces', 'phase_forces')),
          ('XSPH (phase_xsph)', ('phase_xsph',))]
rows, named = [], 0
for label, keys in phases:
    c = sum(b.get(f, 0) - a.get(f, 0) for f in set(a) | set(b) if any(k in f.split(':')[-1] for k in keys))
    rows.append((label, c)); named += c
rows.append(('rest (stress through the plugin, pressure, sort, bookkeeping)', total - named))
print(f"SPH dam break, {n} particles (dx {dx:g}), 1 thread, instructions per particle-step:")
for label, c in rows: print(f"  {c / 2 / n:8.0f}  {label}")
print(f"  {total / 2 / n:8.0f}  total")
PY
