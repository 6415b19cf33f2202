#!/usr/bin/env bash
# Runs the C++ suite under AddressSanitizer + UndefinedBehaviorSanitizer (clang, the instrumented
# build of scripts/build_sanitizers.sh in build-sanitizers/), in two shards side by side. Fails on
# any sanitizer report: UB aborts the test (-fno-sanitize-recover), ASan/LSan exit non-zero, and the
# log is also searched for reports in case a child process swallowed the exit status.
#
#   bash scripts/test_sanitizers.sh
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
build="$root/build-sanitizers"

bash scripts/build_sanitizers.sh

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:halt_on_error=1:check_initialization_order=1:strict_init_order=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# Under the sanitizers the suite runs single-threaded some 25 times slower: the reduced suite.
source "$root/scripts/reduced_test_suite.sh"
log="$build/ctest.log"
status=0
# The suite as two GoogleTest shards side by side: under the sanitizers one process runs it for
# minutes on one core, and by then the package's wheel, built beside this job, has left the other.
shards=2
pids=()
for ((i = 0; i < shards; ++i)); do
  (cd "$build/modules/tripose" && GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i \
     OPENCV_TEST_DATA_PATH="$root/test/data" ./opencv_test_tripose --gtest_color=no) > "$build/shard$i.log" 2>&1 &
  pids+=($!)
done
for pid in "${pids[@]}"; do
  wait "$pid" || status=$?
done
cat "$build"/shard*.log > "$log"
grep -E "^\[  (PASSED|FAILED)  \]|^\[==========\] .* ran" "$log" || true
if [ "$status" -ne 0 ]; then
  grep -B 20 -E "^\[  FAILED  \]" "$log" | head -n 200 >&2 || true
fi
if grep -qE "runtime error:|ERROR: (Address|Leak)Sanitizer|SUMMARY: (Address|UndefinedBehavior|Leak)Sanitizer" "$log"; then
  echo "[sanitizers] sanitizer report found in $log" >&2
  exit 1
fi
if [ "$status" -ne 0 ]; then
  echo "[sanitizers] the C++ suite failed" >&2
  exit "$status"
fi
echo "[sanitizers] clean"
