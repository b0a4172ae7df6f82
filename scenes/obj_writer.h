#pragma once
// Writing a Scene as a Wavefront OBJ file, for viewers that read OBJ but not glTF (the peer
// comparison with OpenSceneGraph, tools/osg-compare.sh).
//
// Geometry only: every object's mesh is written in world coordinates (metres, +Y up, as OBJ
// readers expect), as one group per object, with positions and normals deduplicated by exact
// value (a box hall's 24 vertices per box become 8 positions; its normals 6 in all), faces
// as `f p//n`, counter-clockwise front faces (flipped for mirroring objects). Materials,
// colours and texture coordinates are not written. The bytes depend only on the scene.

#include "scenes/scene.h"

#include <filesystem>
#include <string>

namespace cavewall::scenes {

// The .obj file contents.
std::string objText(const Scene& scene);

// Writes objText(scene) to `file` (atomically, creating folders). Throws Error naming the file.
void writeObj(const Scene& scene, const std::filesystem::path& file);

}  // namespace cavewall::scenes
