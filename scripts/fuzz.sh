#!/usr/bin/env bash
# Runs each libFuzzer target of test/fuzz (clang, ASan + UBSan; built with the C++ suite by
# scripts/build_sanitizers.sh in build-sanitizers/) for a while: first over the checked-in
# regression inputs (test/fuzz/regressions/<target>/, each a bug once found and fixed), then fuzzing
# from the seed corpus (test/fuzz/corpus/<target>/).
#
#   bash scripts/fuzz.sh            # 60 s per target (what the test command runs)
#   bash scripts/fuzz.sh 3600       # an hour per target
#
# New inputs go to build-sanitizers/corpus/<target>/ (the checked-in seeds are only read); a crash,
# a sanitizer report, a timeout or running out of memory leaves its input in
# build-sanitizers/artifacts/ and fails the script. The two targets fuzz side by side.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
seconds=${1:-60}
build="$root/build-sanitizers"

bash scripts/build_sanitizers.sh

export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
# max_len: the largest problem the API decoder reads is about 5 KB; problem files of a few dozen
# features stay under 16 KB. timeout: no single input may take longer than this (seconds); a
# timeout fails the run like a crash. The API's is set by its slowest legitimate path, the
# multi-start search of the RANSAC's refinement where the cost has several basins: 6 points and 6
# lines took 0.22 s in a release build (816 refinements, most of them 100 iterations) and 82 s
# here, where a typical input takes a quarter of a second. A hang still ends the run.
declare -A max_len=([fuzz_estimate_pose]=8192 [fuzz_problem_reader]=16384)
declare -A timeout=([fuzz_estimate_pose]=150 [fuzz_problem_reader]=5)

# fuzz TARGET: fuzzes for $seconds from the seed corpus.
fuzz() {
  local target=$1 work="$build/corpus/$1"
  mkdir -p "$work" "$build/artifacts"
  nice "$build/test/fuzz/$target" "$work" "test/fuzz/corpus/$target" \
    -max_total_time="$seconds" -max_len="${max_len[$target]}" -timeout="${timeout[$target]}" \
    -error_exitcode=77 -artifact_prefix="$build/artifacts/$target-" -print_final_stats=1
}

for target in fuzz_estimate_pose fuzz_problem_reader; do
  regressions="test/fuzz/regressions/$target"
  if compgen -G "$regressions/*" >/dev/null; then
    echo "[fuzz] $target: replaying $regressions"
    "$build/test/fuzz/$target" -timeout="${timeout[$target]}" "$regressions"/* 2>"$build/$target.replay.log" ||
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
echo "[fuzz] no crash, no timeout"
