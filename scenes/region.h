#pragma once
// Floor regions: convex polygons in the (x, z) plane (scene_description.h). Counter-clockwise
// means counter-clockwise seen from +Y, i.e. turning from +x towards -z.

#include "scenes/scene_description.h"

#include <glm/glm.hpp>

#include <vector>

namespace cavewall::scenes {

// Signed area in m²: positive for counter-clockwise regions.
double regionArea(const std::vector<glm::dvec2>& region);

// Index of the first corner that turns the wrong way (or is a reversal) for a counter-clockwise
// convex polygon, -1 when convex. Collinear corners are allowed.
int firstNonConvexCorner(const std::vector<glm::dvec2>& region);

// True when (x, z) is inside or on the boundary (within `tolerance` metres) of a
// counter-clockwise convex region.
bool regionContains(const std::vector<glm::dvec2>& region, glm::dvec2 p, double tolerance = 1e-9);

// Area in m² shared by two counter-clockwise convex regions (0 when they only touch).
double overlapArea(const std::vector<glm::dvec2>& a, const std::vector<glm::dvec2>& b);

// The cell whose region contains the world point's (x, z); among several (storeys), the one
// with the highest floor at or below p.y + 0.5 m, else the lowest floor. -1 when none.
// The distance (metres) between the segment [a, b] and the convex region (0 when they meet).
double segmentRegionDistance(glm::dvec2 a, glm::dvec2 b, const std::vector<glm::dvec2>& region);

int findCell(const std::vector<Cell>& cells, glm::dvec3 p);

// The absolute head heights (y) the walls of cell `cell` serve: d.headHeightRange, raised by
// the height of the cell's floor above the lowest cell floor (a storey above serves the same
// heads over its own floor). Cells that all share one floor serve d.headHeightRange itself.
glm::dvec2 cellHeadHeights(const SceneDescription& d, int cell);

}  // namespace cavewall::scenes
