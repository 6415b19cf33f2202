#!/usr/bin/env bash
# The demo command of the README: installs the dependencies, builds, and estimates the pose of the
# third view of the bundled Merton College I triplet (Oxford VGG multi-view data) from its points
# and lines, printing the estimate beside the ground truth and writing an overlay image.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build --target tripose_demo_vgg
mkdir -p build/demo
build/samples/tripose_demo_vgg --data test/data/vgg/Merton-College-I --views 0 1 2 \
  --image test/data/vgg/Merton-College-I/003.jpg --output build/demo/merton_college_i_view3.png
