#!/bin/sh
# The hostile sweep (#18, helpers userview and setrange): every numeric --set parameter of every 2D shipped scene
# (scripts/scenes/**, a scene whose dim defaults to 2 or that has no dim) at 0 and at -1, run for 0.002 s of sim
# time. Each run is classed by its exit status and message:
#   ran      exit 0
#   named    refused (exit 1 or 2) with a message that names the --set parameter ("--set NAME=" or "--set NAME:")
#   setting  refused by the scene setting or material value of the same name ("h.scene: dx = 0"), not the --set
#   derived  refused, the message naming something else (a quantity the value became)
#   CRASH    any other exit status (a signal, the guard's 3, a timeout's 124)
# usage: scripts/validation/hostile_sets.sh [BUILD_DIR] [OUT.tsv]   (one run at a time; niced; OMP_NUM_THREADS=1)
set -u
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$here/build/release}
out=${2:-hostile_sets.tsv}
hearth=$build/app/hearth
export OMP_NUM_THREADS=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
printf 'scene\tparam\tvalue\texit\tclass\tmessage\n' > "$out"
for scene in $(cd "$here" && find scripts/scenes -name '*.lua' | sort); do
  "$hearth" run "$here/$scene" --params > "$tmp/params" 2>&1 || { printf '%s\t-\t-\t-\tCRASH\t--params failed\n' "$scene" >> "$out"; continue; }
  # a 3D-only scene (dim's default 3) is left out, as userview did
  if grep -Eq '^  dim = 3' "$tmp/params"; then continue; fi
  # numeric parameters: "  name = 0.005" or "  name = 0.005 (...)" as --params lists them
  for p in $(sed -nE 's/^  ([A-Za-z_][A-Za-z0-9_]*) = -?[0-9.][0-9.e+-]*([ ,(].*)?$/\1/p' "$tmp/params"); do
    for v in 0 -1; do
      timeout 300 nice "$hearth" run "$here/$scene" --quiet --until 0.002 --out "$tmp/o" --set "$p=$v" \
        > "$tmp/log" 2>&1
      rc=$?
      msg=$(grep -m1 -E '^hearth( run)?:|rror' "$tmp/log" | sed "s|$here/||" | cut -c1-220)
      [ -n "$msg" ] || msg=$(tail -1 "$tmp/log" | cut -c1-220)
      if [ $rc -eq 0 ]; then class=ran
      elif [ $rc -eq 1 ] || [ $rc -eq 2 ]; then
        if grep -Eq -- "--set $p(=|:| )" "$tmp/log"; then class=named
        else class=derived; fi
      else class=CRASH; fi
      printf '%s\t%s\t%s\t%s\t%s\t%s\n' "$scene" "$p" "$v" "$rc" "$class" "$msg" >> "$out"
      rm -rf "$tmp/o"
    done
  done
done
printf 'runs %s: ' "$(($(wc -l < "$out") - 1))"
cut -f5 "$out" | tail -n +2 | sort | uniq -c | tr '\n' ' '
echo
