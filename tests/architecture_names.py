#!/usr/bin/env python3
"""architecture_names.py CASE SOURCE_ROOT: docs/architecture.md names every
module, so a newcomer who reads the map can find any file, and a file added
without a line in the map fails the suite.

A module is a source file under core/, lua/, app/ or plugins/ (.c, .h, .lua,
.py). The map names it by its file name (`thermal.c`) or, for a pair, as
`thermal.[ch]`. The map groups files by folder, so a bare name is enough;
a name must stand alone (`sph.c` is not named by `rheometer_sph.c`).

Cases:
  architecture_names_every_module    the source tree and its map agree
  architecture_check_catches_unnamed the check fails on a scratch tree with
                                     an unnamed file (so the first case can
                                     fail)
"""
import os
import re
import shutil
import sys
import tempfile

TOPS = ("core", "lua", "app", "plugins")
EXTS = (".c", ".h", ".lua", ".py")


def modules(root):
    out = []
    for top in TOPS:
        for d, _, files in os.walk(os.path.join(root, top)):
            for f in files:
                if f.endswith(EXTS):
                    out.append(os.path.relpath(os.path.join(d, f), root))
    return sorted(out)


def named(text, path):
    """The map names path's file by its name, or a .c/.h by stem.[ch]."""
    base = os.path.basename(path)
    stem, ext = os.path.splitext(base)
    forms = [re.escape(base)]
    if ext in (".c", ".h"):
        forms.append(re.escape(stem) + r"\.\[ch\]")
    # not part of a longer name: no word character, dot or slash-free prefix glued on
    pat = r"(?<![\w.])(?:" + "|".join(forms) + r")(?![\w])"
    return re.search(pat, text) is not None


def unnamed(root):
    doc = os.path.join(root, "docs", "architecture.md")
    text = open(doc, encoding="utf-8").read()
    return [p for p in modules(root) if not named(text, p)]


def case_tree(root):
    if not os.path.isfile(os.path.join(root, "core", "sim", "scene.c")):
        sys.exit(f"FAIL: {root} has no core/sim/scene.c; is it the source root?")
    missing = unnamed(root)
    for p in missing:
        print(f"FAIL: {p} is not named in docs/architecture.md", file=sys.stderr)
    if missing:
        sys.exit(f"FAIL: {len(missing)} module(s) missing from the map; add one line each")
    print(f"docs/architecture.md names all {len(modules(root))} modules")


def case_catches(root):
    tmp = tempfile.mkdtemp()
    try:
        for d in ("core/sim/solver", "lua/hearth", "app/tui", "plugins", "docs"):
            os.makedirs(os.path.join(tmp, d))
        files = ["core/sim/scene.c", "core/sim/solver/grid.c", "core/sim/solver/grid.h",
                 "core/sim/solver/rheometer_sph.c", "lua/hearth/init.lua", "app/tui/tui_app.c",
                 "plugins/elastic.c", "core/sim/solver/sph.c"]
        for p in files:
            open(os.path.join(tmp, p), "w").write("/* stub */\n")
        # sph.c appears only inside a longer name; elastic.c not at all
        open(os.path.join(tmp, "docs", "architecture.md"), "w").write(
            "- `scene.c`\n- `grid.[ch]`\n- `rheometer_sph.c`\n- init.lua, `tui_app.c`\n")
        got = unnamed(tmp)
        want = ["core/sim/solver/sph.c", "plugins/elastic.c"]
        if got != want:
            sys.exit(f"FAIL: the check found {got} unnamed, expected {want}")
        print(f"the check flags the {len(want)} unnamed files and passes the named ones")
    finally:
        shutil.rmtree(tmp)


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    case, root = sys.argv[1], sys.argv[2]
    {"architecture_names_every_module": case_tree,
     "architecture_check_catches_unnamed": case_catches}.get(
        case, lambda r: sys.exit(f"unknown case {case}"))(root)
