#!/usr/bin/env bash
# fields_off_overhead.sh REV [CELLS]: what the optional fields' code costs a
# momentum-only step when they are off. Builds REV (a commit from before the
# code in question) and the working tree without -march=native (valgrind
# does not decode AVX-512), then counts instructions per step of the 3D
# `hearth bench` block with callgrind: the difference between a 1-step and a
# 10-step run, divided by 9, so setup cancels. Instruction counts are exact
# and repeatable where wall time on a shared machine is not.
#   scripts/bench/fields_off_overhead.sh 09d4b28     # before water, boundary, mixing and SPH
set -euo pipefail
rev=${1:?usage: fields_off_overhead.sh REV [CELLS]} cells=${2:-32}
root=$(cd "$(dirname "$0")/../.." && pwd)
command -v valgrind >/dev/null || { echo "fields_off_overhead: needs valgrind" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'git -C "$root" worktree remove --force "$tmp/old" >/dev/null 2>&1 || true; rm -rf "$tmp"' EXIT
git -C "$root" worktree add -q --detach "$tmp/old" "$rev"
for tree in "$tmp/old" "$root"; do
    [ -f "$tree/build/nn/build.ninja" ] || meson setup "$tree/build/nn" "$tree" --buildtype=release -Dnative=false >/dev/null
    ninja -C "$tree/build/nn" >/dev/null
done
count() { # count HEARTH STEPS -> instructions
    OMP_WAIT_POLICY=passive OMP_NUM_THREADS=1 valgrind --tool=callgrind --callgrind-out-file=/dev/null \
        "$1" bench --threads 1 --cells "$cells" --steps "$2" --dim 3 2>&1 | awk '/refs/ {gsub(",", "", $NF); print $NF}'
}
per_step() { python3 -c "print(($(count "$1" 10) - $(count "$1" 1)) / 9)"; }
old=$(per_step "$tmp/old/build/nn/app/hearth")
new=$(per_step "$root/build/nn/app/hearth")
python3 -c "print('instructions per step: %s %.4g, now %.4g, ratio %.4f' % ('$rev', $old, $new, $new / $old))"
