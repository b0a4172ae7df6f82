#pragma once
// A rectangle of a wall texture, as fractions of its width and height: u right from the left
// edge, t down from the upper edge (as the rows are stored). The wall passes draw only the part
// of a wall where a texture has content (walls::contentRect, walls::coveredRect,
// walls::depthDrawRect): the pixels they leave out are ones every texture leaves unchanged.

#include "display/off_axis.h"

#include <glm/glm.hpp>

namespace cavewall::walls {

struct TextureRect {
    glm::dvec2 lo{0.0}, hi{1.0};  // the whole texture by default
    bool empty() const { return !(hi.x > lo.x && hi.y > lo.y); }
};

// The smallest rectangle holding both (an empty one adds nothing).
inline TextureRect unite(const TextureRect& a, const TextureRect& b) {
    if (a.empty()) return b;
    if (b.empty()) return a;
    return {glm::min(a.lo, b.lo), glm::max(a.hi, b.hi)};
}

// The empty rectangle.
inline TextureRect noRect() { return {glm::dvec2(0.0), glm::dvec2(0.0)}; }

// The point of `wall` (world) at texture fractions u (right) and t (down from the upper edge).
inline glm::dvec3 wallPoint(const display::ScreenQuad& wall, double u, double t) {
    return wall.upperLeft + u * (wall.lowerRight - wall.lowerLeft) + t * (wall.lowerLeft - wall.upperLeft);
}

}  // namespace cavewall::walls
