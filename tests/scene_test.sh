#!/usr/bin/env bash
# scene_test.sh SCENE HEARTH SOURCE_ROOT: run a shipped scene for a few frames
# and check it finishes and writes pictures that decode.
here=$(cd "$(dirname "$0")" && pwd) # png_check.py lives here
set -u
name=$1 hearth=$2 root=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
"$hearth" run "$root/scripts/scenes/$name.lua" --until 0.1 --frames 2 --quiet > out.txt 2> err.txt
rc=$?
[ $rc -eq 0 ] || { echo "FAIL: $name exited $rc: $(cat err.txt)" >&2; exit 1; }
out=$(basename "$name") # scenes in subfolders (sph/bread_roll) write to hearth-out/<file name>
n=$(find "hearth-out/$out" -name '*.png' | wc -l)
[ "$n" -ge 3 ] || { echo "FAIL: $name wrote $n PNG frames, expected at least 3" >&2; exit 1; }
for f in $(find "hearth-out/$out" -name '*.png'); do
    python3 "$here/png_check.py" "$f" >/dev/null || { echo "FAIL: $f does not decode" >&2; exit 1; }
done
# every CSV it writes names its time with the unit (t_s; #18, helper userfix6: a bare t gave none), and every other
# column its unit too (#18, helper userfix7: the SPH particle files' T, s:run's kinetic gave none)
csvs=$(find "hearth-out/$out" -name '*.csv' | sort)
if [ -n "$csvs" ]; then
    # shellcheck disable=SC2086 # one argument a file; the names have no spaces
    python3 "$here/scene_csv.py" --units "$root/scripts/scenes/$name.lua" $csvs ||
        { echo "FAIL: $name: a CSV's column gives no unit (above)" >&2; exit 1; }
fi
cat out.txt
echo ok
