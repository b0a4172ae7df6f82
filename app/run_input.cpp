#include "app/run_input.h"

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
    c.joystickTurns = o.tracker != kDesktop;  // desktop: A and D strafe
    return c;
}

input::PipelineConfig pipelineConfig(const RunOptions& o) {
    input::PipelineConfig c = input::pipelineConfigFor(o.display);
    if (o.tracker == kDesktop) c.caveFromTracker = glm::dmat4(1.0);  // the mapper works in the cave frame
    return c;
}

std::unique_ptr<input::TrackerSource> trackerFor(const RunOptions& o) {
    return o.tracker == kDesktop ? nullptr : input::makeTracker(o.tracker, input::trackerContextFor(o.display));
}

}  // namespace

std::optional<input::NavMode> navMode(Navigation nav, const scenes::SceneDescription& d) {
    switch (nav) {
    case Navigation::Auto:
        if (d.walkPath.size() < 2) return std::nullopt;
        return input::NavMode::Guided;
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
    : _tracker(trackerFor(o)),
      _pipeline(pipelineConfig(o)),
      _query(scene),
      _navigator(navigatorConfig(o), &_query),
      _mode(navMode(o.nav, d)),
      _replay(dynamic_cast<input::ReplaySource*>(_tracker.get()) != nullptr),
      _realTime(realTime),
      _start(std::chrono::steady_clock::now()) {
    if (!_tracker) {
        if (o.window != app::WindowMode::Window)
            throw Error("--tracker desktop: expected --window (keyboard and mouse come from the windows)");
        const config::Viewer& v = o.display.viewer;
        _desktop = std::make_unique<input::DesktopMapper>(input::DesktopConfig{}, input::Pose{v.headPosition, v.headOrientation});
    }
    placeAtPathStart(_navigator, d);
    if (_mode) {
        _navigator.setMode(*_mode);
        if (*_mode == input::NavMode::Guided) _navigator.setGuidePath(floorPath(d));
    }
    if (o.record) _recorder = std::make_unique<input::Recorder>(*o.record, o.tracker);
}

walkthrough::FrameInput RunInput::next(long i, bool readImages, const std::vector<input::Event>& windowEvents) {
    const double t = static_cast<double>(i) * kRunStep;
    if (_realTime && (_desktop || _tracker->isLive()))
        std::this_thread::sleep_until(_start + std::chrono::duration<double>(t));
    std::vector<input::Event> events;
    for (input::Event e : _desktop ? windowEvents : std::vector<input::Event>{}) {
        e.time = t;
        for (const input::Event& n : _desktop->handle(e)) events.push_back(n);
    }
    const input::Sample sample = _desktop ? _desktop->sample(t) : _tracker->poll(t);
    if (_tracker) events = _tracker->takeEvents();
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
    in.frame = i;
    in.time = t;
    in.head = {tracked.head.pose.position, tracked.head.pose.orientation};
    in.worldFromCave = _navigator.worldFromCave();
    in.hand = walkthrough::HandCursorPose{cursor.hand.position, cursor.hand.orientation, cursor.rayLength};
    in.readImages = readImages;
    return in;
}

}  // namespace cavewall::app
