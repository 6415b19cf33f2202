#!/usr/bin/env bash
# The test command of the README: installs the dependencies, builds, runs every test.
#   C++: the module's tests through ctest (standalone build against the system OpenCV),
#        the installed package consumed by test/consumer.
#   Python: pytest over codegen/ and test/; the Python package built as a manylinux wheel, installed
#        into a fresh virtual environment and tested there (scripts/test_python_package.sh).
#   Hardening: the C++ tests again under ASan + UBSan, then each fuzz target for 60 s.
#   OpenCV extra-module build: tripose inside OpenCV 4.12 with the cv2 bindings, its exported
#        symbols and the cv2.tripose Python tests. The C++ suite on OpenCV's own ts, which needs ts
#        and three more OpenCV modules built, runs the same test sources as the two builds above:
#        `bash scripts/test_intree.sh 4` (OpenCV 5.0: `bash scripts/test_intree.sh 5`) runs it too.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

bash scripts/install_dependencies.sh

# OpenCV for the in-tree test (scripts/test_intree.sh) takes minutes to compile whatever this
# checkout holds. Started now at the lowest priority, it runs on the cycles that the test runs below
# leave idle (most of them use one core) and is finished or nearly so when its test comes. It is
# built without the C++ suite (see above) and with clang, which needs a fifth less CPU time than gcc
# there; the standalone build compiles the module with gcc.
mkdir -p build
export TRIPOSE_INTREE_CPP_TESTS=0 TRIPOSE_OPENCV_COMPILER=clang
nice -n 19 bash scripts/build_opencv_intree.sh 4 > build/opencv-intree.log 2>&1 &
intree_build=$!
trap 'kill "$intree_build" 2>/dev/null || true' EXIT

# The standalone build and the package's wheel compile the core from the same sources with the
# same flags: through ccache (its cache in build/ccache) the wheel gets the standalone build's
# objects instead of compiling them again. Both name the compiler alike, which ccache's key includes.
export CCACHE_DIR="$root/build/ccache"
# The tests compile in batches of files (TRIPOSE_UNITY_TESTS), which halves their compile time.
CXX=/usr/bin/c++ cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_COMPILER_LAUNCHER=ccache \
  -DCMAKE_INSTALL_PREFIX="$root/build/install" -DTRIPOSE_UNITY_TESTS=ON >/dev/null
cmake --build build
cmake --install build >/dev/null

# A downstream project finds the installed package and links its one imported target.
cmake -S test/consumer -B build/consumer -G Ninja -DCMAKE_PREFIX_PATH="$root/build/install" >/dev/null
cmake --build build/consumer
build/consumer/tripose_consumer
# The installed headers on a plain compiler line, without anything the CMake target defines.
c++ -std=c++17 $(pkg-config --cflags opencv4) -I"$root/build/install/include" -fsyntax-only test/consumer/main.cpp

(cd build && ctest --output-on-failure)
.venv/bin/python codegen/generate.py --check
.venv/bin/python -m pytest -q

# The Python package (its wheel, which builds the OpenCV-free core on its own, repaired, installed
# in a fresh virtual environment, its tests run against it) beside the sanitizer job: the
# sanitizer run of the C++ suite is single-threaded for minutes, and the wheel's build uses the
# core it leaves idle. The package's output follows once both have finished.
CXX=/usr/bin/c++ CMAKE_CXX_COMPILER_LAUNCHER=ccache bash scripts/test_python_package.sh > build/python-package.log 2>&1 &
package_job=$!
# Hardening: the C++ suite under ASan + UBSan, then the two fuzz targets side by side for 60 s
# (figures in doc/studies/hardening.md).
sanitizer_status=0
bash scripts/test_sanitizers.sh || sanitizer_status=$?
package_status=0
wait "$package_job" || package_status=$?
cat build/python-package.log
if [ "$package_status" -ne 0 ] || [ "$sanitizer_status" -ne 0 ]; then
  echo "[test] the Python package (status $package_status) or the sanitizer run (status $sanitizer_status) failed" >&2
  exit 1
fi
bash scripts/fuzz.sh 60

if ! wait "$intree_build"; then
  tail -n 60 build/opencv-intree.log >&2
  echo "[test] building OpenCV with tripose inside failed; full log: build/opencv-intree.log" >&2
  exit 1
fi
bash scripts/test_intree.sh 4
