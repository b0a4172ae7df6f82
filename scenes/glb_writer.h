#pragma once
// Writing a Scene as a binary glTF 2.0 file (.glb) that any glTF viewer opens.
//
// Every Mesh becomes one glTF mesh with one primitive (POSITION with min/max, NORMAL, TEXCOORD_0,
// COLOR_0 when present; 16-bit indices when they fit, else 32-bit) and every Object one root
// node instancing it, so shared meshes stay shared. Materials keep factor, alpha mode and
// doubleSided; textures are not written (the generated scenes have none). The bytes depend only
// on the scene: no timestamps, stable number printing.

#include "scenes/scene.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace cavewall::scenes {

// The .glb file contents.
std::vector<std::uint8_t> glbBytes(const Scene& scene);

// Writes glbBytes(scene) to `file` (through a temporary file and a rename, so readers never see
// a partial file); creates missing folders. Throws Error naming the file on failure.
void writeGlb(const Scene& scene, const std::filesystem::path& file);

}  // namespace cavewall::scenes
