#pragma once
// The input side of `cavewall run`: tracker -> tracking pipeline -> navigator (and the optional
// recorder) turned into one walkthrough::FrameInput per frame at the fixed step kRunStep. In cluster mode
// only rank 0 has one; the other ranks receive its FrameInput.
//
// The tracker spec "desktop" is the desktop fallback: keyboard and mouse events of the windows
// (gl::Context::takeInputEvents) go through input::DesktopMapper to head, hand and wand (cave
// frame, no calibration), and A/D strafe instead of turning. It needs windows.

#include "app/run_options.h"
#include "app/scene_query.h"
#include "input/desktop.h"
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

// The navigator's mode for `nav` (Auto: guided along the walk path when there is one, else
// none); None is an empty optional. Throws Error for guided without a walk path.
std::optional<input::NavMode> navMode(app::Navigation nav, const scenes::SceneDescription& description);

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

    // For the log: "dtrack listening on 127.0.0.1:5000 for ..." when the tracker is a live
    // network listener (its bound port, the chosen one for port 0), empty otherwise.
    std::string liveTrackerLine() const;

private:
    std::unique_ptr<input::TrackerSource> _tracker;      // null for the desktop fallback
    std::unique_ptr<input::DesktopMapper> _desktop;
    input::TrackingPipeline _pipeline;
    app::SceneQuery _query;
    input::Navigator _navigator;
    std::optional<input::NavMode> _mode;
    std::unique_ptr<input::Recorder> _recorder;
    bool _replay = false;
    bool _realTime = true;
    input::WandState _lastWand;
    std::chrono::steady_clock::time_point _start;
};

}  // namespace cavewall::app
