#include "app/run_input.h"

#include "app/start_pose.h"
#include "display/display.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <utility>

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
                                                    const scenes::SceneDescription& d, const input::WorldQuery* world,
                                                    const std::optional<StartPose>& start) {
    if (o.tracker != kDesktop) return nullptr;
    if (o.window != app::WindowMode::Window)
        throw Error("--tracker desktop: expected --window (keyboard and mouse come from the windows)");
    if (o.record)
        throw Error(
            "--record: expected a tracker to record, got --tracker desktop (the desktop's keys and mouse "
            "are not recorded)");
    input::DesktopNavigatorConfig c;
    // On a floor inside: the start found there, or the scene's walk path (floor points).
    const bool standingInside = (start && start->onFloor) || d.walkPath.size() >= 2;
    c.speed = input::viewSpeed(glm::length(scene.bounds().size()), standingInside);
    c.eyeHeight = d.eyeHeight;
    c.navigator = navigatorConfig(o);
    const config::Viewer& v = o.display.viewer;
    return std::make_unique<input::DesktopNavigator>(c, input::Pose{v.headPosition, v.headOrientation}, world);
}

// Where a session without a walk path starts (RunOptions::start); none with a walk path or at
// the origin.
std::optional<StartPose> startFor(const RunOptions& o, const scenes::Scene& scene, const scenes::SceneDescription& d) {
    if (d.walkPath.size() >= 2 || o.start == Start::Origin) return std::nullopt;
    const display::Display display(o.display);
    return o.start == Start::ViewAll ? viewAllPose(scene, display) : startPose(scene, display, d.eyeHeight);
}

// The desktop's start: the walk path's, else `start`.
void placeDesktop(input::DesktopNavigator& desktop, const std::optional<StartPose>& start,
                  const scenes::SceneDescription& d) {
    if (d.walkPath.size() >= 2) {
        const glm::dvec3 dir = d.walkPath[1] - d.walkPath[0];
        desktop.setEye(d.walkPath[0], std::atan2(-dir.x, -dir.z));
    } else if (start) {
        desktop.setEye(start->eye, start->yaw);
    }
}

// A tracked CAVE's start without a walk path: its floor on the floor found, or moved so that
// the default head sees the whole model.
void placeTracked(input::Navigator& navigator, const RunOptions& o, const std::optional<StartPose>& start) {
    if (!start) return;
    const StartPose& pose = *start;
    const glm::dvec3 head = o.display.viewer.headPosition;
    const glm::dvec3 onFloor(head.x, pose.onFloor ? 0.0 : head.y, head.z);
    const glm::dvec3 floorEye = pose.onFloor ? glm::dvec3(pose.eye.x, pose.floorY, pose.eye.z) : pose.eye;
    navigator.setWorldFromCave(floorEye - glm::angleAxis(pose.yaw, glm::dvec3(0, 1, 0)) * onFloor, pose.yaw);
}

}  // namespace

std::optional<input::NavMode> navMode(Navigation nav, const scenes::SceneDescription& d, bool interactive) {
    switch (nav) {
        case Navigation::Auto:
            if (d.walkPath.size() >= 2) return input::NavMode::Guided;
            return interactive ? std::optional(input::NavMode::Fly) : std::nullopt;
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

RunInput::RunInput(const RunOptions& o, const scenes::Scene& scene, const scenes::SceneDescription& d, bool realTime,
                   LiveClock clock)
    : _tracker(trackerFor(o)), _pipeline(input::pipelineConfigFor(o.display)), _query(scene),
      _start(startFor(o, scene, d)), _desktop(desktopFor(o, scene, d, &_query, _start)),
      _navigator(navigatorConfig(o), &_query),
      _mode(navMode(o.nav, d, _desktop != nullptr || (o.window == WindowMode::Window && o.frames == 0))),
      _replay(dynamic_cast<input::ReplaySource*>(_tracker.get()) != nullptr), _realTime(realTime),
      _clock(std::move(clock)) {
    placeAtPathStart(_navigator, d);
    placeTracked(_navigator, o, _start);
    if (_desktop) placeDesktop(*_desktop, _start, d);
    if (_mode) {
        _navigator.setMode(*_mode);
        if (_desktop) _desktop->setMode(*_mode);
        if (*_mode == input::NavMode::Guided) _navigator.setGuidePath(floorPath(d));
    }
    if (_desktop) _desktop->setGuidePath(floorPath(d));
    if (o.record) _recorder = std::make_unique<input::Recorder>(*o.record, o.tracker);
    if (_tracker && _tracker->isLive()) _watch.emplace(_tracker->describe());
}

std::string_view RunInput::trackerState() const { return _watch ? input::toString(_watch->state()) : ""; }

std::string_view RunInput::navigationName() const {
    if (!_mode) return "none";
    return input::toString(_desktop ? _desktop->mode() : _navigator.mode());
}

std::optional<double> RunInput::speed() const { return _desktop ? std::optional(_desktop->speed()) : std::nullopt; }

bool RunInput::live() const { return _realTime && (_desktop || _tracker->isLive()); }

// Frame `i`'s time (see run_input.h): the wall clock's in a live session, held to kRunStep
// after the last frame at the earliest.
double RunInput::frameTime(long i) {
    if (!live()) return static_cast<double>(i) * kRunStep;
    const LiveClock::TimePoint now = _clock.now();
    if (i == 0) {
        _clockStart = now;
        return 0.0;
    }
    const double earliest = _lastTime + kRunStep;
    const auto due = _clockStart + std::chrono::duration_cast<LiveClock::TimePoint::duration>(
                                       std::chrono::duration<double>(earliest));
    if (now >= due) return std::chrono::duration<double>(now - _clockStart).count();
    _clock.sleepUntil(due);
    return earliest;
}

walkthrough::FrameInput RunInput::next(long i, bool readImages, const std::vector<input::Event>& windowEvents) {
    const double t = frameTime(i);
    const double step = live() ? std::min(t - _lastTime, kMaxLiveStep) : kRunStep;
    _lastTime = t;
    walkthrough::FrameInput in =
        _desktop ? desktopFrame(i, t, step, windowEvents) : trackedFrame(i, t, step, windowEvents);
    in.frame = i;
    in.time = t;
    in.readImages = readImages;
    return in;
}

// The desktop: window events drive the navigator; the head is the display's default head.
walkthrough::FrameInput RunInput::desktopFrame(long i, double t, double step,
                                               const std::vector<input::Event>& windowEvents) {
    if (_mode) {
        for (input::Event e : windowEvents) {
            e.time = t;
            _desktop->handle(e);
        }
        if (i > 0) _desktop->update(step);
    }
    const input::HandCursor cursor = _desktop->handCursor();
    walkthrough::FrameInput in;
    in.head = {_desktop->head().position, _desktop->head().orientation};
    in.worldFromCave = _desktop->worldFromCave();
    in.hand = walkthrough::HandCursorPose{cursor.hand.position, cursor.hand.orientation, cursor.rayLength};
    return in;
}

// A tracker: sample -> pipeline -> navigator, recorded when asked; the windows' keys act as a
// wand (input/keyboard_wand.h), unrecorded.
walkthrough::FrameInput RunInput::trackedFrame(long i, double t, double step,
                                               const std::vector<input::Event>& windowEvents) {
    input::Sample sample = _tracker->poll(t);
    if (_watch) {
        _watch->update(t, _tracker->stats());
        if (const std::optional<std::string> warning = _watch->warning()) {
            const std::string problem = _tracker->problem();
            std::cerr << "run: warning: " << *warning << (problem.empty() ? "" : "; " + problem) << std::endl;
        }
    }
    std::vector<input::Event> events = _tracker->takeEvents();
    if (!_replay) input::appendWandEvents(_lastWand, sample.wand, t, events);
    _lastWand = sample.wand;
    if (_recorder) {
        _recorder->write(sample);
        for (const input::Event& e : events) _recorder->write(e);
    }
    for (input::Event e : windowEvents) {
        e.time = t;
        if (std::optional<input::Event> mode = _keyboard.handle(e)) events.push_back(*mode);
    }
    sample.wand = _keyboard.apply(sample.wand);
    const input::TrackedFrame tracked = _pipeline.update(sample);
    _navigator.setTracking(tracked.head.pose, tracked.hand.pose, tracked.wand);
    if (_mode) {
        for (const input::Event& e : events) _navigator.handle(e);
        if (i > 0) _navigator.update(step);
    }
    const input::HandCursor cursor = _navigator.handCursor();
    walkthrough::FrameInput in;
    in.head = {tracked.head.pose.position, tracked.head.pose.orientation};
    in.worldFromCave = _navigator.worldFromCave();
    in.hand = walkthrough::HandCursorPose{cursor.hand.position, cursor.hand.orientation, cursor.rayLength};
    return in;
}

}  // namespace cavewall::app
