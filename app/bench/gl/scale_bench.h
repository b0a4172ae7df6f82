#pragma once
// `cavewall bench --scale 2M,8M,32M`: how frame time, resident geometry and the time to the
// first frame grow with the model. Per size, the generated plant (scenes::generatePlant,
// deterministic; written once into `data`/plant-N and reused) is loaded and walked along the
// same first `pathMetres` of its walk path (the same bays at every size: a longer hall has more
// of them, not heavier ones) in the modes below, drawn frame by frame in turn, so their times
// share the machine's load of the same seconds:
//  - full:  all geometry, frustum-culled, full detail (the whole model on the GPU);
//  - near:  the near-geometry limit at the walls' level-of-detail tolerance: structure,
//           objects without a cell and the viewer's cell (no wall quads);
//  - cells: the control, the walls mode's geometry cells as it draws them, no texture;
//  - walls: virtual walls at `alphaDeg`, levels of detail at `lodPixels`, geometry paging by
//           cell under `geometryBudgetMB` (mesh groups shared by cells stored once), textures
//           all resident after a warm-up pass over the stretch;
//  - walls-budget (unless `triangleBudget` is 0): the walls mode with its geometry held to a
//           triangle budget per frame (Maciel & Shirley's (1995) frame budget;
//           WalkthroughSettings::triangleBudget: the level-of-detail tolerance raised just
//           enough, to at most `lodMaxPixels`), by default the near limit's median triangles
//           over the stretch (counted in its warm-up pass), so the walls draw no more geometry
//           than the limit.
//           Its image error is measured like the walls', so what the budget costs shows beside
//           what it saves;
//  - walls-depth (depthBeside, with flat walls): the walls mode with depth walls,
//           their own plan and bake, drawn in turn with the others.
//
// Bounded baking: a cold bake of the whole 2 M plant takes about 20 minutes on this machine
// (hours at 32 M), so only the textures the stretch's frames request (now or soon, by
// walkthrough::FramePlanner from the same eye path) are baked, at `bakeResolution` texels at most,
// into their own cache (`data`/bake-cache: a subset bake replaces a folder's manifest, so it
// never shares folders with full bakes). The report says how many of the plan's textures that
// is. The walkthrough replays the same frames and requests the same ids (requests depend on the
// eye and the plan, not on residency), so nothing it asks for is missing.

#include "app/bench/scale.h"
#include "config/display_config.h"
#include "render/occlusion_settings.h"
#include "walls/plan.h"

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace cavewall::bench::gl {

struct ScaleOptions {
    std::vector<std::size_t> sizes;    // triangle targets (generatePlant), in order
    std::filesystem::path data;        // plants and the subset bake cache
    config::DisplayConfig display;     // validated
    std::string tracker = "sim:walk";  // head source
    double pathMetres = 40.0;          // the stretch of the walk path, metres
    long frames = 60;                  // timed frames over the stretch
    double alphaDeg = 10.0;
    walls::PlanOptions plan;                           // alphaDeg replaced
    walls::WallKind wallKind = walls::WallKind::Flat;  // of both walls modes: flat or depth
    // Also walls-depth (`--walls flat,depth`; wallKind flat): depth walls, planned and baked with
    // their own bound, drawn in turn with the other modes, so depth / flat frame time is
    // measured within one run.
    bool depthBeside = false;
    int bakeResolution = 128;        // texels per texture side at most
    double lodPixels = 1.0;          // the walls and near modes' tolerance
    double geometryBudgetMB = 64.0;  // the walls mode's geometry paging budget
    // walls-budget's triangles per frame: < 0 the near limit's median, 0 no such mode.
    long triangleBudget = -1;
    double lodMaxPixels = 8.0;  // the most its budget may raise the tolerance to
    // Every mode's scene renderer culls what the depth drawn so far hides, as `run` does by
    // default (--no-occlusion, --occlusion-min, --occlusion-min-draws); triangles a frame are
    // then those drawn.
    render::OcclusionSettings occlusion;
    // Every compareEvery-th timed frame (0: none) the near and walls modes' images are compared
    // with full geometry's of the same frame (bench::ErrorPool: pooled PSNR, worst frame, FLIP),
    // read back after each mode's frame is timed.
    int compareEvery = 6;
    bool verbose = true;
    // Called with the report so far after each size (a long run keeps what it measured).
    std::function<void(const bench::ScaleReport&)> afterSize;
};

// Throws cavewall::Error on bad input.
bench::ScaleReport runScaleBench(const ScaleOptions& options);

}  // namespace cavewall::bench::gl
