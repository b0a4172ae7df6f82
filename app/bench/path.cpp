#include "app/bench/path.h"

#include "app/run_input.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cavewall::bench {

double pathLength(const std::vector<glm::dvec3>& points) {
    double length = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) length += glm::length(points[i] - points[i - 1]);
    return length;
}

EyePath recordEyePath(const scenes::Scene& scene, const scenes::SceneDescription& d,
                      const config::DisplayConfig& display, const std::string& trackerSpec, long frames) {
    std::vector<glm::dvec3> floorPath;
    for (const glm::dvec3& p : d.walkPath) floorPath.push_back(p - glm::dvec3(0.0, d.eyeHeight, 0.0));
    const bool guided = floorPath.size() >= 2;
    const double length = pathLength(floorPath);
    app::RunOptions options;
    options.display = display;
    options.tracker = trackerSpec;
    options.nav = app::Navigation::Auto;  // guided along the walk path when there is one
    // Cover the whole path in `frames` steps (at least a slow walk).
    options.guidePace = std::max(1.0, length / (static_cast<double>(std::max(frames - 1, 1L)) * app::kRunStep));
    app::RunInput input(options, scene, d, false);
    EyePath path;
    for (long i = 0; i < frames; ++i) {
        walkthrough::FrameInput in = input.next(i, false);
        in.hand.reset();  // the bench draws no hand cursor
        path.frames.push_back(in);
    }
    std::ostringstream text;
    text << "eye path: head from tracker '" << trackerSpec << "'; ";
    if (guided)
        text << "guided navigator along the scene's walkPath (" << std::lround(length) << " m), its pace set to "
             << std::lround(options.guidePace) << " m/s so that the frames cover the whole path";
    else
        text << "no walkPath: the CAVE stays at the world origin";
    text << "; " << frames << " frames at 1/60 s, the same poses for every mode";
    path.description = text.str();
    return path;
}

}  // namespace cavewall::bench
