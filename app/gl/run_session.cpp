#include "app/gl/run_session.h"

#include "config/json_reader.h"
#include "display/display.h"
#include "display/frame_budget.h"
#include "display/gl/context.h"
#include "input/navigator.h"
#include "input/recording.h"
#include "input/tracker_source.h"
#include "input/tracking_pipeline.h"
#include "hierarchy/cluster_diagram.h"
#include "scenes/image_io.h"
#include "scenes/loader.h"
#include "walkthrough/cluster_control.h"
#include "app/interrupt.h"
#include "app/run_cluster.h"
#include "app/run_input.h"
#include "app/gl/run_output.h"
#include "app/scene_query.h"
#include "app/view_overlay.h"
#include "input/session_keys.h"
#include "walls/cache_budget.h"
#include "walls/gl/background_baker.h"
#include "walls/gl/baker.h"
#include "walls/geometry_pager.h"
#include "walkthrough/gl/walkthrough.h"
#include "walls/wall_setup.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <thread>

namespace cavewall::app::gl {

using app::RunOptions;
using app::RunSummary;
using app::WindowMode;

namespace {

walls::gl::BakeRequest bakeRequest(const RunOptions& o, display::gl::Context* context) {
    walls::gl::BakeRequest request;
    request.scene = o.scene;
    request.context = context;
    request.trustStamps = true;  // the pager checks each file's content as it pages it in
    request.settings.maxResolution = o.bakeResolution;
    request.settings.kind = o.wallKind;
    request.settings.textureFormat = o.textureFormat;
    if (o.cache) request.cache = *o.cache;
    return request;
}

// What the walls were planned and baked with, for the "walls:" line.
std::string planningNote(const RunOptions& o) {
    return "; zones of at least " + config::formatNumber(o.plan.minZoneSize) + " m, textures of at most " +
           std::to_string(o.bakeResolution) + " texels (--min-zone, --max-res, else the scene's \"planning\")";
}

// --bake-on-demand: plans the walls and takes what the cache holds; the baker bakes the rest in
// the background with a context of its own.
walls::WallSetup prepareWallsOnDemand(const RunOptions& o, const scenes::Scene& scene,
                                      const scenes::SceneDescription& d,
                                      std::unique_ptr<walls::gl::BackgroundBaker>& baker) {
    walls::WallSetup setup = walls::prepareWalls(scene, d, walls::planOptionsFor(o.plan, o.wallKind, o.bakeResolution));
    walls::gl::BackgroundBakerOptions options;
    options.niceness = o.bakeNice;
    if (o.cacheBudgetMB > 0.0) options.cacheBudgetBytes = walls::cacheBudgetBytes(o.cacheBudgetMB, "--cache-budget");
    baker = std::make_unique<walls::gl::BackgroundBaker>(scene, d, setup, bakeRequest(o, nullptr), options);
    for (const std::string& w : baker->startWarnings()) std::cerr << "run: warning: " << w << std::endl;
    setup.folder = baker->folder();
    setup.manifest = baker->manifest();
    if (o.verbose)
        std::cout << "walls: " << setup.plan.textures.size() << " textures in " << setup.folder.string() << " ("
                  << setup.manifest.textures.size() << " in the cache, " << baker->stats().missingAtStart
                  << " to bake while walking)" << planningNote(o) << "\n";
    return setup;
}

// Why the session ends before drawing a frame, asked between stages and between textures of a
// bake: a window closed, the quit keys (Escape twice, Ctrl+Q), Ctrl+C or SIGTERM.
struct StopCheck {
    display::gl::Context& context;
    input::SessionKeys keys{};
    std::optional<app::Ending> ending{};

    bool operator()() {
        if (ending) return true;
        for (const input::Event& e : context.takeInputEvents()) keys.handle(e);
        if (context.windowCount() > 0 && context.pollCloseRequested()) ending = app::Ending::WindowClosed;
        if (keys.quitRequested()) ending = app::Ending::Quit;
        if (app::interruptSignal() != 0) ending = app::Ending::Interrupted;
        return ending.has_value();
    }
};

// Prepares the walls and bakes (or finds in the cache) their textures. Stops between textures
// when `stop` says so (the finished textures stay in the cache).
walls::WallSetup prepareWalls(const RunOptions& o, const scenes::Scene& scene, const scenes::SceneDescription& d,
                              display::gl::Context& context, StopCheck* stop) {
    walls::WallSetup setup = walls::prepareWalls(scene, d, walls::planOptionsFor(o.plan, o.wallKind, o.bakeResolution));
    walls::gl::BakeRequest request = bakeRequest(o, &context);
    if (stop) request.stop = [stop] { return (*stop)(); };
    request.progress = [&o, &context](const walls::gl::BakeProgress& p) {
        const int windows = std::min(context.windowCount(), static_cast<int>(o.display.screens.size()));
        for (int w = 0; w < windows && p.baked > 0; ++w)
            context.setTitle(w, "cavewall - " + o.display.screens[w].name + " - baking wall textures " +
                                    std::to_string(p.done) + " of " + std::to_string(p.total));
        if (o.verbose && p.baked > 0 && (p.done % 10 == 0 || p.done == p.total))
            std::cout << "bake: " << p.done << "/" << p.total << " textures (" << p.baked << " baked) "
                      << std::lround(p.seconds) << " s\n"
                      << std::flush;
    };
    walls::gl::BakeResult baked = walls::gl::bakeWalls(scene, d, setup, request);
    for (const std::string& w : baked.warnings) std::cerr << "run: warning: " << w << std::endl;
    setup.folder = baked.folder;
    setup.manifest = std::move(baked.manifest);
    if (o.verbose)
        std::cout << "walls: " << setup.plan.textures.size() << " textures in " << setup.folder.string() << " ("
                  << baked.baked << " baked now, " << baked.reused << " reused"
                  << (baked.stopped ? "; stopped before the rest" : "") << ")" << planningNote(o) << "\n";
    return setup;
}

std::unique_ptr<display::gl::Context> makeContext(const RunOptions& o, const display::Display& display) {
    bool windowed = o.window == WindowMode::Window;
    if (o.window == WindowMode::Auto) windowed = display::gl::windowSystemAvailable();
    if (windowed) {
        const std::string why = display::gl::windowsUnavailableReason();
        if (!why.empty()) throw Error("--window: " + why);
        return display::gl::createWindowedContext(display::gl::windowRequests(display), false);
    }
    return display::gl::createHeadlessContext();
}

// In cluster mode rank 0 plans and bakes first and the others then find everything in the
// cache (one bake per cache folder at a time). They wait for rank 0 up to kBakeWaitSeconds; a
// rank that stopped meanwhile is found by the barrier after it, within --cluster-timeout.
constexpr double kBakeWaitSeconds = 3600.0;

walls::WallSetup prepareWallsOnce(const RunOptions& o, const scenes::Scene& scene, const scenes::SceneDescription& d,
                                  display::gl::Context& context, app::Cluster* cluster, StopCheck& stop) {
    if (!cluster) return prepareWalls(o, scene, d, context, &stop);
    std::optional<walls::WallSetup> setup;
    if (cluster->rank() == 0) setup = prepareWalls(o, scene, d, context, nullptr);
    cluster->waitForRankZero(kBakeWaitSeconds, "waiting for rank 0 to bake the wall textures");
    cluster->barrier(o.clusterTimeout, "every rank after rank 0's bake");
    if (cluster->rank() != 0) {
        RunOptions quiet = o;
        quiet.verbose = false;
        setup = prepareWalls(quiet, scene, d, context, nullptr);
    }
    // The other ranks plan again after the bake; the first frame's broadcast (bounded by
    // --cluster-timeout) waits for the slowest of them here instead.
    cluster->barrier(kBakeWaitSeconds, "waiting for every rank to prepare the walls");
    return std::move(*setup);
}

// The walls the session draws: none in cluster mode, without walls or in a scene without them;
// the plan alone for the control (no textures, nothing baked); planned and baked while walking
// by `baker` (--bake-on-demand); or planned and baked now, until `stop` says so.
std::optional<walls::WallSetup> sessionWalls(const RunOptions& o, const scenes::Scene& scene,
                                             const scenes::SceneDescription& d, display::gl::Context& context,
                                             app::Cluster* cluster, std::unique_ptr<walls::gl::BackgroundBaker>& baker,
                                             StopCheck& stop) {
    if (!o.walls || o.clusters || d.walls.empty()) return std::nullopt;
    if (!o.wallTextures)  // the control draws no texture: the plan alone, nothing baked
        return walls::prepareWalls(scene, d, walls::planOptionsFor(o.plan, o.wallKind, o.bakeResolution));
    if (o.bakeOnDemand) return prepareWallsOnDemand(o, scene, d, baker);
    return prepareWallsOnce(o, scene, d, context, cluster, stop);
}

walkthrough::gl::WalkthroughOptions walkthroughOptions(const RunOptions& o, walls::gl::BackgroundBaker* baker) {
    walkthrough::gl::WalkthroughOptions options;
    options.synchronousPaging = o.synchronousPaging;
    options.wallTextures = o.wallTextures;
    options.textureBudgetMB = o.textureBudgetMB;
    options.geometryBudgetMB = o.geometryBudgetMB;
    options.transition = o.transition;
    options.wallKind = o.wallKind;
    options.depthMarch.cutSheets = !o.keepSheets;
    options.baker = baker;
    options.render.lodPixels = o.lodPixels;
    options.render.occlusion = o.occlusion;
    options.portalCulling = o.portalCulling;
    options.triangleBudget = o.triangleBudget;
    options.lodMaxPixels = std::max(o.lodMaxPixels, o.lodPixels);
    options.clusters.enabled = o.clusters;
    if (o.clusters) {
        options.clusters.divisions = {o.clusterDivisions, std::max(1, o.clusterDivisions / 4), o.clusterDivisions};
        options.clusters.bake.resolution = o.clusterResolution;
        options.clusters.fadeFrames = o.clusterFadeFrames;
        options.clusters.cache = o.cache ? *o.cache : walls::gl::defaultCacheFolder();
        if (o.frameBudgetMs > 0.0) options.clusters.budgetMs = o.frameBudgetMs;
    }
    return options;
}

// What the walkthrough was made with: walls or not, the clusters' bake and costs, and the sizes
// geometry paging is judged by (resident at most the largest three cells).
void summarizeWalkthrough(const walkthrough::gl::Walkthrough& walkthrough, RunSummary& summary) {
    summary.walls = walkthrough.hasWalls();
    if (const hierarchy::ClusterModel* m = walkthrough.clusterModel()) {
        const hierarchy::gl::ClusterBakeStats& b = *walkthrough.clusterBakeStats();
        summary.clusters = b.clusters;
        summary.clustersMade = b.made;
        summary.clustersReused = b.reused;
        summary.clustersSeconds = b.seconds;
        for (const std::string& w : b.warnings) std::cerr << "run: warning: " << w << std::endl;
        summary.msPerTriangle = m->costs.msPerTriangle;
        summary.msPerObject = m->costs.msPerObject;
        summary.texturedBoxMs = m->costs.texturedBoxMs;
        summary.averageBoxMs = m->costs.averageBoxMs;
        summary.texturedViewMs = m->costs.texturedViewMs;
        summary.averageViewMs = m->costs.averageViewMs;
        summary.costResolution = walkthrough.clusterCostResolution();
    }
    const walkthrough::gl::GeometryYardsticks yardsticks = walkthrough.geometryYardsticks();
    summary.largestThreeCellsMB = yardsticks.largestThreeCellsMB;
    summary.modelGeometryMB = yardsticks.wholeModelMB;
    summary.sharedGeometryMB = yardsticks.sharedMB;
}

// What the frame loop drives. Rank 0 alone has input and output.
struct Session {
    const RunOptions& o;
    display::gl::Context& context;
    app::RunInput* input = nullptr;               // rank 0
    app::Cluster* cluster = nullptr;              // cluster mode
    walls::gl::BackgroundBaker* baker = nullptr;  // --bake-on-demand
    walkthrough::gl::Walkthrough& walkthrough;
    RunOutput* output = nullptr;      // rank 0
    const std::vector<int>& screens;  // this rank's, cluster mode
    std::chrono::steady_clock::time_point start;
};

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Rank 0: frame i's saved images, and with clusters the diagram of what it drew from above
// (Maciel & Shirley (1995), Figure D).
void saveFrameImages(const Session& s, long i, const walkthrough::FrameInput& in, walkthrough::FrameResult& r,
                     RunSummary& summary) {
    summary.foldouts.push_back(s.output->saveImages(i, r.images, r.warpedImages));
    if (s.walkthrough.hasClusters())
        scenes::writeImage(
            summary.foldouts.back().parent_path() / "clusters.png",
            hierarchy::clusterDiagram(*s.walkthrough.clusterModel(), *s.walkthrough.lastClusterPlan(), r.eyeWorld));
    if (s.o.keepSavedImages) summary.savedFrames.push_back({i, in.head.position, std::move(r.images)});
}

// Rank 0: what the windows showed at a saved frame (overlay included), beside its images.
void saveWindowImages(const Session& s, const std::filesystem::path& frameFolder) {
    const int windows = std::min(s.context.windowCount(), static_cast<int>(s.o.display.screens.size()));
    for (int w = 0; w < windows; ++w)
        if (std::optional<scenes::Image> shown = s.context.takeWindowCapture(w))
            scenes::writeImage(frameFolder / ("window-" + s.o.display.screens[w].name + ".png"), *shown);
}

// Rank 0: writes frame i (when there is an output folder) and adds it to the summary.
void recordFrame(const Session& s, long i, const walkthrough::FrameInput& in, walkthrough::FrameResult& r,
                 double syncMs, RunSummary& summary) {
    const glm::dvec3 view(in.worldFromCave * glm::dvec4(in.head.orientation * glm::dvec3(0.0, 0.0, -1.0), 0.0));
    if (s.output) s.output->writeFrame(i, in.time, in.head.position, r, syncMs, view);
    if (in.readImages && s.output) saveFrameImages(s, i, in, r, summary);
    if (in.readImages && s.output && s.o.saveWindow) saveWindowImages(s, summary.foldouts.back().parent_path());
    summary.frameMs.push_back(r.frameMs);
    summary.worstErrorDeg = std::max(summary.worstErrorDeg, r.maxErrorDeg);
    summary.worstErrorPx = std::max(summary.worstErrorPx, r.maxErrorPixels);
    summary.worstLodErrorPx = std::max(summary.worstLodErrorPx, r.lodErrorPx);
    summary.misses = r.pager.misses;
    summary.pageIns = r.pager.pageIns;
    summary.checkFailures = r.pager.checkFailures;
    for (const std::string& w : r.warnings) std::cerr << "run: warning: " << w << std::endl;
    summary.geometryPeakMB = std::max(summary.geometryPeakMB, r.geometry.residentMB);
    summary.geometryMisses = r.geometry.misses;
    summary.geometryPageIns = r.geometry.pageIns;
    summary.geometryForced += r.geometryForced;
    if (s.o.verbose && s.o.frames > 0 && (i + 1) % 60 == 0)
        std::cout << "frame " << i + 1 << "/" << s.o.frames << ": " << r.frameMs << " ms\n" << std::flush;
}

// Why the session ends before its next frame, if it does: a window closed, the quit keys,
// Ctrl+C.
std::optional<app::Ending> endBeforeFrame(const Session& s, const input::SessionKeys& keys) {
    if (s.context.windowCount() > 0 && s.context.pollCloseRequested()) return app::Ending::WindowClosed;
    if (keys.quitRequested()) return app::Ending::Quit;
    if (app::interruptSignal() != 0) return app::Ending::Interrupted;
    return std::nullopt;
}

// What the walls draw, for the overlay.
std::string_view drawingName(const Session& s) {
    if (s.walkthrough.hasClusters()) return "hierarchy";
    if (!s.walkthrough.hasWalls()) return "geometry";
    return s.o.wallTextures ? "walls" : "control";
}

// Each window's title and overlay for the coming frame (rank 0, which navigates), from the last
// frame's result.
void showStatus(const Session& s, const input::SessionKeys& keys, const walkthrough::FrameResult& last) {
    if (!s.input || s.context.windowCount() == 0) return;
    app::ViewStatus status{.navigation = s.input->navigationName(),
                           .speed = s.input->speed(),
                           .frameMs = last.frameMs,
                           .help = keys.helpShown(),
                           .drawing = drawingName(s),
                           .texturesToBake = last.texturesToBake,
                           .texturesBaked = last.texturesBaked,
                           .tracker = s.input->trackerState()};
    const display::OverlayText overlay = app::viewOverlay(status);
    const int windows = std::min(s.context.windowCount(), static_cast<int>(s.o.display.screens.size()));
    for (int w = 0; w < windows; ++w) {
        s.context.setTitle(w, app::windowTitle(s.o.display.screens[w].name, status.navigation));
        s.context.setOverlay(w, overlay);
    }
}

// Draws the session's frames (until a window is closed), each held to the frame budget.
void runFrames(const Session& s, RunSummary& summary) {
    const RunOptions& o = s.o;
    // Levels of detail are held to the frame time by triangles (display/frame_budget.h),
    // clusters by predicted milliseconds (hierarchy/cluster_budget.h).
    std::optional<display::FrameTimeBudget> frameBudget;
    std::optional<hierarchy::ClusterBudget> clusterBudget;
    if (o.frameBudgetMs > 0.0 && !o.clusters) frameBudget.emplace(o.frameBudgetMs);
    if (o.frameBudgetMs > 0.0 && o.clusters) clusterBudget.emplace(o.frameBudgetMs);
    input::SessionKeys keys;
    walkthrough::FrameResult last;  // the previous frame's figures, for the overlay
    for (long i = 0; o.frames == 0 || i < o.frames; ++i) {
        const bool save = o.saveEvery > 0 && i % o.saveEvery == 0;
        const std::vector<input::Event> events = s.context.takeInputEvents();
        for (const input::Event& e : events) keys.handle(e);
        if (const std::optional<app::Ending> end = endBeforeFrame(s, keys)) {
            summary.ending = *end;
            break;
        }
        walkthrough::FrameInput in = s.input ? s.input->next(i, save, events) : walkthrough::FrameInput{};
        showStatus(s, keys, last);
        for (int w = 0; save && o.saveWindow && w < s.context.windowCount(); ++w) s.context.requestWindowCapture(w);
        if (frameBudget) in.triangleBudget = frameBudget->budget();
        if (clusterBudget) in.clusterBudgetMs = walkthrough::clusterBudgetFor(*clusterBudget);
        double syncMs = s.cluster ? app::receiveFrame(*s.cluster, in) : 0.0;
        if (s.baker && o.bakeInterleave > 0) s.baker->pause((i / o.bakeInterleave) % 2 == 1);
        walkthrough::FrameResult r = s.walkthrough.renderFrame(in);
        if (i == 0) summary.firstFrameSeconds = secondsSince(s.start);
        if (s.cluster) syncMs = app::combineFrame(*s.cluster, r, syncMs, s.screens);
        // Rank 0: the slowest rank's time.
        if (frameBudget) frameBudget->update(r.frameMs, r.geometryTriangles);
        if (clusterBudget) walkthrough::controlClusters(*clusterBudget, r);
        if (s.input) recordFrame(s, i, in, r, syncMs, summary);
        last.frameMs = r.frameMs;
        last.texturesToBake = r.texturesToBake;
        last.texturesBaked = r.texturesBaked;
    }
}

// --bake-on-demand: stops the baker (the bake in progress finishes and is counted) and adds
// its figures to the summary.
void summarizeBaker(walls::gl::BackgroundBaker& baker, RunSummary& summary) {
    baker.stop();
    const walls::gl::BackgroundBakeStats b = baker.stats();
    summary.texturesMissingAtStart = b.missingAtStart;
    summary.texturesBaked = b.baked;
    summary.texturesStillMissing = b.missing;
    summary.cacheEvictions = b.evictions;
    summary.cacheMB = b.cacheMB;
    summary.bakeWarnings = b.warnings;
}

// `given` with the scene's own zone size and bake resolution (scene.json "planning") unless
// --min-zone or --max-res gave them.
RunOptions withScenePlanning(const RunOptions& given, const scenes::SceneDescription& description) {
    RunOptions o = given;
    walls::useScenePlanning(description, given.planningGiven, o.plan, o.bakeResolution);
    return o;
}

}  // namespace

RunSummary runSession(const RunOptions& given) {
    const auto start = std::chrono::steady_clock::now();
    app::validate(given);
    const display::Display display(given.display);
    scenes::SceneDescription description;
    const scenes::Scene scene = scenes::loadSceneFile(given.scene, &description, given.sceneTextures);
    const RunOptions o = withScenePlanning(given, description);
    for (const std::string& note : scene.notes) std::cerr << "run: " << note << std::endl;
    app::useRoute(description, o.route, o.scene.string());
    RunSummary summary;
    summary.sceneSeconds = secondsSince(start);
    std::unique_ptr<app::Cluster> cluster = app::openCluster(o);
    const int rank = cluster ? cluster->rank() : 0;
    if (cluster) cluster->expectSame(app::sessionFingerprint(o, scene, description), "--cluster");
    // Only rank 0 reads input (a network tracker binds its port once).
    std::unique_ptr<app::RunInput> input = rank == 0 ? std::make_unique<app::RunInput>(o, scene, description) : nullptr;
    if (input && !input->liveTrackerLine().empty()) std::cerr << "run: " << input->liveTrackerLine() << std::endl;
    const auto context = makeContext(o, display);

    // The output files exist from here on, so a session stopped while baking leaves them complete.
    std::unique_ptr<RunOutput> output =
        rank == 0 && !o.out.empty() ? std::make_unique<RunOutput>(o.out, description, display) : nullptr;
    summary.renderer = context->info().renderer;
    StopCheck stop{.context = *context};
    std::unique_ptr<walls::gl::BackgroundBaker> baker;  // --bake-on-demand; outlives the walkthrough
    std::optional<walls::WallSetup> setup =
        stop() ? std::nullopt : sessionWalls(o, scene, description, *context, cluster.get(), baker, stop);
    summary.textures = setup ? static_cast<int>(setup->plan.textures.size()) : 0;
    summary.wallsSeconds = secondsSince(start);
    if (stop()) {
        summary.ending = *stop.ending;
        if (output) output->close();
        summary.rank = rank;
        return summary;
    }
    const std::vector<int> screens =
        cluster ? config::screensOfRank(o.display, rank, cluster->size()) : std::vector<int>{};
    walkthrough::gl::Walkthrough walkthrough(scene, description, display, *context, std::move(setup),
                                             walkthroughOptions(o, baker.get()), screens);

    summary.readySeconds = secondsSince(start);
    summarizeWalkthrough(walkthrough, summary);
    const Session session{.o = o,
                          .context = *context,
                          .input = input.get(),
                          .cluster = cluster.get(),
                          .baker = baker.get(),
                          .walkthrough = walkthrough,
                          .output = output.get(),
                          .screens = screens,
                          .start = start};
    runFrames(session, summary);
    if (output) output->close();
    if (baker) summarizeBaker(*baker, summary);
    summary.rank = rank;
    return summary;
}

}  // namespace cavewall::app::gl
