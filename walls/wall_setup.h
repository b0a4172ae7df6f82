#pragma once
// One way to prepare a scene's virtual walls, used by the baker, run, bench, demo and tests
// alike: plan the zones (walls/plan.h), compute cell visibility and classify the scene's objects
// against every wall side (walls/visibility.h), and set every wall's depth behind it. GL-free.
// Baking (walls/gl/baker.h, walls::gl::bakeWalls) then fills in where the textures are.

#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/bake_manifest.h"
#include "walls/plan.h"
#include "walls/visibility.h"

#include <filesystem>
#include <map>
#include <utility>

namespace cavewall::walls {

struct WallSetup {
    Plan plan;  // Plan::options as given; PlannedWall::depthBehind assigned
    VisibilityTable table;
    // What each wall side shows, by (wall, side): every side with a cell in front of it.
    std::map<std::pair<int, int>, WallContents> contents;
    // Set from the bake (walls::gl::BakeResult): the folder holding the textures and its manifest.
    // Empty until baked; the walkthrough pages textures from here.
    std::filesystem::path folder;
    BakeManifest manifest;
};

// Plans `description` with `options`, computes its visibility table, classifies `scene`'s
// objects against every wall side and assigns each wall's depthBehind (the largest of its
// sides'). `scene` must be the one loaded from `description`. Throws cavewall::Error for bad
// options (validatePlanOptions). A description without walls gives an empty plan.
WallSetup prepareWalls(const scenes::Scene& scene, const scenes::SceneDescription& description,
                       const PlanOptions& options);

// `options` for walls of `kind` baked at most `bakeResolution` texels a side: wallKind set, and
// for depth walls maxResolution at most bakeResolution (their bound reserves the texel size the
// plan gives, walls/depth_wall.h, so the bake must not make texels coarser). Flat plans keep
// maxResolution (their bound does not depend on texels, and the bake key hashes the options).
PlanOptions planOptionsFor(PlanOptions options, WallKind kind, int bakeResolution);

}  // namespace cavewall::walls
