#!/usr/bin/env bash
# compare_reference.sh: hearth's MPM step against the minimal reference step
# (../shared/bench/mpm_reference.c) on the same problem, in one run, so the
# ratios hold on a shared, noisy machine.
#
#   scripts/bench/compare_reference.sh [cells=64] [steps=40]
#
# Prints both raw lines, then the three ratios the core is held to:
#   hearth 1 thread  >= 0.5 x reference particle-steps/s
#   hearth 2 threads >= 1.7 x hearth 1 thread
#   bytes per particle <= 300 (grid included)
# and exits non-zero when one is missed.
set -euo pipefail
cells=${1:-64}
steps=${2:-40}
. "$(dirname "$0")/../setup.sh"
hearth_install_deps
hearth_build build/release --buildtype=release
ref_src="$HEARTH_ROOT/../shared/bench/mpm_reference.c"
[ -f "$ref_src" ] || { echo "compare_reference: $ref_src not found" >&2; exit 2; }
ref_bin=$(mktemp -d)/mpm_reference
cc -O3 -march=native -o "$ref_bin" "$ref_src" -lm
hearth="$HEARTH_ROOT/build/release/app/hearth"

ref=$("$ref_bin" "$cells" "$steps")
h1=$("$hearth" bench --threads 1 --cells "$cells" --steps "$steps")
h2=$("$hearth" bench --threads 2 --cells "$cells" --steps "$steps")
echo "$ref"
echo "hearth 1 thread:  $h1"
echo "hearth 2 threads: $h2"
python3 - "$ref" "$h1" "$h2" <<'PY'
import json, re, sys
ref = dict(kv.split("=") for kv in sys.argv[1].split()[1:])
h1, h2 = json.loads(sys.argv[2]), json.loads(sys.argv[3])
r_ref = float(ref["particle_steps_per_s"])
a = h1["particle_steps_per_s"] / r_ref
b = h2["particle_steps_per_s"] / h1["particle_steps_per_s"]
c = h1["bytes_per_particle"]
ok = [a >= 0.5, b >= 1.7, c <= 300]
print(f"hearth 1 thread / reference   = {a:.2f}  (target >= 0.5)  {'ok' if ok[0] else 'MISSED'}")
print(f"hearth 2 threads / 1 thread   = {b:.2f}  (target >= 1.7)  {'ok' if ok[1] else 'MISSED'}")
print(f"bytes per particle            = {c:.0f}   (target <= 300)  {'ok' if ok[2] else 'MISSED'}")
sys.exit(0 if all(ok) else 1)
PY
