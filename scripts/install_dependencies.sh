#!/usr/bin/env bash
# Installs everything tripose needs, idempotently and quickly when it is already there:
#  - Debian packages (compiler, CMake, Ninja, OpenCV 4.6, Eigen 3.4, GoogleTest, libyaml, Python
#    headers, clang with libFuzzer, ccache, valgrind);
#  - a Python virtual environment in .venv from the pinned requirements/python.txt.
set -euo pipefail
cd "$(dirname "$0")/.."

apt_packages=(build-essential cmake ninja-build pkg-config
              libopencv-dev libeigen3-dev libgtest-dev
              libopencv-contrib-dev          # ximgproc (EDLines), line_descriptor (LBD) for the samples on images
              libyaml-dev                    # the problem reader of the command-line tools
              python3 python3-dev python3-venv python3-numpy
              clang-14 libclang-rt-14-dev    # libFuzzer for scripts/fuzz.sh
              ccache                         # the test command compiles the core once for two builds
              valgrind)                      # callgrind counts the hot paths' instructions (test_instruction_guard.py)

missing=()
for p in "${apt_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "[deps] apt-get install ${missing[*]}"
  sudo_cmd=""; [ "$(id -u)" -ne 0 ] && sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# Debian's python3 (the one python3-dev belongs to) so that the OpenCV in-tree build and the venv agree.
venv=.venv
stamp="$venv/.requirements.sha256"
want=$(sha256sum requirements/python.txt | cut -d' ' -f1)
if [ ! -x "$venv/bin/python" ] || [ "$(cat "$stamp" 2>/dev/null)" != "$want" ]; then
  echo "[deps] creating $venv from requirements/python.txt"
  /usr/bin/python3 -m venv "$venv"
  "$venv/bin/pip" install -q --disable-pip-version-check -r requirements/python.txt
  echo "$want" > "$stamp"
fi
echo "[deps] ready"
