#pragma once
// The input side of `cavewall run`: tracker -> tracking pipeline -> navigator (and the optional
// recorder) turned into one walkthrough::FrameInput per frame at the fixed step kRunStep. In cluster mode
// only rank 0 has one; the other ranks receive its FrameInput.
//
// The tracker spec "desktop" is the desktop fallback: keyboard and mouse events of the windows
// (gl::Context::takeInputEvents) drive an input::DesktopNavigator (mouse look, WASD; the head
// stays at the display's default head and the world turns). It needs windows. Its speed is
// input::viewSpeed of the model's bounding-box diagonal, and without a walk path it starts
// where RunOptions::start says (app/start_pose.h).

#include "app/run_options.h"
#include "app/scene_query.h"
#include "input/desktop_navigator.h"
#include "input/navigator.h"
#include "input/recording.h"
#include "input/tracker_source.h"
#include "input/tracking_pipeline.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walkthrough/frame_types.h"

#include <chrono>
#include <memory>
#include <optional>

namespace cavewall::app {

// The navigator's mode for `nav` (Auto: guided along the walk path when there is one, else fly
// on the desktop and none with a tracker); None is an empty optional. Throws Error for guided
// without a walk path.
std::optional<input::NavMode> navMode(app::Navigation nav, const scenes::SceneDescription& description,
                                      bool desktop = false);

class RunInput {
public:
    // Creates the tracker from options.tracker; copies the structure of `scene` for walk
    // collisions (app/scene_query.h). `realTime`: live trackers (network, desktop) are polled
    // when frame i's time t = i * kRunStep has come; false polls them at once (the bench
    // records its eye path ahead of drawing).
    RunInput(const app::RunOptions& options, const scenes::Scene& scene, const scenes::SceneDescription& description,
             bool realTime = true);

    // The input of frame `frame` (t = frame * kRunStep); live trackers wait for that time when
    // realTime.
    // `windowEvents`: the windows' keyboard and mouse events since the last frame (used by the
    // desktop fallback only).
    walkthrough::FrameInput next(long frame, bool readImages, const std::vector<input::Event>& windowEvents = {});

    bool isDesktop() const { return _desktop != nullptr; }

    // For the window's title and overlay: the navigation mode ("fly", ..., "none") and the
    // desktop's movement speed in m/s (nullopt with a tracker).
    std::string_view navigationName() const;
    std::optional<double> speed() const;

    // For the log: "dtrack listening on 127.0.0.1:5000 for ..." when the tracker is a live
    // network listener (its bound port, the chosen one for port 0), empty otherwise.
    std::string liveTrackerLine() const;

private:
    walkthrough::FrameInput desktopFrame(long frame, double t, const std::vector<input::Event>& windowEvents);
    walkthrough::FrameInput trackedFrame(long frame, double t);

    std::unique_ptr<input::TrackerSource> _tracker;  // null for the desktop fallback
    input::TrackingPipeline _pipeline;
    app::SceneQuery _query;
    std::unique_ptr<input::DesktopNavigator> _desktop;  // the desktop fallback
    input::Navigator _navigator;
    std::optional<input::NavMode> _mode;
    std::unique_ptr<input::Recorder> _recorder;
    bool _replay = false;
    bool _realTime = true;
    input::WandState _lastWand;
    std::chrono::steady_clock::time_point _start;
};

}  // namespace cavewall::app
