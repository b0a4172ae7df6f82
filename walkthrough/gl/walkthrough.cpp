#include "walkthrough/gl/walkthrough.h"

#include "config/error.h"
#include "display/eye_distance.h"
#include "display/timing.h"
#include "scenes/image_io.h"
#include "render/gl/view_loop.h"
#include "hierarchy/cluster_fades.h"
#include "render/lod_choice.h"
#include "walls/gl/background_baker.h"
#include "hierarchy/gl/cluster_costs.h"
#include "walls/gl/texture_store.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <mutex>

namespace cavewall::walkthrough::gl {

namespace {

using Clock = std::chrono::steady_clock;

using display::msSince;

// Makes `context` current before any member touches GL: a bake that made (and dropped) its own
// context, for one, leaves no context current on this thread.
display::gl::Context& madeCurrent(display::gl::Context& context) {
    context.makeCurrent();
    return context;
}

// Geometry paging by cell is on when walls are drawn and a budget is given; the renderer then
// keeps only always-resident meshes in its shared buffers.
WalkthroughOptions withPaging(WalkthroughOptions options, const scenes::SceneDescription& description,
                              const std::optional<walls::WallSetup>& walls) {
    const bool paging = options.geometryBudgetMB > 0.0 && walls && !walls->plan.walls.empty();
    if (paging && options.transition == walkthrough::Transition::Warp)
        throw Error("walkthrough: geometry paging (geometry budget " + std::to_string(options.geometryBudgetMB) +
                    " MB) does not support the warp transition yet (expected transition blend, got warp)");
    if (!options.wallTextures && options.transition == walkthrough::Transition::Warp)
        throw Error(
            "walkthrough: the control without wall textures draws no warp (expected transition blend, "
            "got warp)");
    if (!options.wallTextures && options.baker)
        throw Error(
            "walkthrough: the control without wall textures bakes nothing (expected no background "
            "baker, got one)");
    options.render.pagedCells = paging ? static_cast<int>(description.cells.size()) : 0;
    return options;
}

}  // namespace

// Geometry paging by cell: the pager (GL-free policy) decides which mesh groups
// (scenes/paged_meshes.h, the renderer's GpuScene::meshGroups) are resident; its loader packs a
// group's meshes on the pager's thread into `staged`; planFrame uploads them into the
// renderer's GpuScene and frees the evicted groups' buffers.
struct Walkthrough::CellPaging {
    CellPaging(const scenes::Scene& scene, const scenes::PagedMeshGroups& groups,
               const std::vector<scenes::MeshLod>* lods, double budgetMB)
        : scene(scene), lods(lods), groups(groups),
          pager(walls::groupGeometryBytes(scene, groups, lods), groups.cellGroups, budgetMB,
                [this](int group) { stage(group); }) {}

    void stage(int group) {
        render::gl::PackedGeometry packed = render::gl::packMeshes(scene, lods, groups.groupMeshes[group]);
        std::lock_guard lock(mutex);
        staged[group] = std::move(packed);
    }
    // The staged pack of `group`, or one packed now (a group drawn before its loader ran).
    render::gl::PackedGeometry take(int group) {
        {
            std::lock_guard lock(mutex);
            if (auto found = staged.find(group); found != staged.end()) {
                render::gl::PackedGeometry packed = std::move(found->second);
                staged.erase(found);
                return packed;
            }
        }
        return render::gl::packMeshes(scene, lods, groups.groupMeshes[group]);
    }

    const scenes::Scene& scene;
    const std::vector<scenes::MeshLod>* lods;
    const scenes::PagedMeshGroups& groups;  // the renderer's GpuScene's
    std::mutex mutex;
    std::map<int, render::gl::PackedGeometry> staged;
    walls::GeometryPager pager;  // last: its thread stops before the staging goes
};

struct Walkthrough::WallRuntime {
    // The textures' side: their paging, GPU residency and the passes that draw them.
    struct Textures {
        Textures(const walls::WallSetup& setup, const WalkthroughOptions& options)
            : pager(setup.folder, setup.manifest, options.textureBudgetMB, options.decoder),
              store(pager, static_cast<std::size_t>(options.uploadMBPerFrame * 1024 * 1024)) {
            if (options.wallKind == walls::WallKind::Depth)
                depthPass = std::make_unique<walls::gl::DepthWallPass>(options.depthMarch);
        }
        walls::TexturePager pager;
        walls::gl::TextureStore store;
        walls::gl::WallPass pass;
        std::unique_ptr<walls::gl::DepthWallPass> depthPass;
    };

    WallRuntime(walls::WallSetup s, const WalkthroughOptions& options) : setup(std::move(s)) {
        if (options.wallTextures) textures = std::make_unique<Textures>(setup, options);
    }

    walls::WallSetup setup;
    std::unique_ptr<CellPaging> geometry;  // geometry paging by cell (options.geometryBudgetMB > 0)
    // None in the control (WalkthroughSettings::wallTextures off), which pages, uploads and draws
    // no texture: no pager thread, no wall shaders.
    std::unique_ptr<Textures> textures;
};

struct Walkthrough::ClusterRuntime {
    hierarchy::ClusterModel model;
    std::vector<int> structure;  // always drawn
    std::unique_ptr<hierarchy::gl::ClusterImpostors> impostors;
    hierarchy::ClusterCoherence coherence;
    hierarchy::ClusterFades fades;
    hierarchy::ClusterFramePlan last;
    std::vector<int> drawn;  // the last frame's objects and structure
    int costResolution = 0;  // the cost view's side, pixels
};

namespace {

// The hierarchy over the content objects (structure gets empty bounds: never clustered), its
// impostors and measured costs.
std::unique_ptr<Walkthrough::ClusterRuntime> makeClusters(const scenes::Scene& scene, const ClusterOptions& o,
                                                          render::gl::SceneRenderer& renderer,
                                                          const std::string& rendererName, int costResolution);

// The display's largest screen side in pixels: what the cluster costs are measured at.
int largestScreenSide(const display::Display& display) {
    int side = 1;
    for (const config::Screen& s : display.config().screens) side = std::max({side, s.resolution.x, s.resolution.y});
    return side;
}

}  // namespace

Walkthrough::Walkthrough(const scenes::Scene& scene, const scenes::SceneDescription& description,
                         const display::Display& display, display::gl::Context& context,
                         std::optional<walls::WallSetup> walls, WalkthroughOptions options, std::vector<int> screens)
    : _scene(scene), _description(description), _display(display), _context(madeCurrent(context)),
      _options(withPaging(std::move(options), description, walls)), _screens(std::move(screens)),
      _targets(display, context), _renderer(scene, _options.render),
      _projectors(std::make_unique<display::gl::ProjectorPasses>(display, _targets)) {
    if (_screens.empty())
        for (int s = 0; s < static_cast<int>(display.screens().size()); ++s) _screens.push_back(s);
    if (walls && !walls->plan.walls.empty()) _walls = std::make_unique<WallRuntime>(std::move(*walls), _options);
    if (_walls && _options.render.pagedCells > 0)
        _walls->geometry = std::make_unique<CellPaging>(scene, _renderer.gpu().meshGroups(),
                                                        _renderer.hasLods() ? &_renderer.renderScene().lods() : nullptr,
                                                        _options.geometryBudgetMB);
    _planner =
        std::make_unique<walkthrough::FramePlanner>(scene, description, display, _walls ? &_walls->setup : nullptr,
                                                    _options.transition, _options.morphSeconds, _screens);
    _planner->requestCells(_walls && _walls->geometry);
    _planner->drawTextures(_options.wallTextures);
    _planner->portalCulling(_options.portalCulling);
    if (_options.clusters.enabled)
        _clusters = makeClusters(
            scene, _options.clusters, _renderer, context.info().renderer,
            _options.clusters.costResolution > 0 ? _options.clusters.costResolution : largestScreenSide(display));
    if (_walls && _options.transition == walkthrough::Transition::Warp)
        _warp =
            std::make_unique<walls::gl::WarpPass>(scene, _renderer.gpu(), _options.render, display.depthRange().near);
}

namespace {

std::unique_ptr<Walkthrough::ClusterRuntime> makeClusters(const scenes::Scene& scene, const ClusterOptions& o,
                                                          render::gl::SceneRenderer& renderer,
                                                          const std::string& rendererName, int costResolution) {
    auto c = std::make_unique<Walkthrough::ClusterRuntime>();
    c->coherence = hierarchy::ClusterCoherence(o.coherenceFrames);
    c->fades = hierarchy::ClusterFades(o.fadeFrames);
    std::vector<scenes::Bounds> bounds;
    for (std::size_t i = 0; i < scene.objects.size(); ++i) {
        const scenes::Object& object = scene.objects[i];
        const bool structure = object.role == scenes::Role::Structure;
        bounds.push_back(structure ? scenes::Bounds{} : object.worldBounds);
        if (structure) c->structure.push_back(static_cast<int>(i));
        c->model.objectTriangles.push_back(scene.meshes[object.mesh].triangleCount());
    }
    c->model.tree = hierarchy::buildClusterTree(bounds, o.divisions);
    c->impostors = std::make_unique<hierarchy::gl::ClusterImpostors>(scene, c->model, o.bake, o.cache);
    c->model.costs = hierarchy::gl::measureClusterCosts(renderer, *c->impostors, c->model, scene, rendererName, o.cache,
                                                        costResolution)
                         .costs;
    c->costResolution = costResolution;
    return c;
}

}  // namespace

Walkthrough::~Walkthrough() = default;

const hierarchy::ClusterModel* Walkthrough::clusterModel() const { return _clusters ? &_clusters->model : nullptr; }
const hierarchy::gl::ClusterBakeStats* Walkthrough::clusterBakeStats() const {
    return _clusters ? &_clusters->impostors->stats() : nullptr;
}
const hierarchy::ClusterFramePlan* Walkthrough::lastClusterPlan() const {
    return _clusters ? &_clusters->last : nullptr;
}
int Walkthrough::clusterCostResolution() const { return _clusters ? _clusters->costResolution : 0; }

void Walkthrough::planClusters(const walkthrough::FrameInput& input, glm::dvec3 eyeWorld, std::vector<int>& objects,
                               walkthrough::FrameResult& result) {
    ClusterRuntime& c = *_clusters;
    const double budget = input.clusterBudgetMs > 0.0 ? input.clusterBudgetMs : _options.clusters.budgetMs;
    // Over every screen, also those of other cluster ranks (as the levels of detail).
    c.last = hierarchy::planClusterFrame(c.model, _display.views(input.head), input.worldFromCave, eyeWorld, budget,
                                         &c.coherence);
    c.fades.apply(c.model, eyeWorld, c.last);
    objects = c.last.objects;
    objects.insert(objects.end(), c.structure.begin(), c.structure.end());
    result.clusterObjects = static_cast<int>(c.last.objects.size());
    result.clusterTextured = c.last.textured;
    result.clusterAverage = c.last.average;
    result.clusterFades = c.last.fades;
    result.clusterPredictedMs = c.last.predictedMs;
    result.clusterSelectedMs = c.last.selectedMs;
    result.clusterCheapestMs = c.last.cheapestMs;
    result.clusterBudgetMs = budget;
}

void Walkthrough::waitForTextures() {
    if (!_walls || !_walls->textures) return;
    _walls->textures->pager.waitIdle();
    _walls->textures->store.updateAll();
}

GeometryYardsticks Walkthrough::geometryYardsticks() const {
    constexpr double kMB = 1024.0 * 1024.0;
    const std::vector<scenes::MeshLod>* lods = _renderer.hasLods() ? &_renderer.renderScene().lods() : nullptr;
    const int cells = static_cast<int>(_description.cells.size());
    GeometryYardsticks y;
    y.wholeModelMB = static_cast<double>(walls::modelGeometryBytes(_scene, lods)) / kMB;
    y.largestThreeCellsMB =
        static_cast<double>(walls::largestBytes(walls::cellGeometryBytes(_scene, cells, lods), 3)) / kMB;
    y.sharedMB = static_cast<double>(_renderer.gpu().vertexBytes() + _renderer.gpu().indexBytes()) / kMB;
    return y;
}

// The views of the screens this instance renders.
std::vector<display::ScreenView> Walkthrough::renderedViews(const display::HeadPose& head) const {
    std::vector<display::ScreenView> views = _display.views(head);
    std::erase_if(views, [&](const display::ScreenView& v) {
        return std::find(_screens.begin(), _screens.end(), v.screen) == _screens.end();
    });
    return views;
}

// Pages what the planner asks for, uploads what is ready, then lets it decide against what is
// resident (header, steps 1-2).
walkthrough::FramePlan Walkthrough::planFrame(const walkthrough::FrameInput& input,
                                              const std::vector<display::ScreenView>& views) {
    const walkthrough::TextureRequests wanted = _planner->requests(input, views);
    if (!_walls) return _planner->plan([](int) { return false; });
    WallRuntime& w = *_walls;
    if (w.textures) {
        WallRuntime::Textures& t = *w.textures;
        if (_options.baker) {  // baking on demand: this frame's wishes out, finished bakes in
            _options.baker->rebake(t.pager.takeRefused());  // files that failed their content check
            _options.baker->want(wanted.now, wanted.soon,
                                 glm::dvec3(input.worldFromCave * glm::dvec4(input.head.position, 1.0)));
            _bakedNow = 0;
            for (walls::gl::BakeEvent& e : _options.baker->take()) {
                if (e.evicted) {
                    t.pager.removeTexture(e.texture.id);
                    continue;
                }
                t.pager.addTexture(std::move(e.texture)), ++_bakedNow;
            }
            _bakedTotal += _bakedNow;
        }
        t.pager.request(wanted.now, wanted.soon);
        if (_options.synchronousPaging) t.pager.waitIdle();
        // One paced upload round per frame; synchronous paging uploads everything.
        _uploadedBytes = _options.synchronousPaging ? t.store.updateAll() : t.store.update();
    }
    const auto resident = [&w](int id) { return w.textures && w.textures->store.resident(id); };
    if (!w.geometry) return _planner->plan(resident);
    walls::GeometryPager& pager = w.geometry->pager;
    pager.request(wanted.cellsNow, wanted.cellsSoon);
    if (_options.synchronousPaging) pager.waitIdle();
    for (int group : pager.takeReady()) makeResident(group);
    walkthrough::FramePlan plan = _planner->plan(resident, [&pager](int cell) { return pager.isResident(cell); });
    // Drawn now: the missing groups are loaded at once (a stall).
    for (int cell : plan.geometryForced)
        for (int group : pager.groupsOf(cell)) makeResident(group);
    return plan;
}

// Uploads mesh group `group`, tells the pager, and frees what the pager evicts to make room.
void Walkthrough::makeResident(int group) {
    CellPaging& g = *_walls->geometry;
    if (!g.pager.groupResident(group)) _renderer.gpu().uploadGroup(group, g.take(group));
    g.pager.markResident(group);
    for (int evicted : g.pager.takeEvictions()) _renderer.gpu().freeGroup(evicted);
}

std::vector<walls::gl::WallDraw> Walkthrough::wallDraws(const walkthrough::FramePlan& plan) const {
    std::vector<walls::gl::WallDraw> draws;
    for (const walkthrough::WallDrawPlan& p : plan.wallDraws) {
        walls::gl::WallDraw d{p.quad, {}, {}, 0, {}};
        for (const auto& [id, weight] : p.textures) {
            d.textures[d.count] = _walls->textures->store.texture(id);
            d.contents[d.count] = _walls->textures->store.content(id);
            d.weights[d.count++] = static_cast<float>(weight);
        }
        draws.push_back(d);
    }
    return draws;
}

std::vector<walls::gl::DepthWallDraw> Walkthrough::depthWallDraws(const walkthrough::FramePlan& plan,
                                                                  std::vector<walls::gl::WallDraw>& flat) {
    std::vector<walls::gl::DepthWallDraw> draws;
    if (!_walls || !_walls->textures || !_walls->textures->depthPass) return draws;
    const walls::gl::TextureStore& store = _walls->textures->store;
    std::vector<walls::gl::WallDraw> left;
    for (std::size_t i = 0; i < plan.wallDraws.size() && i < flat.size(); ++i) {
        walls::gl::DepthWallDraw d{flat[i].quad, {}, 0};
        bool all = true;
        // A resident texture without depths (a flat one) draws the whole wall flat; textures
        // not resident are left out, as the flat pass leaves them.
        for (const auto& [id, weight] : plan.wallDraws[i].textures) {
            std::optional<walls::gl::DepthWallLayer> layer = store.depthLayer(id);
            if (!layer) {
                all = all && !store.resident(id);
                continue;
            }
            layer->weight = static_cast<float>(weight);
            d.layers[d.count++] = *layer;
        }
        if (all)
            draws.push_back(d);
        else
            left.push_back(flat[i]);
    }
    flat = std::move(left);
    return draws;
}

Walkthrough::WallDraws Walkthrough::allWallDraws(const walkthrough::FramePlan& plan) {
    WallDraws draws;
    if (_walls && _walls->textures) draws.flat = wallDraws(plan);
    draws.depth = depthWallDraws(plan, draws.flat);
    return draws;
}

std::vector<walkthrough::ViewDepth> Walkthrough::readDepths(const walkthrough::FrameInput& input,
                                                            const std::vector<display::ScreenView>& views,
                                                            const WallDraws& walls) const {
    const glm::dmat4 caveFromWorld = glm::inverse(input.worldFromCave);
    const WallRuntime::Textures* textures = _walls ? _walls->textures.get() : nullptr;
    std::vector<walkthrough::ViewDepth> depths;
    for (const display::ScreenView& view : views) {
        const int image = display::gl::RenderTargets::imageOf(view.pass);
        const display::Viewport& v = view.pass.viewport;
        _targets.bind(view.screen, image);
        glViewport(v.x, v.y, v.width, v.height);
        glEnable(GL_SCISSOR_TEST);
        glScissor(v.x, v.y, v.width, v.height);
        display::FrameStats ignored;
        if (textures)
            textures->pass.drawDepth(walls.flat, view.frustum, caveFromWorld, textures->store.sampler(), ignored);
        if (textures && textures->depthPass)
            textures->depthPass->drawDepth(walls.depth, view.frustum, caveFromWorld, textures->store.sampler(),
                                           ignored);
        glDisable(GL_SCISSOR_TEST);
        const std::vector<float> depth = _targets.readDepth(view.screen, image, v);
        depths.push_back({view.screen, image, view.pass.eye, v.width, v.height,
                          display::eyeDistances(view.frustum, {v.width, v.height}, depth)});
    }
    return depths;
}

void Walkthrough::drawViews(const walkthrough::FrameInput& input, const std::vector<display::ScreenView>& views,
                            const render::DrawFilter& filter, const walkthrough::FramePlan& plan,
                            const WallDraws& draws, walkthrough::FrameResult& result) {
    const glm::dmat4 caveFromWorld = glm::inverse(input.worldFromCave);
    const WallRuntime::Textures* textures = _walls ? _walls->textures.get() : nullptr;
    const std::vector<walls::gl::WallDraw>& walls = draws.flat;
    const std::vector<walls::gl::DepthWallDraw>& depthWalls = draws.depth;
    _renderer.beginFrame(_targets, _screens);
    result.stats = render::gl::forEachView(views, _targets, [&](const display::ScreenView& view) {
        display::ViewStats stats = _renderer.renderView(view, input.worldFromCave, filter);
        result.geometryTriangles += stats.triangles;
        // The warp, wall and cursor passes count into the view's triangles and draw calls.
        display::FrameStats passes;
        if (_warp) _warp->draw(plan.warpWalls, view, caveFromWorld, passes);
        // renderView leaves viewport, scissor and colour mask set for this view.
        if (_clusters) {
            const glm::dvec3 eye = glm::dvec3(input.worldFromCave * glm::dvec4(view.frustum.eye, 1.0));
            _clusters->impostors->draw(_clusters->last.boxes, eye, view.frustum, caveFromWorld, passes);
        }
        if (textures) textures->pass.draw(walls, view.frustum, caveFromWorld, textures->store.sampler(), passes);
        if (textures && textures->depthPass)
            textures->depthPass->draw(depthWalls, view.frustum, caveFromWorld, textures->store.sampler(), passes);
        if (input.hand) {
            if (!_cursor) _cursor = std::make_unique<HandCursorPass>();
            _cursor->draw(*input.hand, view.frustum, passes);
        }
        stats.triangles += passes.triangles;
        stats.drawCalls += passes.drawCalls;
        return stats;
    });
    _renderer.endFrame(_targets);
    result.perScreen = render::gl::statsPerScreen(views, result.stats, _display.screens().size());
}

walkthrough::FrameResult Walkthrough::renderFrame(const walkthrough::FrameInput& input) {
    const auto start = Clock::now();
    const std::optional<walls::gl::BackgroundBakeStats> bakeAtStart =
        _options.baker ? std::optional(_options.baker->stats()) : std::nullopt;
    _context.makeCurrent();  // callers may have used another context (a bake) in between
    reframeWindows();
    const std::vector<display::ScreenView> views = renderedViews(input.head);
    walkthrough::FramePlan plan = planFrame(input, views);
    walkthrough::FrameResult result;
    result.uploadedBytes = _uploadedBytes;
    result.eyeWorld = plan.eyeWorld;
    result.cell = plan.cell;
    result.zone = plan.zone;
    result.maxErrorDeg = plan.maxErrorDeg;
    result.maxErrorPixels = plan.maxErrorPixels;
    result.texturesOverAlpha = plan.texturesOverAlpha;
    result.warpFallbacks = plan.warpFallbacks;
    result.walls = std::move(plan.walls);
    if (_walls && _walls->textures) {
        result.pager = _walls->textures->pager.stats();
        result.warnings = _walls->textures->pager.takeWarnings();
    }
    if (_walls && _walls->geometry) {
        result.geometry = _walls->geometry->pager.stats();
        result.geometry.residentMB = static_cast<double>(_renderer.gpu().residentPagedBytes()) / (1024.0 * 1024.0);
    }
    result.geometryMisses = plan.geometryMisses;
    result.geometryForced = static_cast<int>(plan.geometryForced.size());
    result.geometryFallbacks = plan.geometryFallbacks;
    result.texturesBaked = _bakedTotal;
    result.texturesBakedNow = _bakedNow;
    if (_options.baker) result.texturesToBake = _options.baker->stats().missing;
    render::DrawFilter filter;
    filter.objects = &plan.objects;
    if (!plan.portals.objectSet.empty()) filter.portals = &plan.portals;
    if (_clusters) {
        planClusters(input, plan.eyeWorld, _clusters->drawn, result);
        filter.objects = &_clusters->drawn;
    }
    render::FrameLod lod;
    if (_renderer.hasLods()) {
        // Over every screen, also those of other cluster ranks: each rank then picks the same
        // levels for what several draw, and the budget is the whole display's.
        lod = render::chooseLods(
            _renderer.renderScene(), _display.views(input.head), input.worldFromCave, filter, _options.render.lodPixels,
            input.triangleBudget > 0 ? input.triangleBudget : _options.triangleBudget, _options.lodMaxPixels);
        filter.lodLevels = &lod.levels;
        result.lodTolerancePx = lod.tolerancePx;
        result.lodErrorPx = lod.maxErrorPx;
        result.lodOverBudget = lod.overBudget;
    }
    _timer.begin();
    const WallDraws walls = allWallDraws(plan);
    drawViews(input, views, filter, plan, walls, result);
    _timer.end();
    if (_projectors->any()) _projectors->apply(_targets);  // after the timer: GPU ms is the scene's
    result.cpuMs = msSince(start);
    glFinish();
    result.gpuMs = _timer.waitMs();  // the GPU has finished: no stall
    result.frameMs = msSince(start);
    if (_context.windowCount() > 0) present();
    if (bakeAtStart) {  // the frame overlapped a bake: one ran at its start or end, or one began
        const walls::gl::BackgroundBakeStats end = _options.baker->stats();
        result.bakerBusy = bakeAtStart->busy || end.busy || end.started != bakeAtStart->started;
    }
    if (input.readImages) result.images = display::gl::readFrame(_display, _targets);
    if (input.readImages) result.warpedImages = _projectors->read(result.images);
    if (input.readDepth) result.depths = readDepths(input, views, walls);
    return result;
}

// Whether `screen` takes its window's shape: a screen whose window reframes, unless this is a
// cluster rank (it renders some screens but chooses levels of detail over all of them, as the
// other ranks do, so it keeps the configured quads and its windows letterbox).
bool Walkthrough::reframing(int screen) const {
    return _display.reframes(screen) && _screens.size() == _display.screens().size();
}

// Screens of windows that reframe take their windows' shapes before the frame's views.
void Walkthrough::reframeWindows() {
    const int windows = std::min(_context.windowCount(), _targets.screenCount());
    for (int s = 0; s < windows; ++s)
        if (reframing(s)) _display.reframe(s, _context.windowPixels(s));
}

void Walkthrough::present() {
    const int windows = std::min(_context.windowCount(), _targets.screenCount());
    for (int s = 0; s < windows; ++s) {
        const display::gl::ProjectorPass* pass = _projectors->pass(s);  // a projector shows the corrected image
        display::gl::PresentImage image{pass ? pass->colorTexture(0) : _targets.colorTexture(s, 0), 0, _targets.size(s),
                                        reframing(s)};
        if (_targets.imageCount(s) > 1 && _context.info().stereoWindows)
            image.right = pass ? pass->colorTexture(1) : _targets.colorTexture(s, 1);
        _context.present(s, image);
    }
}

}  // namespace cavewall::walkthrough::gl
