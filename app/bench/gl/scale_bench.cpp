#include "app/bench/gl/scale_bench.h"

#include "config/error.h"
#include "config/json_reader.h"
#include "display/display.h"
#include "display/eye_distance.h"
#include "display/timing.h"
#include "display/gl/context.h"
#include "display/gl/frame_images.h"
#include "display/gl/render_targets.h"
#include "render/gl/scene_renderer.h"
#include "app/bench/gl/modes.h"
#include "app/bench/metrics.h"
#include "app/bench/path.h"
#include "app/bench/report.h"
#include "app/bench/scale_plant.h"
#include "render/lod_choice.h"
#include "scenes/generate.h"
#include "scenes/loader.h"
#include "walkthrough/frame_planner.h"
#include "walls/frame_select.h"
#include "walls/gl/baker.h"
#include "walkthrough/gl/walkthrough.h"
#include "walls/wall_setup.h"

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <thread>
#include <tuple>

namespace cavewall::bench::gl {

namespace {

using Clock = std::chrono::steady_clock;
constexpr double kMB = 1024.0 * 1024.0;
using bench::fixed;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    in >> one >> five >> fifteen;
    return in ? one + " " + five + " " + fifteen : std::string("unknown");
}

// Bakes the `ids` of `setup`'s plan only (a copy of the plan without the others, ids kept).
walls::gl::BakeResult bakeSubset(const scenes::Scene& scene, const scenes::SceneDescription& d,
                                 const walls::WallSetup& setup, const std::set<int>& ids,
                                 const std::filesystem::path& sceneFile, const ScaleOptions& o, walls::WallKind kind,
                                 display::gl::Context& context) {
    walls::WallSetup subset = setup;
    std::erase_if(subset.plan.textures, [&](const walls::Texture& t) { return !ids.count(t.id); });
    walls::gl::BakeRequest request;
    request.scene = sceneFile;
    request.settings.maxResolution = o.bakeResolution;
    request.settings.kind = kind;
    request.settings.jobs = 2;
    request.context = &context;
    request.cache = o.data / "bake-cache";
    return walls::gl::bakeWalls(scene, d, subset, request);
}

// The near limit's draw of one frame: the viewer's cell and the always-drawn objects.
struct NearMode {
    NearMode(const scenes::Scene& scene, const scenes::SceneDescription& d, const display::Display& display,
             display::gl::Context& context, const walls::WallSetup& setup, double lodPixels,
             const render::OcclusionSettings& occlusion)
        : scene(scene), display(display), selector(setup.plan, setup.table, d), targets(display, context),
          renderer(scene, settingsWith(lodPixels, occlusion)), cells(d.cells.size()), lodPixels(lodPixels) {}

    static render::gl::RenderSettings settingsWith(double lodPixels, const render::OcclusionSettings& occlusion) {
        render::gl::RenderSettings s;
        s.lodPixels = lodPixels;
        s.occlusion = occlusion;
        return s;
    }

    // One frame's ms (submission and GPU), triangles submitted and triangles drawn (fewer with
    // occlusion culling).
    struct Frame {
        double ms = 0.0, submitted = 0.0, drawn = 0.0;
    };
    Frame draw(const walkthrough::FrameInput& in) {
        const auto start = Clock::now();
        const glm::dvec3 eye(in.worldFromCave * glm::dvec4(in.head.position, 1.0));
        const walls::FrameSelection selection = selector.select(eye);
        std::vector<bool> mask(cells, false);
        if (selection.cell >= 0 && selection.cell < static_cast<int>(cells)) mask[selection.cell] = true;
        const std::vector<int> objects = walkthrough::objectsOfCells(scene, mask);
        render::DrawFilter filter;
        filter.objects = &objects;
        const std::vector<display::ScreenView> views = display.views(in.head);
        render::FrameLod lod;
        if (renderer.hasLods()) {
            lod = render::chooseLods(renderer.renderScene(), views, in.worldFromCave, filter, lodPixels);
            filter.lodLevels = &lod.levels;
        }
        const display::FrameStats stats = renderer.render(views, targets, in.worldFromCave, filter);
        renderer.waitGpuMs();
        const double ms = display::msSince(start);
        const auto submitted = static_cast<double>(stats.triangles);
        return {ms, submitted, submitted - trianglesCulled(renderer.readOcclusionCounts())};
    }

    // The last frame's depth per view as eye distances (after draw), in display.views' order, as
    // the walkthrough reads it (FrameInput::readDepth).
    std::vector<walkthrough::ViewDepth> readDepths(const display::HeadPose& head) const {
        std::vector<walkthrough::ViewDepth> depths;
        for (const display::ScreenView& view : display.views(head)) {
            const int image = display::gl::RenderTargets::imageOf(view.pass);
            const display::Viewport& v = view.pass.viewport;
            const std::vector<float> depth = targets.readDepth(view.screen, image, v);
            depths.push_back({view.screen, image, view.pass.eye, v.width, v.height,
                              display::eyeDistances(view.frustum, {v.width, v.height}, depth)});
        }
        return depths;
    }

    double residentMB() const {
        return static_cast<double>(renderer.gpu().vertexBytes() + renderer.gpu().indexBytes()) / kMB;
    }

    const scenes::Scene& scene;
    const display::Display& display;
    walls::FrameSelector selector;
    display::gl::RenderTargets targets;
    render::gl::SceneRenderer renderer;
    std::size_t cells;
    double lodPixels;
};

struct Accumulated {
    explicit Accumulated(std::size_t screens) : errors(screens), screenStereo(screens) {}
    std::vector<double> ms;
    double triangles = 0.0, residentMB = 0.0, pagedMB = 0.0;
    int overAlpha = 0;
    long misses = 0, pageIns = 0;
    bench::ErrorPool errors;      // against full geometry (near and walls)
    bool stereoMeasured = false;  // stereo displays: every compared eye's depth against full geometry's
    metrics::StereoError stereo;
    std::vector<metrics::StereoError> screenStereo;

    // Adds one compared frame's depths against full geometry's.
    void addDepths(const display::Display& display, bench::ScaleMode mode,
                   const std::vector<walkthrough::ViewDepth>& depths,
                   const std::vector<walkthrough::ViewDepth>& reference) {
        stereoMeasured = true;
        stereo += addStereoError(display, std::string(bench::toString(mode)), depths, reference, screenStereo);
    }
};

bench::ScaleRow rowOf(bench::ScaleMode mode, const Accumulated& a, const bench::ScaleRow& base) {
    bench::ScaleRow r = base;
    r.mode = mode;
    r.frameMs = bench::timeStats(a.ms);
    r.trianglesPerFrame = a.ms.empty() ? 0.0 : a.triangles / static_cast<double>(a.ms.size());
    r.residentMB = a.residentMB;
    r.pagedPeakMB = a.pagedMB;
    r.geometryMisses = a.misses;
    r.geometryPageIns = a.pageIns;
    r.texturesOverAlpha = a.overAlpha;
    const bench::ImageError e = a.errors.result();
    r.comparedFrames = e.frames;
    if (e.frames > 0) {
        r.psnrDb = e.psnrDb;
        r.worstFramePsnrDb = e.worstFramePsnrDb;
        r.flipMean = e.flipMean;
        r.worstImageFlip = a.errors.worstFlip().mean;
    }
    r.stereoMeasured = a.stereoMeasured;
    r.stereo = a.stereo;
    return r;
}

// One size made ready: the plant loaded, the stretch's eye path recorded, the walls planned and
// the stretch's textures baked.
struct PreparedSize {
    scenes::SceneDescription description;
    scenes::Scene scene;
    bench::EyePath path;
    walls::WallSetup setup;
    std::optional<walls::WallSetup> depthSetup;  // ScaleOptions::depthBeside
    double loadSeconds = 0.0, planSeconds = 0.0, depthPlanSeconds = 0.0;
    std::string size, line;  // "2.07 M triangles"; the report line of what was made
};

// The walls' plan options: checked before any plant is generated, used for every size.
walls::PlanOptions scalePlanOptions(const ScaleOptions& o, walls::WallKind kind) {
    walls::PlanOptions plan = walls::planOptionsFor(o.plan, kind, o.bakeResolution);
    plan.alphaDeg = o.alphaDeg;
    return plan;
}

std::unique_ptr<PreparedSize> prepareSize(const ScaleOptions& o, std::size_t target, const display::Display& display,
                                          display::gl::Context& context) {
    auto p = std::make_unique<PreparedSize>();
    double generateSeconds = 0.0;
    const std::filesystem::path folder = o.data / ("plant-" + std::to_string(target));
    const std::filesystem::path sceneFile = plantFor(target, folder, generateSeconds);
    auto start = Clock::now();
    scenes::SceneDescription& d = p->description;
    p->scene = scenes::loadSceneFile(sceneFile, &d);
    p->loadSeconds = secondsSince(start);
    bench::checkPlantFolder(folder, target, p->scene.triangleCount(), [&] { return plantTriangles(target); });
    if (d.walls.empty() || d.walkPath.size() < 2)
        throw Error(sceneFile.string() + ": expected a plant with virtual walls and a walk path");
    d.walkPath = bench::pathPrefix(d.walkPath, o.pathMetres);
    p->path = bench::recordEyePath(p->scene, d, o.display, o.tracker, o.frames);
    // Plans and bakes the stretch's textures of one kind of walls; the bake's report words.
    auto prepare = [&](walls::WallKind kind, walls::WallSetup& setup, double& planSeconds) {
        const auto planned = Clock::now();
        setup = walls::prepareWalls(p->scene, d, scalePlanOptions(o, kind));
        planSeconds = secondsSince(planned);
        const std::set<int> ids = requestedTextures(p->scene, d, display, setup, p->path);
        const walls::gl::BakeResult baked = bakeSubset(p->scene, d, setup, ids, sceneFile, o, kind, context);
        setup.folder = baked.folder;
        setup.manifest = baked.manifest;
        return "walls planned (zones of at least " + fixed(setup.plan.options.minZoneSize, 2) + " m) in " +
               fixed(planSeconds, 1) + " s; baked " + std::to_string(ids.size()) + " of the plan's " +
               std::to_string(setup.plan.textures.size()) + " textures (those the stretch requests) at most " +
               std::to_string(o.bakeResolution) + " texels: " + std::to_string(baked.baked) + " rendered in " +
               fixed(baked.seconds, 1) + " s, " + std::to_string(baked.reused) + " from the cache";
    };
    std::string made = prepare(o.wallKind, p->setup, p->planSeconds);
    if (o.depthBeside) {
        p->depthSetup.emplace();
        made += "; depth " + prepare(walls::WallKind::Depth, *p->depthSetup, p->depthPlanSeconds);
    }
    p->size = fixed(static_cast<double>(p->scene.triangleCount()) / 1e6, 2) + " M triangles";
    p->line = p->size + " (" + std::to_string(d.cells.size()) + " cells, " + std::to_string(p->scene.objects.size()) +
              " objects): generated in " + fixed(generateSeconds, 1) + " s (0: reused), loaded in " +
              fixed(p->loadSeconds, 2) + " s, " + made;
    return p;
}

using bench::ScaleMode;

// One mode of one size: what draws it and what it measured.
struct SizeMode {
    SizeMode(ScaleMode mode, std::size_t screens) : mode(mode), acc(screens) {}
    ScaleMode mode;
    std::unique_ptr<walkthrough::gl::Walkthrough>
        walk;                        // full's and the walls modes' (cells, walls, walls-budget, walls-depth)
    std::unique_ptr<NearMode> near;  // near's
    double firstFrameSeconds = 0.0;  // made and the stretch's first frame drawn (walls modes: planning too)
    Accumulated acc;
};

// The modes with walls (cells: their geometry cells without textures), which page geometry.
bool hasWalls(ScaleMode mode) {
    return mode != ScaleMode::Full && mode != ScaleMode::FullLod && mode != ScaleMode::Near;
}

// The walls modes' warm-up order over the stretch (each frame they are drawn in kScaleModes').
constexpr ScaleMode kWarmUpOrder[] = {ScaleMode::Walls, ScaleMode::WallsBudget, ScaleMode::DepthWalls,
                                      ScaleMode::Cells};

// One size's modes: kScaleModes' order, those run (full first, near second).
struct SizeModes {
    std::vector<SizeMode> modes;
    std::size_t budget = 0;  // walls-budget's triangles a frame (0: not run)

    SizeMode* find(ScaleMode mode) {
        for (SizeMode& m : modes)
            if (m.mode == mode) return &m;
        return nullptr;
    }
};

// Times make() and frame() on what it made: what was made and the seconds.
template <class Make, class Frame>
auto timeFirst(Make make, Frame frame) {
    const auto t = Clock::now();
    auto made = make();
    frame(*made);
    return std::pair{std::move(made), secondsSince(t)};
}

// The walls mode's walkthrough options; the other walls modes' start from them.
walkthrough::gl::WalkthroughOptions wallsOptionsFor(const ScaleOptions& o) {
    walkthrough::gl::WalkthroughOptions options;
    options.render.lodPixels = o.lodPixels;
    options.render.occlusion = o.occlusion;
    options.geometryBudgetMB = o.geometryBudgetMB;
    options.wallKind = o.wallKind;
    // Synchronous paging: the first frame is complete (its textures and cells loaded), and after
    // the warm-up pass every texture and mesh group of the stretch stays resident, so the timed
    // frames measure drawing (nothing is left to wait for).
    options.synchronousPaging = true;
    options.textureBudgetMB = 4096.0;
    options.uploadMBPerFrame = 4096.0;
    return options;
}

// What one size's modes are made with.
struct SizeSetting {
    const ScaleOptions& o;
    const PreparedSize& p;
    const display::Display& display;
    display::gl::Context& context;
};

// A walkthrough of `walls` and the seconds to make it and draw the stretch's first frame.
std::pair<std::unique_ptr<walkthrough::gl::Walkthrough>, double> firstWalk(
    const SizeSetting& s, const walls::WallSetup& walls, const walkthrough::gl::WalkthroughOptions& options) {
    return timeFirst(
        [&] {
            return std::make_unique<walkthrough::gl::Walkthrough>(s.p.scene, s.p.description, s.display, s.context,
                                                                  walls, options);
        },
        [&](walkthrough::gl::Walkthrough& w) { w.renderFrame(s.p.path.frames.front()); });
}

// The near limit over the whole stretch (its warm-up) and walls-budget's triangles a frame: the
// option's, or the near limit's median.
std::size_t nearBudget(const ScaleOptions& o, NearMode& nearMode, const bench::EyePath& path) {
    std::vector<double> nearTriangles;
    for (const walkthrough::FrameInput& in : path.frames) nearTriangles.push_back(nearMode.draw(in).submitted);
    std::sort(nearTriangles.begin(), nearTriangles.end());
    return o.triangleBudget >= 0 ? static_cast<std::size_t>(o.triangleBudget)
                                 : static_cast<std::size_t>(nearTriangles[nearTriangles.size() / 2]);
}

// Adds a walls mode made by firstWalk to `modes`; planning counts in its time to the first frame
// (the bake does not: it is cached).
void addWalk(std::vector<SizeMode>& modes, const SizeSetting& s, ScaleMode mode,
             std::pair<std::unique_ptr<walkthrough::gl::Walkthrough>, double> made, double planSeconds) {
    SizeMode& m = modes.emplace_back(mode, s.display.screens().size());
    m.walk = std::move(made.first);
    m.firstFrameSeconds = made.second + planSeconds;
}

// Makes one size's modes and times each to its first frame, in this order: full, near, walls,
// cells, walls-depth, then walls-budget (its budget the near limit's median, after its warm-up).
SizeModes makeModes(const SizeSetting& s) {
    const ScaleOptions& o = s.o;
    const PreparedSize& p = s.p;
    const std::size_t screens = s.display.screens().size();
    std::vector<SizeMode> made;
    made.reserve(std::size(bench::kScaleModes));  // no reallocation: `full` and `nearLimit` stay valid
    SizeMode& full = made.emplace_back(ScaleMode::Full, screens);
    walkthrough::gl::WalkthroughOptions fullOptions;
    fullOptions.render.occlusion = o.occlusion;
    std::tie(full.walk, full.firstFrameSeconds) = timeFirst(
        [&] {
            return std::make_unique<walkthrough::gl::Walkthrough>(p.scene, p.description, s.display, s.context,
                                                                  std::nullopt, fullOptions);
        },
        [&](walkthrough::gl::Walkthrough& w) { w.renderFrame(p.path.frames.front()); });
    if (o.lodPixels > 0.0) {  // full geometry with levels of detail at the walls' tolerance
        SizeMode& fullLod = made.emplace_back(ScaleMode::FullLod, screens);
        walkthrough::gl::WalkthroughOptions lodOptions;
        lodOptions.render.lodPixels = o.lodPixels;
        lodOptions.render.occlusion = o.occlusion;
        std::tie(fullLod.walk, fullLod.firstFrameSeconds) = timeFirst(
            [&] {
                return std::make_unique<walkthrough::gl::Walkthrough>(p.scene, p.description, s.display, s.context,
                                                                      std::nullopt, lodOptions);
            },
            [&](walkthrough::gl::Walkthrough& w) { w.renderFrame(p.path.frames.front()); });
    }
    SizeMode& nearLimit = made.emplace_back(ScaleMode::Near, screens);
    std::tie(nearLimit.near, nearLimit.firstFrameSeconds) = timeFirst(
        [&] {
            return std::make_unique<NearMode>(p.scene, p.description, s.display, s.context, p.setup, o.lodPixels,
                                              o.occlusion);
        },
        [&](NearMode& n) { n.draw(p.path.frames.front()); });
    const walkthrough::gl::WalkthroughOptions wallsOptions = wallsOptionsFor(o);
    addWalk(made, s, ScaleMode::Walls, firstWalk(s, p.setup, wallsOptions), p.planSeconds);
    walkthrough::gl::WalkthroughOptions cellsOptions =
        wallsOptions;  // the control: the flat walls' geometry cells, no texture
    cellsOptions.wallTextures = false;
    addWalk(made, s, ScaleMode::Cells, firstWalk(s, p.setup, cellsOptions), p.planSeconds);
    if (p.depthSetup) {  // depth walls beside the flat ones: the same options, their own plan and bake
        walkthrough::gl::WalkthroughOptions depthOptions = wallsOptions;
        depthOptions.wallKind = walls::WallKind::Depth;
        addWalk(made, s, ScaleMode::DepthWalls, firstWalk(s, *p.depthSetup, depthOptions), p.depthPlanSeconds);
    }
    SizeModes out;
    out.budget = nearBudget(o, *nearLimit.near, p.path);
    if (out.budget > 0) {
        walkthrough::gl::WalkthroughOptions budgetOptions = wallsOptions;
        budgetOptions.triangleBudget = out.budget;
        budgetOptions.lodMaxPixels = std::max(o.lodMaxPixels, o.lodPixels);
        addWalk(made, s, ScaleMode::WallsBudget, firstWalk(s, p.setup, budgetOptions), p.planSeconds);
    }
    for (ScaleMode mode : bench::kScaleModes)  // the table's order
        for (SizeMode& m : made)
            if (m.mode == mode) out.modes.push_back(std::move(m));
    return out;
}

// Every walls mode over the whole stretch (kWarmUpOrder), then full geometry's first frames (with
// and without levels of detail).
void warmUp(SizeModes& live, const bench::EyePath& path) {
    for (ScaleMode mode : kWarmUpOrder) {
        const SizeMode* m = live.find(mode);
        if (!m) continue;
        for (const walkthrough::FrameInput& in : path.frames) m->walk->renderFrame(in);
        m->walk->waitForTextures();
    }
    for (ScaleMode mode : {ScaleMode::Full, ScaleMode::FullLod})
        if (SizeMode* m = live.find(mode))
            for (std::size_t i = 0; i < std::min<std::size_t>(3, path.frames.size()); ++i)
                m->walk->renderFrame(path.frames[i]);
    for (SizeMode& m : live.modes)  // the timed frames count only their own culled triangles
        if (m.walk) m.walk->readOcclusionCounts();
}

// A walls mode's frame; its images (when `reference`) compared with full geometry's.
void drawWalk(SizeMode& m, const walkthrough::FrameInput& in, long frame, const walkthrough::FrameResult* reference,
              const display::Display& display) {
    const walkthrough::FrameResult w = m.walk->renderFrame(in);
    Accumulated& a = m.acc;
    a.ms.push_back(w.frameMs);
    a.triangles += static_cast<double>(w.stats.triangles) - trianglesCulled(m.walk->readOcclusionCounts());
    if (reference)
        a.errors.addFrame(
            frame, comparedImages(display, in.head, w.images, reference->images, std::string(bench::toString(m.mode))));
    if (reference && in.readDepth) a.addDepths(display, m.mode, w.depths, reference->depths);
    a.pagedMB = std::max(a.pagedMB, w.geometry.residentMB);
    a.overAlpha = std::max(a.overAlpha, w.texturesOverAlpha);
    a.misses = w.geometry.misses;
    a.pageIns = w.geometry.pageIns;
}

// One path frame drawn by every mode in kScaleModes' order, full geometry first: its images (and,
// on a stereo display, its depths) are the others' reference. Images and depths are read back
// after each mode's frame is timed (walkthrough.h; NearMode::draw).
void drawFrame(SizeModes& live, walkthrough::FrameInput in, long frame, bool compare, const display::Display& display) {
    in.readImages = compare;
    in.readDepth = compare && measuresStereo(display);
    SizeMode& full = live.modes.front();
    const walkthrough::FrameResult f = full.walk->renderFrame(in);
    full.acc.ms.push_back(f.frameMs);
    full.acc.triangles += static_cast<double>(f.stats.triangles) - trianglesCulled(full.walk->readOcclusionCounts());
    for (SizeMode& m : live.modes) {
        if (m.near) {
            const NearMode::Frame near = m.near->draw(in);
            m.acc.ms.push_back(near.ms);
            m.acc.triangles += near.drawn;
            if (compare)
                m.acc.errors.addFrame(
                    frame, comparedImages(display, in.head, display::gl::readFrame(display, m.near->targets), f.images,
                                          std::string(bench::toString(m.mode))));
            if (in.readDepth) m.acc.addDepths(display, m.mode, m.near->readDepths(in.head), f.depths);
        } else if (hasWalls(m.mode) || m.mode == ScaleMode::FullLod) {
            drawWalk(m, in, frame, compare ? &f : nullptr, display);
        }
    }
}

// The size's rows in kScaleModes' order (the table's), each said.
void addRows(const SizeModes& live, const bench::ScaleRow& base, const walkthrough::gl::GeometryYardsticks& yard,
             const walkthrough::gl::GeometryYardsticks& fullYard, const std::function<void(const std::string&)>& say,
             const std::string& size, bench::ScaleReport& report) {
    for (const SizeMode& m : live.modes) {
        bench::ScaleRow r = rowOf(m.mode, m.acc, base);
        if (m.mode == ScaleMode::WallsBudget) r.triangleBudget = live.budget;
        r.firstFrameSeconds = m.firstFrameSeconds;
        const walkthrough::gl::GeometryYardsticks& y =
            m.mode == ScaleMode::Full || m.mode == ScaleMode::FullLod ? fullYard : yard;
        r.wholeModelMB = y.wholeModelMB;
        r.largestThreeCellsMB = y.largestThreeCellsMB;
        report.rows.push_back(r);
        say(size + ": " + std::string(bench::toString(m.mode)) + " median " + fixed(r.frameMs.p50, 2) +
            " ms, resident " + fixed(r.residentMB, 2) + " MB (paged " + fixed(r.pagedPeakMB, 2) + "), whole model " +
            fixed(r.wholeModelMB, 2) + " MB, largest three cells " + fixed(r.largestThreeCellsMB, 2) + " MB");
    }
}

// One size: its modes made and timed to their first frame, warmed up, then drawn frame by frame
// in turn.
void runSize(const ScaleOptions& o, std::size_t target, const display::Display& display, display::gl::Context& context,
             bench::ScaleReport& report) {
    const std::function<void(const std::string&)> say = [&](const std::string& line) {
        if (o.verbose) std::cout << "bench --scale: " << line << "\n" << std::flush;
    };
    const std::unique_ptr<PreparedSize> prepared = prepareSize(o, target, display, context);
    const std::string& size = prepared->size;
    say(prepared->line);
    report.header.push_back(prepared->line);
    bench::ScaleRow base;
    base.targetTriangles = target;
    base.triangles = prepared->scene.triangleCount();
    base.cells = static_cast<int>(prepared->description.cells.size());
    base.loadSeconds = prepared->loadSeconds;

    SizeModes live = makeModes({o, *prepared, display, context});
    // Yardsticks with each mode's own levels: full detail for full, the walls' levels (also the
    // near limit's) for the others.
    const walkthrough::gl::GeometryYardsticks yard = live.find(ScaleMode::Walls)->walk->geometryYardsticks();
    const walkthrough::gl::GeometryYardsticks fullYard = live.find(ScaleMode::Full)->walk->geometryYardsticks();
    say(size + ": warm-up over the stretch");
    warmUp(live, prepared->path);
    const std::string budgetWords = live.find(ScaleMode::WallsBudget)
                                        ? " and walls-budget (" + std::to_string(live.budget) + " triangles a frame)"
                                        : "";
    say(size + ": full" + (live.find(ScaleMode::FullLod) ? ", full-lod" : "") + ", near, cells, walls" + budgetWords +
        (live.find(ScaleMode::DepthWalls) ? " and walls-depth" : "") + " frame by frame in turn");
    live.find(ScaleMode::Full)->acc.residentMB = fullYard.sharedMB;
    if (SizeMode* fullLod = live.find(ScaleMode::FullLod)) fullLod->acc.residentMB = fullYard.sharedMB;
    SizeMode& nearLimit = *live.find(ScaleMode::Near);
    nearLimit.acc.residentMB = nearLimit.near->residentMB();
    long frame = 0;
    for (const walkthrough::FrameInput& in : prepared->path.frames) {
        drawFrame(live, in, frame, o.compareEvery > 0 && frame % o.compareEvery == 0, display);
        ++frame;
    }
    for (SizeMode& m : live.modes)
        if (hasWalls(m.mode)) m.acc.residentMB = yard.sharedMB + m.acc.pagedMB;
    addRows(live, base, yard, fullYard, say, size, report);
}

}  // namespace

bench::ScaleReport runScaleBench(const ScaleOptions& o) {
    if (o.sizes.empty()) throw Error("bench --scale: expected at least one size, got none");
    if (!(o.pathMetres > 0.0))
        throw Error("bench --scale: --scale-metres: expected more than 0 m, got " + config::formatNumber(o.pathMetres));
    if (o.depthBeside && o.wallKind != walls::WallKind::Flat)
        throw Error("bench --scale: depth walls beside the walls need flat walls (--walls flat,depth), got --walls " +
                    std::string(walls::wallKindName(o.wallKind)));
    if (o.triangleBudget != 0 && !(o.lodPixels > 0.0))
        throw Error("bench --scale: --triangle-budget: needs levels of detail (--lod PX with PX > 0), got --lod " +
                    config::formatNumber(o.lodPixels) + " (--triangle-budget 0 leaves the walls-budget mode out)");
    try {  // before any plant is generated
        walls::validatePlanOptions(scalePlanOptions(o, o.wallKind));
        if (o.depthBeside) walls::validatePlanOptions(scalePlanOptions(o, walls::WallKind::Depth));
    } catch (const Error& e) {
        throw Error(std::string("bench --scale: ") + e.what());
    }
    const auto start = Clock::now();
    const display::Display display(o.display);
    const auto context = display::gl::createHeadlessContext();
    bench::ScaleReport report;
    const auto& s0 = o.display.screens.front();
    report.header = {
        "display: " + o.display.name + ", " + std::to_string(o.display.screens.size()) + " screens at " +
            std::to_string(s0.resolution.x) + "x" + std::to_string(s0.resolution.y) + " pixels, " +
            std::string(config::toString(o.display.stereo)) + "; " + context->info().renderer + ", " +
            std::to_string(std::thread::hardware_concurrency()) + " hardware threads",
        "path: the first " + config::formatNumber(o.pathMetres) +
            " m of each plant's walk path (the same bays at every "
            "size), " +
            std::to_string(o.frames) + " frames, head " + o.tracker + "; modes drawn frame by frame in turn",
        "full: all geometry, frustum-culled, full detail; full-lod: the same at lod " +
            config::formatNumber(o.lodPixels) +
            " px, the alternative a user would pick; near: the viewer's cell and structure at lod " +
            config::formatNumber(o.lodPixels) + " px; walls: " + std::string(walls::wallKindName(o.wallKind)) +
            " walls at alpha " + config::formatNumber(o.alphaDeg) + " deg, lod " + config::formatNumber(o.lodPixels) +
            " px, geometry paging under " + config::formatNumber(o.geometryBudgetMB) +
            " MB (mesh groups shared by cells stored once), synchronous "
            "paging (the first frame complete; textures and groups of the stretch resident after a warm-up pass); "
            "cells: the control, the walls' geometry cells (the viewer's, the neighbours in geometry zones and "
            "blend strips, structure) as the walls draw them, no texture; "
            "first frame: the mode's setup and first frame after loading (walls: planning too; baking not, it is "
            "cached)" +
            (o.triangleBudget == 0
                 ? std::string()
                 : "; walls-budget: the walls with their geometry held to " +
                       (o.triangleBudget > 0 ? std::to_string(o.triangleBudget) + " triangles a frame"
                                             : std::string("the near limit's median triangles a frame")) +
                       " (levels of detail coarsened just enough, to at most " + config::formatNumber(o.lodMaxPixels) +
                       " px; over budget beyond)") +
            (o.depthBeside ? "; walls-depth: the walls mode with depth walls (their own plan and bake, each wall pixel "
                             "reprojected to the eye)"
                           : ""),
        o.compareEvery > 0
            ? "image error: near, cells and walls (both kinds) against full geometry's image of the same frame, "
              "every " +
                  std::to_string(o.compareEvery) +
                  " frames (read back after the frame is timed): PSNR on sRGB RGB "
                  "pooled over all compared pixels, the worst frame's, LDR-FLIP mean at each screen's fewest pixels "
                  "per degree"
            : std::string("image error: not compared (--compare-every 0)"),
        "occlusion culling: " + render::describe(o.occlusion) +
            (o.occlusion.on ? " (every mode; triangles a frame are those drawn; walls-budget's budget counts those "
                              "submitted)"
                            : std::string(" (--no-occlusion)")),
        "load average at start: " + loadAverage()};
    for (std::size_t target : o.sizes) {
        runSize(o, target, display, *context, report);
        if (o.afterSize) o.afterSize(report);
    }
    report.header.push_back("load average at end: " + loadAverage() + "; bench time " + fixed(secondsSince(start), 0) +
                            " s");
    return report;
}

}  // namespace cavewall::bench::gl
