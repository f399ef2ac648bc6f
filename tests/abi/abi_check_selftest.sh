#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Shows that abi/check.sh can fail: the stored baseline compared with itself
# passes, and with copies of it that remove a function or change an
# enumerator's value fails. Exit 77 when abidiff is missing.
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
check=$root/abi/check.sh
baseline=$root/abi/libprojcurve.abi
command -v abidiff >/dev/null || { echo "SKIP: abidiff not found"; exit 77; }
work=$(mktemp -d "${TMPDIR:-/tmp}/projcurve-abi-selftest.XXXXXX")
trap 'rm -rf "$work"' EXIT

expect() { # expected-exit-code description file
    local rc=0
    "$check" "$3" >"$work/out.txt" 2>&1 || rc=$?
    if [[ $rc != "$1" ]]; then
        cat "$work/out.txt"
        echo "FAIL: $2: abi/check.sh exited $rc, expected $1"
        exit 1
    fi
    echo "ok: $2 -> exit $rc"
}

expect 0 "baseline against itself" "$baseline"

sed -e "/<elf-symbol name='projcurve_context_create'/d" \
    -e "/<function-decl name='projcurve_context_create'/,/<\/function-decl>/d" \
    "$baseline" >"$work/removed.abi"
cmp -s "$baseline" "$work/removed.abi" && { echo "FAIL: mutation did not apply"; exit 1; }
expect 1 "projcurve_context_create removed" "$work/removed.abi"

sed -e "s/name='PROJCURVE_ERR_NULL_ARGUMENT' value='1'/name='PROJCURVE_ERR_NULL_ARGUMENT' value='31'/" \
    "$baseline" >"$work/enum.abi"
cmp -s "$baseline" "$work/enum.abi" && { echo "FAIL: mutation did not apply"; exit 1; }
expect 1 "enumerator value changed" "$work/enum.abi"
