#!/usr/bin/env python3
"""layer_includes.py CASE SOURCE_ROOT: the layers above the simulator (the
command line and the Lua binding) include only public headers, <hearth/...>
from core/include, never a private header of core/sim (docs/architecture.md,
Layers).

The build already puts only core/include on their include path, so a plain
`#include "rheometer.h"` fails to compile; this check also catches what the
include path cannot: a relative path into core/sim ("../sim/grid.h"), or a
private header copied next to the file that includes it.

Cases:
  app_lua_public_headers_only   the source tree obeys the rule
  layer_check_catches_private   the check itself fails on a scratch tree
                                holding each kind of violation (so the first
                                case can fail)
"""
import os
import re
import shutil
import sys
import tempfile

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)
# the layers above core/sim, which must see only core/include
LAYERS = ("app", "lua")


def sim_headers(root):
    """Every private header under core/sim (subfolders included): real path -> name."""
    out = {}
    for d, _, files in os.walk(os.path.join(root, "core", "sim")):
        for f in files:
            if f.endswith(".h"):
                out[os.path.realpath(os.path.join(d, f))] = f
    return out


def violations(root):
    root = os.path.realpath(root)
    private = sim_headers(root)
    names = set(private.values())
    public = os.path.join(root, "core", "include")
    found = []
    for layer in LAYERS:
        top = os.path.join(root, layer)
        if not os.path.isdir(top):
            continue
        for d, _, files in os.walk(top):
            for f in sorted(files):
                if not f.endswith((".c", ".h")):
                    continue
                path = os.path.join(d, f)
                text = open(path, encoding="utf-8", errors="replace").read()
                for m in INCLUDE.finditer(text):
                    kind, name = m.group(1), m.group(2)
                    line = text.count("\n", 0, m.start()) + 1
                    close = ">" if kind == "<" else '"'
                    where = f"{os.path.relpath(path, root)}:{line}: #include {kind}{name}{close}"
                    # where the compiler could find it: beside the file (quotes), the public headers
                    cands = ([os.path.join(d, name)] if kind == '"' else []) + [os.path.join(public, name)]
                    hit = next((os.path.realpath(c) for c in cands if os.path.isfile(c)), None)
                    if hit in private:
                        found.append(f"{where} is core/sim's private {os.path.relpath(hit, root)}")
                    elif hit and hit.startswith(os.path.join(root, "core", "sim") + os.sep):
                        found.append(f"{where} reaches into core/sim ({os.path.relpath(hit, root)})")
                    elif hit is None and os.path.basename(name) in names:
                        found.append(f"{where} names a core/sim header; use the public <hearth/...> API")
                    elif hit and os.path.basename(hit) in names and not hit.startswith(public + os.sep):
                        found.append(f"{where} is a copy of core/sim's {os.path.basename(hit)}")
    return found


def case_tree(root):
    found = violations(root)
    for v in found:
        print("FAIL:", v, file=sys.stderr)
    if not os.path.isfile(os.path.join(root, "core", "sim", "solver", "grid.h")):
        sys.exit(f"FAIL: {root} has no core/sim/solver/grid.h; is it the source root?")
    if found:
        sys.exit(f"FAIL: {len(found)} private include(s) above core/sim")
    print("app and lua include only public headers")


def case_catches(root):
    tmp = tempfile.mkdtemp()
    try:
        for d in ("core/sim/solver", "core/sim/io", "core/include/hearth", "app/tui", "lua"):
            os.makedirs(os.path.join(tmp, d))
        for h in ("core/sim/solver/grid.h", "core/sim/io/atomic_file.h", "core/include/hearth/hearth.h"):
            open(os.path.join(tmp, h), "w").write("/* stub */\n")
        bad = {
            "app/a.c": '#include "grid.h"\n',                 # by name: the old include path
            "app/tui/b.c": '#include "../../core/sim/solver/grid.h"\n',  # a relative path into core/sim
            "lua/c.c": '#  include <atomic_file.h>\n',             # angle brackets, a subfolder's header
            "lua/d.h": '#include "grid.h"\n',                      # beside a copy...
            "lua/grid.h": "/* a copy */\n",                        # ...of a private header
        }
        good = {"app/ok.c": '#include "hearth/hearth.h"\n#include <stdio.h>\n'}
        for p, t in {**bad, **good}.items():
            open(os.path.join(tmp, p), "w").write(t)
        found = violations(tmp)
        files = {v.split(":")[0] for v in found}
        want = {"app/a.c", "app/tui/b.c", "lua/c.c", "lua/d.h"}
        if files != want:
            sys.exit(f"FAIL: the check flagged {sorted(files)}, expected {sorted(want)}:\n" + "\n".join(found))
        print(f"the check flags all {len(want)} kinds of private include and passes the public one")
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    case, root = sys.argv[1], sys.argv[2]
    {"app_lua_public_headers_only": case_tree, "layer_check_catches_private": case_catches}.get(
        case, lambda r: sys.exit(f"unknown case {case}"))(root)
