#!/usr/bin/env bash
# Builds the module, its C++ suite and the libFuzzer targets with clang in build-sanitizers/, all of
# it instrumented with AddressSanitizer, UndefinedBehaviorSanitizer and libFuzzer's coverage counters
# (cmake/TriposeFuzzing.cmake). One instrumented build serves both the suite under the sanitizers
# (scripts/test_sanitizers.sh) and fuzzing (scripts/fuzz.sh): the core is compiled once for the two.
# A second call rebuilds only what changed.
#
#   bash scripts/build_sanitizers.sh
#
# No perf tests, samples, benchmarks or evaluation: the samples' problem reader is compiled into its
# fuzz target. OpenCV itself is Debian's uninstrumented build; only tripose's own code is checked.
# clang's -fsanitize=undefined includes float-cast-overflow (out-of-range double-to-integer
# conversions), which gcc's does not.
set -euo pipefail
cd "$(dirname "$0")/.."
build=build-sanitizers

bash scripts/install_dependencies.sh

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -gline-tables-only" -DTRIPOSE_BUILD_FUZZERS=ON \
  -DTRIPOSE_BUILD_TESTS=ON -DTRIPOSE_UNITY_TESTS=ON -DTRIPOSE_BUILD_PERF_TESTS=OFF -DTRIPOSE_BUILD_SAMPLES=OFF \
  -DTRIPOSE_BUILD_BENCHMARKS=OFF -DTRIPOSE_BUILD_EVALUATION=OFF >/dev/null
nice cmake --build "$build" -j2 --target opencv_test_tripose fuzz_estimate_pose fuzz_problem_reader
