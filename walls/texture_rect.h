#pragma once
// A rectangle of a wall texture, as fractions of its width and height: u right from the left
// edge, t down from the upper edge (as the rows are stored). The wall passes draw only the part
// of a wall where a texture has content (walls::contentRect, walls::coveredRect,
// walls::depthDrawRect): the pixels they leave out are ones every texture leaves unchanged.

#include "display/off_axis.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>

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

// `r` grown by `by` (fractions) on every side and clipped to the texture; empty stays empty.
inline TextureRect grown(const TextureRect& r, glm::dvec2 by) {
    if (r.empty()) return r;
    return {glm::max(r.lo - by, 0.0), glm::min(r.hi + by, 1.0)};
}

// The rectangle of whole texels around every texel (i, j) of a width x height texture for which
// covered(i, j) holds, grown by `margin` texels and clipped to the texture; empty when none is.
template <class Covered>
TextureRect texelBounds(int width, int height, int margin, Covered covered) {
    int x0 = width, y0 = height, x1 = 0, y1 = 0;
    for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i)
            if (covered(i, j)) {
                x0 = std::min(x0, i);
                x1 = std::max(x1, i + 1);
                y0 = std::min(y0, j);
                y1 = std::max(y1, j + 1);
            }
    if (x1 <= x0) return noRect();
    const glm::dvec2 size(width, height);
    return grown({glm::dvec2(x0, y0) / size, glm::dvec2(x1, y1) / size}, glm::dvec2(std::max(margin, 0)) / size);
}

// The point of `wall` (world) at texture fractions u (right) and t (down from the upper edge).
inline glm::dvec3 wallPoint(const display::ScreenQuad& wall, double u, double t) {
    return wall.upperLeft + u * (wall.lowerRight - wall.lowerLeft) + t * (wall.lowerLeft - wall.upperLeft);
}

// The corners of `rect` on `wall` as the passes' triangle strip takes them: lower left, lower
// right, upper left, upper right.
inline std::array<glm::dvec3, 4> stripCorners(const display::ScreenQuad& wall, const TextureRect& r) {
    return {wallPoint(wall, r.lo.x, r.hi.y), wallPoint(wall, r.hi.x, r.hi.y), wallPoint(wall, r.lo.x, r.lo.y),
            wallPoint(wall, r.hi.x, r.lo.y)};
}

}  // namespace cavewall::walls
