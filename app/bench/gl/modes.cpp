#include "app/bench/gl/modes.h"

#include "display/frame_budget.h"

#include <cmath>
#include "display/timing.h"
#include "walkthrough/cluster_control.h"
#include "hierarchy/cluster_frame.h"
#include "render/lod_choice.h"

#include <algorithm>
#include <cassert>
#include <memory>
#include <chrono>

namespace cavewall::bench::gl {

using namespace bench;

double trianglesCulled(const std::optional<render::gl::OcclusionCounts>& counts) {
    return counts ? static_cast<double>(counts->trianglesSubmitted - counts->trianglesDrawn) : 0.0;
}

bool compared(const ModeContext& c, long frame) { return frame % c.compareEvery == 0; }

namespace {

// Walls that drew the textures they drew last because the wanted ones were not resident
// (walkthrough/frame_planner.h, step 3): flagged fallback, with textures.
int keptFallbacks(const walkthrough::FrameResult& r) {
    int kept = 0;
    for (const walkthrough::WallState& w : r.walls) kept += w.fallback && !w.textures.empty() ? 1 : 0;
    return kept;
}

FrameCost frameCost(const walkthrough::FrameResult& r) {
    return {r.frameMs,
            r.cpuMs,
            r.gpuMs,
            static_cast<double>(r.stats.triangles),
            static_cast<double>(r.stats.drawCalls),
            r.maxErrorDeg,
            r.maxErrorPixels,
            r.pager.residentMB,
            r.pager.misses,
            r.perScreen,
            r.lodErrorPx,
            r.lodTolerancePx,
            r.lodOverBudget,
            r.texturesOverAlpha,
            static_cast<double>(r.uploadedBytes) / 1e6,
            r.clusterPredictedMs,
            r.clusterPredictedFrameMs,
            r.clusterFloorMs,
            r.geometryFallbacks,
            keptFallbacks(r),
            r.texturesBaked};
}

}  // namespace

ModeAccumulator::ModeAccumulator(ModeResult mode, const display::Display& display)
    : _mode(std::move(mode)), _display(display), _errors(display.screens().size()),
      _screenStereo(display.screens().size()), _screenCpu(display.screens().size()),
      _screenTriangles(display.screens().size()), _screenDrawCalls(display.screens().size()) {
    _mode.screens.clear();
    for (const auto& s : display.screens()) {
        ScreenResult screen;
        screen.screen = s.name;
        _mode.screens.push_back(std::move(screen));
    }
}

void ModeAccumulator::addFrame(const FrameCost& cost) {
    _mode.frames.push_back({cost.frameMs, cost.triangles, cost.drawCalls, cost.uploadedMB, cost.texturesOverAlpha,
                            cost.clusterPredictedMs, cost.clusterPredictedFrameMs, cost.clusterFloorMs,
                            cost.geometryFallbacks, cost.keptFallbacks, cost.texturesBaked});
    _mode.texturesOverAlpha += cost.texturesOverAlpha;
    _frame.push_back(cost.frameMs);
    _cpu.push_back(cost.cpuMs);
    _gpu.push_back(cost.gpuMs);
    _triangles += cost.triangles;
    _drawCalls += cost.drawCalls;
    _mode.maxErrDeg = std::max(_mode.maxErrDeg, cost.errorDeg);
    _mode.maxErrPx = std::max(_mode.maxErrPx, cost.errorPx);
    _mode.gpuMB = std::max(_mode.gpuMB, cost.residentMB);
    _mode.misses = std::max(_mode.misses, cost.misses);
    _mode.maxLodErrPx = std::max(_mode.maxLodErrPx, cost.lodErrorPx);
    _lodTolerance += cost.lodTolerancePx;
    _mode.overBudgetFrames += cost.overBudget ? 1 : 0;
    for (std::size_t i = 0; i < cost.perScreen.size() && i < _screenCpu.size(); ++i) {
        _screenCpu[i].push_back(cost.perScreen[i].cpuMs);
        _screenTriangles[i] += static_cast<double>(cost.perScreen[i].triangles);
        _screenDrawCalls[i] += cost.perScreen[i].drawCalls;
    }
}

std::vector<ComparedImage> comparedImages(const display::Display& display, const display::HeadPose& head,
                                          const std::vector<scenes::ScreenImage>& images,
                                          const std::vector<scenes::ScreenImage>& reference, const std::string& mode) {
    if (images.size() != reference.size())
        throw Error("bench: mode " + mode + " read " + std::to_string(images.size()) +
                    " images, expected the reference's " + std::to_string(reference.size()));
    std::vector<ComparedImage> compared;
    for (std::size_t i = 0; i < images.size(); ++i) {
        const int screen = images[i].screen;
        if (screen < 0 || screen >= static_cast<int>(display.screens().size())) continue;
        const scenes::Image& pixels = images[i].pixels;
        const display::ViewScreen view =
            display::viewScreen(display.quad(screen), head.position, {pixels.width, pixels.height});
        const double ppd = std::clamp(display::minPixelsPerDegree(view), 1.0, 1000.0);
        compared.push_back({screen, images[i].image, &pixels, &reference[i].pixels, ppd});
    }
    return compared;
}

void ModeAccumulator::compare(long frame, const display::HeadPose& head, const std::vector<scenes::ScreenImage>& images,
                              const std::vector<walkthrough::ViewDepth>& depths, const ReferenceFrame& reference) {
    _errors.addFrame(frame, comparedImages(_display, head, images, reference.images, modeLabel(_mode)));
    if (measuresStereo(_display)) compareDepths(depths, reference.depths);
}

namespace {

metrics::DepthImage depthImage(const walkthrough::ViewDepth& d, const std::string& name) {
    return {name, d.width, d.height, d.metres};
}

}  // namespace

metrics::StereoError addStereoError(const display::Display& display, const std::string& mode,
                                    const std::vector<walkthrough::ViewDepth>& depths,
                                    const std::vector<walkthrough::ViewDepth>& reference,
                                    std::vector<metrics::StereoError>& screens) {
    if (depths.size() != reference.size())
        throw Error("bench: mode " + mode + " read " + std::to_string(depths.size()) +
                    " depth views, expected the reference's " + std::to_string(reference.size()));
    const metrics::StereoErrorOptions options{.interocularMetres = display.config().viewer.eyeSeparation};
    metrics::StereoError sum;
    for (std::size_t i = 0; i < depths.size(); ++i) {
        const walkthrough::ViewDepth &d = depths[i], &r = reference[i];
        if (d.screen != r.screen || d.image != r.image || d.eye != r.eye || d.screen < 0 ||
            d.screen >= static_cast<int>(screens.size()))
            throw Error("bench: mode " + mode + ": depth view " + std::to_string(i) + " is screen " +
                        std::to_string(d.screen) + " eye " + display::toString(d.eye) +
                        ", expected the reference's screen " + std::to_string(r.screen) + " eye " +
                        display::toString(r.eye));
        const std::string view = display.screens()[d.screen].name + " " + display::toString(d.eye);
        const metrics::StereoError e =
            metrics::stereoError(depthImage(d, mode + " " + view), depthImage(r, "full " + view), options);
        sum += e;
        screens[d.screen] += e;
    }
    return sum;
}

void ModeAccumulator::compareDepths(const std::vector<walkthrough::ViewDepth>& depths,
                                    const std::vector<walkthrough::ViewDepth>& reference) {
    _stereo += addStereoError(_display, modeLabel(_mode), depths, reference, _screenStereo);
}

bool measuresStereo(const display::Display& display) {
    return display.isStereo() && display.config().stereo != config::StereoMode::Anaglyph;
}

bool readsDepth(const ModeContext& c) { return measuresStereo(c.display); }

ModeResult ModeAccumulator::finish(double fullP50) const {
    ModeResult m = _mode;
    m.frameMs = timeStats(_frame);
    m.cpuMs = timeStats(_cpu);
    m.gpuMs = timeStats(_gpu);
    const double n = std::max<double>(1.0, static_cast<double>(_frame.size()));
    m.triangles = _triangles / n;
    m.drawCalls = _drawCalls / n;
    m.meanLodTolerancePx = _lodTolerance / n;
    m.speedup = fullP50 > 0.0 && m.frameMs.p50 > 0.0 ? fullP50 / m.frameMs.p50 : 1.0;
    std::vector<double> triangles;
    for (const FrameSample& f : m.frames) triangles.push_back(f.triangles);
    const TimeStats load = timeStats(triangles);
    m.loadRatio = load.p50 > 0.0 ? load.p99 / load.p50 : 0.0;
    std::vector<double> uploads;
    for (const FrameSample& f : m.frames) uploads.push_back(f.uploadedMB);
    m.uploadedMB = timeStats(uploads);
    m.error = _errors.result();
    m.error.stereoMeasured = measuresStereo(_display);
    m.error.stereo = _stereo;
    m.flipWorst = _errors.worstFlip();
    m.comparedImages = _errors.images();
    for (std::size_t s = 0; s < m.screens.size(); ++s) {
        m.screens[s].error = _errors.screenResult(s);
        m.screens[s].error.stereoMeasured = measuresStereo(_display);
        m.screens[s].error.stereo = _screenStereo[s];
        m.screens[s].cpuMs = timeStats(_screenCpu[s]);
        m.screens[s].triangles = _screenTriangles[s] / n;
        m.screens[s].drawCalls = _screenDrawCalls[s] / n;
    }
    return m;
}

void runWalkthroughModes(const ModeContext& c, std::vector<WalkRun>& runs, ReferenceImages& reference,
                         const std::function<void(const walkthrough::FrameInput&)>& alsoEachFrame) {
    struct Live {
        std::unique_ptr<walkthrough::gl::Walkthrough> walkthrough;
        std::optional<display::FrameTimeBudget> frameBudget;    // levels of detail: triangles
        std::optional<hierarchy::ClusterBudget> clusterBudget;  // clusters: predicted ms
        std::vector<double> warmTriangles;                      // submitted (what a triangle budget caps)
        double culled = 0.0;  // by occlusion culling in the last frame (trianglesCulled)
    };
    std::vector<Live> live(runs.size());
    auto render = [](Live& l, walkthrough::FrameInput in) {  // as app/gl/run_session.cpp
        if (l.frameBudget) in.triangleBudget = l.frameBudget->budget();
        if (l.clusterBudget) in.clusterBudgetMs = walkthrough::clusterBudgetFor(*l.clusterBudget);
        walkthrough::FrameResult r = l.walkthrough->renderFrame(in);
        l.culled = trianglesCulled(l.walkthrough->readOcclusionCounts());
        if (l.frameBudget) l.frameBudget->update(r.frameMs, r.geometryTriangles);
        if (l.clusterBudget) walkthrough::controlClusters(*l.clusterBudget, r);
        return r;
    };
    const long frames = static_cast<long>(c.path.frames.size());
    for (std::size_t i = 0; i < runs.size(); ++i) {
        WalkRun& run = runs[i];
        Live& l = live[i];
        if (run.budgetFrom >= 0) {
            const auto& t = live.at(static_cast<std::size_t>(run.budgetFrom)).warmTriangles;
            run.acc->setTriangleBudget(
                std::max<std::size_t>(1, t.empty() ? 1 : static_cast<std::size_t>(display::median(t))));
        }
        const ModeResult& mode = run.acc->mode();
        walkthrough::gl::WalkthroughOptions options;
        options.transition = run.transition;
        options.morphSeconds = morphSecondsOn(c.path);
        options.render.lodPixels = mode.lodPixels;
        options.render.occlusion = c.occlusion;
        options.portalCulling = c.portalCulling;
        options.triangleBudget = mode.triangleBudget;
        options.lodMaxPixels = c.lodMaxPixels;
        options.wallKind = run.wallKind.value_or(c.wallKind);
        options.depthMarch = c.depthMarch;
        options.clusters.enabled = run.clusters;
        options.clusters.cache = c.clusterCache;
        if (mode.frameBudgetMs > 0.0) options.clusters.budgetMs = mode.frameBudgetMs;
        if (!run.paged) {
            options.synchronousPaging = true;
            options.textureBudgetMB = 4096.0;  // every texture of the path stays resident after warm-up
            options.uploadMBPerFrame = 4096.0;
        }
        const bool hasWalls = run.walls.has_value();
        assert((run.scene == nullptr) == (run.description == nullptr));
        l.walkthrough = std::make_unique<walkthrough::gl::Walkthrough>(
            run.scene ? *run.scene : c.scene, run.description ? *run.description : c.description, c.display, c.context,
            run.walls, options);
        if (mode.frameBudgetMs > 0.0 && !run.clusters) l.frameBudget.emplace(mode.frameBudgetMs);
        if (mode.frameBudgetMs > 0.0 && run.clusters) l.clusterBudget.emplace(mode.frameBudgetMs);
        // Warm-up: shaders, buffers and (with walls, unless paged) every texture of the path made
        // resident; the whole path too for a run whose triangles set a later run's budget.
        bool budgetSource = false;
        for (const WalkRun& other : runs) budgetSource = budgetSource || other.budgetFrom == static_cast<int>(i);
        const long warmUp = !run.paged && (hasWalls || budgetSource) ? frames : std::min<long>(3, frames);
        for (long f = 0; f < warmUp; ++f)
            l.warmTriangles.push_back(static_cast<double>(render(l, c.path.frames[f]).stats.triangles));
        if (!run.paged && hasWalls) l.walkthrough->waitForTextures();
    }
    for (const walkthrough::FrameInput& frame : c.path.frames) {
        walkthrough::FrameInput in = frame;
        in.readImages = compared(c, in.frame);
        in.readDepth = in.readImages && readsDepth(c);
        for (std::size_t i = 0; i < runs.size(); ++i) {
            walkthrough::FrameResult r = render(live[i], in);
            FrameCost cost = frameCost(r);
            cost.triangles -= live[i].culled;
            runs[i].acc->addFrame(cost);
            if (!in.readImages) continue;
            if (runs[i].storeReference)
                reference[in.frame] = {std::move(r.images), std::move(r.depths)};
            else
                runs[i].acc->compare(in.frame, in.head, r.images, r.depths, reference.at(in.frame));
        }
        if (alsoEachFrame) alsoEachFrame(in);
    }
}

double runOnDemandMode(const ModeContext& c, walls::WallSetup walls, walls::gl::BackgroundBaker& baker,
                       ModeAccumulator& acc, const ReferenceImages& reference,
                       std::chrono::steady_clock::time_point start) {
    walkthrough::gl::WalkthroughOptions options;  // background paging at `cavewall run`'s defaults
    options.baker = &baker;
    options.wallKind = c.wallKind;
    options.depthMarch = c.depthMarch;
    options.render.occlusion = c.occlusion;
    options.portalCulling = c.portalCulling;
    walkthrough::gl::Walkthrough walkthrough(c.scene, c.description, c.display, c.context, std::move(walls), options);
    if (c.path.frames.empty()) return display::msSince(start) / 1000.0;
    walkthrough.renderFrame(c.path.frames.front());
    const double firstFrameSeconds = display::msSince(start) / 1000.0;
    for (const walkthrough::FrameInput& frame : c.path.frames) {
        walkthrough::FrameInput in = frame;
        in.readImages = compared(c, in.frame);
        in.readDepth = in.readImages && readsDepth(c);
        walkthrough::FrameResult r = walkthrough.renderFrame(in);
        FrameCost cost = frameCost(r);
        cost.triangles -= trianglesCulled(walkthrough.readOcclusionCounts());
        acc.addFrame(cost);
        if (in.readImages) acc.compare(in.frame, in.head, r.images, r.depths, reference.at(in.frame));
    }
    return firstFrameSeconds;
}

NoiseComparison interleavedNoise(const ModeContext& c, std::optional<walls::WallSetup> walls, const ModeResult& mode,
                                 long frameIndex) {
    walkthrough::gl::WalkthroughOptions options;
    options.synchronousPaging = true;
    options.textureBudgetMB = 4096.0;
    options.uploadMBPerFrame = 4096.0;
    options.render.lodPixels = mode.lodPixels;
    options.render.occlusion = c.occlusion;
    options.portalCulling = c.portalCulling;
    options.triangleBudget = mode.triangleBudget;
    options.lodMaxPixels = c.lodMaxPixels;
    options.wallKind = c.wallKind;
    options.depthMarch = c.depthMarch;
    walkthrough::gl::Walkthrough walkthrough(c.scene, c.description, c.display, c.context, std::move(walls), options);
    const walkthrough::FrameInput fixed = c.path.frames.at(static_cast<std::size_t>(frameIndex));
    for (const walkthrough::FrameInput& in : c.path.frames) walkthrough.renderFrame(in);
    walkthrough.waitForTextures();
    std::vector<double> path, repeated;
    for (const walkthrough::FrameInput& in : c.path.frames) {
        path.push_back(walkthrough.renderFrame(in).frameMs);
        walkthrough::FrameInput again = fixed;
        again.frame = in.frame;  // the pager's recency moves on as in a run
        repeated.push_back(walkthrough.renderFrame(again).frameMs);
    }
    return {timeStats(path), timeStats(repeated)};
}

}  // namespace cavewall::bench::gl
