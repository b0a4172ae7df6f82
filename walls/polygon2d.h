#pragma once
// Small helpers for convex floor polygons in the (x, z) plane (or any 2D frame): half-plane
// clipping, area, centroid and containment. Polygons are vertex lists, either orientation
// unless stated; clipping keeps the input's orientation.

#include <glm/glm.hpp>

#include <vector>

namespace cavewall::walls {

using Polygon2 = std::vector<glm::dvec2>;

// The part of `polygon` (convex) where dot(normal, p) <= offset.
Polygon2 clipHalfPlane(const Polygon2& polygon, glm::dvec2 normal, double offset);

// The part of `polygon` (convex) inside the axis-aligned box [lo, hi]; infinite bounds are
// allowed and skip that side.
Polygon2 clipBox(const Polygon2& polygon, glm::dvec2 lo, glm::dvec2 hi);

// Signed area (positive for counter-clockwise in a right-handed (u, v) frame), m².
double signedArea(const Polygon2& polygon);

// Area centroid; the vertex mean for degenerate polygons; (0, 0) for an empty one.
glm::dvec2 centroid(const Polygon2& polygon);

// True when `p` is inside or on the boundary (within `tolerance` metres) of convex `polygon`.
bool containsConvex(const Polygon2& polygon, glm::dvec2 p, double tolerance = 1e-9);

// The point of convex `polygon` nearest to `p` (`p` itself when inside); `p` for an empty one.
glm::dvec2 closestPointConvex(const Polygon2& polygon, glm::dvec2 p);

// True when the polygon is convex (either orientation) with a non-zero area.
bool isConvex(const Polygon2& polygon);

}  // namespace cavewall::walls
