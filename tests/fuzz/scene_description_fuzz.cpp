// Fuzz target: a scene.json (parse, then validate); model files resolve in a folder that does
// not exist.
#include "config/error.h"
#include "scenes/scene_description_io.h"
#include "tests/fuzz/fuzz_target.h"

#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        const auto d = cavewall::scenes::parseSceneDescription(text, "scene.json", "/nonexistent-fuzz-dir");
        cavewall::scenes::validateSceneDescription(d, "scene.json");
    } catch (const cavewall::Error&) {}
    return 0;
}
