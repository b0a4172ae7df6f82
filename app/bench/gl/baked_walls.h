#pragma once
// The walls `cavewall bench SCENE` draws: planned and baked (or found in the bake cache) per
// alpha, for the bench scene, for the flat walls beside its depth walls (`--walls
// flat,depth`), and for every compare scene (`--compare-scene`, the same model with other
// cells and walls).

#include "app/bench/gl/driver.h"
#include "app/bench/report.h"
#include "display/gl/context.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/wall_setup.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace cavewall::bench::gl {

struct BakedWalls {
    walls::WallSetup setup;
    double texels = 0.0, diskMB = 0.0;
    std::string summary;
};

// Plans and bakes (or finds in the cache) the walls of `sceneFile` at `alphaDeg`, of `kind`.
BakedWalls bakeWalls(const BenchOptions& o, const std::filesystem::path& sceneFile, double alphaDeg,
                     walls::WallKind kind, const scenes::Scene& scene, const scenes::SceneDescription& d,
                     display::gl::Context& context);

// The bench scene's walls at every alpha: of `kind`, with a header line (`label` names the
// kind where the bench draws two) for each.
std::vector<BakedWalls> bakeOwnWalls(const BenchOptions& o, walls::WallKind kind, const scenes::Scene& scene,
                                     const scenes::SceneDescription& description, display::gl::Context& context,
                                     BenchReport& report);

// The compare scene (--compare-scene): the same model (objects and triangles) with walls.
struct CompareScene {
    scenes::SceneDescription description;
    scenes::Scene scene;
};

// The compare scenes, each checked against `scene` (the same model) and the others' labels.
std::vector<std::unique_ptr<CompareScene>> loadCompareScenes(const BenchOptions& o, const scenes::Scene& scene);

// Plans and bakes every compare scene's walls at every alpha (per scene, per alpha), with a
// header line for each.
std::vector<std::vector<BakedWalls>> bakeCompareScenes(const BenchOptions& o,
                                                       const std::vector<std::unique_ptr<CompareScene>>& others,
                                                       const scenes::SceneDescription& description,
                                                       display::gl::Context& context, BenchReport& report);

// The model's triangles.
std::size_t triangleCount(const scenes::Scene& scene);

// `line` on stdout when the bench is verbose.
void say(const BenchOptions& o, const std::string& line);

}  // namespace cavewall::bench::gl
