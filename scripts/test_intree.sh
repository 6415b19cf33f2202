#!/usr/bin/env bash
# Builds tripose inside OpenCV (scripts/build_opencv_intree.sh) and runs its tests there:
#   - opencv_test_tripose: the same C++ test sources as the standalone build, on OpenCV's own ts;
#   - modules/tripose/misc/python/test/test_tripose.py through OpenCV's Python test runner, with
#     the freshly built cv2 (Debian's python3 and numpy, which the bindings were compiled against).
#
#   bash scripts/test_intree.sh [4|5]      (default 4: OpenCV 4.12; 5: OpenCV 5.0)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)

out=$(bash "$repo/scripts/build_opencv_intree.sh" "${1:-4}" | tee /dev/stderr)
bld=$(sed -n 's/^OPENCV_INTREE_BUILD=//p' <<<"$out")
pythonpath=$(sed -n 's/^OPENCV_INTREE_PYTHONPATH=//p' <<<"$out")
opencv_src=$(sed -n 's/^OPENCV_INTREE_SOURCE=//p' <<<"$out")

export OPENCV_TEST_DATA_PATH="$repo/test/data"

echo "[intree] C++: opencv_test_tripose"
"$bld/bin/opencv_test_tripose" --gtest_color=no

echo "[intree] Python: test_tripose.py"
# The runner reads opencv_python_tests.cfg from the current folder to find module test folders.
(cd "$bld" && PYTHONPATH="$pythonpath" OPENCV_PYTEST_FILTER=test_tripose \
   /usr/bin/python3 "$opencv_src/modules/python/test/test.py" --repo "$opencv_src" -v)
