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
    w.lowerLeft = {a.x, 0, a.y};
    w.lowerRight = {b.x, 0, b.y};
    w.upperLeft = {a.x, 3, a.y};
    w.cells = {0, 1};
    d.walls.push_back(w);
    d.headHeightRange = {1.3, 1.9};
    return d;
}

// Three 10 m x 10 m cells in a row along z: A (z in [0, 10]), B ([-10, 0]), C ([-20, -10]),
// cut by the 4 m high virtual walls A|B (z = 0) and B|C (z = -10), both facing +z. From A, B's
// far wall B|C is parallel to A|B.
inline scenes::SceneDescription threeInARow() {
    scenes::SceneDescription d;
    d.name = "three";
    d.cells.push_back({"A", {{-5, 10}, {5, 10}, {5, 0}, {-5, 0}}, 0.0});
    d.cells.push_back({"B", {{-5, 0}, {5, 0}, {5, -10}, {-5, -10}}, 0.0});
    d.cells.push_back({"C", {{-5, -10}, {5, -10}, {5, -20}, {-5, -20}}, 0.0});
    for (int i = 0; i < 2; ++i) {
        scenes::VirtualWall w;
        w.name = i == 0 ? "A|B" : "B|C";
        const double z = -10.0 * i;
        w.lowerLeft = {-5, 0, z};
        w.lowerRight = {5, 0, z};
        w.upperLeft = {-5, 4, z};
        w.cells = {i, i + 1};
        d.walls.push_back(w);
    }
    d.headHeightRange = {1.3, 1.9};
    return d;
}

}  // namespace cavewall::walls::testing
