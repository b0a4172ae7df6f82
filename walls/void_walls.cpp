#include "walls/void_walls.h"

#include "scenes/region.h"
#include "scenes/storey_voids.h"

#include <algorithm>
#include <limits>

namespace cavewall::walls {

namespace {

// Per cell, the plan samples of its region open from its floor to the floor of the storey above
// (scenes::cellVoids; none for the top storey's cells).
std::vector<scenes::PlanMask> voidsToStoreyAbove(const scenes::Scene& scene, const std::vector<scenes::Cell>& cells,
                                                 const std::vector<Storey>& storeys) {
    std::vector<double> tops;
    std::vector<scenes::PlanRect> bounds;
    for (const scenes::Cell& c : cells) {
        const auto above = static_cast<std::size_t>(storeyAt(storeys, c.floorY)) + 1;
        tops.push_back(above < storeys.size() ? storeys[above].floorY : std::numeric_limits<double>::infinity());
        bounds.push_back(scenes::regionBounds(c.region));
    }
    return scenes::cellVoids(scene, cells, tops, bounds);
}

}  // namespace

int raiseWallsUnderVoids(scenes::SceneDescription& description, const scenes::Scene& scene,
                         const std::vector<Storey>& storeys) {
    if (storeys.size() < 2 || description.walls.empty()) return 0;
    const std::vector<scenes::PlanMask> voids = voidsToStoreyAbove(scene, description.cells, storeys);
    int raised = 0;
    for (scenes::VirtualWall& w : description.walls) {
        const auto above = static_cast<std::size_t>(storeyAt(storeys, std::min(w.lowerLeft.y, w.lowerRight.y))) + 1;
        if (w.kind != scenes::WallKind::Virtual || above >= storeys.size()) continue;
        const glm::dvec2 a(w.lowerLeft.x, w.lowerLeft.z), b(w.lowerRight.x, w.lowerRight.z);
        const glm::dvec2 lo = glm::min(a, b) - kVoidWallReach, hi = glm::max(a, b) + kVoidWallReach;
        long open = 0;
        for (int c : w.cells)
            if (c >= 0 && c < static_cast<int>(voids.size())) open += voids[static_cast<std::size_t>(c)].count(lo, hi);
        if (open == 0 || storeys[above].ceilingY <= w.upperLeft.y) continue;
        w.upperLeft.y = storeys[above].ceilingY;
        ++raised;
    }
    return raised;
}

}  // namespace cavewall::walls
