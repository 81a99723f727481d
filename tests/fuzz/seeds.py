#!/usr/bin/env python3
"""Write the generated part of the fuzz seed corpora (tests/fuzz/corpus/).

Run from anywhere: python3 tests/fuzz/seeds.py [--hearth BUILD/app/hearth]
(the checkpoint seeds need a hearth binary to save them). Files are small and
deterministic, so rerunning gives the same bytes. Hand-picked seeds (the
shipped masks, crash reproducers found by scripts/fuzz) live next to these and
are not touched. PNGs are built by hand with zlib so no imaging library is
needed, and so broken ones can be built on purpose."""
import os
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))
SIG = b"\x89PNG\r\n\x1a\n"


def chunk(kind, data, crc=None):
    c = zlib.crc32(kind + data) & 0xFFFFFFFF if crc is None else crc
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", c)


def ihdr(w, h, depth, ctype, interlace=0):
    return chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, depth, ctype, 0, 0, interlace))


def samples(ctype):
    return {0: 1, 2: 3, 3: 1, 4: 2, 6: 4}[ctype]


def disc(w, h, x, y):
    """1 inside a disc in the middle, 0 outside."""
    cx, cy, r = (w - 1) / 2, (h - 1) / 2, min(w, h) / 3
    return (x - cx) ** 2 + (y - cy) ** 2 <= r * r


def raw_rows(w, h, depth, ctype, value):
    """Unfiltered scanlines; value(x, y, channel) gives a sample in 0..2^depth-1."""
    out = bytearray()
    ns = samples(ctype)
    for y in range(h):
        out.append(0)  # filter: none
        if depth < 8:
            bits, acc, nb = [], 0, 0
            for x in range(w):
                acc = (acc << depth) | value(x, y, 0)
                nb += depth
                if nb == 8:
                    out.append(acc)
                    acc, nb = 0, 0
            if nb:
                out.append(acc << (8 - nb))
        else:
            for x in range(w):
                for c in range(ns):
                    v = value(x, y, c)
                    out += struct.pack(">H", v) if depth == 16 else bytes([v])
    return bytes(out)


def png(w, h, depth, ctype, value, extra=b"", interlace=0):
    assert interlace == 0
    data = zlib.compress(raw_rows(w, h, depth, ctype, value), 9)
    return SIG + ihdr(w, h, depth, ctype) + extra + chunk(b"IDAT", data) + chunk(b"IEND", b"")


def grey_value(depth, inside_dark=True):
    top = (1 << depth) - 1

    def v(x, y, c, w=16, h=12):
        return 0 if disc(w, h, x, y) == inside_dark else top

    return v


def write(sub, name, data):
    d = os.path.normpath(os.path.join(HERE, "corpus", sub))
    os.makedirs(d, exist_ok=True)
    with open(os.path.join(d, name), "wb") as f:
        f.write(data)


def png_seeds():
    W, H = 16, 12
    for depth in (1, 2, 4, 8, 16):
        write("png_mask", f"gray{depth}.png", png(W, H, depth, 0, grey_value(depth)))
    # palette: index 0 dark, 1 light; with a tRNS making index 1 transparent
    plte = chunk(b"PLTE", bytes([20, 20, 20, 250, 250, 250]))
    pv = lambda x, y, c: 0 if disc(W, H, x, y) else 1
    write("png_mask", "palette8.png", png(W, H, 8, 3, pv, plte))
    write("png_mask", "palette4_trns.png", png(W, H, 4, 3, pv, plte + chunk(b"tRNS", bytes([255, 0]))))
    write("png_mask", "palette_index_past_plte.png", png(W, H, 8, 3, lambda x, y, c: 7, plte))
    # RGB, grey+alpha, RGBA in 8 and 16 bits: dark opaque disc, transparent outside
    for depth in (8, 16):
        top = (1 << depth) - 1
        write("png_mask", f"rgb{depth}.png",
              png(W, H, depth, 2, lambda x, y, c, t=top: 0 if disc(W, H, x, y) else t))
        write("png_mask", f"gray_alpha{depth}.png",
              png(W, H, depth, 4, lambda x, y, c, t=top: (0 if c == 0 else t) if disc(W, H, x, y) else (0 if c == 0 else 0)))
        write("png_mask", f"rgba{depth}.png",
              png(W, H, depth, 6, lambda x, y, c, t=top: (t if c == 3 else 0) if disc(W, H, x, y) else (0 if c == 3 else t)))
    write("png_mask", "gray_trns.png", png(W, H, 8, 0, grey_value(8), chunk(b"tRNS", struct.pack(">H", 255))))
    write("png_mask", "one_pixel.png", png(1, 1, 8, 0, lambda x, y, c: 0))
    write("png_mask", "one_row.png", png(40, 1, 8, 0, lambda x, y, c: 0 if 10 < x < 30 else 255))
    write("png_mask", "one_column.png", png(1, 40, 8, 0, lambda x, y, c: 0 if 10 < y < 30 else 255))
    write("png_mask", "all_white.png", png(W, H, 8, 0, lambda x, y, c: 255))
    write("png_mask", "all_black.png", png(W, H, 8, 0, lambda x, y, c: 0))
    # Adam7 interlaced grey: the scanlines of the seven passes, built here
    write("png_mask", "interlaced.png", interlaced(W, H))
    # filters other than none: Sub, Up, Average, Paeth on successive rows
    write("png_mask", "filters.png", filtered(W, H))
    # broken on purpose
    good = png(W, H, 8, 0, grey_value(8))
    write("png_mask", "zero_width.png", SIG + ihdr(0, H, 8, 0) + good[33:])
    write("png_mask", "zero_height.png", SIG + ihdr(W, 0, 8, 0) + good[33:])
    write("png_mask", "huge_5000.png", SIG + ihdr(5000, 5000, 8, 0) + good[33:])
    write("png_mask", "huge_40000.png", SIG + ihdr(40000, 3, 8, 0) + good[33:])
    write("png_mask", "huge_2e31.png", SIG + ihdr(0x7FFFFFFF, 0x7FFFFFFF, 8, 0) + good[33:])
    write("png_mask", "bad_depth.png", SIG + ihdr(W, H, 3, 0) + good[33:])
    # odd length on purpose: fuzz_png_mask.c recomputes the CRCs of even-length inputs
    write("png_mask", "bad_ihdr_crc.png", SIG + chunk(b"IHDR", good[16:29], crc=0) + good[33:] + b"\0")
    idat_at = good.index(b"IDAT") - 4
    n = struct.unpack(">I", good[idat_at:idat_at + 4])[0]
    write("png_mask", "truncated_idat.png", good[:idat_at + 8 + n // 2])
    write("png_mask", "garbage_zlib.png", good[:33] + chunk(b"IDAT", bytes(range(200, 250))) + chunk(b"IEND", b""))
    write("png_mask", "short_idat.png", good[:33] + chunk(b"IDAT", zlib.compress(b"\0" * 20)) + chunk(b"IEND", b""))
    write("png_mask", "no_iend.png", good[:good.index(b"IEND") - 4])
    write("png_mask", "signature_only.png", SIG)
    write("png_mask", "empty.png", b"")
    write("png_mask", "not_png.png", b"shear_rate,stress\n1,2\n")
    # a small decompression bomb: 1024 x 1024 grey from 1 kB, all zero bytes.
    # (A 4096^2 one, the largest allowed, takes ~20 s under ASan: too slow for
    # the corpus replay; unit_mask's mask_huge_and_bomb times that case.)
    big = zlib.compress(b"\0" * (1025 * 1024), 9)
    write("png_mask", "bomb_1024.png", SIG + ihdr(1024, 1024, 8, 0) + chunk(b"IDAT", big) + chunk(b"IEND", b""))


ADAM7 = [(0, 0, 8, 8), (4, 0, 8, 8), (0, 4, 4, 8), (2, 0, 4, 4), (0, 2, 2, 4), (1, 0, 2, 2), (0, 1, 1, 2)]


def interlaced(w, h):
    raw = bytearray()
    for x0, y0, dx, dy in ADAM7:
        xs = range(x0, w, dx)
        ys = range(y0, h, dy)
        if not xs or not ys:
            continue
        for y in ys:
            raw.append(0)
            raw += bytes(0 if disc(w, h, x, y) else 255 for x in xs)
    hdr = chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 0, 0, 0, 1))
    return SIG + hdr + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b"")


def filtered(w, h):
    rows = [[0 if disc(w, h, x, y) else 255 for x in range(w)] for y in range(h)]
    raw = bytearray()
    prev = [0] * w
    for y, row in enumerate(rows):
        ft = y % 5
        raw.append(ft)
        for x in range(w):
            a = row[x - 1] if x else 0
            b = prev[x]
            c = prev[x - 1] if x else 0
            if ft == 0:
                pred = 0
            elif ft == 1:
                pred = a
            elif ft == 2:
                pred = b
            elif ft == 3:
                pred = (a + b) // 2
            else:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            raw.append((row[x] - pred) & 0xFF)
        prev = row
    return SIG + ihdr(w, h, 8, 0) + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + chunk(b"IEND", b"")


def csv_seeds():
    ok = "shear_rate,stress\n0.1,12.5\n1,15\n10,31\n100,120\n"
    w = lambda name, text: write("csv", name, text.encode() if isinstance(text, str) else text)
    w("valid.csv", ok)
    w("valid_quoted_reordered.csv", '# a comment\n"stress","temperature","shear_rate"\n 12.5 , 20, 0.1\n15,20,1\n\n31,20,10\n')
    w("valid_bom_crlf.csv", "\ufeffshear_rate,stress\r\n0.5,3\r\n5,8\r\n50,40\r\n")
    w("newtonian.csv", "shear_rate,stress\n1,1\n2,2\n4,4\n8,8\n")
    w("empty.csv", "")
    w("only_comments.csv", "# nothing here\n\n   \n")
    w("header_only.csv", "shear_rate,stress\n")
    w("one_row.csv", "shear_rate,stress\n1,2\n")
    w("two_rows.csv", "shear_rate,stress\n1,2\n3,4\n")
    w("no_header.csv", "1,2\n3,4\n5,6\n")
    w("nan.csv", "shear_rate,stress\n1,nan\n2,3\n4,5\n")
    w("inf.csv", "shear_rate,stress\ninf,1\n2,3\n4,5\n")
    w("huge_number.csv", "shear_rate,stress\n1e400,1\n2,3\n4,5\n")
    w("tiny_numbers.csv", "shear_rate,stress\n1e-320,1e-320\n2e-320,3e-320\n4e-300,5e-300\n")
    w("extreme_range.csv", "shear_rate,stress\n1e-300,1e300\n1e300,1e-300\n1,1\n")
    w("negative.csv", "shear_rate,stress\n-1,2\n2,3\n4,5\n")
    w("zero.csv", "shear_rate,stress\n0,2\n2,3\n4,5\n")
    w("text.csv", "shear_rate,stress\nfast,high\n2,3\n4,5\n")
    w("trailing_text.csv", "shear_rate,stress\n1Pa,2\n2,3\n4,5\n")
    w("hex.csv", "shear_rate,stress\n0x10,0x1p3\n2,3\n4,5\n")
    w("missing_cell.csv", "shear_rate,stress\n1\n2,3\n4,5\n")
    w("many_columns.csv", ",".join(["x"] * 70 + ["shear_rate", "stress"]) + "\n" + ",".join(["1"] * 72) + "\n" * 3)
    w("long_line.csv", "shear_rate,stress\n" + "1" * 5000 + ",2\n2,3\n4,5\n")
    w("long_line_exact.csv", "shear_rate,stress\n" + "1" * 4093 + ",2\n2,3\n4,5\n")
    w("no_final_newline.csv", "shear_rate,stress\n1,2\n2,3\n4,5")
    w("nul_bytes.csv", b"shear_rate,stress\n1,2\x00junk\n2,3\n4,5\n")
    w("many_rows.csv", "shear_rate,stress\n" + "".join(f"{1 + i * 0.01:.3f},{2 + i * 0.02:.3f}\n" for i in range(3000)))
    w("duplicate_header.csv", "shear_rate,stress,shear_rate,stress\n1,2,9,9\n2,3,9,9\n4,5,9,9\n")


def scene_seeds():
    w = lambda name, text: write("scene", name, text.encode())
    # Escapes the sandbox let out before issue 15's allow-list sandbox: kept as
    # regressions (the sandbox must refuse them).
    p = w
    w("tiny_drop.lua", """local h = require "hearth"
local s = h.scene{dim = 2, box = {{0, 0}, {0.1, 0.1}}, dx = 0.01, seed = 1}
local m = h.material("elastic", {E = 1e4, nu = 0.3, density = 1000})
s:add{material = m, shape = h.box({0.03, 0.03}, {0.06, 0.06}), ppc = 2}
s:collider{shape = h.plane({0, 0.02}, {0, 1}), mode = "separate", friction = 0.3}
s:step(1)
s:run{until_t = 0.004}
""")
    w("tiny_outputs.lua", """local h = require "hearth"
local s = h.scene{dim = 2, box = {{0, 0}, {0.1, 0.1}}, dx = 0.01, seed = 2}
local soup = h.material("newtonian", {density = 1000, bulk = 2e4, viscosity = 0.5})
s:add{material = soup, shape = h.disc({0.05, 0.05}, 0.02), ppc = 2}
s:step(2)
s:save("ck.bin")
h.write("note.txt", "hello")
s:vtu("p.vtu")
s:ply("p.ply")
""")
    w("syntax_error.lua", "local x = = 1\n")
    w("runtime_error.lua", "error('boom')\n")
    w("error_table.lua", "error({})\n")
    w("infinite_loop.lua", "while true do end\n")
    w("string_bomb.lua", "local s = string.rep('x', 1 << 20)\nwhile true do s = s .. s end\n")
    w("deep_recursion.lua", "local function f(n) return f(n + 1) + 1 end\nf(1)\n")
    # Escapes aim at "../", the folder fuzz_scene.c watches beside the output folder.
    w("escape_io.lua", "io.open('../escape_io', 'w'):write('x')\n")
    w("escape_load_binary.lua", "load(string.dump(function() end))()\n")
    w("escape_debug.lua", "local d = package.loaded.debug\nlocal _, v = d.getupvalue(io.open, 2)\nv('../escape_debug', 'w')\n")
    p("escape_write.lua", "local h = require 'hearth'\nh.write('../escape_write', 'x')\n")
    p("escape_csv.lua", """local h = require "hearth"
local s = h.scene{dim = 2, box = {{0, 0}, {0.1, 0.1}}, dx = 0.01, seed = 1}
local m = h.material("elastic", {E = 1e4, nu = 0.3, density = 1000})
s:add{material = m, shape = h.box({0.03, 0.03}, {0.06, 0.06}), ppc = 2}
s:run{until_t = 0.001, csv = "../escape_csv.csv"}
""")
    p("escape_save.lua", """local h = require "hearth"
local s = h.scene{dim = 2, box = {{0, 0}, {0.1, 0.1}}, dx = 0.01, seed = 1}
s:save("../escape_save.ck")
""")
    w("bad_scene_numbers.lua", """local h = require "hearth"
h.scene{dim = 2, box = {{0, 0}, {0/0, 1}}, dx = -1}
""")


CK_SCENES = {
    # 2D, two materials, a plane collider (as tests/lua/ck_save.lua, smaller)
    "two_materials_2d.ck": """local h = require "hearth"
local s = h.scene{dim = 2, dx = 1 / 16, box = {{0, 0}, {1, 1}}, seed = 3}
local jelly = h.material("elastic", {E = 2e4, nu = 0.3, density = 1000})
local soup = h.material("newtonian", {density = 1000, bulk = 2e4, viscosity = 0.5})
s:add{shape = h.box({0.3, 0.3}, {0.6, 0.5}), material = jelly, ppc = 2, jitter = 0.5, velocity = {0.2, 0}}
s:add{shape = h.disc({0.5, 0.7}, 0.1), material = soup, ppc = 2, jitter = 0.5}
s:collider{shape = h.plane({0, 0.15}, {0, 1}), mode = "separate", friction = 0.3}
s:step(5)
s:save("OUT")
""",
    # 3D, a few particles, a sphere collider
    "small_3d.ck": """local h = require "hearth"
local s = h.scene{dim = 3, dx = 1 / 8, box = {{0, 0, 0}, {1, 1, 1}}, seed = 4}
local jelly = h.material("elastic", {E = 2e4, nu = 0.3, density = 1000})
s:add{shape = h.box({0.4, 0.4, 0.4}, {0.6, 0.6, 0.6}), material = jelly, ppc = 1}
s:collider{shape = h.sphere({0.5, 0.1, 0.5}, 0.1), mode = "sticky"}
s:step(2)
s:save("OUT")
""",
    # a mask body and a mask collider: the checkpoint carries the distance field
    "mask_2d.ck": """local h = require "hearth"
local s = h.scene{dim = 2, dx = 1 / 16, box = {{0, 0}, {1, 1}}, seed = 5}
local dough = h.material("elastic", {E = 5e4, nu = 0.3, density = 1200})
s:add{shape = h.mask("MASK", {0.3, 0.3}, {0.7, 0.6}), material = dough, ppc = 2}
s:collider{shape = h.mask("MASK", {0.0, 0.0}, {1.0, 0.1}), mode = "slip"}
s:step(2)
s:save("OUT")
""",
    # heat on: the temperature column and the oven are saved too
    "heat_2d.ck": """local h = require "hearth"
local s = h.scene{dim = 2, dx = 1 / 16, box = {{0, 0}, {1, 1}}, seed = 6, heat = "explicit"}
local dough = h.material("elastic", {E = 5e4, nu = 0.3, density = 1200})
s:add{shape = h.box({0.3, 0.2}, {0.7, 0.4}), material = dough, ppc = 2}
s:step(2)
s:save("OUT")
""",
    # version 4's additions: a humid oven with latent heat and browning, a Robin wet
    # collider, a held (Dirichlet) collider and a body that keeps its temperature
    "fields_v4_2d.ck": """local h = require "hearth"
local s = h.scene{dim = 2, dx = 1 / 16, box = {{0, 0}, {1, 1}}, seed = 7, gravity = {0, 0},
  oven = {temperature = 180, beta = 20, saturation = 0.3}, latent_heat = true, browning = true, browning_scale = 50}
local m = h.material("elastic", {E = 5e4, density = 500, specific_heat = 2000, conductivity = 0.5,
  water_diffusivity = 1e-7, evaporation = 6e-6})
s:collider{shape = h.plane({0, 0.1}, {0, 1}), temperature = 150, fixed_temperature = true}
s:collider{shape = h.plane({0.9, 0}, {-1, 0}), saturation = 0.9, beta_water = 0.05}
s:add{shape = h.box({0.3, 0.1}, {0.7, 0.3}), material = m, ppc = 2, saturation = 0.6, fixed = true}
s:add{shape = h.box({0.1, 0.5}, {0.2, 0.6}), material = m, ppc = 2, temperature = 90, fixed_temperature = true}
s:step(2)
s:save("OUT")
""",
    # version 5's DEF additions: damping, a boiling point, two fields with friction, venting pores
    "fields_v5_2d.ck": """local h = require "hearth"
local s = h.scene{dim = 2, dx = 1 / 16, box = {{0, 0}, {1, 1}}, seed = 8, oven = {temperature = 180, beta = 20},
  latent_heat = true, boiling_point = 95, damping = 2, two_field = true, two_field_friction = 0.3, gas_vent = 0.5,
  vent_porosity = 0.6}
local m = h.material("cam_clay_dough", {E = 1e5, density = 500, porosity = 0.7, gas_rate = 1e-6})
s:add{shape = h.box({0.3, 0.1}, {0.7, 0.3}), material = m, ppc = 2, saturation = 0.5}
s:step(2)
s:save("OUT")
""",
    # version 5: periodic axes (MPM, no heat or water across them)
    "periodic_v5_2d.ck": """local h = require "hearth"
local s = h.scene{dim = 2, dx = 1 / 16, box = {{0, 0}, {1, 1}}, seed = 9, periodic_x = true}
local jelly = h.material("elastic", {E = 2e4, nu = 0.3, density = 1000})
s:add{shape = h.box({0.8, 0.3}, {1.0, 0.5}), material = jelly, ppc = 2, velocity = {0.5, 0}}
s:step(2)
s:save("OUT")
""",
    # version 13: CO2 shares with amounts (the gas_made column) and, at cfl 0.9, the lone-particle bound (self_max)
    "gas_amount_v13_2d.ck": """local h = require "hearth"
local s = h.scene{dim = 2, dx = 1 / 16, box = {{0, 0}, {1, 1}}, seed = 10, cfl = 0.9, oven = {temperature = 180, beta = 20}}
local m = h.material("elastic", {E = 5e4, density = 500, conductivity = 0.5, gas_rate = 0.01, reaction_temperature = 60,
  gas_rate_2 = 0.02, reaction_temperature_2 = 40, gas_amount = 1e-3, gas_amount_2 = 2e-3})
s:add{shape = h.box({0.3, 0.1}, {0.7, 0.3}), material = m, ppc = 2, temperature = 60, fixed = true}
s:add{shape = h.box({0.1, 0.6}, {0.13, 0.63}), material = m, ppc = 1, temperature = 60}
s:step(4)
s:save("OUT")
""",
    # version 14: a heated tray that goes in cold (start_temperature, warm_time, t_added per collider)
    "warming_v14_2d.ck": """local h = require "hearth"
local s = h.scene{dim = 2, dx = 1 / 16, box = {{0, 0}, {1, 1}}, seed = 11, oven = {temperature = 180, beta = 20}}
local m = h.material("elastic", {E = 5e4, density = 500, specific_heat = 2000, conductivity = 0.5})
s:collider{shape = h.plane({0, 0.1}, {0, 1}), temperature = 180, beta = 100, start_temperature = 20, warm_time = 0.5}
s:add{shape = h.box({0.3, 0.1}, {0.7, 0.3}), material = m, ppc = 2, temperature = 20}
s:step(3)
s:save("OUT")
""",
    # version 15: a sheet the food draws its heat from (heat_capacity, area and the sheet's state per collider)
    "drawing_sheet_v15_2d.ck": """local h = require "hearth"
local s = h.scene{dim = 2, dx = 1 / 16, box = {{0, 0}, {1, 1}}, seed = 12, oven = {temperature = 180, beta = 20}}
local m = h.material("elastic", {E = 5e4, density = 500, specific_heat = 2000, conductivity = 0.5})
s:collider{shape = h.plane({0, 0.1}, {0, 1}), temperature = 180, beta = 100, start_temperature = 20, warm_time = 0.5,
  heat_capacity = 2430, area = 1}
s:add{shape = h.box({0.3, 0.1}, {0.7, 0.3}), material = m, ppc = 2, temperature = 20}
s:step(3)
s:save("OUT")
""",
    # version 16: an oven whose walls radiate (oven.wall_temperature, oven.emissivity, oven.radiation_scale in DEF)
    "walls_v16_2d.ck": """local h = require "hearth"
local s = h.scene{dim = 2, dx = 1 / 16, box = {{0, 0}, {1, 1}}, seed = 12,
  oven = {temperature = 180, beta = 20, wall_temperature = 240, emissivity = 0.9, radiation_scale = 2}}
local m = h.material("elastic", {E = 5e4, density = 500, specific_heat = 2000, conductivity = 0.5})
s:add{shape = h.box({0.3, 0.1}, {0.7, 0.3}), material = m, ppc = 2, temperature = 20}
s:step(3)
s:save("OUT")
""",
}


def checkpoint_seeds(hearth):
    """Checkpoints saved by the hearth binary given (they depend on its format version)."""
    import subprocess
    import tempfile
    mask = os.path.join(HERE, "corpus", "png_mask", "gray8.png")
    with tempfile.TemporaryDirectory() as tmp:
        for name, text in CK_SCENES.items():
            out = os.path.join(tmp, name)
            scene = os.path.join(tmp, name + ".lua")
            with open(scene, "w") as f:
                f.write(text.replace("OUT", out).replace("MASK", mask))
            r = subprocess.run([hearth, "run", "--trust", "--quiet", "--out", tmp, scene], capture_output=True, text=True)
            if r.returncode != 0 or not os.path.exists(out):
                print(f"{name}: hearth run failed ({r.returncode}): {r.stderr.strip()}")
                continue
            with open(out, "rb") as f:
                data = f.read()
            if len(data) > 64 * 1024:
                print(f"{name}: {len(data)} bytes, over the 64 kB corpus limit; skipped")
                continue
            write("checkpoint", name, data)
            # and three broken copies: cut in half, one flipped bit, the header alone
            write("checkpoint", name.replace(".ck", "_truncated.ck"), data[: len(data) // 2])
            flipped = bytearray(data)
            flipped[len(data) // 3] ^= 0x10
            write("checkpoint", name.replace(".ck", "_bitflip.ck"), bytes(flipped))
            write("checkpoint", name.replace(".ck", "_head.ck"), data[:64])
    write("checkpoint", "empty.ck", b"")
    write("checkpoint", "not_a_checkpoint.ck", b"shear_rate,stress\n1,2\n")


if __name__ == "__main__":
    import sys
    png_seeds()
    csv_seeds()
    scene_seeds()
    if len(sys.argv) == 3 and sys.argv[1] == "--hearth":
        checkpoint_seeds(sys.argv[2])
    else:
        print("checkpoint seeds: pass --hearth PATH/TO/hearth to (re)write them")
