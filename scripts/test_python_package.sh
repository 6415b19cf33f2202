#!/usr/bin/env bash
# The Python package as a user gets it: `pip wheel .` builds the wheel (the OpenCV-free core and the
# extension only: the build never looks for OpenCV), auditwheel repairs it into a manylinux wheel,
# which is installed into a fresh virtual environment; the package's tests (python/tests) then run
# against that installation, not the source tree.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
out=build/python-package
rm -rf "$out/wheel" "$out/wheelhouse" "$out/venv"
mkdir -p "$out"

.venv/bin/pip wheel --no-deps --disable-pip-version-check -q -w "$out/wheel" .
PATH="$root/.venv/bin:$PATH" .venv/bin/auditwheel repair -w "$out/wheelhouse" "$out"/wheel/tripose-*.whl >/dev/null
wheel=$(ls "$out"/wheelhouse/tripose-*.whl)
echo "[package] $(basename "$wheel"): $(du -k "$wheel" | cut -f1) KiB"

/usr/bin/python3 -m venv "$out/venv"
"$out/venv/bin/pip" install -q --disable-pip-version-check "$wheel" -r requirements/python-package-tests.txt
# From outside the repository, so that `import tripose` can only find the installed package.
cd "$out"
TRIPOSE_REPO="$root" "$root/$out/venv/bin/python" -m pytest -q -p no:cacheprovider "$root/python/tests"
