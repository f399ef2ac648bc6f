#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Compares a built libprojcurve.so with the stored baseline abi/libprojcurve.abi
# using libabigail's abidiff. Fails (exit 1) on
#   - an incompatible change (abidiff bit 8: a function removed), and
#   - any other change to the existing interface (bit 4 once additions are
#     ignored: a parameter or return type changed, an enumerator's value
#     changed, ...).
# Added functions and enumerators appended at the end of an enum are
# compatible and pass. Exits 77 (CTest "skipped") when abidiff is missing or
# the library has no debug information to compare.
# Usage: abi/check.sh path/to/libprojcurve.so.X.Y.Z   (or an abidw XML file)
set -uo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
lib=${1:?usage: abi/check.sh path/to/libprojcurve.so.X.Y.Z}
baseline=$root/abi/libprojcurve.abi

if ! command -v abidiff >/dev/null; then
    echo "SKIP: abidiff not found (install the Debian package abigail-tools)"
    exit 77
fi
is_elf() { [[ $(head -c 4 "$1" | od -An -c | tr -d ' ') == 177ELF ]]; }
# An ELF library must carry DWARF; an ABI XML corpus (as in the self-test) is
# compared as it is.
# (Here-strings, not pipes into grep -q: with pipefail an early exit of
# grep would make the writer's SIGPIPE look like a failure.)
if is_elf "$lib" && ! grep -q '\.debug_info' <<<"$(readelf -S "$lib" 2>/dev/null)"; then
    echo "SKIP: $lib has no debug information (configure with PROJCURVE_DEBUG_INFO=ON)"
    exit 77
fi

# For a library, keep only the types of the public headers, as abidw did
# for the baseline (abidiff rejects these options for an XML input).
filter=()
is_elf "$lib" && filter=(--headers-dir2 "$root/include" --drop-private-types --exported-interfaces-only)
abidiff "${filter[@]}" --no-added-syms "$baseline" "$lib"
rc=$?
if (( rc & 3 )); then
    echo "FAIL: abidiff could not compare (exit $rc)"
    exit 1
fi
if (( rc & 8 )); then
    echo "FAIL: incompatible ABI change (see above). If intended, bump the major version: docs/abi.md"
    exit 1
fi
if (( rc & 4 )); then
    echo "FAIL: the existing ABI changed (see above). If intended, bump the major version: docs/abi.md"
    exit 1
fi
echo "ABI compatible with abi/libprojcurve.abi"
