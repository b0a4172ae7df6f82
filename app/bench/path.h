#pragma once
// The eye path of `cavewall bench`: recorded once, then replayed identically for every mode.
//
// The head comes from a tracker (input::makeTracker spec; default "sim:walk", a simulated
// walking head) through the display's tracking pipeline; the CAVE is moved along the scene's
// walkPath by the guided navigator (input/navigator.h), starting at the path's first point
// facing along it, at a pace chosen so that `frames` frames at 1/60 s cover the whole path. A
// walk cut by walkBreaks is walked piece by piece (frames in proportion to each piece's length,
// at one pace), with no frame between the pieces.
// Without a walkPath the CAVE stays at the world origin. Poses are polled at t = i / 60 s,
// through the same input loop as `cavewall run` (app/run_input.h), live trackers without
// waiting for that time.

#include "config/display_config.h"
#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walkthrough/frame_types.h"

#include <string>
#include <vector>

namespace cavewall::bench {

struct EyePath {
    std::vector<walkthrough::FrameInput> frames;  // readImages false; no hand cursor
    std::string description;                      // one line for the report header
    double pace = 1.0;                            // m/s along the walk path (1 without one)
};

// How long a warp-morph lasts on `path` (WalkthroughSettings::morphSeconds): the distance a
// viewer covers during `morphSeconds` at `walkingPace` (m/s; `cavewall run`'s guided pace), at
// the path's own pace, so that a morph spans the same stretch of the walk as it would walked.
double morphSecondsOn(const EyePath& path, double morphSeconds, double walkingPace);
// The same at `cavewall run`'s defaults: WalkthroughSettings::morphSeconds at RunOptions::guidePace.
double morphSecondsOn(const EyePath& path);

// Throws cavewall::Error for a bad tracker spec.
EyePath recordEyePath(const scenes::Scene& scene, const scenes::SceneDescription& description,
                      const config::DisplayConfig& display, const std::string& trackerSpec, long frames);

// How many of `frames` each piece of a walk of `lengths` (metres) gets: in proportion to its
// length, at least one each (two for a piece that has a length) while frames last; the last
// piece takes what is left.
std::vector<long> framesPerPiece(const std::vector<double>& lengths, long frames);

// Length of a polyline, metres.
double pathLength(const std::vector<glm::dvec3>& points);

}  // namespace cavewall::bench
