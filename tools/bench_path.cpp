#include "tools/bench_path.h"

#include "input/navigator.h"
#include "input/tracker_source.h"
#include "input/tracking_pipeline.h"
#include "tools/run_session.h"
#include "tools/scene_query.h"

#include <cmath>
#include <sstream>

namespace cavewall::tools {

double pathLength(const std::vector<glm::dvec3>& points) {
    double length = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) length += glm::length(points[i] - points[i - 1]);
    return length;
}

EyePath recordEyePath(const scenes::Scene& scene, const scenes::SceneDescription& d, const config::DisplayConfig& display,
                      const std::string& trackerSpec, long frames) {
    const auto tracker = input::makeTracker(trackerSpec, input::trackerContextFor(display));
    input::TrackingPipeline pipeline(input::pipelineConfigFor(display));
    const SceneQuery query(scene);
    std::vector<glm::dvec3> floorPath;
    for (const glm::dvec3& p : d.walkPath) floorPath.push_back(p - glm::dvec3(0.0, d.eyeHeight, 0.0));
    const bool guided = floorPath.size() >= 2;
    input::NavigatorConfig config;
    const double length = pathLength(floorPath);
    // Cover the whole path in `frames` steps (at least a slow walk).
    config.guidePace = std::max(1.0, length / (static_cast<double>(std::max(frames - 1, 1L)) * kRunStep));
    input::Navigator navigator(config, &query);
    if (guided) {
        const glm::dvec3 dir = floorPath[1] - floorPath[0];
        navigator.setWorldFromCave(floorPath[0], std::atan2(-dir.x, -dir.z));  // -Z of the CAVE along the path
        navigator.setMode(input::NavMode::Guided);
        navigator.setGuidePath(floorPath);
    }
    EyePath path;
    for (long i = 0; i < frames; ++i) {
        const double t = static_cast<double>(i) * kRunStep;
        const input::Sample sample = tracker->poll(t);
        for (const input::Event& e : tracker->takeEvents())
            if (guided) navigator.handle(e);
        const input::TrackedFrame tracked = pipeline.update(sample);
        navigator.setTracking(tracked.head.pose, tracked.hand.pose, tracked.wand);
        if (guided && i > 0) navigator.update(kRunStep);
        walls::FrameInput in;
        in.frame = i;
        in.time = t;
        in.head = {tracked.head.pose.position, tracked.head.pose.orientation};
        in.worldFromCave = navigator.worldFromCave();
        path.frames.push_back(in);
    }
    std::ostringstream text;
    text << "eye path: head from tracker '" << trackerSpec << "'; ";
    if (guided)
        text << "guided navigator along the scene's walkPath (" << std::lround(length) << " m), its pace set to "
             << std::lround(config.guidePace) << " m/s so that the frames cover the whole path";
    else
        text << "no walkPath: the CAVE stays at the world origin";
    text << "; " << frames << " frames at 1/60 s, the same poses for every mode";
    path.description = text.str();
    return path;
}

}  // namespace cavewall::tools
