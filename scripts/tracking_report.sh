#!/usr/bin/env bash
# The drift table of doc/studies/tracking.md: tripose_track on every VGG sequence with more than three
# frames, per method, window and local adjustment (--local-refine); time per frame is the median over
# RUNS runs (default 5) of the tracker's mean time per registered frame.
#
#   bash scripts/tracking_report.sh [build dir] [data dir]
set -euo pipefail
build=${1:-build}
data=${2:-test/data/vgg}
runs=${RUNS:-5}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
echo "| sequence | frames | method | window | local adjustment | drift (% of path) | last frame rot (deg) | ms per frame |"
echo "| --- | --- | --- | --- | --- | --- | --- | --- |"
for sequence in Corridor Model-House Wadham-College; do
  for method in linear ransac; do
    for window in 2 3 4 5 10; do
      for adjust in 0 1; do
        [ "$method" = linear ] && [ "$adjust" != 0 ] && continue
        times=()
        for ((r = 0; r < runs; ++r)); do
          log=$("$build/test/evaluation/tripose_track_vgg" --data "$data/$sequence" --output "$out/track.yml" --window "$window" \
                  --method "$method" --local-refine "$adjust")
          times+=("$(echo "$log" | sed -n 's/.*; \([0-9.]*\) ms per frame/\1/p')")
        done
        drift=$(echo "$log" | sed -n 's/Drift of the last frame: \([0-9.na]*\) %.*/\1/p')
        frames=$(echo "$log" | sed -n 's/.*: \([0-9]*\) frames,.*/\1/p')
        rot=$(echo "$log" | awk -v last=$((frames - 1)) '$1 == last && $2 == "registered" { print $6 }')
        median=$(printf '%s\n' "${times[@]}" | sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }')
        echo "| $sequence | $frames | $method | $window | $([ "$adjust" = 0 ] && echo no || echo yes) | $drift | $rot | $median |"
      done
    done
  done
done
