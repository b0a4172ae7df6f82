#include "walls/wall_setup.h"

#include <algorithm>

namespace cavewall::walls {

WallSetup prepareWalls(const scenes::Scene& scene, const scenes::SceneDescription& description,
                       const PlanOptions& options) {
    WallSetup s;
    s.plan = planZones(description, options);
    s.table = computeVisibility(description);
    for (PlannedWall& w : s.plan.walls) {
        w.depthBehind = 0.0;  // as assignDepthBehind: the deeper of the two sides
        for (int side = 0; side < 2; ++side) {
            if (w.cells[side] < 0) continue;
            WallContents c = wallContents(scene, description, s.table, w.id, side);
            w.depthBehind = std::max(w.depthBehind, c.depthBehind);
            s.contents[{w.id, side}] = std::move(c);
        }
    }
    for (const WallSide& side : s.plan.sides)
        if (!s.contents.count({side.wall, side.side}))
            s.contents[{side.wall, side.side}] = wallContents(scene, description, s.table, side.wall, side.side);
    return s;
}

}  // namespace cavewall::walls
