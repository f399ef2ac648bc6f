#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Regenerates abi/libprojcurve.abi, the stored description of the public ABI
# that abi/check.sh compares every build against. Run it after an intended
# ABI change (see docs/abi.md):
#   abi/update-baseline.sh            # configure + build a fresh Release copy
#   abi/update-baseline.sh BUILD_DIR  # or take BUILD_DIR/libprojcurve.so.*
# then review `git diff abi/` and commit it with the change.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
command -v abidw >/dev/null || { echo "abidw not found (Debian package abigail-tools)" >&2; exit 1; }

if [[ $# -ge 1 ]]; then
    build_dir=$(cd "$1" && pwd)
else
    build_dir=$(mktemp -d "${TMPDIR:-/tmp}/projcurve-abi.XXXXXX")
    trap 'rm -rf "$build_dir"' EXIT
    cmake -S "$root" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DPROJCURVE_BUILD_TESTS=OFF \
        -DPROJCURVE_BUILD_BENCH=OFF -DPROJCURVE_BUILD_CLI=OFF >/dev/null
    cmake --build "$build_dir" --target projcurve -j2 >/dev/null
fi
lib=$(find "$build_dir" -maxdepth 1 -name 'libprojcurve.so.*.*' -type f -print -quit)
[[ -n $lib ]] || { echo "no libprojcurve.so.X.Y.Z in $build_dir" >&2; exit 1; }

# Only the exported functions and the types declared in the public headers
# are kept (--exported-interfaces-only, --drop-private-types),
# and no source locations, so that editing a comment does not touch the file.
abidw --headers-dir "$root/include" --drop-private-types --exported-interfaces-only \
      --no-show-locs --short-locs \
      --no-corpus-path --no-comp-dir-path --out-file "$root/abi/libprojcurve.abi" "$lib"
echo "wrote abi/libprojcurve.abi from $lib:"
grep -c "<elf-symbol name='projcurve_" "$root/abi/libprojcurve.abi" | sed 's/$/ exported functions/'
