#!/usr/bin/env bash
# sph_identical.sh BUILD OUT: the bits a change to the SPH step must keep,
# one line each, into OUT (compare two with diff): the md5 of every frame
# and CSV the seven SPH scenes write in 0.1 s (scripts/scenes/sph/), the
# dam break's particle hash (scripts/bench/sph_dam_break.lua, 5k particles
# in 2D and 8k in 3D, every column) at 1 to 4 threads, and every line the unit_sph tests print.
#   scripts/bench/sph_identical.sh build/release /tmp/before.txt   # on the old commit
#   scripts/bench/sph_identical.sh build/release /tmp/after.txt && diff /tmp/before.txt /tmp/after.txt
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=$(cd "$1" && pwd) out=$2
hearth=$build/app/hearth
export HEARTH_PLUGIN_PATH=$build/plugins HEARTH_TEST_PLUGIN_DIR=$build/tests/plugins HEARTH_SOURCE_ROOT=$root
export OMP_WAIT_POLICY=passive
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
: > "$out.part"
for f in "$root"/scripts/scenes/sph/*.lua; do
    name=$(basename "$f" .lua)
    (cd "$tmp" && OMP_NUM_THREADS=2 "$hearth" run "$f" --until 0.1 --frames 2 --quiet > /dev/null)
    # compare_mpm_sph's compare.csv: its column 2 is CPU seconds, which vary, so it is left out
    [ -f "$tmp/hearth-out/$name/compare.csv" ] && cut -d, -f1,3- "$tmp/hearth-out/$name/compare.csv" > "$tmp/compare.cut" &&
        mv "$tmp/compare.cut" "$tmp/hearth-out/$name/compare.csv"
    (cd "$tmp/hearth-out/$name" && find . -type f \( -name '*.png' -o -name '*.csv' \) | sort | xargs md5sum) |
        sed "s|^|$name |" >> "$out.part"
done
for t in 1 2 3 4; do
    OMP_NUM_THREADS=$t "$hearth" run "$root/scripts/bench/sph_dam_break.lua" --quiet --set dx=0.004 --set steps=6 \
        --set hash=1 | sed "s|^|dam break, $t threads: |" >> "$out.part"
    OMP_NUM_THREADS=$t "$hearth" run "$root/scripts/bench/sph_dam_break.lua" --quiet --set dim=3 --set dx=0.01 \
        --set steps=4 --set hash=1 | sed "s|^|3D dam break, $t threads: |" >> "$out.part"
done
# every SPH core test's printed numbers (the test names from tests/meson.build;
# unit_sph.c was split by topic into these three)
for exe in unit_sph unit_sph_transport unit_sph_bubble; do
    for t in $(sed -n "/'$exe' :/,/\]/p" "$root/tests/meson.build" | grep -o "'sph_[a-z_0-9]*'" | tr -d "'"); do
        # (wall times, which vary, left out)
        (cd "$tmp" && { OMP_NUM_THREADS=2 "$build/tests/$exe" "$t" 2>&1 && echo "exit 0" || echo "exit $?"; } |
            sed -E 's/[0-9.]+ ms/(ms)/g' | sed "s|^|$t: |") >> "$out.part"
    done
done
mv "$out.part" "$out"
