#pragma once
// Constant-time zone lookup for the runtime: per cell and wall, a uniform grid over the cell's
// bounding box lists the zones whose bounding boxes overlap each grid square; a query tests
// only those. Same answers as findZone (walls/plan.h).

#include "walls/plan.h"

#include <vector>

namespace cavewall::walls {

class ZoneIndex {
public:
    // Keeps no reference to `plan` beyond its zones' polygons, which it copies.
    explicit ZoneIndex(const Plan& plan);

    // The zone of (cell, wall) containing floor point p (x, z), or -1.
    int find(int cell, int wall, glm::dvec2 p) const;

private:
    struct SideGrid {
        int cell = 0, wall = 0;
        glm::dvec2 origin{0.0};
        double square = 1.0;  // metres per grid square
        glm::ivec2 count{0};
        std::vector<std::vector<int>> squares;  // zone ids per square, row-major
    };
    std::vector<SideGrid> _sides;
    std::vector<Polygon2> _polygons;  // by zone id
};

}  // namespace cavewall::walls
