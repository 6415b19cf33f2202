#!/usr/bin/env bash
# Builds tripose inside OpenCV (scripts/build_opencv_intree.sh) and runs its tests there:
#   - opencv_test_tripose: the same C++ test sources as the standalone build, on OpenCV's own ts;
#   - modules/tripose/misc/python/test/test_tripose.py through OpenCV's Python test runner, with
#     the freshly built cv2 (Debian's python3 and numpy, which the bindings were compiled against).
#
#   bash scripts/test_intree.sh [4|5]      (default 4: OpenCV 4.12; 5: OpenCV 5.0)
#
# With TRIPOSE_INTREE_CPP_TESTS=0 (as the test command runs it) OpenCV is built without ts and the C++
# suite, which the standalone build and the sanitizer build run already: the exported symbols and
# the Python tests are checked.
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)

# The tests run under the build's lock (--run), so that a run from another checkout sharing the
# cache cannot rebuild the libraries while they are loaded.
if [ -z "${OPENCV_INTREE_BUILD:-}" ]; then
  exec bash "$repo/scripts/build_opencv_intree.sh" "${1:-4}" --run bash "$repo/scripts/test_intree.sh"
fi

export OPENCV_TEST_DATA_PATH="$repo/test/data"

echo "[intree] exported symbols of libopencv_tripose"
# Built with -fvisibility=hidden as OpenCV builds every module: the library exports its public API
# (cv::tripose functions, parameter structs, and the public classes' members, destructors, vtables
# and type information) and nothing of its internals (detail::, generated::, Eigen). A tripose symbol
# other than those, or anything of those namespaces, fails the run. (Instantiations of OpenCV's own
# exported templates may appear: they belong to OpenCV's API, not ours.)
library=$(ls "$OPENCV_INTREE_BUILD"/lib/libopencv_tripose.so* | head -n 1)
leaked=$(nm -D --defined-only "$library" | awk '{print $3}' | c++filt | grep tripose \
           | grep -v -E '^cv::tripose::[A-Za-z_]+(::~?[A-Za-z_]+)?\(' \
           | grep -v -E '^(vtable|typeinfo|typeinfo name) for cv::tripose::[A-Za-z_]+$' || true)
leaked_internal=$(nm -D --defined-only "$library" | awk '{print $3}' | c++filt \
                    | grep -E 'cv::tripose::(detail|generated)::|Eigen::' || true)
if [ -n "$leaked$leaked_internal" ]; then
  echo "[intree] libopencv_tripose exports symbols outside its public API:" >&2
  printf '%s\n%s\n' "$leaked" "$leaked_internal" | sed '/^$/d' | head -n 40 >&2
  exit 1
fi
echo "[intree] only cv::tripose's public API is exported ($(nm -D --defined-only "$library" | grep -c ' T ') functions)"

if [ "${TRIPOSE_INTREE_CPP_TESTS:-1}" = 1 ]; then
  echo "[intree] C++: opencv_test_tripose (the reduced suite)"
  (source "$repo/scripts/reduced_test_suite.sh" && "$OPENCV_INTREE_BUILD/bin/opencv_test_tripose" --gtest_color=no)
else
  echo "[intree] C++: not built (TRIPOSE_INTREE_CPP_TESTS=0)"
fi

echo "[intree] Python: test_tripose.py"
# The runner reads opencv_python_tests.cfg from the current folder to find module test folders.
(cd "$OPENCV_INTREE_BUILD" && PYTHONPATH="$OPENCV_INTREE_PYTHONPATH" OPENCV_PYTEST_FILTER=test_tripose \
   /usr/bin/python3 "$OPENCV_INTREE_SOURCE/modules/python/test/test.py" --repo "$OPENCV_INTREE_SOURCE" -v)
