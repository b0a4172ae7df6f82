#pragma once
// The plants of `cavewall bench --scale` (app/bench/gl/scale_bench.h), GL-free: one generated and
// stamped per size, and the wall textures a stretch of its walk path requests.

#include "app/bench/path.h"
#include "display/display.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/wall_setup.h"

#include <cstddef>
#include <filesystem>
#include <set>

namespace cavewall::bench {

// The plant for `triangles`, generated into `folder` (and stamped, bench::kPlantStamp) unless
// it is there already; `generateSeconds` is 0 when it was. Returns its scene.json.
std::filesystem::path plantFor(std::size_t triangles, const std::filesystem::path& folder, double& generateSeconds);

// The drawn triangles of the plant generated for `triangles`, made again in memory (for a
// folder without a stamp).
std::size_t plantTriangles(std::size_t triangles);

// The textures the path's frames request (now or soon) with every texture resident, in id order.
std::set<int> requestedTextures(const scenes::Scene& scene, const scenes::SceneDescription& d,
                                const display::Display& display, const walls::WallSetup& setup,
                                const bench::EyePath& path);

}  // namespace cavewall::bench
