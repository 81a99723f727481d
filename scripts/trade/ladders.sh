#!/usr/bin/env bash
# scripts/trade/ladders.sh [--full] [--hearth PATH] [--out DIR] [--jobs N]
# The default speed/accuracy ladders of the shipped scenes (hearth trade).
# Without --full: the quick ladders CI runs (seconds), into a temp folder unless --out.
# With --full: every ladder, results into docs/trade/<ladder>/ (trade.csv, trade.png)
# unless --out; docs/trade/README.md says what they show.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
full=0 hearth="$root/build/release/app/hearth" out="" jobs=2
while [ $# -gt 0 ]; do
    case $1 in
        --full) full=1 ;;
        --hearth) hearth=$2; shift ;;
        --out) out=$2; shift ;;
        --jobs) jobs=$2; shift ;;
        *) echo "ladders.sh: unknown option '$1'; usage: ladders.sh [--full] [--hearth PATH] [--out DIR] [--jobs N]" >&2; exit 2 ;;
    esac
    shift
done
[ -x "$hearth" ] || { echo "ladders.sh: no hearth at $hearth (build first, or pass --hearth)" >&2; exit 2; }
if [ -z "$out" ]; then
    if [ $full = 1 ]; then out="$root/docs/trade"; else out=$(mktemp -d); trap 'rm -rf "$out"' EXIT; fi
fi
scenes="$root/scripts/scenes" trade="$root/scripts/trade"
# The heat slab's exact centre temperature at Fo = 0.5 (see heat_slab.lua)
slab_ref="analytic:120 - 100 * 0.7725263834238096^2"

ladder() { # name, then hearth trade arguments; LADDERS="a b" runs only those
    local name=$1; shift
    if [ -n "${LADDERS:-}" ] && [[ " $LADDERS " != *" $name "* ]]; then return 0; fi
    echo "== ladder $name ==" >&2
    mkdir -p "$out/$name"
    "$hearth" trade "$@" --jobs "$jobs" --out "$out/$name/work" >"$out/$name/table.txt" || status=1
    sed -i "/^wrote /d" "$out/$name/table.txt"
    cat "$out/$name/table.txt"
    cp "$out/$name/work/trade.csv" "$out/$name/work/trade.png" "$out/$name/"
    rm -rf "$out/$name/work"
}
status=0
if [ $full = 0 ]; then
    ladder heat_slab_quick "$trade/heat_slab.lua" --metric centre_temperature --knob dx=0.004,0.002 \
        --knob heat=explicit --reference "$slab_ref" --quiet
    exit $status
fi
# explicit vs implicit heat x dx at one small fixed step (dt_max caps both)
ladder heat_slab_dx "$trade/heat_slab.lua" --metric centre_temperature --knob dx=0.004,0.002,0.001 \
    --knob heat=explicit,implicit --set dt_max=0.05 --reference "$slab_ref"
# each at its own step: explicit at min(its stability limit ~ dx^2, 1 s), implicit at 1 s
ladder heat_slab_large_dt "$trade/heat_slab.lua" --metric centre_temperature --knob dx=0.004,0.002,0.001 \
    --knob heat=explicit,implicit --set dt_max=1 --reference "$slab_ref"
# implicit heat in time at fixed dx (backward Euler), against the finest step
ladder heat_slab_dt "$trade/heat_slab.lua" --metric centre_temperature --knob dt_max=1,0.5,0.25,0.125,0.0625 \
    --set heat=implicit --set dx=0.002
# the cookie's height after it lands: dx x ppc in 2D, then 2D against 3D
ladder cookie_height "$scenes/cookie_cutter.lua" --metric height --knob dx=0.03125,0.015625,0.0078125 \
    --knob ppc=4,9 --until 0.4
ladder cookie_spread "$scenes/cookie_cutter.lua" --metric spread --knob dx=0.03125,0.015625,0.0078125 \
    --knob ppc=4,9 --until 0.4
ladder cookie_dim "$scenes/cookie_cutter.lua" --metric height --knob dx=0.03125,0.015625 --knob dim=2,3 \
    --set ppc=8 --until 0.4
# the dam break's front position (newtonian syrup): dx
ladder dam_break_front "$scenes/dam_break.lua" --metric front --knob dx=0.04,0.02,0.01,0.005 --until 0.3
# the 50:50 mayo/honey front down the slope after 1 s: dx x blend mode (Nagasawa et al. Fig. 1)
ladder nozzle_front "$scenes/sauces/nozzle.lua" --metric front --knob dx=0.005,0.0025,0.00125 \
    --knob blend=nonlinear,linear --set ratios=0.5 --set png=false
# one cam_clay_dough cookie in a 150 degC oven: its height after 3 s, dx (Ding et al. Fig. 3)
ladder cookie_dough_height "$scenes/baking/cookies.lua" --metric height --knob dx=0.01,0.005,0.0025 \
    --set ovens=150 --set leaveners=0.0075
# the same maxwell_sph dough under MPM and SPH: its height after 0.5 s, dx x solver
ladder dough_solver "$trade/dough_solver.lua" --metric height --knob dx=0.008,0.004,0.002 --knob solver=mpm,sph
exit $status
