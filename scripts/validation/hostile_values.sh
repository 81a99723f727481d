#!/bin/sh
# The hostile values (#18, helper userview2): every numeric --set parameter of the scenes given (paths under
# scripts/scenes/) at nan, inf, -inf, 1e300, -1e300 and a list of the numbers 1 to 10000, run for 0.002 s of sim
# time, one at a time, niced, OMP_NUM_THREADS=1, each under a 60 s timeout. One tab-separated row a run on stdout:
# scene, parameter, value (LIST for the 10000 numbers), exit status, wall seconds, whether the message names
# "--set PARAM", and the message's first line. scripts/validation/hostile_sets.sh does 0 and -1 over every scene.
# usage: scripts/validation/hostile_values.sh [BUILD_DIR] SCENE...   (e.g. baking/cookies.lua sph/melting_block.lua)
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
build=$here/build/release
case "${1:-}" in */*) [ -d "$1/app" ] && { build=$1; shift; } ;; esac
hearth=$build/app/hearth
export OMP_NUM_THREADS=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
list=$(seq -s, 1 10000)
for scene in "$@"; do
  "$hearth" run "$here/scripts/scenes/$scene" --params > "$tmp/params" 2>&1
  for p in $(sed -nE 's/^  ([A-Za-z_][A-Za-z0-9_]*) = -?[0-9.{][0-9.e+, }-]*([ ,(].*)?$/\1/p' "$tmp/params"); do
    for v in nan inf -inf 1e300 -1e300 LIST; do
      val=$v
      [ "$v" = LIST ] && val=$list
      s0=$(date +%s.%N)
      timeout 60 nice "$hearth" run "$here/scripts/scenes/$scene" --quiet --until 0.002 --out "$tmp/o" --set "$p=$val" \
        > "$tmp/log" 2>&1
      rc=$?
      s1=$(date +%s.%N)
      msg=$(grep -v '^progress' "$tmp/log" | grep -m1 -E 'rror|--set|refus|not|must' | sed "s|$here/||" | cut -c1-200)
      [ -n "$msg" ] || msg=$(tail -1 "$tmp/log" | cut -c1-200)
      named=no
      grep -q -- "--set $p" "$tmp/log" && named=yes
      printf '%s\t%s\t%s\t%s\t%.2f\t%s\t%s\n' "$scene" "$p" "$v" "$rc" "$(echo "$s1 - $s0" | bc)" "$named" "$msg"
      rm -rf "$tmp/o"
    done
  done
done
