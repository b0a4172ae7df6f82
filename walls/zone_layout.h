#pragma once
// Internal to the planner (walls/plan.cpp): the zone layout of one cell for one wall, in the
// wall's floor frame (s along the wall's footprint, d away from it into the cell).

#include "walls/angular_error.h"
#include "walls/plan.h"

namespace cavewall::walls {

// The wall's floor frame as seen from one side.
struct SideFrame {
    glm::dvec2 origin{0.0};       // the wall's lower-left corner (x, z)
    glm::dvec2 along{1.0, 0.0};   // unit, along the footprint
    glm::dvec2 inward{0.0, 1.0};  // unit, towards the viewing cell

    glm::dvec2 toLocal(glm::dvec2 p) const { return {glm::dot(p - origin, along), glm::dot(p - origin, inward)}; }
    glm::dvec2 toWorld(glm::dvec2 l) const { return origin + l.x * along + l.y * inward; }
};

struct SideInput {
    int cell = 0, wall = 0, side = 0;
    SideFrame frame;
    Polygon2 cellRegion;  // world (x, z)
    ScreenQuad quad;
    glm::dvec2 heightRange{1.2, 2.0};
};

// The largest cell planZones accepts (metres, along x or z; ten times a 2 km hall): larger
// ones are refused with an Error naming the cell, since the work grows with the cell's size.
inline constexpr double kMaxCellExtent = 20000.0;

// The smallest distance from `wall`'s plane of `region`'s vertices (x, z) at height y, metres.
double nearestDistance(const Polygon2& region, double y, const ScreenQuad& wall);

// Appends the side's textures to `plan` and its zones to `zones` (Plan::zones, or
// Plan::beyondZones for the far walls of a neighbour; ids continue each vector's numbering) and
// returns the side's summary.
WallSide planSide(Plan& plan, const SideInput& input, std::vector<Zone>& zones);

// The same as planSide for each input in order (identical textures, zones, ids and summaries),
// with the layouts, which are independent, computed in parallel (walls/parallel_for.h).
// `plan`'s walls must hold every input's wall.
std::vector<WallSide> planSides(Plan& plan, const std::vector<SideInput>& inputs, std::vector<Zone>& zones);

// Plans Plan::beyond and Plan::beyondZones (walls/plan.h) once every side is planned.
void planBeyond(Plan& plan, const scenes::SceneDescription& description);

}  // namespace cavewall::walls
