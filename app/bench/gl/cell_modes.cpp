#include "app/bench/gl/cell_modes.h"

#include "display/eye_distance.h"
#include "display/timing.h"
#include "display/gl/render_targets.h"
#include "render/gl/scene_renderer.h"
#include "render/gl/view_loop.h"
#include "render/lod_choice.h"
#include "walkthrough/frame_planner.h"
#include "walls/cell_openings.h"
#include "walls/frame_select.h"
#include "walls/gl/texture_store.h"
#include "walls/gl/wall_pass.h"
#include "walls/gl/wall_quad.h"

#include <cassert>
#include <chrono>
#include <functional>

namespace cavewall::bench::gl {

namespace {

std::vector<bool> cellMask(const walls::FrameSelection& s, std::size_t cellCount, bool nearOnly) {
    std::vector<bool> cells(cellCount, s.allGeometry());
    if (!nearOnly)
        for (int c : s.geometryCells)
            if (c >= 0 && c < static_cast<int>(cellCount)) cells[c] = true;
    if (s.cell >= 0 && s.cell < static_cast<int>(cellCount)) cells[s.cell] = true;
    return cells;
}

// The layer's texture: 512 x 512 (the bake's largest by default), a gradient under a
// checkerboard so that every MIP level differs, with its MIP chain.
display::gl::GlObject layerTexture() {
    constexpr int kSize = 512;
    std::vector<scenes::Image> levels;
    for (int s = kSize; s >= 1; s /= 2) {
        scenes::Image l{"layer", s, s, std::vector<std::uint8_t>(std::size_t(s) * s * 4, 255)};
        for (int y = 0; y < s; ++y)
            for (int x = 0; x < s; ++x) {
                std::uint8_t* p = &l.rgba[(std::size_t(y) * s + x) * 4];
                p[0] = static_cast<std::uint8_t>(x * 255 / s);
                p[1] = ((x * 8 / s) + (y * 8 / s)) % 2 == 0 ? 200 : 60;
                p[2] = static_cast<std::uint8_t>(y * 255 / s);
            }
        levels.push_back(std::move(l));
    }
    return walls::gl::uploadWallTexture(std::move(levels));
}

// Every view's depth as eye distances, after the frame: geometry only (each image keeps its own
// depth buffer). The near limit's bare wall quads and the layer write no depth.
std::vector<walkthrough::ViewDepth> readViewDepths(const std::vector<display::ScreenView>& views,
                                                   const display::gl::RenderTargets& targets) {
    std::vector<walkthrough::ViewDepth> depths;
    for (const display::ScreenView& view : views) {
        const int image = display::gl::RenderTargets::imageOf(view.pass);
        const display::Viewport& v = view.pass.viewport;
        depths.push_back(
            {view.screen, image, view.pass.eye, v.width, v.height,
             display::eyeDistances(view.frustum, {v.width, v.height}, targets.readDepth(view.screen, image, v))});
    }
    return depths;
}

}  // namespace

struct CellModes::State {
    State(const ModeContext& c, const walls::WallSetup& setup, double lodPixels)
        : c(c), setup(setup), lodPixels(lodPixels), selector(setup.plan, setup.table, c.description),
          openings(setup.plan, c.description, c.scene), targets(c.display, c.context),
          renderer(c.scene, settingsOf(c, lodPixels)),
          bare(walls::gl::uploadWallTexture({scenes::Image{"bare", 1, 1, {128, 128, 128, 255}}})),
          layer(layerTexture()), sampler(walls::gl::wallSampler()) {}
    static render::gl::RenderSettings settingsOf(const ModeContext& c, double lodPixels) {
        render::gl::RenderSettings settings;
        settings.lodPixels = lodPixels;
        settings.occlusion = c.occlusion;
        return settings;
    }
    const ModeContext& c;
    const walls::WallSetup& setup;
    const double lodPixels;
    const walls::FrameSelector selector;
    const walls::CellOpenings openings;
    walls::PortalSets portals;
    const display::gl::RenderTargets targets;
    render::gl::SceneRenderer renderer;
    // The limit draws every wall of the viewer's cell as a bare quad: one 1x1 texture through
    // the walls' own pass, so it pays the quads' fill but no texture blending or paging.
    const walls::gl::WallPass quadPass;
    const display::gl::GlObject bare, layer, sampler;
};

CellModes::CellModes(const ModeContext& c, const walls::WallSetup& setup, double lodPixels)
    : _s(std::make_unique<State>(c, setup, lodPixels)) {}

CellModes::~CellModes() = default;

FrameCost CellModes::draw(const walkthrough::FrameInput& in, CellDraw kind) {
    State& s = *_s;
    const ModeContext& c = s.c;
    const auto start = std::chrono::steady_clock::now();
    const glm::dvec3 eye(in.worldFromCave * glm::dvec4(in.head.position, 1.0));
    const walls::FrameSelection selection = s.selector.select(eye);
    const std::vector<bool> cells = cellMask(selection, c.description.cells.size(), kind == CellDraw::Near);
    const std::vector<int> objects = walkthrough::objectsOfCells(c.scene, cells);
    if (c.portalCulling) s.openings.frameSets(selection.cell, cells, c.scene, s.portals);
    render::DrawFilter filter;
    filter.objects = &objects;
    if (c.portalCulling && !s.portals.objectSet.empty()) filter.portals = &s.portals;
    s.renderer.setOcclusionContext(static_cast<std::uint32_t>(kind));
    std::vector<walls::gl::WallDraw> quads;
    if (kind == CellDraw::Near)
        for (const walls::WallBlend& b : selection.walls)
            quads.push_back({walls::quadSeenFrom(s.setup.plan.walls[b.wall].quad, b.side), {s.bare.id()}, {1.0f}, 1});
    const glm::dmat4 caveFromWorld = glm::inverse(in.worldFromCave);
    display::FrameStats quadStats;
    auto afterView = [&](const display::ScreenView& view) {
        if (kind == CellDraw::Near)
            s.quadPass.draw(quads, view.frustum, caveFromWorld, 0, quadStats);
        else  // the view's screen, in the cave frame
            s.quadPass.draw({{c.display.quad(view.screen), {s.layer.id()}, {0.0f}, 1}}, view.frustum, glm::dmat4(1.0),
                            s.sampler.id(), quadStats);
    };
    const std::vector<display::ScreenView> views = c.display.views(in.head);
    render::FrameLod lod;
    if (s.renderer.hasLods()) {
        lod = render::chooseLods(s.renderer.renderScene(), views, in.worldFromCave, filter, s.lodPixels);
        filter.lodLevels = &lod.levels;
    }
    const display::FrameStats stats = s.renderer.render(views, s.targets, in.worldFromCave, filter,
                                                        kind != CellDraw::Cells ? std::function(afterView) : nullptr);
    FrameCost cost;
    cost.gpuMs = s.renderer.waitGpuMs();
    const std::optional<render::gl::OcclusionCounts> counts = s.renderer.readOcclusionCounts();
    cost.frameMs = display::msSince(start);
    cost.cpuMs = stats.cpuMs;
    cost.triangles = static_cast<double>(stats.triangles + quadStats.triangles) - trianglesCulled(counts);
    cost.drawCalls = static_cast<double>(stats.drawCalls + quadStats.drawCalls);
    cost.lodErrorPx = lod.maxErrorPx;
    cost.lodTolerancePx = lod.tolerancePx;
    cost.perScreen = render::gl::statsPerScreen(views, stats, c.display.screens().size());
    return cost;
}

void CellModes::warmUp(const std::vector<CellRun>& runs) {
    for (long i = 0; i < std::min<long>(3, _s->c.path.frames.size()); ++i)
        for (const CellRun& r : runs) draw(_s->c.path.frames[i], r.draw);
}

void CellModes::drawFrame(const walkthrough::FrameInput& in, const std::vector<CellRun>& runs,
                          const ReferenceImages& reference) {
    const ModeContext& c = _s->c;
    for (const CellRun& r : runs) {
        assert(r.acc->mode().lodPixels == _s->lodPixels);
        r.acc->addFrame(draw(in, r.draw));
        if (!in.readImages) continue;
        const std::vector<walkthrough::ViewDepth> depths = readsDepth(c)
                                                               ? readViewDepths(c.display.views(in.head), _s->targets)
                                                               : std::vector<walkthrough::ViewDepth>{};
        r.acc->compare(in.frame, in.head, display::gl::readFrame(c.display, _s->targets), depths,
                       reference.at(in.frame));
    }
}

void runCellModes(const ModeContext& c, const walls::WallSetup& setup, const std::vector<CellRun>& runs,
                  const ReferenceImages& reference) {
    assert(!runs.empty());
    CellModes modes(c, setup, runs.front().acc->mode().lodPixels);
    modes.warmUp(runs);
    // Frame by frame, every run in turn: their times are taken in the same seconds.
    for (walkthrough::FrameInput in : c.path.frames) {
        in.readImages = compared(c, in.frame);
        modes.drawFrame(in, runs, reference);
    }
}

}  // namespace cavewall::bench::gl
