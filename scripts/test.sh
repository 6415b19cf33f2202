#!/usr/bin/env bash
# The test command of the README: installs the dependencies, builds, runs every test.
#   C++: the module's tests through ctest (standalone build against the system OpenCV),
#        the installed package consumed by test/consumer.
#   Python: pytest over codegen/ and test/; the Python package built as a manylinux wheel, installed
#        into a fresh virtual environment and tested there (scripts/test_python_package.sh).
#   Hardening: the C++ tests again under ASan + UBSan, then each fuzz target for 60 s.
#   OpenCV extra-module build: tripose inside OpenCV 4.12, its C++ tests on OpenCV's ts and the
#        cv2.tripose Python tests (scripts/test_intree.sh; OpenCV 5.0: scripts/test_intree.sh 5).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)

bash scripts/install_dependencies.sh

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_INSTALL_PREFIX="$root/build/install" >/dev/null
cmake --build build
cmake --install build >/dev/null

# A downstream project finds the installed package and links its one imported target.
cmake -S test/consumer -B build/consumer -G Ninja -DCMAKE_PREFIX_PATH="$root/build/install" >/dev/null
cmake --build build/consumer
build/consumer/tripose_consumer

(cd build && ctest --output-on-failure)
.venv/bin/python codegen/generate.py --check
.venv/bin/python -m pytest -q

# The Python package: its wheel (which builds the OpenCV-free core on its own), repaired, installed
# in a fresh virtual environment, its tests run against it (about 4 minutes).
bash scripts/test_python_package.sh

# Hardening: about 7.5 minutes on two idle cores (sanitizer build ~4 min + tests 1 min, fuzz build
# ~1.5 min + the two targets side by side for 60 s); measured figures in the README.
bash scripts/test_sanitizers.sh
bash scripts/fuzz.sh 60

bash scripts/test_intree.sh 4
