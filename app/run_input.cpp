#include "app/run_input.h"

#include "app/start_pose.h"
#include "display/display.h"

#include <cmath>
#include <thread>

namespace cavewall::app {

namespace {

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

constexpr const char* kDesktop = "desktop";

input::NavigatorConfig navigatorConfig(const RunOptions& o) {
    input::NavigatorConfig c;
    c.guidePace = o.guidePace;
    return c;
}

std::unique_ptr<input::TrackerSource> trackerFor(const RunOptions& o) {
    return o.tracker == kDesktop ? nullptr : input::makeTracker(o.tracker, input::trackerContextFor(o.display));
}

std::unique_ptr<input::DesktopNavigator> desktopFor(const RunOptions& o, const scenes::Scene& scene,
                                                    const scenes::SceneDescription& d, const input::WorldQuery* world) {
    if (o.tracker != kDesktop) return nullptr;
    if (o.window != app::WindowMode::Window)
        throw Error("--tracker desktop: expected --window (keyboard and mouse come from the windows)");
    if (o.record)
        throw Error(
            "--record: expected a tracker to record, got --tracker desktop (the desktop's keys and mouse "
            "are not recorded)");
    input::DesktopNavigatorConfig c;
    c.speed = input::viewSpeed(glm::length(scene.bounds().size()));
    c.eyeHeight = d.eyeHeight;
    c.navigator = navigatorConfig(o);
    const config::Viewer& v = o.display.viewer;
    return std::make_unique<input::DesktopNavigator>(c, input::Pose{v.headPosition, v.headOrientation}, world);
}

StartPose startFor(const RunOptions& o, const scenes::Scene& scene, const scenes::SceneDescription& d) {
    const display::Display display(o.display);
    return o.start == Start::ViewAll ? viewAllPose(scene, display) : startPose(scene, display, d.eyeHeight);
}

// The desktop's start: the walk path's, else where RunOptions::start says.
void placeDesktop(input::DesktopNavigator& desktop, const RunOptions& o, const scenes::Scene& scene,
                  const scenes::SceneDescription& d) {
    if (d.walkPath.size() >= 2) {
        const glm::dvec3 dir = d.walkPath[1] - d.walkPath[0];
        desktop.setEye(d.walkPath[0], std::atan2(-dir.x, -dir.z));
    } else if (o.start != Start::Origin) {
        const StartPose pose = startFor(o, scene, d);
        desktop.setEye(pose.eye, pose.yaw);
    }
}

// A tracked CAVE's start without a walk path: its floor on the floor found, or moved so that
// the default head sees the whole model.
void placeTracked(input::Navigator& navigator, const RunOptions& o, const scenes::Scene& scene,
                  const scenes::SceneDescription& d) {
    if (d.walkPath.size() >= 2 || o.start == Start::Origin) return;
    const StartPose pose = startFor(o, scene, d);
    const glm::dvec3 head = o.display.viewer.headPosition;
    const glm::dvec3 onFloor(head.x, pose.onFloor ? 0.0 : head.y, head.z);
    const glm::dvec3 floorEye = pose.onFloor ? glm::dvec3(pose.eye.x, pose.floorY, pose.eye.z) : pose.eye;
    navigator.setWorldFromCave(floorEye - glm::angleAxis(pose.yaw, glm::dvec3(0, 1, 0)) * onFloor, pose.yaw);
}

}  // namespace

std::optional<input::NavMode> navMode(Navigation nav, const scenes::SceneDescription& d, bool desktop) {
    switch (nav) {
        case Navigation::Auto:
            if (d.walkPath.size() >= 2) return input::NavMode::Guided;
            return desktop ? std::optional(input::NavMode::Fly) : std::nullopt;
        case Navigation::Guided:
            if (d.walkPath.size() < 2)
                throw Error("--nav guided: the scene has no walkPath (expected at least 2 points, got " +
                            std::to_string(d.walkPath.size()) + ")");
            return input::NavMode::Guided;
        case Navigation::Fly: return input::NavMode::Fly;
        case Navigation::Walk: return input::NavMode::Walk;
        case Navigation::None: return std::nullopt;
    }
    return std::nullopt;
}

std::string RunInput::liveTrackerLine() const {
    return _tracker && _tracker->isLive() ? _tracker->describe() : std::string();
}

RunInput::RunInput(const RunOptions& o, const scenes::Scene& scene, const scenes::SceneDescription& d, bool realTime)
    : _tracker(trackerFor(o)), _pipeline(input::pipelineConfigFor(o.display)), _query(scene),
      _desktop(desktopFor(o, scene, d, &_query)), _navigator(navigatorConfig(o), &_query),
      _mode(navMode(o.nav, d, _desktop != nullptr)),
      _replay(dynamic_cast<input::ReplaySource*>(_tracker.get()) != nullptr), _realTime(realTime),
      _start(std::chrono::steady_clock::now()) {
    placeAtPathStart(_navigator, d);
    placeTracked(_navigator, o, scene, d);
    if (_desktop) placeDesktop(*_desktop, o, scene, d);
    if (_mode) {
        _navigator.setMode(*_mode);
        if (_desktop) _desktop->setMode(*_mode);
        if (*_mode == input::NavMode::Guided) _navigator.setGuidePath(floorPath(d));
    }
    if (_desktop) _desktop->setGuidePath(floorPath(d));
    if (o.record) _recorder = std::make_unique<input::Recorder>(*o.record, o.tracker);
}

std::string_view RunInput::navigationName() const {
    if (!_mode) return "none";
    return input::toString(_desktop ? _desktop->mode() : _navigator.mode());
}

std::optional<double> RunInput::speed() const { return _desktop ? std::optional(_desktop->speed()) : std::nullopt; }

walkthrough::FrameInput RunInput::next(long i, bool readImages, const std::vector<input::Event>& windowEvents) {
    const double t = static_cast<double>(i) * kRunStep;
    if (_realTime && (_desktop || _tracker->isLive()))
        std::this_thread::sleep_until(_start + std::chrono::duration<double>(t));
    walkthrough::FrameInput in = _desktop ? desktopFrame(i, t, windowEvents) : trackedFrame(i, t);
    in.frame = i;
    in.time = t;
    in.readImages = readImages;
    return in;
}

// The desktop: window events drive the navigator; the head is the display's default head.
walkthrough::FrameInput RunInput::desktopFrame(long i, double t, const std::vector<input::Event>& windowEvents) {
    if (_mode) {
        for (input::Event e : windowEvents) {
            e.time = t;
            _desktop->handle(e);
        }
        if (i > 0) _desktop->update(kRunStep);
    }
    const input::HandCursor cursor = _desktop->handCursor();
    walkthrough::FrameInput in;
    in.head = {_desktop->head().position, _desktop->head().orientation};
    in.worldFromCave = _desktop->worldFromCave();
    in.hand = walkthrough::HandCursorPose{cursor.hand.position, cursor.hand.orientation, cursor.rayLength};
    return in;
}

// A tracker: sample -> pipeline -> navigator, recorded when asked.
walkthrough::FrameInput RunInput::trackedFrame(long i, double t) {
    const input::Sample sample = _tracker->poll(t);
    std::vector<input::Event> events = _tracker->takeEvents();
    if (!_replay) input::appendWandEvents(_lastWand, sample.wand, t, events);
    _lastWand = sample.wand;
    if (_recorder) {
        _recorder->write(sample);
        for (const input::Event& e : events) _recorder->write(e);
    }
    const input::TrackedFrame tracked = _pipeline.update(sample);
    _navigator.setTracking(tracked.head.pose, tracked.hand.pose, tracked.wand);
    if (_mode) {
        for (const input::Event& e : events) _navigator.handle(e);
        if (i > 0) _navigator.update(kRunStep);
    }
    const input::HandCursor cursor = _navigator.handCursor();
    walkthrough::FrameInput in;
    in.head = {tracked.head.pose.position, tracked.head.pose.orientation};
    in.worldFromCave = _navigator.worldFromCave();
    in.hand = walkthrough::HandCursorPose{cursor.hand.position, cursor.hand.orientation, cursor.rayLength};
    return in;
}

}  // namespace cavewall::app
