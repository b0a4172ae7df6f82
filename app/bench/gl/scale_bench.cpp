#include "app/bench/gl/scale_bench.h"

#include "config/error.h"
#include "config/json_reader.h"
#include "display/display.h"
#include "display/timing.h"
#include "display/gl/context.h"
#include "display/gl/frame_images.h"
#include "display/gl/render_targets.h"
#include "display/gl/scene_renderer.h"
#include "app/bench/gl/modes.h"
#include "app/bench/metrics.h"
#include "app/bench/path.h"
#include "app/bench/report.h"
#include "render/lod_choice.h"
#include "scenes/generate.h"
#include "scenes/loader.h"
#include "walls/frame_planner.h"
#include "walls/frame_select.h"
#include "walls/gl/baker.h"
#include "walls/gl/walkthrough.h"
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

namespace cavewall::gl {

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

// The plant for `triangles`, generated into `folder` unless it is there already.
std::filesystem::path plantFor(std::size_t triangles, const std::filesystem::path& folder, double& generateSeconds) {
    const std::filesystem::path sceneFile = folder / "scene.json";
    generateSeconds = 0.0;
    if (std::filesystem::exists(sceneFile)) return sceneFile;
    const auto start = Clock::now();
    scenes::GenerateOptions g;
    g.triangles = triangles;
    scenes::GeneratedScene generated = scenes::generatePlant(g);
    scenes::writeGenerated(generated, folder);
    generateSeconds = secondsSince(start);
    return sceneFile;
}

// The textures the path's frames request (now or soon) with every texture resident, in id order.
std::set<int> requestedTextures(const scenes::Scene& scene, const scenes::SceneDescription& d,
                                const display::Display& display, const walls::WallSetup& setup,
                                const bench::EyePath& path) {
    walls::FramePlanner planner(scene, d, display, &setup, walls::Transition::Blend, 0.5);
    planner.requestCells(true);
    std::set<int> ids;
    for (const walls::FrameInput& in : path.frames) {
        const walls::TextureRequests r = planner.requests(in, display.views(in.head));
        ids.insert(r.now.begin(), r.now.end());
        ids.insert(r.soon.begin(), r.soon.end());
        planner.plan([](int) { return true; });
    }
    return ids;
}

// Bakes the `ids` of `setup`'s plan only (a copy of the plan without the others, ids kept).
BakeResult bakeSubset(const scenes::Scene& scene, const scenes::SceneDescription& d, const walls::WallSetup& setup,
                      const std::set<int>& ids, const std::filesystem::path& sceneFile, const ScaleOptions& o,
                      walls::WallKind kind, Context& context) {
    walls::WallSetup subset = setup;
    std::erase_if(subset.plan.textures, [&](const walls::Texture& t) { return !ids.count(t.id); });
    BakeRequest request;
    request.scene = sceneFile;
    request.settings.maxResolution = o.bakeResolution;
    request.settings.kind = kind;
    request.settings.jobs = 2;
    request.context = &context;
    request.cache = o.data / "bake-cache";
    return bakeWalls(scene, d, subset, request);
}

// The near limit's draw of one frame: the viewer's cell and the always-drawn objects.
struct NearMode {
    NearMode(const scenes::Scene& scene, const scenes::SceneDescription& d, const display::Display& display,
             Context& context, const walls::WallSetup& setup, double lodPixels)
        : scene(scene), display(display), selector(setup.plan, setup.table, d), targets(display, context),
          renderer(scene, settingsWith(lodPixels)), cells(d.cells.size()), lodPixels(lodPixels) {}

    static RenderSettings settingsWith(double lodPixels) {
        RenderSettings s;
        s.lodPixels = lodPixels;
        return s;
    }

    // Frame ms (submission and GPU) and triangles.
    std::pair<double, double> draw(const walls::FrameInput& in) {
        const auto start = Clock::now();
        const glm::dvec3 eye(in.worldFromCave * glm::dvec4(in.head.position, 1.0));
        const walls::FrameSelection selection = selector.select(eye);
        std::vector<bool> mask(cells, false);
        if (selection.cell >= 0 && selection.cell < static_cast<int>(cells)) mask[selection.cell] = true;
        const std::vector<int> objects = walls::objectsOfCells(scene, mask);
        render::DrawFilter filter;
        filter.objects = &objects;
        const std::vector<display::ScreenView> views = display.views(in.head);
        render::FrameLod lod;
        if (renderer.hasLods()) {
            lod = render::chooseLods(renderer.renderScene(), views, in.worldFromCave, filter, lodPixels);
            filter.lodLevels = &lod.levels;
        }
        const FrameStats stats = renderer.render(views, targets, in.worldFromCave, filter);
        renderer.waitGpuMs();
        return {display::msSince(start), static_cast<double>(stats.triangles)};
    }

    double residentMB() const {
        return static_cast<double>(renderer.gpu().vertexBytes() + renderer.gpu().indexBytes()) / kMB;
    }

    const scenes::Scene& scene;
    const display::Display& display;
    walls::FrameSelector selector;
    RenderTargets targets;
    SceneRenderer renderer;
    std::size_t cells;
    double lodPixels;
};

struct Accumulated {
    explicit Accumulated(std::size_t screens) : errors(screens) {}
    std::vector<double> ms;
    double triangles = 0.0, residentMB = 0.0, pagedMB = 0.0;
    int overAlpha = 0;
    long misses = 0, pageIns = 0;
    bench::ErrorPool errors;   // against full geometry (near and walls)
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
    if (e.frames > 0) r.psnrDb = e.psnrDb, r.worstFramePsnrDb = e.worstFramePsnrDb, r.flipMean = e.flipMean;
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
                                          Context& context) {
    auto p = std::make_unique<PreparedSize>();
    double generateSeconds = 0.0;
    const std::filesystem::path sceneFile = plantFor(target, o.data / ("plant-" + std::to_string(target)), generateSeconds);
    auto start = Clock::now();
    scenes::SceneDescription& d = p->description;
    p->scene = scenes::loadSceneFile(sceneFile, &d);
    p->loadSeconds = secondsSince(start);
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
        const BakeResult baked = bakeSubset(p->scene, d, setup, ids, sceneFile, o, kind, context);
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

// One size's three modes: made and timed to their first frame, warmed up, then drawn frame by
// frame in turn (one function: the three live modes are shared by every step).
void runSize(const ScaleOptions& o, std::size_t target, const display::Display& display, Context& context,
             bench::ScaleReport& report) {
    auto say = [&](const std::string& line) {
        if (o.verbose) std::cout << "bench --scale: " << line << "\n" << std::flush;
    };
    const std::unique_ptr<PreparedSize> prepared = prepareSize(o, target, display, context);
    const scenes::Scene& scene = prepared->scene;
    const scenes::SceneDescription& d = prepared->description;
    const bench::EyePath& path = prepared->path;
    const walls::WallSetup& setup = prepared->setup;
    const std::string& size = prepared->size;
    const double loadSeconds = prepared->loadSeconds, planSeconds = prepared->planSeconds;
    const std::size_t triangles = scene.triangleCount();
    say(prepared->line);
    report.header.push_back(prepared->line);

    bench::ScaleRow base;
    base.targetTriangles = target;
    base.triangles = triangles;
    base.cells = static_cast<int>(d.cells.size());
    base.loadSeconds = loadSeconds;
    const auto timeFirst = [&](auto make, auto frame) {
        const auto t = Clock::now();
        auto made = make();
        frame(*made);
        return std::pair{std::move(made), secondsSince(t)};
    };
    // Full geometry.
    WalkthroughOptions fullOptions;
    auto [full, fullFirst] = timeFirst(
        [&] { return std::make_unique<Walkthrough>(scene, d, display, context, std::nullopt, fullOptions); },
        [&](Walkthrough& w) { w.renderFrame(path.frames.front()); });
    // The near limit.
    auto [nearMode, nearFirst] = timeFirst(
        [&] { return std::make_unique<NearMode>(scene, d, display, context, setup, o.lodPixels); },
        [&](NearMode& n) { n.draw(path.frames.front()); });
    // Walls: planning counts in its time to the first frame (the bake does not: it is cached).
    WalkthroughOptions wallsOptions;
    wallsOptions.render.lodPixels = o.lodPixels;
    wallsOptions.geometryBudgetMB = o.geometryBudgetMB;
    wallsOptions.wallKind = o.wallKind;
    // Synchronous paging: the first frame is complete (its textures and cells loaded), and after
    // the warm-up pass every texture and mesh group of the stretch stays resident, so the timed
    // frames measure drawing (nothing is left to wait for).
    wallsOptions.synchronousPaging = true;
    wallsOptions.textureBudgetMB = 4096.0;
    wallsOptions.uploadMBPerFrame = 4096.0;
    // A walkthrough of `walls` and the seconds to make it and draw the stretch's first frame.
    const auto firstWalk = [&](const walls::WallSetup& walls, const WalkthroughOptions& options) {
        return timeFirst([&] { return std::make_unique<Walkthrough>(scene, d, display, context, walls, options); },
                         [&](Walkthrough& w) { w.renderFrame(path.frames.front()); });
    };
    auto [walk, wallsFirst] = firstWalk(setup, wallsOptions);
    // The control: the flat walls' geometry cells, no texture.
    WalkthroughOptions cellsOptions = wallsOptions;
    cellsOptions.wallTextures = false;
    auto [cells, cellsFirst] = firstWalk(setup, cellsOptions);
    // Depth walls beside the flat ones: the same options, their own plan and bake.
    std::unique_ptr<Walkthrough> depthWalk;
    double depthFirst = 0.0;
    if (prepared->depthSetup) {
        WalkthroughOptions depthOptions = wallsOptions;
        depthOptions.wallKind = walls::WallKind::Depth;
        std::tie(depthWalk, depthFirst) = firstWalk(*prepared->depthSetup, depthOptions);
    }
    // The near limit over the whole stretch: its warm-up, and its median triangles (the budget).
    std::vector<double> nearTriangles;
    for (const walls::FrameInput& in : path.frames) nearTriangles.push_back(nearMode->draw(in).second);
    std::sort(nearTriangles.begin(), nearTriangles.end());
    const std::size_t budget = o.triangleBudget >= 0 ? static_cast<std::size_t>(o.triangleBudget)
                                                     : static_cast<std::size_t>(nearTriangles[nearTriangles.size() / 2]);
    std::unique_ptr<Walkthrough> budgeted;
    double budgetFirst = 0.0;
    if (budget > 0) {
        WalkthroughOptions budgetOptions = wallsOptions;
        budgetOptions.triangleBudget = budget;
        budgetOptions.lodMaxPixels = std::max(o.lodMaxPixels, o.lodPixels);
        std::tie(budgeted, budgetFirst) = firstWalk(setup, budgetOptions);
    }
    // Yardsticks with each mode's own levels: full detail for full, the walls' levels (also the
    // near limit's) for the others.
    const GeometryYardsticks yard = walk->geometryYardsticks(), fullYard = full->geometryYardsticks();
    say(size + ": warm-up over the stretch");
    for (Walkthrough* w : {walk.get(), budgeted.get(), depthWalk.get(), cells.get()}) {
        if (!w) continue;
        for (const walls::FrameInput& in : path.frames) w->renderFrame(in);
        w->waitForTextures();
    }
    for (std::size_t i = 0; i < std::min<std::size_t>(3, path.frames.size()); ++i) full->renderFrame(path.frames[i]);
    say(size + ": full, near, cells, walls" + std::string(budgeted ? " and walls-budget (" + std::to_string(budget) +
                                                              " triangles a frame)" : "") +
        (depthWalk ? " and walls-depth" : "") + " frame by frame in turn");
    const std::size_t screens = display.screens().size();
    // Indexed as the modes below: full, near, walls, walls-budget, walls-depth, cells.
    Accumulated a[6] = {Accumulated(screens), Accumulated(screens), Accumulated(screens),
                        Accumulated(screens), Accumulated(screens), Accumulated(screens)};
    a[0].residentMB = fullYard.sharedMB;
    a[1].residentMB = nearMode->residentMB();
    // The walkthrough modes, indexed as `a`.
    Walkthrough* const walkthroughs[6] = {nullptr, nullptr, walk.get(), budgeted.get(), depthWalk.get(), cells.get()};
    const char* const names[6] = {"full", "near", "walls", "walls-budget", "walls-depth", "cells"};
    long frame = 0;
    for (walls::FrameInput in : path.frames) {
        // Images are read back after each mode's frame is timed (walkthrough.h; NearMode::draw).
        const bool compare = o.compareEvery > 0 && frame % o.compareEvery == 0;
        in.readImages = compare;
        const walls::FrameResult f = full->renderFrame(in);
        a[0].ms.push_back(f.frameMs), a[0].triangles += static_cast<double>(f.stats.triangles);
        const auto [nearMs, nearTriangles] = nearMode->draw(in);
        a[1].ms.push_back(nearMs), a[1].triangles += nearTriangles;
        if (compare)
            a[1].errors.addFrame(frame, comparedImages(display, in.head, readFrame(display, nearMode->targets), f.images,
                                                       "near"));
        for (int m : {5, 2, 3, 4}) {
            if (!walkthroughs[m]) continue;
            const walls::FrameResult w = walkthroughs[m]->renderFrame(in);
            a[m].ms.push_back(w.frameMs), a[m].triangles += static_cast<double>(w.stats.triangles);
            if (compare) a[m].errors.addFrame(frame, comparedImages(display, in.head, w.images, f.images, names[m]));
            a[m].pagedMB = std::max(a[m].pagedMB, w.geometry.residentMB);
            a[m].overAlpha = std::max(a[m].overAlpha, w.texturesOverAlpha);
            a[m].misses = w.geometry.misses, a[m].pageIns = w.geometry.pageIns;
        }
        ++frame;
    }
    for (int m = 2; m < 6; ++m) a[m].residentMB = yard.sharedMB + a[m].pagedMB;
    const double firsts[6] = {fullFirst, nearFirst, wallsFirst + planSeconds, budgetFirst + planSeconds,
                              depthFirst + prepared->depthPlanSeconds, cellsFirst + planSeconds};
    const bench::ScaleMode modes[6] = {bench::ScaleMode::Full,  bench::ScaleMode::Near,        bench::ScaleMode::Walls,
                                       bench::ScaleMode::WallsBudget, bench::ScaleMode::DepthWalls, bench::ScaleMode::Cells};
    for (int m : {0, 1, 5, 2, 3, 4}) {  // the rows in kScaleModes' order
        if ((m == 3 && !budgeted) || (m == 4 && !depthWalk)) continue;
        bench::ScaleRow r = rowOf(modes[m], a[m], base);
        if (modes[m] == bench::ScaleMode::WallsBudget) r.triangleBudget = budget;
        r.firstFrameSeconds = firsts[m];
        r.wholeModelMB = m == 0 ? fullYard.wholeModelMB : yard.wholeModelMB;
        r.largestThreeCellsMB = m == 0 ? fullYard.largestThreeCellsMB : yard.largestThreeCellsMB;
        report.rows.push_back(r);
        say(size + ": " + std::string(bench::toString(modes[m])) + " median " + fixed(r.frameMs.p50, 2) + " ms, resident " +
            fixed(r.residentMB, 2) + " MB (paged " + fixed(r.pagedPeakMB, 2) + "), whole model " +
            fixed(r.wholeModelMB, 2) + " MB, largest three cells " + fixed(r.largestThreeCellsMB, 2) + " MB");
    }
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
    const auto context = createHeadlessContext();
    bench::ScaleReport report;
    const auto& s0 = o.display.screens.front();
    report.header = {
        "display: " + o.display.name + ", " + std::to_string(o.display.screens.size()) + " screens at " +
            std::to_string(s0.resolution.x) + "x" + std::to_string(s0.resolution.y) + " pixels, " +
            std::string(config::toString(o.display.stereo)) + "; " + context->info().renderer + ", " +
            std::to_string(std::thread::hardware_concurrency()) + " hardware threads",
        "path: the first " + config::formatNumber(o.pathMetres) + " m of each plant's walk path (the same bays at every "
            "size), " + std::to_string(o.frames) + " frames, head " + o.tracker + "; modes drawn frame by frame in turn",
        "full: all geometry, frustum-culled, full detail; near: the viewer's cell and structure at lod " +
            config::formatNumber(o.lodPixels) + " px; walls: " + std::string(walls::wallKindName(o.wallKind)) +
            " walls at alpha " + config::formatNumber(o.alphaDeg) + " deg, lod " + config::formatNumber(o.lodPixels) + " px, geometry paging under " +
            config::formatNumber(o.geometryBudgetMB) + " MB (mesh groups shared by cells stored once), synchronous "
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
            ? "image error: near, cells and walls (both kinds) against full geometry's image of the same frame, every " +
                  std::to_string(o.compareEvery) + " frames (read back after the frame is timed): PSNR on sRGB RGB "
                  "pooled over all compared pixels, the worst frame's, LDR-FLIP mean at each screen's fewest pixels "
                  "per degree"
            : std::string("image error: not compared (--compare-every 0)"),
        "load average at start: " + loadAverage()};
    for (std::size_t target : o.sizes) {
        runSize(o, target, display, *context, report);
        if (o.afterSize) o.afterSize(report);
    }
    report.header.push_back("load average at end: " + loadAverage() + "; bench time " + fixed(secondsSince(start), 0) + " s");
    return report;
}

}  // namespace cavewall::gl
