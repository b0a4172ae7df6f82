#pragma once
// `cavewall run` as a function, shared by the run and demo commands: load the scene and the
// display, plan and bake the walls (when the scene has them), then drive the walkthrough runtime
// (walls/gl/walkthrough.h) from a tracker, the tracking pipeline and the navigator at a fixed
// step of 1/60 s, writing frames.csv, walls.csv and the chosen frames.
//
// Time: frame i is at t = i / 60 s. Simulated, file and replay trackers are polled at exactly
// those times (runs are reproducible); live network trackers are polled in real time.

#include "config/display_config.h"
#include "walls/plan.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cavewall::tools {

inline constexpr double kRunStep = 1.0 / 60.0;  // seconds per frame

enum class WindowMode { Auto, Headless, Window };

struct RunOptions {
    std::filesystem::path scene;                // scene.json (or its folder) or a glTF/GLB file
    config::DisplayConfig display;              // validated
    std::string tracker = "sim:walk";           // input::makeTracker spec
    long frames = 120;
    std::string nav;                            // guided | fly | walk | none; "" = guided along the
                                                // scene's walkPath when it has one, else none
    double guidePace = 1.0;                     // m/s along the walk path (guided)
    WindowMode window = WindowMode::Headless;
    std::string transition = "blend";           // blend | warp
    bool walls = true;                          // false: --no-walls, full (culled) geometry
    walls::PlanOptions plan;                    // alpha etc. for planning and baking
    std::optional<std::filesystem::path> cache; // bake cache folder (default: the baker's)
    long saveEvery = 0;                         // save frames: 0 none, K every K-th frame
    std::optional<std::filesystem::path> record;// write the input stream for replay:
    bool synchronousPaging = false;             // see WalkthroughOptions
    double textureBudgetMB = 256.0;
    double lodPixels = 0.0;                     // --lod: level-of-detail tolerance in pixels, 0 off
    std::size_t triangleBudget = 0;             // --triangle-budget: per frame, 0 none (needs --lod)
    double frameBudgetMs = 0.0;                 // --frame-budget-ms: frame-time target, 0 none (needs --lod)
    double lodMaxPixels = 8.0;                  // --lod-max: the most a budget raises the tolerance to
    std::filesystem::path out;                  // output folder (created)
    bool verbose = true;                        // progress and summary on stdout
    bool cluster = false;                       // --cluster: one process per screen group on MPI
                                                // (tools/run_cluster.h); run under mpirun
    double clusterTimeout = 10.0;               // s a rank waits for the others before ending all
};

struct RunSummary {
    std::string renderer;                       // GL_RENDERER
    bool walls = false;                         // the wall pass ran
    int textures = 0;                           // baked textures available
    std::vector<double> frameMs;                // per frame
    double worstErrorDeg = 0.0, worstErrorPx = 0.0;
    double worstLodErrorPx = 0.0;               // largest level-of-detail error drawn, pixels
    long misses = 0, pageIns = 0;
    std::vector<std::filesystem::path> foldouts;// saved fold-outs, in frame order
    int rank = 0;                               // cluster mode: this process's rank (only rank 0
                                                // fills the fields above)
};

// Runs the session; throws cavewall::Error on bad input (scene, tracker spec, nav mode...).
RunSummary runSession(const RunOptions& options);

// Median of `values` (0 for none).
double median(std::vector<double> values);

}  // namespace cavewall::tools
