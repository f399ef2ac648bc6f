#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# The shared library exports the public API and nothing else, and carries the
# SONAME libprojcurve.so.<major>.
# Usage: check_exports.sh path/to/libprojcurve.so MAJOR
set -euo pipefail

lib=$1 major=$2
for tool in nm readelf; do
    command -v "$tool" >/dev/null || { echo "SKIP: $tool not found"; exit 77; }
done

# nm -D --defined-only lists the dynamic symbols defined here; the version
# node (PROJCURVE_1, type A) is not a symbol of the API.
symbols=$(nm -D --defined-only "$lib" | awk '$2 != "A" { print $3 }' | sed 's/@.*//')
count=$(printf '%s\n' "$symbols" | grep -c . || true)
foreign=$(printf '%s\n' "$symbols" | grep -v '^projcurve_' | grep . || true)
if [[ -n $foreign ]]; then
    echo "FAIL: symbols exported without the projcurve_ prefix:"
    printf '  %s\n' $foreign
    exit 1
fi
if ! grep -qx projcurve_status_string <<<"$symbols"; then
    echo "FAIL: projcurve_status_string is not exported"
    exit 1
fi
# Every exported symbol is declared in the public header.
header=$(dirname "$0")/../../include/projcurve.h
for s in $symbols; do
    grep -q "\b$s(" "$header" || { echo "FAIL: $s is exported but not in projcurve.h"; exit 1; }
done
# And every function declared in projcurve.h is exported: no declaration
# without an implementation.
declared=$(grep -oE '^PROJCURVE_API [^(]*[ *]projcurve_[a-z0-9_]+\(' "$header" |
           grep -oE 'projcurve_[a-z0-9_]+\($' | tr -d '(')
for s in $declared; do
    grep -qx "$s" <<<"$symbols" || { echo "FAIL: $s is declared in projcurve.h but not exported"; exit 1; }
done
echo "$count exported symbols, all projcurve_* and declared in projcurve.h;" \
     "all $(wc -w <<<"$declared") declared functions exported"

soname=$(readelf -d "$lib" | sed -n 's/.*(SONAME).*\[\(.*\)\].*/\1/p')
if [[ $soname != "libprojcurve.so.$major" ]]; then
    echo "FAIL: SONAME is '$soname', expected libprojcurve.so.$major"
    exit 1
fi
echo "SONAME $soname"
