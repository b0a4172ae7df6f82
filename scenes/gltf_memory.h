#pragma once
// Loading a glTF/GLB file whose bytes are already in memory (the fuzz targets use it).

#include "scenes/scene.h"
#include "scenes/texture_budget.h"

#include <filesystem>
#include <string_view>

namespace cavewall::scenes {

// As loadGltf (scenes/loader.h) on `bytes`, a whole .gltf or .glb file; `file` names it in
// messages and its folder is where relative URIs are looked up. The GLB container is checked
// (scenes/glb_container.h) and the JSON's nesting bounded (config/json_depth.h) before the
// glTF parser sees anything. Throws cavewall::Error.
Scene loadGltfFromMemory(std::string_view bytes, const std::filesystem::path& file,
                         int textureMaxSide = TextureLimits{}.maxSide);

}  // namespace cavewall::scenes
