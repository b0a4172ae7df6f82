#include "app/bench/gl/driver.h"

#include "config/json_reader.h"
#include "display/display.h"
#include "display/timing.h"
#include "display/gl/context.h"
#include "scenes/loader.h"
#include "app/bench/gl/modes.h"
#include "app/bench/private_cache.h"
#include "app/gl/run_session.h"
#include "walls/gl/background_baker.h"
#include "walls/gl/baker.h"
#include "walls/wall_setup.h"

#include <algorithm>
#include <memory>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <thread>

namespace cavewall::gl {

using namespace bench;

namespace {

struct BakedWalls {
    walls::WallSetup setup;
    double texels = 0.0, diskMB = 0.0;
    std::string summary;
};

// Plans and bakes (or finds in the cache) the walls of `sceneFile` at `alphaDeg`.
BakedWalls bakeWalls(const BenchOptions& o, const std::filesystem::path& sceneFile, double alphaDeg,
                     const scenes::Scene& scene, const scenes::SceneDescription& d, gl::Context& context) {
    walls::PlanOptions plan = walls::planOptionsFor(o.plan, o.wallKind, o.bakeResolution);
    plan.alphaDeg = alphaDeg;
    BakedWalls out;
    out.setup = walls::prepareWalls(scene, d, plan);
    gl::BakeRequest request;
    request.scene = sceneFile;
    request.settings.maxResolution = o.bakeResolution;
    request.settings.jobs = 2;
    request.settings.drawThreads = 2;
    request.settings.kind = o.wallKind;
    request.settings.textureFormat = o.textureFormat;
    request.context = &context;
    if (o.cache) request.cache = *o.cache;
    gl::BakeResult baked = gl::bakeWalls(scene, d, out.setup, request);
    out.setup.folder = baked.folder;
    for (const walls::BakedTexture& t : baked.manifest.textures)
        out.texels += static_cast<double>(t.resolution.x) * t.resolution.y;
    out.diskMB = static_cast<double>(baked.totalBytes) / 1e6;
    out.setup.manifest = std::move(baked.manifest);
    out.summary = "a=" + config::formatNumber(alphaDeg) + ": " + std::to_string(out.setup.plan.textures.size()) +
                  " textures (" + std::string(walls::textureFormatName(o.textureFormat)) + ", " +
                  fixed(out.diskMB) + " MB on disk), " + std::to_string(baked.baked) + " baked now in " + fixed(baked.seconds) + " s, " +
                  std::to_string(baked.reused) + " from the cache";
    return out;
}

ModeResult namedMode(Mode mode, double lodPixels = 0.0) {
    ModeResult m;
    m.mode = mode;
    m.lodPixels = lodPixels;
    return m;
}

ModeResult wallsMode(double alphaDeg, app::Transition transition, bool paged, double lodPixels,
                     std::size_t triangleBudget, double frameBudgetMs) {
    ModeResult m;
    m.frameBudgetMs = frameBudgetMs;
    m.mode = Mode::Walls;
    m.alphaDeg = alphaDeg;
    m.transition = transition;
    m.paged = paged;
    m.lodPixels = lodPixels;
    m.triangleBudget = triangleBudget;
    return m;
}

void say(const BenchOptions& o, const std::string& line) {
    if (o.verbose) std::cout << line << "\n" << std::flush;
}

std::size_t triangleCount(const scenes::Scene& scene) {
    std::size_t triangles = 0;
    for (const scenes::Object& object : scene.objects) triangles += scene.meshes[object.mesh].triangleCount();
    return triangles;
}

// The compare scene (--compare-scene): the same model (objects and triangles) with walls.
struct CompareScene {
    scenes::SceneDescription description;
    scenes::Scene scene;
};

std::unique_ptr<CompareScene> loadCompareScene(const BenchOptions& o, const BenchOptions::CompareScene& which,
                                               const scenes::Scene& own) {
    auto other = std::make_unique<CompareScene>();
    const std::string name = which.scene.string();
    other->scene = scenes::loadSceneFile(which.scene, &other->description);
    if (other->description.walls.empty())
        throw Error("--compare-scene " + name + ": expected virtual walls to bench, got none");
    const std::size_t mine = triangleCount(own), theirs = triangleCount(other->scene);
    if (other->scene.objects.size() != own.objects.size() || theirs != mine)
        throw Error("--compare-scene " + name + ": expected the same model as " + o.scene.string() + " (" +
                    std::to_string(own.objects.size()) + " objects, " + std::to_string(mine) + " triangles), got " +
                    std::to_string(other->scene.objects.size()) + " objects, " + std::to_string(theirs) + " triangles");
    return other;
}

// Plans and bakes every compare scene's walls at every alpha (per scene, per alpha), with a
// header line for each.
std::vector<std::vector<BakedWalls>> bakeCompareScenes(const BenchOptions& o,
                                                       const std::vector<std::unique_ptr<CompareScene>>& others,
                                                       const scenes::SceneDescription& description,
                                                       gl::Context& context, BenchReport& report) {
    std::vector<std::vector<BakedWalls>> otherBaked(others.size());
    for (std::size_t k = 0; k < others.size(); ++k) {
        const BenchOptions::CompareScene& which = o.compareScenes[k];
        const CompareScene& other = *others[k];
        report.header.push_back("compare scene [" + which.tag + "]: " + which.scene.string() + " (" +
                                std::to_string(other.description.cells.size()) + " cells, " +
                                std::to_string(other.description.walls.size()) + " walls; the bench scene: " +
                                std::to_string(description.cells.size()) + " cells, " +
                                std::to_string(description.walls.size()) + " walls), drawn on the bench scene's eye "
                                "path, its own plan and bake at every alpha");
        for (double alpha : o.alphasDeg) {
            say(o, "bench: plan and bake [" + which.tag + "]'s walls at a=" + config::formatNumber(alpha) + " deg");
            otherBaked[k].push_back(bakeWalls(o, which.scene, alpha, other.scene, other.description, context));
            say(o, "bench: [" + which.tag + "] " + otherBaked[k].back().summary);
            report.header.push_back("bake [" + which.tag + "] " + otherBaked[k].back().summary);
        }
    }
    return otherBaked;
}

// The on-demand mode (--on-demand): plans the walls at `alphaDeg` and walks from an empty,
// private cache while the background baker bakes what the frames want.
ModeResult onDemandMode(const BenchOptions& o, double alphaDeg, const ModeContext& c, const ReferenceImages& reference,
                        double fullP50) {
    makeEmptyPrivateCache(*o.onDemandCache, o.cache ? *o.cache : defaultCacheFolder());
    const auto start = std::chrono::steady_clock::now();  // the scene is loaded: as `run` times it
    walls::PlanOptions plan = walls::planOptionsFor(o.plan, o.wallKind, o.bakeResolution);
    plan.alphaDeg = alphaDeg;
    walls::WallSetup setup = walls::prepareWalls(c.scene, c.description, plan);
    gl::BakeRequest request;
    request.scene = o.scene;
    request.settings.maxResolution = o.bakeResolution;
    request.settings.kind = o.wallKind;
    request.cache = *o.onDemandCache;
    gl::BackgroundBaker baker(c.scene, c.description, setup, request);  // its own headless context
    setup.folder = baker.folder();
    setup.manifest = baker.manifest();
    ModeResult mode;
    mode.mode = Mode::Walls;
    mode.alphaDeg = alphaDeg;
    mode.transition = app::Transition::Blend;
    mode.onDemand.emplace();
    mode.onDemand->cache = o.onDemandCache->string();
    mode.onDemand->texturesMissingAtStart = baker.stats().missingAtStart;
    mode.textures = static_cast<int>(setup.plan.textures.size());
    ModeAccumulator acc(mode, c.display);
    const double firstFrame = runOnDemandMode(c, std::move(setup), baker, acc, reference, start);
    baker.stop();  // the bake in progress finishes and is counted
    ModeResult result = acc.finish(fullP50);
    result.onDemand->firstFrameSeconds = firstFrame;
    result.onDemand->texturesBaked = baker.stats().baked;
    countFallbacks(result.frames, *result.onDemand);
    return result;
}

std::vector<std::string> headerLines(const BenchOptions& o, const scenes::Scene& scene, const gl::Context& context,
                                     const bench::EyePath& path) {
    const std::size_t triangles = triangleCount(scene);
    const auto& s0 = o.display.screens.front();
    return {"scene: " + o.scene.string() + " (" + std::to_string(scene.objects.size()) + " objects, " +
                std::to_string(triangles) + " triangles)",
            "display: " + o.display.name + ", " + std::to_string(o.display.screens.size()) + " screens at " +
                std::to_string(s0.resolution.x) + "x" + std::to_string(s0.resolution.y) + " pixels, " +
                std::string(config::toString(o.display.stereo)) + " stereo mode",
            path.description,
            "image error against the full-geometry image of the same frame, eye and screen, every " +
                std::to_string(o.compareEvery) + " frames; PSNR on sRGB RGB in [0,1] pooled over all compared pixels "
                "(scenes/image_error.h), SSIM on luma (11x11 Gaussian window, sigma 1.5), LDR-FLIP at each screen's "
                "fewest pixels per degree from the frame's head position (display::minPixelsPerDegree, clamped to "
                "[1, 1000]), popping between consecutive compared frames of each screen (32-pixel tiles)",
            "walls: plan minZoneSize " + config::formatNumber(o.plan.minZoneSize) + " m, pixelsPerDegree " +
                config::formatNumber(o.plan.pixelsPerDegree) + ", blendWidth " + config::formatNumber(o.plan.blendWidth) +
                " m; bake maxResolution " + std::to_string(o.bakeResolution) +
                " texels; textures all resident (warm-up pass, synchronous paging) except in the paged mode",
            "machine: " + context.info().renderer + ", " + std::to_string(std::thread::hardware_concurrency()) +
                " hardware threads",
            "transitions: blend at every alpha; warp (structure behind textured walls warped into the texture's "
            "view) at alpha " + config::formatNumber(o.transitionAlphaDeg) + "; 'blend paged' at the same alpha pages "
            "as `cavewall run` does (background decoding, default budget and upload limit, cold start)",
            "near: the near-geometry limit, the viewer's cell plus its walls as bare quads (one 1x1 texture); "
            "cells: the cells the walls mode draws as geometry, without textures; cells+layer: the same plus one "
            "textured full-screen layer per view through the wall pass (512x512 MIP-mapped sRGB, weight 0: the "
            "control's image at one wall layer's cost)",
            o.lodPixels > 0.0 ? "lod: levels of detail built when the mode starts (meshoptimizer, sampled Hausdorff "
                                "error), each object drawn at the coarsest level within " +
                                    config::formatNumber(o.lodPixels) + " px on every screen it appears on; budgets "
                                    "raise that tolerance to at most " + config::formatNumber(o.lodMaxPixels) + " px"
                              : "lod: off (--lod 0)"};
}

}  // namespace

config::DisplayConfig withResolution(config::DisplayConfig display, int pixels) {
    for (config::Screen& s : display.screens) {
        const double longer = std::max(s.resolution.x, s.resolution.y);
        const double scale = longer > 0 ? pixels / longer : 1.0;
        s.resolution = glm::max(glm::ivec2(glm::round(glm::dvec2(s.resolution) * scale)), glm::ivec2(1));
    }
    return display;
}

BenchReport runBenchmark(const BenchOptions& o) {
    if (o.compareEvery < 1) throw Error("bench: compareEvery: expected at least 1, got " + std::to_string(o.compareEvery));
    if (o.alphasDeg.empty()) throw Error("bench: expected at least one alpha for the walls modes, got none");
    if (o.frames < 1) throw Error("--frames: expected at least 1, got " + std::to_string(o.frames));
    for (double budget : o.clusterBudgetsMs)
        if (!(budget > 0.0 && std::isfinite(budget)))
            throw Error("bench: cluster budgets: expected milliseconds > 0, got " + config::formatNumber(budget));
    if (std::find(o.alphasDeg.begin(), o.alphasDeg.end(), o.transitionAlphaDeg) == o.alphasDeg.end())
        throw Error("bench: the warp alpha " + config::formatNumber(o.transitionAlphaDeg) +
                    " is not one of the planned alphas");
    const auto start = std::chrono::steady_clock::now();
    const display::Display display(o.display);
    scenes::SceneDescription description;
    const scenes::Scene scene = scenes::loadSceneFile(o.scene, &description);
    app::useRoute(description, o.route, o.scene.string());
    if (description.walls.empty()) throw Error(o.scene.string() + ": the scene has no virtual walls (expected at least 1 to bench)");
    // Checked before anything is baked: a bad compare scene or cache folder fails at once.
    std::vector<std::unique_ptr<CompareScene>> others;
    for (std::size_t i = 0; i < o.compareScenes.size(); ++i) {
        for (std::size_t k = 0; k < i; ++k)
            if (o.compareScenes[k].tag == o.compareScenes[i].tag)
                throw Error("--compare-scene: expected scenes whose labels differ, got '" + o.compareScenes[i].tag +
                            "' for " + o.compareScenes[k].scene.string() + " and " + o.compareScenes[i].scene.string());
        others.push_back(loadCompareScene(o, o.compareScenes[i], scene));
    }
    if (o.onDemandCache) {
        if (o.wallKind != walls::WallKind::Flat)
            throw Error("--on-demand: baking on demand draws flat walls only, got --walls depth");
        checkPrivateCache(*o.onDemandCache, o.cache ? *o.cache : defaultCacheFolder());
    }
    bench::EyePath path = bench::recordEyePath(scene, description, o.display, o.tracker, o.frames);
    if (o.route == app::Route::Wall)
        path.description += " (--route wall: the scene's wallPath, which hugs the virtual walls, as its walkPath)";
    const auto context = gl::createHeadlessContext();
    BenchReport report;
    report.header = headerLines(o, scene, *context, path);
    const auto& s0 = o.display.screens.front();
    report.resolution = std::to_string(s0.resolution.x) + "x" + std::to_string(s0.resolution.y) + " per screen, " +
                        std::string(config::toString(o.display.stereo));
    const ModeContext c{scene, description, display, *context, path, o.compareEvery, o.lodMaxPixels, o.wallKind,
                        o.clusters ? (o.cache ? *o.cache : defaultCacheFolder()) : std::filesystem::path()};

    const bool lod = o.lodPixels > 0.0;
    std::vector<BakedWalls> baked;
    for (double alpha : o.alphasDeg) {
        say(o, "bench: plan and bake walls at a=" + config::formatNumber(alpha) + " deg");
        baked.push_back(bakeWalls(o, o.scene, alpha, scene, description, *context));
        say(o, "bench: " + baked.back().summary);
        report.header.push_back("bake " + baked.back().summary);
    }
    const std::vector<std::vector<BakedWalls>> otherBaked = bakeCompareScenes(o, others, description, *context, report);
    const auto listed = std::find(o.alphasDeg.begin(), o.alphasDeg.end(), o.transitionAlphaDeg);
    const std::size_t transitionIndex = listed - o.alphasDeg.begin();  // listed: checked on entry

    // Full geometry (the reference) and every walls mode but the paged one, frame by frame in
    // turn: their speed-ups are ratios of times taken in the same seconds.
    std::vector<std::unique_ptr<ModeAccumulator>> accs;  // stable addresses for the runs
    std::vector<WalkRun> runs;
    auto addRun = [&](ModeResult mode, std::optional<std::size_t> wallsIndex, app::Transition transition,
                      int budgetFrom = -1, int compare = -1) {
        const std::vector<BakedWalls>& from = compare >= 0 ? otherBaked[compare] : baked;
        if (wallsIndex) {
            mode.textures = static_cast<int>(from[*wallsIndex].setup.plan.textures.size());
            mode.texels = from[*wallsIndex].texels;
            mode.diskMB = from[*wallsIndex].diskMB;
        }
        if (compare >= 0) mode.sceneTag = o.compareScenes[compare].tag;
        accs.push_back(std::make_unique<ModeAccumulator>(mode, display));
        WalkRun run;
        if (wallsIndex) run.walls = from[*wallsIndex].setup;
        if (compare >= 0) run.scene = &others[compare]->scene, run.description = &others[compare]->description;
        run.acc = accs.back().get();
        run.transition = transition;
        run.storeReference = runs.empty();
        run.budgetFrom = budgetFrom;
        runs.push_back(std::move(run));
        return static_cast<int>(runs.size()) - 1;
    };
    addRun(namedMode(Mode::Full), std::nullopt, app::Transition::Blend);
    if (lod) addRun(namedMode(Mode::Full, o.lodPixels), std::nullopt, app::Transition::Blend);
    for (std::size_t i = 0; i < baked.size(); ++i)
        addRun(wallsMode(o.alphasDeg[i], app::Transition::Blend, false, 0.0, 0, 0.0), i, app::Transition::Blend);
    std::vector<int> lodRun(baked.size(), -1);
    if (lod)
        for (std::size_t i = 0; i < baked.size(); ++i)
            lodRun[i] = addRun(wallsMode(o.alphasDeg[i], app::Transition::Blend, false, o.lodPixels, 0, 0.0), i,
                               app::Transition::Blend);
    addRun(wallsMode(o.alphasDeg[transitionIndex], app::Transition::Warp, false, 0.0, 0, 0.0), transitionIndex,
           app::Transition::Warp);
    if (lod)
        for (std::size_t i = 0; i < baked.size(); ++i)  // budget: the median of the same mode without one
            addRun(wallsMode(o.alphasDeg[i], app::Transition::Blend, false, o.lodPixels, o.triangleBudget, 0.0), i,
                   app::Transition::Blend, o.triangleBudget == 0 ? lodRun[i] : -1);
    if (lod && o.frameBudgetMs > 0.0)
        for (std::size_t i = 0; i < baked.size(); ++i)
            addRun(wallsMode(o.alphasDeg[i], app::Transition::Blend, false, o.lodPixels, 0, o.frameBudgetMs), i,
                   app::Transition::Blend);
    if (o.clusters) {
        std::vector<double> budgets = o.clusterBudgetsMs;
        if (budgets.empty()) budgets.push_back(o.frameBudgetMs > 0.0 ? o.frameBudgetMs : 1000.0 / 60.0);
        for (double budget : budgets) {
            ModeResult m;
            m.mode = Mode::Clusters;
            m.frameBudgetMs = budget;
            runs[addRun(m, std::nullopt, app::Transition::Blend)].clusters = true;
        }
    }
    for (std::size_t k = 0; k < others.size(); ++k) {  // the compare scenes', after all the bench scene's
        const int compare = static_cast<int>(k);
        for (std::size_t i = 0; i < baked.size(); ++i)
            addRun(wallsMode(o.alphasDeg[i], app::Transition::Blend, false, 0.0, 0, 0.0), i, app::Transition::Blend, -1,
                   compare);
        if (lod)
            for (std::size_t i = 0; i < baked.size(); ++i)
                addRun(wallsMode(o.alphasDeg[i], app::Transition::Blend, false, o.lodPixels, 0, 0.0), i,
                       app::Transition::Blend, -1, compare);
    }
    std::string names;
    for (const auto& acc : accs) names += (names.empty() ? "" : ", ") + modeLabel(acc->mode());
    say(o, "bench: " + names + ", frame by frame in turn");
    ReferenceImages reference;
    runWalkthroughModes(c, runs, reference);
    std::vector<ModeResult> interleaved{accs.front()->finish(0.0)};  // the reference: no speed-up
    const double fullP50 = interleaved.front().frameMs.p50;
    for (std::size_t i = 1; i < accs.size(); ++i) interleaved.push_back(accs[i]->finish(fullP50));
    report.header.push_back("drawn frame by frame in turn (the same seconds): " + names +
                            "; then cells, cells+layer and near in turn; then the paged mode alone" +
                            (o.onDemandCache ? "; then the on-demand mode alone" : ""));

    const walls::WallSetup& cellPlan = baked[transitionIndex].setup;
    std::vector<ModeResult> cellModes;
    auto runCells = [&](std::vector<CellDraw> kinds, double lodPixels) {
        std::vector<ModeAccumulator> cellAccs;
        cellAccs.reserve(kinds.size());
        std::vector<CellRun> cellRuns;
        std::string cellNames;
        for (CellDraw kind : kinds) {
            const Mode mode = kind == CellDraw::Near ? Mode::Near : kind == CellDraw::Cells ? Mode::Cells : Mode::CellsLayer;
            cellAccs.emplace_back(namedMode(mode, lodPixels), display);
            cellRuns.push_back({kind, &cellAccs.back()});
            cellNames += (cellNames.empty() ? "" : ", ") + modeLabel(cellAccs.back().mode());
        }
        say(o, "bench: " + cellNames + (kinds.size() > 1 ? ", frame by frame in turn" : ""));
        runCellModes(c, cellPlan, cellRuns, reference);
        for (const ModeAccumulator& acc : cellAccs) cellModes.push_back(acc.finish(fullP50));
    };
    // The control, the control plus one textured layer and the limit in the same seconds: the
    // wall pass's target compares them.
    runCells({CellDraw::Cells, CellDraw::CellsLayer, CellDraw::Near}, 0.0);
    if (lod) runCells({CellDraw::Near}, o.lodPixels);

    ModeResult pagedMode = wallsMode(o.alphasDeg[transitionIndex], app::Transition::Blend, true, 0.0, 0, 0.0);
    pagedMode.textures = static_cast<int>(baked[transitionIndex].setup.plan.textures.size());
    pagedMode.texels = baked[transitionIndex].texels;
    pagedMode.diskMB = baked[transitionIndex].diskMB;
    say(o, "bench: " + modeLabel(pagedMode));
    ModeAccumulator pagedAcc(pagedMode, display);
    std::vector<WalkRun> paged(1);
    paged[0].walls = baked[transitionIndex].setup;
    paged[0].acc = &pagedAcc;
    paged[0].paged = true;
    runWalkthroughModes(c, paged, reference);
    std::optional<ModeResult> onDemand;
    if (o.onDemandCache) {
        say(o, "bench: walls a=" + config::formatNumber(o.transitionAlphaDeg) + " blend on demand, from an empty cache " +
                   o.onDemandCache->string());
        onDemand = onDemandMode(o, o.transitionAlphaDeg, c, reference, fullP50);
        report.header.push_back("on demand: walls at alpha " + config::formatNumber(o.transitionAlphaDeg) +
                                " baked while walking (background baker at nice 10, as `cavewall run "
                                "--bake-on-demand`) from an empty private cache " + o.onDemandCache->string() +
                                ", alone after the paged mode; the first path frame drawn once first (first frame "
                                "after the scene's load: planning, keying the cache, the walkthrough, that frame), then "
                                "every path frame timed");
    }

    // The report in its usual order: full geometry, the cell modes, then the walls modes.
    const std::size_t fullModes = lod ? 2 : 1;
    report.modes.assign(interleaved.begin(), interleaved.begin() + static_cast<long>(fullModes));
    report.modes.insert(report.modes.end(), cellModes.begin(), cellModes.end());
    const std::size_t beforePaged = fullModes + baked.size() * (lod ? 2 : 1) + 1;  // blend, lod, warp
    report.modes.insert(report.modes.end(), interleaved.begin() + static_cast<long>(fullModes),
                        interleaved.begin() + static_cast<long>(beforePaged));
    report.modes.push_back(pagedAcc.finish(fullP50));
    if (onDemand) report.modes.push_back(std::move(*onDemand));
    report.modes.insert(report.modes.end(), interleaved.begin() + static_cast<long>(beforePaged), interleaved.end());
    if (lod && o.triangleBudget == 0)
        report.header.push_back("triangle budgets: per alpha, the median triangles of the same walls mode without a "
                                "budget");
    {  // The noise floor of p99/p50 on this machine, beside a walls mode's, in the same seconds.
        // The budget mode at the last alpha, or the paged one (the clusters mode, listed after
        // them, is not a walls mode).
        ModeResult last = *std::find_if(report.modes.rbegin(), report.modes.rend(), [](const ModeResult& m) {
            return m.mode == Mode::Walls && m.sceneTag.empty() && !m.onDemand;
        });
        last.paged = false;  // drawn with every texture resident, also after the paged mode
        say(o, "bench: noise floor, " + modeLabel(last) + " interleaved with one of its frames");
        const long middle = static_cast<long>(path.frames.size() / 2);
        const std::size_t alpha = lod ? baked.size() - 1 : transitionIndex;
        const NoiseComparison n = interleavedNoise(c, baked[alpha].setup, last, middle);
        auto ratio = [](const TimeStats& t) { return fixed(t.p50 > 0 ? t.p99 / t.p50 : 0.0, 2); };
        report.noiseFloorRatio = n.repeated.p50 > 0 ? n.repeated.p99 / n.repeated.p50 : 0.0;
        report.noiseFloorP95Ratio = n.repeated.p50 > 0 ? n.repeated.p95 / n.repeated.p50 : 0.0;
        report.header.push_back(
            "noise floor: " + modeLabel(last) + " along the path, each frame followed by frame " +
            std::to_string(middle) + " again: the path's frames p50 " + fixed(n.path.p50, 2) + " ms, p99/p50 " +
            ratio(n.path) + "; the repeated frame (the same work every time) p50 " + fixed(n.repeated.p50, 2) +
            " ms, p99/p50 " + ratio(n.repeated) + ": what the repeated frame shows is the machine's noise, not the "
            "renderer's");
    }
    compareWithControl(report);
    report.header.push_back("control: 'cells' (the cells the walls draw as geometry, no textures); 'vs control' is "
                            "every walls mode's pooled PSNR gain over it and its FLIP mean as a fraction of its");
    report.header.push_back("bench time: " +
                            fixed(display::msSince(start) / 1000.0, 0) +
                            " s in total (all modes, bakes included)");
    return report;
}

}  // namespace cavewall::gl
