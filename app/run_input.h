#pragma once
// The input side of `cavewall run`: tracker -> tracking pipeline -> navigator (and the optional
// recorder) turned into one walkthrough::FrameInput per frame. In cluster mode only rank 0 has
// one; the other ranks receive its FrameInput.
//
// Time: a live session (the desktop or a network tracker, realTime) runs on the wall clock: frame
// 0 at t = 0, each later frame kRunStep after the last at the earliest (at most 60 frames a
// second) or, when drawing took longer, at the time it starts; navigation moves by the time
// that passed (at most kMaxLiveStep a frame), so a person moves at the stated speed whatever
// the frame rate. Simulated, file and replayed trackers, and the bench, step kRunStep a frame:
// their runs are reproducible.
//
// With a tracker, the windows' keys act as a wand (input/keyboard_wand.h): W/S/A/D the joystick,
// 1-4 the modes; a session in windows until stopped flies by default.
//
// The tracker spec "desktop" is the desktop fallback: keyboard and mouse events of the windows
// (display::gl::Context::takeInputEvents) drive an input::DesktopNavigator (mouse look, WASD; the head
// stays at the display's default head and the world turns). It needs windows. Its speed is
// input::viewSpeed of the model's bounding-box diagonal (walking pace when it starts standing on
// a floor inside, or on the scene's walk path), and without a walk path it starts
// where RunOptions::start says (app/start_pose.h).

#include "app/run_options.h"
#include "app/scene_query.h"
#include "app/start_pose.h"
#include "input/desktop_navigator.h"
#include "input/keyboard_wand.h"
#include "input/navigator.h"
#include "input/recording.h"
#include "input/tracker_source.h"
#include "input/tracking_pipeline.h"
#include "input/tracker_watch.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walkthrough/frame_types.h"

#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <thread>

namespace cavewall::app {

// The navigator's mode for `nav` (Auto: guided along the walk path when there is one, else fly
// when `interactive` (the desktop, or windows until stopped) and none for a batch run with a
// tracker); None is an empty optional. Throws Error for guided without a walk path.
std::optional<input::NavMode> navMode(app::Navigation nav, const scenes::SceneDescription& description,
                                      bool interactive = false);

// The wall clock a live session runs on (RunInput); tests pass their own.
struct LiveClock {
    using TimePoint = std::chrono::steady_clock::time_point;
    std::function<TimePoint()> now = [] { return std::chrono::steady_clock::now(); };
    std::function<void(TimePoint)> sleepUntil = [](TimePoint t) { std::this_thread::sleep_until(t); };
};

class RunInput {
public:
    // Creates the tracker from options.tracker; copies the structure of `scene` for walk
    // collisions (app/scene_query.h). `realTime`: live trackers (network, desktop) run on the
    // wall clock (see the top); false steps kRunStep a frame and polls them at once (the bench
    // records its eye path ahead of drawing).
    RunInput(const app::RunOptions& options, const scenes::Scene& scene, const scenes::SceneDescription& description,
             bool realTime = true, LiveClock clock = {});

    // The input of frame `frame`, called for 0, 1, 2, ... in turn: t = frame * kRunStep, or
    // the wall clock's time in a live session (which waits until kRunStep after the last).
    // `windowEvents`: the windows' keyboard and mouse events since the last frame (used by the
    // desktop fallback only).
    walkthrough::FrameInput next(long frame, bool readImages, const std::vector<input::Event>& windowEvents = {});

    bool isDesktop() const { return _desktop != nullptr; }

    // For the window's title and overlay: the navigation mode ("fly", ..., "none") and the
    // desktop's movement speed in m/s (nullopt with a tracker).
    std::string_view navigationName() const;
    std::optional<double> speed() const;

    // A live network tracker's state for the overlay ("waiting", "data", "no data"); empty for
    // the desktop and for simulated and recorded trackers. A second without accepted data also
    // prints one warning on stderr (input/tracker_watch.h).
    std::string_view trackerState() const;

    // For the log: "dtrack listening on 127.0.0.1:5000 for ..." when the tracker is a live
    // network listener (its bound port, the chosen one for port 0), empty otherwise.
    std::string liveTrackerLine() const;

private:
    bool live() const;
    double frameTime(long frame);
    walkthrough::FrameInput desktopFrame(long frame, double t, double step,
                                         const std::vector<input::Event>& windowEvents);
    walkthrough::FrameInput trackedFrame(long frame, double t, double step,
                                         const std::vector<input::Event>& windowEvents);

    std::unique_ptr<input::TrackerSource> _tracker;  // null for the desktop fallback
    input::TrackingPipeline _pipeline;
    app::SceneQuery _query;
    std::optional<StartPose> _start;                    // without a walk path (RunOptions::start)
    std::unique_ptr<input::DesktopNavigator> _desktop;  // the desktop fallback
    input::Navigator _navigator;
    std::optional<input::NavMode> _mode;
    std::unique_ptr<input::Recorder> _recorder;
    bool _replay = false;
    bool _realTime = true;
    std::optional<input::TrackerWatch> _watch;  // live trackers
    input::WandState _lastWand;
    input::KeyboardWand _keyboard;  // the windows' keys as a wand, with a tracker
    LiveClock _clock;
    LiveClock::TimePoint _clockStart{};  // a live session's frame 0 (set by it)
    double _lastTime = 0.0;              // the last frame's t
};

}  // namespace cavewall::app
