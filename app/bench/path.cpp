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

namespace {

// The walk's pieces (walkBreaks cut it; one piece without them), as eye points.
std::vector<std::vector<glm::dvec3>> pieces(const scenes::SceneDescription& d) {
    std::vector<std::vector<glm::dvec3>> out(1);
    std::size_t next = 0;
    for (std::size_t i = 0; i < d.walkPath.size(); ++i) {
        if (next < d.walkBreaks.size() && static_cast<int>(i) == d.walkBreaks[next]) {
            out.emplace_back();
            ++next;
        }
        out.back().push_back(d.walkPath[i]);
    }
    return out;
}

}  // namespace

std::vector<long> framesPerPiece(const std::vector<double>& lengths, long frames) {
    double total = 0.0;
    for (double l : lengths) total += l;
    auto least = [&](std::size_t k) { return lengths[k] > 0.0 ? 2L : 1L; };
    long rest = 0;  // the least the pieces after the current one need
    for (std::size_t k = 1; k < lengths.size(); ++k) rest += least(k);
    std::vector<long> out;
    long left = frames;
    for (std::size_t k = 0; k < lengths.size(); ++k) {
        const bool last = k + 1 == lengths.size();
        const long want = total > 0.0 ? std::lround(static_cast<double>(frames) * lengths[k] / total) : 0;
        const long lo = std::min(left, least(k));
        const long n = last ? left : std::clamp(want, lo, std::max(lo, left - rest));
        if (!last) rest -= least(k + 1);
        out.push_back(n);
        left -= n;
    }
    return out;
}

EyePath recordEyePath(const scenes::Scene& scene, const scenes::SceneDescription& d,
                      const config::DisplayConfig& display, const std::string& trackerSpec, long frames) {
    const std::vector<std::vector<glm::dvec3>> walk = pieces(d);
    std::vector<double> lengths;
    double length = 0.0;
    for (const auto& piece : walk) {
        lengths.push_back(pathLength(piece));
        length += lengths.back();
    }
    const bool guided = d.walkPath.size() >= 2;
    app::RunOptions options;
    options.display = display;
    options.tracker = trackerSpec;
    options.nav = app::Navigation::Auto;  // guided along the walk path when there is one
    // Cover the whole path in `frames` steps (at least a slow walk); every piece at one pace.
    const long steps = std::max(frames - static_cast<long>(walk.size()), 1L);
    options.guidePace = std::max(1.0, length / (static_cast<double>(steps) * app::kRunStep));
    const std::vector<long> counts = framesPerPiece(lengths, frames);
    EyePath path;
    if (guided) path.pace = options.guidePace;
    for (std::size_t k = 0; k < walk.size(); ++k) {
        scenes::SceneDescription piece = d;
        piece.walkPath = walk[k];
        piece.walkBreaks.clear();
        app::RunInput input(options, scene, piece, false);
        for (long i = 0; i < counts[k]; ++i) {
            walkthrough::FrameInput in = input.next(i, false);
            in.hand.reset();  // the bench draws no hand cursor
            path.frames.push_back(in);
        }
    }
    std::ostringstream text;
    text << "eye path: head from tracker '" << trackerSpec << "'; ";
    if (guided)
        text << "guided navigator along the scene's walkPath (" << std::lround(length) << " m"
             << (walk.size() > 1 ? " in " + std::to_string(walk.size()) + " pieces walked one after another" : "")
             << "), its pace set to " << std::lround(options.guidePace)
             << " m/s so that the frames cover the whole path";
    else
        text << "no walkPath: the CAVE stays at the world origin";
    text << "; " << frames << " frames at 1/60 s, the same poses for every mode";
    path.description = text.str();
    return path;
}

double morphSecondsOn(const EyePath& path, double morphSeconds, double walkingPace) {
    return path.pace > walkingPace ? morphSeconds * walkingPace / path.pace : morphSeconds;
}

double morphSecondsOn(const EyePath& path) {
    return morphSecondsOn(path, walkthrough::WalkthroughSettings{}.morphSeconds, app::RunOptions{}.guidePace);
}

}  // namespace cavewall::bench
