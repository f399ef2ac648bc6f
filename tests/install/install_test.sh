#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Installs the build tree into a temporary prefix, then builds and runs the
# consumers in this directory against the installed files only:
#   1. through pkg-config (C, and C++17 with the wrappers of projcurve.hpp;
#      shared library, strict warnings),
#   2. through find_package(projcurve CONFIG) (C and C++ shared, C static).
# Usage: install_test.sh CMAKE BUILD_DIR C_COMPILER CXX_COMPILER [EXTRA_FLAGS [CLI_NAME]]
# EXTRA_FLAGS (e.g. the sanitizer flags) are used to compile and link the
# consumers, since an instrumented library needs an instrumented program.
# CLI_NAME, when the build has the command-line tool, must be installed in bin/.
set -euo pipefail

cmake_exe=$1 build_dir=$2 cc=$3 cxx=$4 extra_flags=${5:-} cli_name=${6:-}
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/projcurve-install-test.XXXXXX")
trap 'rm -rf "$work"' EXIT
prefix=$work/prefix

"$cmake_exe" --install "$build_dir" --prefix "$prefix" >"$work/install.log"

pc_file=$(find "$prefix" -name projcurve.pc -print -quit)
config_file=$(find "$prefix" -name projcurveConfig.cmake -print -quit)
[[ -n $pc_file ]] || { echo "FAIL: projcurve.pc not installed"; exit 1; }
[[ -n $config_file ]] || { echo "FAIL: projcurveConfig.cmake not installed"; exit 1; }
[[ -f $prefix/include/projcurve.h && -f $prefix/include/projcurve_version.h &&
   -f $prefix/include/projcurve.hpp ]] ||
    { echo "FAIL: headers not installed"; exit 1; }
libdir=$(dirname "$(dirname "$pc_file")")
for lib in libprojcurve.so libprojcurve.so.1 libprojcurve.a; do
    [[ -e $libdir/$lib ]] || { echo "FAIL: $libdir/$lib not installed"; exit 1; }
done
if [[ -n $cli_name && ! -x $prefix/bin/$cli_name ]]; then
    echo "FAIL: the command-line tool $cli_name is not installed in $prefix/bin"; exit 1
fi

# --- 1. pkg-config -------------------------------------------------------
if command -v pkg-config >/dev/null; then
    export PKG_CONFIG_PATH=$(dirname "$pc_file")
    cflags=$(pkg-config --cflags projcurve)
    libs=$(pkg-config --libs projcurve)
    pc_libdir=$(pkg-config --variable=libdir projcurve)
    strict="-Wall -Wextra -Wpedantic -Werror"
    # shellcheck disable=SC2086  # flag lists are meant to split
    "$cc" -std=c11 $strict $extra_flags $cflags "$here/consumer.c" -o "$work/pc_c" \
        $libs "-Wl,-rpath,$pc_libdir"
    # shellcheck disable=SC2086
    "$cxx" -std=c++17 $strict $extra_flags $cflags "$here/consumer.cpp" -o "$work/pc_cpp" \
        $libs "-Wl,-rpath,$pc_libdir"
    "$work/pc_c"
    "$work/pc_cpp"
    # The programs must run against the installed library, not the build tree.
    grep -q "$prefix" <<<"$(ldd "$work/pc_c")" || { echo "FAIL: pc_c not linked to $prefix"; exit 1; }
    echo "pkg-config consumers: OK"
else
    echo "pkg-config not found: skipping the pkg-config consumers"
fi

# --- 2. find_package ------------------------------------------------------
"$cmake_exe" -S "$here" -B "$work/consumer" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_C_COMPILER="$cc" -DCMAKE_CXX_COMPILER="$cxx" \
    -DCMAKE_C_FLAGS="$extra_flags" -DCMAKE_CXX_FLAGS="$extra_flags" \
    -DCMAKE_EXE_LINKER_FLAGS="$extra_flags" >"$work/consumer.log"
"$cmake_exe" --build "$work/consumer" >>"$work/consumer.log"
"$work/consumer/consumer_c"
"$work/consumer/consumer_cpp"
"$work/consumer/consumer_c_static"
grep -q "$prefix" <<<"$(ldd "$work/consumer/consumer_c")" ||
    { echo "FAIL: consumer_c not linked to $prefix"; exit 1; }
if grep -q libprojcurve <<<"$(ldd "$work/consumer/consumer_c_static")"; then
    echo "FAIL: consumer_c_static depends on the shared library"; exit 1
fi
echo "find_package consumers: OK"

# Another major version is another ABI: the package must refuse it.
major=$(sed -n 's/^#define PROJCURVE_VERSION_MAJOR \([0-9]*\)$/\1/p' "$prefix/include/projcurve_version.h")
if "$cmake_exe" -S "$here" -B "$work/consumer_next" -DCMAKE_PREFIX_PATH="$prefix" \
        -DPROJCURVE_WANTED_VERSION=$((major + 1)) >"$work/next.log" 2>&1; then
    echo "FAIL: find_package(projcurve $((major + 1))) accepted version $major"; exit 1
fi
grep -q "compatible with requested version" "$work/next.log" ||
    { cat "$work/next.log"; echo "FAIL: unexpected find_package failure"; exit 1; }
echo "find_package(projcurve $((major + 1))) refused: OK"
