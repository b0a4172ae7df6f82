#!/bin/sh
# Fuzzes one target of tests/fuzz for a given time with libFuzzer under AddressSanitizer and
# UndefinedBehaviorSanitizer (Debian's clang), one process. Usage:
#   tools/fuzz.sh TARGET SECONDS      TARGET: display_config gltf scene_description dtrack
#                                             opentrack vrpn bake_manifest texture_blocks depth_file
#                                             cluster_impostor warp_mesh blend_mask calibration_pairs
# The working corpus is build-fuzz/corpus/TARGET, seeded from tests/fuzz/corpus/TARGET (plus the
# presets or the shared models); crashes go to build-fuzz/crashes/TARGET/. Copy a crash file
# into tests/fuzz/corpus/TARGET/ once fixed: the replay tests (ctest -R fuzz_replay) keep it.
# FUZZ_TIMEOUT=SECONDS (default 10) is the time one input may take before it counts as a hang;
# raise it on a loaded machine, where a starved process can pass 10 s on a 3 ms input.
# FUZZ_RUNS=N stops after N executions (or SECONDS, whichever comes first); FUZZ_MAX_LEN=BYTES
# (default 65536) is the longest input libFuzzer makes.
set -eu
cd "$(dirname "$0")/.."
[ $# -eq 2 ] || { echo "usage: tools/fuzz.sh TARGET SECONDS" >&2; exit 2; }
target=$1
seconds=$2
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  $(command -v ccache >/dev/null && echo -DCMAKE_CXX_COMPILER_LAUNCHER=ccache) \
  -DCAVEWALL_FUZZ=ON -DCAVEWALL_WITH_GL=OFF -DCAVEWALL_WITH_GLFW=OFF -DCAVEWALL_WITH_MPI=OFF \
  -DCAVEWALL_BUILD_TESTS=OFF -DCAVEWALL_BUILD_BENCH=OFF >/dev/null
cmake --build build-fuzz -j2 -t "${target}_fuzz"
corpus=build-fuzz/corpus/$target
crashes=build-fuzz/crashes/$target
mkdir -p "$corpus" "$crashes"
cp -n tests/fuzz/corpus/"$target"/* "$corpus"/ 2>/dev/null || true
real=$(sed -n 's/^CAVEWALL_REAL_SCENES:PATH=//p' build-fuzz/CMakeCache.txt)
case $target in
  display_config) cp -n config/*.json "$corpus"/ ;;
  gltf) [ -d "$real" ] && find "$real" -size -64k \( -name '*.gltf' -o -name '*.glb' \) -exec cp -n {} "$corpus"/ \; ;;
esac
ASAN_OPTIONS=detect_leaks=1:allocator_may_return_null=1 UBSAN_OPTIONS=print_stacktrace=1 \
  "build-fuzz/tests/fuzz/${target}_fuzz" -max_total_time="$seconds" -rss_limit_mb=4096 -timeout="${FUZZ_TIMEOUT:-10}" \
  -runs="${FUZZ_RUNS:--1}" -max_len="${FUZZ_MAX_LEN:-65536}" -print_final_stats=1 -artifact_prefix="$crashes/" "$corpus"
