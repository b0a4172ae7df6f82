#pragma once
// What an installer checks in a display configuration before a run (`cavewall display`): each
// screen's size, pixels, front side and angular resolution from the default head; the edges
// two screens share; and where two screens in one plane cover the same area (a mistake: both
// project onto it). Pure geometry on a validated configuration, cave frame, metres.

#include "config/display_config.h"
#include "display/off_axis.h"

#include <glm/glm.hpp>

#include <ostream>
#include <string>
#include <vector>

namespace cavewall::display {

struct ScreenFacts {
    std::string name;
    ScreenQuad quad;
    glm::dvec3 upperRight{0.0};  // the fourth corner, lowerRight + upperLeft - lowerLeft
    glm::dvec3 centre{0.0};
    ScreenBasis basis;  // right, up, normal (towards the front side, where the viewer is), size
    glm::ivec2 resolution{0, 0};
    // The fewest pixels per degree anywhere on the screen seen from the default head
    // (minPixelsPerDegree, display/pixel_scale.h).
    double pixelsPerDegree = 0.0;
};

// The facts of every screen of `config` (validated), in configuration order.
std::vector<ScreenFacts> screenFacts(const config::DisplayConfig& config);

// The common part of an edge of screen `a` and an edge of screen `b` (a < b): the two edges lie
// on one line within the tolerance and overlap by more than it.
struct SharedEdge {
    int a = 0, b = 0;
    glm::dvec3 from{0.0}, to{0.0};
};

// The corners every screen carries, lowerLeft, lowerRight, upperRight, upperLeft: its outline.
std::vector<glm::dvec3> outline(const ScreenFacts& screen);

// Every shared edge of every pair of screens; `tolerance` in metres.
std::vector<SharedEdge> sharedEdges(const std::vector<ScreenFacts>& screens, double tolerance = 1e-3);

// The area two screens in one plane (within `tolerance` metres, either facing) both cover.
struct ScreenOverlap {
    int a = 0, b = 0;
    std::vector<glm::dvec3> polygon;  // convex, in the cave frame
    double area = 0.0;                // m², more than tolerance²
};

std::vector<ScreenOverlap> screenOverlaps(const std::vector<ScreenFacts>& screens, double tolerance = 1e-3);

// The text summary of `config` read from `source`: name, stereo mode, near and far, one table
// row per screen (name, size in metres, pixels, normal, pixels per degree), the default head
// and eyes, the tracking calibration and volume, shared edges and overlaps.
void printDisplaySummary(std::ostream& out, const config::DisplayConfig& config, const std::string& source);

}  // namespace cavewall::display
