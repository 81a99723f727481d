#!/usr/bin/env bash
# plugin_sdk_test.sh CASE HEARTH BUILD_ROOT SOURCE_ROOT CC: a plugin author's
# view of hearth. The headers are taken from `meson install --tags devel` into
# a scratch folder, not from the source tree, so a helper that lives only in a
# private header, or a header that is not installed, fails here.
set -u
case_name=$1 hearth=$2 build=$3 src=$4 cc=$5
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

meson install -C "$build" --no-rebuild --quiet --tags devel --destdir "$tmp/root" >"$tmp/install.txt" 2>&1 ||
    fail "meson install --tags devel: $(cat "$tmp/install.txt")"
pc=$(find "$tmp/root" -name hearth.pc | head -1)
[ -n "$pc" ] || fail "hearth.pc was not installed"
# --cflags through the installed hearth.pc, rebased into the scratch root, as an author's build reads it
cflags=$(PKG_CONFIG_PATH=$(dirname "$pc") PKG_CONFIG_SYSROOT_DIR="$tmp/root" pkg-config --cflags hearth) ||
    fail "pkg-config --cflags hearth"
inc=$(find "$tmp/root" -type d -path '*/include/hearth' | head -1)
for h in material.h tensor.h hearth.h lab.h plot.h; do [ -f "$inc/$h" ] || fail "<hearth/$h> is not installed"; done
# the project's own warnings, as errors
warn="-std=c17 -Wall -Wextra -Wpedantic -Wshadow -Wmissing-prototypes -Werror"

case "$case_name" in
plugin_sdk_headers_standalone)
    # each installed header compiles alone, in C and in C++, and defines no symbol (tensor.h's
    # helpers are static inline); the host's headers too, as an embedding program includes them
    for h in material.h tensor.h hearth.h lab.h plot.h; do
        printf '#include <hearth/%s>\n' "$h" >"$tmp/one.c"
        "$cc" $warn $cflags -c "$tmp/one.c" -o "$tmp/one.o" 2>"$tmp/err.txt" || fail "<hearth/$h> alone: $(cat "$tmp/err.txt")"
        [ -z "$(nm --defined-only "$tmp/one.o" | awk '$2 ~ /^[TDBRC]$/')" ] ||
            fail "<hearth/$h> defines symbols: $(nm --defined-only "$tmp/one.o")"
        if command -v c++ >/dev/null; then
            printf '#include <hearth/%s>\n' "$h" >"$tmp/one.cc"
            c++ -std=c++17 -Wall -Wextra -Werror $cflags -c "$tmp/one.cc" -o "$tmp/one_cc.o" 2>"$tmp/err.txt" ||
                fail "<hearth/$h> from C++: $(cat "$tmp/err.txt")"
        fi
    done
    ;;
plugin_sdk_out_of_tree)
    # the shipped plugins built as an outside author builds them: installed headers, libm, nothing else
    for p in elastic snow_plastic cam_clay_dough von_mises_sauce maxwell_sph newtonian; do
        "$cc" $warn -O2 -fPIC -shared -fvisibility=hidden $cflags "$src/plugins/$p.c" -o "$tmp/hearth_$p.so" -lm \
            2>"$tmp/err.txt" || fail "$p.c with only the installed headers: $(cat "$tmp/err.txt")"
        # no symbol wanted from the host: everything undefined is libc's or libm's
        undef=$(nm -D --undefined-only "$tmp/hearth_$p.so" | awk '{print $NF}' | grep -v '@GLIBC' | grep -vE '^(_ITM_|__gmon_start__|__cxa_finalize)')
        [ -z "$undef" ] || fail "$p needs symbols from the host: $undef"
        out=$("$hearth" plugin check "$tmp/hearth_$p.so" 2>&1) || fail "plugin check $p (exit $?): $out"
    done
    ;;
plugin_sdk_uninstalled_pc)
    # an author who builds against a build folder without installing it (README, "Writing a material
    # plugin"): pkg-config prefers the build's meson-uninstalled/hearth-uninstalled.pc, whose Cflags must
    # reach <hearth/material.h>. Bar, set before the first run (#18, helper userview5): elastic.c builds
    # with them alone and passes `hearth plugin check`. Before the fix the .pc gave only core/sim's folders.
    cflags_u=$(PKG_CONFIG_PATH="$build/meson-uninstalled" pkg-config --cflags hearth) ||
        fail "pkg-config --cflags hearth with PKG_CONFIG_PATH=$build/meson-uninstalled"
    "$cc" $warn -O2 -fPIC -shared $cflags_u "$src/plugins/elastic.c" -o "$tmp/hearth_elastic.so" -lm \
        2>"$tmp/err.txt" || fail "elastic.c with the uninstalled .pc's Cflags ($cflags_u): $(cat "$tmp/err.txt")"
    out=$("$hearth" plugin check "$tmp/hearth_elastic.so" 2>&1) || fail "plugin check (exit $?): $out"
    ;;
*) fail "unknown case $case_name" ;;
esac
