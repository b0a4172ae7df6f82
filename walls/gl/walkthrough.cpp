#include "walls/gl/walkthrough.h"

#include "display/timing.h"
#include "scenes/image_io.h"
#include "scenes/region.h"
#include "display/pixel_scale.h"
#include "display/warp.h"
#include "walls/angular_error.h"
#include "display/gl/view_loop.h"
#include "render/lod_choice.h"
#include "walls/gl/bake_key.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

namespace cavewall::gl {

namespace {

using Clock = std::chrono::steady_clock;

using display::msSince;

// Every MIP level of a baked texture file (walls/gl/texture_mips.h convention).
std::vector<scenes::Image> decodeBakedTexture(const std::filesystem::path& file) {
    return scenes::readMipLevels(file);
}

}  // namespace

struct Walkthrough::WallRuntime {
    WallRuntime(WallSetup s, const scenes::SceneDescription& description, const WalkthroughOptions& options)
        : setup(std::move(s)), selector(setup.plan, setup.table, description),
          pager(setup.folder, setup.manifest, options.textureBudgetMB,
                options.decoder ? options.decoder : walls::TexturePager::Decoder(decodeBakedTexture)),
          store(pager, static_cast<std::size_t>(options.uploadMBPerFrame * 1024 * 1024)),
          lastDrawn(setup.plan.walls.size()), morphs(setup.plan.walls.size()) {
        for (const walls::Texture& t : setup.plan.textures) textures[t.id] = &t;
    }

    int sideOf(int cell, int wall) const {
        for (int i = 0; i < static_cast<int>(setup.plan.sides.size()); ++i)
            if (setup.plan.sides[i].cell == cell && setup.plan.sides[i].wall == wall) return i;
        return -1;
    }

    WallSetup setup;
    walls::FrameSelector selector;
    walls::TexturePager pager;
    TextureStore store;
    WallPass pass;
    std::map<int, const walls::Texture*> textures;                  // by id
    // Per wall: the side and textures drawn last; reused only from the same side.
    std::vector<std::pair<int, std::vector<std::pair<int, double>>>> lastDrawn;
    // Per wall, Transition::Warp: what it drew last (kind -1: nothing yet, 0 geometry, 1 texture)
    // and its warp-morph.
    struct Morph {
        int kind = -1;
        std::optional<glm::dvec3> lastSamplingPoint;
        bool active = false, toGeometry = false;
        double start = 0.0;              // FrameInput::time of the switch
        glm::dvec3 samplingPoint{0.0};   // the texture's end of the morph
    };
    std::vector<Morph> morphs;
};

namespace {

// Makes `context` current before any member touches GL: a bake that made (and dropped) its own
// context, for one, leaves no context current on this thread.
Context& madeCurrent(Context& context) {
    context.makeCurrent();
    return context;
}

}  // namespace

Walkthrough::Walkthrough(const scenes::Scene& scene, const scenes::SceneDescription& description,
                         const display::Display& display, Context& context, std::optional<WallSetup> walls,
                         WalkthroughOptions options, std::vector<int> screens)
    : _scene(scene), _description(description), _display(display), _context(madeCurrent(context)), _options(options),
      _screens(std::move(screens)), _targets(display, context), _renderer(scene, options.render) {
    if (_screens.empty())
        for (int s = 0; s < static_cast<int>(display.screens().size()); ++s) _screens.push_back(s);
    if (walls && !walls->plan.walls.empty()) _walls = std::make_unique<WallRuntime>(std::move(*walls), description, options);
    if (_walls && options.transition == Transition::Warp)
        _warp = std::make_unique<WarpPass>(scene, _renderer.gpu(), options.render, display.depthRange().near);
}

Walkthrough::~Walkthrough() = default;

void Walkthrough::waitForTextures() {
    if (!_walls) return;
    _walls->pager.waitIdle();
    while (_walls->store.update() > 0) {
    }
}

std::vector<bool> Walkthrough::geometryMask(const walls::FrameSelection& selection) const {
    std::vector<bool> cells(_description.cells.size(), selection.allGeometry());
    for (int c : selection.geometryCells)
        if (c >= 0 && c < static_cast<int>(cells.size())) cells[c] = true;
    return cells;
}

std::vector<int> Walkthrough::visibleObjects(const std::vector<bool>& cells) const {
    std::vector<int> out;
    for (int i = 0; i < static_cast<int>(_scene.objects.size()); ++i) {
        const scenes::Object& o = _scene.objects[i];
        if (o.role == scenes::Role::Structure || o.cell < 0 || o.cell >= static_cast<int>(cells.size()) || cells[o.cell])
            out.push_back(i);
    }
    return out;
}

// Tells the pager what this frame draws and what nearby zones may draw soon, then uploads what
// is ready (header, step 2).
void Walkthrough::requestTextures(const walls::FrameSelection& selection, glm::dvec3 eyeWorld) {
    WallRuntime& w = *_walls;
    std::vector<int> now, soon;
    const glm::dvec2 eye(eyeWorld.x, eyeWorld.z);
    for (const walls::WallBlend& b : selection.walls) {
        for (const auto& [id, weight] : b.textures) now.push_back(id);
        const int side = w.sideOf(selection.cell, b.wall);
        if (side < 0) continue;
        // Neighbouring zones: what the selection would draw 1.5 m away in each direction.
        for (int dx = -1; dx <= 1; ++dx)
            for (int dz = -1; dz <= 1; ++dz)
                for (const auto& [id, weight] : w.selector.blendAt(side, eye + 1.5 * glm::dvec2(dx, dz)).textures)
                    soon.push_back(id);
    }
    for (const walls::WallBlend& b : selection.beyond)
        for (const auto& [id, weight] : b.textures) now.push_back(id);
    w.pager.request(now, soon);
    if (_options.synchronousPaging) w.pager.waitIdle();
    // One upload round per frame; synchronous paging uploads until nothing is left.
    while (w.store.update() > 0 && _options.synchronousPaging) {
    }
}

// True when every texture of `set` is within the plan's alpha for `eyeWorld`: a stale texture
// beyond the bound is worse than the geometry.
bool Walkthrough::withinBound(const std::vector<std::pair<int, double>>& set, const walls::PlannedWall& wall,
                              glm::dvec3 eyeWorld) const {
    const double alpha = glm::radians(_walls->setup.plan.alphaDeg) + walls::kErrorTolerance;
    for (const auto& [id, weight] : set) {
        auto it = _walls->textures.find(id);
        if (it == _walls->textures.end() ||
            walls::maxAngularError(eyeWorld, it->second->samplingPoint, wall.quad, wall.depthBehind) > alpha)
            return false;
    }
    return true;
}

// What one wall draws (header, step 3); a wall drawn as geometry adds its cell behind to
// `cells`. Returns the quad to draw, if any.
std::optional<WallDraw> Walkthrough::chooseWall(const walls::WallBlend& b, glm::dvec3 eyeWorld, WallState& state,
                                                std::vector<bool>& cells) {
    WallRuntime& w = *_walls;
    const walls::PlannedWall& planned = w.setup.plan.walls[b.wall];
    state = WallState{b.wall, b.textures, b.geometryWeight, false};
    auto allResident = [&](const std::vector<std::pair<int, double>>& set) {
        return !set.empty() && std::all_of(set.begin(), set.end(), [&](auto& t) { return w.store.resident(t.first); });
    };
    if (!b.textures.empty() && !allResident(b.textures)) {
        state.fallback = true;
        const auto& [lastSide, last] = w.lastDrawn[b.wall];
        const bool keep = lastSide == b.side && allResident(last) && withinBound(last, planned, eyeWorld);
        state.textures = keep ? last : std::vector<std::pair<int, double>>{};
        if (state.textures.empty()) state.geometryWeight = 1.0;
    }
    const int behind = planned.cells[1 - b.side];
    if (state.geometryWeight > 0.0 && behind >= 0 && behind < static_cast<int>(cells.size())) cells[behind] = true;
    if (state.textures.empty()) return std::nullopt;
    w.lastDrawn[b.wall] = {b.side, state.textures};
    // Textures seen from the back were baked on the mirrored quad (walls/gl/baker.h).
    WallDraw d{walls::quadSeenFrom(planned.quad, b.side), {}, {}, 0};
    std::vector<std::pair<int, double>> set = state.textures;
    std::sort(set.begin(), set.end(), [](auto& a, auto& c) { return a.second > c.second; });
    double total = 0.0, kept = 0.0;
    for (const auto& [id, weight] : set) {
        total += weight;
        if (d.count == kMaxWallTextures) continue;
        kept += weight;
        d.textures[d.count] = w.store.texture(id);
        d.weights[d.count++] = static_cast<float>(weight);
    }
    // More than kMaxWallTextures (never planned): the kept ones take the dropped weight.
    for (int i = 0; i < d.count && kept > 0.0; ++i) d.weights[i] = static_cast<float>(d.weights[i] * total / kept);
    return d;
}

// True when the warp of `warp` is well-conditioned for every rendered view (display/warp.h).
bool Walkthrough::warpConditioned(const FrameInput& input, const WarpWall& warp) const {
    const glm::dmat4 caveFromWorld = glm::inverse(input.worldFromCave);
    for (const display::ScreenView& view : renderedViews(input.head))
        if (!(display::warpCondition(warpFor(warp, view, caveFromWorld, _display.depthRange().near)) <=
              display::kMaxWarpCondition))
            return false;
    return true;
}

// Transition::Warp: a blend of textures and geometry becomes whichever has the larger weight
// (the warp-morph replaces the fade); textures keep their relative weights.
walls::WallBlend Walkthrough::binaryBlend(walls::WallBlend b) {
    if (b.textures.empty() || b.geometryWeight <= 0.0 || b.geometryWeight >= 1.0) return b;
    if (b.geometryWeight >= 0.5) {
        b.textures.clear();
    } else {
        for (auto& [id, weight] : b.textures) weight /= 1.0 - b.geometryWeight;
    }
    b.geometryWeight = b.textures.empty() ? 1.0 : 0.0;
    return b;
}

// Transition::Warp after chooseWall (header): starts or continues the wall's warp-morph, queues
// its warp, or falls back to geometry. Returns the quad to draw, if any; `morphCells` collects the
// cells drawn warped instead of by the scene renderer.
std::optional<WallDraw> Walkthrough::warpWall(const FrameInput& input, const walls::WallBlend& b, WallState& state,
                                              std::optional<WallDraw> draw, std::vector<bool>& cells,
                                              std::vector<int>& morphCells, FrameResult& result) {
    WallRuntime& w = *_walls;
    const walls::PlannedWall& planned = w.setup.plan.walls[b.wall];
    const int behind = planned.cells[1 - b.side];
    std::optional<glm::dvec3> samplingPoint;
    if (draw && !state.textures.empty()) {
        const auto largest = std::max_element(state.textures.begin(), state.textures.end(),
                                              [](auto& x, auto& y) { return x.second < y.second; });
        if (auto t = w.textures.find(largest->first); t != w.textures.end()) samplingPoint = t->second->samplingPoint;
    }
    WallRuntime::Morph& m = w.morphs[b.wall];
    const int kind = draw ? 1 : 0;
    if (m.kind >= 0 && kind != m.kind && (kind == 1 ? samplingPoint.has_value() : m.lastSamplingPoint.has_value())) {
        m.active = true;
        m.start = input.time;
        m.toGeometry = kind == 0;
        m.samplingPoint = m.toGeometry ? *m.lastSamplingPoint : *samplingPoint;
    }
    m.kind = kind;
    if (samplingPoint) m.lastSamplingPoint = samplingPoint;
    const double s = (input.time - m.start) / _options.morphSeconds;
    if (m.active && !(s >= 0.0 && s < 1.0)) m.active = false;
    WarpWall warp{walls::quadSeenFrom(planned.quad, b.side), samplingPoint.value_or(glm::dvec3(0.0)), -1};
    if (m.active) {
        // The viewpoint moves from the sampling point to the eye (to geometry) or back.
        warp.samplingPoint = m.toGeometry ? glm::mix(m.samplingPoint, result.eyeWorld, s)
                                          : glm::mix(result.eyeWorld, m.samplingPoint, s);
        warp.cell = behind;
    } else if (!samplingPoint || state.geometryWeight > 0.0) {
        return draw;
    }
    if (!warpConditioned(input, warp)) {
        m.active = false;
        state.textures.clear();
        state.geometryWeight = 1.0;
        state.fallback = true;
        if (behind >= 0 && behind < static_cast<int>(cells.size())) cells[behind] = true;
        ++result.warpFallbacks;
        return std::nullopt;
    }
    _warpWalls.push_back(warp);
    if (!m.active) return draw;
    state.textures.clear();
    state.geometryWeight = 1.0;
    morphCells.push_back(behind);
    return std::nullopt;
}

void Walkthrough::measureError(glm::dvec3 eyeCave, FrameResult& result) const {
    double worst = 0.0;
    for (WallState& s : result.walls) {
        const walls::PlannedWall& planned = _walls->setup.plan.walls[s.wall];
        double wall = 0.0;
        for (const auto& [id, weight] : s.textures) {
            auto it = _walls->textures.find(id);
            if (weight <= 0.0 || it == _walls->textures.end()) continue;
            wall = std::max(wall, walls::maxAngularError(result.eyeWorld, it->second->samplingPoint, planned.quad,
                                                         planned.depthBehind));
        }
        s.errorDeg = glm::degrees(wall);
        worst = std::max(worst, wall);
    }
    result.maxErrorDeg = glm::degrees(worst);
    for (int screen : _screens)
        result.maxErrorPixels =
            std::max(result.maxErrorPixels,
                     worst * display::maxPixelsPerRadian(display::viewScreen(
                                 _display.quad(screen), eyeCave, _display.screens()[screen].resolution)));
}

// The views of the screens this instance renders.
std::vector<display::ScreenView> Walkthrough::renderedViews(const display::HeadPose& head) const {
    std::vector<display::ScreenView> views = _display.views(head);
    std::erase_if(views, [&](const display::ScreenView& v) {
        return std::find(_screens.begin(), _screens.end(), v.screen) == _screens.end();
    });
    return views;
}

void Walkthrough::drawViews(const FrameInput& input, const render::DrawFilter& filter,
                            const std::vector<WallDraw>& walls, FrameResult& result) {
    const glm::dmat4 caveFromWorld = glm::inverse(input.worldFromCave);
    _renderer.beginFrame(_targets, _screens);
    const std::vector<display::ScreenView> views = renderedViews(input.head);
    result.stats = forEachView(views, _targets, [&](const display::ScreenView& view) {
        ViewStats stats = _renderer.renderView(view, input.worldFromCave, filter);
        result.geometryTriangles += stats.triangles;
        // The warp, wall and cursor passes count into the view's triangles and draw calls.
        FrameStats passes;
        if (_warp) _warp->draw(_warpWalls, view, caveFromWorld, passes);
        // renderView leaves viewport, scissor and colour mask set for this view.
        if (_walls) _walls->pass.draw(walls, view.frustum, caveFromWorld, _walls->store.sampler(), passes);
        if (input.hand) {
            if (!_cursor) _cursor = std::make_unique<HandCursorPass>();
            _cursor->draw(*input.hand, view.frustum, passes);
        }
        stats.triangles += passes.triangles;
        stats.drawCalls += passes.drawCalls;
        return stats;
    });
    result.perScreen = statsPerScreen(views, result.stats, _display.screens().size());
}

// Steps 1-3 and 5 of the header: selection, paging, what each wall draws, the error.
// Conservative: false only when all four corners of the wall lie outside one clip plane of
// every view in `views` (x, y within ±w, in front of the eye).
bool Walkthrough::wallInView(const std::vector<display::ScreenView>& views, const glm::dmat4& worldFromCave,
                             int wall) const {
    const display::ScreenQuad& q = _walls->setup.plan.walls[wall].quad;
    const glm::dvec3 corners[4] = {q.lowerLeft, q.lowerRight, q.upperLeft, q.lowerRight + q.upperLeft - q.lowerLeft};
    const glm::dmat4 caveFromWorld = glm::inverse(worldFromCave);
    for (const display::ScreenView& view : views) {
        const glm::dmat4 clipFromWorld = view.frustum.clipFromFrame() * caveFromWorld;
        int outside[5] = {0, 0, 0, 0, 0};
        for (const glm::dvec3& c : corners) {
            const glm::dvec4 p = clipFromWorld * glm::dvec4(c, 1.0);
            outside[0] += p.x < -p.w, outside[1] += p.x > p.w, outside[2] += p.y < -p.w, outside[3] += p.y > p.w;
            outside[4] += p.w <= 0.0;
        }
        if (std::none_of(std::begin(outside), std::end(outside), [](int n) { return n == 4; })) return true;
    }
    return false;
}

std::vector<WallDraw> Walkthrough::selectWalls(const FrameInput& input, FrameResult& result, std::vector<bool>& cells) {
    const walls::FrameSelection selection = _walls->selector.select(result.eyeWorld);
    result.cell = selection.cell;
    for (const walls::WallBlend& b : selection.walls)
        if (b.zone >= 0) {
            result.zone = b.zone;
            break;
        }
    cells = geometryMask(selection);
    // Walls outside every view this instance renders are neither paged nor drawn (a cluster
    // rank pages only what its own screens show); they keep a row in walls.csv.
    walls::FrameSelection seen = selection;
    const std::vector<display::ScreenView> views = renderedViews(input.head);
    auto outOfView = [&](const walls::WallBlend& b, bool beyond) {
        if (wallInView(views, input.worldFromCave, b.wall)) return false;
        result.walls.push_back(WallState{b.wall, {}, b.geometryWeight, false, beyond});
        return true;
    };
    std::erase_if(seen.walls, [&](const walls::WallBlend& b) { return outOfView(b, false); });
    std::erase_if(seen.beyond, [&](const walls::WallBlend& b) { return outOfView(b, true); });
    requestTextures(seen, result.eyeWorld);
    std::vector<WallDraw> draws;
    std::vector<int> morphCells;
    _warpWalls.clear();
    for (const walls::WallBlend& selected : seen.walls) {
        const walls::WallBlend b = _warp ? binaryBlend(selected) : selected;
        WallState state;
        auto draw = chooseWall(b, result.eyeWorld, state, cells);
        if (_warp) draw = warpWall(input, b, state, draw, cells, morphCells, result);
        if (draw) draws.push_back(*draw);
        result.walls.push_back(std::move(state));
    }
    // Beyond a neighbour drawn as geometry: its far walls, faded like any other (no warp).
    for (const walls::WallBlend& selected : seen.beyond) {
        WallState state;
        if (auto draw = chooseWall(_warp ? binaryBlend(selected) : selected, result.eyeWorld, state, cells))
            draws.push_back(*draw);
        state.beyond = true;
        result.walls.push_back(std::move(state));
    }
    // A morphing wall's cell behind is drawn by the warp pass only.
    for (int c : morphCells)
        if (c >= 0 && c < static_cast<int>(cells.size())) cells[c] = false;
    measureError(input.head.position, result);
    result.pager = _walls->pager.stats();
    return draws;
}

FrameResult Walkthrough::renderFrame(const FrameInput& input) {
    const auto start = Clock::now();
    _context.makeCurrent();  // callers may have used another context (a bake) in between
    FrameResult result;
    result.eyeWorld = glm::dvec3(input.worldFromCave * glm::dvec4(input.head.position, 1.0));
    std::vector<bool> cells(_description.cells.size(), true);
    std::vector<WallDraw> walls;
    if (_walls)
        walls = selectWalls(input, result, cells);
    else
        result.cell = scenes::findCell(_description.cells, result.eyeWorld);  // reported only
    const std::vector<int> objects = visibleObjects(cells);
    render::DrawFilter filter;
    filter.objects = &objects;
    render::FrameLod lod;
    if (_renderer.hasLods()) {
        // Over every screen, also those of other cluster ranks: each rank then picks the same
        // levels for what several draw, and the budget is the whole display's.
        lod = render::chooseLods(_renderer.renderScene(), _display.views(input.head), input.worldFromCave, filter,
                                 _options.render.lodPixels,
                                 input.triangleBudget > 0 ? input.triangleBudget : _options.triangleBudget,
                                 _options.lodMaxPixels);
        filter.lodLevels = &lod.levels;
        result.lodTolerancePx = lod.tolerancePx;
        result.lodErrorPx = lod.maxErrorPx;
        result.lodOverBudget = lod.overBudget;
    }
    _timer.begin();
    drawViews(input, filter, walls, result);
    _timer.end();
    result.cpuMs = msSince(start);
    glFinish();
    result.gpuMs = _timer.waitMs();  // the GPU has finished: no stall
    result.frameMs = msSince(start);
    if (_context.windowCount() > 0) present();
    if (input.readImages) result.images = readFrame(_display, _targets);
    return result;
}

void Walkthrough::present() {
    const int windows = std::min(_context.windowCount(), _targets.screenCount());
    for (int s = 0; s < windows; ++s) {
        PresentImage image{_targets.colorTexture(s, 0), 0, _targets.size(s)};
        if (_targets.imageCount(s) > 1 && _context.info().stereoWindows) image.right = _targets.colorTexture(s, 1);
        _context.present(s, image);
    }
}

}  // namespace cavewall::gl
