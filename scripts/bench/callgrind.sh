# callgrind.sh: sourced by the instruction-counting benchmarks.
# valgrind does not decode AVX-512, so they run a build without
# -march=native (build/nn), made here when missing.
# Needs $root (the repository) set by the caller.
command -v valgrind >/dev/null || { echo "$(basename "$0"): needs valgrind" >&2; exit 2; }
[ -f "$root/build/nn/build.ninja" ] || meson setup "$root/build/nn" "$root" --buildtype=release -Dnative=false >/dev/null
ninja -C "$root/build/nn" >/dev/null
nn_hearth=$root/build/nn/app/hearth

# refs COMMAND...: the instructions COMMAND executes, one thread.
refs() {
    OMP_WAIT_POLICY=passive OMP_NUM_THREADS=1 HEARTH_PLUGIN_PATH="$root/build/nn/plugins" \
        valgrind --tool=callgrind --callgrind-out-file=/dev/null "$@" 2>&1 | awk '/refs/ {gsub(",", "", $NF); print $NF}'
}
