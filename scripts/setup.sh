# setup.sh: shared by scripts/hearth and scripts/test (sourced, not run).
# Installs missing Debian packages, then configures and builds with meson.
HEARTH_ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)

# Debian packages hearth needs, and how to tell each is there.
hearth_missing_packages() {
    local missing=()
    command -v meson >/dev/null 2>&1 || missing+=(meson)
    command -v ninja >/dev/null 2>&1 || missing+=(ninja-build)
    command -v pkg-config >/dev/null 2>&1 || missing+=(pkg-config)
    command -v cc >/dev/null 2>&1 || missing+=(gcc)
    command -v python3 >/dev/null 2>&1 || missing+=(python3)
    if command -v pkg-config >/dev/null 2>&1; then
        pkg-config --exists lua5.4 || missing+=(liblua5.4-dev)
        pkg-config --exists ncursesw || missing+=(libncurses-dev)
        pkg-config --exists libpng || missing+=(libpng-dev)
        pkg-config --exists cairo || missing+=(libcairo2-dev)
    else
        missing+=(liblua5.4-dev libncurses-dev libpng-dev libcairo2-dev)
    fi
    # the -direct terminal descriptions, so COLORTERM=truecolor gets 24-bit colour in the dashboard
    [ -e /usr/share/terminfo/x/xterm-direct ] || [ -e /lib/terminfo/x/xterm-direct ] || missing+=(ncurses-term)
    # the pictures' text (Cairo finds it through fontconfig)
    [ -e /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf ] || missing+=(fonts-dejavu-core)
    echo "${missing[@]}"
}

hearth_install_deps() {
    local extra=("$@") missing
    missing=$(hearth_missing_packages)
    for p in "${extra[@]}"; do
        command -v "$p" >/dev/null 2>&1 || missing="$missing $p"
    done
    [ -z "${missing// /}" ] && return 0
    echo "hearth: installing missing Debian packages:$missing" >&2
    local sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    $sudo apt-get update -qq >&2 || true
    # shellcheck disable=SC2086
    $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $missing >&2
}

# Optional Debian packages: tests that need one skip (exit 77) without it,
# and nothing else depends on them. python3-vtk9: VTK's own readers check the
# VTU series and PLY files (tests/vtk_check.py). A failed install is only
# reported. scripts/test installs them; HEARTH_NO_OPTIONAL=1 skips that.
# ffmpeg (movies: s:run{movie = ...}, hearth run --movie; the test
# movie_written_with_ffmpeg) is only installed when asked, HEARTH_WITH_FFMPEG=1:
# it pulls in about 100 packages (measured on Debian 12), too much for every CI
# run, and without it hearth only says so and keeps the PNG frames.
# slurm-wlm and munge (the test trade_slurm_array_matches_local starts its own
# single-node Slurm, so a ladder is tested on a real scheduler in CI): 7
# packages, 3.5 MB, 19 s to install here on Debian 12 (more on an image without
# Open MPI's hwloc and numa libraries); HEARTH_NO_SLURM=1 skips them, and that
# test then skips, as trade_mpi_ranks_match_local does without mpirun.
#
# MPI (libopenmpi-dev, openmpi-bin: `mpirun -n N hearth run`, the mpi test
# suite; docs/scaling.md) is installed unless HEARTH_NO_MPI=1: 14 packages,
# 4.3 MB to download, 34 MB on disk, 9.3 s to install on Debian 12 (measured,
# most of the archives already in apt's cache). It must be there before the
# first `meson setup` (-Dmpi=auto looks once); without it the mpi tests skip.
hearth_install_optional() {
    [ "${HEARTH_NO_OPTIONAL:-0}" = 1 ] && return 0
    local missing=()
    /usr/bin/python3 -c "import vtk" >/dev/null 2>&1 || python3 -c "import vtk" >/dev/null 2>&1 || missing+=(python3-vtk9)
    if [ "${HEARTH_NO_MPI:-0}" != 1 ]; then
        command -v mpicc >/dev/null 2>&1 || missing+=(libopenmpi-dev)
        command -v mpirun >/dev/null 2>&1 || missing+=(openmpi-bin)
    fi
    if [ "${HEARTH_WITH_FFMPEG:-0}" = 1 ] && ! command -v ffmpeg >/dev/null 2>&1; then missing+=(ffmpeg); fi
    if [ "${HEARTH_NO_SLURM:-0}" != 1 ]; then
        PATH=$PATH:/usr/sbin command -v slurmctld >/dev/null 2>&1 || missing+=(slurm-wlm)
        PATH=$PATH:/usr/sbin command -v munged >/dev/null 2>&1 || missing+=(munge)
    fi
    [ ${#missing[@]} -eq 0 ] && return 0
    echo "hearth: installing optional Debian packages: ${missing[*]}" >&2
    local sudo=""
    [ "$(id -u)" -ne 0 ] && sudo="sudo"
    $sudo apt-get update -qq >&2 || true
    # one at a time: apt installs nothing of a list when one package of it fails
    local p
    for p in "${missing[@]}"; do
        $sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "$p" >&2 ||
            echo "hearth: optional package $p not installed; the tests that need it will skip" >&2
    done
    return 0
}

# hearth_build DIR [meson options...]: configure once, then build.
hearth_build() {
    local dir="$1"; shift
    if [ ! -f "$HEARTH_ROOT/$dir/build.ninja" ]; then
        meson setup "$HEARTH_ROOT/$dir" "$HEARTH_ROOT" "$@" >&2
    fi
    ninja -C "$HEARTH_ROOT/$dir" >&2
}
