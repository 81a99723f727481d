#!/usr/bin/env python3
"""scene_word_params.py SOURCE_ROOT: every shipped scene and script declares a word-valued parameter with h.choice.

h.params takes a plain string default as free text: --set passes any word through, and a misspelling either
fails later with the scene's own message or runs silently (before h.choice: rise_loaf.lua's soft, slump_dt.lua's
material, marshmallow_skin.lua's only, cup_spoon.lua's mixing). This reads the h.params{...} table of every
scripts/**/*.lua and fails on a string default that is not listed below as free text, with the reason it is.
"""
import os
import re
import sys

root = sys.argv[1]

# (file under scripts/, parameter): why its value is not one of a few words
FREE_TEXT = {
    ("scenes/sauces/nozzle.lua", "pair"): "two sauce names A:B, each checked by h.library.sauce with its nearest",
    ("scenes/sauces/nozzle.lua", "ratios"): "a comma list of mixing ratios, parsed by the scene",
    ("validation/rise_loaf.lua", "png"): "a particle field's name for PNG frames, or \"\" for none (s:run checks it)",
    ("validation/bread3d.lua", "field"): "a particle field's name for the slices (s:png checks it)",
    ("validation/bread3d.lua", "bread"): "the path of the scene it runs",
    ("validation/bread3d.lua", "tray"): "passed on to bread.lua, whose h.choice checks it (h.pass_params)",
    ("validation/crack_heat.lua", "bread"): "the path of the scene it runs",
    ("validation/crack_dt.lua", "bread"): "the path of the scene it runs",
    ("validation/crack_tray.lua", "bread"): "the path of the scene it runs",
    ("validation/loaf_whatif.lua", "loaf"): "the path of the scene it runs",
    ("validation/loaf_whatif.lua", "tray"): "passed on to loaf_physical.lua, whose h.choice checks it (h.pass_params)",
    ("validation/muffin_tear.lua", "muffins"): "the path of the scene it runs",
    ("validation/muffin_tear.lua", "wall_mode"): "passed on to muffins.lua, whose h.choice checks it (h.pass_params)",
}


def params_table(src):
    """The text of the first h.params { ... } table, or None."""
    m = re.search(r"h\.params\s*\{", src)
    if not m:
        return None
    depth, i = 0, m.end() - 1
    for j in range(i, len(src)):
        if src[j] == "{":
            depth += 1
        elif src[j] == "}":
            depth -= 1
            if depth == 0:
                return src[i + 1:j]
    sys.exit("FAIL: an h.params table without its closing brace")


def top_level_strings(table):
    """name = "string" entries at the table's own level (not inside h.choice{...} or a nested table)."""
    # comments out, strings kept (a description may hold "--set ..."); the depth count skips the strings' text
    text = re.sub(r"(\"[^\"]*\"|'[^']*')|--[^\n]*", lambda m: m.group(1) or "", table)
    # h.scene_path("...") is a string default too: the wrappers' paths of the scenes they run (helper userfix10)
    text = re.sub(r"h\.scene_path\(\s*(\"[^\"]*\"|'[^']*')\s*\)", r"\1", text)
    masked = re.sub(r"\"[^\"]*\"|'[^']*'", lambda m: m.group(0)[0] + "_" * (len(m.group(0)) - 2) + m.group(0)[0], text)
    depth, level0 = 0, []
    for ch, shown in zip(masked, text):
        if ch in "{(":
            depth += 1
        elif ch in "})":
            depth -= 1
        level0.append(shown if depth == 0 else " ")
    flat = "".join(level0)
    return re.findall(r"\b(\w+)\s*=\s*(\"[^\"]*\"|'[^']*')", flat)


found, bad, seen = 0, [], set()
for dirpath, _, files in os.walk(os.path.join(root, "scripts")):
    for name in sorted(files):
        if not name.endswith(".lua"):
            continue
        path = os.path.join(dirpath, name)
        rel = os.path.relpath(path, os.path.join(root, "scripts"))
        table = params_table(open(path).read())
        if table is None:
            continue
        found += 1
        for param, value in top_level_strings(table):
            seen.add((rel, param))
            if (rel, param) not in FREE_TEXT:
                bad.append(f"scripts/{rel}: {param} = {value}")
stale = sorted(f"scripts/{f}: {p}" for f, p in FREE_TEXT if (f, p) not in seen)
print(f"{found} scripts with h.params; {len(FREE_TEXT)} free-text parameters listed here")
if stale:
    print("FAIL: listed as free text but no longer a string default there (drop them here): " + "; ".join(stale))
if bad:
    print("FAIL: a string default that is not h.choice{...} (declare its words, or list it here as free text "
          "with the reason): " + "; ".join(bad))
sys.exit(1 if bad or stale else 0)
