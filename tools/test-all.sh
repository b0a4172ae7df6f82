#!/bin/sh
# Builds and runs the whole test suite: the release build with every test (unit, gl, cli), then
# the unit tests again under AddressSanitizer + UndefinedBehaviorSanitizer in a headless-only
# build (no GLFW, no MPI), which also proves that such a build works. That build compiles only
# what the unit tests run (the unit-tests target), at -O1 with line tables only (-g1): asserts
# stay on, the sanitizers' reports keep file and line, and the tests run about twice as fast as
# at -O0. Tests run on every core: no two tests use the same port (each binds a free one), and
# the files some share (a generated scene, a bake cache, the glTF files
# tests/scenes/gltf_builder.h writes) are written atomically with the same content.
set -eu
cd "$(dirname "$0")/.."
export EGL_PLATFORM="${EGL_PLATFORM:-surfaceless}"
jobs="$(nproc)"

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build
ctest --test-dir build -j "$jobs" --output-on-failure --timeout 600

cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DCAVEWALL_SANITIZE=ON \
  -DCAVEWALL_WITH_GLFW=OFF -DCAVEWALL_WITH_MPI=OFF -DCAVEWALL_BUILD_BENCH=OFF
cmake --build build-asan --target unit-tests
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp" \
  ctest --test-dir build-asan -j "$jobs" -L unit --output-on-failure --timeout 600
