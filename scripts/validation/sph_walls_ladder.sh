#!/usr/bin/env bash
# sph_walls_ladder.sh [BUILD_DIR]: the ladders of issue #17's SPH moving walls
# and conduction, longer than the meson tests sph_couette_moving_lid_converges
# and sph_heat_conduction_converges run:
#   Couette:  a 0.02 m layer (periodic in x, three wall layers each side) at
#             1e4 Pa s from rest, the top wall of fixed particles sliding at
#             5 mm/s (hearth_scene_body_motion); worst error against the
#             start-up series at t = 0.05, 0.2, 0.5 L^2/nu as a % of the lid
#             speed, N particles across (SPH_LADDER, default 10 20 40 80)
#   slab:     a pinned periodic block, T = 50 + 30 cos(2 pi x / L) decaying by
#             eq. 3.45-3.46 for one e-fold; worst error as a % of the initial
#             amplitude and the decay rate over D k^2, N particles along the
#             wave (SPH_HEAT_LADDER, default 12 24 48 96)
# with the observed order between neighbouring rungs. Output: docs/validation.md,
# section "SPH moving walls and conduction". A few minutes on one core.
set -eu
build=${1:-build/release}
exe="$build/tests/unit_sph_transport"
[ -x "$exe" ] || { echo "no $exe: build first (ninja -C $build)" >&2; exit 2; }
SPH_LADDER="${SPH_LADDER:-10 20 40 80}" SPH_HEAT_LADDER="${SPH_HEAT_LADDER:-12 24 48 96}" OMP_NUM_THREADS=1 \
    "$exe" sph_walls_ladder
