#pragma once
// Procedurally generated test scenes, deterministic from a seed: the same options always give
// the same Scene, description and file bytes (no clocks, no platform-dependent distributions).
//
//  - plant: an 80 m x 40 m x 8 m production hall (machine tools, robots, pipe racks, conveyors,
//    cabinets; sparsely occluding each other as in Ebbesmeyer's (1997) test scene), cut by 37
//    virtual walls into 24 cells of 10 m (three rows of eight bays). Default: at least 2 M drawn
//    triangles; meshes are shared by instances. Targets of 3 M and more make the hall longer
//    (8 bays per 2 M triangles: 32 M is 1.28 km with 384 cells), not its cells heavier.
//  - house: a 16 m x 12 m house of six rooms with real walls and doorways; every doorway is a
//    portal wall (Aliaga & Lastra's (1997) portal textures); cells are the rooms. Default: at
//    least 200 k drawn triangles.
//  - boxes (generateBoxHall): a 60 m x 8 m x 30 m hall of random axis-aligned boxes for comparing
//    draw paths with other viewers: one mesh, one primitive, one object, one material;
//    24 vertices and 12 triangles per box, per-face normals, no colours or texture coordinates;
//    edges uniform in [kBoxHallMinEdge, kBoxHallMaxEdge) m, every box inside the hall. Default:
//    1 M triangles (ceil(triangles / 12) boxes). No cells or walls.
// Structure (floors, outer and real walls, ceilings, columns, beams) has Role::Structure and
// node names starting with "structure/"; the description tags it with that pattern. Both
// scenes have a walk path through every cell at eye height (through the doors in the house).

#include "scenes/scene.h"
#include "scenes/scene_description.h"

#include <cstdint>
#include <filesystem>

namespace cavewall::scenes {

struct GenerateOptions {
    std::uint64_t seed = 0;
    std::size_t triangles = 0;  // minimum drawn triangles; 0 = the scene's default (2 M / 200 k)
};

struct GeneratedScene {
    Scene scene;
    SceneDescription description;  // models[0].file is "<name>.glb", folder is empty
};

GeneratedScene generatePlant(const GenerateOptions& options);
// The largest triangle target the plant is made for: 512 bays of 10 m (8 per 2 M triangles).
inline constexpr std::size_t kPlantMaxTriangles = 128'000'000;
GeneratedScene generateHouse(const GenerateOptions& options);

inline constexpr std::size_t kBoxHallDefaultTriangles = 1'000'000;
inline constexpr glm::dvec3 kBoxHallSize{60.0, 8.0, 30.0};  // metres; x in [-30, 30], y in [0, 8], z in [-15, 15]
inline constexpr double kBoxHallMinEdge = 0.1, kBoxHallMaxEdge = 1.0;  // metres
Scene generateBoxHall(const GenerateOptions& options);

// Writes <dir>/<name>.glb and <dir>/scene.json (creating `dir`) and returns the scene.json path.
std::filesystem::path writeGenerated(GeneratedScene& generated, const std::filesystem::path& dir);

}  // namespace cavewall::scenes
