#pragma once
// The virtual-wall part of `cavewall bench --stability` (display/projection_stability.h has
// the projection part and the row type). Cases on a reference hall (12 m x 20 m, one 3 m high
// virtual wall across it, head heights 1.2-2.0 m):
//  - blend weights exactly on zone borders (every border vertex and edge midpoint of every
//    zone at alpha 10°, blend strips 0.2 m): the weights' sum error, their jump across the
//    border (1 nm either side), and weights on textures outside their proven region;
//  - alpha toward 0° and toward 90°: every zone's exact error bound divided by alpha (must stay
//    <= 1), with the texture count in the case name; planning must finish.
// No float comparison applies here: StabilityRow::floatError is NaN.

#include "display/projection_stability.h"
#include "scenes/scene_description.h"

#include <vector>

namespace cavewall::walls {

scenes::SceneDescription referenceHall();

std::vector<display::StabilityRow> blendBorderCases();
std::vector<display::StabilityRow> alphaExtremeCases();

}  // namespace cavewall::walls
