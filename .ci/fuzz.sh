#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Fuzzes every file reader, the projection pipeline and the IGES and STEP
# writers with libFuzzer for a bounded time.
#   .ci/fuzz.sh [SECONDS_PER_TARGET]   (default 30, seven targets run one
#                                       per core: 2 min on 2 cores;
#                                       PROJCURVE_FUZZ_SECONDS also works)
#   PROJCURVE_FUZZ_KEEP_CORPUS=1 keeps the corpus of earlier runs.
# Builds the targets of tests/fuzz with clang (-DPROJCURVE_FUZZ=ON) in
# build-fuzz/, first runs every file of the committed corpora
# (tests/fuzz/corpus/: the pipeline targets' minimised seeds and the inputs
# of past findings) through ctest, then seeds each target from tests/data,
# tests/fuzz/seeds and tests/fuzz/corpus, and stops at the first crash, leak
# or input slower than 10 s (-timeout; a pipeline input makes two
# projections of at most 2 s each, FUZZ_TIME_LIMIT in tests/fuzz/fuzz_shapes.h;
# the reproducer is left in build-fuzz/artifacts/).
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-${PROJCURVE_FUZZ_SECONDS:-30}}
if ! [[ $seconds =~ ^[1-9][0-9]*$ ]]; then
    echo "fuzz.sh: seconds per target must be a positive integer, not '$seconds'" >&2
    exit 2
fi
# Fuzzing is part of CI: a machine that cannot build the targets fails it.
if ! command -v clang >/dev/null; then
    echo "fuzz.sh: clang not found (the fuzz targets need clang's libFuzzer)" >&2
    exit 1
fi
probe=$(mktemp -d)
trap 'rm -rf "$probe"' EXIT
echo 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n) { return d && n; }' \
    >"$probe/probe.c"
if ! clang -fsanitize=fuzzer "$probe/probe.c" -o "$probe/probe" 2>/dev/null; then
    echo "fuzz.sh: clang cannot link -fsanitize=fuzzer (Debian/Ubuntu: libclang-rt-N-dev)" >&2
    exit 1
fi

cmake -S . -B build-fuzz -DCMAKE_C_COMPILER=clang -DCMAKE_BUILD_TYPE=RelWithDebInfo \
      -DPROJCURVE_FUZZ=ON -DPROJCURVE_BUILD_BENCH=OFF -DPROJCURVE_BUILD_CLI=OFF
targets=(iges step gismo teapot project iges_write step_write)
cmake --build build-fuzz -j2 --target "${targets[@]/#/fuzz_}"
# Every file of the committed corpora once: a past finding fails here.
ctest --test-dir build-fuzz -R '^fuzz_.*_corpus$' --output-on-failure -j2

test_data=tests/data
declare -A seeds=(
    [iges]="$test_data/cases tests/fuzz/seeds/iges_analytic.igs"
    [step]="$test_data/real/test-joinsurf_01.stp tests/fuzz/seeds/step_complex_rational.stp $test_data/cases-brep/cylinder_analytic.step $test_data/cases-brep/gtest_cone_line_circle.step"
    [gismo]="$test_data/real/horn.xml $test_data/real/shroud_kaplan.xml"
    [teapot]="$test_data/real/teapot_newell_spd.txt"
    [project]="tests/fuzz/corpus/project"
    [iges_write]="tests/fuzz/corpus/iges_write"
    [step_write]="tests/fuzz/corpus/iges_write"
)
mkdir -p build-fuzz/artifacts
# Prepares the corpus of target $1 and fuzzes it; its output goes to
# build-fuzz/fuzz_$1.log (printed after the run, so parallel runs do not mix).
fuzz_target() {
    local reader=$1 corpus=build-fuzz/corpus/$1 seed
    # Each run starts from the seeds: a corpus grown by earlier runs takes
    # longer to load than the time budget (PROJCURVE_FUZZ_KEEP_CORPUS=1
    # keeps it for longer local runs).
    if [[ ${PROJCURVE_FUZZ_KEEP_CORPUS:-0} != 1 ]]; then
        rm -rf "$corpus"
    fi
    mkdir -p "$corpus"
    for seed in ${seeds[$reader]}; do
        if [[ -d $seed && $seed == tests/fuzz/corpus/* ]]; then cp -n "$seed"/* "$corpus"/
        elif [[ -d $seed ]]; then cp -n "$seed"/*.igs "$corpus"/ 2>/dev/null || true
        elif [[ -f $seed ]]; then cp -n "$seed" "$corpus"/
        fi
    done
    # The pipeline targets read at most ~300 bytes (fuzz_shapes.c).
    local max_len=()
    [[ $reader == project || $reader == *_write ]] && max_len=(-max_len=512)
    build-fuzz/tests/fuzz/fuzz_$reader -max_total_time="$seconds" -timeout=10 \
        -rss_limit_mb=2048 -print_final_stats=1 "${max_len[@]}" \
        -artifact_prefix=build-fuzz/artifacts/"$reader"- "$corpus" \
        >"build-fuzz/fuzz_$reader.log" 2>&1
}

# The targets run side by side, one per core (each libFuzzer run is one
# process): the wall time is the per-target time times targets / cores.
parallel=$(nproc 2>/dev/null || echo 1)
((parallel >= 1)) || parallel=1
failed=()
for ((first = 0; first < ${#targets[@]}; first += parallel)); do
    batch=("${targets[@]:first:parallel}")
    pids=()
    for reader in "${batch[@]}"; do
        echo "==== fuzz_$reader: ${seconds}s ===="
        fuzz_target "$reader" &
        pids+=($!)
    done
    for i in "${!batch[@]}"; do
        if ! wait "${pids[$i]}"; then failed+=("${batch[$i]}"); fi
        echo "---- fuzz_${batch[$i]} ----"
        cat "build-fuzz/fuzz_${batch[$i]}.log"
    done
done
if ((${#failed[@]})); then
    echo "fuzzing found a crash, leak or slow input in: ${failed[*]} (reproducers in build-fuzz/artifacts/)" >&2
    exit 1
fi
echo "fuzzing: no crash, leak or slow input found"
