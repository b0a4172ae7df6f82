#pragma once
// Virtual walls under a void reach the ceiling of the storey above. Under an atrium or a
// double-height hall (scenes/storey_voids.h) a viewer sees the upper storey's space over the
// virtual walls of its own storey; a wall that stops at its storey's ceiling leaves that view
// empty whenever the cell behind shows as textures (the texture covers the wall's quad only).
// GL-free.

#include "scenes/scene.h"
#include "scenes/scene_description.h"
#include "walls/storeys.h"

#include <vector>

namespace cavewall::walls {

inline constexpr double kVoidWallReach = 1.0;  // metres beside a wall's footprint a void raises it

// Raises to storeys[i + 1].ceilingY every virtual wall (not a portal: a doorway keeps its
// lintel) standing on storey i (storeyAt of its bottom; `storeys` bottom to top) below the top
// storey whose cells' voids (scenes::cellVoids from their floor to the floor of the storey
// above: the lower storey's slab there, the upper one's not, a ceiling or roof over it) have an
// open plan sample within kVoidWallReach of its footprint. Returns how many were raised.
int raiseWallsUnderVoids(scenes::SceneDescription& description, const scenes::Scene& scene,
                         const std::vector<Storey>& storeys);

}  // namespace cavewall::walls
