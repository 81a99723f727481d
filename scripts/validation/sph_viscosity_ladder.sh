#!/usr/bin/env bash
# sph_viscosity_ladder.sh [BUILD_DIR] [N...]: the SPH viscosity's convergence
# ladder (issue #17), longer than the meson tests sph_creeping_startup_converges
# and sph_poiseuille_converges run. For each N particles across a 0.02 m
# channel (periodic in x, three layers of fixed wall particles):
#   start-up:  1e4 Pa s from rest (the particles stay on their lattice); the worst
#              error against the start-up series at t = 0.05, 0.2, 0.5 L^2/nu,
#              as a fraction of the centreline speed then; slow(0.5): how far the
#              mean speed falls short of the series at 0.5 L^2/nu (negative: fast)
#   steady:    1 Pa s (rows slide) after L^2/nu; worst error as a fraction of the peak
# with the observed order between neighbouring rungs. Output: docs/validation.md,
# section "SPH viscosity". About a minute at 10 20 40 80 on one core.
set -eu
build=${1:-build/release}
shift || true
ladder=${*:-10 20 40 80}
exe="$build/tests/unit_sph_transport"
[ -x "$exe" ] || { echo "no $exe: build first (ninja -C $build)" >&2; exit 2; }
SPH_LADDER="$ladder" OMP_NUM_THREADS=1 "$exe" sph_viscosity_ladder
