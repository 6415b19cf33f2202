#!/usr/bin/env bash
# Builds the libFuzzer targets of test/fuzz with clang (ASan + UBSan, in build-fuzz/) and runs each
# for a while: first over the checked-in regression inputs (test/fuzz/regressions/<target>/, each a
# bug once found and fixed), then fuzzing from the seed corpus (test/fuzz/corpus/<target>/).
#
#   bash scripts/fuzz.sh            # 60 s per target (what the test command runs)
#   bash scripts/fuzz.sh 3600       # an hour per target
#
# New inputs go to build-fuzz/corpus/<target>/ (the checked-in seeds are only read); a crash
# leaves its input in build-fuzz/artifacts/ and fails the script. The two targets fuzz side by side.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
seconds=${1:-60}
build="$root/build-fuzz"

bash scripts/install_dependencies.sh

cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++-14 \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g" -DTRIPOSE_BUILD_FUZZERS=ON \
  -DTRIPOSE_BUILD_TESTS=OFF -DTRIPOSE_BUILD_PERF_TESTS=OFF -DTRIPOSE_BUILD_SAMPLES=OFF \
  -DTRIPOSE_BUILD_BENCHMARKS=OFF -DTRIPOSE_BUILD_EVALUATION=OFF >/dev/null
nice cmake --build "$build" -j2 --target fuzz_estimate_pose fuzz_problem_reader

export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# max_len: the largest problem the API decoder reads is about 5 KB; problem files of a few dozen
# features stay under 16 KB. timeout: no single input may take longer than this (seconds).
declare -A max_len=([fuzz_estimate_pose]=8192 [fuzz_problem_reader]=16384)
# OpenCV 4.6's YAML parser never returns on some corrupt text (e.g. "%YAML:1.0\n  t:d\n(oc-\n"),
# inside cv::FileStorage::open, beyond what the reader can guard. For the reader a timeout is
# therefore saved (build-fuzz/artifacts/fuzz_problem_reader-timeout-*), listed, and fuzzing goes
# on for the rest of its time; a crash, a sanitizer report or running out of memory still fails.
# The API target has no third-party parser in the loop: a timeout there fails the run.
declare -A timeout=([fuzz_estimate_pose]=20 [fuzz_problem_reader]=5)
declare -A timeouts_tolerated=([fuzz_estimate_pose]=0 [fuzz_problem_reader]=1)
timeout_status=70

# fuzz TARGET: fuzzes for $seconds in total, in several runs if tolerated timeouts cut one short.
fuzz() {
  local target=$1 work="$build/corpus/$1" end=$(( $(date +%s) + seconds )) status
  mkdir -p "$work" "$build/artifacts"
  while :; do
    local left=$(( end - $(date +%s) ))
    [ "$left" -gt 0 ] || return 0
    status=0
    nice "$build/test/fuzz/$target" "$work" "test/fuzz/corpus/$target" \
      -max_total_time="$left" -max_len="${max_len[$target]}" -timeout="${timeout[$target]}" \
      -timeout_exitcode=$timeout_status -error_exitcode=77 \
      -artifact_prefix="$build/artifacts/$target-" -print_final_stats=1 || status=$?
    [ "$status" -eq 0 ] && return 0
    [ "$status" -eq $timeout_status ] && [ "${timeouts_tolerated[$target]}" -eq 1 ] || return "$status"
  done
}

for target in fuzz_estimate_pose fuzz_problem_reader; do
  regressions="test/fuzz/regressions/$target"
  if compgen -G "$regressions/*" >/dev/null; then
    echo "[fuzz] $target: replaying $regressions"
    "$build/test/fuzz/$target" "$regressions"/* 2>"$build/$target.replay.log" ||
      { cat "$build/$target.replay.log" >&2; exit 1; }
  fi
done

# The targets run side by side (one per core); each writes its own log.
pids=()
for target in fuzz_estimate_pose fuzz_problem_reader; do
  echo "[fuzz] $target: ${seconds} s from test/fuzz/corpus/$target (log: $build/$target.log)"
  fuzz "$target" >"$build/$target.log" 2>&1 &
  pids+=($!)
done
failed=0
for i in 0 1; do
  target=$([ "$i" -eq 0 ] && echo fuzz_estimate_pose || echo fuzz_problem_reader)
  if wait "${pids[$i]}"; then
    echo "[fuzz] $target: $(grep -E '^Done [0-9]+ runs' "$build/$target.log" | tr '\n' ' ')"
  else
    echo "[fuzz] $target FAILED; the end of its log:" >&2
    tail -n 60 "$build/$target.log" >&2
    failed=1
  fi
done
[ "$failed" -eq 0 ] || exit 1
if compgen -G "$build/artifacts/fuzz_problem_reader-timeout-*" >/dev/null; then
  echo "[fuzz] inputs on which OpenCV's parser did not return (known, not a failure):"
  ls "$build/artifacts/"fuzz_problem_reader-timeout-*
fi
echo "[fuzz] no crash"
