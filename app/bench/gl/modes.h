#pragma once
// The per-mode machinery of `cavewall bench` (app/bench/gl/driver.h): running one mode over the
// eye path and accumulating its times, counts and image errors.

#include "display/gl/frame_images.h"
#include "app/bench/path.h"
#include "app/bench/report.h"
#include "render/occlusion_settings.h"
#include "walkthrough/gl/walkthrough.h"

#include <chrono>
#include <functional>
#include <map>
#include <optional>
#include <vector>

namespace cavewall::bench::gl {

// The full-geometry frame every mode's compared frame is compared with: its screen images and,
// on a stereo display, every view's depth (walkthrough::ViewDepth, eye distances).
struct ReferenceFrame {
    std::vector<scenes::ScreenImage> images;
    std::vector<walkthrough::ViewDepth> depths;  // empty in mono
};
// Frame index -> the reference of that frame.
using ReferenceImages = std::map<long, ReferenceFrame>;

// What one timed frame cost.
struct FrameCost {
    double frameMs = 0.0, cpuMs = 0.0, gpuMs = 0.0;
    double triangles = 0.0, drawCalls = 0.0;
    double errorDeg = 0.0, errorPx = 0.0;
    double residentMB = 0.0;
    long misses = 0;                                // cumulative, as the pager counts
    std::vector<display::ViewStats> perScreen;      // per display screen: CPU ms, triangles, draw calls
    double lodErrorPx = 0.0, lodTolerancePx = 0.0;  // FrameResult's (0 without levels of detail)
    bool overBudget = false;
    int texturesOverAlpha = 0;  // FrameResult's: drawn textures whose exact error exceeds alpha
    double uploadedMB = 0.0;    // wall texture MB uploaded this frame
    // Clusters held to a frame time (FrameResult's): the predicted cost of what was drawn, the
    // frame time the controller predicted and the floor (0 without one).
    double clusterPredictedMs = 0.0, clusterPredictedFrameMs = 0.0, clusterFloorMs = 0.0;
    int geometryFallbacks = 0;  // FrameResult's: walls drawn as geometry for want of a texture
    int keptFallbacks = 0;      // walls drawing the textures they drew last for want of the wanted ones
    int texturesBaked = 0;      // FrameResult's: baking on demand, baked so far
};

// One compared frame's images for bench::ErrorPool: `images` against the `reference` of the
// same frame (same screens and images), FLIP at each screen's minPixelsPerDegree from `head`'s
// position (cave frame; the cyclopean eye, also in stereo). Images of screens the display does
// not have are left out. Throws cavewall::Error naming `mode` when the image counts differ.
std::vector<bench::ComparedImage> comparedImages(const display::Display& display, const display::HeadPose& head,
                                                 const std::vector<scenes::ScreenImage>& images,
                                                 const std::vector<scenes::ScreenImage>& reference,
                                                 const std::string& mode);

// The stereo error (metrics/stereo_error.h) of every view's `depths` against the reference's of
// the same frame (same screens, images and eyes, in the same order) at the viewer's eye
// separation, added per screen to `screens` (one entry per display screen). Returns their sum.
// Throws cavewall::Error naming `mode` when the views differ from the reference's.
metrics::StereoError addStereoError(const display::Display& display, const std::string& mode,
                                    const std::vector<walkthrough::ViewDepth>& depths,
                                    const std::vector<walkthrough::ViewDepth>& reference,
                                    std::vector<metrics::StereoError>& screens);

// Collects one mode's frames and comparisons; finish() fills the bench::ModeResult.
class ModeAccumulator {
public:
    ModeAccumulator(bench::ModeResult mode, const display::Display& display);
    void addFrame(const FrameCost& cost);
    const bench::ModeResult& mode() const { return _mode; }
    // Compares `images` of frame `frame`, seen from `head` (cave frame), with the reference of
    // the same frame (same screens and images); FLIP at each screen's minPixelsPerDegree from
    // the head position (the cyclopean eye, also in stereo). Where measuresStereo, also every
    // view's `depths` with the reference's (the stereo error, at the viewer's eye separation);
    // throws cavewall::Error naming the mode when the views differ from the reference's.
    void compare(long frame, const display::HeadPose& head, const std::vector<scenes::ScreenImage>& images,
                 const std::vector<walkthrough::ViewDepth>& depths, const ReferenceFrame& reference);
    // `fullP50`: the reference mode's median frame ms (0: this is the reference).
    bench::ModeResult finish(double fullP50) const;
    void setTriangleBudget(std::size_t budget) { _mode.triangleBudget = budget; }

private:
    bench::ModeResult _mode;
    const display::Display& _display;
    std::vector<double> _frame, _cpu, _gpu;
    double _triangles = 0.0, _drawCalls = 0.0, _lodTolerance = 0.0;
    bench::ErrorPool _errors;
    void compareDepths(const std::vector<walkthrough::ViewDepth>& depths,
                       const std::vector<walkthrough::ViewDepth>& reference);
    metrics::StereoError _stereo;                            // all screens (stereo displays only)
    std::vector<metrics::StereoError> _screenStereo;         // per screen
    std::vector<std::vector<double>> _screenCpu;             // per screen, per frame
    std::vector<double> _screenTriangles, _screenDrawCalls;  // per screen, summed over frames
};

// Everything a mode run needs; the context is current.
struct ModeContext {
    const scenes::Scene& scene;
    const scenes::SceneDescription& description;
    const display::Display& display;
    display::gl::Context& context;
    const bench::EyePath& path;
    int compareEvery = 4;
    double lodMaxPixels = 8.0;                         // WalkthroughOptions::lodMaxPixels of the budgeted modes
    walls::WallKind wallKind = walls::WallKind::Flat;  // WalkthroughOptions::wallKind of the walls modes
    std::filesystem::path clusterCache;                // ClusterOptions::cache of the clusters modes
    walls::ReprojectSettings depthMarch;               // WalkthroughOptions::depthMarch
    render::OcclusionSettings occlusion{.on = false};  // RenderSettings::occlusion of every mode
    bool portalCulling = true;                         // WalkthroughSettings::portalCulling of every mode
};

// With occlusion culling, the triangles of the last frame that were submitted but not drawn
// (a mode's triangles a frame are those drawn); 0 without it.
double trianglesCulled(const std::optional<render::gl::OcclusionCounts>& counts);

// One walkthrough mode of a runWalkthroughModes call.
struct WalkRun {
    std::optional<walls::WallSetup> walls;  // nullopt: full geometry
    // The scene and description the mode draws, when not the context's (`bench --compare-scene`:
    // the same model with other cells and walls, drawn along the context's eye path). Not
    // owned; both or neither.
    const scenes::Scene* scene = nullptr;
    const scenes::SceneDescription* description = nullptr;
    ModeAccumulator* acc = nullptr;  // not null; its mode's lodPixels, triangleBudget and
                                     // frameBudgetMs set the levels of detail and budgets
    walkthrough::Transition transition = walkthrough::Transition::Blend;
    std::optional<walls::WallKind> wallKind;  // the walls' kind when not the context's (flat beside depth)
    // As `cavewall run` pages: in the background under the default texture budget and upload
    // limit, from a cold start (three warm-up frames), so the timed frames include every
    // page-in, upload and fallback. Otherwise every texture of the path is made resident in a
    // warm-up pass over the whole path.
    bool paged = false;
    // Maciel & Shirley's (1995) textured clusters (ClusterOptions) instead of walls, held to
    // the mode's frameBudgetMs by the frame-time controller as `cavewall run --hierarchy` holds it.
    bool clusters = false;
    bool storeReference = false;  // its compared images become the reference
    // >= 0: the triangle budget is the median triangles per frame of that earlier run's warm-up
    // pass over the path (the same frames, drawn as its timed pass draws them), set on `acc`.
    int budgetFrom = -1;
};

// Whether path frame `frame` is compared with full geometry (every --compare-every'th).
bool compared(const ModeContext& c, long frame);

// Whether a display's modes get the stereo error: stereo, with each eye's pixels apart (all
// but anaglyph, whose eyes share one image and so one depth buffer).
bool measuresStereo(const display::Display& display);
// Whether compared frames read depth back: where the display's modes get the stereo error.
bool readsDepth(const ModeContext& c);

// Runs walkthrough modes over the path, interleaved: after every run's warm-up, each path frame
// is drawn by every run in turn, so that their times share the machine's load of the same
// seconds (a shared machine's load moves by 2x between minutes; ratios of times taken minutes
// apart are not honest). Compared frames of the run with storeReference go to `reference`
// (it comes first), the others' are compared with them. `alsoEachFrame`, when set, is called
// with every path frame after the runs have drawn it (in.readImages: whether it is compared):
// other modes drawn in the same seconds (the cell modes, app/bench/gl/cell_modes.h).
void runWalkthroughModes(const ModeContext& c, std::vector<WalkRun>& runs, ReferenceImages& reference,
                         const std::function<void(const walkthrough::FrameInput&)>& alsoEachFrame = {});

// Baking on demand from a cold cache, alone: `walls` (planned, its folder and
// manifest the baker's, whose cache is empty), drawn as `cavewall run --bake-on-demand` draws
// (background paging, `baker` baking what the frames want). The first path frame is drawn once
// first (its end, from `start`, is the first frame after the scene's load: `start` is taken
// before planning the walls); then every path frame is timed into `acc` and compared with
// `reference`. Returns the first frame's seconds.
double runOnDemandMode(const ModeContext& c, walls::WallSetup walls, walls::gl::BackgroundBaker& baker,
                       ModeAccumulator& acc, const ReferenceImages& reference,
                       std::chrono::steady_clock::time_point start);

// The machine's own frame-time noise beside a mode's: the path drawn as `mode` draws it (walls
// or not, its levels of detail; every texture resident), each frame followed by frame
// `frameIndex` of the path again. The repeated frame's work never changes, so its spread is
// the machine's (scheduling, other tenants), measured in the same seconds as the path's.
struct NoiseComparison {
    bench::TimeStats path, repeated;
};
NoiseComparison interleavedNoise(const ModeContext& c, std::optional<walls::WallSetup> walls,
                                 const bench::ModeResult& mode, long frameIndex);

}  // namespace cavewall::bench::gl
