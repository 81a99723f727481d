#!/usr/bin/env bash
# lua_user_test.sh CASE HEARTH: what a user reads off a scene run as a user runs it (#18, helper userview4): the SPH
# results lines' real minutes, a missing relative dofile path's folder, h.recipes.surface against h.recipes.height,
# s:run's CSV cells where nothing was measured; a browning picture's crust read back off its pixels (png_pixel.py)
# and a 3D particle picture's title (helper userfix9); a 3D browning picture's cut and a 3D slice's plane (helper
# userfix11); h.load's relative path, read from the output folder (helper userview5); a validation wrapper run from
# another folder, the default scene's water, pull_twist's title and the SPH particle files' empty cells (helper
# userfix10). Shares lua_fixture.sh with lua_test.sh (scene files in tests/lua/).
. "$(dirname "$0")/lua_fixture.sh" "$@"

# legs_scene OUTPUTS: legs.lua, a block run in two legs (--set leg=1 to 0.5 s and saved to ck.bin; --set leg=2
# restored from it, to 1 s), frames every 0.25 s with s:run's OUTPUTS (Lua table fields): the restart cases' scene.
legs_scene() {
    cat >legs.lua <<EOF
local h = require "hearth"
local P = h.params { leg = h.number { 1, min = 1, max = 2, integer = true, what = "which leg" } }
local s
if P.leg == 2 then s = h.load("ck.bin") else
  s = h.scene { dim = 2, dx = 0.05, box = { { 0, 0 }, { 1, 1 } } }
  s:add { shape = h.box({ 0.4, 0.4 }, { 0.6, 0.6 }), material = h.material("elastic", { density = 1000 }) }
end
s:run { until_t = P.leg * 0.5, every = 0.25, $1 }
if P.leg == 1 then s:save("ck.bin") end
EOF
}

case "$case_name" in
sph_results_lines_say_real_minutes)
    # #18 (helper userview4): the SPH bread of the dead's and angel food cake's results lines gave a time in simulated
    # seconds alone ("at t = 1.20 s"; the cake's "1.563 at t = 3.50 s", where its peak said "13 min"), which only
    # the run's first line maps to real minutes. Bar set before the run: each line with a time gives its real
    # minutes beside it (S = 1500 and 1600: 0.04 s is 1 min).
    run ../../scripts/scenes/sph/bread_of_the_dead.lua --until 0.04
    expect_rc 0 "the bread of the dead, 0.04 s"
    has out.txt "above the tray at t = 0.04 s, 1 min" "the volume line's real time"
    [ "$(grep -c '^bread of the dead at t = 0.04 s, 1 min (water true): ' out.txt)" -eq 2 ] ||
        fail "the centre and outer lines' real time: $(grep '^bread of the dead at' out.txt)"
    run ../../scripts/scenes/sph/angel_food_cake.lua --set bake=0.02 --set until_t=0.04
    expect_rc 0 "the angel food cake, 0.04 s"
    has out.txt "at t = 0.04 s, 1 min (mean " "the cake's last volume with its real time"
    grep 'relative volume' out.txt
    ;;
sph_cake_out_of_oven_between_frames)
    # #18 (helpers userview4, userfix8): the angel food cake came out of the oven at its first frame at or past the bake
    # (frames every 0.1 s), so `--set bake=0.02 --set until_t=0.04`, no frame between, stayed in the oven to 0.04 s
    # and its line said "still in the oven: the bake ends at 0.02 s". Bar set before the run: the line gives the
    # volume "as the bake ends", not "still in the oven", the bake's-end line is printed and particles_baked.csv is
    # written.
    run ../../scripts/scenes/sph/angel_food_cake.lua --set bake=0.02 --set until_t=0.04 --out o
    expect_rc 0 "the angel food cake, bake 0.02 s of 0.04 s"
    grep 'relative volume' out.txt
    has out.txt " as the bake ends), " "the volume as the bake ends"
    grep -q "still in the oven" out.txt && fail "the line says the cake is still in the oven at 0.04 s"
    has out.txt "angel food cake as the bake ends: crumb band" "the bake's-end line"
    [ -s o/particles_baked.csv ] || fail "no particles_baked.csv"
    ;;
bread_two_slits_read_alike_at_start)
    # #18 (helpers userview4, userfix8): bread.csv's first row read the two-slit loaf's slits 2.70 and 0 mm: the gap's
    # line, a third of the slit depth below the lower shoulder of the dome beside each off-crown slit, lay at the slits'
    # floor (69.8 mm against 70), so the floor particles' jitter opened one and shut the other. The slits are cut
    # alike (mirror images on the seeding lattice: 4 columns each). Bar (set after reading the t = 0 rows, 6.75 and
    # 6.75 mm; only=3 6.45 and 6.75): at t = 0 both read open (> 0) and within one particle spacing (dx / 2 = 2.5 mm)
    # of each other, for all three loaves and for only=3 (another jitter draw).
    for only in 0 3; do
        run ../../scripts/scenes/baking/bread.lua --set only=$only --until 0.001 --out o$only
        expect_rc 0 "bread.lua only=$only, 1 ms"
        python3 - o$only/bread.csv <<'PY' || fail "only=$only: the two slits' gaps at t = 0 (above)"
import csv, sys
r = next(csv.DictReader(open(sys.argv[1])))
a, b = float(r["gap_two_slits_left_m"]), float(r["gap_two_slits_right_m"])
print(f"t = {r['t_s']} s: left {a * 1e3:.2f} mm, right {b * 1e3:.2f} mm (need both > 0, within 2.5 mm)")
sys.exit(0 if a > 0 and b > 0 and abs(a - b) <= 0.0025 else 1)
PY
    done
    ;;
checkpoint_relative_path_says_folder)
    # #18 (helper userview5): restarting another run's checkpoint, h.load("o/ck.bin") stopped with
    # "o3/o/ck.bin: cannot open checkpoint (No such file or directory)": h.load reads a relative path from the
    # output folder, where dofile reads one from the current folder, and nothing said so. Bar set before the
    # run: a missing relative path fails (exit 1) naming the path and that it is read from the output folder; a
    # missing absolute one fails without that remark.
    printf 'local h = require "hearth"\nh.load("other/ck.bin")\n' >rel.lua
    "$hearth" run rel.lua --quiet --out o >out.txt 2>err.txt
    rc=$?
    expect_rc 1 "a missing relative checkpoint"
    has_msg "o/other/ck.bin: cannot open checkpoint" "the path"
    has_msg "(h.load reads a relative path from the output folder, o, where s:save writes" "the folder searched"
    printf 'local h = require "hearth"\nh.load("%s/no_such.bin")\n' "$PWD" >abs.lua
    "$hearth" run abs.lua --quiet --out o >out.txt 2>err.txt
    rc=$?
    expect_rc 1 "a missing absolute checkpoint"
    has_msg "$PWD/no_such.bin: cannot open checkpoint" "the absolute path"
    grep -q "relative path" err.txt && fail "an absolute path said to be relative: $(cat err.txt)"
    ;;
checkpoint_csv_units_after_load)
    # #18 (helper userview5): a 2D scene restored by h.load wrote s:run's CSV with kinetic_J, the 3D column, where
    # the same scene before the save wrote kinetic_J_per_m (h._adopt left the scene's dim unset). Bar set before
    # the run: the loaded scene's header says kinetic_J_per_m in 2D and kinetic_J in 3D, as h.scene's does.
    for d in 2 3; do
        z0='' z1='' z2=''
        [ $d = 3 ] && z0=', 0' z1=', 1' z2=', 0.4'
        cat >save$d.lua <<EOF
local h = require "hearth"
local s = h.scene { dim = $d, dx = 0.05, box = { { 0, 0$z0 }, { 1, 1$z1 } } }
s:add { shape = h.box({ 0.4, 0.4$z2 }, { 0.6, 0.6$z1 }), material = h.material("elastic", { density = 1000 }) }
s:save("ck$d.bin")
local r = h.load("ck$d.bin")
r:run { until_t = 0.01, csv = "loaded$d.csv" }
EOF
        "$hearth" run save$d.lua --quiet --out o >out.txt 2>err.txt
        rc=$?
        expect_rc 0 "a ${d}D scene saved, loaded and run"
    done
    head -1 o/loaded2.csv | grep -q ",kinetic_J_per_m," || fail "2D after h.load: $(head -1 o/loaded2.csv)"
    head -1 o/loaded3.csv | grep -q ",kinetic_J," || fail "3D after h.load: $(head -1 o/loaded3.csv)"
    ;;
checkpoint_vtu_series_continues)
    # #18 (helper userview5): a scene resumed by h.load with the same s:run{vtu = ...} numbered its frames from 0
    # again, over the first leg's files, and its .pvd listed the second leg alone. Bar set before the run: after
    # a leg to 0.5 s (frames every 0.25 s) and a restored leg to 1 s, the .pvd lists b_0000..b_0004 at 0, 0.25,
    # 0.5, 0.75 and 1 s, and the first leg's b_0000.vtu and b_0001.vtu are untouched; a new scene (not restored)
    # into the same folder starts the series afresh, as before.
    legs_scene 'vtu = { path = "vtu/b_%04d.vtu" }'
    "$hearth" run legs.lua --quiet --out o --set leg=1 >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "the first leg"
    cp o/vtu/b_0000.vtu first0.vtu && cp o/vtu/b_0001.vtu first1.vtu || fail "the first leg's frames: $(ls o/vtu)"
    "$hearth" run legs.lua --quiet --out o --set leg=2 >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "the restored leg"
    got=$(sed -n 's/.*timestep="\([^"]*\)".*file="\([^"]*\)".*/\1 \2/p' o/vtu/b.pvd | tr '\n' ';')
    want="0 b_0000.vtu;0.25 b_0001.vtu;0.5 b_0002.vtu;0.75 b_0003.vtu;1 b_0004.vtu;"
    [ "$got" = "$want" ] || fail "the .pvd after the restored leg: $got, expected $want"
    cmp -s first0.vtu o/vtu/b_0000.vtu && cmp -s first1.vtu o/vtu/b_0001.vtu ||
        fail "the restored leg wrote over the first leg's frames"
    "$hearth" run legs.lua --quiet --out o --set leg=1 >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "a new first leg"
    [ "$(grep -c '<DataSet' o/vtu/b.pvd)" -eq 3 ] || fail "a new scene's .pvd: $(cat o/vtu/b.pvd)"
    ;;
checkpoint_frames_and_csv_continue)
    # #18 (helper restartkeep): after h.load, s:run's PNG frames and PLY dumps were numbered from 0 again over the
    # first leg's files and its CSV started afresh (only the VTU series continued). Bar set before the test's first
    # run (a hand trial of the same two legs had been looked at): after a leg to 0.5 s (frames every 0.25 s) and a
    # restored leg to 1 s in a new process, png/f_0000..f_0004 and ply/p_0000..p_0004 are there and no sixth of
    # either; the first leg's files before the checkpoint (f_0000, f_0001, p_0000, p_0001) are byte-unchanged; frame
    # 3 is drawn at 0.75 s (its title's time, its PLY's t), and frame 2, at the checkpoint's instant, is the second
    # leg's (its Source names leg=2), as the VTU series does; series.csv has one header and t_s 0, 0.25, 0.5, 0.75, 1
    # in that order. A new scene (not restored) into the same folder starts its CSV afresh, as before. The first run
    # failed on this script's listing (ls sorts its arguments: ply before png), fixed; the bar is unchanged.
    legs_scene 'csv = "series.csv", png = { field = "speed", path = "png/f_%04d.png" },
  ply = { path = "ply/p_%04d.ply" }'
    "$hearth" run legs.lua --quiet --out o --set leg=1 >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "the first leg"
    mkdir first && cp o/png/f_0000.png o/png/f_0001.png o/ply/p_0000.ply o/ply/p_0001.ply first/ ||
        fail "the first leg's files: $(ls o/png o/ply)"
    "$hearth" run legs.lua --quiet --out o --set leg=2 >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "the restored leg"
    got="$(cd o && { ls png; ls ply; } | tr '\n' ' ')"
    want="f_0000.png f_0001.png f_0002.png f_0003.png f_0004.png"
    want="$want p_0000.ply p_0001.ply p_0002.ply p_0003.ply p_0004.ply "
    [ "$got" = "$want" ] || fail "the files after the restored leg: $got, expected $want"
    for f in f_0000.png f_0001.png; do cmp -s first/$f o/png/$f || fail "the restored leg wrote over $f"; done
    for f in p_0000.ply p_0001.ply; do cmp -s first/$f o/ply/$f || fail "the restored leg wrote over $f"; done
    python3 "$here/png_title.py" o/png/f_0003.png >title.txt || fail "png_title.py: $(cat title.txt)"
    has title.txt "t = 0.75 s" "frame 3's time"
    python3 "$here/png_title.py" --key Source o/png/f_0002.png >title.txt || fail "png_title.py: $(cat title.txt)"
    has title.txt " --set leg=2 (hearth " "frame 2 at the checkpoint, drawn by the second leg"
    head -c 200 o/ply/p_0003.ply | grep -qa "^comment hearth t=0.75$" ||
        fail "p_0003.ply's time: $(head -c 200 o/ply/p_0003.ply)"
    [ "$(grep -c '^t_s,' o/series.csv)" -eq 1 ] || fail "series.csv's headers: $(cat o/series.csv)"
    got=$(sed 1d o/series.csv | cut -d, -f1 | tr '\n' ' ')
    [ "$got" = "0 0.25 0.5 0.75 1 " ] || fail "series.csv's t_s after the restored leg: $got; $(cat o/series.csv)"
    "$hearth" run legs.lua --quiet --out o --set leg=1 >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "a new first leg"
    got=$(sed 1d o/series.csv | cut -d, -f1 | tr '\n' ' ')
    [ "$got" = "0 0.25 0.5 " ] || fail "a new scene's series.csv: $got"
    ;;
png_source_names_demo_and_rheometer)
    # #18 (helper restartkeep): only hearth run's PNGs carried the "Source" text (the command line and version);
    # the demo's frames, the dashboard's slices and the trade and rheometer plots did not. Bar set before the test's
    # first run: hearth demo's frame and hearth rheometer's flow curve each name their own command line and
    # hearth's version and revision.
    "$hearth" demo --out d --until 0.005 --frames 1 --quiet >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "hearth demo"
    src=$(python3 "$here/png_title.py" --key Source d/frame_0000.png) || fail "png_title.py: $src"
    case "$src" in
    *": hearth demo --out d --until 0.005 --frames 1 --quiet (hearth "*", revision "*) ;;
    *) fail "the demo frame's Source text: $src" ;;
    esac
    "$hearth" rheometer sauce.honey --rates 1:10:3 --out r >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "hearth rheometer"
    src=$(python3 "$here/png_title.py" --key Source r/sauce.honey.png) || fail "png_title.py: $src"
    case "$src" in
    *": hearth rheometer sauce.honey --rates 1:10:3 --out r (hearth "*", revision "*) ;;
    *) fail "the flow curve's Source text: $src" ;;
    esac
    ;;
drop_block_energy_line_unit)
    # #18 (helper userview5): drop_block.lua's last line said "kinetic energy 77.4 J" in 2D, where its height.csv
    # says kinetic_J_per_m (a plane scene's mass is per metre of depth). Bar set before the run: the 2D line says
    # J per metre of depth, the 3D line J.
    run ../../scripts/scenes/drop_block.lua --until 0.002
    expect_rc 0 "drop_block.lua in 2D"
    grep -q "^after the drop: t = .* kinetic energy .* J per metre of depth$" out.txt || fail "2D: $(cat out.txt)"
    run ../../scripts/scenes/drop_block.lua --until 0.002 --set dim=3
    expect_rc 0 "drop_block.lua in 3D"
    grep -q "^after the drop: t = .* kinetic energy [^ ]* J$" out.txt || fail "3D: $(cat out.txt)"
    ;;
png_source_names_run)
    # #18 (helper userview5): a PNG frame said its time, step, field and unit, but not which scene and settings drew
    # it (run.json beside it does; a frame copied into a paper's folder lost that). Bar set before the run: a
    # `hearth run` frame carries a "Source" text with the command line (the scene and each --set) and hearth's
    # version.
    run ../../scripts/scenes/drop_block.lua --until 0.002 --set stiffness=2e4 --out o
    expect_rc 0 "drop_block.lua"
    src=$(python3 "$here/png_title.py" --key Source o/frames/speed_0000.png) || fail "png_title.py: $src"
    echo "$src"
    case "$src" in
    *": hearth run "*"drop_block.lua --quiet --until 0.002 --set stiffness=2e4 --out o (hearth "*", revision "*) ;;
    *) fail "the frame's Source text: $src" ;;
    esac
    ;;
dofile_relative_path_says_folder)
    # #18 (helper userview4): scripts/validation/loaf_whatif.lua (and crack_heat, crack_dt, crack_tray, muffin_tear,
    # bread3d) run their scene by a path from the source root; started elsewhere they stopped with "cannot open
    # scripts/scenes/...: No such file or directory" alone. Bar set before the run: a scene's dofile of a missing
    # relative path fails (exit 1) naming the path and the folder it was read from; an absolute one as before.
    run dofile_relative.lua
    expect_rc 1 "a missing relative path"
    has_msg "cannot open scripts/scenes/baking/no_such_scene.lua" "the path"
    has_msg "(a relative path is read from the folder hearth runs in, $(pwd -P)" "the folder searched"
    printf 'dofile("%s/no_such.lua")\n' "$PWD" >abs.lua
    "$hearth" run abs.lua --quiet >out.txt 2>err.txt
    rc=$?
    expect_rc 1 "a missing absolute path"
    has_msg "cannot open $PWD/no_such.lua" "the absolute path"
    grep -q "relative path" err.txt && fail "an absolute path said to be relative: $(cat err.txt)"
    ;;
validation_wrapper_finds_scene_anywhere)
    # #18 (helper userfix10; userview4's item 9): scripts/validation/loaf_whatif.lua (and crack_heat, crack_dt,
    # crack_tray, muffin_tear, bread3d) named their scene from the source root, so `hearth run /abs/path/...` from
    # another folder stopped at their dofile. Bar set before the run: from a temp folder, loaf_whatif.lua by its
    # absolute path (2 real s of the bake) exits 0 and writes loaf.csv; crack_tray.lua likewise (1 ms of bread.lua)
    # writes bread.csv; --set loaf=PATH relative to the working folder still runs (exit 0); h.scene_path keeps an
    # absolute path and joins a relative one to the scene file's folder.
    root=$(cd "$here/.." && pwd)
    "$hearth" run "$root/scripts/validation/loaf_whatif.lua" --quiet --set until_real=2 --out w >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "loaf_whatif.lua by its absolute path from $(pwd)"
    [ -s w/loaf.csv ] || fail "loaf_whatif.lua wrote no loaf.csv"
    "$hearth" run "$root/scripts/validation/crack_tray.lua" --quiet --until 0.001 --out c >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "crack_tray.lua by its absolute path"
    [ -s c/bread.csv ] || fail "crack_tray.lua wrote no bread.csv"
    mkdir -p sub && ln -s "$root/scripts/scenes/baking/loaf_physical.lua" sub/loaf.lua
    "$hearth" run "$root/scripts/validation/loaf_whatif.lua" --quiet --set until_real=2 --set loaf=sub/loaf.lua \
        --out l >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "--set loaf=sub/loaf.lua, relative to the working folder"
    [ -s l/loaf.csv ] || fail "--set loaf=PATH wrote no loaf.csv"
    mkdir -p d && printf '%s\n' 'local h = require "hearth"' \
        'print(h.scene_path("a/b.lua"), h.scene_path("/x/y.lua"))' >d/p.lua
    "$hearth" run d/p.lua --quiet >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "h.scene_path"
    has out.txt "d/a/b.lua	/x/y.lua" "a relative path joined to the scene's folder, an absolute one kept"
    ;;
default_scene_water_sourced)
    # #18 (helper userfix10; userview4's item 11): the dashboard's default scene (assets/cookie_bake.lua) gave its
    # cookie water of invented numbers (diffusivity 2e-8, evaporation 2e-6, saturation 0.4, "so the saturation view has
    # something to show"). Bar set before the run, from the sources the scene names, not from its code: the physical
    # cookie's real water (lua/hearth/dough_physical.lua: D 1e-9 m^2/s, beta^w 1.2e-5 kg/(m^2 s K)) on the water clock
    # W = 660 s / 5 s = 132 (its 11 minute bake for cookies.lua's paper 5 s), at the paper cookie's s_0 = 0.20 x 500 /
    # 1000 = 0.10: K = D / (373.15 s_0) W = 3.53745e-09, beta^w W = 0.001584, each within 1e-5 relative.
    run cookie_water.lua --until 0.001
    expect_rc 0 "cookie_bake.lua"
    grep '^water ' out.txt
    python3 - out.txt <<'PY' || fail "the default scene's water is not the sourced one (above)"
import sys
line = next(l for l in open(sys.argv[1]) if l.startswith("water "))
w = line.split()
got = {w[k]: float(w[k + 1]) for k in range(1, len(w), 2)}
W, s0 = 660 / 5, 0.20 * 500 / 1000
want = {"saturation": s0, "water_diffusivity": 1e-9 / (373.15 * s0) * W, "evaporation": 1.2e-5 * W}
bad = [k for k in want if abs(got[k] / want[k] - 1) > 1e-5]
print("want", want, "bad", bad)
sys.exit(1 if bad else 0)
PY
    ;;
pull_twist_title_gives_eta_unit)
    # #18 (helper userfix10; userview4's item 10): pull_twist.lua's frames and lines gave eta without its unit (the
    # plugin's Pa^3 s, pull_twist.csv's eta_Pa3s): with it the label passed the picture label's 64 bytes
    # (HEARTH_PICTURE_LABEL_MAX, from when a title was one line) and fell back to its short form. Bar set before the
    # run: at its defaults (1 ms of it) j_0000.png's Title text gives "tau_y 300, 1000, 3000 Pa across; eta 1e+06,
    # 1e+08, 1e+10 Pa^3 s up" and each dough's line "eta <value> Pa^3 s".
    run ../../scripts/scenes/baking/pull_twist.lua --until 0.001 --out p
    expect_rc 0 "pull_twist.lua, 1 ms"
    title=$(python3 "$here/png_title.py" p/j_0000.png)
    echo "$title"
    echo "$title" | grep -qF "tau_y 300, 1000, 3000 Pa across; eta 1e+06, 1e+08, 1e+10 Pa^3 s up" ||
        fail "the title does not give eta with its unit: $title"
    [ "$(grep -cE '^tau_y +[0-9]+ Pa, eta +[0-9e+.]+ Pa\^3 s: ' out.txt)" -eq 9 ] ||
        fail "not every dough's line gives eta's unit: $(cat out.txt)"
    ;;
sph_particles_unmeasured_empty)
    # #18 (helper userfix10; userview4's item 13): the SPH particle files (bread_of_the_dead.lua's particles_*.csv,
    # angel_food_cake.lua's) wrote `nan` for a bubble's browning and saturation, where the project's rule is an empty
    # cell for what was not measured. Bars set before the run: h.write writes a `nan` or `-nan` cell of a .csv empty
    # (a .txt as given; a cell that only holds the letters, "banana", as given); both scenes' particle files (0.04 s of
    # each) hold no `nan`, keep tests/scene_csv.py's cell rule (empty cells only in the columns each declares) and have
    # empty browning cells (their bubbles); their readers (sph_crumb_measure.py, sph_cake_rise.py) measure them.
    run csv_nan_empty.lua --out w
    expect_rc 0 "h.write of nan cells"
    printf 'a_m,b_m\n1,\n,2\n,banana\n' | cmp -s - w/x.csv || fail "x.csv: $(cat w/x.csv)"
    grep -q "nan" w/x.txt || fail "x.txt lost its nan: $(cat w/x.txt)"
    root=$(cd "$here/.." && pwd)
    run ../../scripts/scenes/sph/bread_of_the_dead.lua --until 0.04 --out d
    expect_rc 0 "the bread of the dead, 0.04 s"
    run ../../scripts/scenes/sph/angel_food_cake.lua --set bake=0.02 --set until_t=0.04 --out c
    expect_rc 0 "the angel food cake, 0.04 s"
    for f in d/particles_0000.csv d/particles_end.csv c/particles_raw.csv c/particles_end.csv; do
        sc=$root/scripts/scenes/sph/bread_of_the_dead.lua
        case $f in c/*) sc=$root/scripts/scenes/sph/angel_food_cake.lua ;; esac
        grep -qi "nan" "$f" && fail "$f holds nan: $(grep -m1 -i nan "$f")"
        python3 "$here/scene_csv.py" "$f" "$sc" || fail "$f breaks the cells' rule"
        python3 - "$f" <<'PY' || fail "$f: no empty browning cell (its bubbles)"
import csv, sys
n = sum(1 for r in csv.DictReader(open(sys.argv[1])) if r["browning"] == "")
print(f"{sys.argv[1]}: {n} empty browning cells")
sys.exit(0 if n > 0 else 1)
PY
    done
    python3 "$here/sph_crumb_measure.py" 0.006 d/particles_0000.csv d/particles_end.csv || fail "sph_crumb_measure.py"
    python3 "$here/sph_cake_rise.py" 0.003 0 c/particles_raw.csv c/particles_end.csv || fail "sph_cake_rise.py"
    ;;
recipes_surface_below_a_gap)
    # #18 (helper userview4): celery_dip.lua's "sauce surface" was h.recipes.height, the highest material on the line,
    # which read the drops on the lifted celery (0.0711 m for a bath ~25 mm deep). h.recipes.surface reads the top
    # of the lowest material. Bars set before the run (dx 1/64 m, the probe's kernel reaches ~dx/2 past a face):
    # a 0.2 m block on y0 with a blob at 0.5-0.6 above a gap: surface 0.2 +- 2 dx, height 0.5 +- 2 dx; an empty
    # line 0.
    run surface.lua
    expect_rc 0 "the block and the blob"
    cat out.txt
    python3 - out.txt <<'PY' || fail "h.recipes.surface / height (numbers above)"
import re, sys
t = open(sys.argv[1]).read()
hgt, srf = map(float, re.search(r"height=([0-9.]+) surface=([0-9.]+)", t).groups())
empty = float(re.search(r"empty=([0-9.]+)", t).group(1))
dx = 1 / 64
ok = abs(srf - 0.2) <= 2 * dx and abs(hgt - 0.5) <= 2 * dx and empty == 0
sys.exit(0 if ok else 1)
PY
    ;;
csv_negative_zero_written_0)
    # #18 (helpers userview4, userfix8): loaf.csv's base_gap_m read -0.000000 at t = 0 (%.6f of a negative zero) and
    # the roll's trace_NNNN.csv wrote -0 pressures. Bar set before the run: every CSV cell that is a negative zero
    # (-0.000000, -0, -0.000e+00, -0.00) is written 0 (0.000000, 0, ...); -0.5 and a text cell "-0 km" stay; a file
    # that is not a CSV is left as the scene wrote it.
    run csv_negative_zero.lua --out o
    expect_rc 0 "csv_negative_zero.lua"
    cat o/zeros.csv
    printf 'a_m,b_Pa,c_1,d_m,e\n0.000000,0,0.000e+00,0.000000,-0 km\n0.000000,0,0.00,-0.5,x\n' >want.csv
    cmp -s o/zeros.csv want.csv || fail "zeros.csv (above) is not want.csv: $(cat want.csv)"
    has o/note.txt "-0.000000" "a text file left as written"
    ;;
scene_dx_past_box_exit2)
    # #18 (helpers userview4, userfix8): `--set dx=1` on a scene's own dx reached the core's box check, "box axis x
    # spans [0, 0.14] m; it must be at least 6 dx = 6 m long" (exit 1, a scene error blaming the box). Bar set before
    # the run: exit 2 (a usage error) at the scene's line naming --set dx=1, dx and the range its box takes (the
    # shortest axis / 6), for three scenes' declared dx (loaf_physical.lua, bread_roll.lua, dam_break.lua).
    run ../../scripts/scenes/baking/loaf_physical.lua --set dx=1
    expect_rc 2 "loaf_physical.lua --set dx=1"
    has_msg "loaf_physical.lua:" "the scene's file"
    has_msg "--set dx=1: dx (the grid spacing) takes a number in (0, 0.02333333333] m in this scene, not 1: its box's x axis spans 0.14 m" "the loaf's dx and its range"
    run ../../scripts/scenes/sph/bread_roll.lua --set dx=0.05
    expect_rc 2 "bread_roll.lua --set dx=0.05"
    has_msg "--set dx=0.05: dx (the grid spacing) takes a number in (0, 0.02] m in this scene, not 0.05: its box's y axis spans 0.12 m" "the roll's dx and its range"
    run ../../scripts/scenes/dam_break.lua --set dx=0.2
    expect_rc 2 "dam_break.lua --set dx=0.2"
    has_msg "dx (the grid spacing) takes a number in (0, 0.1] m in this scene" "the dam break's dx"
    ;;
run_csv_probe_outside_empty)
    # #18 (helper userview4): s:run{csv = ...} wrote "nan" for a probe outside the material (drop_block.lua's
    # height.csv, speed_m_s@0.5:0.2:0, once the block had fallen past it), where the shipped scenes write an empty
    # cell for "not measured" (tests/scene_csv.py). Bar set before the run: the outside probe's cells are empty in
    # every row, the inside one's are numbers (40 degC), no cell reads nan.
    run run_csv_outside.lua --out o
    expect_rc 0 "run_csv_outside.lua"
    cat o/series.csv
    python3 - o/series.csv <<'PY' || fail "series.csv's probe cells (above)"
import csv, sys
rows = list(csv.reader(open(sys.argv[1])))
head, body = rows[0], rows[1:]
i, o = head.index("temperature_degC@0.45:0.45:0"), head.index("temperature_degC@0.9:0.9:0")
ok = len(body) == 3 and all(r[o] == "" for r in body) and all(abs(float(r[i]) - 40) < 1 for r in body)
ok = ok and not any("nan" in c for r in body for c in r)
sys.exit(0 if ok else 1)
PY
    ;;
browning_picture_shows_crust)
    # #18 (helpers userview4, userfix9): s:png("browning", path) drew a slice, which averaged the one-particle crust with
    # the crumb under it: the physical pancake's browning.png drew its top pale while its line gave 0.247. Bar set
    # before the run: at the top particle's centre on the centre line, the picture's colour read back against the
    # browning colour map (tests/png_pixel.py, the nearest of 101 colours) is within 0.05 of that particle's browning.
    run browning_picture.lua
    expect_rc 0 "the browned block"
    cat out.txt | cut -c1-100
    b=$(awk '/^top particle/{print $NF}' out.txt)
    r=$(python3 "$here/png_pixel.py" hearth-out/browning_picture/browning.png $(awk '/^pixel/{print $2, $3}' out.txt) \
        "$(sed -n 's/^map //p' out.txt)") || fail "png_pixel.py: $r"
    echo "$r"
    t=$(echo "$r" | awk '/^reads/{print $2}')
    awk -v b="$b" -v t="$t" 'BEGIN { d = t - b; exit !(b != "" && t != "" && d <= 0.05 && d >= -0.05) }' ||
        fail "the crust reads $t in the picture, its particle $b"
    echo "crust particle $b, picture reads $t"
    ;;
particles_3d_title_says_projection)
    # #18 (helpers userview4, userfix9): a 3D particle picture draws every depth over each other, the nearest on top,
    # under a title like the 2D one's: muffins.lua --set dim=3 drew each cup's wall twice (its front and its middle).
    # Bar set before the run: the Title text of a 3D particle picture (s:png's and s:run's frame) ends with "seen along
    # -z"; a 2D particle picture's and a slice's (2D, 3D) say no "seen along".
    run projection_title.lua --until 0.002
    expect_rc 0 "the jelly blocks"
    d=hearth-out/projection_title
    python3 "$here/png_title.py" $d/particles_2d.png $d/particles_3d.png $d/slice_2d.png $d/slice_3d.png \
        $d/frame_0000.png | tee titles.txt
    for f in particles_3d frame_0000; do
        grep -q "^$d/$f.png: .*   seen along -z\$" titles.txt || fail "$f.png's title does not say it is seen along -z"
    done
    for f in particles_2d slice_2d slice_3d; do
        grep "^$d/$f.png: " titles.txt | grep -q "seen along" && fail "$f.png's title says seen along"
    done
    ;;
browning_3d_picture_shows_cut)
    # #18 (helper userfix11; userfix9's Left): a 3D browning picture was the particles seen along -z, every depth, the
    # nearest on top: the front face's crust, brown all over, not the ring a cut shows. Bars set before the first run,
    # for a browned block at dx 12.5 and 10 mm (tests/lua/browning_cut_3d.lua): the default picture's title ends
    # "   particles at z = 0.1 ± DX m" (its slab, 2 dx thick); at the block's centre the pixel reads (png_pixel.py,
    # the nearest of the map's 101 colours) within 0.05 of the particle the slab puts there, a crumb under 0.25;
    # at the top of that column within 0.05 of its particle, a crust over 0.5.
    run browning_cut_3d.lua
    expect_rc 0 "the browned 3D block"
    cut -c1-110 out.txt
    d=hearth-out/browning_cut_3d
    map=$(sed -n 's/^map //p' out.txt)
    for dx in 12.5 10; do
        m=$(awk -v d="$dx" 'BEGIN { printf "%g", d / 1000 }')
        grep -q "^picture browning_$dx.png title .*   particles at z = 0.1 ± $m m\$" out.txt ||
            fail "browning_$dx.png's title does not say its slab (z = 0.1 ± $m m)"
        for where in centre top; do
            read -r b px py <<<"$(awk -v w="$where" -v d="$m" '$1 == w && $2 == d { print $4, $6, $7 }' out.txt)"
            r=$(python3 "$here/png_pixel.py" "$d/browning_$dx.png" "$px" "$py" "$map") || fail "png_pixel.py: $r"
            t=$(echo "$r" | awk '/^reads/{print $2}')
            echo "dx $dx mm, $where: particle $b, picture reads $t"
            awk -v b="$b" -v t="$t" -v w="$where" 'BEGIN { d = t - b; ok = b != "" && t != "" && d <= 0.05 && d >= -0.05
                exit !(ok && (w == "centre" ? b < 0.25 : b > 0.5)) }' ||
                fail "dx $dx mm, $where: the picture reads $t, its particle $b (a $where: crumb < 0.25, crust > 0.5)"
        done
    done
    ;;
slice_3d_title_says_plane)
    # #18 (helper userfix11; userfix9's Left): a 3D slice's title said the time alone; its axes' names gave the plane,
    # not where along its normal it cut. Bar set before the run: the Title text of tests/lua/projection_title.lua's 3D
    # slices ends with "   z = 0.05 m" (the default: the domain's middle) and "   x = 0.03 m" (axis = "x", at =
    # 0.03); the 2D slice's names no plane.
    run projection_title.lua --until 0.002
    expect_rc 0 "the jelly blocks"
    d=hearth-out/projection_title
    python3 "$here/png_title.py" $d/slice_2d.png $d/slice_3d.png $d/slice_3d_x.png | tee titles.txt
    grep -q "^$d/slice_3d.png: .*   z = 0.05 m\$" titles.txt || fail "slice_3d.png's title does not say z = 0.05 m"
    grep -q "^$d/slice_3d_x.png: .*   x = 0.03 m\$" titles.txt || fail "slice_3d_x.png's title does not say x = 0.03 m"
    grep "^$d/slice_2d.png: " titles.txt | grep -qE " [xyz] = " && fail "slice_2d.png's title names a plane"
    ;;
*) fail "unknown case $case_name" ;;
esac
echo "ok"
