#pragma once
// Loading scenes from files: a bare glTF 2.0 file (.gltf or .glb), or a scene.json that names
// glTF files and cuts the model into cells (scene_description.h).
//
// Broken files throw cavewall::Error naming the file and the glTF path
// ("x.glb: meshes[3].primitives[0].attributes.POSITION: accessor 12 is out of range ...").
// Content that is valid but unsupported is skipped with a warning in Scene::warnings
// ("scene 'x.glb': ignoring primitive 3 of mesh 7 because it has mode POINTS").

#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "scenes/texture_budget.h"

#include <filesystem>
#include <string_view>

namespace cavewall::scenes {

// Whether a node name matches a structureNodes pattern: '*' matches any run of characters (also
// none), everything else itself. Linear in name x pattern (no backtracking blow-up).
bool matchesNodePattern(std::string_view name, std::string_view pattern);

// Loads one glTF/GLB file; objects are in the file's own frame (glTF: metres, +Y up). Vertex
// data is as the file stores it (no welding or reordering). Images are reduced to at most
// `textureMaxSide` pixels a side as they are decoded (scenes/texture_budget.h); no budget.
Scene loadGltf(const std::filesystem::path& file, int textureMaxSide = TextureLimits{}.maxSide);

// Structure objects (always drawn, never paged) wider than this along x or z and of at least
// 1024 triangles are cut into square columns of this side at load (scenes/mesh_split.h; they
// stay structure): a floor or roof spanning a whole hall is then frustum-culled per column
// instead of drawn whole in every view. One bay of the generated plant.
inline constexpr double kStructureChunkMetres = 10.0;

// Loads every model of a validated description, applies units, up axis and placement, tags
// structure objects (and cuts wide ones, kStructureChunkMetres), prepares the meshes for
// drawing (vertices welded, triangles ordered for the vertex cache unless the material
// blends: scenes/mesh_optimize.h; the shape and the triangle count stay) and gives each
// object to every cell it overlaps (scenes/cell_assignment.h). Images are reduced to `textures`
// (scenes/texture_budget.h) and the outcome is one line of Scene::notes
// ("textures: 41 images, ... MB decoded at full size -> ... MB, ...").
Scene loadScene(const SceneDescription& description, const TextureLimits& textures = {});

// Loads a scene from a path: a scene.json (or a folder holding one) or a bare glTF/GLB file
// (then the description has no cells or walls). `description` receives the description used.
Scene loadSceneFile(const std::filesystem::path& path, SceneDescription* description = nullptr,
                    const TextureLimits& textures = {});

// The files a scene loaded by loadSceneFile(`path`) was read from, for commands that must not
// write over their inputs: the scene.json (`path`, or the one in the folder `path`) and every
// model file of `description` (the description loadSceneFile gave).
std::vector<std::filesystem::path> sceneInputFiles(const std::filesystem::path& path,
                                                   const SceneDescription& description);

}  // namespace cavewall::scenes
