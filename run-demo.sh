#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Builds libprojcurve (Release, in ./build-demo, without tests and benchmarks)
# and runs its demonstration: the `demo` target of CMakeLists.txt, which is
# `projcurve demo` once the command-line tool exists.
set -euo pipefail
cd "$(dirname "$0")"
cmake -S . -B build-demo -DCMAKE_BUILD_TYPE=Release \
      -DPROJCURVE_BUILD_TESTS=OFF -DPROJCURVE_BUILD_BENCH=OFF >/dev/null
cmake --build build-demo -j2
cmake --build build-demo --target demo
