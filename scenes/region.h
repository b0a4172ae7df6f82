#pragma once
// Floor regions: convex polygons in the (x, z) plane (scene_description.h). Counter-clockwise
// means counter-clockwise seen from +Y, i.e. turning from +x towards -z.

#include "scenes/scene_description.h"

#include <glm/glm.hpp>

#include <limits>
#include <vector>

namespace cavewall::scenes {

// An (x, z) rectangle [lo, hi]; lo > hi (the defaults) when it holds nothing.
struct PlanRect {
    glm::dvec2 lo{std::numeric_limits<double>::infinity()};
    glm::dvec2 hi{-std::numeric_limits<double>::infinity()};
};

// The bounds of a region's corners (none for no corners).
PlanRect regionBounds(const std::vector<glm::dvec2>& region);

// Signed area in m²: positive for counter-clockwise regions.
double regionArea(const std::vector<glm::dvec2>& region);

// Index of the first corner that turns the wrong way (or is a reversal) for a counter-clockwise
// convex polygon, -1 when convex. Collinear corners are allowed.
int firstNonConvexCorner(const std::vector<glm::dvec2>& region);

// True when (x, z) is inside or on the boundary of a convex region of either orientation
// (counter-clockwise, as validated scene descriptions have them, or clockwise, as some walls'
// polygons): on no edge's outer side by more than `tolerance` metres, so a point on an edge or
// within `tolerance` of its line counts as inside (cells that share an edge both hold it).
// Which side is outer follows the sign of regionArea. False for fewer than 3 points. A
// non-convex region is not handled (validation refuses it): the answer is that for the
// intersection of its edges' inner half-planes.
bool regionContains(const std::vector<glm::dvec2>& region, glm::dvec2 p, double tolerance = 1e-9);

// Area in m² shared by two counter-clockwise convex regions (0 when they only touch).
double overlapArea(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b);

// The distance (metres) between the segment [a, b] and the convex region (0 when they meet).
double segmentRegionDistance(glm::dvec2 a, glm::dvec2 b, const std::vector<glm::dvec2>& region);

// The cell that holds the world point p (the viewer's eye, an object's centre): among the cells
// whose region contains p's (x, z) (regionContains, within 1 µm; either orientation), the one
// with the highest floor at or below p.y + 0.5 m (p's storey), else the one with the lowest
// floor (an eye below every floor); the first of equal floors. -1 when none. The one rule for
// "which cell holds the eye": walls::FrameSelector uses it too.
int findCell(const std::vector<Cell>& cells, glm::dvec3 p);

// The absolute head heights (y) the walls of cell `cell` serve: d.headHeightRange, raised by
// the height of the cell's floor above the lowest cell floor (a storey above serves the same
// heads over its own floor). Cells that all share one floor serve d.headHeightRange itself.
glm::dvec2 cellHeadHeights(const SceneDescription& d, int cell);

}  // namespace cavewall::scenes
