#include "walls/void_walls.h"

#include "scenes/region.h"
#include "scenes/storey_voids.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cavewall::walls {

namespace {

// The storey whose floor the wall stands on (within 0.5 m), or -1.
int storeyOf(const scenes::VirtualWall& w, const std::vector<StoreySpan>& storeys) {
    const double bottom = std::min(w.lowerLeft.y, w.lowerRight.y);
    for (std::size_t i = 0; i < storeys.size(); ++i)
        if (std::abs(bottom - storeys[i].floorY) <= 0.5) return static_cast<int>(i);
    return -1;
}

// Per cell, the plan samples of its region open from its floor to the floor of the storey above
// (scenes::cellVoids; none for the top storey's cells and cells on no storey).
std::vector<scenes::PlanMask> voidsToStoreyAbove(const scenes::Scene& scene, const std::vector<scenes::Cell>& cells,
                                                 const std::vector<StoreySpan>& storeys) {
    std::vector<double> tops;
    std::vector<scenes::PlanRect> bounds;
    for (const scenes::Cell& c : cells) {
        double top = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i + 1 < storeys.size(); ++i)
            if (std::abs(c.floorY - storeys[i].floorY) <= 0.5) top = storeys[i + 1].floorY;
        tops.push_back(top);
        bounds.push_back(scenes::regionBounds(c.region));
    }
    return scenes::cellVoids(scene, cells, tops, bounds);
}

}  // namespace

int raiseWallsUnderVoids(scenes::SceneDescription& description, const scenes::Scene& scene,
                         const std::vector<StoreySpan>& storeys) {
    if (storeys.size() < 2 || description.walls.empty()) return 0;
    const std::vector<scenes::PlanMask> voids = voidsToStoreyAbove(scene, description.cells, storeys);
    int raised = 0;
    for (scenes::VirtualWall& w : description.walls) {
        const int storey = storeyOf(w, storeys);
        if (w.kind != scenes::WallKind::Virtual || storey < 0 || storey + 1 >= static_cast<int>(storeys.size()))
            continue;
        const glm::dvec2 a(w.lowerLeft.x, w.lowerLeft.z), b(w.lowerRight.x, w.lowerRight.z);
        const glm::dvec2 lo = glm::min(a, b) - kVoidWallReach, hi = glm::max(a, b) + kVoidWallReach;
        long open = 0;
        for (int c : w.cells)
            if (c >= 0 && c < static_cast<int>(voids.size())) open += voids[static_cast<std::size_t>(c)].count(lo, hi);
        const double top = storeys[static_cast<std::size_t>(storey) + 1].ceilingY;
        if (open == 0 || top <= w.upperLeft.y) continue;
        w.upperLeft.y = top;
        ++raised;
    }
    return raised;
}

}  // namespace cavewall::walls
