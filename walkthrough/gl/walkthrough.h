#pragma once
// The walkthrough's GL executor: one frame of a scene with textured virtual walls on every
// screen and eye of a display. Driven by `cavewall run`, the demo, the bench and cluster mode:
// the caller owns the input side (tracker, pipeline, navigation) and passes plain
// walkthrough::FrameInput values (walkthrough/frame_types.h), so rank 0 of a cluster can broadcast them.
//
// Rule: no pure logic under */gl/ beyond what needs a context. Every decision of a frame (the
// cell, each wall's textures and weights, the paging requests, the fallbacks, the warp-morph,
// the error) is made by walkthrough::FramePlanner (walkthrough/frame_planner.h, unit-tested without GL);
// this class only owns the pager, the texture store and the GL passes, and per frame:
//  1. asks the planner which textures are wanted (now / soon) and tells the pager (and, baking
//     on demand, the background baker, whose finished textures join the pager); uploads what
//     is ready within the per-frame byte budget (WalkthroughSettings);
//  2. has the planner decide the frame against what is resident, maps texture ids to GL names;
//     with geometry paging (WalkthroughSettings::geometryBudgetMB), the cells likewise: the
//     pager's loader packs a cell's mesh groups on its thread, this class uploads them into
//     the scene renderer's per-group buffers (render/gl/scene_gpu.h; a mesh shared by cells
//     is stored once) and deletes the buffers of evicted groups, so
//     FrameResult::geometry.residentMB is the GPU bytes of resident groups;
//  3. chooses the levels of detail (SceneRenderer::chooseLods) for the planned objects;
//  4. per screen and eye (drawViews): the planned geometry (frustum-culled by the scene
//     renderer), the warp pass (Transition::Warp, warp_pass.h), the wall quads (wall_pass.h),
//     the hand cursor;
//  5. presents to the windows, times the frame and reads images back when asked;
//  6. with FrameInput::readDepth, after the frame is timed: per view, the walls drawn again
//     depth only (WallPass::drawDepth, DepthWallPass::drawDepth: the depth each eye sees on a
//     flat wall or a depth wall), then the view's depth read back as eye distances. Each image
//     has its own depth buffer, so every eye's geometry depth is still there. The warp and the
//     clusters' impostors keep the depth their own passes write.
// A scene without virtual walls (or no WallSetup) draws all geometry (frustum-culled) and never
// builds the wall program, the pager or the selector.
//
// Context handling lives here: the constructor and renderFrame make the context current, so a
// caller that baked with another context in between needs no makeCurrent of its own.
//
// Frames and units: config/conventions.h. Times in seconds, durations in milliseconds.

#include "display/display.h"
#include "display/gl/context.h"
#include "display/gl/frame_images.h"
#include "display/gl/gpu_timer.h"
#include "display/gl/projector_pass.h"
#include "display/gl/render_targets.h"
#include "render/gl/scene_renderer.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walkthrough/frame_planner.h"
#include "walkthrough/frame_types.h"
#include "hierarchy/gl/cluster_impostors.h"
#include "walkthrough/gl/hand_cursor.h"
#include "walls/depth_wall.h"
#include "walls/gl/depth_wall_pass.h"
#include "walls/gl/wall_pass.h"
#include "walls/gl/warp_pass.h"
#include "walls/wall_setup.h"

#include <memory>
#include <optional>
#include <vector>

namespace cavewall::walls::gl {
class BackgroundBaker;  // walls/gl/background_baker.h
}  // namespace cavewall::walls::gl

namespace cavewall::walkthrough::gl {

// Maciel & Shirley's (1995) textured clusters (hierarchy/gl/cluster_impostors.h,
// hierarchy/cluster_frame.h): the content objects are drawn as the frame's selection from the
// model hierarchy under a budget in predicted milliseconds, objects at full detail (or their
// level of detail) and clusters as textured or average-colour boxes; structure objects are
// always drawn.
struct ClusterOptions {
    bool enabled = false;
    glm::ivec3 divisions{8, 2, 8};  // the hierarchy's finest grid, cells per axis
    hierarchy::gl::ClusterBakeSettings bake;
    std::filesystem::path cache;      // the bake cache folder (clusters/ inside it)
    double budgetMs = 1000.0 / 60.0;  // predicted cost per frame unless FrameInput's
    int coherenceFrames = 3;          // ClusterCoherence threshold
    int fadeFrames = 8;               // hierarchy::ClusterFades: frames a switch is
                                      // cross-faded over (<= 1: none)
    int costResolution = 0;           // pixels of the cost view's side (cluster_costs.h);
                                      // 0: the display's largest screen side
};

struct WalkthroughOptions : walkthrough::WalkthroughSettings {
    ClusterOptions clusters;
    render::gl::RenderSettings render;  // clear colour, ambient, levels of detail
    // Depth: walls drawn by walls::gl::DepthWallPass from a depth bake (BakeSettings::kind, the
    // manifest's depth files, paged and budgeted with the colour by walls::TexturePager and
    // walls::gl::TextureStore); a texture without a depth file is drawn flat, one whose depth file is
    // bad fails like a bad colour file (the wall keeps its last texture or draws geometry).
    walls::WallKind wallKind = walls::WallKind::Flat;
    walls::ReprojectSettings depthMarch;  // the depth wall pass's march (steps, cut sheets)
    // Baking on demand (walls/gl/background_baker.h; flat or depth walls, not with synchronous paging):
    // each frame tells the baker what it wants and hands what it baked (or evicted from the
    // disk) to the texture pager. Not owned; must outlive the walkthrough. Null: none.
    walls::gl::BackgroundBaker* baker = nullptr;
};

// What resident geometry is measured against, in MB (2^20 bytes) of GPU buffers, with the
// renderer's levels of detail: the whole model (every mesh once), the largest three cells (each
// cell's own meshes once, walls::cellGeometryBytes) and the always-resident shared buffers
// (structure, objects without a cell), which paging never frees.
struct GeometryYardsticks {
    double wholeModelMB = 0.0, largestThreeCellsMB = 0.0, sharedMB = 0.0;
};

class Walkthrough {
public:
    // Makes `context` current. Keeps references to scene, description, display and context,
    // which must outlive it. `walls` (walls::prepareWalls, then baked: folder and manifest set)
    // empty: geometry only. `screens`: the screen indices this instance renders (empty: all),
    // for cluster ranks. Throws Error when geometry paging is asked for with the warp transition,
    // and when the control (WalkthroughSettings::wallTextures off, which pages, uploads and draws
    // no texture) is asked for with the warp transition or a background baker.
    Walkthrough(const scenes::Scene& scene, const scenes::SceneDescription& description,
                const display::Display& display, display::gl::Context& context, std::optional<walls::WallSetup> walls,
                WalkthroughOptions options = {}, std::vector<int> screens = {});
    ~Walkthrough();

    walkthrough::FrameResult renderFrame(const walkthrough::FrameInput& input);

    const display::Display& display() const { return _display; }
    const display::gl::RenderTargets& targets() const { return _targets; }
    bool hasWalls() const { return _walls != nullptr; }
    bool hasClusters() const { return _clusters != nullptr; }
    // With clusters: the hierarchy, measured costs and accuracies, and how the impostors were
    // made; the last frame's plan (what was drawn).
    const hierarchy::ClusterModel* clusterModel() const;
    const hierarchy::gl::ClusterBakeStats* clusterBakeStats() const;
    const hierarchy::ClusterFramePlan* lastClusterPlan() const;
    int clusterCostResolution() const;  // the cost view's side in pixels (0 without clusters)
    struct ClusterRuntime;              // walkthrough.cpp
    // Blocks until the pager has decoded everything requested (warm-up for tests and benches).
    void waitForTextures();
    GeometryYardsticks geometryYardsticks() const;
    // With RenderSettings::occlusion on: the scene renderer's draws and triangles submitted
    // and drawn since the last call (waits for the GPU).
    std::optional<render::gl::OcclusionCounts> readOcclusionCounts() { return _renderer.readOcclusionCounts(); }

private:
    struct WallRuntime;
    // With clusters: the frame's selection; its objects (plus structure) replace `objects`.
    void planClusters(const walkthrough::FrameInput& input, glm::dvec3 eyeWorld, std::vector<int>& objects,
                      walkthrough::FrameResult& result);
    struct CellPaging;
    void makeResident(int group);
    walkthrough::FramePlan planFrame(const walkthrough::FrameInput& input,
                                     const std::vector<display::ScreenView>& views);
    std::vector<walls::gl::WallDraw> wallDraws(const walkthrough::FramePlan& plan) const;
    // Depth walls: the walls of `flat` whose every texture has its depth move to the result.
    std::vector<walls::gl::DepthWallDraw> depthWallDraws(const walkthrough::FramePlan& plan,
                                                         std::vector<walls::gl::WallDraw>& flat);
    struct WallDraws {
        std::vector<walls::gl::WallDraw> flat;
        std::vector<walls::gl::DepthWallDraw> depth;
    };
    WallDraws allWallDraws(const walkthrough::FramePlan& plan);
    void drawViews(const walkthrough::FrameInput& input, const std::vector<display::ScreenView>& views,
                   const render::DrawFilter& filter, const walkthrough::FramePlan& plan, const WallDraws& walls,
                   walkthrough::FrameResult& result);
    // After the frame: every view's walls again, depth only, then its depth read back.
    std::vector<walkthrough::ViewDepth> readDepths(const walkthrough::FrameInput& input,
                                                   const std::vector<display::ScreenView>& views,
                                                   const WallDraws& walls) const;
    std::vector<display::ScreenView> renderedViews(const display::HeadPose& head) const;
    bool reframing(int screen) const;
    void reframeWindows();
    void present();

    const scenes::Scene& _scene;
    const scenes::SceneDescription& _description;
    display::Display _display;  // a copy: its windowed screens may take their windows' shapes
    display::gl::Context& _context;
    WalkthroughOptions _options;
    std::vector<int> _screens;
    display::gl::RenderTargets _targets;
    render::gl::SceneRenderer _renderer;
    std::unique_ptr<WallRuntime> _walls;
    std::unique_ptr<ClusterRuntime> _clusters;
    std::size_t _uploadedBytes = 0;      // wall texture bytes uploaded by the last planFrame
    int _bakedNow = 0, _bakedTotal = 0;  // baking on demand: textures handed to the pager
    std::unique_ptr<walkthrough::FramePlanner> _planner;
    std::unique_ptr<HandCursorPass> _cursor;
    std::unique_ptr<walls::gl::WarpPass> _warp;
    std::unique_ptr<display::gl::ProjectorPasses>
        _projectors;               // per-screen projector warp and blend  // Transition::Warp with walls only
    display::gl::GpuTimer _timer;  // timestamp pairs: llvmpipe's first GL_TIME_ELAPSED is garbage
};

}  // namespace cavewall::walkthrough::gl
