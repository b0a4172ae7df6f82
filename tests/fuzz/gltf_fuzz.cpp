// Fuzz target: a whole .gltf or .glb file. Relative URIs resolve in a folder that does not
// exist, so only data: URIs and the GLB's BIN chunk are read.
#include "config/error.h"
#include "scenes/gltf_memory.h"
#include "tests/fuzz/fuzz_target.h"

#include <cassert>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    try {
        const cavewall::scenes::Scene scene =
            cavewall::scenes::loadGltfFromMemory(bytes, "/nonexistent-fuzz-dir/fuzz.glb");
        for (const auto& mesh : scene.meshes)
            for (std::uint32_t index : mesh.indices)
                if (index >= mesh.positions.size()) __builtin_trap();  // an index past the vertices: a loader bug
    } catch (const cavewall::Error&) {}
    return 0;
}
