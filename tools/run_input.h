#pragma once
// The input side of `cavewall run`: tracker -> tracking pipeline -> navigator (and the optional
// recorder) turned into one walls::FrameInput per frame at the fixed step kRunStep. In cluster mode
// only rank 0 has one; the other ranks receive its FrameInput.
//
// The tracker spec "desktop" is the desktop fallback: keyboard and mouse events of the windows
// (gl::Context::takeInputEvents) go through input::DesktopMapper to head, hand and wand (cave
// frame, no calibration), and A/D strafe instead of turning. It needs windows.

#include "input/desktop.h"
#include "input/navigator.h"
#include "input/recording.h"
#include "input/tracker_source.h"
#include "input/tracking_pipeline.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "tools/run_session.h"
#include "tools/scene_query.h"
#include "walls/frame_types.h"

#include <chrono>
#include <memory>
#include <optional>

namespace cavewall::tools {

// The navigation mode for --nav ("" = guided along the walk path when there is one, else
// none); "none" is an empty optional. Throws Error for unknown modes or guided without a path.
std::optional<input::NavMode> navMode(const std::string& nav, const scenes::SceneDescription& description);

class RunInput {
public:
    // Keeps references to `scene` (for walk collisions); creates the tracker from options.tracker.
    RunInput(const RunOptions& options, const scenes::Scene& scene, const scenes::SceneDescription& description);

    // The input of frame `frame` (t = frame * kRunStep); live trackers wait for that time.
    // `windowEvents`: the windows' keyboard and mouse events since the last frame (used by the
    // desktop fallback only).
    walls::FrameInput next(long frame, bool readImages, const std::vector<input::Event>& windowEvents = {});

    bool isDesktop() const { return _desktop != nullptr; }

private:
    std::unique_ptr<input::TrackerSource> _tracker;      // null for the desktop fallback
    std::unique_ptr<input::DesktopMapper> _desktop;
    input::TrackingPipeline _pipeline;
    SceneQuery _query;
    input::Navigator _navigator;
    std::optional<input::NavMode> _mode;
    std::unique_ptr<input::Recorder> _recorder;
    bool _replay = false;
    input::WandState _lastWand;
    std::chrono::steady_clock::time_point _start;
};

}  // namespace cavewall::tools
