#pragma once
// The rooms of automatic walls (walls/auto_walls.h, 5.): pieces of real wall found in a model,
// the lines they form, and a grid's boundaries on those lines turned into portals. GL-free.

#include "scenes/scene_description.h"

#include <glm/glm.hpp>

#include <utility>
#include <vector>

namespace cavewall::walls {

// A piece of real wall: a thin vertical structure box, as the plane through its middle.
struct WallPiece {
    int axis = 0;                 // its normal: 0 (x) or 2 (z)
    double at = 0.0;              // its plane's position along the normal
    double from = 0.0, to = 0.0;  // its extent along the other horizontal axis
    double bottom = 0.0, top = 0.0;
};

// Wall quad on the segment a -> b (x, z) from y0 to y1 whose front faces `frontCentre`: a
// scenes::VirtualWall, or any quad with the same corners (scenes::RealWall).
template <typename Quad = scenes::VirtualWall>
Quad wallBetween(glm::dvec2 a, glm::dvec2 b, double y0, double y1, glm::dvec2 frontCentre) {
    Quad w;
    w.lowerLeft = {a.x, y0, a.y};
    w.lowerRight = {b.x, y0, b.y};
    w.upperLeft = {a.x, y1, a.y};
    const glm::dvec3 normal = glm::cross(w.lowerRight - w.lowerLeft, w.upperLeft - w.lowerLeft);
    const glm::dvec2 toFront = frontCentre - 0.5 * (a + b);
    if (normal.x * toFront.x + normal.z * toFront.y < 0.0) {
        std::swap(w.lowerLeft, w.lowerRight);
        w.upperLeft = {b.x, y1, b.y};
    }
    return w;
}

// Rooms: the grid's boundaries (d.walls) that lie on a line of real wall pieces become portals
// where the pieces reaching the floor leave a gap (a doorway, as high as the lowest piece above
// the gap, else the ceiling), nothing where they close it, and stay virtual walls where no
// piece lies; every piece becomes a real wall (an occluder for the planner's visibility).
void makeRooms(scenes::SceneDescription& d, const std::vector<WallPiece>& pieces, double floorY, double ceilingY);

// Positions along `axis` of lines of wall pieces strictly inside (lo, hi) whose pieces reaching
// the floor cover at least half of `extent`: where a building's rooms meet.
std::vector<double> wallLines(const std::vector<WallPiece>& pieces, int axis, double lo, double hi, double extent,
                              double floorY);

}  // namespace cavewall::walls
