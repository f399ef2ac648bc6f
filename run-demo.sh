#!/usr/bin/env bash
# Builds libprojcurve (Release, in ./build) and runs its demonstration: the
# `demo` target of CMakeLists.txt, which is `projcurve demo` once the
# command-line tool exists.
set -euo pipefail
cd "$(dirname "$0")"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j2
cmake --build build --target demo
