#include "tools/run_session.h"

#include "display/display.h"
#include "display/gl/context.h"
#include "input/navigator.h"
#include "input/recording.h"
#include "input/tracker_source.h"
#include "input/tracking_pipeline.h"
#include "scenes/loader.h"
#include "tools/run_output.h"
#include "tools/scene_query.h"
#include "walls/gl/baker.h"
#include "walls/gl/walkthrough.h"
#include "walls/visibility.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <thread>

namespace cavewall::tools {

namespace {

// Plans and bakes (or finds in the cache) the scene's wall textures.
gl::WallSetup prepareWalls(const RunOptions& o, const scenes::Scene& scene, const scenes::SceneDescription& d,
                           gl::Context& context) {
    walls::BakeRequest request;
    request.scene = o.scene;
    request.plan = o.plan;
    request.context = &context;
    if (o.cache) request.cache = *o.cache;
    if (o.verbose)
        request.progress = [](const walls::BakeProgress& p) {
            if (p.baked > 0 && (p.done % 10 == 0 || p.done == p.total))
                std::cout << "bake: " << p.done << "/" << p.total << " textures (" << p.baked << " baked) "
                          << std::lround(p.seconds) << " s\n" << std::flush;
        };
    walls::BakeResult baked = walls::bakeScene(request);
    context.makeCurrent();
    gl::WallSetup setup;
    setup.plan = walls::planZones(d, o.plan);
    setup.table = walls::computeVisibility(d);
    walls::assignDepthBehind(setup.plan, scene, d, setup.table);
    setup.folder = baked.folder;
    setup.manifest = std::move(baked.manifest);
    if (o.verbose)
        std::cout << "walls: " << setup.plan.textures.size() << " textures in " << setup.folder.string() << " ("
                  << baked.baked << " baked now, " << baked.reused << " reused)\n";
    return setup;
}

std::unique_ptr<gl::Context> makeContext(const RunOptions& o, const display::Display& display) {
    bool windowed = o.window == WindowMode::Window;
    if (o.window == WindowMode::Auto) windowed = gl::windowSystemAvailable();
    if (windowed) {
        const std::string why = gl::windowsUnavailableReason();
        if (!why.empty()) throw Error("--window: " + why);
        return gl::createWindowedContext(gl::windowRequests(display), false);
    }
    return gl::createHeadlessContext();
}

// The navigation mode for --nav; "none" is an empty optional.
std::optional<input::NavMode> navMode(const std::string& nav, const scenes::SceneDescription& d) {
    const std::string mode = nav.empty() ? (d.walkPath.size() >= 2 ? "guided" : "none") : nav;
    if (mode == "none") return std::nullopt;
    if (mode == "guided") {
        if (d.walkPath.size() < 2)
            throw Error("--nav guided: the scene has no walkPath (expected at least 2 points, got " +
                        std::to_string(d.walkPath.size()) + ")");
        return input::NavMode::Guided;
    }
    if (mode == "fly") return input::NavMode::Fly;
    if (mode == "walk") return input::NavMode::Walk;
    throw Error("--nav: expected one of guided, fly, walk, none, got '" + nav + "'");
}

// The CAVE floor at the start of the walk path (path points are eye positions), facing along it.
void placeAtPathStart(input::Navigator& navigator, const scenes::SceneDescription& d) {
    if (d.walkPath.size() < 2) return;
    const glm::dvec3 start = d.walkPath[0] - glm::dvec3(0.0, d.eyeHeight, 0.0);
    const glm::dvec3 dir = d.walkPath[1] - d.walkPath[0];
    // rotateY(yaw) maps the CAVE's front (-Z) to (-sin yaw, 0, -cos yaw).
    navigator.setWorldFromCave(start, std::atan2(-dir.x, -dir.z));
}

std::vector<glm::dvec3> floorPath(const scenes::SceneDescription& d) {
    std::vector<glm::dvec3> path;
    for (const glm::dvec3& p : d.walkPath) path.push_back(p - glm::dvec3(0.0, d.eyeHeight, 0.0));
    return path;
}

}  // namespace

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

RunSummary runSession(const RunOptions& o) {
    if (o.transition == "warp")
        throw Error("--transition warp: the geometry warp transition is not available in this build yet "
                    "(expected blend)");
    if (o.transition != "blend") throw Error("--transition: expected blend or warp, got '" + o.transition + "'");
    if (o.frames < 1) throw Error("--frames: expected at least 1, got " + std::to_string(o.frames));
    const display::Display display(o.display);
    scenes::SceneDescription description;
    const scenes::Scene scene = scenes::loadSceneFile(o.scene, &description);
    const std::optional<input::NavMode> mode = navMode(o.nav, description);
    const auto tracker = input::makeTracker(o.tracker, input::trackerContextFor(o.display));
    const auto context = makeContext(o, display);

    std::optional<gl::WallSetup> setup;
    if (o.walls && !description.walls.empty()) setup = prepareWalls(o, scene, description, *context);
    const int textureCount = setup ? static_cast<int>(setup->plan.textures.size()) : 0;
    gl::WalkthroughOptions options;
    options.synchronousPaging = o.synchronousPaging;
    options.textureBudgetMB = o.textureBudgetMB;
    gl::Walkthrough walkthrough(scene, description, display, *context, std::move(setup), options);

    input::TrackingPipeline pipeline(input::pipelineConfigFor(o.display));
    const SceneQuery query(scene);
    input::NavigatorConfig navConfig;
    navConfig.guidePace = o.guidePace;
    input::Navigator navigator(navConfig, &query);
    placeAtPathStart(navigator, description);
    if (mode) {
        navigator.setMode(*mode);
        if (*mode == input::NavMode::Guided) navigator.setGuidePath(floorPath(description));
    }
    std::unique_ptr<input::Recorder> recorder;
    if (o.record) recorder = std::make_unique<input::Recorder>(*o.record, o.tracker);
    const bool replay = dynamic_cast<input::ReplaySource*>(tracker.get()) != nullptr;

    RunOutput output(o.out, description, display);
    RunSummary summary;
    summary.renderer = context->info().renderer;
    summary.walls = walkthrough.hasWalls();
    input::WandState lastWand;
    const auto start = std::chrono::steady_clock::now();
    for (long i = 0; i < o.frames; ++i) {
        const double t = static_cast<double>(i) * kRunStep;
        if (tracker->isLive()) std::this_thread::sleep_until(start + std::chrono::duration<double>(t));
        const input::Sample sample = tracker->poll(t);
        std::vector<input::Event> events = tracker->takeEvents();
        if (!replay) input::appendWandEvents(lastWand, sample.wand, t, events);
        lastWand = sample.wand;
        if (recorder) {
            recorder->write(sample);
            for (const input::Event& e : events) recorder->write(e);
        }
        const input::TrackedFrame tracked = pipeline.update(sample);
        navigator.setTracking(tracked.head.pose, tracked.hand.pose, tracked.wand);
        if (mode) {
            for (const input::Event& e : events) navigator.handle(e);
            if (i > 0) navigator.update(kRunStep);
        }
        const input::HandCursor cursor = navigator.handCursor();
        gl::FrameInput in;
        in.frame = i;
        in.time = t;
        in.head = {tracked.head.pose.position, tracked.head.pose.orientation};
        in.worldFromCave = navigator.worldFromCave();
        in.hand = gl::HandCursorPose{cursor.hand.position, cursor.hand.orientation, cursor.rayLength};
        in.readImages = o.saveEvery > 0 && i % o.saveEvery == 0;
        const gl::FrameResult r = walkthrough.renderFrame(in);
        output.writeFrame(i, t, in.head.position, r);
        if (in.readImages) summary.foldouts.push_back(output.saveImages(i, r.images));
        summary.frameMs.push_back(r.frameMs);
        summary.worstErrorDeg = std::max(summary.worstErrorDeg, r.maxErrorDeg);
        summary.worstErrorPx = std::max(summary.worstErrorPx, r.maxErrorPixels);
        summary.misses = r.pager.misses;
        summary.pageIns = r.pager.pageIns;
        if (o.verbose && (i + 1) % 60 == 0)
            std::cout << "frame " << i + 1 << "/" << o.frames << ": " << r.frameMs << " ms\n" << std::flush;
    }
    summary.textures = textureCount;
    return summary;
}

}  // namespace cavewall::tools
