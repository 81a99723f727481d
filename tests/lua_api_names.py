#!/usr/bin/env python3
"""lua_api_names.py SOURCE_ROOT: every function a scene can call is in docs/lua.md.

The names come from the code, so the reference cannot drift from it:
  - scene methods registered in C (luaL_Reg tables of lua/lua_scene.c, lua_scene_read.c and
    lua/lua_output.c that become the scene's methods), written s:NAME;
  - shape constructors registered in lua/lua_shapes.c, written h.NAME;
  - functions the Lua module defines (`function h.NAME`, `function S:NAME`
    in lua/hearth/init.lua, run.lua, metrics.lua, params.lua; `function S.NAME` in shapes.lua is h.shapes.NAME).
Names starting with '_' are internal (wrapped by a public function) and skipped.
Each must appear in docs/lua.md as written (s:NAME, h.NAME or h.shapes NAME).
"""
import os
import re
import sys

root = sys.argv[1]
doc = open(os.path.join(root, "docs", "lua.md")).read()


def reg_names(path, table):
    """Names of a `static const luaL_Reg TABLE[] = {...}` in a C file."""
    src = open(os.path.join(root, path)).read()
    m = re.search(r"luaL_Reg\s+" + table + r"\[\]\s*=\s*\{(.*?)\{NULL,\s*NULL\}\s*\}", src, re.S)
    if not m:
        sys.exit(f"FAIL: {path}: no luaL_Reg {table}[] (the test must follow the code)")
    return [n for n in re.findall(r'\{"(\w+)",', m.group(1)) if not n.startswith("_")]


want = []  # (how the doc writes it, where it comes from)
for n in reg_names("lua/lua_scene.c", "methods"):
    want.append((f"s:{n}", "lua_scene.c"))
for n in reg_names("lua/lua_scene_read.c", "hl_scene_readers"):
    want.append((f"s:{n}", "lua_scene_read.c"))
for n in reg_names("lua/lua_output.c", "methods"):
    want.append((f"s:{n}", "lua_output.c"))
for n in reg_names("lua/lua_shapes.c", "fns"):
    want.append((f"h.{n}", "lua_shapes.c"))
for part in ("init.lua", "run.lua", "metrics.lua", "params.lua"):  # init.lua and the parts it loads
    init = open(os.path.join(root, "lua", "hearth", part)).read()
    for n in re.findall(r"^function h\.(\w+)", init, re.M):
        if not n.startswith("_"):
            want.append((f"h.{n}", part))
    for n in re.findall(r"^function S:(\w+)", init, re.M):
        if not n.startswith("_"):
            want.append((f"s:{n}", part))
shapes = open(os.path.join(root, "lua", "hearth", "shapes.lua")).read()
for n in re.findall(r"^function S\.(\w+)", shapes, re.M):
    want.append((n, "shapes.lua (h.shapes)"))

missing = []
for name, where in sorted(set(want)):
    # a whole name: "s:probe" must not be satisfied by "s:probes"
    if not re.search(re.escape(name) + r"(?![\w])", doc):
        missing.append(f"{name} ({where})")
print(f"{len(set(want))} functions registered or defined; {len(missing)} missing from docs/lua.md")
if missing:
    print("FAIL: not in docs/lua.md: " + ", ".join(missing))
    sys.exit(1)
