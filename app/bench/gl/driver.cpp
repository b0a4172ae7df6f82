#include "app/bench/gl/driver.h"

#include "config/json_reader.h"
#include "display/display.h"
#include "display/timing.h"
#include "display/gl/context.h"
#include "scenes/loader.h"
#include "app/bench/gl/baked_walls.h"
#include "app/bench/gl/cell_modes.h"
#include "app/run_options.h"
#include "app/bench/gl/modes.h"
#include "app/bench/private_cache.h"
#include "render/occlusion_settings.h"
#include "app/gl/run_session.h"
#include "walls/gl/background_baker.h"
#include "walls/gl/baker.h"
#include "walls/wall_setup.h"

#include <algorithm>
#include <functional>
#include <optional>
#include <memory>
#include <chrono>
#include <cmath>
#include <iostream>
#include <sstream>
#include <thread>

namespace cavewall::bench::gl {

using namespace bench;

namespace {

ModeResult namedMode(Mode mode, double lodPixels = 0.0) {
    ModeResult m;
    m.mode = mode;
    m.lodPixels = lodPixels;
    return m;
}

// A walls mode's settings besides its alpha (ModeResult's fields of the same names).
struct WallsModeOptions {
    app::Transition transition = app::Transition::Blend;
    bool paged = false;              // paged from a cold start, as `cavewall run` pages
    double lodPixels = 0.0;          // level-of-detail tolerance; 0: full detail
    std::size_t triangleBudget = 0;  // 0: none
    double frameBudgetMs = 0.0;      // the frame-time controller's target; 0: none
    bool flat = false;               // the flat walls beside the depth walls
};

ModeResult wallsMode(double alphaDeg, const WallsModeOptions& options = {}) {
    ModeResult m;
    m.frameBudgetMs = options.frameBudgetMs;
    m.mode = Mode::Walls;
    m.alphaDeg = alphaDeg;
    m.transition = options.transition;
    m.paged = options.paged;
    m.lodPixels = options.lodPixels;
    m.triangleBudget = options.triangleBudget;
    return m;
}

// The on-demand mode (--on-demand): plans the walls at `alphaDeg` and walks from an empty,
// private cache while the background baker bakes what the frames want.
ModeResult onDemandMode(const BenchOptions& o, double alphaDeg, const ModeContext& c, const ReferenceImages& reference,
                        double fullP50) {
    makeEmptyPrivateCache(*o.onDemandCache, o.cache ? *o.cache : walls::gl::defaultCacheFolder());
    const auto start = std::chrono::steady_clock::now();  // the scene is loaded: as `run` times it
    walls::PlanOptions plan = walls::planOptionsFor(o.plan, o.wallKind, o.bakeResolution);
    plan.alphaDeg = alphaDeg;
    walls::WallSetup setup = walls::prepareWalls(c.scene, c.description, plan);
    walls::gl::BakeRequest request;
    request.scene = o.scene;
    request.settings.maxResolution = o.bakeResolution;
    request.settings.kind = o.wallKind;
    request.cache = *o.onDemandCache;
    walls::gl::BackgroundBaker baker(c.scene, c.description, setup, request);  // its own headless context
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

std::vector<std::string> headerLines(const BenchOptions& o, const scenes::Scene& scene,
                                     const display::gl::Context& context, const bench::EyePath& path) {
    const std::size_t triangles = triangleCount(scene);
    const auto& s0 = o.display.screens.front();
    return {"scene: " + o.scene.string() + " (" + std::to_string(scene.objects.size()) + " objects, " +
                std::to_string(triangles) + " triangles)",
            "display: " + o.display.name + ", " + std::to_string(o.display.screens.size()) + " screens at " +
                std::to_string(s0.resolution.x) + "x" + std::to_string(s0.resolution.y) + " pixels, " +
                std::string(config::toString(o.display.stereo)) + " stereo mode",
            path.description,
            "image error against the full-geometry image of the same frame, eye and screen, every " +
                std::to_string(o.compareEvery) +
                " frames; PSNR on sRGB RGB in [0,1] pooled over all compared pixels "
                "(scenes/image_error.h), SSIM on luma (11x11 Gaussian window, sigma 1.5), LDR-FLIP at each screen's "
                "fewest pixels per degree from the frame's head position (display::minPixelsPerDegree, clamped to "
                "[1, 1000]), popping between consecutive compared frames of each screen (32-pixel tiles)",
            "walls: plan minZoneSize " + config::formatNumber(o.plan.minZoneSize) + " m" +
                (o.planningGiven.minZone ? "" : " (the scene's planning.minZone, else the default)") + ", pixelsPerDegree " +
                config::formatNumber(o.plan.pixelsPerDegree) + ", blendWidth " +
                config::formatNumber(o.plan.blendWidth) + " m; bake maxResolution " + std::to_string(o.bakeResolution) +
                " texels" + (o.planningGiven.maxRes ? "" : " (the scene's planning.maxRes, else the default)") +
                "; textures all resident (warm-up pass, synchronous paging) except in the paged mode",
            "machine: " + context.info().renderer + ", " + std::to_string(std::thread::hardware_concurrency()) +
                " hardware threads",
            "transitions: blend at every alpha; warp (structure behind textured walls warped into the texture's "
            "view) at alpha " +
                config::formatNumber(o.transitionAlphaDeg) +
                "; 'blend paged' at the same alpha pages "
                "as `cavewall run` does (background decoding, default budget and upload limit, cold start); a "
                "warp-morph lasts " +
                config::formatNumber(bench::morphSecondsOn(path)) +
                " s of the path's time, the stretch a viewer walks at " +
                config::formatNumber(app::RunOptions{}.guidePace) + " m/s in `cavewall run`'s " +
                config::formatNumber(walkthrough::WalkthroughSettings{}.morphSeconds) + " s",
            "near: the near-geometry limit, the viewer's cell plus its walls as bare quads (one 1x1 texture); "
            "cells: the cells the walls mode draws as geometry, without textures; cells+layer: the same plus one "
            "textured full-screen layer per view through the wall pass (512x512 MIP-mapped sRGB, weight 0: the "
            "control's image at one wall layer's cost)",
            o.lodPixels > 0.0 ? "lod: levels of detail built when the mode starts (meshoptimizer, sampled Hausdorff "
                                "error), each object drawn at the coarsest level within " +
                                    config::formatNumber(o.lodPixels) +
                                    " px on every screen it appears on; budgets "
                                    "raise that tolerance to at most " +
                                    config::formatNumber(o.lodMaxPixels) + " px"
                              : "lod: off (--lod 0)",
            o.occlusion.on ? "occlusion culling: " + render::describe(o.occlusion) +
                                 " (every mode; GPU, two phases per view: what the view saw last frame, then what "
                                 "the depth drawn so far does not hide; the same images); triangles a frame are those "
                                 "drawn"
                           : std::string("occlusion culling: off (--no-occlusion: every mode draws what its frustum "
                                         "and cells keep)"),
            o.portalCulling
                ? "portal culling: on (walls modes and the control: each view draws other cells' objects only "
                  "where their boxes may be seen from its eye through the viewer cell's walls, open "
                  "boundary and windows, walls/cell_openings.h; --no-portal-culling: off)"
                : "portal culling: off (--no-portal-culling: neighbours drawn as geometry are drawn whole)"};
}

// `given` with the scene's own zone size and bake resolution (scene.json "planning") unless
// --min-zone or --bake-resolution gave them.
BenchOptions withScenePlanning(const BenchOptions& given, const scenes::SceneDescription& description) {
    BenchOptions o = given;
    walls::useScenePlanning(description, given.planningGiven, o.plan, o.bakeResolution);
    return o;
}

// The checks that need no file: they fail before anything is loaded.
void checkOptions(const BenchOptions& o) {
    if (o.compareEvery < 1)
        throw Error("bench: compareEvery: expected at least 1, got " + std::to_string(o.compareEvery));
    if (o.alphasDeg.empty()) throw Error("bench: expected at least one alpha for the walls modes, got none");
    if (o.frames < 1) throw Error("--frames: expected at least 1, got " + std::to_string(o.frames));
    if (o.flatBeside && o.wallKind != walls::WallKind::Depth)
        throw Error("bench: flat walls beside: expected depth walls to set them beside, got " +
                    std::string(walls::wallKindName(o.wallKind)) + " walls");
    for (double budget : o.clusterBudgetsMs)
        if (!(budget > 0.0 && std::isfinite(budget)))
            throw Error("bench: cluster budgets: expected milliseconds > 0, got " + config::formatNumber(budget));
    if (std::find(o.alphasDeg.begin(), o.alphasDeg.end(), o.transitionAlphaDeg) == o.alphasDeg.end())
        throw Error("bench: the warp alpha " + config::formatNumber(o.transitionAlphaDeg) +
                    " is not one of the planned alphas");
}

void checkOnDemand(const BenchOptions& o) {
    if (!o.onDemandCache) return;
    if (o.wallKind != walls::WallKind::Flat)
        throw Error("--on-demand: baking on demand draws flat walls only, got --walls depth");
    checkPrivateCache(*o.onDemandCache, o.cache ? *o.cache : walls::gl::defaultCacheFolder());
}

// How a mode is run. The phases run in this order, each mode of a phase in the report's order.
enum class Phase {
    Interleaved,  // full geometry, the walls and clusters modes: frame by frame in turn (the same seconds)
    Cells,        // cells, cells+layer and near: frame by frame in turn
    CellsLod,     // the control and near with levels of detail: after the Interleaved modes each frame
    Paged,        // the walls paged as `cavewall run` pages, alone
    OnDemand,     // the walls baked on demand from an empty cache, alone
};

// One mode of the report, in the report's order, and how it is run.
struct BenchMode {
    Phase phase = Phase::Interleaved;
    ModeResult mode{};                        // what it is: ModeAccumulator's mode (textures included)
    std::optional<std::size_t> alphaIndex{};  // walls modes: the walls baked at alphasDeg[*alphaIndex]
    std::optional<std::size_t> compare{};     // the compare scene it draws (index); none: the bench scene's
    bool flat = false;                        // the flat walls beside the depth walls (flatBaked)
    std::optional<std::size_t> budgetFrom{};  // its triangle budget: that mode's median (index into the table)
    CellDraw draw = CellDraw::Cells;          // the cell phases'
    std::optional<ModeResult> result{};       // once its phase has run
};

// What the phases run with; `reference` and `fullP50` come from the interleaved phase.
struct Bench {
    const BenchOptions& o;
    const display::Display& display;
    const ModeContext& c;
    const std::vector<BakedWalls>& baked;                    // per alpha
    const std::vector<BakedWalls>& flatBaked;                // per alpha: flat walls beside depth walls, or none
    const std::vector<std::vector<BakedWalls>>& otherBaked;  // per compare scene, per alpha
    const std::vector<std::unique_ptr<CompareScene>>& others;
    std::size_t transitionIndex = 0;  // of transitionAlphaDeg in alphasDeg
    ReferenceImages reference{};
    double fullP50 = 0.0;  // full geometry's (the reference's) median ms
};

// A walls mode at alphasDeg[alphaIndex] of the bench scene or of compare scene `compare`, with
// the textures of its walls.
BenchMode wallsAt(const Bench& b, std::size_t alphaIndex, const WallsModeOptions& options,
                  std::optional<std::size_t> compare = std::nullopt, Phase phase = Phase::Interleaved) {
    BenchMode m{.phase = phase,
                .mode = wallsMode(b.o.alphasDeg[alphaIndex], options),
                .alphaIndex = alphaIndex,
                .compare = compare,
                .flat = options.flat};
    m.mode.wallKind = options.flat ? walls::WallKind::Flat : b.o.wallKind;
    const BakedWalls& walls = compare        ? b.otherBaked[*compare][alphaIndex]
                              : options.flat ? b.flatBaked[alphaIndex]
                                             : b.baked[alphaIndex];
    m.mode.textures = static_cast<int>(walls.setup.plan.textures.size());
    m.mode.texels = walls.texels;
    m.mode.diskMB = walls.diskMB;
    if (compare) m.mode.sceneTag = b.o.compareScenes[*compare].tag;
    return m;
}

// The walls modes at every alpha, interleaved; returns their indices in `table`.
std::vector<std::size_t> addWallsModes(std::vector<BenchMode>& table, const Bench& b, const WallsModeOptions& options,
                                       std::optional<std::size_t> compare = std::nullopt) {
    std::vector<std::size_t> added;
    for (std::size_t i = 0; i < b.baked.size(); ++i) {
        added.push_back(table.size());
        table.push_back(wallsAt(b, i, options, compare));
    }
    return added;
}

BenchMode cellMode(Phase phase, CellDraw draw, double lodPixels) {
    const Mode mode = draw == CellDraw::Near ? Mode::Near : draw == CellDraw::Cells ? Mode::Cells : Mode::CellsLayer;
    return {.phase = phase, .mode = namedMode(mode, lodPixels), .draw = draw};
}

// The walls modes with levels of detail under a triangle budget (by default the median of the
// same mode without one, `lodModes`), then under the frame-time controller.
void addBudgetModes(std::vector<BenchMode>& table, const Bench& b, const std::vector<std::size_t>& lodModes) {
    const BenchOptions& o = b.o;
    for (std::size_t i = 0; i < b.baked.size(); ++i) {
        table.push_back(wallsAt(b, i, {.lodPixels = o.lodPixels, .triangleBudget = o.triangleBudget}));
        if (o.triangleBudget == 0) table.back().budgetFrom = lodModes[i];
    }
    if (o.frameBudgetMs > 0.0) addWallsModes(table, b, {.lodPixels = o.lodPixels, .frameBudgetMs = o.frameBudgetMs});
}

// The clusters modes: one per budget, by default one at the frame budget (60 Hz without one).
void addClusterModes(std::vector<BenchMode>& table, const BenchOptions& o) {
    std::vector<double> budgets = o.clusterBudgetsMs;
    if (budgets.empty()) budgets.push_back(o.frameBudgetMs > 0.0 ? o.frameBudgetMs : 1000.0 / 60.0);
    for (double budget : budgets) {
        ModeResult m;
        m.mode = Mode::Clusters;
        m.frameBudgetMs = budget;
        table.push_back({.mode = m});
    }
}

// Every mode of the bench in the report's order: full geometry, the cell modes, the walls
// modes, the paged and on-demand modes, then the budgeted, clusters and compare scenes' modes.
std::vector<BenchMode> planModes(const Bench& b) {
    const BenchOptions& o = b.o;
    const bool lod = o.lodPixels > 0.0;
    std::vector<BenchMode> table;
    table.push_back({.mode = namedMode(Mode::Full)});  // the reference
    if (lod) table.push_back({.mode = namedMode(Mode::Full, o.lodPixels)});
    for (CellDraw draw : {CellDraw::Cells, CellDraw::CellsLayer, CellDraw::Near})
        table.push_back(cellMode(Phase::Cells, draw, 0.0));
    if (lod)  // the control at the walls' tolerance, and the limit
        for (CellDraw draw : {CellDraw::Cells, CellDraw::Near})
            table.push_back(cellMode(Phase::CellsLod, draw, o.lodPixels));
    addWallsModes(table, b, {});
    const std::vector<std::size_t> lodModes =
        lod ? addWallsModes(table, b, {.lodPixels = o.lodPixels}) : std::vector<std::size_t>{};
    if (o.flatBeside) {  // before the (depth) warp, paged and budget modes: the last gives the noise floor
        addWallsModes(table, b, {.flat = true});
        if (lod) addWallsModes(table, b, {.lodPixels = o.lodPixels, .flat = true});
    }
    table.push_back(wallsAt(b, b.transitionIndex, {.transition = app::Transition::Warp}));
    table.push_back(wallsAt(b, b.transitionIndex, {.paged = true}, std::nullopt, Phase::Paged));
    if (o.onDemandCache) table.push_back({.phase = Phase::OnDemand, .mode = wallsMode(o.transitionAlphaDeg)});
    if (lod) addBudgetModes(table, b, lodModes);
    if (o.clusters) addClusterModes(table, o);
    for (std::size_t k = 0; k < b.others.size(); ++k) {  // the compare scenes', after all the bench scene's
        addWallsModes(table, b, {}, k);
        if (lod) addWallsModes(table, b, {.lodPixels = o.lodPixels}, k);
    }
    return table;
}

// The walkthrough run of walls, transition and paging that `m` says.
WalkRun walkRunOf(const Bench& b, const BenchMode& m, ModeAccumulator* acc) {
    WalkRun run;
    const std::vector<BakedWalls>& from = m.compare ? b.otherBaked[*m.compare] : m.flat ? b.flatBaked : b.baked;
    if (m.alphaIndex) run.walls = from[*m.alphaIndex].setup;
    if (m.flat) run.wallKind = walls::WallKind::Flat;
    if (m.compare) {
        run.scene = &b.others[*m.compare]->scene;
        run.description = &b.others[*m.compare]->description;
    }
    run.acc = acc;
    run.transition = m.mode.transition.value_or(app::Transition::Blend);
    run.paged = m.mode.paged;
    run.clusters = m.mode.mode == Mode::Clusters;
    return run;
}

// The table's modes of `phase`, in order.
std::vector<std::size_t> modesOf(const std::vector<BenchMode>& table, Phase phase) {
    std::vector<std::size_t> modes;
    for (std::size_t i = 0; i < table.size(); ++i)
        if (table[i].phase == phase) modes.push_back(i);
    return modes;
}

// The cell modes of a phase and where their frames go (stable addresses: reserved).
struct CellModeRuns {
    std::vector<std::size_t> modes;  // in the table
    std::vector<ModeAccumulator> accs;
    std::vector<CellRun> runs;
    std::string names;  // their labels
};

CellModeRuns cellRunsOf(const std::vector<BenchMode>& table, Phase phase, const Bench& b) {
    CellModeRuns r;
    r.modes = modesOf(table, phase);
    r.accs.reserve(r.modes.size());
    for (std::size_t i : r.modes) {
        r.accs.emplace_back(table[i].mode, b.display);
        r.runs.push_back({table[i].draw, &r.accs.back()});
        r.names += (r.names.empty() ? "" : ", ") + modeLabel(r.accs.back().mode());
    }
    return r;
}

void finishCellRuns(std::vector<BenchMode>& table, const CellModeRuns& r, double fullP50) {
    for (std::size_t k = 0; k < r.modes.size(); ++k) table[r.modes[k]].result = r.accs[k].finish(fullP50);
}

// Runs the walkthrough modes of `phase` (Interleaved or Paged) frame by frame in turn, and with
// the Interleaved ones the CellsLod modes after them every frame (the same seconds); the
// table's first mode (full geometry) is the reference of images and speed-ups. Returns their
// labels as the table shows them.
std::string runWalkPhase(std::vector<BenchMode>& table, Phase phase, Bench& b) {
    const std::vector<std::size_t> modes = modesOf(table, phase);
    std::vector<std::unique_ptr<ModeAccumulator>> accs;  // stable addresses for the runs
    std::vector<WalkRun> runs;
    std::vector<int> runOf(table.size(), -1);
    std::string names;
    for (std::size_t i : modes) {
        accs.push_back(std::make_unique<ModeAccumulator>(table[i].mode, b.display));
        WalkRun run = walkRunOf(b, table[i], accs.back().get());
        run.storeReference = i == 0;
        if (table[i].budgetFrom) run.budgetFrom = runOf[*table[i].budgetFrom];
        runOf[i] = static_cast<int>(runs.size());
        runs.push_back(std::move(run));
        // A triangle budget is known only after the warm-up: say where it comes from.
        names += (names.empty() ? "" : ", ") + modeLabel(accs.back()->mode()) +
                 (table[i].budgetFrom ? " budget (the median triangles of the same mode without one, after its warm-up)"
                                      : "");
    }
    CellModeRuns cells = phase == Phase::Interleaved ? cellRunsOf(table, Phase::CellsLod, b) : CellModeRuns{};
    if (!cells.names.empty()) names += ", " + cells.names;
    say(b.o, "bench: " + names + (modes.size() + cells.modes.size() > 1 ? ", frame by frame in turn" : ""));
    std::optional<CellModes> drawer;
    std::function<void(const walkthrough::FrameInput&)> alsoEachFrame;
    if (!cells.runs.empty()) {
        drawer.emplace(b.c, b.baked[b.transitionIndex].setup, b.o.lodPixels);
        drawer->warmUp(cells.runs);
        alsoEachFrame = [&](const walkthrough::FrameInput& in) { drawer->drawFrame(in, cells.runs, b.reference); };
    }
    runWalkthroughModes(b.c, runs, b.reference, alsoEachFrame);
    for (std::size_t k = 0; k < modes.size(); ++k) {
        const bool reference = modes[k] == 0;  // no speed-up
        table[modes[k]].result = accs[k]->finish(reference ? 0.0 : b.fullP50);
        if (reference) b.fullP50 = table[modes[k]].result->frameMs.p50;
    }
    finishCellRuns(table, cells, b.fullP50);
    // The labels again from the results: a triangle budget is known only after the warm-up.
    std::string labels;
    for (std::size_t i : modes) labels += (labels.empty() ? "" : ", ") + modeLabel(*table[i].result);
    return cells.names.empty() ? labels : labels + ", " + cells.names;
}

// Runs the cell modes of `phase` (Cells) frame by frame in turn, with the selection of the
// walls at transitionAlphaDeg.
void runCellPhase(std::vector<BenchMode>& table, Phase phase, Bench& b) {
    const CellModeRuns cells = cellRunsOf(table, phase, b);
    if (cells.runs.empty()) return;
    say(b.o, "bench: " + cells.names + (cells.runs.size() > 1 ? ", frame by frame in turn" : ""));
    runCellModes(b.c, b.baked[b.transitionIndex].setup, cells.runs, b.reference);
    finishCellRuns(table, cells, b.fullP50);
}

// Runs the on-demand mode (when there is one), with its header line.
void runOnDemandPhase(std::vector<BenchMode>& table, Bench& b, BenchReport& report) {
    const BenchOptions& o = b.o;
    for (std::size_t i : modesOf(table, Phase::OnDemand)) {
        say(o, "bench: walls flat a=" + config::formatNumber(o.transitionAlphaDeg) +
                   " blend on demand, from an empty cache " + o.onDemandCache->string());
        table[i].result = onDemandMode(o, o.transitionAlphaDeg, b.c, b.reference, b.fullP50);
        report.header.push_back(
            "on demand: walls at alpha " + config::formatNumber(o.transitionAlphaDeg) +
            " baked while walking (background baker at nice 10, as `cavewall run "
            "--bake-on-demand`) from an empty private cache " +
            o.onDemandCache->string() +
            ", alone after the paged mode; the first path frame drawn once first (first frame "
            "after the scene's load: planning, keying the cache, the walkthrough, that frame), then "
            "every path frame timed");
    }
}

// The noise floor of p99/p50 on this machine, beside a walls mode's, in the same seconds: the
// budget mode at the last alpha, or the paged one (the clusters mode, listed after them, is not
// a walls mode).
void addNoiseFloor(BenchReport& report, const Bench& b) {
    ModeResult last = *std::find_if(report.modes.rbegin(), report.modes.rend(), [](const ModeResult& m) {
        return m.mode == Mode::Walls && m.sceneTag.empty() && !m.onDemand;
    });
    last.paged = false;  // drawn with every texture resident, also after the paged mode
    say(b.o, "bench: noise floor, " + modeLabel(last) + " interleaved with one of its frames");
    const long middle = static_cast<long>(b.c.path.frames.size() / 2);
    const std::size_t alpha = b.o.lodPixels > 0.0 ? b.baked.size() - 1 : b.transitionIndex;
    const NoiseComparison n = interleavedNoise(b.c, b.baked[alpha].setup, last, middle);
    auto ratio = [](const TimeStats& t) { return fixed(t.p50 > 0 ? t.p99 / t.p50 : 0.0, 2); };
    report.noiseFloorRatio = n.repeated.p50 > 0 ? n.repeated.p99 / n.repeated.p50 : 0.0;
    report.noiseFloorP95Ratio = n.repeated.p50 > 0 ? n.repeated.p95 / n.repeated.p50 : 0.0;
    report.header.push_back("noise floor: " + modeLabel(last) + " along the path, each frame followed by frame " +
                            std::to_string(middle) + " again: the path's frames p50 " + fixed(n.path.p50, 2) +
                            " ms, p99/p50 " + ratio(n.path) + "; the repeated frame (the same work every time) p50 " +
                            fixed(n.repeated.p50, 2) + " ms, p99/p50 " + ratio(n.repeated) +
                            ": what the repeated frame shows is the machine's noise, not the "
                            "renderer's");
}

// Runs every phase of `table` and adds the modes to `report` in the table's order.
void runModes(std::vector<BenchMode>& table, Bench& b, BenchReport& report) {
    const std::string names = runWalkPhase(table, Phase::Interleaved, b);
    report.header.push_back("drawn frame by frame in turn (the same seconds): " + names +
                            "; then cells, cells+layer and near in turn; then the paged mode alone" +
                            (b.o.onDemandCache ? "; then the on-demand mode alone" : ""));
    // The control, the control plus one textured layer and the limit in the same seconds: the
    // wall pass's target compares them.
    runCellPhase(table, Phase::Cells, b);
    runWalkPhase(table, Phase::Paged, b);
    runOnDemandPhase(table, b, report);
    for (BenchMode& m : table) report.modes.push_back(std::move(*m.result));
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

BenchReport runBenchmark(const BenchOptions& given) {
    checkOptions(given);
    const auto start = std::chrono::steady_clock::now();
    const display::Display display(given.display);
    scenes::SceneDescription description;
    const scenes::Scene scene = scenes::loadSceneFile(given.scene, &description);
    const BenchOptions o = withScenePlanning(given, description);
    app::useRoute(description, o.route, o.scene.string());
    if (description.walls.empty())
        throw Error(o.scene.string() + ": the scene has no virtual walls (expected at least 1 to bench)");
    // Checked before anything is baked: a bad compare scene or cache folder fails at once.
    const std::vector<std::unique_ptr<CompareScene>> others = loadCompareScenes(o, scene);
    checkOnDemand(o);
    bench::EyePath path = bench::recordEyePath(scene, description, o.display, o.tracker, o.frames);
    if (o.route == app::Route::Wall)
        path.description += " (--route wall: the scene's wallPath, which hugs the virtual walls, as its walkPath)";
    const auto& first = o.display.screens.front();
    say(o, "bench: " + o.display.name + " at " + std::to_string(first.resolution.x) + " x " +
               std::to_string(first.resolution.y) + " per screen, stereo mode " +
               std::string(config::toString(o.display.stereo)));
    const auto context = display::gl::createHeadlessContext();
    BenchReport report;
    report.saveWorst = o.saveWorst;
    report.header = headerLines(o, scene, *context, path);
    if (measuresStereo(display))
        report.header.push_back(
            "stereo: both eyes drawn, every image metric computed per output image (per eye in separate mode); "
            "stereo error (metrics/stereo_error.h) per eye and pixel against full geometry, eye separation " +
            config::formatNumber(o.display.viewer.eyeSeparation) +
            " m, threshold 1 arcmin; depth read back after each compared frame is timed, virtual walls drawn again "
            "depth only (the depth each eye sees on them)");
    const auto& s0 = o.display.screens.front();
    report.resolution = std::to_string(s0.resolution.x) + "x" + std::to_string(s0.resolution.y) + " per screen, " +
                        std::string(config::toString(o.display.stereo));
    const ModeContext c{scene,
                        description,
                        display,
                        *context,
                        path,
                        o.compareEvery,
                        o.lodMaxPixels,
                        o.wallKind,
                        o.clusters ? (o.cache ? *o.cache : walls::gl::defaultCacheFolder()) : std::filesystem::path(),
                        walls::ReprojectSettings{.cutSheets = !o.keepSheets},
                        o.occlusion,
                        o.portalCulling};

    const std::vector<BakedWalls> baked = bakeOwnWalls(o, o.wallKind, scene, description, *context, report);
    const std::vector<BakedWalls> flatBaked =
        o.flatBeside ? bakeOwnWalls(o, walls::WallKind::Flat, scene, description, *context, report)
                     : std::vector<BakedWalls>{};
    const std::vector<std::vector<BakedWalls>> otherBaked = bakeCompareScenes(o, others, description, *context, report);
    const auto listed = std::find(o.alphasDeg.begin(), o.alphasDeg.end(), o.transitionAlphaDeg);  // checked on entry
    Bench b{.o = o,
            .display = display,
            .c = c,
            .baked = baked,
            .flatBaked = flatBaked,
            .otherBaked = otherBaked,
            .others = others,
            .transitionIndex = static_cast<std::size_t>(listed - o.alphasDeg.begin())};
    std::vector<BenchMode> table = planModes(b);
    runModes(table, b, report);
    if (o.lodPixels > 0.0 && o.triangleBudget == 0)
        report.header.push_back(
            "triangle budgets: per alpha, the median triangles of the same walls mode without a "
            "budget");
    addNoiseFloor(report, b);
    compareWithControl(report);
    compareWithLodBaseline(report);
    recommend(report);
    report.header.push_back(
        "control: 'cells' (the cells the walls draw as geometry, no textures); 'vs control' is "
        "every walls mode's pooled PSNR gain over it and its FLIP mean as a fraction of its, at the "
        "mode's level-of-detail tolerance ('cells lod' for the modes with levels of detail)");
    report.header.push_back("bench time: " + fixed(display::msSince(start) / 1000.0, 0) +
                            " s in total (all modes, bakes included)");
    return report;
}

}  // namespace cavewall::bench::gl
