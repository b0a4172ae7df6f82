#pragma once
// The options of `cavewall run` (and of the demo, which runs the same session four times),
// as plain data with typed modes. The command line parses them once (tools/cmd_run.cpp);
// everything below it compares enums, never strings. validate() holds the rules that tie
// several options together, so every caller of the session gets the same messages.

#include "config/display_config.h"
#include "render/occlusion_settings.h"
#include "scenes/scene_description.h"
#include "scenes/texture_budget.h"
#include "walkthrough/frame_types.h"
#include "walls/depth_wall.h"
#include "walls/plan.h"
#include "walls/texture_blocks.h"

#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cavewall::app {

inline constexpr double kRunStep = 1.0 / 60.0;  // seconds per frame (a live session's shortest)
// A live session's longest navigation step, seconds: after a frame that stalled (a shader
// compiled, the window was dragged) the viewer moves this far at most, not the whole pause.
inline constexpr double kMaxLiveStep = 0.25;

enum class WindowMode { Auto, Headless, Window };

// How a wall's textures hand over to geometry: cross-fade, or geometry warped onto the
// textures (walkthrough/frame_types.h).
using Transition = walkthrough::Transition;

// --nav. Auto: guided along the scene's walkPath when it has one, else None (the CAVE stays
// where the path starts, or at the origin).
enum class Navigation { Auto, Guided, Fly, Walk, None };

// --route: which of the scene's paths the guided navigator follows. Walk: its walkPath (the
// aisles); Wall: its wallPath, a second path that hugs the virtual walls (the eye regions where
// textures are seen from nearest and most obliquely).
enum class Route { Walk, Wall };

// The words the command line accepts for each enum, in the order its help lists them.
inline constexpr std::array<std::pair<std::string_view, Transition>, 2> kTransitionNames{
    {{"blend", Transition::Blend}, {"warp", Transition::Warp}}};
inline constexpr std::array<std::pair<std::string_view, Navigation>, 4> kNavigationNames{
    {{"guided", Navigation::Guided}, {"fly", Navigation::Fly}, {"walk", Navigation::Walk}, {"none", Navigation::None}}};

inline constexpr std::array<std::pair<std::string_view, Route>, 2> kRouteNames{
    {{"walk", Route::Walk}, {"wall", Route::Wall}}};

// --start: where the viewer starts in a scene without a walk path (a path's start always wins).
// Origin: the CAVE at the world's origin. Inside: standing on a floor inside the model, else
// as ViewAll (app/start_pose.h). ViewAll: moved so that the whole model is in view.
enum class Start { Origin, Inside, ViewAll };
inline constexpr std::array<std::pair<std::string_view, Start>, 3> kStartNames{
    {{"inside", Start::Inside}, {"view-all", Start::ViewAll}, {"origin", Start::Origin}}};

// How a session ended (RunSummary::ending).
enum class Ending {
    Frames,        // drew every frame asked for
    WindowClosed,  // a window was closed
    Quit,          // the quit keys (input/session_keys.h)
    Interrupted,   // SIGINT or SIGTERM (app/interrupt.h)
};
std::string_view toString(Ending ending);

// Makes `route` the path the guided navigator follows (SceneDescription::walkPath): Wall
// replaces walkPath by wallPath. Throws cavewall::Error, naming the scene, when the scene has no
// wallPath of at least 2 points.
void useRoute(scenes::SceneDescription& description, Route route, const std::string& sceneName);

// "blend" | "warp".
std::string_view toString(Transition transition);

struct RunOptions {
    std::filesystem::path scene;       // scene.json (or its folder) or a glTF/GLB file
    config::DisplayConfig display;     // validated
    std::string tracker = "sim:walk";  // input::makeTracker spec, or "desktop"
    long frames = 120;                 // >= 0; 0: until a window closes, quit keys or Ctrl+C
    Navigation nav = Navigation::Auto;
    double guidePace = 1.0;       // m/s along the walk path (guided)
    Route route = Route::Walk;    // which of the scene's paths (applied by the session)
    Start start = Start::Origin;  // without a walk path: where the viewer starts
    WindowMode window = WindowMode::Headless;
    Transition transition = Transition::Blend;
    bool walls = true;         // false: --no-walls, full (culled) geometry
    bool wallTextures = true;  // false: the control, the walls' cells without textures
                               // (walkthrough::gl::WalkthroughOptions::wallTextures;
                               // the demo's)
    walls::PlanOptions plan;   // alpha etc. for planning and baking
    // --min-zone and --max-res given (plan.minZoneSize, bakeResolution); else the scene's own
    // (walls::useScenePlanning)
    walls::PlanningFlags planningGiven;
    // --walls depth|flat (walls/depth_wall.h); depth: the bench's recommended walls mode on the
    // plant (docs/benchmarking.md, "The recommended walls mode")
    walls::WallKind wallKind = walls::WallKind::Depth;
    bool keepSheets = false;  // --keep-sheets: depth walls keep their rubber sheets (to measure the cut)
    // --no-occlusion, --occlusion-min, --occlusion-min-draws: RenderSettings::occlusion
    render::OcclusionSettings occlusion;
    bool portalCulling = true;  // --no-portal-culling: WalkthroughSettings::portalCulling
    // --texture-format: storage of baked colour (walls/texture_blocks.h; keys the bake cache)
    walls::TextureFormat textureFormat = walls::TextureFormat::Rgba8;
    std::optional<std::filesystem::path> cache;   // bake cache folder (default: the baker's)
    long saveEvery = 0;                           // save frames: 0 none, K every K-th frame
    bool saveWindow = false;                      // with saveEvery: also what each window shows,
                                                  // overlay included (window-<screen>.png)
    bool keepSavedImages = false;                 // also return the saved frames' images
                                                  // (RunSummary::savedFrames; the demo compares them)
    std::optional<std::filesystem::path> record;  // write the input stream for replay
    bool synchronousPaging = false;               // see walkthrough::gl::WalkthroughOptions
    double textureBudgetMB = 256.0;
    scenes::TextureLimits sceneTextures;  // --texture-max, --texture-budget: the scene's own images
    int bakeResolution = 1024;            // --max-res: BakeSettings::maxResolution (bench, demo: 512)
    // --bake-on-demand: start at once and bake missing textures in the background while walking
    // (walls/gl/background_baker.h); flat walls, without --sync-paging and --cluster.
    bool bakeOnDemand = false;
    double cacheBudgetMB = 0.0;      // --cache-budget: disk MB of the scene's bake folder, 0 none
    int bakeNice = 10;               // --bake-nice: the baker thread's nice value, [0, 19]
    long bakeInterleave = 0;         // --bake-interleave N: pause the baker every other N frames, 0 never
    double geometryBudgetMB = 0.0;   // --geometry-budget: page geometry by cell, MB; 0 off
    double lodPixels = 0.0;          // --lod: level-of-detail tolerance in pixels, 0 off
    std::size_t triangleBudget = 0;  // --triangle-budget: per frame, 0 none (needs --lod)
    double frameBudgetMs = 0.0;      // --frame-budget-ms: frame-time target, 0 none (needs --lod)
    double lodMaxPixels = 8.0;       // --lod-max: the most a budget raises the tolerance to
    // --hierarchy: Maciel & Shirley's (1995) textured clusters instead of walls
    // (walkthrough/gl/walkthrough.h ClusterOptions); the budget is --frame-budget-ms's controller
    // (predicted ms), else 16.7 ms.
    bool clusters = false;
    int clusterDivisions = 8;      // --hierarchy-divisions N: finest grid N x max(1, N/4) x N
    int clusterResolution = 64;    // --hierarchy-res: face texture's longer side, texels
    int clusterFadeFrames = 8;     // --hierarchy-fade N: frames a switch cross-fades over
    std::filesystem::path out;     // output folder (created); empty: no files
    bool verbose = true;           // progress and summary on stdout
    bool cluster = false;          // --cluster: one process per screen group on MPI
                                   // (app/run_cluster.h); run under mpirun
    double clusterTimeout = 10.0;  // s a rank waits for the others before ending all
};

// Throws cavewall::Error, naming the flags, when options contradict each other: frames < 0, a
// triangle or frame-time budget without levels of detail, or both budgets at once; baking on
// demand with --sync-paging or --cluster; a bad --cache-budget, or one without
// --bake-on-demand; saving frames or recording without an output folder; --save-window
// without windows or saved frames.
void validate(const RunOptions& options);

struct RunSummary {
    std::string renderer;         // GL_RENDERER
    bool walls = false;           // the wall pass ran
    int textures = 0;             // baked textures available
    std::vector<double> frameMs;  // per frame
    double worstErrorDeg = 0.0, worstErrorPx = 0.0;
    double worstLodErrorPx = 0.0;  // largest level-of-detail error drawn, pixels
    long misses = 0, pageIns = 0;
    // Wall textures refused when paged in because a file's size or content hash was not the
    // manifest's (walls/texture_pager.h); each was reported once on stderr as it happened.
    long checkFailures = 0;
    // Geometry paging (--geometry-budget): the most resident at once, the largest three cells'
    // geometry and the whole model's (walls/geometry_pager.h sizes), MB; cumulative misses and
    // page-ins; cells drawn though not resident, summed over frames.
    double geometryPeakMB = 0.0, largestThreeCellsMB = 0.0, modelGeometryMB = 0.0;
    double sharedGeometryMB = 0.0;  // geometry paging: the always-resident buffers
    long geometryMisses = 0, geometryPageIns = 0, geometryForced = 0;
    std::vector<std::filesystem::path> foldouts;  // saved fold-outs, in frame order
    // With RunOptions::keepSavedImages: every saved frame's images and the head (cave frame,
    // metres) it was drawn from, in frame order.
    struct SavedFrame {
        long frame = 0;
        glm::dvec3 head{0.0};
        std::vector<scenes::ScreenImage> images;
    };
    std::vector<SavedFrame> savedFrames;
    // Start-up, seconds from runSession's start (the time to the first frame): the scene
    // loaded, the walls prepared (plan, visibility, bake or cache check), the walkthrough ready
    // (uploads, first textures), and the first frame presented.
    double sceneSeconds = 0.0, wallsSeconds = 0.0, readySeconds = 0.0, firstFrameSeconds = 0.0;
    // --hierarchy: clusters in the hierarchy, made now and read from the cache, and the measured
    // costs (ms per triangle, per object, per textured and per average box).
    // --bake-on-demand: textures missing from the cache at the start, baked during the run and
    // still missing at the end; files evicted for --cache-budget and the folder's MB then.
    int texturesMissingAtStart = 0, texturesBaked = 0, texturesStillMissing = 0;
    long cacheEvictions = 0;
    double cacheMB = 0.0;
    std::vector<std::string> bakeWarnings;
    int clusters = 0, clustersMade = 0, clustersReused = 0;
    double clustersSeconds = 0.0;
    double msPerTriangle = 0.0, msPerObject = 0.0, texturedBoxMs = 0.0, averageBoxMs = 0.0;
    double texturedViewMs = 0.0, averageViewMs = 0.0;  // a box's fill per whole view it covers
    int costResolution = 0;                            // pixels of the cost view's side
    int rank = 0;                                      // cluster mode: this process's rank (only rank 0
                                                       // fills the fields above)
    Ending ending = Ending::Frames;
};

}  // namespace cavewall::app
