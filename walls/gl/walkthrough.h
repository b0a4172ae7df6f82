#pragma once
// The walkthrough runtime: one frame of a scene with textured virtual walls on every screen and
// eye of a display (cavewall issue 5). GL-side library class, driven by `cavewall run`, the
// demo, the bench and (later) cluster mode: the caller owns the input side (tracker, pipeline,
// navigation) and passes plain FrameInput values, so rank 0 of a cluster can broadcast them.
//
// Per frame (renderFrame):
//  1. the cyclopean eye in the world = worldFromCave * head position; FrameSelector::select(eye)
//     gives the cell, every bounding wall's texture weights and geometryWeight, and the cells
//     drawn as geometry. One selection per frame, shared by both eyes and all screens.
//  2. the pager is told which textures are drawn now (weight > 0) and which soon (those the
//     selection would draw 1.5 m away in each of 8 directions: the neighbouring zones); ready
//     textures are uploaded within a per-frame byte budget (WalkthroughOptions).
//  3. a wall whose textures are not all resident keeps the textures it drew last (from the same
//     side) if they are still resident and still within the plan's alpha for this eye
//     (maxAngularError), else it is drawn as geometry (its cell behind joins the geometry
//     cells): a wall is never black or missing. Such walls are flagged `fallback`.
//  4. per screen and eye: all structure + objects without a cell + objects of the geometry
//     cells (frustum-culled by the scene renderer), then the wall quads (wall_pass.h), then the
//     hand cursor.
//  5. the error: maxAngularError (walls/angular_error.h) of every texture drawn with non-zero
//     weight against the true eye, in degrees and in pixels (see FrameResult::maxErrorPixels).
// Transition Warp (warp_pass.h): every wall drawn with textures and no geometry weight gets the
// structure behind it warped into its texture's view (the texture of the largest weight when it
// mixes several), between steps 4's geometry and wall quads. When the warp of such a wall is
// ill-conditioned for any rendered screen and eye (display::warpCondition > kMaxWarpCondition:
// the eye near the wall plane), the wall falls back to geometry (its cell behind drawn, no
// texture, flagged `fallback`) and FrameResult::warpFallbacks counts it.
// Warp-morph (Transition::Warp, seed 002 §2): a wall's mix of textures and geometry becomes
// whichever weighs more (no alpha fade between texture and geometry; textures still cross-fade
// among themselves). When a wall switches between texture and geometry, for morphSeconds of
// FrameInput::time its cell behind (content and structure) is drawn by the warp pass through the
// wall as seen from p = lerp(samplingPoint, eye, s) (texture -> geometry; eye -> samplingPoint
// back), s the elapsed share: it starts as the texture's view and ends exact. During the morph
// the wall draws no quad and reports no textures and geometryWeight 1.
// A scene without virtual walls (or WalkthroughOptions::walls = false) draws all geometry
// (frustum-culled) and never builds the wall program, the pager or the selector.
//
// Frames and units: config/conventions.h. Times in seconds, durations in milliseconds.

#include "display/display.h"
#include "display/gl/context.h"
#include "display/gl/frame_images.h"
#include "display/gl/gpu_timer.h"
#include "display/gl/render_targets.h"
#include "display/gl/scene_renderer.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/bake_manifest.h"
#include "walls/frame_select.h"
#include "walls/gl/hand_cursor.h"
#include "walls/gl/texture_store.h"
#include "walls/gl/wall_pass.h"
#include "walls/gl/warp_pass.h"
#include "walls/plan.h"
#include "walls/texture_pager.h"
#include "walls/visibility.h"

#include <filesystem>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace cavewall::gl {

// Everything the wall pass needs from planning and baking. `plan` must have its depthBehind
// assigned (walls::assignDepthBehind); `folder` holds the manifest's texture files.
struct WallSetup {
    walls::Plan plan;
    walls::VisibilityTable table;
    std::filesystem::path folder;
    walls::BakeManifest manifest;
};

// How structure crossing a textured wall meets the texture (see the header comment).
enum class Transition { Blend, Warp };

struct WalkthroughOptions {
    double textureBudgetMB = 256.0;          // GPU budget of resident wall textures, MB, > 0
    double uploadMBPerFrame = 8.0;           // texture bytes uploaded per frame at most, MB
    RenderSettings render;                   // clear colour, ambient
    // Wait for the pager to decode and upload every requested texture before drawing, so the
    // frames depend only on the input (tests, replays, golden images). Off: a frame never
    // waits, missing textures fall back (step 3).
    bool synchronousPaging = false;
    // Reads every MIP level of a baked texture file on the pager's thread; empty:
    // scenes::readMipLevels. Tests inject slow or failing decoders here.
    walls::TexturePager::Decoder decoder;
    Transition transition = Transition::Blend;  // Warp: structure behind textured walls warped
    double morphSeconds = 0.5;               // Warp: duration of a warp-morph, seconds, > 0
    // Levels of detail (render.lodPixels > 0): the geometry of every frame is drawn at the
    // levels render::chooseLods picks for render.lodPixels, over all screens and eyes
    // at once. triangleBudget > 0 caps the triangles the scene renderer submits per frame (all
    // views; the wall, warp and cursor passes are not counted) by raising the tolerance
    // (seed 004's frame budget); 0: no cap.
    std::size_t triangleBudget = 0;
    // The most a budget may raise the tolerance to, pixels (>= render.lodPixels): beyond it a
    // frame is drawn over budget rather than with coarser shapes (FrameResult::lodOverBudget).
    double lodMaxPixels = 8.0;
};

struct FrameInput {
    long frame = 0;                          // frame number (for the pager's recency)
    double time = 0.0;                       // seconds
    display::HeadPose head;                  // cave frame
    glm::dmat4 worldFromCave{1.0};
    std::optional<HandCursorPose> hand;      // drawn when given
    bool readImages = false;                 // read every rendered image back into FrameResult
    // This frame's triangle budget (with levels of detail), > 0 overrides
    // WalkthroughOptions::triangleBudget: a frame-time controller (display/frame_budget.h)
    // sets it frame by frame, the same on every cluster rank.
    std::size_t triangleBudget = 0;
};

// One wall's state in a frame (walls.csv).
struct WallState {
    int wall = 0;                            // index into Plan::walls
    std::vector<std::pair<int, double>> textures;  // drawn (texture id, weight)
    double geometryWeight = 0.0;             // weight of the cell behind as geometry
    bool fallback = false;                   // wanted textures missing: previous or geometry drawn
    bool beyond = false;                     // a far wall of a neighbour drawn as geometry
                                             // (FrameSelection::beyond): not covered by alpha
    double errorDeg = 0.0;                   // exact worst angular error of its drawn textures
};

struct FrameResult {
    glm::dvec3 eyeWorld{0.0};                // cyclopean eye in the world
    int cell = -1, zone = -1;                // viewer's cell (also without walls); zone of the
                                             // first wall with one (-1 without walls)
    double frameMs = 0.0;                    // renderFrame wall-clock time, until the GPU finished
    double cpuMs = 0.0;                      // CPU time until every command was submitted
    double gpuMs = 0.0;                      // GL_TIME_ELAPSED of the frame's commands
    FrameStats stats;                        // triangles and draw calls, all views
    walls::PagerStats pager;
    double maxErrorDeg = 0.0;                // max over drawn textures (0 without textures)
    // maxErrorDeg converted to pixels on the screens: error (rad) * r² / d * pixels per metre,
    // with d the eye's distance to the screen plane and r its distance to the farthest
    // screen corner (the largest pixels per radian on that screen); max over screens.
    double maxErrorPixels = 0.0;
    // Levels of detail (WalkthroughOptions): the pixel tolerance used this frame (raised above
    // render.lodPixels when the triangle budget needed it), the largest geometric error drawn
    // in pixels, and whether even the coarsest levels exceeded the budget. 0 without levels.
    double lodTolerancePx = 0.0, lodErrorPx = 0.0;
    bool lodOverBudget = false;
    std::size_t geometryTriangles = 0;       // of stats.triangles, what the scene renderer submitted
                                             // (what triangleBudget caps)
    int warpFallbacks = 0;                   // Transition::Warp: walls drawn as geometry because
                                             // their warp was ill-conditioned (eye near the plane)
    std::vector<WallState> walls;
    // Per display screen (index = screen), summed over its eyes: wall-clock CPU ms of its views
    // (geometry, walls, cursor), triangles and draw calls. Screens this instance does not
    // render stay zero.
    std::vector<ViewStats> perScreen;
    std::vector<ScreenImage> images;         // when FrameInput::readImages
};

class Walkthrough {
public:
    // Needs `context` current. Keeps references to scene, description, display and context,
    // which must outlive it. `walls` empty: geometry only. `screens`: the screen indices this
    // instance renders (empty: all), for cluster ranks.
    Walkthrough(const scenes::Scene& scene, const scenes::SceneDescription& description,
                const display::Display& display, Context& context, std::optional<WallSetup> walls,
                WalkthroughOptions options = {}, std::vector<int> screens = {});
    ~Walkthrough();

    FrameResult renderFrame(const FrameInput& input);

    const display::Display& display() const { return _display; }
    const RenderTargets& targets() const { return _targets; }
    bool hasWalls() const { return _walls != nullptr; }
    // Blocks until the pager has decoded everything requested (warm-up for tests and benches).
    void waitForTextures();

private:
    struct WallRuntime;
    std::vector<bool> geometryMask(const walls::FrameSelection& selection) const;
    std::vector<int> visibleObjects(const std::vector<bool>& cells) const;
    std::vector<WallDraw> selectWalls(const FrameInput& input, FrameResult& result, std::vector<bool>& cells);
    void requestTextures(const walls::FrameSelection& selection, glm::dvec3 eyeWorld);
    bool wallInView(const std::vector<display::ScreenView>& views, const glm::dmat4& worldFromCave, int wall) const;
    std::optional<WallDraw> chooseWall(const walls::WallBlend& blend, glm::dvec3 eyeWorld, WallState& state,
                                       std::vector<bool>& cells);
    bool withinBound(const std::vector<std::pair<int, double>>& set, const walls::PlannedWall& wall,
                     glm::dvec3 eyeWorld) const;
    bool warpConditioned(const FrameInput& input, const WarpWall& warp) const;
    static walls::WallBlend binaryBlend(walls::WallBlend blend);
    std::optional<WallDraw> warpWall(const FrameInput& input, const walls::WallBlend& blend, WallState& state,
                                     std::optional<WallDraw> draw, std::vector<bool>& cells,
                                     std::vector<int>& morphCells, FrameResult& result);
    void measureError(glm::dvec3 eyeCave, FrameResult& result) const;
    void drawViews(const FrameInput& input, const render::DrawFilter& filter, const std::vector<WallDraw>& walls,
                   FrameResult& result);
    std::vector<display::ScreenView> renderedViews(const display::HeadPose& head) const;
    void present();

    const scenes::Scene& _scene;
    const scenes::SceneDescription& _description;
    const display::Display& _display;
    Context& _context;
    WalkthroughOptions _options;
    std::vector<int> _screens;
    RenderTargets _targets;
    SceneRenderer _renderer;
    std::unique_ptr<WallRuntime> _walls;
    std::unique_ptr<HandCursorPass> _cursor;
    std::unique_ptr<WarpPass> _warp;         // Transition::Warp with walls only
    std::vector<WarpWall> _warpWalls;        // this frame's warped walls
    GpuTimer _timer;                         // timestamp pairs: llvmpipe's first GL_TIME_ELAPSED is garbage
};

}  // namespace cavewall::gl
