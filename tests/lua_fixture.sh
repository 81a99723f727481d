# lua_fixture.sh, sourced by lua_test.sh, lua_params_test.sh and sandbox_test.sh with their
# arguments (CASE HEARTH): the case's temp folder and the helpers both drivers use.
# here: the driver's folder (png_check.py lives there); scenes: tests/lua/.
here=$(cd "$(dirname "$0")" && pwd) # png_check.py lives here
set -u
case_name=$1
hearth=$2
case "$hearth" in /*) ;; */*) hearth=$PWD/$hearth ;; esac # the cases cd to a temp folder
scenes=$(cd "$(dirname "$0")/lua" && pwd)
tmp=$(mktemp -d)
bg_pid=
trap '[ -n "$bg_pid" ] && kill -9 "$bg_pid" 2>/dev/null; rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }

# run SCENE [ARGS...]: hearth run --quiet on tests/lua/SCENE; stdout in out.txt,
# stderr in err.txt, exit status in $rc
run() {
    local scene=$1
    shift
    "$hearth" run "$scenes/$scene" --quiet "$@" >out.txt 2>err.txt
    rc=$?
}
# expect_rc N WHAT: the last run exited N
expect_rc() {
    [ "$rc" -eq "$1" ] || fail "$2: exit $rc, expected $1; stderr: $(cat err.txt) stdout: $(cat out.txt)"
}
# has FILE TEXT WHAT: FILE contains TEXT (fixed string)
has() {
    grep -qF -- "$2" "$1" || fail "$3: '$2' not in $1: $(cat "$1")"
}
# has_msg TEXT WHAT: the error message in err.txt (without its stack traceback) contains TEXT
has_msg() {
    sed '/^stack traceback:/,$d' err.txt >msg.txt
    grep -qF -- "$1" msg.txt || fail "$2: '$1' not in the message: $(cat msg.txt)"
}

# png_check FILE [W H]: see png_check.py
png_check() { python3 "$here/png_check.py" "$@"; }

# whole_files DIR: every .vtu / .png / .csv / .ply in DIR is complete.
whole_files() {
    python3 - "$1" <<'PY' || return 1
import os, re, struct, sys
d, bad, counts = sys.argv[1], [], {}
for name in sorted(os.listdir(d)):
    p = os.path.join(d, name)
    ext = os.path.splitext(name)[1]
    if ".tmp." in name or not os.path.isfile(p):
        continue
    counts[ext] = counts.get(ext, 0) + 1
    b = open(p, "rb").read()
    if ext == ".vtu":
        if not b.startswith(b"<?xml") or not b.endswith(b"</VTKFile>\n"):
            bad.append(f"{name}: VTU does not end with </VTKFile> and a newline ({len(b)} bytes)")
    elif ext == ".png":
        if b[:8] != b"\x89PNG\r\n\x1a\n" or b[-12:] != b"\x00\x00\x00\x00IEND\xaeB`\x82":
            bad.append(f"{name}: PNG without signature or final IEND ({len(b)} bytes)")
    elif ext == ".csv":
        lines = b.decode().split("\n")
        if not b.endswith(b"\n") or len(lines) < 3:
            bad.append(f"{name}: CSV does not end with a newline or has no rows")
        else:
            cols = lines[0].count(",")
            if any(l.count(",") != cols for l in lines[1:-1]):
                bad.append(f"{name}: CSV rows with a different column count")
    elif ext == ".ply":
        end = b.find(b"end_header\n")
        head = b[:end].decode(errors="replace")
        m = re.search(r"element vertex (\d+)", head)
        sizes = {"double": 8, "float": 4, "int": 4, "uint": 4, "uchar": 1, "char": 1, "short": 2, "ushort": 2}
        props = re.findall(r"property (\w+) \w+", head)
        if end < 0 or not m or "binary_little_endian" not in head:
            bad.append(f"{name}: PLY header incomplete")
        elif len(b) != end + 11 + int(m.group(1)) * sum(sizes[t] for t in props):
            bad.append(f"{name}: PLY is {len(b)} bytes; its header promises {end + 11 + int(m.group(1)) * sum(sizes[t] for t in props)}")
if bad:
    sys.exit("\n".join(bad))
print(" ".join(f"{k}:{v}" for k, v in sorted(counts.items())))
PY
}

