#!/bin/sh
# Builds and runs the whole test suite in two builds, each test running once:
# 1. A release build of the product with every test that needs more than the unit label gives:
#    OpenGL contexts (gl), end-to-end runs of the cavewall executable (cli), windows under Xvfb,
#    MPI ranks (mpi) and the VRPN client against the real VRPN server (net). The unit-labelled
#    tests are left out of it (CAVEWALL_UNIT_TESTS=OFF).
# 2. A headless-only build (no GLFW, no MPI) under AddressSanitizer + UndefinedBehaviorSanitizer,
#    which also proves that such a build works, running every unit test and the fuzz corpora's
#    replays. It compiles only what those run (the unit-tests target), at -O1 with line tables
#    only (-g1): asserts stay on, the sanitizers' reports keep file and line, and the tests run
#    about twice as fast as at -O0. The test files themselves are compiled without the
#    sanitizers (tests/CMakeLists.txt); the libraries they call are instrumented.
# Tests run on every core: no two tests use the same port (each binds a free one), and the files
# some share (a generated scene, a bake cache, the glTF files tests/scenes/gltf_builder.h
# writes) are written atomically with the same content.
set -eu
cd "$(dirname "$0")/.."
export EGL_PLATFORM="${EGL_PLATFORM:-surfaceless}"
jobs="$(nproc)"

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCAVEWALL_UNIT_TESTS=OFF
cmake --build build
ctest --test-dir build -j "$jobs" --output-on-failure --timeout 600

cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g1" -DCAVEWALL_SANITIZE=ON \
  -DCAVEWALL_WITH_GLFW=OFF -DCAVEWALL_WITH_MPI=OFF -DCAVEWALL_BUILD_BENCH=OFF -DCAVEWALL_UNIT_TESTS=ON
cmake --build build-asan --target unit-tests
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  LSAN_OPTIONS="suppressions=$PWD/tests/lsan.supp" \
  ctest --test-dir build-asan -j "$jobs" -L unit --output-on-failure --timeout 600
