#pragma once
// Scene descriptions built in code for the walls tests.

#include "scenes/scene_description.h"
#include "walls/stability.h"

#include <cmath>

namespace cavewall::walls::testing {

// A 12 m x 20 m hall (x in [-6, 6], z in [-10, 10]) cut by one 3 m high virtual wall at z = 0
// facing +z: cell 0 "front" (z > 0) and cell 1 "back" (z < 0).
inline scenes::SceneDescription hall() { return referenceHall(); }

// A 7 m wide, 3 m high virtual wall turned 30° about +Y, with a convex pentagon in front of
// it (cell 0) and a triangle behind it (cell 1), neither aligned with the wall.
inline scenes::SceneDescription obliqueCells() {
    scenes::SceneDescription d;
    d.name = "oblique";
    const glm::dvec2 o(1, 2), along(std::cos(0.5235987755982988), -std::sin(0.5235987755982988));
    const glm::dvec2 in(-along.y, along.x);  // front side
    auto at = [&](double s, double t) { return o + s * along + t * in; };
    d.cells.push_back({"pentagon", {at(-0.5, 0), at(7.5, 0), at(9, 6), at(3.5, 11), at(-2, 6)}, 0.0});
    d.cells.push_back({"triangle", {at(7.5, 0), at(-0.5, 0), at(3.5, -8)}, 0.0});
    scenes::VirtualWall w;
    w.name = "oblique";
    const glm::dvec2 a = at(0, 0), b = at(7, 0);
    w.lowerLeft = {a.x, 0, a.y}, w.lowerRight = {b.x, 0, b.y}, w.upperLeft = {a.x, 3, a.y};
    w.cells = {0, 1};
    d.walls.push_back(w);
    d.headHeightRange = {1.3, 1.9};
    return d;
}

}  // namespace cavewall::walls::testing
