#!/usr/bin/env bash
# Builds tripose as an OpenCV extra module (-DOPENCV_EXTRA_MODULES_PATH=<repo>/modules) inside a
# minimal OpenCV: only the modules tripose needs, OpenCV's test module (ts) and the Python 3
# bindings, and only the targets the tests use (opencv_test_tripose, cv2; opencv_perf_tripose with
# TRIPOSE_INTREE_PERF=1).
#
#   bash scripts/build_opencv_intree.sh [4|5|<sdist version>] [--run COMMAND...]   (default 4 = 4.12.0.88)
#
# The OpenCV sources come from the source distribution of opencv-contrib-python-headless on the
# package index pip uses (it holds opencv/ and opencv_contrib/); nothing else is downloaded.
# Everything is cached in $TRIPOSE_OPENCV_CACHE (default ~/.cache/tripose, outside the work tree so
# that a fresh clone on the same machine reuses it): the archive, the unpacked sources and the
# build folder, so a second run only recompiles what changed. Runs are serialised by a lock.
#
# Prints, as its last lines, the paths the tests need (and exports them to --run's COMMAND):
#   OPENCV_INTREE_BUILD=<build folder>   (bin/opencv_test_tripose)
#   OPENCV_INTREE_PYTHONPATH=<folder holding the cv2 package>
#   OPENCV_INTREE_SOURCE=<opencv source folder>
# With --run, COMMAND runs after the build while the lock is still held, so that another checkout
# sharing the cache cannot relink the libraries under the tests.
# Environment: TRIPOSE_OPENCV_JOBS (default 2), TRIPOSE_OPENCV_NICE (default 15), TRIPOSE_INTREE_PERF
# (1: build the perf tests too, and everything at -O3), TRIPOSE_INTREE_CPP_TESTS (0: neither ts nor
# the modules only it needs, nor opencv_test_tripose: the module and cv2 alone, for the Python tests),
# TRIPOSE_OPENCV_COMPILER (gcc, the default, or clang: clang-14, in a build folder of its own).
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)

which=4
if [ $# -gt 0 ] && [ "$1" != "--run" ]; then which=$1; shift; fi
run=()
if [ $# -gt 0 ]; then
  [ "$1" = "--run" ] && [ $# -gt 1 ] || { echo "usage: $0 [4|5|<version>] [--run COMMAND...]" >&2; exit 2; }
  shift
  run=("$@")
fi
case "$which" in
  4|4.x|4.12) version=4.12.0.88 ;;
  5|5.x|5.0)  version=5.0.0.93 ;;
  *)          version=$which ;;
esac
package=opencv-contrib-python-headless
cache=${TRIPOSE_OPENCV_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/tripose}
jobs=${TRIPOSE_OPENCV_JOBS:-2}
niceness=${TRIPOSE_OPENCV_NICE:-15}
python=/usr/bin/python3   # Debian's python3: python3-dev and python3-numpy belong to it

root="$cache/opencv-$version"
src="$root/src"
bld="$root/build"
# clang compiles this build in about four fifths of gcc's CPU time (1117 against 1394 s without the
# C++ suite); the test command uses it. Each compiler keeps its own build folder, so that switching
# does not recompile everything.
case "${TRIPOSE_OPENCV_COMPILER:-gcc}" in
  gcc)   compilers=() ;;
  clang) compilers=(-DCMAKE_C_COMPILER=clang-14 -DCMAKE_CXX_COMPILER=clang++-14); bld="$root/build-clang" ;;
  *)     echo "TRIPOSE_OPENCV_COMPILER must be gcc or clang, not '$TRIPOSE_OPENCV_COMPILER'" >&2; exit 2 ;;
esac
mkdir -p "$root"

# One build at a time per OpenCV version (the developer's tree and CI may share the cache). The
# descriptor stays open through --run's exec, so the lock covers the tests too.
exec 9>"$root/.lock"
flock 9

seconds() { date +%s; }
t_start=$(seconds)
log() { echo "[opencv-intree $version] $*" >&2; }

# 1. The sdist, checked against the sha256 that the index publishes. The index is the one pip is
#    configured with, so ask a Python that has pip: the project's venv, else the system one.
fetch_python="$repo/.venv/bin/python"
[ -x "$fetch_python" ] || fetch_python=$python
archive=$("$fetch_python" "$repo/scripts/opencv/fetch_sdist.py" "$package" "$version" "$cache/sdist")

# 2. Unpack opencv/ only (opencv_contrib/ is not needed to build tripose).
if [ ! -f "$src/.unpacked" ] || [ "$(cat "$src/.unpacked")" != "$(basename "$archive")" ]; then
  log "unpacking $(basename "$archive")"
  rm -rf "$src"
  mkdir -p "$src"
  tar -xzf "$archive" -C "$src" --strip-components=1 --wildcards '*/opencv/*'
  basename "$archive" > "$src/.unpacked"
fi
opencv_src="$src/opencv"
t_unpacked=$(seconds)

# 3. Which modules tripose needs depends on the OpenCV generation: 4.x has calib3d (which pulls
#    features2d and flann); 5.x split it, and Rodrigues/undistortPoints/triangulatePoints live in
#    geometry. ts additionally pulls imgcodecs, videoio and highgui (built without any backend).
#    python_tests (no code) writes opencv_python_tests.cfg, from which OpenCV's Python test runner
#    finds modules/tripose/misc/python/test. BUILD_LIST expands to the required dependencies by
#    itself; they are listed for the reader.
cpp_tests=${TRIPOSE_INTREE_CPP_TESTS:-1}
if [ -d "$opencv_src/modules/calib3d" ]; then
  modules=core,imgproc,calib3d,features2d,flann,python3,python_tests,tripose
else
  modules=core,imgproc,geometry,flann,python3,python_tests,tripose
fi
if [ "$cpp_tests" = 1 ]; then modules+=,ts,imgcodecs,videoio,highgui; fi

# Everything not needed is off: no media, GUI, codecs, accelerators, and no downloads at configure
# time (IPP, ADE, ...: only the package registries are reachable). CPU_DISPATCH is emptied so that
# no extra AVX2/AVX-512 copies of the kernels are compiled: the baseline build is enough for tests.
# No ccache, which OpenCV would use if installed: the build folder is kept between runs, and on a
# first build a cache only misses, at a cost.
# This build is there to compile the module inside OpenCV and run its tests on OpenCV's ts, not to
# be fast. OpenCV's own modules are compiled without optimization (-O0), tripose's library and tests
# at -O1 (scripts/opencv/tripose_optimization.cmake), so that its suite runs at a useful speed.
# Neither GCC nor clang reorders floating-point arithmetic without -ffast-math at any level (and the
# baseline x86-64 target has no fused multiply-add), so the level does not change the results.
# The perf tests, built on request, get -O3 everywhere: their timings are
# meant to be read (switching rebuilds everything).
optimization=-O0
tripose_optimization=-O1
if [ "${TRIPOSE_INTREE_PERF:-0}" = 1 ]; then optimization=-O3; tripose_optimization=-O3; fi
cmake_args=(
  -G Ninja
  "${compilers[@]}"
  -DCMAKE_BUILD_TYPE=Release
  -DCMAKE_CXX_FLAGS_RELEASE="$optimization" -DCMAKE_C_FLAGS_RELEASE="$optimization"
  -DCMAKE_PROJECT_OpenCV_INCLUDE="$repo/scripts/opencv/tripose_optimization.cmake"
  -DTRIPOSE_INTREE_OPTIMIZATION="$tripose_optimization"
  -DOPENCV_EXTRA_MODULES_PATH="$repo/modules"
  -DBUILD_LIST="$modules"
  -DBUILD_TESTS=ON -DBUILD_PERF_TESTS=ON
  -DBUILD_EXAMPLES=OFF -DBUILD_DOCS=OFF -DBUILD_opencv_apps=OFF -DBUILD_JAVA=OFF
  -DBUILD_opencv_js=OFF -DBUILD_opencv_python2=OFF -DBUILD_opencv_python3=ON
  -DPYTHON3_EXECUTABLE="$python" -DPYTHON_DEFAULT_EXECUTABLE="$python"
  -DWITH_EIGEN=ON
  -DCPU_DISPATCH=
  -DWITH_IPP=OFF -DBUILD_IPP_IW=OFF -DWITH_ITT=OFF -DWITH_OPENCL=OFF -DWITH_OPENCLAMDFFT=OFF
  -DWITH_OPENCLAMDBLAS=OFF -DWITH_VA=OFF -DWITH_VA_INTEL=OFF -DWITH_CUDA=OFF -DWITH_OPENVX=OFF
  -DWITH_TBB=OFF -DWITH_OPENMP=OFF -DWITH_LAPACK=OFF -DWITH_PROTOBUF=OFF -DWITH_ADE=OFF
  -DWITH_FLATBUFFERS=OFF -DWITH_VULKAN=OFF -DWITH_HALIDE=OFF -DWITH_OPENVINO=OFF
  -DWITH_GTK=OFF -DWITH_QT=OFF -DWITH_OPENGL=OFF -DWITH_WAYLAND=OFF -DWITH_FRAMEBUFFER=OFF
  -DWITH_VTK=OFF
  -DWITH_FFMPEG=OFF -DWITH_GSTREAMER=OFF -DWITH_V4L=OFF -DWITH_1394=OFF -DWITH_OBSENSOR=OFF
  -DWITH_GPHOTO2=OFF -DWITH_ARAVIS=OFF -DWITH_XINE=OFF -DWITH_OPENNI=OFF -DWITH_OPENNI2=OFF
  -DWITH_LIBREALSENSE=OFF -DWITH_ANDROID_MEDIANDK=OFF
  -DWITH_JPEG=OFF -DWITH_PNG=OFF -DWITH_SPNG=OFF -DWITH_TIFF=OFF -DWITH_WEBP=OFF -DWITH_AVIF=OFF
  -DWITH_JPEGXL=OFF -DWITH_OPENJPEG=OFF -DWITH_JASPER=OFF -DWITH_OPENEXR=OFF -DWITH_GDAL=OFF
  -DWITH_GDCM=OFF -DWITH_IMGCODEC_GIF=OFF -DWITH_QUIRC=OFF -DWITH_UNIFONT=OFF -DWITH_ONNXRUNTIME=OFF
  -DOPENCV_GENERATE_PKGCONFIG=OFF -DOPENCV_ENABLE_NONFREE=OFF
  -DENABLE_CCACHE=OFF
)

log "configuring in $bld (modules: $modules)"
mkdir -p "$bld"
if ! nice -n "$niceness" cmake -S "$opencv_src" -B "$bld" "${cmake_args[@]}" > "$bld/configure.log" 2>&1; then
  tail -n 40 "$bld/configure.log" >&2
  log "configure failed; full log: $bld/configure.log"
  exit 1
fi
# A module that OpenCV silently disabled (missing Eigen, a dependency it could not resolve) would
# only show up later as a missing target: say it now.
required=(tripose python3)
if [ "$cpp_tests" = 1 ]; then required+=(ts); fi
for m in "${required[@]}"; do
  if ! grep -q "To be built:.* $m\b" "$bld/configure.log"; then
    grep -E "To be built|Disabled|Unavailable" "$bld/configure.log" >&2 || true
    log "module $m is not built in this configuration; see $bld/configure.log"
    exit 1
  fi
done
t_configured=$(seconds)

# The perf tests are compiled by the standalone build already (the same sources on the ts shim);
# here they are built only on request (TRIPOSE_INTREE_PERF=1), to run them on OpenCV's own ts.
targets=(opencv_python3)
if [ "$cpp_tests" = 1 ]; then targets+=(opencv_test_tripose); fi
if [ "${TRIPOSE_INTREE_PERF:-0}" = 1 ]; then targets+=(opencv_perf_tripose); fi
log "building ${targets[*]} (-j$jobs, nice $niceness)"
nice -n "$niceness" cmake --build "$bld" -j "$jobs" --target "${targets[@]}"
t_built=$(seconds)

pythonpath="$bld/python_loader"
log "times (s): fetch+unpack $((t_unpacked - t_start)), configure $((t_configured - t_unpacked)), build $((t_built - t_configured)), total $((t_built - t_start))"
echo "OPENCV_INTREE_BUILD=$bld"
echo "OPENCV_INTREE_PYTHONPATH=$pythonpath"
echo "OPENCV_INTREE_SOURCE=$opencv_src"

if [ ${#run[@]} -gt 0 ]; then
  export OPENCV_INTREE_BUILD="$bld" OPENCV_INTREE_PYTHONPATH="$pythonpath" OPENCV_INTREE_SOURCE="$opencv_src"
  exec "${run[@]}"
fi
