#pragma once
// `cavewall bench SCENE`: every rendering mode over the same recorded eye path in one run,
// error against run time.
//
// Modes, in this order (the first is the reference for speed-up and image error):
//  - full:  all geometry, frustum-culled (Walkthrough without walls).
//  - cells: the geometry the walls mode at `transitionAlphaDeg` draws (structure, objects
//           without a cell, the selection's geometry cells), without wall textures: what cell
//           culling alone leaves out and what that costs in error.
//  - cells + layer: the cells mode with one textured full-screen layer per view drawn through
//           the wall pass (walls::gl::WallPass, the walls' sampler, a 512 x 512 MIP-mapped sRGB
//           texture, weight 0 so that the image is the control's): what one wall layer costs,
//           the yardstick of the wall pass (its target: the limit no slower than this).
//  - near:  the near-geometry limit: structure, objects without a cell and the viewer's cell
//           only; the bare wall quads are left out (a handful of triangles), so this is a
//           lower bound of any walls mode's time.
//  - walls at every alpha in `alphasDeg`, transition blend: each its own plan and bake
//           (walls/gl/baker.h, cached), drawn by the walkthrough runtime with synchronous
//           paging after a warm-up pass over the path (all textures resident: the timed pass
//           measures drawing, not decoding).
//  - walls at `transitionAlphaDeg` (or the first alpha when it is not listed), transition warp
//           (walkthrough::Transition::Warp), on the same bake.
//  - with `flatBeside` (wallKind depth): flat walls at every alpha, blend, with and without
//           levels of detail, each alpha its own flat plan and bake, interleaved as above.
//  - with `lodPixels` > 0, levels of detail (scenes/mesh_lod.h) at that pixel tolerance: full,
//           near and every walls blend mode once more with them, then every walls blend mode
//           with them under a triangle budget (`triangleBudget`, or the median triangles of
//           the same mode without a budget), so that the levels' share of the speed-up and of
//           the error reads apart from the walls'.
//  - with `lodPixels` and `frameBudgetMs` > 0, every walls blend mode with levels of detail
//           and the frame-time controller (display/frame_budget.h) aiming at frameBudgetMs.
//  - with `compareScenes`, the same model with other cells and walls (e.g. `cavewall walls`'s
//           proposal): its walls blend modes at every alpha (and with levels of detail), each
//           with its own plan and bake, drawn on the bench scene's eye path frame by frame in
//           turn with full geometry and the bench scene's walls modes (automatic against
//           hand-placed walls, ratios from the same seconds).
//  - with `onDemandCache`, after the paged mode and alone: walls at `transitionAlphaDeg`
//           baked on demand from that empty, private cache (walls::gl::BackgroundBaker, as
//           `cavewall run --bake-on-demand`): first frame after the scene's load, geometry
//           fallbacks per frame, textures baked, frame-time p99/p50.
//  - last, the noise floor: the last mode again, each path frame followed by one fixed frame,
//           whose p99/p50 is the machine's own (a header line, not a mode).
//
// Timing: frame ms is the walkthrough's FrameResult::frameMs (CPU submission + glFinish) or,
// for cells/near, SceneRenderer::render + waiting for its GPU timer; every frame of the path
// is timed. Every `compareEvery`-th frame is read back (after timing) and compared per screen
// and eye with the full-geometry image of that frame (app/bench/metrics.h).

#include "config/display_config.h"
#include "walls/depth_wall.h"
#include "app/bench/report.h"
#include "app/run_options.h"
#include "render/occlusion_settings.h"
#include "walls/plan.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cavewall::bench::gl {

struct BenchOptions {
    std::filesystem::path scene;          // scene.json, its folder, or glTF/GLB
    config::DisplayConfig display;        // validated; drawn at its screens' resolutions
    std::string tracker = "sim:walk";     // head source (input::makeTracker spec)
    app::Route route = app::Route::Walk;  // the scene's path the eye follows
    long frames = 120;                    // frames of the eye path
    int compareEvery = 4;                 // frames between image comparisons, >= 1
    std::vector<double> alphasDeg{10, 20, 30};
    double transitionAlphaDeg = 20.0;                  // warp and paged modes; plan of the cells modes
    walls::PlanOptions plan;                           // alphaDeg replaced per mode
    int bakeResolution = 512;                          // BakeSettings::maxResolution
    walls::PlanningFlags planningGiven;                // --min-zone, --bake-resolution given (useScenePlanning)
    double lodPixels = 1.0;                            // level-of-detail modes' tolerance; 0: none
    std::size_t triangleBudget = 0;                    // the budget mode's; 0: the median of its mode
                                                       // without a budget
    double frameBudgetMs = 1000.0 / 60.0;              // the frame-time modes' target; 0: none
    double lodMaxPixels = 8.0;                         // the most a budget may raise the tolerance to
    walls::WallKind wallKind = walls::WallKind::Flat;  // --walls: flat or depth walls (bake and draw)
    // --walls flat,depth: with wallKind depth, flat walls too at every alpha (blend, and with
    // levels of detail), their own plan and bake, drawn frame by frame in turn with the depth
    // walls (flat against depth walls in the same seconds, stereo error included)
    bool flatBeside = false;
    bool keepSheets = false;  // --keep-sheets: depth walls keep their rubber sheets (to measure the cut)
    // Every mode's scene renderer culls what the depth drawn so far hides
    // (RenderSettings::occlusion; --no-occlusion, --occlusion-min, --occlusion-min-draws);
    // triangles a frame are then those drawn.
    render::OcclusionSettings occlusion;
    // The walls modes and the control draw other cells' objects only where the viewer cell's
    // openings show them (WalkthroughSettings::portalCulling); --no-portal-culling: off.
    bool portalCulling = true;
    // --texture-format: storage of the baked colour (walls/texture_blocks.h), disk and GPU
    walls::TextureFormat textureFormat = walls::TextureFormat::Rgba8;
    std::optional<std::filesystem::path> cache;  // bake cache (default: the baker's)
    bool clusters = false;                       // also Maciel & Shirley's (1995) textured
                                                 // clusters held to frameBudgetMs (16.67 when it
                                                 // is 0), interleaved with full geometry and the
                                                 // walls modes
    std::vector<double> clusterBudgetsMs;        // with clusters: one clusters mode per budget
                                                 // (hierarchy/cluster_budget.h) instead; each > 0
    // Other scene.json files of the same model (same objects and triangles), each with its own
    // cells and walls, benched beside the scene's walls on the scene's eye path; their modes are
    // labelled with their tags ("walls flat a=10 blend [auto]"), which must differ.
    struct CompareScene {
        std::filesystem::path scene;
        std::string tag;
    };
    std::vector<CompareScene> compareScenes;
    // The on-demand mode's private bake cache (bench::makeEmptyPrivateCache: emptied first,
    // never the shared cache); unset: no on-demand mode. Flat walls only.
    std::optional<std::filesystem::path> onDemandCache;
    bool saveWorst = false;  // --save-worst: BenchReport::saveWorst
    bool verbose = true;     // progress on stdout
};

// Runs every mode; throws cavewall::Error on bad input (scene, tracker spec, options).
bench::BenchReport runBenchmark(const BenchOptions& options);

// `display` with every screen's resolution scaled so that its longer side is `pixels`.
config::DisplayConfig withResolution(config::DisplayConfig display, int pixels);

}  // namespace cavewall::bench::gl
