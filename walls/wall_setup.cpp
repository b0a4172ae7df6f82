#include "walls/wall_setup.h"

#include <algorithm>

namespace cavewall::walls {

WallSetup prepareWalls(const scenes::Scene& scene, const scenes::SceneDescription& description,
                       const PlanOptions& options) {
    validatePlanOptions(options);
    WallSetup s;
    s.table = computeVisibility(description);
    std::vector<glm::dvec2> spans;
    for (int w = 0; w < int(description.walls.size()); ++w) {
        const WallContents* sides[2] = {nullptr, nullptr};
        for (int side = 0; side < 2; ++side) {
            if (description.walls[w].cells[side] < 0) continue;
            WallContents& c = s.contents[{w, side}] = wallContents(scene, description, s.table, w, side);
            sides[side] = &c;
        }
        spans.push_back(depthSpanOf(sides[0], sides[1]));
    }
    // Both kinds get the spans (PlannedWall::depthNear, depthBehind); only depth walls plan with them.
    s.plan = planZones(description, options, spans);
    for (const WallSide& side : s.plan.sides)
        if (!s.contents.count({side.wall, side.side}))
            s.contents[{side.wall, side.side}] = wallContents(scene, description, s.table, side.wall, side.side);
    return s;
}

PlanOptions planOptionsFor(PlanOptions options, WallKind kind, int bakeResolution) {
    options.wallKind = kind;
    if (kind == WallKind::Depth) options.maxResolution = std::min(options.maxResolution, std::max(1, bakeResolution));
    return options;
}

}  // namespace cavewall::walls
