#!/bin/sh
# Builds and runs the whole test suite: the release build with every test (unit, gl, cli), then
# the unit tests again under AddressSanitizer + UndefinedBehaviorSanitizer in a headless-only
# build (no GLFW, no MPI), which also proves that such a build works.
set -eu
cd "$(dirname "$0")/.."
export EGL_PLATFORM="${EGL_PLATFORM:-surfaceless}"

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build
ctest --test-dir build --output-on-failure --timeout 600

cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCAVEWALL_SANITIZE=ON \
  -DCAVEWALL_WITH_GLFW=OFF -DCAVEWALL_WITH_MPI=OFF -DCAVEWALL_BUILD_BENCH=OFF
cmake --build build-asan
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp" \
  ctest --test-dir build-asan -L unit --output-on-failure --timeout 600
